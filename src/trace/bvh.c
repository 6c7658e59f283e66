/* Bounding volume hierarchy over triangles: a binary tree built with the
 * binned surface area heuristic, collapsed into a 4-wide tree whose nodes
 * hold their four children's boxes by coordinate; triangles in blocks of
 * four; ordered traversal testing four boxes or four triangles in one SSE2
 * pass; the watertight ray-triangle test of Woop, Benthin and Wald (JCGT
 * 2013). */
#include "internal.h"

#include <float.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

enum {
    BINS = 32,        /* most bins per axis for the SAH sweep */
    MAX_LEAF = 8,     /* a node with more triangles is always split (a leaf
                         reference holds counts 1 to 8) */
    SAH_DEPTH = 48,   /* deeper than this, split at the object median */
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
/* A point's coordinates rounded to float in lanes 0..2, lane 3 zero (built
 * in registers: a vector load of three scalar stores would stall). */
static inline v4 v4_point(const cg_vec3 *p)
{
    __m128 xy = _mm_cvtpd_ps(_mm_loadu_pd(&p->x)), z = _mm_cvtsd_ss(_mm_setzero_ps(), _mm_load_sd(&p->z));
    return _mm_movelh_ps(xy, z);
}
/* (x, y, z, 0) from scalars, in registers. */
static inline v4 v4_set3(float x, float y, float z) { return _mm_setr_ps(x, y, z, 0); }
/* Are lanes 0..2 all zero? */
static inline int v4_zero3(v4 a) { return (_mm_movemask_ps(_mm_cmpeq_ps(a, _mm_setzero_ps())) & 7) == 7; }
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
static inline v4 v4_point(const cg_vec3 *p)
{
    v4 r = {{(float)p->x, (float)p->y, (float)p->z, 0}};
    return r;
}
static inline int v4_zero3(v4 a) { return a.f[0] == 0 && a.f[1] == 0 && a.f[2] == 0; }
static inline v4 v4_set3(float x, float y, float z)
{
    v4 r = {{x, y, z, 0}};
    return r;
}
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

/* The build's state: the references in two buffers (a node's range lives in
 * one, its partition writes the children's into the other), the triangle
 * index of each leaf position, and the nodes. */
typedef struct builder {
    prim_ref *buf[2];
    uint32_t *ids;
    bvh_node *nodes;
    size_t node_count;
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

#if defined(__SSE2__)
/* Three boxes by coordinate (lane a: box a; lo x, y, z, hi x, y, z): their
 * bbox_area, (dx dy + dy dz) + dz dx or 0 when empty, lane by lane. */
static inline v4 area3(const v4 *b)
{
    const v4 zero = _mm_setzero_ps();
    v4 dx = _mm_sub_ps(b[3], b[0]), dy = _mm_sub_ps(b[4], b[1]), dz = _mm_sub_ps(b[5], b[2]);
    v4 empty = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(dx, zero), _mm_cmplt_ps(dy, zero)), _mm_cmplt_ps(dz, zero));
    v4 area = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dy), _mm_mul_ps(dy, dz)), _mm_mul_ps(dz, dx));
    return _mm_andnot_ps(empty, area);
}
#endif

/* The SAH sweep over the bins: the axis and bin (the last one on the left)
 * of least A_left blocks(N_left) + A_right blocks(N_right), the first in
 * axis-then-bin order on ties; axes with sc[a] 0 are left out, and so are
 * planes with an empty side.  best_axis -1 when there is none. */
static void sah_sweep(const bin_set *s, int nb, const float *sc, int *best_axis, int *best_bin,
                      float *best_cost)
{
    *best_axis = -1;
    *best_bin = 0;
    *best_cost = FLT_MAX;
#if defined(__SSE2__)
    /* The three axes at once, one per lane: the bins turned into
     * coordinate vectors (lane a: axis a's bin), each lane computing what
     * the scalar sweep below computes for its axis, in the same order. */
    v4 box[BINS][6];
    __m128i cnt[BINS];
    const v4 zero = _mm_setzero_ps();
    for (int k = 0; k < nb; k++) {
        v4 l0 = s->box[0][k].lo, l1 = s->box[1][k].lo, l2 = s->box[2][k].lo, l3 = zero;
        v4 h0 = s->box[0][k].hi, h1 = s->box[1][k].hi, h2 = s->box[2][k].hi, h3 = zero;
        _MM_TRANSPOSE4_PS(l0, l1, l2, l3);
        _MM_TRANSPOSE4_PS(h0, h1, h2, h3);
        box[k][0] = l0;
        box[k][1] = l1;
        box[k][2] = l2;
        box[k][3] = h0;
        box[k][4] = h1;
        box[k][5] = h2;
        cnt[k] = _mm_set_epi32(0, (int)s->count[2][k], (int)s->count[1][k], (int)s->count[0][k]);
    }
#define BLOCKS4(n) _mm_cvtepi32_ps(_mm_srli_epi32(_mm_add_epi32(n, _mm_set1_epi32(3)), 2))
    v4 right_area[BINS];
    __m128i right_count[BINS];
    v4 acc[6] = {v4_set(FLT_MAX), v4_set(FLT_MAX), v4_set(FLT_MAX),
                 v4_set(-FLT_MAX), v4_set(-FLT_MAX), v4_set(-FLT_MAX)};
    __m128i n = _mm_setzero_si128();
    for (int k = nb - 1; k > 0; k--) {
        for (int j = 0; j < 3; j++) {
            acc[j] = _mm_min_ps(acc[j], box[k][j]);
            acc[3 + j] = _mm_max_ps(acc[3 + j], box[k][3 + j]);
        }
        n = _mm_add_epi32(n, cnt[k]);
        right_area[k] = area3(acc);
        right_count[k] = n;
    }
    for (int j = 0; j < 3; j++) {
        acc[j] = v4_set(FLT_MAX);
        acc[3 + j] = v4_set(-FLT_MAX);
    }
    n = _mm_setzero_si128();
    const __m128i izero = _mm_setzero_si128();
    __m128i axes = _mm_castps_si128(_mm_cmpneq_ps(v4_set3(sc[0], sc[1], sc[2]), zero)), bin = izero;
    v4 cost_best = v4_set(FLT_MAX);
    for (int k = 0; k < nb - 1; k++) {
        for (int j = 0; j < 3; j++) {
            acc[j] = _mm_min_ps(acc[j], box[k][j]);
            acc[3 + j] = _mm_max_ps(acc[3 + j], box[k][3 + j]);
        }
        n = _mm_add_epi32(n, cnt[k]);
        v4 cost = _mm_add_ps(_mm_mul_ps(area3(acc), BLOCKS4(n)),
                             _mm_mul_ps(right_area[k + 1], BLOCKS4(right_count[k + 1])));
        __m128i empty = _mm_or_si128(_mm_cmpeq_epi32(n, izero), _mm_cmpeq_epi32(right_count[k + 1], izero));
        __m128i better = _mm_andnot_si128(empty, _mm_and_si128(axes, _mm_castps_si128(_mm_cmplt_ps(cost, cost_best))));
        cost_best = _mm_or_ps(_mm_and_ps(_mm_castsi128_ps(better), cost),
                              _mm_andnot_ps(_mm_castsi128_ps(better), cost_best));
        bin = _mm_or_si128(_mm_and_si128(better, _mm_set1_epi32(k)), _mm_andnot_si128(better, bin));
    }
#undef BLOCKS4
    float c[4];
    int kb[4];
    v4_store(c, cost_best);
    _mm_storeu_si128((__m128i *)(void *)kb, bin);
    for (int a = 0; a < 3; a++)
        if (c[a] < *best_cost) {
            *best_cost = c[a];
            *best_axis = a;
            *best_bin = kb[a];
        }
#else
    for (int a = 0; a < 3; a++) {
        if (sc[a] == 0)
            continue;
        float right_area[BINS];
        uint32_t right_count[BINS];
        bbox acc;
        bbox_empty(&acc);
        uint32_t n = 0;
        for (int k = nb - 1; k > 0; k--) {
            bbox_grow(&acc, s->box[a][k].lo, s->box[a][k].hi);
            n += s->count[a][k];
            right_area[k] = bbox_area(&acc);
            right_count[k] = n;
        }
        bbox_empty(&acc);
        n = 0;
        for (int k = 0; k < nb - 1; k++) {
            bbox_grow(&acc, s->box[a][k].lo, s->box[a][k].hi);
            n += s->count[a][k];
            if (n == 0 || right_count[k + 1] == 0)
                continue;
            float cost = bbox_area(&acc) * (float)BLOCKS(n)
                         + right_area[k + 1] * (float)BLOCKS(right_count[k + 1]);
            if (cost < *best_cost) {
                *best_cost = cost;
                *best_axis = a;
                *best_bin = k;
            }
        }
    }
#endif
}

/* Bounds of both sides of a partition, grown without branches (in SSE2
 * kept in registers and chosen with masks). */
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
#if defined(__SSE2__)
    /* minps and maxps return their second operand when either is NaN: a
     * value or-ed with an all-ones mask is NaN and leaves that side's
     * bounds as they are. */
    __m128i ones = _mm_set1_epi32(-1), r = _mm_set1_epi32(-right);
    v4 not_left = _mm_castsi128_ps(r), not_right = _mm_castsi128_ps(_mm_xor_si128(r, ones));
    v4 llo = _mm_or_ps(lo, not_left), rlo = _mm_or_ps(lo, not_right);
    v4 lhi = _mm_or_ps(hi, not_left), rhi = _mm_or_ps(hi, not_right);
    s->llo = _mm_min_ps(llo, s->llo);
    s->lhi = _mm_max_ps(lhi, s->lhi);
    s->rlo = _mm_min_ps(rlo, s->rlo);
    s->rhi = _mm_max_ps(rhi, s->rhi);
#else
    if (right) {
        s->rlo = v4_min(s->rlo, lo);
        s->rhi = v4_max(s->rhi, hi);
    } else {
        s->llo = v4_min(s->llo, lo);
        s->lhi = v4_max(s->lhi, hi);
    }
#endif
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
                               v4 origin, v4 scale, v4 last, int best_axis, int best_bin,
                               split *out, int geometry)
{
    size_t l = begin, r = end - 1;
    sides cs, gs;
    sides_init(&cs);
    sides_init(&gs);
#if defined(__SSE2__)
    /* The bin on the axis is past best_bin exactly when the scaled
     * coordinate is at least best_bin + 1 (NaN in the other lanes: never). */
    float th[3] = {NAN, NAN, NAN};
    th[best_axis] = (float)(best_bin + 1);
    v4 threshold = _mm_setr_ps(th[0], th[1], th[2], NAN);
    (void)last;
#endif
    for (size_t i = begin; i < end; i++) {
        v4 lo = v4_load3(src[i].lo), hi = v4_load3(src[i].hi), c = v4_add(lo, hi);
#if defined(__SSE2__)
        int right = _mm_movemask_ps(_mm_cmpge_ps(v4_mul(v4_sub(c, origin), scale), threshold)) != 0;
#else
        int k[4];
        bin_of(c, origin, scale, last, k);
        int right = k[best_axis] > best_bin;
#endif
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
    bbox (*bins)[BINS] = set[0].box;
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
        out->mid = partition(src, dst, begin, end, origin, scale, last, best_axis, best_bin, out, 1);
        return 1;
    }
    bbox_empty(&out->left);
    bbox_empty(&out->right);
    for (int k = 0; k < nb; k++) {
        bbox *side = k <= best_bin ? &out->left : &out->right;
        bbox_grow(side, bins[best_axis][k].lo, bins[best_axis][k].hi);
    }
    out->mid = partition(src, dst, begin, end, origin, scale, last, best_axis, best_bin, out, 0);
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
static void build_node(builder *b, uint32_t index, size_t begin, size_t end, bbox bounds,
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
    build_node(&j->b, root, j->begin, j->end, j->bounds, j->centroids, 2, 1);
    return NULL;
}

/* The binary tree of the references in b->buf[0][0, n) into b->nodes (room
 * for 2 n - 1), the triangle of each leaf position into b->ids; with
 * threads > 1 the root's two subtrees are built at the same time.  The tree
 * is the same either way. */
static int build_tree(builder *out, size_t n, int threads)
{
    bbox bounds, centroids;
    range_bounds(out->buf[0], 0, n, &bounds, &centroids);
    builder b = *out;
    uint32_t root = make_node(&b, &bounds);
    split sp;
    if (threads < 2 || n < PARALLEL_MIN
        || !choose_split(b.buf[0], b.buf[1], 0, n, &bounds, &centroids, 1, &sp)) {
        build_node(&b, root, 0, n, bounds, centroids, 1, 0);
        *out = b;
        return 1;
    }
    size_t right_count = n - sp.mid;
    subtree_job job;
    job.b = b;
    job.b.nodes = malloc((2 * right_count) * sizeof *job.b.nodes);
    job.b.node_count = 0;
    job.begin = sp.mid;
    job.end = n;
    job.bounds = sp.right;
    job.centroids = sp.right_centroids;
    pthread_t id;
    int parallel = job.b.nodes && pthread_create(&id, NULL, build_subtree, &job) == 0;
    uint32_t left = make_node(&b, &sp.left);
    build_node(&b, left, 0, sp.mid, sp.left, sp.left_centroids, 2, 1);
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
    b.nodes[root].offset = shift;
    for (size_t i = 0; i < job.b.node_count; i++) {
        bvh_node node = job.b.nodes[i];
        if (!node.count)
            node.offset += shift;
        b.nodes[shift + i] = node;
    }
    b.node_count += job.b.node_count;
    free(job.b.nodes);
    *out = b;
    return 1;
}

/* ---- the 4-wide tree ------------------------------------------------------ */

/* Collapsing the binary tree: each 4-wide node takes a binary inner node's
 * two children and keeps opening the inner child of largest area in their
 * place until it has four (or only leaves).  Leaves' triangles go to blocks
 * of four, in leaf order. */
typedef struct collapser {
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
} collapser;

static float node_area(const bvh_node *n)
{
    bbox b;
    b.lo = v4_load3(n->lo);
    b.hi = v4_load3(n->hi);
    return bbox_area(&b);
}

/* A leaf's blocks: triangle indices, NaN in unused lanes, and for each
 * triangle its place (block * 4 + lane) in c->where; the corners are filled
 * afterwards, in triangle order (fill_corners). */
static uint32_t emit_leaf(collapser *c, const bvh_node *leaf)
{
    uint32_t first = (uint32_t)c->block_count, count = leaf->count;
    for (uint32_t k = 0; k < count; k += 4) {
        size_t block = c->block_count++;
        bvh_tri4 *b = &c->blocks[block];
        for (uint32_t l = 0; l < 4; l++) {
            if (k + l >= count) {
                for (int j = 0; j < 3; j++)
                    for (int a = 0; a < 3; a++)
                        b->v[j][a][l] = NAN;
                b->id[l] = UINT32_MAX;
                continue;
            }
            uint32_t id = c->ids[leaf->offset + k + l];
            c->where[id] = (uint32_t)(4 * block + l);
            b->id[l] = id;
        }
    }
    return BVH_LEAF | first << 3 | (count - 1);
}

/* The corners of every stored triangle into its lane, reading the triangles
 * in order (the writes scatter, the reads do not wait on each other). */
static void fill_corners(const collapser *c, size_t triangle_count)
{
    for (size_t i = 0; i < triangle_count; i++) {
        uint32_t w = c->where[i];
        if (w == UINT32_MAX)
            continue;
        bvh_tri4 *b = &c->blocks[w / 4];
        uint32_t l = w % 4;
        for (int j = 0; j < 3; j++) {
            cg_vec3 p = c->positions[c->indices ? c->indices[3 * i + j] : 3 * i + j];
            b->v[j][0][l] = (float)p.x;
            b->v[j][1][l] = (float)p.y;
            b->v[j][2][l] = (float)p.z;
        }
    }
}

static uint32_t collapse(collapser *c, uint32_t index, int depth)
{
    const bvh_node *bin = c->bin;
    uint32_t kids[4] = {index + 1, bin[index].offset, 0, 0};
    int n = 2;
    while (n < 4) {
        int best = -1;
        float best_area = -1;
        for (int k = 0; k < n; k++) {
            float area = bin[kids[k]].count ? -1 : node_area(&bin[kids[k]]);
            if (area > best_area) {
                best = k;
                best_area = area;
            }
        }
        if (best < 0)
            break;
        uint32_t open = kids[best];
        kids[best] = open + 1;
        kids[n++] = bin[open].offset;
    }
    uint32_t me = (uint32_t)c->node_count++;
    if (depth > c->depth)
        c->depth = depth;
    bvh4_node *node = &c->nodes[me];
    memset(node, 0, sizeof *node);
    for (int k = 0; k < 4; k++)
        for (int a = 0; a < 3; a++) {
            node->box[2 * a][k] = k < n ? bin[kids[k]].lo[a] : INFINITY;
            node->box[2 * a + 1][k] = k < n ? bin[kids[k]].hi[a] : -INFINITY;
        }
    for (int k = 0; k < 4; k++) {
        uint32_t ref = BVH_NONE;
        if (k < n)
            ref = bin[kids[k]].count ? emit_leaf(c, &bin[kids[k]]) : collapse(c, kids[k], depth + 1);
        c->nodes[me].child[k] = ref;
    }
    return me;
}

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
    /* Finite triangles only; coordinates rounded to float once, here. */
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
        if (!v4_zero3(nan))
            continue;
        prim_ref *r = &refs[n++];
        v4_store(r->lo, lo);
        v4_store(r->hi, hi);
        uint32_t id = (uint32_t)i;
        memcpy(&r->lo[3], &id, sizeof id);
    }
    bvh->triangle_count = n;
    if (n == 0) {
        free(refs);
        *out = bvh;
        return CG_OK;
    }
    if (!joined)
        second = alloc_block(n, sizeof *refs, 0);
    builder b = {{refs, second}, alloc_block(n, sizeof(uint32_t), 0),
                 alloc_block(2 * n - 1, sizeof(bvh_node), 0), 0};
    collapser c = {b.nodes, b.ids, positions, indices, NULL, NULL, 0, NULL, 0, 1};
    cg_status status = CG_ENOMEM;
    if (!b.buf[1] || !b.ids || !b.nodes || !build_tree(&b, n, threads))
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
    bvh->root = b.nodes[0].count ? emit_leaf(&c, &b.nodes[0]) : collapse(&c, 0, 1);
    fill_corners(&c, triangle_count);
    if (reuse) {
        /* Give back the rest of the block if it stays where it is (aligned
         * as the blocks need). */
        bvh_tri4 *shrunk = realloc(c.blocks, c.block_count * sizeof *c.blocks);
        if (shrunk && (uintptr_t)(void *)shrunk % 128 != 0) {
            /* Moved and no longer aligned: copied once more. */
            c.blocks = alloc_block(c.block_count, sizeof *c.blocks, 1);
            if (c.blocks)
                memcpy(c.blocks, shrunk, c.block_count * sizeof *c.blocks);
            free(shrunk);
            if (!c.blocks)
                goto fail;
        } else if (shrunk) {
            c.blocks = shrunk;
        }
    }
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
    double area = node_area(box);
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
        double area = node_area(&bvh->bounds);
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
        /* x - x is 0 exactly for finite x (and the origin must stay finite
         * in float). */
        float fo = (float)o[a];
        if (!(fo - fo == 0) || !(d[a] - d[a] == 0))
            return 0;
        if (fabs(d[a]) > fabs(d[kz]))
            kz = a;
    }
    if (d[kz] == 0 || !(t_min - t_min == 0))
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

/* Lane k of a block as a triangle for the scalar test. */
static void block_triangle(const bvh_tri4 *b, int k, bvh_triangle *tri)
{
    for (int a = 0; a < 3; a++) {
        tri->v0[a] = b->v[0][a][k];
        tri->v1[a] = b->v[1][a][k];
        tri->v2[a] = b->v[2][a][k];
    }
    tri->id = b->id[k];
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

/* The ray as the 4-wide tests read it: origin, inverse direction and the
 * watertight test's permuted origin and shear, each in all four lanes, and
 * the rows of a node's boxes that hold each axis' near and far planes. */
typedef struct ray4 {
    v4 ox, oy, oz, ix, iy, iz, t_min;
    v4 okx, oky, okz, sx, sy, sz;
    int near[3]; /* the far plane's row is near ^ 1 */
} ray4;

static void ray4_setup(ray4 *r, const bvh_ray *ray)
{
    r->ox = v4_set(ray->origin[0]);
    r->oy = v4_set(ray->origin[1]);
    r->oz = v4_set(ray->origin[2]);
    r->ix = v4_set(ray->inverse[0]);
    r->iy = v4_set(ray->inverse[1]);
    r->iz = v4_set(ray->inverse[2]);
    r->t_min = v4_set(ray->t_min);
    r->okx = v4_set(ray->origin[ray->kx]);
    r->oky = v4_set(ray->origin[ray->ky]);
    r->okz = v4_set(ray->origin[ray->kz]);
    r->sx = v4_set(ray->shear_x);
    r->sy = v4_set(ray->shear_y);
    r->sz = v4_set(ray->shear_z);
    /* With a positive inverse the lower plane is met first: then
     * (lo - o) / d <= (hi - o) / d, the min and max of the scalar test. */
    for (int a = 0; a < 3; a++) {
        r->near[a] = ray->inverse[a] >= 0 ? 2 * a : 2 * a + 1;
    }
}

/* A node's four boxes against the ray: bit k of the result says child k is
 * entered, t_near[k] where.  Lane by lane the very operations of hit_box, so
 * each decision is the one hit_box would make; an empty slot's box gives
 * t_near +inf and t_far -inf and is never entered. */
static inline int hit_node4(const bvh_ray *ray, const ray4 *r, const bvh4_node *node,
                            v4 limit4, float t_far_limit, float t_near[4])
{
    if (ray->flat_axes) {
        int mask = 0;
        for (int k = 0; k < 4; k++) {
            bvh_node box;
            for (int a = 0; a < 3; a++) {
                box.lo[a] = node->box[2 * a][k];
                box.hi[a] = node->box[2 * a + 1][k];
            }
            mask |= hit_box_flat(ray, &box, t_far_limit, &t_near[k]) << k;
        }
        return mask;
    }
    const int x = r->near[0], y = r->near[1], z = r->near[2];
    v4 nx = v4_mul(v4_sub(v4_load(node->box[x]), r->ox), r->ix);
    v4 ny = v4_mul(v4_sub(v4_load(node->box[y]), r->oy), r->iy);
    v4 nz = v4_mul(v4_sub(v4_load(node->box[z]), r->oz), r->iz);
    v4 fx = v4_mul(v4_sub(v4_load(node->box[x ^ 1]), r->ox), r->ix);
    v4 fy = v4_mul(v4_sub(v4_load(node->box[y ^ 1]), r->oy), r->iy);
    v4 fz = v4_mul(v4_sub(v4_load(node->box[z ^ 1]), r->oz), r->iz);
    v4 tn = v4_max(v4_max(nx, ny), v4_max(nz, r->t_min));
    /* As hit_box, without its clamp of t_far to FLT_MAX: the limit
     * clamps it anyway. */
    v4 tf = v4_min(v4_min(fx, fy), fz);
    tf = v4_min(v4_mul(tf, v4_set(1.0000003576f)), limit4);
    v4_store(t_near, tn);
#if defined(__SSE2__)
    return _mm_movemask_ps(_mm_cmple_ps(tn, tf));
#else
    int mask = 0;
    for (int k = 0; k < 4; k++)
        mask |= (tn.f[k] <= tf.f[k]) << k;
    return mask;
#endif
}

/* The watertight test on a block of four triangles: bit k of the result
 * says triangle k is hit, with t[k], u[k], v[k].  Lane by lane the very
 * operations of hit_triangle (the same rounding, the same double-precision
 * retry of edge functions that come out zero), so its answers are
 * hit_triangle's; NaN lanes are never hit. */
static inline int hit_tri4(const bvh_ray *ray, const ray4 *r, const bvh_tri4 *b, float t[4],
                           float u[4], float v[4])
{
#if defined(__SSE2__)
    const int kx = ray->kx, ky = ray->ky, kz = ray->kz;
    const v4 ax = v4_sub(v4_load(b->v[0][kx]), r->okx), ay = v4_sub(v4_load(b->v[0][ky]), r->oky),
             az = v4_sub(v4_load(b->v[0][kz]), r->okz);
    const v4 bx = v4_sub(v4_load(b->v[1][kx]), r->okx), by = v4_sub(v4_load(b->v[1][ky]), r->oky),
             bz = v4_sub(v4_load(b->v[1][kz]), r->okz);
    const v4 cx = v4_sub(v4_load(b->v[2][kx]), r->okx), cy = v4_sub(v4_load(b->v[2][ky]), r->oky),
             cz = v4_sub(v4_load(b->v[2][kz]), r->okz);
    const v4 Ax = v4_sub(ax, v4_mul(r->sx, az)), Ay = v4_sub(ay, v4_mul(r->sy, az));
    const v4 Bx = v4_sub(bx, v4_mul(r->sx, bz)), By = v4_sub(by, v4_mul(r->sy, bz));
    const v4 Cx = v4_sub(cx, v4_mul(r->sx, cz)), Cy = v4_sub(cy, v4_mul(r->sy, cz));
    v4 U = v4_sub(v4_mul(Cx, By), v4_mul(Cy, Bx));
    v4 V = v4_sub(v4_mul(Ax, Cy), v4_mul(Ay, Cx));
    v4 W = v4_sub(v4_mul(Bx, Ay), v4_mul(By, Ax));
    const v4 zero = _mm_setzero_ps();
    int flat = _mm_movemask_ps(
        _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(U, zero), _mm_cmpeq_ps(V, zero)), _mm_cmpeq_ps(W, zero)));
    if (flat) {
        float fu[4], fv[4], fw[4], pax[4], pay[4], pbx[4], pby[4], pcx[4], pcy[4];
        v4_store(fu, U);
        v4_store(fv, V);
        v4_store(fw, W);
        v4_store(pax, Ax);
        v4_store(pay, Ay);
        v4_store(pbx, Bx);
        v4_store(pby, By);
        v4_store(pcx, Cx);
        v4_store(pcy, Cy);
        for (int k = 0; k < 4; k++)
            if (flat & (1 << k)) {
                fu[k] = (float)((double)pcx[k] * pby[k] - (double)pcy[k] * pbx[k]);
                fv[k] = (float)((double)pax[k] * pcy[k] - (double)pay[k] * pcx[k]);
                fw[k] = (float)((double)pbx[k] * pay[k] - (double)pby[k] * pax[k]);
            }
        U = v4_load(fu);
        V = v4_load(fv);
        W = v4_load(fw);
    }
    v4 neg = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(U, zero), _mm_cmplt_ps(V, zero)), _mm_cmplt_ps(W, zero));
    v4 pos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(U, zero), _mm_cmpgt_ps(V, zero)), _mm_cmpgt_ps(W, zero));
    int mask = ~_mm_movemask_ps(_mm_and_ps(neg, pos)) & 15;
    if (!mask)
        return 0;
    v4 det = v4_add(v4_add(U, V), W);
    v4 T = v4_add(v4_add(v4_mul(U, v4_mul(r->sz, az)), v4_mul(V, v4_mul(r->sz, bz))),
                  v4_mul(W, v4_mul(r->sz, cz)));
    v4 inv = _mm_div_ps(_mm_set1_ps(1.0f), det);
    v4 tt = v4_mul(T, inv);
    mask &= _mm_movemask_ps(_mm_and_ps(_mm_cmpneq_ps(det, zero), _mm_cmpgt_ps(tt, r->t_min)));
    if (mask) {
        v4_store(t, tt);
        v4_store(u, v4_mul(V, inv));
        v4_store(v, v4_mul(W, inv));
    }
    return mask;
#else
    (void)r;
    int mask = 0;
    for (int k = 0; k < 4; k++) {
        bvh_triangle tri;
        block_triangle(b, k, &tri);
        mask |= hit_triangle(ray, &tri, &t[k], &u[k], &v[k]) << k;
    }
    return mask;
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

/* The lowest set bit of a 4-bit mask. */
static const signed char lowest_lane[16] = {-1, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};

/* Traversal of the 4-wide tree.  Nearest hit (any_hit 0): children entered
 * nearest first, and the best (t, index) with t in (t_min, t_max].  Shadow
 * query (any_hit 1): children in slot order, stopping at the first t in
 * (t_min, t_max).  The ray comes with its slab data (ray_setup_slabs). */
#if defined(__GNUC__)
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ALWAYS_INLINE inline
#endif

/* Inlined in each query, so each gets its own loop with any_hit constant. */
static ALWAYS_INLINE int traverse(const cg_bvh *bvh, bvh_ray *ray, float t_max, int any_hit,
                                  cg_bvh_hit *hit)
{
    float best_t = t_max, limit = cull_limit(best_t);
    {
        v4 o = v4_set3(ray->origin[0], ray->origin[1], ray->origin[2]);
        v4 i = v4_set3(ray->inverse[0], ray->inverse[1], ray->inverse[2]);
        float tn;
        if (!hit_box(ray, o, i, &bvh->bounds, limit, &tn))
            return 0;
    }
    ray_setup_shear(ray);
    ray4 r;
    ray4_setup(&r, ray);
    v4 limit4 = v4_set(limit);
    uint32_t best_id = UINT32_MAX;
    float best_u = 0, best_v = 0;
    int found = 0;
    uint32_t stack[STACK_SIZE];
    float stack_t[STACK_SIZE];
    int top = 0;
    uint32_t ref = bvh->root;
    for (;;) {
        if (!(ref & BVH_LEAF)) {
            const bvh4_node *node = &bvh->nodes[ref];
            float tn[4];
            int mask = hit_node4(ray, &r, node, limit4, limit, tn);
            if (mask) {
                int k = lowest_lane[mask];
                mask &= mask - 1;
                if (!mask) {
                    ref = node->child[k];
                    continue;
                }
                if (any_hit) {
                    /* A shadow ray's limit never shrinks, so what it
                     * pushes stays worth visiting: no order, no distance. */
                    do {
                        stack[top++] = node->child[lowest_lane[mask]];
                        mask &= mask - 1;
                    } while (mask);
                    ref = node->child[k];
                    continue;
                }
                /* Two to four children: sorted by entry distance (slot
                 * order on ties), the farthest pushed first. */
                uint32_t c[4];
                float d[4];
                int n = 1;
                c[0] = node->child[k];
                d[0] = tn[k];
                do {
                    int j = lowest_lane[mask];
                    mask &= mask - 1;
                    int i = n++;
                    while (i > 0 && d[i - 1] > tn[j]) {
                        c[i] = c[i - 1];
                        d[i] = d[i - 1];
                        i--;
                    }
                    c[i] = node->child[j];
                    d[i] = tn[j];
                } while (mask);
                for (int i = n - 1; i > 0; i--) {
                    stack[top] = c[i];
                    stack_t[top] = d[i];
                    top++;
                }
                ref = c[0];
                continue;
            }
        } else {
            const bvh_tri4 *b = bvh->blocks + ((ref & ~BVH_LEAF) >> 3);
            int count = (int)(ref & 7) + 1;
            for (int k = 0; k < count; k += 4, b++) {
                float t[4], u[4], v[4];
                int mask = hit_tri4(ray, &r, b, t, u, v);
                while (mask) {
                    int j = lowest_lane[mask];
                    mask &= mask - 1;
                    if (any_hit) {
                        if (t[j] < t_max)
                            return 1;
                    } else if (better(t[j], b->id[j], best_t, best_id)) {
                        best_t = t[j];
                        best_id = b->id[j];
                        best_u = u[j];
                        best_v = v[j];
                        found = 1;
                        limit = cull_limit(best_t);
                        limit4 = v4_set(limit);
                    }
                }
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
        ref = stack[top];
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
    if (!bvh || bvh->root == BVH_NONE || !ray_setup_slabs(&ray, origin, direction, t_min)
        || !(t_max > t_min))
        return 0;
    return traverse(bvh, &ray, clamp_far(t_max), 0, hit);
}

int cg_bvh_occluded(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                    double t_max)
{
    bvh_ray ray;
    if (!bvh || bvh->root == BVH_NONE || !ray_setup_slabs(&ray, origin, direction, t_min)
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
    /* Every stored triangle through the scalar test, one at a time. */
    for (size_t i = 0; i < 4 * bvh->block_count; i++) {
        const bvh_tri4 *b = &bvh->blocks[i / 4];
        size_t k = i % 4;
        if (b->id[k] == UINT32_MAX)
            continue;
        bvh_triangle tri;
        block_triangle(b, (int)k, &tri);
        float t, u, v;
        if (hit_triangle(&ray, &tri, &t, &u, &v) && better(t, tri.id, best_t, best_id)) {
            best_t = t;
            best_id = tri.id;
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
