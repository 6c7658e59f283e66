/* Gallery: the parallel projections of section 3.1.1. */
#include "demo.h"
#include "wireframe.h"
#include "cg/xform.h"

static int render(demo_context *context)
{
    cg_mat4 dimetric, trimetric = cg_proj_axonometric(cg_radians(-25), cg_radians(20));
    cg_proj_dimetric(0.5, &dimetric);
    wire_view views[] = {
        {"parallel-front.png", "Orthographic front view (x right, y up)",
         cg_proj_view_rotation(CG_VIEW_FRONT)},
        {"parallel-top.png", "Orthographic top view (plan)", cg_proj_view_rotation(CG_VIEW_TOP)},
        {"parallel-side.png", "Orthographic side view (from +x)",
         cg_proj_view_rotation(CG_VIEW_SIDE)},
        {"parallel-isometric.png", "Isometric: all three axes foreshortened by sqrt(2/3)",
         cg_proj_isometric()},
        {"parallel-dimetric.png", "Dimetric: x and y equal, z foreshortened to half", dimetric},
        {"parallel-trimetric.png", "Trimetric: rotations of -25 deg about y and 20 deg about x",
         trimetric},
        {"parallel-cavalier.png", "Oblique cavalier at 45 deg: depth at full length",
         cg_proj_cavalier(cg_radians(45))},
        {"parallel-cabinet.png", "Oblique cabinet at 45 deg: depth at half length",
         cg_proj_cabinet(cg_radians(45))},
        {"parallel-oblique.png", "Oblique at 30 deg with foreshortening 0.75",
         cg_proj_oblique(cg_radians(30), 0.75)},
    };
    return wire_render_views(context, views, (int)(sizeof views / sizeof views[0]));
}

const demo_section demo_section_parallel = {3, "Parallel projections", render};
