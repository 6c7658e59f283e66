/* The rendering pipeline: closed meshes covered exactly once, clipping with
 * the camera inside the mesh, the z-buffer against a brute-force per-pixel
 * depth search, painter's against z-buffer, perspective-correct
 * interpolation, culling, vertex normals, identical output on any thread
 * count, the renderer's float lighting against cg_light_shade, bad input. */
#include "cg/render.h"
#include "cg/color.h"
#include "cg/light.h"
#include "check.h"

#include <stdlib.h>
#include <string.h>

static cg_image *image(int w, int h, cg_pixel_format format)
{
    cg_image *img = NULL;
    cg_image_create(&img, w, h, format);
    return img;
}

static cg_render_options plain_options(void)
{
    cg_render_options o;
    cg_render_options_default(&o);
    o.background = (cg_rgbaf){0, 0, 0, 1};
    return o;
}

static int is_background(const cg_image *img, int x, int y, cg_rgba8 bg)
{
    cg_rgba8 p = cg_image_get_rgba8(img, x, y);
    return p.r == bg.r && p.g == bg.g && p.b == bg.b;
}

/* A convex closed mesh with back faces culled: every covered pixel gets
 * exactly one fragment (fragments == covered pixels), no holes inside. */
static void test_closed_mesh_once(void)
{
    /* A coarse sphere (triangles of many pixels) and a fine one (triangles
     * of a pixel or less, rasterized pixel by pixel). */
    cg_mesh *coarse, *fine;
    CHECK(cg_mesh_sphere(40, 23, 1.0, &coarse) == CG_OK);
    CHECK(cg_mesh_sphere(300, 151, 1.0, &fine) == CG_OK);
    cg_render_options o = plain_options();
    o.background = (cg_rgbaf){1, 0, 1, 1};
    cg_rgba8 bg = cg_linear_to_rgba8(o.background);
    const cg_vec3 eyes[] = {{0, 0, 5}, {3, 2, 1}, {0.1, 5, 0}, {-2, -1, -3}};
    for (int e = 0; e < 8; e++) {
        const cg_mesh *sphere = e < 4 ? coarse : fine;
        o.camera.eye = eyes[e % 4];
        o.shading = (cg_shading)(e % 3);
        o.threads = 1 + e % 3;
        cg_renderer *r;
        CHECK(cg_renderer_create(sphere, &o, &r, NULL) == CG_OK);
        cg_image *img = image(173, 129, CG_PIXEL_RGBA8);
        CHECK(cg_renderer_draw(r, img) == CG_OK);
        cg_render_stats stats = cg_renderer_stats(r);
        size_t covered = 0;
        for (int y = 0; y < img->height; y++)
            for (int x = 0; x < img->width; x++)
                covered += !is_background(img, x, y, bg);
        CHECK_MSG(stats.fragments == covered, "view %d: %zu fragments for %zu covered pixels", e,
                  stats.fragments, covered);
        CHECK(stats.culled > 0 && covered > 1000);
        /* No background pixel strictly inside the silhouette: a pixel
         * whose 4 neighbours at distance 3 are covered is covered. */
        int holes = 0;
        for (int y = 3; y < img->height - 3; y++)
            for (int x = 3; x < img->width - 3; x++)
                if (is_background(img, x, y, bg) && !is_background(img, x - 3, y, bg)
                    && !is_background(img, x + 3, y, bg) && !is_background(img, x, y - 3, bg)
                    && !is_background(img, x, y + 3, bg))
                    holes++;
        CHECK_MSG(holes == 0, "view %d: %d holes", e, holes);
        cg_image_free(img);
        cg_renderer_free(r);
    }
    cg_mesh_free(coarse);
    cg_mesh_free(fine);
}

/* The camera inside a closed sphere: triangles cross the near plane and
 * w <= 0; with culling off every pixel is covered by the inside. */
static void test_camera_inside(void)
{
    cg_mesh *sphere;
    cg_mesh_sphere(32, 16, 10.0, &sphere);
    cg_render_options o = plain_options();
    o.background = (cg_rgbaf){1, 0, 1, 1};
    cg_rgba8 bg = cg_linear_to_rgba8(o.background);
    o.frame_camera = 0;
    o.cull = CG_CULL_NONE;
    o.camera.near = 0.5;
    o.camera.far = 100;
    const cg_vec3 eyes[] = {{0, 0, 0}, {0, 8.5, 0}, {3, -2, 8.2}, {0, 0, -8.4}};
    for (int e = 0; e < 4; e++) {
        o.camera.eye = eyes[e];
        o.camera.target = cg_vec3_make(eyes[e].x + 1, eyes[e].y + 0.3 * e, eyes[e].z - 0.5);
        o.shading = (cg_shading)(e % 3);
        for (int alg = 0; alg < 2; alg++) {
            o.algorithm = alg ? CG_RENDER_PAINTER : CG_RENDER_ZBUFFER;
            cg_renderer *r;
            cg_renderer_create(sphere, &o, &r, NULL);
            cg_image *img = image(96, 64, CG_PIXEL_RGBA8);
            CHECK(cg_renderer_draw(r, img) == CG_OK);
            int missing = 0;
            for (int y = 0; y < img->height; y++)
                for (int x = 0; x < img->width; x++)
                    missing += is_background(img, x, y, bg);
            cg_render_stats s = cg_renderer_stats(r);
            CHECK_MSG(missing == 0, "eye %d algorithm %d: %d pixels show the background", e, alg,
                      missing);
            CHECK(s.clipped > 0);
            if (alg == 0)
                CHECK_MSG(s.fragments == (size_t)96 * 64 || e != 0,
                          "from the centre every pixel is covered once: %zu", s.fragments);
            cg_image_free(img);
            cg_renderer_free(r);
        }
    }
    cg_mesh_free(sphere);
}

/* ---- z-buffer against brute force ----------------------------------------- */

typedef struct soup {
    cg_mesh *mesh;
} soup;

/* n random triangles in [-1, 1]^3, each with its own colour. */
static cg_mesh *random_soup(check_rng *rng, int n, double spread)
{
    cg_mesh *m;
    cg_mesh_create(&m, (size_t)n * 3, (size_t)n, (size_t)n * 3, CG_MESH_FACE_COLORS);
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
        /* Distinct 8-bit codes: red and green carry the index. */
        cg_rgba8 code = {(uint8_t)(t % 200 + 30), (uint8_t)(t / 200 * 20 + 30), 128, 255};
        m->face_colors[t] = cg_rgba8_to_linear(code);
    }
    return m;
}

/* Unlit: the colour of a face is its face colour. */
static cg_render_options unlit(void)
{
    cg_render_options o = plain_options();
    o.shading = CG_SHADING_FLAT;
    o.cull = CG_CULL_NONE;
    o.ambient = 1;
    o.specular = 0;
    o.light_count = 1;
    o.lights[0].direction = cg_vec3_make(0, 0, 1);
    o.lights[0].intensity = 0;
    return o;
}

/* Some vertex of the screen triangle v[0..2] lies outside the w x h image. */
static int outside(const cg_vec3 *v, int w, int h)
{
    for (int k = 0; k < 3; k++)
        if (!(v[k].x >= 0 && v[k].x <= w && v[k].y >= 0 && v[k].y <= h))
            return 1;
    return 0;
}

static void test_zbuffer_brute_force(void)
{
    check_rng rng = {2024};
    int checked = 0, wrong = 0, depth_wrong = 0;
    for (int scene = 0; scene < 6; scene++) {
        cg_mesh *m = random_soup(&rng, 60, 0.6);
        cg_render_options o = unlit();
        o.camera.eye = cg_vec3_make(check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1), 4);
        o.threads = 1 + scene % 2;
        cg_renderer *r;
        CHECK(cg_renderer_create(m, &o, &r, NULL) == CG_OK);
        int w = 80, h = 60;
        cg_image *img = image(w, h, CG_PIXEL_RGBA8);
        CHECK(cg_renderer_draw(r, img) == CG_OK);
        const float *depth = cg_renderer_depth(r);
        cg_camera cam = cg_renderer_camera(r);
        cg_mat4 view, proj;
        cg_camera_view(&cam, &view);
        cg_camera_projection(&cam, (double)w / h, &proj);
        cg_mat4 vp = cg_mat4_mul(cg_viewport(w, h), cg_mat4_mul(proj, view));
        /* Screen positions (x, y, window depth) of every vertex; all are in
         * front of the camera by construction. */
        cg_vec3 *s = malloc(sizeof *s * m->vertex_count);
        /* Snapped to the 1/256 pixel grid as documented: depth is the plane
         * through the snapped vertices. */
        for (size_t i = 0; i < m->vertex_count; i++) {
            s[i] = cg_mat4_transform_point(vp, m->positions[i]);
            s[i].x = floor(s[i].x * 256 + 0.5) / 256;
            s[i].y = floor(s[i].y * 256 + 0.5) / 256;
        }
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                double px = x + 0.5, py = y + 0.5;
                double best = INFINITY, second = INFINITY, margin = INFINITY;
                int winner = -1;
                for (size_t t = 0; t < m->face_count; t++) {
                    cg_vec3 a = s[t * 3], b = s[t * 3 + 1], c = s[t * 3 + 2];
                    double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
                    if (area == 0)
                        continue;
                    double l0 = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
                    double l1 = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
                    double l2 = 1 - l0 - l1;
                    /* Distance to the edges in pixels, to skip ambiguous pixels. */
                    double e0 = fabs(l0 * area) / hypot(c.x - b.x, c.y - b.y);
                    double e1 = fabs(l1 * area) / hypot(a.x - c.x, a.y - c.y);
                    double e2 = fabs(l2 * area) / hypot(b.x - a.x, b.y - a.y);
                    double near_edge = fmin(e0, fmin(e1, e2));
                    double z = l0 * a.z + l1 * b.z + l2 * c.z;
                    if (z < 0 || z > 1)
                        continue;
                    if (l0 >= 0 && l1 >= 0 && l2 >= 0) {
                        if (z < best) {
                            second = best;
                            best = z;
                            winner = (int)t;
                        } else if (z < second)
                            second = z;
                    }
                    if (near_edge < 0.02 && near_edge < margin)
                        margin = near_edge;
                }
                if (margin < 0.02 || second - best < 1e-4)
                    continue; /* ambiguous: a centre on an edge or equal depths */
                if (winner >= 0 && outside(s + winner * 3, w, h))
                    continue; /* cut by a side of the frustum: its depth plane is that of
                                 the snapped cut polygon, not of the snapped vertices */
                checked++;
                cg_rgba8 got = cg_image_get_rgba8(img, x, y);
                float d = depth[y * w + x];
                if (winner < 0) {
                    wrong += got.r != 0 || got.g != 0;
                    depth_wrong += !isinf(d);
                } else {
                    cg_rgba8 want = cg_linear_to_rgba8(m->face_colors[winner]);
                    wrong += got.r != want.r || got.g != want.g;
                    /* A vertex the projection puts a rounding away from a
                     * half step of the 1/256 grid may snap to either side:
                     * allow the depth plane that step of tilt. */
                    const cg_vec3 *v = s + winner * 3;
                    double area = (v[1].x - v[0].x) * (v[2].y - v[0].y)
                                  - (v[1].y - v[0].y) * (v[2].x - v[0].x);
                    double zx = ((v[1].z - v[0].z) * (v[2].y - v[0].y)
                                 - (v[2].z - v[0].z) * (v[1].y - v[0].y))
                                / area;
                    double zy = ((v[2].z - v[0].z) * (v[1].x - v[0].x)
                                 - (v[1].z - v[0].z) * (v[2].x - v[0].x))
                                / area;
                    if (!(fabs(d - best) < 2e-6 + (fabs(zx) + fabs(zy)) / 256)) {
                        depth_wrong++;
                        if (depth_wrong < 5)
                            fprintf(stderr, "depth %.9g want %.9g\n", d, best);
                    }
                }
            }
        free(s);
        cg_image_free(img);
        cg_renderer_free(r);
        cg_mesh_free(m);
    }
    CHECK_MSG(wrong == 0 && depth_wrong == 0 && checked > 20000,
              "z-buffer: %d of %d pixels show the wrong face, %d wrong depths", wrong, checked,
              depth_wrong);
}

/* ---- painter's ------------------------------------------------------------------ */

/* Triangles in parallel slanted planes z = 0.5 x + 0.3 y + c: they never
 * intersect, their depth ranges overlap (plain sorting gets them wrong),
 * and Newell's plane tests order them without splitting. */
static cg_mesh *parallel_layers(check_rng *rng, int n)
{
    cg_mesh *m;
    cg_mesh_create(&m, (size_t)n * 3, (size_t)n, (size_t)n * 3, CG_MESH_FACE_COLORS);
    for (int t = 0; t < n; t++) {
        double c = 0.08 * t + check_rng_range(rng, 0, 0.05);
        cg_vec3 centre = {check_rng_range(rng, -0.6, 0.6), check_rng_range(rng, -0.6, 0.6), 0};
        for (int k = 0; k < 3; k++) {
            double angle = 2 * CG_PI * k / 3 + check_rng_range(rng, 0, 1);
            double x = centre.x + 0.7 * cos(angle), y = centre.y + 0.7 * sin(angle);
            m->positions[t * 3 + k] = cg_vec3_make(x, y, 0.5 * x + 0.3 * y + c - 1);
            m->face_indices[t * 3 + k] = (uint32_t)(t * 3 + k);
        }
        m->face_offsets[t + 1] = (uint32_t)(t * 3 + 3);
        cg_rgba8 code = {(uint8_t)(40 + t * 7), (uint8_t)(200 - t * 5), 90, 255};
        m->face_colors[t] = cg_rgba8_to_linear(code);
    }
    return m;
}

static int compare_images(const cg_image *a, const cg_image *b)
{
    int differ = 0;
    for (int y = 0; y < a->height; y++)
        differ += memcmp(cg_image_row_rgba8((cg_image *)a, y), cg_image_row_rgba8((cg_image *)b, y),
                         (size_t)a->width * 4)
                          != 0
                      ? 1
                      : 0;
    return differ;
}

static int count_differences(const cg_image *a, const cg_image *b)
{
    int differ = 0;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            cg_rgba8 p = cg_image_get_rgba8(a, x, y), q = cg_image_get_rgba8(b, x, y);
            differ += p.r != q.r || p.g != q.g || p.b != q.b;
        }
    return differ;
}

static void render_with(const cg_mesh *m, cg_render_options o, cg_render_algorithm alg,
                        cg_image *img, cg_render_stats *stats)
{
    o.algorithm = alg;
    cg_renderer *r;
    CHECK(cg_renderer_create(m, &o, &r, NULL) == CG_OK);
    CHECK(cg_renderer_draw(r, img) == CG_OK);
    if (stats)
        *stats = cg_renderer_stats(r);
    cg_renderer_free(r);
}

static void test_painter(void)
{
    check_rng rng = {31337};
    int naive_wrong = 0;
    for (int scene = 0; scene < 5; scene++) {
        cg_mesh *m = parallel_layers(&rng, 14);
        cg_render_options o = unlit();
        o.camera.eye = cg_vec3_make(0.3 * scene - 0.6, 0.2, 3);
        o.shading = scene % 2 ? CG_SHADING_FLAT : CG_SHADING_GOURAUD;
        cg_image *z = image(120, 90, CG_PIXEL_RGBA8), *p = image(120, 90, CG_PIXEL_RGBA8),
                 *n = image(120, 90, CG_PIXEL_RGBA8);
        cg_render_stats ps;
        render_with(m, o, CG_RENDER_ZBUFFER, z, NULL);
        render_with(m, o, CG_RENDER_PAINTER, p, &ps);
        render_with(m, o, CG_RENDER_DEPTH_SORT, n, NULL);
        CHECK_MSG(compare_images(z, p) == 0,
                  "scene %d: painter's differs from the z-buffer in %d pixels", scene,
                  count_differences(z, p));
        CHECK_EQ_INT(ps.splits, 0);
        /* Plain sorting is wrong on most of these scenes. */
        naive_wrong += count_differences(z, n) > 0;
        cg_image_free(z);
        cg_image_free(p);
        cg_image_free(n);
        cg_mesh_free(m);
    }
    CHECK_MSG(naive_wrong >= 3, "plain depth sorting was wrong in only %d of 5 scenes",
              naive_wrong);
    /* A cyclic overlap (three sticks, each over the next) and random
     * interpenetrating triangles: splitting makes painter's agree with the
     * z-buffer except along the cuts. */
    for (int scene = 0; scene < 4; scene++) {
        cg_mesh *m = random_soup(&rng, 25, 0.7);
        cg_render_options o = unlit();
        o.camera.eye = cg_vec3_make(0, 0, 4);
        cg_image *z = image(100, 100, CG_PIXEL_RGBA8), *p = image(100, 100, CG_PIXEL_RGBA8);
        cg_render_stats ps;
        render_with(m, o, CG_RENDER_ZBUFFER, z, NULL);
        render_with(m, o, CG_RENDER_PAINTER, p, &ps);
        int differ = count_differences(z, p);
        CHECK_MSG(differ <= 100 * 100 / 100, "soup %d: %d pixels differ (%zu splits)", scene,
                  differ, ps.splits);
        CHECK(ps.splits > 0);
        cg_image_free(z);
        cg_image_free(p);
        cg_mesh_free(m);
    }
}

/* ---- perspective-correct interpolation --------------------------------------- */

static void test_perspective_interpolation(void)
{
    /* A floor quad receding from the camera, colours by corner; unlit so the
     * colour is the interpolated vertex colour. */
    cg_mesh *m;
    cg_mesh_create(&m, 4, 1, 4, CG_MESH_COLORS);
    m->positions[0] = cg_vec3_make(-1, -0.5, 0);
    m->positions[1] = cg_vec3_make(1, -0.5, 0);
    m->positions[2] = cg_vec3_make(1, -0.5, -8);
    m->positions[3] = cg_vec3_make(-1, -0.5, -8);
    m->colors[0] = (cg_rgbaf){1, 0, 0, 1};
    m->colors[1] = (cg_rgbaf){0, 1, 0, 1};
    m->colors[2] = (cg_rgbaf){0, 0, 1, 1};
    m->colors[3] = (cg_rgbaf){1, 1, 0, 1};
    for (int k = 0; k < 4; k++)
        m->face_indices[k] = (uint32_t)k;
    m->face_offsets[1] = 4;
    cg_render_options o = unlit();
    o.shading = CG_SHADING_GOURAUD;
    o.frame_camera = 0;
    o.camera.eye = cg_vec3_make(0, 0.2, 1.5);
    o.camera.target = cg_vec3_make(0, -0.4, -3);
    o.camera.near = 0.1;
    o.camera.far = 50;
    int w = 64, h = 48;
    cg_image *img = image(w, h, CG_PIXEL_RGBAF);
    render_with(m, o, CG_RENDER_ZBUFFER, img, NULL);
    double worst = 0;
    int checked = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            cg_vec3 origin, dir;
            cg_camera_ray(&o.camera, w, h, x + 0.5, y + 0.5, &origin, &dir);
            if (!(dir.y < 0))
                continue;
            double t = (-0.5 - origin.y) / dir.y;
            cg_vec3 p = cg_vec3_add(origin, cg_vec3_scale(dir, t));
            double u = (p.x + 1) / 2, v = -p.z / 8; /* bilinear over the quad is not the
                                                       triangles' interpolation: use the two triangles */
            if (!(u > 0.02 && u < 0.98 && v > 0.02 && v < 0.98) || fabs(u - v) < 0.02)
                continue;
            /* Triangle 0-1-2 where u > v, else 0-2-3: barycentric in 3D. */
            double c[3];
            cg_rgbaf *col = m->colors;
            if (u > v) {
                double l1 = u - v, l2 = v, l0 = 1 - u;
                c[0] = l0 * col[0].r + l1 * col[1].r + l2 * col[2].r;
                c[1] = l0 * col[0].g + l1 * col[1].g + l2 * col[2].g;
                c[2] = l0 * col[0].b + l1 * col[1].b + l2 * col[2].b;
            } else {
                double l0 = 1 - v, l2 = u, l3 = v - u;
                c[0] = l0 * col[0].r + l2 * col[2].r + l3 * col[3].r;
                c[1] = l0 * col[0].g + l2 * col[2].g + l3 * col[3].g;
                c[2] = l0 * col[0].b + l2 * col[2].b + l3 * col[3].b;
            }
            cg_rgbaf got = cg_image_get(img, x, y);
            double e = fmax(fabs(got.r - c[0]), fmax(fabs(got.g - c[1]), fabs(got.b - c[2])));
            if (e > worst)
                worst = e;
            checked++;
        }
    CHECK_MSG(worst < 2e-3 && checked > 500,
              "perspective-correct colours: worst error %g over %d pixels", worst, checked);
    cg_image_free(img);
    cg_mesh_free(m);
}

/* ---- culling ---------------------------------------------------------------------- */

static void test_culling(void)
{
    cg_mesh *m;
    cg_mesh_create(&m, 3, 1, 3, 0);
    m->positions[0] = cg_vec3_make(-1, -1, 0);
    m->positions[1] = cg_vec3_make(1, -1, 0);
    m->positions[2] = cg_vec3_make(0, 1, 0);
    for (int k = 0; k < 3; k++)
        m->face_indices[k] = (uint32_t)k;
    m->face_offsets[1] = 3;
    cg_render_options o = plain_options();
    cg_image *img = image(32, 32, CG_PIXEL_RGBA8);
    cg_render_stats s;
    for (int alg = 0; alg < 2; alg++) {
        /* Seen counter-clockwise from +z: front. */
        o.cull = CG_CULL_BACK;
        o.camera.eye = cg_vec3_make(0, 0, 3);
        render_with(m, o, (cg_render_algorithm)alg, img, &s);
        CHECK(s.fragments > 100 && s.culled == 0);
        /* From -z it is clockwise: culled, unless culling is off. */
        o.camera.eye = cg_vec3_make(0, 0, -3);
        render_with(m, o, (cg_render_algorithm)alg, img, &s);
        CHECK(s.fragments == 0 && s.culled == 1);
        o.cull = CG_CULL_NONE;
        render_with(m, o, (cg_render_algorithm)alg, img, &s);
        CHECK(s.fragments > 100 && s.culled == 0);
    }
    /* Whole-object culling: the mesh behind the camera. */
    o.frame_camera = 0;
    o.camera.eye = cg_vec3_make(0, 0, -3);
    o.camera.target = cg_vec3_make(0, 0, -6);
    render_with(m, o, CG_RENDER_ZBUFFER, img, &s);
    CHECK(s.object_culled && s.fragments == 0);
    cg_image_free(img);
    cg_mesh_free(m);
}

/* ---- normals ------------------------------------------------------------------------ */

static void test_normals(void)
{
    cg_mesh *box;
    cg_mesh_box(cg_vec3_make(-1, -1, -1), cg_vec3_make(1, 1, 1), &box);
    cg_vec3 n[24];
    CHECK(cg_mesh_corner_normals(box, cg_radians(60), n) == CG_OK);
    int faces_ok = 1;
    for (size_t f = 0; f < 6; f++)
        for (uint32_t k = box->face_offsets[f]; k < box->face_offsets[f + 1]; k++) {
            /* Sharp edges: every corner keeps its face normal, outward. */
            cg_vec3 p = box->positions[box->face_indices[k]];
            double dot = cg_vec3_dot(n[k], p);
            faces_ok &= fabs(cg_vec3_length(n[k]) - 1) < 1e-12 && fabs(dot - 1) < 1e-12;
        }
    CHECK_MSG(faces_ok, "60 degree crease: box corners keep their face normals");
    CHECK(cg_mesh_corner_normals(box, cg_radians(100), n) == CG_OK);
    int smooth_ok = 1;
    for (int k = 0; k < 24; k++) {
        cg_vec3 p = cg_vec3_normalize(box->positions[box->face_indices[k]]);
        smooth_ok &= cg_vec3_length(cg_vec3_sub(n[k], p)) < 1e-12;
    }
    CHECK_MSG(smooth_ok, "100 degree crease: corners share the diagonal normal (equal angles)");
    cg_mesh_free(box);
    /* A sphere: angle-weighted normals point outward along the radius. */
    cg_mesh *sphere;
    cg_mesh_sphere(64, 32, 2, &sphere);
    size_t corners = sphere->face_offsets[sphere->face_count];
    cg_vec3 *sn = malloc(sizeof *sn * corners);
    CHECK(cg_mesh_corner_normals(sphere, cg_radians(60), sn) == CG_OK);
    double worst = 0;
    for (size_t k = 0; k < corners; k++) {
        cg_vec3 p = cg_vec3_normalize(sphere->positions[sphere->face_indices[k]]);
        worst = fmax(worst, cg_vec3_length(cg_vec3_sub(sn[k], p)));
    }
    CHECK_MSG(worst < 0.01, "sphere normals within %g of the radius", worst);
    free(sn);
    cg_mesh_free(sphere);
}

/* ---- threads --------------------------------------------------------------------------- */

static void test_threads_identical(void)
{
    cg_mesh *torus;
    cg_mesh_torus(90, 40, 1, 0.45, &torus);
    for (int mode = 0; mode < 7; mode++) {
        cg_render_options o = plain_options();
        o.camera.eye = cg_vec3_make(0.5, 2, 3);
        o.shading = (cg_shading)(mode % 3);
        o.edges = mode == 3 ? CG_EDGES_OVERLAY : mode == 4 ? CG_EDGES_HIDDEN_LINE : CG_EDGES_NONE;
        o.algorithm = mode == 5 ? CG_RENDER_PAINTER : CG_RENDER_ZBUFFER;
        o.cull = mode == 6 ? CG_CULL_NONE : CG_CULL_BACK;
        cg_image *first = NULL;
        for (int threads = 1; threads <= 5; threads += 2) {
            o.threads = threads;
            cg_image *img = image(211, 157, CG_PIXEL_RGBA8);
            render_with(torus, o, o.algorithm, img, NULL);
            if (!first)
                first = img;
            else {
                CHECK_MSG(compare_images(first, img) == 0, "mode %d: %d threads differ from 1",
                          mode, threads);
                cg_image_free(img);
            }
        }
        cg_image_free(first);
    }
    cg_mesh_free(torus);
}

/* ---- bad input ------------------------------------------------------------------------- */

static void test_bad_input(void)
{
    cg_render_options o = plain_options();
    cg_image *img = image(16, 16, CG_PIXEL_RGBA8);
    cg_rgba8 bg = cg_linear_to_rgba8(o.background);
    /* No faces: the background. */
    cg_mesh *empty;
    cg_mesh_create(&empty, 0, 0, 0, 0);
    cg_image_clear_rgba8(img, (cg_rgba8){1, 2, 3, 4});
    CHECK(cg_render(empty, &o, img, NULL) == CG_OK);
    CHECK(is_background(img, 0, 0, bg) && is_background(img, 15, 15, bg));
    cg_mesh_free(empty);
    /* Degenerate and NaN triangles: skipped, the rest drawn. */
    cg_mesh *m;
    cg_mesh_create(&m, 9, 3, 9, 0);
    m->positions[0] = cg_vec3_make(0, 0, 0);
    m->positions[1] = cg_vec3_make(1, 1, 0);
    m->positions[2] = cg_vec3_make(2, 2, 0); /* collinear */
    m->positions[3] = cg_vec3_make(NAN, 0, 0);
    m->positions[4] = cg_vec3_make(1, 0, 0);
    m->positions[5] = cg_vec3_make(0, INFINITY, 0);
    m->positions[6] = cg_vec3_make(-1, -1, 0);
    m->positions[7] = cg_vec3_make(1, -1, 0);
    m->positions[8] = cg_vec3_make(0, 1, 0);
    for (int k = 0; k < 9; k++)
        m->face_indices[k] = (uint32_t)k;
    for (int f = 0; f <= 3; f++)
        m->face_offsets[f] = (uint32_t)(f * 3);
    for (int alg = 0; alg < 3; alg++)
        for (int shading = 0; shading < 3; shading++) {
            o.algorithm = (cg_render_algorithm)alg;
            o.shading = (cg_shading)shading;
            o.edges = shading == 2 ? CG_EDGES_OVERLAY : CG_EDGES_NONE;
            CHECK(cg_render(m, &o, img, NULL) == CG_OK);
            int drawn = 0;
            for (int y = 0; y < 16; y++)
                for (int x = 0; x < 16; x++)
                    drawn += !is_background(img, x, y, bg);
            CHECK_MSG(drawn > 10, "the valid triangle is drawn (%d pixels)", drawn);
        }
    o.edges = CG_EDGES_WIREFRAME;
    CHECK(cg_render(m, &o, img, NULL) == CG_OK);
    o.edges = CG_EDGES_NONE;
    o.algorithm = CG_RENDER_ZBUFFER;
    /* Only NaN vertices: nothing to frame, the background. */
    for (int k = 0; k < 9; k++)
        m->positions[k] = cg_vec3_make(NAN, NAN, NAN);
    CHECK(cg_render(m, &o, img, NULL) == CG_OK);
    CHECK(is_background(img, 8, 8, bg));
    /* Invalid meshes, options and images. */
    m->face_indices[4] = 99;
    cg_error err;
    CHECK(cg_render(m, &o, img, &err) == CG_EFORMAT);
    CHECK(strstr(err.message, "99") != NULL);
    m->face_indices[4] = 4;
    CHECK(cg_render(NULL, &o, img, NULL) == CG_EINVAL);
    CHECK(cg_render(m, NULL, img, NULL) == CG_EINVAL);
    CHECK(cg_render(m, &o, NULL, NULL) == CG_EINVAL);
    cg_image zero = *img;
    zero.width = 0;
    CHECK(cg_render(m, &o, &zero, NULL) == CG_EINVAL);
    cg_render_options bad = o;
    bad.threads = 0;
    CHECK(cg_render(m, &bad, img, NULL) == CG_EINVAL);
    bad = o;
    bad.light_count = 1;
    bad.lights[0].direction = cg_vec3_make(0, 0, 0);
    CHECK(cg_render(m, &bad, img, NULL) == CG_EINVAL);
    bad = o;
    bad.frame_camera = 0;
    bad.camera.near = -1;
    cg_renderer *r;
    CHECK(cg_renderer_create(m, &bad, &r, NULL) == CG_OK);
    CHECK(cg_renderer_draw(r, img) == CG_EINVAL);
    CHECK(cg_renderer_depth(r) == NULL);
    cg_renderer_free(r);
    cg_mesh_free(m);
    cg_image_free(img);
}

/* Random meshes (with NaN, infinite and huge coordinates), random cameras
 * (inside, behind, grazing) and every mode: a status, never a crash (run
 * under the sanitizers in CI), and with culling on a closed mesh no pixel
 * gets two fragments. */
static void test_random_scenes(void)
{
    check_rng rng = {4242};
    int ok = 1;
    for (int trial = 0; trial < 150; trial++) {
        cg_mesh *m = random_soup(&rng, 1 + (int)check_rng_int(&rng, 0, 40), 2.0);
        for (size_t i = 0; i < m->vertex_count; i++) {
            double u = check_rng_unit(&rng);
            if (u < 0.02)
                m->positions[i].x = NAN;
            else if (u < 0.03)
                m->positions[i].y = INFINITY;
            else if (u < 0.04)
                m->positions[i].z = 1e300;
        }
        cg_render_options o = plain_options();
        o.frame_camera = check_rng_unit(&rng) < 0.5;
        o.camera.eye = cg_vec3_make(check_rng_range(&rng, -3, 3), check_rng_range(&rng, -3, 3),
                                    check_rng_range(&rng, -3, 3));
        o.camera.target = cg_vec3_make(check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1),
                                       check_rng_range(&rng, -1, 1));
        o.camera.near = check_rng_range(&rng, 1e-4, 1);
        o.camera.far = o.camera.near + check_rng_range(&rng, 1e-3, 100);
        o.camera.orthographic = check_rng_unit(&rng) < 0.2;
        o.camera.ortho_height = check_rng_range(&rng, 0.1, 5);
        o.camera.fovy = check_rng_range(&rng, 0.05, 3.0);
        o.algorithm = (cg_render_algorithm)check_rng_int(&rng, 0, 2);
        o.shading = (cg_shading)check_rng_int(&rng, 0, 2);
        o.cull = (cg_cull_mode)check_rng_int(&rng, 0, 1);
        o.edges = (cg_edge_mode)check_rng_int(&rng, 0, 3);
        o.threads = (int)check_rng_int(&rng, 1, 3);
        int w = (int)check_rng_int(&rng, 1, 70), h = (int)check_rng_int(&rng, 1, 50);
        cg_image *img = image(w, h, check_rng_unit(&rng) < 0.2 ? CG_PIXEL_RGBAF : CG_PIXEL_RGBA8);
        cg_status status = cg_render(m, &o, img, NULL);
        ok &= status == CG_OK || status == CG_EINVAL;
        cg_image_free(img);
        cg_mesh_free(m);
    }
    CHECK_MSG(ok, "random scenes give CG_OK or CG_EINVAL");
}

/* One renderer drawing many frames keeps its buffers and worker threads
 * between them: frames whose thread count, image size, shading, culling and
 * algorithm change from one to the next must each equal a fresh one-shot
 * render with the same options. */
static void test_renderer_reuse(void)
{
    cg_mesh *torus;
    cg_mesh_torus(60, 30, 1, 0.45, &torus);
    cg_render_options o = plain_options();
    o.camera.eye = cg_vec3_make(0.5, 2, 3);
    cg_renderer *r;
    CHECK(cg_renderer_create(torus, &o, &r, NULL) == CG_OK);
    check_rng rng = {99};
    int differ = 0, depth_differ = 0, w = 0, h = 0;
    for (int frame = 0; frame < 24; frame++) {
        o.threads = 1 + (int)(check_rng_next(&rng) % 4);
        o.shading = (cg_shading)(check_rng_next(&rng) % 3);
        o.cull = check_rng_next(&rng) % 2 ? CG_CULL_BACK : CG_CULL_NONE;
        o.algorithm = frame % 6 == 5 ? CG_RENDER_PAINTER : CG_RENDER_ZBUFFER;
        o.edges = frame % 8 == 3 ? CG_EDGES_WIREFRAME : CG_EDGES_NONE;
        o.camera.eye = cg_vec3_make(check_rng_range(&rng, -3, 3), check_rng_range(&rng, -3, 3), 3);
        o.frame_camera = frame % 2; /* unframed: the torus fills different tiles */
        if (frame % 4 == 0) {       /* the same size for a few frames, then another */
            w = 40 + (int)(check_rng_next(&rng) % 200);
            h = 30 + (int)(check_rng_next(&rng) % 150);
        }
        cg_image *a = image(w, h, CG_PIXEL_RGBA8), *b = image(w, h, CG_PIXEL_RGBA8);
        CHECK(cg_renderer_set_options(r, &o) == CG_OK);
        CHECK(cg_renderer_draw(r, a) == CG_OK);
        cg_renderer *fresh;
        CHECK(cg_renderer_create(torus, &o, &fresh, NULL) == CG_OK);
        CHECK(cg_renderer_draw(fresh, b) == CG_OK);
        differ += compare_images(a, b) != 0;
        /* The depth buffers too (tiles left empty keep their cleared depth
         * from frame to frame instead of being cleared again). */
        const float *da = cg_renderer_depth(r), *db = cg_renderer_depth(fresh);
        if (!da || !db)
            depth_differ += da != db;
        else
            depth_differ += memcmp(da, db, sizeof(float) * (size_t)w * (size_t)h) != 0;
        cg_renderer_free(fresh);
        cg_image_free(a);
        cg_image_free(b);
    }
    CHECK_MSG(differ == 0, "renderer reuse: %d of 24 frames differ from fresh renders", differ);
    CHECK_MSG(depth_differ == 0, "renderer reuse: %d of 24 depth buffers differ", depth_differ);
    cg_renderer_free(r);
    cg_mesh_free(torus);
}

/* ---- lighting ---------------------------------------------------------------------- */

/* The renderer evaluates the illumination model in float; a flat-shaded
 * triangle drawn into a float image shows that colour, which must agree with
 * cg_light_shade (double) at the triangle's centroid with its face normal,
 * for random lights, coefficients, cameras (perspective and orthographic). */
static void test_float_lighting(void)
{
    check_rng rng = {77};
    double worst = 0;
    int checked = 0;
    for (int trial = 0; trial < 200; trial++) {
        cg_mesh *m;
        cg_mesh_create(&m, 3, 1, 3, 0);
        m->positions[0] = cg_vec3_make(-1, -1, check_rng_range(&rng, -0.3, 0.3));
        m->positions[1] = cg_vec3_make(1, -1, check_rng_range(&rng, -0.3, 0.3));
        m->positions[2] = cg_vec3_make(0, 1.2, check_rng_range(&rng, -0.3, 0.3));
        for (int k = 0; k < 3; k++)
            m->face_indices[k] = (uint32_t)k;
        m->face_offsets[1] = 3;
        cg_render_options o = plain_options();
        o.shading = CG_SHADING_FLAT;
        o.cull = CG_CULL_NONE;
        o.frame_camera = 0;
        o.camera.eye = cg_vec3_make(check_rng_range(&rng, -1, 1), check_rng_range(&rng, -1, 1), 3);
        o.camera.target = cg_vec3_make(0, 0, 0);
        o.camera.orthographic = trial % 3 == 0;
        o.camera.ortho_height = 3;
        o.ambient = check_rng_range(&rng, 0, 0.5);
        o.specular = trial % 4 == 1 ? 0 : check_rng_range(&rng, 0, 1);
        static const double shininess[4] = {1, 2, 7.5, 64};
        o.shininess = shininess[trial % 4];
        o.color = (cg_rgbaf){(float)check_rng_range(&rng, 0, 1), (float)check_rng_range(&rng, 0, 1),
                             (float)check_rng_range(&rng, 0, 1), 1};
        o.background = (cg_rgbaf){-1, -1, -1, 1}; /* no colour the shading gives */
        o.light_count = 1 + trial % 3;
        for (int i = 0; i < o.light_count; i++) {
            o.lights[i].direction = cg_vec3_make(check_rng_range(&rng, -1, 1),
                                                 check_rng_range(&rng, -1, 1),
                                                 check_rng_range(&rng, 0.1, 1));
            o.lights[i].intensity = check_rng_range(&rng, 0.2, 1.2);
        }
        cg_image *img = image(32, 24, CG_PIXEL_RGBAF);
        render_with(m, o, CG_RENDER_ZBUFFER, img, NULL);
        cg_rgbaf got = cg_image_get(img, 16, 12);
        /* The definition, in double. */
        cg_vec3 a = m->positions[0], b = m->positions[1], c = m->positions[2];
        cg_vec3 centre = cg_vec3_scale(cg_vec3_add(cg_vec3_add(a, b), c), 1.0 / 3);
        cg_vec3 normal = cg_vec3_normalize(cg_vec3_cross(cg_vec3_sub(b, a), cg_vec3_sub(c, a)));
        cg_vec3 view = cg_vec3_normalize(
            cg_vec3_sub(o.camera.eye, o.camera.orthographic ? o.camera.target : centre));
        cg_material material = cg_material_make(cg_vec3_make(o.color.r, o.color.g, o.color.b),
                                                o.ambient, 1, o.specular, o.shininess);
        material.specular = CG_SPECULAR_BLINN;
        cg_light lights[CG_RENDER_MAX_LIGHTS + 1];
        lights[0] = cg_light_ambient(cg_vec3_make(1, 1, 1));
        for (int i = 0; i < o.light_count; i++) {
            double k = o.lights[i].intensity;
            lights[i + 1] = cg_light_directional(cg_vec3_scale(o.lights[i].direction, -1),
                                                 cg_vec3_make(k, k, k));
        }
        cg_vec3 want = cg_light_shade(centre, normal, view, &material, lights,
                                      (size_t)o.light_count + 1);
        double e = fmax(fabs(got.r - want.x), fmax(fabs(got.g - want.y), fabs(got.b - want.z)));
        e /= fmax(1, fmax(want.x, fmax(want.y, want.z)));
        if (e > worst)
            worst = e;
        checked += got.r >= 0;
        cg_image_free(img);
        cg_mesh_free(m);
    }
    CHECK_MSG(worst < 1e-5 && checked == 200,
              "float lighting: worst relative error %g against cg_light_shade (%d checked)", worst,
              checked);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_random_scenes);
    CHECK_GROUP(test_closed_mesh_once);
    CHECK_GROUP(test_camera_inside);
    CHECK_GROUP(test_zbuffer_brute_force);
    CHECK_GROUP(test_painter);
    CHECK_GROUP(test_perspective_interpolation);
    CHECK_GROUP(test_culling);
    CHECK_GROUP(test_normals);
    CHECK_GROUP(test_threads_identical);
    CHECK_GROUP(test_float_lighting);
    CHECK_GROUP(test_renderer_reuse);
    CHECK_GROUP(test_bad_input);
    return check_finish();
}
