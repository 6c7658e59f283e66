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
#include "../core/arena.h"

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

int boolean_add_edge(engine *g, int64_t x0, int64_t y0, int64_t x1, int64_t y1, int op,
                     uint32_t orig)
{
    if (y0 == y1) {
        if (x0 == x1)
            return 1;
        GROW(g->horizontals, g->horizontal_count, g->horizontal_capacity, return 0);
        g->horizontals[g->horizontal_count++] =
            (horizontal_edge){y0, x0 < x1 ? x0 : x1, x0 < x1 ? x1 : x0};
        return 1;
    }
    GROW_SMALL(g->edges, g->edge_count, g->edge_capacity, g->edges_small, return 0);
    edge *e = &g->edges[g->edge_count++];
    if (y0 < y1) {
        *e = (edge){x0, y0, x1, y1, 0, orig, -1, (uint8_t)op};
    } else {
        *e = (edge){x1, y1, x0, y0, 0, orig, 1, (uint8_t)op};
    }
    e->slope = (double)(e->x_top - e->x_bottom) / (double)(e->y_top - e->y_bottom);
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
    engine *g = s->engine;
    void *mem = s->block, *mem_small = s->block_small;
    size_t cap = s->block_size;
    memset(s, 0, sizeof *s);
    s->engine = g;
    s->block = mem;
    s->block_small = mem_small;
    s->block_size = cap;
}

/* The arrays of a pass over g's edges, taken from arena (measuring, then
 * carving; light: the light sweep's too). */
static void sweep_take_arrays(sweep *s, core_arena *arena, int light)
{
    size_t edge_room = s->engine->edge_count ? s->engine->edge_count : 1,
           horizontal_count = s->engine->horizontal_count;
    size_t sort_room = edge_room > horizontal_count ? edge_room : horizontal_count;
    uint32_t **edge_lists[] = {&s->by_bottom,        &s->by_top,     &s->active,
                               &s->next_active,      &s->starting,   &s->break_queue,
                               &s->break_queue_next, &s->point_edges};
    for (size_t i = 0; i < (light ? 8u : 7u); i++)
        *edge_lists[i] = core_arena_take(arena, edge_room, sizeof(uint32_t));
    s->run_x = core_arena_take(arena, edge_room, sizeof *s->run_x);
    s->run_y = core_arena_take(arena, edge_room, sizeof *s->run_y);
    s->winding_subject = core_arena_take(arena, edge_room, sizeof *s->winding_subject);
    s->winding_clip = core_arena_take(arena, edge_room, sizeof *s->winding_clip);
    s->x_current = core_arena_take(arena, edge_room, sizeof *s->x_current);
    s->x_next = core_arena_take(arena, edge_room, sizeof *s->x_next);
    s->scanlines = core_arena_take(arena, 2 * edge_room, sizeof *s->scanlines);
    /* dirty positions: new edges and run breaks at points, queued run
     * breaks, horizontal meets: each at most once per position */
    s->dirty = core_arena_take(arena, 3 * edge_room, sizeof *s->dirty);
    /* run_open, run_up, run_break, run_break_next in one block (cleared at
     * once) */
    s->run_open = core_arena_take(arena, 4 * edge_room, 1);
    s->sort_scratch = core_arena_take(arena, sort_room, sizeof *s->sort_scratch);
    s->sort_tmp = core_arena_take(arena, sort_room, sizeof *s->sort_tmp);
    s->horizontals_sorted = core_arena_take(arena, horizontal_count, sizeof *s->horizontals_sorted);
    s->horizontal_order = core_arena_take(arena, horizontal_count, sizeof *s->horizontal_order);
    if (light)
        s->seams = core_arena_take(arena, 3 * edge_room + 1, sizeof *s->seams);
}

/* The arrays of a pass over g's edges, carved from one block kept from pass
 * to pass (large blocks come fresh from the system, page by page, so fewer
 * and reused ones are much cheaper): 0 when out of memory. */
static int sweep_alloc(sweep *s, int light)
{
    core_arena measure = core_arena_measuring();
    sweep_take_arrays(s, &measure, light);
    if (measure.failed)
        return 0;
    size_t need = measure.used;
    /* (the next pass usually has a few more edges) */
    if (need > s->block_size && core_arena_block(&s->block, &s->block_size, need + need / 8 + 2048,
                                                 s->block_small) != CG_OK)
        return 0;
    core_arena carve = core_arena_on(s->block, s->block_size);
    sweep_take_arrays(s, &carve, light);
    size_t edge_room = s->engine->edge_count ? s->engine->edge_count : 1;
    s->run_up = s->run_open + edge_room;
    s->run_break = s->run_open + 2 * edge_room;
    s->run_break_next = s->run_open + 3 * edge_room;
    memset(s->run_open, 0, 4 * edge_room);
    s->break_queue_capacity = edge_room;
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
    uint32_t *block_small; /* the caller's block of 3 * 64 they start in */
    size_t edge_count, capacity; /* edges of the last pass (room for cap) */
    size_t kept; /* of them, not split: now g->edges[0..kept) */
    size_t horizontals_sorted; /* g->horizontals[0..horizontals_sorted) is in order */
    int valid;
    /* the last pass's scanlines and the distinct y of its split points
     * (sorted), when they were few: the next pass's scanlines are the two
     * merged (a split edge's pieces form a path from its bottom to its top,
     * so every scanline stays one, and each split point's y becomes one) */
    int64_t *scanlines, *split_ys;
    size_t scanline_count, split_y_count, scanline_capacity, split_y_capacity;
    int scanlines_valid;
} carry;

/* whether a goes before b (or ties) by (y_bottom, x_bottom), or by (y_top, x_top) when top */
static inline int edge_before(const edge *a, const edge *b, int top)
{
    int64_t a1 = top ? a->y_top : a->y_bottom, b1 = top ? b->y_top : b->y_bottom;
    if (a1 != b1)
        return a1 < b1;
    return (top ? a->x_top : a->x_bottom) <= (top ? b->x_top : b->x_bottom);
}

/* out = the edges kept (in their last order, renumbered) merged with the
 * pieces, sorted; tmp holds the pieces' order.  0 when the count is off. */
static int merge_order(sweep *s, const carry *c, uint32_t *old, uint32_t *out, uint32_t *tmp,
                       int top)
{
    engine *g = s->engine;
    const edge *edges = g->edges;
    size_t edge_count = g->edge_count, part_count = edge_count - c->kept, kept_count = 0;
    for (size_t i = 0; i < c->edge_count; i++) {
        uint32_t m = c->map[old[i]];
        if (m != UINT32_MAX)
            old[kept_count++] = m;
    }
    if (kept_count != c->kept)
        return 0;
    if (part_count) {
        const edge *parts = &edges[c->kept];
        if (!boolean_sort_two_keys(top ? &parts->y_top : &parts->y_bottom,
                                   top ? &parts->x_top : &parts->x_bottom, sizeof(edge), part_count,
                                   tmp, s->sort_scratch, s->sort_tmp))
            return 0;
        for (size_t i = 0; i < part_count; i++)
            tmp[i] += (uint32_t)c->kept;
    }
    size_t i = 0, j = 0, k = 0, lg = 1;
    while (((size_t)1 << lg) < kept_count)
        lg++;
    if (part_count * lg < kept_count) {
        /* few pieces (a search each costs less than a look at each kept
         * edge): the place of each among the kept edges by binary search,
         * the kept edges copied in blocks between them */
        for (; j < part_count; j++) {
            const edge *p = &edges[tmp[j]];
            size_t lo = i, hi = kept_count;
            while (lo < hi) {
                size_t mid = lo + (hi - lo) / 2;
                if (edge_before(&edges[old[mid]], p, top))
                    lo = mid + 1;
                else
                    hi = mid;
            }
            memcpy(out + k, old + i, (lo - i) * sizeof *out);
            k += lo - i;
            i = lo;
            out[k++] = tmp[j];
        }
        memcpy(out + k, old + i, (kept_count - i) * sizeof *out);
        return 1;
    }
    while (i < kept_count || j < part_count)
        out[k++] =
            j >= part_count || (i < kept_count && edge_before(&edges[old[i]], &edges[tmp[j]], top))
                ? old[i++]
                : tmp[j++];
    return 1;
}

/* Sorts the edges by bottom and by top (from the last pass's orders when
 * there is one), the scanlines (both merged) and the horizontal edges: 0
 * when out of memory. */
NOINLINE static int sweep_sort(sweep *s, carry *c)
{
    engine *g = s->engine;
    size_t edge_count = g->edge_count;
    keyval *scratch = s->sort_scratch, *tmp = s->sort_tmp;
    /* edges by bottom and by top; the scanlines are both merged */
    int sorted = c->valid && merge_order(s, c, c->by_bottom, s->by_bottom, s->starting, 0) &&
                 merge_order(s, c, c->by_top, s->by_top, s->dirty, 1);
    int from_last = sorted && c->scanlines_valid &&
                    c->scanline_count + c->split_y_count <= 2 * (edge_count ? edge_count : 1);
    if (!sorted)
        sorted = !edge_count ||
                 (boolean_sort_two_keys(&g->edges[0].y_bottom, &g->edges[0].x_bottom, sizeof(edge),
                                        edge_count, s->by_bottom, scratch, tmp) &&
                  boolean_sort_two_keys(&g->edges[0].y_top, &g->edges[0].x_top, sizeof(edge),
                                        edge_count, s->by_top, scratch, tmp));
    /* the scanlines: the two orders merged, each with its next distinct y
     * at hand (INT64_MAX past its end; no y reaches it) */
    const edge *edges = g->edges;
    size_t u = 0, i = 0, j = 0, n = sorted && !from_last ? edge_count : 0;
    if (from_last) {
        /* the last pass's scanlines merged with its split points' y */
        while (i < c->scanline_count || j < c->split_y_count) {
            int64_t y = j == c->split_y_count ||
                                (i < c->scanline_count && c->scanlines[i] <= c->split_ys[j])
                            ? c->scanlines[i++]
                            : c->split_ys[j++];
            if (u == 0 || s->scanlines[u - 1] != y)
                s->scanlines[u++] = y;
        }
        i = j = 0;
    }
    int64_t yb = n ? edges[s->by_bottom[0]].y_bottom : INT64_MAX,
            yt = n ? edges[s->by_top[0]].y_top : INT64_MAX;
    const uint32_t *bb = s->by_bottom, *bt = s->by_top;
    int64_t *ys = s->scanlines;
    for (;;) {
        int64_t y = yb <= yt ? yb : yt;
        if (y == INT64_MAX) /* (no y reaches it) */
            break;
        /* past the edges with this bottom, with this top: the next y is
         * larger */
        while (yb == y)
            yb = ++i < n ? edges[bb[i]].y_bottom : INT64_MAX;
        while (yt == y)
            yt = ++j < n ? edges[bt[j]].y_top : INT64_MAX;
        ys[u++] = y;
    }
    s->scanline_count = u;
#ifdef CG_CLIP_CHECK_YS
    if (from_last) {
        size_t v = 0;
        int64_t *all = malloc(2 * edge_count * sizeof *all);
        for (size_t q = 0; q < edge_count; q++) {
            all[v++] = edges[q].yb;
            all[v++] = edges[q].yt;
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
    if (sorted && g->horizontal_count > 1 &&
        !(c->valid && c->horizontals_sorted == g->horizontal_count)) {
        sorted = boolean_sort_two_keys(&g->horizontals[0].y, &g->horizontals[0].x_left,
                                       sizeof(horizontal_edge), g->horizontal_count,
                                       s->horizontal_order, scratch, tmp);
        if (sorted) {
            for (size_t i = 0; i < g->horizontal_count; i++)
                s->horizontals_sorted[i] = g->horizontals[s->horizontal_order[i]];
            memcpy(g->horizontals, s->horizontals_sorted,
                   g->horizontal_count * sizeof *g->horizontals);
        }
    }
    c->horizontals_sorted = g->horizontal_count;
    c->valid = 0;
    return sorted;
}

/* Keeps the orders of this pass for the next one (before boolean_apply_splits). */
static int carry_keep(carry *c, const sweep *s)
{
    size_t edge_count = s->engine->edge_count;
    if (edge_count > c->capacity) {
        size_t cap = edge_count + edge_count / 2;
        if (c->by_bottom != c->block_small)
            free(c->by_bottom); /* (the three arrays in one block) */
        c->capacity = 0;
        c->by_bottom = malloc(3 * cap * sizeof *c->by_bottom);
        if (!c->by_bottom)
            return 0;
        c->by_top = c->by_bottom + cap;
        c->map = c->by_top + cap;
        c->capacity = cap;
    }
    memcpy(c->by_bottom, s->by_bottom, edge_count * sizeof *c->by_bottom);
    memcpy(c->by_top, s->by_top, edge_count * sizeof *c->by_top);
    c->edge_count = edge_count;
    /* the scanlines and the split points' y, when these are few */
    const engine *g = s->engine;
    c->scanlines_valid = 0;
    if (g->split_count > edge_count / 16)
        return 1;
    if (s->scanline_count > c->scanline_capacity) {
        free(c->scanlines);
        c->scanline_capacity = 0;
        c->scanlines = malloc((s->scanline_count + s->scanline_count / 2) * sizeof *c->scanlines);
        if (!c->scanlines)
            return 0;
        c->scanline_capacity = s->scanline_count + s->scanline_count / 2;
    }
    if (g->split_count > c->split_y_capacity) {
        free(c->split_ys);
        c->split_y_capacity = 0;
        c->split_ys = malloc(g->split_count * sizeof *c->split_ys);
        if (!c->split_ys)
            return 0;
        c->split_y_capacity = g->split_count;
    }
    memcpy(c->scanlines, s->scanlines, s->scanline_count * sizeof *c->scanlines);
    c->scanline_count = s->scanline_count;
    for (size_t i = 0; i < g->split_count; i++)
        c->split_ys[i] = g->splits[i].y;
    qsort(c->split_ys, g->split_count, sizeof *c->split_ys, cmp_i64);
    c->split_y_count = g->split_count;
    c->scanlines_valid = 1;
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
    if (g->split_count < 1024)
        return 0;
    int64_t x0 = g->splits[0].x, x1 = x0, y0 = g->splits[0].y, y1 = y0;
    for (size_t k = 1; k < g->split_count; k++) {
        x0 = g->splits[k].x < x0 ? g->splits[k].x : x0;
        x1 = g->splits[k].x > x1 ? g->splits[k].x : x1;
        y0 = g->splits[k].y < y0 ? g->splits[k].y : y0;
        y1 = g->splits[k].y > y1 ? g->splits[k].y : y1;
    }
    return ((double)(x1 - x0) + 1) * ((double)(y1 - y0) + 1) < DENSE_AREA * (double)g->split_count;
}

static cg_status run_passes(engine *g, cg_polygon_set64 *result)
{
    sweep s;
    memset(&s, 0, sizeof s);
    s.engine = g;
    /* small inputs: the sweep's block (and the assembly's, the splits')
     * on the stack, and the orders kept between passes */
    max_align_t mem_small[8192 / sizeof(max_align_t)];
    s.block = s.block_small = mem_small;
    s.block_size = sizeof mem_small;
    uint32_t carry_small[3 * 64];
    cg_status st = CG_ENOMEM;
    size_t visits = 0, swept_edges = 0; /* of the last full sweep */
    carry c;
    memset(&c, 0, sizeof c);
    c.block_small = carry_small;
    c.by_bottom = carry_small;
    c.by_top = carry_small + 64;
    c.map = carry_small + 128;
    c.capacity = 64;
    ck_log logs[2]; /* this pass's checkpoints, the last pass's */
    memset(logs, 0, sizeof logs);
    int current_log = 0, can_resume = 0;
    /* the y ranges of the edges split by the last pass (merged), and its
     * pieces */
    int64_t(*bands)[2] = NULL;
    size_t band_count = 0;
    piece *saved = NULL; /* the first pass's pieces (when it classified) */
    size_t saved_capacity = 0, (*ranges)[2] = NULL;
    int paired = g->edge_count + g->horizontal_count <= PAIRS_MAX_EDGES;
    int snapped = 0; /* a pass snapped completely (once is enough) */
    if (paired) {
        uint32_t map[PAIRS_MAX_EDGES];
        size_t kept;
        if (!boolean_add_pair_splits(g) ||
            !boolean_apply_splits(g, map, &kept, s.block, s.block_size))
            return CG_ENOMEM;
    }
    if (g->workspace &&
        g->workspace->block_size > s.block_size) { /* (the workspace's block, taken) */
        s.block = g->workspace->block;
        s.block_size = g->workspace->block_size;
        g->workspace->block = NULL;
        g->workspace->block_size = 0;
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
        int light = pass >= 1 && visits > LIGHT_COST * swept_edges;
        sweep_reset(&s);
        if (!sweep_alloc(&s, light) || !sweep_sort(&s, &c))
            break;
        if (light) {
            g->piece_count = 0;
            s.classify = 1;
            s.changed = 0;
            int r = boolean_light_sweep(&s);
            if (!r)
                break;
            if (r == 1) {
                st = boolean_assemble(g, result, &s.block, &s.block_size, s.block_small)
                         ? CG_OK
                         : CG_ENOMEM;
                break;
            }
            /* something to split: start over with the full sweep */
            memset(s.run_open, 0,
                   4 * (g->edge_count ? g->edge_count
                                      : 1)); /* and run_up, run_break, run_break_next */
            g->split_count = 0;
        }
        g->piece_count = 0;
        s.classify = 1;
        s.changed = 0;
        /* later passes round on the pieces themselves, which settles
         * whatever the input-line rounding could not */
        s.use_input_lines = pass < 8;
        s.record_meets = pass == 0;
        if (can_resume && !light && band_count) {
            s.prev_map = c.map;
            s.prev_edge_count = c.edge_count;
            s.prev_checkpoint = boolean_ck_load(&s, &logs[current_log ^ 1], 0, bands[0][0]);
            size_t below =
                s.prev_checkpoint
                    ? logs[current_log ^ 1].checkpoints[s.prev_checkpoint - 1].piece_count
                    : 0;
            if (saved) {
                /* its pieces stay where they are; this pass emits only
                 * those of the bands, and notes the ranges it takes */
                s.prev_log = &logs[current_log ^ 1];
                s.bands = (const int64_t(*)[2])bands;
                s.band_count = band_count;
                s.taken_ranges = ranges;
                if (below) {
                    ranges[0][0] = 0;
                    ranges[0][1] = below;
                    s.taken_count = 1;
                }
            } else {
                g->piece_count = below;
            }
        }
        ck_log *log = &logs[current_log];
        log->checkpoint_count = log->edge_count = 0;
        log->budget = g->edge_count / 2 + 256; /* (a small block: no fresh pages) */
        /* (later passes are nearly always the last; small inputs gain
         * less than the checkpoints cost) */
        s.log = pass == 0 && g->edge_count >= 128 ? log : NULL;
        s.checkpoint_visits = 0;
        int r = boolean_run_sweep(&s);
        if (r <= 0) {
            if (r < 0)
                st = CG_ERANGE;
            break;
        }
        /* (a pass that started at a checkpoint looked at fewer edges than a
         * whole one would have: the last count stands unless larger) */
        if (!s.start_scanline || s.visits > visits)
            visits = s.visits;
        swept_edges = g->edge_count;
        if (saved && s.prev_log && s.taken_count) {
            /* the pieces taken, then this pass's */
            size_t w = 0;
            for (size_t k = 0; k < s.taken_count; k++) {
                memmove(saved + w, saved + ranges[k][0],
                        (ranges[k][1] - ranges[k][0]) * sizeof *saved);
                w += ranges[k][1] - ranges[k][0];
            }
            if (w + g->piece_count > saved_capacity) {
                piece *q = realloc(saved, (w + g->piece_count) * sizeof *q);
                if (!q)
                    break;
                saved = q;
                saved_capacity = w + g->piece_count;
            }
            if (g->piece_count)
                memcpy(saved + w, g->pieces, g->piece_count * sizeof *saved);
            if (g->pieces != g->pieces_small)
                free(g->pieces);
            g->pieces = saved;
            g->piece_capacity = saved_capacity;
            g->piece_count += w;
            saved = NULL;
        }
        free(saved);
        saved = NULL;
        if (!s.changed) {
            st = boolean_assemble(g, result, &s.block, &s.block_size, s.block_small) ? CG_OK
                                                                                     : CG_ENOMEM;
            break;
        }
        int snap_now = !snapped && (s.visits >= DENSE_VISITS * swept_edges ||
                                    (pass == 0 && dense_crossings(g)));
        if (pass >= 1 && !snap_now && !boolean_add_hot_pixel_splits(g, 0))
            break;
        free(bands);
        bands = NULL;
        band_count = 0;
        can_resume = 0;
        log->end_piece_count = g->piece_count;
        free(ranges);
        ranges = NULL;
        /* (else there is nothing to resume from; nor after complete snap
         * rounding, which splits nearly every edge) */
        if (log->checkpoint_count && !snap_now) {
            /* (when this pass stopped classifying, only the lowest bottom is
             * of use: one band) */
            size_t nb = s.classify ? g->split_count : 1;
            bands = malloc(nb * sizeof *bands);
            if (!bands)
                break;
            bands[0][0] = INT64_MAX;
            bands[0][1] = INT64_MIN;
            for (size_t i = 0; i < g->split_count; i++) {
                const edge *e = &g->edges[g->splits[i].edge];
                size_t k = nb == 1 ? 0 : i;
                bands[k][0] = nb == 1 && bands[0][0] < e->y_bottom ? bands[0][0] : e->y_bottom;
                bands[k][1] = nb == 1 && bands[0][1] > e->y_top ? bands[0][1] : e->y_top;
            }
            qsort(bands, nb, sizeof *bands, cmp_band);
            for (size_t i = 0; i < nb; i++) {
                if (band_count && bands[i][0] <= bands[band_count - 1][1]) {
                    if (bands[i][1] > bands[band_count - 1][1])
                        bands[band_count - 1][1] = bands[i][1];
                } else {
                    bands[band_count][0] = bands[i][0];
                    bands[band_count][1] = bands[i][1];
                    band_count++;
                }
            }
            can_resume = 1;
            if (pass == 0 && s.classify && g->piece_count) {
                ranges = malloc((band_count + 1) * sizeof *ranges);
                if (ranges && g->pieces == g->pieces_small) { /* (saved is freed) */
                    piece *q = malloc(g->piece_capacity * sizeof *q);
                    if (q)
                        memcpy(q, g->pieces, g->piece_count * sizeof *q);
                    else {
                        free(ranges);
                        ranges = NULL;
                    }
                    g->pieces = q ? q : g->pieces;
                }
                if (ranges) {
                    saved = g->pieces; /* (the next pass starts a new array) */
                    saved_capacity = g->piece_capacity;
                    g->pieces = NULL;
                    g->piece_capacity = 0;
                    g->piece_count = 0;
                }
            }
        }
        current_log ^= 1;
        if (!carry_keep(&c, &s) ||
            !(snap_now ? boolean_snap_complete(g, c.map, &c.kept, s.block, s.block_size)
                       : boolean_apply_splits(g, c.map, &c.kept, s.block, s.block_size)))
            break;
        if (snap_now) {
            c.horizontals_sorted = 0; /* (its horizontal edges are put in order again) */
            snapped = 1;
        }
        c.valid = 1;
        if (g->edge_count > UINT32_MAX / 2) {
            st = CG_ERANGE; /* too many pieces for 32-bit edge numbers */
            break;
        }
    }
    if (s.block != s.block_small) {
        if (g->workspace)
            g->workspace->block =
                keep_larger(g->workspace->block, &g->workspace->block_size, s.block, s.block_size);
        else
            free(s.block);
    }
    for (int k = 0; k < 2; k++) {
        free(logs[k].checkpoints);
        free(logs[k].edges);
    }
    free(saved);
    free(ranges);
    free(bands);
    if (c.by_bottom != c.block_small)
        free(c.by_bottom); /* (and by_top, map) */
    free(c.scanlines);
    free(c.split_ys);
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
         * (horizontal ones go to g->horizontals) */
        if (g->edge_capacity - g->edge_count < b - a) {
            size_t c = g->edge_count + (b - a) + g->edge_capacity / 2 + 64;
            edge *e = g->edges == g->edges_small ? malloc(c * sizeof *e)
                                                 : realloc(g->edges, c * sizeof *e);
            if (!e)
                return CG_ENOMEM;
            if (g->edges == g->edges_small && g->edge_count)
                memcpy(e, g->edges, g->edge_count * sizeof *e);
            g->edges = e;
            g->edge_capacity = c;
        }
        /* (held here: the byte stores below would make them be read
         * again) */
        const cg_point64 *pts = set->points;
        edge *edges = g->edges;
        size_t edge_count = g->edge_count;
        for (size_t i = a; i < b; i++) {
            cg_point64 p = pts[i], q = pts[i + 1 < b ? i + 1 : a];
            if (p.y == q.y) { /* (to g->horizontals) */
                if (!boolean_add_edge(g, p.x, p.y, q.x, q.y, op, NO_ORIG))
                    return CG_ENOMEM;
                continue;
            }
            edge *e = &edges[edge_count++];
            int up = p.y < q.y;
            cg_point64 lo = up ? p : q, hi = up ? q : p;
            e->x_bottom = lo.x;
            e->y_bottom = lo.y;
            e->x_top = hi.x;
            e->y_top = hi.y;
            e->input_edge = NO_ORIG;
            e->winding = (int8_t)(up ? -1 : 1);
            e->operand = (uint8_t)op;
            e->slope = (double)(hi.x - lo.x) / (double)(hi.y - lo.y);
        }
        g->edge_count = edge_count;
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
    free(ws->block);
    free(ws->edges);
    free(ws->pieces);
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
    g.workspace = ws;
    g.operation = op;
    g.fill[0] = subject_fill;
    g.fill[1] = clip_fill;
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            g.in_result[a * 2 + b] = (unsigned char)(op == CG_CLIP_INTERSECTION ? a && b
                                                     : op == CG_CLIP_UNION      ? a || b
                                                     : op == CG_CLIP_DIFFERENCE ? a && !b
                                                                                : a != b);
    for (int a = 0; a < 5; a++)
        for (int b = 0; b < 5; b++)
            g.in_result_near[a][b] = (unsigned char)inside_rule(&g, a - 2, b - 2);
    /* room for the input's edges and some pieces: no regrowth; on small
     * inputs the edges, split points and pieces start on the stack (most
     * calls then need no allocation for them) */
    edge e_small[96];
    split_point s_small[32];
    piece p_small[64];
    size_t npts = (subject ? subject->point_count : 0) + (clip ? clip->point_count : 0);
    if (npts && npts < UINT32_MAX / 4) {
        g.edge_capacity = npts + npts / 4 + 64;
        if (g.edge_capacity <= sizeof e_small / sizeof e_small[0]) {
            g.edges = g.edges_small = e_small;
            g.edge_capacity = sizeof e_small / sizeof e_small[0];
            g.splits = g.splits_small = s_small;
            g.split_capacity = sizeof s_small / sizeof s_small[0];
            g.pieces = g.pieces_small = p_small;
            g.piece_capacity = sizeof p_small / sizeof p_small[0];
        } else if (ws && ws->edge_capacity >= g.edge_capacity) { /* (the workspace's, taken) */
            g.edges = ws->edges;
            g.edge_capacity = ws->edge_capacity;
            ws->edges = NULL;
            ws->edge_capacity = 0;
        } else {
            g.edges = malloc(g.edge_capacity * sizeof *g.edges);
            if (!g.edges)
                g.edge_capacity = 0;
        }
        if (ws && !g.pieces_small && ws->pieces) {
            g.pieces = ws->pieces;
            g.piece_capacity = ws->piece_capacity;
            ws->pieces = NULL;
            ws->piece_capacity = 0;
        }
    }
    cg_status st = load(&g, subject, 0);
    if (st == CG_OK)
        st = load(&g, clip, 1);
    if (st == CG_OK && g.edge_count > UINT32_MAX / 4)
        st = CG_ERANGE;
    if (st == CG_OK)
        st = run_passes(&g, result);
    if (st != CG_OK)
        cg_polygon_set64_clear(result);
    /* the edges and pieces back to the workspace, or freed */
    if (g.edges != g.edges_small) {
        if (ws)
            ws->edges = keep_larger(ws->edges, &ws->edge_capacity, g.edges, g.edge_capacity);
        else
            free(g.edges);
    }
    free(g.horizontals);
    free(g.meets);
    if (g.splits != g.splits_small)
        free(g.splits);
    if (g.pieces != g.pieces_small) {
        if (ws)
            ws->pieces = keep_larger(ws->pieces, &ws->piece_capacity, g.pieces, g.piece_capacity);
        else
            free(g.pieces);
    }
    if (g.input_edges != g.input_edges_small)
        free(g.input_edges);
    return st;
}
