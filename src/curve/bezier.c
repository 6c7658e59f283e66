/* Bézier curves of any degree: Bernstein polynomials, de Casteljau's
 * evaluation and subdivision (section 2.3.3). */
#include "cg/curve.h"
#include "internal.h"

#include <stdlib.h>
#include <string.h>

double cg_bernstein(int n, int i, double t)
{
    if (n < 0 || i < 0 || i > n)
        return 0;
    /* C(n, i) t^i (1-t)^(n-i), the binomial built as a running product. */
    double c = 1;
    int k = i < n - i ? i : n - i;
    for (int j = 1; j <= k; j++)
        c = c * (n - k + j) / j;
    return c * pow(t, i) * pow(1 - t, n - i);
}

int curve_points_finite(const cg_vec2 *p, int count)
{
    for (int i = 0; i < count; i++)
        if (!isfinite(p[i].x) || !isfinite(p[i].y))
            return 0;
    return 1;
}

static int valid(const void *control, int count, int min)
{
    return control && count >= min && count <= CG_BEZIER_MAX_POINTS;
}

/* In-place de Casteljau on work[0..count-1]: afterwards work[0] is Q(t);
 * left/right (optional) receive the subdivided control polygons. */
void curve_casteljau(cg_vec2 *work, int count, double t, cg_vec2 *left, cg_vec2 *right)
{
    double s = 1 - t;
    for (int level = count - 1; level >= 0; level--) {
        if (left)
            left[count - 1 - level] = work[0];
        if (right)
            right[level] = work[level];
        for (int i = 0; i < level; i++)
            work[i] = cg_vec2_make(s * work[i].x + t * work[i + 1].x,
                                   s * work[i].y + t * work[i + 1].y);
    }
}

cg_status cg_bezier_point(const cg_vec2 *control, int count, double t, cg_vec2 *out)
{
    if (!valid(control, count, 1) || !out || !isfinite(t) || !curve_points_finite(control, count))
        return CG_EINVAL;
    cg_vec2 small[16], *work = count <= 16 ? small : malloc((size_t)count * sizeof *work);
    if (!work)
        return CG_ENOMEM;
    memcpy(work, control, (size_t)count * sizeof *work);
    curve_casteljau(work, count, t, NULL, NULL);
    *out = work[0];
    if (work != small)
        free(work);
    return CG_OK;
}

cg_status cg_bezier_tangent(const cg_vec2 *control, int count, double t, cg_vec2 *out)
{
    if (!valid(control, count, 2) || !out || !isfinite(t) || !curve_points_finite(control, count))
        return CG_EINVAL;
    /* Q'(t) = n * (the Bézier of the differences of the control points). */
    int n = count - 1;
    cg_vec2 small[16], *work = n <= 16 ? small : malloc((size_t)n * sizeof *work);
    if (!work)
        return CG_ENOMEM;
    for (int i = 0; i < n; i++)
        work[i] = cg_vec2_scale(cg_vec2_sub(control[i + 1], control[i]), n);
    curve_casteljau(work, n, t, NULL, NULL);
    *out = work[0];
    if (work != small)
        free(work);
    return CG_OK;
}

cg_status cg_bezier_point3(const cg_vec3 *control, int count, double t, cg_vec3 *out)
{
    if (!valid(control, count, 1) || !out || !isfinite(t))
        return CG_EINVAL;
    for (int i = 0; i < count; i++)
        if (!isfinite(control[i].x) || !isfinite(control[i].y) || !isfinite(control[i].z))
            return CG_EINVAL;
    cg_vec3 small[16], *work = count <= 16 ? small : malloc((size_t)count * sizeof *work);
    if (!work)
        return CG_ENOMEM;
    memcpy(work, control, (size_t)count * sizeof *work);
    double s = 1 - t;
    for (int level = count - 1; level > 0; level--)
        for (int i = 0; i < level; i++)
            work[i] = cg_vec3_add(cg_vec3_scale(work[i], s), cg_vec3_scale(work[i + 1], t));
    *out = work[0];
    if (work != small)
        free(work);
    return CG_OK;
}

cg_status cg_bezier_split(const cg_vec2 *control, int count, double t, cg_vec2 *left,
                          cg_vec2 *right)
{
    if (!valid(control, count, 1) || !isfinite(t) || !curve_points_finite(control, count))
        return CG_EINVAL;
    cg_vec2 small[16], *work = count <= 16 ? small : malloc((size_t)count * sizeof *work);
    if (!work)
        return CG_ENOMEM;
    memcpy(work, control, (size_t)count * sizeof *work);
    curve_casteljau(work, count, t, left, right);
    if (work != small)
        free(work);
    return CG_OK;
}
