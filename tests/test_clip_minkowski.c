/* Minkowski sums against their definition: x lies in A + B when x - a lies
 * in B for some a in A, that is when the reflected pattern moved to x,
 * x - A, meets B.  For a convex pattern A and an open path B that is when
 * some point x - e(t) of a path edge lies in A: the convex function
 * t -> max over A's edges of the outward distance of x - e(t) (0 on A's
 * boundary, negative inside) is minimised by ternary search; for a region
 * B, also when x - a0 lies in B.  Random convex patterns, random
 * self-crossing polylines and star polygons with holes: membership at
 * random points agrees (points within two grid units of the boundary left
 * out); the difference is the sum with the reflected pattern; closed forms
 * (a square swept along a segment, a square grown by a square); bad input. */
#include "polygon_shapes.h"
#include "check.h"

/* The outward distance of (x, y) from the convex counter-clockwise ring
 * a[0..n): the largest over its edges. */
static double convex_gap(const cg_point64 *a, int n, double x, double y)
{
    double worst = -INFINITY;
    for (int i = 0; i < n; i++) {
        cg_point64 p = a[i], q = a[(i + 1) % n];
        double ex = (double)(q.x - p.x), ey = (double)(q.y - p.y), l = hypot(ex, ey);
        worst = fmax(worst, (ex * (y - (double)p.y) - ey * (x - (double)p.x)) / -l);
    }
    return worst;
}

/* min over t of convex_gap(x - e(t)) along the edge e0-e1. */
static double swept_gap(const cg_point64 *a, int n, double x, double y, cg_point64 e0,
                        cg_point64 e1)
{
    double lo = 0, hi = 1;
    for (int k = 0; k < 80; k++) {
        double t1 = lo + (hi - lo) / 3, t2 = hi - (hi - lo) / 3;
        double f1 = convex_gap(a, n, x - ((double)e0.x + t1 * (double)(e1.x - e0.x)),
                               y - ((double)e0.y + t1 * (double)(e1.y - e0.y)));
        double f2 = convex_gap(a, n, x - ((double)e0.x + t2 * (double)(e1.x - e0.x)),
                               y - ((double)e0.y + t2 * (double)(e1.y - e0.y)));
        if (f1 < f2)
            hi = t2;
        else
            lo = t1;
    }
    double t = (lo + hi) / 2;
    return convex_gap(a, n, x - ((double)e0.x + t * (double)(e1.x - e0.x)),
                      y - ((double)e0.y + t * (double)(e1.y - e0.y)));
}

static int convex_pattern(cg_point64 *a, double r)
{
    int n = 3 + (int)shapes_between(0, 8);
    double angle = shapes_between(0, 1), step = 2 * M_PI / n;
    for (int i = 0; i < n; i++) {
        double t = angle + step * (i + shapes_between(0, 0.5));
        a[i] = (cg_point64){(int64_t)llround(r * cos(t)), (int64_t)llround(r * sin(t))};
    }
    return n;
}

static long judged, unjudged;

static void random_sums(void)
{
    cg_polygon_set64 pattern = {0}, reflected = {0}, path = {0}, sum = {0}, diff = {0};
    for (int trial = 0; trial < 150; trial++) {
        cg_point64 a[16], minus[16];
        int n = convex_pattern(a, shapes_between(50, 400));
        cg_polygon_set64_clear(&pattern);
        cg_polygon_set64_clear(&reflected);
        cg_polygon_set64_add_ring(&pattern, a, (size_t)n, 1);
        for (int i = 0; i < n; i++)
            minus[i] = (cg_point64){-a[i].x, -a[i].y};
        cg_polygon_set64_add_ring(&reflected, minus, (size_t)n, 1);
        int open = trial % 2 == 0;
        cg_polygon_set64_clear(&path);
        cg_point64 p[40];
        int m = open ? 1 + (int)shapes_between(0, 12) : 5 + (int)shapes_between(0, 30);
        for (int i = 0; i < m; i++) {
            double t = 2 * M_PI * i / m, r = shapes_between(600, 2000);
            p[i] = open ? (cg_point64){(int64_t)shapes_between(-2000, 2000),
                                       (int64_t)shapes_between(-2000, 2000)}
                        : (cg_point64){(int64_t)llround(r * cos(t)), (int64_t)llround(r * sin(t))};
        }
        cg_polygon_set64_add_ring(&path, p, (size_t)m, 1);
        if (!open) { /* a hole */
            cg_point64 h[4] = {{-200, -200}, {-200, 200}, {200, 200}, {200, -200}};
            cg_polygon_set64_add_ring(&path, h, 4, 1);
        }
        CHECK(cg_minkowski64(CG_MINKOWSKI_SUM, &pattern, &path, open, CG_CLIP_EVEN_ODD, &sum)
              == CG_OK);
        CHECK(cg_minkowski64(CG_MINKOWSKI_DIFFERENCE, &reflected, &path, open, CG_CLIP_EVEN_ODD,
                             &diff)
              == CG_OK);
        /* the same pieces, their crossings rounded alike (up to the order
         * the engine meets them in: a grid unit along the boundary) */
        double perimeter = 0;
        for (size_t r = 0; r < sum.ring_count; r++)
            for (size_t i = sum.ring_start[r]; i < sum.ring_start[r + 1]; i++) {
                cg_point64 u = sum.points[i];
                cg_point64 v =
                    sum.points[i + 1 < sum.ring_start[r + 1] ? i + 1 : sum.ring_start[r]];
                perimeter += hypot((double)(v.x - u.x), (double)(v.y - u.y));
            }
        CHECK_MSG(fabs(cg_polygon_set64_area(&sum) - cg_polygon_set64_area(&diff)) <= perimeter,
                  "trial %d: the difference with -A is not the sum with A: areas %.17g, %.17g",
                  trial, cg_polygon_set64_area(&sum), cg_polygon_set64_area(&diff));
        for (int k = 0; k < 300; k++) {
            double x = shapes_between(-2600, 2600), y = shapes_between(-2600, 2600), gap = INFINITY;
            for (size_t r = 0; r < path.ring_count; r++) {
                size_t s = path.ring_start[r], e = path.ring_start[r + 1];
                for (size_t i = s; i < e; i++) {
                    size_t j = i + 1 < e ? i + 1 : (open && e - s > 1 ? i : s);
                    gap = fmin(gap, swept_gap(a, n, x, y, path.points[i], path.points[j]));
                }
            }
            if (fabs(gap) < 2) {
                unjudged++;
                continue;
            }
            int want = gap < 0
                       || (!open
                           && shapes_winding64(&path, x - (double)a[0].x, y - (double)a[0].y) % 2);
            int got = shapes_winding64(&sum, x, y) != 0;
            judged++;
            CHECK_MSG(got == want, "trial %d: (%.1f, %.1f) gap %.2f: got %d, want %d", trial, x, y,
                      gap, got, want);
        }
    }
    printf("   %ld points judged, %ld within 2 units of the boundary\n", judged, unjudged);
    CHECK(judged > 50 * unjudged);
    cg_polygon_set64_clear(&pattern);
    cg_polygon_set64_clear(&reflected);
    cg_polygon_set64_clear(&path);
    cg_polygon_set64_clear(&sum);
    cg_polygon_set64_clear(&diff);
}

static void closed_forms_and_bad_input(void)
{
    cg_polygon_set pattern = {0}, path = {0}, r = {0};
    cg_vec2 square[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, segment[2] = {{0, 0}, {10, 0}};
    cg_vec2 big[5] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}};
    cg_polygon_set_add_ring(&pattern, square, 4, 1);
    cg_polygon_set_add_ring(&path, segment, 2, 1);
    CHECK(cg_minkowski(CG_MINKOWSKI_SUM, &pattern, &path, 1, CG_CLIP_EVEN_ODD, 0, &r) == CG_OK);
    CHECK_NEAR(cg_polygon_set_area(&r), 24, 1e-9);
    cg_polygon_set_clear(&path);
    cg_polygon_set_add_ring(&path, big, 5, 1);
    CHECK(cg_minkowski(CG_MINKOWSKI_SUM, &pattern, &path, 0, CG_CLIP_EVEN_ODD, 0, &r) == CG_OK);
    CHECK_NEAR(cg_polygon_set_area(&r), 144, 1e-9);
    /* the square's boundary as a path back to its start: a frame 12 wide
     * outside, 8 inside */
    CHECK(cg_minkowski(CG_MINKOWSKI_SUM, &pattern, &path, 1, CG_CLIP_EVEN_ODD, 0, &r) == CG_OK);
    CHECK_NEAR(cg_polygon_set_area(&r), 144 - 64, 1e-9);
    cg_clip_workspace *ws = cg_clip_workspace_create();
    CHECK(cg_minkowski_ws(ws, CG_MINKOWSKI_DIFFERENCE, &pattern, &path, 0, CG_CLIP_EVEN_ODD, 0, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set_area(&r), 144, 1e-9);
    cg_clip_workspace_free(ws);
    CHECK(cg_minkowski((cg_minkowski_op)5, &pattern, &path, 0, CG_CLIP_EVEN_ODD, 0, &r)
          == CG_EINVAL);
    CHECK(cg_minkowski(CG_MINKOWSKI_SUM, &pattern, &path, 0, (cg_clip_fill)9, 0, &r) == CG_EINVAL);
    CHECK(cg_minkowski(CG_MINKOWSKI_SUM, NULL, &path, 0, CG_CLIP_EVEN_ODD, 0, &r) == CG_EINVAL);
    path.points[0].x = NAN;
    CHECK(cg_minkowski(CG_MINKOWSKI_SUM, &pattern, &path, 0, CG_CLIP_EVEN_ODD, 0, &r) == CG_EINVAL);
    cg_polygon_set64 far = {0}, p64 = {0}, r64 = {0};
    cg_point64 f[3] = {{CG_CLIP_MAX_COORD, 0}, {CG_CLIP_MAX_COORD, 1}, {0, 0}};
    cg_point64 q[3] = {{10, 0}, {10, 1}, {0, 0}};
    cg_polygon_set64_add_ring(&far, f, 3, 1);
    cg_polygon_set64_add_ring(&p64, q, 3, 1);
    CHECK(cg_minkowski64(CG_MINKOWSKI_SUM, &p64, &far, 0, CG_CLIP_EVEN_ODD, &r64) == CG_ERANGE);
    cg_polygon_set64 none = {0};
    CHECK(cg_minkowski64(CG_MINKOWSKI_SUM, &p64, &none, 1, CG_CLIP_EVEN_ODD, &r64) == CG_OK
          && r64.ring_count == 0);
    cg_polygon_set64_clear(&far);
    cg_polygon_set64_clear(&p64);
    cg_polygon_set_clear(&pattern);
    cg_polygon_set_clear(&path);
    cg_polygon_set_clear(&r);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(random_sums);
    CHECK_GROUP(closed_forms_and_bad_input);
    return check_finish();
}
