/* Local operations on the half-edge structure: edge flip, edge split, edge
 * collapse, face split, face and vertex removal.  Each either refuses and
 * changes nothing, or leaves a structure that passes cg_hemesh_validate. */
#include "internal.h"

#include <stdlib.h>

static void link(cg_hemesh *m, uint32_t a, uint32_t b)
{
    m->halfedges[a].next = b;
    m->halfedges[b].prev = a;
}

static int halfedge_live(const cg_hemesh *m, uint32_t h)
{
    return m && h < m->halfedge_count && m->halfedges[h].origin != CG_HEMESH_DELETED;
}

static size_t loop_length(const cg_hemesh *m, uint32_t h0)
{
    size_t n = 0;
    uint32_t h = h0;
    do {
        n++;
        h = m->halfedges[h].next;
    } while (h != h0);
    return n;
}

static void delete_edge(cg_hemesh *m, uint32_t h)
{
    h &= ~1u;
    m->halfedges[h].origin = m->halfedges[h + 1].origin = CG_HEMESH_DELETED;
    m->halfedges[h].face = m->halfedges[h + 1].face = CG_HEMESH_NONE;
    m->live_edges--;
}

static void delete_vertex(cg_hemesh *m, uint32_t v)
{
    m->vertex_halfedge[v] = CG_HEMESH_DELETED;
    m->live_vertices--;
}

static void delete_face(cg_hemesh *m, uint32_t f)
{
    m->face_halfedge[f] = CG_HEMESH_DELETED;
    m->live_faces--;
}

/* Number of boundary half-edges leaving v. */
static size_t boundary_gaps(const cg_hemesh *m, uint32_t v)
{
    uint32_t h0 = m->vertex_halfedge[v];
    if (h0 >= CG_HEMESH_DELETED || m->halfedges[h0].face != CG_HEMESH_NONE)
        return 0;
    size_t n = 0;
    uint32_t h = h0;
    do {
        n += m->halfedges[h].face == CG_HEMESH_NONE;
        h = cg_hemesh_ccw(m, h);
    } while (h != h0);
    return n;
}

/* ---- flip ------------------------------------------------------------------ */

cg_status cg_hemesh_flip_edge(cg_hemesh *m, uint32_t e)
{
    if (!m || e >= m->halfedge_count / 2 || !halfedge_live(m, 2 * e))
        return CG_EINVAL;
    uint32_t h = 2 * e, t = h + 1;
    uint32_t f0 = m->halfedges[h].face, f1 = m->halfedges[t].face;
    if (f0 == CG_HEMESH_NONE || f1 == CG_HEMESH_NONE || loop_length(m, h) != 3
        || loop_length(m, t) != 3)
        return CG_EINVAL;
    uint32_t h1 = m->halfedges[h].next, h2 = m->halfedges[h1].next;
    uint32_t t1 = m->halfedges[t].next, t2 = m->halfedges[t1].next;
    uint32_t a = m->halfedges[h].origin, b = m->halfedges[t].origin;
    uint32_t c = m->halfedges[h2].origin, d = m->halfedges[t2].origin;
    if (c == d || cg_hemesh_find_halfedge(m, c, d) != CG_HEMESH_NONE)
        return CG_EINVAL;
    m->halfedges[h].origin = d;
    m->halfedges[t].origin = c;
    link(m, h2, t1);
    link(m, t1, h);
    link(m, h, h2);
    link(m, t2, h1);
    link(m, h1, t);
    link(m, t, t2);
    m->halfedges[t1].face = f0;
    m->halfedges[h1].face = f1;
    m->face_halfedge[f0] = h;
    m->face_halfedge[f1] = t;
    if (m->vertex_halfedge[a] == h)
        m->vertex_halfedge[a] = t1;
    if (m->vertex_halfedge[b] == t)
        m->vertex_halfedge[b] = h1;
    return CG_OK;
}

/* ---- splits ---------------------------------------------------------------- */

/* Splits the face of p and q (two different half-edges of one face whose
 * origins are not adjacent) by a new edge between their origins: p's part
 * keeps the face, q's part gets a new one.  Room must be reserved. */
static void connect(cg_hemesh *m, uint32_t p, uint32_t q)
{
    uint32_t f = m->halfedges[p].face;
    uint32_t pp = m->halfedges[p].prev, qp = m->halfedges[q].prev;
    uint32_t k = hm_add_edge(m, m->halfedges[q].origin, m->halfedges[p].origin);
    /* k: origin(q) -> origin(p) closes p's part; k + 1 closes q's part */
    link(m, qp, k);
    link(m, k, p);
    link(m, pp, k + 1);
    link(m, k + 1, q);
    m->halfedges[k].face = f;
    m->face_halfedge[f] = p;
    uint32_t g = hm_add_face(m, q, f);
    uint32_t h = q;
    do {
        m->halfedges[h].face = g;
        h = m->halfedges[h].next;
    } while (h != q);
}

cg_status cg_hemesh_split_edge(cg_hemesh *m, uint32_t e, cg_vec3 position, uint32_t *new_vertex)
{
    if (!m || e >= m->halfedge_count / 2 || !halfedge_live(m, 2 * e))
        return CG_EINVAL;
    if (hm_reserve(m, 1, 3, 2) != CG_OK)
        return CG_ENOMEM;
    uint32_t h = 2 * e, t = h + 1;
    uint32_t a = m->halfedges[h].origin, b = m->halfedges[t].origin;
    uint32_t fh = m->halfedges[h].face, ft = m->halfedges[t].face;
    int tri_h = fh != CG_HEMESH_NONE && loop_length(m, h) == 3;
    int tri_t = ft != CG_HEMESH_NONE && loop_length(m, t) == 3;
    uint32_t hn = m->halfedges[h].next, tp = m->halfedges[t].prev;
    uint32_t v = hm_add_vertex(m, position);
    uint32_t ends[2] = {a, b};
    double half[2] = {0.5, 0.5};
    hm_blend_attributes(m, v, ends, half, 2);
    /* h: a -> v, n: v -> b, n + 1: b -> v, t: v -> a */
    uint32_t n = hm_add_edge(m, v, b);
    m->halfedges[t].origin = v;
    m->halfedges[n].face = fh;
    m->halfedges[n + 1].face = ft;
    link(m, n, hn);
    link(m, h, n);
    link(m, tp, n + 1);
    link(m, n + 1, t);
    if (m->vertex_halfedge[b] == t)
        m->vertex_halfedge[b] = n + 1;
    m->vertex_halfedge[v] = fh == CG_HEMESH_NONE ? n : ft == CG_HEMESH_NONE ? t : n;
    /* keep triangles triangular: join v to the opposite corners */
    if (tri_h)
        connect(m, n, m->halfedges[h].prev);
    if (tri_t)
        connect(m, t, m->halfedges[n + 1].prev);
    if (new_vertex)
        *new_vertex = v;
    return CG_OK;
}

cg_status cg_hemesh_split_face(cg_hemesh *m, uint32_t f, cg_vec3 position, uint32_t *new_vertex)
{
    if (!m || f >= m->face_count || m->face_halfedge[f] >= CG_HEMESH_DELETED)
        return CG_EINVAL;
    uint32_t h0 = m->face_halfedge[f];
    size_t k = loop_length(m, h0);
    uint32_t *side = malloc(k * sizeof *side);
    uint32_t *corner = malloc(k * sizeof *corner);
    double *weight = malloc(k * sizeof *weight);
    if (!side || !corner || !weight || hm_reserve(m, 1, k, k - 1) != CG_OK) {
        free(side);
        free(corner);
        free(weight);
        return CG_ENOMEM;
    }
    uint32_t h = h0;
    for (size_t i = 0; i < k; i++) {
        side[i] = h;
        corner[i] = m->halfedges[h].origin;
        weight[i] = 1.0 / (double)k;
        h = m->halfedges[h].next;
    }
    uint32_t c = hm_add_vertex(m, position);
    hm_blend_attributes(m, c, corner, weight, k);
    /* spoke i: s_i = c -> corner i, s_i + 1 = corner i -> c */
    uint32_t first = (uint32_t)m->halfedge_count;
    for (size_t i = 0; i < k; i++)
        hm_add_edge(m, c, corner[i]);
    for (size_t i = 0; i < k; i++) {
        uint32_t s_in = first + 2 * (uint32_t)((i + 1) % k) + 1; /* corner i+1 -> c */
        uint32_t s_out = first + 2 * (uint32_t)i;                /* c -> corner i */
        uint32_t face = i == 0 ? f : hm_add_face(m, side[i], f);
        link(m, side[i], s_in);
        link(m, s_in, s_out);
        link(m, s_out, side[i]);
        m->halfedges[side[i]].face = m->halfedges[s_in].face = m->halfedges[s_out].face = face;
        if (i == 0)
            m->face_halfedge[f] = side[0];
    }
    m->vertex_halfedge[c] = first;
    free(side);
    free(corner);
    free(weight);
    if (new_vertex)
        *new_vertex = c;
    return CG_OK;
}

cg_status cg_hemesh_split_face_between(cg_hemesh *m, uint32_t p, uint32_t q, uint32_t *new_face)
{
    if (!halfedge_live(m, p) || !halfedge_live(m, q) || p == q)
        return CG_EINVAL;
    uint32_t f = m->halfedges[p].face;
    if (f == CG_HEMESH_NONE || m->halfedges[q].face != f || m->halfedges[p].next == q
        || m->halfedges[q].next == p
        || cg_hemesh_find_halfedge(m, m->halfedges[p].origin, m->halfedges[q].origin)
               != CG_HEMESH_NONE)
        return CG_EINVAL;
    if (hm_reserve(m, 0, 1, 1) != CG_OK)
        return CG_ENOMEM;
    connect(m, p, q);
    if (new_face)
        *new_face = (uint32_t)m->face_count - 1;
    return CG_OK;
}

/* ---- collapse ----------------------------------------------------------------- */

/* Appends the neighbours of v to a malloc'ed list; NULL on failure. */
static uint32_t *neighbors(const cg_hemesh *m, uint32_t v, size_t *count)
{
    size_t n = cg_hemesh_vertex_neighbors(m, v, 1, NULL, 0);
    uint32_t *list = malloc((n ? n : 1) * sizeof *list);
    if (list)
        cg_hemesh_vertex_neighbors(m, v, 1, list, n);
    *count = n;
    return list;
}

/* Apex of the triangle on h's side, or NONE when that side is not a triangle. */
static uint32_t apex(const cg_hemesh *m, uint32_t h)
{
    if (m->halfedges[h].face == CG_HEMESH_NONE || loop_length(m, h) != 3)
        return CG_HEMESH_NONE;
    return m->halfedges[m->halfedges[h].prev].origin;
}

/* An apex loses one edge: refuse when it would be left interior with fewer
 * than 3 edges, or when the triangle is an ear (its other two edges on the
 * boundary), which would leave an edge with no face. */
static int apex_ok(const cg_hemesh *m, uint32_t h)
{
    uint32_t c = apex(m, h);
    if (c == CG_HEMESH_NONE)
        return 1;
    uint32_t hn = m->halfedges[h].next, hp = m->halfedges[h].prev;
    if (m->halfedges[hn ^ 1u].face == CG_HEMESH_NONE
        && m->halfedges[hp ^ 1u].face == CG_HEMESH_NONE)
        return 0;
    if (!cg_hemesh_vertex_is_boundary(m, c) && cg_hemesh_valence(m, c) <= 3)
        return 0;
    return 1;
}

/* Whether a face around u other than the two sides of h (u -> v) has v as
 * a corner: after the collapse it would visit v twice. */
static int other_face_joins(const cg_hemesh *m, uint32_t h)
{
    uint32_t u = m->halfedges[h].origin, v = m->halfedges[h ^ 1u].origin;
    uint32_t own[2] = {m->halfedges[h].face, m->halfedges[h ^ 1u].face};
    uint32_t x0 = m->vertex_halfedge[u], x = x0;
    do {
        uint32_t f = m->halfedges[x].face;
        if (f != CG_HEMESH_NONE && f != own[0] && f != own[1]) {
            uint32_t y = x;
            do {
                if (m->halfedges[y].origin == v)
                    return 1;
                y = m->halfedges[y].next;
            } while (y != x);
        }
        x = cg_hemesh_ccw(m, x);
    } while (x != x0);
    return 0;
}

int cg_hemesh_collapse_ok(const cg_hemesh *m, uint32_t h)
{
    if (!halfedge_live(m, h))
        return 0;
    uint32_t t = h ^ 1u, u = m->halfedges[h].origin, v = m->halfedges[t].origin;
    if (boundary_gaps(m, u) > 1 || boundary_gaps(m, v) > 1)
        return 0;
    int edge_boundary = m->halfedges[h].face == CG_HEMESH_NONE
                        || m->halfedges[t].face == CG_HEMESH_NONE;
    if (!edge_boundary && cg_hemesh_vertex_is_boundary(m, u) && cg_hemesh_vertex_is_boundary(m, v))
        return 0;
    if (!apex_ok(m, h) || !apex_ok(m, t) || other_face_joins(m, h))
        return 0;
    /* link condition: common neighbours are exactly the apexes */
    uint32_t c = apex(m, h), d = apex(m, t);
    /* One apex for both triangles (joined to it by two different edges):
     * they share two sides, and the collapse would leave an edge with no
     * face. */
    if (c != CG_HEMESH_NONE && c == d)
        return 0;
    size_t nu, nv;
    uint32_t *lu = neighbors(m, u, &nu), *lv = neighbors(m, v, &nv);
    int ok = lu && lv, edges_to_v = 0;
    for (size_t i = 0; ok && i < nu; i++) {
        uint32_t w = lu[i];
        /* a second edge between u and v would become a loop at v */
        if (w == v && ++edges_to_v > 1)
            ok = 0;
        if (w == v || w == c || w == d)
            continue;
        for (size_t j = 0; j < nv; j++)
            if (lv[j] == w) {
                ok = 0;
                break;
            }
    }
    free(lu);
    free(lv);
    return ok;
}

/* Removes the triangle on x's side (x: u -> v, the edge being collapsed):
 * the edge of prev(x) (at u) goes, the edge of next(x) (at v) takes its
 * place on the far side. */
static void drop_triangle(cg_hemesh *m, uint32_t x)
{
    uint32_t xn = m->halfedges[x].next, xp = m->halfedges[x].prev;
    uint32_t c = m->halfedges[xp].origin, o = xp ^ 1u;
    uint32_t f = m->halfedges[x].face;
    /* xn takes o's place in o's loop */
    uint32_t on = m->halfedges[o].next, op = m->halfedges[o].prev, of = m->halfedges[o].face;
    m->halfedges[xn].face = of;
    link(m, op, xn);
    link(m, xn, on);
    if (of != CG_HEMESH_NONE && m->face_halfedge[of] == o)
        m->face_halfedge[of] = xn;
    if (m->vertex_halfedge[c] == xp)
        m->vertex_halfedge[c] = xn ^ 1u;
    delete_edge(m, xp);
    delete_face(m, f);
    hm_fix_vertex_halfedge(m, c);
}

/* For the side of y: v -> u (twin of the collapsed half-edge), the triangle
 * loses the edge of next(y) (at u) and keeps the edge of prev(y) (at v). */
static void drop_triangle_twin(cg_hemesh *m, uint32_t y)
{
    uint32_t yn = m->halfedges[y].next, yp = m->halfedges[y].prev;
    uint32_t d = m->halfedges[yp].origin, o = yn ^ 1u;
    uint32_t f = m->halfedges[y].face;
    uint32_t on = m->halfedges[o].next, op = m->halfedges[o].prev, of = m->halfedges[o].face;
    m->halfedges[yp].face = of;
    link(m, op, yp);
    link(m, yp, on);
    if (of != CG_HEMESH_NONE && m->face_halfedge[of] == o)
        m->face_halfedge[of] = yp;
    if (m->vertex_halfedge[d] == o)
        m->vertex_halfedge[d] = yp;
    delete_edge(m, yn);
    delete_face(m, f);
    hm_fix_vertex_halfedge(m, d);
}

static void unlink_side(cg_hemesh *m, uint32_t x)
{
    uint32_t xn = m->halfedges[x].next, xp = m->halfedges[x].prev, f = m->halfedges[x].face;
    link(m, xp, xn);
    if (f != CG_HEMESH_NONE && m->face_halfedge[f] == x)
        m->face_halfedge[f] = xn;
}

cg_status cg_hemesh_collapse_edge(cg_hemesh *m, uint32_t h)
{
    if (!cg_hemesh_collapse_ok(m, h))
        return CG_EINVAL;
    uint32_t t = h ^ 1u, u = m->halfedges[h].origin, v = m->halfedges[t].origin;
    size_t n = cg_hemesh_vertex_outgoing(m, u, 1, NULL, 0);
    uint32_t *out = malloc(n * sizeof *out);
    if (!out)
        return CG_ENOMEM;
    cg_hemesh_vertex_outgoing(m, u, 1, out, n);
    uint32_t keep = m->halfedges[h].next; /* v -> ..., survives either way */
    if (apex(m, h) != CG_HEMESH_NONE)
        drop_triangle(m, h);
    else
        unlink_side(m, h);
    if (apex(m, t) != CG_HEMESH_NONE)
        drop_triangle_twin(m, t);
    else
        unlink_side(m, t);
    for (size_t i = 0; i < n; i++)
        if (m->halfedges[out[i]].origin == u)
            m->halfedges[out[i]].origin = v;
    free(out);
    delete_edge(m, h);
    delete_vertex(m, u);
    m->vertex_halfedge[v] = keep;
    hm_fix_vertex_halfedge(m, v);
    return CG_OK;
}

/* ---- removal ------------------------------------------------------------------ */

cg_status cg_hemesh_remove_face(cg_hemesh *m, uint32_t f)
{
    if (!m || f >= m->face_count || m->face_halfedge[f] >= CG_HEMESH_DELETED)
        return CG_EINVAL;
    uint32_t h0 = m->face_halfedge[f];
    size_t k = loop_length(m, h0);
    uint32_t *side = malloc(k * sizeof *side);
    uint32_t *keep = malloc(k * sizeof *keep);
    uint32_t *corner = malloc(k * sizeof *corner);
    if (!side || !keep || !corner) {
        free(side);
        free(keep);
        free(corner);
        return CG_ENOMEM;
    }
    uint32_t h = h0;
    for (size_t i = 0; i < k; i++) {
        side[i] = h;
        corner[i] = m->halfedges[h].origin;
        h = m->halfedges[h].next;
    }
    /* for each corner, an outgoing half-edge whose edge survives */
    for (size_t i = 0; i < k; i++) {
        uint32_t x = side[i];
        keep[i] = CG_HEMESH_NONE;
        do {
            uint32_t a = m->halfedges[x].face, b = m->halfedges[x ^ 1u].face;
            int dies = (a == f && b == CG_HEMESH_NONE) || (b == f && a == CG_HEMESH_NONE);
            if (!dies) {
                keep[i] = x;
                break;
            }
            x = cg_hemesh_ccw(m, x);
        } while (x != side[i]);
    }
    for (size_t i = 0; i < k; i++)
        m->halfedges[side[i]].face = CG_HEMESH_NONE;
    delete_face(m, f);
    for (size_t i = 0; i < k; i++) {
        uint32_t x = side[i], y = x ^ 1u;
        if (m->halfedges[y].face != CG_HEMESH_NONE)
            continue;
        uint32_t xn = m->halfedges[x].next, xp = m->halfedges[x].prev;
        uint32_t yn = m->halfedges[y].next, yp = m->halfedges[y].prev;
        if (xn == y && yn == x) {
            /* a lone edge */
        } else if (xn == y) {
            link(m, xp, yn);
        } else if (yn == x) {
            link(m, yp, xn);
        } else {
            link(m, xp, yn);
            link(m, yp, xn);
        }
        delete_edge(m, x);
    }
    for (size_t i = 0; i < k; i++) {
        uint32_t v = corner[i];
        if (keep[i] == CG_HEMESH_NONE) {
            if (m->vertex_halfedge[v] != CG_HEMESH_DELETED)
                delete_vertex(m, v); /* left with no edge */
            continue;
        }
        m->vertex_halfedge[v] = keep[i];
        hm_fix_vertex_halfedge(m, v);
    }
    free(corner);
    free(side);
    free(keep);
    return CG_OK;
}

cg_status cg_hemesh_remove_vertex(cg_hemesh *m, uint32_t v)
{
    if (!m || v >= m->vertex_count || m->vertex_halfedge[v] == CG_HEMESH_DELETED)
        return CG_EINVAL;
    if (m->vertex_halfedge[v] == CG_HEMESH_NONE) {
        delete_vertex(m, v);
        return CG_OK;
    }
    size_t n = cg_hemesh_vertex_faces(m, v, 1, NULL, 0);
    uint32_t *faces = malloc((n ? n : 1) * sizeof *faces);
    if (!faces)
        return CG_ENOMEM;
    cg_hemesh_vertex_faces(m, v, 1, faces, n);
    cg_status s = CG_OK;
    for (size_t i = 0; i < n && s == CG_OK; i++)
        s = cg_hemesh_remove_face(m, faces[i]);
    free(faces);
    /* every edge at v had a face there, so v is gone with the last face */
    return s;
}
