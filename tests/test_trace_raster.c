/* The ray tracer against the rasterizer (module render) on the same meshes
 * and cameras: the pixels each covers (pixel centres, no supersampling)
 * agree on at least 99.5% of the image. */
#include "check.h"
#include "cg/mesh.h"
#include "cg/render.h"
#include "cg/trace.h"

static void compare(const char *name, cg_mesh *mesh, cg_vec3 direction, int orthographic)
{
    const int w = 200, h = 150;
    cg_vec3 lo, hi;
    CHECK(cg_mesh_bounds(mesh, &lo, &hi) == CG_OK);
    cg_camera camera = cg_camera_default();
    camera.eye = cg_vec3_sub(camera.target, direction);
    camera.orthographic = orthographic;
    CHECK(cg_camera_frame(&camera, lo, hi, (double)w / h) == CG_OK);

    cg_render_options o;
    cg_render_options_default(&o);
    o.camera = camera;
    o.frame_camera = 0;
    o.cull = CG_CULL_NONE;
    o.background = (cg_rgbaf){0, 0, 0, 0};
    cg_image *raster, *traced;
    cg_image_create(&raster, w, h, CG_PIXEL_RGBA8);
    cg_image_create(&traced, w, h, CG_PIXEL_RGBA8);
    cg_error err;
    CHECK(cg_render(mesh, &o, raster, &err) == CG_OK);

    cg_trace_scene *scene;
    cg_trace_scene_create(&scene);
    cg_trace_material m = cg_trace_material_default();
    CHECK(cg_trace_scene_add_mesh(scene, mesh, NULL, cg_radians(60), &m) == CG_OK);
    cg_trace_options opt = cg_trace_options_default();
    opt.background = (cg_rgbaf){0, 0, 0, 0};
    opt.shadows = 0;
    opt.max_depth = 0;
    CHECK(cg_trace_render(scene, &camera, &opt, traced, NULL) == CG_OK);

    long agree = 0, covered = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int a = cg_image_get_rgba8(raster, x, y).a > 0,
                b = cg_image_get_rgba8(traced, x, y).a > 0;
            agree += a == b;
            covered += a;
        }
    double rate = (double)agree / (w * h);
    printf("%s: %ld pixels covered by the rasterizer, masks agree on %.3f%%\n", name, covered,
           100 * rate);
    CHECK_MSG(rate >= 0.995, "%s: masks agree on only %.3f%%", name, 100 * rate);
    CHECK_MSG(covered > w * h / 20, "%s: only %ld pixels covered", name, covered);
    cg_trace_scene_free(scene);
    cg_image_free(raster);
    cg_image_free(traced);
}

int main(void)
{
    cg_mesh *mesh;
    CHECK(cg_mesh_torus(48, 24, 1, 0.35, &mesh) == CG_OK);
    compare("torus", mesh, cg_vec3_make(0.3, -0.8, -1), 0);
    compare("torus, parallel", mesh, cg_vec3_make(-0.5, -0.4, -1), 1);
    cg_mesh_free(mesh);
    CHECK(cg_mesh_box(cg_vec3_make(-1, -0.5, -2), cg_vec3_make(1, 0.5, 2), &mesh) == CG_OK);
    compare("box", mesh, cg_vec3_make(1, -1, -1), 0);
    cg_mesh_free(mesh);
    cg_error err;
    if (cg_mesh_load(CG_SOURCE_DIR "/data/meshes/bunny.obj", &mesh, &err) == CG_OK) {
        compare("bunny", mesh, cg_vec3_make(0, 0, -1), 0);
        compare("bunny, from above", mesh, cg_vec3_make(0.4, -1, -0.3), 0);
        cg_mesh_free(mesh);
    } else {
        printf("bunny: %s (skipped)\n", err.message);
    }
    return check_finish();
}
