/* Counts of an indexed mesh as it was read, before any repair: the distinct
 * vertex pairs its faces use and the components its faces form through
 * shared vertices.  These describe the file, where cg_hemesh_stats_compute
 * describes the (possibly repaired) half-edge structure. */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

/* The faces the half-edge build accepts: 3 or more corners, every index in
 * range and no vertex twice.  stamp (vertex_count entries) marks the
 * corners of face f with f + 1. */
static int counts_face_is_polygon(const cg_mesh *mesh, size_t f, uint32_t *stamp)
{
    uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
    if (end < begin || end - begin < 3)
        return 0;
    for (uint32_t k = begin; k < end; k++) {
        uint32_t v = mesh->face_indices[k];
        if (v >= mesh->vertex_count || stamp[v] == (uint32_t)f + 1)
            return 0;
        stamp[v] = (uint32_t)f + 1;
    }
    return 1;
}

/* Distinct unordered vertex pairs among the sides of the polygons: each side
 * is bucketed under its smaller vertex (a counting sort), and inside a
 * bucket a stamp per larger vertex counts each pair once. */
static size_t counts_distinct_pairs(const cg_mesh *mesh, const uint8_t *polygon, uint32_t *start,
                                    uint32_t *other, uint32_t *stamp)
{
    size_t V = mesh->vertex_count;
    memset(start, 0, (V + 1) * sizeof *start);
    /* pass 0 counts the sides of each bucket, pass 1 places them */
    for (int pass = 0; pass < 2; pass++) {
        for (size_t f = 0; f < mesh->face_count; f++) {
            if (!polygon[f])
                continue;
            uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
            for (uint32_t k = begin; k < end; k++) {
                uint32_t a = mesh->face_indices[k],
                         c = mesh->face_indices[k + 1 < end ? k + 1 : begin];
                uint32_t lo = a < c ? a : c, hi = a < c ? c : a;
                if (pass == 0)
                    start[lo + 1]++;
                else
                    other[start[lo]++] = hi;
            }
        }
        if (pass == 0)
            for (size_t v = 0; v < V; v++)
                start[v + 1] += start[v];
    }
    /* bucket v now runs from start[v - 1] (0 for v = 0) to start[v] */
    memset(stamp, 0xff, V * sizeof *stamp);
    size_t pairs = 0;
    for (size_t v = 0; v < V; v++)
        for (uint32_t i = v ? start[v - 1] : 0; i < start[v]; i++)
            if (stamp[other[i]] != (uint32_t)v) {
                stamp[other[i]] = (uint32_t)v;
                pairs++;
            }
    return pairs;
}

cg_status cg_hemesh_input_counts_compute(const cg_mesh *mesh, cg_hemesh_input_counts *out)
{
    if (!mesh || !out || (mesh->face_count && !mesh->face_offsets)
        || (mesh->face_count && mesh->face_offsets[mesh->face_count] && !mesh->face_indices))
        return CG_EINVAL;
    if (mesh->vertex_count >= 0x7fffffffu || mesh->face_count >= 0x7fffffffu)
        return CG_ERANGE;
    memset(out, 0, sizeof *out);
    size_t V = mesh->vertex_count, F = mesh->face_count;
    size_t C = F ? mesh->face_offsets[F] : 0;
    uint32_t *stamp = malloc((V ? V : 1) * sizeof *stamp);
    uint32_t *parent = malloc((V ? V : 1) * sizeof *parent);
    uint32_t *start = malloc((V + 1) * sizeof *start);
    uint32_t *other = malloc((C ? C : 1) * sizeof *other);
    uint8_t *polygon = malloc(F ? F : 1);
    uint8_t *used = calloc(V ? V : 1, 1);
    cg_status status = CG_OK;
    if (!stamp || !parent || !start || !other || !polygon || !used) {
        status = CG_ENOMEM;
        goto done;
    }
    memset(stamp, 0, (V ? V : 1) * sizeof *stamp);
    for (size_t v = 0; v < V; v++)
        parent[v] = (uint32_t)v;
    size_t components = V;
    for (size_t f = 0; f < F; f++) {
        polygon[f] = (uint8_t)counts_face_is_polygon(mesh, f, stamp);
        if (!polygon[f]) {
            out->bad_faces++;
            continue;
        }
        out->faces++;
        uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
        uint32_t root = hm_find_root(parent, mesh->face_indices[begin]);
        for (uint32_t k = begin; k < end; k++) {
            uint32_t v = mesh->face_indices[k], r = hm_find_root(parent, v);
            used[v] = 1;
            if (r != root) {
                parent[r] = root;
                components--;
            }
        }
    }
    out->vertices = V;
    for (size_t v = 0; v < V; v++)
        out->isolated_vertices += !used[v];
    out->components = components;
    out->edges = counts_distinct_pairs(mesh, polygon, start, other, stamp);
    out->euler_characteristic = (long)out->vertices - (long)out->edges + (long)out->faces;
done:
    free(stamp);
    free(parent);
    free(start);
    free(other);
    free(polygon);
    free(used);
    return status;
}
