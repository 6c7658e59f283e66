/* Private pieces of the scene module. */
#ifndef CG_SCENE_INTERNAL_H
#define CG_SCENE_INTERNAL_H

#include "cg/scene.h"

/* The default material: light grey, ka 0.15, kd 0.85, ks 0.25, shininess 32,
 * Blinn-Phong, opaque. */
cg_scene_material scene_default_material(void);

/* A scene with defaults everywhere and the default material, no objects. */
cg_status scene_create_empty(cg_scene **out);

/* cg_scene_world_mesh, and (face_material not NULL) a new array of the
 * material index of each face. */
cg_status scene_world_mesh(const cg_scene *scene, cg_mesh **out, uint32_t **face_material,
                           cg_error *err);
/* cg_scene_raster_options before any material: the scene's camera, settings
 * and lights at full strength. */
cg_status scene_raster_base_options(const cg_scene *scene, cg_scene_algorithm algorithm,
                                    cg_render_options *options, cg_error *err);
/* Turns options (from scene_raster_base_options) into the options that light every face with
 * material m as the ray tracer does: ambient lights times ka, the lights'
 * strengths times kd, ks (times the specular colour) over kd.  Without
 * lights, the ray tracer's key light and a white ambient light. */
cg_status scene_material_options(const cg_scene *scene, const cg_material *m,
                                 cg_render_options *options, cg_error *err);
/* Renders with the rasterizer (z-buffer or painter's) into image: one pass
 * per material where the scene has several (render_materials.c). */
cg_status scene_render_raster(const cg_scene *scene, cg_scene_algorithm algorithm, cg_image *image,
                              cg_error *err);
/* Renders with the ray tracer into image. */
cg_status scene_render_trace(const cg_scene *scene, cg_image *image, cg_error *err);

#endif
