/* Textures against their definitions (cg/texture.h), over random inputs:
 * decoding (sRGB curve or code / 255), the mip chain (each level the
 * area-weighted box average of the one before, in linear light), wrap
 * indices, nearest / bilinear / trilinear samples against sums written out
 * here, and PNG / JPEG files read back (JPEG written with libjpeg itself,
 * broken ones refused with a message). */
#include "cg.h"
#include "check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <jpeglib.h>

/* The sRGB curve, written out (IEC 61966-2-1). */
static double srgb_decode(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static cg_image *random_image(check_rng *rng, int width, int height)
{
    cg_image *image;
    if (cg_image_create(&image, width, height, CG_PIXEL_RGBA8) != CG_OK)
        return NULL;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            cg_rgba8 c = {(uint8_t)check_rng_int(rng, 0, 255), (uint8_t)check_rng_int(rng, 0, 255),
                          (uint8_t)check_rng_int(rng, 0, 255),
                          (uint8_t)(check_rng_int(rng, 0, 3) ? check_rng_int(rng, 0, 255) : 255)};
            cg_image_set_rgba8(image, x, y, c);
        }
    return image;
}

/* Level 0 texel (x, y) by the definition: decoded, premultiplied when colour. */
static void expected_texel(const cg_image *image, int x, int y, cg_texture_encoding e,
                           double out[4])
{
    cg_rgba8 c = cg_image_get_rgba8(image, x, y);
    double a = c.a / 255.0;
    double rgb[3] = {c.r / 255.0, c.g / 255.0, c.b / 255.0};
    for (int k = 0; k < 3; k++)
        out[k] = e == CG_TEXTURE_SRGB ? srgb_decode(rgb[k]) * a : rgb[k];
    out[3] = a;
}

static void decoding(void)
{
    check_rng rng = {11};
    for (int round = 0; round < 40; round++) {
        int w = (int)check_rng_int(&rng, 1, 17), h = (int)check_rng_int(&rng, 1, 17);
        cg_texture_encoding e = round % 2 ? CG_TEXTURE_LINEAR : CG_TEXTURE_SRGB;
        cg_image *image = random_image(&rng, w, h);
        cg_texture *t = NULL;
        CHECK(cg_texture_from_image(image, e, &t) == CG_OK);
        if (!t) {
            cg_image_free(image);
            continue;
        }
        int levels = 1;
        for (int side = w > h ? w : h; side > 1; side /= 2)
            levels++;
        CHECK_EQ_INT(t->level_count, levels);
        CHECK(t->levels[0].width == w && t->levels[0].height == h);
        long bad = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                double want[4];
                expected_texel(image, x, y, e, want);
                cg_rgbaf got = t->levels[0].texels[y * w + x];
                bad += fabs(got.r - want[0]) > 2e-6 || fabs(got.g - want[1]) > 2e-6
                       || fabs(got.b - want[2]) > 2e-6 || fabs(got.a - want[3]) > 1e-7;
            }
        CHECK_MSG(bad == 0, "round %d: %ld texels differ from the definition", round, bad);
        cg_texture_free(t);
        cg_image_free(image);
    }
}

/* Overlap of [a0, a1) and [b0, b1). */
static double overlap(double a0, double a1, double b0, double b1)
{
    double lo = fmax(a0, b0), hi = fmin(a1, b1);
    return hi > lo ? hi - lo : 0;
}

static void mip_box_average(void)
{
    check_rng rng = {23};
    for (int round = 0; round < 40; round++) {
        int w = (int)check_rng_int(&rng, 1, 40), h = (int)check_rng_int(&rng, 1, 40);
        cg_image *image = random_image(&rng, w, h);
        cg_texture *t = NULL;
        CHECK(cg_texture_from_image(image, round % 2 ? CG_TEXTURE_LINEAR : CG_TEXTURE_SRGB, &t)
              == CG_OK);
        for (int k = 1; t && k < t->level_count; k++) {
            const cg_texture_level *a = &t->levels[k - 1], *b = &t->levels[k];
            int ew = a->width > 1 ? a->width / 2 : 1, eh = a->height > 1 ? a->height / 2 : 1;
            CHECK(b->width == ew && b->height == eh);
            double rx = (double)a->width / b->width, ry = (double)a->height / b->height;
            long bad = 0;
            for (int y = 0; y < b->height; y++)
                for (int x = 0; x < b->width; x++) {
                    /* the area-weighted mean of every level-(k-1) texel under texel (x, y) */
                    double sum[4] = {0, 0, 0, 0}, area = 0;
                    for (int sy = 0; sy < a->height; sy++)
                        for (int sx = 0; sx < a->width; sx++) {
                            double wgt = overlap(sx, sx + 1, x * rx, (x + 1) * rx)
                                         * overlap(sy, sy + 1, y * ry, (y + 1) * ry);
                            if (wgt == 0)
                                continue;
                            cg_rgbaf s = a->texels[sy * a->width + sx];
                            sum[0] += wgt * s.r, sum[1] += wgt * s.g, sum[2] += wgt * s.b,
                                sum[3] += wgt * s.a;
                            area += wgt;
                        }
                    cg_rgbaf got = b->texels[y * b->width + x];
                    bad += fabs(got.r - sum[0] / area) > 1e-5 || fabs(got.g - sum[1] / area) > 1e-5
                           || fabs(got.b - sum[2] / area) > 1e-5
                           || fabs(got.a - sum[3] / area) > 1e-5;
                }
            CHECK_MSG(bad == 0, "round %d level %d (%dx%d): %ld texels are not the box average",
                      round, k, b->width, b->height, bad);
        }
        CHECK(t && t->levels[t->level_count - 1].width == 1
              && t->levels[t->level_count - 1].height == 1);
        cg_texture_free(t);
        cg_image_free(image);
    }
    /* in linear light: black and white average to 0.5, not to sRGB code 128 */
    cg_image *bw;
    cg_image_create(&bw, 2, 1, CG_PIXEL_RGBA8);
    cg_rgba8 black = {0, 0, 0, 255}, white = {255, 255, 255, 255};
    cg_image_set_rgba8(bw, 0, 0, black);
    cg_image_set_rgba8(bw, 1, 0, white);
    cg_texture *t;
    CHECK(cg_texture_from_image(bw, CG_TEXTURE_SRGB, &t) == CG_OK);
    CHECK_NEAR(t->levels[1].texels[0].r, 0.5, 1e-7);
    cg_texture_free(t);
    cg_image_free(bw);
}

static int wrap_by_definition(long long i, int n, cg_texture_wrap wrap)
{
    if (wrap == CG_TEXTURE_CLAMP)
        return i < 0 ? 0 : i >= n ? n - 1 : (int)i;
    if (wrap == CG_TEXTURE_REPEAT) {
        long long k = i;
        while (k < 0)
            k += n;
        return (int)(k % n);
    }
    /* mirrored: walk the pattern 0 1 .. n-1 n-1 .. 0 from 0 */
    long long k = i < 0 ? -i - 1 : i; /* mirror at -0.5 */
    long long period = 2LL * n;
    k %= period;
    return (int)(k < n ? k : period - 1 - k);
}

static void wrap_modes(void)
{
    check_rng rng = {31};
    long bad = 0;
    for (int round = 0; round < 20000; round++) {
        int n = (int)check_rng_int(&rng, 1, 9);
        long long i = check_rng_int(&rng, -40, 40);
        cg_texture_wrap wrap = (cg_texture_wrap)check_rng_int(&rng, 0, 2);
        bad += cg_texture_wrap_index(i, n, wrap) != wrap_by_definition(i, n, wrap);
    }
    CHECK_MSG(bad == 0, "%ld wrapped indices differ from the definition", bad);
    /* the patterns written out for n = 3 */
    static const int mirrored[] = {2, 1, 0, 0, 1, 2, 2, 1, 0, 0};
    static const int repeated[] = {0, 1, 2, 0, 1, 2, 0, 1, 2, 0};
    static const int clamped[] = {0, 0, 0, 0, 1, 2, 2, 2, 2, 2};
    for (int i = -3; i < 7; i++) {
        CHECK_EQ_INT(cg_texture_wrap_index(i, 3, CG_TEXTURE_MIRRORED_REPEAT), mirrored[i + 3]);
        CHECK_EQ_INT(cg_texture_wrap_index(i, 3, CG_TEXTURE_REPEAT), repeated[i + 3]);
        CHECK_EQ_INT(cg_texture_wrap_index(i, 3, CG_TEXTURE_CLAMP), clamped[i + 3]);
    }
    CHECK_EQ_INT(cg_texture_wrap_index(-(1LL << 60), 7, CG_TEXTURE_REPEAT),
                 wrap_by_definition(-(1LL << 60) % 7 + 7, 7, CG_TEXTURE_REPEAT));
}

/* The bilinear sample of a level written out: four texels, four weights. */
static void bilinear_by_hand(const cg_texture_level *l, cg_texture_wrap wu, cg_texture_wrap wv,
                             double u, double v, double out[4])
{
    double x = u * l->width - 0.5, y = (1 - v) * l->height - 0.5;
    double x0 = floor(x), y0 = floor(y), fx = x - x0, fy = y - y0;
    double sum[4] = {0, 0, 0, 0};
    for (int dy = 0; dy < 2; dy++)
        for (int dx = 0; dx < 2; dx++) {
            double w = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy);
            int tx = wrap_by_definition((long long)x0 + dx, l->width, wu);
            int ty = wrap_by_definition((long long)y0 + dy, l->height, wv);
            cg_rgbaf t = l->texels[ty * l->width + tx];
            sum[0] += w * t.r, sum[1] += w * t.g, sum[2] += w * t.b, sum[3] += w * t.a;
        }
    memcpy(out, sum, sizeof sum);
}

static void straighten(double c[4], cg_texture_encoding e)
{
    if (e != CG_TEXTURE_SRGB)
        return;
    for (int k = 0; k < 3; k++)
        c[k] = c[3] > 0 ? c[k] / c[3] : 0;
}

static int near4(cg_rgbaf got, const double want[4], double tolerance)
{
    double scale = 1 + fabs(want[0]) + fabs(want[1]) + fabs(want[2]);
    return fabs(got.r - want[0]) <= tolerance * scale && fabs(got.g - want[1]) <= tolerance * scale
           && fabs(got.b - want[2]) <= tolerance * scale && fabs(got.a - want[3]) <= tolerance;
}

static void sampling(void)
{
    check_rng rng = {47};
    long bad_nearest = 0, bad_bilinear = 0, bad_trilinear = 0, samples = 0;
    for (int round = 0; round < 60; round++) {
        int w = (int)check_rng_int(&rng, 1, 12), h = (int)check_rng_int(&rng, 1, 12);
        cg_texture_encoding e = round % 2 ? CG_TEXTURE_LINEAR : CG_TEXTURE_SRGB;
        cg_image *image = random_image(&rng, w, h);
        cg_texture *t = NULL;
        cg_texture_from_image(image, e, &t);
        for (int k = 0; t && k < 200; k++) {
            cg_texture_sampler s = {CG_TEXTURE_NEAREST, (cg_texture_wrap)check_rng_int(&rng, 0, 2),
                                    (cg_texture_wrap)check_rng_int(&rng, 0, 2)};
            double u = check_rng_range(&rng, -3, 3), v = check_rng_range(&rng, -3, 3);
            double lod = check_rng_range(&rng, -1, t->level_count + 1);
            /* nearest: the texel whose square holds (u, v) */
            int tx = wrap_by_definition((long long)floor(u * w), w, s.wrap_u);
            int ty = wrap_by_definition((long long)floor((1 - v) * h), h, s.wrap_v);
            cg_rgbaf texel = t->levels[0].texels[ty * w + tx];
            double want[4] = {texel.r, texel.g, texel.b, texel.a};
            straighten(want, e);
            bad_nearest += !near4(cg_texture_sample(t, &s, u, v, lod), want, 1e-6);
            s.filter = CG_TEXTURE_BILINEAR;
            bilinear_by_hand(&t->levels[0], s.wrap_u, s.wrap_v, u, v, want);
            straighten(want, e);
            bad_bilinear += !near4(cg_texture_sample(t, &s, u, v, lod), want, 1e-5);
            /* trilinear: the two levels around the clamped lod, mixed */
            s.filter = CG_TEXTURE_TRILINEAR;
            double clamped = fmin(fmax(lod, 0), t->level_count - 1);
            int level = (int)floor(clamped);
            double f = clamped - level, a[4], b[4] = {0, 0, 0, 0};
            bilinear_by_hand(&t->levels[level], s.wrap_u, s.wrap_v, u, v, a);
            if (level + 1 < t->level_count)
                bilinear_by_hand(&t->levels[level + 1], s.wrap_u, s.wrap_v, u, v, b);
            for (int c = 0; c < 4; c++)
                want[c] = a[c] + f * (b[c] - a[c]);
            straighten(want, e);
            bad_trilinear += !near4(cg_texture_sample(t, &s, u, v, lod), want, 1e-5);
            samples++;
        }
        cg_texture_free(t);
        cg_image_free(image);
    }
    CHECK_MSG(bad_nearest == 0, "%ld of %ld nearest samples differ", bad_nearest, samples);
    CHECK_MSG(bad_bilinear == 0, "%ld of %ld bilinear samples differ", bad_bilinear, samples);
    CHECK_MSG(bad_trilinear == 0, "%ld of %ld trilinear samples differ", bad_trilinear, samples);
}

/* Edges and hand-computed values on a 2 x 2 texture:
 *
 *   v = 1  +-------+-------+
 *          |  red  | green |     row 0
 *          +-------+-------+
 *          | blue  | clear |     row 1 (alpha 0, colour white)
 *   v = 0  +-------+-------+
 *        u = 0           u = 1 */
static void edges_and_alpha(void)
{
    cg_image *image;
    cg_image_create(&image, 2, 2, CG_PIXEL_RGBA8);
    cg_rgba8 red = {255, 0, 0, 255}, green = {0, 255, 0, 255}, blue = {0, 0, 255, 255},
             clear = {255, 255, 255, 0};
    cg_image_set_rgba8(image, 0, 0, red);
    cg_image_set_rgba8(image, 1, 0, green);
    cg_image_set_rgba8(image, 0, 1, blue);
    cg_image_set_rgba8(image, 1, 1, clear);
    cg_texture *t;
    CHECK(cg_texture_from_image(image, CG_TEXTURE_SRGB, &t) == CG_OK);
    cg_texture_sampler s = {CG_TEXTURE_BILINEAR, CG_TEXTURE_CLAMP, CG_TEXTURE_CLAMP};
    /* a texel centre gives the texel */
    cg_rgbaf c = cg_texture_sample(t, &s, 0.25, 0.75, 0);
    CHECK(c.r == 1 && c.g == 0 && c.b == 0 && c.a == 1);
    /* halfway between blue and the clear texel: blue at half alpha, no white bleeding in */
    c = cg_texture_sample(t, &s, 0.5, 0.25, 0);
    CHECK_NEAR(c.a, 0.5, 1e-6);
    CHECK_NEAR(c.r, 0, 1e-6);
    CHECK_NEAR(c.b, 1, 1e-6);
    /* the centre mixes red, green and blue equally (the clear texel adds only alpha) */
    c = cg_texture_sample(t, &s, 0.5, 0.5, 0);
    CHECK_NEAR(c.a, 0.75, 1e-6);
    CHECK_NEAR(c.r, 1.0 / 3, 1e-6);
    CHECK_NEAR(c.g, 1.0 / 3, 1e-6);
    /* clamp: far outside gives the edge texel */
    c = cg_texture_sample(t, &s, -50, 1e9, 0);
    CHECK(c.r == 1 && c.a == 1);
    /* repeat: u = 1 + 0.25 is u = 0.25; mirrored: u = 1.25 is u = 0.75 */
    s.wrap_u = s.wrap_v = CG_TEXTURE_REPEAT;
    c = cg_texture_sample(t, &s, 1.25, 0.75, 0);
    CHECK(c.r == 1 && c.g == 0);
    s.wrap_u = CG_TEXTURE_MIRRORED_REPEAT;
    c = cg_texture_sample(t, &s, 1.25, 0.75, 0);
    CHECK(c.g == 1 && c.r == 0);
    /* repeat across the edge: at u = 0 (between texel 1 and texel 0 of the next copy) */
    s.wrap_u = CG_TEXTURE_REPEAT;
    c = cg_texture_sample(t, &s, 0, 0.75, 0);
    CHECK_NEAR(c.r, 0.5, 1e-6);
    CHECK_NEAR(c.g, 0.5, 1e-6);
    /* NaN and infinite coordinates are taken as 0; huge ones do not overflow */
    c = cg_texture_sample(t, &s, NAN, INFINITY, NAN);
    CHECK(isfinite(c.r) && isfinite(c.a));
    c = cg_texture_sample(t, &s, 1e300, -1e300, 1e300);
    CHECK(isfinite(c.r) && isfinite(c.a));
    cg_texture_free(t);
    cg_image_free(image);
}

/* ---- files ------------------------------------------------------------- */

static unsigned char *jpeg_encode(const cg_image *image, int grey, int quality, unsigned long *size)
{
    struct jpeg_compress_struct info;
    struct jpeg_error_mgr errors;
    info.err = jpeg_std_error(&errors);
    jpeg_create_compress(&info);
    unsigned char *out = NULL;
    jpeg_mem_dest(&info, &out, size);
    info.image_width = (JDIMENSION)image->width;
    info.image_height = (JDIMENSION)image->height;
    info.input_components = grey ? 1 : 4;
    info.in_color_space = grey ? JCS_GRAYSCALE : JCS_EXT_RGBA;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, quality, TRUE);
    if (!grey) { /* no chroma subsampling, so colours come back close */
        info.comp_info[0].h_samp_factor = info.comp_info[0].v_samp_factor = 1;
    }
    jpeg_start_compress(&info, TRUE);
    unsigned char *row = malloc((size_t)image->width * 4);
    while (info.next_scanline < info.image_height) {
        const cg_rgba8 *src = (const cg_rgba8 *)(image->data + info.next_scanline * image->stride);
        for (int x = 0; x < image->width; x++) {
            if (grey) {
                row[x] = src[x].g;
            } else {
                memcpy(row + 4 * x, &src[x], 4);
            }
        }
        JSAMPROW r = row;
        jpeg_write_scanlines(&info, &r, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    free(row);
    return out;
}

static void jpeg_files(void)
{
    /* a smooth image survives JPEG at quality 100 within a few codes */
    cg_image *image;
    cg_image_create(&image, 37, 21, CG_PIXEL_RGBA8);
    for (int y = 0; y < 21; y++)
        for (int x = 0; x < 37; x++) {
            cg_rgba8 c = {(uint8_t)(x * 6), (uint8_t)(y * 11), (uint8_t)(128 + x - y), 255};
            cg_image_set_rgba8(image, x, y, c);
        }
    for (int grey = 0; grey < 2; grey++) {
        unsigned long size = 0;
        unsigned char *bytes = jpeg_encode(image, grey, 100, &size);
        cg_texture *t = NULL;
        cg_error err;
        CHECK_MSG(cg_texture_load_memory(bytes, size, "smooth.jpg", CG_TEXTURE_LINEAR, &t, &err)
                      == CG_OK,
                  "%s", err.message);
        if (t) {
            CHECK(t->levels[0].width == 37 && t->levels[0].height == 21);
            long far = 0;
            for (int y = 0; y < 21; y++)
                for (int x = 0; x < 37; x++) {
                    cg_rgba8 c = cg_image_get_rgba8(image, x, y);
                    cg_rgbaf got = t->levels[0].texels[y * 37 + x];
                    double want[3] = {c.r / 255.0, c.g / 255.0, c.b / 255.0};
                    if (grey)
                        far += fabs(got.r - want[1]) > 3 / 255.0 || got.r != got.g
                               || got.g != got.b;
                    else
                        far += fabs(got.r - want[0]) > 4 / 255.0
                               || fabs(got.g - want[1]) > 4 / 255.0
                               || fabs(got.b - want[2]) > 4 / 255.0;
                    far += got.a != 1;
                }
            CHECK_MSG(far == 0, "grey %d: %ld texels are far from the image", grey, far);
        }
        cg_texture_free(t);
        /* every truncation is refused with a message naming the file */
        long bad = 0;
        for (unsigned long n = 0; n < size; n += n < 700 ? 1 : 37) {
            t = NULL;
            cg_error_clear(&err);
            cg_status s = cg_texture_load_memory(bytes, n, "cut.jpg", CG_TEXTURE_SRGB, &t, &err);
            bad += s == CG_OK || t || strncmp(err.message, "cut.jpg: ", 9) != 0;
            cg_texture_free(t);
        }
        CHECK_MSG(bad == 0, "grey %d: %ld truncated JPEG files were not refused", grey, bad);
        free(bytes);
    }
    cg_image_free(image);
    /* not an image; a PNG whose header claims too many pixels */
    cg_texture *t = NULL;
    cg_error err;
    CHECK(cg_texture_load_memory("GIF89a", 6, "a.gif", CG_TEXTURE_SRGB, &t, &err) == CG_EFORMAT
          && strstr(err.message, "a.gif: expected a PNG or JPEG image"));
    unsigned char png[33] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0,
                             0,    13,  'I', 'H', 'D',  'R',  0,    1,    0, 0,
                             0,    1,   0,   0,   8,    6,    0,    0,    0};
    CHECK(cg_texture_load_memory(png, sizeof png, "big.png", CG_TEXTURE_SRGB, &t, &err) == CG_ERANGE
          && strstr(err.message, "big.png: a PNG of 65536 x 65536 pixels"));
    CHECK(cg_texture_load("/nonexistent/t.png", CG_TEXTURE_SRGB, &t, &err) == CG_EIO
          && strstr(err.message, "/nonexistent/t.png: cannot open"));
}

static void png_files(void)
{
    check_rng rng = {5};
    cg_image *image = random_image(&rng, 13, 9);
    char path[] = "/tmp/cg_texture_XXXXXX.png";
    int fd = mkstemps(path, 4);
    CHECK(fd >= 0);
    close(fd);
    cg_error err;
    CHECK(cg_image_write(image, path, CG_FILE_PNG, &err) == CG_OK);
    for (int e = 0; e < 2; e++) {
        cg_texture *t = NULL;
        CHECK_MSG(cg_texture_load(path, (cg_texture_encoding)e, &t, &err) == CG_OK, "%s",
                  err.message);
        long bad = 0;
        for (int y = 0; t && y < 9; y++)
            for (int x = 0; x < 13; x++) {
                double want[4];
                expected_texel(image, x, y, (cg_texture_encoding)e, want);
                cg_rgbaf got = t->levels[0].texels[y * 13 + x];
                bad += fabs(got.r - want[0]) > 2e-6 || fabs(got.a - want[3]) > 1e-7;
            }
        CHECK_MSG(t && bad == 0, "encoding %d: %ld texels differ (alpha must be kept)", e, bad);
        cg_texture_free(t);
    }
    remove(path);
    cg_image_free(image);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(decoding);
    CHECK_GROUP(mip_box_average);
    CHECK_GROUP(wrap_modes);
    CHECK_GROUP(sampling);
    CHECK_GROUP(edges_and_alpha);
    CHECK_GROUP(jpeg_files);
    CHECK_GROUP(png_files);
    return check_finish();
}
