/* Test and benchmark meshes for the half-edge structure, built in code:
 * tetrahedron, cube, grids with boundary, tori, voxel surfaces (genus by
 * construction) and icospheres.  Header-only; every function returns a
 * cg_mesh the caller frees, or NULL when memory runs out. */
#ifndef CG_TEST_HEMESH_SHAPES_H
#define CG_TEST_HEMESH_SHAPES_H

#include "cg/hemesh.h"
#include "cg/mesh.h"

#include <stdlib.h>
#include <string.h>

/* A growable list of polygons. */
typedef struct shape {
    size_t vertex_count, vertex_capacity;
    cg_vec3 *positions;
    size_t face_count, face_capacity, index_count, index_capacity;
    uint32_t *offsets, *indices;
} shape;

static inline void shape_vertex(shape *s, double x, double y, double z)
{
    if (s->vertex_count == s->vertex_capacity) {
        s->vertex_capacity = s->vertex_capacity * 2 + 16;
        s->positions = (cg_vec3 *)realloc(s->positions, s->vertex_capacity * sizeof *s->positions);
    }
    s->positions[s->vertex_count++] = cg_vec3_make(x, y, z);
}

static inline void shape_face(shape *s, const uint32_t *v, size_t n)
{
    if (s->face_count + 1 >= s->face_capacity) {
        s->face_capacity = s->face_capacity * 2 + 16;
        s->offsets = (uint32_t *)realloc(s->offsets, (s->face_capacity + 1) * sizeof *s->offsets);
    }
    if (s->index_count + n > s->index_capacity) {
        s->index_capacity = s->index_capacity * 2 + n + 16;
        s->indices = (uint32_t *)realloc(s->indices, s->index_capacity * sizeof *s->indices);
    }
    if (s->face_count == 0)
        s->offsets[0] = 0;
    memcpy(s->indices + s->index_count, v, n * sizeof *v);
    s->index_count += n;
    s->offsets[++s->face_count] = (uint32_t)s->index_count;
}

static inline void shape_face3(shape *s, uint32_t a, uint32_t b, uint32_t c)
{
    uint32_t v[3] = {a, b, c};
    shape_face(s, v, 3);
}

/* A quad, or two triangles (a, b, c) and (a, c, d) when triangles is set. */
static inline void shape_quad(shape *s, uint32_t a, uint32_t b, uint32_t c, uint32_t d,
                              int triangles)
{
    if (triangles) {
        shape_face3(s, a, b, c);
        shape_face3(s, a, c, d);
    } else {
        uint32_t v[4] = {a, b, c, d};
        shape_face(s, v, 4);
    }
}

static inline cg_mesh *shape_finish(shape *s)
{
    cg_mesh *m = NULL;
    if (cg_mesh_create(&m, s->vertex_count, s->face_count, s->index_count, 0) == CG_OK) {
        memcpy(m->positions, s->positions, s->vertex_count * sizeof *s->positions);
        if (s->face_count)
            memcpy(m->face_offsets, s->offsets, (s->face_count + 1) * sizeof *s->offsets);
        memcpy(m->face_indices, s->indices, s->index_count * sizeof *s->indices);
    }
    free(s->positions);
    free(s->offsets);
    free(s->indices);
    memset(s, 0, sizeof *s);
    return m;
}

static inline cg_mesh *shape_tetrahedron(void)
{
    shape s = {0};
    shape_vertex(&s, 1, 1, 1);
    shape_vertex(&s, 1, -1, -1);
    shape_vertex(&s, -1, 1, -1);
    shape_vertex(&s, -1, -1, 1);
    shape_face3(&s, 0, 1, 2);
    shape_face3(&s, 0, 2, 3);
    shape_face3(&s, 0, 3, 1);
    shape_face3(&s, 1, 3, 2);
    return shape_finish(&s);
}

/* The cube [-1, 1]^3 as 6 quads (or 12 triangles). */
static inline cg_mesh *shape_cube(int triangles)
{
    shape s = {0};
    for (int i = 0; i < 8; i++)
        shape_vertex(&s, i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    shape_quad(&s, 0, 2, 3, 1, triangles); /* z = -1 */
    shape_quad(&s, 4, 5, 7, 6, triangles); /* z = +1 */
    shape_quad(&s, 0, 1, 5, 4, triangles); /* y = -1 */
    shape_quad(&s, 2, 6, 7, 3, triangles); /* y = +1 */
    shape_quad(&s, 0, 4, 6, 2, triangles); /* x = -1 */
    shape_quad(&s, 1, 3, 7, 5, triangles); /* x = +1 */
    return shape_finish(&s);
}

/* An nx by ny grid in the plane z = 0 (one boundary loop). */
static inline cg_mesh *shape_grid(int nx, int ny, int triangles)
{
    shape s = {0};
    for (int j = 0; j <= ny; j++)
        for (int i = 0; i <= nx; i++)
            shape_vertex(&s, i, j, 0);
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            uint32_t a = (uint32_t)(j * (nx + 1) + i);
            shape_quad(&s, a, a + 1, a + 1 + (uint32_t)(nx + 1), a + (uint32_t)(nx + 1), triangles);
        }
    return shape_finish(&s);
}

/* A torus of n by m quads (n, m >= 3), radii 1 and 0.35. */
static inline cg_mesh *shape_torus(int n, int m, int triangles)
{
    shape s = {0};
    for (int i = 0; i < n; i++)
        for (int j = 0; j < m; j++) {
            double u = 2 * CG_PI * i / n, v = 2 * CG_PI * j / m;
            double r = 1 + 0.35 * cos(v);
            shape_vertex(&s, r * cos(u), r * sin(u), 0.35 * sin(v));
        }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < m; j++) {
            uint32_t a = (uint32_t)(i * m + j), b = (uint32_t)(((i + 1) % n) * m + j);
            uint32_t c = (uint32_t)(((i + 1) % n) * m + (j + 1) % m),
                     d = (uint32_t)(i * m + (j + 1) % m);
            shape_quad(&s, a, b, c, d, triangles);
        }
    return shape_finish(&s);
}

/* The boundary surface of a set of unit voxels: filled(x, y, z) for x < nx,
 * y < ny, z < nz given as a string of nz layers of ny rows of nx characters,
 * '#' filled.  Quads face outward. */
static inline cg_mesh *shape_voxels(const char *cells, int nx, int ny, int nz, int triangles)
{
    shape s = {0};
    size_t lattice = (size_t)(nx + 1) * (ny + 1) * (nz + 1);
    uint32_t *id = (uint32_t *)malloc(lattice * sizeof *id);
    memset(id, 0xff, lattice * sizeof *id);
#define VOX(x, y, z)                                                      \
    ((x) >= 0 && (y) >= 0 && (z) >= 0 && (x) < nx && (y) < ny && (z) < nz \
     && cells[((z)*ny + (y)) * nx + (x)] == '#')
    for (int z = 0; z < nz; z++)
        for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx; x++) {
                if (!VOX(x, y, z))
                    continue;
                for (int axis = 0; axis < 3; axis++)
                    for (int sign = -1; sign <= 1; sign += 2) {
                        int d[3] = {0, 0, 0};
                        d[axis] = sign;
                        if (VOX(x + d[0], y + d[1], z + d[2]))
                            continue;
                        int u = (axis + 1) % 3, w = (axis + 2) % 3;
                        int base[3] = {x, y, z};
                        if (sign > 0)
                            base[axis]++;
                        uint32_t corner[4];
                        for (int k = 0; k < 4; k++) {
                            int p[3] = {base[0], base[1], base[2]};
                            if (k == 1 || k == 2)
                                p[u]++;
                            if (k == 2 || k == 3)
                                p[w]++;
                            size_t key = ((size_t)p[2] * (ny + 1) + p[1]) * (nx + 1) + p[0];
                            if (id[key] == 0xffffffffu) {
                                id[key] = (uint32_t)s.vertex_count;
                                shape_vertex(&s, p[0], p[1], p[2]);
                            }
                            corner[k] = id[key];
                        }
                        if (sign > 0)
                            shape_quad(&s, corner[0], corner[1], corner[2], corner[3], triangles);
                        else
                            shape_quad(&s, corner[0], corner[3], corner[2], corner[1], triangles);
                    }
            }
#undef VOX
    free(id);
    return shape_finish(&s);
}

/* Genus 1 and 2 voxel solids: a ring and a double ring. */
static inline cg_mesh *shape_ring(int triangles)
{
    return shape_voxels("###"
                        "#.#"
                        "###",
                        3, 3, 1, triangles);
}
static inline cg_mesh *shape_double_ring(int triangles)
{
    return shape_voxels("#####"
                        "#.#.#"
                        "#####",
                        5, 3, 1, triangles);
}

/* An icosphere: the icosahedron Loop-subdivided `level` times with its
 * vertices pushed onto the unit sphere. */
static inline cg_mesh *shape_icosphere(int level)
{
    shape s = {0};
    double t = (1 + sqrt(5.0)) / 2;
    double v[12][3] = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                       {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    static const uint32_t f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                      {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                      {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                      {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int i = 0; i < 12; i++)
        shape_vertex(&s, v[i][0], v[i][1], v[i][2]);
    for (int i = 0; i < 20; i++)
        shape_face3(&s, f[i][0], f[i][1], f[i][2]);
    cg_mesh *mesh = shape_finish(&s);
    cg_hemesh *h = NULL;
    if (!mesh || cg_hemesh_build(mesh, 0, &h, NULL, NULL) != CG_OK) {
        cg_mesh_free(mesh);
        return NULL;
    }
    cg_mesh_free(mesh);
    for (int l = 0; l < level; l++) {
        cg_hemesh *next = NULL;
        if (cg_hemesh_subdivide_loop(h, &next) != CG_OK) {
            cg_hemesh_free(h);
            return NULL;
        }
        cg_hemesh_free(h);
        h = next;
    }
    for (size_t i = 0; i < h->vertex_count; i++)
        h->positions[i] = cg_vec3_normalize(h->positions[i]);
    mesh = NULL;
    cg_hemesh_to_mesh(h, &mesh);
    cg_hemesh_free(h);
    return mesh;
}

#endif
