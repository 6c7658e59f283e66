/* Bresenham's midpoint circle (Algorithm 2 of the notes), filled circles and
 * circular arcs.
 *
 * Algorithm 2 walks the first octant (0 <= x <= y) from (0, r) and mirrors
 * each pixel eight ways.  Its integer decision value at pixel (x, y) is
 *     f = (x + 1)^2 + y^2 - y - r^2
 * (the notes' f at the midpoint (x + 1, y - 1/2) less 1/4), and it keeps y
 * while f < 0.  So the row chosen at column x is the y with
 *     y (y - 1) < r^2 - x^2 <= y (y + 1),
 * which lets a clipped walk start at any column with the decision value and
 * increments the full walk would have there.
 *
 * Where octants meet, mirrors coincide: at x = 0 the mirrors in -x, at
 * x = y the swapped mirrors.  Those are skipped, so every pixel of the
 * circle is drawn once.  A last step of Algorithm 2 that ends with x > y
 * mirrors an earlier pixel and is not drawn. */
#include "internal.h"

#include <stdlib.h>

/* The row of the first octant at column x (0 <= x <= r). */
static long long octant_row(long long r, long long x)
{
    long long n = r * r - x * x; /* < 2^62 */
    long long y = (long long)ceil(sqrt((double)n + 0.25) - 0.5);
    if (y < 0)
        y = 0;
    while (y > 0 && y * (y - 1) >= n)
        y--;
    while (y * (y + 1) < n)
        y++;
    return y;
}

/* The last column of the first octant: the largest x with x <= row(x). */
static long long octant_end(long long r)
{
    long long x = (long long)floor((double)r / sqrt(2.0));
    while (x > 0 && x > octant_row(r, x))
        x--;
    while (x + 1 <= r && x + 1 <= octant_row(r, x + 1))
        x++;
    return x;
}

/* One mirror of the first octant: the image pixel of octant pixel (x, y) is
 * (cx + sa x, cy - sb y), or (cx + sb y, cy - sa x) when swapped. */
typedef struct mirror {
    int sa, sb, swap;
} mirror;

static const mirror mirrors[8] = {
    {1, 1, 0}, {1, 1, 1}, {1, -1, 0}, {1, -1, 1}, {-1, 1, 0}, {-1, 1, 1}, {-1, -1, 0}, {-1, -1, 1},
};

typedef cg_pixel_fn pixel_fn;

typedef struct circle_walk {
    long long cx, cy, r, last; /* last: octant_end(r) */
    long long width, height;
    const cg_painter *fast; /* an opaque RGBA8 painter: plot directly */
} circle_walk;

/* Columns x in [lo, hi] of the octant with row(x) in [ylo, yhi] (row is
 * non-increasing).  Returns 0 when empty. */
static int rows_to_columns(const circle_walk *w, long long ylo, long long yhi, long long *lo,
                           long long *hi)
{
    /* smallest x with row(x) <= yhi */
    long long a = *lo, b = *hi + 1;
    while (a < b) {
        long long m = a + (b - a) / 2;
        if (octant_row(w->r, m) <= yhi)
            b = m;
        else
            a = m + 1;
    }
    long long first = a;
    /* largest x with row(x) >= ylo */
    a = *lo - 1;
    b = *hi;
    while (a < b) {
        long long m = b - (b - a) / 2;
        if (octant_row(w->r, m) >= ylo)
            a = m;
        else
            b = m - 1;
    }
    *lo = first;
    *hi = a;
    return *lo <= *hi;
}

/* One step of Algorithm 2's midpoint decision from column x to x + 1: east
 * (f < 0) or south-east.  Returns 1 when south-east (y goes down by one). */
static inline int midpoint_step(long long *f, long long *de, long long *dse)
{
    if (*f < 0) {
        *f += *de;
        *de += 2;
        *dse += 2;
        return 0;
    }
    *f += *dse;
    *de += 2;
    *dse += 4;
    return 1;
}

/* Runs Algorithm 2 over the columns of one mirror that land in the image,
 * calling plot for each pixel it owns. */
static void walk_mirror(const circle_walk *w, mirror m, pixel_fn plot, void *context)
{
    long long lo = m.sa > 0 ? 0 : 1, hi = w->last;
    /* The coordinate that follows x: px = cx + sa x, or py = cy - sa x. */
    long long base = m.swap ? w->cy : w->cx, limit = m.swap ? w->height : w->width;
    long long s = m.swap ? -m.sa : m.sa;
    long long a = s > 0 ? -base : base - (limit - 1), b = s > 0 ? limit - 1 - base : base;
    lo = lo > a ? lo : a;
    hi = hi < b ? hi : b;
    if (lo > hi)
        return;
    /* The coordinate that follows y: py = cy - sb y, or px = cx + sb y. */
    base = m.swap ? w->cx : w->cy;
    limit = m.swap ? w->width : w->height;
    s = m.swap ? m.sb : -m.sb;
    long long ylo = s > 0 ? -base : base - (limit - 1), yhi = s > 0 ? limit - 1 - base : base;
    if (!rows_to_columns(w, ylo, yhi, &lo, &hi))
        return;
    long long x = lo, y = octant_row(w->r, x);
    long long f = (x + 1) * (x + 1) + y * y - y - w->r * w->r;
    long long de = 2 * x + 3, dse = 2 * x - 2 * y + 5;
    if (w->fast) {
        /* Opaque RGBA8: walk a pointer.  x + 1 moves the pixel by sa in x
         * (or -sa in y when swapped); y - 1 by sb in y (or -sb in x). */
        const cg_image *image = w->fast->image;
        ptrdiff_t stride = (ptrdiff_t)image->stride;
        long long px = m.swap ? w->cx + m.sb * y : w->cx + m.sa * x;
        long long py = m.swap ? w->cy - m.sa * x : w->cy - m.sb * y;
        ptrdiff_t step_x = m.swap ? -m.sa * stride : m.sa * 4;
        ptrdiff_t step_y = m.swap ? -m.sb * 4 : m.sb * stride;
        unsigned char *p = image->data + (ptrdiff_t)py * stride + (ptrdiff_t)px * 4;
        uint32_t packed = w->fast->packed;
        for (; x <= hi; x++) {
            if (!(m.swap && x == y))
                memcpy(p, &packed, 4);
            p += step_x;
            if (midpoint_step(&f, &de, &dse)) {
                y--;
                p += step_y;
            }
        }
        return;
    }
    for (; x <= hi; x++) {
        if (!(m.swap && x == y)) {
            if (m.swap)
                plot(context, w->cx + m.sb * y, w->cy - m.sa * x);
            else
                plot(context, w->cx + m.sa * x, w->cy - m.sb * y);
        }
        y -= midpoint_step(&f, &de, &dse);
    }
}

static void walk_circle(const cg_image *image, int cx, int cy, int r, pixel_fn plot, void *context,
                        const cg_painter *fast)
{
    if (r == 0) {
        if (cg_image_contains(image, cx, cy))
            plot(context, cx, cy);
        return;
    }
    circle_walk w = {cx, cy, r, octant_end(r), image->width, image->height, fast};
    for (int i = 0; i < 8; i++)
        walk_mirror(&w, mirrors[i], plot, context);
}

static void plot_painter(void *context, long long x, long long y)
{
    cg_painter_plot(context, (int)x, (int)y);
}

cg_status cg_draw_circle(cg_image *image, int cx, int cy, int r, cg_rgba8 color)
{
    if (!image || !image->data || r < 0)
        return CG_EINVAL;
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    if ((long long)cx - r < 0 || (long long)cy - r < 0 || (long long)cx + r >= image->width
        || (long long)cy + r >= image->height) {
        walk_circle(image, cx, cy, r, plot_painter, &painter, painter.opaque ? &painter : NULL);
        return CG_OK;
    }
    /* Entirely inside: one walk, eight stores per column. */
    if (r == 0) {
        cg_painter_plot(&painter, cx, cy);
        return CG_OK;
    }
    cg_painter_plot(&painter, cx, cy - r);
    cg_painter_plot(&painter, cx, cy + r);
    cg_painter_plot(&painter, cx + r, cy);
    cg_painter_plot(&painter, cx - r, cy);
    int x = 0, y = r;
    long long f = 1 - (long long)r, de = 3, dse = 5 - 2 * (long long)r;
    for (;;) {
        y -= midpoint_step(&f, &de, &dse);
        x++;
        if (x >= y)
            break;
        cg_painter_plot(&painter, cx + x, cy - y);
        cg_painter_plot(&painter, cx - x, cy - y);
        cg_painter_plot(&painter, cx + x, cy + y);
        cg_painter_plot(&painter, cx - x, cy + y);
        cg_painter_plot(&painter, cx + y, cy - x);
        cg_painter_plot(&painter, cx - y, cy - x);
        cg_painter_plot(&painter, cx + y, cy + x);
        cg_painter_plot(&painter, cx - y, cy + x);
    }
    if (x == y) {
        cg_painter_plot(&painter, cx + x, cy - y);
        cg_painter_plot(&painter, cx - x, cy - y);
        cg_painter_plot(&painter, cx + x, cy + y);
        cg_painter_plot(&painter, cx - x, cy + y);
    }
    return CG_OK;
}

/* Half-width of the digital circle on the row at offset d (0 <= d <= r):
 * the largest |x offset| of its pixels there. */
static long long disc_half_width(long long r, long long d, long long last)
{
    if (d <= last)
        return octant_row(r, d); /* the swapped mirror of column d */
    /* Otherwise the last column whose row is at least d: x^2 < r^2 - d(d-1). */
    long long n = r * r - d * d + d;
    long long x = draw_isqrt(n);
    return x * x == n ? x - 1 : x;
}

cg_status cg_draw_disc(cg_image *image, int cx, int cy, int r, cg_rgba8 color)
{
    if (!image || !image->data || r < 0)
        return CG_EINVAL;
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    long long last = octant_end(r);
    long long y0 = (long long)cy - r < 0 ? 0 : (long long)cy - r;
    long long y1 = (long long)cy + r >= image->height ? image->height - 1 : (long long)cy + r;
    for (long long y = y0; y <= y1; y++) {
        long long d = y < cy ? cy - y : y - cy;
        long long w = disc_half_width(r, d, last);
        long long a = (long long)cx - w, b = (long long)cx + w;
        if (a < 0)
            a = 0;
        if (b >= image->width)
            b = image->width - 1;
        if (a <= b)
            draw_painter_span(&painter, (int)a, (int)b, (int)y);
    }
    return CG_OK;
}

/* ---- arcs ---------------------------------------------------------------- */

int draw_arc_contains(double start, double sweep, double dx, double dy_up)
{
    if (sweep >= 360)
        return 1;
    double a = (dx == 0 && dy_up == 0) ? 0 : atan2(dy_up, dx) * (180.0 / CG_PI);
    double rel = fmod(a - start + 720.0, 360.0);
    return rel <= sweep + 1e-9 || rel >= 360 - 1e-9;
}

void draw_arc_plot(void *context, long long x, long long y)
{
    const cg_arc_filter *a = context;
    if (cg_painter_visible(a->painter, x, y)
        && draw_arc_contains(a->start, a->sweep, (double)(x - a->cx), (double)(a->cy - y)))
        cg_painter_plot(a->painter, (int)x, (int)y);
}

int draw_arc_range(double start_deg, double end_deg, double *start, double *sweep)
{
    if (!isfinite(start_deg) || !isfinite(end_deg))
        return 0;
    if (end_deg - start_deg >= 360) {
        *start = 0;
        *sweep = 360;
        return 1;
    }
    *start = fmod(fmod(start_deg, 360.0) + 360.0, 360.0);
    *sweep = fmod(fmod(end_deg - start_deg, 360.0) + 360.0, 360.0);
    return 1;
}

cg_status cg_draw_arc(cg_image *image, int cx, int cy, int r, double start_deg, double end_deg,
                      cg_rgba8 color)
{
    cg_arc_filter a;
    if (!image || !image->data || r < 0 || !draw_arc_range(start_deg, end_deg, &a.start, &a.sweep))
        return CG_EINVAL;
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    a.painter = &painter;
    a.cx = cx;
    a.cy = cy;
    walk_circle(image, cx, cy, r, draw_arc_plot, &a, NULL);
    return CG_OK;
}
