/* Rectangle clips, triangulations and simplifications read back by GEOS:
 * every result GEOSisValid; a rectangle clip covers what GEOS's
 * intersection of the same region with the rectangle covers (the area of
 * the symmetric difference within the rounding); the union of the
 * triangles, as GEOS computes it, is the triangulated region; a simplified
 * polygon stays within the RDP tolerance of the original (Hausdorff
 * distance of the boundaries).  Inputs: random star polygons with holes,
 * made simple by cg's union first so that GEOS accepts them. */
#define SHAPES_WITH_GEOS
#include "polygon_shapes.h"
#include "check.h"

static GEOSContextHandle_t geos;
static double symmetric_difference_area(GEOSGeometry *a, GEOSGeometry *b)
{
    GEOSGeometry *x = GEOSSymDifference_r(geos, a, b);
    double area = -1;
    if (x)
        GEOSArea_r(geos, x, &area);
    GEOSGeom_destroy_r(geos, x);
    return area;
}

static void rectangles(void)
{
    cg_polygon_set region = {0}, clipped = {0};
    for (int trial = 0; trial < 200; trial++) {
        shapes_random_region(&region, 0);
        double x0 = shapes_between(-40, 30), y0 = shapes_between(-40, 30);
        cg_rect r = {x0, y0, x0 + shapes_between(0.1, 40), y0 + shapes_between(0.1, 40)};
        CHECK(cg_rect_clip(&region, CG_CLIP_NON_ZERO, r, 0, &clipped) == CG_OK);
        GEOSGeometry *mine = shapes_geos_polygons(geos, &clipped);
        CHECK_MSG(GEOSisValid_r(geos, mine) == 1, "trial %d: rect clip not valid", trial);
        GEOSGeometry *g = shapes_geos_polygons(geos, &region);
        GEOSGeometry *box = GEOSGeom_createRectangle_r(geos, r.xmin, r.ymin, r.xmax, r.ymax);
        GEOSGeometry *want = GEOSIntersection_r(geos, g, box);
        double diff = symmetric_difference_area(mine, want);
        CHECK_MSG(diff >= 0 && diff < 1e-6, "trial %d: rect clip differs from GEOS by %g", trial,
                  diff);
        GEOSGeom_destroy_r(geos, want);
        GEOSGeom_destroy_r(geos, box);
        GEOSGeom_destroy_r(geos, g);
        GEOSGeom_destroy_r(geos, mine);
    }
    cg_polygon_set_clear(&region);
    cg_polygon_set_clear(&clipped);
}

static void triangulations(void)
{
    cg_polygon_set region = {0}, triangles = {0};
    for (int trial = 0; trial < 200; trial++) {
        shapes_random_region(&region, 0);
        CHECK(cg_triangulate(&region, CG_CLIP_NON_ZERO, 0, &triangles) == CG_OK);
        GEOSGeometry *tri = shapes_geos_polygons(geos, &triangles);
        int valid = 1;
        for (int k = 0; k < GEOSGetNumGeometries_r(geos, tri); k++)
            valid &= GEOSisValid_r(geos, GEOSGetGeometryN_r(geos, tri, k)) == 1;
        CHECK_MSG(valid, "trial %d: a triangle not valid", trial);
        GEOSGeometry *covered = GEOSUnaryUnion_r(geos, tri);
        GEOSGeometry *g = shapes_geos_polygons(geos, &region);
        double diff = symmetric_difference_area(covered, g), area;
        GEOSArea_r(geos, g, &area);
        CHECK_MSG(diff >= 0 && diff <= 1e-9 * area, "trial %d: union of triangles differs by %g",
                  trial, diff);
        GEOSGeom_destroy_r(geos, g);
        GEOSGeom_destroy_r(geos, covered);
        GEOSGeom_destroy_r(geos, tri);
    }
    cg_polygon_set_clear(&region);
    cg_polygon_set_clear(&triangles);
}

static void simplifications(void)
{
    cg_polygon_set region = {0}, simple = {0};
    for (int trial = 0; trial < 200; trial++) {
        shapes_random_region(&region, 0);
        double tolerance = shapes_between(0.01, 3);
        int rdp = trial % 2 == 0;
        CHECK(cg_simplify(&region, 0, CG_CLIP_NON_ZERO,
                          rdp ? CG_SIMPLIFY_RDP : CG_SIMPLIFY_VISVALINGAM,
                          rdp ? tolerance : tolerance * tolerance, 0, &simple)
              == CG_OK);
        GEOSGeometry *mine = shapes_geos_polygons(geos, &simple);
        CHECK_MSG(GEOSisValid_r(geos, mine) == 1, "trial %d: simplified not valid", trial);
        if (rdp) {
            GEOSGeometry *g = shapes_geos_polygons(geos, &region);
            GEOSGeometry *b1 = GEOSBoundary_r(geos, mine), *b2 = GEOSBoundary_r(geos, g);
            double h = INFINITY;
            GEOSHausdorffDistanceDensify_r(geos, b1, b2, 0.05, &h);
            CHECK_MSG(h <= tolerance * 1.0001 + 1e-9, "trial %d: Hausdorff %g > tolerance %g",
                      trial, h, tolerance);
            GEOSGeom_destroy_r(geos, b1);
            GEOSGeom_destroy_r(geos, b2);
            GEOSGeom_destroy_r(geos, g);
        }
        GEOSGeom_destroy_r(geos, mine);
    }
    cg_polygon_set_clear(&region);
    cg_polygon_set_clear(&simple);
}

int main(int argc, char **argv)
{
    geos = shapes_geos_start();
    check_start(argc, argv);
    CHECK_GROUP(rectangles);
    CHECK_GROUP(triangulations);
    CHECK_GROUP(simplifications);
    GEOS_finish_r(geos);
    return check_finish();
}
