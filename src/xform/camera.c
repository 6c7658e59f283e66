/* The look-at view matrix and the viewport mapping. */
#include "cg/xform.h"

cg_status cg_view_look_at(cg_vec3 eye, cg_vec3 target, cg_vec3 up, cg_mat4 *out)
{
    cg_vec3 forward = cg_vec3_sub(target, eye);
    double distance = cg_vec3_length(forward);
    if (!out || !(distance > 0) || !isfinite(distance))
        return CG_EINVAL;
    forward = cg_vec3_scale(forward, 1.0 / distance);
    cg_vec3 side = cg_vec3_cross(forward, up);
    double side_length = cg_vec3_length(side);
    /* up parallel to the viewing direction (or zero) leaves no roll defined. */
    if (!(side_length > 1e-12 * cg_vec3_length(up)) || !isfinite(side_length))
        return CG_EINVAL;
    side = cg_vec3_scale(side, 1.0 / side_length);
    cg_vec3 true_up = cg_vec3_cross(side, forward);
    cg_mat4 m = {{{side.x, side.y, side.z, -cg_vec3_dot(side, eye)},
                  {true_up.x, true_up.y, true_up.z, -cg_vec3_dot(true_up, eye)},
                  {-forward.x, -forward.y, -forward.z, cg_vec3_dot(forward, eye)},
                  {0, 0, 0, 1}}};
    *out = m;
    return CG_OK;
}

cg_mat4 cg_viewport(int width, int height)
{
    cg_mat4 m = {{{width / 2.0, 0, 0, width / 2.0},
                  {0, -height / 2.0, 0, height / 2.0},
                  {0, 0, 0.5, 0.5},
                  {0, 0, 0, 1}}};
    return m;
}

cg_vec3 cg_project_point(cg_mat4 transform, cg_vec3 point, int *visible)
{
    cg_vec4 h = cg_mat4_mul_vec4(transform, cg_vec4_from_point(point));
    if (visible)
        *visible = h.w > 0;
    if (!(h.w != 0))
        return cg_vec3_make(0, 0, 0);
    return cg_vec3_make(h.x / h.w, h.y / h.w, h.z / h.w);
}
