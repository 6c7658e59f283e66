/* Variable offsets: a distance per vertex, interpolated along each edge.
 *
 * The region swept by a disk whose centre runs along an edge p-q while its
 * radius goes linearly from r_p to r_q is the convex hull of the two end
 * disks (every disk on the way lies in it, and it is the union of them):
 *
 *              ___-------___
 *          .-'               '---.___
 *         /    r_p               r_q '.
 *        |  p *-----------------------* q |
 *         \                         _.'
 *          '-.___           ___---''
 *                '---------'
 *
 * bounded by the two outer tangents and the arcs of each disk beyond them.
 * The band is the union of these hulls over every edge of the paths (rings
 * closed, or open polylines); the result is the region united with it
 * (inflating), less it (deflating), or the band itself (open paths).  The
 * arcs are drawn with chords inside the circles, within the arc tolerance. */
#include "polygon_internal.h"

#include "../core/array.h"

#include <math.h>

typedef CORE_ARRAY(cg_point64) point_array;

/* Appends the arc of the circle (c, r) from angle a0 counter-clockwise to
 * a1 (a1 >= a0), ends included, with steps of at most `step`. */
static cg_status push_arc(point_array *out, cg_point64 c, double r, double a0, double a1,
                          double step)
{
    int steps = (int)ceil((a1 - a0) / step);
    steps = steps < 1 ? 1 : steps;
    cg_status st = CG_OK;
    for (int k = 0; k <= steps && st == CG_OK; k++) {
        double a = a0 + (a1 - a0) * k / steps;
        cg_point64 p = {(int64_t)llround((double)c.x + r * cos(a)),
                        (int64_t)llround((double)c.y + r * sin(a))};
        st = core_array_push(out, p);
    }
    return st;
}

/* The angle step whose chords stay within tolerance of a circle of radius
 * r (at most a quarter turn). */
static double arc_step(double r, double tolerance)
{
    if (tolerance >= r)
        return M_PI / 2;
    double step = 2 * acos(1 - tolerance / r);
    return step > M_PI / 2 ? M_PI / 2 : step;
}

/* The hull of the disks (p, rp) and (q, rq) as a counter-clockwise ring
 * into ring (emptied first; nothing when both radii are 0). */
static cg_status hull(point_array *ring, cg_point64 p, double rp, cg_point64 q, double rq,
                      double tolerance)
{
    ring->count = 0;
    if (rp <= 0 && rq <= 0)
        return CG_OK;
    double dx = (double)(q.x - p.x), dy = (double)(q.y - p.y), length = hypot(dx, dy);
    double step = arc_step(fmax(rp, rq), tolerance);
    if (length <= fabs(rp - rq)) /* one disk holds the other */
        return rp >= rq ? push_arc(ring, p, rp, 0, 2 * M_PI - step / 2, step)
                        : push_arc(ring, q, rq, 0, 2 * M_PI - step / 2, step);
    /* the outer tangents touch each circle at angle heading +- beta, where
     * cos(beta) = (rp - rq) / length */
    double heading = atan2(dy, dx), beta = acos((rp - rq) / length);
    cg_status st = CG_OK;
    if (rq > 0) /* the arc of q's circle in front, from -beta to +beta */
        st = push_arc(ring, q, rq, heading - beta, heading + beta, step);
    else
        st = core_array_push(ring, q);
    if (st == CG_OK && rp > 0) /* p's behind, from beta to 2 pi - beta */
        st = push_arc(ring, p, rp, heading + beta, heading + 2 * M_PI - beta, step);
    else if (st == CG_OK)
        st = core_array_push(ring, p);
    return st;
}

/* The hulls of every edge of paths (closed when `closed`) into band. */
static cg_status build_hulls(const cg_polygon_set64 *paths, const double *radii, int closed,
                             double tolerance, cg_polygon_set64 *band)
{
    point_array ring = {0};
    cg_status st = CG_OK;
    for (size_t r = 0; r < paths->ring_count && st == CG_OK; r++) {
        size_t a = paths->ring_start[r], b = paths->ring_start[r + 1];
        for (size_t i = a; i < b && st == CG_OK; i++) {
            size_t j = i + 1 < b ? i + 1 : a;
            if (j == a && !closed && b - a > 1)
                break;
            st = hull(&ring, paths->points[i], radii[i], paths->points[j], radii[j], tolerance);
            if (st == CG_OK && ring.count >= 3)
                st = cg_polygon_set64_add_ring(band, ring.data, ring.count, 1);
        }
    }
    core_array_free(&ring);
    return st;
}

/* Checks deltas: finite, of one sign; the sign (+1, -1, or 0 when all are
 * zero) and the largest |delta|, or CG_EINVAL. */
static cg_status check_deltas(const double *deltas, size_t n, int *sign, double *largest)
{
    int positive = 0, negative = 0;
    *largest = 0;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(deltas[i]))
            return CG_EINVAL;
        positive |= deltas[i] > 0;
        negative |= deltas[i] < 0;
        *largest = fmax(*largest, fabs(deltas[i]));
    }
    if (positive && negative)
        return CG_EINVAL;
    *sign = positive ? 1 : negative ? -1 : 0;
    return CG_OK;
}

cg_status cg_offset_variable64_ws(cg_clip_workspace *ws, const cg_polygon_set64 *paths,
                                  const double *deltas, const cg_offset_options *options,
                                  cg_polygon_set64 *result)
{
    cg_offset_options defaults = cg_offset_options_default();
    if (!options)
        options = &defaults;
    if (!paths || !result || (!deltas && paths->point_count > 0)
        || (unsigned)options->fill > CG_CLIP_NEGATIVE || !isfinite(options->arc_tolerance)
        || options->arc_tolerance < 0
        || (options->end != CG_OFFSET_END_POLYGON && options->end != CG_OFFSET_END_JOINED
            && options->end != CG_OFFSET_END_ROUND))
        return CG_EINVAL;
    int sign;
    double largest_delta;
    int64_t largest;
    cg_status st = check_deltas(deltas, paths->point_count, &sign, &largest_delta);
    if (st == CG_OK)
        st = polygon_set64_max_abs(paths, &largest);
    if (st != CG_OK)
        return st;
    if ((double)largest + largest_delta + 2 > (double)CG_CLIP_MAX_COORD)
        return CG_ERANGE;
    double *radii = paths->point_count ? malloc(paths->point_count * sizeof *radii) : NULL;
    if (paths->point_count && !radii)
        return CG_ENOMEM;
    for (size_t i = 0; i < paths->point_count; i++)
        radii[i] = fabs(deltas[i]);
    double tolerance = options->arc_tolerance > 0 ? options->arc_tolerance : largest_delta / 500;
    tolerance = fmax(tolerance, fmax(0.25, largest_delta * 1e-5));
    int polygons = options->end == CG_OFFSET_END_POLYGON;
    cg_polygon_set64 band = {0}, simple = {0}, none = {0};
    st = build_hulls(paths, radii, options->end != CG_OFFSET_END_ROUND, tolerance, &band);
    free(radii);
    if (st == CG_OK && polygons)
        st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, paths, options->fill, &none, options->fill,
                                  &simple);
    if (st == CG_OK) {
        cg_clip_op op = !polygons || sign >= 0 ? CG_CLIP_UNION : CG_CLIP_DIFFERENCE;
        st = cg_clip_boolean64_ws(ws, op, &simple, CG_CLIP_NON_ZERO, &band, CG_CLIP_NON_ZERO,
                                  result);
    }
    if (st == CG_OK)
        polygon_drop_slivers(result);
    cg_polygon_set64_clear(&band);
    cg_polygon_set64_clear(&simple);
    return st;
}

cg_status cg_offset_variable64(const cg_polygon_set64 *paths, const double *deltas,
                               const cg_offset_options *options, cg_polygon_set64 *result)
{
    return cg_offset_variable64_ws(NULL, paths, deltas, options, result);
}

cg_status cg_offset_variable(const cg_polygon_set *paths, const double *deltas,
                             const cg_offset_options *options, double scale, cg_polygon_set *result)
{
    cg_offset_options grid_options = options ? *options : cg_offset_options_default();
    if (!paths || !result || (!deltas && paths->point_count > 0)
        || !isfinite(grid_options.arc_tolerance))
        return CG_EINVAL;
    int sign;
    double largest_delta;
    cg_status st = check_deltas(deltas, paths->point_count, &sign, &largest_delta);
    if (st != CG_OK)
        return st;
    polygon_grid grid;
    st = polygon_grid_pick(scale, polygon_max_abs(paths) + largest_delta, &grid);
    if (st != CG_OK)
        return st;
    grid_options.arc_tolerance = polygon_grid_to(grid, grid_options.arc_tolerance);
    double *grid_deltas = paths->point_count ? malloc(paths->point_count * sizeof *grid_deltas)
                                             : NULL;
    if (paths->point_count && !grid_deltas)
        return CG_ENOMEM;
    for (size_t i = 0; i < paths->point_count; i++)
        grid_deltas[i] = polygon_grid_to(grid, deltas[i]);
    cg_polygon_set64 in = {0}, out = {0};
    st = polygon_set_to_grid(paths, grid, &in);
    if (st == CG_OK && in.point_count != paths->point_count)
        st = CG_EINVAL; /* rings must cover the points, one delta each */
    if (st == CG_OK)
        st = cg_offset_variable64_ws(NULL, &in, grid_deltas, &grid_options, &out);
    if (st == CG_OK)
        st = polygon_set_from_grid(&out, grid, result);
    free(grid_deltas);
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
    return st;
}
