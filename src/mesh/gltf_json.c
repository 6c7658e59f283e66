/* Typed access to a glTF file's JSON: every getter checks the JSON type and
 * range of one member and fails with a message naming its path and what the
 * glTF 2.0 specification expects there. */
#include "gltf_internal.h"

#include <float.h>
#include <stdio.h>
#include <stdlib.h>

cg_status gltf_out_of_memory(gltf_document *doc)
{
    return cg_error_set(doc->err, CG_ENOMEM, "%s: out of memory", doc->name);
}

const char *gltf_describe(const cJSON *value, char buffer[48])
{
    if (!value)
        return "nothing";
    if (cJSON_IsNumber(value)) {
        snprintf(buffer, 48, "the number %.10g", value->valuedouble);
        return buffer;
    }
    if (cJSON_IsString(value)) {
        const char *s = value->valuestring;
        size_t n = strlen(s);
        snprintf(buffer, 48, "the string \"%.24s%s\"", s, n > 24 ? "..." : "");
        for (char *c = buffer; *c; c++)
            if ((unsigned char)*c < 32 || (unsigned char)*c > 126)
                *c = '?';
        return buffer;
    }
    if (cJSON_IsBool(value))
        return cJSON_IsTrue(value) ? "true" : "false";
    if (cJSON_IsNull(value))
        return "null";
    if (cJSON_IsArray(value))
        return "an array";
    if (cJSON_IsObject(value))
        return "an object";
    return "an unknown value";
}

cg_status gltf_fail(gltf_document *doc, const char *path, const char *key, const char *expected,
                    const cJSON *got)
{
    char buffer[48];
    return cg_error_set(doc->err, CG_EFORMAT, "%s: %s%s%s: expected %s, got %s", doc->name, path,
                        key && *path ? "." : "", key ? key : "", expected,
                        gltf_describe(got, buffer));
}

static const cJSON *member(const cJSON *object, const char *key)
{
    return object ? cJSON_GetObjectItemCaseSensitive(object, key) : NULL;
}

cg_status gltf_get_integer(gltf_document *doc, const cJSON *object, const char *path,
                           const char *key, int required, int64_t fallback, int64_t minimum,
                           int64_t maximum, int64_t *out)
{
    const cJSON *value = member(object, key);
    if (!value && !required) {
        *out = fallback;
        return CG_OK;
    }
    double d = value && cJSON_IsNumber(value) ? value->valuedouble : 0;
    if (!value || !cJSON_IsNumber(value) || d != floor(d) || d < (double)minimum
        || d > (double)maximum) {
        char expected[96];
        if (maximum >= ((int64_t)1 << 53))
            snprintf(expected, sizeof expected, "an integer >= %lld", (long long)minimum);
        else
            snprintf(expected, sizeof expected, "an integer in [%lld, %lld]", (long long)minimum,
                     (long long)maximum);
        return gltf_fail(doc, path, key, expected, value);
    }
    *out = (int64_t)d;
    return CG_OK;
}

cg_status gltf_get_index(gltf_document *doc, const cJSON *object, const char *path, const char *key,
                         int required, const gltf_list *list, const char *list_name, size_t *out)
{
    const cJSON *value = member(object, key);
    if (!value && !required) {
        *out = SIZE_MAX;
        return CG_OK;
    }
    double d = value && cJSON_IsNumber(value) ? value->valuedouble : -1;
    if (!value || !cJSON_IsNumber(value) || d != floor(d) || d < 0 || d >= (double)list->count) {
        char expected[96];
        if (list->count == 0)
            snprintf(expected, sizeof expected, "an index into %s, but the file has none",
                     list_name);
        else
            snprintf(expected, sizeof expected, "an index into %s (0 to %zu)", list_name,
                     list->count - 1);
        return gltf_fail(doc, path, key, expected, value);
    }
    *out = (size_t)d;
    return CG_OK;
}

cg_status gltf_get_number(gltf_document *doc, const cJSON *object, const char *path,
                          const char *key, double fallback, double *out)
{
    const cJSON *value = member(object, key);
    if (!value) {
        *out = fallback;
        return CG_OK;
    }
    if (!cJSON_IsNumber(value) || !isfinite(value->valuedouble))
        return gltf_fail(doc, path, key, "a finite number", value);
    *out = value->valuedouble;
    return CG_OK;
}

cg_status gltf_get_bool(gltf_document *doc, const cJSON *object, const char *path, const char *key,
                        int fallback, int *out)
{
    const cJSON *value = member(object, key);
    if (!value) {
        *out = fallback;
        return CG_OK;
    }
    if (!cJSON_IsBool(value))
        return gltf_fail(doc, path, key, "true or false", value);
    *out = cJSON_IsTrue(value);
    return CG_OK;
}

cg_status gltf_get_string(gltf_document *doc, const cJSON *object, const char *path,
                          const char *key, int required, const char **out)
{
    const cJSON *value = member(object, key);
    *out = NULL;
    if (!value && !required)
        return CG_OK;
    if (!value || !cJSON_IsString(value))
        return gltf_fail(doc, path, key, "a string", value);
    *out = value->valuestring;
    return CG_OK;
}

cg_status gltf_get_object(gltf_document *doc, const cJSON *object, const char *path,
                          const char *key, int required, const cJSON **out)
{
    const cJSON *value = member(object, key);
    *out = NULL;
    if (!value && !required)
        return CG_OK;
    if (!value || !cJSON_IsObject(value))
        return gltf_fail(doc, path, key, "an object", value);
    *out = value;
    return CG_OK;
}

cg_status gltf_get_numbers(gltf_document *doc, const cJSON *object, const char *path,
                           const char *key, size_t count, double *values, int *present)
{
    const cJSON *value = member(object, key);
    *present = 0;
    if (!value)
        return CG_OK;
    char expected[64];
    snprintf(expected, sizeof expected, count ? "an array of %zu numbers" : "an array of numbers",
             count);
    if (!cJSON_IsArray(value))
        return gltf_fail(doc, path, key, expected, value);
    size_t n = 0;
    for (const cJSON *item = value->child; item; item = item->next, n++) {
        if (!cJSON_IsNumber(item) || !isfinite(item->valuedouble) || (count && n >= count)) {
            char item_path[160];
            snprintf(item_path, sizeof item_path, "%s%s%s[%zu]", path, *path ? "." : "", key, n);
            return gltf_fail(doc, item_path, NULL,
                             count && n >= count ? "the end of the array" : "a finite number",
                             item);
        }
        if (values && (!count || n < count))
            values[n] = item->valuedouble;
    }
    if ((count && n != count) || n == 0)
        return gltf_fail(doc, path, key, expected, value);
    *present = 1;
    return CG_OK;
}

void gltf_list_free(gltf_list *list)
{
    free(list->items);
    list->items = NULL;
    list->count = 0;
}

cg_status gltf_get_list(gltf_document *doc, const cJSON *object, const char *path, const char *key,
                        size_t minimum, gltf_list *out)
{
    out->items = NULL;
    out->count = 0;
    const cJSON *value = member(object, key);
    if (!value)
        return CG_OK;
    char expected[64];
    snprintf(expected, sizeof expected, "an array of at least %zu item%s", minimum,
             minimum == 1 ? "" : "s");
    if (!cJSON_IsArray(value))
        return gltf_fail(doc, path, key, expected, value);
    size_t n = 0;
    for (const cJSON *item = value->child; item; item = item->next)
        n++;
    if (n < minimum)
        return gltf_fail(doc, path, key, expected, value);
    if (n && !(out->items = malloc(n * sizeof *out->items)))
        return gltf_out_of_memory(doc);
    n = 0;
    for (cJSON *item = value->child; item; item = item->next)
        out->items[n++] = item;
    out->count = n;
    return CG_OK;
}

cg_status gltf_check_objects(gltf_document *doc, const gltf_list *list, const char *name)
{
    for (size_t i = 0; i < list->count; i++)
        if (!cJSON_IsObject(list->items[i])) {
            char path[96];
            snprintf(path, sizeof path, "%s[%zu]", name, i);
            return gltf_fail(doc, path, NULL, "an object", list->items[i]);
        }
    return CG_OK;
}

cg_status gltf_get_object_list(gltf_document *doc, const cJSON *object, const char *path,
                               const char *key, gltf_list *out)
{
    cg_status s = gltf_get_list(doc, object, path, key, 1, out);
    if (s == CG_OK)
        s = gltf_check_objects(doc, out, key);
    if (s != CG_OK)
        gltf_list_free(out);
    return s;
}
