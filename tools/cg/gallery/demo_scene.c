/* Gallery: one scene file rendered by each visible-surface algorithm, and the
 * classic ray-tracing scene from its file (docs/scene-format.md). */
#include "demo.h"
#include "cg/scene.h"

#include <stdio.h>

typedef struct scene_picture {
    const char *scene, *file, *caption;
    cg_scene_algorithm algorithm;
    int width, height;
} scene_picture;

#ifdef CG_SOURCE_DIR
static int copy_scene_inputs(demo_context *context, const char *scene)
{
    static const char *const meshes[] = {"data/meshes/bunny.obj", "data/meshes/teapot.obj"};
    if (demo_copy_input(context, scene) != 0)
        return 1;
    for (size_t i = 0; i < sizeof meshes / sizeof meshes[0]; i++)
        if (demo_copy_input(context, meshes[i]) != 0)
            return 1;
    return 0;
}
#endif

static int render(demo_context *context)
{
#ifdef CG_SOURCE_DIR
    static const scene_picture pictures[] = {
        {"bunny", "scene-bunny-zbuffer.png",
         "Scene file, z-buffer: Phong shading, three lights (ambient, directional, point)",
         CG_SCENE_ZBUFFER, 320, 240},
        {"bunny", "scene-bunny-painter.png", "The same scene file with the painter's algorithm",
         CG_SCENE_PAINTER, 320, 240},
        {"bunny", "scene-bunny-raytrace.png",
         "The same scene file ray traced: shadows and the checkered floor material",
         CG_SCENE_RAYTRACE, 320, 240},
        {"spheres", "scene-spheres.png",
         "Glass and mirror spheres over a checkered floor, soft shadows from an area light",
         CG_SCENE_RAYTRACE, 360, 225},
        {"transforms", "scene-transforms.png",
         "One teapot placed three times by transform lists: translate, rotate about a point, "
         "scale and reflect",
         CG_SCENE_ZBUFFER, 360, 203},
        {"projections", "scene-isometric.png", "A scene in an isometric camera", CG_SCENE_ZBUFFER,
         320, 240},
    };
    static const char *const algorithm_names[] = {"zbuffer", "painter", "raytrace"};
    for (size_t i = 0; i < sizeof pictures / sizeof pictures[0]; i++) {
        const scene_picture *p = &pictures[i];
        char path[1024], command[1024];
        snprintf(path, sizeof path, "%s/examples/scenes/%s.json", CG_SOURCE_DIR, p->scene);
        cg_scene *scene;
        cg_error err;
        if (cg_scene_load(path, &scene, &err) != CG_OK) {
            fprintf(stderr, "demo: %s (skipped)\n", err.message);
            continue;
        }
        /* The caption runs in the gallery folder: the scene file and the
         * meshes it names go there, at their paths in the source tree. */
        snprintf(path, sizeof path, "examples/scenes/%s.json", p->scene);
        if (copy_scene_inputs(context, path) != 0) {
            cg_scene_free(scene);
            return 1;
        }
        scene->width = p->width;
        scene->height = p->height;
        scene->threads = 2;
        cg_image *image = NULL;
        cg_status s = cg_scene_render_with(scene, p->algorithm, &image, &err);
        cg_scene_free(scene);
        if (s != CG_OK) {
            fprintf(stderr, "demo: %s\n", err.message);
            return 1;
        }
        snprintf(command, sizeof command,
                 "cg render examples/scenes/%s.json --algorithm %s --size %dx%d -o %s", p->scene,
                 algorithm_names[p->algorithm], p->width, p->height, p->file);
        int status = demo_add(context, p->file, image, p->caption, command);
        cg_image_free(image);
        if (status)
            return status;
    }
#else
    (void)context;
#endif
    return 0;
}

const demo_section demo_section_scene = {5, "Scene files", render};
