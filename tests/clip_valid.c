/* Every result of cg_clip_boolean is valid in the OGC Simple Features sense,
 * as GEOS's GEOSisValid judges it: simple rings (no ring touches itself),
 * holes inside their outer ring touching it at most at single points, polygons
 * whose interiors do not overlap.  The inputs are random self-intersecting
 * and touching rings on small grids under every fill rule and operation;
 * the results also keep the area the definition gives (checked through the
 * identities between the operations and against the winding numbers at
 * random points away from the input edges). */
#include "cg/clip.h"
#include "check.h"

#include "clip_geos_shapes.h"

#include <stdarg.h>
#include <string.h>

/* the winding number of (x, y) for the rings of s (counter-clockwise +1) */
static int winding(const cg_polygon_set *s, double x, double y)
{
    int w = 0;
    for (size_t r = 0; r < s->ring_count; r++) {
        size_t a = s->ring_start[r], b = s->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_vec2 p = s->points[i], q = s->points[i + 1 < b ? i + 1 : a];
            double c = (q.x - p.x) * (y - p.y) - (x - p.x) * (q.y - p.y);
            if (p.y <= y && q.y > y && c > 0)
                w++;
            else if (p.y > y && q.y <= y && c < 0)
                w--;
        }
    }
    return w;
}

static int filled(int w, cg_clip_fill f)
{
    switch (f) {
    case CG_CLIP_EVEN_ODD: return w & 1;
    case CG_CLIP_NON_ZERO: return w != 0;
    case CG_CLIP_POSITIVE: return w > 0;
    default: return w < 0;
    }
}

static int in_op(cg_clip_op op, int a, int b)
{
    switch (op) {
    case CG_CLIP_INTERSECTION: return a && b;
    case CG_CLIP_UNION: return a || b;
    case CG_CLIP_DIFFERENCE: return a && !b;
    default: return a != b;
    }
}

/* distance from (x, y) to the nearest edge of s */
static double edge_distance(const cg_polygon_set *s, double x, double y)
{
    double best = INFINITY;
    for (size_t r = 0; r < s->ring_count; r++) {
        size_t a = s->ring_start[r], b = s->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_vec2 p = s->points[i], q = s->points[i + 1 < b ? i + 1 : a];
            double dx = q.x - p.x, dy = q.y - p.y, l = dx * dx + dy * dy;
            double t = l > 0 ? ((x - p.x) * dx + (y - p.y) * dy) / l : 0;
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            double ex = p.x + t * dx - x, ey = p.y + t * dy - y, d = sqrt(ex * ex + ey * ey);
            if (d < best)
                best = d;
        }
    }
    return best;
}

/* the summed length of the rings of s */
static double perimeter(const cg_polygon_set *s)
{
    double l = 0;
    for (size_t r = 0; r < s->ring_count; r++) {
        size_t a = s->ring_start[r], b = s->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_vec2 p = s->points[i], q = s->points[i + 1 < b ? i + 1 : a];
            l += hypot(q.x - p.x, q.y - p.y);
        }
    }
    return l;
}

/* 1-3 random rings of 3 to `most` (at most 64) vertices on an n x n grid
 * scaled by `unit` (crossings, shared vertices and edges, repeated and
 * collinear points) */
static void random_rings(check_rng *rng, cg_polygon_set *s, int n, double unit, int most)
{
    int rings = (int)check_rng_int(rng, 1, 3);
    for (int r = 0; r < rings; r++) {
        cg_vec2 p[64];
        int m = (int)check_rng_int(rng, 3, most);
        for (int i = 0; i < m; i++)
            p[i] = cg_vec2_make(unit * (double)check_rng_int(rng, 0, n),
                                unit * (double)check_rng_int(rng, 0, n));
        cg_polygon_set_add_ring(s, p, (size_t)m, 1);
    }
}

static long invalid_reported;

static void check_valid(GEOSContextHandle_t h, const cg_polygon_set *r, int round, int op)
{
    GEOSGeometry *g = clip_geos_polygons(h, r);
    char valid = g ? GEOSisValid_r(h, g) : 0;
    if (valid != 1 && invalid_reported++ < 10) {
        char *why = g ? GEOSisValidReason_r(h, g) : NULL;
        char *wkt = g ? GEOSGeomToWKT_r(h, g) : NULL;
        fprintf(stderr, "round %d op %d: %s\n  %s\n", round, op, why ? why : "?", wkt ? wkt : "");
        GEOSFree_r(h, why);
        GEOSFree_r(h, wkt);
    }
    CHECK_MSG(valid == 1, "round %d op %d: result not valid (GEOSisValid)", round, op);
    if (g)
        GEOSGeom_destroy_r(h, g);
}

int main(void)
{
    GEOSContextHandle_t h = clip_geos_start();
    check_rng rng = {0x5eed0f0e};
    static const int grids[] = {2, 3, 4, 5, 8, 16};
    long results = 0, cleaned = 0, points = 0;
    static const int crowded[] = {12, 40, 100, 400};
    for (int round = 0; round < 4400; round++) {
        /* the last 400 rounds crowded: rings of up to 64 vertices on grids
         * of 12 to 400 units (many active edges, complete snap rounding) */
        int big = round >= 4000;
        int n = big ? crowded[round % 4] : grids[round % 6], most = big ? 64 : 9;
        /* unscaled: every crossing rounded to the grid, edges collapsing;
         * scaled by 1024: the rounding small against the features, so the
         * membership of points away from the edges is the definition's */
        double unit = (round / 6) % 2 ? 1024 : 1;
        cg_polygon_set a = {0}, b = {0};
        random_rings(&rng, &a, n, unit, most);
        if (check_rng_int(&rng, 0, 5))
            random_rings(&rng, &b, n, unit, most);
        cg_clip_fill fa = (cg_clip_fill)check_rng_int(&rng, 0, 3);
        cg_clip_fill fb = (cg_clip_fill)check_rng_int(&rng, 0, 3);
        cg_polygon_set r[4] = {{0}};
        double area[4];
        for (int op = 0; op < 4; op++) {
            CHECK(cg_clip_boolean((cg_clip_op)op, &a, fa, &b, fb, 1, &r[op]) == CG_OK);
            check_valid(h, &r[op], round, op);
            area[op] = cg_polygon_set_area(&r[op]);
            results++;
        }
        /* |A u B| = |A| + |B| - |A n B|, xor = union - intersection,
         * difference = |A| - |A n B| (|A|, |B| as each operand cleaned),
         * within what rounding the crossings to the unit grid can move: a
         * unit along each input edge, twice */
        cg_polygon_set ca = {0}, cb = {0};
        CHECK(cg_clip_boolean(CG_CLIP_UNION, &a, fa, NULL, CG_CLIP_EVEN_ODD, 1, &ca) == CG_OK);
        CHECK(cg_clip_boolean(CG_CLIP_UNION, &b, fb, NULL, CG_CLIP_EVEN_ODD, 1, &cb) == CG_OK);
        check_valid(h, &ca, round, 4);
        check_valid(h, &cb, round, 5);
        cleaned += 2;
        double aa = cg_polygon_set_area(&ca), ab = cg_polygon_set_area(&cb);
        double tol = 2 * (perimeter(&a) + perimeter(&b));
        CHECK_NEAR(area[1], aa + ab - area[0], tol);
        CHECK_NEAR(area[3], area[1] - area[0], tol);
        CHECK_NEAR(area[2], aa - area[0], tol);
        if (unit > 1) {
            for (int s = 0; s < 12; s++) {
                double x = check_rng_range(&rng, -0.5, n + 0.5) * unit;
                double y = check_rng_range(&rng, -0.5, n + 0.5) * unit;
                if (edge_distance(&a, x, y) < 4 || (b.ring_count && edge_distance(&b, x, y) < 4))
                    continue;
                int ia = filled(winding(&a, x, y), fa), ib = filled(winding(&b, x, y), fb);
                for (int op = 0; op < 4; op++)
                    CHECK_MSG((winding(&r[op], x, y) != 0) == in_op((cg_clip_op)op, ia, ib),
                              "round %d op %d point %g %g", round, op, x, y);
                points++;
            }
        }
        for (int op = 0; op < 4; op++)
            cg_polygon_set_clear(&r[op]);
        cg_polygon_set_clear(&ca);
        cg_polygon_set_clear(&cb);
        cg_polygon_set_clear(&a);
        cg_polygon_set_clear(&b);
    }
    printf("GEOS validity: %ld results and %ld cleaned operands checked, %ld points compared\n",
           results, cleaned, points);
    GEOS_finish_r(h);
    return check_finish();
}
