/* The double API of the boolean operations: coordinates scaled to the
 * integer grid and back. */
#include "../internal.h"

#include <math.h>
#include <stdlib.h>

/* The grid of the double API: multiply by an explicit scale, or (automatic)
 * by 2^exponent with ldexp, which reaches every double's range exactly. */
typedef struct grid {
    double scale;
    int exponent;
} grid;

static double max_abs(const cg_polygon_set *set)
{
    double m = 0;
    if (!set)
        return 0;
    for (size_t i = 0; i < set->point_count; i++) {
        double a = fabs(set->points[i].x), b = fabs(set->points[i].y);
        if (!isfinite(a) || !isfinite(b))
            return NAN;
        if (a > m)
            m = a;
        if (b > m)
            m = b;
    }
    return m;
}

static grid pick_grid(double scale, double largest)
{
    grid g = {scale > 0 ? scale : 0, 0};
    if (scale > 0 || !(largest > 0))
        return g;
    int e;
    frexp(largest, &e); /* largest < 2^e: 2^(36 - e) maps it below 2^36 */
    g.exponent = 36 - e;
    return g;
}

static double to_grid(grid g, double v)
{
    return g.scale > 0 ? v * g.scale : ldexp(v, g.exponent);
}
static double from_grid(grid g, int64_t v)
{
    return g.scale > 0 ? (double)v / g.scale : ldexp((double)v, -g.exponent);
}

static cg_status grid_points(const cg_polygon_set *in, grid g, cg_polygon_set64 *out)
{
    cg_polygon_set64_clear(out);
    if (!in)
        return CG_OK;
    for (size_t r = 0; r < in->ring_count; r++) {
        size_t a = in->ring_start[r], b = in->ring_start[r + 1];
        if (b < a || b > in->point_count)
            return CG_EINVAL;
        /* the ring opened, with room for its points, and filled below */
        cg_status st = cg_polygon_set64_add_ring(out, NULL, 0, 1);
        if (st == CG_OK)
            st = clip_polygon_set64_reserve(out, out->point_count + (b - a), out->ring_count,
                                            out->polygon_count);
        if (st != CG_OK)
            return st;
        out->ring_count--;
        for (size_t i = a; i < b; i++) {
            double x = to_grid(g, in->points[i].x), y = to_grid(g, in->points[i].y);
            if (!isfinite(x) || !isfinite(y))
                return isfinite(in->points[i].x) && isfinite(in->points[i].y) ? CG_ERANGE
                                                                              : CG_EINVAL;
            if (fabs(x) > (double)CG_CLIP_MAX_COORD || fabs(y) > (double)CG_CLIP_MAX_COORD)
                return CG_ERANGE;
            out->points[out->point_count++] = (cg_point64){(int64_t)llround(x),
                                                           (int64_t)llround(y)};
        }
        out->ring_count++;
        out->ring_start[out->ring_count] = out->point_count;
    }
    return CG_OK;
}

static cg_status ungrid_points(const cg_polygon_set64 *in, grid g, cg_polygon_set *out)
{
    cg_polygon_set_clear(out);
    for (size_t p = 0; p < in->polygon_count; p++) {
        for (size_t r = in->polygon_start[p]; r < in->polygon_start[p + 1]; r++) {
            size_t a = in->ring_start[r], b = in->ring_start[r + 1];
            /* the ring opened, with room for its points, and filled below */
            cg_status st = cg_polygon_set_add_ring(out, NULL, 0, r == in->polygon_start[p]);
            if (st == CG_OK)
                st = clip_polygon_set_reserve(out, out->point_count + (b - a), out->ring_count,
                                              out->polygon_count);
            if (st != CG_OK)
                return st;
            out->ring_count--;
            for (size_t i = a; i < b; i++) {
                out->points[out->point_count++] = cg_vec2_make(from_grid(g, in->points[i].x),
                                                               from_grid(g, in->points[i].y));
            }
            out->ring_count++;
            out->ring_start[out->ring_count] = out->point_count;
        }
    }
    return CG_OK;
}

cg_status cg_clip_boolean(cg_clip_op op, const cg_polygon_set *subject, cg_clip_fill subject_fill,
                          const cg_polygon_set *clip, cg_clip_fill clip_fill, double scale,
                          cg_polygon_set *result)
{
    return cg_clip_boolean_ws(NULL, op, subject, subject_fill, clip, clip_fill, scale, result);
}

cg_status cg_clip_boolean_ws(cg_clip_workspace *ws, cg_clip_op op, const cg_polygon_set *subject,
                             cg_clip_fill subject_fill, const cg_polygon_set *clip,
                             cg_clip_fill clip_fill, double scale, cg_polygon_set *result)
{
    if (!result)
        return CG_EINVAL;
    if (result == subject || result == clip) {
        /* the result replaces an operand: computed beside it first */
        cg_polygon_set own = {0};
        cg_status st = cg_clip_boolean_ws(ws, op, subject, subject_fill, clip, clip_fill, scale,
                                          &own);
        cg_polygon_set_clear(result);
        *result = own;
        return st;
    }
    cg_polygon_set_clear(result);
    if (isnan(scale) || isinf(scale))
        return CG_EINVAL;
    double m1 = max_abs(subject), m2 = max_abs(clip);
    if (isnan(m1) || isnan(m2))
        return CG_EINVAL;
    grid g = pick_grid(scale, m1 > m2 ? m1 : m2);
    cg_polygon_set64 a = {0}, b = {0}, r = {0};
    cg_status st = grid_points(subject, g, &a);
    if (st == CG_OK)
        st = grid_points(clip, g, &b);
    if (st == CG_OK)
        st = cg_clip_boolean64_ws(ws, op, &a, subject_fill, &b, clip_fill, &r);
    if (st == CG_OK)
        st = ungrid_points(&r, g, result);
    if (st != CG_OK)
        cg_polygon_set_clear(result);
    cg_polygon_set64_clear(&a);
    cg_polygon_set64_clear(&b);
    cg_polygon_set64_clear(&r);
    return st;
}
