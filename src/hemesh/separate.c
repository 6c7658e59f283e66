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

#include <stdlib.h>
#include <string.h>

/* Lists the live edges that join the same two vertices as a lower edge. */
static cg_status separate_find(const cg_hemesh *m, uint32_t **list, size_t *count)
{
    size_t V = m->vertex_count, E = m->halfedge_count / 2;
    uint32_t *start = calloc(V + 1, sizeof *start);
    uint32_t *sorted = malloc((E ? E : 1) * sizeof *sorted);
    uint32_t *stamp = malloc((V ? V : 1) * sizeof *stamp);
    uint32_t *found = NULL;
    size_t n = 0;
    cg_status status = CG_OK;
    if (!start || !sorted || !stamp) {
        status = CG_ENOMEM;
        goto done;
    }
    /* edges by their smaller vertex (a counting sort, edge order kept) */
    for (size_t e = 0; e < E; e++) {
        uint32_t a = m->halfedges[2 * e].origin, b = m->halfedges[2 * e + 1].origin;
        if (a < CG_HEMESH_DELETED)
            start[(a < b ? a : b) + 1]++;
    }
    for (size_t v = 0; v < V; v++)
        start[v + 1] += start[v];
    for (size_t e = 0; e < E; e++) {
        uint32_t a = m->halfedges[2 * e].origin, b = m->halfedges[2 * e + 1].origin;
        if (a < CG_HEMESH_DELETED)
            sorted[start[a < b ? a : b]++] = (uint32_t)e;
    }
    memset(stamp, 0xff, (V ? V : 1) * sizeof *stamp);
    for (size_t v = 0; v < V; v++)
        for (uint32_t i = v ? start[v - 1] : 0; i < start[v]; i++) {
            uint32_t e = sorted[i];
            uint32_t a = m->halfedges[2 * e].origin, b = m->halfedges[2 * e + 1].origin;
            uint32_t other = a == v ? b : a;
            if (stamp[other] != (uint32_t)v) {
                stamp[other] = (uint32_t)v;
                continue;
            }
            if ((n & (n - 1)) == 0) { /* capacity doubles at powers of two */
                uint32_t *p = realloc(found, (n ? 2 * n : 1) * sizeof *p);
                if (!p) {
                    status = CG_ENOMEM;
                    goto done;
                }
                found = p;
            }
            found[n++] = e;
        }
done:
    free(start);
    free(sorted);
    free(stamp);
    if (status != CG_OK) {
        free(found);
        found = NULL;
        n = 0;
    }
    *list = found;
    *count = n;
    return status;
}

/* Lists the edges at the vertices from first on that join a vertex an
 * earlier edge around it already joins (the only ones a split can add). */
static cg_status separate_find_new(const cg_hemesh *m, size_t first, uint32_t **list, size_t *count)
{
    size_t V = m->vertex_count;
    uint32_t *stamp = malloc((V ? V : 1) * sizeof *stamp);
    uint32_t *found = NULL;
    size_t n = 0;
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
            } else {
                if ((n & (n - 1)) == 0) {
                    uint32_t *p = realloc(found, (n ? 2 * n : 1) * sizeof *p);
                    if (!p) {
                        free(found);
                        free(stamp);
                        return CG_ENOMEM;
                    }
                    found = p;
                }
                found[n++] = h >> 1;
            }
            h = cg_hemesh_cw(m, h);
        } while (h != h0);
    }
    free(stamp);
    *list = found;
    *count = n;
    return CG_OK;
}

cg_status hm_split_multiple_edges(cg_hemesh *m, size_t *split, uint32_t **face_origin)
{
    *split = 0;
    *face_origin = NULL;
    size_t first_new_face = m->face_count;
    /* A split joins the new vertex to the opposite corners of its triangles;
     * when both are one vertex those two new edges coincide, and the next
     * round splits one of them (whose opposite corners differ).  Later
     * rounds look only at the vertices the last one added. */
    size_t first_new_vertex = 0;
    for (int round = 0; round < 8; round++) {
        uint32_t *list;
        size_t n, vertices = m->vertex_count;
        cg_status s = round ? separate_find_new(m, first_new_vertex, &list, &n) : separate_find(m, &list, &n);
        first_new_vertex = vertices;
        if (s != CG_OK)
            return s;
        if (!n)
            return CG_OK;
        s = hm_reserve(m, n, 3 * n, 2 * n);
        uint32_t *grown = s == CG_OK ? realloc(*face_origin, (m->face_count + 2 * n - first_new_face + 1)
                                                                 * sizeof *grown)
                                     : NULL;
        if (!grown) {
            free(list);
            return s == CG_OK ? CG_ENOMEM : s;
        }
        *face_origin = grown;
        for (size_t i = 0; i < n; i++) {
            uint32_t e = list[i], h = 2 * e;
            uint32_t sides[2] = {m->halfedges[h].face, m->halfedges[h + 1].face};
            cg_vec3 p = m->positions[m->halfedges[h].origin], q = m->positions[m->halfedges[h + 1].origin];
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
