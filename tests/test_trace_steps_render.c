/* The traces of cg/trace_steps.h that explain a whole rendered picture,
 * against the renderers: the painter's trace is the renderer's own run
 * (the same bytes as cg_renderer_draw), its sorted list is sorted, its
 * tests hold where it says they do, and painting its polygons again in the
 * order it gives, by cg_raster_triangle, gives the library's picture. */
#include "check.h"
#include "cg/color.h"
#include "cg/mesh.h"
#include "cg/render.h"
#include "cg/trace.h"
#include "cg/trace_steps.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { WIDTH = 64, HEIGHT = 48 };

static cg_image *image(int width, int height)
{
    cg_image *img = NULL;
    if (cg_image_create(&img, width, height, CG_PIXEL_RGBA8) != CG_OK)
        abort();
    return img;
}

/* n triangles of random size around random centres in [-1, 1]^3, face t
 * coloured with red t + 30 so that a pixel names its triangle. */
static cg_mesh *soup(check_rng *rng, int n, double spread)
{
    cg_mesh *m;
    if (cg_mesh_create(&m, (size_t)n * 3, (size_t)n, (size_t)n * 3, CG_MESH_FACE_COLORS) != CG_OK)
        abort();
    for (int t = 0; t < n; t++) {
        cg_vec3 c = {check_rng_range(rng, -1, 1), check_rng_range(rng, -1, 1),
                     check_rng_range(rng, -1, 1)};
        for (int k = 0; k < 3; k++) {
            m->positions[t * 3 + k] = cg_vec3_make(c.x + check_rng_range(rng, -spread, spread),
                                                   c.y + check_rng_range(rng, -spread, spread),
                                                   c.z + check_rng_range(rng, -spread, spread));
            m->face_indices[t * 3 + k] = (uint32_t)(t * 3 + k);
        }
        m->face_offsets[t + 1] = (uint32_t)(t * 3 + 3);
        cg_rgba8 code = {(uint8_t)(t + 30), 90, 128, 255};
        m->face_colors[t] = cg_rgba8_to_linear(code);
    }
    return m;
}

static int same_image(const cg_image *a, const cg_image *b)
{
    for (int y = 0; y < a->height; y++)
        if (memcmp(cg_image_row_rgba8((cg_image *)a, y), cg_image_row_rgba8((cg_image *)b, y),
                   (size_t)a->width * 4)
            != 0)
            return 0;
    return 1;
}

static const char *text_of(const cg_step *s, const char *name)
{
    const cg_step_field *f = cg_step_find(s, name);
    return f && f->kind == CG_STEP_TEXT ? f->text : NULL;
}

static long long integer_of(const cg_step *s, const char *name)
{
    const cg_step_field *f = cg_step_find(s, name);
    return f && f->kind == CG_STEP_INTEGER ? f->integer : -1;
}

/* ---- the painter's algorithm -------------------------------------------------- */

typedef struct replay {
    int *last; /* per pixel: the triangle painted last there, or -1 */
    int triangle;
} replay;

static void replay_span(void *user, int y, int x_begin, int x_end)
{
    replay *r = user;
    for (int x = x_begin; x < x_end; x++)
        r->last[y * WIDTH + x] = r->triangle;
}

/* The bounding box of an outline's points [from, to). */
static void box(const cg_vec2 *p, int from, int to, double lo[2], double hi[2])
{
    lo[0] = lo[1] = INFINITY;
    hi[0] = hi[1] = -INFINITY;
    for (int i = from; i < to; i++) {
        lo[0] = fmin(lo[0], p[i].x);
        hi[0] = fmax(hi[0], p[i].x);
        lo[1] = fmin(lo[1], p[i].y);
        hi[1] = fmax(hi[1], p[i].y);
    }
}

/* The tests the step says passed or failed on the x and y extents hold on
 * its two outlines (P's first, closed by its first vertex, then Q's). */
static int extents_agree(const cg_step *s, int p_vertices)
{
    double plo[2], phi[2], qlo[2], qhi[2];
    box(s->geometry, 0, p_vertices, plo, phi);
    box(s->geometry, p_vertices + 1, s->geometry_count, qlo, qhi);
    static const char *const names[2] = {"x_extents", "y_extents"};
    for (int axis = 0; axis < 2; axis++) {
        const char *said = text_of(s, names[axis]);
        if (!said)
            continue;
        int apart = phi[axis] <= qlo[axis] || qhi[axis] <= plo[axis];
        if (apart != (strcmp(said, "apart") == 0))
            return 0;
    }
    return 1;
}

/* One scene: the trace against cg_renderer_draw and against the replay. */
static void painter_scene(check_rng *rng, int scene, long *splits, long *swaps, long *tests)
{
    int n = (int)check_rng_int(rng, 1, 14);
    cg_mesh *m = soup(rng, n, scene % 3 == 0 ? 0.9 : 0.4);
    cg_render_options o;
    cg_render_options_default(&o);
    o.algorithm = scene % 2 ? CG_RENDER_PAINTER : CG_RENDER_ZBUFFER; /* the trace sets painter's */
    o.shading = CG_SHADING_UNLIT;
    o.cull = scene % 4 == 1 ? CG_CULL_BACK : CG_CULL_NONE;
    o.background = (cg_rgbaf){0, 0, 0, 1};
    o.camera.eye = cg_vec3_make(check_rng_range(rng, -2, 2), check_rng_range(rng, -2, 2), 4);
    cg_renderer *r;
    CHECK(cg_renderer_create(m, &o, &r, NULL) == CG_OK);
    cg_image *traced = image(WIDTH, HEIGHT), *drawn = image(WIDTH, HEIGHT);
    cg_step_log *log;
    CHECK(cg_step_log_create(&log) == CG_OK);
    CHECK(cg_painter_steps(r, traced, cg_step_log_record, log) == CG_OK);
    cg_render_stats stats = cg_renderer_stats(r);
    o.algorithm = CG_RENDER_PAINTER;
    CHECK(cg_renderer_set_options(r, &o) == CG_OK);
    CHECK(cg_renderer_draw(r, drawn) == CG_OK);
    CHECK_MSG(same_image(traced, drawn), "scene %d: the traced frame is not cg_renderer_draw's",
              scene);
    int *last = malloc(sizeof(int) * WIDTH * HEIGHT), painted[64] = {0};
    for (int i = 0; i < WIDTH * HEIGHT; i++)
        last[i] = -1;
    double previous = INFINITY;
    long sorted = 0, paints = 0;
    for (size_t i = 0; i < cg_step_log_count(log); i++) {
        const cg_step *s = cg_step_log_get(log, i);
        if (strcmp(s->phase, "sorted") == 0) {
            double z = cg_step_find(s, "z_max")->real;
            CHECK_MSG(z <= previous, "scene %d: the list is not sorted by z_max", scene);
            previous = z;
            sorted++;
        } else if (strcmp(s->phase, "tests") == 0) {
            long long p = integer_of(s, "P");
            CHECK(p >= 0 && p < 64);
            const char *outcome = text_of(s, "outcome");
            *tests += 1;
            *swaps += strstr(outcome, "swap, Q moved") != NULL;
            *splits += strstr(outcome, "split") != NULL;
            /* P's outline has as many vertices as P; read them from the count of
             * points up to its closing repeat. */
            int pv = 1;
            while (
                pv < s->geometry_count
                && (s->geometry[pv].x != s->geometry[0].x || s->geometry[pv].y != s->geometry[0].y))
                pv++;
            CHECK_MSG(extents_agree(s, pv), "scene %d, step %zu: an extent test is wrong", scene,
                      i);
        } else {
            CHECK(strcmp(s->phase, "paint") == 0);
            long long polygon = integer_of(s, "polygon"), triangle = integer_of(s, "triangle");
            CHECK(polygon >= 0 && polygon < 64 && triangle >= 0 && triangle < n);
            if (polygon >= 0 && polygon < 64)
                CHECK_MSG(painted[polygon]++ == 0, "scene %d: polygon %lld painted twice", scene,
                          polygon);
            CHECK_EQ_INT(integer_of(s, "order"), paints);
            paints++;
            replay rp = {last, (int)triangle};
            for (int k = 1; k + 2 < s->geometry_count; k++) {
                cg_vec2 t[3] = {s->geometry[0], s->geometry[k], s->geometry[k + 1]};
                CHECK(cg_raster_triangle(t, WIDTH, HEIGHT, replay_span, &rp) == CG_OK);
            }
        }
    }
    /* Every polygon is painted once: the sorted ones, and two pieces for each split
     * in place of the polygon split. */
    CHECK_EQ_INT(paints, sorted + (long)stats.splits);
    long wrong = 0;
    for (int y = 0; y < HEIGHT; y++)
        for (int x = 0; x < WIDTH; x++) {
            cg_rgba8 c = cg_image_get_rgba8(drawn, x, y);
            int expected = c.r == 0 && c.g == 0 ? -1 : c.r - 30;
            wrong += last[y * WIDTH + x] != expected;
        }
    CHECK_MSG(wrong == 0, "scene %d: painting in the traced order differs in %ld pixels", scene,
              wrong);
    free(last);
    cg_step_log_free(log);
    cg_image_free(traced);
    cg_image_free(drawn);
    cg_renderer_free(r);
    cg_mesh_free(m);
}

static void painter_agrees(void)
{
    check_rng rng = {0x9a1e7e5};
    long splits = 0, swaps = 0, tests = 0;
    for (int scene = 0; scene < 400; scene++)
        painter_scene(&rng, scene, &splits, &swaps, &tests);
    printf("painter: 400 scenes, %ld pair tests, %ld swaps, %ld splits\n", tests, swaps, splits);
    /* The scenes exercise every outcome. */
    CHECK_MSG(splits > 20 && swaps > 20 && tests > 1000, "%ld splits, %ld swaps, %ld tests", splits,
              swaps, tests);
    /* The options are the renderer's again afterwards, and a NULL callback is
     * refused. */
    cg_image *img = image(WIDTH, HEIGHT);
    CHECK(cg_painter_steps(NULL, img, cg_step_log_record, NULL) == CG_EINVAL);
    cg_image_free(img);
}

/* ---- a pixel's ray tree ------------------------------------------------------- */

enum { RAY_W = 20, RAY_H = 15, MAX_RAYS = 4096 };

typedef struct tree {
    double color[MAX_RAYS][3], local[MAX_RAYS][3], kr[MAX_RAYS], kt[MAX_RAYS];
    int parent[MAX_RAYS], kind[MAX_RAYS], hit[MAX_RAYS];
    int rays, shadows, pixels;
    double pixel[4];
} tree;

static int grow_tree(void *user, const cg_step *s)
{
    tree *t = user;
    if (strcmp(s->phase, "rays") == 0) {
        int i = (int)integer_of(s, "ray");
        if (i != t->rays || i >= MAX_RAYS)
            return 1;
        t->rays++;
        t->parent[i] = (int)integer_of(s, "parent");
        const char *kind = text_of(s, "kind");
        t->kind[i] = kind[0] == 'p' ? 0 : kind[2] == 'f' && kind[3] == 'l' ? 1 : 2;
        const cg_step_field *local = cg_step_find(s, "local"), *color = cg_step_find(s, "color");
        t->hit[i] = local->kind == CG_STEP_REALS;
        for (int k = 0; k < 3; k++) {
            t->local[i][k] = t->hit[i] ? local->reals[k] : 0;
            t->color[i][k] = color->reals[k];
        }
        const cg_step_field *kr = cg_step_find(s, "kr"), *kt = cg_step_find(s, "kt");
        t->kr[i] = kr->kind == CG_STEP_REAL ? kr->real : 0;
        t->kt[i] = kt->kind == CG_STEP_REAL ? kt->real : 0;
    } else if (strcmp(s->phase, "shadow rays") == 0) {
        t->shadows++;
    } else {
        const cg_step_field *c = cg_step_find(s, "color");
        memcpy(t->pixel, c->reals, sizeof t->pixel);
        t->pixels++;
    }
    return 0;
}

/* color = local + kr color(reflected child) + kt color(refracted child), for
 * every ray that hit; the number of rays where it does not hold. */
static int tree_sums_wrong(const tree *t)
{
    int wrong = 0;
    for (int i = 0; i < t->rays; i++) {
        if (!t->hit[i])
            continue;
        double sum[3] = {t->local[i][0], t->local[i][1], t->local[i][2]};
        for (int c = i + 1; c < t->rays; c++)
            if (t->parent[c] == i)
                for (int k = 0; k < 3; k++)
                    sum[k] += (t->kind[c] == 1 ? t->kr[i] : t->kt[i]) * t->color[c][k];
        for (int k = 0; k < 3; k++)
            wrong += fabs(sum[k] - t->color[i][k]) > 1e-9 * (1 + fabs(sum[k]));
    }
    return wrong;
}

static cg_trace_scene *random_scene(check_rng *rng)
{
    cg_trace_scene *scene;
    if (cg_trace_scene_create(&scene) != CG_OK)
        abort();
    int spheres = (int)check_rng_int(rng, 1, 5);
    for (int i = 0; i < spheres; i++) {
        cg_trace_material m = cg_trace_material_default();
        m.surface = cg_material_make(
            cg_vec3_make(check_rng_unit(rng), check_rng_unit(rng), check_rng_unit(rng)), 0.1,
            check_rng_range(rng, 0, 0.9), check_rng_range(rng, 0, 0.6),
            check_rng_range(rng, 1, 60));
        int glass = check_rng_int(rng, 0, 2) == 0;
        m.surface.reflectance = check_rng_range(rng, 0, glass ? 0.2 : 0.8);
        m.surface.transmittance = glass ? check_rng_range(rng, 0.5, 1 - m.surface.reflectance) : 0;
        m.surface.refractive_index = glass ? check_rng_range(rng, 1.1, 2.0) : 0;
        cg_vec3 c = {check_rng_range(rng, -2, 2), check_rng_range(rng, -0.5, 2),
                     check_rng_range(rng, -2, 1)};
        CHECK(cg_trace_scene_add_sphere(scene, c, check_rng_range(rng, 0.3, 1.2), NULL, &m)
              == CG_OK);
    }
    cg_trace_material floor = cg_trace_material_default();
    floor.surface.reflectance = check_rng_range(rng, 0, 0.5);
    floor.checker_size = 0.7;
    floor.checker_color = cg_vec3_make(0.1, 0.1, 0.1);
    CHECK(cg_trace_scene_add_plane(scene, cg_vec3_make(0, -1, 0), cg_vec3_make(0, 1, 0), &floor)
          == CG_OK);
    cg_light ambient = cg_light_ambient(cg_vec3_make(0.2, 0.2, 0.2));
    cg_light point = cg_light_point(cg_vec3_make(check_rng_range(rng, -4, 4), 5, 4),
                                    cg_vec3_make(0.9, 0.9, 0.8));
    cg_light sun = cg_light_directional(cg_vec3_make(-1, 2, 1), cg_vec3_make(0.4, 0.4, 0.5));
    CHECK(cg_trace_scene_add_light(scene, &ambient) == CG_OK);
    CHECK(cg_trace_scene_add_light(scene, &point) == CG_OK);
    CHECK(cg_trace_scene_add_light(scene, &sun) == CG_OK);
    if (check_rng_int(rng, 0, 2) == 0) {
        cg_trace_area_light area = {{-1, 4, -1}, {2, 0, 0}, {0, 0, 2}, {0.5, 0.5, 0.5}, 2};
        CHECK(cg_trace_scene_add_area_light(scene, &area) == CG_OK);
    }
    return scene;
}

static void ray_agrees(void)
{
    check_rng rng = {0x7a4e};
    long pixels = 0, rays = 0, refracted = 0, shadows = 0;
    tree *t = malloc(sizeof *t);
    for (int scene_index = 0; scene_index < 30; scene_index++) {
        cg_trace_scene *scene = random_scene(&rng);
        cg_camera camera = cg_camera_default();
        camera.eye = cg_vec3_make(check_rng_range(&rng, -1, 1), 1.5, 7);
        cg_trace_options o = cg_trace_options_default();
        o.samples = scene_index % 5 == 4 ? 4 : 1;
        o.max_depth = (int)check_rng_int(&rng, 0, 6);
        o.shadows = scene_index % 7 != 3;
        cg_image *img;
        CHECK(cg_image_create(&img, RAY_W, RAY_H, CG_PIXEL_RGBAF) == CG_OK);
        CHECK(cg_trace_render(scene, &camera, &o, img, NULL) == CG_OK);
        int wrong = 0, sums = 0;
        for (int y = 0; y < RAY_H; y++)
            for (int x = 0; x < RAY_W; x++) {
                memset(t, 0, sizeof *t);
                CHECK(cg_trace_pixel_steps(scene, &camera, &o, RAY_W, RAY_H, x, y, grow_tree, t)
                      == CG_OK);
                cg_rgbaf want = cg_image_get(img, x, y);
                wrong += t->pixels != 1 || (float)t->pixel[0] != want.r
                         || (float)t->pixel[1] != want.g || (float)t->pixel[2] != want.b
                         || (float)t->pixel[3] != want.a;
                sums += tree_sums_wrong(t);
                pixels++;
                rays += t->rays;
                shadows += t->shadows;
                for (int i = 0; i < t->rays; i++)
                    refracted += t->kind[i] == 2;
            }
        CHECK_MSG(wrong == 0, "scene %d: %d pixels differ from cg_trace_render", scene_index,
                  wrong);
        CHECK_MSG(sums == 0, "scene %d: %d rays whose colour is not local + kr R + kt T",
                  scene_index, sums);
        cg_image_free(img);
        cg_trace_scene_free(scene);
    }
    free(t);
    printf("ray trees: %ld pixels, %ld rays (%ld refracted), %ld shadow rays\n", pixels, rays,
           refracted, shadows);
    CHECK(refracted > 100);
    cg_trace_scene *scene = random_scene(&rng);
    cg_camera camera = cg_camera_default();
    CHECK(cg_trace_pixel_steps(scene, &camera, NULL, 10, 10, 10, 0, grow_tree, NULL) == CG_EINVAL);
    cg_trace_scene_free(scene);
}

/* ---- shading at a pixel --------------------------------------------------------- */

typedef struct probe {
    double last[3], pixel[4], sums;
    int written, pixels, bad;
} probe;

static int watch_pixel(void *user, const cg_step *s)
{
    probe *p = user;
    if (strcmp(s->phase, "pixel") == 0) {
        memcpy(p->pixel, cg_step_find(s, "color")->reals, sizeof p->pixel);
        p->pixels++;
        return 0;
    }
    const cg_step_field *l = cg_step_find(s, "barycentric"), *b = cg_step_find(s, "perspective");
    p->bad += fabs(l->reals[0] + l->reals[1] + l->reals[2] - 1) > 1e-12
              || fabs(b->reals[0] + b->reals[1] + b->reals[2] - 1) > 1e-12 || l->reals[0] < -1e-6
              || l->reals[1] < 0 || l->reals[2] < 0;
    if (strcmp(text_of(s, "decision"), "nearer: written") == 0) {
        const cg_step_field *c = cg_step_find(s, "color");
        memcpy(p->last, c->reals, sizeof p->last);
        p->written++;
        p->bad += !(cg_step_find(s, "depth")->real < cg_step_find(s, "buffer")->real);
    }
    return 0;
}

static void shading_agrees(void)
{
    check_rng rng = {0x5ead};
    long fragments = 0, pixels = 0;
    double worst = 0;
    for (int scene = 0; scene < 60; scene++) {
        cg_mesh *m = soup(&rng, (int)check_rng_int(&rng, 1, 10), 0.8);
        cg_render_options o;
        cg_render_options_default(&o);
        o.shading = (cg_shading)(scene % 3);
        o.cull = scene % 2 ? CG_CULL_BACK : CG_CULL_NONE;
        o.camera.eye = cg_vec3_make(check_rng_range(&rng, -2, 2), check_rng_range(&rng, -2, 2), 4);
        if (scene % 4 == 3) {
            o.light_count = 2;
            o.lights[0] = (cg_render_light){{1, 1, 1}, 0.7};
            o.lights[1] = (cg_render_light){{-1, 0, 0.5}, 0.5};
        }
        cg_renderer *r;
        CHECK(cg_renderer_create(m, &o, &r, NULL) == CG_OK);
        cg_image *drawn, *traced;
        CHECK(cg_image_create(&drawn, 32, 24, CG_PIXEL_RGBAF) == CG_OK);
        CHECK(cg_image_create(&traced, 32, 24, CG_PIXEL_RGBAF) == CG_OK);
        CHECK(cg_renderer_draw(r, drawn) == CG_OK);
        int wrong = 0;
        for (int y = 0; y < 24; y++)
            for (int x = 0; x < 32; x++) {
                probe p = {{0, 0, 0}, {0, 0, 0, 0}, 0, 0, 0, 0};
                CHECK(cg_shading_pixel_steps(r, traced, x, y, watch_pixel, &p) == CG_OK);
                cg_rgbaf want = cg_image_get(drawn, x, y);
                int w1 = p.pixels != 1, w2 = p.bad != 0,
                    w3 = (float)p.pixel[0] != want.r || (float)p.pixel[1] != want.g
                         || (float)p.pixel[2] != want.b;
                wrong += w1 || w2 || w3;
                if (p.written) {
                    double d = fmax(fabs(p.last[0] - want.r),
                                    fmax(fabs(p.last[1] - want.g), fabs(p.last[2] - want.b)));
                    worst = fmax(worst, d);
                    wrong += d > 2e-4;
                } else {
                    wrong += want.r != o.background.r || want.g != o.background.g;
                }
                fragments += p.written;
                pixels++;
            }
        CHECK_MSG(wrong == 0, "scene %d (shading %d): %d pixels disagree", scene, scene % 3, wrong);
        cg_image_free(drawn);
        cg_image_free(traced);
        cg_renderer_free(r);
        cg_mesh_free(m);
    }
    printf("shading: %ld pixels, %ld written fragments, largest colour difference %.3g\n", pixels,
           fragments, worst);
    CHECK(fragments > 1500);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(painter_agrees);
    CHECK_GROUP(ray_agrees);
    CHECK_GROUP(shading_agrees);
    return check_finish();
}
