/* The dispatch point of `cg render --algorithm raytrace`.
 *
 * render_request.c parses the options, raytrace_run.c loads the mesh, fixes
 * the camera (framed to the mesh unless --eye was given; options->frame_camera
 * is then 0) and calls render_raytrace_create_extra (raytrace_run.h) and the
 * two functions below; raytracer.c implements them with the ray tracer
 * (module trace). */
#ifndef CG_TOOL_RAYTRACER_H
#define CG_TOOL_RAYTRACER_H

#include "cg/mesh.h"
#include "cg/render.h"

typedef struct render_raytracer render_raytracer;

/* render_raytrace_create_extra prepares mesh (an acceleration structure,
 * normals...) for tracing with the camera, lights (options->lights, or the
 * default key light when light_count is 0), ambient, specular, shininess,
 * colours, shading, crease angle and thread count of options.  It returns
 * CLI_OK, or prints one line ("cg: render: ...") and returns CLI_FAILED. */
/* Renders one frame into image (RGBA8, the --size of the command); may be
 * called many times (--repeat).  Returns CLI_OK or prints and returns
 * CLI_FAILED. */
int render_raytrace_draw(render_raytracer *tracer, cg_image *image);
void render_raytrace_free(render_raytracer *tracer);

#endif
