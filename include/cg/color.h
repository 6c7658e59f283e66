/* cg/color.h - colour transfer curves and colour parsing. */
#ifndef CG_COLOR_H
#define CG_COLOR_H

#include "cg/core.h"
#include "cg/image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The exact sRGB transfer curves (IEC 61966-2-1) on [0, 1]; values outside
 * are clamped, NaN gives 0. */
double cg_srgb_to_linear(double encoded);
double cg_linear_to_srgb(double linear);

/* 8-bit forms: decoding by table, encoding with correct rounding in the
 * encoded domain (cg_linear_to_srgb8(cg_srgb8_to_linear(k)) == k for all k). */
float cg_srgb8_to_linear(uint8_t code);
uint8_t cg_linear_to_srgb8(float linear);

cg_rgbaf cg_rgba8_to_linear(cg_rgba8 color);
cg_rgba8 cg_linear_to_rgba8(cg_rgbaf color);

/* Parses "#rgb", "#rrggbb", "#rrggbbaa" or a CSS colour name ("red",
 * "cornflowerblue", "transparent"; case-insensitive) into an encoded colour.
 * CG_EFORMAT with a message naming the text otherwise. */
cg_status cg_color_parse(const char *text, cg_rgba8 *out, cg_error *err);

#ifdef __cplusplus
}
#endif
#endif
