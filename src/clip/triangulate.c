/* Constrained Delaunay triangulation of polygons with holes, on the grid.
 *
 * 1. The rings are made simple by a union (fill rule), so that they meet
 *    at most at vertices; their distinct points are the vertices.
 * 2. The Delaunay triangulation of the vertices is built by inserting them
 *    one by one (random rounds, each in Morton order; each found by walking
 *    from the last one) into
 *    a triangle that encloses the grid, each insertion split and then made
 *    Delaunay again by flipping (Lawson).
 * 3. Each ring edge missing from it is recovered by flipping the edges
 *    that cross it (Sloan); a ring edge with vertices on it (a hole may
 *    touch its outer ring inside an edge) is recovered piece by piece.
 * 4. Every edge that is not a ring edge is flipped until it is locally
 *    Delaunay, which makes the triangulation the constrained Delaunay one.
 * 5. The triangles to the left of the ring edges (outer rings run
 *    counter-clockwise, holes clockwise) and those reached from them
 *    without crossing a ring edge are the result.
 *
 * A triangle stores its vertices counter-clockwise and, for each vertex i,
 * the neighbour across the edge opposite it (from vertex i+1 to i+2):
 *
 *                 v[2]
 *                 /  \
 *   neighbor[1]  /    \  neighbor[0]
 *               /      \
 *            v[0] ----- v[1]
 *               neighbor[2]
 */
#include "triangulate_internal.h"

#include "../core/array.h"
#include "../core/sort.h"

#include <stdlib.h>
#include <string.h>

#define NONE UINT32_MAX
#define NEXT(i) ((i) == 2 ? 0 : (i) + 1)
#define PREV(i) ((i) == 0 ? 2 : (i)-1)

typedef struct triangle {
    uint32_t vertex[3];
    uint32_t neighbor[3];
    uint8_t constrained; /* bit i: the edge opposite vertex i is a ring edge */
    uint8_t inside;
} triangle;

typedef struct mesh {
    CORE_ARRAY(cg_point64) points; /* the vertices, then the 3 enclosing corners */
    CORE_ARRAY(triangle) triangles;
    CORE_ARRAY(uint32_t) corner_of; /* a triangle with each vertex */
    CORE_ARRAY(uint64_t) stack;     /* edges to check: triangle << 2 | vertex */
    uint32_t last;                  /* where the next walk starts */
} mesh;

static cg_point64 point_of(const mesh *m, const triangle *t, int i)
{
    return m->points.data[t->vertex[i]];
}

/* Where triangle u keeps t as a neighbour. */
static int back_index(const mesh *m, uint32_t u, uint32_t t)
{
    const triangle *x = &m->triangles.data[u];
    return x->neighbor[0] == t ? 0 : x->neighbor[1] == t ? 1 : 2;
}

static void relink(mesh *m, uint32_t u, uint32_t from, uint32_t to)
{
    if (u != NONE)
        m->triangles.data[u].neighbor[back_index(m, u, from)] = to;
}

static void set_triangle(mesh *m, uint32_t t, uint32_t a, uint32_t b, uint32_t c, uint32_t na,
                         uint32_t nb, uint32_t nc)
{
    triangle *x = &m->triangles.data[t];
    *x = (triangle){{a, b, c}, {na, nb, nc}, 0, 0};
    m->corner_of.data[a] = m->corner_of.data[b] = m->corner_of.data[c] = t;
}

static cg_status push_edge(mesh *m, uint32_t t, int i)
{
    return core_array_push(&m->stack, (uint64_t)t << 2 | (uint64_t)i);
}

/* Flips the edge opposite vertex i of t (p, b, c) with the neighbour u
 * (d, c, b) into t = (p, b, d) and u = (p, d, c); ring-edge marks follow
 * their edges. */
static void flip(mesh *m, uint32_t t, int i)
{
    triangle *x = &m->triangles.data[t];
    uint32_t u = x->neighbor[i];
    int j = back_index(m, u, t);
    triangle *y = &m->triangles.data[u];
    uint32_t p = x->vertex[i], b = x->vertex[NEXT(i)], c = x->vertex[PREV(i)], d = y->vertex[j];
    uint32_t tn_b = x->neighbor[NEXT(i)], tn_c = x->neighbor[PREV(i)];
    uint32_t un_c = y->neighbor[NEXT(j)], un_b = y->neighbor[PREV(j)];
    int tc_b = x->constrained >> NEXT(i) & 1, tc_c = x->constrained >> PREV(i) & 1;
    int uc_c = y->constrained >> NEXT(j) & 1, uc_b = y->constrained >> PREV(j) & 1;
    set_triangle(m, t, p, b, d, un_c, u, tn_c);
    set_triangle(m, u, p, d, c, un_b, tn_b, t);
    m->triangles.data[t].constrained = (uint8_t)(uc_c | tc_c << 2);
    m->triangles.data[u].constrained = (uint8_t)(uc_b | tc_b << 1);
    relink(m, un_c, u, t);
    relink(m, tn_b, t, u);
}

/* Flips illegal edges from the stack until it is empty: an edge that is not
 * a ring edge, whose far vertex lies inside the circle of its triangle. */
static cg_status legalize(mesh *m)
{
    cg_status st = CG_OK;
    while (m->stack.count > 0 && st == CG_OK) {
        uint64_t e = m->stack.data[--m->stack.count];
        uint32_t t = (uint32_t)(e >> 2);
        int i = (int)(e & 3);
        triangle *x = &m->triangles.data[t];
        uint32_t u = x->neighbor[i];
        if (u == NONE || (x->constrained >> i & 1))
            continue;
        const triangle *y = &m->triangles.data[u];
        cg_point64 d = point_of(m, y, back_index(m, u, t));
        if (triangulate_incircle(point_of(m, x, 0), point_of(m, x, 1), point_of(m, x, 2), d) <= 0)
            continue;
        flip(m, t, i);
        /* the four outer edges of the quadrilateral: opposite p in both,
         * and opposite d in t, c in u */
        st = push_edge(m, t, 0);
        if (st == CG_OK)
            st = push_edge(m, u, 0);
        if (st == CG_OK)
            st = push_edge(m, t, 2);
        if (st == CG_OK)
            st = push_edge(m, u, 1);
    }
    return st;
}

/* The triangle holding p, found by walking from the last one: every step
 * crosses an edge that has p strictly on its far side. */
static uint32_t locate(const mesh *m, cg_point64 p)
{
    uint32_t t = m->last;
    int start = 0;
    for (;;) {
        const triangle *x = &m->triangles.data[t];
        int moved = 0;
        for (int k = 0; k < 3 && !moved; k++) {
            int e = (start + k) % 3;
            if (polygon_orient(point_of(m, x, NEXT(e)), point_of(m, x, PREV(e)), p) < 0) {
                t = x->neighbor[e];
                moved = 1;
            }
        }
        if (!moved)
            return t;
        start = start == 2 ? 0 : start + 1;
    }
}

/* Inserts vertex v: into the triangle holding it (split in three), or onto
 * the edge it lies on (the two triangles split in four). */
static cg_status insert(mesh *m, uint32_t v)
{
    cg_point64 p = m->points.data[v];
    uint32_t t = locate(m, p);
    triangle x = m->triangles.data[t];
    int on_edge = -1;
    for (int e = 0; e < 3; e++)
        if (polygon_orient(point_of(m, &x, NEXT(e)), point_of(m, &x, PREV(e)), p) == 0)
            on_edge = e;
    size_t first = m->triangles.count;
    if (core_array_reserve_for(&m->triangles, first + 3) != CG_OK)
        return CG_ENOMEM;
    m->triangles.count += 2; /* t (and u, on an edge) are reused */
    uint32_t b1 = (uint32_t)first, b2 = (uint32_t)first + 1;
    cg_status st = CG_OK;
    if (on_edge < 0) {
        uint32_t v0 = x.vertex[0], v1 = x.vertex[1], v2 = x.vertex[2];
        set_triangle(m, t, v0, v1, v, b1, b2, x.neighbor[2]);
        set_triangle(m, b1, v1, v2, v, b2, t, x.neighbor[0]);
        set_triangle(m, b2, v2, v0, v, t, b1, x.neighbor[1]);
        relink(m, x.neighbor[0], t, b1);
        relink(m, x.neighbor[1], t, b2);
        st = push_edge(m, t, 2);
        if (st == CG_OK)
            st = push_edge(m, b1, 2);
        if (st == CG_OK)
            st = push_edge(m, b2, 2);
    } else {
        /* t = (a, b, c) with p on b-c; u = (d, c, b) across it */
        uint32_t a = x.vertex[on_edge], b = x.vertex[NEXT(on_edge)], c = x.vertex[PREV(on_edge)];
        uint32_t nb = x.neighbor[NEXT(on_edge)], nc = x.neighbor[PREV(on_edge)];
        uint32_t u = x.neighbor[on_edge];
        triangle y = m->triangles.data[u];
        int j = back_index(m, u, t);
        uint32_t d = y.vertex[j], un_b = y.neighbor[PREV(j)], un_c = y.neighbor[NEXT(j)];
        set_triangle(m, t, a, b, v, b2, b1, nc);   /* t1 = (a, b, p) */
        set_triangle(m, b1, a, v, c, u, nb, t);    /* t2 = (a, p, c) */
        set_triangle(m, u, d, c, v, b1, b2, un_b); /* u1 = (d, c, p) */
        set_triangle(m, b2, d, v, b, t, un_c, u);  /* u2 = (d, p, b) */
        relink(m, nb, t, b1);
        relink(m, un_c, u, b2);
        st = push_edge(m, t, 2);
        if (st == CG_OK)
            st = push_edge(m, b1, 1);
        if (st == CG_OK)
            st = push_edge(m, u, 2);
        if (st == CG_OK)
            st = push_edge(m, b2, 1);
    }
    m->last = t;
    return st == CG_OK ? legalize(m) : st;
}

/* The triangle with the directed edge a-b, as (triangle, vertex opposite);
 * NONE when a-b is not an edge.  Turns around a's fan. */
static uint32_t find_edge(const mesh *m, uint32_t a, uint32_t b, int *opposite)
{
    uint32_t start = m->corner_of.data[a], t = start;
    do {
        const triangle *x = &m->triangles.data[t];
        int k = x->vertex[0] == a ? 0 : x->vertex[1] == a ? 1 : 2;
        if (x->vertex[NEXT(k)] == b) {
            *opposite = PREV(k);
            return t;
        }
        t = x->neighbor[NEXT(k)];
    } while (t != start && t != NONE);
    return NONE;
}

/* 1 when segment p-q crosses segment a-b at a point inside both. */
static int crosses(cg_point64 p, cg_point64 q, cg_point64 a, cg_point64 b)
{
    int s1 = polygon_orient(a, b, p), s2 = polygon_orient(a, b, q);
    int s3 = polygon_orient(p, q, a), s4 = polygon_orient(p, q, b);
    return s1 * s2 < 0 && s3 * s4 < 0;
}

/* 1 when c lies strictly inside segment a-b. */
static int inside_segment(cg_point64 a, cg_point64 b, cg_point64 c)
{
    if (polygon_orient(a, b, c) != 0)
        return 0;
    polygon_i128 dot = (polygon_i128)(c.x - a.x) * (b.x - a.x)
                       + (polygon_i128)(c.y - a.y) * (b.y - a.y);
    polygon_i128 len = (polygon_i128)(b.x - a.x) * (b.x - a.x)
                       + (polygon_i128)(b.y - a.y) * (b.y - a.y);
    return dot > 0 && dot < len;
}

typedef CORE_ARRAY(uint64_t) edge_queue;

/* Walks from a towards b, gathering into queue (emptied first) the edges
 * that cross segment a-b, up to b or to the first vertex lying on the
 * segment (a touching ring's vertex may): that vertex, or b, in *reached. */
static cg_status gather_crossings(mesh *m, uint32_t a, uint32_t b, edge_queue *queue,
                                  uint32_t *reached)
{
    cg_point64 pa = m->points.data[a], pb = m->points.data[b];
    uint32_t s = m->corner_of.data[a];
    int i = 0;
    queue->count = 0;
    for (size_t guard = 0;; guard++) { /* the triangle of a's fan that a-b leaves a through */
        if (guard > m->triangles.count)
            return CG_EINVAL;
        const triangle *x = &m->triangles.data[s];
        int k = x->vertex[0] == a ? 0 : x->vertex[1] == a ? 1 : 2;
        cg_point64 p = point_of(m, x, NEXT(k)), q = point_of(m, x, PREV(k));
        if (inside_segment(pa, pb, p) || inside_segment(pa, pb, q)) {
            *reached = inside_segment(pa, pb, p) ? x->vertex[NEXT(k)] : x->vertex[PREV(k)];
            return CG_OK; /* a-reached is already an edge */
        }
        if (polygon_orient(pa, p, pb) > 0 && polygon_orient(pa, q, pb) < 0) {
            i = k;
            break;
        }
        s = x->neighbor[NEXT(k)];
    }
    for (;;) { /* cross the edge opposite i of s, into the next triangle */
        const triangle *x = &m->triangles.data[s];
        uint32_t p = x->vertex[NEXT(i)], q = x->vertex[PREV(i)];
        if (core_array_push(queue, (uint64_t)p << 32 | q) != CG_OK)
            return CG_ENOMEM;
        uint32_t u = x->neighbor[i];
        const triangle *y = &m->triangles.data[u];
        int j = back_index(m, u, s);
        uint32_t z = y->vertex[j];
        int side = polygon_orient(pa, pb, m->points.data[z]);
        if (z == b || side == 0) {
            *reached = z;
            return CG_OK;
        }
        /* leave through the edge whose ends lie on both sides of a-b: the
         * entry edge's right end with z when z is on the left */
        i = side > 0 ? NEXT(j) : PREV(j);
        s = u;
    }
}

/* Sloan: flips each queued edge crossing a-b whose quadrilateral is
 * convex; one still crossing goes back into the queue, as does one not
 * yet flippable, until none crosses. */
static cg_status flip_crossings(mesh *m, uint32_t a, uint32_t b, edge_queue *queue)
{
    cg_point64 pa = m->points.data[a], pb = m->points.data[b];
    size_t limit = 64 * queue->count + 1024;
    for (size_t head = 0; head < queue->count; head++) {
        if (head > limit)
            return CG_EINVAL; /* cannot happen when no vertex lies on a-b */
        uint32_t p = (uint32_t)(queue->data[head] >> 32), q = (uint32_t)queue->data[head];
        int k;
        uint32_t s = find_edge(m, p, q, &k);
        if (s == NONE)
            continue;
        const triangle *x = &m->triangles.data[s];
        uint32_t u = x->neighbor[k];
        uint32_t r = m->triangles.data[u].vertex[back_index(m, u, s)], w = x->vertex[k];
        cg_point64 pw = m->points.data[w], pr = m->points.data[r];
        cg_status st = CG_OK;
        if (!crosses(pw, pr, m->points.data[p], m->points.data[q])) {
            st = core_array_push(queue, queue->data[head]);
        } else {
            flip(m, s, k); /* the new edge is w-r */
            if (crosses(pw, pr, pa, pb))
                st = core_array_push(queue, (uint64_t)w << 32 | r);
        }
        if (st != CG_OK)
            return st;
    }
    return CG_OK;
}

/* Marks the edge a-b (present) as a ring edge on both sides. */
static cg_status mark_edge(mesh *m, uint32_t a, uint32_t b)
{
    int i;
    uint32_t t = find_edge(m, a, b, &i);
    if (t == NONE)
        return CG_EINVAL;
    triangle *x = &m->triangles.data[t];
    x->constrained |= (uint8_t)(1 << i);
    uint32_t u = x->neighbor[i];
    m->triangles.data[u].constrained |= (uint8_t)(1 << back_index(m, u, t));
    return CG_OK;
}

/* Makes the ring edge a-b a union of triangle edges (split at the vertices
 * lying on it) by flipping the edges that cross it, and marks them. */
static cg_status recover_edge(mesh *m, uint32_t a, uint32_t b)
{
    edge_queue queue = {0};
    cg_status st = CG_OK;
    while (a != b && st == CG_OK) {
        int i;
        uint32_t reached = b;
        if (find_edge(m, a, b, &i) == NONE)
            st = gather_crossings(m, a, b, &queue, &reached);
        if (st == CG_OK)
            st = flip_crossings(m, a, reached, &queue);
        if (st == CG_OK)
            st = mark_edge(m, a, reached);
        a = reached;
    }
    core_array_free(&queue);
    return st;
}

/* The triangle with the first piece of ring edge a-b leaving a (to b, or
 * to the first vertex on the way), as (triangle, vertex opposite). */
static uint32_t first_piece(const mesh *m, uint32_t a, uint32_t b, int *opposite)
{
    uint32_t t = find_edge(m, a, b, opposite);
    if (t != NONE)
        return t;
    cg_point64 pa = m->points.data[a], pb = m->points.data[b];
    uint32_t start = m->corner_of.data[a];
    t = start;
    do {
        const triangle *x = &m->triangles.data[t];
        int k = x->vertex[0] == a ? 0 : x->vertex[1] == a ? 1 : 2;
        if (inside_segment(pa, pb, point_of(m, x, NEXT(k)))) {
            *opposite = PREV(k);
            return t;
        }
        t = x->neighbor[NEXT(k)];
    } while (t != start && t != NONE);
    return NONE;
}

/* ---- building it ------------------------------------------------------------ */

/* Interleaves the bits of x and y (each below 2^28). */
static uint64_t morton(uint64_t x, uint64_t y)
{
    uint64_t key = 0;
    for (int bit = 0; bit < 28; bit++)
        key |= (x >> bit & 1) << (2 * bit) | (y >> bit & 1) << (2 * bit + 1);
    return key;
}

typedef struct keyed {
    uint64_t key;
    uint32_t vertex;
} keyed;

static int compare_keyed(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    return (x->key > y->key) - (x->key < y->key);
}

static int compare_points(const void *a, const void *b)
{
    const cg_point64 *p = a, *q = b;
    if (p->x != q->x)
        return (p->x > q->x) - (p->x < q->x);
    return (p->y > q->y) - (p->y < q->y);
}

/* The index of p among the sorted distinct points. */
static uint32_t vertex_of(const mesh *m, size_t count, cg_point64 p)
{
    const cg_point64 *found = bsearch(&p, m->points.data, count, sizeof p, compare_points);
    return (uint32_t)(found - m->points.data);
}

/* The distinct points of the rings, sorted, then the enclosing triangle's
 * three corners and its one triangle. */
static cg_status start_mesh(mesh *m, const cg_polygon_set64 *rings, size_t *count)
{
    size_t n = rings->point_count;
    if (core_array_reserve_for(&m->points, n + 3) != CG_OK)
        return CG_ENOMEM;
    if (n > 0) /* memcpy wants non-null pointers even for no points */
        memcpy(m->points.data, rings->points, n * sizeof *rings->points);
    core_sort(m->points.data, n, sizeof *m->points.data, compare_points);
    size_t distinct = 0;
    for (size_t i = 0; i < n; i++)
        if (distinct == 0 || compare_points(&m->points.data[distinct - 1], &m->points.data[i]) != 0)
            m->points.data[distinct++] = m->points.data[i];
    const int64_t far = (int64_t)1 << 42;
    m->points.data[distinct] = (cg_point64){-far, -far};
    m->points.data[distinct + 1] = (cg_point64){2 * far, -far};
    m->points.data[distinct + 2] = (cg_point64){-far, 2 * far};
    m->points.count = distinct + 3;
    *count = distinct;
    if (core_array_reserve_for(&m->corner_of, distinct + 3) != CG_OK
        || core_array_reserve_for(&m->triangles, 2 * distinct + 8) != CG_OK)
        return CG_ENOMEM;
    m->corner_of.count = distinct + 3;
    m->triangles.count = 1;
    uint32_t c = (uint32_t)distinct;
    set_triangle(m, 0, c, c + 1, c + 2, NONE, NONE, NONE);
    m->last = 0;
    return CG_OK;
}

/* Inserts every vertex. */
static cg_status insert_all(mesh *m, size_t count)
{
    CORE_ARRAY(keyed) order = {0};
    if (core_array_reserve_for(&order, count) != CG_OK)
        return CG_ENOMEM;
    int64_t lo_x = INT64_MAX, lo_y = INT64_MAX, hi = 1;
    for (size_t i = 0; i < count; i++) {
        lo_x = m->points.data[i].x < lo_x ? m->points.data[i].x : lo_x;
        lo_y = m->points.data[i].y < lo_y ? m->points.data[i].y : lo_y;
    }
    for (size_t i = 0; i < count; i++) {
        int64_t dx = m->points.data[i].x - lo_x, dy = m->points.data[i].y - lo_y;
        hi = dx > hi ? dx : hi;
        hi = dy > hi ? dy : hi;
    }
    /* biased randomized insertion: the vertices shuffled, then in rounds
     * of doubling size (1, 2, 4, ...), each round in Morton order, so that
     * points along a curve are not met in order (which makes every insertion
     * flip around the whole curve) and each walk stays short */
    double to_key = 268435455.0 / (double)hi;
    uint64_t random = 0x9e3779b97f4a7c15ull;
    for (size_t i = 0; i < count; i++)
        order.data[i].vertex = (uint32_t)i;
    for (size_t i = count; i > 1; i--) {
        random ^= random << 13;
        random ^= random >> 7;
        random ^= random << 17;
        size_t j = (size_t)(random % i);
        uint32_t swap = order.data[i - 1].vertex;
        order.data[i - 1].vertex = order.data[j].vertex;
        order.data[j].vertex = swap;
    }
    for (size_t i = 0; i < count; i++) {
        cg_point64 p = m->points.data[order.data[i].vertex];
        uint64_t x = (uint64_t)((double)(p.x - lo_x) * to_key);
        uint64_t y = (uint64_t)((double)(p.y - lo_y) * to_key);
        uint64_t round = 0;
        while (((size_t)2 << round) <= i + 1)
            round++;
        order.data[i].key = round << 56 | morton(x, y); /* rounds below 2^8 */
    }
    core_sort(order.data, count, sizeof *order.data, compare_keyed);
    cg_status st = CG_OK;
    for (size_t i = 0; i < count && st == CG_OK; i++)
        st = insert(m, order.data[i].vertex);
    core_array_free(&order);
    return st;
}

/* Every edge that is not a ring edge made locally Delaunay. */
static cg_status make_delaunay(mesh *m)
{
    cg_status st = CG_OK;
    for (uint32_t t = 0; t < m->triangles.count && st == CG_OK; t++)
        for (int i = 0; i < 3 && st == CG_OK; i++)
            if (m->triangles.data[t].neighbor[i] != NONE && m->triangles.data[t].neighbor[i] > t)
                st = push_edge(m, t, i);
    return st == CG_OK ? legalize(m) : st;
}

/* Marks inside the triangles left of each ring edge and those reached from
 * them without crossing a ring edge. */
static cg_status mark_inside(mesh *m, const cg_polygon_set64 *rings, size_t count)
{
    m->stack.count = 0;
    for (size_t r = 0; r < rings->ring_count; r++) {
        size_t a = rings->ring_start[r], b = rings->ring_start[r + 1];
        for (size_t k = a; k < b; k++) {
            uint32_t u = vertex_of(m, count, rings->points[k]);
            uint32_t v = vertex_of(m, count, rings->points[k + 1 < b ? k + 1 : a]);
            int i;
            uint32_t t = first_piece(m, u, v, &i);
            if (t != NONE && !m->triangles.data[t].inside) {
                m->triangles.data[t].inside = 1;
                if (push_edge(m, t, 0) != CG_OK)
                    return CG_ENOMEM;
            }
        }
    }
    while (m->stack.count > 0) {
        uint32_t t = (uint32_t)(m->stack.data[--m->stack.count] >> 2);
        const triangle *x = &m->triangles.data[t];
        for (int i = 0; i < 3; i++) {
            uint32_t u = x->neighbor[i];
            if (u == NONE || (x->constrained >> i & 1) || m->triangles.data[u].inside)
                continue;
            m->triangles.data[u].inside = 1;
            if (push_edge(m, u, 0) != CG_OK)
                return CG_ENOMEM;
            x = &m->triangles.data[t];
        }
    }
    return CG_OK;
}

/* Steps 2 to 5 on simple rings; the inside triangles into result. */
static cg_status triangulate_rings(mesh *m, const cg_polygon_set64 *rings, cg_polygon_set64 *result)
{
    size_t count;
    if (rings->point_count > ((size_t)1 << 30))
        return CG_EUNSUPPORTED;
    cg_status st = start_mesh(m, rings, &count);
    if (st == CG_OK)
        st = insert_all(m, count);
    for (size_t r = 0; r < rings->ring_count && st == CG_OK; r++) {
        size_t a = rings->ring_start[r], b = rings->ring_start[r + 1];
        for (size_t k = a; k < b && st == CG_OK; k++)
            st = recover_edge(m, vertex_of(m, count, rings->points[k]),
                              vertex_of(m, count, rings->points[k + 1 < b ? k + 1 : a]));
    }
    if (st == CG_OK)
        st = make_delaunay(m);
    if (st == CG_OK)
        st = mark_inside(m, rings, count);
    cg_polygon_set64_clear(result);
    for (uint32_t t = 0; t < m->triangles.count && st == CG_OK; t++) {
        const triangle *x = &m->triangles.data[t];
        if (!x->inside)
            continue;
        cg_point64 p[3] = {point_of(m, x, 0), point_of(m, x, 1), point_of(m, x, 2)};
        st = cg_polygon_set64_add_ring(result, p, 3, 1);
    }
    return st;
}

cg_status cg_triangulate64_ws(cg_clip_workspace *ws, const cg_polygon_set64 *paths,
                              cg_clip_fill fill, cg_polygon_set64 *triangles)
{
    if (!paths || !triangles || (unsigned)fill > CG_CLIP_NEGATIVE)
        return CG_EINVAL;
    cg_polygon_set64 simple = {0}, none = {0};
    cg_status st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, paths, fill, &none, fill, &simple);
    mesh m = {0};
    if (st == CG_OK)
        st = triangulate_rings(&m, &simple, triangles);
    core_array_free(&m.points);
    core_array_free(&m.triangles);
    core_array_free(&m.corner_of);
    core_array_free(&m.stack);
    cg_polygon_set64_clear(&simple);
    return st;
}

cg_status cg_triangulate64(const cg_polygon_set64 *paths, cg_clip_fill fill,
                           cg_polygon_set64 *triangles)
{
    return cg_triangulate64_ws(NULL, paths, fill, triangles);
}

cg_status cg_triangulate_ws(cg_clip_workspace *ws, const cg_polygon_set *paths, cg_clip_fill fill,
                            double scale, cg_polygon_set *triangles)
{
    if (!paths || !triangles)
        return CG_EINVAL;
    polygon_grid grid;
    cg_polygon_set64 in = {0}, out = {0};
    cg_status st = polygon_grid_pick(scale, polygon_max_abs(paths), &grid);
    if (st == CG_OK)
        st = polygon_set_to_grid(paths, grid, &in);
    if (st == CG_OK)
        st = cg_triangulate64_ws(ws, &in, fill, &out);
    if (st == CG_OK)
        st = polygon_set_from_grid(&out, grid, triangles);
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
    return st;
}

cg_status cg_triangulate(const cg_polygon_set *paths, cg_clip_fill fill, double scale,
                         cg_polygon_set *triangles)
{
    return cg_triangulate_ws(NULL, paths, fill, scale, triangles);
}
