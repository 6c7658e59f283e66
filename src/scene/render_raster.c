/* A scene through the rasterizer: every object becomes part of one mesh in
 * world space (spheres and boxes tessellated, planes as a large square around
 * the scene), coloured per face by its material, and the scene's lights are
 * given to the renderer as directional lights. */
#include "internal.h"
#include "checker.h"
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
    case CG_SCENE_MESH: *mesh = o->mesh; return o->mesh ? CG_OK : CG_EINVAL;
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
    case CG_SCENE_BOX: s = cg_mesh_box(o->lo, o->hi, owned); break;
    case CG_SCENE_PLANE: s = plane_mesh(o, center, radius, owned); break;
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
        all->face_colors[*faces + f] = keep_face_colors && part->face_colors ? part->face_colors[f]
                                                                             : color;
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

/* part under transform, as a new mesh (positions and faces only). */
static cg_status world_copy(const cg_mesh *part, cg_mat4 transform, cg_mesh **out)
{
    size_t corners = part->face_offsets[part->face_count];
    cg_status s = cg_mesh_create(out, part->vertex_count, part->face_count, corners, 0);
    if (s != CG_OK)
        return s;
    for (size_t i = 0; i < part->vertex_count; i++)
        (*out)->positions[i] = cg_mat4_transform_point(transform, part->positions[i]);
    memcpy((*out)->face_offsets, part->face_offsets, (part->face_count + 1) * sizeof(uint32_t));
    memcpy((*out)->face_indices, part->face_indices, corners * sizeof(uint32_t));
    return CG_OK;
}

static cg_rgbaf opaque(cg_vec3 c)
{
    cg_rgbaf r = {(float)c.x, (float)c.y, (float)c.z, 1};
    return r;
}

/* The cells of a checker material on object o, as the ray tracer draws them:
 * a plane's own axes from its (transformed) point, the world axes for the
 * others. */
static checker_frame object_checker(const cg_scene_object *o, double size)
{
    checker_frame f;
    memset(&f, 0, sizeof f);
    f.size = size;
    if (o->kind == CG_SCENE_PLANE) {
        cg_mat4 inverse;
        cg_vec3 n = o->normal;
        if (cg_mat4_inverse(o->transform, &inverse) == CG_OK)
            n = cg_mat4_transform_vector(cg_mat4_transpose(inverse), o->normal);
        n = cg_vec3_normalize(n);
        cg_vec3 helper = fabs(n.x) < 0.9 ? cg_vec3_make(1, 0, 0) : cg_vec3_make(0, 1, 0);
        f.origin = cg_mat4_transform_point(o->transform, o->point);
        f.axis[0] = cg_vec3_normalize(cg_vec3_cross(helper, n));
        f.axis[1] = cg_vec3_cross(n, f.axis[0]);
        f.axes = 2;
    } else {
        f.axis[0] = cg_vec3_make(1, 0, 0);
        f.axis[1] = cg_vec3_make(0, 1, 0);
        f.axis[2] = cg_vec3_make(0, 0, 1);
        f.axes = 3;
    }
    return f;
}

/* The geometry of object i for the rasterizer: *mesh (NULL: nothing to draw)
 * with *transform to apply; a checker material is cut into its cells in
 * world space (then the transform is the identity). */
static cg_status raster_part(const cg_scene *scene, size_t i, cg_vec3 center, double radius,
                             const cg_mesh **mesh, cg_mesh **owned, cg_mat4 *transform)
{
    const cg_scene_object *o = &scene->objects[i];
    const cg_scene_material *m = &scene->materials[o->material];
    *transform = o->transform;
    cg_status s = object_mesh(o, center, radius, mesh, owned);
    if (s != CG_OK || !*mesh || !(m->checker_size > 0))
        return s;
    cg_mesh *world, *cells;
    if ((s = world_copy(*mesh, o->transform, &world)) != CG_OK)
        return s;
    checker_frame frame = object_checker(o, m->checker_size);
    s = scene_checker_split(world, &frame, opaque(m->surface.color), opaque(m->checker_color),
                            &cells);
    cg_mesh_free(world);
    cg_mesh_free(*owned);
    *owned = cells;
    *mesh = cells;
    *transform = cg_mat4_identity();
    return s;
}

cg_status scene_world_mesh(const cg_scene *scene, cg_mesh **out, uint32_t **face_material,
                           cg_error *err)
{
    cg_vec3 center;
    double radius;
    scene_plane_extent(scene, &center, &radius);
    size_t n = scene->object_count;
    const cg_mesh **parts = calloc(n ? n : 1, sizeof *parts);
    cg_mesh **owned = calloc(n ? n : 1, sizeof *owned);
    cg_mat4 *transforms = calloc(n ? n : 1, sizeof *transforms);
    cg_status s = parts && owned && transforms ? CG_OK : CG_ENOMEM;
    size_t vertex_total = 0, face_total = 0, corner_total = 0;
    for (size_t i = 0; i < n && s == CG_OK; i++) {
        s = raster_part(scene, i, center, radius, &parts[i], &owned[i], &transforms[i]);
        if (s == CG_ERANGE)
            cg_error_set(err, s,
                         "scene: objects[%zu]: the checker's cells are too small for the "
                         "rasterizer to cut the object into (over 4 million pieces)",
                         i);
        if (s == CG_OK && parts[i]) {
            vertex_total += parts[i]->vertex_count;
            face_total += parts[i]->face_count;
            corner_total += parts[i]->face_offsets[parts[i]->face_count];
        }
    }
    if (s == CG_OK)
        s = cg_mesh_create(out, vertex_total, face_total, corner_total, CG_MESH_FACE_COLORS);
    if (s == CG_OK && face_material
        && !(*face_material = malloc((face_total ? face_total : 1) * sizeof **face_material))) {
        cg_mesh_free(*out);
        *out = NULL;
        s = CG_ENOMEM;
    }
    if (s == CG_OK) {
        size_t vertices = 0, faces = 0, corners = 0;
        for (size_t i = 0; i < n; i++) {
            if (!parts[i])
                continue;
            const cg_scene_object *o = &scene->objects[i];
            cg_rgbaf color = opaque(scene->materials[o->material].surface.color);
            int checkered = scene->materials[o->material].checker_size > 0;
            size_t first_face = faces;
            append(*out, parts[i], transforms[i], color, o->material == 0 || checkered, &vertices,
                   &faces, &corners);
            if (cg_mat4_determinant(o->transform) < 0)
                reverse_faces(*out, first_face, faces - first_face);
            for (size_t f = first_face; face_material && f < faces; f++)
                (*face_material)[f] = (uint32_t)o->material;
        }
    }
    for (size_t i = 0; owned && i < n; i++)
        cg_mesh_free(owned[i]);
    free(owned);
    free(parts);
    free(transforms);
    if (s == CG_ERANGE)
        return s;
    if (s != CG_OK)
        return cg_error_set(err, s, "scene: cannot build the mesh to rasterize: %s",
                            cg_status_str(s));
    return CG_OK;
}

cg_status cg_scene_world_mesh(const cg_scene *scene, cg_mesh **out, cg_error *err)
{
    if (!scene || !out)
        return cg_error_set(err, CG_EINVAL, "scene: no scene or output given");
    return scene_world_mesh(scene, out, NULL, err);
}

/* The renderer's lights from the scene's: directional lights as they are,
 * point, spot and area lights as seen from the scene's centre, at the
 * strength of their strongest channel. */
static void renderer_lights(const cg_scene *scene, cg_render_options *o)
{
    cg_vec3 lo, hi;
    scene_bounds(scene, &lo, &hi);
    cg_vec3 center = cg_vec3_scale(cg_vec3_add(lo, hi), 0.5);
    o->light_count = 0;
    for (size_t i = 0; i < scene->light_count; i++) {
        const cg_light *l = &scene->lights[i];
        double strength = fmax(l->color.x, fmax(l->color.y, l->color.z));
        if (l->kind == CG_LIGHT_AMBIENT)
            continue; /* scene_material_options: ambient light times ka */
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
        cg_vec3 middle = cg_vec3_add(a->corner,
                                     cg_vec3_scale(cg_vec3_add(a->edge_u, a->edge_v), 0.5));
        cg_vec3 toward = cg_vec3_sub(middle, center);
        if (cg_vec3_length(toward) > 0) {
            cg_render_light r = {toward, fmax(a->color.x, fmax(a->color.y, a->color.z))};
            o->lights[o->light_count++] = r;
        }
    }
}

cg_status scene_raster_base_options(const cg_scene *scene, cg_scene_algorithm algorithm,
                                    cg_render_options *o, cg_error *err)
{
    cg_render_options_default(o);
    cg_status s = scene_view(scene, &o->camera, &o->model);
    if (s != CG_OK)
        return cg_error_set(err, s,
                            "scene: the camera cannot see the scene (eye, target and up "
                            "must not be degenerate)");
    o->frame_camera = 0;
    o->algorithm = algorithm == CG_SCENE_PAINTER ? CG_RENDER_PAINTER : CG_RENDER_ZBUFFER;
    o->shading = scene->shading == CG_SCENE_FLAT    ? CG_SHADING_FLAT
                 : scene->shading == CG_SCENE_PHONG ? CG_SHADING_PHONG
                                                    : CG_SHADING_GOURAUD;
    o->cull = scene->cull_back ? CG_CULL_BACK : CG_CULL_NONE;
    o->edges = (cg_edge_mode)scene->edges;
    o->threads = scene->threads;
    if (scene->msaa > 1 && o->algorithm != CG_RENDER_ZBUFFER)
        return cg_error_set(err, CG_EUNSUPPORTED,
                            "scene: render.msaa: the painter's algorithm draws one sample per "
                            "pixel (use the zbuffer algorithm, or msaa 1)");
    o->msaa = scene->msaa;
    o->background = scene->background;
    renderer_lights(scene, o);
    return CG_OK;
}

cg_status cg_scene_raster_options(const cg_scene *scene, cg_scene_algorithm algorithm,
                                  cg_render_options *o, cg_error *err)
{
    if (!scene || !o)
        return cg_error_set(err, CG_EINVAL, "scene: no scene or options given");
    cg_status s = scene_raster_base_options(scene, algorithm, o, err);
    if (s != CG_OK)
        return s;
    /* One material for the whole mesh: the first object's. */
    size_t m = scene->object_count ? scene->objects[0].material : 0;
    return scene_material_options(scene, &scene->materials[m].surface, o, err);
}
