/* The midpoint ellipse for axis-aligned ellipses, and elliptical arcs.
 *
 * F(x, y) = ry^2 x^2 + rx^2 y^2 - rx^2 ry^2 is negative inside the ellipse.
 * As for the circle's octants, each quadrant is cut where the real curve's
 * slope is -1, at x* = rx^2 / sqrt(rx^2 + ry^2), y* = ry^2 / sqrt(rx^2 + ry^2):
 *  - region 1, the columns 0 <= x <= x*, takes in each column the row whose
 *    upper midpoint is the first outside: the smallest y >= 0 with
 *    F(x, y + 1/2) >= 0 (the midpoint rule of the notes, E or SE);
 *  - region 2, the rows 0 <= y <= y*, takes in each row the smallest x >= 0
 *    with F(x + 1/2, y) >= 0 (S or SE).
 * Each pixel is then within 1/2 of the real curve along its region's minor
 * axis.  The regions meet near (x*, y*): when their last pixels coincide
 * the pixel is drawn once, when they are two apart the pixel between them
 * joins the curve (the one its own row or column picks, when adjacent to
 * both).  Decision values are exact in 128-bit arithmetic; each
 * column or row is computed directly, so only the columns and rows that can
 * reach the image are visited.  Four mirrors give the other quadrants;
 * pixels on the axes are drawn once.  Equal radii draw Bresenham's circle. */
#include "internal.h"

enum { MAX_RADIUS = 1 << 30 };

typedef struct ellipse {
    long long cx, cy, rx, ry;
    cg_wide a2, b2;
    cg_pixel_fn plot;
    void *context;
} ellipse;

static void emit4(const ellipse *e, long long x, long long y)
{
    e->plot(e->context, e->cx + x, e->cy - y);
    if (x > 0)
        e->plot(e->context, e->cx - x, e->cy - y);
    if (y > 0)
        e->plot(e->context, e->cx + x, e->cy + y);
    if (x > 0 && y > 0)
        e->plot(e->context, e->cx - x, e->cy + y);
}

/* Smallest y >= 0 with 4 F(x, y + 1/2) >= 0. */
static long long row_of_column(const ellipse *e, long long x)
{
    cg_wide rhs = 4 * e->a2 * e->b2 - 4 * e->b2 * x * x;
    double t = (double)e->ry
               * sqrt(fmax(0, 1 - ((double)x / (double)e->rx) * ((double)x / (double)e->rx)));
    long long y = (long long)(t - 0.5) - 1;
    if (y < 0)
        y = 0;
    while (y > 0 && e->a2 * (2 * y - 1) * (2 * y - 1) >= rhs)
        y--;
    while (e->a2 * (2 * y + 1) * (2 * y + 1) < rhs)
        y++;
    return y;
}

/* Smallest x >= 0 with 4 F(x + 1/2, y) >= 0. */
static long long column_of_row(const ellipse *e, long long y)
{
    cg_wide rhs = 4 * e->a2 * e->b2 - 4 * e->a2 * y * y;
    double t = (double)e->rx
               * sqrt(fmax(0, 1 - ((double)y / (double)e->ry) * ((double)y / (double)e->ry)));
    long long x = (long long)(t - 0.5) - 1;
    if (x < 0)
        x = 0;
    while (x > 0 && e->b2 * (2 * x - 1) * (2 * x - 1) >= rhs)
        x--;
    while (e->b2 * (2 * x + 1) * (2 * x + 1) < rhs)
        x++;
    return x;
}

/* The offsets t in [0, last] for which centre + t or centre - t lies in
 * [0, size): one hull of at most about 2 size values. */
static int visible_offsets(long long centre, long long size, long long last, long long *lo,
                           long long *hi)
{
    long long a1 = -centre > 0 ? -centre : 0,
              b1 = size - 1 - centre < last ? size - 1 - centre : last;
    long long a2 = centre - size + 1 > 0 ? centre - size + 1 : 0,
              b2 = centre < last ? centre : last;
    int one = a1 <= b1, two = a2 <= b2;
    if (!one && !two)
        return 0;
    *lo = one && two ? (a1 < a2 ? a1 : a2) : one ? a1 : a2;
    *hi = one && two ? (b1 > b2 ? b1 : b2) : one ? b1 : b2;
    return 1;
}

static void walk_ellipse(const ellipse *e, long long width, long long height)
{
    if (e->rx == 0 || e->ry == 0) { /* a segment along an axis, or a point */
        long long lo, hi;
        if (e->ry == 0 && visible_offsets(e->cx, width, e->rx, &lo, &hi))
            for (long long x = lo; x <= hi; x++)
                emit4(e, x, 0);
        if (e->rx == 0 && e->ry > 0 && visible_offsets(e->cy, height, e->ry, &lo, &hi))
            for (long long y = lo; y <= hi; y++)
                emit4(e, 0, y);
        return;
    }
    /* Last column of region 1 and last row of region 2: x^2 (a2 + b2) <= a2^2. */
    cg_wide sum = e->a2 + e->b2;
    long long xs = (long long)((double)e->a2 / sqrt((double)sum)),
              ys = (long long)((double)e->b2 / sqrt((double)sum));
    while (xs > 0 && (cg_wide)xs * xs * sum > e->a2 * e->a2)
        xs--;
    while ((cg_wide)(xs + 1) * (xs + 1) * sum <= e->a2 * e->a2)
        xs++;
    while (ys > 0 && (cg_wide)ys * ys * sum > e->b2 * e->b2)
        ys--;
    while ((cg_wide)(ys + 1) * (ys + 1) * sum <= e->b2 * e->b2)
        ys++;
    long long lo, hi;
    if (visible_offsets(e->cx, width, xs, &lo, &hi))
        for (long long x = lo; x <= hi; x++)
            emit4(e, x, row_of_column(e, x));
    long long ax = xs, ay = row_of_column(e, xs); /* region 1's last pixel */
    long long bx = column_of_row(e, ys), by = ys; /* region 2's last pixel */
    int same = ax == bx && ay == by;
    if (visible_offsets(e->cy, height, ys, &lo, &hi))
        for (long long y = lo; y <= hi; y++)
            if (!(same && y == ys))
                emit4(e, column_of_row(e, y), y);
    /* Bridge a two-pixel gap at the junction with the pixel its row (or
     * column) would choose, kept adjacent to both ends. */
    if (ay - by == 2) {
        long long x = column_of_row(e, ay - 1), low = ax > bx - 1 ? ax : bx - 1;
        long long high = ax + 1 < bx ? ax + 1 : bx;
        emit4(e, x < low ? low : x > high ? high : x, ay - 1);
    } else if (bx - ax == 2) {
        long long y = row_of_column(e, ax + 1), low = by > ay - 1 ? by : ay - 1;
        long long high = by + 1 < ay ? by + 1 : ay;
        emit4(e, ax + 1, y < low ? low : y > high ? high : y);
    }
}

static void plot_visible(void *context, long long x, long long y)
{
    cg_painter_plot_clipped(context, x, y);
}

static cg_status check(const cg_image *image, int rx, int ry)
{
    if (!image || !image->data || rx < 0 || ry < 0)
        return CG_EINVAL;
    if (rx > MAX_RADIUS || ry > MAX_RADIUS)
        return CG_ERANGE;
    return CG_OK;
}

cg_status cg_draw_ellipse(cg_image *image, int cx, int cy, int rx, int ry, cg_rgba8 color)
{
    cg_status status = check(image, rx, ry);
    if (status != CG_OK)
        return status;
    if (rx == ry)
        return cg_draw_circle(image, cx, cy, rx, color);
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    ellipse e = {cx, cy, rx, ry, (cg_wide)rx * rx, (cg_wide)ry * ry, plot_visible, &painter};
    walk_ellipse(&e, image->width, image->height);
    return CG_OK;
}

cg_status cg_draw_ellipse_arc(cg_image *image, int cx, int cy, int rx, int ry, double start_deg,
                              double end_deg, cg_rgba8 color)
{
    cg_arc_filter a;
    cg_status status = check(image, rx, ry);
    if (status != CG_OK)
        return status;
    if (!draw_arc_range(start_deg, end_deg, &a.start, &a.sweep))
        return CG_EINVAL;
    if (rx == ry)
        return cg_draw_arc(image, cx, cy, rx, start_deg, end_deg, color);
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    a.painter = &painter;
    a.cx = cx;
    a.cy = cy;
    ellipse e = {cx, cy, rx, ry, (cg_wide)rx * rx, (cg_wide)ry * ry, draw_arc_plot, &a};
    walk_ellipse(&e, image->width, image->height);
    return CG_OK;
}
