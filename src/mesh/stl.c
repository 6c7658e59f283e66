/* STL reader, ASCII and binary.
 *
 * STL lists every triangle with its own three corners; the reader merges
 * corners with bit-identical coordinates (-0 and +0 taken as equal) through
 * a hash table so that the mesh is indexed and neighbouring triangles share
 * vertices.  Facet normals and the binary attribute word are not kept.
 *
 * Binary or ASCII: a binary file is 84 + 50 n bytes where n is the 32-bit
 * count at byte 80; that test comes first, because binary files may begin
 * with "solid" too.  Otherwise a file starting with "solid" is ASCII, and any
 * other is binary with a wrong size (an error saying so). */
#include "internal.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct vertex_table {
    uint32_t *slots; /* vertex index + 1, 0 for empty */
    size_t size;     /* a power of two */
} vertex_table;

static uint64_t position_hash(cg_vec3 p)
{
    uint64_t a, b, c;
    memcpy(&a, &p.x, 8);
    memcpy(&b, &p.y, 8);
    memcpy(&c, &p.z, 8);
    uint64_t h = a * 0x9e3779b97f4a7c15u;
    h = (h ^ (h >> 31) ^ b) * 0xbf58476d1ce4e5b9u;
    h = (h ^ (h >> 29) ^ c) * 0x94d049bb133111ebu;
    return h ^ (h >> 32);
}

static int same_bits(cg_vec3 a, cg_vec3 b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* The index of position p, adding a vertex when it is new. */
static cg_status merge_vertex(mesh_builder *b, vertex_table *table, cg_vec3 p, uint32_t *index)
{
    p.x += 0.0; /* -0 becomes +0 */
    p.y += 0.0;
    p.z += 0.0;
    if (2 * (b->vertex_count + 1) > table->size) {
        size_t size = table->size ? table->size * 2 : 4096;
        uint32_t *slots = calloc(size, sizeof *slots);
        if (!slots)
            return CG_ENOMEM;
        for (size_t v = 0; v < b->vertex_count; v++) {
            size_t j = position_hash(b->positions[v]) & (size - 1);
            while (slots[j])
                j = (j + 1) & (size - 1);
            slots[j] = (uint32_t)v + 1;
        }
        free(table->slots);
        table->slots = slots;
        table->size = size;
    }
    size_t j = position_hash(p) & (table->size - 1);
    while (table->slots[j]) {
        if (same_bits(b->positions[table->slots[j] - 1], p)) {
            *index = table->slots[j] - 1;
            return CG_OK;
        }
        j = (j + 1) & (table->size - 1);
    }
    size_t v;
    cg_status s = builder_push_vertex(b, p, &v);
    if (s != CG_OK)
        return s;
    table->slots[j] = (uint32_t)v + 1;
    *index = (uint32_t)v;
    return CG_OK;
}

static float load_float(const unsigned char *p)
{
    uint32_t bits = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16
                    | (uint32_t)p[3] << 24;
    float f;
    memcpy(&f, &bits, 4);
    return f;
}

static cg_status read_binary(const unsigned char *bytes, size_t size, const char *name,
                             mesh_builder *b, vertex_table *table, cg_error *err)
{
    if (size < 84)
        return cg_error_set(err, CG_EFORMAT,
                            "%s: byte %zu: expected an 84-byte binary STL header (or 'solid' "
                            "for ASCII STL), the file ends first",
                            name, size);
    uint64_t n = (uint64_t)bytes[80] | (uint64_t)bytes[81] << 8 | (uint64_t)bytes[82] << 16
                 | (uint64_t)bytes[83] << 24;
    if (n * 50 + 84 != size)
        return cg_error_set(err, CG_EFORMAT,
                            "%s: byte 80: the header says %llu triangles (%llu bytes) but the "
                            "file has %zu bytes",
                            name, (unsigned long long)n, (unsigned long long)(n * 50 + 84), size);
    if (builder_reserve_faces(b, (size_t)n) != CG_OK
        || builder_reserve_indices(b, (size_t)n * 3) != CG_OK
        || builder_reserve_vertices(b, (size_t)n / 2 + 3) != CG_OK)
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", name);
    for (size_t t = 0; t < n; t++) {
        const unsigned char *p = bytes + 84 + 50 * t + 12;
        for (int k = 0; k < 3; k++, p += 12) {
            uint32_t v;
            cg_vec3 q = cg_vec3_make(load_float(p), load_float(p + 4), load_float(p + 8));
            if (mesh_nonfinite_axis(q) >= 0) {
                char item[48];
                snprintf(item, sizeof item, "triangle %zu, corner %d", t, k);
                return mesh_nonfinite_error(err, name, 0, (size_t)(p - bytes), item, q);
            }
            if (merge_vertex(b, table, q, &v) != CG_OK)
                return cg_error_set(err, CG_ENOMEM, "%s: out of memory", name);
            b->face_indices[b->index_count++] = v;
        }
        builder_end_face(b);
    }
    return CG_OK;
}

/* Matches the word `keyword` at the cursor (after blanks and line ends). */
static int expect_word(text_cursor *t, const char *keyword)
{
    while (t->p < t->end && is_space(*t->p)) {
        if (is_line_end(*t->p))
            text_next_line(t);
        else
            t->p++;
    }
    size_t n = strlen(keyword);
    if ((size_t)(t->end - t->p) < n || memcmp(t->p, keyword, n) != 0
        || (t->p + n < t->end && !is_space(t->p[n])))
        return 0;
    t->p += n;
    return 1;
}

static void skip_rest_of_line(text_cursor *t)
{
    while (t->p < t->end && !is_line_end(*t->p))
        t->p++;
}

static cg_status read_ascii(const char *bytes, size_t size, const char *name, mesh_builder *b,
                            vertex_table *table, cg_error *err)
{
    text_cursor t = {bytes, bytes + size, name, 1};
    int solids = 0;
    for (;;) {
        if (!expect_word(&t, "solid")) {
            if (solids && t.p >= t.end)
                break;
            return text_expected(&t, solids ? "'solid' or the end of the file" : "'solid'", err);
        }
        solids++;
        skip_rest_of_line(&t); /* the solid's name */
        for (;;) {
            if (expect_word(&t, "endsolid")) {
                skip_rest_of_line(&t);
                break;
            }
            if (!expect_word(&t, "facet"))
                return text_expected(&t, "'facet' or 'endsolid'", err);
            if (!expect_word(&t, "normal"))
                return text_expected(&t, "'normal' after 'facet'", err);
            double ignored;
            for (int k = 0; k < 3; k++) {
                cg_status s = text_double(&t, &ignored, "a facet normal component", err);
                if (s != CG_OK)
                    return s;
            }
            if (!expect_word(&t, "outer") || !expect_word(&t, "loop"))
                return text_expected(&t, "'outer loop'", err);
            size_t corners = 0;
            while (expect_word(&t, "vertex")) {
                double c[3];
                for (int k = 0; k < 3; k++) {
                    cg_status s = text_double(&t, &c[k], "a vertex coordinate", err);
                    if (s != CG_OK)
                        return s;
                }
                cg_vec3 position = cg_vec3_make(c[0], c[1], c[2]);
                if (mesh_nonfinite_axis(position) >= 0)
                    return mesh_nonfinite_error(err, name, t.line, 0, NULL, position);
                uint32_t v;
                cg_status s = merge_vertex(b, table, position, &v);
                if (s == CG_OK)
                    s = builder_push_index(b, v);
                if (s != CG_OK)
                    return cg_error_set(err, s, "%s:%zu: %s", name, t.line,
                                        s == CG_ENOMEM ? "out of memory"
                                                       : "more vertices than cg_mesh holds");
                corners++;
            }
            if (corners < 3)
                return text_expected(
                    &t, corners ? "another 'vertex' (a facet has 3 or more)" : "'vertex'", err);
            if (!expect_word(&t, "endloop"))
                return text_expected(&t, "'vertex' or 'endloop'", err);
            if (!expect_word(&t, "endfacet"))
                return text_expected(&t, "'endfacet'", err);
            if (builder_end_face(b) != CG_OK)
                return cg_error_set(err, CG_ENOMEM, "%s:%zu: out of memory", name, t.line);
        }
    }
    return CG_OK;
}

cg_status stl_read(const unsigned char *bytes, size_t size, const char *name, cg_mesh **out,
                   cg_error *err)
{
    mesh_builder b;
    builder_init(&b);
    vertex_table table = {NULL, 0};
    int binary = 1;
    if (size >= 84) {
        uint64_t n = (uint64_t)bytes[80] | (uint64_t)bytes[81] << 8 | (uint64_t)bytes[82] << 16
                     | (uint64_t)bytes[83] << 24;
        binary = n * 50 + 84 == size;
    }
    if (!binary || size < 84) {
        size_t i = 0;
        while (i < size && is_space((char)bytes[i]))
            i++;
        binary = !(size - i >= 5 && memcmp(bytes + i, "solid", 5) == 0);
    }
    cg_status s = binary ? read_binary(bytes, size, name, &b, &table, err)
                         : read_ascii((const char *)bytes, size, name, &b, &table, err);
    if (s == CG_OK && (s = builder_finish(&b, out)) != CG_OK)
        s = cg_error_set(err, s, "%s: out of memory", name);
    free(table.slots);
    builder_free(&b);
    return s;
}
