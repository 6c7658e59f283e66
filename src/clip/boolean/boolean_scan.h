/* What the two sweeps of the boolean operations share (boolean_sweep.c,
 * boolean_light.c): the exact comparisons of edges on a scanline, the
 * lookups in the active list, the classification of a beam, and the steps
 * on a scanline that are out of line (boolean_scanline.c). */
#ifndef CG_CLIP_BOOLEAN_SCAN_H
#define CG_CLIP_BOOLEAN_SCAN_H

#include "boolean_engine.h"

/* ---- steps on a scanline (boolean_scanline.c) -------------------------- */

/* Split point (x, y) for edge e: the pass will be repeated.  0 when out of
 * memory. */
int boolean_add_split(sweep *s, uint32_t e, int64_t x, int64_t y);
/* Passing edge e meets something at scanline y (the current one, or the
 * next when `next`): its run breaks there when that is a grid point, else
 * it gets a split point there.  0 when out of memory. */
int boolean_meet(sweep *s, uint32_t e, int64_t y, int next);
/* Edge e's open run closed at y, emitted as a piece: 0 when out of memory. */
int boolean_close_run(sweep *s, uint32_t e, int64_t y);
/* The horizontal boundary pieces on scanline y, between below[] and
 * above[], under the horizontal edges [h0, h1): 0 when out of memory. */
int boolean_horizontal_pieces(sweep *s, int64_t y, const uint32_t *below, size_t below_count,
                              const uint32_t *above, size_t above_count, size_t h0, size_t h1);
/* The passing edges of above[] through the horizontal edges [h0, h1) at y
 * meet them; their positions added to dirty[].  0 when out of memory. */
int boolean_horizontal_meets(sweep *s, int64_t y, const uint32_t *above, size_t above_count,
                             size_t h0, size_t h1, uint32_t *dirty, size_t *dirty_count);
/* Edges u and v meet at one point of the next scanline y_next: 0 when out
 * of memory. */
int boolean_meet_at_next(sweep *s, uint32_t u, uint32_t v, int64_t y_next);

/* ---- exact comparisons and lookups ------------------------------------- */

/* whether edge e ends at scanline y */
static inline int ends_at(const edge *e, int64_t y)
{
    return e->y_top == y;
}

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

static inline void sort_u32(uint32_t *a, size_t n)
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
static inline size_t first_at_x(const edge *edges, const uint32_t *list, size_t lo, size_t hi,
                                int64_t y, int64_t X, const double *x_current)
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
    int64_t X = *ending_at >= next_end
                        || (*starting_at < starting_count
                            && edges[starting[*starting_at]].x_bottom
                                   <= edges[top[*ending_at]].x_top)
                    ? edges[starting[*starting_at]].x_bottom
                    : edges[top[*ending_at]].x_top;
    *f0 = *starting_at;
    while (*starting_at < starting_count && edges[starting[*starting_at]].x_bottom == X)
        (*starting_at)++;
    while (*ending_at < next_end && edges[top[*ending_at]].x_top == X)
        (*ending_at)++;
    return X;
}

/* a and b (both active in a beam, not crossing inside it) coincide there:
 * they are on one line */
static inline int coincident(const edge *a, const edge *b)
{
    if (a->slope != b->slope) /* dx / dy rounded once: equal when collinear */
        return 0;
    i128 dx = a->x_top - a->x_bottom, dy = a->y_top - a->y_bottom;
    return dx * (b->y_bottom - a->y_bottom) == dy * (b->x_bottom - a->x_bottom)
           && dx * (b->y_top - a->y_bottom) == dy * (b->x_top - a->x_bottom);
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
                if (!boolean_close_run(s, e, y))
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

#endif
