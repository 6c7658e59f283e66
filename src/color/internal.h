/* Private pieces shared by the colour sources. */
#ifndef CG_COLOR_INTERNAL_H
#define CG_COLOR_INTERNAL_H

/* The D65 white of the sRGB matrix: its row sums, written as sums so that
 * they equal (bit for bit) the matrix applied to linear white. */
#define CG_COLOR_WHITE_X (0.4124 + 0.3576 + 0.1805)
#define CG_COLOR_WHITE_Z (0.0193 + 0.1192 + 0.9505)

/* Run-time choice of an AVX2 version of the SIMD-friendly kernels (GCC on
 * x86-64 Linux); elsewhere the plain function. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define CG_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define CG_SIMD_CLONES
#endif


#endif
