/* The double API's grid for the polygon-geometry operations, and exact
 * helpers on int64 rings. */
#include "polygon_internal.h"

#include "../core/array.h"

#include <math.h>
#include <string.h>

cg_status polygon_grid_pick(double scale, double largest, polygon_grid *grid)
{
    if (isnan(scale) || isinf(scale) || isnan(largest) || isinf(largest))
        return CG_EINVAL;
    grid->scale = scale > 0 ? scale : 0;
    grid->exponent = 0;
    if (scale <= 0 && largest > 0) {
        int e;
        frexp(largest, &e); /* largest < 2^e: 2^(36 - e) maps it below 2^36 */
        grid->exponent = 36 - e;
    }
    return CG_OK;
}

double polygon_grid_to(polygon_grid grid, double value)
{
    return grid.scale > 0 ? value * grid.scale : ldexp(value, grid.exponent);
}

double polygon_grid_from(polygon_grid grid, int64_t value)
{
    return grid.scale > 0 ? (double)value / grid.scale : ldexp((double)value, -grid.exponent);
}

double polygon_max_abs(const cg_polygon_set *set)
{
    double m = 0;
    for (size_t i = 0; set && i < set->point_count; i++) {
        double a = fabs(set->points[i].x), b = fabs(set->points[i].y);
        if (!isfinite(a) || !isfinite(b))
            return NAN;
        m = a > m ? a : m;
        m = b > m ? b : m;
    }
    return m;
}

cg_status polygon_set_to_grid(const cg_polygon_set *in, polygon_grid grid, cg_polygon_set64 *out)
{
    cg_polygon_set64_clear(out);
    CORE_ARRAY(cg_point64) ring = {0};
    cg_status st = CG_OK;
    for (size_t r = 0; in && r < in->ring_count && st == CG_OK; r++) {
        size_t a = in->ring_start[r], b = in->ring_start[r + 1];
        if (b < a || b > in->point_count) {
            st = CG_EINVAL;
            break;
        }
        ring.count = 0;
        st = core_array_reserve_for(&ring, b - a);
        for (size_t i = a; i < b && st == CG_OK; i++) {
            double x = nearbyint(polygon_grid_to(grid, in->points[i].x));
            double y = nearbyint(polygon_grid_to(grid, in->points[i].y));
            if (!(fabs(x) <= (double)CG_CLIP_MAX_COORD && fabs(y) <= (double)CG_CLIP_MAX_COORD))
                st = CG_ERANGE;
            else
                ring.data[ring.count++] = (cg_point64){(int64_t)x, (int64_t)y};
        }
        if (st == CG_OK)
            st = cg_polygon_set64_add_ring(out, ring.data, ring.count, 1);
    }
    core_array_free(&ring);
    return st;
}

cg_status polygon_set_from_grid(const cg_polygon_set64 *in, polygon_grid grid, cg_polygon_set *out)
{
    cg_polygon_set_clear(out);
    CORE_ARRAY(cg_vec2) ring = {0};
    cg_status st = CG_OK;
    size_t polygon = 0;
    for (size_t r = 0; in && r < in->ring_count && st == CG_OK; r++) {
        int new_polygon = 1;
        if (in->polygon_count > 0) {
            while (polygon + 1 < in->polygon_count && in->polygon_start[polygon + 1] <= r)
                polygon++;
            new_polygon = in->polygon_start[polygon] == r;
        }
        size_t a = in->ring_start[r], b = in->ring_start[r + 1];
        ring.count = 0;
        st = core_array_reserve_for(&ring, b - a);
        for (size_t i = a; i < b && st == CG_OK; i++)
            ring.data[ring.count++] = cg_vec2_make(polygon_grid_from(grid, in->points[i].x),
                                                   polygon_grid_from(grid, in->points[i].y));
        if (st == CG_OK)
            st = cg_polygon_set_add_ring(out, ring.data, ring.count, new_polygon);
    }
    core_array_free(&ring);
    return st;
}

polygon_i128 polygon_ring_twice_area(const cg_point64 *p, size_t n)
{
    polygon_i128 s = 0;
    for (size_t i = 1; i + 1 < n; i++) {
        polygon_i128 x1 = p[i].x - p[0].x, y1 = p[i].y - p[0].y;
        polygon_i128 x2 = p[i + 1].x - p[0].x, y2 = p[i + 1].y - p[0].y;
        s += x1 * y2 - x2 * y1;
    }
    return s;
}

cg_status polygon_set64_check_range(const cg_polygon_set64 *set)
{
    int64_t largest;
    cg_status st = polygon_set64_max_abs(set, &largest);
    if (st == CG_OK && largest > CG_CLIP_MAX_COORD)
        st = CG_ERANGE;
    return st;
}

cg_status polygon_set64_max_abs(const cg_polygon_set64 *set, int64_t *largest)
{
    int64_t m = 0;
    for (size_t r = 0; set && r < set->ring_count; r++)
        if (set->ring_start[r + 1] < set->ring_start[r]
            || set->ring_start[r + 1] > set->point_count)
            return CG_EINVAL;
    for (size_t i = 0; set && i < set->point_count; i++) {
        int64_t x = set->points[i].x, y = set->points[i].y;
        /* INT64_MIN has no absolute value: it is out of range anyway */
        x = x == INT64_MIN ? INT64_MAX : (x < 0 ? -x : x);
        y = y == INT64_MIN ? INT64_MAX : (y < 0 ? -y : y);
        m = x > m ? x : m;
        m = y > m ? y : m;
    }
    *largest = m;
    return CG_OK;
}

int polygon_orient(cg_point64 a, cg_point64 b, cg_point64 c)
{
    polygon_i128 d = (polygon_i128)(b.x - a.x) * (c.y - a.y)
                     - (polygon_i128)(b.y - a.y) * (c.x - a.x);
    return (d > 0) - (d < 0);
}

static int is_sliver(const cg_point64 *p, size_t n)
{
    polygon_i128 twice_area = polygon_ring_twice_area(p, n);
    double perimeter = 0;
    for (size_t i = 0; i < n; i++) {
        cg_point64 a = p[i], b = p[(i + 1) % n];
        perimeter += hypot((double)(b.x - a.x), (double)(b.y - a.y));
    }
    double area = fabs((double)twice_area) / 2;
    return area < perimeter / 2;
}

void polygon_drop_slivers(cg_polygon_set64 *set)
{
    size_t rings = 0, points = 0, polygons = 0;
    for (size_t k = 0; k < set->polygon_count; k++) {
        size_t r0 = set->polygon_start[k], r1 = set->polygon_start[k + 1];
        size_t first_ring = rings;
        for (size_t r = r0; r < r1; r++) {
            size_t a = set->ring_start[r], n = set->ring_start[r + 1] - a;
            if (is_sliver(set->points + a, n)) {
                if (r == r0)
                    break; /* the outer ring: the whole polygon goes */
                continue;
            }
            /* the ring moved down to where the kept ones end (never up) */
            memmove(set->points + points, set->points + a, n * sizeof *set->points);
            set->ring_start[rings] = points;
            points += n;
            rings++;
        }
        if (rings > first_ring)
            set->polygon_start[polygons++] = first_ring;
    }
    set->point_count = points;
    set->ring_count = rings;
    set->polygon_count = polygons;
    if (set->ring_start)
        set->ring_start[rings] = points;
    if (set->polygon_start)
        set->polygon_start[polygons] = rings;
}
