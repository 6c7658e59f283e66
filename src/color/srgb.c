/* sRGB transfer curves. */
#include "cg/color.h"
#include "srgb_tables.h"


double cg_srgb_to_linear(double encoded)
{
    double c = cg_intensity_clamp(encoded);
    if (c == 1)
        return 1;
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

double cg_linear_to_srgb(double linear)
{
    double l = cg_intensity_clamp(linear);
    if (l == 1)
        return 1;
    return l <= 0.0031308 ? l * 12.92 : 1.055 * pow(l, 1.0 / 2.4) - 0.055;
}

float cg_srgb8_to_linear(uint8_t code)
{
    return color_srgb_decode_table[code];
}

uint8_t cg_linear_to_srgb8(float linear)
{
    return cg_srgb_encode_unit(linear);
}

/* Outputs larger than this many floats (16 MiB) are written with streaming
 * stores where available: they bypass the caches, which the result would
 * not fit anyway, and save reading every destination line first. */
#define STREAM_THRESHOLD ((size_t)4 << 20)

void cg_srgb8_decode(const uint8_t *in, float *out, size_t n)
{
    const float *t = color_srgb_decode_table;
    size_t i = 0;
    if (n >= STREAM_THRESHOLD) {
        for (; i < n && ((uintptr_t)(out + i) & 15) != 0; i++)
            out[i] = t[in[i]];
        for (; i + 4 <= n; i += 4)
            v4_stream(out + i, v4_set4(t[in[i]], t[in[i + 1]], t[in[i + 2]], t[in[i + 3]]));
        v4_stream_fence();
    }
    for (; i < n; i++)
        out[i] = t[in[i]];
}

void cg_srgb8_encode(const float *in, uint8_t *out, size_t n)
{
    for (size_t i = 0; i < n; i++)
        out[i] = cg_srgb_encode_unit(in[i]);
}

cg_rgbaf cg_rgba8_to_linear(cg_rgba8 color)
{
    cg_rgbaf r = {color_srgb_decode_table[color.r], color_srgb_decode_table[color.g],
                  color_srgb_decode_table[color.b], color.a / 255.0f};
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

cg_status cg_image_decode_srgb(const cg_image *src, cg_image **out)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if (!src || src->format != CG_PIXEL_RGBA8)
        return CG_EINVAL;
    cg_status status = cg_image_create(out, src->width, src->height, CG_PIXEL_RGBAF);
    if (status != CG_OK)
        return status;
    for (int y = 0; y < src->height; y++) {
        const cg_rgba8 *in = cg_image_row_rgba8((cg_image *)src, y);
        cg_rgbaf *o = cg_image_row_rgbaf(*out, y);
        for (int x = 0; x < src->width; x++) {
            o[x].r = color_srgb_decode_table[in[x].r];
            o[x].g = color_srgb_decode_table[in[x].g];
            o[x].b = color_srgb_decode_table[in[x].b];
            o[x].a = in[x].a * (1.0f / 255.0f);
        }
    }
    return CG_OK;
}

cg_status cg_image_encode_srgb(const cg_image *src, cg_image **out)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if (!src || src->format != CG_PIXEL_RGBAF)
        return CG_EINVAL;
    cg_status status = cg_image_create(out, src->width, src->height, CG_PIXEL_RGBA8);
    if (status != CG_OK)
        return status;
    for (int y = 0; y < src->height; y++) {
        const cg_rgbaf *in = cg_image_row_rgbaf((cg_image *)src, y);
        cg_rgba8 *o = cg_image_row_rgba8(*out, y);
        for (int x = 0; x < src->width; x++) {
            o[x].r = cg_srgb_encode_unit(in[x].r);
            o[x].g = cg_srgb_encode_unit(in[x].g);
            o[x].b = cg_srgb_encode_unit(in[x].b);
            o[x].a = alpha_to_8(in[x].a);
        }
    }
    return CG_OK;
}
