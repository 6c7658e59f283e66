/* From computed intensities to displayable pixels (6.1.5): exposure,
 * quantization, ordered (Bayer) dithering, Floyd-Steinberg error diffusion
 * and halftone cells. */
#include "cg/color.h"
#include "internal.h"

#include <stdlib.h>
#include <string.h>

double cg_intensity_expose(double intensity, double exposure)
{
    if (!(intensity > 0) || !(exposure > 0))
        return 0;
    if (isinf(intensity) || isinf(exposure))
        return 1;
    return -expm1(-exposure * intensity);
}

static int levels_ok(int levels)
{
    return levels >= 2 && levels <= 256;
}

double cg_intensity_quantize(double intensity, int levels)
{
    if (levels < 2)
        levels = 2;
    if (levels > 256)
        levels = 256;
    double top = levels - 1;
    return floor(cg_intensity_clamp(intensity) * top + 0.5) / top;
}

cg_status cg_image_tonemap(const cg_image *src, double stops, double exposure, cg_image **out)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if (!src || src->format != CG_PIXEL_RGBAF || !isfinite(stops) || !isfinite(exposure)
        || fabs(stops) > 1000)
        return CG_EINVAL;
    cg_status status = cg_image_create(out, src->width, src->height, CG_PIXEL_RGBA8);
    if (status != CG_OK)
        return status;
    double scale = exp2(stops);
    for (int y = 0; y < src->height; y++) {
        const cg_rgbaf *in = cg_image_row_rgbaf((cg_image *)src, y);
        cg_rgba8 *o = cg_image_row_rgba8(*out, y);
        for (int x = 0; x < src->width; x++) {
            double c[3] = {in[x].r * scale, in[x].g * scale, in[x].b * scale};
            for (int k = 0; k < 3; k++)
                c[k] = exposure > 0 ? cg_intensity_expose(c[k], exposure)
                                    : cg_intensity_clamp(c[k]);
            cg_rgbaf mapped = {(float)c[0], (float)c[1], (float)c[2], in[x].a};
            o[x] = cg_linear_to_rgba8(mapped);
        }
    }
    return CG_OK;
}

/* The n x n Bayer index matrix (n = 2, 4, 8) built by the recursion
 * B(2n) = [4B, 4B+2; 4B+3, 4B+1]. */
static void bayer_matrix(int n, int m[8][8])
{
    m[0][0] = 0;
    for (int size = 1; size < n; size *= 2)
        for (int y = 0; y < size; y++)
            for (int x = 0; x < size; x++) {
                int b = 4 * m[y][x];
                m[y][x] = b;
                m[y][x + size] = b + 2;
                m[y + size][x] = b + 3;
                m[y + size][x + size] = b + 1;
            }
}

static float clamp_float(float v)
{
    if (!(v > 0))
        return 0;
    return v < 1 ? v : 1;
}

static void ordered(const float *in, float *out, int width, int height, size_t stride, int levels,
                    int n, color_dither_report *report)
{
    int m[8][8];
    bayer_matrix(n, m);
    double threshold[8][8];
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++)
            threshold[y][x] = (m[y][x] + 0.5) / (n * n);
    double top = levels - 1;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            size_t i = (size_t)y * stride + (size_t)x;
            double s = clamp_float(in[i]) * top;
            double base = floor(s);
            double k = base + (s - base > threshold[y % n][x % n] ? 1 : 0);
            float input = in[i];
            out[i] = (float)((k > top ? top : k) / top);
            if (report)
                color_report_ordered(report, x, y, input, s, m[y % n][x % n], n, out[i]);
        }
}

static float quantize_float(double v, double top)
{
    double k = floor(v * top + 0.5);
    if (k < 0)
        k = 0;
    if (k > top)
        k = top;
    return (float)(k / top);
}

/* Floyd-Steinberg on a working copy in double (errors accumulate in double
 * so the total is kept to rounding). */
static cg_status floyd_steinberg(const float *in, float *out, int width, int height, size_t stride,
                                 int levels, color_dither_report *report)
{
    size_t w = (size_t)width;
    double *cur = calloc(w + 2, sizeof *cur), *next = calloc(w + 2, sizeof *next);
    if (!cur || !next) {
        free(cur);
        free(next);
        return CG_ENOMEM;
    }
    double top = levels - 1;
    for (size_t x = 0; x < w; x++)
        cur[x + 1] = clamp_float(in[x]);
    for (int y = 0; y < height; y++) {
        int last_row = y == height - 1;
        if (!last_row) {
            const float *row = in + (size_t)(y + 1) * stride;
            for (size_t x = 0; x < w; x++)
                next[x + 1] = clamp_float(row[x]);
        }
        float *o = out + (size_t)y * stride;
        for (size_t x = 0; x < w; x++) {
            double v = cur[x + 1];
            float q = quantize_float(v, top), input = in[(size_t)y * stride + x];
            o[x] = q;
            double e = v - q;
            int right = x + 1 < w, left = x > 0;
            double wr = right ? 7 : 0;
            double wbl = !last_row && left ? 3 : 0, wb = !last_row ? 5 : 0;
            double wbr = !last_row && right ? 1 : 0;
            double total = wr + wbl + wb + wbr;
            if (report) {
                double weights[4] = {wr, wbl, wb, wbr};
                color_report_diffusion(report, (int)x, y, input, v, q, e, weights);
            }
            if (total == 0)
                continue; /* the last pixel: its error leaves the image */
            e /= total;
            cur[x + 2] += e * wr;
            next[x] += e * wbl;
            next[x + 1] += e * wb;
            next[x + 2] += e * wbr;
        }
        double *t = cur;
        cur = next;
        next = t;
    }
    free(cur);
    free(next);
    return CG_OK;
}

cg_status color_dither_plane(const float *in, float *out, int width, int height, size_t stride,
                             int levels, cg_dither method, color_dither_report *report)
{
    if (!in || !out || width <= 0 || height <= 0 || stride < (size_t)width || !levels_ok(levels))
        return CG_EINVAL;
    switch (method) {
    case CG_DITHER_NONE: {
        double top = levels - 1;
        for (int y = 0; y < height; y++)
            for (int x = 0; x < width; x++) {
                size_t i = (size_t)y * stride + (size_t)x;
                float input = in[i];
                out[i] = quantize_float(clamp_float(input), top);
                if (report)
                    color_report_quantize(report, x, y, input, top, out[i]);
            }
        return CG_OK;
    }
    case CG_DITHER_BAYER2: ordered(in, out, width, height, stride, levels, 2, report); return CG_OK;
    case CG_DITHER_BAYER4: ordered(in, out, width, height, stride, levels, 4, report); return CG_OK;
    case CG_DITHER_BAYER8: ordered(in, out, width, height, stride, levels, 8, report); return CG_OK;
    case CG_DITHER_FLOYD_STEINBERG:
        return floyd_steinberg(in, out, width, height, stride, levels, report);
    default: return CG_EINVAL;
    }
}

cg_status cg_dither_plane(const float *in, float *out, int width, int height, size_t stride,
                          int levels, cg_dither method)
{
    return color_dither_plane(in, out, width, height, stride, levels, method, NULL);
}

cg_status cg_image_dither(cg_image *image, int levels, cg_dither method)
{
    if (!image || image->format != CG_PIXEL_RGBA8 || !levels_ok(levels)
        || (int)method < CG_DITHER_NONE || method > CG_DITHER_FLOYD_STEINBERG)
        return CG_EINVAL;
    size_t n = (size_t)image->width * (size_t)image->height;
    float *plane = malloc(n * sizeof *plane);
    if (!plane)
        return CG_ENOMEM;
    cg_status status = CG_OK;
    for (int c = 0; c < 3 && status == CG_OK; c++) {
        for (int y = 0; y < image->height; y++) {
            const uint8_t *row = (const uint8_t *)cg_image_row_rgba8(image, y);
            for (int x = 0; x < image->width; x++)
                plane[(size_t)y * image->width + x] = row[4 * x + c] / 255.0f;
        }
        status = cg_dither_plane(plane, plane, image->width, image->height, (size_t)image->width,
                                 levels, method);
        for (int y = 0; y < image->height && status == CG_OK; y++) {
            uint8_t *row = (uint8_t *)cg_image_row_rgba8(image, y);
            for (int x = 0; x < image->width; x++)
                row[4 * x + c] = (uint8_t)(plane[(size_t)y * image->width + x] * 255.0f + 0.5f);
        }
    }
    free(plane);
    return status;
}

/* Clustered-dot orders: pixel (x, y) of a cell is on when its rank is below
 * the number of pixels to light. */
static const int halftone2[4] = {0, 2, 3, 1};
static const int halftone3[9] = {6, 8, 4, 1, 0, 3, 5, 2, 7};
static const int halftone4[16] = {12, 5, 6, 13, 4, 0, 1, 7, 11, 3, 2, 8, 15, 10, 9, 14};

cg_status cg_halftone_plane(const float *in, int width, int height, size_t stride, int cell,
                            uint8_t *out)
{
    if (!in || !out || width <= 0 || height <= 0 || stride < (size_t)width || cell < 2 || cell > 4)
        return CG_EINVAL;
    const int *rank = cell == 2 ? halftone2 : cell == 3 ? halftone3 : halftone4;
    size_t out_width = (size_t)width * (size_t)cell;
    int cells = cell * cell;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            int on = (int)floor(clamp_float(in[(size_t)y * stride + (size_t)x]) * cells + 0.5);
            for (int j = 0; j < cell; j++) {
                uint8_t *o = out + ((size_t)y * cell + (size_t)j) * out_width + (size_t)x * cell;
                for (int i = 0; i < cell; i++)
                    o[i] = rank[j * cell + i] < on ? 255 : 0;
            }
        }
    return CG_OK;
}
