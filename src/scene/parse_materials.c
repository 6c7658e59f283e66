/* The scene file's "materials": named surfaces (illumination coefficients,
 * reflectance, transmittance, a 3D checker) on top of the default material. */
#include "parse.h"

#include <cjson/cJSON.h>
#include <stdlib.h>
#include <string.h>

static cg_status parse_material(const scene_parser *p, const char *path, const cJSON *v,
                                cg_scene_material *m)
{
    static const char *const keys[] = {
        "color",       "specular_color", "ka",  "kd",      "ks",       "shininess", "specular",
        "reflectance", "transmittance",  "ior", "checker", "emission", NULL};
    static const char *const models[] = {"phong", "blinn", NULL};
    cg_material *s = &m->surface;
    int model = (int)s->specular;
    cg_status st;
    if ((st = scene_need_object(p, path, v)) || (st = scene_check_keys(p, path, v, keys))
        || (st = scene_get_color(p, path, v, "color", &s->color))
        || (st = scene_get_color(p, path, v, "specular_color", &s->specular_color))
        || (st = scene_get_number(p, path, v, "ka", 0, 1e3, &s->ka))
        || (st = scene_get_number(p, path, v, "kd", 0, 1e3, &s->kd))
        || (st = scene_get_number(p, path, v, "ks", 0, 1e3, &s->ks))
        || (st = scene_get_number(p, path, v, "shininess", 0, 1e5, &s->shininess))
        || (st = scene_get_choice(p, path, v, "specular", models, &model))
        || (st = scene_get_number(p, path, v, "reflectance", 0, 1, &s->reflectance))
        || (st = scene_get_number(p, path, v, "transmittance", 0, 1, &s->transmittance))
        || (st = scene_get_number(p, path, v, "ior", 0.01, 100, &s->refractive_index))
        || (st = scene_get_color(p, path, v, "emission", &m->emission)))
        return st;
    s->specular = (cg_specular_model)model;
    const cJSON *checker = cJSON_GetObjectItemCaseSensitive(v, "checker");
    if (checker) {
        static const char *const checker_keys[] = {"color", "size", NULL};
        char checker_path[SCENE_PATH_SIZE];
        scene_path_join(checker_path, path, "checker");
        m->checker_size = 1;
        m->checker_color = cg_vec3_make(0.1, 0.1, 0.1);
        if ((st = scene_need_object(p, checker_path, checker))
            || (st = scene_check_keys(p, checker_path, checker, checker_keys))
            || (st = scene_get_color(p, checker_path, checker, "color", &m->checker_color))
            || (st = scene_get_number(p, checker_path, checker, "size", 1e-9, 1e12,
                                      &m->checker_size)))
            return st;
    }
    return CG_OK;
}

cg_status scene_parse_materials(const scene_parser *p, const cJSON *v, cg_scene *s)
{
    cg_status st;
    if ((st = scene_need_object(p, "materials", v)))
        return st;
    for (const cJSON *item = v->child; item; item = item->next) {
        char path[SCENE_PATH_SIZE];
        scene_path_join(path, "materials", item->string);
        for (size_t i = 0; i < s->material_count; i++)
            if (s->materials[i].name && strcmp(s->materials[i].name, item->string) == 0)
                return scene_fail(p, path, "material defined twice");
        cg_scene_material m = scene_default_material();
        if ((st = parse_material(p, path, item, &m)))
            return st;
        if ((st = scene_reserve(p, (void **)&s->materials, &p->capacity->materials,
                                s->material_count, sizeof *s->materials)))
            return st;
        if (!(m.name = malloc(strlen(item->string) + 1)))
            return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
        strcpy(m.name, item->string);
        s->materials[s->material_count++] = m;
    }
    return CG_OK;
}
