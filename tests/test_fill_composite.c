/* Compositing: cg_composite against the W3C Compositing and Blending
 * spec's formulas on random premultiplied colours, the rasterizer in the
 * sRGB space against the coverage it gives in linear light, and the
 * gradient extensions (spread, focal point, transform) against their
 * definitions. */
#include "cg/fill.h"
#include "cg/color.h"
#include "check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static check_rng rng = {0x5eed1234abcdULL};

/* A random premultiplied colour; sometimes transparent or opaque. */
static cg_rgbaf random_premultiplied(void)
{
    double a = check_rng_unit(&rng);
    long long pick = check_rng_int(&rng, 0, 9);
    if (pick == 0)
        a = 0;
    else if (pick == 1)
        a = 1;
    cg_rgbaf c = {(float)(check_rng_unit(&rng) * a), (float)(check_rng_unit(&rng) * a),
                  (float)(check_rng_unit(&rng) * a), (float)a};
    return c;
}

/* ---- the spec, written out per operator (section 9.1 of Compositing 1) ---- */

static void reference_operator(cg_composite_operator op, const double *s, const double *b,
                               double *out)
{
    double as = s[3], ab = b[3];
    for (int i = 0; i < 4; i++) {
        double cs = s[i], cb = b[i], v;
        switch (op) {
        case CG_OPERATOR_CLEAR: v = 0; break;
        case CG_OPERATOR_SOURCE: v = cs; break;
        case CG_OPERATOR_DESTINATION: v = cb; break;
        case CG_OPERATOR_OVER: v = cs + cb * (1 - as); break;
        case CG_OPERATOR_DESTINATION_OVER: v = cs * (1 - ab) + cb; break;
        case CG_OPERATOR_IN: v = cs * ab; break;
        case CG_OPERATOR_DESTINATION_IN: v = cb * as; break;
        case CG_OPERATOR_OUT: v = cs * (1 - ab); break;
        case CG_OPERATOR_DESTINATION_OUT: v = cb * (1 - as); break;
        case CG_OPERATOR_ATOP: v = cs * ab + cb * (1 - as); break;
        case CG_OPERATOR_DESTINATION_ATOP: v = cs * (1 - ab) + cb * as; break;
        case CG_OPERATOR_XOR: v = cs * (1 - ab) + cb * (1 - as); break;
        default: v = fmin(1, cs + cb); break; /* plus */
        }
        out[i] = v;
    }
}

/* ---- the spec's blend functions (section 10), in double ---- */

static double ref_separable(cg_blend_mode m, double cb, double cs)
{
    switch (m) {
    case CG_BLEND_NORMAL: return cs;
    case CG_BLEND_MULTIPLY: return cb * cs;
    case CG_BLEND_SCREEN: return 1 - (1 - cb) * (1 - cs);
    case CG_BLEND_OVERLAY: /* HardLight(Cs, Cb) */
        return cb <= 0.5 ? cs * 2 * cb : 1 - (1 - cs) * (1 - (2 * cb - 1));
    case CG_BLEND_DARKEN: return fmin(cb, cs);
    case CG_BLEND_LIGHTEN: return fmax(cb, cs);
    case CG_BLEND_COLOR_DODGE: return cb == 0 ? 0 : (cs == 1 ? 1 : fmin(1, cb / (1 - cs)));
    case CG_BLEND_COLOR_BURN: return cb == 1 ? 1 : (cs == 0 ? 0 : 1 - fmin(1, (1 - cb) / cs));
    case CG_BLEND_HARD_LIGHT: return cs <= 0.5 ? cb * 2 * cs : 1 - (1 - cb) * (1 - (2 * cs - 1));
    case CG_BLEND_SOFT_LIGHT: {
        if (cs <= 0.5)
            return cb - (1 - 2 * cs) * cb * (1 - cb);
        double d = cb <= 0.25 ? ((16 * cb - 12) * cb + 4) * cb : sqrt(cb);
        return cb + (2 * cs - 1) * (d - cb);
    }
    case CG_BLEND_DIFFERENCE: return fabs(cb - cs);
    default: return cb + cs - 2 * cb * cs; /* exclusion */
    }
}

static double ref_lum(const double *c)
{
    return 0.3 * c[0] + 0.59 * c[1] + 0.11 * c[2];
}

static void ref_clip(double *c)
{
    double l = ref_lum(c);
    double n = fmin(c[0], fmin(c[1], c[2])), x = fmax(c[0], fmax(c[1], c[2]));
    if (n < 0)
        for (int i = 0; i < 3; i++)
            c[i] = l + (c[i] - l) * l / (l - n);
    if (x > 1)
        for (int i = 0; i < 3; i++)
            c[i] = l + (c[i] - l) * (1 - l) / (x - l);
}

static void ref_set_lum(double *c, double l)
{
    double d = l - ref_lum(c);
    for (int i = 0; i < 3; i++)
        c[i] += d;
    ref_clip(c);
}

static double ref_sat(const double *c)
{
    return fmax(c[0], fmax(c[1], c[2])) - fmin(c[0], fmin(c[1], c[2]));
}

/* SetSat by sorting indices: Cmax, Cmid, Cmin. */
static void ref_set_sat(double *c, double s)
{
    int idx[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++)
        for (int k = i + 1; k < 3; k++)
            if (c[idx[k]] > c[idx[i]]) {
                int t = idx[i];
                idx[i] = idx[k];
                idx[k] = t;
            }
    double mx = c[idx[0]], md = c[idx[1]], mn = c[idx[2]];
    if (mx > mn) {
        c[idx[1]] = (md - mn) * s / (mx - mn);
        c[idx[0]] = s;
    } else {
        c[idx[1]] = c[idx[0]] = 0;
    }
    c[idx[2]] = 0;
}

static void ref_blend(cg_blend_mode m, const double *cb, const double *cs, double *out)
{
    double t[3];
    switch (m) {
    case CG_BLEND_HUE:
        memcpy(t, cs, sizeof t);
        ref_set_sat(t, ref_sat(cb));
        ref_set_lum(t, ref_lum(cb));
        break;
    case CG_BLEND_SATURATION:
        memcpy(t, cb, sizeof t);
        ref_set_sat(t, ref_sat(cs));
        ref_set_lum(t, ref_lum(cb));
        break;
    case CG_BLEND_COLOR:
        memcpy(t, cs, sizeof t);
        ref_set_lum(t, ref_lum(cb));
        break;
    case CG_BLEND_LUMINOSITY:
        memcpy(t, cb, sizeof t);
        ref_set_lum(t, ref_lum(cs));
        break;
    default:
        for (int i = 0; i < 3; i++)
            t[i] = ref_separable(m, cb[i], cs[i]);
    }
    memcpy(out, t, sizeof t);
}

static int near_color(cg_rgbaf got, const double *want, double tol)
{
    return fabs(got.r - want[0]) <= tol && fabs(got.g - want[1]) <= tol
           && fabs(got.b - want[2]) <= tol && fabs(got.a - want[3]) <= tol;
}

static void operators(void)
{
    for (int op = 0; op < CG_OPERATOR_COUNT; op++) {
        int bad = 0;
        for (int n = 0; n < 2000; n++) {
            cg_rgbaf s = random_premultiplied(), b = random_premultiplied();
            double sd[4] = {s.r, s.g, s.b, s.a}, bd[4] = {b.r, b.g, b.b, b.a}, want[4];
            reference_operator((cg_composite_operator)op, sd, bd, want);
            cg_rgbaf got = cg_composite(s, b, (cg_composite_operator)op, CG_BLEND_NORMAL);
            if (!near_color(got, want, 2e-6) && bad++ == 0)
                CHECK_MSG(0,
                          "%s: (%g %g %g %g) on (%g %g %g %g) gave (%g %g %g %g), want "
                          "(%g %g %g %g)",
                          cg_composite_operator_name((cg_composite_operator)op), sd[0], sd[1],
                          sd[2], sd[3], bd[0], bd[1], bd[2], bd[3], got.r, got.g, got.b, got.a,
                          want[0], want[1], want[2], want[3]);
        }
        CHECK_MSG(bad == 0, "%s: %d of 2000 off", cg_composite_operator_name(op), bad);
    }
}

static void blend_modes(void)
{
    for (int m = 0; m < CG_BLEND_COUNT; m++) {
        int bad = 0;
        for (int n = 0; n < 2000; n++) {
            cg_rgbaf s = random_premultiplied(), b = random_premultiplied();
            double as = s.a, ab = b.a;
            double Cs[3] = {as > 0 ? s.r / as : 0, as > 0 ? s.g / as : 0, as > 0 ? s.b / as : 0};
            double Cb[3] = {ab > 0 ? b.r / ab : 0, ab > 0 ? b.g / ab : 0, ab > 0 ? b.b / ab : 0};
            double B[3], want[4];
            ref_blend((cg_blend_mode)m, Cb, Cs, B);
            /* section 9.1: co = cs (1 - ab) + cb (1 - as) + as ab B(Cb, Cs) */
            double cs[3] = {s.r, s.g, s.b}, cb[3] = {b.r, b.g, b.b};
            for (int i = 0; i < 3; i++)
                want[i] = cs[i] * (1 - ab) + cb[i] * (1 - as) + as * ab * B[i];
            want[3] = as + ab * (1 - as);
            cg_rgbaf got = cg_composite(s, b, CG_OPERATOR_OVER, (cg_blend_mode)m);
            if (!near_color(got, want, 1e-5) && bad++ == 0)
                CHECK_MSG(0, "%s: (%g %g %g %g) on (%g %g %g %g) gave (%g %g %g), want (%g %g %g)",
                          cg_blend_mode_name((cg_blend_mode)m), s.r, s.g, s.b, s.a, b.r, b.g, b.b,
                          b.a, got.r, got.g, got.b, want[0], want[1], want[2]);
        }
        CHECK_MSG(bad == 0, "%s: %d of 2000 off", cg_blend_mode_name(m), bad);
    }
    /* a few values worked by hand */
    cg_rgbaf white = {1, 1, 1, 1}, grey = {0.5f, 0.5f, 0.5f, 1}, red = {1, 0, 0, 1};
    cg_rgbaf got = cg_composite(grey, grey, CG_OPERATOR_OVER, CG_BLEND_MULTIPLY);
    CHECK_NEAR(got.r, 0.25, 1e-6);
    got = cg_composite(white, grey, CG_OPERATOR_OVER, CG_BLEND_DIFFERENCE);
    CHECK_NEAR(got.g, 0.5, 1e-6);
    got = cg_composite(red, grey, CG_OPERATOR_OVER, CG_BLEND_LUMINOSITY);
    CHECK_NEAR(got.r, 0.3, 1e-6); /* grey at red's luminosity */
    got = cg_composite(grey, red, CG_OPERATOR_OVER, CG_BLEND_HUE);
    CHECK_NEAR(got.r, 0.3, 1e-6); /* grey has no saturation: red's luminosity in grey */
}

static void names(void)
{
    for (int op = 0; op < CG_OPERATOR_COUNT; op++) {
        cg_composite_operator back;
        CHECK(cg_composite_operator_parse(cg_composite_operator_name(op), &back) == CG_OK);
        CHECK_EQ_INT(back, op);
    }
    for (int m = 0; m < CG_BLEND_COUNT; m++) {
        cg_blend_mode back;
        CHECK(cg_blend_mode_parse(cg_blend_mode_name(m), &back) == CG_OK);
        CHECK_EQ_INT(back, m);
    }
    cg_composite_operator op;
    CHECK(cg_composite_operator_parse("source-over", &op) == CG_OK && op == CG_OPERATOR_OVER);
    CHECK(cg_composite_operator_parse("copy", &op) == CG_OK && op == CG_OPERATOR_SOURCE);
    CHECK(cg_composite_operator_parse("Over", &op) == CG_EINVAL);
    cg_blend_mode m;
    CHECK(cg_blend_mode_parse("", &m) == CG_EINVAL);
    CHECK(cg_composite_operator_name(CG_OPERATOR_COUNT) == NULL);
    cg_rasterizer *r;
    CHECK(cg_rasterizer_create(&r) == CG_OK);
    CHECK(
        cg_rasterizer_set_compositing(r, (cg_compositing_space)2, CG_OPERATOR_OVER, CG_BLEND_NORMAL)
        == CG_EINVAL);
    CHECK(cg_rasterizer_set_compositing(r, CG_COMPOSITE_SRGB, CG_OPERATOR_COUNT, CG_BLEND_NORMAL)
          == CG_EINVAL);
    CHECK(cg_rasterizer_set_compositing(r, CG_COMPOSITE_SRGB, CG_OPERATOR_OVER, (cg_blend_mode)-1)
          == CG_EINVAL);
    cg_rasterizer_free(r);
}

static cg_image *filled_image(int w, int h, cg_rgba8 c)
{
    cg_image *image;
    if (cg_image_create(&image, w, h, CG_PIXEL_RGBA8) != CG_OK)
        return NULL;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            cg_image_row_rgba8(image, y)[x] = c;
    return image;
}

static cg_rgba8 random_rgba8(void)
{
    cg_rgba8 c = {(uint8_t)check_rng_int(&rng, 0, 255), (uint8_t)check_rng_int(&rng, 0, 255),
                  (uint8_t)check_rng_int(&rng, 0, 255), (uint8_t)check_rng_int(&rng, 0, 255)};
    if (check_rng_int(&rng, 0, 3) == 0)
        c.a = 255;
    return c;
}

/* The expected pixel of colour s drawn at coverage k onto d in the sRGB
 * space, from the encoded values alone. */
static void expected_srgb(cg_rgba8 s, cg_rgba8 d, double k, cg_composite_operator op,
                          cg_blend_mode mode, double *out)
{
    double as = s.a / 255.0, ab = d.a / 255.0;
    cg_rgbaf sp = {(float)(s.r / 255.0 * as), (float)(s.g / 255.0 * as), (float)(s.b / 255.0 * as),
                   (float)as};
    cg_rgbaf bp = {(float)(d.r / 255.0 * ab), (float)(d.g / 255.0 * ab), (float)(d.b / 255.0 * ab),
                   (float)ab};
    cg_rgbaf full = cg_composite(sp, bp, op, mode);
    double f[4] = {full.r, full.g, full.b, full.a}, b[4] = {bp.r, bp.g, bp.b, bp.a};
    for (int i = 0; i < 4; i++)
        out[i] = b[i] + (f[i] - b[i]) * k;
}

static void rasterizer_srgb(void)
{
    cg_rasterizer *r;
    CHECK(cg_rasterizer_create(&r) == CG_OK);
    /* half-covered white over black: 128 in sRGB, 188 in linear light */
    cg_vec2 half[4] = {{0, 0}, {0.5, 0}, {0.5, 1}, {0, 1}};
    int four = 4;
    cg_rgba8 black = {0, 0, 0, 255}, white = {255, 255, 255, 255};
    cg_paint paint = cg_paint_solid(white);
    cg_image *image = filled_image(1, 1, black);
    CHECK(cg_rasterizer_fill_polygon_aa(r, image, half, &four, 1, CG_FILL_NONZERO, &paint)
          == CG_OK);
    CHECK_EQ_INT(cg_image_row_rgba8(image, 0)[0].r, 188);
    cg_image_row_rgba8(image, 0)[0] = black;
    CHECK(cg_rasterizer_set_compositing(r, CG_COMPOSITE_SRGB, CG_OPERATOR_OVER, CG_BLEND_NORMAL)
          == CG_OK);
    CHECK(cg_rasterizer_fill_polygon_aa(r, image, half, &four, 1, CG_FILL_NONZERO, &paint)
          == CG_OK);
    CHECK_EQ_INT(cg_image_row_rgba8(image, 0)[0].r, 128);
    cg_image_free(image);

    /* every operator and mode at random coverages: the pixel equals the
     * formula on the encoded values within one code */
    int bad = 0, total = 0;
    for (int n = 0; n < 3000; n++) {
        cg_composite_operator op = (cg_composite_operator)check_rng_int(&rng, 0,
                                                                        CG_OPERATOR_COUNT - 1);
        cg_blend_mode mode = (cg_blend_mode)check_rng_int(&rng, 0, CG_BLEND_COUNT - 1);
        cg_rgba8 s = random_rgba8(), d = random_rgba8();
        double width = check_rng_int(&rng, 0, 4) == 0 ? 1 : check_rng_unit(&rng);
        cg_vec2 box[4] = {{0, 0}, {width, 0}, {width, 1}, {0, 1}};
        image = filled_image(1, 1, d);
        paint = cg_paint_solid(s);
        CHECK(cg_rasterizer_set_compositing(r, CG_COMPOSITE_SRGB, op, mode) == CG_OK);
        CHECK(cg_rasterizer_fill_polygon_aa(r, image, box, &four, 1, CG_FILL_NONZERO, &paint)
              == CG_OK);
        cg_rgba8 got = cg_image_row_rgba8(image, 0)[0];
        double want[4];
        /* the rasterizer's coverage is quantised to 1/255 */
        expected_srgb(s, d, floor(width * 255 + 0.5) / 255, op, mode, want);
        double wa = want[3], got_rgb[3] = {got.r, got.g, got.b}, ok = fabs(got.a - wa * 255) <= 1;
        /* premultiplied, where rounding the colour and the alpha each
         * moves a value by at most half a code */
        for (int i = 0; i < 3; i++)
            ok = ok && fabs(got_rgb[i] * got.a / 255 - want[i] * 255) <= 1.01;
        total++;
        if (!ok && bad++ < 3)
            CHECK_MSG(0,
                      "%s/%s: (%d %d %d %d) at %g onto (%d %d %d %d) gave (%d %d %d %d), want "
                      "(%.1f %.1f %.1f %.1f)",
                      cg_composite_operator_name(op), cg_blend_mode_name(mode), s.r, s.g, s.b, s.a,
                      width, d.r, d.g, d.b, d.a, got.r, got.g, got.b, got.a,
                      wa > 0 ? want[0] / wa * 255 : 0, wa > 0 ? want[1] / wa * 255 : 0,
                      wa > 0 ? want[2] / wa * 255 : 0, wa * 255);
        cg_image_free(image);
    }
    CHECK_MSG(bad == 0, "%d of %d pixels off", bad, total);
    cg_rasterizer_free(r);
}

/* sRGB source-over of random shapes: each pixel is the mix of paint and
 * background by the coverage the default drawing gives (white over
 * transparent leaves the coverage in alpha). */
static void srgb_shapes(void)
{
    cg_rasterizer *linear, *srgb;
    CHECK(cg_rasterizer_create(&linear) == CG_OK && cg_rasterizer_create(&srgb) == CG_OK);
    CHECK(cg_rasterizer_set_compositing(srgb, CG_COMPOSITE_SRGB, CG_OPERATOR_OVER, CG_BLEND_NORMAL)
          == CG_OK);
    int bad = 0;
    for (int n = 0; n < 40; n++) {
        cg_vec2 pts[7];
        for (int i = 0; i < 7; i++)
            pts[i] = cg_vec2_make(check_rng_range(&rng, -5, 37), check_rng_range(&rng, -5, 37));
        int seven = 7;
        cg_rgba8 none = {0, 0, 0, 0}, white = {255, 255, 255, 255};
        cg_rgba8 bg = random_rgba8(), ink = random_rgba8();
        bg.a = 255;
        cg_image *coverage = filled_image(32, 32, none), *image = filled_image(32, 32, bg);
        cg_paint w = cg_paint_solid(white), p = cg_paint_solid(ink);
        cg_fill_rule rule = n % 2 ? CG_FILL_EVEN_ODD : CG_FILL_NONZERO;
        CHECK(cg_rasterizer_fill_polygon_aa(linear, coverage, pts, &seven, 1, rule, &w) == CG_OK);
        CHECK(cg_rasterizer_fill_polygon_aa(srgb, image, pts, &seven, 1, rule, &p) == CG_OK);
        for (int y = 0; y < 32; y++)
            for (int x = 0; x < 32; x++) {
                double k = cg_image_row_rgba8(coverage, y)[x].a / 255.0 * ink.a / 255.0;
                cg_rgba8 got = cg_image_row_rgba8(image, y)[x];
                double want[3] = {ink.r * k + bg.r * (1 - k), ink.g * k + bg.g * (1 - k),
                                  ink.b * k + bg.b * (1 - k)};
                if (fabs(got.r - want[0]) > 0.51 || fabs(got.g - want[1]) > 0.51
                    || fabs(got.b - want[2]) > 0.51 || got.a != 255)
                    bad++;
            }
        cg_image_free(coverage);
        cg_image_free(image);
    }
    CHECK_MSG(bad == 0, "%d pixels differ from the coverage mix", bad);
    cg_rasterizer_free(linear);
    cg_rasterizer_free(srgb);
}

/* Paints a 1-row image with a gradient and returns its pixels' red codes. */
static void gradient_row(const cg_paint *paint, int width, cg_compositing_space space, uint8_t *red)
{
    cg_rasterizer *r;
    cg_rgba8 none = {0, 0, 0, 0};
    cg_image *image = filled_image(width, 1, none);
    CHECK(cg_rasterizer_create(&r) == CG_OK);
    CHECK(cg_rasterizer_set_compositing(r, space, CG_OPERATOR_OVER, CG_BLEND_NORMAL) == CG_OK);
    cg_vec2 box[4] = {{0, 0}, {width, 0}, {width, 1}, {0, 1}};
    int four = 4;
    CHECK(cg_rasterizer_fill_polygon_aa(r, image, box, &four, 1, CG_FILL_NONZERO, paint) == CG_OK);
    for (int x = 0; x < width; x++)
        red[x] = cg_image_row_rgba8(image, 0)[x].r;
    cg_rasterizer_free(r);
    cg_image_free(image);
}

static void gradients(void)
{
    cg_gradient_stop stops[2] = {{0, {0, 0, 0, 255}}, {1, {255, 0, 0, 255}}};
    uint8_t a[256], b[256];
    /* sRGB space: the encoded value rises linearly, t at pixel centres */
    cg_paint linear = cg_paint_linear(cg_vec2_make(0, 0), cg_vec2_make(256, 0), stops, 2);
    gradient_row(&linear, 256, CG_COMPOSITE_SRGB, a);
    int bad = 0;
    for (int x = 0; x < 256; x++)
        bad += abs(a[x] - (int)floor((x + 0.5) / 256 * 255 + 0.5)) > 1;
    CHECK_MSG(bad == 0, "%d pixels of an sRGB ramp off", bad);
    /* spread: reflect and repeat over 4 periods */
    for (int spread = CG_SPREAD_REFLECT; spread <= CG_SPREAD_REPEAT; spread++) {
        cg_paint g = cg_paint_linear(cg_vec2_make(0, 0), cg_vec2_make(64, 0), stops, 2);
        g.spread = (cg_gradient_spread)spread;
        gradient_row(&g, 256, CG_COMPOSITE_SRGB, a);
        bad = 0;
        for (int x = 0; x < 256; x++) {
            double t = (x + 0.5) / 64, m = t - 2 * floor(t / 2);
            double u = spread == CG_SPREAD_REPEAT ? t - floor(t) : (m > 1 ? 2 - m : m);
            bad += abs(a[x] - (int)floor(u * 255 + 0.5)) > 2;
        }
        CHECK_MSG(bad == 0, "spread %d: %d pixels off", spread, bad);
    }
    /* a transform scaling x by 4 is the same as endpoints 4 times as far */
    cg_paint small = cg_paint_linear(cg_vec2_make(0, 0), cg_vec2_make(64, 0), stops, 2);
    small.has_transform = 1;
    small.transform = cg_mat3_identity();
    small.transform.m[0][0] = 4;
    gradient_row(&small, 256, CG_COMPOSITE_SRGB, a);
    gradient_row(&linear, 256, CG_COMPOSITE_SRGB, b);
    CHECK(memcmp(a, b, 256) == 0);
    /* a singular transform is refused */
    small.transform.m[0][0] = 0;
    cg_image *image = filled_image(4, 4, stops[0].color);
    cg_vec2 box[4] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    int four = 4;
    CHECK(cg_fill_polygon_aa(image, box, &four, 1, CG_FILL_NONZERO, &small) == CG_EINVAL);
    small.has_transform = 0;
    small.spread = (cg_gradient_spread)7;
    CHECK(cg_fill_polygon_aa(image, box, &four, 1, CG_FILL_NONZERO, &small) == CG_EINVAL);
    cg_image_free(image);
    /* focal point at the centre: the plain radial gradient; off centre: t
     * is 0 at the focus and 1 on the circle along each ray from it */
    cg_paint radial = cg_paint_radial(cg_vec2_make(128, 0.5), 100, stops, 2);
    gradient_row(&radial, 256, CG_COMPOSITE_SRGB, a);
    radial.has_focal = 1;
    radial.focal = cg_vec2_make(128, 0.5);
    gradient_row(&radial, 256, CG_COMPOSITE_SRGB, b);
    CHECK(memcmp(a, b, 256) == 0);
    radial.focal = cg_vec2_make(78.5, 0.5); /* 49.5 left of the centre */
    gradient_row(&radial, 256, CG_COMPOSITE_SRGB, a);
    /* along the row the rays meet the circle at x = 28 and x = 228 */
    bad = 0;
    for (int x = 0; x < 256; x++) {
        double d = x + 0.5 - 78.5, t = fmin(1, fabs(d) / (d < 0 ? 50.5 : 149.5));
        bad += abs(a[x] - (int)floor(t * 255 + 0.5)) > 1;
    }
    CHECK_MSG(bad == 0, "%d pixels of a focal gradient off", bad);
    CHECK_EQ_INT(a[78], 0);
    /* a focus beyond the circle moves inside it: still t = 1 beyond */
    radial.focal = cg_vec2_make(400, 0.5);
    gradient_row(&radial, 256, CG_COMPOSITE_SRGB, a);
    CHECK_EQ_INT(a[0], 255);
}

static cg_path *rect_path(double x0, double y0, double x1, double y1)
{
    cg_path *path;
    if (cg_path_create(&path) != CG_OK)
        return NULL;
    cg_path_move_to(path, x0, y0);
    cg_path_line_to(path, x1, y0);
    cg_path_line_to(path, x1, y1);
    cg_path_line_to(path, x0, y1);
    cg_path_close(path);
    return path;
}

static void layers(void)
{
    cg_rasterizer *r;
    CHECK(cg_rasterizer_create(&r) == CG_OK);
    CHECK(cg_rasterizer_set_compositing(r, CG_COMPOSITE_SRGB, CG_OPERATOR_OVER, CG_BLEND_NORMAL)
          == CG_OK);
    cg_rgba8 white = {255, 255, 255, 255}, red = {255, 0, 0, 255}, none = {0, 0, 0, 0};
    cg_image *image = filled_image(32, 32, white), *layer = filled_image(32, 32, none);
    /* two overlapping opaque squares in a layer at opacity 0.5: one flat
     * colour, overlap or not (drawn directly they would differ) */
    cg_path *a = rect_path(2, 2, 20, 20), *b = rect_path(10, 10, 30, 30);
    cg_paint paint = cg_paint_solid(red);
    CHECK(cg_rasterizer_fill_path(r, layer, a, CG_FILL_NONZERO, &paint) == CG_OK);
    CHECK(cg_rasterizer_fill_path(r, layer, b, CG_FILL_NONZERO, &paint) == CG_OK);
    cg_layer_style style = cg_layer_style_default();
    style.opacity = 0.5;
    CHECK(cg_rasterizer_composite_layer(r, image, layer, &style) == CG_OK);
    cg_rgba8 p1 = cg_image_row_rgba8(image, 5)[5], p2 = cg_image_row_rgba8(image, 15)[15];
    cg_rgba8 p3 = cg_image_row_rgba8(image, 0)[0];
    CHECK(p1.r == 255 && abs(p1.g - 128) <= 1 && p1.g == p2.g && p1.b == p2.b);
    CHECK(p3.r == 255 && p3.g == 255 && p3.b == 255);

    /* a clip: an even-odd ring whose edges cut pixels; each pixel is the
     * mix of before and after by the ring's own coverage */
    cg_image *before = filled_image(32, 32, white), *coverage = filled_image(32, 32, none);
    cg_image *after = filled_image(32, 32, white);
    cg_path *ring;
    CHECK(cg_path_create(&ring) == CG_OK);
    CHECK(
        cg_path_append_svg(ring, "M 3.3 3.7 L 28.6 4.2 L 27.1 29.4 Z M 9 9 L 20 10 L 18 19 Z", NULL)
        == CG_OK);
    cg_rasterizer *plain;
    CHECK(cg_rasterizer_create(&plain) == CG_OK);
    cg_paint ink = cg_paint_solid(white);
    CHECK(cg_rasterizer_fill_path(plain, coverage, ring, CG_FILL_EVEN_ODD, &ink) == CG_OK);
    style = cg_layer_style_default();
    CHECK(cg_rasterizer_composite_layer(r, after, layer, &style) == CG_OK);
    style.clip = ring;
    style.clip_rule = CG_FILL_EVEN_ODD;
    cg_image *clipped = filled_image(32, 32, white);
    CHECK(cg_rasterizer_composite_layer(r, clipped, layer, &style) == CG_OK);
    int bad = 0, partial = 0;
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++) {
            double k = cg_image_row_rgba8(coverage, y)[x].a / 255.0;
            cg_rgba8 b0 = cg_image_row_rgba8(before, y)[x], b1 = cg_image_row_rgba8(after, y)[x];
            cg_rgba8 got = cg_image_row_rgba8(clipped, y)[x];
            double want = b0.g + (b1.g - b0.g) * k;
            bad += fabs(got.g - want) > 0.51 || got.r != 255;
            partial += k > 0 && k < 1 && b1.g != b0.g;
        }
    CHECK_MSG(bad == 0, "%d clipped pixels off", bad);
    CHECK(partial > 10);

    /* a luminance mask of grey g scales alpha by g (the weights sum to 1) */
    cg_image *mask = filled_image(32, 32, white);
    for (int x = 0; x < 32; x++) {
        uint8_t g = (uint8_t)(x * 8);
        cg_rgba8 grey = {g, g, g, 255};
        for (int y = 0; y < 32; y++)
            cg_image_row_rgba8(mask, y)[x] = grey;
    }
    cg_image *masked = filled_image(32, 32, white);
    style = cg_layer_style_default();
    style.mask = mask;
    style.mask_type = CG_MASK_LUMINANCE;
    CHECK(cg_rasterizer_composite_layer(r, masked, layer, &style) == CG_OK);
    bad = 0;
    for (int x = 2; x < 30; x++) { /* the layer's squares cover these on row 15 */
        cg_rgba8 got = cg_image_row_rgba8(masked, 15)[x];
        double k = x * 8 / 255.0;
        bad += fabs(got.g - 255 * (1 - k)) > 0.51;
    }
    CHECK_MSG(bad == 0, "%d masked pixels off", bad);
    style.mask_type = CG_MASK_ALPHA; /* opaque mask: unchanged */
    cg_image *alpha_masked = filled_image(32, 32, white);
    CHECK(cg_rasterizer_composite_layer(r, alpha_masked, layer, &style) == CG_OK);
    CHECK(memcmp(alpha_masked->data, after->data, (size_t)after->stride * 32) == 0);

    /* a blend mode: multiply over a background of random colours */
    cg_image *backdrop = filled_image(32, 32, white), *expected = NULL;
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++)
            cg_image_row_rgba8(backdrop, y)[x] = random_rgba8();
    CHECK(cg_image_copy(backdrop, &expected) == CG_OK);
    style = cg_layer_style_default();
    style.mode = CG_BLEND_MULTIPLY;
    CHECK(cg_rasterizer_composite_layer(r, backdrop, layer, &style) == CG_OK);
    bad = 0;
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++) {
            cg_rgba8 s = cg_image_row_rgba8(layer, y)[x], d = cg_image_row_rgba8(expected, y)[x];
            cg_rgba8 got = cg_image_row_rgba8(backdrop, y)[x];
            double want[4];
            expected_srgb(s, d, 1, CG_OPERATOR_OVER, CG_BLEND_MULTIPLY, want);
            bad += fabs(got.a - want[3] * 255) > 0.51
                   || fabs(got.g * got.a / 255.0 - want[1] * 255) > 1.01;
        }
    CHECK_MSG(bad == 0, "%d multiplied pixels off", bad);

    /* bad input */
    cg_image *small = filled_image(8, 8, none);
    style = cg_layer_style_default();
    CHECK(cg_rasterizer_composite_layer(r, image, small, &style) == CG_EINVAL);
    style.opacity = 1.5;
    CHECK(cg_rasterizer_composite_layer(r, image, layer, &style) == CG_EINVAL);
    style.opacity = NAN;
    CHECK(cg_rasterizer_composite_layer(r, image, layer, &style) == CG_EINVAL);
    style = cg_layer_style_default();
    style.mask = small;
    CHECK(cg_rasterizer_composite_layer(r, image, layer, &style) == CG_EINVAL);
    style = cg_layer_style_default();
    style.mode = CG_BLEND_COUNT;
    CHECK(cg_rasterizer_composite_layer(r, image, layer, &style) == CG_EINVAL);
    cg_image *list[] = {image, layer,  before,       coverage, after,    clipped,
                        mask,  masked, alpha_masked, backdrop, expected, small};
    for (size_t i = 0; i < sizeof list / sizeof *list; i++)
        cg_image_free(list[i]);
    cg_path_free(a);
    cg_path_free(b);
    cg_path_free(ring);
    cg_rasterizer_free(plain);
    cg_rasterizer_free(r);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(operators);
    CHECK_GROUP(blend_modes);
    CHECK_GROUP(names);
    CHECK_GROUP(rasterizer_srgb);
    CHECK_GROUP(srgb_shapes);
    CHECK_GROUP(gradients);
    CHECK_GROUP(layers);
    return check_finish();
}
