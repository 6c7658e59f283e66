/* Keyframe animation of a scene (the key "animation"): tracks of keys, each
 * track one animated value (a camera value, an object's translate, rotate
 * or scale, a light's intensity), and the scene's values as the file gave
 * them, that animated placements and intensities start from. */
#ifndef CG_SCENE_ANIMATION_H
#define CG_SCENE_ANIMATION_H

#include "internal.h"
#include "../core/array.h"

typedef enum animation_value {
    ANIMATE_EYE,
    ANIMATE_TARGET,
    ANIMATE_UP,
    ANIMATE_FOV,       /* degrees */
    ANIMATE_TRANSLATE, /* of an object */
    ANIMATE_ROTATE,    /* of an object: degrees about x, then y, then z */
    ANIMATE_SCALE,     /* of an object: per axis, about the origin */
    ANIMATE_INTENSITY  /* of a light: a factor on its colour */
} animation_value;

typedef struct animation_key {
    double frame;
    cg_vec3 value; /* one-number values in x */
} animation_key;

typedef struct animation_track {
    animation_value value;
    size_t target;                  /* the object, or the light (area lights after the others) */
    int area_light;                 /* intensity: target indexes area_lights */
    CORE_ARRAY(animation_key) keys; /* sorted by frame, no frame twice */
} animation_track;

struct cg_scene_animation {
    int catmull_rom; /* 0: linear between keys */
    CORE_ARRAY(animation_track) tracks;
    /* the values the file gave, that animated placements and intensities
     * start from (a pose writes only what is animated) */
    size_t object_count, light_count, area_light_count;
    cg_mat4 *transforms;   /* object_count */
    cg_vec3 *light_colors; /* light_count */
    cg_vec3 *area_colors;  /* area_light_count */
};

/* The value of a track at frame: held before the first and after the last
 * key, interpolated between (linearly, or by the uniform Catmull-Rom
 * spline through the neighbouring keys, cg/curve.h). */
cg_vec3 animation_track_at(const animation_track *track, int catmull_rom, double frame);

void animation_free(cg_scene_animation *animation);

#endif
