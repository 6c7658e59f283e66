/* The options `cg render` and `cg trace-render` share (the command-line
 * contract of the rendering issue): output, size, camera, lights, ambient,
 * shading, threads, colours and --repeat, parsed in one place so that both
 * commands spell, default, check and report them the same way. */
#ifndef CG_TOOL_RENDER_OPTIONS_H
#define CG_TOOL_RENDER_OPTIONS_H

#include "cg/render.h"

typedef struct render_cli_options {
    const char *output;      /* -o, --output */
    int width, height;       /* --size (default 800x600) */
    cg_vec3 eye, target, up; /* --eye, --target, --up (default 0,1,0) */
    double fov_degrees;      /* --fov (default 45) */
    double ortho_height;     /* --ortho; > 0: parallel view (--fov resets it to 0) */
    double near, far;        /* --near, --far (default: the mesh's depth range) */
    int repeat;              /* --repeat N (0: one frame, no timing line) */
    /* Which of them the command line gave. */
    int have_size, have_eye, have_target, have_shading, have_threads, have_background;
    int have_near, have_far;
    /* Set by `cg trace-render`: a --light-dir beyond CG_RENDER_MAX_LIGHTS is
     * reported as "too many lights" before its direction is checked (`cg
     * render` checks the direction first and says "at most 8 lights"). */
    int lights_full_first;
    /* --light-dir (repeatable), --ambient, --shading, --threads,
     * --background, --color; frame_camera is 0. */
    cg_render_options render;
} render_cli_options;

void render_cli_options_default(render_cli_options *o);

/* Parses the option at argv[*i] (advancing *i past its value) if it is one
 * of the shared ones: 1 when consumed, 0 when not one of them, -1 after
 * printing a usage error for command. */
int render_cli_parse_option(const char *command, int argc, char **argv, int *i,
                            render_cli_options *o);

/* Sets the placed camera's near and far: the depth range of the box
 * [lo, hi] along its viewing direction (cg_camera_fit_depth) when bounded,
 * then --near and --far where given.  CLI_OK, or the usage error for
 * command when the two do not make a range (far <= near, or a perspective
 * near <= 0). */
int render_cli_set_depth(const char *command, const render_cli_options *o, int bounded,
                         cg_vec3 lo, cg_vec3 hi, cg_camera *camera);

/* text as an index into names[0..count): 0, or -1 after printing
 * "WHAT: expected A, B or C, got 'TEXT'". */
int render_cli_parse_choice(const char *command, const char *what, const char *text,
                            const char *const *names, int count, int *out);

/* CLI_OK when output names a file of a known image format, otherwise the
 * usage error (missing -o, unknown extension). */
int render_cli_check_output(const char *command, const char *output);

#endif
