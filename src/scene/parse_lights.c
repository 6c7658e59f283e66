/* The scene file's "lights": ambient, point, directional, spot and area
 * lights, each with a colour times an intensity. */
#include "parse.h"

#include <cjson/cJSON.h>

cg_status scene_parse_light(const scene_parser *p, const char *path, const cJSON *v, cg_scene *s)
{
    static const char *const kinds[] = {"ambient", "point", "directional", "spot", "area", NULL};
    static const char *const keys[] = {
        "type",     "color",  "intensity", "position", "direction", "attenuation", "cutoff",
        "exponent", "corner", "edge_u",    "edge_v",   "samples",   NULL};
    cg_status st;
    if ((st = scene_need_object(p, path, v)) || (st = scene_check_keys(p, path, v, keys)))
        return st;
    int kind = -1;
    if ((st = scene_get_choice(p, path, v, "type", kinds, &kind)))
        return st;
    if (kind < 0) {
        char type_path[SCENE_PATH_SIZE];
        scene_path_join(type_path, path, "type");
        return scene_expected(p, type_path,
                              "one of \"ambient\", \"point\", \"directional\", \"spot\", \"area\"",
                              NULL);
    }
    cg_vec3 color = {1, 1, 1}, position = {0, 10, 0}, direction = {0, -1, 0};
    double intensity = 1, cutoff = 30, exponent = 0;
    if ((st = scene_get_color(p, path, v, "color", &color))
        || (st = scene_get_number(p, path, v, "intensity", 0, 1e9, &intensity))
        || (st = scene_get_vec3(p, path, v, "position", &position))
        || (st = scene_get_vec3(p, path, v, "direction", &direction))
        || (st = scene_get_number(p, path, v, "cutoff", 1e-6, 180, &cutoff))
        || (st = scene_get_number(p, path, v, "exponent", 0, 1e4, &exponent)))
        return st;
    color = cg_vec3_scale(color, intensity);
    if (kind == 4) { /* area */
        cg_scene_area_light a = {{0, 10, 0}, {1, 0, 0}, {0, 0, 1}, color, 4};
        if ((st = scene_get_vec3(p, path, v, "corner", &a.corner))
            || (st = scene_get_vec3(p, path, v, "edge_u", &a.edge_u))
            || (st = scene_get_vec3(p, path, v, "edge_v", &a.edge_v))
            || (st = scene_get_int(p, path, v, "samples", 1, 64, &a.samples)))
            return st;
        if (!(cg_vec3_length(cg_vec3_cross(a.edge_u, a.edge_v)) > 0))
            return scene_fail(p, path, "expected edge_u and edge_v spanning a rectangle");
        if ((st = scene_reserve(p, (void **)&s->area_lights, &p->capacity->area_lights,
                                s->area_light_count, sizeof a)))
            return st;
        s->area_lights[s->area_light_count++] = a;
        return CG_OK;
    }
    if ((kind == 2 || kind == 3) && !(cg_vec3_length(direction) > 0))
        return scene_fail(p, path, "expected a non-zero direction");
    cg_light light;
    switch (kind) {
    case 0: light = cg_light_ambient(color); break;
    case 1: light = cg_light_point(position, color); break;
    case 2: light = cg_light_directional(direction, color); break;
    default: light = cg_light_spot(position, direction, cg_radians(cutoff), exponent, color); break;
    }
    const cJSON *att = cJSON_GetObjectItemCaseSensitive(v, "attenuation");
    if (att) {
        double c[3];
        char att_path[SCENE_PATH_SIZE];
        scene_path_join(att_path, path, "attenuation");
        if ((st = scene_read_numbers(p, att_path, att, 3, c)))
            return st;
        cg_light_set_attenuation(&light, c[0], c[1], c[2]);
    }
    cg_error check;
    if (cg_light_check(&light, &check) != CG_OK)
        return scene_fail(p, path, "%s", check.message);
    if ((st = scene_reserve(p, (void **)&s->lights, &p->capacity->lights, s->light_count,
                            sizeof light)))
        return st;
    s->lights[s->light_count++] = light;
    return CG_OK;
}
