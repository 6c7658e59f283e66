/* Netpbm PPM and PGM: P2 and P3 (ASCII), P5 and P6 (binary, 8 or 16 bits). */
#include "internal.h"
#include "cg/color.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

typedef struct pnm_reader {
    const unsigned char *bytes;
    size_t size, at;
    const char *name;
} pnm_reader;

static void skip_space_and_comments(pnm_reader *r)
{
    while (r->at < r->size) {
        if (r->bytes[r->at] == '#') {
            while (r->at < r->size && r->bytes[r->at] != '\n')
                r->at++;
        } else if (isspace(r->bytes[r->at])) {
            r->at++;
        } else {
            break;
        }
    }
}

/* Reads an unsigned decimal number; what names the field in messages. */
static cg_status read_number(pnm_reader *r, const char *what, unsigned long limit,
                             unsigned long *value, cg_error *err)
{
    skip_space_and_comments(r);
    if (r->at >= r->size)
        return cg_error_set(err, CG_EFORMAT, "%s: truncated: expected %s at byte %zu", r->name,
                            what, r->at);
    if (!isdigit(r->bytes[r->at]))
        return cg_error_set(err, CG_EFORMAT, "%s: byte %zu: expected %s, got '%c'", r->name, r->at,
                            what, isprint(r->bytes[r->at]) ? r->bytes[r->at] : '?');
    unsigned long v = 0;
    while (r->at < r->size && isdigit(r->bytes[r->at])) {
        v = v * 10 + (unsigned long)(r->bytes[r->at] - '0');
        if (v > limit)
            return cg_error_set(err, CG_ERANGE, "%s: byte %zu: %s larger than %lu", r->name, r->at,
                                what, limit);
        r->at++;
    }
    *value = v;
    return CG_OK;
}

cg_status pnm_decode(const unsigned char *bytes, size_t size, const char *name, cg_image **out,
                     cg_error *err)
{
    pnm_reader r = {bytes, size, 2, name};
    char kind = (char)bytes[1];
    if (kind != '2' && kind != '3' && kind != '5' && kind != '6')
        return cg_error_set(err, CG_EUNSUPPORTED,
                            "%s: Netpbm P%c is not supported (expected P2, P3, P5 or P6)", name,
                            kind);
    int channels = (kind == '3' || kind == '6') ? 3 : 1;
    int binary = kind == '5' || kind == '6';
    unsigned long width, height, maxval;
    cg_status status;
    if ((status = read_number(&r, "the width", CG_IMAGE_MAX_SIDE + 1UL, &width, err)) != CG_OK
        || (status = read_number(&r, "the height", CG_IMAGE_MAX_SIDE + 1UL, &height, err)) != CG_OK
        || (status = image_check_dimensions(width, height, name, err)) != CG_OK
        || (status = read_number(&r, "the maximum value", 65535, &maxval, err)) != CG_OK)
        return status;
    if (maxval == 0)
        return cg_error_set(err, CG_EFORMAT, "%s: maximum value must be 1 to 65535, got 0", name);
    size_t samples = (size_t)width * height * (size_t)channels;
    size_t sample_bytes = maxval > 255 ? 2 : 1;
    if (binary) {
        if (r.at >= size || !isspace(bytes[r.at]))
            return cg_error_set(err, CG_EFORMAT,
                                "%s: expected one whitespace byte after the maximum value", name);
        r.at++;
        if (size - r.at < samples * sample_bytes)
            return cg_error_set(err, CG_EFORMAT,
                                "%s: truncated: expected %zu bytes of pixel data, got %zu", name,
                                samples * sample_bytes, size - r.at);
    }
    status = cg_image_create(out, (int)width, (int)height, CG_PIXEL_RGBA8);
    if (status != CG_OK)
        return cg_error_set(err, status, "%s: cannot allocate %lu x %lu image", name, width,
                            height);
    for (size_t i = 0; i < samples; i++) {
        unsigned long v;
        if (binary) {
            const unsigned char *p = bytes + r.at + i * sample_bytes;
            v = sample_bytes == 2 ? (unsigned long)p[0] << 8 | p[1] : p[0];
            if (v > maxval) {
                status = cg_error_set(err, CG_EFORMAT, "%s: sample %zu is %lu, above maximum %lu",
                                      name, i, v, maxval);
                break;
            }
        } else if ((status = read_number(&r, "a sample", maxval, &v, err)) != CG_OK) {
            break;
        }
        uint8_t value = (uint8_t)((v * 255 + maxval / 2) / maxval);
        size_t pixel = i / (size_t)channels;
        cg_rgba8 *px = (cg_rgba8 *)(*out)->data + pixel;
        if (channels == 1) {
            px->r = px->g = px->b = value;
        } else {
            uint8_t *channel = &px->r;
            channel[i % 3] = value;
        }
        px->a = 255;
    }
    if (status != CG_OK) {
        cg_image_free(*out);
        *out = NULL;
    }
    return status;
}

/* Luminance of an encoded pixel, computed in linear light (Rec. 709 weights). */
static uint8_t gray_of(cg_rgba8 px)
{
    float y = 0.2126f * cg_srgb8_to_linear(px.r) + 0.7152f * cg_srgb8_to_linear(px.g)
              + 0.0722f * cg_srgb8_to_linear(px.b);
    return cg_linear_to_srgb8(y);
}

cg_status pnm_encode(const cg_image *image, cg_file_format format, byte_buffer *out, cg_error *err)
{
    int gray = format == CG_FILE_PGM || format == CG_FILE_PGM_ASCII;
    int ascii = format == CG_FILE_PPM_ASCII || format == CG_FILE_PGM_ASCII;
    char header[64];
    int n = snprintf(header, sizeof header, "P%c\n%d %d\n255\n",
                     ascii ? (gray ? '2' : '3') : (gray ? '5' : '6'), image->width, image->height);
    cg_status status = byte_buffer_append(out, header, (size_t)n);
    for (int y = 0; y < image->height && status == CG_OK; y++) {
        const cg_rgba8 *row = (const cg_rgba8 *)(image->data + (size_t)y * image->stride);
        for (int x = 0; x < image->width && status == CG_OK; x++) {
            uint8_t samples[3] = {row[x].r, row[x].g, row[x].b};
            int count = 3;
            if (gray) {
                samples[0] = gray_of(row[x]);
                count = 1;
            }
            if (!ascii) {
                status = byte_buffer_append(out, samples, (size_t)count);
                continue;
            }
            char text[16];
            int length = count == 1 ? snprintf(text, sizeof text, "%u\n", samples[0])
                                    : snprintf(text, sizeof text, "%u %u %u\n", samples[0],
                                               samples[1], samples[2]);
            status = byte_buffer_append(out, text, (size_t)length);
        }
    }
    if (status != CG_OK)
        return cg_error_set(err, status, "Netpbm encoding: out of memory");
    return CG_OK;
}
