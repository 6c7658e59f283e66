/* glTF accessors: typed elements in a buffer view.
 *
 *   buffer view  |<------------------- byteLength ------------------->|
 *                 byteOffset  element 0        element 1
 *                |---------->[x y z]...pad...[x y z]...pad...
 *                            |<-- stride --->|
 *
 * The stride is the view's byteStride, or the element size when it has
 * none.  A matrix's columns each start on a 4-byte boundary (a MAT3 of
 * bytes takes 12 bytes, not 9).  A sparse accessor starts from its view's
 * elements (zeros without one) and replaces those sparse.indices name with
 * sparse.values. */
#include "gltf_internal.h"

#include <stdio.h>
#include <stdlib.h>

static size_t component_size(int type)
{
    switch (type) {
    case GLTF_BYTE:
    case GLTF_UNSIGNED_BYTE: return 1;
    case GLTF_SHORT:
    case GLTF_UNSIGNED_SHORT: return 2;
    case GLTF_UNSIGNED_INT:
    case GLTF_FLOAT: return 4;
    }
    return 0;
}

static const char *const type_names[] = {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
static const int type_components[] = {1, 2, 3, 4, 4, 9, 16};

/* Rows of a matrix type (0 for scalars and vectors). */
static int matrix_rows(int components)
{
    return components == 4 ? 2 : components == 9 ? 3 : components == 16 ? 4 : 0;
}

typedef struct layout {
    size_t element_size;  /* bytes of one element, column padding included */
    size_t column_stride; /* bytes between matrix columns; 0 for vectors */
    int rows;
} layout;

static layout layout_of(const gltf_accessor *a)
{
    layout l = {0, 0, 0};
    size_t size = component_size(a->component_type);
    int is_matrix = strncmp(a->type, "MAT", 3) == 0;
    if (!is_matrix) {
        l.element_size = size * (size_t)a->components;
        return l;
    }
    l.rows = matrix_rows(a->components);
    l.column_stride = (size * (size_t)l.rows + 3) / 4 * 4;
    l.element_size = l.column_stride * (size_t)l.rows;
    return l;
}

/* Offset of component c within an element. */
static size_t component_offset(const layout *l, size_t size, int c)
{
    if (!l->rows)
        return size * (size_t)c;
    return l->column_stride * (size_t)(c / l->rows) + size * (size_t)(c % l->rows);
}

static cg_status check_sparse(gltf_document *doc, const cJSON *sparse, const char *path,
                              const gltf_accessor *a, const layout *l)
{
    int64_t count, offset;
    int64_t index_type;
    size_t view;
    const cJSON *indices, *values;
    char sub[96];
    cg_status s = gltf_get_integer(doc, sparse, path, "count", 1, 0, 1, (int64_t)a->count, &count);
    if (s == CG_OK)
        s = gltf_get_object(doc, sparse, path, "indices", 1, &indices);
    if (s == CG_OK)
        s = gltf_get_object(doc, sparse, path, "values", 1, &values);
    if (s != CG_OK)
        return s;
    /* indices */
    snprintf(sub, sizeof sub, "%s.indices", path);
    s = gltf_get_index(doc, indices, sub, "bufferView", 1, &doc->buffer_views, "bufferViews",
                       &view);
    if (s == CG_OK)
        s = gltf_get_integer(doc, indices, sub, "byteOffset", 0, 0, 0, INT64_MAX / 4, &offset);
    if (s == CG_OK)
        s = gltf_get_integer(doc, indices, sub, "componentType", 1, 0, 0, 1 << 20, &index_type);
    if (s != CG_OK)
        return s;
    if (index_type != GLTF_UNSIGNED_BYTE && index_type != GLTF_UNSIGNED_SHORT
        && index_type != GLTF_UNSIGNED_INT)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s.componentType: expected 5121, 5123 or 5125 (unsigned byte, "
                            "short or int), got %lld",
                            doc->name, sub, (long long)index_type);
    gltf_view v;
    if ((s = gltf_get_view(doc, view, &v)) != CG_OK)
        return s;
    size_t need = (size_t)count * component_size((int)index_type);
    if ((uint64_t)offset + need > v.byte_length)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s: expected %zu index bytes inside bufferViews[%zu] (%zu bytes) "
                            "from byteOffset %lld",
                            doc->name, sub, need, view, v.byte_length, (long long)offset);
    /* values */
    snprintf(sub, sizeof sub, "%s.values", path);
    s = gltf_get_index(doc, values, sub, "bufferView", 1, &doc->buffer_views, "bufferViews", &view);
    if (s == CG_OK)
        s = gltf_get_integer(doc, values, sub, "byteOffset", 0, 0, 0, INT64_MAX / 4, &offset);
    if (s == CG_OK)
        s = gltf_get_view(doc, view, &v);
    if (s != CG_OK)
        return s;
    need = (size_t)count * l->element_size;
    if ((uint64_t)offset + need > v.byte_length)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s: expected %zu value bytes inside bufferViews[%zu] (%zu bytes) "
                            "from byteOffset %lld",
                            doc->name, sub, need, view, v.byte_length, (long long)offset);
    return CG_OK;
}

cg_status gltf_accessor_describe(gltf_document *doc, size_t index, gltf_accessor *out)
{
    const cJSON *accessor = doc->accessors.items[index];
    char path[48];
    snprintf(path, sizeof path, "accessors[%zu]", index);
    int64_t component_type, count, offset;
    const char *type;
    int normalized;
    size_t view = SIZE_MAX;
    cg_status s = gltf_get_integer(doc, accessor, path, "componentType", 1, 0, 0, 1 << 20,
                                   &component_type);
    if (s == CG_OK)
        s = gltf_get_integer(doc, accessor, path, "count", 1, 0, 1, CG_MESH_MAX_VERTICES, &count);
    if (s == CG_OK)
        s = gltf_get_string(doc, accessor, path, "type", 1, &type);
    if (s == CG_OK)
        s = gltf_get_bool(doc, accessor, path, "normalized", 0, &normalized);
    if (s == CG_OK)
        s = gltf_get_index(doc, accessor, path, "bufferView", 0, &doc->buffer_views, "bufferViews",
                           &view);
    if (s == CG_OK)
        s = gltf_get_integer(doc, accessor, path, "byteOffset", 0, 0, 0, INT64_MAX / 4, &offset);
    if (s != CG_OK)
        return s;
    size_t size = component_size((int)component_type);
    if (!size)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s.componentType: expected 5120, 5121, 5122, 5123, 5125 or 5126, "
                            "got %lld",
                            doc->name, path, (long long)component_type);
    int type_index = -1;
    for (int t = 0; t < 7; t++)
        if (strcmp(type, type_names[t]) == 0)
            type_index = t;
    if (type_index < 0)
        return gltf_fail(doc, path, "type",
                         "\"SCALAR\", \"VEC2\", \"VEC3\", \"VEC4\", \"MAT2\", \"MAT3\" or \"MAT4\"",
                         cJSON_GetObjectItemCaseSensitive(accessor, "type"));
    if (normalized && (component_type == GLTF_FLOAT || component_type == GLTF_UNSIGNED_INT))
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s.normalized: expected false for float and unsigned int "
                            "components",
                            doc->name, path);
    out->index = index;
    out->count = (size_t)count;
    out->component_type = (int)component_type;
    out->components = type_components[type_index];
    out->normalized = normalized;
    out->type = type_names[type_index];
    layout l = layout_of(out);
    if (view == SIZE_MAX) {
        if (out->count * (size_t)out->components > gltf_element_budget(doc))
            return cg_error_set(doc->err, CG_ERANGE,
                                "%s: %s.count: %zu %s elements without a bufferView (all zeros) "
                                "are more than cg reads from a file of %zu bytes",
                                doc->name, path, out->count, type, doc->input_bytes);
        if (cJSON_GetObjectItemCaseSensitive(accessor, "byteOffset"))
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s.byteOffset: expected no byteOffset without a bufferView",
                                doc->name, path);
    } else {
        gltf_view v;
        if ((s = gltf_get_view(doc, view, &v)) != CG_OK)
            return s;
        if (offset % (int64_t)size || (v.buffer_offset + (size_t)offset) % size)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s.byteOffset: expected the data to start at a multiple of "
                                "%zu bytes (the component size) in its buffer, got byteOffset "
                                "%lld in bufferViews[%zu] at %zu",
                                doc->name, path, size, (long long)offset, view, v.buffer_offset);
        size_t stride = v.byte_stride ? v.byte_stride : l.element_size;
        if (stride < l.element_size)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: bufferViews[%zu].byteStride: expected at least %zu (the size "
                                "of a %s of this component type, for %s), got %zu",
                                doc->name, view, l.element_size, type, path, stride);
        uint64_t end = (uint64_t)offset + (uint64_t)stride * (out->count - 1) + l.element_size;
        if (end > v.byte_length)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s: expected %zu elements of %zu bytes (stride %zu) from "
                                "byteOffset %lld to fit in bufferViews[%zu] (%zu bytes), but they "
                                "end at byte %llu",
                                doc->name, path, out->count, l.element_size, stride,
                                (long long)offset, view, v.byte_length, (unsigned long long)end);
    }
    const cJSON *sparse;
    char sparse_path[64];
    snprintf(sparse_path, sizeof sparse_path, "%s.sparse", path);
    if ((s = gltf_get_object(doc, accessor, path, "sparse", 0, &sparse)) != CG_OK)
        return s;
    if (sparse)
        return check_sparse(doc, sparse, sparse_path, out, &l);
    return CG_OK;
}

static uint32_t read_u32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* One component at p as a double, normalized as the accessor says. */
static double read_component(const unsigned char *p, int type, int normalized)
{
    switch (type) {
    case GLTF_BYTE: {
        double v = (int8_t)p[0];
        return normalized ? fmax(v / 127.0, -1.0) : v;
    }
    case GLTF_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
    case GLTF_SHORT: {
        double v = (int16_t)(uint16_t)(p[0] | p[1] << 8);
        return normalized ? fmax(v / 32767.0, -1.0) : v;
    }
    case GLTF_UNSIGNED_SHORT: {
        double v = (uint16_t)(p[0] | p[1] << 8);
        return normalized ? v / 65535.0 : v;
    }
    case GLTF_UNSIGNED_INT: return read_u32(p);
    default: {
        uint32_t bits = read_u32(p);
        float f;
        memcpy(&f, &bits, sizeof f);
        return f;
    }
    }
}

/* Reads `count` elements starting at bytes (stride apart) into values. */
static void read_elements(const gltf_accessor *a, const unsigned char *bytes, size_t stride,
                          size_t count, double *values)
{
    size_t k = (size_t)a->components;
    if (a->component_type == GLTF_FLOAT && strncmp(a->type, "MAT", 3) != 0) {
        /* the common case, without a switch per component */
        for (size_t i = 0; i < count; i++) {
            const unsigned char *element = bytes + i * stride;
            for (size_t c = 0; c < k; c++) {
                uint32_t bits = read_u32(element + 4 * c);
                float f;
                memcpy(&f, &bits, sizeof f);
                values[i * k + c] = f;
            }
        }
        return;
    }
    layout l = layout_of(a);
    size_t size = component_size(a->component_type);
    size_t offsets[16];
    for (int c = 0; c < a->components; c++)
        offsets[c] = component_offset(&l, size, c);
    for (size_t i = 0; i < count; i++) {
        const unsigned char *element = bytes + i * stride;
        for (int c = 0; c < a->components; c++)
            values[i * (size_t)a->components + (size_t)c] = read_component(
                element + offsets[c], a->component_type, a->normalized);
    }
}

/* A sparse part's view bytes at its byteOffset (checked by describe). */
static const unsigned char *sparse_bytes(gltf_document *doc, const cJSON *part)
{
    size_t view = (size_t)cJSON_GetObjectItemCaseSensitive(part, "bufferView")->valuedouble;
    const cJSON *offset = cJSON_GetObjectItemCaseSensitive(part, "byteOffset");
    gltf_view v;
    if (gltf_get_view(doc, view, &v) != CG_OK)
        return NULL;
    return v.bytes + (offset ? (size_t)offset->valuedouble : 0);
}

cg_status gltf_accessor_read_doubles(gltf_document *doc, const gltf_accessor *a, double *values)
{
    const cJSON *accessor = doc->accessors.items[a->index];
    const cJSON *view_item = cJSON_GetObjectItemCaseSensitive(accessor, "bufferView");
    layout l = layout_of(a);
    if (view_item) {
        gltf_view v;
        cg_status s = gltf_get_view(doc, (size_t)view_item->valuedouble, &v);
        if (s != CG_OK)
            return s;
        const cJSON *offset = cJSON_GetObjectItemCaseSensitive(accessor, "byteOffset");
        read_elements(a, v.bytes + (offset ? (size_t)offset->valuedouble : 0),
                      v.byte_stride ? v.byte_stride : l.element_size, a->count, values);
    } else {
        memset(values, 0, a->count * (size_t)a->components * sizeof *values);
    }
    const cJSON *sparse = cJSON_GetObjectItemCaseSensitive(accessor, "sparse");
    if (!sparse)
        return CG_OK;
    size_t count = (size_t)cJSON_GetObjectItemCaseSensitive(sparse, "count")->valuedouble;
    const cJSON *indices = cJSON_GetObjectItemCaseSensitive(sparse, "indices");
    const cJSON *values_part = cJSON_GetObjectItemCaseSensitive(sparse, "values");
    int index_type = (int)cJSON_GetObjectItemCaseSensitive(indices, "componentType")->valuedouble;
    const unsigned char *index_bytes = sparse_bytes(doc, indices);
    const unsigned char *value_bytes = sparse_bytes(doc, values_part);
    if (!index_bytes || !value_bytes)
        return doc->err ? doc->err->status : CG_EFORMAT;
    size_t index_size = component_size(index_type);
    int64_t previous = -1;
    for (size_t k = 0; k < count; k++) {
        gltf_accessor index_accessor = {0, 1, index_type, 1, 0, "SCALAR"};
        double target;
        read_elements(&index_accessor, index_bytes + k * index_size, index_size, 1, &target);
        if (target <= (double)previous || target >= (double)a->count)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: accessors[%zu].sparse.indices: expected strictly increasing "
                                "indices below %zu, got %.0f after %lld (entry %zu)",
                                doc->name, a->index, a->count, target, (long long)previous, k);
        previous = (int64_t)target;
        read_elements(a, value_bytes + k * l.element_size, l.element_size, 1,
                      values + (size_t)target * (size_t)a->components);
    }
    return CG_OK;
}

cg_status gltf_accessor_read_indices(gltf_document *doc, const gltf_accessor *a, uint32_t *values)
{
    if (a->components != 1 || a->normalized
        || (a->component_type != GLTF_UNSIGNED_BYTE && a->component_type != GLTF_UNSIGNED_SHORT
            && a->component_type != GLTF_UNSIGNED_INT))
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: accessors[%zu]: expected indices: a SCALAR of unsigned byte, "
                            "short or int (5121, 5123, 5125), not normalized; got %s of %d%s",
                            doc->name, a->index, a->type, a->component_type,
                            a->normalized ? ", normalized" : "");
    const cJSON *accessor = doc->accessors.items[a->index];
    const cJSON *view_item = cJSON_GetObjectItemCaseSensitive(accessor, "bufferView");
    if (view_item && !cJSON_GetObjectItemCaseSensitive(accessor, "sparse")) {
        /* straight from the view */
        gltf_view v;
        cg_status s = gltf_get_view(doc, (size_t)view_item->valuedouble, &v);
        if (s != CG_OK)
            return s;
        const cJSON *offset = cJSON_GetObjectItemCaseSensitive(accessor, "byteOffset");
        size_t size = component_size(a->component_type);
        size_t stride = v.byte_stride ? v.byte_stride : size;
        const unsigned char *p = v.bytes + (offset ? (size_t)offset->valuedouble : 0);
        for (size_t i = 0; i < a->count; i++, p += stride)
            values[i] = size == 1 ? p[0] : size == 2 ? (uint32_t)(p[0] | p[1] << 8) : read_u32(p);
        return CG_OK;
    }
    /* sparse or all zeros: through doubles (8 bytes per index, freed at once) */
    double *all = malloc(a->count * sizeof *all);
    if (!all)
        return gltf_out_of_memory(doc);
    cg_status s = gltf_accessor_read_doubles(doc, a, all);
    for (size_t i = 0; s == CG_OK && i < a->count; i++)
        values[i] = (uint32_t)all[i];
    free(all);
    return s;
}
