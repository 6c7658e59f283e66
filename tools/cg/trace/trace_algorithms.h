/* The algorithms of `cg trace`, one table per chapter group (trace_*.c);
 * cmd_trace.c looks the name up in each. */
#ifndef CG_TOOL_TRACE_ALGORITHMS_H
#define CG_TOOL_TRACE_ALGORITHMS_H

#include "trace_output.h"

typedef struct trace_algorithm {
    const char *name;      /* as typed after `cg trace` */
    const char *arguments; /* "X1 Y1 X2 Y2" */
    /* argv[0] is the algorithm's name; returns the exit status. */
    int (*run)(int argc, char **argv, const trace_outputs *out);
} trace_algorithm;

/* Each table ends with a {NULL} entry. */
extern const trace_algorithm trace_chapter2_algorithms[];
extern const trace_algorithm trace_view_algorithms[];
extern const trace_algorithm trace_fill_algorithms[];
extern const trace_algorithm trace_clip_algorithms[];

/* Argument parsing for the algorithms: each prints "cg: trace: ..." and
 * returns -1 on a bad value, 0 when good. */
int trace_parse_int(const char *what, const char *text, long min, long max, long *out);
int trace_parse_real(const char *what, const char *text, double *out);
/* "X,Y" with finite coordinates. */
int trace_parse_point(const char *what, const char *text, cg_vec2 *out);

/* The next word of *at (words are separated by spaces and tabs) into
 * word[0..size): 1 with *at past it, 0 at the end of the text, -1 when the
 * word does not fit. */
int trace_next_word(const char **at, char *word, size_t size);
/* "X,Y X,Y ..." into at most capacity points: the count, or -1 after a
 * message. */
int trace_parse_polygon(const char *what, const char *text, cg_vec2 *points, int capacity);

#endif
