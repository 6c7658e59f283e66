/* Building the half-edge structure from an indexed mesh.
 *
 * 1. Faces are checked (size, range, repeated vertices) and, when asked,
 *    bad ones dropped.
 * 2. Twins are matched in linear time: every face side (a, b) goes into the
 *    bucket of its smaller vertex (a counting sort), and within a bucket a
 *    direct-address table indexed by the other vertex - a perfect hash with
 *    no collisions, so no worst case even around a vertex of huge valence -
 *    pairs the two sides of each edge.  Edges are numbered in bucket order.
 * 3. When two faces traverse an edge the same way and CG_HEMESH_ORIENT is
 *    set, faces are reoriented by a breadth-first walk over the face
 *    adjacency and the matching is redone.
 * 4. Face loops are linked; each boundary half-edge is linked to the next by
 *    rotating about its end vertex; the fans of each vertex are counted as
 *    the cycles of the rotation, and a vertex with several is split (or is
 *    an error).
 */
#include "build.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cg_hemesh_report_clear(cg_hemesh_report *report)
{
    if (!report)
        return;
    free(report->bad_faces);
    free(report->nonmanifold_edges);
    free(report->nonmanifold_vertices);
    free(report->face_map);
    memset(report, 0, sizeof *report);
}

/* Step 2: match the sides of the faces into edges.  The side of corner k
 * goes from its vertex to the next corner's.  Each group of sides on the
 * same vertex pair fills edges in turn: a side takes the half-edge of its
 * direction in the group's current edge, or opens a new edge (a cut) when
 * that half-edge is taken. */

/* What a matching pass has counted so far (saved and restored around a
 * bucket that has to be matched again). */
typedef struct matching_counts {
    size_t edges, nonmanifold, misoriented, cut;
    size_t entries; /* of report->nonmanifold_edges (2 per edge) */
} matching_counts;

/* The scratch of one matching pass.  The per-vertex arrays are indexed by
 * the other vertex of a side in the bucket of vertex a; stamp says which
 * bucket last touched an entry. */
typedef struct matching {
    uint32_t *start;  /* V + 1: bucket v ends at start[v] once the sides are sorted */
    uint64_t *bucket; /* corners: other vertex << 32 | corner << 1 | (larger to smaller) */
    uint32_t *stamp, *current, *uses, *same_way;
    uint8_t *occupied;        /* which half-edges of the current edge are taken */
    uint32_t *first, *second; /* the group's first two corners, only when orienting */
    cg_hemesh_report *report; /* NULL: this pass records nothing */
    matching_counts counts;
    int failed;
} matching;

/* Sorts the sides into the buckets of their smaller vertex (a counting sort). */
static void sort_sides(const hm_builder *b, matching *mt)
{
    size_t V = b->mesh->vertex_count;
    const uint32_t *off = b->offsets, *idx = b->indices;
    for (size_t f = 0; f < b->faces; f++) {
        uint32_t begin = off[f], end = off[f + 1];
        uint32_t prev = idx[end - 1];
        for (uint32_t k = begin; k < end; k++) {
            uint32_t v = idx[k];
            mt->start[(prev < v ? prev : v) + 1]++;
            prev = v;
        }
    }
    for (size_t v = 0; v < V; v++)
        mt->start[v + 1] += mt->start[v];
    for (size_t f = 0; f < b->faces; f++) {
        uint32_t begin = off[f], end = off[f + 1];
        for (uint32_t k = begin; k < end; k++) {
            uint32_t a = idx[k], c = idx[k + 1 < end ? k + 1 : begin];
            uint32_t lo = a < c ? a : c, hi = a < c ? c : a;
            mt->bucket[mt->start[lo]++] = (uint64_t)hi << 32 | (uint64_t)k << 1 | (uint64_t)(a > c);
        }
    }
}

/* Opens a new edge on the vertices (a, other): the current edge of their group. */
static void open_edge(hm_builder *b, matching *mt, uint32_t a, uint32_t other)
{
    mt->current[other] = (uint32_t)mt->counts.edges++;
    b->edge_vertices[2 * mt->current[other]] = a;
    b->edge_vertices[2 * mt->current[other] + 1] = other;
}

/* The third side of edge (a, other): the edge is non-manifold. */
static void count_nonmanifold(hm_builder *b, matching *mt, uint32_t a, uint32_t other)
{
    matching_counts *n = &mt->counts;
    /* a non-manifold edge is not counted as misoriented too */
    if (mt->same_way[other] == a)
        n->misoriented--;
    if (!n->nonmanifold) {
        b->first_nonmanifold[0] = a;
        b->first_nonmanifold[1] = other;
    }
    n->nonmanifold++;
    if (mt->report) {
        hm_list_push(&mt->report->nonmanifold_edges, &n->entries, &b->nonmanifold_edge_capacity, a,
                     &mt->failed);
        hm_list_push(&mt->report->nonmanifold_edges, &n->entries, &b->nonmanifold_edge_capacity,
                     other, &mt->failed);
    }
    if (mt->first) {
        b->partner[mt->first[other]] = CG_HEMESH_NONE;
        b->partner[mt->second[other]] = CG_HEMESH_NONE;
    }
}

/* Matches the sides of bucket a (bucket[begin..end)).  Returns 1 when a
 * third side turns up in a bucket that is not sorted (then what this
 * bucket counted must be undone and the bucket sorted and matched again),
 * else 0. */
static int match_bucket(hm_builder *b, matching *mt, uint32_t a, size_t begin, size_t end,
                        int sorted)
{
    for (size_t i = begin; i < end; i++) {
        uint64_t entry = mt->bucket[i];
        uint32_t other = (uint32_t)(entry >> 32);
        uint32_t corner = (uint32_t)(entry & 0xffffffffu) >> 1;
        uint32_t dir = (uint32_t)entry & 1u;
        if (b->partner)
            b->partner[corner] = CG_HEMESH_NONE;
        if (mt->stamp[other] != a) {
            mt->stamp[other] = a;
            mt->uses[other] = 1;
            mt->occupied[other] = 0;
            open_edge(b, mt, a, other);
            if (mt->first)
                mt->first[other] = corner;
        } else {
            uint32_t n = ++mt->uses[other];
            if (n == 2) {
                if (mt->occupied[other] & (1u << dir)) {
                    if (!mt->counts.misoriented) {
                        b->first_misoriented[0] = a;
                        b->first_misoriented[1] = other;
                    }
                    mt->counts.misoriented++;
                    mt->same_way[other] = a;
                }
                if (mt->first) {
                    mt->second[other] = corner;
                    b->partner[mt->first[other]] = corner;
                    b->partner[corner] = mt->first[other];
                }
            } else if (n == 3) {
                if (!sorted)
                    return 1;
                count_nonmanifold(b, mt, a, other);
            }
            if (mt->occupied[other] & (1u << dir)) {
                size_t listed = mt->counts.cut;
                hm_list_push(&b->cut_edges, &listed, &b->cut_capacity, (uint32_t)mt->counts.edges,
                             &mt->failed);
                mt->counts.cut++;
                mt->occupied[other] = 0;
                open_edge(b, mt, a, other);
            }
        }
        mt->occupied[other] |= (uint8_t)(1u << dir);
        b->corner_halfedge[corner] = 2 * mt->current[other] + dir;
    }
    return 0;
}

/* Sorts a crowded bucket about its vertex in the order of radial.c, from
 * the sizes of its groups, so that it can be matched again. */
static cg_status sort_crowded_bucket(hm_builder *b, matching *mt, uint32_t a, size_t begin,
                                     size_t end)
{
    /* the sizes of the bucket's groups, stamped apart from the matching */
    for (size_t i = begin; i < end; i++)
        mt->same_way[mt->bucket[i] >> 32] = CG_HEMESH_NONE;
    for (size_t i = begin; i < end; i++) {
        uint32_t other = (uint32_t)(mt->bucket[i] >> 32);
        if (mt->stamp[other] != (a | 0x80000000u)) {
            mt->stamp[other] = a | 0x80000000u;
            mt->uses[other] = 0;
        }
        mt->uses[other]++;
    }
    return hm_radial_sort_bucket(b->mesh, b->offsets, b->indices, b->faces, a, mt->bucket + begin,
                                 end - begin, mt->uses);
}

static void matching_free(matching *mt)
{
    free(mt->start);
    free(mt->bucket);
    free(mt->stamp);
    free(mt->current);
    free(mt->uses);
    free(mt->occupied);
    free(mt->same_way);
    free(mt->first);
    free(mt->second);
}

static cg_status match(hm_builder *b, int record)
{
    size_t V = b->mesh->vertex_count, C = b->corners;
    size_t vn = V ? V : 1;
    matching mt;
    memset(&mt, 0, sizeof mt);
    mt.report = record ? b->report : NULL;
    mt.start = calloc(V + 1, sizeof *mt.start);
    mt.bucket = malloc((C ? C : 1) * sizeof *mt.bucket);
    mt.stamp = malloc(vn * sizeof *mt.stamp);
    mt.current = malloc(vn * sizeof *mt.current);
    mt.uses = malloc(vn * sizeof *mt.uses);
    mt.occupied = malloc(vn);
    mt.same_way = malloc(vn * sizeof *mt.same_way);
    mt.first = b->partner ? malloc(vn * sizeof *mt.first) : NULL;
    mt.second = b->partner ? malloc(vn * sizeof *mt.second) : NULL;
    free(b->corner_halfedge);
    free(b->cut_edges);
    b->cut_edges = NULL;
    b->cut_capacity = 0;
    free(b->edge_vertices);
    b->corner_halfedge = malloc((C ? C : 1) * sizeof *b->corner_halfedge);
    b->edge_vertices = malloc((C ? C : 1) * 2 * sizeof *b->edge_vertices);
    if (!mt.start || !mt.bucket || !mt.stamp || !mt.current || !mt.uses || !mt.occupied
        || !mt.same_way || (b->partner && (!mt.first || !mt.second)) || !b->corner_halfedge
        || !b->edge_vertices) {
        matching_free(&mt);
        return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    }
    sort_sides(b, &mt);
    memset(mt.stamp, 0xff, vn * sizeof *mt.stamp);
    memset(mt.same_way, 0xff, vn * sizeof *mt.same_way);
    for (size_t a = 0; a < V && !mt.failed; a++) {
        size_t begin = a ? mt.start[a - 1] : 0, end = mt.start[a];
        /* where a third side turns up the bucket is matched again in the
         * order of radial.c, from the counts it started with */
        matching_counts saved = mt.counts;
        int sorted = !(b->flags & CG_HEMESH_SPLIT_NONMANIFOLD);
        if (match_bucket(b, &mt, (uint32_t)a, begin, end, sorted)) {
            mt.counts = saved;
            if (sort_crowded_bucket(b, &mt, (uint32_t)a, begin, end) != CG_OK)
                mt.failed = 1;
            else
                match_bucket(b, &mt, (uint32_t)a, begin, end, 1);
        }
    }
    int failed = mt.failed;
    if (!failed) {
        if (mt.report)
            mt.report->nonmanifold_edge_count = mt.counts.entries / 2;
        b->edges = mt.counts.edges;
        b->nonmanifold = mt.counts.nonmanifold;
        b->misoriented = mt.counts.misoriented;
        b->cut = mt.counts.cut;
    }
    matching_free(&mt);
    return failed ? cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory") : CG_OK;
}

/* Step 3: orient each component by a breadth-first walk over faces joined
 * by edges with exactly two sides; then reverse the faces that need it. */
static cg_status orient(hm_builder *b)
{
    size_t F = b->faces, C = b->corners;
    if (!b->own_indices) { /* reversing faces needs a private copy */
        b->own_indices = malloc((C ? C : 1) * sizeof *b->own_indices);
        if (!b->own_indices)
            return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
        memcpy(b->own_indices, b->indices, C * sizeof *b->own_indices);
        b->indices = b->own_indices;
    }
    uint32_t *face_of = malloc((C ? C : 1) * sizeof *face_of);
    uint8_t *state = calloc(F ? F : 1, 1); /* 0 unvisited, 1 keep, 2 flip */
    uint32_t *queue = malloc((F ? F : 1) * sizeof *queue);
    if (!face_of || !state || !queue) {
        free(face_of);
        free(state);
        free(queue);
        return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    }
    for (size_t f = 0; f < F; f++)
        for (uint32_t k = b->offsets[f]; k < b->offsets[f + 1]; k++)
            face_of[k] = (uint32_t)f;
    int orientable = 1;
    size_t flipped = 0;
    for (size_t seed = 0; seed < F; seed++) {
        if (state[seed])
            continue;
        size_t head = 0, tail = 0;
        state[seed] = 1;
        queue[tail++] = (uint32_t)seed;
        while (head < tail) {
            uint32_t f = queue[head++];
            for (uint32_t k = b->offsets[f]; k < b->offsets[f + 1]; k++) {
                uint32_t p = b->partner[k];
                if (p == CG_HEMESH_NONE)
                    continue;
                uint32_t g = face_of[p];
                /* the two sides run the same way when their origins match */
                int same = b->indices[k] == b->indices[p];
                uint8_t want = (uint8_t)(same ? 3 - state[f] : state[f]);
                if (!state[g]) {
                    state[g] = want;
                    queue[tail++] = g;
                } else if (state[g] != want) {
                    orientable = 0;
                }
            }
        }
    }
    for (size_t f = 0; f < F; f++) {
        if (state[f] != 2)
            continue;
        flipped++;
        uint32_t *lo = b->own_indices + b->offsets[f], *hi = b->own_indices + b->offsets[f + 1] - 1;
        while (lo < hi) {
            uint32_t t = *lo;
            *lo++ = *hi;
            *hi-- = t;
        }
    }
    if (b->report) {
        b->report->flipped_face_count = flipped;
        b->report->orientable = orientable;
    }
    free(face_of);
    free(state);
    free(queue);
    return CG_OK;
}

cg_status cg_hemesh_build(const cg_mesh *mesh, unsigned flags, cg_hemesh **out,
                          cg_hemesh_report *report, cg_error *err)
{
    if (report)
        memset(report, 0, sizeof *report);
    if (out)
        *out = NULL;
    if (!mesh || !out)
        return cg_error_set(err, CG_EINVAL, "hemesh: no mesh given");
    if (!mesh->face_offsets
        || (mesh->face_count && (!mesh->face_indices || mesh->face_offsets[0] != 0))
        || (mesh->vertex_count && !mesh->positions))
        return cg_error_set(err, CG_EFORMAT, "hemesh: the mesh arrays are inconsistent");
    if (mesh->face_count == 0)
        return cg_error_set(err, CG_EEMPTY, "hemesh: the mesh has no faces (%zu vertices)",
                            mesh->vertex_count);
    if (mesh->vertex_count >= 0x7fffffffu || mesh->face_count >= 0x7fffffffu)
        return cg_error_set(err, CG_ERANGE, "hemesh: too many vertices or faces");
    if (report)
        report->orientable = 1;
    hm_builder b;
    memset(&b, 0, sizeof b);
    b.mesh = mesh;
    b.flags = flags;
    b.report = report;
    b.err = err;
    cg_status s = hm_build_check_faces(&b);
    if (s == CG_OK && (flags & CG_HEMESH_ORIENT)) {
        b.partner = malloc((b.corners ? b.corners : 1) * sizeof *b.partner);
        if (!b.partner)
            s = cg_error_set(err, CG_ENOMEM, "hemesh: out of memory");
    }
    if (s == CG_OK)
        s = match(&b, 1);
    if (s == CG_OK && report)
        report->misoriented_edge_count = b.misoriented;
    if (s == CG_OK && (flags & CG_HEMESH_ORIENT) && b.misoriented) {
        s = orient(&b);
        free(b.partner);
        b.partner = NULL;
        if (s == CG_OK)
            s = match(&b, 0);
    }
    if (s == CG_OK && b.cut && !(flags & CG_HEMESH_SPLIT_NONMANIFOLD)) {
        if (b.nonmanifold)
            s = cg_error_set(err, CG_EFORMAT,
                             "hemesh: edge (%u, %u) is on more than two faces (non-manifold; %zu "
                             "such edges; CG_HEMESH_SPLIT_NONMANIFOLD splits them)",
                             b.first_nonmanifold[0], b.first_nonmanifold[1], b.nonmanifold);
        else
            s = cg_error_set(err, CG_EFORMAT,
                             "hemesh: two faces run along edge (%u, %u) in the same direction "
                             "(inconsistent orientation; %zu such edges; %s)",
                             b.first_misoriented[0], b.first_misoriented[1], b.misoriented,
                             (flags & CG_HEMESH_ORIENT) ? "the surface is not orientable: "
                                                          "CG_HEMESH_SPLIT_NONMANIFOLD cuts it"
                                                        : "CG_HEMESH_ORIENT reorients faces");
    }
    if (s == CG_OK && report)
        report->cut_edge_count = b.cut;
    if (s == CG_OK)
        s = hm_build_assemble(&b, out);
    uint32_t *face_origin = NULL; /* of the faces the edge splits add */
    size_t split = 0;
    if (s == CG_OK && b.cut) {
        s = hm_split_multiple_edges(*out, b.cut_edges, b.cut, &split, &face_origin);
        if (s != CG_OK) {
            s = cg_error_set(err, s, "hemesh: out of memory");
            cg_hemesh_free(*out);
            *out = NULL;
        }
        if (report)
            report->split_edge_count = split;
    }
    if (s == CG_OK) /* after vertex and edge splits */
        hm_shrink_to_fit(*out);
    if (s == CG_OK && report) {
        size_t faces = (*out)->face_count;
        report->face_map = malloc(faces * sizeof *report->face_map);
        if (!report->face_map) {
            s = cg_error_set(err, CG_ENOMEM, "hemesh: out of memory");
            cg_hemesh_free(*out);
            *out = NULL;
        } else {
            for (size_t f = 0; f < b.faces; f++)
                report->face_map[f] = b.face_map ? b.face_map[f] : (uint32_t)f;
            for (size_t f = b.faces; f < faces; f++)
                report->face_map[f] = report->face_map[face_origin[f - b.faces]];
        }
    }
    free(b.own_offsets);
    free(b.own_indices);
    free(b.face_map);
    free(b.corner_halfedge);
    free(b.edge_vertices);
    free(b.partner);
    free(b.cut_edges);
    free(face_origin);
    return s;
}
