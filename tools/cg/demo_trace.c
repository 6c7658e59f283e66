/* Gallery: ray tracing (section 5.4) - the classic scene of glass and mirror
 * spheres over a checkered floor, and a scanned mesh with shadows. */
#include "demo.h"
#include "render_raytrace.h"

#include <stdio.h>

static int add(demo_context *context, const raytrace_settings *s, const char *file,
               const char *caption, const char *command)
{
    cg_image *image;
    if (raytrace_render("demo", s, &image) != 0)
        return 1;
    int status = demo_add(context, file, image, caption, command);
    cg_image_free(image);
    return status;
}

static int render(demo_context *context)
{
    raytrace_settings s;
    raytrace_settings_default(&s);
    s.scene = "spheres";
    s.width = 480;
    s.height = 320;
    s.samples = 4;
    s.threads = 2;
    s.quiet = 1;
    if (add(context, &s, "trace-spheres.png",
            "Whitted ray tracing through a SAH bounding volume hierarchy: a glass sphere "
            "(refraction by Snell's law, Schlick Fresnel, total internal reflection), a mirror "
            "sphere, soft shadows from an area light, 4 stratified samples per pixel",
            "cg trace-render --scene spheres -o trace-spheres.png --size 480x320 --spp 4"))
        return 1;
#ifdef CG_DATA_DIR
    raytrace_settings_default(&s);
    s.input = CG_DATA_DIR "/meshes/bunny.obj";
    s.width = 400;
    s.height = 320;
    s.samples = 4;
    s.threads = 2;
    s.quiet = 1;
    s.floor = 1;
    s.color = (cg_rgba8){225, 190, 150, 255};
    s.light_dirs[0] = cg_vec3_normalize(cg_vec3_make(-0.6, 1, 0.5));
    s.light_count = 1;
    if (add(context, &s, "trace-bunny.png",
            "A scanned mesh (Stanford bunny, 3,674 triangles) ray traced with hard shadows on a "
            "checkered floor, interpolated normals",
            "cg trace-render data/meshes/bunny.obj --floor --light-dir=-0.6,1,0.5 "
            "--color '#e1be96' --size 400x320 --spp 4 -o trace-bunny.png"))
        return 1;
#endif
    return 0;
}

const demo_section demo_section_trace = {5, "Ray tracing", render};
