/* cg_clip_boolean against GEOS on random valid polygons (with holes, shared
 * edges and vertices): the areas agree and random points are inside both
 * results or neither. */
#include "cg/clip.h"
#include "check.h"

#include "clip_geos_shapes.h"

#include <stdarg.h>
#include <string.h>

static void star(check_rng *rng, cg_vec2 *p, int n, double cx, double cy, double r0, double r1,
                 int cw)
{
    for (int i = 0; i < n; i++) {
        int j = cw ? n - 1 - i : i;
        double a = 2 * CG_PI * (i + check_rng_range(rng, 0, 0.8)) / n,
               r = check_rng_range(rng, r0, r1);
        p[j] = cg_vec2_make(cx + r * cos(a), cy + r * sin(a));
    }
}

static int inside_result(const cg_polygon_set *r, double x, double y)
{
    int in = 0;
    for (size_t k = 0; k < r->ring_count; k++) {
        size_t a = r->ring_start[k], b = r->ring_start[k + 1];
        for (size_t i = a; i < b; i++) {
            cg_vec2 p = r->points[i], q = r->points[i + 1 < b ? i + 1 : a];
            if ((p.y <= y) != (q.y <= y) && p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y) < x)
                in = !in;
        }
    }
    return in;
}

int main(void)
{
    GEOSContextHandle_t h = clip_geos_start();
    check_rng rng = {0xfeed};
    long points = 0;
    for (int it = 0; it < 400; it++) {
        cg_polygon_set a = {0}, b = {0};
        cg_vec2 p[80];
        if (it % 3 == 2) {
            /* rectangles on a coarse grid: shared edges and vertices */
            for (int k = 0; k < 2; k++) {
                double x0 = (double)check_rng_int(&rng, 0, 4),
                       y0 = (double)check_rng_int(&rng, 0, 4);
                double x1 = x0 + (double)check_rng_int(&rng, 1, 4),
                       y1 = y0 + (double)check_rng_int(&rng, 1, 4);
                cg_vec2 rect[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
                cg_polygon_set_add_ring(k ? &b : &a, rect, 4, 1);
            }
        } else {
            int n = (int)check_rng_int(&rng, 3, 60);
            star(&rng, p, n, 0, 0, 0.5, 1.5, 0);
            cg_polygon_set_add_ring(&a, p, (size_t)n, 1);
            n = (int)check_rng_int(&rng, 3, 60);
            double cx = check_rng_range(&rng, -1, 1), cy = check_rng_range(&rng, -1, 1);
            star(&rng, p, n, cx, cy, 0.6, 1.4, 0);
            cg_polygon_set_add_ring(&b, p, (size_t)n, 1);
            if (n >= 8) {
                /* a clockwise hole within b's inner radius */
                star(&rng, p, 12, cx, cy, 0.1, 0.3, 1);
                cg_polygon_set_add_ring(&b, p, 12, 0);
            }
        }
        GEOSGeometry *ga = clip_geos_polygons(h, &a), *gb = clip_geos_polygons(h, &b);
        for (int op = 0; op < 4; op++) {
            cg_polygon_set r = {0};
            CHECK(cg_clip_boolean((cg_clip_op)op, &a, CG_CLIP_NON_ZERO, &b, CG_CLIP_NON_ZERO, 0, &r)
                  == CG_OK);
            GEOSGeometry *gr = op == 0   ? GEOSIntersection_r(h, ga, gb)
                               : op == 1 ? GEOSUnion_r(h, ga, gb)
                               : op == 2 ? GEOSDifference_r(h, ga, gb)
                                         : GEOSSymDifference_r(h, ga, gb);
            CHECK(gr != NULL);
            if (!gr)
                continue;
            double area = 0;
            GEOSArea_r(h, gr, &area);
            CHECK_NEAR(cg_polygon_set_area(&r), area, 1e-9 * (1 + area));
            const GEOSPreparedGeometry *prep = GEOSPrepare_r(h, gr);
            for (int s = 0; s < 40; s++) {
                double x = check_rng_range(&rng, -2, 9), y = check_rng_range(&rng, -2, 9);
                GEOSGeometry *pt = GEOSGeom_createPointFromXY_r(h, x, y);
                /* skip points on or very near an input boundary */
                double da = 0, db = 0;
                GEOSGeometry *ba = GEOSBoundary_r(h, ga), *bb = GEOSBoundary_r(h, gb);
                GEOSDistance_r(h, ba, pt, &da);
                GEOSDistance_r(h, bb, pt, &db);
                GEOSGeom_destroy_r(h, ba);
                GEOSGeom_destroy_r(h, bb);
                if (da > 1e-6 && db > 1e-6) {
                    int want = GEOSPreparedContains_r(h, prep, pt) == 1;
                    points++;
                    CHECK_MSG(inside_result(&r, x, y) == want, "round %d op %d point %g %g", it, op,
                              x, y);
                }
                GEOSGeom_destroy_r(h, pt);
            }
            GEOSPreparedGeom_destroy_r(h, prep);
            GEOSGeom_destroy_r(h, gr);
            cg_polygon_set_clear(&r);
        }
        GEOSGeom_destroy_r(h, ga);
        GEOSGeom_destroy_r(h, gb);
        cg_polygon_set_clear(&a);
        cg_polygon_set_clear(&b);
    }
    printf("GEOS: %ld points compared\n", points);
    GEOS_finish_r(h);
    return check_finish();
}
