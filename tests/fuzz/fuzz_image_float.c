/* libFuzzer target: the float image readers (PFM, Radiance HDR, OpenEXR
 * through OpenEXRCore) from memory, by cg_image_load_memory.  A failure must
 * leave no image and give a message naming the input; an image that loads
 * must have sides within cg's limits, and survive a PFM round trip bit for
 * bit (colour channels; PFM has no alpha).  OpenEXR files whose data window
 * claims more than 4 million pixels are skipped: ZIP or DWA can fill them
 * from a few kilobytes, so they only time the decompressor. */
#include "cg/image_float.h"
#include "fuzz_image_checks.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

static int32_t le32(const unsigned char *p)
{
    return (int32_t)((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16
                     | (uint32_t)p[3] << 24);
}

/* Any "dataWindow" box2i attribute of an EXR header over 4e6 pixels. */
static int huge_exr(const unsigned char *data, size_t size)
{
    static const char key[] = "dataWindow\0box2i";
    if (size < 4 || memcmp(data, "\x76\x2f\x31\x01", 4) != 0)
        return 0;
    for (size_t i = 4; i + sizeof key + 20 <= size; i++)
        if (memcmp(data + i, key, sizeof key) == 0) {
            const unsigned char *b = data + i + sizeof key + 4;
            double w = (double)le32(b + 8) - le32(b) + 1,
                   h = (double)le32(b + 12) - le32(b + 4) + 1;
            if (w * h > 4e6)
                return 1;
        }
    return 0;
}

static int same_bits(float a, float b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    if (huge_exr(data, size))
        return 0;
    cg_image *image = NULL;
    cg_error err;
    cg_status status = cg_image_load_memory(data, size, "fuzz", &image, &err);
    if (!fuzz_image_loaded(status, image, &err))
        return 0;
    if (image->format != CG_PIXEL_RGBAF) { /* an 8-bit file: fuzz_image's business */
        cg_image_free(image);
        return 0;
    }
    /* the PFM writer through a file would touch the disk; through memory
     * cg has no public encoder, so write and read a temporary file only for
     * small images */
    if ((size_t)image->width * (size_t)image->height <= 4096) {
        char path[] = "/tmp/fuzz_image_float_XXXXXX.pfm";
        int fd = mkstemps(path, 4);
        if (fd < 0)
            abort();
        close(fd);
        cg_image *again = NULL;
        if (cg_image_write(image, path, CG_FILE_PFM, &err) != CG_OK
            || cg_image_load(path, &again, &err) != CG_OK || again->width != image->width
            || again->height != image->height)
            abort();
        remove(path);
        for (int y = 0; y < image->height; y++) {
            const cg_rgbaf *a = (const cg_rgbaf *)(image->data + (size_t)y * image->stride);
            const cg_rgbaf *b = (const cg_rgbaf *)(again->data + (size_t)y * again->stride);
            for (int x = 0; x < image->width; x++)
                if (!same_bits(a[x].r, b[x].r) || !same_bits(a[x].g, b[x].g)
                    || !same_bits(a[x].b, b[x].b))
                    abort();
        }
        cg_image_free(again);
    }
    cg_image_free(image);
    return 0;
}
