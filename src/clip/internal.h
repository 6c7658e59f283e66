/* Private pieces shared by the clip module's files. */
#ifndef CG_CLIP_INTERNAL_H
#define CG_CLIP_INTERNAL_H

#include "cg/clip.h"

__extension__ typedef __int128 clip_i128;

/* Room in set for this many points, rings and polygons in all, grown as
 * cg_polygon_set*_add_ring grows it (the capacities come out the same as
 * when the rings are added one by one). */
cg_status clip_polygon_set_reserve(cg_polygon_set *set, size_t points, size_t rings,
                                   size_t polygons);
cg_status clip_polygon_set64_reserve(cg_polygon_set64 *set, size_t points, size_t rings,
                                     size_t polygons);

/* The first point of ring r of set.  A set whose rings hold no point may
 * have no point array at all (points == NULL), and NULL + 0 is undefined
 * in C: the offset is taken only when there is an array. */
static inline const cg_point64 *clip_ring_points(const cg_polygon_set64 *set, size_t r)
{
    return set->points ? set->points + set->ring_start[r] : set->points;
}

/* Twice the signed area of the ring p[0..n) (counter-clockwise positive),
 * exact (0 below 3 points). */
clip_i128 clip_ring_twice_area(const cg_point64 *p, size_t n);

/* Twice the signed area of the ring p[0..n) in doubles (counter-clockwise
 * positive; n >= 1): the orientation of the windows and subjects of
 * Sutherland-Hodgman and Weiler-Atherton and of their traces. */
double clip_twice_area(const cg_vec2 *p, size_t n);
/* Weiler-Atherton's input rings (weiler.c, and its trace in trace_weiler.c):
 * a copy of in[0..n) into out without repeated points, counter-clockwise,
 * moved by d; returns the copy's size. */
size_t clip_weiler_prepare(const cg_vec2 *in, size_t n, cg_vec2 d, cg_vec2 *out);
/* Whether the subject edge a + t d and the window edge c + u e cross
 * properly, 0 <= t < 1 and 0 <= u < 1 (parallel edges never do); then *t,
 * *u, and *entering: the subject goes into the counter-clockwise window. */
int clip_weiler_crossing(cg_vec2 a, cg_vec2 d, cg_vec2 c, cg_vec2 e, double *t, double *u,
                         int *entering);

#endif
