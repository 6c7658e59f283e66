/* The path tracer's emitters sampled as lights: a Lambert plane beside a
 * square emitter against the closed-form irradiance, the MIS estimator's
 * mean against the estimator without emitter sampling on random scenes (and
 * its lower variance), emitters seen directly and in a mirror, a closed
 * emitting box, and determinism with emitters. */
#include "cg/mesh.h"
#include "cg/pathtrace.h"
#include "check.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

enum { W = 16, H = 12 };

static cg_trace_material lambert(double albedo)
{
    cg_trace_material m = cg_trace_material_default();
    m.surface.color = cg_vec3_make(albedo, albedo, albedo);
    m.surface.kd = 1;
    m.surface.ka = 0;
    m.surface.ks = 0;
    return m;
}

static cg_trace_material emitter(cg_vec3 radiance)
{
    cg_trace_material m = lambert(0);
    m.emission = radiance;
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

/* Adds the faces (each `corners` points of p, consecutive) as one mesh. */
static cg_status add_faces(cg_trace_scene *scene, const cg_vec3 *p, size_t faces, size_t corners,
                           const cg_trace_material *m)
{
    cg_mesh *mesh = NULL;
    size_t n = faces * corners;
    cg_status s = cg_mesh_create(&mesh, n, faces, n, 0);
    if (s != CG_OK)
        return s;
    for (size_t i = 0; i < n; i++) {
        mesh->positions[i] = p[i];
        mesh->face_indices[i] = (uint32_t)i;
    }
    for (size_t f = 0; f <= faces; f++)
        mesh->face_offsets[f] = (uint32_t)(f * corners);
    s = cg_trace_scene_add_mesh(scene, mesh, NULL, 0, m);
    cg_mesh_free(mesh);
    return s;
}

/* The square [x0, x1] x [z0, z1] at height y. */
static cg_status add_square(cg_trace_scene *scene, double x0, double x1, double z0, double z1,
                            double y, const cg_trace_material *m)
{
    cg_vec3 p[4] = {cg_vec3_make(x0, y, z0), cg_vec3_make(x1, y, z0), cg_vec3_make(x1, y, z1),
                    cg_vec3_make(x0, y, z1)};
    return add_faces(scene, p, 1, 4, m);
}

static cg_image *render(cg_trace_scene *scene, const cg_camera *cam, const cg_path_options *o)
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

static double image_mean(const cg_image *im, int channel)
{
    double s = 0;
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++) {
            cg_rgbaf c = cg_image_get(im, x, y);
            s += channel == 0 ? c.r : (channel == 1 ? c.g : c.b);
        }
    return s / ((double)im->width * im->height);
}

/* Irradiance at the origin from a Lambertian emitter of unit radiance
 * covering the rectangle [0, a] x [0, b] at height h parallel to the
 * receiving plane, signed in a and b (the corner form factor times pi). */
static double corner_irradiance(double a, double b, double h)
{
    double ra = sqrt(h * h + a * a), rb = sqrt(h * h + b * b);
    return 0.5 * (a / ra * atan(b / ra) + b / rb * atan(a / rb));
}

static double square_irradiance(double px, double pz, double x0, double x1, double z0, double z1,
                                double h)
{
    x0 -= px;
    x1 -= px;
    z0 -= pz;
    z1 -= pz;
    return corner_irradiance(x1, z1, h) - corner_irradiance(x0, z1, h)
           - corner_irradiance(x1, z0, h) + corner_irradiance(x0, z0, h);
}

/* A Lambert plane y = 0 (albedo rho) beside a black square emitter of
 * radiance Le at height h: the patch seen from above, outside the square's
 * shadow on the camera rays, has L = rho Le E / pi with E the closed form.
 * Both estimators are unbiased; the one with emitter sampling is far
 * quieter. */
static void square_emitter(void)
{
    const double rho = 0.7, le = 20, h = 0.8, px = 0.9, pz = 0.2;
    const double sx0 = -0.25, sx1 = 0.25, sz0 = -0.25, sz1 = 0.25; /* 0.5 x 0.5 */
    cg_trace_scene *scene = NULL;
    cg_trace_scene_create(&scene);
    cg_trace_material plane = lambert(rho), glow = emitter(cg_vec3_make(le, le, le));
    cg_trace_scene_add_plane(scene, cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &plane);
    CHECK(add_square(scene, sx0, sx1, sz0, sz1, h, &glow) == CG_OK);
    cg_camera cam = looking_at(cg_vec3_make(px, 5, pz), cg_vec3_make(px, 0, pz));
    cam.orthographic = 1;
    cam.ortho_height = 0.04;
    /* The expected image mean: the closed form averaged over the patch. */
    double expected = 0;
    const int grid = 8;
    for (int i = 0; i < grid; i++)
        for (int k = 0; k < grid; k++) {
            double x = px + (i + 0.5 - grid / 2.0) / grid * 0.04 * W / H;
            double z = pz + (k + 0.5 - grid / 2.0) / grid * 0.04;
            expected += rho * le * square_irradiance(x, z, sx0, sx1, sz0, sz1, h) / M_PI;
        }
    expected /= grid * grid;
    cg_path_options o = cg_path_options_default();
    o.spp = 64;
    o.max_depth = 4;
    cg_image *im = render(scene, &cam, &o);
    double mean = im ? image_mean(im, 0) : -1;
    CHECK_REPORT(fabs(mean - expected) < 0.01 * expected, "emitter sampling %.5f vs closed %.5f",
                 mean, expected);
    /* The same picture with emission found by BSDF rays alone: the same mean
     * within its (much larger) noise. */
    o.no_emitter_sampling = 1;
    o.spp = 1024;
    cg_image *old = render(scene, &cam, &o);
    double old_mean = old ? image_mean(old, 0) : -1;
    CHECK_REPORT(fabs(old_mean - expected) < 0.05 * expected, "BSDF hits only %.5f vs closed %.5f",
                 old_mean, expected);
    /* One depth: no emitter is met after the first hit, so none counts. */
    o.no_emitter_sampling = 0;
    o.spp = 4;
    o.max_depth = 1;
    cg_image *one = render(scene, &cam, &o);
    CHECK_REPORT(one && image_mean(one, 0) == 0, "max depth 1 sees no indirect emitter");
    cg_image_free(im);
    cg_image_free(old);
    cg_image_free(one);
    cg_trace_scene_free(scene);
}

static uint64_t rng_state;
static double rnd(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

/* A random room: a floor, a few spheres of random materials, and 1 to 4
 * random emitting triangles or squares (some tiny, some facing away). */
static cg_trace_scene *random_scene(uint64_t seed)
{
    rng_state = seed * 0x9e3779b97f4a7c15ULL + 1;
    cg_trace_scene *scene = NULL;
    cg_trace_scene_create(&scene);
    cg_trace_material floor = lambert(0.3 + 0.6 * rnd());
    cg_trace_scene_add_plane(scene, cg_vec3_make(0, -1, 0), cg_vec3_make(0, 1, 0), &floor);
    int spheres = 1 + (int)(rnd() * 3);
    for (int i = 0; i < spheres; i++) {
        cg_trace_material m = lambert(rnd());
        double kind = rnd();
        if (kind < 0.25)
            m.surface.reflectance = rnd();
        else if (kind < 0.4) {
            m.surface.transmittance = 1;
            m.surface.refractive_index = 1.5;
        }
        cg_vec3 c = cg_vec3_make(4 * rnd() - 2, -0.5 + rnd(), -2 * rnd());
        cg_trace_scene_add_sphere(scene, c, 0.3 + 0.5 * rnd(), NULL, &m);
    }
    int lights = 1 + (int)(rnd() * 4);
    for (int i = 0; i < lights; i++) {
        cg_trace_material g = emitter(cg_vec3_make(10 * rnd(), 10 * rnd(), 10 * rnd()));
        g.surface.color = cg_vec3_make(0.5, 0.5, 0.5); /* emitters reflect too */
        double size = rnd() < 0.5 ? 0.05 + 0.1 * rnd() : 0.5 + rnd();
        cg_vec3 c = cg_vec3_make(4 * rnd() - 2, 1 + 2 * rnd(), -2 * rnd());
        if (rnd() < 0.5) {
            add_square(scene, c.x - size, c.x + size, c.z - size, c.z + size, c.y, &g);
        } else {
            cg_vec3 p[3] = {c, cg_vec3_add(c, cg_vec3_make(size, -size * rnd(), 0)),
                            cg_vec3_add(c, cg_vec3_make(0, size * rnd(), size))};
            add_faces(scene, p, 1, 3, &g);
        }
    }
    return scene;
}

/* The image mean over seeds: its mean, the standard error of that mean, and
 * the variance of a pixel averaged over the image. */
static void seed_statistics(cg_trace_scene *scene, const cg_camera *cam, cg_path_options o,
                            int seeds, double *mean, double *error, double *pixel_variance)
{
    double s = 0, s2 = 0;
    double *p = calloc((size_t)W * H, sizeof *p), *p2 = calloc((size_t)W * H, sizeof *p2);
    for (int r = 0; r < seeds; r++) {
        o.seed = 100 + (uint64_t)r;
        cg_image *im = render(scene, cam, &o);
        double m = im ? image_mean(im, 1) : -1;
        s += m;
        s2 += m * m;
        for (int y = 0; im && y < H; y++)
            for (int x = 0; x < W; x++) {
                double v = cg_image_get(im, x, y).g;
                p[y * W + x] += v;
                p2[y * W + x] += v * v;
            }
        cg_image_free(im);
    }
    *mean = s / seeds;
    *error = sqrt(fmax(s2 / seeds - *mean * *mean, 0) / (seeds - 1));
    double v = 0;
    for (int i = 0; i < W * H; i++) {
        double pm = p[i] / seeds;
        v += fmax(p2[i] / seeds - pm * pm, 0) * seeds / (seeds - 1);
    }
    *pixel_variance = v / (W * H);
    free(p);
    free(p2);
}

/* On random scenes the mean with emitter sampling and MIS equals the mean
 * without it within 4.5 standard errors, and the pixel variance drops. */
static void mis_unbiased(void)
{
    double worst_z = 0, ratio_product = 1;
    const int scenes = 6;
    for (int k = 0; k < scenes; k++) {
        cg_trace_scene *scene = random_scene((uint64_t)k + 1);
        cg_camera cam = looking_at(cg_vec3_make(0, 1, 5), cg_vec3_make(0, 0, -1));
        cg_path_options o = cg_path_options_default();
        o.spp = 16;
        o.max_depth = 6;
        o.environment = cg_vec3_make(0.1, 0.1, 0.1);
        double m1, e1, v1, m0, e0, v0;
        seed_statistics(scene, &cam, o, 12, &m1, &e1, &v1);
        o.no_emitter_sampling = 1;
        seed_statistics(scene, &cam, o, 12, &m0, &e0, &v0);
        double z = fabs(m1 - m0) / sqrt(e1 * e1 + e0 * e0 + 1e-30);
        worst_z = z > worst_z ? z : worst_z;
        CHECK_REPORT(z < 4.5, "scene %d: mean %.5f (MIS) vs %.5f (hits only), z %.2f", k, m1, m0,
                     z);
        CHECK_REPORT(v1 < v0, "scene %d: pixel variance %.4g (MIS) vs %.4g", k, v1, v0);
        ratio_product *= v0 / v1;
        cg_trace_scene_free(scene);
    }
    double ratio = pow(ratio_product, 1.0 / scenes);
    CHECK_REPORT(ratio > 2, "variance ratio (geometric mean) %.2f", ratio);
    if (getenv("CG_TEST_VERBOSE"))
        printf("mis: worst z %.2f, variance ratio (geometric mean) %.2f\n", worst_z, ratio);
}

/* An emitter seen directly, and in a perfect mirror, is exactly its
 * radiance: camera and specular rays carry MIS weight 1. */
static void seen_directly(void)
{
    cg_vec3 le = cg_vec3_make(0.25, 0.5, 2);
    cg_trace_material glow = emitter(le), mirror = lambert(0);
    mirror.surface.reflectance = 1;
    for (int view = 0; view < 2; view++) {
        cg_trace_scene *scene = NULL;
        cg_trace_scene_create(&scene);
        add_square(scene, -5, 5, -5, 5, 2, &glow);
        cg_camera cam = looking_at(cg_vec3_make(0, 1, 0), cg_vec3_make(0, 2, 0));
        if (view == 1) {
            cg_trace_scene_add_plane(scene, cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &mirror);
            cam = looking_at(cg_vec3_make(0, 1, 0), cg_vec3_make(0, 0, 0));
        }
        cam.fovy = 0.5;
        cg_path_options o = cg_path_options_default();
        o.spp = 3;
        cg_image *im = render(scene, &cam, &o);
        int exact = im != NULL;
        for (int y = 0; im && y < H; y++)
            for (int x = 0; x < W; x++) {
                cg_rgbaf c = cg_image_get(im, x, y);
                exact &= fabs(c.r - le.x) < 1e-6 && fabs(c.g - le.y) < 1e-6
                         && fabs(c.b - le.z) < 1e-6;
            }
        CHECK_REPORT(exact, "an emitter seen %s is not its emission",
                     view ? "in a mirror" : "directly");
        cg_image_free(im);
        cg_trace_scene_free(scene);
    }
}

/* Inside a closed box mesh emitting E with albedo a, every surface is a
 * sampled emitter: the radiance is E / (1 - a). */
static void closed_box(void)
{
    cg_vec3 v[8];
    for (int i = 0; i < 8; i++)
        v[i] = cg_vec3_make(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    const int f[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                         {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    cg_vec3 p[24];
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 4; j++)
            p[4 * i + j] = v[f[i][j]];
    cg_trace_material room = lambert(0.4);
    room.emission = cg_vec3_make(0.2, 0.2, 0.2);
    cg_trace_scene *scene = NULL;
    cg_trace_scene_create(&scene);
    CHECK(add_faces(scene, p, 6, 4, &room) == CG_OK);
    cg_camera cam = looking_at(cg_vec3_make(0.1, 0.2, 0.3), cg_vec3_make(0.5, -0.3, -1));
    cg_path_options o = cg_path_options_default();
    o.spp = 64;
    o.max_depth = 64;
    cg_image *im = render(scene, &cam, &o);
    double mean = im ? image_mean(im, 0) : -1, want = 0.2 / 0.6;
    CHECK_REPORT(fabs(mean - want) < 0.01 * want, "emitting box mean %.5f, want %.5f", mean, want);
    cg_image_free(im);
    cg_trace_scene_free(scene);
}

/* With emitters, the sums are the same on any thread count and split. */
static void determinism(void)
{
    cg_trace_scene *scene = random_scene(3);
    cg_camera cam = looking_at(cg_vec3_make(0, 1, 5), cg_vec3_make(0, 0, -1));
    cg_path_options o = cg_path_options_default();
    o.spp = 6;
    size_t n = (size_t)W * H * 3;
    uint64_t *ref = calloc(n, 8), *other = calloc(n, 8);
    CHECK(cg_path_render_sums(scene, &cam, W, H, &o, ref) == CG_OK);
    o.threads = 3;
    cg_path_render_sums(scene, &cam, W, H, &o, other);
    CHECK_REPORT(memcmp(ref, other, n * 8) == 0, "3 threads give the same sums");
    memset(other, 0, n * 8);
    o.sample_end = 2;
    cg_path_render_sums(scene, &cam, W, H, &o, other);
    o.sample_begin = 2;
    o.sample_end = 6;
    cg_path_render_sums(scene, &cam, W, H, &o, other);
    CHECK_REPORT(memcmp(ref, other, n * 8) == 0, "sample ranges add up to the whole");
    memset(other, 0, n * 8);
    o.no_emitter_sampling = 1;
    o.sample_begin = o.sample_end = 0;
    cg_path_render_sums(scene, &cam, W, H, &o, other);
    CHECK_REPORT(memcmp(ref, other, n * 8) != 0, "emitter sampling changes the samples");
    free(ref);
    free(other);
    cg_trace_scene_free(scene);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(square_emitter);
    CHECK_GROUP(mis_unbiased);
    CHECK_GROUP(seen_directly);
    CHECK_GROUP(closed_box);
    CHECK_GROUP(determinism);
    return check_finish();
}
