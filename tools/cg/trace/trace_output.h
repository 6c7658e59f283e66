/* The outputs every `cg trace` algorithm shares: a recorded trace (the
 * library's cg_step_log plus the notes printed above it) written as a table,
 * as JSON (docs/teaching.md gives the schema), as one PNG per step, and as a
 * self-contained HTML page that steps through those pictures. */
#ifndef CG_TOOL_TRACE_OUTPUT_H
#define CG_TOOL_TRACE_OUTPUT_H

#include "options.h"
#include "cg/core.h"
#include "cg/image.h"
#include "cg/trace_steps.h"

enum { TRACE_MAX_NOTES = 24, TRACE_MAX_SCENE = 2, TRACE_MAX_FRAMES = 2000 };

/* Geometry drawn in every frame (the clip window, the subject polygon, the
 * control polygon). */
typedef struct trace_scene_path {
    cg_vec2 *points;
    int count;
    int closed;
} trace_scene_path;

typedef struct trace_run {
    const char *algorithm; /* the subcommand: "line", "liang-barsky" */
    int argc;              /* its arguments, for JSON and the page */
    char **argv;
    char *title;
    char *notes[TRACE_MAX_NOTES];
    int note_count;
    char *summary; /* the closing line, or NULL */
    cg_step_log *log;
    int y_up; /* geometry is y-up (clipping), not image rows */
    trace_scene_path scene[TRACE_MAX_SCENE];
    int scene_count;
    cg_image *background; /* the image a fill works on, owned (or NULL) */
} trace_run;

/* Where a trace goes: the table (default) or JSON on stdout, and the
 * frames and the page when asked. */
typedef struct trace_outputs {
    int json;
    const char *frames_dir;
    const char *html;
} trace_outputs;

/* The options every algorithm takes (options.h), anywhere on the line. */
extern const cli_syntax trace_output_syntax;

/* Parses --json, --frames DIR and --html OUT out of argv[1..argc) and
 * leaves the other arguments, in order, in argv[1..*argc); 0, or -1 after
 * printing an error. */
int trace_outputs_parse(int *argc, char **argv, trace_outputs *out);

/* A run with an empty log; the title as printf.  NULL when out of memory. */
trace_run *trace_run_create(const char *algorithm, int argc, char **argv, const char *title, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
void trace_run_free(trace_run *run);
void trace_note(trace_run *run, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void trace_summary(trace_run *run, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* Copies count points as scene geometry. */
void trace_scene_add(trace_run *run, const cg_vec2 *points, int count, int closed);

/* The pixels of every step, one "x y" pair per pixel (for summaries). */
long trace_pixel_total(const trace_run *run);

/* Checks the library's status (a usage error for CG_EINVAL/CG_ERANGE with
 * what, a failure otherwise), then writes the outputs asked for, and frees
 * the run; the exit status. */
int trace_finish(trace_run *run, cg_status status, const char *what, const trace_outputs *out);

/* A field as the table shows it ("-" for no value), cut at size. */
void trace_field_text(const cg_step_field *f, char *out, size_t size);

/* Printing (trace_output.c) and pictures (trace_frames.c). */
void trace_print_table(const trace_run *run);
void trace_print_json(const trace_run *run);
int trace_write_frames(const trace_run *run, const char *dir, int *frame_count);
int trace_write_html(const trace_run *run, const char *frames_dir, int frame_count,
                     const char *path);

#endif
