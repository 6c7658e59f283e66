/* Sutherland-Hodgman polygon clipping (11.2.1, Fig. 11.5) in 2D against a
 * convex window and in 3D against planes; frustum planes and culling. */
#include "cg/clip.h"
#include "../core/array.h"

#include <stdlib.h>
#include <string.h>

typedef struct vec2_list {
    cg_vec2 *points;
    size_t count, capacity;
} vec2_list;

static int list_push(vec2_list *l, cg_vec2 p)
{
    if (core_array_reserve((void **)&l->points, &l->capacity, l->count + 1, sizeof *l->points)
        != CG_OK)
        return 0;
    l->points[l->count++] = p;
    return 1;
}

static double signed_area2(const cg_vec2 *p, size_t n)
{
    double s = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++)
        s += cg_vec2_cross(p[j], p[i]);
    return s;
}

/* Intersection of segment s-e with the infinite line through a-b; only
 * called when s and e are on different sides, so the denominator is not 0.
 * Computed from the endpoint that is inside so that it does not matter in
 * which direction the edge is walked. */
static cg_vec2 line_cross(cg_vec2 s, double ds, cg_vec2 e, double de)
{
    double t = ds / (ds - de);
    return cg_vec2_add(s, cg_vec2_scale(cg_vec2_sub(e, s), t));
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
    double area = signed_area2(window, m);
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
    vec2_list in = {0}, res = {0};
    for (size_t i = 0; i < n; i++)
        if (!list_push(&res, subject[i]))
            goto nomem;
    for (size_t k = 0; k < m && res.count; k++) {
        cg_vec2 a = window[k], b = window[(k + 1) % m];
        cg_vec2 edge = cg_vec2_sub(b, a);
        if (edge.x == 0 && edge.y == 0)
            continue;
        vec2_list t = in;
        in = res;
        res = t;
        res.count = 0;
        cg_vec2 s = in.points[in.count - 1];
        double ds = orient * cg_vec2_cross(edge, cg_vec2_sub(s, a));
        for (size_t i = 0; i < in.count; i++) {
            cg_vec2 e = in.points[i];
            double de = orient * cg_vec2_cross(edge, cg_vec2_sub(e, a));
            if (de >= 0) {
                if (ds < 0 && de > 0 && !list_push(&res, line_cross(e, de, s, ds)))
                    goto nomem;
                if (!list_push(&res, e))
                    goto nomem;
            } else if (ds >= 0) {
                if (ds > 0 && !list_push(&res, line_cross(s, ds, e, de)))
                    goto nomem;
            }
            s = e;
            ds = de;
        }
    }
    free(in.points);
    if (res.count == 0) {
        free(res.points);
        return CG_OK;
    }
    *out = res.points;
    *out_count = res.count;
    return CG_OK;
nomem:
    free(in.points);
    free(res.points);
    return CG_ENOMEM;
}

typedef struct vec3_list {
    cg_vec3 *points;
    size_t count, capacity;
} vec3_list;

static int list3_push(vec3_list *l, cg_vec3 p)
{
    if (core_array_reserve((void **)&l->points, &l->capacity, l->count + 1, sizeof *l->points)
        != CG_OK)
        return 0;
    l->points[l->count++] = p;
    return 1;
}

static cg_vec3 plane_cross(cg_vec3 s, double ds, cg_vec3 e, double de)
{
    double t = ds / (ds - de);
    return cg_vec3_add(s, cg_vec3_scale(cg_vec3_sub(e, s), t));
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
    vec3_list in = {0}, res = {0};
    for (size_t i = 0; i < n; i++)
        if (!list3_push(&res, polygon[i]))
            goto nomem;
    for (size_t k = 0; k < plane_count && res.count; k++) {
        vec3_list t = in;
        in = res;
        res = t;
        res.count = 0;
        cg_vec3 nrm = planes[k].normal;
        double off = planes[k].offset;
        cg_vec3 s = in.points[in.count - 1];
        double ds = cg_vec3_dot(nrm, s) + off;
        for (size_t i = 0; i < in.count; i++) {
            cg_vec3 e = in.points[i];
            double de = cg_vec3_dot(nrm, e) + off;
            if (de >= 0) {
                if (ds < 0 && de > 0 && !list3_push(&res, plane_cross(e, de, s, ds)))
                    goto nomem;
                if (!list3_push(&res, e))
                    goto nomem;
            } else if (ds > 0) {
                if (!list3_push(&res, plane_cross(s, ds, e, de)))
                    goto nomem;
            }
            s = e;
            ds = de;
        }
    }
    free(in.points);
    if (res.count == 0) {
        free(res.points);
        return CG_OK;
    }
    *out = res.points;
    *out_count = res.count;
    return CG_OK;
nomem:
    free(in.points);
    free(res.points);
    return CG_ENOMEM;
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
