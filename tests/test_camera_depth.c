/* Cameras placed by hand, away from the line through the mesh's centre:
 * random triangles anywhere in the view volume (perspective and parallel,
 * wide depth ranges, parallel ones reaching behind the eye) are drawn
 * exactly as the pixel-centre rule says, by the z-buffer, the painter's
 * algorithm and the ray tracer, once cg_camera_fit_depth has set near and
 * far.  The expected coverage is computed here from the screen positions
 * the triangles were made from (1/256-pixel grid points), with the
 * top-left rule in exact integers. */
#include "check.h"
#include "cg.h"

#include <string.h>

enum { WIDTH = 72, HEIGHT = 54, TRIANGLES = 10 };

typedef struct screen_triangle {
    long long x[3], y[3]; /* 1/256 pixel, y down */
} screen_triangle;

static long long edge(long long ax, long long ay, long long bx, long long by, long long px,
                      long long py)
{
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/* Whether the centre of pixel (x, y) is inside t by the top-left rule;
 * *on_edge set when it lies exactly on an edge line, *near_edge when
 * within 1/256 pixel of one. */
static int covers(const screen_triangle *t, int x, int y, int *on_edge, int *near_edge)
{
    long long X[3], Y[3];
    memcpy(X, t->x, sizeof X);
    memcpy(Y, t->y, sizeof Y);
    long long area = edge(X[0], Y[0], X[1], Y[1], X[2], Y[2]);
    if (area < 0) {
        long long s = X[1];
        X[1] = X[2];
        X[2] = s;
        s = Y[1];
        Y[1] = Y[2];
        Y[2] = s;
    }
    long long px = (long long)x * 256 + 128, py = (long long)y * 256 + 128;
    int inside = 1;
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        long long e = edge(X[i], Y[i], X[j], Y[j], px, py);
        if (e == 0)
            *on_edge = 1;
        if ((double)e * e
            <= (double)((X[j] - X[i]) * (X[j] - X[i]) + (Y[j] - Y[i]) * (Y[j] - Y[i])))
            *near_edge = 1;
        if (e < 0) {
            inside = 0;
        } else if (e == 0) {
            long long dx = X[j] - X[i], dy = Y[j] - Y[i];
            if (!((dy == 0 && dx > 0) || dy < 0))
                inside = 0;
        }
    }
    return inside;
}

/* A random camera: eye anywhere, looking anywhere, up anywhere. */
static cg_camera random_camera(check_rng *rng, int orthographic)
{
    cg_camera c = cg_camera_default();
    for (;;) {
        c.eye = cg_vec3_make(check_rng_range(rng, -80, 80), check_rng_range(rng, -80, 80),
                             check_rng_range(rng, -80, 80));
        cg_vec3 d = cg_vec3_make(check_rng_range(rng, -1, 1), check_rng_range(rng, -1, 1),
                                 check_rng_range(rng, -1, 1));
        c.up = cg_vec3_make(check_rng_range(rng, -1, 1), check_rng_range(rng, -1, 1),
                            check_rng_range(rng, -1, 1));
        double dl = cg_vec3_length(d);
        if (dl > 0.2 && cg_vec3_length(cg_vec3_cross(d, c.up)) > 0.2 * dl * cg_vec3_length(c.up)) {
            c.target = cg_vec3_add(c.eye, cg_vec3_scale(d, check_rng_range(rng, 0.5, 50) / dl));
            break;
        }
    }
    c.orthographic = orthographic;
    c.fovy = cg_radians(check_rng_range(rng, 20, 150));
    c.ortho_height = check_rng_range(rng, 1, 300);
    return c;
}

/* The view-space point that the camera shows at screen point (sx, sy) in
 * pixels at depth d along the view. */
static cg_vec3 unproject(const cg_camera *c, double sx, double sy, double d)
{
    double aspect = (double)WIDTH / HEIGHT;
    double nx = 2 * sx / WIDTH - 1, ny = 1 - 2 * sy / HEIGHT;
    double half = c->orthographic ? c->ortho_height / 2 : d * tan(c->fovy / 2);
    return cg_vec3_make(nx * half * aspect, ny * half, -d);
}

/* TRIANGLES triangles whose vertices sit on 1/256-pixel grid points of a
 * random part of the picture (so the mesh's centre is off the view axis),
 * at depths spread over three decades (a parallel camera's also behind
 * the eye). */
static cg_mesh *random_triangles(check_rng *rng, const cg_camera *c, screen_triangle *t)
{
    cg_mat4 view, inverse_view;
    cg_camera_view(c, &view);
    cg_mat4_inverse(view, &inverse_view);
    double x0 = check_rng_range(rng, 0, WIDTH * 0.6), x1 = check_rng_range(rng, x0 + 8, WIDTH);
    double y0 = check_rng_range(rng, 0, HEIGHT * 0.6), y1 = check_rng_range(rng, y0 + 8, HEIGHT);
    double scale = check_rng_range(rng, 0.5, 200);
    cg_mesh *m = NULL;
    cg_mesh_create(&m, TRIANGLES * 3, TRIANGLES, TRIANGLES * 3, 0);
    for (int i = 0; i < TRIANGLES; i++) {
        do {
            for (int k = 0; k < 3; k++) {
                t[i].x[k] = (long long)floor(check_rng_range(rng, x0, x1) * 256);
                t[i].y[k] = (long long)floor(check_rng_range(rng, y0, y1) * 256);
            }
        } while (edge(t[i].x[0], t[i].y[0], t[i].x[1], t[i].y[1], t[i].x[2], t[i].y[2]) == 0);
        for (int k = 0; k < 3; k++) {
            double d = scale * pow(10, check_rng_range(rng, -1.5, 1.5));
            if (c->orthographic && check_rng_unit(rng) < 0.3)
                d = -d;
            cg_vec3 p = unproject(c, t[i].x[k] / 256.0, t[i].y[k] / 256.0, d);
            m->positions[i * 3 + k] = cg_mat4_transform_point(inverse_view, p);
            m->face_indices[i * 3 + k] = (uint32_t)(i * 3 + k);
        }
        m->face_offsets[i + 1] = (uint32_t)(i * 3 + 3);
    }
    return m;
}

static cg_image *render_raster(const cg_mesh *m, const cg_camera *c, cg_render_algorithm a)
{
    cg_render_options o;
    cg_render_options_default(&o);
    o.algorithm = a;
    o.camera = *c;
    o.frame_camera = 0;
    o.cull = CG_CULL_NONE;
    o.shading = CG_SHADING_FLAT;
    o.background = (cg_rgbaf){0, 0, 0, 1};
    o.color = (cg_rgbaf){1, 1, 1, 1};
    o.ambient = 1;
    o.specular = 0;
    cg_image *img = NULL;
    cg_renderer *r = NULL;
    cg_image_create(&img, WIDTH, HEIGHT, CG_PIXEL_RGBA8);
    CHECK(cg_renderer_create(m, &o, &r, NULL) == CG_OK);
    CHECK(r && cg_renderer_draw(r, img) == CG_OK);
    cg_renderer_free(r);
    return img;
}

static cg_image *render_traced(const cg_mesh *m, const cg_camera *c)
{
    cg_trace_scene *scene = NULL;
    cg_trace_material material = cg_trace_material_default();
    material.surface.ka = 1;
    cg_light ambient = cg_light_ambient(cg_vec3_make(1, 1, 1));
    CHECK(cg_trace_scene_create(&scene) == CG_OK);
    CHECK(cg_trace_scene_add_mesh(scene, m, NULL, 0, &material) == CG_OK);
    CHECK(cg_trace_scene_add_light(scene, &ambient) == CG_OK);
    cg_trace_options o = cg_trace_options_default();
    o.background = (cg_rgbaf){0, 0, 0, 1};
    o.shadows = 0;
    o.max_depth = 0;
    o.clip_depth = 1; /* the rasterizer's view volume: near and far must enclose them */
    cg_image *img = NULL;
    cg_image_create(&img, WIDTH, HEIGHT, CG_PIXEL_RGBA8);
    CHECK(cg_trace_render(scene, c, &o, img, NULL) == CG_OK);
    cg_trace_scene_free(scene);
    return img;
}

/* What a renderer may leave undecided: nothing (the rasterizer), centres
 * exactly on an edge line, where the rule decides a tie (the ray tracer
 * intersects the triangles themselves, not snapped ones), or centres within
 * 1/256 pixel of an edge (the painter's algorithm snaps the points where it
 * splits a polygon, which may move its outline by that much). */
enum { EXACT, SKIP_TIES, SKIP_NEAR_EDGES };

/* Pixels where the picture and the expected coverage disagree. */
static int mismatches(const cg_image *img, const screen_triangle *t, int skip, int *checked)
{
    int wrong = 0;
    for (int y = 0; y < HEIGHT; y++)
        for (int x = 0; x < WIDTH; x++) {
            int want = 0, tie = 0, near_edge = 0;
            for (int i = 0; i < TRIANGLES; i++)
                want |= covers(&t[i], x, y, &tie, &near_edge);
            if ((skip == SKIP_TIES && tie) || (skip == SKIP_NEAR_EDGES && near_edge))
                continue;
            cg_rgba8 p = cg_image_get_rgba8((cg_image *)img, x, y);
            wrong += (p.r > 0) != want;
            ++*checked;
        }
    return wrong;
}

static void test_coverage(void)
{
    check_rng rng = {1812};
    int wrong[3] = {0, 0, 0}, checked[3] = {0, 0, 0}, covered = 0;
    for (int scene = 0; scene < 60; scene++) {
        int orthographic = scene % 2;
        cg_camera c = random_camera(&rng, orthographic);
        screen_triangle t[TRIANGLES];
        cg_mesh *m = random_triangles(&rng, &c, t);
        cg_vec3 lo, hi;
        CHECK(cg_mesh_bounds(m, &lo, &hi) == CG_OK);
        CHECK(cg_camera_fit_depth(&c, lo, hi) == CG_OK);
        if (orthographic)
            CHECK(c.near < c.far);
        else
            CHECK(c.near > 0 && c.near < c.far);
        cg_image *z = render_raster(m, &c, CG_RENDER_ZBUFFER);
        cg_image *p = render_raster(m, &c, CG_RENDER_PAINTER);
        cg_image *r = render_traced(m, &c);
        int before = checked[0], w[3];
        w[0] = mismatches(z, t, EXACT, &checked[0]);
        w[1] = mismatches(p, t, SKIP_NEAR_EDGES, &checked[1]);
        w[2] = mismatches(r, t, SKIP_TIES, &checked[2]);
        for (int k = 0; k < 3; k++)
            wrong[k] += w[k];
        CHECK_MSG(w[0] == 0 && w[1] == 0 && w[2] == 0,
                  "%s camera %d: %d, %d, %d pixels wrong (z-buffer, painter's, ray tracer) "
                  "of %d; near %g far %g",
                  orthographic ? "parallel" : "perspective", scene, w[0], w[1], w[2],
                  checked[0] - before, c.near, c.far);
        for (int y = 0; y < HEIGHT; y++)
            for (int x = 0; x < WIDTH; x++)
                covered += cg_image_get_rgba8(z, x, y).r > 0;
        cg_image_free(z);
        cg_image_free(p);
        cg_image_free(r);
        cg_mesh_free(m);
    }
    /* The scenes are not empty: the check has something to see. */
    CHECK_MSG(covered > 3 * WIDTH * HEIGHT, "only %d pixels covered in all", covered);
    printf("coverage: %d, %d, %d pixels checked (z-buffer, painter's, ray tracer), %d covered\n",
           checked[0], checked[1], checked[2], covered);
}

/* The depth range encloses exactly the box's corners along the view: every
 * corner within [near, far] and the extreme ones within the padding. */
static void test_fit_depth_definition(void)
{
    check_rng rng = {77};
    for (int i = 0; i < 2000; i++) {
        cg_camera c = random_camera(&rng, i % 2);
        cg_vec3 a = {check_rng_range(&rng, -100, 100), check_rng_range(&rng, -100, 100),
                     check_rng_range(&rng, -100, 100)};
        cg_vec3 size = {check_rng_range(&rng, 0, 50), check_rng_range(&rng, 0, 50),
                        check_rng_range(&rng, 0, 50)};
        cg_vec3 b = cg_vec3_add(a, size);
        CHECK(cg_camera_fit_depth(&c, a, b) == CG_OK);
        cg_mat4 view;
        cg_camera_view(&c, &view);
        double dmin = INFINITY, dmax = -INFINITY;
        for (int k = 0; k < 8; k++) {
            cg_vec3 p = {k & 1 ? b.x : a.x, k & 2 ? b.y : a.y, k & 4 ? b.z : a.z};
            double d = -cg_mat4_transform_point(view, p).z;
            dmin = fmin(dmin, d);
            dmax = fmax(dmax, d);
        }
        double room = 2e-3 * (dmax - dmin) + 2e-5 * fmax(fabs(dmin), fabs(dmax)) + 1e-9;
        if (!c.orthographic && dmax <= 0) { /* behind the eye: any valid range */
            CHECK(c.near > 0 && c.far > c.near);
            continue;
        }
        CHECK(c.far >= dmax && c.far <= dmax + room);
        if (c.orthographic || dmin >= c.far * 1e-4)
            CHECK(c.near <= dmin && c.near >= dmin - room
                  && (c.orthographic || c.near >= dmin * 0.999));
        else
            CHECK(c.near == c.far * 1e-4);
    }
    cg_camera c = cg_camera_default();
    cg_vec3 lo = {0, 0, 0}, hi = {1, 1, 1}, nan = {NAN, 0, 0};
    CHECK(cg_camera_fit_depth(NULL, lo, hi) == CG_EINVAL);
    CHECK(cg_camera_fit_depth(&c, hi, lo) == CG_EINVAL);
    CHECK(cg_camera_fit_depth(&c, nan, hi) == CG_EINVAL);
    c.up = cg_vec3_make(0, 0, 1); /* along the view */
    CHECK(cg_camera_fit_depth(&c, lo, hi) == CG_EINVAL);
}

/* Framing: every corner of the box projects inside the picture, and the
 * projected box touches two opposite sides less the 5% margin. */
static void test_frame_tight(void)
{
    check_rng rng = {4242};
    double aspect = (double)WIDTH / HEIGHT;
    int standoffs = 0;
    for (int i = 0; i < 2000; i++) {
        cg_camera c = random_camera(&rng, i % 2);
        cg_vec3 a = {check_rng_range(&rng, -100, 100), check_rng_range(&rng, -100, 100),
                     check_rng_range(&rng, -100, 100)};
        cg_vec3 b = cg_vec3_add(a, cg_vec3_make(check_rng_range(&rng, 0.1, 50),
                                                check_rng_range(&rng, 0.1, 50),
                                                check_rng_range(&rng, 0.1, 50)));
        cg_vec3 direction = cg_vec3_normalize(cg_vec3_sub(c.target, c.eye));
        CHECK(cg_camera_frame(&c, a, b, aspect) == CG_OK);
        CHECK(
            cg_vec3_length(cg_vec3_sub(cg_vec3_normalize(cg_vec3_sub(c.target, c.eye)), direction))
            < 1e-9);
        cg_mat4 view, projection;
        CHECK(cg_camera_view(&c, &view) == CG_OK);
        CHECK(cg_camera_projection(&c, aspect, &projection) == CG_OK);
        cg_mat4 vp = cg_mat4_mul(projection, view);
        double ex = 0, ey = 0, nearest = INFINITY;
        double diagonal = cg_vec3_length(cg_vec3_sub(b, a));
        int inside = 1;
        for (int k = 0; k < 8; k++) {
            cg_vec3 p = {k & 1 ? b.x : a.x, k & 2 ? b.y : a.y, k & 4 ? b.z : a.z};
            int visible;
            cg_vec3 n = cg_project_point(vp, p, &visible);
            inside &= visible && fabs(n.x) <= 1 + 1e-9 && fabs(n.y) <= 1 + 1e-9 && n.z >= -1 - 1e-9
                      && n.z <= 1 + 1e-9;
            nearest = fmin(nearest, -cg_mat4_transform_point(view, p).z);
            ex = fmax(ex, fabs(n.x));
            ey = fmax(ey, fabs(n.y));
        }
        CHECK_MSG(inside, "frame %d: a corner outside the view", i);
        double fill = fmax(ex, ey);
        /* A wide perspective view seeing a corner head-on may fit from
         * nearer than the eye's standoff of 1/20 diagonal allows. */
        if (!c.orthographic && fabs(nearest - 0.05 * diagonal) < 1e-9 * diagonal) {
            CHECK(fill <= 1 / 1.05 + 1e-9);
            standoffs++;
            continue;
        }
        CHECK_MSG(fill > 1 / 1.05 - 1e-9 && fill < 1 / 1.05 + 1e-9,
                  "frame %d (%s): the box reaches %g of the picture", i,
                  c.orthographic ? "parallel" : "perspective", fill);
    }
    CHECK_MSG(standoffs < 400, "%d of 2000 framings stopped at the standoff", standoffs);
}

/* Looking along up: another up, perpendicular, signed as a camera pitching
 * onto the direction; any other up is kept. */
static void test_up_for(void)
{
    cg_vec3 y = {0, 1, 0};
    cg_vec3 down = cg_camera_up_for(cg_vec3_make(0, -3, 0), y);
    cg_vec3 up = cg_camera_up_for(cg_vec3_make(0, 2, 0), y);
    CHECK(down.x == 0 && down.y == 0 && down.z == -1);
    CHECK(up.x == 0 && up.y == 0 && up.z == 1);
    cg_vec3 kept = cg_camera_up_for(cg_vec3_make(0, -1, 0.5), y);
    CHECK(kept.x == 0 && kept.y == 1 && kept.z == 0);
    check_rng rng = {9};
    for (int i = 0; i < 1000; i++) {
        cg_vec3 d = {check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1),
                     check_rng_range(&rng, -1, 1)};
        cg_vec3 u = cg_camera_up_for(d, cg_vec3_scale(d, check_rng_range(&rng, -3, 3)));
        CHECK(fabs(cg_vec3_length(u) - 1) < 1e-12 && fabs(cg_vec3_dot(u, d)) < 1e-12);
    }
    /* Framing a box from straight above with the default up works. */
    cg_camera c = cg_camera_default();
    c.eye = cg_vec3_make(0, 1, 0);
    c.target = cg_vec3_make(0, 0, 0);
    CHECK(cg_camera_frame(&c, cg_vec3_make(-1, -1, -1), cg_vec3_make(1, 1, 1), 1.5) == CG_OK);
    cg_mat4 view;
    CHECK(cg_camera_view(&c, &view) == CG_OK);
    CHECK(c.up.z == -1);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_fit_depth_definition);
    CHECK_GROUP(test_frame_tight);
    CHECK_GROUP(test_up_for);
    CHECK_GROUP(test_coverage);
    return check_finish();
}
