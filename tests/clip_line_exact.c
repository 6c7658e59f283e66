/* Line clipping against exact rational clipping (GMP's mpq): for any finite
 * coordinates, up to +-1.7e308 and down to the subnormals, Cohen-Sutherland
 * and Liang-Barsky in 2D and 3D accept exactly the segments that meet the
 * closed window, and give the visible part's endpoints as the exact ones
 * rounded to the nearest double (ties to even), bit for bit. */
#include "cg/clip.h"
#include "check.h"

#include <float.h>
#include <gmp.h>
#include <string.h>

/* the double nearest to q, ties to even (q within the finite doubles) */
static double nearest(const mpq_t q)
{
    double d = mpq_get_d(q), best = d;
    mpq_t c, diff, bestdiff;
    mpq_inits(c, diff, bestdiff, NULL);
    mpq_set_d(c, d);
    mpq_sub(bestdiff, q, c);
    mpq_abs(bestdiff, bestdiff);
    double cand[2] = {nextafter(d, -INFINITY), nextafter(d, INFINITY)};
    for (int i = 0; i < 2; i++) {
        if (!isfinite(cand[i]))
            continue;
        mpq_set_d(c, cand[i]);
        mpq_sub(diff, q, c);
        mpq_abs(diff, diff);
        int cmp = mpq_cmp(diff, bestdiff);
        uint64_t bits;
        memcpy(&bits, &cand[i], sizeof bits);
        if (cmp < 0 || (cmp == 0 && !(bits & 1))) {
            best = cand[i];
            mpq_set(bestdiff, diff);
        }
    }
    mpq_clears(c, diff, bestdiff, NULL);
    return best == 0 ? 0.0 : best;
}

/* The exact clip of a..b by [lo, hi] (dim axes): the parameters where the
 * segment is inside every slab, from the last entry to the first exit.
 * Returns whether it is visible; out the endpoints rounded. */
static int exact_clip(int dim, const double *a, const double *b, const double *lo, const double *hi,
                      double *out0, double *out1)
{
    mpq_t t0, t1, t, d, q;
    mpq_inits(t0, t1, t, d, q, NULL);
    mpq_set_ui(t0, 0, 1);
    mpq_set_ui(t1, 1, 1);
    int visible = 1;
    for (int j = 0; j < dim && visible; j++) {
        mpq_t aj, bj, bound;
        mpq_inits(aj, bj, bound, NULL);
        mpq_set_d(aj, a[j]);
        mpq_set_d(bj, b[j]);
        mpq_sub(d, bj, aj);
        if (mpq_sgn(d) == 0) {
            if (a[j] < lo[j] || a[j] > hi[j])
                visible = 0;
        } else {
            for (int side = 0; side < 2; side++) {
                mpq_set_d(bound, side ? hi[j] : lo[j]);
                mpq_sub(t, bound, aj);
                mpq_div(t, t, d);
                /* entering at lo when moving up, at hi when moving down */
                int entering = (side == 0) == (mpq_sgn(d) > 0);
                if (entering && mpq_cmp(t, t0) > 0)
                    mpq_set(t0, t);
                if (!entering && mpq_cmp(t, t1) < 0)
                    mpq_set(t1, t);
            }
        }
        mpq_clears(aj, bj, bound, NULL);
    }
    if (visible && mpq_cmp(t0, t1) > 0)
        visible = 0;
    for (int j = 0; j < dim && visible; j++) {
        mpq_t aj, bj;
        mpq_inits(aj, bj, NULL);
        mpq_set_d(aj, a[j]);
        mpq_set_d(bj, b[j]);
        mpq_sub(d, bj, aj);
        for (int e = 0; e < 2; e++) {
            mpq_mul(q, d, e ? t1 : t0);
            mpq_add(q, q, aj);
            (e ? out1 : out0)[j] = nearest(q);
        }
        mpq_clears(aj, bj, NULL);
    }
    mpq_clears(t0, t1, t, d, q, NULL);
    return visible;
}

/* a random finite double: any exponent, or near a few values of interest */
static double random_double(check_rng *rng, const double *near, int nnear)
{
    int kind = (int)check_rng_int(rng, 0, 9);
    double sign = check_rng_int(rng, 0, 1) ? -1 : 1;
    if (kind <= 2)
        return sign * ldexp(check_rng_range(rng, 0.5, 1), (int)check_rng_int(rng, -1074, 1024));
    if (kind == 3) /* the largest magnitudes */
        return sign * DBL_MAX * check_rng_range(rng, 0.5, 1);
    if (kind == 4 && nnear) /* a value of the window itself */
        return near[check_rng_int(rng, 0, nnear - 1)];
    if (kind == 5 && nnear) /* a few steps from one */
        return near[check_rng_int(rng, 0, nnear - 1)] + (double)check_rng_int(rng, -3, 3);
    if (kind == 6)
        return sign * (double)check_rng_int(rng, 0, 20);
    if (kind == 7) /* subnormal */
        return sign * ldexp((double)check_rng_int(rng, 0, 1 << 20), -1074);
    return sign * check_rng_range(rng, 0, 1) * ldexp(1, (int)check_rng_int(rng, -20, 80));
}

static long compared;

static void compare(int dim, const double *a, const double *b, const double *lo, const double *hi,
                    int round)
{
    double want0[3], want1[3];
    int want = exact_clip(dim, a, b, lo, hi, want0, want1);
    for (int alg = 0; alg < 2; alg++) {
        double got0[3] = {0}, got1[3] = {0};
        int acc = -1;
        cg_status st;
        if (dim == 2) {
            cg_rect w = {lo[0], lo[1], hi[0], hi[1]};
            cg_vec2 p0 = cg_vec2_make(a[0], a[1]), p1 = cg_vec2_make(b[0], b[1]);
            st = alg ? cg_clip_line_liang_barsky(w, &p0, &p1, &acc)
                     : cg_clip_line_cohen_sutherland(w, &p0, &p1, &acc, NULL, NULL);
            got0[0] = p0.x, got0[1] = p0.y, got1[0] = p1.x, got1[1] = p1.y;
        } else {
            cg_box3 box = {cg_vec3_make(lo[0], lo[1], lo[2]), cg_vec3_make(hi[0], hi[1], hi[2])};
            cg_vec3 p0 = cg_vec3_make(a[0], a[1], a[2]), p1 = cg_vec3_make(b[0], b[1], b[2]);
            st = alg ? cg_clip_line_liang_barsky3(box, &p0, &p1, &acc)
                     : cg_clip_line_cohen_sutherland3(box, &p0, &p1, &acc);
            got0[0] = p0.x, got0[1] = p0.y, got0[2] = p0.z;
            got1[0] = p1.x, got1[1] = p1.y, got1[2] = p1.z;
        }
        CHECK(st == CG_OK);
        CHECK_MSG(acc == want, "round %d %dD %s: accepted %d, exact %d", round, dim,
                  alg ? "liang-barsky" : "cohen-sutherland", acc, want);
        if (acc != 1 || want != 1)
            continue;
        int same = 1;
        for (int j = 0; j < dim; j++)
            same &= got0[j] == want0[j] && got1[j] == want1[j];
        CHECK_MSG(same,
                  "round %d %dD %s: (%.17g %.17g %.17g) (%.17g %.17g %.17g), exact (%.17g %.17g "
                  "%.17g) (%.17g %.17g %.17g)",
                  round, dim, alg ? "liang-barsky" : "cohen-sutherland", got0[0], got0[1],
                  dim == 3 ? got0[2] : 0, got1[0], got1[1], dim == 3 ? got1[2] : 0, want0[0],
                  want0[1], dim == 3 ? want0[2] : 0, want1[0], want1[1], dim == 3 ? want1[2] : 0);
        compared++;
    }
}

static void random_case(check_rng *rng, int dim, int round)
{
    double lo[3], hi[3], a[3], b[3], bounds[6];
    for (int j = 0; j < dim; j++) {
        double u, v;
        if (check_rng_int(rng, 0, 1)) { /* a small window */
            u = (double)check_rng_int(rng, -10, 10);
            v = u + (double)check_rng_int(rng, 0, 20);
        } else {
            u = random_double(rng, NULL, 0);
            v = random_double(rng, NULL, 0);
        }
        lo[j] = u < v ? u : v;
        hi[j] = u < v ? v : u;
        bounds[2 * j] = lo[j];
        bounds[2 * j + 1] = hi[j];
    }
    for (int j = 0; j < dim; j++) {
        a[j] = random_double(rng, bounds, 2 * dim);
        b[j] = check_rng_int(rng, 0, 9) ? random_double(rng, bounds, 2 * dim) : a[j];
    }
    if (check_rng_int(rng, 0, 19) == 0)
        memcpy(b, a, sizeof a); /* a point */
    compare(dim, a, b, lo, hi, round);
}

int main(void)
{
    /* the two cases of the command-line examples */
    double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
    compare(2, (double[]){1.7e308, 0}, (double[]){-1.7e308, 5}, lo, hi, -1);
    compare(2, (double[]){1e18, 0}, (double[]){-1e18, 5}, lo, hi, -2);
    {
        cg_rect w = {0, 0, 10, 10};
        cg_vec2 p0 = cg_vec2_make(1e18, 0), p1 = cg_vec2_make(-1e18, 5);
        int acc = 0;
        CHECK(cg_clip_line_liang_barsky(w, &p0, &p1, &acc) == CG_OK && acc);
        CHECK(p0.x == 10 && p0.y == 2.5 && p1.x == 0 && p1.y == 2.5);
    }
    /* edge cases: the extremes, through corners, along bounds, subnormals */
    static const double ext[] = {DBL_MAX,  -DBL_MAX, 1.7e308,   -1.7e308, DBL_MIN,
                                 -DBL_MIN, 4.9e-324, -4.9e-324, 0,        10,
                                 5,        1e-300,   1e300};
    int ne = (int)(sizeof ext / sizeof ext[0]), round = 0;
    for (int i = 0; i < ne; i++)
        for (int j = 0; j < ne; j++)
            for (int k = 0; k < ne; k++) {
                compare(2, (double[]){ext[i], ext[j]}, (double[]){ext[k], ext[(i + j + k) % ne]},
                        lo, hi, round);
                compare(2, (double[]){ext[i], ext[j]}, (double[]){ext[j], ext[k]}, lo, hi, round);
                compare(3, (double[]){ext[i], ext[j], ext[k]}, (double[]){ext[k], ext[i], ext[j]},
                        lo, hi, round++);
            }
    /* a window at the extremes, and one of subnormal size */
    double blo[2] = {-DBL_MAX, -4.9e-324}, bhi[2] = {DBL_MAX, 4.9e-324};
    for (int i = 0; i < ne; i++)
        for (int j = 0; j < ne; j++)
            compare(2, (double[]){ext[i], ext[j]}, (double[]){-ext[j], ext[(i + 1) % ne]}, blo, bhi,
                    round++);
    check_rng rng = {0x11e5c1f};
    /* short segments of integers and halves near a small window, as a
     * drawing program clips them */
    for (int i = 0; i < 20000; i++) {
        int dim = 2 + (i % 4 == 3);
        double a[3], b[3], wlo[3], whi[3];
        for (int j = 0; j < dim; j++) {
            wlo[j] = (double)check_rng_int(&rng, -10, 0);
            whi[j] = wlo[j] + (double)check_rng_int(&rng, 0, 20);
            a[j] = (double)check_rng_int(&rng, -80, 80) / 2;
            b[j] = (double)check_rng_int(&rng, -80, 80) / 2;
        }
        compare(dim, a, b, wlo, whi, round++);
    }
    for (int i = 0; i < 40000; i++)
        random_case(&rng, 2 + (i % 4 == 3), round++);
    printf("exact line clipping: %ld clips compared\n", compared);
    return check_finish();
}
