/* The illumination at a point, light by light (cg/trace_steps.h): the
 * notes' ambient, diffuse and specular terms with the attenuation and spot
 * factors that scale them.  Each light's terms are cg_light_shade_terms of
 * that light alone, the closing step the terms of all of them. */
#include "cg/light.h"
#include "../core/steps.h"

#include <math.h>

static const char *kind_name(cg_light_kind kind)
{
    switch (kind) {
    case CG_LIGHT_AMBIENT: return "ambient";
    case CG_LIGHT_POINT: return "point";
    case CG_LIGHT_DIRECTIONAL: return "directional";
    default: return "spot";
    }
}

static void vector_field(core_step *s, const char *name, cg_vec3 v, double store[3])
{
    store[0] = v.x;
    store[1] = v.y;
    store[2] = v.z;
    core_step_reals(s, name, store, 3);
}

/* The factors of one non-ambient light, for display: f_att, spot, N.L and
 * the specular base (R.V or N.H). */
static void light_factors(const cg_light *l, cg_vec3 position, cg_vec3 normal, cg_vec3 view,
                          const cg_material *m, core_step *s, double (*store)[3])
{
    cg_vec3 to_light;
    double distance;
    if (!cg_light_vector(l, position, &to_light, &distance)) {
        core_step_text(s, "note", "the point is at the light: no direction, no light");
        return;
    }
    double attenuation = 1, spot = 1;
    if (l->kind != CG_LIGHT_DIRECTIONAL) {
        double denom = l->attenuation[0] + l->attenuation[1] * distance
                       + l->attenuation[2] * distance * distance;
        attenuation = denom > 1 ? 1 / denom : 1;
    }
    if (l->kind == CG_LIGHT_SPOT) {
        double c = -cg_vec3_dot(to_light, l->direction);
        spot = c >= l->spot_cos_cutoff
                   ? (l->spot_exponent != 0 ? (c > 0 ? pow(c, l->spot_exponent) : 0) : 1)
                   : 0;
    }
    double nl = cg_vec3_dot(normal, to_light), base;
    vector_field(s, "L", to_light, store[0]);
    core_step_real(s, "distance", distance);
    core_step_real(s, "f_att", attenuation);
    core_step_real(s, "spot", spot);
    core_step_real(s, "N.L", nl);
    if (m->specular == CG_SPECULAR_BLINN) {
        cg_vec3 h = cg_vec3_add(to_light, view);
        double length = cg_vec3_length(h);
        base = length > 0 ? cg_vec3_dot(normal, h) / length : 0;
        vector_field(s, "H", length > 0 ? cg_vec3_scale(h, 1 / length) : h, store[1]);
        core_step_real(s, "N.H", base);
    } else {
        cg_vec3 r = cg_vec3_sub(cg_vec3_scale(normal, 2 * nl), to_light);
        base = cg_vec3_dot(r, view);
        vector_field(s, "R", r, store[1]);
        core_step_real(s, "R.V", base);
    }
    double spec = nl > 0 && base > 0 ? pow(base > 1 ? 1 : base, m->shininess) : 0;
    core_step_real(s, "spec", spec);
    core_step_text(s, "note",
                   nl > 0 ? (spot > 0 ? "lit" : "outside the spot's cone")
                          : "N.L <= 0: the light is behind the surface");
}

cg_status cg_light_steps(cg_vec3 position, cg_vec3 normal, cg_vec3 view,
                         const cg_material *material, const cg_light *lights, size_t count,
                         cg_step_fn step, void *user)
{
    if (!step || !material || (count && !lights) || cg_material_check(material, NULL) != CG_OK)
        return CG_EINVAL;
    for (size_t i = 0; i < count; i++)
        if (cg_light_check(&lights[i], NULL) != CG_OK)
            return CG_EINVAL;
    for (size_t i = 0; i < count; i++) {
        const cg_light *l = &lights[i];
        cg_shade_terms t = cg_light_shade_terms(position, normal, view, material, l, 1, NULL);
        double store[7][3]; /* rows 0-1: light_factors; 2, 4-6: the terms */
        core_step s;
        core_step_begin(&s, "lights");
        core_step_integer(&s, "light", (long long)i);
        core_step_text(&s, "kind", kind_name(l->kind));
        vector_field(&s, "I_l", l->color, store[4]);
        if (l->kind != CG_LIGHT_AMBIENT)
            light_factors(l, position, normal, view, material, &s, store);
        vector_field(&s, "ambient", t.ambient, store[5]);
        vector_field(&s, "diffuse", t.diffuse, store[6]);
        vector_field(&s, "specular", t.specular, store[2]);
        if (core_step_emit(&s, step, user))
            return CG_OK;
    }
    cg_shade_terms all = cg_light_shade_terms(position, normal, view, material, lights, count,
                                              NULL);
    cg_vec3 total = cg_vec3_add(all.ambient, cg_vec3_add(all.diffuse, all.specular));
    double store[4][3];
    core_step s;
    core_step_begin(&s, "total");
    vector_field(&s, "ambient", all.ambient, store[0]);
    vector_field(&s, "diffuse", all.diffuse, store[1]);
    vector_field(&s, "specular", all.specular, store[2]);
    vector_field(&s, "I", total, store[3]);
    core_step_emit(&s, step, user);
    return CG_OK;
}
