/* The colour of a textured fragment.  The rasterizer hands over the
 * attributes interpolated perspective-correctly at the pixel centre
 * (attribute / w and 1 / w are affine on the screen) and the exact
 * derivatives of the texture coordinates along the pixel's row and column
 * (the quotient rule on those affine functions).  Here the material's
 * texture transform is applied, the level of detail chosen from the pixel's
 * footprint in texels, as OpenGL does,
 *
 *   rho = max(|(du/dx, dv/dx) * (w, h)|, |(du/dy, dv/dy) * (w, h)|),
 *   lod = log2(rho),
 *
 * the base colour sampled and multiplied by the interpolated colour (the
 * material's factor times the vertex colours), then lit per pixel unless
 * the shading is unlit. */
#include "pipeline.h"

#include <math.h>

int render_textured_fragment(const render_frame *f, uint32_t material, const float *v,
                             const float duv[4], float out[3], float *alpha_out)
{
    float base[3] = {v[6], v[7], v[8]};
    const render_material *m = material != RENDER_NO_MATERIAL ? &f->r->materials[material] : NULL;
    float alpha = m ? m->alpha : 1;
    if (m && m->base_texture) {
        const cg_texture *texture = m->base_texture;
        float u0 = v[TEXTURED_UV], v0 = v[TEXTURED_UV + 1];
        double u = m->transform[0][0] * u0 + m->transform[0][1] * v0 + m->transform[0][2];
        double t = m->transform[1][0] * u0 + m->transform[1][1] * v0 + m->transform[1][2];
        double w = texture->levels[0].width, h = texture->levels[0].height;
        /* The footprint of the pixel's unit steps, in level-0 texels. */
        double xu = (m->transform[0][0] * duv[0] + m->transform[0][1] * duv[1]) * w;
        double xv = (m->transform[1][0] * duv[0] + m->transform[1][1] * duv[1]) * h;
        double yu = (m->transform[0][0] * duv[2] + m->transform[0][1] * duv[3]) * w;
        double yv = (m->transform[1][0] * duv[2] + m->transform[1][1] * duv[3]) * h;
        double rho2 = fmax(xu * xu + xv * xv, yu * yu + yv * yv);
        double lod = rho2 > 0 ? 0.5 * log2(rho2) : 0;
        cg_texture_sampler sampler = {f->o->texture_filter, m->wrap_u, m->wrap_v};
        cg_rgbaf texel = cg_texture_sample(texture, &sampler, u, t, lod);
        base[0] *= texel.r;
        base[1] *= texel.g;
        base[2] *= texel.b;
        alpha *= texel.a;
    }
    if (alpha_out)
        *alpha_out = alpha; /* the caller decides */
    else if (m && alpha < m->alpha_cutoff)
        return 0; /* glTF alphaMode MASK */
    if (f->o->shading == CG_SHADING_UNLIT) {
        out[0] = base[0];
        out[1] = base[1];
        out[2] = base[2];
        return 1;
    }
    float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    float inv = len > 0 ? 1 / len : 0;
    float normal[3] = {v[0] * inv, v[1] * inv, v[2] * inv};
    render_shade(&f->lighting, v + 3, normal, base, out);
    return 1;
}
