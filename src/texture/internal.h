/* Private pieces of the texture module: the JPEG decoder (jpeg.c). */
#ifndef CG_TEXTURE_INTERNAL_H
#define CG_TEXTURE_INTERNAL_H

#include "cg/texture.h"

/* True when the bytes start like a JPEG file (SOI marker FF D8 FF). */
int texture_is_jpeg(const unsigned char *bytes, size_t size);

/* Decodes a baseline or progressive JPEG (grey, YCbCr or RGB) into a new
 * RGBA8 image with alpha 255.  CG_EFORMAT for malformed or truncated data
 * (libjpeg's message is given), CG_EUNSUPPORTED for CMYK / YCCK,
 * CG_ERANGE over CG_TEXTURE_MAX_TEXELS, CG_ENOMEM. */
cg_status texture_jpeg_decode(const unsigned char *bytes, size_t size, const char *name,
                              cg_image **out, cg_error *err);

#endif
