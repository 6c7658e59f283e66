/* A scene through the rasterizer: every object becomes part of one mesh in
 * world space (spheres and boxes tessellated, planes as a large square around
 * the scene), coloured per face by its material, and the scene's lights are
 * given to the renderer as directional lights. */
#include "internal.h"
#include "view.h"
#include "cg/render.h"

#include <stdlib.h>
#include <string.h>

/* Tessellation of spheres for the rasterizer. */
#define SPHERE_SLICES 96
#define SPHERE_STACKS 48

/* The square standing for an infinite plane (scene_plane_square). */
static cg_status plane_mesh(const cg_scene_object *o, cg_vec3 center, double radius, cg_mesh **out)
{
    cg_vec3 corners[4];
    scene_plane_square(o, center, radius, corners);
    cg_status s = cg_mesh_create(out, 4, 1, 4, 0);
    if (s != CG_OK)
        return s;
    cg_mesh *m = *out;
    for (uint32_t k = 0; k < 4; k++) {
        m->positions[k] = corners[k];
        m->face_indices[k] = k;
    }
    m->face_offsets[1] = 4;
    return CG_OK;
}

/* The object's own geometry in object space (before its transform); for a
 * mesh object the loaded mesh itself (*owned stays 0). */
static cg_status object_mesh(const cg_scene_object *o, cg_vec3 center, double radius,
                             const cg_mesh **mesh, cg_mesh **owned)
{
    *owned = NULL;
    cg_status s = CG_OK;
    switch (o->kind) {
    case CG_SCENE_MESH:
        *mesh = o->mesh;
        return o->mesh ? CG_OK : CG_EINVAL;
    case CG_SCENE_SPHERE:
        if (o->radius <= 0) { /* an invisible sphere */
            *mesh = NULL;
            return CG_OK;
        }
        s = cg_mesh_sphere(SPHERE_SLICES, SPHERE_STACKS, o->radius, owned);
        if (s == CG_OK)
            for (size_t i = 0; i < (*owned)->vertex_count; i++)
                (*owned)->positions[i] = cg_vec3_add((*owned)->positions[i], o->center);
        break;
    case CG_SCENE_BOX:
        s = cg_mesh_box(o->lo, o->hi, owned);
        break;
    case CG_SCENE_PLANE:
        s = plane_mesh(o, center, radius, owned);
        break;
    }
    *mesh = *owned;
    return s;
}

/* Appends part (transformed, coloured) to the combined mesh at the given
 * vertex, face and corner positions. */
static void append(cg_mesh *all, const cg_mesh *part, cg_mat4 transform, cg_rgbaf color,
                   int keep_face_colors, size_t *vertices, size_t *faces, size_t *corners)
{
    uint32_t base = (uint32_t)*vertices;
    for (size_t i = 0; i < part->vertex_count; i++)
        all->positions[*vertices + i] = cg_mat4_transform_point(transform, part->positions[i]);
    for (size_t f = 0; f < part->face_count; f++) {
        uint32_t begin = part->face_offsets[f], end = part->face_offsets[f + 1];
        for (uint32_t k = begin; k < end; k++)
            all->face_indices[*corners + (k - begin)] = base + part->face_indices[k];
        *corners += end - begin;
        all->face_offsets[*faces + f + 1] = (uint32_t)*corners;
        all->face_colors[*faces + f] =
            keep_face_colors && part->face_colors ? part->face_colors[f] : color;
    }
    *vertices += part->vertex_count;
    *faces += part->face_count;
}

/* A mirror (negative determinant) turns counter-clockwise faces clockwise:
 * such objects get their faces reversed so that culling still works. */
static void reverse_faces(cg_mesh *all, size_t first_face, size_t face_count)
{
    for (size_t f = first_face; f < first_face + face_count; f++) {
        uint32_t *a = all->face_indices + all->face_offsets[f];
        uint32_t *b = all->face_indices + all->face_offsets[f + 1] - 1;
        for (; a < b; a++, b--) {
            uint32_t t = *a;
            *a = *b;
            *b = t;
        }
    }
}

cg_status cg_scene_world_mesh(const cg_scene *scene, cg_mesh **out, cg_error *err)
{
    if (!scene || !out)
        return cg_error_set(err, CG_EINVAL, "scene: no scene or output given");
    cg_vec3 center;
    double radius;
    scene_plane_extent(scene, &center, &radius);
    size_t n = scene->object_count;
    const cg_mesh **parts = calloc(n ? n : 1, sizeof *parts);
    cg_mesh **owned = calloc(n ? n : 1, sizeof *owned);
    cg_status s = parts && owned ? CG_OK : CG_ENOMEM;
    size_t vertex_total = 0, face_total = 0, corner_total = 0;
    for (size_t i = 0; i < n && s == CG_OK; i++) {
        s = object_mesh(&scene->objects[i], center, radius, &parts[i], &owned[i]);
        if (s == CG_OK && parts[i]) {
            vertex_total += parts[i]->vertex_count;
            face_total += parts[i]->face_count;
            corner_total += parts[i]->face_offsets[parts[i]->face_count];
        }
    }
    if (s == CG_OK)
        s = cg_mesh_create(out, vertex_total, face_total, corner_total, CG_MESH_FACE_COLORS);
    if (s == CG_OK) {
        size_t vertices = 0, faces = 0, corners = 0;
        for (size_t i = 0; i < n; i++) {
            if (!parts[i])
                continue;
            const cg_scene_object *o = &scene->objects[i];
            cg_vec3 c = scene->materials[o->material].surface.color;
            cg_rgbaf color = {(float)c.x, (float)c.y, (float)c.z, 1};
            size_t first_face = faces;
            append(*out, parts[i], o->transform, color, o->material == 0, &vertices, &faces, &corners);
            if (cg_mat4_determinant(o->transform) < 0)
                reverse_faces(*out, first_face, faces - first_face);
        }
    }
    for (size_t i = 0; owned && i < n; i++)
        cg_mesh_free(owned[i]);
    free(owned);
    free(parts);
    if (s != CG_OK)
        return cg_error_set(err, s, "scene: cannot build the mesh to rasterize: %s",
                            cg_status_str(s));
    return CG_OK;
}

/* The renderer's lights from the scene's: directional lights as they are,
 * point, spot and area lights as seen from the scene's centre. */
static void renderer_lights(const cg_scene *scene, cg_render_options *o)
{
    cg_vec3 lo, hi;
    scene_bounds(scene, &lo, &hi);
    cg_vec3 center = cg_vec3_scale(cg_vec3_add(lo, hi), 0.5);
    double ambient = 0;
    int have_ambient = 0;
    o->light_count = 0;
    for (size_t i = 0; i < scene->light_count; i++) {
        const cg_light *l = &scene->lights[i];
        double strength = fmax(l->color.x, fmax(l->color.y, l->color.z));
        if (l->kind == CG_LIGHT_AMBIENT) {
            ambient += strength;
            have_ambient = 1;
            continue;
        }
        if (o->light_count == CG_RENDER_MAX_LIGHTS)
            continue;
        cg_vec3 toward = l->kind == CG_LIGHT_DIRECTIONAL ? cg_vec3_scale(l->direction, -1)
                                                         : cg_vec3_sub(l->position, center);
        if (!(cg_vec3_length(toward) > 0))
            continue;
        cg_render_light r = {toward, strength};
        o->lights[o->light_count++] = r;
    }
    for (size_t i = 0; i < scene->area_light_count && o->light_count < CG_RENDER_MAX_LIGHTS; i++) {
        const cg_scene_area_light *a = &scene->area_lights[i];
        cg_vec3 middle = cg_vec3_add(a->corner, cg_vec3_scale(cg_vec3_add(a->edge_u, a->edge_v), 0.5));
        cg_vec3 toward = cg_vec3_sub(middle, center);
        if (cg_vec3_length(toward) > 0) {
            cg_render_light r = {toward, fmax(a->color.x, fmax(a->color.y, a->color.z))};
            o->lights[o->light_count++] = r;
        }
    }
    /* The surface terms come from the first object's material. */
    const cg_material *m = &scene->materials[scene->object_count ? scene->objects[0].material : 0].surface;
    if (have_ambient)
        o->ambient = ambient * m->ka;
    o->specular = m->ks;
    o->shininess = m->shininess;
}

cg_status cg_scene_raster_options(const cg_scene *scene, cg_scene_algorithm algorithm,
                                  cg_render_options *o, cg_error *err)
{
    if (!scene || !o)
        return cg_error_set(err, CG_EINVAL, "scene: no scene or options given");
    cg_render_options_default(o);
    cg_status s = scene_view(scene, &o->camera, &o->model);
    if (s != CG_OK)
        return cg_error_set(err, s, "scene: the camera cannot see the scene (eye, target and up "
                                    "must not be degenerate)");
    o->frame_camera = 0;
    o->algorithm = algorithm == CG_SCENE_PAINTER ? CG_RENDER_PAINTER : CG_RENDER_ZBUFFER;
    o->shading = scene->shading == CG_SCENE_FLAT ? CG_SHADING_FLAT
               : scene->shading == CG_SCENE_PHONG ? CG_SHADING_PHONG : CG_SHADING_GOURAUD;
    o->cull = scene->cull_back ? CG_CULL_BACK : CG_CULL_NONE;
    o->edges = (cg_edge_mode)scene->edges;
    o->threads = scene->threads;
    o->background = scene->background;
    renderer_lights(scene, o);
    return CG_OK;
}

cg_status scene_render_raster(const cg_scene *scene, cg_scene_algorithm algorithm, cg_image *image,
                              cg_error *err)
{
    cg_render_options o;
    cg_status s = cg_scene_raster_options(scene, algorithm, &o, err);
    if (s != CG_OK)
        return s;
    cg_mesh *world = NULL;
    if ((s = cg_scene_world_mesh(scene, &world, err)) != CG_OK)
        return s;
    s = cg_render(world, &o, image, err);
    cg_mesh_free(world);
    return s;
}
