/* PNG through libpng's simplified API, which reports errors without longjmp. */
#include "internal.h"

#include <png.h>
#include <stdlib.h>
#include <string.h>

cg_status png_decode(const unsigned char *bytes, size_t size, const char *name, cg_image **out,
                     cg_error *err)
{
    png_image png;
    memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&png, bytes, size))
        return cg_error_set(err, CG_EFORMAT, "%s: bad PNG header: %s", name, png.message);
    cg_status status = image_check_dimensions(png.width, png.height, name, err);
    if (status != CG_OK) {
        png_image_free(&png);
        return status;
    }
    png.format = PNG_FORMAT_RGBA;
    status = cg_image_create(out, (int)png.width, (int)png.height, CG_PIXEL_RGBA8);
    if (status != CG_OK) {
        png_image_free(&png);
        return cg_error_set(err, status, "%s: cannot allocate %u x %u image", name, png.width,
                            png.height);
    }
    if (!png_image_finish_read(&png, NULL, (*out)->data, (png_int_32)(*out)->stride, NULL)) {
        cg_image_free(*out);
        *out = NULL;
        return cg_error_set(err, CG_EFORMAT, "%s: corrupt or truncated PNG data: %s", name,
                            png.message);
    }
    return CG_OK;
}

cg_status png_encode(const cg_image *image, byte_buffer *out, cg_error *err)
{
    png_image png;
    memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    png.width = (png_uint_32)image->width;
    png.height = (png_uint_32)image->height;
    png.format = PNG_FORMAT_RGBA;
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&png, NULL, &size, 0, image->data, (png_int_32)image->stride,
                                   NULL))
        return cg_error_set(err, CG_EIO, "PNG encoding failed: %s", png.message);
    unsigned char *bytes = malloc(size);
    if (!bytes)
        return cg_error_set(err, CG_ENOMEM, "PNG encoding: out of memory");
    if (!png_image_write_to_memory(&png, bytes, &size, 0, image->data, (png_int_32)image->stride,
                                   NULL)) {
        free(bytes);
        return cg_error_set(err, CG_EIO, "PNG encoding failed: %s", png.message);
    }
    byte_buffer_free(out);
    out->bytes = bytes;
    out->size = out->capacity = size;
    return CG_OK;
}
