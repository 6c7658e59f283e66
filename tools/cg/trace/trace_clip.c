/* `cg trace` for chapter 11: Cohen-Sutherland, Liang-Barsky,
 * Sutherland-Hodgman and Weiler-Atherton (y-up coordinates, as cg clip). */
#include "trace_algorithms.h"

#include "cli.h"
#include "cg/clip.h"
#include "cg/xform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_POLYGON = 256 };

/* The arguments of the two line clippers, NAME XMIN YMIN XMAX YMAX X0,Y0
 * X1,Y1: 0, or CLI_USAGE after a message. */
static int read_window_segment(const char *name, int argc, char **argv, cg_rect *window,
                               cg_vec2 *p0, cg_vec2 *p1)
{
    double bounds[4];
    static const char *const names[4] = {"XMIN", "YMIN", "XMAX", "YMAX"};
    if (argc != 7)
        return cli_usage_error("trace", "%s: expected '%s XMIN YMIN XMAX YMAX X0,Y0 X1,Y1'", name,
                               name);
    for (int i = 0; i < 4; i++)
        if (trace_parse_real(names[i], argv[i + 1], &bounds[i]))
            return CLI_USAGE;
    if (trace_parse_point("P0", argv[5], p0) || trace_parse_point("P1", argv[6], p1))
        return CLI_USAGE;
    if (bounds[0] > bounds[2] || bounds[1] > bounds[3])
        return cli_usage_error("trace", "%s: the window needs XMIN <= XMAX and YMIN <= YMAX", name);
    *window = (cg_rect){bounds[0], bounds[1], bounds[2], bounds[3]};
    return 0;
}

/* The window's outline in the scene. */
static void add_window_frame(trace_run *run, cg_rect window)
{
    cg_vec2 frame[4] = {{window.xmin, window.ymin},
                        {window.xmax, window.ymin},
                        {window.xmax, window.ymax},
                        {window.xmin, window.ymax}};
    trace_scene_add(run, frame, 4, 1);
}

static int run_cohen_sutherland(int argc, char **argv, const trace_outputs *out)
{
    cg_rect window;
    cg_vec2 p0, p1;
    if (read_window_segment("cohen-sutherland", argc, argv, &window, &p0, &p1))
        return CLI_USAGE;
    trace_run *run = trace_run_create(
        "cohen-sutherland", argc - 1, argv + 1,
        "Cohen-Sutherland: (%g, %g)-(%g, %g) against [%g, %g] x [%g, %g]", p0.x, p0.y, p1.x, p1.y,
        window.xmin, window.xmax, window.ymin, window.ymax);
    if (!run)
        return cli_fail("trace: out of memory");
    run->y_up = 1;
    add_window_frame(run, window);
    trace_note(run, "region codes TBRL: T y > ymax, B y < ymin, R x > xmax, L x < xmin (a "
                    "point on the boundary is inside)");
    trace_note(run, "both codes 0: trivial accept; their AND not 0: trivial reject (both "
                    "beyond one boundary)");
    trace_note(run, "otherwise the outside endpoint (p0 first) moves to the first boundary its "
                    "code names (top, bottom, right, left), and its code is computed again");
    cg_status status = cg_cohen_sutherland_steps(window, p0, p1, cg_step_log_record, run->log);
    return trace_finish(run, status, "the window or the points are not valid", out);
}

static int run_liang_barsky(int argc, char **argv, const trace_outputs *out)
{
    cg_rect window;
    cg_vec2 p0, p1;
    if (read_window_segment("liang-barsky", argc, argv, &window, &p0, &p1))
        return CLI_USAGE;
    trace_run *run = trace_run_create("liang-barsky", argc - 1, argv + 1,
                                      "Liang-Barsky: (%g, %g)-(%g, %g) against [%g, %g] x [%g, %g]",
                                      p0.x, p0.y, p1.x, p1.y, window.xmin, window.xmax, window.ymin,
                                      window.ymax);
    if (!run)
        return cli_fail("trace: out of memory");
    run->y_up = 1;
    add_window_frame(run, window);
    trace_note(run, "P(t) = P0 + t (P1 - P0), 0 <= t <= 1, is inside where p_k t <= q_k:");
    trace_note(run, "  left p = -dx, q = x0 - xmin; right p = dx, q = xmax - x0;");
    trace_note(run, "  bottom p = -dy, q = y0 - ymin; top p = dy, q = ymax - y0");
    trace_note(run, "p < 0: entering at t = q/p (t_enter = max); p > 0: leaving (t_exit = min); "
                    "p = 0: parallel, outside when q < 0");
    trace_note(run, "visible from t_enter to t_exit when t_enter <= t_exit (the outcome's points "
                    "are computed exactly by the library)");
    cg_status status = cg_liang_barsky_steps(window, p0, p1, cg_step_log_record, run->log);
    return trace_finish(run, status, "the window or the points are not valid", out);
}

/* NAME "WINDOW" "SUBJECT", the arguments of the two polygon clippers, into
 * window[0..*m) and subject[0..*n): 0, or CLI_USAGE after a message. */
static int read_window_subject(int argc, char **argv, cg_vec2 *window, int *m, cg_vec2 *subject,
                               int *n)
{
    if (argc != 3)
        return cli_usage_error("trace",
                               "%s: expected '%s \"WINDOW\" \"SUBJECT\"', each as 'X,Y X,Y X,Y "
                               "...'",
                               argv[0], argv[0]);
    *m = trace_parse_polygon("WINDOW", argv[1], window, MAX_POLYGON);
    *n = *m < 0 ? -1 : trace_parse_polygon("SUBJECT", argv[2], subject, MAX_POLYGON);
    return *m < 0 || *n < 0 ? CLI_USAGE : 0;
}

/* The window and the subject in the scene, y up. */
static void add_window_subject(trace_run *run, const cg_vec2 *window, int m, const cg_vec2 *subject,
                               int n)
{
    run->y_up = 1;
    trace_scene_add(run, window, m, 1);
    trace_scene_add(run, subject, n, 1);
}

static int run_sutherland_hodgman(int argc, char **argv, const trace_outputs *out)
{
    static cg_vec2 window[MAX_POLYGON], subject[MAX_POLYGON];
    int m = 0, n = 0;
    if (read_window_subject(argc, argv, window, &m, subject, &n))
        return CLI_USAGE;
    if (m < 3)
        return cli_usage_error("trace", "sutherland-hodgman: the window needs at least 3 "
                                        "points");
    trace_run *run = trace_run_create("sutherland-hodgman", argc - 1, argv + 1,
                                      "Sutherland-Hodgman: a %d-gon clipped by a convex %d-gon", n,
                                      m);
    if (!run)
        return cli_fail("trace: out of memory");
    add_window_subject(run, window, m, subject, n);
    trace_note(run, "for each clip edge in turn, every polygon edge s -> e of the input list "
                    "adds to the output list:");
    trace_note(run, "  in -> in: e;  in -> out: the crossing;  out -> out: nothing;  out -> in: "
                    "the crossing, then e");
    trace_note(run, "(a point on the clip line is inside); the output list is the next edge's "
                    "input");
    cg_status status = cg_sutherland_hodgman_steps(subject, (size_t)n, window, (size_t)m,
                                                   cg_step_log_record, run->log);
    return trace_finish(run, status,
                        "the window must be convex with non-zero area, and "
                        "every point finite",
                        out);
}

static int run_weiler_atherton(int argc, char **argv, const trace_outputs *out)
{
    static cg_vec2 window[MAX_POLYGON], subject[MAX_POLYGON];
    int m = 0, n = 0;
    if (read_window_subject(argc, argv, window, &m, subject, &n))
        return CLI_USAGE;
    if (m < 3 || n < 3)
        return cli_usage_error("trace", "weiler-atherton: each polygon needs at least 3 points");
    trace_run *run = trace_run_create("weiler-atherton", argc - 1, argv + 1,
                                      "Weiler-Atherton: a %d-gon clipped by a %d-gon", n, m);
    if (!run)
        return cli_fail("trace: out of memory");
    add_window_subject(run, window, m, subject, n);
    trace_note(run, "both boundaries are made counter-clockwise; every crossing of a subject "
                    "edge with a window edge is entering (the subject goes into the window) or "
                    "exiting");
    trace_note(run, "each boundary's list gets its crossings inserted in order; from each "
                    "entering crossing not yet visited:");
    trace_note(run, "  follow the subject to the next crossing, then the window to the next, "
                    "... until the start comes back: one loop");
    trace_note(run, "loops turning clockwise are holes of the smallest loop around them");
    cg_status status = cg_weiler_atherton_steps(subject, (size_t)n, window, (size_t)m,
                                                cg_step_log_record, run->log);
    return trace_finish(run, status, "each polygon needs 3 finite points", out);
}

/* "X,Y,Z X,Y,Z ..." into at most capacity points: the count, or -1. */
static int parse_polygon3(const char *text, cg_vec3 *points, int capacity)
{
    int count = 0, got;
    char word[192];
    for (const char *at = text; (got = trace_next_word(&at, word, sizeof word)) != 0; count++) {
        if (got < 0 || count >= capacity) {
            cli_usage_error("trace", "frustum: at most %d points X,Y,Z", capacity);
            return -1;
        }
        if (cli_parse_vec3("trace", "POLYGON", word, &points[count]))
            return -1;
    }
    return count;
}

/* frustum 'X,Y,Z ...' [EYE [TARGET [FOVY]]]: the polygon clipped against the
 * six planes of the camera's view volume (4:3, near 1, far 20). */
static int run_frustum(int argc, char **argv, const trace_outputs *out)
{
    static cg_vec3 polygon[MAX_POLYGON];
    cg_vec3 eye = {0, 0, 5}, target = {0, 0, 0};
    double fovy = 60;
    if (argc < 2 || argc > 5)
        return cli_usage_error("trace", "frustum: expected 'frustum \"X,Y,Z X,Y,Z ...\" [EYE "
                                        "[TARGET [FOVY]]]'");
    int n = parse_polygon3(argv[1], polygon, MAX_POLYGON);
    if (n < 0 || (argc > 2 && cli_parse_vec3("trace", "EYE", argv[2], &eye))
        || (argc > 3 && cli_parse_vec3("trace", "TARGET", argv[3], &target))
        || (argc > 4 && trace_parse_real("FOVY", argv[4], &fovy)))
        return CLI_USAGE;
    if (n < 3)
        return cli_usage_error("trace", "frustum: the polygon needs at least 3 points");
    cg_mat4 view, projection;
    if (!(fovy > 0 && fovy < 180)
        || cg_view_look_at(eye, target, cg_vec3_make(0, 1, 0), &view) != CG_OK
        || cg_proj_perspective(fovy * 3.14159265358979323846 / 180, 4.0 / 3.0, 1, 20, &projection)
               != CG_OK)
        return cli_usage_error("trace", "frustum: EYE and TARGET must differ (not along +y) and "
                                        "FOVY lie in (0, 180)");
    cg_plane planes[6];
    cg_frustum_planes(cg_mat4_mul(projection, view), planes);
    static const char *const names[6] = {"left", "right", "bottom", "top", "near", "far"};
    trace_run *run = trace_run_create("frustum", argc - 1, argv + 1,
                                      "A %d-gon clipped against the view volume of a camera at "
                                      "(%g, %g, %g) looking at (%g, %g, %g)",
                                      n, eye.x, eye.y, eye.z, target.x, target.y, target.z);
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run,
               "%g degrees, aspect 4:3, near 1, far 20; the six planes in world space, "
               "normals inward: d(p) = N.p + offset >= 0 inside",
               fovy);
    for (int k = 0; k < 6; k++)
        trace_note(run, "  %-6s N = (%.6g, %.6g, %.6g), offset %.6g", names[k], planes[k].normal.x,
                   planes[k].normal.y, planes[k].normal.z, planes[k].offset);
    trace_note(run, "for each plane, every edge s -> e: in -> in: e; in -> out: the crossing; "
                    "out -> in: the crossing, then e; out -> out: nothing");
    cg_status status = cg_clip_planes_steps(polygon, (size_t)n, planes, 6, names,
                                            cg_step_log_record, run->log);
    return trace_finish(run, status, "every point must be finite", out);
}

const trace_algorithm trace_clip_algorithms[] = {
    {"cohen-sutherland", "XMIN YMIN XMAX YMAX X0,Y0 X1,Y1", run_cohen_sutherland},
    {"liang-barsky", "XMIN YMIN XMAX YMAX X0,Y0 X1,Y1", run_liang_barsky},
    {"sutherland-hodgman", "'WINDOW' 'SUBJECT'", run_sutherland_hodgman},
    {"weiler-atherton", "'WINDOW' 'SUBJECT'", run_weiler_atherton},
    {"frustum", "'X,Y,Z X,Y,Z ...' [EYE [TARGET [FOVY]]]", run_frustum},
    {NULL, NULL, NULL},
};
