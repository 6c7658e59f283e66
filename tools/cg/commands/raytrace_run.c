/* The ray tracer's options, camera, timing and output around the ray tracer
 * hook (see raytrace_run.h), for `cg render --algorithm raytrace` and its
 * alias `cg trace-render`. */
#include "raytrace_run.h"

#include "cli.h"
#include "render_progress.h"
#include "cg/color.h"
#include "cg/mesh.h"
#include "cg/xform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void raytrace_settings_default(raytrace_settings *s)
{
    memset(s, 0, sizeof *s);
    render_cli_options_default(&s->common);
    s->common.lights_full_first = 1;
    s->view_from = cg_vec3_make(0, 0, 1);
    raytrace_extra_default(&s->extra);
}

/* The camera: the classic scene's own view, or framed to the mesh's box
 * [lo, hi] from the --view-from direction unless --eye places it (as the
 * rasterizer's path of `cg render` does). */
static int place_camera(const raytrace_settings *s, int bounded, cg_vec3 lo, cg_vec3 hi,
                        cg_camera *c)
{
    *c = cg_camera_default();
    c->up = s->common.up;
    c->fovy = cg_radians(s->common.fov_degrees);
    c->orthographic = s->common.ortho_height > 0;
    if (c->orthographic)
        c->ortho_height = s->common.ortho_height;
    if (!bounded) {
        lo = cg_vec3_make(-1, -1, -1);
        hi = cg_vec3_make(1, 1, 1);
    }
    cg_vec3 centre = cg_vec3_scale(cg_vec3_add(lo, hi), 0.5);
    if (s->extra.classic_scene && !s->common.have_eye && !s->common.have_target) {
        c->eye = cg_vec3_make(0, 2.4, 7.5);
        c->target = cg_vec3_make(-0.2, 0.8, -0.6);
    } else if (s->common.have_eye) {
        c->eye = s->common.eye;
        c->target = s->common.have_target ? s->common.target : centre;
    } else {
        c->target = s->common.have_target ? s->common.target : centre;
        c->eye = cg_vec3_add(c->target, s->view_from);
        cg_camera_frame(c, lo, hi, (double)s->common.size.width / s->common.size.height);
        if (s->common.have_target) {
            cg_vec3 offset = cg_vec3_sub(c->eye, c->target);
            c->target = s->common.target;
            c->eye = cg_vec3_add(s->common.target, offset);
        }
        if (s->common.ortho_height > 0)
            c->ortho_height = s->common.ortho_height;
    }
    cg_vec3 view = cg_vec3_sub(c->target, c->eye);
    double distance = cg_vec3_length(view);
    if (!(distance > 0) || !(cg_vec3_length(c->up) > 0)
        || cg_vec3_length(cg_vec3_cross(view, c->up)) <= 1e-12 * distance)
        return 0;
    /* Rays start at the eye; a parallel view's start on the near plane,
     * which encloses the mesh (the classic scene's spheres and floor reach
     * beyond any box: there the eye's own plane). */
    c->near = distance * 1e-4;
    c->far = distance * 1e4;
    return 1;
}

int raytrace_render(const char *command, const raytrace_settings *s, cg_image **out)
{
    *out = NULL;
    if (!s->input == !s->extra.classic_scene)
        return cli_usage_error(command, "expected a MESH file or --scene spheres (one of them)");
    cg_mesh *mesh = NULL;
    cg_error err;
    cg_vec3 lo = {0, 0, 0}, hi = {0, 0, 0};
    int bounded = 0;
    if (s->input) {
        if (cg_mesh_load(s->input, &mesh, &err) != CG_OK)
            return cli_fail("%s", err.message);
        if (mesh->face_count == 0) {
            size_t n = mesh->vertex_count;
            cg_mesh_free(mesh);
            return cli_fail("%s: %s: nothing to draw: the file has %zu vertices and no faces (a "
                            "point cloud, lines only, or a truncated file)",
                            command, s->input, n);
        }
        bounded = cg_mesh_bounds(mesh, &lo, &hi) == CG_OK;
    }
    cg_render_options o = s->common.render;
    if (!place_camera(s, bounded, lo, hi, &o.camera)) {
        cg_mesh_free(mesh);
        return cli_usage_error(command, "the eye must differ from the target and up must not be "
                                        "parallel to the viewing direction");
    }
    if (render_cli_set_depth(command, &s->common, bounded, lo, hi, &o.camera) != CLI_OK) {
        cg_mesh_free(mesh);
        return CLI_USAGE;
    }
    if (s->extra.classic_scene || s->extra.floor) {
        /* Infinite planes: seen to the horizon and up to the eye. */
        double distance = cg_vec3_length(cg_vec3_sub(o.camera.target, o.camera.eye));
        if (!s->common.have_far)
            o.camera.far = INFINITY;
        if (!s->common.have_near && !o.camera.orthographic)
            o.camera.near = fmin(o.camera.near, distance * 1e-4);
    }
    if ((s->extra.classic_scene || s->extra.floor) && !s->common.have_background)
        o.background = cg_rgba8_to_linear((cg_rgba8){150, 190, 235, 255}); /* a sky */
    render_progress progress;
    render_progress_start(&progress, command);
    if (!s->quiet) {
        o.progress = render_progress_show;
        o.progress_user = &progress;
    }
    render_raytracer *tracer;
    int status = render_raytrace_create_extra(mesh, &o, &s->extra, &tracer);
    cg_mesh_free(mesh);
    if (status != CLI_OK)
        return status;
    cg_image *image;
    if (cg_image_create(&image, s->common.size.width, s->common.size.height, CG_PIXEL_RGBA8)
        != CG_OK) {
        render_raytrace_free(tracer);
        return cli_fail("%s: cannot make a %dx%d image", command, s->common.size.width,
                        s->common.size.height);
    }
    int runs = s->common.repeat > 0 ? s->common.repeat : 1;
    double *times = malloc((size_t)runs * sizeof *times);
    if (!times)
        status = cli_fail("%s: out of memory", command);
    for (int r = 0; r < runs && status == CLI_OK; r++) {
        render_progress_start(&progress, command);
        status = render_raytrace_draw(tracer, image);
        times[r] = cli_now() - progress.start;
        render_progress_end(&progress);
    }
    if (status == CLI_OK && s->common.repeat > 0)
        fprintf(stderr, "frame: %.1f ms\n", cli_median(times, runs) * 1e3);
    if (status == CLI_OK && s->stats) {
        double build, seconds;
        unsigned long long rays;
        render_raytrace_stats(tracer, &build, &rays, &seconds);
        fprintf(stderr, "bvh build: %.2f ms\n", build * 1e3);
        fprintf(stderr, "rays: %llu in %.1f ms, %.2f Mrays/s\n", rays, seconds * 1e3,
                seconds > 0 ? (double)rays / seconds * 1e-6 : 0.0);
    }
    free(times);
    render_raytrace_free(tracer);
    if (status != CLI_OK) {
        cg_image_free(image);
        return status;
    }
    *out = image;
    return CLI_OK;
}

int raytrace_run(const char *command, const raytrace_settings *s)
{
    if (render_cli_check_output(command, s->common.output) != CLI_OK)
        return CLI_USAGE;
    cg_image *image;
    int status = raytrace_render(command, s, &image);
    if (status != CLI_OK)
        return status;
    status = cli_write_image(image, s->common.output);
    cg_image_free(image);
    return status;
}
