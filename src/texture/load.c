/* Reading texture files: PNG through cg's image reader (libpng), JPEG
 * through libjpeg-turbo (jpeg.c), told apart by their first bytes. */
#include "internal.h"
#include "../core/array.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

cg_status cg_texture_load_memory(const void *bytes, size_t size, const char *name,
                                 cg_texture_encoding encoding, cg_texture **out, cg_error *err)
{
    if (!name)
        name = "texture";
    if (!out)
        return cg_error_set(err, CG_EINVAL, "%s: no output texture given", name);
    *out = NULL;
    if (!bytes && size)
        return cg_error_set(err, CG_EINVAL, "%s: no bytes given", name);
    static const unsigned char png_magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    cg_image *image = NULL;
    cg_status s;
    if (texture_is_jpeg(bytes, size))
        s = texture_jpeg_decode(bytes, size, name, &image, err);
    else if (size >= 8 && memcmp(bytes, png_magic, 8) == 0) {
        /* the header's size first, so that no image over the limit is decoded */
        const unsigned char *b = bytes;
        if (size >= 24) {
            uint64_t width = (uint64_t)b[16] << 24 | (uint64_t)b[17] << 16 | b[18] << 8 | b[19];
            uint64_t height = (uint64_t)b[20] << 24 | (uint64_t)b[21] << 16 | b[22] << 8 | b[23];
            if (width * height > CG_TEXTURE_MAX_TEXELS)
                return cg_error_set(err, CG_ERANGE,
                                    "%s: a PNG of %llu x %llu pixels, over the %zu texels cg reads",
                                    name, (unsigned long long)width, (unsigned long long)height,
                                    (size_t)CG_TEXTURE_MAX_TEXELS);
        }
        s = cg_image_read_memory(bytes, size, name, &image, err);
    } else
        return cg_error_set(err, CG_EFORMAT, "%s: expected a PNG or JPEG image%s", name,
                            size == 0 ? ", the file is empty" : "");
    if (s != CG_OK)
        return s;
    s = cg_texture_from_image(image, encoding, out);
    int width = image->width, height = image->height;
    cg_image_free(image);
    if (s == CG_ERANGE)
        return cg_error_set(err, s, "%s: %d x %d pixels, over the %zu texels cg reads", name, width,
                            height, (size_t)CG_TEXTURE_MAX_TEXELS);
    if (s != CG_OK)
        return cg_error_set(err, s, "%s: out of memory for %d x %d texels", name, width, height);
    return CG_OK;
}

cg_status cg_texture_load(const char *path, cg_texture_encoding encoding, cg_texture **out,
                          cg_error *err)
{
    if (out)
        *out = NULL;
    if (!path || !out)
        return cg_error_set(err, CG_EINVAL, "texture load: no path or output given");
    FILE *file = fopen(path, "rb");
    if (!file)
        return cg_error_set(err, CG_EIO, "%s: cannot open: %s", path, strerror(errno));
    /* texture files are small next to the texels they make: read whole */
    CORE_ARRAY(unsigned char) data = {0};
    unsigned char chunk[65536];
    size_t got;
    cg_status s = CG_OK;
    while ((got = fread(chunk, 1, sizeof chunk, file)) > 0) {
        if (data.count > ((size_t)1 << 30)
            || core_array_reserve_for(&data, data.count + got) != CG_OK) {
            s = cg_error_set(err, CG_ENOMEM, "%s: file too large or out of memory", path);
            break;
        }
        memcpy(data.data + data.count, chunk, got);
        data.count += got;
    }
    if (s == CG_OK && ferror(file))
        s = cg_error_set(err, CG_EIO, "%s: read error", path);
    fclose(file);
    if (s == CG_OK)
        s = cg_texture_load_memory(data.data, data.count, path, encoding, out, err);
    core_array_free(&data);
    return s;
}
