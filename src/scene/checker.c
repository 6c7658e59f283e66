/* A checker material as geometry for the rasterizer: every face is cut along
 * the cell boundaries of the pattern, and each piece takes the colour of its
 * cell, so the z-buffer and the painter's algorithm show the same cells as
 * the ray tracer, which colours each hit point (src/trace/render.c).
 *
 * A cell is the set of points p with floor(t_i(p)) fixed for each axis i,
 * where t_i(p) = (p - origin) . axis_i / size: the world axes for meshes,
 * spheres and boxes, the plane's own two axes (from the ray tracer's rule)
 * for planes.  Its colour is the second one when the sum of the floors is
 * odd.  Pieces are clipped one slab at a time (Sutherland-Hodgman against
 * the two planes of the slab); a point where an edge meets a cell plane is
 * computed from the edge's two ends in a fixed order, so the faces on both
 * sides of the edge get the same point, and the pieces' corners are merged by
 * position so that the renderer's smooth normals still join across them. */
#include "checker.h"
#include "../core/array.h"
#include "../core/vector_order.h"
#include "../core/sort.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

/* The most pieces one object may be cut into. */
#define CHECKER_MAX_PIECES ((size_t)1 << 22)

typedef struct polygon_list {
    cg_vec3 *points; /* the corners of every polygon, one after another */
    size_t *starts;  /* polygon i is points[starts[i] .. starts[i + 1]) */
    size_t count, point_count, point_capacity, start_capacity;
} polygon_list;

static int list_reserve(polygon_list *l, size_t points)
{
    return core_array_reserve((void **)&l->points, &l->point_capacity, l->point_count + points,
                              sizeof *l->points)
               == CG_OK
           && core_array_reserve((void **)&l->starts, &l->start_capacity, l->count + 2,
                                 sizeof *l->starts)
                  == CG_OK;
}

/* Appends the polygon p[0..n) when it has at least three corners. */
static int list_add(polygon_list *l, const cg_vec3 *p, size_t n)
{
    if (n < 3)
        return 1;
    if (!list_reserve(l, n))
        return 0;
    if (l->count == 0)
        l->starts[0] = 0;
    memcpy(l->points + l->point_count, p, n * sizeof *p);
    l->point_count += n;
    l->starts[++l->count] = l->point_count;
    return 1;
}

static void list_clear(polygon_list *l)
{
    l->count = 0;
    l->point_count = 0;
}

static void list_free(polygon_list *l)
{
    free(l->points);
    free(l->starts);
}

static double coordinate(const checker_frame *frame, int axis, cg_vec3 p)
{
    return cg_vec3_dot(cg_vec3_sub(p, frame->origin), frame->axis[axis]) / frame->size;
}

/* The point of segment [a, b] at coordinate level (between theirs), from
 * the ends in lexicographic order, so that an edge is cut the same way from
 * either face. */
static cg_vec3 cut(const checker_frame *frame, int axis, cg_vec3 a, cg_vec3 b, double level)
{
    if (core_vec3_less(b, a)) {
        cg_vec3 t = a;
        a = b;
        b = t;
    }
    double ta = coordinate(frame, axis, a), tb = coordinate(frame, axis, b);
    double s = (level - ta) / (tb - ta);
    return cg_vec3_add(a, cg_vec3_scale(cg_vec3_sub(b, a), s));
}

/* Sutherland-Hodgman: the part of in[0..n) with sign * (t - level) >= 0,
 * into out (room for 2n points); returns its corner count. */
static size_t clip_half(const checker_frame *frame, int axis, const cg_vec3 *in, size_t n,
                        double level, double sign, cg_vec3 *out)
{
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        cg_vec3 a = in[i], b = in[(i + 1) % n];
        double da = sign * (coordinate(frame, axis, a) - level);
        double db = sign * (coordinate(frame, axis, b) - level);
        if (da >= 0)
            out[m++] = a;
        if ((da >= 0) != (db >= 0) && da != 0 && db != 0)
            out[m++] = cut(frame, axis, a, b, level);
    }
    return m;
}

/* Cuts every polygon of in along the cell planes of one axis into out. */
static cg_status split_axis(const checker_frame *frame, int axis, const polygon_list *in,
                            polygon_list *out, cg_vec3 **scratch, size_t *room)
{
    list_clear(out);
    for (size_t i = 0; i < in->count; i++) {
        const cg_vec3 *p = in->points + in->starts[i];
        size_t n = in->starts[i + 1] - in->starts[i];
        double lo = DBL_MAX, hi = -DBL_MAX;
        for (size_t k = 0; k < n; k++) {
            double t = coordinate(frame, axis, p[k]);
            lo = fmin(lo, t);
            hi = fmax(hi, t);
        }
        double first = floor(lo), last = floor(hi);
        if (!(hi - lo < (double)CHECKER_MAX_PIECES)
            || out->count + (size_t)(last - first) + 1 > CHECKER_MAX_PIECES)
            return CG_ERANGE;
        if (first == last || hi == first + 1) {
            if (!list_add(out, p, n))
                return CG_ENOMEM;
            continue;
        }
        /* A slab at a time.  Each half-plane clip adds at most one corner per
         * crossing edge: 2n after the first, 4n after the second. */
        if (core_array_reserve((void **)scratch, room, 6 * n, sizeof **scratch) != CG_OK)
            return CG_ENOMEM;
        cg_vec3 *low = *scratch, *slab = *scratch + 2 * n;
        for (double k = first; k <= last && k < hi; k++) {
            size_t a = clip_half(frame, axis, p, n, k, 1, low);
            size_t b = clip_half(frame, axis, low, a, k + 1, -1, slab);
            if (!list_add(out, slab, b))
                return CG_ENOMEM;
        }
    }
    return CG_OK;
}

/* The cell parity of a piece, at its centroid. */
static int odd_cell(const checker_frame *frame, const cg_vec3 *p, size_t n)
{
    cg_vec3 c = {0, 0, 0};
    for (size_t k = 0; k < n; k++)
        c = cg_vec3_add(c, p[k]);
    c = cg_vec3_scale(c, 1.0 / (double)n);
    double parity = 0;
    for (int axis = 0; axis < frame->axes; axis++)
        parity += floor(coordinate(frame, axis, c));
    return fmod(fabs(parity), 2) == 1;
}

typedef struct keyed_point {
    cg_vec3 p;
    size_t index;
} keyed_point;

static int compare_points(const void *a, const void *b)
{
    const keyed_point *x = a, *y = b;
    if (core_vec3_less(x->p, y->p))
        return -1;
    if (core_vec3_less(y->p, x->p))
        return 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

/* The pieces as a mesh: corners merged by position, repeated neighbours
 * dropped, faces of fewer than three corners left out. */
static cg_status pieces_mesh(const checker_frame *frame, const polygon_list *pieces, cg_rgbaf even,
                             cg_rgbaf odd, cg_mesh **out)
{
    size_t n = pieces->point_count;
    keyed_point *keys = malloc((n ? n : 1) * sizeof *keys);
    uint32_t *id = malloc((n ? n : 1) * sizeof *id);
    cg_status s = keys && id ? CG_OK : CG_ENOMEM;
    size_t unique = 0;
    if (s == CG_OK && n > UINT32_MAX)
        s = CG_ERANGE;
    if (s == CG_OK) {
        for (size_t i = 0; i < n; i++)
            keys[i] = (keyed_point){pieces->points[i], i};
        core_sort(keys, n, sizeof *keys, compare_points);
        for (size_t i = 0; i < n; i++) {
            if (i > 0 && (core_vec3_less(keys[i - 1].p, keys[i].p)))
                unique++;
            id[keys[i].index] = (uint32_t)unique;
        }
        if (n)
            unique++;
        s = cg_mesh_create(out, unique, pieces->count, n, CG_MESH_FACE_COLORS);
    }
    if (s == CG_OK) {
        cg_mesh *m = *out;
        for (size_t i = 0; i < n; i++)
            m->positions[id[keys[i].index]] = keys[i].p;
        size_t faces = 0, corners = 0;
        for (size_t f = 0; f < pieces->count; f++) {
            size_t begin = pieces->starts[f], end = pieces->starts[f + 1], first = corners;
            for (size_t k = begin; k < end; k++)
                if (corners == first || m->face_indices[corners - 1] != id[k])
                    m->face_indices[corners++] = id[k];
            while (corners - first > 1 && m->face_indices[corners - 1] == m->face_indices[first])
                corners--;
            if (corners - first < 3) {
                corners = first;
                continue;
            }
            m->face_colors[faces] = odd_cell(frame, pieces->points + begin, end - begin) ? odd
                                                                                         : even;
            m->face_offsets[++faces] = (uint32_t)corners;
        }
        m->face_count = faces;
    }
    free(keys);
    free(id);
    return s;
}

/* Appends every polygon of from to all. */
static int list_append(polygon_list *all, const polygon_list *from)
{
    for (size_t i = 0; i < from->count; i++)
        if (!list_add(all, from->points + from->starts[i], from->starts[i + 1] - from->starts[i]))
            return 0;
    return 1;
}

cg_status scene_checker_split(const cg_mesh *part, const checker_frame *frame, cg_rgbaf even,
                              cg_rgbaf odd, cg_mesh **out)
{
    *out = NULL;
    if (!(frame->size > 0) || !isfinite(frame->size) || frame->axes < 1 || frame->axes > 3)
        return CG_EINVAL;
    size_t room = 0;
    cg_vec3 *scratch = NULL;
    polygon_list a = {0}, b = {0}, all = {0};
    cg_status s = CG_OK;
    for (size_t f = 0; f < part->face_count && s == CG_OK; f++) {
        uint32_t begin = part->face_offsets[f], end = part->face_offsets[f + 1];
        list_clear(&a);
        if (!list_reserve(&a, end - begin)) {
            s = CG_ENOMEM;
            break;
        }
        for (uint32_t k = begin; k < end; k++)
            a.points[a.point_count++] = part->positions[part->face_indices[k]];
        a.starts[0] = 0;
        a.starts[a.count = 1] = a.point_count;
        polygon_list *from = &a, *to = &b;
        for (int axis = 0; axis < frame->axes && s == CG_OK; axis++) {
            s = split_axis(frame, axis, from, to, &scratch, &room);
            polygon_list *t = from;
            from = to;
            to = t;
        }
        if (s == CG_OK && all.count + from->count > CHECKER_MAX_PIECES)
            s = CG_ERANGE;
        if (s == CG_OK && !list_append(&all, from))
            s = CG_ENOMEM;
    }
    if (s == CG_OK)
        s = pieces_mesh(frame, &all, even, odd, out);
    free(scratch);
    list_free(&a);
    list_free(&b);
    list_free(&all);
    return s;
}
