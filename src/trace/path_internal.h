/* Private pieces of the path tracer's files. */
#ifndef CG_TRACE_PATH_INTERNAL_H
#define CG_TRACE_PATH_INTERNAL_H

#include "cg/pathtrace.h"
#include "internal.h"

/* The random numbers of one sample of one pixel. */
typedef struct path_sampler {
    uint64_t seed, pixel, sample, dimension;
} path_sampler;

/* The pixel offset in [0, 1)^2 of sample k: the R2 sequence shifted by a
 * hash of (seed, pixel). */
void path_pixel_offset(const path_sampler *s, double *dx, double *dy);
/* The next dimension's number in [0, 1), a hash of (seed, pixel, sample,
 * dimension). */
double path_next(path_sampler *s);

/* The emitters as lights (path_lights.c): every triangle of a mesh whose
 * material emits, with the cumulative sums of area times emitted luminance
 * (cdf[count - 1] == total).  Empty (count 0) when nothing emits. */
typedef struct path_lights {
    uint32_t *triangles; /* indices into the scene's triangles */
    double *cdf;
    size_t count;
    double total;
} path_lights;

/* Rec. 709 luminance of a linear colour, 0 when not positive. */
double path_luminance(cg_vec3 c);
/* Collects the built scene's emissive triangles; CG_ENOMEM. */
cg_status path_lights_build(const cg_trace_scene *scene, path_lights *out);
void path_lights_free(path_lights *lights);
/* The area density (1 / length^2) with which the list samples a point of
 * object o: its emitted luminance over total; 0 when o is not listed. */
double path_lights_pdf_area(const path_lights *lights, const trace_object *o);
/* The power-heuristic weight of an emitter's radiance met by a ray that
 * BSDF sampling chose with solid-angle density bsdf_pdf, after distance,
 * arriving at cosine cos_light to the emitter's normal: 1 when o is not on
 * the list. */
double path_lights_hit_weight(const path_lights *lights, const trace_object *o, double bsdf_pdf,
                              double distance, double cos_light);
/* One emitter point for the diffuse lobe at hit (shading normal n,
 * geometric ng, lobe probability diffuse): the MIS-weighted estimate of
 * the irradiance sum Le cos / pdf over the emitters, to be multiplied by
 * diffuse * albedo / pi.  Draws three numbers when the list is not empty. */
cg_vec3 path_lights_direct(const cg_trace_scene *scene, const path_lights *lights,
                           const trace_hit *hit, cg_vec3 n, cg_vec3 ng, double diffuse,
                           path_sampler *rng);

/* The radiance arriving along the ray (unit direction); lights NULL or
 * empty: emitters count only where paths meet them. */
cg_vec3 path_radiance(const cg_trace_scene *scene, const path_lights *lights,
                      const cg_path_options *options, cg_vec3 origin, cg_vec3 direction,
                      path_sampler *rng);

#endif
