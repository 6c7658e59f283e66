/* Colour models on 8-bit pixels: the byte encodings of each model, and whole
 * buffers with integer / table fast paths for HSV, HSL and L*a*b*. */
#include "cg/color.h"
#include "internal.h"
#include "tables.h"

#include <string.h>

/* round half up of v, clamped to [0, 255]; NaN -> 0. */
static uint8_t byte_of(double v)
{
    if (!(v > 0))
        return 0;
    if (v >= 255)
        return 255;
    return (uint8_t)(int)floor(v + 0.5);
}

static uint8_t hue_byte(double h)
{
    if (!isfinite(h))
        return 0;
    double t = floor(h * (256.0 / 360.0) + 0.5);
    long k = (long)fmod(t, 256.0);
    if (k < 0)
        k += 256;
    return (uint8_t)k;
}

#define YIQ_I_SCALE (127.5 / 0.596)
#define YIQ_Q_SCALE (127.5 / 0.523)

void cg_color_to_bytes(cg_color_model model, const double *v, uint8_t *b)
{
    switch (model) {
    case CG_MODEL_HSV:
    case CG_MODEL_HSL:
        b[0] = hue_byte(v[0]);
        b[1] = byte_of(255 * v[1]);
        b[2] = byte_of(255 * v[2]);
        break;
    case CG_MODEL_CMYK:
        for (int i = 0; i < 4; i++)
            b[i] = byte_of(255 * v[i]);
        break;
    case CG_MODEL_YIQ:
        b[0] = byte_of(255 * v[0]);
        b[1] = byte_of(128 + YIQ_I_SCALE * v[1]);
        b[2] = byte_of(128 + YIQ_Q_SCALE * v[2]);
        break;
    case CG_MODEL_YCBCR601:
    case CG_MODEL_YCBCR709:
        b[0] = byte_of(255 * v[0]);
        b[1] = byte_of(128 + 255 * v[1]);
        b[2] = byte_of(128 + 255 * v[2]);
        break;
    case CG_MODEL_XYZ:
        b[0] = byte_of(255 * v[0] / CG_COLOR_WHITE_X);
        b[1] = byte_of(255 * v[1]);
        b[2] = byte_of(255 * v[2] / CG_COLOR_WHITE_Z);
        break;
    case CG_MODEL_LAB:
        b[0] = byte_of(v[0] * 2.55);
        b[1] = byte_of(128 + v[1]);
        b[2] = byte_of(128 + v[2]);
        break;
    default: /* RGB, linear, CMY */
        for (int i = 0; i < 3; i++)
            b[i] = byte_of(255 * v[i]);
        break;
    }
}

void cg_color_from_bytes(cg_color_model model, const uint8_t *b, double *v)
{
    switch (model) {
    case CG_MODEL_HSV:
    case CG_MODEL_HSL:
        v[0] = b[0] * (360.0 / 256.0);
        v[1] = b[1] / 255.0;
        v[2] = b[2] / 255.0;
        break;
    case CG_MODEL_CMYK:
        for (int i = 0; i < 4; i++)
            v[i] = b[i] / 255.0;
        break;
    case CG_MODEL_YIQ:
        v[0] = b[0] / 255.0;
        v[1] = (b[1] - 128) / YIQ_I_SCALE;
        v[2] = (b[2] - 128) / YIQ_Q_SCALE;
        break;
    case CG_MODEL_YCBCR601:
    case CG_MODEL_YCBCR709:
        v[0] = b[0] / 255.0;
        v[1] = (b[1] - 128) / 255.0;
        v[2] = (b[2] - 128) / 255.0;
        break;
    case CG_MODEL_XYZ:
        v[0] = b[0] / 255.0 * CG_COLOR_WHITE_X;
        v[1] = b[1] / 255.0;
        v[2] = b[2] / 255.0 * CG_COLOR_WHITE_Z;
        break;
    case CG_MODEL_LAB:
        v[0] = b[0] / 2.55;
        v[1] = b[1] - 128.0;
        v[2] = b[2] - 128.0;
        break;
    default:
        for (int i = 0; i < 3; i++)
            v[i] = b[i] / 255.0;
        break;
    }
}

/* ---- exact integer division by small divisors ------------------------------
 * floor(n / d) == (n * ceil(2^32 / d)) >> 32 whenever n d < 2^32: the error
 * n (ceil(2^32/d) - 2^32/d) / 2^32 < n / 2^32 stays below 1/d, the smallest
 * gap between n/d and the next integer.  Here n < 2^20 and d <= 3060. */
static inline uint32_t divide(uint32_t n, uint32_t d)
{
    return (uint32_t)(((uint64_t)n * cg_color_reciprocal[d]) >> 32);
}

/* Hue byte: round(256 h / 360) mod 256 with h / 60 = sector + x / delta:
 * round((512 t + 6 delta) / (12 delta)) with t = sector delta + x in
 * [0, 6 delta) (x < 0 in sector 0 wraps by 6 delta). */
static inline uint8_t hue8(int r, int g, int b, int max, int delta)
{
    int s;
    if (max == r) {
        s = g - b;
        if (s < 0)
            s += 6 * delta;
    } else if (max == g) {
        s = 2 * delta + b - r;
    } else {
        s = 4 * delta + r - g;
    }
    uint32_t q = divide((uint32_t)(512 * s + 6 * delta), (uint32_t)(12 * delta));
    return (uint8_t)q; /* 256 wraps to 0 */
}

static void rgb8_to_hsv8(const uint8_t *in, uint8_t *out, size_t n, int ch)
{
    for (size_t i = 0; i < n; i++, in += ch, out += ch) {
        int r = in[0], g = in[1], b = in[2];
        int max = r > g ? r : g, min = r < g ? r : g;
        if (b > max)
            max = b;
        if (b < min)
            min = b;
        int delta = max - min;
        uint8_t a = ch == 4 ? in[3] : 0;
        if (delta == 0) {
            out[0] = 0;
            out[1] = 0;
        } else {
            out[0] = hue8(r, g, b, max, delta);
            /* round(255 delta / max) */
            out[1] = (uint8_t)divide((uint32_t)(510 * delta + max), (uint32_t)(2 * max));
        }
        out[2] = (uint8_t)max;
        if (ch == 4)
            out[3] = a;
    }
}

static void rgb8_to_hsl8(const uint8_t *in, uint8_t *out, size_t n, int ch)
{
    for (size_t i = 0; i < n; i++, in += ch, out += ch) {
        int r = in[0], g = in[1], b = in[2];
        int max = r > g ? r : g, min = r < g ? r : g;
        if (b > max)
            max = b;
        if (b < min)
            min = b;
        int delta = max - min, sum = max + min;
        uint8_t a = ch == 4 ? in[3] : 0;
        if (delta == 0) {
            out[0] = 0;
            out[1] = 0;
        } else {
            out[0] = hue8(r, g, b, max, delta);
            int d = sum <= 255 ? sum : 510 - sum;
            uint32_t s = divide((uint32_t)(510 * delta + d), (uint32_t)(2 * d));
            out[1] = (uint8_t)(s > 255 ? 255 : s);
        }
        out[2] = (uint8_t)((sum + 1) >> 1);
        if (ch == 4)
            out[3] = a;
    }
}

/* HSV bytes to RGB: round(255 x) of the double formula, in exact integers.
 * h / 60 = (6 H) / 256: sector (6 H) >> 8, f = F / 256 with F = (6 H) & 255. */
static void hsv8_to_rgb8(const uint8_t *in, uint8_t *out, size_t n, int ch)
{
    for (size_t i = 0; i < n; i++, in += ch, out += ch) {
        unsigned h6 = 6u * in[0], s = in[1], v = in[2];
        unsigned sector = h6 >> 8, f = h6 & 255;
        unsigned p = (2 * v * (255 - s) + 255) / 510;
        unsigned q = (2 * v * (65280 - s * f) + 65280) / 130560;
        unsigned tt = (2 * v * (65280 - s * (256 - f)) + 65280) / 130560;
        unsigned r, g, b;
        switch (sector) {
        case 0: r = v; g = tt; b = p; break;
        case 1: r = q; g = v; b = p; break;
        case 2: r = p; g = v; b = tt; break;
        case 3: r = p; g = q; b = v; break;
        case 4: r = tt; g = p; b = v; break;
        default: r = v; g = p; b = q; break;
        }
        out[0] = (uint8_t)r;
        out[1] = (uint8_t)g;
        out[2] = (uint8_t)b;
        if (ch == 4)
            out[3] = in[3];
    }
}

/* ---- L*a*b* ------------------------------------------------------------------
 * Linear X/Xn, Y, Z/Zn are sums of three per-channel table entries (decode
 * and matrix folded together); the CIE f() is a table of 4097 samples on
 * [0, 1] with linear interpolation (error < 1e-5, far below half a byte). */
static inline float lab_f_lookup(float v)
{
    float s = v * (float)CG_LAB_F_SIZE;
    if (!(s > 0))
        s = 0;
    if (s > (float)CG_LAB_F_SIZE)
        s = (float)CG_LAB_F_SIZE;
    int i = (int)s;
    float frac = s - (float)i;
    return cg_lab_f_table[i] + (cg_lab_f_table[i + 1] - cg_lab_f_table[i]) * frac;
}

static inline uint8_t byte_of_float(float v)
{
    if (!(v > 0))
        return 0;
    if (v >= 255)
        return 255;
    return (uint8_t)(int)(v + 0.5f);
}

static void rgb8_to_lab8(const uint8_t *in, uint8_t *out, size_t n, int ch)
{
    const float(*t)[256][3] = cg_lab_channel_table;
    for (size_t i = 0; i < n; i++, in += ch, out += ch) {
        const float *r = t[0][in[0]], *g = t[1][in[1]], *b = t[2][in[2]];
        float fx = lab_f_lookup(r[0] + g[0] + b[0]);
        float fy = lab_f_lookup(r[1] + g[1] + b[1]);
        float fz = lab_f_lookup(r[2] + g[2] + b[2]);
        uint8_t a = ch == 4 ? in[3] : 0;
        out[0] = byte_of_float((116.0f * 2.55f) * fy - 16.0f * 2.55f);
        out[1] = byte_of_float(500.0f * (fx - fy) + 128.0f);
        out[2] = byte_of_float(200.0f * (fy - fz) + 128.0f);
        if (ch == 4)
            out[3] = a;
    }
}

/* ---- generic paths through double ----------------------------------------- */

static void via_double(cg_color_model from, cg_color_model to, const uint8_t *in, uint8_t *out,
                       size_t n, int ch)
{
    for (size_t i = 0; i < n; i++, in += ch, out += ch) {
        double a[4], b[4];
        uint8_t alpha = ch == 4 ? in[3] : 0;
        cg_color_from_bytes(from, in, a);
        cg_color_convert(from, to, a, b);
        cg_color_to_bytes(to, b, out);
        if (ch == 4)
            out[3] = alpha;
    }
}

static int buffer_args_ok(cg_color_model model, const uint8_t *in, const uint8_t *out,
                          int channels)
{
    return in && out && (channels == 3 || channels == 4) && (int)model >= 0
           && model < CG_MODEL_COUNT && model != CG_MODEL_CMYK;
}

cg_status cg_rgb8_to_model8(cg_color_model model, const uint8_t *in, uint8_t *out, size_t n,
                            int channels)
{
    if (!buffer_args_ok(model, in, out, channels))
        return CG_EINVAL;
    switch (model) {
    case CG_MODEL_HSV: rgb8_to_hsv8(in, out, n, channels); return CG_OK;
    case CG_MODEL_HSL: rgb8_to_hsl8(in, out, n, channels); return CG_OK;
    case CG_MODEL_LAB: rgb8_to_lab8(in, out, n, channels); return CG_OK;
    case CG_MODEL_RGB:
        if (in != out)
            memmove(out, in, n * (size_t)channels);
        return CG_OK;
    default: via_double(CG_MODEL_RGB, model, in, out, n, channels); return CG_OK;
    }
}

cg_status cg_model8_to_rgb8(cg_color_model model, const uint8_t *in, uint8_t *out, size_t n,
                            int channels)
{
    if (!buffer_args_ok(model, in, out, channels))
        return CG_EINVAL;
    switch (model) {
    case CG_MODEL_HSV: hsv8_to_rgb8(in, out, n, channels); return CG_OK;
    case CG_MODEL_RGB:
        if (in != out)
            memmove(out, in, n * (size_t)channels);
        return CG_OK;
    default: via_double(model, CG_MODEL_RGB, in, out, n, channels); return CG_OK;
    }
}

static cg_status image_rows(cg_image *image, cg_color_model model, int forward)
{
    if (!image || image->format != CG_PIXEL_RGBA8)
        return CG_EINVAL;
    if (image->stride == (size_t)image->width * 4) { /* contiguous: one call */
        uint8_t *all = image->data;
        size_t n = (size_t)image->width * (size_t)image->height;
        return forward ? cg_rgb8_to_model8(model, all, all, n, 4)
                       : cg_model8_to_rgb8(model, all, all, n, 4);
    }
    for (int y = 0; y < image->height; y++) {
        uint8_t *row = (uint8_t *)cg_image_row_rgba8(image, y);
        cg_status s = forward ? cg_rgb8_to_model8(model, row, row, (size_t)image->width, 4)
                              : cg_model8_to_rgb8(model, row, row, (size_t)image->width, 4);
        if (s != CG_OK)
            return s;
    }
    return CG_OK;
}

cg_status cg_image_rgb_to_model(cg_image *image, cg_color_model model)
{
    return image_rows(image, model, 1);
}

cg_status cg_image_model_to_rgb(cg_image *image, cg_color_model model)
{
    return image_rows(image, model, 0);
}
