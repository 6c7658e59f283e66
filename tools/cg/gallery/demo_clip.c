/* Gallery: clipping (chapter 11) - lines, polygons, boolean operations
 * (Figure 11.6), fill rules, a mesh cut by a box and frustum culling. */
#include "clip_view.h"
#include "demo.h"
#include "script_pictures.h"

#include "cg/xform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const cg_rgba8 GREY = {170, 170, 170, 255};
static const cg_rgba8 INK = {30, 30, 30, 255}, WINDOW = {200, 40, 30, 255};
static const cg_rgba8 KEEP = {30, 110, 220, 255};
static const cg_rgba8 RESULT = {251, 188, 5, 235}, RESULT2 = {52, 168, 83, 220};

/* a deterministic generator for the pictures */
static double unit(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

/* Appends a stroked polyline (world coordinates, width in pixels) to a draw
 * script, as clip_view_polyline strokes it: round joins and caps.  Pixel
 * coordinates with 4 decimals: the script defines the picture, and this
 * keeps the mesh pictures' scripts small. */
static void script_polyline(sketch *t, const clip_view *v, const cg_vec2 *p, size_t n, int closed,
                            double width, cg_rgba8 color)
{
    sketch_add(t, "color #%02x%02x%02x%02x\nwidth %.17g\npath", color.r, color.g, color.b, color.a,
               width);
    for (size_t i = 0; i < n; i++) {
        cg_vec2 q = clip_view_map(v, p[i]);
        sketch_add(t, " %c %.4f %.4f", i ? 'L' : 'M', q.x, q.y);
    }
    sketch_add(t, "%s\nstroke\n", closed ? " Z" : "");
}

/* A draw script for a picture of polygon sets, starting with a white
 * canvas with round joins and caps (as clip_view strokes). */
static sketch *canvas(int w, int h)
{
    sketch *k = calloc(1, sizeof *k);
    if (k)
        sketch_add(k, "size %d %d\nbackground #ffffff\njoin round\ncap round\n", w, h);
    return k;
}

/* The set filled anti-aliased under the non-zero rule, as clip_view_fill
 * does: one aapolygon with a contour line per further ring. */
static void script_fill(sketch *t, const clip_view *v, const cg_polygon_set *set, cg_rgba8 color)
{
    if (!set || set->ring_count == 0)
        return;
    sketch_add(t, "color #%02x%02x%02x%02x\nfillrule nonzero\n", color.r, color.g, color.b,
               color.a);
    for (size_t r = 0; r < set->ring_count; r++) {
        sketch_add(t, r ? "contour" : "aapolygon");
        for (size_t i = set->ring_start[r]; i < set->ring_start[r + 1]; i++) {
            cg_vec2 q = clip_view_map(v, set->points[i]);
            sketch_add(t, " %.4f %.4f", q.x, q.y);
        }
        sketch_add(t, "\n");
    }
}

/* Every ring of the set stroked closed, as clip_view_stroke does. */
static void script_stroke(sketch *t, const clip_view *v, const cg_polygon_set *set, double width,
                          cg_rgba8 color)
{
    for (size_t r = 0; set && r < set->ring_count; r++) {
        size_t a = set->ring_start[r], b = set->ring_start[r + 1];
        script_polyline(t, v, set->points + a, b - a, 1, width, color);
    }
}

/* Writes the script next to its picture, adds the picture and frees both. */
static int add(demo_context *c, const char *name, sketch *k, const char *caption)
{
    if (!k)
        return 1;
    int r = draw_demo_sketch(c, k, name, caption);
    free(k);
    return r;
}

/* 40 random segments clipped by the window in C; the picture is a draw
 * script of the segments, the window and the visible parts, so that its
 * caption's command draws it again. */
static int lines(demo_context *c, int liang)
{
    sketch *k = canvas(480, 360);
    if (!k)
        return 1;
    cg_rect w = {-1.5, -1, 1.5, 1};
    clip_view v = clip_view_fit(cg_vec2_make(-3, -2.2), cg_vec2_make(3, 2.2), 480, 360, 10);
    /* the window's lines extended: the nine regions of the rCodes */
    cg_vec2 ext[4][2] = {{{-1.5, -3}, {-1.5, 3}},
                         {{1.5, -3}, {1.5, 3}},
                         {{-4, -1}, {4, -1}},
                         {{-4, 1}, {4, 1}}};
    for (int i = 0; i < 4; i++)
        script_polyline(k, &v, ext[i], 2, 0, 1, (cg_rgba8){220, 220, 220, 255});
    cg_vec2 box[4] = {{-1.5, -1}, {1.5, -1}, {1.5, 1}, {-1.5, 1}};
    script_polyline(k, &v, box, 4, 1, 2.5, WINDOW);
    uint64_t s = liang ? 99 : 7;
    for (int i = 0; i < 40; i++) {
        cg_vec2 a = {unit(&s) * 6 - 3, unit(&s) * 4.4 - 2.2},
                b = {unit(&s) * 6 - 3, unit(&s) * 4.4 - 2.2};
        cg_vec2 seg[2] = {a, b};
        script_polyline(k, &v, seg, 2, 0, 1.2, GREY);
        int acc = 0;
        if (liang)
            cg_clip_line_liang_barsky(w, &a, &b, &acc);
        else
            cg_clip_line_cohen_sutherland(w, &a, &b, &acc, NULL, NULL);
        if (acc) {
            cg_vec2 in[2] = {a, b};
            script_polyline(k, &v, in, 2, 0, 3, KEEP);
        }
    }
    return add(
        c, liang ? "clip-liang-barsky" : "clip-cohen-sutherland", k,
        liang ? "Liang-Barsky: 40 segments (grey) and their parametric clip against the window "
                "(blue); one segment clipped as text: cg clip line -1.5 -1 1.5 1 -2.5 0.3 2 1.9 "
                "--algorithm liang-barsky"
              : "Cohen-Sutherland: 40 segments (grey) against the window; the extended window "
                "edges bound the nine rCode regions (TBRL); visible parts in blue; one segment "
                "step by step: cg clip line -1.5 -1 1.5 1 -2.5 0.3 2 1.9 --trace");
}

static void ring_set(cg_polygon_set *s, const cg_vec2 *p, size_t n, int new_polygon)
{
    cg_polygon_set_add_ring(s, p, n, new_polygon);
}

static void circle(cg_polygon_set *s, double cx, double cy, double r, int n, int cw, int newp)
{
    cg_vec2 p[128];
    for (int i = 0; i < n && i < 128; i++) {
        double a = 2 * CG_PI * (cw ? n - i : i) / n;
        p[i] = cg_vec2_make(cx + r * cos(a), cy + r * sin(a));
    }
    ring_set(s, p, (size_t)(n < 128 ? n : 128), newp);
}

/* writes a set as WKT into the gallery folder for the command shown */
static void save_wkt(demo_context *c, const char *name, const cg_polygon_set *s)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", demo_directory(c), name);
    FILE *f = fopen(path, "w");
    if (!f)
        return;
    if (s->ring_count == 0) {
        fputs("MULTIPOLYGON EMPTY\n", f);
    } else {
        /* every ring as its own polygon: paths, as cg clip boolean reads them */
        fputs("MULTIPOLYGON (", f);
        for (size_t r = 0; r < s->ring_count; r++) {
            fputs(r ? ", ((" : "((", f);
            for (size_t i = s->ring_start[r]; i <= s->ring_start[r + 1]; i++) {
                size_t k = i < s->ring_start[r + 1] ? i : s->ring_start[r];
                fprintf(f, "%s%.9g %.9g", i > s->ring_start[r] ? ", " : "", s->points[k].x,
                        s->points[k].y);
            }
            fputs("))", f);
        }
        fputs(")\n", f);
    }
    fclose(f);
}

/* panel (col,row) of a grid: draws A, B faint and the result solid */
static void panel(sketch *im, int col, int row, int pw, int ph, const cg_polygon_set *a,
                  const cg_polygon_set *b, const cg_polygon_set *r, cg_vec2 lo, cg_vec2 hi)
{
    clip_view v = clip_view_fit(lo, hi, pw, ph, 14);
    v.ox += col * pw;
    v.oy += row * ph;
    if (r)
        script_fill(im, &v, r, RESULT);
    if (a)
        script_stroke(im, &v, a, 1.2, (cg_rgba8){40, 90, 200, 255});
    if (b)
        script_stroke(im, &v, b, 1.2, WINDOW);
    if (r)
        script_stroke(im, &v, r, 2.2, INK);
}

static int polygons(demo_context *c)
{
    /* Sutherland-Hodgman: a concave 'W' against a convex pentagon (Fig. 11.4) */
    cg_vec2 W[] = {{0, 4},   {1, 0},   {2, 3},   {3, 0},   {4, 4},
                   {3.3, 4}, {3, 1.6}, {2, 4.6}, {1, 1.6}, {0.7, 4}};
    cg_vec2 pent[] = {{0.3, 0.8}, {3.7, 0.8}, {4.2, 3}, {2, 4.3}, {-0.2, 3}};
    cg_vec2 *out = NULL;
    size_t n = 0;
    cg_polygon_set sw = {0}, sp = {0}, sr = {0};
    ring_set(&sw, W, 10, 1);
    ring_set(&sp, pent, 5, 1);
    if (cg_clip_sutherland_hodgman(W, 10, pent, 5, &out, &n) == CG_OK && n)
        ring_set(&sr, out, n, 1);
    free(out);
    sketch *im = canvas(480, 420);
    if (im)
        panel(im, 0, 0, 480, 420, &sw, &sp, &sr, cg_vec2_make(-0.4, -0.2), cg_vec2_make(4.4, 4.8));
    save_wkt(c, "clip-w.wkt", &sw);
    save_wkt(c, "clip-pentagon.wkt", &sp);
    int r = add(c, "clip-sutherland-hodgman", im,
                "Sutherland-Hodgman: the concave W (blue) clipped edge by edge against a convex "
                "pentagon (red); one output polygon, joined along the window's edge as the notes "
                "warn (the clipped polygon as WKT: cg clip "
                "polygon clip-pentagon.wkt clip-w.wkt)");
    cg_polygon_set wr = {0};
    if (!r) {
        /* Weiler-Atherton: a comb-shaped window splits a disc into pieces */
        cg_vec2 comb[] = {{-1.4, -1.6}, {1.4, -1.6},  {1.4, 1.3},    {0.9, 1.3},    {0.9, -1.2},
                          {0.45, -1.2}, {0.45, 1.3},  {-0.05, 1.3},  {-0.05, -1.2}, {-0.5, -1.2},
                          {-0.5, 1.3},  {-0.95, 1.3}, {-0.95, -1.2}, {-1.4, -1.2}};
        cg_polygon_set disc = {0}, cs = {0};
        circle(&disc, 0, 0.25, 1.15, 64, 0, 1);
        ring_set(&cs, comb, 14, 1);
        /* the disc's top is cut off by the comb's teeth: several pieces */
        cg_clip_weiler_atherton(disc.points, disc.point_count, comb, 14, &wr);
        im = canvas(480, 420);
        if (im) {
            clip_view v = clip_view_fit(cg_vec2_make(-1.6, -1.7), cg_vec2_make(1.6, 1.5), 480, 420,
                                        14);
            for (size_t p = 0; p < wr.polygon_count; p++) {
                cg_polygon_set one = {0};
                for (size_t k = wr.polygon_start[p]; k < wr.polygon_start[p + 1]; k++)
                    ring_set(&one, wr.points + wr.ring_start[k],
                             wr.ring_start[k + 1] - wr.ring_start[k], k == wr.polygon_start[p]);
                script_fill(im, &v, &one, p % 2 ? RESULT2 : RESULT);
                cg_polygon_set_clear(&one);
            }
            script_stroke(im, &v, &disc, 1.2, (cg_rgba8){40, 90, 200, 255});
            script_stroke(im, &v, &cs, 1.5, WINDOW);
            script_stroke(im, &v, &wr, 2.2, INK);
        }
        save_wkt(c, "clip-comb.wkt", &cs);
        save_wkt(c, "clip-disc.wkt", &disc);
        char caption[300];
        snprintf(
            caption, sizeof caption,
            "Weiler-Atherton: a disc (blue) clipped by a concave comb (red) gives %zu separate "
            "polygons (as WKT: cg clip polygon clip-comb.wkt clip-disc.wkt --algorithm "
            "weiler-atherton)",
            wr.polygon_count);
        r = add(c, "clip-weiler-atherton", im, caption);
        cg_polygon_set_clear(&disc);
        cg_polygon_set_clear(&cs);
    }
    cg_polygon_set_clear(&sw);
    cg_polygon_set_clear(&sp);
    cg_polygon_set_clear(&sr);
    cg_polygon_set_clear(&wr);
    return r;
}

/* Figure 11.6: A, B, A-B, B-A, A u B, A n B, A xor B */
static int booleans(demo_context *c)
{
    cg_polygon_set a = {0}, b = {0}, r = {0};
    circle(&a, 0, 0, 1, 96, 0, 1);
    circle(&a, 0.1, -0.1, 0.38, 48, 1, 0); /* a hole in A */
    cg_vec2 sq[4];
    for (int i = 0; i < 4; i++) {
        double ang = cg_radians(20 + 90 * i);
        sq[i] = cg_vec2_make(1.0 + 1.05 * cos(ang), 0.25 + 1.05 * sin(ang));
    }
    ring_set(&b, sq, 4, 1);
    save_wkt(c, "clip-a.wkt", &a);
    save_wkt(c, "clip-b.wkt", &b);
    const int pw = 300, ph = 240;
    sketch *im = canvas(pw * 3, ph * 2);
    if (!im)
        return 1;
    cg_vec2 lo = {-1.15, -1.3}, hi = {2.25, 1.55};
    panel(im, 0, 0, pw, ph, &a, &b, NULL, lo, hi);
    struct {
        cg_clip_op op;
        int swap;
    } cases[5] = {{CG_CLIP_DIFFERENCE, 0},
                  {CG_CLIP_DIFFERENCE, 1},
                  {CG_CLIP_UNION, 0},
                  {CG_CLIP_INTERSECTION, 0},
                  {CG_CLIP_XOR, 0}};
    int status = 0;
    for (int k = 0; k < 5; k++) {
        const cg_polygon_set *x = cases[k].swap ? &b : &a, *y = cases[k].swap ? &a : &b;
        if (cg_clip_boolean(cases[k].op, x, CG_CLIP_NON_ZERO, y, CG_CLIP_NON_ZERO, 0, &r) != CG_OK)
            status = 1;
        panel(im, (k + 1) % 3, (k + 1) / 3, pw, ph, &a, &b, &r, lo, hi);
    }
    status |= add(
        c, "clip-boolean", im,
        "Figure 11.6 by the scanbeam (Vatti-style) boolean operations: A (blue, a disc with a "
        "hole) and B (red); then A-B, B-A, A union B, A intersection B, A xor B (one of them: "
        "cg clip boolean xor clip-a.wkt clip-b.wkt --fill nonzero -o xor.png)");
    cg_polygon_set_clear(&a);
    cg_polygon_set_clear(&b);
    cg_polygon_set_clear(&r);
    return status;
}

static int fill_rules(demo_context *c)
{
    /* a self-intersecting path: a pentagram (winding 2 in its middle) plus a clockwise square
     * overlapping it, so windings 0..3 occur */
    cg_polygon_set s = {0}, r = {0};
    cg_vec2 star[5];
    for (int i = 0; i < 5; i++) {
        double ang = CG_PI / 2 + 2 * CG_PI * (2 * i) / 5;
        star[i] = cg_vec2_make(cos(ang), sin(ang));
    }
    ring_set(&s, star, 5, 1);
    cg_vec2 sq[4] = {{-0.3, -0.9}, {-0.3, 0.1}, {0.3, 0.1}, {0.3, -0.9}}; /* clockwise */
    ring_set(&s, sq, 4, 1);
    save_wkt(c, "clip-star.wkt", &s);
    const int pw = 240, ph = 240;
    sketch *im = canvas(pw * 4, ph);
    if (!im)
        return 1;
    int status = 0;
    for (int k = 0; k < 4; k++) {
        if (cg_clip_boolean(CG_CLIP_UNION, &s, (cg_clip_fill)k, NULL, CG_CLIP_NON_ZERO, 0, &r)
            != CG_OK)
            status = 1;
        panel(im, k, 0, pw, ph, &s, NULL, &r, cg_vec2_make(-1.05, -1.0), cg_vec2_make(1.05, 1.05));
    }
    status |= add(
        c, "clip-fill-rules", im,
        "One self-intersecting set of paths (a pentagram and a clockwise square) under the four "
        "fill "
        "rules: even-odd, non-zero, positive, negative; each result is simple polygons with holes "
        "(one rule: cg clip boolean union clip-star.wkt clip-star.wkt --fill positive -o "
        "positive.png)");
    cg_polygon_set_clear(&s);
    cg_polygon_set_clear(&r);
    return status;
}

/* a torus knot-ish tube as a test mesh: a torus */
static cg_mesh *torus(int nu, int nv)
{
    cg_mesh *m = NULL;
    if (cg_mesh_create(&m, (size_t)nu * nv, (size_t)nu * nv * 2, (size_t)nu * nv * 6,
                       CG_MESH_NORMALS)
        != CG_OK)
        return NULL;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double u = 2 * CG_PI * i / nu, w = 2 * CG_PI * j / nv;
            cg_vec3 ctr = {cos(u), sin(u), 0};
            cg_vec3 n = {cos(w) * cos(u), cos(w) * sin(u), sin(w)};
            m->positions[i * nv + j] = cg_vec3_add(ctr, cg_vec3_scale(n, 0.4));
            m->normals[i * nv + j] = n;
        }
    size_t k = 0, f = 0;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            uint32_t a = (uint32_t)(i * nv + j), b = (uint32_t)(((i + 1) % nu) * nv + j);
            uint32_t cc = (uint32_t)(((i + 1) % nu) * nv + (j + 1) % nv),
                     d = (uint32_t)(i * nv + (j + 1) % nv);
            uint32_t t[6] = {a, b, cc, a, cc, d};
            for (int q = 0; q < 6; q++) {
                m->face_indices[k++] = t[q];
                if (q % 3 == 2)
                    m->face_offsets[++f] = (uint32_t)k;
            }
        }
    return m;
}

static void draw_mesh(sketch *im, const clip_view *v, const cg_mesh *m, cg_mat4 proj, cg_rgba8 col,
                      double width, int lit)
{
    for (size_t f = 0; f < m->face_count; f++) {
        uint32_t o = m->face_offsets[f];
        cg_vec2 p[3];
        cg_vec3 q[3];
        for (int k = 0; k < 3; k++) {
            q[k] = cg_mat4_transform_point(proj, m->positions[m->face_indices[o + k]]);
            p[k] = cg_vec2_make(q[k].x, q[k].y);
        }
        if (lit) {
            /* flat shade facing triangles by the projected normal */
            cg_vec3 nrm = cg_vec3_normalize(
                cg_vec3_cross(cg_vec3_sub(q[1], q[0]), cg_vec3_sub(q[2], q[0])));
            if (nrm.z <= 0)
                continue;
            double shade = 0.35 + 0.65 * nrm.z;
            cg_polygon_set t = {0};
            cg_polygon_set_add_ring(&t, p, 3, 1);
            script_fill(im, v, &t,
                        (cg_rgba8){(uint8_t)(60 * shade + 40), (uint8_t)(140 * shade + 40),
                                   (uint8_t)(230 * shade + 20), 255});
            cg_polygon_set_clear(&t);
        } else {
            script_polyline(im, v, p, 3, 1, width, col);
        }
    }
}

static int mesh_cut(demo_context *c)
{
    cg_mesh *m = torus(72, 28);
    if (!m)
        return 1;
    cg_mat4 proj = cg_proj_axonometric(cg_radians(-30), cg_radians(35));
    const int pw = 320, ph = 300;
    sketch *im = canvas(pw * 3, ph);
    int status = im ? 0 : 1;
    for (int k = 0; k < 3 && !status; k++) {
        /* the box translated along x in steps, as in the notes' Fig. 11.9 */
        cg_box3 box = {{-1.6 + 0.9 * k, -0.9, -0.6}, {-0.3 + 0.9 * k, 1.6, 0.25}};
        cg_mesh *cut = NULL;
        if (cg_clip_mesh_box(m, box, &cut) != CG_OK) {
            status = 1;
            break;
        }
        clip_view v = clip_view_fit(cg_vec2_make(-1.9, -1.5), cg_vec2_make(1.9, 1.5), pw, ph, 10);
        v.ox += k * pw;
        draw_mesh(im, &v, m, proj, (cg_rgba8){215, 215, 215, 255}, 0.6, 0);
        draw_mesh(im, &v, cut, proj, INK, 0.6, 1);
        /* the box's edges */
        for (int e = 0; e < 12; e++) {
            int axis = e / 4, a = e % 4;
            cg_vec3 p0, p1;
            double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
            double c0[3], c1[3];
            int o1 = (axis + 1) % 3, o2 = (axis + 2) % 3;
            c0[axis] = lo[axis];
            c1[axis] = hi[axis];
            c0[o1] = c1[o1] = (a & 1) ? hi[o1] : lo[o1];
            c0[o2] = c1[o2] = (a & 2) ? hi[o2] : lo[o2];
            p0 = cg_mat4_transform_point(proj, cg_vec3_make(c0[0], c0[1], c0[2]));
            p1 = cg_mat4_transform_point(proj, cg_vec3_make(c1[0], c1[1], c1[2]));
            cg_vec2 seg[2] = {{p0.x, p0.y}, {p1.x, p1.y}};
            script_polyline(im, &v, seg, 2, 0, 1.5, WINDOW);
        }
        cg_mesh_free(cut);
    }
    cg_mesh_free(m);
    if (status) {
        if (im)
            free(im->text);
        free(im);
        return 1;
    }
    return add(
        c, "clip-mesh-box", im,
        "3D clipping of a torus (4,032 triangles) against an axis-aligned box moved along x in "
        "steps, as in Fig. 11.9: triangles cut at the box faces with interpolated normals, the "
        "cut closed (shared edges give the same new vertex)");
}

static int culling(demo_context *c)
{
    cg_mat4 proj, view;
    cg_proj_perspective(cg_radians(50), 1.0, 1, 30, &proj);
    cg_view_look_at(cg_vec3_make(0, 0, 0), cg_vec3_make(0, 0, -1), cg_vec3_make(0, 1, 0), &view);
    cg_plane planes[6];
    cg_frustum_planes(cg_mat4_mul(proj, view), planes);
    sketch *im = canvas(480, 420);
    if (!im)
        return 1;
    /* top view: x right, -z up */
    clip_view v = clip_view_fit(cg_vec2_make(-16, -1), cg_vec2_make(16, 31), 480, 420, 10);
    uint64_t s = 1234;
    int counts[3] = {0, 0, 0};
    for (int i = 0; i < 220; i++) {
        cg_vec3 ctr = {unit(&s) * 32 - 16, unit(&s) * 2 - 1, -(unit(&s) * 32 - 1)};
        double h = 0.25 + unit(&s) * 0.9;
        cg_box3 b = {{ctr.x - h, ctr.y - h, ctr.z - h}, {ctr.x + h, ctr.y + h, ctr.z + h}};
        cg_cull cull = cg_frustum_cull_box(planes, b);
        counts[cull]++;
        cg_polygon_set sq = {0};
        cg_vec2 p[4] = {{b.lo.x, -b.hi.z}, {b.hi.x, -b.hi.z}, {b.hi.x, -b.lo.z}, {b.lo.x, -b.lo.z}};
        cg_polygon_set_add_ring(&sq, p, 4, 1);
        static const cg_rgba8 col[3] = {{200, 200, 200, 255},
                                        {251, 188, 5, 255},
                                        {52, 168, 83, 255}};
        script_fill(im, &v, &sq, col[cull]);
        script_stroke(im, &v, &sq, 0.8, INK);
        cg_polygon_set_clear(&sq);
    }
    double t = tan(cg_radians(25));
    cg_vec2 fr[4] = {{-t * 1, 1}, {t * 1, 1}, {t * 30, 30}, {-t * 30, 30}};
    script_polyline(im, &v, fr, 4, 1, 2, WINDOW);
    char caption[256];
    snprintf(
        caption, sizeof caption,
        "Frustum culling by bounding boxes (top view, camera at the bottom looking up): %d outside "
        "(grey), %d crossing a plane (yellow), %d inside (green)",
        counts[0], counts[1], counts[2]);
    return add(c, "clip-frustum-culling", im, caption);
}

static int render(demo_context *context)
{
    int r = lines(context, 0);
    r |= lines(context, 1);
    r |= polygons(context);
    r |= booleans(context);
    r |= fill_rules(context);
    r |= mesh_cut(context);
    r |= culling(context);
    return r;
}

const demo_section demo_section_clip = {11, "Clipping", render};
