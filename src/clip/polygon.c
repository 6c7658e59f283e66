/* Sutherland-Hodgman polygon clipping (11.2.1, Fig. 11.5) in 2D against a
 * convex window and in 3D against planes; frustum planes and culling. */
#include "cg/clip.h"
#include "internal.h"
#include "../core/array.h"

#include <stdlib.h>
#include <string.h>

/* The points of a polygon as dim doubles each (cg_vec2 or cg_vec3). */
typedef struct point_list {
    double *values;
    size_t count, capacity; /* in points */
} point_list;

static int list_push(point_list *l, const double *p, int dim)
{
    if (core_array_reserve((void **)&l->values, &l->capacity, l->count + 1,
                           (size_t)dim * sizeof *l->values)
        != CG_OK)
        return 0;
    memcpy(l->values + l->count++ * (size_t)dim, p, (size_t)dim * sizeof *p);
    return 1;
}

/* The crossing of segment s-e with the plane, from the signed distances of
 * its ends; only called when they are on different sides, so the
 * denominator is not 0.  Computed from the endpoint that is inside so that
 * it does not matter in which direction the edge is walked. */
static int list_push_crossing(point_list *l, const double *s, double ds, const double *e, double de,
                              int dim)
{
    double t = ds / (ds - de), p[3];
    for (int i = 0; i < dim; i++)
        p[i] = s[i] + (e[i] - s[i]) * t;
    return list_push(l, p, dim);
}

/* One stage of Sutherland-Hodgman (Fig. 11.5): every edge s -> e of in, with
 * the signed distances dist (>= 0 inside), adds to res: in -> in: e;
 * in -> out: the crossing; out -> out: nothing; out -> in: the crossing,
 * then e.  A point on the plane is inside and adds no crossing. */
static int clip_stage(const point_list *in, const double *dist, int dim, point_list *res)
{
    const double *s = in->values + (in->count - 1) * (size_t)dim;
    double ds = dist[in->count - 1];
    for (size_t i = 0; i < in->count; i++) {
        const double *e = in->values + i * (size_t)dim;
        double de = dist[i];
        if (de >= 0) {
            if (ds < 0 && de > 0 && !list_push_crossing(res, e, de, s, ds, dim))
                return 0;
            if (!list_push(res, e, dim))
                return 0;
        } else if (ds > 0) {
            if (!list_push_crossing(res, s, ds, e, de, dim))
                return 0;
        }
        s = e;
        ds = de;
    }
    return 1;
}

/* Fills dist[0..count) with the signed distances of points (dim doubles
 * each) to plane k of context; 0 when plane k clips nothing (skipped). */
typedef int (*plane_distances)(const void *context, size_t k, const double *points, size_t count,
                               double *dist);

/* The subject clipped by planes 0..plane_count of context in turn, each
 * stage's output the next one's input; the result in *out (NULL when empty). */
static cg_status clip_by_planes(const double *subject, size_t n, int dim, size_t plane_count,
                                plane_distances distances, const void *context, double **out,
                                size_t *out_count)
{
    point_list in = {0}, res = {0};
    double *dist = NULL;
    size_t dist_capacity = 0;
    for (size_t i = 0; i < n; i++)
        if (!list_push(&res, subject + i * (size_t)dim, dim))
            goto nomem;
    for (size_t k = 0; k < plane_count && res.count; k++) {
        if (core_array_reserve((void **)&dist, &dist_capacity, res.count, sizeof *dist) != CG_OK)
            goto nomem;
        if (!distances(context, k, res.values, res.count, dist))
            continue;
        point_list t = in;
        in = res;
        res = t;
        res.count = 0;
        if (!clip_stage(&in, dist, dim, &res))
            goto nomem;
    }
    free(in.values);
    free(dist);
    if (res.count == 0) {
        free(res.values);
        return CG_OK;
    }
    *out = res.values;
    *out_count = res.count;
    return CG_OK;
nomem:
    free(in.values);
    free(res.values);
    free(dist);
    return CG_ENOMEM;
}

/* The convex window's edges as planes: distance orient * (edge x (p - a)),
 * positive inside; an edge of length 0 clips nothing. */
typedef struct window_planes {
    const cg_vec2 *window;
    size_t m;
    double orient;
} window_planes;

static int window_distances(const void *context, size_t k, const double *points, size_t count,
                            double *dist)
{
    const window_planes *w = context;
    cg_vec2 a = w->window[k], b = w->window[(k + 1) % w->m];
    cg_vec2 edge = cg_vec2_sub(b, a);
    if (edge.x == 0 && edge.y == 0)
        return 0;
    for (size_t i = 0; i < count; i++) {
        cg_vec2 p = {points[2 * i], points[2 * i + 1]};
        dist[i] = w->orient * cg_vec2_cross(edge, cg_vec2_sub(p, a));
    }
    return 1;
}

cg_status cg_clip_sutherland_hodgman(const cg_vec2 *subject, size_t n, const cg_vec2 *window,
                                     size_t m, cg_vec2 **out, size_t *out_count)
{
    if (!out || !out_count)
        return CG_EINVAL;
    *out = NULL;
    *out_count = 0;
    if ((!subject && n) || !window || m < 3)
        return CG_EINVAL;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(subject[i].x) || !isfinite(subject[i].y))
            return CG_EINVAL;
    for (size_t i = 0; i < m; i++)
        if (!isfinite(window[i].x) || !isfinite(window[i].y))
            return CG_EINVAL;
    double area = clip_twice_area(window, m);
    if (!(area != 0) || !isfinite(area))
        return CG_EINVAL;
    double orient = area > 0 ? 1.0 : -1.0;
    /* convexity: every turn has the orientation's sign (or is straight) */
    for (size_t i = 0; i < m; i++) {
        cg_vec2 a = window[i], b = window[(i + 1) % m], c = window[(i + 2) % m];
        if (orient * cg_vec2_cross(cg_vec2_sub(b, a), cg_vec2_sub(c, b)) < 0)
            return CG_EINVAL;
    }
    if (n == 0)
        return CG_OK;
    window_planes planes = {window, m, orient};
    double *values = NULL;
    cg_status st = clip_by_planes((const double *)subject, n, 2, m, window_distances, &planes,
                                  &values, out_count);
    *out = (cg_vec2 *)values;
    return st;
}

/* Planes as given: distance N.p + offset. */
static int plane_distances_3d(const void *context, size_t k, const double *points, size_t count,
                              double *dist)
{
    const cg_plane *plane = (const cg_plane *)context + k;
    for (size_t i = 0; i < count; i++) {
        cg_vec3 p = {points[3 * i], points[3 * i + 1], points[3 * i + 2]};
        dist[i] = cg_vec3_dot(plane->normal, p) + plane->offset;
    }
    return 1;
}

cg_status cg_clip_polygon_planes(const cg_vec3 *polygon, size_t n, const cg_plane *planes,
                                 size_t plane_count, cg_vec3 **out, size_t *out_count)
{
    if (!out || !out_count)
        return CG_EINVAL;
    *out = NULL;
    *out_count = 0;
    if ((!polygon && n) || (!planes && plane_count))
        return CG_EINVAL;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(polygon[i].x) || !isfinite(polygon[i].y) || !isfinite(polygon[i].z))
            return CG_EINVAL;
    for (size_t k = 0; k < plane_count; k++)
        if (!isfinite(planes[k].normal.x) || !isfinite(planes[k].normal.y)
            || !isfinite(planes[k].normal.z) || !isfinite(planes[k].offset))
            return CG_EINVAL;
    if (n == 0)
        return CG_OK;
    double *values = NULL;
    cg_status st = clip_by_planes((const double *)polygon, n, 3, plane_count, plane_distances_3d,
                                  planes, &values, out_count);
    *out = (cg_vec3 *)values;
    return st;
}

void cg_frustum_planes(cg_mat4 m, cg_plane planes[6])
{
    /* Gribb and Hartmann: the clip-space conditions -w <= x, y, z <= w read
     * as row3 +- row_i applied to the world point. */
    for (int i = 0; i < 3; i++) {
        for (int s = 0; s < 2; s++) {
            double sign = s ? -1.0 : 1.0;
            cg_plane *p = &planes[2 * i + s];
            p->normal = cg_vec3_make(m.m[3][0] + sign * m.m[i][0], m.m[3][1] + sign * m.m[i][1],
                                     m.m[3][2] + sign * m.m[i][2]);
            p->offset = m.m[3][3] + sign * m.m[i][3];
        }
    }
}

cg_cull cg_frustum_cull_box(const cg_plane planes[6], cg_box3 box)
{
    cg_cull result = CG_CULL_INSIDE;
    for (int i = 0; i < 6; i++) {
        cg_vec3 n = planes[i].normal;
        cg_vec3 far = cg_vec3_make(n.x >= 0 ? box.hi.x : box.lo.x, n.y >= 0 ? box.hi.y : box.lo.y,
                                   n.z >= 0 ? box.hi.z : box.lo.z);
        cg_vec3 near = cg_vec3_make(n.x >= 0 ? box.lo.x : box.hi.x, n.y >= 0 ? box.lo.y : box.hi.y,
                                    n.z >= 0 ? box.lo.z : box.hi.z);
        if (cg_vec3_dot(n, far) + planes[i].offset < 0)
            return CG_CULL_OUTSIDE;
        if (cg_vec3_dot(n, near) + planes[i].offset < 0)
            result = CG_CULL_INTERSECTS;
    }
    return result;
}
