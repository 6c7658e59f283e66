/* Tests of cg/color.h: transfer curves, colour models in double and 8-bit,
 * conversions by name, intensity mapping and dithering, parsing. */
#include "check.h"
#include "cg/color.h"
#include "../src/color/srgb_tables.h" /* to check the encode tables' invariant */

#include <string.h>

static cg_vec3 v3(double x, double y, double z)
{
    return cg_vec3_make(x, y, z);
}

static int near3(cg_vec3 a, cg_vec3 b, double tol)
{
    return fabs(a.x - b.x) <= tol && fabs(a.y - b.y) <= tol && fabs(a.z - b.z) <= tol;
}

#define CHECK_VEC(got, want, tol)                                                               \
    do {                                                                                        \
        cg_vec3 g_ = (got), w_ = (want);                                                        \
        CHECK_MSG(near3(g_, w_, tol), "%s = (%.17g, %.17g, %.17g), want (%.17g, %.17g, %.17g)", \
                  #got, g_.x, g_.y, g_.z, w_.x, w_.y, w_.z);                                    \
    } while (0)

static cg_vec3 random_rgb(check_rng *r)
{
    return v3(check_rng_unit(r), check_rng_unit(r), check_rng_unit(r));
}

/* ---- transfer curves ------------------------------------------------------ */

static uint8_t encode_reference(float linear)
{
    /* round(255 * srgb(linear)) in double, the definition */
    return (uint8_t)floor(255 * cg_linear_to_srgb(linear) + 0.5);
}

static void test_srgb(void)
{
    check_rng r = {42};
    for (int i = 0; i < 100000; i++) {
        double x = check_rng_unit(&r);
        CHECK_NEAR(cg_srgb_to_linear(cg_linear_to_srgb(x)), x, 1e-12);
        CHECK_NEAR(cg_linear_to_srgb(cg_srgb_to_linear(x)), x, 1e-12);
    }
    /* Known points: the knee and the ends. */
    CHECK_NEAR(cg_srgb_to_linear(0.04045), 0.04045 / 12.92, 1e-15);
    CHECK_NEAR(cg_srgb_to_linear(1), 1, 0);
    CHECK_NEAR(cg_srgb_to_linear(0.5), 0.21404114048223255, 1e-15);
    CHECK_NEAR(cg_linear_to_srgb(0.18), 0.46135612950044164, 1e-14);
    CHECK(cg_srgb_to_linear(NAN) == 0 && cg_linear_to_srgb(-3) == 0 && cg_linear_to_srgb(7) == 1);
    CHECK(cg_srgb_to_linear(INFINITY) == 1);

    /* 8-bit: code -> linear -> code is exact; encoding matches the double
     * definition except within float rounding of a threshold. */
    int bad = 0;
    for (int k = 0; k < 256; k++)
        bad += cg_linear_to_srgb8(cg_srgb8_to_linear((uint8_t)k)) != k;
    CHECK_EQ_INT(bad, 0);
    bad = 0;
    for (int i = 0; i < 2000000; i++) {
        float x = (float)check_rng_range(&r, -0.1, 1.1);
        uint8_t got = cg_linear_to_srgb8(x), want = encode_reference(x);
        if (got != want) {
            double e = 255 * cg_linear_to_srgb(x);
            if (fabs(e - floor(e) - 0.5) > 1e-4)
                bad++;
        }
    }
    CHECK_EQ_INT(bad, 0);
    /* Just below and at each threshold (nextafter on both sides). */
    bad = 0;
    for (int k = 1; k < 256; k++) {
        double t = cg_srgb_to_linear((k - 0.5) / 255);
        float hi = (float)t, lo = nextafterf(hi, 0);
        while ((double)hi < t)
            hi = nextafterf(hi, 2);
        while ((double)lo >= t)
            lo = nextafterf(lo, 0);
        bad += cg_linear_to_srgb8(hi) != k || cg_linear_to_srgb8(lo) != k - 1;
    }
    CHECK_MSG(bad <= 2, "%d thresholds off", bad); /* float rounding of the table */
    CHECK(cg_linear_to_srgb8(NAN) == 0 && cg_linear_to_srgb8(INFINITY) == 255
          && cg_linear_to_srgb8(-INFINITY) == 0);

    /* Buffers agree with the single-value forms. */
    uint8_t codes[256], again[256];
    float lin[256];
    for (int k = 0; k < 256; k++)
        codes[k] = (uint8_t)k;
    cg_srgb8_decode(codes, lin, 256);
    cg_srgb8_encode(lin, again, 256);
    CHECK(memcmp(codes, again, 256) == 0);
    CHECK(lin[128] == cg_srgb8_to_linear(128));
    /* A large buffer (the streaming path), misaligned by one float. */
    size_t big = ((size_t)4 << 20) + 37;
    uint8_t *bytes = malloc(big), *back = malloc(big);
    float *floats = malloc((big + 1) * sizeof *floats);
    if (bytes && back && floats) {
        for (size_t i = 0; i < big; i++)
            bytes[i] = (uint8_t)(i * 2654435761u >> 13);
        cg_srgb8_decode(bytes, floats + 1, big);
        cg_srgb8_encode(floats + 1, back, big);
        size_t wrong = 0;
        for (size_t i = 0; i < big; i++)
            wrong += floats[i + 1] != cg_srgb8_to_linear(bytes[i]) || back[i] != bytes[i];
        CHECK_EQ_INT(wrong, 0);
    }
    free(bytes);
    free(back);
    free(floats);

    /* CRT power law. */
    CHECK_NEAR(cg_gamma_decode(0.5, 2.2), pow(0.5, 2.2), 1e-15);
    CHECK_NEAR(cg_gamma_encode(cg_gamma_decode(0.3, 2.5), 2.5), 0.3, 1e-12);
    CHECK(cg_gamma_decode(0.5, 0) == 0 && cg_gamma_encode(0.5, NAN) == 0);
    CHECK(cg_gamma_decode(NAN, 2.2) == 0 && cg_gamma_encode(9, 2.2) == 1);

    CHECK_NEAR(cg_luminance(v3(1, 1, 1)), 1, 1e-15);
    CHECK_NEAR(cg_luma(v3(1, 1, 1)), 1, 1e-15);
    CHECK_NEAR(cg_luminance(v3(0, 1, 0)), 0.7152, 1e-15);
}

static void test_images(void)
{
    cg_image *img, *lin, *back;
    CHECK(cg_image_create(&img, 67, 23, CG_PIXEL_RGBA8) == CG_OK);
    check_rng r = {7};
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            cg_rgba8 c = {(uint8_t)check_rng_int(&r, 0, 255), (uint8_t)check_rng_int(&r, 0, 255),
                          (uint8_t)check_rng_int(&r, 0, 255), (uint8_t)check_rng_int(&r, 0, 255)};
            cg_image_set_rgba8(img, x, y, c);
        }
    CHECK(cg_image_decode_srgb(img, &lin) == CG_OK);
    CHECK(lin->format == CG_PIXEL_RGBAF);
    CHECK(cg_image_encode_srgb(lin, &back) == CG_OK);
    CHECK(memcmp(img->data, back->data, img->stride * (size_t)img->height) == 0);
    cg_rgbaf p = cg_image_row_rgbaf(lin, 5)[7];
    cg_rgba8 q = cg_image_row_rgba8(img, 5)[7];
    CHECK(p.r == cg_srgb8_to_linear(q.r) && fabsf(p.a - q.a / 255.0f) < 1e-7f);
    cg_image *none = (cg_image *)1;
    CHECK(cg_image_decode_srgb(lin, &none) == CG_EINVAL && none == NULL);
    CHECK(cg_image_encode_srgb(img, &none) == CG_EINVAL);

    /* Tone mapping: clamp and exposure. */
    cg_image *hdr, *ldr;
    CHECK(cg_image_create(&hdr, 3, 1, CG_PIXEL_RGBAF) == CG_OK);
    cg_rgbaf *row = cg_image_row_rgbaf(hdr, 0);
    row[0] = (cg_rgbaf){0.25f, 4.0f, NAN, 1};
    row[1] = (cg_rgbaf){-1, INFINITY, 0.5f, 0.5f};
    CHECK(cg_image_tonemap(hdr, 1, 0, &ldr) == CG_OK); /* x2 then clamp */
    cg_rgba8 o = cg_image_row_rgba8(ldr, 0)[0];
    CHECK(o.r == cg_linear_to_srgb8(0.5f) && o.g == 255 && o.b == 0 && o.a == 255);
    o = cg_image_row_rgba8(ldr, 0)[1];
    CHECK(o.r == 0 && o.g == 255 && o.b == 255 && o.a == 128);
    cg_image_free(ldr);
    CHECK(cg_image_tonemap(hdr, 0, 1, &ldr) == CG_OK);
    o = cg_image_row_rgba8(ldr, 0)[0];
    CHECK(o.r == cg_linear_to_srgb8((float)(1 - exp(-0.25))));
    CHECK(cg_image_tonemap(hdr, NAN, 1, &none) == CG_EINVAL);
    CHECK(cg_image_tonemap(img, 0, 1, &none) == CG_EINVAL);
    cg_image_free(ldr);
    cg_image_free(hdr);
    cg_image_free(img);
    cg_image_free(lin);
    cg_image_free(back);
}

/* ---- models in double ----------------------------------------------------- */

static void test_reference_values(void)
{
    static const struct {
        double r, g, b, h;
    } hues[] = {{1, 0, 0, 0},   {1, 1, 0, 60},  {0, 1, 0, 120},
                {0, 1, 1, 180}, {0, 0, 1, 240}, {1, 0, 1, 300}};
    for (int i = 0; i < 6; i++) {
        cg_vec3 rgb = v3(hues[i].r, hues[i].g, hues[i].b);
        CHECK_VEC(cg_rgb_to_hsv(rgb), v3(hues[i].h, 1, 1), 1e-12);
        CHECK_VEC(cg_rgb_to_hsl(rgb), v3(hues[i].h, 1, 0.5), 1e-12);
        CHECK_VEC(cg_hsv_to_rgb(v3(hues[i].h, 1, 1)), rgb, 1e-12);
        CHECK_VEC(cg_hsl_to_rgb(v3(hues[i].h, 1, 0.5)), rgb, 1e-12);
    }
    /* Orange: h = 30 (hand: 60 * (0.5 - 0) / 1). */
    CHECK_VEC(cg_rgb_to_hsv(v3(1, 0.5, 0)), v3(30, 1, 1), 1e-12);
    /* Dark desaturated: (0.2, 0.4, 0.3): max .4, min .2, h = 60 (2 + (.3-.2)/.2) = 150,
     * s_hsv = .5, l = .3, s_hsl = .2 / .6. */
    CHECK_VEC(cg_rgb_to_hsv(v3(0.2, 0.4, 0.3)), v3(150, 0.5, 0.4), 1e-12);
    CHECK_VEC(cg_rgb_to_hsl(v3(0.2, 0.4, 0.3)), v3(150, 1.0 / 3.0, 0.3), 1e-12);
    /* Light colour (L > 1/2): (0.9, 0.7, 0.8): l = .8, s = .2 / (2 - 1.6) = .5, h = 330. */
    CHECK_VEC(cg_rgb_to_hsl(v3(0.9, 0.7, 0.8)), v3(330, 0.5, 0.8), 1e-12);
    for (int k = 0; k <= 10; k++) {
        double g = k / 10.0;
        CHECK_VEC(cg_rgb_to_hsv(v3(g, g, g)), v3(0, 0, g), 0);
        CHECK_VEC(cg_rgb_to_hsl(v3(g, g, g)), v3(0, 0, g), 0);
        CHECK_VEC(cg_rgb_to_yiq(v3(g, g, g)), v3(g, 0, 0), 1e-15);
        CHECK_VEC(cg_rgb_to_ycbcr(v3(g, g, g), CG_YCBCR_BT709), v3(g, 0, 0), 1e-15);
        cg_vec3 lab = cg_rgb_to_lab(v3(g, g, g));
        CHECK_NEAR(lab.y, 0, 1e-12);
        CHECK_NEAR(lab.z, 0, 1e-12);
    }
    /* D65 white. */
    CHECK_VEC(cg_linear_to_xyz(v3(1, 1, 1)), v3(0.9505, 1.0, 1.089), 1e-12);
    CHECK_VEC(cg_d65_white(), v3(0.9505, 1.0, 1.089), 1e-12);
    CHECK_VEC(cg_xyz_to_lab(cg_d65_white()), v3(100, 0, 0), 1e-12);
    CHECK_VEC(cg_rgb_to_lab(v3(1, 1, 1)), v3(100, 0, 0), 1e-12);
    CHECK_VEC(cg_rgb_to_lab(v3(0, 0, 0)), v3(0, 0, 0), 1e-12);
    /* sRGB red in Lab: published 53.24, 80.09, 67.20 (with a more precise
     * matrix than the 4-digit one of IEC 61966-2-1 used here). */
    CHECK_VEC(cg_rgb_to_lab(v3(1, 0, 0)), v3(53.24, 80.09, 67.20), 0.03);
    /* Mid grey (linear 0.18) has L* = 116 * cbrt(0.18) - 16 = 49.496. */
    CHECK_NEAR(cg_xyz_to_lab(v3(0.18 * 0.9505, 0.18, 0.18 * 1.089)).x, 49.496, 0.001);
    /* YCbCr of red, BT.601: Y = .299, Cb = -.299 / 1.772, Cr = .5. */
    CHECK_VEC(cg_rgb_to_ycbcr(v3(1, 0, 0), CG_YCBCR_BT601), v3(0.299, -0.299 / 1.772, 0.5), 1e-15);
    CHECK_VEC(cg_rgb_to_ycbcr(v3(0, 0, 1), CG_YCBCR_BT709), v3(0.0722, 0.5, -0.0722 / 1.5748),
              1e-15);
    CHECK_VEC(cg_rgb_to_yiq(v3(1, 0, 0)), v3(0.299, 0.596, 0.212), 1e-15);
    /* CMY and CMYK. */
    CHECK_VEC(cg_rgb_to_cmy(v3(1, 0.25, 0)), v3(0, 0.75, 1), 0);
    cg_vec4 k = cg_rgb_to_cmyk(v3(0.5, 0.25, 0));
    CHECK(k.x == 0 && k.y == 0.5 && k.z == 1 && k.w == 0.5);
    k = cg_rgb_to_cmyk(v3(0, 0, 0));
    CHECK(k.x == 0 && k.y == 0 && k.z == 0 && k.w == 1);
    /* Tints, shades, tones. */
    cg_vec3 base = v3(0.8, 0.2, 0.4);
    CHECK_VEC(cg_color_tint(base, 1), v3(1, 1, 1), 0);
    CHECK_VEC(cg_color_tint(base, 0.5), v3(0.9, 0.6, 0.7), 1e-15);
    CHECK_VEC(cg_color_shade(base, 0.25), v3(0.6, 0.15, 0.3), 1e-15);
    CHECK_VEC(cg_color_tone(base, 1, 0.5), v3(0.5, 0.5, 0.5), 0);
    CHECK_VEC(cg_color_tone(base, NAN, 0.5), base, 0);
    CHECK_VEC(cg_color_shade(base, 7), v3(0, 0, 0), 0);
    /* Tints keep the hue and lower the saturation; shades keep the hue. */
    CHECK_NEAR(cg_rgb_to_hsv(cg_color_tint(base, 0.3)).x, cg_rgb_to_hsv(base).x, 1e-9);
    CHECK_NEAR(cg_rgb_to_hsv(cg_color_shade(base, 0.3)).x, cg_rgb_to_hsv(base).x, 1e-9);
}

static void test_round_trips(void)
{
    check_rng r = {2026};
    int bad[10] = {0};
    for (int i = 0; i < 200000; i++) {
        cg_vec3 c = random_rgb(&r);
        if (i < 64) /* edges: channels at 0 and 1, greys */
            c = v3((i & 1)   ? 1
                   : (i & 8) ? c.x
                             : 0,
                   (i & 2) ? 1 : c.y,
                   (i & 4)    ? 0
                   : (i & 16) ? c.z
                              : c.y);
        bad[0] += !near3(cg_hsv_to_rgb(cg_rgb_to_hsv(c)), c, 1e-9);
        bad[1] += !near3(cg_hsl_to_rgb(cg_rgb_to_hsl(c)), c, 1e-9);
        bad[2] += !near3(cg_cmy_to_rgb(cg_rgb_to_cmy(c)), c, 1e-9);
        bad[3] += !near3(cg_cmyk_to_rgb(cg_rgb_to_cmyk(c)), c, 1e-9);
        bad[4] += !near3(cg_yiq_to_rgb(cg_rgb_to_yiq(c)), c, 1e-9);
        bad[5] += !near3(cg_ycbcr_to_rgb(cg_rgb_to_ycbcr(c, CG_YCBCR_BT601), CG_YCBCR_BT601), c,
                         1e-9);
        bad[6] += !near3(cg_ycbcr_to_rgb(cg_rgb_to_ycbcr(c, CG_YCBCR_BT709), CG_YCBCR_BT709), c,
                         1e-9);
        bad[7] += !near3(cg_xyz_to_linear(cg_linear_to_xyz(c)), c, 1e-9);
        bad[8] += !near3(cg_lab_to_rgb(cg_rgb_to_lab(c)), c, 1e-9);
        /* model -> rgb -> model from random model values */
        cg_vec3 hsv = v3(check_rng_range(&r, 0, 360), check_rng_unit(&r), check_rng_unit(&r));
        cg_vec3 back = cg_rgb_to_hsv(cg_hsv_to_rgb(hsv));
        /* hue is free where s or v is 0: compare the colours instead */
        bad[9] += !near3(cg_hsv_to_rgb(back), cg_hsv_to_rgb(hsv), 1e-9)
                  || (hsv.y > 1e-3 && hsv.z > 1e-3
                      && (fabs(back.y - hsv.y) > 1e-9
                          || fmin(fabs(back.x - hsv.x), 360 - fabs(back.x - hsv.x)) > 1e-6));
    }
    static const char *names[10] = {"hsv",      "hsl",      "cmy", "cmyk", "yiq",
                                    "ycbcr601", "ycbcr709", "xyz", "lab",  "hsv from hsv"};
    for (int i = 0; i < 10; i++)
        CHECK_MSG(bad[i] == 0, "%s round trip: %d failures", names[i], bad[i]);
    /* Hue is always in [0, 360). */
    int out_of_range = 0;
    for (int i = 0; i < 100000; i++) {
        cg_vec3 c = random_rgb(&r);
        c.z = c.x - 1e-17 * (i & 3); /* nearly red-dominant with g < b */
        double h = cg_rgb_to_hsv(c).x, h2 = cg_rgb_to_hsl(c).x;
        out_of_range += !(h >= 0 && h < 360) || !(h2 >= 0 && h2 < 360);
    }
    CHECK_EQ_INT(out_of_range, 0);
}

/* Every 8-bit colour to HSV and HSL and back, in double, rounds back exactly. */
static void test_all_8bit_round_trip(void)
{
    long bad_hsv = 0, bad_hsl = 0;
    for (int r = 0; r < 256; r++)
        for (int g = 0; g < 256; g++)
            for (int b = 0; b < 256; b++) {
                cg_vec3 c = v3(r / 255.0, g / 255.0, b / 255.0);
                cg_vec3 x = cg_hsv_to_rgb(cg_rgb_to_hsv(c));
                bad_hsv += floor(x.x * 255 + 0.5) != r || floor(x.y * 255 + 0.5) != g
                           || floor(x.z * 255 + 0.5) != b;
                x = cg_hsl_to_rgb(cg_rgb_to_hsl(c));
                bad_hsl += floor(x.x * 255 + 0.5) != r || floor(x.y * 255 + 0.5) != g
                           || floor(x.z * 255 + 0.5) != b;
            }
    CHECK_EQ_INT(bad_hsv, 0);
    CHECK_EQ_INT(bad_hsl, 0);
}

/* ---- 8-bit pixels ------------------------------------------------------------ */

/* round(num / den) half up, in exact integers. */
static int div_round(long num, long den)
{
    return (int)((2 * num + den) / (2 * den));
}

/* The 8-bit HSV / HSL definition in exact rational arithmetic, written
 * independently of the library's reciprocal tables. */
static void hsx8_reference(int r, int g, int b, int hsl, uint8_t out[3])
{
    int max = r > g ? (r > b ? r : b) : (g > b ? g : b);
    int min = r < g ? (r < b ? r : b) : (g < b ? g : b);
    int d = max - min;
    int h = 0, s = 0;
    if (d > 0) {
        /* h/60 = sector + x/d;  H8 = round(256/6 * (sector + x/d)) mod 256 */
        long t = max == r ? g - b : max == g ? 2L * d + b - r : 4L * d + r - g;
        if (t < 0)
            t += 6L * d;
        h = div_round(256 * t, 6L * d) % 256;
        if (hsl) {
            int sum = max + min;
            s = div_round(255L * d, sum <= 255 ? sum : 510 - sum);
        } else {
            s = div_round(255L * d, max);
        }
    }
    out[0] = (uint8_t)h;
    out[1] = (uint8_t)s;
    out[2] = (uint8_t)(hsl ? (max + min + 1) / 2 : max);
}

/* The double result scaled to a byte may sit on a tie (k + 1/2) where
 * floating rounding decides: accept either neighbour there. */
static int byte_matches(int got, double scaled)
{
    double f = floor(scaled + 0.5);
    if (got == (int)f)
        return 1;
    return fabs(scaled - floor(scaled) - 0.5) < 1e-7 && abs(got - (int)f) == 1;
}

static void test_8bit_fast_paths(void)
{
    enum { N = 1 << 24 };
    uint8_t *rgb = malloc((size_t)N * 3), *out = malloc((size_t)N * 3),
            *back = malloc((size_t)N * 3);
    if (!rgb || !out || !back) {
        CHECK(!"out of memory");
        return;
    }
    for (long i = 0; i < N; i++) {
        rgb[3 * i] = (uint8_t)(i >> 16);
        rgb[3 * i + 1] = (uint8_t)(i >> 8);
        rgb[3 * i + 2] = (uint8_t)i;
    }
    /* RGB -> HSV8 and HSL8 against the rational definition, all colours. */
    for (int hsl = 0; hsl < 2; hsl++) {
        CHECK(cg_rgb8_to_model8(hsl ? CG_MODEL_HSL : CG_MODEL_HSV, rgb, out, N, 3) == CG_OK);
        long bad = 0, bad_double = 0;
        for (long i = 0; i < N; i++) {
            uint8_t want[3];
            hsx8_reference(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], hsl, want);
            if (memcmp(want, out + 3 * i, 3) != 0 && bad++ < 5)
                fprintf(stderr, "%s8 of %d %d %d: got %d %d %d want %d %d %d\n",
                        hsl ? "hsl" : "hsv", rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], out[3 * i],
                        out[3 * i + 1], out[3 * i + 2], want[0], want[1], want[2]);
            if ((i & 63) == 0) { /* and against the double conversion */
                cg_vec3 c = v3(rgb[3 * i] / 255.0, rgb[3 * i + 1] / 255.0, rgb[3 * i + 2] / 255.0);
                cg_vec3 m = hsl ? cg_rgb_to_hsl(c) : cg_rgb_to_hsv(c);
                int h = out[3 * i] == 0 && m.x > 359 ? 256 : out[3 * i];
                bad_double += !byte_matches(h, m.x * 256 / 360)
                              || !byte_matches(out[3 * i + 1], m.y * 255)
                              || !byte_matches(out[3 * i + 2], m.z * 255);
            }
        }
        CHECK_EQ_INT(bad, 0);
        CHECK_EQ_INT(bad_double, 0);
    }
    /* HSV8 -> RGB: every byte triple against the double formula. */
    CHECK(cg_model8_to_rgb8(CG_MODEL_HSV, rgb, back, N, 3) == CG_OK);
    long bad = 0;
    for (long i = 0; i < N; i++) {
        double hsv[3], x[3];
        cg_color_from_bytes(CG_MODEL_HSV, rgb + 3 * i, hsv);
        cg_color_convert(CG_MODEL_HSV, CG_MODEL_RGB, hsv, x);
        for (int c = 0; c < 3; c++)
            if (!byte_matches(back[3 * i + c], x[c] * 255) && bad++ < 5)
                fprintf(stderr, "hsv8 %d %d %d -> rgb: channel %d got %d want %.9f\n", rgb[3 * i],
                        rgb[3 * i + 1], rgb[3 * i + 2], c, back[3 * i + c], x[c] * 255);
    }
    CHECK_EQ_INT(bad, 0);
    /* 8-bit HSV round trip: off by little (256 hues, 256 saturations). */
    CHECK(cg_rgb8_to_model8(CG_MODEL_HSV, rgb, out, N, 3) == CG_OK);
    CHECK(cg_model8_to_rgb8(CG_MODEL_HSV, out, back, N, 3) == CG_OK);
    int worst = 0;
    for (long i = 0; i < 3L * N; i++) {
        int d = abs(rgb[i] - back[i]);
        worst = d > worst ? d : worst;
    }
    CHECK_MSG(worst <= 3, "8-bit HSV round trip off by %d", worst);

    /* Lab8 fast path: within 1 of the double conversion, on a grid. */
    CHECK(cg_rgb8_to_model8(CG_MODEL_LAB, rgb, out, N, 3) == CG_OK);
    long off = 0, far = 0, count = 0;
    for (long i = 0; i < N; i += 7) {
        uint8_t want[3];
        double c[3] = {rgb[3 * i] / 255.0, rgb[3 * i + 1] / 255.0, rgb[3 * i + 2] / 255.0}, lab[3];
        cg_color_convert(CG_MODEL_RGB, CG_MODEL_LAB, c, lab);
        cg_color_to_bytes(CG_MODEL_LAB, lab, want);
        for (int k = 0; k < 3; k++) {
            int d = abs(want[k] - out[3 * i + k]);
            off += d != 0;
            far += d > 1;
        }
        count += 3;
    }
    CHECK_EQ_INT(far, 0);
    CHECK_MSG(off * 1000 < count, "Lab8: %ld of %ld bytes off by one", off, count);
    free(rgb);
    free(out);
    free(back);
}

static void test_bytes_and_buffers(void)
{
    /* 4-channel buffers keep alpha, in place works, other models go through double. */
    uint8_t px[8] = {255, 0, 0, 77, 10, 200, 30, 9};
    uint8_t copy[8];
    memcpy(copy, px, 8);
    CHECK(cg_rgb8_to_model8(CG_MODEL_HSV, px, px, 2, 4) == CG_OK);
    CHECK(px[0] == 0 && px[1] == 255 && px[2] == 255 && px[3] == 77 && px[7] == 9);
    CHECK(cg_model8_to_rgb8(CG_MODEL_HSV, px, px, 2, 4) == CG_OK);
    CHECK(px[0] == 255 && px[1] == 0 && px[2] == 0 && px[3] == 77);
    for (int m = 0; m < CG_MODEL_COUNT; m++) {
        if (m == CG_MODEL_CMYK) {
            CHECK(cg_rgb8_to_model8((cg_color_model)m, copy, px, 2, 4) == CG_EINVAL);
            continue;
        }
        uint8_t model[8], rgb[8];
        CHECK(cg_rgb8_to_model8((cg_color_model)m, copy, model, 2, 4) == CG_OK);
        CHECK(cg_model8_to_rgb8((cg_color_model)m, model, rgb, 2, 4) == CG_OK);
        int worst = 0;
        for (int i = 0; i < 8; i++)
            worst = abs(rgb[i] - copy[i]) > worst ? abs(rgb[i] - copy[i]) : worst;
        /* linear light and XYZ in 8 bits lose dark values, Lab's 1-unit a*b*
         * steps are coarse in saturated greens; the others stay close */
        int limit = m == CG_MODEL_LINEAR || m == CG_MODEL_XYZ || m == CG_MODEL_LAB ? 12 : 3;
        CHECK_MSG(worst <= limit, "model %s: 8-bit round trip off by %d",
                  cg_color_model_name((cg_color_model)m), worst);
    }
    CHECK(cg_rgb8_to_model8(CG_MODEL_HSV, copy, px, 2, 5) == CG_EINVAL);
    CHECK(cg_rgb8_to_model8((cg_color_model)99, copy, px, 2, 3) == CG_EINVAL);
    /* Byte encodings of a few values. */
    double v[4] = {359.9, 0.5, 1.0, 0};
    uint8_t b[4];
    cg_color_to_bytes(CG_MODEL_HSV, v, b);
    CHECK(b[0] == 0 && b[1] == 128 && b[2] == 255); /* 255.93 rounds to 256 = 0 */
    double lab[3] = {100, -128.4, 200};
    cg_color_to_bytes(CG_MODEL_LAB, lab, b);
    CHECK(b[0] == 255 && b[1] == 0 && b[2] == 255);
    double ycc[3] = {1, -0.5, 0.5};
    cg_color_to_bytes(CG_MODEL_YCBCR601, ycc, b); /* 128 -+ 127.5, half up */
    CHECK(b[0] == 255 && b[1] == 1 && b[2] == 255);
    double nan3[3] = {NAN, NAN, NAN};
    cg_color_to_bytes(CG_MODEL_RGB, nan3, b);
    CHECK(b[0] == 0 && b[1] == 0 && b[2] == 0);
    /* Images in place. */
    cg_image *img;
    CHECK(cg_image_create(&img, 5, 4, CG_PIXEL_RGBA8) == CG_OK);
    cg_image_clear_rgba8(img, (cg_rgba8){10, 20, 200, 99});
    CHECK(cg_image_rgb_to_model(img, CG_MODEL_HSV) == CG_OK);
    cg_rgba8 p = cg_image_get_rgba8(img, 4, 3);
    uint8_t want[3];
    hsx8_reference(10, 20, 200, 0, want);
    CHECK(p.r == want[0] && p.g == want[1] && p.b == want[2] && p.a == 99);
    CHECK(cg_image_model_to_rgb(img, CG_MODEL_HSV) == CG_OK);
    p = cg_image_get_rgba8(img, 0, 0);
    CHECK(abs(p.r - 10) <= 2 && abs(p.g - 20) <= 2 && p.b == 200);
    cg_image_free(img);
}

static void test_by_name(void)
{
    cg_color_model m;
    cg_error err;
    CHECK(cg_color_model_parse("HSV", 3, &m, &err) == CG_OK && m == CG_MODEL_HSV);
    CHECK(cg_color_model_parse("srgb", 4, &m, &err) == CG_OK && m == CG_MODEL_RGB);
    CHECK(cg_color_model_parse("linear-x", 6, &m, &err) == CG_OK && m == CG_MODEL_LINEAR);
    CHECK(cg_color_model_parse("hsvx", 4, &m, &err) == CG_EFORMAT);
    CHECK(strstr(err.message, "'hsvx'") != NULL);
    for (int i = 0; i < CG_MODEL_COUNT; i++) {
        const char *name = cg_color_model_name((cg_color_model)i);
        CHECK(cg_color_model_parse(name, strlen(name), &m, NULL) == CG_OK && (int)m == i);
    }
    CHECK(strcmp(cg_color_model_name((cg_color_model)-1), "unknown") == 0);
    /* Every pair: from a random RGB colour to A, A to B, B back to RGB. */
    check_rng r = {99};
    int bad = 0;
    for (int i = 0; i < 2000; i++) {
        double rgb[4] = {check_rng_unit(&r), check_rng_unit(&r), check_rng_unit(&r), 0};
        for (int a = 0; a < CG_MODEL_COUNT; a++)
            for (int b = 0; b < CG_MODEL_COUNT; b++) {
                double x[4], y[4], z[4];
                cg_color_convert(CG_MODEL_RGB, (cg_color_model)a, rgb, x);
                cg_color_convert((cg_color_model)a, (cg_color_model)b, x, y);
                cg_color_convert((cg_color_model)b, CG_MODEL_RGB, y, z);
                if (fabs(z[0] - rgb[0]) > 1e-9 || fabs(z[1] - rgb[1]) > 1e-9
                    || fabs(z[2] - rgb[2]) > 1e-9)
                    bad++;
            }
    }
    CHECK_EQ_INT(bad, 0);
    double in[4] = {0.5, 0.5, 0.5, 0}, out[4];
    CHECK(cg_color_convert(CG_MODEL_RGB, CG_MODEL_LINEAR, in, out) == CG_OK);
    CHECK_NEAR(out[0], 0.21404114048223255, 1e-15);
    CHECK(cg_color_convert((cg_color_model)42, CG_MODEL_RGB, in, out) == CG_EINVAL);
    /* XYZ to Lab outside the RGB gamut is not clamped. */
    double xyz[3] = {0.1, 0.5, 0.05}, lab[3], xyz2[3];
    cg_color_convert(CG_MODEL_XYZ, CG_MODEL_LAB, xyz, lab);
    cg_color_convert(CG_MODEL_LAB, CG_MODEL_XYZ, lab, xyz2);
    CHECK_VEC(v3(xyz2[0], xyz2[1], xyz2[2]), v3(0.1, 0.5, 0.05), 1e-12);
}

static void test_bad_input(void)
{
    /* Clamping and NaN handling: documented, never propagated. */
    CHECK_VEC(cg_rgb_to_hsv(v3(NAN, 2, -1)), cg_rgb_to_hsv(v3(0, 1, 0)), 0);
    CHECK_VEC(cg_hsv_to_rgb(v3(720, 1, 1)), v3(1, 0, 0), 1e-12);
    CHECK_VEC(cg_hsv_to_rgb(v3(-120, 1, 1)), v3(0, 0, 1), 1e-12);
    CHECK_VEC(cg_hsv_to_rgb(v3(INFINITY, 1, 1)), v3(1, 0, 0), 0);
    CHECK_VEC(cg_hsl_to_rgb(v3(NAN, NAN, NAN)), v3(0, 0, 0), 0);
    CHECK_VEC(cg_hsv_to_rgb(v3(1e300, 0.5, 0.5)), cg_hsv_to_rgb(v3(fmod(1e300, 360), 0.5, 0.5)), 0);
    cg_vec3 x = cg_lab_to_rgb(v3(NAN, 1e308, -INFINITY));
    CHECK(x.x >= 0 && x.x <= 1 && x.y >= 0 && x.y <= 1 && x.z >= 0 && x.z <= 1);
    x = cg_yiq_to_rgb(v3(5, -5, NAN));
    CHECK(x.x >= 0 && x.x <= 1 && x.y >= 0 && x.y <= 1 && x.z >= 0 && x.z <= 1);
    x = cg_ycbcr_to_rgb(v3(2, 7, -7), CG_YCBCR_BT601);
    CHECK(x.x >= 0 && x.x <= 1 && x.y >= 0 && x.y <= 1 && x.z >= 0 && x.z <= 1);
    cg_vec4 k = cg_rgb_to_cmyk(v3(NAN, NAN, NAN));
    CHECK(k.w == 1);
    CHECK(cg_intensity_clamp(NAN) == 0 && cg_intensity_clamp(INFINITY) == 1
          && cg_intensity_clamp(-1) == 0 && cg_intensity_clamp(0.25) == 0.25);
    CHECK(cg_intensity_expose(NAN, 1) == 0 && cg_intensity_expose(INFINITY, 1) == 1
          && cg_intensity_expose(-2, 1) == 0);
    CHECK_NEAR(cg_intensity_expose(1, 2), 1 - exp(-2), 1e-15);
}

/* ---- intensity to pixel ------------------------------------------------------ */

static void test_quantize_dither(void)
{
    CHECK(cg_intensity_quantize(0.5, 2) == 1); /* ties up */
    CHECK(cg_intensity_quantize(0.49, 2) == 0);
    CHECK_NEAR(cg_intensity_quantize(0.3, 4), 1.0 / 3.0, 1e-15);
    CHECK(cg_intensity_quantize(NAN, 8) == 0 && cg_intensity_quantize(2, 8) == 1);

    const cg_dither methods[5] = {CG_DITHER_NONE, CG_DITHER_BAYER2, CG_DITHER_BAYER4,
                                  CG_DITHER_BAYER8, CG_DITHER_FLOYD_STEINBERG};
    enum { W = 64, H = 64 };
    static float in[W * H], out[W * H];
    check_rng r = {5};
    int bad_mean = 0, bad_levels = 0;
    for (int levels = 2; levels <= 16; levels *= 2)
        for (int m = 1; m < 5; m++)
            for (int trial = 0; trial < 40; trial++) {
                float v = (float)(trial < 3 ? trial / 2.0 : check_rng_unit(&r));
                for (int i = 0; i < W * H; i++)
                    in[i] = v;
                CHECK(cg_dither_plane(in, out, W, H, W, levels, methods[m]) == CG_OK);
                double sum = 0;
                for (int i = 0; i < W * H; i++) {
                    sum += out[i];
                    double k = out[i] * (levels - 1);
                    bad_levels += fabs(k - floor(k + 0.5)) > 1e-5;
                }
                double mean = sum / (W * H);
                if (fabs(mean - v) > 1.0 / (2 * levels)) {
                    if (bad_mean++ < 5)
                        fprintf(stderr, "dither %d levels %d: flat %g -> mean %g\n", m, levels, v,
                                mean);
                }
            }
    CHECK_EQ_INT(bad_mean, 0);
    CHECK_EQ_INT(bad_levels, 0);
    /* Ordered dithering over whole tiles is much closer: within 1/(2 n^2 (N-1)). */
    for (int i = 0; i < W * H; i++)
        in[i] = 0.3f;
    CHECK(cg_dither_plane(in, out, W, H, W, 2, CG_DITHER_BAYER8) == CG_OK);
    double sum = 0;
    for (int i = 0; i < W * H; i++)
        sum += out[i];
    CHECK_NEAR(sum / (W * H), 0.3, 1.0 / 128 + 1e-9);
    /* Floyd-Steinberg preserves the total of a random image. */
    for (int levels = 2; levels <= 256; levels *= 4) {
        double total_in = 0, total_out = 0;
        for (int i = 0; i < W * H; i++) {
            in[i] = (float)check_rng_unit(&r);
            total_in += in[i];
        }
        CHECK(cg_dither_plane(in, out, W, H, W, levels, CG_DITHER_FLOYD_STEINBERG) == CG_OK);
        for (int i = 0; i < W * H; i++)
            total_out += out[i];
        CHECK_MSG(fabs(total_out - total_in) <= 1.0 / (levels - 1) + 1e-3,
                  "FS total %g -> %g at %d levels", total_in, total_out, levels);
    }
    /* One row and one column images too (border weights). */
    for (int i = 0; i < W; i++)
        in[i] = 0.37f;
    CHECK(cg_dither_plane(in, out, W, 1, W, 2, CG_DITHER_FLOYD_STEINBERG) == CG_OK);
    sum = 0;
    for (int i = 0; i < W; i++)
        sum += out[i];
    CHECK(fabs(sum - 0.37 * W) <= 1);
    CHECK(cg_dither_plane(in, out, 1, W, 1, 2, CG_DITHER_FLOYD_STEINBERG) == CG_OK);
    /* Plain quantization = cg_intensity_quantize. */
    in[0] = 0.6f;
    in[1] = NAN;
    in[2] = 3;
    CHECK(cg_dither_plane(in, out, 3, 1, 3, 4, CG_DITHER_NONE) == CG_OK);
    CHECK(fabs(out[0] - cg_intensity_quantize(0.6f, 4)) < 1e-7 && out[1] == 0 && out[2] == 1);
    /* Bad arguments. */
    CHECK(cg_dither_plane(in, out, 0, 1, 1, 4, CG_DITHER_NONE) == CG_EINVAL);
    CHECK(cg_dither_plane(in, out, 4, 1, 3, 4, CG_DITHER_NONE) == CG_EINVAL);
    CHECK(cg_dither_plane(in, out, 3, 1, 3, 1, CG_DITHER_NONE) == CG_EINVAL);
    CHECK(cg_dither_plane(in, out, 3, 1, 3, 257, CG_DITHER_NONE) == CG_EINVAL);
    CHECK(cg_dither_plane(in, out, 3, 1, 3, 4, (cg_dither)9) == CG_EINVAL);

    /* Image dithering: every channel ends on a level, alpha untouched. */
    cg_image *img;
    CHECK(cg_image_create(&img, 40, 30, CG_PIXEL_RGBA8) == CG_OK);
    for (int y = 0; y < 30; y++)
        for (int x = 0; x < 40; x++)
            cg_image_set_rgba8(img, x, y, (cg_rgba8){(uint8_t)(x * 6), (uint8_t)(y * 8), 100, 50});
    CHECK(cg_image_dither(img, 4, CG_DITHER_BAYER4) == CG_OK);
    int off_level = 0;
    for (int y = 0; y < 30; y++)
        for (int x = 0; x < 40; x++) {
            cg_rgba8 p = cg_image_get_rgba8(img, x, y);
            off_level += p.r % 85 || p.g % 85 || p.b % 85 || p.a != 50;
        }
    CHECK_EQ_INT(off_level, 0);
    cg_image_free(img);
}

static void test_halftone(void)
{
    float in[11];
    for (int i = 0; i <= 10; i++)
        in[i] = (float)(i / 10.0);
    uint8_t out[11 * 9 * 4 * 4];
    for (int cell = 2; cell <= 4; cell++) {
        CHECK(cg_halftone_plane(in, 11, 1, 11, cell, out) == CG_OK);
        int bad = 0, monotone = 1;
        for (int i = 0; i <= 10; i++) {
            int on = 0;
            for (int j = 0; j < cell; j++)
                for (int k = 0; k < cell; k++) {
                    uint8_t v = out[j * 11 * cell + i * cell + k];
                    on += v == 255;
                    bad += v != 0 && v != 255;
                    /* a pixel on at level i stays on at higher levels */
                    if (v == 255 && i < 10 && out[j * 11 * cell + (i + 1) * cell + k] != 255)
                        monotone = 0;
                }
            bad += on != (int)floor(in[i] * cell * cell + 0.5);
        }
        CHECK_EQ_INT(bad, 0);
        CHECK(monotone);
    }
    CHECK(cg_halftone_plane(in, 11, 1, 11, 5, out) == CG_EINVAL);
    CHECK(cg_halftone_plane(in, 11, 1, 10, 3, out) == CG_EINVAL);
}

/* ---- parsing ----------------------------------------------------------------- */

static void test_parse(void)
{
    cg_rgba8 c;
    cg_error err;
    CHECK(cg_color_parse("#ff8000", &c, &err) == CG_OK && c.r == 255 && c.g == 128 && c.b == 0
          && c.a == 255);
    CHECK(cg_color_parse("#F80", &c, &err) == CG_OK && c.r == 255 && c.g == 136 && c.b == 0);
    CHECK(cg_color_parse("#f808", &c, &err) == CG_OK && c.a == 136);
    CHECK(cg_color_parse("#11223344", &c, &err) == CG_OK && c.a == 0x44);
    CHECK(cg_color_parse("CornflowerBlue", &c, &err) == CG_OK && c.r == 0x64 && c.g == 0x95
          && c.b == 0xed);
    CHECK(cg_color_parse("rebeccapurple", &c, &err) == CG_OK && c.r == 0x66 && c.b == 0x99);
    CHECK(cg_color_parse("aliceblue", &c, &err) == CG_OK && c.r == 0xf0);
    CHECK(cg_color_parse("yellowgreen", &c, &err) == CG_OK && c.r == 0x9a);
    CHECK(cg_color_parse("lightgoldenrodyellow", &c, &err) == CG_OK && c.b == 0xd2);
    CHECK(cg_color_parse("transparent", &c, &err) == CG_OK && c.a == 0);
    CHECK(cg_color_parse("grey", &c, &err) == CG_OK && c.r == 128);
    CHECK(cg_color_parse("bluish", &c, &err) == CG_EFORMAT);
    CHECK(strstr(err.message, "'bluish'") != NULL);
    CHECK(cg_color_parse("#12345", &c, &err) == CG_EFORMAT);
    CHECK(strstr(err.message, "#12345") != NULL);
    CHECK(cg_color_parse("#12g456", &c, &err) == CG_EFORMAT);
    CHECK(strstr(err.message, "#12g456") != NULL);
    CHECK(cg_color_parse("#", &c, &err) == CG_EFORMAT);
    CHECK(cg_color_parse("", &c, &err) == CG_EFORMAT);
    CHECK(cg_color_parse(NULL, &c, &err) == CG_EINVAL);
}

/* The shared exact encode rests on one property of its tables: a 1/4096
 * bucket of linear values holds at most one code threshold, and each
 * bucket starts at the code of its lower end.  The three-lane form must
 * give the scalar form's codes lane by lane. */
static void test_encode_tables(void)
{
    int bad = 0, bucket_bad = 0;
    for (int i = 0; i <= 4096; i++) {
        float lo = i / 4096.0f;
        int below = 0;
        while (below < 255 && color_srgb_threshold_table[below] <= lo)
            below++;
        bad += color_srgb_encode_start[i] != below;
        if (i < 4096)
            bucket_bad += color_srgb_encode_start[i + 1] - color_srgb_encode_start[i] > 1;
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(bucket_bad, 0);
#if defined(__SSE2__)
    check_rng r = {77};
    bad = 0;
    for (int i = 0; i < 300000; i++) {
        float v[3];
        for (int k = 0; k < 3; k++) {
            /* near a threshold a third of the time, anywhere (and outside
             * [0, 1]) otherwise */
            int t = (int)check_rng_range(&r, 0, 255);
            v[k] = i % 3 == 0 ? nextafterf(color_srgb_threshold_table[t],
                                           (float)check_rng_range(&r, -1, 2))
                              : (float)check_rng_range(&r, -0.2, 1.2);
        }
        if (i == 0) {
            v[0] = NAN;
            v[1] = INFINITY;
            v[2] = -INFINITY;
        }
        cg_rgba8 px = {0, 0, 0, 77};
        cg_srgb_encode_rgb(&px, _mm_setr_ps(v[0], v[1], v[2], 0.5f));
        uint8_t rgb[3] = {px.r, px.g, px.b};
        bad += px.a != 77;
        for (int k = 0; k < 3; k++)
            bad += rgb[k] != cg_srgb_encode_unit(v[k]) || rgb[k] != cg_linear_to_srgb8(v[k]);
    }
    CHECK_EQ_INT(bad, 0);
#endif
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_srgb);
    CHECK_GROUP(test_encode_tables);
    CHECK_GROUP(test_images);
    CHECK_GROUP(test_reference_values);
    CHECK_GROUP(test_round_trips);
    CHECK_GROUP(test_all_8bit_round_trip);
    CHECK_GROUP(test_8bit_fast_paths);
    CHECK_GROUP(test_bytes_and_buffers);
    CHECK_GROUP(test_by_name);
    CHECK_GROUP(test_bad_input);
    CHECK_GROUP(test_quantize_dither);
    CHECK_GROUP(test_halftone);
    CHECK_GROUP(test_parse);
    return check_finish();
}
