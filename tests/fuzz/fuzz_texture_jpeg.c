/* libFuzzer target: textures from JPEG bytes (libjpeg-turbo through
 * cg_texture_load_memory), then sampled.  Inputs that do not start like a
 * JPEG are made to (the SOI marker is put in front), so that every run
 * reaches the decoder.  A texture that loads must have a consistent mip
 * chain and finite samples; a failure must come with a message. */
#include "cg/texture.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    unsigned char *bytes = malloc(size + 3);
    if (!bytes)
        return 0;
    size_t n = size;
    if (size >= 3 && data[0] == 0xFF && data[1] == 0xD8 && data[2] == 0xFF) {
        memcpy(bytes, data, size);
    } else {
        bytes[0] = 0xFF, bytes[1] = 0xD8, bytes[2] = 0xFF;
        memcpy(bytes + 3, data, size);
        n = size + 3;
    }
    cg_texture *texture = NULL;
    cg_error err;
    cg_status status = cg_texture_load_memory(bytes, n, "fuzz.jpg", CG_TEXTURE_SRGB, &texture,
                                              &err);
    if (status == CG_OK) {
        if (!texture || texture->level_count < 1)
            abort();
        const cg_texture_level *last = &texture->levels[texture->level_count - 1];
        if (last->width != 1 || last->height != 1)
            abort();
        cg_texture_sampler sampler = {CG_TEXTURE_TRILINEAR, CG_TEXTURE_REPEAT, CG_TEXTURE_CLAMP};
        for (int k = 0; k < 8; k++) {
            cg_rgbaf c = cg_texture_sample(texture, &sampler, k * 0.37 - 1, k * 0.21, k * 0.5);
            if (!isfinite(c.r) || !isfinite(c.g) || !isfinite(c.b) || fabsf(c.a - 1) > 1e-5f)
                abort();
        }
    } else if (texture || err.status != status || err.message[0] == '\0') {
        abort();
    }
    cg_texture_free(texture);
    free(bytes);
    return 0;
}
