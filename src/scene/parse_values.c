/* The value readers of the scene parser: numbers, whole numbers, booleans,
 * vectors, colours and choices, each checked against its range, and the
 * messages that name the JSON path and what was expected (parse.h). */
#include "parse.h"
#include "../core/array.h"
#include "cg/color.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

cg_status scene_fail(const scene_parser *p, const char *path, const char *format, ...)
{
    char message[400];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    return cg_error_set(p->err, CG_EFORMAT, "%s: %s: %s", p->name, path, message);
}

/* A short description of a JSON value for "got ..." in messages. */
static void describe(const cJSON *v, char *out, size_t size)
{
    if (!v)
        snprintf(out, size, "nothing");
    else if (cJSON_IsString(v))
        snprintf(out, size, "\"%.40s%s\"", v->valuestring,
                 strlen(v->valuestring) > 40 ? "..." : "");
    else if (cJSON_IsNumber(v))
        snprintf(out, size, "%.17g", v->valuedouble);
    else if (cJSON_IsBool(v))
        snprintf(out, size, "%s", cJSON_IsTrue(v) ? "true" : "false");
    else if (cJSON_IsNull(v))
        snprintf(out, size, "null");
    else if (cJSON_IsArray(v))
        snprintf(out, size, "an array of %d", cJSON_GetArraySize(v));
    else
        snprintf(out, size, "an object");
}

cg_status scene_expected(const scene_parser *p, const char *path, const char *what, const cJSON *v)
{
    char got[64];
    describe(v, got, sizeof got);
    return scene_fail(p, path, "expected %s, got %s", what, got);
}

void scene_path_format(char *out, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(out, SCENE_PATH_SIZE, format, args);
    va_end(args);
}

/* path.key, or key at the top level. */
void scene_path_join(char *out, const char *path, const char *key)
{
    scene_path_format(out, "%s%s%s", path, path[0] ? "." : "", key);
}

/* obj[key], or NULL when absent; key_path receives path.key. */
static const cJSON *member(const cJSON *obj, const char *path, const char *key, char *key_path)
{
    scene_path_join(key_path, path, key);
    return cJSON_GetObjectItemCaseSensitive(obj, key);
}

/* Every key of obj must be one of allowed (NULL-terminated). */
cg_status scene_check_keys(const scene_parser *p, const char *path, const cJSON *obj,
                           const char *const *allowed)
{
    for (const cJSON *item = obj->child; item; item = item->next) {
        int known = 0;
        for (const char *const *a = allowed; *a; a++)
            if (strcmp(item->string, *a) == 0)
                known = 1;
        if (!known) {
            char list[200] = "", key_path[SCENE_PATH_SIZE];
            for (const char *const *a = allowed; *a; a++) {
                size_t used = strlen(list);
                snprintf(list + used, sizeof list - used, "%s%s", used ? ", " : "", *a);
            }
            scene_path_join(key_path, path, item->string);
            return scene_fail(p, key_path, "unknown key (expected one of: %s)", list);
        }
    }
    return CG_OK;
}

cg_status scene_need_object(const scene_parser *p, const char *path, const cJSON *v)
{
    return cJSON_IsObject(v) ? CG_OK : scene_expected(p, path, "an object", v);
}

/* Optional number in [min, max]: *out untouched when absent. */
cg_status scene_get_number(const scene_parser *p, const char *path, const cJSON *obj,
                           const char *key, double min, double max, double *out)
{
    char key_path[SCENE_PATH_SIZE], what[96];
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    if (!cJSON_IsNumber(v) || !(v->valuedouble >= min) || !(v->valuedouble <= max)) {
        snprintf(what, sizeof what, "a number between %g and %g", min, max);
        return scene_expected(p, key_path, what, v);
    }
    *out = v->valuedouble;
    return CG_OK;
}

cg_status scene_get_int(const scene_parser *p, const char *path, const cJSON *obj, const char *key,
                        int min, int max, int *out)
{
    char key_path[SCENE_PATH_SIZE], what[96];
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    if (!cJSON_IsNumber(v) || !(v->valuedouble >= min) || !(v->valuedouble <= max)
        || v->valuedouble != (double)(int)v->valuedouble) {
        snprintf(what, sizeof what, "a whole number between %d and %d", min, max);
        return scene_expected(p, key_path, what, v);
    }
    *out = (int)v->valuedouble;
    return CG_OK;
}

cg_status scene_get_bool(const scene_parser *p, const char *path, const cJSON *obj, const char *key,
                         int *out)
{
    char key_path[SCENE_PATH_SIZE];
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    if (!cJSON_IsBool(v))
        return scene_expected(p, key_path, "true or false", v);
    *out = cJSON_IsTrue(v);
    return CG_OK;
}

/* An array of n finite numbers at v. */
cg_status scene_read_numbers(const scene_parser *p, const char *path, const cJSON *v, int n,
                             double *out)
{
    char what[64];
    snprintf(what, sizeof what, "an array of %d numbers", n);
    if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != n)
        return scene_expected(p, path, what, v);
    int i = 0;
    for (const cJSON *item = v->child; item; item = item->next, i++) {
        if (!cJSON_IsNumber(item) || !isfinite(item->valuedouble)) {
            char item_path[SCENE_PATH_SIZE];
            scene_path_format(item_path, "%s[%d]", path, i);
            return scene_expected(p, item_path, "a finite number", item);
        }
        out[i] = item->valuedouble;
    }
    return CG_OK;
}

cg_status scene_get_vec3(const scene_parser *p, const char *path, const cJSON *obj, const char *key,
                         cg_vec3 *out)
{
    char key_path[SCENE_PATH_SIZE];
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    double xyz[3];
    cg_status s = scene_read_numbers(p, key_path, v, 3, xyz);
    if (s == CG_OK)
        *out = cg_vec3_make(xyz[0], xyz[1], xyz[2]);
    return s;
}

/* A colour: "#rrggbb" or a name (sRGB, decoded to linear light), or an
 * array [r, g, b] of linear values >= 0. */
cg_status scene_get_color(const scene_parser *p, const char *path, const cJSON *obj,
                          const char *key, cg_vec3 *out)
{
    char key_path[SCENE_PATH_SIZE];
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    if (cJSON_IsString(v)) {
        cg_rgba8 encoded;
        cg_error parse_error;
        if (cg_color_parse(v->valuestring, &encoded, &parse_error) != CG_OK)
            return scene_fail(p, key_path, "%s", parse_error.message);
        cg_rgbaf linear = cg_rgba8_to_linear(encoded);
        *out = cg_vec3_make(linear.r, linear.g, linear.b);
        return CG_OK;
    }
    double rgb[3];
    if (!cJSON_IsArray(v))
        return scene_expected(p, key_path,
                              "a colour (\"#rrggbb\", a name, or [r, g, b] in linear light)", v);
    cg_status s = scene_read_numbers(p, key_path, v, 3, rgb);
    if (s != CG_OK)
        return s;
    if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0)
        return scene_expected(p, key_path, "colour components >= 0", v);
    *out = cg_vec3_make(rgb[0], rgb[1], rgb[2]);
    return CG_OK;
}

/* One of names (NULL-terminated); *out gets its index. */
cg_status scene_get_choice(const scene_parser *p, const char *path, const cJSON *obj,
                           const char *key, const char *const *names, int *out)
{
    char key_path[SCENE_PATH_SIZE], what[200] = "one of";
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    for (int i = 0; names[i]; i++) {
        if (cJSON_IsString(v) && strcmp(v->valuestring, names[i]) == 0) {
            *out = i;
            return CG_OK;
        }
        size_t used = strlen(what);
        snprintf(what + used, sizeof what - used, "%s \"%s\"", i ? "," : "", names[i]);
    }
    return scene_expected(p, key_path, what, v);
}

cg_status scene_reserve(const scene_parser *p, void **items, size_t *capacity, size_t count,
                        size_t item_size)
{
    if (core_array_reserve(items, capacity, count + 1, item_size) != CG_OK)
        return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
    return CG_OK;
}
