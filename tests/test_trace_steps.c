/* The traces of cg/trace_steps.h against the library calls they explain:
 * the pixels a trace lists are the pixels cg_draw_* sets, the points and
 * lists it ends with are those of the curve and clipping functions, over
 * many random inputs in every octant and the edge cases. */
#include "check.h"
#include "cg/clip.h"
#include "cg/curve.h"
#include "cg/color.h"
#include "cg/draw.h"
#include "cg/hemesh.h"
#include "cg/light.h"
#include "cg/mesh.h"
#include "cg/render.h"
#include "cg/xform.h"
#include "cg/fill.h"
#include "cg/trace_steps.h"

#include <stdlib.h>
#include <string.h>

enum { SIDE = 80 };

static int stop_after_three(void *user, const cg_step *s);

/* The pixels of a trace, marked on a SIDE x SIDE grid (those inside it),
 * with how often each was listed. */
typedef struct marks {
    int count[SIDE][SIDE];
    long outside, listed;
    const char *only_phase; /* NULL: every phase */
} marks;

static int mark_step(void *user, const cg_step *s)
{
    marks *m = user;
    if (m->only_phase && (!s->phase || strcmp(s->phase, m->only_phase) != 0))
        return 0;
    for (int i = 0; i < s->pixel_count; i++) {
        int x = s->pixels[2 * i], y = s->pixels[2 * i + 1];
        m->listed++;
        if (x >= 0 && y >= 0 && x < SIDE && y < SIDE)
            m->count[y][x]++;
        else
            m->outside++;
    }
    return 0;
}

/* Compares the marks with the set pixels of image; the number of
 * differences (and of pixels listed twice when once is asked). */
static long compare(const marks *m, const cg_image *image, int each_once)
{
    long differences = 0;
    for (int y = 0; y < SIDE; y++)
        for (int x = 0; x < SIDE; x++) {
            int set = cg_image_get_rgba8(image, x, y).r == 255;
            if ((m->count[y][x] > 0) != set || (each_once && m->count[y][x] > 1))
                differences++;
        }
    return differences;
}

static const cg_rgba8 white = {255, 255, 255, 255}, black = {0, 0, 0, 255};

static cg_image *blank(void)
{
    cg_image *image = NULL;
    if (cg_image_create(&image, SIDE, SIDE, CG_PIXEL_RGBA8) != CG_OK)
        abort();
    cg_image_clear_rgba8(image, black);
    return image;
}

static marks *new_marks(const char *phase)
{
    marks *m = calloc(1, sizeof *m);
    if (!m)
        abort();
    m->only_phase = phase;
    return m;
}

/* ---- lines ----------------------------------------------------------------- */

static void line_agrees(void)
{
    check_rng rng = {0x1e5f00d};
    int octants[9] = {0};
    for (int trial = 0; trial < 3000; trial++) {
        /* Endpoints up to 20 pixels outside the image on each side. */
        int x0 = (int)check_rng_int(&rng, -20, SIDE + 20),
            y0 = (int)check_rng_int(&rng, -20, SIDE + 20);
        int x1 = (int)check_rng_int(&rng, -20, SIDE + 20),
            y1 = (int)check_rng_int(&rng, -20, SIDE + 20);
        if (trial % 10 == 0) /* diagonals, axes and points, where ties live */
            switch (trial / 10 % 4) {
            case 0: y1 = y0 + (x1 - x0); break;
            case 1: y1 = y0 - (x1 - x0); break;
            case 2: y1 = y0; break;
            default: x1 = x0; break;
            }
        marks *m = new_marks("walk");
        cg_image *image = blank();
        CHECK(cg_line_steps(x0, y0, x1, y1, mark_step, m) == CG_OK);
        CHECK(cg_draw_line(image, x0, y0, x1, y1, white) == CG_OK);
        long dx = labs((long)x1 - x0), dy = labs((long)y1 - y0);
        CHECK_MSG(compare(m, image, 1) == 0,
                  "line (%d, %d)-(%d, %d): trace and cg_draw_line differ", x0, y0, x1, y1);
        CHECK_EQ_INT(m->listed, (dx > dy ? dx : dy) + 1);
        cg_image_free(image);
        free(m);
        /* The octant step names the octant of the direction. */
        cg_step_log *log;
        CHECK(cg_step_log_create(&log) == CG_OK);
        CHECK(cg_line_steps(x0, y0, x1, y1, cg_step_log_record, log) == CG_OK);
        const cg_step *first = cg_step_log_get(log, 0);
        const cg_step_field *octant = cg_step_find(first, "octant");
        CHECK(octant && octant->kind == CG_STEP_INTEGER);
        if (octant) {
            int k = (int)octant->integer;
            octants[k]++;
            if (k == 0) {
                CHECK(x0 == x1 && y0 == y1);
            } else {
                double angle = atan2((double)y1 - y0, (double)x1 - x0) * 180
                               / 3.14159265358979323846;
                if (angle < 0)
                    angle += 360;
                /* exact diagonals belong to the octant they open */
                CHECK_MSG(angle >= 45.0 * (k - 1) - 1e-9
                              && angle < 45.0 * k - 1e-9 + (k == 8 ? 1e-6 : 0),
                          "direction (%d, %d) at %g degrees is not in octant %d", x1 - x0, y1 - y0,
                          angle, k);
            }
        }
        /* f and the move agree: f <= 0 selects E. */
        for (size_t i = 2; i < cg_step_log_count(log); i++) {
            const cg_step *s = cg_step_log_get(log, i);
            const cg_step_field *f = cg_step_find(s, "f"), *move = cg_step_find(s, "move");
            CHECK(f && move && strcmp(move->text, f->integer <= 0 ? "E" : "NE") == 0);
        }
        cg_step_log_free(log);
    }
    for (int k = 1; k <= 8; k++)
        CHECK_MSG(octants[k] > 100, "octant %d tried %d times", k, octants[k]);
}

/* The DDA's pixels against its definition: one per major coordinate, each
 * within 1/2 of the real line along the minor axis, ends exact. */
static int dda_check(void *user, const cg_step *s)
{
    const int *line = user; /* x0 y0 x1 y1 */
    long dx = line[2] - line[0], dy = line[3] - line[1];
    int x = s->pixels[0], y = s->pixels[1];
    int k = (int)cg_step_find(s, "k")->integer;
    if (labs(dx) >= labs(dy) && dx != 0) {
        int step = dx > 0 ? 1 : -1;
        CHECK(x == line[0] + step * k);
        double real_y = line[1] + (double)dy * (x - line[0]) / (double)dx;
        CHECK_MSG(fabs(y - real_y) <= 0.5 + 1e-9, "DDA pixel (%d, %d) is %g from the line", x, y,
                  fabs(y - real_y));
    } else if (dy != 0) {
        int step = dy > 0 ? 1 : -1;
        CHECK(y == line[1] + step * k);
        double real_x = line[0] + (double)dx * (y - line[1]) / (double)dy;
        CHECK(fabs(x - real_x) <= 0.5 + 1e-9);
    }
    return 0;
}

static void dda_definition(void)
{
    check_rng rng = {0xdda};
    for (int trial = 0; trial < 2000; trial++) {
        int line[4];
        for (int i = 0; i < 4; i++)
            line[i] = (int)check_rng_int(&rng, -300, 300);
        CHECK(cg_line_dda_steps(line[0], line[1], line[2], line[3], dda_check, line) == CG_OK);
        /* and the last pixel is the second endpoint */
        cg_step_log *log;
        cg_step_log_create(&log);
        cg_line_dda_steps(line[0], line[1], line[2], line[3], cg_step_log_record, log);
        const cg_step *last = cg_step_log_get(log, cg_step_log_count(log) - 1);
        CHECK(last->pixels[0] == line[2] && last->pixels[1] == line[3]);
        cg_step_log_free(log);
    }
}

typedef struct wu_check {
    const int *line;
    cg_image *image;
} wu_check;

static int wu_column_check(void *user, const cg_step *s)
{
    wu_check *w = user;
    const int *line = w->line;
    long dx = line[2] - line[0], dy = line[3] - line[1];
    int steep = labs(dy) > labs(dx);
    long n = steep ? labs(dy) : labs(dx);
    long long k = cg_step_find(s, "k")->integer;
    double minor = cg_step_find(s, "minor")->real;
    double exact = n ? (steep ? line[0] + (double)dx * k / n : line[1] + (double)dy * k / n)
                     : (steep ? line[0] : line[1]);
    CHECK_NEAR(minor, exact, 1e-9 * (1 + fabs(exact)));
    CHECK(s->pixel_count == 2 && s->intensity);
    CHECK_NEAR(s->intensity[0] + s->intensity[1], 1, 1e-12);
    int lower = steep ? s->pixels[0] : s->pixels[1], upper = steep ? s->pixels[2] : s->pixels[3];
    CHECK(upper == lower + 1 && lower <= minor && minor < lower + 1);
    CHECK_NEAR(s->intensity[1], minor - lower, 1e-12);
    /* the pixels drawn by cg_draw_line_wu carry these intensities */
    for (int i = 0; i < 2; i++) {
        int x = s->pixels[2 * i], y = s->pixels[2 * i + 1];
        if (cg_image_contains(w->image, x, y))
            CHECK_NEAR(cg_image_get(w->image, x, y).r, s->intensity[i], 2e-6);
    }
    return 0;
}

static void wu_agrees(void)
{
    check_rng rng = {0x3e};
    cg_image *image;
    cg_image_create(&image, SIDE, SIDE, CG_PIXEL_RGBAF);
    for (int trial = 0; trial < 2000; trial++) {
        int line[4];
        for (int i = 0; i < 4; i++)
            line[i] = (int)check_rng_int(&rng, -20, SIDE + 20);
        cg_image_clear(image, (cg_rgbaf){0, 0, 0, 1});
        CHECK(cg_draw_line_wu(image, line[0], line[1], line[2], line[3], white) == CG_OK);
        wu_check w = {line, image};
        CHECK(cg_line_wu_steps(line[0], line[1], line[2], line[3], wu_column_check, &w) == CG_OK);
        /* and nothing else is lit */
        marks *m = new_marks(NULL);
        cg_line_wu_steps(line[0], line[1], line[2], line[3], mark_step, m);
        long stray = 0;
        for (int y = 0; y < SIDE; y++)
            for (int x = 0; x < SIDE; x++)
                stray += m->count[y][x] == 0 && cg_image_get(image, x, y).r != 0;
        CHECK_EQ_INT(stray, 0);
        free(m);
    }
    cg_image_free(image);
}

/* ---- circles and ellipses ------------------------------------------------- */

static void circle_agrees(void)
{
    check_rng rng = {0xc1c1e};
    for (int trial = 0; trial < 400; trial++) {
        int r = trial < 60 ? trial : (int)check_rng_int(&rng, 0, 70);
        int cx = (int)check_rng_int(&rng, -10, SIDE + 10),
            cy = (int)check_rng_int(&rng, -10, SIDE + 10);
        if (trial < 60)
            cx = cy = SIDE / 2;
        marks *m = new_marks(NULL);
        cg_image *image = blank();
        CHECK(cg_circle_steps(cx, cy, r, mark_step, m) == CG_OK);
        CHECK(cg_draw_circle(image, cx, cy, r, white) == CG_OK);
        CHECK_MSG(compare(m, image, 1) == 0,
                  "circle r %d at (%d, %d): trace and cg_draw_circle differ", r, cx, cy);
        cg_image_free(image);
        free(m);
    }
}

/* Region steps' decisions agree with their moves. */
static int ellipse_moves(void *user, const cg_step *s)
{
    (void)user;
    const cg_step_field *d = cg_step_find(s, "d"), *move = cg_step_find(s, "move");
    if (!s->phase || !d || d->kind != CG_STEP_INTEGER)
        return 0;
    if (strcmp(s->phase, "region 1") == 0)
        CHECK_MSG((d->integer < 0) == (strcmp(move->text, "E") == 0), "region 1: d %lld, move %s",
                  d->integer, move->text);
    if (strcmp(s->phase, "region 2") == 0 && strncmp(move->text, "switch", 6) != 0)
        CHECK_MSG((d->integer >= 0) == (strcmp(move->text, "S") == 0), "region 2: d %lld, move %s",
                  d->integer, move->text);
    return 0;
}

static void ellipse_agrees(void)
{
    check_rng rng = {0xe111};
    for (int trial = 0; trial < 1500; trial++) {
        int rx = (int)check_rng_int(&rng, 0, 60), ry = (int)check_rng_int(&rng, 0, 60);
        if (trial % 7 == 0) /* thin ellipses */
            ry = (int)check_rng_int(&rng, 0, 3);
        if (rx == ry)
            continue;
        int cx = (int)check_rng_int(&rng, -10, SIDE + 10),
            cy = (int)check_rng_int(&rng, -10, SIDE + 10);
        if (trial < 200)
            cx = cy = SIDE / 2;
        marks *m = new_marks(NULL);
        cg_image *image = blank();
        CHECK(cg_ellipse_steps(cx, cy, rx, ry, mark_step, m) == CG_OK);
        CHECK(cg_draw_ellipse(image, cx, cy, rx, ry, white) == CG_OK);
        CHECK_MSG(compare(m, image, 0) == 0,
                  "ellipse %d x %d at (%d, %d): trace and "
                  "cg_draw_ellipse differ",
                  rx, ry, cx, cy);
        CHECK(cg_ellipse_steps(cx, cy, rx, ry, ellipse_moves, NULL) == CG_OK);
        cg_image_free(image);
        free(m);
    }
}

/* ---- curves ------------------------------------------------------------------- */

static void random_points(check_rng *rng, cg_vec2 *p, int n, double size)
{
    for (int i = 0; i < n; i++)
        p[i] = cg_vec2_make(check_rng_range(rng, -size, size), check_rng_range(rng, -size, size));
}

static void casteljau_agrees(void)
{
    check_rng rng = {0xca57};
    for (int trial = 0; trial < 500; trial++) {
        int n = (int)check_rng_int(&rng, 2, 12);
        cg_vec2 control[12], left[12], right[12], q;
        random_points(&rng, control, n, 100);
        double t = trial % 5 == 0 ? check_rng_int(&rng, 0, 1) : check_rng_unit(&rng);
        cg_step_log *log;
        cg_step_log_create(&log);
        CHECK(cg_casteljau_steps(control, n, t, cg_step_log_record, log) == CG_OK);
        CHECK_EQ_INT(cg_step_log_count(log), n + 1);
        cg_bezier_point(control, n, t, &q);
        cg_bezier_split(control, n, t, left, right);
        const cg_step *top = cg_step_log_get(log, (size_t)n - 1);
        const cg_step_field *point = cg_step_find(top, "Q");
        CHECK(point && point->kind == CG_STEP_POINT && point->point.x == q.x
              && point->point.y == q.y);
        const cg_step *split = cg_step_log_get(log, (size_t)n);
        const cg_step_field *l = cg_step_find(split, "left"), *r = cg_step_find(split, "right");
        CHECK(l && r && l->point_count == (size_t)n && r->point_count == (size_t)n);
        for (int i = 0; l && r && i < n; i++)
            CHECK(memcmp(&l->points[i], &left[i], sizeof left[i]) == 0
                  && memcmp(&r->points[i], &right[i], sizeof right[i]) == 0);
        /* each level has one point fewer, and is the interpolation of the one before */
        for (int level = 1; level < n; level++) {
            const cg_step_field *prev = cg_step_find(cg_step_log_get(log, (size_t)level - 1),
                                                     "points");
            const cg_step_field *cur = cg_step_find(cg_step_log_get(log, (size_t)level), "points");
            CHECK(cur->point_count + 1 == prev->point_count);
            for (size_t i = 0; i < cur->point_count; i++) {
                cg_vec2 e = cg_vec2_add(cg_vec2_scale(prev->points[i], 1 - t),
                                        cg_vec2_scale(prev->points[i + 1], t));
                CHECK_NEAR(cur->points[i].x, e.x, 1e-9);
                CHECK_NEAR(cur->points[i].y, e.y, 1e-9);
            }
        }
        cg_step_log_free(log);
    }
}

static void cubic_agrees(void)
{
    check_rng rng = {0xc0b1c};
    for (int trial = 0; trial < 400; trial++) {
        cg_cubic2 curve;
        curve.basis = (cg_curve_basis)(trial % 4);
        random_points(&rng, curve.g, 4, 50);
        int n = (int)check_rng_int(&rng, 1, 20);
        cg_step_log *log;
        cg_step_log_create(&log);
        CHECK(cg_cubic_steps(&curve, n, cg_step_log_record, log) == CG_OK);
        CHECK_EQ_INT(cg_step_log_count(log), n + 1);
        for (size_t k = 0; k < cg_step_log_count(log); k++) {
            const cg_step *s = cg_step_log_get(log, k);
            double t = cg_step_find(s, "t")->real, w[4], sum = 0;
            cg_vec2 q = cg_cubic2_point(&curve, t), blended = {0, 0};
            const cg_step_field *point = cg_step_find(s, "Q");
            CHECK(point->point.x == q.x && point->point.y == q.y);
            static const char *const names[4] = {"b1", "b2", "b3", "b4"};
            for (int j = 0; j < 4; j++) {
                w[j] = cg_step_find(s, names[j])->real;
                sum += w[j];
                blended = cg_vec2_add(blended, cg_vec2_scale(curve.g[j], w[j]));
            }
            CHECK_NEAR(blended.x, q.x, 1e-9 * 200);
            CHECK_NEAR(blended.y, q.y, 1e-9 * 200);
            if (curve.basis != CG_BASIS_HERMITE) /* the weights of a point basis sum to 1 */
                CHECK_NEAR(sum, 1, 1e-12);
        }
        cg_step_log_free(log);
    }
}

typedef struct point_list {
    cg_vec2 p[4096];
    int n;
} point_list;

static cg_status collect_point(void *user, cg_vec2 p)
{
    point_list *l = user;
    if (l->n < 4096)
        l->p[l->n] = p;
    l->n++;
    return CG_OK;
}

static int collect_emitted(void *user, const cg_step *s)
{
    point_list *l = user;
    const cg_step_field *point = cg_step_find(s, "point");
    const cg_step_field *decision = cg_step_find(s, "decision");
    if (point && point->kind == CG_STEP_POINT) {
        CHECK(strcmp(decision->text, "emit") == 0);
        collect_point(l, point->point);
    } else {
        CHECK(strcmp(decision->text, "split") == 0);
    }
    return 0;
}

static void flatten_agrees(void)
{
    check_rng rng = {0xf1a7};
    static point_list library, traced;
    for (int trial = 0; trial < 600; trial++) {
        int n = (int)check_rng_int(&rng, 2, 8);
        cg_vec2 control[8];
        random_points(&rng, control, n, 200);
        if (trial % 9 == 0) /* a cusp: coincident middle points */
            control[n / 2] = control[(n - 1) / 2];
        double tolerance = pow(10, check_rng_range(&rng, -2, 1));
        library.n = traced.n = 0;
        cg_status a = cg_bezier_flatten(control, n, tolerance, collect_point, &library);
        cg_status b = cg_bezier_flatten_steps(control, n, tolerance, collect_emitted, &traced);
        CHECK(a == CG_OK);
        if (library.n > 4096 || b == CG_ERANGE)
            continue;
        CHECK(b == CG_OK);
        CHECK_EQ_INT(traced.n, library.n);
        CHECK_MSG(traced.n == library.n
                      && memcmp(traced.p, library.p, (size_t)library.n * sizeof library.p[0]) == 0,
                  "flatten trial %d: the trace's points differ from cg_bezier_flatten's", trial);
    }
}

/* ---- viewing, illumination, colour ------------------------------------------- */

static const cg_step *last_step_of(const cg_step_log *log, const char *phase)
{
    const cg_step *found = NULL;
    for (size_t i = 0; i < cg_step_log_count(log); i++) {
        const cg_step *s = cg_step_log_get(log, i);
        if (s->phase && strcmp(s->phase, phase) == 0)
            found = s;
    }
    return found;
}

static void pipeline_agrees(void)
{
    check_rng rng = {0x919e};
    int inside = 0;
    for (int trial = 0; trial < 1000; trial++) {
        cg_vec3 eye = {check_rng_range(&rng, -10, 10), check_rng_range(&rng, -10, 10),
                       check_rng_range(&rng, 2, 10)};
        cg_vec3 target = {check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1),
                          check_rng_range(&rng, -1, 1)};
        cg_vec3 point = {check_rng_range(&rng, -3, 3), check_rng_range(&rng, -3, 3),
                         check_rng_range(&rng, -3, 3)};
        cg_mat4 model = cg_xform3_rotate_y(check_rng_range(&rng, 0, 6)), view, projection;
        CHECK(cg_view_look_at(eye, target, cg_vec3_make(0, 1, 0), &view) == CG_OK);
        CHECK(cg_proj_perspective(check_rng_range(&rng, 0.3, 2), 4.0 / 3, 0.1, 100, &projection)
              == CG_OK);
        cg_step_log *log;
        cg_step_log_create(&log);
        CHECK(cg_pipeline_steps(model, view, projection, 640, 480, point, cg_step_log_record, log)
              == CG_OK);
        const cg_step *window = last_step_of(log, "point");
        int visible;
        cg_vec3 expected = cg_project_point(
            cg_mat4_mul(cg_viewport(640, 480), cg_mat4_mul(projection, cg_mat4_mul(view, model))),
            point, &visible);
        const cg_step_field *space = cg_step_find(window, "space");
        if (!visible) {
            CHECK(strcmp(space->text, "ndc") == 0);
        } else {
            CHECK(strcmp(space->text, "window") == 0);
            const cg_step_field *c = cg_step_find(window, "coordinates");
            CHECK(c->kind == CG_STEP_REALS && c->real_count == 4);
            CHECK_NEAR(c->reals[0], expected.x, 1e-9 * (1 + fabs(expected.x)));
            CHECK_NEAR(c->reals[1], expected.y, 1e-9 * (1 + fabs(expected.y)));
            CHECK_NEAR(c->reals[2], expected.z, 1e-9 * (1 + fabs(expected.z)));
            inside += window->pixel_count == 1;
            if (window->pixel_count == 1)
                CHECK(window->pixels[0] == (int)floor(expected.x)
                      && window->pixels[1] == (int)floor(expected.y));
        }
        /* the composite is the product of its factors */
        const cg_step *composite = cg_step_log_get(log, 3);
        cg_mat4 pvm = cg_mat4_mul(projection, cg_mat4_mul(view, model));
        for (int k = 0; k < 16; k++)
            CHECK(cg_step_find(composite, "value")->reals[k] == pvm.m[k / 4][k % 4]);
        cg_step_log_free(log);
    }
    CHECK(inside > 100);
}

static void color_agrees(void)
{
    check_rng rng = {0xc0102};
    for (int trial = 0; trial < 4000; trial++) {
        cg_vec3 rgb = {check_rng_range(&rng, -0.2, 1.2), check_rng_range(&rng, -0.2, 1.2),
                       check_rng_range(&rng, -0.2, 1.2)};
        if (trial % 7 == 0) /* greys and ties between channels */
            rgb.y = rgb.x;
        if (trial % 11 == 0)
            rgb.z = rgb.x = rgb.y;
        for (int lightness = 0; lightness < 2; lightness++) {
            cg_step_log *log;
            cg_step_log_create(&log);
            CHECK(cg_rgb_to_hsv_steps(rgb, lightness, cg_step_log_record, log) == CG_OK);
            const cg_step_field *v = cg_step_find(last_step_of(log, "result"), "value");
            cg_vec3 e = lightness ? cg_rgb_to_hsl(rgb) : cg_rgb_to_hsv(rgb);
            CHECK_MSG(v && v->real_count == 3 && v->reals[0] == e.x && v->reals[1] == e.y
                          && v->reals[2] == e.z,
                      "%s of (%g, %g, %g): the trace's result differs", lightness ? "HSL" : "HSV",
                      rgb.x, rgb.y, rgb.z);
            cg_step_log_free(log);
        }
    }
}

static cg_vec3 reals3(const cg_step *s, const char *name)
{
    const cg_step_field *f = cg_step_find(s, name);
    return f && f->real_count == 3 ? cg_vec3_make(f->reals[0], f->reals[1], f->reals[2])
                                   : cg_vec3_make(NAN, NAN, NAN);
}

static void light_agrees(void)
{
    check_rng rng = {0x11947};
    for (int trial = 0; trial < 1000; trial++) {
        cg_light lights[4];
        lights[0] = cg_light_ambient(cg_vec3_make(0.1, 0.2, 0.3));
        lights[1] = cg_light_point(cg_vec3_make(check_rng_range(&rng, -5, 5),
                                                check_rng_range(&rng, -5, 5),
                                                check_rng_range(&rng, -5, 5)),
                                   cg_vec3_make(1, 0.9, 0.8));
        cg_light_set_attenuation(&lights[1], 1, 0.1, 0.05);
        lights[2] = cg_light_directional(
            cg_vec3_make(check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1), -1),
            cg_vec3_make(0.5, 0.5, 0.5));
        lights[3] = cg_light_spot(cg_vec3_make(0, 0, 4),
                                  cg_vec3_make(check_rng_range(&rng, -0.5, 0.5), 0, -1), 0.6, 2,
                                  cg_vec3_make(1, 1, 1));
        cg_material material = cg_material_make(cg_vec3_make(0.8, 0.4, 0.2), 0.2, 0.7, 0.5,
                                                check_rng_range(&rng, 1, 60));
        material.specular = trial % 2 ? CG_SPECULAR_BLINN : CG_SPECULAR_PHONG;
        cg_vec3 normal = cg_vec3_normalize(
            cg_vec3_make(check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1), 1));
        cg_vec3 view = cg_vec3_normalize(
            cg_vec3_make(check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1), 1));
        cg_vec3 point = {check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1), 0};
        cg_step_log *log;
        cg_step_log_create(&log);
        CHECK(cg_light_steps(point, normal, view, &material, lights, 4, cg_step_log_record, log)
              == CG_OK);
        cg_shade_terms all = cg_light_shade_terms(point, normal, view, &material, lights, 4, NULL);
        cg_vec3 diffuse = {0, 0, 0};
        for (size_t i = 0; i < 4; i++) {
            const cg_step *s = cg_step_log_get(log, i);
            cg_vec3 d = reals3(s, "diffuse");
            diffuse = cg_vec3_add(diffuse, d);
            if (i == 0)
                continue;
            /* the diffuse term is f_att spot Il kd Od max(N.L, 0) */
            double factor = cg_step_find(s, "f_att")->real * cg_step_find(s, "spot")->real
                            * fmax(cg_step_find(s, "N.L")->real, 0) * material.kd;
            CHECK_NEAR(d.x, factor * lights[i].color.x * material.color.x, 1e-12);
            CHECK_NEAR(d.z, factor * lights[i].color.z * material.color.z, 1e-12);
            /* and the specular term f_att spot Il ks spec */
            double spec = cg_step_find(s, "f_att")->real * cg_step_find(s, "spot")->real
                          * cg_step_find(s, "spec")->real * material.ks;
            CHECK_NEAR(reals3(s, "specular").y, spec * lights[i].color.y, 1e-9);
        }
        CHECK_NEAR(diffuse.x, all.diffuse.x, 1e-12);
        CHECK_NEAR(diffuse.y, all.diffuse.y, 1e-12);
        const cg_step *total = last_step_of(log, "total");
        cg_vec3 t = reals3(total, "I");
        CHECK(t.x == all.ambient.x + (all.diffuse.x + all.specular.x));
        cg_step_log_free(log);
    }
    cg_material bad = cg_material_make(cg_vec3_make(1, 1, 1), -1, 0, 0, 1);
    CHECK(cg_light_steps(cg_vec3_make(0, 0, 0), cg_vec3_make(0, 0, 1), cg_vec3_make(0, 0, 1), &bad,
                         NULL, 0, stop_after_three, NULL)
          == CG_EINVAL);
}

static void vanishing_agrees(void)
{
    check_rng rng = {0x7a};
    int found = 0;
    for (int trial = 0; trial < 1000; trial++) {
        cg_vec3 eye = {check_rng_range(&rng, -5, 5), check_rng_range(&rng, -5, 5),
                       check_rng_range(&rng, 3, 8)};
        cg_vec3 d = {check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1),
                     check_rng_range(&rng, -1, 1)};
        cg_mat4 view, projection;
        if (cg_view_look_at(eye, cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &view) != CG_OK
            || !(cg_vec3_length(d) > 0.1))
            continue;
        cg_proj_perspective(1, 4.0 / 3, 0.1, 100, &projection);
        cg_step_log *log;
        cg_step_log_create(&log);
        CHECK(cg_vanishing_point_steps(view, projection, 640, 480, d, cg_step_log_record, log)
              == CG_OK);
        const cg_step *last = last_step_of(log, "point");
        if (strcmp(cg_step_find(last, "space")->text, "window") == 0) {
            /* the images of points far along any line of direction d approach it */
            cg_vec3 base = {check_rng_range(&rng, -2, 2), check_rng_range(&rng, -2, 2),
                            check_rng_range(&rng, -2, 2)};
            int visible;
            cg_mat4 whole = cg_mat4_mul(cg_viewport(640, 480), cg_mat4_mul(projection, view));
            cg_vec3 far = cg_project_point(whole, cg_vec3_add(base, cg_vec3_scale(d, 1e7)),
                                           &visible);
            const double *vp = cg_step_find(last, "coordinates")->reals;
            CHECK(visible);
            CHECK_NEAR(far.x, vp[0], 1e-2 * (1 + fabs(vp[0])));
            CHECK_NEAR(far.y, vp[1], 1e-2 * (1 + fabs(vp[1])));
            found++;
        } else { /* no vanishing point: the direction does not go away from the eye */
            cg_vec4 e = cg_mat4_mul_vec4(view, cg_vec4_make(d.x, d.y, d.z, 0));
            CHECK(!(e.z < 0));
        }
        cg_step_log_free(log);
    }
    CHECK(found > 200);
}

static int count_culled(void *user, const cg_step *s)
{
    *(size_t *)user += strcmp(cg_step_find(s, "decision")->text, "back: culled") == 0;
    return 0;
}

static void backface_agrees(void)
{
    check_rng rng = {0xbacf};
    cg_mesh *meshes[3];
    CHECK(cg_mesh_sphere(12, 8, 1, &meshes[0]) == CG_OK);
    CHECK(cg_mesh_box(cg_vec3_make(-1, -0.5, -2), cg_vec3_make(1, 0.5, 2), &meshes[1]) == CG_OK);
    CHECK(cg_mesh_torus(16, 8, 1, 0.3, &meshes[2]) == CG_OK);
    cg_image *image;
    cg_image_create(&image, 800, 600, CG_PIXEL_RGBA8);
    for (int trial = 0; trial < 30; trial++) {
        const cg_mesh *mesh = meshes[trial % 3];
        cg_render_options options;
        cg_render_options_default(&options);
        options.model = cg_mat4_mul(cg_xform3_rotate_x(check_rng_range(&rng, 0, 6)),
                                    cg_xform3_rotate_y(check_rng_range(&rng, 0, 6)));
        options.camera.orthographic = trial % 5 == 4;
        cg_renderer *renderer;
        CHECK(cg_renderer_create(mesh, &options, &renderer, NULL) == CG_OK);
        CHECK(cg_renderer_draw(renderer, image) == CG_OK);
        cg_render_stats stats = cg_renderer_stats(renderer);
        cg_camera camera = cg_renderer_camera(renderer);
        size_t culled = 0;
        CHECK(cg_backface_steps(mesh, options.model, &camera, count_culled, &culled) == CG_OK);
        CHECK_MSG(culled == stats.culled,
                  "trial %d: the trace culls %zu triangles, the renderer %zu (rejected %zu, "
                  "clipped %zu, of %zu)",
                  trial, culled, stats.culled, stats.rejected, stats.clipped, stats.triangles);
        cg_renderer_free(renderer);
    }
    cg_image_free(image);
    for (int i = 0; i < 3; i++)
        cg_mesh_free(meshes[i]);
}

typedef struct zbuffer_view {
    double margin;
    int covered;
    double depth;
} zbuffer_view;

/* The result's depth, and how clearly the pixel centre is inside the
 * winning triangle (or outside every triangle when none won). */
static int read_zbuffer(void *user, const cg_step *s)
{
    zbuffer_view *z = user;
    const cg_step_field *w = cg_step_find(s, "barycentric");
    if (strcmp(s->phase, "fragments") == 0 && w && w->kind == CG_STEP_REALS) {
        double inner = fmin(w->reals[0], fmin(w->reals[1], w->reals[2]));
        z->margin = fmin(z->margin, fabs(inner)); /* near an edge of any triangle */
    }
    if (strcmp(s->phase, "result") == 0) {
        const cg_step_field *depth = cg_step_find(s, "depth");
        z->covered = depth->kind == CG_STEP_REAL;
        z->depth = z->covered ? depth->real : INFINITY;
    }
    return 0;
}

static void zbuffer_agrees(void)
{
    check_rng rng = {0x2b};
    cg_mesh *meshes[2];
    CHECK(cg_mesh_sphere(10, 6, 1, &meshes[0]) == CG_OK);
    CHECK(cg_mesh_torus(12, 6, 1, 0.35, &meshes[1]) == CG_OK);
    const int width = 160, height = 120;
    cg_image *image;
    cg_image_create(&image, width, height, CG_PIXEL_RGBA8);
    int compared = 0, hits = 0;
    for (int trial = 0; trial < 20; trial++) {
        const cg_mesh *mesh = meshes[trial % 2];
        cg_render_options options;
        cg_render_options_default(&options);
        options.model = cg_mat4_mul(cg_xform3_rotate_x(check_rng_range(&rng, 0, 6)),
                                    cg_xform3_rotate_y(check_rng_range(&rng, 0, 6)));
        cg_renderer *renderer;
        CHECK(cg_renderer_create(mesh, &options, &renderer, NULL) == CG_OK);
        CHECK(cg_renderer_draw(renderer, image) == CG_OK);
        const float *depth = cg_renderer_depth(renderer);
        cg_camera camera = cg_renderer_camera(renderer);
        for (int k = 0; k < 40; k++) {
            int x = (int)check_rng_int(&rng, 0, width - 1),
                y = (int)check_rng_int(&rng, 0, height - 1);
            zbuffer_view z = {INFINITY, 0, INFINITY};
            CHECK(cg_zbuffer_pixel_steps(mesh, options.model, &camera, width, height, x, y, 1,
                                         read_zbuffer, &z)
                  == CG_OK);
            if (z.margin < 0.02) /* the centre is near an edge: snapping decides */
                continue;
            double expected = depth[(size_t)y * width + x];
            compared++;
            hits += z.covered;
            CHECK_MSG(z.covered == isfinite(expected),
                      "trial %d pixel (%d, %d): trace %s, renderer %s", trial, x, y,
                      z.covered ? "covered" : "background",
                      isfinite(expected) ? "covered" : "background");
            if (z.covered && isfinite(expected))
                CHECK_NEAR(z.depth, expected, 1e-3); /* the renderer snaps vertices to sub-pixels */
        }
        cg_renderer_free(renderer);
    }
    CHECK(compared > 300 && hits > 100);
    cg_image_free(image);
    cg_mesh_free(meshes[0]);
    cg_mesh_free(meshes[1]);
}

typedef struct halfedge_list {
    uint32_t h[256];
    size_t n;
} halfedge_list;

static int collect_halfedge(void *user, const cg_step *s)
{
    halfedge_list *l = user;
    if (l->n < 256)
        l->h[l->n] = (uint32_t)cg_step_find(s, "h")->integer;
    l->n++;
    return 0;
}

static void hemesh_agrees(void)
{
    cg_mesh *shapes[2];
    CHECK(cg_mesh_torus(10, 6, 1, 0.3, &shapes[0]) == CG_OK);
    CHECK(cg_mesh_box(cg_vec3_make(0, 0, 0), cg_vec3_make(1, 2, 3), &shapes[1]) == CG_OK);
    for (int i = 0; i < 2; i++) {
        cg_hemesh *m;
        CHECK(cg_hemesh_build(shapes[i], 0, &m, NULL, NULL) == CG_OK);
        uint32_t expected[256];
        for (uint32_t f = 0; f < m->face_count; f++) {
            halfedge_list l = {{0}, 0};
            CHECK(cg_hemesh_face_loop_steps(m, f, collect_halfedge, &l) == CG_OK);
            size_t n = cg_hemesh_face_halfedges(m, f, expected, 256);
            CHECK(l.n == n && memcmp(l.h, expected, n * sizeof *expected) == 0);
        }
        for (uint32_t v = 0; v < m->vertex_count; v++) {
            halfedge_list l = {{0}, 0};
            CHECK(cg_hemesh_one_ring_steps(m, v, collect_halfedge, &l) == CG_OK);
            size_t n = cg_hemesh_vertex_outgoing(m, v, 1, expected, 256);
            CHECK(l.n == n && memcmp(l.h, expected, n * sizeof *expected) == 0);
        }
        CHECK(cg_hemesh_face_loop_steps(m, (uint32_t)m->face_count, collect_halfedge, NULL)
              == CG_EINVAL);
        CHECK(cg_hemesh_one_ring_steps(m, (uint32_t)m->vertex_count, collect_halfedge, NULL)
              == CG_EINVAL);
        cg_hemesh_free(m);
        cg_mesh_free(shapes[i]);
    }
}

/* ---- filling ------------------------------------------------------------------ */

static void scanline_agrees(void)
{
    check_rng rng = {0x5ca1};
    for (int trial = 0; trial < 1500; trial++) {
        /* one or two contours of 3 to 9 points, some beyond the image, some on
         * pixel centres and edges (where the centre rule decides) */
        cg_vec2 points[18];
        int sizes[2] = {(int)check_rng_int(&rng, 3, 9), (int)check_rng_int(&rng, 3, 9)};
        int contours = trial % 3 == 0 ? 2 : 1, total = sizes[0] + (contours == 2 ? sizes[1] : 0);
        for (int i = 0; i < total; i++) {
            double x = check_rng_range(&rng, -15, SIDE + 15),
                   y = check_rng_range(&rng, -15, SIDE + 15);
            if (trial % 4 == 1) { /* on the half-grid: centres and pixel edges */
                x = floor(x * 2) / 2;
                y = floor(y * 2) / 2;
            }
            points[i] = cg_vec2_make(x, y);
        }
        cg_fill_rule rule = trial % 2 ? CG_FILL_NONZERO : CG_FILL_EVEN_ODD;
        marks *m = new_marks("scan-lines");
        cg_image *image = blank();
        CHECK(cg_scanline_fill_steps(points, sizes, contours, rule, mark_step, m) == CG_OK);
        CHECK(cg_fill_polygon(image, points, sizes, contours, rule, white) == CG_OK);
        CHECK_MSG(compare(m, image, 1) == 0, "scanline trial %d: trace and cg_fill_polygon differ",
                  trial);
        cg_image_free(image);
        free(m);
    }
    cg_vec2 far[3] = {{0, 0}, {5000, 0}, {0, 5}};
    int three = 3;
    CHECK(cg_scanline_fill_steps(far, &three, 1, CG_FILL_EVEN_ODD, mark_step, NULL) == CG_ERANGE);
    CHECK(cg_scanline_fill_steps(far, &three, 1, (cg_fill_rule)7, mark_step, NULL) == CG_EINVAL);
}

/* Random walls: a few lines and circles of two colours on white, and
 * noise, so that regions are ragged and touch diagonally. */
static cg_image *random_walls(check_rng *rng)
{
    cg_image *image = blank();
    cg_image_clear_rgba8(image, white);
    cg_rgba8 walls[2] = {{0, 0, 0, 255}, {10, 0, 0, 255}};
    for (int i = 0; i < 6; i++) {
        cg_rgba8 c = walls[i % 2];
        int a = (int)check_rng_int(rng, 0, SIDE - 1), b = (int)check_rng_int(rng, 0, SIDE - 1);
        if (i % 3 == 2)
            cg_draw_circle(image, a, b, (int)check_rng_int(rng, 3, 30), c);
        else
            cg_draw_line(image, a, b, (int)check_rng_int(rng, 0, SIDE - 1),
                         (int)check_rng_int(rng, 0, SIDE - 1), c);
    }
    for (int i = 0; i < 150; i++)
        cg_image_set_rgba8(image, (int)check_rng_int(rng, 0, SIDE - 1),
                           (int)check_rng_int(rng, 0, SIDE - 1), walls[i % 2]);
    return image;
}

static void flood_agrees(void)
{
    check_rng rng = {0xf100d};
    const cg_rgba8 paint = {0, 200, 0, 255};
    for (int trial = 0; trial < 400; trial++) {
        cg_image *image = random_walls(&rng), *painted;
        cg_image_copy(image, &painted);
        int x = (int)check_rng_int(&rng, 0, SIDE - 1), y = (int)check_rng_int(&rng, 0, SIDE - 1);
        cg_connectivity c = trial % 2 ? CG_CONNECT_8 : CG_CONNECT_4;
        int tolerance = trial % 3 == 0 ? 20 : 0, boundary = trial % 4 >= 2;
        cg_rgba8 wall = {0, 0, 0, 255};
        marks *m = new_marks("stack");
        size_t filled = 0;
        if (boundary) {
            CHECK(cg_boundary_fill_steps(image, x, y, wall, c, tolerance, mark_step, m) == CG_OK);
            CHECK(cg_boundary_fill(painted, x, y, paint, wall, c, tolerance, &filled) == CG_OK);
        } else {
            CHECK(cg_flood_fill_steps(image, x, y, c, tolerance, mark_step, m) == CG_OK);
            CHECK(cg_flood_fill(painted, x, y, paint, c, tolerance, &filled) == CG_OK);
        }
        /* the pixels the library painted: those now of the paint colour */
        cg_image *changed = blank();
        for (int j = 0; j < SIDE; j++)
            for (int i = 0; i < SIDE; i++)
                if (cg_image_get_rgba8(painted, i, j).g == 200)
                    cg_image_set_rgba8(changed, i, j, white);
        CHECK_MSG(compare(m, changed, 1) == 0,
                  "fill trial %d from (%d, %d): trace and library differ", trial, x, y);
        CHECK_EQ_INT(m->listed, filled);
        cg_image_free(image);
        cg_image_free(painted);
        cg_image_free(changed);
        free(m);
    }
    cg_image *image = blank();
    CHECK(cg_flood_fill_steps(image, -1, 0, CG_CONNECT_4, 0, mark_step, NULL) == CG_ERANGE);
    CHECK(cg_flood_fill_steps(image, 0, 0, (cg_connectivity)5, 0, mark_step, NULL) == CG_EINVAL);
    cg_image_free(image);
}

/* ---- clipping ---------------------------------------------------------------- */

static void liang_barsky_agrees(void)
{
    check_rng rng = {0x1b};
    int accepted_count = 0, rejected_count = 0;
    for (int trial = 0; trial < 4000; trial++) {
        cg_rect w = {check_rng_range(&rng, -10, 0), check_rng_range(&rng, -10, 0),
                     check_rng_range(&rng, 0, 10), check_rng_range(&rng, 0, 10)};
        cg_vec2 p0 = {check_rng_range(&rng, -20, 20), check_rng_range(&rng, -20, 20)};
        cg_vec2 p1 = {check_rng_range(&rng, -20, 20), check_rng_range(&rng, -20, 20)};
        if (trial % 8 == 0) /* vertical and horizontal lines: p = 0 */
            p1.x = p0.x;
        if (trial % 8 == 1)
            p1.y = p0.y;
        cg_vec2 c0 = p0, c1 = p1;
        int accepted;
        CHECK(cg_clip_line_liang_barsky(w, &c0, &c1, &accepted) == CG_OK);
        cg_step_log *log;
        cg_step_log_create(&log);
        CHECK(cg_liang_barsky_steps(w, p0, p1, cg_step_log_record, log) == CG_OK);
        size_t count = cg_step_log_count(log);
        const cg_step *last = cg_step_log_get(log, count - 1);
        const cg_step_field *outcome = cg_step_find(last, "outcome");
        CHECK(outcome && strcmp(outcome->text, accepted ? "accept" : "reject") == 0);
        /* the trace's own t_enter and t_exit give the same part */
        const cg_step *boundary = cg_step_log_get(log, count - 2);
        double t0 = cg_step_find(boundary, "t_enter")->real,
               t1 = cg_step_find(boundary, "t_exit")->real;
        int traced_accept = t0 <= t1 && !strstr(cg_step_find(boundary, "kind")->text, "reject");
        CHECK_EQ_INT(traced_accept, accepted);
        if (accepted) {
            accepted_count++;
            const cg_step_field *from = cg_step_find(last, "from"), *to = cg_step_find(last, "to");
            CHECK(from->point.x == c0.x && from->point.y == c0.y && to->point.x == c1.x
                  && to->point.y == c1.y);
            cg_vec2 d = cg_vec2_sub(p1, p0);
            CHECK_NEAR(p0.x + t0 * d.x, c0.x, 1e-9);
            CHECK_NEAR(p0.y + t0 * d.y, c0.y, 1e-9);
            CHECK_NEAR(p0.x + t1 * d.x, c1.x, 1e-9);
            CHECK_NEAR(p0.y + t1 * d.y, c1.y, 1e-9);
        } else {
            rejected_count++;
        }
        /* p and q as the notes define them */
        const cg_step *left = cg_step_log_get(log, 0);
        CHECK(strcmp(cg_step_find(left, "boundary")->text, "left") == 0);
        CHECK(cg_step_find(left, "p")->real == -(p1.x - p0.x)
              && cg_step_find(left, "q")->real == p0.x - w.xmin);
        cg_step_log_free(log);
    }
    CHECK(accepted_count > 500 && rejected_count > 500);
}

static void cohen_sutherland_agrees(void)
{
    check_rng rng = {0xc5};
    for (int trial = 0; trial < 2000; trial++) {
        cg_rect w = {check_rng_range(&rng, -10, 0), check_rng_range(&rng, -10, 0),
                     check_rng_range(&rng, 0, 10), check_rng_range(&rng, 0, 10)};
        cg_vec2 p0 = {check_rng_range(&rng, -20, 20), check_rng_range(&rng, -20, 20)};
        cg_vec2 p1 = {check_rng_range(&rng, -20, 20), check_rng_range(&rng, -20, 20)};
        cg_vec2 c0 = p0, c1 = p1;
        int accepted;
        CHECK(cg_clip_line_cohen_sutherland(w, &c0, &c1, &accepted, NULL, NULL) == CG_OK);
        cg_step_log *log;
        cg_step_log_create(&log);
        CHECK(cg_cohen_sutherland_steps(w, p0, p1, cg_step_log_record, log) == CG_OK);
        const cg_step *last = cg_step_log_get(log, cg_step_log_count(log) - 1);
        CHECK(strcmp(cg_step_find(last, "outcome")->text, accepted ? "accept" : "reject") == 0);
        if (accepted) {
            cg_vec2 from = cg_step_find(last, "from")->point, to = cg_step_find(last, "to")->point;
            CHECK(from.x == c0.x && from.y == c0.y && to.x == c1.x && to.y == c1.y);
        }
        /* every step's codes are the region codes of its endpoints */
        for (size_t i = 0; i + 1 < cg_step_log_count(log); i++) {
            const cg_step *s = cg_step_log_get(log, i);
            unsigned code = cg_clip_rcode(w, cg_step_find(s, "p0")->point);
            const char *text = cg_step_find(s, "code0")->text;
            CHECK(((code & CG_RCODE_TOP) != 0) == (text[0] == '1')
                  && ((code & CG_RCODE_LEFT) != 0) == (text[3] == '1'));
        }
        cg_step_log_free(log);
    }
}

/* The last "output" list of a Sutherland-Hodgman trace (the lists step of
 * the last clip edge). */
typedef struct last_list {
    cg_vec2 p[1024];
    size_t n;
    int seen;
} last_list;

static int keep_lists(void *user, const cg_step *s)
{
    last_list *l = user;
    const cg_step_field *input = cg_step_find(s, "input"), *output = cg_step_find(s, "output");
    if (input && output) {
        l->n = output->point_count < 1024 ? output->point_count : 1024;
        if (l->n)
            memcpy(l->p, output->points, l->n * sizeof l->p[0]);
        l->seen++;
    }
    return 0;
}

static void sutherland_hodgman_agrees(void)
{
    check_rng rng = {0x5a};
    static last_list list;
    for (int trial = 0; trial < 1500; trial++) {
        /* a convex window: points on a circle in order; a random subject */
        int m = (int)check_rng_int(&rng, 3, 8), n = (int)check_rng_int(&rng, 3, 12);
        cg_vec2 window[8], subject[12];
        double start = check_rng_range(&rng, 0, 6.28);
        for (int i = 0; i < m; i++) {
            double a = start + 6.283185307179586 * (i + check_rng_range(&rng, 0.1, 0.9)) / m;
            window[i] = cg_vec2_make(10 * cos(a), 10 * sin(a));
        }
        if (trial % 2) /* clockwise windows too */
            for (int i = 0; i < m / 2; i++) {
                cg_vec2 t = window[i];
                window[i] = window[m - 1 - i];
                window[m - 1 - i] = t;
            }
        random_points(&rng, subject, n, 15);
        if (trial % 10 == 0) /* vertices on the window's corners */
            subject[0] = window[0];
        cg_vec2 *result = NULL;
        size_t count = 0;
        cg_status a = cg_clip_sutherland_hodgman(subject, (size_t)n, window, (size_t)m, &result,
                                                 &count);
        memset(&list, 0, sizeof list);
        cg_status b = cg_sutherland_hodgman_steps(subject, (size_t)n, window, (size_t)m, keep_lists,
                                                  &list);
        CHECK(a == b);
        if (a == CG_OK) {
            CHECK(list.seen >= 1);
            CHECK_MSG(list.n == count
                          && (count == 0 || memcmp(list.p, result, count * sizeof *result) == 0),
                      "trial %d: the trace's last list (%zu points) is not the library's (%zu)",
                      trial, list.n, count);
        }
        free(result);
    }
    /* A non-convex window is refused as by the library. */
    cg_vec2 dart[4] = {{0, 0}, {10, 0}, {2, 2}, {0, 10}},
            square[4] = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    CHECK(cg_sutherland_hodgman_steps(square, 4, dart, 4, keep_lists, &list) == CG_EINVAL);
}

/* A random simple polygon: star-shaped around c, angles in order. */
static int random_star(check_rng *rng, cg_vec2 c, double radius, cg_vec2 *out)
{
    int n = (int)check_rng_int(rng, 3, 10);
    double angles[10];
    for (int i = 0; i < n; i++)
        angles[i] = 6.283185307179586 * (i + check_rng_range(rng, 0.05, 0.95)) / n;
    for (int i = 0; i < n; i++) {
        double r = radius * check_rng_range(rng, 0.3, 1);
        out[i] = cg_vec2_make(c.x + r * cos(angles[i]), c.y + r * sin(angles[i]));
    }
    return n;
}

static int same_ring(const cg_vec2 *a, size_t an, const cg_vec2 *b, size_t bn)
{
    return an == bn && memcmp(a, b, an * sizeof *a) == 0;
}

static void weiler_atherton_agrees(void)
{
    check_rng rng = {0x3a};
    int with_crossings = 0, with_holes = 0;
    for (int trial = 0; trial < 800; trial++) {
        cg_vec2 subject[10], window[10];
        int n = random_star(&rng, cg_vec2_make(0, 0), 10, subject);
        int m = random_star(
            &rng, cg_vec2_make(check_rng_range(&rng, -8, 8), check_rng_range(&rng, -8, 8)),
            check_rng_range(&rng, 3, 14), window);
        if (trial % 2) /* clockwise input too */
            for (int i = 0; i < n / 2; i++) {
                cg_vec2 t = subject[i];
                subject[i] = subject[n - 1 - i];
                subject[n - 1 - i] = t;
            }
        cg_polygon_set result = {0};
        CHECK(cg_clip_weiler_atherton(subject, (size_t)n, window, (size_t)m, &result) == CG_OK);
        cg_step_log *log;
        cg_step_log_create(&log);
        CHECK(
            cg_weiler_atherton_steps(subject, (size_t)n, window, (size_t)m, cg_step_log_record, log)
            == CG_OK);
        /* the loops kept are the library's rings, and the result steps list them */
        size_t loops = 0, results = 0, rings_found = 0;
        for (size_t i = 0; i < cg_step_log_count(log); i++) {
            const cg_step *st = cg_step_log_get(log, i);
            if (st->phase && strcmp(st->phase, "loops") == 0
                && strcmp(cg_step_find(st, "kept")->text, "yes") == 0) {
                loops++;
                const cg_step_field *ring = cg_step_find(st, "ring");
                for (size_t r = 0; r < result.ring_count; r++)
                    rings_found += same_ring(ring->points, ring->point_count,
                                             result.points + result.ring_start[r],
                                             result.ring_start[r + 1] - result.ring_start[r]);
            }
            if (st->phase && strcmp(st->phase, "result") == 0) {
                const cg_step_field *ring = cg_step_find(st, "ring");
                CHECK(results < result.ring_count
                      && same_ring(ring->points, ring->point_count,
                                   result.points + result.ring_start[results],
                                   result.ring_start[results + 1] - result.ring_start[results]));
                results++;
            }
            if (st->phase && strcmp(st->phase, "crossings") == 0
                && cg_step_find(st, "crossing")->text[1] == '0')
                with_crossings++;
        }
        CHECK_EQ_INT(results, result.ring_count);
        if (loops > 0) {
            CHECK_EQ_INT(loops, result.ring_count);
            CHECK_EQ_INT(rings_found, result.ring_count);
        }
        with_holes += result.ring_count > result.polygon_count;
        cg_step_log_free(log);
        cg_polygon_set_clear(&result);
    }
    CHECK(with_crossings > 300);
    (void)with_holes;
    cg_vec2 two[2] = {{0, 0}, {1, 1}};
    CHECK(cg_weiler_atherton_steps(two, 2, two, 2, stop_after_three, NULL) == CG_EINVAL);
}

static int keep_last_output3(void *user, const cg_step *s)
{
    const cg_step_field *input = cg_step_find(s, "input"), *output = cg_step_find(s, "output");
    double *last = user;
    if (input && output) {
        last[0] = (double)output->real_count;
        if (output->real_count)
            memcpy(last + 1, output->reals, output->real_count * sizeof *last);
    }
    return 0;
}

static void frustum_agrees(void)
{
    check_rng rng = {0xf7};
    static double last[1 + 3 * 64];
    for (int trial = 0; trial < 1000; trial++) {
        cg_mat4 view, projection;
        cg_view_look_at(cg_vec3_make(check_rng_range(&rng, -3, 3), check_rng_range(&rng, -3, 3), 6),
                        cg_vec3_make(0, 0, 0), cg_vec3_make(0, 1, 0), &view);
        cg_proj_perspective(1, 4.0 / 3, 1, 20, &projection);
        cg_plane planes[6];
        cg_frustum_planes(cg_mat4_mul(projection, view), planes);
        int n = (int)check_rng_int(&rng, 3, 8);
        cg_vec3 polygon[8];
        for (int i = 0; i < n; i++)
            polygon[i] = cg_vec3_make(check_rng_range(&rng, -8, 8), check_rng_range(&rng, -8, 8),
                                      check_rng_range(&rng, -30, 8));
        cg_vec3 *result = NULL;
        size_t count = 0;
        CHECK(cg_clip_polygon_planes(polygon, (size_t)n, planes, 6, &result, &count) == CG_OK);
        last[0] = -1;
        CHECK(cg_clip_planes_steps(polygon, (size_t)n, planes, 6, NULL, keep_last_output3, last)
              == CG_OK);
        CHECK_EQ_INT(last[0], 3 * (double)count);
        for (size_t i = 0; i < count && last[0] == 3 * (double)count; i++)
            CHECK(last[1 + 3 * i] == result[i].x && last[2 + 3 * i] == result[i].y
                  && last[3 + 3 * i] == result[i].z);
        free(result);
    }
}

/* ---- the log and bad input ------------------------------------------------------ */

static int stop_after_three(void *user, const cg_step *s)
{
    (void)s;
    return ++*(int *)user >= 3;
}

static void log_and_bad_input(void)
{
    int calls = 0;
    CHECK(cg_line_steps(0, 0, 40, 7, stop_after_three, &calls) == CG_OK);
    CHECK_EQ_INT(calls, 3);
    cg_step_log *log;
    CHECK(cg_step_log_create(&log) == CG_OK);
    cg_vec2 control[3] = {{0, 0}, {5, 9}, {10, 0}};
    CHECK(cg_casteljau_steps(control, 3, 0.25, cg_step_log_record, log) == CG_OK);
    CHECK(cg_step_log_status(log) == CG_OK);
    const cg_step *s = cg_step_log_get(log, 0);
    CHECK(s && s->phase && strcmp(s->phase, "levels") == 0 && s->geometry_count == 3);
    CHECK(cg_step_log_get(log, 99) == NULL);
    CHECK(cg_step_find(s, "no such field") == NULL);
    cg_step_log_free(log);
    cg_step_log_free(NULL);
    CHECK(cg_line_steps(0, 0, 2000000, 0, cg_step_log_record, NULL) == CG_ERANGE);
    CHECK(cg_line_steps(0, 0, 1, 1, NULL, NULL) == CG_EINVAL);
    CHECK(cg_circle_steps(0, 0, -1, stop_after_three, &calls) == CG_EINVAL);
    CHECK(cg_ellipse_steps(0, 0, 30000, 3, stop_after_three, &calls) == CG_ERANGE);
    CHECK(cg_casteljau_steps(control, 1, 0.5, stop_after_three, &calls) == CG_EINVAL);
    cg_vec2 bad[2] = {{0, 0}, {NAN, 1}};
    CHECK(cg_casteljau_steps(bad, 2, 0.5, stop_after_three, &calls) == CG_EINVAL);
    CHECK(cg_bezier_flatten_steps(control, 3, 0, stop_after_three, &calls) == CG_EINVAL);
    CHECK(cg_bezier_flatten_steps(control, 3, 1e-30, stop_after_three, &calls) == CG_ERANGE);
    cg_cubic2 curve = {CG_BASIS_BEZIER, {{0, 0}, {1, 1}, {2, 1}, {3, 0}}};
    CHECK(cg_cubic_steps(&curve, 0, stop_after_three, &calls) == CG_EINVAL);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(line_agrees);
    CHECK_GROUP(dda_definition);
    CHECK_GROUP(wu_agrees);
    CHECK_GROUP(circle_agrees);
    CHECK_GROUP(ellipse_agrees);
    CHECK_GROUP(casteljau_agrees);
    CHECK_GROUP(cubic_agrees);
    CHECK_GROUP(flatten_agrees);
    CHECK_GROUP(hemesh_agrees);
    CHECK_GROUP(pipeline_agrees);
    CHECK_GROUP(vanishing_agrees);
    CHECK_GROUP(backface_agrees);
    CHECK_GROUP(zbuffer_agrees);
    CHECK_GROUP(color_agrees);
    CHECK_GROUP(light_agrees);
    CHECK_GROUP(scanline_agrees);
    CHECK_GROUP(flood_agrees);
    CHECK_GROUP(cohen_sutherland_agrees);
    CHECK_GROUP(liang_barsky_agrees);
    CHECK_GROUP(sutherland_hodgman_agrees);
    CHECK_GROUP(weiler_atherton_agrees);
    CHECK_GROUP(frustum_agrees);
    CHECK_GROUP(log_and_bad_input);
    return check_finish();
}
