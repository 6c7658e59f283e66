/* cg clip offset | minkowski | rect | triangulate | simplify: polygon geometry beyond
 * the boolean operations (cg/polygon.h), WKT in and out. */
#include "clip_geometry.h"
#include "clip_paths.h"
#include "clip_view.h"
#include "cli.h"

#include "cg/polygon.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PICTURE_SIZE 640

static const cg_rgba8 INPUT_FILL = {66, 133, 244, 60}, INPUT_LINE = {40, 90, 200, 255};
static const cg_rgba8 RESULT_FILL = {251, 188, 5, 200}, RESULT_LINE = {30, 30, 30, 255};

/* The picture: the input faint (its paths open or closed), the result on top
 * (filled polygons, or open paths when result_open). */
static int draw(const char *path, const cg_polygon_set *input, int input_open,
                const cg_polygon_set *result, int result_open)
{
    const cg_polygon_set *sets[] = {input, result};
    cg_image *image = NULL;
    clip_view v;
    if (clip_view_canvas(sets, 2, PICTURE_SIZE, &image, &v) != CG_OK)
        return cli_fail("clip: out of memory");
    cg_status st = CG_OK;
    if (!input_open)
        st = clip_view_fill(image, &v, input, INPUT_FILL);
    if (st == CG_OK && !result_open)
        st = clip_view_fill(image, &v, result, RESULT_FILL);
    for (size_t r = 0; st == CG_OK && r < input->ring_count; r++)
        st = clip_view_polyline(image, &v, input->points + input->ring_start[r],
                                input->ring_start[r + 1] - input->ring_start[r], !input_open, 1.5,
                                INPUT_LINE);
    for (size_t r = 0; st == CG_OK && r < result->ring_count; r++)
        st = clip_view_polyline(image, &v, result->points + result->ring_start[r],
                                result->ring_start[r + 1] - result->ring_start[r], !result_open,
                                result_open ? 3 : 1.5, RESULT_LINE);
    int status = st == CG_OK ? cli_write_image(image, path)
                             : cli_fail("clip: %s", cg_status_str(st));
    cg_image_free(image);
    return status;
}

/* The arguments of every command of this file, parsed by cli_parse. */
typedef struct geometry_arguments {
    const char *picture;               /* -o */
    int repeat;                        /* --repeat, 0 when not given */
    int fill;                          /* --fill: cg_clip_fill */
    int join;                          /* offset --join: cg_offset_join */
    int end, end_given;                /* offset --end: index in end_choices */
    double miter_limit, arc_tolerance; /* offset */
    double min_angle;                  /* triangulate */
    int algorithm;                     /* simplify: cg_simplify_algorithm */
} geometry_arguments;

static const char *const fill_choices[] = {"evenodd", "nonzero", "positive", "negative", NULL};
static const char *const join_choices[] = {"miter", "round", "square", "bevel", NULL};
/* The ends of line strings, in the order of cg_offset_end from
 * CG_OFFSET_END_JOINED. */
static const char *const end_choices[] = {"joined", "butt", "square", "round", NULL};
static const char *const algorithm_choices[] = {"rdp", "visvalingam", NULL};

/* --fill, -o and --repeat: the options every command here takes. */
#define GEOMETRY_COMMON_OPTIONS                                                            \
    {.name = "--fill",                                                                     \
     .kind = CLI_CHOICE,                                                                   \
     .offset = offsetof(geometry_arguments, fill),                                         \
     .choices = fill_choices,                                                              \
     .help = "the fill rule of the polygons read (default evenodd)"},                      \
        CLI_OPTION_OUTPUT(geometry_arguments, picture, "OUT.png",                          \
                          "draw the input and the result instead of printing the result"), \
        CLI_OPTION_REPEAT(geometry_arguments, repeat, 100000,                              \
                          "perform the operation N times; the median time on stderr")

static const cli_option offset_options[] = {
    {.name = "--join",
     .kind = CLI_CHOICE,
     .offset = offsetof(geometry_arguments, join),
     .choices = join_choices,
     .help = "the corners (default miter)"},
    {.name = "--end",
     .kind = CLI_CHOICE,
     .offset = offsetof(geometry_arguments, end),
     .choices = end_choices,
     .given = CLI_GIVEN(geometry_arguments, end_given),
     .help = "the ends of line strings (default round)"},
    {.name = "--miter-limit",
     .kind = CLI_DOUBLE,
     .offset = offsetof(geometry_arguments, miter_limit),
     .value_name = "M",
     .help = "miters cut flat at M times |DELTA| (default 2)",
     .range_text = "a number >= 1",
     .low = 1,
     .high = 1e300},
    {.name = "--arc-tolerance",
     .kind = CLI_DOUBLE,
     .offset = offsetof(geometry_arguments, arc_tolerance),
     .value_name = "T",
     .help = "the gap between a round join and its chords (default |DELTA|/500)",
     .range_text = "a positive number",
     .low = 0,
     .high = 1e300,
     .open = CLI_OPEN_LOW},
    GEOMETRY_COMMON_OPTIONS,
};
static const cli_option triangulate_options[] = {
    {.name = "--min-angle",
     .kind = CLI_DOUBLE,
     .offset = offsetof(geometry_arguments, min_angle),
     .value_name = "A",
     .help = "refine until no angle is below A degrees",
     .range_text = "degrees from 0 to 30 (beyond it refinement need not end)",
     .low = 0,
     .high = CG_TRIANGULATE_MAX_MIN_ANGLE},
    GEOMETRY_COMMON_OPTIONS,
};
static const cli_option simplify_options[] = {
    {.name = "--algorithm",
     .kind = CLI_CHOICE,
     .offset = offsetof(geometry_arguments, algorithm),
     .choices = algorithm_choices,
     .help = "Ramer-Douglas-Peucker (the default) or Visvalingam-Whyatt"},
    GEOMETRY_COMMON_OPTIONS,
};
static const cli_option shared_options[] = {GEOMETRY_COMMON_OPTIONS};

static const cli_option_group offset_groups[] = {CLI_GROUP(NULL, offset_options), {0}};
static const cli_option_group triangulate_groups[] = {CLI_GROUP(NULL, triangulate_options), {0}};
static const cli_option_group simplify_groups[] = {CLI_GROUP(NULL, simplify_options), {0}};
static const cli_option_group common_groups[] = {CLI_GROUP(NULL, shared_options), {0}};

const cli_syntax clip_offset_syntax = {.command = "clip",
                                       .action = "offset",
                                       .groups = offset_groups,
                                       .max_positionals = 2,
                                       .too_many = "offset: unexpected argument '%s'",
                                       .min_positionals = 2,
                                       .too_few = "offset: expected DELTA IN"};
const cli_syntax clip_minkowski_syntax = {
    .command = "clip",
    .action = "minkowski",
    .groups = common_groups,
    .max_positionals = 3,
    .too_many = "minkowski: unexpected argument '%s'",
    .min_positionals = 3,
    .too_few = "minkowski: expected sum|difference PATTERN PATH"};
const cli_syntax clip_rect_syntax = {.command = "clip",
                                     .action = "rect",
                                     .groups = common_groups,
                                     .max_positionals = 5,
                                     .too_many = "rect: unexpected argument '%s'",
                                     .min_positionals = 5,
                                     .too_few = "rect: expected XMIN YMIN XMAX YMAX IN"};
const cli_syntax clip_triangulate_syntax = {.command = "clip",
                                            .action = "triangulate",
                                            .groups = triangulate_groups,
                                            .max_positionals = 1,
                                            .too_many = "triangulate: unexpected argument '%s'",
                                            .min_positionals = 1,
                                            .too_few = "triangulate: expected IN"};
const cli_syntax clip_simplify_syntax = {.command = "clip",
                                         .action = "simplify",
                                         .groups = simplify_groups,
                                         .max_positionals = 2,
                                         .too_many = "simplify: unexpected argument '%s'",
                                         .min_positionals = 2,
                                         .too_few = "simplify: expected TOLERANCE IN"};

/* Parses a command's arguments with the defaults set; checks -o's format.
 * CLI_OK, or CLI_USAGE after a message. */
static int parse_geometry(const cli_syntax *syntax, int argc, char **argv, geometry_arguments *args,
                          const char **positionals)
{
    cg_offset_options defaults = cg_offset_options_default();
    *args = (geometry_arguments){NULL,
                                 0,
                                 CG_CLIP_EVEN_ODD,
                                 CG_OFFSET_JOIN_MITER,
                                 0,
                                 0,
                                 defaults.miter_limit,
                                 defaults.arc_tolerance,
                                 0,
                                 CG_SIMPLIFY_RDP};
    if (cli_parse(syntax, argc, argv, args, positionals, NULL) != CLI_OK)
        return CLI_USAGE;
    if (args->picture && cg_file_format_from_path(args->picture) == CG_FILE_UNKNOWN)
        return cli_usage_error("clip", "%s: -o %s: unknown image format (expected .png, .ppm)",
                               syntax->action, args->picture);
    return CLI_OK;
}

/* A positional number: finite (and >= low when low_given). */
static int parse_number(const char *name, const char *text, int at_least_zero, double *out)
{
    if (cli_parse_double("clip", name, text, out) != 0)
        return CLI_USAGE;
    if (!isfinite(*out) || (at_least_zero && !(*out >= 0)))
        return cli_usage_error("clip", "%s: expected a finite number%s, got '%s'", name,
                               at_least_zero ? " >= 0" : "", text);
    return CLI_OK;
}

/* Prints the median of the timings on stderr as "NAME: 1.23 ms". */
static void report_time(const char *name, double *times, long runs)
{
    if (times && runs > 0)
        fprintf(stderr, "%s: %.2f ms\n", name, cli_median(times, (int)runs) * 1e3);
}

/* Writes the result (or draws it); frees nothing. */
static int finish(const geometry_arguments *common, const cg_polygon_set *input, int input_open,
                  const cg_polygon_set *result, int result_open)
{
    if (common->picture)
        return draw(common->picture, input, input_open, result, result_open);
    if (result_open)
        clip_paths_write_lines(stdout, result);
    else
        clip_wkt_write(stdout, result);
    return fflush(stdout) == 0 ? CLI_OK : cli_fail("clip: cannot write the result");
}

/* One run of a command's operation on the input, with a workspace or NULL. */
typedef cg_status (*geometry_step)(const void *args, cg_clip_workspace *ws,
                                   const cg_polygon_set *input, int open, cg_polygon_set *result);

/* Runs step once, or --repeat times timing each (with a workspace when
 * want_workspace), reports the median, then writes or draws the result. */
static int run_timed(const char *name, const geometry_arguments *common, int want_workspace,
                     geometry_step step, const void *args, const cg_polygon_set *input, int open,
                     cg_polygon_set *result, int result_open)
{
    long runs = common->repeat > 0 ? common->repeat : 1;
    double *times = common->repeat > 0 ? malloc((size_t)runs * sizeof *times) : NULL;
    cg_clip_workspace *ws = runs > 1 && want_workspace ? cg_clip_workspace_create() : NULL;
    cg_status st = CG_OK;
    for (long k = 0; k < runs && st == CG_OK; k++) {
        double t0 = cli_now();
        st = step(args, ws, input, open, result);
        if (times)
            times[k] = cli_now() - t0;
    }
    cg_clip_workspace_free(ws);
    if (st == CG_OK)
        report_time(name, times, runs);
    free(times);
    if (st != CG_OK)
        return cli_fail("clip: %s: %s", name, cg_status_str(st));
    return finish(common, input, open, result, result_open);
}


/* What a command does once its arguments are parsed: read IN, check what it
 * holds, run the step (timed), write or draw the result. */
typedef struct geometry_job {
    const char *name;
    geometry_step step;
    void *args;
    /* NULL, or 0 to go on / CLI_USAGE after a message, given whether IN holds
     * line strings; it may fill args from that. */
    int (*check)(void *args, const char *file, int open);
    int workspace_for_lines; /* use a workspace on line strings too */
    int workspace_for_polygons;
    int result_open_when_open; /* line strings in, line strings out */
    /* NULL, or told the result once it is written (for warnings) */
    void (*report)(const void *args, const cg_polygon_set *result);
} geometry_job;

static int run_job(const geometry_job *job, const char *file, const geometry_arguments *common)
{
    cg_polygon_set input = {0}, result = {0};
    cg_error err;
    int open = 0, status;
    if (clip_paths_read(file, &input, &open, &err) != CG_OK)
        status = cli_fail("clip: %s", err.message);
    else if (!job->check || (status = job->check(job->args, file, open)) == 0)
        status = run_timed(job->name, common,
                           open ? job->workspace_for_lines : job->workspace_for_polygons, job->step,
                           job->args, &input, open, &result, open && job->result_open_when_open);
    if (status == 0 && job->report)
        job->report(job->args, &result);
    cg_polygon_set_clear(&input);
    cg_polygon_set_clear(&result);
    return status;
}


typedef struct offset_args {
    double delta;
    cg_offset_options options;
    int end; /* index in offset_ends, or -1: the default for what IN holds */
} offset_args;

static cg_status offset_step(const void *args, cg_clip_workspace *ws, const cg_polygon_set *input,
                             int open, cg_polygon_set *result)
{
    const offset_args *a = args;
    (void)open;
    return cg_offset_ws(ws, input, a->delta, &a->options, 0, result);
}

/* The ends butt, square and round are for line strings; the default end
 * follows what IN holds. */
static int offset_check(void *args, const char *file, int open)
{
    offset_args *a = args;
    if (!open && a->end > CG_OFFSET_END_JOINED)
        return cli_usage_error("clip", "offset: --end %s is for line strings; %s holds polygons",
                               end_choices[a->end - CG_OFFSET_END_JOINED], file);
    a->options.end = a->end >= 0 ? (cg_offset_end)a->end
                     : open      ? CG_OFFSET_END_ROUND
                                 : CG_OFFSET_END_POLYGON;
    return 0;
}

static int offset(int argc, char **argv)
{
    geometry_arguments common;
    const char *positionals[2];
    if (parse_geometry(&clip_offset_syntax, argc, argv, &common, positionals) != CLI_OK)
        return CLI_USAGE;
    double delta;
    if (parse_number("DELTA", positionals[0], 0, &delta) != CLI_OK)
        return CLI_USAGE;
    cg_offset_options options = cg_offset_options_default();
    options.fill = (cg_clip_fill)common.fill;
    options.join = (cg_offset_join)common.join;
    options.miter_limit = common.miter_limit;
    options.arc_tolerance = common.arc_tolerance;
    offset_args args = {delta, options, common.end_given ? CG_OFFSET_END_JOINED + common.end : -1};
    geometry_job job = {"offset", offset_step, &args, offset_check, 1, 1, 0, NULL};
    return run_job(&job, positionals[1], &common);
}

typedef struct rect_args {
    cg_rect window;
    cg_clip_fill fill;
} rect_args;

static cg_status rect_step(const void *args, cg_clip_workspace *ws, const cg_polygon_set *input,
                           int open, cg_polygon_set *result)
{
    const rect_args *a = args;
    return open ? cg_rect_clip_lines(input, a->window, 0, result)
                : cg_rect_clip_ws(ws, input, a->fill, a->window, 0, result);
}

/* cg clip rect XMIN YMIN XMAX YMAX IN */
static int rect(int argc, char **argv)
{
    static const char *names[4] = {"XMIN", "YMIN", "XMAX", "YMAX"};
    geometry_arguments common;
    const char *positionals[5];
    if (parse_geometry(&clip_rect_syntax, argc, argv, &common, positionals) != CLI_OK)
        return CLI_USAGE;
    double v[4];
    for (int k = 0; k < 4; k++)
        if (parse_number(names[k], positionals[k], 0, &v[k]) != CLI_OK)
            return CLI_USAGE;
    if (v[0] > v[2] || v[1] > v[3])
        return cli_usage_error("clip", "rect: the rectangle needs XMIN <= XMAX and YMIN <= YMAX");
    rect_args args = {{v[0], v[1], v[2], v[3]}, (cg_clip_fill)common.fill};
    geometry_job job = {"rect", rect_step, &args, NULL, 0, 1, 1, NULL};
    return run_job(&job, positionals[4], &common);
}

typedef struct triangulate_args {
    cg_clip_fill fill;
    double min_angle;
} triangulate_args;

static cg_status triangulate_step(const void *args, cg_clip_workspace *ws,
                                  const cg_polygon_set *input, int open, cg_polygon_set *result)
{
    const triangulate_args *a = args;
    (void)open;
    return cg_triangulate_refined_ws(ws, input, a->fill, a->min_angle, 0, result);
}

/* The smallest angle of triangle p, in degrees. */
static double smallest_angle(const cg_vec2 *p)
{
    double least = 180;
    for (int i = 0; i < 3; i++) {
        cg_vec2 a = p[i], b = p[(i + 1) % 3], c = p[(i + 2) % 3];
        double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
        double angle = atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / M_PI;
        least = angle < least ? angle : least;
    }
    return least;
}

/* Refinement keeps some angles under the bound (at input corners too sharp
 * to refine, and where the grid is too coarse to split further): say how
 * many, so that a user does not take the bound for a guarantee. */
static void triangulate_report(const void *args, const cg_polygon_set *result)
{
    const triangulate_args *a = args;
    if (a->min_angle <= 0)
        return;
    size_t under = 0;
    for (size_t t = 0; t < result->ring_count; t++)
        if (result->ring_start[t + 1] - result->ring_start[t] == 3
            && smallest_angle(result->points + result->ring_start[t]) < a->min_angle - 1e-9)
            under++;
    if (under)
        fprintf(stderr,
                "cg: clip: triangulate: %zu of %zu triangles keep an angle under %g degrees (at "
                "input corners too sharp to refine, or where the grid is too coarse to split)\n",
                under, result->ring_count, a->min_angle);
}

/* Triangles are made of polygons only. */
static int triangulate_check(void *args, const char *file, int open)
{
    (void)args;
    if (open)
        return cli_usage_error("clip", "triangulate: %s holds line strings; expected polygons",
                               file);
    return 0;
}

/* cg clip triangulate IN: the triangles as a MULTIPOLYGON. */
static int triangulate(int argc, char **argv)
{
    geometry_arguments common;
    const char *positionals[1];
    if (parse_geometry(&clip_triangulate_syntax, argc, argv, &common, positionals) != CLI_OK)
        return CLI_USAGE;
    triangulate_args args = {(cg_clip_fill)common.fill, common.min_angle};
    geometry_job job = {"triangulate",     triangulate_step, &args, triangulate_check, 1, 1, 0,
                        triangulate_report};
    return run_job(&job, positionals[0], &common);
}

typedef struct simplify_args {
    cg_clip_fill fill;
    cg_simplify_algorithm algorithm;
    double tolerance;
} simplify_args;

static cg_status simplify_step(const void *args, cg_clip_workspace *ws, const cg_polygon_set *input,
                               int open, cg_polygon_set *result)
{
    const simplify_args *a = args;
    (void)ws;
    return cg_simplify(input, open, a->fill, a->algorithm, a->tolerance, 0, result);
}

/* cg clip simplify TOLERANCE IN [--algorithm rdp|visvalingam] */
static int simplify(int argc, char **argv)
{
    geometry_arguments common;
    const char *positionals[2];
    if (parse_geometry(&clip_simplify_syntax, argc, argv, &common, positionals) != CLI_OK)
        return CLI_USAGE;
    double tolerance;
    if (parse_number("TOLERANCE", positionals[0], 1, &tolerance) != CLI_OK)
        return CLI_USAGE;
    simplify_args args = {(cg_clip_fill)common.fill, (cg_simplify_algorithm)common.algorithm,
                          tolerance};
    geometry_job job = {"simplify", simplify_step, &args, NULL, 0, 0, 1, NULL};
    return run_job(&job, positionals[1], &common);
}

typedef struct minkowski_args {
    cg_minkowski_op op;
    cg_clip_fill fill;
    const cg_polygon_set *pattern;
} minkowski_args;

static cg_status minkowski_step(const void *args, cg_clip_workspace *ws,
                                const cg_polygon_set *input, int open, cg_polygon_set *result)
{
    const minkowski_args *a = args;
    return cg_minkowski_ws(ws, a->op, a->pattern, input, open, a->fill, 0, result);
}

/* cg clip minkowski sum|difference PATTERN PATH */
static int minkowski(int argc, char **argv)
{
    geometry_arguments common;
    const char *positionals[3];
    if (parse_geometry(&clip_minkowski_syntax, argc, argv, &common, positionals) != CLI_OK)
        return CLI_USAGE;
    const char *operation = positionals[0], *files[2] = {positionals[1], positionals[2]};
    minkowski_args args = {CG_MINKOWSKI_SUM, (cg_clip_fill)common.fill, NULL};
    if (strcmp(operation, "sum") == 0)
        args.op = CG_MINKOWSKI_SUM;
    else if (strcmp(operation, "difference") == 0)
        args.op = CG_MINKOWSKI_DIFFERENCE;
    else
        return cli_usage_error("clip", "minkowski: expected sum or difference, got '%s'",
                               operation);
    if (strcmp(files[0], "-") == 0 && strcmp(files[1], "-") == 0)
        return cli_usage_error("clip", "minkowski: only one of PATTERN and PATH can be '-'");
    cg_polygon_set pattern = {0}, path = {0}, result = {0};
    cg_error err;
    int pattern_open = 0, open = 0, status = CLI_FAILED;
    if (clip_paths_read(files[0], &pattern, &pattern_open, &err) != CG_OK
        || clip_paths_read(files[1], &path, &open, &err) != CG_OK) {
        cli_fail("clip: %s", err.message);
        goto done;
    }
    if (pattern_open) {
        status = cli_usage_error("clip",
                                 "minkowski: %s holds line strings; the pattern is a "
                                 "polygon",
                                 files[0]);
        goto done;
    }
    args.pattern = &pattern;
    status = run_timed("minkowski", &common, 1, minkowski_step, &args, &path, open, &result, 0);
done:
    cg_polygon_set_clear(&pattern);
    cg_polygon_set_clear(&path);
    cg_polygon_set_clear(&result);
    return status;
}

int clip_geometry_handles(const char *name)
{
    return strcmp(name, "offset") == 0 || strcmp(name, "rect") == 0
           || strcmp(name, "minkowski") == 0 || strcmp(name, "triangulate") == 0
           || strcmp(name, "simplify") == 0;
}

int clip_geometry_run(int argc, char **argv)
{
    if (strcmp(argv[0], "offset") == 0)
        return offset(argc, argv);
    if (strcmp(argv[0], "rect") == 0)
        return rect(argc, argv);
    if (strcmp(argv[0], "minkowski") == 0)
        return minkowski(argc, argv);
    if (strcmp(argv[0], "triangulate") == 0)
        return triangulate(argc, argv);
    if (strcmp(argv[0], "simplify") == 0)
        return simplify(argc, argv);
    return cli_usage_error("clip", "unknown clip command '%s'", argv[0]);
}
