/* The half-edge structure: building, invariants, traversals against brute
 * force over the face list, counts and genus, bad input. */
#include "check.h"
#include "hemesh_shapes.h"

#include "cg/hemesh.h"

#include <string.h>

static cg_hemesh *build_ok(const cg_mesh *mesh, unsigned flags)
{
    cg_hemesh *h = NULL;
    cg_error err;
    cg_status s = cg_hemesh_build(mesh, flags, &h, NULL, &err);
    CHECK_MSG(s == CG_OK, "build failed: %s", err.message);
    if (h) {
        cg_status v = cg_hemesh_validate(h, &err);
        CHECK_MSG(v == CG_OK, "invalid after build: %s", err.message);
    }
    return h;
}

static void check_stats(const char *name, const cg_hemesh *h, size_t V, size_t E, size_t F,
                        size_t loops, size_t components, long genus)
{
    cg_hemesh_stats st;
    CHECK(cg_hemesh_stats_compute(h, &st, NULL, NULL) == CG_OK);
    CHECK_MSG(st.vertices == V && st.edges == E && st.faces == F,
              "%s: V E F = %zu %zu %zu, expected %zu %zu %zu", name, st.vertices, st.edges,
              st.faces, V, E, F);
    CHECK_MSG(st.boundary_loops == loops, "%s: %zu boundary loops, expected %zu", name,
              st.boundary_loops, loops);
    CHECK_MSG(st.components == components, "%s: %zu components, expected %zu", name, st.components,
              components);
    CHECK_MSG(st.genus == genus, "%s: genus %ld, expected %ld", name, st.genus, genus);
    CHECK_EQ_INT(st.euler_characteristic, (long)V - (long)E + (long)F);
}

/* ---- traversals against the face list ------------------------------------ */

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* For every vertex: neighbours, faces and valence from the structure equal
 * those computed by brute force from the input faces; clockwise order is
 * the reverse of counter-clockwise order; every face loop equals the input
 * face up to rotation; face neighbours share an edge. */
static void check_traversals(const char *name, const cg_mesh *mesh, const cg_hemesh *h)
{
    size_t V = mesh->vertex_count;
    uint32_t a[256], b[256], c[256];
    int failures = 0;
    for (size_t v = 0; v < V && failures < 3; v++) {
        /* brute force: neighbours and faces of v */
        size_t nn = 0, nf = 0;
        uint32_t nb[256], fc[256];
        for (size_t f = 0; f < mesh->face_count; f++) {
            uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
            for (uint32_t k = begin; k < end; k++) {
                if (mesh->face_indices[k] != v)
                    continue;
                fc[nf++] = (uint32_t)f;
                uint32_t next = mesh->face_indices[k + 1 < end ? k + 1 : begin];
                uint32_t prev = mesh->face_indices[k > begin ? k - 1 : end - 1];
                nb[nn++] = next;
                nb[nn++] = prev;
            }
        }
        qsort(nb, nn, sizeof *nb, cmp_u32);
        size_t u = 0;
        for (size_t i = 0; i < nn; i++)
            if (!u || nb[u - 1] != nb[i])
                nb[u++] = nb[i];
        nn = u;
        size_t n1 = cg_hemesh_vertex_neighbors(h, (uint32_t)v, 1, a, 256);
        size_t n2 = cg_hemesh_vertex_neighbors(h, (uint32_t)v, -1, b, 256);
        size_t n3 = cg_hemesh_vertex_faces(h, (uint32_t)v, 1, c, 256);
        CHECK_EQ_INT(n1, nn);
        CHECK_EQ_INT(n2, nn);
        CHECK_EQ_INT(cg_hemesh_valence(h, (uint32_t)v), nn);
        CHECK_EQ_INT(n3, nf);
        if (n1 != nn || n3 != nf) {
            failures++;
            continue;
        }
        /* cw is ccw reversed: b = a[0], a[n-1], ..., a[1] */
        int reversed = n1 == 0 || b[0] == a[0];
        for (size_t i = 1; i < n1 && reversed; i++)
            reversed = b[i] == a[n1 - i];
        CHECK_MSG(reversed,
                  "%s: vertex %zu: clockwise ring is not the counter-clockwise one reversed", name,
                  v);
        qsort(a, n1, sizeof *a, cmp_u32);
        CHECK_MSG(memcmp(a, nb, nn * sizeof *a) == 0, "%s: vertex %zu: wrong neighbours", name, v);
        qsort(c, n3, sizeof *c, cmp_u32);
        CHECK_MSG(memcmp(c, fc, nf * sizeof *c) == 0, "%s: vertex %zu: wrong faces", name, v);
    }
    /* the umbrella average is the mean of the neighbours */
    cg_vec3 *avg = malloc((V ? V : 1) * sizeof *avg);
    CHECK(cg_hemesh_neighbor_average(h, avg) == CG_OK);
    for (size_t v = 0; v < V; v++) {
        size_t n = cg_hemesh_vertex_neighbors(h, (uint32_t)v, 1, a, 256);
        cg_vec3 mean = h->positions[v];
        if (n) {
            mean = cg_vec3_make(0, 0, 0);
            for (size_t i = 0; i < n; i++)
                mean = cg_vec3_add(mean, cg_vec3_scale(h->positions[a[i]], 1.0 / (double)n));
        }
        CHECK(cg_vec3_length(cg_vec3_sub(mean, avg[v])) < 1e-12);
    }
    free(avg);
    /* face loops equal the input faces (the build keeps face numbers) */
    for (size_t f = 0; f < mesh->face_count; f++) {
        uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
        size_t n = cg_hemesh_face_vertices(h, (uint32_t)f, a, 256);
        CHECK_EQ_INT(n, end - begin);
        if (n != end - begin)
            continue;
        size_t shift = 0;
        while (shift < n && a[shift] != mesh->face_indices[begin])
            shift++;
        int same = shift < n;
        for (size_t i = 0; i < n && same; i++)
            same = a[(shift + i) % n] == mesh->face_indices[begin + i];
        CHECK_MSG(same, "%s: face %zu loop differs from the input", name, f);
        size_t k = cg_hemesh_face_neighbors(h, (uint32_t)f, b, 256);
        for (size_t i = 0; i < k; i++) {
            /* g shares an edge (two consecutive vertices) with f */
            size_t m = cg_hemesh_face_vertices(h, b[i], c, 256);
            int shared = 0;
            for (size_t x = 0; x < n && !shared; x++)
                for (size_t y = 0; y < m && !shared; y++)
                    shared = a[x] == c[(y + 1) % m] && a[(x + 1) % n] == c[y];
            CHECK_MSG(shared, "%s: face %zu and its neighbour %u share no edge", name, f, b[i]);
        }
    }
}

/* ---- closed shapes and genus ------------------------------------------------ */

static void test_shapes(void)
{
    struct {
        const char *name;
        cg_mesh *mesh;
        size_t V, E, F, loops, components;
        long genus;
    } cases[] = {
        {"tetrahedron", shape_tetrahedron(), 4, 6, 4, 0, 1, 0},
        {"cube", shape_cube(0), 8, 12, 6, 0, 1, 0},
        {"cube triangles", shape_cube(1), 8, 18, 12, 0, 1, 0},
        {"grid 5x3", shape_grid(5, 3, 0), 24, 38, 15, 1, 1, 0},
        {"grid 4x4 triangles", shape_grid(4, 4, 1), 25, 56, 32, 1, 1, 0},
        {"torus", shape_torus(8, 5, 0), 40, 80, 40, 0, 1, 1},
        {"torus triangles", shape_torus(7, 4, 1), 28, 84, 56, 0, 1, 1},
        {"voxel", shape_voxels("#", 1, 1, 1, 0), 8, 12, 6, 0, 1, 0},
        {"ring", shape_ring(0), 32, 64, 32, 0, 1, 1},
        {"double ring", shape_double_ring(1), 0, 0, 0, 0, 1, 2},
        {"icosphere", shape_icosphere(2), 162, 480, 320, 0, 1, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        cg_mesh *mesh = cases[i].mesh;
        CHECK(mesh != NULL);
        if (!mesh)
            continue;
        cg_hemesh *h = build_ok(mesh, 0);
        if (!h) {
            cg_mesh_free(mesh);
            continue;
        }
        if (cases[i].V == 0) { /* counts not worked by hand: only the genus */
            cg_hemesh_stats st;
            CHECK(cg_hemesh_stats_compute(h, &st, NULL, NULL) == CG_OK);
            CHECK_EQ_INT(st.genus, cases[i].genus);
            CHECK_EQ_INT(st.euler_characteristic, 2 - 2 * cases[i].genus);
            CHECK_EQ_INT(st.components, 1);
        } else {
            check_stats(cases[i].name, h, cases[i].V, cases[i].E, cases[i].F, cases[i].loops,
                        cases[i].components, cases[i].genus);
        }
        check_traversals(cases[i].name, mesh, h);
        /* round trip through the indexed mesh keeps every face */
        cg_mesh *back = NULL;
        CHECK(cg_hemesh_to_mesh(h, &back) == CG_OK);
        if (back) {
            CHECK_EQ_INT(back->vertex_count, mesh->vertex_count);
            CHECK_EQ_INT(back->face_count, mesh->face_count);
            CHECK(memcmp(back->positions, mesh->positions,
                         mesh->vertex_count * sizeof *mesh->positions)
                  == 0);
            check_traversals("round trip", back, h);
            cg_mesh_free(back);
        }
        cg_hemesh_free(h);
        cg_mesh_free(mesh);
    }
}

/* Two disjoint shapes of different genus: genus is -1 ("mixed") and the
 * per-component list holds both. */
static void test_components(void)
{
    cg_mesh *a = shape_torus(6, 4, 0), *b = shape_cube(0);
    cg_mesh *m = NULL;
    CHECK(cg_mesh_create(&m, a->vertex_count + b->vertex_count + 2, a->face_count + b->face_count,
                         a->face_offsets[a->face_count] + b->face_offsets[b->face_count], 0)
          == CG_OK);
    memcpy(m->positions, a->positions, a->vertex_count * sizeof *a->positions);
    memcpy(m->positions + a->vertex_count, b->positions, b->vertex_count * sizeof *b->positions);
    size_t na = a->face_offsets[a->face_count];
    memcpy(m->face_indices, a->face_indices, na * sizeof *m->face_indices);
    for (size_t k = 0; k < b->face_offsets[b->face_count]; k++)
        m->face_indices[na + k] = b->face_indices[k] + (uint32_t)a->vertex_count;
    for (size_t f = 0; f <= a->face_count; f++)
        m->face_offsets[f] = a->face_offsets[f];
    for (size_t f = 1; f <= b->face_count; f++)
        m->face_offsets[a->face_count + f] = b->face_offsets[f] + (uint32_t)na;
    /* the last two vertices are isolated */
    cg_hemesh_report rep;
    cg_hemesh *h = NULL;
    CHECK(cg_hemesh_build(m, 0, &h, &rep, NULL) == CG_OK);
    CHECK_EQ_INT(rep.isolated_vertex_count, 2);
    CHECK(cg_hemesh_validate(h, NULL) == CG_OK);
    cg_hemesh_stats st;
    long *genus = NULL;
    size_t count = 0;
    CHECK(cg_hemesh_stats_compute(h, &st, &genus, &count) == CG_OK);
    CHECK_EQ_INT(st.components, 4);
    CHECK_EQ_INT(st.isolated_vertices, 2);
    CHECK_EQ_INT(st.genus, -1);
    CHECK_EQ_INT(count, 2);
    if (count == 2) {
        CHECK_EQ_INT(genus[0], 1);
        CHECK_EQ_INT(genus[1], 0);
    }
    CHECK_EQ_INT(st.euler_characteristic, 0 + 2 + 2);
    free(genus);
    cg_hemesh_report_clear(&rep);
    cg_hemesh_free(h);
    cg_mesh_free(a);
    cg_mesh_free(b);
    cg_mesh_free(m);
}

/* ---- geometry ------------------------------------------------------------------ */

static void test_geometry(void)
{
    cg_mesh *mesh = shape_cube(0);
    cg_hemesh *h = build_ok(mesh, 0);
    for (uint32_t f = 0; f < 6; f++) {
        CHECK_NEAR(cg_hemesh_face_area(h, f), 4.0, 1e-12);
        /* outward: the normal points the same way as the face centre */
        cg_vec3 n = cg_hemesh_face_normal(h, f), centre = {0, 0, 0};
        uint32_t v[4];
        cg_hemesh_face_vertices(h, f, v, 4);
        for (int i = 0; i < 4; i++)
            centre = cg_vec3_add(centre, cg_vec3_scale(h->positions[v[i]], 0.25));
        CHECK_NEAR(cg_vec3_dot(n, centre), 1.0, 1e-12);
    }
    for (uint32_t v = 0; v < 8; v++) {
        cg_vec3 n = cg_hemesh_vertex_normal(h, v);
        cg_vec3 expect = cg_vec3_normalize(h->positions[v]);
        CHECK_NEAR(cg_vec3_dot(n, expect), 1.0, 1e-12);
    }
    CHECK(cg_hemesh_compute_normals(h) == CG_OK);
    CHECK_NEAR(cg_vec3_dot(h->normals[3], cg_vec3_normalize(h->positions[3])), 1.0, 1e-12);
    cg_hemesh_free(h);
    cg_mesh_free(mesh);
    /* the icosphere's area approaches 4 pi from below */
    mesh = shape_icosphere(3);
    h = build_ok(mesh, 0);
    double area = 0;
    for (uint32_t f = 0; f < h->face_count; f++)
        area += cg_hemesh_face_area(h, f);
    CHECK(area < 4 * CG_PI && area > 0.97 * 4 * CG_PI);
    cg_hemesh_free(h);
    cg_mesh_free(mesh);
}

/* ---- attributes survive build and conversion ------------------------------------- */

static void test_attributes(void)
{
    cg_mesh *src = shape_grid(3, 2, 1);
    cg_mesh *mesh = NULL;
    CHECK(cg_mesh_create(&mesh, src->vertex_count, src->face_count,
                         src->face_offsets[src->face_count],
                         CG_MESH_NORMALS | CG_MESH_TEXCOORDS | CG_MESH_COLORS | CG_MESH_FACE_COLORS)
          == CG_OK);
    memcpy(mesh->positions, src->positions, src->vertex_count * sizeof *src->positions);
    memcpy(mesh->face_offsets, src->face_offsets,
           (src->face_count + 1) * sizeof *src->face_offsets);
    memcpy(mesh->face_indices, src->face_indices,
           src->face_offsets[src->face_count] * sizeof(uint32_t));
    for (size_t v = 0; v < mesh->vertex_count; v++) {
        mesh->normals[v] = cg_vec3_make(0, 0, 1);
        mesh->texcoords[v] = cg_vec2_make(mesh->positions[v].x / 3, mesh->positions[v].y / 2);
        mesh->colors[v] = (cg_rgbaf){(float)v / 12.0f, 0.5f, 0.25f, 1.0f};
    }
    for (size_t f = 0; f < mesh->face_count; f++)
        mesh->face_colors[f] = (cg_rgbaf){0.1f * (float)f, 0, 0, 1};
    cg_hemesh *h = build_ok(mesh, 0);
    cg_mesh *back = NULL;
    CHECK(cg_hemesh_to_mesh(h, &back) == CG_OK);
    CHECK(back->normals && back->texcoords && back->colors && back->face_colors);
    CHECK(memcmp(back->texcoords, mesh->texcoords, mesh->vertex_count * sizeof *mesh->texcoords)
          == 0);
    CHECK(memcmp(back->colors, mesh->colors, mesh->vertex_count * sizeof *mesh->colors) == 0);
    CHECK(memcmp(back->normals, mesh->normals, mesh->vertex_count * sizeof *mesh->normals) == 0);
    CHECK(memcmp(back->face_colors, mesh->face_colors, mesh->face_count * sizeof *mesh->face_colors)
          == 0);
    /* an edge split averages the attributes of the edge's ends */
    uint32_t e = 0, v;
    cg_vec2 ta = h->texcoords[h->halfedges[0].origin], tb = h->texcoords[h->halfedges[1].origin];
    CHECK(cg_hemesh_split_edge(h, e, cg_vec3_make(0, 0, 0), &v) == CG_OK);
    CHECK_NEAR(h->texcoords[v].x, 0.5 * (ta.x + tb.x), 1e-12);
    CHECK_NEAR(h->texcoords[v].y, 0.5 * (ta.y + tb.y), 1e-12);
    CHECK(cg_hemesh_validate(h, NULL) == CG_OK);
    cg_mesh_free(back);
    cg_hemesh_free(h);
    cg_mesh_free(mesh);
    cg_mesh_free(src);
}

/* ---- bad input ---------------------------------------------------------------------- */

static cg_mesh *faces_mesh(size_t vertex_count, const uint32_t *sizes, size_t face_count,
                           const uint32_t *indices)
{
    size_t total = 0;
    for (size_t f = 0; f < face_count; f++)
        total += sizes[f];
    cg_mesh *m = NULL;
    if (cg_mesh_create(&m, vertex_count, face_count, total, 0) != CG_OK)
        return NULL;
    for (size_t v = 0; v < vertex_count; v++)
        m->positions[v] = cg_vec3_make((double)(v % 3), (double)(v / 3 % 3), (double)(v / 9));
    for (size_t f = 0; f < face_count; f++)
        m->face_offsets[f + 1] = m->face_offsets[f] + sizes[f];
    if (total)
        memcpy(m->face_indices, indices, total * sizeof *indices);
    return m;
}

static void expect_error(const char *name, const cg_mesh *m, unsigned flags, cg_status want,
                         const char *words)
{
    cg_hemesh *h = (cg_hemesh *)1;
    cg_error err;
    cg_error_clear(&err);
    cg_status s = cg_hemesh_build(m, flags, &h, NULL, &err);
    CHECK_MSG(s == want, "%s: status %d, expected %d (%s)", name, (int)s, (int)want, err.message);
    CHECK(h == NULL);
    CHECK_MSG(strstr(err.message, words) != NULL, "%s: message '%s' lacks '%s'", name, err.message,
              words);
}

static void test_bad_input(void)
{
    uint32_t tri[] = {3};
    /* out of range */
    uint32_t i1[] = {0, 1, 7};
    cg_mesh *m = faces_mesh(3, tri, 1, i1);
    expect_error("out of range", m, 0, CG_EFORMAT, "refers to vertex 7");
    expect_error("out of range, dropped", m, CG_HEMESH_DROP_BAD_FACES, CG_EEMPTY,
                 "no usable faces");
    cg_mesh_free(m);
    /* repeated vertex */
    uint32_t sizes2[] = {3, 4};
    uint32_t i2[] = {0, 1, 2, 0, 2, 1, 2};
    m = faces_mesh(4, sizes2, 2, i2);
    expect_error("repeated", m, 0, CG_EFORMAT, "face 1 repeats vertex");
    {
        cg_hemesh *h = NULL;
        cg_hemesh_report rep;
        CHECK(cg_hemesh_build(m, CG_HEMESH_DROP_BAD_FACES, &h, &rep, NULL) == CG_OK);
        CHECK_EQ_INT(rep.bad_face_count, 1);
        CHECK(rep.bad_face_count == 1 && rep.bad_faces[0] == 1);
        CHECK_EQ_INT(rep.isolated_vertex_count, 1);
        CHECK(h && h->live_faces == 1 && cg_hemesh_validate(h, NULL) == CG_OK);
        cg_hemesh_report_clear(&rep);
        cg_hemesh_free(h);
    }
    cg_mesh_free(m);
    /* too few corners */
    uint32_t sizes3[] = {2, 3};
    uint32_t i3[] = {0, 1, 0, 1, 2};
    m = faces_mesh(3, sizes3, 2, i3);
    expect_error("two corners", m, 0, CG_EFORMAT, "has 2 corners");
    cg_mesh_free(m);
    /* zero faces */
    m = faces_mesh(5, NULL, 0, NULL);
    expect_error("no faces", m, CG_HEMESH_REPAIR, CG_EEMPTY, "no faces");
    cg_mesh_free(m);
    expect_error("null", NULL, 0, CG_EINVAL, "no mesh");
    /* three triangles on edge (0, 1): a book */
    uint32_t sizes4[] = {3, 3, 3};
    uint32_t i4[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    m = faces_mesh(5, sizes4, 3, i4);
    expect_error("book", m, 0, CG_EFORMAT, "edge (0, 1) is on more than two faces");
    {
        cg_hemesh *h = NULL;
        cg_hemesh_report rep;
        CHECK(cg_hemesh_build(m, CG_HEMESH_SPLIT_NONMANIFOLD, &h, &rep, NULL) == CG_OK);
        CHECK_EQ_INT(rep.nonmanifold_edge_count, 1);
        CHECK(rep.nonmanifold_edge_count == 1 && rep.nonmanifold_edges[0] == 0
              && rep.nonmanifold_edges[1] == 1);
        CHECK_EQ_INT(rep.cut_edge_count, 1);
        CHECK(h && cg_hemesh_validate(h, NULL) == CG_OK);
        /* the third sheet is separated: its ends are split off */
        CHECK_EQ_INT(rep.added_vertex_count, 2);
        CHECK_EQ_INT(h->live_vertices, 7);
        CHECK_EQ_INT(h->live_faces, 3);
        cg_hemesh_stats st;
        cg_hemesh_stats_compute(h, &st, NULL, NULL);
        CHECK_EQ_INT(st.components, 2);
        CHECK_EQ_INT(st.complex_vertices, 0);
        cg_hemesh_report_clear(&rep);
        cg_hemesh_free(h);
    }
    cg_mesh_free(m);
    /* bowtie: two triangles sharing vertex 0 only */
    uint32_t sizes5[] = {3, 3};
    uint32_t i5[] = {0, 1, 2, 0, 3, 4};
    m = faces_mesh(5, sizes5, 2, i5);
    expect_error("bowtie", m, 0, CG_EFORMAT, "vertex 0 form more than one fan");
    {
        cg_hemesh *h = NULL;
        cg_hemesh_report rep;
        CHECK(cg_hemesh_build(m, CG_HEMESH_SPLIT_NONMANIFOLD, &h, &rep, NULL) == CG_OK);
        CHECK_EQ_INT(rep.nonmanifold_vertex_count, 1);
        CHECK(rep.nonmanifold_vertex_count == 1 && rep.nonmanifold_vertices[0] == 0);
        CHECK_EQ_INT(rep.added_vertex_count, 1);
        CHECK(h && h->live_vertices == 6 && cg_hemesh_validate(h, NULL) == CG_OK);
        CHECK(h && h->positions[5].x == h->positions[0].x);
        cg_hemesh_report_clear(&rep);
        cg_hemesh_free(h);
    }
    cg_mesh_free(m);
    /* two triangles traversing edge (0, 1) the same way */
    uint32_t i6[] = {0, 1, 2, 0, 1, 3};
    m = faces_mesh(4, sizes5, 2, i6);
    expect_error("misoriented", m, 0, CG_EFORMAT, "same direction");
    {
        cg_hemesh *h = NULL;
        cg_hemesh_report rep;
        CHECK(cg_hemesh_build(m, CG_HEMESH_ORIENT, &h, &rep, NULL) == CG_OK);
        CHECK_EQ_INT(rep.misoriented_edge_count, 1);
        CHECK_EQ_INT(rep.flipped_face_count, 1);
        CHECK_EQ_INT(rep.orientable, 1);
        CHECK(h && cg_hemesh_validate(h, NULL) == CG_OK);
        CHECK(h && h->live_edges == 5);
        cg_hemesh_report_clear(&rep);
        cg_hemesh_free(h);
    }
    cg_mesh_free(m);
}

/* A cube whose faces are randomly reversed is reoriented to a closed sphere;
 * a Moebius strip is found not orientable and is cut. */
static void test_orientation(void)
{
    check_rng rng = {12345};
    for (int trial = 0; trial < 20; trial++) {
        cg_mesh *m = trial % 2 ? shape_torus(6, 5, 1) : shape_cube(trial % 4 == 0);
        size_t flipped = 0;
        int keep_first = 1;
        for (size_t f = 0; f < m->face_count; f++) {
            if (check_rng_next(&rng) % 3 || (f == 0 && keep_first))
                continue;
            uint32_t *lo = m->face_indices + m->face_offsets[f],
                     *hi = m->face_indices + m->face_offsets[f + 1] - 1;
            while (lo < hi) {
                uint32_t t = *lo;
                *lo++ = *hi;
                *hi-- = t;
            }
            flipped++;
        }
        cg_hemesh *h = NULL;
        cg_hemesh_report rep;
        cg_error err;
        cg_status s = cg_hemesh_build(m, CG_HEMESH_ORIENT, &h, &rep, &err);
        CHECK_MSG(s == CG_OK, "reorient: %s", err.message);
        if (s == CG_OK) {
            CHECK_EQ_INT(rep.flipped_face_count, flipped);
            CHECK(cg_hemesh_validate(h, NULL) == CG_OK);
            cg_hemesh_stats st;
            cg_hemesh_stats_compute(h, &st, NULL, NULL);
            CHECK_EQ_INT(st.boundary_loops, 0);
            CHECK_EQ_INT(st.genus, trial % 2);
        }
        cg_hemesh_report_clear(&rep);
        cg_hemesh_free(h);
        cg_mesh_free(m);
    }
    /* Moebius strip: a 1 x n strip of quads glued with a half twist */
    shape sh = {0};
    int n = 8;
    for (int i = 0; i < n; i++) {
        double u = 2 * CG_PI * i / n, t = u / 2;
        for (int side = -1; side <= 1; side += 2) {
            double r = 1 + 0.3 * side * cos(t);
            shape_vertex(&sh, r * cos(u), r * sin(u), 0.3 * side * sin(t));
        }
    }
    for (int i = 0; i < n; i++) {
        uint32_t a = (uint32_t)(2 * i), b = a + 1;
        uint32_t c = (uint32_t)(2 * ((i + 1) % n)), d = c + 1;
        if (i == n - 1) { /* the twist swaps the sides */
            uint32_t t = c;
            c = d;
            d = t;
        }
        shape_quad(&sh, a, c, d, b, 0);
    }
    cg_mesh *m = shape_finish(&sh);
    expect_error("moebius", m, CG_HEMESH_ORIENT, CG_EFORMAT, "not orientable");
    cg_hemesh *h = NULL;
    cg_hemesh_report rep;
    CHECK(cg_hemesh_build(m, CG_HEMESH_REPAIR, &h, &rep, NULL) == CG_OK);
    CHECK_EQ_INT(rep.orientable, 0);
    CHECK(h && cg_hemesh_validate(h, NULL) == CG_OK);
    cg_hemesh_report_clear(&rep);
    cg_hemesh_free(h);
    cg_mesh_free(m);
}

/* Random polygon soups: anything may be wrong; the strict build either
 * succeeds with a valid structure or reports an error, and the repairing
 * build gives a valid structure or CG_EEMPTY. */
static void test_random_soups(void)
{
    check_rng rng = {777};
    for (int trial = 0; trial < 300; trial++) {
        size_t V = (size_t)check_rng_int(&rng, 1, 12), F = (size_t)check_rng_int(&rng, 1, 14);
        uint32_t sizes[14], idx[14 * 6];
        size_t k = 0;
        for (size_t f = 0; f < F; f++) {
            sizes[f] = (uint32_t)check_rng_int(&rng, 2, 6);
            for (uint32_t i = 0; i < sizes[f]; i++)
                idx[k++] = (uint32_t)check_rng_int(&rng, 0, (long long)V + (trial % 7 == 0));
        }
        cg_mesh *m = faces_mesh(V, sizes, F, idx);
        for (int pass = 0; pass < 2; pass++) {
            cg_hemesh *h = NULL;
            cg_hemesh_report rep;
            cg_error err;
            cg_status s = cg_hemesh_build(m, pass ? CG_HEMESH_REPAIR : 0, &h, &rep, &err);
            if (s == CG_OK) {
                cg_status v = cg_hemesh_validate(h, &err);
                CHECK_MSG(v == CG_OK, "soup %d pass %d: %s", trial, pass, err.message);
                cg_hemesh_stats st;
                CHECK(cg_hemesh_stats_compute(h, &st, NULL, NULL) == CG_OK);
                CHECK_EQ_INT(st.complex_vertices, 0);
                cg_mesh *back = NULL;
                CHECK(cg_hemesh_to_mesh(h, &back) == CG_OK);
                CHECK(back && cg_mesh_validate(back, NULL) == CG_OK);
                cg_mesh_free(back);
            } else {
                CHECK_MSG(pass == 0 || s == CG_EEMPTY, "soup %d: repair failed: %s", trial,
                          err.message);
                CHECK(h == NULL && err.message[0] != 0);
            }
            cg_hemesh_report_clear(&rep);
            cg_hemesh_free(h);
        }
        cg_mesh_free(m);
    }
}

/* Voxel sets with diagonal contacts have non-manifold edges and vertices;
 * split, the surface is manifold and closed. */
static void test_random_voxels(void)
{
    check_rng rng = {4242};
    for (int trial = 0; trial < 40; trial++) {
        char cells[4 * 4 * 3 + 1];
        for (int i = 0; i < 48; i++)
            cells[i] = check_rng_next(&rng) % 2 ? '#' : '.';
        cells[48] = 0;
        cg_mesh *m = shape_voxels(cells, 4, 4, 3, trial % 2);
        if (!m->face_count) {
            cg_mesh_free(m);
            continue;
        }
        cg_hemesh *h = NULL;
        cg_hemesh_report rep;
        cg_error err;
        cg_status s = cg_hemesh_build(m, CG_HEMESH_SPLIT_NONMANIFOLD, &h, &rep, &err);
        CHECK_MSG(s == CG_OK, "voxels %d: %s", trial, err.message);
        if (s == CG_OK) {
            CHECK_MSG(cg_hemesh_validate(h, &err) == CG_OK, "voxels %d: %s", trial, err.message);
            cg_hemesh_stats st;
            cg_hemesh_stats_compute(h, &st, NULL, NULL);
            CHECK_EQ_INT(st.boundary_loops, 0);
            CHECK_EQ_INT(st.complex_vertices, 0);
            CHECK(st.genus >= -1);
            /* a strict build fails exactly when something was split */
            cg_hemesh *strict = NULL;
            cg_status s2 = cg_hemesh_build(m, 0, &strict, NULL, NULL);
            CHECK((s2 == CG_OK)
                  == (rep.nonmanifold_edge_count == 0 && rep.nonmanifold_vertex_count == 0));
            cg_hemesh_free(strict);
        }
        cg_hemesh_report_clear(&rep);
        cg_hemesh_free(h);
        cg_mesh_free(m);
    }
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_shapes);
    CHECK_GROUP(test_components);
    CHECK_GROUP(test_geometry);
    CHECK_GROUP(test_attributes);
    CHECK_GROUP(test_bad_input);
    CHECK_GROUP(test_orientation);
    CHECK_GROUP(test_random_soups);
    CHECK_GROUP(test_random_voxels);
    return check_finish();
}
