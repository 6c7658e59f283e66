/* The engine of the boolean operations (boolean_*.c): its edges, pieces
 * and sweep state, the exact helpers its files share, and the step each
 * file does.  boolean.c describes the algorithm and runs the passes.
 *
 * The engine's words (every name below is made of them):
 *
 *   edge            a non-horizontal segment of an operand's ring, kept
 *                   from its bottom (lower y) to its top, with the winding
 *                   its path adds and its operand (subject 0, clip 1).
 *   horizontal      a horizontal edge: it adds no winding, only splits and
 *                   the result's horizontal boundary pieces come of it.
 *   input edge      the edge of the operands an edge is a part of after
 *                   splits; crossings are rounded on its line.
 *   split point     a grid point where an edge must get a vertex (a
 *                   crossing rounded, a touching point off the grid).
 *   part            one of the edges a split edge is replaced by.
 *   scanline        a y where an edge starts or ends; the sweep visits the
 *                   scanlines from bottom to top.
 *   scanbeam        the band between two consecutive scanlines: no edge
 *                   starts or ends inside it.
 *   active list     the edges crossing the current scanbeam, in order of
 *                   x (`below`: the last beam's, `above`: this one's).
 *   winding         the sum over the paths around a point (+1 a turn
 *                   counter-clockwise); each operand has its own, and the
 *                   windings right of an edge decide if it bounds the result.
 *   piece           a directed segment of the result's boundary (the result
 *                   on its left); pieces join into rings.
 *   run             the pieces of one edge over consecutive scanbeams,
 *                   emitted as one piece when it closes; it breaks where
 *                   something meets the edge.
 *   meet            a grid point where a run broke (no split was needed).
 *   dirty position  a place in the active list whose windings must be
 *                   looked at again (a new edge, a run break, a crossing).
 *   hot pixel       the unit square around a grid point that is a split
 *                   point or a vertex: snap rounding routes every edge that
 *                   meets it through its centre.
 *   pass            one sweep over all the edges: it splits what crosses,
 *                   or, when nothing does, classifies and emits the pieces.
 *   checkpoint      the whole sweep state at the start of a scanline, from
 *                   which the next pass resumes.
 *
 * In the code `g` is the engine and `s` the sweep of the current pass;
 * x and y are grid coordinates. */
#ifndef CG_CLIP_BOOLEAN_ENGINE_H
#define CG_CLIP_BOOLEAN_ENGINE_H

#include "../internal.h"
#include "../../core/array.h"
#include "../../core/invariant.h"

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

/* An edge of the sweep, bottom to top (y_bottom < y_top). */
typedef struct edge {
    int64_t x_bottom, y_bottom; /* its lower end */
    int64_t x_top, y_top;       /* its upper end */
    double slope;               /* dx / dy */
    uint32_t input_edge;        /* the input edge it is a part of (in the engine's
                                 * input_edges), or NO_ORIG: itself */
    int8_t winding;             /* winding added when crossed from left to right */
    uint8_t operand;            /* 0 subject, 1 clip */
} edge;
#define NO_ORIG UINT32_MAX

/* A horizontal edge at y, from x_left to x_right (x_left < x_right). */
typedef struct horizontal_edge {
    int64_t y, x_left, x_right;
} horizontal_edge;
/* A split point (x, y) of edge number `edge`. */
typedef struct split_point {
    uint32_t edge;
    int64_t x, y;
} split_point;
/* A piece of the result's boundary, directed from start to end. */
typedef struct piece {
    int64_t x_start, y_start, x_end, y_end;
} piece;

/* What one boolean operation works on: the edges of both operands (split
 * pass after pass), and what the passes find and emit. */
typedef struct engine {
    edge *edges; /* the edges of both operands */
    size_t edge_count, edge_capacity;
    horizontal_edge *horizontals; /* the horizontal edges */
    size_t horizontal_count, horizontal_capacity;
    split_point *splits; /* the split points this pass found */
    size_t split_count, split_capacity;
    piece *pieces; /* the result's boundary pieces */
    size_t piece_count, piece_capacity;
    /* the grid points where the first pass broke runs (edges meeting
     * there need no split), kept for complete snap rounding */
    cg_point64 *meets;
    size_t meet_count, meet_capacity;
    /* the input edges of parts (x_bottom, y_bottom, x_top, y_top):
     * input_edges_small or on the heap */
    int64_t (*input_edges)[4];
    size_t input_edge_count, input_edge_capacity;
    int64_t input_edges_small[16][4];
    /* the caller's buffers that edges, splits and pieces start in on small
     * inputs (then never freed; NULL when none) */
    edge *edges_small;
    split_point *splits_small;
    piece *pieces_small;
    cg_clip_op operation;
    cg_clip_fill fill[2];               /* the subject's and the clip's fill rule */
    cg_clip_workspace *workspace;       /* the blocks kept between calls, or NULL */
    unsigned char in_result[4];         /* in the result, by (in subject, in clip) */
    unsigned char in_result_near[5][5]; /* inside() for windings -2..2 */
} engine;

/* The blocks a workspace keeps from call to call: the sweep's block, the
 * edges and the pieces (each NULL while the call holds it) */
struct cg_clip_workspace {
    void *block; /* the sweep's block */
    size_t block_size;
    edge *edges; /* an edge array */
    size_t edge_capacity;
    piece *pieces; /* a piece array */
    size_t piece_capacity;
};

/* Room for `more` elements after the `count` of an engine array that may
 * still be in the caller's buffer `initial` (NULL when none): grown by the
 * one growth policy (core_array_reserve_from), checked inline first (the
 * callers are hot).  0 when out of memory, the array unchanged. */
static inline int boolean_room(void **data, size_t *capacity, size_t count, size_t more,
                               size_t element_size, const void *initial)
{
    return count + more <= *capacity
           || core_array_reserve_from(data, capacity, count, count + more, element_size, initial)
                  == CG_OK;
}

/* Room for more edges, horizontal edges, split points, meets. */
static inline int room_for_edges(engine *g, size_t more)
{
    return boolean_room((void **)&g->edges, &g->edge_capacity, g->edge_count, more,
                        sizeof *g->edges, g->edges_small);
}
static inline int room_for_horizontal(engine *g)
{
    return boolean_room((void **)&g->horizontals, &g->horizontal_capacity, g->horizontal_count, 1,
                        sizeof *g->horizontals, NULL);
}
static inline int room_for_split(engine *g)
{
    return boolean_room((void **)&g->splits, &g->split_capacity, g->split_count, 1,
                        sizeof *g->splits, g->splits_small);
}
static inline int room_for_meet(engine *g)
{
    return boolean_room((void **)&g->meets, &g->meet_capacity, g->meet_count, 1, sizeof *g->meets,
                        NULL);
}

/* Adds the edge (x0, y0)-(x1, y1) of operand op (0 subject, 1 clip) to g:
 * a horizontal one to g->horizontals, dropped when it is a point; orig as edge.orig.
 * 0 when out of memory. */
int boolean_add_edge(engine *g, int64_t x0, int64_t y0, int64_t x1, int64_t y1, int op,
                     uint32_t orig);

/* ---- exact helpers ------------------------------------------------------ */

/* floor(n / d + 1/2) for d > 0 */
static inline int64_t round_div(i128 n, i128 d)
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

/* the same in 64 bits */
static inline int64_t round_div64(int64_t n, int64_t d)
{
    int64_t q = n / d, r = n % d;
    if (r < 0) {
        q -= 1;
        r += d;
    }
    return q + (2 * r >= d);
}

/* x of edge e at scanline y as num / den, den > 0 */
static inline i128 x_num(const edge *e, int64_t y)
{
    return (i128)e->x_bottom * (e->y_top - e->y_bottom)
           + (i128)(y - e->y_bottom) * (e->x_top - e->x_bottom);
}

static inline int64_t x_den(const edge *e)
{
    return e->y_top - e->y_bottom;
}

static inline double x_at(const edge *e, int64_t y)
{
    if (y == e->y_bottom)
        return (double)e->x_bottom;
    if (y == e->y_top)
        return (double)e->x_top;
    return (double)e->x_bottom + (double)(y - e->y_bottom) * e->slope;
}

/* x of edge e at scanline y, rounded, in *x: whether it is exact.  In 64
 * bits when the offset along the edge fits (short edges, coarse grids),
 * else in 128. */
static inline int x_is_integer(const edge *e, int64_t y, int64_t *x)
{
    int64_t dy = y - e->y_bottom, dx = e->x_top - e->x_bottom, d = x_den(e), lim = (int64_t)1 << 30;
    if (dy < lim && dy > -lim && dx < lim && dx > -lim) { /* (|dy dx| < 2^60) */
        int64_t q = dy * dx, f = round_div64(q, d);
        *x = e->x_bottom + f;
        return f * d == q;
    }
    i128 n = x_num(e, y), dd = d;
    *x = round_div(n, dd);
    return (i128)*x * dd == n;
}

/* x of edge e at scanline y, rounded */
static inline int64_t x_rounded(const edge *e, int64_t y)
{
    int64_t x;
    x_is_integer(e, y, &x);
    return x;
}

/* Intersection of the lines a0-a1 and b0-b1 rounded to the grid; 0 when
 * parallel (boolean_scanline.c). */
int boolean_line_intersection(int64_t ax0, int64_t ay0, int64_t ax1, int64_t ay1, int64_t bx0,
                              int64_t by0, int64_t bx1, int64_t by1, int64_t *px, int64_t *py);

/* ---- in the result: fill rules and the operation -------------------------- */

static inline int fill_in(cg_clip_fill f, int64_t w)
{
    switch (f) {
    case CG_CLIP_EVEN_ODD: return (int)(w & 1);
    case CG_CLIP_NON_ZERO: return w != 0;
    case CG_CLIP_POSITIVE: return w > 0;
    default: return w < 0;
    }
}

static inline int inside_rule(const engine *g, int64_t wa, int64_t wb)
{
    return g->in_result[(fill_in(g->fill[0], wa) << 1) | fill_in(g->fill[1], wb)];
}

/* whether a point with windings wa (subject) and wb (clip) is in the result */
static inline int inside(const engine *g, int64_t wa, int64_t wb)
{
    if ((uint64_t)(wa + 2) < 5 && (uint64_t)(wb + 2) < 5)
        return g->in_result_near[wa + 2][wb + 2];
    return inside_rule(g, wa, wb);
}

/* ---- sorting (boolean_sort.c) ----------------------------------------- */

typedef struct keyval {
    uint64_t key;
    uint32_t val;
} keyval;

/* idx[0..n) = 0..n-1 ordered by (k1, k2), ties by index: k1 and k2 point at
 * int64_t fields of record 0, records are `stride` bytes apart; scratch
 * holds n keyvals, tmp n or is NULL.  0 when out of memory. */
int boolean_sort_two_keys(const int64_t *k1, const int64_t *k2, size_t stride, size_t n,
                          uint32_t *idx, keyval *scratch, keyval *tmp);
/* qsort, by straight insertion when n is small */
void boolean_sort_few(void *base, size_t n, size_t size, int (*cmp)(const void *, const void *));

/* ---- the sweep's state ---------------------------------------------------- */

typedef struct sweep {
    engine *engine;
    int64_t *scanlines; /* the distinct y of the edges' ends, in order */
    size_t scanline_count;
    uint32_t *by_bottom;            /* edge numbers sorted by (y_bottom, x_bottom) */
    uint32_t *by_top;               /* edge numbers sorted by (y_top, x_top) */
    uint32_t *active, *next_active; /* the active list below the scanline, and the
                                     * room for the one above it */
    uint32_t *starting;             /* the edges starting at this scanline, by x */
    uint32_t *dirty;                /* dirty positions in the active list */
    /* the light sweep's: the edges through one point; where new
     * neighbours meet */
    uint32_t *point_edges, *seams;
    keyval *sort_scratch, *sort_tmp; /* for sorting */
    horizontal_edge *horizontals_sorted;
    uint32_t *horizontal_order;
    void *block; /* all of the above, carved from one block */
    size_t block_size;
    void *block_small; /* the caller's block `block` starts as (never freed) */
    /* the windings right of each edge (its coincident group), per operand:
     * sums of at most edge_count <= INT32_MAX terms of +-1 */
    int32_t *winding_subject, *winding_clip;
    size_t active_count;
    double *x_current, *x_next; /* x at the current scanline, at the next one */
    /* each edge's run: open or not, going up (the result on its left) or
     * down, its start, and whether it breaks at this scanline, the next */
    unsigned char *run_open, *run_up;
    unsigned char *run_break, *run_break_next;
    int64_t *run_x, *run_y;
    int classify;  /* the pass classifies and emits pieces */
    int changed;   /* the pass found split points */
    size_t visits; /* active edges summed over the scanlines (full sweep) */
    /* the edges of run_break, of run_break_next (full sweep); when full,
     * every position is looked at */
    uint32_t *break_queue, *break_queue_next;
    size_t break_queue_count, break_queue_capacity;
    int break_queue_full;
    int use_input_lines;      /* round on the input edges (early passes) */
    int record_meets;         /* note the grid points where runs break (g->meets) */
    struct ck_log *log;       /* checkpoints of this pass, or NULL */
    size_t checkpoint_visits; /* the next checkpoint once visits reach this */
    /* where the sweep starts (resumed): its scanline, and the next edges
     * of by_bottom and by_top */
    size_t start_scanline, start_bottom, start_top;
    int64_t y_span; /* from the first scanline to the last */
    /* the hand-over to the last pass's results (boolean_ck_same) */
    const struct ck_log *prev_log; /* or NULL */
    const uint32_t *prev_map;      /* its edge numbers to ours */
    size_t prev_edge_count;        /* its edges */
    size_t prev_checkpoint;        /* its next checkpoint to compare */
    const int64_t (*bands)[2];     /* the y ranges of the edges it split, merged */
    size_t band_count, band;       /* how many; the next one */
    size_t (*taken_ranges)[2];     /* the ranges of its pieces taken */
    size_t taken_count;
} sweep;

/* ---- a pass's arrays and orders (boolean_prepare.c) ---------------------- */

/* What a pass leaves to the next: its orders of the edges and where its
 * edges went (boolean_apply_splits). */
typedef struct carry {
    uint32_t *by_bottom, *by_top, *map;
    uint32_t *block_small;       /* the caller's block of 3 * 64 they start in */
    size_t edge_count, capacity; /* edges of the last pass (room for cap) */
    size_t kept;                 /* of them, not split: now g->edges[0..kept) */
    size_t horizontals_sorted;   /* g->horizontals[0..horizontals_sorted) is in order */
    int valid;
    /* the last pass's scanlines and the distinct y of its split points
     * (sorted), when they were few: the next pass's scanlines are the two
     * merged (a split edge's pieces form a path from its bottom to its top,
     * so every scanline stays one, and each split point's y becomes one) */
    int64_t *scanlines, *split_ys;
    size_t scanline_count, split_y_count, scanline_capacity, split_y_capacity;
    int scanlines_valid;
} carry;

/* Forgets the arrays of the last pass; their memory is kept for the next. */
void boolean_sweep_reset(sweep *s);
/* The arrays of a pass over the engine's edges (the light sweep's too when
 * `light`), carved from the sweep's block: 0 when out of memory. */
int boolean_sweep_alloc(sweep *s, int light);
/* Sorts the edges by bottom and by top (from the last pass's orders in c
 * when there are some), the scanlines and the horizontal edges: 0 when out
 * of memory. */
int boolean_sweep_sort(sweep *s, carry *c);
/* Keeps the orders of this pass in c for the next one (before
 * boolean_apply_splits): 0 when out of memory. */
int boolean_carry_keep(carry *c, const sweep *s);

/* ---- checkpoints (boolean_checkpoint.c) ------------------------------------ */

/* Checkpoints.  A full pass that splits edges is repeated, but below the
 * lowest split edge the next pass would see exactly the same edges, events
 * and classification.  So while a pass still classifies, it notes from time
 * to time its whole state at the start of a scanline (the active edges in
 * order, with their x there, windings, open runs and run breaks, and how
 * many pieces were emitted); the next pass starts at the last such scanline
 * at or below every split edge, with that state, and keeps the pieces
 * emitted below it. */
/* an active edge at a checkpoint */
typedef struct ck_edge {
    uint32_t edge;                         /* its number in that pass */
    unsigned flags;                        /* 1 run break here, 2 run open, 4 run goes up */
    int32_t winding_subject, winding_clip; /* the windings right of it */
    double x_at_scanline;                  /* its x at the checkpoint's scanline */
    int64_t run_x, run_y;                  /* where its open run started */
} ck_edge;
/* a checkpoint: its scanline, the pieces emitted by then, and its active
 * edges, ck_log.edges[first_edge..first_edge + edge_count) */
typedef struct ck_point {
    int64_t scanline_y;
    size_t piece_count, first_edge, edge_count;
} ck_point;
/* the checkpoints of a pass */
typedef struct ck_log {
    ck_point *checkpoints;
    size_t checkpoint_count, checkpoint_capacity;
    ck_edge *edges; /* the active edges of all of them */
    size_t edge_count, edge_capacity;
    size_t budget;          /* most edge records kept */
    size_t end_piece_count; /* pieces at the end of the pass */
} ck_log;

/* ---- the steps -------------------------------------------------------- */

/* The full sweep of a pass (boolean_sweep.c): splits what crosses, or, when
 * nothing needs a split, classifies and emits the pieces.  1 when done, 0
 * when out of memory, -1 when the active list was out of order (a bug: the
 * caller gives CG_ERANGE rather than a wrong result). */
int boolean_run_sweep(sweep *s);

#define LIGHT_BAIL 2
/* The light sweep of a pass expected to find nothing to split
 * (boolean_light.c): 1 when final, LIGHT_BAIL when something needs a split,
 * 0 when out of memory. */
int boolean_light_sweep(sweep *s);

/* Checkpoints (boolean_checkpoint.c): notes the state at the start of
 * scanline y; compares this pass's state with the last pass's checkpoint c;
 * takes the state of the last checkpoint at or below y (its index + 1, or 0). */
int boolean_ck_record(sweep *s, int64_t y);
int boolean_ck_same(const sweep *s, const ck_point *c);
size_t boolean_ck_load(sweep *s, const ck_log *L, size_t j0, int64_t y);

/* Splits (boolean_split.c): snap rounding to the hot pixels of the split
 * points (complete when `vertices`: of boolean_complete_hot_points, the
 * split points replaced by the snapping's); every split edge replaced by
 * its pieces (map[old edge]: its new index, or UINT32_MAX when split). */
int boolean_add_hot_pixel_splits(engine *g, int vertices);
int boolean_apply_splits(engine *g, uint32_t *map, size_t *kept, void *mem, size_t cap);

/* a point of an edge; t orders it along the edge */
typedef struct split_sort {
    int64_t x, y;
    i128 along;
} split_sort;

static inline int before_along(const split_sort *p, const split_sort *q)
{
    if (p->along != q->along)
        return p->along < q->along;
    if (p->y != q->y)
        return p->y < q->y;
    return p->x < q->x;
}

/* Does the segment a-b meet the "hot pixel" of the grid point p?  Exact,
 * on doubled coordinates.  Two kinds of pixel:
 * - half_open: the points that round to p, [px - 1/2, px + 1/2) x
 *   [py - 1/2, py + 1/2) (y up, as on the grid):
 *
 *       py + 1/2  o - - - - - - o   top side: out (rounds to py + 1)
 *                 |             :
 *                 |             :
 *                 |      + p    :   right side: out (rounds to px + 1)
 *                 |             :
 *                 |             :
 *       py - 1/2  *-------------o   left and bottom sides: in
 *             px - 1/2       px + 1/2
 *
 *   (* the one corner that is in, o the three that are out).  These tile
 *   the plane, so an edge meets its hot pixels one after the other, in
 *   the order of their centres along it, and snapping to them cannot make
 *   two edges cross (Hobby's theorem).
 *   Touching at a shared corner of four pixels, closed ones would let two
 *   edges take their centres in crossing orders.
 * - else the open square: the edge passes through its inside (what the
 *   iterated snap rounding uses; its verifying passes settle the rest). */
static inline int boolean_meets_pixel(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px,
                                      int64_t py, int half_open)
{
    /* (coordinates are within 2^40 + 1: doubled, they fit 64 bits) */
    int64_t x0 = 2 * px - 1, x1 = 2 * px + 1, y0 = 2 * py - 1, y1 = 2 * py + 1;
    int64_t Ax = 2 * ax, Ay = 2 * ay, Bx = 2 * bx, By = 2 * by;
    if ((Ax < x0 && Bx < x0) || (Ax > x1 && Bx > x1) || (Ay < y0 && By < y0)
        || (Ay > y1 && By > y1))
        return 0;
    /* (the half-open pixel leaves out its right and top sides) */
    if (half_open && ((Ax >= x1 && Bx >= x1) || (Ay >= y1 && By >= y1)))
        return 0;
    /* the line through a and b meets the square only if the centre is
     * within half the square's width across the line, |d x (p - a)| <=
     * (|dx| + |dy|) / 2: in doubles first, with a wide margin for rounding */
    double dx = (double)(bx - ax), dy = (double)(by - ay);
    double u = dy * (double)(px - ax), v = dx * (double)(py - ay);
    if (fabs(u - v) > 0.5 * (fabs(dx) + fabs(dy)) + 1e-9 * (fabs(u) + fabs(v)) + 1)
        return 0;
    /* the square's corners on either side of the line: 64-bit products when
     * every difference is below 2^30 */
    int64_t cx[4] = {x0, x1, x1, x0}, cy[4] = {y0, y0, y1, y1};
    int64_t ex = Bx - Ax, ey = By - Ay, far = (int64_t)1 << 30;
    int narrow = ex < far && ex > -far && ey < far && ey > -far && x1 - Ax < far && Ax - x0 < far
                 && y1 - Ay < far && Ay - y0 < far;
    /* the half-open pixel as the closed one moved by (-d, -d), d tending to
     * 0: a corner on the line moves to the side of sign(ey - ex) (the
     * other corners, an integer from it, stay where they are) */
    int tie = half_open ? (ey > ex) - (ey < ex) : 0;
    int pos = 0, neg = 0;
    for (int k = 0; k < 4; k++) {
        int side;
        if (narrow) {
            int64_t o = ex * (cy[k] - Ay) - ey * (cx[k] - Ax);
            side = (o > 0) - (o < 0);
        } else {
            i128 o = (i128)ex * (cy[k] - Ay) - (i128)ey * (cx[k] - Ax);
            side = (o > 0) - (o < 0);
        }
        if (!side)
            side = tie;
        pos += side > 0;
        neg += side < 0;
    }
    if (half_open) /* (met unless every corner is strictly on one side) */
        return pos < 4 && neg < 4;
    return pos && neg;
}

/* The hot points of complete snap rounding: the split points, the edges'
 * ends (horizontal ones too) and the grid points where the sweep broke runs
 * (g->meets).  How many, repeats counted; and add(ctx, x, y) for each of them,
 * 0 when an add gave 0 (inlined with a constant add, at no cost). */
static inline size_t boolean_hot_point_count(const engine *g)
{
    return g->split_count + 2 * (g->edge_count + g->horizontal_count) + g->meet_count;
}

static inline int boolean_each_hot_point(const engine *g, int (*add)(void *, int64_t, int64_t),
                                         void *ctx)
{
    int ok = 1;
    for (size_t k = 0; k < g->split_count; k++)
        ok &= add(ctx, g->splits[k].x, g->splits[k].y);
    for (size_t i = 0; i < g->edge_count; i++)
        ok &= add(ctx, g->edges[i].x_bottom, g->edges[i].y_bottom)
              & add(ctx, g->edges[i].x_top, g->edges[i].y_top);
    for (size_t i = 0; i < g->horizontal_count; i++)
        ok &= add(ctx, g->horizontals[i].x_left, g->horizontals[i].y)
              & add(ctx, g->horizontals[i].x_right, g->horizontals[i].y);
    for (size_t i = 0; i < g->meet_count; i++)
        ok &= add(ctx, g->meets[i].x, g->meets[i].y);
    return ok;
}

/* the helpers of the splits, shared with complete snap rounding: a[0..n) in
 * order along their edge; the hot points above in an array (NULL when out
 * of memory); the input
 * edge e's pieces take (e itself noted when it is one; NO_ORIG when out of
 * memory); the edges g->edges[0..old_ne) marked dead dropped, the rest moved
 * down with the pieces after them (map[old edge]: its new index or
 * UINT32_MAX; the number kept returned) */
void boolean_sort_along(split_sort *a, size_t n);
split_point *boolean_complete_hot_points(const engine *g, size_t *n);
uint32_t boolean_orig_of(engine *g, const edge *e);
size_t boolean_drop_split_edges(engine *g, size_t old_ne, const unsigned char *dead, uint32_t *map);

/* Complete snap rounding (boolean_snap.c), in place of the hot pixels'
 * splits and their application (same map and kept): every edge routed
 * through each hot pixel of boolean_each_hot_point it meets.  When the
 * edges are short in grid units (a coarse grid, where many pieces then
 * coincide), the pieces of one operand with the same ends are made one,
 * their windings added (dropped when these cancel).  0 when out of memory. */
int boolean_snap_complete(engine *g, uint32_t *map, size_t *kept, void *mem, size_t cap);

#define PAIRS_MAX_EDGES 112 /* (below 128: an edge number fits in 7 bits) */
/* The crossings of a small input found pair by pair, as split points
 * (boolean_pairs.c); 0 when out of memory. */
int boolean_add_pair_splits(engine *g);

/* The pieces of the final pass linked into rings, holes under their outer
 * rings (boolean_assemble.c); *buf (*cap bytes) is scratch, replaced by a
 * larger block when needed unless it is `fixed`.  0 when out of memory. */
int boolean_assemble(engine *g, cg_polygon_set64 *result, void **buf, size_t *cap,
                     const void *fixed);
/* A ring cut at the points it passes twice into loops that pass each point
 * once, written back over pts, loop k ending at (*ends)[k] (allocated; free
 * it); at[0..branches) the indices of its points with several ways out,
 * when there are at most PINCH_FEW (boolean_pinch.c); 0 when out of memory. */
#define PINCH_FEW 32
int boolean_split_pinches(cg_point64 *pts, size_t n, const size_t *at, size_t branches,
                          size_t **ends, size_t *count);

#endif
