/* Gallery: filling (chapter 10) - even-odd against non-zero, joins and caps,
 * dashes and gradients, a flood-filled maze, 4- against 8-connectivity. */
#include "demo.h"
#include "script_pictures.h"
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

/* A pentagram and two overlapping rings traced the same way, filled
 * even-odd (left) and non-zero (right): a `cg draw` script. */
static int fill_rules(demo_context *context)
{
    script_text t = {{0}, 0};
    script_add(&t, "# even-odd (left) against non-zero (right)\nsize 520 260\n"
                   "background #faf8f2\nwidth 1.2\n");
    static const char *const rules[2] = {"evenodd", "nonzero"};
    for (int half = 0; half < 2; half++) {
        int dx = 260 * half;
        script_add(&t, "fillrule %s\n", rules[half]);
        script_add(&t, "path M %d 20 l 60 195 l -165 -120 l 210 0 l -165 120 Z\n", 130 + dx);
        script_add(&t, "color #d65c3e\nfill\ncolor #282830\nstroke\n");
        script_add(&t,
                   "path M %d 180 a 34 34 0 1 1 68 0 a 34 34 0 1 1 -68 0 Z "
                   "M %d 180 a 34 34 0 1 1 68 0 a 34 34 0 1 1 -68 0 Z\n",
                   62 + dx, 100 + dx);
        script_add(&t, "color #3a76be\nfill\ncolor #282830\nstroke\n");
    }
    return draw_demo_script(context, "fill-rules", t.text,
                            "Even-odd (left) against non-zero winding (right): a pentagram and "
                            "two rings traced the same way; anti-aliased by exact area coverage");
}

/* Thick zig-zags with each join and segments with each cap over their
 * centre lines, and dashed arcs: a `cg draw` script. */
static int joins_and_caps(demo_context *context)
{
    static const char *const joins[3] = {"miter", "round", "bevel"};
    static const char *const caps[3] = {"butt", "round", "square"};
    static const char *const colors[3] = {"#408c6e", "#d68034", "#705cbe"};
    script_text t = {{0}, 0};
    script_add(&t, "# joins (top), caps (middle), dashes (bottom)\nsize 540 330\n"
                   "background #faf8f2\n");
    for (int j = 0; j < 3; j++) {
        double x = 30 + 175 * j;
        char zig[160], segment[96];
        snprintf(zig, sizeof zig, "M %g 150 L %g 50 L %g 150 L %g 70 L %g 140", x, x + 35, x + 70,
                 x + 105, x + 140);
        snprintf(segment, sizeof segment, "M %g 215 L %g 215", x + 25, x + 115);
        script_add(&t, "color %s\nwidth 22\njoin %s\ncap butt\ndash\npath %s\nstroke\n", colors[j],
                   joins[j], zig);
        script_add(&t, "color #dc2828\nwidth 1.5\njoin round\nstroke\n");
        script_add(&t, "color %s\nwidth 26\ncap %s\npath %s\nstroke\n", colors[j], caps[j],
                   segment);
        script_add(&t, "color #dc2828\nwidth 1.5\ncap butt\nstroke\n");
        script_add(&t,
                   "color %s\nwidth 9\ncap %s\ndash 14 12\n"
                   "path M %g 290 A 70 30 0 0 1 %g 290\nstroke\n",
                   colors[j], caps[j], x + 5, x + 135);
    }
    return draw_demo_script(context, "fill-joins-caps", t.text,
                            "Strokes turned into polygons: miter, round and bevel joins (top), "
                            "butt, round and square caps (middle; centre lines in red), dashed "
                            "arcs with each cap");
}

/* A glyph-like outline of arcs and lines: solid, linear and radial
 * gradients. */
static int gradients(demo_context *context, cg_rasterizer *r)
{
    cg_image *image = canvas(540, 175);
    if (!image)
        return 1;
    cg_gradient_stop warm[3] = {{0, {250, 200, 60, 255}},
                                {0.5, {230, 80, 60, 255}},
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
 * flood-filled from one seed in its own colour.  The maze is generated in C
 * and drawn magnified by a script: its walls as rectangles (one per run of
 * wall pixels in a row), then a flood from each region's seed (magnified by
 * whole blocks, the regions keep their 4-connectivity). */
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
    sketch k = {0};
    sketch_add(&k, "size %d %d\nbackground #%02x%02x%02x\ncolor #%02x%02x%02x\n", side * SCALE,
               side * SCALE, open.r, open.g, open.b, wall.r, wall.g, wall.b);
    for (int y = 0; y < side; y++)
        for (int x = 0; x < side;) {
            int end = x;
            while (end < side && cg_image_get_rgba8(small, end, y).r == wall.r)
                end++;
            if (end > x)
                sketch_add(&k, "polygon %d %d %d %d %d %d %d %d\n", x * SCALE, y * SCALE,
                           end * SCALE, y * SCALE, end * SCALE, (y + 1) * SCALE, x * SCALE,
                           (y + 1) * SCALE);
            x = end > x ? end : x + 1;
        }
    static const cg_rgba8 palette[] = {
        {230, 90, 70, 255},   {70, 150, 220, 255}, {90, 180, 100, 255},  {240, 180, 50, 255},
        {160, 100, 200, 255}, {60, 190, 180, 255}, {220, 120, 170, 255}, {150, 150, 60, 255}};
    int regions = 0;
    for (int y = 1; y < side; y += 2)
        for (int x = 1; x < side; x += 2) {
            cg_rgba8 p = cg_image_get_rgba8(small, x, y);
            if (p.r == 255 && p.g == 255 && p.b == 255) {
                cg_rgba8 c = palette[regions++ % 8];
                cg_flood_fill(small, x, y, c, CG_CONNECT_4, 0, NULL);
                sketch_add(&k, "color #%02x%02x%02x\nflood %d %d\n", c.r, c.g, c.b,
                           x * SCALE + SCALE / 2, y * SCALE + SCALE / 2);
            }
        }
    cg_image_free(small);
    return draw_demo_sketch(context, &k, "fill-maze",
                            "Flood fill: a random maze with some passages walled up; each region "
                            "filled from one seed by the scan-line span algorithm (4-connected), "
                            "in its own colour");
}

/* One wall cell of the magnified grid: CELL x CELL pixels from its top-left
 * grid line, so that cells meeting at a corner touch only diagonally. */
static void wall_cell(script_text *t, int x, int y, int cell)
{
    for (int j = 0; j < cell; j++)
        script_add(t, "line %d %d %d %d\n", x * cell, y * cell + j, x * cell + cell - 1,
                   y * cell + j);
}

/* One-pixel diagonal gaps: a 4-connected fill stops, an 8-connected one
 * leaks through.  Drawn magnified by a script: the walls as blocks of pixels,
 * the seed fill run on the magnified picture (its connectivity is that of
 * the pixels), then the grid drawn over it. */
static int connectivity(demo_context *context)
{
    enum { N = 24, CELL = 11 };
    const char *fills[2] = {"#4696dc", "#e65a46"};
    const char *names[2] = {"fill-connect4", "fill-connect8"};
    const char *captions[2] = {
        "Seed fill from the top-left pixel, 4-connected: it stops at the one-pixel diagonal wall",
        "The same seed fill, 8-connected: it slips through the diagonal wall's corners"};
    int failed = 0, side = N * CELL + 1;
    for (int k = 0; k < 2; k++) {
        static script_text t; /* large: a line per pixel row of each wall cell */
        t.length = 0;
        script_add(&t, "size %d %d\nbackground #ffffff\ncolor #2c2c36\n", side, side);
        for (int i = 0; i < N; i++) { /* a diagonal wall and short stairs */
            wall_cell(&t, i, N - 1 - i, CELL);
            if (i % 6 < 3)
                wall_cell(&t, (i + N / 2) % N, i, CELL);
        }
        script_add(&t, "color %s\n%s %d %d\ncolor #cdcdcd\n", fills[k], k ? "flood8" : "flood",
                   CELL + CELL / 2, CELL + CELL / 2);
        for (int g = 0; g <= N; g++)
            script_add(&t, "line %d 0 %d %d\nline 0 %d %d %d\n", g * CELL, g * CELL, side - 1,
                       g * CELL, side - 1, g * CELL);
        failed |= draw_demo_script(context, names[k], t.text, captions[k]);
    }
    return failed;
}

/* One triangle at pixel scale, magnified: the aliased scan-line fill paints
 * the pixels whose centres are inside; the anti-aliased fill shades each
 * pixel by the area it covers.  The true outline is drawn over both. */
static int pixel_view(demo_context *context, cg_rasterizer *r)
{
    enum { W = 22, H = 14, CELL = 16 };
    const cg_vec2 tri[3] = {{2.3, 1.6}, {19.6, 5.2}, {7.4, 12.7}};
    int three = 3, failed = 0;
    cg_rgba8 ink_cell = {58, 118, 190, 255}, red = {220, 40, 40, 255};
    for (int aa = 0; aa < 2; aa++) {
        cg_image *small;
        zoom z;
        if (cg_image_create(&small, W, H, CG_PIXEL_RGBA8) != CG_OK)
            return 1;
        if (zoom_create(&z, W, H, CELL)) {
            cg_image_free(small);
            return 1;
        }
        cg_paint paint = cg_paint_solid(ink_cell);
        if (aa)
            cg_rasterizer_fill_polygon_aa(r, small, tri, &three, 1, CG_FILL_NONZERO, &paint);
        else
            cg_rasterizer_fill_polygon(r, small, tri, &three, 1, CG_FILL_NONZERO, ink_cell);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                cg_rgba8 p = cg_image_get_rgba8(small, x, y);
                if (!p.a)
                    continue;
                /* the cell shows the pixel over white */
                int k = p.a;
                cg_rgba8 c = {(uint8_t)(255 - (255 - p.r) * k / 255),
                              (uint8_t)(255 - (255 - p.g) * k / 255),
                              (uint8_t)(255 - (255 - p.b) * k / 255), 255};
                zoom_fill(&z, x, y, c);
            }
        cg_image_free(small);
        /* the outline and the pixel centres on the magnified image */
        sketch k = {0};
        zoom_to_script(&z, &k);
        sketch_add(&k, "color #%02x%02x%02x\nwidth 2\npath", red.r, red.g, red.b);
        for (int i = 0; i < 3; i++)
            sketch_add(&k, " %c %.17g %.17g", i ? 'L' : 'M', tri[i].x * CELL + 0.5,
                       tri[i].y * CELL + 0.5);
        sketch_add(&k, " Z\nstroke\ncolor #282830\n");
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                double cx = (x + 0.5) * CELL + 0.5, cy = (y + 0.5) * CELL + 0.5, d = 1.6;
                sketch_add(&k,
                           "path M %.17g %.17g A %g %g 0 1 1 %.17g %.17g A %g %g 0 1 1 %.17g "
                           "%.17g Z\nfill\n",
                           cx + d, cy, d, d, cx - d, cy, d, d, cx + d, cy);
            }
        failed |= draw_demo_sketch(context, &k, aa ? "fill-pixels-aa" : "fill-pixels-aliased",
                                   aa ? "Anti-aliased fill, magnified: each pixel shaded by the "
                                        "exact area of it inside the triangle (signed-area "
                                        "accumulation)"
                                      : "Scan-line fill, magnified: a pixel is painted when its "
                                        "centre (dot) is inside the triangle (red)");
    }
    return failed;
}

static int render(demo_context *context)
{
    cg_rasterizer *r;
    if (cg_rasterizer_create(&r) != CG_OK)
        return 1;
    int failed = pixel_view(context, r);
    failed |= fill_rules(context);
    failed |= joins_and_caps(context);
    failed |= gradients(context, r);
    failed |= maze(context);
    failed |= connectivity(context);
    cg_rasterizer_free(r);
    return failed;
}

const demo_section demo_section_fill = {10, "Filling", render};
