/* cg/color.h - colour models, transfer curves, intensity mapping (chapters
 * 6.1.5 and 7).
 *
 * Conventions:
 *  - "RGB" without qualification means sRGB-ENCODED R'G'B' in [0, 1] (what
 *    files, colour pickers and #rrggbb hold).  HSV, HSL, CMY, CMYK, YIQ and
 *    YCbCr are defined on encoded RGB, as everywhere in practice.  "Linear"
 *    RGB is linear light (sRGB primaries, D65); XYZ and L*a*b* are computed
 *    from linear RGB.
 *  - Double-precision triples are cg_vec3 (x, y, z = first, second, third
 *    component: r g b, h s v, h s l, L a b ...); CMYK is a cg_vec4.
 *  - Ranges: RGB, saturation, lightness, value, CMY(K) in [0, 1]; hue in
 *    degrees [0, 360); YIQ: Y in [0, 1], I in [-0.596, 0.596], Q in
 *    [-0.523, 0.523]; YCbCr: Y in [0, 1], Cb and Cr in [-0.5, 0.5]; XYZ with
 *    the D65 white (0.9505, 1, 1.089); L* in [0, 100].
 *  - Bad input is clamped, never propagated: every conversion clamps its
 *    bounded inputs to their range (NaN -> the low end, +inf -> the high end),
 *    reduces hue modulo 360 (a non-finite hue -> 0), and treats a NaN in an
 *    unbounded input (XYZ, L*a*b*, YIQ) as 0.  Conversions that produce RGB
 *    clamp it to [0, 1] (out-of-gamut colours).
 */
#ifndef CG_COLOR_H
#define CG_COLOR_H

#include "cg/core.h"
#include "cg/image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- transfer curves ------------------------------------------------------ */

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

/* Whole buffers of n values (any channel layout: every value is converted;
 * use the image functions below to keep alpha linear).  Encoding is exact:
 * the same result as cg_linear_to_srgb8 for every float. */
void cg_srgb8_decode(const uint8_t *in, float *out, size_t n);
void cg_srgb8_encode(const float *in, uint8_t *out, size_t n);

/* The CRT power law of 7.2.1: intensity = voltage^gamma, and the gamma
 * correction that undoes it, voltage = intensity^(1/gamma).  Values are
 * clamped to [0, 1] (NaN -> 0); gamma must be > 0 (otherwise 0 is returned). */
double cg_gamma_decode(double voltage, double gamma);
double cg_gamma_encode(double intensity, double gamma);

/* Relative luminance Y of LINEAR RGB (Rec. 709 / sRGB primaries):
 * 0.2126 R + 0.7152 G + 0.0722 B. */
double cg_luminance(cg_vec3 linear_rgb);
/* Luma Y' of ENCODED RGB, BT.601 weights 0.299, 0.587, 0.114 (the Y of YIQ
 * and of BT.601 YCbCr). */
double cg_luma(cg_vec3 rgb);

/* cg_image_decode_srgb and cg_image_encode_srgb are in cg/image.h. */

/* ---- colour models (double) ---------------------------------------------- */

cg_vec3 cg_rgb_to_hsv(cg_vec3 rgb);
cg_vec3 cg_hsv_to_rgb(cg_vec3 hsv);
/* HSL as in 7.3.4: L = (max + min) / 2, S = (max - min) / (max + min) when
 * L <= 1/2, (max - min) / (2 - max - min) otherwise; hue as for HSV. */
cg_vec3 cg_rgb_to_hsl(cg_vec3 rgb);
cg_vec3 cg_hsl_to_rgb(cg_vec3 hsl);
/* CMY = 1 - RGB. */
cg_vec3 cg_rgb_to_cmy(cg_vec3 rgb);
cg_vec3 cg_cmy_to_rgb(cg_vec3 cmy);
/* K = 1 - max(R, G, B); C = (1 - R - K) / (1 - K) ...; black is (0, 0, 0, 1). */
cg_vec4 cg_rgb_to_cmyk(cg_vec3 rgb);
cg_vec3 cg_cmyk_to_rgb(cg_vec4 cmyk);
/* NTSC YIQ with the matrix of the notes (0.299 0.587 0.114 / 0.596 -0.275
 * -0.321 / 0.212 -0.523 0.311) and its exact inverse. */
cg_vec3 cg_rgb_to_yiq(cg_vec3 rgb);
cg_vec3 cg_yiq_to_rgb(cg_vec3 yiq);

typedef enum cg_ycbcr_standard {
    CG_YCBCR_BT601 = 0, /* Kr = 0.299,  Kb = 0.114 */
    CG_YCBCR_BT709 = 1  /* Kr = 0.2126, Kb = 0.0722 */
} cg_ycbcr_standard;
/* Y = Kr R + Kg G + Kb B, Cb = (B - Y) / (2 (1 - Kb)), Cr = (R - Y) / (2 (1 - Kr)).
 * Returned as (Y, Cb, Cr). */
cg_vec3 cg_rgb_to_ycbcr(cg_vec3 rgb, cg_ycbcr_standard standard);
cg_vec3 cg_ycbcr_to_rgb(cg_vec3 ycbcr, cg_ycbcr_standard standard);

/* CIE XYZ from LINEAR RGB with the sRGB matrix (0.4124 0.3576 0.1805 /
 * 0.2126 0.7152 0.0722 / 0.0193 0.1192 0.9505) and its exact inverse. */
cg_vec3 cg_linear_to_xyz(cg_vec3 linear_rgb);
cg_vec3 cg_xyz_to_linear(cg_vec3 xyz);
/* The D65 white of that matrix: (0.9505, 1.0, 1.089). */
cg_vec3 cg_d65_white(void);
/* CIE 1976 L*a*b* relative to the D65 white above. */
cg_vec3 cg_xyz_to_lab(cg_vec3 xyz);
cg_vec3 cg_lab_to_xyz(cg_vec3 lab);
/* Shortcuts from and to ENCODED sRGB. */
cg_vec3 cg_rgb_to_lab(cg_vec3 rgb);
cg_vec3 cg_lab_to_rgb(cg_vec3 lab);

/* Any model to any other by name. */
typedef enum cg_color_model {
    CG_MODEL_RGB = 0, /* sRGB-encoded R'G'B' */
    CG_MODEL_LINEAR,  /* linear-light RGB */
    CG_MODEL_HSV,
    CG_MODEL_HSL,
    CG_MODEL_CMY,
    CG_MODEL_CMYK, /* 4 components */
    CG_MODEL_YIQ,
    CG_MODEL_YCBCR601,
    CG_MODEL_YCBCR709,
    CG_MODEL_XYZ,
    CG_MODEL_LAB,
    CG_MODEL_COUNT
} cg_color_model;

/* "rgb" (also "srgb"), "linear", "hsv", "hsl", "cmy", "cmyk", "yiq",
 * "ycbcr601", "ycbcr709", "xyz", "lab"; case-insensitive.  The first n
 * characters of name only (n = strlen(name) for the whole string).
 * CG_EFORMAT (message naming the text) for an unknown name. */
cg_status cg_color_model_parse(const char *name, size_t n, cg_color_model *out, cg_error *err);
const char *cg_color_model_name(cg_color_model model);
/* 4 for CMYK, 3 for the others. */
int cg_color_model_components(cg_color_model model);
/* Converts in (3 or 4 components as the model has) to out.  Between linear,
 * XYZ and L*a*b* the path stays linear (no clamp to the RGB gamut); other
 * paths go through encoded RGB.  CG_EINVAL for an unknown model. */
cg_status cg_color_convert(cg_color_model from, cg_color_model to, const double *in, double *out);

/* ---- tints, shades and tones (7.3.1) ------------------------------------- */

/* Mix base with white (tint), black (shade) or grey (tone: with grey of the
 * given level) by amount in [0, 1] (0: base, 1: white / black / grey):
 * base + amount (target - base), per component, in whatever RGB space base is
 * given (encoded: the painter's mixing; linear: physical mixing of light).
 * amount is clamped to [0, 1] (NaN -> 0). */
cg_vec3 cg_color_tint(cg_vec3 base, double amount);
cg_vec3 cg_color_shade(cg_vec3 base, double amount);
cg_vec3 cg_color_tone(cg_vec3 base, double amount, double grey);

/* ---- 8-bit pixels ----------------------------------------------------------
 * Each model stored in three bytes (CMYK in four):
 *   RGB, CMY(K): round(255 v).   HSV, HSL: H8 = round(256 h / 360) mod 256
 *   (the full byte covers the circle, as OpenCV's *_FULL codes), S, V, L:
 *   round(255 v).   YCbCr (full range, JPEG/JFIF): round(255 Y),
 *   round(128 + 255 Cb), round(128 + 255 Cr), clamped to [0, 255].
 *   YIQ: round(255 Y), round(128 + 127.5 I / 0.596), round(128 + 127.5 Q / 0.523).
 *   XYZ: round(255 X / Xn), round(255 Y), round(255 Z / Zn) clamped (white is
 *   255, 255, 255).   Lab: round(255 L / 100), round(128 + a), round(128 + b)
 *   clamped (as OpenCV's 8-bit Lab).   Linear: round(255 v) (this loses dark
 *   detail: prefer float images for linear light).
 * Rounding is half up.  The 8-bit RGB->model->RGB round trip is lossy for
 * every model but RGB and CMY (256 hues, quantized chroma): use double for
 * exact round trips. */
void cg_color_to_bytes(cg_color_model model, const double *value, uint8_t *bytes);
void cg_color_from_bytes(cg_color_model model, const uint8_t *bytes, double *value);

/* n pixels of `channels` bytes (3 or 4: the 4th, alpha, is copied) from RGB
 * to a model or back.  Fast SIMD-friendly paths for RGB->HSV, HSV->RGB,
 * RGB->HSL and RGB->Lab; the others go through double per pixel.  HSV and HSL
 * results are exactly the rounding (half up) of the exact rational value of
 * the byte encodings above, which is also what the double conversion gives
 * except on exact ties (k + 1/2), where double rounding may pick either
 * neighbour; Lab is within 1 unit of the double conversion (99.9 % equal).
 * CMYK is not available here (4 components).  in and out may be the same
 * buffer, but must not overlap otherwise.  CG_EINVAL for CMYK, an unknown
 * model or channels not 3 or 4. */
cg_status cg_rgb8_to_model8(cg_color_model model, const uint8_t *in, uint8_t *out, size_t n,
                            int channels);
cg_status cg_model8_to_rgb8(cg_color_model model, const uint8_t *in, uint8_t *out, size_t n,
                            int channels);
/* The same on an RGBA8 image (in place: its r, g, b bytes then hold the model). */
cg_status cg_image_rgb_to_model(cg_image *image, cg_color_model model);
cg_status cg_image_model_to_rgb(cg_image *image, cg_color_model model);

/* ---- intensity to pixel (6.1.5) ------------------------------------------ */

/* Clamp to [0, 1]; NaN -> 0, +inf -> 1. */
double cg_intensity_clamp(double intensity);
/* Exposure: 1 - exp(-exposure * intensity) for intensity >= 0, a smooth
 * mapping of [0, inf) onto [0, 1) (exposure > 0; NaN or negative -> 0). */
double cg_intensity_expose(double intensity, double exposure);
/* Nearest of the levels 0, 1/(N-1), ..., 1 (levels in 2..256; the input is
 * clamped first).  Ties round up. */
double cg_intensity_quantize(double intensity, int levels);
/* cg_image_tonemap (these on a whole float image) is in cg/image.h. */

/* Quantizes a plane of width x height values (rows `stride` floats apart) to
 * `levels` levels (2..256): out[i] = k / (levels - 1).  Inputs are clamped
 * to [0, 1] (NaN -> 0) first.  Ordered dithering compares the fractional
 * part with the Bayer threshold (b + 1/2) / n^2 of pixel (x mod n, y mod n).
 * Floyd-Steinberg scans rows left to right and pushes each pixel's whole error
 * to its unvisited neighbours; at the image border the weights of the
 * missing neighbours go to the present ones, so the total intensity is
 * preserved up to the error of the last pixel.  in and out may be the same.
 * CG_EINVAL for bad sizes, levels or method; CG_ENOMEM.  The methods
 * (cg_dither) and cg_image_dither, on a whole image, are in cg/image.h. */
cg_status cg_dither_plane(const float *in, float *out, int width, int height, size_t stride,
                          int levels, cg_dither method);

/* Halftoning with cell x cell patterns (cell 2, 3 or 4), for devices with
 * two intensity levels: each input value in [0, 1] becomes a cell of
 * cell x cell binary pixels of which round(v * cell^2) are on, grown in the
 * order of a clustered-dot pattern (3x3: the classic order 6 8 4 / 1 0 3 /
 * 5 2 7).  out has (width*cell) x (height*cell) bytes, 0 or 255, rows
 * contiguous.  CG_EINVAL for bad sizes or cell. */
cg_status cg_halftone_plane(const float *in, int width, int height, size_t stride, int cell,
                            uint8_t *out);

/* ---- parsing ---------------------------------------------------------------- */

/* Parses "#rgb", "#rgba", "#rrggbb", "#rrggbbaa" or a CSS colour name (the full CSS
 * Color 4 list of 148 names, "transparent" included; case-insensitive) into
 * an encoded colour.  CG_EFORMAT with a message naming the text otherwise. */
cg_status cg_color_parse(const char *text, cg_rgba8 *out, cg_error *err);

#ifdef __cplusplus
}
#endif
#endif
