/* Texture sampling: nearest, bilinear and trilinear filtering with the
 * three wrap modes.
 *
 *        u w - 0.5 = x          texels i0 = floor(x), i0 + 1 (wrapped)
 *   ... |  i0  |  i0+1 | ...    weights 1 - fx, fx with fx = x - i0
 *          *   ^    *           (* texel centres, ^ the sample)
 *
 * Rows run top to bottom while v runs bottom to top: y = (1 - v) h - 0.5. */
#include "cg/texture.h"

#include <math.h>

int cg_texture_wrap_index(long long i, int n, cg_texture_wrap wrap)
{
    if (n <= 1)
        return 0;
    if (wrap == CG_TEXTURE_CLAMP)
        return i < 0 ? 0 : i >= n ? n - 1 : (int)i;
    if (wrap == CG_TEXTURE_MIRRORED_REPEAT) {
        long long period = 2LL * n, k = ((i % period) + period) % period;
        return (int)(k < n ? k : period - 1 - k);
    }
    return (int)(((i % n) + n) % n);
}

/* A coordinate brought into one period of its wrap mode, so that scaling
 * it by the texture's size cannot overflow; the wrapped texels are the same. */
static double reduce(double t, cg_texture_wrap wrap)
{
    if (!isfinite(t))
        return 0;
    if (wrap == CG_TEXTURE_CLAMP)
        return t < -1 ? -1 : t > 2 ? 2 : t;
    double period = wrap == CG_TEXTURE_MIRRORED_REPEAT ? 2 : 1;
    return t - period * floor(t / period);
}

static cg_rgbaf at(const cg_texture_level *level, int x, int y)
{
    return level->texels[(size_t)y * (size_t)level->width + (size_t)x];
}

static cg_rgbaf nearest(const cg_texture_level *level, const cg_texture_sampler *s, double u,
                        double v)
{
    long long x = (long long)floor(u * level->width), y = (long long)floor((1 - v) * level->height);
    return at(level, cg_texture_wrap_index(x, level->width, s->wrap_u),
              cg_texture_wrap_index(y, level->height, s->wrap_v));
}

static cg_rgbaf bilinear(const cg_texture_level *level, const cg_texture_sampler *s, double u,
                         double v)
{
    double x = u * level->width - 0.5, y = (1 - v) * level->height - 0.5;
    double x0 = floor(x), y0 = floor(y);
    float fx = (float)(x - x0), fy = (float)(y - y0);
    int xa = cg_texture_wrap_index((long long)x0, level->width, s->wrap_u);
    int xb = cg_texture_wrap_index((long long)x0 + 1, level->width, s->wrap_u);
    int ya = cg_texture_wrap_index((long long)y0, level->height, s->wrap_v);
    int yb = cg_texture_wrap_index((long long)y0 + 1, level->height, s->wrap_v);
    cg_rgbaf t00 = at(level, xa, ya), t10 = at(level, xb, ya), t01 = at(level, xa, yb),
             t11 = at(level, xb, yb);
    float w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
    cg_rgbaf r = {w00 * t00.r + w10 * t10.r + w01 * t01.r + w11 * t11.r,
                  w00 * t00.g + w10 * t10.g + w01 * t01.g + w11 * t11.g,
                  w00 * t00.b + w10 * t10.b + w01 * t01.b + w11 * t11.b,
                  w00 * t00.a + w10 * t10.a + w01 * t01.a + w11 * t11.a};
    return r;
}

cg_rgbaf cg_texture_sample(const cg_texture *texture, const cg_texture_sampler *sampler, double u,
                           double v, double lod)
{
    cg_rgbaf r = {0, 0, 0, 0};
    if (!texture || !sampler || texture->level_count < 1)
        return r;
    u = reduce(u, sampler->wrap_u);
    v = reduce(v, sampler->wrap_v);
    if (sampler->filter == CG_TEXTURE_NEAREST) {
        r = nearest(&texture->levels[0], sampler, u, v);
    } else if (sampler->filter == CG_TEXTURE_BILINEAR) {
        r = bilinear(&texture->levels[0], sampler, u, v);
    } else {
        double top = texture->level_count - 1;
        lod = !isfinite(lod) || lod < 0 ? 0 : lod > top ? top : lod;
        int k = (int)floor(lod);
        float f = (float)(lod - k);
        r = bilinear(&texture->levels[k], sampler, u, v);
        if (f > 0 && k + 1 < texture->level_count) {
            cg_rgbaf next = bilinear(&texture->levels[k + 1], sampler, u, v);
            r.r += f * (next.r - r.r);
            r.g += f * (next.g - r.g);
            r.b += f * (next.b - r.b);
            r.a += f * (next.a - r.a);
        }
    }
    if (texture->encoding == CG_TEXTURE_SRGB) { /* back to straight alpha */
        if (r.a > 0) {
            r.r /= r.a;
            r.g /= r.a;
            r.b /= r.a;
        } else {
            r.r = r.g = r.b = 0;
        }
    }
    return r;
}
