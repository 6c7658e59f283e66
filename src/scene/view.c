/* The camera of a scene: bounds of its objects, the projection kinds of
 * chapter 3 turned into a camera (and, for oblique views, a shear), and
 * framing. */
#include "view.h"

#include <float.h>

static void grow(cg_vec3 *lo, cg_vec3 *hi, cg_vec3 p)
{
    *lo = cg_vec3_make(fmin(lo->x, p.x), fmin(lo->y, p.y), fmin(lo->z, p.z));
    *hi = cg_vec3_make(fmax(hi->x, p.x), fmax(hi->y, p.y), fmax(hi->z, p.z));
}

/* Grows the box by the eight corners of [a, b] under transform. */
static void grow_box(cg_vec3 *lo, cg_vec3 *hi, cg_vec3 a, cg_vec3 b, cg_mat4 transform)
{
    for (int i = 0; i < 8; i++) {
        cg_vec3 c = cg_vec3_make(i & 1 ? b.x : a.x, i & 2 ? b.y : a.y, i & 4 ? b.z : a.z);
        cg_vec3 p = cg_mat4_transform_point(transform, c);
        if (isfinite(p.x) && isfinite(p.y) && isfinite(p.z))
            grow(lo, hi, p);
    }
}

void scene_bounds(const cg_scene *scene, cg_vec3 *lo, cg_vec3 *hi)
{
    cg_vec3 a = {DBL_MAX, DBL_MAX, DBL_MAX}, b = {-DBL_MAX, -DBL_MAX, -DBL_MAX};
    for (size_t i = 0; i < scene->object_count; i++) {
        const cg_scene_object *o = &scene->objects[i];
        cg_vec3 ol, oh, r = {o->radius, o->radius, o->radius};
        switch (o->kind) {
        case CG_SCENE_MESH:
            if (o->mesh && cg_mesh_bounds(o->mesh, &ol, &oh) == CG_OK)
                grow_box(&a, &b, ol, oh, o->transform);
            break;
        case CG_SCENE_SPHERE:
            grow_box(&a, &b, cg_vec3_sub(o->center, r), cg_vec3_add(o->center, r), o->transform);
            break;
        case CG_SCENE_BOX: grow_box(&a, &b, o->lo, o->hi, o->transform); break;
        case CG_SCENE_PLANE: break; /* unbounded: it does not decide the framing */
        }
    }
    if (!(a.x <= b.x)) { /* nothing finite: the unit cube */
        a = cg_vec3_make(-1, -1, -1);
        b = cg_vec3_make(1, 1, 1);
    }
    *lo = a;
    *hi = b;
}

/* A plane drawn as a square of this many scene radii on a side. */
#define PLANE_EXTENT 6.0

void scene_plane_extent(const cg_scene *scene, cg_vec3 *center, double *radius)
{
    cg_vec3 lo, hi;
    scene_bounds(scene, &lo, &hi);
    *center = cg_vec3_scale(cg_vec3_add(lo, hi), 0.5);
    *radius = fmax(0.5 * cg_vec3_length(cg_vec3_sub(hi, lo)), 1e-6);
}

void scene_plane_square(const cg_scene_object *o, cg_vec3 center, double radius, cg_vec3 corners[4])
{
    cg_vec3 n = cg_vec3_normalize(o->normal);
    cg_vec3 c = cg_vec3_sub(center,
                            cg_vec3_scale(n, cg_vec3_dot(cg_vec3_sub(center, o->point), n)));
    cg_vec3 helper = fabs(n.x) < 0.9 ? cg_vec3_make(1, 0, 0) : cg_vec3_make(0, 1, 0);
    cg_vec3 u = cg_vec3_scale(cg_vec3_normalize(cg_vec3_cross(n, helper)), PLANE_EXTENT * radius);
    cg_vec3 v = cg_vec3_cross(n, u);
    corners[0] = cg_vec3_sub(cg_vec3_sub(c, u), v);
    corners[1] = cg_vec3_sub(cg_vec3_add(c, u), v);
    corners[2] = cg_vec3_add(cg_vec3_add(c, u), v);
    corners[3] = cg_vec3_add(cg_vec3_sub(c, u), v);
}

/* The box that near and far enclose: scene_bounds and the planes' squares. */
static void depth_bounds(const cg_scene *scene, cg_vec3 *lo, cg_vec3 *hi)
{
    cg_vec3 center;
    double radius;
    scene_bounds(scene, lo, hi);
    scene_plane_extent(scene, &center, &radius);
    for (size_t i = 0; i < scene->object_count; i++) {
        const cg_scene_object *o = &scene->objects[i];
        if (o->kind != CG_SCENE_PLANE)
            continue;
        cg_vec3 corners[4];
        scene_plane_square(o, center, radius, corners);
        for (int k = 0; k < 4; k++) {
            cg_vec3 p = cg_mat4_transform_point(o->transform, corners[k]);
            if (isfinite(p.x) && isfinite(p.y) && isfinite(p.z))
                grow(lo, hi, p);
        }
    }
}

/* The rotation of an axonometric projection kind. */
static cg_mat4 axonometric_rotation(const cg_scene *scene)
{
    cg_mat4 r;
    switch (scene->projection) {
    case CG_SCENE_ISOMETRIC: return cg_proj_isometric();
    case CG_SCENE_DIMETRIC:
        if (cg_proj_dimetric(scene->projection_ratio, &r) == CG_OK)
            return r;
        return cg_proj_isometric();
    default: return cg_proj_axonometric(scene->projection_angle, scene->projection_angle2);
    }
}

cg_status scene_view(const cg_scene *scene, cg_camera *camera, cg_mat4 *model)
{
    cg_vec3 lo, hi;
    scene_bounds(scene, &lo, &hi);
    double aspect = (double)scene->width / scene->height;
    cg_camera c = scene->camera;
    *model = cg_mat4_identity();
    switch (scene->projection) {
    case CG_SCENE_ISOMETRIC:
    case CG_SCENE_DIMETRIC:
    case CG_SCENE_TRIMETRIC: {
        /* The rotation R brings the scene into view space looking down -z;
         * the camera therefore looks along R^T (0, 0, -1) with up R^T (0, 1, 0). */
        cg_mat4 rt = cg_mat4_transpose(axonometric_rotation(scene));
        cg_vec3 forward = cg_mat4_transform_vector(rt, cg_vec3_make(0, 0, -1));
        c.up = cg_mat4_transform_vector(rt, cg_vec3_make(0, 1, 0));
        double distance = cg_vec3_length(cg_vec3_sub(c.target, c.eye));
        c.eye = cg_vec3_sub(c.target, cg_vec3_scale(forward, distance > 0 ? distance : 1));
        c.orthographic = 1;
        break;
    }
    default: break;
    }
    if (scene->frame_camera) {
        cg_status s = cg_camera_frame(&c, lo, hi, aspect);
        if (s != CG_OK)
            return s;
    }
    if (c.orthographic && scene->camera.ortho_height > 0)
        c.ortho_height = scene->camera.ortho_height;
    else if (c.orthographic && !scene->frame_camera)
        c.ortho_height = 1.05 * cg_vec3_length(cg_vec3_sub(hi, lo));
    if (scene_is_oblique(scene)) {
        /* An oblique view is an orthographic one after a shear in view space:
         * a point d units farther away than the target moves by ratio d along
         * the projection angle. */
        double ratio = scene->projection == CG_SCENE_CAVALIER  ? 1
                       : scene->projection == CG_SCENE_CABINET ? 0.5
                                                               : scene->projection_ratio;
        cg_mat4 view, inverse_view;
        cg_status s = cg_camera_view(&c, &view);
        if (s == CG_OK)
            s = cg_mat4_inverse(view, &inverse_view);
        if (s != CG_OK)
            return s;
        /* The shear keeps the target's depth plane in place, so the scene
         * stays centred however far back the eye stands. */
        double target_z = -cg_vec3_length(cg_vec3_sub(c.target, c.eye));
        cg_mat4 shear = cg_mat4_mul(cg_xform3_translate(0, 0, target_z),
                                    cg_mat4_mul(cg_proj_oblique(scene->projection_angle, -ratio),
                                                cg_xform3_translate(0, 0, -target_z)));
        *model = cg_mat4_mul(inverse_view, cg_mat4_mul(shear, view));
        /* The shear moves the scene sideways: widen the view to keep it in. */
        c.ortho_height *= 1 + ratio;
    }
    cg_vec3 depth_lo, depth_hi;
    depth_bounds(scene, &depth_lo, &depth_hi);
    cg_status s = cg_camera_fit_depth(&c, depth_lo, depth_hi);
    if (s != CG_OK)
        return s;
    if (scene->near_given)
        c.near = scene->camera.near;
    if (scene->far_given)
        c.far = scene->camera.far;
    if (!(c.far > c.near))
        return CG_EINVAL;
    *camera = c;
    return CG_OK;
}

int scene_is_oblique(const cg_scene *scene)
{
    return scene->projection == CG_SCENE_CAVALIER || scene->projection == CG_SCENE_CABINET
           || scene->projection == CG_SCENE_OBLIQUE;
}
