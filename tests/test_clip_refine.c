/* Triangulations refined to a minimum angle, against the definition, exactly
 * (coordinates below 2^20, so this test's own in-circle determinant fits in
 * 128 bits): every triangle counter-clockwise with positive area; twice
 * their areas sum exactly to twice the region's (the union of the input);
 * every directed triangle edge lies on a ring edge or is met by its
 * reverse, and the triangle edges along each ring edge cover it exactly
 * (so the points added on it lie on it and the triangles tile the region);
 * every edge not on a ring edge is locally Delaunay (the triangulation of
 * all the vertices is constrained Delaunay); and every triangle's smallest
 * angle is at least the bound, except where that angle lies at a vertex
 * where two ring edges meet at less than 60 degrees (for self-crossing
 * rings, whose crossings are rounded to the grid so that an edge may have
 * no grid point to split it at, those below the bound are counted, not
 * failed).  Inputs: random star
 * polygons with holes, random self-crossing rings, combs (sharp input
 * angles), a square with touching square holes; bounds 5 to 30 degrees. */
#include "polygon_shapes.h"
#include "check.h"

__extension__ typedef __int128 i128;

static i128 dot(cg_point64 a, cg_point64 b, cg_point64 c) /* (b - a) . (c - a) */
{
    return (i128)(b.x - a.x) * (c.x - a.x) + (i128)(b.y - a.y) * (c.y - a.y);
}

static int same(cg_point64 a, cg_point64 b)
{
    return a.x == b.x && a.y == b.y;
}

static int in_circle(cg_point64 a, cg_point64 b, cg_point64 c, cg_point64 d)
{
    i128 adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
    i128 cdx = c.x - d.x, cdy = c.y - d.y;
    return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
               + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
               + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady)
           > 0;
}

/* The angle (degrees) at v of the triangle v, a, b. */
static double angle_at(cg_point64 v, cg_point64 a, cg_point64 b)
{
    double c = (double)shapes_cross64(v, a, b), d = (double)dot(v, a, b);
    return atan2(fabs(c), d) * 180 / M_PI;
}

/* Whether v is a vertex of the rings where two ring edges meet at less than
 * 60 degrees. */
static int sharp_vertex(const cg_polygon_set64 *rings, cg_point64 v)
{
    cg_point64 ends[64];
    int n = 0;
    for (size_t r = 0; r < rings->ring_count; r++) {
        size_t a = rings->ring_start[r], b = rings->ring_start[r + 1];
        for (size_t i = a; i < b && n < 62; i++)
            if (same(rings->points[i], v)) {
                ends[n++] = rings->points[i + 1 < b ? i + 1 : a];
                ends[n++] = rings->points[i > a ? i - 1 : b - 1];
            }
    }
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (angle_at(v, ends[i], ends[j]) < 60)
                return 1;
    return 0;
}

/* The ring edge containing the directed edge p-q (collinear, within it, in
 * its direction): 1 when there is one. */
static int on_ring_edge(const cg_polygon_set64 *rings, cg_point64 p, cg_point64 q)
{
    for (size_t r = 0; r < rings->ring_count; r++) {
        size_t a = rings->ring_start[r], b = rings->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_point64 u = rings->points[i], v = rings->points[i + 1 < b ? i + 1 : a];
            i128 l = dot(u, v, v);
            if (shapes_cross64(u, v, p) == 0 && shapes_cross64(u, v, q) == 0 && dot(u, v, p) >= 0
                && dot(u, v, q) <= l && dot(u, v, q) > dot(u, v, p))
                return 1;
        }
    }
    return 0;
}

static long total_triangles, sharp_exceptions, whole_exceptions;

/* Euclid's algorithm, recursively: a segment of steps (dx, dy) has a grid
 * point inside exactly when gcd(dx, dy) > 1. */
static int64_t gcd(int64_t a, int64_t b)
{
    return b == 0 ? (a < 0 ? -a : a) : gcd(b, a % b);
}

/* Whether a vertex of triangle p is an end of a triangle edge along a ring
 * edge with no grid point inside (which cannot be split). */
static int near_whole_piece(const cg_polygon_set64 *tri, const cg_polygon_set64 *rings,
                            const cg_point64 *p)
{
    for (size_t t = 0; t < tri->ring_count; t++) {
        const cg_point64 *q = tri->points + tri->ring_start[t];
        for (int k = 0; k < 3; k++) {
            cg_point64 a = q[k], b = q[(k + 1) % 3];
            if (gcd(b.x - a.x, b.y - a.y) >= 2 || !on_ring_edge(rings, a, b))
                continue;
            for (int i = 0; i < 3; i++)
                if (same(p[i], a) || same(p[i], b))
                    return 1;
        }
    }
    return 0;
}

/* strict: the angle bound checked (inputs on a coarse lattice, whose ring
 * edges can be split); otherwise the triangles below it are only counted. */
static void check_refined(const char *what, int trial, const cg_polygon_set64 *input,
                          cg_clip_fill fill, double bound, int strict)
{
    cg_polygon_set64 simple = {0}, none = {0}, tri = {0};
    cg_clip_boolean64(CG_CLIP_UNION, input, fill, &none, fill, &simple);
    cg_status st = cg_triangulate_refined64(input, fill, bound, &tri);
    CHECK_MSG(st == CG_OK, "%s %d: %s", what, trial, cg_status_str(st));
    i128 area = 0, want = 0;
    int bad = 0, unmatched = 0, not_delaunay = 0, small = 0, uncovered = 0;
    size_t nt = tri.ring_count;
    for (size_t t = 0; t < nt; t++) {
        const cg_point64 *p = tri.points + tri.ring_start[t];
        i128 a = shapes_cross64(p[0], p[1], p[2]);
        bad += tri.ring_start[t + 1] - tri.ring_start[t] != 3 || a <= 0;
        area += a;
        int worst = 0;
        double angle[3];
        for (int k = 0; k < 3; k++) {
            angle[k] = angle_at(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
            worst = angle[k] < angle[worst] ? k : worst;
        }
        if (angle[worst] < bound - 1e-9) {
            if (sharp_vertex(&simple, p[worst]))
                sharp_exceptions++;
            else if (!strict || near_whole_piece(&tri, &simple, p))
                whole_exceptions++;
            else
                small++;
        }
        for (int k = 0; k < 3; k++) {
            cg_point64 from = p[k], to = p[(k + 1) % 3], opposite = p[(k + 2) % 3];
            if (on_ring_edge(&simple, from, to))
                continue;
            /* the twin: the triangle with to-from */
            int found = 0;
            for (size_t u = 0; u < nt && !found; u++) {
                const cg_point64 *q = tri.points + tri.ring_start[u];
                for (int j = 0; j < 3 && !found; j++)
                    if (same(q[j], to) && same(q[(j + 1) % 3], from)) {
                        found = 1;
                        not_delaunay += in_circle(from, to, opposite, q[(j + 2) % 3]);
                    }
            }
            unmatched += !found;
        }
    }
    for (size_t r = 0; r < simple.ring_count; r++) {
        size_t a = simple.ring_start[r], b = simple.ring_start[r + 1];
        for (size_t i = a; i + 2 < b; i++)
            want += shapes_cross64(simple.points[a], simple.points[i + 1], simple.points[i + 2]);
        for (size_t i = a; i < b; i++) {
            /* the triangle edges along it cover it: their projections sum to
             * its squared length (no edge is there twice: each has a twin
             * or lies on a ring edge, and the areas add up) */
            cg_point64 u = simple.points[i], v = simple.points[i + 1 < b ? i + 1 : a];
            i128 covered = 0;
            for (size_t t = 0; t < nt; t++) {
                const cg_point64 *p = tri.points + tri.ring_start[t];
                for (int k = 0; k < 3; k++) {
                    cg_point64 from = p[k], to = p[(k + 1) % 3];
                    if (shapes_cross64(u, v, from) == 0 && shapes_cross64(u, v, to) == 0
                        && dot(u, v, from) >= 0 && dot(u, v, to) <= dot(u, v, v)
                        && dot(u, v, to) > dot(u, v, from))
                        covered += dot(u, v, to) - dot(u, v, from);
                }
            }
            uncovered += covered != dot(u, v, v);
        }
    }
    total_triangles += (long)nt;
    CHECK_MSG(bad == 0, "%s %d: %d triangles not counter-clockwise with area", what, trial, bad);
    CHECK_MSG(area == want, "%s %d: twice the areas %.0f, of the region %.0f", what, trial,
              (double)area, (double)want);
    CHECK_MSG(unmatched == 0, "%s %d: %d edges with no twin", what, trial, unmatched);
    CHECK_MSG(uncovered == 0, "%s %d: %d ring edges not covered", what, trial, uncovered);
    CHECK_MSG(not_delaunay == 0, "%s %d: %d edges not Delaunay", what, trial, not_delaunay);
    CHECK_MSG(small == 0, "%s %d: %d triangles below %g degrees", what, trial, small, bound);
    cg_polygon_set64_clear(&simple);
    cg_polygon_set64_clear(&tri);
}

static const double bounds[] = {5, 15, 20, 25, 28, 30};

/* A star-shaped ring around (cx, cy) on the lattice of step 2^12. */
static void star(cg_polygon_set64 *s, int n, int64_t cx, int64_t cy, int64_t r_lo, int64_t r_hi,
                 int reversed)
{
    cg_point64 p[64];
    for (int i = 0; i < n; i++) {
        double t = 2 * M_PI * (i + 0.3 * (double)shapes_int(0, 100) / 100) / n;
        double r = (double)shapes_int(r_lo, r_hi);
        cg_point64 q = {(cx + (int64_t)llround(r * cos(t))) * 4096,
                        (cy + (int64_t)llround(r * sin(t))) * 4096};
        p[reversed ? n - 1 - i : i] = q;
    }
    cg_polygon_set64_add_ring(s, p, (size_t)n, 1);
}

static void random_polygons(void)
{
    cg_polygon_set64 s = {0};
    for (int trial = 0; trial < 60; trial++) {
        cg_polygon_set64_clear(&s);
        star(&s, 5 + (int)shapes_int(0, 20), 0, 0, 60, 120, 0);
        star(&s, 3 + (int)shapes_int(0, 5), -25, 0, 10, 20, 1);
        star(&s, 3 + (int)shapes_int(0, 5), 25, 10, 8, 18, 1);
        check_refined("stars", trial, &s, CG_CLIP_NON_ZERO, bounds[trial % 6], 1);
    }
    for (int trial = 0; trial < 60; trial++) { /* self-crossing: sharp corners */
        cg_polygon_set64_clear(&s);
        cg_point64 p[12];
        int n = 3 + (int)shapes_int(0, 9);
        for (int i = 0; i < n; i++)
            p[i] = (cg_point64){shapes_int(-100, 100) * 4096, shapes_int(-100, 100) * 4096};
        cg_polygon_set64_add_ring(&s, p, (size_t)n, 1);
        check_refined("crossing", trial, &s, (cg_clip_fill)(trial % 4), bounds[trial % 6], 0);
    }
    printf("   %ld triangles; below the bound: %ld at a corner sharper than 60 degrees, %ld "
           "where a ring edge has no grid point inside to split it at (crossings rounded to the "
           "grid)\n",
           total_triangles, sharp_exceptions, whole_exceptions);
    cg_polygon_set64_clear(&s);
}

static void structured(void)
{
    cg_polygon_set64 s = {0};
    /* a comb: teeth with sharp tips */
    cg_point64 comb[40];
    int n = 0;
    comb[n++] = (cg_point64){0, 0};
    for (int k = 0; k < 8; k++) {
        comb[n++] = (cg_point64){(int64_t)(20 * k + 20) * 4096, 0};
        comb[n++] = (cg_point64){(int64_t)(20 * k + 10) * 4096, 120 * 4096};
    }
    comb[n++] = (cg_point64){0, 120 * 4096};
    cg_polygon_set64_add_ring(&s, comb, (size_t)n, 1);
    for (int b = 0; b < 6; b++)
        check_refined("comb", b, &s, CG_CLIP_NON_ZERO, bounds[b], 1);
    /* a square with square holes touching at corners */
    cg_polygon_set64_clear(&s);
    cg_point64 outer[4] = {{0, 0}, {160 * 4096, 0}, {160 * 4096, 160 * 4096}, {0, 160 * 4096}};
    cg_polygon_set64_add_ring(&s, outer, 4, 1);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            if ((i + j) % 2 == 0) {
                int64_t x = (20 + 30 * i) * 4096, y = (20 + 30 * j) * 4096, w = 30 * 4096;
                cg_point64 h[4] = {{x, y}, {x, y + w}, {x + w, y + w}, {x + w, y}};
                cg_polygon_set64_add_ring(&s, h, 4, 1);
            }
    for (int b = 0; b < 6; b++)
        check_refined("holes", b, &s, CG_CLIP_EVEN_ODD, bounds[b], 1);
    cg_polygon_set64_clear(&s);
}

static void double_api_and_bad_input(void)
{
    cg_polygon_set s = {0}, r = {0};
    cg_vec2 thin[3] = {{0, 0}, {10, 0}, {5, 0.5}}; /* angles of 5.7 degrees */
    cg_polygon_set_add_ring(&s, thin, 3, 1);
    CHECK(cg_triangulate_refined(&s, CG_CLIP_EVEN_ODD, 20, 0, &r) == CG_OK);
    CHECK(r.ring_count > 1); /* the obtuse angle's triangle was split */
    CHECK_NEAR(cg_polygon_set_area(&r), 2.5, 1e-9);
    cg_clip_workspace *ws = cg_clip_workspace_create();
    CHECK(cg_triangulate_refined_ws(ws, &s, CG_CLIP_EVEN_ODD, 0, 0, &r) == CG_OK);
    CHECK(r.ring_count == 1);
    cg_clip_workspace_free(ws);
    CHECK(cg_triangulate_refined(&s, CG_CLIP_EVEN_ODD, 30.5, 0, &r) == CG_EINVAL);
    CHECK(cg_triangulate_refined(&s, CG_CLIP_EVEN_ODD, -1, 0, &r) == CG_EINVAL);
    CHECK(cg_triangulate_refined(&s, CG_CLIP_EVEN_ODD, NAN, 0, &r) == CG_EINVAL);
    CHECK(cg_triangulate_refined(&s, (cg_clip_fill)7, 20, 0, &r) == CG_EINVAL);
    CHECK(cg_triangulate_refined(NULL, CG_CLIP_EVEN_ODD, 20, 0, &r) == CG_EINVAL);
    cg_polygon_set64 none = {0}, r64 = {0};
    CHECK(cg_triangulate_refined64(&none, CG_CLIP_EVEN_ODD, 30, &r64) == CG_OK);
    CHECK(r64.ring_count == 0);
    cg_polygon_set_clear(&s);
    cg_polygon_set_clear(&r);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(random_polygons);
    CHECK_GROUP(structured);
    CHECK_GROUP(double_api_and_bad_input);
    return check_finish();
}
