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
static cg_status check_faces(builder *b)
{
    const cg_mesh *mesh = b->mesh;
    cg_hemesh_report *rep = b->report;
    size_t bad = 0, kept_corners = 0;
    uint32_t *stamp = NULL;
    int failed = 0;
    size_t first_bad = 0;
    char why[160] = "";
    for (size_t f = 0; f < mesh->face_count; f++) {
        uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
        int is_bad = 0;
        if (end < begin || end - begin < 3) {
            is_bad = 1;
            if (!bad)
                snprintf(why, sizeof why, "has %ld corners, expected 3 or more",
                         (long)end - (long)begin);
        } else {
            for (uint32_t k = begin; k < end && !is_bad; k++)
                if (mesh->face_indices[k] >= mesh->vertex_count) {
                    is_bad = 1;
                    if (!bad)
                        snprintf(why, sizeof why, "refers to vertex %u, but there are %zu",
                                 mesh->face_indices[k], mesh->vertex_count);
                }
            uint32_t size = end - begin;
            if (!is_bad && size <= 8) {
                for (uint32_t i = begin; i < end && !is_bad; i++)
                    for (uint32_t j = i + 1; j < end; j++)
                        if (mesh->face_indices[i] == mesh->face_indices[j]) {
                            is_bad = 1;
                            if (!bad)
                                snprintf(why, sizeof why, "repeats vertex %u",
                                         mesh->face_indices[i]);
                            break;
                        }
            } else if (!is_bad) {
                if (!stamp && !(stamp = calloc(mesh->vertex_count, sizeof *stamp)))
                    return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
                for (uint32_t k = begin; k < end; k++) {
                    uint32_t v = mesh->face_indices[k];
                    if (stamp[v] == (uint32_t)f + 1) {
                        is_bad = 1;
                        if (!bad)
                            snprintf(why, sizeof why, "repeats vertex %u", v);
                        break;
                    }
                    stamp[v] = (uint32_t)f + 1;
                }
            }
        }
        if (is_bad) {
            if (!bad)
                first_bad = f;
            bad++;
            if (rep)
                list_push(&rep->bad_faces, &rep->bad_face_count, &b->bad_face_capacity, (uint32_t)f,
                          &failed);
        } else {
            kept_corners += end - begin;
        }
    }
    free(stamp);
    if (failed)
        return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    if (bad && !(b->flags & CG_HEMESH_DROP_BAD_FACES))
        return cg_error_set(b->err, CG_EFORMAT,
                            "hemesh: face %zu %s (%zu bad face%s in all; CG_HEMESH_DROP_BAD_FACES "
                            "leaves them out)",
                            first_bad, why, bad, bad == 1 ? "" : "s");
    if (mesh->face_count == bad)
        return cg_error_set(b->err, CG_EEMPTY, "hemesh: the mesh has no usable faces (%zu given)",
                            mesh->face_count);
    if (kept_corners > 0x7ffffffful)
        return cg_error_set(b->err, CG_ERANGE, "hemesh: %zu face corners, at most 2^31 - 1",
                            kept_corners);
    b->faces = mesh->face_count - bad;
    b->corners = kept_corners;
    if (!bad) {
        b->offsets = mesh->face_offsets;
        b->indices = mesh->face_indices;
        return CG_OK;
    }
    /* A private copy without the dropped faces. */
    b->own_offsets = malloc((b->faces + 1) * sizeof *b->own_offsets);
    b->own_indices = malloc((kept_corners ? kept_corners : 1) * sizeof *b->own_indices);
    b->face_map = malloc(b->faces * sizeof *b->face_map);
    if (!b->own_offsets || !b->own_indices || !b->face_map)
        return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    size_t nf = 0, k = 0, next_bad = 0;
    b->own_offsets[0] = 0;
    for (size_t f = 0; f < mesh->face_count; f++) {
        if (rep && next_bad < rep->bad_face_count && rep->bad_faces[next_bad] == f) {
            next_bad++;
            continue;
        }
        if (!rep && bad) {
            /* no report to consult: re-check cheaply */
            uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
            int ok = end >= begin && end - begin >= 3;
            for (uint32_t i = begin; ok && i < end; i++) {
                ok = mesh->face_indices[i] < mesh->vertex_count;
                for (uint32_t j = i + 1; ok && j < end && end - begin <= 64; j++)
                    ok = mesh->face_indices[i] != mesh->face_indices[j];
            }
            if (!ok)
                continue;
            if (end - begin > 64) {
                /* large faces: fall back on sorting a copy */
                size_t n = end - begin;
                uint32_t *tmp = malloc(n * sizeof *tmp);
                if (!tmp)
                    return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
                memcpy(tmp, mesh->face_indices + begin, n * sizeof *tmp);
                for (size_t i = 1; i < n; i++) { /* insertion sort is fine: rare */
                    uint32_t x = tmp[i];
                    size_t j = i;
                    while (j > 0 && tmp[j - 1] > x) {
                        tmp[j] = tmp[j - 1];
                        j--;
                    }
                    tmp[j] = x;
                }
                for (size_t i = 1; i < n && ok; i++)
                    ok = tmp[i] != tmp[i - 1];
                free(tmp);
                if (!ok)
                    continue;
            }
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

/* Step 2: match the sides of the faces into edges.  The side of corner k
 * goes from its vertex to the next corner's.  Each group of sides on the
 * same vertex pair fills edges in turn: a side takes the half-edge of its
 * direction in the group's current edge, or opens a new edge (a cut) when
 * that half-edge is taken. */
static cg_status match(builder *b, int record)
{
    size_t V = b->mesh->vertex_count, C = b->corners;
    const uint32_t *off = b->offsets, *idx = b->indices;
    cg_hemesh_report *rep = record ? b->report : NULL;
    size_t vn = V ? V : 1;
    uint32_t *start = calloc(V + 1, sizeof *start);
    uint64_t *bucket = malloc((C ? C : 1) * sizeof *bucket);
    uint32_t *stamp = malloc(vn * sizeof *stamp);
    uint32_t *current = malloc(vn * sizeof *current);
    uint32_t *uses = malloc(vn * sizeof *uses);
    uint8_t *occupied = malloc(vn);
    uint32_t *same_way = malloc(vn * sizeof *same_way);
    uint32_t *first = b->partner ? malloc(vn * sizeof *first) : NULL;
    uint32_t *second = b->partner ? malloc(vn * sizeof *second) : NULL;
    cg_status status = CG_OK;
    int failed = 0;
    free(b->corner_halfedge);
    free(b->cut_edges);
    b->cut_edges = NULL;
    b->cut_capacity = 0;
    free(b->edge_vertices);
    b->corner_halfedge = malloc((C ? C : 1) * sizeof *b->corner_halfedge);
    b->edge_vertices = malloc((C ? C : 1) * 2 * sizeof *b->edge_vertices);
    if (!start || !bucket || !stamp || !current || !uses || !occupied || !same_way
        || (b->partner && (!first || !second)) || !b->corner_halfedge || !b->edge_vertices) {
        status = cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
        goto done;
    }
    /* counting sort of the sides by their smaller vertex */
    for (size_t f = 0; f < b->faces; f++) {
        uint32_t begin = off[f], end = off[f + 1];
        uint32_t prev = idx[end - 1];
        for (uint32_t k = begin; k < end; k++) {
            uint32_t v = idx[k];
            start[(prev < v ? prev : v) + 1]++;
            prev = v;
        }
    }
    for (size_t v = 0; v < V; v++)
        start[v + 1] += start[v];
    /* entry: other vertex << 32 | corner << 1 | (side goes larger to smaller) */
    for (size_t f = 0; f < b->faces; f++) {
        uint32_t begin = off[f], end = off[f + 1];
        for (uint32_t k = begin; k < end; k++) {
            uint32_t a = idx[k], c = idx[k + 1 < end ? k + 1 : begin];
            uint32_t lo = a < c ? a : c, hi = a < c ? c : a;
            bucket[start[lo]++] = (uint64_t)hi << 32 | (uint64_t)k << 1 | (uint64_t)(a > c);
        }
    }
    /* bucket v now ends at start[v] and begins at start[v - 1] */
    memset(stamp, 0xff, vn * sizeof *stamp);
    memset(same_way, 0xff, vn * sizeof *same_way);
    size_t edges = 0, nonmanifold = 0, misoriented = 0, cut = 0, entries = 0;
    for (size_t a = 0; a < V; a++) {
        size_t begin = a ? start[a - 1] : 0, end = start[a];
        /* where a third side turns up the bucket is matched again in the
         * order of radial.c, from the counts it started with */
        size_t saved_edges = edges, saved_nonmanifold = nonmanifold, saved_misoriented = misoriented,
               saved_cut = cut, saved_entries = entries;
        int sorted = !(b->flags & CG_HEMESH_SPLIT_NONMANIFOLD), crowded = 0;
    match_bucket:
        for (size_t i = begin; i < end; i++) {
            uint64_t entry = bucket[i];
            uint32_t other = (uint32_t)(entry >> 32);
            uint32_t corner = (uint32_t)(entry & 0xffffffffu) >> 1;
            uint32_t dir = (uint32_t)entry & 1u;
            if (b->partner)
                b->partner[corner] = CG_HEMESH_NONE;
            if (stamp[other] != (uint32_t)a) {
                stamp[other] = (uint32_t)a;
                uses[other] = 1;
                occupied[other] = 0;
                current[other] = (uint32_t)edges++;
                b->edge_vertices[2 * current[other]] = (uint32_t)a;
                b->edge_vertices[2 * current[other] + 1] = other;
                if (first)
                    first[other] = corner;
            } else {
                uint32_t n = ++uses[other];
                if (n == 2) {
                    if (occupied[other] & (1u << dir)) {
                        if (!misoriented) {
                            b->first_misoriented[0] = (uint32_t)a;
                            b->first_misoriented[1] = other;
                        }
                        misoriented++;
                        same_way[other] = (uint32_t)a;
                    }
                    if (first) {
                        second[other] = corner;
                        b->partner[first[other]] = corner;
                        b->partner[corner] = first[other];
                    }
                } else if (n == 3) {
                    if (!sorted) {
                        crowded = 1;
                        break;
                    }
                    /* a non-manifold edge is not counted as misoriented too */
                    if (same_way[other] == (uint32_t)a)
                        misoriented--;
                    if (!nonmanifold) {
                        b->first_nonmanifold[0] = (uint32_t)a;
                        b->first_nonmanifold[1] = other;
                    }
                    nonmanifold++;
                    if (rep) {
                        list_push(&rep->nonmanifold_edges, &entries,
                                  &b->nonmanifold_edge_capacity, (uint32_t)a, &failed);
                        list_push(&rep->nonmanifold_edges, &entries,
                                  &b->nonmanifold_edge_capacity, other, &failed);
                    }
                    if (first) {
                        b->partner[first[other]] = CG_HEMESH_NONE;
                        b->partner[second[other]] = CG_HEMESH_NONE;
                    }
                }
                if (occupied[other] & (1u << dir)) {
                    size_t listed = cut;
                    list_push(&b->cut_edges, &listed, &b->cut_capacity, (uint32_t)edges, &failed);
                    cut++;
                    occupied[other] = 0;
                    current[other] = (uint32_t)edges++;
                    b->edge_vertices[2 * current[other]] = (uint32_t)a;
                    b->edge_vertices[2 * current[other] + 1] = other;
                }
            }
            occupied[other] |= (uint8_t)(1u << dir);
            b->corner_halfedge[corner] = 2 * current[other] + dir;
        }
        if (crowded) {
            crowded = 0;
            sorted = 1;
            edges = saved_edges, nonmanifold = saved_nonmanifold, misoriented = saved_misoriented;
            cut = saved_cut, entries = saved_entries;
            /* the sizes of the bucket's groups, stamped apart from the matching */
            for (size_t i = begin; i < end; i++)
                same_way[bucket[i] >> 32] = CG_HEMESH_NONE;
            for (size_t i = begin; i < end; i++) {
                uint32_t other = (uint32_t)(bucket[i] >> 32);
                if (stamp[other] != ((uint32_t)a | 0x80000000u)) {
                    stamp[other] = (uint32_t)a | 0x80000000u;
                    uses[other] = 0;
                }
                uses[other]++;
            }
            if (hm_radial_sort_bucket(b->mesh, off, idx, b->faces, (uint32_t)a, bucket + begin,
                                      end - begin, uses) != CG_OK) {
                failed = 1;
                break;
            }
            goto match_bucket;
        }
    }
    if (failed) {
        status = cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
        goto done;
    }
    if (rep)
        rep->nonmanifold_edge_count = entries / 2;
    b->edges = edges;
    b->nonmanifold = nonmanifold;
    b->misoriented = misoriented;
    b->cut = cut;
done:
    free(start);
    free(bucket);
    free(stamp);
    free(current);
    free(uses);
    free(occupied);
    free(same_way);
    free(first);
    free(second);
    return status;
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
static cg_status assemble(builder *b, cg_hemesh **out)
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
    cg_hemesh_halfedge *he = m->halfedges;
    for (size_t e = 0; e < b->edges; e++) {
        cg_hemesh_halfedge x = {CG_HEMESH_NONE, CG_HEMESH_NONE, b->edge_vertices[2 * e], CG_HEMESH_NONE};
        he[2 * e] = x;
        x.origin = b->edge_vertices[2 * e + 1];
        he[2 * e + 1] = x;
    }
    /* The fan walk below jumps around memory, so it runs on a compact copy
     * of the rotation h -> twin(prev(h)) (4 bytes a half-edge) and two
     * bitmaps, filled while linking, rather than on the 16-byte half-edges. */
    size_t words = H / 64 + 1;
    /* the edge vertices (2 per edge = H entries) are read above and no longer
     * needed: their memory, already mapped, holds the rotation */
    uint32_t *rotation = b->edge_vertices;
    uint64_t *seen = calloc(2 * words, sizeof *seen), *on_boundary = seen ? seen + words : NULL;
    if (!seen) {
        cg_hemesh_free(m);
        return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    }
    /* face loops */
    for (size_t f = 0; f < F; f++) {
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
    /* boundary loops: the next of boundary half-edge x (ending at u) is the
     * boundary half-edge leaving u found by rotating from twin(x) */
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
    /* fans: the cycles of the rotation */
    for (size_t v = 0; v < V; v++)
        m->vertex_halfedge[v] = CG_HEMESH_NONE;
    size_t nonmanifold_vertices = 0, added = 0;
    uint32_t first_bad_vertex = 0;
    int failed = 0;
    uint32_t *extra_fans = NULL; /* first half-edge of each extra fan */
    size_t extra_count = 0, extra_capacity = 0;
    cg_hemesh_report *rep = b->report;
    for (size_t h0 = 0; h0 < H; h0++) {
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
        list_push(&extra_fans, &extra_count, &extra_capacity, pick, &failed);
    }
    free(seen);
    /* count distinct vertices among the extra fans (each fan's vertex is its origin) */
    if (extra_count) {
        uint8_t *mark = calloc(V, 1);
        if (!mark)
            failed = 1;
        for (size_t i = 0; mark && i < extra_count; i++) {
            uint32_t v = he[extra_fans[i]].origin;
            if (!mark[v]) {
                mark[v] = 1;
                if (!nonmanifold_vertices || v < first_bad_vertex)
                    first_bad_vertex = v;
                nonmanifold_vertices++;
            }
        }
        if (rep && mark)
            for (size_t v = 0; v < V; v++)
                if (mark[v])
                    list_push(&rep->nonmanifold_vertices, &rep->nonmanifold_vertex_count,
                              &b->nonmanifold_vertex_capacity, (uint32_t)v, &failed);
        free(mark);
    }
    if (failed) {
        free(extra_fans);
        cg_hemesh_free(m);
        return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    }
    if (nonmanifold_vertices && !(b->flags & CG_HEMESH_SPLIT_NONMANIFOLD)) {
        free(extra_fans);
        cg_hemesh_free(m);
        return cg_error_set(b->err, CG_EFORMAT,
                            "hemesh: the faces around vertex %u form more than one fan "
                            "(non-manifold; %zu such vertices; CG_HEMESH_SPLIT_NONMANIFOLD "
                            "splits them)",
                            first_bad_vertex, nonmanifold_vertices);
    }
    /* attributes of the input vertices */
    memcpy(m->positions, mesh->positions, V * sizeof *m->positions);
    if (mesh->normals)
        memcpy(m->normals, mesh->normals, V * sizeof *m->normals);
    if (mesh->texcoords)
        memcpy(m->texcoords, mesh->texcoords, V * sizeof *m->texcoords);
    if (mesh->colors)
        memcpy(m->colors, mesh->colors, V * sizeof *m->colors);
    for (size_t f = 0; f < F && mesh->face_colors; f++)
        m->face_colors[f] = mesh->face_colors[b->face_map ? b->face_map[f] : f];
    m->live_vertices = V;
    m->live_edges = b->edges;
    m->live_faces = F;
    /* split: one new vertex per extra fan */
    if (extra_count) {
        s = hm_reserve(m, extra_count, 0, 0);
        if (s != CG_OK) {
            free(extra_fans);
            cg_hemesh_free(m);
            return cg_error_set(b->err, s, "hemesh: out of memory");
        }
        for (size_t i = 0; i < extra_count; i++) {
            uint32_t h0 = extra_fans[i], old = he[h0].origin;
            uint32_t v = hm_add_vertex(m, m->positions[old]);
            double one = 1.0;
            hm_blend_attributes(m, v, &old, &one, 1);
            if (m->normals)
                m->normals[v] = m->normals[old];
            m->vertex_halfedge[v] = h0;
            uint32_t h = h0;
            do {
                m->halfedges[h].origin = v;
                h = m->halfedges[h].prev ^ 1u;
            } while (h != h0);
            added++;
        }
    }
    free(extra_fans);
    if (rep) {
        rep->added_vertex_count = added;
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
