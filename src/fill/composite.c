/* Compositing: the Porter-Duff operators and the blend modes of the W3C
 * Compositing and Blending spec, on one pixel (cg_composite) and along a span
 * of a drawing in either compositing space (fill_general_span).
 *
 * The general formula (Compositing and Blending, "the general formula for
 * compositing and blending"): the source colour is first mixed with the
 * blend result where the backdrop is opaque,
 *     cs' = (1 - ab) * Cs + ab * B(Cb, Cs)            (straight colours)
 * then the operator weighs source and backdrop,
 *     co = as * cs' * Fa + ab * Cb * Fb,  ao = as * Fa + ab * Fb. */
#include "internal.h"
#include "cg/color.h"

#include <string.h>

/* ---- blend functions on straight colours in [0, 1] ------------------------- */

static float hard_light(float cb, float cs)
{
    if (cs <= 0.5f)
        return cb * 2 * cs; /* multiply(cb, 2 cs) */
    float s = 2 * cs - 1;
    return cb + s - cb * s; /* screen(cb, 2 cs - 1) */
}

static float soft_light(float cb, float cs)
{
    if (cs <= 0.5f)
        return cb - (1 - 2 * cs) * cb * (1 - cb);
    float d = cb <= 0.25f ? ((16 * cb - 12) * cb + 4) * cb : sqrtf(cb);
    return cb + (2 * cs - 1) * (d - cb);
}

static float separable(cg_blend_mode mode, float cb, float cs)
{
    switch (mode) {
    case CG_BLEND_MULTIPLY: return cb * cs;
    case CG_BLEND_SCREEN: return cb + cs - cb * cs;
    case CG_BLEND_OVERLAY: return hard_light(cs, cb);
    case CG_BLEND_DARKEN: return cb < cs ? cb : cs;
    case CG_BLEND_LIGHTEN: return cb > cs ? cb : cs;
    case CG_BLEND_COLOR_DODGE:
        if (cb <= 0)
            return 0;
        if (cs >= 1)
            return 1;
        return fminf(1, cb / (1 - cs));
    case CG_BLEND_COLOR_BURN:
        if (cb >= 1)
            return 1;
        if (cs <= 0)
            return 0;
        return 1 - fminf(1, (1 - cb) / cs);
    case CG_BLEND_HARD_LIGHT: return hard_light(cb, cs);
    case CG_BLEND_SOFT_LIGHT: return soft_light(cb, cs);
    case CG_BLEND_DIFFERENCE: return fabsf(cb - cs);
    case CG_BLEND_EXCLUSION: return cb + cs - 2 * cb * cs;
    default: return cs;
    }
}

/* The non-separable modes work on the colour as a whole: its luminosity
 * (the spec's weights 0.3, 0.59, 0.11) and saturation (max - min). */
static float lum(const float *c)
{
    return 0.3f * c[0] + 0.59f * c[1] + 0.11f * c[2];
}

static void clip_color(float *c)
{
    float l = lum(c), n = fminf(c[0], fminf(c[1], c[2])), x = fmaxf(c[0], fmaxf(c[1], c[2]));
    for (int i = 0; i < 3; i++) {
        if (n < 0 && l - n > 0)
            c[i] = l + (c[i] - l) * l / (l - n);
        if (x > 1 && x - l > 0)
            c[i] = l + (c[i] - l) * (1 - l) / (x - l);
    }
}

static void set_lum(float *c, float l)
{
    float d = l - lum(c);
    for (int i = 0; i < 3; i++)
        c[i] += d;
    clip_color(c);
}

static float sat(const float *c)
{
    return fmaxf(c[0], fmaxf(c[1], c[2])) - fminf(c[0], fminf(c[1], c[2]));
}

/* The spec's SetSat: the largest component becomes s, the smallest 0, the
 * middle one keeps its place between them. */
static void set_sat(float *c, float s)
{
    int hi = 0, lo = 0;
    for (int i = 1; i < 3; i++) {
        if (c[i] > c[hi])
            hi = i;
        if (c[i] < c[lo])
            lo = i;
    }
    if (hi == lo) { /* all equal */
        c[0] = c[1] = c[2] = 0;
        return;
    }
    int mid = 3 - hi - lo;
    float range = c[hi] - c[lo];
    c[mid] = (c[mid] - c[lo]) * s / range;
    c[hi] = s;
    c[lo] = 0;
}

/* B(cb, cs) for all three channels into out. */
static void blend_colors(cg_blend_mode mode, const float *cb, const float *cs, float *out)
{
    if (mode < CG_BLEND_HUE) {
        for (int i = 0; i < 3; i++)
            out[i] = separable(mode, cb[i], cs[i]);
        return;
    }
    switch (mode) {
    case CG_BLEND_HUE:
        memcpy(out, cs, 3 * sizeof *out);
        set_sat(out, sat(cb));
        set_lum(out, lum(cb));
        break;
    case CG_BLEND_SATURATION:
        memcpy(out, cb, 3 * sizeof *out);
        set_sat(out, sat(cs));
        set_lum(out, lum(cb));
        break;
    case CG_BLEND_COLOR:
        memcpy(out, cs, 3 * sizeof *out);
        set_lum(out, lum(cb));
        break;
    default: /* luminosity */
        memcpy(out, cb, 3 * sizeof *out);
        set_lum(out, lum(cs));
        break;
    }
}

/* ---- one pixel ----------------------------------------------------------------- */

static void operator_factors(cg_composite_operator op, float as, float ab, float *fa, float *fb)
{
    switch (op) {
    case CG_OPERATOR_CLEAR:
        *fa = 0;
        *fb = 0;
        break;
    case CG_OPERATOR_SOURCE:
        *fa = 1;
        *fb = 0;
        break;
    case CG_OPERATOR_DESTINATION:
        *fa = 0;
        *fb = 1;
        break;
    case CG_OPERATOR_DESTINATION_OVER:
        *fa = 1 - ab;
        *fb = 1;
        break;
    case CG_OPERATOR_IN:
        *fa = ab;
        *fb = 0;
        break;
    case CG_OPERATOR_DESTINATION_IN:
        *fa = 0;
        *fb = as;
        break;
    case CG_OPERATOR_OUT:
        *fa = 1 - ab;
        *fb = 0;
        break;
    case CG_OPERATOR_DESTINATION_OUT:
        *fa = 0;
        *fb = 1 - as;
        break;
    case CG_OPERATOR_ATOP:
        *fa = ab;
        *fb = 1 - as;
        break;
    case CG_OPERATOR_DESTINATION_ATOP:
        *fa = 1 - ab;
        *fb = as;
        break;
    case CG_OPERATOR_XOR:
        *fa = 1 - ab;
        *fb = 1 - as;
        break;
    case CG_OPERATOR_PLUS:
        *fa = 1;
        *fb = 1;
        break;
    default:
        *fa = 1;
        *fb = 1 - as;
        break; /* over */
    }
}

cg_rgbaf cg_composite(cg_rgbaf source, cg_rgbaf backdrop, cg_composite_operator op,
                      cg_blend_mode mode)
{
    float as = source.a, ab = backdrop.a;
    float cs[3] = {source.r, source.g, source.b}; /* premultiplied for now */
    const float cb[3] = {backdrop.r, backdrop.g, backdrop.b};
    if (mode != CG_BLEND_NORMAL && as > 0 && ab > 0) {
        /* straight colours for B, then back to premultiplied:
         * as * cs' = (1 - ab) * as * Cs + as * ab * B(Cb, Cs) */
        float s[3], b[3], mixed[3];
        for (int i = 0; i < 3; i++) {
            s[i] = cs[i] / as;
            b[i] = cb[i] / ab;
        }
        blend_colors(mode, b, s, mixed);
        for (int i = 0; i < 3; i++)
            cs[i] = (1 - ab) * cs[i] + as * ab * mixed[i];
    }
    float fa, fb;
    operator_factors(op, as, ab, &fa, &fb);
    cg_rgbaf out = {cs[0] * fa + cb[0] * fb, cs[1] * fa + cb[1] * fb, cs[2] * fa + cb[2] * fb,
                    as * fa + ab * fb};
    if (op == CG_OPERATOR_PLUS) {
        out.r = fminf(out.r, 1);
        out.g = fminf(out.g, 1);
        out.b = fminf(out.b, 1);
        out.a = fminf(out.a, 1);
    }
    return out;
}

/* ---- names ------------------------------------------------------------------------ */

static const char *const operator_names[CG_OPERATOR_COUNT] = {"over",
                                                              "clear",
                                                              "source",
                                                              "destination",
                                                              "destination-over",
                                                              "in",
                                                              "destination-in",
                                                              "out",
                                                              "destination-out",
                                                              "atop",
                                                              "destination-atop",
                                                              "xor",
                                                              "plus"};

static const char *const blend_names[CG_BLEND_COUNT] = {
    "normal",      "multiply",   "screen",     "overlay",    "darken",     "lighten",
    "color-dodge", "color-burn", "hard-light", "soft-light", "difference", "exclusion",
    "hue",         "saturation", "color",      "luminosity"};

const char *cg_composite_operator_name(cg_composite_operator op)
{
    return (unsigned)op < CG_OPERATOR_COUNT ? operator_names[op] : NULL;
}

const char *cg_blend_mode_name(cg_blend_mode mode)
{
    return (unsigned)mode < CG_BLEND_COUNT ? blend_names[mode] : NULL;
}

cg_status cg_composite_operator_parse(const char *name, cg_composite_operator *out)
{
    if (!name || !out)
        return CG_EINVAL;
    static const struct {
        const char *alias;
        cg_composite_operator op;
    } aliases[] = {{"source-over", CG_OPERATOR_OVER}, {"copy", CG_OPERATOR_SOURCE},
                   {"source-in", CG_OPERATOR_IN},     {"source-out", CG_OPERATOR_OUT},
                   {"source-atop", CG_OPERATOR_ATOP}, {"lighter", CG_OPERATOR_PLUS},
                   {"plus-lighter", CG_OPERATOR_PLUS}};
    for (int i = 0; i < CG_OPERATOR_COUNT; i++)
        if (strcmp(name, operator_names[i]) == 0) {
            *out = (cg_composite_operator)i;
            return CG_OK;
        }
    for (size_t i = 0; i < sizeof aliases / sizeof *aliases; i++)
        if (strcmp(name, aliases[i].alias) == 0) {
            *out = aliases[i].op;
            return CG_OK;
        }
    return CG_EINVAL;
}

cg_status cg_blend_mode_parse(const char *name, cg_blend_mode *out)
{
    if (!name || !out)
        return CG_EINVAL;
    for (int i = 0; i < CG_BLEND_COUNT; i++)
        if (strcmp(name, blend_names[i]) == 0) {
            *out = (cg_blend_mode)i;
            return CG_OK;
        }
    return CG_EINVAL;
}

cg_status cg_rasterizer_set_compositing(cg_rasterizer *r, cg_compositing_space space,
                                        cg_composite_operator op, cg_blend_mode mode)
{
    if (!r || (space != CG_COMPOSITE_LINEAR && space != CG_COMPOSITE_SRGB)
        || (unsigned)op >= CG_OPERATOR_COUNT || (unsigned)mode >= CG_BLEND_COUNT)
        return CG_EINVAL;
    r->space = space;
    r->op = op;
    r->mode = mode;
    return CG_OK;
}

/* ---- pixels in a compositing space ------------------------------------------------ */

/* k * composite(source, backdrop) + (1 - k) * backdrop: the operator within
 * the shape's coverage k. */
cg_rgbaf fill_composite_covered(cg_rgbaf source, cg_rgbaf backdrop, cg_composite_operator op,
                                cg_blend_mode mode, float k)
{
    if (op == CG_OPERATOR_OVER && mode == CG_BLEND_NORMAL) {
        /* the same, with k folded into the source */
        float f = 1 - source.a * k;
        cg_rgbaf out = {source.r * k + backdrop.r * f, source.g * k + backdrop.g * f,
                        source.b * k + backdrop.b * f, source.a * k + backdrop.a * f};
        return out;
    }
    cg_rgbaf full = cg_composite(source, backdrop, op, mode);
    if (k >= 1)
        return full;
    cg_rgbaf out = {backdrop.r + (full.r - backdrop.r) * k, backdrop.g + (full.g - backdrop.g) * k,
                    backdrop.b + (full.b - backdrop.b) * k, backdrop.a + (full.a - backdrop.a) * k};
    return out;
}

void fill_composite_pixel8(cg_rgba8 *d, cg_rgbaf source, cg_compositing_space space,
                           cg_composite_operator op, cg_blend_mode mode, float k)
{
    cg_rgbaf b = fill_load_pixel8(*d, space);
    *d = fill_store_pixel8(fill_composite_covered(source, b, op, mode, k), space);
}

void fill_composite_pixelf(cg_rgbaf *d, cg_rgbaf source, cg_compositing_space space,
                           cg_composite_operator op, cg_blend_mode mode, float k)
{
    cg_rgbaf b = fill_load_pixelf(*d, space);
    *d = fill_store_pixelf(fill_composite_covered(source, b, op, mode, k), space);
}

/* The general span's common case: source-over, normal, in the sRGB space,
 * onto RGBA8 (fill_srgb_over); an opaque solid paint fills full coverage
 * by stores. */
static void srgb_over_span(const fill_painter *p, int y, int x0, int n, const uint8_t *cover)
{
    cg_rgba8 *row = cg_image_row_rgba8(p->image, y) + x0;
    if (p->type == CG_PAINT_SOLID) {
        float sr = p->space_color.r * 255, sg = p->space_color.g * 255;
        float sb = p->space_color.b * 255, alpha = p->space_color.a;
        if (!cover && p->opaque) {
            fill_store32((uint32_t *)row, n, p->encoded);
            return;
        }
        for (int i = 0; i < n; i++) {
            int c = cover ? cover[i] : 255;
            if (c == 255 && p->opaque)
                memcpy(&row[i], &p->encoded, sizeof row[i]);
            else if (c)
                fill_srgb_over(&row[i], sr, sg, sb, alpha * (c * (1.0f / 255.0f)));
        }
        return;
    }
    for (int i = 0; i < n; i++) {
        int c = cover ? cover[i] : 255;
        if (c == 0)
            continue;
        const cg_rgbaf *s = fill_gradient_at(p, x0 + i + 0.5, y + 0.5);
        fill_srgb_over(&row[i], s->r * 255, s->g * 255, s->b * 255, s->a * (c * (1.0f / 255.0f)));
    }
}

void fill_general_span(const fill_painter *p, int y, int x0, int n, const uint8_t *cover)
{
    cg_image *image = p->image;
    if (p->space == CG_COMPOSITE_SRGB && p->op == CG_OPERATOR_OVER && p->mode == CG_BLEND_NORMAL
        && image->format == CG_PIXEL_RGBA8) {
        srgb_over_span(p, y, x0, n, cover);
        return;
    }
    cg_compositing_space space = (cg_compositing_space)p->space;
    cg_composite_operator op = (cg_composite_operator)p->op;
    cg_blend_mode mode = (cg_blend_mode)p->mode;
    for (int i = 0; i < n; i++) {
        int c = cover ? cover[i] : 255;
        if (c == 0)
            continue;
        cg_rgbaf s; /* straight, in the space */
        if (p->type == CG_PAINT_SOLID) {
            s = p->space_color;
        } else {
            s = *fill_gradient_at(p, x0 + i + 0.5, y + 0.5);
        }
        cg_rgbaf source = {s.r * s.a, s.g * s.a, s.b * s.a, s.a};
        float k = c * (1.0f / 255.0f);
        if (image->format == CG_PIXEL_RGBA8)
            fill_composite_pixel8(cg_image_row_rgba8(image, y) + x0 + i, source, space, op, mode,
                                  k);
        else
            fill_composite_pixelf(cg_image_row_rgbaf(image, y) + x0 + i, source, space, op, mode,
                                  k);
    }
}
