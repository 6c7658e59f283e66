/* 2D transformations as 3x3 homogeneous matrices (section 4.1-4.3). */
#include "cg/xform.h"

cg_mat3 cg_xform2_translate(double tx, double ty)
{
    cg_mat3 m = {{{1, 0, tx}, {0, 1, ty}, {0, 0, 1}}};
    return m;
}

cg_mat3 cg_xform2_scale(double sx, double sy, double cx, double cy)
{
    /* T(c) S T(-c) written out: the fixed point c stays where it is. */
    cg_mat3 m = {{{sx, 0, cx * (1 - sx)}, {0, sy, cy * (1 - sy)}, {0, 0, 1}}};
    return m;
}

cg_mat3 cg_xform2_rotate(double angle, double cx, double cy)
{
    double c = cos(angle), s = sin(angle);
    cg_mat3 m = {{{c, -s, cx - c * cx + s * cy}, {s, c, cy - s * cx - c * cy}, {0, 0, 1}}};
    return m;
}

cg_status cg_xform2_reflect(cg_vec2 point, cg_vec2 direction, cg_mat3 *out)
{
    double length = cg_vec2_length(direction);
    if (!out || !(length > 0) || !isfinite(length) || !isfinite(point.x) || !isfinite(point.y))
        return CG_EINVAL;
    double ux = direction.x / length, uy = direction.y / length;
    /* Householder reflection across the line: I - 2 n n^T with n the normal,
     * which equals 2 u u^T - I with u the unit direction. */
    double a = 2 * ux * ux - 1, b = 2 * ux * uy, d = 2 * uy * uy - 1;
    cg_mat3 m = {{{a, b, point.x - a * point.x - b * point.y},
                  {b, d, point.y - b * point.x - d * point.y},
                  {0, 0, 1}}};
    *out = m;
    return CG_OK;
}

cg_mat3 cg_xform2_shear(double shx, double shy)
{
    cg_mat3 m = {{{1, shx, 0}, {shy, 1, 0}, {0, 0, 1}}};
    return m;
}
