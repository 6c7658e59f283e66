/* Portable float map (PFM): "PF" (RGB) or "Pf" (grey), width and height,
 * a scale whose sign gives the byte order (negative: little-endian), then
 * 32-bit IEEE floats, rows from the bottom of the image to its top.  The
 * scale's magnitude is not applied, so that values round-trip bit for bit. */
#include "internal.h"

#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static int is_space(unsigned char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

/* Reads one whitespace-separated header token into buf; 0 at the end. */
static int header_token(const unsigned char *b, size_t size, size_t *at, char *buf, size_t cap)
{
    while (*at < size && is_space(b[*at]))
        (*at)++;
    size_t n = 0;
    while (*at < size && !is_space(b[*at])) {
        if (n + 1 >= cap)
            return 0;
        buf[n++] = (char)b[(*at)++];
    }
    buf[n] = '\0';
    return n > 0;
}

static int parse_side(const char *text, unsigned long *out)
{
    char *end;
    if (text[0] < '0' || text[0] > '9')
        return 0;
    *out = strtoul(text, &end, 10);
    return *end == '\0';
}

static float load_float(const unsigned char *p, int little)
{
    uint32_t u = little ? (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16
                              | (uint32_t)p[3] << 24
                        : (uint32_t)p[3] | (uint32_t)p[2] << 8 | (uint32_t)p[1] << 16
                              | (uint32_t)p[0] << 24;
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

cg_status pfm_decode(const unsigned char *bytes, size_t size, const char *name, cg_image **out,
                     cg_error *err)
{
    *out = NULL;
    if (size < 2 || bytes[0] != 'P' || (bytes[1] != 'F' && bytes[1] != 'f'))
        return cg_error_set(err, CG_EFORMAT, "%s: not a PFM file (expected PF or Pf)", name);
    int channels = bytes[1] == 'F' ? 3 : 1;
    size_t at = 2;
    char w[32], h[32], s[64];
    unsigned long width, height;
    if (!header_token(bytes, size, &at, w, sizeof w) || !header_token(bytes, size, &at, h, sizeof h)
        || !parse_side(w, &width) || !parse_side(h, &height))
        return cg_error_set(err, CG_EFORMAT, "%s: bad PFM header: expected width and height", name);
    cg_status status = image_check_dimensions(width, height, name, err);
    if (status != CG_OK)
        return status;
    if (!header_token(bytes, size, &at, s, sizeof s))
        return cg_error_set(err, CG_EFORMAT, "%s: bad PFM header: no scale", name);
    char *end;
    double scale = strtod(s, &end);
    if (*end != '\0' || !isfinite(scale) || scale == 0)
        return cg_error_set(err, CG_EFORMAT, "%s: bad PFM scale '%s' (a non-zero number)", name, s);
    if (at >= size || !is_space(bytes[at]))
        return cg_error_set(err, CG_EFORMAT, "%s: PFM header ends without pixel data", name);
    at++; /* the single whitespace character before the data */
    size_t row_bytes = (size_t)width * (size_t)channels * 4;
    if ((size - at) / row_bytes < height)
        return cg_error_set(err, CG_EFORMAT,
                            "%s: truncated PFM data: %lu x %lu x %d floats need %zu bytes, got %zu",
                            name, width, height, channels, row_bytes * height, size - at);
    if ((status = cg_image_create(out, (int)width, (int)height, CG_PIXEL_RGBAF)) != CG_OK)
        return cg_error_set(err, status, "%s: cannot allocate %lu x %lu image", name, width,
                            height);
    int little = scale < 0;
    for (unsigned long y = 0; y < height; y++) {
        const unsigned char *p = bytes + at + (size_t)(height - 1 - y) * row_bytes;
        cg_rgbaf *row = cg_image_row_rgbaf(*out, (int)y);
        for (unsigned long x = 0; x < width; x++, p += 4 * channels) {
            float r = load_float(p, little);
            row[x].r = r;
            row[x].g = channels == 3 ? load_float(p + 4, little) : r;
            row[x].b = channels == 3 ? load_float(p + 8, little) : r;
            row[x].a = 1;
        }
    }
    return CG_OK;
}

cg_status pfm_encode(const cg_image *image, byte_buffer *out, cg_error *err)
{
    char header[64];
    int n = snprintf(header, sizeof header, "PF\n%d %d\n-1.0\n", image->width, image->height);
    size_t row_bytes = (size_t)image->width * 12;
    unsigned char *row = malloc(row_bytes);
    cg_status status = row && n > 0 ? byte_buffer_append(out, header, (size_t)n) : CG_ENOMEM;
    for (int y = image->height - 1; y >= 0 && status == CG_OK; y--) {
        const cg_rgbaf *in = cg_image_row_rgbaf((cg_image *)image, y);
        for (int x = 0; x < image->width; x++) {
            float c[3] = {in[x].r, in[x].g, in[x].b};
            for (int k = 0; k < 3; k++) {
                uint32_t u;
                memcpy(&u, &c[k], sizeof u);
                unsigned char *q = row + 12 * (size_t)x + 4 * (size_t)k;
                q[0] = (unsigned char)u;
                q[1] = (unsigned char)(u >> 8);
                q[2] = (unsigned char)(u >> 16);
                q[3] = (unsigned char)(u >> 24);
            }
        }
        status = byte_buffer_append(out, row, row_bytes);
    }
    free(row);
    if (status != CG_OK)
        return cg_error_set(err, status, "PFM: out of memory encoding %d x %d image", image->width,
                            image->height);
    return CG_OK;
}
