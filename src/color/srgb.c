/* sRGB transfer curves. */
#include "cg/color.h"
#include "srgb_tables.h"

static double clamp_unit(double v)
{
    if (!(v > 0)) /* also NaN */
        return 0;
    return v < 1 ? v : 1;
}

double cg_srgb_to_linear(double encoded)
{
    double c = clamp_unit(encoded);
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

double cg_linear_to_srgb(double linear)
{
    double l = clamp_unit(linear);
    return l <= 0.0031308 ? l * 12.92 : 1.055 * pow(l, 1.0 / 2.4) - 0.055;
}

float cg_srgb8_to_linear(uint8_t code)
{
    return cg_srgb_decode_table[code];
}

uint8_t cg_linear_to_srgb8(float linear)
{
    /* Binary search for the number of thresholds at or below linear; NaN
     * compares false everywhere and lands on 0. */
    int low = 0, high = 255;
    while (low < high) {
        int mid = (low + high) / 2;
        if (linear >= cg_srgb_threshold_table[mid])
            low = mid + 1;
        else
            high = mid;
    }
    return (uint8_t)low;
}

cg_rgbaf cg_rgba8_to_linear(cg_rgba8 color)
{
    cg_rgbaf r = {cg_srgb_decode_table[color.r], cg_srgb_decode_table[color.g],
                  cg_srgb_decode_table[color.b], color.a / 255.0f};
    return r;
}

static uint8_t alpha_to_8(float a)
{
    if (!(a > 0))
        return 0;
    if (a >= 1)
        return 255;
    return (uint8_t)(a * 255.0f + 0.5f);
}

cg_rgba8 cg_linear_to_rgba8(cg_rgbaf color)
{
    cg_rgba8 r = {cg_linear_to_srgb8(color.r), cg_linear_to_srgb8(color.g),
                  cg_linear_to_srgb8(color.b), alpha_to_8(color.a)};
    return r;
}
