/* Curves of section 2.3 drawn as flattened polylines. */
#include "internal.h"
#include "cg/curve.h"
#include "../core/array.h"

#include <stdlib.h>

typedef CORE_ARRAY(cg_vec2) point_list;

static cg_status append(void *user, cg_vec2 p)
{
    point_list *list = user;
    return core_array_push(list, p);
}

/* Largest coordinate accepted for aliased curves, whose points are rounded
 * to int pixel indices. */
#define ALIASED_LIMIT 1e9

static cg_status draw_points(cg_image *image, const point_list *list, cg_draw_mode mode,
                             cg_rgba8 color)
{
    if (mode == CG_DRAW_ANTIALIASED) {
        /* Both modes take image-plane coordinates; aliased curves join the pixels
         * that contain the polyline's points with Bresenham lines. */
        return cg_draw_polyline_aa(image, list->data, (int)list->count, color);
    }
    int *xy = malloc(list->count * 2 * sizeof *xy);
    if (!xy)
        return CG_ENOMEM;
    int n = 0;
    for (size_t i = 0; i < list->count; i++) {
        int x = (int)floor(list->data[i].x), y = (int)floor(list->data[i].y);
        if (n > 0 && xy[2 * n - 2] == x && xy[2 * n - 1] == y)
            continue;
        xy[2 * n] = x;
        xy[2 * n + 1] = y;
        n++;
    }
    cg_status status = cg_draw_polyline(image, xy, n, color);
    free(xy);
    return status;
}

/* Flattens count Bézier control polygons of `degree + 1` points each, joined
 * end to start, and draws them as one polyline. */
static cg_status draw_beziers(cg_image *image, const cg_vec2 *control, int segments, int stride,
                              int points, double tolerance, cg_draw_mode mode, cg_rgba8 color)
{
    if (!image || !image->data || !control
        || (mode != CG_DRAW_ALIASED && mode != CG_DRAW_ANTIALIASED))
        return CG_EINVAL;
    int same = 1;
    for (int s = 0; s < segments; s++)
        for (int i = 0; i < points; i++) {
            cg_vec2 p = control[s * stride + i];
            if (!isfinite(p.x) || !isfinite(p.y))
                return CG_EINVAL;
            if (mode == CG_DRAW_ALIASED && (fabs(p.x) > ALIASED_LIMIT || fabs(p.y) > ALIASED_LIMIT))
                return CG_ERANGE;
            if (p.x != control[0].x || p.y != control[0].y)
                same = 0;
        }
    if (!(tolerance > 0) || !isfinite(tolerance))
        return CG_EINVAL;
    if (same)
        return CG_EEMPTY;
    point_list list = {NULL, 0, 0};
    cg_status status = append(&list, control[0]);
    for (int s = 0; s < segments && status == CG_OK; s++)
        status = cg_bezier_flatten(control + s * stride, points, tolerance, append, &list);
    if (status == CG_OK)
        status = draw_points(image, &list, mode, color);
    free(list.data);
    return status;
}

cg_status cg_draw_bezier(cg_image *image, const cg_vec2 *control, int count, double tolerance,
                         cg_draw_mode mode, cg_rgba8 color)
{
    if (count < 2 || count > CG_BEZIER_MAX_POINTS)
        return CG_EINVAL;
    return draw_beziers(image, control, 1, count, count, tolerance, mode, color);
}

cg_status cg_draw_hermite(cg_image *image, cg_vec2 p1, cg_vec2 p4, cg_vec2 r1, cg_vec2 r4,
                          double tolerance, cg_draw_mode mode, cg_rgba8 color)
{
    cg_cubic2 h = {CG_BASIS_HERMITE, {p1, p4, r1, r4}}, b;
    cg_vec2 check[4] = {p1, p4, r1, r4};
    for (int i = 0; i < 4; i++)
        if (!isfinite(check[i].x) || !isfinite(check[i].y))
            return CG_EINVAL;
    cg_cubic2_convert(&h, CG_BASIS_BEZIER, &b);
    return draw_beziers(image, b.g, 1, 4, 4, tolerance, mode, color);
}

/* A uniform spline of count control points: count - 3 cubic segments, each
 * converted to Bézier form. */
static cg_status draw_spline(cg_image *image, cg_curve_basis basis, const cg_vec2 *control,
                             int count, double tolerance, cg_draw_mode mode, cg_rgba8 color)
{
    if (!control || count < 4 || count > (1 << 20) || !image)
        return CG_EINVAL;
    int same = 1;
    for (int i = 1; i < count; i++)
        same &= control[i].x == control[0].x && control[i].y == control[0].y;
    if (same && isfinite(control[0].x) && isfinite(control[0].y))
        return CG_EEMPTY;
    cg_vec2 *beziers = malloc((size_t)(count - 3) * 4 * sizeof *beziers);
    if (!beziers)
        return CG_ENOMEM;
    for (int s = 0; s + 3 < count; s++) {
        cg_cubic2 segment = {basis, {control[s], control[s + 1], control[s + 2], control[s + 3]}},
                  b;
        cg_cubic2_convert(&segment, CG_BASIS_BEZIER, &b);
        for (int i = 0; i < 4; i++)
            beziers[4 * s + i] = b.g[i];
    }
    cg_status status = draw_beziers(image, beziers, count - 3, 4, 4, tolerance, mode, color);
    free(beziers);
    return status;
}

cg_status cg_draw_bspline(cg_image *image, const cg_vec2 *control, int count, double tolerance,
                          cg_draw_mode mode, cg_rgba8 color)
{
    return draw_spline(image, CG_BASIS_BSPLINE, control, count, tolerance, mode, color);
}

cg_status cg_draw_catmull_rom(cg_image *image, const cg_vec2 *control, int count, double tolerance,
                              cg_draw_mode mode, cg_rgba8 color)
{
    return draw_spline(image, CG_BASIS_CATMULL_ROM, control, count, tolerance, mode, color);
}
