/* Pieces shared inside src/curve. */
#ifndef CG_CURVE_INTERNAL_H
#define CG_CURVE_INTERNAL_H

#include "cg/curve.h"

/* True when every coordinate of the count points is finite. */
int curve_points_finite(const cg_vec2 *points, int count);
/* de Casteljau in place (work[0] becomes Q(t)); left and right, when not
 * NULL, receive the control polygons of [0, t] and [t, 1]. */
void curve_casteljau(cg_vec2 *work, int count, double t, cg_vec2 *left, cg_vec2 *right);

/* Adaptive flattening's pieces (flatten.c), shared with its trace: the
 * squared distance from p to the segment a-b, and the deepest level of
 * halving (CG_ERANGE when the tolerance is too small for the curve). */
double curve_distance2_to_segment(cg_vec2 p, cg_vec2 a, cg_vec2 b);
cg_status curve_flatten_depth(const cg_vec2 *control, int count, double tolerance, int *depth);

#endif
