/* `cg render SCENE.json`: scene files through the cg tool. */
#ifndef CG_TOOL_RENDER_SCENE_H
#define CG_TOOL_RENDER_SCENE_H

/* Command-line settings that take precedence over the scene file's; a
 * negative value (or 0 for sizes) leaves the scene's. */
typedef struct render_scene_overrides {
    int algorithm;     /* 0 zbuffer, 1 painter, 2 raytrace */
    int shading;       /* 0 flat, 1 gouraud, 2 phong */
    int width, height; /* --size */
    int threads;
    int samples;       /* --spp */
    int depth;         /* --depth */
    int repeat;        /* --repeat N: time N frames, print the median */
} render_scene_overrides;

/* Nothing overridden. */
render_scene_overrides render_scene_no_overrides(void);

/* True when an option named name appears in argv (alone or as name=...). */
int render_scene_option_given(int argc, char **argv, const char *name);

/* True when path names a scene file (ends in .json). */
int render_scene_is_scene(const char *path);

/* Loads the scene, renders it (with the overrides), draws its overlays with
 * the cg draw interpreter and writes out_path.  Returns the exit status after
 * printing any error; nothing is written on failure. */
int render_scene_file(const char *path, const char *out_path, const render_scene_overrides *o);

#endif
