/* The Weiler-Atherton trace of cg/trace_steps.h, computed as weiler.c
 * computes it: both boundaries made counter-clockwise (the window moved by
 * 1e-9 of the extent off degenerate contacts), every crossing of a subject
 * edge with a window edge found and marked entering or exiting, both
 * vertex lists with the crossings inserted in order, and the traversal:
 *
 *   from an entering crossing I, follow the subject to the next crossing
 *   (it exits), follow the window from there to the next crossing (it
 *   enters), ... until I comes back: one loop of the result.
 *
 * Labels: S3 is the subject's vertex 3, W1 the window's vertex 1, I2 the
 * crossing 2 (numbered along the subject). */
#include "cg/clip.h"
#include "internal.h"
#include "../core/array.h"
#include "../core/steps.h"
#include "../core/sort.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { LABELS = 4096 };

typedef struct crossing {
    size_t subject_edge, window_edge;
    double t, u;
    cg_vec2 p;
    int entering;
} crossing;

/* A node of a boundary list: a vertex (crossing = -1) or a crossing. */
typedef struct node {
    cg_vec2 p;
    long vertex, crossing;
    size_t twin; /* the crossing's node on the other list */
    int visited;
} node;

typedef CORE_ARRAY(node) node_list;
typedef CORE_ARRAY(cg_vec2) point_list;

typedef struct weiler_trace {
    cg_vec2 *subject, *window;
    size_t n, m;
    CORE_ARRAY(crossing) crossings;
    node_list lists[2]; /* 0 subject, 1 window */
    cg_step_fn fn;
    void *user;
} weiler_trace;

static void label(const node *x, int window, char *out, size_t size)
{
    if (x->crossing >= 0)
        snprintf(out, size, "I%ld", x->crossing);
    else
        snprintf(out, size, "%c%ld", window ? 'W' : 'S', x->vertex);
}

static int by_subject_edge(const void *a, const void *b)
{
    const crossing *x = a, *y = b;
    if (x->subject_edge != y->subject_edge)
        return x->subject_edge < y->subject_edge ? -1 : 1;
    return (x->t > y->t) - (x->t < y->t);
}

/* Every crossing, sorted along the subject, one step each. */
static int find_crossings(weiler_trace *w)
{
    for (size_t i = 0; i < w->n; i++) {
        cg_vec2 a = w->subject[i], d = cg_vec2_sub(w->subject[(i + 1) % w->n], a);
        for (size_t j = 0; j < w->m; j++) {
            cg_vec2 c = w->window[j], e = cg_vec2_sub(w->window[(j + 1) % w->m], c);
            double t, u;
            int entering;
            if (!clip_weiler_crossing(a, d, c, e, &t, &u, &entering))
                continue;
            crossing x = {i, j, t, u, cg_vec2_add(a, cg_vec2_scale(d, t)), entering};
            if (core_array_push(&w->crossings, x) != CG_OK)
                return -1;
        }
    }
    core_sort(w->crossings.data, w->crossings.count, sizeof *w->crossings.data, by_subject_edge);
    for (size_t k = 0; k < w->crossings.count; k++) {
        const crossing *x = &w->crossings.data[k];
        core_step s;
        cg_vec2 edge[2] = {w->subject[x->subject_edge], w->subject[(x->subject_edge + 1) % w->n]};
        char name[32];
        snprintf(name, sizeof name, "I%zu", k);
        core_step_begin(&s, "crossings");
        core_step_text(&s, "crossing", name);
        core_step_integer(&s, "subject_edge", (long long)x->subject_edge);
        core_step_integer(&s, "window_edge", (long long)x->window_edge);
        core_step_real(&s, "t", x->t);
        core_step_real(&s, "u", x->u);
        core_step_point(&s, "point", x->p);
        core_step_text(&s, "kind", x->entering ? "entering" : "exiting");
        s.step.geometry = edge;
        s.step.geometry_count = 2;
        if (core_step_emit(&s, w->fn, w->user))
            return 1;
    }
    return 0;
}

/* A crossing's place along the window: by window edge, then u. */
typedef struct window_place {
    size_t window_edge;
    double u;
    size_t crossing;
} window_place;

static int by_window_edge(const void *a, const void *b)
{
    const window_place *x = a, *y = b;
    if (x->window_edge != y->window_edge)
        return x->window_edge < y->window_edge ? -1 : 1;
    return (x->u > y->u) - (x->u < y->u);
}

static int emit_list(weiler_trace *w, int window)
{
    node_list *l = &w->lists[window];
    char text[LABELS] = "", name[32];
    cg_vec2 *points = malloc(l->count * sizeof *points);
    if (!points)
        return -1;
    for (size_t i = 0; i < l->count; i++) {
        label(&l->data[i], window, name, sizeof name);
        long c = l->data[i].crossing;
        core_text_append(text, LABELS, "%s%s%s", i ? " " : "", name,
                         c < 0                           ? ""
                         : w->crossings.data[c].entering ? "(in)"
                                                         : "(out)");
        points[i] = l->data[i].p;
    }
    core_step s;
    core_step_begin(&s, "lists");
    core_step_text(&s, "boundary", window ? "window" : "subject");
    core_step_text(&s, "nodes", text);
    core_step_points(&s, "points", points, l->count);
    s.step.geometry = points;
    s.step.geometry_count = (int)l->count;
    s.step.closed = 1;
    int stopped = core_step_emit(&s, w->fn, w->user);
    free(points);
    return stopped;
}

/* Both lists: each boundary's vertices with its crossings inserted in
 * order, the twins linking the two copies of each crossing. */
static int build_lists(weiler_trace *w)
{
    size_t nx = w->crossings.count, k = 0;
    size_t *subject_node = malloc(nx * sizeof *subject_node);
    window_place *places = malloc(nx * sizeof *places);
    int outcome = subject_node && places ? 0 : -1;
    for (size_t i = 0; i < w->n && outcome == 0; i++) {
        node v = {w->subject[i], (long)i, -1, 0, 0};
        if (core_array_push(&w->lists[0], v) != CG_OK)
            outcome = -1;
        for (; outcome == 0 && k < nx && w->crossings.data[k].subject_edge == i; k++) {
            node x = {w->crossings.data[k].p, -1, (long)k, 0, 0};
            subject_node[k] = w->lists[0].count;
            if (core_array_push(&w->lists[0], x) != CG_OK)
                outcome = -1;
        }
    }
    for (size_t i = 0; outcome == 0 && i < nx; i++)
        places[i] = (window_place){w->crossings.data[i].window_edge, w->crossings.data[i].u, i};
    if (outcome == 0)
        core_sort(places, nx, sizeof *places, by_window_edge);
    k = 0;
    for (size_t j = 0; j < w->m && outcome == 0; j++) {
        node v = {w->window[j], (long)j, -1, 0, 0};
        if (core_array_push(&w->lists[1], v) != CG_OK)
            outcome = -1;
        for (; outcome == 0 && k < nx && places[k].window_edge == j; k++) {
            size_t c = places[k].crossing, s = subject_node[c];
            node x = {w->crossings.data[c].p, -1, (long)c, s, 0};
            w->lists[0].data[s].twin = w->lists[1].count;
            if (core_array_push(&w->lists[1], x) != CG_OK)
                outcome = -1;
        }
    }
    free(subject_node);
    free(places);
    if (outcome == 0)
        outcome = emit_list(w, 0);
    if (outcome == 0)
        outcome = emit_list(w, 1);
    return outcome;
}

/* One leg of a loop: from crossing node `at` of list `side` along that
 * boundary to its next crossing, the points appended to ring.  Returns the
 * crossing's node index on that list, or -1 (the walk ran away). */
static long walk_leg(weiler_trace *w, int side, size_t at, point_list *ring, int loop, int *stopped)
{
    node_list *l = &w->lists[side];
    size_t limit = w->lists[0].count + w->lists[1].count, guard = 0, first = ring->count;
    l->data[at].visited = 1;
    w->lists[1 - side].data[l->data[at].twin].visited = 1;
    if (core_array_push(ring, l->data[at].p) != CG_OK)
        return -1;
    size_t cur = (at + 1) % l->count;
    while (l->data[cur].crossing < 0 && guard++ < limit) {
        if (core_array_push(ring, l->data[cur].p) != CG_OK)
            return -1;
        cur = (cur + 1) % l->count;
    }
    char from[32], to[32], path[LABELS] = "";
    label(&l->data[at], side, from, sizeof from);
    label(&l->data[cur], side, to, sizeof to);
    for (size_t i = at;; i = (i + 1) % l->count) {
        char name[32];
        label(&l->data[i], side, name, sizeof name);
        core_text_append(path, LABELS, "%s%s", i == at ? "" : " ", name);
        if (i == cur || strlen(path) + 8 >= LABELS)
            break;
    }
    size_t leg_points = ring->count - first;
    cg_vec2 *leg = malloc((leg_points + 1) * sizeof *leg);
    if (!leg)
        return -1;
    memcpy(leg, ring->data + first, leg_points * sizeof *leg);
    leg[leg_points] = l->data[cur].p;
    core_step s;
    core_step_begin(&s, "traversal");
    core_step_integer(&s, "loop", loop);
    core_step_text(&s, "from", from);
    core_step_text(&s, "along", side ? "window" : "subject");
    core_step_text(&s, "path", path);
    core_step_text(&s, "to", to);
    core_step_points(&s, "emitted", leg, leg_points);
    s.step.geometry = leg;
    s.step.geometry_count = (int)leg_points + 1;
    s.step.kept = leg;
    s.step.kept_count = (int)leg_points + 1;
    *stopped = core_step_emit(&s, w->fn, w->user);
    free(leg);
    return (long)cur;
}

/* Every loop, started from each entering crossing not yet visited, as
 * weiler.c walks them.  0, 1 when stopped, -1 out of memory. */
static int traverse(weiler_trace *w)
{
    node_list *subject = &w->lists[0];
    size_t limit = w->lists[0].count + w->lists[1].count;
    int loop = 0;
    for (size_t start = 0; start < subject->count; start++) {
        const node *x = &subject->data[start];
        if (x->crossing < 0 || !w->crossings.data[x->crossing].entering || x->visited)
            continue;
        point_list ring = {0};
        int side = 0, stopped = 0;
        size_t cur = start, guard = 0;
        do {
            long next = walk_leg(w, side, cur, &ring, loop, &stopped);
            if (next < 0 || stopped) {
                free(ring.data);
                return next < 0 ? -1 : 1;
            }
            cur = w->lists[side].data[next].twin;
            side = 1 - side;
        } while (!(side == 0 && cur == start) && guard++ < limit);
        core_step s;
        core_step_begin(&s, "loops");
        core_step_integer(&s, "loop", loop);
        core_step_integer(&s, "points", (long long)ring.count);
        core_step_text(&s, "kept", ring.count >= 3 ? "yes" : "no: fewer than 3 points");
        core_step_points(&s, "ring", ring.data, ring.count);
        s.step.geometry = ring.data;
        s.step.geometry_count = (int)ring.count;
        s.step.closed = 1;
        stopped = core_step_emit(&s, w->fn, w->user);
        free(ring.data);
        if (stopped)
            return 1;
        loop++;
    }
    return 0;
}

/* The library's result, ring by ring (loops turning clockwise became
 * holes of the smallest loop around them). */
static void emit_result(const cg_polygon_set *result, cg_step_fn fn, void *user)
{
    for (size_t p = 0; p < result->polygon_count; p++)
        for (size_t r = result->polygon_start[p]; r < result->polygon_start[p + 1]; r++) {
            size_t first = result->ring_start[r], count = result->ring_start[r + 1] - first;
            cg_vec2 *closed = malloc((count + 1) * sizeof *closed);
            if (!closed)
                return;
            memcpy(closed, result->points + first, count * sizeof *closed);
            closed[count] = closed[0];
            core_step s;
            core_step_begin(&s, "result");
            core_step_integer(&s, "polygon", (long long)p);
            core_step_text(&s, "role", r == result->polygon_start[p] ? "outer" : "hole");
            core_step_real(&s, "area", cg_polygon_set_ring_area(result, r));
            core_step_points(&s, "ring", closed, count);
            s.step.kept = closed;
            s.step.kept_count = (int)count + 1;
            int stopped = core_step_emit(&s, fn, user);
            free(closed);
            if (stopped)
                return;
        }
}

static int emit_prepared(const weiler_trace *w, double delta)
{
    core_step s;
    core_step_begin(&s, "prepare");
    core_step_points(&s, "subject", w->subject, w->n);
    core_step_points(&s, "window", w->window, w->m);
    core_step_real(&s, "window_shift", delta);
    s.step.geometry = w->window;
    s.step.geometry_count = (int)w->m;
    s.step.closed = 1;
    return core_step_emit(&s, w->fn, w->user);
}

cg_status cg_weiler_atherton_steps(const cg_vec2 *subject, size_t n, const cg_vec2 *window,
                                   size_t m, cg_step_fn step, void *user)
{
    cg_polygon_set result = {0};
    if (!step)
        return CG_EINVAL;
    cg_status status = cg_clip_weiler_atherton(subject, n, window, m, &result);
    if (status != CG_OK)
        return status;
    double extent = 0;
    for (size_t i = 0; i < n + m; i++) {
        cg_vec2 p = i < n ? subject[i] : window[i - n];
        extent = fmax(extent, fmax(fabs(p.x), fabs(p.y)));
    }
    double delta = (extent > 0 ? extent : 1) * 1e-9;
    weiler_trace w = {malloc(n * sizeof(cg_vec2)),
                      malloc(m * sizeof(cg_vec2)),
                      0,
                      0,
                      {0},
                      {{0}, {0}},
                      step,
                      user};
    int outcome = w.subject && w.window ? 0 : -1;
    if (outcome == 0) {
        w.n = clip_weiler_prepare(subject, n, cg_vec2_make(0, 0), w.subject);
        w.m = clip_weiler_prepare(
            window, m, cg_vec2_make(delta * 0.7548776662, delta * 0.5698402910), w.window);
        outcome = emit_prepared(&w, delta);
    }
    int flat = w.n < 3 || w.m < 3 || clip_twice_area(w.subject, w.n) == 0
               || clip_twice_area(w.window, w.m) == 0;
    if (outcome == 0 && !flat)
        outcome = find_crossings(&w);
    if (outcome == 0 && !flat && (w.crossings.count == 0 || w.crossings.count % 2)) {
        core_step s;
        core_step_begin(&s, "containment");
        core_step_text(&s, "outcome",
                       result.ring_count ? "no crossing: one polygon lies inside "
                                           "the other and is the result"
                                         : "no crossing: the polygons are apart");
        outcome = core_step_emit(&s, step, user);
    } else if (outcome == 0 && !flat) {
        outcome = build_lists(&w);
        if (outcome == 0)
            outcome = traverse(&w);
    }
    if (outcome == 0)
        emit_result(&result, step, user);
    cg_polygon_set_clear(&result);
    free(w.subject);
    free(w.window);
    free(w.crossings.data);
    free(w.lists[0].data);
    free(w.lists[1].data);
    return outcome < 0 ? CG_ENOMEM : CG_OK;
}
