/* Splitting polygonal faces into triangles: the one triangulation every
 * renderer, the ray tracer and the writers share.
 *
 * A face is projected onto the coordinate plane most nearly parallel to
 * its best-fit plane (the largest component of Newell's normal), with the
 * axes ordered so that the face stays counter-clockwise.  The projection
 * copies coordinates without arithmetic, so integer and other exactly
 * representable inputs keep exact orientation tests.
 *
 * When the fan from the first corner covers the face exactly, that fan is
 * the answer: every convex face keeps the triangles it always had.  The
 * fan is exact when none of its triangles is clockwise or folded back
 * through the first corner.  Otherwise the face is cut by ear clipping: a corner is an
 * ear when it is convex and no other corner lies inside or on its
 * triangle; a corner where the boundary does not turn (collinear or
 * repeated vertices, spikes) is cut at once as a triangle of no area, which
 * changes the remaining polygon by no area either.  Corners that repeat a
 * corner of the candidate ear (the two ends of a bridge into a hole, a
 * face that touches itself) are not inside it.  When a full round finds no
 * ear
 * (self-intersecting faces, or rounding on nearly degenerate ones), the
 * first convex corner is cut anyway, so a face of n corners always gives
 * n - 2 triangles. */
#include "cg/mesh.h"

#include <math.h>
#include <stdlib.h>

/* Faces up to this size are triangulated without allocating. */
#define TRIANGULATE_STACK 32

typedef struct ring {
    double (*p)[2];   /* projected corners */
    uint32_t *prev, *next;
} ring;

static double orient(const double a[2], const double b[2], const double c[2])
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static int same_point(const double a[2], const double b[2])
{
    return a[0] == b[0] && a[1] == b[1];
}

/* Projects the n corners of a face; 0 when the face has no usable normal
 * (all corners on a line, or a coordinate that is not finite). */
static int project(const cg_vec3 *positions, const uint32_t *indices, uint32_t n,
                   double (*out)[2])
{
    double nx = 0, ny = 0, nz = 0;
    for (uint32_t k = 0; k < n; k++) {
        cg_vec3 a = positions[indices[k]], b = positions[indices[k + 1 < n ? k + 1 : 0]];
        nx += (a.y - b.y) * (a.z + b.z);
        ny += (a.z - b.z) * (a.x + b.x);
        nz += (a.x - b.x) * (a.y + b.y);
    }
    double ax = fabs(nx), ay = fabs(ny), az = fabs(nz);
    if (!isfinite(ax + ay + az) || !(ax + ay + az > 0))
        return 0;
    /* Dropping x keeps (y, z), y keeps (z, x), z keeps (x, y): each pair is
     * counter-clockwise about the positive dropped axis. */
    int axis = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    double sign = axis == 0 ? nx : axis == 1 ? ny : nz;
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    if (sign < 0) {
        int swap = u;
        u = v;
        v = swap;
    }
    for (uint32_t k = 0; k < n; k++) {
        cg_vec3 q = positions[indices[k]];
        const double c[3] = {q.x, q.y, q.z};
        out[k][0] = c[u];
        out[k][1] = c[v];
    }
    return 1;
}

/* Whether the fan from corner 0 covers the projected polygon exactly: no
 * fan triangle is clockwise or folds back through corner 0, so the
 * boundary turns monotonically around corner 0 and (a face that does not
 * cross itself cannot wind around a corner on its boundary twice) each
 * point of the face lies in exactly one fan triangle. */
static int fan_is_exact(const double (*p)[2], uint32_t n)
{
    for (uint32_t k = 1; k + 1 < n; k++) {
        double o = orient(p[0], p[k], p[k + 1]);
        if (o > 0)
            continue;
        double dot = (p[k][0] - p[0][0]) * (p[k + 1][0] - p[0][0])
                     + (p[k][1] - p[0][1]) * (p[k + 1][1] - p[0][1]);
        if (o < 0 || dot < 0 || o != o)
            return 0;
    }
    return 1;
}

static int is_ear(const ring *g, uint32_t i)
{
    uint32_t a = g->prev[i], c = g->next[i];
    const double *t[3] = {g->p[a], g->p[i], g->p[c]};
    double o = orient(t[0], t[1], t[2]);
    if (o == 0)
        return 1; /* no turn: cutting it changes no area */
    if (!(o > 0))
        return 0;
    double x0 = fmin(fmin(t[0][0], t[1][0]), t[2][0]), x1 = fmax(fmax(t[0][0], t[1][0]), t[2][0]);
    double y0 = fmin(fmin(t[0][1], t[1][1]), t[2][1]), y1 = fmax(fmax(t[0][1], t[1][1]), t[2][1]);
    for (uint32_t q = g->next[c]; q != a; q = g->next[q]) {
        const double *s = g->p[q];
        if (s[0] < x0 || s[0] > x1 || s[1] < y0 || s[1] > y1)
            continue;
        /* A repeat of a corner of the ear is not inside it.  An edge from
         * the repeat into the ear would end inside or on it, or cross an
         * edge of the face: the other corners' tests see the first, and a
         * face that crosses itself has no exact triangulation anyway. */
        if (same_point(s, t[0]) || same_point(s, t[1]) || same_point(s, t[2]))
            continue;
        if (orient(t[0], t[1], s) >= 0 && orient(t[1], t[2], s) >= 0 && orient(t[2], t[0], s) >= 0)
            return 0;
    }
    return 1;
}

/* The corner cut when a full round finds no ear: the first convex one from
 * start, else start. */
static uint32_t forced_corner(const ring *g, uint32_t start)
{
    uint32_t i = start;
    do {
        if (orient(g->p[g->prev[i]], g->p[i], g->p[g->next[i]]) > 0)
            return i;
        i = g->next[i];
    } while (i != start);
    return start;
}

/* Ear clipping of the n projected corners in g (n >= 4); triangles of
 * corner numbers base + k. */
static void clip_ears(ring *g, uint32_t n, uint32_t base, uint32_t (*out)[3])
{
    for (uint32_t k = 0; k < n; k++) {
        g->prev[k] = k ? k - 1 : n - 1;
        g->next[k] = k + 1 < n ? k + 1 : 0;
    }
    uint32_t i = 0, remaining = n, tried = 0;
    size_t t = 0;
    while (remaining > 3) {
        if (!is_ear(g, i)) {
            i = g->next[i];
            if (++tried < remaining)
                continue;
            i = forced_corner(g, i);
        }
        uint32_t a = g->prev[i], c = g->next[i];
        out[t][0] = base + a;
        out[t][1] = base + i;
        out[t++][2] = base + c;
        g->next[a] = c;
        g->prev[c] = a;
        remaining--;
        tried = 0;
        i = c;
    }
    out[t][0] = base + g->prev[i];
    out[t][1] = base + i;
    out[t][2] = base + g->next[i];
}

static void fan(uint32_t n, uint32_t base, uint32_t (*out)[3])
{
    for (uint32_t k = 1; k + 1 < n; k++) {
        out[k - 1][0] = base;
        out[k - 1][1] = base + k;
        out[k - 1][2] = base + k + 1;
    }
}

/* Triangulates face f with g's arrays (room for its corners). */
static void triangulate(const cg_mesh *mesh, size_t f, ring *g, uint32_t (*out)[3])
{
    uint32_t base = mesh->face_offsets[f], n = mesh->face_offsets[f + 1] - base;
    if (n < 4 || !project(mesh->positions, mesh->face_indices + base, n, g->p)
        || fan_is_exact((const double (*)[2])g->p, n))
        fan(n, base, out);
    else
        clip_ears(g, n, base, out);
}

static void ring_free(ring *g)
{
    free(g->p);
    free(g->prev);
    free(g->next);
}

static cg_status ring_alloc(ring *g, size_t n)
{
    g->p = malloc(n * sizeof *g->p);
    g->prev = malloc(n * sizeof *g->prev);
    g->next = malloc(n * sizeof *g->next);
    if (!g->p || !g->prev || !g->next) {
        ring_free(g);
        return CG_ENOMEM;
    }
    return CG_OK;
}

cg_status cg_mesh_triangulate_face(const cg_mesh *mesh, size_t f, uint32_t (*triangles)[3])
{
    if (!mesh || !triangles || f >= mesh->face_count)
        return CG_EINVAL;
    uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
    if (end < begin || end - begin < 3)
        return CG_EINVAL;
    for (uint32_t k = begin; k < end; k++)
        if (mesh->face_indices[k] >= mesh->vertex_count)
            return CG_EINVAL;
    uint32_t n = end - begin;
    double p[TRIANGULATE_STACK][2];
    uint32_t prev[TRIANGULATE_STACK], next[TRIANGULATE_STACK];
    ring g = {p, prev, next};
    if (n > TRIANGULATE_STACK && ring_alloc(&g, n) != CG_OK)
        return CG_ENOMEM;
    triangulate(mesh, f, &g, triangles);
    if (n > TRIANGULATE_STACK)
        ring_free(&g);
    return CG_OK;
}

cg_status cg_mesh_triangulate(const cg_mesh *mesh, uint32_t (*triangles)[3])
{
    if (!mesh || !triangles)
        return CG_EINVAL;
    cg_status status = cg_mesh_validate(mesh, NULL);
    if (status != CG_OK)
        return status;
    uint32_t largest = 3;
    for (size_t f = 0; f < mesh->face_count; f++)
        if (cg_mesh_face_size(mesh, f) > largest)
            largest = cg_mesh_face_size(mesh, f);
    ring g;
    if (ring_alloc(&g, largest) != CG_OK)
        return CG_ENOMEM;
    size_t t = 0;
    for (size_t f = 0; f < mesh->face_count; f++) {
        triangulate(mesh, f, &g, triangles + t);
        t += cg_mesh_face_size(mesh, f) - 2;
    }
    ring_free(&g);
    return CG_OK;
}
