/* The viewing pipeline of chapters 3-4 step by step (cg/trace_steps.h):
 * each matrix, their composite, and one point carried through them in
 * homogeneous coordinates, before and after the perspective divide, to the
 * viewport.
 *
 *   object --M--> world --V--> eye --P--> clip (x, y, z, w)
 *        --divide by w--> NDC [-1, 1]^3 --W (viewport)--> pixel (x, y), depth */
#include "cg/xform.h"
#include "../core/steps.h"

#include <math.h>

static void matrix_reals(cg_mat4 m, double out[16])
{
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            out[4 * r + c] = m.m[r][c];
}

static int emit_matrix(const char *name, const char *meaning, cg_mat4 m, cg_step_fn fn, void *user)
{
    double reals[16];
    matrix_reals(m, reals);
    core_step s;
    core_step_begin(&s, "matrices");
    core_step_text(&s, "matrix", name);
    core_step_text(&s, "meaning", meaning);
    core_step_reals(&s, "value", reals, 16);
    return core_step_emit(&s, fn, user);
}

static int emit_point(const char *space, const char *how, cg_vec4 p, cg_step_fn fn, void *user)
{
    double reals[4] = {p.x, p.y, p.z, p.w};
    core_step s;
    core_step_begin(&s, "point");
    core_step_text(&s, "space", space);
    core_step_text(&s, "how", how);
    core_step_reals(&s, "coordinates", reals, 4);
    return core_step_emit(&s, fn, user);
}

cg_status cg_pipeline_steps(cg_mat4 model, cg_mat4 view, cg_mat4 projection, int width, int height,
                            cg_vec3 point, cg_step_fn step, void *user)
{
    if (!step || width <= 0 || height <= 0 || !isfinite(point.x) || !isfinite(point.y)
        || !isfinite(point.z))
        return CG_EINVAL;
    cg_mat4 viewport = cg_viewport(width, height);
    cg_mat4 composite = cg_mat4_mul(projection, cg_mat4_mul(view, model));
    cg_mat4 whole = cg_mat4_mul(viewport, composite);
    if (emit_matrix("M", "model: object to world", model, step, user)
        || emit_matrix("V", "view: world to eye (eye at the origin, looking down -z)", view, step,
                       user)
        || emit_matrix("P", "projection: eye to clip coordinates", projection, step, user)
        || emit_matrix("P V M", "the composite, applied once per point", composite, step, user)
        || emit_matrix("W", "viewport: NDC [-1, 1] to pixels, y down, depth to [0, 1]", viewport,
                       step, user)
        || emit_matrix("W P V M", "everything, as cg_project_point takes it", whole, step, user))
        return CG_OK;
    cg_vec4 object = cg_vec4_from_point(point);
    cg_vec4 world = cg_mat4_mul_vec4(model, object);
    cg_vec4 eye = cg_mat4_mul_vec4(view, world);
    cg_vec4 clip = cg_mat4_mul_vec4(projection, eye);
    if (emit_point("object", "(x, y, z, 1)", object, step, user)
        || emit_point("world", "M times object", world, step, user)
        || emit_point("eye", "V times world", eye, step, user)
        || emit_point("clip",
                      "P times eye (homogeneous: w is the depth -z_eye for a "
                      "perspective)",
                      clip, step, user))
        return CG_OK;
    if (!(clip.w > 0)) {
        core_step s;
        core_step_begin(&s, "point");
        core_step_text(&s, "space", "ndc");
        core_step_text(&s, "how", "w <= 0: the point is behind the camera, no divide");
        core_step_none(&s, "coordinates");
        core_step_emit(&s, step, user);
        return CG_OK;
    }
    cg_vec4 ndc = cg_vec4_make(clip.x / clip.w, clip.y / clip.w, clip.z / clip.w, 1);
    int inside = fabs(ndc.x) <= 1 && fabs(ndc.y) <= 1 && fabs(ndc.z) <= 1;
    cg_vec4 window = cg_mat4_mul_vec4(viewport, ndc);
    if (emit_point("ndc",
                   inside ? "clip / w: inside the view volume [-1, 1]^3"
                          : "clip / w: outside the view volume, clipped away",
                   ndc, step, user))
        return CG_OK;
    core_step s;
    double reals[4] = {window.x, window.y, window.z, window.w};
    core_step_begin(&s, "point");
    core_step_text(&s, "space", "window");
    core_step_text(&s, "how",
                   "W times ndc: x, y in pixels (pixel floor(x), floor(y)), z the "
                   "depth");
    core_step_reals(&s, "coordinates", reals, 4);
    int xy[2] = {(int)floor(window.x), (int)floor(window.y)};
    if (inside && fabs(window.x) < 1e9 && fabs(window.y) < 1e9) {
        s.step.pixels = xy;
        s.step.pixel_count = 1;
    }
    core_step_emit(&s, step, user);
    return CG_OK;
}

cg_status cg_vanishing_point_steps(cg_mat4 view, cg_mat4 projection, int width, int height,
                                   cg_vec3 direction, cg_step_fn step, void *user)
{
    if (!step || width <= 0 || height <= 0 || !isfinite(direction.x) || !isfinite(direction.y)
        || !isfinite(direction.z) || !(cg_vec3_length(direction) > 0))
        return CG_EINVAL;
    cg_mat4 viewport = cg_viewport(width, height);
    cg_vec4 at_infinity = cg_vec4_make(direction.x, direction.y, direction.z, 0);
    cg_vec4 eye = cg_mat4_mul_vec4(view, at_infinity);
    cg_vec4 clip = cg_mat4_mul_vec4(projection, eye);
    if (emit_point("direction",
                   "the point at infinity (dx, dy, dz, 0) all lines of this "
                   "direction meet",
                   at_infinity, step, user)
        || emit_point("eye", "V times it (w stays 0: a translation cannot move it)", eye, step,
                      user)
        || emit_point("clip", "P times eye: w = -z_eye, the depth of the direction", clip, step,
                      user))
        return CG_OK;
    if (!(clip.w > 0)) {
        core_step s;
        core_step_begin(&s, "point");
        core_step_text(&s, "space", "ndc");
        core_step_text(&s, "how",
                       clip.w == 0 ? "w = 0: the lines are parallel to the image "
                                     "plane and stay parallel (no vanishing point)"
                                   : "w < 0: the lines recede behind the camera (no "
                                     "vanishing point in front)");
        core_step_none(&s, "coordinates");
        core_step_emit(&s, step, user);
        return CG_OK;
    }
    cg_vec4 ndc = cg_vec4_make(clip.x / clip.w, clip.y / clip.w, clip.z / clip.w, 1);
    cg_vec4 window = cg_mat4_mul_vec4(viewport, ndc);
    if (emit_point("ndc", "clip / w (z > 1: beyond the far plane, as a point at infinity is)", ndc,
                   step, user))
        return CG_OK;
    core_step s;
    double reals[4] = {window.x, window.y, window.z, window.w};
    core_step_begin(&s, "point");
    core_step_text(&s, "space", "window");
    core_step_text(&s, "how", "W times ndc: the vanishing point in pixels");
    core_step_reals(&s, "coordinates", reals, 4);
    int xy[2] = {(int)floor(window.x), (int)floor(window.y)};
    if (fabs(window.x) < 1e9 && fabs(window.y) < 1e9 && window.x >= 0 && window.y >= 0
        && window.x < width && window.y < height) {
        s.step.pixels = xy;
        s.step.pixel_count = 1;
    }
    core_step_emit(&s, step, user);
    return CG_OK;
}
