/* The tiled rasterizer, the pipeline's last stage: a set-up triangle drawn
 * inside one tile (or, for the painter's algorithm, the whole image).  Each
 * row of the triangle's box inside the tile is reduced to its covered run by
 * the three integer edge functions (render_row_span in internal.h, with a
 * picture), then the run is shaded pixel
 * by pixel -- flat, Gouraud or Phong -- behind the depth test.  The edge
 * functions are exact (fixed-point vertices, 64-bit products), so a pixel
 * centre on an edge shared by two triangles is drawn by exactly one of them
 * (the top-left rule), whichever tile or thread draws it. */
#include "pipeline.h"
#include "attributes.h"
#include "cg/color.h"
#include "../core/simd4.h"

#include <string.h>

/* ---- fragments ---------------------------------------------------------- */

static inline void store(unsigned char *row, int x, const float c[3], const int rgba8)
{
    if (rgba8) {
        cg_rgba8 *p = (cg_rgba8 *)row + x;
        p->r = cg_srgb_encode_unit(c[0]);
        p->g = cg_srgb_encode_unit(c[1]);
        p->b = cg_srgb_encode_unit(c[2]);
        p->a = 255;
    } else {
        cg_rgbaf *p = (cg_rgbaf *)row + x;
        p->r = c[0];
        p->g = c[1];
        p->b = c[2];
        p->a = 1;
    }
}

/* Gouraud colour along one covered run of a row.  Colour / w and 1 / w are
 * affine on the screen, so from pixel to pixel they change by constant
 * steps: each stretch of at most RENDER_TILE pixels starts from their exact
 * values at its first pixel (from the integer edge functions) and then only
 * adds the steps, which saves most of the per-pixel interpolation.  The
 * rounding of at most RENDER_TILE float additions stays far below one code
 * of an 8-bit channel.  Depth is still computed from the edge functions at
 * every pixel, as in the other modes, so the depth test is unchanged; the
 * stretches start at fixed offsets from the run's start, so the result does
 * not depend on the number of threads. */
typedef struct gouraud_plane {
    float ia, z0, dz1, dz2;  /* depth, as in raster_mode */
    float q[3], c[3][3];     /* 1 / w and colour / w: vertex 0, d1, d2 */
    float q_step, c_step[3]; /* their change per pixel to the right */
    int64_t step1, step2;    /* edge functions 1 and 2 per pixel */
} gouraud_plane;

/* An opaque pixel from the three colours in lanes 0-2 of v (lane 3, 1 / w
 * in the Gouraud runs, is ignored): every lane rounded as the scalar encode
 * rounds it, so the pictures are identical, with a quarter of the work. */
static inline void encode_store(cg_rgba8 *p, v4 v)
{
    cg_srgb_encode_rgb(p, v);
    p->a = 255;
}

static inline void gouraud_run(const gouraud_plane *g, int64_t w1, int64_t w2, float *zrow,
                               unsigned char *row, int x0, int begin, int end, const int depth_test,
                               const int rgba8)
{
    if (rgba8) {
        const v4 base = v4_set4(g->c[0][0], g->c[0][1], g->c[0][2], g->q[0]);
        const v4 d1 = v4_set4(g->c[1][0], g->c[1][1], g->c[1][2], g->q[1]);
        const v4 d2 = v4_set4(g->c[2][0], g->c[2][1], g->c[2][2], g->q[2]);
        const v4 step = v4_set4(g->c_step[0], g->c_step[1], g->c_step[2], g->q_step);
        v4 v = v4_set(0.0f);
        cg_rgba8 *out = (cg_rgba8 *)row + x0;
        /* Locals: the byte stores below may alias anything in memory. */
        const int64_t step1 = g->step1, step2 = g->step2;
        const float ia = g->ia, z0 = g->z0, dz1 = g->dz1, dz2 = g->dz2;
        for (int i = begin, restart = begin; i < end;
             i++, w1 += step1, w2 += step2, v = v4_add(v, step)) {
            float l1 = (float)w1 * ia, l2 = (float)w2 * ia;
            if (i == restart) {
                v = v4_add(v4_add(base, v4_mul(v4_set(l1), d1)), v4_mul(v4_set(l2), d2));
                restart += RENDER_TILE;
            }
            float z = z0 + l1 * dz1 + l2 * dz2;
            if (depth_test && !(z < zrow[i]))
                continue;
            zrow[i] = z;
            float r = 1 / v4_lane3(v);
            encode_store(out + i, v4_mul(v, v4_set(r)));
        }
        return;
    }
    float q = 0, c[3] = {0, 0, 0};
    for (int i = begin, restart = begin; i < end; i++, w1 += g->step1, w2 += g->step2,
             q += g->q_step, c[0] += g->c_step[0], c[1] += g->c_step[1], c[2] += g->c_step[2]) {
        float l1 = (float)w1 * g->ia, l2 = (float)w2 * g->ia;
        if (i == restart) {
            q = g->q[0] + l1 * g->q[1] + l2 * g->q[2];
            for (int j = 0; j < 3; j++)
                c[j] = g->c[0][j] + l1 * g->c[1][j] + l2 * g->c[2][j];
            restart += RENDER_TILE;
        }
        float z = g->z0 + l1 * g->dz1 + l2 * g->dz2;
        if (depth_test && !(z < zrow[i]))
            continue;
        zrow[i] = z;
        float r = 1 / q;
        float v[3] = {c[0] * r, c[1] * r, c[2] * r};
        store(row, x0 + i, v, rgba8);
    }
}

/* One Gouraud pixel from its barycentric weights l1, l2, evaluated as a run
 * starts (for triangles of a few pixels, which have no runs to speak of). */
static inline void gouraud_pixel(const gouraud_plane *g, float l1, float l2, unsigned char *row,
                                 int x, const int rgba8)
{
    if (rgba8) {
        v4 v = v4_add(
            v4_add(v4_set4(g->c[0][0], g->c[0][1], g->c[0][2], g->q[0]),
                   v4_mul(v4_set(l1), v4_set4(g->c[1][0], g->c[1][1], g->c[1][2], g->q[1]))),
            v4_mul(v4_set(l2), v4_set4(g->c[2][0], g->c[2][1], g->c[2][2], g->q[2])));
        float r = 1 / v4_lane3(v);
        encode_store((cg_rgba8 *)row + x, v4_mul(v, v4_set(r)));
        return;
    }
    float q = g->q[0] + l1 * g->q[1] + l2 * g->q[2], c[3];
    for (int j = 0; j < 3; j++)
        c[j] = g->c[0][j] + l1 * g->c[1][j] + l2 * g->c[2][j];
    float r = 1 / q;
    float v[3] = {c[0] * r, c[1] * r, c[2] * r};
    store(row, x, v, rgba8);
}

static void gouraud_setup(const setup_triangle *t, const raster_edges *e, float ia,
                          gouraud_plane *g)
{
    g->ia = ia;
    g->z0 = t->z[0];
    g->dz1 = t->z[1] - t->z[0];
    g->dz2 = t->z[2] - t->z[0];
    g->q[0] = t->iw[0];
    g->q[1] = t->iw[1] - t->iw[0];
    g->q[2] = t->iw[2] - t->iw[0];
    for (int j = 0; j < 3; j++) {
        g->c[0][j] = t->a[j] * t->iw[0];
        g->c[1][j] = t->a[3 + j] * t->iw[1] - g->c[0][j];
        g->c[2][j] = t->a[6 + j] * t->iw[2] - g->c[0][j];
    }
    g->step1 = e->step_x[1];
    g->step2 = e->step_x[2];
    float s1 = (float)g->step1 * ia, s2 = (float)g->step2 * ia;
    g->q_step = s1 * g->q[1] + s2 * g->q[2];
    for (int j = 0; j < 3; j++)
        g->c_step[j] = s1 * g->c[1][j] + s2 * g->c[2][j];
}

/* Clipped to the tile, a triangle box at most this many pixels on each side
 * is rasterized pixel by pixel. */
#define TINY 4

/* raster_mode is written once and specialized by render_raster for each
 * shading mode and image format: its constant arguments must reach the
 * per-pixel loop, so it is forced inline where the compiler allows. */
#if defined(__GNUC__)
#define RENDER_SPECIALIZE __attribute__((always_inline)) inline
#else
#define RENDER_SPECIALIZE inline
#endif

static RENDER_SPECIALIZE size_t raster_mode(const render_frame *f, const setup_triangle *t, int x0,
                                            int y0, int x1, int y1, const int mode,
                                            const int depth_test, const int rgba8)
{
    if (!render_clip_to_box(t, &x0, &y0, &x1, &y1))
        return 0;
    raster_edges e;
    render_edges_at(t, x0, y0, &e);
    const float ia = t->inverse_area, z0 = t->z[0], dz1 = t->z[1] - z0, dz2 = t->z[2] - z0;
    const int n = f->attribute_count;
    attribute_plane plane;
    if (mode == MODE_PHONG || mode == MODE_TEXTURED)
        attribute_setup(t, &e, ia, n, &plane);
    gouraud_plane gouraud;
    if (mode == MODE_GOURAUD)
        gouraud_setup(t, &e, ia, &gouraud);
    size_t fragments = 0;
    if (mode != MODE_PHONG && mode != MODE_TEXTURED && x1 - x0 <= TINY && y1 - y0 <= TINY) {
        /* A few pixels (most triangles of a finely tessellated mesh): each
         * tested and shaded on its own, without the runs' setup. */
        for (int y = y0; y < y1;
             y++, e.w[0] += e.step_y[0], e.w[1] += e.step_y[1], e.w[2] += e.step_y[2]) {
            int64_t a = e.w[0], b = e.w[1], c = e.w[2];
            float *zrow = f->depth + (size_t)y * f->width;
            unsigned char *row = f->image->data + (size_t)y * f->image->stride;
            for (int x = x0; x < x1; x++, a += e.step_x[0], b += e.step_x[1], c += e.step_x[2]) {
                if ((a | b | c) < 0)
                    continue;
                fragments++;
                float l1 = (float)b * ia, l2 = (float)c * ia;
                float z = z0 + l1 * dz1 + l2 * dz2;
                if (depth_test && !(z < zrow[x]))
                    continue;
                zrow[x] = z;
                if (mode == MODE_GOURAUD)
                    gouraud_pixel(&gouraud, l1, l2, row, x, rgba8);
                else if (rgba8)
                    ((cg_rgba8 *)row)[x] = t->color8;
                else
                    store(row, x, t->color, rgba8);
            }
        }
        return fragments;
    }
    for (int y = y0; y < y1;
         y++, e.w[0] += e.step_y[0], e.w[1] += e.step_y[1], e.w[2] += e.step_y[2]) {
        int begin, end;
        if (x1 - x0 <= 8) {
            /* Narrow: test the few pixels instead of dividing. */
            int64_t a = e.w[0], b = e.w[1], c = e.w[2];
            begin = x1 - x0;
            end = 0;
            for (int i = 0; i < x1 - x0; i++, a += e.step_x[0], b += e.step_x[1], c += e.step_x[2])
                if ((a | b | c) >= 0) {
                    if (i < begin)
                        begin = i;
                    end = i + 1;
                }
        } else {
            render_row_span(e.w, e.step_x, x1 - x0, &begin, &end);
        }
        if (begin >= end)
            continue;
        fragments += (size_t)(end - begin);
        int64_t w1 = e.w[1] + begin * e.step_x[1], w2 = e.w[2] + begin * e.step_x[2];
        float *zrow = f->depth + (size_t)y * f->width + x0;
        unsigned char *row = f->image->data + (size_t)y * f->image->stride;
        if (mode == MODE_GOURAUD) {
            gouraud_run(&gouraud, w1, w2, zrow, row, x0, begin, end, depth_test, rgba8);
            continue;
        }
        for (int i = begin; i < end; i++, w1 += e.step_x[1], w2 += e.step_x[2]) {
            float l1 = (float)w1 * ia, l2 = (float)w2 * ia;
            float z = z0 + l1 * dz1 + l2 * dz2;
            if (depth_test && !(z < zrow[i]))
                continue;
            if (mode != MODE_TEXTURED)
                zrow[i] = z;
            int x = x0 + i;
            if (mode == MODE_FLAT) {
                if (rgba8)
                    ((cg_rgba8 *)row)[x] = t->color8;
                else
                    store(row, x, t->color, rgba8);
                continue;
            }
            float c[3];
            if (!attribute_pixel(f, t, &plane, l1, l2, mode, c, NULL))
                continue; /* dropped: neither colour nor depth */
            if (mode == MODE_TEXTURED)
                zrow[i] = z;
            store(row, x, c, rgba8);
        }
    }
    return fragments;
}

#define RASTER_CASE(mode)                                                 \
    (rgba8 ? (depth_test ? raster_mode(f, t, x0, y0, x1, y1, mode, 1, 1)  \
                         : raster_mode(f, t, x0, y0, x1, y1, mode, 0, 1)) \
           : (depth_test ? raster_mode(f, t, x0, y0, x1, y1, mode, 1, 0)  \
                         : raster_mode(f, t, x0, y0, x1, y1, mode, 0, 0)))

size_t render_raster(const render_frame *f, const setup_triangle *t, int x0, int y0, int x1, int y1,
                     int depth_test)
{
    int rgba8 = f->image->format == CG_PIXEL_RGBA8;
    const cg_renderer *r = f->r;
    int probe = r->shade_step && r->probe_x >= x0 && r->probe_x < x1 && r->probe_y >= y0
                && r->probe_y < y1 && r->probe_x >= t->box[0] && r->probe_x < t->box[2]
                && r->probe_y >= t->box[1] && r->probe_y < t->box[3];
    float before = probe ? f->depth[(size_t)r->probe_y * f->width + r->probe_x] : 0;
    size_t fragments;
    switch (f->shading) {
    case MODE_FLAT: fragments = RASTER_CASE(MODE_FLAT); break;
    case MODE_GOURAUD: fragments = RASTER_CASE(MODE_GOURAUD); break;
    case MODE_TEXTURED: fragments = RASTER_CASE(MODE_TEXTURED); break;
    default: fragments = RASTER_CASE(MODE_PHONG); break;
    }
    if (probe)
        render_probe_fragment(f, t, before);
    return fragments;
}
