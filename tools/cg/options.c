/* The option parser of the cg commands (see options.h). */
#include "options.h"

#include "cg/color.h"

#include <string.h>

/* The member of the arguments struct at offset, as a pointer to T. */
#define MEMBER(T, arguments, offset) ((T *)(void *)((char *)(arguments) + (offset)))

/* The option of syntax that argument names ("--size", "--size=...", or its
 * alias), or NULL. */
static const cli_option *find_option(const cli_syntax *syntax, const char *argument)
{
    for (const cli_option_group *group = syntax->groups; group && group->options; group++)
        for (size_t k = 0; k < group->count; k++) {
            const cli_option *option = &group->options[k];
            if (cli_option_is(argument, option->name)
                || (option->alias && cli_option_is(argument, option->alias)))
                return option;
        }
    return NULL;
}

/* "A, B or C" (or "A|B|C") of a NULL-terminated list, into list[0..room). */
static void choice_list(const char *const *choices, const char *joint, const char *last_joint,
                        char *list, size_t room)
{
    list[0] = '\0';
    for (int i = 0; choices[i]; i++) {
        strncat(list, choices[i], room - strlen(list) - 1);
        if (choices[i + 1])
            strncat(list, choices[i + 2] ? joint : last_joint, room - strlen(list) - 1);
    }
}

static int parse_choice(const char *command, const char *what, const char *const *choices,
                        const char *text, int *out)
{
    for (int i = 0; choices[i]; i++)
        if (strcmp(text, choices[i]) == 0) {
            *out = i;
            return 0;
        }
    char list[256];
    choice_list(choices, ", ", " or ", list, sizeof list);
    cli_usage_error(command, "%s: expected %s, got '%s'", what, list, text);
    return -1;
}

static int in_range(const cli_option *option, double value)
{
    int low_ok = option->open & CLI_OPEN_LOW ? value > option->low : value >= option->low;
    int high_ok = option->open & CLI_OPEN_HIGH ? value < option->high : value <= option->high;
    return low_ok && high_ok;
}

int cli_read_double(const char *command, const cli_option *option, const char *text, double *out)
{
    const char *what = option->what ? option->what : option->name;
    double value;
    if (cli_parse_double(command, what, text, &value))
        return -1;
    if (option->range_text && !in_range(option, value)) {
        cli_usage_error(command, "%s: expected %s, got '%s'", what, option->range_text, text);
        return -1;
    }
    *out = value;
    return 0;
}

/* Reads text, the value of option, into arguments: 0 or -1 after printing. */
static int store_value(const char *command, const cli_option *option, const char *text,
                       void *arguments)
{
    const char *what = option->what ? option->what : option->name;
    size_t at = option->offset;
    switch (option->kind) {
    case CLI_INT: {
        long value;
        if (cli_parse_long(command, what, text, option->min, option->max, &value))
            return -1;
        *MEMBER(int, arguments, at) = (int)value;
        return 0;
    }
    case CLI_DOUBLE: return cli_read_double(command, option, text, MEMBER(double, arguments, at));
    case CLI_STRING: *MEMBER(const char *, arguments, at) = text; return 0;
    case CLI_CHOICE:
        return parse_choice(command, what, option->choices, text, MEMBER(int, arguments, at));
    case CLI_VEC3: return cli_parse_vec3(command, what, text, MEMBER(cg_vec3, arguments, at));
    case CLI_SIZE: {
        cli_size *size = MEMBER(cli_size, arguments, at);
        return cli_parse_size(command, what, text, &size->width, &size->height);
    }
    case CLI_COLOR: return cli_parse_color(command, what, text, MEMBER(cg_rgba8, arguments, at));
    case CLI_LINEAR_COLOR: {
        cg_rgba8 color;
        if (cli_parse_color(command, what, text, &color))
            return -1;
        *MEMBER(cg_rgbaf, arguments, at) = cg_rgba8_to_linear(color);
        return 0;
    }
    case CLI_CUSTOM: return option->parse(command, option, text, arguments);
    case CLI_FLAG: break;
    }
    return 0;
}

/* The option at argv[*i] (advancing *i past its value): 0 or -1. */
static int parse_option(const cli_syntax *syntax, const cli_option *option, int argc, char **argv,
                        int *i, void *arguments)
{
    const char *command = syntax->command;
    if (option->kind == CLI_FLAG) {
        if (strchr(argv[*i], '=')) {
            cli_usage_error(command, "option %.*s takes no value", (int)strcspn(argv[*i], "="),
                            argv[*i]);
            return -1;
        }
        *MEMBER(int, arguments, option->offset) = option->flag_value;
    } else {
        const char *text = cli_option_value(command, argc, argv, i);
        if (!text || store_value(command, option, text, arguments))
            return -1;
    }
    if (option->given)
        *MEMBER(int, arguments, option->given - 1) += 1;
    return 0;
}

int cli_parse(const cli_syntax *syntax, int argc, char **argv, void *arguments,
              const char **positionals, int *count)
{
    const char *command = syntax->command;
    const char *action = syntax->action ? syntax->action : "";
    const char *colon = syntax->action ? ": " : "";
    int positional_count = 0;
    for (int i = 1; i < argc; i++) {
        const char *argument = argv[i];
        if (cli_is_option(argument)) {
            const cli_option *option = find_option(syntax, argument);
            if (!option)
                return cli_usage_error(command, "%s%sunknown option '%s'", action, colon, argument);
            if (parse_option(syntax, option, argc, argv, &i, arguments))
                return CLI_USAGE;
        } else if (syntax->positional) {
            if (syntax->positional(command, positional_count++, argument, arguments))
                return CLI_USAGE;
        } else if (positional_count < syntax->max_positionals) {
            positionals[positional_count++] = argument;
        } else {
            return cli_usage_error(command,
                                   syntax->too_many ? syntax->too_many : "unexpected argument '%s'",
                                   argument);
        }
    }
    if (positional_count < syntax->min_positionals)
        return cli_usage_error(command, "%s",
                               syntax->too_few ? syntax->too_few : "too few arguments");
    if (count)
        *count = positional_count;
    return CLI_OK;
}

int cli_given(const cli_option *option, const void *arguments)
{
    return option->given && *MEMBER(const int, arguments, option->given - 1) > 0;
}

int cli_run_action(const char *command, int argc, char **argv, const cli_action *actions,
                   size_t count, const char *missing, const char *unknown)
{
    for (size_t k = 0; argc >= 2 && k < count; k++)
        if (strcmp(argv[1], actions[k].name) == 0)
            return actions[k].run(argc - 1, argv + 1);
    char list[256] = "";
    for (size_t k = 0; k < count; k++) {
        strncat(list, actions[k].name, sizeof list - strlen(list) - 1);
        if (k + 1 < count)
            strncat(list, k + 2 == count ? " or " : ", ", sizeof list - strlen(list) - 1);
    }
    if (argc < 2)
        return missing ? cli_usage_error(command, "%s", missing)
                       : cli_usage_error(command, "expected %s", list);
    if (unknown)
        return cli_usage_error(command, unknown, argv[1]);
    return cli_usage_error(command, "unknown action '%s' (expected %s)", argv[1], list);
}

/* ---- the help ---------------------------------------------------------------- */

enum { HELP_COLUMN = 24 };

/* "  --size WxH" or "  -o, --output OUT" or "  --shading flat|gouraud|phong". */
static void option_spelling(const cli_option *option, char *text, size_t room)
{
    char value[256] = "";
    if (option->kind == CLI_CHOICE && !option->value_name)
        choice_list(option->choices, "|", "|", value, sizeof value);
    else if (option->kind != CLI_FLAG && option->value_name)
        snprintf(value, sizeof value, "%s", option->value_name);
    else if (option->kind != CLI_FLAG)
        snprintf(value, sizeof value, "VALUE");
    snprintf(text, room, "  %s%s%s%s%s", option->name, option->alias ? ", " : "",
             option->alias ? option->alias : "", value[0] ? " " : "", value);
}

/* The help text, its first line after the spelling (or below it when the
 * spelling reaches the column), its other lines in the column. */
static void print_option(FILE *out, const cli_option *option)
{
    char spelling[320];
    option_spelling(option, spelling, sizeof spelling);
    const char *help = option->help ? option->help : "";
    int width = (int)strlen(spelling);
    if (width + 2 > HELP_COLUMN)
        fprintf(out, "%s\n%*s", spelling, HELP_COLUMN, "");
    else
        fprintf(out, "%-*s", HELP_COLUMN, spelling);
    for (const char *line = help;;) {
        size_t length = strcspn(line, "\n");
        fprintf(out, "%.*s\n", (int)length, line);
        if (line[length] == '\0')
            break;
        line += length + 1;
        fprintf(out, "%*s", HELP_COLUMN, "");
    }
}

void cli_print_options(FILE *out, const cli_syntax *const *syntaxes)
{
    for (const cli_syntax *const *s = syntaxes; s && *s; s++) {
        const cli_syntax *syntax = *s;
        if (!syntax->groups || !syntax->groups->options)
            continue;
        if (syntax->action)
            fprintf(out, "\nOptions of cg %s %s:\n", syntax->command, syntax->action);
        else
            fprintf(out, "\nOptions:\n");
        for (const cli_option_group *group = syntax->groups; group->options; group++) {
            if (group->heading)
                fprintf(out, "%s\n", group->heading);
            for (size_t k = 0; k < group->count; k++)
                print_option(out, &group->options[k]);
        }
    }
}
