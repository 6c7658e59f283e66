/* The path tracer against analytic cases (white furnace, a Lambert plane
 * under point and directional lights), against the Whitted tracer's direct
 * lighting, its noise rate, and its determinism over threads, tiles and
 * sample ranges. */
#include "cg/pathtrace.h"
#include "check.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

enum { W = 24, H = 18 };

static cg_trace_material lambert(double albedo)
{
    cg_trace_material m = cg_trace_material_default();
    m.surface.color = cg_vec3_make(albedo, albedo, albedo);
    m.surface.kd = 1;
    m.surface.ka = 0;
    m.surface.ks = 0;
    return m;
}

static cg_camera looking_at(cg_vec3 eye, cg_vec3 target)
{
    cg_camera c = cg_camera_default();
    c.eye = eye;
    c.target = target;
    c.up = cg_vec3_make(0, 1, 0);
    if (fabs(eye.x - target.x) < 1e-9 && fabs(eye.z - target.z) < 1e-9)
        c.up = cg_vec3_make(0, 0, -1);
    c.near = 0.01;
    c.far = 100;
    return c;
}

/* Mean of channel r over the image. */
static double image_mean(const cg_image *im)
{
    double s = 0;
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++)
            s += cg_image_get(im, x, y).r;
    return s / ((double)im->width * im->height);
}

static cg_image *render(cg_trace_scene *scene, const cg_camera *cam, cg_path_options *o)
{
    cg_image *im = NULL;
    if (cg_image_create(&im, W, H, CG_PIXEL_RGBAF) != CG_OK)
        return NULL;
    if (cg_path_render(scene, cam, o, im) != CG_OK) {
        cg_image_free(im);
        return NULL;
    }
    return im;
}

/* A sphere of one material filling part of the view under environment 0.5:
 * every pixel's expected value is 0.5 times the albedo where paths end on
 * the sphere's Lambert lobe after one bounce (a convex body is left at once). */
static double furnace(cg_trace_material m, int spp, double *worst)
{
    cg_trace_scene *scene = NULL;
    cg_trace_scene_create(&scene);
    cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &m);
    cg_camera cam = looking_at(cg_vec3_make(0, 0, 3), cg_vec3_make(0, 0, 0));
    cg_path_options o = cg_path_options_default();
    o.spp = spp;
    o.max_depth = 64;
    o.environment = cg_vec3_make(0.5, 0.5, 0.5);
    cg_image *im = render(scene, &cam, &o);
    double mean = im ? image_mean(im) : -1;
    *worst = 0;
    for (int y = 0; im && y < H; y++)
        for (int x = 0; x < W; x++) {
            double e = fabs(cg_image_get(im, x, y).r - 0.5);
            *worst = e > *worst ? e : *worst;
        }
    cg_image_free(im);
    cg_trace_scene_free(scene);
    return mean;
}

static void white_furnace(void)
{
    double worst;
    /* White Lambert: every path returns exactly the environment. */
    double mean = furnace(lambert(1), 8, &worst);
    CHECK_REPORT(fabs(mean - 0.5) < 1e-5, "lambert furnace mean %.7f", mean);
    CHECK_REPORT(worst < 1e-5, "lambert furnace worst pixel error %.2g", worst);
    /* A perfect mirror too. */
    cg_trace_material mirror = lambert(0.3);
    mirror.surface.reflectance = 1;
    mean = furnace(mirror, 4, &worst);
    CHECK_REPORT(worst < 1e-5, "mirror furnace worst pixel error %.2g", worst);
    /* Smooth glass conserves energy: paths bounce inside, Russian roulette
     * ends some; the mean stays within the noise bound. */
    cg_trace_material glass = lambert(0.3);
    glass.surface.transmittance = 1;
    glass.surface.refractive_index = 1.5;
    mean = furnace(glass, 64, &worst);
    CHECK_REPORT(fabs(mean - 0.5) < 0.01, "glass furnace mean %.5f", mean);
    /* A grey Lambert sphere: 0.5 outside it; on it albedo 0.5 makes each
     * bounce keep half, so its pixels lie strictly between 0.25 and 0.5. */
    mean = furnace(lambert(0.5), 8, &worst);
    CHECK_REPORT(mean < 0.5 && mean > 0.25 + 0.05, "grey furnace mean %.5f", mean);
}

/* A Lambert plane y = 0 of albedo rho seen from above: under a directional
 * light of irradiance E at angle theta, L = rho E cos(theta) / pi exactly;
 * under a point light of intensity I at height h with 1/d^2 falloff,
 * L = rho I h / (pi d^3). */
/* Emission.  Seen directly, a black emitter gives its radiance exactly.
 * Inside a closed sphere emitting E with Lambert albedo a (no lights, no
 * sky), every path bounces until Russian roulette or the depth stops it:
 * the radiance is E (1 + a + a^2 + ...) = E / (1 - a), here 0.2 / 0.6. */
static void emission(void)
{
    cg_trace_scene *scene = NULL;
    cg_trace_material glow = lambert(0);
    glow.emission = cg_vec3_make(0.25, 0.5, 2);
    cg_trace_scene_create(&scene);
    cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &glow);
    cg_camera cam = looking_at(cg_vec3_make(0, 0, 3), cg_vec3_make(0, 0, 0));
    cam.fovy = 0.2; /* radians: the sphere (half-angle 0.34) fills the view */
    cg_path_options o = cg_path_options_default();
    o.spp = 2;
    cg_image *im = render(scene, &cam, &o);
    int exact = im != NULL;
    for (int y = 0; im && y < H; y++)
        for (int x = 0; x < W; x++) {
            cg_rgbaf c = cg_image_get(im, x, y);
            exact &= fabs(c.r - 0.25) < 1e-6 && fabs(c.g - 0.5) < 1e-6 && fabs(c.b - 2) < 1e-6;
        }
    CHECK_REPORT(exact, "a black emitter seen directly is not its emission");
    cg_image_free(im);
    cg_trace_scene_free(scene);

    cg_trace_material room = lambert(0.4);
    room.emission = cg_vec3_make(0.2, 0.2, 0.2);
    cg_trace_scene_create(&scene);
    cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &room);
    cam = looking_at(cg_vec3_make(0, 0, 0.2), cg_vec3_make(0, 0, -1));
    o.spp = 64;
    o.max_depth = 64;
    im = render(scene, &cam, &o);
    double mean = im ? image_mean(im) : -1;
    CHECK_REPORT(fabs(mean - 0.2 / 0.6) < 0.01 * (0.2 / 0.6), "emitting room mean %.5f, want %.5f",
                 mean, 0.2 / 0.6);
    cg_image_free(im);
    cg_trace_scene_free(scene);

    cg_trace_material bad = lambert(0.5);
    bad.emission.y = -1;
    cg_trace_scene_create(&scene);
    CHECK_REPORT(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &bad) != CG_OK,
                 "a negative emission is accepted");
    bad.emission.y = NAN;
    CHECK_REPORT(cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &bad) != CG_OK,
                 "a NaN emission is accepted");
    cg_trace_scene_free(scene);
}

static void lambert_plane(void)
{
    double rho = 0.7;
    cg_trace_material m = lambert(rho);
    for (int kind = 0; kind < 2; kind++) {
        cg_trace_scene *scene = NULL;
        cg_trace_scene_create(&scene);
        cg_trace_scene_add_plane(scene, cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &m);
        cg_light l;
        cg_vec3 lp = cg_vec3_make(0.3, 4, -0.2);
        if (kind == 0) {
            l = cg_light_directional(cg_vec3_make(1, -2, 0.5), cg_vec3_make(2, 2, 2));
        } else {
            l = cg_light_point(lp, cg_vec3_make(30, 30, 30));
            cg_light_set_attenuation(&l, 0, 0, 1);
        }
        cg_trace_scene_add_light(scene, &l);
        cg_camera cam = looking_at(cg_vec3_make(0, 5, 0), cg_vec3_make(0, 0, 0));
        cam.orthographic = 1;
        cam.ortho_height = 0.2; /* a small patch: the point light's field is smooth on it */
        cg_path_options o = cg_path_options_default();
        o.spp = 4;
        o.max_depth = 4;
        cg_image *im = render(scene, &cam, &o);
        double expected;
        if (kind == 0) {
            double c = 2 / sqrt(1 + 4 + 0.25);
            expected = rho * 2 * c / M_PI;
        } else {
            double d = sqrt(lp.x * lp.x + lp.y * lp.y + lp.z * lp.z);
            expected = rho * 30 * lp.y / (M_PI * d * d * d);
        }
        double mean = im ? image_mean(im) : -1;
        double tol = kind == 0 ? 1e-5 : 2e-3 * expected;
        CHECK_REPORT(fabs(mean - expected) < tol, "light %d: %.6f vs closed form %.6f", kind, mean,
                     expected);
        cg_image_free(im);
        cg_trace_scene_free(scene);
    }
}

/* Direct light only (max depth 1, black environment) on a diffuse scene
 * equals the Whitted tracer's diffuse term (kd Od I cos f_att) over pi. */
static void whitted_direct(void)
{
    cg_trace_scene *scene = NULL;
    cg_trace_scene_create(&scene);
    cg_trace_material a = lambert(0.8), b = lambert(0.4);
    cg_trace_scene_add_plane(scene, cg_vec3_make(0, -1, 0), cg_vec3_make(0, 1, 0), &a);
    cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &b);
    cg_light l = cg_light_point(cg_vec3_make(2, 4, 3), cg_vec3_make(40, 40, 40));
    cg_light_set_attenuation(&l, 0, 0, 1);
    cg_trace_scene_add_light(scene, &l);
    cg_camera cam = looking_at(cg_vec3_make(0, 2, 6), cg_vec3_make(0, 0, 0));
    cg_path_options o = cg_path_options_default();
    o.spp = 64;
    o.max_depth = 1;
    cg_image *path = render(scene, &cam, &o);
    cg_image *whitted = NULL;
    cg_image_create(&whitted, W, H, CG_PIXEL_RGBAF);
    cg_trace_options t = cg_trace_options_default();
    t.samples = 64;
    t.max_depth = 0;
    t.background.a = 1;
    cg_status s = cg_trace_render(scene, &cam, &t, whitted, NULL);
    CHECK_REPORT(s == CG_OK && path, "both render");
    double worst = 0, mp = 0, mw = 0;
    for (int y = 0; path && y < H; y++)
        for (int x = 0; x < W; x++) {
            double p = cg_image_get(path, x, y).r, w = cg_image_get(whitted, x, y).r / M_PI;
            mp += p;
            mw += w;
            worst = fabs(p - w) > worst ? fabs(p - w) : worst;
        }
    CHECK_REPORT(mw > 0.05 * W * H && fabs(mp - mw) < 0.01 * mw, "means %.5f vs %.5f", mp / (W * H),
                 mw / (W * H));
    CHECK_REPORT(worst < 0.1, "worst pixel difference %.4f", worst);
    cg_image_free(path);
    cg_image_free(whitted);
    cg_trace_scene_free(scene);
}

/* Indirect light: a grey sphere on a grey plane under a uniform sky.  The
 * RMS error against a 1024-sample reference falls as 1/sqrt(spp). */
static void noise_rate(void)
{
    cg_trace_scene *scene = NULL;
    cg_trace_scene_create(&scene);
    cg_trace_material a = lambert(0.7);
    cg_trace_scene_add_plane(scene, cg_vec3_make(0, -1, 0), cg_vec3_make(0, 1, 0), &a);
    cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 0, 0), 1, NULL, &a);
    cg_camera cam = looking_at(cg_vec3_make(0, 1, 5), cg_vec3_make(0, -0.5, 0));
    cg_path_options o = cg_path_options_default();
    o.environment = cg_vec3_make(1, 1, 1);
    o.threads = 2;
    o.spp = 1024;
    cg_image *ref = render(scene, &cam, &o);
    double rms[2];
    const int spp[2] = {4, 64};
    for (int i = 0; i < 2; i++) {
        o.spp = spp[i];
        double e2 = 0;
        /* Several seeds, so that the estimate of the error is steady. */
        for (uint64_t seed = 1; seed <= 4; seed++) {
            o.seed = seed;
            cg_image *im = render(scene, &cam, &o);
            for (int y = 0; im && ref && y < H; y++)
                for (int x = 0; x < W; x++) {
                    double d = cg_image_get(im, x, y).r - cg_image_get(ref, x, y).r;
                    e2 += d * d;
                }
            cg_image_free(im);
        }
        rms[i] = sqrt(e2 / (4.0 * W * H));
    }
    double ratio = rms[0] / rms[1]; /* sqrt(64 / 4) = 4 expected */
    CHECK_REPORT(rms[1] > 0 && ratio > 3 && ratio < 5.5, "rms %.4f, %.4f: ratio %.2f", rms[0],
                 rms[1], ratio);
    cg_image_free(ref);
    cg_trace_scene_free(scene);
}

static cg_trace_scene *busy_scene(void)
{
    cg_trace_scene *scene = NULL;
    cg_trace_scene_create(&scene);
    cg_trace_material a = lambert(0.7), g = lambert(0.2), mr = lambert(0.1);
    g.surface.transmittance = 1;
    g.surface.refractive_index = 1.5;
    mr.surface.reflectance = 0.8;
    cg_trace_scene_add_plane(scene, cg_vec3_make(0, -1, 0), cg_vec3_make(0, 1, 0), &a);
    cg_trace_scene_add_sphere(scene, cg_vec3_make(-1, 0, 0), 1, NULL, &g);
    cg_trace_scene_add_sphere(scene, cg_vec3_make(1.2, 0, -0.5), 1, NULL, &mr);
    cg_light l = cg_light_point(cg_vec3_make(2, 4, 3), cg_vec3_make(40, 40, 40));
    cg_light_set_attenuation(&l, 0, 0, 1);
    cg_trace_scene_add_light(scene, &l);
    cg_trace_area_light al = {cg_vec3_make(-1, 3, -1), cg_vec3_make(1, 0, 0), cg_vec3_make(0, 0, 1),
                              cg_vec3_make(5, 5, 5), 1};
    cg_trace_scene_add_area_light(scene, &al);
    return scene;
}

static void determinism(void)
{
    cg_trace_scene *scene = busy_scene();
    cg_camera cam = looking_at(cg_vec3_make(0, 1, 6), cg_vec3_make(0, 0, 0));
    cg_path_options o = cg_path_options_default();
    o.spp = 12;
    o.seed = 7;
    o.environment = cg_vec3_make(0.2, 0.3, 0.5);
    size_t n = (size_t)W * H * 3;
    uint64_t *ref = calloc(n, 8), *other = calloc(n, 8);
    CHECK_REPORT(cg_path_render_sums(scene, &cam, W, H, &o, ref) == CG_OK, "whole render");
    const int threads[3] = {1, 2, 4};
    for (int i = 0; i < 3; i++) {
        memset(other, 0, n * 8);
        o.threads = threads[i];
        cg_path_render_sums(scene, &cam, W, H, &o, other);
        CHECK_REPORT(memcmp(ref, other, n * 8) == 0, "%d threads give the same sums", threads[i]);
    }
    /* Sample ranges 0..5 and 5..12 add up to the whole. */
    memset(other, 0, n * 8);
    o.threads = 2;
    o.sample_begin = 0;
    o.sample_end = 5;
    cg_path_render_sums(scene, &cam, W, H, &o, other);
    o.sample_begin = 5;
    o.sample_end = 12;
    cg_path_render_sums(scene, &cam, W, H, &o, other);
    CHECK_REPORT(memcmp(ref, other, n * 8) == 0, "sample ranges add up to the whole");
    /* Four tiles of uneven size. */
    o.sample_begin = 0;
    o.sample_end = 0;
    const int xs[3] = {0, 7, W}, ys[3] = {0, 11, H};
    int same = 1;
    for (int ty = 0; ty < 2; ty++)
        for (int tx = 0; tx < 2; tx++) {
            o.x0 = xs[tx];
            o.x1 = xs[tx + 1];
            o.y0 = ys[ty];
            o.y1 = ys[ty + 1];
            int w = o.x1 - o.x0, h = o.y1 - o.y0;
            uint64_t *tile = calloc((size_t)w * h * 3, 8);
            cg_path_render_sums(scene, &cam, W, H, &o, tile);
            for (int y = 0; y < h; y++)
                same &= memcmp(tile + (size_t)y * w * 3, ref + ((size_t)(o.y0 + y) * W + o.x0) * 3,
                               (size_t)w * 3 * 8)
                        == 0;
            free(tile);
        }
    CHECK_REPORT(same, "tiles give the whole render's sums");
    /* A different seed changes the picture. */
    o.x0 = o.x1 = o.y0 = o.y1 = 0;
    o.seed = 8;
    memset(other, 0, n * 8);
    cg_path_render_sums(scene, &cam, W, H, &o, other);
    CHECK_REPORT(memcmp(ref, other, n * 8) != 0, "another seed, other samples");
    free(ref);
    free(other);
    cg_trace_scene_free(scene);
}

/* Two sample ranges saved as parts, loaded and merged: the whole render's
 * sums; damaged files and mismatched parts are refused. */
static void parts(void)
{
    cg_trace_scene *scene = busy_scene();
    cg_camera cam = looking_at(cg_vec3_make(0, 1, 6), cg_vec3_make(0, 0, 0));
    cg_path_options o = cg_path_options_default();
    o.spp = 6;
    o.seed = 3;
    size_t n = (size_t)W * H * 3;
    uint64_t *ref = calloc(n, 8), *a = calloc(n, 8), *b = calloc(n, 8);
    cg_path_render_sums(scene, &cam, W, H, &o, ref);
    o.sample_end = 2;
    cg_path_render_sums(scene, &cam, W, H, &o, a);
    o.sample_begin = 2;
    o.sample_end = 6;
    cg_path_render_sums(scene, &cam, W, H, &o, b);
    cg_path_part pa = {W, H, 0, 0, W, H, 0, 2, 6, 8, 3, 77, a}, pb = pa;
    pb.sample_begin = 2;
    pb.sample_end = 6;
    pb.sums = b;
    cg_error err;
    CHECK_REPORT(cg_path_part_save(&pa, "pathtrace_a.part", &err) == CG_OK, "save a");
    CHECK_REPORT(cg_path_part_save(&pb, "pathtrace_b.part", &err) == CG_OK, "save b");
    cg_path_part loaded[2], merged;
    CHECK_REPORT(cg_path_part_load("pathtrace_a.part", &loaded[0], &err) == CG_OK, "load a");
    CHECK_REPORT(cg_path_part_load("pathtrace_b.part", &loaded[1], &err) == CG_OK, "load b");
    cg_status s = cg_path_part_merge(loaded, 2, &merged, &err);
    CHECK_REPORT(s == CG_OK && memcmp(merged.sums, ref, n * 8) == 0, "merged sums are the whole");
    if (s == CG_OK)
        free(merged.sums);
    CHECK_REPORT(cg_path_part_merge(loaded, 1, &merged, &err) == CG_EINVAL,
                 "missing samples refused: %s", err.message);
    loaded[1].seed = 4;
    CHECK_REPORT(cg_path_part_merge(loaded, 2, &merged, &err) == CG_EINVAL, "another seed refused");
    loaded[1].seed = loaded[0].seed;
    loaded[1].render_key = 78;
    CHECK_REPORT(cg_path_part_merge(loaded, 2, &merged, &err) == CG_EINVAL,
                 "another render key refused");
    CHECK_REPORT(loaded[0].render_key == 77, "the render key survives save and load");
    free(loaded[0].sums);
    free(loaded[1].sums);
    FILE *f = fopen("pathtrace_a.part", "r+b");
    if (f) {
        fseek(f, -3, SEEK_END);
        fputc('x', f);
        fclose(f);
    }
    f = fopen("pathtrace_bad.part", "wb");
    if (f) {
        fwrite("CGPART1\n", 1, 8, f);
        fclose(f);
    }
    CHECK_REPORT(cg_path_part_load("pathtrace_bad.part", &merged, &err) == CG_EFORMAT,
                 "short header refused");
    CHECK_REPORT(cg_path_part_load("pathtrace_missing.part", &merged, &err) == CG_EIO,
                 "missing file refused");
    remove("pathtrace_a.part");
    remove("pathtrace_b.part");
    remove("pathtrace_bad.part");
    free(ref);
    free(a);
    free(b);
    cg_trace_scene_free(scene);
}

static void bad_input(void)
{
    cg_trace_scene *scene = busy_scene();
    cg_camera cam = looking_at(cg_vec3_make(0, 1, 6), cg_vec3_make(0, 0, 0));
    uint64_t sums[3 * 4] = {0};
    cg_path_options o = cg_path_options_default();
    CHECK_REPORT(cg_path_render_sums(NULL, &cam, 2, 2, &o, sums) == CG_EINVAL, "no scene");
    CHECK_REPORT(cg_path_render_sums(scene, NULL, 2, 2, &o, sums) == CG_EINVAL, "no camera");
    CHECK_REPORT(cg_path_render_sums(scene, &cam, 0, 2, &o, sums) == CG_EINVAL, "zero width");
    CHECK_REPORT(cg_path_render_sums(scene, &cam, 2, 2, &o, NULL) == CG_EINVAL, "no sums");
    cg_path_options b = o;
    b.spp = 0;
    CHECK_REPORT(cg_path_render_sums(scene, &cam, 2, 2, &b, sums) == CG_EINVAL, "spp 0");
    b = o;
    b.max_depth = 0;
    CHECK_REPORT(cg_path_render_sums(scene, &cam, 2, 2, &b, sums) == CG_EINVAL, "depth 0");
    b = o;
    b.threads = 1000;
    CHECK_REPORT(cg_path_render_sums(scene, &cam, 2, 2, &b, sums) == CG_ERANGE, "too many threads");
    b = o;
    b.sample_begin = 4;
    b.sample_end = 3;
    CHECK_REPORT(cg_path_render_sums(scene, &cam, 2, 2, &b, sums) == CG_EINVAL, "empty range");
    b.sample_begin = 0;
    b.sample_end = 17;
    CHECK_REPORT(cg_path_render_sums(scene, &cam, 2, 2, &b, sums) == CG_EINVAL, "range past spp");
    b = o;
    b.environment.y = NAN;
    CHECK_REPORT(cg_path_render_sums(scene, &cam, 2, 2, &b, sums) == CG_EINVAL, "NaN environment");
    b = o;
    b.x0 = 1;
    b.x1 = 3;
    b.y1 = 1;
    CHECK_REPORT(cg_path_render_sums(scene, &cam, 2, 2, &b, sums) == CG_EINVAL, "tile outside");
    cg_camera bad = cam;
    bad.target = bad.eye;
    CHECK_REPORT(cg_path_render_sums(scene, &bad, 2, 2, &o, sums) != CG_OK, "degenerate camera");
    CHECK_REPORT(cg_path_resolve(sums, 2, 2, 0, NULL, 0, 0) == CG_EINVAL, "resolve without image");
    cg_trace_scene_free(scene);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(white_furnace);
    CHECK_GROUP(emission);
    CHECK_GROUP(lambert_plane);
    CHECK_GROUP(whitted_direct);
    CHECK_GROUP(noise_rate);
    CHECK_GROUP(determinism);
    CHECK_GROUP(parts);
    CHECK_GROUP(bad_input);
    return check_finish();
}
