/* Private pieces shared by the colour sources. */
#ifndef CG_COLOR_INTERNAL_H
#define CG_COLOR_INTERNAL_H

/* The D65 white of the sRGB matrix: its row sums, written as sums so that
 * they equal (bit for bit) the matrix applied to linear white. */
#define CG_COLOR_WHITE_X (0.4124 + 0.3576 + 0.1805)
#define CG_COLOR_WHITE_Z (0.0193 + 0.1192 + 0.9505)

/* Run-time choice of SIMD versions of the kernels written for the
 * vectorizer: each kernel is compiled three times, plain, for AVX2 and for
 * AVX-512 (512-bit vectors), and cg_simd_level() picks one from what the CPU
 * (and the OS) supports.  GCC on x86 only; elsewhere the three are the same
 * plain function. */
#if defined(__GNUC__) && !defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
#define CG_SIMD_DISPATCH 1
#define CG_TARGET_AVX2 __attribute__((target("avx2")))
#define CG_TARGET_AVX512 \
    __attribute__((target("avx512f,avx512bw,avx512vl,avx512dq,prefer-vector-width=512")))
#else
#define CG_TARGET_AVX2
#define CG_TARGET_AVX512
#endif

/* 2: AVX-512 (F, BW, VL, DQ); 1: AVX2; 0: neither (or no dispatch). */
static inline int cg_simd_level(void)
{
#ifdef CG_SIMD_DISPATCH
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw")
        && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq"))
        return 2;
    if (__builtin_cpu_supports("avx2"))
        return 1;
#endif
    return 0;
}

/* Defines the three variants NAME, NAME_avx2 and NAME_avx512 with a macro
 * DEFINE(NAME, ATTRIBUTES, ...). */
#define CG_SIMD_VARIANTS(DEFINE, NAME, ...)          \
    DEFINE(NAME, , __VA_ARGS__)                      \
    DEFINE(NAME##_avx2, CG_TARGET_AVX2, __VA_ARGS__) \
    DEFINE(NAME##_avx512, CG_TARGET_AVX512, __VA_ARGS__)

/* The one of three variants for this CPU. */
#define CG_SIMD_PICK(base, avx2, avx512) \
    (cg_simd_level() == 2 ? (avx512) : cg_simd_level() == 1 ? (avx2) : (base))

/* ---- intensity to pixel, step by step (trace_dither.c) ------------------- */

#include "cg/trace_steps.h"

/* Where cg_dither_plane_steps sends the steps of a plane being dithered. */
typedef struct color_dither_report {
    cg_step_fn fn;
    void *user;
    int stopped; /* the callback asked to stop: no more steps */
} color_dither_report;

/* cg_dither_plane, reporting each pixel when report is not NULL. */
cg_status color_dither_plane(const float *in, float *out, int width, int height, size_t stride,
                             int levels, cg_dither method, color_dither_report *report);
/* One pixel of plain quantization to top + 1 levels, of ordered dithering
 * (Bayer index b of the n x n matrix), of Floyd-Steinberg error diffusion
 * (v: the input plus the errors it received; weights: of the right, below
 * left, below and below right neighbours, 0 where there is none). */
void color_report_quantize(color_dither_report *r, int x, int y, float input, double top,
                           float out);
void color_report_ordered(color_dither_report *r, int x, int y, float input, double scaled, int b,
                          int n, float out);
void color_report_diffusion(color_dither_report *r, int x, int y, float input, double v, float out,
                            double error, const double weights[4]);

#endif
