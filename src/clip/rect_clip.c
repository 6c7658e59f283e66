/* Clipping polygons and polylines against an axis-aligned rectangle.
 *
 * Polygons: each ring is cut by the rectangle's four sides in turn
 * (Sutherland-Hodgman).  Cutting a closed path by a half-plane replaces
 * each of its runs outside by the stretch of the side between where the
 * run left and where it came back, which leaves the winding number of
 * every point inside unchanged; so the cut rings cover, inside the
 * rectangle, what the input covers, under the same fill rule.  They may
 * run along the sides back and forth (where the polygon left and came
 * back), so the boolean engine unites them into simple polygons -- on the
 * cut rings only, a small part of the input when the rectangle is small:
 *
 *        +-----------+               +-----------+
 *        |   rect    |               |           |
 *     +--+---+    +--+--+   cut:     +---+    +--+
 *     |  |   |    |  |  |    -->     |   |    |  |   the two stretches
 *     |  +---+----+--+  |            +---+----+--+   of the bottom side
 *     |      +----+     |                            run back and forth
 *     +-----------------+
 *
 * Polylines: each segment is cut by the four sides (Liang-Barsky); a
 * polyline leaving the rectangle ends a piece there, and one coming back
 * starts the next. */
#include "polygon_internal.h"

#include "../core/array.h"

#include <math.h>

typedef CORE_ARRAY(cg_point64) point_array;

/* One side of the rectangle as a half-plane: the points whose coordinate
 * `axis` (0 x, 1 y) is >= limit (sign +1) or <= limit (sign -1). */
typedef struct side {
    int axis, sign;
    int64_t limit;
} side;

static int64_t coordinate(cg_point64 p, int axis)
{
    return axis ? p.y : p.x;
}

static int inside(side s, cg_point64 p)
{
    int64_t c = coordinate(p, s.axis);
    return s.sign > 0 ? c >= s.limit : c <= s.limit;
}

/* Where the edge a-b (one end on each side of the line) crosses the side's
 * line, the other coordinate rounded to the grid. */
static cg_point64 crossing(side s, cg_point64 a, cg_point64 b)
{
    int64_t ca = coordinate(a, s.axis), cb = coordinate(b, s.axis);
    int64_t oa = coordinate(a, !s.axis), ob = coordinate(b, !s.axis);
    int64_t other = oa + polygon_divide_rounded((polygon_i128)(ob - oa) * (s.limit - ca), cb - ca);
    return s.axis ? (cg_point64){other, s.limit} : (cg_point64){s.limit, other};
}

/* The ring in[0..n) cut by the side into out (emptied first). */
static cg_status cut_ring(side s, const cg_point64 *in, size_t n, point_array *out)
{
    out->count = 0;
    cg_status st = core_array_reserve_for(out, 2 * n);
    for (size_t i = 0; i < n && st == CG_OK; i++) {
        cg_point64 a = in[i], b = in[(i + 1) % n];
        int ia = inside(s, a), ib = inside(s, b);
        if (ia)
            out->data[out->count++] = a;
        if (ia != ib && coordinate(a, s.axis) != s.limit && coordinate(b, s.axis) != s.limit)
            out->data[out->count++] = crossing(s, a, b);
    }
    return st;
}

static void ring_bounds(const cg_point64 *p, size_t n, cg_rect64 *bounds)
{
    *bounds = (cg_rect64){INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
    for (size_t i = 0; i < n; i++) {
        bounds->xmin = p[i].x < bounds->xmin ? p[i].x : bounds->xmin;
        bounds->ymin = p[i].y < bounds->ymin ? p[i].y : bounds->ymin;
        bounds->xmax = p[i].x > bounds->xmax ? p[i].x : bounds->xmax;
        bounds->ymax = p[i].y > bounds->ymax ? p[i].y : bounds->ymax;
    }
}

static cg_status check_input(const cg_polygon_set64 *paths, cg_rect64 rect,
                             const cg_polygon_set64 *result)
{
    if (!paths || !result || rect.xmin > rect.xmax || rect.ymin > rect.ymax)
        return CG_EINVAL;
    return polygon_set64_check_range(paths);
}

/* Every ring of paths cut to the rectangle, into cut (rings of fewer than
 * three points dropped). */
static cg_status cut_rings(const cg_polygon_set64 *paths, cg_rect64 rect, cg_polygon_set64 *cut)
{
    const side sides[4] = {{0, 1, rect.xmin},
                           {0, -1, rect.xmax},
                           {1, 1, rect.ymin},
                           {1, -1, rect.ymax}};
    point_array one = {0}, two = {0};
    cg_status st = CG_OK;
    for (size_t r = 0; r < paths->ring_count && st == CG_OK; r++) {
        size_t n = paths->ring_start[r + 1] - paths->ring_start[r];
        if (n < 3) /* also: no points at all, where paths->points may be NULL */
            continue;
        const cg_point64 *p = paths->points + paths->ring_start[r];
        cg_rect64 b;
        ring_bounds(p, n, &b);
        if (b.xmax < rect.xmin || b.xmin > rect.xmax || b.ymax < rect.ymin || b.ymin > rect.ymax)
            continue; /* it winds around no point of the rectangle */
        if (b.xmin >= rect.xmin && b.xmax <= rect.xmax && b.ymin >= rect.ymin
            && b.ymax <= rect.ymax) {
            st = cg_polygon_set64_add_ring(cut, p, n, 1);
            continue;
        }
        const cg_point64 *from = p;
        size_t count = n;
        point_array *to = &one;
        for (int k = 0; k < 4 && st == CG_OK && count >= 3; k++) {
            st = cut_ring(sides[k], from, count, to);
            from = to->data;
            count = to->count;
            to = to == &one ? &two : &one;
        }
        if (st == CG_OK && count >= 3)
            st = cg_polygon_set64_add_ring(cut, from, count, 1);
    }
    core_array_free(&one);
    core_array_free(&two);
    return st;
}

cg_status cg_rect_clip64_ws(cg_clip_workspace *ws, const cg_polygon_set64 *paths, cg_clip_fill fill,
                            cg_rect64 rect, cg_polygon_set64 *result)
{
    cg_status st = check_input(paths, rect, result);
    if (st != CG_OK)
        return st;
    if ((unsigned)fill > CG_CLIP_NEGATIVE)
        return CG_EINVAL;
    cg_polygon_set64 cut = {0}, none = {0};
    st = cut_rings(paths, rect, &cut);
    if (st == CG_OK)
        st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, &cut, fill, &none, fill, result);
    cg_polygon_set64_clear(&cut);
    return st;
}

cg_status cg_rect_clip64(const cg_polygon_set64 *paths, cg_clip_fill fill, cg_rect64 rect,
                         cg_polygon_set64 *result)
{
    return cg_rect_clip64_ws(NULL, paths, fill, rect, result);
}

/* ---- polylines -------------------------------------------------------------- */

static cg_point64 along(cg_point64 a, cg_point64 b, double t, cg_rect64 rect)
{
    double x = nearbyint((double)a.x + t * (double)(b.x - a.x));
    double y = nearbyint((double)a.y + t * (double)(b.y - a.y));
    /* the rounding keeps the point on the rectangle */
    x = fmin(fmax(x, (double)rect.xmin), (double)rect.xmax);
    y = fmin(fmax(y, (double)rect.ymin), (double)rect.ymax);
    return (cg_point64){(int64_t)x, (int64_t)y};
}

/* The segment a-b cut by the rectangle (Liang-Barsky): 0 when nothing of it
 * is inside, else 1 with the parameters of its part inside. */
static int cut_segment(cg_point64 a, cg_point64 b, cg_rect64 rect, double *t0, double *t1)
{
    double dx = (double)(b.x - a.x), dy = (double)(b.y - a.y);
    double p[4] = {-dx, dx, -dy, dy};
    double q[4] = {(double)(a.x - rect.xmin), (double)(rect.xmax - a.x), (double)(a.y - rect.ymin),
                   (double)(rect.ymax - a.y)};
    *t0 = 0;
    *t1 = 1;
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0) {
            if (q[k] < 0)
                return 0;
        } else if (p[k] < 0) {
            *t0 = fmax(*t0, q[k] / p[k]);
        } else {
            *t1 = fmin(*t1, q[k] / p[k]);
        }
    }
    return *t0 <= *t1;
}

/* Which sides of the rectangle p lies beyond (Cohen-Sutherland's code). */
static unsigned outcode(cg_point64 p, cg_rect64 rect)
{
    return (unsigned)(p.x < rect.xmin) | (unsigned)(p.x > rect.xmax) << 1
           | (unsigned)(p.y < rect.ymin) << 2 | (unsigned)(p.y > rect.ymax) << 3;
}

static cg_status clip_polyline(polygon_pieces *out, const cg_point64 *p, size_t n, cg_rect64 rect)
{
    cg_status st = CG_OK;
    if (n == 1 && p[0].x >= rect.xmin && p[0].x <= rect.xmax && p[0].y >= rect.ymin
        && p[0].y <= rect.ymax)
        st = polygon_piece_add(out, p[0]);
    unsigned code = n > 0 ? outcode(p[0], rect) : 0;
    for (size_t i = 0; i + 1 < n && st == CG_OK; i++) {
        double t0 = 0, t1 = 1;
        unsigned next = outcode(p[i + 1], rect), both = code | next, beyond = code & next;
        code = next;
        /* both ends beyond one side: nothing inside; both inside: all of it */
        if (beyond || (both && !cut_segment(p[i], p[i + 1], rect, &t0, &t1))) {
            st = polygon_piece_end(out, 1);
            continue;
        }
        if (t0 > 0)
            st = polygon_piece_end(out, 1); /* it comes (back) in here */
        if (st == CG_OK)
            st = polygon_piece_add(out, t0 > 0 ? along(p[i], p[i + 1], t0, rect) : p[i]);
        if (st == CG_OK)
            st = polygon_piece_add(out, t1 < 1 ? along(p[i], p[i + 1], t1, rect) : p[i + 1]);
        if (st == CG_OK && t1 < 1)
            st = polygon_piece_end(out, 1); /* and leaves */
    }
    return st == CG_OK ? polygon_piece_end(out, 1) : st;
}

cg_status cg_rect_clip_lines64(const cg_polygon_set64 *paths, cg_rect64 rect,
                               cg_polygon_set64 *result)
{
    cg_status st = check_input(paths, rect, result);
    if (st != CG_OK)
        return st;
    cg_polygon_set64 own = {0};
    polygon_pieces out = {&own, {0}};
    for (size_t r = 0; r < paths->ring_count && st == CG_OK; r++) {
        size_t n = paths->ring_start[r + 1] - paths->ring_start[r];
        if (n > 0) /* paths->points may be NULL when no path has points */
            st = clip_polyline(&out, paths->points + paths->ring_start[r], n, rect);
    }
    core_array_free(&out.open);
    if (st == CG_OK) {
        cg_polygon_set64_clear(result);
        *result = own;
    } else {
        cg_polygon_set64_clear(&own);
    }
    return st;
}

/* ---- the double API ------------------------------------------------------------ */

static cg_status rect_to_grid(cg_rect rect, polygon_grid grid, cg_rect64 *out)
{
    double v[4] = {rect.xmin, rect.ymin, rect.xmax, rect.ymax};
    int64_t g[4];
    for (int k = 0; k < 4; k++) {
        if (!isfinite(v[k]))
            return CG_EINVAL;
        double x = nearbyint(polygon_grid_to(grid, v[k]));
        if (!(fabs(x) <= (double)CG_CLIP_MAX_COORD))
            return CG_ERANGE;
        g[k] = (int64_t)x;
    }
    *out = (cg_rect64){g[0], g[1], g[2], g[3]};
    return CG_OK;
}

/* The grid for paths and rect, both converted to it. */
static cg_status to_grid(const cg_polygon_set *paths, cg_rect rect, double scale,
                         polygon_grid *grid, cg_polygon_set64 *in, cg_rect64 *rect64)
{
    if (!paths || !(rect.xmin <= rect.xmax) || !(rect.ymin <= rect.ymax))
        return CG_EINVAL;
    double largest = polygon_max_abs(paths);
    double r = fmax(fmax(fabs(rect.xmin), fabs(rect.xmax)), fmax(fabs(rect.ymin), fabs(rect.ymax)));
    cg_status st = polygon_grid_pick(scale, fmax(largest, r), grid);
    if (st == CG_OK)
        st = rect_to_grid(rect, *grid, rect64);
    if (st == CG_OK)
        st = polygon_set_to_grid(paths, *grid, in);
    return st;
}

/* The double entry points: paths and rect on the grid, clipped there as
 * polygons (with fill, and ws) or as lines, and the result back. */
static cg_status clip_on_grid(cg_clip_workspace *ws, const cg_polygon_set *paths, int lines,
                              cg_clip_fill fill, cg_rect rect, double scale, cg_polygon_set *result)
{
    if (!result)
        return CG_EINVAL;
    polygon_grid grid;
    cg_polygon_set64 in = {0}, out = {0};
    cg_rect64 r;
    cg_status st = to_grid(paths, rect, scale, &grid, &in, &r);
    if (st == CG_OK)
        st = lines ? cg_rect_clip_lines64(&in, r, &out) : cg_rect_clip64_ws(ws, &in, fill, r, &out);
    if (st == CG_OK)
        st = polygon_set_from_grid(&out, grid, result);
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
    return st;
}

cg_status cg_rect_clip_ws(cg_clip_workspace *ws, const cg_polygon_set *paths, cg_clip_fill fill,
                          cg_rect rect, double scale, cg_polygon_set *result)
{
    return clip_on_grid(ws, paths, 0, fill, rect, scale, result);
}

cg_status cg_rect_clip(const cg_polygon_set *paths, cg_clip_fill fill, cg_rect rect, double scale,
                       cg_polygon_set *result)
{
    return cg_rect_clip_ws(NULL, paths, fill, rect, scale, result);
}

cg_status cg_rect_clip_lines(const cg_polygon_set *paths, cg_rect rect, double scale,
                             cg_polygon_set *result)
{
    return clip_on_grid(NULL, paths, 1, CG_CLIP_EVEN_ODD, rect, scale, result);
}
