/* Aliased scan-line polygon fill (section 10.2): an edge table sorted by
 * first scan-line, an active edge list kept sorted by crossing, spans
 * between crossings painted under the even-odd or non-zero rule.
 *
 * Sampling is at pixel centres.  An edge is active on the scan-lines whose
 * centre y satisfies top <= y < bottom (so horizontal edges never are, and a
 * vertex on a scan-line is counted once), and a pixel belongs to the span
 * starting at a crossing when its centre x >= the crossing.  Each edge's
 * crossing is computed directly from its endpoints (ordered top to bottom),
 * so two polygons sharing an edge compute the same crossing bit for bit and
 * split the pixels on it between them without overlap or gap. */
#include "internal.h"
#include "../core/sort.h"

#include <stdlib.h>
#include <string.h>

cg_status cg_rasterizer_create(cg_rasterizer **out)
{
    if (!out)
        return CG_EINVAL;
    *out = calloc(1, sizeof **out);
    if (!*out)
        return CG_ENOMEM;
    (*out)->tolerance = 0.1;
    return CG_OK;
}

void cg_rasterizer_free(cg_rasterizer *r)
{
    if (!r)
        return;
    free(r->lines);
    free(r->accumulation);
    free(r->cover);
    free(r->touched);
    free(r->order);
    free(r->active);
    free(r->edges);
    free(r->crossings);
    fill_polylines_free(&r->flat);
    fill_polylines_free(&r->outline);
    free(r);
}

cg_status cg_rasterizer_set_tolerance(cg_rasterizer *r, double tolerance)
{
    if (!r || !(tolerance >= 0.001 && tolerance <= 100))
        return CG_EINVAL;
    r->tolerance = tolerance;
    return CG_OK;
}

cg_status fill_check_polygon(const cg_vec2 *points, const int *contour_sizes, int contour_count,
                             size_t *total)
{
    *total = 0;
    if (contour_count < 0 || (contour_count > 0 && !contour_sizes))
        return CG_EINVAL;
    size_t n = 0;
    for (int i = 0; i < contour_count; i++) {
        if (contour_sizes[i] < 0)
            return CG_EINVAL;
        n += (size_t)contour_sizes[i];
    }
    if (n > 0 && !points)
        return CG_EINVAL;
    for (size_t i = 0; i < n; i++)
        if (!(fabs(points[i].x) <= CG_FILL_MAX_COORD && fabs(points[i].y) <= CG_FILL_MAX_COORD))
            return CG_EINVAL; /* also NaN */
    *total = n;
    return CG_OK;
}

static int compare_edges(const void *a, const void *b)
{
    const fill_edge *x = a, *y = b;
    return (x->first_row > y->first_row) - (x->first_row < y->first_row);
}

static cg_status add_edge(cg_rasterizer *r, cg_vec2 a, cg_vec2 b, int height)
{
    if (a.y == b.y)
        return CG_OK;
    int dir = b.y > a.y ? 1 : -1;
    cg_vec2 top = dir > 0 ? a : b, bottom = dir > 0 ? b : a;
    double first = ceil(top.y - 0.5), last = ceil(bottom.y - 0.5) - 1;
    if (first < 0)
        first = 0;
    if (last > height - 1)
        last = height - 1;
    if (first > last)
        return CG_OK;
    if (core_array_reserve((void **)&r->edges, &r->edge_capacity, r->edge_count + 1,
                           sizeof *r->edges)
        != CG_OK)
        return CG_ENOMEM;
    fill_edge *e = &r->edges[r->edge_count++];
    e->x0 = top.x;
    e->y0 = top.y;
    e->slope = (bottom.x - top.x) / (bottom.y - top.y);
    e->first_row = (int)first;
    e->last_row = (int)last;
    e->dir = dir;
    return CG_OK;
}

/* Pixel index of the first centre at or right of x, clamped to [0, width]. */
static inline int first_pixel_at(double x, int width)
{
    double p = x - 0.5; /* exact for |x| < 2^52 */
    if (!(p > 0))
        return 0;
    if (p >= width)
        return width;
    int i = (int)p; /* p > 0: truncation is floor; ceil is one more unless integral */
    return i + (i < p);
}

typedef struct active_edge {
    double x;
    int dir;
    unsigned edge;
} active_edge;

/* Sorts edges by first row: insertion sort for the few edges of most
 * polygons, qsort beyond. */
static void sort_edges(fill_edge *edges, size_t n)
{
    if (n > 48) {
        core_sort(edges, n, sizeof *edges, compare_edges);
        return;
    }
    for (size_t i = 1; i < n; i++) {
        fill_edge e = edges[i];
        size_t j = i;
        while (j > 0 && edges[j - 1].first_row > e.first_row) {
            edges[j] = edges[j - 1];
            j--;
        }
        edges[j] = e;
    }
}

cg_status cg_rasterizer_fill_polygon(cg_rasterizer *r, cg_image *image, const cg_vec2 *points,
                                     const int *contour_sizes, int contour_count, cg_fill_rule rule,
                                     cg_rgba8 color)
{
    if (!r || !image || !image->data || (rule != CG_FILL_EVEN_ODD && rule != CG_FILL_NONZERO))
        return CG_EINVAL;
    size_t total;
    cg_status status = fill_check_polygon(points, contour_sizes, contour_count, &total);
    if (status != CG_OK)
        return status;
    r->edge_count = 0;
    size_t start = 0;
    for (int c = 0; c < contour_count; c++) {
        size_t n = (size_t)contour_sizes[c];
        for (size_t i = 0; i < n; i++) {
            status = add_edge(r, points[start + i], points[start + (i + 1) % n], image->height);
            if (status != CG_OK)
                return status;
        }
        start += n;
    }
    if (r->edge_count == 0)
        return CG_OK;
    if (r->edge_count > 0xffffffffu)
        return CG_ERANGE;
    sort_edges(r->edges, r->edge_count);
    /* The active list reuses the crossing buffer's memory as active_edge
     * records. */
    if (core_array_reserve((void **)&r->crossings, &r->crossing_capacity,
                           (r->edge_count * sizeof(active_edge) + sizeof(fill_crossing) - 1)
                               / sizeof(fill_crossing),
                           sizeof *r->crossings)
        != CG_OK)
        return CG_ENOMEM;
    cg_paint paint = cg_paint_solid(color);
    fill_painter painter;
    status = fill_painter_init(&painter, r, image, &paint);
    if (status != CG_OK)
        return status;
    active_edge *active = (active_edge *)(void *)r->crossings;
    size_t active_count = 0, next = 0;
    int width = image->width;
    int last_row = 0;
    for (size_t i = 0; i < r->edge_count; i++)
        if (r->edges[i].last_row > last_row)
            last_row = r->edges[i].last_row;
    for (int y = r->edges[0].first_row; y <= last_row; y++) {
        /* Drop finished edges, move the rest to this scan-line, add new ones. */
        double yc = y + 0.5;
        size_t kept = 0;
        for (size_t i = 0; i < active_count; i++) {
            unsigned index = active[i].edge;
            const fill_edge *e = &r->edges[index];
            if (e->last_row < y)
                continue;
            active[kept].x = e->x0 + (yc - e->y0) * e->slope;
            active[kept].dir = e->dir;
            active[kept].edge = index;
            kept++;
        }
        active_count = kept;
        while (next < r->edge_count && r->edges[next].first_row == y) {
            const fill_edge *e = &r->edges[next];
            active_edge a = {e->x0 + (yc - e->y0) * e->slope, e->dir, (unsigned)next};
            active[active_count++] = a;
            next++;
        }
        if (active_count == 0) {
            if (next < r->edge_count)
                y = r->edges[next].first_row - 1;
            continue;
        }
        /* Insertion sort: the order changes little from one line to the next. */
        for (size_t i = 1; i < active_count; i++) {
            active_edge a = active[i];
            size_t j = i;
            while (j > 0 && active[j - 1].x > a.x) {
                active[j] = active[j - 1];
                j--;
            }
            active[j] = a;
        }
        int winding = 0, inside = 0, span_start = 0;
        for (size_t i = 0; i < active_count; i++) {
            winding += active[i].dir;
            int now = rule == CG_FILL_NONZERO ? winding != 0 : (winding & 1);
            if (now && !inside) {
                span_start = first_pixel_at(active[i].x, width);
            } else if (!now && inside) {
                int end = first_pixel_at(active[i].x, width);
                fill_painter_span(&painter, y, span_start, end - span_start, NULL);
            }
            inside = now;
        }
    }
    return CG_OK;
}

cg_status cg_fill_polygon(cg_image *image, const cg_vec2 *points, const int *contour_sizes,
                          int contour_count, cg_fill_rule rule, cg_rgba8 color)
{
    cg_rasterizer *r;
    cg_status status = cg_rasterizer_create(&r);
    if (status != CG_OK)
        return status;
    status = cg_rasterizer_fill_polygon(r, image, points, contour_sizes, contour_count, rule,
                                        color);
    cg_rasterizer_free(r);
    return status;
}
