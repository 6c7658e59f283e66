/* The triangle rasterizer on its own: coverage by definition (pixel centres
 * inside the snapped triangle, top-left rule on edges), watertight tilings
 * that cover every pixel exactly once, bad input. */
#include "cg/render.h"
#include "check.h"

#include <stdlib.h>
#include <string.h>

typedef struct grid {
    int width, height;
    unsigned char *count;
    int bad_span;
} grid;

static void count_span(void *user, int y, int x0, int x1)
{
    grid *g = user;
    if (y < 0 || y >= g->height || x0 < 0 || x1 > g->width || x0 >= x1) {
        g->bad_span = 1;
        return;
    }
    for (int x = x0; x < x1; x++)
        g->count[(size_t)y * g->width + x]++;
}

static grid grid_make(int w, int h)
{
    grid g = {w, h, calloc((size_t)w * h, 1), 0};
    return g;
}

/* ---- the definition, computed independently with exact integers ---------- */

static long long snap(double v)
{
    return (long long)floor(v * 256 + 0.5);
}

/* Edge function of p against a->b (1/256 units). */
static long long edge(long long ax, long long ay, long long bx, long long by, long long px,
                      long long py)
{
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/* Whether pixel (x, y) is covered: centre strictly inside, or on an edge
 * that is a top edge (horizontal, interior below) or a left edge (interior
 * to the right). */
static int covered(const cg_vec2 v[3], int x, int y)
{
    long long X[3], Y[3];
    for (int k = 0; k < 3; k++) {
        X[k] = snap(v[k].x);
        Y[k] = snap(v[k].y);
    }
    long long area = edge(X[0], Y[0], X[1], Y[1], X[2], Y[2]);
    if (area == 0)
        return 0;
    if (area < 0) {
        long long t = X[1];
        X[1] = X[2];
        X[2] = t;
        t = Y[1];
        Y[1] = Y[2];
        Y[2] = t;
    }
    long long px = (long long)x * 256 + 128, py = (long long)y * 256 + 128;
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        long long e = edge(X[i], Y[i], X[j], Y[j], px, py);
        if (e < 0)
            return 0;
        if (e == 0) {
            /* On the edge: belongs to the triangle when the interior is
             * below a horizontal edge or right of the edge. */
            long long dx = X[j] - X[i], dy = Y[j] - Y[i];
            int top = dy == 0 && dx > 0, left = dy < 0;
            if (!top && !left)
                return 0;
        }
    }
    return 1;
}

static void test_definition(void)
{
    check_rng rng = {12345};
    int mismatches = 0, total = 0;
    for (int t = 0; t < 400; t++) {
        int w = 24, h = 20;
        cg_vec2 v[3];
        for (int k = 0; k < 3; k++) {
            /* Half of the vertices on the 1/2-pixel lattice so that centres
             * fall on edges often. */
            if (check_rng_unit(&rng) < 0.5)
                v[k] = cg_vec2_make(check_rng_int(&rng, -4, 2 * w + 4) * 0.5,
                                    check_rng_int(&rng, -4, 2 * h + 4) * 0.5);
            else
                v[k] = cg_vec2_make(check_rng_range(&rng, -3, w + 3),
                                    check_rng_range(&rng, -3, h + 3));
        }
        grid g = grid_make(w, h);
        CHECK(cg_raster_triangle(v, w, h, count_span, &g) == CG_OK);
        CHECK(!g.bad_span);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                total++;
                if (g.count[y * w + x] != covered(v, x, y))
                    mismatches++;
            }
        free(g.count);
    }
    CHECK_MSG(mismatches == 0, "%d of %d pixels differ from the definition", mismatches, total);
}

static void test_top_left(void)
{
    /* The square [0.5, 4.5]^2 with centres on all four sides, as two
     * triangles: the top and left sides are in, the bottom and right out. */
    cg_vec2 a[3] = {{0.5, 0.5}, {4.5, 0.5}, {4.5, 4.5}};
    cg_vec2 b[3] = {{0.5, 0.5}, {4.5, 4.5}, {0.5, 4.5}};
    grid g = grid_make(8, 8);
    cg_raster_triangle(a, 8, 8, count_span, &g);
    cg_raster_triangle(b, 8, 8, count_span, &g);
    int ok = 1;
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++)
            ok &= g.count[y * 8 + x] == (x < 4 && y < 4);
    CHECK_MSG(ok, "the square covers exactly pixels 0..3 x 0..3");
    /* A single triangle: horizontal top edge at y = 1.5 (centres on it are
     * in), horizontal bottom edge of another at y = 1.5 (out). */
    cg_vec2 top[3] = {{0.5, 1.5}, {6.5, 1.5}, {3.5, 5}};
    cg_vec2 bottom[3] = {{3.5, -2}, {6.5, 1.5}, {0.5, 1.5}};
    memset(g.count, 0, 64);
    cg_raster_triangle(top, 8, 8, count_span, &g);
    CHECK(g.count[1 * 8 + 2] == 1 && g.count[1 * 8 + 5] == 1);
    memset(g.count, 0, 64);
    cg_raster_triangle(bottom, 8, 8, count_span, &g);
    CHECK(g.count[1 * 8 + 2] == 0 && g.count[1 * 8 + 3] == 0 && g.count[0 * 8 + 3] == 1);
    /* A vertical left edge at x = 2.5 is in, a vertical right edge out. */
    cg_vec2 left[3] = {{2.5, 0}, {2.5, 8}, {7, 4}};
    cg_vec2 right[3] = {{2.5, 0}, {-2, 4}, {2.5, 8}};
    memset(g.count, 0, 64);
    cg_raster_triangle(left, 8, 8, count_span, &g);
    CHECK(g.count[4 * 8 + 2] == 1 && g.count[4 * 8 + 1] == 0);
    memset(g.count, 0, 64);
    cg_raster_triangle(right, 8, 8, count_span, &g);
    CHECK(g.count[4 * 8 + 2] == 0 && g.count[4 * 8 + 1] == 1);
    free(g.count);
}

/* A jittered grid of points (some far outside the image), each cell cut
 * into two triangles along a random diagonal, both orientations: every
 * pixel of the image is covered exactly once. */
static void test_tiling(void)
{
    check_rng rng = {777};
    for (int trial = 0; trial < 12; trial++) {
        int w = 61 + trial * 7, h = 47 + trial * 5;
        int n = 6 + trial;
        cg_vec2 *p = malloc(sizeof *p * (size_t)(n + 1) * (n + 1));
        double spread = trial % 3 == 2 ? 1e6 : 40;
        for (int i = 0; i <= n; i++)
            for (int j = 0; j <= n; j++) {
                double x = (double)j / n * w, y = (double)i / n * h;
                if (j == 0)
                    x = -spread;
                if (j == n)
                    x = w + spread;
                if (i == 0)
                    y = -spread;
                if (i == n)
                    y = h + spread;
                if (j > 0 && j < n)
                    x += check_rng_range(&rng, -0.3, 0.3) * w / n;
                if (i > 0 && i < n)
                    y += check_rng_range(&rng, -0.3, 0.3) * h / n;
                /* Some vertices exactly on pixel centres and edges. */
                if (trial % 2 && i > 0 && i < n && j > 0 && j < n) {
                    x = floor(x) + 0.5;
                    y = floor(y);
                }
                p[i * (n + 1) + j] = cg_vec2_make(x, y);
            }
        grid g = grid_make(w, h);
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                cg_vec2 a = p[i * (n + 1) + j], b = p[i * (n + 1) + j + 1],
                        c = p[(i + 1) * (n + 1) + j + 1], d = p[(i + 1) * (n + 1) + j];
                cg_vec2 t1[3], t2[3];
                if (check_rng_unit(&rng) < 0.5) {
                    t1[0] = a;
                    t1[1] = b;
                    t1[2] = c;
                    t2[0] = a;
                    t2[1] = c;
                    t2[2] = d;
                } else {
                    t1[0] = a;
                    t1[1] = b;
                    t1[2] = d;
                    t2[0] = b;
                    t2[1] = c;
                    t2[2] = d;
                }
                if (check_rng_unit(&rng) < 0.5) {
                    cg_vec2 s = t1[1];
                    t1[1] = t1[2];
                    t1[2] = s;
                }
                cg_raster_triangle(t1, w, h, count_span, &g);
                cg_raster_triangle(t2, w, h, count_span, &g);
            }
        int wrong = 0;
        for (int k = 0; k < w * h; k++)
            wrong += g.count[k] != 1;
        CHECK_MSG(wrong == 0 && !g.bad_span, "tiling %d: %d pixels not covered exactly once", trial,
                  wrong);
        free(g.count);
        free(p);
    }
}

/* A fan of random triangles around a centre point: a star-shaped polygon;
 * pixels inside are covered once, none twice. */
static void test_fan(void)
{
    check_rng rng = {99};
    for (int trial = 0; trial < 30; trial++) {
        int w = 50, h = 50, n = 4 + trial % 20;
        cg_vec2 centre = {check_rng_range(&rng, 10, 40), check_rng_range(&rng, 10, 40)};
        cg_vec2 ring[32];
        for (int k = 0; k < n; k++) {
            double angle = 2 * CG_PI * (k + check_rng_range(&rng, 0, 0.4)) / n;
            double r = check_rng_range(&rng, 30, 60);
            ring[k] = cg_vec2_make(centre.x + r * cos(angle), centre.y + r * sin(angle));
        }
        grid g = grid_make(w, h);
        for (int k = 0; k < n; k++) {
            cg_vec2 t[3] = {centre, ring[k], ring[(k + 1) % n]};
            cg_raster_triangle(t, w, h, count_span, &g);
        }
        int twice = 0;
        for (int k = 0; k < w * h; k++)
            twice += g.count[k] > 1;
        CHECK_MSG(twice == 0, "fan %d: %d pixels covered twice", trial, twice);
        free(g.count);
    }
}

static void test_bad_input(void)
{
    grid g = grid_make(8, 8);
    cg_vec2 ok[3] = {{0, 0}, {8, 0}, {0, 8}};
    cg_vec2 nan[3] = {{0, 0}, {NAN, 0}, {0, 8}};
    cg_vec2 inf[3] = {{0, 0}, {INFINITY, 0}, {0, 8}};
    cg_vec2 line[3] = {{0, 0}, {4, 4}, {8, 8}};
    cg_vec2 point[3] = {{3, 3}, {3, 3}, {3, 3}};
    CHECK(cg_raster_triangle(nan, 8, 8, count_span, &g) == CG_EINVAL);
    CHECK(cg_raster_triangle(inf, 8, 8, count_span, &g) == CG_EINVAL);
    CHECK(cg_raster_triangle(NULL, 8, 8, count_span, &g) == CG_EINVAL);
    CHECK(cg_raster_triangle(ok, 8, 8, NULL, &g) == CG_EINVAL);
    CHECK(cg_raster_triangle(ok, -1, 8, count_span, &g) == CG_EINVAL);
    CHECK(cg_raster_triangle(ok, CG_RASTER_MAX_SIDE + 1, 8, count_span, &g) == CG_ERANGE);
    CHECK(cg_raster_triangle(ok, 0, 0, count_span, &g) == CG_OK);
    CHECK(cg_raster_triangle(line, 8, 8, count_span, &g) == CG_OK);
    CHECK(cg_raster_triangle(point, 8, 8, count_span, &g) == CG_OK);
    int any = 0;
    for (int k = 0; k < 64; k++)
        any += g.count[k];
    CHECK_MSG(any == 0, "degenerate triangles cover nothing (%d)", any);
    /* Huge coordinates: no overflow, the visible part only. */
    cg_vec2 huge[3] = {{-1e12, -1e12}, {1e12, -1e12}, {0, 1e12}};
    CHECK(cg_raster_triangle(huge, 8, 8, count_span, &g) == CG_OK);
    any = 0;
    for (int k = 0; k < 64; k++)
        any += g.count[k];
    CHECK_MSG(any == 64 && !g.bad_span, "a huge triangle covers the whole grid once (%d)", any);
    cg_vec2 absurd[3] = {{-1e300, -1e300}, {1e300, -1e300}, {0, 1e300}};
    memset(g.count, 0, 64);
    CHECK(cg_raster_triangle(absurd, 8, 8, count_span, &g) == CG_OK);
    int over = 0;
    for (int k = 0; k < 64; k++)
        over += g.count[k] > 1;
    CHECK(!g.bad_span && over == 0);
    free(g.count);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_definition);
    CHECK_GROUP(test_top_left);
    CHECK_GROUP(test_tiling);
    CHECK_GROUP(test_fan);
    CHECK_GROUP(test_bad_input);
    return check_finish();
}
