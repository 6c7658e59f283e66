/* The settings shared by `cg render` and `cg trace-render` (see
 * render_options.h); render_request.c parses them. */
#include "render_options.h"

#include "cli.h"

#include <math.h>
#include <string.h>

void render_cli_options_default(render_cli_options *o)
{
    memset(o, 0, sizeof *o);
    o->size.width = 800;
    o->size.height = 600;
    o->eye = cg_vec3_make(0, 0, 1);
    o->up = cg_vec3_make(0, 1, 0);
    o->fov_degrees = 45;
    cg_render_options_default(&o->render);
    o->render.frame_camera = 0;
}

int render_cli_check_output(const char *command, const char *output)
{
    if (!output)
        return cli_usage_error(command, "expected -o OUT (.png, .ppm or .pgm)");
    if (cg_file_format_from_path(output) == CG_FILE_UNKNOWN)
        return cli_usage_error(command, "%s: unknown output format (expected .png, .ppm or .pgm)",
                               output);
    return CLI_OK;
}

int render_cli_set_depth(const char *command, const render_cli_options *o, int bounded, cg_vec3 lo,
                         cg_vec3 hi, cg_camera *camera)
{
    if (bounded)
        cg_camera_fit_depth(camera, lo, hi); /* the camera was checked: it cannot fail */
    if (o->have_near)
        camera->near = o->near;
    if (o->have_far)
        camera->far = o->far;
    if (!camera->orthographic && !(camera->near > 0))
        return cli_usage_error(command,
                               "--near: expected a distance > 0 for a perspective view, "
                               "got %g",
                               camera->near);
    if (!(camera->far > camera->near))
        return cli_usage_error(command, "--far: expected a distance greater than near (%g), got %g",
                               camera->near, camera->far);
    return CLI_OK;
}
