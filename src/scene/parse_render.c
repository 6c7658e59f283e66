/* The scene file's "image" (size and background) and "render" (algorithm,
 * shading, culling, edges, the z-buffer's samples per pixel and the ray
 * tracer's settings). */
#include "parse.h"

cg_status scene_parse_image(const scene_parser *p, const cJSON *v, cg_scene *s)
{
    static const char *const keys[] = {"width", "height", "background", NULL};
    cg_status st;
    if ((st = scene_need_object(p, "image", v)) || (st = scene_check_keys(p, "image", v, keys))
        || (st = scene_get_int(p, "image", v, "width", 1, CG_SCENE_MAX_SIDE, &s->width))
        || (st = scene_get_int(p, "image", v, "height", 1, CG_SCENE_MAX_SIDE, &s->height)))
        return st;
    cg_vec3 bg = {s->background.r, s->background.g, s->background.b};
    if ((st = scene_get_color(p, "image", v, "background", &bg)))
        return st;
    s->background.r = (float)bg.x;
    s->background.g = (float)bg.y;
    s->background.b = (float)bg.z;
    return CG_OK;
}

cg_status scene_parse_render(const scene_parser *p, const cJSON *v, cg_scene *s)
{
    static const char *const keys[] = {"algorithm", "shading", "cull",    "edges", "threads",
                                       "samples",   "depth",   "shadows", "msaa",  NULL};
    static const char *const algorithms[] = {"zbuffer", "painter", "raytrace", NULL};
    static const char *const shadings[] = {"flat", "gouraud", "phong", NULL};
    static const char *const culls[] = {"none", "back", NULL};
    static const char *const edges[] = {"none", "wireframe", "hidden-line", "overlay", NULL};
    int algorithm = (int)s->algorithm, shading = (int)s->shading, cull = s->cull_back,
        edge = (int)s->edges;
    cg_status st;
    if ((st = scene_need_object(p, "render", v)) || (st = scene_check_keys(p, "render", v, keys))
        || (st = scene_get_choice(p, "render", v, "algorithm", algorithms, &algorithm))
        || (st = scene_get_choice(p, "render", v, "shading", shadings, &shading))
        || (st = scene_get_choice(p, "render", v, "cull", culls, &cull))
        || (st = scene_get_choice(p, "render", v, "edges", edges, &edge))
        || (st = scene_get_int(p, "render", v, "threads", 1, 64, &s->threads))
        || (st = scene_get_int(p, "render", v, "samples", 1, 1024, &s->samples))
        || (st = scene_get_int(p, "render", v, "depth", 0, 32, &s->max_depth))
        || (st = scene_get_bool(p, "render", v, "shadows", &s->shadows))
        || (st = scene_get_int(p, "render", v, "msaa", 1, 16, &s->msaa)))
        return st;
    if (s->msaa & (s->msaa - 1))
        return scene_expected(p, "render.msaa", "1, 2, 4, 8 or 16",
                              cJSON_GetObjectItemCaseSensitive(v, "msaa"));
    s->algorithm = (cg_scene_algorithm)algorithm;
    s->shading = (cg_scene_shading)shading;
    s->cull_back = cull;
    s->edges = (cg_scene_edges)edge;
    return CG_OK;
}
