/* Private to libcg: four-lane vectors, SSE2 where available, plain C
 * elsewhere, the one place cg's code names SIMD instructions.  v4 holds four
 * floats (the BVH build and traversal, the Gouraud runs, the sRGB encode),
 * i4 four 32-bit integers (the SAH sweep's counts, 16-byte pixel and depth
 * stores of the fills and tile clears, the flood fill's four-pixel test).
 * The plain C versions give, lane by lane, exactly what the instructions
 * give (min and max return their second operand when either is NaN,
 * comparisons are false with NaN, masks are all-ones or all-zero bit
 * patterns, stores write the same bytes), so code written once on these
 * gives the same results either way. */
#ifndef CG_CORE_SIMD4_H
#define CG_CORE_SIMD4_H

#include "cg/core.h"

#include <stdint.h>
#include <string.h>

#if defined(__SSE2__)
#include <emmintrin.h>

typedef __m128 v4;

static inline v4 v4_load(const float *p)
{
    return _mm_loadu_ps(p);
}
static inline void v4_store(float *p, v4 a)
{
    _mm_storeu_ps(p, a);
}
static inline v4 v4_set(float x)
{
    return _mm_set1_ps(x);
}
/* (x, y, z, w) and (x, y, z, 0) from scalars, in registers. */
static inline v4 v4_set4(float x, float y, float z, float w)
{
    return _mm_setr_ps(x, y, z, w);
}
static inline v4 v4_set3(float x, float y, float z)
{
    return _mm_setr_ps(x, y, z, 0);
}
/* Lanes 0..2 of p, lane 3 zero: the fourth float of a node or reference
 * holds integer bits, which as a float may be a denormal that slows
 * arithmetic, so it is masked off before any. */
static inline v4 v4_load3(const float *p)
{
    const __m128i mask = _mm_set_epi32(0, -1, -1, -1);
    return _mm_and_ps(_mm_loadu_ps(p), _mm_castsi128_ps(mask));
}
/* A point's coordinates rounded to float in lanes 0..2, lane 3 zero (built
 * in registers: a vector load of three scalar stores would stall). */
static inline v4 v4_point(const cg_vec3 *p)
{
    __m128 xy = _mm_cvtpd_ps(_mm_loadu_pd(&p->x)),
           z = _mm_cvtsd_ss(_mm_setzero_ps(), _mm_load_sd(&p->z));
    return _mm_movelh_ps(xy, z);
}

static inline v4 v4_add(v4 a, v4 b)
{
    return _mm_add_ps(a, b);
}
static inline v4 v4_sub(v4 a, v4 b)
{
    return _mm_sub_ps(a, b);
}
static inline v4 v4_mul(v4 a, v4 b)
{
    return _mm_mul_ps(a, b);
}
static inline v4 v4_div(v4 a, v4 b)
{
    return _mm_div_ps(a, b);
}
/* a < b ? a : b and a > b ? a : b per lane, as the instructions define. */
static inline v4 v4_min(v4 a, v4 b)
{
    return _mm_min_ps(a, b);
}
static inline v4 v4_max(v4 a, v4 b)
{
    return _mm_max_ps(a, b);
}

/* Comparisons: all-ones lanes where true. */
static inline v4 v4_lt(v4 a, v4 b)
{
    return _mm_cmplt_ps(a, b);
}
static inline v4 v4_le(v4 a, v4 b)
{
    return _mm_cmple_ps(a, b);
}
static inline v4 v4_gt(v4 a, v4 b)
{
    return _mm_cmpgt_ps(a, b);
}
static inline v4 v4_ge(v4 a, v4 b)
{
    return _mm_cmpge_ps(a, b);
}
static inline v4 v4_eq(v4 a, v4 b)
{
    return _mm_cmpeq_ps(a, b);
}
static inline v4 v4_neq(v4 a, v4 b)
{
    return _mm_cmpneq_ps(a, b);
}
/* Bitwise: a | b, a & b, and ~mask & a. */
static inline v4 v4_or(v4 a, v4 b)
{
    return _mm_or_ps(a, b);
}
static inline v4 v4_and(v4 a, v4 b)
{
    return _mm_and_ps(a, b);
}
static inline v4 v4_andnot(v4 mask, v4 a)
{
    return _mm_andnot_ps(mask, a);
}
/* All lanes all-ones when flag is 1, all zero when it is 0. */
static inline v4 v4_mask_if(int flag)
{
    return _mm_castsi128_ps(_mm_set1_epi32(-flag));
}
/* ~mask. */
static inline v4 v4_not(v4 mask)
{
    return _mm_castsi128_ps(_mm_xor_si128(_mm_castps_si128(mask), _mm_set1_epi32(-1)));
}
/* Bit k: the sign bit of lane k (of a mask: lane k true). */
static inline int v4_bits(v4 mask)
{
    return _mm_movemask_ps(mask);
}

/* Lanes 0..2 truncated to integers. */
static inline void v4_to_int(v4 a, int *out)
{
    _mm_storeu_si128((__m128i *)(void *)out, _mm_cvttps_epi32(a));
}
/* Lane 3 (the w of (x, y, z, w)). */
static inline float v4_lane3(v4 a)
{
    return _mm_cvtss_f32(_mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 3, 3, 3)));
}
/* Stores to 16-byte aligned p past the caches (for outputs larger than
 * they are); v4_stream_fence() orders them before later stores. */
static inline void v4_stream(float *p, v4 a)
{
    _mm_stream_ps(p, a);
}
static inline void v4_stream_fence(void)
{
    _mm_sfence();
}
/* (y, z, x, w): each of lanes 0..2 next to the following one. */
static inline v4 v4_yzx(v4 a)
{
    return _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 0, 2, 1));
}
/* (lane 0 + lane 1) + lane 2. */
static inline float v4_sum3(v4 a)
{
    v4 s = _mm_add_ss(a, _mm_shuffle_ps(a, a, _MM_SHUFFLE(1, 1, 1, 1)));
    return _mm_cvtss_f32(_mm_add_ss(s, _mm_movehl_ps(a, a)));
}
/* max(lanes 0..2 of a, x) and min(lanes 0..2 of a, x). */
static inline float v4_max3(v4 a, float x)
{
    v4 b = _mm_shuffle_ps(a, a, _MM_SHUFFLE(1, 1, 1, 1)),
       c = _mm_shuffle_ps(a, a, _MM_SHUFFLE(2, 2, 2, 2));
    return _mm_cvtss_f32(_mm_max_ss(_mm_max_ss(a, b), _mm_max_ss(c, _mm_set_ss(x))));
}
static inline float v4_min3(v4 a, float x)
{
    v4 b = _mm_shuffle_ps(a, a, _MM_SHUFFLE(1, 1, 1, 1)),
       c = _mm_shuffle_ps(a, a, _MM_SHUFFLE(2, 2, 2, 2));
    return _mm_cvtss_f32(_mm_min_ss(_mm_min_ss(a, b), _mm_min_ss(c, _mm_set_ss(x))));
}
/* Rows r[0..3] become the columns. */
static inline void v4_transpose(v4 r[4])
{
    _MM_TRANSPOSE4_PS(r[0], r[1], r[2], r[3]);
}


/* Four 32-bit integers (the SAH sweep's triangle counts and bin numbers). */
typedef __m128i i4;

static inline i4 i4_set(int x)
{
    return _mm_set1_epi32(x);
}
/* (x, y, z, 0). */
static inline i4 i4_set3(int x, int y, int z)
{
    return _mm_set_epi32(0, z, y, x);
}
static inline i4 i4_add(i4 a, i4 b)
{
    return _mm_add_epi32(a, b);
}
/* 16 bytes at p (any alignment), as four 32-bit lanes. */
static inline i4 i4_load(const void *p)
{
    return _mm_loadu_si128((const __m128i *)p);
}
static inline void i4_store(void *p, i4 a)
{
    _mm_storeu_si128((__m128i *)p, a);
}
/* The same to 16-byte aligned p past the caches (see v4_stream). */
static inline void i4_stream(void *p, i4 a)
{
    _mm_stream_si128((__m128i *)p, a);
}
/* The bits of a's four floats as integer lanes. */
static inline i4 i4_from_v4_bits(v4 a)
{
    return _mm_castps_si128(a);
}
/* Lanes 0..3 of a truncated to integers (a's lanes within int's range). */
static inline i4 i4_truncate(v4 a)
{
    return _mm_cvttps_epi32(a);
}
/* Lane k (0..3, a constant) of a. */
static inline int i4_lane(i4 a, int k)
{
    switch (k) {
    case 0: return _mm_cvtsi128_si32(a);
    case 1: return _mm_cvtsi128_si32(_mm_shuffle_epi32(a, 0x55));
    case 2: return _mm_cvtsi128_si32(_mm_shuffle_epi32(a, 0xaa));
    default: return _mm_cvtsi128_si32(_mm_shuffle_epi32(a, 0xff));
    }
}
/* Whether the four lanes of a and b are all equal. */
static inline int i4_all_equal(i4 a, i4 b)
{
    return _mm_movemask_epi8(_mm_cmpeq_epi32(a, b)) == 0xFFFF;
}
/* All-ones lanes where a lane is 0. */
static inline v4 i4_is_zero(i4 a)
{
    return _mm_castsi128_ps(_mm_cmpeq_epi32(a, _mm_setzero_si128()));
}
/* mask ? a : b, lane by lane. */
static inline i4 i4_select(v4 mask, i4 a, i4 b)
{
    __m128i m = _mm_castps_si128(mask);
    return _mm_or_si128(_mm_and_si128(m, a), _mm_andnot_si128(m, b));
}
/* (n + 3) / 4 of each lane (n >= 0), as a float. */
static inline v4 i4_quarter_up(i4 n)
{
    return _mm_cvtepi32_ps(_mm_srli_epi32(_mm_add_epi32(n, _mm_set1_epi32(3)), 2));
}

#else

typedef struct v4 {
    float f[4];
} v4;

static inline v4 v4_load(const float *p)
{
    v4 r;
    memcpy(r.f, p, sizeof r.f);
    return r;
}
static inline void v4_store(float *p, v4 a)
{
    memcpy(p, a.f, sizeof a.f);
}
static inline v4 v4_set4(float x, float y, float z, float w)
{
    v4 r = {{x, y, z, w}};
    return r;
}
static inline v4 v4_set(float x)
{
    return v4_set4(x, x, x, x);
}
static inline v4 v4_set3(float x, float y, float z)
{
    return v4_set4(x, y, z, 0);
}
static inline v4 v4_load3(const float *p)
{
    return v4_set3(p[0], p[1], p[2]);
}
static inline v4 v4_point(const cg_vec3 *p)
{
    return v4_set3((float)p->x, (float)p->y, (float)p->z);
}

/* A lane's bits as an integer and back, for the masks and bitwise
 * operations. */
static inline uint32_t v4_lane_bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}
static inline float v4_bits_lane(uint32_t u)
{
    float x;
    memcpy(&x, &u, sizeof x);
    return x;
}

#define V4_OP(name, expr)             \
    static inline v4 name(v4 a, v4 b) \
    {                                 \
        v4 r;                         \
        for (int i = 0; i < 4; i++)   \
            r.f[i] = (expr);          \
        return r;                     \
    }
#define V4_TRUE v4_bits_lane(UINT32_MAX)
V4_OP(v4_add, a.f[i] + b.f[i])
V4_OP(v4_sub, a.f[i] - b.f[i])
V4_OP(v4_mul, a.f[i] * b.f[i])
V4_OP(v4_div, a.f[i] / b.f[i])
V4_OP(v4_min, a.f[i] < b.f[i] ? a.f[i] : b.f[i])
V4_OP(v4_max, a.f[i] > b.f[i] ? a.f[i] : b.f[i])
V4_OP(v4_lt, a.f[i] < b.f[i] ? V4_TRUE : 0)
V4_OP(v4_le, a.f[i] <= b.f[i] ? V4_TRUE : 0)
V4_OP(v4_gt, a.f[i] > b.f[i] ? V4_TRUE : 0)
V4_OP(v4_ge, a.f[i] >= b.f[i] ? V4_TRUE : 0)
V4_OP(v4_eq, a.f[i] == b.f[i] ? V4_TRUE : 0)
V4_OP(v4_neq, a.f[i] != b.f[i] ? V4_TRUE : 0)
V4_OP(v4_or, v4_bits_lane(v4_lane_bits(a.f[i]) | v4_lane_bits(b.f[i])))
V4_OP(v4_and, v4_bits_lane(v4_lane_bits(a.f[i]) & v4_lane_bits(b.f[i])))
V4_OP(v4_andnot, v4_bits_lane(~v4_lane_bits(a.f[i]) & v4_lane_bits(b.f[i])))
#undef V4_TRUE
#undef V4_OP

static inline v4 v4_mask_if(int flag)
{
    return v4_set(v4_bits_lane(flag ? UINT32_MAX : 0));
}
static inline v4 v4_not(v4 mask)
{
    return v4_andnot(mask, v4_set(v4_bits_lane(UINT32_MAX)));
}
static inline int v4_bits(v4 mask)
{
    int bits = 0;
    for (int i = 0; i < 4; i++)
        bits |= (int)(v4_lane_bits(mask.f[i]) >> 31) << i;
    return bits;
}
/* Out of range and NaN give 0 (cvttps gives INT_MIN; the values binning
 * meets are clamped before). */
static inline void v4_to_int(v4 a, int *out)
{
    for (int i = 0; i < 4; i++)
        out[i] = (a.f[i] > -2e9f && a.f[i] < 2e9f) ? (int)a.f[i] : 0;
}
static inline float v4_lane3(v4 a)
{
    return a.f[3];
}
static inline void v4_stream(float *p, v4 a)
{
    memcpy(p, a.f, sizeof a.f);
}
static inline void v4_stream_fence(void) {}
static inline v4 v4_yzx(v4 a)
{
    return v4_set4(a.f[1], a.f[2], a.f[0], a.f[3]);
}
static inline float v4_sum3(v4 a)
{
    return a.f[0] + a.f[1] + a.f[2];
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
static inline void v4_transpose(v4 r[4])
{
    for (int i = 0; i < 4; i++)
        for (int j = i + 1; j < 4; j++) {
            float t = r[i].f[j];
            r[i].f[j] = r[j].f[i];
            r[j].f[i] = t;
        }
}


typedef struct i4 {
    int32_t i[4];
} i4;

static inline i4 i4_set(int x)
{
    i4 r = {{x, x, x, x}};
    return r;
}
static inline i4 i4_set3(int x, int y, int z)
{
    i4 r = {{x, y, z, 0}};
    return r;
}
static inline i4 i4_add(i4 a, i4 b)
{
    i4 r;
    for (int k = 0; k < 4; k++)
        r.i[k] = (int32_t)((uint32_t)a.i[k] + (uint32_t)b.i[k]);
    return r;
}
static inline i4 i4_load(const void *p)
{
    i4 r;
    memcpy(r.i, p, sizeof r.i);
    return r;
}
static inline void i4_store(void *p, i4 a)
{
    memcpy(p, a.i, sizeof a.i);
}
static inline void i4_stream(void *p, i4 a)
{
    memcpy(p, a.i, sizeof a.i);
}
static inline i4 i4_from_v4_bits(v4 a)
{
    i4 r;
    memcpy(r.i, a.f, sizeof r.i);
    return r;
}
static inline i4 i4_truncate(v4 a)
{
    i4 r;
    v4_to_int(a, r.i);
    return r;
}
static inline int i4_lane(i4 a, int k)
{
    return a.i[k];
}
static inline int i4_all_equal(i4 a, i4 b)
{
    return a.i[0] == b.i[0] && a.i[1] == b.i[1] && a.i[2] == b.i[2] && a.i[3] == b.i[3];
}
static inline v4 i4_is_zero(i4 a)
{
    v4 r;
    for (int k = 0; k < 4; k++)
        r.f[k] = v4_bits_lane(a.i[k] == 0 ? UINT32_MAX : 0);
    return r;
}
static inline i4 i4_select(v4 mask, i4 a, i4 b)
{
    i4 r;
    for (int k = 0; k < 4; k++)
        r.i[k] = v4_lane_bits(mask.f[k]) ? a.i[k] : b.i[k];
    return r;
}
static inline v4 i4_quarter_up(i4 n)
{
    v4 r;
    for (int k = 0; k < 4; k++)
        r.f[k] = (float)(int32_t)(((uint32_t)n.i[k] + 3) >> 2);
    return r;
}

#endif

/* mask ? a : b, lane by lane (mask lanes all-ones or all-zero). */
static inline v4 v4_select(v4 mask, v4 a, v4 b)
{
    return v4_or(v4_and(mask, a), v4_andnot(mask, b));
}

#endif
