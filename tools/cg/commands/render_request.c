/* The one command line of `cg render` and `cg trace-render` (see
 * render_request.h): the table of their options (options.h), then the checks
 * that every option given means something for the algorithm and the input
 * it would act on, so that none is ignored in silence. */
#include "render_request.h"

#include "cli.h"
#include "render_scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Choices are stored as ints into these enums. */
_Static_assert(sizeof(cg_shading) == sizeof(int) && sizeof(cg_cull_mode) == sizeof(int)
                   && sizeof(cg_texture_filter) == sizeof(int)
                   && sizeof(cg_edge_mode) == sizeof(int)
                   && sizeof(render_algorithm) == sizeof(int),
               "choice members are ints");

/* ---- the options that do more than store a value ---------------------------------- */

/* --fov: degrees in (0, 180); a perspective view again after --ortho. */
static int parse_fov(const char *command, const cli_option *option, const char *text,
                     void *arguments)
{
    render_cli_options *common = &((render_request *)arguments)->trace.common;
    if (cli_read_double(command, option, text, &common->fov_degrees))
        return -1;
    common->ortho_height = 0;
    return 0;
}

/* --light-dir X,Y,Z: one more directional light, of strength 1. */
static int parse_light(const char *command, const cli_option *option, const char *text,
                       void *arguments)
{
    render_cli_options *common = &((render_request *)arguments)->trace.common;
    cg_render_options *render = &common->render;
    cg_vec3 direction;
    if (cli_parse_vec3(command, option->name, text, &direction))
        return -1;
    int full = render->light_count == CG_RENDER_MAX_LIGHTS;
    if (full && common->lights_full_first) {
        cli_usage_error(command, "--light-dir: too many lights");
        return -1;
    }
    if (!(cg_vec3_length(direction) > 0)) {
        cli_usage_error(command, "--light-dir: the direction must not be zero");
        return -1;
    }
    if (full) {
        cli_usage_error(command, "--light-dir: at most %d lights", CG_RENDER_MAX_LIGHTS);
        return -1;
    }
    render->lights[render->light_count].direction = direction;
    render->lights[render->light_count++].intensity = 1;
    return 0;
}

/* --view-from X,Y,Z: a direction, so not zero. */
static int parse_view_from(const char *command, const cli_option *option, const char *text,
                           void *arguments)
{
    raytrace_settings *trace = &((render_request *)arguments)->trace;
    if (cli_parse_vec3(command, option->name, text, &trace->view_from))
        return -1;
    if (!(cg_vec3_length(trace->view_from) > 0)) {
        cli_usage_error(command, "--view-from: the direction must not be zero");
        return -1;
    }
    return 0;
}

/* --scene spheres: the one built-in scene. */
static int parse_scene(const char *command, const cli_option *option, const char *text,
                       void *arguments)
{
    (void)option;
    if (strcmp(text, "spheres") != 0) {
        cli_usage_error(command, "--scene: unknown scene '%s' (expected spheres)", text);
        return -1;
    }
    ((render_request *)arguments)->trace.extra.classic_scene = 1;
    return 0;
}

/* --msaa 1|2|4|8|16: samples per pixel of the z-buffer. */
static int parse_msaa(const char *command, const cli_option *option, const char *text,
                      void *arguments)
{
    (void)option;
    static const char *const counts[] = {"1", "2", "4", "8", "16"};
    for (int k = 0; k < 5; k++)
        if (strcmp(text, counts[k]) == 0) {
            ((render_request *)arguments)->trace.common.render.msaa = 1 << k;
            return 0;
        }
    cli_usage_error(command, "--msaa: expected 1, 2, 4, 8 or 16 samples per pixel, got '%s'", text);
    return -1;
}

/* --frames A..B: frames A to B (inclusive) of an animated scene. */
static int parse_frames(const char *command, const cli_option *option, const char *text,
                        void *arguments)
{
    (void)option;
    render_request *r = arguments;
    char *end;
    long a = strtol(text, &end, 10), b = -1;
    if (end != text && end[0] == '.' && end[1] == '.') {
        const char *rest = end + 2;
        b = strtol(rest, &end, 10);
        if (end == rest)
            b = -1;
    }
    if (*end || a < 0 || b < a || b > 1000000) {
        cli_usage_error(command, "--frames: expected A..B with 0 <= A <= B <= 1000000, got '%s'",
                        text);
        return -1;
    }
    r->frame_first = (int)a;
    r->frame_last = (int)b;
    return 0;
}

/* ---- the table ------------------------------------------------------------------- */

#define COMMON(member) offsetof(render_request, trace.common.member)
#define RENDER(member) offsetof(render_request, trace.common.render.member)
#define EXTRA(member) offsetof(render_request, trace.extra.member)
#define GIVEN(option) CLI_GIVEN(render_request, given[option])

static const char *const shadings[] = {"flat", "gouraud", "phong", "unlit", NULL};
static const char *const texture_filters[] = {"nearest", "bilinear", "trilinear", NULL};
static const char *const culls[] = {"none", "back", NULL};
static const char *const algorithms[] = {"zbuffer", "painter", "raytrace", "depth-sort", NULL};

static const cli_option output_options[] = {
    CLI_OPTION_OUTPUT(render_request, trace.common.output, "OUT",
                      "the image to write (.png, .ppm, .pgm)"),
};

static const cli_option camera_options[] = {
    CLI_OPTION_SIZE(render_request, trace.common.size, GIVEN(OPT_SIZE),
                    "image size (default 800x600)"),
    {.name = "--eye",
     .kind = CLI_VEC3,
     .offset = COMMON(eye),
     .value_name = "X,Y,Z",
     .given = GIVEN(OPT_EYE),
     .help = "camera position (then no automatic framing)"},
    {.name = "--view-from",
     .kind = CLI_CUSTOM,
     .parse = parse_view_from,
     .value_name = "X,Y,Z",
     .given = GIVEN(OPT_VIEW_FROM),
     .help = "direction from the mesh toward a framed camera (default 0,0,1)"},
    {.name = "--target",
     .kind = CLI_VEC3,
     .offset = COMMON(target),
     .value_name = "X,Y,Z",
     .given = GIVEN(OPT_TARGET),
     .help = "point looked at (default: the centre of the mesh)"},
    {.name = "--up",
     .kind = CLI_VEC3,
     .offset = COMMON(up),
     .value_name = "X,Y,Z",
     .given = GIVEN(OPT_UP),
     .help = "up direction (default 0,1,0)"},
    {.name = "--fov",
     .kind = CLI_CUSTOM,
     .parse = parse_fov,
     .value_name = "DEGREES",
     .given = GIVEN(OPT_FOV),
     .low = 0,
     .high = 180,
     .open = CLI_OPEN_LOW | CLI_OPEN_HIGH,
     .range_text = "degrees between 0 and 180",
     .help = "vertical field of view, perspective (default 45)"},
    {.name = "--ortho",
     .kind = CLI_DOUBLE,
     .offset = COMMON(ortho_height),
     .value_name = "HEIGHT",
     .given = GIVEN(OPT_ORTHO),
     .low = 0,
     .high = INFINITY,
     .open = CLI_OPEN_LOW,
     .range_text = "a positive height",
     .help = "parallel projection showing HEIGHT world units vertically"},
    {.name = "--near",
     .kind = CLI_DOUBLE,
     .offset = COMMON(near),
     .value_name = "D",
     .given = GIVEN(OPT_NEAR),
     .help = "near clip distance along the view (default: from the mesh's\n"
             "depth range; a parallel view's near may be 0 or negative)"},
    {.name = "--far",
     .kind = CLI_DOUBLE,
     .offset = COMMON(far),
     .value_name = "D",
     .given = GIVEN(OPT_FAR),
     .help = "far clip distance (default: from the mesh's depth range)"},
};

static const cli_option light_options[] = {
    {.name = "--light-dir",
     .kind = CLI_CUSTOM,
     .parse = parse_light,
     .value_name = "X,Y,Z",
     .given = GIVEN(OPT_LIGHT_DIR),
     .help = "directional light toward which lit surfaces face, strength 1;\n"
             "repeatable (default: one light from the camera's upper left)"},
    {.name = "--ambient",
     .kind = CLI_DOUBLE,
     .offset = RENDER(ambient),
     .value_name = "K",
     .given = GIVEN(OPT_AMBIENT),
     .low = 0,
     .high = INFINITY,
     .range_text = "a number >= 0",
     .help = "ambient coefficient (default 0.15)"},
    {.name = "--specular",
     .kind = CLI_DOUBLE,
     .offset = RENDER(specular),
     .value_name = "K",
     .given = GIVEN(OPT_SPECULAR),
     .low = 0,
     .high = INFINITY,
     .range_text = "a number >= 0",
     .help = "specular coefficient, Blinn-Phong (default 0.25)"},
    {.name = "--shininess",
     .kind = CLI_DOUBLE,
     .offset = RENDER(shininess),
     .value_name = "N",
     .given = GIVEN(OPT_SHININESS),
     .low = 0,
     .high = INFINITY,
     .range_text = "a number >= 0",
     .help = "specular exponent (default 32)"},
    {.name = "--color",
     .kind = CLI_LINEAR_COLOR,
     .offset = RENDER(color),
     .value_name = "COLOR",
     .given = GIVEN(OPT_COLOR),
     .help = "diffuse colour where the file has none (default #c4c4c4)"},
    {.name = "--background",
     .kind = CLI_LINEAR_COLOR,
     .offset = RENDER(background),
     .value_name = "COLOR",
     .given = GIVEN(OPT_BACKGROUND),
     .help = "background (default #1d1f27; a sky with --floor and --scene)"},
};

static const cli_option pipeline_options[] = {
    {.name = "--shading",
     .kind = CLI_CHOICE,
     .offset = RENDER(shading),
     .choices = shadings,
     .given = GIVEN(OPT_SHADING),
     .help = "shading model (default gouraud); unlit: the material's\n"
             "colour and texture as they are, no lighting"},
    {.name = "--crease",
     .kind = CLI_DOUBLE,
     .offset = offsetof(render_request, crease_degrees),
     .value_name = "DEGREES",
     .given = GIVEN(OPT_CREASE),
     .low = 0,
     .high = 180,
     .range_text = "a number >= 0 and <= 180",
     .help = "computed normals are split where faces meet at a\n"
             "larger angle (default 60)"},
    {.name = "--algorithm",
     .kind = CLI_CHOICE,
     .offset = offsetof(render_request, algorithm),
     .choices = algorithms,
     .given = GIVEN(OPT_ALGORITHM),
     .help = "visible-surface algorithm (default zbuffer); depth-sort is\n"
             "painter's without its overlap tests, to show their purpose"},
    CLI_OPTION_THREADS(render_request, trace.common.render.threads, GIVEN(OPT_THREADS),
                       "worker threads, 1 to 64; the picture is the same for any N"),
    CLI_OPTION_REPEAT(render_request, trace.common.repeat, 100000,
                      "render N frames after loading and print the median time\n"
                      "on stderr as 'frame: 12.3 ms'"),
    {.name = "--quiet",
     .kind = CLI_FLAG,
     .offset = offsetof(render_request, trace.quiet),
     .flag_value = 1,
     .given = GIVEN(OPT_QUIET),
     .help = "no progress on stderr (shown for frames over a second)"},
};

/* The rasterizer's own (the ray tracer sees both faces and draws no edges). */
static const cli_option raster_options[] = {
    {.name = "--shadows",
     .kind = CLI_FLAG,
     .offset = RENDER(shadows),
     .flag_value = 1,
     .given = GIVEN(OPT_SHADOWS),
     .help = "shadow maps for the directional lights (percentage-closer\n"
             "filtered; the ray tracer casts shadow rays instead)"},
    {.name = "--msaa",
     .kind = CLI_CUSTOM,
     .parse = parse_msaa,
     .value_name = "1|2|4|8|16",
     .given = GIVEN(OPT_MSAA),
     .help = "multisample anti-aliasing: samples per pixel at the standard\n"
             "positions, resolved in linear light (default 1; z-buffer only)"},
    {.name = "--texture-filter",
     .kind = CLI_CHOICE,
     .offset = RENDER(texture_filter),
     .choices = texture_filters,
     .given = GIVEN(OPT_TEXTURE_FILTER),
     .help = "how base-colour textures are sampled (default trilinear:\n"
             "mip levels chosen from each pixel's footprint)"},
    {.name = "--cull",
     .kind = CLI_CHOICE,
     .offset = RENDER(cull),
     .choices = culls,
     .given = GIVEN(OPT_CULL),
     .help = "back-face culling; front faces are counter-clockwise as\n"
             "seen by the camera (default back)"},
    {.name = "--wireframe",
     .kind = CLI_FLAG,
     .offset = RENDER(edges),
     .flag_value = CG_EDGES_WIREFRAME,
     .given = GIVEN(OPT_WIREFRAME),
     .help = "every edge, no faces"},
    {.name = "--hidden-line",
     .kind = CLI_FLAG,
     .offset = RENDER(edges),
     .flag_value = CG_EDGES_HIDDEN_LINE,
     .given = GIVEN(OPT_HIDDEN_LINE),
     .help = "visible edges only"},
    {.name = "--edges",
     .kind = CLI_FLAG,
     .offset = RENDER(edges),
     .flag_value = CG_EDGES_OVERLAY,
     .given = GIVEN(OPT_EDGES),
     .help = "shaded faces with their visible edges"},
    {.name = "--output-depth",
     .kind = CLI_FLAG,
     .offset = offsetof(render_request, output_depth),
     .flag_value = 1,
     .given = GIVEN(OPT_OUTPUT_DEPTH),
     .help = "write the depth buffer (near light, far dark) instead"},
    {.name = "--edge-color",
     .kind = CLI_LINEAR_COLOR,
     .offset = RENDER(edge_color),
     .value_name = "COLOR",
     .given = GIVEN(OPT_EDGE_COLOR),
     .help = "colour of wireframe and hidden lines"},
};

static const cli_option raytrace_options[] = {
    {.name = "--spp",
     .kind = CLI_INT,
     .offset = EXTRA(samples),
     .value_name = "N",
     .min = 1,
     .max = 65536,
     .given = GIVEN(OPT_SPP),
     .help = "samples per pixel, stratified (default 1: pixel centres)"},
    {.name = "--depth",
     .kind = CLI_INT,
     .offset = EXTRA(depth),
     .value_name = "N",
     .min = 0,
     .max = 64,
     .given = GIVEN(OPT_DEPTH),
     .help = "reflection/refraction recursion limit, 0..64 (default 5)"},
    {.name = "--no-shadows",
     .kind = CLI_FLAG,
     .offset = EXTRA(shadows),
     .flag_value = 0,
     .given = GIVEN(OPT_NO_SHADOWS),
     .help = "no shadow rays"},
    {.name = "--floor",
     .kind = CLI_FLAG,
     .offset = EXTRA(floor),
     .flag_value = 1,
     .given = GIVEN(OPT_FLOOR),
     .help = "a checkered floor under the mesh (and a sky behind)"},
    {.name = "--scene",
     .kind = CLI_CUSTOM,
     .parse = parse_scene,
     .value_name = "spheres",
     .given = GIVEN(OPT_SCENE),
     .help = "the built-in scene instead of a file"},
    {.name = "--stats",
     .kind = CLI_FLAG,
     .offset = offsetof(render_request, trace.stats),
     .flag_value = 1,
     .given = GIVEN(OPT_STATS),
     .help = "print the BVH build time and rays per second"},
};

static const cli_option scene_options[] = {
    {.name = "--frames",
     .kind = CLI_CUSTOM,
     .parse = parse_frames,
     .value_name = "A..B",
     .given = GIVEN(OPT_FRAMES),
     .help = "frames A to B of the scene's animation, one image each: OUT\n"
             "with %d (or %04d) takes the frame number, else -NNNN goes\n"
             "before its extension (out.png: out-0000.png, ...)"},
};

static const cli_option_group render_groups[] = {
    CLI_GROUP(NULL, output_options),
    CLI_GROUP("Camera (default: looking along -z, placed so the whole mesh fills the view):",
              camera_options),
    CLI_GROUP("Light and material:", light_options),
    CLI_GROUP("Pipeline:", pipeline_options),
    CLI_GROUP("Rasterizer (not with --algorithm raytrace):", raster_options),
    CLI_GROUP("Ray tracer (--algorithm raytrace only):", raytrace_options),
    CLI_GROUP("Scene files:", scene_options),
    {0},
};

const cli_syntax render_syntax = {
    .command = "render",
    .groups = render_groups,
    .max_positionals = 1,
    .too_many = "expected one MESH file, got '%s' as well",
};

/* ---- what was given --------------------------------------------------------------- */

int render_request_has(const render_request *r, render_option option)
{
    return r->given[option] > 0;
}

const char *render_option_name(render_option option)
{
    for (const cli_option_group *group = render_groups; group->options; group++)
        for (size_t k = 0; k < group->count; k++)
            if (group->options[k].given == GIVEN(option))
                return group->options[k].name;
    return "?";
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
    static const render_option raster_only[] = {
        OPT_CULL,         OPT_WIREFRAME,      OPT_HIDDEN_LINE, OPT_EDGES,  OPT_EDGE_COLOR,
        OPT_OUTPUT_DEPTH, OPT_TEXTURE_FILTER, OPT_MSAA,        OPT_SHADOWS};
    static const render_option trace_options[] = {OPT_SPP,        OPT_DEPTH, OPT_STATS,
                                                  OPT_NO_SHADOWS, OPT_FLOOR, OPT_SCENE};
    /* A scene file brings its own objects and normals, and is rendered
     * through cg/scene.h, which keeps no ray or depth statistics. */
    static const render_option not_for_scenes[] = {
        OPT_CREASE, OPT_EDGE_COLOR, OPT_OUTPUT_DEPTH,   OPT_FLOOR,
        OPT_SCENE,  OPT_STATS,      OPT_TEXTURE_FILTER, OPT_SHADOWS};
    const raytrace_settings *s = &r->trace;
    int k;
    if (trace_only && r->algorithm != RENDER_RAYTRACE)
        return cli_usage_error(command,
                               "--algorithm: %s always ray traces (use cg render for "
                               "the other algorithms)",
                               command);
    if (s->common.have_eye && s->have_view_from)
        return cli_usage_error(command, "--eye and --view-from exclude each other");
    if (render_request_has(r, OPT_UP) && !(cg_vec3_length(s->common.up) > 0))
        return cli_usage_error(command, "--up: the up vector must not be zero");
    if (s->input && render_scene_is_scene(s->input) && (k = first_given(r, not_for_scenes, 8)) >= 0)
        return cli_usage_error(command, "%s: not available with a scene file (%s)",
                               render_option_name((render_option)k),
                               k == OPT_FLOOR || k == OPT_SCENE ? "put the objects in the scene"
                                                                : "it applies to mesh files");
    if (render_request_has(r, OPT_FRAMES) && !(s->input && render_scene_is_scene(s->input)))
        return cli_usage_error(command, "--frames: animates a scene file (its \"animation\" "
                                        "key); a mesh file has one frame");
    if (s->common.render.shading == CG_SHADING_UNLIT
        && (r->algorithm == RENDER_RAYTRACE || (s->input && render_scene_is_scene(s->input))))
        return cli_usage_error(command,
                               "--shading unlit: only the rasterizer draws mesh files unlit "
                               "(use --algorithm zbuffer or painter on a mesh file)");
    if (r->algorithm == RENDER_RAYTRACE && (k = first_given(r, raster_only, 9)) >= 0)
        return cli_usage_error(command,
                               "%s: not available with the ray tracer (use --algorithm "
                               "zbuffer or painter)",
                               render_option_name((render_option)k));
    if ((r->algorithm == RENDER_PAINTER || r->algorithm == RENDER_DEPTH_SORT)
        && s->common.render.msaa > 1)
        return cli_usage_error(command, "--msaa: only the z-buffer multisamples (the painter's "
                                        "algorithms draw one sample per pixel)");
    if (r->algorithm != RENDER_RAYTRACE && (k = first_given(r, trace_options, 6)) >= 0)
        return cli_usage_error(command,
                               "%s: only the ray tracer uses it (add --algorithm "
                               "raytrace)",
                               render_option_name((render_option)k));
    return CLI_OK;
}

/* The settings that say which options a scene file keeps its own for. */
static void note_given(render_request *r)
{
    render_cli_options *common = &r->trace.common;
    common->have_size = r->given[OPT_SIZE];
    common->have_eye = r->given[OPT_EYE];
    common->have_target = r->given[OPT_TARGET];
    common->have_shading = r->given[OPT_SHADING];
    common->have_threads = r->given[OPT_THREADS];
    common->have_background = r->given[OPT_BACKGROUND];
    common->have_near = r->given[OPT_NEAR];
    common->have_far = r->given[OPT_FAR];
    r->trace.have_samples = r->given[OPT_SPP];
    r->trace.have_depth = r->given[OPT_DEPTH];
    r->trace.have_view_from = r->given[OPT_VIEW_FROM];
}

int render_request_parse(const char *command, int argc, char **argv, int trace_only,
                         render_request *r)
{
    memset(r, 0, sizeof *r);
    raytrace_settings_default(&r->trace);
    r->algorithm = trace_only ? RENDER_RAYTRACE : RENDER_ZBUFFER;
    r->crease_degrees = 60;
    cli_syntax syntax = render_syntax; /* the messages name the command typed */
    syntax.command = command;
    const char *input = NULL;
    if (cli_parse(&syntax, argc, argv, r, &input, NULL) != CLI_OK)
        return CLI_USAGE;
    r->trace.input = input;
    note_given(r);
    r->trace.common.render.crease_angle = cg_radians(r->crease_degrees);
    return check_combinations(command, trace_only, r);
}
