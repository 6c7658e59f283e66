/* Private pieces of the triangulation (src/clip/triangulate*.c). */
#ifndef CG_CLIP_TRIANGULATE_INTERNAL_H
#define CG_CLIP_TRIANGULATE_INTERNAL_H

#include "polygon_internal.h"

/* The sign of the in-circle determinant of a, b, c (counter-clockwise) and
 * d: positive when d lies strictly inside the circle through a, b, c, zero
 * on it, negative outside.  Exact for coordinates within 2^44. */
int triangulate_incircle(cg_point64 a, cg_point64 b, cg_point64 c, cg_point64 d);

#endif
