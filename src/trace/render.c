/* Whitted-style ray tracing: local illumination with shadow rays, mirror
 * reflection and refraction, stratified supersampling, tiles claimed by the
 * workers of the scene's worker pool (trace_scene_pool). */
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
    double *visibility; /* one per scene light */
} context;

cg_vec3 trace_surface_color(const trace_object *o, cg_vec3 p)
{
    const cg_trace_material *m = &o->material;
    if (!(m->checker_size > 0))
        return m->surface.color;
    double s = m->checker_size;
    double parity;
    if (o->kind == TRACE_PLANE) {
        /* In the plane's own axes, so a floor is not speckled by rounding of
         * its height. */
        cg_vec3 d = cg_vec3_sub(p, o->center);
        parity = floor(cg_vec3_dot(d, o->axis_u) / s) + floor(cg_vec3_dot(d, o->axis_v) / s);
    } else {
        parity = floor(p.x / s) + floor(p.y / s) + floor(p.z / s);
    }
    return fmod(fabs(parity), 2) == 1 ? m->checker_color : m->surface.color;
}

/* Is the light at distance along the unit vector to_light unobstructed? */
static int visible(context *ctx, const trace_hit *hit, cg_vec3 n_geometric, cg_vec3 to_light,
                   double distance)
{
    if (!ctx->options->shadows)
        return 1;
    cg_vec3 origin = trace_offset(hit, n_geometric);
    ctx->rays++;
    return !trace_occluded(ctx->scene, origin, to_light, 0, distance);
}

/* Local illumination at the hit through the shared model of cg/light.h,
 * with each light's visibility found by a shadow ray; area lights are
 * sampled as point lights on a jittered grid. */
static cg_vec3 illuminate(context *ctx, const trace_hit *hit, const cg_material *material,
                          cg_vec3 n, cg_vec3 n_geometric, cg_vec3 to_viewer, sampler *rng)
{
    const cg_trace_scene *scene = ctx->scene;
    int lit = material->kd > 0 || material->ks > 0;
    for (size_t i = 0; i < scene->light_count; i++) {
        const cg_light *l = &scene->lights[i];
        cg_vec3 to_light;
        double distance;
        if (l->kind == CG_LIGHT_AMBIENT) {
            ctx->visibility[i] = 1;
        } else if (!lit || !cg_light_vector(l, hit->point, &to_light, &distance)
                   || cg_vec3_dot(n_geometric, to_light) <= 0 || cg_vec3_dot(n, to_light) <= 0) {
            ctx->visibility[i] = 0;
        } else {
            ctx->visibility[i] = visible(ctx, hit, n_geometric, to_light, distance);
        }
    }
    cg_vec3 sum = cg_shade_terms_sum(cg_light_shade_terms(
        hit->point, n, to_viewer, material, scene->lights, scene->light_count, ctx->visibility));
    for (size_t i = 0; lit && i < scene->area_light_count; i++) {
        const cg_trace_area_light *l = &scene->area_lights[i];
        int side = l->samples;
        cg_vec3 color = cg_vec3_scale(l->color, 1.0 / (side * side));
        for (int sy = 0; sy < side; sy++)
            for (int sx = 0; sx < side; sx++) {
                /* One jittered sample in each cell of a side x side grid. */
                double a = (sx + next_random(rng)) / side, b = (sy + next_random(rng)) / side;
                cg_vec3 target = cg_vec3_add(l->corner, cg_vec3_add(cg_vec3_scale(l->edge_u, a),
                                                                    cg_vec3_scale(l->edge_v, b)));
                cg_light point = cg_light_point(target, color);
                cg_vec3 to_light;
                double distance;
                if (!cg_light_vector(&point, hit->point, &to_light, &distance)
                    || cg_vec3_dot(n_geometric, to_light) <= 0 || cg_vec3_dot(n, to_light) <= 0)
                    continue;
                if (visible(ctx, hit, n_geometric, to_light, distance))
                    sum = cg_vec3_add(
                        sum, cg_light_shade(hit->point, n, to_viewer, material, &point, 1));
            }
    }
    return sum;
}

/* Radiance along the ray (direction unit) between t_min and t_max (the
 * camera's near and far for a primary ray); *hit_any set when it hits. */
static cg_vec3 trace(context *ctx, cg_vec3 origin, cg_vec3 direction, double t_min, double t_max,
                     int depth, double weight, sampler *rng, int *hit_any)
{
    const cg_trace_options *opt = ctx->options;
    trace_hit hit;
    ctx->rays++;
    if (!trace_intersect(ctx->scene, origin, direction, t_min, t_max, &hit)) {
        if (hit_any)
            *hit_any = 0;
        return cg_vec3_make(opt->background.r, opt->background.g, opt->background.b);
    }
    if (hit_any)
        *hit_any = 1;
    const trace_object *o = &ctx->scene->objects[hit.object];
    cg_material material = o->material.surface;
    /* Normals facing the incoming ray; entering tells which side we are on. */
    int entering = cg_vec3_dot(hit.normal, direction) < 0;
    cg_vec3 ng = entering ? hit.normal : cg_vec3_scale(hit.normal, -1);
    cg_vec3 n = opt->normals == CG_TRACE_SMOOTH ? hit.smooth_normal : hit.normal;
    if (cg_vec3_dot(n, ng) < 0)
        n = cg_vec3_scale(n, -1);
    cg_vec3 to_viewer = cg_vec3_scale(direction, -1);
    material.color = trace_surface_color(o, hit.point);
    cg_vec3 color = cg_vec3_add(o->material.emission,
                                illuminate(ctx, &hit, &material, n, ng, to_viewer, rng));
    if (depth >= opt->max_depth)
        return color;
    cg_vec3 mirror = cg_reflect(direction, n);
    if (cg_vec3_dot(mirror, ng) <= 0)
        mirror = cg_reflect(direction, ng);
    double reflect_weight = material.reflectance, transmit = material.transmittance;
    if (transmit > 0) {
        /* Refractive index 0 means 1 (cg/light.h): no bending. */
        double ior = material.refractive_index > 0 ? material.refractive_index : 1;
        double n1 = entering ? 1 : ior, n2 = entering ? ior : 1;
        cg_vec3 refracted;
        double cos_i = -cg_vec3_dot(direction, n);
        if (cg_refract(direction, n, n1, n2, &refracted) && cg_vec3_dot(refracted, ng) < 0) {
            double fresnel = cg_fresnel_schlick(cos_i, n1, n2);
            reflect_weight += transmit * fresnel;
            double w = transmit * (1 - fresnel);
            if (w * weight >= MIN_WEIGHT) {
                cg_vec3 c = trace(ctx, trace_offset(&hit, cg_vec3_scale(ng, -1)), refracted, 0,
                                  INFINITY, depth + 1, weight * w, rng, NULL);
                color = cg_vec3_add(color, cg_vec3_scale(c, w));
            }
        } else {
            reflect_weight += transmit; /* total internal reflection */
        }
    }
    if (reflect_weight > 0 && reflect_weight * weight >= MIN_WEIGHT) {
        cg_vec3 c = trace(ctx, trace_offset(&hit, ng), mirror, 0, INFINITY, depth + 1,
                          weight * reflect_weight, rng, NULL);
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
    /* The depths along the viewing axis between which a primary ray sees,
     * from its origin: near to far from the eye, 0 to far - near from a
     * parallel camera's near plane.  The unnormalized direction advances
     * one unit of depth per unit, so t = depth * its length. */
    double depth_from, depth_to;
    int tiles_x, tiles_total;
    core_worker_pool *pool;
    core_worker_phase tiles;
    uint64_t *rays;     /* per worker */
    double *visibility; /* light_count per worker */
    /* Progress: the tiles done, counted and reported one call at a time. */
    pthread_mutex_t progress_lock;
    int done_tiles;
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
        cg_vec3 step = cg_vec3_add(
            j->dir0, cg_vec3_add(cg_vec3_scale(j->dir_dx, px), cg_vec3_scale(j->dir_dy, py)));
        double length = cg_vec3_length(step);
        cg_vec3 direction = cg_vec3_normalize(step);
        int hit = 0;
        cg_vec3 c = trace(ctx, origin, direction, j->depth_from * length, j->depth_to * length, 0,
                          1, &rng, &hit);
        double w = 1.0 / ((double)rows * in_row);
        r += c.x * w;
        g += c.y * w;
        b += c.z * w;
        a += (hit ? 1.0 : opt->background.a) * w;
    }
    cg_rgbaf out = {(float)r, (float)g, (float)b, (float)a};
    cg_image_set(j->image, x, y, out);
}

/* The tiles a worker claims, pixel by pixel; the rays it traced. */
static void render_tiles(void *job_context, int worker)
{
    job *j = job_context;
    context ctx = {j->scene, j->options, 0, j->visibility + (size_t)worker * j->scene->light_count};
    size_t claimed;
    while (core_worker_pool_claim(&j->tiles, &claimed)) {
        int tile = (int)claimed;
        int x0 = tile % j->tiles_x * TILE, y0 = tile / j->tiles_x * TILE;
        int x1 = x0 + TILE < j->image->width ? x0 + TILE : j->image->width;
        int y1 = y0 + TILE < j->image->height ? y0 + TILE : j->image->height;
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++)
                render_pixel(j, &ctx, x, y);
        core_worker_pool_finish(j->pool, &j->tiles);
        if (j->options->progress) {
            pthread_mutex_lock(&j->progress_lock);
            j->done_tiles++;
            j->options->progress(j->options->progress_user, j->done_tiles, j->tiles_total);
            pthread_mutex_unlock(&j->progress_lock);
        }
    }
    j->rays[worker] = ctx.rays;
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
    j->depth_from = 0;
    j->depth_to = INFINITY;
    if (j->options->clip_depth) {
        j->depth_from = camera->orthographic ? 0 : camera->near;
        j->depth_to = camera->orthographic ? camera->far - camera->near : camera->far;
        if (!(j->depth_to > j->depth_from) || !(j->depth_from >= 0) || isnan(j->depth_to))
            return CG_EINVAL;
    }
    return CG_OK;
}

static double seconds_since(const struct timespec *a)
{
    struct timespec b;
    clock_gettime(CLOCK_MONOTONIC, &b);
    return (double)(b.tv_sec - a->tv_sec) + (double)(b.tv_nsec - a->tv_nsec) * 1e-9;
}

cg_status cg_trace_render(cg_trace_scene *scene, const cg_camera *camera,
                          const cg_trace_options *options, cg_image *image, cg_trace_stats *stats)
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
    cg_status s = cg_trace_scene_build(scene, opt.threads, &build);
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
    j.pool = trace_scene_pool(scene, opt.threads);
    int workers = core_worker_pool_workers(j.pool);
    core_worker_pool_phase_init(&j.tiles, (size_t)j.tiles_total);
    j.rays = calloc((size_t)workers, sizeof *j.rays);
    j.visibility = malloc(((size_t)workers * scene->light_count + 1) * sizeof *j.visibility);
    if (!j.rays || !j.visibility || pthread_mutex_init(&j.progress_lock, NULL) != 0) {
        free(j.rays);
        free(j.visibility);
        return CG_ENOMEM;
    }
    core_worker_pool_run(j.pool, render_tiles, &j);
    pthread_mutex_destroy(&j.progress_lock);
    uint64_t rays = 0;
    for (int i = 0; i < workers; i++)
        rays += j.rays[i];
    free(j.rays);
    free(j.visibility);
    if (stats) {
        stats->build_seconds = build;
        stats->render_seconds = seconds_since(&start);
        stats->rays = rays;
    }
    return CG_OK;
}

/* ---- the classic scene -------------------------------------------------- */

cg_status cg_trace_scene_classic(cg_trace_scene **out)
{
    if (!out)
        return CG_EINVAL;
    cg_trace_scene *scene;
    cg_status s = cg_trace_scene_create(&scene);
    if (s != CG_OK)
        return s;
    cg_trace_material floor = cg_trace_material_default();
    floor.surface.color = cg_vec3_make(0.85, 0.85, 0.8);
    floor.surface.ks = 0;
    floor.surface.reflectance = 0.08;
    floor.checker_color = cg_vec3_make(0.08, 0.1, 0.25);
    floor.checker_size = 1;

    cg_trace_material glass = cg_trace_material_default();
    glass.surface.ka = 0;
    glass.surface.kd = 0;
    glass.surface.ks = 0.8;
    glass.surface.shininess = 200;
    glass.surface.transmittance = 1;
    glass.surface.refractive_index = 1.5;

    cg_trace_material mirror = cg_trace_material_default();
    mirror.surface.color = cg_vec3_make(0.9, 0.9, 0.95);
    mirror.surface.ka = 0.2;
    mirror.surface.kd = 0.05;
    mirror.surface.ks = 0.8;
    mirror.surface.shininess = 200;
    mirror.surface.reflectance = 0.85;

    cg_trace_material red = cg_trace_material_default();
    red.surface.color = cg_vec3_make(0.8, 0.12, 0.08);
    red.surface.ks = 0.4;
    red.surface.shininess = 60;

    cg_trace_area_light sun;
    sun.corner = cg_vec3_make(-5, 8, 1);
    sun.edge_u = cg_vec3_make(2, 0, 0);
    sun.edge_v = cg_vec3_make(0, 0, 2);
    sun.color = cg_vec3_make(1.0, 0.97, 0.9);
    sun.samples = 3;
    cg_light ambient = cg_light_ambient(cg_vec3_make(0.1, 0.1, 0.12));
    cg_light fill = cg_light_directional(cg_vec3_make(-1, -2, -3), cg_vec3_make(0.2, 0.22, 0.28));

    if ((s = cg_trace_scene_add_plane(scene, cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &floor))
            != CG_OK
        || (s = cg_trace_scene_add_sphere(scene, cg_vec3_make(0, 1, 0), 1, NULL, &glass)) != CG_OK
        || (s = cg_trace_scene_add_sphere(scene, cg_vec3_make(-2.2, 1, -1.6), 1, NULL, &mirror))
               != CG_OK
        || (s = cg_trace_scene_add_sphere(scene, cg_vec3_make(2.1, 0.7, -1.2), 0.7, NULL, &red))
               != CG_OK
        || (s = cg_trace_scene_add_area_light(scene, &sun)) != CG_OK
        || (s = cg_trace_scene_add_light(scene, &ambient)) != CG_OK
        || (s = cg_trace_scene_add_light(scene, &fill)) != CG_OK) {
        cg_trace_scene_free(scene);
        return s;
    }
    *out = scene;
    return CG_OK;
}
