/* Tests of the ray tracer: BVH queries against brute force, watertightness
 * of the triangle test on closed meshes, optics against hand values, bad
 * input, shadows, and identical pictures on any thread count. */
#include "check.h"
#include "trace_meshes.h"
#include "cg/trace.h"
#include "../src/trace/internal.h" /* to compare trees node by node */

#include <string.h>

/* Sanitizer builds run the same checks on fewer rays. */
#if defined(__SANITIZE_ADDRESS__)
#define RAY_SCALE 8
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RAY_SCALE 8
#endif
#endif
#ifndef RAY_SCALE
#define RAY_SCALE 1
#endif

/* A target point: a random vertex, a random point on an edge, or a random
 * point in a triangle. */
static cg_vec3 feature_point(check_rng *rng, const soup *s, int kind)
{
    size_t t = (size_t)check_rng_int(rng, 0, (long long)s->nt - 1);
    int k = (int)check_rng_int(rng, 0, 2);
    cg_vec3 a = corner(s, t, k), b = corner(s, t, (k + 1) % 3), c = corner(s, t, (k + 2) % 3);
    if (kind == 0)
        return a;
    double x = check_rng_unit(rng);
    if (kind == 1)
        return cg_vec3_add(a, cg_vec3_scale(cg_vec3_sub(b, a), x));
    double y = check_rng_unit(rng) * (1 - x);
    return cg_vec3_add(
        a, cg_vec3_add(cg_vec3_scale(cg_vec3_sub(b, a), x), cg_vec3_scale(cg_vec3_sub(c, a), y)));
}

/* BVH nearest hit and occlusion against brute force on rays of every kind. */
static void check_against_brute(const char *name, const soup *s, long rays, check_rng *rng)
{
    cg_bvh *bvh;
    CHECK(cg_bvh_build(s->p, s->nv, s->idx, s->nt, &bvh) == CG_OK);
    long mismatches = 0, occluded_mismatches = 0, hits = 0;
    for (long i = 0; i < rays; i++) {
        cg_vec3 o, d;
        int kind = (int)(i % 5);
        o = cg_vec3_make(check_rng_range(rng, -2, 2), check_rng_range(rng, -2, 2),
                         check_rng_range(rng, -2, 2));
        if (kind <= 2) {
            /* Toward a vertex, an edge point or an interior point. */
            d = cg_vec3_sub(feature_point(rng, s, kind), o);
        } else if (kind == 3) {
            /* Along an edge's line, starting behind it. */
            size_t t = (size_t)check_rng_int(rng, 0, (long long)s->nt - 1);
            cg_vec3 a = corner(s, t, 0), b = corner(s, t, 1);
            d = cg_vec3_sub(b, a);
            o = cg_vec3_sub(a, cg_vec3_scale(d, check_rng_range(rng, 0.1, 3)));
        } else {
            d = random_dir(rng);
        }
        if (i % 7 == 0) /* axis-aligned components */
            d.x = 0;
        double t_max = i % 3 == 0 ? check_rng_range(rng, 0, 3) : INFINITY;
        cg_bvh_hit a, b;
        int ha = cg_bvh_intersect(bvh, o, d, 0, t_max, &a);
        int hb = cg_bvh_intersect_brute(bvh, o, d, 0, t_max, &b);
        hits += hb;
        if (ha != hb || (ha && (a.triangle != b.triangle || a.t != b.t))) {
            if (mismatches++ < 5)
                fprintf(stderr, "%s ray %ld: bvh %d (%u, %.9g) brute %d (%u, %.9g)\n", name, i, ha,
                        ha ? a.triangle : 0, ha ? a.t : 0, hb, hb ? b.triangle : 0, hb ? b.t : 0);
        }
        int occluded = cg_bvh_occluded(bvh, o, d, 0, t_max);
        int expect = hb && b.t < t_max;
        if (!expect && hb && b.t == t_max) {
            /* A hit exactly at t_max occludes only when a nearer one exists. */
            expect = cg_bvh_intersect_brute(bvh, o, d, 0, nextafter(t_max, 0), NULL);
        }
        occluded_mismatches += occluded != expect;
    }
    CHECK_MSG(mismatches == 0, "%s: %ld of %ld rays differ from brute force", name, mismatches,
              rays);
    CHECK_MSG(occluded_mismatches == 0, "%s: %ld of %ld shadow rays differ", name,
              occluded_mismatches, rays);
    CHECK_MSG(hits > rays / 10, "%s: only %ld hits of %ld rays", name, hits, rays);
    cg_bvh_stats st;
    cg_bvh_get_stats(bvh, &st);
    CHECK(st.nodes >= 1 && st.nodes <= 2 * st.triangles);
    CHECK(st.depth >= 1 && st.depth <= 128);
    cg_bvh_free(bvh);
}

/* Rays from inside a closed mesh toward its vertices and edges always hit. */
static void check_watertight(const char *name, const soup *s, cg_vec3 (*inside)(check_rng *),
                             long rays, check_rng *rng)
{
    cg_bvh *bvh;
    CHECK(cg_bvh_build(s->p, s->nv, s->idx, s->nt, &bvh) == CG_OK);
    long misses = 0;
    for (long i = 0; i < rays; i++) {
        cg_vec3 o = inside(rng);
        cg_vec3 d = i % 3 == 2 ? random_dir(rng)
                               : cg_vec3_sub(feature_point(rng, s, (int)(i % 3)), o);
        if (!cg_bvh_intersect(bvh, o, d, 0, INFINITY, NULL))
            misses++;
        if (!cg_bvh_occluded(bvh, o, d, 0, INFINITY))
            misses++;
    }
    CHECK_MSG(misses == 0, "%s: %ld of %ld rays from inside slipped through", name, misses, rays);
    cg_bvh_free(bvh);
}

static cg_vec3 inside_sphere(check_rng *rng)
{
    return cg_vec3_scale(random_dir(rng), check_rng_range(rng, 0, 0.8));
}

static cg_vec3 inside_torus(check_rng *rng)
{
    double a = check_rng_range(rng, 0, 2 * CG_PI);
    cg_vec3 core = cg_vec3_make(cos(a), 0, sin(a));
    return cg_vec3_add(core, cg_vec3_scale(random_dir(rng), check_rng_range(rng, 0, 0.25)));
}

static void test_bvh(void)
{
    check_rng rng = {12345};
    soup sphere = bumpy_sphere(&rng, 12, 16, 0.05);
    soup ring = torus(20, 10);
    soup rand = random_soup(&rng, 300);
    check_against_brute("sphere", &sphere, 400000 / RAY_SCALE, &rng);
    check_against_brute("torus", &ring, 400000 / RAY_SCALE, &rng);
    check_against_brute("soup", &rand, 600000 / RAY_SCALE, &rng);
    check_watertight("sphere", &sphere, inside_sphere, 600000 / RAY_SCALE, &rng);
    check_watertight("torus", &ring, inside_torus, 600000 / RAY_SCALE, &rng);

    /* Built on two threads: the very same tree, node for node. */
    soup big = bumpy_sphere(&rng, 60, 90, 0.05);
    cg_bvh *one, *two;
    CHECK(cg_bvh_build(big.p, big.nv, big.idx, big.nt, &one) == CG_OK);
    CHECK(cg_bvh_build_threads(big.p, big.nv, big.idx, big.nt, 2, &two) == CG_OK);
    CHECK_EQ_INT(one->node_count, two->node_count);
    CHECK(one->node_count == two->node_count
          && memcmp(one->nodes, two->nodes, one->node_count * sizeof *one->nodes) == 0);
    CHECK(one->root == two->root && one->block_count == two->block_count
          && memcmp(one->blocks, two->blocks, one->block_count * sizeof *one->blocks) == 0);
    cg_bvh_free(one);
    cg_bvh_free(two);
    CHECK(cg_bvh_build_threads(big.p, big.nv, big.idx, big.nt, 0, &two) == CG_EINVAL);
    check_against_brute("big sphere", &big, 8000 / RAY_SCALE, &rng);
    soup_free(&big);

    /* Over 2^19 triangles the build keeps its references in one block that
     * the triangle blocks then take over: the same queries, the same tree
     * on two threads. */
    soup huge = bumpy_sphere(&rng, 366, 720, 0.05);
    CHECK(huge.nt >= (1u << 19));
    CHECK(cg_bvh_build(huge.p, huge.nv, huge.idx, huge.nt, &one) == CG_OK);
    CHECK(cg_bvh_build_threads(huge.p, huge.nv, huge.idx, huge.nt, 2, &two) == CG_OK);
    CHECK(one && two && one->block_count == two->block_count
          && memcmp(one->blocks, two->blocks, one->block_count * sizeof *one->blocks) == 0);
    CHECK((uintptr_t)(void *)one->blocks % 128 == 0);
    cg_bvh_free(one);
    cg_bvh_free(two);
    check_against_brute("half-million sphere", &huge, 64 / RAY_SCALE, &rng);
    soup_free(&huge);

    /* The same closed mesh far from the origin and scaled up: still
     * watertight (rays from its centre). */
    soup far = bumpy_sphere(&rng, 16, 20, 0.02);
    for (size_t i = 0; i < far.nv; i++)
        far.p[i] = cg_vec3_add(cg_vec3_scale(far.p[i], 1000), cg_vec3_make(5e4, -3e4, 2e4));
    cg_bvh *bvh;
    CHECK(cg_bvh_build(far.p, far.nv, far.idx, far.nt, &bvh) == CG_OK);
    long misses = 0;
    for (int i = 0; i < 100000 / RAY_SCALE; i++) {
        cg_vec3 o = cg_vec3_add(cg_vec3_make(5e4, -3e4, 2e4),
                                cg_vec3_scale(inside_sphere(&rng), 500));
        cg_vec3 d = cg_vec3_sub(feature_point(&rng, &far, i % 2), o);
        misses += !cg_bvh_intersect(bvh, o, d, 0, INFINITY, NULL);
    }
    CHECK_MSG(misses == 0, "far sphere: %ld rays slipped through", misses);
    cg_bvh_free(bvh);
    soup_free(&far);
    soup_free(&sphere);
    soup_free(&ring);
    soup_free(&rand);
}

static void test_triangle_and_bad_input(void)
{
    cg_vec3 a = {0, 0, 0}, b = {1, 0, 0}, c = {0, 1, 0};
    double t, u, v;
    CHECK(cg_ray_triangle(cg_vec3_make(0.25, 0.25, 1), cg_vec3_make(0, 0, -1), a, b, c, 0, INFINITY,
                          &t, &u, &v));
    CHECK_NEAR(t, 1, 1e-7);
    CHECK_NEAR(u, 0.25, 1e-7);
    CHECK_NEAR(v, 0.25, 1e-7);
    /* Back face is hit too; t is in the ray's units. */
    CHECK(cg_ray_triangle(cg_vec3_make(0.25, 0.25, -2), cg_vec3_make(0, 0, 4), a, b, c, 0, INFINITY,
                          &t, NULL, NULL));
    CHECK_NEAR(t, 0.5, 1e-7);
    CHECK(!cg_ray_triangle(cg_vec3_make(0.75, 0.75, 1), cg_vec3_make(0, 0, -1), a, b, c, 0,
                           INFINITY, &t, &u, &v));
    /* Range: t_min exclusive, t_max inclusive. */
    CHECK(!cg_ray_triangle(cg_vec3_make(0.25, 0.25, 1), cg_vec3_make(0, 0, -1), a, b, c, 1,
                           INFINITY, &t, &u, &v));
    CHECK(cg_ray_triangle(cg_vec3_make(0.25, 0.25, 1), cg_vec3_make(0, 0, -1), a, b, c, 0, 1, &t,
                          &u, &v));
    CHECK(!cg_ray_triangle(cg_vec3_make(0.25, 0.25, 1), cg_vec3_make(0, 0, -1), a, b, c, 0, 0.5, &t,
                           &u, &v));
    /* Parallel rays, degenerate triangles, NaN and zero directions: no hit. */
    CHECK(!cg_ray_triangle(cg_vec3_make(-1, 0.25, 0), cg_vec3_make(1, 0, 0), a, b, c, 0, INFINITY,
                           &t, &u, &v));
    CHECK(!cg_ray_triangle(cg_vec3_make(0.25, 0, 1), cg_vec3_make(0, 0, -1), a, b, b, 0, INFINITY,
                           &t, &u, &v));
    CHECK(!cg_ray_triangle(cg_vec3_make(0.5, 0, 1), cg_vec3_make(0, 0, -1), a, b,
                           cg_vec3_make(2, 0, 0), 0, INFINITY, &t, &u, &v));
    CHECK(!cg_ray_triangle(cg_vec3_make(NAN, 0.25, 1), cg_vec3_make(0, 0, -1), a, b, c, 0, INFINITY,
                           &t, &u, &v));
    CHECK(!cg_ray_triangle(cg_vec3_make(0.25, 0.25, 1), cg_vec3_make(0, 0, 0), a, b, c, 0, INFINITY,
                           &t, &u, &v));
    CHECK(!cg_ray_triangle(cg_vec3_make(0.25, 0.25, 1), cg_vec3_make(0, 0, -1), a, b,
                           cg_vec3_make(0, NAN, 0), 0, INFINITY, &t, &u, &v));
    /* Corners and edges count as inside. */
    CHECK(cg_ray_triangle(cg_vec3_make(0, 0, 1), cg_vec3_make(0, 0, -1), a, b, c, 0, INFINITY, &t,
                          &u, &v));
    CHECK(cg_ray_triangle(cg_vec3_make(0.5, 0.5, 1), cg_vec3_make(0, 0, -1), a, b, c, 0, INFINITY,
                          &t, &u, &v));

    /* BVH: empty, NaN vertices, bad indices. */
    cg_bvh *bvh;
    CHECK(cg_bvh_build(NULL, 0, NULL, 0, &bvh) == CG_OK);
    CHECK(!cg_bvh_intersect(bvh, a, c, 0, INFINITY, NULL));
    CHECK(!cg_bvh_occluded(bvh, a, c, 0, INFINITY));
    cg_bvh_free(bvh);
    cg_vec3 p[6] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {NAN, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(cg_bvh_build(p, 6, NULL, 2, &bvh) == CG_OK);
    cg_bvh_stats st;
    cg_bvh_get_stats(bvh, &st);
    CHECK_EQ_INT(st.triangles, 1);
    cg_bvh_hit h;
    CHECK(
        cg_bvh_intersect(bvh, cg_vec3_make(0.2, 0.2, 1), cg_vec3_make(0, 0, -1), 0, INFINITY, &h));
    CHECK_EQ_INT(h.triangle, 0);
    CHECK(!cg_bvh_intersect(bvh, cg_vec3_make(0.2, 0.2, 1), cg_vec3_make(0, NAN, -1), 0, INFINITY,
                            &h));
    CHECK(!cg_bvh_intersect(bvh, cg_vec3_make(INFINITY, 0.2, 1), cg_vec3_make(0, 0, -1), 0,
                            INFINITY, &h));
    cg_bvh_free(bvh);
    uint32_t bad[3] = {0, 1, 6};
    CHECK(cg_bvh_build(p, 6, bad, 1, &bvh) == CG_EINVAL);
    CHECK(cg_bvh_build(p, 6, NULL, 3, &bvh) == CG_EINVAL);
    /* Many copies of one triangle: the build must still terminate with a
     * shallow tree, and ties go to the lowest index. */
    enum { COPIES = 5000 };
    cg_vec3 *same = malloc(3 * COPIES * sizeof *same);
    for (int i = 0; i < 3 * COPIES; i++)
        same[i] = p[i % 3];
    CHECK(cg_bvh_build(same, 3 * COPIES, NULL, COPIES, &bvh) == CG_OK);
    CHECK(
        cg_bvh_intersect(bvh, cg_vec3_make(0.2, 0.2, 1), cg_vec3_make(0, 0, -1), 0, INFINITY, &h));
    CHECK_EQ_INT(h.triangle, 0);
    cg_bvh_get_stats(bvh, &st);
    CHECK(st.depth <= 64);
    cg_bvh_free(bvh);
    free(same);
}

static void test_optics(void)
{
    cg_vec3 n = {0, 1, 0};
    cg_vec3 r = cg_reflect(cg_vec3_make(1, -1, 0), n);
    CHECK_NEAR(r.x, 1, 1e-15);
    CHECK_NEAR(r.y, 1, 1e-15);
    /* Normal incidence passes straight through. */
    cg_vec3 t;
    CHECK(cg_refract(cg_vec3_make(0, -1, 0), n, 1, 1.5, &t));
    CHECK_NEAR(t.x, 0, 1e-15);
    CHECK_NEAR(t.y, -1, 1e-15);
    /* Snell: 45 degrees from air into glass, sin(theta_t) = sin 45 / 1.5. */
    cg_vec3 in = cg_vec3_normalize(cg_vec3_make(1, -1, 0));
    CHECK(cg_refract(in, n, 1, 1.5, &t));
    CHECK_NEAR(t.x, sqrt(0.5) / 1.5, 1e-12);
    CHECK_NEAR(cg_vec3_length(t), 1, 1e-12);
    CHECK(t.y < 0);
    /* Leaving glass at 45 degrees is beyond the critical angle asin(1/1.5) =
     * 41.8 degrees: total internal reflection; at 40 degrees it refracts. */
    CHECK(!cg_refract(in, n, 1.5, 1, &t));
    double a40 = cg_radians(40);
    CHECK(cg_refract(cg_vec3_make(sin(a40), -cos(a40), 0), n, 1.5, 1, &t));
    CHECK_NEAR(t.x, 1.5 * sin(a40), 1e-12);
    /* Schlick: R0 = ((1 - 1.5) / 2.5)^2 = 0.04 at normal incidence, 1 at
     * grazing incidence and under total internal reflection. */
    CHECK_NEAR(cg_fresnel_schlick(1, 1, 1.5), 0.04, 1e-15);
    CHECK_NEAR(cg_fresnel_schlick(0, 1, 1.5), 1, 1e-15);
    CHECK_NEAR(cg_fresnel_schlick(0.5, 1, 1.5), 0.04 + 0.96 / 32, 1e-15);
    CHECK_NEAR(cg_fresnel_schlick(cos(cg_radians(45)), 1.5, 1), 1, 0);
    /* Leaving glass below the critical angle uses the transmitted angle:
     * at 30 degrees, sin(theta_t) = 0.75. */
    double ct = sqrt(1 - 0.75 * 0.75);
    CHECK_NEAR(cg_fresnel_schlick(cos(cg_radians(30)), 1.5, 1), 0.04 + 0.96 * pow(1 - ct, 5),
               1e-12);
    /* Invalid indices: no refraction, full reflection. */
    CHECK(!cg_refract(in, n, 1, 0, &t));
    CHECK(!cg_refract(in, n, NAN, 1, &t));
    CHECK_NEAR(cg_fresnel_schlick(0.5, 1, 0), 1, 0);
}

/* Whether two RGBA8 images of one size hold the same bytes. */
static int same_pixels(cg_image *a, cg_image *b)
{
    int same = 1;
    for (int y = 0; same && y < a->height; y++)
        same = memcmp(cg_image_row_rgba8(a, y), cg_image_row_rgba8(b, y), 4 * (size_t)a->width)
               == 0;
    return same;
}

static int render_equal(cg_trace_scene *scene, const cg_camera *cam, cg_trace_options opt, int w,
                        int h)
{
    cg_image *a, *b;
    cg_image_create(&a, w, h, CG_PIXEL_RGBA8);
    cg_image_create(&b, w, h, CG_PIXEL_RGBA8);
    opt.threads = 1;
    int ok = cg_trace_render(scene, cam, &opt, a, NULL) == CG_OK;
    opt.threads = 3;
    ok = ok && cg_trace_render(scene, cam, &opt, b, NULL) == CG_OK && same_pixels(a, b);
    cg_image_free(a);
    cg_image_free(b);
    return ok;
}

/* The classic scene, a camera at eye looking at its centre, and options
 * with `samples` samples per pixel. */
static cg_trace_scene *classic_view(cg_vec3 eye, int samples, cg_camera *cam, cg_trace_options *opt)
{
    cg_trace_scene *scene = NULL;
    CHECK(cg_trace_scene_classic(&scene) == CG_OK);
    *cam = cg_camera_default();
    cam->eye = eye;
    cam->target = cg_vec3_make(0, 0.8, 0);
    *opt = cg_trace_options_default();
    opt->samples = samples;
    return scene;
}

/* Progress calls of one render: their count and whether done rose by one
 * at each call up to the total. */
typedef struct progress_log {
    int calls, in_order, total;
} progress_log;

static void log_progress(void *user, int done, int total)
{
    progress_log *log = user;
    log->calls++;
    log->in_order &= done == log->calls && total == log->total;
}

/* One scene rendered again and again on changing thread counts (its worker
 * pool kept, remade when the count changes): the same bytes and the same
 * ray count every time, and the progress called once per tile, in order. */
static void test_scene_threads(void)
{
    cg_camera cam;
    cg_trace_options opt;
    cg_trace_scene *scene = classic_view(cg_vec3_make(1, 2, 6), 2, &cam, &opt);
    if (!scene)
        return;
    const int w = 70, h = 37, tiles = 5 * 3; /* tiles of 16 pixels */
    cg_image *first, *again;
    CHECK(cg_image_create(&first, w, h, CG_PIXEL_RGBA8) == CG_OK);
    CHECK(cg_image_create(&again, w, h, CG_PIXEL_RGBA8) == CG_OK);
    cg_trace_stats reference, stats;
    CHECK(cg_trace_render(scene, &cam, &opt, first, &reference) == CG_OK);
    static const int counts[] = {4, 2, 2, 7, 1, 3, 16, 2};
    for (size_t i = 0; i < sizeof counts / sizeof *counts; i++) {
        opt.threads = counts[i];
        progress_log log = {0, 1, tiles};
        opt.progress = log_progress;
        opt.progress_user = &log;
        CHECK(cg_trace_render(scene, &cam, &opt, again, &stats) == CG_OK);
        CHECK_MSG(same_pixels(first, again), "%d threads: the picture differs from one thread's",
                  counts[i]);
        CHECK_EQ_INT(stats.rays, reference.rays);
        CHECK_MSG(log.calls == tiles && log.in_order,
                  "%d threads: %d progress calls (in order: %d)", counts[i], log.calls,
                  log.in_order);
    }
    cg_image_free(first);
    cg_image_free(again);
    cg_trace_scene_free(scene);
}

static void test_scene(void)
{
    cg_camera cam;
    cg_trace_options opt;
    cg_trace_scene *scene = classic_view(cg_vec3_make(0, 2.5, 7), 3, &cam, &opt);
    if (!scene)
        return;
    CHECK_MSG(render_equal(scene, &cam, opt, 45, 31),
              "classic scene differs between 1 and 3 threads");
    cg_trace_stats stats;
    cg_image *img;
    cg_image_create(&img, 40, 30, CG_PIXEL_RGBAF);
    CHECK(cg_trace_render(scene, &cam, &opt, img, &stats) == CG_OK);
    CHECK(stats.rays >= 40 * 30 * 3);
    opt.samples = 0;
    CHECK(cg_trace_render(scene, &cam, &opt, img, NULL) == CG_EINVAL);
    opt.samples = 1;
    opt.max_depth = 1000;
    CHECK(cg_trace_render(scene, &cam, &opt, img, NULL) == CG_ERANGE);
    opt.max_depth = -1;
    CHECK(cg_trace_render(scene, &cam, &opt, img, NULL) == CG_EINVAL);
    cg_trace_scene_free(scene);

    /* Bad objects. */
    CHECK(cg_trace_scene_create(&scene) == CG_OK);
    cg_trace_material m = cg_trace_material_default();
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), -1, NULL, &m) == CG_EINVAL);
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), NAN, NULL, &m) == CG_EINVAL);
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(NAN, 0, 0), 1, NULL, &m) == CG_EINVAL);
    cg_mat4 singular = cg_xform3_scale(1, 0, 1, cg_vec3_make(0, 0, 0));
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, &singular, &m) == CG_EINVAL);
    CHECK(cg_trace_scene_add_plane(scene, cg_vec3_make(0, 0, 0), cg_vec3_make(0, 0, 0), &m)
          == CG_EINVAL);
    m.surface.transmittance = 1;
    m.surface.refractive_index = -1;
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &m) == CG_EINVAL);
    m.surface.refractive_index = NAN;
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &m) == CG_EINVAL);
    m = cg_trace_material_default();
    m.surface.reflectance = 2;
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &m) == CG_EINVAL);
    m = cg_trace_material_default();
    m.checker_size = -1;
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &m) == CG_EINVAL);
    cg_light light = cg_light_directional(cg_vec3_make(0, 0, -1), cg_vec3_make(1, 1, 1));
    light.direction = cg_vec3_make(0, 0, 0);
    CHECK(cg_trace_scene_add_light(scene, &light) == CG_EINVAL); /* zero direction */
    cg_trace_area_light area = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}, 0};
    CHECK(cg_trace_scene_add_area_light(scene, &area) == CG_EINVAL); /* no samples */
    area.samples = 2;
    area.corner.x = NAN;
    CHECK(cg_trace_scene_add_area_light(scene, &area) == CG_EINVAL);

    /* The empty scene renders the background; a zero-radius sphere is
     * invisible. */
    cg_vec3 lo, hi;
    CHECK(cg_trace_scene_bounds(scene, &lo, &hi) == CG_EEMPTY);
    m = cg_trace_material_default();
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 0, NULL, &m) == CG_OK);
    opt = cg_trace_options_default();
    opt.background = (cg_rgbaf){0.25f, 0.5f, 0.75f, 1};
    CHECK(cg_trace_render(scene, &cam, &opt, img, NULL) == CG_OK);
    int all_background = 1;
    for (int y = 0; y < 30; y++)
        for (int x = 0; x < 40; x++) {
            cg_rgbaf p = cg_image_get(img, x, y);
            all_background &= p.r == 0.25f && p.g == 0.5f && p.b == 0.75f && p.a == 1;
        }
    CHECK(all_background);
    cg_trace_scene_free(scene);

    /* A glass sphere inside a closed mirror sphere, seen from inside: every
     * ray bounces until the depth limit; the render must end. */
    CHECK(cg_trace_scene_create(&scene) == CG_OK);
    cg_trace_material mirror = cg_trace_material_default();
    mirror.surface.reflectance = 1;
    cg_trace_material glass = cg_trace_material_default();
    glass.surface.transmittance = 1;
    glass.surface.kd = 0;
    glass.surface.refractive_index = 1e-3; /* absurd but valid: total internal reflection */
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 10, NULL, &mirror) == CG_OK);
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, -3), 1, NULL, &glass) == CG_OK);
    light = cg_light_point(cg_vec3_make(0, 5, 0), cg_vec3_make(1, 1, 1));
    CHECK(cg_trace_scene_add_light(scene, &light) == CG_OK);
    cam = cg_camera_default();
    cam.eye = cg_vec3_make(0, 0, 0);
    cam.target = cg_vec3_make(0, 0, -1);
    opt = cg_trace_options_default();
    opt.max_depth = 64;
    cg_image *small;
    cg_image_create(&small, 8, 6, CG_PIXEL_RGBAF);
    CHECK(cg_trace_render(scene, &cam, &opt, small, NULL) == CG_OK);
    cg_image_free(small);
    cg_trace_scene_free(scene);
    cg_image_free(img);
}

/* A glass sphere of index 1 (and of index 0, which means 1) bends nothing
 * and reflects nothing: the picture equals the one without the sphere. */
static void test_index_one(void)
{
    cg_image *img[3];
    cg_camera cam = cg_camera_default();
    cam.eye = cg_vec3_make(0, 1.5, 6);
    cam.target = cg_vec3_make(0, 0.5, 0);
    for (int k = 0; k < 3; k++) {
        cg_trace_scene *scene;
        cg_trace_scene_create(&scene);
        cg_trace_material floor = cg_trace_material_default();
        floor.checker_size = 0.5;
        floor.checker_color = cg_vec3_make(0.2, 0.3, 0.9);
        cg_trace_scene_add_plane(scene, cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &floor);
        cg_light l = cg_light_directional(cg_vec3_make(0, -1, 0), cg_vec3_make(1, 1, 1));
        cg_trace_scene_add_light(scene, &l);
        if (k > 0) {
            cg_trace_material glass = cg_trace_material_default();
            glass.surface.ka = glass.surface.kd = glass.surface.ks = 0;
            glass.surface.transmittance = 1;
            glass.surface.refractive_index = k == 1 ? 1 : 0;
            CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 1, 0), 1, NULL, &glass)
                  == CG_OK);
        }
        cg_image_create(&img[k], 40, 30, CG_PIXEL_RGBAF);
        cg_trace_options opt = cg_trace_options_default();
        opt.shadows = 0;
        CHECK(cg_trace_render(scene, &cam, &opt, img[k], NULL) == CG_OK);
        cg_trace_scene_free(scene);
    }
    double worst0 = 0;
    for (int y = 0; y < 30; y++)
        for (int x = 0; x < 40; x++) {
            cg_rgbaf b = cg_image_get(img[1], x, y), c = cg_image_get(img[2], x, y);
            worst0 = fmax(worst0, fabs(c.r - b.r) + fabs(c.g - b.g) + fabs(c.b - b.b));
        }
    /* Pixels whose ray passes within rounding of a checker edge may flip. */
    long differ = 0;
    for (int y = 0; y < 30; y++)
        for (int x = 0; x < 40; x++) {
            cg_rgbaf a = cg_image_get(img[0], x, y), b = cg_image_get(img[1], x, y);
            differ += fabs(a.r - b.r) > 1e-4;
        }
    CHECK_MSG(differ <= 2, "index-1 sphere changes %ld pixels", differ);
    CHECK_NEAR(worst0, 0, 0);
    for (int k = 0; k < 3; k++)
        cg_image_free(img[k]);
}

/* A mesh with NaN vertices, degenerate faces and out-of-range indices. */
static void test_mesh_input(void)
{
    cg_mesh *mesh;
    CHECK(cg_mesh_create(&mesh, 5, 3, 10, 0) == CG_OK);
    cg_vec3 p[5] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {NAN, 0, 0}};
    memcpy(mesh->positions, p, sizeof p);
    uint32_t idx[10] = {0, 1, 2, 3, /* quad */ 0, 0, 1, /* degenerate */ 4, 1, 2 /* NaN */};
    memcpy(mesh->face_indices, idx, sizeof idx);
    uint32_t off[4] = {0, 4, 7, 10};
    memcpy(mesh->face_offsets, off, sizeof off);
    cg_trace_scene *scene;
    CHECK(cg_trace_scene_create(&scene) == CG_OK);
    cg_trace_material m = cg_trace_material_default();
    CHECK(cg_trace_scene_add_mesh(scene, mesh, NULL, cg_radians(60), &m) == CG_OK);
    cg_light light = cg_light_directional(cg_vec3_make(0, 0, -1), cg_vec3_make(1, 1, 1));
    CHECK(cg_trace_scene_add_light(scene, &light) == CG_OK);
    light = cg_light_ambient(cg_vec3_make(0.1, 0.1, 0.1));
    CHECK(cg_trace_scene_add_light(scene, &light) == CG_OK);
    cg_camera cam = cg_camera_default();
    cg_image *img;
    cg_image_create(&img, 32, 32, CG_PIXEL_RGBAF);
    cg_trace_options opt = cg_trace_options_default();
    CHECK(cg_trace_render(scene, &cam, &opt, img, NULL) == CG_OK);
    /* The quad covers the centre: ambient 0.1 + diffuse 0.9 facing the light. */
    cg_rgbaf c = cg_image_get(img, 16, 16);
    CHECK_NEAR(c.r, 1.0 + 0.2, 1e-3); /* plus the highlight almost straight on: 0.2 */
    CHECK_NEAR(c.a, 1, 0);
    cg_rgbaf corner_px = cg_image_get(img, 0, 0);
    CHECK(corner_px.r == 0 && corner_px.a == 1); /* background: opaque black */
    mesh->face_indices[9] = 7;                   /* out of range */
    CHECK(cg_trace_scene_add_mesh(scene, mesh, NULL, cg_radians(60), &m) == CG_EFORMAT);
    cg_mesh_free(mesh);
    cg_image_free(img);
    cg_trace_scene_free(scene);
}

/* Hard shadows by definition: under an orthographic camera looking down, a
 * point on the floor behind a sphere (seen from the light) gets ambient
 * only, a point in the open gets ambient + diffuse cos(angle). */
static void test_shadow(void)
{
    cg_trace_scene *scene;
    CHECK(cg_trace_scene_create(&scene) == CG_OK);
    cg_trace_material m = cg_trace_material_default();
    m.surface.ks = 0;
    CHECK(cg_trace_scene_add_plane(scene, cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &m)
          == CG_OK);
    CHECK(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 2, 0), 1, NULL, &m) == CG_OK);
    /* Light from (1, 1, 0): it travels along (-1, -1, 0). */
    cg_light light = cg_light_directional(cg_vec3_make(-1, -1, 0), cg_vec3_make(1, 1, 1));
    CHECK(cg_trace_scene_add_light(scene, &light) == CG_OK);
    light = cg_light_ambient(cg_vec3_make(0.1, 0.1, 0.1));
    CHECK(cg_trace_scene_add_light(scene, &light) == CG_OK);
    cg_camera cam = cg_camera_default();
    cam.eye = cg_vec3_make(0, 10, 0);
    cam.target = cg_vec3_make(0, 0, 0);
    cam.up = cg_vec3_make(0, 0, -1);
    cam.orthographic = 1;
    cam.ortho_height = 8;
    cam.near = 1;
    cg_image *img;
    cg_image_create(&img, 64, 64, CG_PIXEL_RGBAF);
    cg_trace_options opt = cg_trace_options_default();
    CHECK(cg_trace_render(scene, &cam, &opt, img, NULL) == CG_OK);
    /* Pixel centre x = -4 + 8 (px + 0.5) / 64: pixel 15 is at x = -2.06,
     * z = 0 (row 31.5 -> pixel 31 or 32), the shadow's centre at (-2, 0, 0). */
    double lit = 0.1 + 0.9 * sqrt(0.5);
    CHECK_NEAR(cg_image_get(img, 15, 32).r, 0.1, 1e-5);
    CHECK_NEAR(cg_image_get(img, 56, 56).r, lit, 1e-5);
    opt.shadows = 0;
    CHECK(cg_trace_render(scene, &cam, &opt, img, NULL) == CG_OK);
    CHECK_NEAR(cg_image_get(img, 15, 32).r, lit, 1e-5);
    cg_image_free(img);
    cg_trace_scene_free(scene);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_triangle_and_bad_input);
    CHECK_GROUP(test_optics);
    CHECK_GROUP(test_bvh);
    CHECK_GROUP(test_scene);
    CHECK_GROUP(test_scene_threads);
    CHECK_GROUP(test_mesh_input);
    CHECK_GROUP(test_index_one);
    CHECK_GROUP(test_shadow);
    return check_finish();
}
