/* Layers: a transparent image drawn on its own, then composited onto the
 * drawing with an opacity, a blend mode and operator, a clip path and a
 * mask, pixel by pixel in the rasterizer's compositing space.
 *
 *   layer pixel --(alpha x opacity x mask)--> source
 *   source, drawing pixel --blend, operator--> result
 *   drawing pixel = clip * result + (1 - clip) * drawing pixel */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

cg_layer_style cg_layer_style_default(void)
{
    cg_layer_style style;
    memset(&style, 0, sizeof style);
    style.opacity = 1;
    style.op = CG_OPERATOR_OVER;
    style.mode = CG_BLEND_NORMAL;
    style.clip_rule = CG_FILL_NONZERO;
    style.mask_type = CG_MASK_ALPHA;
    return style;
}

static cg_rgbaf image_pixel(const cg_image *image, int x, int y, cg_compositing_space space)
{
    if (image->format == CG_PIXEL_RGBA8)
        return fill_load_pixel8(cg_image_row_rgba8((cg_image *)image, y)[x], space);
    return fill_load_pixelf(cg_image_row_rgbaf((cg_image *)image, y)[x], space);
}

/* The mask's value at a pixel: alpha, or luminance times alpha (the
 * luminance of the premultiplied colour is already times alpha). */
static float mask_value(const cg_image *mask, cg_mask_type type, int x, int y,
                        cg_compositing_space space)
{
    cg_rgbaf m = image_pixel(mask, x, y, space);
    if (type == CG_MASK_ALPHA)
        return m.a;
    return 0.2125f * m.r + 0.7154f * m.g + 0.0721f * m.b;
}

/* The clip path's coverage as the alpha of a transparent image: white
 * drawn over it in the default compositing. */
static cg_status clip_coverage(cg_rasterizer *r, const cg_image *like, const cg_path *clip,
                               cg_fill_rule rule, cg_image **out)
{
    cg_status status = cg_image_create(out, like->width, like->height, CG_PIXEL_RGBA8);
    if (status != CG_OK)
        return status;
    int space = r->space, op = r->op, mode = r->mode;
    r->space = CG_COMPOSITE_LINEAR;
    r->op = CG_OPERATOR_OVER;
    r->mode = CG_BLEND_NORMAL;
    cg_rgba8 white = {255, 255, 255, 255};
    cg_paint paint = cg_paint_solid(white);
    status = cg_rasterizer_fill_path(r, *out, clip, rule, &paint);
    r->space = space;
    r->op = op;
    r->mode = mode;
    if (status != CG_OK) {
        cg_image_free(*out);
        *out = NULL;
    }
    return status;
}

static int same_size(const cg_image *a, const cg_image *b)
{
    return a->width == b->width && a->height == b->height && a->data && b->data
           && (b->format == CG_PIXEL_RGBA8 || b->format == CG_PIXEL_RGBAF);
}

cg_status cg_rasterizer_composite_layer(cg_rasterizer *r, cg_image *image, const cg_image *layer,
                                        const cg_layer_style *style)
{
    if (!r || !image || !layer || !style || !same_size(layer, image) || !same_size(image, layer)
        || !(style->opacity >= 0 && style->opacity <= 1) || (unsigned)style->op >= CG_OPERATOR_COUNT
        || (unsigned)style->mode >= CG_BLEND_COUNT
        || (style->clip_rule != CG_FILL_NONZERO && style->clip_rule != CG_FILL_EVEN_ODD)
        || (style->mask
            && (!same_size(layer, style->mask)
                || (style->mask_type != CG_MASK_ALPHA && style->mask_type != CG_MASK_LUMINANCE))))
        return CG_EINVAL;
    cg_compositing_space space = (cg_compositing_space)r->space;
    cg_image *clip = NULL;
    if (style->clip) {
        cg_status status = clip_coverage(r, image, style->clip, style->clip_rule, &clip);
        if (status != CG_OK)
            return status;
    }
    float opacity = (float)style->opacity;
    /* the common case of SVG groups: over, normal, sRGB, RGBA8 onto RGBA8 */
    int fast = space == CG_COMPOSITE_SRGB && style->op == CG_OPERATOR_OVER
               && style->mode == CG_BLEND_NORMAL && image->format == CG_PIXEL_RGBA8
               && layer->format == CG_PIXEL_RGBA8
               && (!style->mask || style->mask_type == CG_MASK_ALPHA);
    int x0 = 0, y0 = 0, x1 = image->width, y1 = image->height;
    if (style->has_box) {
        x0 = style->box_x0 > 0 ? style->box_x0 : 0;
        y0 = style->box_y0 > 0 ? style->box_y0 : 0;
        x1 = style->box_x1 < x1 ? style->box_x1 : x1;
        y1 = style->box_y1 < y1 ? style->box_y1 : y1;
    }
    for (int y = y0; y < y1; y++) {
        const cg_rgba8 *clip_row = clip ? cg_image_row_rgba8(clip, y) : NULL;
        for (int x = x0; x < x1; x++) {
            float k = clip_row ? clip_row[x].a * (1.0f / 255.0f) : 1.0f;
            if (k == 0)
                continue;
            if (fast) {
                cg_rgba8 s = cg_image_row_rgba8((cg_image *)layer, y)[x];
                if (s.a == 0)
                    continue;
                float a = s.a * (1.0f / 255.0f) * opacity * k;
                if (style->mask)
                    a *= cg_image_row_rgba8((cg_image *)style->mask, y)[x].a * (1.0f / 255.0f);
                fill_srgb_over(cg_image_row_rgba8(image, y) + x, s.r, s.g, s.b, a);
                continue;
            }
            cg_rgbaf source = image_pixel(layer, x, y, space);
            float scale = opacity;
            if (style->mask)
                scale *= mask_value(style->mask, style->mask_type, x, y, space);
            if (source.a == 0 && style->op == CG_OPERATOR_OVER)
                continue; /* nothing over the drawing leaves it as it is */
            source.r *= scale;
            source.g *= scale;
            source.b *= scale;
            source.a *= scale;
            if (image->format == CG_PIXEL_RGBA8)
                fill_composite_pixel8(cg_image_row_rgba8(image, y) + x, source, space, style->op,
                                      style->mode, k);
            else
                fill_composite_pixelf(cg_image_row_rgbaf(image, y) + x, source, space, style->op,
                                      style->mode, k);
        }
    }
    cg_image_free(clip);
    return CG_OK;
}
