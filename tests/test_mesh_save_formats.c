/* The OFF, STL and glTF (.glb) writers read back by cg's readers: random
 * meshes with normals, texture coordinates, vertex and face colours and
 * materials come back with what each format carries, exactly (OFF) or
 * within float rounding (STL, glTF), triangle by triangle in order. */
#include "cg.h"
#include "check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[64];

/* A random closed-ish mesh: a sphere with every optional array filled. */
static cg_mesh *random_mesh(check_rng *rng, int with_materials)
{
    cg_mesh *sphere;
    int slices = (int)check_rng_int(rng, 3, 12), stacks = (int)check_rng_int(rng, 2, 9);
    if (cg_mesh_sphere(slices, stacks, check_rng_range(rng, 0.1, 50), &sphere) != CG_OK)
        return NULL;
    cg_mesh *m;
    if (cg_mesh_create(&m, sphere->vertex_count, sphere->face_count,
                       sphere->face_offsets[sphere->face_count],
                       CG_MESH_NORMALS | CG_MESH_TEXCOORDS | CG_MESH_COLORS | CG_MESH_FACE_COLORS)
        != CG_OK)
        return NULL;
    memcpy(m->face_offsets, sphere->face_offsets, (sphere->face_count + 1) * sizeof(uint32_t));
    memcpy(m->face_indices, sphere->face_indices,
           sphere->face_offsets[sphere->face_count] * sizeof(uint32_t));
    for (size_t v = 0; v < m->vertex_count; v++) {
        m->positions[v] = sphere->positions[v];
        double x = check_rng_range(rng, -1, 1), y = check_rng_range(rng, -1, 1), z = 0.5;
        double length = sqrt(x * x + y * y + z * z);
        m->normals[v] = cg_vec3_make(x / length, y / length, z / length);
        m->texcoords[v] = cg_vec2_make(check_rng_range(rng, -2, 2), check_rng_range(rng, 0, 1));
        cg_rgbaf c = {(float)check_rng_range(rng, 0, 1), (float)check_rng_range(rng, 0, 1),
                      (float)check_rng_range(rng, 0, 1), (float)check_rng_range(rng, 0, 1)};
        m->colors[v] = c;
    }
    for (size_t f = 0; f < m->face_count; f++) {
        cg_rgbaf c = {(float)check_rng_range(rng, 0, 1), (float)check_rng_range(rng, 0, 1),
                      (float)check_rng_range(rng, 0, 1), 1};
        m->face_colors[f] = c;
    }
    if (with_materials) {
        m->material_count = 3;
        m->materials = calloc(3, sizeof *m->materials);
        m->face_materials = malloc(m->face_count * sizeof *m->face_materials);
        for (size_t i = 0; i < 3; i++) {
            m->materials[i] = cg_mesh_material_default();
            m->materials[i].name = malloc(16);
            snprintf(m->materials[i].name, 16, "material %zu", i);
            m->materials[i].model = CG_MESH_MATERIAL_METALLIC_ROUGHNESS;
            m->materials[i].metallic = 0.25 * (double)i;
            m->materials[i].roughness = 0.5;
            m->materials[i].base_color.g = 0.5f;
        }
        for (size_t f = 0; f < m->face_count; f++)
            m->face_materials[f] = f % 4 == 3 ? CG_MESH_NO_MATERIAL : (uint32_t)(f % 3);
    }
    cg_mesh_free(sphere);
    return m;
}

static int near(double a, double b, double tolerance)
{
    return fabs(a - b) <= tolerance * fmax(1, fabs(b));
}

static void off_round_trip(void)
{
    check_rng rng = {101};
    for (int round = 0; round < 20; round++) {
        cg_mesh *m = random_mesh(&rng, 0), *back = NULL;
        char path[128];
        snprintf(path, sizeof path, "%s/m.off", dir);
        cg_error err;
        CHECK_MSG(cg_mesh_save(m, path, CG_MESH_FORMAT_AUTO, &err) == CG_OK, "%s", err.message);
        CHECK_MSG(cg_mesh_load(path, &back, &err) == CG_OK, "%s", err.message);
        if (back) {
            CHECK(back->vertex_count == m->vertex_count && back->face_count == m->face_count);
            CHECK(back->normals && back->texcoords && back->colors && back->face_colors);
            long bad = 0;
            for (size_t v = 0; back->colors && v < m->vertex_count; v++) {
                bad += memcmp(&back->positions[v], &m->positions[v], sizeof(cg_vec3)) != 0;
                bad += memcmp(&back->normals[v], &m->normals[v], sizeof(cg_vec3)) != 0;
                bad += memcmp(&back->texcoords[v], &m->texcoords[v], sizeof(cg_vec2)) != 0;
                bad += !near(back->colors[v].r, m->colors[v].r, 1e-6)
                       || !near(back->colors[v].a, m->colors[v].a, 1e-6);
            }
            for (size_t k = 0; k < m->face_offsets[m->face_count]; k++)
                bad += back->face_indices[k] != m->face_indices[k];
            for (size_t f = 0; back->face_colors && f < m->face_count; f++)
                bad += !near(back->face_colors[f].b, m->face_colors[f].b, 1e-6);
            CHECK_MSG(bad == 0, "round %d: %ld values differ after OFF", round, bad);
        }
        cg_mesh_free(back);
        cg_mesh_free(m);
    }
}

/* The triangles of m (corner vertex indices), in order. */
static uint32_t (*triangles_of(const cg_mesh *m, size_t *n))[3]
{
    *n = cg_mesh_triangle_count(m);
    uint32_t(*t)[3] = malloc((*n ? *n : 1) * sizeof *t);
    cg_mesh_triangulate(m, t);
    for (size_t i = 0; i < *n; i++)
        for (int k = 0; k < 3; k++)
            t[i][k] = m->face_indices[t[i][k]];
    return t;
}

static int same_float3(cg_vec3 a, cg_vec3 b)
{
    return (float)a.x == (float)b.x && (float)a.y == (float)b.y && (float)a.z == (float)b.z;
}

static void stl_round_trip(void)
{
    check_rng rng = {202};
    for (int round = 0; round < 20; round++) {
        cg_mesh *m = random_mesh(&rng, 0), *back = NULL;
        char path[128];
        snprintf(path, sizeof path, "%s/m.stl", dir);
        cg_error err;
        CHECK_MSG(cg_mesh_save(m, path, CG_MESH_FORMAT_AUTO, &err) == CG_OK, "%s", err.message);
        CHECK_MSG(cg_mesh_load(path, &back, &err) == CG_OK, "%s", err.message);
        size_t n, nb = 0;
        uint32_t(*a)[3] = triangles_of(m, &n);
        uint32_t(*b)[3] = back ? triangles_of(back, &nb) : NULL;
        CHECK(back && nb == n);
        long bad = 0;
        for (size_t t = 0; back && t < n && t < nb; t++)
            for (int k = 0; k < 3; k++)
                bad += !same_float3(back->positions[b[t][k]], m->positions[a[t][k]]);
        CHECK_MSG(bad == 0, "round %d: %ld corners differ after STL", round, bad);
        free(a);
        free(b);
        cg_mesh_free(back);
        cg_mesh_free(m);
    }
}

static void glb_round_trip(void)
{
    check_rng rng = {303};
    for (int round = 0; round < 20; round++) {
        int with_materials = round % 2;
        cg_mesh *m = random_mesh(&rng, with_materials), *back = NULL;
        char path[128];
        snprintf(path, sizeof path, "%s/m.glb", dir);
        cg_error err;
        CHECK_MSG(cg_mesh_save(m, path, CG_MESH_FORMAT_AUTO, &err) == CG_OK, "%s", err.message);
        CHECK_MSG(cg_mesh_load(path, &back, &err) == CG_OK, "%s", err.message);
        if (!back) {
            cg_mesh_free(m);
            continue;
        }
        size_t n, nb;
        uint32_t(*a)[3] = triangles_of(m, &n);
        uint32_t(*b)[3] = triangles_of(back, &nb);
        CHECK_EQ_INT(nb, n);
        /* the writer groups triangles by material (0, 1, 2, then none), in order */
        size_t *order = malloc(n * sizeof *order), k = 0;
        size_t *face_of = malloc(n * sizeof *face_of);
        for (size_t f = 0, t = 0; f < m->face_count; f++)
            for (uint32_t c = 2; c < cg_mesh_face_size(m, f); c++)
                face_of[t++] = f;
        for (int g = 0; g <= (with_materials ? 3 : 0); g++)
            for (size_t t = 0; t < n; t++) {
                uint32_t mat = with_materials ? m->face_materials[face_of[t]] : CG_MESH_NO_MATERIAL;
                if (with_materials ? (g == 3 ? mat == CG_MESH_NO_MATERIAL : mat == (uint32_t)g) : 1)
                    order[k++] = t;
            }
        long bad = 0;
        for (size_t i = 0; i < n && i < nb && k == n; i++) {
            size_t t = order[i];
            for (int c = 0; c < 3; c++) {
                uint32_t v = a[t][c], w = b[i][c];
                bad += !same_float3(back->positions[w], m->positions[v]);
                bad += !near(back->normals[w].x, m->normals[v].x, 1e-6);
                bad += (float)back->texcoords[w].x != (float)m->texcoords[v].x
                       || fabs(back->texcoords[w].y - m->texcoords[v].y) > 1e-6;
                bad += !near(back->colors[w].g, m->colors[v].g, 1e-6);
            }
            if (with_materials) {
                uint32_t want = m->face_materials[face_of[t]];
                bad += back->face_materials[i] != want;
            }
        }
        CHECK_MSG(bad == 0, "round %d: %ld values differ after glTF", round, bad);
        if (with_materials) {
            CHECK(back->material_count == 3 && strcmp(back->materials[2].name, "material 2") == 0
                  && back->materials[2].metallic == 0.5 && back->materials[1].base_color.g == 0.5f);
        }
        free(order);
        free(face_of);
        free(a);
        free(b);
        cg_mesh_free(back);
        cg_mesh_free(m);
    }
    /* .gltf text is not written */
    cg_mesh *box;
    cg_mesh_box(cg_vec3_make(0, 0, 0), cg_vec3_make(1, 1, 1), &box);
    char path[128];
    snprintf(path, sizeof path, "%s/m.gltf", dir);
    cg_error err;
    CHECK(cg_mesh_save(box, path, CG_MESH_FORMAT_AUTO, &err) == CG_EUNSUPPORTED
          && strstr(err.message, "name it .glb") && access(path, F_OK) != 0);
    cg_mesh_free(box);
}

int main(int argc, char **argv)
{
    snprintf(dir, sizeof dir, "/tmp/cg_save_XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    check_start(argc, argv);
    CHECK_GROUP(off_round_trip);
    CHECK_GROUP(stl_round_trip);
    CHECK_GROUP(glb_round_trip);
    char command[128];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    if (system(command) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
    return check_finish();
}
