/* Writing one colour into an image: plain stores or linear-light blending. */
#include "internal.h"

void cg_painter_init(cg_painter *painter, cg_image *image, cg_rgba8 color)
{
    painter->image = image;
    painter->color = color;
    painter->linear = cg_rgba8_to_linear(color);
    memcpy(&painter->packed, &color, 4);
    painter->opaque = image->format == CG_PIXEL_RGBA8 && color.a == 255;
}

void cg_painter_span(const cg_painter *painter, int x0, int x1, int y)
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

void cg_painter_cover(const cg_painter *painter, int x, int y, float coverage)
{
    if (!(coverage > 0))
        return;
    cg_rgbaf c = painter->linear;
    c.a *= coverage < 1 ? coverage : 1;
    cg_image_blend(painter->image, x, y, c);
}

long long cg_isqrt(long long n)
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
