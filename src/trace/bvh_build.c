/* The binary BVH of a triangle set, built top down with the binned surface
 * area heuristic: each node's centroids are binned on the three axes, the
 * plane of least A_left blocks(N_left) + A_right blocks(N_right) is found in
 * one sweep over the bins, and the references are partitioned into a second
 * buffer without branches on the side.  The root's two subtrees can be built
 * on two workers of a worker pool; the tree is the same either way. */
#include "bvh_internal.h"

#include <math.h>
#include <stdlib.h>

/* The triangle index a reference carries. */
static inline uint32_t prim_id(const prim_ref *r)
{
    uint32_t id;
    memcpy(&id, &r->lo[3], sizeof id);
    return id;
}

static void set_node(bvh_node *node, const bbox *bounds)
{
    float lo[4], hi[4];
    v4_store(lo, bounds->lo);
    v4_store(hi, bounds->hi);
    memcpy(node->lo, lo, sizeof node->lo);
    memcpy(node->hi, hi, sizeof node->hi);
    node->offset = 0;
    node->count = 0;
}

static uint32_t make_node(bvh_builder *b, const bbox *bounds)
{
    uint32_t index = (uint32_t)b->node_count++;
    set_node(&b->nodes[index], bounds);
    return index;
}

/* Bin coordinates of a centroid (times 2: lo + hi) on the three axes,
 * clamped to [0, last] in float before truncation (NaN gives 0): for the
 * values binning meets, the bins clamping the integers would give. */
static inline void bin_of(v4 centroid, v4 origin, v4 scale, v4 last, int *k)
{
    v4 x = v4_mul(v4_sub(centroid, origin), scale);
    v4_to_int(v4_min(v4_max(x, v4_set(0)), last), k);
}

/* The split of a node: where, and the children's bounds. */
typedef struct split {
    size_t mid;
    bbox left, right, left_centroids, right_centroids;
} split;

/* Bins on the three axes: bounds and counts. */
typedef struct bin_set {
    bbox box[3][BINS];
    uint32_t count[3][BINS];
} bin_set;

static void bins_clear(bin_set *s, int nb)
{
    for (int a = 0; a < 3; a++)
        for (int k = 0; k < nb; k++) {
            bbox_empty(&s->box[a][k]);
            s->count[a][k] = 0;
        }
}

static inline void bins_add(bin_set *s, const prim_ref *r, v4 origin, v4 scale, v4 last)
{
    v4 lo = v4_load3(r->lo), hi = v4_load3(r->hi);
    int k[4];
    bin_of(v4_add(lo, hi), origin, scale, last, k);
    for (int a = 0; a < 3; a++) {
        bbox_grow(&s->box[a][k[a]], lo, hi);
        s->count[a][k[a]]++;
    }
}

/* Three boxes by coordinate (lane a: box a; lo x, y, z, hi x, y, z): their
 * bbox_area, (dx dy + dy dz) + dz dx or 0 when empty, lane by lane. */
static inline v4 area3(const v4 *b)
{
    const v4 zero = v4_set(0);
    v4 dx = v4_sub(b[3], b[0]), dy = v4_sub(b[4], b[1]), dz = v4_sub(b[5], b[2]);
    v4 empty = v4_or(v4_or(v4_lt(dx, zero), v4_lt(dy, zero)), v4_lt(dz, zero));
    v4 area = v4_add(v4_add(v4_mul(dx, dy), v4_mul(dy, dz)), v4_mul(dz, dx));
    return v4_andnot(empty, area);
}

/* The bins turned into coordinate vectors for the sweep: box[k] holds
 * bin k's lo x, y, z and hi x, y, z with lane a for axis a, count[k] its
 * counts likewise. */
static void bins_by_axis(const bin_set *s, int nb, v4 box[][6], i4 *count)
{
    for (int k = 0; k < nb; k++) {
        v4 lo[4] = {s->box[0][k].lo, s->box[1][k].lo, s->box[2][k].lo, v4_set(0)};
        v4 hi[4] = {s->box[0][k].hi, s->box[1][k].hi, s->box[2][k].hi, v4_set(0)};
        v4_transpose(lo);
        v4_transpose(hi);
        for (int j = 0; j < 3; j++) {
            box[k][j] = lo[j];
            box[k][3 + j] = hi[j];
        }
        count[k] = i4_set3((int)s->count[0][k], (int)s->count[1][k], (int)s->count[2][k]);
    }
}

/* The SAH sweep over the bins: the axis and bin (the last one on the left)
 * of least A_left blocks(N_left) + A_right blocks(N_right), the first in
 * axis-then-bin order on ties; axes with sc[a] 0 are left out, and so are
 * planes with an empty side.  best_axis -1 when there is none.  The three
 * axes are swept at once, one per lane. */
static void sah_sweep(const bin_set *s, int nb, const float *sc, int *best_axis, int *best_bin,
                      float *best_cost)
{
    v4 box[BINS][6];
    i4 count[BINS];
    bins_by_axis(s, nb, box, count);
    /* From the right: the area and count right of each plane. */
    v4 right_area[BINS];
    i4 right_count[BINS];
    v4 acc[6] = {v4_set(FLT_MAX),  v4_set(FLT_MAX),  v4_set(FLT_MAX),
                 v4_set(-FLT_MAX), v4_set(-FLT_MAX), v4_set(-FLT_MAX)};
    const v4 zero = v4_set(0);
    i4 n = i4_set(0);
    for (int k = nb - 1; k > 0; k--) {
        for (int j = 0; j < 3; j++) {
            acc[j] = v4_min(acc[j], box[k][j]);
            acc[3 + j] = v4_max(acc[3 + j], box[k][3 + j]);
        }
        n = i4_add(n, count[k]);
        right_area[k] = area3(acc);
        right_count[k] = n;
    }
    /* From the left: the cost of each plane, the least kept per axis. */
    for (int j = 0; j < 3; j++) {
        acc[j] = v4_set(FLT_MAX);
        acc[3 + j] = v4_set(-FLT_MAX);
    }
    n = i4_set(0);
    v4 axes = v4_neq(v4_set3(sc[0], sc[1], sc[2]), zero);
    i4 bin = i4_set(0);
    v4 cost_best = v4_set(FLT_MAX);
    for (int k = 0; k < nb - 1; k++) {
        for (int j = 0; j < 3; j++) {
            acc[j] = v4_min(acc[j], box[k][j]);
            acc[3 + j] = v4_max(acc[3 + j], box[k][3 + j]);
        }
        n = i4_add(n, count[k]);
        v4 cost = v4_add(v4_mul(area3(acc), i4_quarter_up(n)),
                         v4_mul(right_area[k + 1], i4_quarter_up(right_count[k + 1])));
        v4 empty = v4_or(i4_is_zero(n), i4_is_zero(right_count[k + 1]));
        v4 better = v4_andnot(empty, v4_and(axes, v4_lt(cost, cost_best)));
        cost_best = v4_select(better, cost, cost_best);
        bin = i4_select(better, i4_set(k), bin);
    }
    float c[4];
    int kb[4];
    v4_store(c, cost_best);
    i4_store(kb, bin);
    *best_axis = -1;
    *best_bin = 0;
    *best_cost = FLT_MAX;
    for (int a = 0; a < 3; a++)
        if (c[a] < *best_cost) {
            *best_cost = c[a];
            *best_axis = a;
            *best_bin = kb[a];
        }
}

/* Bounds of both sides of a partition, grown without branches (kept in
 * registers and chosen with masks). */
typedef struct sides {
    v4 llo, lhi, rlo, rhi;
} sides;

static inline void sides_init(sides *s)
{
    s->llo = s->rlo = v4_set(FLT_MAX);
    s->lhi = s->rhi = v4_set(-FLT_MAX);
}

static inline void sides_grow(sides *s, v4 lo, v4 hi, int right)
{
    /* min and max return their second operand when either is NaN: a value
     * or-ed with an all-ones mask is NaN and leaves that side's bounds as
     * they are. */
    v4 not_left = v4_mask_if(right), not_right = v4_not(not_left);
    v4 llo = v4_or(lo, not_left), rlo = v4_or(lo, not_right);
    v4 lhi = v4_or(hi, not_left), rhi = v4_or(hi, not_right);
    s->llo = v4_min(llo, s->llo);
    s->lhi = v4_max(lhi, s->lhi);
    s->rlo = v4_min(rlo, s->rlo);
    s->rhi = v4_max(rhi, s->rhi);
}

static inline void sides_get(const sides *s, bbox *left, bbox *right)
{
    left->lo = s->llo;
    left->hi = s->lhi;
    right->lo = s->rlo;
    right->hi = s->rhi;
}

/* Partitions src[begin, end) into dst[begin, end) without branches on the
 * side: each reference goes to the next free place of its side (the left
 * from begin up, the right from end down), the side of bin best_bin + 1 on
 * and past.  The children's centroid bounds into out, and with geometry
 * their bounds too.  Returns where the right side begins. */
static inline size_t partition(const prim_ref *src, prim_ref *dst, size_t begin, size_t end,
                               v4 origin, v4 scale, int best_axis, int best_bin, split *out,
                               int geometry)
{
    size_t l = begin, r = end - 1;
    sides cs, gs;
    sides_init(&cs);
    sides_init(&gs);
    /* The bin on the axis is past best_bin exactly when the scaled
     * coordinate is at least best_bin + 1 (NaN in the other lanes: never). */
    float th[3] = {NAN, NAN, NAN};
    th[best_axis] = (float)(best_bin + 1);
    v4 threshold = v4_set4(th[0], th[1], th[2], NAN);
    for (size_t i = begin; i < end; i++) {
        v4 lo = v4_load3(src[i].lo), hi = v4_load3(src[i].hi), c = v4_add(lo, hi);
        int right = v4_bits(v4_ge(v4_mul(v4_sub(c, origin), scale), threshold)) != 0;
        size_t at = right ? r : l;
        v4_store(dst[at].lo, v4_load(src[i].lo));
        v4_store(dst[at].hi, v4_load(src[i].hi));
        l += (size_t)!right;
        r -= (size_t)right;
        sides_grow(&cs, c, c, right);
        if (geometry)
            sides_grow(&gs, lo, hi, right);
    }
    sides_get(&cs, &out->left_centroids, &out->right_centroids);
    if (geometry)
        sides_get(&gs, &out->left, &out->right);
    return l;
}

/* Finds the binned-SAH split of src[begin, end) (bounds and centroid bounds
 * given) and partitions the range into dst[begin, end), the left side from
 * begin up, the right side from end down; 0 when a leaf is better. */
static int sah_split(const prim_ref *src, prim_ref *dst, size_t begin, size_t end,
                     const bbox *bounds, const bbox *centroids, split *out)
{
    size_t count = end - begin;
    int nb = count < 64 ? 8 : count < 1024 ? 16 : BINS;
    float clo[4], chi[4], sc[4] = {0, 0, 0, 0};
    v4_store(clo, centroids->lo);
    v4_store(chi, centroids->hi);
    int any = 0;
    for (int a = 0; a < 3; a++) {
        float extent = chi[a] - clo[a];
        sc[a] = extent > 0 ? (float)nb * (1 - 1e-6f) / extent : 0;
        any |= sc[a] > 0;
    }
    if (!any)
        return 0;
    v4 origin = centroids->lo, scale = v4_set3(sc[0], sc[1], sc[2]), last = v4_set((float)(nb - 1));
    /* Two sets of bins, for even and odd references, so consecutive
     * references landing in the same bin do not wait on each other (for
     * small nodes one set: clearing and merging would cost more). */
    bin_set set[2];
    bins_clear(&set[0], nb);
    size_t i = begin;
    /* Large nodes bin an evenly spread sample of SAMPLE to 2 SAMPLE
     * references, which chooses the split about as well. */
    size_t stride = count >= 2 * SAMPLE ? count / SAMPLE : 1;
    if (count >= 64) {
        bins_clear(&set[1], nb);
        for (; i + stride < end; i += 2 * stride) {
            bins_add(&set[0], &src[i], origin, scale, last);
            bins_add(&set[1], &src[i + stride], origin, scale, last);
        }
        for (int a = 0; a < 3; a++)
            for (int k = 0; k < nb; k++) {
                bbox_grow(&set[0].box[a][k], set[1].box[a][k].lo, set[1].box[a][k].hi);
                set[0].count[a][k] += set[1].count[a][k];
            }
    }
    for (; i < end; i += stride)
        bins_add(&set[0], &src[i], origin, scale, last);
    bbox(*bins)[BINS] = set[0].box;
    int best_axis, best_bin;
    float best_cost;
    sah_sweep(&set[0], nb, sc, &best_axis, &best_bin, &best_cost);
    if (best_axis < 0)
        return 0;
    /* Splitting costs a traversal step plus the children's blocks weighted
     * by the chance of entering them; a leaf costs its blocks. */
    float parent_area = bbox_area(bounds);
    float split_cost = parent_area > 0 ? TRAVERSAL_COST + best_cost / parent_area : FLT_MAX;
    if (count <= MAX_LEAF && split_cost >= (float)BLOCKS(count))
        return 0;
    if (stride > 1) {
        /* Bins of a sample: the children's bounds from the partition. */
        out->mid = partition(src, dst, begin, end, origin, scale, best_axis, best_bin, out, 1);
        return 1;
    }
    bbox_empty(&out->left);
    bbox_empty(&out->right);
    for (int k = 0; k < nb; k++) {
        bbox *side = k <= best_bin ? &out->left : &out->right;
        bbox_grow(side, bins[best_axis][k].lo, bins[best_axis][k].hi);
    }
    out->mid = partition(src, dst, begin, end, origin, scale, best_axis, best_bin, out, 0);
    return 1;
}

static void range_bounds(const prim_ref *refs, size_t begin, size_t end, bbox *bounds,
                         bbox *centroids)
{
    bbox_empty(bounds);
    bbox_empty(centroids);
    for (size_t i = begin; i < end; i++) {
        v4 lo = v4_load3(refs[i].lo), hi = v4_load3(refs[i].hi), c = v4_add(lo, hi);
        bbox_grow(bounds, lo, hi);
        bbox_grow(centroids, c, c);
    }
}

/* Decides how node (bounds given) over src[begin, end) splits: 0 for a
 * leaf, else 1 with the split and the children's references in
 * dst[begin, end). */
static int choose_split(const prim_ref *src, prim_ref *dst, size_t begin, size_t end,
                        const bbox *bounds, const bbox *centroids, int depth, split *sp)
{
    size_t count = end - begin;
    /* Up to one block a leaf costs 1, and any split more (a traversal step
     * plus at least one block weighted by the chance of entering it): the
     * SAH would make a leaf, without binning. */
    if (count <= 4)
        return 0;
    if (depth < SAH_DEPTH && sah_split(src, dst, begin, end, bounds, centroids, sp))
        return 1;
    if (count <= MAX_LEAF)
        return 0;
    /* Many triangles with one centroid, or a tree deeper than SAH_DEPTH
     * (only for pathological inputs): split the range in two halves, which
     * bounds the depth by log2 of the count. */
    memcpy(dst + begin, src + begin, count * sizeof *src);
    sp->mid = begin + count / 2;
    range_bounds(dst, begin, sp->mid, &sp->left, &sp->left_centroids);
    range_bounds(dst, sp->mid, end, &sp->right, &sp->right_centroids);
    return 1;
}

/* Builds the subtree of node index (its bounds already stored) over the
 * references buf[which][begin, end). */
static void build_node(bvh_builder *b, uint32_t index, size_t begin, size_t end, bbox bounds,
                       bbox centroids, int depth, int which)
{
    for (;;) {
        split sp;
        const prim_ref *src = b->buf[which];
        if (!choose_split(src, b->buf[!which], begin, end, &bounds, &centroids, depth, &sp)) {
            for (size_t i = begin; i < end; i++)
                b->ids[i] = prim_id(&src[i]);
            b->nodes[index].offset = (uint32_t)begin;
            b->nodes[index].count = (uint32_t)(end - begin);
            return;
        }
        which = !which;
        /* The left child directly follows its parent; the right one's index
         * is known once the left subtree is built.  Recursing on the left and
         * looping on the right keeps the recursion depth at the tree depth
         * (at most SAH_DEPTH + 32). */
        uint32_t left = make_node(b, &sp.left);
        build_node(b, left, begin, sp.mid, sp.left, sp.left_centroids, depth + 1, which);
        uint32_t right = make_node(b, &sp.right);
        b->nodes[index].offset = right;
        index = right;
        begin = sp.mid;
        bounds = sp.right;
        centroids = sp.right_centroids;
        depth++;
    }
}

/* The root's two subtrees as the two blocks of one phase: the left one
 * into the builder's node array right after the root, the right one into
 * its own array, appended afterwards.  Whichever worker claims a block
 * builds it; the caller builds both when no other worker comes. */
typedef struct subtree {
    bvh_builder b;
    uint32_t root;
    size_t begin, end;
    bbox bounds, centroids;
} subtree;

typedef struct subtree_job {
    core_worker_pool *pool;
    core_worker_phase sides;
    subtree side[2];
} subtree_job;

static void build_subtrees(void *context, int worker)
{
    (void)worker;
    subtree_job *j = context;
    size_t k;
    while (core_worker_pool_claim(&j->sides, &k)) {
        subtree *s = &j->side[k];
        build_node(&s->b, s->root, s->begin, s->end, s->bounds, s->centroids, 2, 1);
        core_worker_pool_finish(j->pool, &j->sides);
    }
}

/* The right subtree's nodes after the left one's, its child links shifted. */
static void append_subtree(bvh_builder *b, uint32_t root, const bvh_builder *right)
{
    uint32_t shift = (uint32_t)b->node_count;
    b->nodes[root].offset = shift;
    for (size_t i = 0; i < right->node_count; i++) {
        bvh_node node = right->nodes[i];
        if (!node.count)
            node.offset += shift;
        b->nodes[shift + i] = node;
    }
    b->node_count += right->node_count;
}

int bvh_build_tree(bvh_builder *out, size_t n, core_worker_pool *pool)
{
    bbox bounds, centroids;
    range_bounds(out->buf[0], 0, n, &bounds, &centroids);
    bvh_builder b = *out;
    uint32_t root = make_node(&b, &bounds);
    split sp;
    if (core_worker_pool_workers(pool) < 2 || n < PARALLEL_MIN
        || !choose_split(b.buf[0], b.buf[1], 0, n, &bounds, &centroids, 1, &sp)) {
        build_node(&b, root, 0, n, bounds, centroids, 1, 0);
        *out = b;
        return 1;
    }
    subtree_job job;
    job.pool = pool;
    core_worker_pool_phase_init(&job.sides, 2);
    subtree *left = &job.side[0], *right = &job.side[1];
    left->b = b;
    left->root = make_node(&left->b, &sp.left);
    left->begin = 0;
    left->end = sp.mid;
    left->bounds = sp.left;
    left->centroids = sp.left_centroids;
    right->b = b;
    right->b.nodes = malloc((2 * (n - sp.mid)) * sizeof *right->b.nodes);
    right->b.node_count = 0;
    if (!right->b.nodes)
        return 0;
    right->root = make_node(&right->b, &sp.right);
    right->begin = sp.mid;
    right->end = n;
    right->bounds = sp.right;
    right->centroids = sp.right_centroids;
    core_worker_pool_run(pool, build_subtrees, &job);
    b = left->b;
    append_subtree(&b, root, &right->b);
    free(right->b.nodes);
    *out = b;
    return 1;
}
