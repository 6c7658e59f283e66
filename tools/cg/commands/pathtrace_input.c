/* The path tracer's input and its render key (see pathtrace_input.h). */
#include "pathtrace_input.h"

#include "render_scene.h"
#include "cg/image_float.h"
#include "cg/scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const uint64_t digest_start = 0xcbf29ce484222325ull;

/* FNV-1a over n bytes, continuing from hash. */
static uint64_t digest(uint64_t hash, const void *bytes, size_t n)
{
    const unsigned char *p = bytes;
    for (size_t i = 0; i < n; i++)
        hash = (hash ^ p[i]) * 0x100000001b3ull;
    return hash;
}

/* What the path tracer takes from a mesh: positions, normals, vertex and
 * face colours, and the faces. */
static uint64_t digest_mesh(uint64_t hash, const cg_mesh *m)
{
    size_t v = m->vertex_count, f = m->face_count;
    hash = digest(hash, &v, sizeof v);
    hash = digest(hash, &f, sizeof f);
    if (v) {
        hash = digest(hash, m->positions, v * sizeof *m->positions);
        if (m->normals)
            hash = digest(hash, m->normals, v * sizeof *m->normals);
        if (m->colors)
            hash = digest(hash, m->colors, v * sizeof *m->colors);
    }
    if (f) {
        hash = digest(hash, m->face_offsets, (f + 1) * sizeof *m->face_offsets);
        hash = digest(hash, m->face_indices, m->face_offsets[f] * sizeof *m->face_indices);
        if (m->face_colors)
            hash = digest(hash, m->face_colors, f * sizeof *m->face_colors);
    }
    return hash;
}

/* A scene file's bytes (everything but its meshes, which are digested as
 * loaded); 0 when it cannot be read again. */
static uint64_t digest_file(uint64_t hash, const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return hash;
    unsigned char block[65536];
    size_t n;
    while ((n = fread(block, 1, sizeof block, f)) > 0)
        hash = digest(hash, block, n);
    fclose(f);
    return hash;
}

/* The size and the sky (colour, or the map's pixels and intensity). */
static uint64_t digest_picture(uint64_t hash, const pathtrace_input *in)
{
    /* The estimator's version: parts of renders whose sums would differ
     * (2: emissive meshes sampled as lights) never merge. */
    static const char estimator[] = "cg path tracer 2";
    hash = digest(hash, estimator, sizeof estimator);
    int size[2] = {in->width, in->height};
    hash = digest(hash, size, sizeof size);
    double sky_color[3] = {in->environment.x, in->environment.y, in->environment.z};
    hash = digest(hash, sky_color, sizeof sky_color);
    const cg_image *sky = in->environment_map;
    if (sky) {
        int map_size[2] = {sky->width, sky->height};
        hash = digest(hash, map_size, sizeof map_size);
        hash = digest(hash, &in->environment_intensity, sizeof in->environment_intensity);
        for (int y = 0; y < sky->height; y++)
            for (int x = 0; x < sky->width; x++) {
                cg_rgbaf c = cg_image_get(sky, x, y);
                float rgb[3] = {c.r, c.g, c.b};
                hash = digest(hash, rgb, sizeof rgb);
            }
    }
    return hash;
}

/* The environment map as linear-light floats: float files as they are,
 * 8-bit ones decoded from sRGB. */
static cg_status load_sky(const char *path, cg_image **sky, cg_error *err)
{
    cg_error inner;
    cg_status s = cg_image_load_linear(path, sky, &inner);
    return s == CG_OK ? CG_OK : cg_error_set(err, s, "--environment: %s", inner.message);
}

/* One mesh under the default material, framed for the picture's aspect. */
static cg_status load_mesh(const char *path, pathtrace_input *in, cg_error *err)
{
    cg_mesh *mesh = NULL;
    cg_status s = cg_mesh_load(path, &mesh, err);
    if (s != CG_OK)
        return s;
    in->key = digest_mesh(digest_start, mesh);
    cg_trace_material m = cg_trace_material_default();
    m.surface.color = cg_vec3_make(0.8, 0.8, 0.8);
    m.surface.kd = 1;
    cg_vec3 lo, hi;
    if ((s = cg_trace_scene_create(&in->scene)) == CG_OK)
        s = cg_trace_scene_add_mesh(in->scene, mesh, NULL, 0.6, &m);
    cg_mesh_free(mesh);
    if (s == CG_OK && (s = cg_trace_scene_bounds(in->scene, &lo, &hi)) != CG_OK)
        return cg_error_set(err, s, "%s: no faces to render", path);
    if (s != CG_OK)
        return err && err->message[0]
                   ? s
                   : cg_error_set(err, s, "%s: the path tracer refused the mesh", path);
    in->camera = cg_camera_default();
    in->camera.target = cg_vec3_scale(cg_vec3_add(lo, hi), 0.5);
    in->camera.eye = cg_vec3_add(in->camera.target, cg_vec3_make(0, 0, 1));
    if ((s = cg_camera_frame(&in->camera, lo, hi, (double)in->width / in->height)) != CG_OK)
        return cg_error_set(err, s, "%s: cannot frame the mesh", path);
    return CG_OK;
}

/* A scene file: its own size unless --size, its sky unless the command
 * line gives one (the map moves into the input). */
static cg_status load_scene(const char *path, cli_size size, int size_given, pathtrace_input *in,
                            cg_error *err)
{
    cg_scene *scene = NULL;
    cg_status s = cg_scene_load(path, &scene, err);
    if (s != CG_OK)
        return s;
    if (size_given) {
        scene->width = size.width;
        scene->height = size.height;
    }
    in->width = scene->width;
    in->height = scene->height;
    uint64_t key = digest_file(digest_start, path);
    for (size_t i = 0; i < scene->object_count; i++)
        if (scene->objects[i].mesh)
            key = digest_mesh(key, scene->objects[i].mesh);
    in->key = key;
    if (scene->environment_given) {
        in->environment = scene->environment_color;
        in->environment_map = scene->environment_map;
        in->environment_intensity = scene->environment_intensity;
        scene->environment_map = NULL;
    } else {
        in->environment = cg_vec3_make(scene->background.r, scene->background.g,
                                       scene->background.b);
    }
    cg_error inner;
    if ((s = cg_scene_trace_scene(scene, 0, &in->scene, &in->camera, &inner)) != CG_OK)
        cg_error_set(err, s, "%s: %s", path, inner.message);
    cg_scene_free(scene);
    return s;
}

cg_status pathtrace_input_load(const char *path, cli_size size, int size_given,
                               const pathtrace_sky *sky, pathtrace_input *in, cg_error *err)
{
    memset(in, 0, sizeof *in);
    in->width = size.width;
    in->height = size.height;
    in->environment = cg_vec3_make(1, 1, 1);
    in->environment_intensity = 1;
    cg_status s = render_scene_is_scene(path) ? load_scene(path, size, size_given, in, err)
                                              : load_mesh(path, in, err);
    if (s == CG_OK && (sky->file || sky->color_given)) {
        cg_image_free(in->environment_map);
        in->environment_map = NULL;
        in->environment_intensity = 1;
        if (sky->color_given)
            in->environment = sky->color;
        else
            s = load_sky(sky->file, &in->environment_map, err);
    }
    if (s == CG_OK && sky->intensity_given) {
        if (!in->environment_map)
            s = cg_error_set(err, CG_EINVAL,
                             "--environment-intensity scales an --environment map; give one, "
                             "or scale --environment-color itself");
        else
            in->environment_intensity = sky->intensity;
    }
    if (s != CG_OK) {
        pathtrace_input_free(in);
        return s;
    }
    in->key = digest_picture(in->key, in);
    return CG_OK;
}

void pathtrace_input_free(pathtrace_input *in)
{
    cg_trace_scene_free(in->scene);
    cg_image_free(in->environment_map);
    in->scene = NULL;
    in->environment_map = NULL;
}
