/* Multisample anti-aliasing against its definition.  A white triangle drawn
 * unlit on black into a float image under a parallel camera whose mapping
 * to the screen is exact (vertices on the 1/256-pixel grid stay there), so
 * that at N samples each pixel's value is (covered samples) / N exactly.
 * The covered samples are counted here independently: Vulkan's standard
 * sample locations (fractions of the pixel, y down), and a sample inside
 * when it lies strictly inside the triangle, or on an edge whose inward
 * normal points right, or straight down (a left or top edge), computed in
 * exact integers.  Then: closed meshes and tilings covered once at every
 * sample, a half-covered pixel's colour the linear-light mix, identical
 * bytes on any thread count, one sample byte-identical to the plain
 * rasterizer, alpha-to-coverage for a MASK material, bad counts refused. */
#include "cg.h"
#include "check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SIDE 64

/* Vulkan's standard sample locations, in sixteenths of the pixel from its
 * top-left corner. */
static const int locations1[1][2] = {{8, 8}};
static const int locations2[2][2] = {{12, 12}, {4, 4}};
static const int locations4[4][2] = {{6, 2}, {14, 6}, {2, 10}, {10, 14}};
static const int locations8[8][2] = {{9, 5},  {7, 11}, {13, 9},  {5, 3},
                                     {3, 13}, {1, 7},  {11, 15}, {15, 1}};
static const int locations16[16][2] = {{9, 9},   {7, 5},  {5, 10},  {12, 7}, {3, 6}, {10, 13},
                                       {13, 11}, {11, 3}, {6, 14},  {8, 1},  {4, 2}, {2, 12},
                                       {0, 8},   {15, 4}, {14, 15}, {1, 0}};

static const int (*locations(int n))[2]
{
    return n == 1   ? locations1
           : n == 2 ? locations2
           : n == 4 ? locations4
           : n == 8 ? locations8
                    : locations16;
}

static long long cross(long long ax, long long ay, long long bx, long long by)
{
    return ax * by - ay * bx;
}

/* Whether the point (px, py) (1/256 pixel, y down) is covered by the
 * triangle v (1/256 pixel): the definition, with no shared code. */
static int covers(long long v[3][2], long long px, long long py)
{
    if (cross(v[1][0] - v[0][0], v[1][1] - v[0][1], v[2][0] - v[0][0], v[2][1] - v[0][1]) == 0)
        return 0;
    for (int k = 0; k < 3; k++) {
        const long long *p = v[k], *q = v[(k + 1) % 3], *r = v[(k + 2) % 3];
        long long dx = q[0] - p[0], dy = q[1] - p[1];
        long long side_r = cross(dx, dy, r[0] - p[0], r[1] - p[1]);
        long long side = cross(dx, dy, px - p[0], py - p[1]);
        if ((side > 0 && side_r > 0) || (side < 0 && side_r < 0))
            continue;
        if (side != 0)
            return 0;
        /* On the edge's line: the inward normal decides. */
        long long nx = -dy, ny = dx;
        if (nx * (r[0] - p[0]) + ny * (r[1] - p[1]) < 0) {
            nx = -nx;
            ny = -ny;
        }
        if (!(nx > 0 || (nx == 0 && ny > 0)))
            return 0;
    }
    return 1;
}

static void parallel_options(cg_render_options *o, int samples)
{
    cg_render_options_default(o);
    o->frame_camera = 0;
    o->camera.eye = cg_vec3_make(0, 0, 1);
    o->camera.target = cg_vec3_make(0, 0, 0);
    o->camera.up = cg_vec3_make(0, 1, 0);
    o->camera.orthographic = 1;
    o->camera.ortho_height = SIDE;
    o->camera.near = 0.5;
    o->camera.far = 2;
    o->shading = CG_SHADING_UNLIT;
    o->cull = CG_CULL_NONE;
    o->color = (cg_rgbaf){1, 1, 1, 1};
    o->background = (cg_rgbaf){0, 0, 0, 1};
    o->msaa = samples;
}

/* A mesh of one triangle with screen vertices v (1/256 pixel). */
static cg_mesh *triangle_mesh(long long v[3][2])
{
    cg_mesh *m;
    if (cg_mesh_create(&m, 3, 1, 3, 0) != CG_OK)
        return NULL;
    for (int k = 0; k < 3; k++) {
        m->positions[k] = cg_vec3_make((double)v[k][0] / 256 - SIDE / 2,
                                       SIDE / 2 - (double)v[k][1] / 256, 0);
        m->face_indices[k] = (uint32_t)k;
    }
    m->face_offsets[1] = 3;
    return m;
}

/* A coordinate on the 1/256 grid, or (every other triangle) on the 1/16
 * grid, where sample positions lie: edges then pass through samples. */
static long long coordinate(check_rng *rng, int coarse)
{
    long long c = check_rng_int(rng, 0, SIDE * 256);
    return coarse ? c / 16 * 16 : c;
}

static void coverage(void)
{
    check_rng rng = {0x2545f4914f6cdd1dULL};
    static const int counts[] = {1, 2, 4, 8, 16};
    for (int ci = 0; ci < 5; ci++) {
        int n = counts[ci];
        const int(*at)[2] = locations(n);
        long mismatches = 0, pixels = 0, partial = 0;
        for (int trial = 0; trial < 120; trial++) {
            long long v[3][2];
            int coarse = trial % 2;
            for (int k = 0; k < 3; k++) {
                v[k][0] = coordinate(&rng, coarse);
                v[k][1] = coordinate(&rng, coarse);
            }
            if (trial % 7 == 3) { /* a thin sliver */
                v[2][0] = v[1][0] + check_rng_int(&rng, -8, 8);
                v[2][1] = v[1][1] + check_rng_int(&rng, -900, 900);
            }
            cg_mesh *m = triangle_mesh(v);
            cg_render_options o;
            parallel_options(&o, n);
            cg_image *image;
            CHECK(cg_image_create(&image, SIDE, SIDE, CG_PIXEL_RGBAF) == CG_OK);
            cg_renderer *r;
            cg_error err;
            CHECK(cg_renderer_create(m, &o, &r, &err) == CG_OK);
            CHECK(cg_renderer_draw(r, image) == CG_OK);
            long long total = 0;
            for (int y = 0; y < SIDE; y++) {
                const cg_rgbaf *row = cg_image_row_rgbaf(image, y);
                for (int x = 0; x < SIDE; x++) {
                    int k = 0;
                    for (int s = 0; s < n; s++)
                        k += covers(v, (long long)x * 256 + at[s][0] * 16,
                                    (long long)y * 256 + at[s][1] * 16);
                    total += k;
                    pixels++;
                    partial += k > 0 && k < n;
                    if (row[x].r * (float)n != (float)k || row[x].g != row[x].r) {
                        if (mismatches++ < 5)
                            CHECK_MSG(0,
                                      "%d samples, triangle %d, pixel (%d, %d): %g, expected %d/%d",
                                      n, trial, x, y, row[x].r, k, n);
                    }
                }
            }
            CHECK_EQ_INT(cg_renderer_stats(r).fragments, total);
            cg_renderer_free(r);
            cg_image_free(image);
            cg_mesh_free(m);
        }
        CHECK_EQ_INT(mismatches, 0);
        /* The test saw edges: many pixels partly covered (n > 1). */
        CHECK(n == 1 || partial > 1000);
        (void)pixels;
    }
}

/* A tiling of the picture by jittered grid triangles (vertices on the 1/16
 * grid, so edges cross samples): every sample covered exactly once. */
static void tiling(void)
{
    check_rng rng = {0x9e3779b97f4a7c15ULL};
    enum { G = 8 };
    long long gx[G + 1][G + 1], gy[G + 1][G + 1];
    for (int i = 0; i <= G; i++)
        for (int j = 0; j <= G; j++) {
            long long step = SIDE * 256 / G;
            gx[i][j] = j * step + (j > 0 && j < G ? check_rng_int(&rng, -40, 40) * 16 / 16 : 0);
            gy[i][j] = i * step + (i > 0 && i < G ? check_rng_int(&rng, -40, 40) : 0);
            gx[i][j] = gx[i][j] / 16 * 16;
            gy[i][j] = gy[i][j] / 16 * 16;
        }
    cg_mesh *m;
    CHECK(cg_mesh_create(&m, (G + 1) * (G + 1), 2 * G * G, 6 * G * G, 0) == CG_OK);
    for (int i = 0; i <= G; i++)
        for (int j = 0; j <= G; j++)
            m->positions[i * (G + 1) + j] = cg_vec3_make((double)gx[i][j] / 256 - SIDE / 2,
                                                         SIDE / 2 - (double)gy[i][j] / 256, 0);
    size_t f = 0;
    for (int i = 0; i < G; i++)
        for (int j = 0; j < G; j++) {
            uint32_t a = (uint32_t)(i * (G + 1) + j), b = a + 1, c = a + G + 1, d = c + 1;
            uint32_t t[2][3] = {{a, c, b}, {b, c, d}};
            for (int k = 0; k < 2; k++, f++) {
                m->face_offsets[f + 1] = (uint32_t)(3 * (f + 1));
                memcpy(m->face_indices + 3 * f, t[k], sizeof t[k]);
            }
        }
    static const int counts[] = {2, 4, 8, 16};
    for (int ci = 0; ci < 4; ci++) {
        cg_render_options o;
        parallel_options(&o, counts[ci]);
        cg_image *image;
        CHECK(cg_image_create(&image, SIDE, SIDE, CG_PIXEL_RGBAF) == CG_OK);
        cg_renderer *r;
        cg_error err;
        CHECK(cg_renderer_create(m, &o, &r, &err) == CG_OK);
        CHECK(cg_renderer_draw(r, image) == CG_OK);
        long holes = 0;
        for (int y = 0; y < SIDE; y++)
            for (int x = 0; x < SIDE; x++)
                holes += cg_image_row_rgbaf(image, y)[x].r != 1;
        CHECK_EQ_INT(holes, 0);
        CHECK_EQ_INT(cg_renderer_stats(r).fragments, (long long)counts[ci] * SIDE * SIDE);
        cg_renderer_free(r);
        cg_image_free(image);
    }
    cg_mesh_free(m);
}

/* A closed sphere around a perspective camera: every sample of every pixel
 * covered once. */
static void closed_mesh(void)
{
    cg_mesh *m;
    CHECK(cg_mesh_sphere(37, 23, 1, &m) == CG_OK);
    static const int counts[] = {2, 4, 8, 16};
    for (int ci = 0; ci < 4; ci++) {
        cg_render_options o;
        cg_render_options_default(&o);
        o.frame_camera = 0;
        o.camera.eye = cg_vec3_make(0.1, -0.05, 0.2);
        o.camera.target = cg_vec3_make(0.7, 0.3, -1);
        o.camera.near = 0.01;
        o.camera.far = 3;
        o.cull = CG_CULL_NONE;
        o.shading = CG_SHADING_UNLIT;
        o.color = (cg_rgbaf){1, 1, 1, 1};
        o.background = (cg_rgbaf){0, 0, 0, 1};
        o.msaa = counts[ci];
        o.threads = 3;
        cg_image *image;
        CHECK(cg_image_create(&image, 150, 97, CG_PIXEL_RGBAF) == CG_OK);
        cg_renderer *r;
        cg_error err;
        CHECK(cg_renderer_create(m, &o, &r, &err) == CG_OK);
        CHECK(cg_renderer_draw(r, image) == CG_OK);
        long holes = 0;
        for (int y = 0; y < 97; y++)
            for (int x = 0; x < 150; x++)
                /* 1 up to the rounding of perspective-correct colour; a
                 * sample missed would take 1/16 at least. */
                holes += fabsf(cg_image_row_rgbaf(image, y)[x].r - 1) > 1e-4f;
        CHECK_EQ_INT(holes, 0);
        CHECK_EQ_INT(cg_renderer_stats(r).fragments, (long long)counts[ci] * 150 * 97);
        cg_renderer_free(r);
        cg_image_free(image);
    }
    cg_mesh_free(m);
}

/* A vertical edge through the middle of a pixel column: at 4 samples two of
 * them are covered, so the pixel is half the triangle's colour and half the
 * background's, mixed in linear light (not in sRGB codes). */
static void linear_mix(void)
{
    const cg_rgbaf a = {0.8f, 0.02f, 0.5f, 1}, b = {0.01f, 0.6f, 0.1f, 1};
    long long v[3][2] = {{0, 0}, {(long long)(10.5 * 256), 0}, {(long long)(10.5 * 256), 64 * 256}};
    long long w[3][2] = {{0, 0}, {(long long)(10.5 * 256), 64 * 256}, {0, 64 * 256}};
    cg_mesh *m;
    CHECK(cg_mesh_create(&m, 4, 2, 6, 0) == CG_OK);
    long long corner[4][2] = {{v[0][0], v[0][1]},
                              {v[1][0], v[1][1]},
                              {w[1][0], w[1][1]},
                              {w[2][0], w[2][1]}};
    for (int k = 0; k < 4; k++)
        m->positions[k] = cg_vec3_make((double)corner[k][0] / 256 - SIDE / 2,
                                       SIDE / 2 - (double)corner[k][1] / 256, 0);
    uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
    memcpy(m->face_indices, idx, sizeof idx);
    m->face_offsets[1] = 3;
    m->face_offsets[2] = 6;
    for (int format = 0; format < 2; format++) {
        cg_render_options o;
        parallel_options(&o, 4);
        o.color = a;
        o.background = b;
        cg_image *image;
        CHECK(cg_image_create(&image, SIDE, SIDE, format ? CG_PIXEL_RGBAF : CG_PIXEL_RGBA8)
              == CG_OK);
        cg_error err;
        CHECK(cg_render(m, &o, image, &err) == CG_OK);
        float mix[3] = {0.5f * a.r + 0.5f * b.r, 0.5f * a.g + 0.5f * b.g, 0.5f * a.b + 0.5f * b.b};
        for (int y = 0; y < SIDE; y += 9) {
            if (format) {
                cg_rgbaf p = cg_image_row_rgbaf(image, y)[10];
                CHECK_NEAR(p.r, mix[0], 1e-6);
                CHECK_NEAR(p.g, mix[1], 1e-6);
                CHECK_NEAR(p.b, mix[2], 1e-6);
                cg_rgbaf in = cg_image_row_rgbaf(image, y)[9],
                         out = cg_image_row_rgbaf(image, y)[11];
                CHECK(in.r == a.r && in.g == a.g && out.r == b.r && out.g == b.g);
            } else {
                cg_rgba8 p = cg_image_row_rgba8(image, y)[10];
                CHECK_EQ_INT(p.r, cg_linear_to_srgb8(mix[0]));
                CHECK_EQ_INT(p.g, cg_linear_to_srgb8(mix[1]));
                CHECK_EQ_INT(p.b, cg_linear_to_srgb8(mix[2]));
                /* Mixing the codes instead would be far off. */
                int naive = (cg_linear_to_srgb8(a.g) + cg_linear_to_srgb8(b.g) + 1) / 2;
                CHECK(abs(naive - p.g) > 20);
            }
        }
        cg_image_free(image);
    }
    cg_mesh_free(m);
}

static cg_image *draw_sphere(const cg_mesh *m, int samples, int threads, cg_shading shading)
{
    cg_render_options o;
    cg_render_options_default(&o);
    o.msaa = samples;
    o.threads = threads;
    o.shading = shading;
    o.camera.eye = cg_vec3_make(1, 0.7, 2);
    cg_image *image;
    if (cg_image_create(&image, 211, 130, CG_PIXEL_RGBA8) != CG_OK)
        return NULL;
    cg_error err;
    if (cg_render(m, &o, image, &err) != CG_OK) {
        cg_image_free(image);
        return NULL;
    }
    return image;
}

static int same_image(const cg_image *a, const cg_image *b)
{
    if (!a || !b)
        return 0;
    for (int y = 0; y < a->height; y++)
        if (memcmp(a->data + (size_t)y * a->stride, b->data + (size_t)y * b->stride,
                   (size_t)a->width * 4)
            != 0)
            return 0;
    return 1;
}

/* Identical bytes on 1, 2 and 5 threads at every count and shading; the
 * counts differ from each other (edges are smoothed), and msaa 0 and 1 are
 * the one-sample picture. */
static void threads_and_counts(void)
{
    cg_mesh *m;
    CHECK(cg_mesh_torus(40, 24, 1, 0.35, &m) == CG_OK);
    static const cg_shading shadings[] = {CG_SHADING_FLAT, CG_SHADING_GOURAUD, CG_SHADING_PHONG};
    for (int si = 0; si < 3; si++) {
        cg_image *one = draw_sphere(m, 1, 1, shadings[si]);
        cg_image *zero = draw_sphere(m, 0, 2, shadings[si]);
        CHECK(same_image(one, zero));
        for (int n = 2; n <= 16; n *= 2) {
            cg_image *a = draw_sphere(m, n, 1, shadings[si]);
            cg_image *b = draw_sphere(m, n, 2, shadings[si]);
            cg_image *c = draw_sphere(m, n, 5, shadings[si]);
            CHECK(same_image(a, b));
            CHECK(same_image(a, c));
            CHECK(!same_image(a, one));
            cg_image_free(a);
            cg_image_free(b);
            cg_image_free(c);
        }
        cg_image_free(one);
        cg_image_free(zero);
    }
    cg_mesh_free(m);
}

/* Alpha-to-coverage: a square of a MASK material (cutoff 0.5) whose alpha
 * is a, drawn white on black: at one sample dropped below the cutoff and
 * whole above it; at N samples round(a' N) of them, a' the alpha mapped so
 * that the cutoff falls at one half. */
static void alpha_to_coverage(void)
{
    static const float alphas[] = {0.1f, 0.3f, 0.45f, 0.6f, 0.7f, 0.9f, 1.0f};
    for (size_t ai = 0; ai < sizeof alphas / sizeof *alphas; ai++) {
        float alpha = alphas[ai];
        long long v[3][2] = {{0, 0}, {SIDE * 256, 0}, {0, SIDE * 256}};
        cg_mesh *m = triangle_mesh(v);
        CHECK(m != NULL);
        cg_mesh_material material = cg_mesh_material_default();
        material.base_color = (cg_rgbaf){1, 1, 1, alpha};
        material.alpha_mode = CG_MESH_ALPHA_MASK;
        material.alpha_cutoff = 0.5;
        uint32_t face_material = 0;
        m->materials = &material;
        m->material_count = 1;
        m->face_materials = &face_material;
        for (int n = 1; n <= 16; n *= 2) {
            cg_render_options o;
            parallel_options(&o, n);
            cg_image *image;
            CHECK(cg_image_create(&image, SIDE, SIDE, CG_PIXEL_RGBAF) == CG_OK);
            cg_error err;
            CHECK(cg_render(m, &o, image, &err) == CG_OK);
            double mapped = alpha < 0.5 ? alpha : 0.5 + 0.5 * (alpha - 0.5) / 0.5;
            int k = n == 1 ? (alpha >= 0.5) : (int)floor(mapped * n + 0.5);
            if (k > n)
                k = n;
            /* A pixel well inside the triangle. */
            CHECK_MSG(cg_image_row_rgbaf(image, 5)[5].r * (float)n == (float)k,
                      "alpha %g, %d samples: %g, expected %d/%d", alpha, n,
                      cg_image_row_rgbaf(image, 5)[5].r, k, n);
            cg_image_free(image);
        }
        m->materials = NULL;
        m->material_count = 0;
        m->face_materials = NULL;
        cg_mesh_free(m);
    }
}

static void bad_counts(void)
{
    cg_mesh *m;
    CHECK(cg_mesh_sphere(8, 6, 1, &m) == CG_OK);
    static const int bad[] = {3, 5, 6, 7, 9, 12, 15, 17, 32, -1, -4};
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        cg_render_options o;
        cg_render_options_default(&o);
        o.msaa = bad[k];
        cg_renderer *r = NULL;
        cg_error err;
        CHECK(cg_renderer_create(m, &o, &r, &err) == CG_EINVAL);
        CHECK(r == NULL);
    }
    cg_render_options o;
    cg_render_options_default(&o);
    o.msaa = 4;
    o.algorithm = CG_RENDER_PAINTER;
    cg_renderer *r = NULL;
    cg_error err;
    CHECK(cg_renderer_create(m, &o, &r, &err) == CG_EINVAL);
    o.algorithm = CG_RENDER_ZBUFFER;
    CHECK(cg_renderer_create(m, &o, &r, &err) == CG_OK);
    o.msaa = 6;
    CHECK(cg_renderer_set_options(r, &o) == CG_EINVAL);
    cg_renderer_free(r);
    cg_mesh_free(m);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(coverage);
    CHECK_GROUP(tiling);
    CHECK_GROUP(closed_mesh);
    CHECK_GROUP(linear_mix);
    CHECK_GROUP(threads_and_counts);
    CHECK_GROUP(alpha_to_coverage);
    CHECK_GROUP(bad_counts);
    return check_finish();
}
