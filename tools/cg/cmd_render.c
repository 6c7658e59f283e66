/* cg render MESH|SCENE.json -o OUT: the rasterizing pipeline (z-buffer or painter's) or
 * the ray tracer on a mesh or scene file (render_command.c does the work). */
#include "command.h"
#include "render_command.h"

#define NAME "render"

static int run(int argc, char **argv)
{
    return render_command_run(NAME, argc, argv, 0);
}

const cg_command cg_command_render = {
    NAME,
    "render a mesh or scene file: z-buffer, painter's or ray tracing",
    "usage: cg render MESH -o OUT [options]\n"
    "       cg render SCENE.json -o OUT [options]\n"
    "       cg render --scene spheres --algorithm raytrace -o OUT [options]\n\n"
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
    "'cg trace-render ...' is 'cg render --algorithm raytrace ...'.\n\n"
    "Camera (default: looking along -z, placed so the whole mesh fills the view):\n"
    "  --size WxH            image size (default 800x600)\n"
    "  --eye X,Y,Z           camera position (then no automatic framing)\n"
    "  --view-from X,Y,Z     direction from the mesh toward a framed camera (default 0,0,1)\n"
    "  --target X,Y,Z        point looked at (default: the centre of the mesh)\n"
    "  --up X,Y,Z            up direction (default 0,1,0)\n"
    "  --fov DEGREES         vertical field of view, perspective (default 45)\n"
    "  --ortho HEIGHT        parallel projection showing HEIGHT world units vertically\n"
    "  --near D, --far D     clip distances along the view (default: the mesh's depth\n"
    "                        range; a parallel view's near may be 0 or negative)\n"
    "Light and material:\n"
    "  --light-dir X,Y,Z     directional light toward which lit surfaces face, strength 1;\n"
    "                        repeatable (default: one light from the camera's upper left)\n"
    "  --ambient K           ambient coefficient (default 0.15)\n"
    "  --specular K          specular coefficient, Blinn-Phong (default 0.25)\n"
    "  --shininess N         specular exponent (default 32)\n"
    "  --color COLOR         diffuse colour where the file has none (default #c4c4c4)\n"
    "  --background COLOR    background (default #1d1f27)\n"
    "  --edge-color COLOR    colour of wireframe and hidden lines\n"
    "Pipeline:\n"
    "  --shading flat|gouraud|phong   (default gouraud)\n"
    "  --crease DEGREES      computed normals are split where faces meet at a\n"
    "                        larger angle (default 60)\n"
    "  --cull back|none      back-face culling; front faces are counter-clockwise as\n"
    "                        seen by the camera (default back)\n"
    "  --algorithm zbuffer|painter|raytrace|depth-sort\n"
    "                        visible-surface algorithm (default zbuffer); depth-sort is\n"
    "                        painter's without its overlap tests, to show their purpose\n"
    "  --wireframe           every edge, no faces\n"
    "  --hidden-line         visible edges only\n"
    "  --edges               shaded faces with their visible edges\n"
    "  --output-depth        write the depth buffer (near light, far dark) instead\n"
    "  --threads N           worker threads, 1 to 64; the picture is the same for any N\n"
    "  --repeat N            render N frames after loading and print the median time\n"
    "                        on stderr as 'frame: 12.3 ms'\n"
    "  --quiet               no progress on stderr\n"
    "Ray tracer (--algorithm raytrace only):\n"
    "  --spp N               samples per pixel, stratified (default 1: pixel centres)\n"
    "  --depth N             reflection/refraction recursion limit, 0..64 (default 5)\n"
    "  --no-shadows          no shadow rays\n"
    "  --floor               a checkered floor under the mesh (and a sky behind)\n"
    "  --scene spheres       the built-in scene instead of a file\n"
    "  --stats               print the BVH build time and rays per second\n"
    "Frames that take longer than a second show their progress on stderr.\n",
    run,
    NULL,
};
