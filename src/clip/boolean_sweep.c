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

/* the input edge e is a piece of */
static inline void edge_orig(const engine *g, const bedge *e, int64_t o[4])
{
    if (e->orig == NO_ORIG) {
        o[0] = e->xb;
        o[1] = e->yb;
        o[2] = e->xt;
        o[3] = e->yt;
    } else {
        memcpy(o, g->O[e->orig], sizeof g->O[0]);
    }
}

/* sign of x_a(y) - x_b(y); xa, xb are the double values */
static inline int cmp_x(const bedge *a, const bedge *b, int64_t y, double xa, double xb)
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
    engine *g = s->g;
    GROW_SMALL(g->S, g->ns, g->caps, g->S_small, return 0);
    g->S[g->ns++] = (splitpt){e, x, y};
    s->changed = 1;
    /* this pass will be repeated; it goes on classifying so that the next
     * pass can take its results between the split edges, unless it takes
     * no checkpoints or they are many or long (then little would be left to
     * take) */
    const bedge *ed = &g->E[e];
    if (!s->log || g->ns > 16 || 2 * (ed->yt - ed->yb) > s->yspan)
        s->classify = 0;
    return 1;
}

/* Passing edge e meets something at scanline y (the current one, or the
 * next when `next`): a vertex for it there. */
/* Edge e's run breaks at the current scanline (or the next, `next`): it
 * meets something at a grid point, where no split is needed. */
static void break_run(sweep *s, uint32_t e, int next)
{
    if (next && !s->brk_next[e]) {
        if (s->nbrkq < s->capbrkq)
            s->brkq_next[s->nbrkq++] = e;
        else
            s->brkq_full = 1;
    }
    (next ? s->brk_next : s->brk)[e] = 1;
}

/* the grid point (x, y), where a run breaks, noted in g->M: 0 when out of
 * memory */
NOINLINE static int record_meet(sweep *s, int64_t x, int64_t y)
{
    engine *g = s->g;
    GROW(g->M, g->nm, g->capm, return 0);
    g->M[g->nm++] = (cg_point64){x, y};
    return 1;
}

static int meet(sweep *s, uint32_t e, int64_t y, int next)
{
    int64_t x;
    const bedge *ed = &s->g->E[e];
    if (x_is_integer(ed, y, &x)) {
        break_run(s, e, next);
        return !s->record_meets || record_meet(s, x, y);
    }
    /* round the input edge's x there rather than the piece's, so that
     * rounding errors do not add up along an edge split many times */
    int64_t o[4];
    edge_orig(s->g, ed, o);
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
    size_t cap = g->capp < g->ne / 2 ? g->ne / 2 : g->capp; /* (doubled) */
    void *p = boolean_grow_from(g->P, g->P_small, g->np, &cap, sizeof *g->P);
    if (!p)
        return 0;
    g->P = p;
    g->capp = cap;
    return 1;
}

static int emit(engine *g, int64_t x0, int64_t y0, int64_t x1, int64_t y1)
{
    if (x0 == x1 && y0 == y1)
        return 1;
    if (g->np == g->capp && !grow_pieces(g))
        return 0;
    g->P[g->np++] = (piece){x0, y0, x1, y1};
    return 1;
}

static int close_run(sweep *s, uint32_t e, int64_t y)
{
    const bedge *ed = &s->g->E[e];
    int64_t x = y == ed->yt ? ed->xt : x_rounded(ed, y);
    s->run_open[e] = 0;
    if (s->run_up[e])
        return emit(s->g, s->run_x[e], s->run_y[e], x, y);
    return emit(s->g, x, y, s->run_x[e], s->run_y[e]);
}

/* Horizontal boundary pieces on scanline y: between below[] (edges reaching
 * y from below, x at y in xc) and above[] (edges leaving y upwards), under
 * the horizontal edges H[h0..h1) at y (sorted by x0).  Elsewhere on the
 * scanline nothing lies on it, so the windings just below and just above it
 * agree: there the edges only add up the windings, with no exact look. */
static int horizontal_pieces(sweep *s, int64_t y, const uint32_t *below, size_t nb,
                             const uint32_t *above, size_t na, size_t h0, size_t h1)
{
    engine *g = s->g;
    const bedge *E = g->E;
    const double *xc = s->xc;
    int64_t wb[2] = {0, 0}, wa[2] = {0, 0};
    size_t i = 0, j = 0;
    for (size_t h = h0; h < h1;) {
        /* the horizontal edges overlapping from H[h] on: x in [lo, hi] */
        int64_t lo = g->H[h].x0, hi = g->H[h].x1;
        for (h++; h < h1 && g->H[h].x0 <= hi; h++)
            hi = g->H[h].x1 > hi ? g->H[h].x1 : hi;
        double start = (double)lo - 0.5, end = (double)hi + 0.5;
        for (; i < nb && xc[below[i]] < start; i++)
            wb[E[below[i]].op] += E[below[i]].w;
        for (; j < na && xc[above[j]] < start; j++)
            wa[E[above[j]].op] += E[above[j]].w;
        int have_prev = 0;
        int64_t prev_x = 0;
        while ((i < nb && xc[below[i]] <= end) || (j < na && xc[above[j]] <= end)) {
            /* the leftmost next position */
            uint32_t idx;
            if (j >= na || (i < nb && cmp_x(&E[below[i]], &E[above[j]], y, xc[below[i]],
                                            xc[above[j]]) <= 0))
                idx = below[i];
            else
                idx = above[j];
            const bedge *e = &E[idx];
            int64_t X = x_rounded(e, y);
            if (have_prev) {
                int sb = inside(g, wb[0], wb[1]), sa = inside(g, wa[0], wa[1]);
                if (sb != sa && X != prev_x) {
                    if (sa ? !emit(g, prev_x, y, X, y) : !emit(g, X, y, prev_x, y))
                        return 0;
                }
            }
            /* apply everything at this position */
            double xv = xc[idx];
            while (i < nb && cmp_x(&E[below[i]], e, y, xc[below[i]], xv) == 0) {
                wb[E[below[i]].op] += E[below[i]].w;
                i++;
            }
            while (j < na && cmp_x(&E[above[j]], e, y, xc[above[j]], xv) == 0) {
                wa[E[above[j]].op] += E[above[j]].w;
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
static inline int cmp_xi(const bedge *e, int64_t y, int64_t X, double xe)
{
    double d = xe - (double)X;
    if (d > 0.01)
        return 1;
    if (d < -0.01)
        return -1;
    i128 n = x_num(e, y), r = (i128)X * x_den(e);
    return (n > r) - (n < r);
}

/* The horizontal edges at y: H[*h0..*ih) (ih moves on from scanline to
 * scanline). */
static inline void horizontals_at(const engine *g, int64_t y, size_t *ih, size_t *h0)
{
    while (*ih < g->nh && g->H[*ih].y < y)
        (*ih)++;
    *h0 = *ih;
    while (*ih < g->nh && g->H[*ih].y == y)
        (*ih)++;
}

/* x of list[i] at y: from xc, or computed when xc is NULL */
static inline double x_of(const bedge *E, const uint32_t *list, size_t i, int64_t y,
                          const double *xc)
{
    return xc ? xc[list[i]] : x_at(&E[list[i]], y);
}

/* The first position in list[lo..hi) (sorted by x at y) whose x at y is
 * not below the integer X. */
static size_t first_at_x(const bedge *E, const uint32_t *list, size_t lo, size_t hi, int64_t y,
                         int64_t X, const double *xc)
{
    size_t n = hi;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (x_of(E, list, mid, y, xc) < (double)X - 0.5)
            lo = mid + 1;
        else
            hi = mid;
    }
    while (lo < n && cmp_xi(&E[list[lo]], y, X, x_of(E, list, lo, y, xc)) < 0)
        lo++;
    return lo;
}

/* The next point where edges start (fresh[*jf..nf), by x) or end
 * (top[*jt..it), by x) on this scanline: its x; fresh[f0..*jf) start there
 * and the cursors move past it. */
static inline int64_t next_event(const bedge *E, const uint32_t *fresh, size_t nf, size_t *jf,
                                 const uint32_t *top, size_t it, size_t *jt, size_t *f0)
{
    int64_t X = *jt >= it || (*jf < nf && E[fresh[*jf]].xb <= E[top[*jt]].xt) ? E[fresh[*jf]].xb
                                                                             : E[top[*jt]].xt;
    *f0 = *jf;
    while (*jf < nf && E[fresh[*jf]].xb == X)
        (*jf)++;
    while (*jt < it && E[top[*jt]].xt == X)
        (*jt)++;
    return X;
}

/* Passing edges of above[] (sorted at y, x at y in xc) whose x lies within
 * a horizontal edge H[h0..h1) at y (sorted by x0) meet it: a vertex there.
 * Their positions are added to dirty[]. */
static int horizontal_meets(sweep *s, int64_t y, const uint32_t *above, size_t na, size_t h0,
                            size_t h1, uint32_t *dirty, size_t *nd)
{
    const engine *g = s->g;
    const bedge *E = g->E;
    size_t hj = h0;
    /* the union of H[h0..hj) as disjoint intervals, the last [lo, reach]:
     * the edges come in order of x, and one at x >= (x0 of H[hj - 1]) - 1/2
     * can only lie in the last (the others end a unit before it starts) */
    int64_t lo = INT64_MIN, reach = INT64_MIN;
    for (size_t k = 0; k < na; k++) {
        uint32_t e = above[k];
        if (E[e].yb == y)
            continue;
        double xv = s->xc[e];
        while (hj < h1 && (double)g->H[hj].x0 <= xv + 0.5) {
            if (g->H[hj].x0 > reach)
                lo = g->H[hj].x0; /* (a new interval) */
            if (g->H[hj].x1 > reach)
                reach = g->H[hj].x1;
            hj++;
        }
        if ((double)reach >= xv - 0.5) {
            /* exact: lo <= x(y) <= reach */
            i128 n = x_num(&E[e], y), d = x_den(&E[e]);
            if ((i128)lo * d <= n && n <= (i128)reach * d) {
                if (!meet(s, e, y, 0))
                    return 0;
                dirty[(*nd)++] = (uint32_t)k;
            }
        }
    }
    return 1;
}

/* a and b (both active in a beam, not crossing inside it) coincide there:
 * they are on one line */
static inline int coincident(const bedge *a, const bedge *b)
{
    if (a->slope != b->slope) /* dx / dy rounded once: equal when collinear */
        return 0;
    i128 dx = a->xt - a->xb, dy = a->yt - a->yb;
    return dx * (b->yb - a->yb) == dy * (b->xb - a->xb) &&
           dx * (b->yt - a->yb) == dy * (b->xt - a->xb);
}

/* Classification of the beam above y: no crossing inside it, so the order
 * at y (ties by direction) is the order throughout.  Only the groups of
 * coincident edges around a dirty position (a new edge, a run break) need a
 * look: elsewhere the windings are those of the last beam, because the
 * edges ending and starting at one point (or along one chain of horizontal
 * edges, whose crossing edges are dirty) add up to the same windings.
 * dirty[] is sorted. */
static ALWAYS_INLINE int classify_dirty(sweep *s, int64_t y, const uint32_t *above,
                                        size_t na, const uint32_t *dirty, size_t nd)
{
    const engine *g = s->g;
    const bedge *E = g->E;
    int32_t *wr0 = s->wr0, *wr1 = s->wr1;
    size_t done = 0;
    for (size_t d = 0; d < nd; d++) {
        size_t k = dirty[d];
        if (k < done)
            continue;
        while (k > done && coincident(&E[above[k - 1]], &E[above[k]]))
            k--;
        int64_t w0 = 0, w1 = 0; /* (subject's, clip's) */
        if (k > 0) {
            w0 = wr0[above[k - 1]];
            w1 = wr1[above[k - 1]];
        }
        int left = inside(g, w0, w1);
        size_t k2 = k + 1;
        uint32_t rep = above[k];
        if (E[rep].op)
            w1 += E[rep].w;
        else
            w0 += E[rep].w;
        while (k2 < na && coincident(&E[above[k]], &E[above[k2]])) {
            uint32_t b = above[k2];
            if (b < rep)
                rep = b;
            if (E[b].op)
                w1 += E[b].w;
            else
                w0 += E[b].w;
            k2++;
        }
        int right = inside(g, w0, w1);
        for (size_t q = k; q < k2; q++) {
            uint32_t e = above[q];
            int boundary = e == rep && left != right;
            int up = left; /* result on the left (-x side): go up */
            if (s->run_open[e] && (!boundary || s->brk[e] || s->run_up[e] != up)) {
                if (!close_run(s, e, y))
                    return 0;
            }
            if (boundary && !s->run_open[e]) {
                s->run_open[e] = 1;
                s->run_up[e] = (unsigned char)up;
                s->run_y[e] = y;
                s->run_x[e] = y == E[e].yb ? E[e].xb : x_rounded(&E[e], y);
            }
            s->brk[e] = 0;
            wr0[e] = (int32_t)w0;
            wr1[e] = (int32_t)w1;
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
NOINLINE static int meet_at_next(sweep *s, uint32_t u, uint32_t v, int64_t yn)
{
    const bedge *E = s->g->E;
    int64_t x = 0;
    if (E[u].yt == yn || E[v].yt == yn || x_is_integer(&E[u], yn, &x)) {
        /* a grid point (ends are grid points): the runs of those that go
         * on break there */
        if (E[u].yt > yn)
            break_run(s, u, 1);
        if (E[v].yt > yn)
            break_run(s, v, 1);
        /* (an edge's end is a vertex already) */
        return !s->record_meets || E[u].yt == yn || E[v].yt == yn || record_meet(s, x, yn);
    }
    if (coincident(&E[u], &E[v]))
        return 1;
    return add_split(s, u, x, yn) && add_split(s, v, x, yn);
}

/* x lies within a unit of [a, b] or [b, a] */
static inline int near_span(double x, double a, double b)
{
    return a < b ? x >= a - 1 && x <= b + 1 : x >= b - 1 && x <= a + 1;
}

/* Returns 1 when done, 0 when out of memory, -1 when the active list was
 * not in order (a bug: the caller gives CG_ERANGE rather than a wrong
 * result). */
int boolean_run_sweep(sweep *s)
{
    engine *g = s->g;
    size_t ne = g->ne, nys = s->nys, ip = s->start_ip, it = s->start_it, ih = 0;
    const bedge *E = g->E;
    uint32_t *fresh = s->fresh, *dirty = s->dirty;
    /* the bottom of the next edge to start (INT64_MAX: none; no y reaches
     * it) */
#define NEXT_BOTTOM() (ip < ne ? E[s->by_bottom[ip]].yb : INT64_MAX)
    int64_t y_start = NEXT_BOTTOM();
    if (!s->start_iy)
        s->nact = 0;
    s->yspan = nys ? s->ys[nys - 1] - s->ys[0] : 0;
    for (size_t iy = s->start_iy; iy < nys; iy++) {
        int64_t y = s->ys[iy];
        /* the next scanline (the last has none: yn == y) */
        int64_t yn = iy + 1 < nys ? s->ys[iy + 1] : y;
        while (s->prev && s->band < s->nbands && s->bands[s->band][1] < y)
            s->band++; /* (bands come with prev only) */
        if (s->prev && s->band > 0 && !s->changed &&
            (s->band == s->nbands || y <= s->bands[s->band][0])) {
            /* between the split edges: the last pass's results hold from
             * the first checkpoint where the states agree to the last one
             * below the next split edge */
            const struct ck_log *L = s->prev;
            while (s->prev_j < L->npt && L->pt[s->prev_j].y < y)
                s->prev_j++;
            if (s->prev_j < L->npt && L->pt[s->prev_j].y == y &&
                boolean_ck_same(s, &L->pt[s->prev_j])) {
                size_t from = L->pt[s->prev_j].np, to = s->prev->end_np, j = 0;
                if (s->band < s->nbands) {
                    j = boolean_ck_load(s, L, s->prev_j, s->bands[s->band][0]);
                    if (!CG_INVARIANT(j != 0)) /* prev_j itself is one */
                        return -1;
                    to = L->pt[j - 1].np;
                }
                s->ranges[s->nranges][0] = from;
                s->ranges[s->nranges][1] = to;
                s->nranges++;
                if (!j)
                    return 1;
                s->prev_j = j;
                iy = s->start_iy;
                ip = s->start_ip;
                y_start = NEXT_BOTTOM();
                it = s->start_it;
                y = s->ys[iy];
                yn = iy + 1 < nys ? s->ys[iy + 1] : y;
            }
        }
        if (s->log && s->classify && s->visits >= s->ck_visits) {
            /* a checkpoint costs about as much as a look at each active
             * edge: one per eight such looks at most (and at most one per
             * 64 looks on large inputs, where the next pass's jumps need
             * not be as fine) */
            if (!boolean_ck_record(s, y))
                s->log = NULL;
            s->ck_visits = s->visits + 8 * s->nact + (s->g->ne >= 1024 ? 64 : 16);
        }
        uint32_t *below = s->act;
        size_t nb = s->nact;
        /* x at y of the edges of the last beam: computed there as its top */
        double *swap = s->xc;
        s->xc = s->xn;
        s->xn = swap;
        double *xc = s->xc, *xn = s->xn;
        /* breaks found at the top of the last beam are for this scanline;
         * the classification of the last beam cleared the others */
        unsigned char *bswap = s->brk;
        s->brk = s->brk_next;
        s->brk_next = bswap;
        /* the edges starting here, by x (by_bottom), ties by x at yn */
        size_t nf = 0;
        while (y_start == y) {
            uint32_t e = s->by_bottom[ip++];
            y_start = NEXT_BOTTOM();
            xc[e] = (double)E[e].xb;
            xn[e] = x_at(&E[e], yn);
            size_t m = nf;
            while (m > 0 && E[fresh[m - 1]].xb == E[e].xb &&
                   cmp_x(&E[fresh[m - 1]], &E[e], yn, xn[fresh[m - 1]], xn[e]) > 0) {
                fresh[m] = fresh[m - 1];
                m--;
            }
            fresh[m] = e;
            nf++;
        }
        /* edges ending here, by x: by_top[t0..it), needed only among many
         * passing edges (few take one look each below; `it` catches up
         * then) */
        size_t t0 = it;
        if (nb >= 32) {
            while (it < ne && E[s->by_top[it]].yt < y)
                it++;
            t0 = it;
            while (it < ne && E[s->by_top[it]].yt == y)
                it++;
        }
        /* the edges with a run break here, found at the top of the last
         * beam */
        uint32_t *q = s->brkq;
        s->brkq = s->brkq_next;
        s->brkq_next = q;
        size_t nq = s->nbrkq;
        int q_full = s->brkq_full;
        s->nbrkq = 0;
        s->brkq_full = 0;
        /* above: the passing edges in their order (sorted at y by the last
         * beam) with the ending ones taken out and the new ones put in, at
         * the points where edges end or start (found by binary search);
         * passing edges through such a point need a vertex there */
        size_t na = 0, jf = 0, nd = 0;
        int dirty_sorted = 1;
        uint32_t *above = s->nxt;
        /* the order at yn is checked from above[k0] on, after last (x at
         * yn of above[k0 - 1], or -INFINITY) */
        double last = -INFINITY;
        size_t k0 = 0;
        if (nb < 4 * (nf + it - t0) + 32) {
            /* few edges: one look at each, which also takes x at yn and
             * checks the order there up to the first inversion (k0) */
            k0 = SIZE_MAX;
#define TAKE(v, xv)                                                                                \
    do {                                                                                           \
        double x_ = (xv);                                                                          \
        if (x_ > last + 0.01)                                                                      \
            last = x_;                                                                             \
        else if (k0 == SIZE_MAX)                                                                   \
            k0 = na;                                                                               \
        above[na++] = (v);                                                                         \
    } while (0)
            for (size_t k = 0; k < nb; k++) {
                uint32_t e = below[k];
                const bedge *ee = &E[e];
                if (ee->yt == y) {
                    if (s->classify && s->run_open[e] && !close_run(s, e, y))
                        return 0;
                    continue;
                }
                while (jf < nf) {
                    uint32_t f = fresh[jf];
                    double xf = xc[f];
                    int c = xc[e] < xf - 0.01 ? -1 : cmp_x(ee, &E[f], y, xc[e], xf);
                    if (c < 0)
                        break;
                    if (c == 0) {
                        /* a new edge starts on a passing one: a vertex there */
                        if (!meet(s, e, y, 0))
                            return 0;
                        break; /* the order at yn is settled below */
                    }
                    dirty[nd++] = (uint32_t)na;
                    TAKE(f, xn[f]);
                    jf++;
                }
                if (s->brk[e])
                    dirty[nd++] = (uint32_t)na;
                double xe = yn == ee->yt ? (double)ee->xt
                                         : (double)ee->xb + (double)(yn - ee->yb) * ee->slope;
                xn[e] = xe;
                TAKE(e, xe);
            }
            while (jf < nf) {
                dirty[nd++] = (uint32_t)na;
                uint32_t f = fresh[jf++];
                TAKE(f, xn[f]);
            }
#undef TAKE
            if (k0 == SIZE_MAX)
                k0 = na;
            else
                last = k0 ? xn[above[k0 - 1]] : -INFINITY;
        } else {
            size_t jt = t0, ib = 0, ended = 0;
            while (jf < nf || jt < it) {
                size_t f0;
                int64_t X = next_event(E, fresh, nf, &jf, s->by_top, it, &jt, &f0);
                size_t lo = first_at_x(E, below, ib, nb, y, X, xc);
                copy_ids(above + na, below + ib, lo - ib);
                na += lo - ib;
                ib = lo;
                while (ib < nb && cmp_xi(&E[below[ib]], y, X, xc[below[ib]]) == 0) {
                    uint32_t e = below[ib++];
                    if (E[e].yt == y) {
                        ended++;
                        if (s->classify && s->run_open[e] && !close_run(s, e, y))
                            return 0;
                        continue;
                    }
                    if (jf > f0 && !meet(s, e, y, 0))
                        return 0;
                    dirty[nd++] = (uint32_t)na;
                    above[na++] = e;
                }
                for (size_t k = f0; k < jf; k++) {
                    dirty[nd++] = (uint32_t)na;
                    above[na++] = fresh[k];
                }
            }
            copy_ids(above + na, below + ib, nb - ib);
            na += nb - ib;
            if (!CG_INVARIANT(ended == it - t0)) /* sorted as expected */
                return -1;
            if (q_full) {
                for (size_t k = 0; k < na; k++)
                    if (s->brk[above[k]])
                        dirty[nd++] = (uint32_t)k;
                dirty_sorted = 0;
            } else if (nq && s->classify) {
                /* their positions, by binary search on x */
                for (size_t k = 0; k < nq; k++) {
                    uint32_t e = s->brkq[k];
                    if (E[e].yt <= y)
                        continue;
                    double xe = xc[e];
                    size_t lo = 0, hi = na;
                    while (lo < hi) {
                        size_t mid = lo + (hi - lo) / 2;
                        if (xc[above[mid]] < xe - 0.5)
                            lo = mid + 1;
                        else
                            hi = mid;
                    }
                    while (lo < na && above[lo] != e)
                        lo++;
                    if (lo < na) {
                        dirty[nd++] = (uint32_t)lo;
                        dirty_sorted = 0;
                    }
                }
            }
        }
        /* (edges meeting at y were found at the top of the last beam, or
         * just above) */
        /* horizontal edges on this scanline */
        size_t h0 = ih;
        if (ih < g->nh)
            horizontals_at(g, y, &ih, &h0);
        if (ih > h0) {
            if (!horizontal_meets(s, y, above, na, h0, ih, dirty, &nd))
                return 0;
            dirty_sorted = 0;
            if (s->classify && !horizontal_pieces(s, y, below, nb, above, na, h0, ih))
                return 0;
        }
        s->visits += na;
        /* the beam [y, yn] */
        uint32_t *t = s->act;
        s->act = above;
        s->nxt = t;
        s->nact = na;
        if (iy + 1 == nys)
            break;
        /* the order at yn: an inversion is a crossing inside the beam,
         * unless the two edges meet at y (then it is their order) */
        size_t cross_lo = SIZE_MAX, cross_hi = 0; /* positions of crossings */
        for (size_t k = k0; k < na; k++) {
            uint32_t v = above[k];
            const bedge *ev = &E[v];
            double xv = yn == ev->yt ? (double)ev->xt
                                     : (double)ev->xb + (double)(yn - ev->yb) * ev->slope;
            xn[v] = xv;
            if (xv > last + 0.01) {
                last = xv;
                continue;
            }
            size_t m = k;
            while (m > 0) {
                uint32_t u = above[m - 1];
                int c = cmp_x(&E[u], &E[v], yn, xn[u], xn[v]);
                if (c == 0 && (E[u].yt > yn || E[v].yt > yn) && !meet_at_next(s, u, v, yn))
                    return 0;
                if (c <= 0)
                    break;
                if (cmp_x(&E[u], &E[v], y, xc[u], xc[v]) != 0) {
                    /* u and v cross strictly inside the beam: the crossing
                     * of the input edges they come from, rounded, when it
                     * lies in the beam within a unit of both pieces (no
                     * drift), else the crossing of the pieces.  (Pieces
                     * bent by earlier splits can cross far from where
                     * their input edges do: a split there would bend them
                     * by units, and on coarse grids that went on pass
                     * after pass.) */
                    const bedge *a = &E[u], *b = &E[v];
                    int64_t px, py, oa[4], ob[4];
                    edge_orig(g, a, oa);
                    edge_orig(g, b, ob);
                    if (!s->use_input_lines ||
                        !boolean_line_intersection(oa[0], oa[1], oa[2], oa[3], ob[0], ob[1], ob[2],
                                                   ob[3], &px, &py) ||
                        py < y || py > yn || !near_span((double)px, xc[u], xn[u]) ||
                        !near_span((double)px, xc[v], xn[v])) {
                        boolean_line_intersection(a->xb, a->yb, a->xt, a->yt, b->xb, b->yb, b->xt,
                                                  b->yt, &px, &py);
                    }
                    if (py < y)
                        py = y;
                    if (py > yn)
                        py = yn;
                    if (!add_split(s, u, px, py) || !add_split(s, v, px, py))
                        return 0;
                    cross_lo = m - 1 < cross_lo ? m - 1 : cross_lo;
                    cross_hi = k > cross_hi ? k : cross_hi;
                }
                above[m] = u;
                m--;
            }
            above[m] = v;
            last = xn[above[k]];
        }
        if (!s->classify)
            continue; /* this pass will be repeated */
        if (!dirty_sorted)
            sort_u32(dirty, nd);
        if (cross_lo <= cross_hi) {
            /* edges crossed inside the beam (the pass will be repeated):
             * the windings of the positions between them change too */
            size_t w = 0, d = 0;
            for (; d < nd && dirty[d] < cross_lo; d++)
                if (!w || fresh[w - 1] != dirty[d])
                    fresh[w++] = dirty[d];
            for (size_t q = cross_lo; q <= cross_hi; q++)
                fresh[w++] = (uint32_t)q;
            for (; d < nd; d++)
                if (dirty[d] > cross_hi && fresh[w - 1] != dirty[d])
                    fresh[w++] = dirty[d];
            memcpy(dirty, fresh, w * sizeof *dirty);
            nd = w;
        }
        if (!classify_dirty(s, y, above, na, dirty, nd))
            return 0;
    }
    return 1;
#undef NEXT_BOTTOM
}

/* ---- the light sweep ------------------------------------------------------- */

/* the order of a and b just above a point they share: by direction */
static inline int cmp_dir(const bedge *a, const bedge *b)
{
    i128 l = (i128)(a->xt - a->xb) * (b->yt - b->yb), r = (i128)(b->xt - b->xb) * (a->yt - a->yb);
    return (l > r) - (l < r);
}

/* a is left of b just above the current scanline: do they cross before
 * either ends? */
static int cross_above(const bedge *a, const bedge *b)
{
    int64_t yt = a->yt < b->yt ? a->yt : b->yt;
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
    engine *g = s->g;
    size_t ne = g->ne, nys = s->nys, ip = 0, it = 0, ih = 0;
    const bedge *E = g->E;
    uint32_t *fresh = s->fresh, *dirty = s->dirty, *clus = s->clus, *seam = s->seam;
    const uint32_t *by_top = s->by_top;
    s->nact = 0;
    for (size_t iy = 0; iy < nys; iy++) {
        int64_t y = s->ys[iy];
        int has_next = iy + 1 < nys;
        uint32_t *below = s->act, *above = s->nxt;
        size_t nb = s->nact, na = 0, nd = 0, nseam = 0;
        /* edges starting here, by x, then by direction */
        size_t nf = 0;
        while (ip < ne && E[s->by_bottom[ip]].yb == y) {
            uint32_t e = s->by_bottom[ip++];
            size_t m = nf;
            while (m > 0 && E[fresh[m - 1]].xb == E[e].xb && cmp_dir(&E[fresh[m - 1]], &E[e]) > 0) {
                fresh[m] = fresh[m - 1];
                m--;
            }
            fresh[m] = e;
            nf++;
        }
        /* edges ending here, by x */
        size_t t0 = it;
        while (it < ne && E[by_top[it]].yt == y)
            it++;
        size_t ended = 0, jf = 0, jt = t0, ib = 0;
        /* every point where edges end or start: the edges through it
         * (ending, passing, starting) are replaced by the passing and
         * starting ones in the order of their directions */
        while (jf < nf || jt < it) {
            size_t f0;
            int64_t X = next_event(E, fresh, nf, &jf, by_top, it, &jt, &f0);
            size_t lo = first_at_x(E, below, ib, nb, y, X, NULL);
            copy_ids(above + na, below + ib, lo - ib);
            na += lo - ib;
            size_t nc = 0, c1 = lo;
            while (c1 < nb && cmp_xi(&E[below[c1]], y, X, x_at(&E[below[c1]], y)) == 0) {
                uint32_t e = below[c1++];
                if (E[e].yt == y) {
                    ended++;
                    if (s->run_open[e] && !close_run(s, e, y))
                        return 0;
                    continue;
                }
                s->brk[e] = 1; /* passes through a vertex: its run breaks */
                clus[nc++] = e;
            }
            ib = c1;
            for (size_t k = f0; k < jf; k++)
                clus[nc++] = fresh[k];
            /* in the order of their directions (passing edges may cross
             * there) */
            for (size_t k = 1; k < nc; k++) {
                uint32_t v = clus[k];
                size_t m = k;
                while (m > 0 && cmp_dir(&E[clus[m - 1]], &E[v]) > 0) {
                    clus[m] = clus[m - 1];
                    m--;
                }
                clus[m] = v;
            }
            for (size_t k = 0; k < nc; k++) {
                seam[nseam++] = (uint32_t)na;
                dirty[nd++] = (uint32_t)na;
                above[na++] = clus[k];
            }
            seam[nseam++] = (uint32_t)na;
        }
        if (ended != it - t0)
            return LIGHT_BAIL; /* an ending edge was not where expected */
        copy_ids(above + na, below + ib, nb - ib);
        na += nb - ib;
        /* horizontal edges on this scanline: the whole line is looked at */
        size_t h0;
        horizontals_at(g, y, &ih, &h0);
        if (ih > h0) {
            for (size_t k = 0; k < nb; k++)
                s->xc[below[k]] = x_at(&E[below[k]], y);
            for (size_t k = 0; k < na; k++)
                s->xc[above[k]] = x_at(&E[above[k]], y);
            if (!horizontal_meets(s, y, above, na, h0, ih, dirty, &nd))
                return 0;
            if (s->changed)
                return LIGHT_BAIL;
            sort_u32(dirty, nd);
            if (!horizontal_pieces(s, y, below, nb, above, na, h0, ih))
                return 0;
        }
        /* new neighbours */
        for (size_t k = 0; k < nseam; k++) {
            size_t p = seam[k];
            if (p > 0 && p < na && cross_above(&E[above[p - 1]], &E[above[p]]))
                return LIGHT_BAIL;
        }
        s->act = above;
        s->nxt = below;
        s->nact = na;
        if (!has_next)
            break;
        if (!classify_dirty(s, y, above, na, dirty, nd))
            return 0;
    }
    return 1;
}
