/* Subdivision stencils and local operations (chapter 9) step by step
 * (cg/trace_steps.h).  A stencil gives the new position of one old vertex
 * with the arithmetic of subdivide.c, so it is the subdivided mesh's
 * vertex bit for bit:
 *
 *   Loop, interior:          (1 - n beta) P + beta sum of the n neighbours,
 *                            beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n
 *   Catmull-Clark, interior: (F + 2 R + (n - 3) P) / n, F the average of the
 *                            face points (centroids) around P, R of the
 *                            midpoints of its edges
 *   boundary (both):         3/4 P + 1/8 (a + b), a and b its boundary
 *                            neighbours
 *
 * An edge operation lists the half-edge records around the edge before
 * and after the library's flip, split or collapse. */
#include "cg/hemesh.h"
#include "../core/steps.h"

#include <math.h>
#include <stdlib.h>

static cg_vec2 flat(cg_vec3 p)
{
    return cg_vec2_make(p.x, p.y);
}

static void vec3_field(core_step *s, const char *name, cg_vec3 p, double *store)
{
    store[0] = p.x;
    store[1] = p.y;
    store[2] = p.z;
    core_step_reals(s, name, store, 3);
}

/* One term of a stencil: its source, weight and position. */
static int emit_term(const char *phase, long long k, const char *what, long long index,
                     double weight, cg_vec3 p, cg_vec3 from, cg_step_fn fn, void *user)
{
    double xyz[3];
    cg_vec2 line[2] = {flat(from), flat(p)};
    core_step s;
    core_step_begin(&s, phase);
    core_step_integer(&s, "k", k);
    core_step_text(&s, "term", what);
    if (index >= 0)
        core_step_integer(&s, "index", index);
    else
        core_step_none(&s, "index");
    core_step_real(&s, "weight", weight);
    vec3_field(&s, "position", p, xyz);
    s.step.geometry = line;
    s.step.geometry_count = 2;
    s.step.kept = line; /* the stencil's star stays in the frames */
    s.step.kept_count = 2;
    return core_step_emit(&s, fn, user);
}

static int emit_result(const char *rule, size_t n, cg_vec3 p, cg_vec3 moved, double beta,
                       cg_step_fn fn, void *user)
{
    double a[3], b[3];
    cg_vec2 line[2] = {flat(p), flat(moved)};
    core_step s;
    core_step_begin(&s, "result");
    core_step_text(&s, "rule", rule);
    core_step_integer(&s, "n", (long long)n);
    if (isnan(beta))
        core_step_none(&s, "beta");
    else
        core_step_real(&s, "beta", beta);
    vec3_field(&s, "old", p, a);
    vec3_field(&s, "new", moved, b);
    s.step.geometry = line;
    s.step.geometry_count = 2;
    s.step.kept = line + 1;
    s.step.kept_count = 1;
    return core_step_emit(&s, fn, user);
}

static int dense(const cg_hemesh *m)
{
    return m->live_vertices == m->vertex_count && m->live_faces == m->face_count
           && 2 * m->live_edges == m->halfedge_count;
}

/* Isolated and boundary vertices, as subdivide.c places them: 1 when v is
 * one (its steps emitted), 0 for an interior vertex. */
static int outside_interior(const cg_hemesh *m, uint32_t v, cg_step_fn fn, void *user)
{
    uint32_t h = m->vertex_halfedge[v];
    cg_vec3 p = m->positions[v];
    if (h == CG_HEMESH_NONE) {
        emit_term("stencil", 0, "P", v, 1, p, p, fn, user);
        emit_result("isolated: stays", 0, p, p, NAN, fn, user);
        return 1;
    }
    if (m->halfedges[h].face != CG_HEMESH_NONE)
        return 0;
    const cg_hemesh_halfedge *he = m->halfedges;
    uint32_t a = he[h ^ 1u].origin, b = he[he[h].prev].origin;
    cg_vec3 pa = m->positions[a], pb = m->positions[b];
    cg_vec3 moved = cg_vec3_add(cg_vec3_scale(p, 0.75), cg_vec3_scale(cg_vec3_add(pa, pb), 0.125));
    if (!emit_term("stencil", 0, "P", v, 0.75, p, p, fn, user)
        && !emit_term("stencil", 1, "boundary neighbour", a, 0.125, pa, p, fn, user)
        && !emit_term("stencil", 2, "boundary neighbour", b, 0.125, pb, p, fn, user))
        emit_result("boundary: 3/4 P + 1/8 (a + b)", 2, p, moved, NAN, fn, user);
    return 1;
}

cg_status cg_hemesh_loop_stencil_steps(const cg_hemesh *m, uint32_t v, cg_step_fn step, void *user)
{
    if (!m || !step || v >= m->vertex_count || !dense(m))
        return CG_EINVAL;
    const cg_hemesh_halfedge *he = m->halfedges;
    for (size_t f = 0; f < m->face_count; f++) {
        uint32_t h = m->face_halfedge[f];
        if (he[he[he[h].next].next].next != h)
            return CG_EUNSUPPORTED;
    }
    if (outside_interior(m, v, step, user))
        return CG_OK;
    uint32_t h0 = m->vertex_halfedge[v], h = h0;
    size_t n = 0;
    do {
        n++;
        h = he[h ^ 1u].next;
    } while (h != h0);
    double c = 0.375 + 0.25 * cos(2.0 * CG_PI / (double)n), beta = (0.625 - c * c) / (double)n;
    cg_vec3 p = m->positions[v], sum = {0, 0, 0};
    if (emit_term("stencil", 0, "P", v, 1.0 - (double)n * beta, p, p, step, user))
        return CG_OK;
    long long k = 1;
    do {
        uint32_t w = he[h ^ 1u].origin;
        sum = cg_vec3_add(sum, m->positions[w]);
        if (emit_term("stencil", k++, "neighbour", w, beta, m->positions[w], p, step, user))
            return CG_OK;
        h = he[h ^ 1u].next;
    } while (h != h0);
    cg_vec3 moved = cg_vec3_add(cg_vec3_scale(p, 1.0 - (double)n * beta), cg_vec3_scale(sum, beta));
    emit_result("interior: (1 - n beta) P + beta sum", n, p, moved, beta, step, user);
    return CG_OK;
}

static cg_vec3 centroid(const cg_hemesh *m, uint32_t f)
{
    const cg_hemesh_halfedge *he = m->halfedges;
    uint32_t h0 = m->face_halfedge[f], h = h0, k = 0;
    cg_vec3 sum = {0, 0, 0};
    do {
        sum = cg_vec3_add(sum, m->positions[he[h].origin]);
        k++;
        h = he[h].next;
    } while (h != h0);
    return cg_vec3_scale(sum, 1.0 / (double)k);
}

cg_status cg_hemesh_catmull_clark_stencil_steps(const cg_hemesh *m, uint32_t v, cg_step_fn step,
                                                void *user)
{
    if (!m || !step || v >= m->vertex_count || !dense(m))
        return CG_EINVAL;
    if (outside_interior(m, v, step, user))
        return CG_OK;
    const cg_hemesh_halfedge *he = m->halfedges;
    uint32_t h0 = m->vertex_halfedge[v], h = h0;
    cg_vec3 p = m->positions[v], fsum = {0, 0, 0}, rsum = {0, 0, 0};
    size_t n = 0;
    do {
        n++;
        h = he[h ^ 1u].next;
    } while (h != h0);
    double dn = (double)n;
    long long k = 0;
    if (emit_term("stencil", k++, "P", v, (dn - 3.0) / dn, p, p, step, user))
        return CG_OK;
    do {
        cg_vec3 face_point = centroid(m, he[h].face);
        uint32_t w = he[h ^ 1u].origin;
        cg_vec3 mid = cg_vec3_scale(cg_vec3_add(p, m->positions[w]), 0.5);
        fsum = cg_vec3_add(fsum, face_point);
        rsum = cg_vec3_add(rsum, m->positions[w]);
        if (emit_term("stencil", k++, "face point", he[h].face, 1.0 / (dn * dn), face_point, p,
                      step, user)
            || emit_term("stencil", k++, "edge midpoint", w, 2.0 / (dn * dn), mid, p, step, user))
            return CG_OK;
        h = he[h ^ 1u].next;
    } while (h != h0);
    cg_vec3 favg = cg_vec3_scale(fsum, 1.0 / dn);
    cg_vec3 ravg = cg_vec3_scale(cg_vec3_add(cg_vec3_scale(p, dn), rsum), 0.5 / dn);
    cg_vec3 moved = cg_vec3_scale(
        cg_vec3_add(cg_vec3_add(favg, cg_vec3_scale(ravg, 2.0)), cg_vec3_scale(p, dn - 3.0)),
        1.0 / dn);
    emit_result("interior: (F + 2R + (n - 3) P) / n", n, p, moved, NAN, step, user);
    return CG_OK;
}

/* ---- edge operations ------------------------------------------------------ */

enum { MAX_AROUND = 64 };

/* The live vertices named in *vs (at most MAX_AROUND), for the records. */
typedef struct around {
    uint32_t v[MAX_AROUND];
    int count;
} around;

static void add_vertex(around *a, const cg_hemesh *m, uint32_t v)
{
    if (v >= m->vertex_count || cg_hemesh_vertex_is_deleted(m, v) || a->count >= MAX_AROUND)
        return;
    for (int i = 0; i < a->count; i++)
        if (a->v[i] == v)
            return;
    a->v[a->count++] = v;
}

/* The edge's ends and the corners opposite it. */
static around edge_vertices(const cg_hemesh *m, uint32_t e)
{
    around a = {{0}, 0};
    const cg_hemesh_halfedge *he = m->halfedges;
    for (uint32_t h = 2 * e; h < 2 * e + 2; h++) {
        add_vertex(&a, m, he[h].origin);
        if (he[h].face != CG_HEMESH_NONE)
            add_vertex(&a, m, he[he[h].prev].origin);
    }
    return a;
}

/* One step per half-edge leaving a vertex of a (in their one-rings). */
static int emit_records(const cg_hemesh *m, const char *phase, const around *a, cg_step_fn fn,
                        void *user)
{
    const cg_hemesh_halfedge *he = m->halfedges;
    long long k = 0;
    for (int i = 0; i < a->count; i++) {
        uint32_t h0 = m->vertex_halfedge[a->v[i]], h = h0;
        if (h0 >= CG_HEMESH_DELETED)
            continue;
        int guard = 0;
        do {
            cg_vec2 line[2] = {flat(m->positions[he[h].origin]),
                               flat(m->positions[cg_hemesh_dest(m, h)])};
            core_step s;
            core_step_begin(&s, phase);
            core_step_integer(&s, "k", k++);
            core_step_integer(&s, "h", h);
            core_step_integer(&s, "origin", he[h].origin);
            core_step_integer(&s, "dest", cg_hemesh_dest(m, h));
            core_step_integer(&s, "twin", h ^ 1u);
            core_step_integer(&s, "next", he[h].next);
            core_step_integer(&s, "prev", he[h].prev);
            if (he[h].face == CG_HEMESH_NONE)
                core_step_text(&s, "face", "boundary");
            else
                core_step_integer(&s, "face", he[h].face);
            s.step.geometry = line;
            s.step.geometry_count = 2;
            if (core_step_emit(&s, fn, user))
                return 1;
            h = he[h ^ 1u].next;
        } while (h != h0 && ++guard < 1024);
    }
    return 0;
}

cg_status cg_hemesh_edge_operation_steps(cg_hemesh *m, cg_edge_operation operation, uint32_t e,
                                         cg_step_fn step, void *user)
{
    if (!m || !step || e >= m->halfedge_count / 2 || cg_hemesh_edge_is_deleted(m, e)
        || (operation != CG_EDGE_FLIP && operation != CG_EDGE_SPLIT
            && operation != CG_EDGE_COLLAPSE))
        return CG_EINVAL;
    around before = edge_vertices(m, e);
    uint32_t a = m->halfedges[2 * e].origin, b = m->halfedges[2 * e + 1].origin;
    if (emit_records(m, "before", &before, step, user))
        return CG_OK;
    cg_status status;
    uint32_t added = CG_HEMESH_NONE;
    const char *what;
    switch (operation) {
    case CG_EDGE_FLIP:
        status = cg_hemesh_flip_edge(m, e);
        what = "flip: the edge now joins the opposite corners";
        break;
    case CG_EDGE_SPLIT:
        status = cg_hemesh_split_edge(
            m, e, cg_vec3_scale(cg_vec3_add(m->positions[a], m->positions[b]), 0.5), &added);
        what = "split at the midpoint: a new vertex joined to the opposite corners";
        break;
    default:
        status = cg_hemesh_collapse_edge(m, 2 * e);
        what = "collapse of h = 2e: its origin removed, its edges joined to its destination";
        break;
    }
    core_step s;
    core_step_begin(&s, "operation");
    core_step_integer(&s, "edge", e);
    core_step_integer(&s, "a", a);
    core_step_integer(&s, "b", b);
    core_step_text(&s, "operation", what);
    core_step_text(&s, "result", status == CG_OK ? "done" : "refused: the structure is unchanged");
    if (added != CG_HEMESH_NONE)
        core_step_integer(&s, "new_vertex", added);
    else
        core_step_none(&s, "new_vertex");
    cg_vec2 line[2] = {flat(m->positions[a]), flat(m->positions[b])};
    s.step.geometry = line;
    s.step.geometry_count = 2;
    if (core_step_emit(&s, step, user) || (status != CG_OK && status != CG_EINVAL))
        return status == CG_EINVAL ? CG_OK : status;
    if (status != CG_OK)
        return CG_OK;
    around after = before;
    add_vertex(&after, m, added);
    around live = {{0}, 0};
    for (int i = 0; i < after.count; i++)
        add_vertex(&live, m, after.v[i]);
    emit_records(m, "after", &live, step, user);
    return CG_OK;
}
