/* `cg render` and `cg trace-render`: parse once, then hand the request to the
 * path for its input and algorithm. */
#include "render_command.h"

#include "cli.h"
#include "pathtrace_command.h"
#include "render_mesh.h"
#include "render_request.h"
#include "render_scene.h"

int render_command_run(const char *command, int argc, char **argv, int trace_only)
{
    if (pathtrace_requested(argc, argv))
        return pathtrace_command_run(command, argc, argv);
    render_request r;
    int status = render_request_parse(command, argc, argv, trace_only, &r);
    if (status != CLI_OK)
        return status;
    const raytrace_settings *s = &r.trace;
    if (!s->input && !s->extra.classic_scene)
        return cli_usage_error(command,
                               r.algorithm == RENDER_RAYTRACE
                                   ? "expected a MESH file or --scene spheres (one of them)"
                                   : "expected a MESH file");
    if (render_cli_check_output(command, s->common.output) != CLI_OK)
        return CLI_USAGE;
    if (s->input && !s->extra.classic_scene && render_scene_is_scene(s->input))
        return render_scene_file(command, &r);
    if (r.algorithm == RENDER_RAYTRACE)
        return raytrace_run(command, s);
    return render_mesh_raster(command, &r);
}
