/* Private pieces shared by the BVH's stages: the build (bvh_build.c, the
 * binned SAH), the collapse into the 4-wide tree (bvh_collapse.c), the
 * traversal (bvh_traverse.c) and the scalar triangle test
 * (ray_triangle.c); bvh.c runs the stages. */
#ifndef CG_TRACE_BVH_INTERNAL_H
#define CG_TRACE_BVH_INTERNAL_H

#include "internal.h"
#include "../core/simd4.h"
#include "../core/worker_pool.h"

#include <float.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

enum {
    BINS = 32,      /* most bins per axis for the SAH sweep */
    MAX_LEAF = 8,   /* a node with more triangles is always split (a leaf
                         reference holds counts 1 to 8) */
    SAH_DEPTH = 48, /* deeper than this, split at the object median */
    /* The 4-wide tree is at most as deep as the binary one (SAH_DEPTH + 32
     * inner levels), and each level pushes at most three children. */
    STACK_SIZE = 3 * (SAH_DEPTH + 33) + 16,
    PARALLEL_MIN = 4096, /* fewer triangles: build on one thread */
    /* From this many triangles the two buffers of references (64 bytes a
     * triangle, 32 MiB here: beyond what malloc keeps for reuse) are one
     * block that the triangle blocks reuse. */
    REUSE_MIN = 1 << 19,
    SAMPLE = 4096 /* nodes of 2 SAMPLE or more bin SAMPLE to 2 SAMPLE - 1 */
};

/* The SAH counts triangles in blocks of four, as the leaves store and test
 * them: testing one block costs 1, entering a node TRAVERSAL_COST. */
#define BLOCKS(n) (((n) + 3) / 4)
#ifndef TRAVERSAL_COST
#define TRAVERSAL_COST 1.0f
#endif

/* ---- boxes ---------------------------------------------------------------- */

typedef struct bbox {
    v4 lo, hi;
} bbox;

static inline void bbox_empty(bbox *b)
{
    b->lo = v4_set(FLT_MAX);
    b->hi = v4_set(-FLT_MAX);
}

static inline void bbox_grow(bbox *b, v4 lo, v4 hi)
{
    b->lo = v4_min(b->lo, lo);
    b->hi = v4_max(b->hi, hi);
}

/* Half the surface area (the factor cancels in the SAH), (dx dy + dy dz) +
 * dz dx; 0 when empty. */
static inline float bbox_area(const bbox *b)
{
    v4 d = v4_sub(b->hi, b->lo);
    if (v4_bits(v4_lt(d, v4_set(0))) & 7)
        return 0;
    return v4_sum3(v4_mul(d, v4_yzx(d)));
}

static inline float bvh_node_area(const bvh_node *n)
{
    bbox b;
    b.lo = v4_load3(n->lo);
    b.hi = v4_load3(n->hi);
    return bbox_area(&b);
}

/* ---- building ------------------------------------------------------------ */

/* A triangle's bounds while building: lanes 0..2 of lo and hi, its index in
 * the fourth float of lo (as bits). */
typedef struct prim_ref {
    float lo[4];
    float hi[4];
} prim_ref;

/* The build's state: the references in two buffers (a node's range lives in
 * one, its partition writes the children's into the other), the triangle
 * index of each leaf position, and the nodes. */
typedef struct bvh_builder {
    prim_ref *buf[2];
    uint32_t *ids;
    bvh_node *nodes;
    size_t node_count;
} bvh_builder;

/* The binary tree of the references in b->buf[0][0, n) into b->nodes (room
 * for 2 n - 1), the triangle of each leaf position into b->ids; on a pool
 * of two workers or more the root's two subtrees are built at the same
 * time.  The tree is the same either way.  0 when out of memory. */
int bvh_build_tree(bvh_builder *out, size_t n, core_worker_pool *pool);

/* ---- the 4-wide tree ------------------------------------------------------ */

/* Collapsing the binary tree (bvh_collapse.c): its nodes and leaf order
 * in, the 4-wide nodes and triangle blocks out. */
typedef struct bvh_collapser {
    const bvh_node *bin;
    const uint32_t *ids; /* triangle of each leaf position */
    const cg_vec3 *positions;
    const uint32_t *indices;
    uint32_t *where; /* place of each triangle (by index) in the blocks */
    bvh4_node *nodes;
    size_t node_count;
    bvh_tri4 *blocks;
    size_t block_count;
    int depth;
} bvh_collapser;

/* A leaf's blocks (indices only; the corners come with
 * bvh_fill_corners); returns its reference. */
uint32_t bvh_emit_leaf(bvh_collapser *c, const bvh_node *leaf);
/* The 4-wide subtree of binary inner node index; returns its reference. */
uint32_t bvh_collapse(bvh_collapser *c, uint32_t index, int depth);
/* The corners of every stored triangle into its lane. */
void bvh_fill_corners(const bvh_collapser *c, size_t triangle_count);

/* ---- queries --------------------------------------------------------------- */

/* Is the candidate (t, id) better than the best so far? */
static inline int bvh_better(float t, uint32_t id, float best_t, uint32_t best_id)
{
    return t < best_t || (t == best_t && id < best_id);
}

static inline float bvh_clamp_far(double t_max)
{
    if (!(t_max < (double)FLT_MAX))
        return FLT_MAX;
    return (float)t_max;
}

#endif
