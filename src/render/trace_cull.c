/* Back-face culling (5.1) step by step (cg/trace_steps.h): for each
 * triangle of the mesh (faces fan-triangulated, as the renderer does), its
 * normal N = (v1 - v0) x (v2 - v0) in world space, the view vector V from
 * v0 toward the eye (for a parallel camera: the direction opposite the
 * view), and the sign of N.V:
 *
 *          N ^            eye
 *            |          /
 *            |        / V        N.V > 0: the face turns toward the eye
 *     v0 ----+------/----- v1    (front, kept); N.V <= 0: a back face,
 *                                culled
 *
 * Counter-clockwise faces seen from outside have outward normals. */
#include "cg/render.h"
#include "cg/xform.h"
#include "../core/steps.h"

#include <stdlib.h>

cg_status cg_backface_steps(const cg_mesh *mesh, cg_mat4 model, const cg_camera *camera,
                            cg_step_fn step, void *user)
{
    if (!mesh || !camera || !step)
        return CG_EINVAL;
    cg_status status = cg_mesh_validate(mesh, NULL);
    if (status != CG_OK)
        return status;
    cg_mat4 view;
    if (cg_camera_view(camera, &view) != CG_OK)
        return CG_EINVAL;
    size_t count = cg_mesh_triangle_count(mesh);
    uint32_t(*triangles)[3] = malloc((count ? count : 1) * sizeof *triangles);
    size_t *face_of = malloc((count ? count : 1) * sizeof *face_of);
    if (!triangles || !face_of) {
        free(triangles);
        free(face_of);
        return CG_ENOMEM;
    }
    /* triangles[] holds corner numbers (positions in face_indices) */
    for (size_t f = 0, t = 0; f < mesh->face_count; f++) {
        size_t corners = cg_mesh_face_size(mesh, f);
        if (corners >= 3 && cg_mesh_triangulate_face(mesh, f, triangles + t) == CG_OK)
            for (size_t k = 0; k + 2 < corners; k++)
                face_of[t++] = f;
    }
    cg_vec3 forward = cg_vec3_sub(camera->target, camera->eye);
    size_t culled = 0;
    for (size_t t = 0; t < count; t++) {
        cg_vec3 v[3];
        for (int k = 0; k < 3; k++)
            v[k] = cg_mat4_transform_point(model,
                                           mesh->positions[mesh->face_indices[triangles[t][k]]]);
        cg_vec3 normal = cg_vec3_cross(cg_vec3_sub(v[1], v[0]), cg_vec3_sub(v[2], v[0]));
        cg_vec3 to_eye = camera->orthographic ? cg_vec3_scale(forward, -1)
                                              : cg_vec3_sub(camera->eye, v[0]);
        double dot = cg_vec3_dot(normal, to_eye);
        int back = !(dot > 0);
        culled += back;
        double n[3] = {normal.x, normal.y, normal.z}, e[3] = {to_eye.x, to_eye.y, to_eye.z};
        /* The triangle as the camera sees it, for the frames: view-space x
         * and y, divided by the depth for a perspective camera; closed. */
        cg_vec2 outline[4];
        for (int k = 0; k < 3; k++) {
            cg_vec3 e3 = cg_mat4_transform_point(view, v[k]);
            double depth = camera->orthographic || !(e3.z < 0) ? 1 : -e3.z;
            outline[k] = cg_vec2_make(e3.x / depth, e3.y / depth);
        }
        outline[3] = outline[0];
        core_step s;
        core_step_begin(&s, "triangles");
        core_step_integer(&s, "triangle", (long long)t);
        core_step_integer(&s, "face", (long long)face_of[t]);
        core_step_reals(&s, "N", n, 3);
        core_step_reals(&s, "V", e, 3);
        core_step_real(&s, "N.V", dot);
        core_step_text(&s, "decision", back ? "back: culled" : "front: kept");
        core_step_integer(&s, "culled_so_far", (long long)culled);
        s.step.geometry = outline;
        s.step.geometry_count = 3;
        s.step.closed = 1;
        if (!back) {
            s.step.kept = outline;
            s.step.kept_count = 4;
        }
        if (core_step_emit(&s, step, user))
            break;
    }
    free(triangles);
    free(face_of);
    return CG_OK;
}
