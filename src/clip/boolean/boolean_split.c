/* Splitting for the boolean operations: snap rounding to hot pixels, and
 * the replacement of every split edge by its pieces. */
#include "boolean_engine.h"
#include "../../core/sort.h"

static int cmp_along(const void *a, const void *b)
{
    const split_sort *p = a, *q = b;
    return before_along(p, q) ? -1 : before_along(q, p);
}

/* the split points of one edge in order along it: straight insertion up to
 * 64 or when they are nearly in order (long edges on coarse grids have
 * dozens; complete snap rounding gives them nearly sorted), else qsort (a
 * comparison through its pointer costs more) */
static inline void sort_along(split_sort *a, size_t n)
{
    if (n > 64) {
        size_t descents = 0;
        for (size_t i = 1; i < n; i++)
            descents += before_along(&a[i], &a[i - 1]);
        if (descents > n / 16) {
            core_sort(a, n, sizeof *a, cmp_along);
            return;
        }
    }
    for (size_t i = 1; i < n; i++) {
        split_sort v = a[i];
        size_t j = i;
        for (; j > 0 && before_along(&v, &a[j - 1]); j--)
            a[j] = a[j - 1];
        a[j] = v;
    }
}

/* Snap rounding (Hobby): every edge that passes through the pixel of a
 * rounded split point is split there too, so that nearly parallel edges
 * meet at one grid point instead of crossing again a little further on.
 * Used from the second pass on.  The points are put in a grid of square
 * cells (about two points a cell; sorted by y, then x, each point once, in
 * each cell), and each edge looks at the cells along it, row by row: the
 * cost follows the edges' lengths and the points near them, not the points
 * in their y range (dense crossings of long edges made that quadratic). */
typedef struct hot_grid {
    int64_t x_low, y_low, side;
    size_t cols, rows;
    size_t *start; /* the points of cell k: pts[start[k]..start[k + 1]) */
    cg_point64 *points;
} hot_grid;

static int cmp_point_yx(const void *a, const void *b)
{
    const cg_point64 *p = a, *q = b;
    if (p->y != q->y)
        return p->y < q->y ? -1 : 1;
    return (p->x > q->x) - (p->x < q->x);
}

static size_t hot_cell(const hot_grid *h, int64_t x, int64_t y)
{
    return (size_t)((y - h->y_low) / h->side) * h->cols + (size_t)((x - h->x_low) / h->side);
}

static int hot_grid_build(hot_grid *h, const split_point *S, size_t split_count)
{
    int64_t x1 = S[0].x, y1 = S[0].y;
    h->x_low = x1;
    h->y_low = y1;
    for (size_t k = 1; k < split_count; k++) {
        h->x_low = S[k].x < h->x_low ? S[k].x : h->x_low;
        h->y_low = S[k].y < h->y_low ? S[k].y : h->y_low;
        x1 = S[k].x > x1 ? S[k].x : x1;
        y1 = S[k].y > y1 ? S[k].y : y1;
    }
    double w = (double)(x1 - h->x_low) + 1, ht = (double)(y1 - h->y_low) + 1;
    double side = ceil(sqrt(w * ht * 2 / (double)split_count));
    for (;;) { /* at most about 4 cells a point, whatever the shape */
        double cols = floor((w - 1) / side) + 1, rows = floor((ht - 1) / side) + 1;
        if (cols * rows <= 4 * (double)split_count + 64)
            break;
        side = ceil(side * 1.5);
    }
    h->side = (int64_t)side;
    h->cols = (size_t)((x1 - h->x_low) / h->side) + 1;
    h->rows = (size_t)((y1 - h->y_low) / h->side) + 1;
    size_t cells = h->cols * h->rows;
    h->start = calloc(cells + 1, sizeof *h->start);
    h->points = malloc(split_count * sizeof *h->points);
    size_t *next = malloc((cells + 1) * sizeof *next);
    if (!h->start || !h->points || !next) {
        free(next);
        return 0;
    }
    for (size_t k = 0; k < split_count; k++)
        h->start[hot_cell(h, S[k].x, S[k].y) + 1]++;
    for (size_t c = 0; c < cells; c++)
        h->start[c + 1] += h->start[c];
    memcpy(next, h->start, (cells + 1) * sizeof *next);
    for (size_t k = 0; k < split_count; k++)
        h->points[next[hot_cell(h, S[k].x, S[k].y)]++] = (cg_point64){S[k].x, S[k].y};
    free(next);
    /* each cell's points in order, each point once (crossings give a point
     * per edge, and on coarse grids many round to one point) */
    size_t kept = 0;
    for (size_t c = 0; c < cells; c++) {
        size_t a = h->start[c], b = h->start[c + 1];
        if (b - a > 1)
            boolean_sort_few(h->points + a, b - a, sizeof *h->points, cmp_point_yx);
        h->start[c] = kept;
        for (size_t q = a; q < b; q++)
            if (q == a || h->points[q].x != h->points[q - 1].x
                || h->points[q].y != h->points[q - 1].y)
                h->points[kept++] = h->points[q];
    }
    h->start[cells] = kept;
    return 1;
}

/* (boolean_each_hot_point's add: the point appended to the array) */
static int append_point(void *ctx, int64_t x, int64_t y)
{
    split_point **at = ctx;
    *(*at)++ = (split_point){0, x, y};
    return 1;
}

split_point *boolean_complete_hot_points(const engine *g, size_t *n)
{
    split_point *pts = malloc(boolean_hot_point_count(g) * sizeof *pts), *at = pts;
    if (!pts)
        return NULL;
    boolean_each_hot_point(g, append_point, &at);
    *n = (size_t)(at - pts);
    return pts;
}

/* Snap rounding to the hot pixels (see hot_grid; complete, with the edges'
 * ends and run breaks too, when `vertices`): 0 when out of memory. */
int boolean_add_hot_pixel_splits(engine *g, int vertices)
{
    size_t split_count = g->split_count;
    if (split_count == 0)
        return 1;
    hot_grid h;
    memset(&h, 0, sizeof h);
    int ok;
    if (vertices) {
        size_t n;
        split_point *pts = boolean_complete_hot_points(g, &n);
        if (!pts)
            return 0;
        /* every split point is a hot pixel its edge passes through: the
         * snapping finds it again */
        g->split_count = 0;
        ok = hot_grid_build(&h, pts, n);
        free(pts);
    } else {
        ok = hot_grid_build(&h, g->splits, split_count);
    }
    for (size_t i = 0; ok && i < g->edge_count; i++) {
        const edge e = g->edges[i];
        int64_t xlo = e.x_bottom < e.x_top ? e.x_bottom : e.x_top,
                xhi = e.x_bottom < e.x_top ? e.x_top : e.x_bottom;
        if (e.y_top + 1 < h.y_low)
            continue;
        size_t r = e.y_bottom - 1 > h.y_low ? (size_t)((e.y_bottom - 1 - h.y_low) / h.side) : 0;
        for (; ok && r < h.rows; r++) {
            int64_t ry0 = h.y_low + (int64_t)r * h.side, ry1 = ry0 + h.side - 1;
            if (ry0 > e.y_top + 1)
                break;
            /* the edge's x over the row's y and one unit more each way
             * (clamped to the edge), widened by two units: a pixel whose
             * centre is there may meet it */
            int64_t ya = ry0 - 1 > e.y_bottom ? ry0 - 1 : e.y_bottom,
                    yz = ry1 + 1 < e.y_top ? ry1 + 1 : e.y_top;
            if (ya > yz)
                ya = yz = ya > e.y_top ? e.y_top : e.y_bottom;
            double xa = x_at(&e, ya), xz = x_at(&e, yz);
            double lo = (xa < xz ? xa : xz) - 2 - (double)h.x_low;
            double hi = (xa < xz ? xz : xa) + 2 - (double)h.x_low;
            if (hi < 0)
                continue;
            size_t c0 = lo <= 0 ? 0 : (size_t)(lo / (double)h.side);
            size_t c1 = (size_t)(hi / (double)h.side);
            if (c1 >= h.cols)
                c1 = h.cols - 1;
            for (size_t c = c0; ok && c <= c1; c++) {
                size_t cell = r * h.cols + c;
                for (size_t q = h.start[cell]; q < h.start[cell + 1]; q++) {
                    int64_t px = h.points[q].x, py = h.points[q].y;
                    if (py < e.y_bottom - 1 || py > e.y_top + 1 || px < xlo - 1 || px > xhi + 1
                        || (px == e.x_bottom && py == e.y_bottom)
                        || (px == e.x_top && py == e.y_top)
                        || !boolean_meets_pixel(e.x_bottom, e.y_bottom, e.x_top, e.y_top, px, py,
                                                vertices))
                        continue;
                    ok = room_for_split(g);
                    if (!ok)
                        break; /* out of memory: no room for the point */
                    g->splits[g->split_count++] = (split_point){(uint32_t)i, px, py};
                }
            }
        }
    }
    free(h.start);
    free(h.points);
    return ok;
}

/* Notes input edge e as the input edge of its pieces: its number, NO_ORIG
 * when out of memory.  (The first few in the engine itself.) */
static uint32_t add_orig(engine *g, const edge *e)
{
    if (!g->input_edges) {
        g->input_edges = g->input_edges_small;
        g->input_edge_capacity = sizeof g->input_edges_small / sizeof g->input_edges_small[0];
    }
    if (!boolean_room((void **)&g->input_edges, &g->input_edge_capacity, g->input_edge_count, 1,
                      sizeof g->input_edges[0], g->input_edges_small))
        return NO_ORIG;
    int64_t *o = g->input_edges[g->input_edge_count];
    o[0] = e->x_bottom;
    o[1] = e->y_bottom;
    o[2] = e->x_top;
    o[3] = e->y_top;
    return (uint32_t)g->input_edge_count++;
}

/* the input edge of e's pieces: e's own, or e itself noted (NO_ORIG when
 * out of memory) */
static inline uint32_t orig_of(engine *g, const edge *e)
{
    return e->input_edge == NO_ORIG ? add_orig(g, e) : e->input_edge;
}

static ALWAYS_INLINE int add_pieces_along(engine *g, const edge *e, const split_sort *pts, size_t m)
{
    /* the input edge of the pieces */
    uint32_t orig = orig_of(g, e);
    if (orig == NO_ORIG)
        return 0;
    /* the path direction of the edge: w == -1 means upwards */
    for (size_t k = 0; k + 1 < m; k++) {
        split_sort p = pts[k], q = pts[k + 1];
        if (p.x == q.x && p.y == q.y)
            continue;
        size_t ne = g->edge_count;
        int ok = e->winding < 0 ? boolean_add_edge(g, p.x, p.y, q.x, q.y, e->operand, orig)
                                : boolean_add_edge(g, q.x, q.y, p.x, p.y, e->operand, orig);
        if (!ok)
            return 0;
        if (g->edge_count > ne) /* (a merged edge counts more than once) */
            g->edges[ne].winding = (int8_t)(g->edges[ne].winding
                                            * (e->winding < 0 ? -e->winding : e->winding));
    }
    return 1;
}

uint32_t boolean_orig_of(engine *g, const edge *e)
{
    return orig_of(g, e);
}

/* (for complete snap rounding; inlined here) */
void boolean_sort_along(split_sort *a, size_t n)
{
    sort_along(a, n);
}

size_t boolean_drop_split_edges(engine *g, size_t old_edge_count, const unsigned char *dead,
                                uint32_t *map)
{
    size_t w = 0;
    for (size_t i = 0; i < old_edge_count; i++) {
        map[i] = dead[i] ? UINT32_MAX : (uint32_t)w;
        if (!dead[i])
            g->edges[w++] = g->edges[i];
    }
    size_t kept = w;
    for (size_t i = old_edge_count; i < g->edge_count; i++)
        g->edges[w++] = g->edges[i];
    g->edge_count = w;
    return kept;
}

/* Replaces every edge that has split points by its pieces: map[old edge]
 * receives its new index, or UINT32_MAX when it was split
 * (the pieces come after the edges kept, in g->edges[*kept..]); mem (cap
 * bytes, or NULL) is scratch. */
int boolean_apply_splits(engine *g, uint32_t *map, size_t *kept, void *mem, size_t cap)
{
    size_t old_edge_count = g->edge_count, split_count = g->split_count;
    split_sort small[34], *buf = small; /* the points of one edge */
    size_t capbuf = sizeof small / sizeof small[0];
    /* the split points by edge (a counting sort into order[]; the points of
     * one edge are put in order along it below), in one block with dead[]:
     * the caller's `mem` (cap bytes) when large enough */
    size_t at = (old_edge_count + 1 + 3) & ~(size_t)3,
           bytes = at + (old_edge_count + 1 + split_count) * sizeof(uint32_t);
    unsigned char *own = bytes > cap || !mem ? calloc(bytes, 1) : NULL;
    unsigned char *dead = own ? own : mem;
    if (!dead)
        return 0;
    if (!own)
        memset(dead, 0, at + (old_edge_count + 1) * sizeof(uint32_t)); /* (dead and first) */
    uint32_t *first = (uint32_t *)(void *)(dead + at), *order = first + old_edge_count + 1;
    /* room for the pieces at once: at most one per split point and split
     * edge */
    if (!room_for_edges(g, split_count
                               + (split_count < old_edge_count ? split_count : old_edge_count))) {
        free(own);
        return 0;
    }
    for (size_t k = 0; k < split_count; k++)
        first[g->splits[k].edge + 1]++;
    for (size_t i = 1; i <= old_edge_count; i++)
        first[i] += first[i - 1];
    for (size_t k = 0; k < split_count; k++)
        order[first[g->splits[k].edge]++] = (uint32_t)k;
    for (size_t i = 0; i < split_count;) {
        size_t j = i;
        uint32_t edge_index = g->splits[order[i]].edge;
        while (j < split_count && g->splits[order[j]].edge == edge_index)
            j++;
        size_t n = j - i;
        if (!boolean_room((void **)&buf, &capbuf, 0, n + 2, sizeof *buf, small))
            goto fail;
        edge e = g->edges[edge_index];
        i128 dx = e.x_top - e.x_bottom, dy = e.y_top - e.y_bottom;
        size_t m = 0;
        buf[m++] = (split_sort){e.x_bottom, e.y_bottom, -1};
        for (size_t k = i; k < j; k++) {
            int64_t x = g->splits[order[k]].x, y = g->splits[order[k]].y;
            i128 t = (i128)(x - e.x_bottom) * dx + (i128)(y - e.y_bottom) * dy;
            buf[m++] = (split_sort){x, y, t};
        }
        sort_along(buf + 1, m - 1);
        buf[m++] = (split_sort){e.x_top, e.y_top, 0};
        dead[edge_index] = 1;
        if (!add_pieces_along(g, &e, buf, m))
            goto fail;
        i = j;
    }
    if (buf != small)
        free(buf);
    *kept = boolean_drop_split_edges(g, old_edge_count, dead, map);
    g->split_count = 0;
    free(own);
    return 1;
fail: /* out of memory */
    if (buf != small)
        free(buf);
    free(own);
    return 0;
}
