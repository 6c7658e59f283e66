/* 3D transformations as 4x4 homogeneous matrices (section 4.4). */
#include "cg/xform.h"

cg_mat4 cg_xform3_translate(double tx, double ty, double tz)
{
    cg_mat4 m = cg_mat4_identity();
    m.m[0][3] = tx;
    m.m[1][3] = ty;
    m.m[2][3] = tz;
    return m;
}

cg_mat4 cg_xform3_scale(double sx, double sy, double sz, cg_vec3 center)
{
    cg_mat4 m = cg_mat4_identity();
    m.m[0][0] = sx;
    m.m[1][1] = sy;
    m.m[2][2] = sz;
    m.m[0][3] = center.x * (1 - sx);
    m.m[1][3] = center.y * (1 - sy);
    m.m[2][3] = center.z * (1 - sz);
    return m;
}

cg_mat4 cg_xform3_rotate_x(double angle)
{
    double c = cos(angle), s = sin(angle);
    cg_mat4 m = {{{1, 0, 0, 0}, {0, c, -s, 0}, {0, s, c, 0}, {0, 0, 0, 1}}};
    return m;
}

cg_mat4 cg_xform3_rotate_y(double angle)
{
    double c = cos(angle), s = sin(angle);
    cg_mat4 m = {{{c, 0, s, 0}, {0, 1, 0, 0}, {-s, 0, c, 0}, {0, 0, 0, 1}}};
    return m;
}

cg_mat4 cg_xform3_rotate_z(double angle)
{
    double c = cos(angle), s = sin(angle);
    cg_mat4 m = {{{c, -s, 0, 0}, {s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    return m;
}

static int finite_vec3(cg_vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

/* Makes the 3x3 linear part act about point p instead of the origin:
 * the translation column becomes p - L p. */
static void fix_point(cg_mat4 *m, cg_vec3 p)
{
    cg_vec3 lp = cg_mat4_transform_vector(*m, p);
    m->m[0][3] = p.x - lp.x;
    m->m[1][3] = p.y - lp.y;
    m->m[2][3] = p.z - lp.z;
}

cg_status cg_xform3_rotate_axis(cg_vec3 axis, double angle, cg_vec3 point, cg_mat4 *out)
{
    double length = cg_vec3_length(axis);
    if (!out || !(length > 0) || !isfinite(length) || !finite_vec3(point) || !isfinite(angle))
        return CG_EINVAL;
    cg_vec3 u = cg_vec3_scale(axis, 1.0 / length);
    double c = cos(angle), s = sin(angle), t = 1 - c;
    cg_mat4 m = {{{t * u.x * u.x + c, t * u.x * u.y - s * u.z, t * u.x * u.z + s * u.y, 0},
                  {t * u.x * u.y + s * u.z, t * u.y * u.y + c, t * u.y * u.z - s * u.x, 0},
                  {t * u.x * u.z - s * u.y, t * u.y * u.z + s * u.x, t * u.z * u.z + c, 0},
                  {0, 0, 0, 1}}};
    fix_point(&m, point);
    *out = m;
    return CG_OK;
}

cg_status cg_xform3_reflect(cg_vec3 point, cg_vec3 normal, cg_mat4 *out)
{
    double length = cg_vec3_length(normal);
    if (!out || !(length > 0) || !isfinite(length) || !finite_vec3(point))
        return CG_EINVAL;
    cg_vec3 n = cg_vec3_scale(normal, 1.0 / length);
    /* Householder: I - 2 n n^T about the plane through point. */
    cg_mat4 m = {{{1 - 2 * n.x * n.x, -2 * n.x * n.y, -2 * n.x * n.z, 0},
                  {-2 * n.x * n.y, 1 - 2 * n.y * n.y, -2 * n.y * n.z, 0},
                  {-2 * n.x * n.z, -2 * n.y * n.z, 1 - 2 * n.z * n.z, 0},
                  {0, 0, 0, 1}}};
    fix_point(&m, point);
    *out = m;
    return CG_OK;
}

cg_mat4 cg_xform3_shear(double xy, double xz, double yx, double yz, double zx, double zy)
{
    cg_mat4 m = {{{1, xy, xz, 0}, {yx, 1, yz, 0}, {zx, zy, 1, 0}, {0, 0, 0, 1}}};
    return m;
}
