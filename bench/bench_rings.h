/* Integer polygon sets as the clipping peers take them (bench_clip,
 * bench_polygon): the coordinates flat, x then y, and each ring's length. */
#ifndef CG_BENCH_RINGS_H
#define CG_BENCH_RINGS_H

#include "cg/clip.h"

#include <stdint.h>
#include <stdlib.h>

/* *xy: 2 coordinates a point; *len: the points of each ring (one spare
 * entry each, so an empty set still allocates). */
static inline void bench_rings_flatten(const cg_polygon_set64 *set, int64_t **xy, size_t **len)
{
    *xy = malloc(2 * (set->point_count + 1) * sizeof **xy);
    *len = malloc((set->ring_count + 1) * sizeof **len);
    for (size_t i = 0; i < set->point_count; i++) {
        (*xy)[2 * i] = set->points[i].x;
        (*xy)[2 * i + 1] = set->points[i].y;
    }
    for (size_t r = 0; r < set->ring_count; r++)
        (*len)[r] = set->ring_start[r + 1] - set->ring_start[r];
}

#endif
