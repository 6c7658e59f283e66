/* `cg trace` for chapter 5's visible-surface algorithms that draw a whole
 * picture: the painter's algorithm (the renderer's own run, reported by
 * cg_painter_steps) and a pixel's ray tree (cg_ray_tree_steps). */
#include "trace_algorithms.h"

#include "cli.h"
#include "cg/render.h"
#include "cg/trace.h"
#include "cg/trace_steps.h"

#include <stdio.h>
#include <string.h>

enum { PAINTER_WIDTH = 160, PAINTER_HEIGHT = 120, PAINTER_MAX_TRIANGLES = 4096 };

static size_t count_phase(const cg_step_log *log, const char *phase)
{
    size_t n = 0;
    for (size_t i = 0; i < cg_step_log_count(log); i++) {
        const cg_step *s = cg_step_log_get(log, i);
        n += s->phase && strcmp(s->phase, phase) == 0;
    }
    return n;
}

/* The painter's frame of the mesh, as cg render --algorithm painter draws it
 * (flat shading, no culling: the painter's algorithm alone decides what is
 * seen), with its steps in run->log and the picture as run's background. */
static cg_status painter_frame(const cg_mesh *mesh, cg_mat4 model, const cg_camera *camera,
                               trace_run *run, cg_render_stats *stats, cg_error *err)
{
    cg_render_options o;
    cg_render_options_default(&o);
    o.camera = *camera;
    o.frame_camera = 0;
    o.model = model;
    o.algorithm = CG_RENDER_PAINTER;
    o.shading = CG_SHADING_FLAT;
    o.cull = CG_CULL_NONE;
    o.background = (cg_rgbaf){1, 1, 1, 1};
    cg_renderer *renderer;
    cg_status status = cg_renderer_create(mesh, &o, &renderer, err);
    if (status != CG_OK)
        return status;
    status = cg_image_create(&run->background, PAINTER_WIDTH, PAINTER_HEIGHT, CG_PIXEL_RGBA8);
    if (status == CG_OK)
        status = cg_painter_steps(renderer, run->background, cg_step_log_record, run->log);
    *stats = cg_renderer_stats(renderer);
    cg_renderer_free(renderer);
    return status;
}

/* painter MESH [ABOUT_Y [ABOUT_X]] */
static int run_painter(int argc, char **argv, const trace_outputs *out)
{
    double about_y, about_x;
    cg_mesh *mesh;
    cg_mat4 model;
    cg_camera camera;
    int turned = trace_turned_mesh(argc, argv, (double)PAINTER_WIDTH / PAINTER_HEIGHT, &about_y,
                                   &about_x, &mesh, &model, &camera);
    if (turned != CLI_OK)
        return turned;
    if (cg_mesh_triangle_count(mesh) > PAINTER_MAX_TRIANGLES) {
        cg_mesh_free(mesh);
        return cli_usage_error("trace",
                               "painter: %s has more than %d triangles; trace a smaller "
                               "mesh",
                               argv[1], PAINTER_MAX_TRIANGLES);
    }
    trace_run *run = trace_run_create("painter", argc - 1, argv + 1,
                                      "The painter's algorithm on %s turned %g degrees about y "
                                      "and %g about x, a %dx%d frame",
                                      argv[1], about_y, about_x, PAINTER_WIDTH, PAINTER_HEIGHT);
    if (!run) {
        cg_mesh_free(mesh);
        return cli_fail("trace: out of memory");
    }
    trace_note(run, "polygons: the triangles in window coordinates (x, y in pixels, y down; "
                    "depth z in [0, 1], larger is farther); flat shading, no culling");
    trace_note(run, "sorted by z_max, farthest first; before the list's head P is painted, each "
                    "Q whose depth range reaches P's is tested, up to the first test that passes:");
    trace_note(run,
               "1 x extents apart, 2 y extents apart, 3 P wholly behind Q's plane, 4 Q "
               "wholly in front of P's plane, 5 the projections apart (an edge separates them)");
    trace_note(run, "all five fail: Q moves in front of P (swap) unless it was moved before, then "
                    "one is split by the other's plane; '-' marks a test not reached");
    trace_note(run,
               "the frames show the painter's final picture faded, the polygons looked at "
               "in red (a test's P and Q joined at their first vertices), those painted in grey");
    cg_render_stats stats;
    cg_error err = {0};
    cg_status status = painter_frame(mesh, model, &camera, run, &stats, &err);
    cg_mesh_free(mesh);
    if (status == CG_EFORMAT) {
        trace_run_free(run);
        return cli_fail("trace: %s: %s", argv[1], err.message);
    }
    trace_summary(run, "%zu polygons painted (%zu triangles, splits: %zu), %zu pair tests",
                  count_phase(run->log, "paint"), stats.triangles, stats.splits,
                  count_phase(run->log, "tests"));
    return trace_finish(run, status, "the mesh cannot be drawn", out);
}

/* The scene of `ray`: the classic spheres seen as the docs' example sees
 * them, or the mesh turned and framed as `painter` frames it, a little
 * mirror-like, under the renderer's key light. */
static int ray_scene(const char *what, double aspect, cg_trace_scene **scene, cg_camera *camera)
{
    if (strcmp(what, "spheres") == 0) {
        if (cg_trace_scene_classic(scene) != CG_OK)
            return cli_fail("trace: out of memory");
        *camera = cg_camera_default();
        camera->eye = cg_vec3_make(0, 2.4, 7.5);
        return CLI_OK;
    }
    cg_mesh *mesh;
    cg_mat4 model, view;
    if (trace_frame_mesh(what, 30, 20, aspect, &mesh, &model, camera) != CLI_OK)
        return CLI_FAILED;
    cg_trace_material material = cg_trace_material_default();
    material.surface = cg_material_make(cg_vec3_make(0.8, 0.5, 0.3), 0.2, 0.7, 0.4, 32);
    material.surface.reflectance = 0.3;
    cg_light ambient = cg_light_ambient(cg_vec3_make(0.3, 0.3, 0.3));
    cg_status status = cg_trace_scene_create(scene);
    if (status == CG_OK)
        status = cg_trace_scene_add_mesh(*scene, mesh, &model, 1.0, &material);
    if (status == CG_OK && cg_camera_view(camera, &view) == CG_OK) {
        cg_light key = cg_render_key_light(view);
        status = cg_trace_scene_add_light(*scene, &key);
    }
    if (status == CG_OK)
        status = cg_trace_scene_add_light(*scene, &ambient);
    cg_mesh_free(mesh);
    if (status != CG_OK) {
        cg_trace_scene_free(*scene);
        return cli_fail("trace: %s: %s", what, cg_status_str(status));
    }
    return CLI_OK;
}

/* ray spheres|MESH X Y [WxH] */
static int run_ray(int argc, char **argv, const trace_outputs *out)
{
    long x, y;
    int width = PAINTER_WIDTH, height = PAINTER_HEIGHT;
    if (argc < 4 || argc > 5)
        return cli_usage_error("trace", "ray: expected 'ray spheres|MESH X Y [WxH]'");
    if ((argc > 4 && cli_parse_size("trace", "WxH", argv[4], &width, &height))
        || trace_parse_int("X", argv[2], 0, width - 1, &x)
        || trace_parse_int("Y", argv[3], 0, height - 1, &y))
        return CLI_USAGE;
    cg_trace_scene *scene;
    cg_camera camera;
    if (ray_scene(argv[1], (double)width / height, &scene, &camera) != CLI_OK)
        return CLI_FAILED;
    trace_run *run = trace_run_create("ray", argc - 1, argv + 1,
                                      "The ray tree of pixel (%ld, %ld) of a %dx%d frame of %s", x,
                                      y, width, height, argv[1]);
    if (!run) {
        cg_trace_scene_free(scene);
        return cli_fail("trace: out of memory");
    }
    run->y_up = 1;
    trace_note(run, "a primary ray through the pixel's centre; at each hit the local light "
                    "(ambient, diffuse, specular) with one shadow ray per light, then");
    trace_note(run, "a reflected ray of weight kr and, through glass, a refracted one of weight "
                    "kt: Schlick's Fresnel F moves kt F of the transmission to kr, kt = T (1 - F)");
    trace_note(run, "color = local + kr color(reflected) + kt color(refracted); a ray whose "
                    "weight in the pixel is below 1/1024, or past depth 5, is not traced");
    trace_note(run,
               "colours are linear RGB; the frames show the rays from the side: -z across, y up");
    cg_trace_options options = cg_trace_options_default();
    options.clip_depth = 1;
    cg_status status = cg_trace_pixel_steps(scene, &camera, &options, width, height, (int)x, (int)y,
                                            cg_step_log_record, run->log);
    cg_trace_scene_free(scene);
    return trace_finish(run, status, "the scene cannot be traced", out);
}

const trace_algorithm trace_surfaces_algorithms[] = {
    {"painter", "MESH [ABOUT_Y [ABOUT_X]]", run_painter},
    {"ray", "spheres|MESH X Y [WxH]", run_ray},
    {NULL, NULL, NULL},
};
