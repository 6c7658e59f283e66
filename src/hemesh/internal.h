/* Private pieces shared by the half-edge files. */
#ifndef CG_HEMESH_INTERNAL_H
#define CG_HEMESH_INTERNAL_H

#include "cg/hemesh.h"

/* Attribute arrays to allocate, as the CG_MESH_* flags of cg_mesh_create. */
cg_status hm_create(cg_hemesh **out, size_t vertices, size_t halfedges, size_t faces,
                    unsigned attribute_flags);
/* The CG_MESH_* flags of the attributes m has. */
unsigned hm_attribute_flags(const cg_hemesh *m);

/* Room for `extra` more elements; CG_ENOMEM or CG_ERANGE (indices would
 * reach CG_HEMESH_DELETED) on failure, leaving m unchanged. */
cg_status hm_reserve(cg_hemesh *m, size_t extra_vertices, size_t extra_edges, size_t extra_faces);
/* Gives back the room beyond the counts (the growth of a repairing build). */
void hm_shrink_to_fit(cg_hemesh *m);
/* Appends elements (room must have been reserved); returns the index (the
 * first half-edge for an edge).  New elements are zeroed / NONE. */
uint32_t hm_add_vertex(cg_hemesh *m, cg_vec3 position);
uint32_t hm_add_edge(cg_hemesh *m, uint32_t origin, uint32_t destination);
uint32_t hm_add_face(cg_hemesh *m, uint32_t halfedge, uint32_t color_from);

/* Vertex attributes of dst become the weighted sum of those of src (n terms). */
void hm_blend_attributes(cg_hemesh *m, uint32_t dst, const uint32_t *src, const double *weight,
                         size_t n);

/* The root of v in a union-find forest over the vertices (parent[r] == r
 * at a root), halving the path on the way. */
static inline uint32_t hm_find_root(uint32_t *parent, uint32_t v)
{
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

/* Points vertex_halfedge[v] at a boundary outgoing half-edge when there is
 * one, rotating from its current (live) half-edge. */
void hm_fix_vertex_halfedge(cg_hemesh *m, uint32_t v);

/* Sorts the n entries of the bucket of vertex lo (other << 32 | corner << 1
 * | direction) by other vertex and, in groups of three or more sides (uses
 * holds each group's size), by angle about the edge, so that pairing them
 * in turn pairs neighbours across a solid (see radial.c); offsets and
 * indices are the faces' (faces of them).  CG_ENOMEM. */
cg_status hm_radial_sort_bucket(const cg_mesh *mesh, const uint32_t *offsets,
                                const uint32_t *indices, size_t faces, uint32_t lo,
                                uint64_t *entries, size_t n, const uint32_t *uses);

/* Splits at its midpoint every edge that joins the same two vertices as
 * another, until no two do (see separate.c).  Such a pair always holds an
 * edge the build opened for an extra side: candidates lists those.
 * *split receives the number of splits, *face_origin (malloc'ed, may be
 * NULL) for each face added, the face it was split from.  CG_ENOMEM. */
cg_status hm_split_multiple_edges(cg_hemesh *m, const uint32_t *candidates, size_t candidate_count,
                                  size_t *split, uint32_t **face_origin);

#endif
