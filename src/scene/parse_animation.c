/* The scene file's "animation": keyframes of the camera, the objects'
 * placement and the lights' intensities (animation.h).
 *
 *   "animation": {"frames": 48, "interpolation": "catmull-rom",
 *                 "keys": [{"frame": 0, "camera": {"eye": [0, 1, 5]},
 *                           "objects": [{"object": 0, "rotate": [0, 0, 0]}],
 *                           "lights": [{"light": 0, "intensity": 1}]},
 *                          {"frame": 47, ...}]}
 *
 * Each value a key names starts or extends that value's track; a track's
 * keys may come in any order but not twice at one frame.  Objects and
 * lights are the indices of the file's "objects" and "lights" arrays. */
#include "animation.h"
#include "parse.h"
#include "../core/sort.h"

#include <stdlib.h>
#include <string.h>

#define ANIMATION_MAX_FRAMES 1000000
#define ANIMATION_MAX_KEYS 100000

/* The track of (value, target), made when new. */
static cg_status track_for(const scene_parser *p, cg_scene_animation *a, animation_value value,
                           size_t target, animation_track **out)
{
    for (size_t i = 0; i < a->tracks.count; i++)
        if (a->tracks.data[i].value == value && a->tracks.data[i].target == target) {
            *out = &a->tracks.data[i];
            return CG_OK;
        }
    animation_track fresh = {value, target, 0, {0}};
    if (core_array_push(&a->tracks, fresh) != CG_OK)
        return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
    *out = &a->tracks.data[a->tracks.count - 1];
    return CG_OK;
}

static cg_status add_key(const scene_parser *p, cg_scene_animation *a, animation_value value,
                         size_t target, double frame, cg_vec3 v)
{
    animation_track *t = NULL;
    cg_status st = track_for(p, a, value, target, &t);
    animation_key key = {frame, v};
    if (st == CG_OK && core_array_push(&t->keys, key) != CG_OK)
        st = cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
    return st;
}

/* obj[key] (when present) as one key of (value, target). */
static cg_status key_vec3(const scene_parser *p, const char *path, const cJSON *obj,
                          const char *key, cg_scene_animation *a, animation_value value,
                          size_t target, double frame)
{
    if (!cJSON_GetObjectItemCaseSensitive(obj, key))
        return CG_OK;
    cg_vec3 v;
    cg_status st = scene_get_vec3(p, path, obj, key, &v);
    return st ? st : add_key(p, a, value, target, frame, v);
}

static cg_status key_number(const scene_parser *p, const char *path, const cJSON *obj,
                            const char *key, double min, double max, cg_scene_animation *a,
                            animation_value value, size_t target, double frame)
{
    if (!cJSON_GetObjectItemCaseSensitive(obj, key))
        return CG_OK;
    double x;
    cg_status st = scene_get_number(p, path, obj, key, min, max, &x);
    return st ? st : add_key(p, a, value, target, frame, cg_vec3_make(x, x, x));
}

static cg_status parse_camera_key(const scene_parser *p, const char *path, const cJSON *v,
                                  cg_scene_animation *a, double frame)
{
    static const char *const keys[] = {"eye", "target", "up", "fov", NULL};
    cg_status st;
    if ((st = scene_need_object(p, path, v)) || (st = scene_check_keys(p, path, v, keys))
        || (st = key_vec3(p, path, v, "eye", a, ANIMATE_EYE, 0, frame))
        || (st = key_vec3(p, path, v, "target", a, ANIMATE_TARGET, 0, frame))
        || (st = key_vec3(p, path, v, "up", a, ANIMATE_UP, 0, frame)))
        return st;
    return key_number(p, path, v, "fov", 1, 179, a, ANIMATE_FOV, 0, frame);
}

/* An index into the scene's objects, or its lights, at obj[key]. */
static cg_status get_index(const scene_parser *p, const char *path, const cJSON *obj,
                           const char *key, size_t count, size_t *out)
{
    int index = -1;
    cg_status st = scene_get_int(p, path, obj, key, 0, count ? (int)count - 1 : 0, &index);
    if (st)
        return st;
    if (index < 0 || (size_t)index >= count)
        return scene_fail(p, path, "needs \"%s\", the index of one of the scene's %zu %ss", key,
                          count, key);
    *out = (size_t)index;
    return CG_OK;
}

/* Light i of the file: area lights are kept apart from the others. */
static void light_slot(const cJSON *root, size_t file_index, int *area, size_t *slot)
{
    const cJSON *lights = cJSON_GetObjectItemCaseSensitive(root, "lights");
    size_t areas = 0, others = 0, i = 0;
    for (const cJSON *l = lights ? lights->child : NULL; l; l = l->next, i++) {
        const cJSON *type = cJSON_GetObjectItemCaseSensitive(l, "type");
        int is_area = cJSON_IsString(type) && strcmp(type->valuestring, "area") == 0;
        if (i == file_index) {
            *area = is_area;
            *slot = is_area ? areas : others;
            return;
        }
        *(is_area ? &areas : &others) += 1;
    }
}

static cg_status parse_list(const scene_parser *p, const char *path, const cJSON *root,
                            const cJSON *list, const cg_scene *s, cg_scene_animation *a,
                            double frame, int objects)
{
    static const char *const object_keys[] = {"object", "translate", "rotate", "scale", NULL};
    static const char *const light_keys[] = {"light", "intensity", NULL};
    if (!cJSON_IsArray(list))
        return scene_expected(p, path, "an array", list);
    size_t lights = s->light_count + s->area_light_count, i = 0;
    for (const cJSON *item = list->child; item; item = item->next, i++) {
        char at[SCENE_PATH_SIZE];
        scene_path_format(at, "%s[%zu]", path, i);
        size_t target = 0;
        cg_status st;
        if ((st = scene_need_object(p, at, item))
            || (st = scene_check_keys(p, at, item, objects ? object_keys : light_keys))
            || (st = get_index(p, at, item, objects ? "object" : "light",
                               objects ? s->object_count : lights, &target)))
            return st;
        if (objects) {
            if ((st = key_vec3(p, at, item, "translate", a, ANIMATE_TRANSLATE, target, frame))
                || (st = key_vec3(p, at, item, "rotate", a, ANIMATE_ROTATE, target, frame)))
                return st;
            const cJSON *scale = cJSON_GetObjectItemCaseSensitive(item, "scale");
            st = cJSON_IsNumber(scale)
                     ? key_number(p, at, item, "scale", -1e9, 1e9, a, ANIMATE_SCALE, target, frame)
                     : key_vec3(p, at, item, "scale", a, ANIMATE_SCALE, target, frame);
        } else {
            int area = 0;
            size_t slot = 0;
            light_slot(root, target, &area, &slot);
            /* area lights take the slots after the others */
            st = key_number(p, at, item, "intensity", 0, 1e9, a, ANIMATE_INTENSITY,
                            area ? s->light_count + slot : slot, frame);
        }
        if (st)
            return st;
    }
    return CG_OK;
}

static cg_status parse_key(const scene_parser *p, const char *path, const cJSON *root,
                           const cJSON *v, const cg_scene *s, cg_scene_animation *a)
{
    static const char *const keys[] = {"frame", "camera", "objects", "lights", "comment", NULL};
    double frame = -1;
    cg_status st;
    if ((st = scene_need_object(p, path, v)) || (st = scene_check_keys(p, path, v, keys))
        || (st = scene_get_number(p, path, v, "frame", 0, ANIMATION_MAX_FRAMES, &frame)))
        return st;
    if (frame < 0)
        return scene_fail(p, path, "needs \"frame\", the frame number of the key");
    char at[SCENE_PATH_SIZE];
    const cJSON *part;
    if ((part = cJSON_GetObjectItemCaseSensitive(v, "camera"))) {
        scene_path_join(at, path, "camera");
        if ((st = parse_camera_key(p, at, part, a, frame)))
            return st;
    }
    if ((part = cJSON_GetObjectItemCaseSensitive(v, "objects"))) {
        scene_path_join(at, path, "objects");
        if ((st = parse_list(p, at, root, part, s, a, frame, 1)))
            return st;
    }
    if ((part = cJSON_GetObjectItemCaseSensitive(v, "lights"))) {
        scene_path_join(at, path, "lights");
        if ((st = parse_list(p, at, root, part, s, a, frame, 0)))
            return st;
    }
    return CG_OK;
}

static int compare_keys(const void *a, const void *b)
{
    double x = ((const animation_key *)a)->frame, y = ((const animation_key *)b)->frame;
    return (x > y) - (x < y);
}

/* Sorts each track by frame, refuses a frame given twice, and splits the
 * intensity targets into lights and area lights. */
static cg_status finish_tracks(const scene_parser *p, const cg_scene *s, cg_scene_animation *a)
{
    for (size_t i = 0; i < a->tracks.count; i++) {
        animation_track *t = &a->tracks.data[i];
        core_sort(t->keys.data, t->keys.count, sizeof *t->keys.data, compare_keys);
        for (size_t k = 1; k < t->keys.count; k++)
            if (t->keys.data[k].frame == t->keys.data[k - 1].frame)
                return scene_fail(p, "animation.keys", "two keys give the same value at frame %g",
                                  t->keys.data[k].frame);
        if (t->value == ANIMATE_INTENSITY && t->target >= s->light_count) {
            t->area_light = 1;
            t->target -= s->light_count;
        }
    }
    return CG_OK;
}

/* The file's values, restored before each pose. */
static cg_status keep_base(const scene_parser *p, const cg_scene *s, cg_scene_animation *a)
{
    a->object_count = s->object_count;
    a->light_count = s->light_count;
    a->area_light_count = s->area_light_count;
    a->transforms = malloc((s->object_count + 1) * sizeof *a->transforms);
    a->light_colors = malloc((s->light_count + 1) * sizeof *a->light_colors);
    a->area_colors = malloc((s->area_light_count + 1) * sizeof *a->area_colors);
    if (!a->transforms || !a->light_colors || !a->area_colors)
        return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
    for (size_t i = 0; i < s->object_count; i++)
        a->transforms[i] = s->objects[i].transform;
    for (size_t i = 0; i < s->light_count; i++)
        a->light_colors[i] = s->lights[i].color;
    for (size_t i = 0; i < s->area_light_count; i++)
        a->area_colors[i] = s->area_lights[i].color;
    return CG_OK;
}

cg_status scene_parse_animation(const scene_parser *p, const cJSON *root, const cJSON *v,
                                cg_scene *s)
{
    static const char *const keys[] = {"frames", "interpolation", "keys", "comment", NULL};
    static const char *const interpolations[] = {"linear", "catmull-rom", NULL};
    int frames = 0, interpolation = 0;
    cg_status st;
    if ((st = scene_need_object(p, "animation", v))
        || (st = scene_check_keys(p, "animation", v, keys))
        || (st = scene_get_int(p, "animation", v, "frames", 1, ANIMATION_MAX_FRAMES, &frames))
        || (st = scene_get_choice(p, "animation", v, "interpolation", interpolations,
                                  &interpolation)))
        return st;
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(v, "keys");
    if (!cJSON_IsArray(list) || cJSON_GetArraySize(list) == 0)
        return scene_expected(p, "animation.keys", "an array of one key or more", list);
    if (cJSON_GetArraySize(list) > ANIMATION_MAX_KEYS)
        return scene_fail(p, "animation.keys", "more than %d keys", ANIMATION_MAX_KEYS);
    cg_scene_animation *a = calloc(1, sizeof *a);
    if (!a)
        return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
    s->animation = a;
    a->catmull_rom = interpolation == 1;
    double last = 0;
    size_t i = 0;
    for (const cJSON *key = list->child; key; key = key->next, i++) {
        char at[SCENE_PATH_SIZE];
        scene_path_format(at, "animation.keys[%zu]", i);
        if ((st = parse_key(p, at, root, key, s, a)))
            return st;
        const cJSON *f = cJSON_GetObjectItemCaseSensitive(key, "frame");
        last = f->valuedouble > last ? f->valuedouble : last;
    }
    /* without "frames", the frames run to the last key */
    s->frame_count = frames > 0 ? frames : (int)last + 1;
    if ((st = finish_tracks(p, s, a)))
        return st;
    return keep_base(p, s, a);
}
