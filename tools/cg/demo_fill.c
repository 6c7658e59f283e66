/* Gallery: filling (chapter 10) - even-odd against non-zero, joins and caps,
 * dashes and gradients, a flood-filled maze, 4- against 8-connectivity. */
#include "demo.h"
#include "cg/fill.h"
#include "../../tests/maze.h"

#include <stdio.h>
#include <stdlib.h>

#define COMMAND "cg demo --only Filling"

static const cg_rgba8 paper = {250, 248, 242, 255}, ink = {40, 40, 48, 255};

static int save(demo_context *context, const char *file, cg_image *image, const char *caption)
{
    int status = demo_add(context, file, image, caption, COMMAND);
    cg_image_free(image);
    return status;
}

static cg_image *canvas(int width, int height)
{
    cg_image *image;
    if (cg_image_create(&image, width, height, CG_PIXEL_RGBA8) != CG_OK)
        return NULL;
    cg_image_clear_rgba8(image, paper);
    return image;
}

static void stroke_svg(cg_rasterizer *r, cg_image *image, const char *data, double width,
                       cg_rgba8 color)
{
    cg_path *path;
    if (cg_path_create(&path) != CG_OK)
        return;
    cg_stroke_style style = cg_stroke_style_default();
    style.width = width;
    style.join = CG_JOIN_ROUND;
    cg_paint paint = cg_paint_solid(color);
    if (cg_path_append_svg(path, data, NULL) == CG_OK)
        cg_rasterizer_stroke_path(r, image, path, &style, &paint);
    cg_path_free(path);
}

/* A pentagram and two overlapping rings drawn in one direction, filled
 * even-odd (left) and non-zero (right). */
static int fill_rules(demo_context *context, cg_rasterizer *r)
{
    cg_image *image = canvas(520, 260);
    if (!image)
        return 1;
    cg_rgba8 colors[2] = {{214, 92, 62, 255}, {58, 118, 190, 255}};
    cg_path *path;
    if (cg_path_create(&path) != CG_OK) {
        cg_image_free(image);
        return 1;
    }
    for (int half = 0; half < 2; half++)
        for (int s = 0; s < 2; s++) {
            char d[512];
            if (s == 0)
                snprintf(d, sizeof d, "M %d 20 l 60 195 l -165 -120 l 210 0 l -165 120 Z",
                         130 + 260 * half);
            else
                snprintf(d, sizeof d,
                         "M %d 180 a 34 34 0 1 1 68 0 a 34 34 0 1 1 -68 0 Z "
                         "M %d 180 a 34 34 0 1 1 68 0 a 34 34 0 1 1 -68 0 Z",
                         62 + 260 * half, 100 + 260 * half);
            cg_path_reset(path);
            cg_path_append_svg(path, d, NULL);
            cg_paint paint = cg_paint_solid(colors[s]), outline = cg_paint_solid(ink);
            cg_rasterizer_fill_path(r, image, path, half ? CG_FILL_NONZERO : CG_FILL_EVEN_ODD,
                                    &paint);
            cg_stroke_style thin = cg_stroke_style_default();
            thin.width = 1.2;
            cg_rasterizer_stroke_path(r, image, path, &thin, &outline);
        }
    cg_path_free(path);
    return save(context, "fill-rules.png", image,
                "Even-odd (left) against non-zero winding (right): a pentagram and two rings "
                "traced the same way; anti-aliased by exact area coverage");
}

/* Thick zig-zags with each join, over their centre lines, and segments with
 * each cap. */
static int joins_and_caps(demo_context *context, cg_rasterizer *r)
{
    cg_image *image = canvas(540, 330);
    if (!image)
        return 1;
    cg_rgba8 colors[3] = {{64, 140, 110, 255}, {214, 128, 52, 255}, {112, 92, 190, 255}};
    cg_rgba8 red = {220, 40, 40, 255};
    for (int j = 0; j < 3; j++) {
        double x = 30 + 175 * j;
        char zig[256];
        snprintf(zig, sizeof zig, "M %g 150 L %g 50 L %g 150 L %g 70 L %g 140", x, x + 35, x + 70,
                 x + 105, x + 140);
        cg_path *path;
        if (cg_path_create(&path) != CG_OK)
            break;
        cg_path_append_svg(path, zig, NULL);
        cg_stroke_style style = cg_stroke_style_default();
        style.width = 22;
        style.join = (cg_line_join)j;
        style.miter_limit = 10;
        cg_paint paint = cg_paint_solid(colors[j]);
        cg_rasterizer_stroke_path(r, image, path, &style, &paint);
        stroke_svg(r, image, zig, 1.5, red);
        /* caps: butt, round, square on a horizontal segment */
        char segment[128];
        snprintf(segment, sizeof segment, "M %g 215 L %g 215", x + 25, x + 115);
        cg_path_reset(path);
        cg_path_append_svg(path, segment, NULL);
        style = cg_stroke_style_default();
        style.width = 26;
        style.cap = (cg_line_cap)j;
        cg_rasterizer_stroke_path(r, image, path, &style, &paint);
        stroke_svg(r, image, segment, 1.5, red);
        /* dashes with the same cap */
        snprintf(segment, sizeof segment, "M %g 290 A 70 30 0 0 1 %g 290", x + 5, x + 135);
        cg_path_reset(path);
        cg_path_append_svg(path, segment, NULL);
        double dashes[2] = {14, 12};
        style.width = 9;
        style.dashes = dashes;
        style.dash_count = 2;
        cg_rasterizer_stroke_path(r, image, path, &style, &paint);
        cg_path_free(path);
    }
    return save(context, "fill-joins-caps.png", image,
                "Strokes turned into polygons: miter, round and bevel joins (top), butt, round "
                "and square caps (middle; centre lines in red), dashed arcs with each cap");
}

/* A glyph-like outline of arcs and lines: solid, linear and radial
 * gradients. */
static int gradients(demo_context *context, cg_rasterizer *r)
{
    cg_image *image = canvas(540, 175);
    if (!image)
        return 1;
    cg_gradient_stop warm[3] = {{0, {250, 200, 60, 255}}, {0.5, {230, 80, 60, 255}},
                                {1, {120, 30, 110, 255}}};
    cg_gradient_stop cool[2] = {{0, {255, 255, 255, 255}}, {1, {30, 90, 170, 255}}};
    /* the same ring with a notch, three times */
    for (int k = 0; k < 3; k++) {
        double cx = 90 + 180 * k;
        char d[512];
        snprintf(d, sizeof d,
                 "M %g 110 A 80 80 0 1 1 %g 110 L %g 110 A 42 42 0 1 0 %g 110 Z "
                 "M %g 60 L %g 110 L %g 160 Z",
                 cx - 80, cx + 80, cx + 42, cx - 42, cx - 24, cx + 30, cx - 24);
        cg_path *path;
        if (cg_path_create(&path) != CG_OK)
            break;
        cg_path_append_svg(path, d, NULL);
        cg_paint paint = k == 0   ? cg_paint_solid(ink)
                         : k == 1 ? cg_paint_linear(cg_vec2_make(cx - 80, 30),
                                                    cg_vec2_make(cx + 80, 190), warm, 3)
                                  : cg_paint_radial(cg_vec2_make(cx - 20, 80), 110, cool, 2);
        cg_rasterizer_fill_path(r, image, path, CG_FILL_EVEN_ODD, &paint);
        cg_path_free(path);
    }
    return save(context, "fill-gradients.png", image,
                "Paths of arcs and lines filled even-odd: solid, a linear gradient and a radial "
                "gradient, interpolated in linear light");
}

/* A random maze with a few passages walled up, each separate region
 * flood-filled from one seed in its own colour. */
static int maze(demo_context *context)
{
    enum { CELLS = 40, SCALE = 6 };
    int side = 2 * CELLS + 1;
    cg_image *small;
    if (cg_image_create(&small, side, side, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_rgba8 wall = {44, 44, 54, 255}, open = {255, 255, 255, 255};
    /* every 97th passage stays walled: the maze falls into regions */
    if (maze_draw(small, CELLS, CELLS, 12345, 97, wall, open) != 0) {
        cg_image_free(small);
        return 1;
    }
    static const cg_rgba8 palette[] = {{230, 90, 70, 255},  {70, 150, 220, 255}, {90, 180, 100, 255},
                                       {240, 180, 50, 255}, {160, 100, 200, 255}, {60, 190, 180, 255},
                                       {220, 120, 170, 255}, {150, 150, 60, 255}};
    int regions = 0;
    for (int y = 1; y < side; y += 2)
        for (int x = 1; x < side; x += 2) {
            cg_rgba8 p = cg_image_get_rgba8(small, x, y);
            if (p.r == 255 && p.g == 255 && p.b == 255)
                cg_flood_fill(small, x, y, palette[regions++ % 8], CG_CONNECT_4, 0, NULL);
        }
    cg_image *image;
    if (cg_image_create(&image, side * SCALE, side * SCALE, CG_PIXEL_RGBA8) != CG_OK) {
        cg_image_free(small);
        return 1;
    }
    for (int y = 0; y < side * SCALE; y++)
        for (int x = 0; x < side * SCALE; x++)
            cg_image_set_rgba8(image, x, y, cg_image_get_rgba8(small, x / SCALE, y / SCALE));
    cg_image_free(small);
    return save(context, "fill-maze.png", image,
                "Flood fill: a random maze with some passages walled up; each region filled "
                "from one seed by the scan-line span algorithm (4-connected), in its own colour");
}

/* One-pixel diagonal gaps: a 4-connected fill stops, an 8-connected one
 * leaks through.  Shown enlarged. */
static int connectivity(demo_context *context)
{
    enum { N = 24, SCALE = 11 };
    cg_rgba8 white = {255, 255, 255, 255}, wall = {44, 44, 54, 255};
    cg_rgba8 fills[2] = {{70, 150, 220, 255}, {230, 90, 70, 255}};
    cg_image *image;
    if (cg_image_create(&image, 2 * N * SCALE + SCALE, N * SCALE, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_image_clear_rgba8(image, paper);
    for (int k = 0; k < 2; k++) {
        cg_image *small;
        if (cg_image_create(&small, N, N, CG_PIXEL_RGBA8) != CG_OK)
            break;
        cg_image_clear_rgba8(small, white);
        for (int i = 0; i < N; i++) { /* a diagonal wall and a staircase */
            cg_image_set_rgba8(small, i, N - 1 - i, wall);
            if (i % 6 < 3)
                cg_image_set_rgba8(small, (i + N / 2) % N, i, wall);
        }
        cg_flood_fill(small, 1, 1, fills[k], k ? CG_CONNECT_8 : CG_CONNECT_4, 0, NULL);
        for (int y = 0; y < N * SCALE; y++)
            for (int x = 0; x < N * SCALE; x++) {
                cg_rgba8 p = cg_image_get_rgba8(small, x / SCALE, y / SCALE);
                if (x % SCALE == 0 || y % SCALE == 0) { /* grid lines */
                    p.r = (uint8_t)(p.r * 0.85);
                    p.g = (uint8_t)(p.g * 0.85);
                    p.b = (uint8_t)(p.b * 0.85);
                }
                cg_image_set_rgba8(image, x + k * (N + 1) * SCALE, y, p);
            }
        cg_image_free(small);
    }
    return save(context, "fill-connectivity.png", image,
                "Seed fill from the top-left pixel: 4-connected (left) stops at the one-pixel "
                "diagonal wall, 8-connected (right) slips through its corners");
}

static int render(demo_context *context)
{
    cg_rasterizer *r;
    if (cg_rasterizer_create(&r) != CG_OK)
        return 1;
    int failed = fill_rules(context, r);
    failed |= joins_and_caps(context, r);
    failed |= gradients(context, r);
    failed |= maze(context);
    failed |= connectivity(context);
    cg_rasterizer_free(r);
    return failed;
}

const demo_section demo_section_fill = {10, "Filling", render};
