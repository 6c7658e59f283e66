/* No two edges on the same pair of vertices.
 *
 * Cutting the extra uses of a non-manifold edge leaves two edges between
 * its ends.  When the faces around each end still form one fan (a solid
 * pinched along an edge, touching itself again around its ends), the vertex
 * split keeps both edges on one vertex pair, and an indexed mesh, which
 * names an edge by its two vertices only, would glue them again: the written
 * mesh would be as non-manifold as the input.  Splitting all but one of such
 * edges at their midpoint (triangles stay triangles) keeps the surface,
 * closed where it was closed, with the same Euler characteristic, and leaves
 * every vertex pair on one edge: the result converts to an indexed mesh that
 * builds again without a defect.
 */
#include "internal.h"
#include "../core/array.h"

#include <stdlib.h>
#include <string.h>

/* Lists the edges among candidates that join the same two vertices as
 * another edge that is not listed before them. */
static cg_status separate_find_among(const cg_hemesh *m, const uint32_t *candidates, size_t count,
                                     uint32_t **list, size_t *found_count)
{
    CORE_ARRAY(uint32_t) found = {0};
    for (size_t i = 0; i < count; i++) {
        uint32_t e = candidates[i], u = m->halfedges[2 * e].origin,
                 v = m->halfedges[2 * e + 1].origin;
        uint32_t h0 = m->vertex_halfedge[u], h = h0;
        int twice = 0;
        do {
            uint32_t f = h >> 1;
            /* another edge to v, not one split already (listed earlier) */
            if (f != e && m->halfedges[h ^ 1u].origin == v) {
                twice = 1;
                for (size_t j = 0; j < found.count && twice; j++)
                    twice = found.data[j] != f;
            }
            h = cg_hemesh_cw(m, h);
        } while (h != h0 && !twice);
        if (!twice)
            continue;
        if (core_array_push(&found, e) != CG_OK) {
            free(found.data);
            return CG_ENOMEM;
        }
    }
    *list = found.data;
    *found_count = found.count;
    return CG_OK;
}

/* Lists the edges at the vertices from first on that join a vertex an
 * earlier edge around it already joins (the only ones a split can add). */
static cg_status separate_find_new(const cg_hemesh *m, size_t first, uint32_t **list, size_t *count)
{
    size_t V = m->vertex_count;
    uint32_t *stamp = malloc((V ? V : 1) * sizeof *stamp);
    CORE_ARRAY(uint32_t) found = {0};
    if (!stamp)
        return CG_ENOMEM;
    memset(stamp, 0xff, V * sizeof *stamp);
    for (size_t v = first; v < V; v++) {
        uint32_t h0 = m->vertex_halfedge[v], h = h0;
        if (h0 >= CG_HEMESH_DELETED)
            continue;
        do {
            uint32_t d = m->halfedges[h ^ 1u].origin;
            if (stamp[d] != (uint32_t)v) {
                stamp[d] = (uint32_t)v;
            } else if (core_array_push(&found, h >> 1) != CG_OK) {
                free(found.data);
                free(stamp);
                return CG_ENOMEM;
            }
            h = cg_hemesh_cw(m, h);
        } while (h != h0);
    }
    free(stamp);
    *list = found.data;
    *count = found.count;
    return CG_OK;
}

cg_status hm_split_multiple_edges(cg_hemesh *m, const uint32_t *candidates, size_t candidate_count,
                                  size_t *split, uint32_t **face_origin)
{
    *split = 0;
    *face_origin = NULL;
    size_t first_new_face = m->face_count;
    /* A split joins the new vertex to the opposite corners of its triangles;
     * when both are one vertex those two new edges coincide, and the next
     * round splits one of them (whose opposite corners differ).  Later
     * rounds look only at the vertices the last one added. */
    size_t first_new_vertex = 0, face_origin_capacity = 0;
    for (int round = 0; round < 8; round++) {
        uint32_t *list;
        size_t n, vertices = m->vertex_count;
        cg_status s = round ? separate_find_new(m, first_new_vertex, &list, &n)
                            : separate_find_among(m, candidates, candidate_count, &list, &n);
        first_new_vertex = vertices;
        if (s != CG_OK)
            return s;
        if (!n)
            return CG_OK;
        s = hm_reserve(m, n, 3 * n, 2 * n);
        if (s == CG_OK)
            s = core_array_reserve((void **)face_origin, &face_origin_capacity,
                                   m->face_count + 2 * n - first_new_face + 1,
                                   sizeof **face_origin);
        if (s != CG_OK) {
            free(list);
            return s;
        }
        for (size_t i = 0; i < n; i++) {
            uint32_t e = list[i], h = 2 * e;
            uint32_t sides[2] = {m->halfedges[h].face, m->halfedges[h + 1].face};
            cg_vec3 p = m->positions[m->halfedges[h].origin],
                    q = m->positions[m->halfedges[h + 1].origin];
            cg_vec3 mid = {0.5 * (p.x + q.x), 0.5 * (p.y + q.y), 0.5 * (p.z + q.z)};
            size_t before = m->face_count;
            int triangle[2];
            for (int k = 0; k < 2; k++)
                triangle[k] = sides[k] != CG_HEMESH_NONE && cg_hemesh_face_size(m, sides[k]) == 3;
            if (cg_hemesh_split_edge(m, e, mid, NULL) != CG_OK) {
                free(list);
                return CG_ENOMEM; /* room was reserved: not reached */
            }
            /* the triangles on either side each gave one new face, in order */
            size_t g = before;
            for (int k = 0; k < 2; k++)
                if (triangle[k])
                    (*face_origin)[g++ - first_new_face] = sides[k];
            (*split)++;
        }
        free(list);
    }
    return CG_OK;
}
