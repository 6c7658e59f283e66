/* `cg trace` for chapter 2: lines (Bresenham, DDA), the midpoint circle and
 * ellipse, cubic curves (Hermite, Bézier, B-spline: T M G), de Casteljau
 * and adaptive flattening. */
#include "trace_algorithms.h"

#include "cli.h"
#include "cg/curve.h"

#include <stdio.h>
#include <string.h>

enum { MAX_LINE_STEPS = 100000, MAX_RADIUS = 100000, MAX_ELLIPSE_RADIUS = 20000 };

static long long field_integer(const trace_run *run, size_t step, const char *name)
{
    const cg_step_field *f = cg_step_find(cg_step_log_get(run->log, step), name);
    return f && f->kind == CG_STEP_INTEGER ? f->integer : 0;
}

static int parse_line(const char *name, int argc, char **argv, long v[4])
{
    static const char *const names[4] = {"X1", "Y1", "X2", "Y2"};
    if (argc != 5)
        return cli_usage_error("trace", "%s: expected '%s X1 Y1 X2 Y2'", name, name);
    for (int i = 0; i < 4; i++)
        if (trace_parse_int(names[i], argv[i + 1], -2147483647L - 1, 2147483647L, &v[i]))
            return CLI_USAGE;
    long long dx = (long long)v[2] - v[0], dy = (long long)v[3] - v[1];
    if (dx < 0)
        dx = -dx;
    if (dy < 0)
        dy = -dy;
    if ((dx > dy ? dx : dy) > MAX_LINE_STEPS)
        return cli_fail("trace: the line has more than %d steps; trace a shorter one",
                        MAX_LINE_STEPS);
    return CLI_OK;
}

/* The frame of the three line traces: X1 Y1 X2 Y2 parsed into v, the run
 * titled "TITLE from (X1, Y1) to (X2, Y2)" with the real line through the
 * pixel centres in its scene.  NULL with the exit status in *code. */
static trace_run *begin_line(const char *name, const char *title, int argc, char **argv, long v[4],
                             int *code)
{
    *code = parse_line(name, argc, argv, v);
    if (*code)
        return NULL;
    trace_run *run = trace_run_create(name, argc - 1, argv + 1, "%s from (%ld, %ld) to (%ld, %ld)",
                                      title, v[0], v[1], v[2], v[3]);
    if (!run) {
        *code = cli_fail("trace: out of memory");
        return NULL;
    }
    cg_vec2 real_line[2] = {{v[0] + 0.5, v[1] + 0.5}, {v[2] + 0.5, v[3] + 0.5}};
    trace_scene_add(run, real_line, 2, 0);
    return run;
}

static int run_line(int argc, char **argv, const trace_outputs *out)
{
    long v[4];
    int code;
    trace_run *run = begin_line("line", "Bresenham's line (Algorithm 1)", argc, argv, v, &code);
    if (!run)
        return code;
    cg_status status = cg_line_steps((int)v[0], (int)v[1], (int)v[2], (int)v[3], cg_step_log_record,
                                     run->log);
    if (status == CG_OK && cg_step_log_count(run->log) > 0) {
        const cg_step *octant = cg_step_log_get(run->log, 0);
        long long dx = field_integer(run, 0, "dx"), dy = field_integer(run, 0, "dy");
        trace_note(
            run,
            "octant %lld (1 to 8 counter-clockwise from +x with y as given: 1 is 0 <= dy < dx)",
            field_integer(run, 0, "octant"));
        if (strcmp(cg_step_find(octant, "swap")->text, "no") != 0)
            trace_note(run, "walked from (%ld, %ld), the end with the smaller major coordinate",
                       v[2], v[3]);
        if (strcmp(cg_step_find(octant, "exchange")->text, "no") != 0)
            trace_note(run, "steep line: x and y exchanged, so E steps y and NE steps both");
        if (strcmp(cg_step_find(octant, "mirror")->text, "no") != 0)
            trace_note(run, "the minor coordinate decreases: NE steps it by -1");
        trace_note(run, "first octant: dx = %lld, dy = %lld", dx, dy);
        trace_note(run, "f = 2dy - dx = %lld, dE = 2dy = %lld, dNE = 2(dy - dx) = %lld",
                   field_integer(run, 0, "f0"), field_integer(run, 0, "dE"),
                   field_integer(run, 0, "dNE"));
        trace_note(run, "f <= 0 selects E (f += dE), else NE (f += dNE); f_next is f after "
                        "the update");
        long pixels = trace_pixel_total(run);
        trace_summary(run, "%ld pixel%s", pixels, pixels == 1 ? "" : "s");
    }
    return trace_finish(run, status, "the line cannot be traced", out);
}

static int run_dda(int argc, char **argv, const trace_outputs *out)
{
    long v[4];
    int code;
    trace_run *run = begin_line("dda", "DDA line", argc, argv, v, &code);
    if (!run)
        return code;
    long long dx = (long long)v[2] - v[0], dy = (long long)v[3] - v[1];
    long long n = (dx < 0 ? -dx : dx) > (dy < 0 ? -dy : dy) ? (dx < 0 ? -dx : dx)
                                                            : (dy < 0 ? -dy : dy);
    trace_note(run, "steps n = max(|dx|, |dy|) = %lld; x += dx/n = %g, y += dy/n = %g", n,
               n ? (double)dx / (double)n : 0.0, n ? (double)dy / (double)n : 0.0);
    trace_note(run, "each pixel is (round(x), round(y)), halves rounded up");
    cg_status status = cg_line_dda_steps((int)v[0], (int)v[1], (int)v[2], (int)v[3],
                                         cg_step_log_record, run->log);
    long pixels = trace_pixel_total(run);
    trace_summary(run, "%ld pixel%s", pixels, pixels == 1 ? "" : "s");
    return trace_finish(run, status, "the line cannot be traced", out);
}

static int run_wu(int argc, char **argv, const trace_outputs *out)
{
    long v[4];
    int code;
    trace_run *run = begin_line("wu", "Wu's anti-aliased line", argc, argv, v, &code);
    if (!run)
        return code;
    trace_note(run, "one column per step along the major axis (rows for a steep line); minor is "
                    "the real line's other coordinate there");
    trace_note(run, "the two pixels around it share the intensity: I_lower = 1 - frac(minor), "
                    "I_upper = frac(minor)");
    cg_status status = cg_line_wu_steps((int)v[0], (int)v[1], (int)v[2], (int)v[3],
                                        cg_step_log_record, run->log);
    trace_summary(run, "%zu columns", cg_step_log_count(run->log));
    return trace_finish(run, status, "the line cannot be traced", out);
}

static int run_circle(int argc, char **argv, const trace_outputs *out)
{
    long r;
    if (argc != 2)
        return cli_usage_error("trace", "circle: expected 'circle R'");
    if (trace_parse_int("R", argv[1], 0, MAX_RADIUS, &r))
        return CLI_USAGE;
    trace_run *run = trace_run_create("circle", argc - 1, argv + 1,
                                      "Bresenham's circle (Algorithm 2), radius %ld: first octant "
                                      "0 <= x <= y from (0, %ld)",
                                      r, r);
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run, "f = 1 - r = %ld, dE = 3, dSE = -2r + 5 = %ld", 1 - r, 5 - 2 * r);
    trace_note(run, "f < 0 selects E (x + 1, y): f += dE, dE += 2, dSE += 2");
    trace_note(run, "else SE (x + 1, y - 1): f += dSE, dE += 2, dSE += 4");
    trace_note(run, "f, dE, dSE: values tested; f_next, dE_next, dSE_next: after the update");
    trace_note(run, "the circle is centred on (0, 0); each step sets its pixel's 8 mirrors");
    cg_status status = cg_circle_steps(0, 0, (int)r, cg_step_log_record, run->log);
    size_t steps = cg_step_log_count(run->log);
    long pixels = trace_pixel_total(run);
    trace_summary(run, "%zu step%s; with 8-way symmetry the circle has %ld pixel%s", steps,
                  steps == 1 ? "" : "s", pixels, pixels == 1 ? "" : "s");
    return trace_finish(run, status, "the circle cannot be traced", out);
}

static int run_ellipse(int argc, char **argv, const trace_outputs *out)
{
    long rx, ry;
    if (argc != 3)
        return cli_usage_error("trace", "ellipse: expected 'ellipse RX RY'");
    if (trace_parse_int("RX", argv[1], 0, MAX_ELLIPSE_RADIUS, &rx)
        || trace_parse_int("RY", argv[2], 0, MAX_ELLIPSE_RADIUS, &ry))
        return CLI_USAGE;
    if (rx == ry)
        return cli_usage_error("trace",
                               "ellipse: equal radii draw the circle: use "
                               "'cg trace circle %ld'",
                               rx);
    trace_run *run = trace_run_create("ellipse", argc - 1, argv + 1,
                                      "Midpoint ellipse, radii rx = %ld, ry = %ld, centred on "
                                      "(0, 0)",
                                      rx, ry);
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run, "F(x, y) = ry^2 x^2 + rx^2 y^2 - rx^2 ry^2 (negative inside); d is 4F at "
                    "the midpoint tested");
    trace_note(run, "region 1 (slope above -1), one pixel per column from (0, ry): "
                    "d1 = 4F(x, y - 1/2); d1 < 0 selects E, else SE");
    trace_note(run, "the switch: where the slope reaches -1, x = rx^2 / sqrt(rx^2 + ry^2)");
    trace_note(run, "region 2, one pixel per row down to y = 0: d2 = 4F(x + 1/2, y); "
                    "d2 >= 0 selects S, else SE");
    trace_note(run, "a bridge pixel closes a two-pixel gap between the regions; each step "
                    "sets its pixel's 4 mirrors");
    cg_status status = cg_ellipse_steps(0, 0, (int)rx, (int)ry, cg_step_log_record, run->log);
    long pixels = trace_pixel_total(run);
    trace_summary(run, "%zu steps; with 4-way symmetry the ellipse has %ld pixel%s",
                  cg_step_log_count(run->log), pixels, pixels == 1 ? "" : "s");
    return trace_finish(run, status, "the ellipse cannot be traced", out);
}

/* ---- curves ------------------------------------------------------------------ */

/* Parses count points from argv; CLI_OK or CLI_USAGE. */
static int parse_points(char **argv, int count, cg_vec2 *points)
{
    char what[32];
    for (int i = 0; i < count; i++) {
        snprintf(what, sizeof what, "point %d", i + 1);
        if (trace_parse_point(what, argv[i], &points[i]))
            return CLI_USAGE;
    }
    return CLI_OK;
}

static int run_cubic(cg_curve_basis basis, int argc, char **argv, const trace_outputs *out)
{
    static const char *const forms[] = {"hermite P1 P4 R1 R4 [N]", "bezier P1 P2 P3 P4 [N]",
                                        "bspline P0 P1 P2 P3 [N]", "catmull-rom P0 P1 P2 P3 [N]"};
    long n = 8;
    cg_cubic2 curve = {basis, {{0, 0}, {0, 0}, {0, 0}, {0, 0}}};
    if (argc != 5 && argc != 6)
        return cli_usage_error("trace", "%s: expected '%s' (points as X,Y)", argv[0], forms[basis]);
    if (parse_points(argv + 1, 4, curve.g) != CLI_OK)
        return CLI_USAGE;
    if (argc == 6 && trace_parse_int("N", argv[5], 1, 1000, &n))
        return CLI_USAGE;
    trace_run *run = trace_run_create(argv[0], argc - 1, argv + 1,
                                      "%s segment Q(t) = T M G at t = 0, 1/%ld, ..., 1",
                                      cg_curve_basis_name(basis), n);
    if (!run)
        return cli_fail("trace: out of memory");
    cg_mat4 m = cg_curve_basis_matrix(basis);
    static const char *const geometry[] = {"G = [P1 P4 R1 R4] (endpoints, then tangents)",
                                           "G = [P1 P2 P3 P4]", "G = [P0 P1 P2 P3]",
                                           "G = [P0 P1 P2 P3]"};
    trace_note(run, "T = [t^3 t^2 t 1]; %s", geometry[basis]);
    for (int i = 0; i < 4; i++)
        trace_note(run, "M row %d: %8.4g %8.4g %8.4g %8.4g", i + 1, m.m[i][0], m.m[i][1], m.m[i][2],
                   m.m[i][3]);
    for (int i = 0; i < 4; i++)
        trace_note(run, "G%d = (%g, %g)", i + 1, curve.g[i].x, curve.g[i].y);
    trace_note(run, "b1..b4 = T M, the blending weights: Q = b1 G1 + b2 G2 + b3 G3 + b4 G4");
    if (basis != CG_BASIS_HERMITE)
        trace_scene_add(run, curve.g, 4, 0);
    cg_status status = cg_cubic_steps(&curve, (int)n, cg_step_log_record, run->log);
    return trace_finish(run, status, "the curve cannot be traced", out);
}

static int run_hermite(int argc, char **argv, const trace_outputs *out)
{
    return run_cubic(CG_BASIS_HERMITE, argc, argv, out);
}

static int run_bezier(int argc, char **argv, const trace_outputs *out)
{
    return run_cubic(CG_BASIS_BEZIER, argc, argv, out);
}

static int run_bspline(int argc, char **argv, const trace_outputs *out)
{
    return run_cubic(CG_BASIS_BSPLINE, argc, argv, out);
}

static int run_catmull_rom(int argc, char **argv, const trace_outputs *out)
{
    return run_cubic(CG_BASIS_CATMULL_ROM, argc, argv, out);
}

enum { MAX_CONTROL = 64 };

/* NAME NUMBER P0 P1 [P2 ...], the arguments of casteljau and flatten: the
 * number (called what) and 2 to MAX_CONTROL control points.  CLI_OK, or
 * CLI_USAGE after a message. */
static int read_control(const char *what, int argc, char **argv, double *number,
                        cg_vec2 control[MAX_CONTROL], int *count)
{
    *count = argc - 2;
    if (argc < 4 || *count > MAX_CONTROL)
        return cli_usage_error("trace",
                               "%s: expected '%s %s P0 P1 [P2 ...]' with 2 to %d points X,Y",
                               argv[0], argv[0], what, MAX_CONTROL);
    if (trace_parse_real(what, argv[1], number)
        || parse_points(argv + 2, *count, control) != CLI_OK)
        return CLI_USAGE;
    return CLI_OK;
}

static int run_casteljau(int argc, char **argv, const trace_outputs *out)
{
    double t;
    cg_vec2 control[MAX_CONTROL];
    int count;
    if (read_control("T", argc, argv, &t, control, &count) != CLI_OK)
        return CLI_USAGE;
    trace_run *run = trace_run_create("casteljau", argc - 1, argv + 1,
                                      "de Casteljau's algorithm at t = %g, degree %d", t,
                                      count - 1);
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run, "level r: P_i^r = (1 - t) P_i^(r-1) + t P_(i+1)^(r-1); the last level is "
                    "Q(t)");
    trace_note(run, "subdivision: the first point of each level makes the left curve [0, t], "
                    "the last point the right curve [t, 1]");
    trace_scene_add(run, control, count, 0);
    cg_status status = cg_casteljau_steps(control, count, t, cg_step_log_record, run->log);
    return trace_finish(run, status, "the curve cannot be traced", out);
}

static int run_flatten(int argc, char **argv, const trace_outputs *out)
{
    double tolerance;
    cg_vec2 control[MAX_CONTROL];
    int count;
    if (read_control("TOLERANCE", argc, argv, &tolerance, control, &count) != CLI_OK)
        return CLI_USAGE;
    if (!(tolerance > 0))
        return cli_usage_error("trace", "flatten: TOLERANCE must be positive, got '%s'", argv[1]);
    trace_run *run = trace_run_create("flatten", argc - 1, argv + 1,
                                      "Adaptive flattening of a degree-%d Bezier curve within %g",
                                      count - 1, tolerance);
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run, "a piece is flat when every control point lies within the tolerance of "
                    "its chord (the curve lies in the control points' convex hull): its chord "
                    "joins the polyline");
    trace_note(run, "otherwise it is split at t = 1/2 by de Casteljau and both halves are "
                    "tested, left first");
    trace_scene_add(run, control, count, 0);
    cg_status status = cg_bezier_flatten_steps(control, count, tolerance, cg_step_log_record,
                                               run->log);
    long segments = 0;
    for (size_t i = 0; i < cg_step_log_count(run->log); i++)
        segments += cg_step_log_get(run->log, i)->kept_count > 0;
    trace_summary(run, "%zu pieces tested; the polyline has %ld segment%s",
                  cg_step_log_count(run->log), segments, segments == 1 ? "" : "s");
    return trace_finish(run, status, "the tolerance is too small for this curve", out);
}

const trace_algorithm trace_chapter2_algorithms[] = {
    {"line", "X1 Y1 X2 Y2", run_line},
    {"dda", "X1 Y1 X2 Y2", run_dda},
    {"wu", "X1 Y1 X2 Y2", run_wu},
    {"circle", "R", run_circle},
    {"ellipse", "RX RY", run_ellipse},
    {"hermite", "P1 P4 R1 R4 [N]", run_hermite},
    {"bezier", "P1 P2 P3 P4 [N]", run_bezier},
    {"bspline", "P0 P1 P2 P3 [N]", run_bspline},
    {"catmull-rom", "P0 P1 P2 P3 [N]", run_catmull_rom},
    {"casteljau", "T P0 P1 [P2 ...]", run_casteljau},
    {"flatten", "TOLERANCE P0 P1 [P2 ...]", run_flatten},
    {NULL, NULL, NULL},
};
