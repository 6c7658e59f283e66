/* OFF reader (Geomview Object File Format): "OFF" with the optional
 * prefixes ST (texture coordinates), C (vertex colours) and N (normals);
 * vertex lines hold x y z [nx ny nz] [r g b [a]] [s t]; face lines hold
 * n i1 ... in, optionally followed by a colour (r g b [a], 0..1 or 0..255,
 * or one colour-map index, which is ignored).  4OFF, nOFF and binary OFF
 * are not read (CG_EUNSUPPORTED).  '#' starts a comment anywhere. */
#include "internal.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct off_reader {
    text_cursor t;
    cg_error *err;
    mesh_builder b;
    int normals, colors, texcoords;
} off_reader;

static cg_status off_fail(off_reader *r, const char *what)
{
    return text_expected(&r->t, what, r->err);
}

static cg_status read_keyword(off_reader *r)
{
    text_cursor *t = &r->t;
    text_skip_space_and_comments(t);
    const char *word = t->p;
    if (t->end - t->p >= 2 && memcmp(t->p, "ST", 2) == 0) {
        r->texcoords = 1;
        t->p += 2;
    }
    int unsupported = 0;
    while (t->p < t->end && (*t->p == 'C' || *t->p == 'N' || *t->p == '4' || *t->p == 'n')) {
        r->colors |= *t->p == 'C';
        r->normals |= *t->p == 'N';
        unsupported |= *t->p == '4' || *t->p == 'n';
        t->p++;
    }
    if (t->end - t->p < 3 || memcmp(t->p, "OFF", 3) != 0) {
        t->p = word;
        return off_fail(r, "'OFF' (or COFF, NOFF, STOFF ...) as the first word");
    }
    t->p += 3;
    if (unsupported)
        return cg_error_set(r->err, CG_EUNSUPPORTED,
                            "%s:%zu: 4OFF and nOFF (4 or n dimensions) are not read", t->name,
                            t->line);
    text_skip_blanks(t);
    if (t->end - t->p >= 6 && memcmp(t->p, "BINARY", 6) == 0)
        return cg_error_set(r->err, CG_EUNSUPPORTED, "%s:%zu: binary OFF is not read", t->name,
                            t->line);
    return CG_OK;
}

/* Reads a count (whole number >= 0) after blanks, line ends and comments. */
static cg_status read_count(off_reader *r, int64_t *out, const char *what)
{
    text_skip_space_and_comments(&r->t);
    if (r->t.p < r->t.end && parse_int64(&r->t.p, r->t.end, out) && *out >= 0)
        return CG_OK;
    return off_fail(r, what);
}

/* Numbers up to the end of the line; returns how many or -1. */
static int line_numbers(off_reader *r, double *values, int max)
{
    int n = 0;
    while (!text_at_line_end(&r->t)) {
        if (n == max || !parse_double(&r->t.p, r->t.end, &values[n]))
            return -1;
        n++;
    }
    return n;
}

static cg_rgbaf color_from(const double *c, int n)
{
    int is_float = 1;
    for (int i = 0; i < n; i++)
        if (c[i] > 1)
            is_float = 0;
    cg_rgbaf color = {mesh_color_component(c[0], is_float, 0),
                      mesh_color_component(c[1], is_float, 0),
                      mesh_color_component(c[2], is_float, 0),
                      n == 4 ? mesh_color_component(c[3], is_float, 1) : 1.0f};
    return color;
}

static cg_status read_vertices(off_reader *r, int64_t count)
{
    int base = 3 + 3 * r->normals + 2 * r->texcoords;
    char expected[80];
    snprintf(expected, sizeof expected, "%d%s numbers on a vertex line", base + 3 * r->colors,
             r->colors ? " or one more" : "");
    for (int64_t i = 0; i < count; i++) {
        text_skip_space_and_comments(&r->t);
        if (r->t.p >= r->t.end)
            return cg_error_set(r->err, CG_EFORMAT,
                                "%s:%zu: expected %lld vertices, the file ends after %lld",
                                r->t.name, r->t.line, (long long)count, (long long)i);
        double v[12];
        const char *start = r->t.p;
        int n = line_numbers(r, v, 12);
        int colour = n - base;
        if (n < 0 || (r->colors ? colour != 3 && colour != 4 : colour != 0)) {
            r->t.p = n < 0 ? r->t.p : start;
            return off_fail(r, expected);
        }
        cg_vec3 position = cg_vec3_make(v[0], v[1], v[2]);
        if (mesh_nonfinite_axis(position) >= 0)
            return mesh_nonfinite_error(r->err, r->t.name, r->t.line, 0, NULL, position);
        size_t k;
        if (builder_push_vertex(&r->b, position, &k) != CG_OK)
            return cg_error_set(r->err, CG_ENOMEM, "%s:%zu: out of memory", r->t.name, r->t.line);
        int at = 3;
        if (r->normals) {
            r->b.normals[k] = cg_vec3_make(v[3], v[4], v[5]);
            at += 3;
        }
        if (r->colors) {
            r->b.colors[k] = color_from(v + at, colour);
            at += colour;
        }
        if (r->texcoords)
            r->b.texcoords[k] = cg_vec2_make(v[at], v[at + 1]);
    }
    return CG_OK;
}

static cg_status read_faces(off_reader *r, int64_t count)
{
    for (int64_t i = 0; i < count; i++) {
        text_skip_space_and_comments(&r->t);
        if (r->t.p >= r->t.end)
            return cg_error_set(r->err, CG_EFORMAT,
                                "%s:%zu: expected %lld faces, the file ends after %lld", r->t.name,
                                r->t.line, (long long)count, (long long)i);
        int64_t n;
        if (!parse_int64(&r->t.p, r->t.end, &n) || n < 3)
            return off_fail(r, "a face's vertex count (3 or more)");
        for (int64_t j = 0; j < n; j++) {
            int64_t v;
            text_skip_blanks(&r->t);
            if (!parse_int64(&r->t.p, r->t.end, &v))
                return off_fail(r, "a vertex index");
            if (v < 0 || (uint64_t)v >= r->b.vertex_count)
                return cg_error_set(r->err, CG_EFORMAT,
                                    "%s:%zu: face %lld refers to vertex %lld, but there are %zu "
                                    "vertices (numbered from 0)",
                                    r->t.name, r->t.line, (long long)i, (long long)v,
                                    r->b.vertex_count);
            if (builder_push_index(&r->b, (uint32_t)v) != CG_OK)
                return cg_error_set(r->err, CG_ERANGE, "%s:%zu: too many face corners for cg_mesh",
                                    r->t.name, r->t.line);
        }
        double c[4];
        int k = line_numbers(r, c, 4);
        if (k < 0 || k == 2)
            return off_fail(r, "the end of the face, or a colour (r g b [a]) after it");
        if (builder_reserve_faces(&r->b, 1) != CG_OK || builder_end_face(&r->b) != CG_OK)
            return cg_error_set(r->err, CG_ENOMEM, "%s:%zu: out of memory", r->t.name, r->t.line);
        if (k >= 3) {
            cg_rgbaf white = {1, 1, 1, 1};
            if (!r->b.face_colors && builder_add_arrays(&r->b, CG_MESH_FACE_COLORS, white) != CG_OK)
                return cg_error_set(r->err, CG_ENOMEM, "%s: out of memory", r->t.name);
            r->b.face_colors[r->b.face_count - 1] = color_from(c, k);
        } else if (r->b.face_colors) {
            cg_rgbaf white = {1, 1, 1, 1};
            r->b.face_colors[r->b.face_count - 1] = white;
        }
    }
    return CG_OK;
}

cg_status off_read(const char *bytes, size_t size, const char *name, cg_mesh **out, cg_error *err)
{
    off_reader r;
    memset(&r, 0, sizeof r);
    r.t = text_cursor_start(bytes, size, name);
    r.err = err;
    builder_init(&r.b);
    int64_t nv = 0, nf = 0, ne = 0;
    cg_status s = read_keyword(&r);
    if (s == CG_OK)
        s = read_count(&r, &nv, "the vertex count");
    if (s == CG_OK)
        s = read_count(&r, &nf, "the face count");
    if (s == CG_OK && !text_at_line_end(&r.t))
        s = read_count(&r, &ne, "the edge count");
    if (s == CG_OK && !text_at_line_end(&r.t))
        s = off_fail(&r, "the end of the line after the counts");
    if (s == CG_OK) {
        cg_rgbaf white = {1, 1, 1, 1};
        unsigned flags = (r.normals ? CG_MESH_NORMALS : 0) | (r.colors ? CG_MESH_COLORS : 0)
                         | (r.texcoords ? CG_MESH_TEXCOORDS : 0);
        /* reserve only what the rest of the file can hold: 6 bytes a vertex, 8 a face */
        size_t left = (size_t)(r.t.end - r.t.p);
        size_t vertices = (uint64_t)nv < left / 6 ? (size_t)nv : left / 6;
        size_t faces = (uint64_t)nf < left / 8 ? (size_t)nf : left / 8;
        if (builder_add_arrays(&r.b, flags, white) != CG_OK
            || builder_reserve_vertices(&r.b, vertices) != CG_OK
            || builder_reserve_faces(&r.b, faces) != CG_OK
            || builder_reserve_indices(&r.b, faces * 3) != CG_OK)
            s = cg_error_set(err, CG_ENOMEM, "%s: out of memory", name);
    }
    if (s == CG_OK && (uint64_t)nv > CG_MESH_MAX_VERTICES)
        s = cg_error_set(err, CG_ERANGE, "%s: %lld vertices is over cg_mesh's limit", name,
                         (long long)nv);
    if (s == CG_OK)
        s = read_vertices(&r, nv);
    if (s == CG_OK)
        s = read_faces(&r, nf);
    if (s == CG_OK) {
        text_skip_space_and_comments(&r.t);
        if (r.t.p < r.t.end)
            s = off_fail(&r, "the end of the file after the last face");
    }
    if (s == CG_OK && (s = builder_finish(&r.b, out)) != CG_OK)
        s = cg_error_set(err, s, "%s: out of memory", name);
    builder_free(&r.b);
    return s;
}
