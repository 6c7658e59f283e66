/* Polygon sets: the input and output type of the boolean operations. */
#include "internal.h"
#include "../core/array.h"

#include <stdlib.h>
#include <string.h>

#define DEFINE_SET(SET, POINT, PREFIX, RESERVE)                                                    \
    void PREFIX##_clear(SET *set)                                                                  \
    {                                                                                              \
        if (!set)                                                                                  \
            return;                                                                                \
        free(set->points);                                                                         \
        free(set->ring_start);                                                                     \
        free(set->polygon_start);                                                                  \
        memset(set, 0, sizeof *set);                                                               \
    }                                                                                              \
    cg_status RESERVE(SET *set, size_t points, size_t rings, size_t polygons)                      \
    {                                                                                              \
        if (points > ((size_t)-1) / 4 / sizeof(POINT) || rings > ((size_t)-1) / 4 / sizeof(size_t) \
            || polygons > ((size_t)-1) / 4 / sizeof(size_t))                                       \
            return CG_ENOMEM;                                                                      \
        if (core_array_reserve((void **)&set->points, &set->point_capacity, points, sizeof(POINT)) \
                != CG_OK                                                                           \
            || core_array_reserve((void **)&set->ring_start, &set->ring_capacity, rings + 1,       \
                                  sizeof(size_t))                                                  \
                   != CG_OK                                                                        \
            || core_array_reserve((void **)&set->polygon_start, &set->polygon_capacity,            \
                                  polygons + 1, sizeof(size_t))                                    \
                   != CG_OK)                                                                       \
            return CG_ENOMEM;                                                                      \
        return CG_OK;                                                                              \
    }                                                                                              \
    cg_status PREFIX##_add_ring(SET *set, const POINT *points, size_t n, int new_polygon)          \
    {                                                                                              \
        if (!set || (!points && n))                                                                \
            return CG_EINVAL;                                                                      \
        if (n > ((size_t)-1) / 4 / sizeof(POINT) - set->point_count)                               \
            return CG_ENOMEM;                                                                      \
        int new_p = new_polygon || set->polygon_count == 0;                                        \
        cg_status st = RESERVE(set, set->point_count + n, set->ring_count + 1,                     \
                               set->polygon_count + new_p);                                        \
        if (st != CG_OK)                                                                           \
            return st;                                                                             \
        if (new_p) {                                                                               \
            if (set->polygon_count == 0)                                                           \
                set->polygon_start[0] = 0;                                                         \
            set->polygon_count++;                                                                  \
        }                                                                                          \
        if (set->ring_count == 0)                                                                  \
            set->ring_start[0] = 0;                                                                \
        if (n)                                                                                     \
            memcpy(set->points + set->point_count, points, n * sizeof *points);                    \
        set->point_count += n;                                                                     \
        set->ring_count++;                                                                         \
        set->ring_start[set->ring_count] = set->point_count;                                       \
        set->polygon_start[set->polygon_count] = set->ring_count;                                  \
        return CG_OK;                                                                              \
    }

DEFINE_SET(cg_polygon_set, cg_vec2, cg_polygon_set, clip_polygon_set_reserve)
DEFINE_SET(cg_polygon_set64, cg_point64, cg_polygon_set64, clip_polygon_set64_reserve)

double cg_polygon_set_ring_area(const cg_polygon_set *set, size_t r)
{
    if (!set || r >= set->ring_count)
        return 0;
    size_t a = set->ring_start[r], b = set->ring_start[r + 1];
    double s = 0;
    if (b - a < 3)
        return 0;
    /* relative to the first point for accuracy */
    cg_vec2 o = set->points[a];
    for (size_t i = a + 1; i + 1 < b; i++)
        s += cg_vec2_cross(cg_vec2_sub(set->points[i], o), cg_vec2_sub(set->points[i + 1], o));
    return 0.5 * s;
}

double cg_polygon_set_area(const cg_polygon_set *set)
{
    double s = 0;
    for (size_t r = 0; set && r < set->ring_count; r++)
        s += cg_polygon_set_ring_area(set, r);
    return s;
}

clip_i128 clip_ring_twice_area(const cg_point64 *p, size_t n)
{
    clip_i128 s = 0;
    for (size_t i = 1; i + 1 < n; i++) {
        clip_i128 x1 = p[i].x - p[0].x, y1 = p[i].y - p[0].y;
        clip_i128 x2 = p[i + 1].x - p[0].x, y2 = p[i + 1].y - p[0].y;
        s += x1 * y2 - x2 * y1;
    }
    return s;
}

double cg_polygon_set64_area(const cg_polygon_set64 *set)
{
    double total = 0;
    for (size_t r = 0; set && r < set->ring_count; r++) {
        size_t a = set->ring_start[r], b = set->ring_start[r + 1];
        total += 0.5 * (double)clip_ring_twice_area(clip_ring_points(set, r), b - a);
    }
    return total;
}
