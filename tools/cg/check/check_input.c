/* Reading the student's output for `cg check`, and the verdict lines. */
#include "check.h"

#include "cli.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_LINE = 4096 };

/* The line's text without its comment, separators made blanks; 0 when it is
 * blank, -1 when too long. */
static int clean_line(char *text, FILE *in)
{
    size_t n = strlen(text);
    if (n > 0 && text[n - 1] != '\n' && !feof(in))
        return -1;
    char *hash = strchr(text, '#');
    if (hash)
        *hash = 0;
    int words = 0;
    for (char *c = text; *c; c++) {
        if (*c == ',' || *c == '(' || *c == ')' || *c == '\r' || *c == '\n' || *c == '\t')
            *c = ' ';
        if (*c != ' ')
            words = 1;
    }
    return words;
}

/* The two words of text, or a message. */
static int split_pair(char *text, long line, char **a, char **b)
{
    char original[64];
    snprintf(original, sizeof original, "%s", text + strspn(text, " "));
    for (size_t n = strlen(original); n > 0 && original[n - 1] == ' ';)
        original[--n] = 0;
    char *save = NULL;
    *a = strtok_r(text, " ", &save);
    *b = *a ? strtok_r(NULL, " ", &save) : NULL;
    char *extra = *b ? strtok_r(NULL, " ", &save) : NULL;
    if (!*a || !*b || extra) {
        cli_usage_error("check", "standard input:%ld: expected 'X Y' (two numbers), got '%s'", line,
                        original);
        return -1;
    }
    return 0;
}

static int parse_whole(const char *text, long line, long long *out)
{
    char *end;
    errno = 0;
    long long v = strtoll(text, &end, 10);
    if (end == text || *end || errno == ERANGE || v < -2147483648LL || v > 2147483647LL) {
        cli_usage_error("check",
                        "standard input:%ld: expected a whole number within +-2^31, got '%s'", line,
                        text);
        return -1;
    }
    *out = v;
    return 0;
}

static int parse_real(const char *text, long line, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (end == text || *end || errno == ERANGE || !isfinite(v)) {
        cli_usage_error("check", "standard input:%ld: expected a finite number, got '%s'", line,
                        text);
        return -1;
    }
    *out = v;
    return 0;
}

/* Calls take(user, a, b, line) for each pair of words; CLI_OK or the first
 * failure. */
static int read_pairs(FILE *in, int (*take)(void *user, const char *a, const char *b, long line),
                      void *user)
{
    char text[MAX_LINE];
    long line = 0;
    while (fgets(text, sizeof text, in)) {
        line++;
        int words = clean_line(text, in);
        if (words < 0)
            return cli_usage_error("check", "standard input:%ld: a line of more than %d characters",
                                   line, MAX_LINE - 2);
        if (words == 0)
            continue;
        char *a, *b;
        if (split_pair(text, line, &a, &b))
            return CLI_USAGE;
        int code = take(user, a, b, line);
        if (code != CLI_OK)
            return code;
    }
    if (ferror(in))
        return cli_usage_error("check", "cannot read standard input");
    return CLI_OK;
}

static int take_pixel(void *user, const char *a, const char *b, long line)
{
    check_pixel p = {0, 0, line};
    if (parse_whole(a, line, &p.x) || parse_whole(b, line, &p.y))
        return CLI_USAGE;
    if (core_array_push((check_pixels *)user, p) != CG_OK)
        return cli_fail("check: out of memory");
    return CLI_OK;
}

static int take_point(void *user, const char *a, const char *b, long line)
{
    check_point p = {{0, 0}, line};
    if (parse_real(a, line, &p.p.x) || parse_real(b, line, &p.p.y))
        return CLI_USAGE;
    if (core_array_push((check_points *)user, p) != CG_OK)
        return cli_fail("check: out of memory");
    return CLI_OK;
}

int check_read_pixels(FILE *in, check_pixels *out)
{
    return read_pairs(in, take_pixel, out);
}

int check_read_points(FILE *in, check_points *out)
{
    return read_pairs(in, take_point, out);
}

static int compare_pixels(const void *pa, const void *pb)
{
    const check_pixel *a = pa, *b = pb;
    if (a->y != b->y)
        return a->y < b->y ? -1 : 1;
    if (a->x != b->x)
        return a->x < b->x ? -1 : 1;
    return (a->line > b->line) - (a->line < b->line);
}

check_pixel *check_sorted(const check_pixels *pixels)
{
    if (pixels->count == 0)
        return NULL;
    check_pixel *sorted = malloc(pixels->count * sizeof *sorted);
    if (!sorted)
        return NULL;
    memcpy(sorted, pixels->data, pixels->count * sizeof *sorted);
    core_sort(sorted, pixels->count, sizeof *sorted, compare_pixels);
    return sorted;
}

long check_find(const check_pixel *sorted, size_t count, long long x, long long y)
{
    size_t lo = 0, hi = count;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const check_pixel *p = &sorted[mid];
        if (p->y < y || (p->y == y && p->x < x))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < count && sorted[lo].x == x && sorted[lo].y == y ? (long)lo : -1;
}

long check_first_repeat(const check_pixel *sorted, size_t count)
{
    long best = -1;
    for (size_t i = 1; i < count; i++)
        if (sorted[i].x == sorted[i - 1].x && sorted[i].y == sorted[i - 1].y
            && (best < 0 || sorted[i].line < sorted[best].line))
            best = (long)i;
    return best;
}

static void verdict(const char *word, const char *format, va_list args)
{
    fputs(word, stdout);
    vprintf(format, args);
    putchar('\n');
}

int check_right(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    verdict("right: ", format, args);
    va_end(args);
    return CLI_OK;
}

int check_wrong(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    verdict("wrong: ", format, args);
    va_end(args);
    return CLI_FAILED;
}

void check_note(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    verdict("note: ", format, args);
    va_end(args);
}

int check_wrong_repeat(const check_pixel *sorted, long r, const char *what)
{
    long first = r;
    while (first > 0 && sorted[first - 1].x == sorted[r].x && sorted[first - 1].y == sorted[r].y)
        first--;
    return check_wrong("pixel (%lld, %lld) is listed twice (lines %ld and %ld); %s sets each "
                       "pixel once",
                       sorted[r].x, sorted[r].y, sorted[first].line, sorted[r].line, what);
}

static long long gcd(long long a, long long b)
{
    while (b) {
        long long t = a % b;
        a = b;
        b = t;
    }
    return a;
}

void check_fraction(char *text, size_t size, long long p, long long q)
{
    long long g = gcd(p < 0 ? -p : p, q);
    if (g > 1) {
        p /= g;
        q /= g;
    }
    if (q == 1)
        snprintf(text, size, "%lld", p);
    else
        snprintf(text, size, "%lld/%lld = %.2f", p, q, (double)p / (double)q);
}

int check_read_set(FILE *in, const char *what, check_pixel **sorted, size_t *count)
{
    check_pixels pixels = {0};
    *sorted = NULL;
    *count = 0;
    int code = check_read_pixels(in, &pixels);
    if (code == CLI_OK && pixels.count) {
        *sorted = check_sorted(&pixels);
        if (!*sorted)
            code = cli_fail("check: out of memory");
    }
    if (code == CLI_OK) {
        long repeat = check_first_repeat(*sorted, pixels.count);
        if (repeat >= 0)
            code = check_wrong_repeat(*sorted, repeat, what);
    }
    *count = pixels.count;
    core_array_free(&pixels);
    if (code != CLI_OK) {
        free(*sorted);
        *sorted = NULL;
    }
    return code;
}
