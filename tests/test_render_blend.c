/* Alpha blending against its definition: stacks of full-picture quads at
 * distinct depths, each of a BLEND material with a random colour and alpha
 * (some of them opaque), drawn unlit in every submission order into a float
 * image, one sample and four.  Every pixel must be the over operator folded
 * here from the farthest quad to the nearest in linear light, starting from
 * the nearest opaque quad (or the background): the blended quads are drawn
 * after the opaque ones, back to front, without writing depth.  Pictures of
 * a mesh without BLEND materials are not touched by any of this (checked
 * by the other render tests byte for byte). */
#include "cg.h"
#include "check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SIDE 40
#define LAYERS 5

typedef struct layer {
    double z; /* world z: nearer the camera (at z = 2) when larger */
    float color[3], alpha;
    int opaque;
} layer;

/* The quads, submitted in the order given. */
static cg_mesh *stack_mesh(const layer *layers, const int *order, int count,
                           cg_mesh_material *materials)
{
    cg_mesh *m;
    if (cg_mesh_create(&m, 4 * (size_t)count, (size_t)count, 4 * (size_t)count, 0) != CG_OK)
        return NULL;
    m->face_materials = malloc((size_t)count * sizeof *m->face_materials);
    m->materials = malloc((size_t)count * sizeof *m->materials);
    if (!m->face_materials || !m->materials)
        return m;
    m->material_count = (size_t)count;
    for (int i = 0; i < count; i++) {
        const layer *l = &layers[order[i]];
        double h = SIDE; /* larger than the view: covers every pixel */
        cg_vec3 c[4] = {{-h, -h, l->z}, {h, -h, l->z}, {h, h, l->z}, {-h, h, l->z}};
        for (int k = 0; k < 4; k++) {
            m->positions[4 * i + k] = c[k];
            m->face_indices[4 * i + k] = (uint32_t)(4 * i + k);
        }
        m->face_offsets[i + 1] = (uint32_t)(4 * (i + 1));
        cg_mesh_material mat = cg_mesh_material_default();
        mat.name = NULL;
        mat.base_color = (cg_rgbaf){l->color[0], l->color[1], l->color[2], l->alpha};
        mat.alpha_mode = l->opaque ? CG_MESH_ALPHA_OPAQUE : CG_MESH_ALPHA_BLEND;
        materials[i] = mat;
        m->materials[i] = mat;
        m->face_materials[i] = (uint32_t)i;
    }
    return m;
}

static void free_stack(cg_mesh *m)
{
    /* The materials' names and maps are not ours to free. */
    if (m) {
        m->material_count = 0;
        free(m->materials);
        m->materials = NULL;
        cg_mesh_free(m);
    }
}

static void stacks(void)
{
    check_rng rng = {0x51ed2701a3c5ULL};
    long bad = 0, checked = 0;
    for (int trial = 0; trial < 60; trial++) {
        layer layers[LAYERS];
        int count = 2 + (int)check_rng_int(&rng, 0, LAYERS - 2);
        for (int i = 0; i < count; i++) {
            layers[i].z = -1 + 0.37 * i + check_rng_range(&rng, 0, 0.3);
            for (int j = 0; j < 3; j++)
                layers[i].color[j] = (float)check_rng_unit(&rng);
            layers[i].opaque = trial % 3 == 1 && i == 1;
            layers[i].alpha = layers[i].opaque ? 1 : (float)check_rng_range(&rng, 0.05, 0.95);
        }
        const float background[3] = {0.02f, 0.3f, 0.7f};
        /* The expected colour: from the nearest opaque layer (or the
         * background), the nearer blended ones laid over it far to near. */
        double expected[3] = {background[0], background[1], background[2]};
        for (int i = 0; i < count; i++) { /* layers go far to near */
            double a = layers[i].opaque ? 1 : layers[i].alpha;
            for (int j = 0; j < 3; j++)
                expected[j] = layers[i].color[j] * a + expected[j] * (1 - a);
        }
        int order[LAYERS];
        for (int i = 0; i < count; i++)
            order[i] = i;
        for (int i = count - 1; i > 0; i--) { /* a random submission order */
            int j = (int)check_rng_int(&rng, 0, i), t = order[i];
            order[i] = order[j];
            order[j] = t;
        }
        cg_mesh_material materials[LAYERS];
        cg_mesh *m = stack_mesh(layers, order, count, materials);
        CHECK(m && m->materials);
        for (int samples = 1; samples <= 4; samples *= 4) {
            cg_render_options o;
            cg_render_options_default(&o);
            o.frame_camera = 0;
            o.camera.eye = cg_vec3_make(0.1, 0.2, 2);
            o.camera.target = cg_vec3_make(0, 0, 0);
            o.camera.near = 0.1;
            o.camera.far = 10;
            o.shading = CG_SHADING_UNLIT;
            o.cull = CG_CULL_NONE;
            o.background = (cg_rgbaf){background[0], background[1], background[2], 1};
            o.msaa = samples;
            o.threads = 1 + trial % 3;
            cg_image *image;
            CHECK(cg_image_create(&image, SIDE, SIDE, CG_PIXEL_RGBAF) == CG_OK);
            cg_error err;
            CHECK(cg_render(m, &o, image, &err) == CG_OK);
            for (int y = 0; y < SIDE; y++)
                for (int x = 0; x < SIDE; x++) {
                    cg_rgbaf p = cg_image_row_rgbaf(image, y)[x];
                    double got[3] = {p.r, p.g, p.b};
                    checked++;
                    for (int j = 0; j < 3; j++)
                        if (fabs(got[j] - expected[j]) > 2e-5 && bad++ < 5)
                            CHECK_MSG(0,
                                      "trial %d, %d samples, pixel (%d, %d), channel %d: %g, "
                                      "expected %g",
                                      trial, samples, x, y, j, got[j], expected[j]);
                }
            cg_image_free(image);
        }
        free_stack(m);
    }
    CHECK_EQ_INT(bad, 0);
    CHECK(checked == 60L * 2 * SIDE * SIDE);
}

/* Half a picture covered by a blended quad in front of an opaque one, at 4
 * samples: a pixel half covered is the mean of the blended and the opaque
 * colour (every sample blended once or not at all). */
static void blended_edge(void)
{
    layer layers[2] = {{-0.5, {0.9f, 0.1f, 0.1f}, 1, 1}, {0.5, {0.1f, 0.2f, 0.9f}, 0.4f, 0}};
    int order[2] = {1, 0};
    cg_mesh_material materials[2];
    cg_mesh *m = stack_mesh(layers, order, 2, materials);
    CHECK(m && m->materials);
    /* The blended quad (submitted first) keeps x < 0 only. */
    for (int k = 0; k < 4; k++)
        if (m->positions[k].x > 0)
            m->positions[k].x = 0;
    cg_render_options o;
    cg_render_options_default(&o);
    o.frame_camera = 0;
    o.camera.eye = cg_vec3_make(0, 0, 2);
    o.camera.target = cg_vec3_make(0, 0, 0);
    o.camera.orthographic = 1;
    o.camera.ortho_height = 2;
    o.camera.near = 0.1;
    o.camera.far = 10;
    o.shading = CG_SHADING_UNLIT;
    o.cull = CG_CULL_NONE;
    o.msaa = 4;
    cg_image *image;
    /* 41 pixels wide: the edge x = 0 runs down the middle of column 20. */
    CHECK(cg_image_create(&image, 41, 41, CG_PIXEL_RGBAF) == CG_OK);
    cg_error err;
    CHECK(cg_render(m, &o, image, &err) == CG_OK);
    float front[3], back[3] = {0.9f, 0.1f, 0.1f};
    for (int j = 0; j < 3; j++)
        front[j] = layers[1].color[j] * 0.4f + back[j] * 0.6f;
    cg_rgbaf left = cg_image_row_rgbaf(image, 20)[5], right = cg_image_row_rgbaf(image, 20)[35],
             mid = cg_image_row_rgbaf(image, 20)[20];
    CHECK_NEAR(left.r, front[0], 1e-5);
    CHECK_NEAR(left.b, front[2], 1e-5);
    CHECK_NEAR(right.r, back[0], 1e-6);
    CHECK_NEAR(mid.r, 0.5 * (front[0] + back[0]), 1e-5);
    CHECK_NEAR(mid.b, 0.5 * (front[2] + back[2]), 1e-5);
    cg_image_free(image);
    free_stack(m);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(stacks);
    CHECK_GROUP(blended_edge);
    return check_finish();
}
