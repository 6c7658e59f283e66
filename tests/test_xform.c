/* Transformations, projections, camera and viewport against hand-worked
 * values and geometric invariants. */
#include "cg.h"
#include "check.h"

static void check_vec2(cg_vec2 a, double x, double y, double tol, const char *what)
{
    CHECK_MSG(fabs(a.x - x) <= tol && fabs(a.y - y) <= tol, "%s: got (%.17g, %.17g), want (%g, %g)",
              what, a.x, a.y, x, y);
}

static void check_vec3(cg_vec3 a, double x, double y, double z, double tol, const char *what)
{
    CHECK_MSG(fabs(a.x - x) <= tol && fabs(a.y - y) <= tol && fabs(a.z - z) <= tol,
              "%s: got (%.17g, %.17g, %.17g), want (%g, %g, %g)", what, a.x, a.y, a.z, x, y, z);
}

static cg_vec3 random_vec3(check_rng *r, double s)
{
    return cg_vec3_make(check_rng_range(r, -s, s), check_rng_range(r, -s, s),
                        check_rng_range(r, -s, s));
}

static void test_2d_known_points(void)
{
    check_vec2(cg_mat3_transform_point(cg_xform2_translate(2, -3), cg_vec2_make(1, 1)), 3, -2, 0,
               "translate");
    check_vec2(cg_mat3_transform_point(cg_xform2_rotate(CG_PI / 2, 0, 0), cg_vec2_make(1, 0)), 0, 1,
               1e-15, "rotate 90 about origin");
    /* Rotation about (2, 1): the centre stays, (3, 1) goes to (2, 2). */
    cg_mat3 r = cg_xform2_rotate(CG_PI / 2, 2, 1);
    check_vec2(cg_mat3_transform_point(r, cg_vec2_make(2, 1)), 2, 1, 1e-15, "rotation centre");
    check_vec2(cg_mat3_transform_point(r, cg_vec2_make(3, 1)), 2, 2, 1e-15, "rotate about point");
    cg_mat3 s = cg_xform2_scale(2, 3, 1, 1);
    check_vec2(cg_mat3_transform_point(s, cg_vec2_make(1, 1)), 1, 1, 0, "scale fixed point");
    check_vec2(cg_mat3_transform_point(s, cg_vec2_make(2, 2)), 3, 4, 0, "scale about point");
    check_vec2(cg_mat3_transform_point(cg_xform2_shear(0.5, 0), cg_vec2_make(1, 2)), 2, 2, 0,
               "shear x");
    check_vec2(cg_mat3_transform_point(cg_xform2_shear(0, 2), cg_vec2_make(1, 2)), 1, 4, 0,
               "shear y");
    cg_mat3 m;
    /* Reflection about y = x maps (a, b) to (b, a). */
    CHECK_EQ_INT(cg_xform2_reflect(cg_vec2_make(0, 0), cg_vec2_make(1, 1), &m), CG_OK);
    check_vec2(cg_mat3_transform_point(m, cg_vec2_make(3, -1)), -1, 3, 1e-15, "reflect y=x");
    /* About the horizontal line y = 2: (5, 7) -> (5, -3). */
    CHECK_EQ_INT(cg_xform2_reflect(cg_vec2_make(0, 2), cg_vec2_make(-4, 0), &m), CG_OK);
    check_vec2(cg_mat3_transform_point(m, cg_vec2_make(5, 7)), 5, -3, 1e-14, "reflect y=2");
    CHECK_EQ_INT(cg_xform2_reflect(cg_vec2_make(0, 0), cg_vec2_make(0, 0), &m), CG_EINVAL);
    CHECK_EQ_INT(cg_xform2_reflect(cg_vec2_make(NAN, 0), cg_vec2_make(1, 0), &m), CG_EINVAL);
}

static void test_2d_random_invariants(void)
{
    check_rng rng = {2024};
    for (int n = 0; n < 5000; n++) {
        cg_vec2 c = cg_vec2_make(check_rng_range(&rng, -50, 50), check_rng_range(&rng, -50, 50));
        cg_vec2 d = cg_vec2_make(check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1));
        cg_vec2 p = cg_vec2_make(check_rng_range(&rng, -50, 50), check_rng_range(&rng, -50, 50));
        cg_vec2 q = cg_vec2_make(check_rng_range(&rng, -50, 50), check_rng_range(&rng, -50, 50));
        double angle = check_rng_range(&rng, -7, 7);
        cg_mat3 rot = cg_xform2_rotate(angle, c.x, c.y);
        cg_vec2 rp = cg_mat3_transform_point(rot, p), rq = cg_mat3_transform_point(rot, q);
        CHECK_NEAR(cg_vec2_length(cg_vec2_sub(rp, rq)), cg_vec2_length(cg_vec2_sub(p, q)), 1e-11);
        CHECK_NEAR(cg_vec2_length(cg_vec2_sub(rp, c)), cg_vec2_length(cg_vec2_sub(p, c)), 1e-11);
        CHECK_NEAR(cg_mat3_determinant(rot), 1, 1e-14);
        if (cg_vec2_length(d) < 1e-3)
            continue;
        cg_mat3 ref;
        CHECK_EQ_INT(cg_xform2_reflect(c, d, &ref), CG_OK);
        CHECK_NEAR(cg_mat3_determinant(ref), -1, 1e-13);
        CHECK(cg_mat3_near(cg_mat3_mul(ref, ref), cg_mat3_identity(), 1e-12));
        /* The midpoint of p and its image lies on the line; the segment is
         * perpendicular to it. */
        cg_vec2 rp2 = cg_mat3_transform_point(ref, p);
        cg_vec2 mid = cg_vec2_scale(cg_vec2_add(p, rp2), 0.5);
        CHECK_NEAR(cg_vec2_cross(cg_vec2_normalize(d), cg_vec2_sub(mid, c)), 0, 1e-10);
        CHECK_NEAR(cg_vec2_dot(d, cg_vec2_sub(rp2, p)), 0, 1e-10);
        /* Inverse of a composite undoes it. */
        cg_mat3 steps[4] = {rot, ref, cg_xform2_scale(2.5, 0.25, q.x, q.y),
                            cg_xform2_shear(0.3, -0.7)};
        cg_mat3 all = cg_mat3_compose(steps, 4), inv;
        CHECK_EQ_INT(cg_mat3_inverse(all, &inv), CG_OK);
        cg_vec2 back = cg_mat3_transform_point(inv, cg_mat3_transform_point(all, p));
        CHECK(fabs(back.x - p.x) < 1e-12 * 100 && fabs(back.y - p.y) < 1e-12 * 100);
        CHECK(cg_mat3_near(cg_mat3_mul(inv, all), cg_mat3_identity(), 1e-12));
    }
}

static void test_3d(void)
{
    check_vec3(cg_mat4_transform_point(cg_xform3_rotate_x(CG_PI / 2), cg_vec3_make(0, 1, 0)), 0, 0,
               1, 1e-15, "rotate x: y -> z");
    check_vec3(cg_mat4_transform_point(cg_xform3_rotate_y(CG_PI / 2), cg_vec3_make(0, 0, 1)), 1, 0,
               0, 1e-15, "rotate y: z -> x");
    check_vec3(cg_mat4_transform_point(cg_xform3_rotate_z(CG_PI / 2), cg_vec3_make(1, 0, 0)), 0, 1,
               0, 1e-15, "rotate z: x -> y");
    cg_mat4 m;
    /* 120 degrees about (1,1,1) cycles the axes: x -> y -> z -> x. */
    CHECK_EQ_INT(
        cg_xform3_rotate_axis(cg_vec3_make(1, 1, 1), 2 * CG_PI / 3, cg_vec3_make(0, 0, 0), &m),
        CG_OK);
    check_vec3(cg_mat4_transform_point(m, cg_vec3_make(1, 0, 0)), 0, 1, 0, 1e-15, "axis (1,1,1)");
    /* About the vertical axis through (1, 0, 0): (2, 5, 0) -> (1, 5, -1) for +90 deg. */
    CHECK_EQ_INT(cg_xform3_rotate_axis(cg_vec3_make(0, 2, 0), CG_PI / 2, cg_vec3_make(1, 0, 0), &m),
                 CG_OK);
    check_vec3(cg_mat4_transform_point(m, cg_vec3_make(2, 5, 0)), 1, 5, -1, 1e-15,
               "axis through point");
    CHECK_EQ_INT(cg_xform3_rotate_axis(cg_vec3_make(0, 0, 0), 1, cg_vec3_make(0, 0, 0), &m),
                 CG_EINVAL);
    /* Reflection about the plane z = 2. */
    CHECK_EQ_INT(cg_xform3_reflect(cg_vec3_make(0, 0, 2), cg_vec3_make(0, 0, 5), &m), CG_OK);
    check_vec3(cg_mat4_transform_point(m, cg_vec3_make(1, 2, 3)), 1, 2, 1, 1e-15, "reflect z=2");
    CHECK_EQ_INT(cg_xform3_reflect(cg_vec3_make(0, 0, 0), cg_vec3_make(0, 0, 0), &m), CG_EINVAL);
    check_vec3(cg_mat4_transform_point(cg_xform3_scale(2, 3, 4, cg_vec3_make(1, 1, 1)),
                                       cg_vec3_make(2, 2, 2)),
               3, 4, 5, 0, "scale about point");
    check_vec3(cg_mat4_transform_point(cg_xform3_shear(1, 0, 0, 0, 0, 2), cg_vec3_make(1, 1, 1)), 2,
               1, 3, 0, "shear");

    check_rng rng = {77};
    for (int n = 0; n < 5000; n++) {
        cg_vec3 axis = random_vec3(&rng, 1), point = random_vec3(&rng, 20);
        cg_vec3 p = random_vec3(&rng, 20), q = random_vec3(&rng, 20), s = random_vec3(&rng, 20);
        if (cg_vec3_length(axis) < 1e-3)
            continue;
        double angle = check_rng_range(&rng, -7, 7);
        CHECK_EQ_INT(cg_xform3_rotate_axis(axis, angle, point, &m), CG_OK);
        cg_vec3 mp = cg_mat4_transform_point(m, p), mq = cg_mat4_transform_point(m, q),
                ms = cg_mat4_transform_point(m, s);
        /* Lengths and angles preserved; points on the axis fixed. */
        CHECK_NEAR(cg_vec3_length(cg_vec3_sub(mp, mq)), cg_vec3_length(cg_vec3_sub(p, q)), 1e-11);
        CHECK_NEAR(cg_vec3_dot(cg_vec3_sub(mp, ms), cg_vec3_sub(mq, ms)),
                   cg_vec3_dot(cg_vec3_sub(p, s), cg_vec3_sub(q, s)), 1e-9);
        cg_vec3 on_axis = cg_vec3_add(point, cg_vec3_scale(axis, 3.7));
        cg_vec3 fixed = cg_mat4_transform_point(m, on_axis);
        CHECK(cg_vec3_length(cg_vec3_sub(fixed, on_axis)) < 1e-12 * 100);
        CHECK_NEAR(cg_mat4_determinant(m), 1, 1e-13);
        cg_mat4 ref;
        CHECK_EQ_INT(cg_xform3_reflect(point, axis, &ref), CG_OK);
        CHECK_NEAR(cg_mat4_determinant(ref), -1, 1e-13);
        CHECK(cg_mat4_near(cg_mat4_mul(ref, ref), cg_mat4_identity(), 1e-12));
        cg_mat4 steps[5] = {m, ref, cg_xform3_translate(p.x, p.y, p.z),
                            cg_xform3_scale(0.5, 2, 3, q),
                            cg_xform3_shear(0.1, 0.2, -0.3, 0.4, 0.5, -0.6)};
        cg_mat4 all = cg_mat4_compose(steps, 5), inv;
        CHECK_EQ_INT(cg_mat4_inverse(all, &inv), CG_OK);
        cg_vec3 back = cg_mat4_transform_point(inv, cg_mat4_transform_point(all, s));
        CHECK(cg_vec3_length(cg_vec3_sub(back, s)) < 1e-12 * 1000);
    }
}

/* The eight corners of the unit cube [0,1]^3. */
static cg_vec3 corner(int i)
{
    return cg_vec3_make(i & 1, (i >> 1) & 1, (i >> 2) & 1);
}

static void test_parallel_projections(void)
{
    for (int i = 0; i < 8; i++) {
        cg_vec3 c = corner(i);
        cg_vec3 front = cg_mat4_transform_point(cg_proj_view_rotation(CG_VIEW_FRONT), c);
        check_vec3(front, c.x, c.y, c.z, 0, "front view");
        cg_vec3 top = cg_mat4_transform_point(cg_proj_view_rotation(CG_VIEW_TOP), c);
        check_vec2(cg_vec2_make(top.x, top.y), c.x, -c.z, 1e-15, "top view shows x and -z");
        CHECK_NEAR(top.z, c.y, 1e-15); /* higher is nearer the viewer */
        cg_vec3 side = cg_mat4_transform_point(cg_proj_view_rotation(CG_VIEW_SIDE), c);
        check_vec2(cg_vec2_make(side.x, side.y), -c.z, c.y, 1e-15, "side view shows -z and y");
        CHECK_NEAR(side.z, c.x, 1e-15);
        /* Cavalier: depth at full length along 45 deg; cabinet: half. */
        cg_vec3 cav = cg_mat4_transform_point(cg_proj_cavalier(CG_PI / 4), c);
        check_vec2(cg_vec2_make(cav.x, cav.y), c.x + c.z * sqrt(0.5), c.y + c.z * sqrt(0.5), 1e-15,
                   "cavalier");
        cg_vec3 cab = cg_mat4_transform_point(cg_proj_cabinet(CG_PI / 6), c);
        check_vec2(cg_vec2_make(cab.x, cab.y), c.x + 0.5 * c.z * cos(CG_PI / 6),
                   c.y + 0.5 * c.z * sin(CG_PI / 6), 1e-15, "cabinet");
    }
    /* Isometric: the main diagonal projects to a point, the three axes are
     * foreshortened equally by sqrt(2/3) and meet at 120 degrees. */
    cg_mat4 iso = cg_proj_isometric();
    cg_vec3 diag = cg_mat4_transform_point(iso, cg_vec3_make(1, 1, 1));
    check_vec2(cg_vec2_make(diag.x, diag.y), 0, 0, 1e-15, "isometric diagonal");
    cg_vec3 f = cg_proj_foreshortening(iso);
    check_vec3(f, sqrt(2.0 / 3), sqrt(2.0 / 3), sqrt(2.0 / 3), 1e-15, "isometric foreshortening");
    cg_vec3 ix = cg_mat4_transform_vector(iso, cg_vec3_make(1, 0, 0));
    cg_vec3 iy = cg_mat4_transform_vector(iso, cg_vec3_make(0, 1, 0));
    double cosine = (ix.x * iy.x + ix.y * iy.y) / (hypot(ix.x, ix.y) * hypot(iy.x, iy.y));
    CHECK_NEAR(cosine, cos(2 * CG_PI / 3), 1e-14);
    cg_mat4 dim;
    CHECK_EQ_INT(cg_proj_dimetric(0.5, &dim), CG_OK);
    f = cg_proj_foreshortening(dim);
    CHECK_NEAR(f.x, f.y, 1e-14);
    CHECK_NEAR(f.z, 0.5 * f.x, 1e-14);
    CHECK_NEAR(f.x * f.x + f.y * f.y + f.z * f.z, 2, 1e-14);
    CHECK_EQ_INT(cg_proj_dimetric(0, &dim), CG_EINVAL);
    CHECK_EQ_INT(cg_proj_dimetric(NAN, &dim), CG_EINVAL);
    cg_mat4 tri = cg_proj_axonometric(0.3, 0.5);
    f = cg_proj_foreshortening(tri);
    CHECK(fabs(f.x - f.y) > 1e-3 && fabs(f.y - f.z) > 1e-3 && fabs(f.x - f.z) > 1e-3);

    /* Parallel projections keep parallel lines parallel. */
    cg_mat4 kinds[6] = {
        iso, dim, tri, cg_proj_cavalier(0.7), cg_proj_cabinet(1.1), cg_proj_oblique(2.0, 0.3)};
    check_rng rng = {5};
    for (int k = 0; k < 6; k++) {
        for (int n = 0; n < 500; n++) {
            cg_vec3 d = random_vec3(&rng, 1), a = random_vec3(&rng, 10), b = random_vec3(&rng, 10);
            cg_vec3 pa0 = cg_mat4_transform_point(kinds[k], a);
            cg_vec3 pa1 = cg_mat4_transform_point(kinds[k], cg_vec3_add(a, d));
            cg_vec3 pb0 = cg_mat4_transform_point(kinds[k], b);
            cg_vec3 pb1 = cg_mat4_transform_point(kinds[k], cg_vec3_add(b, cg_vec3_scale(d, 2.5)));
            double cross = (pa1.x - pa0.x) * (pb1.y - pb0.y) - (pa1.y - pa0.y) * (pb1.x - pb0.x);
            CHECK_NEAR(cross, 0, 1e-12);
        }
    }
}

static void test_perspective(void)
{
    cg_mat4 p;
    CHECK_EQ_INT(cg_proj_frustum(-2, 2, -1, 1, 1, 10, &p), CG_OK);
    /* Near-plane corners go to NDC corners at z = -1; far ones at z = +1. */
    check_vec3(cg_mat4_transform_point(p, cg_vec3_make(2, 1, -1)), 1, 1, -1, 1e-15, "near corner");
    check_vec3(cg_mat4_transform_point(p, cg_vec3_make(-20, -10, -10)), -1, -1, 1, 1e-14,
               "far corner");
    /* A unit cube 2 units in front of the camera, hand computed:
     * x_ndc = (2 near / (r - l)) x / -z = 0.5 x / -z, y_ndc = y / -z. */
    for (int i = 0; i < 8; i++) {
        cg_vec3 c = cg_vec3_add(corner(i), cg_vec3_make(-0.5, -0.5, -3));
        cg_vec3 ndc = cg_mat4_transform_point(p, c);
        CHECK_NEAR(ndc.x, 0.5 * c.x / -c.z, 1e-15);
        CHECK_NEAR(ndc.y, c.y / -c.z, 1e-15);
        CHECK_NEAR(ndc.z, (11.0 / 9 * c.z + 20.0 / 9) / c.z, 1e-14);
    }
    CHECK_EQ_INT(cg_proj_frustum(-1, 1, -1, 1, 0, 10, &p), CG_EINVAL);
    CHECK_EQ_INT(cg_proj_frustum(-1, 1, -1, 1, 5, 5, &p), CG_EINVAL);
    CHECK_EQ_INT(cg_proj_frustum(1, 1, -1, 1, 1, 5, &p), CG_EINVAL);
    CHECK_EQ_INT(cg_proj_perspective(0, 1, 1, 10, &p), CG_EINVAL);
    CHECK_EQ_INT(cg_proj_perspective(CG_PI, 1, 1, 10, &p), CG_EINVAL);
    CHECK_EQ_INT(cg_proj_perspective(1, NAN, 1, 10, &p), CG_EINVAL);
    CHECK_EQ_INT(cg_proj_orthographic(-1, 1, -1, 1, 1, 1, &p), CG_EINVAL);
    CHECK_EQ_INT(cg_proj_orthographic(-2, 2, -1, 1, 1, 3, &p), CG_OK);
    check_vec3(cg_mat4_transform_point(p, cg_vec3_make(2, -1, -3)), 1, -1, 1, 1e-15,
               "ortho corner");
}

/* The vanishing point of direction d: the image of the point at infinity. */
static int vanishing_point(cg_mat4 m, cg_vec3 d, cg_vec2 *out)
{
    cg_vec4 h = cg_mat4_mul_vec4(m, cg_vec4_make(d.x, d.y, d.z, 0));
    if (fabs(h.w) < 1e-12)
        return 0; /* the family stays parallel in the image */
    *out = cg_vec2_make(h.x / h.w, h.y / h.w);
    return 1;
}

static void test_vanishing_points(void)
{
    cg_mat4 proj, view;
    cg_proj_perspective(1.0, 1.0, 0.1, 1000, &proj);
    cg_vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    struct {
        cg_vec3 eye, target;
        int points;
    } setups[3] = {
        {{0.5, 0.5, 5}, {0.5, 0.5, 0}, 1}, /* facing the cube: one point */
        {{4, 0.5, 4}, {0, 0.5, 0}, 2},     /* turned, level: two points */
        {{4, 5, 4}, {0, 0, 0}, 3},         /* turned and tilted: three */
    };
    for (int s = 0; s < 3; s++) {
        CHECK_EQ_INT(cg_view_look_at(setups[s].eye, setups[s].target, cg_vec3_make(0, 1, 0), &view),
                     CG_OK);
        cg_mat4 m = cg_mat4_mul(proj, view);
        int finite = 0;
        for (int a = 0; a < 3; a++) {
            cg_vec2 vp;
            int has = vanishing_point(m, axes[a], &vp);
            finite += has;
            /* Every edge of the cube in this family heads to the same point:
             * project points far along each of the four parallel edges. */
            for (int e = 0; e < 4; e++) {
                cg_vec3 start = cg_vec3_make(0, 0, 0);
                int u = (a + 1) % 3, v = (a + 2) % 3;
                double *sc = &start.x;
                sc[u] = e & 1;
                sc[v] = (e >> 1) & 1;
                cg_vec3 near_point = cg_mat4_transform_point(m, start);
                /* Far along the edge, on whichever side stays in front of the
                 * camera: both ends of a line share its vanishing point. */
                cg_vec3 far_dir = cg_vec3_scale(axes[a], 1e7);
                cg_vec4 h = cg_mat4_mul_vec4(m, cg_vec4_from_point(cg_vec3_add(start, far_dir)));
                if (h.w <= 0)
                    h = cg_mat4_mul_vec4(m, cg_vec4_from_point(cg_vec3_sub(start, far_dir)));
                if (has) {
                    CHECK_MSG(fabs(h.x / h.w - vp.x) < 1e-5 && fabs(h.y / h.w - vp.y) < 1e-5,
                              "setup %d axis %d edge %d converges", s, a, e);
                } else {
                    /* No vanishing point: images of the edges are parallel to
                     * the image of the axis direction. */
                    cg_vec3 step = cg_mat4_transform_point(m, cg_vec3_add(start, axes[a]));
                    cg_vec3 d0 = cg_vec3_sub(step, near_point);
                    cg_vec3 ref0 = cg_mat4_transform_point(m, cg_vec3_make(0, 0, 0));
                    cg_vec3 ref1 = cg_mat4_transform_point(m, axes[a]);
                    cg_vec3 d1 = cg_vec3_sub(ref1, ref0);
                    CHECK_NEAR(d0.x * d1.y - d0.y * d1.x, 0, 1e-12);
                }
            }
        }
        CHECK_MSG(finite == setups[s].points, "setup %d: %d vanishing points, want %d", s, finite,
                  setups[s].points);
    }
    /* One-point perspective: the depth edges converge at the image of the
     * view direction, the centre of the image when looking through it. */
    cg_view_look_at(cg_vec3_make(0, 0, 5), cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &view);
    cg_vec2 centre = {NAN, NAN}; /* stays NaN, and fails, if no point is found */
    CHECK(vanishing_point(cg_mat4_mul(proj, view), cg_vec3_make(0, 0, -1), &centre));
    check_vec2(centre, 0, 0, 1e-15, "vanishing point at the centre");
}

static void test_camera_and_viewport(void)
{
    cg_mat4 vp = cg_viewport(640, 480);
    check_vec3(cg_mat4_transform_point(vp, cg_vec3_make(-1, 1, -1)), 0, 0, 0, 0, "top-left");
    check_vec3(cg_mat4_transform_point(vp, cg_vec3_make(1, -1, 1)), 640, 480, 1, 0, "bottom-right");
    check_vec3(cg_mat4_transform_point(vp, cg_vec3_make(0, 0, 0)), 320, 240, 0.5, 0, "centre");

    cg_mat4 view;
    cg_vec3 eye = {3, 4, 5}, target = {1, -2, 0.5};
    CHECK_EQ_INT(cg_view_look_at(eye, target, cg_vec3_make(0, 1, 0), &view), CG_OK);
    check_vec3(cg_mat4_transform_point(view, eye), 0, 0, 0, 1e-14, "eye to origin");
    cg_vec3 t = cg_mat4_transform_point(view, target);
    check_vec3(t, 0, 0, -cg_vec3_length(cg_vec3_sub(target, eye)), 1e-14, "target on -z");
    CHECK_EQ_INT(cg_view_look_at(eye, eye, cg_vec3_make(0, 1, 0), &view), CG_EINVAL);
    CHECK_EQ_INT(
        cg_view_look_at(cg_vec3_make(0, 0, 0), cg_vec3_make(0, 5, 0), cg_vec3_make(0, 1, 0), &view),
        CG_EINVAL);

    /* A primary ray through a pixel projects back onto that pixel. */
    check_rng rng = {3};
    for (int ortho = 0; ortho < 2; ortho++) {
        cg_camera cam = cg_camera_default();
        cam.eye = eye;
        cam.target = target;
        cam.orthographic = ortho;
        cam.ortho_height = 3;
        int w = 320, h = 200;
        cg_mat4 proj;
        CHECK_EQ_INT(cg_camera_view(&cam, &view), CG_OK);
        CHECK_EQ_INT(cg_camera_projection(&cam, (double)w / h, &proj), CG_OK);
        cg_mat4 all = cg_mat4_mul(cg_viewport(w, h), cg_mat4_mul(proj, view));
        for (int n = 0; n < 1000; n++) {
            double x = check_rng_range(&rng, 0, w), y = check_rng_range(&rng, 0, h);
            cg_vec3 o, d;
            CHECK_EQ_INT(cg_camera_ray(&cam, w, h, x, y, &o, &d), CG_OK);
            CHECK_NEAR(cg_vec3_length(d), 1, 1e-14);
            cg_vec3 p = cg_mat4_transform_point(
                all, cg_vec3_add(o, cg_vec3_scale(d, check_rng_range(&rng, 1, 8))));
            CHECK(fabs(p.x - x) < 1e-9 && fabs(p.y - y) < 1e-9);
        }
    }
    /* Framing puts the whole box inside the view. */
    cg_camera cam = cg_camera_default();
    cg_vec3 lo = {-10, 2, 30}, hi = {5, 40, 31};
    CHECK_EQ_INT(cg_camera_frame(&cam, lo, hi, 16.0 / 9), CG_OK);
    cg_mat4 proj;
    cg_camera_view(&cam, &view);
    cg_camera_projection(&cam, 16.0 / 9, &proj);
    for (int i = 0; i < 8; i++) {
        cg_vec3 c = cg_vec3_make(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        int visible;
        cg_vec3 ndc = cg_project_point(cg_mat4_mul(proj, view), c, &visible);
        CHECK(visible && fabs(ndc.x) <= 1 && fabs(ndc.y) <= 1 && fabs(ndc.z) <= 1);
    }
    CHECK_EQ_INT(cg_camera_frame(&cam, hi, lo, 1), CG_EINVAL);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_2d_known_points);
    CHECK_GROUP(test_2d_random_invariants);
    CHECK_GROUP(test_3d);
    CHECK_GROUP(test_parallel_projections);
    CHECK_GROUP(test_perspective);
    CHECK_GROUP(test_vanishing_points);
    CHECK_GROUP(test_camera_and_viewport);
    return check_finish();
}
