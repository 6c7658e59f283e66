/* The scene file's "objects" (mesh files, spheres, planes, boxes, each with
 * a material and a transform) and "overlays" (lines of a cg draw script). */
#include "parse.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

char *scene_resolve_path(const char *base_dir, const char *file)
{
    size_t base = (base_dir && base_dir[0] && file[0] != '/') ? strlen(base_dir) + 1 : 0;
    char *path = malloc(base + strlen(file) + 1);
    if (!path)
        return NULL;
    if (base)
        snprintf(path, base + strlen(file) + 1, "%s/%s", base_dir, file);
    else
        strcpy(path, file);
    return path;
}

cg_status scene_parse_object(const scene_parser *p, const char *path, const cJSON *v, cg_scene *s)
{
    static const char *const kinds[] = {"mesh", "sphere", "plane", "box", NULL};
    static const char *const keys[] = {"type", "file", "center",   "radius",    "point", "normal",
                                       "lo",   "hi",   "material", "transform", NULL};
    cg_status st;
    if ((st = scene_need_object(p, path, v)) || (st = scene_check_keys(p, path, v, keys))
        || (st = scene_reserve(p, (void **)&s->objects, &p->capacity->objects, s->object_count,
                               sizeof *s->objects)))
        return st;
    /* Counted before it is read so that cg_scene_free releases a half-read
     * object too. */
    cg_scene_object *o = &s->objects[s->object_count++];
    memset(o, 0, sizeof *o);
    int kind = -1;
    if ((st = scene_get_choice(p, path, v, "type", kinds, &kind)))
        return st;
    char key_path[SCENE_PATH_SIZE];
    if (kind < 0) {
        scene_path_join(key_path, path, "type");
        return scene_expected(p, key_path, "one of \"mesh\", \"sphere\", \"plane\", \"box\"", NULL);
    }
    o->kind = (cg_scene_object_kind)kind;
    o->transform = cg_mat4_identity();
    o->radius = 1;
    o->normal = cg_vec3_make(0, 1, 0);
    o->lo = cg_vec3_make(-0.5, -0.5, -0.5);
    o->hi = cg_vec3_make(0.5, 0.5, 0.5);
    if ((st = scene_get_vec3(p, path, v, "center", &o->center))
        || (st = scene_get_number(p, path, v, "radius", 0, 1e15, &o->radius))
        || (st = scene_get_vec3(p, path, v, "point", &o->point))
        || (st = scene_get_vec3(p, path, v, "normal", &o->normal))
        || (st = scene_get_vec3(p, path, v, "lo", &o->lo))
        || (st = scene_get_vec3(p, path, v, "hi", &o->hi)))
        return st;
    if (o->kind == CG_SCENE_PLANE && !(cg_vec3_length(o->normal) > 0)) {
        scene_path_join(key_path, path, "normal");
        return scene_fail(p, key_path, "expected a non-zero normal");
    }
    /* A box of zero size on an axis has no inside (and no mesh to rasterize). */
    if (o->kind == CG_SCENE_BOX && !(o->lo.x < o->hi.x && o->lo.y < o->hi.y && o->lo.z < o->hi.z)) {
        scene_path_join(key_path, path, "hi");
        return scene_fail(p, key_path,
                          "expected every coordinate of hi to be greater than that of lo "
                          "(a box of non-zero size on each axis)");
    }
    const cJSON *transform = cJSON_GetObjectItemCaseSensitive(v, "transform");
    if (transform) {
        scene_path_join(key_path, path, "transform");
        if ((st = scene_parse_transform(p, key_path, transform, &o->transform)))
            return st;
    }
    const cJSON *material = cJSON_GetObjectItemCaseSensitive(v, "material");
    if (material) {
        scene_path_join(key_path, path, "material");
        if (!cJSON_IsString(material))
            return scene_expected(p, key_path, "the name of a material", material);
        size_t i = 1;
        while (i < s->material_count && strcmp(s->materials[i].name, material->valuestring) != 0)
            i++;
        if (i == s->material_count)
            return scene_expected(p, key_path, "the name of a material defined in \"materials\"",
                                  material);
        o->material = i;
    }
    const cJSON *file = cJSON_GetObjectItemCaseSensitive(v, "file");
    if (o->kind == CG_SCENE_MESH) {
        scene_path_join(key_path, path, "file");
        if (!cJSON_IsString(file) || !file->valuestring[0])
            return scene_expected(p, key_path, "the path of a mesh file", file);
        if (!(o->file = scene_resolve_path(p->base_dir, file->valuestring)))
            return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
        if (p->load_meshes) {
            cg_error mesh_error;
            cg_status ms = cg_mesh_load(o->file, &o->mesh, &mesh_error);
            if (ms != CG_OK)
                return cg_error_set(p->err, ms, "%s: %s: %s", p->name, key_path,
                                    mesh_error.message);
        }
    } else if (file) {
        scene_path_join(key_path, path, "file");
        return scene_fail(p, key_path, "only mesh objects have a file");
    }
    return CG_OK;
}

cg_status scene_parse_overlay(const scene_parser *p, const char *path, const cJSON *v, cg_scene *s)
{
    if (!cJSON_IsString(v) || strchr(v->valuestring, '\n'))
        return scene_expected(p, path, "one line of a cg draw script", v);
    cg_status st = scene_reserve(p, (void **)&s->overlays, &p->capacity->overlays, s->overlay_count,
                                 sizeof *s->overlays);
    if (st)
        return st;
    size_t length = strlen(v->valuestring) + 1;
    if (!(s->overlays[s->overlay_count] = malloc(length)))
        return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
    memcpy(s->overlays[s->overlay_count++], v->valuestring, length);
    return CG_OK;
}
