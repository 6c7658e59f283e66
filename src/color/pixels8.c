/* Colour models on 8-bit pixels: the byte encodings of each model, and whole
 * buffers, with SIMD-friendly exact kernels for HSV and HSL and a fast
 * L*a*b* kernel. */
/* Floating-point selects in the kernels below must become blends: allow it
 * (no code here relies on floating-point traps). */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("no-trapping-math")
#endif

#include "cg/color.h"
#include "internal.h"
#include "srgb_tables.h"

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

/* ---- vectorizable HSV / HSL kernels ------------------------------------------
 * The exact rational formulas of the byte encodings, e.g. H8 =
 * floor((512 t + 6 delta) / (12 delta)) with t the hue numerator in units of
 * delta, S8 = floor((510 delta + max) / (2 max)), in float on planar blocks,
 * so that the compiler can use SIMD (with a run-time choice of AVX2 where
 * available).  Every numerator is an integer below 2^24, hence exact in float, and a
 * correctly rounded float quotient never crosses the integer above the true
 * quotient (the gap, at least 1/d, exceeds half an ulp of the result), so
 * truncation gives the exact floor. */
#define BLOCK 512

/* Each kernel reads m pixels of CH bytes from in and writes them to out
 * (never the same memory: callers copy a block first); alpha is copied.
 * Deinterleaving to planar bytes first lets the arithmetic loop load
 * contiguous vectors. */
#define HSV_FORWARD(NAME, ATTR, CH, HSL)                                            \
    ATTR static void NAME(const uint8_t *restrict in, uint8_t *restrict out, int m) \
    {                                                                               \
        uint8_t pr[BLOCK], pg[BLOCK], pb[BLOCK], ph[BLOCK], ps[BLOCK];              \
        for (int i = 0; i < m; i++) {                                               \
            pr[i] = in[CH * i];                                                     \
            pg[i] = in[CH * i + 1];                                                 \
            pb[i] = in[CH * i + 2];                                                 \
        }                                                                           \
        for (int i = 0; i < m; i++) {                                               \
            float r = pr[i], g = pg[i], b = pb[i];                                  \
            float mx = r > g ? r : g;                                               \
            mx = mx > b ? mx : b;                                                   \
            float mn = r < g ? r : g;                                               \
            mn = mn < b ? mn : b;                                                   \
            float d = mx - mn;                                                      \
            float t = mx == r ? g - b : (mx == g ? 2 * d + b - r : 4 * d + r - g);  \
            t = t < 0 ? t + 6 * d : t;                                              \
            float dd = d > 0 ? d : 1;                                               \
            int h = (int)((512 * t + 6 * dd) / (12 * dd));                          \
            /* saturation denominator: max (HSV); max + min or 510 - max - min  \
             * (HSL, by the lightness) */   \
            float sum = mx + mn;                                                    \
            float den = HSL ? (sum <= 255 ? sum : 510 - sum) : mx;                  \
            den = den > 0 ? den : 1;                                                \
            ph[i] = (uint8_t)h; /* 256 wraps to 0 */                                \
            ps[i] = (uint8_t)(int)((510 * d + den) / (2 * den));                    \
            pb[i] = (uint8_t)(int)(HSL ? (sum + 1) * 0.5f : mx);                    \
        }                                                                           \
        for (int i = 0; i < m; i++) {                                               \
            out[CH * i] = ph[i];                                                    \
            out[CH * i + 1] = ps[i];                                                \
            out[CH * i + 2] = pb[i];                                                \
            if (CH == 4)                                                            \
                out[CH * i + CH - 1] = in[CH * i + CH - 1];                         \
        }                                                                           \
    }

/* (H8, S8, V8) -> RGB: round(255 x) of the double formula with h / 60 =
 * 6 H / 256, as exact integer quotients.  One channel of HSV -> RGB as x = V - V S w(k), k = (n + h / 60) mod 6,
 * w = clamp(min(k, 4 - k), 0, 1) (n = 5, 3, 1 for R, G, B), all in units of
 * 1/256 of a sector: round(v (65280 - s W) / 65280) with W = 256 w, that is
 * floor(X / 65280) with X = v (65280 - s W) + 32640 < 2^24.  As 65280 =
 * 256 * 255, floor(X / 65280) = floor(u / 255) with u = X >> 8 <= 65152, and
 * floor(u / 255) = (u + 1 + (u >> 8)) >> 8 for every u < 65535: integer
 * operations only. */
static inline int hsv_channel(int n256, int h6, int s, int v)
{
    int k = n256 + h6;
    k = k >= 1536 ? k - 1536 : k;
    int w = k < 1024 - k ? k : 1024 - k;
    w = w > 0 ? w : 0;
    w = w < 256 ? w : 256;
    int u = (v * (65280 - s * w) + 32640) >> 8;
    return (u + 1 + (u >> 8)) >> 8;
}

#define HSV_INVERSE(NAME, ATTR, CH)                                                 \
    ATTR static void NAME(const uint8_t *restrict in, uint8_t *restrict out, int m) \
    {                                                                               \
        uint8_t ph[BLOCK], ps[BLOCK], pv[BLOCK], pr[BLOCK], pg[BLOCK], pb[BLOCK];   \
        for (int i = 0; i < m; i++) {                                               \
            ph[i] = in[CH * i];                                                     \
            ps[i] = in[CH * i + 1];                                                 \
            pv[i] = in[CH * i + 2];                                                 \
        }                                                                           \
        for (int i = 0; i < m; i++) {                                               \
            int h6 = 6 * ph[i], s = ps[i], v = pv[i];                               \
            pr[i] = (uint8_t)hsv_channel(1280, h6, s, v);                           \
            pg[i] = (uint8_t)hsv_channel(768, h6, s, v);                            \
            pb[i] = (uint8_t)hsv_channel(256, h6, s, v);                            \
        }                                                                           \
        for (int i = 0; i < m; i++) {                                               \
            out[CH * i] = pr[i];                                                    \
            out[CH * i + 1] = pg[i];                                                \
            out[CH * i + 2] = pb[i];                                                \
            if (CH == 4)                                                            \
                out[CH * i + CH - 1] = in[CH * i + CH - 1];                         \
        }                                                                           \
    }

CG_SIMD_VARIANTS(HSV_FORWARD, hsv_forward_3, 3, 0)
CG_SIMD_VARIANTS(HSV_FORWARD, hsv_forward_4, 4, 0)
CG_SIMD_VARIANTS(HSV_FORWARD, hsl_forward_3, 3, 1)
CG_SIMD_VARIANTS(HSV_FORWARD, hsl_forward_4, 4, 1)
CG_SIMD_VARIANTS(HSV_INVERSE, hsv_inverse_3, 3)
CG_SIMD_VARIANTS(HSV_INVERSE, hsv_inverse_4, 4)

typedef void (*block_kernel)(const uint8_t *restrict, uint8_t *restrict, int);

/* Runs a kernel over n pixels in blocks, through a copy when in and out
 * overlap (in place). */
static void run_blocks(const uint8_t *in, uint8_t *out, size_t n, int ch, block_kernel kernel)
{
    size_t bytes = n * (size_t)ch;
    int overlap = in < out + bytes && out < in + bytes;
    uint8_t copy[BLOCK * 4];
    while (n > 0) {
        int m = n < BLOCK ? (int)n : BLOCK;
        const uint8_t *src = in;
        if (overlap) {
            memcpy(copy, in, (size_t)m * (size_t)ch);
            src = copy;
        }
        kernel(src, out, m);
        in += (size_t)m * (size_t)ch;
        out += (size_t)m * (size_t)ch;
        n -= (size_t)m;
    }
}

static void rgb8_to_hsv8(const uint8_t *in, uint8_t *out, size_t n, int ch)
{
    run_blocks(in, out, n, ch,
               ch == 4 ? CG_SIMD_PICK(hsv_forward_4, hsv_forward_4_avx2, hsv_forward_4_avx512)
                       : CG_SIMD_PICK(hsv_forward_3, hsv_forward_3_avx2, hsv_forward_3_avx512));
}

static void rgb8_to_hsl8(const uint8_t *in, uint8_t *out, size_t n, int ch)
{
    run_blocks(in, out, n, ch,
               ch == 4 ? CG_SIMD_PICK(hsl_forward_4, hsl_forward_4_avx2, hsl_forward_4_avx512)
                       : CG_SIMD_PICK(hsl_forward_3, hsl_forward_3_avx2, hsl_forward_3_avx512));
}

static void hsv8_to_rgb8(const uint8_t *in, uint8_t *out, size_t n, int ch)
{
    run_blocks(in, out, n, ch,
               ch == 4 ? CG_SIMD_PICK(hsv_inverse_4, hsv_inverse_4_avx2, hsv_inverse_4_avx512)
                       : CG_SIMD_PICK(hsv_inverse_3, hsv_inverse_3_avx2, hsv_inverse_3_avx512));
}

/* ---- L*a*b* ---------------------------------------------------------------- */

/* The vectorizable form: decode by table, the sRGB matrix divided by the
 * white, and the cube root by a bit-level first guess (about 3 % off)
 * refined by two Newton steps y = (2 y + t / y^2) / 3 (relative error about
 * 2e-6, a thousandth of a byte in the result). */
static inline float cube_root_guess(float t)
{
    int32_t bits;
    memcpy(&bits, &t, sizeof bits);
    bits = (int32_t)((float)bits * (1.0f / 3.0f)) + 0x2a514067;
    float y;
    memcpy(&y, &bits, sizeof y);
    return y;
}

static inline float lab_f_fast(float t)
{
    float y = cube_root_guess(t);
    y = (2 * y + t / (y * y)) * (1.0f / 3);
    y = (2 * y + t / (y * y)) * (1.0f / 3);
    const float knee = (6.0f / 29) * (6.0f / 29) * (6.0f / 29);
    return t > knee ? y : t * (841.0f / 108) + 4.0f / 29;
}

static inline float clamp_byte(float v)
{
    v = v > 0 ? v : 0;
    return v < 255 ? v : 255;
}

/* Decoding goes to planar arrays first (table lookups), then the
 * arithmetic runs on contiguous floats, which vectorizes. */
#define LAB_FORWARD(NAME, ATTR, CH)                                                           \
    ATTR static void NAME(const uint8_t *restrict in, uint8_t *restrict out, int m)           \
    {                                                                                         \
        const float *dec = color_srgb_decode_table;                                           \
        float lr[BLOCK], lg[BLOCK], lb[BLOCK];                                                \
        for (int i = 0; i < m; i++) {                                                         \
            lr[i] = dec[in[CH * i]];                                                          \
            lg[i] = dec[in[CH * i + 1]];                                                      \
            lb[i] = dec[in[CH * i + 2]];                                                      \
        }                                                                                     \
        for (int i = 0; i < m; i++) {                                                         \
            float r = lr[i], g = lg[i], b = lb[i];                                            \
            float x = LAB_MX0 * r + LAB_MX1 * g + LAB_MX2 * b;                                \
            float y = 0.2126f * r + 0.7152f * g + 0.0722f * b;                                \
            float z = LAB_MZ0 * r + LAB_MZ1 * g + LAB_MZ2 * b;                                \
            float fx = lab_f_fast(x), fy = lab_f_fast(y), fz = lab_f_fast(z);                 \
            out[CH * i] = (uint8_t)(int)(clamp_byte((116.0f * 2.55f) * fy - 16.0f * 2.55f)    \
                                         + 0.5f);                                             \
            out[CH * i + 1] = (uint8_t)(int)(clamp_byte(500.0f * (fx - fy) + 128.0f) + 0.5f); \
            out[CH * i + 2] = (uint8_t)(int)(clamp_byte(200.0f * (fy - fz) + 128.0f) + 0.5f); \
        }                                                                                     \
        if (CH == 4)                                                                          \
            for (int i = 0; i < m; i++)                                                       \
                out[CH * i + CH - 1] = in[CH * i + CH - 1];                                   \
    }

/* Rows of the sRGB matrix for X / Xn and Z / Zn. */
#define LAB_MX0 ((float)(0.4124 / CG_COLOR_WHITE_X))
#define LAB_MX1 ((float)(0.3576 / CG_COLOR_WHITE_X))
#define LAB_MX2 ((float)(0.1805 / CG_COLOR_WHITE_X))
#define LAB_MZ0 ((float)(0.0193 / CG_COLOR_WHITE_Z))
#define LAB_MZ1 ((float)(0.1192 / CG_COLOR_WHITE_Z))
#define LAB_MZ2 ((float)(0.9505 / CG_COLOR_WHITE_Z))

CG_SIMD_VARIANTS(LAB_FORWARD, lab_forward_3, 3)
CG_SIMD_VARIANTS(LAB_FORWARD, lab_forward_4, 4)

static void rgb8_to_lab8(const uint8_t *in, uint8_t *out, size_t n, int ch)
{
    run_blocks(in, out, n, ch,
               ch == 4 ? CG_SIMD_PICK(lab_forward_4, lab_forward_4_avx2, lab_forward_4_avx512)
                       : CG_SIMD_PICK(lab_forward_3, lab_forward_3_avx2, lab_forward_3_avx512));
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

static int buffer_args_ok(cg_color_model model, const uint8_t *in, const uint8_t *out, int channels)
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
