/* Private: constant sRGB lookup tables shared by the image, colour, fill and
 * render code, and the one exact encode built on them. */
#ifndef CG_SRGB_TABLES_H
#define CG_SRGB_TABLES_H

#include "cg/image.h" /* cg_rgba8 */

#include "../core/simd4.h"

#include <stdint.h>

extern const float color_srgb_decode_table[256];
/* threshold[k]: least linear value of code k + 1; threshold[255] = +infinity. */
extern const float color_srgb_threshold_table[256];
/* encode_start[i]: the code of linear value i / 4096 (i = 0 .. 4096). */
extern const uint8_t color_srgb_encode_start[4097];

/* The correctly rounded sRGB code of a linear value, clamped to [0, 1]
 * (NaN gives 0).  The value's 1/4096 bucket gives the least code it can
 * have; at most one threshold lies inside a bucket (checked when the tables
 * were made), so one comparison settles the code, without branches. */
static inline uint8_t cg_srgb_encode_unit(float linear)
{
    float x = linear > 0 ? linear : 0;
    x = x < 1 ? x : 1;
    unsigned code = color_srgb_encode_start[(int)(x * 4096.0f)];
    return (uint8_t)(code + (x >= color_srgb_threshold_table[code]));
}

/* The same for lanes 0, 1 and 2 of v at once, into px's r, g and b (its
 * alpha is left as it is). */
static inline void cg_srgb_encode_rgb(cg_rgba8 *px, v4 v)
{
    /* max(v, 0) gives 0 for NaN, as above */
    v = v4_min(v4_max(v, v4_set(0.0f)), v4_set(1.0f));
    i4 i = i4_truncate(v4_mul(v, v4_set(4096.0f)));
    unsigned c0 = color_srgb_encode_start[i4_lane(i, 0)];
    unsigned c1 = color_srgb_encode_start[i4_lane(i, 1)];
    unsigned c2 = color_srgb_encode_start[i4_lane(i, 2)];
    v4 next = v4_set3(color_srgb_threshold_table[c0], color_srgb_threshold_table[c1],
                      color_srgb_threshold_table[c2]);
    int up = v4_bits(v4_ge(v, next));
    px->r = (uint8_t)(c0 + (up & 1));
    px->g = (uint8_t)(c1 + ((up >> 1) & 1));
    px->b = (uint8_t)(c2 + ((up >> 2) & 1));
}

#endif
