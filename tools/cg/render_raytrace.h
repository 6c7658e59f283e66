/* The ray tracer behind `cg trace-render` (and `cg render --algorithm
 * raytrace`): the settings of the shared render contract plus the ray
 * tracer's own, an option parser both commands can call one option at a
 * time, and the runner. */
#ifndef CG_TOOL_RENDER_RAYTRACE_H
#define CG_TOOL_RENDER_RAYTRACE_H

#include "cg/image.h"
#include "cg/core.h"

enum { RAYTRACE_MAX_LIGHTS = 8 };

typedef struct raytrace_settings {
    const char *input;  /* mesh file, or NULL with scene set */
    const char *scene;  /* built-in scene name ("spheres"), or NULL */
    const char *output; /* -o */
    int width, height;  /* --size */
    cg_vec3 eye, target, up;
    int have_eye, have_target;
    int orthographic;   /* --ortho given */
    double fov_degrees, ortho_height;
    cg_vec3 light_dirs[RAYTRACE_MAX_LIGHTS]; /* toward the lights */
    int light_count;
    double ambient;
    int flat;           /* --shading flat (gouraud and phong interpolate normals) */
    int threads;
    cg_rgba8 background, color;
    int have_background;
    int repeat;
    int samples, depth; /* --spp, --depth */
    int stats;          /* --stats */
    int shadows;        /* --no-shadows clears it */
    int quiet;          /* --quiet: no progress */
    int floor;          /* --floor: a checkered floor under the mesh */
} raytrace_settings;

void raytrace_settings_default(raytrace_settings *s);

/* Parses the option at argv[*i] (advancing *i past its value) when it is one
 * of the settings above: returns 1 when consumed, 0 when not a ray-tracer
 * option, -1 after printing an error for a bad value. */
int raytrace_parse_option(const char *command, int argc, char **argv, int *i,
                          raytrace_settings *s);

/* Loads or builds the scene and renders it into a new image (settings.repeat
 * times when > 0, printing "frame: 12.3 ms"); returns an exit status. */
int raytrace_render(const char *command, const raytrace_settings *s, cg_image **out);

/* Loads or builds the scene, renders (settings.repeat times when > 0,
 * printing "frame: 12.3 ms"), writes settings.output; returns an exit status. */
int raytrace_run(const char *command, const raytrace_settings *s);

#endif
