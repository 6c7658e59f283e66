/* Loop and Catmull-Clark subdivision, built directly as a new half-edge
 * structure.
 *
 * Numbering (old mesh: V vertices, E edges, F faces):
 *  - old vertex v keeps index v; the point of edge e is V + e; the point of
 *    face f (Catmull-Clark) is V + E + f.
 *  - old edge e (a = origin(2e), b = origin(2e + 1), midpoint m) becomes the
 *    edges 2e = (a, m) and 2e + 1 = (m, b): half-edges 4e: a->m, 4e+1: m->a,
 *    4e+2: m->b, 4e+3: b->m.  So old half-edge h = 2e + s has the first half
 *    first(h) = 4e + 3s (origin(h) -> m) and second half second(h) =
 *    4e + 2 - s (m -> dest(h)).
 *  - the new edges inside old faces come after the 2E split ones.
 */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

static inline uint32_t first_half(uint32_t h)
{
    return 4 * (h >> 1) + 3 * (h & 1u);
}
static inline uint32_t second_half(uint32_t h)
{
    return 4 * (h >> 1) + 2 - (h & 1u);
}

static void link(cg_hemesh *m, uint32_t a, uint32_t b)
{
    m->halfedges[a].next = b;
    m->halfedges[b].prev = a;
}

/* A compact version of m (a copy when m has deleted elements). */
static cg_status dense(const cg_hemesh *m, const cg_hemesh **out, cg_hemesh **owned)
{
    *owned = NULL;
    *out = m;
    if (m->live_vertices == m->vertex_count && 2 * m->live_edges == m->halfedge_count
        && m->live_faces == m->face_count)
        return CG_OK;
    cg_status s = cg_hemesh_copy(m, owned);
    if (s != CG_OK)
        return s;
    cg_hemesh_compact(*owned);
    *out = *owned;
    return CG_OK;
}

/* The split old edges: origins, boundary links, vertex half-edges of old
 * vertices and edge points, and linear attributes (edge points at the
 * midpoint).  Interior links are the caller's. */
static void split_edges(const cg_hemesh *m, cg_hemesh *r)
{
    size_t V = m->vertex_count, E = m->halfedge_count / 2;
    const cg_hemesh_halfedge *he = m->halfedges;
    cg_hemesh_halfedge *rh = r->halfedges;
    for (size_t e = 0; e < E; e++) {
        uint32_t mid = (uint32_t)(V + e);
        uint32_t a = he[2 * e].origin, b = he[2 * e + 1].origin;
        rh[4 * e].origin = a;
        rh[4 * e + 1].origin = mid;
        rh[4 * e + 2].origin = mid;
        rh[4 * e + 3].origin = b;
        for (int k = 0; k < 4; k++)
            rh[4 * e + k].face = CG_HEMESH_NONE;
        uint32_t pick = he[2 * e].face == CG_HEMESH_NONE       ? (uint32_t)(4 * e + 2)
                        : he[2 * e + 1].face == CG_HEMESH_NONE ? (uint32_t)(4 * e + 1)
                                                               : (uint32_t)(4 * e + 2);
        r->vertex_halfedge[mid] = pick;
        uint32_t ends[2] = {a, b};
        double half[2] = {0.5, 0.5};
        hm_blend_attributes(r, mid, ends, half, 2);
    }
    for (size_t h = 0; h < 2 * E; h++) {
        if (he[h].face != CG_HEMESH_NONE)
            continue;
        link(r, first_half((uint32_t)h), second_half((uint32_t)h));
        link(r, second_half((uint32_t)h), first_half(he[h].next));
    }
    for (size_t v = 0; v < V; v++) {
        uint32_t h = m->vertex_halfedge[v];
        r->vertex_halfedge[v] = h == CG_HEMESH_NONE ? CG_HEMESH_NONE : first_half(h);
    }
}

static cg_status make_result(const cg_hemesh *m, size_t vertices, size_t edges, size_t faces,
                             cg_hemesh **out)
{
    if (vertices >= CG_HEMESH_DELETED || 2 * edges >= CG_HEMESH_DELETED
        || faces >= CG_HEMESH_DELETED)
        return CG_ERANGE;
    cg_hemesh *r;
    cg_status s = hm_create(&r, vertices, 2 * edges, faces, hm_attribute_flags(m));
    if (s != CG_OK)
        return s;
    size_t V = m->vertex_count;
    if (m->texcoords)
        memcpy(r->texcoords, m->texcoords, V * sizeof *m->texcoords);
    if (m->colors)
        memcpy(r->colors, m->colors, V * sizeof *m->colors);
    r->live_vertices = vertices;
    r->live_edges = edges;
    r->live_faces = faces;
    *out = r;
    return CG_OK;
}

/* Boundary rule for an old vertex whose half-edge h is on the boundary. */
static cg_vec3 boundary_vertex(const cg_hemesh *m, uint32_t h)
{
    const cg_hemesh_halfedge *he = m->halfedges;
    cg_vec3 p = m->positions[he[h].origin];
    cg_vec3 a = m->positions[he[h ^ 1u].origin], b = m->positions[he[he[h].prev].origin];
    return cg_vec3_add(cg_vec3_scale(p, 0.75), cg_vec3_scale(cg_vec3_add(a, b), 0.125));
}

/* Both schemes leave an isolated vertex where it is and move a boundary
 * vertex along the boundary curve.  Returns 1 when v is one of those (its
 * new position set), 0 for an interior vertex, which each scheme moves by
 * its own rule. */
static int place_outside_interior(const cg_hemesh *m, cg_hemesh *r, size_t v)
{
    uint32_t h0 = m->vertex_halfedge[v];
    if (h0 == CG_HEMESH_NONE) {
        r->positions[v] = m->positions[v];
        return 1;
    }
    if (m->halfedges[h0].face == CG_HEMESH_NONE) {
        r->positions[v] = boundary_vertex(m, h0);
        return 1;
    }
    return 0;
}

static double loop_beta(size_t n)
{
    double c = 0.375 + 0.25 * cos(2.0 * CG_PI / (double)n);
    return (0.625 - c * c) / (double)n;
}

/* The start of both schemes: checks the arguments and gives input's dense
 * form (*owned: a compacted copy to free, or NULL when input is dense). */
static cg_status subdivide_begin(const cg_hemesh *input, cg_hemesh **out, const cg_hemesh **m,
                                 cg_hemesh **owned)
{
    if (!input || !out)
        return CG_EINVAL;
    *out = NULL;
    return dense(input, m, owned);
}

cg_status cg_hemesh_subdivide_loop(const cg_hemesh *input, cg_hemesh **out)
{
    const cg_hemesh *m;
    cg_hemesh *owned;
    cg_status s = subdivide_begin(input, out, &m, &owned);
    if (s != CG_OK)
        return s;
    size_t V = m->vertex_count, E = m->halfedge_count / 2, F = m->face_count;
    const cg_hemesh_halfedge *he = m->halfedges;
    for (size_t f = 0; f < F; f++) {
        uint32_t h = m->face_halfedge[f];
        if (he[he[he[h].next].next].next != h) {
            cg_hemesh_free(owned);
            return CG_EUNSUPPORTED;
        }
    }
    cg_hemesh *r;
    s = make_result(m, V + E, 2 * E + 3 * F, 4 * F, &r);
    if (s != CG_OK) {
        cg_hemesh_free(owned);
        return s;
    }
    split_edges(m, r);
    cg_hemesh_halfedge *rh = r->halfedges;
    size_t base = 4 * E;
    for (size_t f = 0; f < F; f++) {
        uint32_t h[3];
        h[0] = m->face_halfedge[f];
        h[1] = he[h[0]].next;
        h[2] = he[h[1]].next;
        uint32_t in[3];
        for (uint32_t i = 0; i < 3; i++) {
            /* even: m_i -> m_{i-1} in corner triangle i; odd: the reverse, centre */
            in[i] = (uint32_t)(base + 6 * f + 2 * i);
            rh[in[i]].origin = (uint32_t)(V + (h[i] >> 1));
            rh[in[i] + 1].origin = (uint32_t)(V + (h[(i + 2) % 3] >> 1));
        }
        for (uint32_t i = 0; i < 3; i++) {
            uint32_t face = (uint32_t)(4 * f + i);
            uint32_t a = first_half(h[i]), b = in[i], c = second_half(h[(i + 2) % 3]);
            link(r, a, b);
            link(r, b, c);
            link(r, c, a);
            rh[a].face = rh[b].face = rh[c].face = face;
            r->face_halfedge[face] = a;
        }
        uint32_t centre = (uint32_t)(4 * f + 3);
        link(r, in[0] + 1, in[1] + 1);
        link(r, in[1] + 1, in[2] + 1);
        link(r, in[2] + 1, in[0] + 1);
        rh[in[0] + 1].face = rh[in[1] + 1].face = rh[in[2] + 1].face = centre;
        r->face_halfedge[centre] = in[0] + 1;
        if (m->face_colors)
            for (int i = 0; i < 4; i++)
                r->face_colors[4 * f + i] = m->face_colors[f];
    }
    /* positions: old vertices */
    double table[16];
    for (size_t n = 1; n < 16; n++)
        table[n] = loop_beta(n);
    for (size_t v = 0; v < V; v++) {
        uint32_t h0 = m->vertex_halfedge[v];
        cg_vec3 p = m->positions[v];
        if (place_outside_interior(m, r, v))
            continue;
        cg_vec3 sum = {0, 0, 0};
        size_t n = 0;
        uint32_t h = h0;
        do {
            sum = cg_vec3_add(sum, m->positions[he[h ^ 1u].origin]);
            n++;
            h = he[h ^ 1u].next;
        } while (h != h0);
        double beta = n < 16 ? table[n] : loop_beta(n);
        r->positions[v] = cg_vec3_add(cg_vec3_scale(p, 1.0 - (double)n * beta),
                                      cg_vec3_scale(sum, beta));
    }
    /* edge points */
    for (size_t e = 0; e < E; e++) {
        uint32_t h = (uint32_t)(2 * e);
        cg_vec3 a = m->positions[he[h].origin], b = m->positions[he[h + 1].origin];
        cg_vec3 p;
        if (he[h].face == CG_HEMESH_NONE || he[h + 1].face == CG_HEMESH_NONE) {
            p = cg_vec3_scale(cg_vec3_add(a, b), 0.5);
        } else {
            cg_vec3 c = m->positions[he[he[h].prev].origin];
            cg_vec3 d = m->positions[he[he[h + 1].prev].origin];
            p = cg_vec3_add(cg_vec3_scale(cg_vec3_add(a, b), 0.375),
                            cg_vec3_scale(cg_vec3_add(c, d), 0.125));
        }
        r->positions[V + e] = p;
    }
    if (m->normals)
        cg_hemesh_compute_normals(r);
    cg_hemesh_free(owned);
    *out = r;
    return CG_OK;
}

/* offset[f]: the first corner of face f in a numbering of all corners face
 * by face (offset[F] is their count). */
static uint32_t *face_corner_offsets(const cg_hemesh *m)
{
    size_t F = m->face_count;
    uint32_t *offset = malloc((F + 1) * sizeof *offset);
    if (!offset)
        return NULL;
    size_t corners = 0;
    for (size_t f = 0; f < F; f++) {
        offset[f] = (uint32_t)corners;
        uint32_t h0 = m->face_halfedge[f], h = h0;
        do {
            corners++;
            h = m->halfedges[h].next;
        } while (h != h0);
    }
    offset[F] = (uint32_t)corners;
    return offset;
}

/* Catmull-Clark: the face point of face f (the centroid, attributes
 * averaged) and the quads around it, one per corner. */
static void catmull_clark_face(const cg_hemesh *m, cg_hemesh *r, const uint32_t *offset, size_t f)
{
    size_t V = m->vertex_count, E = m->halfedge_count / 2;
    const cg_hemesh_halfedge *he = m->halfedges;
    cg_hemesh_halfedge *rh = r->halfedges;
    size_t base = 4 * E;
    uint32_t fp = (uint32_t)(V + E + f);
    uint32_t h0 = m->face_halfedge[f], h = h0;
    uint32_t k = offset[f + 1] - offset[f];
    cg_vec3 centroid = {0, 0, 0};
    uint32_t i = 0;
    do {
        /* I_i: even m_i -> fp (quad i), odd fp -> m_i (quad i + 1) */
        uint32_t in = (uint32_t)(base + 2 * (offset[f] + i));
        uint32_t in_prev = (uint32_t)(base + 2 * (offset[f] + (i + k - 1) % k));
        uint32_t face = offset[f] + i;
        uint32_t a = first_half(h), c = second_half(he[h].prev);
        rh[in].origin = (uint32_t)(V + (h >> 1));
        rh[in + 1].origin = fp;
        link(r, a, in);
        link(r, in, in_prev + 1);
        link(r, in_prev + 1, c);
        link(r, c, a);
        rh[a].face = rh[in].face = rh[in_prev + 1].face = rh[c].face = face;
        r->face_halfedge[face] = a;
        if (m->face_colors)
            r->face_colors[face] = m->face_colors[f];
        centroid = cg_vec3_add(centroid, m->positions[he[h].origin]);
        i++;
        h = he[h].next;
    } while (h != h0);
    r->positions[fp] = cg_vec3_scale(centroid, 1.0 / (double)k);
    r->vertex_halfedge[fp] = (uint32_t)(base + 2 * offset[f] + 1);
    if (r->texcoords || r->colors || r->normals) {
        uint32_t *src = malloc(k * sizeof *src);
        double *w = malloc(k * sizeof *w);
        if (src && w) {
            for (uint32_t j = 0, x = h0; j < k; j++, x = he[x].next) {
                src[j] = he[x].origin;
                w[j] = 1.0 / (double)k;
            }
            hm_blend_attributes(r, fp, src, w, k);
        }
        free(src);
        free(w);
    }
}

/* Catmull-Clark edge points: the average of the ends and the two face
 * points, or the midpoint on the boundary. */
static void catmull_clark_edge_points(const cg_hemesh *m, cg_hemesh *r)
{
    size_t V = m->vertex_count, E = m->halfedge_count / 2;
    const cg_hemesh_halfedge *he = m->halfedges;
    for (size_t e = 0; e < E; e++) {
        uint32_t h = (uint32_t)(2 * e);
        cg_vec3 a = m->positions[he[h].origin], b = m->positions[he[h + 1].origin];
        cg_vec3 p = cg_vec3_add(a, b);
        if (he[h].face == CG_HEMESH_NONE || he[h + 1].face == CG_HEMESH_NONE)
            p = cg_vec3_scale(p, 0.5);
        else
            p = cg_vec3_scale(cg_vec3_add(p, cg_vec3_add(r->positions[V + E + he[h].face],
                                                         r->positions[V + E + he[h + 1].face])),
                              0.25);
        r->positions[V + e] = p;
    }
}

/* Catmull-Clark: the old vertices move to (F + 2R + (n - 3)P) / n, F the
 * average of the face points around, R of the edge midpoints; boundary
 * vertices follow the boundary curve. */
static void catmull_clark_vertex_points(const cg_hemesh *m, cg_hemesh *r)
{
    size_t V = m->vertex_count, E = m->halfedge_count / 2;
    const cg_hemesh_halfedge *he = m->halfedges;
    for (size_t v = 0; v < V; v++) {
        uint32_t h0 = m->vertex_halfedge[v];
        cg_vec3 p = m->positions[v];
        if (place_outside_interior(m, r, v))
            continue;
        cg_vec3 fsum = {0, 0, 0}, rsum = {0, 0, 0};
        size_t n = 0;
        uint32_t h = h0;
        do {
            fsum = cg_vec3_add(fsum, r->positions[V + E + he[h].face]);
            rsum = cg_vec3_add(rsum, m->positions[he[h ^ 1u].origin]);
            n++;
            h = he[h ^ 1u].next;
        } while (h != h0);
        double dn = (double)n;
        /* R = average of midpoints (p + w) / 2 */
        cg_vec3 favg = cg_vec3_scale(fsum, 1.0 / dn);
        cg_vec3 ravg = cg_vec3_scale(cg_vec3_add(cg_vec3_scale(p, dn), rsum), 0.5 / dn);
        r->positions[v] = cg_vec3_scale(
            cg_vec3_add(cg_vec3_add(favg, cg_vec3_scale(ravg, 2.0)), cg_vec3_scale(p, dn - 3.0)),
            1.0 / dn);
    }
}

cg_status cg_hemesh_subdivide_catmull_clark(const cg_hemesh *input, cg_hemesh **out)
{
    const cg_hemesh *m;
    cg_hemesh *owned;
    cg_status s = subdivide_begin(input, out, &m, &owned);
    if (s != CG_OK)
        return s;
    size_t V = m->vertex_count, E = m->halfedge_count / 2, F = m->face_count;
    uint32_t *offset = face_corner_offsets(m);
    if (!offset) {
        cg_hemesh_free(owned);
        return CG_ENOMEM;
    }
    size_t corners = offset[F];
    cg_hemesh *r;
    s = make_result(m, V + E + F, 2 * E + corners, corners, &r);
    if (s != CG_OK) {
        free(offset);
        cg_hemesh_free(owned);
        return s;
    }
    split_edges(m, r);
    for (size_t f = 0; f < F; f++)
        catmull_clark_face(m, r, offset, f);
    catmull_clark_edge_points(m, r);
    catmull_clark_vertex_points(m, r);
    if (m->normals)
        cg_hemesh_compute_normals(r);
    free(offset);
    cg_hemesh_free(owned);
    *out = r;
    return CG_OK;
}
