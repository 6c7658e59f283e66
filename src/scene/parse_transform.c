/* An object's "transform": a list of steps (translate, scale, rotate,
 * reflect, shear, matrix) composed in the order listed. */
#include "parse.h"

#include <cjson/cJSON.h>
#include <math.h>

/* One step of a transform list: {"translate": [x, y, z]}, {"scale": s or
 * [sx, sy, sz], "center": [..]}, {"rotate": degrees, "axis": [..],
 * "point": [..]}, {"reflect": normal, "point": [..]}, {"shear": [xy, xz, yx,
 * yz, zx, zy]} or {"matrix": [16 numbers, row by row]}. */
static cg_status parse_step(const scene_parser *p, const char *path, const cJSON *v, cg_mat4 *out)
{
    static const char *const translate_keys[] = {"translate", NULL};
    static const char *const scale_keys[] = {"scale", "center", NULL};
    static const char *const rotate_keys[] = {"rotate", "axis", "point", NULL};
    static const char *const reflect_keys[] = {"reflect", "point", NULL};
    static const char *const shear_keys[] = {"shear", NULL};
    static const char *const matrix_keys[] = {"matrix", NULL};
    cg_status st;
    if ((st = scene_need_object(p, path, v)))
        return st;
    cg_vec3 center = {0, 0, 0};
    char key_path[SCENE_PATH_SIZE];
    const cJSON *x;
    if ((x = cJSON_GetObjectItemCaseSensitive(v, "translate"))) {
        cg_vec3 t = {0, 0, 0};
        if ((st = scene_check_keys(p, path, v, translate_keys))
            || (st = scene_get_vec3(p, path, v, "translate", &t)))
            return st;
        *out = cg_xform3_translate(t.x, t.y, t.z);
    } else if ((x = cJSON_GetObjectItemCaseSensitive(v, "scale"))) {
        cg_vec3 factors;
        if ((st = scene_check_keys(p, path, v, scale_keys))
            || (st = scene_get_vec3(p, path, v, "center", &center)))
            return st;
        scene_path_join(key_path, path, "scale");
        if (cJSON_IsNumber(x) && isfinite(x->valuedouble))
            factors = cg_vec3_make(x->valuedouble, x->valuedouble, x->valuedouble);
        else if ((st = scene_get_vec3(p, path, v, "scale", &factors)))
            return st;
        if (factors.x == 0 || factors.y == 0 || factors.z == 0)
            return scene_expected(p, key_path, "non-zero scale factors", x);
        *out = cg_xform3_scale(factors.x, factors.y, factors.z, center);
    } else if ((x = cJSON_GetObjectItemCaseSensitive(v, "rotate"))) {
        cg_vec3 axis = {0, 1, 0};
        double degrees = 0;
        if ((st = scene_check_keys(p, path, v, rotate_keys))
            || (st = scene_get_number(p, path, v, "rotate", -1e6, 1e6, &degrees))
            || (st = scene_get_vec3(p, path, v, "axis", &axis))
            || (st = scene_get_vec3(p, path, v, "point", &center)))
            return st;
        if (cg_xform3_rotate_axis(axis, cg_radians(degrees), center, out) != CG_OK)
            return scene_fail(p, path, "expected a non-zero rotation axis");
    } else if ((x = cJSON_GetObjectItemCaseSensitive(v, "reflect"))) {
        cg_vec3 normal = {0, 1, 0};
        if ((st = scene_check_keys(p, path, v, reflect_keys))
            || (st = scene_get_vec3(p, path, v, "reflect", &normal))
            || (st = scene_get_vec3(p, path, v, "point", &center)))
            return st;
        if (cg_xform3_reflect(center, normal, out) != CG_OK)
            return scene_fail(p, path, "expected a non-zero plane normal");
    } else if ((x = cJSON_GetObjectItemCaseSensitive(v, "shear"))) {
        double k[6];
        scene_path_join(key_path, path, "shear");
        if ((st = scene_check_keys(p, path, v, shear_keys))
            || (st = scene_read_numbers(p, key_path, x, 6, k)))
            return st;
        *out = cg_xform3_shear(k[0], k[1], k[2], k[3], k[4], k[5]);
    } else if ((x = cJSON_GetObjectItemCaseSensitive(v, "matrix"))) {
        double m[16];
        scene_path_join(key_path, path, "matrix");
        if ((st = scene_check_keys(p, path, v, matrix_keys))
            || (st = scene_read_numbers(p, key_path, x, 16, m)))
            return st;
        for (int i = 0; i < 16; i++)
            out->m[i / 4][i % 4] = m[i];
        cg_mat4 inverse;
        if (cg_mat4_inverse(*out, &inverse) != CG_OK)
            return scene_fail(p, key_path, "expected an invertible matrix");
    } else {
        return scene_expected(
            p, path, "a step with one of translate, scale, rotate, reflect, shear, matrix", v);
    }
    return CG_OK;
}

cg_status scene_parse_transform(const scene_parser *p, const char *path, const cJSON *v,
                                cg_mat4 *out)
{
    if (!cJSON_IsArray(v))
        return scene_expected(p, path, "an array of transformation steps", v);
    int n = cJSON_GetArraySize(v);
    if (n > CG_SCENE_MAX_TRANSFORMS)
        return scene_fail(p, path, "%d steps, more than the limit of %d", n,
                          CG_SCENE_MAX_TRANSFORMS);
    *out = cg_mat4_identity();
    int i = 0;
    for (const cJSON *item = v->child; item; item = item->next, i++) {
        char step_path[SCENE_PATH_SIZE];
        cg_mat4 step;
        scene_path_format(step_path, "%s[%d]", path, i);
        cg_status st = parse_step(p, step_path, item, &step);
        if (st)
            return st;
        *out = cg_mat4_mul(step, *out); /* the steps happen in the order listed */
    }
    return CG_OK;
}
