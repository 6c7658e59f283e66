/* Adaptive flattening of Bézier curves to polylines within a tolerance.
 *
 * The curve lies in the convex hull of its control points, so when every
 * control point is within tolerance of the chord (the segment from the first
 * to the last control point) the curve is too, and since the curve runs
 * continuously from one end of the chord to the other, every chord point is
 * within tolerance of the curve as well.  Otherwise the curve is split at
 * t = 1/2 by de Casteljau and both halves are flattened in turn.
 *
 * Halving divides the second differences of the control polygon by 4, which
 * bounds the depth in advance: a control polygon whose second differences are
 * at most M lies within n^2 M / 8 of its chord.  That bound decides the
 * deepest level (so floating-point rounding can never make the recursion run
 * away) and rejects tolerances that would need more than 2^24 segments. */
#include "cg/curve.h"
#include "internal.h"

#include <stdlib.h>
#include <string.h>

enum { MAX_SEGMENTS_LOG2 = 24 };

typedef struct flattener {
    int count;
    double tolerance2;
    int max_depth;
    cg_vec2 *levels; /* per depth: left and right halves, count points each */
    cg_vec2 *work;
    cg_point_sink sink;
    void *user;
} flattener;

double curve_distance2_to_segment(cg_vec2 p, cg_vec2 a, cg_vec2 b)
{
    cg_vec2 d = cg_vec2_sub(b, a), ap = cg_vec2_sub(p, a);
    double l2 = cg_vec2_dot(d, d);
    if (l2 > 0) {
        double s = cg_vec2_dot(ap, d) / l2;
        s = s < 0 ? 0 : s > 1 ? 1 : s;
        ap = cg_vec2_sub(ap, cg_vec2_scale(d, s));
    }
    return cg_vec2_dot(ap, ap);
}

static int flat(const flattener *f, const cg_vec2 *c)
{
    for (int i = 1; i < f->count - 1; i++)
        if (!(curve_distance2_to_segment(c[i], c[0], c[f->count - 1]) <= f->tolerance2))
            return 0;
    return 1;
}

static cg_status flatten(flattener *f, const cg_vec2 *c, int depth)
{
    if (depth >= f->max_depth || flat(f, c))
        return f->sink(f->user, c[f->count - 1]);
    cg_vec2 *left = f->levels + (size_t)depth * 2 * (size_t)f->count, *right = left + f->count;
    memcpy(f->work, c, (size_t)f->count * sizeof *c);
    curve_casteljau(f->work, f->count, 0.5, left, right);
    cg_status status = flatten(f, left, depth + 1);
    return status != CG_OK ? status : flatten(f, right, depth + 1);
}

/* The deepest level of halving the curve may need (see the top). */
cg_status curve_flatten_depth(const cg_vec2 *control, int count, double tolerance, int *out)
{
    double second = 0, scale = 0;
    for (int i = 0; i < count; i++) {
        scale = fmax(scale, fmax(fabs(control[i].x), fabs(control[i].y)));
        if (i + 2 < count) {
            cg_vec2 d = cg_vec2_add(cg_vec2_sub(control[i + 2], cg_vec2_scale(control[i + 1], 2)),
                                    control[i]);
            second = fmax(second, cg_vec2_length(d));
        }
    }
    if (!isfinite(second) || tolerance < scale * 1e-12)
        return CG_ERANGE;
    /* Depth d suffices once n^2 M / 8 / 4^d <= tolerance. */
    double n = count - 1, ratio = n * n * second / (8 * tolerance);
    int depth = 0;
    while (ratio > 1 && depth <= MAX_SEGMENTS_LOG2) {
        ratio /= 4;
        depth++;
    }
    if (depth > MAX_SEGMENTS_LOG2)
        return CG_ERANGE;
    *out = depth;
    return CG_OK;
}

cg_status cg_bezier_flatten(const cg_vec2 *control, int count, double tolerance, cg_point_sink sink,
                            void *user)
{
    if (!control || !sink || count < 2 || count > CG_BEZIER_MAX_POINTS || !(tolerance > 0)
        || !isfinite(tolerance) || !curve_points_finite(control, count))
        return CG_EINVAL;
    int depth;
    cg_status depth_status = curve_flatten_depth(control, count, tolerance, &depth);
    if (depth_status != CG_OK)
        return depth_status;
    flattener f = {count, tolerance * tolerance, depth, NULL, NULL, sink, user};
    size_t points = ((size_t)depth * 2 + 1) * (size_t)count;
    cg_vec2 small[256], *buffer = points <= 256 ? small : malloc(points * sizeof *buffer);
    if (!buffer)
        return CG_ENOMEM;
    f.work = buffer;
    f.levels = buffer + count;
    cg_status status = flatten(&f, control, 0);
    if (buffer != small)
        free(buffer);
    return status;
}

cg_status cg_cubic2_flatten(const cg_cubic2 *curve, double tolerance, cg_point_sink sink,
                            void *user)
{
    cg_cubic2 bezier;
    if (!curve)
        return CG_EINVAL;
    cg_status status = cg_cubic2_convert(curve, CG_BASIS_BEZIER, &bezier);
    if (status != CG_OK)
        return status;
    return cg_bezier_flatten(bezier.g, 4, tolerance, sink, user);
}
