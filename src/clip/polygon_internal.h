/* Private pieces shared by the polygon-geometry files of the clip module
 * (offset, rectangle clipping, triangulation, simplification): the grid of
 * the double API and small exact helpers on int64 rings.  They use only the
 * boolean engine's public API (cg/clip.h). */
#ifndef CG_CLIP_POLYGON_INTERNAL_H
#define CG_CLIP_POLYGON_INTERNAL_H

#include "cg/polygon.h"

__extension__ typedef __int128 polygon_i128;

/* The grid of a double API call: multiply by an explicit scale, or
 * (automatic) by 2^exponent, which is exact at any magnitude. */
typedef struct polygon_grid {
    double scale;
    int exponent;
} polygon_grid;

/* The grid for scale (<= 0: automatic, mapping `largest` below 2^36).
 * CG_EINVAL for a NaN or infinite scale or largest. */
cg_status polygon_grid_pick(double scale, double largest, polygon_grid *grid);
double polygon_grid_to(polygon_grid grid, double value);
double polygon_grid_from(polygon_grid grid, int64_t value);
/* The largest |coordinate| of the set: NaN when one is not finite. */
double polygon_max_abs(const cg_polygon_set *set);
/* The set on the grid, ring by ring (out emptied first): CG_ERANGE when a
 * rounded coordinate leaves +-CG_CLIP_MAX_COORD, CG_EINVAL for a ring
 * outside the point array. */
cg_status polygon_set_to_grid(const cg_polygon_set *in, polygon_grid grid, cg_polygon_set64 *out);
/* The grid set back in doubles (out emptied first), polygons kept. */
cg_status polygon_set_from_grid(const cg_polygon_set64 *in, polygon_grid grid, cg_polygon_set *out);

/* Twice the signed area of the ring p[0..n), exact (0 below 3 points). */
polygon_i128 polygon_ring_twice_area(const cg_point64 *p, size_t n);
/* The largest |coordinate| of the set; CG_EINVAL when a ring lies outside
 * its point array. */
cg_status polygon_set64_max_abs(const cg_polygon_set64 *set, int64_t *largest);
/* That check, then CG_ERANGE when a coordinate is beyond CG_CLIP_MAX_COORD. */
cg_status polygon_set64_check_range(const cg_polygon_set64 *set);
/* Drops from a result (polygons with holes) every ring narrower than a
 * grid unit on average (its area below half its perimeter), the rounding's
 * slivers: a polygon with its holes when it is its outer ring, a hole
 * alone (filled) otherwise.  The rings left keep their order. */
void polygon_drop_slivers(cg_polygon_set64 *set);
/* Sign of the cross product (b - a) x (c - a), exact. */
int polygon_orient(cg_point64 a, cg_point64 b, cg_point64 c);

#endif
