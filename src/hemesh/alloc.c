/* Allocation, growth, copying, compaction and conversion of the half-edge
 * structure. */
#include "internal.h"
#include "../core/array.h"

#include <stdlib.h>
#include <string.h>

/* Grows *array (when there is one: attributes are optional) from capacity
 * to room for `needed` elements with the growth policy of src/core/array.h,
 * zeroing the new room; *grown_capacity receives the new capacity.  The
 * policy depends only on (capacity, needed), so parallel arrays grown from
 * the same capacity end with the same one. */
static cg_status grow_array(void **array, size_t element, size_t capacity, size_t needed,
                            size_t *grown_capacity)
{
    if (!*array)
        return CG_OK;
    size_t room = capacity;
    if (core_array_reserve(array, &room, needed, element) != CG_OK)
        return CG_ENOMEM;
    memset((char *)*array + capacity * element, 0, (room - capacity) * element);
    *grown_capacity = room;
    return CG_OK;
}

unsigned hm_attribute_flags(const cg_hemesh *m)
{
    return (m->normals ? CG_MESH_NORMALS : 0u) | (m->texcoords ? CG_MESH_TEXCOORDS : 0u)
           | (m->colors ? CG_MESH_COLORS : 0u) | (m->face_colors ? CG_MESH_FACE_COLORS : 0u);
}

cg_status hm_create(cg_hemesh **out, size_t vertices, size_t halfedges, size_t faces,
                    unsigned flags)
{
    *out = NULL;
    if (vertices >= CG_HEMESH_DELETED || halfedges >= CG_HEMESH_DELETED
        || faces >= CG_HEMESH_DELETED)
        return CG_ERANGE;
    cg_hemesh *m = calloc(1, sizeof *m);
    if (!m)
        return CG_ENOMEM;
    size_t vc = vertices ? vertices : 1, hc = halfedges ? halfedges : 2, fc = faces ? faces : 1;
    m->vertex_capacity = vc;
    m->halfedge_capacity = hc;
    m->face_capacity = fc;
    m->halfedges = malloc(hc * sizeof *m->halfedges);
    m->vertex_halfedge = malloc(vc * sizeof *m->vertex_halfedge);
    m->face_halfedge = malloc(fc * sizeof *m->face_halfedge);
    m->positions = malloc(vc * sizeof *m->positions);
    int failed = !m->halfedges || !m->vertex_halfedge || !m->face_halfedge || !m->positions;
    if (flags & CG_MESH_NORMALS)
        failed |= !(m->normals = calloc(vc, sizeof *m->normals));
    if (flags & CG_MESH_TEXCOORDS)
        failed |= !(m->texcoords = calloc(vc, sizeof *m->texcoords));
    if (flags & CG_MESH_COLORS)
        failed |= !(m->colors = calloc(vc, sizeof *m->colors));
    if (flags & CG_MESH_FACE_COLORS)
        failed |= !(m->face_colors = calloc(fc, sizeof *m->face_colors));
    if (failed) {
        cg_hemesh_free(m);
        return CG_ENOMEM;
    }
    m->vertex_count = vertices;
    m->halfedge_count = halfedges;
    m->face_count = faces;
    *out = m;
    return CG_OK;
}

void cg_hemesh_free(cg_hemesh *m)
{
    if (!m)
        return;
    free(m->halfedges);
    free(m->vertex_halfedge);
    free(m->face_halfedge);
    free(m->positions);
    free(m->normals);
    free(m->texcoords);
    free(m->colors);
    free(m->face_colors);
    free(m);
}

cg_status hm_reserve(cg_hemesh *m, size_t extra_vertices, size_t extra_edges, size_t extra_faces)
{
    size_t nv = m->vertex_count + extra_vertices, nh = m->halfedge_count + 2 * extra_edges,
           nf = m->face_count + extra_faces;
    if (nv >= CG_HEMESH_DELETED || nh >= CG_HEMESH_DELETED || nf >= CG_HEMESH_DELETED)
        return CG_ERANGE;
    /* The arrays of one kind share one capacity: it is updated only once
     * all of them have grown. */
    if (nv > m->vertex_capacity) {
        size_t old = m->vertex_capacity, c = old;
        void *vh = m->vertex_halfedge, *pos = m->positions;
        void *nor = m->normals, *tex = m->texcoords, *col = m->colors;
        cg_status s = grow_array(&vh, sizeof *m->vertex_halfedge, old, nv, &c);
        m->vertex_halfedge = vh;
        if (s == CG_OK)
            s = grow_array(&pos, sizeof *m->positions, old, nv, &c);
        m->positions = pos;
        if (s == CG_OK)
            s = grow_array(&nor, sizeof *m->normals, old, nv, &c);
        m->normals = nor;
        if (s == CG_OK)
            s = grow_array(&tex, sizeof *m->texcoords, old, nv, &c);
        m->texcoords = tex;
        if (s == CG_OK)
            s = grow_array(&col, sizeof *m->colors, old, nv, &c);
        m->colors = col;
        if (s != CG_OK)
            return s;
        m->vertex_capacity = c;
    }
    if (nh > m->halfedge_capacity) {
        size_t c = m->halfedge_capacity;
        void *he = m->halfedges;
        cg_status s = grow_array(&he, sizeof *m->halfedges, m->halfedge_capacity, nh, &c);
        m->halfedges = he;
        if (s != CG_OK)
            return s;
        m->halfedge_capacity = c;
    }
    if (nf > m->face_capacity) {
        size_t old = m->face_capacity, c = old;
        void *fh = m->face_halfedge, *fcol = m->face_colors;
        cg_status s = grow_array(&fh, sizeof *m->face_halfedge, old, nf, &c);
        m->face_halfedge = fh;
        if (s == CG_OK)
            s = grow_array(&fcol, sizeof *m->face_colors, old, nf, &c);
        m->face_colors = fcol;
        if (s != CG_OK)
            return s;
        m->face_capacity = c;
    }
    return CG_OK;
}

/* realloc to n elements of size bytes, keeping the block when that fails */
static void shrink_array(void **p, size_t size, size_t n)
{
    if (!*p || !n)
        return;
    void *q = realloc(*p, n * size);
    if (q)
        *p = q;
}

void hm_shrink_to_fit(cg_hemesh *m)
{
    size_t V = m->vertex_count, H = m->halfedge_count, F = m->face_count;
    void *p;
    if (V && V < m->vertex_capacity) {
        p = m->vertex_halfedge, shrink_array(&p, sizeof *m->vertex_halfedge, V),
        m->vertex_halfedge = p;
        p = m->positions, shrink_array(&p, sizeof *m->positions, V), m->positions = p;
        p = m->normals, shrink_array(&p, sizeof *m->normals, V), m->normals = p;
        p = m->texcoords, shrink_array(&p, sizeof *m->texcoords, V), m->texcoords = p;
        p = m->colors, shrink_array(&p, sizeof *m->colors, V), m->colors = p;
        m->vertex_capacity = V;
    }
    if (H && H < m->halfedge_capacity) {
        p = m->halfedges, shrink_array(&p, sizeof *m->halfedges, H), m->halfedges = p;
        m->halfedge_capacity = H;
    }
    if (F && F < m->face_capacity) {
        p = m->face_halfedge, shrink_array(&p, sizeof *m->face_halfedge, F), m->face_halfedge = p;
        p = m->face_colors, shrink_array(&p, sizeof *m->face_colors, F), m->face_colors = p;
        m->face_capacity = F;
    }
}

uint32_t hm_add_vertex(cg_hemesh *m, cg_vec3 position)
{
    uint32_t v = (uint32_t)m->vertex_count++;
    m->vertex_halfedge[v] = CG_HEMESH_NONE;
    m->positions[v] = position;
    if (m->normals)
        m->normals[v] = cg_vec3_make(0, 0, 0);
    if (m->texcoords)
        m->texcoords[v] = cg_vec2_make(0, 0);
    if (m->colors)
        memset(&m->colors[v], 0, sizeof m->colors[v]);
    m->live_vertices++;
    return v;
}

uint32_t hm_add_edge(cg_hemesh *m, uint32_t origin, uint32_t destination)
{
    uint32_t h = (uint32_t)m->halfedge_count;
    m->halfedge_count += 2;
    cg_hemesh_halfedge a = {CG_HEMESH_NONE, CG_HEMESH_NONE, origin, CG_HEMESH_NONE};
    cg_hemesh_halfedge b = {CG_HEMESH_NONE, CG_HEMESH_NONE, destination, CG_HEMESH_NONE};
    m->halfedges[h] = a;
    m->halfedges[h + 1] = b;
    m->live_edges++;
    return h;
}

uint32_t hm_add_face(cg_hemesh *m, uint32_t halfedge, uint32_t color_from)
{
    uint32_t f = (uint32_t)m->face_count++;
    m->face_halfedge[f] = halfedge;
    if (m->face_colors)
        m->face_colors[f] = m->face_colors[color_from];
    m->live_faces++;
    return f;
}

void hm_blend_attributes(cg_hemesh *m, uint32_t dst, const uint32_t *src, const double *weight,
                         size_t n)
{
    if (m->normals) {
        cg_vec3 s = {0, 0, 0};
        for (size_t i = 0; i < n; i++)
            s = cg_vec3_add(s, cg_vec3_scale(m->normals[src[i]], weight[i]));
        m->normals[dst] = cg_vec3_normalize(s);
    }
    if (m->texcoords) {
        cg_vec2 s = {0, 0};
        for (size_t i = 0; i < n; i++)
            s = cg_vec2_add(s, cg_vec2_scale(m->texcoords[src[i]], weight[i]));
        m->texcoords[dst] = s;
    }
    if (m->colors) {
        cg_rgbaf s = {0, 0, 0, 0};
        for (size_t i = 0; i < n; i++) {
            s.r += (float)weight[i] * m->colors[src[i]].r;
            s.g += (float)weight[i] * m->colors[src[i]].g;
            s.b += (float)weight[i] * m->colors[src[i]].b;
            s.a += (float)weight[i] * m->colors[src[i]].a;
        }
        m->colors[dst] = s;
    }
}

void hm_fix_vertex_halfedge(cg_hemesh *m, uint32_t v)
{
    uint32_t h0 = m->vertex_halfedge[v];
    if (h0 >= CG_HEMESH_DELETED)
        return;
    uint32_t h = h0;
    do {
        if (m->halfedges[h].face == CG_HEMESH_NONE) {
            m->vertex_halfedge[v] = h;
            return;
        }
        h = cg_hemesh_ccw(m, h);
    } while (h != h0);
}

cg_status cg_hemesh_copy(const cg_hemesh *m, cg_hemesh **out)
{
    if (!m || !out)
        return CG_EINVAL;
    cg_hemesh *c;
    cg_status s = hm_create(&c, m->vertex_count, m->halfedge_count, m->face_count,
                            hm_attribute_flags(m));
    if (s != CG_OK)
        return s;
    memcpy(c->halfedges, m->halfedges, m->halfedge_count * sizeof *m->halfedges);
    memcpy(c->vertex_halfedge, m->vertex_halfedge, m->vertex_count * sizeof *m->vertex_halfedge);
    memcpy(c->face_halfedge, m->face_halfedge, m->face_count * sizeof *m->face_halfedge);
    memcpy(c->positions, m->positions, m->vertex_count * sizeof *m->positions);
    if (m->normals)
        memcpy(c->normals, m->normals, m->vertex_count * sizeof *m->normals);
    if (m->texcoords)
        memcpy(c->texcoords, m->texcoords, m->vertex_count * sizeof *m->texcoords);
    if (m->colors)
        memcpy(c->colors, m->colors, m->vertex_count * sizeof *m->colors);
    if (m->face_colors)
        memcpy(c->face_colors, m->face_colors, m->face_count * sizeof *m->face_colors);
    c->live_vertices = m->live_vertices;
    c->live_edges = m->live_edges;
    c->live_faces = m->live_faces;
    *out = c;
    return CG_OK;
}

void cg_hemesh_compact(cg_hemesh *m)
{
    if (!m)
        return;
    size_t nv = 0, ne = 0, nf = 0;
    /* New indices, computed in place of nothing: three small maps. */
    uint32_t *vmap = malloc((m->vertex_count ? m->vertex_count : 1) * sizeof *vmap);
    uint32_t *emap = malloc((m->halfedge_count / 2 + 1) * sizeof *emap);
    uint32_t *fmap = malloc((m->face_count ? m->face_count : 1) * sizeof *fmap);
    if (!vmap || !emap || !fmap) {
        /* Compaction is an optimisation: without memory the structure stays
         * valid, just sparse. */
        free(vmap);
        free(emap);
        free(fmap);
        return;
    }
    for (size_t v = 0; v < m->vertex_count; v++)
        vmap[v] = m->vertex_halfedge[v] == CG_HEMESH_DELETED ? CG_HEMESH_DELETED : (uint32_t)nv++;
    for (size_t e = 0; e < m->halfedge_count / 2; e++)
        emap[e] = m->halfedges[2 * e].origin == CG_HEMESH_DELETED ? CG_HEMESH_DELETED
                                                                  : (uint32_t)ne++;
    for (size_t f = 0; f < m->face_count; f++)
        fmap[f] = m->face_halfedge[f] == CG_HEMESH_DELETED ? CG_HEMESH_DELETED : (uint32_t)nf++;
#define HM_MAP_H(h) ((h) >= CG_HEMESH_DELETED ? (h) : (emap[(h) >> 1] << 1 | ((h)&1u)))
    for (size_t h = 0; h < m->halfedge_count; h++) {
        if (emap[h >> 1] == CG_HEMESH_DELETED)
            continue;
        cg_hemesh_halfedge x = m->halfedges[h];
        cg_hemesh_halfedge y = {HM_MAP_H(x.next), HM_MAP_H(x.prev), vmap[x.origin],
                                x.face == CG_HEMESH_NONE ? CG_HEMESH_NONE : fmap[x.face]};
        m->halfedges[HM_MAP_H((uint32_t)h)] = y;
    }
    for (size_t v = 0; v < m->vertex_count; v++) {
        if (vmap[v] == CG_HEMESH_DELETED)
            continue;
        uint32_t h = m->vertex_halfedge[v];
        m->vertex_halfedge[vmap[v]] = HM_MAP_H(h);
        m->positions[vmap[v]] = m->positions[v];
        if (m->normals)
            m->normals[vmap[v]] = m->normals[v];
        if (m->texcoords)
            m->texcoords[vmap[v]] = m->texcoords[v];
        if (m->colors)
            m->colors[vmap[v]] = m->colors[v];
    }
    for (size_t f = 0; f < m->face_count; f++) {
        if (fmap[f] == CG_HEMESH_DELETED)
            continue;
        m->face_halfedge[fmap[f]] = HM_MAP_H(m->face_halfedge[f]);
        if (m->face_colors)
            m->face_colors[fmap[f]] = m->face_colors[f];
    }
#undef HM_MAP_H
    m->vertex_count = nv;
    m->halfedge_count = 2 * ne;
    m->face_count = nf;
    free(vmap);
    free(emap);
    free(fmap);
}

cg_status cg_hemesh_to_mesh(const cg_hemesh *m, cg_mesh **out)
{
    if (!m || !out)
        return CG_EINVAL;
    *out = NULL;
    size_t corners = 0;
    for (size_t h = 0; h < m->halfedge_count; h++)
        if (m->halfedges[h].origin != CG_HEMESH_DELETED && m->halfedges[h].face != CG_HEMESH_NONE)
            corners++;
    uint32_t *vmap = malloc((m->vertex_count ? m->vertex_count : 1) * sizeof *vmap);
    if (!vmap)
        return CG_ENOMEM;
    cg_mesh *mesh;
    cg_status s = cg_mesh_create(&mesh, m->live_vertices, m->live_faces, corners,
                                 hm_attribute_flags(m));
    if (s != CG_OK) {
        free(vmap);
        return s;
    }
    size_t nv = 0;
    for (size_t v = 0; v < m->vertex_count; v++) {
        if (m->vertex_halfedge[v] == CG_HEMESH_DELETED)
            continue;
        vmap[v] = (uint32_t)nv;
        mesh->positions[nv] = m->positions[v];
        if (m->normals)
            mesh->normals[nv] = m->normals[v];
        if (m->texcoords)
            mesh->texcoords[nv] = m->texcoords[v];
        if (m->colors)
            mesh->colors[nv] = m->colors[v];
        nv++;
    }
    size_t nf = 0, k = 0;
    for (size_t f = 0; f < m->face_count; f++) {
        uint32_t h0 = m->face_halfedge[f];
        if (h0 == CG_HEMESH_DELETED)
            continue;
        uint32_t h = h0;
        do {
            mesh->face_indices[k++] = vmap[m->halfedges[h].origin];
            h = m->halfedges[h].next;
        } while (h != h0);
        if (m->face_colors)
            mesh->face_colors[nf] = m->face_colors[f];
        mesh->face_offsets[++nf] = (uint32_t)k;
    }
    free(vmap);
    *out = mesh;
    return CG_OK;
}
