/* The full sweep of a pass of the boolean operations: scanline by
 * scanline, the active list above it built from the one below, the
 * horizontal edges on it, the order at the next scanline checked (what
 * crosses is split), and, while the pass classifies, the beam classified
 * and its boundary pieces emitted. */
#include "boolean_scan.h"

/* x lies within a unit of [a, b] or [b, a] */
static inline int near_span(double x, double a, double b)
{
    return a < b ? x >= a - 1 && x <= b + 1 : x >= b - 1 && x <= a + 1;
}

/* the bottom of edge by_bottom[next_start], the next to start (INT64_MAX
 * when none is left: no y reaches it) */
static inline int64_t bottom_of_next(const sweep *s, size_t next_start)
{
    return next_start < s->engine->edge_count ? s->engine->edges[s->by_bottom[next_start]].y_bottom
                                              : INT64_MAX;
}

/* x of e at y, y above its bottom (by the slope, exact at its top) */
static inline double x_above(const edge *e, int64_t y)
{
    return y == e->y_top ? (double)e->x_top
                         : (double)e->x_bottom + (double)(y - e->y_bottom) * e->slope;
}

/* Edge e put at above[above_count] (the count with it returned), x_next its
 * x at the next scanline: the order there is checked on the way, *last the
 * x of the edge before, *check_from the first position out of order
 * (SIZE_MAX while none is) */
static inline size_t take_in_order(uint32_t *above, size_t above_count, uint32_t e, double x_next,
                                   double *last, size_t *check_from)
{
    if (x_next > *last + 0.01)
        *last = x_next;
    else if (*check_from == SIZE_MAX)
        *check_from = above_count;
    above[above_count] = e;
    return above_count + 1;
}

/* One scanline of the full sweep: where it is, and the lists it builds. */
typedef struct scanline_state {
    int64_t y, y_next;       /* this scanline, the next (y itself at the last) */
    uint32_t *below, *above; /* the active list below y; above it (being built) */
    size_t below_count, above_count;
    size_t starting_count; /* the edges starting at y: s->starting[0..starting_count) */
    /* the edges ending at y, by_top[ending_first..ending_end), when looked
     * up (among many passing edges only) */
    size_t ending_first, ending_end;
    size_t dirty_count; /* positions in s->dirty */
    int dirty_sorted;
    /* the order at y_next is checked from above[check_from] on, after
     * `last` (x at y_next of above[check_from - 1], or -INFINITY) */
    double last;
    size_t check_from;
    size_t queued;  /* run breaks queued for y, in s->break_queue */
    int queue_full; /* more were: every position is looked at */
} scanline_state;

/* The hand-over from the last pass: between the edges it split, its results
 * hold from the first checkpoint where the states agree to the last one
 * below the next split edge.  At such a checkpoint at y, its pieces up to
 * there are taken: 2 when that is the rest of the pass; 1 when the sweep
 * jumps to that last checkpoint (*scanline, *next_start and *next_end
 * moved); 0 when the sweep goes on; -1 when the checkpoints are not as
 * expected (cannot happen). */
static ALWAYS_INLINE int take_last_pass(sweep *s, int64_t y, size_t *scanline, size_t *next_start,
                                        size_t *next_end)
{
    while (s->band < s->band_count && s->bands[s->band][1] < y)
        s->band++;
    if (s->band == 0 || s->changed || (s->band < s->band_count && y > s->bands[s->band][0]))
        return 0;
    const struct ck_log *last = s->prev_log;
    while (s->prev_checkpoint < last->checkpoint_count
           && last->checkpoints[s->prev_checkpoint].scanline_y < y)
        s->prev_checkpoint++;
    if (s->prev_checkpoint == last->checkpoint_count
        || last->checkpoints[s->prev_checkpoint].scanline_y != y
        || !boolean_ck_same(s, &last->checkpoints[s->prev_checkpoint]))
        return 0;
    size_t from = last->checkpoints[s->prev_checkpoint].piece_count, to = last->end_piece_count,
           j = 0;
    if (s->band < s->band_count) {
        j = boolean_ck_load(s, last, s->prev_checkpoint, s->bands[s->band][0]);
        if (!CG_INVARIANT(j != 0)) /* prev_checkpoint itself is one */
            return -1;
        to = last->checkpoints[j - 1].piece_count;
    }
    s->taken_ranges[s->taken_count][0] = from;
    s->taken_ranges[s->taken_count][1] = to;
    s->taken_count++;
    if (!j)
        return 2;
    s->prev_checkpoint = j;
    *scanline = s->start_scanline;
    *next_start = s->start_bottom;
    *next_end = s->start_top;
    return 1;
}

/* The edges starting at line->y in s->starting, by x, ties by x at y_next
 * (their x there noted): next_start moves past them. */
static ALWAYS_INLINE void gather_starting(sweep *s, scanline_state *line, size_t *next_start,
                                          int64_t *y_start)
{
    const edge *edges = s->engine->edges;
    uint32_t *starting = s->starting;
    double *x_current = s->x_current, *x_next = s->x_next;
    size_t starting_count = 0;
    while (*y_start == line->y) {
        uint32_t e = s->by_bottom[(*next_start)++];
        *y_start = bottom_of_next(s, *next_start);
        x_current[e] = (double)edges[e].x_bottom;
        x_next[e] = x_at(&edges[e], line->y_next);
        size_t m = starting_count;
        while (m > 0 && edges[starting[m - 1]].x_bottom == edges[e].x_bottom
               && cmp_x(&edges[starting[m - 1]], &edges[e], line->y_next, x_next[starting[m - 1]],
                        x_next[e])
                      > 0) {
            starting[m] = starting[m - 1];
            m--;
        }
        starting[m] = e;
        starting_count++;
    }
    line->starting_count = starting_count;
}

/* The list above y among few passing edges: one look at each, which also
 * takes x at y_next and checks the order there up to the first inversion
 * (check_from).  0 when out of memory. */
static ALWAYS_INLINE int above_by_looking_at_each(sweep *s, scanline_state *line)
{
    const edge *edges = s->engine->edges;
    const uint32_t *below = line->below, *starting = s->starting;
    uint32_t *above = line->above, *dirty = s->dirty;
    const double *x_current = s->x_current;
    double *x_next = s->x_next;
    int64_t y = line->y, y_next = line->y_next;
    size_t above_count = 0, dirty_count = 0, starting_at = 0;
    size_t starting_count = line->starting_count, check_from = SIZE_MAX;
    double last = -INFINITY;
    for (size_t k = 0; k < line->below_count; k++) {
        uint32_t e = below[k];
        const edge *ee = &edges[e];
        if (ends_at(ee, y)) {
            if (s->classify && s->run_open[e] && !boolean_close_run(s, e, y))
                return 0;
            continue;
        }
        while (starting_at < starting_count) {
            uint32_t f = starting[starting_at];
            double xf = x_current[f];
            int c = x_current[e] < xf - 0.01 ? -1 : cmp_x(ee, &edges[f], y, x_current[e], xf);
            if (c < 0)
                break;
            if (c == 0) {
                /* a new edge starts on a passing one: a vertex there */
                if (!boolean_meet(s, e, y, 0))
                    return 0;
                break; /* the order at y_next is settled below */
            }
            dirty[dirty_count++] = (uint32_t)above_count;
            above_count = take_in_order(above, above_count, f, x_next[f], &last, &check_from);
            starting_at++;
        }
        if (s->run_break[e])
            dirty[dirty_count++] = (uint32_t)above_count;
        double xe = x_above(ee, y_next);
        x_next[e] = xe;
        above_count = take_in_order(above, above_count, e, xe, &last, &check_from);
    }
    while (starting_at < starting_count) {
        dirty[dirty_count++] = (uint32_t)above_count;
        uint32_t f = starting[starting_at++];
        above_count = take_in_order(above, above_count, f, x_next[f], &last, &check_from);
    }
    if (check_from == SIZE_MAX)
        check_from = above_count;
    else
        last = check_from ? x_next[above[check_from - 1]] : -INFINITY;
    line->above_count = above_count;
    line->dirty_count = dirty_count;
    line->check_from = check_from;
    line->last = last;
    return 1;
}

/* The positions of the edges whose runs break at y (queued at the top of
 * the last beam) made dirty: by binary search on x, or, when the queue
 * overflowed, by a look at every position. */
static ALWAYS_INLINE void dirty_run_breaks(sweep *s, scanline_state *line)
{
    const edge *edges = s->engine->edges;
    const uint32_t *above = line->above;
    const double *x_current = s->x_current;
    uint32_t *dirty = s->dirty;
    size_t above_count = line->above_count;
    if (line->queue_full) {
        for (size_t k = 0; k < above_count; k++)
            if (s->run_break[above[k]])
                dirty[line->dirty_count++] = (uint32_t)k;
        line->dirty_sorted = 0;
        return;
    }
    if (!line->queued || !s->classify)
        return;
    for (size_t k = 0; k < line->queued; k++) {
        uint32_t e = s->break_queue[k];
        if (edges[e].y_top <= line->y)
            continue;
        double xe = x_current[e];
        size_t lo = 0, hi = above_count;
        while (lo < hi) {
            size_t mid = lo + (hi - lo) / 2;
            if (x_current[above[mid]] < xe - 0.5)
                lo = mid + 1;
            else
                hi = mid;
        }
        while (lo < above_count && above[lo] != e)
            lo++;
        if (lo < above_count) {
            dirty[line->dirty_count++] = (uint32_t)lo;
            line->dirty_sorted = 0;
        }
    }
}

/* The list above y among many passing edges: the passing edges in their
 * order (sorted at y by the last beam) with the ending ones taken out and
 * the new ones put in, at the points where edges end or start (found by
 * binary search); passing edges through such a point need a vertex there.
 * 0 when out of memory, -1 when the active list was not in order. */
static ALWAYS_INLINE int above_by_events(sweep *s, scanline_state *line)
{
    const edge *edges = s->engine->edges;
    const uint32_t *below = line->below, *starting = s->starting;
    uint32_t *above = line->above, *dirty = s->dirty;
    const double *x_current = s->x_current;
    int64_t y = line->y;
    size_t above_count = 0, dirty_count = 0, starting_at = 0, below_count = line->below_count;
    size_t ending_at = line->ending_first, below_at = 0, ended = 0;
    while (starting_at < line->starting_count || ending_at < line->ending_end) {
        size_t f0;
        int64_t X = next_event(edges, starting, line->starting_count, &starting_at, s->by_top,
                               line->ending_end, &ending_at, &f0);
        size_t lo = first_at_x(edges, below, below_at, below_count, y, X, x_current);
        copy_ids(above + above_count, below + below_at, lo - below_at);
        above_count += lo - below_at;
        below_at = lo;
        while (below_at < below_count
               && cmp_xi(&edges[below[below_at]], y, X, x_current[below[below_at]]) == 0) {
            uint32_t e = below[below_at++];
            if (ends_at(&edges[e], y)) {
                ended++;
                if (s->classify && s->run_open[e] && !boolean_close_run(s, e, y))
                    return 0;
                continue;
            }
            if (starting_at > f0 && !boolean_meet(s, e, y, 0))
                return 0;
            dirty[dirty_count++] = (uint32_t)above_count;
            above[above_count++] = e;
        }
        for (size_t k = f0; k < starting_at; k++) {
            dirty[dirty_count++] = (uint32_t)above_count;
            above[above_count++] = starting[k];
        }
    }
    copy_ids(above + above_count, below + below_at, below_count - below_at);
    above_count += below_count - below_at;
    if (!CG_INVARIANT(ended == line->ending_end - line->ending_first)) /* sorted as expected */
        return -1;
    line->above_count = above_count;
    line->dirty_count = dirty_count;
    line->check_from = 0;
    line->last = -INFINITY;
    dirty_run_breaks(s, line);
    return 1;
}

/* Edges u and v (u left of v at y) cross strictly inside the beam: the
 * crossing of the input edges they come from, rounded, when it lies in the
 * beam within a unit of both pieces (no drift), else the crossing of the
 * pieces, a split point of both.  (Pieces bent by earlier splits can cross
 * far from where their input edges do: a split there would bend them by
 * units, and on coarse grids that went on pass after pass.)  0 when out
 * of memory. */
static int split_crossing(sweep *s, int64_t y, int64_t y_next, uint32_t u, uint32_t v)
{
    const engine *g = s->engine;
    const edge *a = &g->edges[u], *b = &g->edges[v];
    const double *x_current = s->x_current, *x_next = s->x_next;
    int64_t px, py, oa[4], ob[4];
    edge_orig(g, a, oa);
    edge_orig(g, b, ob);
    if (!s->use_input_lines
        || !boolean_line_intersection(oa[0], oa[1], oa[2], oa[3], ob[0], ob[1], ob[2], ob[3], &px,
                                      &py)
        || py < y || py > y_next || !near_span((double)px, x_current[u], x_next[u])
        || !near_span((double)px, x_current[v], x_next[v])) {
        boolean_line_intersection(a->x_bottom, a->y_bottom, a->x_top, a->y_top, b->x_bottom,
                                  b->y_bottom, b->x_top, b->y_top, &px, &py);
    }
    if (py < y)
        py = y;
    if (py > y_next)
        py = y_next;
    return boolean_add_split(s, u, px, py) && boolean_add_split(s, v, px, py);
}

/* above[k] is left of above[k - 1] at y_next (an inversion): moved down to
 * its place there, the edges it passes that it crosses inside the beam
 * split (their positions widen [*cross_lo, *cross_hi]), those it meets at
 * y_next given their vertex.  0 when out of memory.  (Out of line: the
 * exact tests would crowd the registers of the loop over the list.) */
NOINLINE static int settle_inversion(sweep *s, uint32_t *above, size_t k, int64_t y, int64_t y_next,
                                     size_t *cross_lo, size_t *cross_hi)
{
    const edge *edges = s->engine->edges;
    const double *x_current = s->x_current, *x_next = s->x_next;
    uint32_t v = above[k];
    size_t m = k;
    while (m > 0) {
        uint32_t u = above[m - 1];
        int c = cmp_x(&edges[u], &edges[v], y_next, x_next[u], x_next[v]);
        if (c == 0 && (edges[u].y_top > y_next || edges[v].y_top > y_next)
            && !boolean_meet_at_next(s, u, v, y_next))
            return 0;
        if (c <= 0)
            break;
        if (cmp_x(&edges[u], &edges[v], y, x_current[u], x_current[v]) != 0) {
            if (!split_crossing(s, y, y_next, u, v))
                return 0;
            *cross_lo = m - 1 < *cross_lo ? m - 1 : *cross_lo;
            *cross_hi = k > *cross_hi ? k : *cross_hi;
        }
        above[m] = u;
        m--;
    }
    above[m] = v;
    return 1;
}

/* The order at y_next, from check_from on: an inversion is a crossing
 * inside the beam (split), unless the two edges meet at y_next (then it is
 * their order there); the list is put in that order.  The positions of the
 * crossings in [*cross_lo, *cross_hi].  0 when out of memory. */
static ALWAYS_INLINE int order_at_next(sweep *s, scanline_state *line, size_t *cross_lo,
                                       size_t *cross_hi)
{
    const edge *edges = s->engine->edges;
    uint32_t *above = line->above;
    double *x_next = s->x_next, last = line->last;
    int64_t y = line->y, y_next = line->y_next;
    size_t above_count = line->above_count;
    for (size_t k = line->check_from; k < above_count; k++) {
        uint32_t v = above[k];
        double xv = x_above(&edges[v], y_next);
        x_next[v] = xv;
        if (xv > last + 0.01) {
            last = xv;
            continue;
        }
        if (!settle_inversion(s, above, k, y, y_next, cross_lo, cross_hi))
            return 0;
        last = x_next[above[k]];
    }
    return 1;
}

/* The beam above y classified: its dirty positions in order, with every
 * position between crossings (the pass will be repeated, but the windings
 * there change too).  0 when out of memory. */
static ALWAYS_INLINE int classify_beam(sweep *s, scanline_state *line, size_t cross_lo,
                                       size_t cross_hi)
{
    uint32_t *dirty = s->dirty, *merged = s->starting; /* (free by now) */
    size_t dirty_count = line->dirty_count;
    if (!line->dirty_sorted)
        sort_u32(dirty, dirty_count);
    if (cross_lo <= cross_hi) {
        size_t w = 0, d = 0;
        for (; d < dirty_count && dirty[d] < cross_lo; d++)
            if (!w || merged[w - 1] != dirty[d])
                merged[w++] = dirty[d];
        for (size_t q = cross_lo; q <= cross_hi; q++)
            merged[w++] = (uint32_t)q;
        for (; d < dirty_count; d++)
            if (dirty[d] > cross_hi && merged[w - 1] != dirty[d])
                merged[w++] = dirty[d];
        memcpy(dirty, merged, w * sizeof *dirty);
        dirty_count = w;
    }
    return classify_dirty(s, line->y, line->above, line->above_count, dirty, dirty_count);
}

/* The full sweep, scanline by scanline: the list above each one built from
 * the one below, the horizontal edges on it, the order at the next one
 * checked (crossings split), and, while the pass classifies, the beam
 * classified.  Returns 1 when done, 0 when out of memory, -1 when the
 * active list was not in order (a bug: the caller gives CG_ERANGE rather
 * than a wrong result). */
int boolean_run_sweep(sweep *s)
{
    engine *g = s->engine;
    size_t edge_count = g->edge_count, scanline_count = s->scanline_count,
           next_start = s->start_bottom, next_end = s->start_top, next_horizontal = 0;
    const edge *edges = g->edges;
    int64_t y_start = bottom_of_next(s, next_start);
    if (!s->start_scanline)
        s->active_count = 0;
    s->y_span = scanline_count ? s->scanlines[scanline_count - 1] - s->scanlines[0] : 0;
    for (size_t scanline = s->start_scanline; scanline < scanline_count; scanline++) {
        if (s->prev_log) {
            int jump = take_last_pass(s, s->scanlines[scanline], &scanline, &next_start, &next_end);
            if (jump < 0)
                return -1;
            if (jump == 2)
                return 1;
            if (jump)
                y_start = bottom_of_next(s, next_start);
        }
        scanline_state line;
        line.y = s->scanlines[scanline];
        line.y_next = scanline + 1 < scanline_count ? s->scanlines[scanline + 1] : line.y;
        if (s->log && s->classify && s->visits >= s->checkpoint_visits) {
            /* a checkpoint costs about as much as a look at each active
             * edge: one per eight such looks at most (and at most one per
             * 64 looks on large inputs, where the next pass's jumps need
             * not be as fine) */
            if (!boolean_ck_record(s, line.y))
                s->log = NULL;
            s->checkpoint_visits = s->visits + 8 * s->active_count
                                   + (s->engine->edge_count >= 1024 ? 64 : 16);
        }
        line.below = s->active;
        line.below_count = s->active_count;
        line.above = s->next_active;
        /* x at y of the edges of the last beam: computed there as its top */
        double *swap = s->x_current;
        s->x_current = s->x_next;
        s->x_next = swap;
        /* breaks found at the top of the last beam are for this scanline;
         * the classification of the last beam cleared the others */
        unsigned char *break_swap = s->run_break;
        s->run_break = s->run_break_next;
        s->run_break_next = break_swap;
        gather_starting(s, &line, &next_start, &y_start);
        /* edges ending here, by x: by_top[ending_first..next_end), needed
         * only among many passing edges (few take one look each; next_end
         * catches up then) */
        line.ending_first = next_end;
        if (line.below_count >= 32) {
            while (next_end < edge_count && edges[s->by_top[next_end]].y_top < line.y)
                next_end++;
            line.ending_first = next_end;
            while (next_end < edge_count && edges[s->by_top[next_end]].y_top == line.y)
                next_end++;
        }
        line.ending_end = next_end;
        /* the edges with a run break here, found at the top of the last
         * beam */
        uint32_t *queue_swap = s->break_queue;
        s->break_queue = s->break_queue_next;
        s->break_queue_next = queue_swap;
        line.queued = s->break_queue_count;
        line.queue_full = s->break_queue_full;
        s->break_queue_count = 0;
        s->break_queue_full = 0;
        line.dirty_sorted = 1;
        int built = line.below_count < 4 * (line.starting_count + next_end - line.ending_first) + 32
                        ? above_by_looking_at_each(s, &line)
                        : above_by_events(s, &line);
        if (built <= 0)
            return built;
        /* (edges meeting at y were found at the top of the last beam, or
         * just above) */
        /* horizontal edges on this scanline */
        size_t h0 = next_horizontal;
        if (next_horizontal < g->horizontal_count)
            horizontals_at(g, line.y, &next_horizontal, &h0);
        if (next_horizontal > h0) {
            size_t dirty_count = line.dirty_count; /* (line stays in registers) */
            if (!boolean_horizontal_meets(s, line.y, line.above, line.above_count, h0,
                                          next_horizontal, s->dirty, &dirty_count))
                return 0;
            line.dirty_count = dirty_count;
            line.dirty_sorted = 0;
            if (s->classify
                && !boolean_horizontal_pieces(s, line.y, line.below, line.below_count, line.above,
                                              line.above_count, h0, next_horizontal))
                return 0;
        }
        s->visits += line.above_count;
        /* the beam [y, y_next] */
        s->active = line.above;
        s->next_active = line.below;
        s->active_count = line.above_count;
        if (scanline + 1 == scanline_count)
            break;
        size_t cross_lo = SIZE_MAX, cross_hi = 0; /* positions of crossings */
        if (!order_at_next(s, &line, &cross_lo, &cross_hi))
            return 0;
        if (s->classify && !classify_beam(s, &line, cross_lo, cross_hi))
            return 0;
        /* (else this pass will be repeated) */
    }
    return 1;
}
