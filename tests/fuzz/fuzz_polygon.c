/* libFuzzer target: the polygon geometry beyond booleans (cg/polygon.h) on
 * the integer and double APIs.  See README-polygon.md for the input layout.
 * Per input, on a few rings mostly on a 0..63 grid (self-crossing,
 * touching, degenerate):
 *   - every call returns CG_OK, or CG_ERANGE exactly when a coordinate lies
 *     beyond CG_CLIP_MAX_COORD (never an abort, never another status);
 *   - offsets: a result well formed (outer rings counter-clockwise, holes
 *     clockwise, rings of 3 points or more); inflating never loses area of
 *     the union, deflating never gains any;
 *   - rectangle clips: every vertex inside the rectangle, the area at most
 *     the union's (and that of the rectangle) plus the rounding;
 *   - triangulations (refined to a minimum angle too): every triangle
 *     counter-clockwise with positive area, twice their areas summing
 *     exactly to twice the union's;
 *   - simplification: as many rings as the union, each of 3 points or more;
 *   - open paths clipped by polygons (the rings as polylines, against their
 *     own union and against the rectangle): pieces of two distinct points
 *     or more; the intersection and the difference together as long as the
 *     paths, and the intersection with the rectangle as long as the
 *     rectangle clip of the lines, within the rounding of the crossings;
 *   - variable offsets as offsets (bit 7): well formed, inflating never
 *     loses area, deflating never gains any; Minkowski sums well formed;
 *   - the double API with scale 1 gives the integer API's areas. */
#include "cg/polygon.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

__extension__ typedef __int128 i128;

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

#define FAIL() fail(__LINE__)
static void fail(int line)
{
    fprintf(stderr, "fuzz_polygon.c:%d: invariant broken\n", line);
    abort();
}

typedef struct reader {
    const unsigned char *p;
    size_t n;
} reader;

static unsigned get(reader *r)
{
    if (!r->n)
        return 0;
    r->n--;
    return *r->p++;
}

static i128 twice_area(const cg_point64 *p, size_t n)
{
    i128 s = 0;
    for (size_t i = 1; i + 1 < n; i++)
        s += (i128)(p[i].x - p[0].x) * (p[i + 1].y - p[0].y)
             - (i128)(p[i + 1].x - p[0].x) * (p[i].y - p[0].y);
    return s;
}

static i128 set_twice_area(const cg_polygon_set64 *s)
{
    i128 total = 0;
    for (size_t r = 0; r < s->ring_count; r++)
        total += twice_area(s->points + s->ring_start[r], s->ring_start[r + 1] - s->ring_start[r]);
    return total;
}

/* A boolean-style result: polygons whose first ring is counter-clockwise,
 * the others clockwise, every ring of 3 points or more. */
static void check_well_formed(const cg_polygon_set64 *s)
{
    for (size_t p = 0; p < s->polygon_count; p++)
        for (size_t r = s->polygon_start[p]; r < s->polygon_start[p + 1]; r++) {
            size_t n = s->ring_start[r + 1] - s->ring_start[r];
            if (n < 3)
                FAIL();
            i128 a = twice_area(s->points + s->ring_start[r], n);
            if ((r == s->polygon_start[p]) != (a > 0))
                FAIL();
        }
}

static void check_status(cg_status st, int in_range)
{
    if (st != CG_OK && !(st == CG_ERANGE && !in_range))
        FAIL();
}

static double set_length(const cg_polygon_set64 *s)
{
    double total = 0;
    for (size_t r = 0; r < s->ring_count; r++) {
        if (s->ring_start[r + 1] - s->ring_start[r] < 2)
            FAIL();
        for (size_t i = s->ring_start[r]; i + 1 < s->ring_start[r + 1]; i++) {
            double dx = (double)(s->points[i + 1].x - s->points[i].x);
            double dy = (double)(s->points[i + 1].y - s->points[i].y);
            if (dx == 0 && dy == 0)
                FAIL();
            total += hypot(dx, dy);
        }
    }
    return total;
}

static double paths_length(const cg_polygon_set64 *s)
{
    double total = 0;
    for (size_t r = 0; r < s->ring_count; r++)
        for (size_t i = s->ring_start[r]; i + 1 < s->ring_start[r + 1]; i++)
            total += hypot((double)(s->points[i + 1].x - s->points[i].x),
                           (double)(s->points[i + 1].y - s->points[i].y));
    return total;
}

/* The rings of in as open paths, clipped by their own union (simple) and by
 * the rectangle. */
static void check_lines(const cg_polygon_set64 *in, const cg_polygon_set64 *simple, cg_rect64 rect,
                        int in_range)
{
    cg_polygon_set64 inside = {0}, outside = {0}, window = {0}, by_rect = {0};
    cg_status st = cg_clip_lines64(CG_CLIP_INTERSECTION, in, simple, CG_CLIP_NON_ZERO, &inside);
    check_status(st, in_range);
    if (st == CG_OK) {
        st = cg_clip_lines64(CG_CLIP_DIFFERENCE, in, simple, CG_CLIP_NON_ZERO, &outside);
        check_status(st, 1);
        double slack = 2.0 * (double)(inside.ring_count + outside.ring_count + 1);
        if (fabs(set_length(&inside) + set_length(&outside) - paths_length(in)) > slack)
            FAIL();
    }
    if (st == CG_OK && rect.xmin < rect.xmax && rect.ymin < rect.ymax) {
        cg_point64 w[4] = {{rect.xmin, rect.ymin},
                           {rect.xmax, rect.ymin},
                           {rect.xmax, rect.ymax},
                           {rect.xmin, rect.ymax}};
        cg_polygon_set64_add_ring(&window, w, 4, 1);
        /* the general engine refuses a window beyond its grid; the
         * rectangle clip takes any rectangle */
        int window_in_range = rect.xmax <= CG_CLIP_MAX_COORD && rect.ymax <= CG_CLIP_MAX_COORD;
        cg_status by_window = cg_clip_lines64(CG_CLIP_INTERSECTION, in, &window, CG_CLIP_EVEN_ODD,
                                              &inside);
        check_status(by_window, window_in_range);
        if (cg_rect_clip_lines64(in, rect, &by_rect) != CG_OK)
            FAIL();
        double length = 0; /* the rectangle clip keeps pieces of one point */
        for (size_t r = 0; r < by_rect.ring_count; r++)
            for (size_t i = by_rect.ring_start[r]; i + 1 < by_rect.ring_start[r + 1]; i++)
                length += hypot((double)(by_rect.points[i + 1].x - by_rect.points[i].x),
                                (double)(by_rect.points[i + 1].y - by_rect.points[i].y));
        double slack = 2.0 * (double)(inside.ring_count + by_rect.ring_count + 1);
        if (by_window == CG_OK && fabs(set_length(&inside) - length) > slack)
            FAIL();
    }
    cg_polygon_set64_clear(&inside);
    cg_polygon_set64_clear(&outside);
    cg_polygon_set64_clear(&window);
    cg_polygon_set64_clear(&by_rect);
}

/* Variable offsets (the distance at vertex i: delta scaled by i mod 3)
 * and the Minkowski sum of the first ring's region with the rings (as
 * paths when the end is round, else as a region). */
static void check_variable_and_minkowski(const cg_polygon_set64 *in, double delta,
                                         cg_offset_options *o, i128 area, int in_range)
{
    cg_polygon_set64 out = {0}, pattern = {0};
    double deltas[4 * 32];
    for (size_t i = 0; i < in->point_count; i++)
        deltas[i] = delta * (double)(i % 3) / 2;
    cg_status st = cg_offset_variable64(in, deltas, o, &out);
    if (st != CG_ERANGE) {
        check_status(st, 1);
        check_well_formed(&out);
        if (o->end == CG_OFFSET_END_POLYGON && delta > 0 && set_twice_area(&out) < area)
            FAIL();
        if (o->end == CG_OFFSET_END_POLYGON && delta < 0 && set_twice_area(&out) > area)
            FAIL();
    }
    if (in->ring_count > 0)
        cg_polygon_set64_add_ring(&pattern, in->points, in->ring_start[1], 1);
    int open = o->end != CG_OFFSET_END_POLYGON;
    st = cg_minkowski64(delta < 0 ? CG_MINKOWSKI_DIFFERENCE : CG_MINKOWSKI_SUM, &pattern, in, open,
                        o->fill, &out);
    if (st != CG_ERANGE) {
        check_status(st, in_range);
        check_well_formed(&out);
    }
    cg_polygon_set64_clear(&out);
    cg_polygon_set64_clear(&pattern);
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    reader r = {data, size};
    unsigned head = get(&r), rings = 1 + (get(&r) & 3), shift = get(&r) % 40;
    cg_polygon_set64 in = {0}, simple = {0}, none = {0}, out = {0};
    int in_range = 1;
    for (unsigned k = 0; k < rings; k++) {
        cg_point64 p[32];
        unsigned n = get(&r) % 32;
        for (unsigned i = 0; i < n; i++) {
            int64_t x = (int64_t)(get(&r) & 63), y = (int64_t)(get(&r) & 63);
            p[i] = (cg_point64){x * ((int64_t)1 << shift), y * ((int64_t)1 << shift)};
            in_range &= p[i].x <= CG_CLIP_MAX_COORD && p[i].y <= CG_CLIP_MAX_COORD;
        }
        cg_polygon_set64_add_ring(&in, p, n, 1);
    }
    cg_clip_fill fill = (cg_clip_fill)(head >> 2 & 3);
    cg_status st = cg_clip_boolean64(CG_CLIP_UNION, &in, fill, &none, fill, &simple);
    check_status(st, in_range);
    if (st != CG_OK)
        goto done;
    i128 area = set_twice_area(&simple);
    double scale = (double)((int64_t)1 << shift);
    switch (head & 3) {
    case 0: { /* offset */
        cg_offset_options o = cg_offset_options_default();
        o.join = (cg_offset_join)(head >> 4 & 3);
        o.fill = fill;
        o.end = head & 64 ? CG_OFFSET_END_ROUND : CG_OFFSET_END_POLYGON;
        double delta = ((double)(get(&r) % 16) - 8) * scale * 0.75;
        if (head & 128) {
            check_variable_and_minkowski(&in, delta, &o, area, in_range);
            break;
        }
        st = cg_offset64(&in, delta, &o, &out);
        if (st == CG_ERANGE)
            break; /* the offset itself may leave the grid */
        check_status(st, 1);
        check_well_formed(&out);
        if (o.end == CG_OFFSET_END_POLYGON && delta > 0 && set_twice_area(&out) < area)
            FAIL();
        if (o.end == CG_OFFSET_END_POLYGON && delta < 0 && set_twice_area(&out) > area)
            FAIL();
        break;
    }
    case 1: { /* rectangle */
        int64_t v[4];
        for (int k = 0; k < 4; k++)
            v[k] = (int64_t)(get(&r) & 63) * ((int64_t)1 << shift);
        cg_rect64 rect = {v[0] < v[2] ? v[0] : v[2], v[1] < v[3] ? v[1] : v[3],
                          v[0] < v[2] ? v[2] : v[0], v[1] < v[3] ? v[3] : v[1]};
        if (head & 32)
            check_lines(&in, &simple, rect, in_range);
        st = head & 64 ? cg_rect_clip_lines64(&in, rect, &out)
                       : cg_rect_clip64(&in, fill, rect, &out);
        check_status(st, in_range);
        for (size_t i = 0; i < out.point_count; i++)
            if (out.points[i].x < rect.xmin || out.points[i].x > rect.xmax
                || out.points[i].y < rect.ymin || out.points[i].y > rect.ymax)
                FAIL();
        if (!(head & 64)) {
            check_well_formed(&out);
            /* each crossing rounded moves an edge by half a unit */
            double slack = (double)(in.point_count + 4) * 2
                           * ((double)(rect.xmax - rect.xmin) + (double)(rect.ymax - rect.ymin)
                              + 2);
            if ((double)set_twice_area(&out) > (double)area + slack)
                FAIL();
        }
        break;
    }
    case 2: /* triangulation, refined to a minimum angle with bit 6 */
        st = head & 64 ? cg_triangulate_refined64(&in, fill, (double)(get(&r) % 31), &out)
                       : cg_triangulate64(&in, fill, &out);
        check_status(st, in_range);
        for (size_t t = 0; t < out.ring_count; t++)
            if (out.ring_start[t + 1] - out.ring_start[t] != 3
                || twice_area(out.points + out.ring_start[t], 3) <= 0)
                FAIL();
        if (set_twice_area(&out) != area)
            FAIL();
        break;
    default: { /* simplification */
        cg_simplify_algorithm a = head & 16 ? CG_SIMPLIFY_VISVALINGAM : CG_SIMPLIFY_RDP;
        double tolerance = (double)(get(&r) % 8) * scale
                           * (a == CG_SIMPLIFY_VISVALINGAM ? scale : 1);
        st = cg_simplify64(&in, 0, fill, a, tolerance, &out);
        check_status(st, in_range);
        check_well_formed(&out);
        if (out.ring_count != simple.ring_count)
            FAIL();
        break;
    }
    }
    if ((head & 128) && shift == 0 && (head & 3) == 2) {
        /* the double API on the same grid */
        cg_polygon_set d = {0}, dout = {0};
        for (size_t k = 0; k < in.ring_count; k++) {
            cg_vec2 q[32];
            size_t n = in.ring_start[k + 1] - in.ring_start[k];
            for (size_t i = 0; i < n; i++)
                q[i] = cg_vec2_make((double)in.points[in.ring_start[k] + i].x,
                                    (double)in.points[in.ring_start[k] + i].y);
            cg_polygon_set_add_ring(&d, q, n, 1);
        }
        if (cg_triangulate(&d, fill, 1, &dout) != CG_OK)
            FAIL();
        if (fabs(cg_polygon_set_area(&dout) - (double)area / 2) > 1e-6)
            FAIL();
        cg_polygon_set_clear(&d);
        cg_polygon_set_clear(&dout);
    }
done:
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&simple);
    cg_polygon_set64_clear(&out);
    return 0;
}
