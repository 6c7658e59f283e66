/* The clipping traces of cg/trace_steps.h: Liang-Barsky's p, q and t per
 * boundary, and Sutherland-Hodgman's lists per clip edge. */
#include "cg/clip.h"
#include "internal.h"
#include "../core/array.h"
#include "../core/steps.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


/* The last step of both line clippers: accepted with the visible part
 * from-to (kept), or rejected; drawn over segment[0..2) when not NULL. */
static void emit_line_outcome(int accepted, cg_vec2 from, cg_vec2 to, const cg_vec2 *segment,
                              cg_step_fn step, void *user)
{
    core_step s;
    cg_vec2 visible[2] = {from, to};
    core_step_begin(&s, "outcome");
    core_step_text(&s, "outcome", accepted ? "accept" : "reject");
    if (accepted) {
        core_step_point(&s, "from", from);
        core_step_point(&s, "to", to);
        s.step.kept = visible;
        s.step.kept_count = 2;
    } else {
        core_step_none(&s, "from");
        core_step_none(&s, "to");
    }
    if (segment) {
        s.step.geometry = segment;
        s.step.geometry_count = 2;
    }
    core_step_emit(&s, step, user);
}

cg_status cg_liang_barsky_steps(cg_rect window, cg_vec2 p0, cg_vec2 p1, cg_step_fn step, void *user)
{
    cg_vec2 c0 = p0, c1 = p1;
    int accepted;
    if (!step)
        return CG_EINVAL;
    cg_status status = cg_clip_line_liang_barsky(window, &c0, &c1, &accepted);
    if (status != CG_OK)
        return status;
    /* x = x0 + t dx, y = y0 + t dy is inside where p_k t <= q_k for all k:
     *   left   p1 = -dx  q1 = x0 - xmin      right  p2 = dx  q2 = xmax - x0
     *   bottom p3 = -dy  q3 = y0 - ymin      top    p4 = dy  q4 = ymax - y0
     * p < 0: the line enters the half-plane at t = q / p; p > 0: leaves. */
    double dx = p1.x - p0.x, dy = p1.y - p0.y;
    const char *names[4] = {"left", "right", "bottom", "top"};
    double p[4] = {-dx, dx, -dy, dy};
    double q[4] = {p0.x - window.xmin, window.xmax - p0.x, p0.y - window.ymin, window.ymax - p0.y};
    double t_enter = 0, t_exit = 1;
    int rejected = 0;
    cg_vec2 segment[2] = {p0, p1};
    for (int k = 0; k < 4 && !rejected; k++) {
        core_step s;
        const char *kind;
        double t = NAN;
        if (p[k] == 0) {
            kind = q[k] < 0 ? "parallel, outside: reject" : "parallel, inside";
            rejected = q[k] < 0;
        } else {
            t = q[k] / p[k];
            if (p[k] < 0) {
                kind = "entering";
                t_enter = fmax(t_enter, t);
            } else {
                kind = "leaving";
                t_exit = fmin(t_exit, t);
            }
            if (t_enter > t_exit) {
                rejected = 1;
                kind = p[k] < 0 ? "entering after the exit: reject"
                                : "leaving before the entry: reject";
            }
        }
        core_step_begin(&s, "boundaries");
        core_step_text(&s, "boundary", names[k]);
        core_step_real(&s, "p", p[k]);
        core_step_real(&s, "q", q[k]);
        if (p[k] == 0)
            core_step_none(&s, "t");
        else
            core_step_real(&s, "t", t);
        core_step_text(&s, "kind", kind);
        core_step_real(&s, "t_enter", t_enter);
        core_step_real(&s, "t_exit", t_exit);
        s.step.geometry = segment;
        s.step.geometry_count = 2;
        if (core_step_emit(&s, step, user))
            return CG_OK;
    }
    emit_line_outcome(accepted, c0, c1, segment, step, user);
    return CG_OK;
}

/* ---- Sutherland-Hodgman ------------------------------------------------------ */

typedef CORE_ARRAY(cg_vec2) point_array;

/* The point where s-e crosses the clip line, from the end that is inside,
 * as cg_clip_sutherland_hodgman computes it. */
static cg_vec2 crossing(cg_vec2 inside, double d_inside, cg_vec2 outside, double d_outside)
{
    double t = d_inside / (d_inside - d_outside);
    return cg_vec2_add(inside, cg_vec2_scale(cg_vec2_sub(outside, inside), t));
}

typedef struct clip_edge_trace {
    cg_step_fn fn;
    void *user;
    int index;
    cg_vec2 edge[2];
    char phase[32];
} clip_edge_trace;

static int emit_pair(clip_edge_trace *c, cg_vec2 s, double ds, cg_vec2 e, double de,
                     const char *rule, const cg_vec2 *output, size_t output_count)
{
    core_step st;
    cg_vec2 pair[2] = {s, e};
    core_step_begin(&st, c->phase);
    core_step_point(&st, "s", s);
    core_step_point(&st, "e", e);
    core_step_text(&st, "s_side", ds >= 0 ? "in" : "out");
    core_step_text(&st, "e_side", de >= 0 ? "in" : "out");
    core_step_text(&st, "case", rule);
    core_step_points(&st, "output", output, output_count);
    st.step.geometry = pair;
    st.step.geometry_count = 2;
    return core_step_emit(&st, c->fn, c->user);
}

/* One clip edge over the list in: the output list in out.  1 when the
 * callback stopped the trace, -1 out of memory. */
static int clip_one_edge(clip_edge_trace *c, double orient, const point_array *in, point_array *out)
{
    cg_vec2 a = c->edge[0], edge = cg_vec2_sub(c->edge[1], a);
    out->count = 0;
    cg_vec2 s = in->data[in->count - 1];
    double ds = orient * cg_vec2_cross(edge, cg_vec2_sub(s, a));
    for (size_t i = 0; i < in->count; i++) {
        cg_vec2 e = in->data[i], emitted[2];
        size_t n = 0;
        double de = orient * cg_vec2_cross(edge, cg_vec2_sub(e, a));
        const char *rule;
        if (de >= 0) {
            if (ds < 0 && de > 0) {
                emitted[n++] = crossing(e, de, s, ds);
                rule = "out -> in: the crossing, then e";
            } else {
                rule = ds < 0 ? "out -> on the line: e" : "in -> in: e";
            }
            emitted[n++] = e;
        } else if (ds >= 0) {
            rule = ds > 0 ? "in -> out: the crossing" : "on the line -> out: nothing";
            if (ds > 0)
                emitted[n++] = crossing(s, ds, e, de);
        } else {
            rule = "out -> out: nothing";
        }
        for (size_t k = 0; k < n; k++)
            if (core_array_push(out, emitted[k]) != CG_OK)
                return -1;
        if (emit_pair(c, s, ds, e, de, rule, emitted, n))
            return 1;
        s = e;
        ds = de;
    }
    core_step st;
    core_step_begin(&st, c->phase);
    core_step_points(&st, "input", in->data, in->count);
    core_step_points(&st, "output", out->data, out->count);
    st.step.geometry = c->edge;
    st.step.geometry_count = 2;
    st.step.kept = out->data;
    st.step.kept_count = (int)out->count;
    st.step.kept_closed = 1;
    return core_step_emit(&st, c->fn, c->user) ? 1 : 0;
}

cg_status cg_sutherland_hodgman_steps(const cg_vec2 *subject, size_t n, const cg_vec2 *window,
                                      size_t m, cg_step_fn step, void *user)
{
    cg_vec2 *result = NULL;
    size_t result_count = 0;
    if (!step)
        return CG_EINVAL;
    /* The library's checks (convex window, finite points) come first. */
    cg_status status = cg_clip_sutherland_hodgman(subject, n, window, m, &result, &result_count);
    free(result);
    if (status != CG_OK || n == 0)
        return status;
    double orient = clip_twice_area(window, m) > 0 ? 1.0 : -1.0;
    point_array lists[2] = {{0}, {0}};
    int current = 0, outcome = 0;
    for (size_t i = 0; i < n; i++)
        if (core_array_push(&lists[0], subject[i]) != CG_OK)
            outcome = -1;
    for (size_t k = 0; k < m && lists[current].count && outcome == 0; k++) {
        clip_edge_trace c = {step, user, (int)k, {window[k], window[(k + 1) % m]}, ""};
        if (c.edge[0].x == c.edge[1].x && c.edge[0].y == c.edge[1].y)
            continue;
        snprintf(c.phase, sizeof c.phase, "clip edge %zu", k + 1);
        outcome = clip_one_edge(&c, orient, &lists[current], &lists[1 - current]);
        current = 1 - current;
    }
    free(lists[0].data);
    free(lists[1].data);
    return outcome < 0 ? CG_ENOMEM : CG_OK;
}

/* ---- Cohen-Sutherland ------------------------------------------------------ */

typedef struct cohen_relay {
    cg_step_fn fn;
    void *user;
    int stopped;
} cohen_relay;

/* The notes' 4-bit TBRL code as text: "1001" is top and left. */
static void code_text(unsigned code, char out[5])
{
    out[0] = code & CG_RCODE_TOP ? '1' : '0';
    out[1] = code & CG_RCODE_BOTTOM ? '1' : '0';
    out[2] = code & CG_RCODE_RIGHT ? '1' : '0';
    out[3] = code & CG_RCODE_LEFT ? '1' : '0';
    out[4] = 0;
}

static void relay_cohen(void *user, cg_vec2 p0, unsigned code0, cg_vec2 p1, unsigned code1,
                        const char *what)
{
    cohen_relay *r = user;
    if (r->stopped)
        return;
    char c0[5], c1[5];
    code_text(code0, c0);
    code_text(code1, c1);
    cg_vec2 segment[2] = {p0, p1};
    core_step s;
    core_step_begin(&s, "steps");
    core_step_point(&s, "p0", p0);
    core_step_text(&s, "code0", c0);
    core_step_point(&s, "p1", p1);
    core_step_text(&s, "code1", c1);
    core_step_text(&s, "and", (code0 & code1) ? "not 0: both outside one boundary" : "0");
    core_step_text(&s, "step", what);
    s.step.geometry = segment;
    s.step.geometry_count = 2;
    r->stopped = core_step_emit(&s, r->fn, r->user);
}

cg_status cg_cohen_sutherland_steps(cg_rect window, cg_vec2 p0, cg_vec2 p1, cg_step_fn step,
                                    void *user)
{
    if (!step)
        return CG_EINVAL;
    cohen_relay relay = {step, user, 0};
    int accepted;
    cg_status status = cg_clip_line_cohen_sutherland(window, &p0, &p1, &accepted, relay_cohen,
                                                     &relay);
    if (status != CG_OK || relay.stopped)
        return status;
    emit_line_outcome(accepted, p0, p1, NULL, step, user);
    return CG_OK;
}
