/* Complete snap rounding for the boolean operations (Hobby): used once, when
 * the crossings are dense.  Every edge is routed through the centre of each
 * hot pixel it meets: on coarse grids by walking its pixels, the pieces that
 * then coincide merged as they come; else through the cells of the
 * hot-pixel grid (boolean_split.c). */
#include "boolean_engine.h"

/* the pixel walk: up to this many pixels of edge per hot point (beyond, the
 * cells of the hot-pixel grid: boolean_add_hot_pixel_splits) */
#define PIXEL_WALK 16

/* The hot points, within the bounds of the edges (where every hot point
 * is): a bit per grid point of the bounds when these are small against the
 * points (on coarse grids), else a hash set of keys (y - y0) << 32 |
 * (x - x0), open addressing with UINT64_MAX for a free slot, grown to stay
 * at most half full */
typedef struct hot_set {
    uint64_t *bits; /* or NULL */
    uint64_t *slots;
    size_t mask, count;
    int64_t x_low, y_low, x_high, y_high;
    uint64_t width;
} hot_set;

static inline size_t key_hash(uint64_t k, size_t mask)
{
    k *= 0x9e3779b97f4a7c15u;
    return (size_t)(k ^ (k >> 29)) & mask;
}

static inline uint64_t hot_key(const hot_set *h, int64_t x, int64_t y)
{
    return (uint64_t)(y - h->y_low) << 32 | (uint64_t)(x - h->x_low);
}

/* whether the hash set has hot point (x, y), within its bounds */
NOINLINE static int hot_hash_has(const hot_set *h, int64_t x, int64_t y)
{
    uint64_t k = hot_key(h, x, y);
    for (size_t i = key_hash(k, h->mask);; i = (i + 1) & h->mask) {
        if (h->slots[i] == k)
            return 1;
        if (h->slots[i] == UINT64_MAX)
            return 0;
    }
}

/* (room for cap keys; the ones of old[0..oldcap) put in) */
static int hot_set_alloc(hot_set *h, size_t cap, const uint64_t *old, size_t oldcap)
{
    h->slots = malloc(cap * sizeof *h->slots);
    if (!h->slots)
        return 0;
    h->mask = cap - 1;
    memset(h->slots, 0xff, cap * sizeof *h->slots);
    for (size_t k = 0; k < oldcap; k++) {
        if (old[k] == UINT64_MAX)
            continue;
        size_t i = key_hash(old[k], h->mask);
        while (h->slots[i] != UINT64_MAX)
            i = (i + 1) & h->mask;
        h->slots[i] = old[k];
    }
    return 1;
}

NOINLINE static int hot_hash_add(hot_set *h, int64_t x, int64_t y)
{
    if (2 * (h->count + 1) > h->mask + 1) {
        uint64_t *old = h->slots;
        if (!hot_set_alloc(h, 2 * (h->mask + 1), old, h->mask + 1)) {
            h->slots = old;
            return 0;
        }
        free(old);
    }
    uint64_t k = hot_key(h, x, y);
    size_t i = key_hash(k, h->mask);
    while (h->slots[i] != UINT64_MAX && h->slots[i] != k)
        i = (i + 1) & h->mask;
    if (h->slots[i] == UINT64_MAX) {
        h->slots[i] = k;
        h->count++;
    }
    return 1;
}

static inline int hot_set_add(void *set, int64_t x, int64_t y)
{
    hot_set *h = set;
    if (!h->bits)
        return hot_hash_add(h, x, y);
    uint64_t b = (uint64_t)(y - h->y_low) * h->width + (uint64_t)(x - h->x_low);
    h->bits[b >> 6] |= (uint64_t)1 << (b & 63);
    return 1;
}

/* the bounds of the edges (horizontal ones too), and the edges' length in
 * pixels (returned) */
static double edge_bounds(const engine *g, hot_set *h)
{
    double length = 0;
    h->x_low = h->y_low = INT64_MAX;
    h->x_high = h->y_high = INT64_MIN;
    for (size_t i = 0; i < g->edge_count; i++) {
        const edge *e = &g->edges[i];
        int64_t lo = e->x_bottom < e->x_top ? e->x_bottom : e->x_top,
                hi = e->x_bottom < e->x_top ? e->x_top : e->x_bottom;
        length += (double)(e->y_top - e->y_bottom) + (double)(hi - lo) + 1;
        h->x_low = lo < h->x_low ? lo : h->x_low;
        h->x_high = hi > h->x_high ? hi : h->x_high;
        h->y_low = e->y_bottom < h->y_low ? e->y_bottom : h->y_low;
        h->y_high = e->y_top > h->y_high ? e->y_top : h->y_high;
    }
    for (size_t i = 0; i < g->horizontal_count; i++) {
        const horizontal_edge *e = &g->horizontals[i];
        h->x_low = e->x_left < h->x_low ? e->x_left : h->x_low;
        h->x_high = e->x_right > h->x_high ? e->x_right : h->x_high;
        h->y_low = e->y < h->y_low ? e->y : h->y_low;
        h->y_high = e->y > h->y_high ? e->y : h->y_high;
    }
    return length;
}

/* the hot points (boolean_each_hot_point), straight from the engine (room
 * at first for one a crossing, each given by its two edges) */
static int hot_set_build(hot_set *h, const engine *g)
{
    size_t n = g->split_count / 2 + 2 * (g->edge_count + g->horizontal_count) + g->meet_count,
           cap = 64;
    while (cap < 2 * n)
        cap *= 2;
    h->count = 0;
    h->width = (uint64_t)(h->x_high - h->x_low) + 1;
    double cells = (double)h->width * ((double)(h->y_high - h->y_low) + 1);
    h->bits = NULL;
    h->slots = NULL;
    if (cells <= 8 * 8 * (double)cap) { /* (no larger than the hash set) */
        h->bits = calloc((size_t)(cells / 64) + 1, sizeof *h->bits);
        if (!h->bits)
            return 0;
    } else if (!hot_set_alloc(h, cap, NULL, 0)) {
        return 0;
    }
    return boolean_each_hot_point(g, hot_set_add, h);
}

/* The pieces made so far (of g->edges or g->horizontals), by content: open addressing on
 * an index + 1 (0 when free), at most half full */
typedef struct made_index {
    uint32_t *slots;
    size_t mask, count;
} made_index;

static inline size_t piece_key(int64_t xb, int64_t yb, int64_t xt, int64_t yt, unsigned op,
                               size_t mask)
{
    uint64_t h = (uint64_t)xb * 0x9e3779b97f4a7c15u;
    h = (h ^ (uint64_t)yb) * 0xff51afd7ed558ccdu;
    h = (h ^ (uint64_t)xt) * 0xc4ceb9fe1a85ec53u;
    return key_hash(h ^ (uint64_t)yt ^ op, mask);
}

static inline size_t horizontal_key(int64_t y, int64_t x0, int64_t x1, size_t mask)
{
    uint64_t h = ((uint64_t)y * 0x9e3779b97f4a7c15u ^ (uint64_t)x0) * 0xff51afd7ed558ccdu;
    return key_hash(h ^ (uint64_t)x1, mask);
}

/* room in x for `more` records (of g->edges when `pieces`, else of g->horizontals): 0
 * when out of memory */
static int index_room(made_index *x, const engine *g, int pieces, size_t more)
{
    if (2 * (x->count + more) <= x->mask + 1 && x->slots)
        return 1;
    size_t cap = x->slots ? 2 * (x->mask + 1) : 1024;
    while (cap < 2 * (x->count + more))
        cap *= 2;
    uint32_t *slot = calloc(cap, sizeof *slot);
    if (!slot)
        return 0;
    for (size_t i = 0; x->slots && i <= x->mask; i++) {
        uint32_t r = x->slots[i];
        if (!r)
            continue;
        size_t h;
        if (pieces) {
            const edge *e = &g->edges[r - 1];
            h = piece_key(e->x_bottom, e->y_bottom, e->x_top, e->y_top, e->operand, cap - 1);
        } else {
            const horizontal_edge *e = &g->horizontals[r - 1];
            h = horizontal_key(e->y, e->x_left, e->x_right, cap - 1);
        }
        while (slot[h])
            h = (h + 1) & (cap - 1);
        slot[h] = r;
    }
    free(x->slots);
    x->slots = slot;
    x->mask = cap - 1;
    return 1;
}

/* Horizontal edge (y, x0..x1) added to g->horizontals unless it is there (it carries
 * no winding: a copy adds nothing); x has room.  0 when out of memory. */
static int add_horizontal_once(engine *g, made_index *x, int64_t y, int64_t x0, int64_t x1)
{
    size_t h = horizontal_key(y, x0, x1, x->mask);
    for (uint32_t r; (r = x->slots[h]); h = (h + 1) & x->mask) {
        const horizontal_edge *o = &g->horizontals[r - 1];
        if (o->y == y && o->x_left == x0 && o->x_right == x1)
            return 1;
    }
    if (!room_for_horizontal(g))
        return 0;
    g->horizontals[g->horizontal_count++] = (horizontal_edge){y, x0, x1};
    x->slots[h] = (uint32_t)g->horizontal_count;
    x->count++;
    return 1;
}

/* The pieces of edge e between its points pts[0..m) (in order from its
 * bottom), each counted into the piece made before with its ends and
 * operand, when there is one, else added (horizontal ones once): the
 * splits' pieces of an edge (boolean_split.c), without making the copies
 * first.  0 when out of memory. */
static int add_merged_pieces(engine *g, const edge *e, const split_sort *pts, size_t m,
                             made_index *pieces, made_index *horizontals)
{
    uint32_t orig = boolean_orig_of(g, e);
    if (orig == NO_ORIG || !index_room(pieces, g, 1, m) || !index_room(horizontals, g, 0, m))
        return 0;
    int count = e->winding < 0 ? -e->winding : e->winding;
    for (size_t k = 0; k + 1 < m; k++) {
        split_sort p = pts[k], q = pts[k + 1];
        if (p.x == q.x && p.y == q.y)
            continue;
        if (p.y == q.y) {
            if (!add_horizontal_once(g, horizontals, p.y, p.x < q.x ? p.x : q.x,
                                     p.x < q.x ? q.x : p.x))
                return 0;
            continue;
        }
        /* the path runs from p to q (up the edge's points when w < 0) */
        int up = (e->winding < 0) == (p.y < q.y);
        split_sort lo = p.y < q.y ? p : q, hi = p.y < q.y ? q : p;
        int8_t w = (int8_t)(up ? -count : count);
        size_t h = piece_key(lo.x, lo.y, hi.x, hi.y, e->operand, pieces->mask);
        uint32_t r;
        for (; (r = pieces->slots[h]); h = (h + 1) & pieces->mask) {
            const edge *o = &g->edges[r - 1];
            if (o->x_bottom == lo.x && o->y_bottom == lo.y && o->x_top == hi.x && o->y_top == hi.y
                && o->operand == e->operand)
                break;
        }
        if (r) {
            edge *o = &g->edges[r - 1];
            int sum = o->winding + w;
            if (sum >= -127 && sum <= 127) {
                o->winding = (int8_t)sum;
                if (o->input_edge != orig)
                    o->input_edge = NO_ORIG; /* (rounded on itself, if ever split) */
                continue;
            }
            /* (a winding beyond int8: kept apart) */
        }
        if (!room_for_edges(g, 1))
            return 0;
        g->edges[g->edge_count] = (edge){
            lo.x, lo.y, hi.x,      hi.y, (double)(hi.x - lo.x) / (double)(hi.y - lo.y),
            orig, w,    e->operand};
        g->edge_count++;
        if (!r) {
            pieces->slots[h] = (uint32_t)g->edge_count;
            pieces->count++;
        }
    }
    return 1;
}

/* g->horizontals with each horizontal edge once, indexed in x: 0 when out of memory */
static int index_horizontals(engine *g, made_index *x)
{
    size_t n = g->horizontal_count;
    g->horizontal_count = 0;
    if (!index_room(x, g, 0, n))
        return 0;
    for (size_t i = 0; i < n; i++) /* (moved down in order; the room is there) */
        if (!add_horizontal_once(g, x, g->horizontals[i].y, g->horizontals[i].x_left,
                                 g->horizontals[i].x_right))
            return 0;
    return 1;
}

/* g->edges[from..ne) without the pieces whose windings cancelled */
static void drop_cancelled(engine *g, size_t from)
{
    size_t k = from;
    for (size_t i = from; i < g->edge_count; i++)
        if (g->edges[i].winding)
            g->edges[k++] = g->edges[i];
    g->edge_count = k;
}

/* floor and ceiling of v (|v| < 2^62) */
static inline int64_t floor_i64(double v)
{
    int64_t t = (int64_t)v;
    return t - (v < (double)t);
}

static inline int64_t ceil_i64(double v)
{
    int64_t t = (int64_t)v;
    return t + (v > (double)t);
}

/* whether hot point (px, py) is in h, (px, py) within its bounds; row is
 * (py - y0) * width - x0, the bitmap's index of (0, py) (modulo 2^64) */
static inline int hot_at(const hot_set *h, uint64_t row, int64_t px, int64_t py)
{
    if (h->bits) {
        uint64_t b = row + (uint64_t)px;
        return (int)(h->bits[b >> 6] >> (b & 63)) & 1;
    }
    return hot_hash_has(h, px, py);
}

/* The hot pixels edge e meets, in buf after its bottom (t ordering them
 * along e), row by row: the pixels there in the order e meets them, looked
 * up in h.  The number of points in buf, or 0 when out of memory. */
static size_t walk_pixels(const edge *e, const hot_set *h, split_sort **buf, size_t *cap,
                          split_sort *small)
{
    i128 dx = e->x_top - e->x_bottom, dy = e->y_top - e->y_bottom;
    int right = e->x_top >= e->x_bottom;
    /* (far above the rounding errors of x along the edge) */
    double eps = 1e-6 + 2e-12 * (fabs((double)e->x_bottom) + fabs((double)e->x_top));
    size_t m = 0;
    (*buf)[m++] = (split_sort){e->x_bottom, e->y_bottom, -1};
    for (int64_t py = e->y_bottom; py <= e->y_top; py++) {
        /* the edge's x over the pixel row [py - 1/2, py + 1/2] (clamped to
         * the edge), widened for rounding: the pixels p0..p1 there */
        double ya = py == e->y_bottom ? (double)py : (double)py - 0.5;
        double yz = py == e->y_top ? (double)py : (double)py + 0.5;
        double xa = (double)e->x_bottom + e->slope * (ya - (double)e->y_bottom);
        double xz = (double)e->x_bottom + e->slope * (yz - (double)e->y_bottom);
        double lo = xa < xz ? xa : xz, hi = xa < xz ? xz : xa;
        int64_t p0 = ceil_i64(lo - 0.5 - eps), p1 = floor_i64(hi + 0.5 + eps);
        /* (the hot points are within the edges' bounds) */
        int64_t q0 = p0 > h->x_low ? p0 : h->x_low, q1 = p1 < h->x_high ? p1 : h->x_high;
        int end_row = py == e->y_bottom || py == e->y_top;
        uint64_t row = (uint64_t)(py - h->y_low) * h->width - (uint64_t)h->x_low;
        for (int64_t k = 0; k <= q1 - q0; k++) {
            int64_t px = right ? q0 + k : q1 - k;
            if (!hot_at(h, row, px, py)
                || (end_row
                    && ((px == e->x_bottom && py == e->y_bottom)
                        || (px == e->x_top && py == e->y_top))))
                continue;
            /* between p0 and p1, the edge's x over the row overlaps the
             * pixel's by a clear margin: some of the edge is inside; at
             * the two ends, unless it does, the exact test */
            if (px == p0 || px == p1) {
                double in_lo = (double)px - 0.5 > lo ? (double)px - 0.5 : lo;
                double in_hi = (double)px + 0.5 < hi ? (double)px + 0.5 : hi;
                if (!(in_hi - in_lo > 4 * eps)
                    && !boolean_meets_pixel(e->x_bottom, e->y_bottom, e->x_top, e->y_top, px, py,
                                            1))
                    continue;
            }
            if (!boolean_room((void **)buf, cap, m, 2, sizeof **buf, small))
                return 0; /* (room for the top too) */
            i128 t = (i128)(px - e->x_bottom) * dx + (i128)(py - e->y_bottom) * dy;
            (*buf)[m++] = (split_sort){px, py, t};
        }
    }
    return m;
}

/* Each edge's pixels walked, its pieces added and merged at once: the cost
 * follows the edges' lengths in grid units (bounded by the caller), and no
 * split point is stored. */
static int snap_by_pixel_walk(engine *g, const hot_set *h, size_t expect, uint32_t *map,
                              size_t *kept, void *mem, size_t cap)
{
    size_t old_edge_count = g->edge_count;
    g->split_count = 0;
    made_index pieces = {0}, horizontals = {0};
    /* (sized at once for about as many pieces as the crossings' split
     * points, of which coincide most) */
    if (!index_room(&pieces, g, 1, expect / 2) || !index_room(&horizontals, g, 0, expect / 4)) {
        free(pieces.slots);
        return 0;
    }
    unsigned char *own = old_edge_count > cap || !mem ? calloc(old_edge_count + 1, 1) : NULL;
    unsigned char *dead = own ? own : mem;
    split_sort small[64], *buf = small;
    size_t capbuf = sizeof small / sizeof small[0];
    int ok = dead != NULL && index_horizontals(g, &horizontals);
    if (ok && !own)
        memset(dead, 0, old_edge_count);
    for (size_t i = 0; ok && i < old_edge_count; i++) {
        const edge e = g->edges[i];
        size_t m = walk_pixels(&e, h, &buf, &capbuf, small);
        ok = m > 0;
        if (m < 2)
            continue; /* (no hot pixel on the way: the edge stays) */
        boolean_sort_along(buf + 1, m - 1);
        buf[m++] = (split_sort){e.x_top, e.y_top, 0};
        dead[i] = 1;
        ok = add_merged_pieces(g, &e, buf, m, &pieces, &horizontals);
    }
    if (ok) {
        *kept = boolean_drop_split_edges(g, old_edge_count, dead, map);
        drop_cancelled(g, *kept);
    }
    if (buf != small)
        free(buf);
    free(own);
    free(pieces.slots);
    free(horizontals.slots);
    return ok;
}

/* The split points and run breaks, once in the hot set: their arrays given
 * back (the next passes have few; the less a call holds at once, the less
 * of the heap the C library gives back and takes again on every call) */
static void release_hot_sources(engine *g)
{
    if (!g->splits_small) { /* (small inputs keep theirs: it may be the caller's) */
        free(g->splits);
        g->splits = NULL;
        g->split_capacity = 0;
    }
    g->split_count = 0;
    free(g->meets);
    g->meets = NULL;
    g->meet_count = g->meet_capacity = 0;
}

/* the edges' array cut to their number and a little (the merged pieces are
 * a fraction of the snapped ones it grew for) */
static void shrink_edges(engine *g)
{
    size_t want = g->edge_count + g->edge_count / 4 + 64;
    if (g->edges == g->edges_small || g->edge_capacity <= want + want / 4)
        return;
    edge *e = realloc(g->edges, want * sizeof *e);
    if (e) {
        g->edges = e;
        g->edge_capacity = want;
    }
}

int boolean_snap_complete(engine *g, uint32_t *map, size_t *kept, void *mem, size_t cap)
{
    hot_set h;
    double length = edge_bounds(g, &h);
    if (length <= PIXEL_WALK * (double)boolean_hot_point_count(g)
        && h.x_high - h.x_low < INT64_C(1) << 32 && h.y_high - h.y_low < INT64_C(1) << 32) {
        if (!hot_set_build(&h, g)) {
            free(h.bits);
            free(h.slots);
            return 0;
        }
        size_t expect = g->split_count;
        release_hot_sources(g);
        int ok = snap_by_pixel_walk(g, &h, expect, map, kept, mem, cap);
        free(h.bits);
        free(h.slots);
        if (ok)
            shrink_edges(g);
        return ok;
    }
    /* long edges: each looks at the cells of the hot-pixel grid along it */
    return boolean_add_hot_pixel_splits(g, 1) && boolean_apply_splits(g, map, kept, mem, cap);
}
