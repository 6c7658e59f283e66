/* Argument parsing shared by the `cg trace` algorithms. */
#include "trace_algorithms.h"

#include "cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int trace_parse_int(const char *what, const char *text, long min, long max, long *out)
{
    return cli_parse_long("trace", what, text, min, max, out);
}

int trace_parse_real(const char *what, const char *text, double *out)
{
    return cli_parse_double("trace", what, text, out);
}

int trace_parse_point(const char *what, const char *text, cg_vec2 *out)
{
    return trace_parse_point_for("trace", what, text, out);
}

int trace_parse_point_for(const char *command, const char *what, const char *text, cg_vec2 *out)
{
    const char *comma = strchr(text, ',');
    if (!comma || comma == text || !comma[1]) {
        cli_usage_error(command, "%s: expected a point X,Y, got '%s'", what, text);
        return -1;
    }
    char x[64];
    size_t n = (size_t)(comma - text);
    if (n >= sizeof x) {
        cli_usage_error(command, "%s: '%s' is not a point X,Y", what, text);
        return -1;
    }
    memcpy(x, text, n);
    x[n] = 0;
    if (cli_parse_double(command, what, x, &out->x)
        || cli_parse_double(command, what, comma + 1, &out->y))
        return -1;
    if (!isfinite(out->x) || !isfinite(out->y)) {
        cli_usage_error(command, "%s: the point '%s' is not finite", what, text);
        return -1;
    }
    return 0;
}

int trace_next_word(const char **at, char *word, size_t size)
{
    const char *p = *at + strspn(*at, " \t");
    size_t n = strcspn(p, " \t");
    *at = p + n;
    if (n == 0)
        return 0;
    if (n >= size)
        return -1;
    memcpy(word, p, n);
    word[n] = 0;
    return 1;
}

/* "X,Y X,Y ..." into points; the count, or -1 after a message. */
int trace_parse_polygon(const char *what, const char *text, cg_vec2 *points, int capacity)
{
    return trace_parse_polygon_for("trace", what, text, points, capacity);
}

int trace_parse_polygon_for(const char *command, const char *what, const char *text,
                            cg_vec2 *points, int capacity)
{
    int count = 0, got;
    char word[128];
    for (const char *at = text; (got = trace_next_word(&at, word, sizeof word)) != 0; count++) {
        if (got < 0 || count >= capacity) {
            cli_usage_error(command, "%s: at most %d points of at most %zu characters", what,
                            capacity, sizeof word - 1);
            return -1;
        }
        if (trace_parse_point_for(command, what, word, &points[count]))
            return -1;
    }
    return count;
}

int trace_parse_contours(const char *command, const char *name, const char *text, cg_vec2 *points,
                         int capacity, int *sizes, int max_contours, int *contour_count)
{
    char part[4096];
    int total = 0, count = 0;
    const char *at = text;
    for (;;) {
        size_t n = strcspn(at, ";");
        if (n >= sizeof part || count >= max_contours)
            return cli_usage_error(command, "%s: at most %d contours of at most %zu characters",
                                   name, max_contours, sizeof part - 1);
        memcpy(part, at, n);
        part[n] = 0;
        int got = trace_parse_polygon_for(command, "POLYGON", part, points + total,
                                          capacity - total);
        if (got < 0)
            return CLI_USAGE;
        if (got > 0) {
            if (got < 3)
                return cli_usage_error(command, "%s: a contour needs at least 3 points", name);
            sizes[count++] = got;
            total += got;
        }
        if (!at[n])
            break;
        at += n + 1;
    }
    if (count == 0)
        return cli_usage_error(command, "%s: the polygon has no points", name);
    *contour_count = count;
    return CLI_OK;
}

int trace_parse_window_segment(const char *command, const char *name, int argc, char **argv,
                               cg_rect *window, cg_vec2 *p0, cg_vec2 *p1)
{
    double bounds[4];
    static const char *const names[4] = {"XMIN", "YMIN", "XMAX", "YMAX"};
    if (argc != 7)
        return cli_usage_error(command, "%s: expected '%s XMIN YMIN XMAX YMAX X0,Y0 X1,Y1'", name,
                               name);
    for (int i = 0; i < 4; i++)
        if (cli_parse_double(command, names[i], argv[i + 1], &bounds[i]))
            return CLI_USAGE;
    if (trace_parse_point_for(command, "P0", argv[5], p0)
        || trace_parse_point_for(command, "P1", argv[6], p1))
        return CLI_USAGE;
    if (bounds[0] > bounds[2] || bounds[1] > bounds[3])
        return cli_usage_error(command, "%s: the window needs XMIN <= XMAX and YMIN <= YMAX", name);
    *window = (cg_rect){bounds[0], bounds[1], bounds[2], bounds[3]};
    return CLI_OK;
}
