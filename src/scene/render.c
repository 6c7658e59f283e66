/* Rendering a scene with the algorithm it asks for. */
#include "internal.h"

cg_status cg_scene_render_with(const cg_scene *scene, cg_scene_algorithm algorithm, cg_image **out,
                               cg_error *err)
{
    if (!scene || !out)
        return cg_error_set(err, CG_EINVAL, "scene render: no scene or output given");
    *out = NULL;
    cg_image *image;
    cg_status s = cg_image_create(&image, scene->width, scene->height, CG_PIXEL_RGBA8);
    if (s != CG_OK)
        return cg_error_set(err, s, "scene: cannot create a %d x %d image", scene->width,
                            scene->height);
    if (algorithm == CG_SCENE_RAYTRACE)
        s = scene_render_trace(scene, image, err);
    else
        s = scene_render_raster(scene, algorithm, image, err);
    if (s != CG_OK) {
        cg_image_free(image);
        return s;
    }
    *out = image;
    return CG_OK;
}

cg_status cg_scene_render(const cg_scene *scene, cg_image **out, cg_error *err)
{
    if (!scene)
        return cg_error_set(err, CG_EINVAL, "scene render: no scene given");
    return cg_scene_render_with(scene, scene->algorithm, out, err);
}
