/* Bresenham's line algorithm (Algorithm 1 of the notes) in all octants,
 * clipped exactly to the image.
 *
 * In the first-octant frame (major coordinate u, minor v, du >= dv >= 0) the
 * walk of Algorithm 1 selects, at step k, the row offset
 *     j(k) = ceil((2 dv k - du) / (2 du)) = floor((2 dv k + du - 1) / (2 du)),
 * the rounding of the real line's v with ties going to the start side
 * (f <= 0 selects E).  j(k) is non-decreasing, so the steps whose pixel is
 * visible form one interval of k, found in closed form; the walk then starts
 * at its first step with the decision value Algorithm 1 would have there,
 *     f = 2 dv (k + 1) - du (2 j + 1),
 * and runs over the visible steps only. */
#include "internal.h"

void draw_line_frame_make(int x0, int y0, int x1, int y1, cg_line_frame *frame)
{
    long long dx = (long long)x1 - x0, dy = (long long)y1 - y0;
    long long adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    frame->x_major = adx >= ady;
    frame->swapped = frame->x_major ? dx < 0 : dy < 0;
    if (frame->swapped) {
        int t = x0;
        x0 = x1;
        x1 = t;
        t = y0;
        y0 = y1;
        y1 = t;
        dx = -dx;
        dy = -dy;
    }
    frame->u0 = frame->x_major ? x0 : y0;
    frame->v0 = frame->x_major ? y0 : x0;
    frame->du = frame->x_major ? dx : dy;
    long long dv = frame->x_major ? dy : dx;
    frame->sv = dv < 0 ? -1 : 1;
    frame->dv = dv < 0 ? -dv : dv;
}

/* floor(a / b) and ceil(a / b) for b > 0, in 64-bit arithmetic when both
 * fit (the common case: 128-bit division is a slow library call). */
static cg_wide floor_div(cg_wide a, cg_wide b)
{
    if (a >= INT64_MIN && a <= INT64_MAX && b <= INT64_MAX) {
        long long x = (long long)a, y = (long long)b, q = x / y;
        return (x % y != 0 && x < 0) ? q - 1 : q;
    }
    cg_wide q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

static cg_wide ceil_div(cg_wide a, cg_wide b)
{
    return -floor_div(-a, b);
}

void draw_line_clipped(const cg_painter *painter, int x0, int y0, int x1, int y1, int skip_first)
{
    cg_line_frame l;
    draw_line_frame_make(x0, y0, x1, y1, &l);
    const cg_image *image = painter->image;
    long long umax = (l.x_major ? image->width : image->height) - 1;
    long long vmax = (l.x_major ? image->height : image->width) - 1;

    /* Steps k in [0, du] whose major coordinate is inside the image. */
    long long kmin = -l.u0 > 0 ? -l.u0 : 0;
    long long kmax = umax - l.u0 < l.du ? umax - l.u0 : l.du;
    if (skip_first) {
        if (l.swapped)
            kmax = kmax < l.du - 1 ? kmax : l.du - 1;
        else
            kmin = kmin > 1 ? kmin : 1;
    }
    if (kmin > kmax)
        return;
    /* Row offsets j in [jlo, jhi] whose minor coordinate is inside. */
    long long jlo = l.sv > 0 ? -l.v0 : l.v0 - vmax;
    long long jhi = l.sv > 0 ? vmax - l.v0 : l.v0;
    if (jhi < 0 || jlo > l.dv)
        return;
    if (l.dv > 0) {
        if (jlo > 0) {
            cg_wide k = ceil_div((cg_wide)2 * l.du * jlo - l.du + 1, (cg_wide)2 * l.dv);
            if (k > kmin)
                kmin = (long long)k;
        }
        if (jhi < l.dv) {
            cg_wide k = floor_div((cg_wide)2 * l.du * jhi + l.du, (cg_wide)2 * l.dv);
            if (k < kmax)
                kmax = (long long)k;
        }
        if (kmin > kmax)
            return;
    }
    long long j = l.du > 0
                      ? (long long)floor_div((cg_wide)2 * l.dv * kmin + l.du - 1, (cg_wide)2 * l.du)
                      : 0;
    long long f = (long long)((cg_wide)2 * l.dv * (kmin + 1) - (cg_wide)l.du * (2 * j + 1));
    long long de = 2 * l.dv, dne = 2 * (l.dv - l.du);
    long long u = l.u0 + kmin, v = l.v0 + l.sv * j, n = kmax - kmin;

    if (painter->opaque) {
        /* Walk a pointer: one store and one add per pixel. */
        ptrdiff_t stride = (ptrdiff_t)image->stride;
        ptrdiff_t step_u = l.x_major ? 4 : stride, step_v = l.x_major ? l.sv * stride : l.sv * 4;
        long long x = l.x_major ? u : v, y = l.x_major ? v : u;
        unsigned char *p = image->data + (ptrdiff_t)y * stride + (ptrdiff_t)x * 4;
        uint32_t packed = painter->packed;
        ptrdiff_t step_uv = step_u + step_v;
        /* Branch-free: the E/NE choice of a random line is unpredictable. */
        for (long long i = 0; i <= n; i++) {
            memcpy(p, &packed, 4);
            int diagonal = f > 0;
            p += diagonal ? step_uv : step_u;
            f += diagonal ? dne : de;
        }
        return;
    }
    for (long long i = 0; i <= n; i++, u++) {
        if (l.x_major)
            cg_painter_plot(painter, (int)u, (int)v);
        else
            cg_painter_plot(painter, (int)v, (int)u);
        if (f > 0) {
            v += l.sv;
            f += dne;
        } else {
            f += de;
        }
    }
}

cg_status cg_draw_line(cg_image *image, int x0, int y0, int x1, int y1, cg_rgba8 color)
{
    if (!image || !image->data)
        return CG_EINVAL;
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    draw_line_clipped(&painter, x0, y0, x1, y1, 0);
    return CG_OK;
}

cg_status cg_draw_polyline(cg_image *image, const int *xy, int count, cg_rgba8 color)
{
    if (!image || !image->data || !xy || count < 1)
        return CG_EINVAL;
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    if (count == 1) {
        cg_painter_plot_clipped(&painter, xy[0], xy[1]);
        return CG_OK;
    }
    for (int i = 1; i < count; i++)
        draw_line_clipped(&painter, xy[2 * i - 2], xy[2 * i - 1], xy[2 * i], xy[2 * i + 1], i > 1);
    return CG_OK;
}
