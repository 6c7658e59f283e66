/* Scene objects: defaults and release. */
#include "internal.h"
#include "animation.h"

#include <stdlib.h>
#include <string.h>

cg_scene_material scene_default_material(void)
{
    cg_scene_material m;
    memset(&m, 0, sizeof m);
    m.surface = cg_material_make(cg_vec3_make(0.7, 0.7, 0.7), 0.15, 0.85, 0.25, 32);
    m.surface.specular = CG_SPECULAR_BLINN;
    return m;
}

cg_status scene_create_empty(cg_scene **out)
{
    cg_scene *s = calloc(1, sizeof *s);
    if (!s)
        return CG_ENOMEM;
    s->width = 640;
    s->height = 480;
    cg_rgbaf background = {0.01f, 0.012f, 0.016f, 1};
    s->background = background;
    s->environment_intensity = 1;
    s->environment_color = cg_vec3_make(1, 1, 1);
    s->camera = cg_camera_default();
    s->camera.ortho_height = 0; /* 0: chosen by framing */
    s->frame_camera = 1;
    s->projection = CG_SCENE_PERSPECTIVE;
    s->projection_ratio = 0.5;
    s->projection_angle = cg_radians(45);
    s->algorithm = CG_SCENE_ZBUFFER;
    s->shading = CG_SCENE_GOURAUD;
    s->cull_back = 1;
    s->edges = CG_SCENE_EDGES_NONE;
    s->threads = 1;
    s->samples = 1;
    s->max_depth = 5;
    s->shadows = 1;
    s->msaa = 1;
    s->materials = malloc(sizeof *s->materials);
    if (!s->materials) {
        free(s);
        return CG_ENOMEM;
    }
    s->materials[0] = scene_default_material();
    s->material_count = 1;
    *out = s;
    return CG_OK;
}

void cg_scene_free(cg_scene *scene)
{
    if (!scene)
        return;
    for (size_t i = 0; i < scene->object_count; i++) {
        free(scene->objects[i].file);
        cg_mesh_free(scene->objects[i].mesh);
    }
    for (size_t i = 0; i < scene->material_count; i++)
        free(scene->materials[i].name);
    for (size_t i = 0; i < scene->overlay_count; i++)
        free(scene->overlays[i]);
    free(scene->environment_file);
    cg_image_free(scene->environment_map);
    animation_free(scene->animation);
    free(scene->objects);
    free(scene->materials);
    free(scene->lights);
    free(scene->area_lights);
    free(scene->overlays);
    free(scene);
}
