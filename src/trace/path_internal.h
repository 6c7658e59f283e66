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

/* The radiance arriving along the ray (unit direction). */
cg_vec3 path_radiance(const cg_trace_scene *scene, const cg_path_options *options, cg_vec3 origin,
                      cg_vec3 direction, path_sampler *rng);

#endif
