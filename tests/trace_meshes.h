/* Generated triangle meshes for the ray tracer's tests and benchmark:
 * closed meshes with shared vertices (a bumpy sphere, a torus) and random
 * triangle soups.  Uses check.h's deterministic generator. */
#ifndef CG_TEST_TRACE_MESHES_H
#define CG_TEST_TRACE_MESHES_H

#include "check.h"
#include "cg/core.h"

typedef struct soup {
    cg_vec3 *p;
    uint32_t *idx;
    size_t nv, nt;
} soup;

static inline void soup_free(soup *s)
{
    free(s->p);
    free(s->idx);
}

/* A closed sphere-like mesh of stacks x slices with shared vertices, radius
 * jittered per vertex so no two triangles are alike. */
static inline soup bumpy_sphere(check_rng *rng, int stacks, int slices, double jitter)
{
    soup s;
    s.nv = 2 + (size_t)(stacks - 1) * slices;
    s.nt = 2 * (size_t)slices * (stacks - 1);
    s.p = malloc(s.nv * sizeof *s.p);
    s.idx = malloc(3 * s.nt * sizeof *s.idx);
    s.p[0] = cg_vec3_make(0, 1, 0);
    s.p[1] = cg_vec3_make(0, -1, 0);
    for (int i = 1; i < stacks; i++)
        for (int j = 0; j < slices; j++) {
            double th = CG_PI * i / stacks, ph = 2 * CG_PI * j / slices;
            double r = 1 + jitter * check_rng_range(rng, -1, 1);
            s.p[2 + (size_t)(i - 1) * slices + j] = cg_vec3_make(r * sin(th) * cos(ph), r * cos(th),
                                                                 r * sin(th) * sin(ph));
        }
    size_t t = 0;
#define V(i, j) (uint32_t)(2 + (size_t)((i)-1) * slices + (size_t)(((j) % slices)))
#define TRI(a, b, c)            \
    do {                        \
        s.idx[3 * t] = (a);     \
        s.idx[3 * t + 1] = (b); \
        s.idx[3 * t + 2] = (c); \
        t++;                    \
    } while (0)
    for (int j = 0; j < slices; j++) {
        TRI(0, V(1, j + 1), V(1, j));
        TRI(1, V(stacks - 1, j), V(stacks - 1, j + 1));
    }
    for (int i = 1; i < stacks - 1; i++)
        for (int j = 0; j < slices; j++) {
            TRI(V(i, j), V(i, j + 1), V(i + 1, j));
            TRI(V(i, j + 1), V(i + 1, j + 1), V(i + 1, j));
        }
    s.nt = t;
    return s;
}

/* A closed torus (major radius 1, minor 0.35) with shared vertices. */
static inline soup torus(int nu, int nv)
{
    soup s;
    s.nv = (size_t)nu * nv;
    s.nt = 2 * s.nv;
    s.p = malloc(s.nv * sizeof *s.p);
    s.idx = malloc(3 * s.nt * sizeof *s.idx);
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double a = 2 * CG_PI * i / nu, b = 2 * CG_PI * j / nv;
            double r = 1 + 0.35 * cos(b);
            s.p[(size_t)i * nv + j] = cg_vec3_make(r * cos(a), 0.35 * sin(b), r * sin(a));
        }
    size_t t = 0;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            uint32_t a = (uint32_t)(i * nv + j), b = (uint32_t)(((i + 1) % nu) * nv + j),
                     c = (uint32_t)(i * nv + (j + 1) % nv),
                     d = (uint32_t)(((i + 1) % nu) * nv + (j + 1) % nv);
            TRI(a, b, d);
            TRI(a, d, c);
        }
    return s;
}

/* Random triangles of random sizes in the cube [-1, 1]^3, some tiny, some
 * degenerate (repeated or collinear corners). */
static inline soup random_soup(check_rng *rng, size_t n)
{
    soup s;
    s.nv = 3 * n;
    s.nt = n;
    s.p = malloc(s.nv * sizeof *s.p);
    s.idx = NULL;
    for (size_t i = 0; i < n; i++) {
        cg_vec3 c = cg_vec3_make(check_rng_range(rng, -1, 1), check_rng_range(rng, -1, 1),
                                 check_rng_range(rng, -1, 1));
        double size = pow(10, check_rng_range(rng, -3, -0.3));
        for (int k = 0; k < 3; k++)
            s.p[3 * i + k] = cg_vec3_add(c, cg_vec3_make(size * check_rng_range(rng, -1, 1),
                                                         size * check_rng_range(rng, -1, 1),
                                                         size * check_rng_range(rng, -1, 1)));
        if (i % 97 == 0)
            s.p[3 * i + 2] = s.p[3 * i + 1]; /* repeated corner */
        if (i % 89 == 0)                     /* collinear */
            s.p[3 * i + 2] = cg_vec3_scale(cg_vec3_add(s.p[3 * i], s.p[3 * i + 1]), 0.5);
    }
    return s;
}

static inline cg_vec3 corner(const soup *s, size_t t, int k)
{
    return s->p[s->idx ? s->idx[3 * t + k] : 3 * t + k];
}

static inline cg_vec3 random_dir(check_rng *rng)
{
    for (;;) {
        cg_vec3 d = cg_vec3_make(check_rng_range(rng, -1, 1), check_rng_range(rng, -1, 1),
                                 check_rng_range(rng, -1, 1));
        double l = cg_vec3_length(d);
        if (l > 0.01 && l <= 1)
            return cg_vec3_scale(d, 1 / l);
    }
}

#undef V
#undef TRI

#endif
