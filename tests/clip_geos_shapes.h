/* cg polygon sets as GEOS geometries, for the tests that check the boolean
 * operations against GEOS (clip_geos.c, clip_valid.c). */
#ifndef CG_TESTS_CLIP_GEOS_SHAPES_H
#define CG_TESTS_CLIP_GEOS_SHAPES_H

#include "cg/clip.h"

#include <geos_c.h>
#include <stdlib.h>

/* (GEOS's notices and errors are not the tests' business: they check the
 * results) */
static void clip_geos_quiet(const char *fmt, ...)
{
    (void)fmt;
}

/* A GEOS context that says nothing. */
static inline GEOSContextHandle_t clip_geos_start(void)
{
    GEOSContextHandle_t h = GEOS_init_r();
    GEOSContext_setNoticeHandler_r(h, clip_geos_quiet);
    GEOSContext_setErrorHandler_r(h, clip_geos_quiet);
    return h;
}

/* The closed ring p[0..n) as a GEOS linear ring (the first point repeated
 * at the end). */
static inline GEOSGeometry *clip_geos_ring(GEOSContextHandle_t h, const cg_vec2 *p, size_t n)
{
    GEOSCoordSequence *s = GEOSCoordSeq_create_r(h, (unsigned)n + 1, 2);
    for (size_t i = 0; i <= n; i++) {
        GEOSCoordSeq_setX_r(h, s, (unsigned)i, p[i % n].x);
        GEOSCoordSeq_setY_r(h, s, (unsigned)i, p[i % n].y);
    }
    return GEOSGeom_createLinearRing_r(h, s);
}

/* The set as a GEOS MultiPolygon: each of its polygons (polygon_start) its
 * outer ring, then its holes, as many as it has. */
static inline GEOSGeometry *clip_geos_polygons(GEOSContextHandle_t h, const cg_polygon_set *s)
{
    size_t np = s->polygon_count;
    GEOSGeometry **polys = malloc((np ? np : 1) * sizeof *polys);
    for (size_t k = 0; k < np; k++) {
        size_t r0 = s->polygon_start[k], r1 = s->polygon_start[k + 1];
        GEOSGeometry *outer = clip_geos_ring(h, s->points + s->ring_start[r0],
                                             s->ring_start[r0 + 1] - s->ring_start[r0]);
        GEOSGeometry **holes = malloc((r1 - r0) * sizeof *holes);
        for (size_t r = r0 + 1; r < r1; r++)
            holes[r - r0 - 1] = clip_geos_ring(h, s->points + s->ring_start[r],
                                               s->ring_start[r + 1] - s->ring_start[r]);
        polys[k] = GEOSGeom_createPolygon_r(h, outer, holes, (unsigned)(r1 - r0 - 1));
        free(holes);
    }
    GEOSGeometry *g = GEOSGeom_createCollection_r(h, GEOS_MULTIPOLYGON, polys, (unsigned)np);
    free(polys);
    return g;
}

#endif
