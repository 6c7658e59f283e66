/* Private pieces of the triangulation (src/clip/triangulate*.c). */
#ifndef CG_CLIP_TRIANGULATE_INTERNAL_H
#define CG_CLIP_TRIANGULATE_INTERNAL_H

#include "polygon_internal.h"

/* The sign of the in-circle determinant of a, b, c (counter-clockwise) and
 * d: positive when d lies strictly inside the circle through a, b, c, zero
 * on it, negative outside.  Exact for coordinates within 2^44. */
int triangulate_incircle(cg_point64 a, cg_point64 b, cg_point64 c, cg_point64 d);

/* The constrained Delaunay triangulation of simple rings (a boolean result,
 * or one with points added on its edges) and extra points inside them:
 * every distinct point a vertex, every ring edge a union of triangle edges;
 * the triangles inside into result (emptied first), each one ring of three
 * points counter-clockwise.  CG_EUNSUPPORTED beyond 2^30 points. */
cg_status triangulate_cdt(const cg_polygon_set64 *rings, const cg_point64 *extra,
                          size_t extra_count, cg_polygon_set64 *result);

/* The constrained Delaunay triangulation of simple rings refined until no
 * triangle has an angle below min_angle degrees (0 < min_angle <= 30),
 * except those whose smallest angle lies at a vertex where ring edges meet
 * at less than 60 degrees; the triangles into result (emptied first). */
cg_status triangulate_refine(const cg_polygon_set64 *simple, double min_angle,
                             cg_polygon_set64 *result);

#endif
