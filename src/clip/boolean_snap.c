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
    uint64_t *slot;
    size_t mask, count;
    int64_t x0, y0, x1, y1;
    uint64_t width;
} hot_set;

static inline size_t key_hash(uint64_t k, size_t mask)
{
    k *= 0x9e3779b97f4a7c15u;
    return (size_t)(k ^ (k >> 29)) & mask;
}

static inline uint64_t hot_key(const hot_set *h, int64_t x, int64_t y)
{
    return (uint64_t)(y - h->y0) << 32 | (uint64_t)(x - h->x0);
}

/* whether the hash set has hot point (x, y), within its bounds */
NOINLINE static int hot_hash_has(const hot_set *h, int64_t x, int64_t y)
{
    uint64_t k = hot_key(h, x, y);
    for (size_t i = key_hash(k, h->mask);; i = (i + 1) & h->mask) {
        if (h->slot[i] == k)
            return 1;
        if (h->slot[i] == UINT64_MAX)
            return 0;
    }
}

/* (room for cap keys; the ones of old[0..oldcap) put in) */
static int hot_set_alloc(hot_set *h, size_t cap, const uint64_t *old, size_t oldcap)
{
    h->slot = malloc(cap * sizeof *h->slot);
    if (!h->slot)
        return 0;
    h->mask = cap - 1;
    memset(h->slot, 0xff, cap * sizeof *h->slot);
    for (size_t k = 0; k < oldcap; k++) {
        if (old[k] == UINT64_MAX)
            continue;
        size_t i = key_hash(old[k], h->mask);
        while (h->slot[i] != UINT64_MAX)
            i = (i + 1) & h->mask;
        h->slot[i] = old[k];
    }
    return 1;
}

NOINLINE static int hot_hash_add(hot_set *h, int64_t x, int64_t y)
{
    if (2 * (h->count + 1) > h->mask + 1) {
        uint64_t *old = h->slot;
        if (!hot_set_alloc(h, 2 * (h->mask + 1), old, h->mask + 1)) {
            h->slot = old;
            return 0;
        }
        free(old);
    }
    uint64_t k = hot_key(h, x, y);
    size_t i = key_hash(k, h->mask);
    while (h->slot[i] != UINT64_MAX && h->slot[i] != k)
        i = (i + 1) & h->mask;
    if (h->slot[i] == UINT64_MAX) {
        h->slot[i] = k;
        h->count++;
    }
    return 1;
}

static inline int hot_set_add(void *set, int64_t x, int64_t y)
{
    hot_set *h = set;
    if (!h->bits)
        return hot_hash_add(h, x, y);
    uint64_t b = (uint64_t)(y - h->y0) * h->width + (uint64_t)(x - h->x0);
    h->bits[b >> 6] |= (uint64_t)1 << (b & 63);
    return 1;
}

/* the bounds of the edges (horizontal ones too), and the edges' length in
 * pixels (returned) */
static double edge_bounds(const engine *g, hot_set *h)
{
    double length = 0;
    h->x0 = h->y0 = INT64_MAX;
    h->x1 = h->y1 = INT64_MIN;
    for (size_t i = 0; i < g->ne; i++) {
        const bedge *e = &g->E[i];
        int64_t lo = e->xb < e->xt ? e->xb : e->xt, hi = e->xb < e->xt ? e->xt : e->xb;
        length += (double)(e->yt - e->yb) + (double)(hi - lo) + 1;
        h->x0 = lo < h->x0 ? lo : h->x0;
        h->x1 = hi > h->x1 ? hi : h->x1;
        h->y0 = e->yb < h->y0 ? e->yb : h->y0;
        h->y1 = e->yt > h->y1 ? e->yt : h->y1;
    }
    for (size_t i = 0; i < g->nh; i++) {
        const hseg *e = &g->H[i];
        h->x0 = e->x0 < h->x0 ? e->x0 : h->x0;
        h->x1 = e->x1 > h->x1 ? e->x1 : h->x1;
        h->y0 = e->y < h->y0 ? e->y : h->y0;
        h->y1 = e->y > h->y1 ? e->y : h->y1;
    }
    return length;
}

/* the hot points (boolean_each_hot_point), straight from the engine (room
 * at first for one a crossing, each given by its two edges) */
static int hot_set_build(hot_set *h, const engine *g)
{
    size_t n = g->ns / 2 + 2 * (g->ne + g->nh) + g->nm, cap = 64;
    while (cap < 2 * n)
        cap *= 2;
    h->count = 0;
    h->width = (uint64_t)(h->x1 - h->x0) + 1;
    double cells = (double)h->width * ((double)(h->y1 - h->y0) + 1);
    h->bits = NULL;
    h->slot = NULL;
    if (cells <= 8 * 8 * (double)cap) { /* (no larger than the hash set) */
        h->bits = calloc((size_t)(cells / 64) + 1, sizeof *h->bits);
        if (!h->bits)
            return 0;
    } else if (!hot_set_alloc(h, cap, NULL, 0)) {
        return 0;
    }
    return boolean_each_hot_point(g, hot_set_add, h);
}

/* The pieces made so far (of g->E or g->H), by content: open addressing on
 * an index + 1 (0 when free), at most half full */
typedef struct made_index {
    uint32_t *slot;
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

/* room in x for `more` records (of g->E when `pieces`, else of g->H): 0
 * when out of memory */
static int index_room(made_index *x, const engine *g, int pieces, size_t more)
{
    if (2 * (x->count + more) <= x->mask + 1 && x->slot)
        return 1;
    size_t cap = x->slot ? 2 * (x->mask + 1) : 1024;
    while (cap < 2 * (x->count + more))
        cap *= 2;
    uint32_t *slot = calloc(cap, sizeof *slot);
    if (!slot)
        return 0;
    for (size_t i = 0; x->slot && i <= x->mask; i++) {
        uint32_t r = x->slot[i];
        if (!r)
            continue;
        size_t h;
        if (pieces) {
            const bedge *e = &g->E[r - 1];
            h = piece_key(e->xb, e->yb, e->xt, e->yt, e->op, cap - 1);
        } else {
            const hseg *e = &g->H[r - 1];
            h = horizontal_key(e->y, e->x0, e->x1, cap - 1);
        }
        while (slot[h])
            h = (h + 1) & (cap - 1);
        slot[h] = r;
    }
    free(x->slot);
    x->slot = slot;
    x->mask = cap - 1;
    return 1;
}

/* Horizontal edge (y, x0..x1) added to g->H unless it is there (it carries
 * no winding: a copy adds nothing); x has room.  0 when out of memory. */
static int add_horizontal_once(engine *g, made_index *x, int64_t y, int64_t x0, int64_t x1)
{
    size_t h = horizontal_key(y, x0, x1, x->mask);
    for (uint32_t r; (r = x->slot[h]); h = (h + 1) & x->mask) {
        const hseg *o = &g->H[r - 1];
        if (o->y == y && o->x0 == x0 && o->x1 == x1)
            return 1;
    }
    GROW(g->H, g->nh, g->caph, return 0);
    g->H[g->nh++] = (hseg){y, x0, x1};
    x->slot[h] = (uint32_t)g->nh;
    x->count++;
    return 1;
}

/* The pieces of edge e between its points pts[0..m) (in order from its
 * bottom), each counted into the piece made before with its ends and
 * operand, when there is one, else added (horizontal ones once): the
 * splits' pieces of an edge (boolean_split.c), without making the copies
 * first.  0 when out of memory. */
static int add_merged_pieces(engine *g, const bedge *e, const split_sort *pts, size_t m,
                             made_index *pieces, made_index *horizontals)
{
    uint32_t orig = boolean_orig_of(g, e);
    if (orig == NO_ORIG || !index_room(pieces, g, 1, m) || !index_room(horizontals, g, 0, m))
        return 0;
    int count = e->w < 0 ? -e->w : e->w;
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
        int up = (e->w < 0) == (p.y < q.y);
        split_sort lo = p.y < q.y ? p : q, hi = p.y < q.y ? q : p;
        int8_t w = (int8_t)(up ? -count : count);
        size_t h = piece_key(lo.x, lo.y, hi.x, hi.y, e->op, pieces->mask);
        uint32_t r;
        for (; (r = pieces->slot[h]); h = (h + 1) & pieces->mask) {
            const bedge *o = &g->E[r - 1];
            if (o->xb == lo.x && o->yb == lo.y && o->xt == hi.x && o->yt == hi.y && o->op == e->op)
                break;
        }
        if (r) {
            bedge *o = &g->E[r - 1];
            int sum = o->w + w;
            if (sum >= -127 && sum <= 127) {
                o->w = (int8_t)sum;
                if (o->orig != orig)
                    o->orig = NO_ORIG; /* (rounded on itself, if ever split) */
                continue;
            }
            /* (a winding beyond int8: kept apart) */
        }
        GROW_SMALL(g->E, g->ne, g->cape, g->E_small, return 0);
        g->E[g->ne] = (bedge){lo.x, lo.y, hi.x, hi.y,
                              (double)(hi.x - lo.x) / (double)(hi.y - lo.y), orig, w, e->op};
        g->ne++;
        if (!r) {
            pieces->slot[h] = (uint32_t)g->ne;
            pieces->count++;
        }
    }
    return 1;
}

/* g->H with each horizontal edge once, indexed in x: 0 when out of memory */
static int index_horizontals(engine *g, made_index *x)
{
    size_t n = g->nh;
    g->nh = 0;
    if (!index_room(x, g, 0, n))
        return 0;
    for (size_t i = 0; i < n; i++) /* (moved down in order; the room is there) */
        if (!add_horizontal_once(g, x, g->H[i].y, g->H[i].x0, g->H[i].x1))
            return 0;
    return 1;
}

/* g->E[from..ne) without the pieces whose windings cancelled */
static void drop_cancelled(engine *g, size_t from)
{
    size_t k = from;
    for (size_t i = from; i < g->ne; i++)
        if (g->E[i].w)
            g->E[k++] = g->E[i];
    g->ne = k;
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
static size_t walk_pixels(const bedge *e, const hot_set *h, split_sort **buf, size_t *cap,
                          split_sort *small)
{
    i128 dx = e->xt - e->xb, dy = e->yt - e->yb;
    int right = e->xt >= e->xb;
    /* (far above the rounding errors of x along the edge) */
    double eps = 1e-6 + 2e-12 * (fabs((double)e->xb) + fabs((double)e->xt));
    size_t m = 0;
    (*buf)[m++] = (split_sort){e->xb, e->yb, -1};
    for (int64_t py = e->yb; py <= e->yt; py++) {
        /* the edge's x over the pixel row [py - 1/2, py + 1/2] (clamped to
         * the edge), widened for rounding: the pixels p0..p1 there */
        double ya = py == e->yb ? (double)py : (double)py - 0.5;
        double yz = py == e->yt ? (double)py : (double)py + 0.5;
        double xa = (double)e->xb + e->slope * (ya - (double)e->yb);
        double xz = (double)e->xb + e->slope * (yz - (double)e->yb);
        double lo = xa < xz ? xa : xz, hi = xa < xz ? xz : xa;
        int64_t p0 = ceil_i64(lo - 0.5 - eps), p1 = floor_i64(hi + 0.5 + eps);
        /* (the hot points are within the edges' bounds) */
        int64_t q0 = p0 > h->x0 ? p0 : h->x0, q1 = p1 < h->x1 ? p1 : h->x1;
        int end_row = py == e->yb || py == e->yt;
        uint64_t row = (uint64_t)(py - h->y0) * h->width - (uint64_t)h->x0;
        for (int64_t k = 0; k <= q1 - q0; k++) {
            int64_t px = right ? q0 + k : q1 - k;
            if (!hot_at(h, row, px, py) ||
                (end_row && ((px == e->xb && py == e->yb) || (px == e->xt && py == e->yt))))
                continue;
            /* between p0 and p1, the edge's x over the row overlaps the
             * pixel's by a clear margin: some of the edge is inside; at
             * the two ends, unless it does, the exact test */
            if (px == p0 || px == p1) {
                double in_lo = (double)px - 0.5 > lo ? (double)px - 0.5 : lo;
                double in_hi = (double)px + 0.5 < hi ? (double)px + 0.5 : hi;
                if (!(in_hi - in_lo > 4 * eps) &&
                    !boolean_meets_pixel(e->xb, e->yb, e->xt, e->yt, px, py, 1))
                    continue;
            }
            if (m + 2 > *cap) { /* (and room for the top) */
                split_sort *nb = boolean_grow_from(*buf, small, m, cap, sizeof *nb);
                if (!nb)
                    return 0;
                *buf = nb;
            }
            i128 t = (i128)(px - e->xb) * dx + (i128)(py - e->yb) * dy;
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
    size_t old_ne = g->ne;
    g->ns = 0;
    made_index pieces = {0}, horizontals = {0};
    /* (sized at once for about as many pieces as the crossings' split
     * points, of which coincide most) */
    if (!index_room(&pieces, g, 1, expect / 2) || !index_room(&horizontals, g, 0, expect / 4)) {
        free(pieces.slot);
        return 0;
    }
    unsigned char *own = old_ne > cap || !mem ? calloc(old_ne + 1, 1) : NULL;
    unsigned char *dead = own ? own : mem;
    split_sort small[64], *buf = small;
    size_t capbuf = sizeof small / sizeof small[0];
    int ok = dead != NULL && index_horizontals(g, &horizontals);
    if (ok && !own)
        memset(dead, 0, old_ne);
    for (size_t i = 0; ok && i < old_ne; i++) {
        const bedge e = g->E[i];
        size_t m = walk_pixels(&e, h, &buf, &capbuf, small);
        ok = m > 0;
        if (m < 2)
            continue; /* (no hot pixel on the way: the edge stays) */
        boolean_sort_along(buf + 1, m - 1);
        buf[m++] = (split_sort){e.xt, e.yt, 0};
        dead[i] = 1;
        ok = add_merged_pieces(g, &e, buf, m, &pieces, &horizontals);
    }
    if (ok) {
        *kept = boolean_drop_split_edges(g, old_ne, dead, map);
        drop_cancelled(g, *kept);
    }
    if (buf != small)
        free(buf);
    free(own);
    free(pieces.slot);
    free(horizontals.slot);
    return ok;
}

/* The split points and run breaks, once in the hot set: their arrays given
 * back (the next passes have few; the less a call holds at once, the less
 * of the heap the C library gives back and takes again on every call) */
static void release_hot_sources(engine *g)
{
    if (!g->S_small) { /* (small inputs keep theirs: it may be the caller's) */
        free(g->S);
        g->S = NULL;
        g->caps = 0;
    }
    g->ns = 0;
    free(g->M);
    g->M = NULL;
    g->nm = g->capm = 0;
}

/* the edges' array cut to their number and a little (the merged pieces are
 * a fraction of the snapped ones it grew for) */
static void shrink_edges(engine *g)
{
    size_t want = g->ne + g->ne / 4 + 64;
    if (g->E == g->E_small || g->cape <= want + want / 4)
        return;
    bedge *e = realloc(g->E, want * sizeof *e);
    if (e) {
        g->E = e;
        g->cape = want;
    }
}

int boolean_snap_complete(engine *g, uint32_t *map, size_t *kept, void *mem, size_t cap)
{
    hot_set h;
    double length = edge_bounds(g, &h);
    if (length <= PIXEL_WALK * (double)boolean_hot_point_count(g) &&
        h.x1 - h.x0 < INT64_C(1) << 32 && h.y1 - h.y0 < INT64_C(1) << 32) {
        if (!hot_set_build(&h, g)) {
            free(h.bits);
            free(h.slot);
            return 0;
        }
        size_t expect = g->ns;
        release_hot_sources(g);
        int ok = snap_by_pixel_walk(g, &h, expect, map, kept, mem, cap);
        free(h.bits);
        free(h.slot);
        if (ok)
            shrink_edges(g);
        return ok;
    }
    /* long edges: each looks at the cells of the hot-pixel grid along it */
    return boolean_add_hot_pixel_splits(g, 1) && boolean_apply_splits(g, map, kept, mem, cap);
}
