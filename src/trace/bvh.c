/* Bounding volume hierarchy over triangles: binned SAH build, 32-byte nodes,
 * ordered traversal, and the watertight ray-triangle test of Woop, Benthin and
 * Wald (JCGT 2013). */
#include "internal.h"

#include <float.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

enum {
    BINS = 32,        /* most bins per axis for the SAH sweep */
    MAX_LEAF = 8,     /* a node with more triangles is always split */
    SAH_DEPTH = 48,   /* deeper than this, split at the object median */
    STACK_SIZE = 128, /* > SAH_DEPTH + 32: the deepest possible tree */
    PARALLEL_MIN = 4096 /* fewer triangles: build on one thread */
};

/* Cost of visiting a node relative to testing one triangle, for the SAH. */
#ifndef TRAVERSAL_COST
#define TRAVERSAL_COST 1.0f
#endif

/* ---- four-float vectors: SSE2 where available, plain C elsewhere -------- */

#if defined(__SSE2__)
#include <emmintrin.h>
typedef __m128 v4;
static inline v4 v4_load(const float *p) { return _mm_loadu_ps(p); }
static inline v4 v4_set(float x) { return _mm_set1_ps(x); }
/* Lanes 0..2 of p, lane 3 zero: the fourth float of a node or reference
 * holds integer bits, which as a float may be a denormal that slows
 * arithmetic, so it is masked off before any. */
static inline v4 v4_load3(const float *p)
{
    const __m128i mask = _mm_set_epi32(0, -1, -1, -1);
    return _mm_and_ps(_mm_loadu_ps(p), _mm_castsi128_ps(mask));
}
static inline v4 v4_add(v4 a, v4 b) { return _mm_add_ps(a, b); }
static inline v4 v4_sub(v4 a, v4 b) { return _mm_sub_ps(a, b); }
static inline v4 v4_mul(v4 a, v4 b) { return _mm_mul_ps(a, b); }
/* a < b ? a : b and a > b ? a : b per lane, as the instructions define. */
static inline v4 v4_min(v4 a, v4 b) { return _mm_min_ps(a, b); }
static inline v4 v4_max(v4 a, v4 b) { return _mm_max_ps(a, b); }
static inline void v4_store(float *p, v4 a) { _mm_storeu_ps(p, a); }
/* Lanes 0..2 truncated to integers. */
static inline void v4_to_int(v4 a, int *out)
{
    _mm_storeu_si128((__m128i *)(void *)out, _mm_cvttps_epi32(a));
}
/* max(lanes 0..2 of a, x) and min(lanes 0..2 of a, x). */
static inline float v4_max3(v4 a, float x)
{
    v4 b = _mm_shuffle_ps(a, a, _MM_SHUFFLE(1, 1, 1, 1)), c = _mm_shuffle_ps(a, a, _MM_SHUFFLE(2, 2, 2, 2));
    return _mm_cvtss_f32(_mm_max_ss(_mm_max_ss(a, b), _mm_max_ss(c, _mm_set_ss(x))));
}
static inline float v4_min3(v4 a, float x)
{
    v4 b = _mm_shuffle_ps(a, a, _MM_SHUFFLE(1, 1, 1, 1)), c = _mm_shuffle_ps(a, a, _MM_SHUFFLE(2, 2, 2, 2));
    return _mm_cvtss_f32(_mm_min_ss(_mm_min_ss(a, b), _mm_min_ss(c, _mm_set_ss(x))));
}
/* Lanes 0 and 1: max (min) of lanes 0..2 of a, and of b. */
static inline v4 v4_max2x3(v4 a, v4 b)
{
    v4 xy = _mm_unpacklo_ps(a, b), zw = _mm_unpackhi_ps(a, b); /* ax bx ay by, az bz .. */
    return _mm_max_ps(_mm_max_ps(xy, zw), _mm_movehl_ps(xy, xy));
}
static inline v4 v4_min2x3(v4 a, v4 b)
{
    v4 xy = _mm_unpacklo_ps(a, b), zw = _mm_unpackhi_ps(a, b);
    return _mm_min_ps(_mm_min_ps(xy, zw), _mm_movehl_ps(xy, xy));
}
#else
typedef struct v4 { float f[4]; } v4;
static inline v4 v4_load(const float *p) { v4 r; memcpy(r.f, p, sizeof r.f); return r; }
static inline v4 v4_set(float x) { v4 r = {{x, x, x, x}}; return r; }
static inline v4 v4_load3(const float *p) { v4 r = {{p[0], p[1], p[2], 0}}; return r; }
#define V4_OP(name, expr)                                        \
    static inline v4 name(v4 a, v4 b)                            \
    {                                                            \
        v4 r;                                                    \
        for (int i = 0; i < 4; i++)                              \
            r.f[i] = (expr);                                     \
        return r;                                                \
    }
V4_OP(v4_add, a.f[i] + b.f[i])
V4_OP(v4_sub, a.f[i] - b.f[i])
V4_OP(v4_mul, a.f[i] * b.f[i])
V4_OP(v4_min, a.f[i] < b.f[i] ? a.f[i] : b.f[i])
V4_OP(v4_max, a.f[i] > b.f[i] ? a.f[i] : b.f[i])
#undef V4_OP
static inline void v4_store(float *p, v4 a) { memcpy(p, a.f, sizeof a.f); }
static inline void v4_to_int(v4 a, int *out)
{
    for (int i = 0; i < 4; i++)
        out[i] = (a.f[i] > -2e9f && a.f[i] < 2e9f) ? (int)a.f[i] : 0;
}
static inline float v4_max3(v4 a, float x)
{
    float m = a.f[0] > a.f[1] ? a.f[0] : a.f[1];
    m = m > a.f[2] ? m : a.f[2];
    return m > x ? m : x;
}
static inline float v4_min3(v4 a, float x)
{
    float m = a.f[0] < a.f[1] ? a.f[0] : a.f[1];
    m = m < a.f[2] ? m : a.f[2];
    return m < x ? m : x;
}
#endif

/* ---- building ------------------------------------------------------------ */

/* A triangle's bounds while building: lanes 0..2 of lo and hi, its index in
 * the fourth float of lo (as bits). */
typedef struct prim_ref {
    float lo[4];
    float hi[4];
} prim_ref;

static inline uint32_t prim_id(const prim_ref *r)
{
    uint32_t id;
    memcpy(&id, &r->lo[3], sizeof id);
    return id;
}

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

/* Half the surface area (the factor cancels in the SAH); 0 when empty. */
static inline float bbox_area(const bbox *b)
{
#if defined(__SSE2__)
    /* The scalar formula below, lane by lane: (dx dy + dy dz) + dz dx. */
    v4 d = _mm_sub_ps(b->hi, b->lo);
    if (_mm_movemask_ps(_mm_cmplt_ps(d, _mm_setzero_ps())) & 7)
        return 0;
    v4 p = _mm_mul_ps(d, _mm_shuffle_ps(d, d, _MM_SHUFFLE(3, 0, 2, 1)));
    v4 s = _mm_add_ss(p, _mm_shuffle_ps(p, p, _MM_SHUFFLE(1, 1, 1, 1)));
    return _mm_cvtss_f32(_mm_add_ss(s, _mm_movehl_ps(p, p)));
#else
    float lo[4], hi[4];
    v4_store(lo, b->lo);
    v4_store(hi, b->hi);
    float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    if (dx < 0 || dy < 0 || dz < 0)
        return 0;
    return dx * dy + dy * dz + dz * dx;
#endif
}

typedef struct builder {
    prim_ref *refs;
    bvh_node *nodes;
    size_t node_count;
    int depth;
} builder;

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

static uint32_t make_node(builder *b, const bbox *bounds)
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

/* Finds the binned-SAH split of refs[begin, end) (bounds and centroid
 * bounds given) and partitions the range; 0 when a leaf is better. */
static int sah_split(prim_ref *refs, size_t begin, size_t end, const bbox *bounds,
                     const bbox *centroids, split *out)
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
    v4 origin = centroids->lo, scale = v4_load(sc), last = v4_set((float)(nb - 1));
    bbox bins[3][BINS];
    uint32_t counts[3][BINS];
    for (int a = 0; a < 3; a++)
        for (int k = 0; k < nb; k++) {
            bbox_empty(&bins[a][k]);
            counts[a][k] = 0;
        }
    for (size_t i = begin; i < end; i++) {
        v4 lo = v4_load3(refs[i].lo), hi = v4_load3(refs[i].hi);
        int k[4];
        bin_of(v4_add(lo, hi), origin, scale, last, k);
        for (int a = 0; a < 3; a++) {
            bbox_grow(&bins[a][k[a]], lo, hi);
            counts[a][k[a]]++;
        }
    }
    int best_axis = -1, best_bin = 0;
    float best_cost = FLT_MAX;
    for (int a = 0; a < 3; a++) {
        if (sc[a] == 0)
            continue;
        float right_area[BINS];
        uint32_t right_count[BINS];
        bbox acc;
        bbox_empty(&acc);
        uint32_t n = 0;
        for (int k = nb - 1; k > 0; k--) {
            bbox_grow(&acc, bins[a][k].lo, bins[a][k].hi);
            n += counts[a][k];
            right_area[k] = bbox_area(&acc);
            right_count[k] = n;
        }
        bbox_empty(&acc);
        n = 0;
        for (int k = 0; k < nb - 1; k++) {
            bbox_grow(&acc, bins[a][k].lo, bins[a][k].hi);
            n += counts[a][k];
            if (n == 0 || right_count[k + 1] == 0)
                continue;
            float cost = bbox_area(&acc) * (float)n + right_area[k + 1] * (float)right_count[k + 1];
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = a;
                best_bin = k;
            }
        }
    }
    if (best_axis < 0)
        return 0;
    /* Splitting costs a traversal step (1) plus the children's triangles
     * weighted by the chance of entering them; a leaf costs its count. */
    float parent_area = bbox_area(bounds);
    float split_cost = parent_area > 0 ? TRAVERSAL_COST + best_cost / parent_area : FLT_MAX;
    if (count <= MAX_LEAF && split_cost >= (float)count)
        return 0;
    bbox_empty(&out->left);
    bbox_empty(&out->right);
    bbox_empty(&out->left_centroids);
    bbox_empty(&out->right_centroids);
    for (int k = 0; k < nb; k++) {
        bbox *side = k <= best_bin ? &out->left : &out->right;
        bbox_grow(side, bins[best_axis][k].lo, bins[best_axis][k].hi);
    }
    size_t i = begin, j = end;
    while (i < j) {
        v4 lo = v4_load3(refs[i].lo), hi = v4_load3(refs[i].hi), c = v4_add(lo, hi);
        int k[4];
        bin_of(c, origin, scale, last, k);
        if (k[best_axis] <= best_bin) {
            bbox_grow(&out->left_centroids, c, c);
            i++;
        } else {
            j--;
            bbox_grow(&out->right_centroids, c, c);
            prim_ref t = refs[i];
            refs[i] = refs[j];
            refs[j] = t;
        }
    }
    out->mid = i;
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

/* Decides how node (bounds given) over refs[begin, end) splits: 0 for a
 * leaf, else 1 with the split. */
static int choose_split(prim_ref *refs, size_t begin, size_t end, const bbox *bounds,
                        const bbox *centroids, int depth, split *sp)
{
    size_t count = end - begin;
    if (count <= 2)
        return 0;
    if (depth < SAH_DEPTH && sah_split(refs, begin, end, bounds, centroids, sp))
        return 1;
    if (count <= MAX_LEAF)
        return 0;
    /* Many triangles with one centroid, or a tree deeper than SAH_DEPTH
     * (only for pathological inputs): split the range in two halves, which
     * bounds the depth by log2 of the count. */
    sp->mid = begin + count / 2;
    range_bounds(refs, begin, sp->mid, &sp->left, &sp->left_centroids);
    range_bounds(refs, sp->mid, end, &sp->right, &sp->right_centroids);
    return 1;
}

/* Builds the subtree of node index (its bounds already stored). */
static void build_node(builder *b, uint32_t index, size_t begin, size_t end, bbox bounds,
                       bbox centroids, int depth)
{
    for (;;) {
        if (depth > b->depth)
            b->depth = depth;
        split sp;
        if (!choose_split(b->refs, begin, end, &bounds, &centroids, depth, &sp)) {
            b->nodes[index].offset = (uint32_t)begin;
            b->nodes[index].count = (uint32_t)(end - begin);
            return;
        }
        /* The left child directly follows its parent; the right one's index
         * is known once the left subtree is built.  Recursing on the left and
         * looping on the right keeps the recursion depth at the tree depth
         * (at most SAH_DEPTH + 32). */
        uint32_t left = make_node(b, &sp.left);
        build_node(b, left, begin, sp.mid, sp.left, sp.left_centroids, depth + 1);
        uint32_t right = make_node(b, &sp.right);
        b->nodes[index].offset = right;
        index = right;
        begin = sp.mid;
        bounds = sp.right;
        centroids = sp.right_centroids;
        depth++;
    }
}

/* The right subtree of the root, built on a second thread into its own node
 * array and appended afterwards. */
typedef struct subtree_job {
    builder b;
    size_t begin, end;
    bbox bounds, centroids;
} subtree_job;

static void *build_subtree(void *arg)
{
    subtree_job *j = arg;
    uint32_t root = make_node(&j->b, &j->bounds);
    build_node(&j->b, root, j->begin, j->end, j->bounds, j->centroids, 2);
    return NULL;
}

static void sah_of(const cg_bvh *bvh, uint32_t index, double *cost)
{
    const bvh_node *n = &bvh->nodes[index];
    bbox b;
    b.lo = v4_load3(n->lo);
    b.hi = v4_load3(n->hi);
    double area = bbox_area(&b);
    if (n->count) {
        *cost += area * n->count;
        return;
    }
    *cost += area;
    sah_of(bvh, index + 1, cost);
    sah_of(bvh, n->offset, cost);
}

/* The tree of refs[0, n) into bvh->nodes; with threads > 1 the root's two
 * subtrees are built at the same time.  The tree is the same either way. */
static int build_tree(cg_bvh *bvh, prim_ref *refs, size_t n, int threads)
{
    bbox bounds, centroids;
    range_bounds(refs, 0, n, &bounds, &centroids);
    builder b = {refs, bvh->nodes, 0, 0};
    uint32_t root = make_node(&b, &bounds);
    split sp;
    if (threads < 2 || n < PARALLEL_MIN || !choose_split(refs, 0, n, &bounds, &centroids, 1, &sp)) {
        build_node(&b, root, 0, n, bounds, centroids, 1);
        bvh->node_count = b.node_count;
        bvh->depth = b.depth;
        return 1;
    }
    size_t right_count = n - sp.mid;
    subtree_job job;
    job.b.refs = refs;
    job.b.nodes = malloc((2 * right_count) * sizeof *job.b.nodes);
    job.b.node_count = 0;
    job.b.depth = 0;
    job.begin = sp.mid;
    job.end = n;
    job.bounds = sp.right;
    job.centroids = sp.right_centroids;
    pthread_t id;
    int parallel = job.b.nodes && pthread_create(&id, NULL, build_subtree, &job) == 0;
    uint32_t left = make_node(&b, &sp.left);
    build_node(&b, left, 0, sp.mid, sp.left, sp.left_centroids, 2);
    if (parallel) {
        pthread_join(id, NULL);
    } else {
        /* No second thread: the same subtree on this one. */
        if (!job.b.nodes)
            job.b.nodes = malloc((2 * right_count) * sizeof *job.b.nodes);
        if (!job.b.nodes)
            return 0;
        build_subtree(&job);
    }
    /* Append the right subtree, shifting its child links. */
    uint32_t shift = (uint32_t)b.node_count;
    bvh->nodes[root].offset = shift;
    for (size_t i = 0; i < job.b.node_count; i++) {
        bvh_node node = job.b.nodes[i];
        if (!node.count)
            node.offset += shift;
        bvh->nodes[shift + i] = node;
    }
    bvh->node_count = b.node_count + job.b.node_count;
    bvh->depth = b.depth > job.b.depth ? b.depth : job.b.depth;
    free(job.b.nodes);
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
    if ((!positions && vertex_count) || (triangle_count && !positions) || threads < 1)
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
    prim_ref *refs = malloc((triangle_count ? triangle_count : 1) * sizeof *refs);
    if (!bvh || !refs) {
        free(bvh);
        free(refs);
        return CG_ENOMEM;
    }
    /* Finite triangles only; coordinates rounded to float once, here. */
    size_t n = 0;
    for (size_t i = 0; i < triangle_count; i++) {
        prim_ref r;
        int finite = 1;
        for (int a = 0; a < 3; a++) {
            r.lo[a] = FLT_MAX;
            r.hi[a] = -FLT_MAX;
        }
        for (int k = 0; k < 3 && finite; k++) {
            cg_vec3 p = positions[indices ? indices[3 * i + k] : 3 * i + k];
            float f[3] = {(float)p.x, (float)p.y, (float)p.z};
            for (int a = 0; a < 3; a++) {
                if (!isfinite(f[a])) {
                    finite = 0;
                    break;
                }
                if (f[a] < r.lo[a])
                    r.lo[a] = f[a];
                if (f[a] > r.hi[a])
                    r.hi[a] = f[a];
            }
        }
        if (!finite)
            continue;
        uint32_t id = (uint32_t)i;
        memcpy(&r.lo[3], &id, sizeof id);
        r.hi[3] = 0;
        refs[n++] = r;
    }
    bvh->triangle_count = n;
    bvh->nodes = malloc((2 * n + 1) * sizeof *bvh->nodes);
    bvh->triangles = malloc((n ? n : 1) * sizeof *bvh->triangles);
    if (!bvh->nodes || !bvh->triangles || (n && !build_tree(bvh, refs, n, threads))) {
        free(refs);
        cg_bvh_free(bvh);
        return CG_ENOMEM;
    }
    for (size_t i = 0; i < n; i++) {
        bvh_triangle *t = &bvh->triangles[i];
        uint32_t id = prim_id(&refs[i]);
        float *corner[3] = {t->v0, t->v1, t->v2};
        for (int k = 0; k < 3; k++) {
            cg_vec3 p = positions[indices ? indices[3 * (size_t)id + k] : 3 * (size_t)id + k];
            corner[k][0] = (float)p.x;
            corner[k][1] = (float)p.y;
            corner[k][2] = (float)p.z;
        }
        t->id = id;
    }
    free(refs);
    *out = bvh;
    return CG_OK;
}

void cg_bvh_free(cg_bvh *bvh)
{
    if (!bvh)
        return;
    free(bvh->nodes);
    free(bvh->triangles);
    free(bvh);
}

void cg_bvh_get_stats(const cg_bvh *bvh, cg_bvh_stats *out)
{
    memset(out, 0, sizeof *out);
    if (!bvh)
        return;
    out->triangles = bvh->triangle_count;
    out->nodes = bvh->node_count;
    out->depth = bvh->depth;
    for (size_t i = 0; i < bvh->node_count; i++)
        out->leaves += bvh->nodes[i].count != 0;
    if (bvh->node_count) {
        double cost = 0;
        sah_of(bvh, 0, &cost);
        bbox b;
        b.lo = v4_load3(bvh->nodes[0].lo);
        b.hi = v4_load3(bvh->nodes[0].hi);
        double area = bbox_area(&b);
        out->sah_cost = area > 0 ? cost / area : 0;
    }
}

/* ---- rays and the triangle test ---------------------------------------- */

/* The ray's checks and its data for the slab test (origin, inverse, flat
 * axes) and the watertight test's dominant axis kz; 0 when the ray is not
 * finite or has zero direction. */
static int ray_setup_slabs(bvh_ray *ray, cg_vec3 origin, cg_vec3 direction, double t_min)
{
    double o[3] = {origin.x, origin.y, origin.z}, d[3] = {direction.x, direction.y, direction.z};
    int kz = 0;
    for (int a = 0; a < 3; a++) {
        if (!isfinite(o[a]) || !isfinite(d[a]) || !isfinite((float)o[a]))
            return 0;
        if (fabs(d[a]) > fabs(d[kz]))
            kz = a;
    }
    if (d[kz] == 0 || !isfinite(t_min))
        return 0;
    ray->flat_axes = 0;
    for (int a = 0; a < 3; a++) {
        ray->direction[a] = d[a];
        ray->origin[a] = (float)o[a];
        float f = (float)d[a];
        /* A zero (or float-underflowing) component is handled apart by the
         * slab test; its inverse only has to stay finite. */
        if (f == 0) {
            f = 1e-30f;
            ray->flat_axes |= 1 << a;
        }
        ray->inverse[a] = 1.0f / f;
    }
    ray->kz = kz;
    ray->t_min = (float)t_min;
    return 1;
}

/* The rest of the watertight test's data: the axis permutation and the
 * shear.  Apart, so that rays missing the BVH's root box (most primary
 * rays of a framed mesh) skip its three divisions. */
static void ray_setup_shear(bvh_ray *ray)
{
    const double *d = ray->direction;
    int kz = ray->kz, kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0) {
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    ray->kx = kx;
    ray->ky = ky;
    ray->shear_x = (float)(d[kx] / d[kz]);
    ray->shear_y = (float)(d[ky] / d[kz]);
    ray->shear_z = (float)(1.0 / d[kz]);
}

int bvh_ray_setup(bvh_ray *ray, cg_vec3 origin, cg_vec3 direction, double t_min)
{
    if (!ray_setup_slabs(ray, origin, direction, t_min))
        return 0;
    ray_setup_shear(ray);
    return 1;
}

/* The watertight test against t in (ray->t_min, t_max] (t_max included when
 * inclusive, excluded otherwise).  Edge functions exactly zero are recomputed
 * in double, as the paper prescribes, so the sign decision is consistent
 * between neighbouring triangles. */
static inline int hit_triangle(const bvh_ray *ray, const bvh_triangle *tri, float *t_out,
                               float *u_out, float *v_out)
{
    const int kx = ray->kx, ky = ray->ky, kz = ray->kz;
    const float ax = tri->v0[kx] - ray->origin[kx], ay = tri->v0[ky] - ray->origin[ky],
                az = tri->v0[kz] - ray->origin[kz];
    const float bx = tri->v1[kx] - ray->origin[kx], by = tri->v1[ky] - ray->origin[ky],
                bz = tri->v1[kz] - ray->origin[kz];
    const float cx = tri->v2[kx] - ray->origin[kx], cy = tri->v2[ky] - ray->origin[ky],
                cz = tri->v2[kz] - ray->origin[kz];
    const float Ax = ax - ray->shear_x * az, Ay = ay - ray->shear_y * az;
    const float Bx = bx - ray->shear_x * bz, By = by - ray->shear_y * bz;
    const float Cx = cx - ray->shear_x * cz, Cy = cy - ray->shear_y * cz;
    float U = Cx * By - Cy * Bx;
    float V = Ax * Cy - Ay * Cx;
    float W = Bx * Ay - By * Ax;
    if (U == 0 || V == 0 || W == 0) {
        U = (float)((double)Cx * By - (double)Cy * Bx);
        V = (float)((double)Ax * Cy - (double)Ay * Cx);
        W = (float)((double)Bx * Ay - (double)By * Ax);
    }
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0))
        return 0;
    float det = U + V + W;
    if (det == 0)
        return 0;
    float T = U * (ray->shear_z * az) + V * (ray->shear_z * bz) + W * (ray->shear_z * cz);
    float inv = 1.0f / det;
    float t = T * inv;
    if (!(t > ray->t_min))
        return 0;
    *t_out = t;
    *u_out = V * inv;
    *v_out = W * inv;
    return 1;
}

/* The slab test for rays with a zero direction component: on such an axis
 * the slab holds the whole ray or none of it, boundaries included. */
static int hit_box_flat(const bvh_ray *ray, const bvh_node *node, float t_far_limit,
                        float *t_near)
{
    float tn = ray->t_min, tf = FLT_MAX;
    for (int a = 0; a < 3; a++) {
        if (ray->flat_axes & (1 << a)) {
            if (ray->origin[a] < node->lo[a] || ray->origin[a] > node->hi[a]) {
                *t_near = FLT_MAX;
                return 0;
            }
            continue;
        }
        float t0 = (node->lo[a] - ray->origin[a]) * ray->inverse[a];
        float t1 = (node->hi[a] - ray->origin[a]) * ray->inverse[a];
        float n = t0 < t1 ? t0 : t1, f = t0 < t1 ? t1 : t0;
        tn = n > tn ? n : tn;
        tf = f < tf ? f : tf;
    }
    tf *= 1.0000003576f;
    tf = tf < t_far_limit ? tf : t_far_limit;
    *t_near = tn;
    return tn <= tf;
}

/* Slab test; far distances grown by 1 + 2 gamma(3) (Ize 2013) so rounding
 * never rejects a box that the exact ray touches.  origin and inverse hold
 * the ray's origin and 1 / direction in lanes 0..2. */
static inline int hit_box(const bvh_ray *ray, v4 origin, v4 inverse, const bvh_node *node,
                          float t_far_limit, float *t_near)
{
    if (ray->flat_axes)
        return hit_box_flat(ray, node, t_far_limit, t_near);
    v4 t0 = v4_mul(v4_sub(v4_load3(node->lo), origin), inverse);
    v4 t1 = v4_mul(v4_sub(v4_load3(node->hi), origin), inverse);
    float tn = v4_max3(v4_min(t0, t1), ray->t_min);
    float tf = v4_min3(v4_max(t0, t1), FLT_MAX) * 1.0000003576f;
    tf = tf < t_far_limit ? tf : t_far_limit;
    *t_near = tn;
    return tn <= tf;
}

/* Both children of a node at once: hit_box's operations, with the two
 * boxes' horizontal reductions shared (lanes 0 and 1 hold the first and the
 * second box), so each decision is the one hit_box would make.  Bit 0 of
 * the result: the first box is hit; bit 1: the second. */
static inline int hit_boxes(const bvh_ray *ray, v4 origin, v4 inverse, const bvh_node *first,
                            const bvh_node *second, v4 t_min4, v4 t_far_limit4,
                            float t_far_limit, float t_near[2])
{
#if defined(__SSE2__)
    if (ray->flat_axes) {
        int a = hit_box_flat(ray, first, t_far_limit, &t_near[0]);
        return a | hit_box_flat(ray, second, t_far_limit, &t_near[1]) << 1;
    }
    v4 a0 = v4_mul(v4_sub(v4_load3(first->lo), origin), inverse);
    v4 a1 = v4_mul(v4_sub(v4_load3(first->hi), origin), inverse);
    v4 b0 = v4_mul(v4_sub(v4_load3(second->lo), origin), inverse);
    v4 b1 = v4_mul(v4_sub(v4_load3(second->hi), origin), inverse);
    v4 tn = v4_max2x3(v4_min(a0, a1), v4_min(b0, b1));
    v4 tf = v4_min2x3(v4_max(a0, a1), v4_max(b0, b1));
    tn = v4_max(tn, t_min4);
    tf = v4_mul(v4_min(tf, v4_set(FLT_MAX)), v4_set(1.0000003576f));
    tf = v4_min(tf, t_far_limit4);
    float near4[4];
    v4_store(near4, tn);
    t_near[0] = near4[0];
    t_near[1] = near4[1];
    return _mm_movemask_ps(_mm_cmple_ps(tn, tf)) & 3;
#else
    (void)t_min4;
    (void)t_far_limit4;
    int a = hit_box(ray, origin, inverse, first, t_far_limit, &t_near[0]);
    return a | hit_box(ray, origin, inverse, second, t_far_limit, &t_near[1]) << 1;
#endif
}

/* How far beyond the best hit so far a box may begin and still be entered:
 * the box and triangle tests round differently, so a triangle touching its
 * box's boundary can report a t an ulp or so before the computed entry. */
static inline float cull_limit(float t)
{
    return t + fabsf(t) * (1.0f / 65536);
}

/* Is the candidate (t, id) better than the best so far? */
static inline int better(float t, uint32_t id, float best_t, uint32_t best_id)
{
    return t < best_t || (t == best_t && id < best_id);
}

static float clamp_far(double t_max)
{
    if (!(t_max < (double)FLT_MAX))
        return FLT_MAX;
    return (float)t_max;
}

/* Ordered traversal.  Nearest hit (any_hit 0): the best (t, index) with t in
 * (t_min, t_max].  Shadow query (any_hit 1): stops at the first t in
 * (t_min, t_max).  The ray comes with its slab data (ray_setup_slabs). */
static inline int traverse(const cg_bvh *bvh, bvh_ray *ray, float t_max, int any_hit,
                           cg_bvh_hit *hit)
{
    float best_t = t_max, limit = cull_limit(best_t);
    const float o3[4] = {ray->origin[0], ray->origin[1], ray->origin[2], 0};
    const float i3[4] = {ray->inverse[0], ray->inverse[1], ray->inverse[2], 0};
    v4 o4 = v4_load(o3), i4 = v4_load(i3), t_min4 = v4_set(ray->t_min), limit4 = v4_set(limit);
    uint32_t best_id = UINT32_MAX;
    float best_u = 0, best_v = 0;
    int found = 0;
    uint32_t stack[STACK_SIZE];
    float stack_t[STACK_SIZE];
    int top = 0;
    float tn;
    if (!hit_box(ray, o4, i4, &bvh->nodes[0], limit, &tn))
        return 0;
    ray_setup_shear(ray);
    uint32_t index = 0;
    for (;;) {
        const bvh_node *node = &bvh->nodes[index];
        if (node->count) {
            const bvh_triangle *tri = bvh->triangles + node->offset;
            for (uint32_t k = 0; k < node->count; k++) {
                float t, u, v;
                if (!hit_triangle(ray, &tri[k], &t, &u, &v))
                    continue;
                if (any_hit) {
                    if (t < t_max)
                        return 1;
                } else if (better(t, tri[k].id, best_t, best_id)) {
                    best_t = t;
                    best_id = tri[k].id;
                    best_u = u;
                    best_v = v;
                    found = 1;
                    limit = cull_limit(t);
                    limit4 = v4_set(limit);
                }
            }
        } else {
            uint32_t left = index + 1, right = node->offset;
            float tb[2];
            int h = hit_boxes(ray, o4, i4, &bvh->nodes[left], &bvh->nodes[right], t_min4,
                              limit4, limit, tb);
            if (h == 3) {
                if (tb[1] < tb[0]) {
                    uint32_t s = left;
                    left = right;
                    right = s;
                    tb[1] = tb[0];
                }
                stack[top] = right;
                /* A shadow ray's limit never shrinks, so what it pushed
                 * stays worth visiting: no distance to keep. */
                if (!any_hit)
                    stack_t[top] = tb[1];
                top++;
                index = left;
                continue;
            }
            if (h) {
                index = h == 1 ? left : right;
                continue;
            }
        }
        /* Pop the next subtree that can still hold a nearer hit. */
        for (;;) {
            if (top == 0)
                goto done;
            top--;
            if (any_hit || stack_t[top] <= limit)
                break;
        }
        index = stack[top];
    }
done:
    if (found && hit) {
        hit->triangle = best_id;
        hit->t = best_t;
        hit->u = best_u;
        hit->v = best_v;
    }
    return found;
}

int cg_bvh_intersect(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                     double t_max, cg_bvh_hit *hit)
{
    bvh_ray ray;
    if (!bvh || !bvh->node_count || !ray_setup_slabs(&ray, origin, direction, t_min)
        || !(t_max > t_min))
        return 0;
    return traverse(bvh, &ray, clamp_far(t_max), 0, hit);
}

int cg_bvh_occluded(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                    double t_max)
{
    bvh_ray ray;
    if (!bvh || !bvh->node_count || !ray_setup_slabs(&ray, origin, direction, t_min)
        || !(t_max > t_min))
        return 0;
    return traverse(bvh, &ray, clamp_far(t_max), 1, NULL);
}

int cg_bvh_intersect_brute(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                           double t_max, cg_bvh_hit *hit)
{
    bvh_ray ray;
    if (!bvh || !bvh_ray_setup(&ray, origin, direction, t_min) || !(t_max > t_min))
        return 0;
    float best_t = clamp_far(t_max);
    uint32_t best_id = UINT32_MAX;
    int found = 0;
    for (size_t i = 0; i < bvh->triangle_count; i++) {
        float t, u, v;
        const bvh_triangle *tri = &bvh->triangles[i];
        if (hit_triangle(&ray, tri, &t, &u, &v) && better(t, tri->id, best_t, best_id)) {
            best_t = t;
            best_id = tri->id;
            found = 1;
            if (hit) {
                hit->u = u;
                hit->v = v;
            }
        }
    }
    if (found && hit) {
        hit->triangle = best_id;
        hit->t = best_t;
    }
    return found;
}

int cg_ray_triangle(cg_vec3 origin, cg_vec3 direction, cg_vec3 a, cg_vec3 b, cg_vec3 c,
                    double t_min, double t_max, double *t, double *u, double *v)
{
    bvh_ray ray;
    if (!bvh_ray_setup(&ray, origin, direction, t_min))
        return 0;
    bvh_triangle tri;
    const cg_vec3 corner[3] = {a, b, c};
    float *dst[3] = {tri.v0, tri.v1, tri.v2};
    for (int k = 0; k < 3; k++) {
        dst[k][0] = (float)corner[k].x;
        dst[k][1] = (float)corner[k].y;
        dst[k][2] = (float)corner[k].z;
        if (!isfinite(dst[k][0]) || !isfinite(dst[k][1]) || !isfinite(dst[k][2]))
            return 0;
    }
    tri.id = 0;
    float ft, fu, fv;
    if (!hit_triangle(&ray, &tri, &ft, &fu, &fv) || !(ft <= t_max))
        return 0;
    if (t)
        *t = ft;
    if (u)
        *u = fu;
    if (v)
        *v = fv;
    return 1;
}
