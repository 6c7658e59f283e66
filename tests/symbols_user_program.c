/* A user's program that links libcg and also defines, as variables of its
 * own, every global name libcg's modules use internally (the generated file
 * symbols_user_names.c, made by test_symbols.sh).  It links and runs only when
 * libcg keeps those names to itself.  It loads and renders a scene (scene
 * parser, mesh reader, rasterizer, ray tracer), writes a PNG and runs a
 * boolean operation, so that the internal functions behind them are called.
 * Usage: symbols_user_program SCENE.json OUT.png */
#include <cg.h>
#include <stdio.h>

int main(int argc, char **argv)
{
    if (argc != 3)
        return 2;
    cg_error err = {0};
    cg_scene *scene = NULL;
    if (cg_scene_load(argv[1], &scene, &err) != CG_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    int failed = 0;
    for (int algorithm = CG_SCENE_ZBUFFER; algorithm <= CG_SCENE_RAYTRACE && !failed; algorithm++) {
        cg_image *image = NULL;
        failed = cg_scene_render_with(scene, (cg_scene_algorithm)algorithm, &image, &err) != CG_OK
                 || cg_image_write(image, argv[2], CG_FILE_UNKNOWN, &err) != CG_OK;
        cg_image_free(image);
    }
    cg_scene_free(scene);
    if (failed) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }

    cg_vec2 square[4] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    cg_vec2 shifted[4] = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    cg_polygon_set a = {0}, b = {0}, result = {0};
    if (cg_polygon_set_add_ring(&a, square, 4, 1) != CG_OK
        || cg_polygon_set_add_ring(&b, shifted, 4, 1) != CG_OK
        || cg_clip_boolean(CG_CLIP_UNION, &a, CG_CLIP_NON_ZERO, &b, CG_CLIP_NON_ZERO, 1024, &result)
               != CG_OK)
        return 1;
    double area = cg_polygon_set_area(&result);
    cg_polygon_set_clear(&a);
    cg_polygon_set_clear(&b);
    cg_polygon_set_clear(&result);
    printf("union area %g\n", area);
    return area == 7 ? 0 : 1;
}
