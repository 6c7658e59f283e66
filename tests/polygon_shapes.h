/* Random shapes and GEOS conversions for the polygon-geometry tests
 * (offset, rectangle clipping, triangulation, simplification). */
#ifndef CG_TEST_POLYGON_SHAPES_H
#define CG_TEST_POLYGON_SHAPES_H

#include "cg/polygon.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* xorshift64*: the same shapes on every machine. */
static uint64_t shapes_state = 0x9e3779b97f4a7c15ull;
static inline double shapes_uniform(void)
{
    shapes_state ^= shapes_state >> 12;
    shapes_state ^= shapes_state << 25;
    shapes_state ^= shapes_state >> 27;
    return (double)((shapes_state * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}
static inline double shapes_between(double lo, double hi)
{
    return lo + (hi - lo) * shapes_uniform();
}

/* A whole number in [lo, hi] (hi - lo below 2^63), from the same stream. */
static inline int64_t shapes_int(int64_t lo, int64_t hi)
{
    return lo
           + (int64_t)((uint64_t)(shapes_uniform() * 9007199254740992.0) % (uint64_t)(hi - lo + 1));
}

/* Twice the signed area of triangle a b c, exact for any grid coordinates. */
__extension__ typedef __int128 shapes_i128;
static inline shapes_i128 shapes_cross64(cg_point64 a, cg_point64 b, cg_point64 c)
{
    return (shapes_i128)(b.x - a.x) * (c.y - a.y) - (shapes_i128)(b.y - a.y) * (c.x - a.x);
}

/* A star-shaped ring of n vertices around c: radius between r_lo and r_hi at
 * sorted random angles; counter-clockwise, or clockwise when reversed. */
static inline void shapes_star(cg_vec2 *out, int n, cg_vec2 c, double r_lo, double r_hi,
                               int reversed)
{
    double *angles = malloc((size_t)n * sizeof *angles);
    double a = 0;
    for (int i = 0; i < n; i++) {
        a += shapes_between(0.3, 1.0);
        angles[i] = a;
    }
    for (int i = 0; i < n; i++) {
        double t = 2 * M_PI * angles[i] / (a + shapes_between(0.3, 1.0));
        double r = shapes_between(r_lo, r_hi);
        out[reversed ? n - 1 - i : i] = cg_vec2_make(c.x + r * cos(t), c.y + r * sin(t));
    }
    free(angles);
}

/* A convex ring of n vertices on the circle of radius r around c, no gap
 * between consecutive vertices wider than 2pi/3 (interior angles >= 60
 * degrees). */
static inline void shapes_convex(cg_vec2 *out, int n, cg_vec2 c, double r, int reversed)
{
    double *angles = malloc((size_t)n * sizeof *angles), a = 0;
    for (int i = 0; i < n; i++) {
        a += shapes_between(0.5, 1.0);
        angles[i] = a;
    }
    double total = a + shapes_between(0.5, 1.0);
    for (int i = 0; i < n; i++) {
        double t = 2 * M_PI * angles[i] / total;
        out[reversed ? n - 1 - i : i] = cg_vec2_make(c.x + r * cos(t), c.y + r * sin(t));
    }
    free(angles);
}

/* The winding number of the rings of s around the point (x, y), counted
 * by the crossing rule: +1 for each edge crossing upward with the point on
 * its left, -1 downward with the point on its right. */
static inline int shapes_winding64(const cg_polygon_set64 *s, double x, double y)
{
    int w = 0;
    for (size_t r = 0; r < s->ring_count; r++) {
        size_t a = s->ring_start[r], b = s->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_point64 p = s->points[i], q = s->points[i + 1 < b ? i + 1 : a];
            double c = (double)(q.x - p.x) * (y - (double)p.y)
                       - (x - (double)p.x) * (double)(q.y - p.y);
            if ((double)p.y <= y && (double)q.y > y && c > 0)
                w++;
            else if ((double)q.y <= y && (double)p.y > y && c < 0)
                w--;
        }
    }
    return w;
}

/* A simple random region: one to three stars, each with a small star hole
 * (only the first when holes_in_every_star is 0), united by cg so that
 * GEOS accepts the result. */
static inline void shapes_random_region(cg_polygon_set *region, int holes_in_every_star)
{
    cg_polygon_set raw = {0}, none = {0};
    cg_vec2 ring[60];
    int stars = 1 + (int)(shapes_uniform() * 3);
    for (int k = 0; k < stars; k++) {
        int n = 5 + (int)(shapes_uniform() * 50);
        cg_vec2 c = {shapes_between(-30, 30), shapes_between(-30, 30)};
        shapes_star(ring, n, c, 5, 25, 0);
        cg_polygon_set_add_ring(&raw, ring, (size_t)n, 1);
        if (k == 0 || holes_in_every_star) {
            shapes_star(ring, 8, c, 1, 4, 1);
            cg_polygon_set_add_ring(&raw, ring, 8, 1);
        }
    }
    cg_clip_boolean(CG_CLIP_UNION, &raw, CG_CLIP_NON_ZERO, &none, CG_CLIP_NON_ZERO, 0, region);
    cg_polygon_set_clear(&raw);
}

#ifdef SHAPES_WITH_GEOS
#include <geos_c.h>

/* A GEOS context whose notices and errors are silent (the tests judge
 * GEOS's answers, not its messages). */
static inline void shapes_geos_silence(const char *fmt, ...)
{
    (void)fmt;
}
static inline GEOSContextHandle_t shapes_geos_start(void)
{
    GEOSContextHandle_t h = GEOS_init_r();
    GEOSContext_setNoticeHandler_r(h, shapes_geos_silence);
    GEOSContext_setErrorHandler_r(h, shapes_geos_silence);
    return h;
}

static inline GEOSGeometry *shapes_geos_ring(GEOSContextHandle_t h, const cg_vec2 *p, size_t n,
                                             int closed)
{
    unsigned count = (unsigned)n + (closed ? 1 : 0);
    GEOSCoordSequence *s = GEOSCoordSeq_create_r(h, count, 2);
    for (unsigned i = 0; i < count; i++) {
        GEOSCoordSeq_setX_r(h, s, i, p[i % n].x);
        GEOSCoordSeq_setY_r(h, s, i, p[i % n].y);
    }
    return closed ? GEOSGeom_createLinearRing_r(h, s) : GEOSGeom_createLineString_r(h, s);
}

/* A result set (polygons with their holes) as a GEOS MultiPolygon. */
static inline GEOSGeometry *shapes_geos_polygons(GEOSContextHandle_t h, const cg_polygon_set *s)
{
    size_t np = s->polygon_count;
    GEOSGeometry **polys = malloc((np ? np : 1) * sizeof *polys);
    for (size_t k = 0; k < np; k++) {
        size_t r0 = s->polygon_start[k], r1 = s->polygon_start[k + 1];
        GEOSGeometry *outer = shapes_geos_ring(h, s->points + s->ring_start[r0],
                                               s->ring_start[r0 + 1] - s->ring_start[r0], 1);
        GEOSGeometry **holes = malloc((r1 - r0) * sizeof *holes);
        for (size_t r = r0 + 1; r < r1; r++)
            holes[r - r0 - 1] = shapes_geos_ring(h, s->points + s->ring_start[r],
                                                 s->ring_start[r + 1] - s->ring_start[r], 1);
        polys[k] = GEOSGeom_createPolygon_r(h, outer, holes, (unsigned)(r1 - r0 - 1));
        free(holes);
    }
    GEOSGeometry *g = GEOSGeom_createCollection_r(h, GEOS_MULTIPOLYGON, polys, (unsigned)np);
    free(polys);
    return g;
}

/* Every ring of s as an open line string, in a GEOS MultiLineString. */
static inline GEOSGeometry *shapes_geos_lines(GEOSContextHandle_t h, const cg_polygon_set *s)
{
    size_t n = s->ring_count;
    GEOSGeometry **lines = malloc((n ? n : 1) * sizeof *lines);
    for (size_t r = 0; r < n; r++)
        lines[r] = shapes_geos_ring(h, s->points + s->ring_start[r],
                                    s->ring_start[r + 1] - s->ring_start[r], 0);
    GEOSGeometry *g = GEOSGeom_createCollection_r(h, GEOS_MULTILINESTRING, lines, (unsigned)n);
    free(lines);
    return g;
}
#endif

#endif
