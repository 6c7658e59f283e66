/* `cg render --algorithm raytrace`: placeholder until the ray tracer is
 * built in (see render_raytrace.h for the contract this file fulfils). */
#include "render_raytrace.h"
#include "cli.h"

#include <stddef.h>

int render_raytrace_create(const cg_mesh *mesh, const cg_render_options *options,
                           render_raytracer **out)
{
    (void)mesh;
    (void)options;
    if (out)
        *out = NULL;
    return cli_fail("render: --algorithm raytrace is not available in this build "
                    "(use zbuffer or painter)");
}

int render_raytrace_draw(render_raytracer *tracer, cg_image *image)
{
    (void)tracer;
    (void)image;
    return cli_fail("render: --algorithm raytrace is not available in this build");
}

void render_raytrace_free(render_raytracer *tracer)
{
    (void)tracer;
}
