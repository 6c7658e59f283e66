/* The dispatch point of `cg render --algorithm raytrace`.
 *
 * cmd_render.c parses the options, loads the mesh, fixes the camera (framed
 * to the mesh unless --eye was given; options->frame_camera is then 0) and
 * calls these three functions; render_raytrace.c implements them with the
 * ray tracer (module trace).  Until the ray tracer is built in, create
 * reports that the algorithm is not available. */
#ifndef CG_TOOL_RENDER_RAYTRACE_H
#define CG_TOOL_RENDER_RAYTRACE_H

#include "cg/mesh.h"
#include "cg/render.h"

typedef struct render_raytracer render_raytracer;

/* Prepares mesh (an acceleration structure, normals...) for tracing with the
 * camera, lights (options->lights, or the default key light when
 * light_count is 0), ambient, specular, shininess, colours, shading, culling
 * and thread count of options.  Returns CLI_OK, or prints one line
 * ("cg: render: ...") and returns CLI_FAILED. */
int render_raytrace_create(const cg_mesh *mesh, const cg_render_options *options,
                           render_raytracer **out);
/* Renders one frame into image (RGBA8, the --size of the command); may be
 * called many times (--repeat).  Returns CLI_OK or prints and returns
 * CLI_FAILED. */
int render_raytrace_draw(render_raytracer *tracer, cg_image *image);
void render_raytrace_free(render_raytracer *tracer);

#endif
