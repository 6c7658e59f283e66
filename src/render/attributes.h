/* Perspective-correct per-pixel attributes of a set-up triangle (Phong and
 * textured shading), shared by the one-sample rasterizer (rasterizer.c) and
 * the multisampled one (multisample.c). */
#ifndef CG_RENDER_ATTRIBUTES_H
#define CG_RENDER_ATTRIBUTES_H

#include "pipeline.h"

/* Per-pixel attributes (Phong and textured): attribute / w and 1 / w at
 * vertex 0 and their changes toward vertices 1 and 2, and the barycentric
 * weights' change per pixel right and down (for the texture coordinates'
 * derivatives). */
typedef struct attribute_plane {
    int n;
    float w_base, w_d1, w_d2;
    float p_base[RENDER_MAX_ATTRIBUTES], p_d1[RENDER_MAX_ATTRIBUTES], p_d2[RENDER_MAX_ATTRIBUTES];
    float l1x, l2x, l1y, l2y;
} attribute_plane;

static inline void attribute_setup(const setup_triangle *t, const raster_edges *e, float ia, int n,
                                   attribute_plane *p)
{
    p->n = n;
    p->w_base = t->iw[0];
    p->w_d1 = t->iw[1] - t->iw[0];
    p->w_d2 = t->iw[2] - t->iw[0];
    for (int j = 0; j < n; j++) {
        p->p_base[j] = t->a[j] * t->iw[0];
        p->p_d1[j] = t->a[n + j] * t->iw[1] - p->p_base[j];
        p->p_d2[j] = t->a[2 * n + j] * t->iw[2] - p->p_base[j];
    }
    p->l1x = (float)e->step_x[1] * ia;
    p->l2x = (float)e->step_x[2] * ia;
    p->l1y = (float)e->step_y[1] * ia;
    p->l2y = (float)e->step_y[2] * ia;
}

/* The colour of a Phong or textured pixel with barycentric weights l1, l2;
 * 0 when a textured fragment is dropped (alpha mask).  With alpha, a
 * textured fragment's alpha goes there and the mask is left to the caller
 * (alpha-to-coverage); Phong fragments are opaque. */
static inline int attribute_pixel(const render_frame *f, const setup_triangle *t,
                                  const attribute_plane *p, float l1, float l2, const int mode,
                                  float c[3], float *alpha)
{
    /* Perspective-correct: attribute / w and 1 / w are affine on the
     * screen; divide their interpolants. */
    const int n = p->n;
    float r = 1 / (p->w_base + l1 * p->w_d1 + l2 * p->w_d2);
    float v[RENDER_MAX_ATTRIBUTES];
    for (int j = 0; j < n; j++)
        v[j] = (p->p_base[j] + l1 * p->p_d1[j] + l2 * p->p_d2[j]) * r;
    if (mode == MODE_TEXTURED) {
        /* d(a / q) = (d(a q) - a dq) / q with a q and q affine. */
        float duv[4];
        float qx = p->l1x * p->w_d1 + p->l2x * p->w_d2, qy = p->l1y * p->w_d1 + p->l2y * p->w_d2;
        for (int j = 0; j < 2; j++) {
            int k = TEXTURED_UV + j;
            duv[j] = (p->l1x * p->p_d1[k] + p->l2x * p->p_d2[k] - v[k] * qx) * r;
            duv[2 + j] = (p->l1y * p->p_d1[k] + p->l2y * p->p_d2[k] - v[k] * qy) * r;
        }
        return render_textured_fragment(f, t->material, v, duv, c, alpha);
    }
    float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    float inv = len > 0 ? 1 / len : 0;
    float normal[3] = {v[0] * inv, v[1] * inv, v[2] * inv};
    render_shade(&f->lighting, v + 3, normal, n > 6 ? v + 6 : t->color, c);
    if (alpha)
        *alpha = 1;
    return 1;
}

#endif
