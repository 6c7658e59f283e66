/* The traces of cg/trace_steps.h that explain a whole rendered picture,
 * against the renderers: the painter's trace is the renderer's own run
 * (the same bytes as cg_renderer_draw), its sorted list is sorted, its
 * tests hold where it says they do, and painting its polygons again in the
 * order it gives, by cg_raster_triangle, gives the library's picture. */
#include "check.h"
#include "cg/color.h"
#include "cg/mesh.h"
#include "cg/render.h"
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
            *swaps += strstr(outcome, "swap") != NULL;
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

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(painter_agrees);
    return check_finish();
}
