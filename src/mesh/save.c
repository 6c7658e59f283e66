/* Mesh writers: OBJ (with an MTL library for face colours) and PLY (ASCII
 * or binary little-endian); OFF, STL and glTF are in save_off_stl.c and
 * gltf_write.c.  Each file is streamed to a temporary file
 * beside its destination and renamed over it only when complete
 * (src/core/safe_file.c). */
#include "internal.h"
#include "../core/safe_file.h"

#include "cg/color.h"

#include <stdio.h>
#include <stdlib.h>

/* Shortest of %.15g / %.17g that reads back as exactly v. */
static int format_double(char *buffer, double v)
{
    int n = snprintf(buffer, 32, "%.15g", v);
    const char *p = buffer;
    double back;
    if (v == v && !(parse_double(&p, buffer + n, &back) && back == v))
        n = snprintf(buffer, 32, "%.17g", v);
    return n;
}

static void put_numbers(FILE *f, const char *prefix, const double *v, int count)
{
    char buffer[40];
    fputs(prefix, f);
    for (int i = 0; i < count; i++) {
        int n = format_double(buffer, v[i]);
        putc(' ', f);
        fwrite(buffer, 1, (size_t)n, f);
    }
    putc('\n', f);
}

/* ---- OBJ ----------------------------------------------------------------- */

/* Distinct face colours, as material numbers. */
typedef struct color_table {
    cg_rgbaf *colors;
    uint32_t *slots; /* material + 1, 0 empty */
    size_t count, size;
} color_table;

static uint64_t color_hash(cg_rgbaf c)
{
    uint64_t w[2];
    memcpy(w, &c, sizeof w);
    uint64_t h = (w[0] ^ (w[1] * 0x9e3779b97f4a7c15u)) * 0xbf58476d1ce4e5b9u;
    return h ^ (h >> 31);
}

static cg_status color_index(color_table *t, cg_rgbaf c, uint32_t *out)
{
    if (2 * (t->count + 1) > t->size) {
        size_t size = t->size ? 2 * t->size : 256;
        uint32_t *slots = calloc(size, sizeof *slots);
        cg_rgbaf *colors = realloc(t->colors, size / 2 * sizeof *colors);
        if (!slots || !colors) {
            free(slots);
            if (colors)
                t->colors = colors;
            return CG_ENOMEM;
        }
        t->colors = colors;
        for (size_t i = 0; i < t->count; i++) {
            size_t j = color_hash(colors[i]) & (size - 1);
            while (slots[j])
                j = (j + 1) & (size - 1);
            slots[j] = (uint32_t)i + 1;
        }
        free(t->slots);
        t->slots = slots;
        t->size = size;
    }
    size_t j = color_hash(c) & (t->size - 1);
    while (t->slots[j]) {
        if (memcmp(&t->colors[t->slots[j] - 1], &c, sizeof c) == 0) {
            *out = t->slots[j] - 1;
            return CG_OK;
        }
        j = (j + 1) & (t->size - 1);
    }
    t->colors[t->count] = c;
    t->slots[j] = (uint32_t)++t->count;
    *out = (uint32_t)t->count - 1;
    return CG_OK;
}

/* PATH with its .obj extension (if any) replaced by .mtl. */
static char *library_path(const char *path)
{
    size_t length = strlen(path);
    if (length >= 4 && cg_mesh_format_from_path(path) == CG_MESH_FORMAT_OBJ
        && path[length - 4] == '.')
        length -= 4;
    char *out = malloc(length + 5);
    if (out) {
        memcpy(out, path, length);
        memcpy(out + length, ".mtl", 5);
    }
    return out;
}

static cg_status write_library(const char *path, const color_table *t, cg_error *err)
{
    safe_file o;
    cg_status s = safe_file_open(&o, path, err);
    if (s != CG_OK)
        return s;
    fputs("# material library written by cg: one diffuse colour per material\n", o.file);
    for (size_t m = 0; m < t->count; m++) {
        double kd[3] = {t->colors[m].r, t->colors[m].g, t->colors[m].b};
        double d = t->colors[m].a;
        fprintf(o.file, "newmtl cg_color_%zu\n", m);
        put_numbers(o.file, "Kd", kd, 3);
        put_numbers(o.file, "d", &d, 1);
    }
    return safe_file_close(&o, CG_OK, err);
}

static cg_status save_obj(const cg_mesh *m, const char *path, cg_error *err)
{
    color_table colors = {NULL, NULL, 0, 0};
    uint32_t *face_material = NULL;
    char *library = NULL;
    cg_status s = CG_OK;
    if (m->face_colors && m->face_count) {
        face_material = malloc(m->face_count * sizeof *face_material);
        library = library_path(path);
        if (!face_material || !library)
            s = CG_ENOMEM;
        for (size_t f = 0; s == CG_OK && f < m->face_count; f++)
            s = color_index(&colors, m->face_colors[f], &face_material[f]);
        if (s != CG_OK)
            s = cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
        if (s == CG_OK)
            s = write_library(library, &colors, err);
    }
    safe_file o;
    if (s == CG_OK)
        s = safe_file_open(&o, path, err);
    if (s == CG_OK) {
        FILE *f = o.file;
        fprintf(f, "# written by cg: %zu vertices, %zu faces\n", m->vertex_count, m->face_count);
        if (library) {
            const char *slash = strrchr(library, '/');
            fprintf(f, "mtllib %s\n", slash ? slash + 1 : library);
        }
        for (size_t v = 0; v < m->vertex_count; v++) {
            double p[6] = {m->positions[v].x, m->positions[v].y, m->positions[v].z, 0, 0, 0};
            if (m->colors) {
                p[3] = m->colors[v].r;
                p[4] = m->colors[v].g;
                p[5] = m->colors[v].b;
            }
            put_numbers(f, "v", p, m->colors ? 6 : 3);
        }
        for (size_t v = 0; m->texcoords && v < m->vertex_count; v++)
            put_numbers(f, "vt", &m->texcoords[v].x, 2);
        for (size_t v = 0; m->normals && v < m->vertex_count; v++)
            put_numbers(f, "vn", &m->normals[v].x, 3);
        uint32_t current = UINT32_MAX;
        for (size_t face = 0; face < m->face_count; face++) {
            if (face_material && face_material[face] != current) {
                current = face_material[face];
                fprintf(f, "usemtl cg_color_%u\n", current);
            }
            putc('f', f);
            for (uint32_t k = m->face_offsets[face]; k < m->face_offsets[face + 1]; k++) {
                unsigned long i = (unsigned long)m->face_indices[k] + 1;
                if (m->texcoords && m->normals)
                    fprintf(f, " %lu/%lu/%lu", i, i, i);
                else if (m->texcoords)
                    fprintf(f, " %lu/%lu", i, i);
                else if (m->normals)
                    fprintf(f, " %lu//%lu", i, i);
                else
                    fprintf(f, " %lu", i);
            }
            putc('\n', f);
        }
        s = safe_file_close(&o, CG_OK, err);
    }
    free(colors.colors);
    free(colors.slots);
    free(face_material);
    free(library);
    return s;
}

/* ---- PLY ----------------------------------------------------------------- */

/* The PLY body being written: binary, or ASCII with one item a line. */
typedef struct ply_out {
    FILE *file;
    int binary;
    int first; /* no value on this ASCII line yet */
} ply_out;

static void put_le(ply_out *o, uint64_t bits, int bytes)
{
    unsigned char b[8];
    for (int i = 0; i < bytes; i++)
        b[i] = (unsigned char)(bits >> (8 * i));
    fwrite(b, 1, (size_t)bytes, o->file);
}

/* Writes text for one ASCII value, with the blank before it. */
static void put_text(ply_out *o, const char *text, int n)
{
    if (!o->first)
        putc(' ', o->file);
    o->first = 0;
    fwrite(text, 1, (size_t)n, o->file);
}

static void put_double(ply_out *o, double v)
{
    if (o->binary) {
        uint64_t bits;
        memcpy(&bits, &v, 8);
        put_le(o, bits, 8);
    } else {
        char buffer[40];
        put_text(o, buffer, format_double(buffer, v));
    }
}

static void put_float(ply_out *o, double v)
{
    float x = (float)v;
    if (o->binary) {
        uint32_t bits;
        memcpy(&bits, &x, 4);
        put_le(o, bits, 4);
    } else {
        char buffer[40];
        put_text(o, buffer, snprintf(buffer, sizeof buffer, "%.9g", (double)x));
    }
}

static void put_integer(ply_out *o, uint32_t v, int bytes)
{
    if (o->binary) {
        put_le(o, v, bytes);
    } else {
        char buffer[16];
        put_text(o, buffer, snprintf(buffer, sizeof buffer, "%lu", (unsigned long)v));
    }
}

static void put_color(ply_out *o, cg_rgbaf c)
{
    cg_rgba8 e = cg_linear_to_rgba8(c);
    unsigned char b[4] = {e.r, e.g, e.b, e.a};
    for (int i = 0; i < 4; i++)
        put_integer(o, b[i], 1);
}

static void end_item(ply_out *o)
{
    if (!o->binary)
        putc('\n', o->file);
    o->first = 1;
}

static cg_status save_ply(const cg_mesh *m, const char *path, int binary, cg_error *err)
{
    uint32_t largest = 0;
    for (size_t face = 0; face < m->face_count; face++)
        if (cg_mesh_face_size(m, face) > largest)
            largest = cg_mesh_face_size(m, face);
    int count_bytes = largest > 255 ? 4 : 1;
    int index_bytes = 4;
    safe_file o;
    cg_status s = safe_file_open(&o, path, err);
    if (s != CG_OK)
        return s;
    FILE *f = o.file;
    ply_out w = {f, binary, 1};
    fprintf(f, "ply\nformat %s 1.0\ncomment written by cg\nelement vertex %zu\n",
            binary ? "binary_little_endian" : "ascii", m->vertex_count);
    fputs("property double x\nproperty double y\nproperty double z\n", f);
    if (m->normals)
        fputs("property float nx\nproperty float ny\nproperty float nz\n", f);
    if (m->texcoords)
        fputs("property float u\nproperty float v\n", f);
    if (m->colors)
        fputs("property uchar red\nproperty uchar green\nproperty uchar blue\n"
              "property uchar alpha\n",
              f);
    fprintf(f, "element face %zu\nproperty list %s %s vertex_indices\n", m->face_count,
            count_bytes == 1 ? "uchar" : "uint", m->vertex_count > INT32_MAX ? "uint" : "int");
    if (m->face_colors)
        fputs("property uchar red\nproperty uchar green\nproperty uchar blue\n"
              "property uchar alpha\n",
              f);
    fputs("end_header\n", f);
    for (size_t v = 0; v < m->vertex_count; v++) {
        put_double(&w, m->positions[v].x);
        put_double(&w, m->positions[v].y);
        put_double(&w, m->positions[v].z);
        if (m->normals) {
            put_float(&w, m->normals[v].x);
            put_float(&w, m->normals[v].y);
            put_float(&w, m->normals[v].z);
        }
        if (m->texcoords) {
            put_float(&w, m->texcoords[v].x);
            put_float(&w, m->texcoords[v].y);
        }
        if (m->colors)
            put_color(&w, m->colors[v]);
        end_item(&w);
    }
    for (size_t face = 0; face < m->face_count; face++) {
        put_integer(&w, cg_mesh_face_size(m, face), count_bytes);
        for (uint32_t k = m->face_offsets[face]; k < m->face_offsets[face + 1]; k++)
            put_integer(&w, m->face_indices[k], index_bytes);
        if (m->face_colors)
            put_color(&w, m->face_colors[face]);
        end_item(&w);
    }
    return safe_file_close(&o, CG_OK, err);
}

cg_status cg_mesh_save(const cg_mesh *mesh, const char *path, cg_mesh_format format, cg_error *err)
{
    if (!mesh || !path)
        return cg_error_set(err, CG_EINVAL, "mesh save: no mesh or path given");
    cg_status s = cg_mesh_validate(mesh, err);
    if (s != CG_OK)
        return s;
    if (format == CG_MESH_FORMAT_AUTO)
        format = cg_mesh_format_from_path(path);
    switch (format) {
    case CG_MESH_FORMAT_OBJ: return save_obj(mesh, path, err);
    case CG_MESH_FORMAT_PLY:
    case CG_MESH_FORMAT_PLY_BINARY: return save_ply(mesh, path, 1, err);
    case CG_MESH_FORMAT_PLY_ASCII: return save_ply(mesh, path, 0, err);
    case CG_MESH_FORMAT_OFF: return off_write(mesh, path, err);
    case CG_MESH_FORMAT_STL: return stl_write(mesh, path, err);
    case CG_MESH_FORMAT_GLTF: {
        size_t n = strlen(path);
        if (n >= 5 && strcmp(path + n - 5, ".gltf") == 0)
            return cg_error_set(err, CG_EUNSUPPORTED,
                                "%s: cg writes glTF as one binary file: name it .glb", path);
        return gltf_write(mesh, path, err);
    }
    default:
        return cg_error_set(err, CG_EUNSUPPORTED,
                            "%s: cg writes OBJ, PLY, OFF, STL and glTF binary (.glb) meshes "
                            "(name the file so, or give the format)",
                            path);
    }
}
