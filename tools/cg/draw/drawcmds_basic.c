/* `cg draw` commands of chapter 2: canvas, colours, lines, circles,
 * ellipses, arcs and curves (docs/draw-script.md). */
#include "draw_script.h"
#include "cg/curve.h"
#include "cg/draw.h"

#include <stdlib.h>
#include <string.h>

static int run_size(draw_state *s, int argc, char **argv)
{
    int w, h;
    if (draw_arg_count(s, argc, argv, 2, "size W H") || draw_arg_int(s, argv[1], "W", &w)
        || draw_arg_int(s, argv[2], "H", &h))
        return 1;
    if (s->canvas)
        return draw_error(s, "the canvas size is already set: 'size' may appear only once");
    if (w < 1 || h < 1 || w > CG_IMAGE_MAX_SIDE || h > CG_IMAGE_MAX_SIDE
        || (size_t)w * (size_t)h > CG_IMAGE_MAX_PIXELS)
        return draw_error(s,
                          "expected a canvas size from 1 x 1 to %d x %d with at most %zu pixels, "
                          "got %s x %s",
                          CG_IMAGE_MAX_SIDE, CG_IMAGE_MAX_SIDE, (size_t)CG_IMAGE_MAX_PIXELS,
                          argv[1], argv[2]);
    cg_status status = cg_image_create(&s->canvas, w, h, CG_PIXEL_RGBA8);
    if (status != CG_OK)
        return draw_error(s, "cannot create a %d x %d canvas: %s", w, h, cg_status_str(status));
    cg_image_clear_rgba8(s->canvas, s->background);
    return 0;
}

static int run_background(draw_state *s, int argc, char **argv)
{
    if (draw_arg_count(s, argc, argv, 1, "background COLOR")
        || draw_arg_color(s, argv[1], &s->background))
        return 1;
    if (s->canvas)
        cg_image_clear_rgba8(s->canvas, s->background);
    return 0;
}

static int run_color(draw_state *s, int argc, char **argv)
{
    return draw_arg_count(s, argc, argv, 1, "color COLOR") || draw_arg_color(s, argv[1], &s->color);
}

static int run_tolerance(draw_state *s, int argc, char **argv)
{
    double t;
    if (draw_arg_count(s, argc, argv, 1, "tolerance T") || draw_arg_double(s, argv[1], "T", &t))
        return 1;
    if (!(t > 0))
        return draw_error(s, "expected a tolerance T > 0 (in pixels), got '%s'", argv[1]);
    s->tolerance = t;
    return 0;
}

static int run_antialias(draw_state *s, int argc, char **argv)
{
    if (draw_arg_count(s, argc, argv, 1, "antialias on|off"))
        return 1;
    if (strcmp(argv[1], "on") == 0)
        s->antialias = 1;
    else if (strcmp(argv[1], "off") == 0)
        s->antialias = 0;
    else
        return draw_error(s, "expected 'on' or 'off' after antialias, got '%s'", argv[1]);
    return 0;
}

/* n integer arguments named by names[], for the exact algorithms. */
static int ints(draw_state *s, int argc, char **argv, const char *usage, int n,
                const char *const *names, int *out)
{
    if (draw_arg_count(s, argc, argv, n, usage))
        return 1;
    for (int i = 0; i < n; i++)
        if (draw_arg_int(s, argv[i + 1], names[i], &out[i]))
            return 1;
    return 0;
}

static int doubles(draw_state *s, int argc, char **argv, const char *usage, int n,
                   const char *const *names, double *out)
{
    if (draw_arg_count(s, argc, argv, n, usage))
        return 1;
    for (int i = 0; i < n; i++)
        if (draw_arg_double(s, argv[i + 1], names[i], &out[i]))
            return 1;
    return 0;
}

static const char *const line_names[] = {"X0", "Y0", "X1", "Y1"};
static const char *const circle_names[] = {"CX", "CY", "R", "START_DEG", "END_DEG"};
static const char *const ellipse_names[] = {"CX", "CY", "RX", "RY", "START_DEG", "END_DEG"};

static int run_line(draw_state *s, int argc, char **argv)
{
    int v[4];
    cg_image *canvas;
    if (ints(s, argc, argv, "line X0 Y0 X1 Y1", 4, line_names, v) || !(canvas = draw_canvas(s)))
        return 1;
    return draw_check(s, cg_draw_line(canvas, v[0], v[1], v[2], v[3], s->color));
}

static int run_aaline(draw_state *s, int argc, char **argv)
{
    double v[4];
    cg_image *canvas;
    if (doubles(s, argc, argv, "aaline X0 Y0 X1 Y1", 4, line_names, v)
        || !(canvas = draw_canvas(s)))
        return 1;
    return draw_check(s, cg_draw_line_aa(canvas, v[0], v[1], v[2], v[3], s->color));
}

static int run_polyline(draw_state *s, int argc, char **argv)
{
    cg_image *canvas;
    int n = argc - 1;
    if (n < 2 || n % 2)
        return draw_error(s,
                          "'polyline' expects one or more X Y pairs of integers, got %d number%s",
                          n, n == 1 ? "" : "s");
    if (!(canvas = draw_canvas(s)))
        return 1;
    int *xy = malloc((size_t)n * sizeof *xy);
    if (!xy)
        return draw_error(s, "out of memory");
    for (int i = 0; i < n; i++)
        if (draw_arg_int(s, argv[i + 1], i % 2 ? "Y" : "X", &xy[i])) {
            free(xy);
            return 1;
        }
    int status = draw_check(s, cg_draw_polyline(canvas, xy, n / 2, s->color));
    free(xy);
    return status;
}

static int radius_ok(draw_state *s, int r, const char *what)
{
    if (r < 0)
        return draw_error(s, "expected a radius %s >= 0, got %d", what, r);
    return 0;
}

static int run_circle(draw_state *s, int argc, char **argv)
{
    int v[3];
    cg_image *canvas;
    if (ints(s, argc, argv, "circle CX CY R", 3, circle_names, v) || radius_ok(s, v[2], "R")
        || !(canvas = draw_canvas(s)))
        return 1;
    return draw_check(s, cg_draw_circle(canvas, v[0], v[1], v[2], s->color));
}

static int run_disc(draw_state *s, int argc, char **argv)
{
    int v[3];
    cg_image *canvas;
    if (ints(s, argc, argv, "disc CX CY R", 3, circle_names, v) || radius_ok(s, v[2], "R")
        || !(canvas = draw_canvas(s)))
        return 1;
    return draw_check(s, cg_draw_disc(canvas, v[0], v[1], v[2], s->color));
}

static int run_aacircle(draw_state *s, int argc, char **argv)
{
    double v[3];
    cg_image *canvas;
    if (doubles(s, argc, argv, "aacircle CX CY R", 3, circle_names, v))
        return 1;
    if (v[2] < 0)
        return draw_error(s, "expected a radius R >= 0, got %s", argv[3]);
    if (!(canvas = draw_canvas(s)))
        return 1;
    cg_status status = cg_draw_circle_aa(canvas, v[0], v[1], v[2], s->color);
    if (status == CG_ERANGE)
        return draw_error(s, "R = %s is out of range: anti-aliased circles take radii up to 1e9",
                          argv[3]);
    return draw_check(s, status);
}

static int run_ellipse(draw_state *s, int argc, char **argv)
{
    int v[4];
    cg_image *canvas;
    if (ints(s, argc, argv, "ellipse CX CY RX RY", 4, ellipse_names, v) || radius_ok(s, v[2], "RX")
        || radius_ok(s, v[3], "RY") || !(canvas = draw_canvas(s)))
        return 1;
    cg_status status = cg_draw_ellipse(canvas, v[0], v[1], v[2], v[3], s->color);
    if (status == CG_ERANGE)
        return draw_error(s,
                          "radii %d and %d are out of range: ellipses take radii up to 2^30 = "
                          "1073741824",
                          v[2], v[3]);
    return draw_check(s, status);
}

static int run_aaellipse(draw_state *s, int argc, char **argv)
{
    double v[4];
    cg_image *canvas;
    if (doubles(s, argc, argv, "aaellipse CX CY RX RY", 4, ellipse_names, v))
        return 1;
    if (v[2] < 0 || v[3] < 0)
        return draw_error(s, "expected radii RX, RY >= 0, got %s and %s", argv[3], argv[4]);
    if (!(canvas = draw_canvas(s)))
        return 1;
    cg_status status = cg_draw_ellipse_aa(canvas, v[0], v[1], v[2], v[3], s->color);
    if (status == CG_ERANGE)
        return draw_error(s,
                          "radii %s and %s are out of range: anti-aliased ellipses take radii "
                          "up to 1e9",
                          argv[3], argv[4]);
    return draw_check(s, status);
}

static int run_arc(draw_state *s, int argc, char **argv)
{
    int v[3];
    double a[2];
    cg_image *canvas;
    if (draw_arg_count(s, argc, argv, 5, "arc CX CY R START_DEG END_DEG"))
        return 1;
    for (int i = 0; i < 3; i++)
        if (draw_arg_int(s, argv[i + 1], circle_names[i], &v[i]))
            return 1;
    if (draw_arg_double(s, argv[4], "START_DEG", &a[0])
        || draw_arg_double(s, argv[5], "END_DEG", &a[1]) || radius_ok(s, v[2], "R")
        || !(canvas = draw_canvas(s)))
        return 1;
    return draw_check(s, cg_draw_arc(canvas, v[0], v[1], v[2], a[0], a[1], s->color));
}

static int run_ellipsearc(draw_state *s, int argc, char **argv)
{
    int v[4];
    double a[2];
    cg_image *canvas;
    if (draw_arg_count(s, argc, argv, 6, "ellipsearc CX CY RX RY START_DEG END_DEG"))
        return 1;
    for (int i = 0; i < 4; i++)
        if (draw_arg_int(s, argv[i + 1], ellipse_names[i], &v[i]))
            return 1;
    if (draw_arg_double(s, argv[5], "START_DEG", &a[0])
        || draw_arg_double(s, argv[6], "END_DEG", &a[1]) || radius_ok(s, v[2], "RX")
        || radius_ok(s, v[3], "RY") || !(canvas = draw_canvas(s)))
        return 1;
    return draw_check(s, cg_draw_ellipse_arc(canvas, v[0], v[1], v[2], v[3], a[0], a[1], s->color));
}

/* Curves: a drawing status CG_EEMPTY means every control point coincides. */
static int curve_status(draw_state *s, cg_status status)
{
    if (status == CG_EEMPTY)
        return draw_error(s, "zero-length curve: every control point is the same point");
    if (status == CG_ERANGE)
        return draw_error(s,
                          "curve out of range: coordinates beyond 1e9 in magnitude (with "
                          "antialias off), or tolerance %g too small for its size",
                          s->tolerance);
    return draw_check(s, status);
}

static cg_draw_mode mode(const draw_state *s)
{
    return s->antialias ? CG_DRAW_ANTIALIASED : CG_DRAW_ALIASED;
}

static int run_bezier(draw_state *s, int argc, char **argv)
{
    cg_vec2 *p;
    int n;
    cg_image *canvas;
    if (draw_arg_points(s, argc, argv, 1, 2, "bezier X0 Y0 X1 Y1 ... Xn Yn", &p, &n))
        return 1;
    if (n > CG_BEZIER_MAX_POINTS) {
        free(p);
        return draw_error(s, "a Bezier curve may have at most %d control points, got %d",
                          CG_BEZIER_MAX_POINTS, n);
    }
    int status = 1;
    if ((canvas = draw_canvas(s)))
        status = curve_status(s, cg_draw_bezier(canvas, p, n, s->tolerance, mode(s), s->color));
    free(p);
    return status;
}

static int run_hermite(draw_state *s, int argc, char **argv)
{
    static const char *const names[] = {"P1X", "P1Y", "P4X", "P4Y", "R1X", "R1Y", "R4X", "R4Y"};
    double v[8];
    cg_image *canvas;
    if (doubles(s, argc, argv, "hermite P1X P1Y P4X P4Y R1X R1Y R4X R4Y", 8, names, v)
        || !(canvas = draw_canvas(s)))
        return 1;
    return curve_status(s,
                        cg_draw_hermite(canvas, cg_vec2_make(v[0], v[1]), cg_vec2_make(v[2], v[3]),
                                        cg_vec2_make(v[4], v[5]), cg_vec2_make(v[6], v[7]),
                                        s->tolerance, mode(s), s->color));
}

static int run_spline(draw_state *s, int argc, char **argv, int catmull_rom)
{
    cg_vec2 *p;
    int n;
    cg_image *canvas;
    if (draw_arg_points(s, argc, argv, 1, 4,
                        catmull_rom ? "catmullrom X0 Y0 X1 Y1 X2 Y2 X3 Y3 ..."
                                    : "bspline X0 Y0 X1 Y1 X2 Y2 X3 Y3 ...",
                        &p, &n))
        return 1;
    int status = 1;
    if ((canvas = draw_canvas(s)))
        status = curve_status(s, (catmull_rom ? cg_draw_catmull_rom : cg_draw_bspline)(
                                     canvas, p, n, s->tolerance, mode(s), s->color));
    free(p);
    return status;
}

static int run_bspline(draw_state *s, int argc, char **argv)
{
    return run_spline(s, argc, argv, 0);
}

static int run_catmullrom(draw_state *s, int argc, char **argv)
{
    return run_spline(s, argc, argv, 1);
}

static const draw_command commands[] = {
    {"size", "size W H", run_size},
    {"background", "background COLOR", run_background},
    {"color", "color COLOR", run_color},
    {"tolerance", "tolerance T", run_tolerance},
    {"antialias", "antialias on|off", run_antialias},
    {"line", "line X0 Y0 X1 Y1", run_line},
    {"aaline", "aaline X0 Y0 X1 Y1", run_aaline},
    {"polyline", "polyline X0 Y0 X1 Y1 ...", run_polyline},
    {"circle", "circle CX CY R", run_circle},
    {"disc", "disc CX CY R", run_disc},
    {"aacircle", "aacircle CX CY R", run_aacircle},
    {"ellipse", "ellipse CX CY RX RY", run_ellipse},
    {"aaellipse", "aaellipse CX CY RX RY", run_aaellipse},
    {"arc", "arc CX CY R START_DEG END_DEG", run_arc},
    {"ellipsearc", "ellipsearc CX CY RX RY START_DEG END_DEG", run_ellipsearc},
    {"bezier", "bezier X0 Y0 X1 Y1 ... Xn Yn", run_bezier},
    {"hermite", "hermite P1X P1Y P4X P4Y R1X R1Y R4X R4Y", run_hermite},
    {"bspline", "bspline X0 Y0 X1 Y1 X2 Y2 X3 Y3 ...", run_bspline},
    {"catmullrom", "catmullrom X0 Y0 X1 Y1 X2 Y2 X3 Y3 ...", run_catmullrom},
};

const draw_command_table draw_commands_basic = {"basic", commands,
                                                (int)(sizeof commands / sizeof commands[0])};
