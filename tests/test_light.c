/* Tests of the illumination model (cg/light.h): each term against values
 * worked by hand, the model against its definition on random inputs, no
 * negative energy, back-facing lights, visibility, bad lights and materials. */
#include "check.h"
#include "cg/light.h"

#include <string.h>

#define EPS 1e-12

static void check_vec(cg_vec3 got, cg_vec3 want, double tol, const char *what)
{
    CHECK_MSG(fabs(got.x - want.x) <= tol && fabs(got.y - want.y) <= tol
                  && fabs(got.z - want.z) <= tol,
              "%s: got (%.17g, %.17g, %.17g), want (%.17g, %.17g, %.17g)", what, got.x, got.y,
              got.z, want.x, want.y, want.z);
}

static cg_vec3 v3(double x, double y, double z)
{
    return cg_vec3_make(x, y, z);
}

static void test_hand_worked(void)
{
    cg_vec3 origin = v3(0, 0, 0), up = v3(0, 0, 1);
    cg_material m = cg_material_make(v3(1, 0.5, 0.25), 0.2, 0.8, 0, 1);

    /* Ambient: ka Od Ia = 0.2 * (1, .5, .25) * (.5, .5, 1). */
    cg_light amb = cg_light_ambient(v3(0.5, 0.5, 1));
    cg_shade_terms t = cg_light_shade_terms(origin, up, up, &m, &amb, 1, NULL);
    check_vec(t.ambient, v3(0.1, 0.05, 0.05), EPS, "ambient");
    check_vec(t.diffuse, v3(0, 0, 0), 0, "ambient light has no diffuse term");
    check_vec(t.specular, v3(0, 0, 0), 0, "ambient light has no specular term");

    /* Diffuse from a point light straight above at distance 10 with
     * f = 1 / (1 + 0.01 * 100) = 0.5: kd Od f = 0.8 * 0.5 * (1, .5, .25). */
    cg_light point = cg_light_point(v3(0, 0, 10), v3(1, 1, 1));
    cg_light_set_attenuation(&point, 1, 0, 0.01);
    t = cg_light_shade_terms(origin, up, up, &m, &point, 1, NULL);
    check_vec(t.diffuse, v3(0.4, 0.2, 0.1), EPS, "diffuse, attenuated point light");
    check_vec(t.ambient, v3(0, 0, 0), 0, "point light has no ambient term");

    /* Linear attenuation: d = 10, c1 = 0.3: f = 1 / 4. */
    cg_light_set_attenuation(&point, 1, 0.3, 0);
    t = cg_light_shade_terms(origin, up, up, &m, &point, 1, NULL);
    check_vec(t.diffuse, v3(0.2, 0.1, 0.05), EPS, "diffuse, linear attenuation");
    /* f is clamped to 1: c0 = 0.25 alone would give 4. */
    cg_light_set_attenuation(&point, 0.25, 0, 0);
    t = cg_light_shade_terms(origin, up, up, &m, &point, 1, NULL);
    check_vec(t.diffuse, v3(0.8, 0.4, 0.2), EPS, "attenuation clamped to 1");

    /* Lambert: a directional light at 60 degrees from the normal, Il = 2:
     * kd Od Il cos 60 = 1 * 1 * 2 * 0.5. */
    cg_material white = cg_material_make(v3(1, 1, 1), 0, 1, 0, 1);
    double s60 = sqrt(3) / 2;
    cg_light sun = cg_light_directional(v3(-s60, 0, -0.5), v3(2, 2, 2));
    t = cg_light_shade_terms(origin, up, up, &white, &sun, 1, NULL);
    check_vec(t.diffuse, v3(1, 1, 1), 1e-12, "Lambert cos 60");
    /* The direction's length does not matter. */
    sun = cg_light_directional(v3(-5 * s60, 0, -2.5), v3(2, 2, 2));
    t = cg_light_shade_terms(origin, up, up, &white, &sun, 1, NULL);
    check_vec(t.diffuse, v3(1, 1, 1), 1e-12, "directional light normalized");

    /* Phong: L at 45 degrees in the xz plane, V = N: R = (-1, 0, 1)/sqrt2,
     * R.V = 1/sqrt2, n = 2: spec = 1/2; ks = 0.5 -> 0.25. */
    cg_material shiny = cg_material_make(v3(1, 1, 1), 0, 0, 0.5, 2);
    cg_light l45 = cg_light_directional(v3(-1, 0, -1), v3(1, 1, 1));
    t = cg_light_shade_terms(origin, up, up, &shiny, &l45, 1, NULL);
    check_vec(t.specular, v3(0.25, 0.25, 0.25), 1e-12, "Phong specular");
    check_vec(t.diffuse, v3(0, 0, 0), 0, "kd = 0: no diffuse");
    /* Viewer along R: R.V = 1, spec = ks. */
    t = cg_light_shade_terms(origin, up, cg_vec3_normalize(v3(-1, 0, 1)), &shiny, &l45, 1, NULL);
    check_vec(t.specular, v3(0.5, 0.5, 0.5), 1e-12, "Phong specular, mirror direction");
    /* Viewer on the same side as the light: R.V = 0 -> nothing. */
    t = cg_light_shade_terms(origin, up, cg_vec3_normalize(v3(1, 0, 1)), &shiny, &l45, 1, NULL);
    check_vec(t.specular, v3(0, 0, 0), 1e-12, "Phong specular, R perpendicular to V");

    /* Blinn-Phong: H bisects L (45 deg) and V = N, so N.H = cos 22.5 deg and
     * (N.H)^2 = (1 + cos 45) / 2. */
    shiny.specular = CG_SPECULAR_BLINN;
    t = cg_light_shade_terms(origin, up, up, &shiny, &l45, 1, NULL);
    double blinn = 0.5 * (1 + sqrt(0.5)) / 2;
    check_vec(t.specular, v3(blinn, blinn, blinn), 1e-12, "Blinn-Phong specular");
    /* Shininess 10: cos(22.5 deg)^10. */
    shiny.shininess = 10;
    t = cg_light_shade_terms(origin, up, up, &shiny, &l45, 1, NULL);
    double b10 = 0.5 * pow(cos(CG_PI / 8), 10);
    check_vec(t.specular, v3(b10, b10, b10), 1e-12, "Blinn-Phong, n = 10");

    /* Specular colour and light colour multiply per channel. */
    shiny.specular_color = v3(1, 0.5, 0);
    l45.color = v3(0.5, 1, 1);
    t = cg_light_shade_terms(origin, up, up, &shiny, &l45, 1, NULL);
    check_vec(t.specular, v3(b10 * 0.5, b10 * 0.5, 0), 1e-12, "specular colours");

    /* Spot light at (0,0,5) pointing down, cutoff 30 deg, exponent 2.
     * Point (1,0,0): -L.axis = 5/sqrt26 (11.3 deg, inside): spot factor
     * 25/26, N.L = 5/sqrt26. */
    cg_light spot = cg_light_spot(v3(0, 0, 5), v3(0, 0, -1), cg_radians(30), 2, v3(1, 1, 1));
    t = cg_light_shade_terms(v3(1, 0, 0), up, up, &white, &spot, 1, NULL);
    double want = 25.0 / 26.0 * 5 / sqrt(26);
    check_vec(t.diffuse, v3(want, want, want), 1e-12, "spot light inside the cone");
    /* Point (5,0,0): 45 deg, outside the cone. */
    t = cg_light_shade_terms(v3(5, 0, 0), up, up, &white, &spot, 1, NULL);
    check_vec(t.diffuse, v3(0, 0, 0), 0, "spot light outside the cone");
    /* Exponent 0: uniform inside the cone. */
    spot.spot_exponent = 0;
    t = cg_light_shade_terms(v3(1, 0, 0), up, up, &white, &spot, 1, NULL);
    want = 5 / sqrt(26);
    check_vec(t.diffuse, v3(want, want, want), 1e-12, "spot light, exponent 0");

    /* The total is the sum of the terms and of the lights. */
    cg_light all[4] = {amb, point, sun, spot};
    cg_material mix = cg_material_make(v3(0.9, 0.6, 0.3), 0.3, 0.7, 0.4, 12);
    cg_vec3 p = v3(0.5, 0.25, 0), n = up, v = cg_vec3_normalize(v3(0.2, 0.1, 1));
    cg_vec3 total = cg_light_shade(p, n, v, &mix, all, 4);
    cg_vec3 sum = v3(0, 0, 0);
    for (int i = 0; i < 4; i++)
        sum = cg_vec3_add(sum, cg_light_shade(p, n, v, &mix, &all[i], 1));
    check_vec(total, sum, 1e-12, "sum over lights");
    check_vec(total, cg_shade_terms_sum(cg_light_shade_terms(p, n, v, &mix, all, 4, NULL)), 0,
              "shade equals the sum of the terms");
}

static void test_back_facing(void)
{
    cg_vec3 origin = v3(0, 0, 0), up = v3(0, 0, 1);
    cg_material m = cg_material_make(v3(1, 1, 1), 0.1, 0.8, 0.9, 1);
    cg_light lights[3] = {
        cg_light_point(v3(0.3, 0.1, -2), v3(5, 5, 5)),
        cg_light_directional(v3(0.1, 0.2, 1), v3(5, 5, 5)),
        cg_light_spot(v3(0, 0, -3), v3(0, 0, 1), 1.0, 1, v3(5, 5, 5)),
    };
    /* Viewers on both sides: whatever the viewer, a light behind the surface
     * adds no diffuse and no specular light (even if R.V or N.H > 0). */
    cg_vec3 views[3] = {up, v3(0, 0, -1), cg_vec3_normalize(v3(1, 0, -0.1))};
    for (int model = 0; model < 2; model++) {
        m.specular = (cg_specular_model)model;
        for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++) {
                cg_shade_terms t = cg_light_shade_terms(origin, up, views[k], &m, &lights[i], 1,
                                                        NULL);
                check_vec(cg_shade_terms_sum(t), v3(0, 0, 0), 0, "back-facing light");
            }
    }
    /* Grazing: N.L = 0 exactly. */
    cg_light graze = cg_light_directional(v3(1, 0, 0), v3(1, 1, 1));
    check_vec(cg_light_shade(origin, up, up, &m, &graze, 1), v3(0, 0, 0), 0, "grazing light");
    /* face_forward flips a normal facing away from the viewer. */
    cg_vec3 f = cg_light_face_forward(v3(0, 0, -1), up);
    check_vec(f, up, 0, "face forward flips");
    f = cg_light_face_forward(up, up);
    check_vec(f, up, 0, "face forward keeps");
}

static cg_vec3 random_unit(check_rng *r)
{
    for (;;) {
        cg_vec3 v = v3(check_rng_range(r, -1, 1), check_rng_range(r, -1, 1),
                       check_rng_range(r, -1, 1));
        double l = cg_vec3_length(v);
        if (l > 0.1 && l <= 1)
            return cg_vec3_scale(v, 1 / l);
    }
}

static cg_vec3 random_color(check_rng *r, double max)
{
    return v3(check_rng_range(r, 0, max), check_rng_range(r, 0, max), check_rng_range(r, 0, max));
}

/* The model computed straight from its definition, for one non-ambient light. */
static cg_vec3 reference(cg_vec3 p, cg_vec3 n, cg_vec3 v, const cg_material *m, const cg_light *l)
{
    cg_vec3 L;
    double f = 1, spot = 1;
    if (l->kind == CG_LIGHT_DIRECTIONAL) {
        L = cg_vec3_scale(l->direction, -1);
    } else {
        cg_vec3 d = cg_vec3_sub(l->position, p);
        double dist = cg_vec3_length(d);
        L = cg_vec3_scale(d, 1 / dist);
        double denom = l->attenuation[0] + l->attenuation[1] * dist
                       + l->attenuation[2] * dist * dist;
        f = denom > 0 ? fmin(1, 1 / denom) : 1;
        if (l->kind == CG_LIGHT_SPOT) {
            double c = -cg_vec3_dot(L, l->direction);
            spot = c >= l->spot_cos_cutoff ? pow(fmax(c, 0), l->spot_exponent) : 0;
        }
    }
    double nl = cg_vec3_dot(n, L);
    if (nl <= 0)
        return v3(0, 0, 0);
    double spec;
    if (m->specular == CG_SPECULAR_PHONG) {
        cg_vec3 R = cg_vec3_sub(cg_vec3_scale(n, 2 * nl), L);
        spec = pow(fmax(cg_vec3_dot(R, v), 0), m->shininess);
    } else {
        cg_vec3 H = cg_vec3_normalize(cg_vec3_add(L, v));
        spec = pow(fmax(cg_vec3_dot(n, H), 0), m->shininess);
    }
    cg_vec3 diffuse = cg_vec3_scale(m->color, m->kd * nl);
    cg_vec3 specular = cg_vec3_scale(m->specular_color, m->ks * spec);
    return cg_vec3_scale(cg_vec3_mul(l->color, cg_vec3_add(diffuse, specular)), f * spot);
}

static void test_random(void)
{
    check_rng r = {0x1234567887654321ULL};
    int negative = 0, mismatch = 0;
    for (int iter = 0; iter < 20000; iter++) {
        cg_material m = cg_material_make(random_color(&r, 1), check_rng_unit(&r),
                                         check_rng_unit(&r), check_rng_unit(&r),
                                         check_rng_range(&r, 0.5, 200));
        m.specular_color = random_color(&r, 1);
        m.specular = (cg_specular_model)(iter & 1);
        cg_vec3 p = v3(check_rng_range(&r, -5, 5), check_rng_range(&r, -5, 5),
                       check_rng_range(&r, -5, 5));
        cg_vec3 n = random_unit(&r), v = random_unit(&r);
        cg_light l;
        int kind = (int)check_rng_int(&r, 1, 3);
        cg_vec3 where = v3(check_rng_range(&r, -10, 10), check_rng_range(&r, -10, 10),
                           check_rng_range(&r, -10, 10));
        if (kind == 1)
            l = cg_light_point(where, random_color(&r, 3));
        else if (kind == 2)
            l = cg_light_directional(random_unit(&r), random_color(&r, 3));
        else
            l = cg_light_spot(where, random_unit(&r), check_rng_range(&r, 0.1, 3.1),
                              check_rng_range(&r, 0, 20), random_color(&r, 3));
        if (kind != 2)
            cg_light_set_attenuation(&l, check_rng_range(&r, 0, 1), check_rng_range(&r, 0, 0.5),
                                     check_rng_range(&r, 0, 0.1));
        CHECK(cg_light_check(&l, NULL) == CG_OK);
        CHECK(cg_material_check(&m, NULL) == CG_OK);
        cg_vec3 got = cg_light_shade(p, n, v, &m, &l, 1);
        cg_vec3 want = reference(p, n, v, &m, &l);
        double tol = 1e-9 * (1 + fabs(want.x) + fabs(want.y) + fabs(want.z));
        if (fabs(got.x - want.x) > tol || fabs(got.y - want.y) > tol
            || fabs(got.z - want.z) > tol) {
            if (mismatch++ < 5)
                fprintf(stderr, "iter %d kind %d: got (%g %g %g) want (%g %g %g)\n", iter, kind,
                        got.x, got.y, got.z, want.x, want.y, want.z);
        }
        if (!(got.x >= 0 && got.y >= 0 && got.z >= 0))
            negative++;
        /* Visibility scales the light linearly. */
        double vis = check_rng_unit(&r);
        cg_vec3 half = cg_shade_terms_sum(cg_light_shade_terms(p, n, v, &m, &l, 1, &vis));
        if (fabs(half.x - vis * got.x) > tol || fabs(half.z - vis * got.z) > tol)
            mismatch++;
    }
    CHECK_EQ_INT(mismatch, 0);
    CHECK_EQ_INT(negative, 0);
}

static void test_visibility(void)
{
    cg_vec3 origin = v3(0, 0, 0), up = v3(0, 0, 1);
    cg_material m = cg_material_make(v3(1, 1, 1), 0.5, 0.5, 0.5, 4);
    cg_light ls[2] = {cg_light_ambient(v3(1, 1, 1)), cg_light_point(v3(0, 0, 1), v3(1, 1, 1))};
    double vis[2] = {0, 0};
    cg_shade_terms t = cg_light_shade_terms(origin, up, up, &m, ls, 2, vis);
    check_vec(t.ambient, v3(0.5, 0.5, 0.5), EPS, "ambient ignores visibility");
    check_vec(cg_vec3_add(t.diffuse, t.specular), v3(0, 0, 0), 0, "shadowed light");
    vis[1] = 1;
    t = cg_light_shade_terms(origin, up, up, &m, ls, 2, vis);
    check_vec(t.diffuse, v3(0.5, 0.5, 0.5), EPS, "visible light");
    check_vec(t.specular, v3(0.5, 0.5, 0.5), EPS, "visible light specular");
    /* A point at the light's position gets nothing from it (no direction). */
    t = cg_light_shade_terms(v3(0, 0, 1), up, up, &m, ls, 2, NULL);
    check_vec(cg_vec3_add(t.diffuse, t.specular), v3(0, 0, 0), 0, "point at the light");
}

static void test_vector(void)
{
    cg_vec3 dir;
    double dist;
    cg_light a = cg_light_ambient(v3(1, 1, 1));
    CHECK(cg_light_vector(&a, v3(0, 0, 0), &dir, &dist) == 0);
    cg_light p = cg_light_point(v3(3, 4, 0), v3(1, 1, 1));
    CHECK(cg_light_vector(&p, v3(0, 0, 0), &dir, &dist) == 1);
    CHECK_NEAR(dist, 5, EPS);
    check_vec(dir, v3(0.6, 0.8, 0), EPS, "to point light");
    CHECK(cg_light_vector(&p, v3(3, 4, 0), &dir, &dist) == 0);
    cg_light d = cg_light_directional(v3(0, -2, 0), v3(1, 1, 1));
    CHECK(cg_light_vector(&d, v3(7, 7, 7), &dir, &dist) == 1);
    CHECK(isinf(dist));
    check_vec(dir, v3(0, 1, 0), EPS, "to directional light");
}

static void test_checks(void)
{
    cg_error err;
    cg_light l = cg_light_point(v3(0, 0, 0), v3(1, 1, 1));
    CHECK(cg_light_check(&l, &err) == CG_OK);
    l.color.y = NAN;
    CHECK(cg_light_check(&l, &err) == CG_EINVAL);
    CHECK(strstr(err.message, "colour") != NULL);
    l.color.y = -1;
    CHECK(cg_light_check(&l, &err) == CG_EINVAL);
    l = cg_light_point(v3(0, INFINITY, 0), v3(1, 1, 1));
    CHECK(cg_light_check(&l, &err) == CG_EINVAL);
    CHECK(strstr(err.message, "position") != NULL);
    l = cg_light_point(v3(0, 0, 0), v3(1, 1, 1));
    cg_light_set_attenuation(&l, 0, 0, 0);
    CHECK(cg_light_check(&l, &err) == CG_EINVAL);
    cg_light_set_attenuation(&l, 1, -0.5, 0);
    CHECK(cg_light_check(&l, &err) == CG_EINVAL);
    CHECK(strstr(err.message, "c1") != NULL);
    l = cg_light_directional(v3(0, 0, 0), v3(1, 1, 1)); /* zero direction */
    CHECK(cg_light_check(&l, &err) == CG_EINVAL);
    CHECK(strstr(err.message, "direction") != NULL);
    l = cg_light_spot(v3(0, 0, 0), v3(0, 1, 0), 0.5, -1, v3(1, 1, 1));
    CHECK(cg_light_check(&l, &err) == CG_EINVAL);
    l = cg_light_spot(v3(0, 0, 0), v3(0, 1, 0), 0.5, 3, v3(1, 1, 1));
    CHECK(cg_light_check(&l, &err) == CG_OK);
    l.kind = (cg_light_kind)17;
    CHECK(cg_light_check(&l, &err) == CG_EINVAL);
    CHECK(cg_light_check(NULL, NULL) == CG_EINVAL);

    cg_material m = cg_material_make(v3(1, 1, 1), 0.1, 0.5, 0.5, 10);
    CHECK(cg_material_check(&m, &err) == CG_OK);
    m.ks = -0.1;
    CHECK(cg_material_check(&m, &err) == CG_EINVAL);
    CHECK(strstr(err.message, "ks") != NULL);
    m.ks = 0.5;
    m.shininess = NAN;
    CHECK(cg_material_check(&m, &err) == CG_EINVAL);
    CHECK(strstr(err.message, "shininess") != NULL);
    m.shininess = 10;
    m.specular = (cg_specular_model)5;
    CHECK(cg_material_check(&m, &err) == CG_EINVAL);
    CHECK(cg_material_check(NULL, NULL) == CG_EINVAL);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_hand_worked);
    CHECK_GROUP(test_back_facing);
    CHECK_GROUP(test_random);
    CHECK_GROUP(test_visibility);
    CHECK_GROUP(test_vector);
    CHECK_GROUP(test_checks);
    return check_finish();
}
