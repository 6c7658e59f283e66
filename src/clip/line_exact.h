/* Exact integer arithmetic for the line clippers (line_exact.c): doubles
 * scaled to integers, sums and products of them, and one quotient rounded
 * to the nearest double. */
#ifndef CG_CLIP_LINE_EXACT_H
#define CG_CLIP_LINE_EXACT_H

#include <stdint.h>

/* room for a product of two differences of scaled doubles (4,200 bits)
 * and the shifts of the rounded division */
#define LINE_INT_LIMBS 72

/* sign and magnitude, w[0..n) least significant first, n = 0 for zero */
typedef struct line_int {
    int neg, n;
    uint64_t w[LINE_INT_LIMBS];
} line_int;

/* the exponent e of the lowest set bit among v[0..n) (all finite): every
 * one of them is an integer multiple of 2^e (1024 when all are zero) */
int line_scale(const double *v, int n);
/* x = v / 2^scale, an integer when scale comes from line_scale */
void line_int_from(line_int *x, double v, int scale);
void line_int_small(line_int *x, int v);
/* *r = *x (copying only the limbs in use) */
void line_int_copy(line_int *r, const line_int *x);
/* r = a + b, or a - b when negate_b (r may be a or b) */
void line_int_add(line_int *r, const line_int *a, const line_int *b, int negate_b);
/* r = a b (r may be a or b) */
void line_int_mul(line_int *r, const line_int *a, const line_int *b);
int line_int_sign(const line_int *x);
/* num / den 2^scale rounded to the nearest double, ties to even (den != 0;
 * the result must be finite) */
double line_int_quotient(const line_int *num, const line_int *den, int scale);

/* A segment a..b (dim 2 or 3) with its coordinates and a window's bounds
 * scaled to integers (line_seg_init); a point of it by its parameter
 * t = num / den, den > 0. */
typedef struct line_seg {
    int dim, scale, small;
    double a[3], b[3];
    int64_t sa[3], sd[3]; /* a and b - a, scaled, in the small form (line_exact.c) */
    line_int ai[3], d[3]; /* the same otherwise */
} line_seg;
typedef struct line_param {
    int64_t num, den;    /* in the small form */
    line_int bnum, bden; /* otherwise */
} line_param;

/* the bounds lo, hi only set the scale (so that they are integers too) */
void line_seg_init(line_seg *s, int dim, const double *a, const double *b, const double *lo,
                   const double *hi);
/* *r = *t */
void line_param_copy(line_param *r, const line_param *t);
/* t = 0 (a), or 1 (b) when at_b */
void line_param_end(line_param *t, int at_b);
/* t where coordinate `axis` is `bound` (one of the window's bounds; b - a
 * must not be 0 on that axis) */
void line_param_bound(const line_seg *s, int axis, double bound, line_param *t);
/* the sign of t - u */
int line_param_cmp(const line_seg *s, const line_param *t, const line_param *u);
/* the sign of coordinate `axis` of the point at t minus `bound` (a window bound) */
int line_side(const line_seg *s, const line_param *t, int axis, double bound);
/* coordinate `axis` of the point at t, rounded to the nearest double */
double line_coord(const line_seg *s, const line_param *t, int axis);

#endif
