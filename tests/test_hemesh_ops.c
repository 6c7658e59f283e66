/* Operations on the half-edge structure (flip, split, collapse, face split,
 * removal) on random meshes with full validation after each, and Loop and
 * Catmull-Clark subdivision against counts and stencils worked by hand. */
#include "check.h"
#include "hemesh_shapes.h"

#include "cg/hemesh.h"

#include <string.h>

static cg_hemesh *build(cg_mesh *mesh)
{
    cg_hemesh *h = NULL;
    cg_error err;
    CHECK_MSG(cg_hemesh_build(mesh, 0, &h, NULL, &err) == CG_OK, "build: %s", err.message);
    cg_mesh_free(mesh);
    return h;
}

static int valid(const cg_hemesh *h, const char *after)
{
    cg_error err;
    cg_status s = cg_hemesh_validate(h, &err);
    CHECK_MSG(s == CG_OK, "invalid after %s: %s", after, err.message);
    return s == CG_OK;
}

static long chi(const cg_hemesh *h)
{
    return (long)h->live_vertices - (long)h->live_edges + (long)h->live_faces;
}

static uint32_t random_live_edge(const cg_hemesh *h, check_rng *rng)
{
    for (int tries = 0; tries < 1000; tries++) {
        uint32_t e = (uint32_t)check_rng_int(rng, 0, (long long)h->halfedge_count / 2 - 1);
        if (!cg_hemesh_edge_is_deleted(h, e))
            return e;
    }
    return CG_HEMESH_NONE;
}

static uint32_t random_live_face(const cg_hemesh *h, check_rng *rng)
{
    for (int tries = 0; tries < 1000 && h->face_count; tries++) {
        uint32_t f = (uint32_t)check_rng_int(rng, 0, (long long)h->face_count - 1);
        if (!cg_hemesh_face_is_deleted(h, f))
            return f;
    }
    return CG_HEMESH_NONE;
}

static int is_triangle_side(const cg_hemesh *h, uint32_t x)
{
    return !cg_hemesh_halfedge_is_boundary(h, x)
           && cg_hemesh_face_size(h, cg_hemesh_face(h, x)) == 3;
}

/* Link condition by brute force: the vertices joined to both ends of h are
 * exactly the opposite corners of the adjacent triangles. */
static int link_condition(const cg_hemesh *h, uint32_t x)
{
    uint32_t u = cg_hemesh_origin(h, x), v = cg_hemesh_dest(h, x);
    uint32_t a[512], b[512];
    size_t na = cg_hemesh_vertex_neighbors(h, u, 1, a, 512);
    size_t nb = cg_hemesh_vertex_neighbors(h, v, 1, b, 512);
    uint32_t c = is_triangle_side(h, x) ? cg_hemesh_origin(h, cg_hemesh_prev(h, x))
                                        : CG_HEMESH_NONE;
    uint32_t y = x ^ 1u;
    uint32_t d = is_triangle_side(h, y) ? cg_hemesh_origin(h, cg_hemesh_prev(h, y))
                                        : CG_HEMESH_NONE;
    for (size_t i = 0; i < na && i < 512; i++)
        for (size_t j = 0; j < nb && j < 512; j++)
            if (a[i] == b[j] && a[i] != c && a[i] != d)
                return 0;
    return 1;
}

/* Random operations, each checked for its effect on V, E, F and chi. */
static void random_operations(const char *name, cg_hemesh *h, int steps, uint64_t seed)
{
    check_rng rng = {seed};
    long chi0 = chi(h);
    int done[7] = {0};
    for (int step = 0; step < steps && h->live_faces > 2; step++) {
        size_t V = h->live_vertices, E = h->live_edges, F = h->live_faces;
        int op = (int)check_rng_int(&rng, 0, 6);
        uint32_t e = random_live_edge(h, &rng);
        if (e == CG_HEMESH_NONE)
            break;
        char what[64];
        snprintf(what, sizeof what, "%s step %d op %d", name, step, op);
        if (op == 0) { /* flip */
            uint32_t a = cg_hemesh_origin(h, 2 * e), b = cg_hemesh_dest(h, 2 * e);
            int tri = is_triangle_side(h, 2 * e) && is_triangle_side(h, 2 * e + 1);
            uint32_t c = tri ? cg_hemesh_origin(h, cg_hemesh_prev(h, 2 * e)) : 0;
            uint32_t d = tri ? cg_hemesh_origin(h, cg_hemesh_prev(h, 2 * e + 1)) : 0;
            cg_status s = cg_hemesh_flip_edge(h, e);
            CHECK(s == CG_OK || !tri || cg_hemesh_find_halfedge(h, c, d) != CG_HEMESH_NONE);
            if (s == CG_OK) {
                done[0]++;
                uint32_t p = cg_hemesh_origin(h, 2 * e), q = cg_hemesh_dest(h, 2 * e);
                CHECK((p == c && q == d) || (p == d && q == c));
                CHECK(cg_hemesh_find_halfedge(h, a, b) == CG_HEMESH_NONE);
            }
            CHECK(h->live_vertices == V && h->live_edges == E && h->live_faces == F);
        } else if (op == 1) { /* split edge */
            int sides = is_triangle_side(h, 2 * e) + is_triangle_side(h, 2 * e + 1);
            cg_vec3 mid = cg_vec3_scale(cg_vec3_add(h->positions[cg_hemesh_origin(h, 2 * e)],
                                                    h->positions[cg_hemesh_dest(h, 2 * e)]),
                                        0.5);
            uint32_t v;
            CHECK(cg_hemesh_split_edge(h, e, mid, &v) == CG_OK);
            done[1]++;
            CHECK_EQ_INT(h->live_vertices, V + 1);
            CHECK_EQ_INT(h->live_edges, E + 1 + (size_t)sides);
            CHECK_EQ_INT(h->live_faces, F + (size_t)sides);
            CHECK_EQ_INT(cg_hemesh_valence(h, v), 2 + sides);
        } else if (op == 2) { /* collapse */
            uint32_t x = 2 * e + (uint32_t)(check_rng_next(&rng) & 1);
            int sides = is_triangle_side(h, x) + is_triangle_side(h, x ^ 1u);
            int ok = cg_hemesh_collapse_ok(h, x);
            if (!link_condition(h, x))
                CHECK_MSG(!ok, "%s: collapse accepted though the link condition fails", what);
            uint32_t u = cg_hemesh_origin(h, x), v = cg_hemesh_dest(h, x);
            size_t degree_u = cg_hemesh_valence(h, u), degree_v = cg_hemesh_valence(h, v);
            cg_status s = cg_hemesh_collapse_edge(h, x);
            CHECK((s == CG_OK) == ok);
            if (s == CG_OK) {
                done[2]++;
                CHECK(cg_hemesh_vertex_is_deleted(h, u));
                CHECK_EQ_INT(h->live_vertices, V - 1);
                CHECK_EQ_INT(h->live_edges, E - 1 - (size_t)sides);
                CHECK_EQ_INT(h->live_faces, F - (size_t)sides);
                CHECK_EQ_INT(cg_hemesh_valence(h, v), degree_u + degree_v - 2 - (size_t)sides);
            } else {
                CHECK(h->live_vertices == V && h->live_edges == E && h->live_faces == F);
            }
        } else if (op == 3) { /* split face */
            uint32_t f = random_live_face(h, &rng);
            if (f == CG_HEMESH_NONE)
                continue;
            size_t k = cg_hemesh_face_size(h, f);
            uint32_t v;
            CHECK(cg_hemesh_split_face(h, f, cg_vec3_make(0, 0, 0), &v) == CG_OK);
            done[3]++;
            CHECK_EQ_INT(h->live_vertices, V + 1);
            CHECK_EQ_INT(h->live_edges, E + k);
            CHECK_EQ_INT(h->live_faces, F + k - 1);
            CHECK_EQ_INT(cg_hemesh_valence(h, v), k);
        } else if (op == 6) { /* split a face along a diagonal */
            uint32_t f = random_live_face(h, &rng);
            if (f == CG_HEMESH_NONE)
                continue;
            uint32_t sides[64];
            size_t k = cg_hemesh_face_halfedges(h, f, sides, 64);
            if (k > 64)
                continue;
            uint32_t p = sides[check_rng_int(&rng, 0, (long long)k - 1)];
            uint32_t q = sides[check_rng_int(&rng, 0, (long long)k - 1)];
            uint32_t u = cg_hemesh_origin(h, p), w = cg_hemesh_origin(h, q);
            int allowed = p != q && cg_hemesh_next(h, p) != q && cg_hemesh_next(h, q) != p
                          && cg_hemesh_find_halfedge(h, u, w) == CG_HEMESH_NONE;
            uint32_t g;
            cg_status s = cg_hemesh_split_face_between(h, p, q, &g);
            CHECK((s == CG_OK) == allowed);
            if (s == CG_OK) {
                done[6]++;
                CHECK_EQ_INT(h->live_edges, E + 1);
                CHECK_EQ_INT(h->live_faces, F + 1);
                CHECK_EQ_INT(cg_hemesh_face_size(h, f) + cg_hemesh_face_size(h, g), k + 2);
                CHECK(cg_hemesh_find_halfedge(h, u, w) != CG_HEMESH_NONE);
            } else {
                CHECK(h->live_edges == E && h->live_faces == F);
            }
        } else if (op == 4 && step % 5 == 0 && F > 8) { /* remove a face (rarely: it changes chi) */
            uint32_t f = random_live_face(h, &rng);
            if (f == CG_HEMESH_NONE)
                continue;
            CHECK(cg_hemesh_remove_face(h, f) == CG_OK);
            CHECK(cg_hemesh_face_is_deleted(h, f));
            CHECK_EQ_INT(h->live_faces, F - 1);
            done[4]++;
            chi0 = chi(h);
        } else if (op == 5 && step % 7 == 0 && F > 8) { /* remove a vertex */
            uint32_t v = cg_hemesh_origin(h, 2 * e);
            size_t nf = cg_hemesh_vertex_faces(h, v, 1, NULL, 0);
            CHECK(cg_hemesh_remove_vertex(h, v) == CG_OK);
            CHECK(cg_hemesh_vertex_is_deleted(h, v));
            CHECK_EQ_INT(h->live_faces, F - nf);
            done[5]++;
            chi0 = chi(h);
        } else {
            continue;
        }
        if (!valid(h, what))
            return;
        CHECK_MSG(chi(h) == chi0, "%s: chi %ld, was %ld", what, chi(h), chi0);
    }
    if (getenv("HEMESH_VERBOSE"))
        fprintf(stderr,
                "%s: flips %d splits %d collapses %d face splits %d face removals %d vertex "
                "removals %d diagonals %d\n",
                name, done[0], done[1], done[2], done[3], done[4], done[5], done[6]);
    CHECK_MSG(done[0] + done[1] + done[2] + done[3] > steps / 4, "%s: too few operations done",
              name);
    /* compaction keeps the counts and the invariants */
    cg_hemesh_stats before, after;
    cg_hemesh_stats_compute(h, &before, NULL, NULL);
    cg_hemesh_compact(h);
    valid(h, "compaction");
    cg_hemesh_stats_compute(h, &after, NULL, NULL);
    CHECK(before.vertices == after.vertices && before.edges == after.edges
          && before.faces == after.faces && before.boundary_loops == after.boundary_loops
          && before.components == after.components);
    CHECK_EQ_INT(h->vertex_count, h->live_vertices);
    CHECK_EQ_INT(h->face_count, h->live_faces);
    /* and the indexed mesh builds back to the same counts */
    cg_mesh *mesh = NULL;
    CHECK(cg_hemesh_to_mesh(h, &mesh) == CG_OK);
    cg_hemesh *again = NULL;
    cg_error err;
    /* complex vertices (left by removals) rebuild only when split */
    cg_status s = cg_hemesh_build(mesh, after.complex_vertices ? CG_HEMESH_SPLIT_NONMANIFOLD : 0,
                                  &again, NULL, &err);
    CHECK_MSG(s == CG_OK, "%s: rebuild: %s", name, err.message);
    if (again) {
        cg_hemesh_stats st;
        cg_hemesh_stats_compute(again, &st, NULL, NULL);
        CHECK(st.edges == after.edges && st.faces == after.faces);
        CHECK(st.vertices == after.vertices || after.complex_vertices);
        CHECK(st.boundary_loops == after.boundary_loops || after.complex_vertices);
        CHECK_EQ_INT(st.complex_vertices, 0);
    }
    cg_hemesh_free(again);
    cg_mesh_free(mesh);
}

static void test_random_operations(void)
{
    struct {
        const char *name;
        cg_mesh *mesh;
    } cases[] = {
        {"icosphere", shape_icosphere(2)},     {"torus", shape_torus(9, 6, 1)},
        {"grid", shape_grid(7, 6, 1)},         {"cube quads", shape_cube(0)},
        {"torus quads", shape_torus(8, 5, 0)}, {"double ring", shape_double_ring(1)},
        {"grid quads", shape_grid(5, 5, 0)},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        for (uint64_t seed = 1; seed <= 6; seed++) {
            cg_mesh *copy = NULL;
            cg_mesh *src = cases[i].mesh;
            cg_mesh_create(&copy, src->vertex_count, src->face_count,
                           src->face_offsets[src->face_count], 0);
            memcpy(copy->positions, src->positions, src->vertex_count * sizeof *src->positions);
            memcpy(copy->face_offsets, src->face_offsets, (src->face_count + 1) * sizeof(uint32_t));
            memcpy(copy->face_indices, src->face_indices,
                   src->face_offsets[src->face_count] * sizeof(uint32_t));
            cg_hemesh *h = build(copy);
            if (!h)
                continue;
            random_operations(cases[i].name, h, 300, seed * 7919 + i);
            cg_hemesh_free(h);
        }
        cg_mesh_free(cases[i].mesh);
    }
}

/* Small random meshes (triangles and some quads of random vertices, the
 * bad faces dropped) under random splits, flips and collapses: every operation that
 * succeeds leaves a valid structure.  Among them are closed surfaces where
 * the two triangles of an edge also share their third vertex through two
 * different edges (a doubled edge, which splits and flips can make): the
 * collapse of such an edge must be refused, as the triangles share two
 * sides and would leave an edge without faces; so must the collapse of an
 * edge whose ends are joined by a second edge (it would become a loop) or
 * are both corners of a third face (it would visit a vertex twice). */
static void test_random_small_edits(void)
{
    check_rng rng = {20261202};
    int collapses = 0, refused = 0;
    for (int round = 0; round < 6000; round++) {
        size_t V = (size_t)check_rng_int(&rng, 4, 13), F = (size_t)check_rng_int(&rng, 2, 13);
        cg_mesh *mesh;
        if (cg_mesh_create(&mesh, V, F, 4 * F, 0) != CG_OK)
            break;
        for (size_t i = 0; i < V; i++)
            mesh->positions[i] = cg_vec3_make(
                check_rng_int(&rng, 0, 99), check_rng_int(&rng, 0, 99), check_rng_int(&rng, 0, 99));
        uint32_t corners = 0; /* triangles, and a quad now and then */
        for (size_t f = 0; f < F; f++) {
            mesh->face_offsets[f] = corners;
            for (long long k = check_rng_int(&rng, 0, 4) == 0 ? 4 : 3; k > 0; k--)
                mesh->face_indices[corners++] = (uint32_t)check_rng_int(&rng, 0, (long long)V - 1);
        }
        mesh->face_offsets[F] = corners;
        cg_hemesh *h = NULL;
        cg_status built = cg_hemesh_build(mesh, CG_HEMESH_DROP_BAD_FACES, &h, NULL, NULL);
        cg_mesh_free(mesh);
        if (built != CG_OK)
            continue;
        for (int step = 0; step < 6; step++) {
            uint32_t e = random_live_edge(h, &rng);
            if (e == CG_HEMESH_NONE)
                break;
            long long op = check_rng_int(&rng, 0, 2);
            cg_status s;
            const char *what = op == 0 ? "split" : op == 1 ? "flip" : "collapse";
            if (op == 0) {
                s = cg_hemesh_split_edge(h, e, cg_vec3_make(0.5, 0.5, 0.5), NULL);
            } else if (op == 1) {
                s = cg_hemesh_flip_edge(h, e);
            } else {
                s = cg_hemesh_collapse_edge(h, 2 * e);
                collapses += s == CG_OK;
                refused += s == CG_EINVAL;
            }
            if (s == CG_OK && !valid(h, what))
                break;
        }
        cg_hemesh_free(h);
    }
    CHECK(collapses > 300 && refused > 300);
    fprintf(stderr, "random small edits: %d collapses done, %d refused\n", collapses, refused);
}

/* Flip and collapse on the tetrahedron: every flip would join two joined
 * vertices and every collapse would leave valence-2 vertices: all refused. */
static void test_tetrahedron_refusals(void)
{
    cg_hemesh *h = build(shape_tetrahedron());
    for (uint32_t e = 0; e < 6; e++)
        CHECK(cg_hemesh_flip_edge(h, e) == CG_EINVAL);
    for (uint32_t x = 0; x < 12; x++)
        CHECK(cg_hemesh_collapse_edge(h, x) == CG_EINVAL);
    valid(h, "refusals");
    CHECK(cg_hemesh_flip_edge(h, 99) == CG_EINVAL);
    CHECK(cg_hemesh_split_face(h, 99, cg_vec3_make(0, 0, 0), NULL) == CG_EINVAL);
    CHECK(cg_hemesh_remove_face(h, 99) == CG_EINVAL);
    CHECK(cg_hemesh_remove_vertex(h, 99) == CG_EINVAL);
    CHECK(cg_hemesh_collapse_edge(h, 99) == CG_EINVAL);
    /* flipping twice on an octahedron-like pair restores the edge */
    cg_hemesh_free(h);
    h = build(shape_icosphere(1));
    uint32_t a = cg_hemesh_origin(h, 0), b = cg_hemesh_dest(h, 0);
    CHECK(cg_hemesh_flip_edge(h, 0) == CG_OK);
    CHECK(cg_hemesh_flip_edge(h, 0) == CG_OK);
    CHECK(cg_hemesh_find_halfedge(h, a, b) != CG_HEMESH_NONE);
    valid(h, "double flip");
    /* removing every face leaves nothing */
    for (uint32_t f = 0; f < h->face_count; f++) {
        CHECK(cg_hemesh_remove_face(h, f) == CG_OK);
        if (!valid(h, "removing all faces"))
            break;
    }
    CHECK_EQ_INT(h->live_vertices, 0);
    CHECK_EQ_INT(h->live_edges, 0);
    CHECK_EQ_INT(h->live_faces, 0);
    cg_hemesh_free(h);
}

/* Removing a face of a closed mesh opens one boundary loop; removing a face
 * that touches the boundary at one vertex only makes a complex vertex. */
static void check_counts_plain(const cg_hemesh *h, size_t V, size_t E, size_t F)
{
    CHECK_EQ_INT(h->live_vertices, V);
    CHECK_EQ_INT(h->live_edges, E);
    CHECK_EQ_INT(h->live_faces, F);
}

static void test_removal_boundary(void)
{
    cg_hemesh *h = build(shape_cube(0));
    CHECK(cg_hemesh_remove_face(h, 0) == CG_OK);
    valid(h, "remove face");
    cg_hemesh_stats st;
    cg_hemesh_stats_compute(h, &st, NULL, NULL);
    CHECK_EQ_INT(st.boundary_loops, 1);
    CHECK_EQ_INT(st.euler_characteristic, 1);
    CHECK_EQ_INT(st.genus, 0);
    cg_hemesh_free(h);
    /* grid 3x3 quads: remove the centre, then a corner-touching face */
    h = build(shape_grid(3, 3, 0));
    CHECK(cg_hemesh_remove_face(h, 4) == CG_OK);
    valid(h, "remove centre");
    cg_hemesh_stats_compute(h, &st, NULL, NULL);
    CHECK_EQ_INT(st.boundary_loops, 2);
    CHECK(cg_hemesh_remove_face(h, 1) == CG_OK); /* joins the hole to the outside */
    valid(h, "remove side");
    cg_hemesh_stats_compute(h, &st, NULL, NULL);
    CHECK_EQ_INT(st.boundary_loops, 1);
    cg_hemesh_free(h);
    h = build(shape_grid(3, 3, 0));
    CHECK(cg_hemesh_remove_face(h, 0) == CG_OK);
    CHECK(cg_hemesh_remove_face(h, 4) == CG_OK); /* touches face 0's hole at one vertex */
    valid(h, "complex vertex");
    cg_hemesh_stats_compute(h, &st, NULL, NULL);
    CHECK_EQ_INT(st.complex_vertices, 1);
    /* the complex vertex's one-ring still visits all its edges */
    uint32_t v = 5; /* grid vertex (1, 1) */
    CHECK_EQ_INT(cg_hemesh_valence(h, v), 4);
    CHECK_EQ_INT(cg_hemesh_vertex_faces(h, v, 1, NULL, 0), 2);
    /* collapses at a complex vertex are refused */
    uint32_t x = h->vertex_halfedge[v];
    CHECK(!cg_hemesh_collapse_ok(h, x));
    CHECK(!cg_hemesh_collapse_ok(h, x ^ 1u));
    cg_hemesh_free(h);
}

/* Splitting every quad of a grid along a diagonal gives the triangulated
 * grid; a quad refuses a split between neighbouring corners. */
static void test_diagonals(void)
{
    cg_hemesh *h = build(shape_grid(4, 3, 0));
    size_t E = h->live_edges, F = h->live_faces;
    CHECK(cg_hemesh_split_face_between(h, h->face_halfedge[0],
                                       cg_hemesh_next(h, h->face_halfedge[0]), NULL)
          == CG_EINVAL);
    CHECK(cg_hemesh_split_face_between(h, h->face_halfedge[0], h->face_halfedge[1], NULL)
          == CG_EINVAL);
    for (uint32_t f = 0; f < F; f++) {
        uint32_t p = h->face_halfedge[f], q = cg_hemesh_next(h, cg_hemesh_next(h, p)), g;
        CHECK(cg_hemesh_split_face_between(h, p, q, &g) == CG_OK);
        CHECK_EQ_INT(cg_hemesh_face_size(h, f), 3);
        CHECK_EQ_INT(cg_hemesh_face_size(h, g), 3);
        valid(h, "diagonal split");
    }
    check_counts_plain(h, 20, E + F, 2 * F);
    cg_hemesh_stats st;
    cg_hemesh_stats_compute(h, &st, NULL, NULL);
    CHECK(st.all_triangles && st.boundary_loops == 1 && st.euler_characteristic == 1);
    /* a triangle has no diagonal */
    uint32_t p = h->face_halfedge[0];
    CHECK(cg_hemesh_split_face_between(h, p, cg_hemesh_prev(h, p), NULL) == CG_EINVAL);
    cg_hemesh_free(h);
}

/* ---- subdivision ---------------------------------------------------------------- */

static void check_counts(const char *name, const cg_hemesh *h, size_t V, size_t E, size_t F)
{
    CHECK_MSG(h->live_vertices == V && h->live_edges == E && h->live_faces == F,
              "%s: V E F = %zu %zu %zu, expected %zu %zu %zu", name, h->live_vertices,
              h->live_edges, h->live_faces, V, E, F);
}

static int near3(cg_vec3 a, cg_vec3 b)
{
    return fabs(a.x - b.x) < 1e-12 && fabs(a.y - b.y) < 1e-12 && fabs(a.z - b.z) < 1e-12;
}

static void test_loop(void)
{
    cg_hemesh *h = build(shape_tetrahedron());
    /* levels 0 to 3: V' = V + E, E' = 2E + 3F, F' = 4F */
    size_t V = 4, E = 6, F = 4;
    cg_hemesh *level = h, *next = NULL;
    for (int l = 1; l <= 3; l++) {
        CHECK(cg_hemesh_subdivide_loop(level, &next) == CG_OK);
        size_t V2 = V + E, E2 = 2 * E + 3 * F, F2 = 4 * F;
        V = V2, E = E2, F = F2;
        check_counts("loop tetrahedron", next, V, E, F);
        valid(next, "loop");
        cg_hemesh_stats st;
        cg_hemesh_stats_compute(next, &st, NULL, NULL);
        CHECK(st.all_triangles && st.genus == 0 && st.euler_characteristic == 2);
        if (l == 1) {
            CHECK_EQ_INT(V, 10);
            CHECK_EQ_INT(E, 24);
            CHECK_EQ_INT(F, 16);
            /* stencils: valence 3, beta = 3/16 */
            for (uint32_t v = 0; v < 4; v++) {
                cg_vec3 sum = {0, 0, 0};
                for (uint32_t w = 0; w < 4; w++)
                    if (w != v)
                        sum = cg_vec3_add(sum, h->positions[w]);
                cg_vec3 want = cg_vec3_add(cg_vec3_scale(h->positions[v], 1 - 9.0 / 16),
                                           cg_vec3_scale(sum, 3.0 / 16));
                CHECK(near3(next->positions[v], want));
            }
            for (uint32_t e = 0; e < 6; e++) {
                cg_vec3 a = h->positions[cg_hemesh_origin(h, 2 * e)],
                        b = h->positions[cg_hemesh_dest(h, 2 * e)];
                cg_vec3 c = h->positions[cg_hemesh_origin(h, cg_hemesh_prev(h, 2 * e))];
                cg_vec3 d = h->positions[cg_hemesh_origin(h, cg_hemesh_prev(h, 2 * e + 1))];
                cg_vec3 want = cg_vec3_add(cg_vec3_scale(cg_vec3_add(a, b), 3.0 / 8),
                                           cg_vec3_scale(cg_vec3_add(c, d), 1.0 / 8));
                CHECK(near3(next->positions[4 + e], want));
                /* the edge point is joined to both ends of its edge */
                CHECK(cg_hemesh_find_halfedge(next, 4 + e, cg_hemesh_origin(h, 2 * e))
                      != CG_HEMESH_NONE);
                CHECK(cg_hemesh_find_halfedge(next, 4 + e, cg_hemesh_dest(h, 2 * e))
                      != CG_HEMESH_NONE);
            }
        }
        if (level != h)
            cg_hemesh_free(level);
        level = next;
    }
    cg_hemesh_free(level);
    cg_hemesh_free(h);
    /* boundary: a triangulated grid keeps one loop; boundary stencils */
    h = build(shape_grid(3, 2, 1));
    CHECK(cg_hemesh_subdivide_loop(h, &next) == CG_OK);
    valid(next, "loop grid");
    cg_hemesh_stats st;
    cg_hemesh_stats_compute(next, &st, NULL, NULL);
    CHECK_EQ_INT(st.boundary_loops, 1);
    check_counts("loop grid", next, h->live_vertices + h->live_edges,
                 2 * h->live_edges + 3 * h->live_faces, 4 * h->live_faces);
    /* vertex 1 = (1, 0) on the bottom edge: 3/4 v + 1/8 ((0,0) + (2,0)) = v */
    CHECK(near3(next->positions[1], cg_vec3_make(1, 0, 0)));
    /* corner (0, 0): 3/4 (0,0) + 1/8 ((1,0) + (0,1)) */
    CHECK(near3(next->positions[0], cg_vec3_make(0.125, 0.125, 0)));
    for (uint32_t e = 0; e < h->live_edges; e++)
        if (cg_hemesh_edge_is_boundary(h, e)) {
            cg_vec3 mid = cg_vec3_scale(cg_vec3_add(h->positions[cg_hemesh_origin(h, 2 * e)],
                                                    h->positions[cg_hemesh_dest(h, 2 * e)]),
                                        0.5);
            CHECK(near3(next->positions[h->vertex_count + e], mid));
        }
    cg_hemesh_free(next);
    cg_hemesh_free(h);
    /* quads are refused */
    h = build(shape_cube(0));
    next = (cg_hemesh *)1;
    CHECK(cg_hemesh_subdivide_loop(h, &next) == CG_EUNSUPPORTED);
    CHECK(next == NULL);
    cg_hemesh_free(h);
}

static void test_catmull_clark(void)
{
    cg_hemesh *h = build(shape_cube(0));
    cg_hemesh *next = NULL;
    CHECK(cg_hemesh_subdivide_catmull_clark(h, &next) == CG_OK);
    /* V' = V + E + F = 26, E' = 2E + sum of face sizes = 48, F' = 24 */
    check_counts("catmull-clark cube", next, 26, 48, 24);
    valid(next, "catmull-clark cube");
    cg_hemesh_stats st;
    cg_hemesh_stats_compute(next, &st, NULL, NULL);
    CHECK(st.all_quads && st.genus == 0);
    /* corner (1, 1, 1) (vertex 7) -> 5/9 (1, 1, 1) */
    CHECK(near3(next->positions[7], cg_vec3_make(5.0 / 9, 5.0 / 9, 5.0 / 9)));
    /* face points are centroids */
    for (uint32_t f = 0; f < 6; f++) {
        uint32_t v[4];
        cg_hemesh_face_vertices(h, f, v, 4);
        cg_vec3 c = {0, 0, 0};
        for (int i = 0; i < 4; i++)
            c = cg_vec3_add(c, cg_vec3_scale(h->positions[v[i]], 0.25));
        CHECK(near3(next->positions[8 + 12 + f], c));
    }
    /* edge (1,1,-1)-(1,1,1) -> (3/4, 3/4, 0) */
    uint32_t x = cg_hemesh_find_halfedge(h, 3, 7);
    CHECK(x != CG_HEMESH_NONE);
    if (x != CG_HEMESH_NONE)
        CHECK(near3(next->positions[8 + (x >> 1)], cg_vec3_make(0.75, 0.75, 0)));
    /* levels 2 and 3 */
    size_t V = 26, E = 48, F = 24;
    cg_hemesh *level = next;
    for (int l = 2; l <= 3; l++) {
        CHECK(cg_hemesh_subdivide_catmull_clark(level, &next) == CG_OK);
        size_t corners = 4 * F;
        V = V + E + F;
        E = 2 * E + corners;
        F = corners;
        check_counts("catmull-clark level", next, V, E, F);
        valid(next, "catmull-clark level");
        cg_hemesh_free(level);
        level = next;
    }
    cg_hemesh_free(level);
    cg_hemesh_free(h);
    /* tetrahedron: V' = 4 + 6 + 4, E' = 12 + 12, F' = 12 */
    h = build(shape_tetrahedron());
    CHECK(cg_hemesh_subdivide_catmull_clark(h, &next) == CG_OK);
    check_counts("catmull-clark tetrahedron", next, 14, 24, 12);
    valid(next, "catmull-clark tetrahedron");
    cg_hemesh_free(next);
    cg_hemesh_free(h);
    /* mixed polygons with boundary, and a mesh with holes from removals */
    h = build(shape_grid(4, 3, 0));
    cg_hemesh_split_face(h, 2, cg_vec3_make(2.5, 0.5, 0), NULL);
    cg_hemesh_remove_face(h, 5);
    valid(h, "before subdivision");
    size_t corners = 0;
    for (uint32_t f = 0; f < h->face_count; f++)
        if (!cg_hemesh_face_is_deleted(h, f))
            corners += cg_hemesh_face_size(h, f);
    CHECK(cg_hemesh_subdivide_catmull_clark(h, &next) == CG_OK);
    check_counts("catmull-clark mixed", next, h->live_vertices + h->live_edges + h->live_faces,
                 2 * h->live_edges + corners, corners);
    valid(next, "catmull-clark mixed");
    cg_hemesh_stats before, after;
    cg_hemesh_stats_compute(h, &before, NULL, NULL);
    cg_hemesh_stats_compute(next, &after, NULL, NULL);
    CHECK_EQ_INT(after.euler_characteristic, before.euler_characteristic);
    CHECK_EQ_INT(after.boundary_loops, before.boundary_loops);
    cg_hemesh *loop = NULL;
    CHECK(cg_hemesh_subdivide_loop(h, &loop) == CG_EUNSUPPORTED);
    cg_hemesh_free(next);
    cg_hemesh_free(h);
    /* genus survives subdivision */
    h = build(shape_double_ring(0));
    CHECK(cg_hemesh_subdivide_catmull_clark(h, &next) == CG_OK);
    cg_hemesh_stats_compute(next, &after, NULL, NULL);
    CHECK_EQ_INT(after.genus, 2);
    cg_hemesh_free(h);
    CHECK(cg_hemesh_subdivide_loop(next, &h) == CG_EUNSUPPORTED);
    cg_hemesh_free(next);
    h = build(shape_double_ring(1));
    CHECK(cg_hemesh_subdivide_loop(h, &next) == CG_OK);
    cg_hemesh_stats_compute(next, &after, NULL, NULL);
    CHECK_EQ_INT(after.genus, 2);
    valid(next, "loop double ring");
    cg_hemesh_free(next);
    cg_hemesh_free(h);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_random_operations);
    CHECK_GROUP(test_random_small_edits);
    CHECK_GROUP(test_tetrahedron_refusals);
    CHECK_GROUP(test_removal_boundary);
    CHECK_GROUP(test_diagonals);
    CHECK_GROUP(test_loop);
    CHECK_GROUP(test_catmull_clark);
    return check_finish();
}
