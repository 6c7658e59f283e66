/* The growable mesh builder every reader fills, and checks shared by the readers. */
#include "internal.h"

#include "cg/color.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

void builder_init(mesh_builder *b)
{
    memset(b, 0, sizeof *b);
}

void builder_free(mesh_builder *b)
{
    free(b->positions);
    free(b->normals);
    free(b->texcoords);
    free(b->colors);
    free(b->face_offsets);
    free(b->face_colors);
    free(b->face_indices);
    builder_init(b);
}

/* Resizes *array to capacity elements of size bytes. */
static cg_status resize(void **array, size_t capacity, size_t size)
{
    if (capacity > SIZE_MAX / size)
        return CG_ENOMEM;
    void *grown = realloc(*array, capacity ? capacity * size : size);
    if (!grown)
        return CG_ENOMEM;
    *array = grown;
    return CG_OK;
}

/* The capacity to grow to so that count + more fit: at least double. */
static cg_status next_capacity(size_t count, size_t capacity, size_t more, size_t limit,
                               size_t *out)
{
    if (more > limit || count > limit - more)
        return CG_ERANGE;
    size_t needed = count + more;
    size_t grown = capacity < 64 ? 64 : capacity + capacity / 2;
    if (grown < needed)
        grown = needed;
    if (grown > limit)
        grown = limit;
    *out = grown;
    return CG_OK;
}

cg_status builder_reserve_vertices(mesh_builder *b, size_t more)
{
    if (b->vertex_capacity - b->vertex_count >= more)
        return CG_OK;
    size_t capacity;
    cg_status s = next_capacity(b->vertex_count, b->vertex_capacity, more, CG_MESH_MAX_VERTICES,
                                &capacity);
    if (s == CG_OK)
        s = resize((void **)&b->positions, capacity, sizeof *b->positions);
    if (s == CG_OK && b->normals)
        s = resize((void **)&b->normals, capacity, sizeof *b->normals);
    if (s == CG_OK && b->texcoords)
        s = resize((void **)&b->texcoords, capacity, sizeof *b->texcoords);
    if (s == CG_OK && b->colors)
        s = resize((void **)&b->colors, capacity, sizeof *b->colors);
    if (s == CG_OK)
        b->vertex_capacity = capacity;
    return s;
}

cg_status builder_reserve_faces(mesh_builder *b, size_t more)
{
    if (b->face_offsets && b->face_capacity - b->face_count >= more)
        return CG_OK;
    size_t capacity;
    cg_status s = next_capacity(b->face_count, b->face_capacity, more, CG_MESH_MAX_INDICES,
                                &capacity);
    int first = b->face_offsets == NULL;
    if (s == CG_OK)
        s = resize((void **)&b->face_offsets, capacity + 1, sizeof *b->face_offsets);
    if (s == CG_OK && b->face_colors)
        s = resize((void **)&b->face_colors, capacity, sizeof *b->face_colors);
    if (s == CG_OK) {
        b->face_capacity = capacity;
        if (first)
            b->face_offsets[0] = 0;
    }
    return s;
}

cg_status builder_reserve_indices(mesh_builder *b, size_t more)
{
    if (b->index_capacity - b->index_count >= more)
        return CG_OK;
    size_t capacity;
    cg_status s = next_capacity(b->index_count, b->index_capacity, more, CG_MESH_MAX_INDICES,
                                &capacity);
    if (s == CG_OK)
        s = resize((void **)&b->face_indices, capacity, sizeof *b->face_indices);
    if (s == CG_OK)
        b->index_capacity = capacity;
    return s;
}

cg_status builder_add_arrays(mesh_builder *b, unsigned flags, cg_rgbaf fill)
{
    size_t vcap = b->vertex_capacity ? b->vertex_capacity : 1;
    size_t fcap = b->face_capacity ? b->face_capacity : 1;
    if ((flags & CG_MESH_NORMALS) && !b->normals) {
        if (!(b->normals = calloc(vcap, sizeof *b->normals)))
            return CG_ENOMEM;
    }
    if ((flags & CG_MESH_TEXCOORDS) && !b->texcoords) {
        if (!(b->texcoords = calloc(vcap, sizeof *b->texcoords)))
            return CG_ENOMEM;
    }
    if ((flags & CG_MESH_COLORS) && !b->colors) {
        if (!(b->colors = malloc(vcap * sizeof *b->colors)))
            return CG_ENOMEM;
        for (size_t i = 0; i < b->vertex_count; i++)
            b->colors[i] = fill;
    }
    if ((flags & CG_MESH_FACE_COLORS) && !b->face_colors) {
        if (!(b->face_colors = malloc(fcap * sizeof *b->face_colors)))
            return CG_ENOMEM;
        for (size_t i = 0; i < b->face_count; i++)
            b->face_colors[i] = fill;
    }
    b->flags |= flags;
    return CG_OK;
}

cg_status builder_end_face(mesh_builder *b)
{
    if (!b->face_offsets || b->face_count == b->face_capacity) {
        cg_status s = builder_reserve_faces(b, 1);
        if (s != CG_OK)
            return s;
    }
    b->face_count++;
    b->face_offsets[b->face_count] = (uint32_t)b->index_count;
    return CG_OK;
}

/* Shrinks an array to count elements (keeping it when realloc fails). */
static void *shrink(void *array, size_t count, size_t size)
{
    if (!array)
        return NULL;
    void *smaller = realloc(array, count ? count * size : size);
    return smaller ? smaller : array;
}

cg_status builder_finish(mesh_builder *b, cg_mesh **out)
{
    *out = NULL;
    if (!b->face_offsets) {
        cg_status s = builder_reserve_faces(b, 1);
        if (s != CG_OK)
            return s;
    }
    if (!b->positions && builder_reserve_vertices(b, 1) != CG_OK)
        return CG_ENOMEM;
    if (!b->face_indices && builder_reserve_indices(b, 1) != CG_OK)
        return CG_ENOMEM;
    cg_mesh *m = calloc(1, sizeof *m);
    if (!m)
        return CG_ENOMEM;
    m->vertex_count = b->vertex_count;
    m->positions = shrink(b->positions, b->vertex_count, sizeof *m->positions);
    m->normals = shrink(b->normals, b->vertex_count, sizeof *m->normals);
    m->texcoords = shrink(b->texcoords, b->vertex_count, sizeof *m->texcoords);
    m->colors = shrink(b->colors, b->vertex_count, sizeof *m->colors);
    m->face_count = b->face_count;
    m->face_offsets = shrink(b->face_offsets, b->face_count + 1, sizeof *m->face_offsets);
    m->face_indices = shrink(b->face_indices, b->index_count, sizeof *m->face_indices);
    m->face_colors = shrink(b->face_colors, b->face_count, sizeof *m->face_colors);
    builder_init(b);
    *out = m;
    return CG_OK;
}

float mesh_color_component(double value, int is_float, int is_alpha)
{
    double v = is_float ? value : value / 255.0;
    if (!(v > 0))
        v = 0;
    if (v > 1)
        v = 1;
    return (float)(is_alpha ? v : cg_srgb_to_linear(v));
}

cg_status mesh_check_indices(const mesh_builder *b, const char *name, cg_error *err)
{
    for (size_t f = 0; f < b->face_count; f++)
        for (uint32_t k = b->face_offsets[f]; k < b->face_offsets[f + 1]; k++)
            if (b->face_indices[k] >= b->vertex_count)
                return cg_error_set(err, CG_EFORMAT,
                                    "%s: face %zu refers to vertex %u, but there are only %zu "
                                    "vertices",
                                    name, f, b->face_indices[k], b->vertex_count);
    return CG_OK;
}

cg_status mesh_nonfinite_error(cg_error *err, const char *name, size_t line, size_t byte,
                               const char *item, cg_vec3 p)
{
    int axis = mesh_nonfinite_axis(p);
    double value = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
    char where[48];
    if (line)
        snprintf(where, sizeof where, ":%zu", line);
    else
        snprintf(where, sizeof where, ": byte %zu", byte);
    return cg_error_set(err, CG_EFORMAT,
                        "%s%s: expected a finite vertex coordinate, got %c = %g%s%s%s", name, where,
                        "xyz"[axis < 0 ? 0 : axis], value, item ? " (" : "", item ? item : "",
                        item ? ")" : "");
}

cg_status mesh_note(char **notes, const char *format, ...)
{
    char line[600];
    va_list args;
    va_start(args, format);
    vsnprintf(line, sizeof line, format, args);
    va_end(args);
    size_t old = *notes ? strlen(*notes) : 0, n = strlen(line);
    char *grown = realloc(*notes, old + n + 2);
    if (!grown)
        return CG_ENOMEM;
    memcpy(grown + old, line, n);
    grown[old + n] = '\n';
    grown[old + n + 1] = '\0';
    *notes = grown;
    return CG_OK;
}
