/* Shading at one pixel, step by step (cg/trace_steps.h): while
 * cg_shading_pixel_steps draws a frame, render_raster hands every triangle
 * it rasterizes over the probed pixel to render_probe_fragment, which
 * reports the fragment there: its screen barycentric coordinates from the
 * rasterizer's own edge functions, the perspective-correct weights, the
 * depth test, and the values the shading mode interpolates:
 *
 *   flat:     one colour per face, lit once at setup
 *   Gouraud:  the colours lit at the vertices, interpolated
 *   Phong:    the normals (and positions, colours) interpolated, the
 *             normal renormalized, then lit at the pixel:
 *             ambient + kd base sum c (N.L) + ks sum c spec
 *
 * The pixel the frame ends with is the renderer's own. */
#include "internal.h"
#include "pipeline.h"
#include "../core/steps.h"

#include <string.h>

static void reals(core_step *s, const char *name, const float *v, int n, double *store)
{
    for (int i = 0; i < n; i++)
        store[i] = v[i];
    core_step_reals(s, name, store, (size_t)n);
}

/* The interpolated attributes: sum of b_k a_k with the perspective-correct
 * weights b. */
static void interpolate(const setup_triangle *t, int n, int from, int count, const double b[3],
                        float *out)
{
    for (int j = 0; j < count; j++)
        out[j] = (float)(b[0] * t->a[from + j] + b[1] * t->a[n + from + j]
                         + b[2] * t->a[2 * n + from + j]);
}

static void mode_fields(const render_frame *f, const setup_triangle *t, core_step *s,
                        const double b[3], double store[8][9])
{
    const int n = f->attribute_count;
    float v[9], w[9];
    if (f->shading == MODE_FLAT) {
        core_step_text(s, "mode", "flat: the face's colour, lit once");
        reals(s, "color", t->color, 3, store[0]);
        return;
    }
    if (f->shading == MODE_GOURAUD) {
        core_step_text(s, "mode", "Gouraud: vertex colours interpolated");
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++)
                w[3 * k + j] = t->a[k * n + j];
        reals(s, "vertex_colors", w, 9, store[0]);
        interpolate(t, n, 0, 3, b, v);
        reals(s, "color", v, 3, store[1]);
        return;
    }
    if (f->shading != MODE_PHONG) {
        core_step_text(s, "mode", "per-pixel textured or unlit: not traced further");
        return;
    }
    core_step_text(s, "mode", "Phong: normals interpolated, lit per pixel");
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 3; j++)
            w[3 * k + j] = t->a[k * n + j];
    reals(s, "vertex_normals", w, 9, store[0]);
    interpolate(t, n, 0, n > 6 ? 9 : 6, b, v);
    float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), inv = len > 0 ? 1 / len : 0;
    float normal[3] = {v[0] * inv, v[1] * inv, v[2] * inv};
    const float *base = n > 6 ? v + 6 : t->color;
    reals(s, "N", normal, 3, store[1]);
    reals(s, "position", v + 3, 3, store[2]);
    reals(s, "base", base, 3, store[3]);
    float ambient[3], diffuse[3], specular[3], color[3];
    render_shade_terms(&f->lighting, v + 3, normal, base, ambient, diffuse, specular);
    for (int j = 0; j < 3; j++)
        color[j] = ambient[j] + diffuse[j] + specular[j];
    reals(s, "ambient", ambient, 3, store[4]);
    reals(s, "diffuse", diffuse, 3, store[5]);
    reals(s, "specular", specular, 3, store[6]);
    reals(s, "color", color, 3, store[7]);
}

void render_probe_fragment(const render_frame *f, const setup_triangle *t, float depth_before)
{
    cg_renderer *r = f->r;
    int x = r->probe_x, y = r->probe_y;
    raster_edges e;
    render_edges_at(t, x, y, &e);
    if ((e.w[0] | e.w[1] | e.w[2]) < 0)
        return; /* the centre is not covered: no fragment */
    /* The rasterizer's weights (float, as it computes them), l0 = 1 - l1 - l2 */
    float l1 = (float)e.w[1] * t->inverse_area, l2 = (float)e.w[2] * t->inverse_area;
    double l[3] = {1.0 - l1 - l2, l1, l2};
    double q = l[0] * t->iw[0] + l[1] * t->iw[1] + l[2] * t->iw[2];
    double b[3] = {l[0] * t->iw[0] / q, l[1] * t->iw[1] / q, l[2] * t->iw[2] / q};
    float depth_after = f->depth[(size_t)y * f->width + x];
    double window[9], store[8][9];
    float depth = t->z[0] + l1 * (t->z[1] - t->z[0]) + l2 * (t->z[2] - t->z[0]);
    cg_vec2 outline[4];
    for (int k = 0; k < 3; k++) {
        window[3 * k] = t->x[k] / (double)RENDER_SUBPIXEL;
        window[3 * k + 1] = t->y[k] / (double)RENDER_SUBPIXEL;
        window[3 * k + 2] = t->z[k];
        outline[k] = cg_vec2_make(window[3 * k], window[3 * k + 1]);
    }
    outline[3] = outline[0];
    core_step s;
    core_step_begin(&s, "fragments");
    core_step_integer(&s, "fragment", r->probe_count++);
    core_step_reals(&s, "window_xyz", window, 9);
    core_step_reals(&s, "barycentric", l, 3);
    core_step_reals(&s, "perspective", b, 3);
    core_step_real(&s, "depth", depth);
    core_step_real(&s, "buffer", depth_before);
    core_step_text(&s, "decision",
                   depth_after != depth_before ? "nearer: written" : "not nearer: hidden");
    mode_fields(f, t, &s, b, store);
    s.step.geometry = outline;
    s.step.geometry_count = 4;
    if (!r->probe_stopped && core_step_emit(&s, r->shade_step, r->shade_user))
        r->probe_stopped = 1;
}

cg_status cg_shading_pixel_steps(cg_renderer *renderer, cg_image *image, int x, int y,
                                 cg_step_fn step, void *user)
{
    if (!renderer || !image || !step || x < 0 || y < 0 || x >= image->width || y >= image->height
        || renderer->options.algorithm != CG_RENDER_ZBUFFER)
        return CG_EINVAL;
    int threads = renderer->options.threads;
    renderer->options.threads = 1;
    renderer->shade_step = step;
    renderer->shade_user = user;
    renderer->probe_x = x;
    renderer->probe_y = y;
    renderer->probe_count = 0;
    renderer->probe_stopped = 0;
    cg_status status = cg_renderer_draw(renderer, image);
    renderer->options.threads = threads;
    renderer->shade_step = NULL;
    if (status != CG_OK || renderer->probe_stopped)
        return status;
    cg_rgbaf c = cg_image_get(image, x, y);
    double rgba[4] = {c.r, c.g, c.b, c.a};
    int xy[2] = {x, y};
    core_step s;
    core_step_begin(&s, "pixel");
    core_step_pixel(&s, "pixel", x, y);
    core_step_integer(&s, "fragments", renderer->probe_count);
    core_step_reals(&s, "color", rgba, 4);
    s.step.pixels = xy;
    s.step.pixel_count = 1;
    core_step_emit(&s, step, user);
    return CG_OK;
}
