/* Step 4 of the half-edge build: the structure itself (build.h).  Face
 * loops are linked; each boundary half-edge is linked to the next by
 * rotating about its end vertex; the fans of each vertex are the cycles of
 * the rotation, and a vertex with several is split (or is an error). */
#include "build.h"

#include <stdlib.h>
#include <string.h>

/* Step 4: the structure itself. */

/* The half-edge structure with the edges of the matching, their links not
 * yet made, and room for the midpoint splits that cut edges may need. */
static cg_status create_structure(const hm_builder *b, cg_hemesh **out)
{
    const cg_mesh *mesh = b->mesh;
    size_t V = mesh->vertex_count, F = b->faces, H = 2 * b->edges;
    unsigned flags = (mesh->normals ? CG_MESH_NORMALS : 0u)
                     | (mesh->texcoords ? CG_MESH_TEXCOORDS : 0u)
                     | (mesh->colors ? CG_MESH_COLORS : 0u)
                     | (mesh->face_colors ? CG_MESH_FACE_COLORS : 0u);
    cg_hemesh *m;
    /* room for the midpoint splits that cut edges may need (about one per
     * cut: 3 edges and 2 faces each), so that they do not grow the arrays;
     * what is left over is given back at the end of the build */
    size_t room = b->cut && H + 6 * b->cut < 0x7fffffffu && F + 2 * b->cut < 0x7fffffffu ? b->cut
                                                                                         : 0;
    cg_status s = hm_create(&m, V, H + 6 * room, F + 2 * room, flags);
    if (s != CG_OK)
        return cg_error_set(b->err, s, "hemesh: %s",
                            s == CG_ERANGE ? "too many elements" : "out of memory");
    m->halfedge_count = H;
    m->face_count = F;
    for (size_t e = 0; e < b->edges; e++) {
        cg_hemesh_halfedge x = {CG_HEMESH_NONE, CG_HEMESH_NONE, b->edge_vertices[2 * e],
                                CG_HEMESH_NONE};
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
static void link_loops(const hm_builder *b, cg_hemesh *m, uint32_t *rotation, uint64_t *on_boundary)
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
static void find_fans(hm_builder *b, cg_hemesh *m, const uint32_t *rotation, uint64_t *seen,
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
        hm_list_push(extra, count, capacity, pick, failed);
    }
}

/* Counts the distinct vertices of the extra fans (each fan's vertex is its
 * first half-edge's origin) into *vertices with the smallest in *first, and
 * lists them in the report. */
static void count_fan_vertices(hm_builder *b, const cg_hemesh *m, const uint32_t *extra,
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
                hm_list_push(&rep->nonmanifold_vertices, &rep->nonmanifold_vertex_count,
                             &b->nonmanifold_vertex_capacity, (uint32_t)v, failed);
    free(mark);
}

/* The attributes of the input vertices and faces. */
static void copy_attributes(const hm_builder *b, cg_hemesh *m)
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

cg_status hm_build_assemble(hm_builder *b, cg_hemesh **out)
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
        count_fan_vertices(b, m, extra_fans, extra_count, &nonmanifold_vertices, &first_bad_vertex,
                           &failed);
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
