/* The settings `cg render` and `cg trace-render` share (the command-line
 * contract of the rendering issue): output, size, camera, lights, ambient,
 * shading, threads, colours and --repeat, with their defaults; the table of
 * their options is render_request.c's, one for both commands. */
#ifndef CG_TOOL_RENDER_OPTIONS_H
#define CG_TOOL_RENDER_OPTIONS_H

#include "options.h"
#include "cg/render.h"

typedef struct render_cli_options {
    const char *output;      /* -o, --output */
    cli_size size;           /* --size (default 800x600) */
    cg_vec3 eye, target, up; /* --eye, --target, --up (default 0,1,0) */
    double fov_degrees;      /* --fov (default 45) */
    double ortho_height;     /* --ortho; > 0: parallel view (--fov resets it to 0) */
    double near, far;        /* --near, --far (default: the mesh's depth range) */
    int repeat;              /* --repeat N (0: one frame, no timing line) */
    /* Which of them the command line gave (render_request.c notes them). */
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

/* Sets the placed camera's near and far: the depth range of the box
 * [lo, hi] along its viewing direction (cg_camera_fit_depth) when bounded,
 * then --near and --far where given.  CLI_OK, or the usage error for
 * command when the two do not make a range (far <= near, or a perspective
 * near <= 0). */
int render_cli_set_depth(const char *command, const render_cli_options *o, int bounded, cg_vec3 lo,
                         cg_vec3 hi, cg_camera *camera);

/* CLI_OK when output names a file of a known image format, otherwise the
 * usage error (missing -o, unknown extension). */
int render_cli_check_output(const char *command, const char *output);

#endif
