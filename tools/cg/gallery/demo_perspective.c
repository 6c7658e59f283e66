/* Gallery: one-, two- and three-point perspective (section 3.1.2), made by
 * placing the camera, with the look-at view matrix and a frustum. */
#include "demo.h"
#include "wireframe.h"
#include "cg/xform.h"

static cg_mat4 camera(cg_vec3 eye, cg_vec3 target, double fovy_degrees)
{
    cg_mat4 view, projection;
    cg_view_look_at(eye, target, cg_vec3_make(0, 1, 0), &view);
    cg_proj_perspective(cg_radians(fovy_degrees), 4.0 / 3.0, 0.1, 100, &projection);
    return cg_mat4_mul(projection, view);
}

static int render(demo_context *context)
{
    wire_view views[] = {
        {"perspective-1point.png",
         "One-point perspective: the camera faces the fronts squarely; only depth edges (blue) "
         "converge",
         camera(cg_vec3_make(0, 1.2, 3.2), cg_vec3_make(0, 1.2, 0), 60)},
        {"perspective-2point.png",
         "Two-point perspective: camera turned about the vertical, level view; verticals stay "
         "parallel",
         camera(cg_vec3_make(2.6, 0.5, 2.6), cg_vec3_make(0, 0.5, 0), 60)},
        {"perspective-3point.png",
         "Three-point perspective: camera turned and looking down; all three families converge",
         camera(cg_vec3_make(2.4, 3.6, 2.4), cg_vec3_make(0, 0, 0), 60)},
    };
    return wire_render_views(context, views, (int)(sizeof views / sizeof views[0]));
}

const demo_section demo_section_perspective = {3, "Perspective projections", render};
