/* A scene through the ray tracer: objects, materials and lights map one to
 * one onto cg/trace.h's scene. */
#include "internal.h"
#include "view.h"
#include "cg/render.h"
#include "cg/trace.h"

/* The crease angle the rasterizer uses by default, so smooth normals agree. */
#define CREASE_ANGLE (60.0 * CG_PI / 180.0)

static cg_trace_material trace_material(const cg_scene_material *m)
{
    cg_trace_material t = cg_trace_material_default();
    t.surface = m->surface;
    t.checker_color = m->checker_color;
    t.checker_size = m->checker_size;
    t.emission = m->emission;
    return t;
}

static cg_status add_object(cg_trace_scene *trace, const cg_scene *scene, const cg_scene_object *o)
{
    cg_trace_material material = trace_material(&scene->materials[o->material]);
    switch (o->kind) {
    case CG_SCENE_MESH:
        return cg_trace_scene_add_mesh(trace, o->mesh, &o->transform, CREASE_ANGLE, &material);
    case CG_SCENE_SPHERE:
        return cg_trace_scene_add_sphere(trace, o->center, o->radius, &o->transform, &material);
    case CG_SCENE_BOX: {
        cg_mesh *box;
        cg_status s = cg_mesh_box(o->lo, o->hi, &box);
        if (s == CG_OK)
            s = cg_trace_scene_add_mesh(trace, box, &o->transform, CREASE_ANGLE, &material);
        cg_mesh_free(box);
        return s;
    }
    case CG_SCENE_PLANE: {
        /* Points move with the transform; normals with its inverse transpose. */
        cg_mat4 inverse;
        cg_status s = cg_mat4_inverse(o->transform, &inverse);
        if (s != CG_OK)
            return CG_EINVAL;
        cg_vec3 point = cg_mat4_transform_point(o->transform, o->point);
        cg_vec3 normal = cg_mat4_transform_vector(cg_mat4_transpose(inverse), o->normal);
        return cg_trace_scene_add_plane(trace, point, normal, &material);
    }
    }
    return CG_EINVAL;
}

/* The ray tracer draws planes whole, to the horizon and up to the eye:
 * unless the file sets them, far is unbounded and a perspective near the
 * old 1e-4 of the eye's distance to the target, where the rasterizer's
 * squares (which decide scene_view's range) would cut them. */
static void open_depth_for_planes(const cg_scene *scene, cg_camera *camera)
{
    int planes = 0;
    for (size_t i = 0; i < scene->object_count; i++)
        planes |= scene->objects[i].kind == CG_SCENE_PLANE;
    if (!planes)
        return;
    if (!scene->far_given)
        camera->far = INFINITY;
    double distance = cg_vec3_length(cg_vec3_sub(camera->target, camera->eye));
    if (!scene->near_given && !camera->orthographic)
        camera->near = fmin(camera->near, 1e-4 * distance);
}

cg_status cg_scene_trace_scene(const cg_scene *scene, int default_lights, cg_trace_scene **out,
                               cg_camera *camera, cg_error *err)
{
    if (!scene || !out || !camera)
        return cg_error_set(err, CG_EINVAL, "scene: no scene, output or camera given");
    *out = NULL;
    if (scene_is_oblique(scene))
        return cg_error_set(
            err, CG_EUNSUPPORTED,
            "scene: the ray tracer draws perspective and orthogonal views only; "
            "render cavalier, cabinet and oblique projections with zbuffer or painter");
    cg_mat4 model;
    cg_status s = scene_view(scene, camera, &model);
    if (s != CG_OK)
        return cg_error_set(err, s, "scene: the camera cannot see the scene");
    open_depth_for_planes(scene, camera);
    cg_trace_scene *trace;
    if ((s = cg_trace_scene_create(&trace)) != CG_OK)
        return cg_error_set(err, s, "scene: cannot create the ray-tracing scene");
    for (size_t i = 0; i < scene->object_count && s == CG_OK; i++)
        if ((s = add_object(trace, scene, &scene->objects[i])) != CG_OK)
            cg_error_set(err, s, "scene: objects[%zu]: the ray tracer refused it (%s)", i,
                         cg_status_str(s));
    for (size_t i = 0; i < scene->light_count && s == CG_OK; i++)
        if ((s = cg_trace_scene_add_light(trace, &scene->lights[i])) != CG_OK)
            cg_error_set(err, s, "scene: lights[%zu]: the ray tracer refused it", i);
    for (size_t i = 0; i < scene->area_light_count && s == CG_OK; i++) {
        const cg_scene_area_light *a = &scene->area_lights[i];
        cg_trace_area_light light = {a->corner, a->edge_u, a->edge_v, a->color, a->samples};
        if ((s = cg_trace_scene_add_area_light(trace, &light)) != CG_OK)
            cg_error_set(err, s, "scene: an area light was refused");
    }
    if (s == CG_OK && default_lights && scene->light_count + scene->area_light_count == 0) {
        /* No lights given: the rasterizer's, its key light and a white
         * ambient light (scaled by each material's ka). */
        cg_mat4 view;
        cg_light ambient = cg_light_ambient(cg_vec3_make(1, 1, 1)), key;
        if ((s = cg_camera_view(camera, &view)) == CG_OK) {
            key = cg_render_key_light(view);
            s = cg_trace_scene_add_light(trace, &key);
        }
        if (s == CG_OK)
            s = cg_trace_scene_add_light(trace, &ambient);
    }
    if (s != CG_OK) {
        cg_trace_scene_free(trace);
        return s;
    }
    *out = trace;
    return CG_OK;
}

cg_status scene_render_trace(const cg_scene *scene, cg_image *image, cg_error *err)
{
    cg_camera camera;
    cg_trace_scene *trace;
    cg_status s = cg_scene_trace_scene(scene, 1, &trace, &camera, err);
    if (s != CG_OK)
        return s;
    cg_trace_options options = cg_trace_options_default();
    options.samples = scene->samples;
    options.max_depth = scene->max_depth;
    options.threads = scene->threads;
    options.shadows = scene->shadows;
    options.normals = scene->shading == CG_SCENE_FLAT ? CG_TRACE_FLAT : CG_TRACE_SMOOTH;
    options.background = scene->background;
    options.clip_depth = 1;
    if ((s = cg_trace_render(trace, &camera, &options, image, NULL)) != CG_OK)
        cg_error_set(err, s, "scene: ray tracing failed: %s", cg_status_str(s));
    cg_trace_scene_free(trace);
    return s;
}
