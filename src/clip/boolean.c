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
 * for speed), so the result does not depend on rounding luck. */
#include "internal.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef clip_i128 i128;

/* NOINLINE keeps a function out of its caller, where it would crowd the
 * registers of the sweep's hot loop; ALWAYS_INLINE puts the per-scanline
 * classification into the sweeps (measured cheaper than the calls) */
#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define NOINLINE
#define ALWAYS_INLINE inline
#endif

typedef struct bedge {
    int64_t xb, yb, xt, yt; /* bottom and top, yb < yt */
    double slope;           /* dx / dy */
    uint32_t orig;          /* the input edge it is a piece of (engine's O), or
                             * NO_ORIG: itself */
    int8_t w;               /* winding added when crossed from left to right */
    uint8_t op;             /* 0 subject, 1 clip */
} bedge;
#define NO_ORIG UINT32_MAX

typedef struct hseg { int64_t y, x0, x1; } hseg;
typedef struct splitpt { uint32_t edge; int64_t x, y; } splitpt;
typedef struct piece { int64_t x0, y0, x1, y1; } piece;

/* Room for one more item in arr (n items, room for cap; `fail` runs when
 * memory runs out).  arr may still be the caller's buffer `small` (on the
 * stack, for small inputs): it moves to the heap when it grows.  GROW is the
 * same for arrays that are on the heap from the start. */
#define GROW_SMALL(arr, n, cap, small, fail)                                   \
    do {                                                                       \
        if ((n) == (cap)) {                                                    \
            void *p_ = grow_from(arr, small, n, &(cap), sizeof *(arr));        \
            if (!p_)                                                           \
                fail;                                                          \
            (arr) = p_;                                                        \
        }                                                                      \
    } while (0)

/* GROW_SMALL's growth (out of line: the callers are hot): NULL when out of
 * memory, arr unchanged */
static void *grow_from(void *arr, const void *small, size_t n, size_t *cap, size_t size)
{
    size_t c = *cap ? *cap * 2 : 32;
    void *p = arr == small ? malloc(c * size) : realloc(arr, c * size);
    if (!p)
        return NULL;
    if (arr == small && n)
        memcpy(p, arr, n * size);
    *cap = c;
    return p;
}

#define GROW(arr, n, cap, fail) GROW_SMALL(arr, n, cap, NULL, fail)

typedef struct engine {
    bedge *E;
    size_t ne, cape;
    hseg *H;
    size_t nh, caph;
    splitpt *S;
    size_t ns, caps;
    piece *P;
    size_t np, capp;
    int64_t (*O)[4]; /* input edges of pieces (x0, y0, x1, y1): O_small or heap */
    size_t no, capo;
    int64_t O_small[16][4];
    /* the caller's buffers that E, S and P start in on small inputs (then
     * never freed; NULL when none) */
    bedge *E_small;
    splitpt *S_small;
    piece *P_small;
    cg_clip_op op;
    cg_clip_fill fill[2];
    unsigned char table[4]; /* in the result, by (in subject, in clip) */
    unsigned char near[5][5]; /* inside() for windings -2..2 */
} engine;

static int add_piece(engine *g, int64_t x0, int64_t y0, int64_t x1, int64_t y1, int op,
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

/* ---- exact helpers ------------------------------------------------------ */

/* floor(n / d + 1/2) for d > 0 */
static int64_t round_div(i128 n, i128 d)
{
    i128 q = n / d, r = n % d;
    if (r < 0) {
        q -= 1;
        r += d;
    }
    if (2 * r >= d)
        q += 1;
    return (int64_t)q;
}

/* x of edge e at scanline y as num / den, den > 0 */
static inline i128 x_num(const bedge *e, int64_t y)
{
    return (i128)e->xb * (e->yt - e->yb) + (i128)(y - e->yb) * (e->xt - e->xb);
}
static inline int64_t x_den(const bedge *e) { return e->yt - e->yb; }

static inline double x_at(const bedge *e, int64_t y)
{
    if (y == e->yb)
        return (double)e->xb;
    if (y == e->yt)
        return (double)e->xt;
    return (double)e->xb + (double)(y - e->yb) * e->slope;
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

static int x_is_integer(const bedge *e, int64_t y, int64_t *x)
{
    i128 n = x_num(e, y), d = x_den(e);
    *x = round_div(n, d);
    return (i128)*x * d == n;
}

/* ---- sorting ------------------------------------------------------------ */

typedef struct keyval { uint64_t key; uint32_t val; } keyval;

/* v put into a[0..i), in order by key, after the equal keys: a[0..i] in
 * order */
static inline void insert_key(keyval *a, size_t i, keyval v)
{
    for (; i > 0 && a[i - 1].key > v.key; i--)
        a[i] = a[i - 1];
    a[i] = v;
}

/* Stable sort of a[0..n) by key: straight insertion up to 48 keys, below
 * 2,048 one pass by the top bits then insertion (when the keys spread
 * evenly), else an LSD radix sort (6- or 11-bit digits, only as many passes
 * as the largest key needs); tmp holds n or is NULL. */
static int radix_sort(keyval *a, size_t n, keyval *tmp)
{
    if (n < 2)
        return 1;
    uint64_t all = 0;
    for (size_t i = 0; i < n; i++)
        all |= a[i].key;
    if (n <= 48) { /* few keys: straight insertion (stable) */
        for (size_t i = 1; i < n; i++)
            insert_key(a, i, a[i]);
        return 1;
    }
    keyval *t = tmp ? tmp : malloc(n * sizeof *t), *src = a, *dst = t;
    if (!t)
        return 0;
    if (n < 2048) {
        /* one pass by the top bits (about n buckets, stable), then straight
         * insertion, which moves keys within their bucket only: unless a
         * bucket holds many keys (uneven keys), then the digits below */
        int top = 0, b = 6;
        while (top < 64 && (all >> top))
            top++;
        while (((size_t)1 << b) < n)
            b++;
        int shift = top > b ? top - b : 0;
        size_t count[2048], most = 0;
        memset(count, 0, ((size_t)1 << b) * sizeof count[0]);
        for (size_t i = 0; i < n; i++) {
            size_t c = ++count[a[i].key >> shift];
            most = c > most ? c : most;
        }
        if (most <= 16) {
            size_t sum = 0;
            for (size_t d = 0; d < ((size_t)1 << b); d++) {
                size_t c = count[d];
                count[d] = sum;
                sum += c;
            }
            for (size_t i = 0; i < n; i++)
                t[count[a[i].key >> shift]++] = a[i];
            for (size_t i = 0; i < n; i++)
                insert_key(a, i, t[i]);
            if (!tmp)
                free(t);
            return 1;
        }
    }
    /* small inputs: small digit tables */
    const int bits = n < 2048 ? 6 : 11;
    for (int shift = 0; shift < 64 && (all >> shift); shift += bits) {
        size_t count[1 << 11];
        memset(count, 0, ((size_t)1 << bits) * sizeof count[0]);
        for (size_t i = 0; i < n; i++)
            count[(src[i].key >> shift) & ((1u << bits) - 1)]++;
        if (count[(src[0].key >> shift) & ((1u << bits) - 1)] == n)
            continue; /* every key has this digit */
        size_t sum = 0;
        for (size_t d = 0; d < (1u << bits); d++) {
            size_t c = count[d];
            count[d] = sum;
            sum += c;
        }
        for (size_t i = 0; i < n; i++)
            dst[count[(src[i].key >> shift) & ((1u << bits) - 1)]++] = src[i];
        keyval *x = src;
        src = dst;
        dst = x;
    }
    if (src != a)
        memcpy(a, src, n * sizeof *a);
    if (!tmp)
        free(t);
    return 1;
}

/* The natural runs of sort_two_keys' input, merged: idx[0..n) ordered by
 * (k1, k2, index) as the radix sort orders it, when the sequence is made
 * of at most MAX_RUNS ascending or strictly descending runs (the edges of
 * smooth rings come in a few monotone chains): 1, else 0 (nothing
 * written).  The runs are merged all at once, straight from the records
 * (each run's next key at hand, the least of them taken). */
#define MAX_RUNS 8
static int sort_runs(const int64_t *k1, const int64_t *k2, size_t stride, size_t n,
                     uint32_t *idx)
{
#define KEY(base, i) (*(const int64_t *)((const char *)(base) + (size_t)(i) * stride))
    /* run r: positions at[r], at[r] + step[r], ... up to (excluding) end[r] */
    ptrdiff_t at[MAX_RUNS], end[MAX_RUNS], step[MAX_RUNS];
    int64_t h1[MAX_RUNS], h2[MAX_RUNS];
    size_t nr = 0;
    for (size_t i = 0; i < n;) {
        if (nr == MAX_RUNS)
            return 0;
        int64_t p1 = KEY(k1, i), p2 = KEY(k2, i);
        size_t j = i + 1;
        if (j < n && (KEY(k1, j) < p1 || (KEY(k1, j) == p1 && KEY(k2, j) < p2))) {
            /* strictly descending (no ties: backwards, it is in order) */
            do {
                p1 = KEY(k1, j);
                p2 = KEY(k2, j);
                j++;
            } while (j < n && (KEY(k1, j) < p1 || (KEY(k1, j) == p1 && KEY(k2, j) < p2)));
            at[nr] = (ptrdiff_t)j - 1;
            end[nr] = (ptrdiff_t)i - 1;
            step[nr] = -1;
        } else {
            while (j < n && (KEY(k1, j) > p1 || (KEY(k1, j) == p1 && KEY(k2, j) >= p2))) {
                p1 = KEY(k1, j);
                p2 = KEY(k2, j);
                j++;
            }
            at[nr] = (ptrdiff_t)i;
            end[nr] = (ptrdiff_t)j;
            step[nr] = 1;
        }
        h1[nr] = KEY(k1, at[nr]);
        h2[nr] = KEY(k2, at[nr]);
        nr++;
        i = j;
    }
    for (size_t o = 0; o < n; o++) {
        size_t b = 0;
        for (size_t r = 1; r < nr; r++)
            if (h1[r] < h1[b] ||
                (h1[r] == h1[b] && (h2[r] < h2[b] || (h2[r] == h2[b] && at[r] < at[b]))))
                b = r;
        idx[o] = (uint32_t)at[b];
        at[b] += step[b];
        if (at[b] == end[b]) { /* run b is used up: the last takes its place */
            nr--;
            at[b] = at[nr];
            end[b] = end[nr];
            step[b] = step[nr];
            h1[b] = h1[nr];
            h2[b] = h2[nr];
        } else {
            h1[b] = KEY(k1, at[b]);
            h2[b] = KEY(k2, at[b]);
        }
    }
    return 1;
#undef KEY
}
/* idx[0..n) ordered by (k1[i], k2[i]) lexicographically (the keys are
 * int64 fields of records `stride` bytes apart); scratch of n, tmp of n or
 * NULL.  The natural runs merged when they are few (sort_runs), else a
 * radix sort by k1, then each run of equal k1 (short in practice) by k2. */
static int sort_two_keys(const int64_t *k1, const int64_t *k2, size_t stride, size_t n,
                         uint32_t *idx, keyval *scratch, keyval *tmp)
{
#define KEY(base, i) (*(const int64_t *)((const char *)(base) + (size_t)(i) * stride))
    if (n == 0)
        return 1;
    if (n <= 32) { /* few: straight insertion (stable: ties by index) */
        for (size_t i = 0; i < n; i++) {
            int64_t a1 = KEY(k1, i), a2 = KEY(k2, i);
            size_t j = i;
            for (; j > 0 && (KEY(k1, idx[j - 1]) > a1 ||
                             (KEY(k1, idx[j - 1]) == a1 && KEY(k2, idx[j - 1]) > a2));
                 j--)
                idx[j] = idx[j - 1];
            idx[j] = (uint32_t)i;
        }
        return 1;
    }
    if (n >= 64) {
        if (sort_runs(k1, k2, stride, n, idx))
            return 1;
    }
    int64_t lo1 = KEY(k1, 0);
    for (size_t i = 1; i < n; i++) {
        int64_t a = KEY(k1, i);
        lo1 = a < lo1 ? a : lo1;
    }
    for (size_t i = 0; i < n; i++)
        scratch[i] = (keyval){(uint64_t)(KEY(k1, i) - lo1), (uint32_t)i};
    if (!radix_sort(scratch, n, tmp))
        return 0;
    for (size_t i = 0; i < n;) {
        size_t j = i + 1;
        while (j < n && scratch[j].key == scratch[i].key)
            j++;
        if (j - i > 1) {
            int64_t lo2 = KEY(k2, scratch[i].val);
            for (size_t q = i + 1; q < j; q++) {
                int64_t b = KEY(k2, scratch[q].val);
                lo2 = b < lo2 ? b : lo2;
            }
            for (size_t q = i; q < j; q++)
                scratch[q].key = (uint64_t)(KEY(k2, scratch[q].val) - lo2);
            if (j - i > 256) {
                if (!radix_sort(scratch + i, j - i, tmp ? tmp + i : NULL))
                    return 0;
            } else {
                for (size_t q = i + 1; q < j; q++) {
                    keyval v = scratch[q];
                    size_t m = q;
                    for (; m > i && scratch[m - 1].key > v.key; m--)
                        scratch[m] = scratch[m - 1];
                    scratch[m] = v;
                }
            }
        }
        i = j;
    }
    for (size_t i = 0; i < n; i++)
        idx[i] = scratch[i].val;
    return 1;
#undef KEY
}

/* ---- the sweep ------------------------------------------------------------ */

typedef struct sweep {
    engine *g;
    int64_t *ys;
    size_t nys;
    uint32_t *by_bottom; /* edges sorted by yb */
    uint32_t *act, *nxt, *fresh, *dirty;
    uint32_t *by_top, *clus, *seam; /* the light sweep's */
    keyval *scratch, *scratch2;      /* for sorting */
    hseg *hsorted;
    uint32_t *horder;
    void *mem; /* all of the above, carved from one block */
    size_t memcap;
    void *mem_small; /* the caller's block mem starts as (never freed) */
    int32_t *wr0, *wr1; /* windings right of each edge (its coincident group):
                         * sums of at most ne <= INT32_MAX terms of +-1 */
    size_t nact;
    double *xc, *xn; /* x at the current scanline, at the next one */
    /* runs */
    unsigned char *run_open, *run_up;
    unsigned char *brk, *brk_next; /* a run breaks at this scanline, the next */
    int64_t *run_x, *run_y;
    int classify, changed;
    size_t visits; /* active edges summed over the scanlines (full sweep) */
    uint32_t *brkq, *brkq_next; /* the edges of brk, of brk_next (full sweep) */
    size_t nbrkq, capbrkq;
    int brkq_full;
    int use_input_lines; /* round on the input edges (early passes) */
    struct ck_log *log;   /* checkpoints of this pass, or NULL */
    size_t ck_visits;     /* the next checkpoint once visits reach this */
    size_t start_iy, start_ip, start_it; /* where the sweep starts (resumed) */
    int64_t yspan;        /* from the first scanline to the last */
    /* the hand-over to the last pass's results (ck_same) */
    const struct ck_log *prev; /* or NULL */
    const uint32_t *prev_map;  /* its edge numbers to ours */
    size_t prev_ne, prev_j;
    const int64_t (*bands)[2]; /* the y ranges of the edges it split, merged */
    size_t nbands, band;
    size_t (*ranges)[2];       /* the ranges of its pieces taken */
    size_t nranges;
} sweep;

/* Checkpoints.  A full pass that splits edges is repeated, but below the
 * lowest split edge the next pass would see exactly the same edges, events
 * and classification.  So while a pass still classifies, it notes from time
 * to time its whole state at the start of a scanline (the active edges in
 * order, with their x there, windings, open runs and run breaks, and how
 * many pieces were emitted); the next pass starts at the last such scanline
 * at or below every split edge, with that state, and keeps the pieces
 * emitted below it. */
typedef struct ck_edge {
    uint32_t e;
    unsigned flags; /* 1 run break here, 2 run open, 4 run goes up */
    int32_t wr0, wr1;
    double x;
    int64_t run_x, run_y;
} ck_edge;
typedef struct ck_point { int64_t y; size_t np, first, n; } ck_point;
typedef struct ck_log {
    ck_point *pt;
    size_t npt, cappt;
    ck_edge *ed;
    size_t ned, caped;
    size_t budget; /* most edge records kept */
    size_t end_np; /* pieces at the end of the pass */
} ck_log;

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
static int meet(sweep *s, uint32_t e, int64_t y, int next)
{
    int64_t x;
    const bedge *ed = &s->g->E[e];
    if (x_is_integer(ed, y, &x)) {
        if (next && !s->brk_next[e]) {
            if (s->nbrkq < s->capbrkq)
                s->brkq_next[s->nbrkq++] = e;
            else
                s->brkq_full = 1;
        }
        (next ? s->brk_next : s->brk)[e] = 1;
        /* an exact split is not needed: the run breaks there */
        return 1;
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

/* Intersection of the lines a0-a1 and b0-b1 rounded to the grid; 0 when
 * parallel. */
static int line_intersection(int64_t ax0, int64_t ay0, int64_t ax1, int64_t ay1, int64_t bx0,
                             int64_t by0, int64_t bx1, int64_t by1, int64_t *px, int64_t *py)
{
    i128 dax = ax1 - ax0, day = ay1 - ay0, dbx = bx1 - bx0, dby = by1 - by0;
    i128 den = dax * dby - day * dbx;
    if (den == 0)
        return 0;
    i128 num = (i128)(bx0 - ax0) * dby - (i128)(by0 - ay0) * dbx;
    if (den < 0) {
        den = -den;
        num = -num;
    }
    /* the point must be on segment a (0 <= t <= 1) for the products to fit */
    if (num < 0 || num > den)
        return 0;
    *px = ax0 + round_div(num * dax, den);
    *py = ay0 + round_div(num * day, den);
    return 1;
}

static inline int fill_in(cg_clip_fill f, int64_t w)
{
    switch (f) {
    case CG_CLIP_EVEN_ODD:
        return (int)(w & 1);
    case CG_CLIP_NON_ZERO:
        return w != 0;
    case CG_CLIP_POSITIVE:
        return w > 0;
    default:
        return w < 0;
    }
}

static inline int inside_rule(const engine *g, int64_t wa, int64_t wb)
{
    return g->table[(fill_in(g->fill[0], wa) << 1) | fill_in(g->fill[1], wb)];
}

/* whether a point with windings wa (subject) and wb (clip) is in the result */
static inline int inside(const engine *g, int64_t wa, int64_t wb)
{
    if ((uint64_t)(wa + 2) < 5 && (uint64_t)(wb + 2) < 5)
        return g->near[wa + 2][wb + 2];
    return inside_rule(g, wa, wb);
}

static int emit(engine *g, int64_t x0, int64_t y0, int64_t x1, int64_t y1)
{
    if (x0 == x1 && y0 == y1)
        return 1;
    GROW_SMALL(g->P, g->np, g->capp, g->P_small, return 0);
    g->P[g->np++] = (piece){x0, y0, x1, y1};
    return 1;
}

static int close_run(sweep *s, uint32_t e, int64_t y)
{
    const bedge *ed = &s->g->E[e];
    int64_t x = y == ed->yt ? ed->xt : round_div(x_num(ed, y), x_den(ed));
    s->run_open[e] = 0;
    if (s->run_up[e])
        return emit(s->g, s->run_x[e], s->run_y[e], x, y);
    return emit(s->g, x, y, s->run_x[e], s->run_y[e]);
}

/* Horizontal boundary pieces on scanline y: between below[] (edges reaching
 * y from below, x at y in xc) and above[] (edges leaving y upwards). */
static int horizontal_pieces(sweep *s, int64_t y, const uint32_t *below, size_t nb,
                             const uint32_t *above, size_t na)
{
    engine *g = s->g;
    int64_t wb[2] = {0, 0}, wa[2] = {0, 0};
    size_t i = 0, j = 0;
    int have_prev = 0;
    int64_t prev_x = 0;
    while (i < nb || j < na) {
        /* the leftmost next position */
        const bedge *e;
        uint32_t idx;
        if (j >= na || (i < nb && cmp_x(&g->E[below[i]], &g->E[above[j]], y, s->xc[below[i]],
                                        s->xc[above[j]]) <= 0))
            idx = below[i];
        else
            idx = above[j];
        e = &g->E[idx];
        int64_t X = round_div(x_num(e, y), x_den(e));
        if (have_prev) {
            int sb = inside(g, wb[0], wb[1]), sa = inside(g, wa[0], wa[1]);
            if (sb != sa && X != prev_x) {
                if (sa ? !emit(g, prev_x, y, X, y) : !emit(g, X, y, prev_x, y))
                    return 0;
            }
        }
        /* apply everything at this position */
        double xv = s->xc[idx];
        while (i < nb && cmp_x(&g->E[below[i]], e, y, s->xc[below[i]], xv) == 0) {
            wb[g->E[below[i]].op] += g->E[below[i]].w;
            i++;
        }
        while (j < na && cmp_x(&g->E[above[j]], e, y, s->xc[above[j]], xv) == 0) {
            wa[g->E[above[j]].op] += g->E[above[j]].w;
            j++;
        }
        have_prev = 1;
        prev_x = X;
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
    int64_t reach = INT64_MIN;
    for (size_t k = 0; k < na; k++) {
        uint32_t e = above[k];
        if (E[e].yb == y)
            continue;
        double xv = s->xc[e];
        while (hj < h1 && (double)g->H[hj].x0 <= xv + 0.5) {
            if (g->H[hj].x1 > reach)
                reach = g->H[hj].x1;
            hj++;
        }
        if ((double)reach >= xv - 0.5) {
            /* exact: x0 <= x(y) <= reach for some segment */
            i128 n = x_num(&E[e], y), d = x_den(&E[e]);
            int covered = 0;
            for (size_t q = h0; q < hj && !covered; q++)
                covered = (i128)g->H[q].x0 * d <= n && n <= (i128)g->H[q].x1 * d;
            if (covered) {
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
                s->run_x[e] = y == E[e].yb ? E[e].xb : round_div(x_num(&E[e], y), x_den(&E[e]));
            }
            s->brk[e] = 0;
            wr0[e] = (int32_t)w0;
            wr1[e] = (int32_t)w1;
        }
        done = k2;
    }
    return 1;
}

/* an active edge's run flags, as ck_edge.flags */
static inline unsigned ck_flags(const sweep *s, uint32_t e)
{
    return (unsigned)s->brk_next[e] | (unsigned)s->run_open[e] << 1 |
           (unsigned)(s->run_open[e] && s->run_up[e]) << 2;
}

/* Notes the state at the start of scanline y (before its events): 0 when
 * no more checkpoints are taken (budget spent or out of memory). */
static int ck_record(sweep *s, int64_t y)
{
    ck_log *L = s->log;
    size_t n = s->nact;
    if (L->ned + n > L->budget)
        return 0;
    GROW(L->pt, L->npt, L->cappt, return 0);
    while (L->ned + n > L->caped) {
        size_t c = L->caped ? 2 * L->caped : 256;
        ck_edge *p = realloc(L->ed, c * sizeof *p);
        if (!p)
            return 0;
        L->ed = p;
        L->caped = c;
    }
    L->pt[L->npt++] = (ck_point){y, s->g->np, L->ned, n};
    for (size_t k = 0; k < n; k++) {
        uint32_t e = s->act[k];
        L->ed[L->ned++] = (ck_edge){e, ck_flags(s, e), s->wr0[e], s->wr1[e], s->xn[e],
                                    s->run_x[e], s->run_y[e]};
    }
    return 1;
}

/* Is this pass's state at the start of the scanline of checkpoint c of the
 * last pass the same as that pass's there?  Then, as no edge above was
 * split, the rest of this pass would be the rest of that one. */
static int ck_same(const sweep *s, const ck_point *c)
{
    if (c->n != s->nact)
        return 0;
    const ck_edge *r = s->prev->ed + c->first;
    for (size_t k = 0; k < c->n; k++) {
        uint32_t e = s->act[k];
        if (r[k].e >= s->prev_ne || s->prev_map[r[k].e] != e || r[k].flags != ck_flags(s, e) ||
            r[k].x != s->xn[e] || r[k].wr0 != s->wr0[e] || r[k].wr1 != s->wr1[e] ||
            (s->run_open[e] && (r[k].run_x != s->run_x[e] || r[k].run_y != s->run_y[e])))
            return 0;
    }
    return 1;
}

/* first of a[0..n) (edge numbers sorted by a field) whose field is >= y */
static size_t first_edge_at(const bedge *E, const uint32_t *a, size_t n, int64_t y, int top)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if ((top ? E[a[mid]].yt : E[a[mid]].yb) < y)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Takes the state of the last checkpoint L->pt[j] (j >= j0) of the last
 * pass at or below y (every edge active there kept its number, map[] of
 * the last pass's): its index + 1, or 0 when there is none. */
static size_t ck_load(sweep *s, const ck_log *L, size_t j0, int64_t y)
{
    size_t j = L->npt;
    while (j > j0 && L->pt[j - 1].y > y)
        j--;
    if (j == j0)
        return 0;
    const ck_point *c = &L->pt[j - 1];
    size_t lo = 0, hi = s->nys;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (s->ys[mid] < c->y)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo == s->nys || s->ys[lo] != c->y)
        return 0;
    /* (L->ed is NULL when no checkpoint logged an edge) */
    const ck_edge *r = c->n ? L->ed + c->first : NULL;
    for (size_t k = 0; k < c->n; k++)
        if (r[k].e >= s->prev_ne || s->prev_map[r[k].e] == UINT32_MAX)
            return 0; /* (cannot happen: no active edge there was split) */
    s->nbrkq = 0;
    s->brkq_full = 0;
    for (size_t k = 0; k < c->n; k++) {
        uint32_t e = s->prev_map[r[k].e];
        s->act[k] = e;
        s->xn[e] = r[k].x;
        s->brk_next[e] = (unsigned char)(r[k].flags & 1);
        s->run_open[e] = (unsigned char)(r[k].flags >> 1 & 1);
        s->run_up[e] = (unsigned char)(r[k].flags >> 2 & 1);
        s->wr0[e] = r[k].wr0;
        s->wr1[e] = r[k].wr1;
        s->run_x[e] = r[k].run_x;
        s->run_y[e] = r[k].run_y;
        if (r[k].flags & 1)
            s->brkq_next[s->nbrkq++] = e;
    }
    s->nact = c->n;
    s->start_iy = lo;
    s->start_ip = first_edge_at(s->g->E, s->by_bottom, s->g->ne, c->y, 0);
    s->start_it = first_edge_at(s->g->E, s->by_top, s->g->ne, c->y, 1);
    return j;
}

/* Returns 1 when done, 0 when out of memory, -1 when the active list was
 * not in order (a bug: the caller gives CG_ERANGE rather than a wrong
 * result). */
static int run_sweep(sweep *s)
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
            if (s->prev_j < L->npt && L->pt[s->prev_j].y == y && ck_same(s, &L->pt[s->prev_j])) {
                size_t from = L->pt[s->prev_j].np, to = s->prev->end_np, j = 0;
                if (s->band < s->nbands) {
                    j = ck_load(s, L, s->prev_j, s->bands[s->band][0]);
                    if (!j)
                        return -1; /* (cannot happen: prev_j itself is one) */
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
            if (!ck_record(s, y))
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
            if (ended != it - t0)
                return -1; /* not sorted as expected (cannot happen) */
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
            if (s->classify && !horizontal_pieces(s, y, below, nb, above, na))
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
                if (c == 0 && ((E[u].yt > yn && !meet(s, u, yn, 1)) || (E[v].yt > yn && !meet(s, v, yn, 1))))
                    return 0;
                if (c <= 0)
                    break;
                if (cmp_x(&E[u], &E[v], y, xc[u], xc[v]) != 0) {
                    /* u and v cross strictly inside the beam: the crossing
                     * of the input edges they come from, rounded, when it
                     * lies in the beam (no drift), else the crossing of the
                     * pieces */
                    const bedge *a = &E[u], *b = &E[v];
                    int64_t px, py, oa[4], ob[4];
                    edge_orig(g, a, oa);
                    edge_orig(g, b, ob);
                    if (!s->use_input_lines ||
                        !line_intersection(oa[0], oa[1], oa[2], oa[3], ob[0], ob[1], ob[2], ob[3],
                                           &px, &py) ||
                        py < y || py > yn) {
                        line_intersection(a->xb, a->yb, a->xt, a->yt, b->xb, b->yb, b->xt, b->yt,
                                          &px, &py);
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

#define LIGHT_BAIL 2
#define LIGHT_COST 16

/* The sweep of a pass that is expected to find nothing to split (the pass
 * after the splits): Bentley-Ottmann's idea instead of a look at every
 * active edge on every scanline.  The active list changes only at the
 * points where edges end or start (found by binary search); two edges can
 * only cross after being neighbours, so each new pair of neighbours is
 * checked once.  Returns 1 when the pass is final (the pieces are emitted),
 * LIGHT_BAIL when something needs a split (the caller runs the full sweep),
 * 0 when out of memory. */
static int light_sweep(sweep *s)
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
            if (!horizontal_pieces(s, y, below, nb, above, na))
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

/* qsort, by straight insertion when n is small (the assembly's few rings;
 * cmp is a total order, so the result is qsort's) */
static void sort_few(void *base, size_t n, size_t size, int (*cmp)(const void *, const void *))
{
    unsigned char v[64], *a = base;
    if (n > 16 || size > sizeof v) {
        qsort(base, n, size, cmp);
        return;
    }
    for (size_t i = 1; i < n; i++) {
        size_t j = i;
        memcpy(v, a + i * size, size);
        for (; j > 0 && cmp(a + (j - 1) * size, v) > 0; j--)
            memcpy(a + j * size, a + (j - 1) * size, size);
        if (j != i)
            memcpy(a + j * size, v, size);
    }
}

/* Replaces every edge that has split points by its pieces. */
typedef struct split_sort { int64_t x, y; i128 t; } split_sort;

static int cmp_along(const void *a, const void *b)
{
    const split_sort *p = a, *q = b;
    if (p->t != q->t)
        return p->t < q->t ? -1 : 1;
    if (p->y != q->y)
        return p->y < q->y ? -1 : 1;
    return (p->x > q->x) - (p->x < q->x);
}

/* Does the segment a-b meet the closed unit square centred on p (the "hot
 * pixel" of a rounded point)?  Exact, on doubled coordinates. */
static int meets_pixel(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
    i128 x0 = 2 * (i128)px - 1, x1 = 2 * (i128)px + 1, y0 = 2 * (i128)py - 1, y1 = 2 * (i128)py + 1;
    i128 Ax = 2 * (i128)ax, Ay = 2 * (i128)ay, Bx = 2 * (i128)bx, By = 2 * (i128)by;
    if ((Ax < x0 && Bx < x0) || (Ax > x1 && Bx > x1) || (Ay < y0 && By < y0) || (Ay > y1 && By > y1))
        return 0;
    /* the line through a and b meets the square only if the centre is
     * within half the square's width across the line, |d x (p - a)| <=
     * (|dx| + |dy|) / 2: in doubles first, with a wide margin for rounding */
    double dx = (double)(bx - ax), dy = (double)(by - ay);
    double u = dy * (double)(px - ax), v = dx * (double)(py - ay);
    if (fabs(u - v) > 0.5 * (fabs(dx) + fabs(dy)) + 1e-9 * (fabs(u) + fabs(v)) + 1)
        return 0;
    int pos = 0, neg = 0;
    i128 cx[4] = {x0, x1, x1, x0}, cy[4] = {y0, y0, y1, y1};
    for (int k = 0; k < 4; k++) {
        i128 o = (Bx - Ax) * (cy[k] - Ay) - (By - Ay) * (cx[k] - Ax);
        pos |= o > 0;
        neg |= o < 0;
    }
    return !(pos && !neg) && !(neg && !pos);
}

/* Snap rounding (Hobby): every edge that passes through the pixel of a
 * rounded split point is split there too, so that nearly parallel edges
 * meet at one grid point instead of crossing again a little further on.
 * Used from the second pass on.  The points are put in a grid of square
 * cells (about two points a cell; sorted by y, then x, in each cell), and
 * each edge looks at the cells along it, row by row: the cost follows the
 * edges' lengths and the points near them, not the points in their y
 * range (dense crossings of long edges made that quadratic). */
typedef struct hot_grid {
    int64_t x0, y0, side;
    size_t cols, rows;
    size_t *start; /* the points of cell k: pts[start[k]..start[k + 1]) */
    cg_point64 *pts;
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
    return (size_t)((y - h->y0) / h->side) * h->cols + (size_t)((x - h->x0) / h->side);
}

static int hot_grid_build(hot_grid *h, const splitpt *S, size_t ns)
{
    int64_t x1 = S[0].x, y1 = S[0].y;
    h->x0 = x1;
    h->y0 = y1;
    for (size_t k = 1; k < ns; k++) {
        h->x0 = S[k].x < h->x0 ? S[k].x : h->x0;
        h->y0 = S[k].y < h->y0 ? S[k].y : h->y0;
        x1 = S[k].x > x1 ? S[k].x : x1;
        y1 = S[k].y > y1 ? S[k].y : y1;
    }
    double w = (double)(x1 - h->x0) + 1, ht = (double)(y1 - h->y0) + 1;
    double side = ceil(sqrt(w * ht * 2 / (double)ns));
    for (;;) { /* at most about 4 cells a point, whatever the shape */
        double cols = floor((w - 1) / side) + 1, rows = floor((ht - 1) / side) + 1;
        if (cols * rows <= 4 * (double)ns + 64)
            break;
        side = ceil(side * 1.5);
    }
    h->side = (int64_t)side;
    h->cols = (size_t)((x1 - h->x0) / h->side) + 1;
    h->rows = (size_t)((y1 - h->y0) / h->side) + 1;
    size_t cells = h->cols * h->rows;
    h->start = calloc(cells + 1, sizeof *h->start);
    h->pts = malloc(ns * sizeof *h->pts);
    size_t *next = malloc((cells + 1) * sizeof *next);
    if (!h->start || !h->pts || !next) {
        free(next);
        return 0;
    }
    for (size_t k = 0; k < ns; k++)
        h->start[hot_cell(h, S[k].x, S[k].y) + 1]++;
    for (size_t c = 0; c < cells; c++)
        h->start[c + 1] += h->start[c];
    memcpy(next, h->start, (cells + 1) * sizeof *next);
    for (size_t k = 0; k < ns; k++)
        h->pts[next[hot_cell(h, S[k].x, S[k].y)]++] = (cg_point64){S[k].x, S[k].y};
    free(next);
    for (size_t c = 0; c < cells; c++)
        if (h->start[c + 1] - h->start[c] > 1)
            sort_few(h->pts + h->start[c], h->start[c + 1] - h->start[c], sizeof *h->pts,
                     cmp_point_yx);
    return 1;
}

static int add_hot_pixel_splits(engine *g, int vertices)
{
    size_t ns = g->ns;
    if (ns == 0)
        return 1;
    hot_grid h;
    memset(&h, 0, sizeof h);
    int ok;
    if (vertices) {
        /* the edges' ends are hot pixels too (complete snap rounding) */
        splitpt *pts = malloc((ns + 2 * g->ne) * sizeof *pts);
        ok = pts != NULL;
        if (ok) {
            memcpy(pts, g->S, ns * sizeof *pts);
            size_t n = ns;
            for (size_t i = 0; i < g->ne; i++) {
                pts[n++] = (splitpt){0, g->E[i].xb, g->E[i].yb};
                pts[n++] = (splitpt){0, g->E[i].xt, g->E[i].yt};
            }
            ok = hot_grid_build(&h, pts, n);
            free(pts);
        }
    } else {
        ok = hot_grid_build(&h, g->S, ns);
    }
    for (size_t i = 0; ok && i < g->ne; i++) {
        const bedge e = g->E[i];
        int64_t xlo = e.xb < e.xt ? e.xb : e.xt, xhi = e.xb < e.xt ? e.xt : e.xb;
        if (e.yt + 1 < h.y0)
            continue;
        size_t r = e.yb - 1 > h.y0 ? (size_t)((e.yb - 1 - h.y0) / h.side) : 0;
        for (; ok && r < h.rows; r++) {
            int64_t ry0 = h.y0 + (int64_t)r * h.side, ry1 = ry0 + h.side - 1;
            if (ry0 > e.yt + 1)
                break;
            /* the edge's x over the row's y and one unit more each way
             * (clamped to the edge), widened by two units: a pixel whose
             * centre is there may meet it */
            int64_t ya = ry0 - 1 > e.yb ? ry0 - 1 : e.yb, yz = ry1 + 1 < e.yt ? ry1 + 1 : e.yt;
            if (ya > yz)
                ya = yz = ya > e.yt ? e.yt : e.yb;
            double xa = x_at(&e, ya), xz = x_at(&e, yz);
            double lo = (xa < xz ? xa : xz) - 2 - (double)h.x0;
            double hi = (xa < xz ? xz : xa) + 2 - (double)h.x0;
            if (hi < 0)
                continue;
            size_t c0 = lo <= 0 ? 0 : (size_t)(lo / (double)h.side);
            size_t c1 = (size_t)(hi / (double)h.side);
            if (c1 >= h.cols)
                c1 = h.cols - 1;
            for (size_t c = c0; ok && c <= c1; c++) {
                size_t cell = r * h.cols + c;
                for (size_t q = h.start[cell]; q < h.start[cell + 1]; q++) {
                    int64_t px = h.pts[q].x, py = h.pts[q].y;
                    if ((q > h.start[cell] && px == h.pts[q - 1].x && py == h.pts[q - 1].y) ||
                        py < e.yb - 1 || py > e.yt + 1 || px < xlo - 1 || px > xhi + 1 ||
                        (px == e.xb && py == e.yb) || (px == e.xt && py == e.yt) ||
                        !meets_pixel(e.xb, e.yb, e.xt, e.yt, px, py))
                        continue;
                    GROW_SMALL(g->S, g->ns, g->caps, g->S_small, {
                        ok = 0;
                        break;
                    });
                    g->S[g->ns++] = (splitpt){(uint32_t)i, px, py};
                }
            }
        }
    }
    free(h.start);
    free(h.pts);
    return ok;
}

/* Notes input edge e as the input edge of its pieces: its number, NO_ORIG
 * when out of memory.  (The first few in the engine itself.) */
static uint32_t add_orig(engine *g, const bedge *e)
{
    if (!g->O) {
        g->O = g->O_small;
        g->capo = sizeof g->O_small / sizeof g->O_small[0];
    }
    GROW_SMALL(g->O, g->no, g->capo, g->O_small, return NO_ORIG);
    int64_t *o = g->O[g->no];
    o[0] = e->xb;
    o[1] = e->yb;
    o[2] = e->xt;
    o[3] = e->yt;
    return (uint32_t)g->no++;
}

/* map[old edge] receives its new index, or UINT32_MAX when it was split
 * (the pieces come after the edges kept, in g->E[*kept..]); mem (cap
 * bytes, or NULL) is scratch. */
static int apply_splits(engine *g, uint32_t *map, size_t *kept, void *mem, size_t cap)
{
    size_t old_ne = g->ne, ns = g->ns;
    split_sort small[34], *buf = small; /* the points of one edge */
    size_t capbuf = sizeof small / sizeof small[0];
    /* the split points by edge (a counting sort into order[]; the points of
     * one edge are put in order along it below), in one block with dead[]:
     * the caller's `mem` (cap bytes) when large enough */
    size_t at = (old_ne + 1 + 3) & ~(size_t)3, bytes = at + (old_ne + 1 + ns) * sizeof(uint32_t);
    unsigned char *own = bytes > cap || !mem ? calloc(bytes, 1) : NULL;
    unsigned char *dead = own ? own : mem;
    if (!dead)
        return 0;
    if (!own)
        memset(dead, 0, at + (old_ne + 1) * sizeof(uint32_t)); /* (dead and first) */
    uint32_t *first = (uint32_t *)(void *)(dead + at), *order = first + old_ne + 1;
    for (size_t k = 0; k < ns; k++)
        first[g->S[k].edge + 1]++;
    for (size_t i = 1; i <= old_ne; i++)
        first[i] += first[i - 1];
    for (size_t k = 0; k < ns; k++)
        order[first[g->S[k].edge]++] = (uint32_t)k;
    for (size_t i = 0; i < ns;) {
        size_t j = i;
        uint32_t ei = g->S[order[i]].edge;
        while (j < ns && g->S[order[j]].edge == ei)
            j++;
        size_t n = j - i;
        if (n + 2 > capbuf) {
            capbuf = (n + 2) * 2;
            split_sort *nb = buf == small ? malloc(capbuf * sizeof *nb)
                                          : realloc(buf, capbuf * sizeof *nb);
            if (!nb) {
                if (buf != small)
                    free(buf);
                free(own);
                return 0;
            }
            buf = nb;
        }
        bedge e = g->E[ei];
        i128 dx = e.xt - e.xb, dy = e.yt - e.yb;
        size_t m = 0;
        buf[m++] = (split_sort){e.xb, e.yb, -1};
        for (size_t k = i; k < j; k++) {
            int64_t x = g->S[order[k]].x, y = g->S[order[k]].y;
            i128 t = (i128)(x - e.xb) * dx + (i128)(y - e.yb) * dy;
            buf[m++] = (split_sort){x, y, t};
        }
        sort_few(buf + 1, m - 1, sizeof *buf, cmp_along);
        buf[m++] = (split_sort){e.xt, e.yt, 0};
        dead[ei] = 1;
        /* the input edge of the pieces */
        uint32_t orig = e.orig == NO_ORIG ? add_orig(g, &e) : e.orig;
        if (orig == NO_ORIG) {
            if (buf != small)
                free(buf);
            free(own);
            return 0;
        }
        /* the path direction of the edge: w == -1 means upwards */
        for (size_t k = 0; k + 1 < m; k++) {
            split_sort p = buf[k], q = buf[k + 1];
            if (p.x == q.x && p.y == q.y)
                continue;
            int ok = e.w < 0 ? add_piece(g, p.x, p.y, q.x, q.y, e.op, orig)
                             : add_piece(g, q.x, q.y, p.x, p.y, e.op, orig);
            if (!ok) {
                if (buf != small)
                    free(buf);
                free(own);
                return 0;
            }
        }
        i = j;
    }
    if (buf != small)
        free(buf);
    /* compact */
    size_t w = 0;
    for (size_t i = 0; i < old_ne; i++) {
        map[i] = dead[i] ? UINT32_MAX : (uint32_t)w;
        if (!dead[i])
            g->E[w++] = g->E[i];
    }
    *kept = w;
    for (size_t i = old_ne; i < g->ne; i++)
        g->E[w++] = g->E[i];
    g->ne = w;
    g->ns = 0;
    free(own);
    return 1;
}

/* ---- small inputs: crossings found pair by pair ------------------------------ */

/* On few edges, testing every pair for a crossing costs less than a sweep
 * that only looks for them.  The crossings found are rounded as the first
 * sweep rounds them and the edges split before it, so that it normally
 * finds nothing more to split and classifies at once.  It still verifies:
 * a crossing made by the rounding is split by further passes as usual. */
#define PAIRS_MAX_EDGES 112 /* (below 128: an edge number fits in 7 bits) */

/* The side of c from the line a-b: its sign.  `narrow`: every coordinate
 * difference is below 2^31, so 64-bit products are exact. */
static inline int orientation(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t cx,
                              int64_t cy, int narrow)
{
    if (narrow) {
        int64_t o = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
        return (o > 0) - (o < 0);
    }
    i128 o = (i128)(bx - ax) * (cy - ay) - (i128)(by - ay) * (cx - ax);
    return (o > 0) - (o < 0);
}

/* Do a and b, whose bounding boxes overlap, cross at one point inside both
 * (neither end of either on the other)? */
static int cross_inside(const bedge *a, const bedge *b, int narrow)
{
    int s1 = orientation(a->xb, a->yb, a->xt, a->yt, b->xb, b->yb, narrow);
    int s2 = orientation(a->xb, a->yb, a->xt, a->yt, b->xt, b->yt, narrow);
    if (s1 * s2 >= 0)
        return 0;
    int s3 = orientation(b->xb, b->yb, b->xt, b->yt, a->xb, a->yb, narrow);
    int s4 = orientation(b->xb, b->yb, b->xt, b->yt, a->xt, a->yt, narrow);
    return s3 * s4 < 0;
}

static int add_split_point(engine *g, uint32_t e, int64_t x, int64_t y)
{
    GROW_SMALL(g->S, g->ns, g->caps, g->S_small, return 0);
    g->S[g->ns++] = (splitpt){e, x, y};
    return 1;
}

/* an edge's bounding box, y from yb to yt */
typedef struct edge_box { int64_t yb, yt, xlo, xhi; uint32_t e; } edge_box;

/* The split points of every crossing of two edges inside both, rounded, and
 * of every edge passing a horizontal edge at a point off the grid: those the
 * first sweep would find, so that the passes after it go as they would
 * (snapping to hot pixels only where rounding made a new crossing: snapping
 * at once would collapse slivers narrower than a unit that the exact
 * rounding keeps).  The edges are visited by their lowest y, so that the
 * pairs whose y ranges overlap come together. */
static int add_pair_splits(engine *g)
{
    const bedge *E = g->E;
    edge_box B[PAIRS_MAX_EDGES];
    size_t n = g->ne;
    int64_t xmin = INT64_MAX, xmax = INT64_MIN, ymin = INT64_MAX, ymax = INT64_MIN;
    for (size_t i = 0; i < n; i++) {
        const bedge *e = &E[i];
        int64_t xlo = e->xb < e->xt ? e->xb : e->xt, xhi = e->xb < e->xt ? e->xt : e->xb;
        xmin = xlo < xmin ? xlo : xmin;
        xmax = xhi > xmax ? xhi : xmax;
        ymin = e->yb < ymin ? e->yb : ymin;
        ymax = e->yt > ymax ? e->yt : ymax;
    }
    /* by yb, ties by number: (yb - ymin, number) packed in one key (the
     * spread of grid coordinates is below 2^42, n below 2^7) */
    uint64_t key[PAIRS_MAX_EDGES];
    for (size_t i = 0; i < n; i++) {
        uint64_t v = (uint64_t)(E[i].yb - ymin) << 7 | i;
        size_t k = i;
        for (; k > 0 && key[k - 1] > v; k--)
            key[k] = key[k - 1];
        key[k] = v;
    }
    for (size_t k = 0; k < n; k++) {
        const bedge *e = &E[key[k] & 127];
        B[k] = (edge_box){e->yb, e->yt, e->xb < e->xt ? e->xb : e->xt,
                          e->xb < e->xt ? e->xt : e->xb, (uint32_t)(key[k] & 127)};
    }
    int narrow = n && xmax - xmin < (INT64_C(1) << 31) && ymax - ymin < (INT64_C(1) << 31);
    for (size_t i = 0; i < n; i++) {
        /* (B[j].yb >= B[i].yb: the y ranges overlap while B[j].yb < B[i].yt) */
        for (size_t j = i + 1; j < n && B[j].yb < B[i].yt; j++) {
            if (B[j].xlo > B[i].xhi || B[i].xlo > B[j].xhi)
                continue;
            const bedge *a = &E[B[i].e], *b = &E[B[j].e];
            if (!cross_inside(a, b, narrow))
                continue;
            int64_t px, py;
            line_intersection(a->xb, a->yb, a->xt, a->yt, b->xb, b->yb, b->xt, b->yt, &px, &py);
            if (!add_split_point(g, B[i].e, px, py) || !add_split_point(g, B[j].e, px, py))
                return 0;
        }
    }
    for (size_t h = 0; h < g->nh; h++) {
        const hseg *H = &g->H[h];
        for (size_t i = 0; i < n && B[i].yb < H->y; i++) {
            const bedge *e = &E[B[i].e];
            int64_t x;
            if (H->y >= e->yt || B[i].xlo > H->x1 || B[i].xhi < H->x0 || x_is_integer(e, H->y, &x))
                continue;
            i128 num = x_num(e, H->y), d = x_den(e);
            if ((i128)H->x0 * d <= num && num <= (i128)H->x1 * d &&
                !add_split_point(g, B[i].e, x, H->y))
                return 0;
        }
    }
    return 1;
}

/* ---- assembly -------------------------------------------------------------- */

/* Clockwise angle from direction r to direction o, as an order key:
 * returns <0 when o1 comes before o2 turning clockwise from r. */
static int half_cw(i128 rx, i128 ry, i128 ox, i128 oy)
{
    i128 c = rx * oy - ry * ox, d = rx * ox + ry * oy;
    if (c < 0)
        return 0;
    if (c == 0 && d < 0)
        return 1;
    if (c > 0)
        return 2;
    return 3;
}

static int cw_before(i128 rx, i128 ry, const piece *a, const piece *b)
{
    i128 ax = a->x1 - a->x0, ay = a->y1 - a->y0, bx = b->x1 - b->x0, by = b->y1 - b->y0;
    int ha = half_cw(rx, ry, ax, ay), hb = half_cw(rx, ry, bx, by);
    if (ha != hb)
        return ha < hb;
    i128 c = ax * by - ay * bx;
    return c < 0; /* b is clockwise of a */
}

typedef struct ring_by_area { double area; size_t ring; } ring_by_area;
static int cmp_area(const void *a, const void *b)
{
    const ring_by_area *x = a, *y = b;
    if (x->area != y->area)
        return x->area < y->area ? -1 : 1;
    return (x->ring > y->ring) - (x->ring < y->ring);
}

typedef struct hole_point { int64_t x, y; size_t ring, parent; } hole_point;
static int cmp_hole_x(const void *a, const void *b)
{
    const hole_point *p = a, *q = b;
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    return (p->ring > q->ring) - (p->ring < q->ring);
}
static int cmp_hole_y(const void *a, const void *b)
{
    const hole_point *p = a, *q = b;
    if (p->y != q->y)
        return p->y < q->y ? -1 : 1;
    return (p->ring > q->ring) - (p->ring < q->ring);
}

/* first index of a (sorted by x, or by y) whose x (y) is >= v */
static size_t first_at_least(const hole_point *a, size_t n, int64_t v, int by_y)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if ((by_y ? a[mid].y : a[mid].x) < v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* a hash of a grid point in [0, 2^bits) */
static inline size_t point_hash(int64_t x, int64_t y, size_t bits)
{
    uint64_t h = (uint64_t)x * 0x9e3779b97f4a7c15u ^ (uint64_t)y * 0xc2b2ae3d27d4eb4fu;
    h ^= h >> 29;
    return (size_t)((h * 0xbf58476d1ce4e5b9u) >> (64 - bits));
}

/* The first of the pieces P[0..np) (sorted by start point, y then x)
 * starting at (vx, vy), np when none: a search that gallops from P[from]
 * and then halves. */
static size_t first_leaving(const piece *P, size_t np, size_t from, int64_t vx, int64_t vy)
{
#define BEFORE(i) (P[i].y0 < vy || (P[i].y0 == vy && P[i].x0 < vx))
    size_t lo, hi; /* the first not BEFORE is in [lo, hi] (hi == np: none) */
    if (BEFORE(from)) {
        size_t step = 1;
        lo = from + 1;
        hi = lo;
        while (hi < np && BEFORE(hi)) {
            lo = hi + 1;
            hi = step < np - hi ? hi + step : np;
            step *= 2;
        }
    } else {
        size_t step = 1;
        hi = from;
        lo = from;
        while (lo > 0 && !BEFORE(lo - 1)) {
            hi = lo - 1;
            lo = step < lo ? lo - step : 0;
            step *= 2;
        }
    }
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (BEFORE(mid))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < np && P[lo].x0 == vx && P[lo].y0 == vy ? lo : np;
#undef BEFORE
}

/* whether p is in the hash set h (2^bits entries: index + 1 into pts, 0
 * free) */
static int is_vertex(const uint32_t *h, size_t bits, const cg_point64 *pts, cg_point64 p)
{
    for (size_t i = point_hash(p.x, p.y, bits); h[i]; i = (i + 1) & (((size_t)1 << bits) - 1))
        if (pts[h[i] - 1].x == p.x && pts[h[i] - 1].y == p.y)
            return 1;
    return 0;
}

typedef struct ringbuf {
    cg_point64 *pts;
    size_t n, cap;
} ringbuf;

/* buf (cap bytes, or NULL) is the sweep's block, no longer needed: the
 * assembly's arrays are carved from it when they fit (no fresh pages). */
static int assemble(engine *g, cg_polygon_set64 *result, void *buf, size_t cap)
{
    size_t np = g->np;
    piece *P = g->P;
    if (np == 0)
        return 1;
    /* Every array of the assembly from one block sized from the piece
     * count (a ring takes each piece at most once and has 3 vertices or
     * more, so at most np points in all and np / 3 rings): one allocation
     * per call, which is most of the fixed cost on small inputs. */
    if (np > ((size_t)-1) / 256 || np >= UINT32_MAX)
        return 0;
    size_t mr = np / 3 + 1; /* rings at most */
    size_t bytes = 0, off[16], k = 0;
#define ASM_PART(n, size) (off[k++] = bytes, bytes += ((n) * (size) + 15) & ~(size_t)15)
    ASM_PART(np, sizeof(keyval));       /* 0: sort scratch */
    ASM_PART(np, sizeof(uint32_t));     /* 1: sort order */
    ASM_PART(np, sizeof(piece));        /* 2: sorted pieces */
    ASM_PART(np, 1);                    /* 3: used */
    ASM_PART(np, sizeof(keyval));       /* 4: sort temporary */
    ASM_PART(np, sizeof(cg_point64));   /* 5: ring points */
    ASM_PART(mr + 1, sizeof(size_t));   /* 6: ring starts */
    ASM_PART(mr, sizeof(double));       /* 7: area */
    ASM_PART(mr, 4 * sizeof(int64_t));  /* 8: bounding boxes */
    ASM_PART(mr, sizeof(size_t));       /* 9: parent */
    ASM_PART(mr, sizeof(size_t));       /* 10: outer rings */
    ASM_PART(mr, sizeof(ring_by_area)); /* 11: outers by area */
    ASM_PART(mr, sizeof(hole_point));   /* 12: hole points */
    ASM_PART(mr, sizeof(hole_point));   /* 13: candidates */
    ASM_PART(2 * (mr + 1), sizeof(size_t)); /* 14: first and next hole */
    /* the first piece leaving a point: by a hash of the point, or on many
     * pieces (where the lookups would miss the caches) by a search from the
     * piece that arrives there (a ring's next piece is usually close by in
     * the order) */
    int hashed = np < 32768;
    size_t hbits = 4;
    while (hashed && ((size_t)1 << hbits) < 2 * np)
        hbits++;
    ASM_PART(hashed ? (size_t)1 << hbits : 0, sizeof(uint32_t)); /* 15: start point -> first piece */
#undef ASM_PART
    char *own = bytes > cap || !buf ? malloc(bytes) : NULL, *mem = own ? own : buf;
    if (!mem)
        return 0;
    {
        keyval *scratch = (keyval *)(mem + off[0]);
        uint32_t *order = (uint32_t *)(mem + off[1]);
        piece *sorted = (piece *)(mem + off[2]);
        if (!sort_two_keys(&P[0].y0, &P[0].x0, sizeof(piece), np, order, scratch,
                           (keyval *)(mem + off[4]))) {
            free(own);
            return 0;
        }
        for (size_t i = 0; i < np; i++)
            sorted[i] = P[order[i]];
        memcpy(P, sorted, np * sizeof *P);
    }
    /* the first of the (sorted) pieces leaving each point, by a hash of the
     * point (open addressing; index + 1, 0 is free) */
    uint32_t *first = (uint32_t *)(mem + off[15]);
    size_t hmask = ((size_t)1 << hbits) - 1;
    if (hashed)
        memset(first, 0, (hmask + 1) * sizeof *first);
    for (size_t i = 0; i < np && hashed; i++) {
        if (i && P[i].x0 == P[i - 1].x0 && P[i].y0 == P[i - 1].y0)
            continue;
        size_t h = point_hash(P[i].x0, P[i].y0, hbits);
        while (first[h])
            h = (h + 1) & hmask;
        first[h] = (uint32_t)(i + 1);
    }
    unsigned char *used = (unsigned char *)(mem + off[3]);
    memset(used, 0, np);
    /* rings collected first: points and ring boundaries (in the block:
     * never grown, never freed on their own) */
    cg_polygon_set64 rings = {0};
    rings.points = (cg_point64 *)(mem + off[5]);
    rings.ring_start = (size_t *)(mem + off[6]);
    rings.ring_start[0] = 0;
    ringbuf rb = {NULL, 0, 0};
    int ok = 0;
    for (size_t start = 0; start < np; start++) {
        if (used[start])
            continue;
        /* walked in place, after the rings so far */
        rb.pts = rings.points + rings.point_count;
        rb.cap = np - rings.point_count;
        rb.n = 0;
        size_t cur = start;
        used[cur] = 1;
        for (;;) {
            if (rb.n == rb.cap)
                goto fail; /* (cannot happen: each piece is taken once) */
            rb.pts[rb.n++] = (cg_point64){P[cur].x0, P[cur].y0};
            int64_t vx = P[cur].x1, vy = P[cur].y1;
            /* outgoing pieces at v: the first of them */
            size_t lo = hashed ? np : first_leaving(P, np, cur, vx, vy);
            for (size_t h = point_hash(vx, vy, hbits); hashed && first[h]; h = (h + 1) & hmask) {
                size_t f = first[h] - 1;
                if (P[f].x0 == vx && P[f].y0 == vy) {
                    lo = f;
                    break;
                }
            }
            size_t best = (size_t)-1;
            i128 rx = P[cur].x0 - P[cur].x1, ry = P[cur].y0 - P[cur].y1;
            for (size_t k = lo; k < np && P[k].y0 == vy && P[k].x0 == vx; k++) {
                if (used[k] && k != start)
                    continue;
                if (best == (size_t)-1 || cw_before(rx, ry, &P[k], &P[best]))
                    best = k;
            }
            if (best == (size_t)-1 || best == start)
                break;
            cur = best;
            used[cur] = 1;
        }
        /* drop collinear vertices */
        size_t n = rb.n;
        int again = 1;
        while (again && n >= 3) {
            again = 0;
            size_t m = 0;
            for (size_t i = 0; i < n; i++) {
                cg_point64 a = m ? rb.pts[m - 1] : rb.pts[n - 1], b = rb.pts[i],
                           c = rb.pts[i + 1 < n ? i + 1 : 0];
                i128 cr = (i128)(b.x - a.x) * (c.y - b.y) - (i128)(b.y - a.y) * (c.x - b.x);
                if (cr == 0) {
                    again = 1;
                    continue;
                }
                rb.pts[m++] = b;
            }
            n = m;
        }
        if (n < 3)
            continue;
        if (rings.ring_count == mr)
            goto fail; /* (cannot happen, as above) */
        rings.point_count += n;
        rings.ring_start[++rings.ring_count] = rings.point_count;
    }
    /* classify and nest */
    {
        size_t nr = rings.ring_count;
        double *area = (double *)(mem + off[7]);
        int64_t(*bb)[4] = (int64_t(*)[4])(mem + off[8]);
        size_t *parent = (size_t *)(mem + off[9]);
        size_t *order = (size_t *)(mem + off[10]);
        size_t nouter = 0;
        for (size_t r = 0; r < nr; r++) {
            size_t a = rings.ring_start[r], b = rings.ring_start[r + 1];
            i128 s = 0;
            int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
            for (size_t i = a; i < b; i++) {
                cg_point64 p = rings.points[i], q = rings.points[i + 1 < b ? i + 1 : a];
                s += (i128)p.x * q.y - (i128)q.x * p.y;
                if (p.x < x0)
                    x0 = p.x;
                if (p.x > x1)
                    x1 = p.x;
                if (p.y < y0)
                    y0 = p.y;
                if (p.y > y1)
                    y1 = p.y;
            }
            area[r] = (double)s;
            bb[r][0] = x0;
            bb[r][1] = y0;
            bb[r][2] = x1;
            bb[r][3] = y1;
            parent[r] = (size_t)-1;
            if (s > 0)
                order[nouter++] = r;
        }
        /* Each hole goes to the smallest outer containing a point of one
         * of its edges that is on no other ring (below).  The outers are taken by increasing area; for each, the still unplaced
         * holes within its box are tested together: the outer's edges are
         * matched with the hole points sorted by y. */
        int fail_nest = 0;
        ring_by_area *ra = (ring_by_area *)(mem + off[11]);
        size_t nholes = nr - nouter;
        hole_point *hp = (hole_point *)(mem + off[12]);
        hole_point *cand = (hole_point *)(mem + off[13]);
        {
            for (size_t i = 0; i < nouter; i++)
                ra[i] = (ring_by_area){area[order[i]], order[i]};
            sort_few(ra, nouter, sizeof *ra, cmp_area);
            /* The point of a hole (in quadrupled coordinates): the midpoint
             * of one of its edges, or else a quarter point, that is not a
             * vertex of another ring (rings may touch there, after the
             * collinear vertex of the hole went away), so that it is on no
             * other ring. */
            uint32_t *verts = NULL; /* a hash set of the vertices, when first needed */
            size_t vbits = 4;
            size_t nv = rings.point_count;
            size_t h = 0;
            for (size_t r = 0; r < nr && !fail_nest; r++) {
                if (area[r] > 0)
                    continue;
                size_t a0 = rings.ring_start[r], a1 = rings.ring_start[r + 1];
                cg_point64 u0 = rings.points[a0], v0 = rings.points[a0 + 1];
                int64_t px = 2 * (u0.x + v0.x), py = 2 * (u0.y + v0.y);
                int found = 0;
                for (int quarter = 0; quarter < 2 && !found; quarter++) {
                    for (size_t i = a0; i < a1 && !found; i++) {
                        cg_point64 u = rings.points[i], v = rings.points[i + 1 < a1 ? i + 1 : a0];
                        int64_t qx = quarter ? 3 * u.x + v.x : 2 * (u.x + v.x);
                        int64_t qy = quarter ? 3 * u.y + v.y : 2 * (u.y + v.y);
                        cg_point64 m = {qx / 4, qy / 4};
                        if (!(qx & 3) && !(qy & 3) && !verts) {
                            while (((size_t)1 << vbits) < 2 * nv)
                                vbits++;
                            verts = calloc((size_t)1 << vbits, sizeof *verts);
                            if (!verts) {
                                fail_nest = 1;
                                break;
                            }
                            for (size_t v = 0; v < nv; v++) {
                                cg_point64 p = rings.points[v];
                                size_t h = point_hash(p.x, p.y, vbits);
                                while (verts[h])
                                    h = (h + 1) & (((size_t)1 << vbits) - 1);
                                verts[h] = (uint32_t)(v + 1);
                            }
                        }
                        if ((qx & 3) || (qy & 3) ||
                            !is_vertex(verts, vbits, rings.points, m)) {
                            px = qx;
                            py = qy;
                            found = 1;
                        }
                    }
                }
                hp[h++] = (hole_point){px, py, r, 0};
            }
            free(verts);
            if (fail_nest)
                nholes = 0;
            sort_few(hp, nholes, sizeof *hp, cmp_hole_x);
            size_t unplaced = nholes;
            for (size_t oi = 0; oi < nouter && unplaced; oi++) {
                size_t o = ra[oi].ring;
                int64_t bx0 = 4 * bb[o][0], by0 = 4 * bb[o][1], bx1 = 4 * bb[o][2], by1 = 4 * bb[o][3];
                /* candidates: holes with bx0 <= x <= bx1 (binary search), in y range */
                size_t lo = first_at_least(hp, nholes, bx0, 0);
                size_t nc = 0;
                for (size_t k = lo; k < nholes && hp[k].x <= bx1; k++)
                    if (hp[k].parent == 0 && hp[k].y >= by0 && hp[k].y <= by1) {
                        cand[nc] = hp[k];
                        cand[nc].parent = k; /* index back into hp */
                        nc++;
                    }
                if (!nc)
                    continue;
                sort_few(cand, nc, sizeof *cand, cmp_hole_y);
                unsigned char *in = calloc(nc, 1);
                if (!in) {
                    fail_nest = 1;
                    break;
                }
                size_t s0 = rings.ring_start[o], s1 = rings.ring_start[o + 1];
                for (size_t i = s0; i < s1; i++) {
                    cg_point64 u = rings.points[i], v = rings.points[i + 1 < s1 ? i + 1 : s0];
                    int64_t uy = 4 * u.y, vy = 4 * v.y;
                    if (uy == vy)
                        continue;
                    int64_t ylo = uy < vy ? uy : vy, yhi = uy < vy ? vy : uy;
                    /* candidates with ylo <= y < yhi */
                    size_t l = first_at_least(cand, nc, ylo, 1);
                    i128 ux = 4 * (i128)u.x, vx = 4 * (i128)v.x;
                    for (size_t k = l; k < nc && cand[k].y < yhi; k++) {
                        i128 mx = cand[k].x, my = cand[k].y;
                        i128 lhs = (mx - ux) * (vy - uy), rhs = (vx - ux) * (my - uy);
                        if (vy > uy ? lhs < rhs : lhs > rhs)
                            in[k] = !in[k];
                    }
                }
                for (size_t k = 0; k < nc; k++)
                    if (in[k]) {
                        hole_point *hpk = &hp[cand[k].parent];
                        hpk->parent = o + 1;
                        parent[hpk->ring] = o;
                        unplaced--;
                    }
                free(in);
            }
        }
        if (fail_nest)
            goto fail;
        /* output: each outer followed by its holes (a hole without an outer
         * cannot happen; it would be dropped) */
        size_t *first_hole = (size_t *)(mem + off[14]);
        size_t *next_hole = first_hole + (nr + 1);
        int fail = 0;
        {
            for (size_t r = 0; r < nr; r++)
                first_hole[r] = (size_t)-1;
            for (size_t r = nr; r-- > 0;) {
                if (parent[r] != (size_t)-1) {
                    next_hole[r] = first_hole[parent[r]];
                    first_hole[parent[r]] = r;
                }
            }
            for (size_t r = 0; r < nr && !fail; r++) {
                if (area[r] <= 0)
                    continue;
                size_t a = rings.ring_start[r];
                if (cg_polygon_set64_add_ring(result, rings.points + a,
                                              rings.ring_start[r + 1] - a, 1) != CG_OK) {
                    fail = 1;
                    break;
                }
                for (size_t h = first_hole[r]; h != (size_t)-1; h = next_hole[h]) {
                    size_t ha = rings.ring_start[h];
                    if (cg_polygon_set64_add_ring(result, rings.points + ha,
                                                  rings.ring_start[h + 1] - ha, 0) != CG_OK) {
                        fail = 1;
                        break;
                    }
                }
            }
        }
        if (fail)
            goto fail;
    }
    ok = 1;
fail:
    free(own);
    return ok;
}

#define MAX_PASSES 64
/* A pass that looked at this many active edges per edge (long active lists:
 * another whole pass would be dear) snaps to the pixels of the edges' ends
 * as well as of its rounded points, from then on: complete snap rounding
 * (Hobby), after which a verifying pass finds nothing to split (on dense
 * crossings the rounding otherwise makes new ones, pass after pass). */
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
 * edges went (apply_splits). */
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

/* order[0..n) by (k1, k2) of the edges (fields of bedge) */
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
        if (!sort_two_keys(top ? &P->yt : &P->yb, top ? &P->xt : &P->xb, sizeof(bedge), np, tmp,
                           s->scratch, s->scratch2))
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
        sorted = !ne || (sort_two_keys(&g->E[0].yb, &g->E[0].xb, sizeof(bedge), ne, s->by_bottom,
                                       scratch, tmp) &&
                         sort_two_keys(&g->E[0].yt, &g->E[0].xt, sizeof(bedge), ne, s->by_top,
                                       scratch, tmp));
    /* the scanlines: the two orders merged, each with its next distinct y
     * at hand (INT64_MAX past its end; no y reaches it) */
    const bedge *E = g->E;
    size_t u = 0, i = 0, j = 0, n = sorted && !from_last ? ne : 0;
    if (from_last) {
        /* the last pass's scanlines merged with its split points' y */
        while (i < c->nys || j < c->nsy) {
            int64_t y = j == c->nsy || (i < c->nys && c->ys[i] <= c->sy[j]) ? c->ys[i++] : c->sy[j++];
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
        sorted = sort_two_keys(&g->H[0].y, &g->H[0].x0, sizeof(hseg), g->nh, s->horder, scratch,
                               tmp);
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

/* Keeps the orders of this pass for the next one (before apply_splits). */
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

static cg_status boolean_run(engine *g, cg_polygon_set64 *result)
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
    int dense = 0; /* a pass split many edges: snap to every hot pixel */
    if (paired) {
        uint32_t map[PAIRS_MAX_EDGES];
        size_t kept;
        if (!add_pair_splits(g) || !apply_splits(g, map, &kept, s.mem, s.memcap))
            return CG_ENOMEM;
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
            int r = light_sweep(&s);
            if (!r)
                break;
            if (r == 1) {
                st = assemble(g, result, s.mem, s.memcap) ? CG_OK : CG_ENOMEM;
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
        if (can_resume && !light && nbands) {
            s.prev_map = c.map;
            s.prev_ne = c.n;
            s.prev_j = ck_load(&s, &logs[cur ^ 1], 0, bands[0][0]);
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
        int r = run_sweep(&s);
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
            st = assemble(g, result, s.mem, s.memcap) ? CG_OK : CG_ENOMEM;
            break;
        }
        if (s.visits >= DENSE_VISITS * edges)
            dense = 1;
        if ((pass >= 1 || dense) && !add_hot_pixel_splits(g, dense))
            break;
        free(bands);
        bands = NULL;
        nbands = 0;
        can_resume = 0;
        log->end_np = g->np;
        free(ranges);
        ranges = NULL;
        if (log->npt) { /* (else there is nothing to resume from) */
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
        if (!carry_keep(&c, &s) || !apply_splits(g, c.map, &c.kept, s.mem, s.memcap))
            break;
        c.valid = 1;
        if (g->ne > UINT32_MAX / 2) {
            st = CG_ERANGE; /* too many pieces for 32-bit edge numbers */
            break;
        }
    }
    if (s.mem != s.mem_small)
        free(s.mem);
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
                if (!add_piece(g, p.x, p.y, q.x, q.y, op, NO_ORIG))
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

cg_status cg_clip_boolean64(cg_clip_op op, const cg_polygon_set64 *subject,
                            cg_clip_fill subject_fill, const cg_polygon_set64 *clip,
                            cg_clip_fill clip_fill, cg_polygon_set64 *result)
{
    if (!result)
        return CG_EINVAL;
    cg_polygon_set64_clear(result);
    if ((unsigned)op > CG_CLIP_XOR || (unsigned)subject_fill > CG_CLIP_NEGATIVE ||
        (unsigned)clip_fill > CG_CLIP_NEGATIVE)
        return CG_EINVAL;
    engine g;
    memset(&g, 0, sizeof g);
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
        } else {
            g.E = malloc(g.cape * sizeof *g.E);
            if (!g.E)
                g.cape = 0;
        }
    }
    cg_status st = load(&g, subject, 0);
    if (st == CG_OK)
        st = load(&g, clip, 1);
    if (st == CG_OK && g.ne > UINT32_MAX / 4)
        st = CG_ERANGE;
    if (st == CG_OK)
        st = boolean_run(&g, result);
    if (st != CG_OK)
        cg_polygon_set64_clear(result);
    if (g.E != g.E_small)
        free(g.E);
    free(g.H);
    if (g.S != g.S_small)
        free(g.S);
    if (g.P != g.P_small)
        free(g.P);
    if (g.O != g.O_small)
        free(g.O);
    return st;
}

/* ---- the double API ------------------------------------------------------------ */

/* The grid of the double API: multiply by an explicit scale, or (automatic)
 * by 2^exponent with ldexp, which reaches every double's range exactly. */
typedef struct grid { double scale; int exponent; } grid;

static double max_abs(const cg_polygon_set *set)
{
    double m = 0;
    if (!set)
        return 0;
    for (size_t i = 0; i < set->point_count; i++) {
        double a = fabs(set->points[i].x), b = fabs(set->points[i].y);
        if (!isfinite(a) || !isfinite(b))
            return NAN;
        if (a > m)
            m = a;
        if (b > m)
            m = b;
    }
    return m;
}

static grid pick_grid(double scale, double largest)
{
    grid g = {scale > 0 ? scale : 0, 0};
    if (scale > 0 || !(largest > 0))
        return g;
    int e;
    frexp(largest, &e); /* largest < 2^e: 2^(36 - e) maps it below 2^36 */
    g.exponent = 36 - e;
    return g;
}

static double to_grid(grid g, double v) { return g.scale > 0 ? v * g.scale : ldexp(v, g.exponent); }
static double from_grid(grid g, int64_t v)
{
    return g.scale > 0 ? (double)v / g.scale : ldexp((double)v, -g.exponent);
}

static cg_status grid_points(const cg_polygon_set *in, grid g, cg_polygon_set64 *out)
{
    cg_polygon_set64_clear(out);
    if (!in)
        return CG_OK;
    for (size_t r = 0; r < in->ring_count; r++) {
        size_t a = in->ring_start[r], b = in->ring_start[r + 1];
        if (b < a || b > in->point_count)
            return CG_EINVAL;
        cg_status st = cg_polygon_set64_add_ring(out, NULL, 0, 1);
        if (st != CG_OK)
            return st;
        out->ring_count--; /* reopened below point by point */
        for (size_t i = a; i < b; i++) {
            double x = to_grid(g, in->points[i].x), y = to_grid(g, in->points[i].y);
            if (!isfinite(x) || !isfinite(y))
                return isfinite(in->points[i].x) && isfinite(in->points[i].y) ? CG_ERANGE
                                                                              : CG_EINVAL;
            if (fabs(x) > (double)CG_CLIP_MAX_COORD || fabs(y) > (double)CG_CLIP_MAX_COORD)
                return CG_ERANGE;
            cg_point64 p = {(int64_t)llround(x), (int64_t)llround(y)};
            if (out->point_count == out->point_capacity) {
                size_t cap = out->point_capacity ? out->point_capacity * 2 : 64;
                cg_point64 *q = realloc(out->points, cap * sizeof *q);
                if (!q)
                    return CG_ENOMEM;
                out->points = q;
                out->point_capacity = cap;
            }
            out->points[out->point_count++] = p;
        }
        out->ring_count++;
        out->ring_start[out->ring_count] = out->point_count;
    }
    return CG_OK;
}

static cg_status ungrid_points(const cg_polygon_set64 *in, grid g, cg_polygon_set *out)
{
    cg_polygon_set_clear(out);
    for (size_t p = 0; p < in->polygon_count; p++) {
        for (size_t r = in->polygon_start[p]; r < in->polygon_start[p + 1]; r++) {
            size_t a = in->ring_start[r], b = in->ring_start[r + 1];
            cg_status st = cg_polygon_set_add_ring(out, NULL, 0, r == in->polygon_start[p]);
            if (st != CG_OK)
                return st;
            out->ring_count--;
            for (size_t i = a; i < b; i++) {
                if (out->point_count == out->point_capacity) {
                    size_t cap = out->point_capacity ? out->point_capacity * 2 : 64;
                    cg_vec2 *q = realloc(out->points, cap * sizeof *q);
                    if (!q)
                        return CG_ENOMEM;
                    out->points = q;
                    out->point_capacity = cap;
                }
                out->points[out->point_count++] =
                    cg_vec2_make(from_grid(g, in->points[i].x), from_grid(g, in->points[i].y));
            }
            out->ring_count++;
            out->ring_start[out->ring_count] = out->point_count;
        }
    }
    return CG_OK;
}

cg_status cg_clip_boolean(cg_clip_op op, const cg_polygon_set *subject, cg_clip_fill subject_fill,
                          const cg_polygon_set *clip, cg_clip_fill clip_fill, double scale,
                          cg_polygon_set *result)
{
    if (!result)
        return CG_EINVAL;
    cg_polygon_set_clear(result);
    if (isnan(scale) || isinf(scale))
        return CG_EINVAL;
    double m1 = max_abs(subject), m2 = max_abs(clip);
    if (isnan(m1) || isnan(m2))
        return CG_EINVAL;
    grid g = pick_grid(scale, m1 > m2 ? m1 : m2);
    cg_polygon_set64 a = {0}, b = {0}, r = {0};
    cg_status st = grid_points(subject, g, &a);
    if (st == CG_OK)
        st = grid_points(clip, g, &b);
    if (st == CG_OK)
        st = cg_clip_boolean64(op, &a, subject_fill, &b, clip_fill, &r);
    if (st == CG_OK)
        st = ungrid_points(&r, g, result);
    if (st != CG_OK)
        cg_polygon_set_clear(result);
    cg_polygon_set64_clear(&a);
    cg_polygon_set64_clear(&b);
    cg_polygon_set64_clear(&r);
    return st;
}
