/* Line clipping, Sutherland-Hodgman, mesh-box clipping and frustum culling
 * against their definitions. */
#include "cg/clip.h"
#include "cg/xform.h"
#include "check.h"

#include <fenv.h>
#include <string.h>

/* ---- lines -------------------------------------------------------------- */

/* exact clip of an integer segment by an integer window: the parameter
 * interval [t0, t1] as fractions (num / den, den > 0) */
typedef struct frac {
    long long n, d;
} frac;
static int frac_less(frac a, frac b)
{
    return a.n * b.d < b.n * a.d;
}

static int exact_clip(const long long w[4], const long long s[4], double out[4])
{
    frac t0 = {0, 1}, t1 = {1, 1};
    long long p[2] = {s[0], s[1]}, d[2] = {s[2] - s[0], s[3] - s[1]};
    for (int axis = 0; axis < 2; axis++) {
        long long lo = w[axis], hi = w[axis + 2];
        if (d[axis] == 0) {
            if (p[axis] < lo || p[axis] > hi)
                return 0;
            continue;
        }
        frac a = {lo - p[axis], d[axis]}, b = {hi - p[axis], d[axis]};
        if (a.d < 0) {
            a.n = -a.n;
            a.d = -a.d;
            b.n = -b.n;
            b.d = -b.d;
        }
        frac enter = d[axis] > 0 ? a : b, leave = d[axis] > 0 ? b : a;
        if (frac_less(t0, enter))
            t0 = enter;
        if (frac_less(leave, t1))
            t1 = leave;
    }
    if (frac_less(t1, t0))
        return 0;
    double u0 = (double)t0.n / (double)t0.d, u1 = (double)t1.n / (double)t1.d;
    out[0] = (double)p[0] + u0 * (double)d[0];
    out[1] = (double)p[1] + u0 * (double)d[1];
    out[2] = (double)p[0] + u1 * (double)d[0];
    out[3] = (double)p[1] + u1 * (double)d[1];
    return 1;
}

static void lines(void)
{
    check_rng rng = {12345};
    long agree = 0;
    int divbyzero = 0;
    for (int it = 0; it < 100000; it++) {
        long long w[4] = {check_rng_int(&rng, -20, 0), check_rng_int(&rng, -20, 0), 0, 0};
        w[2] = w[0] + check_rng_int(&rng, 0, 30);
        w[3] = w[1] + check_rng_int(&rng, 0, 30);
        long long s[4];
        for (int k = 0; k < 4; k++)
            s[k] = check_rng_int(&rng, -40, 40);
        int kind = it % 8;
        if (kind == 1) { /* a point */
            s[2] = s[0];
            s[3] = s[1];
        } else if (kind == 2) { /* horizontal / vertical */
            s[3] = s[1];
        } else if (kind == 3) {
            s[2] = s[0];
        } else if (kind == 4) { /* endpoints on the window's edges or corners */
            s[0] = w[check_rng_int(&rng, 0, 1) * 2];
            s[1] = w[1 + check_rng_int(&rng, 0, 1) * 2];
        } else if (kind == 5) { /* along an edge of the window */
            s[0] = s[2] = w[check_rng_int(&rng, 0, 1) * 2];
        }
        double want[4] = {0, 0, 0, 0};
        int expect = exact_clip(w, s, want);
        cg_rect win = {(double)w[0], (double)w[1], (double)w[2], (double)w[3]};
        cg_vec2 a0 = {(double)s[0], (double)s[1]}, a1 = {(double)s[2], (double)s[3]};
        cg_vec2 b0 = a0, b1 = a1;
        int acc_cs = -1, acc_lb = -1;
        feclearexcept(FE_DIVBYZERO);
        CHECK(cg_clip_line_cohen_sutherland(win, &a0, &a1, &acc_cs, NULL, NULL) == CG_OK);
        if (fetestexcept(FE_DIVBYZERO))
            divbyzero++;
        CHECK(cg_clip_line_liang_barsky(win, &b0, &b1, &acc_lb) == CG_OK);
        CHECK_MSG(acc_cs == expect && acc_lb == expect,
                  "window %lld %lld %lld %lld segment %lld %lld %lld %lld: cs %d lb %d exact %d",
                  w[0], w[1], w[2], w[3], s[0], s[1], s[2], s[3], acc_cs, acc_lb, expect);
        if (expect && acc_cs == 1 && acc_lb == 1) {
            /* the same visible part, in the segment's direction */
            double tol = 1e-9;
            int ok = fabs(a0.x - want[0]) <= tol && fabs(a0.y - want[1]) <= tol
                     && fabs(a1.x - want[2]) <= tol && fabs(a1.y - want[3]) <= tol
                     && fabs(b0.x - want[0]) <= tol && fabs(b0.y - want[1]) <= tol
                     && fabs(b1.x - want[2]) <= tol && fabs(b1.y - want[3]) <= tol;
            CHECK_MSG(
                ok, "segment %lld %lld %lld %lld: cs %g %g %g %g lb %g %g %g %g exact %g %g %g %g",
                s[0], s[1], s[2], s[3], a0.x, a0.y, a1.x, a1.y, b0.x, b0.y, b1.x, b1.y, want[0],
                want[1], want[2], want[3]);
            agree += ok;
        }
    }
    CHECK_EQ_INT(divbyzero, 0);
    printf("lines: %ld clipped segments agree with the exact clip\n", agree);

    /* the notes' region codes (Fig. 11.1) */
    cg_rect w = {0, 0, 10, 10};
    CHECK_EQ_INT(cg_clip_rcode(w, cg_vec2_make(5, 5)), 0);
    CHECK_EQ_INT(cg_clip_rcode(w, cg_vec2_make(-1, 11)), 9);  /* 1001 */
    CHECK_EQ_INT(cg_clip_rcode(w, cg_vec2_make(5, 11)), 8);   /* 1000 */
    CHECK_EQ_INT(cg_clip_rcode(w, cg_vec2_make(11, 11)), 10); /* 1010 */
    CHECK_EQ_INT(cg_clip_rcode(w, cg_vec2_make(-1, 5)), 1);   /* 0001 */
    CHECK_EQ_INT(cg_clip_rcode(w, cg_vec2_make(11, 5)), 2);   /* 0010 */
    CHECK_EQ_INT(cg_clip_rcode(w, cg_vec2_make(-1, -1)), 5);  /* 0101 */
    CHECK_EQ_INT(cg_clip_rcode(w, cg_vec2_make(5, -1)), 4);   /* 0100 */
    CHECK_EQ_INT(cg_clip_rcode(w, cg_vec2_make(11, -1)), 6);  /* 0110 */
    CHECK_EQ_INT(cg_clip_rcode(w, cg_vec2_make(10, 0)), 0);   /* boundary is inside */

    /* bad input */
    cg_vec2 p = {0, 0}, q = {NAN, 1};
    int acc = 7;
    CHECK(cg_clip_line_cohen_sutherland(w, &p, &q, &acc, NULL, NULL) == CG_EINVAL && acc == 0);
    q = cg_vec2_make(INFINITY, 1);
    CHECK(cg_clip_line_liang_barsky(w, &p, &q, &acc) == CG_EINVAL);
    cg_rect bad = {5, 0, 1, 10};
    q = cg_vec2_make(1, 1);
    CHECK(cg_clip_line_liang_barsky(bad, &p, &q, &acc) == CG_EINVAL);
    CHECK(cg_clip_line_cohen_sutherland(w, NULL, &q, &acc, NULL, NULL) == CG_EINVAL);
    /* huge but finite coordinates */
    p = cg_vec2_make(-1e308, -1e308);
    q = cg_vec2_make(1e308, 1e308);
    CHECK(cg_clip_line_liang_barsky(w, &p, &q, &acc) == CG_OK);
}

static void lines3(void)
{
    check_rng rng = {999};
    cg_box3 box = {{-1, -2, -3}, {2, 1, 0.5}};
    long both = 0;
    for (int it = 0; it < 50000; it++) {
        cg_vec3 a = {check_rng_range(&rng, -4, 4), check_rng_range(&rng, -4, 4),
                     check_rng_range(&rng, -4, 4)};
        cg_vec3 b = {check_rng_range(&rng, -4, 4), check_rng_range(&rng, -4, 4),
                     check_rng_range(&rng, -4, 4)};
        if (it % 7 == 1)
            b.z = a.z;
        if (it % 11 == 2)
            b = a;
        cg_vec3 a1 = a, b1 = b, a2 = a, b2 = b;
        int c1 = -1, c2 = -1;
        CHECK(cg_clip_line_cohen_sutherland3(box, &a1, &b1, &c1) == CG_OK);
        CHECK(cg_clip_line_liang_barsky3(box, &a2, &b2, &c2) == CG_OK);
        /* reference: dense sampling of the segment */
        int any = 0;
        for (int k = 0; k <= 2000 && !any; k++) {
            cg_vec3 p = cg_vec3_add(a, cg_vec3_scale(cg_vec3_sub(b, a), k / 2000.0));
            any = cg_clip_rcode3(box, p) == 0;
        }
        if (any)
            CHECK_MSG(c1 == 1 && c2 == 1, "3D segment visible but cs %d lb %d", c1, c2);
        if (c1 == 1 && c2 == 1) {
            both++;
            CHECK(cg_vec3_length(cg_vec3_sub(a1, a2)) < 1e-9
                  && cg_vec3_length(cg_vec3_sub(b1, b2)) < 1e-9);
            CHECK(cg_clip_rcode3(box, a2) == 0 && cg_clip_rcode3(box, b2) == 0);
        } else {
            CHECK_MSG(c1 == c2, "3D cs %d lb %d", c1, c2);
        }
    }
    CHECK(both > 1000);
}

/* ---- Sutherland-Hodgman -------------------------------------------------- */

static int star(check_rng *rng, cg_vec2 *p, int n, double cx, double cy, double r0, double r1)
{
    for (int i = 0; i < n; i++) {
        double a = 2 * CG_PI * (i + check_rng_range(rng, 0, 0.8)) / n,
               r = check_rng_range(rng, r0, r1);
        p[i] = cg_vec2_make(cx + r * cos(a), cy + r * sin(a));
    }
    return n;
}

static void sutherland_hodgman(void)
{
    check_rng rng = {31337};
    for (int it = 0; it < 1000; it++) {
        cg_vec2 win[16], sub[40];
        int m = (int)check_rng_int(&rng, 3, 12), n = (int)check_rng_int(&rng, 3, 40);
        /* convex window: points on a circle in order */
        for (int i = 0; i < m; i++) {
            double a = 2 * CG_PI * (i + check_rng_range(&rng, 0, 0.9)) / m;
            win[i] = cg_vec2_make(1.0 * cos(a), 0.7 * sin(a));
        }
        if (it % 2) /* clockwise */
            for (int i = 0; i < m / 2; i++) {
                cg_vec2 t = win[i];
                win[i] = win[m - 1 - i];
                win[m - 1 - i] = t;
            }
        star(&rng, sub, n, check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1), 0.2, 1.2);
        cg_vec2 *out = NULL;
        size_t cnt = 0;
        CHECK(cg_clip_sutherland_hodgman(sub, (size_t)n, win, (size_t)m, &out, &cnt) == CG_OK);
        cg_polygon_set s = {0}, w = {0}, r = {0}, o = {0};
        cg_polygon_set_add_ring(&s, sub, (size_t)n, 1);
        cg_polygon_set_add_ring(&w, win, (size_t)m, 1);
        CHECK(
            cg_clip_boolean(CG_CLIP_INTERSECTION, &s, CG_CLIP_NON_ZERO, &w, CG_CLIP_NON_ZERO, 0, &r)
            == CG_OK);
        if (cnt)
            cg_polygon_set_add_ring(&o, out, cnt, 1);
        CHECK_NEAR(cg_polygon_set_area(&o), cg_polygon_set_area(&r), 1e-8);
        /* every output point inside (or on) the window */
        double orient = cg_polygon_set_area(&w) > 0 ? 1 : -1;
        for (size_t i = 0; i < cnt; i++)
            for (int k = 0; k < m; k++) {
                cg_vec2 a = win[k], b = win[(k + 1) % m];
                CHECK(orient * cg_vec2_cross(cg_vec2_sub(b, a), cg_vec2_sub(out[i], a)) >= -1e-12);
            }
        free(out);
        cg_polygon_set_clear(&s);
        cg_polygon_set_clear(&w);
        cg_polygon_set_clear(&r);
        cg_polygon_set_clear(&o);
    }
    /* the notes' Fig. 11.4 situation: a concave 'W' against a pentagon */
    cg_vec2 W[] = {{0, 4},   {1, 0}, {2, 3}, {3, 0}, {4, 4},
                   {3.3, 4}, {3, 2}, {2, 5}, {1, 2}, {0.7, 4}};
    cg_vec2 pent[] = {{0.5, 1}, {3.5, 1}, {4, 3}, {2, 4.2}, {0, 3}};
    cg_vec2 *out = NULL;
    size_t cnt = 0;
    CHECK(cg_clip_sutherland_hodgman(W, 10, pent, 5, &out, &cnt) == CG_OK);
    CHECK(cnt >= 10);
    free(out);
    /* bad windows */
    cg_vec2 line[] = {{0, 0}, {1, 1}, {2, 2}}, concave[] = {{0, 0}, {4, 0}, {1, 1}, {0, 4}};
    CHECK(cg_clip_sutherland_hodgman(W, 10, line, 3, &out, &cnt) == CG_EINVAL);
    CHECK(cg_clip_sutherland_hodgman(W, 10, concave, 4, &out, &cnt) == CG_EINVAL);
    CHECK(cg_clip_sutherland_hodgman(W, 10, pent, 2, &out, &cnt) == CG_EINVAL);
    cg_vec2 nanw[] = {{0, 0}, {1, 0}, {NAN, 1}};
    CHECK(cg_clip_sutherland_hodgman(W, 10, nanw, 3, &out, &cnt) == CG_EINVAL);
    CHECK(out == NULL && cnt == 0);
    /* subject entirely outside */
    cg_vec2 far[] = {{100, 100}, {101, 100}, {101, 101}};
    CHECK(cg_clip_sutherland_hodgman(far, 3, pent, 5, &out, &cnt) == CG_OK && cnt == 0
          && out == NULL);

    /* 3D: a polygon in z = 1 against vertical planes equals the 2D clip */
    for (int it = 0; it < 200; it++) {
        cg_vec2 sub[30];
        int n = (int)check_rng_int(&rng, 3, 30);
        star(&rng, sub, n, 0, 0, 0.3, 1.5);
        cg_vec3 poly[30];
        for (int i = 0; i < n; i++)
            poly[i] = cg_vec3_make(sub[i].x, sub[i].y, 1);
        cg_plane planes[4] = {{{0, 1, 0}, 0.5}, {{-1, 0, 0}, 1}, {{0, -1, 0}, 0.5}, {{1, 0, 0}, 1}};
        cg_vec2 sq[4] = {{-1, -0.5}, {1, -0.5}, {1, 0.5}, {-1, 0.5}};
        cg_vec3 *o3 = NULL;
        cg_vec2 *o2 = NULL;
        size_t c3 = 0, c2 = 0;
        CHECK(cg_clip_polygon_planes(poly, (size_t)n, planes, 4, &o3, &c3) == CG_OK);
        CHECK(cg_clip_sutherland_hodgman(sub, (size_t)n, sq, 4, &o2, &c2) == CG_OK);
        CHECK_EQ_INT(c3, c2);
        for (size_t i = 0; i < c3 && i < c2; i++)
            CHECK(fabs(o3[i].x - o2[i].x) < 1e-12 && fabs(o3[i].y - o2[i].y) < 1e-12
                  && o3[i].z == 1);
        free(o3);
        free(o2);
    }
}

/* ---- Weiler-Atherton ------------------------------------------------------ */

static void weiler_atherton(void)
{
    check_rng rng = {8080};
    long split = 0;
    for (int it = 0; it < 1500; it++) {
        cg_vec2 sub[40], win[40];
        int n = (int)check_rng_int(&rng, 3, 40), m = (int)check_rng_int(&rng, 3, 40);
        if (it % 4 == 3) {
            /* on a coarse grid: shared vertices and edges */
            double x0 = (double)check_rng_int(&rng, 0, 3), y0 = (double)check_rng_int(&rng, 0, 3);
            double x1 = x0 + (double)check_rng_int(&rng, 1, 3),
                   y1 = y0 + (double)check_rng_int(&rng, 1, 3);
            cg_vec2 r1[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
            memcpy(sub, r1, sizeof r1);
            n = 4;
            x0 = (double)check_rng_int(&rng, 0, 3);
            y0 = (double)check_rng_int(&rng, 0, 3);
            x1 = x0 + (double)check_rng_int(&rng, 1, 3);
            y1 = y0 + (double)check_rng_int(&rng, 1, 3);
            cg_vec2 r2[4] = {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}}; /* clockwise */
            memcpy(win, r2, sizeof r2);
            m = 4;
        } else {
            star(&rng, sub, n, 0, 0, 0.2, 1.5);
            star(&rng, win, m, check_rng_range(&rng, -0.8, 0.8), check_rng_range(&rng, -0.8, 0.8),
                 0.2, 1.5);
            if (it % 2)
                for (int i = 0; i < m / 2; i++) {
                    cg_vec2 t = win[i];
                    win[i] = win[m - 1 - i];
                    win[m - 1 - i] = t;
                }
        }
        cg_polygon_set wa = {0}, s = {0}, w = {0}, r = {0};
        CHECK(cg_clip_weiler_atherton(sub, (size_t)n, win, (size_t)m, &wa) == CG_OK);
        cg_polygon_set_add_ring(&s, sub, (size_t)n, 1);
        cg_polygon_set_add_ring(&w, win, (size_t)m, 1);
        CHECK(
            cg_clip_boolean(CG_CLIP_INTERSECTION, &s, CG_CLIP_NON_ZERO, &w, CG_CLIP_NON_ZERO, 0, &r)
            == CG_OK);
        CHECK_MSG(fabs(cg_polygon_set_area(&wa) - cg_polygon_set_area(&r)) <= 1e-6,
                  "round %d: Weiler-Atherton %.9f, boolean %.9f", it, cg_polygon_set_area(&wa),
                  cg_polygon_set_area(&r));
        /* as many pieces as the boolean operation finds */
        CHECK_MSG(wa.polygon_count == r.polygon_count || it % 4 == 3,
                  "round %d: %zu pieces, boolean %zu", it, wa.polygon_count, r.polygon_count);
        split += wa.polygon_count > 1;
        cg_polygon_set_clear(&wa);
        cg_polygon_set_clear(&s);
        cg_polygon_set_clear(&w);
        cg_polygon_set_clear(&r);
    }
    CHECK(split > 50);
    printf("Weiler-Atherton: %ld results split into several polygons\n", split);
    cg_polygon_set r = {0};
    cg_vec2 tri[3] = {{0, 0}, {1, 0}, {0, 1}}, nanp[3] = {{0, 0}, {NAN, 0}, {0, 1}};
    CHECK(cg_clip_weiler_atherton(tri, 2, tri, 3, &r) == CG_EINVAL);
    CHECK(cg_clip_weiler_atherton(tri, 3, nanp, 3, &r) == CG_EINVAL);
    CHECK(cg_clip_weiler_atherton(tri, 3, tri, 3, &r) == CG_OK);
    CHECK_NEAR(cg_polygon_set_area(&r), 0.5, 1e-8);
    cg_polygon_set_clear(&r);
}

/* ---- mesh against a box --------------------------------------------------- */

static cg_mesh *sphere(int slices, int stacks)
{
    cg_mesh *m = NULL;
    size_t nv = (size_t)slices * (stacks - 1) + 2, nf = (size_t)slices * (stacks - 1) * 2;
    if (cg_mesh_create(&m, nv, nf, nf * 3, CG_MESH_NORMALS | CG_MESH_TEXCOORDS | CG_MESH_COLORS)
        != CG_OK)
        return NULL;
    size_t v = 0;
    m->positions[v++] = cg_vec3_make(0, 0, 1);
    for (int i = 1; i < stacks; i++)
        for (int j = 0; j < slices; j++) {
            double th = CG_PI * i / stacks, ph = 2 * CG_PI * j / slices;
            m->positions[v++] = cg_vec3_make(sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
        }
    m->positions[v++] = cg_vec3_make(0, 0, -1);
    for (size_t i = 0; i < nv; i++) {
        cg_vec3 p = m->positions[i];
        m->normals[i] = p;
        m->texcoords[i] = cg_vec2_make(p.x, p.y); /* linear in position */
        m->colors[i] = (cg_rgbaf){(float)p.z, (float)(p.x + p.y), 0.5f, 1};
    }
    size_t f = 0, k = 0;
#define TRI(a, b, c)                          \
    do {                                      \
        m->face_indices[k++] = (uint32_t)(a); \
        m->face_indices[k++] = (uint32_t)(b); \
        m->face_indices[k++] = (uint32_t)(c); \
        m->face_offsets[++f] = (uint32_t)k;   \
    } while (0)
    for (int j = 0; j < slices; j++)
        TRI(0, 1 + j, 1 + (j + 1) % slices);
    for (int i = 0; i < stacks - 2; i++)
        for (int j = 0; j < slices; j++) {
            int a = 1 + i * slices + j, b = 1 + i * slices + (j + 1) % slices;
            int c = a + slices, d = b + slices;
            TRI(a, c, d);
            TRI(a, d, b);
        }
    int last = (int)nv - 1, base = 1 + (stacks - 2) * slices;
    for (int j = 0; j < slices; j++)
        TRI(last, base + (j + 1) % slices, base + j);
#undef TRI
    m->face_count = f;
    return m;
}

static int on_box_face(cg_box3 b, cg_vec3 p, cg_vec3 q)
{
    return (p.x == b.lo.x && q.x == b.lo.x) || (p.x == b.hi.x && q.x == b.hi.x)
           || (p.y == b.lo.y && q.y == b.lo.y) || (p.y == b.hi.y && q.y == b.hi.y)
           || (p.z == b.lo.z && q.z == b.lo.z) || (p.z == b.hi.z && q.z == b.hi.z);
}

static int cmp_edge(const void *a, const void *b)
{
    const uint64_t *x = a, *y = b;
    return (*x > *y) - (*x < *y);
}

static void mesh_box(void)
{
    cg_mesh *m = sphere(40, 30);
    CHECK(m != NULL);
    if (!m)
        return;
    cg_box3 boxes[3] = {{{-0.5, -2, -2}, {2, 0.3, 0.6}},
                        {{-0.7, -0.6, -0.5}, {0.6, 0.7, 0.4}},
                        {{-2, -2, -2}, {2, 2, 2}}};
    for (int bi = 0; bi < 3; bi++) {
        cg_box3 box = boxes[bi];
        cg_mesh *c = NULL;
        CHECK(cg_clip_mesh_box(m, box, &c) == CG_OK);
        if (!c)
            continue;
        CHECK(c->face_count > 0);
        CHECK(cg_mesh_validate(c, NULL) == CG_OK);
        for (size_t i = 0; i < c->vertex_count; i++) {
            cg_vec3 p = c->positions[i];
            CHECK(cg_clip_rcode3(box, p) == 0);
            CHECK_NEAR(cg_vec3_length(c->normals[i]), 1, 1e-9);
            CHECK(fabs(c->texcoords[i].x - p.x) < 1e-12 && fabs(c->texcoords[i].y - p.y) < 1e-12);
            CHECK(fabs(c->colors[i].r - p.z) < 1e-6 && fabs(c->colors[i].g - (p.x + p.y)) < 1e-6);
        }
        /* closed cut: every edge is used by two triangles (once each way)
         * unless it lies on a face of the box */
        size_t ne = c->face_count * 3;
        uint64_t *e = malloc(ne * sizeof *e);
        for (size_t t = 0; t < c->face_count; t++)
            for (int k = 0; k < 3; k++) {
                uint32_t a = c->face_indices[3 * t + k], b = c->face_indices[3 * t + (k + 1) % 3];
                e[3 * t + k] = ((uint64_t)a << 32) | b;
            }
        qsort(e, ne, sizeof *e, cmp_edge);
        long open = 0;
        for (size_t i = 0; i < ne; i++) {
            uint32_t a = (uint32_t)(e[i] >> 32), b = (uint32_t)e[i];
            uint64_t rev = ((uint64_t)b << 32) | a;
            if (!bsearch(&rev, e, ne, sizeof *e, cmp_edge)
                && !on_box_face(box, c->positions[a], c->positions[b]))
                open++;
        }
        CHECK_EQ_INT(open, 0);
        free(e);
        if (bi == 2) /* a box around everything keeps the mesh */
            CHECK_EQ_INT(c->face_count, m->face_count);
        cg_mesh_free(c);
    }
    cg_mesh *c = NULL;
    cg_box3 bad = {{1, 0, 0}, {0, 1, 1}};
    CHECK(cg_clip_mesh_box(m, bad, &c) == CG_EINVAL && c == NULL);
    cg_box3 away = {{5, 5, 5}, {6, 6, 6}};
    CHECK(cg_clip_mesh_box(m, away, &c) == CG_OK && c && c->face_count == 0);
    cg_mesh_free(c);
    cg_mesh_free(m);
}

/* ---- frustum culling -------------------------------------------------------- */

static void frustum(void)
{
    cg_mat4 proj, view;
    CHECK(cg_proj_perspective(cg_radians(60), 1.5, 0.5, 50, &proj) == CG_OK);
    CHECK(
        cg_view_look_at(cg_vec3_make(1, 2, 10), cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &view)
        == CG_OK);
    cg_mat4 pv = cg_mat4_mul(proj, view);
    cg_plane planes[6];
    cg_frustum_planes(pv, planes);
    check_rng rng = {2024};
    int counts[3] = {0, 0, 0};
    for (int it = 0; it < 5000; it++) {
        cg_vec3 c = {check_rng_range(&rng, -30, 30), check_rng_range(&rng, -30, 30),
                     check_rng_range(&rng, -50, 15)};
        cg_vec3 h = {check_rng_range(&rng, 0.01, 4), check_rng_range(&rng, 0.01, 4),
                     check_rng_range(&rng, 0.01, 4)};
        cg_box3 box = {cg_vec3_sub(c, h), cg_vec3_add(c, h)};
        cg_cull cull = cg_frustum_cull_box(planes, box);
        counts[cull]++;
        /* sample points of the box in clip space */
        int any_in = 0, all_in = 1;
        for (int k = 0; k < 64; k++) {
            cg_vec3 p = {box.lo.x + (box.hi.x - box.lo.x) * (k & 3) / 3.0,
                         box.lo.y + (box.hi.y - box.lo.y) * ((k >> 2) & 3) / 3.0,
                         box.lo.z + (box.hi.z - box.lo.z) * ((k >> 4) & 3) / 3.0};
            cg_vec4 q = cg_mat4_mul_vec4(pv, cg_vec4_from_point(p));
            int in = q.w > 0 && fabs(q.x) <= q.w && fabs(q.y) <= q.w && fabs(q.z) <= q.w;
            any_in |= in;
            all_in &= in;
        }
        if (any_in)
            CHECK(cull != CG_CULL_OUTSIDE);
        if (cull == CG_CULL_INSIDE)
            CHECK(all_in);
    }
    CHECK(counts[0] > 100 && counts[1] > 100 && counts[2] > 10);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(lines);
    CHECK_GROUP(lines3);
    CHECK_GROUP(sutherland_hodgman);
    CHECK_GROUP(weiler_atherton);
    CHECK_GROUP(mesh_box);
    CHECK_GROUP(frustum);
    return check_finish();
}
