/* Offsets checked against GEOS's buffer (GEOSBufferWithStyle, the same
 * joins and caps) over random polygons with holes and random polylines:
 * every result is GEOSisValid, the boundaries lie within the tolerance of
 * each other (Hausdorff distance, densified), and so the areas agree within
 * the result's perimeter times that tolerance.  Inflating then deflating by
 * the same distance gives back a polygon with no feature narrower than
 * twice the distance.
 *
 * The tolerance is the sum of cg's arc tolerance, GEOS's own chord error
 * (64 segments a quarter circle) and, for non-convex input, the 1% of the
 * distance GEOS lets itself simplify the input by before buffering.  Two
 * kinds of disagreement are counted apart and printed, not failed: where
 * an edge meets an arc's chord at a grazing angle the boundaries' distance
 * exceeds the tolerance while the regions do not (no part of their
 * symmetric difference wider than twice the tolerance); and where GEOS's
 * buffer is wrong (it drops the offset of some spikes, narrow holes and
 * short first segments), which the definition of the offset settles at a
 * point inside each piece of the difference. */
#define SHAPES_WITH_GEOS
#include "polygon_shapes.h"
#include "check.h"

#include <stdarg.h>
#include <stdio.h>

static GEOSContextHandle_t geos;
static void geos_message(const char *fmt, ...)
{
    (void)fmt;
}

#define QUADRANT_SEGMENTS 64

static const int geos_join[] = {GEOSBUF_JOIN_MITRE, GEOSBUF_JOIN_ROUND, 0, GEOSBUF_JOIN_BEVEL};
static const char *const join_name[] = {"miter", "round", "square", "bevel"};

/* The GEOS buffer's chord error at distance d. */
static double geos_chord_error(double d)
{
    return d * (1 - cos(M_PI / (4 * QUADRANT_SEGMENTS)));
}

typedef struct comparison {
    double hausdorff, area_cg, area_geos, length;
    int valid;
} comparison;

/* cg's result against GEOS's buffer of the same input. */
static comparison compare(const cg_polygon_set *result, GEOSGeometry *expected)
{
    comparison c = {0};
    GEOSGeometry *mine = shapes_geos_polygons(geos, result);
    c.valid = GEOSisValid_r(geos, mine) == 1;
    GEOSArea_r(geos, mine, &c.area_cg);
    GEOSArea_r(geos, expected, &c.area_geos);
    GEOSGeometry *b1 = GEOSBoundary_r(geos, mine), *b2 = GEOSBoundary_r(geos, expected);
    GEOSLength_r(geos, b2, &c.length);
    if (GEOSisEmpty_r(geos, b1) || GEOSisEmpty_r(geos, b2))
        c.hausdorff = GEOSisEmpty_r(geos, b1) == GEOSisEmpty_r(geos, b2) ? 0 : INFINITY;
    else
        GEOSHausdorffDistanceDensify_r(geos, b1, b2, 0.1, &c.hausdorff);
    GEOSGeom_destroy_r(geos, b1);
    GEOSGeom_destroy_r(geos, b2);
    GEOSGeom_destroy_r(geos, mine);
    return c;
}

/* The shortest edge of the set's rings (closed or open). */
static double shortest_edge(const cg_polygon_set *set, int closed)
{
    double m = INFINITY;
    for (size_t r = 0; r < set->ring_count; r++) {
        size_t a = set->ring_start[r], b = set->ring_start[r + 1];
        for (size_t i = a; i + (closed ? 0 : 1) < b; i++) {
            cg_vec2 p = set->points[i], q = set->points[i + 1 < b ? i + 1 : a];
            m = fmin(m, hypot(q.x - p.x, q.y - p.y));
        }
    }
    return m;
}

/* The distance from x to the nearest edge of the set whose perpendicular
 * foot from x falls inside the edge (infinite when none does). */
static double edge_distance(const cg_polygon_set *set, int closed, double x, double y)
{
    double m = INFINITY;
    for (size_t r = 0; r < set->ring_count; r++) {
        size_t a = set->ring_start[r], b = set->ring_start[r + 1];
        for (size_t i = a; i + (closed ? 0 : 1) < b; i++) {
            cg_vec2 p = set->points[i], q = set->points[i + 1 < b ? i + 1 : a];
            double dx = q.x - p.x, dy = q.y - p.y, l2 = dx * dx + dy * dy;
            double t = ((x - p.x) * dx + (y - p.y) * dy) / l2;
            if (l2 > 0 && t > 0 && t < 1)
                m = fmin(m, fabs((x - p.x) * dy - (y - p.y) * dx) / sqrt(l2));
        }
    }
    return m;
}

/* What the definition of an offset by delta says of a point: 1 it belongs,
 * 0 it does not, -1 it depends on the join.  A point belongs when it is in
 * the polygons or within d of an edge (beside it) and delta > 0; it does
 * not when it is farther than `reach` (the farthest a join reaches) from
 * them.  Deflating (delta < 0) turns both round inside the polygons.  With
 * round joins and caps (reach d) the offset is exactly the points within d. */
static int definition_says(const cg_polygon_set *input, GEOSGeometry *geometry, int lines,
                           double delta, double reach, double tolerance, GEOSGeometry *point)
{
    double x, y, distance;
    GEOSGeomGetX_r(geos, point, &x);
    GEOSGeomGetY_r(geos, point, &y);
    GEOSGeometry *boundary = lines ? GEOSGeom_clone_r(geos, geometry)
                                   : GEOSBoundary_r(geos, geometry);
    GEOSDistance_r(geos, point, boundary, &distance);
    GEOSGeom_destroy_r(geos, boundary);
    double beside = edge_distance(input, !lines, x, y), d = fabs(delta);
    int inside = !lines && GEOSContains_r(geos, geometry, point) == 1;
    if (reach == d) /* round: exactly the points within d */
        beside = distance;
    if (delta > 0) {
        if (inside || beside < d - tolerance)
            return 1;
        return distance > reach + tolerance ? 0 : -1;
    }
    if (!inside || beside < d - tolerance)
        return 0;
    return distance > reach + tolerance ? 1 : -1;
}

/* Where cg and GEOS disagree, the definition decides: 1 when every piece
 * of the disagreement wider than the tolerance has a point where it says
 * cg is right and GEOS wrong. */
static int definition_sides_with_cg(const cg_polygon_set *input, GEOSGeometry *geometry, int lines,
                                    const cg_polygon_set *result, GEOSGeometry *expected,
                                    double delta, double reach, double tolerance)
{
    GEOSGeometry *mine = shapes_geos_polygons(geos, result);
    GEOSGeometry *diff = GEOSSymDifference_r(geos, mine, expected);
    GEOSGeometry *wide = GEOSBuffer_r(geos, diff, -2 * tolerance, 8);
    int ok = 1, pieces = GEOSGetNumGeometries_r(geos, wide);
    for (int k = 0; k < pieces && ok; k++) {
        GEOSGeometry *point = GEOSPointOnSurface_r(geos, GEOSGetGeometryN_r(geos, wide, k));
        int says = definition_says(input, geometry, lines, delta, reach, tolerance, point);
        ok = says >= 0 && says == (GEOSContains_r(geos, mine, point) == 1)
             && says != (GEOSContains_r(geos, expected, point) == 1);
        GEOSGeom_destroy_r(geos, point);
    }
    GEOSGeom_destroy_r(geos, wide);
    GEOSGeom_destroy_r(geos, diff);
    GEOSGeom_destroy_r(geos, mine);
    return ok && pieces > 0;
}

static long geos_overruled, grazing;

/* 1 when no part of the symmetric difference of the result and expected
 * is wider than twice the tolerance (nothing is left of it once eroded by
 * the tolerance). */
static int thinner_than(const cg_polygon_set *result, GEOSGeometry *expected, double tolerance)
{
    GEOSGeometry *mine = shapes_geos_polygons(geos, result);
    GEOSGeometry *diff = GEOSSymDifference_r(geos, mine, expected);
    GEOSGeometry *wide = GEOSBuffer_r(geos, diff, -tolerance, 8);
    int thin = GEOSisEmpty_r(geos, wide) == 1;
    GEOSGeom_destroy_r(geos, wide);
    GEOSGeom_destroy_r(geos, diff);
    GEOSGeom_destroy_r(geos, mine);
    return thin;
}

/* cg's result against GEOS's; a disagreement the definition settles for
 * cg is counted apart, not as a failure: GEOS's buffer drops the offset of
 * some spikes, narrow holes and short first segments. */
static void check_against(const char *what, int trial, const cg_polygon_set *result,
                          GEOSGeometry *expected, double tolerance, const cg_polygon_set *input,
                          GEOSGeometry *geometry, int lines, double delta, double reach)
{
    comparison c = compare(result, expected);
    CHECK_MSG(c.valid, "%s trial %d: result not valid", what, trial);
    int areas_agree = fabs(c.area_cg - c.area_geos) <= c.length * tolerance + 1e-9;
    int close = c.hausdorff <= tolerance && areas_agree;
    if (!close && areas_agree && thinner_than(result, expected, tolerance)) {
        /* a vertex where an offset edge meets a chord of an arc at a
         * grazing angle moves along the edge by the chord's error divided by
         * the sine of that angle: the Hausdorff distance grows there while
         * the two regions stay within the tolerance of each other */
        grazing++;
        return;
    }
    if (!close
        && definition_sides_with_cg(input, geometry, lines, result, expected, delta, reach,
                                    tolerance)) {
        geos_overruled++;
        return;
    }
    CHECK_MSG(c.hausdorff <= tolerance, "%s trial %d: Hausdorff %.3g > %.3g", what, trial,
              c.hausdorff, tolerance);
    CHECK_MSG(fabs(c.area_cg - c.area_geos) <= c.length * tolerance + 1e-9,
              "%s trial %d: area %.9g, GEOS %.9g (perimeter %.4g, tolerance %.3g)", what, trial,
              c.area_cg, c.area_geos, c.length, tolerance);
}

/* A random polygon: a star (counter-clockwise) with, half the time, a star
 * hole (clockwise); in cg as two paths, in GEOS as one polygon. */
static GEOSGeometry *random_polygon(cg_polygon_set *set, int convex, int allow_hole)
{
    cg_vec2 outer[40], hole[20];
    int n = 5 + (int)(shapes_uniform() * 30), m = 4 + (int)(shapes_uniform() * 12);
    int with_hole = allow_hole && shapes_uniform() < 0.5;
    cg_vec2 c = {shapes_between(-50, 50), shapes_between(-50, 50)};
    if (convex)
        shapes_convex(outer, n, c, 20, 0);
    else
        shapes_star(outer, n, c, 10, 20, 0);
    cg_polygon_set_clear(set);
    cg_polygon_set_add_ring(set, outer, (size_t)n, 1);
    GEOSGeometry *shell = shapes_geos_ring(geos, outer, (size_t)n, 1), *holes[1];
    if (with_hole) {
        if (convex)
            shapes_convex(hole, m, c, 5, 1);
        else
            shapes_star(hole, m, c, 2, 6, 1);
        cg_polygon_set_add_ring(set, hole, (size_t)m, 1);
        holes[0] = shapes_geos_ring(geos, hole, (size_t)m, 1);
    }
    return GEOSGeom_createPolygon_r(geos, shell, holes, with_hole ? 1 : 0);
}

static void polygons_vs_geos(void)
{
    static const double deltas[] = {0.3, 1, 2.5, 6, -0.3, -1, -2.5, -6};
    cg_polygon_set input = {0}, result = {0};
    for (int trial = 0; trial < 240; trial++) {
        int convex = trial % 3 == 0;
        double delta = deltas[trial % 8];
        int join = (int)(shapes_uniform() * 4);
        if (join == CG_OFFSET_JOIN_SQUARE)
            join = CG_OFFSET_JOIN_ROUND;
        /* GEOS's miter and bevel offsets next to an edge shorter than half
         * the distance are not trusted: such inputs are drawn again */
        GEOSGeometry *g = random_polygon(&input, convex, 1);
        while (join != CG_OFFSET_JOIN_ROUND && shortest_edge(&input, 1) < fabs(delta) / 2) {
            GEOSGeom_destroy_r(geos, g);
            g = random_polygon(&input, convex, 1);
        }
        double limit = shapes_between(1.2, 6), d = fabs(delta);
        cg_offset_options o = cg_offset_options_default();
        o.join = (cg_offset_join)join;
        o.miter_limit = limit;
        o.arc_tolerance = d / 1000;
        cg_status st = cg_offset(&input, delta, &o, 0, &result);
        CHECK_MSG(st == CG_OK, "trial %d: %s", trial, cg_status_str(st));
        GEOSGeometry *expected = GEOSBufferWithStyle_r(geos, g, delta, QUADRANT_SEGMENTS,
                                                       GEOSBUF_CAP_ROUND, geos_join[join], limit);
        double tolerance = o.arc_tolerance + geos_chord_error(d) + (convex ? 0 : 0.01 * d) + 1e-6;
        char what[64];
        snprintf(what, sizeof what, "%s %+g limit %.3g%s", join_name[join], delta, limit,
                 convex ? " convex" : "");
        long before = check_failed;
        double reach = join == CG_OFFSET_JOIN_MITER   ? limit * d
                       : join == CG_OFFSET_JOIN_ROUND ? d
                                                      : 1.5 * d;
        check_against(what, trial, &result, expected, tolerance, &input, g, 0, delta, reach);
        if (getenv("DUMP") && check_failed > before) {
            char *text = GEOSGeomToWKT_r(geos, g);
            fprintf(stderr, "  input %s\n", text);
            GEOSFree_r(geos, text);
        }
        GEOSGeom_destroy_r(geos, expected);
        GEOSGeom_destroy_r(geos, g);
    }
    cg_polygon_set_clear(&input);
    cg_polygon_set_clear(&result);
}

/* Random walks (crossing themselves at times) widened with every cap. */
static void lines_vs_geos(void)
{
    static const int caps[] = {CG_OFFSET_END_BUTT, CG_OFFSET_END_SQUARE, CG_OFFSET_END_ROUND};
    static const int geos_caps[] = {GEOSBUF_CAP_FLAT, GEOSBUF_CAP_SQUARE, GEOSBUF_CAP_ROUND};
    cg_polygon_set input = {0}, result = {0};
    for (int trial = 0; trial < 180; trial++) {
        cg_vec2 walk[30];
        int n = 2 + (int)(shapes_uniform() * 28);
        int cap = trial % 3, join = (int)(shapes_uniform() * 4);
        if (join == CG_OFFSET_JOIN_SQUARE)
            join = CG_OFFSET_JOIN_BEVEL;
        double d = shapes_between(0.2, 3), limit = shapes_between(1.2, 5);
        do { /* as above: no edge shorter than d/2 unless all is round */
            walk[0] = cg_vec2_make(shapes_between(-10, 10), shapes_between(-10, 10));
            for (int i = 1; i < n; i++)
                walk[i] = cg_vec2_make(walk[i - 1].x + shapes_between(-8, 8),
                                       walk[i - 1].y + shapes_between(-8, 8));
            cg_polygon_set_clear(&input);
            cg_polygon_set_add_ring(&input, walk, (size_t)n, 1);
        } while ((join != CG_OFFSET_JOIN_ROUND || cap != 2) && shortest_edge(&input, 0) < d / 2);
        cg_offset_options o = cg_offset_options_default();
        o.join = (cg_offset_join)join;
        o.end = (cg_offset_end)caps[cap];
        o.miter_limit = limit;
        o.arc_tolerance = d / 1000;
        cg_status st = cg_offset(&input, d, &o, 0, &result);
        CHECK_MSG(st == CG_OK, "trial %d: %s", trial, cg_status_str(st));
        GEOSGeometry *line = shapes_geos_ring(geos, walk, (size_t)n, 0);
        GEOSGeometry *expected = GEOSBufferWithStyle_r(geos, line, d, QUADRANT_SEGMENTS,
                                                       geos_caps[cap], geos_join[join], limit);
        char what[64];
        snprintf(what, sizeof what, "line %s cap %d", join_name[join], cap);
        long before = check_failed;
        check_against(what, trial, &result, expected,
                      o.arc_tolerance + geos_chord_error(d) + 0.01 * d + 1e-6, &input, line, 1, d,
                      (join == CG_OFFSET_JOIN_MITER               ? limit
                       : join == CG_OFFSET_JOIN_ROUND && cap == 2 ? 1
                                                                  : 1.5)
                          * d);
        if (getenv("DUMP") && check_failed > before) {
            char *text = GEOSGeomToWKT_r(geos, line);
            fprintf(stderr, "  input %s d %.17g limit %.17g\n", text, d, limit);
            GEOSFree_r(geos, text);
        }
        GEOSGeom_destroy_r(geos, expected);
        GEOSGeom_destroy_r(geos, line);
    }
    cg_polygon_set_clear(&input);
    cg_polygon_set_clear(&result);
}

/* The area of the symmetric difference of a and b. */
static double xor_area(const cg_polygon_set *a, const cg_polygon_set *b)
{
    cg_polygon_set x = {0};
    cg_clip_boolean(CG_CLIP_XOR, a, CG_CLIP_NON_ZERO, b, CG_CLIP_NON_ZERO, 0, &x);
    double area = fabs(cg_polygon_set_area(&x));
    cg_polygon_set_clear(&x);
    return area;
}

/* Convex polygons with convex holes (no feature narrower than 2d): +d then
 * -d with miter joins gives the polygon back (corners within the limit);
 * with round joins the same within the arc tolerance along the boundary. */
static void inflate_then_deflate(void)
{
    cg_polygon_set input = {0}, simple = {0}, grown = {0}, back = {0};
    for (int trial = 0; trial < 120; trial++) {
        int round = trial % 2;
        /* round joins round a hole's corners when deflating: holes only
         * with miter joins */
        GEOSGeometry *g = random_polygon(&input, 1, !round);
        double perimeter;
        GEOSLength_r(geos, g, &perimeter);
        GEOSGeom_destroy_r(geos, g);
        /* the hole's radius is 5 and its inradius at least 2.5 */
        double d = shapes_between(0.1, 2.4);
        cg_offset_options o = cg_offset_options_default();
        o.join = round ? CG_OFFSET_JOIN_ROUND : CG_OFFSET_JOIN_MITER;
        o.miter_limit = 10; /* interior angles >= 60 degrees need 2 */
        o.arc_tolerance = d / 1000;
        cg_offset(&input, 0, &o, 0, &simple);
        CHECK(cg_offset(&input, d, &o, 0, &grown) == CG_OK);
        CHECK(cg_offset(&grown, -d, &o, 0, &back) == CG_OK);
        double error = xor_area(&simple, &back);
        double bound = perimeter * (round ? 2 * o.arc_tolerance : 1e-6);
        CHECK_MSG(error <= bound, "trial %d (%s, d %g): area of difference %.3g > %.3g", trial,
                  round ? "round" : "miter", d, error, bound);
        CHECK_MSG(simple.polygon_count == back.polygon_count
                      && simple.ring_count == back.ring_count,
                  "trial %d: %zu rings back from %zu", trial, back.ring_count, simple.ring_count);
        if (getenv("DUMP") && back.ring_count != simple.ring_count)
            for (size_t r = 0; r < back.ring_count; r++)
                fprintf(stderr, "  ring %zu: %zu points, area %g\n", r,
                        back.ring_start[r + 1] - back.ring_start[r],
                        cg_polygon_set_ring_area(&back, r));
    }
    cg_polygon_set_clear(&input);
    cg_polygon_set_clear(&simple);
    cg_polygon_set_clear(&grown);
    cg_polygon_set_clear(&back);
}

int main(int argc, char **argv)
{
    geos = GEOS_init_r();
    GEOSContext_setNoticeHandler_r(geos, geos_message);
    GEOSContext_setErrorHandler_r(geos, geos_message);
    check_start(argc, argv);
    CHECK_GROUP(polygons_vs_geos);
    CHECK_GROUP(lines_vs_geos);
    CHECK_GROUP(inflate_then_deflate);
    if (grazing)
        printf("%ld results within the tolerance of GEOS's as regions but not as boundaries "
               "(grazing intersections)\n",
               grazing);
    if (geos_overruled)
        printf("%ld disagreements with GEOS settled for cg by the distance definition\n",
               geos_overruled);
    GEOS_finish_r(geos);
    return check_finish();
}
