/* The glTF 2.0 reader: a .glb container or .gltf text, its JSON, the
 * top-level checks, and the mesh of the default scene in world space.
 *
 *   .glb:  header  | chunk 0: JSON       | chunk 1: BIN (optional)
 *          magic "glTF", version 2, total length; each chunk: length, type,
 *          data padded to 4 bytes.
 *
 * The reader works in three steps, so that memory follows the file's data:
 * check the document and list the mesh instances of the default scene; add
 * up their vertices and triangles; allocate the mesh once and fill it. */
#include "gltf_internal.h"

#include <stdio.h>
#include <stdlib.h>

#define GLB_JSON 0x4E4F534Au
#define GLB_BIN 0x004E4942u

static uint32_t u32_at(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Finds the JSON and BIN chunks of a .glb file. */
static cg_status read_container(gltf_document *doc, const unsigned char *bytes, size_t size,
                                const char **json, size_t *json_size)
{
    if (size < 20)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: byte %zu: expected a 12-byte GLB header and a JSON chunk, the "
                            "file ends",
                            doc->name, size);
    uint32_t version = u32_at(bytes + 4), length = u32_at(bytes + 8);
    if (version != 2)
        return cg_error_set(doc->err, CG_EUNSUPPORTED, "%s: byte 4: expected GLB version 2, got %u",
                            doc->name, version);
    if (length != size)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: byte 8: expected the GLB length to be the file size %zu, got %u",
                            doc->name, size, length);
    size_t at = 12;
    for (int chunk = 0; at < size; chunk++) {
        if (size - at < 8)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: byte %zu: expected a chunk header of 8 bytes, %zu remain",
                                doc->name, at, size - at);
        uint32_t chunk_length = u32_at(bytes + at), type = u32_at(bytes + at + 4);
        if (chunk_length > size - at - 8)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: byte %zu: expected a chunk of at most %zu bytes, got a length "
                                "of %u",
                                doc->name, at, size - at - 8, chunk_length);
        const unsigned char *data = bytes + at + 8;
        if (chunk == 0 && type != GLB_JSON)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: byte %zu: expected the JSON chunk first (type 0x4E4F534A), "
                                "got type 0x%08X",
                                doc->name, at + 4, type);
        if (chunk == 0) {
            *json = (const char *)data;
            *json_size = chunk_length;
        } else if (chunk == 1 && type == GLB_BIN) {
            doc->glb_binary = data;
            doc->glb_binary_size = chunk_length;
        } else if (type == GLB_JSON || type == GLB_BIN) {
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: byte %zu: expected one JSON chunk then at most one BIN "
                                "chunk, got another",
                                doc->name, at + 4);
        } /* chunks of other types are to be ignored */
        at += 8 + ((size_t)chunk_length + 3) / 4 * 4;
    }
    return CG_OK;
}

static cg_status parse_json(gltf_document *doc, const char *json, size_t size)
{
    if (size >= 3 && memcmp(json, "\xEF\xBB\xBF", 3) == 0) { /* a UTF-8 byte order mark */
        json += 3;
        size -= 3;
    }
    const char *end = NULL;
    doc->root = cJSON_ParseWithLengthOpts(json, size, &end, 0);
    if (!doc->root) {
        size_t at = end && end >= json && end <= json + size ? (size_t)(end - json) : 0;
        size_t line = 1;
        for (size_t i = 0; i < at; i++)
            line += json[i] == '\n';
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: JSON line %zu (byte %zu): expected valid JSON (or out of memory)",
                            doc->name, line, at);
    }
    if (!cJSON_IsObject(doc->root))
        return gltf_fail(doc, "the top level", NULL, "a JSON object", doc->root);
    return CG_OK;
}

/* Extensions cg reads, or that change nothing for a mesh. */
static int extension_supported(const char *name)
{
    static const char *const supported[] = {
        "KHR_texture_transform", "KHR_materials_emissive_strength",
        "KHR_lights_punctual",   "KHR_mesh_quantization",
        "KHR_materials_unlit",
    };
    for (size_t i = 0; i < sizeof supported / sizeof supported[0]; i++)
        if (strcmp(name, supported[i]) == 0)
            return 1;
    return 0;
}

static cg_status check_asset(gltf_document *doc)
{
    const cJSON *asset;
    const char *version, *min_version;
    cg_status s = gltf_get_object(doc, doc->root, "", "asset", 1, &asset);
    if (s == CG_OK)
        s = gltf_get_string(doc, asset, "asset", "version", 1, &version);
    if (s == CG_OK)
        s = gltf_get_string(doc, asset, "asset", "minVersion", 0, &min_version);
    if (s != CG_OK)
        return s;
    if (strncmp(version, "2.", 2) != 0)
        return cg_error_set(doc->err, version[0] == '1' ? CG_EUNSUPPORTED : CG_EFORMAT,
                            "%s: asset.version: expected \"2.x\" (cg reads glTF 2), got \"%.20s\"",
                            doc->name, version);
    if (min_version && strcmp(min_version, "2.0") != 0)
        return cg_error_set(doc->err, CG_EUNSUPPORTED,
                            "%s: asset.minVersion: cg reads glTF 2.0, the file needs \"%.20s\"",
                            doc->name, min_version);
    gltf_list required;
    if ((s = gltf_get_list(doc, doc->root, "", "extensionsRequired", 1, &required)) != CG_OK)
        return s;
    for (size_t i = 0; s == CG_OK && i < required.count; i++) {
        const cJSON *item = required.items[i];
        char path[64];
        snprintf(path, sizeof path, "extensionsRequired[%zu]", i);
        if (!cJSON_IsString(item))
            s = gltf_fail(doc, path, NULL, "an extension name", item);
        else if (!extension_supported(item->valuestring))
            s = cg_error_set(doc->err, CG_EUNSUPPORTED,
                             "%s: %s: the file requires the extension %.60s, which cg does not "
                             "read",
                             doc->name, path, item->valuestring);
    }
    gltf_list_free(&required);
    return s;
}

/* Every item of every top-level array: an object whose name, when given, is
 * a string and whose extensions, when given, are an object. */
static cg_status check_common(gltf_document *doc, const gltf_list *list, const char *key)
{
    for (size_t i = 0; i < list->count; i++) {
        char path[64];
        snprintf(path, sizeof path, "%s[%zu]", key, i);
        const char *name;
        const cJSON *extensions;
        cg_status s = gltf_get_string(doc, list->items[i], path, "name", 0, &name);
        if (s == CG_OK)
            s = gltf_get_object(doc, list->items[i], path, "extensions", 0, &extensions);
        if (s != CG_OK)
            return s;
    }
    return CG_OK;
}

static cg_status read_lists(gltf_document *doc)
{
    struct {
        gltf_list *list;
        const char *key;
    } lists[] = {
        {&doc->accessors, "accessors"}, {&doc->buffer_views, "bufferViews"},
        {&doc->buffers, "buffers"},     {&doc->meshes, "meshes"},
        {&doc->nodes, "nodes"},         {&doc->scenes, "scenes"},
        {&doc->materials, "materials"}, {&doc->textures, "textures"},
        {&doc->images, "images"},       {&doc->cameras, "cameras"},
        {&doc->skins, "skins"},         {&doc->animations, "animations"},
        {&doc->samplers, "samplers"},
    };
    for (size_t i = 0; i < sizeof lists / sizeof lists[0]; i++) {
        cg_status s = gltf_get_object_list(doc, doc->root, "", lists[i].key, lists[i].list);
        if (s == CG_OK)
            s = check_common(doc, lists[i].list, lists[i].key);
        if (s != CG_OK)
            return s;
    }
    const cJSON *extensions, *lights;
    cg_status s = gltf_get_object(doc, doc->root, "", "extensions", 0, &extensions);
    if (s == CG_OK)
        s = gltf_get_object(doc, extensions, "extensions", "KHR_lights_punctual", 0, &lights);
    if (s == CG_OK && lights)
        s = gltf_get_object_list(doc, lights, "extensions.KHR_lights_punctual", "lights",
                                 &doc->lights);
    const char *extension_names[] = {"extensionsUsed"};
    gltf_list used;
    if (s == CG_OK
        && (s = gltf_get_list(doc, doc->root, "", extension_names[0], 1, &used)) == CG_OK) {
        for (size_t i = 0; i < used.count; i++)
            if (cJSON_IsString(used.items[i])
                && strcmp(used.items[i]->valuestring, "KHR_mesh_quantization") == 0)
                doc->quantized = 1;
        gltf_list_free(&used);
    }
    return s;
}

/* "skipped 2 line primitives, 1 skin (the rest pose is drawn)..." */
static char *write_notes(const gltf_document *doc)
{
    const gltf_skipped *k = &doc->skipped;
    struct {
        size_t count;
        const char *what;
    } items[] = {
        {k->point_primitives, "point primitive(s) (not drawn)"},
        {k->line_primitives, "line primitive(s) (not drawn)"},
        {k->no_position_primitives, "primitive(s) without POSITION (not drawn)"},
        {k->skins, "skin(s) (the rest pose is drawn)"},
        {k->morph_targets, "morph target(s) (the base shape is drawn)"},
        {k->animations, "animation(s) (the rest pose is drawn)"},
        {k->cameras, "camera(s) (recorded, not used by cg_mesh)"},
        {k->lights, "KHR_lights_punctual light(s) (recorded, not used by cg_mesh)"},
    };
    char text[1024];
    size_t n = 0;
    text[0] = '\0';
    for (size_t i = 0; i < sizeof items / sizeof items[0]; i++)
        if (items[i].count && n < sizeof text - 100)
            n += (size_t)snprintf(text + n, sizeof text - n, "%s: %zu %s\n", doc->name,
                                  items[i].count, items[i].what);
    if (!n)
        return NULL;
    char *notes = malloc(n + 1);
    if (notes)
        memcpy(notes, text, n + 1);
    return notes;
}

static void free_document(gltf_document *doc)
{
    gltf_free_buffers(doc);
    gltf_list *lists[] = {&doc->accessors, &doc->buffer_views, &doc->buffers,   &doc->meshes,
                          &doc->nodes,     &doc->scenes,       &doc->materials, &doc->textures,
                          &doc->images,    &doc->cameras,      &doc->skins,     &doc->animations,
                          &doc->lights,    &doc->samplers};
    for (size_t i = 0; i < sizeof lists / sizeof lists[0]; i++)
        gltf_list_free(lists[i]);
    cJSON_Delete(doc->root);
}

static cg_status build_mesh(gltf_document *doc, cg_mesh **out)
{
    gltf_instance_array instances = {0};
    gltf_totals totals;
    cg_status s = CG_OK;
    /* every buffer view and accessor, used or not, follows the rules */
    for (size_t i = 0; s == CG_OK && i < doc->buffer_views.count; i++) {
        gltf_view view;
        s = gltf_get_view(doc, i, &view);
    }
    for (size_t i = 0; s == CG_OK && i < doc->accessors.count; i++) {
        gltf_accessor accessor;
        s = gltf_accessor_describe(doc, i, &accessor);
    }
    if (s == CG_OK)
        s = gltf_check_cameras_and_lights(doc);
    if (s == CG_OK)
        s = gltf_collect_instances(doc, &instances);
    if (s == CG_OK)
        s = gltf_count_primitives(doc, &instances, &totals);
    cg_mesh *mesh = NULL;
    if (s == CG_OK) {
        unsigned flags = (totals.all_normals ? CG_MESH_NORMALS : 0)
                         | (totals.any_texcoords ? CG_MESH_TEXCOORDS : 0)
                         | (totals.any_colors ? CG_MESH_COLORS : 0);
        s = cg_mesh_create(&mesh, totals.vertices, totals.triangles, 3 * totals.triangles, flags);
        if (s != CG_OK)
            s = cg_error_set(doc->err, s, "%s: %zu vertices and %zu triangles: %s", doc->name,
                             totals.vertices, totals.triangles,
                             s == CG_ENOMEM ? "out of memory" : "more than cg_mesh holds");
    }
    if (s == CG_OK && doc->materials.count && totals.triangles) {
        if (!(mesh->face_materials = malloc(totals.triangles * sizeof *mesh->face_materials)))
            s = gltf_out_of_memory(doc);
        for (size_t f = 0; s == CG_OK && f < totals.triangles; f++)
            mesh->face_materials[f] = CG_MESH_NO_MATERIAL;
    }
    if (s == CG_OK)
        s = gltf_fill_mesh(doc, &instances, mesh);
    if (s == CG_OK)
        s = gltf_read_materials(doc, mesh);
    if (s == CG_OK) {
        doc->skipped.skins = doc->skins.count;
        doc->skipped.animations = doc->animations.count;
        doc->skipped.cameras = doc->cameras.count;
        doc->skipped.lights = doc->lights.count;
        mesh->notes = write_notes(doc);
    }
    core_array_free(&instances);
    if (s != CG_OK) {
        cg_mesh_free(mesh);
        return s;
    }
    *out = mesh;
    return CG_OK;
}

cg_status gltf_read(const unsigned char *bytes, size_t size, const char *name,
                    const char *directory, cg_mesh **out, cg_error *err)
{
    gltf_document doc;
    memset(&doc, 0, sizeof doc);
    doc.name = name;
    doc.input_bytes = size;
    doc.directory = directory;
    doc.err = err;
    *out = NULL;
    const char *json = (const char *)bytes;
    size_t json_size = size;
    cg_status s = CG_OK;
    if (size >= 4 && memcmp(bytes, "glTF", 4) == 0)
        s = read_container(&doc, bytes, size, &json, &json_size);
    if (s == CG_OK)
        s = parse_json(&doc, json, json_size);
    if (s == CG_OK)
        s = check_asset(&doc);
    if (s == CG_OK)
        s = read_lists(&doc);
    size_t scene;
    if (s == CG_OK) /* the document's own structure before any buffer is read */
        s = gltf_get_index(&doc, doc.root, "", "scene", 0, &doc.scenes, "scenes", &scene);
    if (s == CG_OK)
        s = gltf_load_buffers(&doc);
    if (s == CG_OK)
        s = build_mesh(&doc, out);
    free_document(&doc);
    return s;
}
