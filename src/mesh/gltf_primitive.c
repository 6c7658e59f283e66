/* glTF mesh primitives to cg_mesh triangles, in world space.
 *
 * Each use of a mesh by a node (an instance) appends the vertices of every
 * triangle primitive (mode 4, 5 or 6) as its accessors hold them, moved by
 * the node's world matrix, and its triangles with the indices offset:
 *
 *   TRIANGLES       v0 v1 v2 | v3 v4 v5 | ...      triangle i: 3i, 3i+1, 3i+2
 *   TRIANGLE_STRIP  v0 v1 v2 v3 v4 ...             triangle i: i, i+1+i%2, i+2-i%2
 *   TRIANGLE_FAN    v0 v1 v2 v3 ...                triangle i: i+1, i+2, 0
 *
 * A world matrix with a negative determinant mirrors the mesh, so its
 * triangles are reversed to stay counter-clockwise seen from outside.
 * Normals move by the inverse transpose.  Texture coordinates are turned
 * from glTF's (origin top-left) to cg's (origin bottom-left, as OBJ):
 * v' = 1 - v.  Points and lines are counted and left out. */
#include "gltf_internal.h"

#include <stdio.h>
#include <stdlib.h>

enum {
    MODE_POINTS = 0,
    MODE_LINES = 1,
    MODE_LINE_LOOP = 2,
    MODE_LINE_STRIP = 3,
    MODE_TRIANGLES = 4,
    MODE_TRIANGLE_STRIP = 5,
    MODE_TRIANGLE_FAN = 6
};

/* A primitive's checked description. */
typedef struct primitive {
    int mode;
    gltf_accessor position, normal, texcoord, color;
    int has_position, has_normal, has_texcoord, has_color;
    int has_indices;
    gltf_accessor indices;
    size_t material; /* SIZE_MAX: none */
    size_t triangles;
} primitive;

static size_t triangles_of(int mode, size_t n)
{
    if (mode == MODE_TRIANGLES)
        return n / 3;
    if (mode == MODE_TRIANGLE_STRIP || mode == MODE_TRIANGLE_FAN)
        return n >= 3 ? n - 2 : 0;
    return 0;
}

/* Reads attribute `key` when present and checks its type. */
static cg_status attribute(gltf_document *doc, const cJSON *attributes, const char *path,
                           const char *key, int float_only, const char *types, size_t count,
                           gltf_accessor *out, int *present)
{
    size_t index;
    cg_status s = gltf_get_index(doc, attributes, path, key, 0, &doc->accessors, "accessors",
                                 &index);
    *present = 0;
    if (s != CG_OK || index == SIZE_MAX)
        return s;
    if ((s = gltf_accessor_describe(doc, index, out)) != CG_OK)
        return s;
    int ok_type = strstr(types, out->type) != NULL;
    int small_unsigned = out->component_type == GLTF_UNSIGNED_BYTE
                         || out->component_type == GLTF_UNSIGNED_SHORT;
    int small_integer = small_unsigned || out->component_type == GLTF_BYTE
                        || out->component_type == GLTF_SHORT;
    int ok_component = out->component_type == GLTF_FLOAT
                       || (!float_only && out->normalized && small_unsigned)
                       /* KHR_mesh_quantization: integer positions, normals and texcoords */
                       || (doc->quantized && strcmp(key, "COLOR_0") != 0 && small_integer
                           && (out->normalized || strcmp(key, "NORMAL") != 0));
    if (!ok_type || !ok_component)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s.%s: expected an accessor of %s %s, got accessors[%zu]: %s of "
                            "component type %d%s",
                            doc->name, path, key, types,
                            float_only ? "floats" : "floats or normalized unsigned bytes/shorts",
                            index, out->type, out->component_type,
                            out->normalized ? " (normalized)" : "");
    if (count != SIZE_MAX && out->count != count)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s.%s: expected %zu elements like POSITION, got accessors[%zu] "
                            "with %zu",
                            doc->name, path, key, count, index, out->count);
    *present = 1;
    return CG_OK;
}

/* Checks an attribute's name (the specification's semantics, or an
 * application's starting with '_') and notes which numbered sets appear. */
static cg_status check_semantic(gltf_document *doc, const char *path, const char *name,
                                unsigned long long sets[4])
{
    static const char *const families[4] = {"TEXCOORD_", "COLOR_", "JOINTS_", "WEIGHTS_"};
    if (name[0] == '_' || strcmp(name, "POSITION") == 0 || strcmp(name, "NORMAL") == 0
        || strcmp(name, "TANGENT") == 0)
        return CG_OK;
    for (int k = 0; k < 4; k++) {
        size_t n = strlen(families[k]);
        if (strncmp(name, families[k], n) != 0)
            continue;
        const char *digits = name + n;
        size_t length = strlen(digits);
        int ok = length >= 1 && length <= 2 && (length == 1 || digits[0] != '0');
        for (size_t i = 0; i < length; i++)
            ok &= digits[i] >= '0' && digits[i] <= '9';
        if (ok && atoi(digits) < 64) {
            sets[k] |= 1ULL << atoi(digits);
            return CG_OK;
        }
    }
    return cg_error_set(doc->err, CG_EFORMAT,
                        "%s: %s.%.40s: expected POSITION, NORMAL, TANGENT, TEXCOORD_n, COLOR_n, "
                        "JOINTS_n, WEIGHTS_n or a name starting with '_'",
                        doc->name, path, name);
}

static cg_status describe_primitive(gltf_document *doc, const cJSON *item, const char *path,
                                    primitive *p)
{
    memset(p, 0, sizeof *p);
    if (!cJSON_IsObject(item))
        return gltf_fail(doc, path, NULL, "an object", item);
    int64_t mode;
    size_t indices, material;
    const cJSON *attributes;
    cg_status s = gltf_get_integer(doc, item, path, "mode", 0, MODE_TRIANGLES, 0, 6, &mode);
    if (s == CG_OK)
        s = gltf_get_object(doc, item, path, "attributes", 1, &attributes);
    if (s == CG_OK)
        s = gltf_get_index(doc, item, path, "indices", 0, &doc->accessors, "accessors", &indices);
    if (s == CG_OK)
        s = gltf_get_index(doc, item, path, "material", 0, &doc->materials, "materials", &material);
    if (s != CG_OK)
        return s;
    p->mode = (int)mode;
    p->material = material;
    char attributes_path[128];
    snprintf(attributes_path, sizeof attributes_path, "%s.attributes", path);
    /* every attribute is an accessor index with a known name */
    unsigned long long sets[4] = {0, 0, 0, 0}; /* TEXCOORD_n, COLOR_n, JOINTS_n, WEIGHTS_n */
    for (const cJSON *a = attributes->child; a; a = a->next) {
        size_t index;
        if ((s = gltf_get_index(doc, attributes, attributes_path, a->string, 1, &doc->accessors,
                                "accessors", &index))
            != CG_OK)
            return s;
        if ((s = check_semantic(doc, attributes_path, a->string, sets)) != CG_OK)
            return s;
    }
    static const char *const families[4] = {"TEXCOORD", "COLOR", "JOINTS", "WEIGHTS"};
    for (int k = 0; k < 4; k++)
        if (sets[k] & (sets[k] + 1)) /* not 0b0..01..1: a gap */
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s: expected %s_0, %s_1, ... without a gap, got %s_%d without "
                                "%s_%d",
                                doc->name, attributes_path, families[k], families[k], families[k],
                                63 - __builtin_clzll(sets[k]), families[k],
                                __builtin_ctzll(~sets[k]));
    s = attribute(doc, attributes, attributes_path, "POSITION", 1, "VEC3", SIZE_MAX, &p->position,
                  &p->has_position);
    size_t count = p->has_position ? p->position.count : SIZE_MAX;
    if (s == CG_OK)
        s = attribute(doc, attributes, attributes_path, "NORMAL", 1, "VEC3", count, &p->normal,
                      &p->has_normal);
    if (s == CG_OK)
        s = attribute(doc, attributes, attributes_path, "TEXCOORD_0", 0, "VEC2", count,
                      &p->texcoord, &p->has_texcoord);
    if (s == CG_OK)
        s = attribute(doc, attributes, attributes_path, "COLOR_0", 0, "VEC3 VEC4", count, &p->color,
                      &p->has_color);
    if (s != CG_OK)
        return s;
    if (indices != SIZE_MAX) {
        p->has_indices = 1;
        if ((s = gltf_accessor_describe(doc, indices, &p->indices)) != CG_OK)
            return s;
        if (p->indices.components != 1 || p->indices.normalized
            || (p->indices.component_type != GLTF_UNSIGNED_BYTE
                && p->indices.component_type != GLTF_UNSIGNED_SHORT
                && p->indices.component_type != GLTF_UNSIGNED_INT))
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s.indices: expected an accessor of unsigned byte, short or "
                                "int SCALARs, got accessors[%zu]: %s of component type %d",
                                doc->name, path, indices, p->indices.type,
                                p->indices.component_type);
    }
    size_t n = p->has_indices ? p->indices.count : p->has_position ? p->position.count : 0;
    if (p->mode == MODE_TRIANGLES && n % 3)
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s: expected a multiple of 3 %s for mode 4 (triangles), got %zu",
                            doc->name, path, p->has_indices ? "indices" : "vertices", n);
    if (p->has_position)
        p->triangles = triangles_of(p->mode, n);
    return CG_OK;
}

/* Calls describe_primitive on each of mesh m's primitives; visit (may be
 * NULL) gets each one. */
typedef cg_status (*primitive_visit)(gltf_document *doc, const primitive *p, size_t mesh,
                                     size_t index, void *context);

static cg_status each_primitive(gltf_document *doc, size_t m, primitive_visit visit, void *context)
{
    char path[64];
    snprintf(path, sizeof path, "meshes[%zu]", m);
    gltf_list primitives;
    cg_status s = gltf_get_list(doc, doc->meshes.items[m], path, "primitives", 1, &primitives);
    if (s == CG_OK && !primitives.count)
        s = cg_error_set(doc->err, CG_EFORMAT, "%s: %s: expected primitives", doc->name, path);
    for (size_t i = 0; s == CG_OK && i < primitives.count; i++) {
        char item_path[112];
        snprintf(item_path, sizeof item_path, "%s.primitives[%zu]", path, i);
        primitive p;
        s = describe_primitive(doc, primitives.items[i], item_path, &p);
        if (s == CG_OK && visit)
            s = visit(doc, &p, m, i, context);
    }
    gltf_list_free(&primitives);
    return s;
}

typedef struct counting {
    gltf_totals *totals;
    int counting_skipped;
} counting;

static cg_status count_visit(gltf_document *doc, const primitive *p, size_t mesh, size_t index,
                             void *context)
{
    (void)index;
    counting *c = context;
    gltf_totals *t = c->totals;
    int drawn = p->has_position && p->mode >= MODE_TRIANGLES;
    if (c->counting_skipped) {
        if (p->mode == MODE_POINTS)
            doc->skipped.point_primitives++;
        else if (p->mode <= MODE_LINE_STRIP)
            doc->skipped.line_primitives++;
        else if (!p->has_position)
            doc->skipped.no_position_primitives++;
    }
    if (!drawn || c->counting_skipped)
        return CG_OK;
    if (p->position.count > CG_MESH_MAX_VERTICES - t->vertices
        || p->triangles > (CG_MESH_MAX_INDICES / 3) - t->triangles)
        return cg_error_set(doc->err, CG_ERANGE,
                            "%s: the default scene has more vertices or triangles than cg_mesh "
                            "holds",
                            doc->name);
    size_t budget = gltf_element_budget(doc);
    if (t->vertices + p->position.count > budget
        || t->triangles + p->triangles > budget - (t->vertices + p->position.count))
        return cg_error_set(doc->err, CG_ERANGE,
                            "%s: meshes[%zu]: the default scene's instances make more than %zu "
                            "vertices and triangles, more than cg makes from a file of %zu bytes",
                            doc->name, mesh, budget, doc->input_bytes);
    t->vertices += p->position.count;
    t->triangles += p->triangles;
    t->all_normals &= p->has_normal;
    t->any_texcoords |= p->has_texcoord;
    t->any_colors |= p->has_color;
    return CG_OK;
}

cg_status gltf_count_primitives(gltf_document *doc, const gltf_instance_array *instances,
                                gltf_totals *totals)
{
    memset(totals, 0, sizeof *totals);
    totals->all_normals = 1;
    /* every mesh is checked, used or not; skipped parts counted once per mesh */
    counting c = {totals, 1};
    gltf_totals unused = *totals;
    c.totals = &unused;
    for (size_t m = 0; m < doc->meshes.count; m++) {
        char path[48];
        snprintf(path, sizeof path, "meshes[%zu]", m);
        gltf_list targets;
        cg_status s = each_primitive(doc, m, count_visit, &c);
        if (s != CG_OK)
            return s;
        const cJSON *primitives = cJSON_GetObjectItemCaseSensitive(doc->meshes.items[m],
                                                                   "primitives");
        for (const cJSON *p = primitives->child; p; p = p->next) {
            if ((s = gltf_get_list(doc, p, path, "targets", 1, &targets)) != CG_OK)
                return s;
            doc->skipped.morph_targets += targets.count;
            gltf_list_free(&targets);
        }
    }
    c.totals = totals;
    c.counting_skipped = 0;
    for (size_t i = 0; i < instances->count; i++) {
        cg_status s = each_primitive(doc, instances->data[i].mesh, count_visit, &c);
        if (s != CG_OK)
            return s;
    }
    if (totals->vertices == 0)
        totals->all_normals = 0;
    return CG_OK;
}

typedef struct filling {
    cg_mesh *mesh;
    const gltf_instance *instance;
    cg_mat4 normal_matrix;
    int mirrored;
    int identity;            /* the world matrix is the identity: nothing to move */
    size_t vertex, triangle; /* next free */
} filling;

static cg_status read_all(gltf_document *doc, const gltf_accessor *a, double **values)
{
    *values = malloc(a->count * (size_t)a->components * sizeof **values);
    if (!*values)
        return gltf_out_of_memory(doc);
    cg_status s = gltf_accessor_read_doubles(doc, a, *values);
    if (s != CG_OK) {
        free(*values);
        *values = NULL;
    }
    return s;
}

/* p moved by the affine matrix m (glTF node matrices are affine: TRS, or a
 * matrix whose last row is checked to be 0 0 0 1). */
static cg_vec3 affine_point(const cg_mat4 *m, cg_vec3 p)
{
    return cg_vec3_make(m->m[0][0] * p.x + m->m[0][1] * p.y + m->m[0][2] * p.z + m->m[0][3],
                        m->m[1][0] * p.x + m->m[1][1] * p.y + m->m[1][2] * p.z + m->m[1][3],
                        m->m[2][0] * p.x + m->m[2][1] * p.y + m->m[2][2] * p.z + m->m[2][3]);
}

static cg_vec3 linear_vector(const cg_mat4 *m, cg_vec3 v)
{
    return cg_vec3_make(m->m[0][0] * v.x + m->m[0][1] * v.y + m->m[0][2] * v.z,
                        m->m[1][0] * v.x + m->m[1][1] * v.y + m->m[1][2] * v.z,
                        m->m[2][0] * v.x + m->m[2][1] * v.y + m->m[2][2] * v.z);
}

static cg_status read_positions(gltf_document *doc, const primitive *p, filling *f)
{
    /* straight into the mesh: a cg_vec3 array is an array of doubles */
    cg_vec3 *out = f->mesh->positions + f->vertex;
    cg_status s = gltf_accessor_read_doubles(doc, &p->position, &out->x);
    const cg_mat4 *world = &f->instance->world;
    for (size_t i = 0; s == CG_OK && i < p->position.count; i++) {
        cg_vec3 q = out[i];
        if (mesh_nonfinite_axis(q) >= 0)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: accessors[%zu]: element %zu: expected a finite POSITION, got "
                                "(%g, %g, %g)",
                                doc->name, p->position.index, i, q.x, q.y, q.z);
        if (!f->identity)
            out[i] = affine_point(world, q);
        if (mesh_nonfinite_axis(out[i]) >= 0)
            return cg_error_set(doc->err, CG_ERANGE,
                                "%s: nodes[%zu]: the world transform takes POSITION element %zu "
                                "of accessors[%zu] beyond the range of doubles",
                                doc->name, f->instance->node, i, p->position.index);
    }
    return s;
}

static cg_status fill_vertices(gltf_document *doc, const primitive *p, filling *f)
{
    cg_mesh *mesh = f->mesh;
    size_t base = f->vertex, n = p->position.count;
    cg_status s = read_positions(doc, p, f);
    if (s == CG_OK && mesh->normals
        && (s = gltf_accessor_read_doubles(doc, &p->normal, &mesh->normals[base].x)) == CG_OK) {
        for (size_t i = 0; i < n; i++) {
            cg_vec3 v = mesh->normals[base + i];
            if (!f->identity)
                v = linear_vector(&f->normal_matrix, v);
            double length = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
            mesh->normals[base + i] = length > 0 && isfinite(length)
                                          ? cg_vec3_make(v.x / length, v.y / length, v.z / length)
                                          : cg_vec3_make(0, 0, 0);
        }
    }
    if (s == CG_OK && mesh->texcoords && p->has_texcoord
        && (s = gltf_accessor_read_doubles(doc, &p->texcoord, &mesh->texcoords[base].x)) == CG_OK)
        for (size_t i = 0; i < n; i++)
            mesh->texcoords[base + i].y = 1.0 - mesh->texcoords[base + i].y;
    double *values;
    if (s == CG_OK && mesh->colors && p->has_color
        && (s = read_all(doc, &p->color, &values)) == CG_OK) {
        size_t k = (size_t)p->color.components;
        for (size_t i = 0; i < n; i++) {
            const double *c = values + k * i;
            cg_rgbaf color = {(float)c[0], (float)c[1], (float)c[2], k == 4 ? (float)c[3] : 1.0f};
            mesh->colors[base + i] = color;
        }
        free(values);
    }
    return s;
}

/* Reads a primitive's indices into out and checks them against its vertices. */
static cg_status read_indices(gltf_document *doc, const primitive *p, size_t mesh_index,
                              size_t index, uint32_t *out)
{
    cg_status s = gltf_accessor_read_indices(doc, &p->indices, out);
    for (size_t i = 0; s == CG_OK && i < p->indices.count; i++)
        if (out[i] >= p->position.count)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: meshes[%zu].primitives[%zu].indices: expected indices below "
                                "%zu (the POSITION count), got %u (accessors[%zu], element %zu)",
                                doc->name, mesh_index, index, p->position.count, out[i],
                                p->indices.index, i);
    return s;
}

/* The triangles of a primitive into the mesh, from its indices (NULL: the
 * vertices in order). */
static void put_triangles(const primitive *p, const uint32_t *indices, filling *f)
{
    cg_mesh *mesh = f->mesh;
    uint32_t material = p->material == SIZE_MAX ? CG_MESH_NO_MATERIAL : (uint32_t)p->material;
    for (size_t t = 0; t < p->triangles; t++) {
        size_t corner[3];
        if (p->mode == MODE_TRIANGLES) {
            corner[0] = 3 * t, corner[1] = 3 * t + 1, corner[2] = 3 * t + 2;
        } else if (p->mode == MODE_TRIANGLE_STRIP) {
            corner[0] = t, corner[1] = t + 1 + t % 2, corner[2] = t + 2 - t % 2;
        } else {
            corner[0] = t + 1, corner[1] = t + 2, corner[2] = 0;
        }
        if (f->mirrored) {
            size_t swap = corner[1];
            corner[1] = corner[2];
            corner[2] = swap;
        }
        size_t face = f->triangle + t;
        uint32_t v[3];
        for (int k = 0; k < 3; k++)
            v[k] = (uint32_t)(f->vertex + (indices ? indices[corner[k]] : corner[k]));
        /* indices may be this very array (TRIANGLES read in place): write after reading */
        for (int k = 0; k < 3; k++)
            mesh->face_indices[3 * face + (size_t)k] = v[k];
        mesh->face_offsets[face + 1] = (uint32_t)(3 * (face + 1));
        if (mesh->face_materials)
            mesh->face_materials[face] = material;
    }
}

static cg_status fill_visit(gltf_document *doc, const primitive *p, size_t mesh_index, size_t index,
                            void *context)
{
    filling *f = context;
    if (!p->has_position || p->mode < MODE_TRIANGLES)
        return CG_OK;
    cg_status s = fill_vertices(doc, p, f);
    if (s != CG_OK)
        return s;
    uint32_t *indices = NULL, *scratch = NULL;
    if (p->has_indices && p->mode == MODE_TRIANGLES) {
        /* as many indices as corners: read them where the corners go */
        indices = f->mesh->face_indices + 3 * f->triangle;
    } else if (p->has_indices) {
        if (!(indices = scratch = malloc(p->indices.count * sizeof *indices)))
            return gltf_out_of_memory(doc);
    }
    if (indices)
        s = read_indices(doc, p, mesh_index, index, indices);
    if (s == CG_OK)
        put_triangles(p, indices, f);
    free(scratch);
    f->vertex += p->position.count;
    f->triangle += p->triangles;
    return s;
}

cg_status gltf_fill_mesh(gltf_document *doc, const gltf_instance_array *instances, cg_mesh *mesh)
{
    filling f = {mesh, NULL, cg_mat4_identity(), 0, 0, 0, 0};
    if (mesh->colors)
        for (size_t i = 0; i < mesh->vertex_count; i++) {
            cg_rgbaf white = {1, 1, 1, 1};
            mesh->colors[i] = white;
        }
    for (size_t i = 0; i < instances->count; i++) {
        f.instance = &instances->data[i];
        cg_mat4 inverse;
        if (cg_mat4_inverse(f.instance->world, &inverse) == CG_OK)
            f.normal_matrix = cg_mat4_transpose(inverse);
        else
            f.normal_matrix = f.instance->world; /* singular: the mesh is flat anyway */
        f.mirrored = cg_mat4_determinant(f.instance->world) < 0;
        cg_mat4 identity = cg_mat4_identity();
        f.identity = memcmp(&identity, &f.instance->world, sizeof identity) == 0;
        cg_status s = each_primitive(doc, f.instance->mesh, fill_visit, &f);
        if (s != CG_OK)
            return s;
    }
    return CG_OK;
}
