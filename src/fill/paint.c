/* Paints: solid colours and gradients (linear, radial with a focal point,
 * spread methods, a transform), and their fast source-over in linear light
 * onto RGBA8 (sRGB-encoded) or RGBAF images; other compositing goes
 * through composite.c. */
#include "internal.h"
#include "cg/color.h"

#include <stdlib.h>
#include <string.h>

cg_paint cg_paint_solid(cg_rgba8 color)
{
    cg_paint p;
    memset(&p, 0, sizeof p);
    p.type = CG_PAINT_SOLID;
    p.color = color;
    return p;
}

cg_paint cg_paint_linear(cg_vec2 p0, cg_vec2 p1, const cg_gradient_stop *stops, int stop_count)
{
    cg_paint p;
    memset(&p, 0, sizeof p);
    p.type = CG_PAINT_LINEAR;
    p.p0 = p0;
    p.p1 = p1;
    p.stops = stops;
    p.stop_count = stop_count;
    return p;
}

cg_paint cg_paint_radial(cg_vec2 center, double radius, const cg_gradient_stop *stops,
                         int stop_count)
{
    cg_paint p;
    memset(&p, 0, sizeof p);
    p.type = CG_PAINT_RADIAL;
    p.p0 = center;
    p.radius = radius;
    p.stops = stops;
    p.stop_count = stop_count;
    return p;
}

static int finite_vec(cg_vec2 v)
{
    return isfinite(v.x) && isfinite(v.y) && fabs(v.x) <= CG_FILL_MAX_COORD
           && fabs(v.y) <= CG_FILL_MAX_COORD;
}

/* The 256-entry colour ramp of a gradient: stops interpolated in linear
 * light with premultiplied alpha, stored straight. */
/* A stop's colour as the ramp holds it: linear light, or the encoded
 * values in [0, 1] for the sRGB space. */
static cg_rgbaf stop_color(const fill_painter *p, cg_rgba8 color)
{
    if (p->space != CG_COMPOSITE_SRGB)
        return cg_rgba8_to_linear(color);
    cg_rgbaf c = {color.r / 255.0f, color.g / 255.0f, color.b / 255.0f, color.a / 255.0f};
    return c;
}

/* In the sRGB space the stops mix with straight alpha, as SVG renderers
 * mix them. */
static cg_rgbaf mix_straight(cg_rgbaf a, cg_rgbaf b, float u)
{
    cg_rgbaf c = {a.r + (b.r - a.r) * u, a.g + (b.g - a.g) * u, a.b + (b.b - a.b) * u,
                  a.a + (b.a - a.a) * u};
    return c;
}

static cg_status build_ramp(fill_painter *p, const cg_paint *paint)
{
    if (!paint->stops || paint->stop_count < 1)
        return CG_EINVAL;
    for (int i = 0; i < paint->stop_count; i++) {
        double o = paint->stops[i].offset;
        if (!(o >= 0 && o <= 1) || (i > 0 && o < paint->stops[i - 1].offset))
            return CG_EINVAL;
    }
    int n = paint->stop_count, s = 0;
    for (int i = 0; i < 256; i++) {
        double t = i / 255.0;
        while (s < n && paint->stops[s].offset <= t)
            s++;
        /* stops[s-1].offset <= t < stops[s].offset */
        cg_rgbaf c;
        if (s == 0) {
            c = stop_color(p, paint->stops[0].color);
        } else if (s == n) {
            c = stop_color(p, paint->stops[n - 1].color);
        } else {
            cg_rgbaf a = stop_color(p, paint->stops[s - 1].color);
            cg_rgbaf b = stop_color(p, paint->stops[s].color);
            double span = paint->stops[s].offset - paint->stops[s - 1].offset;
            float u = span > 0 ? (float)((t - paint->stops[s - 1].offset) / span) : 1.0f;
            if (p->space == CG_COMPOSITE_SRGB) {
                p->ramp[i] = mix_straight(a, b, u);
                continue;
            }
            float alpha = a.a + (b.a - a.a) * u;
            c.a = alpha;
            if (alpha > 0) {
                c.r = (a.r * a.a + (b.r * b.a - a.r * a.a) * u) / alpha;
                c.g = (a.g * a.a + (b.g * b.a - a.g * a.a) * u) / alpha;
                c.b = (a.b * a.a + (b.b * b.a - a.b * a.a) * u) / alpha;
            } else {
                c.r = c.g = c.b = 0;
            }
        }
        p->ramp[i] = c;
    }
    return CG_OK;
}

cg_status fill_painter_init(fill_painter *p, struct cg_rasterizer *r, cg_image *image,
                            const cg_paint *paint)
{
    if (!paint)
        return CG_EINVAL;
    /* Field by field: the ramp (4 KiB) is only written for gradients. */
    p->r = p->g = p->b = p->a = 0;
    p->encoded = 0;
    p->opaque = 0;
    p->same_exact = 0;
    p->gx = p->gy = p->gc = 0;
    p->cx = p->cy = p->inv_radius = 0;
    p->image = image;
    p->cache = r;
    p->type = paint->type;
    p->space = r->space;
    p->op = r->op;
    p->mode = r->mode;
    p->general = r->space != CG_COMPOSITE_LINEAR || r->op != CG_OPERATOR_OVER
                 || r->mode != CG_BLEND_NORMAL;
    p->spread = CG_SPREAD_PAD;
    p->focal = 0;
    p->transformed = 0;
    if (paint->type == CG_PAINT_SOLID) {
        cg_rgbaf c = cg_rgba8_to_linear(paint->color);
        p->space_color = stop_color(p, paint->color);
        p->r = c.r;
        p->g = c.g;
        p->b = c.b;
        p->a = c.a;
        memcpy(&p->encoded, &paint->color, sizeof p->encoded);
        memcpy(p->encoded_rgba, &paint->color, sizeof p->encoded_rgba);
        p->opaque = paint->color.a == 255;
        p->same_exact = color_srgb_decode_table[paint->color.r] == p->r
                        && color_srgb_decode_table[paint->color.g] == p->g
                        && color_srgb_decode_table[paint->color.b] == p->b;
        if (r->blend_gen == 0 || r->blend_src != p->encoded) {
            r->blend_src = p->encoded;
            fill_next_generation(r);
        }
        return CG_OK;
    }
    if (paint->type != CG_PAINT_LINEAR && paint->type != CG_PAINT_RADIAL)
        return CG_EINVAL;
    if ((unsigned)paint->spread > CG_SPREAD_REPEAT)
        return CG_EINVAL;
    p->spread = paint->spread;
    if (paint->has_transform) {
        for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++)
                if (!isfinite(paint->transform.m[i][k]))
                    return CG_EINVAL;
        if (cg_mat3_inverse(paint->transform, &p->inverse) != CG_OK)
            return CG_EINVAL;
        p->transformed = 1;
    }
    if (paint->type == CG_PAINT_LINEAR) {
        if (!finite_vec(paint->p0) || !finite_vec(paint->p1))
            return CG_EINVAL;
        double dx = paint->p1.x - paint->p0.x, dy = paint->p1.y - paint->p0.y;
        double len2 = dx * dx + dy * dy;
        if (len2 > 0) {
            p->gx = dx / len2;
            p->gy = dy / len2;
        }
        p->gc = -(paint->p0.x * p->gx + paint->p0.y * p->gy);
        return build_ramp(p, paint);
    }
    if (paint->type == CG_PAINT_RADIAL) {
        if (!finite_vec(paint->p0) || !(paint->radius > 0) || !isfinite(paint->radius))
            return CG_EINVAL;
        p->cx = paint->p0.x;
        p->cy = paint->p0.y;
        p->inv_radius = 1.0 / paint->radius;
        p->radius = paint->radius;
        if (paint->has_focal) {
            if (!finite_vec(paint->focal))
                return CG_EINVAL;
            /* a focal point on or beyond the circle moves just inside it */
            double fx = paint->focal.x - p->cx, fy = paint->focal.y - p->cy;
            double d = sqrt(fx * fx + fy * fy), limit = paint->radius * 0.999;
            if (d > limit) {
                fx *= limit / d;
                fy *= limit / d;
            }
            p->focal = d > 0;
            p->fx = p->cx + fx;
            p->fy = p->cy + fy;
        }
        return build_ramp(p, paint);
    }
    return CG_EINVAL;
}

uint32_t fill_solid_miss(const fill_blend_state *s, uint32_t v, int c, uint64_t key, uint32_t slot)
{
    cg_rgba8 px;
    memcpy(&px, &v, sizeof px);
    fill_solid_pixel(s->p, &px, c);
    memcpy(&v, &px, sizeof v);
    s->keys[slot] = key;
    s->values[slot] = v;
    return v;
}

void fill_solid_run(const fill_painter *p, uint32_t *d, int n, const uint8_t *cover, int constant)
{
    fill_blend_state s = fill_blend_begin(p);
    if (cover)
        for (int i = 0; i < n; i++)
            fill_solid_cached(&s, d + i, cover[i]);
    else
        for (int i = 0; i < n; i++)
            fill_solid_cached(&s, d + i, constant);
}

static inline void blendf(cg_rgbaf *d, float r, float g, float b, float as)
{
    float ad = d->a * (1 - as), a = as + ad;
    if (a <= 0) {
        d->r = d->g = d->b = d->a = 0;
        return;
    }
    float inv = 1 / a;
    d->r = (r * as + d->r * ad) * inv;
    d->g = (g * as + d->g * ad) * inv;
    d->b = (b * as + d->b * ad) * inv;
    d->a = a;
}

static inline const cg_rgbaf *ramp_at(const fill_painter *p, double t)
{
    int i;
    if (!(t > 0))
        i = 0;
    else if (t >= 1)
        i = 255;
    else
        i = (int)(t * 255.0 + 0.5);
    return &p->ramp[i];
}

/* The spread method applied to t. */
static double spread_t(int spread, double t)
{
    if (spread == CG_SPREAD_REPEAT)
        return t - floor(t);
    if (spread == CG_SPREAD_REFLECT) {
        double m = t - 2 * floor(t * 0.5); /* in [0, 2) */
        return m > 1 ? 2 - m : m;
    }
    return t;
}

/* Radial from a focal point f inside the circle (c, r): the ray from f
 * through the point q meets the circle at f + s (q - f), s > 0 the root of
 * |s d - e|^2 = r^2 with d = q - f and e = c - f; t = 1 / s.
 *
 *            . - - - .            circle (c, r)
 *          /     c     \
 *         |   f ---q----x         x = f + s (q - f)
 *          \           /
 *            ` - - - '            t = |q - f| / |x - f| */
static double focal_t(const fill_painter *p, double x, double y)
{
    double dx = x - p->fx, dy = y - p->fy, ex = p->cx - p->fx, ey = p->cy - p->fy;
    double dd = dx * dx + dy * dy, de = dx * ex + dy * ey;
    if (dd == 0)
        return 0;
    double disc = de * de - dd * (ex * ex + ey * ey - p->radius * p->radius);
    double denominator = de + sqrt(disc > 0 ? disc : 0);
    return denominator > 0 ? dd / denominator : 1;
}

const cg_rgbaf *fill_gradient_at(const fill_painter *p, double px, double py)
{
    if (p->transformed) {
        const double(*m)[3] = p->inverse.m;
        double x = m[0][0] * px + m[0][1] * py + m[0][2];
        py = m[1][0] * px + m[1][1] * py + m[1][2];
        px = x;
    }
    double u;
    if (p->type == CG_PAINT_LINEAR) {
        u = p->gx * px + p->gy * py + p->gc;
    } else if (p->focal) {
        u = focal_t(p, px, py);
    } else {
        double dx = px - p->cx, dy = py - p->cy;
        u = sqrt(dx * dx + dy * dy) * p->inv_radius;
    }
    if (p->spread != CG_SPREAD_PAD && isfinite(u))
        u = spread_t(p->spread, u);
    return ramp_at(p, u);
}

static void solid_span(const fill_painter *p, int y, int x0, int n, const uint8_t *cover)
{
    cg_image *image = p->image;
    if (image->format == CG_PIXEL_RGBA8) {
        cg_rgba8 *row = cg_image_row_rgba8(image, y) + x0;
        if (!cover && p->opaque) {
            fill_store32((uint32_t *)row, n, p->encoded);
            return;
        }
        fill_solid_run(p, (uint32_t *)row, n, cover, 255);
        return;
    }
    cg_rgbaf *row = cg_image_row_rgbaf(image, y) + x0;
    for (int i = 0; i < n; i++) {
        int c = cover ? cover[i] : 255;
        if (c == 0)
            continue;
        float as = p->a * (c * (1.0f / 255.0f));
        if (as >= 1) {
            cg_rgbaf v = {p->r, p->g, p->b, 1};
            row[i] = v;
        } else {
            blendf(&row[i], p->r, p->g, p->b, as);
        }
    }
}

static void gradient_span(const fill_painter *p, int y, int x0, int n, const uint8_t *cover)
{
    cg_image *image = p->image;
    double py = y + 0.5;
    for (int i = 0; i < n; i++) {
        int c = cover ? cover[i] : 255;
        if (c == 0)
            continue;
        const cg_rgbaf *s = fill_gradient_at(p, x0 + i + 0.5, py);
        float as = s->a * (c * (1.0f / 255.0f));
        if (image->format == CG_PIXEL_RGBA8) {
            cg_rgba8 *d = cg_image_row_rgba8(image, y) + x0 + i;
            if (as >= 1) {
                d->r = cg_srgb_encode_unit(s->r);
                d->g = cg_srgb_encode_unit(s->g);
                d->b = cg_srgb_encode_unit(s->b);
                d->a = 255;
            } else {
                fill_blend8(d, s->r, s->g, s->b, as);
            }
        } else {
            cg_rgbaf *d = cg_image_row_rgbaf(image, y) + x0 + i;
            if (as >= 1) {
                cg_rgbaf v = {s->r, s->g, s->b, 1};
                *d = v;
            } else {
                blendf(d, s->r, s->g, s->b, as);
            }
        }
    }
}

void fill_painter_span(const fill_painter *p, int y, int x0, int n, const uint8_t *cover)
{
    if (n <= 0)
        return;
    if (p->general)
        fill_general_span(p, y, x0, n, cover);
    else if (p->type == CG_PAINT_SOLID)
        solid_span(p, y, x0, n, cover);
    else
        gradient_span(p, y, x0, n, cover);
}
