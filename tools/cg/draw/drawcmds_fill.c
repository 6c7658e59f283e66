/* `cg draw` commands of chapter 10: polygons (aliased and anti-aliased, with
 * contours), SVG paths filled or stroked, stroke style, flood and boundary
 * fill (docs/draw-script.md, "Filling"). */
#include "draw_script_run.h"
#include "cg/fill.h"
#include "../../../src/core/array.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What the fill commands keep between lines. */
typedef struct draw_fill {
    cg_rasterizer *rasterizer;
    cg_path *path; /* the current path (`path`), for fill and stroke */
    /* the polygon being drawn: a polygon line's points, then each contour's */
    cg_vec2 *points;
    int *sizes;
    int point_count, contour_count;
    size_t point_capacity, contour_capacity;
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
    }
    double t = s->tolerance < 0.001 ? 0.001 : (s->tolerance > 100 ? 100 : s->tolerance);
    cg_rasterizer_set_tolerance(s->fill->rasterizer, t);
    return s->fill;
}

cg_rasterizer *draw_fill_rasterizer(draw_state *state)
{
    draw_fill *f = fill_of(state);
    return f ? f->rasterizer : NULL;
}

static int out_of_memory(const draw_state *s)
{
    return draw_error(s, "out of memory");
}

/* ---- attributes ------------------------------------------------------------ */

static int run_fillrule(draw_state *s, int argc, char **argv)
{
    static const char *const words[] = {"evenodd", "nonzero"}; /* = cg_fill_rule */
    return draw_arg_keyword(s, argc, argv, "fillrule evenodd|nonzero", words, 2, &s->fill_rule);
}

static int run_join(draw_state *s, int argc, char **argv)
{
    static const char *const words[] = {"miter", "round", "bevel"}; /* = cg_line_join */
    return draw_arg_keyword(s, argc, argv, "join miter|round|bevel", words, 3, &s->line_join);
}

static int run_cap(draw_state *s, int argc, char **argv)
{
    static const char *const words[] = {"butt", "round", "square"}; /* = cg_line_cap */
    return draw_arg_keyword(s, argc, argv, "cap butt|round|square", words, 3, &s->line_cap);
}

/* compositing SPACE [OPERATOR [BLEND_MODE]]: how later fills mix colours. */
static int run_compositing(draw_state *s, int argc, char **argv)
{
    static const char *const usage = "compositing linear|srgb [OPERATOR [BLEND_MODE]]";
    if (argc < 2 || argc > 4)
        return draw_error(s, "expected %s", usage);
    static const char *const spaces[] = {"linear", "srgb"}; /* = cg_compositing_space */
    int space = -1;
    for (int i = 0; i < 2; i++)
        if (strcmp(argv[1], spaces[i]) == 0)
            space = i;
    if (space < 0)
        return draw_error(s, "expected linear or srgb after 'compositing', got '%s'", argv[1]);
    cg_composite_operator op = CG_OPERATOR_OVER;
    cg_blend_mode mode = CG_BLEND_NORMAL;
    if (argc > 2 && cg_composite_operator_parse(argv[2], &op) != CG_OK)
        return draw_error(s,
                          "expected an operator (over, source, in, out, atop, xor, plus, "
                          "clear, destination-over, ...) after '%s', got '%s'",
                          argv[1], argv[2]);
    if (argc > 3 && cg_blend_mode_parse(argv[3], &mode) != CG_OK)
        return draw_error(s,
                          "expected a blend mode (normal, multiply, screen, overlay, ..., "
                          "luminosity) after '%s', got '%s'",
                          argv[2], argv[3]);
    draw_fill *f = fill_of(s);
    if (!f)
        return out_of_memory(s);
    return draw_check(
        s, cg_rasterizer_set_compositing(f->rasterizer, (cg_compositing_space)space, op, mode));
}

static int run_width(draw_state *s, int argc, char **argv)
{
    double w;
    if (draw_arg_count(s, argc, argv, 1, "width W") || draw_arg_double(s, argv[1], "W", &w))
        return 1;
    if (!(w > 0) || w > CG_FILL_MAX_COORD)
        return draw_error(s,
                          "expected a stroke width W > 0 and at most 2^40 = 1099511627776, "
                          "got '%s'",
                          argv[1]);
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

static int draw_polygon(draw_state *s, draw_fill *f, cg_image *canvas, int antialias)
{
    cg_status status;
    cg_fill_rule rule = (cg_fill_rule)s->fill_rule;
    if (antialias) {
        cg_paint paint = cg_paint_solid(s->color);
        status = cg_rasterizer_fill_polygon_aa(f->rasterizer, canvas, f->points, f->sizes,
                                               f->contour_count, rule, &paint);
    } else {
        status = cg_rasterizer_fill_polygon(f->rasterizer, canvas, f->points, f->sizes,
                                            f->contour_count, rule, s->color);
    }
    return draw_check(s, status);
}

/* Appends the X Y pairs of argv[1..] as a contour; 0 or an error printed.
 * A point the fill cannot take (beyond CG_FILL_MAX_COORD) is reported on its
 * own line, as the fill call would report it. */
static int add_contour(draw_state *s, draw_fill *f, int argc, char **argv, const char *usage)
{
    int numbers = argc - 1;
    if (numbers < 6 || numbers % 2)
        return draw_error(s, "'%s' expects three or more X Y pairs (%s), got %d number%s", argv[0],
                          usage, numbers, numbers == 1 ? "" : "s");
    int n = numbers / 2;
    if (core_array_reserve((void **)&f->points, &f->point_capacity,
                           (size_t)f->point_count + (size_t)n, sizeof *f->points)
            != CG_OK
        || core_array_reserve((void **)&f->sizes, &f->contour_capacity,
                              (size_t)f->contour_count + 1, sizeof *f->sizes)
               != CG_OK)
        return out_of_memory(s);
    cg_vec2 *points = f->points + f->point_count;
    if (draw_arg_point_pairs(s, argv + 1, n, points))
        return 1;
    for (int i = 0; i < 2 * n; i++) {
        if (!(fabs(i % 2 ? points[i / 2].y : points[i / 2].x) <= CG_FILL_MAX_COORD))
            return draw_error(s,
                              "%c%d = %s is out of range: coordinates are at most 2^40 = "
                              "1099511627776 in magnitude",
                              i % 2 ? 'Y' : 'X', i / 2, argv[1 + i]);
    }
    f->point_count += n;
    f->sizes[f->contour_count++] = n;
    return 0;
}

static int run_contour(draw_state *s, int argc, char **argv);

/* A polygon line and the contour lines right after it are one polygon, drawn
 * once with all its contours, in the colour and rule of the polygon line
 * (no command can come between them). */
static int run_any_polygon(draw_state *s, int argc, char **argv, int antialias, const char *usage)
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
    int contours = 0;
    while (contours < s->next_count && s->next_lines[contours].command->run == run_contour) {
        const draw_line *line = &s->next_lines[contours];
        s->line = line->number;
        if (add_contour(s, f, line->argc, line->argv, "contour X0 Y0 X1 Y1 X2 Y2 ..."))
            return 1;
        contours++;
    }
    s->consumed = contours;
    return draw_polygon(s, f, canvas, antialias);
}

static int run_polygon(draw_state *s, int argc, char **argv)
{
    return run_any_polygon(s, argc, argv, 0, "polygon X0 Y0 X1 Y1 X2 Y2 ...");
}

static int run_aapolygon(draw_state *s, int argc, char **argv)
{
    return run_any_polygon(s, argc, argv, 1, "aapolygon X0 Y0 X1 Y1 X2 Y2 ...");
}

/* The polygon lines take the contour lines that follow them, so a contour
 * line that runs on its own follows no polygon. */
static int run_contour(draw_state *s, int argc, char **argv)
{
    (void)argc;
    (void)argv;
    if (!draw_canvas(s))
        return 1;
    return draw_error(s, "'contour' must follow a polygon, aapolygon or contour line");
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
    {"compositing", "compositing linear|srgb [OPERATOR [BLEND_MODE]]", run_compositing},
    {"join", "join miter|round|bevel", run_join},
    {"cap", "cap butt|round|square", run_cap},
    {"dash", "dash ON OFF ...", run_dash},
    {"flood", "flood X Y", run_flood},
    {"flood8", "flood8 X Y", run_flood8},
    {"boundaryfill", "boundaryfill X Y BOUNDARY_COLOR", run_boundaryfill},
};

const draw_command_table draw_commands_fill = {"fill", commands,
                                               (int)(sizeof commands / sizeof commands[0])};
