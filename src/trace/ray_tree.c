/* One pixel's ray tree (cg/trace_steps.h): render.c reports each ray it
 * traces, each light it looks for and each split between reflection and
 * refraction as it shades, so the tree is the renderer's own.  The rays are
 * kept and given out in the order they were started (a ray before the rays
 * it spawns):
 *
 *         primary --hit--> local light (a shadow ray per light)
 *            |  \\
 *            |   +-- reflected, weight kr (mirror; plus kt F from Fresnel)
 *            +------ refracted, weight kt (1 - F) (Snell; none on total
 *                    internal reflection)
 *
 *   colour = local + kr colour(reflected) + kt colour(refracted) */
#include "internal.h"
#include "../core/array.h"
#include "../core/steps.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct ray_node {
    int sample, parent, kind, depth, hit, object_kind, entering, total;
    double weight, t, fresnel, kr, kt;
    cg_vec3 origin, direction, point, normal, local, color;
    int object;
    uint32_t triangle;
} ray_node;

typedef struct shadow_node {
    int ray, kind, check, visible, samples;
    size_t light;
} shadow_node;

struct trace_ray_report {
    const cg_trace_scene *scene;
    int x, y, sample, failed;
    double px, py;
    ray_node *rays;
    size_t ray_count, ray_capacity;
    shadow_node *shadows;
    size_t shadow_count, shadow_capacity;
    int *stack; /* the rays not done, innermost last */
    size_t depth, stack_capacity;
};

trace_ray_report *trace_report_create(const cg_trace_scene *scene, int x, int y)
{
    trace_ray_report *r = calloc(1, sizeof *r);
    if (r) {
        r->scene = scene;
        r->x = x;
        r->y = y;
    }
    return r;
}

void trace_report_free(trace_ray_report *r)
{
    if (!r)
        return;
    free(r->rays);
    free(r->shadows);
    free(r->stack);
    free(r);
}

void trace_report_sample(trace_ray_report *r, int sample, double px, double py)
{
    r->sample = sample;
    r->px = px;
    r->py = py;
}

int trace_report_ray(trace_ray_report *r, trace_ray_kind kind, int depth, double weight,
                     cg_vec3 origin, cg_vec3 direction)
{
    if (r->failed
        || core_array_reserve((void **)&r->rays, &r->ray_capacity, r->ray_count + 1,
                              sizeof *r->rays)
               != CG_OK
        || core_array_reserve((void **)&r->stack, &r->stack_capacity, r->depth + 1,
                              sizeof *r->stack)
               != CG_OK) {
        r->failed = 1;
        return -1;
    }
    ray_node *n = &r->rays[r->ray_count];
    *n = (ray_node){0};
    n->sample = r->sample;
    n->parent = r->depth ? r->stack[r->depth - 1] : -1;
    n->kind = (int)kind;
    n->depth = depth;
    n->weight = weight;
    n->origin = origin;
    n->direction = direction;
    n->fresnel = n->kr = n->kt = NAN;
    r->stack[r->depth++] = (int)r->ray_count;
    return (int)r->ray_count++;
}

void trace_report_hit(trace_ray_report *r, int node, const trace_hit *hit, int object_kind,
                      cg_vec3 normal, int entering)
{
    ray_node *n = &r->rays[node];
    n->hit = 1;
    n->t = hit->t;
    n->point = hit->point;
    n->normal = normal;
    n->object = hit->object;
    n->triangle = hit->triangle;
    n->object_kind = object_kind;
    n->entering = entering;
}

void trace_report_shadow(trace_ray_report *r, size_t light, int light_kind, trace_light_check check,
                         int visible, int samples)
{
    if (r->failed || !r->depth
        || core_array_reserve((void **)&r->shadows, &r->shadow_capacity, r->shadow_count + 1,
                              sizeof *r->shadows)
               != CG_OK) {
        r->failed = 1;
        return;
    }
    r->shadows[r->shadow_count++] = (shadow_node){
        r->stack[r->depth - 1], light_kind, (int)check, visible, samples, light};
}

void trace_report_local(trace_ray_report *r, int node, cg_vec3 local)
{
    r->rays[node].local = local;
}

void trace_report_split(trace_ray_report *r, int node, double fresnel, double kr, double kt,
                        int total)
{
    ray_node *n = &r->rays[node];
    n->fresnel = fresnel;
    n->kr = kr;
    n->kt = kt;
    n->total = total;
}

void trace_report_done(trace_ray_report *r, int node, const trace_hit *hit, cg_vec3 color)
{
    (void)hit;
    r->rays[node].color = color;
    if (r->depth)
        r->depth--;
}

static void vec3_field(core_step *s, const char *name, cg_vec3 v, double *store)
{
    store[0] = v.x;
    store[1] = v.y;
    store[2] = v.z;
    core_step_reals(s, name, store, 3);
}

static void real_or_none(core_step *s, const char *name, double v)
{
    if (isnan(v))
        core_step_none(s, name);
    else
        core_step_real(s, name, v);
}

static const char *const kinds[3] = {"primary", "reflected", "refracted"};

static int emit_ray(const trace_ray_report *r, size_t i, cg_step_fn fn, void *user)
{
    const ray_node *n = &r->rays[i];
    char what[64];
    double a[3], b[3], c[3], d[3];
    static const char *const objects[3] = {"mesh", "sphere", "plane"};
    if (!n->hit)
        snprintf(what, sizeof what, "miss: background");
    else if (n->object_kind == TRACE_MESH)
        snprintf(what, sizeof what, "mesh %d, triangle %u", n->object, n->triangle);
    else
        snprintf(what, sizeof what, "%s %d", objects[n->object_kind % 3], n->object);
    const char *next = !n->hit              ? "-"
                       : isnan(n->kr)       ? "depth limit: no secondary rays"
                       : n->total           ? "total internal reflection"
                       : !isnan(n->fresnel) ? "reflect kr, refract kt"
                       : n->kr > 0          ? "reflect kr"
                                            : "opaque, no mirror";
    cg_vec3 end = n->hit ? n->point : cg_vec3_add(n->origin, n->direction);
    /* seen from the side: -z across (away from a camera looking down -z), y up */
    cg_vec2 line[2] = {cg_vec2_make(-n->origin.z, n->origin.y), cg_vec2_make(-end.z, end.y)};
    core_step s;
    core_step_begin(&s, "rays");
    core_step_integer(&s, "sample", n->sample);
    core_step_integer(&s, "ray", (long long)i);
    if (n->parent >= 0)
        core_step_integer(&s, "parent", n->parent);
    else
        core_step_none(&s, "parent");
    core_step_text(&s, "kind", kinds[n->kind]);
    core_step_integer(&s, "depth", n->depth);
    core_step_real(&s, "weight", n->weight);
    core_step_text(&s, "hit", what);
    if (n->hit) {
        core_step_real(&s, "t", n->t);
        vec3_field(&s, "point", n->point, a);
        vec3_field(&s, "normal", n->normal, b);
        core_step_text(&s, "side", n->entering ? "outside" : "inside");
        vec3_field(&s, "local", n->local, c);
    } else {
        core_step_none(&s, "t");
        core_step_none(&s, "point");
        core_step_none(&s, "normal");
        core_step_none(&s, "side");
        core_step_none(&s, "local");
    }
    real_or_none(&s, "fresnel", n->fresnel);
    real_or_none(&s, "kr", n->kr);
    real_or_none(&s, "kt", n->kt);
    core_step_text(&s, "secondary", next);
    vec3_field(&s, "color", n->color, d);
    s.step.geometry = line;
    s.step.geometry_count = 2;
    s.step.kept = line;
    s.step.kept_count = 2;
    return core_step_emit(&s, fn, user);
}

static int emit_shadow(const trace_ray_report *r, size_t i, cg_step_fn fn, void *user)
{
    const shadow_node *n = &r->shadows[i];
    static const char *const light_kinds[4] = {"ambient", "point", "directional", "spot"};
    char verdict[64];
    switch ((trace_light_check)n->check) {
    case TRACE_LIGHT_AMBIENT: snprintf(verdict, sizeof verdict, "ambient: no shadow ray"); break;
    case TRACE_LIGHT_AWAY:
        snprintf(verdict, sizeof verdict, "faces away (or no diffuse, no specular): none cast");
        break;
    case TRACE_LIGHT_TESTED:
        snprintf(verdict, sizeof verdict, "%s",
                 n->visible ? "reaches the light: lit" : "blocked: in shadow");
        break;
    case TRACE_LIGHT_UNTESTED: snprintf(verdict, sizeof verdict, "shadows off: lit"); break;
    default:
        snprintf(verdict, sizeof verdict, "%d of %d samples reach it", n->visible, n->samples);
        break;
    }
    core_step s;
    core_step_begin(&s, "shadow rays");
    core_step_integer(&s, "ray", n->ray);
    core_step_integer(&s, "light", (long long)n->light);
    core_step_text(&s, "kind", n->check == TRACE_LIGHT_AREA ? "area" : light_kinds[n->kind & 3]);
    core_step_text(&s, "verdict", verdict);
    return core_step_emit(&s, fn, user);
}

cg_status trace_report_emit(trace_ray_report *r, cg_rgbaf pixel, cg_step_fn fn, void *user)
{
    if (r->failed)
        return CG_ENOMEM;
    for (size_t i = 0; i < r->ray_count; i++)
        if (emit_ray(r, i, fn, user))
            return CG_OK;
    for (size_t i = 0; i < r->shadow_count; i++)
        if (emit_shadow(r, i, fn, user))
            return CG_OK;
    double rgba[4] = {pixel.r, pixel.g, pixel.b, pixel.a};
    core_step s;
    core_step_begin(&s, "pixel");
    core_step_pixel(&s, "pixel", r->x, r->y);
    core_step_integer(&s, "rays", (long long)r->ray_count);
    core_step_integer(&s, "shadow_rays", (long long)r->shadow_count);
    core_step_reals(&s, "color", rgba, 4);
    core_step_emit(&s, fn, user); /* no pixel: the frames show the rays in world space */
    return CG_OK;
}
