/* Private pieces of the scene module. */
#ifndef CG_SCENE_INTERNAL_H
#define CG_SCENE_INTERNAL_H

#include "cg/scene.h"

/* The default material: light grey, ka 0.15, kd 0.85, ks 0.25, shininess 32,
 * Blinn-Phong, opaque. */
cg_scene_material scene_default_material(void);

/* A scene with defaults everywhere and the default material, no objects. */
cg_status scene_create_empty(cg_scene **out);

/* Renders with the rasterizer (z-buffer or painter's) into image. */
cg_status scene_render_raster(const cg_scene *scene, cg_scene_algorithm algorithm, cg_image *image,
                              cg_error *err);
/* Renders with the ray tracer into image. */
cg_status scene_render_trace(const cg_scene *scene, cg_image *image, cg_error *err);

#endif
