/* What `cg render --algorithm pathtrace` renders: a mesh (grey Lambert,
 * framed as cg render frames it) or a scene file (its objects, materials,
 * lights, camera and "environment"), the picture size, the sky, and the
 * render key that part files carry. */
#ifndef CG_TOOL_PATHTRACE_INPUT_H
#define CG_TOOL_PATHTRACE_INPUT_H

#include "options.h"
#include "cg/pathtrace.h"

#include <stdint.h>

/* The sky the command line asks for; each part overrides the scene's. */
typedef struct pathtrace_sky {
    const char *file; /* --environment, or NULL */
    cg_vec3 color;    /* --environment-color when color_given */
    double intensity; /* --environment-intensity when intensity_given */
    int color_given, intensity_given;
} pathtrace_sky;

typedef struct pathtrace_input {
    cg_trace_scene *scene;
    cg_camera camera;
    int width, height;            /* --size, or a scene file's image size */
    cg_vec3 environment;          /* the uniform sky when there is no map */
    cg_image *environment_map;    /* linear light, or NULL */
    double environment_intensity; /* scales the map */
    uint64_t key;                 /* digest of the input, size and sky (cg_path_part.render_key) */
} pathtrace_input;

/* Loads path; size is --size (used for a scene only when size_given).  The
 * error names the file; the usage problems (an intensity with no map to
 * scale) come back as CG_EINVAL. */
cg_status pathtrace_input_load(const char *path, cli_size size, int size_given,
                               const pathtrace_sky *sky, pathtrace_input *in, cg_error *err);
void pathtrace_input_free(pathtrace_input *in);

#endif
