/* cg clip line | polygon | boolean: the clipping algorithms of chapter 11. */
#include "clip_geometry.h"
#include "clip_paths.h"
#include "clip_view.h"
#include "cli.h"
#include "command.h"

#include "cg/polygon.h"

#include <stdlib.h>
#include <string.h>

#define PICTURE_SIZE 640

static void rcode_bits(unsigned code, char out[5])
{
    /* TBRL, as in Fig. 11.1 */
    out[0] = (code & CG_RCODE_TOP) ? '1' : '0';
    out[1] = (code & CG_RCODE_BOTTOM) ? '1' : '0';
    out[2] = (code & CG_RCODE_RIGHT) ? '1' : '0';
    out[3] = (code & CG_RCODE_LEFT) ? '1' : '0';
    out[4] = 0;
}

static void print_trace(void *user, cg_vec2 p0, unsigned c0, cg_vec2 p1, unsigned c1,
                        const char *step)
{
    int *n = user;
    char b0[5], b1[5];
    rcode_bits(c0, b0);
    rcode_bits(c1, b1);
    printf("step %d: P0 (%.15g, %.15g) rCode %s, P1 (%.15g, %.15g) rCode %s: %s\n", ++*n, p0.x,
           p0.y, b0, p1.x, p1.y, b1, step);
}

/* cg clip line: the window and the segment as eight numbers, the options. */
typedef struct line_arguments {
    double numbers[8]; /* XMIN YMIN XMAX YMAX X0 Y0 X1 Y1 */
    int liang_barsky;  /* --algorithm liang-barsky */
    int trace;
} line_arguments;

static int line_number(const char *command, int index, const char *text, void *arguments)
{
    static const char *names[8] = {"XMIN", "YMIN", "XMAX", "YMAX", "X0", "Y0", "X1", "Y1"};
    line_arguments *a = arguments;
    if (index >= 8) {
        cli_usage_error(command, "line: expected 8 numbers, got '%s' as a ninth", text);
        return -1;
    }
    return cli_parse_double(command, names[index], text, &a->numbers[index]);
}

static const char *const line_algorithms[] = {"cohen-sutherland", "liang-barsky", NULL};
static const cli_option line_options[] = {
    {.name = "--algorithm",
     .kind = CLI_CHOICE,
     .offset = offsetof(line_arguments, liang_barsky),
     .choices = line_algorithms,
     .help = "the clipping algorithm (default cohen-sutherland)"},
    {.name = "--trace",
     .kind = CLI_FLAG,
     .offset = offsetof(line_arguments, trace),
     .flag_value = 1,
     .help = "print each step of Cohen-Sutherland with the region codes"},
};
static const cli_option_group line_groups[] = {CLI_GROUP(NULL, line_options), {0}};
static const cli_syntax line_syntax = {
    .command = "clip",
    .action = "line",
    .groups = line_groups,
    .positional = line_number,
    .min_positionals = 8,
    .too_few = "line: expected XMIN YMIN XMAX YMAX X0 Y0 X1 Y1",
};

static int line(int argc, char **argv)
{
    line_arguments a = {{0}, 0, 0};
    if (cli_parse(&line_syntax, argc, argv, &a, NULL, NULL) != CLI_OK)
        return CLI_USAGE;
    int trace = a.trace, liang = a.liang_barsky;
    const double *v = a.numbers;
    if (v[0] > v[2] || v[1] > v[3])
        return cli_usage_error("clip", "line: the window needs XMIN <= XMAX and YMIN <= YMAX");
    if (trace && liang)
        return cli_usage_error("clip", "line: --trace shows the rCodes of cohen-sutherland");
    cg_rect w = {v[0], v[1], v[2], v[3]};
    cg_vec2 p0 = {v[4], v[5]}, p1 = {v[6], v[7]};
    int accepted = 0, steps = 0;
    cg_status st = liang ? cg_clip_line_liang_barsky(w, &p0, &p1, &accepted)
                         : cg_clip_line_cohen_sutherland(w, &p0, &p1, &accepted,
                                                         trace ? print_trace : NULL, &steps);
    if (st != CG_OK)
        return cli_fail("clip: %s", cg_status_str(st));
    if (accepted)
        printf("%.15g %.15g %.15g %.15g\n", p0.x, p0.y, p1.x, p1.y);
    else
        printf("rejected\n");
    return CLI_OK;
}

static const cg_rgba8 SUBJECT_FILL = {66, 133, 244, 60}, SUBJECT_LINE = {40, 90, 200, 255};
static const cg_rgba8 CLIP_FILL = {234, 67, 53, 60}, CLIP_LINE = {190, 40, 30, 255};
static const cg_rgba8 RESULT_FILL = {251, 188, 5, 230}, RESULT_LINE = {30, 30, 30, 255};

/* Strokes every ring of set as an open path. */
static cg_status stroke_open(cg_image *image, const clip_view *v, const cg_polygon_set *set,
                             double width, cg_rgba8 color)
{
    cg_status st = CG_OK;
    for (size_t r = 0; st == CG_OK && r < set->ring_count; r++)
        st = clip_view_polyline(image, v, set->points + set->ring_start[r],
                                set->ring_start[r + 1] - set->ring_start[r], 0, width, color);
    return st;
}

/* The picture of a clip: both operands faint, the result solid on top;
 * when `open`, a and the result are open paths (drawn as lines). */
static int draw(const char *path, const cg_polygon_set *a, const cg_polygon_set *b,
                const cg_polygon_set *result, int open)
{
    const cg_polygon_set *sets[] = {a, b, result};
    cg_image *image = NULL;
    clip_view v;
    if (clip_view_canvas(sets, 3, PICTURE_SIZE, &image, &v) != CG_OK)
        return cli_fail("clip: out of memory");
    cg_status st = open ? CG_OK : clip_view_fill(image, &v, a, SUBJECT_FILL);
    if (st == CG_OK)
        st = clip_view_fill(image, &v, b, CLIP_FILL);
    if (st == CG_OK && !open)
        st = clip_view_fill(image, &v, result, RESULT_FILL);
    if (st == CG_OK)
        st = open ? stroke_open(image, &v, a, 1.5, SUBJECT_LINE)
                  : clip_view_stroke(image, &v, a, 1.5, SUBJECT_LINE);
    if (st == CG_OK)
        st = clip_view_stroke(image, &v, b, 1.5, CLIP_LINE);
    if (st == CG_OK)
        st = open ? stroke_open(image, &v, result, 4, RESULT_LINE)
                  : clip_view_stroke(image, &v, result, 2.5, RESULT_LINE);
    int status = st == CG_OK ? cli_write_image(image, path)
                             : cli_fail("clip: %s", cg_status_str(st));
    cg_image_free(image);
    return status;
}

/* cg clip boolean OPERATION A B: the fill rule of both, the picture, timing. */
typedef struct boolean_arguments {
    int fill; /* cg_clip_fill, in the order of fill_rules */
    const char *output;
    int repeat;
} boolean_arguments;

static const char *const fill_rules[] = {"evenodd", "nonzero", "positive", "negative", NULL};
static const cli_option boolean_options[] = {
    {.name = "--fill",
     .kind = CLI_CHOICE,
     .offset = offsetof(boolean_arguments, fill),
     .choices = fill_rules,
     .help = "the fill rule of A and B (default evenodd)"},
    CLI_OPTION_OUTPUT(boolean_arguments, output, "OUT.png",
                      "draw A, B and the result instead of printing the result"),
    CLI_OPTION_REPEAT(boolean_arguments, repeat, 100000,
                      "perform the operation N times; the median time on stderr"),
};
static const cli_option_group boolean_groups[] = {CLI_GROUP(NULL, boolean_options), {0}};
static const cli_syntax boolean_syntax = {
    .command = "clip",
    .action = "boolean",
    .groups = boolean_groups,
    .max_positionals = 3,
    .too_many = "boolean: unexpected argument '%s'",
    .min_positionals = 3,
    .too_few = "boolean: expected OPERATION A B",
};

static int boolean(int argc, char **argv)
{
    static const char *ops[4] = {"intersection", "union", "difference", "xor"};
    boolean_arguments arguments = {CG_CLIP_EVEN_ODD, NULL, 0};
    const char *positionals[3];
    if (cli_parse(&boolean_syntax, argc, argv, &arguments, positionals, NULL) != CLI_OK)
        return CLI_USAGE;
    const char *opname = positionals[0], *out = arguments.output;
    const char *files[2] = {positionals[1], positionals[2]};
    long repeat = arguments.repeat;
    cg_clip_fill fill = (cg_clip_fill)arguments.fill;
    int op = -1;
    for (int i = 0; i < 4; i++)
        if (strcmp(opname, ops[i]) == 0)
            op = i;
    if (op < 0)
        return cli_usage_error("clip",
                               "boolean: expected intersection, union, difference or xor, "
                               "got '%s'",
                               opname);
    if (strcmp(files[0], "-") == 0 && strcmp(files[1], "-") == 0)
        return cli_usage_error("clip", "boolean: only one of A and B can be '-' (stdin)");
    if (out && cg_file_format_from_path(out) == CG_FILE_UNKNOWN)
        return cli_usage_error("clip", "-o %s: unknown image format (expected .png, .ppm)", out);
    cg_polygon_set a = {0}, b = {0}, r = {0};
    cg_error err;
    int status = CLI_FAILED;
    int open = 0;
    if (clip_paths_read(files[0], &a, &open, &err) != CG_OK
        || clip_wkt_read(files[1], &b, &err) != CG_OK) {
        cli_fail("clip: %s", err.message);
        goto done;
    }
    if (open && op != CG_CLIP_INTERSECTION && op != CG_CLIP_DIFFERENCE) {
        cli_fail("clip: boolean %s: %s holds line strings, which only intersection and "
                 "difference clip",
                 ops[op], files[0]);
        goto done;
    }
    double *times = repeat > 0 ? malloc((size_t)repeat * sizeof *times) : NULL;
    long runs = repeat > 0 ? repeat : 1;
    cg_status st = CG_OK;
    /* repeated runs keep the engine's blocks from one to the next, as a
     * program running many operations would */
    cg_clip_workspace *ws = repeat > 1 ? cg_clip_workspace_create() : NULL;
    for (long k = 0; k < runs && st == CG_OK; k++) {
        double t0 = cli_now();
        st = open ? cg_clip_lines_ws(ws, (cg_clip_op)op, &a, &b, fill, 0, &r)
                  : cg_clip_boolean_ws(ws, (cg_clip_op)op, &a, fill, &b, fill, 0, &r);
        if (times)
            times[k] = cli_now() - t0;
    }
    cg_clip_workspace_free(ws);
    if (st != CG_OK) {
        free(times);
        cli_fail("clip: boolean %s: %s", ops[op], cg_status_str(st));
        goto done;
    }
    if (times) {
        fprintf(stderr, "boolean: %.2f ms\n", cli_median(times, (int)repeat) * 1e3);
        free(times);
    }
    if (out) {
        status = draw(out, &a, &b, &r, open);
    } else {
        if (open)
            clip_paths_write_lines(stdout, &r);
        else
            clip_wkt_write(stdout, &r);
        status = fflush(stdout) == 0 ? CLI_OK : cli_fail("clip: cannot write the result");
    }
done:
    cg_polygon_set_clear(&a);
    cg_polygon_set_clear(&b);
    cg_polygon_set_clear(&r);
    return status;
}

/* cg clip polygon WINDOW SUBJECT: first rings of two WKT files. */
typedef struct polygon_arguments {
    int weiler_atherton; /* --algorithm weiler-atherton */
    const char *output;
} polygon_arguments;

static const char *const polygon_algorithms[] = {"sutherland-hodgman", "weiler-atherton", NULL};
static const cli_option polygon_options[] = {
    {.name = "--algorithm",
     .kind = CLI_CHOICE,
     .offset = offsetof(polygon_arguments, weiler_atherton),
     .choices = polygon_algorithms,
     .help = "the clipping algorithm (default sutherland-hodgman)"},
    CLI_OPTION_OUTPUT(polygon_arguments, output, "OUT.png",
                      "draw WINDOW, SUBJECT and the result instead of printing the result"),
};
static const cli_option_group polygon_groups[] = {CLI_GROUP(NULL, polygon_options), {0}};
static const cli_syntax polygon_syntax = {
    .command = "clip",
    .action = "polygon",
    .groups = polygon_groups,
    .max_positionals = 2,
    .too_many = "polygon: unexpected argument '%s'",
    .min_positionals = 2,
    .too_few = "polygon: expected WINDOW SUBJECT",
};

static int polygon(int argc, char **argv)
{
    polygon_arguments arguments = {0, NULL};
    const char *files[2] = {NULL, NULL};
    if (cli_parse(&polygon_syntax, argc, argv, &arguments, files, NULL) != CLI_OK)
        return CLI_USAGE;
    const char *out = arguments.output;
    int weiler = arguments.weiler_atherton;
    if (out && cg_file_format_from_path(out) == CG_FILE_UNKNOWN)
        return cli_usage_error("clip", "-o %s: unknown image format (expected .png, .ppm)", out);
    cg_polygon_set w = {0}, s = {0}, r = {0};
    cg_error err;
    int status = CLI_FAILED;
    cg_status st;
    if (clip_wkt_read(files[0], &w, &err) != CG_OK || clip_wkt_read(files[1], &s, &err) != CG_OK) {
        cli_fail("clip: %s", err.message);
        goto done;
    }
    if (w.ring_count == 0 || s.ring_count == 0) {
        cli_fail("clip: polygon: %s is empty", w.ring_count == 0 ? files[0] : files[1]);
        goto done;
    }
    const cg_vec2 *wp = w.points, *sp = s.points;
    size_t wn = w.ring_start[1], sn = s.ring_start[1];
    if (weiler) {
        st = cg_clip_weiler_atherton(sp, sn, wp, wn, &r);
    } else {
        cg_vec2 *pts = NULL;
        size_t n = 0;
        st = cg_clip_sutherland_hodgman(sp, sn, wp, wn, &pts, &n);
        if (st == CG_OK && n >= 3)
            st = cg_polygon_set_add_ring(&r, pts, n, 1);
        free(pts);
    }
    if (st != CG_OK) {
        cli_fail("clip: polygon: %s%s", cg_status_str(st),
                 st == CG_EINVAL && !weiler ? " (Sutherland-Hodgman needs a convex window)" : "");
        goto done;
    }
    if (out) {
        status = draw(out, &s, &w, &r, 0);
    } else {
        clip_wkt_write(stdout, &r);
        status = CLI_OK;
    }
done:
    cg_polygon_set_clear(&w);
    cg_polygon_set_clear(&s);
    cg_polygon_set_clear(&r);
    return status;
}

static int run(int argc, char **argv)
{
    if (argc >= 2 && clip_geometry_handles(argv[1]))
        return clip_geometry_run(argc - 1, argv + 1);
    static const cli_action actions[] = {{"line", line},
                                         {"polygon", polygon},
                                         {"boolean", boolean}};
    return cli_run_action("clip", argc, argv, actions, 3, NULL,
                          "unknown clip command '%s' (expected line, polygon or boolean)");
}

static const cli_syntax *const clip_syntaxes[] = {&line_syntax,
                                                  &polygon_syntax,
                                                  &boolean_syntax,
                                                  &clip_offset_syntax,
                                                  &clip_minkowski_syntax,
                                                  &clip_rect_syntax,
                                                  &clip_triangulate_syntax,
                                                  &clip_simplify_syntax,
                                                  NULL};

const cg_command cg_command_clip = {
    "clip",
    "clip segments and polygons; boolean operations on polygons (WKT)",
    "usage: cg clip line XMIN YMIN XMAX YMAX X0 Y0 X1 Y1\n"
    "                    [--algorithm cohen-sutherland|liang-barsky] [--trace]\n"
    "       cg clip polygon WINDOW SUBJECT [--algorithm sutherland-hodgman|weiler-atherton]\n"
    "                    [-o OUT.png]\n"
    "       cg clip boolean intersection|union|difference|xor A B\n"
    "                    [--fill evenodd|nonzero|positive|negative] [-o OUT.png] [--repeat "
    "N]\n" CLIP_GEOMETRY_USAGE_LINES "\n"
    "line: clips the segment (X0,Y0)-(X1,Y1) against the window and prints the\n"
    "visible part as 'X0 Y0 X1 Y1', or 'rejected'.  --trace prints each step of\n"
    "Cohen-Sutherland with the endpoints' 4-bit region codes (TBRL, as in the notes).\n\n"
    "polygon: clips the first ring of SUBJECT by the first ring of WINDOW (WKT\n"
    "files, '-' for stdin): Sutherland-Hodgman (the default) needs a convex window,\n"
    "Weiler-Atherton takes any simple window and may give several polygons.\n\n"
    "boolean: reads polygons A and B as WKT POLYGON or MULTIPOLYGON ('-' for\n"
    "stdin, MULTIPOLYGON EMPTY allowed); every ring is a path whose orientation\n"
    "counts under the fill rule (default evenodd, for both).  Prints the result as\n"
    "a WKT MULTIPOLYGON (outer rings counter-clockwise, holes clockwise) or\n"
    "MULTIPOLYGON EMPTY; -o OUT.png draws A, B and the result instead.  --repeat N\n"
    "performs the operation N times after reading (through one workspace, which\n"
    "keeps the engine's memory from run to run) and prints the median time on\n"
    "stderr as 'boolean: 1.23 ms'.  Coordinates are rounded to a grid 2^36 times\n"
    "finer than the largest |coordinate| (see docs/clip.md).  When A holds line\n"
    "strings (LINESTRING or MULTILINESTRING), intersection prints the pieces of\n"
    "them inside B (its boundary included) and difference the pieces outside, as a\n"
    "MULTILINESTRING in order along each line; -o draws them over B.\n\n" CLIP_GEOMETRY_USAGE_TEXT,
    run,
    clip_syntaxes,
};
