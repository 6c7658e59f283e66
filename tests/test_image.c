/* Images: creation limits, pixel access, blending, conversion, and the PNG
 * and PPM/PGM readers and writers, including every kind of bad file. */
#include "cg.h"
#include "check.h"

#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void test_create(void)
{
    cg_image *img = NULL;
    CHECK_EQ_INT(cg_image_create(&img, 0, 10, CG_PIXEL_RGBA8), CG_EINVAL);
    CHECK(img == NULL);
    CHECK_EQ_INT(cg_image_create(&img, 10, -1, CG_PIXEL_RGBA8), CG_EINVAL);
    CHECK_EQ_INT(cg_image_create(&img, CG_IMAGE_MAX_SIDE + 1, 1, CG_PIXEL_RGBA8), CG_ERANGE);
    /* just over 2^30 pixels (CG_IMAGE_CREATE_MAX_PIXELS) */
    CHECK_EQ_INT(cg_image_create(&img, (1 << 15) + 1, 1 << 15, CG_PIXEL_RGBA8), CG_ERANGE);
    CHECK(img == NULL);
    CHECK_EQ_INT(cg_image_create(&img, 10, 10, (cg_pixel_format)7), CG_EINVAL);
    CHECK_EQ_INT(cg_image_create(NULL, 10, 10, CG_PIXEL_RGBA8), CG_EINVAL);
    CHECK_EQ_INT(cg_image_create(&img, 3, 2, CG_PIXEL_RGBAF), CG_OK);
    CHECK(img->width == 3 && img->height == 2 && img->stride == 3 * sizeof(cg_rgbaf));
    cg_rgbaf p = cg_image_get(img, 2, 1);
    CHECK(p.r == 0 && p.a == 0);
    cg_image_free(img);
    cg_image_free(NULL);
}

static void test_pixels_and_blend(void)
{
    cg_image *img;
    CHECK_EQ_INT(cg_image_create(&img, 4, 4, CG_PIXEL_RGBA8), CG_OK);
    cg_rgba8 red = {255, 0, 0, 255};
    cg_image_clear_rgba8(img, red);
    cg_rgba8 got = cg_image_get_rgba8(img, 3, 3);
    CHECK(got.r == 255 && got.g == 0 && got.a == 255);
    /* Out of range: reads transparent black, writes nothing, no crash. */
    cg_image_set_rgba8(img, -1, 0, red);
    cg_image_set_rgba8(img, 4, 0, red);
    got = cg_image_get_rgba8(img, 0, 99);
    CHECK(got.a == 0);
    /* Half-transparent white over opaque black gives 0.5 linear = 188 encoded. */
    cg_rgba8 black = {0, 0, 0, 255};
    cg_image_clear_rgba8(img, black);
    cg_rgbaf half_white = {1, 1, 1, 0.5f};
    cg_image_blend(img, 1, 1, half_white);
    got = cg_image_get_rgba8(img, 1, 1);
    CHECK_EQ_INT(got.r, 188);
    CHECK_EQ_INT(got.a, 255);
    /* Blend onto transparent keeps the colour, alpha becomes the source's. */
    cg_rgba8 none = {0, 0, 0, 0};
    cg_image_clear_rgba8(img, none);
    cg_rgbaf green = {0, 1, 0, 0.25f};
    cg_image_blend(img, 2, 2, green);
    cg_rgbaf g = cg_image_get(img, 2, 2);
    CHECK_NEAR(g.g, 1, 1e-6);
    CHECK_NEAR(g.a, 64 / 255.0, 1e-6);
    /* RGBA8 -> RGBAF -> RGBA8 is exact for every code. */
    cg_image *wide, *back, *codes;
    CHECK_EQ_INT(cg_image_create(&codes, 256, 1, CG_PIXEL_RGBA8), CG_OK);
    for (int i = 0; i < 256; i++) {
        cg_rgba8 c = {(uint8_t)i, (uint8_t)(255 - i), (uint8_t)(i * 7), (uint8_t)i};
        cg_image_set_rgba8(codes, i, 0, c);
    }
    CHECK_EQ_INT(cg_image_convert(codes, CG_PIXEL_RGBAF, &wide), CG_OK);
    CHECK_EQ_INT(cg_image_convert(wide, CG_PIXEL_RGBA8, &back), CG_OK);
    CHECK(memcmp(codes->data, back->data, 256 * 4) == 0);
    cg_image_free(wide);
    cg_image_free(back);
    /* Image over image, clipped, at offsets up to the limits of int. */
    cg_image_clear_rgba8(img, black);
    /* codes is 256 x 1 with alpha = index: at x offset -252, pixel 3 of row 1
     * receives the opaque code 255 and row 0 nothing. */
    cg_image_blend_image(img, codes, -252, 1);
    CHECK_EQ_INT(cg_image_get_rgba8(img, 3, 1).r, 255);
    CHECK_EQ_INT(cg_image_get_rgba8(img, 3, 0).r, 0);
    cg_image_blend_image(img, codes, INT_MIN, INT_MIN);
    cg_image_blend_image(img, codes, INT_MAX, INT_MAX);
    CHECK_EQ_INT(cg_image_get_rgba8(img, 0, 0).r, 0);
    cg_image_free(codes);
    cg_image_free(img);
}

static cg_image *pattern(int w, int h, int opaque)
{
    cg_image *img;
    if (cg_image_create(&img, w, h, CG_PIXEL_RGBA8) != CG_OK)
        return NULL;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            cg_rgba8 c = {(uint8_t)(x * 13 + y), (uint8_t)(y * 7), (uint8_t)(x ^ y),
                          opaque ? 255 : (uint8_t)(x * 5 + y * 3)};
            cg_image_set_rgba8(img, x, y, c);
        }
    return img;
}

static int same_rgb(const cg_image *a, const cg_image *b, int check_alpha)
{
    if (a->width != b->width || a->height != b->height)
        return 0;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            cg_rgba8 p = cg_image_get_rgba8(a, x, y), q = cg_image_get_rgba8(b, x, y);
            if (p.r != q.r || p.g != q.g || p.b != q.b || (check_alpha && p.a != q.a))
                return 0;
        }
    return 1;
}

static void test_round_trips(void)
{
    cg_image *img = pattern(37, 23, 0), *opaque = pattern(37, 23, 1), *back;
    cg_error err;
    CHECK_EQ_INT(cg_image_write(img, "rt.png", CG_FILE_UNKNOWN, &err), CG_OK);
    CHECK_EQ_INT(cg_image_read("rt.png", &back, &err), CG_OK);
    CHECK(back && same_rgb(img, back, 1));
    cg_image_free(back);
    cg_file_format formats[2] = {CG_FILE_PPM, CG_FILE_PPM_ASCII};
    for (int i = 0; i < 2; i++) {
        CHECK_EQ_INT(cg_image_write(opaque, "rt.ppm", formats[i], &err), CG_OK);
        CHECK_EQ_INT(cg_image_read("rt.ppm", &back, &err), CG_OK);
        CHECK(back && same_rgb(opaque, back, 1));
        cg_image_free(back);
    }
    /* PGM stores luminance: a grey image survives exactly. */
    cg_image *grey;
    cg_image_create(&grey, 16, 16, CG_PIXEL_RGBA8);
    for (int i = 0; i < 256; i++) {
        cg_rgba8 c = {(uint8_t)i, (uint8_t)i, (uint8_t)i, 255};
        cg_image_set_rgba8(grey, i % 16, i / 16, c);
    }
    cg_file_format grey_formats[2] = {CG_FILE_PGM, CG_FILE_PGM_ASCII};
    for (int i = 0; i < 2; i++) {
        CHECK_EQ_INT(cg_image_write(grey, "rt.pgm", grey_formats[i], &err), CG_OK);
        CHECK_EQ_INT(cg_image_read("rt.pgm", &back, &err), CG_OK);
        CHECK(back && same_rgb(grey, back, 1));
        cg_image_free(back);
    }
    /* A float image is encoded when written. */
    cg_image *linear;
    cg_image_convert(opaque, CG_PIXEL_RGBAF, &linear);
    CHECK_EQ_INT(cg_image_write(linear, "rt2.png", CG_FILE_UNKNOWN, &err), CG_OK);
    CHECK_EQ_INT(cg_image_read("rt2.png", &back, &err), CG_OK);
    CHECK(back && same_rgb(opaque, back, 1));
    cg_image_free(back);
    cg_image_free(linear);
    cg_image_free(grey);
    cg_image_free(img);
    cg_image_free(opaque);
}

static void write_bytes(const char *path, const void *bytes, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (f) {
        fwrite(bytes, 1, n, f);
        fclose(f);
    }
}

static unsigned char *read_all(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc((size_t)size);
    *n = fread(b, 1, (size_t)size, f);
    fclose(f);
    return b;
}

/* Reads bytes from memory and expects the given status and a message
 * containing text. */
static void expect_bad(const void *bytes, size_t n, cg_status status, const char *text)
{
    cg_image *img = (cg_image *)1;
    cg_error err;
    cg_error_clear(&err);
    cg_status got = cg_image_read_memory(bytes, n, "bad", &img, &err);
    CHECK_MSG(got == status, "expected status %d, got %d (%s) for '%s'", status, got, err.message,
              text);
    CHECK(img == NULL);
    CHECK_MSG(strstr(err.message, text) != NULL, "message '%s' should contain '%s'", err.message,
              text);
}

static uint32_t crc32_of(const unsigned char *p, size_t n)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1)));
    }
    return c ^ 0xffffffffu;
}

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static void test_bad_files(void)
{
    expect_bad("", 0, CG_EFORMAT, "empty");
    expect_bad("GIF89a....", 10, CG_EFORMAT, "unknown image format");
    expect_bad("P6\n", 3, CG_EFORMAT, "truncated");
    expect_bad("P6\n4 4\n255\nabc", 14, CG_EFORMAT, "truncated");
    expect_bad("P6 4 x 255\n", 11, CG_EFORMAT, "expected the height");
    expect_bad("P3 1 1 255\n1 2 300\n", 19, CG_ERANGE, "larger than 255");
    expect_bad("P3 1 1 255\n1 2\n", 15, CG_EFORMAT, "truncated");
    expect_bad("P2 2 1 0\n0 0\n", 13, CG_EFORMAT, "maximum value");
    expect_bad("P5 99999999999 1 255\n", 21, CG_ERANGE, "the width larger");
    expect_bad("P5 100000 100000 255\n", 21, CG_ERANGE, "over cg's limit");
    expect_bad("P6 0 5 255\n", 11, CG_EFORMAT, "zero width");
    expect_bad("P4 1 1\n\x80", 8, CG_EUNSUPPORTED, "not supported");
    expect_bad("P5 1 1 9\n\x0a", 10, CG_EFORMAT, "above maximum");

    /* PNG: write a good file, then damage it in each way. */
    cg_image *img = pattern(20, 10, 0);
    cg_error err;
    cg_image_write(img, "good.png", CG_FILE_PNG, &err);
    cg_image_free(img);
    size_t n;
    unsigned char *png = read_all("good.png", &n);
    CHECK(png && n > 60);
    if (!png)
        return;
    expect_bad(png, 8, CG_EFORMAT, "bad PNG header");
    expect_bad(png, 20, CG_EFORMAT, "bad PNG header");
    expect_bad(png, n - 20, CG_EFORMAT, "corrupt or truncated");
    unsigned char *copy = malloc(n);
    memcpy(copy, png, n);
    copy[1] = 'X';
    expect_bad(copy, n, CG_EFORMAT, "unknown image format");
    /* Corrupt a byte inside the IDAT chunk: its CRC no longer matches. */
    memcpy(copy, png, n);
    for (size_t i = 8; i + 8 < n; i++)
        if (memcmp(copy + i, "IDAT", 4) == 0) {
            copy[i + 6] ^= 0x55;
            break;
        }
    expect_bad(copy, n, CG_EFORMAT, "corrupt or truncated");
    /* Corrupt the IHDR CRC. */
    memcpy(copy, png, n);
    copy[29] ^= 0xff;
    expect_bad(copy, n, CG_EFORMAT, "bad PNG header");
    /* A valid header claiming 20000 x 20000 pixels: refused before any
     * allocation as over the limit (or by libpng's own limits). */
    memcpy(copy, png, n);
    put32(copy + 16, 20000);
    put32(copy + 20, 20000);
    put32(copy + 29, crc32_of(copy + 12, 17));
    expect_bad(copy, n, CG_ERANGE, "over cg's limit");
    free(copy);
    free(png);

    cg_image *out = (cg_image *)1;
    CHECK_EQ_INT(cg_image_read("no/such/file.png", &out, &err), CG_EIO);
    CHECK(out == NULL && strstr(err.message, "no/such/file.png"));
}

static void test_write_never_clobbers(void)
{
    cg_image *img = pattern(8, 8, 1);
    cg_error err;
    /* Unknown extension: refused before anything is written. */
    CHECK_EQ_INT(cg_image_write(img, "picture.gif", CG_FILE_UNKNOWN, &err), CG_EINVAL);
    CHECK(access("picture.gif", F_OK) != 0);
    /* A failing rename (the target is a directory) leaves it as it was and
     * removes the temporary file. */
    mkdir("target.png", 0777);
    CHECK_EQ_INT(cg_image_write(img, "target.png", CG_FILE_UNKNOWN, &err), CG_EIO);
    struct stat st;
    CHECK(stat("target.png", &st) == 0 && S_ISDIR(st.st_mode));
    rmdir("target.png");
    /* A good file is replaced only by a complete one. */
    write_bytes("keep.png", "not really a png", 16);
    CHECK_EQ_INT(cg_image_write(img, "missing-dir/keep.png", CG_FILE_UNKNOWN, &err), CG_EIO);
    CHECK_EQ_INT(cg_image_write(img, "keep.png", CG_FILE_UNKNOWN, &err), CG_OK);
    cg_image *back;
    CHECK_EQ_INT(cg_image_read("keep.png", &back, &err), CG_OK);
    cg_image_free(back);
    cg_image_free(img);
    /* No temporary files are left behind. */
    FILE *ls = popen("ls | grep -c tmp- || true", "r");
    char line[32] = "";
    if (ls) {
        if (!fgets(line, sizeof line, ls))
            line[0] = '\0';
        pclose(ls);
    }
    CHECK(atoi(line) == 0);
}

static void test_file_format_from_path(void)
{
    CHECK_EQ_INT(cg_file_format_from_path("a/b.PNG"), CG_FILE_PNG);
    CHECK_EQ_INT(cg_file_format_from_path("x.ppm"), CG_FILE_PPM);
    CHECK_EQ_INT(cg_file_format_from_path("x.pgm"), CG_FILE_PGM);
    CHECK_EQ_INT(cg_file_format_from_path("x.jpg"), CG_FILE_UNKNOWN);
    CHECK_EQ_INT(cg_file_format_from_path("noext"), CG_FILE_UNKNOWN);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_create);
    CHECK_GROUP(test_pixels_and_blend);
    CHECK_GROUP(test_round_trips);
    CHECK_GROUP(test_bad_files);
    CHECK_GROUP(test_write_never_clobbers);
    CHECK_GROUP(test_file_format_from_path);
    return check_finish();
}
