/* The light sweep of a pass of the boolean operations, the one expected to
 * find nothing to split: it visits only the points where edges start and
 * end, and checks each new pair of neighbours once. */
#include "boolean_scan.h"

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
            while (m > 0 && edges[starting[m - 1]].x_bottom == edges[e].x_bottom
                   && cmp_dir(&edges[starting[m - 1]], &edges[e]) > 0) {
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
            while (point_end < below_count
                   && cmp_xi(&edges[below[point_end]], y, X, x_at(&edges[below[point_end]], y))
                          == 0) {
                uint32_t e = below[point_end++];
                if (ends_at(&edges[e], y)) {
                    ended++;
                    if (s->run_open[e] && !boolean_close_run(s, e, y))
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
            if (!boolean_horizontal_meets(s, y, above, above_count, h0, next_horizontal, dirty,
                                          &dirty_count))
                return 0;
            if (s->changed)
                return LIGHT_BAIL;
            sort_u32(dirty, dirty_count);
            if (!boolean_horizontal_pieces(s, y, below, below_count, above, above_count, h0,
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
