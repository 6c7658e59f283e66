/* `cg render --algorithm raytrace` (and its alias `cg trace-render`): the
 * ray tracer behind the hook of raytracer.h.  The mesh is lit as the rasterizer
 * lights it (cg_render_options: white ambient light times --ambient, kd 1,
 * Blinn-Phong --specular and --shininess, the --light-dir lights or the key
 * light from the camera's upper left), so both renderers give the same
 * picture apart from shadows and the ray tracer's reflections. */
#include "raytracer.h"

#include "cli.h"
#include "raytrace_run.h"
#include "cg/light.h"
#include "cg/trace.h"

#include <stdlib.h>
#include <string.h>

struct render_raytracer {
    cg_trace_scene *scene;
    cg_camera camera;
    int frame_camera;
    cg_trace_options options;
    void (*progress)(void *user, double fraction);
    void *progress_user;
    double build_seconds;
    cg_trace_stats stats;
};

void raytrace_extra_default(raytrace_extra *extra)
{
    memset(extra, 0, sizeof *extra);
    extra->samples = 1;
    extra->depth = 5;
    extra->shadows = 1;
}

static cg_vec3 rgb(cg_rgbaf c)
{
    return cg_vec3_make(c.r, c.g, c.b);
}

/* A checkered floor under the scene's bounding box, cells a third of its
 * size, slightly reflective. */
static void add_floor(cg_trace_scene *scene)
{
    cg_vec3 lo, hi;
    if (cg_trace_scene_bounds(scene, &lo, &hi) != CG_OK)
        return;
    double size = fmax(hi.x - lo.x, fmax(hi.y - lo.y, hi.z - lo.z));
    cg_trace_material m = cg_trace_material_default();
    m.surface = cg_material_make(cg_vec3_make(0.8, 0.8, 0.78), 1, 0.9, 0, 1);
    m.surface.reflectance = 0.05;
    m.checker_color = cg_vec3_make(0.3, 0.32, 0.36);
    m.checker_size = size > 0 ? size / 3 : 1;
    cg_trace_scene_add_plane(scene, lo, cg_vec3_make(0, 1, 0), &m);
}

/* The options' directional lights, or (default_light, none given) the
 * rasterizer's key light (cg_render_key_light). */
static void add_lights(cg_trace_scene *scene, const cg_render_options *o, int default_light)
{
    for (int i = 0; i < o->light_count; i++) {
        double k = o->lights[i].intensity;
        cg_light l = cg_light_directional(cg_vec3_scale(o->lights[i].direction, -1),
                                          cg_vec3_make(k, k, k));
        cg_trace_scene_add_light(scene, &l);
    }
    cg_mat4 view;
    if (o->light_count || !default_light || cg_camera_view(&o->camera, &view) != CG_OK)
        return;
    cg_light key = cg_render_key_light(view);
    cg_trace_scene_add_light(scene, &key);
}

static void tile_progress(void *user, int done, int total)
{
    render_raytracer *t = user;
    t->progress(t->progress_user, (double)done / total);
}

int render_raytrace_create_extra(const cg_mesh *mesh, const cg_render_options *o,
                                 const raytrace_extra *extra, render_raytracer **out)
{
    *out = NULL;
    render_raytracer *t = calloc(1, sizeof *t);
    if (!t)
        return cli_fail("render: out of memory");
    cg_status st;
    if (extra->classic_scene) {
        st = cg_trace_scene_classic(&t->scene);
    } else if ((st = cg_trace_scene_create(&t->scene)) == CG_OK) {
        cg_trace_material m = cg_trace_material_default();
        m.surface = cg_material_make(rgb(o->color), o->ambient, 1, o->specular, o->shininess);
        m.surface.specular = CG_SPECULAR_BLINN;
        cg_light ambient = cg_light_ambient(cg_vec3_make(1, 1, 1));
        if ((st = cg_trace_scene_add_mesh(t->scene, mesh, &o->model, o->crease_angle, &m)) == CG_OK)
            st = cg_trace_scene_add_light(t->scene, &ambient);
    }
    if (st != CG_OK) {
        render_raytrace_free(t);
        return cli_fail("render: the ray tracer cannot take this mesh: %s", cg_status_str(st));
    }
    if (extra->floor && !extra->classic_scene)
        add_floor(t->scene);
    add_lights(t->scene, o, !extra->classic_scene);
    t->camera = o->camera;
    t->frame_camera = o->frame_camera;
    t->options = cg_trace_options_default();
    t->options.clip_depth = 1; /* --near and --far mean what they do for the rasterizer */
    t->options.samples = extra->samples;
    t->options.max_depth = extra->depth;
    t->options.shadows = extra->shadows;
    t->options.threads = o->threads;
    t->options.normals = o->shading == CG_SHADING_FLAT ? CG_TRACE_FLAT : CG_TRACE_SMOOTH;
    t->options.background = o->background;
    if (o->progress) {
        t->progress = o->progress;
        t->progress_user = o->progress_user;
        t->options.progress = tile_progress;
        t->options.progress_user = t;
    }
    if ((st = cg_trace_scene_build(t->scene, o->threads, &t->build_seconds)) != CG_OK) {
        render_raytrace_free(t);
        return cli_fail("render: building the BVH: %s", cg_status_str(st));
    }
    *out = t;
    return CLI_OK;
}

int render_raytrace_draw(render_raytracer *tracer, cg_image *image)
{
    if (tracer->frame_camera) {
        cg_vec3 lo, hi;
        if (cg_trace_scene_bounds(tracer->scene, &lo, &hi) == CG_OK)
            cg_camera_frame(&tracer->camera, lo, hi, (double)image->width / image->height);
        tracer->frame_camera = 0;
    }
    cg_status st = cg_trace_render(tracer->scene, &tracer->camera, &tracer->options, image,
                                   &tracer->stats);
    if (st != CG_OK)
        return cli_fail("render: ray tracing: %s", cg_status_str(st));
    return CLI_OK;
}

void render_raytrace_stats(const render_raytracer *tracer, double *build_seconds,
                           unsigned long long *rays, double *render_seconds)
{
    *build_seconds = tracer->build_seconds;
    *rays = (unsigned long long)tracer->stats.rays;
    *render_seconds = tracer->stats.render_seconds;
}

void render_raytrace_free(render_raytracer *tracer)
{
    if (!tracer)
        return;
    cg_trace_scene_free(tracer->scene);
    free(tracer);
}
