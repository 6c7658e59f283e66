/* Simplification of polygons and polylines with their topology kept.
 *
 * Removing a stretch of a path between a and b and joining a-b directly is
 * safe when no other vertex lies in the region between the stretch and
 * a-b (nor on its boundary): an edge crossing a-b would have to enter that
 * region, and it cannot cross the stretch (the paths are simple), so one of
 * its ends would lie inside.  For Visvalingam-Whyatt the region is the
 * triangle of a vertex and its neighbours; for Ramer-Douglas-Peucker the
 * polygon of the whole stretch.  A uniform grid of the vertices finds the
 * candidates; removed vertices no longer count.
 *
 *          v                        stretch a ... b
 *         / \         a-b kept          ____
 *        /   \        only if no       /    \__
 *       a-----b       vertex in here  a--------b
 */
#include "polygon_internal.h"

#include "../core/array.h"

#include <math.h>
#include <stdlib.h>

typedef struct simplifier {
    const cg_point64 *points;
    size_t count;
    uint8_t *alive;
    size_t *next, *prev;  /* along each path (closed ones cyclic) */
    size_t *stamp, token; /* stamp[v] == token: v is inside the stretch checked */
    /* the grid: cell c holds vertices cell_items[cell_start[c] .. cell_start[c + 1]) */
    size_t *cell_start, *cell_items;
    int64_t x0, y0;
    double cell_size;
    size_t columns, rows;
} simplifier;

static size_t cell_column(const simplifier *s, int64_t x)
{
    double c = floor((double)(x - s->x0) / s->cell_size);
    return c < 0 ? 0 : c >= (double)s->columns ? s->columns - 1 : (size_t)c;
}

static size_t cell_row(const simplifier *s, int64_t y)
{
    double r = floor((double)(y - s->y0) / s->cell_size);
    return r < 0 ? 0 : r >= (double)s->rows ? s->rows - 1 : (size_t)r;
}

static cg_status build_grid(simplifier *s)
{
    int64_t x1 = INT64_MIN, y1 = INT64_MIN;
    s->x0 = s->y0 = INT64_MAX;
    for (size_t i = 0; i < s->count; i++) {
        cg_point64 p = s->points[i];
        s->x0 = p.x < s->x0 ? p.x : s->x0;
        s->y0 = p.y < s->y0 ? p.y : s->y0;
        x1 = p.x > x1 ? p.x : x1;
        y1 = p.y > y1 ? p.y : y1;
    }
    double w = (double)(x1 - s->x0) + 1, h = (double)(y1 - s->y0) + 1;
    s->cell_size = fmax(sqrt(w * h / (double)(s->count + 1)), 1);
    s->columns = (size_t)fmin(ceil(w / s->cell_size), 4096) + 1;
    s->rows = (size_t)fmin(ceil(h / s->cell_size), 4096) + 1;
    s->cell_size = fmax(w / (double)(s->columns - 1), h / (double)(s->rows - 1));
    size_t cells = s->columns * s->rows;
    s->cell_start = calloc(cells + 1, sizeof *s->cell_start);
    s->cell_items = malloc((s->count + 1) * sizeof *s->cell_items);
    if (!s->cell_start || !s->cell_items)
        return CG_ENOMEM;
    for (size_t i = 0; i < s->count; i++)
        s->cell_start[cell_row(s, s->points[i].y) * s->columns + cell_column(s, s->points[i].x)
                      + 1]++;
    for (size_t c = 0; c < cells; c++)
        s->cell_start[c + 1] += s->cell_start[c];
    size_t *fill = malloc((cells + 1) * sizeof *fill);
    if (!fill)
        return CG_ENOMEM;
    for (size_t c = 0; c <= cells; c++)
        fill[c] = s->cell_start[c];
    for (size_t i = 0; i < s->count; i++)
        s->cell_items[fill[cell_row(s, s->points[i].y) * s->columns
                           + cell_column(s, s->points[i].x)]++] = i;
    free(fill);
    return CG_OK;
}

static int same(cg_point64 a, cg_point64 b)
{
    return a.x == b.x && a.y == b.y;
}

/* 1 when the edge from `from` to w leaves along the direction of from-to. */
static int runs_along(cg_point64 from, cg_point64 to, cg_point64 w)
{
    polygon_i128 dot = (polygon_i128)(w.x - from.x) * (to.x - from.x)
                       + (polygon_i128)(w.y - from.y) * (to.y - from.y);
    return polygon_orient(from, to, w) == 0 && dot > 0;
}

/* 1 when q lies in the closed triangle a, v, b (either orientation). */
static int in_triangle(cg_point64 a, cg_point64 v, cg_point64 b, cg_point64 q)
{
    int o = polygon_orient(a, v, b);
    int s1 = polygon_orient(a, v, q) * o, s2 = polygon_orient(v, b, q) * o;
    int s3 = polygon_orient(b, a, q) * o;
    return s1 >= 0 && s2 >= 0 && s3 >= 0;
}

/* One edge p -> r of a winding-number count about q: 1 when q lies on
 * the edge, else 0 with *winding moved by an upward (+1) or downward (-1)
 * crossing of q's row with q on its left. */
static int winding_edge(cg_point64 p, cg_point64 r, cg_point64 q, int *winding)
{
    if (polygon_orient(p, r, q) == 0 && (q.x - p.x) * (q.x - r.x) <= 0
        && (q.y - p.y) * (q.y - r.y) <= 0)
        return 1;
    if (p.y <= q.y && r.y > q.y && polygon_orient(p, r, q) > 0)
        (*winding)++;
    else if (p.y > q.y && r.y <= q.y && polygon_orient(p, r, q) < 0)
        (*winding)--;
    return 0;
}

/* 1 when q lies in or on the polygon of the stretch from a along the path
 * to b, closed by b-a (winding number, boundary included). */
static int in_stretch(const simplifier *s, size_t a, size_t b, cg_point64 q)
{
    int winding = 0;
    for (size_t i = a; i != b; i = s->next[i])
        if (winding_edge(s->points[i], s->points[s->next[i]], q, &winding))
            return 1;
    if (winding_edge(s->points[b], s->points[a], q, &winding))
        return 1;
    return winding != 0;
}

/* 1 when replacing the stretch a ... b (the vertices strictly between
 * them: from a's next on) by a-b leaves every other live vertex outside
 * the region between them. */
static int shortcut_is_safe(simplifier *s, size_t a, size_t b)
{
    cg_point64 pa = s->points[a], pb = s->points[b];
    int64_t x0 = pa.x < pb.x ? pa.x : pb.x, x1 = pa.x > pb.x ? pa.x : pb.x;
    int64_t y0 = pa.y < pb.y ? pa.y : pb.y, y1 = pa.y > pb.y ? pa.y : pb.y;
    int triangle = s->next[s->next[a]] == b;
    s->token++;
    for (size_t i = s->next[a]; i != b; i = s->next[i]) {
        s->stamp[i] = s->token;
        x0 = s->points[i].x < x0 ? s->points[i].x : x0;
        x1 = s->points[i].x > x1 ? s->points[i].x : x1;
        y0 = s->points[i].y < y0 ? s->points[i].y : y0;
        y1 = s->points[i].y > y1 ? s->points[i].y : y1;
    }
    size_t c0 = cell_column(s, x0), c1 = cell_column(s, x1);
    for (size_t row = cell_row(s, y0); row <= cell_row(s, y1); row++)
        for (size_t c = c0; c <= c1; c++) {
            size_t cell = row * s->columns + c;
            for (size_t k = s->cell_start[cell]; k < s->cell_start[cell + 1]; k++) {
                size_t q = s->cell_items[k];
                cg_point64 pq = s->points[q];
                /* the stretch's own vertices are in it by definition */
                if (!s->alive[q] || q == a || q == b || s->stamp[q] == s->token || pq.x < x0
                    || pq.x > x1 || pq.y < y0 || pq.y > y1)
                    continue;
                if (same(pq, pa) || same(pq, pb)) {
                    /* a path touching at a or b: its edges from there end
                     * inside (found as vertices), or run along a-b, which
                     * would then lie on them */
                    cg_point64 from = same(pq, pa) ? pa : pb, to = same(pq, pa) ? pb : pa;
                    if (runs_along(from, to, s->points[s->next[q]])
                        || runs_along(from, to, s->points[s->prev[q]]))
                        return 0;
                    continue;
                }
                if (triangle ? in_triangle(pa, s->points[s->next[a]], pb, pq)
                             : in_stretch(s, a, b, pq))
                    return 0;
            }
        }
    return 1;
}

/* ---- Ramer-Douglas-Peucker ------------------------------------------------------ */

static double distance_to_line(cg_point64 a, cg_point64 b, cg_point64 q)
{
    double dx = (double)(b.x - a.x), dy = (double)(b.y - a.y), l = hypot(dx, dy);
    if (l == 0)
        return hypot((double)(q.x - a.x), (double)(q.y - a.y));
    return fabs(dx * (double)(q.y - a.y) - dy * (double)(q.x - a.x)) / l;
}

/* Simplifies the stretch a ... b (an explicit stack instead of recursion). */
static cg_status rdp_stretch(simplifier *s, size_t a, size_t b, double tolerance)
{
    CORE_ARRAY(size_t) stack = {0};
    cg_status st = core_array_push(&stack, a);
    if (st == CG_OK)
        st = core_array_push(&stack, b);
    while (st == CG_OK && stack.count >= 2) {
        size_t to = stack.data[--stack.count], from = stack.data[--stack.count];
        if (s->next[from] == to)
            continue;
        size_t far = s->next[from];
        double best = -1;
        for (size_t i = s->next[from]; i != to; i = s->next[i]) {
            double dist = distance_to_line(s->points[from], s->points[to], s->points[i]);
            if (dist > best) {
                best = dist;
                far = i;
            }
        }
        if (best <= tolerance && shortcut_is_safe(s, from, to)) {
            for (size_t i = s->next[from]; i != to; i = s->next[i])
                s->alive[i] = 0;
            s->next[from] = to;
            s->prev[to] = from;
            continue;
        }
        st = core_array_push(&stack, from);
        if (st == CG_OK)
            st = core_array_push(&stack, far);
        if (st == CG_OK)
            st = core_array_push(&stack, far);
        if (st == CG_OK)
            st = core_array_push(&stack, to);
    }
    core_array_free(&stack);
    return st;
}

/* A ring through three anchors (its first vertex, the farthest from it,
 * and the farthest from their line), so that it keeps three vertices; an
 * open path between its ends. */
static cg_status rdp_path(simplifier *s, size_t first, size_t n, int closed, double tolerance)
{
    if (!closed)
        return n > 2 ? rdp_stretch(s, first, first + n - 1, tolerance) : CG_OK;
    if (n <= 3)
        return CG_OK;
    size_t f = first, g = first;
    double best = -1;
    for (size_t i = first; i < first + n; i++) {
        double d = hypot((double)(s->points[i].x - s->points[first].x),
                         (double)(s->points[i].y - s->points[first].y));
        if (d > best) {
            best = d;
            f = i;
        }
    }
    best = -1;
    for (size_t i = first; i < first + n; i++) {
        double d = distance_to_line(s->points[first], s->points[f], s->points[i]);
        if (d > best && i != first && i != f) {
            best = d;
            g = i;
        }
    }
    size_t anchors[3] = {first, f < g ? f : g, f < g ? g : f};
    cg_status st = CG_OK;
    for (int k = 0; k < 3 && st == CG_OK; k++)
        st = rdp_stretch(s, anchors[k], anchors[(k + 1) % 3], tolerance);
    return st;
}

/* ---- Visvalingam-Whyatt ------------------------------------------------------------ */

typedef struct candidate {
    double area;
    size_t vertex, version;
} candidate;
typedef CORE_ARRAY(candidate) heap;

static int heap_less(const candidate *a, const candidate *b)
{
    return a->area < b->area;
}

static cg_status heap_push(heap *h, candidate c)
{
    if (core_array_push(h, c) != CG_OK)
        return CG_ENOMEM;
    for (size_t i = h->count - 1; i > 0;) {
        size_t parent = (i - 1) / 2;
        if (!heap_less(&h->data[i], &h->data[parent]))
            break;
        candidate t = h->data[i];
        h->data[i] = h->data[parent];
        h->data[parent] = t;
        i = parent;
    }
    return CG_OK;
}

static candidate heap_pop(heap *h)
{
    candidate top = h->data[0];
    h->data[0] = h->data[--h->count];
    for (size_t i = 0;;) {
        size_t l = 2 * i + 1, r = l + 1, m = i;
        if (l < h->count && heap_less(&h->data[l], &h->data[m]))
            m = l;
        if (r < h->count && heap_less(&h->data[r], &h->data[m]))
            m = r;
        if (m == i)
            break;
        candidate t = h->data[i];
        h->data[i] = h->data[m];
        h->data[m] = t;
        i = m;
    }
    return top;
}

static double triangle_area(const simplifier *s, size_t v)
{
    cg_point64 a = s->points[s->prev[v]], b = s->points[v], c = s->points[s->next[v]];
    return fabs((double)polygon_ring_twice_area((cg_point64[]){a, b, c}, 3)) / 2;
}

/* Removes, smallest first, the vertices of every path whose triangle is
 * below the tolerance; ends of open paths stay, rings keep three. */
static cg_status visvalingam(simplifier *s, const size_t *path_of, size_t *path_size,
                             const uint8_t *movable, int open, double tolerance)
{
    heap h = {0};
    size_t *version = calloc(s->count + 1, sizeof *version);
    cg_status st = version ? CG_OK : CG_ENOMEM;
    for (size_t v = 0; v < s->count && st == CG_OK; v++)
        if (movable[v])
            st = heap_push(&h, (candidate){triangle_area(s, v), v, 0});
    while (st == CG_OK && h.count > 0) {
        candidate c = heap_pop(&h);
        size_t v = c.vertex;
        if (!s->alive[v] || c.version != version[v])
            continue;
        if (c.area >= tolerance)
            break;
        if (!open && path_size[path_of[v]] <= 3)
            continue; /* a ring keeps three vertices */
        size_t a = s->prev[v], b = s->next[v];
        if (!shortcut_is_safe(s, a, b))
            continue; /* tried again when a neighbour goes */
        s->alive[v] = 0;
        s->next[a] = b;
        s->prev[b] = a;
        path_size[path_of[v]]--;
        if (movable[a]
            && (st = heap_push(&h, (candidate){triangle_area(s, a), a, ++version[a]})) != CG_OK)
            break;
        if (movable[b])
            st = heap_push(&h, (candidate){triangle_area(s, b), b, ++version[b]});
    }
    free(version);
    core_array_free(&h);
    return st;
}

/* ---- the operation ------------------------------------------------------------------- */

static cg_status simplify_paths(const cg_polygon_set64 *in, int open,
                                cg_simplify_algorithm algorithm, double tolerance,
                                cg_polygon_set64 *out)
{
    if (in->point_count == 0)
        return CG_OK;
    simplifier s = {in->points, in->point_count, NULL, NULL, NULL, NULL, 0, NULL, NULL, 0, 0, 0, 0,
                    0};
    size_t n = in->point_count, rings = in->ring_count;
    s.alive = malloc(n + 1);
    s.next = malloc((n + 1) * sizeof *s.next);
    s.prev = malloc((n + 1) * sizeof *s.prev);
    size_t *path_of = malloc((n + 1) * sizeof *path_of), *size = malloc((rings + 1) * sizeof *size);
    uint8_t *movable = malloc(n + 1);
    s.stamp = calloc(n + 1, sizeof *s.stamp);
    cg_status st = s.alive && s.next && s.prev && path_of && size && movable && s.stamp
                       ? build_grid(&s)
                       : CG_ENOMEM;
    for (size_t r = 0; r < rings && st == CG_OK; r++) {
        size_t a = in->ring_start[r], b = in->ring_start[r + 1];
        size[r] = b - a;
        for (size_t i = a; i < b; i++) {
            s.alive[i] = 1;
            path_of[i] = r;
            s.next[i] = i + 1 < b ? i + 1 : a;
            s.prev[i] = i > a ? i - 1 : b - 1;
            movable[i] = open ? i > a && i + 1 < b : b - a > 3;
        }
    }
    for (size_t r = 0; r < rings && st == CG_OK && algorithm == CG_SIMPLIFY_RDP; r++)
        st = rdp_path(&s, in->ring_start[r], in->ring_start[r + 1] - in->ring_start[r], !open,
                      tolerance);
    if (st == CG_OK && algorithm == CG_SIMPLIFY_VISVALINGAM)
        st = visvalingam(&s, path_of, size, movable, open, tolerance);
    CORE_ARRAY(cg_point64) ring = {0};
    for (size_t r = 0; r < rings && st == CG_OK; r++) {
        ring.count = 0;
        for (size_t i = in->ring_start[r]; i < in->ring_start[r + 1] && st == CG_OK; i++)
            if (s.alive[i])
                st = core_array_push(&ring, in->points[i]);
        if (st == CG_OK && ring.count > 0)
            st = cg_polygon_set64_add_ring(out, ring.data, ring.count, 1);
    }
    core_array_free(&ring);
    free(s.alive);
    free(s.next);
    free(s.prev);
    free(s.stamp);
    free(s.cell_start);
    free(s.cell_items);
    free(path_of);
    free(size);
    free(movable);
    return st;
}

cg_status cg_simplify64(const cg_polygon_set64 *paths, int open, cg_clip_fill fill,
                        cg_simplify_algorithm algorithm, double tolerance, cg_polygon_set64 *result)
{
    if (!paths || !result || !(tolerance >= 0) || isinf(tolerance)
        || (unsigned)algorithm > CG_SIMPLIFY_VISVALINGAM || (unsigned)fill > CG_CLIP_NEGATIVE)
        return CG_EINVAL;
    cg_status st = polygon_set64_check_range(paths);
    if (st != CG_OK)
        return st;
    cg_polygon_set64 simple = {0}, none = {0}, kept = {0};
    if (!open)
        st = cg_clip_boolean64(CG_CLIP_UNION, paths, fill, &none, fill, &simple);
    if (st == CG_OK)
        st = simplify_paths(open ? paths : &simple, open, algorithm, tolerance, &kept);
    if (st == CG_OK && !open)
        st = cg_clip_boolean64(CG_CLIP_UNION, &kept, CG_CLIP_NON_ZERO, &none, CG_CLIP_NON_ZERO,
                               result);
    if (st == CG_OK && open) {
        cg_polygon_set64_clear(result);
        *result = kept;
        kept = (cg_polygon_set64){0};
    }
    cg_polygon_set64_clear(&simple);
    cg_polygon_set64_clear(&kept);
    return st;
}

cg_status cg_simplify(const cg_polygon_set *paths, int open, cg_clip_fill fill,
                      cg_simplify_algorithm algorithm, double tolerance, double scale,
                      cg_polygon_set *result)
{
    if (!paths || !result || !(tolerance >= 0) || isinf(tolerance))
        return CG_EINVAL;
    polygon_grid grid;
    cg_polygon_set64 in = {0}, out = {0};
    cg_status st = polygon_grid_pick(scale, polygon_max_abs(paths), &grid);
    /* a distance scales with the grid, an area with its square */
    double t = polygon_grid_to(grid, tolerance);
    if (algorithm == CG_SIMPLIFY_VISVALINGAM)
        t = polygon_grid_to(grid, t);
    if (st == CG_OK)
        st = polygon_set_to_grid(paths, grid, &in);
    if (st == CG_OK)
        st = cg_simplify64(&in, open, fill, algorithm, t, &out);
    if (st == CG_OK)
        st = polygon_set_from_grid(&out, grid, result);
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
    return st;
}
