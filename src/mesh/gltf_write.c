/* The glTF 2.0 binary writer (.glb): one mesh, one node, one scene.
 *
 *   BIN chunk:  primitive 0: POSITION (float VEC3) | NORMAL | TEXCOORD_0 |
 *               COLOR_0 (VEC4) | indices (uint32) ; primitive 1: ...
 *
 * Faces are triangulated (cg_mesh_triangulate); the triangles of each
 * material (face_materials) make one primitive, in the order of the
 * material table, faces without a material last, each primitive with the
 * vertices it uses (a vertex shared by two materials is written twice).  Texture coordinates go
 * back to glTF's convention (v = 1 - v'), vertex colours are linear already.
 * Materials keep their factors (base colour, metallic, roughness, emissive,
 * alpha mode and cutoff, double-sided) and their PNG and JPEG maps, embedded
 * after the primitives (base colour, metallic-roughness, normal, occlusion,
 * emissive; an OBJ's map_Kd as the base colour), each with its sampler; a
 * map whose image cannot be read or is in another format is left out. */
#include "internal.h"
#include "../core/array.h"
#include "../core/safe_file.h"

#include <cjson/cJSON.h>
#include <float.h>
#include <stdio.h>
#include <stdlib.h>

typedef CORE_ARRAY(unsigned char) byte_array;

static cg_status put_bytes(byte_array *b, const void *data, size_t n)
{
    if (core_array_reserve_for(b, b->count + n) != CG_OK)
        return CG_ENOMEM;
    memcpy(b->data + b->count, data, n);
    b->count += n;
    return CG_OK;
}

static cg_status put_float(byte_array *b, double v)
{
    float f = (float)v;
    return put_bytes(b, &f, sizeof f); /* glTF is little-endian, as every host cg runs on */
}

/* Adds a buffer view and an accessor over bytes [start, end) of the BIN chunk. */
static cJSON *add_accessor(cJSON *views, cJSON *accessors, size_t start, size_t end,
                           int component_type, size_t count, const char *type)
{
    cJSON *view = cJSON_CreateObject(), *accessor = cJSON_CreateObject();
    cJSON_AddNumberToObject(view, "buffer", 0);
    cJSON_AddNumberToObject(view, "byteOffset", (double)start);
    cJSON_AddNumberToObject(view, "byteLength", (double)(end - start));
    /* ELEMENT_ARRAY_BUFFER for indices, ARRAY_BUFFER for vertex attributes */
    cJSON_AddNumberToObject(view, "target", component_type == 5125 ? 34963 : 34962);
    cJSON_AddNumberToObject(accessor, "bufferView", cJSON_GetArraySize(views));
    cJSON_AddItemToArray(views, view);
    cJSON_AddNumberToObject(accessor, "componentType", component_type);
    cJSON_AddNumberToObject(accessor, "count", (double)count);
    cJSON_AddStringToObject(accessor, "type", type);
    cJSON_AddItemToArray(accessors, accessor);
    return accessor;
}

/* The attributes of vertices[0..count) into bin and their accessors;
 * attributes gets their indices. */
static cg_status write_vertices(const cg_mesh *m, const uint32_t *vertices, size_t count,
                                byte_array *bin, cJSON *views, cJSON *accessors, cJSON *attributes)
{
    cg_status s = CG_OK;
    size_t start = bin->count;
    double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX}, hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX};
    for (size_t i = 0; s == CG_OK && i < count; i++) {
        const double *p = &m->positions[vertices[i]].x;
        for (int k = 0; k < 3 && s == CG_OK; k++) {
            float f = (float)p[k];
            if (!isfinite(f)) /* glTF stores floats */
                return CG_ERANGE;
            lo[k] = f < lo[k] ? f : lo[k];
            hi[k] = f > hi[k] ? f : hi[k];
            s = put_float(bin, p[k]);
        }
    }
    if (s != CG_OK)
        return s;
    cJSON *position = add_accessor(views, accessors, start, bin->count, 5126, count, "VEC3");
    cJSON_AddItemToObject(position, "min", cJSON_CreateDoubleArray(lo, 3));
    cJSON_AddItemToObject(position, "max", cJSON_CreateDoubleArray(hi, 3));
    cJSON_AddNumberToObject(attributes, "POSITION", cJSON_GetArraySize(accessors) - 1);
    if (m->normals) {
        start = bin->count;
        for (size_t i = 0; s == CG_OK && i < count; i++) {
            cg_vec3 n = m->normals[vertices[i]];
            double length = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
            if (!(length > 0)) /* glTF normals are unit vectors */
                n = cg_vec3_make(0, 0, 1), length = 1;
            s = put_float(bin, n.x / length);
            if (s == CG_OK)
                s = put_float(bin, n.y / length);
            if (s == CG_OK)
                s = put_float(bin, n.z / length);
        }
        add_accessor(views, accessors, start, bin->count, 5126, count, "VEC3");
        cJSON_AddNumberToObject(attributes, "NORMAL", cJSON_GetArraySize(accessors) - 1);
    }
    if (m->texcoords && s == CG_OK) {
        start = bin->count;
        for (size_t i = 0; s == CG_OK && i < count; i++) {
            cg_vec2 t = m->texcoords[vertices[i]];
            if (!isfinite((float)t.x) || !isfinite((float)(1.0 - t.y)))
                return CG_ERANGE;
            s = put_float(bin, m->texcoords[vertices[i]].x);
            if (s == CG_OK)
                s = put_float(bin, 1.0 - m->texcoords[vertices[i]].y);
        }
        add_accessor(views, accessors, start, bin->count, 5126, count, "VEC2");
        cJSON_AddNumberToObject(attributes, "TEXCOORD_0", cJSON_GetArraySize(accessors) - 1);
    }
    if (m->colors && s == CG_OK) {
        start = bin->count;
        for (size_t i = 0; s == CG_OK && i < count; i++) {
            const cg_rgbaf *c = &m->colors[vertices[i]];
            float channels[4] = {c->r, c->g, c->b, c->a};
            for (int k = 0; k < 4 && s == CG_OK; k++)
                s = put_float(bin, channels[k] < 0 ? 0 : channels[k] > 1 ? 1 : channels[k]);
        }
        add_accessor(views, accessors, start, bin->count, 5126, count, "VEC4");
        cJSON_AddNumberToObject(attributes, "COLOR_0", cJSON_GetArraySize(accessors) - 1);
    }
    return s;
}

static cJSON *material_json(const cg_mesh_material *m)
{
    cJSON *j = cJSON_CreateObject(), *pbr = cJSON_CreateObject();
    if (m->name && *m->name)
        cJSON_AddStringToObject(j, "name", m->name);
    double base[4] = {m->base_color.r, m->base_color.g, m->base_color.b, m->base_color.a};
    for (int k = 0; k < 4; k++)
        base[k] = base[k] < 0 ? 0 : base[k] > 1 ? 1 : base[k];
    cJSON_AddItemToObject(pbr, "baseColorFactor", cJSON_CreateDoubleArray(base, 4));
    double metallic = m->model == CG_MESH_MATERIAL_PHONG ? 0 : m->metallic;
    double roughness = m->model == CG_MESH_MATERIAL_PHONG
                           ? sqrt(2 / (m->shininess + 2)) /* Blinn-Phong exponent to roughness */
                           : m->roughness;
    cJSON_AddNumberToObject(pbr, "metallicFactor", metallic < 0 ? 0 : metallic > 1 ? 1 : metallic);
    cJSON_AddNumberToObject(pbr, "roughnessFactor",
                            roughness < 0   ? 0
                            : roughness > 1 ? 1
                                            : roughness);
    cJSON_AddItemToObject(j, "pbrMetallicRoughness", pbr);
    double emissive[3] = {m->emissive.r, m->emissive.g, m->emissive.b}, strength = 1;
    for (int k = 0; k < 3; k++)
        strength = emissive[k] > strength ? emissive[k] : strength;
    for (int k = 0; k < 3; k++)
        emissive[k] = emissive[k] < 0 ? 0 : emissive[k] / strength;
    if (emissive[0] > 0 || emissive[1] > 0 || emissive[2] > 0)
        cJSON_AddItemToObject(j, "emissiveFactor", cJSON_CreateDoubleArray(emissive, 3));
    if (strength > 1) {
        cJSON *ext = cJSON_CreateObject(), *es = cJSON_CreateObject();
        cJSON_AddNumberToObject(es, "emissiveStrength", strength);
        cJSON_AddItemToObject(ext, "KHR_materials_emissive_strength", es);
        cJSON_AddItemToObject(j, "extensions", ext);
    }
    if (m->alpha_mode == CG_MESH_ALPHA_MASK) {
        cJSON_AddStringToObject(j, "alphaMode", "MASK");
        cJSON_AddNumberToObject(j, "alphaCutoff", m->alpha_cutoff);
    } else if (m->alpha_mode == CG_MESH_ALPHA_BLEND) {
        cJSON_AddStringToObject(j, "alphaMode", "BLEND");
    }
    if (m->double_sided)
        cJSON_AddTrueToObject(j, "doubleSided");
    return j;
}

/* The bytes of a texture's image: embedded, or the whole file it names
 * (*owned then to free); NULL when there is none or it cannot be read. */
static const unsigned char *image_of(const cg_mesh_texture_ref *t, size_t *n, unsigned char **owned)
{
    *owned = NULL;
    if (t->image_bytes) {
        *n = t->image_byte_count;
        return t->image_bytes;
    }
    FILE *f = t->image_path ? fopen(t->image_path, "rb") : NULL;
    long size = f && fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (size > 0 && (size_t)size < UINT32_MAX && fseek(f, 0, SEEK_SET) == 0
        && (*owned = malloc((size_t)size)) && fread(*owned, 1, (size_t)size, f) != (size_t)size) {
        free(*owned);
        *owned = NULL;
    }
    if (f)
        fclose(f);
    *n = *owned ? (size_t)size : 0;
    return *owned;
}

/* Embeds texture t's image (PNG or JPEG, the formats glTF allows) in bin
 * with its sampler, and adds {"index": texture} to info as key (with its
 * scale or strength, and KHR_texture_transform, bit 2 of *used); a texture
 * without such an image is left out. */
static cg_status add_texture(cJSON *root, byte_array *bin, const cg_mesh_texture_ref *t,
                             cJSON *info, const char *key, int *used)
{
    size_t n;
    unsigned char *owned;
    const unsigned char *bytes = image_of(t, &n, &owned);
    const char *mime = n > 8 && memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0 ? "image/png"
                       : n > 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF
                           ? "image/jpeg"
                           : NULL;
    size_t start = bin->count;
    cg_status s = mime ? put_bytes(bin, bytes, n) : CG_OK;
    free(owned);
    while (s == CG_OK && mime && bin->count % 4) /* the next accessor stays aligned */
        s = put_bytes(bin, "", 1);
    if (s != CG_OK || !mime)
        return s;
    cJSON *views = cJSON_GetObjectItemCaseSensitive(root, "bufferViews");
    cJSON *view = cJSON_CreateObject(), *image = cJSON_CreateObject();
    cJSON_AddNumberToObject(view, "buffer", 0);
    cJSON_AddNumberToObject(view, "byteOffset", (double)start);
    cJSON_AddNumberToObject(view, "byteLength", (double)n);
    cJSON_AddNumberToObject(image, "bufferView", cJSON_GetArraySize(views));
    cJSON_AddItemToArray(views, view);
    cJSON_AddStringToObject(image, "mimeType", mime);
    cJSON *images = cJSON_GetObjectItemCaseSensitive(root, "images");
    if (!images)
        images = cJSON_AddArrayToObject(root, "images");
    cJSON *samplers = cJSON_GetObjectItemCaseSensitive(root, "samplers");
    if (!samplers)
        samplers = cJSON_AddArrayToObject(root, "samplers");
    cJSON *textures = cJSON_GetObjectItemCaseSensitive(root, "textures");
    if (!textures)
        textures = cJSON_AddArrayToObject(root, "textures");
    static const int wrap[] = {10497 /* REPEAT */, 33648 /* MIRRORED */, 33071 /* CLAMP */};
    cJSON *sampler = cJSON_CreateObject(), *texture = cJSON_CreateObject();
    cJSON_AddNumberToObject(sampler, "magFilter", t->magnify_nearest ? 9728 : 9729);
    cJSON_AddNumberToObject(sampler, "minFilter", 9987); /* LINEAR_MIPMAP_LINEAR */
    cJSON_AddNumberToObject(sampler, "wrapS", wrap[t->wrap_u <= 2 ? t->wrap_u : 0]);
    cJSON_AddNumberToObject(sampler, "wrapT", wrap[t->wrap_v <= 2 ? t->wrap_v : 0]);
    cJSON_AddNumberToObject(texture, "sampler", cJSON_GetArraySize(samplers));
    cJSON_AddNumberToObject(texture, "source", cJSON_GetArraySize(images));
    cJSON_AddItemToArray(images, image);
    cJSON_AddItemToArray(samplers, sampler);
    cJSON *ref = cJSON_CreateObject();
    cJSON_AddNumberToObject(ref, "index", cJSON_GetArraySize(textures));
    cJSON_AddItemToArray(textures, texture);
    if (t->amount != 1 && strcmp(key, "normalTexture") == 0)
        cJSON_AddNumberToObject(ref, "scale", t->amount);
    if (t->amount != 1 && strcmp(key, "occlusionTexture") == 0)
        cJSON_AddNumberToObject(ref, "strength", t->amount);
    if (t->offset[0] != 0 || t->offset[1] != 0 || t->rotation != 0 || t->scale[0] != 1
        || t->scale[1] != 1) {
        cJSON *ext = cJSON_AddObjectToObject(ref, "extensions");
        cJSON *transform = cJSON_AddObjectToObject(ext, "KHR_texture_transform");
        cJSON_AddItemToObject(transform, "offset", cJSON_CreateDoubleArray(t->offset, 2));
        cJSON_AddNumberToObject(transform, "rotation", t->rotation);
        cJSON_AddItemToObject(transform, "scale", cJSON_CreateDoubleArray(t->scale, 2));
        *used |= 2;
    }
    cJSON_AddItemToObject(info, key, ref);
    return CG_OK;
}

/* The maps of material m into its JSON j: base colour (map_Kd), metallic-
 * roughness, normal, occlusion and emissive. */
static cg_status add_textures(cJSON *root, byte_array *bin, const cg_mesh_material *m, cJSON *j,
                              int *used)
{
    cJSON *pbr = cJSON_GetObjectItemCaseSensitive(j, "pbrMetallicRoughness");
    cg_status s = add_texture(root, bin, &m->base_color_map, pbr, "baseColorTexture", used);
    if (s == CG_OK && m->model != CG_MESH_MATERIAL_PHONG)
        s = add_texture(root, bin, &m->metallic_roughness_map, pbr, "metallicRoughnessTexture",
                        used);
    if (s == CG_OK && m->model != CG_MESH_MATERIAL_PHONG)
        s = add_texture(root, bin, &m->normal_map, j, "normalTexture", used);
    if (s == CG_OK)
        s = add_texture(root, bin, &m->occlusion_map, j, "occlusionTexture", used);
    if (s == CG_OK)
        s = add_texture(root, bin, &m->emissive_map, j, "emissiveTexture", used);
    return s;
}

/* Which faces belong to primitive `wanted` (a material, or none). */
static int in_group(const cg_mesh *m, size_t f, uint32_t wanted)
{
    uint32_t material = m->face_materials ? m->face_materials[f] : CG_MESH_NO_MATERIAL;
    if (material >= m->material_count)
        material = CG_MESH_NO_MATERIAL;
    return material == wanted;
}

/* One primitive per material (faces without one last), each with the
 * vertices its triangles use (renumbered from 0, in order of first use),
 * so that no vertex is written twice for one primitive. */
static cg_status write_primitives(const cg_mesh *m, const uint32_t (*triangles)[3], byte_array *bin,
                                  cJSON *views, cJSON *accessors, cJSON *primitives)
{
    size_t groups = m->face_materials ? m->material_count + 1 : 1;
    size_t *first_triangle = malloc((m->face_count + 1) * sizeof *first_triangle);
    uint32_t *local = malloc((m->vertex_count ? m->vertex_count : 1) * sizeof *local);
    CORE_ARRAY(uint32_t) used = {0};
    CORE_ARRAY(uint32_t) corners = {0};
    cg_status s = first_triangle && local ? CG_OK : CG_ENOMEM;
    for (size_t f = 0, t = 0; s == CG_OK && f <= m->face_count; f++) { /* face f's first triangle */
        first_triangle[f] = t;
        if (f < m->face_count)
            t += cg_mesh_face_size(m, f) - 2;
    }
    for (size_t v = 0; s == CG_OK && v < m->vertex_count; v++)
        local[v] = UINT32_MAX;
    for (size_t g = 0; g < groups && s == CG_OK; g++) {
        uint32_t wanted = g < m->material_count ? (uint32_t)g : CG_MESH_NO_MATERIAL;
        used.count = corners.count = 0;
        for (size_t f = 0; f < m->face_count && s == CG_OK; f++) {
            if (!in_group(m, f, wanted))
                continue;
            for (size_t t = first_triangle[f]; t < first_triangle[f + 1] && s == CG_OK; t++)
                for (int k = 0; k < 3 && s == CG_OK; k++) {
                    uint32_t v = m->face_indices[triangles[t][k]];
                    if (local[v] == UINT32_MAX) {
                        local[v] = (uint32_t)used.count;
                        s = core_array_push(&used, v);
                    }
                    if (s == CG_OK)
                        s = core_array_push(&corners, local[v]);
                }
        }
        for (size_t i = 0; i < used.count; i++) /* ready for the next primitive */
            local[used.data[i]] = UINT32_MAX;
        if (corners.count == 0 || s != CG_OK)
            continue;
        cJSON *primitive = cJSON_CreateObject(), *attributes = cJSON_CreateObject();
        cJSON_AddItemToObject(primitive, "attributes", attributes);
        s = write_vertices(m, used.data, used.count, bin, views, accessors, attributes);
        size_t start = bin->count;
        if (s == CG_OK)
            s = put_bytes(bin, corners.data, corners.count * sizeof *corners.data);
        add_accessor(views, accessors, start, bin->count, 5125, corners.count, "SCALAR");
        cJSON_AddNumberToObject(primitive, "indices", cJSON_GetArraySize(accessors) - 1);
        if (wanted != CG_MESH_NO_MATERIAL)
            cJSON_AddNumberToObject(primitive, "material", wanted);
        cJSON_AddItemToArray(primitives, primitive);
    }
    core_array_free(&used);
    core_array_free(&corners);
    free(local);
    free(first_triangle);
    return s;
}

static cg_status write_file(const char *path, const char *json, const byte_array *bin,
                            cg_error *err)
{
    size_t json_length = strlen(json), json_padded = (json_length + 3) / 4 * 4;
    size_t bin_padded = (bin->count + 3) / 4 * 4;
    uint64_t total = 12 + 8 + json_padded + (bin->count ? 8 + bin_padded : 0);
    if (total > UINT32_MAX)
        return cg_error_set(err, CG_ERANGE, "%s: over the 4 GiB a .glb holds", path);
    safe_file o;
    cg_status s = safe_file_open(&o, path, err);
    if (s != CG_OK)
        return s;
    uint32_t header[5] = {0x46546C67u /* "glTF" */, 2, (uint32_t)total, (uint32_t)json_padded,
                          0x4E4F534Au};
    fwrite(header, sizeof header[0], 5, o.file);
    fwrite(json, 1, json_length, o.file);
    for (size_t i = json_length; i < json_padded; i++)
        putc(' ', o.file);
    if (bin->count) {
        uint32_t chunk[2] = {(uint32_t)bin_padded, 0x004E4942u};
        fwrite(chunk, sizeof chunk[0], 2, o.file);
        fwrite(bin->data, 1, bin->count, o.file);
        for (size_t i = bin->count; i < bin_padded; i++)
            putc(0, o.file);
    }
    return safe_file_close(&o, CG_OK, err);
}

cg_status gltf_write(const cg_mesh *m, const char *path, cg_error *err)
{
    uint32_t(*triangles)[3];
    cg_status s = mesh_write_triangles(m, path, err, &triangles);
    if (s != CG_OK)
        return s;
    byte_array bin = {0};
    cJSON *root = cJSON_CreateObject(), *asset = cJSON_CreateObject();
    cJSON_AddStringToObject(asset, "version", "2.0");
    cJSON_AddStringToObject(asset, "generator", "cg");
    cJSON_AddItemToObject(root, "asset", asset);
    cJSON *views = cJSON_AddArrayToObject(root, "bufferViews");
    cJSON *accessors = cJSON_AddArrayToObject(root, "accessors");
    cJSON *primitives = cJSON_CreateArray();
    s = write_primitives(m, (const uint32_t(*)[3])triangles, &bin, views, accessors, primitives);
    free(triangles);
    if (s == CG_OK && m->material_count) {
        cJSON *materials = cJSON_AddArrayToObject(root, "materials");
        int used = 0; /* bit 1: KHR_materials_emissive_strength, 2: KHR_texture_transform */
        for (size_t i = 0; i < m->material_count && s == CG_OK; i++) {
            cJSON *material = material_json(&m->materials[i]);
            used |= cJSON_HasObjectItem(material, "extensions");
            cJSON_AddItemToArray(materials, material);
            if (cJSON_GetArraySize(primitives) > 0) /* images live in the BIN chunk */
                s = add_textures(root, &bin, &m->materials[i], material, &used);
        }
        static const char *extensions[] = {"KHR_materials_emissive_strength",
                                           "KHR_texture_transform"};
        if (used) /* every extension a file uses is declared */
            cJSON_AddItemToObject(
                root, "extensionsUsed",
                cJSON_CreateStringArray(extensions + (used == 2), used == 3 ? 2 : 1));
    }
    if (cJSON_GetArraySize(primitives) > 0) {
        cJSON *buffers = cJSON_AddArrayToObject(root, "buffers"), *buffer = cJSON_CreateObject();
        cJSON_AddNumberToObject(buffer, "byteLength", (double)bin.count);
        cJSON_AddItemToArray(buffers, buffer);
        cJSON *meshes = cJSON_AddArrayToObject(root, "meshes"), *mesh = cJSON_CreateObject();
        cJSON_AddItemToObject(mesh, "primitives", primitives);
        cJSON_AddItemToArray(meshes, mesh);
        cJSON *nodes = cJSON_AddArrayToObject(root, "nodes"), *node = cJSON_CreateObject();
        cJSON_AddNumberToObject(node, "mesh", 0);
        cJSON_AddItemToArray(nodes, node);
        cJSON *scenes = cJSON_AddArrayToObject(root, "scenes"), *scene = cJSON_CreateObject();
        cJSON_AddItemToObject(scene, "nodes", cJSON_CreateIntArray((const int[]){0}, 1));
        cJSON_AddItemToArray(scenes, scene);
        cJSON_AddNumberToObject(root, "scene", 0);
    } else {
        cJSON_Delete(primitives);
        /* no triangles: a valid file of no scene content */
        cJSON_DeleteItemFromObject(root, "bufferViews");
        cJSON_DeleteItemFromObject(root, "accessors");
        bin.count = 0;
    }
    char *json = s == CG_OK ? cJSON_PrintUnformatted(root) : NULL;
    cJSON_Delete(root);
    if (s == CG_OK && !json)
        s = CG_ENOMEM;
    if (s == CG_OK)
        s = write_file(path, json, &bin, err);
    else if (s == CG_ENOMEM)
        s = cg_error_set(err, s, "%s: out of memory", path);
    else if (s == CG_ERANGE)
        s = cg_error_set(err, s,
                         "%s: a vertex position or texture coordinate lies beyond the range of "
                         "floats, which glTF stores",
                         path);
    free(json);
    core_array_free(&bin);
    return s;
}
