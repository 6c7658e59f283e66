/* cg demo: renders the gallery, one picture per algorithm, and its page. */
#include "cli.h"
#include "command.h"
#include "demo.h"
#include "../../../src/core/array.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define DEMO_SECTION(name) extern const demo_section demo_section_##name;
#include "demos.inc"
#undef DEMO_SECTION

static const demo_section *const sections[] = {
#define DEMO_SECTION(name) &demo_section_##name,
#include "demos.inc"
#undef DEMO_SECTION
};
enum { SECTION_COUNT = sizeof sections / sizeof sections[0] };

/* Chapter headings of the lecture notes. */
static const char *chapter_title(int chapter)
{
    static const char *titles[] = {
        NULL,
        "Introduction",
        "2D drawing",
        "Projection",
        "Geometrical transformations",
        "Visible-surface determination",
        "Illumination",
        "Color models",
        "Shading",
        "Mesh processing",
        "Filling",
        "Clipping",
    };
    if (chapter >= 1 && chapter <= 11)
        return titles[chapter];
    return "More";
}

typedef struct demo_entry {
    const demo_section *section;
    char *file, *caption, *command;
} demo_entry;

struct demo_context {
    const char *directory;
    const demo_section *current;
    demo_entry *entries;
    size_t count, capacity;
};

const char *demo_directory(const demo_context *context)
{
    return context->directory;
}

static char *duplicate(const char *text)
{
    if (!text)
        return NULL;
    size_t n = strlen(text) + 1;
    char *copy = malloc(n);
    if (copy)
        memcpy(copy, text, n);
    return copy;
}

int demo_add(demo_context *context, const char *file, const cg_image *image, const char *caption,
             const char *command)
{
    size_t length = strlen(context->directory) + strlen(file) + 2;
    char *path = malloc(length);
    if (!path)
        return cli_fail("demo: out of memory");
    snprintf(path, length, "%s/%s", context->directory, file);
    int status = cli_write_image(image, path);
    free(path);
    if (status != CLI_OK)
        return status;
    if (core_array_reserve((void **)&context->entries, &context->capacity, context->count + 1,
                           sizeof *context->entries)
        != CG_OK)
        return cli_fail("demo: out of memory");
    demo_entry *entry = &context->entries[context->count++];
    entry->section = context->current;
    entry->file = duplicate(file);
    entry->caption = duplicate(caption);
    entry->command = duplicate(command);
    return CLI_OK;
}

/* Creates the directories of path (not its last part); 0 or -1. */
static int make_parents(const char *path);

int demo_copy_input(demo_context *context, const char *relative)
{
#ifdef CG_SOURCE_DIR
    char from[4096], to[4096], temporary[4200];
    snprintf(from, sizeof from, "%s/%s", CG_SOURCE_DIR, relative);
    snprintf(to, sizeof to, "%s/%s", context->directory, relative);
    snprintf(temporary, sizeof temporary, "%s.tmp", to);
    FILE *in = fopen(from, "rb");
    if (!in)
        return cli_fail("demo: cannot read %s: %s", from, strerror(errno));
    FILE *out = make_parents(to) == 0 ? fopen(temporary, "wb") : NULL;
    if (!out) {
        fclose(in);
        return cli_fail("demo: cannot write %s: %s", temporary, strerror(errno));
    }
    char buffer[65536];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, in)) > 0)
        if (fwrite(buffer, 1, n, out) != n)
            break;
    int failed = ferror(in) || ferror(out);
    fclose(in);
    failed |= fclose(out) != 0;
    if (failed || rename(temporary, to) != 0) {
        remove(temporary);
        return cli_fail("demo: cannot write %s", to);
    }
    return CLI_OK;
#else
    (void)context;
    (void)relative;
    return CLI_OK;
#endif
}

static void write_escaped(FILE *out, const char *text)
{
    for (; text && *text; text++) {
        switch (*text) {
        case '<': fputs("&lt;", out); break;
        case '>': fputs("&gt;", out); break;
        case '&': fputs("&amp;", out); break;
        case '"': fputs("&quot;", out); break;
        default: fputc(*text, out);
        }
    }
}

/* The caption's command, also in machine-readable form: data-command is the
 * command to run in the gallery folder, data-output the file it writes there
 * (`cg demo --only` writes into out/), which equals the picture. */
static void write_command(FILE *out, const demo_entry *e)
{
    fputs("<code data-command=\"", out);
    write_escaped(out, e->command);
    fputs("\" data-output=\"", out);
    if (strncmp(e->command, "cg demo ", 8) == 0)
        fputs("out/", out);
    write_escaped(out, e->file);
    fputs("\">", out);
    write_escaped(out, e->command);
    fputs("</code>", out);
}

static int compare_sections(const void *a, const void *b)
{
    const demo_section *x = *(const demo_section *const *)a, *y = *(const demo_section *const *)b;
    if (x->chapter != y->chapter)
        return x->chapter - y->chapter;
    return strcmp(x->title, y->title);
}

static int write_page(const demo_context *context, const demo_section **ordered)
{
    size_t length = strlen(context->directory) + 32;
    char *path = malloc(length), *temporary = malloc(length);
    if (!path || !temporary) {
        free(path);
        free(temporary);
        return cli_fail("demo: out of memory");
    }
    snprintf(path, length, "%s/index.html", context->directory);
    snprintf(temporary, length, "%s/index.html.tmp", context->directory);
    FILE *out = fopen(temporary, "w");
    if (!out) {
        int status = cli_fail("demo: cannot write %s: %s", temporary, strerror(errno));
        free(path);
        free(temporary);
        return status;
    }
    fprintf(out,
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<title>cg gallery</title>\n<style>\n"
            "body{font-family:sans-serif;margin:2em;background:#fafafa;color:#222}\n"
            "h2{border-bottom:1px solid #ccc;margin-top:2em}\n"
            ".grid{display:flex;flex-wrap:wrap;gap:1.5em}\n"
            "figure{margin:0;max-width:420px}\n"
            "figure img{max-width:100%%;border:1px solid #ddd;background:#fff;"
            "image-rendering:pixelated}\n"
            "figcaption{font-size:0.9em;margin-top:0.3em}\n"
            "code{display:block;font-size:0.8em;color:#555;margin-top:0.2em;"
            "white-space:pre-wrap}\n</style>\n</head>\n<body>\n"
            "<h1>cg gallery</h1>\n<p>Every picture below was rendered by cg %s; the "
            "command under each one, run in this folder, makes it again.</p>\n",
            CG_VERSION_STRING);
    int chapter = -1;
    for (int s = 0; s < SECTION_COUNT; s++) {
        const demo_section *section = ordered[s];
        if (section->chapter != chapter) {
            if (chapter != -1)
                fputs("</section>\n", out);
            chapter = section->chapter;
            fprintf(out, "<section id=\"chapter-%d\">\n<h2>%d. ", chapter, chapter);
            write_escaped(out, chapter_title(chapter));
            fputs("</h2>\n", out);
        }
        fputs("<h3>", out);
        write_escaped(out, section->title);
        fputs("</h3>\n<div class=\"grid\">\n", out);
        for (size_t i = 0; i < context->count; i++) {
            const demo_entry *e = &context->entries[i];
            if (e->section != section)
                continue;
            fputs("<figure><img src=\"", out);
            write_escaped(out, e->file);
            fputs("\" alt=\"", out);
            write_escaped(out, e->caption);
            fputs("\"><figcaption>", out);
            write_escaped(out, e->caption);
            if (e->command)
                write_command(out, e);
            fputs("</figcaption></figure>\n", out);
        }
        fputs("</div>\n", out);
    }
    if (chapter != -1)
        fputs("</section>\n", out);
    fputs("</body>\n</html>\n", out);
    int failed = ferror(out);
    failed |= fclose(out) != 0;
    int status = CLI_OK;
    if (failed || rename(temporary, path) != 0) {
        status = cli_fail("demo: cannot write %s", path);
        remove(temporary);
    }
    free(path);
    free(temporary);
    return status;
}

static int make_parents(const char *path)
{
    char *copy = duplicate(path);
    if (!copy)
        return -1;
    for (char *p = copy + 1; *p; p++) {
        if (*p == '/') {
            *p = '\0';
            if (mkdir(copy, 0777) != 0 && errno != EEXIST) {
                free(copy);
                return -1;
            }
            *p = '/';
        }
    }
    free(copy);
    return 0;
}

static int make_directory(const char *path)
{
    if (make_parents(path) != 0)
        return -1;
    return (mkdir(path, 0777) == 0 || errno == EEXIST) ? 0 : -1;
}

static int any_section_matches(const demo_section *const *ordered, const char *only)
{
    for (int s = 0; s < SECTION_COUNT; s++)
        if (strstr(ordered[s]->title, only))
            return 1;
    return 0;
}

/* "A; B; C": the section titles for a message (cut short if very long). */
static const char *section_titles(const demo_section *const *ordered, char *list, size_t room)
{
    size_t used = 0;
    list[0] = '\0';
    for (int s = 0; s < SECTION_COUNT && used < room; s++)
        used += (size_t)snprintf(list + used, room - used, "%s%s", s ? "; " : "",
                                 ordered[s]->title);
    return list;
}

typedef struct demo_arguments {
    const char *directory, *only;
} demo_arguments;

static const cli_option demo_options[] = {
    CLI_OPTION_OUTPUT(demo_arguments, directory, "DIR", "the gallery's folder (default out)"),
    {.name = "--only",
     .kind = CLI_STRING,
     .offset = offsetof(demo_arguments, only),
     .value_name = "TEXT",
     .help = "only the sections whose title contains TEXT"},
};
static const cli_option_group demo_groups[] = {CLI_GROUP(NULL, demo_options), {0}};
static const cli_syntax demo_syntax = {.command = "demo", .groups = demo_groups};
static const cli_syntax *const demo_syntaxes[] = {&demo_syntax, NULL};

static int run(int argc, char **argv)
{
    demo_arguments arguments = {"out", NULL};
    if (cli_parse(&demo_syntax, argc, argv, &arguments, NULL, NULL) != CLI_OK)
        return CLI_USAGE;
    const char *directory = arguments.directory, *only = arguments.only;
    const demo_section *ordered[SECTION_COUNT > 0 ? SECTION_COUNT : 1];
    for (int s = 0; s < SECTION_COUNT; s++)
        ordered[s] = sections[s];
    qsort(ordered, SECTION_COUNT, sizeof ordered[0], compare_sections);
    if (only && !any_section_matches(ordered, only)) {
        char titles[2048];
        return cli_usage_error("demo", "--only: no section title contains '%s' (titles: %s)", only,
                               section_titles(ordered, titles, sizeof titles));
    }
    if (make_directory(directory) != 0)
        return cli_fail("demo: cannot create directory %s: %s", directory, strerror(errno));

    demo_context context = {directory, NULL, NULL, 0, 0};
    int status = CLI_OK;
    for (int s = 0; s < SECTION_COUNT && status == CLI_OK; s++) {
        if (only && !strstr(ordered[s]->title, only))
            continue;
        context.current = ordered[s];
        fprintf(stderr, "demo: %s\n", ordered[s]->title);
        if (ordered[s]->render(&context) != 0)
            status = cli_fail("demo: section '%s' failed", ordered[s]->title);
    }
    if (status == CLI_OK)
        status = write_page(&context, ordered);
    if (status == CLI_OK)
        printf("%zu pictures written to %s/ (open %s/index.html)\n", context.count, directory,
               directory);
    for (size_t i = 0; i < context.count; i++) {
        free(context.entries[i].file);
        free(context.entries[i].caption);
        free(context.entries[i].command);
    }
    free(context.entries);
    return status;
}

const cg_command cg_command_demo = {
    "demo",
    "render the gallery of every algorithm to a folder",
    "usage: cg demo [-o DIR] [--only TEXT]\n\n"
    "Renders one PNG per algorithm into DIR (default: out) and writes\n"
    "DIR/index.html, a page with a section per chapter of the lecture notes;\n"
    "each picture has a caption naming the algorithm and the command that makes\n"
    "it, run in DIR (its inputs are written there; see docs/gallery.md).\n"
    "--only renders just the sections whose title contains TEXT.\n",
    run,
    demo_syntaxes,
};
