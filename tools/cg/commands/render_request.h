/* What `cg render` and its alias `cg trace-render` are asked to do: one
 * parser for every option of the two commands, and the checks that an option
 * means something for the chosen algorithm and input (a mesh or a scene file).
 * render_command.c acts on the result. */
#ifndef CG_TOOL_RENDER_REQUEST_H
#define CG_TOOL_RENDER_REQUEST_H

#include "options.h"
#include "raytrace_run.h"

/* --algorithm, in the order of its choices. */
typedef enum render_algorithm {
    RENDER_ZBUFFER = 0,
    RENDER_PAINTER,
    RENDER_RAYTRACE,
    RENDER_DEPTH_SORT
} render_algorithm;

/* The options whose presence matters (an option that only some inputs or
 * algorithms use, or one that overrides a scene file's setting): index of
 * render_request.given. */
typedef enum render_option {
    OPT_ALGORITHM,
    OPT_EYE,
    OPT_TARGET,
    OPT_UP,
    OPT_FOV,
    OPT_ORTHO,
    OPT_VIEW_FROM,
    OPT_LIGHT_DIR,
    OPT_AMBIENT,
    OPT_SPECULAR,
    OPT_SHININESS,
    OPT_COLOR,
    OPT_BACKGROUND,
    OPT_EDGE_COLOR,
    OPT_CREASE,
    OPT_CULL,
    OPT_WIREFRAME,
    OPT_HIDDEN_LINE,
    OPT_EDGES,
    OPT_OUTPUT_DEPTH,
    OPT_SPP,
    OPT_DEPTH,
    OPT_STATS,
    OPT_NO_SHADOWS,
    OPT_FLOOR,
    OPT_SCENE,
    OPT_QUIET,
    OPT_SIZE,
    OPT_NEAR,
    OPT_FAR,
    OPT_SHADING,
    OPT_THREADS,
    OPT_TEXTURE_FILTER,
    OPT_MSAA,
    OPT_SHADOWS,
    OPT_FRAMES,
    OPT_COUNT
} render_option;

typedef struct render_request {
    /* The input, the options `cg render` shares with the ray tracer and the
     * ray tracer's own (--spp, --depth, --stats, --no-shadows, --floor,
     * --scene, --quiet). */
    raytrace_settings trace;
    render_algorithm algorithm;
    double crease_degrees;       /* --crease (default 60) */
    int output_depth;            /* --output-depth */
    int frame_first, frame_last; /* --frames A..B of an animated scene */
    int given[OPT_COUNT];        /* how often each option was on the command line */
} render_request;

/* The command line of `cg render` and `cg trace-render`, for the help. */
extern const cli_syntax render_syntax;

/* Parses argv[1..argc) for command ("render" or "trace-render"; the latter
 * always ray traces).  CLI_OK, or CLI_USAGE after printing one line. */
int render_request_parse(const char *command, int argc, char **argv, int trace_only,
                         render_request *r);

/* True when the option was given. */
int render_request_has(const render_request *r, render_option option);

/* The spelling of an option, for messages ("--no-shadows"). */
const char *render_option_name(render_option option);

#endif
