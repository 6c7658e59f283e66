/* Mesh writers for OFF and binary STL, through a temporary file renamed
 * into place (src/core/safe_file.c).
 *
 * OFF keeps what its prefixes carry: "[ST][C][N]OFF", vertex lines
 * x y z [nx ny nz] [r g b a] [s t], face lines n i1 .. in [r g b a]; colours
 * are written sRGB-encoded in 0..1, as the reader takes them.  STL keeps
 * triangles only: each face is triangulated (cg_mesh_triangulate), and each
 * triangle gets the unit normal of its corners (zero when degenerate). */
#include "internal.h"
#include "../core/safe_file.h"

#include "cg/color.h"

#include <stdio.h>
#include <stdlib.h>

static void put_value(FILE *f, double v)
{
    char buffer[32];
    snprintf(buffer, sizeof buffer, "%.15g", v);
    if (strtod(buffer, NULL) != v)
        snprintf(buffer, sizeof buffer, "%.17g", v);
    fprintf(f, " %s", buffer);
}

static void put_color(FILE *f, cg_rgbaf c)
{
    put_value(f, cg_linear_to_srgb(c.r < 0 ? 0 : c.r > 1 ? 1 : c.r));
    put_value(f, cg_linear_to_srgb(c.g < 0 ? 0 : c.g > 1 ? 1 : c.g));
    put_value(f, cg_linear_to_srgb(c.b < 0 ? 0 : c.b > 1 ? 1 : c.b));
    put_value(f, c.a < 0 ? 0 : c.a > 1 ? 1 : c.a);
}

cg_status off_write(const cg_mesh *m, const char *path, cg_error *err)
{
    safe_file o;
    cg_status s = safe_file_open(&o, path, err);
    if (s != CG_OK)
        return s;
    FILE *f = o.file;
    fprintf(f, "%s%s%sOFF\n# written by cg\n%zu %zu 0\n", m->texcoords ? "ST" : "",
            m->colors ? "C" : "", m->normals ? "N" : "", m->vertex_count, m->face_count);
    for (size_t v = 0; v < m->vertex_count; v++) {
        const cg_vec3 *p = &m->positions[v];
        put_value(f, p->x);
        put_value(f, p->y);
        put_value(f, p->z);
        if (m->normals) {
            put_value(f, m->normals[v].x);
            put_value(f, m->normals[v].y);
            put_value(f, m->normals[v].z);
        }
        if (m->colors)
            put_color(f, m->colors[v]);
        if (m->texcoords) {
            put_value(f, m->texcoords[v].x);
            put_value(f, m->texcoords[v].y);
        }
        putc('\n', f);
    }
    for (size_t face = 0; face < m->face_count; face++) {
        fprintf(f, "%u", cg_mesh_face_size(m, face));
        for (uint32_t k = m->face_offsets[face]; k < m->face_offsets[face + 1]; k++)
            fprintf(f, " %u", m->face_indices[k]);
        if (m->face_colors && m->face_colors[face].a > 0)
            put_color(f, m->face_colors[face]);
        putc('\n', f);
    }
    return safe_file_close(&o, CG_OK, err);
}

static void put_u32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)v, p[1] = (unsigned char)(v >> 8), p[2] = (unsigned char)(v >> 16),
    p[3] = (unsigned char)(v >> 24);
}

static void put_f32(unsigned char *p, double v)
{
    float x = (float)v;
    uint32_t bits;
    memcpy(&bits, &x, sizeof bits);
    put_u32(p, bits);
}

cg_status mesh_write_triangles(const cg_mesh *m, const char *path, cg_error *err,
                               uint32_t (**out)[3])
{
    size_t n = cg_mesh_triangle_count(m);
    uint32_t(*triangles)[3] = malloc((n ? n : 1) * sizeof *triangles);
    *out = NULL;
    if (!triangles)
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    cg_status s = cg_mesh_triangulate(m, triangles);
    if (s != CG_OK) {
        free(triangles);
        return cg_error_set(err, s, "%s: cannot triangulate the mesh", path);
    }
    *out = triangles;
    return CG_OK;
}

cg_status stl_write(const cg_mesh *m, const char *path, cg_error *err)
{
    size_t n = cg_mesh_triangle_count(m);
    if (n > UINT32_MAX)
        return cg_error_set(err, CG_ERANGE, "%s: %zu triangles, more than STL counts", path, n);
    uint32_t(*triangles)[3];
    cg_status s = mesh_write_triangles(m, path, err, &triangles);
    if (s != CG_OK)
        return s;
    safe_file o;
    if ((s = safe_file_open(&o, path, err)) != CG_OK) {
        free(triangles);
        return s;
    }
    unsigned char header[84] = "binary STL written by cg";
    put_u32(header + 80, (uint32_t)n);
    fwrite(header, 1, sizeof header, o.file);
    for (size_t t = 0; t < n; t++) {
        cg_vec3 p[3];
        for (int k = 0; k < 3; k++)
            p[k] = m->positions[m->face_indices[triangles[t][k]]];
        cg_vec3 a = cg_vec3_make(p[1].x - p[0].x, p[1].y - p[0].y, p[1].z - p[0].z);
        cg_vec3 b = cg_vec3_make(p[2].x - p[0].x, p[2].y - p[0].y, p[2].z - p[0].z);
        cg_vec3 normal = cg_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                                      a.x * b.y - a.y * b.x);
        double length = sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
        if (length > 0)
            normal = cg_vec3_make(normal.x / length, normal.y / length, normal.z / length);
        unsigned char record[50] = {0};
        put_f32(record, normal.x), put_f32(record + 4, normal.y), put_f32(record + 8, normal.z);
        for (int k = 0; k < 3; k++) {
            put_f32(record + 12 + 12 * k, p[k].x);
            put_f32(record + 16 + 12 * k, p[k].y);
            put_f32(record + 20 + 12 * k, p[k].z);
        }
        fwrite(record, 1, sizeof record, o.file);
    }
    free(triangles);
    return safe_file_close(&o, CG_OK, err);
}
