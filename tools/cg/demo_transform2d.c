/* Gallery: 2D transformations in homogeneous coordinates (chapter 4). */
#include "demo.h"
#include "cg/draw.h"
#include "cg/xform.h"

#define SIZE 300
#define SCALE 25.0 /* pixels per unit; the origin is at the centre */

static const cg_vec2 house[5] = {{0, 0}, {2, 0}, {2, 2}, {1, 3}, {0, 2}};

static void to_pixel(cg_vec2 p, int *x, int *y)
{
    *x = (int)lround(SIZE / 2.0 + SCALE * p.x);
    *y = (int)lround(SIZE / 2.0 - SCALE * p.y);
}

static void draw_shape(cg_image *image, cg_mat3 m, cg_rgba8 color)
{
    for (int i = 0; i < 5; i++) {
        int x0, y0, x1, y1;
        to_pixel(cg_mat3_transform_point(m, house[i]), &x0, &y0);
        to_pixel(cg_mat3_transform_point(m, house[(i + 1) % 5]), &x1, &y1);
        cg_draw_line(image, x0, y0, x1, y1, color);
    }
}

static void draw_axes(cg_image *image)
{
    cg_rgba8 axis = {200, 200, 200, 255};
    cg_draw_line(image, 0, SIZE / 2, SIZE - 1, SIZE / 2, axis);
    cg_draw_line(image, SIZE / 2, 0, SIZE / 2, SIZE - 1, axis);
}

static int picture(demo_context *context, const char *file, const char *caption, cg_mat3 m)
{
    cg_image *image;
    if (cg_image_create(&image, SIZE, SIZE, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_rgba8 white = {255, 255, 255, 255}, grey = {120, 120, 120, 255}, red = {210, 40, 40, 255};
    cg_image_clear_rgba8(image, white);
    draw_axes(image);
    draw_shape(image, cg_mat3_identity(), grey);
    draw_shape(image, m, red);
    int status = demo_add(context, file, image, caption, "cg demo --only '2D transformations'");
    cg_image_free(image);
    return status;
}

static int render(demo_context *context)
{
    cg_mat3 reflect;
    cg_xform2_reflect(cg_vec2_make(0, 1), cg_vec2_make(2, 1), &reflect);
    cg_mat3 rotate_then_move[2] = {cg_xform2_rotate(cg_radians(90), 0, 0),
                                   cg_xform2_translate(3, 0)};
    cg_mat3 move_then_rotate[2] = {cg_xform2_translate(3, 0),
                                   cg_xform2_rotate(cg_radians(90), 0, 0)};
    int failed = 0;
    failed |= picture(context, "transform-translate.png", "Translation by (2, 1)",
                      cg_xform2_translate(2, 1));
    failed |= picture(context, "transform-rotate.png", "Rotation by 45 deg about (2, 0)",
                      cg_xform2_rotate(cg_radians(45), 2, 0));
    failed |= picture(context, "transform-scale.png", "Scaling by (1.5, 0.5) about (1, 0)",
                      cg_xform2_scale(1.5, 0.5, 1, 0));
    failed |= picture(context, "transform-reflect.png", "Reflection about the line y = x/2 + 1",
                      reflect);
    failed |= picture(context, "transform-shear.png", "Shear x' = x + 0.8 y",
                      cg_xform2_shear(0.8, 0));
    failed |= picture(context, "transform-compose-rt.png",
                      "Composition: rotate 90 deg, then translate by (3, 0)",
                      cg_mat3_compose(rotate_then_move, 2));
    failed |= picture(context, "transform-compose-tr.png",
                      "Composition: translate by (3, 0), then rotate 90 deg (order matters)",
                      cg_mat3_compose(move_then_rotate, 2));
    return failed;
}

const demo_section demo_section_transform2d = {4, "2D transformations", render};
