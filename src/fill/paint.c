/* Paints and compositing: solid colours and gradients, blended source-over
 * in linear light onto RGBA8 (sRGB-encoded) or RGBAF images. */
#include "internal.h"
#include "cg/color.h"

#include <stdlib.h>
#include <string.h>

int fill_reserve_grow(void **array, size_t *capacity, size_t need, size_t size)
{
    if (need <= *capacity)
        return 1;
    size_t grown = *capacity ? *capacity : 64;
    while (grown < need) {
        if (grown > ((size_t)-1 / 2) / size)
            return 0;
        grown *= 2;
    }
    void *p = realloc(*array, grown * size);
    if (!p)
        return 0;
    *array = p;
    *capacity = grown;
    return 1;
}

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
            c = cg_rgba8_to_linear(paint->stops[0].color);
        } else if (s == n) {
            c = cg_rgba8_to_linear(paint->stops[n - 1].color);
        } else {
            cg_rgbaf a = cg_rgba8_to_linear(paint->stops[s - 1].color);
            cg_rgbaf b = cg_rgba8_to_linear(paint->stops[s].color);
            double span = paint->stops[s].offset - paint->stops[s - 1].offset;
            float u = span > 0 ? (float)((t - paint->stops[s - 1].offset) / span) : 1.0f;
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
    if (paint->type == CG_PAINT_SOLID) {
        cg_rgbaf c = cg_rgba8_to_linear(paint->color);
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
        return build_ramp(p, paint);
    }
    return CG_EINVAL;
}

uint32_t fill_solid_miss(const fill_blend_state *s, uint32_t v, int c, uint64_t key,
                         uint32_t slot)
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
        double px = x0 + i + 0.5, u;
        if (p->type == CG_PAINT_LINEAR) {
            u = p->gx * px + p->gy * py + p->gc;
        } else {
            double dx = px - p->cx, dy = py - p->cy;
            u = sqrt(dx * dx + dy * dy) * p->inv_radius;
        }
        const cg_rgbaf *s = ramp_at(p, u);
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
    if (p->type == CG_PAINT_SOLID)
        solid_span(p, y, x0, n, cover);
    else
        gradient_span(p, y, x0, n, cover);
}
