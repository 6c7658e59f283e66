/* cg trace-render MESH -o OUT.png: the alias of `cg render --algorithm raytrace`
 * (render_command.c). */
#include "command.h"
#include "render_command.h"

static int run(int argc, char **argv)
{
    return render_command_run("trace-render", argc, argv, 1);
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
    "This command is 'cg render --algorithm raytrace': the same options with the\n"
    "same meaning and the same pictures, byte for byte (see 'cg help render', which\n"
    "also lists --view-from, --specular, --shininess and --crease).  A scene file\n"
    "(docs/scene-format.md) is ray traced with its own camera, lights and\n"
    "materials; the options given override them as for 'cg render'.\n\n"
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
    "  --background COLOR   where no object is hit (default #1d1f27; a sky with\n"
    "                       --floor and --scene)\n"
    "  --spp N              samples per pixel, stratified (default 1: pixel centres)\n"
    "  --depth N            reflection/refraction recursion limit, 0..64 (default 5)\n"
    "  --no-shadows         no shadow rays\n"
    "  --floor              a checkered floor under the mesh (and a sky behind)\n"
    "  --threads N          worker threads (the picture is the same for any N)\n"
    "  --repeat N           render N times, print the median 'frame: 12.3 ms'\n"
    "  --stats              print the BVH build time and rays per second\n"
    "  --quiet              no progress on stderr (shown for frames over a second)\n",
    run,
    NULL,
};
