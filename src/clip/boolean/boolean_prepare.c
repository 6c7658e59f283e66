/* A pass's arrays and orders for the boolean operations: the sweep's
 * block carved for the pass, the edges sorted by bottom and by top (merged
 * from the last pass's orders when there is one), the scanlines and the
 * horizontal edges in order, and what a pass keeps for the next. */
#include "boolean_engine.h"
#include "../../core/arena.h"
#include "../../core/sort.h"

/* Forgets the arrays of the last pass; their memory is kept for the next. */
void boolean_sweep_reset(sweep *s)
{
    engine *g = s->engine;
    void *block = s->block, *block_small = s->block_small;
    size_t block_size = s->block_size;
    memset(s, 0, sizeof *s);
    s->engine = g;
    s->block = block;
    s->block_small = block_small;
    s->block_size = block_size;
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
int boolean_sweep_alloc(sweep *s, int light)
{
    core_arena measure = core_arena_measuring();
    sweep_take_arrays(s, &measure, light);
    if (measure.failed)
        return 0;
    size_t need = measure.used;
    /* (the next pass usually has a few more edges) */
    if (need > s->block_size
        && core_arena_block(&s->block, &s->block_size, need + need / 8 + 2048, s->block_small)
               != CG_OK)
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
        out[k++] = j >= part_count
                           || (i < kept_count && edge_before(&edges[old[i]], &edges[tmp[j]], top))
                       ? old[i++]
                       : tmp[j++];
    return 1;
}

/* Sorts the edges by bottom and by top (from the last pass's orders when
 * there is one), the scanlines (both merged) and the horizontal edges: 0
 * when out of memory. */
int boolean_sweep_sort(sweep *s, carry *c)
{
    engine *g = s->engine;
    size_t edge_count = g->edge_count;
    keyval *scratch = s->sort_scratch, *tmp = s->sort_tmp;
    /* edges by bottom and by top; the scanlines are both merged */
    int sorted = c->valid && merge_order(s, c, c->by_bottom, s->by_bottom, s->starting, 0)
                 && merge_order(s, c, c->by_top, s->by_top, s->dirty, 1);
    int from_last = sorted && c->scanlines_valid
                    && c->scanline_count + c->split_y_count <= 2 * (edge_count ? edge_count : 1);
    if (!sorted)
        sorted = !edge_count
                 || (boolean_sort_two_keys(&g->edges[0].y_bottom, &g->edges[0].x_bottom,
                                           sizeof(edge), edge_count, s->by_bottom, scratch, tmp)
                     && boolean_sort_two_keys(&g->edges[0].y_top, &g->edges[0].x_top, sizeof(edge),
                                              edge_count, s->by_top, scratch, tmp));
    /* the scanlines: the two orders merged, each with its next distinct y
     * at hand (INT64_MAX past its end; no y reaches it) */
    const edge *edges = g->edges;
    size_t u = 0, i = 0, j = 0, n = sorted && !from_last ? edge_count : 0;
    if (from_last) {
        /* the last pass's scanlines merged with its split points' y */
        while (i < c->scanline_count || j < c->split_y_count) {
            int64_t y = j == c->split_y_count
                                || (i < c->scanline_count && c->scanlines[i] <= c->split_ys[j])
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
        core_sort(all, v, sizeof *all, cmp_i64);
        size_t w = 0;
        for (size_t q = 0; q < v; q++)
            if (!w || all[w - 1] != all[q])
                all[w++] = all[q];
        if (w != u || memcmp(all, s->ys, u * sizeof *all))
            abort();
        free(all);
    }
#endif
    if (sorted && g->horizontal_count > 1
        && !(c->valid && c->horizontals_sorted == g->horizontal_count)) {
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
int boolean_carry_keep(carry *c, const sweep *s)
{
    size_t edge_count = s->engine->edge_count;
    if (edge_count > c->capacity) {
        size_t room = edge_count + edge_count / 2;
        if (c->by_bottom != c->block_small)
            free(c->by_bottom); /* (the three arrays in one block) */
        c->capacity = 0;
        c->by_bottom = malloc(3 * room * sizeof *c->by_bottom);
        if (!c->by_bottom)
            return 0;
        c->by_top = c->by_bottom + room;
        c->map = c->by_top + room;
        c->capacity = room;
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
    core_sort(c->split_ys, g->split_count, sizeof *c->split_ys, cmp_i64);
    c->split_y_count = g->split_count;
    c->scanlines_valid = 1;
    return 1;
}
