/* cg/pathtrace.h - unidirectional path tracing over a cg_trace_scene.
 *
 * Radiance is estimated per pixel by tracing paths from the camera:
 * next-event estimation toward every point, spot, directional and area light
 * of the scene and toward the triangles of emissive meshes (one point per
 * bounce, chosen by area times emitted luminance, weighted against BSDF
 * sampling by the power heuristic), a BSDF-sampled continuation (cosine-weighted for Lambert,
 * exact reflection for mirrors, Fresnel-weighted reflection or refraction for
 * smooth dielectrics), Russian roulette after three bounces, and a maximum
 * depth.  Rays that leave the scene see a uniform environment radiance.
 *
 * A surface's cg_material is read as a mixture: with weight reflectance a
 * mirror, with weight transmittance a smooth dielectric of refractive_index,
 * with the rest Lambert of albedo color * kd (clamped to [0, 1]).  Point and
 * spot lights have intensity color (radiance color / d^2 divided by the
 * cg_light attenuation polynomial's c0 + c1 d + c2 d^2 when that is not
 * {1, 0, 0}, else by d^2); directional lights give irradiance color on a
 * surface facing them; area lights emit radiance color from both faces.
 *
 * Determinism: sample k of pixel (x, y) depends only on (seed, x, y, k): its
 * pixel position is the R2 sequence at k shifted by a hash of (seed, pixel),
 * its other dimensions hashes of (seed, pixel, k, dimension).  Each sample's
 * RGB radiance is clamped to [0, CG_PATH_MAX_RADIANCE] and added in fixed
 * point (units of 2^-20) to 64-bit integer sums, so that sums of disjoint
 * sample ranges or tiles add up to exactly the sums of the whole render, on
 * any thread count.
 */
#ifndef CG_PATHTRACE_H
#define CG_PATHTRACE_H

#include "cg/trace.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest radiance a single sample contributes per channel. */
#define CG_PATH_MAX_RADIANCE 65536.0
/* Fixed-point units per unit radiance in the sums. */
#define CG_PATH_FIXED_ONE 1048576.0

typedef struct cg_path_options {
    int spp;             /* samples per pixel of the finished image, 1 to 2^24 */
    int sample_begin;    /* this call renders samples [begin, end) */
    int sample_end;      /* 0: spp */
    int max_depth;       /* surface interactions per path, 1 to 256 */
    int threads;         /* 1 to 256 */
    uint64_t seed;       /* selects the sample pattern */
    cg_vec3 environment; /* uniform environment radiance, >= 0 */
    /* NULL, or an equirectangular RGBAF map of the sky that replaces the
     * uniform environment: direction d (y up) looks up u = 1/2 +
     * atan2(d.x, -d.z) / 2 pi, v = acos(d.y) / pi, bilinearly, wrapping in u.
     * Rays see it when they leave the scene (it is not sampled directly). */
    const cg_image *environment_map;
    double environment_intensity; /* multiplies the map, >= 0 (default 1) */
    int x0, y0, x1, y1;           /* the tile [x0, x1) x [y0, y1); all 0: the whole image */
    /* 0 (default): emissive meshes are lights, sampled by area times
     * luminance with MIS against BSDF sampling; 1: emission counts only
     * where paths happen to meet it (the estimator without emitter
     * sampling, for comparisons). */
    int no_emitter_sampling;
    /* Called after each finished row of the tile (one call at a time); may
     * be NULL. */
    void (*progress)(void *user, int done, int total);
    void *progress_user;
} cg_path_options;

/* spp 16, max_depth 8, one thread, seed 0, black environment, no map
 * (intensity 1), whole image. */
cg_path_options cg_path_options_default(void);

/* Renders samples [sample_begin, sample_end) of every pixel of the tile of a
 * width x height image and adds them to sums: three uint64 per tile pixel
 * (r, g, b), rows of x1 - x0 pixels from y0.  sums must be zeroed (or hold
 * other sample ranges' sums) by the caller.  CG_EINVAL for NULL arguments, a
 * bad size, tile, range or option, CG_ERANGE beyond the limits. */
cg_status cg_path_render_sums(cg_trace_scene *scene, const cg_camera *camera, int width, int height,
                              const cg_path_options *options, uint64_t *sums);

/* The pixel values of sums over `samples` samples: each channel's sum
 * divided by samples and CG_PATH_FIXED_ONE, alpha 1, written at (x0 + i,
 * y0 + j) of image for the tile's w x h pixels. */
cg_status cg_path_resolve(const uint64_t *sums, int w, int h, uint64_t samples, cg_image *image,
                          int x0, int y0);

/* The whole image (its size) with options->spp samples per pixel (tile and
 * sample range ignored): cg_path_render_sums then cg_path_resolve. */
cg_status cg_path_render(cg_trace_scene *scene, const cg_camera *camera,
                         const cg_path_options *options, cg_image *image);

/* ---- part files ----------------------------------------------------------
 * A part is the sums of one tile and sample range, for renders split over
 * jobs.  File layout (little-endian): the 8 bytes "CGPART1\n"; uint32 width,
 * height, x0, y0, x1, y1, sample_begin, sample_end, spp, max_depth; uint64
 * seed; then (x1 - x0) (y1 - y0) pixels of three uint64 sums, rows from y0. */
typedef struct cg_path_part {
    uint32_t width, height, x0, y0, x1, y1, sample_begin, sample_end, spp, max_depth;
    uint64_t seed;
    /* The caller's digest of everything else the picture depends on (mesh or
     * scene, camera, sky): parts merge only when their keys are equal. */
    uint64_t render_key;
    uint64_t *sums; /* 3 per tile pixel */
} cg_path_part;

/* Writes the part to path atomically (a temporary file renamed over it). */
cg_status cg_path_part_save(const cg_path_part *part, const char *path, cg_error *err);
/* Reads a part; its sums are malloc'ed (free them).  CG_EFORMAT with a
 * message for anything but a well-formed part. */
cg_status cg_path_part_load(const char *path, cg_path_part *out, cg_error *err);
/* Adds the parts into one whole-image part (sums of width x height pixels,
 * malloc'ed): every part must have the same width, height, spp, max_depth,
 * seed and render_key, and every pixel must receive exactly spp samples in all. */
cg_status cg_path_part_merge(const cg_path_part *parts, size_t count, cg_path_part *out,
                             cg_error *err);

#ifdef __cplusplus
}
#endif

#endif
