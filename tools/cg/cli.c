/* Helpers shared by the cg subcommands. */
#include "cli.h"
#include "cg/color.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

int cli_fail(const char *format, ...)
{
    va_list args;
    fputs("cg: ", stderr);
    va_start(args, format);
    vfprintf(stderr, format, args);
    va_end(args);
    fputc('\n', stderr);
    return CLI_FAILED;
}

void cli_print_notes(const char *notes)
{
    while (notes && *notes) {
        const char *end = strchr(notes, '\n');
        size_t n = end ? (size_t)(end - notes) : strlen(notes);
        fprintf(stderr, "cg: note: %.*s\n", (int)n, notes);
        notes += n + (end != NULL);
    }
}

int cli_usage_error(const char *command, const char *format, ...)
{
    va_list args;
    fprintf(stderr, "cg: %s: ", command);
    va_start(args, format);
    vfprintf(stderr, format, args);
    va_end(args);
    fprintf(stderr, " (see 'cg help %s')\n", command);
    return CLI_USAGE;
}

int cli_is_option(const char *arg)
{
    if (arg[0] != '-' || arg[1] == '\0')
        return 0;
    return !(arg[1] == '.' || (arg[1] >= '0' && arg[1] <= '9'));
}

int cli_option_is(const char *arg, const char *name)
{
    size_t n = strlen(name);
    return strncmp(arg, name, n) == 0 && (arg[n] == '\0' || arg[n] == '=');
}

const char *cli_option_value(const char *command, int argc, char **argv, int *i)
{
    const char *equals = strchr(argv[*i], '=');
    if (equals && argv[*i][1] == '-')
        return equals + 1;
    if (*i + 1 >= argc) {
        cli_usage_error(command, "option %s needs a value", argv[*i]);
        return NULL;
    }
    *i += 1;
    return argv[*i];
}

int cli_parse_long(const char *command, const char *what, const char *text, long min, long max,
                   long *out)
{
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE || v < min || v > max) {
        cli_usage_error(command, "%s: expected a whole number from %ld to %ld, got '%s'", what, min,
                        max, text);
        return -1;
    }
    *out = v;
    return 0;
}

int cli_parse_double(const char *command, const char *what, const char *text, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (end == text || *end != '\0' || errno == ERANGE || !isfinite(v)) {
        cli_usage_error(command, "%s: expected a finite number, got '%s'", what, text);
        return -1;
    }
    *out = v;
    return 0;
}

int cli_parse_size(const char *command, const char *what, const char *text, int *width, int *height)
{
    char *end;
    errno = 0;
    long w = strtol(text, &end, 10), h = 0;
    int ok = end != text && (*end == 'x' || *end == 'X');
    if (ok) {
        const char *rest = end + 1;
        h = strtol(rest, &end, 10);
        ok = end != rest && *end == '\0' && errno == 0;
    }
    if (!ok || w < 1 || h < 1 || w > CG_IMAGE_MAX_SIDE || h > CG_IMAGE_MAX_SIDE
        || (size_t)w * (size_t)h > CG_IMAGE_MAX_PIXELS) {
        cli_usage_error(command,
                        "%s: expected WIDTHxHEIGHT, each from 1 to %d, at most %zu pixels in all, "
                        "got '%s'",
                        what, CG_IMAGE_MAX_SIDE, CG_IMAGE_MAX_PIXELS, text);
        return -1;
    }
    *width = (int)w;
    *height = (int)h;
    return 0;
}

int cli_parse_vec3(const char *command, const char *what, const char *text, cg_vec3 *out)
{
    double v[3];
    const char *p = text;
    for (int k = 0; k < 3; k++) {
        char *end;
        errno = 0;
        v[k] = strtod(p, &end);
        int separator_ok = k < 2 ? *end == ',' : *end == '\0';
        if (end == p || !separator_ok || errno == ERANGE || !isfinite(v[k])) {
            cli_usage_error(command, "%s: expected X,Y,Z (three finite numbers), got '%s'", what,
                            text);
            return -1;
        }
        p = end + 1;
    }
    *out = cg_vec3_make(v[0], v[1], v[2]);
    return 0;
}

int cli_parse_color(const char *command, const char *what, const char *text, cg_rgba8 *out)
{
    cg_error err;
    if (cg_color_parse(text, out, &err) != CG_OK) {
        cli_usage_error(command, "%s: %s", what, err.message);
        return -1;
    }
    return 0;
}

int cli_write_image(const cg_image *image, const char *path)
{
    cg_error err;
    if (cg_image_write(image, path, CG_FILE_UNKNOWN, &err) != CG_OK)
        return cli_fail("%s", err.message);
    return CLI_OK;
}

double cli_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double cli_median(double *samples, int n)
{
    if (n <= 0)
        return 0;
    qsort(samples, (size_t)n, sizeof *samples, compare_doubles);
    return n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
}
