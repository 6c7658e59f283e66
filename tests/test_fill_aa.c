/* Anti-aliased fill, paths and strokes: coverage against exact areas
 * (polygons clipped to each pixel square), split polygons, strokes of
 * straight segments, SVG path data, gradients, bad input. */
#include "check.h"
#include "cg/fill.h"
#include "cg/color.h"
#include "../src/fill/internal.h" /* to compare the blend shortcuts with fill_solid_pixel */

#include <stdlib.h>
#include <string.h>

/* Signed area of polygon p[0..n). */
static double area(const cg_vec2 *p, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++) {
        cg_vec2 a = p[i], b = p[(i + 1) % n];
        s += a.x * b.y - a.y * b.x;
    }
    return s / 2;
}

/* Sutherland-Hodgman clip of p against one half-plane (axis, bound, keep
 * the side below when upper). */
static int clip_half(const cg_vec2 *in, int n, cg_vec2 *out, int axis, double bound, int upper)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        cg_vec2 a = in[i], b = in[(i + 1) % n];
        double va = axis ? a.y : a.x, vb = axis ? b.y : b.x;
        int ina = upper ? va <= bound : va >= bound, inb = upper ? vb <= bound : vb >= bound;
        if (ina)
            out[m++] = a;
        if (ina != inb) {
            double t = (bound - va) / (vb - va);
            out[m++] = cg_vec2_make(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t);
        }
    }
    return m;
}

/* Integral of the winding number of polygon p over pixel (x, y): the signed
 * area of p clipped to the square. */
static double pixel_area(const cg_vec2 *p, int n, int x, int y)
{
    cg_vec2 a[256], b[256];
    int m = clip_half(p, n, a, 0, x, 0);
    m = clip_half(a, m, b, 0, x + 1, 1);
    m = clip_half(b, m, a, 1, y, 0);
    m = clip_half(a, m, b, 1, y + 1, 1);
    return area(b, m);
}

static const cg_rgba8 white = {255, 255, 255, 255};

/* A random simple polygon: star-shaped around a centre. */
static int star_polygon(check_rng *rng, cg_vec2 *p, double cx, double cy, double rmin, double rmax)
{
    /* At least 4 vertices, each in its own quarter of the angular step, so
     * that consecutive vertices are less than pi apart and the polygon is
     * simple (star-shaped around the centre). */
    int n = (int)check_rng_int(rng, 4, 24);
    double base = check_rng_range(rng, 0, 2 * CG_PI);
    for (int i = 0; i < n; i++) {
        double a = base + 2 * CG_PI * (i + check_rng_range(rng, 0, 0.9)) / n;
        double r = check_rng_range(rng, rmin, 1) * rmax;
        p[i] = cg_vec2_make(cx + r * cos(a), cy + r * sin(a));
    }
    return n;
}

/* Each pixel's alpha equals the exact covered area within 1/256 (8-bit
 * coverage), on random simple polygons of either orientation, both rules,
 * some reaching outside the image. */
static void coverage_is_area(void)
{
    check_rng rng = {31337};
    int bad = 0, sum_bad = 0;
    cg_rasterizer *r;
    cg_rasterizer_create(&r);
    for (int trial = 0; trial < 2000; trial++) {
        int w = (int)check_rng_int(&rng, 1, 32), h = (int)check_rng_int(&rng, 1, 32);
        cg_image *im;
        cg_image_create(&im, w, h, CG_PIXEL_RGBAF);
        cg_vec2 p[24];
        int n = star_polygon(&rng, p, check_rng_range(&rng, -4, w + 4),
                             check_rng_range(&rng, -4, h + 4), 0.2, check_rng_range(&rng, 0.3, 24));
        if (trial % 2) /* reverse the orientation */
            for (int i = 0; i < n / 2; i++) {
                cg_vec2 t = p[i];
                p[i] = p[n - 1 - i];
                p[n - 1 - i] = t;
            }
        cg_fill_rule rule = trial % 4 < 2 ? CG_FILL_NONZERO : CG_FILL_EVEN_ODD;
        cg_paint paint = cg_paint_solid(white);
        CHECK(cg_rasterizer_fill_polygon_aa(r, im, p, &n, 1, rule, &paint) == CG_OK);
        double worst = 0, sum = 0, exact_sum = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                double exact = fabs(pixel_area(p, n, x, y));
                double got = cg_image_get(im, x, y).a;
                sum += got;
                exact_sum += exact;
                if (fabs(got - exact) > worst)
                    worst = fabs(got - exact);
            }
        if (worst > 1.0 / 256 && ++bad <= 5)
            fprintf(stderr, "coverage trial %d: error %g\n", trial, worst);
        if (fabs(sum - exact_sum) > (double)w * h / 256 + 1e-9)
            sum_bad++;
        cg_image_free(im);
    }
    cg_rasterizer_free(r);
    CHECK_MSG(bad == 0, "%d polygons have a pixel off its exact area by more than 1/256", bad);
    CHECK_MSG(sum_bad == 0, "%d polygons' summed coverage differs from their area", sum_bad);
}

/* A polygon with a hole: even-odd with any orientation, non-zero with the
 * hole reversed; coverage equals outer minus hole per pixel. */
static void holes(void)
{
    check_rng rng = {4};
    int bad = 0;
    for (int trial = 0; trial < 300; trial++) {
        cg_vec2 p[48], outer[24], hole[24];
        /* Outer vertices at radius 9..15, consecutive ones under 90 degrees
         * apart (at least 8 of them), so every edge stays over 6 from the
         * centre; the hole is a small regular polygon of radius under 6. */
        int n1;
        do
            n1 = star_polygon(&rng, outer, 16, 16, 0.6, 15);
        while (n1 < 8);
        int n2 = (int)check_rng_int(&rng, 3, 10);
        double hr = check_rng_range(&rng, 0.5, 5.9);
        for (int i = 0; i < n2; i++) {
            double a = 2 * CG_PI * i / n2;
            hole[i] = cg_vec2_make(16 + hr * cos(a), 16 + hr * sin(a));
        }
        cg_fill_rule rule = trial % 2 ? CG_FILL_NONZERO : CG_FILL_EVEN_ODD;
        int reverse = rule == CG_FILL_NONZERO ? (area(outer, n1) > 0) == (area(hole, n2) > 0)
                                              : (int)check_rng_int(&rng, 0, 1);
        memcpy(p, outer, sizeof(cg_vec2) * n1);
        for (int i = 0; i < n2; i++)
            p[n1 + i] = hole[reverse ? n2 - 1 - i : i];
        int sizes[2] = {n1, n2};
        cg_image *im;
        cg_image_create(&im, 32, 32, CG_PIXEL_RGBAF);
        cg_paint paint = cg_paint_solid(white);
        cg_fill_polygon_aa(im, p, sizes, 2, rule, &paint);
        double worst = 0;
        for (int y = 0; y < 32; y++)
            for (int x = 0; x < 32; x++) {
                double exact = fabs(pixel_area(outer, n1, x, y)) - fabs(pixel_area(hole, n2, x, y));
                double e = fabs(cg_image_get(im, x, y).a - exact);
                if (e > worst)
                    worst = e;
            }
        if (worst > 1.0 / 256 && ++bad <= 3)
            fprintf(stderr, "hole trial %d: error %g\n", trial, worst);
        cg_image_free(im);
    }
    CHECK_MSG(bad == 0, "%d polygons with holes are off", bad);
}

/* Split along a shared edge into two contours of one fill: identical. */
static void split_aa(void)
{
    check_rng rng = {12};
    int bad = 0;
    for (int trial = 0; trial < 500; trial++) {
        int n = (int)check_rng_int(&rng, 4, 12);
        cg_vec2 p[12], both[26];
        double cx = check_rng_range(&rng, 8, 24), cy = check_rng_range(&rng, 8, 24);
        for (int i = 0; i < n; i++) {
            double a = 2 * CG_PI * (i + check_rng_range(&rng, 0, 0.8)) / n;
            p[i] = cg_vec2_make(cx + check_rng_range(&rng, 6, 7) * cos(a),
                                cy + check_rng_range(&rng, 6, 7) * sin(a));
        }
        int k = (int)check_rng_int(&rng, 2, n - 2), m = 0;
        for (int i = 0; i <= k; i++)
            both[m++] = p[i];
        int n1 = m;
        for (int i = k; i <= n; i++)
            both[m++] = p[i % n];
        int sizes[2] = {n1, m - n1};
        cg_image *a, *b;
        cg_image_create(&a, 32, 32, CG_PIXEL_RGBA8);
        cg_image_create(&b, 32, 32, CG_PIXEL_RGBA8);
        cg_rgba8 c = {40, 120, 220, 255};
        cg_paint paint = cg_paint_solid(c);
        cg_fill_rule rule = trial % 2 ? CG_FILL_NONZERO : CG_FILL_EVEN_ODD;
        cg_fill_polygon_aa(a, p, &n, 1, rule, &paint);
        cg_fill_polygon_aa(b, both, sizes, 2, CG_FILL_NONZERO, &paint);
        int worst = 0;
        for (size_t i = 0; i < 32 * 32 * 4; i++) {
            int d = abs(a->data[i] - b->data[i]);
            if (d > worst)
                worst = d;
        }
        if (worst > 1 && ++bad <= 3)
            fprintf(stderr, "aa split trial %d: differs by %d\n", trial, worst);
        cg_image_free(a);
        cg_image_free(b);
    }
    CHECK_MSG(bad == 0, "%d split polygons drawn as two differ from the whole", bad);
}

static double total_alpha(const cg_image *im)
{
    double s = 0;
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++)
            s += cg_image_get(im, x, y).a;
    return s;
}

/* Coverage is stored in 8 bits: each partly covered pixel may be off by
 * half a step. */
static double quantization(const cg_image *im)
{
    int partial = 0;
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++) {
            float a = cg_image_get(im, x, y).a;
            partial += a > 0 && a < 1;
        }
    return partial * 0.5 / 255 + 1e-6;
}

/* Strokes of straight segments: per pixel, a butt-capped segment is the
 * rectangle around it; totals for caps and joins match their areas. */
static void strokes(void)
{
    check_rng rng = {99};
    int bad = 0;
    cg_path *path;
    cg_path_create(&path);
    for (int trial = 0; trial < 500; trial++) {
        cg_vec2 a = {check_rng_range(&rng, 4, 28), check_rng_range(&rng, 4, 28)};
        cg_vec2 b = {check_rng_range(&rng, 4, 28), check_rng_range(&rng, 4, 28)};
        double width = check_rng_range(&rng, 0.2, 6);
        cg_path_reset(path);
        cg_path_move_to(path, a.x, a.y);
        cg_path_line_to(path, b.x, b.y);
        cg_stroke_style style = cg_stroke_style_default();
        style.width = width;
        style.cap = (cg_line_cap)(trial % 3);
        cg_image *im;
        cg_image_create(&im, 32, 32, CG_PIXEL_RGBAF);
        cg_paint paint = cg_paint_solid(white);
        CHECK(cg_stroke_path(im, path, &style, &paint) == CG_OK);
        cg_vec2 u = cg_vec2_normalize(cg_vec2_sub(b, a)), n = {-u.y * width / 2, u.x * width / 2};
        double len = cg_vec2_length(cg_vec2_sub(b, a)), expect;
        if (style.cap == CG_CAP_BUTT) {
            cg_vec2 rect[4] = {cg_vec2_add(a, n), cg_vec2_add(b, n), cg_vec2_sub(b, n),
                               cg_vec2_sub(a, n)};
            double worst = 0;
            for (int y = 0; y < 32; y++)
                for (int x = 0; x < 32; x++) {
                    double e = fabs(cg_image_get(im, x, y).a - fabs(pixel_area(rect, 4, x, y)));
                    if (e > worst)
                        worst = e;
                }
            if (worst > 1.0 / 256 && ++bad <= 3)
                fprintf(stderr, "stroke trial %d: pixel error %g\n", trial, worst);
            expect = len * width;
        } else if (style.cap == CG_CAP_SQUARE) {
            expect = (len + width) * width;
        } else {
            expect = len * width + CG_PI * width * width / 4;
        }
        /* Round caps are polygons within the 0.1 pixel tolerance. */
        double slack = (style.cap == CG_CAP_ROUND ? 0.1 * CG_PI * width : 0) + quantization(im);
        double got = total_alpha(im);
        if (fabs(got - expect) > slack && ++bad <= 6)
            fprintf(stderr, "stroke trial %d (cap %d): area %g expected %g\n", trial, style.cap,
                    got, expect);
        cg_image_free(im);
    }
    /* An L with each join: exact outline areas. */
    for (int join = 0; join < 3; join++) {
        double w = 4, l1 = 20, l2 = 16;
        cg_path_reset(path);
        cg_path_move_to(path, 4, 6);
        cg_path_line_to(path, 4 + l1, 6);
        cg_path_line_to(path, 4 + l1, 6 + l2);
        cg_stroke_style style = cg_stroke_style_default();
        style.width = w;
        style.join = (cg_line_join)join;
        cg_image *im;
        cg_image_create(&im, 40, 40, CG_PIXEL_RGBAF);
        cg_paint paint = cg_paint_solid(white);
        cg_stroke_path(im, path, &style, &paint);
        double expect = w * (l1 + l2);
        if (join == CG_JOIN_BEVEL)
            expect -= w * w / 8;
        if (join == CG_JOIN_ROUND)
            expect -= w * w / 4 - CG_PI * w * w / 16;
        CHECK_NEAR(total_alpha(im), expect, (join == CG_JOIN_ROUND ? 0.2 : 0) + quantization(im));
        cg_image_free(im);
    }
    /* A closed square outline: the annulus between the offsets. */
    cg_path_reset(path);
    cg_path_move_to(path, 8, 8);
    cg_path_line_to(path, 28, 8);
    cg_path_line_to(path, 28, 28);
    cg_path_line_to(path, 8, 28);
    cg_path_close(path);
    cg_stroke_style style = cg_stroke_style_default();
    style.width = 3;
    cg_image *im;
    cg_image_create(&im, 40, 40, CG_PIXEL_RGBAF);
    cg_paint paint = cg_paint_solid(white);
    cg_stroke_path(im, path, &style, &paint);
    CHECK_NEAR(total_alpha(im), 23.0 * 23 - 17.0 * 17, quantization(im));
    /* Dashes: on 4 off 2 along a 30-pixel line with butt caps: 5 dashes of 4. */
    cg_image_clear_rgba8(im, (cg_rgba8){0, 0, 0, 0});
    cg_path_reset(path);
    cg_path_move_to(path, 2, 10);
    cg_path_line_to(path, 32, 10);
    double dashes[2] = {4, 2};
    style.width = 2;
    style.dashes = dashes;
    style.dash_count = 2;
    cg_stroke_path(im, path, &style, &paint);
    CHECK_NEAR(total_alpha(im), 5 * 4 * 2, quantization(im));
    CHECK(cg_image_get(im, 7, 10).a < 0.01f); /* in the first gap: x 6..8 */
    CHECK(cg_image_get(im, 4, 10).a > 0.99f);
    /* Offset by 1: the pattern starts 1 into the first dash. */
    cg_image_clear_rgba8(im, (cg_rgba8){0, 0, 0, 0});
    style.dash_offset = 1;
    cg_stroke_path(im, path, &style, &paint);
    CHECK(cg_image_get(im, 4, 10).a > 0.99f); /* first dash 2..5, gap 5..7 */
    CHECK(cg_image_get(im, 5, 10).a < 0.01f);
    CHECK(cg_image_get(im, 7, 10).a > 0.99f);
    cg_image_free(im);
    CHECK_MSG(bad == 0, "%d strokes off their exact area", bad);
    cg_path_free(path);
}

static void bad_strokes(void)
{
    cg_path *path;
    cg_path_create(&path);
    cg_path_move_to(path, 1, 1);
    cg_path_line_to(path, 10, 10);
    cg_image *im;
    cg_image_create(&im, 16, 16, CG_PIXEL_RGBA8);
    cg_paint paint = cg_paint_solid(white);
    cg_stroke_style s = cg_stroke_style_default();
    s.width = -1;
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_EINVAL);
    s.width = NAN;
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_EINVAL);
    s.width = 0;
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_EINVAL);
    s.width = 1;
    s.miter_limit = 0.5;
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_EINVAL);
    s.miter_limit = 4;
    double neg[2] = {1, -1};
    s.dashes = neg;
    s.dash_count = 2;
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_EINVAL);
    double fine[1] = {1e-9};
    s.dashes = fine;
    s.dash_count = 1;
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_ERANGE);
    s.dash_count = 0;
    s.join = (cg_line_join)9;
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_EINVAL);
    cg_paint bad_paint = cg_paint_linear(cg_vec2_make(0, 0), cg_vec2_make(1, 1), NULL, 0);
    s = cg_stroke_style_default();
    CHECK(cg_stroke_path(im, path, &s, &bad_paint) == CG_EINVAL);
    /* Fine dashes with round caps of a huge width: the dash limit did not
     * count the caps' points (up to 100,000 each), so 1,300 dashes asked
     * for gigabytes; refused like too many dashes (found by fuzz_fill).
     * The same dashes with butt caps or a small width draw (below). */
    double fine_dash[1] = {0.01};
    s.dashes = fine_dash;
    s.dash_count = 1;
    s.cap = CG_CAP_ROUND;
    s.width = 274877906944.0;
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_ERANGE);
    s = cg_stroke_style_default();
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++)
            CHECK(cg_image_get_rgba8(im, x, y).a == 0);
    /* Paths refuse bad coordinates and stay unchanged. */
    CHECK(cg_path_line_to(path, NAN, 0) == CG_EINVAL);
    CHECK(cg_path_move_to(path, 0, INFINITY) == CG_EINVAL);
    CHECK(cg_path_line_to(path, 1e300, 0) == CG_EINVAL);
    CHECK(cg_path_arc(path, 5, 5, -1, 0, 1) == CG_EINVAL);
    CHECK(cg_path_arc(path, 5, 5, 1, 0, NAN) == CG_EINVAL);
    /* An empty path fills and strokes nothing. */
    cg_path_reset(path);
    CHECK(cg_path_is_empty(path));
    CHECK(cg_fill_path(im, path, CG_FILL_NONZERO, &paint) == CG_OK);
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_OK);
    cg_path_move_to(path, 3, 3); /* a bare move strokes nothing */
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_OK);
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++)
            CHECK(cg_image_get_rgba8(im, x, y).a == 0);
    /* A zero-length subpath with round caps is a dot. */
    cg_path_line_to(path, 3, 3);
    s.cap = CG_CAP_ROUND;
    s.width = 4;
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_OK);
    CHECK(cg_image_get_rgba8(im, 3, 3).a == 255);
    cg_path_reset(path);
    cg_path_move_to(path, 1, 1);
    cg_path_line_to(path, 10, 10);
    s.dashes = fine_dash;
    s.dash_count = 1;
    s.width = 2;
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_OK);
    s.cap = CG_CAP_BUTT;
    s.width = 274877906944.0;
    cg_image_clear_rgba8(im, (cg_rgba8){0, 0, 0, 0});
    CHECK(cg_stroke_path(im, path, &s, &paint) == CG_OK);
    CHECK(cg_image_get_rgba8(im, 8, 1).a > 0); /* half of every pixel */
    cg_image_free(im);
    cg_path_free(path);
}

static void svg_paths(void)
{
    cg_path *path;
    cg_path_create(&path);
    cg_error err;
    cg_image *a, *b;
    cg_image_create(&a, 32, 32, CG_PIXEL_RGBAF);
    cg_image_create(&b, 32, 32, CG_PIXEL_RGBAF);
    cg_paint paint = cg_paint_solid(white);
    /* The same square five ways. */
    const char *squares[] = {"M 4 4 L 20 4 L 20 20 L 4 20 Z", "M4,4 20,4 20,20 4,20z",
                             "m4 4 h16 v16 h-16 z", "M4 4H20V20H4Z",
                             "M 4e0 .4e1 l 16 0 0 16 -16 0 Z"};
    for (int i = 0; i < 5; i++) {
        cg_path_reset(path);
        CHECK_MSG(cg_path_append_svg(path, squares[i], &err) == CG_OK, "%s: %s", squares[i],
                  err.message);
        cg_image_clear_rgba8(a, (cg_rgba8){0, 0, 0, 0});
        cg_fill_path(a, path, CG_FILL_NONZERO, &paint);
        CHECK_NEAR(total_alpha(a), 256, 1e-3);
        CHECK(cg_image_get(a, 4, 4).a == 1 && cg_image_get(a, 20, 4).a == 0);
    }
    /* A circle from two SVG arcs: area pi r^2 within the flattening. */
    cg_path_reset(path);
    CHECK(cg_path_append_svg(path, "M 6 16 A 10 10 0 0 1 26 16 A 10 10 0 1 1 6 16 Z", &err)
          == CG_OK);
    cg_image_clear_rgba8(a, (cg_rgba8){0, 0, 0, 0});
    cg_fill_path(a, path, CG_FILL_NONZERO, &paint);
    CHECK_NEAR(total_alpha(a), CG_PI * 100, 0.1 * 2 * CG_PI * 10);
    /* Arcs with radii too small are scaled up: a half circle of radius 5. */
    cg_path_reset(path);
    CHECK(cg_path_append_svg(path, "M 6 16 a 1 1 0 0 0 10 0 z", &err) == CG_OK);
    cg_image_clear_rgba8(a, (cg_rgba8){0, 0, 0, 0});
    cg_fill_path(a, path, CG_FILL_NONZERO, &paint);
    CHECK_NEAR(total_alpha(a), CG_PI * 25 / 2, 0.1 * CG_PI * 5 + 0.1);
    CHECK(cg_image_get(a, 11, 19).a > 0.99f); /* sweep 0 from left to right bulges down (+y) */
    /* cg_path_arc: a full circle. */
    cg_path_reset(path);
    cg_path_arc(path, 16, 16, 8, 0, 2 * CG_PI);
    cg_image_clear_rgba8(b, (cg_rgba8){0, 0, 0, 0});
    cg_fill_path(b, path, CG_FILL_EVEN_ODD, &paint);
    CHECK_NEAR(total_alpha(b), CG_PI * 64, 0.1 * 2 * CG_PI * 8);
    /* Malformed data: a clear message, the path unchanged. */
    const char *bad[] = {
        "L 10 10",     "M 10",    "M 10 10 L 5", "M 1e999 0",      "M 10 10 A 5 5 0 2 1 0 0",
        "M 10 10 X 4", "M nan 4", "M 0x10 4",    "M 10 10 L 4 4 Q"};
    for (int i = 0; i < (int)(sizeof bad / sizeof bad[0]); i++) {
        cg_path_reset(path);
        cg_path_move_to(path, 1, 1);
        CHECK_MSG(cg_path_append_svg(path, bad[i], &err) == CG_EFORMAT, "'%s' accepted", bad[i]);
        CHECK_MSG(strstr(err.message, "offset") != NULL, "'%s': message '%s'", bad[i], err.message);
        CHECK(cg_path_is_empty(path));
    }
    CHECK(cg_path_append_svg(path, "", &err) == CG_OK);
    CHECK(cg_path_append_svg(path, "  ", &err) == CG_OK);
    cg_image_free(a);
    cg_image_free(b);
    cg_path_free(path);
}

static int same_image(const cg_image *a, const cg_image *b)
{
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            cg_rgbaf p = cg_image_get(a, x, y), q = cg_image_get(b, x, y);
            if (fabsf(p.a - q.a) > 1e-6f)
                return 0;
        }
    return 1;
}

/* Quadratic and cubic Beziers, flattened by the curve module: areas of a
 * parabolic segment and of the four-cubic circle; the SVG smooth and
 * relative forms draw the same shapes as the absolute ones. */
static void curves(void)
{
    cg_path *path;
    cg_path_create(&path);
    cg_image *a, *b;
    cg_image_create(&a, 64, 64, CG_PIXEL_RGBAF);
    cg_image_create(&b, 64, 64, CG_PIXEL_RGBAF);
    cg_paint paint = cg_paint_solid(white);
    cg_error err;
    /* Parabolic segment: chord 40, apex 20 above it (control 40 above):
     * area 2/3 * 40 * 20. */
    CHECK(cg_path_append_svg(path, "M 10 50 Q 30 10 50 50 Z", &err) == CG_OK);
    CHECK(cg_fill_path(a, path, CG_FILL_NONZERO, &paint) == CG_OK);
    CHECK_NEAR(total_alpha(a), 2.0 / 3 * 40 * 20, 0.1 * 80 + quantization(a));
    /* A circle of radius 25 from four cubics (k = 0.5523): pi r^2 within
     * the approximation (about 3e-4 of the radius) and the flattening. */
    double r = 25, k = 0.5522847498 * r;
    cg_path_reset(path);
    cg_path_move_to(path, 32 + r, 32);
    cg_path_cubic_to(path, 32 + r, 32 + k, 32 + k, 32 + r, 32, 32 + r);
    cg_path_cubic_to(path, 32 - k, 32 + r, 32 - r, 32 + k, 32 - r, 32);
    cg_path_cubic_to(path, 32 - r, 32 - k, 32 - k, 32 - r, 32, 32 - r);
    cg_path_cubic_to(path, 32 + k, 32 - r, 32 + r, 32 - k, 32 + r, 32);
    cg_path_close(path);
    cg_image_clear_rgba8(a, (cg_rgba8){0, 0, 0, 0});
    CHECK(cg_fill_path(a, path, CG_FILL_EVEN_ODD, &paint) == CG_OK);
    CHECK_NEAR(total_alpha(a), CG_PI * r * r, 0.1 * 2 * CG_PI * r + quantization(a));
    /* Smooth and relative forms. */
    const char *pairs[][2] = {
        {"M 8 40 C 8 10 30 10 30 40 C 30 70 56 70 56 40 Z",
         "M 8 40 c 0 -30 22 -30 22 0 s 26 30 26 0 z"},
        {"M 8 40 Q 20 10 32 40 Q 44 70 56 40 Z", "m 8 40 q 12 -30 24 0 t 24 0 z"},
        {"M 8 8 L 40 8 L 40 40 Z", "M 8 8 H 40 V 40 z"},
    };
    for (int i = 0; i < 3; i++) {
        cg_image_clear_rgba8(a, (cg_rgba8){0, 0, 0, 0});
        cg_image_clear_rgba8(b, (cg_rgba8){0, 0, 0, 0});
        cg_path_reset(path);
        CHECK(cg_path_append_svg(path, pairs[i][0], &err) == CG_OK);
        cg_fill_path(a, path, CG_FILL_NONZERO, &paint);
        cg_path_reset(path);
        CHECK(cg_path_append_svg(path, pairs[i][1], &err) == CG_OK);
        cg_fill_path(b, path, CG_FILL_NONZERO, &paint);
        CHECK_MSG(same_image(a, b), "'%s' and '%s' differ", pairs[i][0], pairs[i][1]);
        CHECK(total_alpha(a) > 100);
    }
    /* A curve with NaN control points is refused. */
    CHECK(cg_path_cubic_to(path, NAN, 0, 1, 1, 2, 2) == CG_EINVAL);
    cg_image_free(a);
    cg_image_free(b);
    cg_path_free(path);
}

/* Curves and arcs far larger than the image: only the part near it costs
 * anything, and the part inside is right. */
static void huge_curves(void)
{
    cg_path *path;
    cg_path_create(&path);
    cg_image *im;
    cg_image_create(&im, 32, 32, CG_PIXEL_RGBAF);
    cg_paint paint = cg_paint_solid(white);
    for (int kind = 0; kind < 2; kind++) {
        double r = 1e11, cx = 16.5 + r, cy = 16; /* leftmost point at x = 16.5 */
        cg_path_reset(path);
        if (kind == 0) {
            cg_path_arc(path, cx, cy, r, 0, 2 * CG_PI);
        } else {
            double k = 0.5522847498 * r;
            cg_path_move_to(path, cx + r, cy);
            cg_path_cubic_to(path, cx + r, cy + k, cx + k, cy + r, cx, cy + r);
            cg_path_cubic_to(path, cx - k, cy + r, cx - r, cy + k, cx - r, cy);
            cg_path_cubic_to(path, cx - r, cy - k, cx - k, cy - r, cx, cy - r);
            cg_path_cubic_to(path, cx + k, cy - r, cx + r, cy - k, cx + r, cy);
        }
        cg_image_clear_rgba8(im, (cg_rgba8){0, 0, 0, 0});
        CHECK(cg_fill_path(im, path, CG_FILL_NONZERO, &paint) == CG_OK);
        int wrong = 0;
        for (int y = 0; y < 32; y++)
            for (int x = 0; x < 32; x++) {
                float a = cg_image_get(im, x, y).a, want = x < 16 ? 0.0f : x == 16 ? 0.5f : 1.0f;
                wrong += fabsf(a - want) > 0.01f;
            }
        CHECK_MSG(wrong == 0, "huge %s: %d pixels wrong", kind ? "cubics" : "arc", wrong);
        /* and its stroke: a band 4 wide around x = 16.5 */
        cg_stroke_style style = cg_stroke_style_default();
        style.width = 4;
        cg_image_clear_rgba8(im, (cg_rgba8){0, 0, 0, 0});
        CHECK(cg_stroke_path(im, path, &style, &paint) == CG_OK);
        CHECK(cg_image_get(im, 16, 10).a > 0.99f && cg_image_get(im, 13, 10).a < 0.01f
              && cg_image_get(im, 20, 10).a < 0.01f);
    }
    cg_image_free(im);
    cg_path_free(path);
}

/* Partial coverage blends like cg_image_blend with alpha scaled by the
 * coverage, over opaque, translucent and transparent pixels. */
static void aa_blending(void)
{
    check_rng rng = {21};
    int bad = 0;
    for (int t = 0; t < 300; t++) {
        cg_rgba8 bg = {(uint8_t)check_rng_int(&rng, 0, 255), (uint8_t)check_rng_int(&rng, 0, 255),
                       (uint8_t)check_rng_int(&rng, 0, 255),
                       (uint8_t)(t % 3 == 0   ? 0
                                 : t % 3 == 1 ? 255
                                              : check_rng_int(&rng, 1, 254))};
        cg_rgba8 fg = {(uint8_t)check_rng_int(&rng, 0, 255), (uint8_t)check_rng_int(&rng, 0, 255),
                       (uint8_t)check_rng_int(&rng, 0, 255),
                       (uint8_t)(t % 2 ? 255 : check_rng_int(&rng, 0, 255))};
        double cover = check_rng_range(&rng, 0.05, 0.95);
        cg_image *a, *b;
        cg_image_create(&a, 2, 1, CG_PIXEL_RGBA8);
        cg_image_clear_rgba8(a, bg);
        cg_image_copy(a, &b);
        cg_vec2 rect[4] = {{0, 0}, {cover, 0}, {cover, 1}, {0, 1}};
        int four = 4;
        cg_paint paint = cg_paint_solid(fg);
        cg_fill_polygon_aa(a, rect, &four, 1, CG_FILL_NONZERO, &paint);
        cg_rgbaf src = cg_rgba8_to_linear(fg);
        src.a *= (float)(floor(cover * 255 + 0.5) / 255); /* coverage is kept in 8 bits */
        cg_image_blend(b, 0, 0, src);
        cg_rgba8 p = cg_image_get_rgba8(a, 0, 0), q = cg_image_get_rgba8(b, 0, 0);
        if ((abs(p.r - q.r) > 1 || abs(p.g - q.g) > 1 || abs(p.b - q.b) > 1 || abs(p.a - q.a) > 1)
            && ++bad <= 5)
            fprintf(stderr, "aa blend %d: %d,%d,%d,%d vs %d,%d,%d,%d\n", t, p.r, p.g, p.b, p.a, q.r,
                    q.g, q.b, q.a);
        cg_image_free(a);
        cg_image_free(b);
    }
    CHECK_MSG(bad == 0, "%d partly covered pixels blend differently from cg_image_blend", bad);
}

/* The same through one reused rasterizer (whose cache of blends then sees
 * many pixel and coverage pairs, and colour changes), with colours from a
 * small palette so pixels often already have the paint's colour: blending a
 * colour over itself must leave the colour exactly and change only alpha. */
static void aa_blending_reused(void)
{
    check_rng rng = {22};
    cg_rasterizer *r;
    CHECK(cg_rasterizer_create(&r) == CG_OK);
    cg_image *a, *b;
    cg_image_create(&a, 2, 1, CG_PIXEL_RGBA8);
    cg_image_create(&b, 2, 1, CG_PIXEL_RGBA8);
    const cg_rgba8 palette[4] = {{30, 60, 200, 255},
                                 {255, 255, 255, 255},
                                 {0, 0, 0, 255},
                                 {200, 30, 90, 160}};
    int bad = 0, same_bad = 0;
    cg_rgba8 fg = palette[0], bg = palette[0];
    for (int t = 0; t < 4000; t++) {
        if (t % 8 == 0) { /* groups of 8: one colour over one pixel value at 8 coverages */
            int g = t / 8;
            fg = palette[check_rng_int(&rng, 0, 3)];
            bg = palette[check_rng_int(&rng, 0, 3)];
            if (g % 5 == 0)
                bg = (cg_rgba8){(uint8_t)check_rng_int(&rng, 0, 255),
                                (uint8_t)check_rng_int(&rng, 0, 255),
                                (uint8_t)check_rng_int(&rng, 0, 255), 255};
            bg.a = (uint8_t)(g % 3 == 0 ? 255 : g % 3 == 1 ? check_rng_int(&rng, 1, 254) : 0);
        }
        double cover = (double)check_rng_int(&rng, 1, 254) / 255;
        cg_image_clear_rgba8(a, bg);
        cg_image_clear_rgba8(b, bg);
        cg_vec2 rect[4] = {{0, 0}, {cover, 0}, {cover, 1}, {0, 1}};
        int four = 4;
        cg_paint paint = cg_paint_solid(fg);
        CHECK(cg_rasterizer_fill_polygon_aa(r, a, rect, &four, 1, CG_FILL_EVEN_ODD, &paint)
              == CG_OK);
        cg_rgbaf src = cg_rgba8_to_linear(fg);
        src.a *= (float)(floor(cover * 255 + 0.5) / 255);
        cg_image_blend(b, 0, 0, src);
        cg_rgba8 p = cg_image_get_rgba8(a, 0, 0), q = cg_image_get_rgba8(b, 0, 0);
        if ((abs(p.r - q.r) > 1 || abs(p.g - q.g) > 1 || abs(p.b - q.b) > 1 || abs(p.a - q.a) > 1)
            && ++bad <= 5)
            fprintf(stderr, "reused aa blend %d: %d,%d,%d,%d vs %d,%d,%d,%d\n", t, p.r, p.g, p.b,
                    p.a, q.r, q.g, q.b, q.a);
        if (bg.a > 0 && bg.r == fg.r && bg.g == fg.g && bg.b == fg.b
            && (p.r != fg.r || p.g != fg.g || p.b != fg.b))
            same_bad++;
    }
    CHECK_MSG(bad == 0, "%d partly covered pixels blend differently from cg_image_blend", bad);
    CHECK_MSG(same_bad == 0, "%d pixels changed colour under paint of their own colour", same_bad);
    cg_image_free(a);
    cg_image_free(b);
    cg_rasterizer_free(r);
}

/* The rasterizer's blend of a solid paint (fill_solid_cached: its direct
 * blend of opaque paint over opaque and transparent pixels, its cache, its
 * own-colour shortcut) against fill_solid_pixel, bit for bit: every
 * coverage over every code of each channel, for opaque and translucent
 * paints over opaque, transparent and translucent pixels. */
static void aa_blend_exact(void)
{
    check_rng rng = {24};
    cg_rasterizer *r;
    CHECK(cg_rasterizer_create(&r) == CG_OK);
    cg_image *im;
    CHECK(cg_image_create(&im, 1, 1, CG_PIXEL_RGBA8) == CG_OK);
    cg_rgba8 paints[10] = {{30, 60, 200, 255}, {200, 90, 40, 255}, {255, 255, 255, 255},
                           {0, 0, 0, 255},     {1, 254, 128, 255}, {200, 30, 90, 160},
                           {90, 10, 30, 0}};
    for (int i = 7; i < 10; i++)
        paints[i] = (cg_rgba8){(uint8_t)check_rng_int(&rng, 0, 255),
                               (uint8_t)check_rng_int(&rng, 0, 255),
                               (uint8_t)check_rng_int(&rng, 0, 255),
                               (uint8_t)(i % 2 ? 255 : check_rng_int(&rng, 1, 254))};
    long bad = 0, tried = 0;
    for (int i = 0; i < 10; i++) {
        cg_paint paint = cg_paint_solid(paints[i]);
        fill_painter p;
        CHECK(fill_painter_init(&p, r, im, &paint) == CG_OK);
        fill_blend_state s = fill_blend_begin(&p);
        for (int k = 0; k < 256; k++)
            for (int alpha = 0; alpha < 4; alpha++) {
                /* every code in each channel, in three arrangements; the
                 * paint's own colour too */
                cg_rgba8 d = {(uint8_t)k, (uint8_t)(255 - k), (uint8_t)(k * 7), 255};
                if (k == 3)
                    d = paints[i];
                d.a = (uint8_t)(alpha == 0 ? 255 : alpha == 1 ? 0 : alpha == 2 ? 1 + k % 254 : 255);
                if (alpha == 3)
                    d.g = d.b = (uint8_t)k;
                for (int c = 0; c < 256; c++) {
                    cg_rgba8 want = d, got = d;
                    fill_solid_pixel(&p, &want, c);
                    uint32_t v;
                    memcpy(&v, &got, sizeof v);
                    fill_solid_cached(&s, &v, c);
                    fill_solid_cached(&s, &v, 0); /* nothing */
                    memcpy(&got, &v, sizeof got);
                    tried++;
                    if (memcmp(&got, &want, sizeof got) != 0 && ++bad <= 5)
                        fprintf(stderr,
                                "blend of %d,%d,%d,%d over %d,%d,%d,%d at %d: %d,%d,%d,%d vs "
                                "%d,%d,%d,%d\n",
                                paints[i].r, paints[i].g, paints[i].b, paints[i].a, d.r, d.g, d.b,
                                d.a, c, got.r, got.g, got.b, got.a, want.r, want.g, want.b, want.a);
                }
            }
    }
    CHECK_MSG(tried == 10L * 256 * 4 * 256, "tried %ld blends", tried);
    CHECK_MSG(bad == 0, "%ld of %ld blends differ from fill_solid_pixel", bad, tried);
    cg_image_free(im);
    cg_rasterizer_free(r);
}

/* Opaque paints over opaque images of many colours through one reused
 * rasterizer, paints alternating between colours (so no state a rasterizer
 * keeps from one paint may leak into the next): every pixel equals
 * cg_image_blend of the paint with alpha = the pixel's coverage, taken from
 * the same polygon filled over a transparent image. */
static void aa_opaque_over_opaque(void)
{
    check_rng rng = {23};
    cg_rasterizer *r;
    CHECK(cg_rasterizer_create(&r) == CG_OK);
    const int size = 48;
    cg_image *im, *expect, *cover;
    cg_image_create(&im, size, size, CG_PIXEL_RGBA8);
    cg_image_create(&expect, size, size, CG_PIXEL_RGBA8);
    cg_image_create(&cover, size, size, CG_PIXEL_RGBA8);
    const cg_rgba8 palette[5] = {{30, 60, 200, 255},
                                 {200, 90, 40, 255},
                                 {255, 255, 255, 255},
                                 {0, 0, 0, 255},
                                 {17, 240, 128, 255}};
    for (int y = 0; y < size; y++)
        for (int x = 0; x < size; x++) {
            cg_rgba8 c = x < size / 2 ? palette[check_rng_int(&rng, 0, 4)]
                                      : (cg_rgba8){(uint8_t)check_rng_int(&rng, 0, 255),
                                                   (uint8_t)check_rng_int(&rng, 0, 255),
                                                   (uint8_t)check_rng_int(&rng, 0, 255), 255};
            cg_image_set_rgba8(im, x, y, c);
        }
    int bad = 0, partial = 0;
    for (int t = 0; t < 120; t++) {
        cg_vec2 p[32];
        int n = star_polygon(&rng, p, check_rng_range(&rng, 0, size),
                             check_rng_range(&rng, 0, size), 0.3, check_rng_range(&rng, 4, 30));
        cg_paint paint = cg_paint_solid(palette[t % 2 ? 1 : check_rng_int(&rng, 0, 4)]);
        memset(cover->data, 0, (size_t)cover->stride * size);
        CHECK(cg_rasterizer_fill_polygon_aa(r, cover, p, &n, 1, CG_FILL_NONZERO, &paint) == CG_OK);
        memcpy(expect->data, im->data, (size_t)im->stride * size);
        CHECK(cg_rasterizer_fill_polygon_aa(r, im, p, &n, 1, CG_FILL_NONZERO, &paint) == CG_OK);
        cg_rgbaf src = cg_rgba8_to_linear(paint.color);
        for (int y = 0; y < size; y++)
            for (int x = 0; x < size; x++) {
                int c = cg_image_get_rgba8(cover, x, y).a;
                if (c == 0)
                    continue;
                partial += c < 255;
                cg_rgbaf s = src;
                s.a = c / 255.0f;
                cg_image_blend(expect, x, y, s);
                cg_rgba8 a = cg_image_get_rgba8(im, x, y), b = cg_image_get_rgba8(expect, x, y);
                if ((abs(a.r - b.r) > 1 || abs(a.g - b.g) > 1 || abs(a.b - b.b) > 1 || a.a != 255)
                    && ++bad <= 5)
                    fprintf(stderr, "opaque over opaque %d (%d,%d) c %d: %d,%d,%d,%d vs %d,%d,%d\n",
                            t, x, y, c, a.r, a.g, a.b, a.a, b.r, b.g, b.b);
            }
    }
    CHECK_MSG(partial > 1000, "only %d partly covered pixels", partial);
    CHECK_MSG(bad == 0, "%d pixels blend differently from cg_image_blend", bad);
    cg_image_free(im);
    cg_image_free(expect);
    cg_image_free(cover);
    cg_rasterizer_free(r);
}

/* Wide shapes (interior runs long enough for the wide-store path) over
 * random opaque backgrounds through one reused rasterizer, paints
 * alternating: where the same polygon covers a pixel fully (alpha exactly
 * 1 in an RGBAF image, another painting path) the pixel has exactly the
 * paint's colour; where it does not touch it, the pixel is unchanged. */
static void aa_wide_interiors(void)
{
    check_rng rng = {4141};
    cg_rasterizer *r;
    CHECK(cg_rasterizer_create(&r) == CG_OK);
    const cg_rgba8 inks[2] = {{30, 60, 200, 255}, {200, 90, 40, 255}};
    int bad = 0, full = 0;
    for (int t = 0; t < 200; t++) {
        int w = (int)check_rng_int(&rng, 60, 400), h = (int)check_rng_int(&rng, 1, 16);
        cg_image *im, *before, *cover;
        cg_image_create(&im, w, h, CG_PIXEL_RGBA8);
        cg_image_create(&before, w, h, CG_PIXEL_RGBA8);
        cg_image_create(&cover, w, h, CG_PIXEL_RGBAF);
        for (size_t i = 0; i < (size_t)im->stride * (size_t)h; i++)
            im->data[i] = (i & 3) == 3 ? 255 : (uint8_t)check_rng_int(&rng, 0, 255);
        memcpy(before->data, im->data, (size_t)im->stride * (size_t)h);
        cg_vec2 p[32];
        int n = star_polygon(&rng, p, w / 2.0, h / 2.0, 0.6, w * 0.7);
        for (int i = 0; i < n; i++) /* squashed to the image's height and past it */
            p[i].y = h / 2.0 + (p[i].y - h / 2.0) * (h + 6.0) / (w * 1.4);
        cg_fill_rule rule = t % 3 ? CG_FILL_NONZERO : CG_FILL_EVEN_ODD;
        cg_paint paint = cg_paint_solid(inks[t % 2]);
        CHECK(cg_rasterizer_fill_polygon_aa(r, cover, p, &n, 1, rule, &paint) == CG_OK);
        CHECK(cg_rasterizer_fill_polygon_aa(r, im, p, &n, 1, rule, &paint) == CG_OK);
        int wrong = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                float a = cg_image_get(cover, x, y).a;
                if (a > 0 && a < 1)
                    continue;
                full += a == 1;
                cg_rgba8 got = cg_image_get_rgba8(im, x, y);
                cg_rgba8 expect = a == 1 ? inks[t % 2] : cg_image_get_rgba8(before, x, y);
                wrong += memcmp(&got, &expect, sizeof got) != 0;
            }
        if (wrong && ++bad <= 5)
            fprintf(stderr, "aa wide trial %d (%dx%d): %d pixels differ\n", t, w, h, wrong);
        cg_image_free(im);
        cg_image_free(before);
        cg_image_free(cover);
    }
    CHECK_MSG(full > 100000, "only %d fully covered pixels", full);
    CHECK_MSG(bad == 0, "%d wide shapes differ in their interiors or outside", bad);
    cg_rasterizer_free(r);
}

/* Even-odd against non-zero on a pentagram; gradients; linear light. */
static void rules_and_paints(void)
{
    cg_vec2 star[5];
    for (int i = 0; i < 5; i++) {
        double a = -CG_PI / 2 + i * 4 * CG_PI / 5;
        star[i] = cg_vec2_make(16 + 14 * cos(a), 16 + 14 * sin(a));
    }
    int five = 5;
    cg_image *im;
    cg_image_create(&im, 32, 32, CG_PIXEL_RGBA8);
    cg_paint paint = cg_paint_solid(white);
    cg_fill_polygon_aa(im, star, &five, 1, CG_FILL_EVEN_ODD, &paint);
    CHECK(cg_image_get_rgba8(im, 16, 16).a == 0);
    CHECK(cg_image_get_rgba8(im, 15, 8).a == 255 && cg_image_get_rgba8(im, 16, 8).a == 255);
    cg_fill_polygon_aa(im, star, &five, 1, CG_FILL_NONZERO, &paint);
    CHECK(cg_image_get_rgba8(im, 16, 16).a == 255);
    /* Half coverage of white over opaque black is linear 0.5: code 188. */
    cg_image_clear_rgba8(im, (cg_rgba8){0, 0, 0, 255});
    cg_vec2 half[4] = {{0, 0}, {10.5, 0}, {10.5, 32}, {0, 32}};
    int four = 4;
    cg_fill_polygon_aa(im, half, &four, 1, CG_FILL_NONZERO, &paint);
    CHECK_EQ_INT(cg_image_get_rgba8(im, 10, 5).r, 188);
    CHECK_EQ_INT(cg_image_get_rgba8(im, 9, 5).r, 255);
    CHECK_EQ_INT(cg_image_get_rgba8(im, 11, 5).r, 0);
    /* Linear gradient black to white along x: monotonic, ends pinned. */
    cg_gradient_stop stops[2] = {{0, {0, 0, 0, 255}}, {1, {255, 255, 255, 255}}};
    cg_paint lin = cg_paint_linear(cg_vec2_make(4, 0), cg_vec2_make(28, 0), stops, 2);
    cg_vec2 all[4] = {{0, 0}, {32, 0}, {32, 32}, {0, 32}};
    CHECK(cg_fill_polygon_aa(im, all, &four, 1, CG_FILL_NONZERO, &lin) == CG_OK);
    CHECK_EQ_INT(cg_image_get_rgba8(im, 0, 3).r, 0);
    CHECK_EQ_INT(cg_image_get_rgba8(im, 31, 3).r, 255);
    int monotonic = 1;
    for (int x = 1; x < 32; x++)
        monotonic &= cg_image_get_rgba8(im, x, 3).r >= cg_image_get_rgba8(im, x - 1, 3).r;
    CHECK(monotonic);
    /* Middle of the gradient is linear 0.5 (interpolated in linear light). */
    for (int x = 4; x < 28; x++)
        CHECK(abs(cg_image_get_rgba8(im, x, 3).r - cg_linear_to_srgb8((float)((x + 0.5 - 4) / 24)))
              <= 2);
    /* Radial: centre is the first stop, far corner the last. */
    cg_paint rad = cg_paint_radial(cg_vec2_make(16, 16), 10, stops, 2);
    CHECK(cg_fill_polygon_aa(im, all, &four, 1, CG_FILL_NONZERO, &rad) == CG_OK);
    CHECK(cg_image_get_rgba8(im, 16, 16).r <= cg_linear_to_srgb8(0.08f));
    CHECK_EQ_INT(cg_image_get_rgba8(im, 0, 0).r, 255);
    /* Bad gradients. */
    cg_gradient_stop backwards[2] = {{0.8, {0, 0, 0, 255}}, {0.2, {255, 255, 255, 255}}};
    cg_paint bad = cg_paint_linear(cg_vec2_make(0, 0), cg_vec2_make(1, 0), backwards, 2);
    CHECK(cg_fill_polygon_aa(im, all, &four, 1, CG_FILL_NONZERO, &bad) == CG_EINVAL);
    bad = cg_paint_radial(cg_vec2_make(0, 0), -1, stops, 2);
    CHECK(cg_fill_polygon_aa(im, all, &four, 1, CG_FILL_NONZERO, &bad) == CG_EINVAL);
    /* NaN polygon: refused, nothing drawn. */
    cg_image_clear_rgba8(im, (cg_rgba8){0, 0, 0, 0});
    cg_vec2 nan_poly[3] = {{1, 1}, {20, NAN}, {3, 20}};
    int three = 3;
    CHECK(cg_fill_polygon_aa(im, nan_poly, &three, 1, CG_FILL_NONZERO, &paint) == CG_EINVAL);
    CHECK(total_alpha(im) == 0);
    /* Huge valid coordinates: a triangle covering everything. */
    cg_vec2 big[3] = {{-1e11, -1e11}, {1e11, -1e9}, {-1e9, 1e11}};
    CHECK(cg_fill_polygon_aa(im, big, &three, 1, CG_FILL_NONZERO, &paint) == CG_OK);
    CHECK_NEAR(total_alpha(im), 32 * 32, 1e-3);
    cg_image_free(im);
}

/* Two distinct points a subnormal distance apart: the segment's direction
 * is still exact (the reciprocal of its length would overflow and give NaN
 * outline points).  Found by fuzz_fill. */
static void tiny_segments(void)
{
    const double tiny = 4.9406564584124654e-324, small = 1e-300;
    for (int diagonal = 0; diagonal < 2; diagonal++) {
        cg_image *a, *b;
        cg_image_create(&a, 16, 16, CG_PIXEL_RGBA8);
        cg_image_create(&b, 16, 16, CG_PIXEL_RGBA8);
        cg_path *pa, *pb;
        cg_path_create(&pa);
        cg_path_create(&pb);
        /* no move: the path starts at the origin, as in SVG */
        cg_path_line_to(pa, tiny, diagonal ? tiny : 0);
        cg_path_line_to(pa, 12, 12);
        cg_path_line_to(pb, small, diagonal ? small : 0);
        cg_path_line_to(pb, 12, 12);
        cg_stroke_style s = cg_stroke_style_default();
        s.width = 3;
        cg_paint paint = cg_paint_solid(white);
        CHECK(cg_stroke_path(a, pa, &s, &paint) == CG_OK);
        CHECK(cg_stroke_path(b, pb, &s, &paint) == CG_OK);
        CHECK(memcmp(a->data, b->data, a->stride * 16) == 0);
        CHECK(cg_image_get_rgba8(a, 6, 6).a == 255);
        cg_path_free(pa);
        cg_path_free(pb);
        cg_image_free(a);
        cg_image_free(b);
    }
}

/* Edges a few units in the last place off vertical, crossing an integer x
 * (a contour of an Adwaita icon closed from x = 56 - 1 ulp to x = 56 over
 * 25 rows): each row's span was deposited as the line's slope times its
 * width, which rounding made 25 times the row's height, and a row of the
 * image filled to the right edge.  Every pixel must hold the exact area. */
static void near_vertical(void)
{
    check_rng rng = {4242};
    int bad = 0, cases = 0;
    for (int n = 0; n < 60; n++) {
        double x = (double)check_rng_int(&rng, 38, 70), top = check_rng_range(&rng, 1, 20);
        double bottom = top + check_rng_range(&rng, 20, 30);
        int ulps = (int)check_rng_int(&rng, 1, 3);
        double off = x;
        for (int i = 0; i < ulps; i++)
            off = nextafter(off, n % 2 ? 0 : 200);
        /* the shape lies right of the edge from (off, bottom) up to (x, top) */
        cg_vec2 p[6] = {{x, top},  {x + 16.125, top}, {x + 16.125, bottom},
                        {102, 98}, {34, 112},         {off, bottom}};
        cg_image *im;
        cg_image_create(&im, 128, 128, CG_PIXEL_RGBA8);
        int six = 6;
        cg_paint paint = cg_paint_solid(white);
        CHECK(cg_fill_polygon_aa(im, p, &six, 1, CG_FILL_NONZERO, &paint) == CG_OK);
        int y0 = (int)top - 1, y1 = (int)bottom + 2;
        for (int py = y0; py < y1; py++)
            for (int px = 0; px < 128; px++) {
                double want = fabs(pixel_area(p, 6, px, py));
                bad += fabs(cg_image_get_rgba8(im, px, py).a / 255.0 - want) > 1.0 / 255;
            }
        cases++;
        cg_image_free(im);
    }
    CHECK_MSG(bad == 0, "%d pixels beside near-vertical edges off in %d shapes", bad, cases);
}

/* A path ending with a quadratic piece: flattening read two coordinates
 * beyond it (a cubic's), past the end of the coordinate array when that was
 * full (AddressSanitizer).  Every count of lines before the quad meets a
 * full array once; filling with and without a final close must agree.
 * Found by fuzz_fill. */
static void final_quads(void)
{
    for (int lines = 0; lines < 70; lines++) {
        cg_path *open_path, *closed;
        cg_path_create(&open_path);
        cg_path_create(&closed);
        cg_path *both[2] = {open_path, closed};
        for (int k = 0; k < 2; k++) {
            cg_path_move_to(both[k], 2, 2);
            for (int i = 0; i < lines; i++)
                cg_path_line_to(both[k], 2 + (i % 7), 14 - (i % 5));
            cg_path_quad_to(both[k], 16, 2, 14, 14);
        }
        cg_path_close(closed);
        cg_image *a, *b;
        cg_image_create(&a, 16, 16, CG_PIXEL_RGBA8);
        cg_image_create(&b, 16, 16, CG_PIXEL_RGBA8);
        cg_paint paint = cg_paint_solid(white);
        CHECK(cg_fill_path(a, open_path, CG_FILL_NONZERO, &paint) == CG_OK);
        CHECK(cg_fill_path(b, closed, CG_FILL_NONZERO, &paint) == CG_OK);
        CHECK(memcmp(a->data, b->data, a->stride * 16) == 0);
        cg_stroke_style s = cg_stroke_style_default();
        CHECK(cg_stroke_path(a, open_path, &s, &paint) == CG_OK);
        cg_path_free(open_path);
        cg_path_free(closed);
        cg_image_free(a);
        cg_image_free(b);
    }
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(coverage_is_area);
    CHECK_GROUP(holes);
    CHECK_GROUP(split_aa);
    CHECK_GROUP(strokes);
    CHECK_GROUP(bad_strokes);
    CHECK_GROUP(tiny_segments);
    CHECK_GROUP(near_vertical);
    CHECK_GROUP(svg_paths);
    CHECK_GROUP(curves);
    CHECK_GROUP(final_quads);
    CHECK_GROUP(aa_blending);
    CHECK_GROUP(aa_blending_reused);
    CHECK_GROUP(aa_blend_exact);
    CHECK_GROUP(aa_opaque_over_opaque);
    CHECK_GROUP(aa_wide_interiors);
    CHECK_GROUP(huge_curves);
    CHECK_GROUP(rules_and_paints);
    return check_finish();
}
