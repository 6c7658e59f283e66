/* Private pieces shared by the ray tracer's files. */
#ifndef CG_TRACE_INTERNAL_H
#define CG_TRACE_INTERNAL_H

#include "cg/trace.h"
#include "../core/worker_pool.h"

/* A node of the binary tree the build makes (32 bytes): bounds, and either
 * two children (count == 0: the left child follows this node, the right one
 * is at offset) or a leaf of count triangles starting at offset in the
 * reordered triangle array.  Also the root's bounds of the final tree. */
typedef struct bvh_node {
    float lo[3];
    uint32_t offset;
    float hi[3];
    uint32_t count;
} bvh_node;

/* A node of the 4-wide tree the queries traverse (128 bytes): the four
 * children's boxes stored by coordinate (box[r][lane], rows lo x, hi x,
 * lo y, hi y, lo z, hi z: a ray's far plane is in the row after or before its
 * near one), so one SSE pass tests all four, and their references.
 * An unused slot has an empty box (lo +inf, hi -inf) that no ray enters. */
typedef struct bvh4_node {
    float box[6][4];
    uint32_t child[4];
    uint32_t pad[4];
} bvh4_node;

/* A child reference: an inner node's index, or BVH_LEAF | first block << 3 |
 * (triangle count - 1) for a leaf of 1 to 8 triangles in consecutive blocks
 * of four. */
#define BVH_LEAF 0x80000000u
#define BVH_NONE 0xffffffffu

/* Four triangles by coordinate (v[corner][axis][lane]) for testing them at
 * once, with their indices as given to the build; an unused lane has NaN
 * corners (never hit) and index UINT32_MAX. */
typedef struct bvh_tri4 {
    float v[3][3][4];
    uint32_t id[4];
} bvh_tri4;

/* A triangle as the scalar test reads it. */
typedef struct bvh_triangle {
    float v0[3], v1[3], v2[3];
    uint32_t id;
} bvh_triangle;

struct cg_bvh {
    bvh4_node *nodes;
    size_t node_count;
    bvh_tri4 *blocks;
    size_t block_count;
    size_t triangle_count;
    uint32_t root;   /* reference of the root (BVH_NONE when empty) */
    bvh_node bounds; /* the root's box */
    int depth;       /* of the 4-wide tree, root = 1 */
};

/* A ray prepared for the watertight test and the slab test. */
typedef struct bvh_ray {
    float origin[3];
    float inverse[3]; /* 1 / direction, with zero components made tiny */
    float shear_x, shear_y, shear_z;
    int kx, ky, kz;
    int flat_axes; /* bit a: direction component a is zero */
    float t_min;
    double direction[3]; /* as given, for the shear */
} bvh_ray;

/* Prepares the ray; 0 when it is not finite or has zero direction. */
int bvh_ray_setup(bvh_ray *ray, cg_vec3 origin, cg_vec3 direction, double t_min);

/* ---- scenes ---- */

typedef enum trace_kind { TRACE_MESH, TRACE_SPHERE, TRACE_PLANE } trace_kind;

typedef struct trace_object {
    trace_kind kind;
    cg_trace_material material;
    /* TRACE_MESH: its triangles in the scene's arrays */
    size_t first_triangle, triangle_count;
    /* TRACE_SPHERE: center and radius in object space, and the transforms;
     * TRACE_PLANE: center is a point on it */
    cg_vec3 center;
    double radius;
    cg_mat4 to_world, to_object;
    cg_mat3 normal_to_world;
    cg_vec3 plane_normal, axis_u, axis_v;
} trace_object;

struct cg_trace_scene {
    trace_object *objects;
    size_t object_count, object_capacity;
    cg_light *lights;
    size_t light_count, light_capacity;
    cg_trace_area_light *area_lights;
    size_t area_light_count, area_light_capacity;
    /* Triangles of all meshes, in world space; normals per triangle corner. */
    cg_vec3 *positions, *normals;
    size_t vertex_count, vertex_capacity, normal_capacity;
    uint32_t *indices; /* 3 per triangle */
    uint32_t *triangle_object;
    size_t triangle_count, index_capacity, triangle_object_capacity;
    cg_bvh *bvh;
    int built;
    /* The worker pool of the BVH build and of the renders (trace_scene_pool),
     * kept until the thread count changes or the scene is freed. */
    core_worker_pool *pool;
    int pool_threads; /* the thread count it was made for */
};

/* The scene's worker pool for `threads` threads (the caller included),
 * made or remade when the count changes; NULL (the caller alone) for one
 * thread or when no pool can be made. */
core_worker_pool *trace_scene_pool(cg_trace_scene *scene, int threads);

/* cg_bvh_build_threads on a worker pool (NULL: the caller alone). */
cg_status trace_bvh_build(const cg_vec3 *positions, size_t vertex_count, const uint32_t *indices,
                          size_t triangle_count, core_worker_pool *pool, cg_bvh **out);

typedef struct trace_hit {
    double t;
    int object;
    uint32_t triangle;
    double u, v;
    cg_vec3 point;         /* on the surface */
    cg_vec3 normal;        /* geometric, unit */
    cg_vec3 smooth_normal; /* interpolated, unit */
    double scale;          /* largest coordinate magnitude involved */
} trace_hit;

int trace_intersect(const cg_trace_scene *scene, cg_vec3 origin, cg_vec3 direction, double t_min,
                    double t_max, trace_hit *hit);
int trace_occluded(const cg_trace_scene *scene, cg_vec3 origin, cg_vec3 direction, double t_min,
                   double t_max);
/* The hit point moved off the surface along normal (unit) by an amount
 * relative to the magnitude of the coordinates. */
cg_vec3 trace_offset(const trace_hit *hit, cg_vec3 normal);

/* The colour of object o at p: its material's, or the checker's second
 * colour on the cells of odd parity (the plane's own axes for a plane,
 * world axes otherwise).  Shared by the Whitted and the path tracer. */
cg_vec3 trace_surface_color(const trace_object *o, cg_vec3 p);

#endif
