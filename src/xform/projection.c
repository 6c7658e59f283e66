/* Parallel and perspective projections (chapter 3). */
#include "cg/xform.h"

static int finite6(double a, double b, double c, double d, double e, double f)
{
    return isfinite(a) && isfinite(b) && isfinite(c) && isfinite(d) && isfinite(e) && isfinite(f);
}

cg_status cg_proj_frustum(double left, double right, double bottom, double top, double near,
                          double far, cg_mat4 *out)
{
    if (!out || !finite6(left, right, bottom, top, near, far) || !(near > 0) || !(far > near)
        || !(right != left) || !(top != bottom))
        return CG_EINVAL;
    cg_mat4 m = {{{2 * near / (right - left), 0, (right + left) / (right - left), 0},
                  {0, 2 * near / (top - bottom), (top + bottom) / (top - bottom), 0},
                  {0, 0, -(far + near) / (far - near), -2 * far * near / (far - near)},
                  {0, 0, -1, 0}}};
    *out = m;
    return CG_OK;
}

cg_status cg_proj_perspective(double fovy, double aspect, double near, double far, cg_mat4 *out)
{
    if (!(fovy > 0) || !(fovy < CG_PI) || !(aspect > 0) || !isfinite(aspect))
        return CG_EINVAL;
    double top = near * tan(fovy / 2);
    return cg_proj_frustum(-top * aspect, top * aspect, -top, top, near, far, out);
}

cg_status cg_proj_orthographic(double left, double right, double bottom, double top, double near,
                               double far, cg_mat4 *out)
{
    if (!out || !finite6(left, right, bottom, top, near, far) || !(right != left)
        || !(top != bottom) || !(far != near))
        return CG_EINVAL;
    cg_mat4 m = {{{2 / (right - left), 0, 0, -(right + left) / (right - left)},
                  {0, 2 / (top - bottom), 0, -(top + bottom) / (top - bottom)},
                  {0, 0, -2 / (far - near), -(far + near) / (far - near)},
                  {0, 0, 0, 1}}};
    *out = m;
    return CG_OK;
}

cg_mat4 cg_proj_view_rotation(cg_ortho_view view)
{
    switch (view) {
    case CG_VIEW_TOP:
        /* Looking down: +y must come toward the viewer (+z). */
        return cg_xform3_rotate_x(CG_PI / 2);
    case CG_VIEW_SIDE:
        /* Looking from +x toward the origin: +x must come toward the viewer. */
        return cg_xform3_rotate_y(-CG_PI / 2);
    case CG_VIEW_FRONT:
    default: return cg_mat4_identity();
    }
}

cg_mat4 cg_proj_axonometric(double about_y, double about_x)
{
    return cg_mat4_mul(cg_xform3_rotate_x(about_x), cg_xform3_rotate_y(about_y));
}

cg_mat4 cg_proj_isometric(void)
{
    return cg_proj_axonometric(-CG_PI / 4, asin(tan(CG_PI / 6)));
}

cg_status cg_proj_dimetric(double z_ratio, cg_mat4 *out)
{
    if (!out || !(z_ratio > 0) || !(z_ratio < 1))
        return CG_EINVAL;
    /* With f the common factor of x and y: the squared factors of the three
     * axes of any rotation sum to 2, so 2 f^2 + (r f)^2 = 2.  Then
     * f_y = cos(about_x) and f_x^2 = 1 - sin^2(about_y) cos^2(about_x). */
    double f2 = 2.0 / (2.0 + z_ratio * z_ratio);
    double about_x = acos(sqrt(f2));
    double about_y = -asin(sqrt((1 - f2) / f2));
    *out = cg_proj_axonometric(about_y, about_x);
    return CG_OK;
}

cg_vec3 cg_proj_foreshortening(cg_mat4 p)
{
    /* Projected image of each unit axis: the x and y rows of the linear part. */
    return cg_vec3_make(hypot(p.m[0][0], p.m[1][0]), hypot(p.m[0][1], p.m[1][1]),
                        hypot(p.m[0][2], p.m[1][2]));
}

cg_mat4 cg_proj_oblique(double angle, double ratio)
{
    cg_mat4 m = cg_mat4_identity();
    m.m[0][2] = ratio * cos(angle);
    m.m[1][2] = ratio * sin(angle);
    return m;
}

cg_mat4 cg_proj_cavalier(double angle)
{
    return cg_proj_oblique(angle, 1.0);
}

cg_mat4 cg_proj_cabinet(double angle)
{
    return cg_proj_oblique(angle, 0.5);
}
