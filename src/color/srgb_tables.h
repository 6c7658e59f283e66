/* Private: constant sRGB lookup tables shared by the image and color code. */
#ifndef CG_SRGB_TABLES_H
#define CG_SRGB_TABLES_H

#include <stdint.h>

extern const float cg_srgb_decode_table[256];
/* threshold[k]: least linear value of code k + 1; threshold[255] = +infinity. */
extern const float cg_srgb_threshold_table[256];
extern const uint8_t cg_srgb_encode_start[4097];

#endif
