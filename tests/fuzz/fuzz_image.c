/* libFuzzer target: the image reader (PNG through libpng, PPM/PGM P2, P3,
 * P5 and P6), from memory.  An image that loads must have sides within cg's
 * limits and survive a PPM round trip pixel for pixel (alpha aside, which
 * PPM drops; a PGM of a grey image as well); a failure must come with a
 * message naming the input. */
#include "cg/image.h"
#include "fuzz_image_checks.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

/* A PNG's IHDR may claim up to 2^28 pixels, which a valid compressed stream
 * of a few kilobytes can fill; such inputs are correct but only time the
 * decompressor, so the target skips them. */
static int huge_png(const unsigned char *data, size_t size)
{
    if (size < 24 || memcmp(data, "\x89PNG", 4) != 0)
        return 0;
    unsigned long w = (unsigned long)data[16] << 24 | (unsigned long)data[17] << 16
                      | (unsigned long)data[18] << 8 | data[19];
    unsigned long h = (unsigned long)data[20] << 24 | (unsigned long)data[21] << 16
                      | (unsigned long)data[22] << 8 | data[23];
    return (double)w * (double)h > 4e6;
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    if (huge_png(data, size))
        return 0;
    cg_image *image = NULL;
    cg_error err;
    cg_status status = cg_image_read_memory(data, size, "fuzz", &image, &err);
    if (!fuzz_image_loaded(status, image, &err))
        return 0;
    /* encode as binary PPM by hand and read it back: the same colours */
    size_t pixels = (size_t)image->width * (size_t)image->height;
    char header[64];
    int n = snprintf(header, sizeof header, "P6\n%d %d\n255\n", image->width, image->height);
    unsigned char *ppm = malloc((size_t)n + 3 * pixels);
    if (!ppm)
        abort();
    memcpy(ppm, header, (size_t)n);
    for (int y = 0; y < image->height; y++) {
        const cg_rgba8 *row = (const cg_rgba8 *)(image->data + (size_t)y * image->stride);
        for (int x = 0; x < image->width; x++) {
            unsigned char *q = ppm + n + 3 * ((size_t)y * (size_t)image->width + (size_t)x);
            q[0] = row[x].r;
            q[1] = row[x].g;
            q[2] = row[x].b;
        }
    }
    cg_image *again = NULL;
    if (cg_image_read_memory(ppm, (size_t)n + 3 * pixels, "again", &again, &err) != CG_OK
        || again->width != image->width || again->height != image->height)
        abort();
    for (int y = 0; y < image->height; y++) {
        const cg_rgba8 *a = (const cg_rgba8 *)(image->data + (size_t)y * image->stride);
        const cg_rgba8 *b = (const cg_rgba8 *)(again->data + (size_t)y * again->stride);
        for (int x = 0; x < image->width; x++)
            if (a[x].r != b[x].r || a[x].g != b[x].g || a[x].b != b[x].b || b[x].a != 255)
                abort();
    }
    free(ppm);
    cg_image_free(again);
    cg_image_free(image);
    return 0;
}
