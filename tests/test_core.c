/* Vectors and matrices: products, transpose, determinant, inverse,
 * composition, over random and edge-case inputs. */
#include "cg.h"
#include "check.h"

#include <float.h>
#include <string.h>

static cg_mat4 random_mat4(check_rng *r, double scale)
{
    cg_mat4 m;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m.m[i][j] = check_rng_range(r, -scale, scale);
    return m;
}

static cg_mat3 random_mat3(check_rng *r, double scale)
{
    cg_mat3 m;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m.m[i][j] = check_rng_range(r, -scale, scale);
    return m;
}

/* Relative distance of a product from the identity, scaled by the matrix's
 * conditioning through the norms of a and its inverse. */
static double identity_error4(cg_mat4 p)
{
    double worst = 0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            worst = fmax(worst, fabs(p.m[i][j] - (i == j)));
    return worst;
}

static void test_inverse_round_trips(void)
{
    check_rng r = {12345};
    int checked = 0;
    for (int n = 0; n < 20000; n++) {
        cg_mat4 a = random_mat4(&r, 10), inv;
        if (cg_mat4_inverse(a, &inv) != CG_OK)
            continue;
        /* Random matrices are sometimes ill-conditioned; the 1e-12 bound is
         * for the well-conditioned ones (condition number below ~1e3). */
        double norm_a = 0, norm_inv = 0;
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) {
                norm_a = fmax(norm_a, fabs(a.m[i][j]));
                norm_inv = fmax(norm_inv, fabs(inv.m[i][j]));
            }
        if (norm_a * norm_inv > 100)
            continue;
        checked++;
        CHECK_MSG(identity_error4(cg_mat4_mul(a, inv)) < 1e-12, "A A^-1 = I (case %d)", n);
        CHECK_MSG(identity_error4(cg_mat4_mul(inv, a)) < 1e-12, "A^-1 A = I (case %d)", n);
        CHECK_NEAR(cg_mat4_determinant(a) * cg_mat4_determinant(inv), 1.0, 1e-9);
    }
    CHECK(checked > 5000);
    for (int n = 0; n < 20000; n++) {
        cg_mat3 a = random_mat3(&r, 10), inv;
        if (cg_mat3_inverse(a, &inv) != CG_OK)
            continue;
        double norm_a = 0, norm_inv = 0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                norm_a = fmax(norm_a, fabs(a.m[i][j]));
                norm_inv = fmax(norm_inv, fabs(inv.m[i][j]));
            }
        if (norm_a * norm_inv > 100)
            continue;
        CHECK(cg_mat3_near(cg_mat3_mul(a, inv), cg_mat3_identity(), 1e-12));
    }
}

static void test_singular(void)
{
    cg_mat4 zero;
    memset(&zero, 0, sizeof zero);
    cg_mat4 out = cg_mat4_identity(), before = out;
    CHECK_EQ_INT(cg_mat4_inverse(zero, &out), CG_ESINGULAR);
    CHECK(memcmp(&out, &before, sizeof out) == 0); /* untouched on failure */
    /* Rank-deficient: third row is the sum of the first two. */
    cg_mat4 rank3 = {{{1, 2, 3, 4}, {5, 6, 7, 8}, {6, 8, 10, 12}, {0, 0, 0, 1}}};
    CHECK_EQ_INT(cg_mat4_inverse(rank3, &out), CG_ESINGULAR);
    CHECK_NEAR(cg_mat4_determinant(rank3), 0, 1e-9);
    cg_mat3 flat = {{{1, 2, 3}, {2, 4, 6}, {0, 0, 1}}}, out3;
    CHECK_EQ_INT(cg_mat3_inverse(flat, &out3), CG_ESINGULAR);
    cg_mat4 nan = cg_mat4_identity();
    nan.m[1][2] = NAN;
    CHECK_EQ_INT(cg_mat4_inverse(nan, &out), CG_ESINGULAR);
    cg_mat4 inf = cg_mat4_identity();
    inf.m[0][0] = INFINITY;
    CHECK_EQ_INT(cg_mat4_inverse(inf, &out), CG_ESINGULAR);
    CHECK_EQ_INT(cg_mat4_inverse(cg_mat4_identity(), NULL), CG_EINVAL);
    /* Tiny but well-conditioned matrices are invertible. */
    cg_mat4 tiny = cg_mat4_identity();
    for (int i = 0; i < 4; i++)
        tiny.m[i][i] = 1e-200;
    CHECK_EQ_INT(cg_mat4_inverse(tiny, &out), CG_OK);
    CHECK_NEAR(out.m[2][2], 1e200, 1e188);
}

static void test_determinant_and_transpose(void)
{
    check_rng r = {99};
    for (int n = 0; n < 2000; n++) {
        cg_mat4 a = random_mat4(&r, 3), b = random_mat4(&r, 3);
        double da = cg_mat4_determinant(a), db = cg_mat4_determinant(b);
        CHECK_NEAR(cg_mat4_determinant(cg_mat4_mul(a, b)), da * db, 1e-9 * (1 + fabs(da * db)));
        CHECK_NEAR(cg_mat4_determinant(cg_mat4_transpose(a)), da, 1e-10 * (1 + fabs(da)));
        CHECK(cg_mat4_near(cg_mat4_transpose(cg_mat4_mul(a, b)),
                           cg_mat4_mul(cg_mat4_transpose(b), cg_mat4_transpose(a)), 1e-12));
        cg_mat3 c = random_mat3(&r, 3), d = random_mat3(&r, 3);
        CHECK_NEAR(cg_mat3_determinant(cg_mat3_mul(c, d)),
                   cg_mat3_determinant(c) * cg_mat3_determinant(d), 1e-9);
    }
    cg_mat3 known = {{{2, 0, 1}, {1, 3, 2}, {1, 1, 1}}};
    CHECK_NEAR(cg_mat3_determinant(known), 2 * (3 - 2) - 0 + 1 * (1 - 3), 0);
}

static void test_composition_order(void)
{
    check_rng r = {7};
    for (int n = 0; n < 2000; n++) {
        cg_mat4 steps[5];
        for (int k = 0; k < 5; k++)
            steps[k] = random_mat4(&r, 2);
        cg_vec3 p = cg_vec3_make(check_rng_range(&r, -5, 5), check_rng_range(&r, -5, 5),
                                 check_rng_range(&r, -5, 5));
        /* Step-by-step application in homogeneous coordinates. */
        cg_vec4 h = cg_vec4_from_point(p);
        for (int k = 0; k < 5; k++)
            h = cg_mat4_mul_vec4(steps[k], h);
        cg_vec4 once = cg_mat4_mul_vec4(cg_mat4_compose(steps, 5), cg_vec4_from_point(p));
        double scale = 1 + fabs(h.x) + fabs(h.y) + fabs(h.z) + fabs(h.w);
        CHECK(fabs(once.x - h.x) < 1e-11 * scale && fabs(once.y - h.y) < 1e-11 * scale
              && fabs(once.z - h.z) < 1e-11 * scale && fabs(once.w - h.w) < 1e-11 * scale);
    }
    CHECK(cg_mat4_near(cg_mat4_compose(NULL, 0), cg_mat4_identity(), 0));
    /* Batch transform equals point-by-point, including in place. */
    cg_vec3 pts[100], out[100];
    for (int i = 0; i < 100; i++)
        pts[i] = cg_vec3_make(i, i * 0.5, -i);
    cg_mat4 m = random_mat4(&r, 1);
    m.m[3][0] = m.m[3][1] = m.m[3][2] = 0.001;
    m.m[3][3] = 2;
    cg_mat4_transform_points(m, pts, out, 100);
    for (int i = 0; i < 100; i++) {
        cg_vec3 e = cg_mat4_transform_point(m, pts[i]);
        CHECK_NEAR(out[i].x, e.x, 1e-12 * (1 + fabs(e.x)));
        CHECK_NEAR(out[i].z, e.z, 1e-12 * (1 + fabs(e.z)));
    }
    cg_mat4_transform_points(m, pts, pts, 100);
    CHECK(memcmp(pts, out, sizeof out) == 0);
}

static void test_vectors(void)
{
    cg_vec3 x = {1, 0, 0}, y = {0, 1, 0};
    cg_vec3 z = cg_vec3_cross(x, y);
    CHECK(z.x == 0 && z.y == 0 && z.z == 1);
    CHECK_NEAR(cg_vec3_length(cg_vec3_normalize(cg_vec3_make(3, 4, 12))), 1, 1e-15);
    cg_vec3 zero = cg_vec3_normalize(cg_vec3_make(0, 0, 0));
    CHECK(zero.x == 0 && zero.y == 0 && zero.z == 0);
    CHECK_NEAR(cg_vec2_cross(cg_vec2_make(1, 0), cg_vec2_make(0, 1)), 1, 0);
    CHECK_NEAR(cg_vec2_length(cg_vec2_make(3e300, 4e300)), 5e300, 1e286);

    /* Unit length and the same direction at every scale, subnormal to
     * near-overflow: v = u * 2^k for a random unit-ish u. */
    check_rng r = {91};
    int bad2 = 0, bad3 = 0;
    for (int i = 0; i < 20000; i++) {
        int k = (int)check_rng_range(&r, -1070, 1020);
        double s = ldexp(1, k);
        cg_vec2 u2 = cg_vec2_make(check_rng_range(&r, -1, 1), check_rng_range(&r, -1, 1));
        cg_vec3 u3 = cg_vec3_make(check_rng_range(&r, -1, 1), check_rng_range(&r, -1, 1),
                                  check_rng_range(&r, -1, 1));
        if (i % 7 == 0)
            u2.y = u3.y = u3.z = 0; /* along an axis */
        if (fabs(u2.x) < 1e-3 && fabs(u2.y) < 1e-3)
            continue;
        if (cg_vec3_length(u3) < 1e-3)
            continue;
        /* the scaled vector as stored (subnormal components lose bits) */
        cg_vec2 v2 = cg_vec2_scale(u2, s);
        cg_vec3 v3 = cg_vec3_scale(u3, s);
        cg_vec2 n2 = cg_vec2_normalize(v2);
        cg_vec3 n3 = cg_vec3_normalize(v3);
        cg_vec2 w2 = cg_vec2_make(ldexp(v2.x, -k), ldexp(v2.y, -k)); /* exact */
        cg_vec3 w3 = cg_vec3_make(ldexp(v3.x, -k), ldexp(v3.y, -k), ldexp(v3.z, -k));
        cg_vec2 e2 = cg_vec2_scale(w2, 1 / cg_vec2_length(w2));
        cg_vec3 e3 = cg_vec3_scale(w3, 1 / cg_vec3_length(w3));
        bad2 += !(fabs(n2.x - e2.x) <= 1e-15 && fabs(n2.y - e2.y) <= 1e-15);
        bad3 += !(fabs(n3.x - e3.x) <= 1e-15 && fabs(n3.y - e3.y) <= 1e-15
                  && fabs(n3.z - e3.z) <= 1e-15);
    }
    CHECK_EQ_INT(bad2, 0);
    CHECK_EQ_INT(bad3, 0);
    cg_vec2 tiny = cg_vec2_normalize(cg_vec2_make(4.9e-324, 0));
    CHECK(tiny.x == 1 && tiny.y == 0);
    cg_vec3 tiny3 = cg_vec3_normalize(cg_vec3_make(0, -4.9e-324, 0));
    CHECK(tiny3.x == 0 && tiny3.y == -1 && tiny3.z == 0);
    cg_vec3 huge3 = cg_vec3_normalize(cg_vec3_make(DBL_MAX, DBL_MAX, 0));
    CHECK_NEAR(huge3.x, sqrt(0.5), 1e-15);
    CHECK_NEAR(huge3.y, sqrt(0.5), 1e-15);
    cg_vec2 huge2 = cg_vec2_normalize(cg_vec2_make(-DBL_MAX, DBL_MAX));
    CHECK_NEAR(huge2.x, -sqrt(0.5), 1e-15);
    CHECK_NEAR(huge2.y, sqrt(0.5), 1e-15);
    cg_vec3 inf3 = cg_vec3_normalize(cg_vec3_make(INFINITY, 1, 0));
    CHECK(isinf(inf3.x) && inf3.y == 1 && inf3.z == 0);
    cg_vec2 nan2 = cg_vec2_normalize(cg_vec2_make(NAN, 1));
    CHECK(isnan(nan2.x) && nan2.y == 1);
}

static void test_status_strings(void)
{
    for (int s = CG_OK; s <= CG_EEMPTY; s++)
        CHECK(cg_status_str((cg_status)s) && cg_status_str((cg_status)s)[0]);
    cg_error err;
    CHECK_EQ_INT(cg_error_set(&err, CG_EFORMAT, "%s:%d: bad", "f", 3), CG_EFORMAT);
    CHECK(strcmp(err.message, "f:3: bad") == 0);
    CHECK_EQ_INT(cg_error_set(NULL, CG_EIO, "x"), CG_EIO);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_inverse_round_trips);
    CHECK_GROUP(test_singular);
    CHECK_GROUP(test_determinant_and_transpose);
    CHECK_GROUP(test_composition_order);
    CHECK_GROUP(test_vectors);
    CHECK_GROUP(test_status_strings);
    return check_finish();
}
