/* The scene parser's shared pieces: the parser state, the value readers
 * (parse_values.c) and one reader per part of the scene format:
 *
 *   parse.c            the top level, cg_scene_parse, cg_scene_load
 *   parse_render.c     "image" and "render"
 *   parse_camera.c     "camera"
 *   parse_lights.c     "lights"
 *   parse_materials.c  "materials"
 *   parse_objects.c    "objects" and "overlays"
 *   parse_transform.c  an object's "transform"
 *   parse_environment.c "environment" (the path tracer's sky)
 *   parse_animation.c  "animation" (keyframes, animation.h)
 *
 * Every reader checks its keys (an unknown key is an error) and reports the
 * first problem as "file: json.path: expected ..., got ...". */
#ifndef CG_SCENE_PARSE_H
#define CG_SCENE_PARSE_H

#include "internal.h"

#include <cjson/cJSON.h>
#include <stddef.h>

/* The room allocated for each growing array of the scene being read (the
 * scene's counts say how much of it is used). */
typedef struct scene_capacities {
    size_t lights, area_lights, materials, objects, overlays;
} scene_capacities;

/* Everything a parsing function needs to report an error and grow the scene. */
typedef struct scene_parser {
    const char *name; /* file name for messages */
    cg_error *err;
    const char *base_dir; /* mesh paths are relative to it (NULL: current folder) */
    int load_meshes;      /* 0: check mesh entries but read no files */
    scene_capacities *capacity;
} scene_parser;

/* The size of a buffer holding a JSON path such as "objects[3].transform[0]". */
#define SCENE_PATH_SIZE 256

#if defined(__GNUC__)
#define SCENE_PRINTF(format_index, first_arg) \
    __attribute__((format(printf, format_index, first_arg)))
#else
#define SCENE_PRINTF(format_index, first_arg)
#endif

/* CG_EFORMAT with "name: path: message". */
cg_status scene_fail(const scene_parser *p, const char *path, const char *format, ...)
    SCENE_PRINTF(3, 4);
/* CG_EFORMAT with "name: path: expected what, got <a description of v>". */
cg_status scene_expected(const scene_parser *p, const char *path, const char *what, const cJSON *v);

/* Writes a JSON path into out (SCENE_PATH_SIZE bytes), cut short if too long. */
void scene_path_format(char *out, const char *format, ...) SCENE_PRINTF(2, 3);
/* path.key, or key at the top level. */
void scene_path_join(char *out, const char *path, const char *key);

/* Every key of obj must be one of allowed (NULL-terminated). */
cg_status scene_check_keys(const scene_parser *p, const char *path, const cJSON *obj,
                           const char *const *allowed);
cg_status scene_need_object(const scene_parser *p, const char *path, const cJSON *v);

/* The readers of obj[key]: each leaves *out untouched when the key is absent
 * and fails naming path.key when the value is not what is expected. */
/* A number in [min, max]. */
cg_status scene_get_number(const scene_parser *p, const char *path, const cJSON *obj,
                           const char *key, double min, double max, double *out);
/* A whole number in [min, max]. */
cg_status scene_get_int(const scene_parser *p, const char *path, const cJSON *obj, const char *key,
                        int min, int max, int *out);
cg_status scene_get_bool(const scene_parser *p, const char *path, const cJSON *obj, const char *key,
                         int *out);
/* Three finite numbers. */
cg_status scene_get_vec3(const scene_parser *p, const char *path, const cJSON *obj, const char *key,
                         cg_vec3 *out);
/* A colour: "#rrggbb" or a name (sRGB, decoded to linear light), or an
 * array [r, g, b] of linear values >= 0. */
cg_status scene_get_color(const scene_parser *p, const char *path, const cJSON *obj,
                          const char *key, cg_vec3 *out);
/* One of names (NULL-terminated); *out gets its index. */
cg_status scene_get_choice(const scene_parser *p, const char *path, const cJSON *obj,
                           const char *key, const char *const *names, int *out);
/* An array of n finite numbers at v (path names v itself). */
cg_status scene_read_numbers(const scene_parser *p, const char *path, const cJSON *v, int n,
                             double *out);

/* Makes room for one more item in *items, a growing array of count items
 * in room for *capacity (src/core/array.h); out of memory is reported. */
cg_status scene_reserve(const scene_parser *p, void **items, size_t *capacity, size_t count,
                        size_t item_size);

/* The parts of the format.  The top-level ones take the value of their key;
 * the items of an array ("lights", "objects") take their path too. */
cg_status scene_parse_image(const scene_parser *p, const cJSON *v, cg_scene *s);
cg_status scene_parse_render(const scene_parser *p, const cJSON *v, cg_scene *s);
cg_status scene_parse_camera(const scene_parser *p, const cJSON *v, cg_scene *s);
cg_status scene_parse_materials(const scene_parser *p, const cJSON *v, cg_scene *s);
cg_status scene_parse_light(const scene_parser *p, const char *path, const cJSON *v, cg_scene *s);
cg_status scene_parse_object(const scene_parser *p, const char *path, const cJSON *v, cg_scene *s);
/* One line of a cg draw script. */
cg_status scene_parse_overlay(const scene_parser *p, const char *path, const cJSON *v, cg_scene *s);
cg_status scene_parse_environment(const scene_parser *p, const cJSON *v, cg_scene *s);
/* After the objects and lights: root is the file's top level. */
cg_status scene_parse_animation(const scene_parser *p, const cJSON *root, const cJSON *v,
                                cg_scene *s);
/* file joined to base_dir unless absolute (malloc'ed; NULL when out of memory). */
char *scene_resolve_path(const char *base_dir, const char *file);
/* A transform list, composed into *out. */
cg_status scene_parse_transform(const scene_parser *p, const char *path, const cJSON *v,
                                cg_mat4 *out);

#endif
