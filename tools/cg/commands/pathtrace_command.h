/* `cg render MESH --algorithm pathtrace ...`: the path tracer's command line
 * (render_command.c hands it over when --algorithm pathtrace is given). */
#ifndef CG_TOOL_PATHTRACE_COMMAND_H
#define CG_TOOL_PATHTRACE_COMMAND_H

#include "options.h"

/* Runs the path tracer's command line; returns an exit status. */
int pathtrace_command_run(const char *command, int argc, char **argv);
/* True when argv asks for --algorithm pathtrace. */
int pathtrace_requested(int argc, char **argv);

extern const cli_syntax pathtrace_syntax;

#endif
