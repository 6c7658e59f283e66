/* Tone mapping a linear float image to 8-bit sRGB: exposure in stops, then
 * a clamp or the ACES-like filmic curve, then cg's sRGB encoding. */
#include "cg/color.h"
#include "cg/image_float.h"

#include <math.h>

/* Narkowicz (2015), "ACES Filmic Tone Mapping Curve": a rational fit of the
 * ACES reference rendering and output transforms, f(0) = 0, f(x) -> 1.03
 * (clamped to 1 on encoding) as x grows; about 0.8 at x = 1. */
static float filmic(float x)
{
    if (!(x > 0))
        return 0;
    if (isinf(x))
        return 1;
    double d = x;
    return (float)(d * (2.51 * d + 0.03) / (d * (2.43 * d + 0.59) + 0.14));
}

static float map_channel(float v, double scale, cg_tonemap curve)
{
    float x = (float)(v * scale);
    return curve == CG_TONEMAP_FILMIC ? filmic(x) : x;
}

cg_status cg_image_tonemap_curve(const cg_image *linear, double exposure, cg_tonemap curve,
                                 cg_image **out)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if (!linear || linear->format != CG_PIXEL_RGBAF || !isfinite(exposure) || fabs(exposure) > 1000
        || (curve != CG_TONEMAP_CLAMP && curve != CG_TONEMAP_FILMIC))
        return CG_EINVAL;
    cg_image *mapped;
    cg_status status = cg_image_create(&mapped, linear->width, linear->height, CG_PIXEL_RGBAF);
    if (status != CG_OK)
        return status;
    double scale = exp2(exposure);
    for (int y = 0; y < linear->height; y++) {
        const cg_rgbaf *in = cg_image_row_rgbaf((cg_image *)linear, y);
        cg_rgbaf *o = cg_image_row_rgbaf(mapped, y);
        for (int x = 0; x < linear->width; x++) {
            o[x].r = map_channel(in[x].r, scale, curve);
            o[x].g = map_channel(in[x].g, scale, curve);
            o[x].b = map_channel(in[x].b, scale, curve);
            o[x].a = in[x].a;
        }
    }
    status = cg_image_encode_srgb(mapped, out);
    cg_image_free(mapped);
    return status;
}
