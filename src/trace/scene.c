/* Scenes for the ray tracer: meshes, spheres and planes with transforms and
 * materials, lights, and the nearest-hit and shadow queries over all of them.
 * Triangles of every mesh share one BVH (in world space); spheres and planes
 * are few and tested one by one. */
#include "internal.h"
#include "../core/array.h"
#include "cg/render.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

cg_trace_material cg_trace_material_default(void)
{
    cg_trace_material m;
    memset(&m, 0, sizeof m);
    m.surface = cg_material_make(cg_vec3_make(1, 1, 1), 1, 0.9, 0.2, 32);
    m.surface.specular = CG_SPECULAR_BLINN;
    return m;
}

static int finite3(cg_vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

static int material_valid(const cg_trace_material *m)
{
    if (cg_material_check(&m->surface, NULL) != CG_OK)
        return 0;
    if (!finite3(m->checker_color) || m->checker_color.x < 0 || m->checker_color.y < 0
        || m->checker_color.z < 0 || !isfinite(m->checker_size) || m->checker_size < 0)
        return 0;
    if (!finite3(m->emission) || m->emission.x < 0 || m->emission.y < 0 || m->emission.z < 0)
        return 0;
    return m->surface.reflectance <= 1 && m->surface.transmittance <= 1;
}

cg_status cg_trace_scene_create(cg_trace_scene **out)
{
    if (!out)
        return CG_EINVAL;
    *out = calloc(1, sizeof **out);
    return *out ? CG_OK : CG_ENOMEM;
}

void cg_trace_scene_free(cg_trace_scene *scene)
{
    if (!scene)
        return;
    free(scene->objects);
    free(scene->lights);
    free(scene->area_lights);
    free(scene->positions);
    free(scene->normals);
    free(scene->indices);
    free(scene->triangle_object);
    cg_bvh_free(scene->bvh);
    core_worker_pool_free(scene->pool);
    free(scene);
}

core_worker_pool *trace_scene_pool(cg_trace_scene *scene, int threads)
{
    if (threads < 2)
        return NULL;
    if (scene->pool_threads != threads) {
        core_worker_pool_free(scene->pool);
        if (core_worker_pool_create(threads, &scene->pool) != CG_OK)
            scene->pool = NULL;
        scene->pool_threads = threads;
    }
    return scene->pool;
}

/* An object of the kind with its material and centre (a plane's point),
 * everything else zero. */
static trace_object object_of(trace_kind kind, const cg_trace_material *material, cg_vec3 center)
{
    trace_object o;
    memset(&o, 0, sizeof o);
    o.kind = kind;
    o.material = *material;
    o.center = center;
    return o;
}

static cg_status add_object(cg_trace_scene *scene, const trace_object *object)
{
    if (core_array_reserve((void **)&scene->objects, &scene->object_capacity,
                           scene->object_count + 1, sizeof *scene->objects)
        != CG_OK)
        return CG_ENOMEM;
    scene->objects[scene->object_count++] = *object;
    cg_bvh_free(scene->bvh);
    scene->bvh = NULL;
    scene->built = 0;
    return CG_OK;
}

/* Upper-left 3x3 of m, for directions. */
static cg_mat3 linear_part(const cg_mat4 *m)
{
    cg_mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.m[i][j] = m->m[i][j];
    return r;
}

static int affine(const cg_mat4 *m)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            if (!isfinite(m->m[i][j]))
                return 0;
    return m->m[3][0] == 0 && m->m[3][1] == 0 && m->m[3][2] == 0 && m->m[3][3] == 1;
}

cg_status cg_trace_scene_add_mesh(cg_trace_scene *scene, const cg_mesh *mesh,
                                  const cg_mat4 *transform, double crease_angle,
                                  const cg_trace_material *material)
{
    if (!scene || !mesh || !material || !material_valid(material) || !(crease_angle >= 0))
        return CG_EINVAL;
    cg_mat4 model = transform ? *transform : cg_mat4_identity();
    cg_mat3 normal_matrix;
    if (!affine(&model) || cg_mat3_inverse(linear_part(&model), &normal_matrix) != CG_OK)
        return CG_EINVAL;
    normal_matrix = cg_mat3_transpose(normal_matrix);
    cg_status status = cg_mesh_validate_topology(mesh, NULL);
    if (status != CG_OK)
        return status;
    size_t triangles = cg_mesh_triangle_count(mesh);
    size_t v0 = scene->vertex_count, t0 = scene->triangle_count;
    if (mesh->vertex_count > UINT32_MAX - v0 || triangles > 0x7fffffff - t0)
        return CG_ERANGE;
    if (core_array_reserve((void **)&scene->positions, &scene->vertex_capacity,
                           v0 + mesh->vertex_count, sizeof *scene->positions)
            != CG_OK
        || core_array_reserve((void **)&scene->normals, &scene->normal_capacity,
                              3 * (t0 + triangles), sizeof *scene->normals)
               != CG_OK
        || core_array_reserve((void **)&scene->indices, &scene->index_capacity,
                              3 * (t0 + triangles), sizeof *scene->indices)
               != CG_OK
        || core_array_reserve((void **)&scene->triangle_object, &scene->triangle_object_capacity,
                              t0 + triangles, sizeof *scene->triangle_object)
               != CG_OK)
        return CG_ENOMEM;
    /* Normals at face corners: the file's vertex normals, or the
     * renderer's crease-angle normals (cg/render.h) when it has none. */
    cg_vec3 *corner = NULL;
    if (!mesh->normals) {
        corner = malloc((mesh->face_offsets[mesh->face_count] + 1) * sizeof *corner);
        if (!corner)
            return CG_ENOMEM;
        if ((status = cg_mesh_corner_normals(mesh, crease_angle, corner)) != CG_OK) {
            free(corner);
            return status;
        }
    }

    uint32_t(*corners)[3] = malloc((triangles ? triangles : 1) * sizeof *corners);
    if (!corners || cg_mesh_triangulate(mesh, corners) != CG_OK) {
        free(corners);
        free(corner);
        return CG_ENOMEM;
    }

    trace_object object = object_of(TRACE_MESH, material, cg_vec3_make(0, 0, 0));
    uint32_t object_index = (uint32_t)scene->object_count;
    for (size_t i = 0; i < mesh->vertex_count; i++)
        scene->positions[v0 + i] = cg_mat4_transform_point(model, mesh->positions[i]);
    uint32_t *idx = scene->indices + 3 * t0;
    cg_vec3 *n = scene->normals + 3 * t0;
    for (size_t t = 0; t < triangles; t++) {
        for (int j = 0; j < 3; j++) {
            uint32_t vertex = mesh->face_indices[corners[t][j]];
            idx[3 * t + j] = (uint32_t)v0 + vertex;
            cg_vec3 normal = corner ? corner[corners[t][j]] : mesh->normals[vertex];
            n[3 * t + j] = cg_vec3_normalize(cg_mat3_mul_vec3(normal_matrix, normal));
        }
        scene->triangle_object[t0 + t] = object_index;
    }
    free(corners);
    free(corner);
    object.first_triangle = t0;
    object.triangle_count = triangles;
    status = add_object(scene, &object);
    if (status != CG_OK)
        return status;
    scene->vertex_count = v0 + mesh->vertex_count;
    scene->triangle_count = t0 + triangles;
    return CG_OK;
}

cg_status cg_trace_scene_add_sphere(cg_trace_scene *scene, cg_vec3 center, double radius,
                                    const cg_mat4 *transform, const cg_trace_material *material)
{
    if (!scene || !material || !material_valid(material) || !finite3(center) || !isfinite(radius)
        || radius < 0)
        return CG_EINVAL;
    trace_object o = object_of(TRACE_SPHERE, material, center);
    o.radius = radius;
    o.to_world = transform ? *transform : cg_mat4_identity();
    if (!affine(&o.to_world) || cg_mat4_inverse(o.to_world, &o.to_object) != CG_OK)
        return CG_EINVAL;
    /* Normals go to world space by the inverse transpose. */
    o.normal_to_world = cg_mat3_transpose(linear_part(&o.to_object));
    return add_object(scene, &o);
}

cg_status cg_trace_scene_add_plane(cg_trace_scene *scene, cg_vec3 point, cg_vec3 normal,
                                   const cg_trace_material *material)
{
    if (!scene || !material || !material_valid(material) || !finite3(point) || !finite3(normal)
        || !(cg_vec3_length(normal) > 0))
        return CG_EINVAL;
    trace_object o = object_of(TRACE_PLANE, material, point);
    o.plane_normal = cg_vec3_normalize(normal);
    /* Two axes in the plane for its checker pattern. */
    cg_vec3 helper = fabs(o.plane_normal.x) < 0.9 ? cg_vec3_make(1, 0, 0) : cg_vec3_make(0, 1, 0);
    o.axis_u = cg_vec3_normalize(cg_vec3_cross(helper, o.plane_normal));
    o.axis_v = cg_vec3_cross(o.plane_normal, o.axis_u);
    return add_object(scene, &o);
}

cg_status cg_trace_scene_add_light(cg_trace_scene *scene, const cg_light *light)
{
    if (!scene || !light || cg_light_check(light, NULL) != CG_OK)
        return CG_EINVAL;
    if (core_array_reserve((void **)&scene->lights, &scene->light_capacity, scene->light_count + 1,
                           sizeof *scene->lights)
        != CG_OK)
        return CG_ENOMEM;
    scene->lights[scene->light_count++] = *light;
    return CG_OK;
}

cg_status cg_trace_scene_add_area_light(cg_trace_scene *scene, const cg_trace_area_light *light)
{
    if (!scene || !light || !finite3(light->corner) || !finite3(light->edge_u)
        || !finite3(light->edge_v) || !finite3(light->color) || light->color.x < 0
        || light->color.y < 0 || light->color.z < 0 || light->samples < 1 || light->samples > 64)
        return CG_EINVAL;
    if (core_array_reserve((void **)&scene->area_lights, &scene->area_light_capacity,
                           scene->area_light_count + 1, sizeof *scene->area_lights)
        != CG_OK)
        return CG_ENOMEM;
    scene->area_lights[scene->area_light_count++] = *light;
    return CG_OK;
}

cg_status cg_trace_scene_build(cg_trace_scene *scene, int threads, double *seconds)
{
    if (!scene || threads < 1)
        return CG_EINVAL;
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    if (!scene->built) {
        cg_bvh_free(scene->bvh);
        scene->bvh = NULL;
        cg_status status = trace_bvh_build(scene->positions, scene->vertex_count, scene->indices,
                                           scene->triangle_count, trace_scene_pool(scene, threads),
                                           &scene->bvh);
        if (status != CG_OK)
            return status;
        scene->built = 1;
    }
    clock_gettime(CLOCK_MONOTONIC, &b);
    if (seconds)
        *seconds = (double)(b.tv_sec - a.tv_sec) + (double)(b.tv_nsec - a.tv_nsec) * 1e-9;
    return CG_OK;
}

/* A box growing to hold points; empty until the first finite point. */
typedef struct bounds_box {
    int any;
    cg_vec3 lo, hi;
} bounds_box;

/* Grows box to hold p; points that are not finite are left out. */
static inline void bounds_add(bounds_box *box, cg_vec3 p)
{
    if (!finite3(p))
        return;
    if (!box->any) {
        box->lo = box->hi = p;
        box->any = 1;
    }
    box->lo = cg_vec3_make(fmin(box->lo.x, p.x), fmin(box->lo.y, p.y), fmin(box->lo.z, p.z));
    box->hi = cg_vec3_make(fmax(box->hi.x, p.x), fmax(box->hi.y, p.y), fmax(box->hi.z, p.z));
}

cg_status cg_trace_scene_bounds(const cg_trace_scene *scene, cg_vec3 *lo, cg_vec3 *hi)
{
    if (!scene || !lo || !hi)
        return CG_EINVAL;
    bounds_box box = {0, {0, 0, 0}, {0, 0, 0}};
    for (size_t i = 0; i < 3 * scene->triangle_count; i++)
        bounds_add(&box, scene->positions[scene->indices[i]]);
    for (size_t i = 0; i < scene->object_count; i++) {
        const trace_object *o = &scene->objects[i];
        if (o->kind != TRACE_SPHERE || o->radius == 0)
            continue;
        for (int corner = 0; corner < 8; corner++) {
            cg_vec3 c = cg_vec3_make(corner & 1 ? o->radius : -o->radius,
                                     corner & 2 ? o->radius : -o->radius,
                                     corner & 4 ? o->radius : -o->radius);
            bounds_add(&box, cg_mat4_transform_point(o->to_world, cg_vec3_add(o->center, c)));
        }
    }
    if (!box.any)
        return CG_EEMPTY;
    *lo = box.lo;
    *hi = box.hi;
    return CG_OK;
}

/* ---- queries --------------------------------------------------------------- */

/* Nearest t in (t_min, t_max] on the sphere, in the parameter of the world ray. */
static int sphere_hit(const trace_object *o, cg_vec3 origin, cg_vec3 direction, double t_min,
                      double t_max, double *t_out)
{
    if (o->radius == 0)
        return 0;
    cg_vec3 ob = cg_mat4_transform_point(o->to_object, origin);
    cg_vec3 db = cg_mat4_transform_vector(o->to_object, direction);
    cg_vec3 f = cg_vec3_sub(ob, o->center);
    double a = cg_vec3_dot(db, db);
    if (!(a > 0))
        return 0;
    double b = -cg_vec3_dot(f, db); /* half of the usual -b */
    /* The discriminant from the distance of the centre to the ray line,
     * which stays accurate for small spheres far away (Haines et al.,
     * "Precision improvements for ray/sphere intersection"). */
    cg_vec3 l = cg_vec3_add(f, cg_vec3_scale(db, b / a));
    double disc = a * (o->radius * o->radius - cg_vec3_dot(l, l));
    if (!(disc >= 0))
        return 0;
    double s = sqrt(disc);
    double q = b + (b >= 0 ? s : -s);
    double c = cg_vec3_dot(f, f) - o->radius * o->radius;
    double t0 = q / a, t1 = q != 0 ? c / q : t0;
    if (t0 > t1) {
        double x = t0;
        t0 = t1;
        t1 = x;
    }
    if (t0 > t_min && t0 <= t_max) {
        *t_out = t0;
        return 1;
    }
    if (t1 > t_min && t1 <= t_max) {
        *t_out = t1;
        return 1;
    }
    return 0;
}

static int plane_hit(const trace_object *o, cg_vec3 origin, cg_vec3 direction, double t_min,
                     double t_max, double *t_out)
{
    double denominator = cg_vec3_dot(direction, o->plane_normal);
    if (denominator == 0)
        return 0;
    double t = cg_vec3_dot(cg_vec3_sub(o->center, origin), o->plane_normal) / denominator;
    if (!(t > t_min && t <= t_max))
        return 0;
    *t_out = t;
    return 1;
}

static double max_abs(cg_vec3 v)
{
    return fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
}

int trace_intersect(const cg_trace_scene *scene, cg_vec3 origin, cg_vec3 direction, double t_min,
                    double t_max, trace_hit *hit)
{
    if (!finite3(origin) || !finite3(direction))
        return 0;
    int found = 0;
    cg_bvh_hit bh;
    if (scene->bvh && cg_bvh_intersect(scene->bvh, origin, direction, t_min, t_max, &bh)) {
        found = 1;
        t_max = bh.t;
        hit->t = bh.t;
        hit->object = (int)scene->triangle_object[bh.triangle];
        hit->triangle = bh.triangle;
        hit->u = bh.u;
        hit->v = bh.v;
    }
    for (size_t i = 0; i < scene->object_count; i++) {
        const trace_object *o = &scene->objects[i];
        double t;
        int h = o->kind == TRACE_SPHERE  ? sphere_hit(o, origin, direction, t_min, t_max, &t)
                : o->kind == TRACE_PLANE ? plane_hit(o, origin, direction, t_min, t_max, &t)
                                         : 0;
        if (h && (t < t_max || !found)) {
            found = 1;
            t_max = t;
            hit->t = t;
            hit->object = (int)i;
        }
    }
    if (!found)
        return 0;
    const trace_object *o = &scene->objects[hit->object];
    if (o->kind == TRACE_MESH) {
        const uint32_t *c = scene->indices + 3 * (size_t)hit->triangle;
        /* Single-precision corners, as the BVH tested them. */
        cg_vec3 p[3];
        for (int k = 0; k < 3; k++) {
            cg_vec3 q = scene->positions[c[k]];
            p[k] = cg_vec3_make((float)q.x, (float)q.y, (float)q.z);
        }
        double w0 = 1 - hit->u - hit->v;
        /* The point from the barycentric weights lies on the triangle's
         * plane up to rounding of the corner coordinates, however far the
         * ray travelled. */
        hit->point = cg_vec3_add(cg_vec3_add(cg_vec3_scale(p[0], w0), cg_vec3_scale(p[1], hit->u)),
                                 cg_vec3_scale(p[2], hit->v));
        hit->normal = cg_vec3_normalize(
            cg_vec3_cross(cg_vec3_sub(p[1], p[0]), cg_vec3_sub(p[2], p[0])));
        const cg_vec3 *cn = scene->normals + 3 * (size_t)hit->triangle;
        cg_vec3 sn = cg_vec3_add(
            cg_vec3_add(cg_vec3_scale(cn[0], w0), cg_vec3_scale(cn[1], hit->u)),
            cg_vec3_scale(cn[2], hit->v));
        sn = cg_vec3_normalize(sn);
        hit->smooth_normal = cg_vec3_length(sn) > 0 ? sn : hit->normal;
        hit->scale = fmax(max_abs(p[0]), fmax(max_abs(p[1]), max_abs(p[2])));
    } else if (o->kind == TRACE_SPHERE) {
        cg_vec3 ob = cg_mat4_transform_point(o->to_object, origin);
        cg_vec3 db = cg_mat4_transform_vector(o->to_object, direction);
        cg_vec3 local = cg_vec3_sub(cg_vec3_add(ob, cg_vec3_scale(db, hit->t)), o->center);
        cg_vec3 n = cg_vec3_normalize(local);
        /* Projected back onto the sphere. */
        hit->point = cg_mat4_transform_point(o->to_world,
                                             cg_vec3_add(o->center, cg_vec3_scale(n, o->radius)));
        hit->normal = cg_vec3_normalize(cg_mat3_mul_vec3(o->normal_to_world, n));
        hit->smooth_normal = hit->normal;
        hit->scale = max_abs(hit->point);
    } else {
        hit->point = cg_vec3_add(origin, cg_vec3_scale(direction, hit->t));
        /* Projected back onto the plane. */
        hit->point = cg_vec3_sub(
            hit->point,
            cg_vec3_scale(o->plane_normal,
                          cg_vec3_dot(cg_vec3_sub(hit->point, o->center), o->plane_normal)));
        hit->normal = o->plane_normal;
        hit->smooth_normal = hit->normal;
        hit->scale = fmax(max_abs(hit->point), max_abs(o->center));
    }
    return 1;
}

int trace_occluded(const cg_trace_scene *scene, cg_vec3 origin, cg_vec3 direction, double t_min,
                   double t_max)
{
    for (size_t i = 0; i < scene->object_count; i++) {
        const trace_object *o = &scene->objects[i];
        double t;
        if (o->kind == TRACE_SPHERE && sphere_hit(o, origin, direction, t_min, t_max, &t)
            && t < t_max)
            return 1;
        if (o->kind == TRACE_PLANE && plane_hit(o, origin, direction, t_min, t_max, &t)
            && t < t_max)
            return 1;
    }
    return scene->bvh && cg_bvh_occluded(scene->bvh, origin, direction, t_min, t_max);
}

cg_vec3 trace_offset(const trace_hit *hit, cg_vec3 normal)
{
    /* 2^-16 of the largest coordinate magnitude: about 128 units in the last
     * place of the single-precision geometry, whatever the scene's scale. */
    double scale = hit->scale * (1.0 / 65536);
    if (!(scale > 0))
        scale = 1e-300;
    return cg_vec3_add(hit->point, cg_vec3_scale(normal, scale));
}
