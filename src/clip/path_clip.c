/* Clipping open paths (polylines) against polygons: the pieces inside the
 * region (intersection) or outside it (difference), in order along each
 * path, decided exactly on the int64 grid.
 *
 * The clip rings are first made simple by a union, so that the region lies
 * on the left of every edge and on the right of none.  Each segment A-B of
 * a path is then split where it meets the boundary: where it crosses an
 * edge, passes through a vertex, or starts on one.  Between two split
 * points the segment meets no boundary, so the whole stretch is inside,
 * outside, or along an edge; which one is read at the split point that
 * starts it, from the boundary's rays there (the two halves of an edge
 * through the point, or each edge leaving and entering a vertex there):
 *
 *           ray out (inside just counter-clockwise of it)
 *             ^
 *             |  d        the stretch leaves the point in direction d; the
 *             | /         first ray clockwise from d decides: the region
 *             |/          lies just counter-clockwise of an edge's forward
 *     --------*------>    ray and not of a backward one
 *
 * (d along a ray: the stretch runs on the boundary).  A path's first point,
 * when on no edge, is placed by its winding number.  Split parameters are
 * ratios of 128-bit cross products, ordered exactly with 256-bit products;
 * a crossing inside an edge is rounded to the nearest grid point, a vertex
 * is kept exactly. */
#include "polygon_internal.h"

#include "../core/array.h"

#include <math.h>

/* Where the stretch that starts at a split point goes. */
enum { STRETCH_OUTSIDE, STRETCH_INSIDE, STRETCH_BOUNDARY };

/* A ray of the boundary from a split point: its direction and whether the
 * region lies just counter-clockwise of it. */
typedef struct ray {
    int64_t dx, dy;
    int inside_after;
} ray;

/* A split point on a segment at parameter num / den (0 <= num < den), with
 * the rays of the boundary feature met there (one vertex pass, or one edge
 * through its interior) and the point itself when it is a grid point. */
typedef struct split {
    polygon_i128 num, den;
    ray rays[2];
    int exact; /* at a vertex: point holds it */
    cg_point64 point;
} split;

typedef CORE_ARRAY(split) split_array;
typedef CORE_ARRAY(ray) ray_array;

/* The pieces being built, and whether one is open. */
typedef struct pieces {
    polygon_pieces built;
    int is_open;
} pieces;

static polygon_i128 cross(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
    return (polygon_i128)ax * by - (polygon_i128)ay * bx;
}

static polygon_i128 dot(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
    return (polygon_i128)ax * bx + (polygon_i128)ay * by;
}

/* Which half of the turn clockwise from d the ray r lies in: 0 for (0, pi),
 * 1 at pi, 2 for (pi, 2 pi); -1 when r points along d. */
static int clockwise_half(int64_t dx, int64_t dy, ray r)
{
    polygon_i128 c = cross(dx, dy, r.dx, r.dy);
    if (c < 0)
        return 0;
    if (c > 0)
        return 2;
    return dot(dx, dy, r.dx, r.dy) > 0 ? -1 : 1;
}

/* Where the stretch leaving a point in direction d goes, from the rays of
 * the boundary there (count > 0). */
static int stretch_from_rays(int64_t dx, int64_t dy, const ray *rays, size_t count)
{
    size_t best = 0;
    int best_half = 3;
    for (size_t i = 0; i < count; i++) {
        int h = clockwise_half(dx, dy, rays[i]);
        if (h < 0)
            return STRETCH_BOUNDARY;
        /* the nearer clockwise from d: a smaller half, or in the same half
         * one counter-clockwise of the other (the two at pi are parallel) */
        if (h < best_half
            || (h == best_half && h != 1
                && cross(rays[best].dx, rays[best].dy, rays[i].dx, rays[i].dy) > 0)) {
            best = i;
            best_half = h;
        }
    }
    return rays[best].inside_after ? STRETCH_INSIDE : STRETCH_OUTSIDE;
}

static int compare_splits(const split *a, const split *b)
{
    return polygon_compare_products(a->num, b->den, b->num, a->den);
}

/* Insertion sort of the few splits of a segment (most have none or two). */
static void sort_splits(split *s, size_t n)
{
    for (size_t i = 1; i < n; i++) {
        split key = s[i];
        size_t j = i;
        while (j > 0 && compare_splits(&s[j - 1], &key) > 0) {
            s[j] = s[j - 1];
            j--;
        }
        s[j] = key;
    }
}

/* The splits of the segment a-b (not a point) by the ring p[0..n). */
static cg_status ring_splits(cg_point64 a, cg_point64 b, const cg_point64 *p, size_t n,
                             split_array *out)
{
    int64_t dx = b.x - a.x, dy = b.y - a.y;
    int64_t xmin = a.x < b.x ? a.x : b.x, xmax = a.x < b.x ? b.x : a.x;
    int64_t ymin = a.y < b.y ? a.y : b.y, ymax = a.y < b.y ? b.y : a.y;
    polygon_i128 length2 = dot(dx, dy, dx, dy);
    for (size_t i = 0; i < n; i++) {
        cg_point64 u = p[i], v = p[i + 1 < n ? i + 1 : 0], w = p[i > 0 ? i - 1 : n - 1];
        if ((u.x < xmin && v.x < xmin) || (u.x > xmax && v.x > xmax) || (u.y < ymin && v.y < ymin)
            || (u.y > ymax && v.y > ymax))
            continue;
        int ou = polygon_orient(a, b, u), ov = polygon_orient(a, b, v);
        split s = {0};
        if (ou == 0) {
            /* the vertex u on the line: a split when within [a, b) */
            polygon_i128 t = dot(u.x - a.x, u.y - a.y, dx, dy);
            if (t >= 0 && t < length2) {
                s = (split){t,
                            length2,
                            {{v.x - u.x, v.y - u.y, 1}, {w.x - u.x, w.y - u.y, 0}},
                            1,
                            u};
                if (core_array_push(out, s) != CG_OK)
                    return CG_ENOMEM;
            }
            if (ov == 0) {
                /* collinear edge: a starting on its interior runs along it */
                polygon_i128 ta = dot(a.x - u.x, a.y - u.y, v.x - u.x, v.y - u.y);
                polygon_i128 te = dot(v.x - u.x, v.y - u.y, v.x - u.x, v.y - u.y);
                if (ta > 0 && ta < te) {
                    s = (split){0, 1, {{v.x - u.x, v.y - u.y, 1}, {u.x - v.x, u.y - v.y, 0}}, 1, a};
                    if (core_array_push(out, s) != CG_OK)
                        return CG_ENOMEM;
                }
            }
            continue;
        }
        if (ou * ov >= 0)
            continue; /* no crossing inside the edge (an end on the line is its own vertex) */
        int oa = polygon_orient(u, v, a), ob = polygon_orient(u, v, b);
        if (oa * ob > 0 || ob == 0)
            continue; /* the line crosses the edge outside the segment, or at b */
        polygon_i128 num = cross(u.x - a.x, u.y - a.y, v.x - u.x, v.y - u.y);
        polygon_i128 den = cross(dx, dy, v.x - u.x, v.y - u.y);
        if (den < 0) {
            num = -num;
            den = -den;
        }
        s = (split){num, den, {{v.x - u.x, v.y - u.y, 1}, {u.x - v.x, u.y - v.y, 0}}, oa == 0, a};
        if (core_array_push(out, s) != CG_OK)
            return CG_ENOMEM;
    }
    return CG_OK;
}

/* The point of a-b at a split, rounded to the grid unless it is one. */
static cg_point64 split_point(cg_point64 a, cg_point64 b, const split *s)
{
    if (s->exact)
        return s->point;
    return (cg_point64){a.x + polygon_divide_rounded(s->num * (b.x - a.x), s->den),
                        a.y + polygon_divide_rounded(s->num * (b.y - a.y), s->den)};
}

static cg_status piece_add(pieces *out, cg_point64 p)
{
    return polygon_piece_add(&out->built, p);
}

/* Ends the open piece (kept when it has two points or more). */
static cg_status piece_end(pieces *out)
{
    out->is_open = 0;
    return polygon_piece_end(&out->built, 2);
}

/* A boundary point p of the path after which the path goes `stretch`. */
static cg_status at_boundary(pieces *out, cg_clip_op op, cg_point64 p, int stretch)
{
    int keep = op == CG_CLIP_INTERSECTION ? stretch != STRETCH_OUTSIDE : stretch == STRETCH_OUTSIDE;
    cg_status st = CG_OK;
    /* the difference leaves out the boundary point; the intersection keeps
     * it and goes on when the path stays in */
    if (out->is_open && (!keep || op == CG_CLIP_DIFFERENCE)) {
        st = piece_add(out, p);
        if (st == CG_OK)
            st = piece_end(out);
    }
    if (st == CG_OK && keep && !out->is_open) {
        out->is_open = 1;
        st = piece_add(out, p);
    }
    return st;
}

/* Gathers the rays of the splits s[from..to) (one point) into rays. */
static cg_status group_rays(const split *s, size_t from, size_t to, ray_array *rays)
{
    rays->count = 0;
    for (size_t k = from; k < to; k++)
        for (int j = 0; j < 2; j++)
            if (core_array_push(rays, s[k].rays[j]) != CG_OK)
                return CG_ENOMEM;
    return CG_OK;
}

/* One path p[0..n) clipped into out. */
static cg_status clip_path(pieces *out, cg_clip_op op, const cg_polygon_set64 *region,
                           const cg_point64 *p, size_t n, split_array *splits, ray_array *rays)
{
    cg_status st = CG_OK;
    int started = 0;
    out->is_open = 0;
    out->built.open.count = 0;
    for (size_t i = 0; i + 1 < n && st == CG_OK; i++) {
        cg_point64 a = p[i], b = p[i + 1];
        if (a.x == b.x && a.y == b.y)
            continue;
        splits->count = 0;
        for (size_t r = 0; r < region->ring_count && st == CG_OK; r++)
            st = ring_splits(a, b, region->points + region->ring_start[r],
                             region->ring_start[r + 1] - region->ring_start[r], splits);
        if (st != CG_OK)
            break;
        sort_splits(splits->data, splits->count);
        if (!started && (splits->count == 0 || splits->data[0].num != 0)) {
            /* the path starts on no edge */
            if (polygon_winding_number(region, a) != 0 ? op == CG_CLIP_INTERSECTION
                                                       : op == CG_CLIP_DIFFERENCE) {
                out->is_open = 1;
                st = piece_add(out, a);
            }
        }
        started = 1;
        for (size_t k = 0; k < splits->count && st == CG_OK;) {
            size_t end = k + 1;
            while (end < splits->count && compare_splits(&splits->data[k], &splits->data[end]) == 0)
                end++;
            st = group_rays(splits->data, k, end, rays);
            if (st != CG_OK)
                break;
            int stretch = stretch_from_rays(b.x - a.x, b.y - a.y, rays->data, rays->count);
            /* a vertex among the group gives the exact point */
            const split *at = &splits->data[k];
            for (size_t j = k; j < end; j++)
                if (splits->data[j].exact)
                    at = &splits->data[j];
            st = at_boundary(out, op, split_point(a, b, at), stretch);
            k = end;
        }
        if (st == CG_OK && out->is_open)
            st = piece_add(out, b);
    }
    return st == CG_OK ? piece_end(out) : st;
}

cg_status cg_clip_lines64_ws(cg_clip_workspace *ws, cg_clip_op op, const cg_polygon_set64 *paths,
                             const cg_polygon_set64 *clip, cg_clip_fill clip_fill,
                             cg_polygon_set64 *result)
{
    if (!paths || !clip || !result || (op != CG_CLIP_INTERSECTION && op != CG_CLIP_DIFFERENCE)
        || (unsigned)clip_fill > CG_CLIP_NEGATIVE)
        return CG_EINVAL;
    int64_t largest;
    cg_status st = polygon_set64_max_abs(paths, &largest);
    if (st != CG_OK)
        return st;
    if (largest > CG_CLIP_MAX_COORD)
        return CG_ERANGE;
    cg_polygon_set64 region = {0}, none = {0}, own = {0};
    st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, clip, clip_fill, &none, clip_fill, &region);
    pieces out = {{&own, {0}}, 0};
    split_array splits = {0};
    ray_array rays = {0};
    for (size_t r = 0; r < paths->ring_count && st == CG_OK; r++) {
        size_t n = paths->ring_start[r + 1] - paths->ring_start[r];
        if (n > 0) /* paths->points may be NULL when no path has points */
            st = clip_path(&out, op, &region, paths->points + paths->ring_start[r], n, &splits,
                           &rays);
    }
    core_array_free(&out.built.open);
    core_array_free(&splits);
    core_array_free(&rays);
    cg_polygon_set64_clear(&region);
    if (st == CG_OK) {
        cg_polygon_set64_clear(result);
        *result = own;
    } else {
        cg_polygon_set64_clear(&own);
    }
    return st;
}

cg_status cg_clip_lines64(cg_clip_op op, const cg_polygon_set64 *paths,
                          const cg_polygon_set64 *clip, cg_clip_fill clip_fill,
                          cg_polygon_set64 *result)
{
    return cg_clip_lines64_ws(NULL, op, paths, clip, clip_fill, result);
}

/* ---- the double API ------------------------------------------------------------ */

cg_status cg_clip_lines_ws(cg_clip_workspace *ws, cg_clip_op op, const cg_polygon_set *paths,
                           const cg_polygon_set *clip, cg_clip_fill clip_fill, double scale,
                           cg_polygon_set *result)
{
    if (!paths || !clip || !result)
        return CG_EINVAL;
    polygon_grid grid;
    cg_polygon_set64 in = {0}, window = {0}, out = {0};
    double largest = polygon_max_abs(paths), clip_largest = polygon_max_abs(clip);
    if (isnan(largest) || isnan(clip_largest))
        return CG_EINVAL;
    cg_status st = polygon_grid_pick(scale, fmax(largest, clip_largest), &grid);
    if (st == CG_OK)
        st = polygon_set_to_grid(paths, grid, &in);
    if (st == CG_OK)
        st = polygon_set_to_grid(clip, grid, &window);
    if (st == CG_OK)
        st = cg_clip_lines64_ws(ws, op, &in, &window, clip_fill, &out);
    if (st == CG_OK)
        st = polygon_set_from_grid(&out, grid, result);
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&window);
    cg_polygon_set64_clear(&out);
    return st;
}

cg_status cg_clip_lines(cg_clip_op op, const cg_polygon_set *paths, const cg_polygon_set *clip,
                        cg_clip_fill clip_fill, double scale, cg_polygon_set *result)
{
    return cg_clip_lines_ws(NULL, op, paths, clip, clip_fill, scale, result);
}
