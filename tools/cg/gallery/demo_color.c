/* Gallery: colour models (chapter 7) - a wheel per model, tints, shades and
 * tones, and the gamma ramp. */
#include "demo.h"
#include "cg/color.h"

#include <stdlib.h>

#define WHEEL 256

static cg_rgba8 byte_color(cg_vec3 rgb)
{
    double v[3] = {rgb.x, rgb.y, rgb.z};
    uint8_t b[3];
    cg_color_to_bytes(CG_MODEL_RGB, v, b);
    cg_rgba8 c = {b[0], b[1], b[2], 255};
    return c;
}

static int add(demo_context *context, const char *file, cg_image *image, const char *caption,
               const char *command)
{
    int status = demo_add(context, file, image, caption, command);
    cg_image_free(image);
    return status;
}

/* A disc: polar (angle in degrees, radius in [0, 1]) or Cartesian (u, v in
 * [-1, 1]) coordinates mapped to encoded RGB by the model; points outside
 * the RGB gamut are drawn in a dark checker. */
typedef int (*wheel_fn)(double angle, double radius, double u, double v, cg_vec3 *rgb);

static int wheel(demo_context *context, const char *file, const char *caption, wheel_fn fn)
{
    cg_image *image;
    if (cg_image_create(&image, WHEEL, WHEEL, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_rgba8 back = {245, 245, 245, 255};
    for (int y = 0; y < WHEEL; y++) {
        cg_rgba8 *row = cg_image_row_rgba8(image, y);
        for (int x = 0; x < WHEEL; x++) {
            double u = (x + 0.5) / WHEEL * 2 - 1, v = 1 - (y + 0.5) / WHEEL * 2;
            double radius = sqrt(u * u + v * v) / 0.96;
            if (radius > 1) {
                row[x] = back;
                continue;
            }
            double angle = cg_degrees(atan2(v, u));
            if (angle < 0)
                angle += 360;
            cg_vec3 rgb;
            if (fn(angle, radius, u / 0.96, v / 0.96, &rgb)) {
                row[x] = byte_color(rgb);
            } else {
                uint8_t g = ((x / 8 + y / 8) & 1) ? 70 : 90;
                cg_rgba8 out = {g, g, g, 255};
                row[x] = out;
            }
        }
    }
    return add(context, file, image, caption, "cg demo --only 'Colour models'");
}

static int hsv_wheel(double angle, double radius, double u, double v, cg_vec3 *rgb)
{
    (void)u, (void)v;
    *rgb = cg_hsv_to_rgb(cg_vec3_make(angle, radius, 1));
    return 1;
}

static int hsl_wheel(double angle, double radius, double u, double v, cg_vec3 *rgb)
{
    (void)u, (void)v;
    *rgb = cg_hsl_to_rgb(cg_vec3_make(angle, 1, 1 - radius)); /* white centre, black rim */
    return 1;
}

/* Inside the gamut when the unclamped RGB is in [0, 1]; the converters clamp,
 * so convert back and compare. */
static int in_gamut(cg_color_model model, const double *value, cg_vec3 *rgb)
{
    double out[4], back[4];
    cg_color_convert(model, CG_MODEL_RGB, value, out);
    cg_color_convert(CG_MODEL_RGB, model, out, back);
    *rgb = cg_vec3_make(out[0], out[1], out[2]);
    double scale = model == CG_MODEL_LAB ? 100 : 1;
    return fabs(back[0] - value[0]) < 1e-3 * scale && fabs(back[1] - value[1]) < 1e-3 * scale
           && fabs(back[2] - value[2]) < 1e-3 * scale;
}

static int yiq_wheel(double angle, double radius, double u, double v, cg_vec3 *rgb)
{
    (void)angle, (void)radius;
    double yiq[3] = {0.5, 0.6 * u, 0.55 * v};
    return in_gamut(CG_MODEL_YIQ, yiq, rgb);
}

static int ycbcr601_wheel(double angle, double radius, double u, double v, cg_vec3 *rgb)
{
    (void)angle, (void)radius;
    double ycc[3] = {0.5, 0.5 * u, 0.5 * v};
    return in_gamut(CG_MODEL_YCBCR601, ycc, rgb);
}

static int ycbcr709_wheel(double angle, double radius, double u, double v, cg_vec3 *rgb)
{
    (void)angle, (void)radius;
    double ycc[3] = {0.5, 0.5 * u, 0.5 * v};
    return in_gamut(CG_MODEL_YCBCR709, ycc, rgb);
}

static int lab_wheel(double angle, double radius, double u, double v, cg_vec3 *rgb)
{
    (void)angle, (void)radius;
    double lab[3] = {65, 100 * u, 100 * v};
    return in_gamut(CG_MODEL_LAB, lab, rgb);
}

/* CIE xy chromaticity: (x, y) with Y chosen so the colour is as bright as
 * the gamut allows; outside the sRGB triangle shown as checker. */
static int xy_wheel(double angle, double radius, double u, double v, cg_vec3 *rgb)
{
    (void)angle, (void)radius;
    double x = 0.05 + 0.4 * (u + 1), y = 0.4 * (v + 1);
    if (y <= 1e-6)
        return 0;
    cg_vec3 xyz = cg_vec3_make(x / y, 1, (1 - x - y) / y);
    /* linear RGB before clamping: invert the matrix by hand via the library
     * on a scaled copy that stays in range */
    double s = fmax(xyz.x, fmax(xyz.y, xyz.z));
    cg_vec3 scaled = cg_vec3_scale(xyz, 0.2 / s); /* keeps in-gamut RGB below 1 */
    cg_vec3 lin = cg_xyz_to_linear(scaled);
    cg_vec3 check = cg_linear_to_xyz(lin);
    if (fabs(check.x - scaled.x) > 1e-6 || fabs(check.y - scaled.y) > 1e-6
        || fabs(check.z - scaled.z) > 1e-6 || 1 - x - y < 0)
        return 0;
    double m = fmax(lin.x, fmax(lin.y, lin.z));
    lin = cg_vec3_scale(lin, 1 / m);
    *rgb = cg_vec3_make(cg_linear_to_srgb(lin.x), cg_linear_to_srgb(lin.y),
                        cg_linear_to_srgb(lin.z));
    return 1;
}

/* Three overlapping discs mixed additively (RGB lights) or subtractively
 * (CMY inks on white paper). */
static int primaries(demo_context *context, int subtractive)
{
    cg_image *image;
    if (cg_image_create(&image, WHEEL, WHEEL, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    const double cx[3] = {0, -0.3, 0.3}, cy[3] = {0.22, -0.2, -0.2};
    for (int y = 0; y < WHEEL; y++) {
        cg_rgba8 *row = cg_image_row_rgba8(image, y);
        for (int x = 0; x < WHEEL; x++) {
            double u = (x + 0.5) / WHEEL * 2 - 1, v = 1 - (y + 0.5) / WHEEL * 2;
            double c[3];
            for (int k = 0; k < 3; k++) {
                double du = u - cx[k], dv = v - cy[k];
                c[k] = du * du + dv * dv < 0.45 * 0.45 ? 1 : 0;
            }
            cg_vec3 rgb = subtractive ? cg_cmy_to_rgb(cg_vec3_make(c[0], c[1], c[2]))
                                      : cg_vec3_make(c[0], c[1], c[2]);
            row[x] = byte_color(rgb);
        }
    }
    return add(context, subtractive ? "color-cmy.png" : "color-rgb.png", image,
               subtractive
                   ? "CMY: cyan, magenta and yellow inks subtract from white paper "
                     "(C = 1 - R ...); all three give black; as numbers: cg color rgb-cmy 1 0 0"
                   : "RGB: red, green and blue lights add; all three give white",
               "cg demo --only 'Colour models'");
}

/* Rows of tints, shades and tones of six hues. */
static int tints(demo_context *context)
{
    enum { STEPS = 11, CELL = 24 };
    const int kinds = 3, hues = 6;
    cg_image *image;
    if (cg_image_create(&image, STEPS * CELL, kinds * hues * CELL + (kinds - 1) * 8, CG_PIXEL_RGBA8)
        != CG_OK)
        return 1;
    cg_image_clear_rgba8(image, (cg_rgba8){255, 255, 255, 255});
    for (int k = 0; k < kinds; k++)
        for (int h = 0; h < hues; h++) {
            cg_vec3 base = cg_hsv_to_rgb(cg_vec3_make(h * 60.0, 1, 1));
            for (int s = 0; s < STEPS; s++) {
                double amount = s / (STEPS - 1.0);
                cg_vec3 c = k == 0   ? cg_color_tint(base, amount)
                            : k == 1 ? cg_color_shade(base, amount)
                                     : cg_color_tone(base, amount, 0.5);
                cg_rgba8 px = byte_color(c);
                int y0 = (k * hues + h) * CELL + k * 8;
                for (int y = 0; y < CELL - 2; y++)
                    for (int x = 0; x < CELL - 2; x++)
                        cg_image_set_rgba8(image, s * CELL + x, y0 + y, px);
            }
        }
    return add(context, "color-tints.png", image,
               "Tints (mixed with white), shades (with black) and tones (with grey) of six "
               "pure hues, amount 0 to 1 left to right",
               "cg demo --only 'Colour models'");
}

/* Top: equal steps of the encoded value; middle: equal steps of linear
 * light encoded with the exact sRGB curve; bottom: the same linear steps
 * gamma-corrected for a CRT with gamma 2.2. */
static int gamma_ramp(demo_context *context)
{
    enum { W = 512, BAND = 48, STEPS = 16 };
    cg_image *image;
    if (cg_image_create(&image, W, 3 * BAND + 2 * 4, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_image_clear_rgba8(image, (cg_rgba8){255, 255, 255, 255});
    for (int band = 0; band < 3; band++)
        for (int x = 0; x < W; x++) {
            double t = (double)(x * STEPS / W) / (STEPS - 1);
            double encoded = band == 0   ? t
                             : band == 1 ? cg_linear_to_srgb(t)
                                         : cg_gamma_encode(t, 2.2);
            uint8_t g = (uint8_t)floor(encoded * 255 + 0.5);
            for (int y = 0; y < BAND; y++)
                cg_image_set_rgba8(image, x, band * (BAND + 4) + y, (cg_rgba8){g, g, g, 255});
        }
    return add(context, "color-gamma-ramp.png", image,
               "Sixteen grey steps. Top: equal steps of the encoded value, which is also what "
               "linear intensities written to the screen uncorrected look like (the display's "
               "power law darkens them). Middle: equal steps of linear light, encoded with the "
               "exact sRGB curve. Bottom: the same steps gamma-corrected for a CRT with "
               "gamma 2.2 (V = I^(1/2.2)), close to sRGB; one step as numbers: cg color "
               "linear-srgb 0.5 0.5 0.5",
               "cg demo --only 'Colour models'");
}

static int render_models(demo_context *context)
{
    int failed = 0;
    failed |= wheel(context, "wheel-hsv.png",
                    "HSV wheel: hue around the circle, saturation outward, V = 1", hsv_wheel);
    failed |= wheel(context, "wheel-hsl.png",
                    "HSL wheel (7.3.4): hue around, lightness from 1 at the centre to 0 at the "
                    "rim, S = 1 (pure hues at half radius)",
                    hsl_wheel);
    failed |= primaries(context, 0);
    failed |= primaries(context, 1);
    failed |= wheel(context, "wheel-yiq.png",
                    "YIQ: the I (horizontal) and Q (vertical) plane at Y = 0.5; checker outside "
                    "the RGB gamut",
                    yiq_wheel);
    failed |= wheel(context, "wheel-ycbcr601.png",
                    "YCbCr BT.601: Cb (horizontal) and Cr (vertical) in [-0.5, 0.5] at Y = 0.5",
                    ycbcr601_wheel);
    failed |= wheel(context, "wheel-ycbcr709.png",
                    "YCbCr BT.709: the same plane with the HDTV weights", ycbcr709_wheel);
    failed |= wheel(context, "wheel-lab.png",
                    "CIE L*a*b*: a* (horizontal) and b* (vertical) in [-100, 100] at L* = 65",
                    lab_wheel);
    failed |= wheel(context, "wheel-xyz.png",
                    "CIE XYZ as xy chromaticity (x from 0.05 to 0.85, y from 0 to 0.8): the sRGB "
                    "gamut triangle, each colour at its brightest",
                    xy_wheel);
    failed |= tints(context);
    failed |= gamma_ramp(context);
    return failed;
}

const demo_section demo_section_color = {7, "Colour models and gamma", render_models};
