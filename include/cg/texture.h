/* cg/texture.h - textures for the renderers: images read from PNG or JPEG,
 * kept in linear light with their mip levels, and sampled with nearest,
 * bilinear or trilinear filtering and three wrap modes.
 *
 * Colour textures (base colour, emissive, specular) are sRGB-encoded in
 * their files and decoded to linear light once, when loaded; data textures
 * (normal, roughness/metallic, occlusion, bump, alpha maps) hold numbers and
 * are kept as they are (code / 255).  The mip levels are built once, from
 * the linear values: level k + 1 is the box average of level k, each of its
 * texels the area-weighted mean of the level-k texels under it.
 *
 * Texture coordinates follow cg_mesh: (0, 0) is the bottom-left corner of
 * the image and (1, 1) the top-right one (as OBJ and OpenGL); texel (x, y)
 * of a level w x h (row 0 at the top) is centred at
 * u = (x + 0.5) / w, v = 1 - (y + 0.5) / h. */
#ifndef CG_TEXTURE_H
#define CG_TEXTURE_H

#include "cg/core.h"
#include "cg/image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a texture's 8-bit codes mean. */
typedef enum cg_texture_encoding {
    CG_TEXTURE_SRGB = 0,  /* colour: decoded with the sRGB curve; alpha linear */
    CG_TEXTURE_LINEAR = 1 /* data: code / 255 in every channel */
} cg_texture_encoding;

typedef enum cg_texture_filter {
    CG_TEXTURE_NEAREST = 0,  /* the texel under the point, level 0 */
    CG_TEXTURE_BILINEAR = 1, /* the four texels around it, weighted, level 0 */
    CG_TEXTURE_TRILINEAR = 2 /* bilinear in levels floor(lod) and floor(lod) + 1,
                                 mixed by lod's fraction (lod clamped to the levels) */
} cg_texture_filter;

typedef enum cg_texture_wrap {
    CG_TEXTURE_REPEAT = 0,          /* texel i of n: i mod n */
    CG_TEXTURE_MIRRORED_REPEAT = 1, /* 0 1 .. n-1 n-1 .. 1 0 0 1 .. */
    CG_TEXTURE_CLAMP = 2            /* the edge texel beyond the edges */
} cg_texture_wrap;

/* The largest texture read: 2^25 texels (8192 x 4096), 16 bytes each in
 * linear light, plus a third for the mip levels. */
#define CG_TEXTURE_MAX_TEXELS ((size_t)1 << 25)

/* One mip level: width x height texels, row 0 at the top.  Colour texels
 * (CG_TEXTURE_SRGB) are stored with premultiplied alpha, so that filtering
 * never bleeds the colour of transparent texels; data texels as they are. */
typedef struct cg_texture_level {
    int width, height;
    cg_rgbaf *texels;
} cg_texture_level;

typedef struct cg_texture {
    cg_texture_encoding encoding;
    int level_count;          /* 1 + floor(log2(max(width, height))) */
    cg_texture_level *levels; /* levels[0] is the image; each next one half the
                                 size (rounded down, at least 1) */
} cg_texture;

typedef struct cg_texture_sampler {
    cg_texture_filter filter;
    cg_texture_wrap wrap_u, wrap_v;
} cg_texture_sampler;

/* Reads a PNG or JPEG file (told apart by content) into a texture with all
 * its mip levels.  Grey, palette and RGB files get alpha 1; 16-bit PNG
 * channels are reduced to 8 bits.  CG_EIO (cannot open or read),
 * CG_EFORMAT (not PNG or JPEG, or malformed / truncated), CG_EUNSUPPORTED
 * (CMYK JPEG), CG_ERANGE (over CG_TEXTURE_MAX_TEXELS), CG_ENOMEM; err says
 * "file: what was wrong". */
cg_status cg_texture_load(const char *path, cg_texture_encoding encoding, cg_texture **out,
                          cg_error *err);
/* The same from bytes in memory; name is used in messages. */
cg_status cg_texture_load_memory(const void *bytes, size_t size, const char *name,
                                 cg_texture_encoding encoding, cg_texture **out, cg_error *err);
/* A texture of an image: RGBA8 codes mean what encoding says; RGBAF pixels
 * are linear values whatever the encoding (colour ones premultiplied when
 * encoding is CG_TEXTURE_SRGB).  CG_EINVAL for a missing image, CG_ERANGE
 * over CG_TEXTURE_MAX_TEXELS, CG_ENOMEM. */
cg_status cg_texture_from_image(const cg_image *image, cg_texture_encoding encoding,
                                cg_texture **out);
void cg_texture_free(cg_texture *texture);

/* The texture's value at (u, v), in linear light with straight alpha (the
 * premultiplied filter result divided by its alpha; 0 where alpha is 0).
 * lod is the level of detail (log2 of texels per pixel) and matters to
 * CG_TEXTURE_TRILINEAR only.  Bilinear weights: with x = u w - 0.5,
 * y = (1 - v) h - 0.5, the texels floor(x) + {0, 1} and floor(y) + {0, 1}
 * (wrapped) get (1 - fx, fx) x (1 - fy, fy), fx and fy the fractions.  A
 * non-finite u, v or lod is taken as 0. */
cg_rgbaf cg_texture_sample(const cg_texture *texture, const cg_texture_sampler *sampler, double u,
                           double v, double lod);

/* The texel index i (any integer) of a row or column of n texels, wrapped. */
int cg_texture_wrap_index(long long i, int n, cg_texture_wrap wrap);

#ifdef __cplusplus
}
#endif
#endif
