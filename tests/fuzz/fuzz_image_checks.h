/* The contract every image reader's fuzz target checks on what a read
 * returned: a failure leaves no image and gives a message naming the input
 * ("fuzz"); an image that loads has sides within cg's limits.  Aborts (so
 * libFuzzer reports the input) when the contract is broken; returns 1 when
 * an image was loaded, 0 when the read failed as it should. */
#ifndef CG_FUZZ_IMAGE_CHECKS_H
#define CG_FUZZ_IMAGE_CHECKS_H

#include "cg/image.h"

#include <stdlib.h>
#include <string.h>

static int fuzz_image_loaded(cg_status status, const cg_image *image, const cg_error *err)
{
    if (status != CG_OK) {
        if (image || err->status != status || strncmp(err->message, "fuzz", 4) != 0)
            abort();
        return 0;
    }
    if (!image || image->width < 1 || image->height < 1 || image->width > CG_IMAGE_MAX_SIDE
        || image->height > CG_IMAGE_MAX_SIDE
        || (size_t)image->width * (size_t)image->height > CG_IMAGE_MAX_PIXELS)
        abort();
    return 1;
}

#endif
