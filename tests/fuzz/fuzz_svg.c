/* libFuzzer target: the SVG reader and drawing (cg/svg.h).
 *
 * The bytes are an SVG document: loaded with cg_svg_load_memory, then, when
 * it loads, drawn twice onto a small RGBA8 image (48 x 40, rows padded
 * beyond width * 4 with guard bytes) under a transform from the first
 * bytes' hash.  Checked beyond "no crash" (ASan + UBSan are on):
 *  - a failure gives a status of the enum and a message naming the input,
 *    and no document;
 *  - a loaded document has a finite positive size and at most 100
 *    warnings, each a non-empty string;
 *  - drawing returns CG_OK or CG_EFORMAT (a use cycle, too large an
 *    expansion) with a message; it writes nothing outside the image;
 *  - drawing is deterministic: the second image equals the first byte for
 *    byte (the document is not changed by drawing).
 * Any failure aborts. */
#include "cg/svg.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

#define WIDTH 48
#define HEIGHT 40
#define PADDING 16 /* bytes after each row */
#define GUARD 0x5A

static cg_image *guarded_image(unsigned char **storage)
{
    size_t stride = WIDTH * 4 + PADDING;
    *storage = malloc(stride * HEIGHT);
    cg_image *image = calloc(1, sizeof *image);
    if (!*storage || !image)
        abort();
    memset(*storage, GUARD, stride * HEIGHT);
    for (int y = 0; y < HEIGHT; y++)
        memset(*storage + y * stride, 0, WIDTH * 4);
    image->width = WIDTH;
    image->height = HEIGHT;
    image->stride = stride;
    image->format = CG_PIXEL_RGBA8;
    image->data = *storage;
    return image;
}

static void check_guards(const unsigned char *storage)
{
    size_t stride = WIDTH * 4 + PADDING;
    for (int y = 0; y < HEIGHT; y++)
        for (size_t i = WIDTH * 4; i < stride; i++)
            if (storage[y * stride + i] != GUARD)
                abort();
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    cg_svg *svg = NULL;
    cg_error err;
    cg_status status = cg_svg_load_memory(data, size, "fuzz.svg", &svg, &err);
    if (status != CG_OK) {
        if (svg || err.status != status || strncmp(err.message, "fuzz.svg", 8) != 0
            || (status != CG_EFORMAT && status != CG_ERANGE && status != CG_ENOMEM))
            abort();
        return 0;
    }
    double w, h;
    cg_svg_size(svg, &w, &h);
    if (!(w > 0 && h > 0 && isfinite(w) && isfinite(h)) || cg_svg_warning_count(svg) > 100)
        abort();
    for (int i = 0; i < cg_svg_warning_count(svg); i++)
        if (!cg_svg_warning(svg, i) || !cg_svg_warning(svg, i)[0])
            abort();
    /* a transform from the input: scale to fit, sometimes rotated */
    uint32_t hash = 2166136261u;
    for (size_t i = 0; i < size && i < 64; i++)
        hash = (hash ^ data[i]) * 16777619u;
    cg_mat3 m = cg_mat3_identity();
    double scale = fmin(WIDTH / w, HEIGHT / h);
    if (!(scale > 1e-6 && scale < 1e6))
        scale = 1;
    double angle = (hash & 7) == 0 ? (hash >> 8 & 255) / 40.0 : 0;
    m.m[0][0] = scale * cos(angle);
    m.m[0][1] = -scale * sin(angle);
    m.m[1][0] = scale * sin(angle);
    m.m[1][1] = scale * cos(angle);
    unsigned char *first_storage, *second_storage;
    cg_image *first = guarded_image(&first_storage), *second = guarded_image(&second_storage);
    cg_status s1 = cg_svg_render(svg, first, m, &err);
    if (s1 != CG_OK && (s1 != CG_EFORMAT || strncmp(err.message, "fuzz.svg", 8) != 0))
        abort();
    cg_status s2 = cg_svg_render(svg, second, m, NULL);
    check_guards(first_storage);
    check_guards(second_storage);
    if (s1 != s2 || memcmp(first_storage, second_storage, (WIDTH * 4 + PADDING) * HEIGHT) != 0)
        abort();
    free(first_storage);
    free(second_storage);
    free(first);
    free(second);
    cg_svg_free(svg);
    return 0;
}
