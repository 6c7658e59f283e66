/* The scene file's "environment": the path tracer's sky, an equirectangular
 * image file with an intensity, or a uniform colour. */
#include "parse.h"
#include "cg/image_float.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The map as linear-light floats: float files as they are, 8-bit files
 * decoded from sRGB. */
static cg_status load_map(const scene_parser *p, const char *file, cg_image **out)
{
    cg_error err;
    cg_status st = cg_image_load_linear(file, out, &err);
    return st == CG_OK ? CG_OK
                       : cg_error_set(p->err, st, "%s: environment.file: %s", p->name, err.message);
}

cg_status scene_parse_environment(const scene_parser *p, const cJSON *v, cg_scene *s)
{
    static const char *const keys[] = {"file", "intensity", "color", NULL};
    cg_status st;
    if ((st = scene_need_object(p, "environment", v))
        || (st = scene_check_keys(p, "environment", v, keys))
        || (st = scene_get_number(p, "environment", v, "intensity", 0, 1e9,
                                  &s->environment_intensity))
        || (st = scene_get_color(p, "environment", v, "color", &s->environment_color)))
        return st;
    const cJSON *file = cJSON_GetObjectItemCaseSensitive(v, "file");
    if (file && cJSON_GetObjectItemCaseSensitive(v, "color"))
        return scene_fail(p, "environment", "give a file or a color, not both");
    if (!file && cJSON_GetObjectItemCaseSensitive(v, "intensity"))
        return scene_fail(p, "environment.intensity", "scales a file; give environment.file");
    s->environment_given = 1;
    if (!file)
        return CG_OK;
    if (!cJSON_IsString(file) || !file->valuestring[0])
        return scene_expected(p, "environment.file", "a file name", file);
    if (!(s->environment_file = scene_resolve_path(p->base_dir, file->valuestring)))
        return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
    return p->load_meshes ? load_map(p, s->environment_file, &s->environment_map) : CG_OK;
}
