/* The path tracer's emitters as lights: every triangle of an emissive mesh,
 * chosen with probability proportional to its area times its emitted
 * luminance, a point on it uniformly, and the multiple importance sampling
 * weights (power heuristic) between that and BSDF sampling. */
#include "path_internal.h"

#include <math.h>
#include <stdlib.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

double path_luminance(cg_vec3 c)
{
    double y = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
    return y > 0 && isfinite(y) ? y : 0;
}

/* The object's emitted luminance when it is on the light list, else 0. */
static double listed_luminance(const trace_object *o)
{
    return o->kind == TRACE_MESH ? path_luminance(o->material.emission) : 0;
}

static double triangle_area(const cg_trace_scene *scene, size_t t, cg_vec3 *normal)
{
    const uint32_t *i = scene->indices + 3 * t;
    cg_vec3 a = scene->positions[i[0]], b = scene->positions[i[1]], c = scene->positions[i[2]];
    cg_vec3 n = cg_vec3_cross(cg_vec3_sub(b, a), cg_vec3_sub(c, a));
    double twice = cg_vec3_length(n);
    if (!(twice > 0) || !isfinite(twice))
        return 0;
    if (normal)
        *normal = cg_vec3_scale(n, 1 / twice);
    return 0.5 * twice;
}

cg_status path_lights_build(const cg_trace_scene *scene, path_lights *out)
{
    path_lights l = {0};
    for (size_t i = 0; i < scene->object_count; i++)
        if (listed_luminance(&scene->objects[i]) > 0)
            l.count += scene->objects[i].triangle_count;
    if (l.count == 0) {
        *out = l;
        return CG_OK;
    }
    l.triangles = malloc(l.count * sizeof *l.triangles);
    l.cdf = malloc(l.count * sizeof *l.cdf);
    if (!l.triangles || !l.cdf) {
        path_lights_free(&l);
        return CG_ENOMEM;
    }
    size_t k = 0;
    double total = 0;
    for (size_t i = 0; i < scene->object_count; i++) {
        const trace_object *o = &scene->objects[i];
        double y = listed_luminance(o);
        if (!(y > 0))
            continue;
        for (size_t t = o->first_triangle; t < o->first_triangle + o->triangle_count; t++) {
            total += triangle_area(scene, t, NULL) * y;
            l.triangles[k] = (uint32_t)t;
            l.cdf[k++] = total;
        }
    }
    l.total = total;
    if (!(total > 0) || !isfinite(total)) /* only degenerate triangles */
        path_lights_free(&l);
    *out = l;
    return CG_OK;
}

void path_lights_free(path_lights *l)
{
    free(l->triangles);
    free(l->cdf);
    l->triangles = NULL;
    l->cdf = NULL;
    l->count = 0;
    l->total = 0;
}

double path_lights_pdf_area(const path_lights *l, const trace_object *o)
{
    return l->count ? listed_luminance(o) / l->total : 0;
}

/* The first entry whose cumulative weight exceeds x (x in [0, total)):
 * entries of zero weight are never chosen. */
static size_t pick(const path_lights *l, double x)
{
    size_t lo = 0, hi = l->count - 1;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (l->cdf[mid] > x)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

static double power_heuristic(double a, double b)
{
    return a * a / (a * a + b * b);
}

double path_lights_hit_weight(const path_lights *l, const trace_object *o, double bsdf_pdf,
                              double distance, double cos_light)
{
    double area_pdf = path_lights_pdf_area(l, o);
    if (!(area_pdf > 0))
        return 1;
    double c = fabs(cos_light);
    if (!(c > 0))
        return 1;
    return power_heuristic(bsdf_pdf, area_pdf * distance * distance / c);
}

cg_vec3 path_lights_direct(const cg_trace_scene *scene, const path_lights *l, const trace_hit *hit,
                           cg_vec3 n, cg_vec3 ng, double diffuse, path_sampler *rng)
{
    cg_vec3 zero = cg_vec3_make(0, 0, 0);
    if (!l->count)
        return zero;
    double u0 = path_next(rng), u1 = path_next(rng), u2 = path_next(rng);
    size_t k = pick(l, u0 * l->total);
    uint32_t t = l->triangles[k];
    cg_vec3 nl;
    if (!(triangle_area(scene, t, &nl) > 0))
        return zero;
    const uint32_t *i = scene->indices + 3 * (size_t)t;
    cg_vec3 a = scene->positions[i[0]], b = scene->positions[i[1]], c = scene->positions[i[2]];
    double r = sqrt(u1);
    cg_vec3 q = cg_vec3_add(cg_vec3_scale(a, 1 - r),
                            cg_vec3_add(cg_vec3_scale(b, r * (1 - u2)), cg_vec3_scale(c, r * u2)));
    /* From the offset origin, so that the emitter lies at dist along the
     * ray; a margin of 1e-4 dist keeps the float triangle test off it. */
    cg_vec3 o = trace_offset(hit, ng);
    cg_vec3 to = cg_vec3_sub(q, o);
    double dist = cg_vec3_length(to);
    if (!(dist > 0) || !isfinite(dist))
        return zero;
    to = cg_vec3_scale(to, 1 / dist);
    double cos_s = cg_vec3_dot(n, to), cos_l = fabs(cg_vec3_dot(nl, to));
    if (!(cos_s > 0) || !(cg_vec3_dot(ng, to) > 0) || !(cos_l > 0))
        return zero;
    const trace_object *emitter = &scene->objects[scene->triangle_object[t]];
    double area_pdf = path_lights_pdf_area(l, emitter);
    double light_pdf = area_pdf * dist * dist / cos_l, bsdf_pdf = diffuse * cos_s / M_PI;
    if (trace_occluded(scene, o, to, 0, dist * (1 - 1e-4)))
        return zero;
    double w = power_heuristic(light_pdf, bsdf_pdf);
    return cg_vec3_scale(emitter->material.emission, w * cos_s / light_pdf);
}
