/* Local illumination: ambient + Lambert diffuse + Phong / Blinn-Phong
 * specular, summed over point, directional and spot lights (chapter 6). */
#include "cg/light.h"

#include <math.h>

cg_material cg_material_make(cg_vec3 color, double ka, double kd, double ks, double shininess)
{
    cg_material m = {0};
    m.color = color;
    m.specular_color = cg_vec3_make(1, 1, 1);
    m.ka = ka;
    m.kd = kd;
    m.ks = ks;
    m.shininess = shininess;
    m.specular = CG_SPECULAR_PHONG;
    return m;
}

static cg_light light_base(cg_light_kind kind, cg_vec3 color)
{
    cg_light l = {0};
    l.kind = kind;
    l.color = color;
    l.attenuation[0] = 1;
    l.spot_cos_cutoff = -1;
    return l;
}

cg_light cg_light_ambient(cg_vec3 color)
{
    return light_base(CG_LIGHT_AMBIENT, color);
}

cg_light cg_light_point(cg_vec3 position, cg_vec3 color)
{
    cg_light l = light_base(CG_LIGHT_POINT, color);
    l.position = position;
    return l;
}

cg_light cg_light_directional(cg_vec3 direction, cg_vec3 color)
{
    cg_light l = light_base(CG_LIGHT_DIRECTIONAL, color);
    l.direction = cg_vec3_normalize(direction);
    return l;
}

cg_light cg_light_spot(cg_vec3 position, cg_vec3 axis, double cutoff, double exponent,
                       cg_vec3 color)
{
    cg_light l = light_base(CG_LIGHT_SPOT, color);
    l.position = position;
    l.direction = cg_vec3_normalize(axis);
    l.spot_cos_cutoff = cos(cutoff);
    l.spot_exponent = exponent;
    return l;
}

void cg_light_set_attenuation(cg_light *light, double c0, double c1, double c2)
{
    light->attenuation[0] = c0;
    light->attenuation[1] = c1;
    light->attenuation[2] = c2;
}

static int finite3(cg_vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

static int color_ok(cg_vec3 c)
{
    return finite3(c) && c.x >= 0 && c.y >= 0 && c.z >= 0;
}

static int unit_ok(cg_vec3 v)
{
    return finite3(v) && fabs(cg_vec3_length(v) - 1) <= 1e-6;
}

cg_status cg_light_check(const cg_light *light, cg_error *err)
{
    if (!light)
        return cg_error_set(err, CG_EINVAL, "light: none given");
    if (light->kind < CG_LIGHT_AMBIENT || light->kind > CG_LIGHT_SPOT)
        return cg_error_set(err, CG_EINVAL, "light: unknown kind %d", (int)light->kind);
    if (!color_ok(light->color))
        return cg_error_set(err, CG_EINVAL,
                            "light: colour must be finite and >= 0, got (%g, %g, %g)",
                            light->color.x, light->color.y, light->color.z);
    if (light->kind == CG_LIGHT_AMBIENT)
        return CG_OK;
    if (light->kind != CG_LIGHT_DIRECTIONAL && !finite3(light->position))
        return cg_error_set(err, CG_EINVAL, "light: position must be finite");
    if (light->kind != CG_LIGHT_POINT && !unit_ok(light->direction))
        return cg_error_set(err, CG_EINVAL,
                            "light: direction must be a finite unit vector, got (%g, %g, %g)",
                            light->direction.x, light->direction.y, light->direction.z);
    if (light->kind != CG_LIGHT_DIRECTIONAL) {
        const double *c = light->attenuation;
        for (int i = 0; i < 3; i++)
            if (!isfinite(c[i]) || c[i] < 0)
                return cg_error_set(err, CG_EINVAL,
                                    "light: attenuation coefficient c%d must be finite and >= 0, "
                                    "got %g",
                                    i, c[i]);
        if (c[0] == 0 && c[1] == 0 && c[2] == 0)
            return cg_error_set(err, CG_EINVAL, "light: attenuation coefficients are all zero");
    }
    if (light->kind == CG_LIGHT_SPOT) {
        if (!isfinite(light->spot_cos_cutoff) || light->spot_cos_cutoff < -1
            || light->spot_cos_cutoff > 1)
            return cg_error_set(err, CG_EINVAL, "light: spot cutoff cosine must be in [-1, 1]");
        if (!isfinite(light->spot_exponent) || light->spot_exponent < 0)
            return cg_error_set(err, CG_EINVAL, "light: spot exponent must be finite and >= 0");
    }
    return CG_OK;
}

cg_status cg_material_check(const cg_material *m, cg_error *err)
{
    if (!m)
        return cg_error_set(err, CG_EINVAL, "material: none given");
    if (!color_ok(m->color))
        return cg_error_set(err, CG_EINVAL,
                            "material: colour must be finite and >= 0, got (%g, %g, %g)",
                            m->color.x, m->color.y, m->color.z);
    if (!color_ok(m->specular_color))
        return cg_error_set(err, CG_EINVAL, "material: specular colour must be finite and >= 0");
    const double k[7] = {
        m->ka, m->kd, m->ks, m->shininess, m->reflectance, m->transmittance, m->refractive_index};
    static const char *names[7] = {
        "ka", "kd", "ks", "shininess", "reflectance", "transmittance", "refractive index"};
    for (int i = 0; i < 7; i++)
        if (!isfinite(k[i]) || k[i] < 0)
            return cg_error_set(err, CG_EINVAL, "material: %s must be finite and >= 0, got %g",
                                names[i], k[i]);
    if (m->specular != CG_SPECULAR_PHONG && m->specular != CG_SPECULAR_BLINN)
        return cg_error_set(err, CG_EINVAL, "material: unknown specular model %d",
                            (int)m->specular);
    return CG_OK;
}

int cg_light_vector(const cg_light *light, cg_vec3 position, cg_vec3 *to_light, double *distance)
{
    if (light->kind == CG_LIGHT_AMBIENT)
        return 0;
    if (light->kind == CG_LIGHT_DIRECTIONAL) {
        *to_light = cg_vec3_scale(light->direction, -1.0);
        *distance = INFINITY;
        return 1;
    }
    cg_vec3 d = cg_vec3_sub(light->position, position);
    double length = cg_vec3_length(d);
    if (!(length > 0))
        return 0;
    *to_light = cg_vec3_scale(d, 1.0 / length);
    *distance = length;
    return 1;
}

/* x^n for x in [0, 1]; 0^0 is taken as 1 (a shininess of 0 gives a constant
 * specular term where the light is in front). */
static double power(double x, double n)
{
    if (n == 1)
        return x;
    if (n == 2)
        return x * x;
    return pow(x, n);
}

cg_shade_terms cg_light_shade_terms(cg_vec3 position, cg_vec3 normal, cg_vec3 view,
                                    const cg_material *m, const cg_light *lights, size_t count,
                                    const double *visibility)
{
    double ar = 0, ag = 0, ab = 0; /* sum of ambient intensities */
    double dr = 0, dg = 0, db = 0; /* sum of Il f spot (N.L) */
    double sr = 0, sg = 0, sb = 0; /* sum of Il f spot spec */
    for (size_t i = 0; i < count; i++) {
        const cg_light *l = &lights[i];
        if (l->kind == CG_LIGHT_AMBIENT) {
            ar += l->color.x;
            ag += l->color.y;
            ab += l->color.z;
            continue;
        }
        cg_vec3 L;
        double scale = visibility ? visibility[i] : 1.0;
        if (l->kind == CG_LIGHT_DIRECTIONAL) {
            L = cg_vec3_make(-l->direction.x, -l->direction.y, -l->direction.z);
        } else {
            cg_vec3 d = cg_vec3_sub(l->position, position);
            double d2 = cg_vec3_dot(d, d);
            if (!(d2 > 0))
                continue; /* the point is at the light: no direction */
            double dist = sqrt(d2);
            L = cg_vec3_scale(d, 1.0 / dist);
            double denom = l->attenuation[0] + l->attenuation[1] * dist + l->attenuation[2] * d2;
            if (denom > 1)
                scale /= denom;
            if (l->kind == CG_LIGHT_SPOT) {
                double c = -cg_vec3_dot(L, l->direction);
                if (!(c >= l->spot_cos_cutoff))
                    continue; /* outside the cone */
                if (l->spot_exponent != 0)
                    scale *= c > 0 ? power(c, l->spot_exponent) : 0;
            }
        }
        double nl = cg_vec3_dot(normal, L);
        if (!(nl > 0) || !(scale > 0))
            continue; /* light behind the surface, or shadowed */
        double spec;
        if (m->specular == CG_SPECULAR_BLINN) {
            cg_vec3 h = cg_vec3_add(L, view);
            double hl = cg_vec3_length(h);
            double nh = hl > 0 ? cg_vec3_dot(normal, h) / hl : 0;
            spec = nh > 0 ? power(nh, m->shininess) : 0;
        } else {
            /* R = 2 (N.L) N - L;  R.V = 2 (N.L)(N.V) - L.V */
            double rv = 2 * nl * cg_vec3_dot(normal, view) - cg_vec3_dot(L, view);
            spec = rv > 0 ? power(rv > 1 ? 1 : rv, m->shininess) : 0;
        }
        double wd = scale * nl;
        dr += l->color.x * wd;
        dg += l->color.y * wd;
        db += l->color.z * wd;
        if (spec > 0) {
            double ws = scale * spec;
            sr += l->color.x * ws;
            sg += l->color.y * ws;
            sb += l->color.z * ws;
        }
    }
    cg_shade_terms t;
    t.ambient = cg_vec3_make(m->ka * m->color.x * ar, m->ka * m->color.y * ag,
                             m->ka * m->color.z * ab);
    t.diffuse = cg_vec3_make(m->kd * m->color.x * dr, m->kd * m->color.y * dg,
                             m->kd * m->color.z * db);
    t.specular = cg_vec3_make(m->ks * m->specular_color.x * sr, m->ks * m->specular_color.y * sg,
                              m->ks * m->specular_color.z * sb);
    return t;
}

cg_vec3 cg_light_shade(cg_vec3 position, cg_vec3 normal, cg_vec3 view, const cg_material *m,
                       const cg_light *lights, size_t count)
{
    return cg_shade_terms_sum(cg_light_shade_terms(position, normal, view, m, lights, count, NULL));
}
