/* Reading and writing image files: format detection and safe replacement. */
#include "internal.h"
#include "cg/image_float.h"
#include "../core/array.h"
#include "../core/safe_file.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

cg_status byte_buffer_append(byte_buffer *buffer, const void *bytes, size_t size)
{
    if (size > SIZE_MAX - buffer->size
        || core_array_reserve((void **)&buffer->bytes, &buffer->capacity, buffer->size + size, 1)
               != CG_OK)
        return CG_ENOMEM;
    memcpy(buffer->bytes + buffer->size, bytes, size);
    buffer->size += size;
    return CG_OK;
}

void byte_buffer_free(byte_buffer *buffer)
{
    free(buffer->bytes);
    buffer->bytes = NULL;
    buffer->size = buffer->capacity = 0;
}

cg_status image_check_dimensions(unsigned long width, unsigned long height, const char *name,
                                 cg_error *err)
{
    if (width == 0 || height == 0)
        return cg_error_set(err, CG_EFORMAT, "%s: image has zero width or height", name);
    if (width > CG_IMAGE_MAX_SIDE || height > CG_IMAGE_MAX_SIDE
        || (size_t)width * (size_t)height > CG_IMAGE_MAX_PIXELS)
        return cg_error_set(err, CG_ERANGE,
                            "%s: %lu x %lu pixels is over cg's limit (%d per side, %zu in all)",
                            name, width, height, CG_IMAGE_MAX_SIDE, CG_IMAGE_MAX_PIXELS);
    return CG_OK;
}

cg_file_format cg_file_format_from_path(const char *path)
{
    const char *dot = path ? strrchr(path, '.') : NULL;
    if (!dot)
        return CG_FILE_UNKNOWN;
    if (strcasecmp(dot, ".png") == 0)
        return CG_FILE_PNG;
    if (strcasecmp(dot, ".ppm") == 0)
        return CG_FILE_PPM;
    if (strcasecmp(dot, ".pgm") == 0)
        return CG_FILE_PGM;
    if (strcasecmp(dot, ".pfm") == 0)
        return CG_FILE_PFM;
    if (strcasecmp(dot, ".hdr") == 0 || strcasecmp(dot, ".pic") == 0)
        return CG_FILE_HDR;
    if (strcasecmp(dot, ".exr") == 0)
        return CG_FILE_EXR;
    return CG_FILE_UNKNOWN;
}

int cg_file_format_is_float(cg_file_format format)
{
    return format == CG_FILE_PFM || format == CG_FILE_HDR || format == CG_FILE_EXR;
}

cg_status cg_image_load_memory(const void *bytes, size_t size, const char *name, cg_image **out,
                               cg_error *err)
{
    static const unsigned char png_magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char exr_magic[4] = {0x76, 0x2f, 0x31, 0x01};
    const unsigned char *b = bytes;
    if (!name)
        name = "image";
    if (!out)
        return cg_error_set(err, CG_EINVAL, "%s: no output image", name);
    *out = NULL;
    if (!b || size == 0)
        return cg_error_set(err, CG_EFORMAT, "%s: file is empty", name);
    if (size >= 8 && memcmp(b, png_magic, 8) == 0)
        return png_decode(b, size, name, out, err);
    if (size >= 2 && b[0] == 'P' && (b[1] == 'F' || b[1] == 'f'))
        return pfm_decode(b, size, name, out, err);
    if (size >= 2 && b[0] == 'P' && b[1] >= '1' && b[1] <= '7')
        return pnm_decode(b, size, name, out, err);
    if (size >= 2 && b[0] == '#' && b[1] == '?')
        return hdr_decode(b, size, name, out, err);
    if (size >= 4 && memcmp(b, exr_magic, 4) == 0)
        return image_exr_decode(b, size, name, out, err);
    return cg_error_set(err, CG_EFORMAT,
                        "%s: unknown image format (expected PNG, PPM/PGM, PFM, Radiance HDR or "
                        "OpenEXR)",
                        name);
}

cg_status cg_image_read_memory(const void *bytes, size_t size, const char *name, cg_image **out,
                               cg_error *err)
{
    cg_status status = cg_image_load_memory(bytes, size, name, out, err);
    if (status != CG_OK || (*out)->format == CG_PIXEL_RGBA8)
        return status;
    cg_image *encoded;
    status = cg_image_encode_srgb(*out, &encoded);
    cg_image_free(*out);
    *out = encoded;
    if (status != CG_OK)
        return cg_error_set(err, status, "%s: cannot allocate the encoded image", name);
    return CG_OK;
}

/* The whole file in memory. */
static cg_status read_whole_file(const char *path, byte_buffer *contents, cg_error *err)
{
    FILE *file = fopen(path, "rb");
    if (!file)
        return cg_error_set(err, CG_EIO, "%s: cannot open: %s", path, strerror(errno));
    unsigned char chunk[65536];
    size_t got;
    cg_status status = CG_OK;
    while ((got = fread(chunk, 1, sizeof chunk, file)) > 0)
        if ((status = byte_buffer_append(contents, chunk, got)) != CG_OK)
            break;
    int failed = ferror(file);
    fclose(file);
    if (status != CG_OK)
        status = cg_error_set(err, status, "%s: file too large to read into memory", path);
    else if (failed)
        status = cg_error_set(err, CG_EIO, "%s: read error", path);
    if (status != CG_OK)
        byte_buffer_free(contents);
    return status;
}

static cg_status read_file_with(const char *path, cg_image **out, cg_error *err, int native)
{
    if (!path || !out)
        return cg_error_set(err, CG_EINVAL, "image read: no path or output given");
    *out = NULL;
    byte_buffer contents = {0};
    cg_status status = read_whole_file(path, &contents, err);
    if (status != CG_OK)
        return status;
    status = native ? cg_image_load_memory(contents.bytes, contents.size, path, out, err)
                    : cg_image_read_memory(contents.bytes, contents.size, path, out, err);
    byte_buffer_free(&contents);
    return status;
}

cg_status cg_image_load(const char *path, cg_image **out, cg_error *err)
{
    return read_file_with(path, out, err, 1);
}

cg_status cg_image_read(const char *path, cg_image **out, cg_error *err)
{
    return read_file_with(path, out, err, 0);
}

cg_status cg_image_load_linear(const char *path, cg_image **out, cg_error *err)
{
    cg_status status = read_file_with(path, out, err, 1);
    if (status != CG_OK || (*out)->format == CG_PIXEL_RGBAF)
        return status;
    cg_image *linear;
    status = cg_image_decode_srgb(*out, &linear);
    cg_image_free(*out);
    *out = status == CG_OK ? linear : NULL;
    if (status != CG_OK)
        return cg_error_set(err, status, "%s: cannot allocate the decoded image", path);
    return CG_OK;
}

/* Writes bytes to a temporary file beside path, then renames it over path. */
cg_status image_replace_file(const char *path, const byte_buffer *contents, cg_error *err)
{
    safe_file o;
    cg_status status = safe_file_open(&o, path, err);
    if (status != CG_OK)
        return status;
    if (fwrite(contents->bytes, 1, contents->size, o.file) != contents->size)
        status = cg_error_set(err, CG_EIO, "%s: cannot write: %s", path, strerror(errno));
    return safe_file_close(&o, status, err);
}

/* PFM or HDR: from RGBAF (an RGBA8 image decoded to linear first). */
static cg_status write_float(const cg_image *image, const char *path, cg_file_format format,
                             cg_error *err)
{
    cg_image *linear = NULL;
    const cg_image *source = image;
    if (image->format != CG_PIXEL_RGBAF) {
        cg_status s = cg_image_decode_srgb(image, &linear);
        if (s != CG_OK)
            return cg_error_set(err, s, "%s: cannot convert the image for writing", path);
        source = linear;
    }
    byte_buffer contents = {0};
    cg_status status = format == CG_FILE_PFM ? pfm_encode(source, &contents, err)
                                             : hdr_encode(source, &contents, err);
    if (status == CG_OK)
        status = image_replace_file(path, &contents, err);
    byte_buffer_free(&contents);
    cg_image_free(linear);
    return status;
}

cg_status cg_image_write(const cg_image *image, const char *path, cg_file_format format,
                         cg_error *err)
{
    if (!image || !path)
        return cg_error_set(err, CG_EINVAL, "image write: no image or path given");
    if (format == CG_FILE_UNKNOWN)
        format = cg_file_format_from_path(path);
    if (format == CG_FILE_UNKNOWN)
        return cg_error_set(err, CG_EINVAL,
                            "%s: unknown output format (expected .png, .ppm, .pgm, .pfm, .hdr "
                            "or .exr)",
                            path);
    if (format == CG_FILE_EXR)
        return cg_image_write_exr(path, image, NULL, 0, NULL, err);
    if (cg_file_format_is_float(format))
        return write_float(image, path, format, err);
    cg_image *encoded = NULL;
    const cg_image *source = image;
    if (image->format != CG_PIXEL_RGBA8) {
        cg_status s = cg_image_convert(image, CG_PIXEL_RGBA8, &encoded);
        if (s != CG_OK)
            return cg_error_set(err, s, "%s: cannot convert the image for writing", path);
        source = encoded;
    }
    byte_buffer contents = {0};
    cg_status status = format == CG_FILE_PNG ? png_encode(source, &contents, err)
                                             : pnm_encode(source, format, &contents, err);
    if (status == CG_OK)
        status = image_replace_file(path, &contents, err);
    byte_buffer_free(&contents);
    cg_image_free(encoded);
    return status;
}
