/* Float images: PFM (bit-exact round trips, both byte orders, orientation),
 * Radiance HDR (hand-made RGBE bytes, flat and run-length scanlines, the
 * quantization bound), OpenEXR (half and float precision, extra layers),
 * tone mapping against its formula, and hostile or truncated files. */
#include "cg.h"
#include "check.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static uint32_t rng_state = 0x2545f491u;
static uint32_t rng(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return rng_state;
}
static float uniform(float lo, float hi)
{
    return lo + (hi - lo) * (float)(rng() >> 8) / 16777216.0f;
}

static uint32_t bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static unsigned char *slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc(n > 0 ? (size_t)n : 1);
    *size = b ? fread(b, 1, (size_t)n, f) : 0;
    fclose(f);
    return b;
}

/* A load from memory that must fail with status and a message containing want. */
static void expect_bad(const void *bytes, size_t size, cg_status status, const char *want)
{
    cg_image *img = (cg_image *)1;
    cg_error err;
    cg_status got = cg_image_load_memory(bytes, size, "bad", &img, &err);
    CHECK_EQ_INT(got, status);
    CHECK(img == NULL);
    if (got != CG_OK)
        CHECK_MSG(strstr(err.message, want) && strncmp(err.message, "bad", 3) == 0
                      && !strchr(err.message, '\n'),
                  "message '%s' lacks '%s'", err.message, want);
    cg_image_free(got == CG_OK ? img : NULL);
}

static cg_image *random_image(int w, int h, int runs)
{
    cg_image *img;
    if (cg_image_create(&img, w, h, CG_PIXEL_RGBAF) != CG_OK)
        return NULL;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            cg_rgbaf c = {uniform(0, 4), uniform(0, 1e3f), uniform(0, 1e-3f), 1};
            if (runs && x > 0 && rng() % 4 != 0)
                c = cg_image_row_rgbaf(img, y)[x - 1]; /* runs for the RLE */
            cg_image_row_rgbaf(img, y)[x] = c;
        }
    return img;
}

static void test_pfm_bits(void)
{
    for (int t = 0; t < 20; t++) {
        int w = 1 + (int)(rng() % 37), h = 1 + (int)(rng() % 23);
        cg_image *img;
        CHECK_EQ_INT(cg_image_create(&img, w, h, CG_PIXEL_RGBAF), CG_OK);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                uint32_t u[3] = {rng(), rng(), rng()}; /* any bits: NaNs, infinities, denormals */
                cg_rgbaf *p = &cg_image_row_rgbaf(img, y)[x];
                memcpy(&p->r, &u[0], 4);
                memcpy(&p->g, &u[1], 4);
                memcpy(&p->b, &u[2], 4);
                p->a = 1;
            }
        cg_error err;
        CHECK_EQ_INT(cg_image_write(img, "float_bits.pfm", CG_FILE_UNKNOWN, &err), CG_OK);
        cg_image *back = NULL;
        CHECK_EQ_INT(cg_image_load("float_bits.pfm", &back, &err), CG_OK);
        if (!back) {
            cg_image_free(img);
            continue;
        }
        CHECK(back->width == w && back->height == h && back->format == CG_PIXEL_RGBAF);
        int same = 1;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                cg_rgbaf a = cg_image_row_rgbaf(img, y)[x], b = cg_image_row_rgbaf(back, y)[x];
                same &= bits(a.r) == bits(b.r) && bits(a.g) == bits(b.g) && bits(a.b) == bits(b.b)
                        && b.a == 1;
            }
        CHECK_MSG(same, "PFM %d x %d not bit-exact", w, h);
        cg_image_free(back);
        cg_image_free(img);
    }
}

static void test_pfm_layout(void)
{
    /* Big-endian grey 2 x 2: file rows bottom first. */
    unsigned char pf[] = "Pf\n2 2\n1.0\n"
                         "\x3f\x80\x00\x00\x40\x00\x00\x00"  /* bottom row: 1, 2 */
                         "\x40\x40\x00\x00\x40\x80\x00\x00"; /* top row: 3, 4 */
    cg_image *img = NULL;
    cg_error err;
    CHECK_EQ_INT(cg_image_load_memory(pf, sizeof pf - 1, "grey", &img, &err), CG_OK);
    if (img) {
        cg_rgbaf tl = cg_image_get(img, 0, 0), br = cg_image_get(img, 1, 1);
        CHECK(tl.r == 3 && tl.g == 3 && tl.b == 3 && tl.a == 1);
        CHECK(br.r == 2 && br.g == 2 && br.b == 2);
        cg_image_free(img);
    }
    /* Little-endian colour 1 x 2, and the header the writer makes. */
    cg_image *two;
    CHECK_EQ_INT(cg_image_create(&two, 1, 2, CG_PIXEL_RGBAF), CG_OK);
    cg_image_set(two, 0, 0, (cg_rgbaf){1, 2, 3, 1});
    cg_image_set(two, 0, 1, (cg_rgbaf){4, 5, 6, 1});
    CHECK_EQ_INT(cg_image_write(two, "float_two.pfm", CG_FILE_PFM, &err), CG_OK);
    size_t n = 0;
    unsigned char *b = slurp("float_two.pfm", &n);
    const char *head = "PF\n1 2\n-1.0\n";
    CHECK(b && n == strlen(head) + 24 && memcmp(b, head, strlen(head)) == 0);
    if (b && n == strlen(head) + 24) {
        float first;
        memcpy(&first, b + strlen(head), 4); /* the bottom row's red, little-endian here */
        CHECK(first == 4);
    }
    free(b);
    cg_image_free(two);
    /* An 8-bit reader of a float file gets the sRGB encoding, clamped. */
    CHECK_EQ_INT(cg_image_read_memory(pf, sizeof pf - 1, "grey", &img, &err), CG_OK);
    if (img) {
        CHECK(img->format == CG_PIXEL_RGBA8 && cg_image_get_rgba8(img, 0, 0).r == 255);
        cg_image_free(img);
    }
}

static void test_pfm_bad(void)
{
    expect_bad("PF\n", 3, CG_EFORMAT, "bad PFM header");
    expect_bad("PF\n2 x\n-1\n", 10, CG_EFORMAT, "bad PFM header");
    expect_bad("PF\n-2 2\n-1\n", 11, CG_EFORMAT, "bad PFM header");
    expect_bad("PF\n1 1\n0\n\0\0\0\0\0\0\0\0\0\0\0\0", 21, CG_EFORMAT, "bad PFM scale");
    expect_bad("PF\n1 1\nnan\n\0\0\0\0\0\0\0\0\0\0\0\0", 23, CG_EFORMAT, "bad PFM scale");
    expect_bad("PF\n1 1\n-1", 9, CG_EFORMAT, "without pixel data");
    expect_bad("PF\n2 2\n-1\n\0\0\0\0", 14, CG_EFORMAT, "truncated PFM");
    expect_bad("PF\n0 2\n-1\n", 10, CG_EFORMAT, "zero width");
    expect_bad("PF\n100000000 100000000\n-1\n", 26, CG_ERANGE, "over cg's limit");
    expect_bad("PF\n20000 20000\n-1\n", 18, CG_ERANGE, "over cg's limit");
    expect_bad("Pf\n99999999999999999999999 1\n-1\n", 31, CG_ERANGE, "over cg's limit");
}

/* An RGBE pixel as Radiance decodes it. */
static float rgbe_value(int m, int e)
{
    return e == 0 ? 0.0f : (float)ldexp(m + 0.5, e - 136);
}

static void test_hdr_bytes(void)
{
    /* Flat scanlines, 2 x 2: rows top first. */
    const unsigned char flat[] = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1.0\n\n-Y 2 +X 2\n"
                                 "\x80\x40\x20\x81"
                                 "\x00\x00\x00\x00"
                                 "\xff\x01\x00\x7f"
                                 "\x10\x20\x30\x88";
    cg_image *img = NULL;
    cg_error err;
    CHECK_EQ_INT(cg_image_load_memory(flat, sizeof flat - 1, "flat", &img, &err), CG_OK);
    if (img) {
        cg_rgbaf p = cg_image_get(img, 0, 0);
        CHECK(p.r == rgbe_value(128, 129) && p.g == rgbe_value(64, 129)
              && p.b == rgbe_value(32, 129) && p.a == 1);
        CHECK(cg_image_get(img, 1, 0).r == 0);
        p = cg_image_get(img, 0, 1);
        CHECK(p.r == rgbe_value(255, 127) && p.g == rgbe_value(1, 127)
              && p.b == rgbe_value(0, 127));
        CHECK(cg_image_get(img, 1, 1).b == rgbe_value(0x30, 0x88));
        cg_image_free(img);
    }
    /* EXPOSURE=K lines are cumulative multipliers the reader undoes: the
     * same pixels under EXPOSURE=2 and EXPOSURE=4 (a product of 8) come out
     * an eighth as bright, exactly (powers of two). */
    const unsigned char exposed[] = "#?RADIANCE\nEXPOSURE=2\nEXPOSURE= 4 \n\n-Y 2 +X 2\n"
                                    "\x80\x40\x20\x81"
                                    "\x00\x00\x00\x00"
                                    "\xff\x01\x00\x7f"
                                    "\x10\x20\x30\x88";
    CHECK_EQ_INT(cg_image_load_memory(exposed, sizeof exposed - 1, "exposed", &img, &err), CG_OK);
    if (img) {
        cg_rgbaf p = cg_image_get(img, 0, 0);
        CHECK(p.r == rgbe_value(128, 129) / 8 && p.g == rgbe_value(64, 129) / 8
              && p.b == rgbe_value(32, 129) / 8 && p.a == 1);
        CHECK(cg_image_get(img, 1, 1).b == rgbe_value(0x30, 0x88) / 8);
        cg_image_free(img);
    }
    /* One run-length scanline of width 8: R a run of 8, G literals, B a run
     * of 5 and 3 literals, E a run of 8. */
    const unsigned char rle[] = "#?RGBE\n\n-Y 1 +X 8\n"
                                "\x02\x02\x00\x08"
                                "\x88\x64"
                                "\x08\x01\x02\x03\x04\x05\x06\x07\x08"
                                "\x85\x09\x03\x0a\x0b\x0c"
                                "\x88\x80";
    CHECK_EQ_INT(cg_image_load_memory(rle, sizeof rle - 1, "rle", &img, &err), CG_OK);
    if (img) {
        int ok = img->width == 8 && img->height == 1;
        for (int x = 0; x < 8 && ok; x++) {
            cg_rgbaf p = cg_image_get(img, x, 0);
            ok = p.r == rgbe_value(100, 128) && p.g == rgbe_value(x + 1, 128)
                 && p.b == rgbe_value(x < 5 ? 9 : 10 + (x - 5), 128);
        }
        CHECK(ok);
        cg_image_free(img);
    }
}

static void test_hdr_round_trip(void)
{
    for (int t = 0; t < 30; t++) {
        int w = 1 + (int)(rng() % 40), h = 1 + (int)(rng() % 9);
        cg_image *img = random_image(w, h, t % 2);
        cg_error err;
        CHECK_EQ_INT(cg_image_write(img, "float_rt.hdr", CG_FILE_UNKNOWN, &err), CG_OK);
        cg_image *back = NULL;
        CHECK_EQ_INT(cg_image_load("float_rt.hdr", &back, &err), CG_OK);
        if (!back) {
            cg_image_free(img);
            continue;
        }
        CHECK(back->width == w && back->height == h);
        double worst = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                cg_rgbaf a = cg_image_get(img, x, y), b = cg_image_get(back, x, y);
                double m = fmax(a.r, fmax(a.g, a.b));
                double e = fmax(fabs(a.r - b.r), fmax(fabs(a.g - b.g), fabs(a.b - b.b)));
                worst = fmax(worst, e / m);
            }
        /* mantissas of 8 bits, decoded at the middle of their step */
        CHECK_MSG(worst <= 1.0 / 256, "HDR %d x %d: relative error %g over 2^-8", w, h, worst);
        cg_image_free(back);
        cg_image_free(img);
    }
}

static void test_hdr_bad(void)
{
    expect_bad("#?RADIANCE\n", 11, CG_EFORMAT, "ends before the resolution");
    expect_bad("#?RADIANCE\nEXPOSURE=0\n\n-Y 1 +X 1\n\0\0\0\0", 37, CG_EFORMAT, "exposure");
    expect_bad("#?RADIANCE\nEXPOSURE=-2\n\n-Y 1 +X 1\n\0\0\0\0", 38, CG_EFORMAT, "exposure");
    expect_bad("#?RADIANCE\nEXPOSURE=nan\n\n-Y 1 +X 1\n\0\0\0\0", 39, CG_EFORMAT, "exposure");
    expect_bad("#?RADIANCE\nEXPOSURE=2x\n\n-Y 1 +X 1\n\0\0\0\0", 38, CG_EFORMAT, "exposure");
    expect_bad("#?RADIANCE\nEXPOSURE=1e300\nEXPOSURE=1e300\n\n-Y 1 +X 1\n\0\0\0\0", 56, CG_EFORMAT,
               "exposure");
    expect_bad("#?NOTHDR\n\n-Y 1 +X 1\n\0\0\0\0", 24, CG_EFORMAT, "not a Radiance HDR");
    expect_bad("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\0\0\0\0", 48, CG_EUNSUPPORTED,
               "xyze");
    expect_bad("#?RADIANCE\n\n+Y 1 +X 1\n\0\0\0\0", 26, CG_EUNSUPPORTED, "orientation");
    expect_bad("#?RADIANCE\n\n-Y 2 +X 1\n\0\0\0\0", 26, CG_EFORMAT, "truncated HDR");
    expect_bad("#?RADIANCE\n\n-Y 1 +X 8\n\x02\x02\x00\x08\x00", 27, CG_EFORMAT, "run length");
    expect_bad("#?RADIANCE\n\n-Y 1 +X 8\n\x02\x02\x00\x08\x89\x01", 28, CG_EFORMAT, "run length");
    expect_bad("#?RADIANCE\n\n-Y 1 +X 8\n\x02\x02\x00\x09\x88\x01", 28, CG_EFORMAT,
               "width mismatch");
    expect_bad("#?RADIANCE\n\n-Y 1 +X 8\n\x02\x02\x00\x08\x88", 27, CG_EFORMAT, "truncated");
    expect_bad("#?RADIANCE\n\n-Y 100000 +X 100000\n", 33, CG_ERANGE, "over cg's limit");
    expect_bad("#?RADIANCE\n\n-Y 0 +X 5\n", 22, CG_EFORMAT, "zero width");
    /* a few bytes claiming 12 x 12,996,627 pixels: refused before allocating */
    expect_bad("#?RADIANCE\n\n-Y 12996627 +X 12\n\x02\x02\x00\x0c", 34, CG_EFORMAT,
               "need at least");
}

/* The filmic curve of cg/image_float.h, in double. */
static double filmic(double x)
{
    return x > 0 ? x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14) : 0;
}

static void test_tonemap(void)
{
    cg_image *img;
    CHECK_EQ_INT(cg_image_create(&img, 64, 4, CG_PIXEL_RGBAF), CG_OK);
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 64; x++) {
            float v = x == 0 ? 0 : (float)ldexp(1.0, x / 4 - 8) * (1 + (float)(x % 4) / 4);
            cg_image_row_rgbaf(img, y)[x] = (cg_rgbaf){v, -v, y == 3 ? NAN : v / 3, 0.5f};
        }
    const double exposures[] = {0, -1.5, 2};
    for (int e = 0; e < 3; e++) {
        cg_image *clamped = NULL, *film = NULL;
        CHECK_EQ_INT(cg_image_tonemap_curve(img, exposures[e], CG_TONEMAP_CLAMP, &clamped), CG_OK);
        CHECK_EQ_INT(cg_image_tonemap_curve(img, exposures[e], CG_TONEMAP_FILMIC, &film), CG_OK);
        if (!clamped || !film)
            break;
        double k = exp2(exposures[e]);
        int ok = 1, last = -1, mono = 1;
        for (int x = 0; x < 64; x++) {
            cg_rgbaf p = cg_image_get(img, x, 0);
            cg_rgba8 c = cg_image_get_rgba8(clamped, x, 0), f = cg_image_get_rgba8(film, x, 0);
            ok &= c.r == cg_linear_to_srgb8((float)(p.r * k)) && c.g == 0 && c.a == 128;
            ok &= f.r == cg_linear_to_srgb8((float)filmic((float)(p.r * k))) && f.g == 0;
            ok &= cg_image_get_rgba8(film, x, 3).b == 0; /* NaN */
            mono &= f.r >= last;
            last = f.r;
        }
        CHECK_MSG(ok, "tone curves differ from their definition at exposure %g", exposures[e]);
        CHECK(mono);
        cg_image_free(clamped);
        cg_image_free(film);
    }
    /* Clamp without exposure is what cg writes to PNG. */
    cg_image *enc = NULL, *tm = NULL;
    CHECK_EQ_INT(cg_image_encode_srgb(img, &enc), CG_OK);
    CHECK_EQ_INT(cg_image_tonemap_curve(img, 0, CG_TONEMAP_CLAMP, &tm), CG_OK);
    CHECK(enc && tm && memcmp(enc->data, tm->data, enc->stride * 4) == 0);
    cg_image_free(enc);
    cg_image_free(tm);
    CHECK(filmic(1e30) > 1 && cg_linear_to_srgb8((float)filmic(1e6)) == 255);
    cg_image *out = (cg_image *)1;
    CHECK_EQ_INT(cg_image_tonemap_curve(img, NAN, CG_TONEMAP_FILMIC, &out), CG_EINVAL);
    CHECK(out == NULL);
    CHECK_EQ_INT(cg_image_tonemap_curve(img, 0, (cg_tonemap)9, &out), CG_EINVAL);
    cg_image *small;
    CHECK_EQ_INT(cg_image_create(&small, 2, 2, CG_PIXEL_RGBA8), CG_OK);
    CHECK_EQ_INT(cg_image_tonemap_curve(small, 0, CG_TONEMAP_CLAMP, &out), CG_EINVAL);
    cg_image_free(small);
    cg_image_free(img);
}

/* The nearest half to v (round to nearest even), in [-65504, 65504]. */
static double half_step(double v)
{
    int e;
    frexp(fabs(v), &e);
    return ldexp(1.0, (e - 1 < -14 ? -14 : e - 1) - 10);
}

static void test_exr(void)
{
    cg_error err;
    cg_image *img = random_image(37, 19, 0);
    if (!cg_exr_supported()) {
        CHECK_EQ_INT(cg_image_write(img, "float.exr", CG_FILE_UNKNOWN, &err), CG_EUNSUPPORTED);
        CHECK(strstr(err.message, "without OpenEXR") != NULL);
        printf("OpenEXR not built in: only the refusal is checked\n");
        cg_image_free(img);
        return;
    }
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            cg_rgbaf *p = &cg_image_row_rgbaf(img, y)[x];
            p->r = uniform(-60000, 60000);
            p->a = uniform(0, 1);
        }
    for (int full = 0; full < 2; full++) {
        cg_exr_options options = {full};
        CHECK_EQ_INT(cg_image_write_exr("float.exr", img, NULL, 0, &options, &err), CG_OK);
        cg_image *back = NULL;
        CHECK_EQ_INT(cg_image_load("float.exr", &back, &err), CG_OK);
        if (!back)
            continue;
        CHECK(back->width == 37 && back->height == 19 && back->format == CG_PIXEL_RGBAF);
        int ok = 1;
        for (int y = 0; y < img->height; y++)
            for (int x = 0; x < img->width; x++) {
                const float *a = &cg_image_row_rgbaf(img, y)[x].r;
                const float *b = &cg_image_row_rgbaf(back, y)[x].r;
                for (int k = 0; k < 4; k++)
                    ok &= full ? bits(a[k]) == bits(b[k])
                               : fabs(a[k] - b[k]) <= 0.5 * half_step(a[k]);
            }
        CHECK_MSG(ok, "EXR %s round trip out of bounds", full ? "float" : "half");
        cg_image_free(back);
    }
    /* Layers: written beside the beauty, which still reads back. */
    cg_image *albedo = random_image(37, 19, 0), *wrong = random_image(3, 3, 0);
    cg_image_layer layers[2] = {{"albedo", "RGB", albedo}, {"depth", "Z", albedo}};
    CHECK_EQ_INT(cg_image_write_exr("float_layers.exr", img, layers, 2, NULL, &err), CG_OK);
    cg_image *back = NULL;
    CHECK_EQ_INT(cg_image_load("float_layers.exr", &back, &err), CG_OK);
    CHECK(back && back->width == 37);
    cg_image_free(back);
    /* OpenEXR's own exrheader (Debian openexr), when present, lists them. */
    FILE *tool = system("command -v exrheader >/dev/null 2>&1") == 0
                     ? popen("exrheader float_layers.exr", "r")
                     : NULL;
    if (tool) {
        char line[256];
        int seen = 0;
        while (fgets(line, sizeof line, tool))
            for (int k = 0; k < 4; k++)
                if (strstr(line, (const char *[]){"albedo.R, 16-bit", "albedo.G, 16-bit",
                                                  "albedo.B, 16-bit", "depth.Z, 16-bit"}[k]))
                    seen |= 1 << k;
        CHECK_EQ_INT(pclose(tool), 0);
        CHECK_MSG(seen == 15, "exrheader lists layer channels %x of f", seen);
    } else
        printf("exrheader missing (Debian openexr): layer names not checked by OpenEXR\n");
    /* Bad layers are refused and leave the file as it was. */
    struct stat before, after;
    CHECK(stat("float_layers.exr", &before) == 0);
    cg_image_layer bad[] = {{"albedo", "RGB", wrong}, {"a b", "R", albedo}, {"x", "", albedo},
                            {"albedo", "RR", albedo}, {NULL, "R", albedo},  {"x", "R", NULL}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        CHECK_EQ_INT(cg_image_write_exr("float_layers.exr", img, &bad[i], 1, NULL, &err),
                     CG_EINVAL);
    CHECK(stat("float_layers.exr", &after) == 0 && after.st_size == before.st_size
          && after.st_mtime == before.st_mtime);
    /* Truncated and corrupted files: refused with the name, never a crash. */
    size_t n = 0;
    unsigned char *bytes = slurp("float_layers.exr", &n);
    CHECK(bytes && n > 200);
    for (size_t cut = 4; bytes && cut < n; cut += n / 7)
        expect_bad(bytes, cut, CG_EFORMAT, "OpenEXR");
    for (int t = 0; bytes && t < 300; t++) {
        unsigned char *copy = malloc(n);
        memcpy(copy, bytes, n);
        for (int k = 0; k < 4; k++)
            copy[4 + rng() % (n - 4)] = (unsigned char)rng();
        cg_image *out = NULL;
        cg_status s = cg_image_load_memory(copy, n, "mutant", &out, &err);
        CHECK(s == CG_OK ? out != NULL : out == NULL && strncmp(err.message, "mutant", 6) == 0);
        cg_image_free(out);
        free(copy);
    }
    free(bytes);
    cg_image_free(albedo);
    cg_image_free(wrong);
    cg_image_free(img);
}

static void test_formats(void)
{
    CHECK_EQ_INT(cg_file_format_from_path("a.PFM"), CG_FILE_PFM);
    CHECK_EQ_INT(cg_file_format_from_path("sky.hdr"), CG_FILE_HDR);
    CHECK_EQ_INT(cg_file_format_from_path("x/beauty.exr"), CG_FILE_EXR);
    CHECK(cg_file_format_is_float(CG_FILE_EXR) && !cg_file_format_is_float(CG_FILE_PNG));
    /* An 8-bit image written to a float format is decoded to linear light. */
    cg_image *img, *back = NULL;
    cg_error err;
    CHECK_EQ_INT(cg_image_create(&img, 1, 1, CG_PIXEL_RGBA8), CG_OK);
    cg_image_set_rgba8(img, 0, 0, (cg_rgba8){188, 0, 255, 255});
    CHECK_EQ_INT(cg_image_write(img, "float_8bit.pfm", CG_FILE_UNKNOWN, &err), CG_OK);
    CHECK_EQ_INT(cg_image_load("float_8bit.pfm", &back, &err), CG_OK);
    if (back) {
        cg_rgbaf p = cg_image_get(back, 0, 0);
        CHECK(p.r == cg_srgb8_to_linear(188) && p.g == 0 && p.b == 1);
    }
    cg_image_free(back);
    /* A write into a missing folder fails cleanly. */
    CHECK(cg_image_write(img, "no/such/dir/x.hdr", CG_FILE_UNKNOWN, &err) != CG_OK);
    cg_image_free(img);
}

/* cg_image_load_linear: every 8-bit code of a PNG decodes from sRGB, alpha
 * scaled; a float file comes back bit for bit; errors name the file. */
static void test_load_linear(void)
{
    cg_image *img, *back = NULL;
    cg_error err;
    CHECK_EQ_INT(cg_image_create(&img, 256, 1, CG_PIXEL_RGBA8), CG_OK);
    for (int k = 0; k < 256; k++)
        cg_image_set_rgba8(img, k, 0, (cg_rgba8){(uint8_t)k, (uint8_t)(255 - k), 0, (uint8_t)k});
    CHECK_EQ_INT(cg_image_write(img, "linear_codes.png", CG_FILE_UNKNOWN, &err), CG_OK);
    CHECK_EQ_INT(cg_image_load_linear("linear_codes.png", &back, &err), CG_OK);
    CHECK(back && back->format == CG_PIXEL_RGBAF && back->width == 256);
    for (int k = 0; back && k < 256; k++) {
        cg_rgbaf p = cg_image_get(back, k, 0);
        CHECK(p.r == cg_srgb8_to_linear((uint8_t)k) && p.g == cg_srgb8_to_linear((uint8_t)(255 - k))
              && p.b == 0 && fabsf(p.a - (float)k / 255) <= 1e-7f);
    }
    cg_image_free(back);
    cg_image_free(img);
    CHECK_EQ_INT(cg_image_create(&img, 2, 1, CG_PIXEL_RGBAF), CG_OK);
    cg_image_set(img, 0, 0, (cg_rgbaf){3.25f, 0.1f, 1e-6f, 1});
    cg_image_set(img, 1, 0, (cg_rgbaf){0, 65504.0f, 0.5f, 1});
    CHECK_EQ_INT(cg_image_write(img, "linear_float.pfm", CG_FILE_UNKNOWN, &err), CG_OK);
    back = NULL;
    CHECK_EQ_INT(cg_image_load_linear("linear_float.pfm", &back, &err), CG_OK);
    for (int x = 0; back && x < 2; x++) {
        cg_rgbaf a = cg_image_get(img, x, 0), b = cg_image_get(back, x, 0);
        CHECK(a.r == b.r && a.g == b.g && a.b == b.b);
    }
    cg_image_free(back);
    cg_image_free(img);
    back = img;
    CHECK_EQ_INT(cg_image_load_linear("no_such_sky.hdr", &back, &err), CG_EIO);
    CHECK(back == NULL && strstr(err.message, "no_such_sky.hdr") != NULL);
    CHECK_EQ_INT(cg_image_load_linear(NULL, &back, &err), CG_EINVAL);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_pfm_bits);
    CHECK_GROUP(test_pfm_layout);
    CHECK_GROUP(test_pfm_bad);
    CHECK_GROUP(test_hdr_bytes);
    CHECK_GROUP(test_hdr_round_trip);
    CHECK_GROUP(test_hdr_bad);
    CHECK_GROUP(test_tonemap);
    CHECK_GROUP(test_exr);
    CHECK_GROUP(test_formats);
    CHECK_GROUP(test_load_linear);
    return check_finish();
}
