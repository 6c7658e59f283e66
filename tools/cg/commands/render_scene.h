/* `cg render SCENE.json` and `cg trace-render SCENE.json`: scene files
 * through the cg tool, with the command line's options applied to the scene
 * (render_scene_apply). */
#ifndef CG_TOOL_RENDER_SCENE_H
#define CG_TOOL_RENDER_SCENE_H

#include "cg/scene.h"

struct render_request;

/* True when path names a scene file (ends in .json). */
int render_scene_is_scene(const char *path);

/* Applies every option the request gave to the scene: size, algorithm,
 * shading, threads, culling, edges, background, the ray tracer's samples,
 * depth and shadows, the camera (--eye, --target, --up, --fov, --ortho,
 * --view-from override the scene's), --light-dir (in place of the scene's
 * lights other than ambient ones) and, for objects without a material,
 * --color, --ambient, --specular and --shininess.  CLI_OK, or CLI_USAGE
 * after printing one line. */
int render_scene_apply(const char *command, const struct render_request *r, cg_scene *scene);

/* Loads the scene r->trace.input, applies the request, renders it (repeat
 * times when asked), draws its overlays with the cg draw interpreter and
 * writes the output.  Returns the exit status after printing any error;
 * nothing is written on failure. */
int render_scene_file(const char *command, const struct render_request *r);

#endif
