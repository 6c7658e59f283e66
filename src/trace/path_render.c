/* The path tracer's driver: rows of the tile claimed by the workers of the
 * scene's pool, fixed-point sums per pixel, and their resolution. */
#include "path_internal.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_THREADS = 256, MAX_DEPTH = 256, MAX_SPP = 1 << 24 };

cg_path_options cg_path_options_default(void)
{
    cg_path_options o;
    memset(&o, 0, sizeof o);
    o.spp = 16;
    o.max_depth = 8;
    o.threads = 1;
    o.environment_intensity = 1;
    return o;
}

typedef struct path_job {
    const cg_trace_scene *scene;
    const cg_camera *camera;
    const cg_path_options *options;
    const path_lights *lights;
    int width, height, x0, y0, x1, y1, begin, end;
    uint64_t *sums;
    core_worker_pool *pool;
    core_worker_phase rows;
    pthread_mutex_t lock;
    int done;
} path_job;

static uint64_t fixed(double v)
{
    if (!(v > 0))
        return 0; /* negative, zero and NaN */
    if (v > CG_PATH_MAX_RADIANCE)
        v = CG_PATH_MAX_RADIANCE;
    return (uint64_t)llround(v * CG_PATH_FIXED_ONE);
}

static void render_pixel(path_job *j, int x, int y, uint64_t *out)
{
    for (int k = j->begin; k < j->end; k++) {
        path_sampler rng = {j->options->seed, (uint64_t)y * (uint64_t)j->width + (uint64_t)x,
                            (uint64_t)k, 0};
        double dx, dy;
        path_pixel_offset(&rng, &dx, &dy);
        cg_vec3 o, d;
        if (cg_camera_ray(j->camera, j->width, j->height, x + dx, y + dy, &o, &d) != CG_OK)
            continue;
        cg_vec3 c = path_radiance(j->scene, j->lights, j->options, o, cg_vec3_normalize(d), &rng);
        out[0] += fixed(c.x);
        out[1] += fixed(c.y);
        out[2] += fixed(c.z);
    }
}

static void render_rows(void *context, int worker)
{
    (void)worker;
    path_job *j = context;
    size_t row;
    int w = j->x1 - j->x0, total = j->y1 - j->y0;
    while (core_worker_pool_claim(&j->rows, &row)) {
        uint64_t *line = j->sums + row * (size_t)w * 3;
        for (int i = 0; i < w; i++)
            render_pixel(j, j->x0 + i, j->y0 + (int)row, line + (size_t)i * 3);
        core_worker_pool_finish(j->pool, &j->rows);
        if (j->options->progress) {
            pthread_mutex_lock(&j->lock);
            j->done++;
            j->options->progress(j->options->progress_user, j->done, total);
            pthread_mutex_unlock(&j->lock);
        }
    }
}

/* A tile of all zeros stands for the whole image. */
static int whole_image(const cg_path_options *o)
{
    return !o->x0 && !o->y0 && !o->x1 && !o->y1;
}

static cg_status check_options(const cg_path_options *o, int width, int height)
{
    if (width <= 0 || height <= 0 || o->spp < 1 || o->max_depth < 1 || o->threads < 1)
        return CG_EINVAL;
    if (o->spp > MAX_SPP || o->max_depth > MAX_DEPTH || o->threads > MAX_THREADS)
        return CG_ERANGE;
    int end = o->sample_end ? o->sample_end : o->spp;
    if (o->sample_begin < 0 || end <= o->sample_begin || end > o->spp)
        return CG_EINVAL;
    cg_vec3 e = o->environment;
    if (!(e.x >= 0 && e.y >= 0 && e.z >= 0) || !isfinite(e.x + e.y + e.z))
        return CG_EINVAL;
    const cg_image *map = o->environment_map;
    if (map && (map->format != CG_PIXEL_RGBAF || map->width < 1 || map->height < 1))
        return CG_EINVAL;
    if (!(o->environment_intensity >= 0) || !isfinite(o->environment_intensity))
        return CG_EINVAL;
    if (!whole_image(o)
        && (o->x0 < 0 || o->y0 < 0 || o->x1 <= o->x0 || o->y1 <= o->y0 || o->x1 > width
            || o->y1 > height))
        return CG_EINVAL;
    return CG_OK;
}

cg_status cg_path_render_sums(cg_trace_scene *scene, const cg_camera *camera, int width, int height,
                              const cg_path_options *options, uint64_t *sums)
{
    if (!scene || !camera || !options || !sums)
        return CG_EINVAL;
    cg_status s = check_options(options, width, height);
    if (s != CG_OK)
        return s;
    if ((s = cg_trace_scene_build(scene, options->threads, NULL)) != CG_OK)
        return s;
    path_job j;
    memset(&j, 0, sizeof j);
    j.scene = scene;
    j.camera = camera;
    j.options = options;
    j.width = width;
    j.height = height;
    int whole = whole_image(options);
    j.x0 = whole ? 0 : options->x0;
    j.y0 = whole ? 0 : options->y0;
    j.x1 = whole ? width : options->x1;
    j.y1 = whole ? height : options->y1;
    j.begin = options->sample_begin;
    j.end = options->sample_end ? options->sample_end : options->spp;
    j.sums = sums;
    cg_vec3 o, d;
    if ((s = cg_camera_ray(camera, width, height, 0.5, 0.5, &o, &d)) != CG_OK)
        return s;
    path_lights lights = {0};
    if (!options->no_emitter_sampling && (s = path_lights_build(scene, &lights)) != CG_OK)
        return s;
    j.lights = &lights;
    if (pthread_mutex_init(&j.lock, NULL) != 0) {
        path_lights_free(&lights);
        return CG_ENOMEM;
    }
    j.pool = trace_scene_pool(scene, options->threads);
    core_worker_pool_phase_init(&j.rows, (size_t)(j.y1 - j.y0));
    core_worker_pool_run(j.pool, render_rows, &j);
    pthread_mutex_destroy(&j.lock);
    path_lights_free(&lights);
    return CG_OK;
}

cg_status cg_path_resolve(const uint64_t *sums, int w, int h, uint64_t samples, cg_image *image,
                          int x0, int y0)
{
    if (!sums || !image || w <= 0 || h <= 0 || samples == 0 || x0 < 0 || y0 < 0
        || x0 + (long)w > image->width || y0 + (long)h > image->height)
        return CG_EINVAL;
    double scale = 1.0 / ((double)samples * CG_PATH_FIXED_ONE);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const uint64_t *p = sums + ((size_t)y * (size_t)w + (size_t)x) * 3;
            cg_rgbaf c = {(float)((double)p[0] * scale), (float)((double)p[1] * scale),
                          (float)((double)p[2] * scale), 1};
            cg_image_set(image, x0 + x, y0 + y, c);
        }
    return CG_OK;
}

cg_status cg_path_render(cg_trace_scene *scene, const cg_camera *camera,
                         const cg_path_options *options, cg_image *image)
{
    if (!options || !image)
        return CG_EINVAL;
    cg_path_options o = *options;
    o.sample_begin = 0;
    o.sample_end = 0;
    o.x0 = o.y0 = o.x1 = o.y1 = 0;
    size_t n = (size_t)image->width * (size_t)image->height * 3;
    if (image->width <= 0 || image->height <= 0)
        return CG_EINVAL;
    uint64_t *sums = calloc(n, sizeof *sums);
    if (!sums)
        return CG_ENOMEM;
    cg_status s = cg_path_render_sums(scene, camera, image->width, image->height, &o, sums);
    if (s == CG_OK)
        s = cg_path_resolve(sums, image->width, image->height, (uint64_t)o.spp, image, 0, 0);
    free(sums);
    return s;
}
