/* Helpers shared by the cg subcommands: argument parsing, messages, timing. */
#ifndef CG_TOOL_CLI_H
#define CG_TOOL_CLI_H

#include "cg/core.h"
#include "cg/image.h"

/* Exit statuses. */
enum { CLI_OK = 0, CLI_FAILED = 1, CLI_USAGE = 2 };

/* Prints "cg: <message>" and a newline to stderr; returns CLI_FAILED. */
int cli_fail(const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* Prints a loader's notes (cg_mesh.notes: one line each) to stderr as
 * "cg: note: ..." lines; nothing for NULL. */
void cli_print_notes(const char *notes);
/* The same, returning CLI_USAGE, and pointing at `cg help COMMAND`. */
int cli_usage_error(const char *command, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* True for "-x" and "--xyz" but not for "-" or negative numbers like "-3.5". */
int cli_is_option(const char *arg);

/* Takes the value of option argv[*i] (either "--name=value" or the next
 * argument) and advances *i.  NULL, with a message printed, when missing. */
const char *cli_option_value(const char *command, int argc, char **argv, int *i);
/* True when argv[i] is the option name (exactly, or as "name=..."). */
int cli_option_is(const char *arg, const char *name);

/* Strict number parsing: the whole text must be a number in range.
 * Each returns 0 on success, otherwise prints "cg: COMMAND: WHAT: ..." and
 * returns -1. */
int cli_parse_long(const char *command, const char *what, const char *text, long min, long max,
                   long *out);
int cli_parse_double(const char *command, const char *what, const char *text, double *out);
/* "WxH" with both in 1..CG_IMAGE_MAX_SIDE. */
int cli_parse_size(const char *command, const char *what, const char *text, int *width,
                   int *height);
/* "X,Y,Z" of finite numbers. */
int cli_parse_vec3(const char *command, const char *what, const char *text, cg_vec3 *out);
/* A colour: #rrggbb, #rrggbbaa or a name. */
int cli_parse_color(const char *command, const char *what, const char *text, cg_rgba8 *out);

/* Writes the image to path in the format of its extension; prints the error. */
int cli_write_image(const cg_image *image, const char *path);

/* Monotonic clock in seconds, and the median of n samples (sorted in place). */
double cli_now(void);
double cli_median(double *samples, int n);

#endif
