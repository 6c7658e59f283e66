/* The curve traces of cg/trace_steps.h: de Casteljau's levels, Q(t) = T M G
 * with its blending weights, and adaptive flattening piece by piece. */
#include "internal.h"
#include "../core/steps.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_CASTELJAU_POINTS = 64, MAX_CUBIC_SAMPLES = 1000, MAX_FLATTEN_STEPS = 100000 };

cg_status cg_casteljau_steps(const cg_vec2 *control, int count, double t, cg_step_fn step,
                             void *user)
{
    if (!control || !step || count < 2 || count > MAX_CASTELJAU_POINTS || !isfinite(t)
        || !curve_points_finite(control, count))
        return CG_EINVAL;
    cg_vec2 work[MAX_CASTELJAU_POINTS], left[MAX_CASTELJAU_POINTS], right[MAX_CASTELJAU_POINTS];
    memcpy(work, control, (size_t)count * sizeof *work);
    double s = 1 - t;
    /* Level r holds count - r points; the left half takes each level's
     * first point, the right half each level's last. */
    for (int level = 0; level < count; level++) {
        int n = count - level;
        if (level > 0)
            for (int i = 0; i < n; i++)
                work[i] = cg_vec2_make(s * work[i].x + t * work[i + 1].x,
                                       s * work[i].y + t * work[i + 1].y);
        left[level] = work[0];
        right[n - 1] = work[n - 1];
        core_step st;
        core_step_begin(&st, "levels");
        core_step_integer(&st, "r", level);
        core_step_real(&st, "t", t);
        core_step_points(&st, "points", work, (size_t)n);
        st.step.geometry = work;
        st.step.geometry_count = n;
        if (level == count - 1) {
            core_step_point(&st, "Q", work[0]);
            st.step.kept = work;
            st.step.kept_count = 1;
        } else {
            core_step_none(&st, "Q");
        }
        if (core_step_emit(&st, step, user))
            return CG_OK;
    }
    core_step st;
    core_step_begin(&st, "subdivision");
    core_step_points(&st, "left", left, (size_t)count);
    core_step_points(&st, "right", right, (size_t)count);
    st.step.geometry = left;
    st.step.geometry_count = count;
    st.step.kept = right;
    st.step.kept_count = count;
    core_step_emit(&st, step, user);
    return CG_OK;
}

cg_status cg_cubic_steps(const cg_cubic2 *curve, int n, cg_step_fn step, void *user)
{
    if (!curve || !step || n < 1 || n > MAX_CUBIC_SAMPLES || !curve_points_finite(curve->g, 4)
        || (unsigned)curve->basis > CG_BASIS_CATMULL_ROM)
        return CG_EINVAL;
    cg_mat4 m = cg_curve_basis_matrix(curve->basis);
    cg_vec2 previous = cg_cubic2_point(curve, 0);
    for (int k = 0; k <= n; k++) {
        double t = (double)k / n, power[4] = {t * t * t, t * t, t, 1}, weight[4];
        static const char *const weight_names[4] = {"b1", "b2", "b3", "b4"};
        for (int j = 0; j < 4; j++) {
            weight[j] = 0;
            for (int i = 0; i < 4; i++)
                weight[j] += power[i] * m.m[i][j];
        }
        cg_vec2 q = cg_cubic2_point(curve, t), chord[2] = {previous, q};
        char t_row[128];
        snprintf(t_row, sizeof t_row, "[%.6g %.6g %.6g 1]", power[0], power[1], power[2]);
        core_step st;
        core_step_begin(&st, cg_curve_basis_name(curve->basis));
        core_step_integer(&st, "k", k);
        core_step_real(&st, "t", t);
        core_step_text(&st, "T", t_row);
        for (int j = 0; j < 4; j++)
            core_step_real(&st, weight_names[j], weight[j]);
        core_step_point(&st, "Q", q);
        st.step.geometry = &chord[1];
        st.step.geometry_count = 1;
        st.step.kept = chord;
        st.step.kept_count = k ? 2 : 1;
        if (core_step_emit(&st, step, user))
            break;
        previous = q;
    }
    return CG_OK;
}

/* ---- flattening ------------------------------------------------------------ */

typedef struct flatten_trace {
    int count, max_depth;
    double tolerance, tolerance2;
    cg_vec2 last; /* the polyline's last point so far */
    long steps;
    cg_step_fn fn;
    void *user;
    int stopped;
} flatten_trace;

/* Why the piece c over [t0, t1] is emitted or split, as cg_bezier_flatten
 * decides it (flatten.c): flat when every inner control point is within
 * the tolerance of the chord. */
static cg_status trace_piece(flatten_trace *f, const cg_vec2 *c, int depth, double t0, double t1)
{
    if (f->stopped)
        return CG_OK;
    if (++f->steps > MAX_FLATTEN_STEPS)
        return CG_ERANGE;
    double worst2 = 0;
    int worst = -1, flat = 1;
    for (int i = 1; i < f->count - 1; i++) {
        double d2 = curve_distance2_to_segment(c[i], c[0], c[f->count - 1]);
        if (!(d2 <= f->tolerance2))
            flat = 0;
        if (worst < 0 || d2 > worst2) {
            worst2 = d2;
            worst = i;
        }
    }
    int emit = depth >= f->max_depth || flat;
    char reason[160];
    if (flat)
        snprintf(reason, sizeof reason, "flat: every control point within %g of the chord",
                 f->tolerance);
    else if (emit)
        snprintf(reason, sizeof reason, "deepest level %d reached: the chord is within %g",
                 f->max_depth, f->tolerance);
    else
        snprintf(reason, sizeof reason, "control point %d is %g from the chord: split at 1/2",
                 worst, sqrt(worst2));
    core_step st;
    cg_vec2 chord[2] = {f->last, c[f->count - 1]};
    core_step_begin(&st, "pieces");
    core_step_integer(&st, "depth", depth);
    core_step_real(&st, "t0", t0);
    core_step_real(&st, "t1", t1);
    if (worst >= 0)
        core_step_real(&st, "distance", sqrt(worst2));
    else
        core_step_none(&st, "distance");
    core_step_text(&st, "decision", emit ? "emit" : "split");
    core_step_text(&st, "why", reason);
    if (emit)
        core_step_point(&st, "point", c[f->count - 1]);
    else
        core_step_none(&st, "point");
    st.step.geometry = c;
    st.step.geometry_count = f->count;
    if (emit) {
        st.step.kept = chord;
        st.step.kept_count = 2;
    }
    if (core_step_emit(&st, f->fn, f->user)) {
        f->stopped = 1;
        return CG_OK;
    }
    if (emit) {
        f->last = c[f->count - 1];
        return CG_OK;
    }
    cg_vec2 *halves = malloc((size_t)f->count * 3 * sizeof *halves);
    if (!halves)
        return CG_ENOMEM;
    cg_vec2 *work = halves, *left = halves + f->count, *right = left + f->count;
    memcpy(work, c, (size_t)f->count * sizeof *c);
    curve_casteljau(work, f->count, 0.5, left, right);
    double middle = 0.5 * (t0 + t1);
    cg_status status = trace_piece(f, left, depth + 1, t0, middle);
    if (status == CG_OK)
        status = trace_piece(f, right, depth + 1, middle, t1);
    free(halves);
    return status;
}

cg_status cg_bezier_flatten_steps(const cg_vec2 *control, int count, double tolerance,
                                  cg_step_fn step, void *user)
{
    if (!control || !step || count < 2 || count > CG_BEZIER_MAX_POINTS || !(tolerance > 0)
        || !isfinite(tolerance) || !curve_points_finite(control, count))
        return CG_EINVAL;
    int depth;
    cg_status status = curve_flatten_depth(control, count, tolerance, &depth);
    if (status != CG_OK)
        return status;
    flatten_trace f = {count, depth, tolerance, tolerance * tolerance, control[0], 0,
                       step,  user,  0};
    return trace_piece(&f, control, 0, 0, 1);
}
