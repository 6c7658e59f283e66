/* Private pieces shared by the image readers and writers. */
#ifndef CG_IMAGE_INTERNAL_H
#define CG_IMAGE_INTERNAL_H

#include "cg/image.h"

/* A growable byte buffer that a writer fills before it goes to disk. */
typedef struct byte_buffer {
    unsigned char *bytes;
    size_t size, capacity;
} byte_buffer;

cg_status byte_buffer_append(byte_buffer *buffer, const void *bytes, size_t size);
void byte_buffer_free(byte_buffer *buffer);

/* Checks a size read from a file against CG_IMAGE_MAX_SIDE/PIXELS. */
cg_status image_check_dimensions(unsigned long width, unsigned long height, const char *name,
                                 cg_error *err);

cg_status png_decode(const unsigned char *bytes, size_t size, const char *name, cg_image **out,
                     cg_error *err);
cg_status pnm_decode(const unsigned char *bytes, size_t size, const char *name, cg_image **out,
                     cg_error *err);
cg_status pfm_decode(const unsigned char *bytes, size_t size, const char *name, cg_image **out,
                     cg_error *err);
cg_status hdr_decode(const unsigned char *bytes, size_t size, const char *name, cg_image **out,
                     cg_error *err);
/* OpenEXR (exr.c); without libopenexr these give CG_EUNSUPPORTED. */
cg_status image_exr_decode(const unsigned char *bytes, size_t size, const char *name,
                           cg_image **out, cg_error *err);

/* Replaces path with contents atomically (a temporary file renamed over it). */
cg_status image_replace_file(const char *path, const byte_buffer *contents, cg_error *err);

/* The float encoders take an RGBAF image. */
cg_status pfm_encode(const cg_image *image, byte_buffer *out, cg_error *err);
cg_status hdr_encode(const cg_image *image, byte_buffer *out, cg_error *err);

/* Encoders take an RGBA8 image. */
cg_status png_encode(const cg_image *image, byte_buffer *out, cg_error *err);
cg_status pnm_encode(const cg_image *image, cg_file_format format, byte_buffer *out, cg_error *err);

#endif
