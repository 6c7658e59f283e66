/* cg/image.h - the one image type every cg stage draws into.
 *
 * Origin top-left, y down; pixel (x, y) covers [x, x+1) x [y, y+1).
 * Two pixel formats:
 *  - CG_PIXEL_RGBA8: 8 bits per channel, sRGB-encoded colour, straight
 *    (non-premultiplied) alpha.  What files hold and screens show.
 *  - CG_PIXEL_RGBAF: 32-bit float per channel, linear light, straight alpha.
 *    For accumulation and shading; convert to RGBA8 to save.
 * The format is the image's statement of whether it is linear or encoded.
 */
#ifndef CG_IMAGE_H
#define CG_IMAGE_H

#include "cg/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cg_pixel_format {
    CG_PIXEL_RGBA8 = 0, /* sRGB-encoded 8-bit RGBA */
    CG_PIXEL_RGBAF = 1  /* linear-light float RGBA */
} cg_pixel_format;

typedef struct cg_rgba8 {
    uint8_t r, g, b, a;
} cg_rgba8;
typedef struct cg_rgbaf {
    float r, g, b, a;
} cg_rgbaf;

/* Limits.  CG_IMAGE_MAX_SIDE: largest width or height, 2^24 = 16,777,216,
 * everywhere.  CG_IMAGE_MAX_PIXELS: largest pixel count of an image read
 * from a file (and of the command-line tool's canvases), 2^28 = 268,435,456
 * pixels (1 GiB in RGBA8), so that a small file cannot claim gigabytes (a
 * decompression bomb).  CG_IMAGE_CREATE_MAX_PIXELS: largest pixel count of
 * an image created in memory by cg_image_create, 2^30 = 1,073,741,824 pixels
 * (4 GiB in RGBA8, 16 GiB in RGBAF), e.g. a 20,000 x 20,000 maze. */
#define CG_IMAGE_MAX_SIDE (1 << 24)
#define CG_IMAGE_MAX_PIXELS ((size_t)1 << 28)
#define CG_IMAGE_CREATE_MAX_PIXELS ((size_t)1 << 30)

typedef struct cg_image {
    int width, height;
    cg_pixel_format format;
    size_t stride;       /* bytes from one row to the next */
    unsigned char *data; /* row 0 first */
} cg_image;

/* A new image of the given size and format, every pixel transparent black.
 * CG_EINVAL for a non-positive size, CG_ERANGE beyond CG_IMAGE_MAX_SIDE or
 * CG_IMAGE_CREATE_MAX_PIXELS. */
cg_status cg_image_create(cg_image **out, int width, int height, cg_pixel_format format);
void cg_image_free(cg_image *image);
/* A deep copy. */
cg_status cg_image_copy(const cg_image *image, cg_image **out);
/* A copy in the other format: RGBA8 -> RGBAF decodes sRGB to linear light,
 * RGBAF -> RGBA8 clamps to [0, 1] and encodes with correct rounding. */
cg_status cg_image_convert(const cg_image *image, cg_pixel_format format, cg_image **out);

/* Fills every pixel with color (given as linear-light float RGBA). */
void cg_image_clear(cg_image *image, cg_rgbaf color);
/* Fills every pixel of an RGBA8 image with an encoded colour. */
void cg_image_clear_rgba8(cg_image *image, cg_rgba8 color);

static inline int cg_image_contains(const cg_image *image, int x, int y)
{
    return x >= 0 && y >= 0 && x < image->width && y < image->height;
}
static inline cg_rgba8 *cg_image_row_rgba8(cg_image *image, int y)
{
    return (cg_rgba8 *)(image->data + (size_t)y * image->stride);
}
static inline cg_rgbaf *cg_image_row_rgbaf(cg_image *image, int y)
{
    return (cg_rgbaf *)(image->data + (size_t)y * image->stride);
}

/* Pixel access in linear-light float, whatever the format.  Reading outside
 * the image gives transparent black; writing outside does nothing. */
cg_rgbaf cg_image_get(const cg_image *image, int x, int y);
void cg_image_set(cg_image *image, int x, int y, cg_rgbaf color);
/* Source-over blend of color (straight alpha, linear light) onto pixel (x, y);
 * for RGBA8 images the blend happens in linear light and is re-encoded. */
void cg_image_blend(cg_image *image, int x, int y, cg_rgbaf color);
/* Source-over blend of all of src onto dst with src's top-left at (dx, dy),
 * clipped to dst. */
void cg_image_blend_image(cg_image *dst, const cg_image *src, int dx, int dy);

/* Encoded 8-bit pixel access for RGBA8 images (fast paths of drawing code). */
cg_rgba8 cg_image_get_rgba8(const cg_image *image, int x, int y);
void cg_image_set_rgba8(cg_image *image, int x, int y, cg_rgba8 color);

/* ---- files -------------------------------------------------------------- */

typedef enum cg_file_format {
    CG_FILE_UNKNOWN = 0,
    CG_FILE_PNG,
    CG_FILE_PPM,       /* binary P6 when written */
    CG_FILE_PGM,       /* binary P5 when written */
    CG_FILE_PPM_ASCII, /* P3 */
    CG_FILE_PGM_ASCII, /* P2 */
    CG_FILE_PFM,       /* portable float map, written as PF little-endian */
    CG_FILE_HDR,       /* Radiance RGBE, run-length encoded when written */
    CG_FILE_EXR        /* OpenEXR, RGBA half with ZIP compression when written */
} cg_file_format;

/* The format named by a path's extension (.png, .ppm, .pgm, .pfm, .hdr,
 * .exr; case-insensitive).  The float formats are in cg/image_float.h. */
cg_file_format cg_file_format_from_path(const char *path);

/* Reads a PNG, PPM (P3, P6) or PGM (P2, P5) file, chosen by its content, into
 * a new RGBA8 image (a float file, see cg/image_float.h, is read and encoded
 * to sRGB, clamped; cg_image_load keeps it in float).  CG_EIO when it cannot be opened, CG_EFORMAT with a
 * message for malformed content, CG_ERANGE for dimensions over the limits. */
cg_status cg_image_read(const char *path, cg_image **out, cg_error *err);
/* The same from memory; name is used in messages. */
cg_status cg_image_read_memory(const void *bytes, size_t size, const char *name, cg_image **out,
                               cg_error *err);

/* Writes the image in the given format (CG_FILE_UNKNOWN: from the path's
 * extension).  The file is written to a temporary name beside path and renamed
 * into place, so a failure leaves any existing file untouched.  PGM stores the
 * luminance; PPM and PGM drop alpha; RGBAF images are encoded to sRGB first.
 * The float formats (PFM, HDR, EXR) take RGBAF images as they are and decode
 * RGBA8 images from sRGB to linear light first. */
cg_status cg_image_write(const cg_image *image, const char *path, cg_file_format format,
                         cg_error *err);

/* ---- whole-image colour operations (implemented with cg/color.h) -------- */

/* Images: an RGBA8 image is sRGB-encoded, an RGBAF image is linear light
 * (see above).  These make the other kind: decode gives RGBAF, encode
 * gives RGBA8 (clamped to [0, 1], NaN -> 0, correctly rounded); alpha is
 * copied (scaled by 255).  CG_EINVAL when src is not of the expected format. */
cg_status cg_image_decode_srgb(const cg_image *src, cg_image **out);
cg_status cg_image_encode_srgb(const cg_image *src, cg_image **out);

/* Maps a linear RGBAF image to a new encoded RGBA8 image: multiplies by
 * 2^stops, then clamps (exposure <= 0) or applies cg_intensity_expose with
 * that exposure, then encodes sRGB.  Alpha copied.  CG_EINVAL unless src is
 * RGBAF and stops, exposure finite. */
cg_status cg_image_tonemap(const cg_image *src, double stops, double exposure, cg_image **out);

typedef enum cg_dither {
    CG_DITHER_NONE = 0,       /* plain quantization to the nearest level */
    CG_DITHER_BAYER2,         /* ordered dithering, 2x2 Bayer matrix */
    CG_DITHER_BAYER4,         /* 4x4 */
    CG_DITHER_BAYER8,         /* 8x8 */
    CG_DITHER_FLOYD_STEINBERG /* error diffusion 7/16, 3/16, 5/16, 1/16 */
} cg_dither;

/* Dithering, as cg_dither_plane (cg/color.h) does it, of each colour channel
 * of an RGBA8 image, on its encoded values (what the screen shows), in place.
 * Alpha is left alone. */
cg_status cg_image_dither(cg_image *image, int levels, cg_dither method);

/* cg_image_rgb_to_model and cg_image_model_to_rgb take a cg_color_model:
 * they are declared in cg/color.h with the colour models. */

#ifdef __cplusplus
}
#endif
#endif
