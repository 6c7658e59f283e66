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
static int cross_inside(const edge *a, const edge *b, int narrow)
{
    int s1 = orientation(a->x_bottom, a->y_bottom, a->x_top, a->y_top, b->x_bottom, b->y_bottom,
                         narrow);
    int s2 = orientation(a->x_bottom, a->y_bottom, a->x_top, a->y_top, b->x_top, b->y_top, narrow);
    if (s1 * s2 >= 0)
        return 0;
    int s3 = orientation(b->x_bottom, b->y_bottom, b->x_top, b->y_top, a->x_bottom, a->y_bottom,
                         narrow);
    int s4 = orientation(b->x_bottom, b->y_bottom, b->x_top, b->y_top, a->x_top, a->y_top, narrow);
    return s3 * s4 < 0;
}

static int add_split_point(engine *g, uint32_t e, int64_t x, int64_t y)
{
    if (!room_for_split(g))
        return 0;
    g->splits[g->split_count++] = (split_point){e, x, y};
    return 1;
}

/* an edge's bounding box, y from y_bottom to y_top */
typedef struct edge_box {
    int64_t y_bottom, y_top, x_low, x_high;
    uint32_t edge;
} edge_box;

/* The split points of every crossing of two edges inside both, rounded, and
 * of every edge passing a horizontal edge at a point off the grid: those the
 * first sweep would find, so that the passes after it go as they would
 * (snapping to hot pixels only where rounding made a new crossing: snapping
 * at once would collapse slivers narrower than a unit that the exact
 * rounding keeps).  The edges are visited by their lowest y, so that the
 * pairs whose y ranges overlap come together. */
int boolean_add_pair_splits(engine *g)
{
    const edge *edges = g->edges;
    edge_box boxes[PAIRS_MAX_EDGES];
    size_t n = g->edge_count;
    int64_t xmin = INT64_MAX, xmax = INT64_MIN, ymin = INT64_MAX, ymax = INT64_MIN;
    for (size_t i = 0; i < n; i++) {
        const edge *e = &edges[i];
        int64_t xlo = e->x_bottom < e->x_top ? e->x_bottom : e->x_top,
                xhi = e->x_bottom < e->x_top ? e->x_top : e->x_bottom;
        xmin = xlo < xmin ? xlo : xmin;
        xmax = xhi > xmax ? xhi : xmax;
        ymin = e->y_bottom < ymin ? e->y_bottom : ymin;
        ymax = e->y_top > ymax ? e->y_top : ymax;
    }
    /* by y_bottom, ties by number: (y_bottom - ymin, number) packed in one key (the
     * spread of grid coordinates is below 2^42, n below 2^7) */
    uint64_t key[PAIRS_MAX_EDGES];
    for (size_t i = 0; i < n; i++) {
        uint64_t v = (uint64_t)(edges[i].y_bottom - ymin) << 7 | i;
        size_t k = i;
        for (; k > 0 && key[k - 1] > v; k--)
            key[k] = key[k - 1];
        key[k] = v;
    }
    for (size_t k = 0; k < n; k++) {
        const edge *e = &edges[key[k] & 127];
        boxes[k] = (edge_box){
            e->y_bottom, e->y_top, e->x_bottom < e->x_top ? e->x_bottom : e->x_top,
            e->x_bottom < e->x_top ? e->x_top : e->x_bottom, (uint32_t)(key[k] & 127)};
    }
    int narrow = n && xmax - xmin < (INT64_C(1) << 31) && ymax - ymin < (INT64_C(1) << 31);
    for (size_t i = 0; i < n; i++) {
        /* (B[j].y_bottom >= B[i].y_bottom: the y ranges overlap while B[j].y_bottom < B[i].y_top) */
        for (size_t j = i + 1; j < n && boxes[j].y_bottom < boxes[i].y_top; j++) {
            if (boxes[j].x_low > boxes[i].x_high || boxes[i].x_low > boxes[j].x_high)
                continue;
            const edge *a = &edges[boxes[i].edge], *b = &edges[boxes[j].edge];
            if (!cross_inside(a, b, narrow))
                continue;
            int64_t px, py;
            boolean_line_intersection(a->x_bottom, a->y_bottom, a->x_top, a->y_top, b->x_bottom,
                                      b->y_bottom, b->x_top, b->y_top, &px, &py);
            if (!add_split_point(g, boxes[i].edge, px, py)
                || !add_split_point(g, boxes[j].edge, px, py))
                return 0;
        }
    }
    for (size_t h = 0; h < g->horizontal_count; h++) {
        const horizontal_edge *horizontal = &g->horizontals[h];
        for (size_t i = 0; i < n && boxes[i].y_bottom < horizontal->y; i++) {
            const edge *e = &edges[boxes[i].edge];
            int64_t x;
            if (horizontal->y >= e->y_top || boxes[i].x_low > horizontal->x_right
                || boxes[i].x_high < horizontal->x_left || x_is_integer(e, horizontal->y, &x))
                continue;
            i128 num = x_num(e, horizontal->y), d = x_den(e);
            if ((i128)horizontal->x_left * d <= num && num <= (i128)horizontal->x_right * d
                && !add_split_point(g, boxes[i].edge, x, horizontal->y))
                return 0;
        }
    }
    return 1;
}
