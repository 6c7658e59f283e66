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
#include "internal.h"
#include "../core/array.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct builder {
    const cg_mesh *mesh;
    unsigned flags;
    cg_hemesh_report *report;
    cg_error *err;
    /* the working faces: kept faces, possibly reversed */
    size_t faces, corners;
    const uint32_t *offsets, *indices;
    uint32_t *own_offsets, *own_indices, *face_map;
    /* matching */
    uint32_t *corner_halfedge; /* corners */
    uint32_t *edge_vertices;   /* 2 per edge: origin of 2e and of 2e + 1 */
    size_t edges;
    size_t nonmanifold, misoriented, cut;
    uint32_t *cut_edges; /* the cut edges opened, cut of them */
    uint32_t first_nonmanifold[2], first_misoriented[2];
    uint32_t *partner; /* corners, only when orienting */
    /* the room of the growing lists: cut_edges and the report's three */
    size_t cut_capacity, bad_face_capacity, nonmanifold_edge_capacity,
        nonmanifold_vertex_capacity;
} builder;

/* Appends value to *list (count items in room for *capacity); sets *failed
 * when memory runs out. */
static void list_push(uint32_t **list, size_t *count, size_t *capacity, uint32_t value,
                      int *failed)
{
    if (core_array_reserve((void **)list, capacity, *count + 1, sizeof **list) != CG_OK) {
        *failed = 1;
        return;
    }
    (*list)[(*count)++] = value;
}

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

/* Step 1: which faces are usable. */

/* Whether face f is bad: fewer than 3 corners, a vertex out of range or a
 * vertex twice.  When it is and why is not NULL, why (160 bytes) receives
 * the reason.  *stamp is per-vertex scratch, allocated on first need for
 * faces too large to compare corner pairs. */
static cg_status face_is_bad(const cg_mesh *mesh, size_t f, uint32_t **stamp, char *why,
                             int *is_bad)
{
    uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
    const size_t why_size = 160;
    *is_bad = 1;
    if (end < begin || end - begin < 3) {
        if (why)
            snprintf(why, why_size, "has %ld corners, expected 3 or more", (long)end - (long)begin);
        return CG_OK;
    }
    for (uint32_t k = begin; k < end; k++)
        if (mesh->face_indices[k] >= mesh->vertex_count) {
            if (why)
                snprintf(why, why_size, "refers to vertex %u, but there are %zu",
                         mesh->face_indices[k], mesh->vertex_count);
            return CG_OK;
        }
    if (end - begin <= 8) {
        for (uint32_t i = begin; i < end; i++)
            for (uint32_t j = i + 1; j < end; j++)
                if (mesh->face_indices[i] == mesh->face_indices[j]) {
                    if (why)
                        snprintf(why, why_size, "repeats vertex %u", mesh->face_indices[i]);
                    return CG_OK;
                }
    } else {
        if (!*stamp && !(*stamp = calloc(mesh->vertex_count, sizeof **stamp)))
            return CG_ENOMEM;
        for (uint32_t k = begin; k < end; k++) {
            uint32_t v = mesh->face_indices[k];
            if ((*stamp)[v] == (uint32_t)f + 1) {
                if (why)
                    snprintf(why, why_size, "repeats vertex %u", v);
                return CG_OK;
            }
            (*stamp)[v] = (uint32_t)f + 1;
        }
    }
    *is_bad = 0;
    return CG_OK;
}

/* Lists the bad faces in increasing order into *list (*count of them in room
 * for *capacity), sums the corners of the others into *kept_corners, and
 * gives the first bad face's reason in why (160 bytes). */
static cg_status list_bad_faces(const cg_mesh *mesh, uint32_t **list, size_t *count,
                                size_t *capacity, size_t *kept_corners, char *why)
{
    uint32_t *stamp = NULL;
    int failed = 0;
    *kept_corners = 0;
    for (size_t f = 0; f < mesh->face_count && !failed; f++) {
        int is_bad;
        if (face_is_bad(mesh, f, &stamp, *count ? NULL : why, &is_bad) != CG_OK) {
            failed = 1;
        } else if (is_bad) {
            list_push(list, count, capacity, (uint32_t)f, &failed);
        } else {
            *kept_corners += mesh->face_offsets[f + 1] - mesh->face_offsets[f];
        }
    }
    free(stamp);
    return failed ? CG_ENOMEM : CG_OK;
}

/* A private copy of the faces without the bad ones (bad_count of them,
 * listed in increasing order), and the map to the input faces. */
static cg_status copy_kept_faces(builder *b, const uint32_t *bad, size_t bad_count)
{
    const cg_mesh *mesh = b->mesh;
    b->own_offsets = malloc((b->faces + 1) * sizeof *b->own_offsets);
    b->own_indices = malloc((b->corners ? b->corners : 1) * sizeof *b->own_indices);
    b->face_map = malloc(b->faces * sizeof *b->face_map);
    if (!b->own_offsets || !b->own_indices || !b->face_map)
        return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    size_t nf = 0, k = 0, next_bad = 0;
    b->own_offsets[0] = 0;
    for (size_t f = 0; f < mesh->face_count; f++) {
        if (next_bad < bad_count && bad[next_bad] == f) {
            next_bad++;
            continue;
        }
        uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
        memcpy(b->own_indices + k, mesh->face_indices + begin, (end - begin) * sizeof *b->own_indices);
        k += end - begin;
        b->face_map[nf++] = (uint32_t)f;
        b->own_offsets[nf] = (uint32_t)k;
    }
    b->offsets = b->own_offsets;
    b->indices = b->own_indices;
    return CG_OK;
}

static cg_status check_faces(builder *b)
{
    const cg_mesh *mesh = b->mesh;
    cg_hemesh_report *rep = b->report;
    /* The bad faces go into the report, or into a list of our own. */
    uint32_t *own_list = NULL;
    size_t own_count = 0, own_capacity = 0, kept_corners;
    uint32_t **list = rep ? &rep->bad_faces : &own_list;
    size_t *bad = rep ? &rep->bad_face_count : &own_count;
    size_t *capacity = rep ? &b->bad_face_capacity : &own_capacity;
    char why[160] = "";
    cg_status status = list_bad_faces(mesh, list, bad, capacity, &kept_corners, why);
    if (status != CG_OK)
        status = cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    else if (*bad && !(b->flags & CG_HEMESH_DROP_BAD_FACES))
        status = cg_error_set(b->err, CG_EFORMAT,
                              "hemesh: face %u %s (%zu bad face%s in all; CG_HEMESH_DROP_BAD_FACES "
                              "leaves them out)",
                              (*list)[0], why, *bad, *bad == 1 ? "" : "s");
    else if (mesh->face_count == *bad)
        status = cg_error_set(b->err, CG_EEMPTY, "hemesh: the mesh has no usable faces (%zu given)",
                              mesh->face_count);
    else if (kept_corners > 0x7ffffffful)
        status = cg_error_set(b->err, CG_ERANGE, "hemesh: %zu face corners, at most 2^31 - 1",
                              kept_corners);
    if (status == CG_OK) {
        b->faces = mesh->face_count - *bad;
        b->corners = kept_corners;
        if (*bad) {
            status = copy_kept_faces(b, *list, *bad);
        } else {
            b->offsets = mesh->face_offsets;
            b->indices = mesh->face_indices;
        }
    }
    free(own_list);
    return status;
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
    uint8_t *occupied;       /* which half-edges of the current edge are taken */
    uint32_t *first, *second; /* the group's first two corners, only when orienting */
    cg_hemesh_report *report; /* NULL: this pass records nothing */
    matching_counts counts;
    int failed;
} matching;

/* Sorts the sides into the buckets of their smaller vertex (a counting sort). */
static void sort_sides(const builder *b, matching *mt)
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
static void open_edge(builder *b, matching *mt, uint32_t a, uint32_t other)
{
    mt->current[other] = (uint32_t)mt->counts.edges++;
    b->edge_vertices[2 * mt->current[other]] = a;
    b->edge_vertices[2 * mt->current[other] + 1] = other;
}

/* The third side of edge (a, other): the edge is non-manifold. */
static void count_nonmanifold(builder *b, matching *mt, uint32_t a, uint32_t other)
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
        list_push(&mt->report->nonmanifold_edges, &n->entries, &b->nonmanifold_edge_capacity, a,
                  &mt->failed);
        list_push(&mt->report->nonmanifold_edges, &n->entries, &b->nonmanifold_edge_capacity,
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
static int match_bucket(builder *b, matching *mt, uint32_t a, size_t begin, size_t end, int sorted)
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
                list_push(&b->cut_edges, &listed, &b->cut_capacity,
                          (uint32_t)mt->counts.edges, &mt->failed);
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
static cg_status sort_crowded_bucket(builder *b, matching *mt, uint32_t a, size_t begin,
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
    return hm_radial_sort_bucket(b->mesh, b->offsets, b->indices, b->faces, a,
                                 mt->bucket + begin, end - begin, mt->uses);
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

static cg_status match(builder *b, int record)
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
static cg_status orient(builder *b)
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

/* Step 4: the structure itself. */

/* The half-edge structure with the edges of the matching, their links not
 * yet made, and room for the midpoint splits that cut edges may need. */
static cg_status create_structure(const builder *b, cg_hemesh **out)
{
    const cg_mesh *mesh = b->mesh;
    size_t V = mesh->vertex_count, F = b->faces, H = 2 * b->edges;
    unsigned flags = (mesh->normals ? CG_MESH_NORMALS : 0u) | (mesh->texcoords ? CG_MESH_TEXCOORDS : 0u)
                     | (mesh->colors ? CG_MESH_COLORS : 0u)
                     | (mesh->face_colors ? CG_MESH_FACE_COLORS : 0u);
    cg_hemesh *m;
    /* room for the midpoint splits that cut edges may need (about one per
     * cut: 3 edges and 2 faces each), so that they do not grow the arrays;
     * what is left over is given back at the end of the build */
    size_t room = b->cut && H + 6 * b->cut < 0x7fffffffu && F + 2 * b->cut < 0x7fffffffu ? b->cut : 0;
    cg_status s = hm_create(&m, V, H + 6 * room, F + 2 * room, flags);
    if (s != CG_OK)
        return cg_error_set(b->err, s, "hemesh: %s", s == CG_ERANGE ? "too many elements" : "out of memory");
    m->halfedge_count = H;
    m->face_count = F;
    for (size_t e = 0; e < b->edges; e++) {
        cg_hemesh_halfedge x = {CG_HEMESH_NONE, CG_HEMESH_NONE, b->edge_vertices[2 * e], CG_HEMESH_NONE};
        m->halfedges[2 * e] = x;
        x.origin = b->edge_vertices[2 * e + 1];
        m->halfedges[2 * e + 1] = x;
    }
    *out = m;
    return CG_OK;
}

/* Links the face loops, then the boundary loops: the next of boundary
 * half-edge x (ending at u) is the boundary half-edge leaving u found by
 * rotating from twin(x).  Fills rotation (h -> twin(prev(h))) and marks the
 * boundary half-edges in on_boundary. */
static void link_loops(const builder *b, cg_hemesh *m, uint32_t *rotation, uint64_t *on_boundary)
{
    cg_hemesh_halfedge *he = m->halfedges;
    size_t H = m->halfedge_count;
    for (size_t f = 0; f < b->faces; f++) {
        uint32_t begin = b->offsets[f], end = b->offsets[f + 1];
        uint32_t prev = b->corner_halfedge[end - 1];
        for (uint32_t k = begin; k < end; k++) {
            uint32_t h = b->corner_halfedge[k];
            he[h].face = (uint32_t)f;
            he[h].prev = prev;
            rotation[h] = prev ^ 1u;
            he[prev].next = h;
            prev = h;
        }
        m->face_halfedge[f] = b->corner_halfedge[begin];
    }
    for (size_t x = 0; x < H; x++) {
        if (he[x].face != CG_HEMESH_NONE)
            continue;
        uint32_t h = (uint32_t)x ^ 1u;
        size_t guard = 0;
        while (he[h].face != CG_HEMESH_NONE && guard++ < H)
            h = he[h].prev ^ 1u;
        he[x].next = h;
        he[h].prev = (uint32_t)x;
        rotation[h] = (uint32_t)x ^ 1u;
        on_boundary[x >> 6] |= (uint64_t)1 << (x & 63);
    }
}

/* The fans are the cycles of the rotation.  Each vertex gets the first
 * half-edge of its first fan (a boundary one where the fan has one); the
 * first half-edges of the other fans go into *extra (count, capacity). */
static void find_fans(builder *b, cg_hemesh *m, const uint32_t *rotation, uint64_t *seen,
                      const uint64_t *on_boundary, uint32_t **extra, size_t *count,
                      size_t *capacity, int *failed)
{
    const cg_hemesh_halfedge *he = m->halfedges;
    for (size_t v = 0; v < b->mesh->vertex_count; v++)
        m->vertex_halfedge[v] = CG_HEMESH_NONE;
    for (size_t h0 = 0; h0 < m->halfedge_count; h0++) {
        if (seen[h0 >> 6] >> (h0 & 63) & 1)
            continue;
        uint32_t v = he[h0].origin, h = (uint32_t)h0, boundary = CG_HEMESH_NONE;
        do {
            seen[h >> 6] |= (uint64_t)1 << (h & 63);
            if (on_boundary[h >> 6] >> (h & 63) & 1)
                boundary = h;
            h = rotation[h];
        } while (h != h0);
        uint32_t pick = boundary != CG_HEMESH_NONE ? boundary : (uint32_t)h0;
        if (m->vertex_halfedge[v] == CG_HEMESH_NONE) {
            m->vertex_halfedge[v] = pick;
            continue;
        }
        /* a second (or later) fan at v */
        list_push(extra, count, capacity, pick, failed);
    }
}

/* Counts the distinct vertices of the extra fans (each fan's vertex is its
 * first half-edge's origin) into *vertices with the smallest in *first, and
 * lists them in the report. */
static void count_fan_vertices(builder *b, const cg_hemesh *m, const uint32_t *extra,
                               size_t count, size_t *vertices, uint32_t *first, int *failed)
{
    size_t V = b->mesh->vertex_count;
    uint8_t *mark = calloc(V, 1);
    if (!mark) {
        *failed = 1;
        return;
    }
    for (size_t i = 0; i < count; i++) {
        uint32_t v = m->halfedges[extra[i]].origin;
        if (!mark[v]) {
            mark[v] = 1;
            if (!*vertices || v < *first)
                *first = v;
            (*vertices)++;
        }
    }
    cg_hemesh_report *rep = b->report;
    if (rep)
        for (size_t v = 0; v < V; v++)
            if (mark[v])
                list_push(&rep->nonmanifold_vertices, &rep->nonmanifold_vertex_count,
                          &b->nonmanifold_vertex_capacity, (uint32_t)v, failed);
    free(mark);
}

/* The attributes of the input vertices and faces. */
static void copy_attributes(const builder *b, cg_hemesh *m)
{
    const cg_mesh *mesh = b->mesh;
    size_t V = mesh->vertex_count;
    memcpy(m->positions, mesh->positions, V * sizeof *m->positions);
    if (mesh->normals)
        memcpy(m->normals, mesh->normals, V * sizeof *m->normals);
    if (mesh->texcoords)
        memcpy(m->texcoords, mesh->texcoords, V * sizeof *m->texcoords);
    if (mesh->colors)
        memcpy(m->colors, mesh->colors, V * sizeof *m->colors);
    for (size_t f = 0; f < b->faces && mesh->face_colors; f++)
        m->face_colors[f] = mesh->face_colors[b->face_map ? b->face_map[f] : f];
    m->live_vertices = V;
    m->live_edges = b->edges;
    m->live_faces = b->faces;
}

/* Splits the vertices: one new vertex (a copy of the old one) per extra fan. */
static cg_status split_fans(cg_hemesh *m, const uint32_t *extra, size_t count)
{
    cg_status s = hm_reserve(m, count, 0, 0);
    if (s != CG_OK)
        return s;
    cg_hemesh_halfedge *he = m->halfedges;
    for (size_t i = 0; i < count; i++) {
        uint32_t h0 = extra[i], old = he[h0].origin;
        uint32_t v = hm_add_vertex(m, m->positions[old]);
        double one = 1.0;
        hm_blend_attributes(m, v, &old, &one, 1);
        if (m->normals)
            m->normals[v] = m->normals[old];
        m->vertex_halfedge[v] = h0;
        uint32_t h = h0;
        do {
            he[h].origin = v;
            h = he[h].prev ^ 1u;
        } while (h != h0);
    }
    return CG_OK;
}

static cg_status assemble(builder *b, cg_hemesh **out)
{
    size_t V = b->mesh->vertex_count, H = 2 * b->edges;
    cg_hemesh *m = NULL;
    cg_status s = create_structure(b, &m);
    if (s != CG_OK)
        return s;
    /* The fan walk jumps around memory, so it runs on a compact copy of the
     * rotation h -> twin(prev(h)) (4 bytes a half-edge) and two bitmaps,
     * filled while linking, rather than on the 16-byte half-edges. */
    size_t words = H / 64 + 1;
    /* the edge vertices (2 per edge = H entries) are read by create_structure
     * and no longer needed: their memory, already mapped, holds the rotation */
    uint32_t *rotation = b->edge_vertices;
    uint64_t *seen = calloc(2 * words, sizeof *seen), *on_boundary = seen ? seen + words : NULL;
    if (!seen) {
        cg_hemesh_free(m);
        return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    }
    link_loops(b, m, rotation, on_boundary);
    size_t nonmanifold_vertices = 0;
    uint32_t first_bad_vertex = 0;
    int failed = 0;
    uint32_t *extra_fans = NULL; /* first half-edge of each extra fan */
    size_t extra_count = 0, extra_capacity = 0;
    find_fans(b, m, rotation, seen, on_boundary, &extra_fans, &extra_count, &extra_capacity,
              &failed);
    free(seen);
    if (extra_count)
        count_fan_vertices(b, m, extra_fans, extra_count, &nonmanifold_vertices,
                           &first_bad_vertex, &failed);
    if (failed)
        s = cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    else if (nonmanifold_vertices && !(b->flags & CG_HEMESH_SPLIT_NONMANIFOLD))
        s = cg_error_set(b->err, CG_EFORMAT,
                         "hemesh: the faces around vertex %u form more than one fan "
                         "(non-manifold; %zu such vertices; CG_HEMESH_SPLIT_NONMANIFOLD "
                         "splits them)",
                         first_bad_vertex, nonmanifold_vertices);
    if (s == CG_OK) {
        copy_attributes(b, m);
        if (extra_count && (s = split_fans(m, extra_fans, extra_count)) != CG_OK)
            cg_error_set(b->err, s, "hemesh: out of memory");
    }
    free(extra_fans);
    if (s != CG_OK) {
        cg_hemesh_free(m);
        return s;
    }
    cg_hemesh_report *rep = b->report;
    if (rep) {
        rep->added_vertex_count = extra_count;
        size_t isolated = 0;
        for (size_t v = 0; v < V; v++)
            isolated += m->vertex_halfedge[v] == CG_HEMESH_NONE;
        rep->isolated_vertex_count = isolated;
    }
    *out = m;
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
    if (!mesh->face_offsets || (mesh->face_count && (!mesh->face_indices || mesh->face_offsets[0] != 0))
        || (mesh->vertex_count && !mesh->positions))
        return cg_error_set(err, CG_EFORMAT, "hemesh: the mesh arrays are inconsistent");
    if (mesh->face_count == 0)
        return cg_error_set(err, CG_EEMPTY, "hemesh: the mesh has no faces (%zu vertices)",
                            mesh->vertex_count);
    if (mesh->vertex_count >= 0x7fffffffu || mesh->face_count >= 0x7fffffffu)
        return cg_error_set(err, CG_ERANGE, "hemesh: too many vertices or faces");
    if (report)
        report->orientable = 1;
    builder b;
    memset(&b, 0, sizeof b);
    b.mesh = mesh;
    b.flags = flags;
    b.report = report;
    b.err = err;
    cg_status s = check_faces(&b);
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
        s = assemble(&b, out);
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
