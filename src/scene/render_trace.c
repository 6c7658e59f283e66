/* A scene through the ray tracer. */
#include "internal.h"

cg_status scene_render_trace(const cg_scene *scene, cg_image *image, cg_error *err)
{
    (void)scene;
    (void)image;
    return cg_error_set(err, CG_EUNSUPPORTED, "scene: the ray tracer is not part of this build");
}
