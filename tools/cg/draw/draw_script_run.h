/* Loading and running whole `cg draw` scripts (used by cmd_draw.c and the
 * gallery). */
#ifndef CG_TOOL_DRAW_SCRIPT_RUN_H
#define CG_TOOL_DRAW_SCRIPT_RUN_H

#include "draw_script.h"

typedef struct draw_line {
    int number;
    int argc;
    char **argv; /* words of the line, pointing into the script's text */
    const draw_command *command;
} draw_line;

typedef struct draw_script {
    const char *file;
    /* NULL for a script file; "overlays" when the lines are the items of that
     * array of a scene file: messages then say "FILE: overlays[I]: ..." */
    const char *json_array;
    char *text;
    draw_line *lines;
    int count;
} draw_script;

/* Reads and tokenises a script ("-" for stdin); unknown commands are
 * reported here.  Returns 0, or prints the error and returns 1. */
int draw_script_load(const char *path, draw_script *script);
/* The same from a NUL-terminated text; name is used in messages. */
int draw_script_parse(const char *name, const char *text, draw_script *script);
/* The same for the items of a JSON array of strings, one a line (the scene
 * file's "overlays"): messages name the file, the array and the item. */
int draw_script_parse_array(const char *name, const char *array, const char *text,
                            draw_script *script);
void draw_script_free(draw_script *script);

/* Runs every command on a fresh state (defaults: white background, black,
 * tolerance 0.25, aliased curves).  Returns 0, or 1 after printing the
 * error.  The caller releases the canvas with draw_state_release. */
int draw_script_run(const draw_script *script, draw_state *state);
void draw_state_release(draw_state *state);

/* Runs the commands on an existing canvas (which stays the caller's), as
 * overlays on a rendered picture; `size` is an error there, since the canvas
 * is already set.  Returns 0, or 1 after printing the error. */
int draw_script_run_on(const draw_script *script, cg_image *canvas);

#endif
