/* Textured rendering against its definition: a textured rectangle drawn
 * unlit, each pixel compared with what the texture holds at the texture
 * coordinates of the point the pixel's centre sees.  That point is found
 * here independently of the rasterizer, by intersecting the camera's
 * primary ray (cg_camera_ray) with the rectangle's plane, so that texture
 * coordinates are checked for perspective correctness on a tilted plane.
 * Nearest samples must be exactly the texel (away from texel borders),
 * bilinear ones the weighted four texels written out here, trilinear ones
 * the mip level the pixel's footprint calls for (levels built here as box
 * averages), for every wrap mode; glTF's alpha mask drops fragments below
 * the cutoff, colour and depth alike. */
#include "cg.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TEX 64 /* texture side (power of two: exact box averages) */

static uint8_t texels[TEX * TEX][3];

static void make_texture(const char *path, check_rng *rng, int side)
{
    cg_image *image;
    CHECK(cg_image_create(&image, side, side, CG_PIXEL_RGBA8) == CG_OK);
    for (int y = 0; y < side; y++)
        for (int x = 0; x < side; x++) {
            uint8_t *t = texels[y * side + x];
            for (int k = 0; k < 3; k++)
                t[k] = (uint8_t)check_rng_int(rng, 0, 255);
            cg_image_set_rgba8(image, x, y, (cg_rgba8){t[0], t[1], t[2], 255});
        }
    cg_error err;
    CHECK_MSG(cg_image_write(image, path, CG_FILE_UNKNOWN, &err) == CG_OK, "%s", err.message);
    cg_image_free(image);
}

/* The rectangle origin + s e1 + t e2 (s, t in [0, 1]) with texture
 * coordinates uv0 + s (du, 0) + t (0, dv). */
typedef struct quad {
    cg_vec3 origin, e1, e2;
    double uv0[2], du, dv;
} quad;

static cg_mesh *quad_mesh(const quad *q, const char *texture, cg_texture_wrap wrap)
{
    static cg_vec3 positions[4];
    static cg_vec2 uvs[4];
    static uint32_t offsets[2] = {0, 4}, indices[4] = {0, 1, 2, 3}, face_material[1] = {0};
    static cg_mesh_material material;
    static cg_mesh mesh;
    static char path[256];
    for (int k = 0; k < 4; k++) {
        double s = (k == 1 || k == 2), t = (k >= 2);
        positions[k] = cg_vec3_add(q->origin,
                                   cg_vec3_add(cg_vec3_scale(q->e1, s), cg_vec3_scale(q->e2, t)));
        uvs[k] = (cg_vec2){q->uv0[0] + s * q->du, q->uv0[1] + t * q->dv};
    }
    material = cg_mesh_material_default();
    snprintf(path, sizeof path, "%s", texture);
    material.base_color_map.image_path = path;
    material.base_color_map.encoding = CG_TEXTURE_SRGB;
    material.base_color_map.wrap_u = material.base_color_map.wrap_v = wrap;
    memset(&mesh, 0, sizeof mesh);
    mesh.vertex_count = 4;
    mesh.positions = positions;
    mesh.texcoords = uvs;
    mesh.face_count = 1;
    mesh.face_offsets = offsets;
    mesh.face_indices = indices;
    mesh.material_count = 1;
    mesh.materials = &material;
    mesh.face_materials = face_material;
    return &mesh;
}

static cg_image *draw(const cg_mesh *mesh, const cg_camera *camera, cg_texture_filter filter,
                      int width, int height)
{
    cg_render_options o;
    cg_render_options_default(&o);
    o.camera = *camera;
    o.frame_camera = 0;
    o.cull = CG_CULL_NONE;
    o.shading = CG_SHADING_UNLIT;
    o.texture_filter = filter;
    o.background = (cg_rgbaf){0, 0, 0, 1};
    cg_image *image;
    cg_error err;
    CHECK(cg_image_create(&image, width, height, CG_PIXEL_RGBA8) == CG_OK);
    CHECK_MSG(cg_render(mesh, &o, image, &err) == CG_OK, "%s", err.message);
    return image;
}

/* The texture coordinates the centre of pixel (x, y) sees, from the ray and
 * the plane; 0 when it misses the rectangle or lies within margin of its
 * sides (in s, t). */
static int pixel_uv(const quad *q, const cg_camera *camera, int width, int height, double x,
                    double y, double margin, double uv[2])
{
    cg_vec3 o, d;
    if (cg_camera_ray(camera, width, height, x, y, &o, &d) != CG_OK)
        return 0;
    cg_vec3 n = cg_vec3_cross(q->e1, q->e2);
    double denom = cg_vec3_dot(n, d);
    if (fabs(denom) < 1e-12)
        return 0;
    double h = cg_vec3_dot(n, cg_vec3_sub(q->origin, o)) / denom;
    cg_vec3 r = cg_vec3_sub(cg_vec3_add(o, cg_vec3_scale(d, h)), q->origin);
    /* e1 and e2 are perpendicular here. */
    double s = cg_vec3_dot(r, q->e1) / cg_vec3_dot(q->e1, q->e1);
    double t = cg_vec3_dot(r, q->e2) / cg_vec3_dot(q->e2, q->e2);
    if (s < margin || s > 1 - margin || t < margin || t > 1 - margin)
        return 0;
    uv[0] = q->uv0[0] + s * q->du;
    uv[1] = q->uv0[1] + t * q->dv;
    return 1;
}

static int wrap(long long i, int n, cg_texture_wrap mode)
{
    if (mode == CG_TEXTURE_CLAMP)
        return i < 0 ? 0 : i >= n ? n - 1 : (int)i;
    if (mode == CG_TEXTURE_REPEAT)
        return (int)(((i % n) + n) % n);
    long long m = ((i % (2 * n)) + 2 * n) % (2 * n);
    return (int)(m < n ? m : 2 * n - 1 - m);
}

/* Linear light of texel (x, y) of level `level` (box averages of level 0). */
static void level_texel(int level, int x, int y, double out[3])
{
    int size = 1 << level;
    out[0] = out[1] = out[2] = 0;
    for (int j = 0; j < size; j++)
        for (int i = 0; i < size; i++)
            for (int k = 0; k < 3; k++)
                out[k] += cg_srgb_to_linear(texels[(y * size + j) * TEX + x * size + i][k] / 255.0);
    for (int k = 0; k < 3; k++)
        out[k] /= (double)size * size;
}

static void bilinear(int level, double u, double v, cg_texture_wrap mode, double out[3])
{
    int n = TEX >> level;
    double x = u * n - 0.5, y = (1 - v) * n - 0.5;
    double fx = x - floor(x), fy = y - floor(y);
    long long x0 = (long long)floor(x), y0 = (long long)floor(y);
    out[0] = out[1] = out[2] = 0;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++) {
            double w = (i ? fx : 1 - fx) * (j ? fy : 1 - fy), c[3];
            level_texel(level, wrap(x0 + i, n, mode), wrap(y0 + j, n, mode), c);
            for (int k = 0; k < 3; k++)
                out[k] += w * c[k];
        }
}

static int near_integer(double value, double tolerance)
{
    return fabs(value - floor(value + 0.5)) < tolerance;
}

/* Nearest: every covered pixel away from texel borders is its texel. */
static void check_nearest(const quad *q, const cg_camera *camera, int width, int height,
                          cg_texture_wrap mode, const char *what)
{
    cg_mesh *mesh = quad_mesh(q, "textured_nearest.png", mode);
    cg_image *image = draw(mesh, camera, CG_TEXTURE_NEAREST, width, height);
    long checked = 0, wrong = 0;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            double uv[2];
            if (!pixel_uv(q, camera, width, height, x + 0.5, y + 0.5, 1e-3, uv))
                continue;
            /* Vertices are snapped to 1/256 pixel: a border within a
             * hundredth of the pixel's footprint may fall either way. */
            double ux[2], uy[2];
            if (!pixel_uv(q, camera, width, height, x + 1.5, y + 0.5, 0, ux)
                || !pixel_uv(q, camera, width, height, x + 0.5, y + 1.5, 0, uy))
                continue;
            double rho = TEX
                         * fmax(hypot(ux[0] - uv[0], ux[1] - uv[1]),
                                hypot(uy[0] - uv[0], uy[1] - uv[1]));
            double tx = uv[0] * TEX, ty = (1 - uv[1]) * TEX, tolerance = 1e-3 + rho / 100;
            if (near_integer(tx, tolerance) || near_integer(ty, tolerance))
                continue;
            const uint8_t *t = texels[wrap((long long)floor(ty), TEX, mode) * TEX
                                      + wrap((long long)floor(tx), TEX, mode)];
            cg_rgba8 p = cg_image_get_rgba8(image, x, y);
            checked++;
            if (abs(p.r - t[0]) > 1 || abs(p.g - t[1]) > 1 || abs(p.b - t[2]) > 1)
                wrong++;
        }
    CHECK_MSG(checked > width * height / 8, "%s: only %ld pixels checked", what, checked);
    CHECK_MSG(wrong == 0, "%s: %ld of %ld pixels not their texel", what, wrong, checked);
    cg_image_free(image);
}

static cg_camera ortho_camera(double height)
{
    cg_camera c = cg_camera_default();
    c.eye = cg_vec3_make(0.5, 0.5, 2);
    c.target = cg_vec3_make(0.5, 0.5, 0);
    c.orthographic = 1;
    c.ortho_height = height;
    c.near = 0.5;
    c.far = 4;
    return c;
}

static void facing_nearest(void)
{
    check_rng rng = {7};
    make_texture("textured_nearest.png", &rng, TEX);
    quad q = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, 1, 1};
    cg_camera camera = ortho_camera(1.25);
    check_nearest(&q, &camera, 160, 160, CG_TEXTURE_REPEAT, "facing, ortho");
    cg_camera persp = cg_camera_default();
    persp.eye = cg_vec3_make(0.5, 0.5, 2.2);
    persp.target = cg_vec3_make(0.5, 0.5, 0);
    persp.near = 0.1;
    persp.far = 10;
    check_nearest(&q, &persp, 200, 150, CG_TEXTURE_REPEAT, "facing, perspective");
}

/* A plane tilted away from a perspective camera: affine interpolation on
 * the screen would put texels far from where they belong. */
static void tilted_perspective(void)
{
    check_rng rng = {11};
    make_texture("textured_nearest.png", &rng, TEX);
    quad q = {{-1, -0.5, 0}, {2, 0, 0}, {0, 0, -6}, {0, 0}, 2, 3};
    cg_camera camera = cg_camera_default();
    camera.eye = cg_vec3_make(0, 0.4, 1.2);
    camera.target = cg_vec3_make(0, -0.3, -2);
    camera.near = 0.05;
    camera.far = 20;
    check_nearest(&q, &camera, 240, 180, CG_TEXTURE_REPEAT, "tilted, perspective");
    /* The depth across the plane varies sevenfold: not a mild case. */
    CHECK(cg_vec3_length(cg_vec3_sub(camera.eye, q.origin)) * 3
          < cg_vec3_length(cg_vec3_sub(camera.eye, cg_vec3_add(q.origin, q.e2))));
}

static void wrap_modes(void)
{
    check_rng rng = {13};
    make_texture("textured_nearest.png", &rng, TEX);
    quad q = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1.25, -0.75}, 3.5, 2.5};
    cg_camera camera = ortho_camera(1.1);
    check_nearest(&q, &camera, 200, 200, CG_TEXTURE_REPEAT, "repeat");
    check_nearest(&q, &camera, 200, 200, CG_TEXTURE_MIRRORED_REPEAT, "mirrored repeat");
    check_nearest(&q, &camera, 200, 200, CG_TEXTURE_CLAMP, "clamp");
}

/* Bilinear or trilinear at a given level of detail (ortho, facing: the
 * footprint of every pixel is `texels_per_pixel` texels of level 0). */
static void check_filtered(cg_texture_filter filter, double lod, cg_texture_wrap mode)
{
    quad q = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.3, 0.2}, 1.7, 1.7};
    double texels_per_pixel = pow(2, lod);
    int side = 128;
    /* side pixels show ortho_height world units; 1 world unit is
     * 1.7 * TEX texels. */
    cg_camera camera = ortho_camera(side * texels_per_pixel / (1.7 * TEX));
    cg_mesh *mesh = quad_mesh(&q, "textured_filtered.png", mode);
    cg_image *image = draw(mesh, &camera, filter, side, side);
    double sum = 0, worst = 0;
    long checked = 0;
    /* Bilinear, and trilinear when magnified: level 0 alone. */
    int level = filter == CG_TEXTURE_BILINEAR || lod < 0 ? 0 : (int)floor(lod);
    double fraction = filter == CG_TEXTURE_BILINEAR || lod < 0 ? 0 : lod - level;
    for (int y = 0; y < side; y++)
        for (int x = 0; x < side; x++) {
            double uv[2], a[3], b[3] = {0, 0, 0};
            if (!pixel_uv(&q, &camera, side, side, x + 0.5, y + 0.5, 1e-3, uv))
                continue;
            bilinear(level, uv[0], uv[1], mode, a);
            if (fraction > 0)
                bilinear(level + 1, uv[0], uv[1], mode, b);
            cg_rgba8 p = cg_image_get_rgba8(image, x, y);
            uint8_t got[3] = {p.r, p.g, p.b};
            for (int k = 0; k < 3; k++) {
                double want = cg_linear_to_srgb(a[k] + fraction * (b[k] - a[k])) * 255;
                double e = fabs(got[k] - want);
                sum += e;
                worst = e > worst ? e : worst;
            }
            checked++;
        }
    CHECK_MSG(checked > 100, "lod %g: only %ld pixels", lod, checked);
    double mean = checked ? sum / (3.0 * checked) : 99;
    CHECK_MSG(mean < 0.6 && worst < 3, "filter %d lod %g wrap %d: mean %.3f, worst %.2f codes",
              (int)filter, lod, (int)mode, mean, worst);
    cg_image_free(image);
}

static void filtered(void)
{
    check_rng rng = {17};
    make_texture("textured_filtered.png", &rng, TEX);
    check_filtered(CG_TEXTURE_BILINEAR, -1, CG_TEXTURE_REPEAT);
    check_filtered(CG_TEXTURE_BILINEAR, -1, CG_TEXTURE_CLAMP);
    check_filtered(CG_TEXTURE_BILINEAR, -1, CG_TEXTURE_MIRRORED_REPEAT);
    /* Magnified: trilinear is bilinear on level 0. */
    check_filtered(CG_TEXTURE_TRILINEAR, -1, CG_TEXTURE_REPEAT);
    check_filtered(CG_TEXTURE_TRILINEAR, 1, CG_TEXTURE_REPEAT);
    check_filtered(CG_TEXTURE_TRILINEAR, 1.5, CG_TEXTURE_REPEAT);
    check_filtered(CG_TEXTURE_TRILINEAR, 2.25, CG_TEXTURE_CLAMP);
}

/* A texture that cannot be read leaves the material its colour, with a
 * warning naming the file. */
static void missing_texture(void)
{
    quad q = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, 1, 1};
    cg_mesh *mesh = quad_mesh(&q, "no_such_texture.png", CG_TEXTURE_REPEAT);
    mesh->materials[0].base_color = (cg_rgbaf){0.25f, 0.5f, 0.75f, 1};
    cg_render_options o;
    cg_render_options_default(&o);
    o.shading = CG_SHADING_UNLIT;
    cg_renderer *r;
    CHECK(cg_renderer_create(mesh, &o, &r, NULL) == CG_OK);
    const char *w = cg_renderer_warnings(r);
    CHECK(w && strstr(w, "no_such_texture.png"));
    cg_image *image;
    CHECK(cg_image_create(&image, 64, 48, CG_PIXEL_RGBA8) == CG_OK);
    CHECK(cg_renderer_draw(r, image) == CG_OK);
    cg_rgba8 p = cg_image_get_rgba8(image, 32, 24);
    CHECK(p.r == cg_linear_to_srgb8(0.25f) && p.g == cg_linear_to_srgb8(0.5f)
          && p.b == cg_linear_to_srgb8(0.75f));
    cg_image_free(image);
    cg_renderer_free(r);
    o.texture_filter = (cg_texture_filter)7;
    CHECK(cg_renderer_create(mesh, &o, &r, NULL) == CG_EINVAL);
}

/* glTF alphaMode MASK: a textured square whose texels are alpha 0 or 1 in
 * front of a red one; where the texel under a pixel is transparent the red
 * square shows, whichever of the two is drawn first (a dropped fragment
 * writes no depth). */
static void alpha_mask(void)
{
    check_rng rng = {19};
    cg_image *image;
    CHECK(cg_image_create(&image, TEX, TEX, CG_PIXEL_RGBA8) == CG_OK);
    static uint8_t alpha[TEX * TEX];
    for (int y = 0; y < TEX; y++)
        for (int x = 0; x < TEX; x++) {
            uint8_t *t = texels[y * TEX + x];
            for (int k = 0; k < 3; k++)
                t[k] = (uint8_t)check_rng_int(&rng, 0, 255);
            alpha[y * TEX + x] = check_rng_int(&rng, 0, 1) ? 255 : 0;
            cg_image_set_rgba8(image, x, y, (cg_rgba8){t[0], t[1], t[2], alpha[y * TEX + x]});
        }
    cg_error err;
    CHECK_MSG(cg_image_write(image, "textured_alpha.png", CG_FILE_UNKNOWN, &err) == CG_OK, "%s",
              err.message);
    cg_image_free(image);
    cg_vec3 positions[8] = {{0, 0, 0.5}, {1, 0, 0.5}, {1, 1, 0.5}, {0, 1, 0.5},
                            {0, 0, 0},   {1, 0, 0},   {1, 1, 0},   {0, 1, 0}};
    cg_vec2 uvs[8] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}};
    uint32_t offsets[3] = {0, 4, 8};
    cg_mesh_material materials[2] = {cg_mesh_material_default(), cg_mesh_material_default()};
    char path[] = "textured_alpha.png";
    materials[0].base_color_map.image_path = path;
    materials[0].alpha_mode = CG_MESH_ALPHA_MASK;
    materials[0].alpha_cutoff = 0.5;
    materials[1].base_color = (cg_rgbaf){1, 0, 0, 1};
    cg_camera camera = ortho_camera(1.2);
    for (int order = 0; order < 2; order++) {
        /* order 0: the masked square first; 1: the red one first. */
        uint32_t indices[8] = {0, 1, 2, 3, 4, 5, 6, 7}, face_materials[2] = {0, 1};
        if (order)
            for (int k = 0; k < 4; k++) {
                indices[k] = (uint32_t)(4 + k);
                indices[4 + k] = (uint32_t)k;
                face_materials[0] = 1;
                face_materials[1] = 0;
            }
        cg_mesh mesh = {0};
        mesh.vertex_count = 8;
        mesh.positions = positions;
        mesh.texcoords = uvs;
        mesh.face_count = 2;
        mesh.face_offsets = offsets;
        mesh.face_indices = indices;
        mesh.material_count = 2;
        mesh.materials = materials;
        mesh.face_materials = face_materials;
        cg_image *out = draw(&mesh, &camera, CG_TEXTURE_NEAREST, 120, 120);
        long checked = 0, wrong = 0, red = 0;
        quad q = {{0, 0, 0.5}, {1, 0, 0}, {0, 1, 0}, {0, 0}, 1, 1};
        for (int y = 0; y < 120; y++)
            for (int x = 0; x < 120; x++) {
                double uv[2];
                if (!pixel_uv(&q, &camera, 120, 120, x + 0.5, y + 0.5, 1e-3, uv))
                    continue;
                double tx = uv[0] * TEX, ty = (1 - uv[1]) * TEX;
                if (near_integer(tx, 0.02) || near_integer(ty, 0.02))
                    continue;
                int i = wrap((long long)floor(ty), TEX, CG_TEXTURE_REPEAT) * TEX
                        + wrap((long long)floor(tx), TEX, CG_TEXTURE_REPEAT);
                cg_rgba8 p = cg_image_get_rgba8(out, x, y);
                cg_rgba8 want = alpha[i] ? (cg_rgba8){texels[i][0], texels[i][1], texels[i][2], 255}
                                         : (cg_rgba8){255, 0, 0, 255};
                red += !alpha[i];
                checked++;
                if (abs(p.r - want.r) > 1 || abs(p.g - want.g) > 1 || abs(p.b - want.b) > 1)
                    wrong++;
            }
        CHECK_MSG(checked > 5000 && red > 1000, "order %d: %ld checked, %ld red", order, checked,
                  red);
        CHECK_MSG(wrong == 0, "order %d: %ld of %ld pixels wrong", order, wrong, checked);
        cg_image_free(out);
    }
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(facing_nearest);
    CHECK_GROUP(tilted_perspective);
    CHECK_GROUP(wrap_modes);
    CHECK_GROUP(filtered);
    CHECK_GROUP(missing_texture);
    CHECK_GROUP(alpha_mask);
    return check_finish();
}
