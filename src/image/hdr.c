/* Radiance RGBE (.hdr): a text header ("#?RADIANCE" or "#?RGBE", lines of
 * VARIABLE=value, an empty line), the resolution line "-Y H +X W" (rows top
 * to bottom, pixels left to right; other orientations are refused), then
 * scanlines, each either flat (4 bytes a pixel) or new-style run-length
 * encoded (2, 2, width high, width low, then the four components one after
 * the other as runs: a count over 128 repeats the next byte count - 128
 * times, a count 1..128 is followed by that many literal bytes).
 * A pixel (R, G, B, E) with E > 0 is ((R, G, B) + 0.5) * 2^(E - 136), as
 * Radiance decodes it; E = 0 is black.  EXPOSURE=K header lines say the
 * pixels were multiplied by K (cumulatively, when there are several): the
 * reader divides by their product, so the image holds the radiance the
 * file was made from, as Radiance's own tools report it. */
#include "internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct hdr_reader {
    const unsigned char *b;
    size_t size, at;
    const char *name;
} hdr_reader;

/* The next header line (without its newline) into line; 0 at the end. */
static int next_line(hdr_reader *r, char *line, size_t cap)
{
    size_t n = 0;
    while (r->at < r->size && r->b[r->at] != '\n') {
        if (n + 1 < cap)
            line[n++] = (char)r->b[r->at];
        r->at++;
    }
    if (r->at >= r->size)
        return 0;
    r->at++;
    line[n] = '\0';
    return 1;
}

static cg_status read_header(hdr_reader *r, unsigned long *width, unsigned long *height,
                             double *exposure, cg_error *err)
{
    *exposure = 1;
    char line[256];
    if (!next_line(r, line, sizeof line)
        || (strncmp(line, "#?RADIANCE", 10) != 0 && strncmp(line, "#?RGBE", 6) != 0))
        return cg_error_set(err, CG_EFORMAT, "%s: not a Radiance HDR file (no #?RADIANCE line)",
                            r->name);
    for (;;) {
        if (!next_line(r, line, sizeof line))
            return cg_error_set(err, CG_EFORMAT, "%s: HDR header ends before the resolution",
                                r->name);
        if (line[0] == '\0')
            break;
        if (strncmp(line, "EXPOSURE=", 9) == 0) {
            char *end;
            double k = strtod(line + 9, &end);
            while (*end == ' ' || *end == '\t' || *end == '\r')
                end++;
            if (end == line + 9 || *end || !(k > 0) || !isfinite(k * *exposure)
                || !(k * *exposure > 0))
                return cg_error_set(err, CG_EFORMAT,
                                    "%s: bad HDR exposure line '%.64s' (expected EXPOSURE=K "
                                    "with K > 0)",
                                    r->name, line);
            *exposure *= k;
        }
        if (strncmp(line, "FORMAT=", 7) == 0 && strcmp(line + 7, "32-bit_rle_rgbe") != 0)
            return cg_error_set(err, CG_EUNSUPPORTED,
                                "%s: HDR pixel format '%s' is not supported (only "
                                "32-bit_rle_rgbe)",
                                r->name, line + 7);
    }
    if (!next_line(r, line, sizeof line))
        return cg_error_set(err, CG_EFORMAT, "%s: HDR file has no resolution line", r->name);
    char tail;
    if (sscanf(line, "-Y %lu +X %lu%c", height, width, &tail) != 2 || line[3] < '0'
        || line[3] > '9')
        return cg_error_set(err, CG_EUNSUPPORTED,
                            "%s: HDR resolution line '%.64s' is not \"-Y H +X W\" (the only "
                            "orientation cg reads)",
                            r->name, line);
    return image_check_dimensions(*width, *height, r->name, err);
}

/* One run-length encoded scanline's four components into scan (4 x width). */
static cg_status read_rle(hdr_reader *r, unsigned char *scan, size_t width, cg_error *err)
{
    for (int c = 0; c < 4; c++) {
        size_t x = 0;
        while (x < width) {
            if (r->at >= r->size)
                return cg_error_set(err, CG_EFORMAT, "%s: truncated HDR scanline", r->name);
            unsigned count = r->b[r->at++];
            int run = count > 128;
            if (run)
                count -= 128;
            if (count == 0 || count > width - x)
                return cg_error_set(err, CG_EFORMAT, "%s: bad HDR run length", r->name);
            if (r->size - r->at < (run ? 1u : count))
                return cg_error_set(err, CG_EFORMAT, "%s: truncated HDR scanline", r->name);
            for (unsigned k = 0; k < count; k++, x++)
                scan[4 * x + (size_t)c] = r->b[r->at + (run ? 0 : k)];
            r->at += run ? 1 : count;
        }
    }
    return CG_OK;
}

static cg_rgbaf rgbe_to_float(const unsigned char *p)
{
    if (p[3] == 0)
        return (cg_rgbaf){0, 0, 0, 1};
    double f = ldexp(1.0, (int)p[3] - 136);
    return (cg_rgbaf){(float)((p[0] + 0.5) * f), (float)((p[1] + 0.5) * f),
                      (float)((p[2] + 0.5) * f), 1};
}

cg_status hdr_decode(const unsigned char *bytes, size_t size, const char *name, cg_image **out,
                     cg_error *err)
{
    *out = NULL;
    hdr_reader r = {bytes, size, 0, name};
    unsigned long width, height;
    double exposure;
    cg_status status = read_header(&r, &width, &height, &exposure, err);
    if (status != CG_OK)
        return status;
    /* An image over a million pixels is allocated only when the data can
     * hold it: a scanline takes at least 4 bytes a pixel flat, or run-length
     * encoded its 4-byte start and two bytes per 127 pixels of each
     * component.  So a few bytes claiming a huge image are refused before
     * any allocation, while the errors of small files still name the exact
     * defect the decoding meets. */
    int rle = width >= 8 && width < 32768;
    size_t row_least = rle ? 4 + 8 * ((width + 126) / 127) : 4 * (size_t)width;
    if ((double)width * (double)height > 1 << 20 && (size - r.at) / row_least < height)
        return cg_error_set(err, CG_EFORMAT,
                            "%s: truncated HDR data: %lu rows of %lu pixels need at least %zu "
                            "bytes, the file has %zu",
                            name, height, width, row_least * height, size - r.at);
    unsigned char *scan = malloc((size_t)width * 4);
    if (!scan
        || (status = cg_image_create(out, (int)width, (int)height, CG_PIXEL_RGBAF)) != CG_OK) {
        free(scan);
        return cg_error_set(err, CG_ENOMEM, "%s: cannot allocate %lu x %lu image", name, width,
                            height);
    }
    for (unsigned long y = 0; y < height && status == CG_OK; y++) {
        const unsigned char *p = bytes + r.at;
        if (rle && size - r.at >= 4 && p[0] == 2 && p[1] == 2 && !(p[2] & 0x80)) {
            if (((unsigned long)p[2] << 8 | p[3]) != width)
                status = cg_error_set(err, CG_EFORMAT, "%s: HDR scanline width mismatch", name);
            else {
                r.at += 4;
                status = read_rle(&r, scan, width, err);
            }
        } else if (size - r.at < 4 * (size_t)width) {
            status = cg_error_set(err, CG_EFORMAT, "%s: truncated HDR data at row %lu of %lu", name,
                                  y, height);
        } else {
            memcpy(scan, p, 4 * (size_t)width);
            r.at += 4 * (size_t)width;
        }
        cg_rgbaf *row = cg_image_row_rgbaf(*out, (int)y);
        for (unsigned long x = 0; x < width && status == CG_OK; x++)
            row[x] = rgbe_to_float(scan + 4 * x);
        for (unsigned long x = 0; exposure != 1 && x < width && status == CG_OK; x++) {
            row[x].r = (float)(row[x].r / exposure);
            row[x].g = (float)(row[x].g / exposure);
            row[x].b = (float)(row[x].b / exposure);
        }
    }
    free(scan);
    if (status != CG_OK) {
        cg_image_free(*out);
        *out = NULL;
    }
    return status;
}

/* Radiance's float_to_rgbe: the largest component sets the shared exponent. */
static void float_to_rgbe(cg_rgbaf c, unsigned char *p)
{
    float v[3] = {c.r, c.g, c.b};
    for (int k = 0; k < 3; k++)
        if (!(v[k] > 0))
            v[k] = 0; /* negative and NaN */
        else if (v[k] > 1e38f)
            v[k] = 1e38f;
    float m = fmaxf(v[0], fmaxf(v[1], v[2]));
    if (m < 1e-32f) {
        p[0] = p[1] = p[2] = p[3] = 0;
        return;
    }
    int e;
    double scale = frexp(m, &e) * 256.0 / m;
    for (int k = 0; k < 3; k++) {
        double q = floor(v[k] * scale);
        p[k] = (unsigned char)(q > 255 ? 255 : q);
    }
    p[3] = (unsigned char)(e + 128);
}

/* One component of a scanline as runs (of 4 or more equal bytes) and literals. */
static cg_status encode_component(const unsigned char *scan, size_t width, int c, byte_buffer *out)
{
    cg_status status = CG_OK;
    size_t x = 0;
    while (x < width && status == CG_OK) {
        size_t run = 1;
        while (x + run < width && run < 127 && scan[4 * (x + run) + c] == scan[4 * x + c])
            run++;
        if (run >= 4) {
            unsigned char rec[2] = {(unsigned char)(128 + run), scan[4 * x + c]};
            status = byte_buffer_append(out, rec, 2);
            x += run;
            continue;
        }
        /* literals up to the next run of 4 */
        size_t n = 0;
        unsigned char lit[129];
        while (x < width && n < 128) {
            size_t r2 = 1;
            while (x + r2 < width && r2 < 4 && scan[4 * (x + r2) + c] == scan[4 * x + c])
                r2++;
            if (r2 >= 4)
                break;
            lit[1 + n++] = scan[4 * x++ + c];
        }
        lit[0] = (unsigned char)n;
        status = byte_buffer_append(out, lit, n + 1);
    }
    return status;
}

cg_status hdr_encode(const cg_image *image, byte_buffer *out, cg_error *err)
{
    char header[128];
    int n = snprintf(header, sizeof header,
                     "#?RADIANCE\nSOFTWARE=cg\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n",
                     image->height, image->width);
    size_t width = (size_t)image->width;
    unsigned char *scan = malloc(4 * width);
    cg_status status = scan ? byte_buffer_append(out, header, (size_t)n) : CG_ENOMEM;
    int rle = width >= 8 && width < 32768;
    for (int y = 0; y < image->height && status == CG_OK; y++) {
        const cg_rgbaf *in = cg_image_row_rgbaf((cg_image *)image, y);
        for (size_t x = 0; x < width; x++)
            float_to_rgbe(in[x], scan + 4 * x);
        if (!rle) {
            status = byte_buffer_append(out, scan, 4 * width);
            continue;
        }
        unsigned char mark[4] = {2, 2, (unsigned char)(width >> 8), (unsigned char)width};
        status = byte_buffer_append(out, mark, 4);
        for (int c = 0; c < 4 && status == CG_OK; c++)
            status = encode_component(scan, width, c, out);
    }
    free(scan);
    if (status != CG_OK)
        return cg_error_set(err, status, "HDR: out of memory encoding %d x %d image", image->width,
                            image->height);
    return CG_OK;
}
