/* Textures: linear-light texels made from an image, and the mip chain.
 *
 * Level k + 1 (m texels wide) is the box average of level k (n wide): its
 * texel x covers the level-k span [x r, (x + 1) r), r = n / m, and is the
 * area-weighted mean of the level-k texels under that span (in 2D the
 * product of a horizontal and a vertical weight).  For even sizes that is
 * the mean of 2 x 2 texels; an odd size gives spans of 2.5 texels, so no
 * texel is dropped:
 *
 *   level k:    | 0 | 1 | 2 | 3 | 4 |        n = 5
 *   level k+1:  |    0     |    1     |      m = 2, r = 2.5
 *   weights:     1  1  .5    .5  1  1  (/ 2.5)
 */
#include "cg/texture.h"
#include "cg/color.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void cg_texture_free(cg_texture *texture)
{
    if (!texture)
        return;
    for (int k = 0; k < texture->level_count; k++)
        free(texture->levels[k].texels);
    free(texture->levels);
    free(texture);
}

/* The source texels under destination texel x and their weights (summing to
 * 1): at most 4 of them, since r <= 3 (n = 3 gives m = 1). */
typedef struct span {
    int first, count;
    float weight[4];
} span;

static span span_of(int x, int n, int m)
{
    double r = (double)n / m, lo = x * r, hi = (x + 1) * r;
    span s;
    s.first = (int)floor(lo);
    s.count = 0;
    for (int i = s.first; i < n && i < hi && s.count < 4; i++) {
        double overlap = fmin(hi, i + 1.0) - fmax(lo, (double)i);
        s.weight[s.count++] = (float)(overlap / r);
    }
    return s;
}

/* Level `to` from level `from` (the box average above). */
static cg_status halve(const cg_texture_level *from, cg_texture_level *to)
{
    int n = from->width, h = from->height;
    int m = n > 1 ? n / 2 : 1, mh = h > 1 ? h / 2 : 1;
    to->width = m;
    to->height = mh;
    to->texels = malloc((size_t)m * (size_t)mh * sizeof *to->texels);
    /* horizontal pass into rows of m, then vertical */
    cg_rgbaf *rows = malloc((size_t)m * (size_t)h * sizeof *rows);
    if (!to->texels || !rows) {
        free(rows);
        return CG_ENOMEM;
    }
    for (int x = 0; x < m; x++) {
        span s = span_of(x, n, m);
        for (int y = 0; y < h; y++) {
            const cg_rgbaf *src = from->texels + (size_t)y * (size_t)n;
            cg_rgbaf sum = {0, 0, 0, 0};
            for (int k = 0; k < s.count; k++) {
                cg_rgbaf t = src[s.first + k];
                float w = s.weight[k];
                sum.r += w * t.r, sum.g += w * t.g, sum.b += w * t.b, sum.a += w * t.a;
            }
            rows[(size_t)y * (size_t)m + (size_t)x] = sum;
        }
    }
    for (int y = 0; y < mh; y++) {
        span s = span_of(y, h, mh);
        for (int x = 0; x < m; x++) {
            cg_rgbaf sum = {0, 0, 0, 0};
            for (int k = 0; k < s.count; k++) {
                cg_rgbaf t = rows[(size_t)(s.first + k) * (size_t)m + (size_t)x];
                float w = s.weight[k];
                sum.r += w * t.r, sum.g += w * t.g, sum.b += w * t.b, sum.a += w * t.a;
            }
            to->texels[(size_t)y * (size_t)m + (size_t)x] = sum;
        }
    }
    free(rows);
    return CG_OK;
}

/* Level 0's texel from an image pixel. */
static cg_rgbaf texel_of(const cg_image *image, int x, int y, cg_texture_encoding encoding)
{
    cg_rgbaf t;
    if (image->format == CG_PIXEL_RGBAF) {
        t = ((const cg_rgbaf *)(image->data + (size_t)y * image->stride))[x];
    } else {
        cg_rgba8 c = ((const cg_rgba8 *)(image->data + (size_t)y * image->stride))[x];
        if (encoding == CG_TEXTURE_SRGB) {
            t.r = cg_srgb8_to_linear(c.r);
            t.g = cg_srgb8_to_linear(c.g);
            t.b = cg_srgb8_to_linear(c.b);
        } else {
            t.r = c.r / 255.0f;
            t.g = c.g / 255.0f;
            t.b = c.b / 255.0f;
        }
        t.a = c.a / 255.0f;
    }
    if (encoding == CG_TEXTURE_SRGB) { /* premultiplied, for filtering */
        t.r *= t.a;
        t.g *= t.a;
        t.b *= t.a;
    }
    return t;
}

cg_status cg_texture_from_image(const cg_image *image, cg_texture_encoding encoding,
                                cg_texture **out)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if (!image || image->width <= 0 || image->height <= 0
        || (encoding != CG_TEXTURE_SRGB && encoding != CG_TEXTURE_LINEAR))
        return CG_EINVAL;
    if ((size_t)image->width * (size_t)image->height > CG_TEXTURE_MAX_TEXELS)
        return CG_ERANGE;
    int levels = 1;
    for (int side = image->width > image->height ? image->width : image->height; side > 1;
         side /= 2)
        levels++;
    cg_texture *t = calloc(1, sizeof *t);
    if (!t || !(t->levels = calloc((size_t)levels, sizeof *t->levels))) {
        free(t);
        return CG_ENOMEM;
    }
    t->encoding = encoding;
    cg_texture_level *base = &t->levels[0];
    base->width = image->width;
    base->height = image->height;
    t->level_count = 1;
    if (!(base->texels = malloc((size_t)image->width * (size_t)image->height
                                * sizeof *base->texels))) {
        cg_texture_free(t);
        return CG_ENOMEM;
    }
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++)
            base->texels[(size_t)y * (size_t)image->width + (size_t)x] = texel_of(image, x, y,
                                                                                  encoding);
    for (int k = 1; k < levels; k++) {
        cg_status s = halve(&t->levels[k - 1], &t->levels[k]);
        t->level_count = k + 1; /* so that free sees what was made */
        if (s != CG_OK) {
            cg_texture_free(t);
            return s;
        }
    }
    *out = t;
    return CG_OK;
}
