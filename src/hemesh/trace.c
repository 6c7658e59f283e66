/* Half-edge traversals (chapter 9) step by step (cg/trace_steps.h): the
 * loop of a face by next, and the one-ring of a vertex by twin and prev,
 * with the same walks as cg_hemesh_face_halfedges and
 * cg_hemesh_vertex_outgoing.
 *
 *          v_dest                 ccw(h) = twin(prev(h)): the outgoing
 *         ^  |                    half-edge after h, counter-clockwise
 *       h |  | twin(h)            around origin(h)
 *         |  v
 *          v_origin  */
#include "cg/hemesh.h"
#include "../core/steps.h"

static cg_vec2 flat(const cg_hemesh *m, uint32_t v)
{
    return cg_vec2_make(m->positions[v].x, m->positions[v].y);
}

static long long index_or_none(uint32_t x)
{
    return x == CG_HEMESH_NONE ? -1 : (long long)x;
}

cg_status cg_hemesh_face_loop_steps(const cg_hemesh *m, uint32_t f, cg_step_fn step, void *user)
{
    if (!m || !step || f >= m->face_count || m->face_halfedge[f] >= CG_HEMESH_DELETED)
        return CG_EINVAL;
    uint32_t h0 = m->face_halfedge[f], h = h0;
    long k = 0;
    do {
        const cg_hemesh_halfedge *e = &m->halfedges[h];
        cg_vec2 edge[2] = {flat(m, e->origin), flat(m, cg_hemesh_dest(m, h))};
        core_step s;
        core_step_begin(&s, "face loop");
        core_step_integer(&s, "k", k++);
        core_step_integer(&s, "h", h);
        core_step_integer(&s, "origin", e->origin);
        core_step_integer(&s, "next", e->next);
        core_step_integer(&s, "twin", cg_hemesh_twin(h));
        core_step_integer(&s, "neighbour_face", index_or_none(m->halfedges[h ^ 1u].face));
        core_step_text(&s, "note",
                       e->next == h0 ? "next is the first half-edge: the loop closes" : "");
        s.step.geometry = edge;
        s.step.geometry_count = 2;
        s.step.kept = edge;
        s.step.kept_count = 2;
        if (core_step_emit(&s, step, user))
            return CG_OK;
        h = e->next;
    } while (h != h0);
    return CG_OK;
}

cg_status cg_hemesh_one_ring_steps(const cg_hemesh *m, uint32_t v, cg_step_fn step, void *user)
{
    if (!m || !step || v >= m->vertex_count || m->vertex_halfedge[v] >= CG_HEMESH_DELETED)
        return CG_EINVAL;
    uint32_t h0 = m->vertex_halfedge[v], h = h0;
    long k = 0;
    do {
        uint32_t previous = m->halfedges[h].prev, after = cg_hemesh_ccw(m, h);
        uint32_t dest = cg_hemesh_dest(m, h);
        cg_vec2 spoke[2] = {flat(m, v), flat(m, dest)};
        core_step s;
        core_step_begin(&s, "one-ring");
        core_step_integer(&s, "k", k++);
        core_step_integer(&s, "h", h);
        core_step_integer(&s, "neighbour", dest);
        core_step_integer(&s, "face", index_or_none(m->halfedges[h].face));
        core_step_integer(&s, "prev", previous);
        core_step_integer(&s, "twin_of_prev", after);
        core_step_text(&s, "note",
                       after == h0 ? "back at the first half-edge: the ring closes"
                       : m->halfedges[h].face == CG_HEMESH_NONE ? "a boundary half-edge"
                                                                : "");
        s.step.geometry = spoke;
        s.step.geometry_count = 2;
        s.step.kept = spoke;
        s.step.kept_count = 2;
        if (core_step_emit(&s, step, user))
            return CG_OK;
        h = after;
    } while (h != h0);
    return CG_OK;
}
