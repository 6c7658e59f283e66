/* Traversals, counts, geometry and validation of the half-edge structure. */
#include "internal.h"
#include "../core/array.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

uint32_t cg_hemesh_find_halfedge(const cg_hemesh *m, uint32_t u, uint32_t v)
{
    if (!m || u >= m->vertex_count || v >= m->vertex_count)
        return CG_HEMESH_NONE;
    uint32_t h0 = m->vertex_halfedge[u];
    if (h0 >= CG_HEMESH_DELETED)
        return CG_HEMESH_NONE;
    uint32_t h = h0;
    do {
        if (m->halfedges[h ^ 1u].origin == v)
            return h;
        h = cg_hemesh_cw(m, h);
    } while (h != h0);
    return CG_HEMESH_NONE;
}

static int face_ok(const cg_hemesh *m, uint32_t f)
{
    return m && f < m->face_count && m->face_halfedge[f] < CG_HEMESH_DELETED;
}

static int vertex_ok(const cg_hemesh *m, uint32_t v)
{
    return m && v < m->vertex_count && m->vertex_halfedge[v] < CG_HEMESH_DELETED;
}

/* what: 0 half-edges, 1 vertices, 2 neighbouring faces (boundary edges have
 * none) of face f, in order; returns how many there are. */
static size_t around_face(const cg_hemesh *m, uint32_t f, int what, uint32_t *out, size_t capacity)
{
    if (!face_ok(m, f))
        return 0;
    size_t n = 0;
    uint32_t h0 = m->face_halfedge[f], h = h0;
    do {
        uint32_t x = what == 0 ? h : what == 1 ? m->halfedges[h].origin : m->halfedges[h ^ 1u].face;
        if (x != CG_HEMESH_NONE || what != 2) {
            if (n < capacity)
                out[n] = x;
            n++;
        }
        h = m->halfedges[h].next;
    } while (h != h0);
    return n;
}

size_t cg_hemesh_face_halfedges(const cg_hemesh *m, uint32_t f, uint32_t *out, size_t capacity)
{
    return around_face(m, f, 0, out, capacity);
}

size_t cg_hemesh_face_vertices(const cg_hemesh *m, uint32_t f, uint32_t *out, size_t capacity)
{
    return around_face(m, f, 1, out, capacity);
}

size_t cg_hemesh_face_neighbors(const cg_hemesh *m, uint32_t f, uint32_t *out, size_t capacity)
{
    return around_face(m, f, 2, out, capacity);
}

size_t cg_hemesh_face_size(const cg_hemesh *m, uint32_t f)
{
    return cg_hemesh_face_halfedges(m, f, NULL, 0);
}

/* what: 0 outgoing half-edges, 1 neighbours, 2 faces (holes have none) of
 * vertex v, turning in the given direction. */
static size_t around_vertex(const cg_hemesh *m, uint32_t v, int direction, int what, uint32_t *out,
                            size_t capacity)
{
    if (!vertex_ok(m, v))
        return 0;
    size_t n = 0;
    uint32_t h0 = m->vertex_halfedge[v], h = h0;
    do {
        uint32_t x = what == 0 ? h : what == 1 ? m->halfedges[h ^ 1u].origin : m->halfedges[h].face;
        if (x != CG_HEMESH_NONE || what != 2) {
            if (n < capacity)
                out[n] = x;
            n++;
        }
        h = direction > 0 ? cg_hemesh_ccw(m, h) : cg_hemesh_cw(m, h);
    } while (h != h0);
    return n;
}

size_t cg_hemesh_vertex_outgoing(const cg_hemesh *m, uint32_t v, int direction, uint32_t *out,
                                 size_t capacity)
{
    return around_vertex(m, v, direction, 0, out, capacity);
}

size_t cg_hemesh_vertex_neighbors(const cg_hemesh *m, uint32_t v, int direction, uint32_t *out,
                                  size_t capacity)
{
    return around_vertex(m, v, direction, 1, out, capacity);
}

size_t cg_hemesh_vertex_faces(const cg_hemesh *m, uint32_t v, int direction, uint32_t *out,
                              size_t capacity)
{
    return around_vertex(m, v, direction, 2, out, capacity);
}

size_t cg_hemesh_valence(const cg_hemesh *m, uint32_t v)
{
    return around_vertex(m, v, 1, 0, NULL, 0);
}

/* Adds the neighbours from half-edge h on until the rotation returns to h0. */
static void ring_rest(const cg_hemesh_halfedge *he, const cg_vec3 *p, uint32_t h, uint32_t h0,
                      double *x, double *y, double *z, size_t *n)
{
    do {
        const cg_hemesh_halfedge *t = &he[h ^ 1u];
        *x += p[t->origin].x;
        *y += p[t->origin].y;
        *z += p[t->origin].z;
        ++*n;
        h = t->next;
    } while (h != h0);
}

/* The average of the neighbours of v, walking clockwise: next(twin(h))
 * reads only the pair h, h ^ 1. */
static cg_vec3 neighbor_average(const cg_hemesh *m, uint32_t v)
{
    uint32_t h0 = m->vertex_halfedge[v];
    if (h0 >= CG_HEMESH_DELETED)
        return m->positions[v];
    double x = 0, y = 0, z = 0;
    size_t n = 0;
    ring_rest(m->halfedges, m->positions, h0, h0, &x, &y, &z, &n);
    double s = 1.0 / (double)n;
    return cg_vec3_make(x * s, y * s, z * s);
}

cg_status cg_hemesh_neighbor_average(const cg_hemesh *m, cg_vec3 *out)
{
    if (!m || !out)
        return CG_EINVAL;
    const cg_hemesh_halfedge *he = m->halfedges;
    const cg_vec3 *p = m->positions;
    size_t V = m->vertex_count, v = 0;
    /* Two vertices at a time: each rotation is a chain of dependent loads,
     * and walking two chains side by side keeps two misses in flight. */
    for (; v + 1 < V; v += 2) {
        uint32_t a0 = m->vertex_halfedge[v], b0 = m->vertex_halfedge[v + 1];
        if (a0 >= CG_HEMESH_DELETED || b0 >= CG_HEMESH_DELETED) {
            out[v] = neighbor_average(m, (uint32_t)v);
            out[v + 1] = neighbor_average(m, (uint32_t)v + 1);
            continue;
        }
        double ax = 0, ay = 0, az = 0, bx = 0, by = 0, bz = 0;
        size_t an = 0, bn = 0;
        uint32_t a = a0, b = b0;
        int a_more = 1, b_more = 1;
        while (a_more & b_more) {
            const cg_hemesh_halfedge *ta = &he[a ^ 1u], *tb = &he[b ^ 1u];
            const cg_vec3 *qa = &p[ta->origin], *qb = &p[tb->origin];
            a = ta->next;
            b = tb->next;
            ax += qa->x, ay += qa->y, az += qa->z;
            bx += qb->x, by += qb->y, bz += qb->z;
            an++, bn++;
            a_more = a != a0;
            b_more = b != b0;
        }
        if (a_more)
            ring_rest(he, p, a, a0, &ax, &ay, &az, &an);
        if (b_more)
            ring_rest(he, p, b, b0, &bx, &by, &bz, &bn);
        double sa = 1.0 / (double)an, sb = 1.0 / (double)bn;
        out[v] = cg_vec3_make(ax * sa, ay * sa, az * sa);
        out[v + 1] = cg_vec3_make(bx * sb, by * sb, bz * sb);
    }
    if (v < V)
        out[v] = neighbor_average(m, (uint32_t)v);
    return CG_OK;
}

/* ---- geometry ------------------------------------------------------------ */

cg_vec3 cg_hemesh_face_newell(const cg_hemesh *m, uint32_t f)
{
    cg_vec3 n = {0, 0, 0};
    if (!face_ok(m, f))
        return n;
    uint32_t h0 = m->face_halfedge[f], h = h0;
    do {
        cg_vec3 a = m->positions[m->halfedges[h].origin];
        cg_vec3 b = m->positions[m->halfedges[h ^ 1u].origin];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
        h = m->halfedges[h].next;
    } while (h != h0);
    return n;
}

cg_vec3 cg_hemesh_face_normal(const cg_hemesh *m, uint32_t f)
{
    return cg_vec3_normalize(cg_hemesh_face_newell(m, f));
}

double cg_hemesh_face_area(const cg_hemesh *m, uint32_t f)
{
    return 0.5 * cg_vec3_length(cg_hemesh_face_newell(m, f));
}

cg_vec3 cg_hemesh_vertex_normal(const cg_hemesh *m, uint32_t v)
{
    cg_vec3 n = {0, 0, 0};
    if (!vertex_ok(m, v))
        return n;
    uint32_t h0 = m->vertex_halfedge[v], h = h0;
    do {
        uint32_t f = m->halfedges[h].face;
        if (f != CG_HEMESH_NONE)
            n = cg_vec3_add(n, cg_hemesh_face_newell(m, f));
        h = cg_hemesh_ccw(m, h);
    } while (h != h0);
    return cg_vec3_normalize(n);
}

cg_status cg_hemesh_compute_normals(cg_hemesh *m)
{
    if (!m)
        return CG_EINVAL;
    if (!m->normals) {
        m->normals = calloc(m->vertex_capacity ? m->vertex_capacity : 1, sizeof *m->normals);
        if (!m->normals)
            return CG_ENOMEM;
    }
    /* each face's Newell vector added to its corners: O(corners) */
    for (size_t v = 0; v < m->vertex_count; v++)
        m->normals[v] = cg_vec3_make(0, 0, 0);
    for (size_t f = 0; f < m->face_count; f++) {
        if (m->face_halfedge[f] >= CG_HEMESH_DELETED)
            continue;
        cg_vec3 n = cg_hemesh_face_newell(m, (uint32_t)f);
        uint32_t h0 = m->face_halfedge[f], h = h0;
        do {
            uint32_t v = m->halfedges[h].origin;
            m->normals[v] = cg_vec3_add(m->normals[v], n);
            h = m->halfedges[h].next;
        } while (h != h0);
    }
    for (size_t v = 0; v < m->vertex_count; v++)
        m->normals[v] = cg_vec3_normalize(m->normals[v]);
    return CG_OK;
}

/* ---- counts -------------------------------------------------------------- */

/* The scratch of cg_hemesh_stats_compute, one entry per vertex (indexed by
 * a component's root vertex for the per-component counts) or per half-edge. */
typedef struct stats_scratch {
    uint32_t *parent;  /* union-find over the vertices; a root is its component's lowest vertex */
    uint8_t *seen;     /* half-edges already walked */
    long *chi;         /* V - E + F of each component */
    long *loops;       /* boundary loops of each component */
    uint8_t *has_face; /* whether the component has a face */
} stats_scratch;

static void stats_scratch_free(stats_scratch *s)
{
    free(s->parent);
    free(s->seen);
    free(s->chi);
    free(s->loops);
    free(s->has_face);
}

/* Joins the ends of every live edge: the components. */
static void union_components(const cg_hemesh *m, uint32_t *parent)
{
    for (size_t v = 0; v < m->vertex_count; v++)
        parent[v] = (uint32_t)v;
    for (size_t h = 0; h < m->halfedge_count; h += 2) {
        if (m->halfedges[h].origin == CG_HEMESH_DELETED)
            continue;
        uint32_t a = hm_find_root(parent, m->halfedges[h].origin);
        uint32_t b = hm_find_root(parent, m->halfedges[h + 1].origin);
        if (a != b) {
            if (a < b)
                parent[b] = a;
            else
                parent[a] = b;
        }
    }
}

/* The boundary loops, in all and per component. */
static void count_boundary_loops(const cg_hemesh *m, stats_scratch *s, cg_hemesh_stats *out)
{
    for (size_t h = 0; h < m->halfedge_count; h++) {
        if (s->seen[h] || m->halfedges[h].origin == CG_HEMESH_DELETED
            || m->halfedges[h].face != CG_HEMESH_NONE)
            continue;
        out->boundary_loops++;
        s->loops[hm_find_root(s->parent, m->halfedges[h].origin)]++;
        uint32_t x = (uint32_t)h;
        do {
            s->seen[x] = 1;
            x = m->halfedges[x].next;
        } while (x != h && !s->seen[x]);
    }
}

/* Isolated vertices, vertices with more than one boundary gap, and whether
 * every face is a triangle / a quad. */
static void count_vertex_and_face_kinds(const cg_hemesh *m, cg_hemesh_stats *out)
{
    out->all_triangles = out->all_quads = 1;
    for (size_t v = 0; v < m->vertex_count; v++) {
        uint32_t h0 = m->vertex_halfedge[v];
        if (h0 == CG_HEMESH_NONE)
            out->isolated_vertices++;
        if (h0 >= CG_HEMESH_DELETED || m->halfedges[h0].face != CG_HEMESH_NONE)
            continue;
        size_t gaps = 0;
        uint32_t h = h0;
        do {
            gaps += m->halfedges[h].face == CG_HEMESH_NONE;
            h = cg_hemesh_ccw(m, h);
        } while (h != h0);
        out->complex_vertices += gaps > 1;
    }
    for (size_t f = 0; f < m->face_count; f++) {
        if (m->face_halfedge[f] >= CG_HEMESH_DELETED)
            continue;
        size_t k = cg_hemesh_face_size(m, (uint32_t)f);
        out->all_triangles &= k == 3;
        out->all_quads &= k == 4;
    }
}

/* The components, and the Euler characteristic of each. */
static void count_component_euler(const cg_hemesh *m, stats_scratch *s, cg_hemesh_stats *out)
{
    for (size_t v = 0; v < m->vertex_count; v++) {
        if (m->vertex_halfedge[v] == CG_HEMESH_DELETED)
            continue;
        uint32_t r = hm_find_root(s->parent, (uint32_t)v);
        if (r == v)
            out->components++;
        s->chi[r]++;
    }
    for (size_t h = 0; h < m->halfedge_count; h += 2)
        if (m->halfedges[h].origin != CG_HEMESH_DELETED)
            s->chi[hm_find_root(s->parent, m->halfedges[h].origin)]--;
    for (size_t f = 0; f < m->face_count; f++) {
        if (m->face_halfedge[f] >= CG_HEMESH_DELETED)
            continue;
        uint32_t r = hm_find_root(s->parent, m->halfedges[m->face_halfedge[f]].origin);
        s->chi[r]++;
        s->has_face[r] = 1;
    }
}

/* The genus of each component with faces, in order of its lowest vertex:
 * out->genus when all agree, and the list (when list is not NULL). */
static cg_status list_genus(const cg_hemesh *m, const stats_scratch *s, cg_hemesh_stats *out,
                            long **list, size_t *count)
{
    long common = -2;
    CORE_ARRAY(long) genus = {0};
    size_t components = 0;
    for (size_t v = 0; v < m->vertex_count; v++) {
        if (m->vertex_halfedge[v] == CG_HEMESH_DELETED || s->parent[v] != v || !s->has_face[v])
            continue;
        long g = (2 - s->chi[v] - s->loops[v]) / 2;
        common = common == -2 ? g : common == g ? g : -1;
        if (list && core_array_push(&genus, g) != CG_OK) {
            free(genus.data);
            return CG_ENOMEM;
        }
        components++;
    }
    out->genus = common < 0 ? -1 : common;
    if (list)
        *list = genus.data;
    if (count)
        *count = components;
    return CG_OK;
}

cg_status cg_hemesh_stats_compute(const cg_hemesh *m, cg_hemesh_stats *out, long **component_genus,
                                  size_t *component_genus_count)
{
    if (component_genus)
        *component_genus = NULL;
    if (component_genus_count)
        *component_genus_count = 0;
    if (!m || !out)
        return CG_EINVAL;
    memset(out, 0, sizeof *out);
    size_t V = m->vertex_count ? m->vertex_count : 1, H = m->halfedge_count ? m->halfedge_count : 1;
    stats_scratch s = {malloc(V * sizeof *s.parent), calloc(H, 1), calloc(V, sizeof *s.chi),
                       calloc(V, sizeof *s.loops), calloc(V, 1)};
    if (!s.parent || !s.seen || !s.chi || !s.loops || !s.has_face) {
        stats_scratch_free(&s);
        return CG_ENOMEM;
    }
    out->vertices = m->live_vertices;
    out->edges = m->live_edges;
    out->faces = m->live_faces;
    out->euler_characteristic = (long)out->vertices - (long)out->edges + (long)out->faces;
    union_components(m, s.parent);
    count_boundary_loops(m, &s, out);
    count_vertex_and_face_kinds(m, out);
    count_component_euler(m, &s, out);
    cg_status status = list_genus(m, &s, out, component_genus, component_genus_count);
    stats_scratch_free(&s);
    return status;
}

/* ---- validation ------------------------------------------------------------ */

/* What the checks of cg_hemesh_validate share. */
typedef struct validation {
    const cg_hemesh *m;
    cg_error *err;
    uint32_t *out_count;  /* per vertex: live half-edges starting there */
    uint32_t *face_sides; /* per face: live half-edges on it */
    uint32_t *stamp;      /* per vertex: the face being walked (NONE: none) */
    size_t live_vertices, live_edges, live_faces;
} validation;

#define FAIL(...) return cg_error_set(check->err, CG_EFORMAT, "hemesh: " __VA_ARGS__)

/* Both halves of an edge are live or deleted together, and a live edge
 * has a face on at least one side. */
static cg_status check_edges(validation *check)
{
    const cg_hemesh *m = check->m;
    for (size_t e = 0; e < m->halfedge_count / 2; e++) {
        const cg_hemesh_halfedge *a = &m->halfedges[2 * e], *b = &m->halfedges[2 * e + 1];
        if ((a->origin == CG_HEMESH_DELETED) != (b->origin == CG_HEMESH_DELETED))
            FAIL("edge %zu is half deleted", e);
        if (a->origin == CG_HEMESH_DELETED)
            continue;
        check->live_edges++;
        if (a->face == CG_HEMESH_NONE && b->face == CG_HEMESH_NONE)
            FAIL("edge %zu has no face on either side", e);
    }
    return CG_OK;
}

/* Each live half-edge: its origin, next, prev, twin and face agree. */
static cg_status check_halfedges(validation *check)
{
    const cg_hemesh *m = check->m;
    size_t V = m->vertex_count, H = m->halfedge_count, F = m->face_count;
    for (size_t i = 0; i < H; i++) {
        const cg_hemesh_halfedge *x = &m->halfedges[i];
        if (x->origin == CG_HEMESH_DELETED)
            continue;
        uint32_t h = (uint32_t)i;
        if (x->origin >= V || m->vertex_halfedge[x->origin] >= CG_HEMESH_DELETED)
            FAIL("half-edge %u starts at vertex %u, which is out of range, deleted or isolated", h,
                 x->origin);
        if (x->next >= H || x->prev >= H || m->halfedges[x->next].origin == CG_HEMESH_DELETED
            || m->halfedges[x->prev].origin == CG_HEMESH_DELETED)
            FAIL("half-edge %u has next %u / prev %u out of range or deleted", h, x->next, x->prev);
        if (m->halfedges[x->next].prev != h || m->halfedges[x->prev].next != h)
            FAIL("half-edge %u: prev(next) or next(prev) is not itself", h);
        if (x->origin == m->halfedges[h ^ 1u].origin)
            FAIL("half-edge %u and its twin start at the same vertex %u", h, x->origin);
        if (m->halfedges[x->next].origin != m->halfedges[h ^ 1u].origin)
            FAIL("half-edge %u ends at %u but its next starts at %u", h,
                 m->halfedges[h ^ 1u].origin, m->halfedges[x->next].origin);
        if (m->halfedges[x->next].face != x->face)
            FAIL("half-edge %u and its next lie on different faces", h);
        if (x->face != CG_HEMESH_NONE) {
            if (x->face >= F || m->face_halfedge[x->face] >= CG_HEMESH_DELETED)
                FAIL("half-edge %u lies on face %u, out of range or deleted", h, x->face);
            check->face_sides[x->face]++;
        }
        check->out_count[x->origin]++;
    }
    return CG_OK;
}

/* Each live face's loop closes over all its half-edges, visits no vertex
 * twice and has at least three sides. */
static cg_status check_face_loops(validation *check)
{
    const cg_hemesh *m = check->m;
    uint32_t *stamp = check->stamp;
    for (size_t f = 0; f < m->face_count; f++) {
        uint32_t h0 = m->face_halfedge[f], sides = check->face_sides[f];
        if (h0 == CG_HEMESH_DELETED)
            continue;
        check->live_faces++;
        if (h0 >= m->halfedge_count || m->halfedges[h0].origin == CG_HEMESH_DELETED
            || m->halfedges[h0].face != f)
            FAIL("face %zu points at half-edge %u, which is not on it", f, h0);
        size_t n = 0;
        uint32_t h = h0;
        do {
            uint32_t v = m->halfedges[h].origin;
            if (n > 0 && stamp[v] == (uint32_t)f)
                FAIL("face %zu visits vertex %u twice", f, v);
            stamp[v] = (uint32_t)f;
            n++;
            h = m->halfedges[h].next;
        } while (h != h0 && n <= sides);
        if (h != h0 || n != sides)
            FAIL("the loop of face %zu does not close over its %u half-edges", f, sides);
        if (n < 3)
            FAIL("face %zu has %zu sides", f, n);
        /* reset the stamps of this face (a vertex may come back in a later face) */
        h = h0;
        do {
            stamp[m->halfedges[h].origin] = CG_HEMESH_NONE;
            h = m->halfedges[h].next;
        } while (h != h0);
    }
    return CG_OK;
}

/* Each live vertex's rotation visits exactly the half-edges starting there,
 * and a boundary vertex points at a boundary half-edge. */
static cg_status check_vertex_fans(validation *check)
{
    const cg_hemesh *m = check->m;
    for (size_t v = 0; v < m->vertex_count; v++) {
        uint32_t h0 = m->vertex_halfedge[v], outgoing = check->out_count[v];
        if (h0 == CG_HEMESH_DELETED) {
            if (outgoing)
                FAIL("deleted vertex %zu still has half-edges", v);
            continue;
        }
        check->live_vertices++;
        if (h0 == CG_HEMESH_NONE) {
            if (outgoing)
                FAIL("vertex %zu has no half-edge but %u half-edges start there", v, outgoing);
            continue;
        }
        if (h0 >= m->halfedge_count || m->halfedges[h0].origin != v)
            FAIL("vertex %zu points at half-edge %u, which does not start there", v, h0);
        size_t n = 0, boundary = 0;
        uint32_t h = h0;
        do {
            if (m->halfedges[h].origin != v)
                FAIL("rotating about vertex %zu reaches half-edge %u from vertex %u", v, h,
                     m->halfedges[h].origin);
            boundary += m->halfedges[h].face == CG_HEMESH_NONE;
            n++;
            h = cg_hemesh_ccw(m, h);
        } while (h != h0 && n <= outgoing);
        if (h != h0 || n != outgoing)
            FAIL("rotating about vertex %zu visits %zu of its %u half-edges", v, n, outgoing);
        if (boundary && m->halfedges[h0].face != CG_HEMESH_NONE)
            FAIL("boundary vertex %zu points at an interior half-edge", v);
    }
    return CG_OK;
}

/* The counts found agree with the stored ones. */
static cg_status check_live_counts(validation *check)
{
    const cg_hemesh *m = check->m;
    if (check->live_vertices != m->live_vertices || check->live_edges != m->live_edges
        || check->live_faces != m->live_faces)
        FAIL("live counts %zu/%zu/%zu differ from the stored %zu/%zu/%zu", check->live_vertices,
             check->live_edges, check->live_faces, m->live_vertices, m->live_edges, m->live_faces);
    return CG_OK;
}

#undef FAIL

cg_status cg_hemesh_validate(const cg_hemesh *m, cg_error *err)
{
    if (!m)
        return cg_error_set(err, CG_EINVAL, "hemesh: none given");
    size_t V = m->vertex_count, H = m->halfedge_count, F = m->face_count;
    if (H % 2 || V > m->vertex_capacity || H > m->halfedge_capacity || F > m->face_capacity)
        return cg_error_set(err, CG_EFORMAT, "hemesh: array sizes are inconsistent");
    validation check = {m,
                        err,
                        calloc(V ? V : 1, sizeof *check.out_count),
                        calloc(F ? F : 1, sizeof *check.face_sides),
                        malloc((V ? V : 1) * sizeof *check.stamp),
                        0,
                        0,
                        0};
    cg_status status;
    if (!check.out_count || !check.face_sides || !check.stamp) {
        status = cg_error_set(err, CG_ENOMEM, "hemesh: out of memory");
    } else {
        memset(check.stamp, 0xff, (V ? V : 1) * sizeof *check.stamp);
        if ((status = check_edges(&check)) == CG_OK && (status = check_halfedges(&check)) == CG_OK
            && (status = check_face_loops(&check)) == CG_OK
            && (status = check_vertex_fans(&check)) == CG_OK)
            status = check_live_counts(&check);
    }
    free(check.out_count);
    free(check.face_sides);
    free(check.stamp);
    return status;
}
