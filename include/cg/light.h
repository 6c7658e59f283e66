/* cg/light.h - local illumination (chapter 6): ambient, Lambert diffuse,
 * Phong and Blinn-Phong specular, point / directional / spot lights with
 * distance attenuation.
 *
 * One model shared by the rasterizer (flat: once per face, Gouraud: per
 * vertex, Phong: per pixel) and the ray tracer (per hit, with shadow rays).
 *
 * For a point P with unit normal N, unit view vector V (from P toward the
 * viewer), material (Od = color, Os = specular_color) and lights l:
 *
 *   I = sum over ambient lights   ka Od Ia
 *     + sum over other lights     vis_l f_att(d_l) spot_l Il
 *                                 ( kd Od max(N.L, 0) + ks Os spec )
 *
 *   spec = max(R.V, 0)^n with R = 2 (N.L) N - L        (Phong)
 *        = max(N.H, 0)^n with H = (L + V) / |L + V|    (Blinn-Phong)
 *   and spec = 0 whenever N.L <= 0 (a light behind the surface adds nothing).
 *
 *   f_att(d) = min(1, 1 / (c0 + c1 d + c2 d^2)), 1 when the denominator is
 *   not positive; directional lights are not attenuated.
 *   spot_l = max(-L.axis, 0)^e when -L.axis >= cos(cutoff), else 0.
 *
 * All colours are linear-light RGB (not sRGB-encoded), components >= 0; a
 * light's colour is its intensity Il and may exceed 1.  The result is linear
 * RGB >= 0 that may exceed 1: map it to pixels with cg_intensity_* in
 * cg/color.h (clamp, exposure) or store it in a CG_PIXEL_RGBAF image.
 *
 * Inputs are trusted for speed: the shading calls do not check their
 * arguments.  Lights and materials made by the constructors below are valid;
 * cg_light_check and cg_material_check validate hand-made ones (a scene
 * reader should call them).  Positions, normals and lights must be in the
 * same space (world or eye).
 */
#ifndef CG_LIGHT_H
#define CG_LIGHT_H

#include "cg/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cg_specular_model {
    CG_SPECULAR_PHONG = 0, /* (R.V)^n */
    CG_SPECULAR_BLINN = 1  /* (N.H)^n, the halfway vector */
} cg_specular_model;

typedef struct cg_material {
    cg_vec3 color;          /* Od: diffuse and ambient colour, linear RGB in [0, 1] */
    cg_vec3 specular_color; /* Os: usually white (1, 1, 1) */
    double ka, kd, ks;      /* ambient, diffuse, specular coefficients, >= 0 */
    double shininess;       /* n, the specular exponent, >= 0 */
    cg_specular_model specular;
    /* Not used by the local model: for the ray tracer (0 = none). */
    double reflectance;      /* kr: fraction of the mirror-reflected ray */
    double transmittance;    /* kt: fraction of the refracted ray */
    double refractive_index; /* of the inside of the surface; 0 means 1 */
} cg_material;

typedef enum cg_light_kind {
    CG_LIGHT_AMBIENT = 0,     /* Ia: adds ka Od Ia everywhere */
    CG_LIGHT_POINT = 1,       /* at position, shines in every direction */
    CG_LIGHT_DIRECTIONAL = 2, /* infinitely far, rays travel along direction */
    CG_LIGHT_SPOT = 3         /* at position, cone around direction */
} cg_light_kind;

typedef struct cg_light {
    cg_light_kind kind;
    cg_vec3 color;          /* linear RGB intensity Il (or Ia), components >= 0 */
    cg_vec3 position;       /* point and spot lights */
    cg_vec3 direction;      /* UNIT vector: directional lights: the direction the
                            light travels (from the light into the scene);
                            spot lights: the cone axis, pointing away from it */
    double attenuation[3];  /* c0, c1, c2 of f_att (point and spot); {1, 0, 0}: none */
    double spot_cos_cutoff; /* cos of the cone's half-angle (spot) */
    double spot_exponent;   /* e, concentration of the beam (spot), >= 0 */
} cg_light;

/* The three terms of the model separately; their sum is the shade. */
typedef struct cg_shade_terms {
    cg_vec3 ambient, diffuse, specular;
} cg_shade_terms;

/* ---- constructors ------------------------------------------------------- */

/* A material with specular colour white and the Phong specular model. */
cg_material cg_material_make(cg_vec3 color, double ka, double kd, double ks, double shininess);

cg_light cg_light_ambient(cg_vec3 color);
/* Unattenuated; set attenuation[] afterwards (or use cg_light_set_attenuation). */
cg_light cg_light_point(cg_vec3 position, cg_vec3 color);
/* direction: the way the light travels, any length > 0 (normalized here). */
cg_light cg_light_directional(cg_vec3 direction, cg_vec3 color);
/* axis: any length > 0; cutoff: half-angle of the cone in radians, in (0, pi];
 * exponent >= 0 (0 = uniform cone). */
cg_light cg_light_spot(cg_vec3 position, cg_vec3 axis, double cutoff, double exponent,
                       cg_vec3 color);
void cg_light_set_attenuation(cg_light *light, double c0, double c1, double c2);

/* CG_EINVAL (with a message naming the field) for a NaN or infinite value, a
 * negative colour component or coefficient, a non-unit direction, an unknown
 * kind, or attenuation coefficients that are all zero or negative.
 * err may be NULL. */
cg_status cg_light_check(const cg_light *light, cg_error *err);
cg_status cg_material_check(const cg_material *material, cg_error *err);

/* ---- shading ------------------------------------------------------------ */

/* The intensity (linear RGB) leaving position toward the viewer.
 * normal and view are unit vectors; view points from the surface toward the
 * eye.  The normal is used as given: for two-sided surfaces pass
 * cg_light_face_forward(normal, view). */
cg_vec3 cg_light_shade(cg_vec3 position, cg_vec3 normal, cg_vec3 view, const cg_material *material,
                       const cg_light *lights, size_t count);

/* The same with the terms kept apart, and an optional visibility per light
 * (visibility[i] in [0, 1] scales light i's diffuse and specular terms: the
 * ray tracer's shadow factor; ambient lights ignore it).  visibility may be
 * NULL (all lights visible). */
cg_shade_terms cg_light_shade_terms(cg_vec3 position, cg_vec3 normal, cg_vec3 view,
                                    const cg_material *material, const cg_light *lights,
                                    size_t count, const double *visibility);

/* The unit vector from position toward the light and the distance to it
 * (INFINITY for directional lights), for shadow rays.  Returns 0 for an
 * ambient light or when position coincides with the light (nothing to
 * trace), 1 otherwise. */
int cg_light_vector(const cg_light *light, cg_vec3 position, cg_vec3 *to_light, double *distance);

/* normal, or -normal when it faces away from the viewer (N.V < 0). */
static inline cg_vec3 cg_light_face_forward(cg_vec3 normal, cg_vec3 view)
{
    return cg_vec3_dot(normal, view) < 0 ? cg_vec3_scale(normal, -1.0) : normal;
}

/* Sum of the three terms. */
static inline cg_vec3 cg_shade_terms_sum(cg_shade_terms t)
{
    return cg_vec3_add(cg_vec3_add(t.ambient, t.diffuse), t.specular);
}

#ifdef __cplusplus
}
#endif
#endif
