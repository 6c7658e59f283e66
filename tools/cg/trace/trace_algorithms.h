/* The algorithms of `cg trace`, one table per chapter group (trace_*.c);
 * cmd_trace.c looks the name up in each. */
#ifndef CG_TOOL_TRACE_ALGORITHMS_H
#define CG_TOOL_TRACE_ALGORITHMS_H

#include "trace_output.h"

#include "cg/hemesh.h"
#include "cg/mesh.h"
#include "cg/xform.h"
#include "cg/clip.h"

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
extern const trace_algorithm trace_surfaces_algorithms[];
extern const trace_algorithm trace_shading_algorithms[];
extern const trace_algorithm trace_mesh_ops_algorithms[];

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

/* Loads the mesh at path, turns it about_y then about_x degrees and frames
 * it with the default camera for the aspect, as cg render does; CLI_OK, or
 * CLI_FAILED after a message (nothing to free then). */
int trace_frame_mesh(const char *path, double about_y, double about_x, double aspect,
                     cg_mesh **mesh, cg_mat4 *model, cg_camera *camera);
/* MESH [ABOUT_Y [ABOUT_X]] (argv[0] the algorithm; 30 and 20 degrees by
 * default) loaded and framed by trace_frame_mesh: CLI_OK, or CLI_USAGE or
 * CLI_FAILED after a message. */
int trace_turned_mesh(int argc, char **argv, double aspect, double *about_y, double *about_x,
                      cg_mesh **mesh, cg_mat4 *model, cg_camera *camera);
/* The half-edge structure of the mesh file (strict: a defect is an error,
 * named); CLI_OK or CLI_FAILED after a message. */
int trace_load_hemesh(const char *path, cg_hemesh **out);
/* The same for another command (`cg check` reads the arguments of the
 * traces): messages start "cg: COMMAND: ". */
int trace_parse_point_for(const char *command, const char *what, const char *text, cg_vec2 *out);
int trace_parse_polygon_for(const char *command, const char *what, const char *text,
                            cg_vec2 *points, int capacity);
/* The polygon of `scanline` (algorithm `name` in messages): contours
 * "X,Y X,Y ...; X,Y ..." of at least 3 points each, at most capacity points
 * and max_contours contours: CLI_OK, or CLI_USAGE after a message. */
int trace_parse_contours(const char *command, const char *name, const char *text, cg_vec2 *points,
                         int capacity, int *sizes, int max_contours, int *contour_count);
/* The arguments of the line clippers, NAME XMIN YMIN XMAX YMAX X0,Y0 X1,Y1
 * (argv[0] is NAME): CLI_OK, or CLI_USAGE after a message. */
int trace_parse_window_segment(const char *command, const char *name, int argc, char **argv,
                               cg_rect *window, cg_vec2 *p0, cg_vec2 *p1);

#endif
