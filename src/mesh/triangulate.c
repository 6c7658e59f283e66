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
#include <string.h>

/* Faces up to this size are triangulated without allocating. */
#define TRIANGULATE_STACK 32
/* Faces of more corners find the corners near an ear through a grid. */
#define TRIANGULATE_GRID 64
/* Ear tests, grid cells and corners looked at, per corner of the face and
 * at least, before the rest of the face is cut at nearby convex corners
 * untested: this bounds the time a face that crosses itself all over
 * takes.  Simple faces need far less (a 100,000-corner star with sawtooth
 * spikes 1,540 a corner, rings and outlines of any size a few tens). */
#define TRIANGULATE_WORK_PER_CORNER 1024
#define TRIANGULATE_WORK_MIN (1 << 20)

typedef struct ring {
    double (*p)[2]; /* projected corners */
    uint32_t *prev, *next;
    /* the grid (large faces only): corners by cell, in cell_items from
     * cell_start[cell] to cell_start[cell + 1]; cut corners are marked */
    uint32_t *cell_start, *cell_items;
    unsigned char *cut;
    int use_grid;
    uint64_t work; /* corners that ear tests may still look at */
    uint32_t cells_x, cells_y;
    double x0, y0, scale_x, scale_y;
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
static int project(const cg_vec3 *positions, const uint32_t *indices, uint32_t n, double (*out)[2])
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

static uint32_t cell_x(const ring *g, double x)
{
    double c = (x - g->x0) * g->scale_x;
    return !(c >= 1) ? 0 : c >= g->cells_x - 1 ? g->cells_x - 1 : (uint32_t)c;
}

static uint32_t cell_y(const ring *g, double y)
{
    double c = (y - g->y0) * g->scale_y;
    return !(c >= 1) ? 0 : c >= g->cells_y - 1 ? g->cells_y - 1 : (uint32_t)c;
}

/* Sorts the n corners into a grid of about n / 2 cells of the shape of
 * their bounding box. */
static void grid_build(ring *g, uint32_t n)
{
    double x0 = g->p[0][0], x1 = x0, y0 = g->p[0][1], y1 = y0;
    for (uint32_t k = 1; k < n; k++) {
        x0 = fmin(x0, g->p[k][0]), x1 = fmax(x1, g->p[k][0]);
        y0 = fmin(y0, g->p[k][1]), y1 = fmax(y1, g->p[k][1]);
    }
    double w = x1 - x0, h = y1 - y0, cells = n / 2.0;
    double across = w > 0 && h > 0 ? ceil(sqrt(cells * w / h)) : 1;
    g->cells_x = (uint32_t)fmin(fmax(across, 1), cells);
    g->cells_y = (uint32_t)fmax(floor(cells / g->cells_x), 1);
    g->x0 = x0;
    g->y0 = y0;
    g->scale_x = w > 0 ? g->cells_x / w : 0;
    g->scale_y = h > 0 ? g->cells_y / h : 0;
    uint32_t count = g->cells_x * g->cells_y;
    for (uint32_t c = 0; c <= count; c++)
        g->cell_start[c] = 0;
    for (uint32_t k = 0; k < n; k++)
        g->cell_start[cell_y(g, g->p[k][1]) * g->cells_x + cell_x(g, g->p[k][0]) + 1]++;
    for (uint32_t c = 0; c < count; c++)
        g->cell_start[c + 1] += g->cell_start[c];
    for (uint32_t k = 0; k < n; k++) {
        uint32_t c = cell_y(g, g->p[k][1]) * g->cells_x + cell_x(g, g->p[k][0]);
        g->cell_items[g->cell_start[c]++] = k; /* cell_start[c] ends at c + 1's start */
        g->cut[k] = 0;
    }
    for (uint32_t c = count; c > 0; c--)
        g->cell_start[c] = g->cell_start[c - 1];
    g->cell_start[0] = 0;
}

/* Whether corner s keeps the ear t from being cut: it lies inside or on
 * the ear and is not a repeat of one of its corners.  A repeat is not
 * inside: an edge from it into the ear would end inside or on the ear, or
 * cross an edge of the face (which has no exact triangulation then). */
static int blocks(const double *const t[3], const double s[2])
{
    if (same_point(s, t[0]) || same_point(s, t[1]) || same_point(s, t[2]))
        return 0;
    return orient(t[0], t[1], s) >= 0 && orient(t[1], t[2], s) >= 0 && orient(t[2], t[0], s) >= 0;
}

static int inside_box(const double s[2], const double box[4])
{
    return s[0] >= box[0] && s[0] <= box[2] && s[1] >= box[1] && s[1] <= box[3];
}

static int is_ear(ring *g, uint32_t i)
{
    g->work -= g->work > 0;
    uint32_t a = g->prev[i], c = g->next[i];
    const double *t[3] = {g->p[a], g->p[i], g->p[c]};
    double o = orient(t[0], t[1], t[2]);
    if (o == 0)
        return 1; /* no turn: cutting it changes no area */
    if (!(o > 0))
        return 0;
    const double box[4] = {
        fmin(fmin(t[0][0], t[1][0]), t[2][0]), fmin(fmin(t[0][1], t[1][1]), t[2][1]),
        fmax(fmax(t[0][0], t[1][0]), t[2][0]), fmax(fmax(t[0][1], t[1][1]), t[2][1])};
    if (!g->use_grid) {
        for (uint32_t q = g->next[c]; q != a; q = g->next[q]) {
            g->work -= g->work > 0;
            if (inside_box(g->p[q], box) && blocks(t, g->p[q]))
                return 0;
        }
        return 1;
    }
    uint32_t cx0 = cell_x(g, box[0]), cx1 = cell_x(g, box[2]);
    uint32_t cy0 = cell_y(g, box[1]), cy1 = cell_y(g, box[3]);
    for (uint32_t y = cy0; y <= cy1; y++)
        for (uint32_t x = cx0; x <= cx1; x++) {
            uint32_t cell = y * g->cells_x + x;
            g->work -= g->work > 0;
            for (uint32_t k = g->cell_start[cell]; k < g->cell_start[cell + 1]; k++) {
                uint32_t q = g->cell_items[k];
                g->work -= g->work > 0;
                if (!g->cut[q] && q != a && q != i && q != c && inside_box(g->p[q], box)
                    && blocks(t, g->p[q]))
                    return 0;
            }
        }
    return 1;
}

/* The corner cut when a full round finds no ear, or once the work is
 * used up: the first convex one of up to `look` corners from start, else
 * start. */
static uint32_t forced_corner(ring *g, uint32_t start, uint32_t look)
{
    uint32_t i = start;
    for (uint32_t k = 0; k < look; k++, i = g->next[i]) {
        g->work -= g->work > 0;
        if (orient(g->p[g->prev[i]], g->p[i], g->p[g->next[i]]) > 0)
            return i;
    }
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
    g->use_grid = n > TRIANGULATE_GRID;
    if (g->use_grid)
        grid_build(g, n);
    uint32_t i = 0, remaining = n, tried = 0;
    g->work = (uint64_t)TRIANGULATE_WORK_PER_CORNER * n + TRIANGULATE_WORK_MIN;
    size_t t = 0;
    while (remaining > 3) {
        if (!g->work) {
            i = forced_corner(g, i, 8);
        } else if (!is_ear(g, i)) {
            i = g->next[i];
            if (++tried < remaining)
                continue;
            i = forced_corner(g, i, remaining);
        }
        uint32_t a = g->prev[i], c = g->next[i];
        out[t][0] = base + a;
        out[t][1] = base + i;
        out[t++][2] = base + c;
        g->next[a] = c;
        g->prev[c] = a;
        if (g->use_grid)
            g->cut[i] = 1;
        remaining--;
        tried = 0;
        /* Going on past the next corner keeps the ears small: cutting
         * corner after corner from one side would fan out from one corner
         * over the whole face. */
        i = remaining > 3 ? g->next[c] : c;
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
        || fan_is_exact((const double(*)[2])g->p, n))
        fan(n, base, out);
    else
        clip_ears(g, n, base, out);
}

static void ring_free(ring *g)
{
    free(g->p);
    free(g->prev);
    free(g->next);
    free(g->cell_start);
    free(g->cell_items);
    free(g->cut);
}

/* Room for faces of n corners (n > TRIANGULATE_STACK). */
static cg_status ring_alloc(ring *g, size_t n)
{
    memset(g, 0, sizeof *g);
    g->p = malloc(n * sizeof *g->p);
    g->prev = malloc(n * sizeof *g->prev);
    g->next = malloc(n * sizeof *g->next);
    int grid = n > TRIANGULATE_GRID;
    if (grid) {
        g->cell_start = malloc((n + 1) * sizeof *g->cell_start);
        g->cell_items = malloc(n * sizeof *g->cell_items);
        g->cut = malloc(n);
    }
    if (!g->p || !g->prev || !g->next || (grid && (!g->cell_start || !g->cell_items || !g->cut))) {
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
    ring g = {.p = p, .prev = prev, .next = next};
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
    cg_status status = cg_mesh_validate_topology(mesh, NULL);
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
