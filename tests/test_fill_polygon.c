/* Aliased scan-line polygon fill against point-in-polygon at every pixel
 * centre, tilings that must cover every pixel exactly once, bad input. */
#include "check.h"
#include "cg/fill.h"
#include "cg/color.h"

#include <stdlib.h>
#include <string.h>

/* Winding number of point (px, py) by the crossing rule of the definition:
 * an edge counts when py lies in [top, bottom) of it and its crossing with
 * the horizontal line is at or left of px (crossing computed from the
 * endpoints ordered top to bottom). */
static int winding_at(const cg_vec2 *pts, const int *sizes, int contours, double px, double py)
{
    int w = 0, start = 0;
    for (int c = 0; c < contours; c++) {
        int n = sizes[c];
        for (int i = 0; i < n; i++) {
            cg_vec2 a = pts[start + i], b = pts[start + (i + 1) % n];
            if (a.y == b.y)
                continue;
            int dir = b.y > a.y ? 1 : -1;
            cg_vec2 t = dir > 0 ? a : b, u = dir > 0 ? b : a;
            if (!(py >= t.y && py < u.y))
                continue;
            double x = t.x + (py - t.y) * ((u.x - t.x) / (u.y - t.y));
            if (x <= px)
                w += dir;
        }
        start += n;
    }
    return w;
}

static int inside(int winding, cg_fill_rule rule)
{
    return rule == CG_FILL_NONZERO ? winding != 0 : (winding & 1);
}

static const cg_rgba8 white = {255, 255, 255, 255};

/* Random polygons (random, integer and half-integer coordinates, some
 * outside the image, several contours) against the reference. */
static void random_polygons(void)
{
    check_rng rng = {2024};
    int bad = 0, total = 0;
    cg_rasterizer *r;
    cg_rasterizer_create(&r);
    for (int trial = 0; trial < 3000; trial++) {
        int w = (int)check_rng_int(&rng, 1, 48), h = (int)check_rng_int(&rng, 1, 48);
        cg_image *im;
        cg_image_create(&im, w, h, CG_PIXEL_RGBA8);
        cg_vec2 pts[40];
        int sizes[4], contours = (int)check_rng_int(&rng, 1, 3), n = 0;
        int mode = trial % 3;
        for (int c = 0; c < contours; c++) {
            sizes[c] = (int)check_rng_int(&rng, 1, 10);
            for (int i = 0; i < sizes[c]; i++) {
                double x = check_rng_range(&rng, -8, w + 8), y = check_rng_range(&rng, -8, h + 8);
                if (mode == 1) { /* vertices on pixel corners */
                    x = floor(x);
                    y = floor(y);
                } else if (mode == 2) { /* vertices and edges through pixel centres */
                    x = floor(x * 2) / 2;
                    y = floor(y * 2) / 2;
                }
                pts[n++] = cg_vec2_make(x, y);
            }
        }
        cg_fill_rule rule = check_rng_int(&rng, 0, 1) ? CG_FILL_NONZERO : CG_FILL_EVEN_ODD;
        CHECK(cg_rasterizer_fill_polygon(r, im, pts, sizes, contours, rule, white) == CG_OK);
        int wrong = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                int expect = inside(winding_at(pts, sizes, contours, x + 0.5, y + 0.5), rule);
                int got = cg_image_get_rgba8(im, x, y).a == 255;
                wrong += expect != got;
            }
        total++;
        if (wrong && ++bad <= 5)
            fprintf(stderr, "polygon trial %d (%dx%d, mode %d): %d pixels differ\n", trial, w, h,
                    mode, wrong);
        cg_image_free(im);
    }
    cg_rasterizer_free(r);
    CHECK_MSG(bad == 0, "%d of %d random polygons differ from point-in-polygon", bad, total);
}

/* Wide images (runs of interior pixels long enough for the wide-store
 * path) over random opaque backgrounds, several contours: a pixel whose
 * centre is inside has exactly the paint's colour, every other pixel keeps
 * its own. */
static void wide_polygons(void)
{
    check_rng rng = {4040};
    int bad = 0;
    cg_rasterizer *r;
    cg_rasterizer_create(&r);
    const cg_rgba8 ink = {30, 60, 200, 255};
    for (int trial = 0; trial < 300; trial++) {
        int w = (int)check_rng_int(&rng, 60, 400), h = (int)check_rng_int(&rng, 1, 12);
        cg_image *im, *before;
        cg_image_create(&im, w, h, CG_PIXEL_RGBA8);
        cg_image_create(&before, w, h, CG_PIXEL_RGBA8);
        for (size_t i = 0; i < (size_t)im->stride * (size_t)h; i++)
            im->data[i] = (i & 3) == 3 ? 255 : (uint8_t)check_rng_int(&rng, 0, 255);
        memcpy(before->data, im->data, (size_t)im->stride * (size_t)h);
        cg_vec2 pts[24];
        int sizes[3], contours = (int)check_rng_int(&rng, 1, 3), n = 0;
        for (int c = 0; c < contours; c++) {
            sizes[c] = (int)check_rng_int(&rng, 3, 8);
            for (int i = 0; i < sizes[c]; i++)
                pts[n++] = cg_vec2_make(check_rng_range(&rng, -20, w + 20),
                                        check_rng_range(&rng, -4, h + 4));
        }
        cg_fill_rule rule = trial % 2 ? CG_FILL_NONZERO : CG_FILL_EVEN_ODD;
        CHECK(cg_rasterizer_fill_polygon(r, im, pts, sizes, contours, rule, ink) == CG_OK);
        int wrong = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                int in = inside(winding_at(pts, sizes, contours, x + 0.5, y + 0.5), rule);
                cg_rgba8 got = cg_image_get_rgba8(im, x, y);
                cg_rgba8 expect = in ? ink : cg_image_get_rgba8(before, x, y);
                wrong += memcmp(&got, &expect, sizeof got) != 0;
            }
        if (wrong && ++bad <= 5)
            fprintf(stderr, "wide polygon trial %d (%dx%d): %d pixels differ\n", trial, w, h,
                    wrong);
        cg_image_free(im);
        cg_image_free(before);
    }
    cg_rasterizer_free(r);
    CHECK_MSG(bad == 0, "%d wide polygons differ from point-in-polygon", bad);
}

/* Counts coverage by painting each tile with alpha 1/2 in linear light:
 * a pixel painted once reads back differently from one painted twice. */
static void tilings(void)
{
    check_rng rng = {77};
    int bad = 0;
    cg_rasterizer *r;
    cg_rasterizer_create(&r);
    for (int trial = 0; trial < 300; trial++) {
        int w = (int)check_rng_int(&rng, 8, 64), h = (int)check_rng_int(&rng, 8, 64);
        int gx = (int)check_rng_int(&rng, 2, 8), gy = (int)check_rng_int(&rng, 2, 8);
        /* A jittered grid extending past the image; half the trials snap
         * the points to the half-pixel lattice so edges hit centres. */
        cg_vec2 grid[9][9];
        for (int j = 0; j <= gy; j++)
            for (int i = 0; i <= gx; i++) {
                double x = -3 + (w + 6.0) * i / gx, y = -3 + (h + 6.0) * j / gy;
                if (i > 0 && i < gx)
                    x += check_rng_range(&rng, -0.3, 0.3) * (w + 6.0) / gx;
                if (j > 0 && j < gy)
                    y += check_rng_range(&rng, -0.3, 0.3) * (h + 6.0) / gy;
                if (trial % 2) {
                    x = floor(x * 2) / 2;
                    y = floor(y * 2) / 2;
                }
                grid[j][i] = cg_vec2_make(x, y);
            }
        cg_image *im;
        cg_image_create(&im, w, h, CG_PIXEL_RGBA8);
        cg_rgba8 black = {0, 0, 0, 255}, half = {255, 255, 255, 128};
        cg_image_clear_rgba8(im, black);
        int quads = trial % 3 == 0;
        for (int j = 0; j < gy; j++)
            for (int i = 0; i < gx; i++) {
                cg_vec2 a = grid[j][i], b = grid[j][i + 1], c = grid[j + 1][i + 1],
                        d = grid[j + 1][i];
                if (quads) {
                    cg_vec2 q[4] = {a, b, c, d};
                    int n = 4;
                    cg_rasterizer_fill_polygon(r, im, q, &n, 1, CG_FILL_NONZERO, half);
                } else if (check_rng_int(&rng, 0, 1)) {
                    cg_vec2 t1[3] = {a, b, c}, t2[3] = {c, a, d}; /* mixed orientations */
                    int n = 3;
                    cg_rasterizer_fill_polygon(r, im, t1, &n, 1, CG_FILL_EVEN_ODD, half);
                    cg_rasterizer_fill_polygon(r, im, t2, &n, 1, CG_FILL_NONZERO, half);
                } else {
                    cg_vec2 t1[3] = {a, b, d}, t2[3] = {b, c, d};
                    int n = 3;
                    cg_rasterizer_fill_polygon(r, im, t1, &n, 1, CG_FILL_NONZERO, half);
                    cg_rasterizer_fill_polygon(r, im, t2, &n, 1, CG_FILL_EVEN_ODD, half);
                }
            }
        /* Once-painted value: white at 1/2 over black in linear light. */
        cg_image *one;
        cg_image_create(&one, 1, 1, CG_PIXEL_RGBA8);
        cg_image_clear_rgba8(one, black);
        cg_vec2 sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        int n4 = 4;
        cg_rasterizer_fill_polygon(r, one, sq, &n4, 1, CG_FILL_NONZERO, half);
        cg_rgba8 once = cg_image_get_rgba8(one, 0, 0);
        cg_image_free(one);
        int wrong = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                wrong += cg_image_get_rgba8(im, x, y).r != once.r;
        if (wrong && ++bad <= 5)
            fprintf(stderr, "tiling trial %d: %d pixels not covered exactly once\n", trial, wrong);
        cg_image_free(im);
    }
    cg_rasterizer_free(r);
    CHECK_MSG(bad == 0, "%d tilings leave gaps or overlaps", bad);
}

static int image_is(const cg_image *im, cg_rgba8 c)
{
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++) {
            cg_rgba8 p = cg_image_get_rgba8(im, x, y);
            if (p.r != c.r || p.g != c.g || p.b != c.b || p.a != c.a)
                return 0;
        }
    return 1;
}

static void bad_input(void)
{
    cg_image *im;
    cg_image_create(&im, 16, 16, CG_PIXEL_RGBA8);
    cg_rgba8 none = {0, 0, 0, 0};
    int three = 3, four = 4;
    cg_vec2 nan_tri[3] = {{1, 1}, {NAN, 5}, {10, 10}};
    CHECK(cg_fill_polygon(im, nan_tri, &three, 1, CG_FILL_NONZERO, white) == CG_EINVAL);
    cg_vec2 inf_tri[3] = {{1, 1}, {INFINITY, 5}, {10, 10}};
    CHECK(cg_fill_polygon(im, inf_tri, &three, 1, CG_FILL_NONZERO, white) == CG_EINVAL);
    cg_vec2 huge_tri[3] = {{1, 1}, {1e300, 5}, {10, 10}};
    CHECK(cg_fill_polygon(im, huge_tri, &three, 1, CG_FILL_NONZERO, white) == CG_EINVAL);
    CHECK(cg_fill_polygon(im, NULL, &three, 1, CG_FILL_NONZERO, white) == CG_EINVAL);
    int negative = -2;
    CHECK(cg_fill_polygon(im, huge_tri, &negative, 1, CG_FILL_NONZERO, white) == CG_EINVAL);
    CHECK(cg_fill_polygon(im, huge_tri, &three, -1, CG_FILL_NONZERO, white) == CG_EINVAL);
    CHECK(cg_fill_polygon(im, huge_tri, &three, 1, (cg_fill_rule)7, white) == CG_EINVAL);
    CHECK(image_is(im, none));
    /* Empty and zero-area polygons: fine, nothing drawn. */
    CHECK(cg_fill_polygon(im, NULL, NULL, 0, CG_FILL_NONZERO, white) == CG_OK);
    cg_vec2 line[3] = {{0, 0}, {8, 8}, {16, 16}};
    CHECK(cg_fill_polygon(im, line, &three, 1, CG_FILL_NONZERO, white) == CG_OK);
    cg_vec2 flat[4] = {{0, 5}, {16, 5}, {16, 5}, {0, 5}};
    CHECK(cg_fill_polygon(im, flat, &four, 1, CG_FILL_EVEN_ODD, white) == CG_OK);
    CHECK(image_is(im, none));
    /* Large but valid coordinates: a triangle covering the whole image. */
    cg_vec2 big[3] = {{-1e11, -1e11}, {1e11, -1e9}, {-1e9, 1e11}};
    CHECK(cg_fill_polygon(im, big, &three, 1, CG_FILL_NONZERO, white) == CG_OK);
    CHECK(image_is(im, white));
    /* Far away entirely: nothing. */
    cg_image_clear_rgba8(im, none);
    cg_vec2 away[3] = {{-1e11, 3}, {-1e10, 3}, {-1e10, 9}};
    CHECK(cg_fill_polygon(im, away, &three, 1, CG_FILL_NONZERO, white) == CG_OK);
    CHECK(image_is(im, none));
    cg_image_free(im);
}

/* A polygon split in two along a shared edge paints the same pixels, each
 * once, as the whole. */
static void split_polygon(void)
{
    check_rng rng = {5};
    int bad = 0;
    for (int trial = 0; trial < 500; trial++) {
        /* A convex polygon: points on an ellipse; split by a chord. */
        int n = (int)check_rng_int(&rng, 4, 12);
        double cx = check_rng_range(&rng, 10, 30), cy = check_rng_range(&rng, 10, 30);
        double rx = check_rng_range(&rng, 3, 15), ry = check_rng_range(&rng, 3, 15);
        cg_vec2 p[12];
        for (int i = 0; i < n; i++) {
            double a = 2 * CG_PI * (i + check_rng_range(&rng, 0, 0.8)) / n;
            p[i] = cg_vec2_make(cx + rx * cos(a), cy + ry * sin(a));
        }
        int k = (int)check_rng_int(&rng, 2, n - 2);
        cg_vec2 first[12], second[12];
        int n1 = 0, n2 = 0;
        for (int i = 0; i <= k; i++)
            first[n1++] = p[i];
        for (int i = k; i <= n; i++)
            second[n2++] = p[i % n];
        cg_image *whole, *parts;
        cg_image_create(&whole, 40, 40, CG_PIXEL_RGBA8);
        cg_image_create(&parts, 40, 40, CG_PIXEL_RGBA8);
        cg_rgba8 half = {255, 255, 255, 128};
        cg_fill_polygon(whole, p, &n, 1, CG_FILL_NONZERO, half);
        cg_fill_polygon(parts, first, &n1, 1, CG_FILL_NONZERO, half);
        cg_fill_polygon(parts, second, &n2, 1, CG_FILL_EVEN_ODD, half);
        if (memcmp(whole->data, parts->data, 40 * 40 * 4) && ++bad <= 3)
            fprintf(stderr, "split trial %d differs\n", trial);
        cg_image_free(whole);
        cg_image_free(parts);
    }
    CHECK_MSG(bad == 0, "%d split polygons differ from the whole", bad);
}

/* Blending with alpha < 255 matches cg_image_blend; float images too. */
static void blending(void)
{
    check_rng rng = {8};
    for (int t = 0; t < 200; t++) {
        cg_image *a, *b;
        cg_image_create(&a, 4, 1, t % 2 ? CG_PIXEL_RGBAF : CG_PIXEL_RGBA8);
        cg_rgba8 bg = {(uint8_t)check_rng_int(&rng, 0, 255), (uint8_t)check_rng_int(&rng, 0, 255),
                       (uint8_t)check_rng_int(&rng, 0, 255), (uint8_t)check_rng_int(&rng, 0, 255)};
        cg_rgba8 fg = {(uint8_t)check_rng_int(&rng, 0, 255), (uint8_t)check_rng_int(&rng, 0, 255),
                       (uint8_t)check_rng_int(&rng, 0, 255), (uint8_t)check_rng_int(&rng, 0, 255)};
        if (t % 10 == 3)
            bg.a = 0; /* over nothing */
        if (t % 10 == 7)
            fg.a = 0; /* nothing to draw */
        if (t % 10 == 9)
            bg.a = 255;
        cg_image_clear_rgba8(a, bg);
        cg_image_copy(a, &b);
        cg_vec2 sq[4] = {{0, 0}, {4, 0}, {4, 1}, {0, 1}};
        int n = 4;
        cg_fill_polygon(a, sq, &n, 1, CG_FILL_NONZERO, fg);
        for (int x = 0; x < 4; x++)
            cg_image_blend(b, x, 0, cg_rgba8_to_linear(fg));
        cg_rgba8 p = cg_image_get_rgba8(a, 2, 0), q = cg_image_get_rgba8(b, 2, 0);
        CHECK_MSG(abs(p.r - q.r) <= 1 && abs(p.g - q.g) <= 1 && abs(p.b - q.b) <= 1
                      && abs(p.a - q.a) <= 1,
                  "blend %d,%d,%d,%d over %d,%d,%d,%d: %d,%d,%d,%d vs %d,%d,%d,%d", fg.r, fg.g,
                  fg.b, fg.a, bg.r, bg.g, bg.b, bg.a, p.r, p.g, p.b, p.a, q.r, q.g, q.b, q.a);
        cg_image_free(a);
        cg_image_free(b);
    }
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(random_polygons);
    CHECK_GROUP(wide_polygons);
    CHECK_GROUP(tilings);
    CHECK_GROUP(bad_input);
    CHECK_GROUP(split_polygon);
    CHECK_GROUP(blending);
    return check_finish();
}
