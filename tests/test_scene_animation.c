/* Scene keyframes (cg_scene_set_frame) against their definition: on random
 * keys, linear tracks equal k_i + t (k_{i+1} - k_i) and Catmull-Rom tracks
 * the spline 1/2 [t^3 t^2 t 1] M_CR [p_{i-1} p_i p_{i+1} p_{i+2}] written
 * out here term by term (end keys standing in for missing neighbours), and
 * both pass through every key and hold before the first and after the last;
 * an object's world matrix is T Rz Ry Rx S times the file's transform
 * (checked on points); a light's colour is the file's times the intensity;
 * poses do not accumulate; keys in any order; bad input names its path. */
#include "cg/scene.h"
#include "check.h"

static uint64_t state = 0x6a09e667f3bcc909ull;
static double uniform01(void)
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return (double)(state >> 11) / 9007199254740992.0;
}

static cg_scene *parse(const char *text, cg_error *err)
{
    cg_scene *s = NULL;
    cg_scene_parse(text, strlen(text), "anim.json", NULL, 0, &s, err);
    return s;
}

static const char *head =
    "{\"camera\": {\"eye\": [0, 1, 5], \"target\": [0, 0, 0]},"
    "\"lights\": [{\"type\": \"ambient\", \"intensity\": 0.5},"
    "{\"type\": \"area\", \"corner\": [0, 4, 0], \"edge_u\": [1, 0, 0],"
    " \"edge_v\": [0, 0, 1], \"color\": [1, 0.5, 0.25]},"
    "{\"type\": \"point\", \"position\": [0, 3, 0], \"color\": [0.2, 0.4, 0.8]}],"
    "\"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1},"
    "{\"type\": \"box\", \"lo\": [0, 0, 0], \"hi\": [1, 1, 1],"
    " \"transform\": [{\"translate\": [1, 2, 3]}]}],";

/* Linear and Catmull-Rom eye tracks through random keys, checked at random
 * frames against the formulas written out independently. */
static void eye_tracks(void)
{
    for (int trial = 0; trial < 200; trial++) {
        int n = 1 + (int)(uniform01() * 6), catmull = trial % 2;
        double frames[8], values[8][3], f = 0;
        char text[4096];
        int at = snprintf(text, sizeof text,
                          "%s\"animation\": {\"interpolation\": \"%s\", \"keys\": [", head,
                          catmull ? "catmull-rom" : "linear");
        for (int k = 0; k < n; k++) {
            f += 1 + (int)(uniform01() * 10);
            frames[k] = f;
            for (int c = 0; c < 3; c++)
                values[k][c] = (double)(int)(uniform01() * 200 - 100) / 8;
        }
        /* the keys written in reverse: order in the file does not matter */
        for (int k = n - 1; k >= 0; k--)
            at += snprintf(text + at, sizeof text - (size_t)at,
                           "%s{\"frame\": %g, \"camera\": {\"eye\": [%g, %g, %g]}}",
                           k == n - 1 ? "" : ",", frames[k], values[k][0], values[k][1],
                           values[k][2]);
        snprintf(text + at, sizeof text - (size_t)at, "]}}");
        cg_error err;
        cg_scene *s = parse(text, &err);
        CHECK_MSG(s != NULL, "trial %d: %s", trial, s ? "" : err.message);
        if (!s)
            continue;
        CHECK_EQ_INT(s->frame_count, (int)frames[n - 1] + 1);
        for (int probe = 0; probe < 40; probe++) {
            double x = probe < n ? frames[probe] : uniform01() * (f + 4) - 2;
            double want[3];
            if (x <= frames[0] || n == 1) {
                memcpy(want, values[0], sizeof want);
            } else if (x >= frames[n - 1]) {
                memcpy(want, values[n - 1], sizeof want);
            } else {
                int i = 0;
                while (!(x >= frames[i] && x < frames[i + 1]))
                    i++;
                double t = (x - frames[i]) / (frames[i + 1] - frames[i]);
                for (int c = 0; c < 3; c++) {
                    double p1 = values[i][c], p2 = values[i + 1][c];
                    double p0 = i > 0 ? values[i - 1][c] : p1;
                    double p3 = i + 2 < n ? values[i + 2][c] : p2;
                    want[c] = catmull ? 0.5
                                            * (2 * p1 + (p2 - p0) * t
                                               + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t * t
                                               + (3 * p1 - p0 - 3 * p2 + p3) * t * t * t)
                                      : p1 + t * (p2 - p1);
                }
            }
            CHECK_EQ_INT(cg_scene_set_frame(s, x), CG_OK);
            cg_vec3 e = s->camera.eye;
            CHECK_MSG(fabs(e.x - want[0]) < 1e-9 && fabs(e.y - want[1]) < 1e-9
                          && fabs(e.z - want[2]) < 1e-9,
                      "trial %d frame %g: eye (%g %g %g), want (%g %g %g)", trial, x, e.x, e.y, e.z,
                      want[0], want[1], want[2]);
            /* not animated: kept */
            CHECK(s->camera.target.x == 0 && s->camera.target.y == 0 && s->camera.target.z == 0);
        }
        cg_scene_free(s);
    }
}

static cg_vec3 apply(cg_mat4 m, cg_vec3 p)
{
    double in[4] = {p.x, p.y, p.z, 1}, out[3];
    for (int r = 0; r < 3; r++)
        out[r] = m.m[r][0] * in[0] + m.m[r][1] * in[1] + m.m[r][2] * in[2] + m.m[r][3] * in[3];
    return cg_vec3_make(out[0], out[1], out[2]);
}

/* Object placements and light intensities, and poses that do not accumulate. */
static void objects_and_lights(void)
{
    char text[4096];
    snprintf(
        text, sizeof text,
        "%s\"animation\": {\"frames\": 11, \"keys\": ["
        "{\"frame\": 0, \"objects\": [{\"object\": 1, \"translate\": [0, 0, 0],"
        " \"rotate\": [0, 0, 0], \"scale\": 1}],"
        " \"lights\": [{\"light\": 1, \"intensity\": 0}, {\"light\": 2, \"intensity\": 1}]},"
        "{\"frame\": 10, \"objects\": [{\"object\": 1, \"translate\": [10, 0, -20],"
        " \"rotate\": [90, 180, 270], \"scale\": [2, 4, 6]}],"
        " \"lights\": [{\"light\": 1, \"intensity\": 2}, {\"light\": 2, \"intensity\": 3}]}]}}",
        head);
    cg_error err;
    cg_scene *s = parse(text, &err);
    CHECK_MSG(s != NULL, "%s", s ? "" : err.message);
    if (!s)
        return;
    CHECK_EQ_INT(s->frame_count, 11);
    for (int pass = 0; pass < 3; pass++)
        for (int f = 10; f >= 0; f -= 1) {
            double t = f / 10.0;
            CHECK_EQ_INT(cg_scene_set_frame(s, f), CG_OK);
            /* the sphere is not animated */
            cg_vec3 q = apply(s->objects[0].transform, cg_vec3_make(1, 2, 3));
            CHECK(q.x == 1 && q.y == 2 && q.z == 3);
            /* the box: S, then Rx, Ry, Rz (degrees), then T, after its own (1, 2, 3) */
            double rx = cg_radians(90 * t), ry = cg_radians(180 * t), rz = cg_radians(270 * t);
            for (int k = 0; k < 8; k++) {
                cg_vec3 p = {k & 1, k >> 1 & 1, k >> 2 & 1};
                double x = p.x + 1, y = p.y + 2, z = p.z + 3;
                x *= 1 + t, y *= 1 + 3 * t, z *= 1 + 5 * t;
                double y1 = y * cos(rx) - z * sin(rx), z1 = y * sin(rx) + z * cos(rx);
                double x2 = x * cos(ry) + z1 * sin(ry), z2 = -x * sin(ry) + z1 * cos(ry);
                double x3 = x2 * cos(rz) - y1 * sin(rz), y3 = x2 * sin(rz) + y1 * cos(rz);
                cg_vec3 want = {x3 + 10 * t, y3, z2 - 20 * t};
                cg_vec3 got = apply(s->objects[1].transform, p);
                CHECK_MSG(fabs(got.x - want.x) < 1e-9 && fabs(got.y - want.y) < 1e-9
                              && fabs(got.z - want.z) < 1e-9,
                          "frame %d corner %d: (%g %g %g), want (%g %g %g)", f, k, got.x, got.y,
                          got.z, want.x, want.y, want.z);
            }
            /* light 1 of the file is the area light, light 2 the point light */
            cg_vec3 area = s->area_lights[0].color, point = s->lights[1].color;
            CHECK(fabs(area.x - 2 * t) < 1e-12 && fabs(area.y - t) < 1e-12
                  && fabs(area.z - 0.5 * t) < 1e-12);
            CHECK(fabs(point.x - 0.2 * (1 + 2 * t)) < 1e-12
                  && fabs(point.z - 0.8 * (1 + 2 * t)) < 1e-12);
            /* the ambient light is not animated */
            CHECK(s->lights[0].color.x == 0.5);
        }
    CHECK_EQ_INT(cg_scene_set_frame(s, NAN), CG_EINVAL);
    CHECK_EQ_INT(cg_scene_set_frame(NULL, 0), CG_EINVAL);
    cg_scene_free(s);
    /* a still scene: nothing to pose */
    snprintf(text, sizeof text, "%s\"render\": {}}", head);
    s = parse(text, &err);
    CHECK(s && s->animation == NULL && s->frame_count == 0);
    if (s) {
        cg_vec3 eye = s->camera.eye;
        CHECK_EQ_INT(cg_scene_set_frame(s, 3), CG_OK);
        CHECK(s->camera.eye.x == eye.x && s->camera.eye.z == eye.z);
    }
    cg_scene_free(s);
}

/* Each bad animation is refused with its JSON path. */
static void bad_input(void)
{
    static const struct {
        const char *animation, *message;
    } cases[] = {
        {"[]", "animation: expected an object"},
        {"{}", "animation.keys: expected an array of one key or more"},
        {"{\"keys\": []}", "animation.keys: expected an array of one key or more"},
        {"{\"keys\": [{}]}", "animation.keys[0]: needs \"frame\""},
        {"{\"keys\": [{\"frame\": -1}]}", "animation.keys[0].frame"},
        {"{\"keys\": [{\"frame\": 0, \"camera\": {\"eye\": [1, 2]}}]}",
         "animation.keys[0].camera.eye"},
        {"{\"keys\": [{\"frame\": 0, \"camera\": {\"zoom\": 2}}]}", "zoom"},
        {"{\"keys\": [{\"frame\": 0, \"objects\": [{\"object\": 2, \"scale\": 1}]}]}",
         "animation.keys[0].objects[0].object"},
        {"{\"keys\": [{\"frame\": 0, \"objects\": [{\"scale\": 1}]}]}",
         "animation.keys[0].objects[0]: needs \"object\""},
        {"{\"keys\": [{\"frame\": 0, \"lights\": [{\"light\": 3, \"intensity\": 1}]}]}",
         "animation.keys[0].lights[0].light"},
        {"{\"keys\": [{\"frame\": 0, \"lights\": [{\"light\": 0, \"intensity\": -1}]}]}",
         "animation.keys[0].lights[0].intensity"},
        {"{\"keys\": [{\"frame\": 2, \"camera\": {\"fov\": 30}}, {\"frame\": 2, \"camera\": "
         "{\"fov\": 40}}]}",
         "two keys give the same value at frame 2"},
        {"{\"interpolation\": \"cubic\", \"keys\": [{\"frame\": 0}]}", "animation.interpolation"},
        {"{\"frames\": 0, \"keys\": [{\"frame\": 0}]}", "animation.frames"},
        {"{\"speed\": 2, \"keys\": [{\"frame\": 0}]}", "speed"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        char text[4096];
        snprintf(text, sizeof text, "%s\"animation\": %s}", head, cases[i].animation);
        cg_error err = {0};
        cg_scene *s = parse(text, &err);
        CHECK_MSG(s == NULL && strstr(err.message, cases[i].message) != NULL,
                  "case %zu: got '%s', want '%s'", i, s ? "(accepted)" : err.message,
                  cases[i].message);
        cg_scene_free(s);
    }
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(eye_tracks);
    CHECK_GROUP(objects_and_lights);
    CHECK_GROUP(bad_input);
    return check_finish();
}
