/* Wavefront OBJ reader, with the diffuse colours (Kd) of MTL material libraries.
 *
 * One pass over the text: positions go straight into the builder and face
 * corners into its index array; texture-coordinate and normal indices, when
 * the file has any, go into two side arrays.  OBJ indexes positions,
 * texture coordinates and normals separately while cg_mesh has one index
 * per corner, so afterwards each position keeps the first (texcoord, normal)
 * pair it is used with, and every other pair used with it becomes a new
 * vertex appended after the file's positions (found again through a hash
 * table).  A file that uses each position with one pair keeps its vertex
 * numbering exactly. */
#include "internal.h"
#include "../core/array.h"

#include <stdio.h>
#include <stdlib.h>

#define OBJ_NONE UINT32_MAX

typedef struct obj_reader {
    text_cursor t;
    cg_error *err;
    mesh_builder b;
    /* texture coordinates and normals as listed in the file */
    cg_vec2 *tex;
    size_t tex_count, tex_capacity;
    cg_vec3 *nor;
    size_t nor_count, nor_capacity;
    /* per corner: 1-based texcoord / normal index, 0 for none; NULL until used */
    uint32_t *corner_tex, *corner_nor;
    size_t corner_capacity;
    /* the largest 1-based index met of each kind, and its line, for forward references */
    uint64_t max_index[3];
    size_t max_line[3];
    /* materials named by usemtl, and the material of each face */
    char **materials;
    size_t material_count, material_capacity;
    uint32_t *face_material;
    size_t face_material_capacity;
    uint32_t current_material;
    /* mtllib lines, to read once the whole file is known */
    char **libraries;
    size_t library_count, library_capacity;
    /* what the libraries say of each material (material_count), and notes */
    cg_mesh_material *mesh_materials;
    char *notes;
} obj_reader;

static cg_status obj_fail(obj_reader *r, const char *what)
{
    return text_expected(&r->t, what, r->err);
}

static cg_status out_of_memory(obj_reader *r)
{
    return cg_error_set(r->err, CG_ENOMEM, "%s:%zu: out of memory", r->t.name, r->t.line);
}

/* Reads up to max numbers to the end of the line; returns how many, or -1. */
static int read_numbers(obj_reader *r, double *values, int max, const char *what)
{
    int n = 0;
    while (!text_at_line_end(&r->t)) {
        if (n == max) {
            obj_fail(r, "the end of the line");
            return -1;
        }
        if (!parse_double(&r->t.p, r->t.end, &values[n])) {
            obj_fail(r, what);
            return -1;
        }
        n++;
    }
    return n;
}

static cg_status read_vertex(obj_reader *r)
{
    double v[6];
    int n = read_numbers(r, v, 6, "a number (x y z [w] or x y z r g b)");
    if (n < 0)
        return r->err ? r->err->status : CG_EFORMAT;
    if (n != 3 && n != 4 && n != 6)
        return cg_error_set(r->err, CG_EFORMAT,
                            "%s:%zu: expected 3, 4 or 6 numbers after 'v' (x y z [w] or x y z r g "
                            "b), got %d",
                            r->t.name, r->t.line, n);
    cg_vec3 position = cg_vec3_make(v[0], v[1], v[2]);
    if (mesh_nonfinite_axis(position) >= 0)
        return mesh_nonfinite_error(r->err, r->t.name, r->t.line, 0, NULL, position);
    size_t i;
    if (builder_push_vertex(&r->b, position, &i) != CG_OK)
        return r->b.vertex_count >= CG_MESH_MAX_VERTICES
                   ? cg_error_set(r->err, CG_ERANGE, "%s:%zu: more vertices than cg_mesh holds",
                                  r->t.name, r->t.line)
                   : out_of_memory(r);
    if (n == 6) {
        cg_rgbaf white = {1, 1, 1, 1};
        if (!r->b.colors && builder_add_arrays(&r->b, CG_MESH_COLORS, white) != CG_OK)
            return out_of_memory(r);
        cg_rgbaf c = {(float)v[3], (float)v[4], (float)v[5], 1};
        r->b.colors[i] = c;
    }
    return CG_OK;
}

static cg_status read_texcoord(obj_reader *r)
{
    double v[3] = {0, 0, 0};
    int n = read_numbers(r, v, 3, "a number (u [v [w]])");
    if (n < 0)
        return r->err ? r->err->status : CG_EFORMAT;
    if (n < 1)
        return obj_fail(r, "a texture coordinate (u [v [w]])");
    if (core_array_reserve((void **)&r->tex, &r->tex_capacity, r->tex_count + 1, sizeof *r->tex)
        != CG_OK)
        return out_of_memory(r);
    r->tex[r->tex_count++] = cg_vec2_make(v[0], v[1]);
    return CG_OK;
}

static cg_status read_normal(obj_reader *r)
{
    double v[3];
    int n = read_numbers(r, v, 3, "a number (x y z)");
    if (n < 0)
        return r->err ? r->err->status : CG_EFORMAT;
    if (n != 3)
        return obj_fail(r, "3 numbers after 'vn'");
    if (core_array_reserve((void **)&r->nor, &r->nor_capacity, r->nor_count + 1, sizeof *r->nor)
        != CG_OK)
        return out_of_memory(r);
    r->nor[r->nor_count++] = cg_vec3_make(v[0], v[1], v[2]);
    return CG_OK;
}

/* Reads one index of kind (0 position, 1 texcoord, 2 normal) at the cursor
 * and gives it 1-based and absolute. */
static cg_status read_index(obj_reader *r, int kind, size_t count, uint32_t *out)
{
    static const char *const what[3] = {"a vertex index", "a texture coordinate index",
                                        "a normal index"};
    static const char *const noun[3] = {"vertices", "texture coordinates", "normals"};
    const char *start = r->t.p;
    int64_t i;
    if (!parse_int64(&r->t.p, r->t.end, &i))
        return obj_fail(r, what[kind]);
    if (i < 0) {
        if ((uint64_t)-i > count) {
            r->t.p = start;
            return cg_error_set(r->err, CG_EFORMAT,
                                "%s:%zu: relative index %lld goes before the first of the %zu "
                                "%s defined so far",
                                r->t.name, r->t.line, (long long)i, count, noun[kind]);
        }
        i = (int64_t)count + i + 1;
    } else if (i == 0) {
        r->t.p = start;
        return obj_fail(r, "an index other than 0 (OBJ counts from 1)");
    } else if ((uint64_t)i > CG_MESH_MAX_VERTICES) {
        r->t.p = start;
        return obj_fail(r, "an index below 2^32");
    }
    if ((uint64_t)i > r->max_index[kind]) {
        r->max_index[kind] = (uint64_t)i;
        r->max_line[kind] = r->t.line;
    }
    *out = (uint32_t)i;
    return CG_OK;
}

/* Makes the per-corner texcoord/normal arrays exist and cover every corner. */
static cg_status ensure_corner_arrays(obj_reader *r)
{
    if (r->corner_capacity >= r->b.index_capacity && r->corner_tex)
        return CG_OK;
    size_t old = r->corner_tex ? r->corner_capacity : 0;
    size_t c = r->b.index_capacity;
    uint32_t *t = realloc(r->corner_tex, c * sizeof *t);
    if (!t)
        return out_of_memory(r);
    r->corner_tex = t;
    uint32_t *n = realloc(r->corner_nor, c * sizeof *n);
    if (!n)
        return out_of_memory(r);
    r->corner_nor = n;
    memset(t + old, 0, (c - old) * sizeof *t);
    memset(n + old, 0, (c - old) * sizeof *n);
    r->corner_capacity = c;
    return CG_OK;
}

static cg_status read_face(obj_reader *r)
{
    size_t corners = 0;
    while (!text_at_line_end(&r->t)) {
        uint32_t v, t = 0, n = 0;
        cg_status s = read_index(r, 0, r->b.vertex_count, &v);
        if (s != CG_OK)
            return s;
        if (r->t.p < r->t.end && *r->t.p == '/') {
            r->t.p++;
            if (r->t.p < r->t.end && *r->t.p != '/') {
                if ((s = read_index(r, 1, r->tex_count, &t)) != CG_OK)
                    return s;
            }
            if (r->t.p < r->t.end && *r->t.p == '/') {
                r->t.p++;
                if ((s = read_index(r, 2, r->nor_count, &n)) != CG_OK)
                    return s;
            }
        }
        if (r->t.p < r->t.end && !is_space(*r->t.p) && *r->t.p != '#')
            return obj_fail(r, "a blank between face corners (v, v/vt, v//vn or v/vt/vn)");
        if (builder_push_index(&r->b, v - 1) != CG_OK)
            return r->b.index_count >= CG_MESH_MAX_INDICES
                       ? cg_error_set(r->err, CG_ERANGE,
                                      "%s:%zu: more face corners than cg_mesh holds", r->t.name,
                                      r->t.line)
                       : out_of_memory(r);
        if (t || n || r->corner_tex) {
            if ((s = ensure_corner_arrays(r)) != CG_OK)
                return s;
            r->corner_tex[r->b.index_count - 1] = t;
            r->corner_nor[r->b.index_count - 1] = n;
        }
        corners++;
    }
    if (corners < 3)
        return cg_error_set(r->err, CG_EFORMAT,
                            "%s:%zu: expected a face of at least 3 vertices, got %zu", r->t.name,
                            r->t.line, corners);
    if (builder_end_face(&r->b) != CG_OK)
        return out_of_memory(r);
    if (r->face_material) {
        if (core_array_reserve((void **)&r->face_material, &r->face_material_capacity,
                               r->b.face_count, sizeof *r->face_material)
            != CG_OK)
            return out_of_memory(r);
        r->face_material[r->b.face_count - 1] = r->current_material;
    }
    return CG_OK;
}

/* The rest of the line, blanks trimmed at both ends, as a new string. */
static char *rest_of_line(obj_reader *r)
{
    text_skip_blanks(&r->t);
    const char *start = r->t.p, *stop = start;
    while (stop < r->t.end && !is_line_end(*stop))
        stop++;
    while (stop > start && is_blank(stop[-1]))
        stop--;
    size_t length = (size_t)(stop - start);
    char *copy = malloc(length + 1);
    if (copy) {
        memcpy(copy, start, length);
        copy[length] = '\0';
    }
    return copy;
}

static cg_status read_usemtl(obj_reader *r)
{
    char *name = rest_of_line(r);
    if (!name)
        return out_of_memory(r);
    size_t m = 0;
    while (m < r->material_count && strcmp(r->materials[m], name) != 0)
        m++;
    if (m == r->material_count) {
        if (core_array_reserve((void **)&r->materials, &r->material_capacity, m + 1,
                               sizeof *r->materials)
            != CG_OK) {
            free(name);
            return out_of_memory(r);
        }
        r->materials[r->material_count++] = name;
    } else {
        free(name);
    }
    if (!r->face_material) {
        size_t c = r->b.face_count + 64;
        if (!(r->face_material = malloc(c * sizeof *r->face_material)))
            return out_of_memory(r);
        r->face_material_capacity = c;
        for (size_t f = 0; f < r->b.face_count; f++)
            r->face_material[f] = OBJ_NONE;
    }
    r->current_material = (uint32_t)m;
    return CG_OK;
}

static cg_status read_mtllib(obj_reader *r)
{
    char *name = rest_of_line(r);
    if (!name)
        return out_of_memory(r);
    if (core_array_reserve((void **)&r->libraries, &r->library_capacity, r->library_count + 1,
                           sizeof *r->libraries)
        != CG_OK) {
        free(name);
        return out_of_memory(r);
    }
    r->libraries[r->library_count++] = name;
    return CG_OK;
}

/* ---- material libraries ------------------------------------------------ */

/* The library `file` (as the mtllib line names it) beside the OBJ file. */
static char *library_path(const char *directory, const char *file)
{
    size_t dl = strlen(directory), fl = strlen(file);
    char *path = malloc(dl + fl + 2);
    if (!path)
        return NULL;
    if (file[0] == '/' || dl == 0) {
        memcpy(path, file, fl + 1);
    } else {
        memcpy(path, directory, dl);
        path[dl] = '/';
        memcpy(path + dl + 1, file, fl + 1);
    }
    return path;
}

static cg_status read_library(obj_reader *r, const char *directory, const char *file,
                              unsigned char *has_kd, int *found)
{
    char *path = library_path(directory, file);
    if (!path)
        return out_of_memory(r);
    cg_status s = mtl_read_library(path, r->materials, r->material_count, r->mesh_materials, has_kd,
                                   &r->notes, r->err, found);
    free(path);
    return s;
}

/* Reads every mtllib line's libraries into the material table; a library
 * that cannot be read is a note, and its materials keep the defaults. */
static cg_status read_libraries(obj_reader *r, const char *directory, unsigned char *has_kd)
{
    cg_status s = CG_OK;
    for (size_t l = 0; s == CG_OK && l < r->library_count; l++) {
        int found = 0;
        s = read_library(r, directory, r->libraries[l], has_kd, &found);
        /* "mtllib a.mtl b.mtl": several names on one line */
        if (s == CG_OK && !found && strpbrk(r->libraries[l], " \t")) {
            int any = 0;
            char *names = r->libraries[l];
            for (char *word = names; s == CG_OK && *word;) {
                while (is_blank(*word))
                    word++;
                char *stop = word;
                while (*stop && !is_blank(*stop))
                    stop++;
                char saved = *stop;
                *stop = '\0';
                if (stop > word) {
                    s = read_library(r, directory, word, has_kd, &found);
                    any |= found;
                }
                *stop = saved;
                word = stop;
            }
            found = any;
        }
        if (s == CG_OK && !found
            && mesh_note(&r->notes,
                         "%s: material library %s not found; "
                         "its materials keep no colour",
                         r->t.name, r->libraries[l])
                   != CG_OK)
            s = out_of_memory(r);
    }
    return s;
}

/* The material table (one entry per usemtl name, defaults first), the
 * libraries read into it, and the face colours of the materials with Kd. */
static cg_status apply_materials(obj_reader *r, const char *directory)
{
    if (!r->face_material || r->material_count == 0)
        return CG_OK;
    r->mesh_materials = calloc(r->material_count, sizeof *r->mesh_materials);
    unsigned char *has_kd = calloc(r->material_count, 1);
    cg_status s = r->mesh_materials && has_kd ? CG_OK : out_of_memory(r);
    for (size_t m = 0; s == CG_OK && m < r->material_count; m++) {
        r->mesh_materials[m] = cg_mesh_material_default();
        size_t n = strlen(r->materials[m]);
        if (!(r->mesh_materials[m].name = malloc(n + 1)))
            s = out_of_memory(r);
        else
            memcpy(r->mesh_materials[m].name, r->materials[m], n + 1);
    }
    if (s == CG_OK && directory)
        s = read_libraries(r, directory, has_kd);
    int any = 0;
    for (size_t m = 0; s == CG_OK && m < r->material_count; m++)
        any |= has_kd[m];
    if (s == CG_OK && any) {
        cg_rgbaf none = {0, 0, 0, 0};
        if (builder_add_arrays(&r->b, CG_MESH_FACE_COLORS, none) != CG_OK) {
            s = out_of_memory(r);
        } else {
            for (size_t f = 0; f < r->b.face_count; f++) {
                uint32_t m = r->face_material[f];
                if (m != OBJ_NONE && has_kd[m]) {
                    cg_rgbaf color = r->mesh_materials[m].base_color;
                    color.a = 1; /* a face colour; transparency is the material's */
                    r->b.face_colors[f] = color;
                } else {
                    r->b.face_colors[f] = none;
                }
            }
        }
    }
    free(has_kd);
    return s;
}

/* Moves the material table, face materials and notes into the mesh. */
static void attach_materials(obj_reader *r, cg_mesh *mesh)
{
    mesh->notes = r->notes;
    r->notes = NULL;
    if (!r->mesh_materials)
        return;
    mesh->materials = r->mesh_materials;
    mesh->material_count = r->material_count;
    r->mesh_materials = NULL;
    /* OBJ_NONE and CG_MESH_NO_MATERIAL are both UINT32_MAX */
    mesh->face_materials = r->face_material;
    r->face_material = NULL;
}

/* ---- one index per corner ---------------------------------------------- */

typedef struct split_entry {
    uint32_t v, t, n, vertex; /* vertex == OBJ_NONE: empty */
} split_entry;

static uint64_t split_hash(uint32_t v, uint32_t t, uint32_t n)
{
    uint64_t h = (uint64_t)v * 0x9e3779b97f4a7c15u;
    h ^= ((uint64_t)t << 32 | n) * 0xc2b2ae3d27d4eb4fu;
    return h ^ (h >> 29);
}

static cg_status unify_indices(obj_reader *r)
{
    mesh_builder *b = &r->b;
    size_t positions = b->vertex_count;
    unsigned flags = (r->tex_count ? CG_MESH_TEXCOORDS : 0) | (r->nor_count ? CG_MESH_NORMALS : 0);
    int any_tex = 0, any_nor = 0;
    for (size_t k = 0; k < b->index_count; k++) {
        any_tex |= r->corner_tex[k] != 0;
        any_nor |= r->corner_nor[k] != 0;
    }
    flags &= (any_tex ? CG_MESH_TEXCOORDS : 0) | (any_nor ? CG_MESH_NORMALS : 0);
    if (!flags)
        return CG_OK;
    cg_rgbaf white = {1, 1, 1, 1};
    uint32_t *first_tex = malloc((positions ? positions : 1) * sizeof *first_tex);
    uint32_t *first_nor = malloc((positions ? positions : 1) * sizeof *first_nor);
    size_t table_size = 0, used = 0;
    split_entry *table = NULL;
    cg_status s = first_tex && first_nor ? builder_add_arrays(b, flags, white) : CG_ENOMEM;
    if (s == CG_OK) {
        for (size_t v = 0; v < positions; v++)
            first_tex[v] = first_nor[v] = OBJ_NONE;
    }
    for (size_t k = 0; s == CG_OK && k < b->index_count; k++) {
        uint32_t v = b->face_indices[k], t = r->corner_tex[k], n = r->corner_nor[k];
        if (first_tex[v] == OBJ_NONE) {
            first_tex[v] = t;
            first_nor[v] = n;
            continue;
        }
        if (first_tex[v] == t && first_nor[v] == n)
            continue;
        /* another pair with this position: find or make its vertex */
        if (2 * (used + 1) > table_size) {
            size_t grown = table_size ? 2 * table_size : 1024;
            split_entry *bigger = malloc(grown * sizeof *bigger);
            if (!bigger) {
                s = CG_ENOMEM;
                break;
            }
            for (size_t i = 0; i < grown; i++)
                bigger[i].vertex = OBJ_NONE;
            for (size_t i = 0; i < table_size; i++) {
                if (table[i].vertex == OBJ_NONE)
                    continue;
                size_t j = split_hash(table[i].v, table[i].t, table[i].n) & (grown - 1);
                while (bigger[j].vertex != OBJ_NONE)
                    j = (j + 1) & (grown - 1);
                bigger[j] = table[i];
            }
            free(table);
            table = bigger;
            table_size = grown;
        }
        size_t j = split_hash(v, t, n) & (table_size - 1);
        while (table[j].vertex != OBJ_NONE
               && !(table[j].v == v && table[j].t == t && table[j].n == n))
            j = (j + 1) & (table_size - 1);
        if (table[j].vertex == OBJ_NONE) {
            size_t added;
            s = builder_push_vertex(b, b->positions[v], &added);
            if (s != CG_OK)
                break;
            if (b->colors)
                b->colors[added] = b->colors[v];
            if (b->texcoords && t)
                b->texcoords[added] = r->tex[t - 1];
            if (b->normals && n)
                b->normals[added] = r->nor[n - 1];
            split_entry e = {v, t, n, (uint32_t)added};
            table[j] = e;
            used++;
        }
        b->face_indices[k] = table[j].vertex;
    }
    for (size_t v = 0; s == CG_OK && v < positions; v++) {
        if (first_tex[v] == OBJ_NONE) {
            /* a position no face uses: when the file lists one texture coordinate
             * (normal) per position, the one of the same number is its own */
            first_tex[v] = r->tex_count == positions ? (uint32_t)v + 1 : 0;
            first_nor[v] = r->nor_count == positions ? (uint32_t)v + 1 : 0;
        }
        if (b->texcoords && first_tex[v])
            b->texcoords[v] = r->tex[first_tex[v] - 1];
        if (b->normals && first_nor[v])
            b->normals[v] = r->nor[first_nor[v] - 1];
    }
    free(first_tex);
    free(first_nor);
    free(table);
    if (s != CG_OK)
        return cg_error_set(r->err, s, "%s: %s", r->t.name,
                            s == CG_ERANGE ? "more vertices than cg_mesh holds" : "out of memory");
    return CG_OK;
}

/* ---- the reader ---------------------------------------------------------- */

static int keyword_is(const char *word, size_t length, const char *keyword)
{
    return strlen(keyword) == length && memcmp(word, keyword, length) == 0;
}

static cg_status read_lines(obj_reader *r)
{
    text_cursor *t = &r->t;
    if (t->end - t->p >= 3 && memcmp(t->p, "\xef\xbb\xbf", 3) == 0)
        t->p += 3; /* UTF-8 byte order mark */
    while (t->p < t->end) {
        text_skip_blanks(t);
        const char *word = t->p;
        while (t->p < t->end && !is_space(*t->p))
            t->p++;
        size_t length = (size_t)(t->p - word);
        cg_status s = CG_OK;
        if (length == 1 && word[0] == 'v') {
            s = read_vertex(r);
        } else if (length == 1 && word[0] == 'f') {
            s = read_face(r);
        } else if (length == 2 && word[0] == 'v' && word[1] == 'n') {
            s = read_normal(r);
        } else if (length == 2 && word[0] == 'v' && word[1] == 't') {
            s = read_texcoord(r);
        } else if (keyword_is(word, length, "usemtl")) {
            s = read_usemtl(r);
        } else if (keyword_is(word, length, "mtllib")) {
            s = read_mtllib(r);
        } else if (length > 0 && word[0] != '#') {
            /* g, o, s, l, p, vp, curves and surfaces, unknown statements: skipped
             * (a line ending in a backslash continues on the next one) */
            while (t->p < t->end && !is_line_end(*t->p))
                t->p++;
            while (t->p > word && t->p < t->end && t->p[-1] == '\\') {
                text_next_line(t);
                while (t->p < t->end && !is_line_end(*t->p))
                    t->p++;
            }
        }
        if (s != CG_OK)
            return s;
        text_next_line(t);
    }
    /* positive indices may refer forward; check them against the final counts */
    size_t counts[3] = {r->b.vertex_count, r->tex_count, r->nor_count};
    static const char *const noun[3] = {"vertex", "texture coordinate", "normal"};
    static const char *const plural[3] = {"vertices", "texture coordinates", "normals"};
    for (int k = 0; k < 3; k++)
        if (r->max_index[k] > counts[k])
            return cg_error_set(r->err, CG_EFORMAT,
                                "%s:%zu: face refers to %s %llu, but the file has %zu %s", t->name,
                                r->max_line[k], noun[k], (unsigned long long)r->max_index[k],
                                counts[k], plural[k]);
    return CG_OK;
}

cg_status obj_read(const char *bytes, size_t size, const char *name, const char *directory,
                   cg_mesh **out, cg_error *err)
{
    obj_reader r;
    memset(&r, 0, sizeof r);
    r.t = text_cursor_start(bytes, size, name);
    r.err = err;
    r.current_material = OBJ_NONE;
    builder_init(&r.b);
    /* a guess from the file size, bounded by it: about 30 bytes a vertex */
    cg_status s = builder_reserve_vertices(&r.b, size / 64 + 16) == CG_OK ? CG_OK : CG_ENOMEM;
    if (s != CG_OK)
        s = cg_error_set(err, s, "%s: out of memory", name);
    if (s == CG_OK)
        s = read_lines(&r);
    if (s == CG_OK && r.b.vertex_count == 0)
        s = cg_error_set(err, CG_EFORMAT, "%s:%zu: expected vertices ('v x y z'), found none", name,
                         r.t.line);
    if (s == CG_OK && r.corner_tex)
        s = unify_indices(&r);
    if (s == CG_OK)
        s = apply_materials(&r, directory);
    if (s == CG_OK && (s = builder_finish(&r.b, out)) != CG_OK)
        s = cg_error_set(err, s, "%s: out of memory", name);
    if (s == CG_OK)
        attach_materials(&r, *out);
    for (size_t m = 0; r.mesh_materials && m < r.material_count; m++)
        cg_mesh_material_clear(&r.mesh_materials[m]);
    free(r.mesh_materials);
    free(r.notes);
    builder_free(&r.b);
    free(r.tex);
    free(r.nor);
    free(r.corner_tex);
    free(r.corner_nor);
    for (size_t m = 0; m < r.material_count; m++)
        free(r.materials[m]);
    free(r.materials);
    free(r.face_material);
    for (size_t l = 0; l < r.library_count; l++)
        free(r.libraries[l]);
    free(r.libraries);
    return s;
}
