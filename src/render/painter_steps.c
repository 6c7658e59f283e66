/* The painter's algorithm step by step (cg/trace_steps.h): painter.c
 * reports its own state through these, so the trace is the renderer's run
 * itself, and the frame it draws is cg_renderer_draw's.
 *
 *   sorted:  the list by farthest depth (z_max), farthest first
 *   tests:   for the list's head P, each Q whose depth range reaches P's,
 *            Newell's tests in order until one passes:
 *              1 x extents apart   2 y extents apart
 *              3 P behind Q's plane   4 Q in front of P's plane
 *              5 the projections apart
 *            when all fail: Q moved in front of P, or a split
 *   paint:   each polygon as it is painted over the ones before */
#include "painter.h"
#include "../core/steps.h"

#include <stdio.h>

enum { OUTLINE = 2 * RENDER_MAX_POLYGON + 2 };

/* The polygon's screen outline, closed by repeating its first vertex. */
static int outline(const painter_polygon *p, cg_vec2 *out)
{
    for (int k = 0; k < p->n; k++)
        out[k] = cg_vec2_make(p->v[k].x, p->v[k].y);
    out[p->n] = out[0];
    return p->n + 1;
}

static void emit(painter *pt, core_step *s)
{
    if (core_step_emit(s, pt->step, pt->user))
        pt->stopped = 1;
}

void painter_report_sorted(painter *pt, int list)
{
    size_t k = 0;
    for (int i = list; i >= 0 && pt->step && !pt->stopped; i = pt->nodes[i].next, k++) {
        const painter_node *n = &pt->nodes[i];
        cg_vec2 points[OUTLINE];
        double x[2] = {n->xmin, n->xmax}, y[2] = {n->ymin, n->ymax};
        core_step s;
        core_step_begin(&s, "sorted");
        core_step_integer(&s, "k", (long long)k);
        core_step_integer(&s, "polygon", i);
        core_step_integer(&s, "triangle", pt->polygons[i].triangle);
        core_step_real(&s, "z_max", n->zmax);
        core_step_real(&s, "z_min", n->zmin);
        core_step_reals(&s, "x_extent", x, 2);
        core_step_reals(&s, "y_extent", y, 2);
        s.step.geometry = points;
        s.step.geometry_count = outline(&pt->polygons[i], points);
        emit(pt, &s);
    }
}

static const char *const test_names[PAINTER_TESTS] = {
    "x extents apart", "y extents apart", "P behind Q's plane", "Q in front of P's plane",
    "projections apart"};

static void test_field(core_step *s, const char *name, int result, const char *yes, const char *no)
{
    if (result < 0)
        core_step_none(s, name);
    else
        core_step_text(s, name, result ? yes : no);
}

static void outcome_text(char *out, size_t size, const int *tests, painter_outcome outcome,
                         int far_piece, int near_piece)
{
    int passed = 0;
    for (int k = 0; tests && k < PAINTER_TESTS; k++)
        if (tests[k] == 1)
            passed = k + 1;
    switch (outcome) {
    case PAINTER_DEPTH_APART:
        snprintf(out, size, "depths apart: no later polygon reaches P's depth, P is painted");
        break;
    case PAINTER_DEPTH_SKIP:
        snprintf(out, size, "depths apart (Q was moved or split: look on)");
        break;
    case PAINTER_PASSED:
        snprintf(out, size, "test %d passes (%s): P cannot hide Q", passed, test_names[passed - 1]);
        break;
    case PAINTER_MOVED: snprintf(out, size, "all fail: swap, Q moved in front of P"); break;
    case PAINTER_SPLIT_P:
        snprintf(out, size,
                 "all fail, a swap cannot help (Q moved before or not separable): split P by Q's "
                 "plane into %d (far) and %d "
                 "(near)",
                 far_piece, near_piece);
        break;
    case PAINTER_SPLIT_Q:
        snprintf(out, size,
                 "all fail, a swap cannot help (Q moved before or not separable): split Q by P's "
                 "plane into %d (far) and %d "
                 "(near)",
                 far_piece, near_piece);
        break;
    case PAINTER_UNRESOLVED:
        snprintf(out, size, "all fail, neither plane cuts the other: the sorted order is kept");
        break;
    }
}

void painter_report_pair(painter *pt, int p, int q, const int *tests, painter_outcome outcome,
                         int far_piece, int near_piece)
{
    if (!pt->step || pt->stopped)
        return;
    static const int none[PAINTER_TESTS] = {-1, -1, -1, -1, -1};
    const int *t = tests ? tests : none;
    char text[160];
    cg_vec2 points[2 * OUTLINE];
    core_step s;
    core_step_begin(&s, "tests");
    core_step_integer(&s, "P", p);
    core_step_integer(&s, "Q", q);
    core_step_text(&s, "z_extents", tests ? "overlap" : "apart");
    test_field(&s, "x_extents", t[0], "apart", "overlap");
    test_field(&s, "y_extents", t[1], "apart", "overlap");
    test_field(&s, "P_behind_Q_plane", t[2], "yes", "no");
    test_field(&s, "Q_front_of_P_plane", t[3], "yes", "no");
    test_field(&s, "projections", t[4], "apart", "overlap");
    outcome_text(text, sizeof text, tests, outcome, far_piece, near_piece);
    core_step_text(&s, "outcome", text);
    int n = outline(&pt->polygons[p], points);
    n += outline(&pt->polygons[q], points + n);
    s.step.geometry = points;
    s.step.geometry_count = n;
    emit(pt, &s);
}

void painter_report_paint(painter *pt, int p, size_t fragments)
{
    size_t order = pt->painted++;
    if (!pt->step || pt->stopped)
        return;
    const painter_polygon *polygon = &pt->polygons[p];
    const painter_node *n = &pt->nodes[p];
    double color[3] = {polygon->color[0], polygon->color[1], polygon->color[2]};
    cg_vec2 points[OUTLINE];
    core_step s;
    core_step_begin(&s, "paint");
    core_step_integer(&s, "order", (long long)order);
    core_step_integer(&s, "polygon", p);
    core_step_integer(&s, "triangle", polygon->triangle);
    core_step_integer(&s, "vertices", polygon->n);
    core_step_real(&s, "z_max", n->zmax);
    core_step_integer(&s, "fragments", (long long)fragments);
    core_step_reals(&s, "color", color, 3);
    s.step.geometry = points;
    s.step.geometry_count = outline(polygon, points);
    s.step.kept = points;
    s.step.kept_count = s.step.geometry_count;
    emit(pt, &s);
}

cg_status cg_painter_steps(cg_renderer *renderer, cg_image *image, cg_step_fn step, void *user)
{
    if (!renderer || !step)
        return CG_EINVAL;
    cg_render_algorithm algorithm = renderer->options.algorithm;
    renderer->options.algorithm = CG_RENDER_PAINTER;
    renderer->painter_step = step;
    renderer->painter_user = user;
    cg_status status = cg_renderer_draw(renderer, image);
    renderer->options.algorithm = algorithm;
    renderer->painter_step = NULL;
    renderer->painter_user = NULL;
    return status;
}
