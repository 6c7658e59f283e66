/* glTF cameras and KHR_lights_punctual lights: checked against the
 * specification's rules (cg_mesh does not carry them; the notes count them).
 *
 *   perspective:  yfov > 0, znear > 0, zfar > znear when given, aspectRatio > 0
 *   orthographic: xmag != 0, ymag != 0, zfar > znear >= 0
 *   light:        type directional | point | spot, color in [0, 1]^3,
 *                 intensity >= 0, range > 0, 0 <= innerConeAngle <
 *                 outerConeAngle <= pi / 2 */
#include "gltf_internal.h"

#include <stdio.h>

static cg_status fail_at(gltf_document *doc, const char *path, const char *what)
{
    return cg_error_set(doc->err, CG_EFORMAT, "%s: %s: expected %s", doc->name, path, what);
}

static cg_status check_camera(gltf_document *doc, size_t index)
{
    const cJSON *camera = doc->cameras.items[index];
    char path[48], sub[80];
    snprintf(path, sizeof path, "cameras[%zu]", index);
    const char *type;
    const cJSON *perspective, *orthographic;
    cg_status s = gltf_get_string(doc, camera, path, "type", 1, &type);
    if (s == CG_OK)
        s = gltf_get_object(doc, camera, path, "perspective", 0, &perspective);
    if (s == CG_OK)
        s = gltf_get_object(doc, camera, path, "orthographic", 0, &orthographic);
    if (s != CG_OK)
        return s;
    double znear, zfar, a, b;
    if (strcmp(type, "perspective") == 0) {
        snprintf(sub, sizeof sub, "%s.perspective", path);
        if (!perspective || orthographic)
            return fail_at(doc, path, "a perspective object (and no orthographic one)");
        if ((s = gltf_get_number(doc, perspective, sub, "yfov", -1, &a)) != CG_OK
            || (s = gltf_get_number(doc, perspective, sub, "znear", -1, &znear)) != CG_OK
            || (s = gltf_get_number(doc, perspective, sub, "zfar", INFINITY, &zfar)) != CG_OK
            || (s = gltf_get_number(doc, perspective, sub, "aspectRatio", 1, &b)) != CG_OK)
            return s;
        if (!(a > 0))
            return fail_at(doc, sub, "yfov: a field of view > 0 (radians)");
        if (!(znear > 0))
            return fail_at(doc, sub, "znear > 0");
        if (!(zfar > znear))
            return fail_at(doc, sub, "zfar > znear");
        if (!(b > 0))
            return fail_at(doc, sub, "aspectRatio > 0");
    } else if (strcmp(type, "orthographic") == 0) {
        snprintf(sub, sizeof sub, "%s.orthographic", path);
        if (!orthographic || perspective)
            return fail_at(doc, path, "an orthographic object (and no perspective one)");
        if ((s = gltf_get_number(doc, orthographic, sub, "xmag", 0, &a)) != CG_OK
            || (s = gltf_get_number(doc, orthographic, sub, "ymag", 0, &b)) != CG_OK
            || (s = gltf_get_number(doc, orthographic, sub, "znear", -1, &znear)) != CG_OK
            || (s = gltf_get_number(doc, orthographic, sub, "zfar", -1, &zfar)) != CG_OK)
            return s;
        if (a == 0 || b == 0)
            return fail_at(doc, sub, "xmag and ymag, not 0");
        if (!(znear >= 0) || !(zfar > znear))
            return fail_at(doc, sub, "znear >= 0 and zfar > znear");
    } else {
        return gltf_fail(doc, path, "type", "\"perspective\" or \"orthographic\"",
                         cJSON_GetObjectItemCaseSensitive(camera, "type"));
    }
    return CG_OK;
}

static cg_status check_light(gltf_document *doc, size_t index)
{
    const cJSON *light = doc->lights.items[index];
    char path[80];
    snprintf(path, sizeof path, "extensions.KHR_lights_punctual.lights[%zu]", index);
    const char *type;
    double color[3] = {1, 1, 1}, intensity, range;
    int present;
    cg_status s = gltf_get_string(doc, light, path, "type", 1, &type);
    if (s == CG_OK)
        s = gltf_get_numbers(doc, light, path, "color", 3, color, &present);
    if (s == CG_OK)
        s = gltf_get_number(doc, light, path, "intensity", 1, &intensity);
    if (s == CG_OK)
        s = gltf_get_number(doc, light, path, "range", INFINITY, &range);
    if (s != CG_OK)
        return s;
    for (int k = 0; k < 3; k++)
        if (color[k] < 0 || color[k] > 1)
            return fail_at(doc, path, "color: 3 numbers in [0, 1]");
    if (!(intensity >= 0))
        return fail_at(doc, path, "intensity >= 0");
    if (!(range > 0))
        return fail_at(doc, path, "range > 0");
    int spot = strcmp(type, "spot") == 0;
    if (!spot && strcmp(type, "point") != 0 && strcmp(type, "directional") != 0)
        return gltf_fail(doc, path, "type", "\"directional\", \"point\" or \"spot\"",
                         cJSON_GetObjectItemCaseSensitive(light, "type"));
    const cJSON *cone;
    if ((s = gltf_get_object(doc, light, path, "spot", spot, &cone)) != CG_OK)
        return s;
    if (spot) {
        char sub[96];
        snprintf(sub, sizeof sub, "%s.spot", path);
        double inner, outer;
        if ((s = gltf_get_number(doc, cone, sub, "innerConeAngle", 0, &inner)) != CG_OK
            || (s = gltf_get_number(doc, cone, sub, "outerConeAngle", M_PI / 4, &outer)) != CG_OK)
            return s;
        if (!(inner >= 0 && inner < outer && outer <= M_PI / 2))
            return fail_at(doc, sub, "0 <= innerConeAngle < outerConeAngle <= pi/2");
    }
    return CG_OK;
}

cg_status gltf_check_cameras_and_lights(gltf_document *doc)
{
    for (size_t i = 0; i < doc->cameras.count; i++) {
        cg_status s = check_camera(doc, i);
        if (s != CG_OK)
            return s;
    }
    for (size_t i = 0; i < doc->lights.count; i++) {
        cg_status s = check_light(doc, i);
        if (s != CG_OK)
            return s;
    }
    return CG_OK;
}
