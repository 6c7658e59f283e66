/* The option parser of the cg commands: a command declares its options once,
 * in a table, and one function parses its command line from the table and
 * `cg help COMMAND` lists the same table.
 *
 * A command keeps its arguments in a struct of its own; each option names
 * the member its value goes to by offset, so that the tables are constant
 * and the options every command shares (-o, --size, --threads, --repeat) are
 * declared once, by the CLI_OPTION_* macros at the end:
 *
 *     typedef struct draw_arguments { const char *output; int repeat; } draw_arguments;
 *     static const cli_option draw_options[] = {
 *         CLI_OPTION_OUTPUT(draw_arguments, output, "OUT", "the image to write"),
 *         CLI_OPTION_REPEAT(draw_arguments, repeat, 1000000, "draw N times ..."),
 *     };
 *     static const cli_option_group draw_groups[] = {CLI_GROUP(NULL, draw_options), {0}};
 *     static const cli_syntax draw_syntax = {
 *         .command = "draw", .groups = draw_groups,
 *         .max_positionals = 1, .too_many = "expected one script, got '%s' as a second",
 *         .min_positionals = 1, .too_few = "expected a script FILE",
 *     };
 *     ...
 *     draw_arguments a = {NULL, 1};
 *     const char *input[1];
 *     int count = 0;
 *     if (cli_parse(&draw_syntax, argc, argv, &a, input, &count) != CLI_OK)
 *         return CLI_USAGE;
 *
 * An option is spelled "--name VALUE" or "--name=VALUE" (a one-dash name such
 * as -o takes the next argument); a flag takes no value.  Every error is one
 * line on stderr, "cg: COMMAND: ... (see 'cg help COMMAND')", and the parse
 * stops at the first one. */
#ifndef CG_TOOL_OPTIONS_H
#define CG_TOOL_OPTIONS_H

#include "cli.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>

/* What an option's value is, and the type of the member it goes to. */
typedef enum cli_option_kind {
    CLI_FLAG,         /* no value: flag_value into an int (or an enum) */
    CLI_INT,          /* a whole number in [min, max] into an int */
    CLI_DOUBLE,       /* a finite number into a double; in [low, high] when range_text is set */
    CLI_STRING,       /* the text itself into a const char * */
    CLI_CHOICE,       /* one of choices[], its index into an int (or an enum) */
    CLI_VEC3,         /* X,Y,Z into a cg_vec3 */
    CLI_SIZE,         /* WxH into a cli_size */
    CLI_COLOR,        /* #rrggbb, #rrggbbaa or a name into a cg_rgba8 */
    CLI_LINEAR_COLOR, /* the same, converted to linear light, into a cg_rgbaf */
    CLI_CUSTOM        /* parse() reads the value and stores it */
} cli_option_kind;

/* An image or window size. */
typedef struct cli_size {
    int width, height;
} cli_size;

/* Bits of cli_option.open: the end of the range is excluded. */
enum { CLI_OPEN_LOW = 1, CLI_OPEN_HIGH = 2 };

typedef struct cli_option cli_option;
struct cli_option {
    const char *name;  /* "--size" */
    const char *alias; /* another spelling ("--output" beside "-o"), or NULL */
    cli_option_kind kind;
    size_t offset;          /* the member of the arguments struct the value goes to */
    const char *value_name; /* in the help: "WxH", "N" (a choice lists its choices) */
    const char *help;       /* for `cg help`; '\n' starts another line */
    const char *what;       /* the option in messages when not its name ("subdivision levels") */
    /* A counter in the arguments struct (CLI_GIVEN) raised each time the
     * option is given; 0 for none. */
    size_t given;
    long min, max;              /* CLI_INT: the accepted range */
    double low, high;           /* CLI_DOUBLE with range_text: the accepted range, */
    int open;                   /* with CLI_OPEN_LOW / CLI_OPEN_HIGH ends excluded */
    const char *range_text;     /* "a number >= 0": "WHAT: expected a number >= 0, got 'x'" */
    const char *const *choices; /* CLI_CHOICE: NULL-terminated */
    int flag_value;             /* CLI_FLAG: the value stored */
    /* CLI_CUSTOM: parses text into the arguments struct; 0, or -1 after
     * printing a usage error for command. */
    int (*parse)(const char *command, const cli_option *option, const char *text, void *arguments);
};

/* The options of a command under one heading of its help. */
typedef struct cli_option_group {
    const char *heading; /* "Camera:", or NULL */
    const cli_option *options;
    size_t count;
} cli_option_group;

#define CLI_GROUP(heading, array)                              \
    {                                                          \
        (heading), (array), sizeof(array) / sizeof((array)[0]) \
    }
/* The given counter of an option: an int member of the arguments struct. */
#define CLI_GIVEN(type, member) (offsetof(type, member) + 1)

/* The command line of one command (or one action of it, "clip line"). */
typedef struct cli_syntax {
    const char *command;            /* for messages: "clip" */
    const char *action;             /* "line": messages say "line: unknown option ..."; or NULL */
    const cli_option_group *groups; /* ended by a group with no options */
    /* Positional arguments: up to max_positionals are collected in order;
     * one more is refused with too_many (a format taking the argument). */
    int max_positionals;
    const char *too_many;
    /* Fewer than min_positionals are refused with too_few (a message),
     * once every argument is read. */
    int min_positionals;
    const char *too_few;
    /* Instead, when set: called for each positional argument (index from 0)
     * as it comes; 0, or -1 after printing a usage error. */
    int (*positional)(const char *command, int index, const char *text, void *arguments);
} cli_syntax;

/* Parses argv[1..argc) (argv[0] names the command or action) into
 * arguments, the struct the options' offsets point into, and the positional
 * arguments into positionals[0..*count) (both may be NULL when the syntax
 * takes none or has a positional function).  CLI_OK, or CLI_USAGE after
 * printing one line. */
int cli_parse(const cli_syntax *syntax, int argc, char **argv, void *arguments,
              const char **positionals, int *count);

/* A CLI_DOUBLE's reading, for a CLI_CUSTOM parse that does more with the
 * number: text as a finite number in the option's range (when range_text is
 * set).  0, or -1 after printing the usage error. */
int cli_read_double(const char *command, const cli_option *option, const char *text, double *out);

/* True when the option (a pointer into one of syntax's tables) was given,
 * for an option that has a given counter. */
int cli_given(const cli_option *option, const void *arguments);

/* One action of a command that has several (`cg clip line`): its name and
 * the function that runs it, given argv[0] = the action's name. */
typedef struct cli_action {
    const char *name;
    int (*run)(int argc, char **argv);
} cli_action;

/* Runs the action argv[1] names with argv[1..argc), and returns its exit
 * status; with no action, the usage error missing, and with another name the
 * usage error unknown (a format taking the name).  NULL for either gives
 * "expected A, B or C" and "unknown action 'X' (expected A, B or C)". */
int cli_run_action(const char *command, int argc, char **argv, const cli_action *actions,
                   size_t count, const char *missing, const char *unknown);

/* The help of the syntaxes' options, after a command's usage text:
 * "Options of cg clip line:" (or "Options:") and one line per option, its
 * help text aligned in a column.  syntaxes ends with NULL. */
void cli_print_options(FILE *out, const cli_syntax *const *syntaxes);

/* ---- the options the commands share: spelled, checked and documented once */

/* -o FILE, also --output FILE: where the result goes. */
#define CLI_OPTION_OUTPUT(type, member, value, help_text)                                        \
    {                                                                                            \
        .name = "-o", .alias = "--output", .kind = CLI_STRING, .offset = offsetof(type, member), \
        .value_name = (value), .help = (help_text)                                               \
    }
/* --size WxH: each side from 1 to CG_IMAGE_MAX_SIDE, at most
 * CG_IMAGE_MAX_PIXELS in all; into a cli_size. */
#define CLI_OPTION_SIZE(type, member, given_counter, help_text)                                    \
    {                                                                                              \
        .name = "--size", .kind = CLI_SIZE, .offset = offsetof(type, member), .value_name = "WxH", \
        .help = (help_text), .given = (given_counter)                                              \
    }
/* --threads N: worker threads, 1 to 64; into an int. */
#define CLI_OPTION_THREADS(type, member, given_counter, help_text)                                 \
    {                                                                                              \
        .name = "--threads", .kind = CLI_INT, .offset = offsetof(type, member), .value_name = "N", \
        .help = (help_text), .given = (given_counter), .min = 1, .max = 64                         \
    }
/* --repeat N: run the timed part N times (1 to most) and print the median
 * time on stderr; into an int. */
#define CLI_OPTION_REPEAT(type, member, most, help_text)                                          \
    {                                                                                             \
        .name = "--repeat", .kind = CLI_INT, .offset = offsetof(type, member), .value_name = "N", \
        .help = (help_text), .min = 1, .max = (most)                                              \
    }

#endif
