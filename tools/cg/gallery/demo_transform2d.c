/* Gallery: 2D transformations in homogeneous coordinates (chapter 4). */
#include "script_pictures.h"
#include "cg/xform.h"

#define SIZE 300
#define SCALE 25.0 /* pixels per unit; the origin is at the centre */

static const cg_vec2 house[5] = {{0, 0}, {2, 0}, {2, 2}, {1, 3}, {0, 2}};

static void to_pixel(cg_vec2 p, int *x, int *y)
{
    *x = (int)lround(SIZE / 2.0 + SCALE * p.x);
    *y = (int)lround(SIZE / 2.0 - SCALE * p.y);
}

/* The house's outline under m, as `line` commands of a draw script. */
static void script_shape(script_text *script, cg_mat3 m, const char *color)
{
    script_add(script, "color %s\n", color);
    for (int i = 0; i < 5; i++) {
        int x0, y0, x1, y1;
        to_pixel(cg_mat3_transform_point(m, house[i]), &x0, &y0);
        to_pixel(cg_mat3_transform_point(m, house[(i + 1) % 5]), &x1, &y1);
        script_add(script, "line %d %d %d %d\n", x0, y0, x1, y1);
    }
}

/* The transform is applied in C; the picture is the draw script of the axes,
 * the house (grey) and its image (red), written next to it. */
static int picture(demo_context *context, const char *name, const char *caption, cg_mat3 m)
{
    script_text script = {.length = 0};
    script_add(&script, "size %d %d\nbackground #ffffff\ncolor #c8c8c8\n", SIZE, SIZE);
    script_add(&script, "line 0 %d %d %d\nline %d 0 %d %d\n", SIZE / 2, SIZE - 1, SIZE / 2,
               SIZE / 2, SIZE / 2, SIZE - 1);
    script_shape(&script, cg_mat3_identity(), "#787878");
    script_shape(&script, m, "#d22828");
    return draw_demo_script(context, name, script.text, caption);
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
    failed |= picture(context, "transform-translate", "Translation by (2, 1)",
                      cg_xform2_translate(2, 1));
    failed |= picture(context, "transform-rotate", "Rotation by 45 deg about (2, 0)",
                      cg_xform2_rotate(cg_radians(45), 2, 0));
    failed |= picture(context, "transform-scale", "Scaling by (1.5, 0.5) about (1, 0)",
                      cg_xform2_scale(1.5, 0.5, 1, 0));
    failed |= picture(context, "transform-reflect", "Reflection about the line y = x/2 + 1",
                      reflect);
    failed |= picture(context, "transform-shear", "Shear x' = x + 0.8 y", cg_xform2_shear(0.8, 0));
    failed |= picture(context, "transform-compose-rt",
                      "Composition: rotate 90 deg, then translate by (3, 0)",
                      cg_mat3_compose(rotate_then_move, 2));
    failed |= picture(context, "transform-compose-tr",
                      "Composition: translate by (3, 0), then rotate 90 deg (order matters)",
                      cg_mat3_compose(move_then_rotate, 2));
    return failed;
}

const demo_section demo_section_transform2d = {4, "2D transformations", render};
