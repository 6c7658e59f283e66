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
    const char *comma = strchr(text, ',');
    if (!comma || comma == text || !comma[1]) {
        cli_usage_error("trace", "%s: expected a point X,Y, got '%s'", what, text);
        return -1;
    }
    char x[64];
    size_t n = (size_t)(comma - text);
    if (n >= sizeof x) {
        cli_usage_error("trace", "%s: '%s' is not a point X,Y", what, text);
        return -1;
    }
    memcpy(x, text, n);
    x[n] = 0;
    if (cli_parse_double("trace", what, x, &out->x)
        || cli_parse_double("trace", what, comma + 1, &out->y))
        return -1;
    if (!isfinite(out->x) || !isfinite(out->y)) {
        cli_usage_error("trace", "%s: the point '%s' is not finite", what, text);
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
    int count = 0, got;
    char word[128];
    for (const char *at = text; (got = trace_next_word(&at, word, sizeof word)) != 0; count++) {
        if (got < 0 || count >= capacity) {
            cli_usage_error("trace", "%s: at most %d points of at most %zu characters", what,
                            capacity, sizeof word - 1);
            return -1;
        }
        if (trace_parse_point(what, word, &points[count]))
            return -1;
    }
    return count;
}
