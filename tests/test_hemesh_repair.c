/* Counts of the input and the repairing build, over random non-manifold
 * meshes: duplicate faces, reversed duplicates, fans of three or more faces
 * on an edge, bow-tie vertices, voxel solids touching along edges, and
 * random polygon soups.  The input counts are checked against a brute-force
 * count; the repair must give a mesh that builds strictly (manifold and
 * oriented) and that a second repair leaves unchanged. */
#include "check.h"
#include "hemesh_shapes.h"

#include "cg/hemesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- brute-force counts ------------------------------------------------- */

static int brute_polygon(const cg_mesh *m, size_t f)
{
    uint32_t begin = m->face_offsets[f], end = m->face_offsets[f + 1];
    if (end - begin < 3)
        return 0;
    for (uint32_t i = begin; i < end; i++) {
        if (m->face_indices[i] >= m->vertex_count)
            return 0;
        for (uint32_t j = i + 1; j < end; j++)
            if (m->face_indices[i] == m->face_indices[j])
                return 0;
    }
    return 1;
}

/* Pairs compared one against all, and components by relaxing a label to
 * the smallest over each face until nothing changes. */
static cg_hemesh_input_counts brute_counts(const cg_mesh *m)
{
    cg_hemesh_input_counts c;
    memset(&c, 0, sizeof c);
    size_t V = m->vertex_count, corners = m->face_offsets[m->face_count];
    uint64_t *pairs = malloc((corners + 1) * sizeof *pairs);
    uint32_t *label = malloc((V + 1) * sizeof *label);
    unsigned char *used = calloc(V + 1, 1);
    size_t n = 0;
    for (size_t v = 0; v < V; v++)
        label[v] = (uint32_t)v;
    for (size_t f = 0; f < m->face_count; f++) {
        if (!brute_polygon(m, f)) {
            c.bad_faces++;
            continue;
        }
        c.faces++;
        uint32_t begin = m->face_offsets[f], end = m->face_offsets[f + 1];
        for (uint32_t k = begin; k < end; k++) {
            uint32_t a = m->face_indices[k], b = m->face_indices[k + 1 < end ? k + 1 : begin];
            uint64_t key = a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
            int seen = 0;
            for (size_t i = 0; i < n && !seen; i++)
                seen = pairs[i] == key;
            if (!seen)
                pairs[n++] = key;
            used[a] = 1;
        }
    }
    for (int changed = 1; changed;) {
        changed = 0;
        for (size_t f = 0; f < m->face_count; f++) {
            if (!brute_polygon(m, f))
                continue;
            uint32_t low = UINT32_MAX;
            for (uint32_t k = m->face_offsets[f]; k < m->face_offsets[f + 1]; k++)
                if (label[m->face_indices[k]] < low)
                    low = label[m->face_indices[k]];
            for (uint32_t k = m->face_offsets[f]; k < m->face_offsets[f + 1]; k++)
                if (label[m->face_indices[k]] != low) {
                    label[m->face_indices[k]] = low;
                    changed = 1;
                }
        }
    }
    c.vertices = V;
    c.edges = n;
    for (size_t v = 0; v < V; v++) {
        c.components += label[v] == v;
        c.isolated_vertices += !used[v];
    }
    c.euler_characteristic = (long)c.vertices - (long)c.edges + (long)c.faces;
    free(pairs);
    free(label);
    free(used);
    return c;
}

static void check_counts(const char *name, int trial, const cg_mesh *m)
{
    cg_hemesh_input_counts got, want = brute_counts(m);
    CHECK_MSG(cg_hemesh_input_counts_compute(m, &got) == CG_OK, "%s %d: counts failed", name,
              trial);
    CHECK_MSG(
        got.vertices == want.vertices && got.edges == want.edges && got.faces == want.faces
            && got.bad_faces == want.bad_faces && got.components == want.components
            && got.isolated_vertices == want.isolated_vertices
            && got.euler_characteristic == want.euler_characteristic,
        "%s %d: counts V %zu E %zu F %zu bad %zu C %zu iso %zu, brute force V %zu E %zu F %zu "
        "bad %zu C %zu iso %zu",
        name, trial, got.vertices, got.edges, got.faces, got.bad_faces, got.components,
        got.isolated_vertices, want.vertices, want.edges, want.faces, want.bad_faces,
        want.components, want.isolated_vertices);
}

/* ---- repair ------------------------------------------------------------- */

static int same_mesh(const cg_mesh *a, const cg_mesh *b)
{
    if (a->vertex_count != b->vertex_count || a->face_count != b->face_count)
        return 0;
    if (memcmp(a->positions, b->positions, a->vertex_count * sizeof *a->positions))
        return 0;
    size_t corners = a->face_offsets[a->face_count];
    return memcmp(a->face_offsets, b->face_offsets, (a->face_count + 1) * sizeof *a->face_offsets)
               == 0
           && memcmp(a->face_indices, b->face_indices, corners * sizeof *a->face_indices) == 0;
}

/* The repaired mesh of m, or NULL when m has no usable face. */
static cg_mesh *repair(const char *name, int trial, const cg_mesh *m, cg_hemesh_report *rep,
                       cg_hemesh_stats *stats)
{
    cg_hemesh *h = NULL;
    cg_error err;
    cg_status s = cg_hemesh_build(m, CG_HEMESH_REPAIR, &h, rep, &err);
    if (s == CG_EEMPTY)
        return NULL;
    CHECK_MSG(s == CG_OK, "%s %d: repair failed: %s", name, trial, err.message);
    if (s != CG_OK)
        return NULL;
    CHECK_MSG(cg_hemesh_validate(h, &err) == CG_OK, "%s %d: %s", name, trial, err.message);
    CHECK(cg_hemesh_stats_compute(h, stats, NULL, NULL) == CG_OK);
    cg_mesh *out = NULL;
    CHECK(cg_hemesh_to_mesh(h, &out) == CG_OK);
    cg_hemesh_free(h);
    return out;
}

/* repair(m) builds strictly, describes the repaired structure, and
 * repair(repair(m)) == repair(m) with nothing reported. */
static void check_repair(const char *name, int trial, const cg_mesh *m, int closed)
{
    cg_hemesh_report rep;
    cg_hemesh_stats st;
    cg_mesh *once = repair(name, trial, m, &rep, &st);
    cg_hemesh_report_clear(&rep);
    if (!once)
        return;
    cg_error err;
    cg_hemesh *strict = NULL;
    cg_status s = cg_hemesh_build(once, 0, &strict, NULL, &err);
    CHECK_MSG(s == CG_OK, "%s %d: the repaired mesh is not a clean manifold: %s", name, trial,
              err.message);
    cg_hemesh_free(strict);
    /* its counts as a file are those of the repaired structure */
    cg_hemesh_input_counts c;
    CHECK(cg_hemesh_input_counts_compute(once, &c) == CG_OK);
    CHECK_MSG(c.vertices == st.vertices && c.edges == st.edges && c.faces == st.faces
                  && c.components == st.components,
              "%s %d: repaired file V %zu E %zu F %zu C %zu, structure V %zu E %zu F %zu C %zu",
              name, trial, c.vertices, c.edges, c.faces, c.components, st.vertices, st.edges,
              st.faces, st.components);
    if (closed)
        CHECK_MSG(st.boundary_loops == 0, "%s %d: %zu boundary loops after repair", name, trial,
                  st.boundary_loops);
    cg_hemesh_stats st2;
    cg_mesh *twice = repair(name, trial, once, &rep, &st2);
    CHECK_MSG(twice && same_mesh(once, twice), "%s %d: a second repair changed the mesh", name,
              trial);
    CHECK_MSG(rep.bad_face_count + rep.flipped_face_count + rep.cut_edge_count
                      + rep.added_vertex_count + rep.split_edge_count + rep.nonmanifold_edge_count
                      + rep.nonmanifold_vertex_count + rep.misoriented_edge_count
                  == 0,
              "%s %d: a second repair still found defects", name, trial);
    cg_hemesh_report_clear(&rep);
    cg_mesh_free(twice);
    cg_mesh_free(once);
}

/* ---- inputs ------------------------------------------------------------- */

static void copy_into(shape *s, const cg_mesh *m)
{
    for (size_t v = 0; v < m->vertex_count; v++)
        shape_vertex(s, m->positions[v].x, m->positions[v].y, m->positions[v].z);
    for (size_t f = 0; f < m->face_count; f++)
        shape_face(s, m->face_indices + m->face_offsets[f],
                   m->face_offsets[f + 1] - m->face_offsets[f]);
}

/* A closed or open base surface with random defects added. */
static cg_mesh *damaged(check_rng *rng, int trial)
{
    cg_mesh *base = trial % 3 == 0   ? shape_torus(6 + trial % 4, 4 + trial % 3, trial % 2)
                    : trial % 3 == 1 ? shape_cube(trial % 2)
                                     : shape_grid(3 + trial % 3, 3, 1);
    shape s;
    memset(&s, 0, sizeof s);
    copy_into(&s, base);
    size_t F = base->face_count;
    cg_mesh_free(base);
    int defects = (int)check_rng_int(rng, 1, 6);
    for (int d = 0; d < defects; d++) {
        uint32_t f = (uint32_t)check_rng_int(rng, 0, (long long)F - 1);
        uint32_t begin = s.offsets[f], n = s.offsets[f + 1] - begin;
        uint32_t v[8];
        memcpy(v, s.indices + begin, n * sizeof *v);
        uint32_t k = (uint32_t)check_rng_int(rng, 0, n - 1);
        uint32_t a = v[k], b = v[(k + 1) % n];
        uint32_t fresh = (uint32_t)s.vertex_count;
        cg_vec3 pa = s.positions[a];
        switch (check_rng_int(rng, 0, 4)) {
        case 0: /* the same face again */ shape_face(&s, v, n); break;
        case 1: /* the face reversed */
            for (uint32_t i = 0; i < n / 2; i++) {
                uint32_t t = v[i];
                v[i] = v[n - 1 - i];
                v[n - 1 - i] = t;
            }
            shape_face(&s, v, n);
            break;
        case 2: /* a fin: a third face on edge (a, b), either way round */
            shape_vertex(&s, pa.x + check_rng_range(rng, -1, 1), pa.y + check_rng_range(rng, -1, 1),
                         pa.z + check_rng_range(rng, -1, 1));
            if (check_rng_next(rng) & 1)
                shape_face3(&s, a, b, fresh);
            else
                shape_face3(&s, b, a, fresh);
            break;
        case 3: /* a bow-tie: a triangle touching the surface at a */
            shape_vertex(&s, pa.x + 1, pa.y + check_rng_range(rng, -1, 1), pa.z + 2);
            shape_vertex(&s, pa.x - 1, pa.y + check_rng_range(rng, -1, 1), pa.z + 2);
            shape_face3(&s, a, fresh, fresh + 1);
            break;
        default: /* a face joining two existing vertices to a far one */
            shape_face3(&s, a, b, (uint32_t)check_rng_int(rng, 0, (long long)fresh - 1));
            break;
        }
    }
    return shape_finish(&s);
}

/* Faces of random size over a few vertices on a small grid. */
static cg_mesh *soup(check_rng *rng, int trial)
{
    shape s;
    memset(&s, 0, sizeof s);
    size_t V = (size_t)check_rng_int(rng, 3, 12), F = (size_t)check_rng_int(rng, 1, 14);
    for (size_t v = 0; v < V; v++)
        shape_vertex(&s, (double)check_rng_int(rng, 0, 2), (double)check_rng_int(rng, 0, 2),
                     (double)check_rng_int(rng, 0, 2));
    for (size_t f = 0; f < F; f++) {
        uint32_t v[6], n = (uint32_t)check_rng_int(rng, 2, 6);
        for (uint32_t i = 0; i < n; i++)
            v[i] = (uint32_t)check_rng_int(rng, 0, (long long)V - 1 + (trial % 5 == 0));
        shape_face(&s, v, n);
    }
    return shape_finish(&s);
}

static void test_damaged(void)
{
    check_rng rng = {1812};
    for (int trial = 0; trial < 600; trial++) {
        cg_mesh *m = damaged(&rng, trial);
        check_counts("damaged", trial, m);
        check_repair("damaged", trial, m, 0);
        cg_mesh_free(m);
    }
}

static void test_soups(void)
{
    check_rng rng = {77};
    for (int trial = 0; trial < 3000; trial++) {
        cg_mesh *m = soup(&rng, trial);
        check_counts("soup", trial, m);
        check_repair("soup", trial, m, 0);
        cg_mesh_free(m);
    }
}

/* Voxel solids touching along edges and at corners: the repaired surface
 * is closed. */
static void test_voxels(void)
{
    check_rng rng = {4242};
    for (int trial = 0; trial < 200; trial++) {
        char cells[4 * 4 * 3 + 1];
        for (int i = 0; i < 48; i++)
            cells[i] = check_rng_next(&rng) % 2 ? '#' : '.';
        cells[48] = 0;
        cg_mesh *m = shape_voxels(cells, 4, 4, 3, trial % 2);
        if (m->face_count) {
            check_counts("voxels", trial, m);
            check_repair("voxels", trial, m, 1);
        }
        cg_mesh_free(m);
    }
}

/* The cases of the definition, counted by hand. */
static void test_small_cases(void)
{
    /* a triangle and its reversed copy on one edge of a square of two
     * triangles: 5 distinct pairs, one component */
    shape s;
    memset(&s, 0, sizeof s);
    shape_vertex(&s, 0, 0, 0);
    shape_vertex(&s, 1, 0, 0);
    shape_vertex(&s, 1, 1, 0);
    shape_vertex(&s, 0, 1, 0);
    shape_face3(&s, 0, 1, 2);
    shape_face3(&s, 0, 2, 3);
    shape_face3(&s, 0, 2, 1);
    cg_mesh *m = shape_finish(&s);
    cg_hemesh_input_counts c;
    CHECK(cg_hemesh_input_counts_compute(m, &c) == CG_OK);
    CHECK_EQ_INT(c.vertices, 4);
    CHECK_EQ_INT(c.edges, 5);
    CHECK_EQ_INT(c.faces, 3);
    CHECK_EQ_INT(c.components, 1);
    CHECK_EQ_INT(c.euler_characteristic, 2);
    check_repair("face and reversed copy", 0, m, 0);
    cg_mesh_free(m);
    /* two cubes sharing an edge stay two closed cubes */
    m = shape_voxels("#..#", 2, 2, 1, 0);
    CHECK(cg_hemesh_input_counts_compute(m, &c) == CG_OK);
    CHECK_EQ_INT(c.vertices, 14);
    CHECK_EQ_INT(c.components, 1);
    cg_hemesh_report rep;
    cg_hemesh_stats st;
    cg_mesh *once = repair("two cubes", 0, m, &rep, &st);
    CHECK_EQ_INT(st.components, 2);
    CHECK_EQ_INT(st.boundary_loops, 0);
    CHECK_EQ_INT(st.genus, 0);
    CHECK_EQ_INT(rep.split_edge_count, 0);
    cg_hemesh_report_clear(&rep);
    cg_mesh_free(once);
    cg_mesh_free(m);
    /* a Moebius strip of 8 quads: not orientable, cut once and oriented */
    memset(&s, 0, sizeof s);
    for (int i = 0; i < 8; i++) {
        double t = 3.14159265358979 * i / 8;
        shape_vertex(&s, cos(2 * t) * (2 + cos(t)), sin(2 * t) * (2 + cos(t)), sin(t));
        shape_vertex(&s, cos(2 * t) * (2 - cos(t)), sin(2 * t) * (2 - cos(t)), -sin(t));
    }
    for (uint32_t i = 0; i < 8; i++) {
        uint32_t a = 2 * i, b = 2 * i + 1, c = i < 7 ? 2 * i + 3 : 0, d = i < 7 ? 2 * i + 2 : 1;
        shape_quad(&s, a, b, c, d, 0);
    }
    m = shape_finish(&s);
    CHECK(cg_hemesh_input_counts_compute(m, &c) == CG_OK);
    CHECK_EQ_INT(c.edges, 24);
    CHECK_EQ_INT(c.euler_characteristic, 0);
    once = repair("Moebius", 0, m, &rep, &st);
    CHECK(!rep.orientable);
    cg_hemesh_report_clear(&rep);
    cg_mesh_free(once);
    check_repair("Moebius", 0, m, 0);
    cg_mesh_free(m);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_small_cases);
    CHECK_GROUP(test_damaged);
    CHECK_GROUP(test_soups);
    CHECK_GROUP(test_voxels);
    return check_finish();
}
