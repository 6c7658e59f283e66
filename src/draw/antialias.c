/* Anti-aliased lines, circles and ellipses, blended in linear light.
 *
 * Lines: a band one pixel thick around the segment, with butt ends at the
 * endpoints.  For a line whose major axis is x (|dx| >= |dy|, slope m), the
 * band's vertical extent in a column is h = sqrt(1 + m^2); the column is cut
 * at the centre of its covered part, and each pixel of the column receives
 * the length of [yc - h/2, yc + h/2] that falls in it, times the fraction of
 * the column between the endpoints.  The coverage summed over a column is
 * h, so coverage per unit of length is 1 at every angle (Wu's algorithm
 * gives 1 per column, which makes diagonals dimmer).  Steep lines are the
 * same with x and y exchanged.  Only the columns where the band meets the
 * image are visited. */
#include "internal.h"

static int finite4(double a, double b, double c, double d)
{
    return isfinite(a) && isfinite(b) && isfinite(c) && isfinite(d);
}

static inline double min2(double a, double b)
{
    return a < b ? a : b;
}
static inline double max2(double a, double b)
{
    return a > b ? a : b;
}

/* floor for the finite values used here (well inside the long long range). */
static inline long long floor_ll(double v)
{
    long long i = (long long)v;
    return (double)i > v ? i - 1 : i;
}

static void line_aa(const cg_painter *painter, double x0, double y0, double x1, double y1)
{
    int swap = fabs(y1 - y0) > fabs(x1 - x0);
    double u0 = swap ? y0 : x0, v0 = swap ? x0 : y0, u1 = swap ? y1 : x1, v1 = swap ? x1 : y1;
    if (u1 < u0) {
        double t = u0;
        u0 = u1;
        u1 = t;
        t = v0;
        v0 = v1;
        v1 = t;
    }
    double du = u1 - u0;
    if (!(du > 0))
        return; /* zero length: no area */
    double m = (v1 - v0) / du, h = sqrt(1 + m * m);
    long long umax = swap ? painter->image->height : painter->image->width;
    long long vmax = swap ? painter->image->width : painter->image->height;
    /* Columns where the band is within the image's extent along v too. */
    double lo = max2(u0, 0), hi = min2(u1, (double)umax);
    if (m != 0) {
        double ua = u0 + (-h - v0) / m, ub = u0 + ((double)vmax + h - v0) / m;
        if (ua > ub) {
            double t = ua;
            ua = ub;
            ub = t;
        }
        lo = max2(lo, ua - 1);
        hi = min2(hi, ub + 1);
    } else if (v0 + h < 0 || v0 - h > (double)vmax) {
        return;
    }
    if (!(lo < hi))
        return;
    long long c0 = floor_ll(lo), c1 = floor_ll(hi);
    if ((double)c1 == hi)
        c1--;
    cg_cover_batch batch;
    batch.painter = painter;
    batch.count = 0;
    double half = 0.5 * h;
    for (long long c = c0; c <= c1; c++) {
        double a = (double)c, b = a + 1, w = 1;
        if (a < u0 || b > u1) { /* an end column: only part of it is covered */
            a = max2(a, u0);
            b = min2(b, u1);
            if (!(b > a))
                continue;
            w = b - a;
        }
        double top = v0 + m * (0.5 * (a + b) - u0) - half;
        long long r = floor_ll(top);
        /* The band [top, top + h] is at most sqrt(2) tall: rows r, r+1, r+2. */
        double first = min2((double)(r + 1) - top, h), rest = h - first;
        double second = min2(rest, 1), third = rest - second;
        double cover[3] = {first * w, second * w, third * w};
        for (int k = 0; k < 3; k++, r++)
            if (cover[k] > 0 && r >= 0 && r < vmax)
                cg_cover_add(&batch, (int)(swap ? r : c), (int)(swap ? c : r), (float)cover[k]);
    }
    draw_cover_flush(&batch);
}

cg_status cg_draw_line_aa(cg_image *image, double x0, double y0, double x1, double y1,
                          cg_rgba8 color)
{
    if (!image || !image->data || !finite4(x0, y0, x1, y1))
        return CG_EINVAL;
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    line_aa(&painter, x0, y0, x1, y1);
    return CG_OK;
}

cg_status cg_draw_polyline_aa(cg_image *image, const cg_vec2 *points, int count, cg_rgba8 color)
{
    if (!image || !image->data || !points || count < 1)
        return CG_EINVAL;
    for (int i = 0; i < count; i++)
        if (!isfinite(points[i].x) || !isfinite(points[i].y))
            return CG_EINVAL;
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    for (int i = 1; i < count; i++)
        line_aa(&painter, points[i - 1].x, points[i - 1].y, points[i].x, points[i].y);
    return CG_OK;
}

/* ---- circles and ellipses ----------------------------------------------- */

/* Visits the pixels whose centres lie in the ring between the ellipses of
 * radii (rx - 1, ry - 1) and (rx + 1, ry + 1), row by row, and covers each
 * with 1 - |d| for the distance estimate d. */
static void ring_aa(const cg_painter *painter, double cx, double cy, double rx, double ry)
{
    const cg_image *image = painter->image;
    double ox = rx + 1, oy = ry + 1, ix = rx - 1, iy = ry - 1;
    double top = fmax(floor(cy - oy), 0), bottom = fmin(ceil(cy + oy), image->height - 1.0);
    cg_cover_batch batch;
    batch.painter = painter;
    batch.count = 0;
    for (double row = top; row <= bottom; row++) {
        double dy = row + 0.5 - cy;
        if (fabs(dy) >= oy)
            continue;
        double outer = ox * sqrt(1 - (dy / oy) * (dy / oy));
        double inner = (ix > 0 && iy > 0 && fabs(dy) < iy) ? ix * sqrt(1 - (dy / iy) * (dy / iy))
                                                           : -1;
        /* Left and right runs, or one run across when there is no hole. */
        double runs[2][2] = {{cx - outer, inner >= 0 ? cx - inner : cx + outer},
                             {cx + inner, cx + outer}};
        int nruns = inner >= 0 ? 2 : 1;
        double split = floor(cx - 0.5); /* last column of the left run */
        for (int k = 0; k < nruns; k++) {
            double a = fmax(floor(runs[k][0] - 0.5), 0);
            double b = fmin(ceil(runs[k][1] - 0.5), image->width - 1.0);
            if (nruns == 2 && k == 0)
                b = fmin(b, split);
            if (nruns == 2 && k == 1)
                a = fmax(a, split + 1);
            for (double col = a; col <= b; col++) {
                double dx = col + 0.5 - cx, d;
                if (rx == ry) {
                    d = sqrt(dx * dx + dy * dy) - rx;
                } else {
                    double fx = dx / rx, fy = dy / ry;
                    double f = fx * fx + fy * fy - 1;
                    double gx = 2 * fx / rx, gy = 2 * fy / ry, g = sqrt(gx * gx + gy * gy);
                    d = g > 0 ? f / g : -fmin(rx, ry);
                }
                double c = 1 - fabs(d);
                if (c > 0)
                    cg_cover_add(&batch, (int)col, (int)row, (float)c);
            }
        }
    }
    draw_cover_flush(&batch);
}

cg_status cg_draw_circle_aa(cg_image *image, double cx, double cy, double r, cg_rgba8 color)
{
    return cg_draw_ellipse_aa(image, cx, cy, r, r, color);
}

cg_status cg_draw_ellipse_aa(cg_image *image, double cx, double cy, double rx, double ry,
                             cg_rgba8 color)
{
    if (!image || !image->data || !finite4(cx, cy, rx, ry) || rx < 0 || ry < 0)
        return CG_EINVAL;
    /* Nothing to do when the ring misses the image. */
    if (cx + rx + 1 < 0 || cy + ry + 1 < 0 || cx - rx - 1 > image->width
        || cy - ry - 1 > image->height)
        return CG_OK;
    if (rx > 1e9 || ry > 1e9)
        return CG_ERANGE;
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    if (rx == 0 || ry == 0) {
        line_aa(&painter, cx - rx, cy - ry, cx + rx, cy + ry);
        return CG_OK;
    }
    ring_aa(&painter, cx, cy, rx, ry);
    return CG_OK;
}
