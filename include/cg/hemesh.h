/* cg/hemesh.h - the half-edge structure (doubly connected edge list) of
 * chapter 9: polygon meshes with boundary, their traversals, counts, local
 * operations and subdivision.
 *
 * Layout.  Everything is an index into plain arrays (no pointers), so the
 * structure is compact, cache-friendly and can be copied with memcpy:
 *  - half-edge h has next, prev, origin and face (16 bytes).  The two
 *    half-edges of edge e are 2e and 2e + 1, so the twin of h is h ^ 1 and is
 *    not stored; the edge of h is h / 2.
 *  - vertex v has one outgoing half-edge vertex_halfedge[v] (CG_HEMESH_NONE
 *    for an isolated vertex) and its position and optional attributes.
 *  - face f has one half-edge face_halfedge[f] of its loop.
 * A boundary half-edge has face CG_HEMESH_NONE; boundary half-edges form the
 * boundary loops through next and prev.  When a vertex is on the boundary its
 * vertex_halfedge is a boundary half-edge, so cg_hemesh_vertex_is_boundary is
 * O(1) and rotating from it visits the whole fan.
 *
 * Faces are counter-clockwise seen from the front, as in cg_mesh.  Rotating
 * around a vertex: cg_hemesh_ccw(h) = twin(prev(h)) is the next outgoing
 * half-edge counter-clockwise, cg_hemesh_cw(h) = next(twin(h)) clockwise.
 *
 * The two halves of edge e = 3, between vertices a and b:
 *
 *              b
 *             /|\        half-edge 6 = 2e runs a -> b, face f on its left
 *            / | \       half-edge 7 = 2e + 1 runs b -> a, face g on its left
 *   face f  /  ^ v  \  face g
 *          /  6| |7  \  edge(6) = edge(7) = 6 / 2 = 7 / 2 = 3
 *              a
 *
 *     halfedges[6] = {next, prev, origin a, face f}
 *     halfedges[7] = {next, prev, origin b, face g}
 *     twin(6) = 6 ^ 1 = 7 and twin(7) = 7 ^ 1 = 6: flipping the lowest bit
 *     moves between the halves, so no twin is stored.
 *
 * Deletion (edge collapse, vertex and face removal) marks elements with
 * CG_HEMESH_DELETED and keeps the indices of everything else; the live counts
 * are kept up to date, and cg_hemesh_compact renumbers densely.
 *
 * The structure is 2-manifold along edges (at most two faces per edge).  A
 * vertex may join several boundary fans only as the result of face removal
 * (a "complex" vertex); the build splits such vertices when asked. */
#ifndef CG_HEMESH_H
#define CG_HEMESH_H

#include "cg/core.h"
#include "cg/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CG_HEMESH_NONE 0xffffffffu    /* no face (boundary), no half-edge (isolated) */
#define CG_HEMESH_DELETED 0xfffffffeu /* element removed by an operation */

typedef struct cg_hemesh_halfedge {
    uint32_t next, prev, origin, face;
} cg_hemesh_halfedge;

typedef struct cg_hemesh {
    size_t vertex_count;   /* array lengths, deleted elements included */
    size_t halfedge_count; /* always even: 2 * number of edge slots */
    size_t face_count;
    size_t live_vertices, live_edges, live_faces; /* not deleted */

    cg_hemesh_halfedge *halfedges;
    uint32_t *vertex_halfedge;
    uint32_t *face_halfedge;

    cg_vec3 *positions;    /* vertex_count */
    cg_vec3 *normals;      /* vertex_count, or NULL */
    cg_vec2 *texcoords;    /* vertex_count, or NULL */
    cg_rgbaf *colors;      /* vertex_count, or NULL */
    cg_rgbaf *face_colors; /* face_count, or NULL */

    size_t vertex_capacity, halfedge_capacity, face_capacity;
} cg_hemesh;

/* ---- building ----------------------------------------------------------- */

/* Build options (bits). */
enum {
    /* Leave out faces with fewer than 3 corners, a vertex index out of range
     * or a vertex repeated; otherwise such a face is an error. */
    CG_HEMESH_DROP_BAD_FACES = 1,
    /* Reverse faces so that each connected component is consistently
     * oriented (the orientation of its first face wins); where a component is
     * not orientable (a Moebius strip) the edges that disagree stay
     * disagreeing and need CG_HEMESH_SPLIT_NONMANIFOLD. */
    CG_HEMESH_ORIENT = 2,
    /* Make the result manifold: an edge used by more than two faces, or by
     * two faces in the same direction, keeps its first opposite pair and the
     * other uses become separate boundary edges; a vertex whose faces form
     * several fans becomes one vertex per fan (attributes copied). */
    CG_HEMESH_SPLIT_NONMANIFOLD = 4,
    CG_HEMESH_REPAIR = 7
};

/* What the build found in the input and what it changed.  Lists hold input
 * indices (faces and vertices of the cg_mesh), in increasing order. */
typedef struct cg_hemesh_report {
    size_t bad_face_count; /* faces too small, out of range or repeating a vertex */
    uint32_t *bad_faces;
    size_t nonmanifold_edge_count;   /* edges on more than two faces */
    uint32_t *nonmanifold_edges;     /* 2 per edge: its vertices, smaller first */
    size_t misoriented_edge_count;   /* edges two faces traverse the same way */
    size_t nonmanifold_vertex_count; /* vertices whose faces form more than one fan */
    uint32_t *nonmanifold_vertices;
    size_t isolated_vertex_count; /* vertices on no face (kept, as isolated vertices) */
    size_t flipped_face_count;    /* faces reversed by CG_HEMESH_ORIENT */
    size_t cut_edge_count;        /* extra edge uses made boundary by the split */
    size_t added_vertex_count;    /* vertices created by splitting vertices */
    /* edges split at their midpoint because, after the cut, another edge
     * joined the same two vertices (an indexed mesh names an edge by its
     * vertices: so the result converts to a manifold cg_mesh) */
    size_t split_edge_count;
    int orientable;     /* 0 when a component could not be oriented */
    uint32_t *face_map; /* for each hemesh face, the input face it came from */
} cg_hemesh_report;

/* Frees the lists of a report and zeroes it (report may be NULL). */
void cg_hemesh_report_clear(cg_hemesh_report *report);

/* Builds the half-edge structure of mesh in linear time.  flags is a set of
 * CG_HEMESH_* options (0 is strict: any defect is an error).  report (may be
 * NULL) receives what was found, also on failure (free its lists with
 * cg_hemesh_report_clear either way); err (may be NULL) a one-line message
 * naming the first defect and the option that repairs it.
 * Errors: CG_EINVAL (NULL mesh), CG_EEMPTY (no usable face), CG_EFORMAT
 * (a defect the flags do not repair), CG_ERANGE, CG_ENOMEM. */
cg_status cg_hemesh_build(const cg_mesh *mesh, unsigned flags, cg_hemesh **out,
                          cg_hemesh_report *report, cg_error *err);

/* An indexed mesh with the live vertices (renumbered densely, isolated ones
 * kept) and faces, with every attribute the structure has. */
cg_status cg_hemesh_to_mesh(const cg_hemesh *hemesh, cg_mesh **out);

cg_status cg_hemesh_copy(const cg_hemesh *hemesh, cg_hemesh **out);
void cg_hemesh_free(cg_hemesh *hemesh);

/* Removes deleted elements and renumbers the rest densely, keeping order. */
void cg_hemesh_compact(cg_hemesh *hemesh);

/* Checks every invariant: array sizes and live counts, each reference in
 * range and not deleted, twin(twin(h)) = h with the two halves apart,
 * next(prev(h)) = prev(next(h)) = h, origin(next(h)) = origin(twin(h)),
 * one face along each loop, every face loop at least 3 long with no
 * repeated vertex, no edge without a face on either side, each vertex's
 * rotation visiting exactly its outgoing half-edges, and a boundary
 * half-edge for every boundary vertex.  CG_EFORMAT with the first broken
 * invariant in err. */
cg_status cg_hemesh_validate(const cg_hemesh *hemesh, cg_error *err);

/* ---- navigation (O(1)) -------------------------------------------------- */

static inline uint32_t cg_hemesh_twin(uint32_t h)
{
    return h ^ 1u;
}
static inline uint32_t cg_hemesh_edge(uint32_t h)
{
    return h >> 1;
}
static inline uint32_t cg_hemesh_next(const cg_hemesh *m, uint32_t h)
{
    return m->halfedges[h].next;
}
static inline uint32_t cg_hemesh_prev(const cg_hemesh *m, uint32_t h)
{
    return m->halfedges[h].prev;
}
static inline uint32_t cg_hemesh_origin(const cg_hemesh *m, uint32_t h)
{
    return m->halfedges[h].origin;
}
static inline uint32_t cg_hemesh_dest(const cg_hemesh *m, uint32_t h)
{
    return m->halfedges[h ^ 1u].origin;
}
static inline uint32_t cg_hemesh_face(const cg_hemesh *m, uint32_t h)
{
    return m->halfedges[h].face;
}
/* Next outgoing half-edge around origin(h), counter-clockwise / clockwise. */
static inline uint32_t cg_hemesh_ccw(const cg_hemesh *m, uint32_t h)
{
    return m->halfedges[h].prev ^ 1u;
}
static inline uint32_t cg_hemesh_cw(const cg_hemesh *m, uint32_t h)
{
    return m->halfedges[h ^ 1u].next;
}
static inline int cg_hemesh_halfedge_is_boundary(const cg_hemesh *m, uint32_t h)
{
    return m->halfedges[h].face == CG_HEMESH_NONE;
}
static inline int cg_hemesh_edge_is_boundary(const cg_hemesh *m, uint32_t e)
{
    return m->halfedges[2 * e].face == CG_HEMESH_NONE
           || m->halfedges[2 * e + 1].face == CG_HEMESH_NONE;
}
static inline int cg_hemesh_vertex_is_boundary(const cg_hemesh *m, uint32_t v)
{
    uint32_t h = m->vertex_halfedge[v];
    return h < CG_HEMESH_DELETED && m->halfedges[h].face == CG_HEMESH_NONE;
}
static inline int cg_hemesh_vertex_is_deleted(const cg_hemesh *m, uint32_t v)
{
    return m->vertex_halfedge[v] == CG_HEMESH_DELETED;
}
static inline int cg_hemesh_face_is_deleted(const cg_hemesh *m, uint32_t f)
{
    return m->face_halfedge[f] == CG_HEMESH_DELETED;
}
static inline int cg_hemesh_edge_is_deleted(const cg_hemesh *m, uint32_t e)
{
    return m->halfedges[2 * e].origin == CG_HEMESH_DELETED;
}
/* The half-edge from u to v, or CG_HEMESH_NONE; O(valence of u). */
uint32_t cg_hemesh_find_halfedge(const cg_hemesh *m, uint32_t u, uint32_t v);

/* ---- traversals: O(size of the answer) ---------------------------------
 * Each writes at most capacity entries to out (out may be NULL when capacity
 * is 0) and returns the full count, so a first call with capacity 0 sizes
 * the array.  direction > 0 walks counter-clockwise, otherwise clockwise.
 * Around a boundary vertex the walk starts at its boundary half-edge. */
size_t cg_hemesh_face_halfedges(const cg_hemesh *m, uint32_t f, uint32_t *out, size_t capacity);
size_t cg_hemesh_face_vertices(const cg_hemesh *m, uint32_t f, uint32_t *out, size_t capacity);
/* Faces across each edge of f (boundary edges skipped). */
size_t cg_hemesh_face_neighbors(const cg_hemesh *m, uint32_t f, uint32_t *out, size_t capacity);
size_t cg_hemesh_vertex_outgoing(const cg_hemesh *m, uint32_t v, int direction, uint32_t *out,
                                 size_t capacity);
size_t cg_hemesh_vertex_neighbors(const cg_hemesh *m, uint32_t v, int direction, uint32_t *out,
                                  size_t capacity);
/* Faces around v (the boundary gap skipped). */
size_t cg_hemesh_vertex_faces(const cg_hemesh *m, uint32_t v, int direction, uint32_t *out,
                              size_t capacity);
/* The average of the neighbours of every vertex (the umbrella operator of
 * Laplacian smoothing): one one-ring traversal of every vertex, O(E).  out
 * has vertex_count entries; isolated and deleted vertices get their own
 * position. */
cg_status cg_hemesh_neighbor_average(const cg_hemesh *m, cg_vec3 *out);
/* Number of edges at v (0 for isolated or deleted vertices). */
size_t cg_hemesh_valence(const cg_hemesh *m, uint32_t v);
/* Number of sides of face f. */
size_t cg_hemesh_face_size(const cg_hemesh *m, uint32_t f);

/* ---- counts and geometry ------------------------------------------------ */

typedef struct cg_hemesh_stats {
    size_t vertices, edges, faces; /* live; isolated vertices included */
    size_t isolated_vertices;
    size_t boundary_loops;
    size_t components;         /* connected components, an isolated vertex is one */
    long euler_characteristic; /* V - E + F */
    /* Genus of each component with faces: (2 - chi - boundary loops) / 2,
     * for orientable surfaces.  genus is that value when all agree, and -1
     * when they differ (then component_genus lists them) or none has faces. */
    long genus;
    size_t complex_vertices; /* vertices with more than one boundary gap */
    int all_triangles, all_quads;
} cg_hemesh_stats;

/* Counts in O(V + E + F).  component_genus (may be NULL) receives a malloc'ed
 * array of the genus of each component with faces, in order of their lowest
 * face; *component_genus_count its length. */
cg_status cg_hemesh_stats_compute(const cg_hemesh *m, cg_hemesh_stats *out, long **component_genus,
                                  size_t *component_genus_count);

/* Counts of an indexed mesh as it was read, before any repair.  faces are
 * the polygons the build accepts (3 or more corners, indices in range, no
 * vertex twice; the others are bad_faces); edges the distinct unordered
 * vertex pairs joined by a side of one of them; components the classes of
 * vertices joined through shared faces (an isolated vertex is one);
 * euler_characteristic V - E + F of these. */
typedef struct cg_hemesh_input_counts {
    size_t vertices, edges, faces, bad_faces;
    size_t isolated_vertices;
    size_t components;
    long euler_characteristic;
} cg_hemesh_input_counts;

/* Counts mesh's topology in O(V + corners), independently of the build.
 * CG_EINVAL (NULL or inconsistent arrays), CG_ERANGE, CG_ENOMEM. */
cg_status cg_hemesh_input_counts_compute(const cg_mesh *mesh, cg_hemesh_input_counts *out);

/* Newell's normal of face f: its direction is the unit normal and its length
 * twice the area for a planar polygon. */
cg_vec3 cg_hemesh_face_newell(const cg_hemesh *m, uint32_t f);
/* Unit normal (zero for a degenerate face) and area of face f. */
cg_vec3 cg_hemesh_face_normal(const cg_hemesh *m, uint32_t f);
double cg_hemesh_face_area(const cg_hemesh *m, uint32_t f);
/* Area-weighted average of the normals of the faces around v, normalized. */
cg_vec3 cg_hemesh_vertex_normal(const cg_hemesh *m, uint32_t v);
/* Fills hemesh->normals (allocating it when absent) with vertex normals. */
cg_status cg_hemesh_compute_normals(cg_hemesh *m);

/* ---- operations ----------------------------------------------------------
 * Each leaves a valid structure, or returns CG_EINVAL (not allowed there,
 * for the reasons listed with each) or CG_ENOMEM, changing nothing. */

/* Turns the edge e between two triangles (a, b, c) and (b, a, d) into the
 * edge (c, d).  Refused on boundary edges, non-triangles, and when c and d
 * are already joined. */
cg_status cg_hemesh_flip_edge(cg_hemesh *m, uint32_t e);

/* Inserts a new vertex at position on edge e (attributes averaged from its
 * ends) and joins it to the opposite corner of each adjacent triangle, so a
 * triangle mesh stays triangular; a larger face just gains a corner.
 * *new_vertex (may be NULL) receives the vertex. */
cg_status cg_hemesh_split_edge(cg_hemesh *m, uint32_t e, cg_vec3 position, uint32_t *new_vertex);

/* Collapses half-edge h: its origin u is removed and its edges join its
 * destination v (which keeps its position).  Adjacent triangles vanish; a
 * larger adjacent face loses a corner.  Refused when the link condition
 * fails (a vertex other than the opposite corners of the adjacent triangles
 * is joined to both u and v), when u and v are both on the boundary but the
 * edge is not, when an opposite corner would be left with valence 2 or a
 * dangling edge, and at complex vertices. */
cg_status cg_hemesh_collapse_edge(cg_hemesh *m, uint32_t h);
/* Whether cg_hemesh_collapse_edge(m, h) would be accepted. */
int cg_hemesh_collapse_ok(const cg_hemesh *m, uint32_t h);

/* Inserts a vertex at position inside face f and joins it to every corner:
 * a k-gon becomes k triangles. */
cg_status cg_hemesh_split_face(cg_hemesh *m, uint32_t f, cg_vec3 position, uint32_t *new_vertex);

/* Splits the face of half-edges p and q by a new edge from origin(p) to
 * origin(q): p's side keeps the face, q's side becomes a new face
 * (*new_face, may be NULL).  Refused unless p and q lie on the same face,
 * their origins are not neighbours along it and not already joined. */
cg_status cg_hemesh_split_face_between(cg_hemesh *m, uint32_t p, uint32_t q, uint32_t *new_face);

/* Removes face f; its edges become boundary, edges left with no face and
 * vertices left with no edge are deleted. */
cg_status cg_hemesh_remove_face(cg_hemesh *m, uint32_t f);
/* Removes vertex v with every face and edge around it, leaving a hole (on
 * CG_ENOMEM some of its faces may already be gone; the structure stays valid). */
cg_status cg_hemesh_remove_vertex(cg_hemesh *m, uint32_t v);

/* ---- subdivision ---------------------------------------------------------
 * Each step builds a new structure directly from the old one (no hashing):
 * one new vertex per edge (and per face for Catmull-Clark), each old
 * half-edge split in two.  Boundaries follow the cubic B-spline rules
 * (boundary edge point: midpoint; boundary vertex: 3/4 v + 1/8 of its two
 * boundary neighbours).  Texture coordinates and colours of new vertices
 * are interpolated linearly (edge midpoints, face centroids), old vertices
 * keep theirs, face colours are inherited and normals recomputed when
 * present.  A structure with deleted elements is compacted (on a copy)
 * first.  CG_ERANGE when the result would not fit 32-bit indices. */

/* Loop (1987): interior vertex (1 - n beta) v + beta sum of neighbours with
 * beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n; interior edge point
 * 3/8 (a + b) + 1/8 (c + d).  Triangles only: CG_EUNSUPPORTED otherwise. */
cg_status cg_hemesh_subdivide_loop(const cg_hemesh *m, cg_hemesh **out);
/* Catmull-Clark (1978): face point the centroid; interior edge point
 * (a + b + f1 + f2) / 4; interior vertex (F + 2R + (n - 3) P) / n with F the
 * average of the face points and R of the edge midpoints around P.  Any
 * polygons; the result is all quads. */
cg_status cg_hemesh_subdivide_catmull_clark(const cg_hemesh *m, cg_hemesh **out);

#ifdef __cplusplus
}
#endif
#endif
