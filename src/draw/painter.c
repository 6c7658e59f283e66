/* Writing one colour into an image: plain stores or linear-light blending. */
#include "internal.h"

void draw_painter_init(cg_painter *painter, cg_image *image, cg_rgba8 color)
{
    painter->image = image;
    painter->color = color;
    painter->linear = cg_rgba8_to_linear(color);
    memcpy(&painter->packed, &color, 4);
    painter->opaque = image->format == CG_PIXEL_RGBA8 && color.a == 255;
}

void draw_painter_span(const cg_painter *painter, int x0, int x1, int y)
{
    cg_image *image = painter->image;
    if (painter->opaque) {
        unsigned char *p = image->data + (size_t)y * image->stride + (size_t)x0 * 4;
        for (int x = x0; x <= x1; x++, p += 4)
            memcpy(p, &painter->packed, 4);
    } else {
        for (int x = x0; x <= x1; x++)
            cg_painter_plot(painter, x, y);
    }
}

void draw_painter_cover(const cg_painter *painter, int x, int y, float coverage)
{
    if (!(coverage > 0))
        return;
    cg_image *image = painter->image;
    cg_rgbaf c = painter->linear;
    c.a *= coverage < 1 ? coverage : 1;
    if (image->format == CG_PIXEL_RGBA8) {
        uint8_t *d = image->data + (size_t)y * image->stride + (size_t)x * 4;
        if (d[3] == 255) {
            /* Over an opaque pixel source-over is a plain mix in linear light. */
            float dst[3], out[3];
            cg_srgb8_decode(d, dst, 3);
            out[0] = c.r * c.a + dst[0] * (1 - c.a);
            out[1] = c.g * c.a + dst[1] * (1 - c.a);
            out[2] = c.b * c.a + dst[2] * (1 - c.a);
            cg_srgb8_encode(out, d, 3);
            return;
        }
    }
    cg_image_blend(image, x, y, c);
}

long long draw_isqrt(long long n)
{
    if (n <= 0)
        return 0;
    long long r = (long long)sqrt((double)n);
    while (r > 0 && (cg_wide)r * r > n)
        r--;
    while ((cg_wide)(r + 1) * (r + 1) <= n)
        r++;
    return r;
}

void draw_cover_flush(cg_cover_batch *batch)
{
    int n = batch->count;
    if (n == 0)
        return;
    uint8_t bytes[CG_COVER_BATCH * 3] = {0};
    float linear[CG_COVER_BATCH * 3];
    for (int i = 0; i < n; i++)
        memcpy(bytes + 3 * i, batch->pixel[i], 3);
    cg_srgb8_decode(bytes, linear, (size_t)n * 3);
    cg_rgbaf c = batch->painter->linear;
    for (int i = 0; i < n; i++) {
        float a = batch->alpha[i], keep = 1 - a;
        float *l = linear + 3 * i;
        l[0] = c.r * a + l[0] * keep;
        l[1] = c.g * a + l[1] * keep;
        l[2] = c.b * a + l[2] * keep;
    }
    cg_srgb8_encode(linear, bytes, (size_t)n * 3);
    for (int i = 0; i < n; i++)
        memcpy(batch->pixel[i], bytes + 3 * i, 3);
    batch->count = 0;
}
