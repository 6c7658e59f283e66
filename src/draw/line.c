/* Bresenham's line algorithm (Algorithm 1 of the notes) in all octants. */
#include "cg/draw.h"
#include "cg/color.h"

static void plot(cg_image *image, int x, int y, cg_rgba8 color)
{
    if (!cg_image_contains(image, x, y))
        return;
    if (color.a == 255)
        cg_image_set_rgba8(image, x, y, color);
    else
        cg_image_blend(image, x, y, cg_rgba8_to_linear(color));
}

cg_status cg_draw_line(cg_image *image, int x0, int y0, int x1, int y1, cg_rgba8 color)
{
    if (!image)
        return CG_EINVAL;
    long long dx = (long long)x1 - x0, dy = (long long)y1 - y0;
    int x_major = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
    /* Walk from the smaller major coordinate so both directions agree. */
    if ((x_major && dx < 0) || (!x_major && dy < 0)) {
        int t = x0; x0 = x1; x1 = t;
        t = y0; y0 = y1; y1 = t;
        dx = -dx;
        dy = -dy;
    }
    long long major = x_major ? dx : dy, minor = x_major ? dy : dx;
    int minor_step = minor < 0 ? -1 : 1;
    if (minor < 0)
        minor = -minor;
    long long f = 2 * minor - major, d_straight = 2 * minor, d_diagonal = 2 * (minor - major);
    long long u = x_major ? x0 : y0, v = x_major ? y0 : x0;
    for (long long i = 0; i <= major; i++) {
        if (x_major)
            plot(image, (int)u, (int)v, color);
        else
            plot(image, (int)v, (int)u, color);
        if (f <= 0) {
            f += d_straight;
        } else {
            f += d_diagonal;
            v += minor_step;
        }
        u++;
    }
    return CG_OK;
}
