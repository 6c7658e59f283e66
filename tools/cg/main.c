/* The cg command: dispatches to one subcommand per tools/cg/cmd_<name>.c. */
#include "cg/core.h"
#include "cli.h"
#include "command.h"

#include <stdio.h>
#include <string.h>

#define CG_COMMAND(name) extern const cg_command cg_command_##name;
#include "commands.inc"
#undef CG_COMMAND

static const cg_command *const commands[] = {
#define CG_COMMAND(name) &cg_command_##name,
#include "commands.inc"
#undef CG_COMMAND
};
static const size_t command_count = sizeof commands / sizeof commands[0];

static const cg_command *find_command(const char *name)
{
    for (size_t i = 0; i < command_count; i++)
        if (strcmp(commands[i]->name, name) == 0)
            return commands[i];
    return NULL;
}

static void print_overview(FILE *out)
{
    fprintf(out, "usage: cg COMMAND [ARGS...]\n"
                 "       cg help COMMAND | cg --help | cg --version\n\n"
                 "cg is the command-line face of libcg, a library of the classical\n"
                 "computer-graphics algorithms.  Commands:\n\n");
    for (size_t i = 0; i < command_count; i++)
        fprintf(out, "  %-14s %s\n", commands[i]->name, commands[i]->summary);
    fprintf(out, "\nRun 'cg help COMMAND' for the options of one command.\n");
}

/* The command's usage text, then its options from its tables. */
static void print_help(const cg_command *command)
{
    printf("%s", command->usage);
    cli_print_options(stdout, command->syntaxes);
}

static int help(int argc, char **argv)
{
    if (argc < 3) {
        print_overview(stdout);
        return CLI_OK;
    }
    const cg_command *command = find_command(argv[2]);
    if (!command) { /* bad usage, as `cg bogus` is: the same status */
        cli_fail("help: unknown command '%s' (run 'cg --help' for the list)", argv[2]);
        return CLI_USAGE;
    }
    print_help(command);
    return CLI_OK;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        print_overview(stderr);
        return CLI_USAGE;
    }
    const char *name = argv[1];
    if (strcmp(name, "--help") == 0 || strcmp(name, "-h") == 0 || strcmp(name, "help") == 0)
        return help(argc, argv);
    if (strcmp(name, "--version") == 0) {
        printf("cg %s\n", CG_VERSION_STRING);
        return CLI_OK;
    }
    const cg_command *command = find_command(name);
    if (!command) {
        fprintf(stderr, "cg: unknown command '%s' (run 'cg --help' for the list)\n", name);
        return CLI_USAGE;
    }
    /* `cg COMMAND --help` is the same as `cg help COMMAND`. */
    for (int i = 2; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            print_help(command);
            return CLI_OK;
        }
    }
    return command->run(argc - 1, argv + 1);
}
