/* The scene file's "camera": eye, target, up and one of the projections of
 * cg/xform.h with its angles and ratio. */
#include "parse.h"

#include <cjson/cJSON.h>
#include <math.h>

cg_status scene_parse_camera(const scene_parser *p, const cJSON *v, cg_scene *s)
{
    static const char *const keys[] = {"eye",    "target", "up",  "projection", "fov",
                                       "height", "near",   "far", "frame",      "angles",
                                       "ratio",  "angle",  NULL};
    static const char *const projections[] = {"perspective", "orthographic", "isometric",
                                              "dimetric",    "trimetric",    "cavalier",
                                              "cabinet",     "oblique",      NULL};
    cg_status st;
    if ((st = scene_need_object(p, "camera", v)) || (st = scene_check_keys(p, "camera", v, keys)))
        return st;
    cg_camera *c = &s->camera;
    int projection = (int)s->projection;
    double fov = cg_degrees(c->fovy), angle = cg_degrees(s->projection_angle);
    s->frame_camera = cJSON_GetObjectItemCaseSensitive(v, "eye") == NULL;
    if ((st = scene_get_vec3(p, "camera", v, "eye", &c->eye))
        || (st = scene_get_vec3(p, "camera", v, "target", &c->target))
        || (st = scene_get_vec3(p, "camera", v, "up", &c->up))
        || (st = scene_get_choice(p, "camera", v, "projection", projections, &projection))
        || (st = scene_get_number(p, "camera", v, "fov", 1, 179, &fov))
        || (st = scene_get_number(p, "camera", v, "height", 1e-9, 1e12, &c->ortho_height))
        || (st = scene_get_number(p, "camera", v, "near", 1e-9, 1e12, &c->near))
        || (st = scene_get_number(p, "camera", v, "far", 1e-9, 1e15, &c->far))
        || (st = scene_get_bool(p, "camera", v, "frame", &s->frame_camera))
        || (st = scene_get_number(p, "camera", v, "ratio", 1e-3, 10, &s->projection_ratio))
        || (st = scene_get_number(p, "camera", v, "angle", -360, 360, &angle)))
        return st;
    const cJSON *angles = cJSON_GetObjectItemCaseSensitive(v, "angles");
    if (angles) {
        double a[2];
        if ((st = scene_read_numbers(p, "camera.angles", angles, 2, a)))
            return st;
        s->projection_angle = cg_radians(a[0]);
        s->projection_angle2 = cg_radians(a[1]);
    } else {
        s->projection_angle = cg_radians(angle);
    }
    if (projection == CG_SCENE_DIMETRIC && !(s->projection_ratio < 1))
        return scene_fail(p, "camera.ratio",
                          "expected a number between 0.001 and 1 (exclusive) for a dimetric view");
    s->near_given = cJSON_GetObjectItemCaseSensitive(v, "near") != NULL;
    s->far_given = cJSON_GetObjectItemCaseSensitive(v, "far") != NULL;
    if (s->near_given && s->far_given && !(c->far > c->near))
        return scene_fail(p, "camera.far", "expected a distance greater than near (%g)", c->near);
    if (!(cg_vec3_length(cg_vec3_sub(c->target, c->eye)) > 0))
        return scene_fail(p, "camera.target", "expected a point different from the eye");
    s->projection = (cg_scene_projection)projection;
    c->fovy = cg_radians(fov);
    c->orthographic = projection != CG_SCENE_PERSPECTIVE;
    return CG_OK;
}
