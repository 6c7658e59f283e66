/* `cg trace-render`: options, camera, timing and output around the ray
 * tracer hook (see trace_command.h). */
#include "trace_command.h"

#include "cli.h"
#include "render_scene.h"
#include "cg/color.h"
#include "cg/mesh.h"
#include "cg/xform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void raytrace_settings_default(raytrace_settings *s)
{
    memset(s, 0, sizeof *s);
    s->width = 800;
    s->height = 600;
    s->up = cg_vec3_make(0, 1, 0);
    s->fov_degrees = 45;
    cg_render_options_default(&s->render);
    s->render.frame_camera = 0;
    raytrace_extra_default(&s->extra);
}

int raytrace_parse_option(const char *command, int argc, char **argv, int *i,
                          raytrace_settings *s)
{
    const char *arg = argv[*i];
    const char *v;
    long n;
    cg_rgba8 c;
    cg_render_options *o = &s->render;
#define VALUE()                                               \
    do {                                                      \
        if (!(v = cli_option_value(command, argc, argv, i))) \
            return -1;                                        \
    } while (0)
    if (cli_option_is(arg, "-o") || cli_option_is(arg, "--output")) {
        VALUE();
        s->output = v;
    } else if (cli_option_is(arg, "--scene")) {
        VALUE();
        if (strcmp(v, "spheres") != 0) {
            cli_usage_error(command, "--scene: unknown scene '%s' (expected spheres)", v);
            return -1;
        }
        s->extra.classic_scene = 1;
    } else if (cli_option_is(arg, "--size")) {
        VALUE();
        if (cli_parse_size(command, "--size", v, &s->width, &s->height))
            return -1;
        s->have_size = 1;
    } else if (cli_option_is(arg, "--eye") || cli_option_is(arg, "--target")
               || cli_option_is(arg, "--up")) {
        int which = cli_option_is(arg, "--eye") ? 0 : cli_option_is(arg, "--target") ? 1 : 2;
        cg_vec3 *dst = which == 0 ? &s->eye : which == 1 ? &s->target : &s->up;
        VALUE();
        if (cli_parse_vec3(command, which == 0 ? "--eye" : which == 1 ? "--target" : "--up", v, dst))
            return -1;
        if (which == 0)
            s->have_eye = 1;
        else if (which == 1)
            s->have_target = 1;
    } else if (cli_option_is(arg, "--fov") || cli_option_is(arg, "--ortho")) {
        int fov = cli_option_is(arg, "--fov");
        double x;
        VALUE();
        if (cli_parse_double(command, fov ? "--fov" : "--ortho", v, &x))
            return -1;
        if (fov ? !(x > 0 && x < 180) : !(x > 0 && isfinite(x))) {
            cli_usage_error(command, fov ? "--fov: expected degrees between 0 and 180, got '%s'"
                                         : "--ortho: expected a positive height, got '%s'", v);
            return -1;
        }
        if (fov) {
            s->fov_degrees = x;
            s->ortho_height = 0;
        } else {
            s->ortho_height = x;
        }
    } else if (cli_option_is(arg, "--light-dir")) {
        cg_vec3 d;
        VALUE();
        if (cli_parse_vec3(command, "--light-dir", v, &d))
            return -1;
        if (!(cg_vec3_length(d) > 0) || o->light_count == CG_RENDER_MAX_LIGHTS) {
            cli_usage_error(command, "--light-dir: %s", o->light_count == CG_RENDER_MAX_LIGHTS
                                                            ? "too many lights"
                                                            : "the direction must not be zero");
            return -1;
        }
        o->lights[o->light_count].direction = d;
        o->lights[o->light_count++].intensity = 1;
    } else if (cli_option_is(arg, "--ambient")) {
        VALUE();
        if (cli_parse_double(command, "--ambient", v, &o->ambient))
            return -1;
        if (!(o->ambient >= 0) || !isfinite(o->ambient)) {
            cli_usage_error(command, "--ambient: expected a number >= 0, got '%s'", v);
            return -1;
        }
    } else if (cli_option_is(arg, "--shading")) {
        VALUE();
        if (strcmp(v, "flat") == 0)
            o->shading = CG_SHADING_FLAT;
        else if (strcmp(v, "gouraud") == 0)
            o->shading = CG_SHADING_GOURAUD;
        else if (strcmp(v, "phong") == 0)
            o->shading = CG_SHADING_PHONG;
        else {
            cli_usage_error(command, "--shading: expected flat, gouraud or phong, got '%s'", v);
            return -1;
        }
        s->have_shading = 1;
    } else if (cli_option_is(arg, "--threads")) {
        VALUE();
        if (cli_parse_long(command, "--threads", v, 1, 64, &n))
            return -1;
        o->threads = (int)n;
        s->have_threads = 1;
    } else if (cli_option_is(arg, "--background") || cli_option_is(arg, "--color")) {
        int background = cli_option_is(arg, "--background");
        VALUE();
        if (cli_parse_color(command, background ? "--background" : "--color", v, &c))
            return -1;
        if (background) {
            o->background = cg_rgba8_to_linear(c);
            s->have_background = 1;
        } else {
            o->color = cg_rgba8_to_linear(c);
        }
    } else if (cli_option_is(arg, "--repeat") || cli_option_is(arg, "--spp")
               || cli_option_is(arg, "--depth")) {
        int which = cli_option_is(arg, "--repeat") ? 0 : cli_option_is(arg, "--spp") ? 1 : 2;
        static const char *const names[] = {"--repeat", "--spp", "--depth"};
        static const long lo[] = {1, 1, 0}, hi[] = {100000, 65536, 64};
        VALUE();
        if (cli_parse_long(command, names[which], v, lo[which], hi[which], &n))
            return -1;
        *(which == 0 ? &s->repeat : which == 1 ? &s->extra.samples : &s->extra.depth) = (int)n;
        s->have_samples |= which == 1;
        s->have_depth |= which == 2;
    } else if (cli_option_is(arg, "--stats")) {
        s->stats = 1;
    } else if (cli_option_is(arg, "--no-shadows")) {
        s->extra.shadows = 0;
    } else if (cli_option_is(arg, "--floor")) {
        s->extra.floor = 1;
    } else if (cli_option_is(arg, "--quiet")) {
        s->quiet = 1;
    } else {
        return 0;
    }
#undef VALUE
    return 1;
}

/* The camera: the classic scene's own view, or framed to the mesh's box
 * [lo, hi] unless --eye places it (as `cg render` does). */
static int place_camera(const raytrace_settings *s, int bounded, cg_vec3 lo, cg_vec3 hi,
                        cg_camera *c)
{
    *c = cg_camera_default();
    c->up = s->up;
    c->fovy = cg_radians(s->fov_degrees);
    c->orthographic = s->ortho_height > 0;
    if (c->orthographic)
        c->ortho_height = s->ortho_height;
    if (!bounded) {
        lo = cg_vec3_make(-1, -1, -1);
        hi = cg_vec3_make(1, 1, 1);
    }
    cg_vec3 centre = cg_vec3_scale(cg_vec3_add(lo, hi), 0.5);
    if (s->extra.classic_scene && !s->have_eye && !s->have_target) {
        c->eye = cg_vec3_make(0, 2.4, 7.5);
        c->target = cg_vec3_make(-0.2, 0.8, -0.6);
    } else if (s->have_eye) {
        c->eye = s->eye;
        c->target = s->have_target ? s->target : centre;
    } else {
        c->target = s->have_target ? s->target : centre;
        c->eye = cg_vec3_add(c->target, cg_vec3_make(0, 0, 1));
        cg_camera_frame(c, lo, hi, (double)s->width / s->height);
        if (s->have_target) {
            cg_vec3 offset = cg_vec3_sub(c->eye, c->target);
            c->target = s->target;
            c->eye = cg_vec3_add(s->target, offset);
        }
        if (s->ortho_height > 0)
            c->ortho_height = s->ortho_height;
    }
    cg_vec3 view = cg_vec3_sub(c->target, c->eye);
    double distance = cg_vec3_length(view);
    if (!(distance > 0) || !(cg_vec3_length(c->up) > 0)
        || cg_vec3_length(cg_vec3_cross(view, c->up)) <= 1e-12 * distance)
        return 0;
    /* Rays start at the eye; a parallel view's start on the near plane. */
    c->near = distance * 1e-4;
    c->far = distance * 1e4;
    return 1;
}

typedef struct progress_state {
    int last;
} progress_state;

static void show_progress(void *user, double fraction)
{
    progress_state *p = user;
    int percent = (int)(100 * fraction);
    if (percent / 10 != p->last / 10) {
        fprintf(stderr, "\rcg: trace-render: %3d%%%s", percent, percent >= 100 ? "\n" : "");
        fflush(stderr);
        p->last = percent;
    }
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
        bounded = cg_mesh_bounds(mesh, &lo, &hi) == CG_OK;
    }
    cg_render_options o = s->render;
    if (!place_camera(s, bounded, lo, hi, &o.camera)) {
        cg_mesh_free(mesh);
        return cli_usage_error(command, "the eye must differ from the target and up must not be "
                                        "parallel to the viewing direction");
    }
    if ((s->extra.classic_scene || s->extra.floor) && !s->have_background)
        o.background = cg_rgba8_to_linear((cg_rgba8){150, 190, 235, 255}); /* a sky */
    progress_state progress = {-1};
    if (!s->quiet && !s->repeat) {
        o.progress = show_progress;
        o.progress_user = &progress;
    }
    render_raytracer *tracer;
    int status = render_raytrace_create_extra(mesh, &o, &s->extra, &tracer);
    cg_mesh_free(mesh);
    if (status != CLI_OK)
        return status;
    cg_image *image;
    if (cg_image_create(&image, s->width, s->height, CG_PIXEL_RGBA8) != CG_OK) {
        render_raytrace_free(tracer);
        return cli_fail("%s: cannot make a %dx%d image", command, s->width, s->height);
    }
    int runs = s->repeat > 0 ? s->repeat : 1;
    double *times = malloc((size_t)runs * sizeof *times);
    if (!times)
        status = cli_fail("%s: out of memory", command);
    for (int r = 0; r < runs && status == CLI_OK; r++) {
        double t0 = cli_now();
        status = render_raytrace_draw(tracer, image);
        times[r] = cli_now() - t0;
    }
    if (status == CLI_OK && s->repeat > 0)
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

/* A scene file through render_scene.h, with the ray tracer. */
static int run_scene(const raytrace_settings *s)
{
    render_scene_overrides o = render_scene_no_overrides();
    o.algorithm = 2;
    if (s->have_size) {
        o.width = s->width;
        o.height = s->height;
    }
    if (s->have_shading)
        o.shading = s->render.shading == CG_SHADING_FLAT ? 0
                    : s->render.shading == CG_SHADING_GOURAUD ? 1 : 2;
    if (s->have_threads)
        o.threads = s->render.threads;
    if (s->have_samples)
        o.samples = s->extra.samples;
    if (s->have_depth)
        o.depth = s->extra.depth;
    o.repeat = s->repeat;
    return render_scene_file(s->input, s->output, &o);
}

int raytrace_run(const char *command, const raytrace_settings *s)
{
    if (!s->output)
        return cli_usage_error(command, "expected -o OUT (.png, .ppm or .pgm)");
    if (cg_file_format_from_path(s->output) == CG_FILE_UNKNOWN)
        return cli_usage_error(command, "%s: unknown output format (expected .png, .ppm or .pgm)",
                               s->output);
    if (s->input && !s->extra.classic_scene && render_scene_is_scene(s->input))
        return run_scene(s);
    cg_image *image;
    int status = raytrace_render(command, s, &image);
    if (status != CLI_OK)
        return status;
    status = cli_write_image(image, s->output);
    cg_image_free(image);
    return status;
}
