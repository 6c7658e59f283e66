/* Crossings of small inputs found pair by pair, before the first sweep. */
#include "boolean_engine.h"

/* On few edges, testing every pair for a crossing costs less than a sweep
 * that only looks for them.  The crossings found are rounded as the first
 * sweep rounds them and the edges split before it, so that it normally
 * finds nothing more to split and classifies at once.  It still verifies:
 * a crossing made by the rounding is split by further passes as usual. */

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
int boolean_add_pair_splits(engine *g)
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
            boolean_line_intersection(a->xb, a->yb, a->xt, a->yt, b->xb, b->yb, b->xt, b->yt, &px,
                                      &py);
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
