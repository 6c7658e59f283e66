/* A scene's materials mean the same under the z-buffer, the painter's
 * algorithm and the ray tracer.
 *
 * Checker: random scenes of a checkered plane, box and sphere (random cell
 * sizes, plane tilts, object transforms (mirrors among them, with back faces
 * culled) and cameras; the objects apart, since the painter's algorithm only
 * approximates interpenetrating polygons) lit by an ambient light
 * only, so every pixel is exactly one of the two checker colours or the
 * background.  Each pixel is classified in the three pictures; wherever the
 * ray tracer's 5x5 neighbourhood is all one class (two pixels away from cell
 * boundaries and silhouettes, where the tessellated sphere, grazing rays and
 * pixel snapping may differ) and the rasterizers drew a surface (their plane is a
 * large square, not infinite), they must give the same class.
 *
 * Surface terms: boxes of different materials (ka, kd, ks, shininess) under
 * directional lights without shadows: inside their faces the rasterizers'
 * colours are the ray tracer's within two codes.
 *
 * Refusals: mirrors, glass, Phong highlights and coloured highlights are
 * refused by the rasterizers with a message naming the material's key. */
#include "check.h"
#include "cg/scene.h"

#include <string.h>

#define W 128
#define H 96

static cg_scene *parse(const char *json)
{
    cg_scene *s = NULL;
    cg_error err;
    if (cg_scene_parse(json, strlen(json), "t.json", NULL, 0, &s, &err) != CG_OK) {
        fprintf(stderr, "scene: %s\n", err.message);
        return NULL;
    }
    return s;
}

static cg_image *render(const cg_scene *s, cg_scene_algorithm a)
{
    cg_image *image = NULL;
    cg_error err;
    if (cg_scene_render_with(s, a, &image, &err) != CG_OK) {
        fprintf(stderr, "render: %s\n", err.message);
        return NULL;
    }
    return image;
}

static const unsigned char *pixel(const cg_image *im, int x, int y)
{
    return im->data + (size_t)y * im->stride + 4 * (size_t)x;
}

/* 0 background, 1 the first colour (red-ish), 2 the checker colour (blue),
 * 3 anything else. */
static int classify(const unsigned char *p)
{
    if (p[0] < 8 && p[1] < 8 && p[2] < 8)
        return 0;
    if (p[0] > 150 && p[2] < 90)
        return 1;
    if (p[2] > 150 && p[0] < 90)
        return 2;
    return 3;
}

static int uniform(const cg_image *im, int x, int y)
{
    int c = classify(pixel(im, x, y));
    for (int dy = -2; dy <= 2; dy++)
        for (int dx = -2; dx <= 2; dx++) {
            int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= im->width || v >= im->height
                || classify(pixel(im, u, v)) != c)
                return 0;
        }
    return 1;
}

static void checker_scenes(void)
{
    check_rng rng = {0x5eedc4ec4e5ULL};
    long compared = 0, checked_both = 0;
    for (int trial = 0; trial < 24; trial++) {
        double size = check_rng_range(&rng, 0.25, 0.8);
        double tilt = check_rng_range(&rng, -0.15, 0.15), angle = check_rng_range(&rng, -60, 60);
        double ex = check_rng_range(&rng, -1.5, 1.5), ez = check_rng_range(&rng, 1.5, 3);
        double ey = check_rng_range(&rng, 4, 6);
        int ortho = trial % 3 == 2;
        char json[2048];
        snprintf(
            json, sizeof json,
            "{\"image\": {\"width\": %d, \"height\": %d, \"background\": [0, 0, 0]},"
            " \"camera\": {\"eye\": [%.3f, %.3f, %.3f], \"target\": [0.4, 0.4, 0],"
            " \"projection\": \"%s\", \"frame\": true},"
            " \"render\": {\"shading\": \"flat\", \"shadows\": false, \"depth\": 0, \"cull\": "
            "\"back\"},"
            " \"lights\": [{\"type\": \"ambient\", \"intensity\": 1}],"
            " \"materials\": {\"c\": {\"color\": [0.9, 0.02, 0.02], \"ka\": 1, \"kd\": 0,"
            " \"ks\": 0, \"checker\": {\"color\": [0.02, 0.02, 0.9], \"size\": %.4f}}},"
            " \"objects\": [{\"type\": \"plane\", \"point\": [0, -0.5, 0],"
            " \"normal\": [%.3f, 1, %.3f], \"material\": \"c\"},"
            " {\"type\": \"box\", \"lo\": [-1, 0, -0.5], \"hi\": [0, 1, 0.4], \"material\": \"c\","
            " \"transform\": [{\"rotate\": %.2f, \"axis\": [0, 1, 0]}%s]},"
            " {\"type\": \"sphere\", \"center\": [1.9, 0.6, 0.3], \"radius\": 0.5, \"material\": "
            "\"c\"}]}",
            W, H, ex, ey, ez, ortho ? "orthographic" : "perspective", size, tilt, -tilt, angle,
            trial % 2 ? ", {\"scale\": [-1, 1, 1]}" : "");
        cg_scene *s = parse(json);
        CHECK(s != NULL);
        if (!s)
            continue;
        cg_image *traced = render(s, CG_SCENE_RAYTRACE);
        cg_image *zbuffer = render(s, CG_SCENE_ZBUFFER);
        cg_image *painter = render(s, CG_SCENE_PAINTER);
        CHECK(traced && zbuffer && painter);
        if (traced && zbuffer && painter) {
            long count[4] = {0, 0, 0, 0}, wrong_z = 0, wrong_p = 0, interior = 0, beyond = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    int c = classify(pixel(traced, x, y));
                    count[c]++;
                    if (!uniform(traced, x, y))
                        continue;
                    /* The rasterizers draw a plane as a large square: beyond
                     * it they show the background where the ray tracer's
                     * plane goes on; compare where both drew a surface. */
                    int z = classify(pixel(zbuffer, x, y)), p = classify(pixel(painter, x, y));
                    if (c != 0 && (z == 0 || p == 0)) {
                        beyond++;
                        continue;
                    }
                    interior++;
                    wrong_z += z != c;
                    wrong_p += p != c;
                }
            CHECK_MSG(count[3] == 0, "trial %d: %ld ray-traced pixels of neither colour", trial,
                      count[3]);
            CHECK_MSG(wrong_z == 0 && wrong_p == 0,
                      "trial %d: %ld (z-buffer) and %ld (painter) of %ld interior pixels show "
                      "another cell than the ray tracer",
                      trial, wrong_z, wrong_p, interior);
            CHECK_MSG(beyond < interior / 4, "trial %d: %ld pixels beyond the rasterized plane",
                      trial, beyond);
            /* Both colours in sizeable areas: the test sees a pattern. */
            if (count[1] > W * H / 20 && count[2] > W * H / 20)
                checked_both++;
            compared += interior;
        }
        cg_image_free(traced);
        cg_image_free(zbuffer);
        cg_image_free(painter);
        cg_scene_free(s);
    }
    CHECK_MSG(checked_both >= 20, "only %ld scenes showed both checker colours", checked_both);
    CHECK_MSG(compared > 24L * W * H / 5, "only %ld interior pixels compared", compared);
}

/* Boxes of three materials under two directional lights, no shadows. */
static void surface_terms(void)
{
    check_rng rng = {0xb0c5ULL};
    for (int trial = 0; trial < 12; trial++) {
        char materials[3][200];
        for (int m = 0; m < 3; m++)
            snprintf(materials[m], sizeof materials[m],
                     "\"m%d\": {\"color\": [%.2f, %.2f, %.2f], \"ka\": %.2f, \"kd\": %.2f, "
                     "\"ks\": %.2f, \"shininess\": %.0f}",
                     m, check_rng_range(&rng, 0.2, 1), check_rng_range(&rng, 0.2, 1),
                     check_rng_range(&rng, 0.2, 1), check_rng_range(&rng, 0, 0.5),
                     check_rng_range(&rng, 0.1, 1), check_rng_range(&rng, 0, 0.8),
                     check_rng_range(&rng, 2, 80));
        char json[2048];
        snprintf(
            json, sizeof json,
            "{\"image\": {\"width\": %d, \"height\": %d},"
            " \"camera\": {\"eye\": [%.2f, 2.5, 4], \"target\": [0, 0, 0], \"frame\": true},"
            " \"render\": {\"shading\": \"phong\", \"shadows\": false, \"depth\": 0},"
            " \"lights\": [{\"type\": \"ambient\", \"intensity\": 0.4},"
            " {\"type\": \"directional\", \"direction\": [-0.4, -1, -0.5]},"
            " {\"type\": \"directional\", \"direction\": [0.8, -0.3, -0.6], \"intensity\": 0.5}],"
            " \"materials\": {%s, %s, %s},"
            " \"objects\": [{\"type\": \"box\", \"lo\": [-2, -0.5, -0.5], \"hi\": [-0.8, 0.5, "
            "0.5], \"material\": \"m0\"},"
            " {\"type\": \"box\", \"lo\": [-0.6, -0.5, -0.5], \"hi\": [0.6, 0.5, 0.5], "
            "\"material\": \"m1\"},"
            " {\"type\": \"box\", \"lo\": [0.8, -0.5, -0.5], \"hi\": [2, 0.5, 0.5], \"material\": "
            "\"m2\"}]}",
            W, H, check_rng_range(&rng, -2, 2), materials[0], materials[1], materials[2]);
        cg_scene *s = parse(json);
        CHECK(s != NULL);
        if (!s)
            continue;
        cg_image *traced = render(s, CG_SCENE_RAYTRACE);
        for (int a = CG_SCENE_ZBUFFER; a <= CG_SCENE_PAINTER && traced; a++) {
            cg_image *raster = render(s, (cg_scene_algorithm)a);
            CHECK(raster != NULL);
            long compared = 0, worst = 0;
            for (int y = 1; raster && y + 1 < H; y++)
                for (int x = 1; x + 1 < W; x++) {
                    /* Inside a face: the ray tracer's 3x3 neighbourhood is
                     * smooth (no silhouette or box edge). */
                    const unsigned char *t = pixel(traced, x, y);
                    int smooth = 1;
                    for (int d = 0; d < 9 && smooth; d++) {
                        const unsigned char *n = pixel(traced, x + d % 3 - 1, y + d / 3 - 1);
                        for (int k = 0; k < 3; k++)
                            smooth &= abs(n[k] - t[k]) <= 3;
                    }
                    if (!smooth)
                        continue;
                    const unsigned char *r = pixel(raster, x, y);
                    for (int k = 0; k < 3; k++)
                        worst = abs(r[k] - t[k]) > worst ? abs(r[k] - t[k]) : worst;
                    compared++;
                }
            CHECK_MSG(worst <= 2, "trial %d, %s: a colour %ld codes from the ray tracer's", trial,
                      a == CG_SCENE_ZBUFFER ? "z-buffer" : "painter", worst);
            CHECK_MSG(compared > W * H / 4, "trial %d: only %ld pixels compared", trial, compared);
            cg_image_free(raster);
        }
        CHECK(traced != NULL);
        cg_image_free(traced);
        cg_scene_free(s);
    }
}

static void refusals(void)
{
    static const char *const keys[][2] = {
        {"\"reflectance\": 0.5", "materials.x.reflectance"},
        {"\"transmittance\": 0.5, \"ior\": 1.5", "materials.x.transmittance"},
        {"\"specular\": \"phong\"", "materials.x.specular"},
        {"\"specular_color\": [1, 0.5, 0.5]", "materials.x.specular_color"},
    };
    for (size_t k = 0; k < sizeof keys / sizeof *keys; k++) {
        char json[512];
        snprintf(json, sizeof json,
                 "{\"image\": {\"width\": 16, \"height\": 16},"
                 " \"materials\": {\"x\": {\"ks\": 0.5, %s}},"
                 " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1,"
                 " \"material\": \"x\"}]}",
                 keys[k][0]);
        cg_scene *s = parse(json);
        CHECK(s != NULL);
        if (!s)
            continue;
        for (int a = CG_SCENE_ZBUFFER; a <= CG_SCENE_PAINTER; a++) {
            cg_image *image = NULL;
            cg_error err;
            cg_status st = cg_scene_render_with(s, (cg_scene_algorithm)a, &image, &err);
            CHECK_MSG(st == CG_EUNSUPPORTED && !image && strstr(err.message, keys[k][1]),
                      "%s: status %d, message '%s'", keys[k][1], (int)st,
                      st != CG_OK ? err.message : "");
            cg_image_free(image);
        }
        cg_image *traced = render(s, CG_SCENE_RAYTRACE);
        CHECK_MSG(traced != NULL, "%s: the ray tracer draws it", keys[k][1]);
        cg_image_free(traced);
        cg_scene_free(s);
    }
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(checker_scenes);
    CHECK_GROUP(surface_terms);
    CHECK_GROUP(refusals);
    return check_finish();
}
