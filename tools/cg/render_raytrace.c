/* The ray tracer as a command: settings, option parsing, scene set-up,
 * timing and output (see render_raytrace.h). */
#include "render_raytrace.h"

#include "cli.h"
#include "cg/color.h"
#include "cg/light.h"
#include "cg/mesh.h"
#include "cg/trace.h"
#include "cg/xform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* TEMPORARY until the mesh readers land on main (branch issue-7-meshio):
 * a weak reference, so that the tool builds with or without them. */
cg_status cg_mesh_load(const char *path, cg_mesh **out, cg_error *err) __attribute__((weak));

void raytrace_settings_default(raytrace_settings *s)
{
    memset(s, 0, sizeof *s);
    s->width = 640;
    s->height = 480;
    s->up = cg_vec3_make(0, 1, 0);
    s->fov_degrees = 45;
    s->ambient = 0.15;
    s->threads = 1;
    s->background = (cg_rgba8){0, 0, 0, 255};
    s->color = (cg_rgba8){200, 200, 200, 255};
    s->samples = 1;
    s->depth = 5;
    s->shadows = 1;
}

int raytrace_parse_option(const char *command, int argc, char **argv, int *i,
                          raytrace_settings *s)
{
    const char *arg = argv[*i];
    const char *v;
    long n;
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
        s->scene = v;
    } else if (cli_option_is(arg, "--size")) {
        VALUE();
        if (cli_parse_size(command, "--size", v, &s->width, &s->height))
            return -1;
    } else if (cli_option_is(arg, "--eye")) {
        VALUE();
        if (cli_parse_vec3(command, "--eye", v, &s->eye))
            return -1;
        s->have_eye = 1;
    } else if (cli_option_is(arg, "--target")) {
        VALUE();
        if (cli_parse_vec3(command, "--target", v, &s->target))
            return -1;
        s->have_target = 1;
    } else if (cli_option_is(arg, "--up")) {
        VALUE();
        if (cli_parse_vec3(command, "--up", v, &s->up))
            return -1;
    } else if (cli_option_is(arg, "--fov")) {
        VALUE();
        if (cli_parse_double(command, "--fov", v, &s->fov_degrees))
            return -1;
        if (!(s->fov_degrees > 0 && s->fov_degrees < 180)) {
            cli_usage_error(command, "--fov: expected degrees in (0, 180), got '%s'", v);
            return -1;
        }
        s->orthographic = 0;
    } else if (cli_option_is(arg, "--ortho")) {
        VALUE();
        if (cli_parse_double(command, "--ortho", v, &s->ortho_height))
            return -1;
        if (!(s->ortho_height > 0) || !isfinite(s->ortho_height)) {
            cli_usage_error(command, "--ortho: expected a positive height, got '%s'", v);
            return -1;
        }
        s->orthographic = 1;
    } else if (cli_option_is(arg, "--light-dir")) {
        VALUE();
        cg_vec3 d;
        if (cli_parse_vec3(command, "--light-dir", v, &d))
            return -1;
        if (!(cg_vec3_length(d) > 0)) {
            cli_usage_error(command, "--light-dir: the direction must not be zero");
            return -1;
        }
        if (s->light_count == RAYTRACE_MAX_LIGHTS) {
            cli_usage_error(command, "--light-dir: at most %d lights", RAYTRACE_MAX_LIGHTS);
            return -1;
        }
        s->light_dirs[s->light_count++] = cg_vec3_normalize(d);
    } else if (cli_option_is(arg, "--ambient")) {
        VALUE();
        if (cli_parse_double(command, "--ambient", v, &s->ambient))
            return -1;
        if (!(s->ambient >= 0) || !isfinite(s->ambient)) {
            cli_usage_error(command, "--ambient: expected a number >= 0, got '%s'", v);
            return -1;
        }
    } else if (cli_option_is(arg, "--shading")) {
        VALUE();
        if (strcmp(v, "flat") == 0)
            s->flat = 1;
        else if (strcmp(v, "gouraud") == 0 || strcmp(v, "phong") == 0)
            s->flat = 0;
        else {
            cli_usage_error(command, "--shading: expected flat, gouraud or phong, got '%s'", v);
            return -1;
        }
    } else if (cli_option_is(arg, "--threads")) {
        VALUE();
        if (cli_parse_long(command, "--threads", v, 1, 256, &n))
            return -1;
        s->threads = (int)n;
    } else if (cli_option_is(arg, "--background")) {
        VALUE();
        if (cli_parse_color(command, "--background", v, &s->background))
            return -1;
        s->have_background = 1;
    } else if (cli_option_is(arg, "--color")) {
        VALUE();
        if (cli_parse_color(command, "--color", v, &s->color))
            return -1;
    } else if (cli_option_is(arg, "--repeat")) {
        VALUE();
        if (cli_parse_long(command, "--repeat", v, 1, 1000, &n))
            return -1;
        s->repeat = (int)n;
    } else if (cli_option_is(arg, "--spp")) {
        VALUE();
        if (cli_parse_long(command, "--spp", v, 1, 65536, &n))
            return -1;
        s->samples = (int)n;
    } else if (cli_option_is(arg, "--depth")) {
        VALUE();
        if (cli_parse_long(command, "--depth", v, 0, 64, &n))
            return -1;
        s->depth = (int)n;
    } else if (cli_option_is(arg, "--stats")) {
        s->stats = 1;
    } else if (cli_option_is(arg, "--no-shadows")) {
        s->shadows = 0;
    } else if (cli_option_is(arg, "--floor")) {
        s->floor = 1;
    } else if (cli_option_is(arg, "--quiet")) {
        s->quiet = 1;
    } else {
        return 0;
    }
#undef VALUE
    return 1;
}

static cg_vec3 linear_rgb(cg_rgba8 c)
{
    cg_rgbaf f = cg_rgba8_to_linear(c);
    return cg_vec3_make(f.r, f.g, f.b);
}

/* A mesh lit as the rasterizer lights it: white ambient light scaled by
 * --ambient (ka), kd 1, Blinn-Phong ks 0.25 and exponent 32; lights along
 * --light-dir, or one from the camera's upper left. */
static int add_mesh(const char *command, cg_trace_scene *scene, const raytrace_settings *s)
{
    cg_mesh *mesh;
    cg_error err;
    if (!cg_mesh_load)
        return cli_fail("%s: this build has no mesh readers; use --scene spheres", command);
    if (cg_mesh_load(s->input, &mesh, &err) != CG_OK)
        return cli_fail("%s", err.message);
    cg_trace_material m = cg_trace_material_default();
    m.surface = cg_material_make(linear_rgb(s->color), s->ambient, 1, 0.25, 32);
    m.surface.specular = CG_SPECULAR_BLINN;
    cg_status st = cg_trace_scene_add_mesh(scene, mesh, NULL, &m);
    cg_mesh_free(mesh);
    if (st != CG_OK)
        return cli_fail("%s: %s: %s", command, s->input, cg_status_str(st));
    cg_light ambient = cg_light_ambient(cg_vec3_make(1, 1, 1));
    cg_trace_scene_add_light(scene, &ambient);
    return 0;
}

/* Directional lights toward s->light_dirs, or (when none and default_light)
 * the rasterizer's default key light: view-space (-1, 1, 1.5), 0.85. */
static void add_lights(cg_trace_scene *scene, const raytrace_settings *s, const cg_camera *camera,
                       int default_light)
{
    for (int i = 0; i < s->light_count; i++) {
        cg_light l = cg_light_directional(cg_vec3_scale(s->light_dirs[i], -1), cg_vec3_make(1, 1, 1));
        cg_trace_scene_add_light(scene, &l);
    }
    cg_mat4 view, inverse;
    if (s->light_count || !default_light || cg_camera_view(camera, &view) != CG_OK
        || cg_mat4_inverse(view, &inverse) != CG_OK)
        return;
    cg_vec3 d = cg_mat4_transform_vector(inverse, cg_vec3_normalize(cg_vec3_make(-1, 1, 1.5)));
    cg_light l = cg_light_directional(cg_vec3_scale(d, -1), cg_vec3_make(0.85, 0.85, 0.85));
    cg_trace_scene_add_light(scene, &l);
}

/* A checkered floor under the scene's bounding box, cells of about a tenth
 * of its size, slightly reflective. */
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
    m.checker_size = size > 0 ? size / 6 : 1;
    cg_trace_scene_add_plane(scene, lo, cg_vec3_make(0, 1, 0), &m);
}

static cg_status place_camera(cg_trace_scene *scene, const raytrace_settings *s, cg_camera *c)
{
    *c = cg_camera_default();
    c->up = s->up;
    c->fovy = cg_radians(s->fov_degrees);
    c->orthographic = s->orthographic;
    if (s->orthographic)
        c->ortho_height = s->ortho_height;
    cg_vec3 lo, hi;
    cg_status st = cg_trace_scene_bounds(scene, &lo, &hi);
    if (st != CG_OK) {
        lo = cg_vec3_make(-1, -1, -1);
        hi = cg_vec3_make(1, 1, 1);
    }
    cg_vec3 center = cg_vec3_scale(cg_vec3_add(lo, hi), 0.5);
    if (s->scene && !s->have_eye && !s->have_target) {
        c->eye = cg_vec3_make(0, 2.4, 7.5);
        c->target = cg_vec3_make(-0.2, 0.8, -0.6);
    } else if (!s->have_eye) {
        if (s->have_target)
            c->eye = cg_vec3_add(s->target, cg_vec3_sub(c->eye, c->target));
        c->target = s->have_target ? s->target : center;
        double aspect = (double)s->width / s->height;
        int keep_height = s->orthographic;
        double height = c->ortho_height;
        st = cg_camera_frame(c, lo, hi, aspect);
        if (st != CG_OK)
            return st;
        if (keep_height)
            c->ortho_height = height;
        if (s->have_target) {
            cg_vec3 back = cg_vec3_sub(c->eye, c->target);
            c->target = s->target;
            c->eye = cg_vec3_add(s->target, back);
        }
    } else {
        c->eye = s->eye;
        c->target = s->have_target ? s->target : center;
    }
    /* Rays start at the eye (or on the near plane of a parallel view). */
    double distance = cg_vec3_length(cg_vec3_sub(c->target, c->eye));
    if (!(distance > 0))
        return CG_EINVAL;
    c->near = distance * 1e-4;
    c->far = distance * 1e4;
    return CG_OK;
}

typedef struct progress_state {
    int last;
} progress_state;

static void show_progress(void *user, int done, int total)
{
    progress_state *p = user;
    int percent = (int)(100.0 * done / total);
    if (percent / 10 != p->last / 10 || done == total) {
        fprintf(stderr, "\rtrace-render: %3d%%%s", percent, done == total ? "\n" : "");
        p->last = percent;
    }
}

static int check_settings(const char *command, const raytrace_settings *s)
{
    if (!s->input && !s->scene)
        return cli_usage_error(command, "expected a mesh file or --scene spheres");
    if (s->input && s->scene)
        return cli_usage_error(command, "give a mesh file or --scene, not both");
    return CLI_OK;
}

int raytrace_render(const char *command, const raytrace_settings *s, cg_image **out)
{
    *out = NULL;
    int status = check_settings(command, s);
    if (status != CLI_OK)
        return status;
    cg_trace_scene *scene = NULL;
    cg_status st;
    if (s->scene) {
        st = cg_trace_scene_classic(&scene);
        if (st != CG_OK)
            return cli_fail("%s: %s", command, cg_status_str(st));
    } else {
        if ((st = cg_trace_scene_create(&scene)) != CG_OK)
            return cli_fail("%s: %s", command, cg_status_str(st));
        if (add_mesh(command, scene, s)) {
            cg_trace_scene_free(scene);
            return CLI_FAILED;
        }
    }
    cg_camera camera;
    if ((st = place_camera(scene, s, &camera)) != CG_OK) {
        cg_trace_scene_free(scene);
        return cli_fail("%s: cannot place the camera (eye and target must differ, up must not be "
                        "along the view)", command);
    }
    if (s->floor && !s->scene)
        add_floor(scene);
    add_lights(scene, s, &camera, !s->scene);
    double build = 0;
    if ((st = cg_trace_scene_build(scene, s->threads, &build)) != CG_OK) {
        cg_trace_scene_free(scene);
        return cli_fail("%s: building the BVH: %s", command, cg_status_str(st));
    }
    cg_image *image;
    if ((st = cg_image_create(&image, s->width, s->height, CG_PIXEL_RGBA8)) != CG_OK) {
        cg_trace_scene_free(scene);
        return cli_fail("%s: %s", command, cg_status_str(st));
    }
    cg_trace_options opt = cg_trace_options_default();
    opt.samples = s->samples;
    opt.max_depth = s->depth;
    opt.threads = s->threads;
    opt.shadows = s->shadows;
    opt.normals = s->flat ? CG_TRACE_FLAT : CG_TRACE_SMOOTH;
    opt.background = cg_rgba8_to_linear(s->background);
    if ((s->scene || s->floor) && !s->have_background) /* a sky for the mirrors to show */
        opt.background = cg_rgba8_to_linear((cg_rgba8){150, 190, 235, 255});
    progress_state progress = {-1};
    if (!s->quiet && !s->repeat) {
        opt.progress = show_progress;
        opt.progress_user = &progress;
    }
    int runs = s->repeat > 0 ? s->repeat : 1;
    double *times = malloc((size_t)runs * sizeof *times);
    cg_trace_stats stats;
    memset(&stats, 0, sizeof stats);
    for (int r = 0; r < runs && times; r++) {
        double t0 = cli_now();
        st = cg_trace_render(scene, &camera, &opt, image, &stats);
        times[r] = cli_now() - t0;
        if (st != CG_OK) {
            status = cli_fail("%s: %s", command, cg_status_str(st));
            break;
        }
    }
    if (!times)
        status = cli_fail("%s: out of memory", command);
    if (status == CLI_OK && s->repeat > 0)
        fprintf(stderr, "frame: %.1f ms\n", cli_median(times, runs) * 1e3);
    if (status == CLI_OK && s->stats) {
        fprintf(stderr, "bvh build: %.2f ms\n", build * 1e3);
        fprintf(stderr, "rays: %llu in %.1f ms, %.2f Mrays/s\n", (unsigned long long)stats.rays,
                stats.render_seconds * 1e3,
                stats.render_seconds > 0 ? stats.rays / stats.render_seconds * 1e-6 : 0.0);
    }
    free(times);
    cg_trace_scene_free(scene);
    if (status != CLI_OK) {
        cg_image_free(image);
        return status;
    }
    *out = image;
    return CLI_OK;
}

int raytrace_run(const char *command, const raytrace_settings *s)
{
    if (!s->output)
        return cli_usage_error(command, "expected -o OUT.png");
    if (cg_file_format_from_path(s->output) == CG_FILE_UNKNOWN)
        return cli_usage_error(command, "%s: unknown output format (expected .png, .ppm, .pgm)",
                               s->output);
    cg_image *image;
    int status = raytrace_render(command, s, &image);
    if (status != CLI_OK)
        return status;
    status = cli_write_image(image, s->output);
    cg_image_free(image);
    return status;
}
