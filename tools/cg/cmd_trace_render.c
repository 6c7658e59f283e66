/* cg trace-render MESH -o OUT.png: the alias of `cg render --algorithm raytrace`
 * (render_command.c). */
#include "command.h"
#include "render_command.h"
#include "render_request.h"

static int run(int argc, char **argv)
{
    return render_command_run("trace-render", argc, argv, 1);
}

static const cli_syntax *const trace_render_syntaxes[] = {&render_syntax, NULL};

const cg_command cg_command_trace_render = {
    "trace-render",
    "render a mesh or the classic scene by ray tracing",
    "usage: cg trace-render MESH -o OUT.png [options]\n"
    "       cg trace-render SCENE.json -o OUT.png [options]\n"
    "       cg trace-render --scene spheres -o OUT.png [options]\n\n"
    "Whitted ray tracing through a BVH: shadows, mirror reflection, refraction with\n"
    "Fresnel; the mesh (OBJ, OFF, PLY, STL) or the built-in scene 'spheres' (glass\n"
    "and mirror spheres over a checkered plane, soft shadows from an area light).\n"
    "This command is 'cg render --algorithm raytrace': the same options with the\n"
    "same meaning and the same pictures, byte for byte (see 'cg help render').\n"
    "A scene file (docs/scene-format.md) is ray traced with its own camera,\n"
    "lights and materials; the options given override them as for 'cg render'.\n",
    run,
    trace_render_syntaxes,
};
