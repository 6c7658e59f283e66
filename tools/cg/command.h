/* One subcommand of the cg tool.  Each tools/cg/cmd_<name>.c defines
 * `const cg_command cg_command_<name>`; the build lists them by file name
 * (cmake/registry.cmake), so adding a subcommand touches no shared file. */
#ifndef CG_TOOL_COMMAND_H
#define CG_TOOL_COMMAND_H

#include "options.h"

typedef struct cg_command {
    const char *name;    /* as typed: "convert", "trace-render" */
    const char *summary; /* one line for `cg --help` */
    const char *usage;   /* the full text for `cg help NAME` */
    /* argv[0] is the subcommand name.  Returns the process exit status:
     * 0 success, 1 failure, 2 bad usage. */
    int (*run)(int argc, char **argv);
    /* The command lines run parses (options.h), NULL-terminated: `cg help
     * NAME` lists their options after usage.  NULL for none. */
    const cli_syntax *const *syntaxes;
} cg_command;

#endif
