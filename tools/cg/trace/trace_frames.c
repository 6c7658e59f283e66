/* A recorded trace as pictures: one PNG per step (the picture so far, with
 * the step's pixels and geometry highlighted), and one HTML page that holds
 * every frame inline and steps through them with buttons and the keys.
 *
 * The frame maps the trace's bounding box onto at most FRAME_SIDE pixels,
 * each pixel of the traced picture a square cell:
 *
 *     (min.x, min.y) +---+---+---+   cell (x, y) of an image trace covers
 *                    |   |   |   |   [x, x+1) x [y, y+1) of the image plane,
 *                    +---+---+---+   drawn scale x scale frame pixels wide;
 *                    |   |###|   |   y-up traces (clipping) are turned so
 *                    +---+---+---+   that y grows upwards on the page.
 */
#include "trace_output.h"

#include "cli.h"
#include "cg/color.h"
#include "cg/draw.h"
#include "cg/fill.h"
#include "cg/image.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { FRAME_SIDE = 640, MAX_CELL = 40 };

typedef struct frame_view {
    double min_x, min_y, max_x, max_y, scale;
    int width, height, y_up;
} frame_view;

static void grow(frame_view *v, double x, double y)
{
    if (!isfinite(x) || !isfinite(y))
        return;
    v->min_x = fmin(v->min_x, x);
    v->min_y = fmin(v->min_y, y);
    v->max_x = fmax(v->max_x, x);
    v->max_y = fmax(v->max_y, y);
}

static void grow_points(frame_view *v, const cg_vec2 *p, int n)
{
    for (int i = 0; i < n; i++)
        grow(v, p[i].x, p[i].y);
}

static frame_view make_view(const trace_run *run)
{
    frame_view v = {INFINITY, INFINITY, -INFINITY, -INFINITY, 1, 1, 1, run->y_up};
    for (int i = 0; i < run->scene_count; i++)
        grow_points(&v, run->scene[i].points, run->scene[i].count);
    if (run->background) {
        grow(&v, 0, 0);
        grow(&v, run->background->width, run->background->height);
    }
    int pixels = run->background != NULL;
    for (size_t i = 0; i < cg_step_log_count(run->log); i++) {
        const cg_step *s = cg_step_log_get(run->log, i);
        pixels |= s->pixel_count > 0;
        for (int k = 0; k < s->pixel_count; k++) {
            grow(&v, s->pixels[2 * k], s->pixels[2 * k + 1]);
            grow(&v, s->pixels[2 * k] + 1, s->pixels[2 * k + 1] + 1);
        }
        grow_points(&v, s->geometry, s->geometry_count);
        grow_points(&v, s->kept, s->kept_count);
    }
    if (!(v.min_x <= v.max_x)) { /* nothing to show */
        v.min_x = v.min_y = 0;
        v.max_x = v.max_y = 1;
    }
    if (pixels) {
        /* A margin of one cell, and whole cells for image traces. */
        v.min_x = floor(v.min_x) - 1;
        v.min_y = floor(v.min_y) - 1;
        v.max_x = ceil(v.max_x) + 1;
        v.max_y = ceil(v.max_y) + 1;
    } else {
        /* Geometry only: a margin of 5%, and the picture as large as allowed. */
        double margin = 0.05 * fmax(fmax(v.max_x - v.min_x, v.max_y - v.min_y), 1e-9);
        v.min_x -= margin;
        v.min_y -= margin;
        v.max_x += margin;
        v.max_y += margin;
    }
    double w = v.max_x - v.min_x, h = v.max_y - v.min_y;
    v.scale = fmin(FRAME_SIDE / w, FRAME_SIDE / h);
    if (pixels && v.scale > MAX_CELL)
        v.scale = MAX_CELL;
    if (v.scale >= 2)
        v.scale = floor(v.scale);
    double width = ceil(w * v.scale), height = ceil(h * v.scale);
    v.width = width >= 1 && width <= 4 * FRAME_SIDE ? (int)width : 0;
    v.height = height >= 1 && height <= 4 * FRAME_SIDE ? (int)height : 0;
    return v;
}

static cg_vec2 to_frame(const frame_view *v, cg_vec2 p)
{
    double y = v->y_up ? v->max_y - p.y : p.y - v->min_y;
    return cg_vec2_make((p.x - v->min_x) * v->scale, y * v->scale);
}

static void fill_cell(cg_image *image, const frame_view *v, int x, int y, cg_rgba8 color,
                      double intensity)
{
    cg_vec2 a = to_frame(v, cg_vec2_make(x, v->y_up ? y + 1 : y));
    int x0 = (int)floor(a.x), y0 = (int)floor(a.y), side = (int)ceil(v->scale);
    color.a = (uint8_t)lround(255 * fmin(1, fmax(0, intensity)));
    cg_rgbaf c = cg_rgba8_to_linear(color);
    for (int j = 0; j < side; j++)
        for (int i = 0; i < side; i++)
            if (cg_image_contains(image, x0 + i, y0 + j) && (side < 4 || (i > 0 && j > 0)))
                cg_image_blend(image, x0 + i, y0 + j, c);
}

/* A polyline stroked width pixels wide with round joins, and a dot on
 * each vertex when dots. */
static void draw_path(cg_image *image, const frame_view *v, const cg_vec2 *p, int n, int closed,
                      cg_rgba8 color, int dots)
{
    cg_path *path;
    if (n <= 0 || cg_path_create(&path) != CG_OK)
        return;
    for (int i = 0; i < n; i++) {
        cg_vec2 a = to_frame(v, p[i]);
        if (i == 0)
            cg_path_move_to(path, a.x, a.y);
        else
            cg_path_line_to(path, a.x, a.y);
    }
    if (closed && n > 2)
        cg_path_close(path);
    cg_stroke_style style = cg_stroke_style_default();
    style.width = 2;
    style.join = CG_JOIN_ROUND;
    style.cap = CG_CAP_ROUND;
    cg_paint paint = cg_paint_solid(color);
    if (n > 1)
        cg_stroke_path(image, path, &style, &paint);
    cg_path_free(path);
    for (int i = 0; dots && i < n; i++) {
        cg_vec2 a = to_frame(v, p[i]);
        cg_path *disc;
        if (cg_path_create(&disc) != CG_OK)
            return;
        cg_path_arc(disc, a.x, a.y, 3.5, 0, 6.283185307179586);
        cg_fill_path(image, disc, CG_FILL_NONZERO, &paint);
        cg_path_free(disc);
    }
}

static void draw_grid(cg_image *image, const frame_view *v)
{
    if (v->scale < 6)
        return;
    cg_rgba8 grid = {225, 225, 225, 255};
    for (double x = v->min_x; x <= v->max_x; x++) {
        cg_vec2 a = to_frame(v, cg_vec2_make(x, v->min_y));
        cg_draw_line(image, (int)a.x, 0, (int)a.x, v->height - 1, grid);
    }
    for (double y = v->min_y; y <= v->max_y; y++) {
        cg_vec2 a = to_frame(v, cg_vec2_make(v->min_x, y));
        cg_draw_line(image, 0, (int)a.y, v->width - 1, (int)a.y, grid);
    }
}

/* Frame `upto`: every pixel and kept path of the steps before it, then
 * that step's own pixels and geometry in the highlight colour. */
static void draw_frame(cg_image *image, const trace_run *run, const frame_view *v, size_t upto)
{
    const cg_rgba8 done = {40, 70, 160, 255}, kept = {60, 60, 60, 255};
    const cg_rgba8 now = {235, 110, 20, 255}, look = {200, 30, 60, 255};
    const cg_rgba8 scene = {40, 150, 70, 255};
    cg_image_clear_rgba8(image, (cg_rgba8){255, 255, 255, 255});
    const cg_image *back = run->background;
    for (int y = 0; back && y < back->height; y++) /* the input image, faded */
        for (int x = 0; x < back->width; x++)
            fill_cell(image, v, x, y, cg_image_get_rgba8(back, x, y), 0.4);
    draw_grid(image, v);
    size_t last_list = 0;
    for (size_t i = 0; i <= upto; i++)
        if (cg_step_log_get(run->log, i)->kept_closed)
            last_list = i;
    for (size_t i = 0; i <= upto; i++) {
        const cg_step *s = cg_step_log_get(run->log, i);
        for (int k = 0; k < s->pixel_count; k++)
            fill_cell(image, v, s->pixels[2 * k], s->pixels[2 * k + 1], i == upto ? now : done,
                      s->intensity ? s->intensity[k] : 1);
    }
    /* the fixed input over the pixels (the real line), under the results */
    for (int i = 0; i < run->scene_count; i++)
        draw_path(image, v, run->scene[i].points, run->scene[i].count, run->scene[i].closed, scene,
                  0);
    for (size_t i = 0; i <= upto; i++) {
        const cg_step *s = cg_step_log_get(run->log, i);
        /* a list of results (Sutherland-Hodgman's) replaces the one before it */
        if (s->kept_closed && i < last_list)
            continue;
        draw_path(image, v, s->kept, s->kept_count, s->kept_closed, i == upto ? now : kept,
                  s->kept_count == 1);
    }
    const cg_step *s = cg_step_log_get(run->log, upto);
    draw_path(image, v, s->geometry, s->geometry_count, s->closed, look, 1);
}

static int make_directory(const char *dir)
{
    if (mkdir(dir, 0777) == 0 || errno == EEXIST) {
        struct stat st;
        if (stat(dir, &st) == 0 && S_ISDIR(st.st_mode))
            return CLI_OK;
    }
    return cli_fail("trace: cannot create the folder %s: %s", dir,
                    errno ? strerror(errno) : "not a folder");
}

static void frame_path(char *out, size_t size, const char *dir, size_t i)
{
    snprintf(out, size, "%s/step_%04zu.png", dir, i);
}

int trace_write_frames(const trace_run *run, const char *dir, int *frame_count)
{
    size_t count = cg_step_log_count(run->log);
    if (count > TRACE_MAX_FRAMES)
        return cli_fail("trace: %zu steps: pictures are drawn for at most %d; trace a smaller "
                        "input",
                        count, TRACE_MAX_FRAMES);
    if (make_directory(dir) != CLI_OK)
        return CLI_FAILED;
    frame_view v = make_view(run);
    if (!(v.scale > 0) || !isfinite(v.scale) || v.width < 1 || v.height < 1
        || v.width > 4 * FRAME_SIDE || v.height > 4 * FRAME_SIDE)
        return cli_fail("trace: the trace's coordinates span too much to be drawn");
    cg_image *image;
    if (cg_image_create(&image, v.width, v.height, CG_PIXEL_RGBA8) != CG_OK)
        return cli_fail("trace: out of memory");
    char path[4096];
    for (size_t i = 0; i < count; i++) {
        draw_frame(image, run, &v, i);
        frame_path(path, sizeof path, dir, i);
        if (cli_write_image(image, path) != CLI_OK) {
            cg_image_free(image);
            return CLI_FAILED;
        }
    }
    cg_image_free(image);
    *frame_count = (int)count;
    return CLI_OK;
}
