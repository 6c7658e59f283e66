/* Parametric cubic curves, Bézier curves, flattening and continuity
 * (section 2.3 of the notes). */
#include "check.h"
#include "cg/curve.h"

#include <stdlib.h>
#include <string.h>

static cg_vec2 rand_point(check_rng *r, double size)
{
    return cg_vec2_make(check_rng_range(r, -size, size), check_rng_range(r, -size, size));
}

static double dist(cg_vec2 a, cg_vec2 b)
{
    return cg_vec2_length(cg_vec2_sub(a, b));
}

static void bernstein(void)
{
    check_rng r = {1};
    for (int n = 0; n <= 25; n++)
        for (int k = 0; k < 40; k++) {
            double t = k == 0 ? 0 : k == 1 ? 1 : check_rng_unit(&r), sum = 0, min = 1;
            for (int i = 0; i <= n; i++) {
                double b = cg_bernstein(n, i, t);
                sum += b;
                min = fmin(min, b);
            }
            CHECK_NEAR(sum, 1, 1e-12);
            CHECK(min >= 0);
        }
    CHECK_NEAR(cg_bernstein(3, 1, 0.5), 3 * 0.5 * 0.25, 1e-15);
    CHECK_EQ_INT(cg_bernstein(3, 4, 0.5), 0);
}

static void basis_matrices(void)
{
    for (int b = CG_BASIS_HERMITE; b <= CG_BASIS_CATMULL_ROM; b++) {
        cg_mat4 m = cg_curve_basis_matrix((cg_curve_basis)b),
                inv = cg_curve_basis_inverse((cg_curve_basis)b);
        CHECK_MSG(cg_mat4_near(cg_mat4_mul(m, inv), cg_mat4_identity(), 1e-12), "basis %d", b);
        CHECK_MSG(cg_mat4_near(cg_mat4_mul(inv, m), cg_mat4_identity(), 1e-12), "basis %d", b);
    }
    /* The matrices printed in the notes. */
    cg_mat4 h = cg_curve_basis_matrix(CG_BASIS_HERMITE);
    CHECK(h.m[0][0] == 2 && h.m[0][1] == -2 && h.m[1][0] == -3 && h.m[1][3] == -1
          && h.m[3][0] == 1);
    cg_mat4 bz = cg_curve_basis_matrix(CG_BASIS_BEZIER);
    CHECK(bz.m[0][0] == -1 && bz.m[1][1] == -6 && bz.m[2][0] == -3 && bz.m[3][0] == 1);
    /* M_B = M_H M_HB (eq. 2.21) */
    cg_mat4 mhb = {{{1, 0, 0, 0}, {0, 0, 0, 1}, {-3, 3, 0, 0}, {0, 0, -3, 3}}};
    CHECK(cg_mat4_near(cg_mat4_mul(h, mhb), bz, 1e-15));
    CHECK(strcmp(cg_curve_basis_name(CG_BASIS_BSPLINE), "bspline") == 0);
}

static void hermite_and_bases(void)
{
    check_rng r = {2};
    for (int i = 0; i < 500; i++) {
        cg_cubic2 h = {
            CG_BASIS_HERMITE,
            {rand_point(&r, 100), rand_point(&r, 100), rand_point(&r, 300), rand_point(&r, 300)}};
        CHECK(dist(cg_cubic2_point(&h, 0), h.g[0]) < 1e-12);
        CHECK(dist(cg_cubic2_point(&h, 1), h.g[1]) < 1e-9);
        CHECK(dist(cg_cubic2_tangent(&h, 0), h.g[2]) < 1e-12);
        CHECK(dist(cg_cubic2_tangent(&h, 1), h.g[3]) < 1e-9);
        /* tangent = derivative of the point (central difference) */
        double t = check_rng_unit(&r), e = 1e-6;
        cg_vec2 fd = cg_vec2_scale(
            cg_vec2_sub(cg_cubic2_point(&h, t + e), cg_cubic2_point(&h, t - e)), 0.5 / e);
        CHECK(dist(fd, cg_cubic2_tangent(&h, t)) < 1e-4);
        /* 3D Hermite */
        cg_cubic3 h3 = {CG_BASIS_HERMITE, {{1, 2, 3}, {4, -5, 6}, {7, 8, -9}, {-1, 0, 2}}};
        CHECK(cg_vec3_length(cg_vec3_sub(cg_cubic3_point(&h3, 1), h3.g[1])) < 1e-12);
        CHECK(cg_vec3_length(cg_vec3_sub(cg_cubic3_tangent(&h3, 0), h3.g[2])) < 1e-12);
        CHECK(cg_vec3_length(cg_vec3_sub(cg_cubic3_tangent(&h3, 1), h3.g[3])) < 1e-12);
    }
    /* Bézier: eq. 2.22, endpoints, R1 = 3 (P2 - P1), R4 = 3 (P4 - P3) */
    for (int i = 0; i < 500; i++) {
        cg_cubic2 b = {
            CG_BASIS_BEZIER,
            {rand_point(&r, 50), rand_point(&r, 50), rand_point(&r, 50), rand_point(&r, 50)}};
        double t = check_rng_unit(&r), s = 1 - t;
        cg_vec2 expect = cg_vec2_add(
            cg_vec2_add(cg_vec2_scale(b.g[0], s * s * s), cg_vec2_scale(b.g[1], 3 * t * s * s)),
            cg_vec2_add(cg_vec2_scale(b.g[2], 3 * t * t * s), cg_vec2_scale(b.g[3], t * t * t)));
        CHECK(dist(cg_cubic2_point(&b, t), expect) < 1e-10);
        cg_vec2 dc;
        CHECK(cg_bezier_point(b.g, 4, t, &dc) == CG_OK);
        CHECK(dist(dc, expect) < 1e-10);
        CHECK(dist(cg_cubic2_tangent(&b, 0), cg_vec2_scale(cg_vec2_sub(b.g[1], b.g[0]), 3))
              < 1e-10);
        CHECK(dist(cg_cubic2_tangent(&b, 1), cg_vec2_scale(cg_vec2_sub(b.g[3], b.g[2]), 3))
              < 1e-10);
        cg_vec2 tan;
        CHECK(cg_bezier_tangent(b.g, 4, t, &tan) == CG_OK);
        CHECK(dist(tan, cg_cubic2_tangent(&b, t)) < 1e-9);
    }
    /* B-spline coefficients, eqs. 2.25-2.28 */
    cg_cubic2 bs = {CG_BASIS_BSPLINE, {{1, 0}, {4, 0}, {2, 0}, {7, 0}}};
    cg_vec2 c[4];
    cg_cubic2_coefficients(&bs, c);
    CHECK_NEAR(c[0].x, (-1 + 12 - 6 + 7) / 6.0, 1e-14);
    CHECK_NEAR(c[1].x, (1 - 8 + 2) / 2.0, 1e-14);
    CHECK_NEAR(c[2].x, (-1 + 2) / 2.0, 1e-14);
    CHECK_NEAR(c[3].x, (1 + 16 + 2) / 6.0, 1e-14);
    /* Catmull-Rom interpolates its middle points with tangents (P2-P0)/2, (P3-P1)/2 */
    cg_cubic2 cr = {CG_BASIS_CATMULL_ROM, {{0, 0}, {1, 2}, {3, 3}, {4, 1}}};
    CHECK(dist(cg_cubic2_point(&cr, 0), cr.g[1]) < 1e-14);
    CHECK(dist(cg_cubic2_point(&cr, 1), cr.g[2]) < 1e-14);
    CHECK(dist(cg_cubic2_tangent(&cr, 0), cg_vec2_make(1.5, 1.5)) < 1e-14);
    CHECK(dist(cg_cubic2_tangent(&cr, 1), cg_vec2_make(1.5, -0.5)) < 1e-14);
}

static void conversions(void)
{
    check_rng r = {3};
    long bad = 0;
    for (int i = 0; i < 400; i++)
        for (int from = 0; from < 4; from++)
            for (int to = 0; to < 4; to++) {
                cg_cubic2 a = {(cg_curve_basis)from,
                               {rand_point(&r, 10), rand_point(&r, 10), rand_point(&r, 10),
                                rand_point(&r, 10)}},
                          b, back;
                CHECK(cg_cubic2_convert(&a, (cg_curve_basis)to, &b) == CG_OK);
                CHECK(b.basis == (cg_curve_basis)to);
                for (int k = 0; k <= 10; k++) {
                    double t = k / 10.0;
                    bad += dist(cg_cubic2_point(&a, t), cg_cubic2_point(&b, t)) > 1e-9;
                    bad += dist(cg_cubic2_tangent(&a, t), cg_cubic2_tangent(&b, t)) > 1e-8;
                }
                cg_cubic2_convert(&b, (cg_curve_basis)from, &back);
                for (int k = 0; k < 4; k++)
                    bad += dist(back.g[k], a.g[k]) > 1e-9;
            }
    CHECK_EQ_INT(bad, 0);
    cg_cubic3 a3 = {CG_BASIS_BSPLINE, {{0, 0, 0}, {1, 2, 3}, {4, 0, 1}, {2, 2, 2}}}, b3;
    CHECK(cg_cubic3_convert(&a3, CG_BASIS_HERMITE, &b3) == CG_OK);
    CHECK(cg_vec3_length(cg_vec3_sub(cg_cubic3_point(&a3, 0.3), cg_cubic3_point(&b3, 0.3)))
          < 1e-12);
    cg_cubic2 bad_basis = {(cg_curve_basis)9, {{0, 0}, {0, 0}, {0, 0}, {0, 0}}}, out;
    CHECK(cg_cubic2_convert(&bad_basis, CG_BASIS_BEZIER, &out) == CG_EINVAL);
}

/* de Casteljau of any degree equals the Bernstein sum; subdivision gives the
 * two parts of the curve. */
static void casteljau(void)
{
    check_rng r = {4};
    long bad = 0;
    for (int i = 0; i < 300; i++) {
        int n = (int)check_rng_int(&r, 1, 40);
        cg_vec2 p[41], left[41], right[41];
        for (int k = 0; k <= n; k++)
            p[k] = rand_point(&r, 100);
        double t = check_rng_unit(&r);
        cg_vec2 q, sum = {0, 0};
        CHECK(cg_bezier_point(p, n + 1, t, &q) == CG_OK);
        for (int k = 0; k <= n; k++)
            sum = cg_vec2_add(sum, cg_vec2_scale(p[k], cg_bernstein(n, k, t)));
        bad += dist(q, sum) > 1e-9;
        double s = check_rng_range(&r, 0.05, 0.95);
        CHECK(cg_bezier_split(p, n + 1, s, left, right) == CG_OK);
        cg_vec2 a, b;
        cg_bezier_point(left, n + 1, t, &a);
        cg_bezier_point(p, n + 1, s * t, &b);
        bad += dist(a, b) > 1e-9;
        cg_bezier_point(right, n + 1, t, &a);
        cg_bezier_point(p, n + 1, s + (1 - s) * t, &b);
        bad += dist(a, b) > 1e-9;
        bad += dist(left[n], right[0]) != 0;
    }
    CHECK_EQ_INT(bad, 0);
    cg_vec3 p3[3] = {{0, 0, 0}, {1, 1, 1}, {2, 0, 4}}, q3;
    CHECK(cg_bezier_point3(p3, 3, 0.5, &q3) == CG_OK);
    CHECK(cg_vec3_length(cg_vec3_sub(q3, cg_vec3_make(1, 0.5, 1.5))) < 1e-15);
    cg_vec2 bad_points[2] = {{0, NAN}, {1, 1}}, q;
    CHECK(cg_bezier_point(bad_points, 2, 0.5, &q) == CG_EINVAL);
    CHECK(cg_bezier_point(bad_points, 0, 0.5, &q) == CG_EINVAL);
    CHECK(cg_bezier_tangent(bad_points + 1, 1, 0.5, &q) == CG_EINVAL);
    CHECK(cg_bezier_split(bad_points, CG_BEZIER_MAX_POINTS + 1, 0.5, NULL, NULL) == CG_EINVAL);
}

/* ---- flattening ---------------------------------------------------------- */

typedef struct polyline {
    cg_vec2 *p;
    int n, cap;
    int fail_after;
} polyline;

static cg_status collect(void *user, cg_vec2 point)
{
    polyline *l = user;
    if (l->fail_after >= 0 && l->n >= l->fail_after)
        return CG_EIO;
    if (l->n == l->cap) {
        l->cap = l->cap ? 2 * l->cap : 256;
        l->p = realloc(l->p, (size_t)l->cap * sizeof *l->p);
    }
    l->p[l->n++] = point;
    return CG_OK;
}

static double point_segment(cg_vec2 p, cg_vec2 a, cg_vec2 b)
{
    cg_vec2 d = cg_vec2_sub(b, a);
    double l2 = cg_vec2_dot(d, d), s = l2 > 0 ? cg_vec2_dot(cg_vec2_sub(p, a), d) / l2 : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    return dist(p, cg_vec2_add(a, cg_vec2_scale(d, s)));
}

static double point_polyline(cg_vec2 p, const cg_vec2 *l, int n)
{
    double best = dist(p, l[0]);
    for (int i = 1; i < n; i++)
        best = fmin(best, point_segment(p, l[i - 1], l[i]));
    return best;
}

static void flattening(void)
{
    check_rng r = {5};
    enum { DENSE = 1500 };
    cg_vec2 *dense = malloc((DENSE + 1) * sizeof *dense);
    long bad_far = 0, bad_back = 0, bad_end = 0;
    polyline l = {NULL, 0, 0, -1};
    for (int i = 0; i < 150; i++) {
        int count = (int)check_rng_int(&r, 2, 9);
        cg_vec2 p[9];
        double size = check_rng_range(&r, 5, 500);
        for (int k = 0; k < count; k++)
            p[k] = rand_point(&r, size);
        double tol = i % 3 == 0 ? 0.1 : i % 3 == 1 ? 0.5 : check_rng_range(&r, 0.01, 3);
        l.n = 0;
        CHECK(collect(&l, p[0]) == CG_OK);
        CHECK(cg_bezier_flatten(p, count, tol, collect, &l) == CG_OK);
        bad_end += l.p[l.n - 1].x != p[count - 1].x || l.p[l.n - 1].y != p[count - 1].y;
        for (int k = 0; k <= DENSE; k++)
            cg_bezier_point(p, count, (double)k / DENSE, &dense[k]);
        /* curve -> polyline */
        for (int k = 0; k <= DENSE; k++)
            bad_far += point_polyline(dense[k], l.p, l.n) > tol * (1 + 1e-9);
        /* polyline -> curve (the dense polyline is far closer than tol) */
        for (int s = 1; s < l.n; s++)
            for (int k = 0; k <= 8; k++) {
                cg_vec2 q = cg_vec2_add(l.p[s - 1],
                                        cg_vec2_scale(cg_vec2_sub(l.p[s], l.p[s - 1]), k / 8.0));
                bad_back += point_polyline(q, dense, DENSE + 1) > tol * 1.001 + 1e-9;
            }
    }
    CHECK_EQ_INT(bad_far, 0);
    CHECK_EQ_INT(bad_back, 0);
    CHECK_EQ_INT(bad_end, 0);
    /* adaptive: a straight Bézier is one segment; a tighter tolerance gives more points */
    cg_vec2 straight[4] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
    l.n = 0;
    CHECK(cg_bezier_flatten(straight, 4, 0.1, collect, &l) == CG_OK);
    CHECK_EQ_INT(l.n, 1);
    cg_vec2 curve[4] = {{0, 0}, {100, 300}, {200, -300}, {300, 0}};
    l.n = 0;
    cg_bezier_flatten(curve, 4, 1, collect, &l);
    int coarse = l.n;
    l.n = 0;
    cg_bezier_flatten(curve, 4, 0.01, collect, &l);
    CHECK(l.n > 3 * coarse && coarse > 4);
    /* cubic segments in other bases */
    cg_cubic2 bs = {CG_BASIS_BSPLINE, {{0, 0}, {100, 300}, {200, -300}, {300, 0}}};
    l.n = 0;
    CHECK(collect(&l, cg_cubic2_point(&bs, 0)) == CG_OK);
    CHECK(cg_cubic2_flatten(&bs, 0.2, collect, &l) == CG_OK);
    for (int k = 0; k <= 200; k++)
        CHECK(point_polyline(cg_cubic2_point(&bs, k / 200.0), l.p, l.n) <= 0.2 + 1e-9);
    /* bad input: nothing emitted */
    l.n = 0;
    CHECK(cg_bezier_flatten(curve, 4, 0, collect, &l) == CG_EINVAL);
    CHECK(cg_bezier_flatten(curve, 4, -1, collect, &l) == CG_EINVAL);
    CHECK(cg_bezier_flatten(curve, 4, NAN, collect, &l) == CG_EINVAL);
    CHECK(cg_bezier_flatten(curve, 4, INFINITY, collect, &l) == CG_EINVAL);
    CHECK(cg_bezier_flatten(curve, 1, 0.5, collect, &l) == CG_EINVAL);
    CHECK(cg_bezier_flatten(NULL, 4, 0.5, collect, &l) == CG_EINVAL);
    cg_vec2 nan_curve[3] = {{0, 0}, {NAN, 1}, {2, 2}},
            inf_curve[3] = {{0, 0}, {INFINITY, 1}, {2, 2}};
    CHECK(cg_bezier_flatten(nan_curve, 3, 0.5, collect, &l) == CG_EINVAL);
    CHECK(cg_bezier_flatten(inf_curve, 3, 0.5, collect, &l) == CG_EINVAL);
    cg_vec2 huge[3] = {{0, 0}, {1e15, 1e15}, {2e15, 0}};
    CHECK(cg_bezier_flatten(huge, 3, 1e-3, collect, &l) == CG_ERANGE);
    CHECK(cg_bezier_flatten(curve, 4, 1e-300, collect, &l) == CG_ERANGE);
    CHECK_EQ_INT(l.n, 0);
    /* a degenerate curve (all points equal) flattens to its end point */
    cg_vec2 dot[3] = {{5, 5}, {5, 5}, {5, 5}};
    CHECK(cg_bezier_flatten(dot, 3, 0.5, collect, &l) == CG_OK);
    CHECK_EQ_INT(l.n, 1);
    /* a sink failure stops the flattening and is returned */
    l.n = 0;
    l.fail_after = 3;
    CHECK(cg_bezier_flatten(curve, 4, 0.01, collect, &l) == CG_EIO);
    CHECK_EQ_INT(l.n, 3);
    /* high degree */
    cg_vec2 *many = malloc(CG_BEZIER_MAX_POINTS * sizeof *many);
    for (int k = 0; k < CG_BEZIER_MAX_POINTS; k++)
        many[k] = cg_vec2_make(k, (k % 2) * 50.0);
    l.n = 0;
    l.fail_after = -1;
    CHECK(cg_bezier_flatten(many, CG_BEZIER_MAX_POINTS, 0.5, collect, &l) == CG_OK);
    CHECK(l.n >= 1 && l.p[l.n - 1].x == CG_BEZIER_MAX_POINTS - 1);
    free(many);
    free(l.p);
    free(dense);
}

static void continuity(void)
{
    check_rng r = {6};
    for (int i = 0; i < 200; i++) {
        int basis = i % 4;
        cg_cubic2 a = {
            (cg_curve_basis)basis,
            {rand_point(&r, 10), rand_point(&r, 10), rand_point(&r, 10), rand_point(&r, 10)}};
        cg_cubic2 b = {
            (cg_curve_basis)((basis + i / 4) % 4),
            {rand_point(&r, 10), rand_point(&r, 10), rand_point(&r, 10), rand_point(&r, 10)}};
        CHECK(cg_cubic2_continuity(&a, &b, 1e-9) == CG_CONTINUITY_NONE);
        cg_cubic2 c1 = b;
        CHECK(cg_cubic2_join_c1(&a, &c1) == CG_OK);
        CHECK(c1.basis == b.basis);
        CHECK(cg_cubic2_continuity(&a, &c1, 1e-9) == CG_CONTINUITY_C1);
        /* the rest of b's Hermite form is kept */
        CHECK(dist(cg_cubic2_point(&c1, 1), cg_cubic2_point(&b, 1)) < 1e-9);
        CHECK(dist(cg_cubic2_tangent(&c1, 1), cg_cubic2_tangent(&b, 1)) < 1e-9);
        cg_cubic2 g1 = b;
        CHECK(cg_cubic2_join_g1(&a, &g1) == CG_OK);
        cg_continuity k = cg_cubic2_continuity(&a, &g1, 1e-9);
        CHECK(k == CG_CONTINUITY_G1);
        CHECK_NEAR(cg_vec2_length(cg_cubic2_tangent(&g1, 0)),
                   cg_vec2_length(cg_cubic2_tangent(&b, 0)), 1e-9);
    }
    /* Figure 2.10: Bézier P1..P4 and P4..P7 with P3, P4, P5 collinear */
    cg_cubic2 left = {CG_BASIS_BEZIER, {{0, 0}, {1, 2}, {2, 1}, {3, 1}}};
    cg_cubic2 right = {CG_BASIS_BEZIER, {{3, 1}, {5, 1}, {6, 3}, {7, 0}}};
    CHECK(cg_cubic2_continuity(&left, &right, 1e-12) == CG_CONTINUITY_G1);
    right.g[1] = cg_vec2_make(4, 1); /* P4 - P3 = P5 - P4: C1 */
    CHECK(cg_cubic2_continuity(&left, &right, 1e-12) == CG_CONTINUITY_C1);
    right.g[1] = cg_vec2_make(4, 2); /* a corner: G0 only */
    CHECK(cg_cubic2_continuity(&left, &right, 1e-12) == CG_CONTINUITY_G0);
    right.g[1] = cg_vec2_make(2, 1); /* opposite direction: G0 only */
    CHECK(cg_cubic2_continuity(&left, &right, 1e-12) == CG_CONTINUITY_G0);
    CHECK(cg_joint_continuity(cg_vec2_make(0, 0), cg_vec2_make(0, 0), cg_vec2_make(0, 0),
                              cg_vec2_make(1, 0), 1e-12)
          == CG_CONTINUITY_G0);
    CHECK(strcmp(cg_continuity_name(CG_CONTINUITY_C1), "C1") == 0);
    cg_cubic3 a3 = {CG_BASIS_BEZIER, {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 1}}};
    cg_cubic3 b3 = {CG_BASIS_BEZIER, {{3, 1, 1}, {4, 1, 2}, {5, 0, 0}, {6, 0, 0}}};
    CHECK(cg_cubic3_continuity(&a3, &b3, 1e-12) == CG_CONTINUITY_C1);
    b3.g[1] = cg_vec3_make(5, 1, 3);
    CHECK(cg_cubic3_continuity(&a3, &b3, 1e-12) == CG_CONTINUITY_G1);
    /* G1 needs a direction */
    cg_cubic2 flat = {CG_BASIS_BEZIER, {{0, 0}, {1, 1}, {3, 3}, {3, 3}}}, other = left;
    CHECK(cg_cubic2_join_g1(&flat, &other) == CG_EINVAL);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(bernstein);
    CHECK_GROUP(basis_matrices);
    CHECK_GROUP(hermite_and_bases);
    CHECK_GROUP(conversions);
    CHECK_GROUP(casteljau);
    CHECK_GROUP(flattening);
    CHECK_GROUP(continuity);
    return check_finish();
}
