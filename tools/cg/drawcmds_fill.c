/* `cg draw` commands of chapter 10: polygons (aliased and anti-aliased, with
 * contours), SVG paths filled or stroked, stroke style, flood and boundary
 * fill (docs/draw-script.md, "Filling"). */
#include "draw_script.h"
#include "cg/fill.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What the fill commands keep between lines. */
typedef struct draw_fill {
    cg_rasterizer *rasterizer;
    cg_path *path;       /* the current path (`path`), for fill and stroke */
    /* the polygon of the last polygon/aapolygon line and its contours */
    cg_vec2 *points;
    int *sizes;
    int point_count, contour_count, point_capacity, contour_capacity;
    int antialias, rule, last_command;
    cg_rgba8 color;
    /* canvas rows saved before the polygon was drawn, restored to redraw it
     * with a new contour */
    unsigned char *saved;
    size_t saved_capacity;
    int saved_top, saved_bottom;
} draw_fill;

void draw_fill_release(draw_state *state)
{
    draw_fill *f = state->fill;
    if (!f)
        return;
    cg_rasterizer_free(f->rasterizer);
    cg_path_free(f->path);
    free(f->points);
    free(f->sizes);
    free(f->saved);
    free(f);
    state->fill = NULL;
}

static draw_fill *fill_of(draw_state *s)
{
    if (!s->fill) {
        s->fill = calloc(1, sizeof *s->fill);
        if (!s->fill)
            return NULL;
        if (cg_rasterizer_create(&s->fill->rasterizer) != CG_OK
            || cg_path_create(&s->fill->path) != CG_OK) {
            draw_fill_release(s);
            return NULL;
        }
        s->fill->last_command = -2;
    }
    double t = s->tolerance < 0.001 ? 0.001 : (s->tolerance > 100 ? 100 : s->tolerance);
    cg_rasterizer_set_tolerance(s->fill->rasterizer, t);
    return s->fill;
}

static int out_of_memory(const draw_state *s)
{
    return draw_error(s, "out of memory");
}

/* ---- attributes ------------------------------------------------------------ */

static int keyword(draw_state *s, int argc, char **argv, const char *usage,
                   const char *const *words, int count, int *out)
{
    if (draw_arg_count(s, argc, argv, 1, usage))
        return 1;
    for (int i = 0; i < count; i++)
        if (strcmp(argv[1], words[i]) == 0) {
            *out = i;
            return 0;
        }
    return draw_error(s, "expected %s after '%s', got '%s'", usage + strlen(argv[0]) + 1, argv[0],
                      argv[1]);
}

static int run_fillrule(draw_state *s, int argc, char **argv)
{
    static const char *const words[] = {"evenodd", "nonzero"}; /* = cg_fill_rule */
    return keyword(s, argc, argv, "fillrule evenodd|nonzero", words, 2, &s->fill_rule);
}

static int run_join(draw_state *s, int argc, char **argv)
{
    static const char *const words[] = {"miter", "round", "bevel"}; /* = cg_line_join */
    return keyword(s, argc, argv, "join miter|round|bevel", words, 3, &s->line_join);
}

static int run_cap(draw_state *s, int argc, char **argv)
{
    static const char *const words[] = {"butt", "round", "square"}; /* = cg_line_cap */
    return keyword(s, argc, argv, "cap butt|round|square", words, 3, &s->line_cap);
}

static int run_width(draw_state *s, int argc, char **argv)
{
    double w;
    if (draw_arg_count(s, argc, argv, 1, "width W") || draw_arg_double(s, argv[1], "W", &w))
        return 1;
    if (!(w > 0) || w > CG_FILL_MAX_COORD)
        return draw_error(s, "expected a stroke width W > 0 and at most 2^40 = 1099511627776, "
                          "got '%s'", argv[1]);
    s->line_width = w;
    return 0;
}

static int run_dash(draw_state *s, int argc, char **argv)
{
    int n = argc - 1;
    if (n > 32)
        return draw_error(s, "expected at most 32 dash lengths (dash ON OFF ...), got %d", n);
    double lengths[32];
    for (int i = 0; i < n; i++) {
        char what[16];
        snprintf(what, sizeof what, "%s", i % 2 ? "OFF" : "ON");
        if (draw_arg_nonnegative(s, argv[i + 1], what, &lengths[i]))
            return 1;
    }
    memcpy(s->dashes, lengths, (size_t)n * sizeof *lengths);
    s->dash_count = n;
    return 0;
}

static cg_stroke_style stroke_style(const draw_state *s)
{
    cg_stroke_style style = cg_stroke_style_default();
    style.width = s->line_width;
    style.join = (cg_line_join)s->line_join;
    style.cap = (cg_line_cap)s->line_cap;
    style.dashes = s->dash_count ? s->dashes : NULL;
    style.dash_count = s->dash_count;
    return style;
}

/* ---- polygons ----------------------------------------------------------------- */

/* Saves canvas rows top..bottom-1 (growing the saved range, whose rows are
 * still as they were before the polygon). */
static int save_rows(draw_fill *f, const cg_image *canvas, int top, int bottom)
{
    if (f->saved_bottom > f->saved_top) {
        if (top > f->saved_top)
            top = f->saved_top;
        if (bottom < f->saved_bottom)
            bottom = f->saved_bottom;
    }
    size_t row = canvas->stride, need = (size_t)(bottom - top) * row;
    if (need > f->saved_capacity) {
        unsigned char *grown = malloc(need);
        if (!grown)
            return 1;
        if (f->saved_bottom > f->saved_top)
            memcpy(grown + (size_t)(f->saved_top - top) * row, f->saved,
                   (size_t)(f->saved_bottom - f->saved_top) * row);
        free(f->saved);
        f->saved = grown;
        f->saved_capacity = need;
    } else if (f->saved_bottom > f->saved_top && f->saved_top != top) {
        memmove(f->saved + (size_t)(f->saved_top - top) * row, f->saved,
                (size_t)(f->saved_bottom - f->saved_top) * row);
    }
    for (int y = top; y < bottom; y++)
        if (!(f->saved_bottom > f->saved_top && y >= f->saved_top && y < f->saved_bottom))
            memcpy(f->saved + (size_t)(y - top) * row, canvas->data + (size_t)y * row, row);
    f->saved_top = top;
    f->saved_bottom = bottom;
    return 0;
}

static void restore_rows(const draw_fill *f, cg_image *canvas)
{
    size_t row = canvas->stride;
    if (f->saved_bottom > f->saved_top)
        memcpy(canvas->data + (size_t)f->saved_top * row, f->saved,
               (size_t)(f->saved_bottom - f->saved_top) * row);
}

/* Rows the points can touch, clamped to the canvas. */
static void row_span(const cg_vec2 *p, int n, int height, int *top, int *bottom)
{
    double lo = p[0].y, hi = p[0].y;
    for (int i = 1; i < n; i++) {
        if (p[i].y < lo)
            lo = p[i].y;
        if (p[i].y > hi)
            hi = p[i].y;
    }
    lo = floor(lo) - 1;
    hi = ceil(hi) + 1;
    *top = lo < 0 ? 0 : (lo > height ? height : (int)lo);
    *bottom = hi < 0 ? 0 : (hi > height ? height : (int)hi);
}

static int draw_polygon(draw_state *s, draw_fill *f, cg_image *canvas)
{
    cg_status status;
    if (f->antialias) {
        cg_paint paint = cg_paint_solid(f->color);
        status = cg_rasterizer_fill_polygon_aa(f->rasterizer, canvas, f->points, f->sizes,
                                               f->contour_count, (cg_fill_rule)f->rule, &paint);
    } else {
        status = cg_rasterizer_fill_polygon(f->rasterizer, canvas, f->points, f->sizes,
                                            f->contour_count, (cg_fill_rule)f->rule, f->color);
    }
    return draw_check(s, status);
}

/* Appends the X Y pairs of argv[1..] as a contour; 0 or an error printed. */
static int add_contour(draw_state *s, draw_fill *f, int argc, char **argv, const char *usage)
{
    int numbers = argc - 1;
    if (numbers < 6 || numbers % 2)
        return draw_error(s, "'%s' expects three or more X Y pairs (%s), got %d number%s",
                          argv[0], usage, numbers, numbers == 1 ? "" : "s");
    cg_vec2 *points;
    int n;
    if (draw_arg_points(s, argc, argv, 1, 3, usage, &points, &n))
        return 1;
    for (int i = 0; i < 2 * n; i++) {
        if (!(fabs(i % 2 ? points[i / 2].y : points[i / 2].x) <= CG_FILL_MAX_COORD)) {
            free(points);
            return draw_error(s, "%c%d = %s is out of range: coordinates are at most 2^40 = "
                              "1099511627776 in magnitude", i % 2 ? 'Y' : 'X', i / 2, argv[1 + i]);
        }
    }
    if (f->point_count + n > f->point_capacity) {
        int capacity = 2 * (f->point_count + n);
        cg_vec2 *grown = realloc(f->points, (size_t)capacity * sizeof *grown);
        if (!grown) {
            free(points);
            return out_of_memory(s);
        }
        f->points = grown;
        f->point_capacity = capacity;
    }
    if (f->contour_count + 1 > f->contour_capacity) {
        int capacity = 2 * (f->contour_count + 1);
        int *grown = realloc(f->sizes, (size_t)capacity * sizeof *grown);
        if (!grown) {
            free(points);
            return out_of_memory(s);
        }
        f->sizes = grown;
        f->contour_capacity = capacity;
    }
    memcpy(f->points + f->point_count, points, (size_t)n * sizeof *points);
    free(points);
    f->point_count += n;
    f->sizes[f->contour_count++] = n;
    return 0;
}

static int start_polygon(draw_state *s, int argc, char **argv, int antialias, const char *usage)
{
    cg_image *canvas = draw_canvas(s);
    draw_fill *f = canvas ? fill_of(s) : NULL;
    if (!canvas)
        return 1;
    if (!f)
        return out_of_memory(s);
    f->point_count = f->contour_count = 0;
    if (add_contour(s, f, argc, argv, usage))
        return 1;
    f->antialias = antialias;
    f->rule = s->fill_rule;
    f->color = s->color;
    f->last_command = s->command;
    f->saved_top = f->saved_bottom = 0;
    int top, bottom;
    row_span(f->points, f->point_count, canvas->height, &top, &bottom);
    if (save_rows(f, canvas, top, bottom))
        return out_of_memory(s);
    return draw_polygon(s, f, canvas);
}

static int run_polygon(draw_state *s, int argc, char **argv)
{
    return start_polygon(s, argc, argv, 0, "polygon X0 Y0 X1 Y1 X2 Y2 ...");
}

static int run_aapolygon(draw_state *s, int argc, char **argv)
{
    return start_polygon(s, argc, argv, 1, "aapolygon X0 Y0 X1 Y1 X2 Y2 ...");
}

/* A further contour of the polygon on the line before: the canvas rows it
 * touched are restored and the polygon drawn again with every contour. */
static int run_contour(draw_state *s, int argc, char **argv)
{
    cg_image *canvas = draw_canvas(s);
    if (!canvas)
        return 1;
    draw_fill *f = s->fill;
    if (!f || f->last_command != s->command - 1)
        return draw_error(s, "'contour' must follow a polygon, aapolygon or contour line");
    int first = f->point_count;
    if (add_contour(s, f, argc, argv, "contour X0 Y0 X1 Y1 X2 Y2 ..."))
        return 1;
    f->last_command = s->command;
    int top, bottom;
    row_span(f->points + first, f->point_count - first, canvas->height, &top, &bottom);
    if (save_rows(f, canvas, top, bottom))
        return out_of_memory(s);
    restore_rows(f, canvas);
    return draw_polygon(s, f, canvas);
}

/* ---- paths --------------------------------------------------------------------- */

static int run_path(draw_state *s, int argc, char **argv)
{
    if (argc < 2)
        return draw_error(s, "'path' expects SVG path data (path M X Y L X Y ... Z)");
    draw_fill *f = fill_of(s);
    if (!f)
        return out_of_memory(s);
    /* the words of the line, joined by spaces, are the path data */
    size_t length = 0;
    for (int i = 1; i < argc; i++)
        length += strlen(argv[i]) + 1;
    char *data = malloc(length);
    if (!data)
        return out_of_memory(s);
    data[0] = 0;
    for (int i = 1; i < argc; i++) {
        strcat(data, argv[i]);
        if (i + 1 < argc)
            strcat(data, " ");
    }
    cg_path_reset(f->path);
    cg_error err;
    cg_status status = cg_path_append_svg(f->path, data, &err);
    free(data);
    if (status != CG_OK)
        return draw_error(s, "%s", err.message);
    return 0;
}

static int current_path(draw_state *s, const char *command, cg_image **canvas, draw_fill **f)
{
    *canvas = draw_canvas(s);
    if (!*canvas)
        return 1;
    *f = s->fill;
    if (!*f || cg_path_is_empty((*f)->path))
        return draw_error(s, "'%s' needs a path: expected a 'path SVG_PATH_DATA' line before it",
                          command);
    return 0;
}

static int run_fill(draw_state *s, int argc, char **argv)
{
    cg_image *canvas;
    draw_fill *f;
    if (draw_arg_count(s, argc, argv, 0, "fill") || current_path(s, "fill", &canvas, &f))
        return 1;
    fill_of(s);
    cg_paint paint = cg_paint_solid(s->color);
    return draw_check(s, cg_rasterizer_fill_path(f->rasterizer, canvas, f->path,
                                                 (cg_fill_rule)s->fill_rule, &paint));
}

static int run_stroke(draw_state *s, int argc, char **argv)
{
    cg_image *canvas;
    draw_fill *f;
    if (draw_arg_count(s, argc, argv, 0, "stroke") || current_path(s, "stroke", &canvas, &f))
        return 1;
    fill_of(s);
    cg_paint paint = cg_paint_solid(s->color);
    cg_stroke_style style = stroke_style(s);
    cg_status status = cg_rasterizer_stroke_path(f->rasterizer, canvas, f->path, &style, &paint);
    if (status == CG_ERANGE)
        return draw_error(s, "the dash pattern is too fine for this path (over 400,000 dashes)");
    return draw_check(s, status);
}

/* ---- flood fill ------------------------------------------------------------------- */

static int seed(draw_state *s, int argc, char **argv, int n, const char *usage, cg_image **canvas,
                int *x, int *y)
{
    if (draw_arg_count(s, argc, argv, n, usage) || draw_arg_int(s, argv[1], "X", x)
        || draw_arg_int(s, argv[2], "Y", y))
        return 1;
    *canvas = draw_canvas(s);
    if (!*canvas)
        return 1;
    if (!cg_image_contains(*canvas, *x, *y))
        return draw_error(s, "the seed (%d, %d) is outside the %d x %d canvas", *x, *y,
                          (*canvas)->width, (*canvas)->height);
    return 0;
}

static int run_flood(draw_state *s, int argc, char **argv)
{
    cg_image *canvas;
    int x, y;
    if (seed(s, argc, argv, 2, "flood X Y", &canvas, &x, &y))
        return 1;
    return draw_check(s, cg_flood_fill(canvas, x, y, s->color, CG_CONNECT_4, 0, NULL));
}

static int run_flood8(draw_state *s, int argc, char **argv)
{
    cg_image *canvas;
    int x, y;
    if (seed(s, argc, argv, 2, "flood8 X Y", &canvas, &x, &y))
        return 1;
    return draw_check(s, cg_flood_fill(canvas, x, y, s->color, CG_CONNECT_8, 0, NULL));
}

static int run_boundaryfill(draw_state *s, int argc, char **argv)
{
    cg_image *canvas;
    int x, y;
    cg_rgba8 boundary;
    if (seed(s, argc, argv, 3, "boundaryfill X Y BOUNDARY_COLOR", &canvas, &x, &y)
        || draw_arg_color(s, argv[3], &boundary))
        return 1;
    return draw_check(s, cg_boundary_fill(canvas, x, y, s->color, boundary, CG_CONNECT_4, 0, NULL));
}

static const draw_command commands[] = {
    {"fillrule", "fillrule evenodd|nonzero", run_fillrule},
    {"polygon", "polygon X0 Y0 X1 Y1 X2 Y2 ...", run_polygon},
    {"contour", "contour X0 Y0 X1 Y1 X2 Y2 ...", run_contour},
    {"aapolygon", "aapolygon X0 Y0 X1 Y1 X2 Y2 ...", run_aapolygon},
    {"path", "path SVG_PATH_DATA", run_path},
    {"fill", "fill", run_fill},
    {"stroke", "stroke", run_stroke},
    {"width", "width W", run_width},
    {"join", "join miter|round|bevel", run_join},
    {"cap", "cap butt|round|square", run_cap},
    {"dash", "dash ON OFF ...", run_dash},
    {"flood", "flood X Y", run_flood},
    {"flood8", "flood8 X Y", run_flood8},
    {"boundaryfill", "boundaryfill X Y BOUNDARY_COLOR", run_boundaryfill},
};

const draw_command_table draw_commands_fill = {"fill", commands,
                                               (int)(sizeof commands / sizeof commands[0])};
