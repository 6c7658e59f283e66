/* The camera shared by the rasterizer and the ray tracer. */
#include "cg/xform.h"

cg_camera cg_camera_default(void)
{
    cg_camera c;
    c.eye = cg_vec3_make(0, 0, 5);
    c.target = cg_vec3_make(0, 0, 0);
    c.up = cg_vec3_make(0, 1, 0);
    c.orthographic = 0;
    c.fovy = cg_radians(45);
    c.ortho_height = 2;
    c.near = 0.1;
    c.far = 100;
    return c;
}

cg_status cg_camera_view(const cg_camera *camera, cg_mat4 *out)
{
    if (!camera)
        return CG_EINVAL;
    return cg_view_look_at(camera->eye, camera->target, camera->up, out);
}

cg_status cg_camera_projection(const cg_camera *camera, double aspect, cg_mat4 *out)
{
    if (!camera || !(aspect > 0) || !isfinite(aspect))
        return CG_EINVAL;
    if (camera->orthographic) {
        double h = camera->ortho_height / 2, w = h * aspect;
        if (!(h > 0))
            return CG_EINVAL;
        return cg_proj_orthographic(-w, w, -h, h, camera->near, camera->far, out);
    }
    return cg_proj_perspective(camera->fovy, aspect, camera->near, camera->far, out);
}

cg_status cg_camera_ray(const cg_camera *camera, int width, int height, double x, double y,
                        cg_vec3 *origin, cg_vec3 *direction)
{
    if (!camera || !origin || !direction || width <= 0 || height <= 0 || !isfinite(x)
        || !isfinite(y))
        return CG_EINVAL;
    cg_mat4 view, inverse_view;
    cg_status status = cg_camera_view(camera, &view);
    if (status != CG_OK)
        return status;
    if ((status = cg_mat4_inverse(view, &inverse_view)) != CG_OK)
        return status;
    double aspect = (double)width / height;
    /* Pixel to NDC, the inverse of cg_viewport. */
    double nx = 2 * x / width - 1, ny = 1 - 2 * y / height;
    cg_vec3 o, d;
    if (camera->orthographic) {
        double h = camera->ortho_height / 2;
        o = cg_vec3_make(nx * h * aspect, ny * h, -camera->near);
        d = cg_vec3_make(0, 0, -1);
    } else {
        double t = tan(camera->fovy / 2);
        o = cg_vec3_make(0, 0, 0);
        d = cg_vec3_normalize(cg_vec3_make(nx * t * aspect, ny * t, -1));
    }
    *origin = cg_mat4_transform_point(inverse_view, o);
    *direction = cg_vec3_normalize(cg_mat4_transform_vector(inverse_view, d));
    return CG_OK;
}
