/* The steps of the boolean operations' sweeps on a scanline that are out
 * of line: split points, run breaks and meets, the pieces a run closes
 * into, and the horizontal edges' meets and boundary pieces. */
#include "boolean_scan.h"

/* Intersection of the lines a0-a1 and b0-b1 rounded to the grid; 0 when
 * parallel. */
int boolean_line_intersection(int64_t ax0, int64_t ay0, int64_t ax1, int64_t ay1, int64_t bx0,
                              int64_t by0, int64_t bx1, int64_t by1, int64_t *px, int64_t *py)
{
    int64_t lim = (int64_t)1 << 20,
            d[6] = {ax1 - ax0, ay1 - ay0, bx1 - bx0, by1 - by0, bx0 - ax0, by0 - ay0};
    /* every difference below 2^20: every product below 2^61, so 64 bits */
    int narrow = 1;
    for (int k = 0; k < 6; k++)
        narrow &= d[k] < lim && d[k] > -lim;
    i128 den, num;
    if (narrow) {
        den = d[0] * d[3] - d[1] * d[2];
        num = d[4] * d[3] - d[5] * d[2];
    } else {
        den = (i128)d[0] * d[3] - (i128)d[1] * d[2];
        num = (i128)d[4] * d[3] - (i128)d[5] * d[2];
    }
    if (den == 0)
        return 0;
    if (den < 0) {
        den = -den;
        num = -num;
    }
    /* the point must be on segment a (0 <= t <= 1) for the products to fit */
    if (num < 0 || num > den)
        return 0;
    if (narrow) {
        *px = ax0 + round_div64((int64_t)num * d[0], (int64_t)den);
        *py = ay0 + round_div64((int64_t)num * d[1], (int64_t)den);
    } else {
        *px = ax0 + round_div(num * d[0], den);
        *py = ay0 + round_div(num * d[1], den);
    }
    return 1;
}

int boolean_add_split(sweep *s, uint32_t e, int64_t x, int64_t y)
{
    engine *g = s->engine;
    if (!room_for_split(g))
        return 0;
    g->splits[g->split_count++] = (split_point){e, x, y};
    s->changed = 1;
    /* this pass will be repeated; it goes on classifying so that the next
     * pass can take its results between the split edges, unless it takes
     * no checkpoints or they are many or long (then little would be left to
     * take) */
    const edge *ed = &g->edges[e];
    if (!s->log || g->split_count > 16 || 2 * (ed->y_top - ed->y_bottom) > s->y_span)
        s->classify = 0;
    return 1;
}

/* Passing edge e meets something at scanline y (the current one, or the
 * next when `next`): a vertex for it there. */
/* Edge e's run breaks at the current scanline (or the next, `next`): it
 * meets something at a grid point, where no split is needed. */
static void break_run(sweep *s, uint32_t e, int next)
{
    if (next && !s->run_break_next[e]) {
        if (s->break_queue_count < s->break_queue_capacity)
            s->break_queue_next[s->break_queue_count++] = e;
        else
            s->break_queue_full = 1;
    }
    (next ? s->run_break_next : s->run_break)[e] = 1;
}

/* the grid point (x, y), where a run breaks, noted in g->meets: 0 when out of
 * memory */
NOINLINE static int record_meet(sweep *s, int64_t x, int64_t y)
{
    engine *g = s->engine;
    if (!room_for_meet(g))
        return 0;
    g->meets[g->meet_count++] = (cg_point64){x, y};
    return 1;
}

int boolean_meet(sweep *s, uint32_t e, int64_t y, int next)
{
    int64_t x;
    const edge *ed = &s->engine->edges[e];
    if (x_is_integer(ed, y, &x)) {
        break_run(s, e, next);
        return !s->record_meets || record_meet(s, x, y);
    }
    /* round the input edge's x there rather than the piece's, so that
     * rounding errors do not add up along an edge split many times */
    int64_t o[4];
    edge_orig(s->engine, ed, o);
    if (s->use_input_lines && o[1] != o[3]) {
        i128 dy = o[3] - o[1];
        i128 n = (i128)o[0] * dy + (i128)(y - o[1]) * (o[2] - o[0]);
        if (dy < 0) {
            n = -n;
            dy = -dy;
        }
        x = round_div(n, dy);
    }
    return boolean_add_split(s, e, x, y);
}

/* Room for more pieces: the first growth goes to one per edge at once (a
 * result has about as many), the ones after by the growth policy.  0 when
 * out of memory. */
NOINLINE static int grow_pieces(engine *g)
{
    size_t needed = g->piece_count + 1;
    if (needed < g->edge_count)
        needed = g->edge_count;
    return core_array_reserve_from((void **)&g->pieces, &g->piece_capacity, g->piece_count, needed,
                                   sizeof *g->pieces, g->pieces_small)
           == CG_OK;
}

static int emit(engine *g, int64_t x0, int64_t y0, int64_t x1, int64_t y1)
{
    if (x0 == x1 && y0 == y1)
        return 1;
    if (g->piece_count == g->piece_capacity && !grow_pieces(g))
        return 0;
    g->pieces[g->piece_count++] = (piece){x0, y0, x1, y1};
    return 1;
}

int boolean_close_run(sweep *s, uint32_t e, int64_t y)
{
    const edge *ed = &s->engine->edges[e];
    int64_t x = y == ed->y_top ? ed->x_top : x_rounded(ed, y);
    s->run_open[e] = 0;
    if (s->run_up[e])
        return emit(s->engine, s->run_x[e], s->run_y[e], x, y);
    return emit(s->engine, x, y, s->run_x[e], s->run_y[e]);
}

/* Horizontal boundary pieces on scanline y: between below[] (edges reaching
 * y from below, x at y in x_current) and above[] (edges leaving y upwards), under
 * the horizontal edges horizontals[h0..h1) at y (sorted by x0).  Elsewhere on the
 * scanline nothing lies on it, so the windings just below and just above it
 * agree: there the edges only add up the windings, with no exact look. */
int boolean_horizontal_pieces(sweep *s, int64_t y, const uint32_t *below, size_t below_count,
                              const uint32_t *above, size_t above_count, size_t h0, size_t h1)
{
    engine *g = s->engine;
    const edge *edges = g->edges;
    const double *x_current = s->x_current;
    int64_t winding_below[2] = {0, 0}, winding_above[2] = {0, 0};
    size_t i = 0, j = 0;
    for (size_t h = h0; h < h1;) {
        /* the horizontal edges overlapping from horizontals[h] on: x in [lo, hi] */
        int64_t lo = g->horizontals[h].x_left, hi = g->horizontals[h].x_right;
        for (h++; h < h1 && g->horizontals[h].x_left <= hi; h++)
            hi = g->horizontals[h].x_right > hi ? g->horizontals[h].x_right : hi;
        double start = (double)lo - 0.5, end = (double)hi + 0.5;
        for (; i < below_count && x_current[below[i]] < start; i++)
            winding_below[edges[below[i]].operand] += edges[below[i]].winding;
        for (; j < above_count && x_current[above[j]] < start; j++)
            winding_above[edges[above[j]].operand] += edges[above[j]].winding;
        int have_prev = 0;
        int64_t prev_x = 0;
        while ((i < below_count && x_current[below[i]] <= end)
               || (j < above_count && x_current[above[j]] <= end)) {
            /* the leftmost next position */
            uint32_t idx;
            if (j >= above_count
                || (i < below_count
                    && cmp_x(&edges[below[i]], &edges[above[j]], y, x_current[below[i]],
                             x_current[above[j]])
                           <= 0))
                idx = below[i];
            else
                idx = above[j];
            const edge *e = &edges[idx];
            int64_t X = x_rounded(e, y);
            if (have_prev) {
                int sb = inside(g, winding_below[0], winding_below[1]),
                    sa = inside(g, winding_above[0], winding_above[1]);
                if (sb != sa && X != prev_x) {
                    if (sa ? !emit(g, prev_x, y, X, y) : !emit(g, X, y, prev_x, y))
                        return 0;
                }
            }
            /* apply everything at this position */
            double xv = x_current[idx];
            while (i < below_count && cmp_x(&edges[below[i]], e, y, x_current[below[i]], xv) == 0) {
                winding_below[edges[below[i]].operand] += edges[below[i]].winding;
                i++;
            }
            while (j < above_count && cmp_x(&edges[above[j]], e, y, x_current[above[j]], xv) == 0) {
                winding_above[edges[above[j]].operand] += edges[above[j]].winding;
                j++;
            }
            have_prev = 1;
            prev_x = X;
        }
    }
    return 1;
}

/* Passing edges of above[] (sorted at y, x at y in x_current) whose x lies within
 * a horizontal edge horizontals[h0..h1) at y (sorted by x0) meet it: a vertex there.
 * Their positions are added to dirty[]. */
int boolean_horizontal_meets(sweep *s, int64_t y, const uint32_t *above, size_t above_count,
                             size_t h0, size_t h1, uint32_t *dirty, size_t *dirty_count)
{
    const engine *g = s->engine;
    const edge *edges = g->edges;
    size_t hj = h0;
    /* the union of horizontals[h0..hj) as disjoint intervals, the last [lo, reach]:
     * the edges come in order of x, and one at x >= (x0 of horizontals[hj - 1]) - 1/2
     * can only lie in the last (the others end a unit before it starts) */
    int64_t lo = INT64_MIN, reach = INT64_MIN;
    for (size_t k = 0; k < above_count; k++) {
        uint32_t e = above[k];
        if (edges[e].y_bottom == y)
            continue;
        double xv = s->x_current[e];
        while (hj < h1 && (double)g->horizontals[hj].x_left <= xv + 0.5) {
            if (g->horizontals[hj].x_left > reach)
                lo = g->horizontals[hj].x_left; /* (a new interval) */
            if (g->horizontals[hj].x_right > reach)
                reach = g->horizontals[hj].x_right;
            hj++;
        }
        if ((double)reach >= xv - 0.5) {
            /* exact: lo <= x(y) <= reach */
            i128 n = x_num(&edges[e], y), d = x_den(&edges[e]);
            if ((i128)lo * d <= n && n <= (i128)reach * d) {
                if (!boolean_meet(s, e, y, 0))
                    return 0;
                dirty[(*dirty_count)++] = (uint32_t)k;
            }
        }
    }
    return 1;
}

/* Two edges at one point of the next scanline yn meet there: a vertex for
 * each one that goes on.  At a grid point the runs just break; off
 * the grid both take that point rounded, one vertex for the two (each
 * rounded on its input edge's line, as meet rounds, they would part and
 * cross again).  Not when they lie on one line: coincident edges stay a
 * group and need no vertex (on coarse grids, where snapped edges often
 * coincide, rounding them made new crossings pass after pass).  Where a
 * third edge crosses such a group there, it splits its neighbour in the
 * group only, and the passes that verify settle the rest (splitting the
 * whole group as well was measured slower).  (Out of line: rare, and the
 * sweep's loop is short of registers.) */
int boolean_meet_at_next(sweep *s, uint32_t u, uint32_t v, int64_t y_next)
{
    const edge *edges = s->engine->edges;
    int64_t x = 0;
    int either_ends = ends_at(&edges[u], y_next) || ends_at(&edges[v], y_next);
    if (either_ends || x_is_integer(&edges[u], y_next, &x)) {
        /* a grid point (ends are grid points): the runs of those that go
         * on break there */
        if (edges[u].y_top > y_next)
            break_run(s, u, 1);
        if (edges[v].y_top > y_next)
            break_run(s, v, 1);
        /* (an edge's end is a vertex already) */
        return !s->record_meets || either_ends || record_meet(s, x, y_next);
    }
    if (coincident(&edges[u], &edges[v]))
        return 1;
    return boolean_add_split(s, u, x, y_next) && boolean_add_split(s, v, x, y_next);
}
