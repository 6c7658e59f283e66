/* The subdivision stencils and edge operations of cg/trace_steps.h against
 * the half-edge library: a stencil's new position is the subdivided mesh's
 * vertex bit for bit and its weights are the scheme's (summing to 1); an
 * edge operation leaves the structure exactly as the library's call does,
 * and its "after" records are the structure's own. */
#include "check.h"
#include "cg/hemesh.h"
#include "cg/mesh.h"
#include "cg/trace_steps.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A w x h grid of squares, jittered, as quads or as two triangles each. */
static cg_hemesh *grid(check_rng *rng, int w, int h, int triangles)
{
    size_t faces = (size_t)w * h * (triangles ? 2 : 1);
    cg_mesh *mesh;
    if (cg_mesh_create(&mesh, (size_t)(w + 1) * (h + 1), faces, faces * (triangles ? 3 : 4), 0)
        != CG_OK)
        abort();
    for (int y = 0; y <= h; y++)
        for (int x = 0; x <= w; x++)
            mesh->positions[y * (w + 1) + x] = cg_vec3_make(x + check_rng_range(rng, -0.3, 0.3),
                                                            y + check_rng_range(rng, -0.3, 0.3),
                                                            check_rng_range(rng, -1, 1));
    size_t f = 0, c = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint32_t a = (uint32_t)(y * (w + 1) + x), b = a + 1, d = a + (uint32_t)w + 1, e = d + 1;
            uint32_t quad[4] = {a, b, e, d};
            if (triangles) {
                uint32_t t[6] = {a, b, e, a, e, d};
                for (int k = 0; k < 6; k++) {
                    mesh->face_indices[c++] = t[k];
                    if (k % 3 == 2)
                        mesh->face_offsets[++f] = (uint32_t)c;
                }
            } else {
                for (int k = 0; k < 4; k++)
                    mesh->face_indices[c++] = quad[k];
                mesh->face_offsets[++f] = (uint32_t)c;
            }
        }
    cg_hemesh *m;
    if (cg_hemesh_build(mesh, 0, &m, NULL, NULL) != CG_OK)
        abort();
    cg_mesh_free(mesh);
    return m;
}

/* A closed triangle mesh: an octahedron with jittered corners. */
static cg_hemesh *octahedron(check_rng *rng)
{
    static const double p[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    static const uint32_t t[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                     {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    cg_mesh *mesh;
    if (cg_mesh_create(&mesh, 6, 8, 24, 0) != CG_OK)
        abort();
    for (int i = 0; i < 6; i++)
        mesh->positions[i] = cg_vec3_make(p[i][0] + check_rng_range(rng, -0.2, 0.2),
                                          p[i][1] + check_rng_range(rng, -0.2, 0.2),
                                          p[i][2] + check_rng_range(rng, -0.2, 0.2));
    for (int f = 0; f < 8; f++) {
        for (int k = 0; k < 3; k++)
            mesh->face_indices[3 * f + k] = t[f][k];
        mesh->face_offsets[f + 1] = (uint32_t)(3 * f + 3);
    }
    cg_hemesh *m;
    if (cg_hemesh_build(mesh, 0, &m, NULL, NULL) != CG_OK)
        abort();
    cg_mesh_free(mesh);
    return m;
}

typedef struct stencil {
    double weights, xyz[3];
    int terms, results;
} stencil;

static int collect(void *user, const cg_step *s)
{
    stencil *st = user;
    if (strcmp(s->phase, "stencil") == 0) {
        st->weights += cg_step_find(s, "weight")->real;
        st->terms++;
    } else {
        const cg_step_field *f = cg_step_find(s, "new");
        memcpy(st->xyz, f->reals, sizeof st->xyz);
        st->results++;
    }
    return 0;
}

/* Every vertex's stencil against the subdivided mesh; the vertices checked. */
static long stencils_agree(const cg_hemesh *m, int loop)
{
    cg_hemesh *r;
    CHECK((loop ? cg_hemesh_subdivide_loop(m, &r) : cg_hemesh_subdivide_catmull_clark(m, &r))
          == CG_OK);
    long wrong = 0;
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        stencil st = {0, {0, 0, 0}, 0, 0};
        CHECK((loop ? cg_hemesh_loop_stencil_steps(m, v, collect, &st)
                    : cg_hemesh_catmull_clark_stencil_steps(m, v, collect, &st))
              == CG_OK);
        cg_vec3 want = r->positions[v];
        wrong += st.results != 1 || st.xyz[0] != want.x || st.xyz[1] != want.y
                 || st.xyz[2] != want.z || fabs(st.weights - 1) > 1e-12;
    }
    CHECK_MSG(wrong == 0, "%s: %ld of %zu stencils differ from the subdivision",
              loop ? "Loop" : "Catmull-Clark", wrong, m->vertex_count);
    long count = (long)m->vertex_count;
    cg_hemesh_free(r);
    return count;
}

static void subdivision_agrees(void)
{
    check_rng rng = {0x5ab1};
    long loop = 0, cc = 0;
    for (int trial = 0; trial < 60; trial++) {
        cg_hemesh *tri = trial % 3 == 0 ? octahedron(&rng)
                                        : grid(&rng, (int)check_rng_int(&rng, 1, 6),
                                               (int)check_rng_int(&rng, 1, 6), 1);
        /* flip a few interior edges: other valences */
        for (int k = 0; k < 6; k++)
            cg_hemesh_flip_edge(
                tri, (uint32_t)check_rng_int(&rng, 0, (long long)tri->halfedge_count / 2 - 1));
        cg_hemesh *finer;
        CHECK(cg_hemesh_subdivide_loop(tri, &finer) == CG_OK);
        loop += stencils_agree(tri, 1) + stencils_agree(finer, 1);
        cc += stencils_agree(tri, 0);
        cg_hemesh *quads = grid(&rng, (int)check_rng_int(&rng, 1, 5),
                                (int)check_rng_int(&rng, 1, 5), 0);
        cc += stencils_agree(quads, 0) + stencils_agree(finer, 0);
        cg_hemesh_free(finer);
        cg_hemesh_free(quads);
        cg_hemesh_free(tri);
    }
    printf("stencils: %ld Loop, %ld Catmull-Clark\n", loop, cc);
    CHECK_MSG(loop > 2000 && cc > 2000, "only %ld Loop and %ld Catmull-Clark stencils", loop, cc);
    cg_hemesh *quads = grid(&rng, 2, 2, 0);
    stencil st = {0, {0, 0, 0}, 0, 0};
    CHECK(cg_hemesh_loop_stencil_steps(quads, 0, collect, &st) == CG_EUNSUPPORTED);
    CHECK(cg_hemesh_catmull_clark_stencil_steps(quads, 9, collect, &st) == CG_EINVAL);
    cg_hemesh_free(quads);
}

/* ---- edge operations ------------------------------------------------------------ */

typedef struct records {
    const cg_hemesh *m;
    int wrong, after, done, refused;
} records;

static int check_record(void *user, const cg_step *s)
{
    records *r = user;
    if (strcmp(s->phase, "operation") == 0) {
        const char *result = cg_step_find(s, "result")->text;
        r->done += strcmp(result, "done") == 0;
        r->refused += strncmp(result, "refused", 7) == 0;
        return 0;
    }
    if (strcmp(s->phase, "after") != 0)
        return 0;
    r->after++;
    uint32_t h = (uint32_t)cg_step_find(s, "h")->integer;
    const cg_hemesh_halfedge *e = &r->m->halfedges[h];
    r->wrong += cg_step_find(s, "origin")->integer != e->origin
                || cg_step_find(s, "next")->integer != e->next
                || cg_step_find(s, "prev")->integer != e->prev
                || cg_step_find(s, "dest")->integer != cg_hemesh_dest(r->m, h)
                || r->m->halfedges[e->next].prev != h;
    return 0;
}

static int same_structure(const cg_hemesh *a, const cg_hemesh *b)
{
    return a->vertex_count == b->vertex_count && a->halfedge_count == b->halfedge_count
           && a->face_count == b->face_count
           && memcmp(a->halfedges, b->halfedges, a->halfedge_count * sizeof *a->halfedges) == 0
           && memcmp(a->vertex_halfedge, b->vertex_halfedge, a->vertex_count * sizeof(uint32_t))
                  == 0
           && memcmp(a->face_halfedge, b->face_halfedge, a->face_count * sizeof(uint32_t)) == 0
           && memcmp(a->positions, b->positions, a->vertex_count * sizeof(cg_vec3)) == 0;
}

static void edge_operations_agree(void)
{
    check_rng rng = {0xed6e};
    long done[3] = {0, 0, 0}, refused[3] = {0, 0, 0};
    for (int trial = 0; trial < 600; trial++) {
        cg_edge_operation op = (cg_edge_operation)(trial % 3);
        cg_hemesh *base = trial % 4 == 0 ? octahedron(&rng)
                                         : grid(&rng, (int)check_rng_int(&rng, 1, 5),
                                                (int)check_rng_int(&rng, 1, 5), trial % 5 != 1);
        cg_hemesh *traced, *called;
        CHECK(cg_hemesh_copy(base, &traced) == CG_OK && cg_hemesh_copy(base, &called) == CG_OK);
        uint32_t e = (uint32_t)check_rng_int(&rng, 0, (long long)base->halfedge_count / 2 - 1);
        records r = {traced, 0, 0, 0, 0};
        CHECK(cg_hemesh_edge_operation_steps(traced, op, e, check_record, &r) == CG_OK);
        cg_status status;
        if (op == CG_EDGE_FLIP)
            status = cg_hemesh_flip_edge(called, e);
        else if (op == CG_EDGE_SPLIT)
            status = cg_hemesh_split_edge(
                called, e,
                cg_vec3_scale(cg_vec3_add(called->positions[called->halfedges[2 * e].origin],
                                          called->positions[called->halfedges[2 * e + 1].origin]),
                              0.5),
                NULL);
        else
            status = cg_hemesh_collapse_edge(called, 2 * e);
        CHECK_MSG(same_structure(traced, called),
                  "trial %d: operation %d on edge %u: the structure is not the library's", trial,
                  op, e);
        CHECK(cg_hemesh_validate(traced, NULL) == CG_OK);
        CHECK_MSG(r.done == (status == CG_OK) && r.refused == (status != CG_OK),
                  "trial %d: the trace says %s, the library %s", trial, r.done ? "done" : "refused",
                  cg_status_str(status));
        CHECK(r.wrong == 0 && (status != CG_OK || r.after > 0));
        done[op] += status == CG_OK;
        refused[op] += status != CG_OK;
        cg_hemesh_free(traced);
        cg_hemesh_free(called);
        cg_hemesh_free(base);
    }
    printf("edge operations done / refused: flip %ld / %ld, split %ld / %ld, collapse %ld / %ld\n",
           done[0], refused[0], done[1], refused[1], done[2], refused[2]);
    for (int op = 0; op < 3; op++)
        CHECK_MSG(done[op] > 20 && (op == 1 || refused[op] > 5),
                  "operation %d: %ld done, %ld refused", op, done[op], refused[op]);
    cg_hemesh *m = octahedron(&rng);
    records r = {m, 0, 0, 0, 0};
    CHECK(cg_hemesh_edge_operation_steps(m, CG_EDGE_FLIP, 12, check_record, &r) == CG_EINVAL);
    CHECK(cg_hemesh_edge_operation_steps(m, (cg_edge_operation)7, 0, check_record, &r)
          == CG_EINVAL);
    cg_hemesh_free(m);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(subdivision_agrees);
    CHECK_GROUP(edge_operations_agree);
    return check_finish();
}
