/* The options shared by `cg render` and `cg trace-render` (see
 * render_options.h). */
#include "render_options.h"

#include "cli.h"
#include "cg/color.h"

#include <math.h>
#include <string.h>

void render_cli_options_default(render_cli_options *o)
{
    memset(o, 0, sizeof *o);
    o->width = 800;
    o->height = 600;
    o->eye = cg_vec3_make(0, 0, 1);
    o->up = cg_vec3_make(0, 1, 0);
    o->fov_degrees = 45;
    cg_render_options_default(&o->render);
    o->render.frame_camera = 0;
}

int render_cli_parse_choice(const char *command, const char *what, const char *text,
                            const char *const *names, int count, int *out)
{
    for (int i = 0; i < count; i++)
        if (strcmp(text, names[i]) == 0) {
            *out = i;
            return 0;
        }
    char list[200] = "";
    for (int i = 0; i < count; i++) {
        strncat(list, names[i], sizeof list - strlen(list) - 1);
        if (i + 1 < count)
            strncat(list, i + 2 == count ? " or " : ", ", sizeof list - strlen(list) - 1);
    }
    cli_usage_error(command, "%s: expected %s, got '%s'", what, list, text);
    return -1;
}

int render_cli_check_output(const char *command, const char *output)
{
    if (!output)
        return cli_usage_error(command, "expected -o OUT (.png, .ppm or .pgm)");
    if (cg_file_format_from_path(output) == CG_FILE_UNKNOWN)
        return cli_usage_error(command, "%s: unknown output format (expected .png, .ppm or .pgm)",
                               output);
    return CLI_OK;
}

int render_cli_set_depth(const char *command, const render_cli_options *o, int bounded,
                         cg_vec3 lo, cg_vec3 hi, cg_camera *camera)
{
    if (bounded)
        cg_camera_fit_depth(camera, lo, hi); /* the camera was checked: it cannot fail */
    if (o->have_near)
        camera->near = o->near;
    if (o->have_far)
        camera->far = o->far;
    if (!camera->orthographic && !(camera->near > 0))
        return cli_usage_error(command, "--near: expected a distance > 0 for a perspective view, "
                                        "got %g", camera->near);
    if (!(camera->far > camera->near))
        return cli_usage_error(command, "--far: expected a distance greater than near (%g), got %g",
                               camera->near, camera->far);
    return CLI_OK;
}

int render_cli_parse_option(const char *command, int argc, char **argv, int *i,
                            render_cli_options *o)
{
    static const char *const shadings[] = {"flat", "gouraud", "phong"};
    const char *a = argv[*i], *v;
    cg_render_options *r = &o->render;
#define VALUE()                                               \
    do {                                                      \
        if (!(v = cli_option_value(command, argc, argv, i))) \
            return -1;                                        \
    } while (0)
    if (cli_option_is(a, "-o") || cli_option_is(a, "--output")) {
        VALUE();
        o->output = v;
    } else if (cli_option_is(a, "--size")) {
        VALUE();
        if (cli_parse_size(command, "--size", v, &o->width, &o->height))
            return -1;
        o->have_size = 1;
    } else if (cli_option_is(a, "--eye") || cli_option_is(a, "--target")
               || cli_option_is(a, "--up")) {
        int which = cli_option_is(a, "--eye") ? 0 : cli_option_is(a, "--target") ? 1 : 2;
        static const char *const names[] = {"--eye", "--target", "--up"};
        cg_vec3 *dst = which == 0 ? &o->eye : which == 1 ? &o->target : &o->up;
        VALUE();
        if (cli_parse_vec3(command, names[which], v, dst))
            return -1;
        if (which == 0)
            o->have_eye = 1;
        else if (which == 1)
            o->have_target = 1;
    } else if (cli_option_is(a, "--fov") || cli_option_is(a, "--ortho")) {
        int fov = cli_option_is(a, "--fov");
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
            o->fov_degrees = x;
            o->ortho_height = 0;
        } else {
            o->ortho_height = x;
        }
    } else if (cli_option_is(a, "--near") || cli_option_is(a, "--far")) {
        int near = cli_option_is(a, "--near");
        double x;
        VALUE();
        if (cli_parse_double(command, near ? "--near" : "--far", v, &x))
            return -1;
        if (!isfinite(x)) {
            cli_usage_error(command, "%s: expected a finite distance, got '%s'",
                            near ? "--near" : "--far", v);
            return -1;
        }
        if (near) {
            o->near = x;
            o->have_near = 1;
        } else {
            o->far = x;
            o->have_far = 1;
        }
    } else if (cli_option_is(a, "--light-dir")) {
        cg_vec3 d;
        VALUE();
        if (cli_parse_vec3(command, "--light-dir", v, &d))
            return -1;
        int full = r->light_count == CG_RENDER_MAX_LIGHTS;
        if (full && o->lights_full_first) {
            cli_usage_error(command, "--light-dir: too many lights");
            return -1;
        }
        if (!(cg_vec3_length(d) > 0)) {
            cli_usage_error(command, "--light-dir: the direction must not be zero");
            return -1;
        }
        if (full) {
            cli_usage_error(command, "--light-dir: at most %d lights", CG_RENDER_MAX_LIGHTS);
            return -1;
        }
        r->lights[r->light_count].direction = d;
        r->lights[r->light_count++].intensity = 1;
    } else if (cli_option_is(a, "--ambient")) {
        double k;
        VALUE();
        if (cli_parse_double(command, "--ambient", v, &k))
            return -1;
        if (!(k >= 0)) {
            cli_usage_error(command, "--ambient: expected a number >= 0, got '%s'", v);
            return -1;
        }
        r->ambient = k;
    } else if (cli_option_is(a, "--shading")) {
        int s;
        VALUE();
        if (render_cli_parse_choice(command, "--shading", v, shadings, 3, &s))
            return -1;
        r->shading = (cg_shading)s;
        o->have_shading = 1;
    } else if (cli_option_is(a, "--threads") || cli_option_is(a, "--repeat")) {
        int threads = cli_option_is(a, "--threads");
        long n;
        VALUE();
        if (cli_parse_long(command, threads ? "--threads" : "--repeat", v, 1,
                           threads ? 64 : 100000, &n))
            return -1;
        if (threads) {
            r->threads = (int)n;
            o->have_threads = 1;
        } else {
            o->repeat = (int)n;
        }
    } else if (cli_option_is(a, "--background") || cli_option_is(a, "--color")) {
        int background = cli_option_is(a, "--background");
        cg_rgba8 c;
        VALUE();
        if (cli_parse_color(command, background ? "--background" : "--color", v, &c))
            return -1;
        if (background) {
            r->background = cg_rgba8_to_linear(c);
            o->have_background = 1;
        } else {
            r->color = cg_rgba8_to_linear(c);
        }
    } else {
        return 0;
    }
#undef VALUE
    return 1;
}
