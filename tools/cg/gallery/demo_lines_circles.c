/* Gallery: scan conversion of lines, circles and ellipses (sections 2.1-2.2). */
#include "script_pictures.h"
#include "cg/draw.h"

#include <stdio.h>
#include <string.h>

static const cg_rgba8 ink = {30, 60, 140, 255}, red = {220, 40, 40, 255},
                      orange = {240, 140, 20, 255};

/* Bresenham's line from (1, 1) to (22, 9), magnified, with the real line
 * through the pixel centres and the midpoints Algorithm 1 tests. */
static int zoomed_line(demo_context *context)
{
    zoom z;
    int x0 = 1, y0 = 1, x1 = 22, y1 = 9;
    if (zoom_create(&z, 24, 11, 22))
        return 1;
    cg_image *grid;
    cg_image_create(&grid, 24, 11, CG_PIXEL_RGBA8);
    cg_draw_line(grid, x0, y0, x1, y1, ink);
    zoom_fill_drawn(&z, grid, (cg_rgba8){140, 170, 230, 255});
    cg_image_free(grid);
    sketch k = {0};
    zoom_to_script(&z, &k);
    /* midpoints (x + 1, y + 1/2) tested at each step, in pixel-centre terms */
    long long dx = x1 - x0, dy = y1 - y0, f = 2 * dy - dx, y = y0;
    for (int x = x0; x < x1; x++) {
        double mx = zoom_x(&z, x + 1.5), my = zoom_x(&z, y + 1.0);
        cg_rgba8 c = f > 0 ? red : orange;
        sketch_add(&k, "color #%02x%02x%02x\ndisc %d %d 3\n", c.r, c.g, c.b, (int)mx, (int)my);
        if (f > 0) {
            y++;
            f += 2 * (dy - dx);
        } else {
            f += 2 * dy;
        }
    }
    sketch_add(&k, "color #141414\naaline %.17g %.17g %.17g %.17g\n", zoom_x(&z, x0 + 0.5),
               zoom_x(&z, y0 + 0.5), zoom_x(&z, x1 + 0.5), zoom_x(&z, y1 + 0.5));
    return draw_demo_sketch(context, &k, "draw-line-zoom",
                            "Bresenham's line (Algorithm 1) from (1, 1) to (22, 9), magnified: the "
                            "real line through the pixel centres, and the midpoints tested at each "
                            "step (red: below the line, NE chosen; orange: above or on it, E); the "
                            "steps as text: cg trace line 1 1 22 9");
}

/* Colours the cells of the first octant as Algorithm 2 selects them. */
typedef struct octant_cells {
    zoom *z;
    int c;
} octant_cells;
static int octant_cell(void *user, const cg_circle_step *s)
{
    octant_cells *o = user;
    if (s->x <= s->y)
        zoom_fill(o->z, o->c + s->x, o->c - s->y, (cg_rgba8){240, 150, 60, 255});
    return 0;
}

/* The digital circle of radius 11 magnified, octant 1 highlighted, with the
 * real circle. */
static int zoomed_circle(demo_context *context)
{
    zoom z;
    int r = 11, c = 13;
    if (zoom_create(&z, 27, 27, 16))
        return 1;
    cg_image *grid;
    cg_image_create(&grid, 27, 27, CG_PIXEL_RGBA8);
    cg_draw_circle(grid, c, c, r, ink);
    zoom_fill_drawn(&z, grid, (cg_rgba8){140, 170, 230, 255});
    cg_image_free(grid);
    octant_cells cells = {&z, c};
    cg_circle_trace(r, octant_cell, &cells);
    double cx = zoom_x(&z, c + 0.5);
    sketch k = {0};
    zoom_to_script(&z, &k);
    sketch_add(&k, "color #141414\naacircle %.17g %.17g %d\ncolor #787878a0\n", cx, cx, r * z.cell);
    /* the lines of symmetry */
    for (int i = 0; i < 4; i++) {
        double a = i * CG_PI / 4, len = (r + 2) * z.cell;
        sketch_add(&k, "aaline %.17g %.17g %.17g %.17g\n", cx - len * cos(a), cx - len * sin(a),
                   cx + len * cos(a), cx + len * sin(a));
    }
    return draw_demo_sketch(context, &k, "draw-circle-zoom",
                            "Bresenham's midpoint circle (Algorithm 2) of radius 11, magnified: "
                            "octant 1 (orange, 0 <= x <= y) is computed and mirrored about the "
                            "four lines of symmetry; each pixel is drawn once; the steps as text: "
                            "cg trace circle 11");
}

static int lines(demo_context *context)
{
    script_text s;
    s.length = 0;
    script_add(&s, "# Bresenham lines in every octant (left) and anti-aliased lines (right)\n"
                   "size 640 320\nbackground white\n");
    for (int k = 0; k < 48; k++) {
        double a = k * 2 * CG_PI / 48;
        const char *colors[3] = {"#1f4e9c", "#c0392b", "#27ae60"};
        script_add(&s, "color %s\nline 160 160 %d %d\n", colors[k % 3],
                   160 + (int)lround(145 * cos(a)), 160 - (int)lround(145 * sin(a)));
        script_add(&s, "aaline 480.5 160.5 %.3f %.3f\n", 480.5 + 145 * cos(a),
                   160.5 - 145 * sin(a));
    }
    return draw_demo_script(
        context, "draw-lines", s.text,
        "48 lines from a centre: Bresenham (left; drawing a to b or b to a gives the "
        "same pixels) and anti-aliased with exact coverage per column, blended in "
        "linear light, so every direction is equally bright (right)");
}

static int circles(demo_context *context)
{
    script_text s;
    s.length = 0;
    script_add(&s,
               "# Bresenham circles, discs, ellipses and arcs\nsize 640 320\nbackground white\n");
    for (int r = 4; r <= 140; r += 8)
        script_add(&s, "color #%02x%02x%02x\ncircle 160 160 %d\n", 40 + r, 80, 220 - r, r);
    script_add(&s, "color #f39c12\ndisc 430 80 50\ncolor #2980b9c0\ndisc 480 110 40\n"
                   "color #8e44ad\nellipse 470 230 150 60\nellipse 470 230 60 75\n"
                   "ellipse 470 230 110 20\ncolor #c0392b\narc 470 230 40 30 150\n"
                   "arc 470 230 48 200 340\nellipsearc 470 230 130 40 -60 60\n");
    return draw_demo_script(context, "draw-circles", s.text,
                            "Midpoint circles of radius 4 to 140 (8-way symmetry), filled discs (a "
                            "half-transparent one blends once per pixel), midpoint ellipses and "
                            "circular and elliptical arcs between two angles");
}

static int antialiased(demo_context *context)
{
    script_text s;
    s.length = 0;
    script_add(&s, "# anti-aliased circles and ellipses against their Bresenham forms\n"
                   "size 640 240\nbackground #101820\n");
    for (int k = 0; k < 7; k++) {
        double r = 6 + k * 15.3;
        script_add(&s,
                   "color #ffd166\ncircle 120 120 %d\ncolor #06d6a0\naacircle 360.5 120.5 %.1f\n",
                   (int)r, r);
    }
    script_add(&s, "color #ef476f\naaellipse 555 120 75 30.5\naaellipse 555 120 30 100\n"
                   "aaellipse 555 120 55 55\n");
    return draw_demo_script(
        context, "draw-aa-circles", s.text,
        "Bresenham circles (left) and anti-aliased circles and ellipses (right): "
        "each pixel's coverage is 1 - |distance to the curve|, blended in linear light");
}

static int render(demo_context *context)
{
    return zoomed_line(context) || zoomed_circle(context) || lines(context) || circles(context)
           || antialiased(context);
}

const demo_section demo_section_lines_circles = {2, "Lines, circles and ellipses", render};
