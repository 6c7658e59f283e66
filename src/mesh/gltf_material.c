/* glTF materials, textures, images and samplers into the mesh's material
 * table (cg_mesh_material), checked against the specification: every
 * factor's range, every texture index, every enumerated value.
 *
 *   material.pbrMetallicRoughness.baseColorTexture = {index: 2, texCoord: 0}
 *        -> textures[2] = {sampler: 0, source: 1}
 *             -> images[1] = {uri: "wood.png"} or {bufferView: 5, mimeType}
 *             -> samplers[0] = {wrapS, wrapT, magFilter, minFilter}
 *
 * Image bytes are not decoded here: a file image keeps its path, an
 * embedded one (data: URI or buffer view) its bytes. */
#include "gltf_internal.h"
#include "../core/base64.h"

#include <stdio.h>
#include <stdlib.h>

static char *copy_string(const char *s)
{
    size_t n = strlen(s);
    char *copy = malloc(n + 1);
    if (copy)
        memcpy(copy, s, n + 1);
    return copy;
}

/* A number member in [minimum, maximum] (default fallback). */
static cg_status number_in(gltf_document *doc, const cJSON *object, const char *path,
                           const char *key, double fallback, double minimum, double maximum,
                           double *out)
{
    cg_status s = gltf_get_number(doc, object, path, key, fallback, out);
    if (s == CG_OK && (*out < minimum || *out > maximum)) {
        char expected[64];
        if (maximum > 1e300)
            snprintf(expected, sizeof expected, "a number >= %g", minimum);
        else
            snprintf(expected, sizeof expected, "a number in [%g, %g]", minimum, maximum);
        return gltf_fail(doc, path, key, expected, cJSON_GetObjectItemCaseSensitive(object, key));
    }
    return s;
}

/* n numbers, each in [0, 1], into values (left as they are when absent). */
static cg_status unit_numbers(gltf_document *doc, const cJSON *object, const char *path,
                              const char *key, size_t n, double *values)
{
    double read[4];
    int present;
    cg_status s = gltf_get_numbers(doc, object, path, key, n, read, &present);
    if (s != CG_OK || !present)
        return s;
    for (size_t i = 0; i < n; i++) {
        if (read[i] < 0 || read[i] > 1) {
            char item[128];
            snprintf(item, sizeof item, "%s.%s[%zu]", path, key, i);
            return gltf_fail(
                doc, item, NULL, "a number in [0, 1]",
                cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(object, key), (int)i));
        }
        values[i] = read[i];
    }
    return CG_OK;
}

static cg_status read_sampler(gltf_document *doc, size_t index, cg_mesh_texture_ref *t)
{
    const cJSON *sampler = doc->samplers.items[index];
    char path[48];
    snprintf(path, sizeof path, "samplers[%zu]", index);
    int64_t mag, min, wrap[2];
    const char *keys[2] = {"wrapS", "wrapT"};
    cg_status s = gltf_get_integer(doc, sampler, path, "magFilter", 0, 9729, 0, 1 << 20, &mag);
    if (s == CG_OK)
        s = gltf_get_integer(doc, sampler, path, "minFilter", 0, 9987, 0, 1 << 20, &min);
    if (s != CG_OK)
        return s;
    if (mag != 9728 && mag != 9729)
        return gltf_fail(doc, path, "magFilter", "9728 (NEAREST) or 9729 (LINEAR)",
                         cJSON_GetObjectItemCaseSensitive(sampler, "magFilter"));
    if (min != 9728 && min != 9729 && (min < 9984 || min > 9987))
        return gltf_fail(doc, path, "minFilter", "9728, 9729 or 9984 to 9987",
                         cJSON_GetObjectItemCaseSensitive(sampler, "minFilter"));
    for (int k = 0; k < 2; k++) {
        if ((s = gltf_get_integer(doc, sampler, path, keys[k], 0, 10497, 0, 1 << 20, &wrap[k]))
            != CG_OK)
            return s;
        if (wrap[k] != 33071 && wrap[k] != 33648 && wrap[k] != 10497)
            return gltf_fail(doc, path, keys[k],
                             "33071 (CLAMP_TO_EDGE), 33648 (MIRRORED_REPEAT) or 10497 (REPEAT)",
                             cJSON_GetObjectItemCaseSensitive(sampler, keys[k]));
    }
    t->wrap_u = wrap[0] == 33071   ? CG_TEXTURE_CLAMP
                : wrap[0] == 33648 ? CG_TEXTURE_MIRRORED_REPEAT
                                   : CG_TEXTURE_REPEAT;
    t->wrap_v = wrap[1] == 33071   ? CG_TEXTURE_CLAMP
                : wrap[1] == 33648 ? CG_TEXTURE_MIRRORED_REPEAT
                                   : CG_TEXTURE_REPEAT;
    t->magnify_nearest = mag == 9728;
    return CG_OK;
}

/* Where an image's bytes are: its file path or a copy of its embedded bytes. */
static cg_status read_image(gltf_document *doc, size_t index, cg_mesh_texture_ref *t)
{
    const cJSON *image = doc->images.items[index];
    char path[48];
    snprintf(path, sizeof path, "images[%zu]", index);
    const char *uri, *mime;
    size_t view;
    cg_status s = gltf_get_string(doc, image, path, "uri", 0, &uri);
    if (s == CG_OK)
        s = gltf_get_string(doc, image, path, "mimeType", 0, &mime);
    if (s == CG_OK)
        s = gltf_get_index(doc, image, path, "bufferView", 0, &doc->buffer_views, "bufferViews",
                           &view);
    if (s != CG_OK)
        return s;
    if ((uri != NULL) == (view != SIZE_MAX))
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s: expected either a uri or a bufferView, got %s", doc->name,
                            path, uri ? "both" : "neither");
    if (view != SIZE_MAX) {
        if (!mime)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s.mimeType: expected \"image/png\" or \"image/jpeg\" with a "
                                "bufferView, got nothing",
                                doc->name, path);
        gltf_view v;
        if ((s = gltf_get_view(doc, view, &v)) != CG_OK)
            return s;
        if (!(t->image_bytes = malloc(v.byte_length)))
            return gltf_out_of_memory(doc);
        memcpy(t->image_bytes, v.bytes, v.byte_length);
        t->image_byte_count = v.byte_length;
        return CG_OK;
    }
    if (strncmp(uri, "data:", 5) == 0) {
        const char *comma = strchr(uri, ',');
        if (!comma || comma - uri < 12 || strncmp(comma - 7, ";base64", 7) != 0)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s.uri: expected a base64 data: URI (data:...;base64,...)",
                                doc->name, path);
        int ok = core_base64_decode(comma + 1, strlen(comma + 1), 0, &t->image_bytes,
                                    &t->image_byte_count);
        if (ok < 0)
            return gltf_out_of_memory(doc);
        if (!ok)
            return cg_error_set(doc->err, CG_EFORMAT, "%s: %s.uri: expected base64 text", doc->name,
                                path);
        return CG_OK;
    }
    /* a file beside the model; percent escapes decoded as for buffers */
    const char *dir = doc->directory ? doc->directory : ".";
    size_t dn = strlen(dir), un = strlen(uri);
    char *file = malloc(dn + un + 2);
    if (!file)
        return gltf_out_of_memory(doc);
    size_t n = 0;
    memcpy(file, dir, dn);
    n = dn;
    file[n++] = '/';
    for (size_t i = 0; i < un; i++) {
        unsigned hex;
        if (uri[i] == '%' && i + 2 < un && sscanf(uri + i + 1, "%2x", &hex) == 1 && hex) {
            file[n++] = (char)hex;
            i += 2;
        } else {
            file[n++] = uri[i];
        }
    }
    file[n] = '\0';
    t->image_path = file;
    return CG_OK;
}

/* A textureInfo object (key of parent) into t; t is left empty when absent. */
static cg_status read_texture_info(gltf_document *doc, const cJSON *parent, const char *path,
                                   const char *key, cg_mesh_texture_ref *t)
{
    const cJSON *info;
    cg_status s = gltf_get_object(doc, parent, path, key, 0, &info);
    if (s != CG_OK || !info)
        return s;
    char here[128];
    snprintf(here, sizeof here, "%s%s%s", path, *path ? "." : "", key);
    size_t texture, sampler, source;
    int64_t texcoord;
    s = gltf_get_index(doc, info, here, "index", 1, &doc->textures, "textures", &texture);
    if (s == CG_OK)
        s = gltf_get_integer(doc, info, here, "texCoord", 0, 0, 0, 1 << 20, &texcoord);
    if (s == CG_OK && strcmp(key, "normalTexture") == 0)
        s = gltf_get_number(doc, info, here, "scale", 1, &t->amount);
    if (s == CG_OK && strcmp(key, "occlusionTexture") == 0)
        s = number_in(doc, info, here, "strength", 1, 0, 1, &t->amount);
    if (s != CG_OK)
        return s;
    t->texcoord_set = (int)texcoord;
    /* KHR_texture_transform */
    const cJSON *extensions, *transform;
    char ext_path[192];
    snprintf(ext_path, sizeof ext_path, "%s.extensions", here);
    s = gltf_get_object(doc, info, here, "extensions", 0, &extensions);
    if (s == CG_OK)
        s = gltf_get_object(doc, extensions, ext_path, "KHR_texture_transform", 0, &transform);
    if (s == CG_OK && transform) {
        snprintf(ext_path, sizeof ext_path, "%s.extensions.KHR_texture_transform", here);
        int present;
        int64_t set;
        s = gltf_get_numbers(doc, transform, ext_path, "offset", 2, t->offset, &present);
        if (s == CG_OK)
            s = gltf_get_number(doc, transform, ext_path, "rotation", 0, &t->rotation);
        if (s == CG_OK)
            s = gltf_get_numbers(doc, transform, ext_path, "scale", 2, t->scale, &present);
        if (s == CG_OK)
            s = gltf_get_integer(doc, transform, ext_path, "texCoord", 0, texcoord, 0, 1 << 20,
                                 &set);
        if (s == CG_OK)
            t->texcoord_set = (int)set;
    }
    if (s != CG_OK)
        return s;
    /* the texture: its sampler and image */
    const cJSON *tex = doc->textures.items[texture];
    char tex_path[48];
    snprintf(tex_path, sizeof tex_path, "textures[%zu]", texture);
    s = gltf_get_index(doc, tex, tex_path, "sampler", 0, &doc->samplers, "samplers", &sampler);
    if (s == CG_OK)
        s = gltf_get_index(doc, tex, tex_path, "source", 0, &doc->images, "images", &source);
    if (s == CG_OK && sampler != SIZE_MAX)
        s = read_sampler(doc, sampler, t);
    if (s == CG_OK && source != SIZE_MAX)
        s = read_image(doc, source, t);
    return s;
}

static cg_status read_material(gltf_document *doc, size_t index, cg_mesh_material *m)
{
    const cJSON *item = doc->materials.items[index];
    char path[48];
    snprintf(path, sizeof path, "materials[%zu]", index);
    *m = cg_mesh_material_default();
    m->model = CG_MESH_MATERIAL_METALLIC_ROUGHNESS;
    const char *name, *alpha_mode;
    const cJSON *pbr, *extensions, *strength, *unlit;
    double base[4] = {1, 1, 1, 1}, emissive[3] = {0, 0, 0}, emissive_strength = 1;
    cg_status s = gltf_get_string(doc, item, path, "name", 0, &name);
    if (s == CG_OK && !(m->name = copy_string(name ? name : "")))
        s = gltf_out_of_memory(doc);
    if (s == CG_OK)
        s = gltf_get_object(doc, item, path, "pbrMetallicRoughness", 0, &pbr);
    char pbr_path[80];
    snprintf(pbr_path, sizeof pbr_path, "%s.pbrMetallicRoughness", path);
    if (s == CG_OK)
        s = unit_numbers(doc, pbr, pbr_path, "baseColorFactor", 4, base);
    if (s == CG_OK)
        s = number_in(doc, pbr, pbr_path, "metallicFactor", 1, 0, 1, &m->metallic);
    if (s == CG_OK)
        s = number_in(doc, pbr, pbr_path, "roughnessFactor", 1, 0, 1, &m->roughness);
    if (s == CG_OK)
        s = read_texture_info(doc, pbr, pbr_path, "baseColorTexture", &m->base_color_map);
    if (s == CG_OK)
        s = read_texture_info(doc, pbr, pbr_path, "metallicRoughnessTexture",
                              &m->metallic_roughness_map);
    if (s == CG_OK)
        s = read_texture_info(doc, item, path, "normalTexture", &m->normal_map);
    if (s == CG_OK)
        s = read_texture_info(doc, item, path, "occlusionTexture", &m->occlusion_map);
    if (s == CG_OK)
        s = read_texture_info(doc, item, path, "emissiveTexture", &m->emissive_map);
    if (s == CG_OK)
        s = unit_numbers(doc, item, path, "emissiveFactor", 3, emissive);
    if (s == CG_OK)
        s = gltf_get_string(doc, item, path, "alphaMode", 0, &alpha_mode);
    if (s == CG_OK)
        s = number_in(doc, item, path, "alphaCutoff", 0.5, 0, 1e308, &m->alpha_cutoff);
    if (s == CG_OK)
        s = gltf_get_bool(doc, item, path, "doubleSided", 0, &m->double_sided);
    if (s == CG_OK)
        s = gltf_get_object(doc, item, path, "extensions", 0, &extensions);
    char ext_path[128];
    snprintf(ext_path, sizeof ext_path, "%s.extensions", path);
    if (s == CG_OK)
        s = gltf_get_object(doc, extensions, ext_path, "KHR_materials_emissive_strength", 0,
                            &strength);
    if (s == CG_OK && strength) {
        snprintf(ext_path, sizeof ext_path, "%s.extensions.KHR_materials_emissive_strength", path);
        s = number_in(doc, strength, ext_path, "emissiveStrength", 1, 0, 1e308, &emissive_strength);
        snprintf(ext_path, sizeof ext_path, "%s.extensions", path);
    }
    if (s == CG_OK)
        s = gltf_get_object(doc, extensions, ext_path, "KHR_materials_unlit", 0, &unlit);
    if (s != CG_OK)
        return s;
    if (alpha_mode) {
        if (strcmp(alpha_mode, "OPAQUE") == 0)
            m->alpha_mode = CG_MESH_ALPHA_OPAQUE;
        else if (strcmp(alpha_mode, "MASK") == 0)
            m->alpha_mode = CG_MESH_ALPHA_MASK;
        else if (strcmp(alpha_mode, "BLEND") == 0)
            m->alpha_mode = CG_MESH_ALPHA_BLEND;
        else
            return gltf_fail(doc, path, "alphaMode", "\"OPAQUE\", \"MASK\" or \"BLEND\"",
                             cJSON_GetObjectItemCaseSensitive(item, "alphaMode"));
    }
    cg_rgbaf color = {(float)base[0], (float)base[1], (float)base[2], (float)base[3]};
    cg_rgbaf glow = {(float)(emissive[0] * emissive_strength),
                     (float)(emissive[1] * emissive_strength),
                     (float)(emissive[2] * emissive_strength), 1};
    m->base_color = color;
    m->emissive = glow;
    m->unlit = unlit != NULL;
    return CG_OK;
}

cg_status gltf_read_materials(gltf_document *doc, cg_mesh *mesh)
{
    size_t n = doc->materials.count;
    /* textures, images and samplers nobody uses are checked too */
    for (size_t i = 0; i < doc->textures.count; i++) {
        char path[48];
        snprintf(path, sizeof path, "textures[%zu]", i);
        size_t sampler, source;
        cg_status s = gltf_get_index(doc, doc->textures.items[i], path, "sampler", 0,
                                     &doc->samplers, "samplers", &sampler);
        if (s == CG_OK)
            s = gltf_get_index(doc, doc->textures.items[i], path, "source", 0, &doc->images,
                               "images", &source);
        if (s != CG_OK)
            return s;
    }
    for (size_t i = 0; i < doc->samplers.count; i++) {
        cg_mesh_texture_ref scratch;
        memset(&scratch, 0, sizeof scratch);
        cg_status s = read_sampler(doc, i, &scratch);
        if (s != CG_OK)
            return s;
    }
    if (!n)
        return CG_OK;
    if (!(mesh->materials = calloc(n, sizeof *mesh->materials)))
        return gltf_out_of_memory(doc);
    for (size_t i = 0; i < n; i++) {
        mesh->material_count = i + 1; /* so that cg_mesh_free clears what is read */
        cg_status s = read_material(doc, i, &mesh->materials[i]);
        if (s != CG_OK)
            return s;
    }
    return CG_OK;
}
