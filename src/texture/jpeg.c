/* JPEG decoding with libjpeg-turbo: libjpeg reports fatal errors through a
 * callback that must not return, so it longjmps back here; its warnings
 * (corrupt or truncated data, which it would otherwise paper over with grey)
 * are made errors too. */
#include "internal.h"

#include <setjmp.h>
#include <stdio.h> /* before jpeglib.h, which uses FILE */
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

typedef struct jpeg_failure {
    struct jpeg_error_mgr manager; /* first: libjpeg sees a jpeg_error_mgr */
    jmp_buf back;
    char message[JMSG_LENGTH_MAX];
} jpeg_failure;

static void on_error(j_common_ptr info)
{
    jpeg_failure *f = (jpeg_failure *)info->err;
    (*info->err->format_message)(info, f->message);
    longjmp(f->back, 1);
}

static void on_message(j_common_ptr info, int level)
{
    if (level < 0) /* a warning: the data is corrupt */
        on_error(info);
}

int texture_is_jpeg(const unsigned char *bytes, size_t size)
{
    return size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
}

cg_status texture_jpeg_decode(const unsigned char *bytes, size_t size, const char *name,
                              cg_image **out, cg_error *err)
{
    struct jpeg_decompress_struct info;
    jpeg_failure failure;
    /* volatile: changed between setjmp and a longjmp back to it */
    cg_image *volatile image = NULL;
    volatile cg_status status = CG_EFORMAT;
    *out = NULL;
    memset(&info, 0, sizeof info);
    info.err = jpeg_std_error(&failure.manager);
    failure.manager.error_exit = on_error;
    failure.manager.emit_message = on_message;
    failure.message[0] = '\0';
    if (setjmp(failure.back)) {
        jpeg_destroy_decompress(&info);
        cg_image_free(image);
        if (status == CG_EFORMAT)
            return cg_error_set(err, CG_EFORMAT, "%s: bad JPEG data: %s", name, failure.message);
        return cg_error_set(err, status, "%s: %s", name, failure.message);
    }
    jpeg_create_decompress(&info);
    /* libjpeg's own working memory, whatever the file claims */
    info.mem->max_memory_to_use = 256L << 20;
    jpeg_mem_src(&info, bytes, (unsigned long)size);
    jpeg_read_header(&info, TRUE);
    if (info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK) {
        status = CG_EUNSUPPORTED;
        snprintf(failure.message, sizeof failure.message,
                 "a CMYK JPEG, which cg does not read (convert it to RGB)");
        longjmp(failure.back, 1);
    }
    if ((size_t)info.image_width * info.image_height > CG_TEXTURE_MAX_TEXELS) {
        status = CG_ERANGE;
        snprintf(failure.message, sizeof failure.message,
                 "a JPEG of %u x %u pixels, over the %zu texels cg reads", info.image_width,
                 info.image_height, (size_t)CG_TEXTURE_MAX_TEXELS);
        longjmp(failure.back, 1);
    }
    info.out_color_space = JCS_EXT_RGBA; /* libjpeg-turbo fills alpha with 255 */
    jpeg_start_decompress(&info);
    cg_image *made = NULL;
    if (cg_image_create(&made, (int)info.output_width, (int)info.output_height, CG_PIXEL_RGBA8)
        != CG_OK) {
        status = CG_ENOMEM;
        snprintf(failure.message, sizeof failure.message, "out of memory");
        longjmp(failure.back, 1);
    }
    image = made;
    while (info.output_scanline < info.output_height) {
        JSAMPROW row = image->data + (size_t)info.output_scanline * image->stride;
        jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    *out = image;
    return CG_OK;
}
