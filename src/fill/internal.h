/* Private pieces shared by the fill module's files. */
#ifndef CG_FILL_INTERNAL_H
#define CG_FILL_INTERNAL_H

#include "cg/fill.h"
#include "../color/srgb_tables.h"
#include "../core/array.h"
#include "../core/simd4.h"
#include "cg/color.h"

#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <wchar.h>

/* ---- growing arrays of points ------------------------------------------- */

/* A set of polylines: points of all of them in one array, and for each its
 * first point, point count and whether it is closed. */
typedef struct fill_polyline {
    size_t start, count;
    int closed;
} fill_polyline;

typedef struct fill_polylines {
    cg_vec2 *points;
    size_t point_count, point_capacity;
    fill_polyline *lines;
    size_t line_count, line_capacity;
} fill_polylines;

void fill_polylines_reset(fill_polylines *set);
void fill_polylines_free(fill_polylines *set);
/* Starts a new polyline. */
cg_status fill_polylines_begin(fill_polylines *set);
/* Appends a point to the current polyline. */
cg_status fill_polylines_add(fill_polylines *set, cg_vec2 p);
/* Marks the current polyline closed. */
void fill_polylines_close(fill_polylines *set);

/* A path's state, saved so that a failed parse can undo what it appended. */
typedef struct fill_path_mark {
    size_t verb_count, coord_count, drawing;
    cg_vec2 current, start;
    int has_current, after_close;
} fill_path_mark;
void fill_path_save(const cg_path *path, fill_path_mark *mark);
void fill_path_restore(cg_path *path, const fill_path_mark *mark);
/* The current point and the start of the current subpath ((0, 0) when none). */
cg_vec2 fill_path_current(const cg_path *path);
cg_vec2 fill_path_start(const cg_path *path);

/* A box beyond which geometry cannot show: x0 <= x <= x1, y0 <= y <= y1. */
typedef struct fill_clip {
    double x0, y0, x1, y1;
} fill_clip;

/* Flattens path into polylines (curves and arcs within tolerance).  With a
 * box, curve and arc pieces wholly beyond it become straight lines (which
 * changes nothing inside it), so huge curves cost time and memory in
 * proportion to their visible part. */
cg_status fill_path_flatten(const cg_path *path, double tolerance, const fill_clip *box,
                            fill_polylines *out);

/* Chords of an arc of radius r through |sweep| radians within tolerance
 * (at least 1, at most 100,000). */
long fill_arc_steps(double r, double sweep, double tolerance);
/* Appends the points of the circular arc around c of radius r from angle a0
 * to a1 (excluding the start point) within tolerance. */
cg_status fill_arc_points(fill_polylines *set, cg_vec2 c, double r, double a0, double a1,
                          double tolerance);

/* The stroke outline of polylines as closed contours (for the non-zero rule). */
cg_status fill_stroke_polylines(const fill_polylines *in, const cg_stroke_style *style,
                                double tolerance, fill_polylines *out);

/* ---- painting spans ------------------------------------------------------ */

/* wmemset stores a 32-bit value n times with the widest stores the C library
 * has for the machine (AVX2, AVX-512, "rep stos"); usable for pixels where
 * wchar_t is int and uint32_t unsigned int, which may alias each other. */
#define FILL_WMEMSET_PIXELS                     \
    (_Generic((wchar_t)0, int : 1, default : 0) \
     && _Generic((uint32_t)0, unsigned int : 1, default : 0))

/* d[0..n-1] = v: the solid interior of a shape.  Long runs go to wmemset
 * (32 bytes and more per store: 5 to 10% off anti-aliased 1024 px shapes),
 * short ones take sixteen bytes per store here, with no call. */
static inline void fill_store32(uint32_t *d, int n, uint32_t v)
{
    int i = 0;
    if (FILL_WMEMSET_PIXELS && n >= 64) {
        uint32_t iv = v; /* v's bits as a wchar_t (int), without overflow */
        wchar_t w;
        memcpy(&w, &iv, sizeof w < sizeof iv ? sizeof w : sizeof iv);
        wmemset((wchar_t *)(void *)d, w, (size_t)n);
        return;
    }
    /* The last four pixels are stored over what the loop stored, and one to
     * three pixels by three stores that may coincide: no branch on the
     * remainder (runs of every length come one after another in a row, and
     * the branches of a loop over the remainder mispredicted). */
    if (n >= 4) {
        i4 four = i4_set((int)v);
        for (; i + 4 < n; i += 4)
            i4_store(d + i, four);
        i4_store(d + n - 4, four);
    } else if (n > 0) {
        d[0] = v;
        d[n >> 1] = v;
        d[n - 1] = v;
    }
}

typedef struct fill_painter {
    cg_image *image;
    struct cg_rasterizer *cache; /* the solid blend cache */
    int type;
    /* solid: linear straight colour and its encoded form */
    float r, g, b, a;
    uint32_t encoded;
    int opaque;
    /* the linear colour is exactly the decoded encoded one, so blending over
     * a pixel of the same colour changes only its alpha */
    int same_exact;
    uint8_t encoded_rgba[4];
    /* gradients */
    double gx, gy, gc;         /* linear: t = gx * x + gy * y + gc */
    double cx, cy, inv_radius; /* radial */
    int spread;                /* cg_gradient_spread */
    int focal;                 /* radial from a focal point (fx, fy) */
    double fx, fy, radius;
    int transformed; /* pixels reach gradient space through inverse */
    cg_mat3 inverse;
    cg_rgbaf ramp[256];
    /* compositing: general is set unless the drawing is linear-light
     * source-over (the fast paths); then the span goes through
     * fill_general_span, and space_color is a solid paint's straight colour
     * in the space (and the ramp's colours are in the space too) */
    int general;
    int space, op, mode;
    cg_rgbaf space_color;
} fill_painter;

/* The ramp colour of a gradient paint at pixel point (x, y). */
const cg_rgbaf *fill_gradient_at(const fill_painter *p, double x, double y);
/* Any paint through any operator in any space (composite.c). */
void fill_general_span(const fill_painter *p, int y, int x0, int n, const uint8_t *cover);
/* Composites premultiplied source (of the space) onto one pixel at coverage k. */
void fill_composite_pixel8(cg_rgba8 *d, cg_rgbaf source, cg_compositing_space space,
                           cg_composite_operator op, cg_blend_mode mode, float k);
void fill_composite_pixelf(cg_rgbaf *d, cg_rgbaf source, cg_compositing_space space,
                           cg_composite_operator op, cg_blend_mode mode, float k);

/* ---- pixels in a compositing space (composite.c, layer.c) ---- */

/* A stored pixel as a premultiplied colour of the space. */
static inline cg_rgbaf fill_load_pixel8(cg_rgba8 px, cg_compositing_space space)
{
    float a = px.a * (1.0f / 255.0f);
    cg_rgbaf c;
    if (space == CG_COMPOSITE_SRGB) {
        float k = a * (1.0f / 255.0f);
        c.r = px.r * k;
        c.g = px.g * k;
        c.b = px.b * k;
    } else {
        c.r = color_srgb_decode_table[px.r] * a;
        c.g = color_srgb_decode_table[px.g] * a;
        c.b = color_srgb_decode_table[px.b] * a;
    }
    c.a = a;
    return c;
}

static inline uint8_t fill_unit_to_byte(float v)
{
    v = v > 0 ? v : 0; /* also NaN */
    v = v < 1 ? v : 1;
    return (uint8_t)(v * 255.0f + 0.5f);
}

static inline cg_rgba8 fill_store_pixel8(cg_rgbaf c, cg_compositing_space space)
{
    cg_rgba8 px = {0, 0, 0, 0};
    px.a = fill_unit_to_byte(c.a);
    if (px.a == 0)
        return px;
    float inv = 1 / c.a;
    if (space == CG_COMPOSITE_SRGB) {
        px.r = fill_unit_to_byte(c.r * inv);
        px.g = fill_unit_to_byte(c.g * inv);
        px.b = fill_unit_to_byte(c.b * inv);
    } else {
        px.r = cg_srgb_encode_unit(c.r * inv);
        px.g = cg_srgb_encode_unit(c.g * inv);
        px.b = cg_srgb_encode_unit(c.b * inv);
    }
    return px;
}

/* RGBAF pixels are straight linear light. */
static inline cg_rgbaf fill_load_pixelf(cg_rgbaf px, cg_compositing_space space)
{
    if (space == CG_COMPOSITE_SRGB) {
        px.r = (float)cg_linear_to_srgb(px.r);
        px.g = (float)cg_linear_to_srgb(px.g);
        px.b = (float)cg_linear_to_srgb(px.b);
    }
    px.r *= px.a;
    px.g *= px.a;
    px.b *= px.a;
    return px;
}

static inline cg_rgbaf fill_store_pixelf(cg_rgbaf c, cg_compositing_space space)
{
    if (!(c.a > 0)) {
        cg_rgbaf none = {0, 0, 0, 0};
        return none;
    }
    float inv = 1 / c.a;
    c.r *= inv;
    c.g *= inv;
    c.b *= inv;
    if (space == CG_COMPOSITE_SRGB) {
        c.r = (float)cg_srgb_to_linear(c.r);
        c.g = (float)cg_srgb_to_linear(c.g);
        c.b = (float)cg_srgb_to_linear(c.b);
    }
    return c;
}

/* Source-over in the sRGB space onto an RGBA8 pixel, the common case of
 * SVG drawing, without the general path's conversions: straight source
 * values sr, sg, sb in 0..255 at alpha a (coverage included, 0..1).  The
 * same mix as fill_composite_pixel8 (within float rounding): over an opaque
 * pixel d + (s - d) a, over nothing the source itself, else the weighted
 * mean of the two by a and d's alpha times 1 - a. */
static inline void fill_srgb_over(cg_rgba8 *d, float sr, float sg, float sb, float a)
{
    if (!(a > 0))
        return;
    if (a >= 1) {
        d->r = (uint8_t)(sr + 0.5f);
        d->g = (uint8_t)(sg + 0.5f);
        d->b = (uint8_t)(sb + 0.5f);
        d->a = 255;
        return;
    }
    if (d->a == 255) {
        d->r = (uint8_t)(d->r + (sr - d->r) * a + 0.5f);
        d->g = (uint8_t)(d->g + (sg - d->g) * a + 0.5f);
        d->b = (uint8_t)(d->b + (sb - d->b) * a + 0.5f);
        return;
    }
    float f = d->a * (1.0f / 255.0f) * (1 - a), out = a + f;
    uint8_t alpha = (uint8_t)(out * 255.0f + 0.5f);
    if (alpha == 0)
        return; /* the general path leaves nothing there either */
    float inv = 1 / out;
    d->r = (uint8_t)fminf(255, (sr * a + d->r * f) * inv + 0.5f);
    d->g = (uint8_t)fminf(255, (sg * a + d->g * f) * inv + 0.5f);
    d->b = (uint8_t)fminf(255, (sb * a + d->b * f) * inv + 0.5f);
    d->a = alpha;
}

/* k * composite(source, backdrop) + (1 - k) * backdrop (premultiplied). */
cg_rgbaf fill_composite_covered(cg_rgbaf source, cg_rgbaf backdrop, cg_composite_operator op,
                                cg_blend_mode mode, float k);

/* CG_EINVAL for a malformed paint. */
cg_status fill_painter_init(fill_painter *p, struct cg_rasterizer *r, cg_image *image,
                            const cg_paint *paint);
/* Paints pixels x0 .. x0+n-1 of row y with coverage cover[i] / 255 (cover
 * NULL: full coverage).  The span must be inside the image. */
void fill_painter_span(const fill_painter *p, int y, int x0, int n, const uint8_t *cover);

/* ---- the rasterizer ------------------------------------------------------- */

typedef struct fill_line {
    double x0, y0, x1, y1;
} fill_line;

typedef struct fill_edge {
    double x0, y0, slope; /* x = x0 + (y - y0) * slope */
    int first_row, last_row, dir;
} fill_edge;

typedef struct fill_crossing {
    double x;
    int dir;
} fill_crossing;

#define FILL_BLEND_BITS 10
#define FILL_BLEND_CACHE (1 << FILL_BLEND_BITS) /* entries */
#define FILL_BLEND_GENERATIONS (1u << 24)

struct cg_rasterizer {
    double tolerance;
    int space, op, mode; /* compositing (cg_rasterizer_set_compositing), 0: the defaults */
    /* anti-aliased: lines clipped to the image, and their bounds */
    fill_line *lines;
    size_t line_count, line_capacity;
    double min_x, min_y, max_x, max_y;
    int clip_width, clip_height;
    float *accumulation;
    size_t accumulation_capacity;
    uint64_t *touched; /* a bit per accumulation cell */
    size_t touched_capacity;
    uint8_t *cover;
    size_t cover_capacity;
    size_t *order;
    size_t order_capacity;
    size_t *active;
    size_t active_capacity;
    /* aliased: edge table and active edges */
    fill_edge *edges;
    size_t edge_count, edge_capacity;
    fill_crossing *crossings;
    size_t crossing_capacity;
    /* path scratch */
    fill_polylines flat, outline;
    /* Solid paint over RGBA8: a direct-mapped cache of fill_solid_pixel's
     * results for the source colour blend_src, keyed by destination value,
     * coverage and generation (a new source colour starts a new one;
     * generation 0, before the first solid paint, has no source colour). */
    uint32_t blend_src, blend_gen;
    uint64_t blend_key[FILL_BLEND_CACHE];
    uint32_t blend_value[FILL_BLEND_CACHE];
};

/* Source-over of a straight linear colour with alpha as onto an encoded pixel. */
static inline void fill_blend8(cg_rgba8 *d, float r, float g, float b, float as)
{
    if (d->a == 255) {
        float dr = color_srgb_decode_table[d->r], dg = color_srgb_decode_table[d->g],
              db = color_srgb_decode_table[d->b];
        d->r = cg_srgb_encode_unit(dr + (r - dr) * as);
        d->g = cg_srgb_encode_unit(dg + (g - dg) * as);
        d->b = cg_srgb_encode_unit(db + (b - db) * as);
        return;
    }
    if (d->a == 0) { /* over nothing: the source colour, with its alpha */
        if (!(as > 0))
            return;
        d->r = cg_srgb_encode_unit(r);
        d->g = cg_srgb_encode_unit(g);
        d->b = cg_srgb_encode_unit(b);
        d->a = (uint8_t)(as * 255.0f + 0.5f);
        return;
    }
    float ad = d->a * (1.0f / 255.0f) * (1 - as), a = as + ad;
    if (a <= 0)
        return;
    float inv = 1 / a; /* the results are weighted means of values in [0, 1] */
    d->r = cg_srgb_encode_unit((r * as + color_srgb_decode_table[d->r] * ad) * inv);
    d->g = cg_srgb_encode_unit((g * as + color_srgb_decode_table[d->g] * ad) * inv);
    d->b = cg_srgb_encode_unit((b * as + color_srgb_decode_table[d->b] * ad) * inv);
    d->a = (uint8_t)(a * 255.0f + 0.5f);
}

/* Paints one RGBA8 pixel with a solid paint at coverage c / 255. */
static inline void fill_solid_pixel(const fill_painter *p, cg_rgba8 *d, int c)
{
    if (c == 0)
        return;
    if (c == 255 && p->opaque) {
        memcpy(d, &p->encoded, 4);
        return;
    }
    float as = p->a * (c * (1.0f / 255.0f));
    if (!(as > 0))
        return;
    if (d->a == 0) { /* over nothing: the colour itself, with its alpha */
        memcpy(d, &p->encoded, 4);
        d->a = (uint8_t)(as * 255.0f + 0.5f);
        return;
    }
    if (p->same_exact && d->r == (uint8_t)p->encoded_rgba[0] && d->g == p->encoded_rgba[1]
        && d->b == p->encoded_rgba[2]) {
        /* fill_blend8 would give the same colour back (it is a weighted
         * mean of two equal values, far from the code's rounding limits):
         * only the alpha changes */
        if (d->a != 255)
            d->a = (uint8_t)((as + d->a * (1.0f / 255.0f) * (1 - as)) * 255.0f + 0.5f);
        return;
    }
    fill_blend8(d, p->r, p->g, p->b, as);
}

/* Starts the next generation of the blend cache (the keys are cleared when
 * the counter wraps, so a stale key never matches; generation 0 is never
 * used again). */
static inline void fill_next_generation(struct cg_rasterizer *r)
{
    if (++r->blend_gen >= FILL_BLEND_GENERATIONS) {
        memset(r->blend_key, 0, sizeof r->blend_key);
        r->blend_gen = 1;
    }
}

/* fill_blend8 of a colour (linear r, g, b) at alpha as over pixel v (of
 * alpha 255, or translucent), channel by channel with the same arithmetic
 * (decode, mix, encode through cg_srgb_encode_unit's tables), so with the same
 * result; the three channels at once with SSE2.  Everything it reads (2.1
 * KiB of tables) stays in the first-level cache. */
#if defined(__SSE2__)
typedef v4 fill_rgb;
static inline fill_rgb fill_rgb_make(float r, float g, float b)
{
    return v4_set3(r, g, b);
}

static inline v4 fill_decode_rgb(const cg_rgba8 *px)
{
    return v4_set3(color_srgb_decode_table[px->r], color_srgb_decode_table[px->g],
                   color_srgb_decode_table[px->b]);
}

static inline uint32_t fill_blend_opaque(uint32_t v, fill_rgb src, float as)
{
    cg_rgba8 px;
    memcpy(&px, &v, sizeof px);
    v4 dk = fill_decode_rgb(&px);
    cg_srgb_encode_rgb(&px, v4_add(dk, v4_mul(v4_sub(src, dk), v4_set(as))));
    memcpy(&v, &px, sizeof v);
    return v;
}

/* The same over a translucent pixel (0 < alpha < 255, as > 0). */
static inline uint32_t fill_blend_translucent(uint32_t v, fill_rgb src, float as)
{
    cg_rgba8 px;
    memcpy(&px, &v, sizeof px);
    float ad = px.a * (1.0f / 255.0f) * (1 - as), a = as + ad;
    v4 mix = v4_add(v4_mul(src, v4_set(as)), v4_mul(fill_decode_rgb(&px), v4_set(ad)));
    cg_srgb_encode_rgb(&px, v4_mul(mix, v4_set(1 / a)));
    px.a = (uint8_t)(a * 255.0f + 0.5f);
    memcpy(&v, &px, sizeof v);
    return v;
}
#else
typedef struct fill_rgb {
    float r, g, b;
} fill_rgb;
static inline fill_rgb fill_rgb_make(float r, float g, float b)
{
    fill_rgb c = {r, g, b};
    return c;
}

static inline uint32_t fill_blend_opaque(uint32_t v, fill_rgb src, float as)
{
    cg_rgba8 px;
    memcpy(&px, &v, sizeof px);
    fill_blend8(&px, src.r, src.g, src.b, as);
    memcpy(&v, &px, sizeof v);
    return v;
}

static inline uint32_t fill_blend_translucent(uint32_t v, fill_rgb src, float as)
{
    return fill_blend_opaque(v, src, as);
}
#endif

/* A solid paint's blend state (its colour, the blend cache's fields),
 * copied into a local variable for a band of rows (the pixel stores could
 * otherwise alias it and force reloads). */
typedef struct fill_blend_state {
    const fill_painter *p;
    uint64_t *keys;
    uint32_t *values;
    uint64_t generation; /* shifted into place */
    fill_rgb src;        /* the paint's linear colour */
    float alpha;         /* and its alpha */
    uint32_t alpha_mask; /* the alpha byte of a pixel's 32 bits */
    uint32_t full;
    int opaque;
    int keep_same;     /* opaque paint over pixels of its own colour changes only alpha */
    uint32_t rgb_mask; /* the bytes of r, g and b in a pixel's 32 bits */
} fill_blend_state;

static inline fill_blend_state fill_blend_begin(const fill_painter *p)
{
    fill_blend_state s;
    s.p = p;
    s.keys = p->cache->blend_key;
    s.values = p->cache->blend_value;
    s.generation = (uint64_t)p->cache->blend_gen << 40;
    s.src = fill_rgb_make(p->r, p->g, p->b);
    s.alpha = p->a;
    s.full = p->encoded;
    s.opaque = p->opaque;
    s.keep_same = p->opaque && p->same_exact;
    cg_rgba8 mask = {255, 255, 255, 0}, alpha = {0, 0, 0, 255};
    memcpy(&s.rgb_mask, &mask, sizeof s.rgb_mask);
    memcpy(&s.alpha_mask, &alpha, sizeof s.alpha_mask);
    return s;
}

/* A miss of the cache: blends and records the result (out of line, so that
 * the hit path below stays small enough to inline). */
uint32_t fill_solid_miss(const fill_blend_state *s, uint32_t v, int c, uint64_t key, uint32_t slot);

#if defined(__GNUC__)
#define FILL_INLINE __attribute__((always_inline)) inline
#else
#define FILL_INLINE inline
#endif

/* fill_solid_pixel's result for pixel value v at coverage c (0 < c, and c
 * < 255 or a translucent paint), without storing it: over transparent
 * pixels and pixels of the paint's own colour directly, opaque paint over
 * any other pixel by the direct blends above, translucent paint through the
 * cache (over destinations of a few colours each coverage level is blended
 * once). */
static FILL_INLINE uint32_t fill_solid_value(const fill_blend_state *s, uint32_t v, int c)
{
    if (v == s->full && s->keep_same) /* over its own opaque colour: unchanged */
        return v;
    uint32_t a = v & s->alpha_mask;
    if (a == 0) { /* over nothing: the colour itself, with the coverage as alpha */
        float as = s->alpha * (c * (1.0f / 255.0f));
        if (!(as > 0)) /* a paint of alpha 0 */
            return v;
        cg_rgba8 px;
        memcpy(&px, &s->full, sizeof px);
        px.a = (uint8_t)(as * 255.0f + 0.5f);
        memcpy(&v, &px, sizeof v);
        return v;
    }
    if (s->keep_same && ((v ^ s->full) & s->rgb_mask) == 0) {
        /* a pixel of the paint's own colour: only its alpha changes (see
         * fill_solid_pixel) */
        cg_rgba8 px;
        memcpy(&px, &v, sizeof px);
        float as = c * (1.0f / 255.0f);
        px.a = (uint8_t)((as + px.a * (1.0f / 255.0f) * (1 - as)) * 255.0f + 0.5f);
        memcpy(&v, &px, sizeof v);
        return v;
    }
    if (s->opaque) {
        float as = s->alpha * (c * (1.0f / 255.0f));
        return a == s->alpha_mask ? fill_blend_opaque(v, s->src, as)
                                  : fill_blend_translucent(v, s->src, as);
    }
    uint64_t key = v | (uint64_t)c << 32 | s->generation;
    uint32_t slot = ((v ^ (uint32_t)c * 0x01000193u) * 2654435769u) >> (32 - FILL_BLEND_BITS);
    if (s->keys[slot] == key)
        return s->values[slot];
    return fill_solid_miss(s, v, c, key, slot);
}

/* fill_solid_pixel on pixel *d. */
static FILL_INLINE void fill_solid_cached(const fill_blend_state *s, uint32_t *d, int c)
{
    if (c == 0)
        return;
    if (c == 255 && s->opaque) {
        *d = s->full;
        return;
    }
    *d = fill_solid_value(s, *d, c);
}

/* Paints n RGBA8 pixels d[0..n-1] with a solid paint at coverage cover[i] /
 * 255 (cover NULL: constant / 255), as fill_solid_cached does. */
void fill_solid_run(const fill_painter *p, uint32_t *d, int n, const uint8_t *cover, int constant);

/* Checks every point of a polygon (finite, within CG_FILL_MAX_COORD) and the
 * contour sizes; *total receives the number of points. */
cg_status fill_check_polygon(const cg_vec2 *points, const int *contour_sizes, int contour_count,
                             size_t *total);

/* Anti-aliased coverage: reset, add lines, then composite. */
void fill_aa_begin(struct cg_rasterizer *r, const cg_image *image);
cg_status fill_aa_add_line(struct cg_rasterizer *r, cg_vec2 a, cg_vec2 b);
cg_status fill_aa_add_polylines(struct cg_rasterizer *r, const fill_polylines *set);
cg_status fill_aa_render(struct cg_rasterizer *r, cg_image *image, cg_fill_rule rule,
                         const cg_paint *paint);

#endif
