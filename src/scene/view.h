/* Private: the camera of a scene. */
#ifndef CG_SCENE_VIEW_H
#define CG_SCENE_VIEW_H

#include "cg/scene.h"

/* Bounding box of the scene's finite objects (planes excluded); the cube
 * [-1, 1]^3 when there are none. */
void scene_bounds(const cg_scene *scene, cg_vec3 *lo, cg_vec3 *hi);

/* Where the rasterizer's squares standing for planes are centred and how
 * big: the centre of scene_bounds and half its diagonal (at least 1e-6). */
void scene_plane_extent(const cg_scene *scene, cg_vec3 *center, double *radius);

/* The square (counter-clockwise seen from the side the normal points to,
 * in object space) that stands for the infinite plane o in the rasterizer:
 * PLANE_EXTENT radii on a side, centred on the plane's point nearest
 * center. */
void scene_plane_square(const cg_scene_object *o, cg_vec3 center, double radius,
                        cg_vec3 corners[4]);

/* The camera that shows the scene with its projection kind, framed when the
 * scene asks for it.  model receives the extra model transform an oblique
 * projection needs (a shear in view space; identity otherwise).  near and
 * far are the file's where it gives them, else the depth range along the
 * view of every object (planes as the rasterizer's squares). */
cg_status scene_view(const cg_scene *scene, cg_camera *camera, cg_mat4 *model);

/* Cavalier, cabinet and general oblique views. */
int scene_is_oblique(const cg_scene *scene);

#endif
