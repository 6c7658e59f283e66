/* Whitted-style ray tracing: local illumination with shadow rays, mirror
 * reflection and refraction, stratified supersampling, tiles on threads. */
#include "internal.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { TILE = 16, MAX_THREADS = 256, MAX_SAMPLES = 65536, MAX_DEPTH = 64 };

/* Contributions smaller than this are not traced further (1/1024 of the
 * pixel: invisible after 8-bit quantization). */
#define MIN_WEIGHT (1.0 / 1024)

cg_trace_options cg_trace_options_default(void)
{
    cg_trace_options o;
    memset(&o, 0, sizeof o);
    o.samples = 1;
    o.max_depth = 5;
    o.threads = 1;
    o.shadows = 1;
    o.normals = CG_TRACE_SMOOTH;
    o.background.a = 1;
    return o;
}

/* ---- deterministic random numbers ---------------------------------------- */

/* A hash of (pixel, sample, dimension) to [0, 1): the same numbers on any
 * thread count because they depend on nothing else. */
static double random_unit(uint64_t a, uint64_t b, uint64_t c)
{
    uint64_t z = a * 0x9e3779b97f4a7c15ULL ^ (b + 0x632be59bd9b4e019ULL) * 0xbf58476d1ce4e5b9ULL
                 ^ (c + 0x94d049bb133111ebULL) * 0xd6e8feb86659fd7dULL;
    z ^= z >> 30;
    z *= 0xbf58476d1ce4e5b9ULL;
    z ^= z >> 27;
    z *= 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

typedef struct sampler {
    uint64_t pixel, sample;
    uint64_t dimension;
} sampler;

static double next_random(sampler *s)
{
    return random_unit(s->pixel, s->sample, s->dimension++);
}

/* ---- shading --------------------------------------------------------------- */

typedef struct context {
    const cg_trace_scene *scene;
    const cg_trace_options *options;
    uint64_t rays;
} context;

static cg_vec3 surface_color(const trace_object *o, cg_vec3 p)
{
    const cg_trace_material *m = &o->material;
    if (!(m->checker_size > 0))
        return m->color;
    double s = m->checker_size;
    long parity;
    if (o->kind == TRACE_PLANE) {
        cg_vec3 d = cg_vec3_sub(p, o->center);
        parity = (long)floor(cg_vec3_dot(d, o->axis_u) / s) + (long)floor(cg_vec3_dot(d, o->axis_v) / s);
    } else {
        parity = (long)floor(p.x / s) + (long)floor(p.y / s) + (long)floor(p.z / s);
    }
    return parity & 1 ? m->checker_color : m->color;
}

/* The local illumination of one light sample: Lambertian diffuse plus a
 * Blinn-Phong highlight.  n, to_viewer and to_light are unit vectors.  This is
 * the one place the illumination model enters the ray tracer. */
static cg_vec3 shade_light(const cg_trace_material *m, cg_vec3 base, cg_vec3 n, cg_vec3 to_viewer,
                           cg_vec3 to_light, cg_vec3 light_color)
{
    double diffuse = cg_vec3_dot(n, to_light);
    if (diffuse <= 0)
        return cg_vec3_make(0, 0, 0);
    cg_vec3 c = cg_vec3_scale(base, m->diffuse * diffuse);
    if (m->specular > 0) {
        cg_vec3 half = cg_vec3_normalize(cg_vec3_add(to_viewer, to_light));
        double h = cg_vec3_dot(n, half);
        if (h > 0) {
            double s = m->specular * pow(h, m->shininess);
            c = cg_vec3_add(c, cg_vec3_make(s, s, s));
        }
    }
    return cg_vec3_mul(c, light_color);
}

static int visible(context *ctx, const trace_hit *hit, cg_vec3 n_geometric, cg_vec3 to_light,
                   double distance)
{
    if (!ctx->options->shadows)
        return 1;
    cg_vec3 origin = trace_offset(hit, n_geometric);
    ctx->rays++;
    return !trace_occluded(ctx->scene, origin, to_light, 0, distance);
}

static cg_vec3 illuminate(context *ctx, const trace_hit *hit, const trace_object *o, cg_vec3 base,
                          cg_vec3 n, cg_vec3 n_geometric, cg_vec3 to_viewer, sampler *rng)
{
    const cg_trace_material *m = &o->material;
    cg_vec3 sum = cg_vec3_scale(base, m->ambient);
    if (m->diffuse == 0 && m->specular == 0)
        return sum;
    for (size_t i = 0; i < ctx->scene->light_count; i++) {
        const cg_trace_light *l = &ctx->scene->lights[i];
        if (l->kind == CG_LIGHT_DIRECTIONAL) {
            if (cg_vec3_dot(n_geometric, l->direction) <= 0 && cg_vec3_dot(n, l->direction) <= 0)
                continue;
            if (visible(ctx, hit, n_geometric, l->direction, INFINITY))
                sum = cg_vec3_add(sum, shade_light(m, base, n, to_viewer, l->direction, l->color));
            continue;
        }
        int side = l->kind == CG_LIGHT_AREA ? l->samples : 1;
        double weight = 1.0 / (side * side);
        for (int sy = 0; sy < side; sy++)
            for (int sx = 0; sx < side; sx++) {
                cg_vec3 target = l->position;
                if (l->kind == CG_LIGHT_AREA) {
                    /* One jittered sample in each cell of a side x side grid. */
                    double a = (sx + next_random(rng)) / side, b = (sy + next_random(rng)) / side;
                    target = cg_vec3_add(target, cg_vec3_add(cg_vec3_scale(l->edge_u, a),
                                                             cg_vec3_scale(l->edge_v, b)));
                }
                cg_vec3 d = cg_vec3_sub(target, hit->point);
                double distance = cg_vec3_length(d);
                if (!(distance > 0))
                    continue;
                d = cg_vec3_scale(d, 1 / distance);
                if (cg_vec3_dot(n_geometric, d) <= 0)
                    continue;
                if (visible(ctx, hit, n_geometric, d, distance))
                    sum = cg_vec3_add(sum, cg_vec3_scale(shade_light(m, base, n, to_viewer, d, l->color),
                                                         weight));
            }
    }
    return sum;
}

/* Radiance along the ray (direction unit); *hit_any set when it hits. */
static cg_vec3 trace(context *ctx, cg_vec3 origin, cg_vec3 direction, int depth, double weight,
                     sampler *rng, int *hit_any)
{
    const cg_trace_options *opt = ctx->options;
    trace_hit hit;
    ctx->rays++;
    if (!trace_intersect(ctx->scene, origin, direction, 0, INFINITY, &hit)) {
        if (hit_any)
            *hit_any = 0;
        return cg_vec3_make(opt->background.r, opt->background.g, opt->background.b);
    }
    if (hit_any)
        *hit_any = 1;
    const trace_object *o = &ctx->scene->objects[hit.object];
    const cg_trace_material *m = &o->material;
    /* Normals facing the incoming ray; entering tells which side we are on. */
    int entering = cg_vec3_dot(hit.normal, direction) < 0;
    cg_vec3 ng = entering ? hit.normal : cg_vec3_scale(hit.normal, -1);
    cg_vec3 n = opt->normals == CG_TRACE_SMOOTH ? hit.smooth_normal : hit.normal;
    if (cg_vec3_dot(n, ng) < 0)
        n = cg_vec3_scale(n, -1);
    cg_vec3 to_viewer = cg_vec3_scale(direction, -1);
    cg_vec3 base = surface_color(o, hit.point);
    cg_vec3 color = illuminate(ctx, &hit, o, base, n, ng, to_viewer, rng);
    if (depth >= opt->max_depth)
        return color;
    cg_vec3 mirror = cg_reflect(direction, n);
    if (cg_vec3_dot(mirror, ng) <= 0)
        mirror = cg_reflect(direction, ng);
    double reflect_weight = m->reflect;
    if (m->transmit > 0) {
        double n1 = entering ? 1 : m->ior, n2 = entering ? m->ior : 1;
        cg_vec3 refracted;
        double cos_i = -cg_vec3_dot(direction, n);
        if (cg_refract(direction, n, n1, n2, &refracted) && cg_vec3_dot(refracted, ng) < 0) {
            double fresnel = cg_fresnel_schlick(cos_i, n1, n2);
            reflect_weight += m->transmit * fresnel;
            double w = m->transmit * (1 - fresnel);
            if (w * weight >= MIN_WEIGHT) {
                cg_vec3 c = trace(ctx, trace_offset(&hit, cg_vec3_scale(ng, -1)), refracted,
                                  depth + 1, weight * w, rng, NULL);
                color = cg_vec3_add(color, cg_vec3_scale(c, w));
            }
        } else {
            reflect_weight += m->transmit; /* total internal reflection */
        }
    }
    if (reflect_weight > 0 && reflect_weight * weight >= MIN_WEIGHT) {
        cg_vec3 c = trace(ctx, trace_offset(&hit, ng), mirror, depth + 1, weight * reflect_weight,
                          rng, NULL);
        color = cg_vec3_add(color, cg_vec3_scale(c, reflect_weight));
    }
    return color;
}

/* ---- the image --------------------------------------------------------- */

typedef struct job {
    const cg_trace_scene *scene;
    const cg_trace_options *options;
    cg_image *image;
    /* Primary rays: origin(x, y) = origin0 + x origin_dx + y origin_dy and
     * direction the same, normalized (both affine in the image point). */
    cg_vec3 origin0, origin_dx, origin_dy, dir0, dir_dx, dir_dy;
    int tiles_x, tiles_total;
    int next_tile, done_tiles;
    pthread_mutex_t lock;
    uint64_t rays;
} job;

static void render_pixel(const job *j, context *ctx, int x, int y)
{
    const cg_trace_options *opt = j->options;
    int n = opt->samples;
    /* Strata: rows of equal height, `cols` cells per full row; the last row
     * holds the remaining samples in wider cells.  Each sample is weighted
     * by its cell's area, so the estimate is unbiased. */
    int cols = (int)ceil(sqrt((double)n));
    int rows = (n + cols - 1) / cols;
    double r = 0, g = 0, b = 0, a = 0;
    uint64_t pixel = (uint64_t)y * (uint64_t)j->image->width + (uint64_t)x;
    for (int k = 0; k < n; k++) {
        int row = k / cols, col = k % cols;
        int in_row = row == rows - 1 ? n - cols * (rows - 1) : cols;
        double sx = 0.5, sy = 0.5;
        sampler rng = {pixel, (uint64_t)k, 0};
        if (n > 1) {
            sx = (col + next_random(&rng)) / in_row;
            sy = (row + next_random(&rng)) / rows;
        }
        double px = x + sx, py = y + sy;
        cg_vec3 origin = cg_vec3_add(j->origin0, cg_vec3_add(cg_vec3_scale(j->origin_dx, px),
                                                             cg_vec3_scale(j->origin_dy, py)));
        cg_vec3 direction = cg_vec3_normalize(cg_vec3_add(
            j->dir0, cg_vec3_add(cg_vec3_scale(j->dir_dx, px), cg_vec3_scale(j->dir_dy, py))));
        int hit = 0;
        cg_vec3 c = trace(ctx, origin, direction, 0, 1, &rng, &hit);
        double w = 1.0 / ((double)rows * in_row);
        r += c.x * w;
        g += c.y * w;
        b += c.z * w;
        a += (hit ? 1.0 : opt->background.a) * w;
    }
    cg_rgbaf out = {(float)r, (float)g, (float)b, (float)a};
    cg_image_set(j->image, x, y, out);
}

static void *worker(void *arg)
{
    job *j = arg;
    context ctx = {j->scene, j->options, 0};
    for (;;) {
        pthread_mutex_lock(&j->lock);
        int tile = j->next_tile++;
        pthread_mutex_unlock(&j->lock);
        if (tile >= j->tiles_total)
            break;
        int x0 = tile % j->tiles_x * TILE, y0 = tile / j->tiles_x * TILE;
        int x1 = x0 + TILE < j->image->width ? x0 + TILE : j->image->width;
        int y1 = y0 + TILE < j->image->height ? y0 + TILE : j->image->height;
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++)
                render_pixel(j, &ctx, x, y);
        pthread_mutex_lock(&j->lock);
        j->done_tiles++;
        if (j->options->progress)
            j->options->progress(j->options->progress_user, j->done_tiles, j->tiles_total);
        pthread_mutex_unlock(&j->lock);
    }
    pthread_mutex_lock(&j->lock);
    j->rays += ctx.rays;
    pthread_mutex_unlock(&j->lock);
    return NULL;
}

/* Primary rays from the shared camera at three image points; both the
 * origin and the direction scaled to unit depth along the viewing axis are
 * affine in the image point, so the rest follow exactly. */
static cg_status setup_camera(job *j, const cg_camera *camera)
{
    int w = j->image->width, h = j->image->height;
    cg_vec3 o[3], d[3], axis, unused;
    cg_status s = cg_camera_ray(camera, w, h, w * 0.5, h * 0.5, &unused, &axis);
    const double px[3] = {0, 1, 0}, py[3] = {0, 0, 1};
    for (int k = 0; k < 3 && s == CG_OK; k++) {
        s = cg_camera_ray(camera, w, h, px[k], py[k], &o[k], &d[k]);
        double along = cg_vec3_dot(d[k], axis);
        if (s == CG_OK && !(along > 0))
            s = CG_EINVAL;
        if (s == CG_OK)
            d[k] = cg_vec3_scale(d[k], 1 / along);
    }
    if (s != CG_OK)
        return s;
    j->origin0 = o[0];
    j->origin_dx = cg_vec3_sub(o[1], o[0]);
    j->origin_dy = cg_vec3_sub(o[2], o[0]);
    j->dir0 = d[0];
    j->dir_dx = cg_vec3_sub(d[1], d[0]);
    j->dir_dy = cg_vec3_sub(d[2], d[0]);
    return CG_OK;
}

static double seconds_since(const struct timespec *a)
{
    struct timespec b;
    clock_gettime(CLOCK_MONOTONIC, &b);
    return (double)(b.tv_sec - a->tv_sec) + (double)(b.tv_nsec - a->tv_nsec) * 1e-9;
}

cg_status cg_trace_render(cg_trace_scene *scene, const cg_camera *camera,
                          const cg_trace_options *options, cg_image *image,
                          cg_trace_stats *stats)
{
    if (!scene || !camera || !image || image->width <= 0 || image->height <= 0)
        return CG_EINVAL;
    cg_trace_options opt = options ? *options : cg_trace_options_default();
    if (opt.samples < 1 || opt.max_depth < 0 || opt.threads < 1)
        return CG_EINVAL;
    if (opt.samples > MAX_SAMPLES || opt.max_depth > MAX_DEPTH || opt.threads > MAX_THREADS)
        return CG_ERANGE;
    if (!isfinite(opt.background.r) || !isfinite(opt.background.g) || !isfinite(opt.background.b)
        || !isfinite(opt.background.a))
        return CG_EINVAL;
    if (stats)
        memset(stats, 0, sizeof *stats);
    double build = 0;
    cg_status s = cg_trace_scene_build(scene, &build);
    if (s != CG_OK)
        return s;
    struct timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    job j;
    memset(&j, 0, sizeof j);
    j.scene = scene;
    j.options = &opt;
    j.image = image;
    if ((s = setup_camera(&j, camera)) != CG_OK)
        return s;
    j.tiles_x = (image->width + TILE - 1) / TILE;
    int tiles_y = (image->height + TILE - 1) / TILE;
    if ((double)j.tiles_x * tiles_y > 0x7fffffff)
        return CG_ERANGE;
    j.tiles_total = j.tiles_x * tiles_y;
    if (pthread_mutex_init(&j.lock, NULL) != 0)
        return CG_ENOMEM;
    int threads = opt.threads < j.tiles_total ? opt.threads : j.tiles_total;
    pthread_t ids[MAX_THREADS];
    int started = 0;
    for (int i = 1; i < threads; i++) {
        if (pthread_create(&ids[started], NULL, worker, &j) != 0)
            break; /* fewer threads: same picture, only slower */
        started++;
    }
    worker(&j);
    for (int i = 0; i < started; i++)
        pthread_join(ids[i], NULL);
    pthread_mutex_destroy(&j.lock);
    if (stats) {
        stats->build_seconds = build;
        stats->render_seconds = seconds_since(&start);
        stats->rays = j.rays;
    }
    return CG_OK;
}

/* ---- the classic scene -------------------------------------------------- */

cg_status cg_trace_scene_classic(cg_trace_scene **out)
{
    cg_trace_scene *scene;
    cg_status s = cg_trace_scene_create(&scene);
    if (s != CG_OK)
        return s;
    cg_trace_material floor = cg_trace_material_default();
    floor.color = cg_vec3_make(0.85, 0.85, 0.8);
    floor.checker_color = cg_vec3_make(0.08, 0.1, 0.25);
    floor.checker_size = 1;
    floor.specular = 0;
    floor.reflect = 0.08;

    cg_trace_material glass = cg_trace_material_default();
    glass.color = cg_vec3_make(1, 1, 1);
    glass.ambient = 0;
    glass.diffuse = 0;
    glass.specular = 0.8;
    glass.shininess = 200;
    glass.transmit = 1;
    glass.ior = 1.5;

    cg_trace_material mirror = cg_trace_material_default();
    mirror.color = cg_vec3_make(0.9, 0.9, 0.95);
    mirror.ambient = 0.02;
    mirror.diffuse = 0.05;
    mirror.specular = 0.8;
    mirror.shininess = 200;
    mirror.reflect = 0.85;

    cg_trace_material red = cg_trace_material_default();
    red.color = cg_vec3_make(0.8, 0.12, 0.08);
    red.specular = 0.4;
    red.shininess = 60;

    cg_trace_light sun;
    memset(&sun, 0, sizeof sun);
    sun.kind = CG_LIGHT_AREA;
    sun.color = cg_vec3_make(0.9, 0.88, 0.8);
    sun.position = cg_vec3_make(-4, 8, 2);
    sun.edge_u = cg_vec3_make(2, 0, 0);
    sun.edge_v = cg_vec3_make(0, 0, 2);
    sun.samples = 3;
    cg_trace_light fill;
    memset(&fill, 0, sizeof fill);
    fill.kind = CG_LIGHT_DIRECTIONAL;
    fill.color = cg_vec3_make(0.2, 0.22, 0.28);
    fill.direction = cg_vec3_make(1, 2, 3);

    if ((s = cg_trace_scene_add_plane(scene, cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &floor))
            != CG_OK
        || (s = cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 1, 0), 1, NULL, &glass)) != CG_OK
        || (s = cg_trace_scene_add_sphere(scene, cg_vec3_make(-2.2, 1, -1.6), 1, NULL, &mirror))
               != CG_OK
        || (s = cg_trace_scene_add_sphere(scene, cg_vec3_make(2.1, 0.7, -1.2), 0.7, NULL, &red))
               != CG_OK
        || (s = cg_trace_scene_add_light(scene, &sun)) != CG_OK
        || (s = cg_trace_scene_add_light(scene, &fill)) != CG_OK) {
        cg_trace_scene_free(scene);
        return s;
    }
    *out = scene;
    return CG_OK;
}
