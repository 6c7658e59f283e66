/* The image type: creation, pixel access, blending, format conversion. */
#include "cg/image.h"
#include "cg/color.h"

#include <stdlib.h>
#include <string.h>

static size_t bytes_per_pixel(cg_pixel_format format)
{
    return format == CG_PIXEL_RGBAF ? sizeof(cg_rgbaf) : sizeof(cg_rgba8);
}

cg_status cg_image_create(cg_image **out, int width, int height, cg_pixel_format format)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if (width <= 0 || height <= 0 || (format != CG_PIXEL_RGBA8 && format != CG_PIXEL_RGBAF))
        return CG_EINVAL;
    if (width > CG_IMAGE_MAX_SIDE || height > CG_IMAGE_MAX_SIDE
        || (size_t)width * (size_t)height > CG_IMAGE_CREATE_MAX_PIXELS)
        return CG_ERANGE;
    cg_image *image = malloc(sizeof *image);
    if (!image)
        return CG_ENOMEM;
    image->width = width;
    image->height = height;
    image->format = format;
    image->stride = (size_t)width * bytes_per_pixel(format);
    image->data = calloc((size_t)height, image->stride);
    if (!image->data) {
        free(image);
        return CG_ENOMEM;
    }
    *out = image;
    return CG_OK;
}

void cg_image_free(cg_image *image)
{
    if (image) {
        free(image->data);
        free(image);
    }
}

cg_status cg_image_copy(const cg_image *image, cg_image **out)
{
    if (!image)
        return CG_EINVAL;
    cg_status status = cg_image_create(out, image->width, image->height, image->format);
    if (status == CG_OK)
        memcpy((*out)->data, image->data, image->stride * (size_t)image->height);
    return status;
}

cg_status cg_image_convert(const cg_image *image, cg_pixel_format format, cg_image **out)
{
    if (!image)
        return CG_EINVAL;
    if (image->format == format)
        return cg_image_copy(image, out);
    return format == CG_PIXEL_RGBAF ? cg_image_decode_srgb(image, out)
                                    : cg_image_encode_srgb(image, out);
}

void cg_image_clear(cg_image *image, cg_rgbaf color)
{
    if (image->format == CG_PIXEL_RGBA8) {
        cg_image_clear_rgba8(image, cg_linear_to_rgba8(color));
        return;
    }
    for (int y = 0; y < image->height; y++) {
        cg_rgbaf *row = cg_image_row_rgbaf(image, y);
        for (int x = 0; x < image->width; x++)
            row[x] = color;
    }
}

void cg_image_clear_rgba8(cg_image *image, cg_rgba8 color)
{
    if (image->format != CG_PIXEL_RGBA8) {
        cg_image_clear(image, cg_rgba8_to_linear(color));
        return;
    }
    cg_rgba8 *first = cg_image_row_rgba8(image, 0);
    for (int x = 0; x < image->width; x++)
        first[x] = color;
    for (int y = 1; y < image->height; y++)
        memcpy(cg_image_row_rgba8(image, y), first, image->stride);
}

cg_rgbaf cg_image_get(const cg_image *image, int x, int y)
{
    cg_rgbaf none = {0, 0, 0, 0};
    if (!cg_image_contains(image, x, y))
        return none;
    if (image->format == CG_PIXEL_RGBAF)
        return cg_image_row_rgbaf((cg_image *)image, y)[x];
    return cg_rgba8_to_linear(cg_image_row_rgba8((cg_image *)image, y)[x]);
}

void cg_image_set(cg_image *image, int x, int y, cg_rgbaf color)
{
    if (!cg_image_contains(image, x, y))
        return;
    if (image->format == CG_PIXEL_RGBAF)
        cg_image_row_rgbaf(image, y)[x] = color;
    else
        cg_image_row_rgba8(image, y)[x] = cg_linear_to_rgba8(color);
}

cg_rgba8 cg_image_get_rgba8(const cg_image *image, int x, int y)
{
    if (image->format != CG_PIXEL_RGBA8)
        return cg_linear_to_rgba8(cg_image_get(image, x, y));
    if (!cg_image_contains(image, x, y)) {
        cg_rgba8 none = {0, 0, 0, 0};
        return none;
    }
    return cg_image_row_rgba8((cg_image *)image, y)[x];
}

void cg_image_set_rgba8(cg_image *image, int x, int y, cg_rgba8 color)
{
    if (image->format != CG_PIXEL_RGBA8) {
        cg_image_set(image, x, y, cg_rgba8_to_linear(color));
        return;
    }
    if (cg_image_contains(image, x, y))
        cg_image_row_rgba8(image, y)[x] = color;
}

/* Source-over with straight alpha: out = src*as + dst*ad*(1-as), divided by
 * the resulting alpha. */
static cg_rgbaf source_over(cg_rgbaf src, cg_rgbaf dst)
{
    float as = src.a < 0 ? 0 : (src.a > 1 ? 1 : src.a);
    float ad = dst.a * (1 - as);
    float a = as + ad;
    cg_rgbaf out = {0, 0, 0, 0};
    if (a <= 0)
        return out;
    out.r = (src.r * as + dst.r * ad) / a;
    out.g = (src.g * as + dst.g * ad) / a;
    out.b = (src.b * as + dst.b * ad) / a;
    out.a = a;
    return out;
}

void cg_image_blend(cg_image *image, int x, int y, cg_rgbaf color)
{
    if (!cg_image_contains(image, x, y))
        return;
    if (color.a >= 1) {
        cg_image_set(image, x, y, color);
        return;
    }
    if (!(color.a > 0))
        return;
    cg_image_set(image, x, y, source_over(color, cg_image_get(image, x, y)));
}

void cg_image_blend_image(cg_image *dst, const cg_image *src, int dx, int dy)
{
    /* In long long: offsets near the limits of int must not overflow. */
    long long x0 = dx < 0 ? -(long long)dx : 0, y0 = dy < 0 ? -(long long)dy : 0;
    for (long long y = y0; y < src->height && y + dy < dst->height; y++)
        for (long long x = x0; x < src->width && x + dx < dst->width; x++)
            cg_image_blend(dst, (int)(x + dx), (int)(y + dy), cg_image_get(src, (int)x, (int)y));
}
