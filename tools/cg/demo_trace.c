/* Gallery: ray tracing (section 5.4) - the classic scene of glass and mirror
 * spheres over a checkered floor, and a scanned mesh with shadows. */
#include "demo.h"
#include "trace_command.h"
#include "cg/color.h"

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
    s.extra.classic_scene = 1;
    s.common.size.width = 480;
    s.common.size.height = 320;
    s.extra.samples = 4;
    s.common.render.threads = 2;
    s.quiet = 1;
    if (add(context, &s, "trace-spheres.png",
            "Whitted ray tracing through a SAH bounding volume hierarchy: a glass sphere "
            "(refraction by Snell's law, Schlick Fresnel, total internal reflection), a mirror "
            "sphere, soft shadows from an area light, 4 stratified samples per pixel",
            "cg trace-render --scene spheres -o trace-spheres.png --size 480x320 --spp 4"))
        return 1;
#ifdef CG_SOURCE_DIR
    FILE *probe = fopen(CG_SOURCE_DIR "/data/meshes/bunny.obj", "rb");
    if (!probe)
        return 0; /* the mesh is not there (an installed tool): no picture */
    fclose(probe);
    if (demo_copy_input(context, "data/meshes/bunny.obj") != 0)
        return 1;
    raytrace_settings_default(&s);
    s.input = CG_SOURCE_DIR "/data/meshes/bunny.obj";
    s.common.size.width = 400;
    s.common.size.height = 320;
    s.extra.samples = 4;
    s.extra.floor = 1;
    s.common.render.threads = 2;
    s.common.render.color = cg_rgba8_to_linear((cg_rgba8){225, 190, 150, 255});
    s.common.render.lights[0].direction = cg_vec3_make(-1, 1, 0.2);
    s.common.eye = cg_vec3_make(5, 9, 18);
    s.common.target = cg_vec3_make(0, 3.5, 0);
    s.common.have_eye = s.common.have_target = 1;
    s.common.render.lights[0].intensity = 1;
    s.common.render.light_count = 1;
    s.quiet = 1;
    if (add(context, &s, "trace-bunny.png",
            "A scanned mesh (Stanford bunny, 3,674 triangles) ray traced with hard shadows on a "
            "checkered floor, interpolated normals",
            "cg trace-render data/meshes/bunny.obj --floor --light-dir=-1,1,0.2 "
            "--eye 5,9,18 --target 0,3.5,0 --color '#e1be96' --size 400x320 --spp 4 "
            "-o trace-bunny.png"))
        return 1;
#endif
    return 0;
}

const demo_section demo_section_trace = {5, "Ray tracing", render};
