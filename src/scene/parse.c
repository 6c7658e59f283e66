/* Reading scene files: JSON (parsed by cJSON) checked key by key, with
 * errors that name the JSON path and what was expected.  This file reads the
 * top level and hands each part to its reader (parse.h). */
#include "parse.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef cg_status (*item_parser)(const scene_parser *p, const char *path, const cJSON *v,
                                 cg_scene *s);

/* Reads the array root[key] (when present) of at most limit items, each with
 * parse_item, naming them key[0], key[1], ... in messages. */
static cg_status parse_array(const scene_parser *p, const cJSON *root, const char *key, int limit,
                             item_parser parse_item, cg_scene *s)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(root, key);
    if (!v)
        return CG_OK;
    if (!cJSON_IsArray(v))
        return scene_expected(p, key, "an array", v);
    if (cJSON_GetArraySize(v) > limit)
        return scene_fail(p, key, "%d entries, more than the limit of %d", cJSON_GetArraySize(v),
                          limit);
    int i = 0;
    for (const cJSON *item = v->child; item; item = item->next, i++) {
        char path[SCENE_PATH_SIZE];
        scene_path_format(path, "%s[%d]", key, i);
        cg_status st = parse_item(p, path, item, s);
        if (st)
            return st;
    }
    return CG_OK;
}

static cg_status parse_scene(const scene_parser *p, const cJSON *root, cg_scene *s)
{
    static const char *const keys[] = {"comment",     "image",     "camera",  "render",
                                       "lights",      "materials", "objects", "overlays",
                                       "environment", "animation", NULL};
    cg_status st;
    if (!cJSON_IsObject(root))
        return cg_error_set(p->err, CG_EFORMAT, "%s: expected a JSON object at the top level",
                            p->name);
    if ((st = scene_check_keys(p, "", root, keys)))
        return st;
    const cJSON *v;
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "image")) && (st = scene_parse_image(p, v, s)))
        return st;
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "camera"))
        && (st = scene_parse_camera(p, v, s)))
        return st;
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "render"))
        && (st = scene_parse_render(p, v, s)))
        return st;
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "environment"))
        && (st = scene_parse_environment(p, v, s)))
        return st;
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "materials"))
        && (st = scene_parse_materials(p, v, s)))
        return st;
    if ((st = parse_array(p, root, "lights", CG_SCENE_MAX_LIGHTS, scene_parse_light, s))
        || (st = parse_array(p, root, "objects", CG_SCENE_MAX_OBJECTS, scene_parse_object, s))
        || (st = parse_array(p, root, "overlays", CG_SCENE_MAX_OVERLAYS, scene_parse_overlay, s)))
        return st;
    /* last: its keys name the objects and lights read above */
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "animation")))
        return scene_parse_animation(p, root, v, s);
    return CG_OK;
}

cg_status cg_scene_parse(const char *text, size_t size, const char *name, const char *base_dir,
                         int load_meshes, cg_scene **out, cg_error *err)
{
    if (!out)
        return cg_error_set(err, CG_EINVAL, "scene: no output given");
    *out = NULL;
    if (!name)
        name = "scene";
    if (!text || size == 0)
        return cg_error_set(err, CG_EFORMAT, "%s: empty scene file", name);
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithLengthOpts(text, size, &end, 0);
    if (!root) {
        /* cJSON reports where it stopped: turn that into a line and column. */
        size_t offset = end && end >= text && (size_t)(end - text) <= size ? (size_t)(end - text)
                                                                           : 0;
        int line = 1, column = 1;
        for (size_t i = 0; i < offset; i++) {
            if (text[i] == '\n') {
                line++;
                column = 1;
            } else {
                column++;
            }
        }
        return cg_error_set(err, CG_EFORMAT, "%s:%d:%d: malformed JSON", name, line, column);
    }
    cg_scene *scene;
    cg_status status = scene_create_empty(&scene);
    if (status != CG_OK) {
        cJSON_Delete(root);
        return cg_error_set(err, status, "%s: out of memory", name);
    }
    /* scene_create_empty gives the default material room of its own. */
    scene_capacities capacity = {.materials = 1};
    scene_parser p = {name, err, base_dir, load_meshes, &capacity};
    status = parse_scene(&p, root, scene);
    cJSON_Delete(root);
    if (status != CG_OK) {
        cg_scene_free(scene);
        return status;
    }
    *out = scene;
    return CG_OK;
}

cg_status cg_scene_load(const char *path, cg_scene **out, cg_error *err)
{
    if (!path || !out)
        return cg_error_set(err, CG_EINVAL, "scene: no path or output given");
    *out = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return cg_error_set(err, CG_EIO, "%s: cannot open: %s", path, strerror(errno));
    /* Scene files are small: anything over 64 MiB is refused before reading. */
    const long limit = 64L << 20;
    long size = -1;
    if (fseek(f, 0, SEEK_END) == 0)
        size = ftell(f);
    if (size < 0 || size > limit || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return cg_error_set(err, size > limit ? CG_ERANGE : CG_EIO,
                            size > limit ? "%s: larger than the 64 MiB limit for scene files"
                                         : "%s: cannot read",
                            path);
    }
    char *text = malloc((size_t)size + 1);
    size_t got = text ? fread(text, 1, (size_t)size, f) : 0;
    int failed = ferror(f) || got != (size_t)size;
    fclose(f);
    if (!text)
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    if (failed) {
        free(text);
        return cg_error_set(err, CG_EIO, "%s: read error", path);
    }
    char *base_dir = malloc(strlen(path) + 1);
    if (!base_dir) {
        free(text);
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    }
    strcpy(base_dir, path);
    char *slash = strrchr(base_dir, '/');
    if (slash)
        *slash = '\0';
    else
        base_dir[0] = '\0';
    cg_status status = cg_scene_parse(text, (size_t)size, path, base_dir, 1, out, err);
    free(base_dir);
    free(text);
    return status;
}
