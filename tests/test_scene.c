/* Scene files: every field read as documented, errors naming the JSON path,
 * limits, hostile input, and rendering with each algorithm. */
#include "cg.h"
#include "check.h"

#include <string.h>

static cg_status parse(const char *json, cg_scene **out, cg_error *err)
{
    return cg_scene_parse(json, strlen(json), "s.json", NULL, 0, out, err);
}

/* Parses json and expects failure with a message containing text. */
static void expect_error(const char *json, const char *text)
{
    cg_scene *s = (cg_scene *)1;
    cg_error err;
    cg_error_clear(&err);
    cg_status st = parse(json, &s, &err);
    CHECK_MSG(st != CG_OK, "accepted: %s", json);
    CHECK(s == NULL);
    CHECK_MSG(strstr(err.message, text) != NULL, "message '%s' should contain '%s'", err.message,
              text);
}

static void test_fields(void)
{
    const char *json =
        "{\"image\": {\"width\": 320, \"height\": 200, \"background\": \"#ff0000\"},"
        " \"camera\": {\"eye\": [1, 2, 3], \"target\": [0, 0, -1], \"up\": [0, 0, 1],"
        "   \"projection\": \"perspective\", \"fov\": 60, \"near\": 0.5, \"far\": 50},"
        " \"render\": {\"algorithm\": \"painter\", \"shading\": \"flat\", \"cull\": \"none\","
        "   \"edges\": \"overlay\", \"threads\": 2, \"samples\": 9, \"depth\": 3, \"shadows\": "
        "false},"
        " \"lights\": [{\"type\": \"ambient\", \"color\": [0.2, 0.2, 0.2]},"
        "   {\"type\": \"directional\", \"direction\": [0, -2, 0], \"intensity\": 2},"
        "   {\"type\": \"point\", \"position\": [1, 1, 1], \"attenuation\": [1, 0.1, 0.01]},"
        "   {\"type\": \"spot\", \"position\": [0, 5, 0], \"direction\": [0, -1, 0], \"cutoff\": "
        "20},"
        "   {\"type\": \"area\", \"corner\": [0, 5, 0], \"edge_u\": [1, 0, 0], \"edge_v\": [0, 0, "
        "1], \"samples\": 3}],"
        " \"materials\": {\"red\": {\"color\": [1, 0, 0], \"ks\": 0.5, \"shininess\": 10, "
        "\"specular\": \"phong\","
        "   \"reflectance\": 0.3, \"transmittance\": 0.2, \"ior\": 1.5, \"checker\": {\"color\": "
        "\"white\", \"size\": 2}}},"
        " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 1, 0], \"radius\": 2, \"material\": "
        "\"red\","
        "   \"transform\": [{\"translate\": [1, 0, 0]}, {\"scale\": 2}, {\"rotate\": 90, \"axis\": "
        "[0, 0, 1]}]},"
        "   {\"type\": \"plane\", \"point\": [0, -1, 0], \"normal\": [0, 1, 0]},"
        "   {\"type\": \"box\", \"lo\": [0, 0, 0], \"hi\": [1, 2, 3]}],"
        " \"overlays\": [\"color red\", \"line 0 0 10 10\"]}";
    cg_scene *s;
    cg_error err;
    CHECK_EQ_INT(parse(json, &s, &err), CG_OK);
    if (!s) {
        fprintf(stderr, "%s\n", err.message);
        return;
    }
    CHECK(s->width == 320 && s->height == 200);
    CHECK_NEAR(s->background.r, 1, 1e-6);
    CHECK_NEAR(s->background.g, 0, 1e-6);
    CHECK(s->camera.eye.x == 1 && s->camera.eye.z == 3 && s->camera.up.z == 1);
    CHECK_NEAR(s->camera.fovy, cg_radians(60), 1e-15);
    CHECK(s->camera.near == 0.5 && s->camera.far == 50 && !s->camera.orthographic);
    CHECK(!s->frame_camera); /* an eye was given */
    CHECK(s->algorithm == CG_SCENE_PAINTER && s->shading == CG_SCENE_FLAT && !s->cull_back);
    CHECK(s->edges == CG_SCENE_EDGES_OVERLAY && s->threads == 2 && s->samples == 9);
    CHECK(s->max_depth == 3 && !s->shadows);
    CHECK_EQ_INT(s->light_count, 4);
    CHECK_EQ_INT(s->area_light_count, 1);
    CHECK(s->lights[0].kind == CG_LIGHT_AMBIENT && s->lights[1].kind == CG_LIGHT_DIRECTIONAL);
    CHECK_NEAR(s->lights[1].color.x, 2, 0);          /* intensity scales the colour */
    CHECK_NEAR(s->lights[1].direction.y, -1, 1e-15); /* normalized */
    CHECK_NEAR(s->lights[2].attenuation[1], 0.1, 0);
    CHECK_NEAR(s->lights[3].spot_cos_cutoff, cos(cg_radians(20)), 1e-12);
    CHECK_EQ_INT(s->area_lights[0].samples, 3);
    CHECK_EQ_INT(s->material_count, 2);
    CHECK(strcmp(s->materials[1].name, "red") == 0);
    CHECK(s->materials[1].surface.ks == 0.5
          && s->materials[1].surface.specular == CG_SPECULAR_PHONG);
    CHECK(s->materials[1].surface.refractive_index == 1.5 && s->materials[1].checker_size == 2);
    CHECK_EQ_INT(s->object_count, 3);
    CHECK(s->objects[0].kind == CG_SCENE_SPHERE && s->objects[0].material == 1);
    /* translate, then scale by 2, then rotate 90 about z: (0,0,0) -> (1,0,0)
     * -> (2,0,0) -> (0,2,0). */
    cg_vec3 p = cg_mat4_transform_point(s->objects[0].transform, cg_vec3_make(0, 0, 0));
    CHECK(fabs(p.x) < 1e-12 && fabs(p.y - 2) < 1e-12 && fabs(p.z) < 1e-12);
    CHECK(s->objects[1].kind == CG_SCENE_PLANE && s->objects[1].material == 0);
    CHECK(s->objects[2].kind == CG_SCENE_BOX && s->objects[2].hi.z == 3);
    CHECK_EQ_INT(s->overlay_count, 2);
    CHECK(strcmp(s->overlays[1], "line 0 0 10 10") == 0);
    cg_scene_free(s);

    /* Every projection kind reads. */
    const char *kinds[] = {"orthographic", "isometric", "dimetric", "trimetric",
                           "cavalier",     "cabinet",   "oblique"};
    for (int i = 0; i < 7; i++) {
        char text[256];
        snprintf(text, sizeof text,
                 "{\"camera\": {\"projection\": \"%s\", \"ratio\": 0.5, \"angles\": [10, 20]}}",
                 kinds[i]);
        CHECK_EQ_INT(parse(text, &s, &err), CG_OK);
        if (s) {
            CHECK_EQ_INT(s->projection, i + 1);
            CHECK(s->camera.orthographic);
            cg_scene_free(s);
        }
    }
}

static void test_errors(void)
{
    expect_error("{\"camera\": {\"fov\": \"wide\"}}",
                 "s.json: camera.fov: expected a number between 1 and 179, got \"wide\"");
    expect_error("{\"camera\": {\"fov\": 180}}",
                 "camera.fov: expected a number between 1 and 179, got 180");
    expect_error("{\"camera\": {\"fob\": 1}}", "camera.fob: unknown key");
    expect_error("{\"cameras\": {}}", "s.json: cameras: unknown key");
    expect_error("{\"image\": {\"width\": 1000000000, \"height\": 1000000000}}",
                 "image.width: expected a whole number between 1 and 16384");
    expect_error("{\"image\": {\"width\": 10.5}}", "image.width: expected a whole number");
    expect_error("{\"image\": {\"background\": \"#12345\"}}", "image.background: colour '#12345'");
    expect_error("{\"image\": {\"background\": \"chartreuse-ish\"}}",
                 "unknown colour 'chartreuse-ish'");
    expect_error("{\"image\": [1, 2]}", "image: expected an object, got an array of 2");
    expect_error("{\"camera\": {\"eye\": [1, 2]}}", "camera.eye: expected an array of 3 numbers");
    expect_error("{\"camera\": {\"eye\": [1, \"x\", 3]}}",
                 "camera.eye[1]: expected a finite number");
    expect_error("{\"camera\": {\"eye\": [0, 0, 0], \"target\": [0, 0, 0]}}", "camera.target");
    expect_error("{\"camera\": {\"near\": 5, \"far\": 1}}",
                 "camera.far: expected a distance greater than near");
    expect_error("{\"camera\": {\"projection\": \"fisheye\"}}",
                 "camera.projection: expected one of \"perspective\"");
    expect_error("{\"render\": {\"algorithm\": \"scanline\"}}",
                 "render.algorithm: expected one of");
    expect_error("{\"render\": {\"threads\": 0}}", "render.threads");
    expect_error("{\"render\": {\"shadows\": 1}}", "render.shadows: expected true or false, got 1");
    expect_error("{\"lights\": [{\"type\": \"laser\"}]}", "lights[0].type: expected one of");
    expect_error("{\"lights\": [{}]}", "lights[0].type: expected one of");
    expect_error("{\"lights\": [{\"type\": \"directional\", \"direction\": [0, 0, 0]}]}",
                 "lights[0]: expected a non-zero direction");
    expect_error("{\"lights\": [{\"type\": \"point\", \"color\": [-1, 0, 0]}]}",
                 "lights[0].color: expected colour components >= 0");
    expect_error("{\"lights\": [{\"type\": \"point\", \"attenuation\": [0, 0, 0]}]}", "lights[0]");
    expect_error("{\"lights\": {}}", "lights: expected an array");
    expect_error("{\"materials\": {\"m\": {\"ka\": -1}}}",
                 "materials.m.ka: expected a number between 0 and");
    expect_error("{\"materials\": {\"m\": {\"glow\": 1}}}", "materials.m.glow: unknown key");
    expect_error("{\"objects\": [{\"type\": \"sphere\", \"material\": \"gold\"}]}",
                 "objects[0].material: expected the name of a material defined in \"materials\", "
                 "got \"gold\"");
    expect_error("{\"objects\": [{\"type\": \"mesh\"}]}",
                 "objects[0].file: expected the path of a mesh file, got nothing");
    expect_error("{\"objects\": [{\"type\": \"sphere\", \"file\": \"a.obj\"}]}",
                 "objects[0].file: only mesh objects");
    expect_error("{\"objects\": [{\"type\": \"sphere\", \"radius\": -1}]}", "objects[0].radius");
    expect_error("{\"objects\": [{\"type\": \"plane\", \"normal\": [0, 0, 0]}]}",
                 "objects[0].normal: expected a non-zero normal");
    expect_error("{\"objects\": [{\"type\": \"box\", \"lo\": [1, 0, 0], \"hi\": [0, 1, 1]}]}",
                 "objects[0].hi");
    expect_error("{\"objects\": [{\"type\": \"sphere\", \"transform\": [{\"spin\": 3}]}]}",
                 "objects[0].transform[0]: expected a step with one of translate");
    expect_error("{\"objects\": [{\"type\": \"sphere\", \"transform\": [{\"scale\": 0}]}]}",
                 "objects[0].transform[0].scale: expected non-zero scale factors");
    expect_error("{\"objects\": [{\"type\": \"sphere\", \"transform\": [{\"rotate\": 5, \"axis\": "
                 "[0, 0, 0]}]}]}",
                 "expected a non-zero rotation axis");
    expect_error("{\"objects\": [{\"type\": \"sphere\", \"transform\": [{\"matrix\": [0,0,0,0, "
                 "0,0,0,0, 0,0,0,0, 0,0,0,1]}]}]}",
                 "transform[0].matrix: expected an invertible matrix");
    expect_error("{\"objects\": [{\"type\": \"sphere\", \"transform\": [{\"translate\": [1, 1, 1], "
                 "\"center\": [0, 0, 0]}]}]}",
                 "transform[0].center: unknown key");
    expect_error("{\"overlays\": [\"line 0 0 1 1\", 7]}",
                 "overlays[1]: expected one line of a cg draw script, got 7");
    expect_error("", "empty scene file");
    expect_error("[1, 2]", "expected a JSON object at the top level");
    expect_error("{\"image\": {\"width\": 10,\n  \"height\": }", "s.json:2:");
    expect_error("{\"image\": {\"width\": 10", "malformed JSON");

    /* A transform list over the limit. */
    size_t size = 64 + (CG_SCENE_MAX_TRANSFORMS + 1) * 24;
    char *big = malloc(size);
    strcpy(big, "{\"objects\": [{\"type\": \"sphere\", \"transform\": [");
    for (int i = 0; i <= CG_SCENE_MAX_TRANSFORMS; i++)
        strcat(big, i ? ", {\"scale\": 1.01}" : "{\"scale\": 1.01}");
    strcat(big, "]}]}");
    expect_error(big, "steps, more than the limit of 256");
    free(big);

    /* Nesting deeper than the JSON reader allows is malformed, not a crash. */
    size_t depth = 5000;
    char *deep = malloc(2 * depth + 16);
    strcpy(deep, "{\"comment\": ");
    size_t at = strlen(deep);
    for (size_t i = 0; i < depth; i++)
        deep[at++] = '[';
    for (size_t i = 0; i < depth; i++)
        deep[at++] = ']';
    deep[at++] = '}';
    deep[at] = '\0';
    expect_error(deep, "malformed JSON");
    free(deep);

    /* A mesh that fails to load names the file and the reader's message. */
    cg_scene *s;
    cg_error err;
    const char *json = "{\"objects\": [{\"type\": \"mesh\", \"file\": \"no-such-mesh.obj\"}]}";
    CHECK(cg_scene_parse(json, strlen(json), "s.json", "some/dir", 1, &s, &err) != CG_OK);
    CHECK_MSG(strstr(err.message, "objects[0].file")
                  && strstr(err.message, "some/dir/no-such-mesh.obj"),
              "message: %s", err.message);
    CHECK_EQ_INT(cg_scene_load("no/such/scene.json", &s, &err), CG_EIO);
}

/* Random damage to a valid scene: every result is a scene or a clear error. */
static void test_mutations(void)
{
    const char *base = "{\"image\": {\"width\": 32, \"height\": 24}, \"camera\": {\"eye\": [0, 0, "
                       "5], \"fov\": 50},"
                       " \"lights\": [{\"type\": \"point\", \"position\": [1, 2, 3]}],"
                       " \"materials\": {\"m\": {\"color\": \"#aabbcc\", \"ks\": 0.5}},"
                       " \"objects\": [{\"type\": \"sphere\", \"radius\": 1, \"material\": \"m\","
                       "   \"transform\": [{\"rotate\": 30, \"axis\": [1, 0, 0]}]}]}";
    size_t n = strlen(base);
    char *text = malloc(n + 1);
    check_rng rng = {4242};
    int accepted = 0, refused = 0;
    const char alphabet[] = "{}[]\",:0123456789.-eE ntfrua";
    for (int trial = 0; trial < 3000; trial++) {
        memcpy(text, base, n + 1);
        int edits = (int)check_rng_int(&rng, 1, 4);
        for (int e = 0; e < edits; e++)
            text[check_rng_int(&rng, 0, (long long)n - 1)] =
                alphabet[check_rng_int(&rng, 0, (long long)sizeof alphabet - 2)];
        cg_scene *s = NULL;
        cg_error err;
        cg_error_clear(&err);
        cg_status st = cg_scene_parse(text, n, "m.json", NULL, 0, &s, &err);
        if (st == CG_OK) {
            accepted++;
            CHECK(s != NULL);
            cg_scene_free(s);
        } else {
            refused++;
            CHECK(s == NULL && err.message[0] != '\0');
        }
    }
    CHECK(accepted > 0 && refused > 0);
    free(text);
}

static double coverage(const cg_image *img, cg_rgba8 background)
{
    size_t covered = 0;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            cg_rgba8 p = cg_image_get_rgba8(img, x, y);
            covered += p.r != background.r || p.g != background.g || p.b != background.b;
        }
    return (double)covered / ((double)img->width * img->height);
}

static void test_render(void)
{
    const char *json = "{\"image\": {\"width\": 96, \"height\": 72, \"background\": \"#000000\"},"
                       " \"camera\": {\"eye\": [0, 0, 6], \"target\": [0, 0, 0], \"fov\": 40},"
                       " \"lights\": [{\"type\": \"directional\", \"direction\": [0, 0, -1]}],"
                       " \"objects\": [{\"type\": \"sphere\", \"radius\": 1}, {\"type\": \"box\", "
                       "\"lo\": [1.5, -0.5, -0.5], \"hi\": [2.2, 0.5, 0.5]}]}";
    cg_scene *s;
    cg_error err;
    CHECK_EQ_INT(parse(json, &s, &err), CG_OK);
    if (!s)
        return;
    cg_rgba8 black = {0, 0, 0, 255};
    cg_image *z = NULL, *painter = NULL, *traced = NULL;
    CHECK_EQ_INT(cg_scene_render_with(s, CG_SCENE_ZBUFFER, &z, &err), CG_OK);
    CHECK_EQ_INT(cg_scene_render_with(s, CG_SCENE_PAINTER, &painter, &err), CG_OK);
    CHECK_EQ_INT(cg_scene_render_with(s, CG_SCENE_RAYTRACE, &traced, &err), CG_OK);
    if (z && painter && traced) {
        CHECK(z->width == 96 && z->height == 72);
        /* A unit sphere 6 units away under a 40 degree view covers about
         * pi (1/ (6 tan 20))^2 / 4 * 72/96... just check it is there and that
         * both algorithms agree on what is covered. */
        double cz = coverage(z, black), cp = coverage(painter, black);
        CHECK_MSG(cz > 0.05 && cz < 0.6, "coverage %g", cz);
        CHECK_NEAR(cz, cp, 0.01);
        /* The ray tracer sees the same objects through the same camera (the
         * rasterizer's sphere is a tessellation: a little smaller). */
        CHECK_NEAR(coverage(traced, black), cz, 0.01);
    }
    cg_image_free(z);
    cg_image_free(painter);
    cg_image_free(traced);
    /* Every projection kind renders something with the rasterizer. */
    const char *kinds[] = {"perspective", "orthographic", "isometric", "dimetric",
                           "trimetric",   "cavalier",     "cabinet",   "oblique"};
    for (int k = 0; k < 8; k++) {
        s->projection = (cg_scene_projection)k;
        s->camera.orthographic = k != 0;
        s->frame_camera = 1;
        cg_image *img = NULL;
        CHECK_MSG(cg_scene_render_with(s, CG_SCENE_ZBUFFER, &img, &err) == CG_OK, "%s: %s",
                  kinds[k], err.message);
        if (img) {
            double c = coverage(img, black);
            CHECK_MSG(c > 0.05 && c < 0.95, "%s covers %g", kinds[k], c);
        }
        cg_image_free(img);
        if (k >= 5) { /* oblique kinds: the ray tracer says it cannot */
            img = NULL;
            CHECK_EQ_INT(cg_scene_render_with(s, CG_SCENE_RAYTRACE, &img, &err), CG_EUNSUPPORTED);
            CHECK(img == NULL && strstr(err.message, "oblique"));
        } else if (k > 0) {
            CHECK_MSG(cg_scene_render_with(s, CG_SCENE_RAYTRACE, &img, &err) == CG_OK,
                      "%s traced: %s", kinds[k], err.message);
            cg_image_free(img);
        }
    }
    cg_scene_free(s);
    /* An empty scene renders the background. */
    CHECK_EQ_INT(
        parse("{\"image\": {\"width\": 8, \"height\": 8, \"background\": \"#000000\"}}", &s, &err),
        CG_OK);
    cg_image *img = NULL;
    if (s && cg_scene_render(s, &img, &err) == CG_OK) {
        CHECK(coverage(img, black) == 0);
        cg_image_free(img);
    }
    cg_scene_free(s);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_fields);
    CHECK_GROUP(test_errors);
    CHECK_GROUP(test_mutations);
    CHECK_GROUP(test_render);
    return check_finish();
}
