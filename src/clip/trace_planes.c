/* Sutherland-Hodgman in 3D against planes (11.3) step by step
 * (cg/trace_steps.h), with cg_clip_polygon_planes's arithmetic: a plane
 * keeps the points p with d(p) = N.p + offset >= 0, and each polygon edge
 * s -> e adds to the output list:
 *
 *     d(s) >= 0, d(e) >= 0: e          d(s) < 0, d(e) > 0: the crossing, e
 *     d(s) > 0,  d(e) < 0:  the crossing                   otherwise: e or nothing
 *
 * The crossing is s + (e - s) d(s) / (d(s) - d(e)), from the end inside. */
#include "cg/clip.h"
#include "../core/array.h"
#include "../core/steps.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef CORE_ARRAY(cg_vec3) point3_list;

static cg_vec3 plane_cross(cg_vec3 s, double ds, cg_vec3 e, double de)
{
    double t = ds / (ds - de);
    return cg_vec3_add(s, cg_vec3_scale(cg_vec3_sub(e, s), t));
}

/* The points as 3 reals each, in a list the caller frees. */
static double *flatten3(const cg_vec3 *p, size_t n)
{
    double *r = malloc((n ? n : 1) * 3 * sizeof *r);
    for (size_t i = 0; r && i < n; i++) {
        r[3 * i] = p[i].x;
        r[3 * i + 1] = p[i].y;
        r[3 * i + 2] = p[i].z;
    }
    return r;
}

static int emit_edge(const char *phase, cg_vec3 s, double ds, cg_vec3 e, double de,
                     const char *rule, const cg_vec3 *added, size_t added_count, cg_step_fn fn,
                     void *user)
{
    double ends[6] = {s.x, s.y, s.z, e.x, e.y, e.z}, out[6];
    for (size_t i = 0; i < added_count; i++) {
        out[3 * i] = added[i].x;
        out[3 * i + 1] = added[i].y;
        out[3 * i + 2] = added[i].z;
    }
    core_step st;
    core_step_begin(&st, phase);
    core_step_reals(&st, "s", ends, 3);
    core_step_reals(&st, "e", ends + 3, 3);
    core_step_real(&st, "d_s", ds);
    core_step_real(&st, "d_e", de);
    core_step_text(&st, "case", rule);
    core_step_reals(&st, "output", out, 3 * added_count);
    return core_step_emit(&st, fn, user);
}

/* One plane over the list in, into out: 1 stopped, -1 out of memory. */
static int clip_plane(const char *phase, cg_plane plane, const point3_list *in, point3_list *out,
                      cg_step_fn fn, void *user)
{
    out->count = 0;
    cg_vec3 s = in->data[in->count - 1];
    double ds = cg_vec3_dot(plane.normal, s) + plane.offset;
    for (size_t i = 0; i < in->count; i++) {
        cg_vec3 e = in->data[i], added[2];
        size_t n = 0;
        double de = cg_vec3_dot(plane.normal, e) + plane.offset;
        const char *rule;
        if (de >= 0) {
            if (ds < 0 && de > 0) {
                added[n++] = plane_cross(e, de, s, ds);
                rule = "out -> in: the crossing, then e";
            } else {
                rule = ds < 0 ? "out -> on the plane: e" : "in -> in: e";
            }
            added[n++] = e;
        } else if (ds > 0) {
            added[n++] = plane_cross(s, ds, e, de);
            rule = "in -> out: the crossing";
        } else {
            rule = ds < 0 ? "out -> out: nothing" : "on the plane -> out: nothing";
        }
        for (size_t k = 0; k < n; k++)
            if (core_array_push(out, added[k]) != CG_OK)
                return -1;
        if (emit_edge(phase, s, ds, e, de, rule, added, n, fn, user))
            return 1;
        s = e;
        ds = de;
    }
    double *input = flatten3(in->data, in->count), *output = flatten3(out->data, out->count);
    int stopped = -1;
    if (input && output) {
        core_step st;
        core_step_begin(&st, phase);
        core_step_reals(&st, "input", input, 3 * in->count);
        core_step_reals(&st, "output", output, 3 * out->count);
        stopped = core_step_emit(&st, fn, user) ? 1 : 0;
    }
    free(input);
    free(output);
    return stopped;
}

cg_status cg_clip_planes_steps(const cg_vec3 *polygon, size_t n, const cg_plane *planes,
                               size_t plane_count, const char *const *plane_names, cg_step_fn step,
                               void *user)
{
    cg_vec3 *result = NULL;
    size_t result_count = 0;
    if (!step)
        return CG_EINVAL;
    cg_status status = cg_clip_polygon_planes(polygon, n, planes, plane_count, &result,
                                              &result_count);
    free(result);
    if (status != CG_OK || n == 0)
        return status;
    point3_list lists[2] = {{0}, {0}};
    int current = 0, outcome = 0;
    for (size_t i = 0; i < n && outcome == 0; i++)
        if (core_array_push(&lists[0], polygon[i]) != CG_OK)
            outcome = -1;
    for (size_t k = 0; k < plane_count && lists[current].count && outcome == 0; k++) {
        char phase[64];
        if (plane_names && plane_names[k])
            snprintf(phase, sizeof phase, "plane %zu (%s)", k + 1, plane_names[k]);
        else
            snprintf(phase, sizeof phase, "plane %zu", k + 1);
        outcome = clip_plane(phase, planes[k], &lists[current], &lists[1 - current], step, user);
        current = 1 - current;
    }
    free(lists[0].data);
    free(lists[1].data);
    return outcome < 0 ? CG_ENOMEM : CG_OK;
}
