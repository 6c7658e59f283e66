/* Multisample anti-aliasing of the z-buffer: N = 2, 4, 8 or 16 samples per
 * pixel at the standard positions of Direct3D 11 and Vulkan (the same
 * tables; in 1/16 pixel from the pixel centre, y down):
 *
 *   2:  (4,4) (-4,-4)
 *   4:  (-2,-6) (6,-2) (-6,2) (2,6)
 *   8:  (1,-3) (-1,3) (5,1) (-3,-5) (-5,5) (-7,-1) (3,7) (7,-7)
 *   16: (1,1) (-1,-3) (-3,2) (4,-1) (-5,-2) (2,5) (5,3) (3,-5)
 *       (-2,6) (0,-7) (-4,-6) (-6,4) (-8,0) (7,-4) (6,7) (-7,-8)
 *
 * A sample is covered when the triangle's three edge functions are >= 0
 * there, with the top-left bias of render_edge_at: the offsets are whole
 * multiples of the 1/256 grid, so the test is the same exact integer one
 * as at pixel centres, and triangles sharing an edge cover each sample
 * along it exactly once.  Each covered sample has its own depth test and
 * depth; the triangle is shaded once per pixel (at the pixel centre, as
 * OpenGL's non-centroid interpolation), and its colour stored in the
 * samples that passed.  When a tile is done the samples of each pixel are
 * averaged in linear light and encoded.
 *
 * Storage is per tile and per worker (render_samples): a pixel is either
 * untouched (background, infinite depth: nothing stored), uniform (every
 * sample the same colour: one colour kept, in an array of one colour per
 * pixel) or mixed (a colour per sample), so a triangle covering whole
 * pixels costs one colour store per pixel, and only mixed pixels are
 * averaged. */
#include "pipeline.h"
#include "attributes.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <string.h>

enum { UNTOUCHED, UNIFORM, MIXED };

static const int8_t positions1[1][2] = {{0, 0}};
static const int8_t positions2[2][2] = {{4, 4}, {-4, -4}};
static const int8_t positions4[4][2] = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
static const int8_t positions8[8][2] = {{1, -3}, {-1, 3},  {5, 1}, {-3, -5},
                                        {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
static const int8_t positions16[16][2] = {{1, 1},  {-1, -3}, {-3, 2}, {4, -1}, {-5, -2}, {2, 5},
                                          {5, 3},  {3, -5},  {-2, 6}, {0, -7}, {-4, -6}, {-6, 4},
                                          {-8, 0}, {7, -4},  {6, 7},  {-7, -8}};

const int8_t (*render_sample_positions(int samples))[2]
{
    switch (samples) {
    case 1: return positions1;
    case 2: return positions2;
    case 4: return positions4;
    case 8: return positions8;
    case 16: return positions16;
    default: return NULL;
    }
}

size_t render_samples_bytes(int samples)
{
    size_t pixels = (size_t)RENDER_TILE * RENDER_TILE;
    return pixels * ((size_t)samples * 5 + 4) * sizeof(float) + pixels;
}

void render_samples_bind(render_samples *s, void *memory, int samples)
{
    size_t pixels = (size_t)RENDER_TILE * RENDER_TILE;
    s->samples = samples;
    s->pixel = memory;
    s->depth = s->pixel + pixels * 4;
    s->color = s->depth + pixels * (size_t)samples;
    s->state = (unsigned char *)(s->color + pixels * (size_t)samples * 4);
}

static inline void copy4(float *to, const float *from)
{
    to[0] = from[0];
    to[1] = from[1];
    to[2] = from[2];
    to[3] = from[3];
}

/* Samples covered in a mask of at most 16 bits. */
static inline int bits(unsigned mask)
{
    static const unsigned char nibble[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
    return nibble[mask & 15] + nibble[mask >> 4 & 15] + nibble[mask >> 8 & 15]
           + nibble[mask >> 12 & 15];
}

void render_samples_begin(render_frame *f, render_samples *s, int x0, int y0, int x1, int y1)
{
    memset(s->state, UNTOUCHED, (size_t)RENDER_TILE * RENDER_TILE);
    s->x0 = x0;
    s->y0 = y0;
    render_clear_tile(f, x0, y0, x1, y1, 0, 1);
}

/* A pixel whose samples all show colour c, nearest depth z: written to the
 * image and depth buffer at once (no resolve needed). */
static inline void write_pixel(const render_frame *f, const render_samples *s, size_t p,
                               const float c[4], float z)
{
    int x = s->x0 + (int)(p % RENDER_TILE), y = s->y0 + (int)(p / RENDER_TILE);
    f->depth[(size_t)y * f->width + x] = z;
    unsigned char *row = f->image->data + (size_t)y * f->image->stride;
    if (f->image->format == CG_PIXEL_RGBA8) {
        cg_rgba8 *q = (cg_rgba8 *)row + x;
#if defined(__SSE2__)
        cg_srgb_encode_rgb(q, _mm_setr_ps(c[0], c[1], c[2], 0));
#else
        q->r = cg_srgb_encode_unit(c[0]);
        q->g = cg_srgb_encode_unit(c[1]);
        q->b = cg_srgb_encode_unit(c[2]);
#endif
        float a = c[3] < 0 ? 0 : c[3] > 1 ? 1 : c[3];
        q->a = c[3] == 1 ? 255 : (uint8_t)(a * 255 + 0.5f);
    } else {
        cg_rgbaf *q = (cg_rgbaf *)row + x;
        q->r = c[0];
        q->g = c[1];
        q->b = c[2];
        q->a = c[3];
    }
}

/* The samples of pixel p before a fragment writes some of them: an untouched
 * pixel gets infinite depths and the background in each sample, a uniform
 * one its colour in each sample. */
static inline void make_writable(const render_frame *f, render_samples *s, size_t p)
{
    const int n = s->samples;
    float *color = s->color + p * (size_t)n * 4;
    if (s->state[p] == UNTOUCHED) {
        float *depth = s->depth + p * (size_t)n;
        for (int k = 0; k < n; k++) {
            depth[k] = INFINITY;
            copy4(color + 4 * k, f->background);
        }
    } else if (s->state[p] == UNIFORM) {
        for (int k = 0; k < n; k++)
            copy4(color + 4 * k, s->pixel + 4 * p);
    }
}

/* The per-triangle constants: each sample's offset in each edge function
 * and in depth. */
typedef struct sample_offsets {
    int64_t edge[3][16];
    int64_t lo[3], hi[3]; /* smallest and largest offset of each edge */
    float z[16];
} sample_offsets;

static void offsets_setup(const setup_triangle *t, const raster_edges *e, int n, float ia,
                          sample_offsets *o)
{
    const int8_t(*xy)[2] = render_sample_positions(n);
    float dz1 = t->z[1] - t->z[0], dz2 = t->z[2] - t->z[0];
    for (int k = 0; k < 3; k++) {
        o->lo[k] = INT64_MAX;
        o->hi[k] = INT64_MIN;
        for (int j = 0; j < n; j++) {
            /* The steps are per pixel; positions in 1/16 pixel. */
            int64_t d = (xy[j][0] * e->step_x[k] + xy[j][1] * e->step_y[k]) / 16;
            o->edge[k][j] = d;
            o->lo[k] = d < o->lo[k] ? d : o->lo[k];
            o->hi[k] = d > o->hi[k] ? d : o->hi[k];
        }
    }
    for (int j = 0; j < n; j++)
        o->z[j] = (float)o->edge[1][j] * ia * dz1 + (float)o->edge[2][j] * ia * dz2;
}

/* Alpha-to-coverage for glTF's MASK: alpha mapped so that the cutoff falls
 * half way, then that fraction of the samples (the first ones: the
 * positions are already spread over the pixel). */
static inline unsigned coverage_of_alpha(float alpha, float cutoff, int n)
{
    float a = alpha < cutoff ? 0.5f * alpha / cutoff
              : cutoff < 1   ? 0.5f + 0.5f * (alpha - cutoff) / (1 - cutoff)
                             : 1; /* a cutoff of 1 keeps alpha 1 whole */
    if (!(a > 0))
        return 0;
    a = a < 1 ? a : 1;
    int k = (int)(a * (float)n + 0.5f);
    return k >= n ? (1u << n) - 1 : (1u << k) - 1;
}

/* The colour of the fragment at a pixel centre (barycentric weights l1, l2);
 * *alpha for textured ones; 0 when it is dropped. */
static inline int shade(const render_frame *f, const setup_triangle *t,
                        const attribute_plane *plane, float l1, float l2, const int mode,
                        float c[4], float *alpha)
{
    *alpha = 1;
    c[3] = 1;
    if (mode == MODE_FLAT) {
        c[0] = t->color[0];
        c[1] = t->color[1];
        c[2] = t->color[2];
        return 1;
    }
    if (mode == MODE_GOURAUD) {
        float r = 1 / (plane->w_base + l1 * plane->w_d1 + l2 * plane->w_d2);
        for (int j = 0; j < 3; j++)
            c[j] = (plane->p_base[j] + l1 * plane->p_d1[j] + l2 * plane->p_d2[j]) * r;
        return 1;
    }
    return attribute_pixel(f, t, plane, l1, l2, mode, c, alpha);
}

/* c over d in linear light (straight alpha a): Porter and Duff's over. */
static inline void over(float d[4], const float c[4], float a)
{
    for (int j = 0; j < 3; j++)
        d[j] = c[j] * a + d[j] * (1 - a);
    d[3] = a + d[3] * (1 - a);
}

/* A fragment of a BLEND material: depth-tested at its samples but not
 * written; its colour laid over what each passing sample shows. */
static void blend_fragment(const render_frame *f, render_samples *s, const setup_triangle *t,
                           const attribute_plane *plane, const sample_offsets *o, size_t p,
                           unsigned covered, float l1, float l2, float zc, int n)
{
    const unsigned full = (1u << n) - 1;
    float *depth = s->depth + p * (size_t)n;
    int untouched = s->state[p] == UNTOUCHED;
    unsigned pass = 0;
    for (int k = 0; k < n; k++)
        if ((covered >> k & 1) && (untouched || zc + o->z[k] < depth[k]))
            pass |= 1u << k;
    if (!pass)
        return;
    float c[4], alpha;
    if (!attribute_pixel(f, t, plane, l1, l2, MODE_TEXTURED, c, &alpha))
        return;
    float a = alpha < 0 ? 0 : alpha > 1 ? 1 : alpha;
    if (pass == full && s->state[p] != MIXED) {
        float *pixel = s->pixel + 4 * p, nearest = INFINITY;
        if (untouched) {
            for (int k = 0; k < n; k++)
                depth[k] = INFINITY;
            copy4(pixel, f->background);
        }
        for (int k = 0; k < n; k++)
            nearest = depth[k] < nearest ? depth[k] : nearest;
        over(pixel, c, a);
        s->state[p] = UNIFORM;
        write_pixel(f, s, p, pixel, nearest);
        return;
    }
    make_writable(f, s, p);
    float *color = s->color + p * (size_t)n * 4;
    for (int k = 0; k < n; k++)
        if (pass >> k & 1)
            over(color + 4 * k, c, a);
    s->state[p] = MIXED;
}

#if defined(__GNUC__)
#define SAMPLES_SPECIALIZE __attribute__((always_inline)) inline
#else
#define SAMPLES_SPECIALIZE inline
#endif

/* One fragment: the samples in `covered` depth-tested, the pixel shaded once
 * if any passes, its colour stored in those that pass.  Returns nothing:
 * the caller counts the covered samples. */
static SAMPLES_SPECIALIZE void fragment(const render_frame *f, render_samples *s,
                                        const setup_triangle *t, const attribute_plane *plane,
                                        const sample_offsets *o, size_t p, unsigned covered,
                                        float l1, float l2, float zc, float cutoff, const int mode,
                                        const int n)
{
    const unsigned full = (1u << n) - 1;
    float *depth = s->depth + p * (size_t)n;
    int untouched = s->state[p] == UNTOUCHED;
    unsigned pass = 0;
    float z[16];
    for (int k = 0; k < n; k++) {
        z[k] = zc + o->z[k];
        if ((covered >> k & 1) && (untouched || z[k] < depth[k]))
            pass |= 1u << k;
    }
    if (!pass)
        return;
    float c[4], alpha;
    if (!shade(f, t, plane, l1, l2, mode, c, &alpha))
        return;
    if (cutoff > 0 && !(pass &= coverage_of_alpha(alpha, cutoff, n)))
        return;
    if (pass == full) {
        float nearest = z[0];
        for (int k = 0; k < n; k++) {
            depth[k] = z[k];
            nearest = z[k] < nearest ? z[k] : nearest;
        }
        copy4(s->pixel + 4 * p, c);
        s->state[p] = UNIFORM;
        write_pixel(f, s, p, c, nearest);
        return;
    }
    make_writable(f, s, p);
    float *color = s->color + p * (size_t)n * 4;
    for (int k = 0; k < n; k++)
        if (pass >> k & 1) {
            depth[k] = z[k];
            copy4(color + 4 * k, c);
        }
    s->state[p] = MIXED;
}

static SAMPLES_SPECIALIZE size_t raster_samples(const render_frame *f, render_samples *s,
                                                const setup_triangle *t, int tx, int ty, int x0,
                                                int y0, int x1, int y1, const int mode, const int n)
{
    if (!render_clip_to_box(t, &x0, &y0, &x1, &y1))
        return 0;
    const unsigned full = (1u << n) - 1;
    raster_edges e;
    render_edges_at(t, x0, y0, &e);
    const float ia = t->inverse_area, z0 = t->z[0], dz1 = t->z[1] - z0, dz2 = t->z[2] - z0;
    sample_offsets o;
    offsets_setup(t, &e, n, ia, &o);
    attribute_plane plane;
    if (mode != MODE_FLAT)
        attribute_setup(t, &e, ia, mode == MODE_GOURAUD ? 3 : f->attribute_count, &plane);
    float cutoff = 0;
    int blend = 0;
    if (mode == MODE_TEXTURED && t->material != RENDER_NO_MATERIAL) {
        cutoff = f->r->materials[t->material].alpha_cutoff;
        blend = f->r->materials[t->material].blend;
    }
    size_t count = 0;
    for (int y = y0; y < y1;
         y++, e.w[0] += e.step_y[0], e.w[1] += e.step_y[1], e.w[2] += e.step_y[2]) {
        /* Pixels where some sample may be inside, and where all are. */
        int64_t any[3], all[3];
        for (int k = 0; k < 3; k++) {
            any[k] = e.w[k] + o.hi[k];
            all[k] = e.w[k] + o.lo[k];
        }
        int begin, end, all_begin, all_end;
        render_row_span(any, e.step_x, x1 - x0, &begin, &end);
        if (begin >= end)
            continue;
        render_row_span(all, e.step_x, x1 - x0, &all_begin, &all_end);
        size_t row = (size_t)(y - ty) * RENDER_TILE + (size_t)(x0 - tx);
        for (int i = begin; i < end; i++) {
            int64_t w[3] = {e.w[0] + i * e.step_x[0], e.w[1] + i * e.step_x[1],
                            e.w[2] + i * e.step_x[2]};
            unsigned covered = full;
            if (i < all_begin || i >= all_end) {
                covered = 0;
                for (int k = 0; k < n; k++)
                    if (((w[0] + o.edge[0][k]) | (w[1] + o.edge[1][k]) | (w[2] + o.edge[2][k]))
                        >= 0)
                        covered |= 1u << k;
                if (!covered)
                    continue;
            }
            count += (size_t)(covered == full ? n : bits(covered));
            float l1 = (float)w[1] * ia, l2 = (float)w[2] * ia;
            if (mode == MODE_TEXTURED && blend)
                blend_fragment(f, s, t, &plane, &o, row + (size_t)i, covered, l1, l2,
                               z0 + l1 * dz1 + l2 * dz2, n);
            else
                fragment(f, s, t, &plane, &o, row + (size_t)i, covered, l1, l2,
                         z0 + l1 * dz1 + l2 * dz2, cutoff, mode, n);
        }
    }
    return count;
}

/* Specialized for each shading mode and sample count: both constant in the
 * per-pixel loops. */
#define SAMPLES_CASE(mode)                                                     \
    switch (s->samples) {                                                      \
    case 1: return raster_samples(f, s, t, x0, y0, x0, y0, x1, y1, mode, 1);   \
    case 2: return raster_samples(f, s, t, x0, y0, x0, y0, x1, y1, mode, 2);   \
    case 4: return raster_samples(f, s, t, x0, y0, x0, y0, x1, y1, mode, 4);   \
    case 8: return raster_samples(f, s, t, x0, y0, x0, y0, x1, y1, mode, 8);   \
    default: return raster_samples(f, s, t, x0, y0, x0, y0, x1, y1, mode, 16); \
    }

size_t render_raster_samples(const render_frame *f, render_samples *s, const setup_triangle *t,
                             int x0, int y0, int x1, int y1)
{
    switch (f->shading) {
    case MODE_FLAT: SAMPLES_CASE(MODE_FLAT);
    case MODE_GOURAUD: SAMPLES_CASE(MODE_GOURAUD);
    case MODE_TEXTURED: SAMPLES_CASE(MODE_TEXTURED);
    default: SAMPLES_CASE(MODE_PHONG);
    }
}

/* The mean of the n colours (n a power of two) of a pixel's samples,
 * summed pairwise: n equal colours sum to exactly n times the colour, so a
 * pixel whose samples agree resolves to that colour exactly. */
static inline void mean(const float *color, int n, float inverse, float out[4])
{
#if defined(__SSE2__)
    __m128 t[16];
    for (int k = 0; k < n; k++)
        t[k] = _mm_loadu_ps(color + 4 * k);
    for (int w = n; w > 1; w /= 2)
        for (int k = 0; k < w / 2; k++)
            t[k] = _mm_add_ps(t[2 * k], t[2 * k + 1]);
    _mm_storeu_ps(out, _mm_mul_ps(t[0], _mm_set1_ps(inverse)));
#else
    float t[16][4];
    memcpy(t, color, (size_t)n * sizeof t[0]);
    for (int w = n; w > 1; w /= 2)
        for (int k = 0; k < w / 2; k++)
            for (int j = 0; j < 4; j++)
                t[k][j] = t[2 * k][j] + t[2 * k + 1][j];
    for (int j = 0; j < 4; j++)
        out[j] = t[0][j] * inverse;
#endif
}

void render_samples_resolve(render_frame *f, render_samples *s, int x0, int y0, int x1, int y1)
{
    const int n = s->samples;
    const float inverse = 1.0f / (float)n;
    /* Untouched and uniform pixels are in the image already. */
    for (int y = y0; y < y1; y++) {
        const unsigned char *state = s->state + (size_t)(y - y0) * RENDER_TILE;
        for (int x = x0; x < x1; x++) {
            if (state[x - x0] != MIXED)
                continue;
            size_t p = (size_t)(y - y0) * RENDER_TILE + (size_t)(x - x0);
            const float *depth = s->depth + p * (size_t)n, *color = s->color + p * (size_t)n * 4;
            float z = depth[0], c[4];
            for (int k = 1; k < n; k++)
                z = depth[k] < z ? depth[k] : z;
            mean(color, n, inverse, c);
            write_pixel(f, s, p, c, z);
        }
    }
}
