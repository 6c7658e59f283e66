/* cg clip offset | rect | triangulate | simplify: polygon geometry beyond
 * the boolean operations (cg/polygon.h), WKT in and out. */
#include "clip_geometry.h"
#include "clip_paths.h"
#include "clip_view.h"
#include "cli.h"

#include "cg/polygon.h"

#include <math.h>
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

/* Index of text in names[0..count), or -1. */
static int pick_name(const char *text, const char *const *names, int count)
{
    for (int i = 0; i < count; i++)
        if (strcmp(text, names[i]) == 0)
            return i;
    return -1;
}

/* The options every command of this file takes: -o and --repeat. */
typedef struct common_options {
    const char *picture;
    long repeat;
} common_options;

/* 1 when argv[*i] was -o or --repeat (taken), 0 when not one of them, -1 on
 * a usage error (printed). */
static int take_common(const char *name, int argc, char **argv, int *i, common_options *common)
{
    if (cli_option_is(argv[*i], "-o")) {
        common->picture = cli_option_value("clip", argc, argv, i);
        if (!common->picture)
            return -1;
        if (cg_file_format_from_path(common->picture) == CG_FILE_UNKNOWN) {
            cli_usage_error("clip", "%s: -o %s: unknown image format (expected .png, .ppm)", name,
                            common->picture);
            return -1;
        }
        return 1;
    }
    if (cli_option_is(argv[*i], "--repeat")) {
        const char *r = cli_option_value("clip", argc, argv, i);
        if (!r || cli_parse_long("clip", "--repeat", r, 1, 100000, &common->repeat) != 0)
            return -1;
        return 1;
    }
    return 0;
}

/* Prints the median of the timings on stderr as "NAME: 1.23 ms". */
static void report_time(const char *name, double *times, long runs)
{
    if (times && runs > 0)
        fprintf(stderr, "%s: %.2f ms\n", name, cli_median(times, (int)runs) * 1e3);
}

/* Writes the result (or draws it); frees nothing. */
static int finish(const common_options *common, const cg_polygon_set *input, int input_open,
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

static const char *const fill_names[] = {"evenodd", "nonzero", "positive", "negative"};

/* One run of a command's operation on the input, with a workspace or NULL. */
typedef cg_status (*geometry_step)(const void *args, cg_clip_workspace *ws,
                                   const cg_polygon_set *input, int open, cg_polygon_set *result);

/* Runs step once, or --repeat times timing each (with a workspace when
 * want_workspace), reports the median, then writes or draws the result. */
static int run_timed(const char *name, const common_options *common, int want_workspace,
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

/* The positional argument after the first ones: IN, then nothing more.
 * 0, or CLI_USAGE after a message. */
static int take_operand(const char *name, const char *arg, const char **first, const char **file)
{
    if (cli_is_option(arg))
        return cli_usage_error("clip", "%s: unknown option '%s'", name, arg);
    if (first && !*first)
        *first = arg;
    else if (!*file)
        *file = arg;
    else
        return cli_usage_error("clip", "%s: unexpected argument '%s'", name, arg);
    return 0;
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
} geometry_job;

static int run_job(const geometry_job *job, const char *file, const common_options *common)
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
    cg_polygon_set_clear(&input);
    cg_polygon_set_clear(&result);
    return status;
}

/* --fill NAME into *fill: 1 taken, 0 not this option, -1 usage error. */
static int take_fill(const char *name, int argc, char **argv, int *i, cg_clip_fill *fill)
{
    if (!cli_option_is(argv[*i], "--fill"))
        return 0;
    const char *value = cli_option_value("clip", argc, argv, i);
    if (!value)
        return -1;
    int k = pick_name(value, fill_names, 4);
    if (k < 0) {
        cli_usage_error("clip",
                        "%s: --fill: expected evenodd, nonzero, positive or negative, "
                        "got '%s'",
                        name, value);
        return -1;
    }
    *fill = (cg_clip_fill)k;
    return 1;
}

static const char *const offset_ends[] = {"polygon", "joined", "butt", "square", "round"};

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
    if (!open && a->end > 1)
        return cli_usage_error("clip", "offset: --end %s is for line strings; %s holds polygons",
                               offset_ends[a->end], file);
    a->options.end = a->end >= 0 ? (cg_offset_end)a->end
                     : open      ? CG_OFFSET_END_ROUND
                                 : CG_OFFSET_END_POLYGON;
    return 0;
}

static int offset(int argc, char **argv)
{
    static const char *const joins[] = {"miter", "round", "square", "bevel"};
    cg_offset_options options = cg_offset_options_default();
    common_options common = {0};
    const char *file = NULL, *delta_text = NULL;
    int end = -1;
    for (int i = 1; i < argc; i++) {
        int taken = take_common("offset", argc, argv, &i, &common);
        if (taken == 0)
            taken = take_fill("offset", argc, argv, &i, &options.fill);
        if (taken < 0)
            return CLI_USAGE;
        if (taken)
            continue;
        const char *value = NULL;
        if (cli_option_is(argv[i], "--join") || cli_option_is(argv[i], "--end")
            || cli_option_is(argv[i], "--miter-limit")
            || cli_option_is(argv[i], "--arc-tolerance")) {
            const char *option = argv[i];
            value = cli_option_value("clip", argc, argv, &i);
            if (!value)
                return CLI_USAGE;
            if (cli_option_is(option, "--join")) {
                int k = pick_name(value, joins, 4);
                if (k < 0)
                    return cli_usage_error("clip",
                                           "offset: --join: expected miter, round, square "
                                           "or bevel, got '%s'",
                                           value);
                options.join = (cg_offset_join)k;
            } else if (cli_option_is(option, "--end")) {
                end = pick_name(value, offset_ends, 5);
                if (end < 1)
                    return cli_usage_error("clip",
                                           "offset: --end: expected butt, square, round "
                                           "or joined, got '%s'",
                                           value);
            } else if (cli_option_is(option, "--miter-limit")) {
                if (cli_parse_double("clip", "--miter-limit", value, &options.miter_limit) != 0)
                    return CLI_USAGE;
                if (!(options.miter_limit >= 1 && isfinite(options.miter_limit)))
                    return cli_usage_error("clip",
                                           "offset: --miter-limit: expected a number "
                                           ">= 1, got '%s'",
                                           value);
            } else {
                if (cli_parse_double("clip", "--arc-tolerance", value, &options.arc_tolerance) != 0)
                    return CLI_USAGE;
                if (!(options.arc_tolerance > 0 && isfinite(options.arc_tolerance)))
                    return cli_usage_error("clip",
                                           "offset: --arc-tolerance: expected a positive "
                                           "number, got '%s'",
                                           value);
            }
        } else if (take_operand("offset", argv[i], &delta_text, &file) != 0) {
            return CLI_USAGE;
        }
    }
    if (!file)
        return cli_usage_error("clip", "offset: expected DELTA IN");
    double delta;
    if (cli_parse_double("clip", "DELTA", delta_text, &delta) != 0)
        return CLI_USAGE;
    if (!isfinite(delta))
        return cli_usage_error("clip", "DELTA: expected a finite number, got '%s'", delta_text);
    offset_args args = {delta, options, end};
    geometry_job job = {"offset", offset_step, &args, offset_check, 1, 1, 0};
    return run_job(&job, file, &common);
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
    double v[4];
    int count = 0;
    const char *file = NULL;
    common_options common = {0};
    cg_clip_fill fill = CG_CLIP_EVEN_ODD;
    for (int i = 1; i < argc; i++) {
        int taken = take_common("rect", argc, argv, &i, &common);
        if (taken == 0)
            taken = take_fill("rect", argc, argv, &i, &fill);
        if (taken < 0)
            return CLI_USAGE;
        if (taken)
            continue;
        if (count < 4 && !cli_is_option(argv[i])) {
            if (cli_parse_double("clip", names[count], argv[i], &v[count]) != 0)
                return CLI_USAGE;
            if (!isfinite(v[count]))
                return cli_usage_error("clip", "%s: expected a finite number, got '%s'",
                                       names[count], argv[i]);
            count++;
        } else if (take_operand("rect", argv[i], NULL, &file) != 0) {
            return CLI_USAGE;
        }
    }
    if (!file)
        return cli_usage_error("clip", "rect: expected XMIN YMIN XMAX YMAX IN");
    if (v[0] > v[2] || v[1] > v[3])
        return cli_usage_error("clip", "rect: the rectangle needs XMIN <= XMAX and YMIN <= YMAX");
    rect_args args = {{v[0], v[1], v[2], v[3]}, fill};
    geometry_job job = {"rect", rect_step, &args, NULL, 0, 1, 1};
    return run_job(&job, file, &common);
}

static cg_status triangulate_step(const void *args, cg_clip_workspace *ws,
                                  const cg_polygon_set *input, int open, cg_polygon_set *result)
{
    (void)open;
    return cg_triangulate_ws(ws, input, *(const cg_clip_fill *)args, 0, result);
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
    const char *file = NULL;
    common_options common = {0};
    cg_clip_fill fill = CG_CLIP_EVEN_ODD;
    for (int i = 1; i < argc; i++) {
        int taken = take_common("triangulate", argc, argv, &i, &common);
        if (taken == 0)
            taken = take_fill("triangulate", argc, argv, &i, &fill);
        if (taken < 0)
            return CLI_USAGE;
        if (taken)
            continue;
        if (take_operand("triangulate", argv[i], NULL, &file) != 0)
            return CLI_USAGE;
    }
    if (!file)
        return cli_usage_error("clip", "triangulate: expected IN");
    geometry_job job = {"triangulate", triangulate_step, &fill, triangulate_check, 1, 1, 0};
    return run_job(&job, file, &common);
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
    const char *file = NULL, *tolerance_text = NULL;
    common_options common = {0};
    cg_clip_fill fill = CG_CLIP_EVEN_ODD;
    cg_simplify_algorithm algorithm = CG_SIMPLIFY_RDP;
    for (int i = 1; i < argc; i++) {
        int taken = take_common("simplify", argc, argv, &i, &common);
        if (taken == 0)
            taken = take_fill("simplify", argc, argv, &i, &fill);
        if (taken < 0)
            return CLI_USAGE;
        if (taken)
            continue;
        if (cli_option_is(argv[i], "--algorithm")) {
            const char *a = cli_option_value("clip", argc, argv, &i);
            if (!a)
                return CLI_USAGE;
            if (strcmp(a, "rdp") == 0)
                algorithm = CG_SIMPLIFY_RDP;
            else if (strcmp(a, "visvalingam") == 0)
                algorithm = CG_SIMPLIFY_VISVALINGAM;
            else
                return cli_usage_error("clip",
                                       "simplify: --algorithm: expected rdp or "
                                       "visvalingam, got '%s'",
                                       a);
        } else if (take_operand("simplify", argv[i], &tolerance_text, &file) != 0) {
            return CLI_USAGE;
        }
    }
    if (!file)
        return cli_usage_error("clip", "simplify: expected TOLERANCE IN");
    double tolerance;
    if (cli_parse_double("clip", "TOLERANCE", tolerance_text, &tolerance) != 0)
        return CLI_USAGE;
    if (!(tolerance >= 0) || isinf(tolerance))
        return cli_usage_error("clip", "TOLERANCE: expected a finite number >= 0, got '%s'",
                               tolerance_text);
    simplify_args args = {fill, algorithm, tolerance};
    geometry_job job = {"simplify", simplify_step, &args, NULL, 0, 0, 1};
    return run_job(&job, file, &common);
}

int clip_geometry_handles(const char *name)
{
    return strcmp(name, "offset") == 0 || strcmp(name, "rect") == 0
           || strcmp(name, "triangulate") == 0 || strcmp(name, "simplify") == 0;
}

int clip_geometry_run(int argc, char **argv)
{
    if (strcmp(argv[0], "offset") == 0)
        return offset(argc, argv);
    if (strcmp(argv[0], "rect") == 0)
        return rect(argc, argv);
    if (strcmp(argv[0], "triangulate") == 0)
        return triangulate(argc, argv);
    if (strcmp(argv[0], "simplify") == 0)
        return simplify(argc, argv);
    return cli_usage_error("clip", "unknown clip command '%s'", argv[0]);
}
