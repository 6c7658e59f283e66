/* Private pieces shared by the clip module's files. */
#ifndef CG_CLIP_INTERNAL_H
#define CG_CLIP_INTERNAL_H

#include "cg/clip.h"

__extension__ typedef __int128 clip_i128;

/* Scale for the double API (see cg_clip_boolean): the given one, or the
 * power of two that maps max_abs to at most 2^36. */
double clip_pick_scale(double scale, double max_abs);
/* Scales and rounds a double set to the grid; CG_EINVAL for non-finite
 * values, CG_ERANGE beyond CG_CLIP_MAX_COORD. */
cg_status clip_to_grid(const cg_polygon_set *in, double scale, cg_polygon_set64 *out);
cg_status clip_from_grid(const cg_polygon_set64 *in, double scale, cg_polygon_set *out);
/* Largest |coordinate| of a set (0 when empty); NaN when one is not finite. */
double clip_max_abs(const cg_polygon_set *set);

#endif
