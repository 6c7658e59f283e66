/* What `cg render` and its alias `cg trace-render` are asked to do: one
 * parser for every option of the two commands, and the checks that an option
 * means something for the chosen algorithm and input (a mesh or a scene file).
 * render_command.c acts on the result. */
#ifndef CG_TOOL_RENDER_REQUEST_H
#define CG_TOOL_RENDER_REQUEST_H

#include "trace_command.h"

/* --algorithm, in the order of its choices. */
typedef enum render_algorithm {
    RENDER_ZBUFFER = 0,
    RENDER_PAINTER,
    RENDER_RAYTRACE,
    RENDER_DEPTH_SORT
} render_algorithm;

/* Options that only some inputs or algorithms use, by the name the user
 * typed them with (for messages); bit i of render_request.given. */
typedef enum render_option {
    OPT_ALGORITHM, OPT_EYE, OPT_TARGET, OPT_UP, OPT_FOV, OPT_ORTHO, OPT_VIEW_FROM,
    OPT_LIGHT_DIR, OPT_AMBIENT, OPT_SPECULAR, OPT_SHININESS, OPT_COLOR, OPT_BACKGROUND,
    OPT_EDGE_COLOR, OPT_CREASE, OPT_CULL, OPT_WIREFRAME, OPT_HIDDEN_LINE, OPT_EDGES,
    OPT_OUTPUT_DEPTH, OPT_SPP, OPT_DEPTH, OPT_STATS, OPT_NO_SHADOWS, OPT_FLOOR, OPT_SCENE,
    OPT_QUIET, OPT_COUNT
} render_option;

typedef struct render_request {
    /* The input, the options `cg render` shares with the ray tracer and the
     * ray tracer's own (--spp, --depth, --stats, --no-shadows, --floor,
     * --scene, --quiet). */
    raytrace_settings trace;
    render_algorithm algorithm;
    double crease_degrees;  /* --crease (default 60) */
    int output_depth;       /* --output-depth */
    unsigned long given;    /* bit render_option: the option was on the command line */
} render_request;

/* Parses argv[1..argc) for command ("render" or "trace-render"; the latter
 * always ray traces).  CLI_OK, or CLI_USAGE after printing one line. */
int render_request_parse(const char *command, int argc, char **argv, int trace_only,
                         render_request *r);

/* True when the option was given. */
int render_request_has(const render_request *r, render_option option);

/* The spelling of an option, for messages ("--no-shadows"). */
const char *render_option_name(render_option option);

#endif
