/* cg/trace.h - ray tracing (section 5.4 of the notes).
 *
 * Two layers:
 *  - cg_bvh: a bounding volume hierarchy over triangles (binned surface area
 *    heuristic, 4-wide nodes, triangles in blocks of four) with a watertight
 *    ray-triangle test; nearest hit and any-hit (shadow) queries.  Usable on
 *    its own.
 *  - cg_trace_scene: triangle meshes, spheres and planes with materials and
 *    per-object transformations, the lights of cg/light.h plus area lights,
 *    shaded by cg/light.h's illumination model, and a
 *    Whitted-style renderer (shadows, mirror reflection, refraction with total
 *    internal reflection and Schlick's Fresnel, recursion limit, stratified
 *    supersampling, tiles on threads with output independent of the thread
 *    count).
 *
 * Rays are origin + t direction; direction need not be unit length and t is
 * measured in its units.  A ray whose origin or direction is not finite, or
 * whose direction is zero, hits nothing.
 */
#ifndef CG_TRACE_H
#define CG_TRACE_H

#include "cg/core.h"
#include "cg/image.h"
#include "cg/light.h"
#include "cg/mesh.h"
#include "cg/xform.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- triangle BVH ------------------------------------------------------- */

typedef struct cg_bvh cg_bvh;

/* Builds a BVH over triangle_count triangles; triangle i has the corners
 * positions[indices[3 i + k]], k = 0, 1, 2 (indices == NULL: corners 3 i,
 * 3 i + 1, 3 i + 2).  Coordinates are stored in single precision.
 * Triangles with a non-finite corner are left out (never hit); degenerate
 * (zero-area) triangles are kept and never hit.  Zero triangles give an
 * empty BVH that hits nothing.  CG_EINVAL for NULL arguments or an index out
 * of range, CG_ERANGE above 2^31 - 1 triangles (or, with leaves of one
 * triangle each, above about 2^28), CG_ENOMEM. */
cg_status cg_bvh_build(const cg_vec3 *positions, size_t vertex_count, const uint32_t *indices,
                       size_t triangle_count, cg_bvh **out);
/* The same tree built with up to threads threads (the root's two subtrees
 * in parallel). */
cg_status cg_bvh_build_threads(const cg_vec3 *positions, size_t vertex_count,
                               const uint32_t *indices, size_t triangle_count, int threads,
                               cg_bvh **out);
void cg_bvh_free(cg_bvh *bvh);

typedef struct cg_bvh_stats {
    size_t triangles; /* triangles stored (finite ones) */
    size_t nodes;     /* nodes of the 4-wide tree, 128 bytes each */
    size_t leaves;    /* leaves (1 to 8 triangles each) */
    int depth;        /* longest root-to-leaf path in nodes, root = 1 */
    double sah_cost;  /* SAH cost of the tree (node 1, triangle 1) */
} cg_bvh_stats;
void cg_bvh_get_stats(const cg_bvh *bvh, cg_bvh_stats *out);

typedef struct cg_bvh_hit {
    uint32_t triangle; /* index of the triangle as given to cg_bvh_build */
    float t;           /* distance along the ray */
    float u, v;        /* barycentric weights of corners 1 and 2 */
} cg_bvh_hit;

/* The nearest hit with t in (t_min, t_max].  Returns 1 and fills *hit, or 0
 * for no hit.  Both faces are hit.  Ties at equal t go to the lower triangle
 * index, so the answer is that of a brute-force loop over all triangles with
 * the same test (cg_bvh_intersect_brute). */
int cg_bvh_intersect(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                     double t_max, cg_bvh_hit *hit);
/* 1 when any triangle is hit with t in (t_min, t_max); stops at the first. */
int cg_bvh_occluded(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                    double t_max);
/* The same nearest-hit query by testing every triangle (for checking). */
int cg_bvh_intersect_brute(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                           double t_max, cg_bvh_hit *hit);

/* The watertight ray-triangle test on its own (Woop, Benthin and Wald 2013):
 * 1 and t, u, v when the ray hits triangle (a, b, c) with t in
 * (t_min, t_max].  Points on an edge or corner count as inside, so a ray
 * through a shared edge hits both neighbours and never slips between them. */
int cg_ray_triangle(cg_vec3 origin, cg_vec3 direction, cg_vec3 a, cg_vec3 b, cg_vec3 c,
                    double t_min, double t_max, double *t, double *u, double *v);

/* ---- optics ------------------------------------------------------------- */

/* Mirror reflection of the incident direction about the unit normal n. */
cg_vec3 cg_reflect(cg_vec3 incident, cg_vec3 n);
/* Refraction of the unit incident direction at a surface with unit normal n
 * (facing against the incident ray) from a medium of index n1 to one of index
 * n2 (Snell's law).  Returns 0 for total internal reflection (or an invalid
 * index: not finite or <= 0), 1 with the unit refracted direction otherwise. */
int cg_refract(cg_vec3 incident, cg_vec3 n, double n1, double n2, cg_vec3 *out);
/* Schlick's approximation of the Fresnel reflectance for an incident ray
 * making cos_incident with the normal, going from index n1 to n2; 1 under total
 * internal reflection, 0 when n1 == n2 (no interface), 1 for an invalid index. */
double cg_fresnel_schlick(double cos_incident, double n1, double n2);

/* ---- scenes --------------------------------------------------------------- */

/* A surface: the shared illumination material of cg/light.h (colour,
 * ka, kd, ks, shininess, and the ray tracer's reflectance, transmittance and
 * refractive index, where 0 means 1) and an optional 3D checker pattern. */
typedef struct cg_trace_material {
    cg_material surface;
    cg_vec3 checker_color; /* second colour of the checker */
    double checker_size;   /* cell size; 0 for the plain colour */
    /* Radiance the surface emits, linear RGB >= 0, the same on both sides
     * and in every direction (0: none).  The Whitted tracer adds it where
     * a ray sees the surface; the path tracer wherever a path meets it (it
     * is not sampled as a light, so small bright emitters are noisy). */
    cg_vec3 emission;
} cg_trace_material;

/* White, ka 1, kd 0.9, ks 0.2, shininess 32, Blinn-Phong, opaque. */
cg_trace_material cg_trace_material_default(void);

/* A rectangular (parallelogram) light: corner + s edge_u + t edge_v for s, t
 * in [0, 1], sampled on a samples x samples jittered grid for soft shadows;
 * each sample acts as a point light of color / samples^2. */
typedef struct cg_trace_area_light {
    cg_vec3 corner, edge_u, edge_v;
    cg_vec3 color;
    int samples; /* 1 to 64 */
} cg_trace_area_light;

typedef struct cg_trace_scene cg_trace_scene;

cg_status cg_trace_scene_create(cg_trace_scene **out);
void cg_trace_scene_free(cg_trace_scene *scene);

/* Adds a mesh (every face fan-triangulated) under the model transform
 * (NULL: identity).  Smooth normals come from the mesh's vertex normals, or
 * else from cg_mesh_corner_normals with crease_angle (radians), as the
 * rasterizer makes them.  Faces with out-of-range indices give CG_EFORMAT;
 * NaN positions make their triangles invisible. */
cg_status cg_trace_scene_add_mesh(cg_trace_scene *scene, const cg_mesh *mesh,
                                  const cg_mat4 *transform, double crease_angle,
                                  const cg_trace_material *material);
/* A sphere; under a transform (NULL: identity) it may become an ellipsoid.
 * Radius 0 gives an invisible sphere; a negative or non-finite radius, or a
 * singular transform, is CG_EINVAL. */
cg_status cg_trace_scene_add_sphere(cg_trace_scene *scene, cg_vec3 center, double radius,
                                    const cg_mat4 *transform, const cg_trace_material *material);
/* An infinite plane through point with normal (need not be unit). */
cg_status cg_trace_scene_add_plane(cg_trace_scene *scene, cg_vec3 point, cg_vec3 normal,
                                   const cg_trace_material *material);
/* A light of cg/light.h (ambient, point, directional, spot); point,
 * directional and spot lights cast shadows.  CG_EINVAL when cg_light_check
 * rejects it. */
cg_status cg_trace_scene_add_light(cg_trace_scene *scene, const cg_light *light);
cg_status cg_trace_scene_add_area_light(cg_trace_scene *scene, const cg_trace_area_light *light);
/* Builds the acceleration structure on up to threads threads (the tree is the
 * same for any count); cg_trace_render calls it when needed.  *seconds (may
 * be NULL) receives the BVH build time. */
cg_status cg_trace_scene_build(cg_trace_scene *scene, int threads, double *seconds);
/* Bounds of the finite objects (planes excluded); CG_EEMPTY when none. */
cg_status cg_trace_scene_bounds(const cg_trace_scene *scene, cg_vec3 *lo, cg_vec3 *hi);

/* The classic scene: glass and mirror spheres over a checkered plane, lit by
 * an area light and a directional light. */
cg_status cg_trace_scene_classic(cg_trace_scene **out);

/* Normals used for triangle meshes. */
typedef enum cg_trace_normals {
    CG_TRACE_FLAT,  /* face normals */
    CG_TRACE_SMOOTH /* interpolated vertex normals (Phong) */
} cg_trace_normals;

typedef struct cg_trace_options {
    int samples;   /* samples per pixel, >= 1 (stratified; 1: pixel centre) */
    int max_depth; /* reflection/refraction recursion limit, >= 0 */
    int threads;   /* worker threads, >= 1 */
    int shadows;   /* cast shadow rays */
    cg_trace_normals normals;
    cg_rgbaf background; /* linear light; alpha kept where no object is hit */
    /* Non-zero: primary rays see only depths between the camera's near and
     * far along the viewing direction, the rasterizer's view volume (far
     * may be +infinity).  0 (default): from the eye, or a parallel camera's
     * near plane, without end. */
    int clip_depth;
    /* Called after each finished tile with done/total tiles (from a worker
     * thread, one call at a time); may be NULL. */
    void (*progress)(void *user, int done, int total);
    void *progress_user;
} cg_trace_options;

cg_trace_options cg_trace_options_default(void);

typedef struct cg_trace_stats {
    double build_seconds; /* BVH build (0 when already built) */
    double render_seconds;
    uint64_t rays; /* primary, shadow and secondary rays traced */
} cg_trace_stats;

/* Renders the scene as seen by camera into image (any size and format; each
 * pixel is overwritten).  The same inputs give the same bytes on any number of
 * threads.  stats may be NULL. */
cg_status cg_trace_render(cg_trace_scene *scene, const cg_camera *camera,
                          const cg_trace_options *options, cg_image *image, cg_trace_stats *stats);

#ifdef __cplusplus
}
#endif
#endif
