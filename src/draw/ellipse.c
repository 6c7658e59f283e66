/* The midpoint ellipse for axis-aligned ellipses, and elliptical arcs.
 *
 * With F(x, y) = ry^2 x^2 + rx^2 y^2 - rx^2 ry^2 the first quadrant is walked
 * from (0, ry).  In region 1, while the slope is shallower than -1 (that is
 * 2 ry^2 (x + 1) < rx^2 (2y - 1)), x steps and the midpoint (x + 1, y - 1/2)
 * decides: inside (F < 0) keeps y (E), otherwise y steps down (SE).  In
 * region 2 y steps down and the midpoint (x + 1/2, y - 1) decides: outside
 * (F > 0) keeps x (S), otherwise x steps (SE).  Decision values are scaled by
 * 4 to stay integer and evaluated exactly in 128-bit arithmetic.  A very flat
 * ellipse can reach y = 0 before x = rx; the row y = 0 is then completed to
 * x = rx.  Four mirrors give the other quadrants; pixels on the axes are
 * drawn once. */
#include "internal.h"

enum { MAX_RADIUS = 1 << 24 };

typedef struct quadrants {
    long long cx, cy;
    cg_pixel_fn plot;
    void *context;
} quadrants;

static void emit4(const quadrants *q, long long x, long long y)
{
    q->plot(q->context, q->cx + x, q->cy - y);
    if (x > 0)
        q->plot(q->context, q->cx - x, q->cy - y);
    if (y > 0)
        q->plot(q->context, q->cx + x, q->cy + y);
    if (x > 0 && y > 0)
        q->plot(q->context, q->cx - x, q->cy + y);
}

static void walk_ellipse(int cx, int cy, int rx, int ry, cg_pixel_fn plot, void *context)
{
    quadrants q = {cx, cy, plot, context};
    cg_wide a2 = (cg_wide)rx * rx, b2 = (cg_wide)ry * ry;
    long long x = 0, y = ry;
    while (y >= 1 && 2 * b2 * (x + 1) < a2 * (2 * y - 1)) {
        emit4(&q, x, y);
        cg_wide d = 4 * b2 * (x + 1) * (x + 1) + a2 * (2 * y - 1) * (2 * y - 1) - 4 * a2 * b2;
        if (d >= 0)
            y--;
        x++;
    }
    for (;;) {
        emit4(&q, x, y);
        if (y == 0)
            break;
        cg_wide d = b2 * (2 * x + 1) * (2 * x + 1) + 4 * a2 * (y - 1) * (y - 1) - 4 * a2 * b2;
        if (d <= 0)
            x++;
        y--;
    }
    while (x < rx)
        emit4(&q, ++x, 0);
}

static void plot_visible(void *context, long long x, long long y)
{
    cg_painter_plot_clipped(context, x, y);
}

static int valid(const cg_image *image, int rx, int ry)
{
    return image && image->data && rx >= 0 && ry >= 0;
}

cg_status cg_draw_ellipse(cg_image *image, int cx, int cy, int rx, int ry, cg_rgba8 color)
{
    if (!valid(image, rx, ry))
        return CG_EINVAL;
    if (rx > MAX_RADIUS || ry > MAX_RADIUS)
        return CG_ERANGE;
    cg_painter painter;
    cg_painter_init(&painter, image, color);
    /* Nothing to walk when the bounding box misses the image. */
    if ((long long)cx + rx < 0 || (long long)cy + ry < 0 || (long long)cx - rx >= image->width
        || (long long)cy - ry >= image->height)
        return CG_OK;
    walk_ellipse(cx, cy, rx, ry, plot_visible, &painter);
    return CG_OK;
}

cg_status cg_draw_ellipse_arc(cg_image *image, int cx, int cy, int rx, int ry, double start_deg,
                              double end_deg, cg_rgba8 color)
{
    cg_arc_filter a;
    if (!valid(image, rx, ry) || !cg_arc_range(start_deg, end_deg, &a.start, &a.sweep))
        return CG_EINVAL;
    if (rx > MAX_RADIUS || ry > MAX_RADIUS)
        return CG_ERANGE;
    cg_painter painter;
    cg_painter_init(&painter, image, color);
    if ((long long)cx + rx < 0 || (long long)cy + ry < 0 || (long long)cx - rx >= image->width
        || (long long)cy - ry >= image->height)
        return CG_OK;
    a.painter = &painter;
    a.cx = cx;
    a.cy = cy;
    walk_ellipse(cx, cy, rx, ry, cg_arc_plot, &a);
    return CG_OK;
}
