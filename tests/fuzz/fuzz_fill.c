/* libFuzzer target: the filling module (cg/fill.h).
 *
 * The bytes are decoded into a small RGBA8 image (up to 96 x 96, rows padded
 * beyond width * 4 and guard bytes before and after) and a short program of
 * drawing operations: anti-aliased and aliased polygon fills, path fills and
 * strokes of SVG path data or of paths built through the API, flood and
 * boundary fills.  One rasterizer is reused by every operation of an input.
 * Checked beyond "no crash" (ASan + UBSan are on):
 *  - every call returns a status of the enum; a polygon or paint with a NaN,
 *    infinite or out-of-range number, or a bad stroke style, is refused;
 *  - a refused call leaves the image unchanged ("draws nothing");
 *  - nothing outside the image is written (row padding and guards);
 *  - a fully transparent paint (solid alpha 0, or a gradient whose stops all
 *    have alpha 0) leaves the image unchanged;
 *  - a fill or stroke through the reused rasterizer gives the same image,
 *    byte for byte, as the one-shot call (cg_fill_polygon_aa, cg_fill_polygon,
 *    cg_fill_path, cg_stroke_path) on a copy of the image;
 *  - a flood fill that succeeds paints its seed and counts at most w * h
 *    pixels; boundary fill paints the seed unless the seed is boundary.
 * Any failure aborts. */
#include "cg/fill.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

/* FUZZ_TRACE=1 in the environment prints each operation (to replay a
 * finding). */
static int trace;

#define GUARD 64
#define GUARD_BYTE 0xA5
#define MAX_SIDE 96
#define MAX_POINTS 64
#define MAX_OPS 8

typedef struct reader {
    const unsigned char *p;
    size_t n;
} reader;

static unsigned byte(reader *r)
{
    if (r->n == 0)
        return 0;
    r->n--;
    return *r->p++;
}

/* A coordinate: mostly small integers around and inside the image (so
 * shapes overlap, touch, share vertices and edges), sometimes quarters,
 * rarely huge, NaN, infinite or just out of range. */
static double coord(reader *r)
{
    unsigned b = byte(r);
    if (b < 0xB0)
        return (double)(b % 112) - 8.0;
    if (b < 0xF0)
        return (double)(b - 0xB0) * 0.25 - 2.0 + (double)(byte(r) % 100);
    static const double special[16] = {NAN,
                                       INFINITY,
                                       -INFINITY,
                                       1e300,
                                       -1e300,
                                       CG_FILL_MAX_COORD,
                                       -CG_FILL_MAX_COORD,
                                       CG_FILL_MAX_COORD * 1.000001,
                                       1e12,
                                       -1e12,
                                       1e6,
                                       -1e6,
                                       0.5,
                                       1e-300,
                                       96.0000001,
                                       4.9e-324};
    return special[b - 0xF0];
}

static int bad_number(double v)
{
    return !(fabs(v) <= CG_FILL_MAX_COORD);
}

static void check(int ok)
{
    if (!ok)
        abort();
}

static void check_status(cg_status s)
{
    check(s >= CG_OK && s <= CG_EEMPTY);
}

/* The image and its buffer: guards before and after, padded rows. */
typedef struct canvas {
    cg_image image;
    unsigned char *buffer;
    size_t bytes;
} canvas;

static void canvas_check_outside(const canvas *c)
{
    const cg_image *im = &c->image;
    for (size_t i = 0; i < GUARD; i++)
        check(c->buffer[i] == GUARD_BYTE && c->buffer[c->bytes - 1 - i] == GUARD_BYTE);
    size_t row = (size_t)im->width * 4;
    for (int y = 0; y < im->height; y++)
        for (size_t i = row; i < im->stride; i++)
            check(im->data[(size_t)y * im->stride + i] == GUARD_BYTE);
}

static int canvas_copy(const canvas *c, canvas *out)
{
    *out = *c;
    out->buffer = malloc(c->bytes);
    if (!out->buffer)
        return 0;
    memcpy(out->buffer, c->buffer, c->bytes);
    out->image.data = out->buffer + GUARD;
    return 1;
}

static int canvas_equal(const canvas *a, const canvas *b)
{
    return a->bytes == b->bytes && memcmp(a->buffer, b->buffer, a->bytes) == 0;
}

static cg_rgba8 color(reader *r)
{
    cg_rgba8 c;
    c.r = (uint8_t)byte(r);
    c.g = (uint8_t)byte(r);
    c.b = (uint8_t)byte(r);
    unsigned a = byte(r);
    /* Alpha 0, 255 and translucent values equally often. */
    c.a = (uint8_t)(a % 3 == 0 ? 0 : a % 3 == 1 ? 255 : a);
    return c;
}

typedef struct paint_input {
    cg_paint paint;
    cg_gradient_stop stops[4];
    int bad;         /* a number the paint must refuse */
    int transparent; /* every colour of the paint has alpha 0 */
} paint_input;

static void read_paint(reader *r, paint_input *pi)
{
    unsigned t = byte(r) % 4;
    pi->bad = 0;
    if (t < 2) {
        pi->paint = cg_paint_solid(color(r));
        pi->transparent = pi->paint.color.a == 0;
        return;
    }
    int n = (int)(byte(r) % 4) + 1;
    pi->transparent = 1;
    double previous = 0;
    for (int i = 0; i < n; i++) {
        unsigned o = byte(r);
        pi->stops[i].offset = o == 255 ? NAN : o == 254 ? 1.5 : o / 253.0;
        pi->stops[i].color = color(r);
        if (pi->stops[i].color.a != 0)
            pi->transparent = 0;
        if (!(pi->stops[i].offset >= 0 && pi->stops[i].offset <= 1)
            || pi->stops[i].offset < previous)
            pi->bad = 1;
        else
            previous = pi->stops[i].offset;
    }
    cg_vec2 p0 = {coord(r), coord(r)};
    if (bad_number(p0.x) || bad_number(p0.y))
        pi->bad = 1;
    if (t == 2) {
        cg_vec2 p1 = {coord(r), coord(r)};
        if (bad_number(p1.x) || bad_number(p1.y))
            pi->bad = 1;
        pi->paint = cg_paint_linear(p0, p1, pi->stops, n);
    } else {
        double radius = coord(r);
        if (!(radius > 0) || !isfinite(radius))
            pi->bad = 1;
        pi->paint = cg_paint_radial(p0, radius, pi->stops, n);
    }
}

/* Checks common to every drawing call: a status of the enum, nothing
 * written outside, nothing drawn when refused or when the paint is
 * transparent, and a refusal when the input holds a bad number. */
static void check_draw(cg_status s, const canvas *c, const canvas *before, int bad, int transparent)
{
    check_status(s);
    canvas_check_outside(c);
    if (bad)
        check(s != CG_OK);
    if (s != CG_OK || transparent)
        check(canvas_equal(c, before));
}

/* Draws through the reused rasterizer on c and through the one-shot call on
 * a copy; both must agree. */
enum { OP_POLYGON_AA, OP_POLYGON, OP_FILL_PATH, OP_STROKE_PATH };

typedef struct draw_args {
    const cg_vec2 *points;
    const int *sizes;
    int contours;
    cg_fill_rule rule;
    const cg_paint *paint;
    cg_rgba8 color;
    const cg_path *path;
    const cg_stroke_style *style;
} draw_args;

static cg_status draw(int op, cg_rasterizer *ras, cg_image *im, const draw_args *a)
{
    switch (op) {
    case OP_POLYGON_AA:
        return ras ? cg_rasterizer_fill_polygon_aa(ras, im, a->points, a->sizes, a->contours,
                                                   a->rule, a->paint)
                   : cg_fill_polygon_aa(im, a->points, a->sizes, a->contours, a->rule, a->paint);
    case OP_POLYGON:
        return ras ? cg_rasterizer_fill_polygon(ras, im, a->points, a->sizes, a->contours, a->rule,
                                                a->color)
                   : cg_fill_polygon(im, a->points, a->sizes, a->contours, a->rule, a->color);
    case OP_FILL_PATH:
        return ras ? cg_rasterizer_fill_path(ras, im, a->path, a->rule, a->paint)
                   : cg_fill_path(im, a->path, a->rule, a->paint);
    default:
        return ras ? cg_rasterizer_stroke_path(ras, im, a->path, a->style, a->paint)
                   : cg_stroke_path(im, a->path, a->style, a->paint);
    }
}

static void draw_both(int op, cg_rasterizer *ras, int default_tolerance, canvas *c,
                      const draw_args *a, int bad, int transparent)
{
    canvas before, fresh;
    if (!canvas_copy(c, &before))
        return;
    if (!canvas_copy(c, &fresh)) {
        free(before.buffer);
        return;
    }
    cg_status s = draw(op, ras, &c->image, a);
    check_draw(s, c, &before, bad, transparent);
    /* Paths and strokes flatten curves with the rasterizer's tolerance; the
     * one-shot calls use the default. */
    if (op == OP_POLYGON_AA || op == OP_POLYGON || default_tolerance) {
        cg_status s2 = draw(op, NULL, &fresh.image, a);
        check(s2 == s);
        check(canvas_equal(c, &fresh));
    }
    free(before.buffer);
    free(fresh.buffer);
}

/* A path from a slice of the bytes taken as SVG path data. */
static cg_status svg_path(reader *r, cg_path *path)
{
    size_t n = byte(r) % 64;
    if (n > r->n)
        n = r->n;
    char text[65];
    memcpy(text, r->p, n);
    text[n] = '\0';
    r->p += n;
    r->n -= n;
    cg_error err;
    int empty = cg_path_is_empty(path);
    cg_status s = cg_path_append_svg(path, text, &err);
    if (trace)
        fprintf(stderr, "svg '%s' -> %d\n", text, s);
    check_status(s);
    if (s != CG_OK)
        check(err.status == s && err.message[0] != '\0' && cg_path_is_empty(path) == empty);
    return s;
}

/* A path built through the API; a move, line or curve with a bad number
 * must be refused. */
static void api_path(reader *r, cg_path *path)
{
    int count = (int)(byte(r) % 6) + 1;
    for (int i = 0; i < count && r->n > 0; i++) {
        unsigned op = byte(r) % 7;
        double v[7];
        static const int arguments[7] = {2, 2, 4, 6, 5, 7, 0};
        int used = arguments[op];
        int bad = 0;
        for (int k = 0; k < used; k++) {
            v[k] = coord(r);
            if (bad_number(v[k]))
                bad = 1;
        }
        cg_status s;
        switch (op) {
        case 0: s = cg_path_move_to(path, v[0], v[1]); break;
        case 1: s = cg_path_line_to(path, v[0], v[1]); break;
        case 2: s = cg_path_quad_to(path, v[0], v[1], v[2], v[3]); break;
        case 3: s = cg_path_cubic_to(path, v[0], v[1], v[2], v[3], v[4], v[5]); break;
        case 4:
            v[3] *= 0.25; /* angles of a few turns */
            v[4] *= 0.25;
            s = cg_path_arc(path, v[0], v[1], v[2], v[3], v[4]);
            break;
        case 5: {
            int large = (int)(byte(r) & 1), sweep = (int)(byte(r) & 1);
            s = cg_path_svg_arc_to(path, v[0], v[1], v[2], large, sweep, v[5], v[6]);
            break;
        }
        default: s = cg_path_close(path); break;
        }
        if (trace) {
            fprintf(stderr, "path op %u:", op);
            for (int k = 0; k < used; k++)
                fprintf(stderr, " %.17g", v[k]);
            fprintf(stderr, " -> %d\n", s);
        }
        check_status(s);
        if (bad && op <= 3)
            check(s != CG_OK);
    }
}

static int read_style(reader *r, cg_stroke_style *st, double dashes[5])
{
    *st = cg_stroke_style_default();
    unsigned f = byte(r);
    int bad = 0;
    st->width = (f & 1) ? coord(r) * 0.25 : 1 + (byte(r) % 16) * 0.5;
    if (!(st->width > 0) || !(st->width <= CG_FILL_MAX_COORD))
        bad = 1;
    st->join = (cg_line_join)((f >> 1) % 4);
    st->cap = (cg_line_cap)((f >> 3) % 4);
    if ((f >> 1) % 4 == 3 || (f >> 3) % 4 == 3)
        bad = 1;
    if (f & 0x20) {
        st->miter_limit = coord(r) * 0.125;
        if (!(st->miter_limit >= 1) || !isfinite(st->miter_limit))
            bad = 1;
    }
    if (f & 0x40) {
        int n = (int)(byte(r) % 5) + 1;
        for (int i = 0; i < n; i++) {
            unsigned b = byte(r);
            dashes[i] = b == 255 ? -1.0 : b == 254 ? NAN : b == 253 ? 0.0 : b / 8.0;
            if (!(dashes[i] >= 0))
                bad = 1;
        }
        st->dashes = dashes;
        st->dash_count = n;
        st->dash_offset = (double)(int)(byte(r) % 64) - 16.0;
    }
    if (trace) {
        fprintf(stderr, "style width %.17g join %d cap %d miter %.17g dashes", st->width, st->join,
                st->cap, st->miter_limit);
        for (int i = 0; i < st->dash_count; i++)
            fprintf(stderr, " %.17g", dashes[i]);
        fprintf(stderr, " offset %.17g\n", st->dash_offset);
    }
    return bad;
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    static int traced;
    if (!traced) {
        trace = getenv("FUZZ_TRACE") != NULL;
        traced = 1;
    }
    reader r = {data, size};
    int w = (int)(byte(&r) % MAX_SIDE) + 1, h = (int)(byte(&r) % MAX_SIDE) + 1;
    unsigned layout = byte(&r);
    canvas c;
    c.image.width = w;
    c.image.height = h;
    c.image.format = CG_PIXEL_RGBA8;
    c.image.stride = (size_t)(w + (int)(layout % 4)) * 4;
    c.bytes = c.image.stride * (size_t)h + 2 * GUARD;
    c.buffer = malloc(c.bytes);
    if (!c.buffer)
        return 0;
    memset(c.buffer, GUARD_BYTE, c.bytes);
    c.image.data = c.buffer + GUARD;

    /* Background: random bytes, a palette of a few colours (regions for
     * flood fill), or one colour; translucent and transparent pixels too. */
    uint32_t seed = (uint32_t)byte(&r) * 2654435761u + 1u;
    cg_rgba8 palette[4];
    for (int i = 0; i < 4; i++)
        palette[i] = color(&r);
    unsigned mode = (layout >> 2) % 4;
    for (int y = 0; y < h; y++) {
        cg_rgba8 *row = cg_image_row_rgba8(&c.image, y);
        for (int x = 0; x < w; x++) {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            if (mode == 0)
                memcpy(&row[x], &seed, 4);
            else if (mode == 1)
                row[x] = palette[seed % 4];
            else if (mode == 2)
                row[x] = palette[((x / 7) ^ (y / 5)) % 2 ? 0 : (seed % 32 == 0 ? 1 : 2)];
            else
                row[x] = palette[0];
        }
    }

    cg_rasterizer *ras = NULL;
    if (cg_rasterizer_create(&ras) != CG_OK) {
        free(c.buffer);
        return 0;
    }
    int default_tolerance = 1;
    cg_path *path = NULL;
    if (cg_path_create(&path) != CG_OK) {
        cg_rasterizer_free(ras);
        free(c.buffer);
        return 0;
    }

    for (int op = 0; op < MAX_OPS && r.n > 0; op++) {
        unsigned code = byte(&r);
        cg_fill_rule rule = (code & 8) ? CG_FILL_NONZERO : CG_FILL_EVEN_ODD;
        paint_input pi;
        draw_args a;
        memset(&a, 0, sizeof a);
        a.rule = rule;
        if (trace)
            fprintf(stderr, "op %u (%s)\n", code % 8, rule ? "non-zero" : "even-odd");
        switch (code % 8) {
        case 0:
        case 1:
        case 2: { /* polygons: anti-aliased (twice as often) or aliased */
            cg_vec2 pts[MAX_POINTS];
            int sizes[4];
            int contours = (int)(byte(&r) % 4) + 1, total = 0, bad = 0;
            for (int k = 0; k < contours; k++) {
                int n = (int)(byte(&r) % 12);
                if (total + n > MAX_POINTS)
                    n = MAX_POINTS - total;
                sizes[k] = n;
                for (int i = 0; i < n; i++) {
                    unsigned s = byte(&r);
                    /* Often a vertex repeats an earlier one. */
                    if (total > 0 && s % 4 == 0) {
                        pts[total] = pts[s / 4 % total];
                    } else {
                        pts[total].x = coord(&r);
                        pts[total].y = coord(&r);
                    }
                    if (bad_number(pts[total].x) || bad_number(pts[total].y))
                        bad = 1;
                    total++;
                }
            }
            a.points = pts;
            a.sizes = sizes;
            a.contours = contours;
            if (code % 8 == 2) {
                a.color = color(&r);
                draw_both(OP_POLYGON, ras, default_tolerance, &c, &a, bad, a.color.a == 0);
            } else {
                read_paint(&r, &pi);
                a.paint = &pi.paint;
                draw_both(OP_POLYGON_AA, ras, default_tolerance, &c, &a, bad || pi.bad,
                          pi.transparent);
            }
            break;
        }
        case 3:
        case 4: { /* fill or stroke a path of SVG data or built through the API */
            unsigned how = byte(&r);
            if (how & 1)
                cg_path_reset(path);
            if (how & 2)
                svg_path(&r, path);
            else
                api_path(&r, path);
            read_paint(&r, &pi);
            a.paint = &pi.paint;
            a.path = path;
            if (code % 8 == 3) {
                draw_both(OP_FILL_PATH, ras, default_tolerance, &c, &a, pi.bad, pi.transparent);
            } else {
                cg_stroke_style st;
                double dashes[5];
                int bad = read_style(&r, &st, dashes);
                a.style = &st;
                draw_both(OP_STROKE_PATH, ras, default_tolerance, &c, &a, bad || pi.bad,
                          pi.transparent);
            }
            break;
        }
        case 5:
        case 6: { /* flood and boundary fill */
            int x = (int)(byte(&r) % (MAX_SIDE + 8)) - 4, y = (int)(byte(&r) % (MAX_SIDE + 8)) - 4;
            unsigned f = byte(&r);
            cg_connectivity conn = f % 3 == 0   ? CG_CONNECT_4
                                   : f % 3 == 1 ? CG_CONNECT_8
                                                : (cg_connectivity)5;
            int tol = (int)(byte(&r) % 40) - 4;
            if (tol > 30)
                tol = 255;
            cg_rgba8 fc = color(&r);
            canvas before;
            if (!canvas_copy(&c, &before))
                break;
            cg_rgba8 seed_before = cg_image_contains(&c.image, x, y)
                                       ? cg_image_row_rgba8(&c.image, y)[x]
                                       : fc;
            size_t filled = (size_t)-1;
            cg_status s;
            int boundary_seed = 0;
            if (code % 8 == 5) {
                s = cg_flood_fill(&c.image, x, y, fc, conn, tol, &filled);
            } else {
                cg_rgba8 bc = (f & 0x80) ? seed_before : palette[f % 4];
                int d = abs(seed_before.r - bc.r);
                if (abs(seed_before.g - bc.g) > d)
                    d = abs(seed_before.g - bc.g);
                if (abs(seed_before.b - bc.b) > d)
                    d = abs(seed_before.b - bc.b);
                if (abs(seed_before.a - bc.a) > d)
                    d = abs(seed_before.a - bc.a);
                boundary_seed = d <= tol;
                s = cg_boundary_fill(&c.image, x, y, fc, bc, conn, tol, &filled);
            }
            int bad = !cg_image_contains(&c.image, x, y) || tol < 0 || tol > 255
                      || (conn != CG_CONNECT_4 && conn != CG_CONNECT_8);
            check_draw(s, &c, &before, bad, 0);
            if (s == CG_OK) {
                check(filled <= (size_t)w * (size_t)h);
                cg_rgba8 now = cg_image_row_rgba8(&c.image, y)[x];
                if (!boundary_seed) {
                    check(filled >= 1);
                    check(memcmp(&now, &fc, 4) == 0);
                } else {
                    check(filled == 0 && canvas_equal(&c, &before));
                }
            }
            free(before.buffer);
            break;
        }
        default: { /* the rasterizer's flattening tolerance */
            unsigned b = byte(&r);
            double t = b == 255 ? NAN : b == 254 ? 0.0005 : b == 253 ? 101.0 : 0.001 + b * 0.02;
            cg_status s = cg_rasterizer_set_tolerance(ras, t);
            check_status(s);
            check((s == CG_OK) == (t >= 0.001 && t <= 100));
            if (s == CG_OK)
                default_tolerance = t == 0.1;
            break;
        }
        }
    }
    cg_path_free(path);
    cg_rasterizer_free(ras);
    free(c.buffer);
    return 0;
}
