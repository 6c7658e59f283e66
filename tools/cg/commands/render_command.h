/* `cg render` and its alias `cg trace-render`: one command line, three
 * inputs (a mesh file, a scene file, the classic scene) and four algorithms. */
#ifndef CG_TOOL_RENDER_COMMAND_H
#define CG_TOOL_RENDER_COMMAND_H

/* Parses argv (render_request.h) and renders; trace_only for
 * `cg trace-render`, which always ray traces.  Returns the exit status. */
int render_command_run(const char *command, int argc, char **argv, int trace_only);

#endif
