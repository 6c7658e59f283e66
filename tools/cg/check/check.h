/* `cg check ALGORITHM ARGS < OUTPUT`: a student's result checked against the
 * algorithm's definition and against cg's own result (cmd_check.c
 * dispatches; one check_<group>.c per group of algorithms).
 *
 * The verdict goes to standard output: "right: ..." (exit 0) or "wrong: ..."
 * (exit 1) naming the first wrong pixel or point, then "note: ..." lines.
 * Usage and input errors are one line "cg: check: ..." on stderr (exit 2). */
#ifndef CG_TOOL_CHECK_H
#define CG_TOOL_CHECK_H

#include "../../../src/core/array.h"
#include "../../../src/core/sort.h"
#include "cg/core.h"

#include <stdio.h>

/* One pixel of the input and the line it was read from. */
typedef struct check_pixel {
    long long x, y;
    long line;
} check_pixel;
typedef CORE_ARRAY(check_pixel) check_pixels;

/* One point of the input (the clippers' coordinates). */
typedef struct check_point {
    cg_vec2 p;
    long line;
} check_point;
typedef CORE_ARRAY(check_point) check_points;

/* The options of every algorithm. */
typedef struct check_options {
    double tolerance; /* how far a point may be from the right one (--tolerance) */
} check_options;

typedef struct check_algorithm {
    const char *name;      /* as typed after `cg check` */
    const char *arguments; /* "X1 Y1 X2 Y2" */
    /* argv[0] is the name; in is the student's output; the exit status. */
    int (*run)(int argc, char **argv, FILE *in, const check_options *options);
} check_algorithm;

/* Each table ends with a {NULL} entry. */
extern const check_algorithm check_line_algorithms[];
extern const check_algorithm check_circle_algorithms[];
extern const check_algorithm check_fill_algorithms[];
extern const check_algorithm check_clip_algorithms[];

/* Reads "X Y" pairs, one a line (blank lines and # comments skipped; "X,Y"
 * and "(X, Y)" accepted too).  Pixels are whole numbers within +-2^31.
 * CLI_OK, CLI_USAGE after a message naming the line, CLI_FAILED when memory
 * runs out. */
int check_read_pixels(FILE *in, check_pixels *out);
int check_read_points(FILE *in, check_points *out);

/* The pixels sorted by (y, x), then line: a sorted copy (free()), NULL when
 * memory runs out or count is 0. */
check_pixel *check_sorted(const check_pixels *pixels);
/* Index of (x, y) in a sorted array, or -1. */
long check_find(const check_pixel *sorted, size_t count, long long x, long long y);
/* The first pixel (by its line) listed twice: the index in sorted of the
 * second listing, or -1 when no pixel repeats. */
long check_first_repeat(const check_pixel *sorted, size_t count);

/* The verdict: prints "right: ..." and returns 0; "wrong: ..." and returns 1. */
int check_right(const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
int check_wrong(const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* "note: ..." after the verdict. */
void check_note(const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* Reads the pixels as a set: CLI_OK with *sorted (by (y, x); free(), NULL
 * when there is none) and *count; else the status after the message or the
 * verdict "wrong: pixel ... is listed twice", what naming the algorithm. */
int check_read_set(FILE *in, const char *what, check_pixel **sorted, size_t *count);

/* "wrong: pixel (x, y) is listed twice (lines a and b); ..." for the repeat
 * at index r of sorted (check_first_repeat), naming what the algorithm
 * draws once. */
int check_wrong_repeat(const check_pixel *sorted, long r, const char *what);

/* A distance p/q (q > 0) as "p/q = 0.62" (reduced), or "2" when whole. */
void check_fraction(char *text, size_t size, long long p, long long q);

#endif
