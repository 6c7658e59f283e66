/* `cg trace` for chapter 5's visible-surface algorithms that draw a whole
 * picture: the painter's algorithm (the renderer's own run, reported by
 * cg_painter_steps) and a pixel's ray tree (cg_ray_tree_steps). */
#include "trace_algorithms.h"

#include "cli.h"
#include "cg/render.h"
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
    double about_y = 30, about_x = 20;
    if (argc < 2 || argc > 4)
        return cli_usage_error("trace", "painter: expected 'painter MESH [ABOUT_Y [ABOUT_X]]' "
                                        "(degrees)");
    if ((argc > 2 && trace_parse_real("ABOUT_Y", argv[2], &about_y))
        || (argc > 3 && trace_parse_real("ABOUT_X", argv[3], &about_x)))
        return CLI_USAGE;
    cg_mesh *mesh;
    cg_mat4 model;
    cg_camera camera;
    if (trace_frame_mesh(argv[1], about_y, about_x, (double)PAINTER_WIDTH / PAINTER_HEIGHT, &mesh,
                         &model, &camera)
        != CLI_OK)
        return CLI_FAILED;
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
    trace_summary(run, "%zu polygons painted (%zu triangles, %zu splits), %zu pair tests",
                  count_phase(run->log, "paint"), stats.triangles, stats.splits,
                  count_phase(run->log, "tests"));
    int code = trace_finish(run, status, "the mesh cannot be drawn", out);
    trace_run_free(run);
    return code;
}

const trace_algorithm trace_surfaces_algorithms[] = {
    {"painter", "MESH [ABOUT_Y [ABOUT_X]]", run_painter},
    {NULL, NULL, NULL},
};
