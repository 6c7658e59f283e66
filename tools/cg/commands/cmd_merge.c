/* cg merge PARTS... -o OUT: adds the path tracer's part files (tiles and
 * sample ranges of one render) into the whole picture. */
#include "command.h"
#include "cli.h"
#include "pathtrace_output.h"

#include <stdlib.h>
#include <string.h>

#define NAME "merge"

enum { MAX_PARTS = 4096 };

typedef struct merge_args {
    const char *output;
    double exposure;
    const char **parts;
    int count;
} merge_args;

static int add_part(const char *command, int index, const char *text, void *arguments)
{
    (void)index;
    merge_args *a = arguments;
    if (a->count >= MAX_PARTS)
        return cli_usage_error(command, "at most %d parts", MAX_PARTS), -1;
    a->parts[a->count++] = text;
    return 0;
}

static const cli_option merge_options[] = {
    CLI_OPTION_OUTPUT(merge_args, output, "OUT", "the picture (.png, .pfm, ...) or a .part"),
    {.name = "--exposure",
     .kind = CLI_DOUBLE,
     .offset = offsetof(merge_args, exposure),
     .value_name = "STOPS",
     .help = "exposure of 8-bit outputs (default 0)"},
};
static const cli_option_group merge_groups[] = {CLI_GROUP(NULL, merge_options), {0}};
static const cli_syntax merge_syntax = {
    .command = NAME, .groups = merge_groups, .positional = add_part};

static int merge_loaded(cg_path_part *parts, int count, const char *output, double exposure)
{
    cg_error err;
    cg_path_part whole;
    if (cg_path_part_merge(parts, (size_t)count, &whole, &err) != CG_OK)
        return cli_fail("%s: %s", NAME, err.message);
    int status = pathtrace_write(NAME, &whole, output, exposure);
    free(whole.sums);
    return status;
}

static int run(int argc, char **argv)
{
    merge_args a;
    memset(&a, 0, sizeof a);
    a.parts = malloc(MAX_PARTS * sizeof *a.parts);
    if (!a.parts)
        return cli_fail("%s: out of memory", NAME);
    int status = cli_parse(&merge_syntax, argc, argv, &a, NULL, NULL);
    if (status == CLI_OK && a.count == 0)
        status = cli_usage_error(NAME, "expected PARTS... (.part files of cg render)");
    if (status == CLI_OK && !a.output)
        status = cli_usage_error(NAME, "expected -o OUT");
    if (status != CLI_OK) {
        free(a.parts);
        return CLI_USAGE;
    }
    cg_path_part *parts = calloc((size_t)a.count, sizeof *parts);
    cg_error err;
    int loaded = 0;
    status = parts ? CLI_OK : cli_fail("%s: out of memory", NAME);
    for (; status == CLI_OK && loaded < a.count; loaded++)
        if (cg_path_part_load(a.parts[loaded], &parts[loaded], &err) != CG_OK)
            status = cli_fail("%s: %s", NAME, err.message);
    if (status == CLI_OK)
        status = merge_loaded(parts, a.count, a.output, a.exposure);
    for (int i = 0; i < a.count && parts; i++)
        free(parts[i].sums);
    free(parts);
    free(a.parts);
    return status;
}

static const cli_syntax *const merge_syntaxes[] = {&merge_syntax, NULL};

const cg_command cg_command_merge = {
    NAME,
    "merge path-traced parts (tiles, sample ranges) into one picture",
    "usage: cg merge PARTS... -o OUT\n\n"
    "Adds the .part files that 'cg render --algorithm pathtrace --tile ... /\n"
    "--sample-range ...' wrote for one render (same size, --spp, --max-depth\n"
    "and --seed) and writes OUT: the same bytes as the whole render.  Every\n"
    "pixel must receive exactly --spp samples.\n",
    run,
    merge_syntaxes,
};
