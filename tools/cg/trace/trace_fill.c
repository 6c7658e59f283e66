/* `cg trace` for chapter 10: scan-line polygon fill. */
#include "trace_algorithms.h"

#include "cli.h"
#include "cg/fill.h"
#include "cg/image.h"

#include <string.h>

enum { MAX_POINTS = 256, MAX_CONTOURS = 16 };

/* "X,Y X,Y ...; X,Y ..." into contours; CLI_OK or CLI_USAGE. */
static int parse_contours(const char *text, cg_vec2 *points, int *sizes, int *contour_count)
{
    char part[4096];
    int total = 0, count = 0;
    const char *at = text;
    for (;;) {
        size_t n = strcspn(at, ";");
        if (n >= sizeof part || count >= MAX_CONTOURS)
            return cli_usage_error("trace",
                                   "scanline: at most %d contours of at most %zu "
                                   "characters",
                                   MAX_CONTOURS, sizeof part - 1);
        memcpy(part, at, n);
        part[n] = 0;
        int got = trace_parse_polygon("POLYGON", part, points + total, MAX_POINTS - total);
        if (got < 0)
            return CLI_USAGE;
        if (got > 0) {
            if (got < 3)
                return cli_usage_error("trace", "scanline: a contour needs at least 3 points");
            sizes[count++] = got;
            total += got;
        }
        if (!at[n])
            break;
        at += n + 1;
    }
    if (count == 0)
        return cli_usage_error("trace", "scanline: the polygon has no points");
    *contour_count = count;
    return CLI_OK;
}

static int run_scanline(int argc, char **argv, const trace_outputs *out)
{
    static cg_vec2 points[MAX_POINTS];
    int sizes[MAX_CONTOURS], contours = 0;
    cg_fill_rule rule = CG_FILL_EVEN_ODD;
    if (argc != 2 && argc != 3)
        return cli_usage_error("trace", "scanline: expected 'scanline \"X,Y X,Y X,Y ...\" "
                                        "[even-odd|nonzero]'");
    if (argc == 3) {
        if (strcmp(argv[2], "nonzero") == 0)
            rule = CG_FILL_NONZERO;
        else if (strcmp(argv[2], "even-odd") != 0)
            return cli_usage_error("trace", "scanline: unknown rule '%s' (even-odd or nonzero)",
                                   argv[2]);
    }
    if (parse_contours(argv[1], points, sizes, &contours) != CLI_OK)
        return CLI_USAGE;
    trace_run *run = trace_run_create(
        "scanline", argc - 1, argv + 1, "Scan-line polygon fill, %d contour%s, %s rule", contours,
        contours == 1 ? "" : "s", rule == CG_FILL_NONZERO ? "non-zero" : "even-odd");
    if (!run)
        return cli_fail("trace: out of memory");
    int start = 0;
    for (int c = 0; c < contours && c < TRACE_MAX_SCENE; c++) {
        trace_scene_add(run, points + start, sizes[c], 1);
        start += sizes[c];
    }
    trace_note(run, "pixels are sampled at their centres (x + 0.5, y + 0.5)");
    trace_note(run, "edge table: each non-horizontal edge, active on the rows whose centre y "
                    "has top <= y < bottom (so a vertex on a centre counts once), sorted by "
                    "first row");
    trace_note(run, "each scan-line: drop finished edges, add starting ones, sort the active "
                    "list by crossing x");
    trace_note(run,
               "spans: between crossings where the %s; a span [xl, xr) takes the "
               "pixels ceil(xl - 0.5) .. ceil(xr - 0.5) - 1 (centre x in [xl, xr))",
               rule == CG_FILL_NONZERO ? "winding number is not zero" : "crossing count is odd");
    cg_status status = cg_scanline_fill_steps(points, sizes, contours, rule, cg_step_log_record,
                                              run->log);
    long pixels = trace_pixel_total(run);
    trace_summary(run, "%ld pixel%s filled", pixels, pixels == 1 ? "" : "s");
    return trace_finish(run, status, "coordinates must be finite and within 4096", out);
}

/* flood IMAGE X Y [4|8] [TOLERANCE], boundary IMAGE X Y COLOR [4|8] [TOLERANCE] */
static int run_seed_fill(int boundary, int argc, char **argv, const trace_outputs *out)
{
    int fixed = boundary ? 5 : 4;
    long x, y, connectivity = 4, tolerance = 0;
    cg_rgba8 wall = {0, 0, 0, 255};
    if (argc < fixed || argc > fixed + 2)
        return cli_usage_error("trace", boundary ? "boundary: expected 'boundary IMAGE X Y COLOR "
                                                   "[4|8] [TOLERANCE]'"
                                                 : "flood: expected 'flood IMAGE X Y [4|8] "
                                                   "[TOLERANCE]'");
    if (trace_parse_int("X", argv[2], -2147483647L, 2147483647L, &x)
        || trace_parse_int("Y", argv[3], -2147483647L, 2147483647L, &y)
        || (boundary && cli_parse_color("trace", "COLOR", argv[4], &wall))
        || (argc > fixed && trace_parse_int("connectivity", argv[fixed], 4, 8, &connectivity))
        || (argc > fixed + 1 && trace_parse_int("TOLERANCE", argv[fixed + 1], 0, 255, &tolerance)))
        return CLI_USAGE;
    if (connectivity != 4 && connectivity != 8)
        return cli_usage_error("trace", "%s: connectivity is 4 or 8, not %ld", argv[0],
                               connectivity);
    cg_image *read, *image;
    cg_error err;
    if (cg_image_read(argv[1], &read, &err) != CG_OK)
        return cli_fail("trace: %s", err.message);
    cg_status status = cg_image_convert(read, CG_PIXEL_RGBA8, &image);
    cg_image_free(read);
    if (status != CG_OK)
        return cli_fail("trace: %s: %s", argv[1], cg_status_str(status));
    trace_run *run = trace_run_create(argv[0], argc - 1, argv + 1,
                                      "%s fill of %s from (%ld, %ld), %ld-connected",
                                      boundary ? "Boundary" : "Flood", argv[1], x, y, connectivity);
    if (!run) {
        cg_image_free(image);
        return cli_fail("trace: out of memory");
    }
    if (boundary)
        trace_note(run,
                   "the region: pixels not of the boundary colour %s (each channel within "
                   "%ld), connected to the seed",
                   argv[4], tolerance);
    else
        trace_note(run,
                   "the region: pixels like the seed's colour (each channel within %ld), "
                   "connected to the seed",
                   tolerance);
    trace_note(run, "pop a seed; extend it left and right to its whole run [left, right] and "
                    "fill it;");
    trace_note(run,
               "push the rightmost pixel of each run of region pixels next to it on the "
               "rows above and below%s",
               connectivity == 8 ? " (diagonals included)" : "");
    cg_connectivity c = connectivity == 8 ? CG_CONNECT_8 : CG_CONNECT_4;
    status = boundary ? cg_boundary_fill_steps(image, (int)x, (int)y, wall, c, (int)tolerance,
                                               cg_step_log_record, run->log)
                      : cg_flood_fill_steps(image, (int)x, (int)y, c, (int)tolerance,
                                            cg_step_log_record, run->log);
    if (image->width <= 512 && image->height <= 512)
        run->background = image; /* drawn under the frames */
    else
        cg_image_free(image);
    long pixels = trace_pixel_total(run);
    trace_summary(run, "%zu seeds popped; %ld pixel%s filled", cg_step_log_count(run->log), pixels,
                  pixels == 1 ? "" : "s");
    return trace_finish(run, status, "the seed must be inside the image", out);
}

static int run_flood(int argc, char **argv, const trace_outputs *out)
{
    return run_seed_fill(0, argc, argv, out);
}

static int run_boundary(int argc, char **argv, const trace_outputs *out)
{
    return run_seed_fill(1, argc, argv, out);
}

const trace_algorithm trace_fill_algorithms[] = {
    {"scanline", "'POLYGON' [even-odd|nonzero]", run_scanline},
    {"flood", "IMAGE X Y [4|8] [TOLERANCE]", run_flood},
    {"boundary", "IMAGE X Y COLOR [4|8] [TOLERANCE]", run_boundary},
    {NULL, NULL, NULL},
};
