/* The sweep of a pass of the boolean operations: the full sweep over every
 * scanline, which finds and splits crossings or classifies the beams and
 * emits the result's boundary pieces, and the light sweep that only visits
 * the points where edges start and end. */
#include "boolean_engine.h"

/* Intersection of the lines a0-a1 and b0-b1 rounded to the grid; 0 when
 * parallel. */
int boolean_line_intersection(int64_t ax0, int64_t ay0, int64_t ax1, int64_t ay1, int64_t bx0,
                              int64_t by0, int64_t bx1, int64_t by1, int64_t *px, int64_t *py)
{
    int64_t lim = (int64_t)1 << 20, d[6] = {ax1 - ax0, ay1 - ay0, bx1 - bx0, by1 - by0, bx0 - ax0,
                                            by0 - ay0};
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

/* whether edge e ends at scanline y */
static inline int ends_at(const edge *e, int64_t y) { return e->y_top == y; }

/* the input edge e is a piece of */
static inline void edge_orig(const engine *g, const edge *e, int64_t o[4])
{
    if (e->input_edge == NO_ORIG) {
        o[0] = e->x_bottom;
        o[1] = e->y_bottom;
        o[2] = e->x_top;
        o[3] = e->y_top;
    } else {
        memcpy(o, g->input_edges[e->input_edge], sizeof g->input_edges[0]);
    }
}

/* sign of x_a(y) - x_b(y); xa, x_bottom are the double values */
static inline int cmp_x(const edge *a, const edge *b, int64_t y, double xa, double xb)
{
    double d = xa - xb;
    if (d > 0.01)
        return 1;
    if (d < -0.01)
        return -1;
    i128 l = x_num(a, y) * x_den(b), r = x_num(b, y) * x_den(a);
    return (l > r) - (l < r);
}

static int add_split(sweep *s, uint32_t e, int64_t x, int64_t y)
{
    engine *g = s->engine;
    GROW_SMALL(g->splits, g->split_count, g->split_capacity, g->splits_small, return 0);
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
    GROW(g->meets, g->meet_count, g->meet_capacity, return 0);
    g->meets[g->meet_count++] = (cg_point64){x, y};
    return 1;
}

static int meet(sweep *s, uint32_t e, int64_t y, int next)
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
    return add_split(s, e, x, y);
}

/* Room for more pieces: the first growth goes to one per edge at once (a
 * result has about as many), the ones after double as GROW_SMALL's.  0 when
 * out of memory. */
NOINLINE static int grow_pieces(engine *g)
{
    size_t cap = g->piece_capacity < g->edge_count / 2 ? g->edge_count / 2
                                                       : g->piece_capacity; /* (doubled) */
    void *p =
        boolean_grow_from(g->pieces, g->pieces_small, g->piece_count, &cap, sizeof *g->pieces);
    if (!p)
        return 0;
    g->pieces = p;
    g->piece_capacity = cap;
    return 1;
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

static int close_run(sweep *s, uint32_t e, int64_t y)
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
static int horizontal_pieces(sweep *s, int64_t y, const uint32_t *below, size_t below_count,
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
        while ((i < below_count && x_current[below[i]] <= end) ||
               (j < above_count && x_current[above[j]] <= end)) {
            /* the leftmost next position */
            uint32_t idx;
            if (j >= above_count ||
                (i < below_count && cmp_x(&edges[below[i]], &edges[above[j]], y,
                                          x_current[below[i]], x_current[above[j]]) <= 0))
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

static void sort_u32(uint32_t *a, size_t n)
{
    for (size_t i = 1; i < n; i++) {
        uint32_t v = a[i];
        size_t j = i;
        for (; j > 0 && a[j - 1] > v; j--)
            a[j] = a[j - 1];
        a[j] = v;
    }
}

static inline void copy_ids(uint32_t *dst, const uint32_t *src, size_t n)
{
    if (n > 16) {
        memcpy(dst, src, n * sizeof *dst);
        return;
    }
    for (size_t i = 0; i < n; i++)
        dst[i] = src[i];
}

/* sign of x_e(y) - X for an integer X; xe is the double value */
static inline int cmp_xi(const edge *e, int64_t y, int64_t X, double xe)
{
    double d = xe - (double)X;
    if (d > 0.01)
        return 1;
    if (d < -0.01)
        return -1;
    i128 n = x_num(e, y), r = (i128)X * x_den(e);
    return (n > r) - (n < r);
}

/* The horizontal edges at y: horizontals[*h0..*ih) (ih moves on from scanline to
 * scanline). */
static inline void horizontals_at(const engine *g, int64_t y, size_t *next_horizontal, size_t *h0)
{
    while (*next_horizontal < g->horizontal_count && g->horizontals[*next_horizontal].y < y)
        (*next_horizontal)++;
    *h0 = *next_horizontal;
    while (*next_horizontal < g->horizontal_count && g->horizontals[*next_horizontal].y == y)
        (*next_horizontal)++;
}

/* x of list[i] at y: from x_current, or computed when x_current is NULL */
static inline double x_of(const edge *edges, const uint32_t *list, size_t i, int64_t y,
                          const double *x_current)
{
    return x_current ? x_current[list[i]] : x_at(&edges[list[i]], y);
}

/* The first position in list[lo..hi) (sorted by x at y) whose x at y is
 * not below the integer X. */
static size_t first_at_x(const edge *edges, const uint32_t *list, size_t lo, size_t hi, int64_t y,
                         int64_t X, const double *x_current)
{
    size_t n = hi;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (x_of(edges, list, mid, y, x_current) < (double)X - 0.5)
            lo = mid + 1;
        else
            hi = mid;
    }
    while (lo < n && cmp_xi(&edges[list[lo]], y, X, x_of(edges, list, lo, y, x_current)) < 0)
        lo++;
    return lo;
}

/* The next point where edges start (fresh[*jf..nf), by x) or end
 * (top[*jt..it), by x) on this scanline: its x; fresh[f0..*jf) start there
 * and the cursors move past it. */
static inline int64_t next_event(const edge *edges, const uint32_t *starting, size_t starting_count,
                                 size_t *starting_at, const uint32_t *top, size_t next_end,
                                 size_t *ending_at, size_t *f0)
{
    int64_t X = *ending_at >= next_end ||
                        (*starting_at < starting_count &&
                         edges[starting[*starting_at]].x_bottom <= edges[top[*ending_at]].x_top)
                    ? edges[starting[*starting_at]].x_bottom
                    : edges[top[*ending_at]].x_top;
    *f0 = *starting_at;
    while (*starting_at < starting_count && edges[starting[*starting_at]].x_bottom == X)
        (*starting_at)++;
    while (*ending_at < next_end && edges[top[*ending_at]].x_top == X)
        (*ending_at)++;
    return X;
}

/* Passing edges of above[] (sorted at y, x at y in x_current) whose x lies within
 * a horizontal edge horizontals[h0..h1) at y (sorted by x0) meet it: a vertex there.
 * Their positions are added to dirty[]. */
static int horizontal_meets(sweep *s, int64_t y, const uint32_t *above, size_t above_count,
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
                if (!meet(s, e, y, 0))
                    return 0;
                dirty[(*dirty_count)++] = (uint32_t)k;
            }
        }
    }
    return 1;
}

/* a and b (both active in a beam, not crossing inside it) coincide there:
 * they are on one line */
static inline int coincident(const edge *a, const edge *b)
{
    if (a->slope != b->slope) /* dx / dy rounded once: equal when collinear */
        return 0;
    i128 dx = a->x_top - a->x_bottom, dy = a->y_top - a->y_bottom;
    return dx * (b->y_bottom - a->y_bottom) == dy * (b->x_bottom - a->x_bottom) &&
           dx * (b->y_top - a->y_bottom) == dy * (b->x_top - a->x_bottom);
}

/* Classification of the beam above y: no crossing inside it, so the order
 * at y (ties by direction) is the order throughout.  Only the groups of
 * coincident edges around a dirty position (a new edge, a run break) need a
 * look: elsewhere the windings are those of the last beam, because the
 * edges ending and starting at one point (or along one chain of horizontal
 * edges, whose crossing edges are dirty) add up to the same windings.
 * dirty[] is sorted. */
static ALWAYS_INLINE int classify_dirty(sweep *s, int64_t y, const uint32_t *above,
                                        size_t above_count, const uint32_t *dirty,
                                        size_t dirty_count)
{
    const engine *g = s->engine;
    const edge *edges = g->edges;
    int32_t *right_subject = s->winding_subject, *right_clip = s->winding_clip;
    size_t done = 0;
    for (size_t d = 0; d < dirty_count; d++) {
        size_t k = dirty[d];
        if (k < done)
            continue;
        while (k > done && coincident(&edges[above[k - 1]], &edges[above[k]]))
            k--;
        int64_t subject_winding = 0, clip_winding = 0; /* (subject's, clip's) */
        if (k > 0) {
            subject_winding = right_subject[above[k - 1]];
            clip_winding = right_clip[above[k - 1]];
        }
        int left = inside(g, subject_winding, clip_winding);
        size_t k2 = k + 1;
        uint32_t rep = above[k];
        if (edges[rep].operand)
            clip_winding += edges[rep].winding;
        else
            subject_winding += edges[rep].winding;
        while (k2 < above_count && coincident(&edges[above[k]], &edges[above[k2]])) {
            uint32_t b = above[k2];
            if (b < rep)
                rep = b;
            if (edges[b].operand)
                clip_winding += edges[b].winding;
            else
                subject_winding += edges[b].winding;
            k2++;
        }
        int right = inside(g, subject_winding, clip_winding);
        for (size_t q = k; q < k2; q++) {
            uint32_t e = above[q];
            int boundary = e == rep && left != right;
            int up = left; /* result on the left (-x side): go up */
            if (s->run_open[e] && (!boundary || s->run_break[e] || s->run_up[e] != up)) {
                if (!close_run(s, e, y))
                    return 0;
            }
            if (boundary && !s->run_open[e]) {
                s->run_open[e] = 1;
                s->run_up[e] = (unsigned char)up;
                s->run_y[e] = y;
                s->run_x[e] = y == edges[e].y_bottom ? edges[e].x_bottom : x_rounded(&edges[e], y);
            }
            s->run_break[e] = 0;
            right_subject[e] = (int32_t)subject_winding;
            right_clip[e] = (int32_t)clip_winding;
        }
        done = k2;
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
NOINLINE static int meet_at_next(sweep *s, uint32_t u, uint32_t v, int64_t y_next)
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
    return add_split(s, u, x, y_next) && add_split(s, v, x, y_next);
}

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

/* Returns 1 when done, 0 when out of memory, -1 when the active list was
 * not in order (a bug: the caller gives CG_ERANGE rather than a wrong
 * result). */
int boolean_run_sweep(sweep *s)
{
    engine *g = s->engine;
    size_t edge_count = g->edge_count, scanline_count = s->scanline_count,
           next_start = s->start_bottom, next_end = s->start_top, next_horizontal = 0;
    const edge *edges = g->edges;
    uint32_t *starting = s->starting, *dirty = s->dirty;
    /* the bottom of the next edge to start (INT64_MAX: none; no y reaches
     * it) */
    int64_t y_start = bottom_of_next(s, next_start);
    if (!s->start_scanline)
        s->active_count = 0;
    s->y_span = scanline_count ? s->scanlines[scanline_count - 1] - s->scanlines[0] : 0;
    for (size_t scanline = s->start_scanline; scanline < scanline_count; scanline++) {
        int64_t y = s->scanlines[scanline];
        /* the next scanline (the last has none: yn == y) */
        int64_t y_next = scanline + 1 < scanline_count ? s->scanlines[scanline + 1] : y;
        while (s->prev_log && s->band < s->band_count && s->bands[s->band][1] < y)
            s->band++; /* (bands come with prev only) */
        if (s->prev_log && s->band > 0 && !s->changed &&
            (s->band == s->band_count || y <= s->bands[s->band][0])) {
            /* between the split edges: the last pass's results hold from
             * the first checkpoint where the states agree to the last one
             * below the next split edge */
            const struct ck_log *L = s->prev_log;
            while (s->prev_checkpoint < L->checkpoint_count &&
                   L->checkpoints[s->prev_checkpoint].scanline_y < y)
                s->prev_checkpoint++;
            if (s->prev_checkpoint < L->checkpoint_count &&
                L->checkpoints[s->prev_checkpoint].scanline_y == y &&
                boolean_ck_same(s, &L->checkpoints[s->prev_checkpoint])) {
                size_t from = L->checkpoints[s->prev_checkpoint].piece_count,
                       to = s->prev_log->end_piece_count, j = 0;
                if (s->band < s->band_count) {
                    j = boolean_ck_load(s, L, s->prev_checkpoint, s->bands[s->band][0]);
                    if (!CG_INVARIANT(j != 0)) /* prev_j itself is one */
                        return -1;
                    to = L->checkpoints[j - 1].piece_count;
                }
                s->taken_ranges[s->taken_count][0] = from;
                s->taken_ranges[s->taken_count][1] = to;
                s->taken_count++;
                if (!j)
                    return 1;
                s->prev_checkpoint = j;
                scanline = s->start_scanline;
                next_start = s->start_bottom;
                y_start = bottom_of_next(s, next_start);
                next_end = s->start_top;
                y = s->scanlines[scanline];
                y_next = scanline + 1 < scanline_count ? s->scanlines[scanline + 1] : y;
            }
        }
        if (s->log && s->classify && s->visits >= s->checkpoint_visits) {
            /* a checkpoint costs about as much as a look at each active
             * edge: one per eight such looks at most (and at most one per
             * 64 looks on large inputs, where the next pass's jumps need
             * not be as fine) */
            if (!boolean_ck_record(s, y))
                s->log = NULL;
            s->checkpoint_visits =
                s->visits + 8 * s->active_count + (s->engine->edge_count >= 1024 ? 64 : 16);
        }
        uint32_t *below = s->active;
        size_t below_count = s->active_count;
        /* x at y of the edges of the last beam: computed there as its top */
        double *swap = s->x_current;
        s->x_current = s->x_next;
        s->x_next = swap;
        double *x_current = s->x_current, *x_next = s->x_next;
        /* breaks found at the top of the last beam are for this scanline;
         * the classification of the last beam cleared the others */
        unsigned char *bswap = s->run_break;
        s->run_break = s->run_break_next;
        s->run_break_next = bswap;
        /* the edges starting here, by x (by_bottom), ties by x at yn */
        size_t starting_count = 0;
        while (y_start == y) {
            uint32_t e = s->by_bottom[next_start++];
            y_start = bottom_of_next(s, next_start);
            x_current[e] = (double)edges[e].x_bottom;
            x_next[e] = x_at(&edges[e], y_next);
            size_t m = starting_count;
            while (m > 0 && edges[starting[m - 1]].x_bottom == edges[e].x_bottom &&
                   cmp_x(&edges[starting[m - 1]], &edges[e], y_next, x_next[starting[m - 1]],
                         x_next[e]) > 0) {
                starting[m] = starting[m - 1];
                m--;
            }
            starting[m] = e;
            starting_count++;
        }
        /* edges ending here, by x: by_top[t0..it), needed only among many
         * passing edges (few take one look each below; `it` catches up
         * then) */
        size_t ending_first = next_end;
        if (below_count >= 32) {
            while (next_end < edge_count && edges[s->by_top[next_end]].y_top < y)
                next_end++;
            ending_first = next_end;
            while (next_end < edge_count && edges[s->by_top[next_end]].y_top == y)
                next_end++;
        }
        /* the edges with a run break here, found at the top of the last
         * beam */
        uint32_t *q = s->break_queue;
        s->break_queue = s->break_queue_next;
        s->break_queue_next = q;
        size_t queued = s->break_queue_count;
        int queue_full = s->break_queue_full;
        s->break_queue_count = 0;
        s->break_queue_full = 0;
        /* above: the passing edges in their order (sorted at y by the last
         * beam) with the ending ones taken out and the new ones put in, at
         * the points where edges end or start (found by binary search);
         * passing edges through such a point need a vertex there */
        size_t above_count = 0, starting_at = 0, dirty_count = 0;
        int dirty_sorted = 1;
        uint32_t *above = s->next_active;
        /* the order at yn is checked from above[k0] on, after last (x at
         * yn of above[k0 - 1], or -INFINITY) */
        double last = -INFINITY;
        size_t check_from = 0;
        if (below_count < 4 * (starting_count + next_end - ending_first) + 32) {
            /* few edges: one look at each, which also takes x at yn and
             * checks the order there up to the first inversion (k0) */
            check_from = SIZE_MAX;
            for (size_t k = 0; k < below_count; k++) {
                uint32_t e = below[k];
                const edge *ee = &edges[e];
                if (ends_at(ee, y)) {
                    if (s->classify && s->run_open[e] && !close_run(s, e, y))
                        return 0;
                    continue;
                }
                while (starting_at < starting_count) {
                    uint32_t f = starting[starting_at];
                    double xf = x_current[f];
                    int c =
                        x_current[e] < xf - 0.01 ? -1 : cmp_x(ee, &edges[f], y, x_current[e], xf);
                    if (c < 0)
                        break;
                    if (c == 0) {
                        /* a new edge starts on a passing one: a vertex there */
                        if (!meet(s, e, y, 0))
                            return 0;
                        break; /* the order at yn is settled below */
                    }
                    dirty[dirty_count++] = (uint32_t)above_count;
                    above_count =
                        take_in_order(above, above_count, f, x_next[f], &last, &check_from);
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
        } else {
            size_t ending_at = ending_first, below_at = 0, ended = 0;
            while (starting_at < starting_count || ending_at < next_end) {
                size_t f0;
                int64_t X = next_event(edges, starting, starting_count, &starting_at, s->by_top,
                                       next_end, &ending_at, &f0);
                size_t lo = first_at_x(edges, below, below_at, below_count, y, X, x_current);
                copy_ids(above + above_count, below + below_at, lo - below_at);
                above_count += lo - below_at;
                below_at = lo;
                while (below_at < below_count &&
                       cmp_xi(&edges[below[below_at]], y, X, x_current[below[below_at]]) == 0) {
                    uint32_t e = below[below_at++];
                    if (ends_at(&edges[e], y)) {
                        ended++;
                        if (s->classify && s->run_open[e] && !close_run(s, e, y))
                            return 0;
                        continue;
                    }
                    if (starting_at > f0 && !meet(s, e, y, 0))
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
            if (!CG_INVARIANT(ended == next_end - ending_first)) /* sorted as expected */
                return -1;
            if (queue_full) {
                for (size_t k = 0; k < above_count; k++)
                    if (s->run_break[above[k]])
                        dirty[dirty_count++] = (uint32_t)k;
                dirty_sorted = 0;
            } else if (queued && s->classify) {
                /* their positions, by binary search on x */
                for (size_t k = 0; k < queued; k++) {
                    uint32_t e = s->break_queue[k];
                    if (edges[e].y_top <= y)
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
                        dirty[dirty_count++] = (uint32_t)lo;
                        dirty_sorted = 0;
                    }
                }
            }
        }
        /* (edges meeting at y were found at the top of the last beam, or
         * just above) */
        /* horizontal edges on this scanline */
        size_t h0 = next_horizontal;
        if (next_horizontal < g->horizontal_count)
            horizontals_at(g, y, &next_horizontal, &h0);
        if (next_horizontal > h0) {
            if (!horizontal_meets(s, y, above, above_count, h0, next_horizontal, dirty,
                                  &dirty_count))
                return 0;
            dirty_sorted = 0;
            if (s->classify && !horizontal_pieces(s, y, below, below_count, above, above_count, h0,
                                                  next_horizontal))
                return 0;
        }
        s->visits += above_count;
        /* the beam [y, yn] */
        uint32_t *t = s->active;
        s->active = above;
        s->next_active = t;
        s->active_count = above_count;
        if (scanline + 1 == scanline_count)
            break;
        /* the order at yn: an inversion is a crossing inside the beam,
         * unless the two edges meet at y (then it is their order) */
        size_t cross_lo = SIZE_MAX, cross_hi = 0; /* positions of crossings */
        for (size_t k = check_from; k < above_count; k++) {
            uint32_t v = above[k];
            const edge *ev = &edges[v];
            double xv = x_above(ev, y_next);
            x_next[v] = xv;
            if (xv > last + 0.01) {
                last = xv;
                continue;
            }
            size_t m = k;
            while (m > 0) {
                uint32_t u = above[m - 1];
                int c = cmp_x(&edges[u], &edges[v], y_next, x_next[u], x_next[v]);
                if (c == 0 && (edges[u].y_top > y_next || edges[v].y_top > y_next) &&
                    !meet_at_next(s, u, v, y_next))
                    return 0;
                if (c <= 0)
                    break;
                if (cmp_x(&edges[u], &edges[v], y, x_current[u], x_current[v]) != 0) {
                    /* u and v cross strictly inside the beam: the crossing
                     * of the input edges they come from, rounded, when it
                     * lies in the beam within a unit of both pieces (no
                     * drift), else the crossing of the pieces.  (Pieces
                     * bent by earlier splits can cross far from where
                     * their input edges do: a split there would bend them
                     * by units, and on coarse grids that went on pass
                     * after pass.) */
                    const edge *a = &edges[u], *b = &edges[v];
                    int64_t px, py, oa[4], ob[4];
                    edge_orig(g, a, oa);
                    edge_orig(g, b, ob);
                    if (!s->use_input_lines ||
                        !boolean_line_intersection(oa[0], oa[1], oa[2], oa[3], ob[0], ob[1], ob[2],
                                                   ob[3], &px, &py) ||
                        py < y || py > y_next || !near_span((double)px, x_current[u], x_next[u]) ||
                        !near_span((double)px, x_current[v], x_next[v])) {
                        boolean_line_intersection(a->x_bottom, a->y_bottom, a->x_top, a->y_top,
                                                  b->x_bottom, b->y_bottom, b->x_top, b->y_top, &px,
                                                  &py);
                    }
                    if (py < y)
                        py = y;
                    if (py > y_next)
                        py = y_next;
                    if (!add_split(s, u, px, py) || !add_split(s, v, px, py))
                        return 0;
                    cross_lo = m - 1 < cross_lo ? m - 1 : cross_lo;
                    cross_hi = k > cross_hi ? k : cross_hi;
                }
                above[m] = u;
                m--;
            }
            above[m] = v;
            last = x_next[above[k]];
        }
        if (!s->classify)
            continue; /* this pass will be repeated */
        if (!dirty_sorted)
            sort_u32(dirty, dirty_count);
        if (cross_lo <= cross_hi) {
            /* edges crossed inside the beam (the pass will be repeated):
             * the windings of the positions between them change too */
            size_t w = 0, d = 0;
            for (; d < dirty_count && dirty[d] < cross_lo; d++)
                if (!w || starting[w - 1] != dirty[d])
                    starting[w++] = dirty[d];
            for (size_t q = cross_lo; q <= cross_hi; q++)
                starting[w++] = (uint32_t)q;
            for (; d < dirty_count; d++)
                if (dirty[d] > cross_hi && starting[w - 1] != dirty[d])
                    starting[w++] = dirty[d];
            memcpy(dirty, starting, w * sizeof *dirty);
            dirty_count = w;
        }
        if (!classify_dirty(s, y, above, above_count, dirty, dirty_count))
            return 0;
    }
    return 1;
}

/* ---- the light sweep ------------------------------------------------------- */

/* the order of a and b just above a point they share: by direction */
static inline int cmp_dir(const edge *a, const edge *b)
{
    i128 l = (i128)(a->x_top - a->x_bottom) * (b->y_top - b->y_bottom),
         r = (i128)(b->x_top - b->x_bottom) * (a->y_top - a->y_bottom);
    return (l > r) - (l < r);
}

/* a is left of b just above the current scanline: do they cross before
 * either ends? */
static int cross_above(const edge *a, const edge *b)
{
    int64_t yt = a->y_top < b->y_top ? a->y_top : b->y_top;
    return cmp_x(a, b, yt, x_at(a, yt), x_at(b, yt)) > 0;
}

/* The sweep of a pass that is expected to find nothing to split (the pass
 * after the splits): Bentley-Ottmann's idea instead of a look at every
 * active edge on every scanline.  The active list changes only at the
 * points where edges end or start (found by binary search); two edges can
 * only cross after being neighbours, so each new pair of neighbours is
 * checked once.  Returns 1 when the pass is final (the pieces are emitted),
 * LIGHT_BAIL when something needs a split (the caller runs the full sweep),
 * 0 when out of memory. */
int boolean_light_sweep(sweep *s)
{
    engine *g = s->engine;
    size_t edge_count = g->edge_count, scanline_count = s->scanline_count, next_start = 0,
           next_end = 0, next_horizontal = 0;
    const edge *edges = g->edges;
    uint32_t *starting = s->starting, *dirty = s->dirty, *point_edges = s->point_edges,
             *seams = s->seams;
    const uint32_t *by_top = s->by_top;
    s->active_count = 0;
    for (size_t scanline = 0; scanline < scanline_count; scanline++) {
        int64_t y = s->scanlines[scanline];
        int has_next = scanline + 1 < scanline_count;
        uint32_t *below = s->active, *above = s->next_active;
        size_t below_count = s->active_count, above_count = 0, dirty_count = 0, seam_count = 0;
        /* edges starting here, by x, then by direction */
        size_t starting_count = 0;
        while (next_start < edge_count && edges[s->by_bottom[next_start]].y_bottom == y) {
            uint32_t e = s->by_bottom[next_start++];
            size_t m = starting_count;
            while (m > 0 && edges[starting[m - 1]].x_bottom == edges[e].x_bottom &&
                   cmp_dir(&edges[starting[m - 1]], &edges[e]) > 0) {
                starting[m] = starting[m - 1];
                m--;
            }
            starting[m] = e;
            starting_count++;
        }
        /* edges ending here, by x */
        size_t ending_first = next_end;
        while (next_end < edge_count && edges[by_top[next_end]].y_top == y)
            next_end++;
        size_t ended = 0, starting_at = 0, ending_at = ending_first, below_at = 0;
        /* every point where edges end or start: the edges through it
         * (ending, passing, starting) are replaced by the passing and
         * starting ones in the order of their directions */
        while (starting_at < starting_count || ending_at < next_end) {
            size_t f0;
            int64_t X = next_event(edges, starting, starting_count, &starting_at, by_top, next_end,
                                   &ending_at, &f0);
            size_t lo = first_at_x(edges, below, below_at, below_count, y, X, NULL);
            copy_ids(above + above_count, below + below_at, lo - below_at);
            above_count += lo - below_at;
            size_t point_edge_count = 0, point_end = lo;
            while (point_end < below_count &&
                   cmp_xi(&edges[below[point_end]], y, X, x_at(&edges[below[point_end]], y)) == 0) {
                uint32_t e = below[point_end++];
                if (ends_at(&edges[e], y)) {
                    ended++;
                    if (s->run_open[e] && !close_run(s, e, y))
                        return 0;
                    continue;
                }
                s->run_break[e] = 1; /* passes through a vertex: its run breaks */
                point_edges[point_edge_count++] = e;
            }
            below_at = point_end;
            for (size_t k = f0; k < starting_at; k++)
                point_edges[point_edge_count++] = starting[k];
            /* in the order of their directions (passing edges may cross
             * there) */
            for (size_t k = 1; k < point_edge_count; k++) {
                uint32_t v = point_edges[k];
                size_t m = k;
                while (m > 0 && cmp_dir(&edges[point_edges[m - 1]], &edges[v]) > 0) {
                    point_edges[m] = point_edges[m - 1];
                    m--;
                }
                point_edges[m] = v;
            }
            for (size_t k = 0; k < point_edge_count; k++) {
                seams[seam_count++] = (uint32_t)above_count;
                dirty[dirty_count++] = (uint32_t)above_count;
                above[above_count++] = point_edges[k];
            }
            seams[seam_count++] = (uint32_t)above_count;
        }
        if (ended != next_end - ending_first)
            return LIGHT_BAIL; /* an ending edge was not where expected */
        copy_ids(above + above_count, below + below_at, below_count - below_at);
        above_count += below_count - below_at;
        /* horizontal edges on this scanline: the whole line is looked at */
        size_t h0;
        horizontals_at(g, y, &next_horizontal, &h0);
        if (next_horizontal > h0) {
            for (size_t k = 0; k < below_count; k++)
                s->x_current[below[k]] = x_at(&edges[below[k]], y);
            for (size_t k = 0; k < above_count; k++)
                s->x_current[above[k]] = x_at(&edges[above[k]], y);
            if (!horizontal_meets(s, y, above, above_count, h0, next_horizontal, dirty,
                                  &dirty_count))
                return 0;
            if (s->changed)
                return LIGHT_BAIL;
            sort_u32(dirty, dirty_count);
            if (!horizontal_pieces(s, y, below, below_count, above, above_count, h0,
                                   next_horizontal))
                return 0;
        }
        /* new neighbours */
        for (size_t k = 0; k < seam_count; k++) {
            size_t p = seams[k];
            if (p > 0 && p < above_count && cross_above(&edges[above[p - 1]], &edges[above[p]]))
                return LIGHT_BAIL;
        }
        s->active = above;
        s->next_active = below;
        s->active_count = above_count;
        if (!has_next)
            break;
        if (!classify_dirty(s, y, above, above_count, dirty, dirty_count))
            return 0;
    }
    return 1;
}
