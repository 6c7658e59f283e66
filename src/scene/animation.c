/* Posing an animated scene at a frame (cg_scene_set_frame): every track's
 * value at the frame replaces the file's value it animates.  Objects: the
 * animated translate, rotate and scale make one matrix
 *
 *     A = T(translate) Rz Ry Rx S(scale)
 *
 * applied after the object's own transform list (world = A M), so a key
 * moves the object as placed by the file. */
#include "animation.h"
#include "cg/curve.h"
#include "cg/xform.h"

#include <math.h>
#include <stdlib.h>

cg_vec3 animation_track_at(const animation_track *track, int catmull_rom, double frame)
{
    const animation_key *k = track->keys.data;
    size_t n = track->keys.count;
    if (n == 1 || frame <= k[0].frame)
        return k[0].value;
    if (frame >= k[n - 1].frame)
        return k[n - 1].value;
    size_t i = 0;
    while (i + 2 < n && k[i + 1].frame <= frame)
        i++;
    double t = (frame - k[i].frame) / (k[i + 1].frame - k[i].frame);
    if (!catmull_rom)
        return cg_vec3_add(k[i].value, cg_vec3_scale(cg_vec3_sub(k[i + 1].value, k[i].value), t));
    /* the end keys stand in for the missing neighbours */
    cg_cubic3 segment = {CG_BASIS_CATMULL_ROM,
                         {k[i > 0 ? i - 1 : i].value, k[i].value, k[i + 1].value,
                          k[i + 2 < n ? i + 2 : i + 1].value}};
    return cg_cubic3_point(&segment, t);
}

void animation_free(cg_scene_animation *animation)
{
    if (!animation)
        return;
    for (size_t i = 0; i < animation->tracks.count; i++)
        core_array_free(&animation->tracks.data[i].keys);
    core_array_free(&animation->tracks);
    free(animation->transforms);
    free(animation->light_colors);
    free(animation->area_colors);
    free(animation);
}

/* The object part of a pose: A M for every object with a track. */
static void pose_objects(cg_scene *scene, const cg_scene_animation *a, double frame)
{
    size_t count = scene->object_count < a->object_count ? scene->object_count : a->object_count;
    for (size_t o = 0; o < count; o++) {
        cg_vec3 translate = {0, 0, 0}, rotate = {0, 0, 0}, scale = {1, 1, 1};
        int moved = 0;
        for (size_t i = 0; i < a->tracks.count; i++) {
            const animation_track *t = &a->tracks.data[i];
            if (t->target != o || t->value < ANIMATE_TRANSLATE || t->value > ANIMATE_SCALE)
                continue;
            cg_vec3 v = animation_track_at(t, a->catmull_rom, frame);
            *(t->value == ANIMATE_TRANSLATE ? &translate
              : t->value == ANIMATE_ROTATE  ? &rotate
                                            : &scale) = v;
            moved = 1;
        }
        if (!moved)
            continue;
        cg_mat4 steps[5] = {cg_xform3_scale(scale.x, scale.y, scale.z, cg_vec3_make(0, 0, 0)),
                            cg_xform3_rotate_x(cg_radians(rotate.x)),
                            cg_xform3_rotate_y(cg_radians(rotate.y)),
                            cg_xform3_rotate_z(cg_radians(rotate.z)),
                            cg_xform3_translate(translate.x, translate.y, translate.z)};
        scene->objects[o].transform = cg_mat4_mul(cg_mat4_compose(steps, 5), a->transforms[o]);
    }
}

/* A light's colour at the frame: the file's times the animated factor.
 * Lights replaced since the file was read (the counts differ) are left. */
static void pose_light(cg_scene *scene, const cg_scene_animation *a, const animation_track *t,
                       double factor)
{
    if (scene->light_count != a->light_count || scene->area_light_count != a->area_light_count)
        return;
    if (t->area_light)
        scene->area_lights[t->target].color = cg_vec3_scale(a->area_colors[t->target], factor);
    else
        scene->lights[t->target].color = cg_vec3_scale(a->light_colors[t->target], factor);
}

cg_status cg_scene_set_frame(cg_scene *scene, double frame)
{
    if (!scene || !isfinite(frame))
        return CG_EINVAL;
    const cg_scene_animation *a = scene->animation;
    if (!a)
        return CG_OK;
    for (size_t i = 0; i < a->tracks.count; i++) {
        const animation_track *t = &a->tracks.data[i];
        cg_vec3 v = animation_track_at(t, a->catmull_rom, frame);
        switch (t->value) {
        case ANIMATE_EYE: scene->camera.eye = v; break;
        case ANIMATE_TARGET: scene->camera.target = v; break;
        case ANIMATE_UP: scene->camera.up = v; break;
        case ANIMATE_FOV: scene->camera.fovy = cg_radians(fmin(179, fmax(1, v.x))); break;
        case ANIMATE_INTENSITY: pose_light(scene, a, t, fmax(0, v.x)); break;
        default: break; /* objects below */
        }
    }
    pose_objects(scene, a, frame);
    return CG_OK;
}
