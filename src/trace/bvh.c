/* Bounding volume hierarchy over triangles: the public calls that build,
 * free and measure it.  The build runs the stages: the triangles' bounds as
 * references, the binary tree of the binned SAH (bvh_build.c), its collapse
 * into a 4-wide tree with triangles in blocks of four (bvh_collapse.c).
 * Queries are in bvh_traverse.c, the scalar triangle test in
 * ray_triangle.c. */
#include "bvh_internal.h"

#include <stdlib.h>
#include <string.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

/* Memory for count items of size bytes: large blocks 2 MiB aligned and, on
 * Linux, offered to the kernel as huge pages, which saves most of the page
 * faults of a first touch; smaller ones 128-byte aligned (pairs of cache
 * lines, which a 4-wide node fills) when lines is set, else from malloc. */
static void *alloc_block(size_t count, size_t size, int lines)
{
    if (count == 0)
        count = 1;
    if (count > SIZE_MAX / size - (2u << 20))
        return NULL;
    size_t bytes = count * size;
    if (bytes >= (4u << 20)) {
        bytes = (bytes + (2u << 20) - 1) / (2u << 20) * (2u << 20);
        void *p = aligned_alloc(2u << 20, bytes);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        if (p)
            madvise(p, bytes, MADV_HUGEPAGE);
#endif
        return p;
    }
    return lines ? aligned_alloc(128, (bytes + 127) / 128 * 128) : malloc(bytes);
}

/* The references of the finite triangles into refs; returns their count.
 * Coordinates are rounded to float once, here. */
static size_t make_refs(const cg_vec3 *positions, const uint32_t *indices, size_t triangle_count,
                        prim_ref *refs)
{
    size_t n = 0;
    const v4 zero = v4_set(0);
    for (size_t i = 0; i < triangle_count; i++) {
        v4 lo = v4_set(FLT_MAX), hi = v4_set(-FLT_MAX), nan = zero;
        for (int k = 0; k < 3; k++) {
            v4 v = v4_point(&positions[indices ? indices[3 * i + k] : 3 * i + k]);
            lo = v4_min(lo, v);
            hi = v4_max(hi, v);
            /* v * 0 is 0 for finite coordinates, NaN otherwise. */
            nan = v4_add(nan, v4_mul(v, zero));
        }
        if ((v4_bits(v4_eq(nan, zero)) & 7) != 7)
            continue;
        prim_ref *r = &refs[n++];
        v4_store(r->lo, lo);
        v4_store(r->hi, hi);
        uint32_t id = (uint32_t)i;
        memcpy(&r->lo[3], &id, sizeof id);
    }
    return n;
}

/* The triangle blocks written into the build's reference block: the rest
 * of it given back if the blocks stay where they are (aligned as they
 * need), else copied once more.  0 when out of memory (the blocks freed). */
static int shrink_blocks(bvh_collapser *c)
{
    bvh_tri4 *shrunk = realloc(c->blocks, c->block_count * sizeof *c->blocks);
    if (shrunk && (uintptr_t)(void *)shrunk % 128 != 0) {
        c->blocks = alloc_block(c->block_count, sizeof *c->blocks, 1);
        if (c->blocks)
            memcpy(c->blocks, shrunk, c->block_count * sizeof *c->blocks);
        free(shrunk);
        return c->blocks != NULL;
    }
    if (shrunk)
        c->blocks = shrunk;
    return 1;
}

cg_status cg_bvh_build(const cg_vec3 *positions, size_t vertex_count, const uint32_t *indices,
                       size_t triangle_count, cg_bvh **out)
{
    return cg_bvh_build_threads(positions, vertex_count, indices, triangle_count, 1, out);
}

cg_status cg_bvh_build_threads(const cg_vec3 *positions, size_t vertex_count,
                               const uint32_t *indices, size_t triangle_count, int threads,
                               cg_bvh **out)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if (threads < 1)
        return CG_EINVAL;
    /* Two workers at most take part (the root's two subtrees); without the
     * second (out of memory, no thread) the caller builds alone. */
    core_worker_pool *pool = NULL;
    if (threads > 1 && triangle_count >= PARALLEL_MIN && core_worker_pool_create(2, &pool) != CG_OK)
        pool = NULL;
    cg_status status = trace_bvh_build(positions, vertex_count, indices, triangle_count, pool, out);
    core_worker_pool_free(pool);
    return status;
}

cg_status trace_bvh_build(const cg_vec3 *positions, size_t vertex_count, const uint32_t *indices,
                          size_t triangle_count, core_worker_pool *pool, cg_bvh **out)
{
    *out = NULL;
    if ((!positions && vertex_count) || (triangle_count && !positions))
        return CG_EINVAL;
    if (triangle_count > 0x7fffffffu)
        return CG_ERANGE;
    if (!indices && triangle_count > vertex_count / 3)
        return CG_EINVAL;
    if (indices)
        for (size_t i = 0; i < 3 * triangle_count; i++)
            if (indices[i] >= vertex_count)
                return CG_EINVAL;
    cg_bvh *bvh = calloc(1, sizeof *bvh);
    /* For large meshes both buffers of references are one block, which
     * afterwards holds the triangle blocks when they fit (most meshes):
     * they are written into memory already mapped rather than into fresh
     * pages the kernel has to clear.  Smaller buffers are allocated apart,
     * where malloc reuses its own memory from one build to the next. */
    int joined = triangle_count >= REUSE_MIN;
    prim_ref *refs = alloc_block(joined ? 2 * triangle_count : triangle_count, sizeof *refs, 0);
    prim_ref *second = joined ? refs + triangle_count : NULL;
    if (!bvh || !refs) {
        free(bvh);
        free(refs);
        return CG_ENOMEM;
    }
    bvh->root = BVH_NONE;
    size_t n = make_refs(positions, indices, triangle_count, refs);
    bvh->triangle_count = n;
    if (n == 0) {
        free(refs);
        *out = bvh;
        return CG_OK;
    }
    if (!joined)
        second = alloc_block(n, sizeof *refs, 0);
    bvh_builder b = {{refs, second},
                     alloc_block(n, sizeof(uint32_t), 0),
                     alloc_block(2 * n - 1, sizeof(bvh_node), 0),
                     0};
    bvh_collapser c = {b.nodes, b.ids, positions, indices, NULL, NULL, 0, NULL, 0, 1};
    cg_status status = CG_ENOMEM;
    if (!b.buf[1] || !b.ids || !b.nodes || !bvh_build_tree(&b, n, pool))
        goto fail;
    size_t blocks = 0;
    for (size_t i = 0; i < b.node_count; i++)
        blocks += BLOCKS(b.nodes[i].count);
    if (blocks >= (BVH_LEAF >> 3)) {
        status = CG_ERANGE;
        goto fail;
    }
    c.nodes = alloc_block(b.node_count / 2 + 1, sizeof *c.nodes, 1);
    int reuse = joined && blocks <= 2 * triangle_count * sizeof *refs / sizeof *c.blocks;
    c.blocks = reuse ? (bvh_tri4 *)(void *)refs : alloc_block(blocks, sizeof *c.blocks, 1);
    if (reuse)
        b.buf[0] = NULL;
    c.where = alloc_block(triangle_count, sizeof *c.where, 0);
    if (!c.nodes || !c.blocks || !c.where)
        goto fail;
    memset(c.where, 0xff, triangle_count * sizeof *c.where);
    bvh->bounds = b.nodes[0];
    bvh->root = b.nodes[0].count ? bvh_emit_leaf(&c, &b.nodes[0]) : bvh_collapse(&c, 0, 1);
    bvh_fill_corners(&c, triangle_count);
    if (reuse && !shrink_blocks(&c))
        goto fail;
    bvh->nodes = c.nodes;
    bvh->node_count = c.node_count;
    bvh->blocks = c.blocks;
    bvh->block_count = c.block_count;
    bvh->depth = b.nodes[0].count ? 1 : c.depth + 1;
    c.nodes = NULL;
    c.blocks = NULL;
    status = CG_OK;
fail:
    free(c.where);
    free(c.nodes);
    free(c.blocks);
    free(b.nodes);
    free(b.ids);
    free(b.buf[0]);
    if (!joined)
        free(second);
    if (status != CG_OK) {
        cg_bvh_free(bvh);
        bvh = NULL;
    }
    *out = bvh;
    return status;
}

void cg_bvh_free(cg_bvh *bvh)
{
    if (!bvh)
        return;
    free(bvh->nodes);
    free(bvh->blocks);
    free(bvh);
}

/* SAH cost of the subtree under ref (box given): 1 per node entered, 1 per
 * triangle tested, weighted by area. */
static double sah_of(const cg_bvh *bvh, uint32_t ref, const bvh_node *box, size_t *leaves)
{
    double area = bvh_node_area(box);
    if (ref & BVH_LEAF) {
        ++*leaves;
        return area * (double)((ref & 7) + 1);
    }
    const bvh4_node *node = &bvh->nodes[ref];
    double cost = area;
    for (int k = 0; k < 4; k++) {
        if (node->child[k] == BVH_NONE)
            continue;
        bvh_node child;
        memset(&child, 0, sizeof child);
        for (int a = 0; a < 3; a++) {
            child.lo[a] = node->box[2 * a][k];
            child.hi[a] = node->box[2 * a + 1][k];
        }
        cost += sah_of(bvh, node->child[k], &child, leaves);
    }
    return cost;
}

void cg_bvh_get_stats(const cg_bvh *bvh, cg_bvh_stats *out)
{
    memset(out, 0, sizeof *out);
    if (!bvh)
        return;
    out->triangles = bvh->triangle_count;
    out->nodes = bvh->node_count;
    if (bvh->root != BVH_NONE) {
        out->depth = bvh->depth;
        double cost = sah_of(bvh, bvh->root, &bvh->bounds, &out->leaves);
        double area = bvh_node_area(&bvh->bounds);
        out->sah_cost = area > 0 ? cost / area : 0;
    }
}
