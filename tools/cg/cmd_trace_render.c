/* cg trace-render MESH -o OUT.png: the ray tracer (see trace_command.c). */
#include "cli.h"
#include "command.h"
#include "trace_command.h"

static int run(int argc, char **argv)
{
    raytrace_settings s;
    raytrace_settings_default(&s);
    for (int i = 1; i < argc; i++) {
        if (!cli_is_option(argv[i])) {
            if (s.input)
                return cli_usage_error("trace-render", "expected one mesh file, got '%s' as a second",
                                       argv[i]);
            s.input = argv[i];
            continue;
        }
        int r = raytrace_parse_option("trace-render", argc, argv, &i, &s);
        if (r < 0)
            return CLI_USAGE;
        if (r == 0)
            return cli_usage_error("trace-render", "unknown option '%s'", argv[i]);
    }
    return raytrace_run("trace-render", &s);
}

const cg_command cg_command_trace_render = {
    "trace-render",
    "render a mesh or the classic scene by ray tracing",
    "usage: cg trace-render MESH -o OUT.png [options]\n"
    "       cg trace-render SCENE.json -o OUT.png [options]\n"
    "       cg trace-render --scene spheres -o OUT.png [options]\n\n"
    "Whitted ray tracing through a BVH: shadows, mirror reflection, refraction with\n"
    "Fresnel; the mesh (OBJ, OFF, PLY, STL) or the built-in scene 'spheres' (glass\n"
    "and mirror spheres over a checkered plane, soft shadows from an area light).\n"
    "The options of 'cg render' mean the same here (and 'cg render --algorithm\n"
    "raytrace' is this ray tracer with its default --spp 1 --depth 5).  A scene file\n"
    "(docs/scene-format.md) is ray traced with its own camera, lights and\n"
    "materials; --size, --shading, --threads, --spp, --depth and --repeat override it.\n\n"
    "  -o FILE              output image (.png, .ppm, .pgm)\n"
    "  --size WxH           image size (default 800x600)\n"
    "  --eye X,Y,Z          camera position (default: frames the whole mesh)\n"
    "  --target X,Y,Z       point looked at (default: the mesh's centre)\n"
    "  --up X,Y,Z           up direction (default 0,1,0)\n"
    "  --fov DEGREES        vertical field of view, perspective (default 45)\n"
    "  --ortho HEIGHT       parallel projection showing HEIGHT world units\n"
    "  --near D, --far D    clip distances along the view (default: the mesh's depth\n"
    "                       range; a parallel view's rays start at near)\n"
    "  --light-dir X,Y,Z    directional light toward which surfaces face (repeatable;\n"
    "                       default: one from the camera's upper left)\n"
    "  --ambient K          ambient coefficient (default 0.15)\n"
    "  --shading MODE       flat (face normals), gouraud or phong (interpolated normals)\n"
    "  --color COLOR        the mesh's diffuse colour (default light grey)\n"
    "  --background COLOR   where no object is hit (default black)\n"
    "  --spp N              samples per pixel, stratified (default 1: pixel centres)\n"
    "  --depth N            reflection/refraction recursion limit, 0..64 (default 5)\n"
    "  --no-shadows         no shadow rays\n"
    "  --floor              a checkered floor under the mesh (and a sky behind)\n"
    "  --threads N          worker threads (the picture is the same for any N)\n"
    "  --repeat N           render N times, print the median 'frame: 12.3 ms'\n"
    "  --stats              print the BVH build time and rays per second\n"
    "  --quiet              no progress on stderr\n",
    run,
};
