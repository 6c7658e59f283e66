/* Clipping a triangle mesh against an axis-aligned box (11.3): each triangle
 * goes through Sutherland-Hodgman against the six faces of the box with all
 * its vertex attributes (faces of more corners are first split by
 * cg_mesh_triangulate); the clipped convex polygon is fanned back into
 * triangles.  A new vertex on an edge is computed from the edge's two
 * endpoints in a fixed order (lexicographic by position), so the two
 * triangles sharing an edge create bit-identical vertices, which are then
 * welded: the cut stays closed. */
#include "cg/clip.h"
#include "../core/array.h"

#include <stdlib.h>
#include <string.h>

typedef struct cvert {
    cg_vec3 p, n;
    cg_vec2 t;
    cg_rgbaf c;
    int64_t source; /* original vertex index, or -1 for a new vertex */
} cvert;

static int pos_less(cg_vec3 a, cg_vec3 b)
{
    if (a.x != b.x)
        return a.x < b.x;
    if (a.y != b.y)
        return a.y < b.y;
    return a.z < b.z;
}

static float lerpf(float a, float b, double t)
{
    return (float)(a + (b - a) * t);
}

/* Vertex where the edge a-b meets the plane coordinate `axis` == value. */
static cvert cut(const cvert *a, const cvert *b, int axis, double value)
{
    if (pos_less(b->p, a->p)) {
        const cvert *t = a;
        a = b;
        b = t;
    }
    double pa = axis == 0 ? a->p.x : axis == 1 ? a->p.y : a->p.z;
    double pb = axis == 0 ? b->p.x : axis == 1 ? b->p.y : b->p.z;
    double t = (value - pa) / (pb - pa);
    cvert v;
    v.p = cg_vec3_add(a->p, cg_vec3_scale(cg_vec3_sub(b->p, a->p), t));
    if (axis == 0)
        v.p.x = value;
    else if (axis == 1)
        v.p.y = value;
    else
        v.p.z = value;
    v.n = cg_vec3_normalize(cg_vec3_add(a->n, cg_vec3_scale(cg_vec3_sub(b->n, a->n), t)));
    v.t = cg_vec2_add(a->t, cg_vec2_scale(cg_vec2_sub(b->t, a->t), t));
    v.c.r = lerpf(a->c.r, b->c.r, t);
    v.c.g = lerpf(a->c.g, b->c.g, t);
    v.c.b = lerpf(a->c.b, b->c.b, t);
    v.c.a = lerpf(a->c.a, b->c.a, t);
    v.source = -1;
    return v;
}

/* Keeps the part of poly (n vertices, room for n + 1) on the inner side of
 * one box face; returns the new count. */
static int clip_face(const cvert *in, int n, cvert *out, int axis, double value, int keep_below)
{
    int m = 0;
    if (n == 0)
        return 0;
    const cvert *s = &in[n - 1];
    double sv = axis == 0 ? s->p.x : axis == 1 ? s->p.y : s->p.z;
    double ds = keep_below ? value - sv : sv - value;
    for (int i = 0; i < n; i++) {
        const cvert *e = &in[i];
        double ev = axis == 0 ? e->p.x : axis == 1 ? e->p.y : e->p.z;
        double de = keep_below ? value - ev : ev - value;
        if (de >= 0) {
            if (ds < 0 && de > 0)
                out[m++] = cut(s, e, axis, value);
            out[m++] = *e;
        } else if (ds > 0) {
            out[m++] = cut(s, e, axis, value);
        }
        s = e;
        ds = de;
    }
    return m;
}

typedef struct weld {
    int64_t *slot; /* output index + 1, 0 empty */
    size_t cap;
} weld;

static uint64_t hash_pos(cg_vec3 p)
{
    uint64_t h = 1469598103934665603ULL, w[3];
    memcpy(&w[0], &p.x, 8);
    memcpy(&w[1], &p.y, 8);
    memcpy(&w[2], &p.z, 8);
    for (int i = 0; i < 3; i++) {
        h ^= w[i] + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        h *= 1099511628211ULL;
    }
    return h;
}

typedef struct builder {
    cvert *verts;
    size_t vertex_count, vertex_capacity;
    uint32_t *tris; /* 3 per triangle */
    size_t triangle_count, triangle_capacity;
    size_t *tri_face;
    int64_t *orig_map; /* original index -> output index + 1 */
    weld w;
} builder;

static int add_vertex(builder *b, const cvert *v, uint32_t *index)
{
    if (v->source >= 0 && b->orig_map[v->source]) {
        *index = (uint32_t)(b->orig_map[v->source] - 1);
        return 1;
    }
    uint64_t h = 0;
    size_t slot = 0;
    if (v->source < 0) {
        h = hash_pos(v->p);
        slot = (size_t)(h & (b->w.cap - 1));
        while (b->w.slot[slot]) {
            const cvert *o = &b->verts[b->w.slot[slot] - 1];
            if (o->p.x == v->p.x && o->p.y == v->p.y && o->p.z == v->p.z) {
                *index = (uint32_t)(b->w.slot[slot] - 1);
                return 1;
            }
            slot = (slot + 1) & (b->w.cap - 1);
        }
    }
    if (b->vertex_count >= CG_MESH_MAX_VERTICES)
        return 0;
    if (core_array_reserve((void **)&b->verts, &b->vertex_capacity, b->vertex_count + 1,
                           sizeof *b->verts)
        != CG_OK)
        return 0;
    b->verts[b->vertex_count] = *v;
    *index = (uint32_t)b->vertex_count;
    b->vertex_count++;
    if (v->source >= 0) {
        b->orig_map[v->source] = (int64_t)b->vertex_count;
    } else {
        b->w.slot[slot] = (int64_t)b->vertex_count;
        if (b->vertex_count * 2 > b->w.cap) { /* grow and rehash the new vertices */
            size_t cap = b->w.cap * 2;
            int64_t *ns = calloc(cap, sizeof *ns);
            if (!ns)
                return 0;
            for (size_t i = 0; i < b->w.cap; i++) {
                if (!b->w.slot[i])
                    continue;
                size_t s = (size_t)(hash_pos(b->verts[b->w.slot[i] - 1].p) & (cap - 1));
                while (ns[s])
                    s = (s + 1) & (cap - 1);
                ns[s] = b->w.slot[i];
            }
            free(b->w.slot);
            b->w.slot = ns;
            b->w.cap = cap;
        }
    }
    return 1;
}

static int add_triangle(builder *b, uint32_t i0, uint32_t i1, uint32_t i2, size_t face)
{
    if (b->triangle_count == b->triangle_capacity) {
        /* (the corners, three a triangle, and the faces grow together) */
        size_t corners_capacity = b->triangle_capacity, faces_capacity = b->triangle_capacity;
        if (core_array_reserve((void **)&b->tris, &corners_capacity, b->triangle_count + 1,
                               3 * sizeof *b->tris)
                != CG_OK
            || core_array_reserve((void **)&b->tri_face, &faces_capacity, b->triangle_count + 1,
                                  sizeof *b->tri_face)
                   != CG_OK)
            return 0;
        b->triangle_capacity = corners_capacity;
    }
    b->tris[3 * b->triangle_count] = i0;
    b->tris[3 * b->triangle_count + 1] = i1;
    b->tris[3 * b->triangle_count + 2] = i2;
    b->tri_face[b->triangle_count] = face;
    b->triangle_count++;
    return 1;
}

cg_status cg_clip_mesh_box(const cg_mesh *mesh, cg_box3 box, cg_mesh **out)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if (!mesh || !isfinite(box.lo.x) || !isfinite(box.lo.y) || !isfinite(box.lo.z)
        || !isfinite(box.hi.x) || !isfinite(box.hi.y) || !isfinite(box.hi.z) || box.lo.x > box.hi.x
        || box.lo.y > box.hi.y || box.lo.z > box.hi.z)
        return CG_EINVAL;
    cg_status st = cg_mesh_validate_topology(mesh, NULL);
    if (st != CG_OK)
        return st;
    builder b = {0};
    st = CG_ENOMEM;
    b.orig_map = calloc(mesh->vertex_count ? mesh->vertex_count : 1, sizeof *b.orig_map);
    b.w.cap = 1024;
    b.w.slot = calloc(b.w.cap, sizeof *b.w.slot);
    /* Faces are split by the mesh module's triangulation (concave faces
     * included), as the renderers split them. */
    size_t triangle_count = cg_mesh_triangle_count(mesh);
    uint32_t(*corners)[3] = malloc((triangle_count ? triangle_count : 1) * sizeof *corners);
    if (!b.orig_map || !b.w.slot || !corners || cg_mesh_triangulate(mesh, corners) != CG_OK)
        goto done;
    const double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
    size_t next_triangle = 0;
    for (size_t f = 0; f < mesh->face_count; f++) {
        uint32_t count = cg_mesh_face_size(mesh, f);
        for (uint32_t k = 1; k + 1 < count; k++) {
            const uint32_t *corner = corners[next_triangle++];
            uint32_t idx[3] = {mesh->face_indices[corner[0]], mesh->face_indices[corner[1]],
                               mesh->face_indices[corner[2]]};
            cvert a[10], c[10];
            int n = 3, bad = 0;
            for (int i = 0; i < 3; i++) {
                uint32_t v = idx[i];
                a[i].p = mesh->positions[v];
                if (!isfinite(a[i].p.x) || !isfinite(a[i].p.y) || !isfinite(a[i].p.z))
                    bad = 1;
                a[i].n = mesh->normals ? mesh->normals[v] : cg_vec3_make(0, 0, 0);
                a[i].t = mesh->texcoords ? mesh->texcoords[v] : cg_vec2_make(0, 0);
                a[i].c = mesh->colors ? mesh->colors[v] : (cg_rgbaf){0, 0, 0, 0};
                a[i].source = v;
            }
            if (bad)
                continue; /* a triangle with a non-finite corner is dropped */
            for (int axis = 0; axis < 3 && n; axis++) {
                n = clip_face(a, n, c, axis, lo[axis], 0);
                n = clip_face(c, n, a, axis, hi[axis], 1);
            }
            if (n < 3)
                continue;
            uint32_t vi[10];
            for (int i = 0; i < n; i++)
                if (!add_vertex(&b, &a[i], &vi[i]))
                    goto done;
            for (int i = 1; i + 1 < n; i++) {
                if (vi[0] == vi[i] || vi[i] == vi[i + 1] || vi[0] == vi[i + 1])
                    continue;
                if (!add_triangle(&b, vi[0], vi[i], vi[i + 1], f))
                    goto done;
            }
        }
    }
    {
        unsigned flags = (mesh->normals ? CG_MESH_NORMALS : 0)
                         | (mesh->texcoords ? CG_MESH_TEXCOORDS : 0)
                         | (mesh->colors ? CG_MESH_COLORS : 0)
                         | (mesh->face_colors ? CG_MESH_FACE_COLORS : 0);
        cg_mesh *m = NULL;
        st = cg_mesh_create(&m, b.vertex_count, b.triangle_count, b.triangle_count * 3, flags);
        if (st != CG_OK)
            goto done;
        for (size_t i = 0; i < b.vertex_count; i++) {
            m->positions[i] = b.verts[i].p;
            if (m->normals)
                m->normals[i] = b.verts[i].n;
            if (m->texcoords)
                m->texcoords[i] = b.verts[i].t;
            if (m->colors)
                m->colors[i] = b.verts[i].c;
        }
        for (size_t t = 0; t < b.triangle_count; t++) {
            m->face_offsets[t + 1] = (uint32_t)(3 * (t + 1));
            memcpy(&m->face_indices[3 * t], &b.tris[3 * t], 3 * sizeof(uint32_t));
            if (m->face_colors)
                m->face_colors[t] = mesh->face_colors[b.tri_face[t]];
        }
        *out = m;
        st = CG_OK;
    }
done:
    free(corners);
    free(b.verts);
    free(b.tris);
    free(b.tri_face);
    free(b.orig_map);
    free(b.w.slot);
    return st;
}
