/* The interpreter of `cg draw` scripts (docs/draw-script.md).
 *
 * A script is plain text, one command a line: the command's name and its
 * arguments separated by blanks; `#` starts a comment.  The interpreter reads
 * the whole script first (tokenising each line once), then runs the commands
 * in order on a draw_state; with --repeat N it runs them N times, each time
 * from a fresh state.
 *
 * Commands come in groups, one file each: tools/cg/draw/drawcmds_<group>.c defines
 *     const draw_command_table draw_commands_<group> = {"group", list, count};
 * and the build lists every such file (cmake/registry.cmake, macro
 * DRAW_COMMANDS), so a new group touches no shared file.  A command's run
 * function checks and converts its arguments with the draw_arg_* helpers
 * below (which print "FILE:LINE: ..." on failure) and draws on the canvas.
 * Every field a command group needs lives in draw_state, in this header. */
#ifndef CG_TOOL_DRAW_SCRIPT_H
#define CG_TOOL_DRAW_SCRIPT_H

#include "cg/core.h"
#include "cg/image.h"

struct draw_line;

typedef struct draw_state {
    /* where we are, for messages */
    const char *file;       /* script name as given ("-" shows as "<stdin>") */
    int line;               /* line number of the command being run */
    const char *json_array; /* non-NULL: the lines are this array of a JSON file */

    /* the canvas: NULL until `size W H` */
    cg_image *canvas;
    cg_rgba8 background; /* default white; `background` fills the canvas */

    /* drawing attributes */
    cg_rgba8 color;   /* default black */
    double tolerance; /* flattening tolerance in pixels, default 0.25 */
    int antialias;    /* curves drawn with anti-aliased lines (`antialias on`) */

    /* The script's lines after the running command.  A command that takes
     * the lines continuing it (polygon and its contour lines) reads them here
     * and sets `consumed` to how many of them it ran; the interpreter skips
     * those.  next_count is 0 when no line follows. */
    const struct draw_line *next_lines;
    int next_count;
    int consumed;

    /* filling (tools/cg/drawcmds_fill.c) */
    int fill_rule;     /* cg_fill_rule of polygon, aapolygon, fill; default non-zero */
    double line_width; /* `width W` of stroke, default 1 */
    int line_join;     /* cg_line_join, default miter */
    int line_cap;      /* cg_line_cap, default butt */
    double dashes[32]; /* `dash ON OFF ...`, dash_count 0: solid */
    int dash_count;
    struct draw_fill *fill; /* polygon being built, current path, scratch */

    /* text (tools/cg/drawcmds_text.c): the font, its size, alignment,
     * baseline, wrapping width and line spacing */
    struct draw_text *text;
} draw_state;

/* Releases state->fill (drawcmds_fill.c); called by draw_state_release. */
void draw_fill_release(draw_state *state);
/* Releases state->text (drawcmds_text.c); called by draw_state_release. */
void draw_text_release(draw_state *state);
/* The rasterizer of the fill commands, with the script's compositing and
 * tolerance: what `fill` fills with (NULL when out of memory). */
struct cg_rasterizer *draw_fill_rasterizer(draw_state *state);

/* A command: run returns 0 on success, non-zero after printing an error
 * (with draw_error).  argv[0] is the command name, argc counts it. */
typedef struct draw_command {
    const char *name;
    const char *usage; /* "line X0 Y0 X1 Y1": shown when arguments are wrong */
    int (*run)(draw_state *state, int argc, char **argv);
} draw_command;

typedef struct draw_command_table {
    const char *group;
    const draw_command *commands;
    int count;
} draw_command_table;

/* Prints "FILE:LINE: message" on stderr and returns 1. */
int draw_error(const draw_state *state, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Argument helpers: each returns 0, or prints an error naming the line and
 * what was expected and returns 1.  `what` names the argument ("X0"). */
/* argc must be exactly n + 1 (min/max: between min + 1 and max + 1). */
int draw_arg_count(const draw_state *state, int argc, char **argv, int n, const char *usage);
/* A whole int in [INT_MIN, INT_MAX]. */
int draw_arg_int(const draw_state *state, const char *text, const char *what, int *out);
/* A finite decimal number. */
int draw_arg_double(const draw_state *state, const char *text, const char *what, double *out);
/* A finite decimal number >= 0. */
int draw_arg_nonnegative(const draw_state *state, const char *text, const char *what, double *out);
/* A colour: #rgb, #rrggbb, #rrggbbaa or a name. */
int draw_arg_color(const draw_state *state, const char *text, cg_rgba8 *out);
/* One word argument (argc must be 2) among words[0 .. count - 1]: *out
 * gets its index; else an error quoting the choices of usage
 * ("fillrule evenodd|nonzero"). */
int draw_arg_keyword(const draw_state *state, int argc, char **argv, const char *usage,
                     const char *const *words, int count, int *out);
/* Points given as X Y pairs from argv[first] to argv[argc - 1]: at least
 * min_points, an even number of numbers.  *out is malloc'ed (caller frees). */
int draw_arg_points(const draw_state *state, int argc, char **argv, int first, int min_points,
                    const char *usage, cg_vec2 **out, int *count);
/* The n points of the 2n words (X0 Y0 X1 Y1 ...) into out[0..n-1], each
 * number as draw_arg_double reads it (errors name it "X3", "Y3"). */
int draw_arg_point_pairs(const draw_state *state, char **words, int n, cg_vec2 *out);

/* The canvas, or an error "expected 'size W H' before drawing" (NULL). */
cg_image *draw_canvas(const draw_state *state);

/* Reports a library failure of a drawing call: 0 for CG_OK, else an error
 * naming the status. */
int draw_check(const draw_state *state, cg_status status);

#endif
