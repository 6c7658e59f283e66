/* cg render MESH|SCENE.json -o OUT: the rasterizing pipeline (z-buffer or painter's) or
 * the ray tracer on a mesh or scene file (render_command.c does the work). */
#include "command.h"
#include "render_command.h"
#include "render_request.h"

#define NAME "render"

static int run(int argc, char **argv)
{
    return render_command_run(NAME, argc, argv, 0);
}

static const cli_syntax *const render_syntaxes[] = {&render_syntax, NULL};

const cg_command cg_command_render = {
    NAME,
    "render a mesh or scene file: z-buffer, painter's or ray tracing",
    "usage: cg render MESH -o OUT [options]\n"
    "       cg render SCENE.json -o OUT [options]\n"
    "       cg render --scene spheres --algorithm raytrace -o OUT [options]\n"
    "       cg render MESH --algorithm pathtrace --spp N -o OUT [path tracer options]\n\n"
    "Renders MESH (OBJ, PLY, OFF or STL, optionally gzip-compressed) and writes\n"
    "OUT in the format of its extension (.png, .ppm, .pgm).  A file with no faces\n"
    "is an error; a frame in which every face was culled gives a warning.\n"
    "A SCENE.json file (docs/scene-format.md) brings its own camera, lights,\n"
    "materials and objects; the options given override them: camera options\n"
    "replace the scene's camera, --light-dir its lights (ambient ones stay),\n"
    "--color, --ambient, --specular and --shininess set the default material.\n"
    "Options without a meaning for a scene (--crease, --edge-color,\n"
    "--output-depth, --floor, --scene, --stats) are refused, as are the ray\n"
    "tracer's options with another algorithm and the rasterizer's with it.\n"
    "'cg trace-render ...' is 'cg render --algorithm raytrace ...'.\n"
    "--algorithm pathtrace takes the path tracer's own options (listed in\n"
    "docs/pathtrace.md); its --tile and --sample-range parts go to cg merge.\n"
    "Frames that take longer than a second show their progress on stderr.\n",
    run,
    render_syntaxes,
};
