/* The path tracer's integrator: next-event estimation toward the scene's
 * lights and emitters (MIS-weighted against BSDF sampling), BSDF-sampled
 * continuation, Russian roulette. */
#include "path_internal.h"

#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* The material as a mixture of lobes with weights summing to 1. */
typedef struct path_surface {
    cg_vec3 albedo;
    double diffuse, mirror, glass, ior;
} path_surface;

static double clamp01(double v)
{
    return v > 0 ? (v < 1 ? v : 1) : 0;
}

/* The surface of material m whose colour at the hit is color (the
 * checker's cell, when the material has one). */
static path_surface surface_of(const cg_material *m, cg_vec3 color)
{
    path_surface s;
    double kd = m->kd;
    s.albedo = cg_vec3_make(clamp01(color.x * kd), clamp01(color.y * kd), clamp01(color.z * kd));
    s.mirror = clamp01(m->reflectance);
    s.glass = clamp01(m->transmittance);
    if (s.mirror + s.glass > 1) {
        double t = s.mirror + s.glass;
        s.mirror /= t;
        s.glass /= t;
    }
    s.diffuse = 1 - s.mirror - s.glass;
    s.ior = m->refractive_index > 0 ? m->refractive_index : 1;
    return s;
}

static double falloff(const cg_light *l, double d)
{
    const double *a = l->attenuation;
    if (a[0] == 1 && a[1] == 0 && a[2] == 0)
        return d * d;
    return a[0] + a[1] * d + a[2] * d * d;
}

/* Irradiance at p (normal n) from light i along a visible shadow ray. */
static cg_vec3 light_irradiance(const cg_trace_scene *scene, const trace_hit *hit, cg_vec3 n,
                                const cg_light *l)
{
    cg_vec3 p = hit->point, to;
    double dist, scale = 1;
    if (l->kind == CG_LIGHT_DIRECTIONAL) {
        to = cg_vec3_scale(l->direction, -1);
        dist = INFINITY;
    } else if (l->kind == CG_LIGHT_POINT || l->kind == CG_LIGHT_SPOT) {
        to = cg_vec3_sub(l->position, p);
        dist = cg_vec3_length(to);
        if (!(dist > 0))
            return cg_vec3_make(0, 0, 0);
        to = cg_vec3_scale(to, 1 / dist);
        double f = falloff(l, dist);
        scale = f > 0 ? 1 / f : 0;
        if (l->kind == CG_LIGHT_SPOT) {
            double c = -cg_vec3_dot(to, l->direction);
            scale *= c >= l->spot_cos_cutoff ? pow(c > 0 ? c : 0, l->spot_exponent) : 0;
        }
    } else {
        return cg_vec3_make(0, 0, 0);
    }
    double cosine = cg_vec3_dot(n, to);
    if (!(cosine > 0) || scale == 0)
        return cg_vec3_make(0, 0, 0);
    cg_vec3 o = trace_offset(hit, n);
    if (trace_occluded(scene, o, to, 0, dist))
        return cg_vec3_make(0, 0, 0);
    return cg_vec3_scale(l->color, cosine * scale);
}

/* Irradiance from one uniformly chosen point of each area light. */
static cg_vec3 area_irradiance(const cg_trace_scene *scene, const trace_hit *hit, cg_vec3 n,
                               const cg_trace_area_light *l, path_sampler *rng)
{
    double s = path_next(rng), t = path_next(rng);
    cg_vec3 q = cg_vec3_add(l->corner,
                            cg_vec3_add(cg_vec3_scale(l->edge_u, s), cg_vec3_scale(l->edge_v, t)));
    cg_vec3 cross = cg_vec3_cross(l->edge_u, l->edge_v);
    double area = cg_vec3_length(cross);
    cg_vec3 to = cg_vec3_sub(q, hit->point);
    double dist = cg_vec3_length(to);
    if (!(area > 0) || !(dist > 0))
        return cg_vec3_make(0, 0, 0);
    to = cg_vec3_scale(to, 1 / dist);
    double cos_s = cg_vec3_dot(n, to), cos_l = fabs(cg_vec3_dot(cross, to)) / area;
    if (!(cos_s > 0))
        return cg_vec3_make(0, 0, 0);
    cg_vec3 o = trace_offset(hit, n);
    if (trace_occluded(scene, o, to, 0, dist * (1 - 1e-7)))
        return cg_vec3_make(0, 0, 0);
    return cg_vec3_scale(l->color, cos_s * cos_l * area / (dist * dist));
}

static cg_vec3 direct(const cg_trace_scene *scene, const trace_hit *hit, cg_vec3 n,
                      path_sampler *rng)
{
    cg_vec3 e = cg_vec3_make(0, 0, 0);
    for (size_t i = 0; i < scene->light_count; i++)
        e = cg_vec3_add(e, light_irradiance(scene, hit, n, &scene->lights[i]));
    for (size_t i = 0; i < scene->area_light_count; i++)
        e = cg_vec3_add(e, area_irradiance(scene, hit, n, &scene->area_lights[i], rng));
    return e;
}

/* A cosine-distributed direction about unit n. */
static cg_vec3 cosine_direction(cg_vec3 n, double u1, double u2)
{
    cg_vec3 a = fabs(n.x) > 0.5 ? cg_vec3_make(0, 1, 0) : cg_vec3_make(1, 0, 0);
    cg_vec3 t = cg_vec3_normalize(cg_vec3_cross(a, n));
    cg_vec3 b = cg_vec3_cross(n, t);
    double r = sqrt(u1), phi = 2 * M_PI * u2;
    double z = sqrt(1 - u1 > 0 ? 1 - u1 : 0);
    return cg_vec3_normalize(
        cg_vec3_add(cg_vec3_add(cg_vec3_scale(t, r * cos(phi)), cg_vec3_scale(b, r * sin(phi))),
                    cg_vec3_scale(n, z)));
}

/* Exact Fresnel reflectance of unpolarized light, cos_i > 0, eta = n1 / n2. */
static double fresnel(double cos_i, double eta, double *cos_t)
{
    double sin2_t = eta * eta * (1 - cos_i * cos_i);
    if (sin2_t >= 1)
        return 1;
    double ct = sqrt(1 - sin2_t);
    *cos_t = ct;
    double rs = (eta * cos_i - ct) / (eta * cos_i + ct);
    double rp = (eta * ct - cos_i) / (eta * ct + cos_i);
    return 0.5 * (rs * rs + rp * rp);
}

/* The glass lobe: the next direction (reflected or refracted). */
static cg_vec3 glass_direction(cg_vec3 d, cg_vec3 n, int entering, double ior, double u,
                               cg_vec3 *offset_normal)
{
    double eta = entering ? 1 / ior : ior, cos_i = -cg_vec3_dot(d, n), cos_t = 0;
    double f = fresnel(cos_i, eta, &cos_t);
    if (u < f) {
        *offset_normal = n;
        return cg_vec3_normalize(cg_reflect(d, n));
    }
    *offset_normal = cg_vec3_scale(n, -1);
    return cg_vec3_normalize(
        cg_vec3_add(cg_vec3_scale(d, eta), cg_vec3_scale(n, eta * cos_i - cos_t)));
}

/* The sky seen along unit direction d: the uniform environment, or the
 * equirectangular map's bilinear value there (u wraps, v clamps). */
static cg_vec3 environment_radiance(const cg_path_options *options, cg_vec3 d)
{
    const cg_image *map = options->environment_map;
    if (!map)
        return options->environment;
    if (map->width == 1 && map->height == 1) { /* a uniform sky, exactly */
        cg_rgbaf c = cg_image_get(map, 0, 0);
        return cg_vec3_scale(cg_vec3_make(c.r, c.g, c.b), options->environment_intensity);
    }
    double y = d.y < -1 ? -1 : (d.y > 1 ? 1 : d.y);
    double u = 0.5 + atan2(d.x, -d.z) / (2 * M_PI), v = acos(y) / M_PI;
    double fx = u * map->width - 0.5, fy = v * map->height - 0.5;
    int x0 = (int)floor(fx), y0 = (int)floor(fy);
    double tx = fx - x0, ty = fy - y0;
    cg_vec3 sum = cg_vec3_make(0, 0, 0);
    for (int k = 0; k < 4; k++) {
        int x = x0 + (k & 1), row = y0 + (k >> 1);
        x = ((x % map->width) + map->width) % map->width;
        row = row < 0 ? 0 : (row >= map->height ? map->height - 1 : row);
        double w = ((k & 1) ? tx : 1 - tx) * ((k >> 1) ? ty : 1 - ty);
        cg_rgbaf c = cg_image_get(map, x, row);
        sum = cg_vec3_add(sum, cg_vec3_scale(cg_vec3_make(c.r, c.g, c.b), w));
    }
    return cg_vec3_scale(sum, options->environment_intensity);
}

/* The continuation of the path at a hit: the next direction and the
 * throughput's factor; *pdf the solid-angle density of a diffuse choice
 * (0: a specular lobe).  0 when the path ends. */
static int continue_path(const path_surface *s, const trace_hit *hit, cg_vec3 n, cg_vec3 ng,
                         int entering, cg_vec3 *direction, cg_vec3 *weight, cg_vec3 *origin,
                         double *pdf, path_sampler *rng)
{
    double u = path_next(rng), u1 = path_next(rng), u2 = path_next(rng);
    cg_vec3 offset_normal = ng;
    *pdf = 0;
    if (u < s->diffuse) {
        *direction = cosine_direction(n, u1, u2);
        if (cg_vec3_dot(*direction, ng) <= 0)
            return 0;
        *weight = cg_vec3_mul(*weight, s->albedo);
        *pdf = s->diffuse * cg_vec3_dot(*direction, n) / M_PI;
    } else if (u < s->diffuse + s->mirror) {
        *direction = cg_vec3_normalize(cg_reflect(*direction, n));
    } else {
        *direction = glass_direction(*direction, n, entering, s->ior, u1, &offset_normal);
    }
    *origin = trace_offset(hit, offset_normal);
    return 1;
}

cg_vec3 path_radiance(const cg_trace_scene *scene, const path_lights *lights,
                      const cg_path_options *options, cg_vec3 origin, cg_vec3 direction,
                      path_sampler *rng)
{
    cg_vec3 sum = cg_vec3_make(0, 0, 0), weight = cg_vec3_make(1, 1, 1);
    path_lights none = {0};
    if (!lights)
        lights = &none;
    double bsdf_pdf = 0; /* of the ray being traced; 0: the camera's or a specular one */
    for (int depth = 0;; depth++) {
        trace_hit hit;
        if (!trace_intersect(scene, origin, direction, 0, INFINITY, &hit))
            return cg_vec3_add(sum, cg_vec3_mul(weight, environment_radiance(options, direction)));
        if (depth >= options->max_depth)
            return sum;
        const trace_object *object = &scene->objects[hit.object];
        double mis = bsdf_pdf > 0 ? path_lights_hit_weight(lights, object, bsdf_pdf, hit.t,
                                                           cg_vec3_dot(direction, hit.normal))
                                  : 1;
        sum = cg_vec3_add(sum, cg_vec3_mul(weight, cg_vec3_scale(object->material.emission, mis)));
        path_surface s = surface_of(&object->material.surface,
                                    trace_surface_color(object, hit.point));
        int entering = cg_vec3_dot(direction, hit.normal) < 0;
        cg_vec3 ng = entering ? hit.normal : cg_vec3_scale(hit.normal, -1);
        cg_vec3 n = cg_vec3_dot(hit.smooth_normal, ng) > 0 ? hit.smooth_normal : ng;
        if (s.diffuse > 0) {
            cg_vec3 e = direct(scene, &hit, ng, rng);
            /* An emitter met by the next ray counts only below the depth. */
            if (depth + 1 < options->max_depth)
                e = cg_vec3_add(e, path_lights_direct(scene, lights, &hit, n, ng, s.diffuse, rng));
            sum = cg_vec3_add(sum, cg_vec3_mul(weight, cg_vec3_scale(cg_vec3_mul(s.albedo, e),
                                                                     s.diffuse / M_PI)));
        }
        if (!continue_path(&s, &hit, n, ng, entering, &direction, &weight, &origin, &bsdf_pdf, rng))
            return sum;
        if (depth >= 3) {
            double m = weight.x > weight.y ? weight.x : weight.y;
            double q = m > weight.z ? m : weight.z;
            q = q < 0.95 ? q : 0.95;
            if (path_next(rng) >= q)
                return sum;
            weight = cg_vec3_scale(weight, 1 / q);
        }
    }
}
