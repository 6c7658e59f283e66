/* The chapter-10 trace of cg/trace_steps.h: scan-line polygon fill with
 * its edge table, active edge list and spans, computed as
 * cg_fill_polygon computes them (scanline.c): pixel centres sampled, an
 * edge active on the rows whose centre y has top <= y < bottom, a span
 * taking the pixels whose centre x lies in [x_left, x_right).
 *
 *        x_left = 2.3          x_right = 7.6
 *    row y  |  .  .  .  .  .  . | .      centres at x + 0.5:
 *           0  1  2 [3  4  5  6  7] 8    first = ceil(x_left - 0.5) = 2
 *                                        last  = ceil(x_right - 0.5) - 1 = 7
 * (the brackets mark pixels 2..7, whose centres 2.5 .. 7.5 are inside). */
#include "internal.h"
#include "../core/array.h"
#include "../core/steps.h"
#include "../core/sort.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_TRACE_COORD = 4096, TEXT_SIZE = 2048 };

typedef struct traced_edge {
    int number; /* edge k leaves vertex k (counted over all contours) */
    cg_vec2 top, bottom;
    double x0, y0, slope; /* as scanline.c: x = x0 + (y - y0) slope, from the top */
    int first_row, last_row, dir;
} traced_edge;

typedef struct active_crossing {
    double x;
    int dir, edge; /* index into the sorted edge table */
} active_crossing;

static int by_first_row(const void *a, const void *b)
{
    const traced_edge *x = a, *y = b;
    if (x->first_row != y->first_row)
        return (x->first_row > y->first_row) - (x->first_row < y->first_row);
    return (x->number > y->number) - (x->number < y->number);
}

static int emit_edge_table(const traced_edge *edges, size_t count, cg_step_fn fn, void *user)
{
    for (size_t i = 0; i < count; i++) {
        const traced_edge *e = &edges[i];
        core_step s;
        cg_vec2 segment[2] = {e->top, e->bottom};
        core_step_begin(&s, "edge table");
        core_step_integer(&s, "edge", e->number);
        core_step_point(&s, "top", e->top);
        core_step_point(&s, "bottom", e->bottom);
        core_step_integer(&s, "first_row", e->first_row);
        core_step_integer(&s, "last_row", e->last_row);
        core_step_real(&s, "x_first", e->x0 + (e->first_row + 0.5 - e->y0) * e->slope);
        core_step_real(&s, "dx_per_row", e->slope);
        core_step_integer(&s, "direction", e->dir);
        s.step.geometry = segment;
        s.step.geometry_count = 2;
        if (core_step_emit(&s, fn, user))
            return 1;
    }
    return 0;
}

typedef CORE_ARRAY(int) pixel_array;

/* One scan-line: its spans' pixels, and the step.  1 when stopped, -1 out
 * of memory. */
static int emit_row(const traced_edge *edges, const active_crossing *active, size_t count, int y,
                    const char *added, const char *removed, cg_fill_rule rule, cg_step_fn fn,
                    void *user, pixel_array *pixels)
{
    char list[TEXT_SIZE], spans[TEXT_SIZE];
    list[0] = spans[0] = 0;
    pixels->count = 0;
    int winding = 0, inside = 0;
    double span_left = 0;
    for (size_t i = 0; i < count; i++) {
        core_text_append(list, TEXT_SIZE, "%se%d x=%.6g %s", i ? ", " : "",
                         edges[active[i].edge].number, active[i].x,
                         active[i].dir > 0 ? "down" : "up");
        winding += active[i].dir;
        int now = rule == CG_FILL_NONZERO ? winding != 0 : (winding & 1);
        if (now && !inside) {
            span_left = active[i].x;
        } else if (!now && inside) {
            long long first = (long long)ceil(span_left - 0.5);
            long long last = (long long)ceil(active[i].x - 0.5) - 1;
            if (first <= last)
                core_text_append(spans, TEXT_SIZE, "%s[%.6g, %.6g) -> %lld..%lld",
                                 spans[0] ? "; " : "", span_left, active[i].x, first, last);
            else
                core_text_append(spans, TEXT_SIZE, "%s[%.6g, %.6g) -> none", spans[0] ? "; " : "",
                                 span_left, active[i].x);
            for (long long x = first; x <= last; x++)
                if (core_array_push(pixels, (int)x) != CG_OK || core_array_push(pixels, y) != CG_OK)
                    return -1;
        }
        inside = now;
    }
    core_step s;
    cg_vec2 row[2] = {{active[0].x, y + 0.5}, {active[count - 1].x, y + 0.5}};
    core_step_begin(&s, "scan-lines");
    core_step_integer(&s, "y", y);
    core_step_real(&s, "centre_y", y + 0.5);
    core_step_text(&s, "added", added);
    core_step_text(&s, "removed", removed);
    core_step_text(&s, "active", list);
    core_step_text(&s, "spans", spans[0] ? spans : "none");
    s.step.pixels = pixels->data;
    s.step.pixel_count = (int)(pixels->count / 2);
    s.step.geometry = row;
    s.step.geometry_count = 2;
    return core_step_emit(&s, fn, user) ? 1 : 0;
}

static int sweep(const traced_edge *edges, size_t count, cg_fill_rule rule, cg_step_fn fn,
                 void *user)
{
    active_crossing *active = malloc(count * sizeof *active);
    pixel_array pixels = {0};
    char added[TEXT_SIZE], removed[TEXT_SIZE];
    int outcome = active ? 0 : -1, last_row = edges[0].last_row;
    for (size_t i = 0; i < count; i++)
        if (edges[i].last_row > last_row)
            last_row = edges[i].last_row;
    size_t active_count = 0, next = 0;
    for (int y = edges[0].first_row; y <= last_row && outcome == 0; y++) {
        double yc = y + 0.5;
        size_t kept = 0;
        added[0] = removed[0] = 0;
        for (size_t i = 0; i < active_count; i++) {
            const traced_edge *e = &edges[active[i].edge];
            if (e->last_row < y) {
                core_text_append(removed, TEXT_SIZE, "%se%d", removed[0] ? " " : "", e->number);
                continue;
            }
            active[kept].x = e->x0 + (yc - e->y0) * e->slope;
            active[kept].dir = e->dir;
            active[kept].edge = active[i].edge;
            kept++;
        }
        active_count = kept;
        while (next < count && edges[next].first_row == y) {
            const traced_edge *e = &edges[next];
            active[active_count++] = (active_crossing){e->x0 + (yc - e->y0) * e->slope, e->dir,
                                                       (int)next};
            core_text_append(added, TEXT_SIZE, "%se%d", added[0] ? " " : "", e->number);
            next++;
        }
        if (active_count == 0) {
            if (next < count)
                y = edges[next].first_row - 1;
            continue;
        }
        for (size_t i = 1; i < active_count; i++) { /* sorted by crossing */
            active_crossing a = active[i];
            size_t j = i;
            while (j > 0 && active[j - 1].x > a.x) {
                active[j] = active[j - 1];
                j--;
            }
            active[j] = a;
        }
        outcome = emit_row(edges, active, active_count, y, added[0] ? added : "-",
                           removed[0] ? removed : "-", rule, fn, user, &pixels);
    }
    free(active);
    free(pixels.data);
    return outcome;
}

cg_status cg_scanline_fill_steps(const cg_vec2 *points, const int *contour_sizes, int contour_count,
                                 cg_fill_rule rule, cg_step_fn step, void *user)
{
    size_t total;
    if (!step || (rule != CG_FILL_EVEN_ODD && rule != CG_FILL_NONZERO))
        return CG_EINVAL;
    cg_status status = fill_check_polygon(points, contour_sizes, contour_count, &total);
    if (status != CG_OK)
        return status;
    for (size_t i = 0; i < total; i++)
        if (fabs(points[i].x) > MAX_TRACE_COORD || fabs(points[i].y) > MAX_TRACE_COORD)
            return CG_ERANGE;
    CORE_ARRAY(traced_edge) edges = {0};
    size_t start = 0;
    for (int c = 0; c < contour_count; c++) {
        size_t n = (size_t)contour_sizes[c];
        for (size_t i = 0; i < n; i++) {
            cg_vec2 a = points[start + i], b = points[start + (i + 1) % n];
            if (a.y == b.y)
                continue; /* horizontal: never active */
            int dir = b.y > a.y ? 1 : -1;
            traced_edge e = {
                (int)(start + i), dir > 0 ? a : b, dir > 0 ? b : a, 0, 0, 0, 0, 0, dir};
            e.first_row = (int)ceil(e.top.y - 0.5);
            e.last_row = (int)ceil(e.bottom.y - 0.5) - 1;
            if (e.first_row > e.last_row)
                continue; /* crosses no centre */
            e.x0 = e.top.x;
            e.y0 = e.top.y;
            e.slope = (e.bottom.x - e.top.x) / (e.bottom.y - e.top.y);
            if (core_array_push(&edges, e) != CG_OK) {
                free(edges.data);
                return CG_ENOMEM;
            }
        }
        start += n;
    }
    if (edges.count == 0) {
        free(edges.data);
        return CG_OK;
    }
    core_sort(edges.data, edges.count, sizeof *edges.data, by_first_row);
    int outcome = emit_edge_table(edges.data, edges.count, step, user);
    if (outcome == 0)
        outcome = sweep(edges.data, edges.count, rule, step, user);
    free(edges.data);
    return outcome < 0 ? CG_ENOMEM : CG_OK;
}
