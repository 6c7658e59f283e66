/* `cg trace-render`: the ray tracer's own command.  It takes the options of
 * `cg render` (into a cg_render_options, as cmd_render.c does) plus the ray
 * tracer's (--spp, --depth, --stats, --no-shadows, --floor, --scene), and
 * renders through the same hook as `cg render --algorithm raytrace`
 * (render_raytrace.h), extended here with those extra settings. */
#ifndef CG_TOOL_TRACE_COMMAND_H
#define CG_TOOL_TRACE_COMMAND_H

#include "render_options.h"
#include "render_raytrace.h"
#include "cg/render.h"

/* What the ray tracer adds to cg_render_options. */
typedef struct raytrace_extra {
    int samples;       /* --spp: samples per pixel (1: pixel centres) */
    int depth;         /* --depth: reflection/refraction recursion limit */
    int shadows;       /* 0 with --no-shadows */
    int floor;         /* --floor: a checkered floor under the mesh, and a sky */
    int classic_scene; /* --scene spheres instead of a mesh */
} raytrace_extra;

void raytrace_extra_default(raytrace_extra *extra);

/* Prepares the ray tracer (render_raytrace.h) with the extra settings; mesh is ignored (may be
 * NULL) for the classic scene. */
int render_raytrace_create_extra(const cg_mesh *mesh, const cg_render_options *options,
                                 const raytrace_extra *extra, render_raytracer **out);
/* BVH build time, and the rays and time of the last frame. */
void render_raytrace_stats(const render_raytracer *tracer, double *build_seconds,
                           unsigned long long *rays, double *render_seconds);

/* Everything the ray tracer is asked to do on a mesh or the classic scene
 * (`cg render --algorithm raytrace` and `cg trace-render`; render_request.h
 * parses the command line, scene files go to render_scene.h). */
typedef struct raytrace_settings {
    const char *input;         /* mesh file, or NULL with extra.classic_scene */
    render_cli_options common; /* the options `cg render` shares (render_options.h) */
    int stats;                 /* --stats */
    int quiet;                 /* --quiet: no progress */
    /* Which settings the command line gave (a scene file keeps its own
     * for the others). */
    int have_samples, have_depth;
    /* --view-from: the direction from the target toward a framed camera
     * (default 0,0,1; render_request.c parses it). */
    cg_vec3 view_from;
    int have_view_from;
    raytrace_extra extra;
} raytrace_settings;

void raytrace_settings_default(raytrace_settings *s);
/* Renders into a new RGBA8 image (s->repeat times when > 0, printing
 * "frame: 12.3 ms"); returns an exit status. */
int raytrace_render(const char *command, const raytrace_settings *s, cg_image **out);
/* raytrace_render, then writes s->common.output. */
int raytrace_run(const char *command, const raytrace_settings *s);

#endif
