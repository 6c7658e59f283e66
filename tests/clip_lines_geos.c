/* Open paths clipped against polygons, read back by GEOS: for random regions
 * (star polygons with holes, made simple by cg's union so that GEOS accepts
 * them) and random self-crossing polylines, some running along the
 * region's edges and through its vertices, the pieces of cg's intersection
 * and difference, as point sets, have the lengths of GEOSIntersection's
 * and GEOSDifference's (within the grid's rounding), with multiplicity
 * they add up to the paths' length, and the midpoint of every
 * segment of a piece is covered by the region (intersection) or lies off it
 * (difference), as GEOS's point-in-polygon says. */
#define SHAPES_WITH_GEOS
#include "polygon_shapes.h"
#include "check.h"

static GEOSContextHandle_t geos;
/* Polylines: random points, and stretches along the region's boundary
 * (from one vertex of a ring to a later one, so edges are run along and
 * vertices passed through). */
static void random_paths(cg_polygon_set *paths, const cg_polygon_set *region)
{
    cg_polygon_set_clear(paths);
    int count = 1 + (int)(shapes_uniform() * 3);
    for (int k = 0; k < count; k++) {
        cg_vec2 p[40];
        int n = 2 + (int)(shapes_uniform() * 30);
        for (int i = 0; i < n; i++) {
            p[i] = cg_vec2_make(shapes_between(-60, 60), shapes_between(-60, 60));
            if (region->point_count > 0 && shapes_uniform() < 0.4)
                p[i] = region->points[(size_t)(shapes_uniform() * (double)region->point_count)];
        }
        if (region->ring_count > 0 && k == 0) {
            size_t r = (size_t)(shapes_uniform() * (double)region->ring_count);
            size_t a = region->ring_start[r], len = region->ring_start[r + 1] - a;
            size_t from = (size_t)(shapes_uniform() * (double)len);
            for (int i = 0; i < n; i++) /* a run along the ring */
                if (i < 12)
                    p[i] = region->points[a + (from + (size_t)i) % len];
        }
        cg_polygon_set_add_ring(paths, p, (size_t)n, 1);
    }
}

static double geos_length(GEOSGeometry *g)
{
    double length = -1;
    if (g)
        GEOSLength_r(geos, g, &length);
    return length;
}

static double cg_length(const cg_polygon_set *s)
{
    double total = 0;
    for (size_t r = 0; r < s->ring_count; r++)
        for (size_t i = s->ring_start[r]; i + 1 < s->ring_start[r + 1]; i++)
            total += hypot(s->points[i + 1].x - s->points[i].x,
                           s->points[i + 1].y - s->points[i].y);
    return total;
}

static long judged, unjudged;

/* The midpoints of every segment of the pieces against GEOS. */
static void check_midpoints(const cg_polygon_set *pieces, const GEOSPreparedGeometry *prepared,
                            const GEOSGeometry *boundary, int inside, int trial)
{
    for (size_t r = 0; r < pieces->ring_count; r++)
        for (size_t i = pieces->ring_start[r]; i + 1 < pieces->ring_start[r + 1]; i++) {
            cg_vec2 a = pieces->points[i], b = pieces->points[i + 1];
            GEOSGeometry *m = GEOSGeom_createPointFromXY_r(geos, (a.x + b.x) / 2, (a.y + b.y) / 2);
            double distance = 0;
            GEOSDistance_r(geos, m, boundary, &distance);
            if (distance < 1e-6) {
                unjudged++; /* on the boundary, or too near it for doubles */
                GEOSGeom_destroy_r(geos, m);
                continue;
            }
            judged++;
            int covered = GEOSPreparedCovers_r(geos, prepared, m) == 1;
            CHECK_MSG(covered == inside, "trial %d: piece %zu segment %zu %s", trial, r, i,
                      inside ? "outside" : "inside");
            GEOSGeom_destroy_r(geos, m);
        }
}

static void against_geos(void)
{
    cg_polygon_set region = {0}, paths = {0}, in = {0}, out = {0};
    for (int trial = 0; trial < 300; trial++) {
        shapes_random_region(&region, 1);
        random_paths(&paths, &region);
        CHECK(cg_clip_lines(CG_CLIP_INTERSECTION, &paths, &region, CG_CLIP_NON_ZERO, 0, &in)
              == CG_OK);
        CHECK(cg_clip_lines(CG_CLIP_DIFFERENCE, &paths, &region, CG_CLIP_NON_ZERO, 0, &out)
              == CG_OK);
        GEOSGeometry *g = shapes_geos_polygons(geos, &region);
        GEOSGeometry *lines = shapes_geos_lines(geos, &paths);
        GEOSGeometry *gi = GEOSIntersection_r(geos, lines, g);
        GEOSGeometry *gd = GEOSDifference_r(geos, lines, g);
        /* the grid is 2^-36 of the largest coordinate (about 1e-9 here):
         * each piece's ends within a grid unit.  GEOS gives point sets (a
         * stretch the paths run twice counts once), so cg's pieces are
         * compared as the union GEOS makes of them, and as they are with
         * the path's own length. */
        double tolerance = 1e-8 * (double)(in.ring_count + out.ring_count + 1);
        GEOSGeometry *mine_in = shapes_geos_lines(geos, &in),
                     *mine_out = shapes_geos_lines(geos, &out);
        GEOSGeometry *set_in = GEOSUnaryUnion_r(geos, mine_in);
        GEOSGeometry *set_out = GEOSUnaryUnion_r(geos, mine_out);
        CHECK_MSG(fabs(geos_length(set_in) - geos_length(gi)) <= tolerance,
                  "trial %d: intersection length %.17g, GEOS %.17g", trial, geos_length(set_in),
                  geos_length(gi));
        CHECK_MSG(fabs(geos_length(set_out) - geos_length(gd)) <= tolerance,
                  "trial %d: difference length %.17g, GEOS %.17g", trial, geos_length(set_out),
                  geos_length(gd));
        CHECK_MSG(fabs(cg_length(&in) + cg_length(&out) - cg_length(&paths)) <= tolerance,
                  "trial %d: pieces %.17g + %.17g, paths %.17g", trial, cg_length(&in),
                  cg_length(&out), cg_length(&paths));
        GEOSGeom_destroy_r(geos, set_in);
        GEOSGeom_destroy_r(geos, set_out);
        GEOSGeom_destroy_r(geos, mine_in);
        GEOSGeom_destroy_r(geos, mine_out);
        const GEOSPreparedGeometry *prepared = GEOSPrepare_r(geos, g);
        GEOSGeometry *boundary = GEOSBoundary_r(geos, g);
        check_midpoints(&in, prepared, boundary, 1, trial);
        check_midpoints(&out, prepared, boundary, 0, trial);
        GEOSPreparedGeom_destroy_r(geos, prepared);
        GEOSGeom_destroy_r(geos, boundary);
        GEOSGeom_destroy_r(geos, gi);
        GEOSGeom_destroy_r(geos, gd);
        GEOSGeom_destroy_r(geos, lines);
        GEOSGeom_destroy_r(geos, g);
    }
    printf("   %ld midpoints judged by GEOS, %ld on or within 1e-6 of the boundary\n", judged,
           unjudged);
    CHECK(judged > 4 * unjudged); /* the runs along edges are on it */
    cg_polygon_set_clear(&region);
    cg_polygon_set_clear(&paths);
    cg_polygon_set_clear(&in);
    cg_polygon_set_clear(&out);
}

int main(int argc, char **argv)
{
    geos = shapes_geos_start();
    check_start(argc, argv);
    CHECK_GROUP(against_geos);
    GEOS_finish_r(geos);
    return check_finish();
}
