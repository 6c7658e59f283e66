/* Private: the camera of a scene. */
#ifndef CG_SCENE_VIEW_H
#define CG_SCENE_VIEW_H

#include "cg/scene.h"

/* Bounding box of the scene's finite objects (planes excluded); the cube
 * [-1, 1]^3 when there are none. */
void scene_bounds(const cg_scene *scene, cg_vec3 *lo, cg_vec3 *hi);

/* The camera that shows the scene with its projection kind, framed when the
 * scene asks for it.  model receives the extra model transform an oblique
 * projection needs (a shear in view space; identity otherwise). */
cg_status scene_view(const cg_scene *scene, cg_camera *camera, cg_mat4 *model);

/* Cavalier, cabinet and general oblique views. */
int scene_is_oblique(const cg_scene *scene);

#endif
