/* A scene's materials under the rasterizer.  The renderer lights a whole mesh
 * with one set of surface terms; a scene's objects each have their own.  So
 * the z-buffer and the painter's algorithm draw the scene once per material
 * used, lit with that material's terms, and once more with every face
 * coloured by the number of its material (no lighting); each pixel is then
 * taken from the pass of the material that is visible there.  Visibility does
 * not depend on colours or lights, so every pass shows the same face at each
 * pixel, and the picture is the one a renderer with per-face materials would
 * draw.
 *
 * What the rasterizer cannot mean the same way is refused by name: mirror
 * reflection and refraction (reflectance, transmittance), the Phong specular
 * model (the renderer's is Blinn-Phong) and a specular colour that is not
 * grey.  The checker pattern is geometry (checker.c). */
#include "internal.h"

#include "cg/render.h"

#include <stdlib.h>
#include <string.h>

/* Below this, kd counts as this, so that ks / kd stays finite; the diffuse
 * term it adds is under 1e-6 of the light. */
#define MIN_KD 1e-6

cg_status scene_material_options(const cg_scene *scene, const cg_material *m, cg_render_options *o,
                                 cg_error *err)
{
    double ambient = 0;
    for (size_t i = 0; i < scene->light_count; i++) {
        const cg_light *l = &scene->lights[i];
        if (l->kind == CG_LIGHT_AMBIENT)
            ambient += fmax(l->color.x, fmax(l->color.y, l->color.z));
    }
    double kd = fmax(m->kd, MIN_KD);
    if (scene->light_count + scene->area_light_count == 0) {
        /* The ray tracer's lights for a scene without any. */
        cg_mat4 view;
        if (cg_camera_view(&o->camera, &view) != CG_OK)
            return cg_error_set(err, CG_EINVAL, "scene: the camera cannot see the scene");
        cg_light key = cg_render_key_light(view);
        cg_render_light toward = {cg_vec3_scale(key.direction, -1), key.color.x};
        o->lights[0] = toward;
        o->light_count = 1;
        ambient = 1;
    } else if (o->light_count == 0) {
        /* Ambient light only: no light for the renderer's diffuse term. */
        cg_render_light none = {cg_vec3_make(0, 1, 0), 0};
        o->lights[0] = none;
        o->light_count = 1;
    }
    for (int i = 0; i < o->light_count; i++)
        o->lights[i].intensity *= kd;
    o->ambient = ambient * m->ka;
    o->specular = m->ks * m->specular_color.x / kd;
    o->shininess = m->shininess;
    return CG_OK;
}

/* The name of material index i for messages. */
static const char *material_name(const cg_scene *scene, size_t i)
{
    return i == 0 || !scene->materials[i].name ? "(the default material)"
                                               : scene->materials[i].name;
}

/* CG_EUNSUPPORTED, with the material and the key, for a property the
 * rasterizer cannot draw as the ray tracer does. */
static cg_status check_material(const cg_scene *scene, size_t i, cg_error *err)
{
    const cg_material *m = &scene->materials[i].surface;
    const char *name = material_name(scene, i);
    const char *hint = "render this scene with raytrace";
    if (m->reflectance > 0)
        return cg_error_set(err, CG_EUNSUPPORTED,
                            "scene: materials.%s.reflectance: the z-buffer "
                            "and the painter's algorithm draw no reflections (%s)",
                            name, hint);
    if (m->transmittance > 0)
        return cg_error_set(err, CG_EUNSUPPORTED,
                            "scene: materials.%s.transmittance: the z-buffer "
                            "and the painter's algorithm draw no refraction (%s)",
                            name, hint);
    if (m->ks > 0 && m->specular != CG_SPECULAR_BLINN)
        return cg_error_set(err, CG_EUNSUPPORTED,
                            "scene: materials.%s.specular: the rasterizer's "
                            "highlights are Blinn-Phong (use \"blinn\", or %s)",
                            name, hint);
    if (m->ks > 0
        && (m->specular_color.x != m->specular_color.y
            || m->specular_color.x != m->specular_color.z))
        return cg_error_set(err, CG_EUNSUPPORTED,
                            "scene: materials.%s.specular_color: the "
                            "rasterizer's highlights are grey (use equal components, or %s)",
                            name, hint);
    return CG_OK;
}

/* One frame of world with options into image. */
static cg_status draw(const cg_mesh *world, const cg_render_options *o, cg_image *image,
                      cg_error *err)
{
    return cg_render(world, o, image, err);
}

/* The pass that tells which material each pixel shows: face colours encode
 * material index + 1 in steps of 1/256 (exact in float), the background 0. */
static cg_status material_pass(const cg_mesh *world, const uint32_t *face_material,
                               const cg_render_options *base, cg_image *ids, cg_error *err)
{
    cg_mesh *coded;
    size_t corners = world->face_offsets[world->face_count];
    cg_status s = cg_mesh_create(&coded, world->vertex_count, world->face_count, corners,
                                 CG_MESH_FACE_COLORS | CG_MESH_NORMALS);
    if (s != CG_OK)
        return cg_error_set(err, s, "scene: out of memory for the material pass");
    memcpy(coded->positions, world->positions, world->vertex_count * sizeof *world->positions);
    /* Flat shading never reads vertex normals: given ones spare the
     * renderer computing them. */
    for (size_t v = 0; v < world->vertex_count; v++)
        coded->normals[v] = cg_vec3_make(0, 0, 1);
    memcpy(coded->face_offsets, world->face_offsets, (world->face_count + 1) * sizeof(uint32_t));
    memcpy(coded->face_indices, world->face_indices, corners * sizeof(uint32_t));
    for (size_t f = 0; f < world->face_count; f++) {
        uint32_t code = face_material[f] + 1;
        cg_rgbaf c = {(float)(code & 255) / 256, (float)((code >> 8) & 255) / 256,
                      (float)((code >> 16) & 255) / 256, 1};
        coded->face_colors[f] = c;
    }
    cg_render_options o = *base;
    o.shading = CG_SHADING_FLAT;
    o.edges = CG_EDGES_NONE;
    o.msaa = 1; /* codes, not colours: never averaged */
    o.ambient = 1;
    o.specular = 0;
    o.light_count = 1;
    o.lights[0].direction = cg_vec3_make(0, 1, 0);
    o.lights[0].intensity = 0;
    o.progress = NULL;
    cg_rgbaf black = {0, 0, 0, 1};
    o.background = black;
    s = draw(coded, &o, ids, err);
    cg_mesh_free(coded);
    return s;
}

static uint32_t decode(const float *pixel)
{
    return (uint32_t)(pixel[0] * 256 + 0.5f) | (uint32_t)(pixel[1] * 256 + 0.5f) << 8
           | (uint32_t)(pixel[2] * 256 + 0.5f) << 16;
}

/* Draws one pass per material used and keeps each one's pixels; the mesh
 * is prepared once for all of them. */
static cg_status material_passes(const cg_scene *scene, const cg_mesh *world,
                                 const uint32_t *face_material, const unsigned char *used,
                                 const cg_render_options *base, cg_image *image, cg_error *err)
{
    int w = image->width, h = image->height;
    cg_image *ids = NULL, *pass = NULL;
    cg_renderer *renderer = NULL;
    cg_status s = cg_image_create(&ids, w, h, CG_PIXEL_RGBAF);
    if (s == CG_OK)
        s = cg_image_create(&pass, w, h, image->format);
    if (s != CG_OK)
        cg_error_set(err, s, "scene: out of memory for the material passes");
    if (s == CG_OK)
        s = material_pass(world, face_material, base, ids, err);
    if (s == CG_OK)
        s = cg_renderer_create(world, base, &renderer, err);
    size_t bytes = image->format == CG_PIXEL_RGBAF ? 4 * sizeof(float) : 4;
    int first = 1;
    for (size_t m = 0; m < scene->material_count && s == CG_OK; m++) {
        if (!used[m])
            continue;
        cg_render_options o = *base;
        if ((s = scene_material_options(scene, &scene->materials[m].surface, &o, err)) != CG_OK)
            break;
        if ((s = cg_renderer_set_options(renderer, &o)) == CG_OK)
            s = cg_renderer_draw(renderer, first ? image : pass);
        if (s != CG_OK) {
            cg_error_set(err, s, "scene: rendering failed: %s", cg_status_str(s));
            break;
        }
        for (int y = 0; !first && y < h; y++) {
            const float *id = (const float *)(ids->data + (size_t)y * ids->stride);
            unsigned char *to = image->data + (size_t)y * image->stride;
            const unsigned char *from = pass->data + (size_t)y * pass->stride;
            for (int x = 0; x < w; x++)
                if (decode(id + 4 * (size_t)x) == m + 1)
                    memcpy(to + bytes * (size_t)x, from + bytes * (size_t)x, bytes);
        }
        first = 0;
    }
    cg_renderer_free(renderer);
    cg_image_free(ids);
    cg_image_free(pass);
    return s;
}

cg_status scene_render_raster(const cg_scene *scene, cg_scene_algorithm algorithm, cg_image *image,
                              cg_error *err)
{
    cg_render_options o;
    cg_status s = scene_raster_base_options(scene, algorithm, &o, err);
    if (s != CG_OK)
        return s;
    unsigned char *used = calloc(scene->material_count, 1);
    if (!used)
        return cg_error_set(err, CG_ENOMEM, "scene: out of memory");
    size_t kinds = 0;
    for (size_t i = 0; i < scene->object_count; i++)
        if (!used[scene->objects[i].material]) {
            used[scene->objects[i].material] = 1;
            kinds++;
        }
    for (size_t m = 0; m < scene->material_count && s == CG_OK; m++)
        if (used[m])
            s = check_material(scene, m, err);
    cg_mesh *world = NULL;
    uint32_t *face_material = NULL;
    if (s == CG_OK)
        s = scene_world_mesh(scene, &world, &face_material, err);
    /* One material, or a wireframe or hidden-line picture (which shade
     * nothing): one pass. */
    if (s == CG_OK
        && (kinds < 2 || o.edges == CG_EDGES_WIREFRAME || o.edges == CG_EDGES_HIDDEN_LINE)) {
        size_t m = scene->object_count ? scene->objects[0].material : 0;
        s = scene_material_options(scene, &scene->materials[m].surface, &o, err);
        if (s == CG_OK)
            s = draw(world, &o, image, err);
    } else if (s == CG_OK) {
        s = material_passes(scene, world, face_material, used, &o, image, err);
    }
    cg_mesh_free(world);
    free(face_material);
    free(used);
    return s;
}
