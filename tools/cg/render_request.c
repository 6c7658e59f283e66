/* The one parser of `cg render` and `cg trace-render` (see render_request.h):
 * the options shared with the ray tracer go through raytrace_parse_option
 * (which takes render_options.h's first), the rasterizer's here; then every
 * option given is checked against the algorithm and the input it would act
 * on, so that none is ignored in silence. */
#include "render_request.h"

#include "cli.h"
#include "render_scene.h"
#include "cg/color.h"

#include <string.h>

static const char *const option_names[OPT_COUNT] = {
    "--algorithm", "--eye", "--target", "--up", "--fov", "--ortho", "--view-from",
    "--light-dir", "--ambient", "--specular", "--shininess", "--color", "--background",
    "--edge-color", "--crease", "--cull", "--wireframe", "--hidden-line", "--edges",
    "--output-depth", "--spp", "--depth", "--stats", "--no-shadows", "--floor", "--scene",
    "--quiet",
};

const char *render_option_name(render_option option)
{
    return option_names[option];
}

int render_request_has(const render_request *r, render_option option)
{
    return (r->given >> option) & 1;
}

/* The option argv[i] names, or OPT_COUNT for the others (-o, --size, ...). */
static render_option option_of(const char *arg)
{
    for (int k = 0; k < OPT_COUNT; k++)
        if (cli_option_is(arg, option_names[k]))
            return (render_option)k;
    return OPT_COUNT;
}

/* The rasterizer's own options and the camera direction: 1 consumed, 0 not
 * one of them, -1 after an error. */
static int parse_render_option(const char *command, int argc, char **argv, int *i,
                               render_request *r)
{
    static const char *const algorithms[] = {"zbuffer", "painter", "raytrace", "depth-sort"};
    static const char *const culls[] = {"none", "back"};
    cg_render_options *o = &r->trace.common.render;
    const char *a = argv[*i], *v = NULL;
#define VALUE()                                               \
    do {                                                      \
        if (!(v = cli_option_value(command, argc, argv, i))) \
            return -1;                                        \
    } while (0)
    if (cli_option_is(a, "--view-from")) {
        VALUE();
        if (cli_parse_vec3(command, "--view-from", v, &r->trace.view_from))
            return -1;
        if (!(cg_vec3_length(r->trace.view_from) > 0)) {
            cli_usage_error(command, "--view-from: the direction must not be zero");
            return -1;
        }
        r->trace.have_view_from = 1;
    } else if (cli_option_is(a, "--specular") || cli_option_is(a, "--shininess")
               || cli_option_is(a, "--crease")) {
        int which = cli_option_is(a, "--specular") ? 0 : cli_option_is(a, "--shininess") ? 1 : 2;
        static const char *const names[] = {"--specular", "--shininess", "--crease"};
        double k;
        VALUE();
        if (cli_parse_double(command, names[which], v, &k))
            return -1;
        if (!(k >= 0) || (which == 2 && k > 180)) {
            cli_usage_error(command, "%s: expected a number >= 0%s, got '%s'", names[which],
                            which == 2 ? " and <= 180" : "", v);
            return -1;
        }
        if (which == 0)
            o->specular = k;
        else if (which == 1)
            o->shininess = k;
        else
            r->crease_degrees = k;
    } else if (cli_option_is(a, "--cull")) {
        int c;
        VALUE();
        if (render_cli_parse_choice(command, "--cull", v, culls, 2, &c))
            return -1;
        o->cull = (cg_cull_mode)c;
    } else if (cli_option_is(a, "--algorithm")) {
        int c;
        VALUE();
        if (render_cli_parse_choice(command, "--algorithm", v, algorithms, 4, &c))
            return -1;
        r->algorithm = (render_algorithm)c;
    } else if (cli_option_is(a, "--wireframe")) {
        o->edges = CG_EDGES_WIREFRAME;
    } else if (cli_option_is(a, "--hidden-line")) {
        o->edges = CG_EDGES_HIDDEN_LINE;
    } else if (cli_option_is(a, "--edges")) {
        o->edges = CG_EDGES_OVERLAY;
    } else if (cli_option_is(a, "--output-depth")) {
        r->output_depth = 1;
    } else if (cli_option_is(a, "--edge-color")) {
        cg_rgba8 c;
        VALUE();
        if (cli_parse_color(command, "--edge-color", v, &c))
            return -1;
        o->edge_color = cg_rgba8_to_linear(c);
    } else {
        return 0;
    }
#undef VALUE
    return 1;
}

/* The first option of set[0..count) that was given, or -1. */
static int first_given(const render_request *r, const render_option *set, int count)
{
    for (int k = 0; k < count; k++)
        if (render_request_has(r, set[k]))
            return (int)set[k];
    return -1;
}

/* Rejects, with one line, an option that means nothing for what was asked. */
static int check_combinations(const char *command, int trace_only, const render_request *r)
{
    static const render_option raster_only[] = {OPT_CULL, OPT_WIREFRAME, OPT_HIDDEN_LINE,
                                                OPT_EDGES, OPT_EDGE_COLOR, OPT_OUTPUT_DEPTH};
    static const render_option trace_options[] = {OPT_SPP, OPT_DEPTH, OPT_STATS,
                                                  OPT_NO_SHADOWS, OPT_FLOOR, OPT_SCENE};
    /* A scene file brings its own objects and normals, and is rendered
     * through cg/scene.h, which keeps no ray or depth statistics. */
    static const render_option not_for_scenes[] = {OPT_CREASE, OPT_EDGE_COLOR, OPT_OUTPUT_DEPTH,
                                                   OPT_FLOOR, OPT_SCENE, OPT_STATS};
    const raytrace_settings *s = &r->trace;
    int k;
    if (trace_only && r->algorithm != RENDER_RAYTRACE)
        return cli_usage_error(command, "--algorithm: %s always ray traces (use cg render for "
                                        "the other algorithms)", command);
    if (s->common.have_eye && s->have_view_from)
        return cli_usage_error(command, "--eye and --view-from exclude each other");
    if (render_request_has(r, OPT_UP) && !(cg_vec3_length(s->common.up) > 0))
        return cli_usage_error(command, "--up: the up vector must not be zero");
    if (s->input && render_scene_is_scene(s->input)
        && (k = first_given(r, not_for_scenes, 6)) >= 0)
        return cli_usage_error(command, "%s: not available with a scene file (%s)",
                               option_names[k],
                               k == OPT_FLOOR || k == OPT_SCENE ? "put the objects in the scene"
                                                                : "it applies to mesh files");
    if (r->algorithm == RENDER_RAYTRACE && (k = first_given(r, raster_only, 6)) >= 0)
        return cli_usage_error(command, "%s: not available with the ray tracer (use --algorithm "
                                        "zbuffer or painter)", option_names[k]);
    if (r->algorithm != RENDER_RAYTRACE && (k = first_given(r, trace_options, 6)) >= 0)
        return cli_usage_error(command, "%s: only the ray tracer uses it (add --algorithm "
                                        "raytrace)", option_names[k]);
    return CLI_OK;
}

int render_request_parse(const char *command, int argc, char **argv, int trace_only,
                         render_request *r)
{
    memset(r, 0, sizeof *r);
    raytrace_settings_default(&r->trace);
    r->algorithm = trace_only ? RENDER_RAYTRACE : RENDER_ZBUFFER;
    r->crease_degrees = 60;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!cli_is_option(a)) {
            if (r->trace.input)
                return cli_usage_error(command, "expected one MESH file, got '%s' as well", a);
            r->trace.input = a;
            continue;
        }
        render_option which = option_of(a);
        int used = raytrace_parse_option(command, argc, argv, &i, &r->trace);
        if (used == 0)
            used = parse_render_option(command, argc, argv, &i, r);
        if (used < 0)
            return CLI_USAGE;
        if (used == 0)
            return cli_usage_error(command, "unknown option '%s'", a);
        if (which != OPT_COUNT)
            r->given |= 1ul << which;
    }
    r->trace.common.render.crease_angle = cg_radians(r->crease_degrees);
    return check_combinations(command, trace_only, r);
}
