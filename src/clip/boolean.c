/* Boolean operations on polygon sets by a sweep over scanbeams, in the manner
 * of Vatti (11.2.2).
 *
 * Every ring of both operands is a closed path on a 64-bit integer grid.  The
 * sweep visits the scanlines (the distinct y of the vertices) from bottom to
 * top; between two scanlines (a scanbeam) the active edges are ordered by x.
 *
 *  1. Intersections.  Two edges whose order at the top of a beam is the
 *     reverse of their order at the bottom cross inside the beam; an edge
 *     that passes through a scanline exactly where another edge or a
 *     horizontal edge is also needs a vertex there.  Such points are rounded
 *     to the grid and the edges split there (both pieces keep the path
 *     closed).  Rounding can move an edge by half a unit, so the sweep is
 *     repeated until a pass finds nothing to split (two passes in practice);
 *     from the second pass on, edges through the pixel of a rounded point are
 *     split there too (snap rounding), which settles nearly parallel fans.
 *  2. Classification.  In the final pass no two edges cross inside a beam,
 *     so walking a beam from left to right and summing the windings of the
 *     subject's and the clip's edges tells, for every gap between edges,
 *     whether it is in the result (fill rule per operand, then the
 *     operation).  An edge (or a group of coincident edges) with the result
 *     on one side only is a piece of the result's boundary, directed so the
 *     result is on its left; the pieces of one edge over consecutive beams
 *     join into a run.  On a scanline the result can only change from below
 *     to above under horizontal edges; there the horizontal boundary pieces
 *     come from comparing the two sides.
 *  3. Assembly.  The directed pieces meet only at grid points; they are
 *     linked into rings taking, at a vertex with several ways out, the
 *     sharpest left turn, which keeps rings that touch at a point apart.
 *     Counter-clockwise rings are outer contours, clockwise ones holes, each
 *     hole going to the smallest outer contour around it.
 *
 * All decisions are exact (128-bit integer arithmetic, with a double filter
 * for speed), so the result does not depend on rounding luck.
 *
 * This file loads the operands and runs the passes; the steps are in
 * boolean_pairs.c (the crossings of small inputs, pair by pair),
 * boolean_sweep.c (the sweeps), boolean_checkpoint.c (where a pass after
 * splits resumes), boolean_split.c (snap rounding and splitting),
 * boolean_assemble.c (rings and holes), boolean_sort.c, and
 * boolean_double.c (the double API); boolean_engine.h holds what they
 * share. */
#include "boolean_engine.h"

int boolean_reserve_from(void **arr, const void *small, size_t n, size_t *cap, size_t need,
                         size_t size)
{
    if (need <= *cap)
        return 1;
    void *p = *arr == small ? malloc(need * size) : realloc(*arr, need * size);
    if (!p)
        return 0;
    if (*arr == small && n)
        memcpy(p, *arr, n * size);
    *arr = p;
    *cap = need;
    return 1;
}

void *boolean_grow_from(void *arr, const void *small, size_t n, size_t *cap, size_t size)
{
    void *p = arr;
    return boolean_reserve_from(&p, small, n, cap, *cap ? *cap * 2 : 32, size) ? p : NULL;
}

int boolean_add_piece(engine *g, int64_t x0, int64_t y0, int64_t x1, int64_t y1, int op,
                      uint32_t orig)
{
    if (y0 == y1) {
        if (x0 == x1)
            return 1;
        GROW(g->H, g->nh, g->caph, return 0);
        g->H[g->nh++] = (hseg){y0, x0 < x1 ? x0 : x1, x0 < x1 ? x1 : x0};
        return 1;
    }
    GROW_SMALL(g->E, g->ne, g->cape, g->E_small, return 0);
    bedge *e = &g->E[g->ne++];
    if (y0 < y1) {
        *e = (bedge){x0, y0, x1, y1, 0, orig, -1, (uint8_t)op};
    } else {
        *e = (bedge){x1, y1, x0, y0, 0, orig, 1, (uint8_t)op};
    }
    e->slope = (double)(e->xt - e->xb) / (double)(e->yt - e->yb);
    return 1;
}

#define MAX_PASSES 64
/* the light sweep's cost per edge, in active edges looked at by the full
 * sweep (the pass driver tries it first when the full sweep was dearer) */
#define LIGHT_COST 16
/* Complete snap rounding (Hobby): the pixels of the edges' ends, of the
 * rounded crossings and of the grid points where edges meet are all hot, and
 * every edge is snapped to each one it passes through; a verifying pass then
 * finds nothing to split.  On dense crossings the iterated rounding instead
 * makes new ones, pass after pass.  A pass snaps completely, once, when it
 * looked at DENSE_VISITS active edges per edge (long active lists: another
 * whole pass would be dear), or when the first pass's crossings are denser
 * than one in DENSE_AREA grid cells (a coarse grid). */
#ifndef DENSE_AREA
#define DENSE_AREA 64
#endif
#ifndef DENSE_VISITS
#define DENSE_VISITS 200
#endif

/* Forgets the arrays of the last pass; their memory is kept for the next. */
static void sweep_reset(sweep *s)
{
    engine *g = s->g;
    void *mem = s->mem, *mem_small = s->mem_small;
    size_t cap = s->memcap;
    memset(s, 0, sizeof *s);
    s->g = g;
    s->mem = mem;
    s->mem_small = mem_small;
    s->memcap = cap;
}

static void *carve(char **p, size_t bytes)
{
    void *r = *p;
    *p += (bytes + 15) & ~(size_t)15;
    return r;
}

/* The arrays of a pass over g's edges, carved from one block kept from pass
 * to pass (large blocks come fresh from the system, page by page, so fewer
 * and reused ones are much cheaper): 0 when out of memory. */
static int sweep_alloc(sweep *s, int light)
{
    size_t n1 = s->g->ne ? s->g->ne : 1, nh = s->g->nh;
    size_t nscratch = n1 > nh ? n1 : nh;
    uint32_t **ids[] = {&s->by_bottom, &s->by_top, &s->act, &s->nxt, &s->fresh, &s->brkq,
                        &s->brkq_next, &s->clus};
    int64_t **i64[] = {&s->run_x, &s->run_y};
    int32_t **i32[] = {&s->wr0, &s->wr1};
    double **f64[] = {&s->xc, &s->xn};
    size_t nids = light ? 8 : 7, need = 32 * 16 + 4 * n1;
    need += (nids * n1 + 3 * n1 + (light ? 3 * n1 + 1 : 0) + nh) * sizeof(uint32_t);
    need += (2 * n1 + 2 * n1) * sizeof(int64_t) + 2 * n1 * sizeof(int32_t) +
            2 * n1 * sizeof(double);
    need += 2 * nscratch * sizeof(keyval) + nh * sizeof(hseg);
    if (need > s->memcap) {
        if (s->mem != s->mem_small)
            free(s->mem);
        s->memcap = 0;
        need += need / 8 + 2048; /* the next pass usually has a few more edges */
        s->mem = malloc(need);
        if (!s->mem)
            return 0;
        s->memcap = need;
    }
    char *p = s->mem;
    for (size_t i = 0; i < nids; i++)
        *ids[i] = carve(&p, n1 * sizeof(uint32_t));
    for (size_t i = 0; i < sizeof i64 / sizeof i64[0]; i++)
        *i64[i] = carve(&p, n1 * sizeof(int64_t));
    for (size_t i = 0; i < sizeof i32 / sizeof i32[0]; i++)
        *i32[i] = carve(&p, n1 * sizeof(int32_t));
    for (size_t i = 0; i < sizeof f64 / sizeof f64[0]; i++)
        *f64[i] = carve(&p, n1 * sizeof(double));
    s->ys = carve(&p, 2 * n1 * sizeof *s->ys);
    /* dirty positions: new edges and run breaks at points, queued run
     * breaks, horizontal meets: each at most once per position */
    s->dirty = carve(&p, 3 * n1 * sizeof *s->dirty);
    s->run_open = carve(&p, 4 * n1); /* and run_up, brk, brk_next */
    s->run_up = s->run_open + n1;
    s->brk = s->run_open + 2 * n1;
    s->brk_next = s->run_open + 3 * n1;
    memset(s->run_open, 0, 4 * n1);
    s->scratch = carve(&p, nscratch * sizeof *s->scratch);
    s->scratch2 = carve(&p, nscratch * sizeof *s->scratch2);
    s->hsorted = carve(&p, nh * sizeof *s->hsorted);
    s->horder = carve(&p, nh * sizeof *s->horder);
    if (light)
        s->seam = carve(&p, (3 * n1 + 1) * sizeof *s->seam);
    s->capbrkq = n1;
    return 1;
}

static int cmp_i64(const void *a, const void *b)
{
    int64_t p = *(const int64_t *)a, q = *(const int64_t *)b;
    return (p > q) - (p < q);
}

/* What a pass leaves to the next: its orders of the edges and where its
 * edges went (boolean_apply_splits). */
typedef struct carry {
    uint32_t *by_bottom, *by_top, *map;
    uint32_t *small; /* the caller's block of 3 * 64 they start in */
    size_t n, cap;   /* edges of the last pass (room for cap) */
    size_t kept;     /* of them, not split: now g->E[0..kept) */
    size_t nh_sorted; /* g->H[0..nh_sorted) is in order */
    int valid;
    /* the last pass's scanlines and the distinct y of its split points
     * (sorted), when they were few: the next pass's scanlines are the two
     * merged (a split edge's pieces form a path from its bottom to its top,
     * so every scanline stays one, and each split point's y becomes one) */
    int64_t *ys, *sy;
    size_t nys, nsy, capys, capsy;
    int ys_valid;
} carry;

/* whether a goes before b (or ties) by (yb, xb), or by (yt, xt) when top */
static inline int edge_before(const bedge *a, const bedge *b, int top)
{
    int64_t a1 = top ? a->yt : a->yb, b1 = top ? b->yt : b->yb;
    if (a1 != b1)
        return a1 < b1;
    return (top ? a->xt : a->xb) <= (top ? b->xt : b->xb);
}

/* out = the edges kept (in their last order, renumbered) merged with the
 * pieces, sorted; tmp holds the pieces' order.  0 when the count is off. */
static int merge_order(sweep *s, const carry *c, uint32_t *old, uint32_t *out, uint32_t *tmp,
                       int top)
{
    engine *g = s->g;
    const bedge *E = g->E;
    size_t ne = g->ne, np = ne - c->kept, na = 0;
    for (size_t i = 0; i < c->n; i++) {
        uint32_t m = c->map[old[i]];
        if (m != UINT32_MAX)
            old[na++] = m;
    }
    if (na != c->kept)
        return 0;
    if (np) {
        const bedge *P = &E[c->kept];
        if (!boolean_sort_two_keys(top ? &P->yt : &P->yb, top ? &P->xt : &P->xb, sizeof(bedge), np,
                                   tmp, s->scratch, s->scratch2))
            return 0;
        for (size_t i = 0; i < np; i++)
            tmp[i] += (uint32_t)c->kept;
    }
    size_t i = 0, j = 0, k = 0, lg = 1;
    while (((size_t)1 << lg) < na)
        lg++;
    if (np * lg < na) {
        /* few pieces (a search each costs less than a look at each kept
         * edge): the place of each among the kept edges by binary search,
         * the kept edges copied in blocks between them */
        for (; j < np; j++) {
            const bedge *p = &E[tmp[j]];
            size_t lo = i, hi = na;
            while (lo < hi) {
                size_t mid = lo + (hi - lo) / 2;
                if (edge_before(&E[old[mid]], p, top))
                    lo = mid + 1;
                else
                    hi = mid;
            }
            memcpy(out + k, old + i, (lo - i) * sizeof *out);
            k += lo - i;
            i = lo;
            out[k++] = tmp[j];
        }
        memcpy(out + k, old + i, (na - i) * sizeof *out);
        return 1;
    }
    while (i < na || j < np)
        out[k++] = j >= np || (i < na && edge_before(&E[old[i]], &E[tmp[j]], top)) ? old[i++]
                                                                                   : tmp[j++];
    return 1;
}

/* Sorts the edges by bottom and by top (from the last pass's orders when
 * there is one), the scanlines (both merged) and the horizontal edges: 0
 * when out of memory. */
NOINLINE static int sweep_sort(sweep *s, carry *c)
{
    engine *g = s->g;
    size_t ne = g->ne;
    keyval *scratch = s->scratch, *tmp = s->scratch2;
    /* edges by bottom and by top; the scanlines are both merged */
    int sorted = c->valid && merge_order(s, c, c->by_bottom, s->by_bottom, s->fresh, 0) &&
                 merge_order(s, c, c->by_top, s->by_top, s->dirty, 1);
    int from_last = sorted && c->ys_valid && c->nys + c->nsy <= 2 * (ne ? ne : 1);
    if (!sorted)
        sorted = !ne || (boolean_sort_two_keys(&g->E[0].yb, &g->E[0].xb, sizeof(bedge), ne,
                                               s->by_bottom, scratch, tmp) &&
                         boolean_sort_two_keys(&g->E[0].yt, &g->E[0].xt, sizeof(bedge), ne,
                                               s->by_top, scratch, tmp));
    /* the scanlines: the two orders merged, each with its next distinct y
     * at hand (INT64_MAX past its end; no y reaches it) */
    const bedge *E = g->E;
    size_t u = 0, i = 0, j = 0, n = sorted && !from_last ? ne : 0;
    if (from_last) {
        /* the last pass's scanlines merged with its split points' y */
        while (i < c->nys || j < c->nsy) {
            int64_t y =
                j == c->nsy || (i < c->nys && c->ys[i] <= c->sy[j]) ? c->ys[i++] : c->sy[j++];
            if (u == 0 || s->ys[u - 1] != y)
                s->ys[u++] = y;
        }
        i = j = 0;
    }
    int64_t yb = n ? E[s->by_bottom[0]].yb : INT64_MAX, yt = n ? E[s->by_top[0]].yt : INT64_MAX;
    const uint32_t *bb = s->by_bottom, *bt = s->by_top;
    int64_t *ys = s->ys;
    for (;;) {
        int64_t y = yb <= yt ? yb : yt;
        if (y == INT64_MAX) /* (no y reaches it) */
            break;
        /* past the edges with this bottom, with this top: the next y is
         * larger */
        while (yb == y)
            yb = ++i < n ? E[bb[i]].yb : INT64_MAX;
        while (yt == y)
            yt = ++j < n ? E[bt[j]].yt : INT64_MAX;
        ys[u++] = y;
    }
    s->nys = u;
#ifdef CG_CLIP_CHECK_YS
    if (from_last) {
        size_t v = 0;
        int64_t *all = malloc(2 * ne * sizeof *all);
        for (size_t q = 0; q < ne; q++) {
            all[v++] = E[q].yb;
            all[v++] = E[q].yt;
        }
        qsort(all, v, sizeof *all, cmp_i64);
        size_t w = 0;
        for (size_t q = 0; q < v; q++)
            if (!w || all[w - 1] != all[q])
                all[w++] = all[q];
        if (w != u || memcmp(all, s->ys, u * sizeof *all))
            abort();
        free(all);
    }
#endif
    if (sorted && g->nh > 1 && !(c->valid && c->nh_sorted == g->nh)) {
        sorted = boolean_sort_two_keys(&g->H[0].y, &g->H[0].x0, sizeof(hseg), g->nh, s->horder,
                                       scratch, tmp);
        if (sorted) {
            for (size_t i = 0; i < g->nh; i++)
                s->hsorted[i] = g->H[s->horder[i]];
            memcpy(g->H, s->hsorted, g->nh * sizeof *g->H);
        }
    }
    c->nh_sorted = g->nh;
    c->valid = 0;
    return sorted;
}

/* Keeps the orders of this pass for the next one (before boolean_apply_splits). */
static int carry_keep(carry *c, const sweep *s)
{
    size_t ne = s->g->ne;
    if (ne > c->cap) {
        size_t cap = ne + ne / 2;
        if (c->by_bottom != c->small)
            free(c->by_bottom); /* (the three arrays in one block) */
        c->cap = 0;
        c->by_bottom = malloc(3 * cap * sizeof *c->by_bottom);
        if (!c->by_bottom)
            return 0;
        c->by_top = c->by_bottom + cap;
        c->map = c->by_top + cap;
        c->cap = cap;
    }
    memcpy(c->by_bottom, s->by_bottom, ne * sizeof *c->by_bottom);
    memcpy(c->by_top, s->by_top, ne * sizeof *c->by_top);
    c->n = ne;
    /* the scanlines and the split points' y, when these are few */
    const engine *g = s->g;
    c->ys_valid = 0;
    if (g->ns > ne / 16)
        return 1;
    if (s->nys > c->capys) {
        free(c->ys);
        c->capys = 0;
        c->ys = malloc((s->nys + s->nys / 2) * sizeof *c->ys);
        if (!c->ys)
            return 0;
        c->capys = s->nys + s->nys / 2;
    }
    if (g->ns > c->capsy) {
        free(c->sy);
        c->capsy = 0;
        c->sy = malloc(g->ns * sizeof *c->sy);
        if (!c->sy)
            return 0;
        c->capsy = g->ns;
    }
    memcpy(c->ys, s->ys, s->nys * sizeof *c->ys);
    c->nys = s->nys;
    for (size_t i = 0; i < g->ns; i++)
        c->sy[i] = g->S[i].y;
    qsort(c->sy, g->ns, sizeof *c->sy, cmp_i64);
    c->nsy = g->ns;
    c->ys_valid = 1;
    return 1;
}

static int cmp_band(const void *a, const void *b)
{
    const int64_t *p = a, *q = b;
    return (p[0] > q[0]) - (p[0] < q[0]);
}

/* A block a call held (arr, room for cap) given back to a workspace slot
 * (slot, room for *slot_cap): the larger of the two stays, the other is
 * freed; the one kept is returned. */
static void *keep_larger(void *slot, size_t *slot_cap, void *arr, size_t cap)
{
    if (cap < *slot_cap) {
        free(arr);
        return slot;
    }
    free(slot);
    *slot_cap = cap;
    return arr;
}

/* Whether the first pass's split points are dense on the grid: more than
 * one in DENSE_AREA units of their bounds.  Rounding them then makes new
 * crossings pass after pass; complete snap rounding settles them at once. */
static int dense_crossings(const engine *g)
{
    if (g->ns < 1024)
        return 0;
    int64_t x0 = g->S[0].x, x1 = x0, y0 = g->S[0].y, y1 = y0;
    for (size_t k = 1; k < g->ns; k++) {
        x0 = g->S[k].x < x0 ? g->S[k].x : x0;
        x1 = g->S[k].x > x1 ? g->S[k].x : x1;
        y0 = g->S[k].y < y0 ? g->S[k].y : y0;
        y1 = g->S[k].y > y1 ? g->S[k].y : y1;
    }
    return ((double)(x1 - x0) + 1) * ((double)(y1 - y0) + 1) < DENSE_AREA * (double)g->ns;
}

static cg_status run_passes(engine *g, cg_polygon_set64 *result)
{
    sweep s;
    memset(&s, 0, sizeof s);
    s.g = g;
    /* small inputs: the sweep's block (and the assembly's, the splits')
     * on the stack, and the orders kept between passes */
    max_align_t mem_small[8192 / sizeof(max_align_t)];
    s.mem = s.mem_small = mem_small;
    s.memcap = sizeof mem_small;
    uint32_t carry_small[3 * 64];
    cg_status st = CG_ENOMEM;
    size_t visits = 0, edges = 0; /* of the last full sweep */
    carry c;
    memset(&c, 0, sizeof c);
    c.small = carry_small;
    c.by_bottom = carry_small;
    c.by_top = carry_small + 64;
    c.map = carry_small + 128;
    c.cap = 64;
    ck_log logs[2]; /* this pass's checkpoints, the last pass's */
    memset(logs, 0, sizeof logs);
    int cur = 0, can_resume = 0;
    /* the y ranges of the edges split by the last pass (merged), and its
     * pieces */
    int64_t(*bands)[2] = NULL;
    size_t nbands = 0;
    piece *saved = NULL; /* the first pass's pieces (when it classified) */
    size_t saved_cap = 0, (*ranges)[2] = NULL;
    int paired = g->ne + g->nh <= PAIRS_MAX_EDGES;
    int snapped = 0; /* a pass snapped completely (once is enough) */
    if (paired) {
        uint32_t map[PAIRS_MAX_EDGES];
        size_t kept;
        if (!boolean_add_pair_splits(g) || !boolean_apply_splits(g, map, &kept, s.mem, s.memcap))
            return CG_ENOMEM;
    }
    if (g->ws && g->ws->memcap > s.memcap) { /* (the workspace's block, taken) */
        s.mem = g->ws->mem;
        s.memcap = g->ws->memcap;
        g->ws->mem = NULL;
        g->ws->memcap = 0;
    }
    /* (the pairs' splits stand for the first pass) */
    for (int pass = paired;; pass++) {
        if (pass == MAX_PASSES) {
            st = CG_ERANGE;
            break;
        }
        /* After the first pass, most passes find nothing more to split.
         * The light sweep costs about LIGHT_COST active edges' worth of work
         * per edge; it is tried first when the full sweep was dearer. */
        int light = pass >= 1 && visits > LIGHT_COST * edges;
        sweep_reset(&s);
        if (!sweep_alloc(&s, light) || !sweep_sort(&s, &c))
            break;
        if (light) {
            g->np = 0;
            s.classify = 1;
            s.changed = 0;
            int r = boolean_light_sweep(&s);
            if (!r)
                break;
            if (r == 1) {
                st =
                    boolean_assemble(g, result, &s.mem, &s.memcap, s.mem_small) ? CG_OK : CG_ENOMEM;
                break;
            }
            /* something to split: start over with the full sweep */
            memset(s.run_open, 0, 4 * (g->ne ? g->ne : 1)); /* and run_up, brk, brk_next */
            g->ns = 0;
        }
        g->np = 0;
        s.classify = 1;
        s.changed = 0;
        /* later passes round on the pieces themselves, which settles
         * whatever the input-line rounding could not */
        s.use_input_lines = pass < 8;
        s.record_meets = pass == 0;
        if (can_resume && !light && nbands) {
            s.prev_map = c.map;
            s.prev_ne = c.n;
            s.prev_j = boolean_ck_load(&s, &logs[cur ^ 1], 0, bands[0][0]);
            size_t below = s.prev_j ? logs[cur ^ 1].pt[s.prev_j - 1].np : 0;
            if (saved) {
                /* its pieces stay where they are; this pass emits only
                 * those of the bands, and notes the ranges it takes */
                s.prev = &logs[cur ^ 1];
                s.bands = (const int64_t(*)[2])bands;
                s.nbands = nbands;
                s.ranges = ranges;
                if (below) {
                    ranges[0][0] = 0;
                    ranges[0][1] = below;
                    s.nranges = 1;
                }
            } else {
                g->np = below;
            }
        }
        ck_log *log = &logs[cur];
        log->npt = log->ned = 0;
        log->budget = g->ne / 2 + 256; /* (a small block: no fresh pages) */
        /* (later passes are nearly always the last; small inputs gain
         * less than the checkpoints cost) */
        s.log = pass == 0 && g->ne >= 128 ? log : NULL;
        s.ck_visits = 0;
        int r = boolean_run_sweep(&s);
        if (r <= 0) {
            if (r < 0)
                st = CG_ERANGE;
            break;
        }
        /* (a pass that started at a checkpoint looked at fewer edges than a
         * whole one would have: the last count stands unless larger) */
        if (!s.start_iy || s.visits > visits)
            visits = s.visits;
        edges = g->ne;
        if (saved && s.prev && s.nranges) {
            /* the pieces taken, then this pass's */
            size_t w = 0;
            for (size_t k = 0; k < s.nranges; k++) {
                memmove(saved + w, saved + ranges[k][0],
                        (ranges[k][1] - ranges[k][0]) * sizeof *saved);
                w += ranges[k][1] - ranges[k][0];
            }
            if (w + g->np > saved_cap) {
                piece *q = realloc(saved, (w + g->np) * sizeof *q);
                if (!q)
                    break;
                saved = q;
                saved_cap = w + g->np;
            }
            if (g->np)
                memcpy(saved + w, g->P, g->np * sizeof *saved);
            if (g->P != g->P_small)
                free(g->P);
            g->P = saved;
            g->capp = saved_cap;
            g->np += w;
            saved = NULL;
        }
        free(saved);
        saved = NULL;
        if (!s.changed) {
            st = boolean_assemble(g, result, &s.mem, &s.memcap, s.mem_small) ? CG_OK : CG_ENOMEM;
            break;
        }
        int snap_now =
            !snapped && (s.visits >= DENSE_VISITS * edges || (pass == 0 && dense_crossings(g)));
        if (pass >= 1 && !snap_now && !boolean_add_hot_pixel_splits(g, 0))
            break;
        free(bands);
        bands = NULL;
        nbands = 0;
        can_resume = 0;
        log->end_np = g->np;
        free(ranges);
        ranges = NULL;
        /* (else there is nothing to resume from; nor after complete snap
         * rounding, which splits nearly every edge) */
        if (log->npt && !snap_now) {
            /* (when this pass stopped classifying, only the lowest bottom is
             * of use: one band) */
            size_t nb = s.classify ? g->ns : 1;
            bands = malloc(nb * sizeof *bands);
            if (!bands)
                break;
            bands[0][0] = INT64_MAX;
            bands[0][1] = INT64_MIN;
            for (size_t i = 0; i < g->ns; i++) {
                const bedge *e = &g->E[g->S[i].edge];
                size_t k = nb == 1 ? 0 : i;
                bands[k][0] = nb == 1 && bands[0][0] < e->yb ? bands[0][0] : e->yb;
                bands[k][1] = nb == 1 && bands[0][1] > e->yt ? bands[0][1] : e->yt;
            }
            qsort(bands, nb, sizeof *bands, cmp_band);
            for (size_t i = 0; i < nb; i++) {
                if (nbands && bands[i][0] <= bands[nbands - 1][1]) {
                    if (bands[i][1] > bands[nbands - 1][1])
                        bands[nbands - 1][1] = bands[i][1];
                } else {
                    bands[nbands][0] = bands[i][0];
                    bands[nbands][1] = bands[i][1];
                    nbands++;
                }
            }
            can_resume = 1;
            if (pass == 0 && s.classify && g->np) {
                ranges = malloc((nbands + 1) * sizeof *ranges);
                if (ranges && g->P == g->P_small) { /* (saved is freed) */
                    piece *q = malloc(g->capp * sizeof *q);
                    if (q)
                        memcpy(q, g->P, g->np * sizeof *q);
                    else {
                        free(ranges);
                        ranges = NULL;
                    }
                    g->P = q ? q : g->P;
                }
                if (ranges) {
                    saved = g->P; /* (the next pass starts a new array) */
                    saved_cap = g->capp;
                    g->P = NULL;
                    g->capp = 0;
                    g->np = 0;
                }
            }
        }
        cur ^= 1;
        if (!carry_keep(&c, &s) ||
            !(snap_now ? boolean_snap_complete(g, c.map, &c.kept, s.mem, s.memcap)
                       : boolean_apply_splits(g, c.map, &c.kept, s.mem, s.memcap)))
            break;
        if (snap_now) {
            c.nh_sorted = 0; /* (its horizontal edges are put in order again) */
            snapped = 1;
        }
        c.valid = 1;
        if (g->ne > UINT32_MAX / 2) {
            st = CG_ERANGE; /* too many pieces for 32-bit edge numbers */
            break;
        }
    }
    if (s.mem != s.mem_small) {
        if (g->ws)
            g->ws->mem = keep_larger(g->ws->mem, &g->ws->memcap, s.mem, s.memcap);
        else
            free(s.mem);
    }
    for (int k = 0; k < 2; k++) {
        free(logs[k].pt);
        free(logs[k].ed);
    }
    free(saved);
    free(ranges);
    free(bands);
    if (c.by_bottom != c.small)
        free(c.by_bottom); /* (and by_top, map) */
    free(c.ys);
    free(c.sy);
    return st;
}

static cg_status load(engine *g, const cg_polygon_set64 *set, int op)
{
    if (!set)
        return CG_OK;
    if (set->ring_count && (!set->ring_start || (!set->points && set->point_count)))
        return CG_EINVAL; /* (rings with no points need no point array) */
    for (size_t r = 0; r < set->ring_count; r++) {
        size_t a = set->ring_start[r], b = set->ring_start[r + 1];
        if (b < a || b > set->point_count)
            return CG_EINVAL;
        for (size_t i = a; i < b; i++) {
            cg_point64 p = set->points[i];
            if (p.x > CG_CLIP_MAX_COORD || p.x < -CG_CLIP_MAX_COORD ||
                p.y > CG_CLIP_MAX_COORD || p.y < -CG_CLIP_MAX_COORD)
                return CG_ERANGE;
        }
        if (b - a < 2)
            continue;
        /* room for the ring's edges at once, then each written in place
         * (horizontal ones go to g->H) */
        if (g->cape - g->ne < b - a) {
            size_t c = g->ne + (b - a) + g->cape / 2 + 64;
            bedge *e = g->E == g->E_small ? malloc(c * sizeof *e) : realloc(g->E, c * sizeof *e);
            if (!e)
                return CG_ENOMEM;
            if (g->E == g->E_small && g->ne)
                memcpy(e, g->E, g->ne * sizeof *e);
            g->E = e;
            g->cape = c;
        }
        /* (held here: the byte stores below would make them be read
         * again) */
        const cg_point64 *pts = set->points;
        bedge *E = g->E;
        size_t ne = g->ne;
        for (size_t i = a; i < b; i++) {
            cg_point64 p = pts[i], q = pts[i + 1 < b ? i + 1 : a];
            if (p.y == q.y) { /* (to g->H) */
                if (!boolean_add_piece(g, p.x, p.y, q.x, q.y, op, NO_ORIG))
                    return CG_ENOMEM;
                continue;
            }
            bedge *e = &E[ne++];
            int up = p.y < q.y;
            cg_point64 lo = up ? p : q, hi = up ? q : p;
            e->xb = lo.x;
            e->yb = lo.y;
            e->xt = hi.x;
            e->yt = hi.y;
            e->orig = NO_ORIG;
            e->w = (int8_t)(up ? -1 : 1);
            e->op = (uint8_t)op;
            e->slope = (double)(hi.x - lo.x) / (double)(hi.y - lo.y);
        }
        g->ne = ne;
    }
    return CG_OK;
}

cg_clip_workspace *cg_clip_workspace_create(void)
{
    return calloc(1, sizeof(cg_clip_workspace));
}

void cg_clip_workspace_free(cg_clip_workspace *ws)
{
    if (!ws)
        return;
    free(ws->mem);
    free(ws->E);
    free(ws->P);
    free(ws);
}

cg_status cg_clip_boolean64(cg_clip_op op, const cg_polygon_set64 *subject,
                            cg_clip_fill subject_fill, const cg_polygon_set64 *clip,
                            cg_clip_fill clip_fill, cg_polygon_set64 *result)
{
    return cg_clip_boolean64_ws(NULL, op, subject, subject_fill, clip, clip_fill, result);
}

cg_status cg_clip_boolean64_ws(cg_clip_workspace *ws, cg_clip_op op,
                               const cg_polygon_set64 *subject, cg_clip_fill subject_fill,
                               const cg_polygon_set64 *clip, cg_clip_fill clip_fill,
                               cg_polygon_set64 *result)
{
    if (!result)
        return CG_EINVAL;
    if (result == subject || result == clip) {
        /* the result replaces an operand: computed beside it first */
        cg_polygon_set64 own = {0};
        cg_status st = cg_clip_boolean64_ws(ws, op, subject, subject_fill, clip, clip_fill, &own);
        cg_polygon_set64_clear(result);
        *result = own;
        return st;
    }
    /* emptied, its arrays kept: a result passed call after call is not
     * allocated again */
    result->point_count = result->ring_count = result->polygon_count = 0;
    if ((unsigned)op > CG_CLIP_XOR || (unsigned)subject_fill > CG_CLIP_NEGATIVE ||
        (unsigned)clip_fill > CG_CLIP_NEGATIVE)
        return CG_EINVAL;
    engine g;
    memset(&g, 0, sizeof g);
    g.ws = ws;
    g.op = op;
    g.fill[0] = subject_fill;
    g.fill[1] = clip_fill;
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            g.table[a * 2 + b] = (unsigned char)(op == CG_CLIP_INTERSECTION ? a && b
                                                 : op == CG_CLIP_UNION      ? a || b
                                                 : op == CG_CLIP_DIFFERENCE ? a && !b
                                                                            : a != b);
    for (int a = 0; a < 5; a++)
        for (int b = 0; b < 5; b++)
            g.near[a][b] = (unsigned char)inside_rule(&g, a - 2, b - 2);
    /* room for the input's edges and some pieces: no regrowth; on small
     * inputs the edges, split points and pieces start on the stack (most
     * calls then need no allocation for them) */
    bedge e_small[96];
    splitpt s_small[32];
    piece p_small[64];
    size_t npts = (subject ? subject->point_count : 0) + (clip ? clip->point_count : 0);
    if (npts && npts < UINT32_MAX / 4) {
        g.cape = npts + npts / 4 + 64;
        if (g.cape <= sizeof e_small / sizeof e_small[0]) {
            g.E = g.E_small = e_small;
            g.cape = sizeof e_small / sizeof e_small[0];
            g.S = g.S_small = s_small;
            g.caps = sizeof s_small / sizeof s_small[0];
            g.P = g.P_small = p_small;
            g.capp = sizeof p_small / sizeof p_small[0];
        } else if (ws && ws->cape >= g.cape) { /* (the workspace's, taken) */
            g.E = ws->E;
            g.cape = ws->cape;
            ws->E = NULL;
            ws->cape = 0;
        } else {
            g.E = malloc(g.cape * sizeof *g.E);
            if (!g.E)
                g.cape = 0;
        }
        if (ws && !g.P_small && ws->P) {
            g.P = ws->P;
            g.capp = ws->capp;
            ws->P = NULL;
            ws->capp = 0;
        }
    }
    cg_status st = load(&g, subject, 0);
    if (st == CG_OK)
        st = load(&g, clip, 1);
    if (st == CG_OK && g.ne > UINT32_MAX / 4)
        st = CG_ERANGE;
    if (st == CG_OK)
        st = run_passes(&g, result);
    if (st != CG_OK)
        cg_polygon_set64_clear(result);
    /* the edges and pieces back to the workspace, or freed */
    if (g.E != g.E_small) {
        if (ws)
            ws->E = keep_larger(ws->E, &ws->cape, g.E, g.cape);
        else
            free(g.E);
    }
    free(g.H);
    free(g.M);
    if (g.S != g.S_small)
        free(g.S);
    if (g.P != g.P_small) {
        if (ws)
            ws->P = keep_larger(ws->P, &ws->capp, g.P, g.capp);
        else
            free(g.P);
    }
    if (g.O != g.O_small)
        free(g.O);
    return st;
}
