/* The z-buffer pipeline: vertex stage, triangle stage (culling, clipping,
 * setup, binning into tiles) and the tiled rasterizer, run by a small team
 * of threads.  Every tile is drawn by one thread from the triangles in mesh
 * order, so the picture does not depend on the number of threads. */
#include "internal.h"
#include "cg/color.h"

#include <pthread.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

/* ---- fragments ---------------------------------------------------------- */

enum { MODE_FLAT, MODE_GOURAUD, MODE_PHONG };

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

/* The covered run [*begin, *end) of a row whose edge functions are w at
 * pixel offset 0 and change by step per pixel, within [0, width): exact
 * integer bounds of where all three are >= 0. */
static inline void row_span(const int64_t w[3], const int64_t step[3], int width, int *begin,
                            int *end)
{
    int64_t lo = 0, hi = width; /* exclusive */
    for (int k = 0; k < 3; k++) {
        if (step[k] > 0) {
            if (w[k] < 0) {
                int64_t first = (-w[k] + step[k] - 1) / step[k];
                if (first > lo)
                    lo = first;
            }
        } else if (step[k] < 0) {
            if (w[k] < 0) {
                hi = 0;
            } else {
                int64_t last = w[k] / -step[k] + 1;
                if (last < hi)
                    hi = last;
            }
        } else if (w[k] < 0) {
            hi = 0;
        }
    }
    if (lo > width)
        lo = width;
    *begin = (int)lo;
    *end = (int)(hi > lo ? hi : lo);
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
    float ia, z0, dz1, dz2;        /* depth, as in raster_mode */
    float q[3], c[3][3];           /* 1 / w and colour / w: vertex 0, d1, d2 */
    float q_step, c_step[3];       /* their change per pixel to the right */
    int64_t step1, step2;          /* edge functions 1 and 2 per pixel */
} gouraud_plane;

#if defined(__SSE2__)
/* An opaque pixel from the three colours in lanes 0-2 of v (lane 3, 1 / w
 * in the Gouraud runs, is ignored): every lane rounded as the scalar encode
 * rounds it, so the pictures are identical, with a quarter of the work. */
static inline void encode_store(cg_rgba8 *p, __m128 v)
{
    cg_srgb_encode_rgb(p, v);
    p->a = 255;
}
#endif

static inline void gouraud_run(const gouraud_plane *g, int64_t w1, int64_t w2, float *zrow,
                               unsigned char *row, int x0, int begin, int end,
                               const int depth_test, const int rgba8)
{
#if defined(__SSE2__)
    if (rgba8) {
        const __m128 base = _mm_setr_ps(g->c[0][0], g->c[0][1], g->c[0][2], g->q[0]);
        const __m128 d1 = _mm_setr_ps(g->c[1][0], g->c[1][1], g->c[1][2], g->q[1]);
        const __m128 d2 = _mm_setr_ps(g->c[2][0], g->c[2][1], g->c[2][2], g->q[2]);
        const __m128 step = _mm_setr_ps(g->c_step[0], g->c_step[1], g->c_step[2], g->q_step);
        __m128 v = _mm_setzero_ps();
        cg_rgba8 *out = (cg_rgba8 *)row + x0;
        /* Locals: the byte stores below may alias anything in memory. */
        const int64_t step1 = g->step1, step2 = g->step2;
        const float ia = g->ia, z0 = g->z0, dz1 = g->dz1, dz2 = g->dz2;
        for (int i = begin, restart = begin; i < end;
             i++, w1 += step1, w2 += step2, v = _mm_add_ps(v, step)) {
            float l1 = (float)w1 * ia, l2 = (float)w2 * ia;
            if (i == restart) {
                v = _mm_add_ps(_mm_add_ps(base, _mm_mul_ps(_mm_set1_ps(l1), d1)),
                               _mm_mul_ps(_mm_set1_ps(l2), d2));
                restart += RENDER_TILE;
            }
            float z = z0 + l1 * dz1 + l2 * dz2;
            if (depth_test && !(z < zrow[i]))
                continue;
            zrow[i] = z;
            float r = 1 / _mm_cvtss_f32(_mm_shuffle_ps(v, v, 0xff));
            encode_store(out + i, _mm_mul_ps(v, _mm_set1_ps(r)));
        }
        return;
    }
#endif
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
#if defined(__SSE2__)
    if (rgba8) {
        __m128 v = _mm_add_ps(
            _mm_add_ps(_mm_setr_ps(g->c[0][0], g->c[0][1], g->c[0][2], g->q[0]),
                       _mm_mul_ps(_mm_set1_ps(l1),
                                  _mm_setr_ps(g->c[1][0], g->c[1][1], g->c[1][2], g->q[1]))),
            _mm_mul_ps(_mm_set1_ps(l2), _mm_setr_ps(g->c[2][0], g->c[2][1], g->c[2][2], g->q[2])));
        float r = 1 / _mm_cvtss_f32(_mm_shuffle_ps(v, v, 0xff));
        encode_store((cg_rgba8 *)row + x, _mm_mul_ps(v, _mm_set1_ps(r)));
        return;
    }
#endif
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

static RENDER_SPECIALIZE size_t raster_mode(const render_frame *f, const setup_triangle *t, int x0, int y0,
                                 int x1, int y1, const int mode, const int depth_test,
                                 const int rgba8)
{
    if (t->box[0] > x0) x0 = t->box[0];
    if (t->box[1] > y0) y0 = t->box[1];
    if (t->box[2] < x1) x1 = t->box[2];
    if (t->box[3] < y1) y1 = t->box[3];
    if (x0 >= x1 || y0 >= y1)
        return 0;
    raster_edges e;
    render_edges_at(t, x0, y0, &e);
    const float ia = t->inverse_area, z0 = t->z[0], dz1 = t->z[1] - z0, dz2 = t->z[2] - z0;
    const int n = f->attribute_count;
    float w_base = t->iw[0], w_d1 = t->iw[1] - t->iw[0], w_d2 = t->iw[2] - t->iw[0];
    float p_base[RENDER_MAX_ATTRIBUTES], p_d1[RENDER_MAX_ATTRIBUTES], p_d2[RENDER_MAX_ATTRIBUTES];
    if (mode == MODE_PHONG)
        for (int j = 0; j < n; j++) {
            p_base[j] = t->a[j] * t->iw[0];
            p_d1[j] = t->a[n + j] * t->iw[1] - p_base[j];
            p_d2[j] = t->a[2 * n + j] * t->iw[2] - p_base[j];
        }
    gouraud_plane gouraud;
    if (mode == MODE_GOURAUD)
        gouraud_setup(t, &e, ia, &gouraud);
    size_t fragments = 0;
    if (mode != MODE_PHONG && x1 - x0 <= TINY && y1 - y0 <= TINY) {
        /* A few pixels (most triangles of a finely tessellated mesh): each
         * tested and shaded on its own, without the runs' setup. */
        for (int y = y0; y < y1; y++, e.w[0] += e.step_y[0], e.w[1] += e.step_y[1],
                 e.w[2] += e.step_y[2]) {
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
    for (int y = y0; y < y1; y++, e.w[0] += e.step_y[0], e.w[1] += e.step_y[1],
             e.w[2] += e.step_y[2]) {
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
            row_span(e.w, e.step_x, x1 - x0, &begin, &end);
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
            zrow[i] = z;
            int x = x0 + i;
            if (mode == MODE_FLAT) {
                if (rgba8)
                    ((cg_rgba8 *)row)[x] = t->color8;
                else
                    store(row, x, t->color, rgba8);
                continue;
            }
            /* Perspective-correct: attribute / w and 1 / w are affine on
             * the screen; divide their interpolants. */
            float r = 1 / (w_base + l1 * w_d1 + l2 * w_d2);
            float v[RENDER_MAX_ATTRIBUTES];
            for (int j = 0; j < n; j++)
                v[j] = (p_base[j] + l1 * p_d1[j] + l2 * p_d2[j]) * r;
            float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            float inv = len > 0 ? 1 / len : 0;
            float normal[3] = {v[0] * inv, v[1] * inv, v[2] * inv}, c[3];
            render_shade(&f->lighting, v + 3, normal, n > 6 ? v + 6 : t->color, c);
            store(row, x, c, rgba8);
        }
    }
    return fragments;
}

#define RASTER_CASE(mode)                                                                  \
    (rgba8 ? (depth_test ? raster_mode(f, t, x0, y0, x1, y1, mode, 1, 1)                     \
                         : raster_mode(f, t, x0, y0, x1, y1, mode, 0, 1))                    \
           : (depth_test ? raster_mode(f, t, x0, y0, x1, y1, mode, 1, 0)                     \
                         : raster_mode(f, t, x0, y0, x1, y1, mode, 0, 0)))

size_t render_raster(const render_frame *f, const setup_triangle *t, int x0, int y0, int x1,
                     int y1, int depth_test)
{
    int rgba8 = f->image->format == CG_PIXEL_RGBA8;
    switch (f->shading) {
    case MODE_FLAT:
        return RASTER_CASE(MODE_FLAT);
    case MODE_GOURAUD:
        return RASTER_CASE(MODE_GOURAUD);
    default:
        return RASTER_CASE(MODE_PHONG);
    }
}

/* ---- vertex stage --------------------------------------------------------- */

/* Clip coordinates of a prepared position (double, so that clipping and
 * snapping see the exact product). */
static inline void clip_of(const render_frame *f, const float p[3], double c[4])
{
    double x = p[0], y = p[1], z = p[2];
    for (int k = 0; k < 4; k++)
        c[k] = f->mvp.m[k][0] * x + f->mvp.m[k][1] * y + f->mvp.m[k][2] * z + f->mvp.m[k][3];
}

static inline void world_of(const render_frame *f, const float p[3], float out[3])
{
    double x = p[0], y = p[1], z = p[2];
    for (int k = 0; k < 3; k++)
        out[k] = (float)(f->model.m[k][0] * x + f->model.m[k][1] * y + f->model.m[k][2] * z
                         + f->model.m[k][3]);
}

void render_clip_position(const render_frame *f, size_t i, double c[4])
{
    clip_of(f, f->r->vertices[i].position, c);
}

void render_world_position(const render_frame *f, size_t i, float out[3])
{
    world_of(f, f->r->vertices[i].position, out);
}

/* The attributes of vertex i (its lit colour for Gouraud; normal, world
 * position and colour for Phong) into out. */
static void compute_attributes(const render_frame *f, size_t i, float *out)
{
    const prepared_vertex *p = &f->r->vertices[i];
    const int n = f->attribute_count;
    float nx = p->normal[0], ny = p->normal[1], nz = p->normal[2], normal[3];
    for (int k = 0; k < 3; k++)
        normal[k] = f->normal_matrix[k][0] * nx + f->normal_matrix[k][1] * ny
                    + f->normal_matrix[k][2] * nz;
    float length = sqrtf(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    float inverse = length > 0 ? 1 / length : 0;
    for (int k = 0; k < 3; k++)
        normal[k] *= inverse;
    float world[3];
    if (f->shading == MODE_GOURAUD) {
        /* Only the specular term needs the position. */
        if (f->lighting.ks != 0)
            world_of(f, p->position, world);
        render_shade(&f->lighting, f->lighting.ks != 0 ? world : p->position, normal, p->color,
                     out);
    } else {
        world_of(f, p->position, world);
        memcpy(out, normal, sizeof normal);
        memcpy(out + 3, world, sizeof world);
        if (n > 6)
            memcpy(out + 6, p->color, sizeof p->color);
    }
}

/* The attributes of vertex i, computed the first time a triangle that is
 * drawn needs them: most vertices of a large mesh belong only to back faces
 * or to triangles that cover no pixel centre, and are never lit.  The
 * thread that moves the vertex's state from 0 to 1 computes them into the
 * frame's array and publishes them (state 2); a thread that finds them in
 * the making computes its own copy into local (the same bits: the same
 * function of the same inputs), so nobody waits for anybody. */
static const float *vertex_attributes(const render_frame *f, uint32_t i, float *local)
{
    float *a = f->attributes + (size_t)i * (size_t)f->attribute_count;
    unsigned char state = atomic_load_explicit(&f->states[i], memory_order_acquire);
    if (state == 2)
        return a;
    if (state == 0 && atomic_compare_exchange_strong_explicit(&f->states[i], &state, 1,
                                                              memory_order_acquire,
                                                              memory_order_acquire)) {
        compute_attributes(f, i, a);
        atomic_store_explicit(&f->states[i], 2, memory_order_release);
        return a;
    }
    if (state == 2)
        return a;
    compute_attributes(f, i, local);
    return local;
}

static void vertex_stage(render_frame *f, size_t begin, size_t end)
{
    const cg_renderer *r = f->r;
    for (size_t i = begin; i < end; i++) {
        const prepared_vertex *p = &r->vertices[i];
        frame_vertex *v = &f->vertices[i];
        double c[4];
        clip_of(f, p->position, c);
        v->outcode = (uint8_t)render_outcode(c);
        v->projected = v->outcode == 0 && c[3] > 0;
        if (v->projected) {
            /* Projected and snapped once here for all the triangles that
             * need no clipping (the clipped ones project the same way). */
            clip_vertex cv;
            screen_vertex s;
            memcpy(cv.c, c, sizeof cv.c);
            render_project(&cv, f->width, f->height, 0, &s);
            v->sx = render_snap(s.x, f->width);
            v->sy = render_snap(s.y, f->height);
            v->sz = (float)s.z;
            v->siw = (float)s.iw;
        }
        atomic_store_explicit(&f->states[i], 0, memory_order_relaxed);
    }
}

/* ---- triangle stage --------------------------------------------------------- */

static void *grow(void *buffer, size_t *capacity, size_t needed, size_t size)
{
    if (needed <= *capacity)
        return buffer;
    size_t capacity2 = *capacity ? *capacity : 64;
    while (capacity2 < needed)
        capacity2 *= 2;
    void *p = realloc(buffer, capacity2 * size);
    if (p)
        *capacity = capacity2;
    return p;
}

/* A buffer of the renderer kept between frames, with room for needed items
 * of size bytes; its contents are not kept when it has to be replaced.  NULL
 * (and capacity 0) when memory runs out. */
static void *reserve(void *buffer, size_t *capacity, size_t needed, size_t size)
{
    if (needed <= *capacity)
        return buffer;
    free(buffer);
    buffer = malloc(needed * size);
    *capacity = buffer ? needed : 0;
    return buffer;
}

/* Room for one more set-up triangle at the end of the chunk's list (with a
 * whole setup_triangle of slack after it, so that it may be written through
 * that type); NULL when memory runs out.  emit_setup keeps it. */
static setup_triangle *next_setup(render_frame *f, render_chunk *c)
{
    if (c->failed)
        return NULL;
    size_t needed = c->setup_count + 1 + f->setup_slack;
    if (needed <= c->setup_capacity)
        return (setup_triangle *)(c->setups + c->setup_count * f->stride);
    void *p = grow(c->setups, &c->setup_capacity, needed, f->stride);
    if (!p) {
        c->failed = 1;
        return NULL;
    }
    c->setups = p;
    return (setup_triangle *)(c->setups + c->setup_count * f->stride);
}

static void emit_setup(render_frame *f, render_chunk *c, const setup_triangle *t)
{
    setup_triangle *slot = next_setup(f, c);
    if (!slot)
        return;
    if (slot != t)
        memcpy(slot, t, f->stride);
    c->setup_count++;
}

static void emit_polygon(render_chunk *c, const screen_vertex *v, int n, const float color[3])
{
    if (c->failed)
        return;
    painter_polygon *p = grow(c->polygons, &c->polygon_capacity, c->polygon_count + 1,
                              sizeof *p);
    if (!p) {
        c->failed = 1;
        return;
    }
    c->polygons = p;
    painter_polygon *out = &c->polygons[c->polygon_count++];
    out->n = n;
    memcpy(out->color, color, sizeof out->color);
    memcpy(out->v, v, sizeof *v * (size_t)n);
}

/* Flat colour (or Phong base colour) of triangle i. */
static void triangle_color(const render_frame *f, size_t i, float out[3])
{
    const uint32_t *tri = f->r->triangles[i];
    const prepared_vertex *p0 = &f->r->vertices[tri[0]];
    if (f->fill_background) {
        memcpy(out, f->background, 3 * sizeof(float));
        return;
    }
    if (f->shading != MODE_FLAT) {
        memcpy(out, p0->color, 3 * sizeof(float));
        return;
    }
    float a[3], b[3], c[3];
    world_of(f, f->r->vertices[tri[0]].position, a);
    world_of(f, f->r->vertices[tri[1]].position, b);
    world_of(f, f->r->vertices[tri[2]].position, c);
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    float normal[3] = {0, 0, 0};
    if (length > 0)
        for (int k = 0; k < 3; k++)
            normal[k] = (float)(n[k] / length);
    float centre[3];
    for (int k = 0; k < 3; k++)
        centre[k] = (a[k] + b[k] + c[k]) / 3;
    render_shade(&f->lighting, centre, normal, p0->color, out);
}

void render_finish_setup(const render_frame *f, setup_triangle *t, const float color[3])
{
    memcpy(t->color, color, sizeof t->color);
    if (f->shading != MODE_FLAT)
        return; /* the encoded colour is for flat shading only */
    t->color8.r = cg_srgb_encode_unit(color[0]);
    t->color8.g = cg_srgb_encode_unit(color[1]);
    t->color8.b = cg_srgb_encode_unit(color[2]);
    t->color8.a = 255;
}


static void triangle_stage(render_frame *f, render_chunk *c, int painter)
{
    const int n = f->attribute_count;
    for (size_t i = c->begin; i < c->end; i++) {
        const uint32_t *tri = f->r->triangles[i];
        const frame_vertex *v[3] = {&f->vertices[tri[0]], &f->vertices[tri[1]],
                                    &f->vertices[tri[2]]};
        unsigned all = v[0]->outcode & v[1]->outcode & v[2]->outcode;
        unsigned any = v[0]->outcode | v[1]->outcode | v[2]->outcode;
        if ((any & 0x40) || all) {
            c->rejected++;
            continue;
        }
        if (!painter && v[0]->projected && v[1]->projected && v[2]->projected) {
            /* Inside the frustum: set up from the snapped vertices; back
             * faces leave before anything else is read. */
            int64_t area = (int64_t)(v[1]->sx - v[0]->sx) * (v[2]->sy - v[0]->sy)
                           - (int64_t)(v[1]->sy - v[0]->sy) * (v[2]->sx - v[0]->sx);
            if (area > 0 && f->cull) {
                c->culled++;
                continue;
            }
            render_corner corner[3];
            for (int k = 0; k < 3; k++) {
                corner[k].x = v[k]->sx;
                corner[k].y = v[k]->sy;
                corner[k].z = v[k]->sz;
                corner[k].iw = v[k]->siw;
                corner[k].a = NULL;
            }
            const render_corner *pc[3] = {&corner[0], &corner[1], &corner[2]};
            /* Set up in place at the end of the chunk's list, attributes
             * after: only triangles that cover a pixel need them. */
            setup_triangle *t = next_setup(f, c);
            if (!t)
                continue;
            int result = render_setup_fixed(pc, f->width, f->height, 0, f->cull, t);
            if (result < 0) {
                c->culled++;
                continue;
            }
            if (result == 0) {
                c->rejected++;
                continue;
            }
            if (n > 0) {
                /* In the setup's order: turned around unless clockwise. */
                static const int turned[3] = {0, 2, 1}, kept[3] = {0, 1, 2};
                const int *order = area > 0 ? kept : turned;
                float local[RENDER_MAX_ATTRIBUTES];
                for (int k = 0; k < 3; k++)
                    memcpy(t->a + k * n, vertex_attributes(f, tri[order[k]], local),
                           sizeof(float) * (size_t)n);
            }
            float color[3];
            triangle_color(f, i, color);
            render_finish_setup(f, t, color);
            emit_setup(f, c, t);
            continue;
        }
        clip_vertex in[3], polygon[RENDER_MAX_POLYGON];
        for (int k = 0; k < 3; k++) {
            render_clip_position(f, tri[k], in[k].c);
            if (n > 0) {
                const float *a = vertex_attributes(f, tri[k], in[k].a);
                if (a != in[k].a)
                    memcpy(in[k].a, a, sizeof(float) * (size_t)n);
            }
        }
        int count = 3;
        const clip_vertex *corners = in;
        if (any) {
            c->clipped++;
            count = render_clip_polygon(in, 3, any, n, polygon);
            corners = polygon;
        }
        screen_vertex s[RENDER_MAX_POLYGON];
        int usable = count >= 3;
        for (int k = 0; k < count; k++) {
            if (!(corners[k].c[3] > 0))
                usable = 0;
            render_project(&corners[k], f->width, f->height, n, &s[k]);
        }
        if (!usable) {
            c->rejected++;
            continue;
        }
        float color[3];
        int colored = 0;
        if (painter) {
            triangle_color(f, i, color);
            /* Culling by the orientation of the whole polygon. */
            double area = 0;
            for (int k = 0; k < count; k++) {
                const screen_vertex *p = &s[k], *q = &s[(k + 1) % count];
                area += (q->x - p->x) * (q->y + p->y);
            }
            /* area > 0 for polygons the camera sees counter-clockwise (front). */
            if (f->cull && area <= 0) {
                c->culled++;
                continue;
            }
            emit_polygon(c, s, count, color);
            continue;
        }
        int culled = 0, emitted = 0;
        for (int k = 1; k + 1 < count; k++) {
            setup_triangle t;
            int result = render_setup(&s[0], &s[k], &s[k + 1], f->width, f->height, n, f->cull,
                                      &t);
            if (result < 0)
                culled = 1;
            if (result != 1)
                continue;
            if (!colored) {
                /* Lit only once the triangle is known to be visible. */
                triangle_color(f, i, color);
                colored = 1;
            }
            render_finish_setup(f, &t, color);
            emit_setup(f, c, &t);
            emitted++;
        }
        if (culled && !emitted)
            c->culled++;
        else if (!emitted)
            c->rejected++;
    }
}

/* Tile lists of one chunk (counting sort by tile, mesh order kept), in
 * buffers kept from frame to frame. */
static void bin_chunk(render_frame *f, render_chunk *c)
{
    if (c->failed)
        return;
    size_t tiles = (size_t)f->tile_count;
    if (c->bin_start_capacity < tiles) {
        free(c->bin_start);
        free(c->bin_fill);
        c->bin_start = malloc((tiles + 1) * sizeof *c->bin_start);
        c->bin_fill = malloc(tiles * sizeof *c->bin_fill);
        c->bin_start_capacity = c->bin_start && c->bin_fill ? tiles : 0;
        if (!c->bin_start_capacity) {
            c->failed = 1;
            return;
        }
    }
    uint32_t *start = c->bin_start, *fill = c->bin_fill;
    memset(start, 0, (tiles + 1) * sizeof *start);
    size_t total = 0;
    for (size_t i = 0; i < c->setup_count; i++) {
        const setup_triangle *t = (const setup_triangle *)(c->setups + i * f->stride);
        int tx0 = t->box[0] / RENDER_TILE, tx1 = (t->box[2] - 1) / RENDER_TILE;
        int ty0 = t->box[1] / RENDER_TILE, ty1 = (t->box[3] - 1) / RENDER_TILE;
        for (int ty = ty0; ty <= ty1; ty++)
            for (int tx = tx0; tx <= tx1; tx++)
                start[ty * f->tiles_x + tx + 1]++;
        total += (size_t)(tx1 - tx0 + 1) * (size_t)(ty1 - ty0 + 1);
    }
    if (total > UINT32_MAX) {
        c->failed = 1;
        return;
    }
    for (size_t t = 0; t < tiles; t++)
        start[t + 1] += start[t];
    void *list = grow(c->bin_list, &c->bin_capacity, total ? total : 1, sizeof *c->bin_list);
    if (!list) {
        c->failed = 1;
        return;
    }
    c->bin_list = list;
    memcpy(fill, start, tiles * sizeof *fill);
    for (size_t i = 0; i < c->setup_count; i++) {
        const setup_triangle *t = (const setup_triangle *)(c->setups + i * f->stride);
        int tx0 = t->box[0] / RENDER_TILE, tx1 = (t->box[2] - 1) / RENDER_TILE;
        int ty0 = t->box[1] / RENDER_TILE, ty1 = (t->box[3] - 1) / RENDER_TILE;
        for (int ty = ty0; ty <= ty1; ty++)
            for (int tx = tx0; tx <= tx1; tx++)
                c->bin_list[fill[ty * f->tiles_x + tx]++] = (uint32_t)i;
    }
}

/* ---- the team of threads ------------------------------------------------------ */

#define VERTEX_BLOCK 4096   /* vertices taken at a time */
#define TRIANGLE_BLOCK 1024 /* triangles per chunk, up to MAX_CHUNKS chunks */
#define MAX_CHUNKS 64

/* One frame's work: three phases (vertex blocks, triangle chunks, tiles),
 * each a set of blocks that threads take from a counter and count when done.
 * A thread moves to the next phase once every block of this one is done; it
 * never waits for a thread that has taken nothing, so a worker the
 * scheduler has not run yet (the machine busy with other work) holds up
 * nobody, and the caller may do the whole frame alone. */
typedef struct team {
    render_frame *frame;
    pthread_mutex_t *lock;      /* the pool's, NULL for the caller alone */
    pthread_cond_t *phase;      /* signalled when a phase completes */
    atomic_size_t next_vertex_block, vertex_blocks_done;
    atomic_size_t next_chunk, chunks_done;
    atomic_size_t next_tile, tiles_done;
    int painter;
    size_t fragments[64];
} team;

/* Counts one block of a phase of `total` done and returns the count; the
 * last one wakes the threads waiting for the phase. */
static size_t block_done(team *tm, atomic_size_t *done, size_t total)
{
    size_t count = atomic_fetch_add(done, 1) + 1;
    if (count == total && tm->lock) {
        pthread_mutex_lock(tm->lock);
        pthread_cond_broadcast(tm->phase);
        pthread_mutex_unlock(tm->lock);
    }
    return count;
}

/* Waits until every block of a phase is done: called once no block is left
 * to take, so only blocks other threads are working on can be missing. */
static void phase_wait(team *tm, atomic_size_t *done, size_t total)
{
    if (atomic_load(done) >= total || !tm->lock)
        return;
    pthread_mutex_lock(tm->lock);
    while (atomic_load(done) < total)
        pthread_cond_wait(tm->phase, tm->lock);
    pthread_mutex_unlock(tm->lock);
}

/* The renderer's worker threads, started at its first frame with more than
 * one thread and kept until the thread count changes or the renderer is
 * freed: starting threads for every frame costs, and a new thread often
 * waits for the scheduler to move it to an idle core, while a kept one
 * wakes on the core it last ran on.  The calling thread is worker 0. */
typedef struct render_pool {
    pthread_mutex_t lock;
    pthread_cond_t wake, idle, phase;
    int threads;                /* started besides the caller */
    int inside;                 /* threads working on the open frame */
    int quit;
    unsigned long generation;   /* frames handed out */
    team *team;                 /* the open frame's; NULL once it is closed */
    pthread_t ids[63];
    struct pool_worker {
        struct render_pool *pool;
        int index;
    } workers[64];
} render_pool;

#if defined(__SSE2__)
/* Fills `rows` rows of `bytes` bytes (a multiple of 4), `stride` bytes
 * apart, with a 16-byte pattern that repeats every 4 bytes (or fills whole
 * 16-byte units); with `stream`, past the caches when the rows are
 * aligned. */
static void fill_rows(unsigned char *p, size_t stride, int rows, size_t bytes, __m128i pattern,
                      int stream)
{
    size_t whole = bytes & ~(size_t)15;
    stream = stream && (uintptr_t)p % 16 == 0 && stride % 16 == 0;
    unsigned char tail[16];
    _mm_storeu_si128((__m128i *)tail, pattern);
    for (int y = 0; y < rows; y++, p += stride) {
        if (stream)
            for (size_t i = 0; i < whole; i += 16)
                _mm_stream_si128((__m128i *)(p + i), pattern);
        else
            for (size_t i = 0; i < whole; i += 16)
                _mm_storeu_si128((__m128i *)(p + i), pattern);
        if (whole < bytes)
            memcpy(p + whole, tail, bytes - whole);
    }
    if (stream)
        _mm_sfence();
}
#endif

/* Clears a rectangle to the background colour and (with depth) infinite
 * depth; tiles no triangle touches are streamed past the caches (stream),
 * which saves reading their lines first and keeps the caches for the tiles
 * drawn. */
static void clear_tile(render_frame *f, int x0, int y0, int x1, int y1, int stream, int depth)
{
    size_t width = (size_t)(x1 - x0);
    size_t pixel = f->image->format == CG_PIXEL_RGBA8 ? sizeof(cg_rgba8) : sizeof(cg_rgbaf);
#if defined(__SSE2__)
    __m128i color;
    if (f->image->format == CG_PIXEL_RGBA8) {
        uint32_t code;
        memcpy(&code, &f->background8, sizeof code);
        color = _mm_set1_epi32((int)code);
    } else {
        color = _mm_castps_si128(_mm_loadu_ps(f->background));
    }
    if (depth)
        fill_rows((unsigned char *)(f->depth + (size_t)y0 * f->width + x0),
                  (size_t)f->width * sizeof(float), y1 - y0, width * sizeof(float),
                  _mm_castps_si128(_mm_set1_ps(INFINITY)), stream);
    fill_rows(f->image->data + (size_t)y0 * f->image->stride + (size_t)x0 * pixel,
              f->image->stride, y1 - y0, width * pixel, color, stream);
#else
    (void)stream;
    const cg_rgbaf background = {f->background[0], f->background[1], f->background[2],
                                 f->background[3]};
    /* The first row by hand, the others copied from it. */
    float *z0 = f->depth + (size_t)y0 * f->width + x0;
    if (depth)
        for (size_t x = 0; x < width; x++)
            z0[x] = INFINITY;
    if (f->image->format == CG_PIXEL_RGBA8) {
        cg_rgba8 *row = cg_image_row_rgba8(f->image, y0) + x0;
        for (size_t x = 0; x < width; x++)
            row[x] = f->background8;
    } else {
        cg_rgbaf *row = cg_image_row_rgbaf(f->image, y0) + x0;
        for (size_t x = 0; x < width; x++)
            row[x] = background;
    }
    const unsigned char *first = f->image->data + (size_t)y0 * f->image->stride + (size_t)x0 * pixel;
    for (int y = y0 + 1; y < y1; y++) {
        if (depth)
            memcpy(f->depth + (size_t)y * f->width + x0, z0, width * sizeof *z0);
        memcpy(f->image->data + (size_t)y * f->image->stride + (size_t)x0 * pixel, first,
               width * pixel);
    }
#endif
}

static void work(team *tm, int index)
{
    render_frame *f = tm->frame;
    int chunks = f->chunk_count;
    /* Vertex stage and triangle stage in blocks taken from shared counters:
     * a thread slowed down (by other work on the machine) holds up the
     * others by one block at most.  The blocks depend on the mesh only,
     * and each lands in its own place, so the result does not depend on
     * which thread took which. */
    size_t vertices = f->r->vertex_count;
    size_t blocks = (vertices + VERTEX_BLOCK - 1) / VERTEX_BLOCK;
    for (;;) {
        size_t b = atomic_fetch_add(&tm->next_vertex_block, 1);
        if (b >= blocks)
            break;
        size_t end = (b + 1) * VERTEX_BLOCK;
        vertex_stage(f, b * VERTEX_BLOCK, end < vertices ? end : vertices);
        block_done(tm, &tm->vertex_blocks_done, blocks);
    }
    phase_wait(tm, &tm->vertex_blocks_done, blocks);
    for (;;) {
        size_t i = atomic_fetch_add(&tm->next_chunk, 1);
        if (i >= (size_t)chunks)
            break;
        /* Worked on in a local copy: the chunks other threads work on lie
         * next to it, and counting in place would bounce the shared cache
         * lines between the cores at every triangle. */
        render_chunk chunk = f->chunks[i];
        triangle_stage(f, &chunk, tm->painter);
        if (!tm->painter)
            bin_chunk(f, &chunk);
        f->chunks[i] = chunk;
        block_done(tm, &tm->chunks_done, (size_t)chunks);
    }
    phase_wait(tm, &tm->chunks_done, (size_t)chunks);
    if (tm->painter)
        return;
    int failed = 0;
    for (int i = 0; i < chunks; i++)
        failed |= f->chunks[i].failed;
    if (failed)
        return;
    size_t fragments = 0;
    for (;;) {
        size_t claimed = atomic_fetch_add(&tm->next_tile, 1);
        if (claimed >= (size_t)f->tile_count)
            break;
        int tile = (int)claimed;
        int x0 = tile % f->tiles_x * RENDER_TILE, y0 = tile / f->tiles_x * RENDER_TILE;
        int x1 = x0 + RENDER_TILE < f->width ? x0 + RENDER_TILE : f->width;
        int y1 = y0 + RENDER_TILE < f->height ? y0 + RENDER_TILE : f->height;
        int empty = 1;
        for (int i = 0; i < chunks && empty; i++)
            empty = f->chunks[i].bin_start[tile] == f->chunks[i].bin_start[tile + 1];
        /* The depth of a tile left empty since it was last cleared is
         * still infinite: only its colour (the caller's image) is written. */
        clear_tile(f, x0, y0, x1, y1, empty, !(empty && f->clean_tiles[tile]));
        f->clean_tiles[tile] = (unsigned char)empty;
        for (int i = 0; i < chunks; i++) {
            const render_chunk *c = &f->chunks[i];
            for (uint32_t k = c->bin_start[tile]; k < c->bin_start[tile + 1]; k++) {
                const setup_triangle *t =
                    (const setup_triangle *)(c->setups + (size_t)c->bin_list[k] * f->stride);
                fragments += render_raster(f, t, x0, y0, x1, y1, 1);
            }
        }
        size_t done = block_done(tm, &tm->tiles_done, (size_t)f->tile_count);
        if (index == 0 && f->o->progress)
            f->o->progress(f->o->progress_user, (double)done / f->tile_count);
    }
    tm->fragments[index] = fragments;
    if (index == 0)
        phase_wait(tm, &tm->tiles_done, (size_t)f->tile_count);
}

static void *pool_main(void *argument)
{
    struct pool_worker *w = argument;
    render_pool *p = w->pool;
    unsigned long seen = 0;
    pthread_mutex_lock(&p->lock);
    for (;;) {
        while (p->generation == seen && !p->quit)
            pthread_cond_wait(&p->wake, &p->lock);
        if (p->quit)
            break;
        seen = p->generation;
        team *tm = p->team;
        if (!tm)
            continue; /* woken too late: the caller finished the frame */
        p->inside++;
        pthread_mutex_unlock(&p->lock);
        work(tm, w->index);
        pthread_mutex_lock(&p->lock);
        if (--p->inside == 0)
            pthread_cond_signal(&p->idle);
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

static void pool_stop(render_pool *p)
{
    if (!p)
        return;
    pthread_mutex_lock(&p->lock);
    p->quit = 1;
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    for (int i = 0; i < p->threads; i++)
        pthread_join(p->ids[i], NULL);
    pthread_cond_destroy(&p->wake);
    pthread_cond_destroy(&p->idle);
    pthread_cond_destroy(&p->phase);
    pthread_mutex_destroy(&p->lock);
    free(p);
}

/* A pool for `threads` threads in all (the caller included); NULL when no
 * other thread can be started, and then the caller works alone.  Threads
 * that cannot be started leave their share to the others. */
static render_pool *pool_start(int threads)
{
    render_pool *p = calloc(1, sizeof *p);
    if (!p)
        return NULL;
    int made = 0; /* synchronization objects initialized */
    made += pthread_mutex_init(&p->lock, NULL) == 0;
    made += made == 1 && pthread_cond_init(&p->wake, NULL) == 0;
    made += made == 2 && pthread_cond_init(&p->idle, NULL) == 0;
    made += made == 3 && pthread_cond_init(&p->phase, NULL) == 0;
    if (made == 4)
        for (int i = 1; i < threads; i++) {
            p->workers[i].pool = p;
            p->workers[i].index = i;
            if (pthread_create(&p->ids[i - 1], NULL, pool_main, &p->workers[i]) != 0)
                break;
            p->threads++;
        }
    if (p->threads > 0)
        return p;
    if (made > 3)
        pthread_cond_destroy(&p->phase);
    if (made > 2)
        pthread_cond_destroy(&p->idle);
    if (made > 1)
        pthread_cond_destroy(&p->wake);
    if (made > 0)
        pthread_mutex_destroy(&p->lock);
    free(p);
    return NULL;
}

/* Runs this frame's work on the caller and the pool's threads. */
static void pool_run(render_pool *p, team *tm)
{
    if (!p) {
        work(tm, 0);
        return;
    }
    tm->lock = &p->lock;
    tm->phase = &p->phase;
    pthread_mutex_lock(&p->lock);
    p->team = tm;
    p->generation++;
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    work(tm, 0);
    /* Closed: threads that wake from now on leave it alone; the caller
     * waits only for those already working on it. */
    pthread_mutex_lock(&p->lock);
    p->team = NULL;
    while (p->inside > 0)
        pthread_cond_wait(&p->idle, &p->lock);
    pthread_mutex_unlock(&p->lock);
}

/* ---- a frame ---------------------------------------------------------------------- */

static cg_status frame_camera(cg_renderer *r, double aspect, cg_camera *camera)
{
    *camera = r->options.camera;
    if (!r->options.frame_camera || !r->has_bounds)
        return CG_OK;
    /* World bounds of the model-space box. */
    cg_vec3 lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < 8; i++) {
        cg_vec3 p = {(i & 1) ? r->hi.x : r->lo.x, (i & 2) ? r->hi.y : r->lo.y,
                     (i & 4) ? r->hi.z : r->lo.z};
        p = cg_mat4_transform_point(r->options.model, p);
        lo = cg_vec3_make(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
        hi = cg_vec3_make(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
    }
    return cg_camera_frame(camera, lo, hi, aspect);
}

cg_light cg_render_key_light(cg_mat4 view)
{
    /* From the camera's upper left, a little in front (view space). */
    cg_vec3 d = cg_vec3_normalize(cg_vec3_make(-1, 1, 1.5));
    /* View-space direction to world: the view's rotation is orthonormal,
     * so its inverse is its transpose. */
    cg_vec3 world = {view.m[0][0] * d.x + view.m[1][0] * d.y + view.m[2][0] * d.z,
                     view.m[0][1] * d.x + view.m[1][1] * d.y + view.m[2][1] * d.z,
                     view.m[0][2] * d.x + view.m[1][2] * d.y + view.m[2][2] * d.z};
    return cg_light_directional(cg_vec3_scale(world, -1), cg_vec3_make(0.85, 0.85, 0.85));
}

static void setup_lighting(render_frame *f, const cg_camera *camera, const cg_mat4 *view)
{
    const cg_render_options *o = f->o;
    render_lighting *l = &f->lighting;
    /* White lights; ka, kd = 1 and ks of the options; Blinn-Phong. */
    l->material = cg_material_make(cg_vec3_make(1, 1, 1), o->ambient, 1, o->specular,
                                   o->shininess);
    l->material.specular = CG_SPECULAR_BLINN;
    if (o->specular == 0)
        l->material.shininess = 1; /* the term is zero anyway: spare its power */
    l->orthographic = camera->orthographic;
    l->eye[0] = (float)camera->eye.x;
    l->eye[1] = (float)camera->eye.y;
    l->eye[2] = (float)camera->eye.z;
    cg_vec3 back = cg_vec3_normalize(cg_vec3_sub(camera->eye, camera->target));
    l->view_dir[0] = (float)back.x;
    l->view_dir[1] = (float)back.y;
    l->view_dir[2] = (float)back.z;
    l->lights[0] = cg_light_ambient(cg_vec3_make(1, 1, 1));
    if (o->light_count == 0) {
        l->lights[1] = cg_render_key_light(*view);
        l->count = 2;
    } else {
        /* The options name the direction toward each light; cg_light the
         * way its light travels. */
        for (int i = 0; i < o->light_count; i++) {
            double k = o->lights[i].intensity;
            l->lights[i + 1] = cg_light_directional(cg_vec3_scale(o->lights[i].direction, -1),
                                                    cg_vec3_make(k, k, k));
        }
        l->count = o->light_count + 1;
    }
    render_lighting_prepare(l);
}

void render_buffers_free(cg_renderer *r)
{
    pool_stop(r->pool);
    r->pool = NULL;
    r->pool_threads = 0;
    for (int i = 0; i < r->chunk_count; i++) {
        free(r->chunks[i].setups);
        free(r->chunks[i].bin_start);
        free(r->chunks[i].bin_fill);
        free(r->chunks[i].bin_list);
        free(r->chunks[i].polygons);
    }
    free(r->chunks);
    r->chunks = NULL;
    r->chunk_count = 0;
    free(r->frame_vertices);
    free(r->frame_attributes);
    free(r->frame_states);
    free(r->clean_tiles);
    r->clean_tiles = NULL;
    r->clean_tile_capacity = 0;
    r->frame_vertices = NULL;
    r->frame_attributes = NULL;
    r->frame_states = NULL;
    r->frame_vertex_capacity = r->frame_attribute_capacity = r->frame_state_capacity = 0;
}

/* The frame's vertex buffers, kept by the renderer. */
static cg_status frame_vertex_buffers(render_frame *f)
{
    cg_renderer *r = f->r;
    size_t count = r->vertex_count ? r->vertex_count : 1;
    size_t floats = count * (size_t)(f->attribute_count ? f->attribute_count : 1);
    r->frame_vertices = reserve(r->frame_vertices, &r->frame_vertex_capacity, count,
                                sizeof *r->frame_vertices);
    r->frame_attributes = reserve(r->frame_attributes, &r->frame_attribute_capacity, floats,
                                  sizeof *r->frame_attributes);
    r->frame_states = reserve(r->frame_states, &r->frame_state_capacity, count,
                              sizeof *r->frame_states);
    if (!r->frame_vertices || !r->frame_attributes || !r->frame_states)
        return CG_ENOMEM;
    f->vertices = r->frame_vertices;
    f->attributes = r->frame_attributes;
    f->states = r->frame_states;
    return CG_OK;
}

/* The triangle ranges of the triangle stage, their buffers kept by the
 * renderer and emptied: one per TRIANGLE_BLOCK triangles, at most
 * MAX_CHUNKS, a number that depends on the mesh only. */
static cg_status frame_chunks(render_frame *f)
{
    cg_renderer *r = f->r;
    size_t wanted = (r->triangle_count + TRIANGLE_BLOCK - 1) / TRIANGLE_BLOCK;
    f->chunk_count = wanted < 1 ? 1 : wanted > MAX_CHUNKS ? MAX_CHUNKS : (int)wanted;
    if (r->chunk_count < f->chunk_count) {
        render_chunk *chunks = realloc(r->chunks, (size_t)f->chunk_count * sizeof *chunks);
        if (!chunks)
            return CG_ENOMEM;
        memset(chunks + r->chunk_count, 0,
               (size_t)(f->chunk_count - r->chunk_count) * sizeof *chunks);
        r->chunks = chunks;
        r->chunk_count = f->chunk_count;
    }
    for (int i = 0; i < f->chunk_count; i++) {
        render_chunk *c = &r->chunks[i];
        c->begin = r->triangle_count * (size_t)i / (size_t)f->chunk_count;
        c->end = r->triangle_count * (size_t)(i + 1) / (size_t)f->chunk_count;
        /* The capacity counts set-ups of the last frame's size. */
        if (c->setup_stride != f->stride) {
            c->setup_capacity = c->setup_stride ? c->setup_capacity * c->setup_stride / f->stride : 0;
            c->setup_stride = f->stride;
        }
        c->setup_count = c->polygon_count = 0;
        c->culled = c->clipped = c->rejected = c->rasterized = 0;
        c->failed = 0;
    }
    f->chunks = r->chunks;
    return CG_OK;
}

cg_status cg_renderer_draw(cg_renderer *r, cg_image *image)
{
    if (!r || !image || !image->data || image->width <= 0 || image->height <= 0
        || (image->format != CG_PIXEL_RGBA8 && image->format != CG_PIXEL_RGBAF))
        return CG_EINVAL;
    if (image->width > CG_RASTER_MAX_SIDE || image->height > CG_RASTER_MAX_SIDE)
        return CG_ERANGE;
    const cg_render_options *o = &r->options;
    memset(&r->stats, 0, sizeof r->stats);
    r->stats.triangles = r->triangle_count;
    r->depth_valid = 0;
    render_frame f;
    memset(&f, 0, sizeof f);
    f.r = r;
    f.o = o;
    f.image = image;
    f.width = image->width;
    f.height = image->height;
    double aspect = (double)f.width / f.height;
    cg_camera camera;
    cg_mat4 view, projection;
    if (frame_camera(r, aspect, &camera) != CG_OK || cg_camera_view(&camera, &view) != CG_OK
        || cg_camera_projection(&camera, aspect, &projection) != CG_OK)
        return CG_EINVAL;
    r->camera = camera;
    f.model = o->model;
    f.mvp = cg_mat4_mul(projection, cg_mat4_mul(view, o->model));
    cg_mat4 inverse;
    if (cg_mat4_inverse(o->model, &inverse) != CG_OK)
        return CG_EINVAL;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            f.normal_matrix[i][j] = (float)inverse.m[j][i];
    setup_lighting(&f, &camera, &view);
    f.fill_background = o->edges == CG_EDGES_HIDDEN_LINE;
    f.shading = f.fill_background ? MODE_FLAT : (int)o->shading;
    f.attribute_count = f.shading == MODE_FLAT ? 0 : f.shading == MODE_GOURAUD ? 3
                        : r->varying_color ? 9 : 6;
    f.cull = o->cull == CG_CULL_BACK;
    f.background[0] = o->background.r;
    f.background[1] = o->background.g;
    f.background[2] = o->background.b;
    f.background[3] = o->background.a;
    f.background8 = cg_linear_to_rgba8(o->background);
    f.stride = SETUP_SIZE(f.attribute_count);
    f.setup_slack = (sizeof(setup_triangle) + f.stride - 1) / f.stride;
    f.tiles_x = (f.width + RENDER_TILE - 1) / RENDER_TILE;
    f.tiles_y = (f.height + RENDER_TILE - 1) / RENDER_TILE;
    f.tile_count = f.tiles_x * f.tiles_y;
    size_t pixels = (size_t)f.width * (size_t)f.height;
    if (r->depth_size < pixels) {
        float *depth = realloc(r->depth, pixels * sizeof *depth);
        if (!depth)
            return CG_ENOMEM;
        r->depth = depth;
        r->depth_size = pixels;
    }
    f.depth = r->depth;
    /* Which tiles hold infinite depth from an earlier frame of this size. */
    int same_layout = r->depth_width == f.width && r->depth_height == f.height;
    if (r->clean_tile_capacity < (size_t)f.tile_count) {
        r->clean_tiles = reserve(r->clean_tiles, &r->clean_tile_capacity, (size_t)f.tile_count, 1);
        if (!r->clean_tiles)
            return CG_ENOMEM;
        same_layout = 0;
    }
    if (!same_layout)
        memset(r->clean_tiles, 0, (size_t)f.tile_count);
    f.clean_tiles = r->clean_tiles;
    r->depth_width = f.width;
    r->depth_height = f.height;

    /* Whole-object culling: the bounding box against the six planes. */
    unsigned all = 0x3f;
    if (r->has_bounds) {
        for (int i = 0; i < 8; i++) {
            cg_vec3 p = {(i & 1) ? r->hi.x : r->lo.x, (i & 2) ? r->hi.y : r->lo.y,
                         (i & 4) ? r->hi.z : r->lo.z};
            cg_vec4 c = cg_mat4_mul_vec4(f.mvp, cg_vec4_from_point(p));
            double cc[4] = {c.x, c.y, c.z, c.w};
            all &= render_outcode(cc);
        }
    }
    if (all || r->triangle_count == 0 || o->edges == CG_EDGES_WIREFRAME) {
        r->stats.object_culled = all != 0 && r->has_bounds;
        clear_tile(&f, 0, 0, f.width, f.height, 0, 1);
        memset(f.clean_tiles, 1, (size_t)f.tile_count);
        r->depth_valid = 1;
        if (o->edges == CG_EDGES_WIREFRAME && !all && r->triangle_count) {
            if (frame_vertex_buffers(&f) != CG_OK)
                return CG_ENOMEM;
            vertex_stage(&f, 0, r->vertex_count);
            r->depth_valid = 0;
            return render_edges(&f);
        }
        return CG_OK;
    }

    f.thread_count = o->threads;
    if ((size_t)f.thread_count > r->triangle_count)
        f.thread_count = (int)r->triangle_count;
    if (frame_vertex_buffers(&f) != CG_OK || frame_chunks(&f) != CG_OK)
        return CG_ENOMEM;
    team tm;
    memset(&tm, 0, sizeof tm);
    tm.frame = &f;
    tm.painter = o->algorithm != CG_RENDER_ZBUFFER;
    atomic_init(&tm.next_vertex_block, 0);
    atomic_init(&tm.vertex_blocks_done, 0);
    atomic_init(&tm.next_chunk, 0);
    atomic_init(&tm.chunks_done, 0);
    atomic_init(&tm.next_tile, 0);
    atomic_init(&tm.tiles_done, 0);
    if (f.thread_count > 1 && r->pool_threads != f.thread_count) {
        pool_stop(r->pool);
        r->pool = pool_start(f.thread_count);
        r->pool_threads = f.thread_count;
    }
    pool_run(f.thread_count > 1 ? r->pool : NULL, &tm);
    cg_status status = CG_OK;
    for (int i = 0; i < f.chunk_count && status == CG_OK; i++) {
        render_chunk *c = &f.chunks[i];
        if (c->failed)
            status = CG_ENOMEM;
        r->stats.culled += c->culled;
        r->stats.clipped += c->clipped;
        r->stats.rejected += c->rejected;
        r->stats.rasterized += c->setup_count;
    }
    for (int i = 0; i < f.thread_count; i++)
        r->stats.fragments += tm.fragments[i];
    if (status == CG_OK && tm.painter) {
        memset(f.clean_tiles, 0, (size_t)f.tile_count); /* painted over everywhere */
        status = render_painter(&f);
    }
    if (status == CG_OK) {
        r->depth_valid = 1;
        r->stats.splits = f.splits;
        if (o->edges == CG_EDGES_HIDDEN_LINE || o->edges == CG_EDGES_OVERLAY)
            status = render_edges(&f);
    }
    return status;
}
