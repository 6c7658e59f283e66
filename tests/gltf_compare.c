/* The helper of tests/test_gltf_validator.sh: a mesh file and the .glb cg
 * wrote from it, both read by cg, are the same mesh as far as glTF carries
 * it.  The writer's contract (src/mesh/gltf_write.c): the triangles of
 * material 0, 1, ... and then those without one, each group in the order of
 * the source's faces; positions rounded to float; normals unit length;
 * v flipped twice (v' = 1 - (1 - v)); colours clamped to [0, 1]; material
 * factors kept (Phong: metallic 0, roughness sqrt(2 / (Ns + 2))); PNG and
 * JPEG maps embedded byte for byte with their sampler and transform.
 * Prints one line (triangles, values compared, values that differ) and the
 * first differences; exit 0 when none differ, 1 otherwise.
 * usage: gltf_compare SOURCE WRITTEN.glb */
#include "cg.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static long compared, differ;

static void expect(int ok, const char *what, size_t where)
{
    compared++;
    if (!ok && ++differ <= 10)
        fprintf(stderr, "gltf_compare: %s differs at %zu\n", what, where);
}

/* Equal within tolerance, relative to the size of a beyond 1. */
static int near(double a, double b, double tolerance)
{
    return fabs(a - b) <= tolerance * (fabs(a) > 1 ? fabs(a) : 1);
}

static double clamp01(double v)
{
    return v < 0 ? 0 : v > 1 ? 1 : v;
}

static uint32_t (*triangles_of(const cg_mesh *m, size_t *n))[3]
{
    *n = cg_mesh_triangle_count(m);
    uint32_t(*t)[3] = malloc((*n ? *n : 1) * sizeof *t);
    if (!t || cg_mesh_triangulate(m, t) != CG_OK) {
        free(t);
        return NULL;
    }
    return t;
}

static uint32_t material_of(const cg_mesh *m, size_t f)
{
    uint32_t k = m->face_materials ? m->face_materials[f] : CG_MESH_NO_MATERIAL;
    return k < m->material_count ? k : CG_MESH_NO_MATERIAL;
}

/* Corner c of source triangle against corner of written triangle. */
static void same_corner(const cg_mesh *a, uint32_t v, const cg_mesh *b, uint32_t w, size_t t)
{
    cg_vec3 p = a->positions[v], q = b->positions[w];
    expect((float)p.x == q.x && (float)p.y == q.y && (float)p.z == q.z, "position", t);
    expect(!a->normals == !b->normals, "having normals", t);
    if (a->normals && b->normals) {
        cg_vec3 n = a->normals[v], o = b->normals[w];
        double length = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        if (!(length > 0))
            n = cg_vec3_make(0, 0, 1), length = 1;
        expect(near(o.x, n.x / length, 1e-6) && near(o.y, n.y / length, 1e-6)
                   && near(o.z, n.z / length, 1e-6),
               "normal", t);
    }
    expect(!a->texcoords == !b->texcoords, "having texture coordinates", t);
    if (a->texcoords && b->texcoords)
        expect((float)a->texcoords[v].x == b->texcoords[w].x
                   && near(a->texcoords[v].y, b->texcoords[w].y, 1e-6),
               "texture coordinates", t);
    expect(!a->colors == !b->colors, "having colours", t);
    if (a->colors && b->colors) {
        const cg_rgbaf *c = &a->colors[v], *d = &b->colors[w];
        expect(near(clamp01(c->r), d->r, 1e-6) && near(clamp01(c->g), d->g, 1e-6)
                   && near(clamp01(c->b), d->b, 1e-6) && near(clamp01(c->a), d->a, 1e-6),
               "colour", t);
    }
}

/* The bytes of a texture's image (embedded or its file's), or NULL; *owned to free. */
static const unsigned char *image_of(const cg_mesh_texture_ref *t, size_t *n, unsigned char **owned)
{
    *owned = NULL, *n = 0;
    if (t->image_bytes) {
        *n = t->image_byte_count;
        return t->image_bytes;
    }
    FILE *f = t->image_path ? fopen(t->image_path, "rb") : NULL;
    if (!f)
        return NULL;
    unsigned char chunk[65536];
    size_t got;
    while ((got = fread(chunk, 1, sizeof chunk, f)) > 0) {
        unsigned char *more = realloc(*owned, *n + got);
        if (!more)
            break;
        memcpy(more + *n, chunk, got);
        *owned = more, *n += got;
    }
    fclose(f);
    return *owned;
}

/* A map of the source is embedded in the written file, the same bytes, when
 * its image is PNG or JPEG (written: whether the writer carries the slot). */
static void same_texture(const cg_mesh_texture_ref *a, const cg_mesh_texture_ref *b, int written,
                         size_t i)
{
    size_t n;
    unsigned char *owned;
    const unsigned char *bytes = image_of(a, &n, &owned);
    int image = written && bytes
                && ((n > 8 && memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0)
                    || (n > 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF));
    expect(image == (b->image_bytes != NULL), "having a texture", i);
    if (image && b->image_bytes) {
        expect(n == b->image_byte_count && memcmp(bytes, b->image_bytes, n) == 0, "texture bytes",
               i);
        expect(a->wrap_u == b->wrap_u && a->wrap_v == b->wrap_v, "texture wrap", i);
        expect(a->magnify_nearest == b->magnify_nearest && a->encoding == b->encoding,
               "texture filter and encoding", i);
        expect(a->offset[0] == b->offset[0] && a->offset[1] == b->offset[1]
                   && a->rotation == b->rotation && a->scale[0] == b->scale[0]
                   && a->scale[1] == b->scale[1],
               "texture transform", i);
        expect(a->amount == b->amount, "texture scale or strength", i);
    }
    free(owned);
}

static void same_material(const cg_mesh_material *m, const cg_mesh_material *w, size_t i)
{
    int pbr = m->model != CG_MESH_MATERIAL_PHONG;
    same_texture(&m->base_color_map, &w->base_color_map, 1, i);
    same_texture(&m->metallic_roughness_map, &w->metallic_roughness_map, pbr, i);
    same_texture(&m->normal_map, &w->normal_map, pbr, i);
    same_texture(&m->occlusion_map, &w->occlusion_map, 1, i);
    same_texture(&m->emissive_map, &w->emissive_map, 1, i);
    expect(strcmp(m->name ? m->name : "", w->name ? w->name : "") == 0, "material name", i);
    expect(w->model == CG_MESH_MATERIAL_METALLIC_ROUGHNESS, "material model", i);
    expect(clamp01(m->base_color.r) == w->base_color.r
               && clamp01(m->base_color.g) == w->base_color.g
               && clamp01(m->base_color.b) == w->base_color.b
               && clamp01(m->base_color.a) == w->base_color.a,
           "base colour", i);
    int phong = m->model == CG_MESH_MATERIAL_PHONG;
    double metallic = phong ? 0 : m->metallic;
    double roughness = phong ? sqrt(2 / (m->shininess + 2)) : m->roughness;
    expect(clamp01(metallic) == w->metallic, "metallic", i);
    expect(near(clamp01(roughness), w->roughness, 1e-12), "roughness", i);
    expect(near(m->emissive.r, w->emissive.r, 1e-6) && near(m->emissive.g, w->emissive.g, 1e-6)
               && near(m->emissive.b, w->emissive.b, 1e-6),
           "emissive", i);
    expect(m->alpha_mode == w->alpha_mode, "alpha mode", i);
    expect(m->alpha_mode != CG_MESH_ALPHA_MASK || m->alpha_cutoff == w->alpha_cutoff,
           "alpha cutoff", i);
    expect(!m->double_sided == !w->double_sided, "double-sided", i);
}

static void compare(const cg_mesh *a, const cg_mesh *b)
{
    size_t n, nb;
    uint32_t(*ta)[3] = triangles_of(a, &n), (*tb)[3] = triangles_of(b, &nb);
    size_t *face_of = malloc((n ? n : 1) * sizeof *face_of);
    expect(ta && tb && face_of, "memory", 0);
    expect(n == nb, "triangle count", n);
    for (size_t f = 0, t = 0; ta && face_of && f < a->face_count; f++)
        for (uint32_t c = 2; c < cg_mesh_face_size(a, f); c++)
            face_of[t++] = f;
    size_t i = 0; /* the written triangle */
    for (size_t g = 0; ta && tb && face_of && n == nb && g <= a->material_count; g++) {
        uint32_t wanted = g < a->material_count ? (uint32_t)g : CG_MESH_NO_MATERIAL;
        for (size_t t = 0; t < n; t++) {
            if (material_of(a, face_of[t]) != wanted)
                continue;
            expect(material_of(b, i) == wanted, "triangle material", i);
            for (int c = 0; c < 3; c++)
                same_corner(a, a->face_indices[ta[t][c]], b, b->face_indices[tb[i][c]], i);
            i++;
        }
    }
    expect(a->material_count == b->material_count || n == 0, "material count", a->material_count);
    for (size_t k = 0; n && k < a->material_count && k < b->material_count; k++)
        same_material(&a->materials[k], &b->materials[k], k);
    free(face_of);
    free(ta);
    free(tb);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: gltf_compare SOURCE WRITTEN.glb\n");
        return 2;
    }
    cg_mesh *a = NULL, *b = NULL;
    cg_error err;
    for (int k = 1; k <= 2; k++)
        if (cg_mesh_load(argv[k], k == 1 ? &a : &b, &err) != CG_OK) {
            fprintf(stderr, "gltf_compare: %s\n", err.message);
            cg_mesh_free(a);
            return 1;
        }
    compare(a, b);
    printf("%s -> %s: %zu triangles, %zu materials, %ld values compared, %ld differ\n", argv[1],
           argv[2], cg_mesh_triangle_count(a), a->material_count, compared, differ);
    cg_mesh_free(a);
    cg_mesh_free(b);
    return differ ? 1 : 0;
}
