/* cg/image_float.h - float image files and tone mapping.
 *
 * Three file formats hold linear-light float pixels (cg_image in
 * CG_PIXEL_RGBAF):
 *  - PFM (.pfm): "PF" colour or "Pf" grey, 32-bit floats, rows bottom to top;
 *    written little-endian, read in either byte order; bit-exact.  No alpha
 *    (read as 1, dropped when written).
 *  - Radiance RGBE (.hdr): 8-bit mantissas with a shared exponent (relative
 *    precision 2^-8 of the brightest channel); flat and new-style run-length
 *    encoded scanlines read, run-length encoded written; only the standard
 *    "-Y H +X W" orientation.  No alpha.
 *  - OpenEXR (.exr): written as RGBA half (or 32-bit float) with ZIP
 *    compression, optionally with extra named channels; read from any
 *    scanline or tiled file with R, G, B (and A), or Y, channels.
 * docs/image.md describes the formats and the tone curves.
 */
#ifndef CG_IMAGE_FLOAT_H
#define CG_IMAGE_FLOAT_H

#include "cg/image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Reads any image file cg knows, recognised by content: the float formats
 * (PFM, HDR, EXR) into a new RGBAF image, the 8-bit ones (PNG, PPM, PGM) into
 * a new RGBA8 image.  Errors as cg_image_read. */
cg_status cg_image_load(const char *path, cg_image **out, cg_error *err);
/* The same from memory; name is used in messages. */
cg_status cg_image_load_memory(const void *bytes, size_t size, const char *name, cg_image **out,
                               cg_error *err);
/* Reads any image file cg knows into a new RGBAF image in linear light: the
 * float formats as they are, the 8-bit ones decoded from sRGB (what an
 * environment map or a light probe needs).  Errors as cg_image_read. */
cg_status cg_image_load_linear(const char *path, cg_image **out, cg_error *err);


/* 1 when the format holds float pixels (PFM, HDR, EXR). */
int cg_file_format_is_float(cg_file_format format);

typedef enum cg_tonemap {
    CG_TONEMAP_CLAMP = 0, /* no curve: values are clamped to [0, 1] */
    CG_TONEMAP_FILMIC     /* Narkowicz's fit of the ACES filmic curve (docs/image.md) */
} cg_tonemap;

/* Maps a linear RGBAF image to a new RGBA8 image: each colour channel is
 * multiplied by 2^exposure (exposure in stops), passed through the curve,
 * and encoded to sRGB exactly as cg_image_write encodes an RGBAF image for
 * PNG (clamped, NaN -> 0, correctly rounded).  Alpha is copied.  The filmic
 * curve is f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14) for x > 0,
 * 0 otherwise.  CG_EINVAL unless linear is RGBAF, exposure is finite and
 * within +-1000, and curve is one of the above. */
cg_status cg_image_tonemap_curve(const cg_image *linear, double exposure, cg_tonemap curve,
                                 cg_image **out);

/* ---- OpenEXR ---------------------------------------------------------- */

/* An extra EXR channel: a float image of the beauty's size whose first
 * `channels` components (1 to 4: r, g, b, a) are written under the names
 * "<name>.<suffix[k]>", e.g. name "albedo", suffixes "RGB" give albedo.R,
 * albedo.G, albedo.B; name "depth", suffixes "Z" give depth.Z. */
typedef struct cg_image_layer {
    const char *name;      /* letters, digits, '_' and '-' */
    const char *suffixes;  /* one character a channel, e.g. "RGB", "XYZ", "Z" */
    const cg_image *image; /* RGBAF, the beauty's size */
} cg_image_layer;

typedef struct cg_exr_options {
    int full_float; /* 0: 16-bit half channels (the default), 1: 32-bit float */
} cg_exr_options;

/* 1 when this build of cg reads and writes OpenEXR (libopenexr was found). */
int cg_exr_supported(void);

/* Writes beauty (RGBAF, or RGBA8 decoded to linear) as the R, G, B, A
 * channels of a ZIP-compressed scanline EXR at path, and each of the n extra
 * layers as further channels, atomically as cg_image_write.  options may be
 * NULL (half).  CG_EINVAL for a bad layer (wrong size or format, bad name),
 * CG_EUNSUPPORTED when cg was built without OpenEXR. */
cg_status cg_image_write_exr(const char *path, const cg_image *beauty, const cg_image_layer *extra,
                             size_t n, const cg_exr_options *options, cg_error *err);

#ifdef __cplusplus
}
#endif
#endif
