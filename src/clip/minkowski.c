/* Minkowski sums of a pattern polygon with a path or a polygon.
 *
 * For a connected pattern A (one polygon of the pattern's union, with its
 * holes) and a path B, A + B is swept by A moving along B.  Along one edge
 * e0-e1 of B, a point x of the sweep has x - e(t) in A for some t: either
 * at an end (x in A + e0 or A + e1), or x - e(t) crosses A's boundary on
 * the way, at some edge a_i-a_{i+1}, and x lies in the parallelogram that
 * edge sweeps:
 *
 *        a_{i+1}+e0 ------- a_{i+1}+e1
 *           /                  /
 *      a_i+e0 ------------ a_i+e1
 *
 * So the sum is the union of the pattern translated to every vertex of the
 * path and of the parallelogram of every pattern edge along every path
 * edge; for a polygon B (a region), also B + a for one point a of each
 * pattern polygon (a point of B's interior reached from a is either in
 * B + a, or the way crosses B's boundary).  Each piece covers its points
 * with winding number 1 (the parallelograms are turned counter-clockwise,
 * a translated polygon keeps its holes), so their union under the non-zero
 * rule gives the sum (united in parts, see unite_tree).  The difference is
 * the sum with the pattern reflected through the origin (every path point
 * less every pattern point). */
#include "polygon_internal.h"

#include <math.h>
#include <stdlib.h>

static cg_status add_translated(cg_polygon_set64 *out, const cg_polygon_set64 *s, int64_t dx,
                                int64_t dy, cg_point64 *scratch, size_t capacity)
{
    cg_status st = CG_OK;
    for (size_t r = 0; r < s->ring_count && st == CG_OK; r++) {
        size_t a = s->ring_start[r], n = s->ring_start[r + 1] - a;
        if (n > capacity)
            return CG_EINVAL;
        for (size_t i = 0; i < n; i++)
            scratch[i] = (cg_point64){s->points[a + i].x + dx, s->points[a + i].y + dy};
        st = cg_polygon_set64_add_ring(out, scratch, n, 1);
    }
    return st;
}

/* The parallelograms of every pattern edge along the path edge e0-e1. */
static cg_status add_swept(cg_polygon_set64 *out, const cg_polygon_set64 *pattern, cg_point64 e0,
                           cg_point64 e1)
{
    cg_status st = CG_OK;
    for (size_t r = 0; r < pattern->ring_count && st == CG_OK; r++) {
        size_t a = pattern->ring_start[r], b = pattern->ring_start[r + 1];
        for (size_t i = a; i < b && st == CG_OK; i++) {
            cg_point64 p = pattern->points[i], q = pattern->points[i + 1 < b ? i + 1 : a];
            cg_point64 quad[4] = {{p.x + e0.x, p.y + e0.y},
                                  {p.x + e1.x, p.y + e1.y},
                                  {q.x + e1.x, q.y + e1.y},
                                  {q.x + e0.x, q.y + e0.y}};
            polygon_i128 area = polygon_ring_twice_area(quad, 4);
            if (area == 0)
                continue;
            if (area < 0) {
                cg_point64 t = quad[1];
                quad[1] = quad[3];
                quad[3] = t;
            }
            st = cg_polygon_set64_add_ring(out, quad, 4, 1);
        }
    }
    return st;
}

typedef CORE_ARRAY(cg_polygon_set64) polygon_set_list;

static void free_sets(polygon_set_list *sets)
{
    for (size_t i = 0; i < sets->count; i++)
        cg_polygon_set64_clear(&sets->data[i]);
    core_array_free(sets);
}

/* Appends the union (non-zero rule) of *pieces to sets; *pieces is emptied. */
static cg_status push_union(cg_clip_workspace *ws, cg_polygon_set64 *pieces, polygon_set_list *sets)
{
    cg_polygon_set64 none = {0}, merged = {0};
    cg_status st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, pieces, CG_CLIP_NON_ZERO, &none,
                                        CG_CLIP_NON_ZERO, &merged);
    if (st == CG_OK && merged.ring_count > 0)
        st = core_array_push(sets, merged);
    if (st != CG_OK || merged.ring_count == 0)
        cg_polygon_set64_clear(&merged);
    cg_polygon_set64_clear(pieces);
    return st;
}

/* The pieces of pattern (simple, one polygon after another) + path, each
 * path vertex's pieces (the pattern there and swept along the edge that
 * follows) already united into one set of `sets`. */
static cg_status add_pieces(cg_clip_workspace *ws, polygon_set_list *sets,
                            const cg_polygon_set64 *pattern, const cg_polygon_set64 *path, int open,
                            const cg_polygon_set64 *region)
{
    size_t capacity = pattern->point_count > region->point_count ? pattern->point_count
                                                                 : region->point_count;
    cg_point64 *scratch = capacity ? malloc(capacity * sizeof *scratch) : NULL;
    if (capacity && !scratch)
        return CG_ENOMEM;
    cg_polygon_set64 pieces = {0};
    cg_status st = CG_OK;
    for (size_t r = 0; r < path->ring_count && st == CG_OK; r++) {
        size_t a = path->ring_start[r], b = path->ring_start[r + 1];
        for (size_t i = a; i < b && st == CG_OK; i++) {
            cg_point64 e0 = path->points[i];
            st = add_translated(&pieces, pattern, e0.x, e0.y, scratch, capacity);
            if (i + 1 < b || (!open && b - a > 1))
                if (st == CG_OK)
                    st = add_swept(&pieces, pattern, e0, path->points[i + 1 < b ? i + 1 : a]);
            if (st == CG_OK)
                st = push_union(ws, &pieces, sets);
        }
    }
    /* a region: itself moved to a point of each pattern polygon */
    for (size_t k = 0; k < pattern->polygon_count && st == CG_OK && !open; k++) {
        cg_point64 p = pattern->points[pattern->ring_start[pattern->polygon_start[k]]];
        st = add_translated(&pieces, region, p.x, p.y, scratch, capacity);
        if (st == CG_OK)
            st = push_union(ws, &pieces, sets);
    }
    cg_polygon_set64_clear(&pieces);
    free(scratch);
    return st;
}

/* The union of every set into result, two at a time in a balanced tree.
 * One sweep over every piece at once would split every piece at every
 * crossing of every other (a 31-point pattern along a 70-point path makes
 * some 10^8 split points, most of them inside the sum); united in pairs,
 * the edges inside each part are gone before the next level sees them. */
static cg_status unite_tree(cg_clip_workspace *ws, polygon_set_list *sets, cg_polygon_set64 *result)
{
    cg_polygon_set64 none = {0};
    cg_status st = CG_OK;
    while (sets->count > 2 && st == CG_OK) {
        size_t kept = 0;
        for (size_t i = 0; i < sets->count && st == CG_OK; i += 2) {
            cg_polygon_set64 merged = {0};
            if (i + 1 < sets->count) {
                st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, &sets->data[i], CG_CLIP_NON_ZERO,
                                          &sets->data[i + 1], CG_CLIP_NON_ZERO, &merged);
                cg_polygon_set64_clear(&sets->data[i]);
                cg_polygon_set64_clear(&sets->data[i + 1]);
            } else {
                merged = sets->data[i];
                sets->data[i] = (cg_polygon_set64){0};
            }
            sets->data[kept++] = merged;
        }
        /* on failure every set stays in place for free_sets (the moved and
         * united ones are empty) */
        if (st == CG_OK)
            sets->count = kept;
    }
    if (st == CG_OK)
        st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, sets->count > 0 ? &sets->data[0] : &none,
                                  CG_CLIP_NON_ZERO, sets->count > 1 ? &sets->data[1] : &none,
                                  CG_CLIP_NON_ZERO, result);
    return st;
}

cg_status cg_minkowski64_ws(cg_clip_workspace *ws, cg_minkowski_op op,
                            const cg_polygon_set64 *pattern, const cg_polygon_set64 *path,
                            int path_open, cg_clip_fill fill, cg_polygon_set64 *result)
{
    if (!pattern || !path || !result || (unsigned)fill > CG_CLIP_NEGATIVE
        || (op != CG_MINKOWSKI_SUM && op != CG_MINKOWSKI_DIFFERENCE))
        return CG_EINVAL;
    int64_t a, b;
    cg_status st = polygon_set64_max_abs(pattern, &a);
    if (st == CG_OK)
        st = polygon_set64_max_abs(path, &b);
    if (st != CG_OK)
        return st;
    if (a > CG_CLIP_MAX_COORD || b > CG_CLIP_MAX_COORD || a + b > CG_CLIP_MAX_COORD)
        return CG_ERANGE;
    cg_polygon_set64 shape = {0}, region = {0}, none = {0};
    polygon_set_list sets = {0};
    st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, pattern, fill, &none, fill, &shape);
    for (size_t i = 0; i < shape.point_count && op == CG_MINKOWSKI_DIFFERENCE; i++)
        shape.points[i] = (cg_point64){-shape.points[i].x, -shape.points[i].y};
    /* reflected, the rings keep their orientation (a half turn) */
    if (st == CG_OK && !path_open)
        st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, path, fill, &none, fill, &region);
    if (st == CG_OK)
        st = add_pieces(ws, &sets, &shape, path_open ? path : &region, path_open, &region);
    if (st == CG_OK)
        st = unite_tree(ws, &sets, result);
    cg_polygon_set64_clear(&shape);
    cg_polygon_set64_clear(&region);
    free_sets(&sets);
    return st;
}

cg_status cg_minkowski64(cg_minkowski_op op, const cg_polygon_set64 *pattern,
                         const cg_polygon_set64 *path, int path_open, cg_clip_fill fill,
                         cg_polygon_set64 *result)
{
    return cg_minkowski64_ws(NULL, op, pattern, path, path_open, fill, result);
}

cg_status cg_minkowski_ws(cg_clip_workspace *ws, cg_minkowski_op op, const cg_polygon_set *pattern,
                          const cg_polygon_set *path, int path_open, cg_clip_fill fill,
                          double scale, cg_polygon_set *result)
{
    if (!pattern || !path || !result)
        return CG_EINVAL;
    double a = polygon_max_abs(pattern), b = polygon_max_abs(path);
    if (isnan(a) || isnan(b))
        return CG_EINVAL;
    polygon_grid grid;
    cg_polygon_set64 p = {0}, q = {0}, out = {0};
    cg_status st = polygon_grid_pick(scale, a + b, &grid);
    if (st == CG_OK)
        st = polygon_set_to_grid(pattern, grid, &p);
    if (st == CG_OK)
        st = polygon_set_to_grid(path, grid, &q);
    if (st == CG_OK)
        st = cg_minkowski64_ws(ws, op, &p, &q, path_open, fill, &out);
    if (st == CG_OK)
        st = polygon_set_from_grid(&out, grid, result);
    cg_polygon_set64_clear(&p);
    cg_polygon_set64_clear(&q);
    cg_polygon_set64_clear(&out);
    return st;
}

cg_status cg_minkowski(cg_minkowski_op op, const cg_polygon_set *pattern,
                       const cg_polygon_set *path, int path_open, cg_clip_fill fill, double scale,
                       cg_polygon_set *result)
{
    return cg_minkowski_ws(NULL, op, pattern, path, path_open, fill, scale, result);
}
