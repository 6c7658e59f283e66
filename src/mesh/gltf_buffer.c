/* glTF buffers and buffer views.  A buffer's bytes come from the GLB file's
 * BIN chunk (a buffer without uri in a .glb), from a base64 data: URI, or
 * from a file named by a relative URI beside the .gltf; each must hold at
 * least its byteLength bytes.  A buffer view is a checked slice of one. */
#include "gltf_internal.h"
#include "../core/base64.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>

/* Percent-decodes a relative URI into a path beside the .gltf (a new string);
 * NULL with *bad set on a malformed escape or a NUL. */
static char *uri_to_path(const char *directory, const char *uri, int *bad)
{
    size_t dir_length = strlen(directory), uri_length = strlen(uri);
    char *path = malloc(dir_length + uri_length + 2);
    *bad = 0;
    if (!path)
        return NULL;
    memcpy(path, directory, dir_length);
    size_t n = dir_length;
    path[n++] = '/';
    for (size_t i = 0; i < uri_length; i++) {
        char c = uri[i];
        if (c == '%') {
            if (i + 2 >= uri_length || !isxdigit((unsigned char)uri[i + 1])
                || !isxdigit((unsigned char)uri[i + 2])) {
                *bad = 1;
                break;
            }
            char hex[3] = {uri[i + 1], uri[i + 2], '\0'};
            long value = strtol(hex, NULL, 16);
            if (value == 0) {
                *bad = 1;
                break;
            }
            path[n++] = (char)value;
            i += 2;
        } else {
            path[n++] = c;
        }
    }
    if (*bad) {
        free(path);
        return NULL;
    }
    path[n] = '\0';
    return path;
}

/* Where a URI's bytes are: a data: URI decoded, or the file it names. */
static cg_status load_uri(gltf_document *doc, const char *uri, const char *path,
                          unsigned char **bytes, size_t *size)
{
    char here[96];
    snprintf(here, sizeof here, "%s.uri", path);
    if (strncmp(uri, "data:", 5) == 0) {
        const char *comma = strchr(uri, ',');
        const char *marker = comma ? comma - 7 : NULL;
        if (!comma || marker < uri + 5 || strncmp(marker, ";base64", 7) != 0)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s: expected a base64 data: URI (data:...;base64,...)",
                                doc->name, here);
        int ok = core_base64_decode(comma + 1, strlen(comma + 1), 0, bytes, size);
        if (ok < 0)
            return gltf_out_of_memory(doc);
        if (ok == 0)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s: expected base64 text after 'base64,', got a character "
                                "outside A-Z a-z 0-9 + /",
                                doc->name, here);
        return CG_OK;
    }
    const char *colon = strchr(uri, ':'), *slash = strchr(uri, '/');
    if ((colon && (!slash || colon < slash)) || uri[0] == '/' || uri[0] == '\0')
        return cg_error_set(doc->err, CG_EUNSUPPORTED,
                            "%s: %s: expected a relative file name or a data: URI, got \"%.60s\"",
                            doc->name, here, uri);
    if (!doc->directory)
        return cg_error_set(doc->err, CG_EUNSUPPORTED,
                            "%s: %s: the file \"%.60s\" is not read when the glTF comes from "
                            "memory",
                            doc->name, here, uri);
    int bad;
    char *file = uri_to_path(doc->directory, uri, &bad);
    if (!file)
        return bad ? cg_error_set(doc->err, CG_EFORMAT,
                                  "%s: %s: expected %%XX escapes of two hex digits (not %%00), "
                                  "got \"%.60s\"",
                                  doc->name, here, uri)
                   : gltf_out_of_memory(doc);
    cg_error inner;
    cg_status s = mesh_read_file(file, bytes, size, &inner);
    if (s != CG_OK)
        s = cg_error_set(doc->err, s, "%s: %s: %s", doc->name, here, inner.message);
    free(file);
    return s;
}

cg_status gltf_load_buffers(gltf_document *doc)
{
    if (doc->buffers.count && !(doc->loaded = calloc(doc->buffers.count, sizeof *doc->loaded)))
        return gltf_out_of_memory(doc);
    for (size_t i = 0; i < doc->buffers.count; i++) {
        const cJSON *buffer = doc->buffers.items[i];
        char path[48];
        snprintf(path, sizeof path, "buffers[%zu]", i);
        int64_t length;
        const char *uri;
        cg_status s = gltf_get_integer(doc, buffer, path, "byteLength", 1, 0, 1,
                                       (int64_t)CG_MESH_MAX_FILE_BYTES, &length);
        if (s == CG_OK)
            s = gltf_get_string(doc, buffer, path, "uri", 0, &uri);
        if (s != CG_OK)
            return s;
        gltf_buffer *loaded = &doc->loaded[i];
        size_t size = 0;
        if (!uri) {
            if (i != 0 || !doc->glb_binary)
                return cg_error_set(doc->err, CG_EFORMAT,
                                    "%s: %s: expected a uri (only buffers[0] of a .glb file with "
                                    "a BIN chunk may leave it out)",
                                    doc->name, path);
            loaded->bytes = doc->glb_binary;
            size = doc->glb_binary_size;
        } else {
            if ((s = load_uri(doc, uri, path, &loaded->owned, &size)) != CG_OK)
                return s;
            loaded->bytes = loaded->owned;
            if (strncmp(uri, "data:", 5) != 0)
                doc->input_bytes += size;
        }
        if (size < (size_t)length)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s.byteLength: expected at most the %zu bytes the data "
                                "holds, got %lld",
                                doc->name, path, size, (long long)length);
        loaded->byte_length = (size_t)length;
    }
    return CG_OK;
}

void gltf_free_buffers(gltf_document *doc)
{
    if (doc->loaded)
        for (size_t i = 0; i < doc->buffers.count; i++)
            free(doc->loaded[i].owned);
    free(doc->loaded);
    doc->loaded = NULL;
}

cg_status gltf_get_view(gltf_document *doc, size_t index, gltf_view *out)
{
    const cJSON *view = doc->buffer_views.items[index];
    char path[48];
    snprintf(path, sizeof path, "bufferViews[%zu]", index);
    size_t buffer;
    int64_t offset, length, stride;
    cg_status s = gltf_get_index(doc, view, path, "buffer", 1, &doc->buffers, "buffers", &buffer);
    if (s == CG_OK)
        s = gltf_get_integer(doc, view, path, "byteOffset", 0, 0, 0, INT64_MAX / 4, &offset);
    if (s == CG_OK)
        s = gltf_get_integer(doc, view, path, "byteLength", 1, 0, 1, INT64_MAX / 4, &length);
    if (s == CG_OK)
        s = gltf_get_integer(doc, view, path, "byteStride", 0, 0, 4, 252, &stride);
    if (s != CG_OK)
        return s;
    if (stride % 4)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s.byteStride: expected a multiple of 4, got %lld", doc->name,
                            path, (long long)stride);
    const gltf_buffer *data = &doc->loaded[buffer];
    if ((uint64_t)offset + (uint64_t)length > data->byte_length)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s: expected to lie inside buffers[%zu] (%zu bytes), but "
                            "byteOffset %lld + byteLength %lld = %llu",
                            doc->name, path, buffer, data->byte_length, (long long)offset,
                            (long long)length, (unsigned long long)(offset + length));
    out->bytes = data->bytes + offset;
    out->byte_length = (size_t)length;
    out->byte_stride = (size_t)stride;
    out->buffer_offset = (size_t)offset;
    return CG_OK;
}
