/* cg/xform.h - geometric transformations in homogeneous coordinates,
 * projections, the camera and the viewport (chapters 3 and 4 of the notes).
 *
 * 2D transformations are 3x3 matrices acting on (x, y, 1); 3D ones are 4x4
 * matrices acting on (x, y, z, 1).  Points are column vectors: M p.  To apply
 * A then B, use B A, i.e. cg_mat4_mul(B, A), or cg_mat4_compose with the steps
 * in the order they happen.  Angles are in radians, counter-clockwise when
 * looking down the axis toward the origin (right-handed).
 *
 * 3D follows OpenGL: right-handed world, the camera looks down -z, and the
 * projections map the view volume to normalized device coordinates
 * [-1, 1]^3 with near at z = -1 and far at z = +1.
 */
#ifndef CG_XFORM_H
#define CG_XFORM_H

#include "cg/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- 2D ------------------------------------------------------------------ */

cg_mat3 cg_xform2_translate(double tx, double ty);
/* Scaling by (sx, sy) about the fixed point (cx, cy). */
cg_mat3 cg_xform2_scale(double sx, double sy, double cx, double cy);
/* Rotation by angle about the point (cx, cy). */
cg_mat3 cg_xform2_rotate(double angle, double cx, double cy);
/* Reflection about the line through point with direction direction.
 * CG_EINVAL when direction is zero or not finite. */
cg_status cg_xform2_reflect(cg_vec2 point, cg_vec2 direction, cg_mat3 *out);
/* Shear: x' = x + shx y, y' = y + shy x. */
cg_mat3 cg_xform2_shear(double shx, double shy);

/* ---- 3D ------------------------------------------------------------------ */

cg_mat4 cg_xform3_translate(double tx, double ty, double tz);
/* Scaling by (sx, sy, sz) about the fixed point center. */
cg_mat4 cg_xform3_scale(double sx, double sy, double sz, cg_vec3 center);
cg_mat4 cg_xform3_rotate_x(double angle);
cg_mat4 cg_xform3_rotate_y(double angle);
cg_mat4 cg_xform3_rotate_z(double angle);
/* Rotation by angle about the axis through point with direction axis
 * (Rodrigues' formula).  CG_EINVAL when axis is zero or not finite. */
cg_status cg_xform3_rotate_axis(cg_vec3 axis, double angle, cg_vec3 point, cg_mat4 *out);
/* Reflection about the plane through point with normal normal.
 * CG_EINVAL when normal is zero or not finite. */
cg_status cg_xform3_reflect(cg_vec3 point, cg_vec3 normal, cg_mat4 *out);
/* Shear: x' = x + xy y + xz z,  y' = y + yx x + yz z,  z' = z + zx x + zy y. */
cg_mat4 cg_xform3_shear(double xy, double xz, double yx, double yz, double zx, double zy);

/* ---- camera and viewing ------------------------------------------------- */

/* The view matrix of a camera at eye looking at target with up roughly up:
 * eye goes to the origin, the viewing direction to -z, up to +y.
 * CG_EINVAL when eye == target or up is parallel to the viewing direction. */
cg_status cg_view_look_at(cg_vec3 eye, cg_vec3 target, cg_vec3 up, cg_mat4 *out);

/* ---- projections --------------------------------------------------------- */

/* Perspective projection of the view frustum with near-plane rectangle
 * [left, right] x [bottom, top] at distance near, far plane at distance far
 * (glFrustum).  CG_EINVAL unless 0 < near < far and the rectangle is not empty. */
cg_status cg_proj_frustum(double left, double right, double bottom, double top, double near,
                          double far, cg_mat4 *out);
/* Symmetric perspective from the vertical field of view (radians, in (0, pi))
 * and the aspect ratio width / height (gluPerspective). */
cg_status cg_proj_perspective(double fovy, double aspect, double near, double far, cg_mat4 *out);
/* Orthographic parallel projection of the box [left, right] x [bottom, top] x
 * [-near, -far] in view space (glOrtho). */
cg_status cg_proj_orthographic(double left, double right, double bottom, double top, double near,
                               double far, cg_mat4 *out);

/* The principal orthographic views: which world plane is looked at. */
typedef enum cg_ortho_view {
    CG_VIEW_FRONT, /* looking along -z: x to the right, y up */
    CG_VIEW_TOP,   /* looking down along -y: x to the right, -z up */
    CG_VIEW_SIDE   /* looking along -x (from the right): -z to the right, y up */
} cg_ortho_view;
/* The rotation that brings a principal view to the front view; follow it with
 * an orthographic projection. */
cg_mat4 cg_proj_view_rotation(cg_ortho_view view);

/* Axonometric view: rotation by about_y around the y axis followed by
 * about_x around the x axis, then orthographic projection along z.
 * The three forms fix the angles:
 *  isometric: about_y = 45 deg, about_x = asin(tan 30 deg) = 35.264 deg, so
 *             the three axes are equally foreshortened (factor sqrt(2/3));
 *  dimetric: two axes equally foreshortened, chosen by the foreshortening
 *            ratio of z (see cg_proj_dimetric);
 *  trimetric: any two angles. */
cg_mat4 cg_proj_axonometric(double about_y, double about_x);
cg_mat4 cg_proj_isometric(void);
/* Dimetric view in which x and y are foreshortened equally and z by the factor
 * z_ratio relative to them (0 < z_ratio < 1; 0.5 is the classic drafting
 * choice).  CG_EINVAL for a ratio out of range. */
cg_status cg_proj_dimetric(double z_ratio, cg_mat4 *out);
/* Foreshortening factors of the unit x, y and z axes under a parallel
 * projection matrix (lengths of their projections onto the image plane). */
cg_vec3 cg_proj_foreshortening(cg_mat4 projection);

/* Oblique parallel projection onto the z = 0 plane: a point at depth z moves by
 * ratio * z in the direction angle (radians from +x):
 *   x' = x + ratio z cos(angle),  y' = y + ratio z sin(angle).
 * Cavalier: ratio 1; cabinet: ratio 1/2.  Depth is kept in z. */
cg_mat4 cg_proj_oblique(double angle, double ratio);
cg_mat4 cg_proj_cavalier(double angle);
cg_mat4 cg_proj_cabinet(double angle);

/* ---- viewport ------------------------------------------------------------ */

/* Maps NDC to pixels of a width x height image: x from [-1, 1] to [0, width],
 * y from [-1, 1] to [height, 0] (y down in images), z from [-1, 1] to [0, 1]. */
cg_mat4 cg_viewport(int width, int height);

/* Transforms a point by a projection-and-viewport matrix; sets *visible to 0
 * when the point is behind the camera (w <= 0), in which case the returned
 * coordinates are meaningless. */
cg_vec3 cg_project_point(cg_mat4 transform, cg_vec3 point, int *visible);


/* ---- camera ---------------------------------------------------------------
 * One camera model for the rasterizer and the ray tracer, so that the same
 * scene renders with either. */

typedef struct cg_camera {
    cg_vec3 eye, target, up;
    int orthographic;    /* 0: perspective with fovy; 1: parallel with ortho_height */
    double fovy;         /* vertical field of view in radians, in (0, pi) */
    double ortho_height; /* height of the visible region for parallel views */
    /* Clip distances along the viewing direction, near < far; a
     * perspective camera needs 0 < near, a parallel one may reach behind
     * the eye (near <= 0). */
    double near, far;
} cg_camera;

/* A perspective camera looking from eye at target with +y up, 45 deg
 * vertical field of view; near and far left for cg_camera_fit_depth or
 * cg_camera_frame to set. */
cg_camera cg_camera_default(void);
/* Places the camera so the box [lo, hi] fills the view: keeps the viewing
 * direction (target - eye), up and field of view and moves eye and target
 * so the box's projected corners just fit (the projected box touches two
 * opposite sides of the picture, less a margin of 5%, and is centred across
 * the other axis; a parallel camera also gets ortho_height).  An up parallel
 * to the viewing direction is replaced by cg_camera_up_for's.  near and far
 * as cg_camera_fit_depth sets them.  CG_EINVAL when the box is empty or not
 * finite. */
cg_status cg_camera_frame(cg_camera *camera, cg_vec3 lo, cg_vec3 hi, double aspect);
/* Sets near and far to enclose the depth range of the box [lo, hi] along
 * the viewing direction: the smallest and largest view-space depth of its
 * eight corners, padded by 0.1% of that range and 1e-5 of the depth (a
 * perspective near by at most 0.1% of itself).  A perspective near stays
 * at least 1e-4 of far (the z-buffer's precision; geometry nearer than
 * that is clipped); a parallel near may be zero or negative.  Nothing else
 * changes.  CG_EINVAL for an empty or non-finite box or an unusable
 * camera (eye on target, up along the view). */
cg_status cg_camera_fit_depth(cg_camera *camera, cg_vec3 lo, cg_vec3 hi);
/* up, or when it is zero or parallel to direction, another up: the world
 * axis least aligned with it (z first) made perpendicular to direction,
 * signed as if the camera had pitched onto direction (looking down -y with
 * up +y gives -z, looking up +y gives +z).  direction need not be unit. */
cg_vec3 cg_camera_up_for(cg_vec3 direction, cg_vec3 up);
/* View matrix (world to camera space). */
cg_status cg_camera_view(const cg_camera *camera, cg_mat4 *out);
/* Projection matrix for the given aspect ratio (width / height). */
cg_status cg_camera_projection(const cg_camera *camera, double aspect, cg_mat4 *out);
/* The primary ray through the image point (x, y) in continuous pixel
 * coordinates of a width x height image (pixel centres at +0.5): origin and
 * unit direction in world space, consistent with view, projection and
 * viewport above.  For parallel cameras the origin lies on the near plane. */
cg_status cg_camera_ray(const cg_camera *camera, int width, int height, double x, double y,
                        cg_vec3 *origin, cg_vec3 *direction);

#ifdef __cplusplus
}
#endif
#endif
