/* A recorded trace as a table or as JSON, and the run that holds it. */
#include "trace_output.h"

#include "cli.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *format_text(const char *format, va_list args)
{
    va_list copy;
    va_copy(copy, args);
    int n = vsnprintf(NULL, 0, format, copy);
    va_end(copy);
    if (n < 0)
        return NULL;
    char *text = malloc((size_t)n + 1);
    if (text)
        vsnprintf(text, (size_t)n + 1, format, args);
    return text;
}

trace_run *trace_run_create(const char *algorithm, int argc, char **argv, const char *title, ...)
{
    trace_run *run = calloc(1, sizeof *run);
    if (!run)
        return NULL;
    run->algorithm = algorithm;
    run->argc = argc;
    run->argv = argv;
    va_list args;
    va_start(args, title);
    run->title = format_text(title, args);
    va_end(args);
    if (!run->title || cg_step_log_create(&run->log) != CG_OK) {
        trace_run_free(run);
        return NULL;
    }
    return run;
}

void trace_run_free(trace_run *run)
{
    if (!run)
        return;
    free(run->title);
    for (int i = 0; i < run->note_count; i++)
        free(run->notes[i]);
    free(run->summary);
    for (int i = 0; i < run->scene_count; i++)
        free(run->scene[i].points);
    cg_step_log_free(run->log);
    cg_image_free(run->background);
    free(run);
}

void trace_note(trace_run *run, const char *format, ...)
{
    if (run->note_count >= TRACE_MAX_NOTES)
        return;
    va_list args;
    va_start(args, format);
    char *text = format_text(format, args);
    va_end(args);
    if (text)
        run->notes[run->note_count++] = text;
}

void trace_summary(trace_run *run, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    free(run->summary);
    run->summary = format_text(format, args);
    va_end(args);
}

void trace_scene_add(trace_run *run, const cg_vec2 *points, int count, int closed)
{
    if (run->scene_count >= TRACE_MAX_SCENE || count <= 0)
        return;
    cg_vec2 *copy = malloc((size_t)count * sizeof *copy);
    if (!copy)
        return;
    memcpy(copy, points, (size_t)count * sizeof *copy);
    run->scene[run->scene_count++] = (trace_scene_path){copy, count, closed};
}

long trace_pixel_total(const trace_run *run)
{
    long total = 0;
    for (size_t i = 0; i < cg_step_log_count(run->log); i++)
        total += cg_step_log_get(run->log, i)->pixel_count;
    return total;
}

enum { MAX_ARGUMENTS = 256 };

/* --frames and --html take a path that is not empty. */
static int parse_path(const char *command, const cli_option *option, const char *text,
                      void *arguments)
{
    if (!*text) {
        cli_usage_error(command, "%s needs a non-empty path", option->name);
        return -1;
    }
    *(const char **)((char *)arguments + option->offset) = text;
    return 0;
}

static const cli_option output_options[] = {
    {.name = "--json",
     .kind = CLI_FLAG,
     .offset = offsetof(trace_outputs, json),
     .flag_value = 1,
     .help = "one JSON object instead of the table (docs/teaching.md)"},
    {.name = "--frames",
     .kind = CLI_CUSTOM,
     .offset = offsetof(trace_outputs, frames_dir),
     .value_name = "DIR",
     .parse = parse_path,
     .help = "a PNG per step (DIR/step_0000.png ...): the picture so\n"
             "far, the step's pixels orange, its geometry red"},
    {.name = "--html",
     .kind = CLI_CUSTOM,
     .offset = offsetof(trace_outputs, html),
     .value_name = "OUT.html",
     .parse = parse_path,
     .help = "one self-contained page stepping through those pictures\n"
             "(buttons, slider, arrow keys; works offline)"},
};

static const cli_option_group output_groups[] = {CLI_GROUP(NULL, output_options), {0}};

const cli_syntax trace_output_syntax = {
    .command = "trace",
    .groups = output_groups,
    .max_positionals = MAX_ARGUMENTS,
    .too_many = "too many arguments (at most 256), from '%s' on",
};

int trace_outputs_parse(int *argc, char **argv, trace_outputs *out)
{
    const char *rest[MAX_ARGUMENTS];
    int count = 0;
    memset(out, 0, sizeof *out);
    if (cli_parse(&trace_output_syntax, *argc, argv, out, rest, &count) != CLI_OK)
        return -1;
    for (int i = 0; i < count; i++)
        argv[i + 1] = (char *)rest[i]; /* the same strings, in order */
    *argc = count + 1;
    argv[*argc] = NULL;
    return 0;
}

/* ---- values as text ---------------------------------------------------------- */

static void put_real(char *out, size_t size, double v)
{
    snprintf(out, size, "%.6g", v == 0 ? 0 : v); /* no "-0" */
}

/* A field as the table shows it ("-" for no value).  Point lists may be
 * long: the text is cut at size. */
void trace_field_text(const cg_step_field *f, char *out, size_t size)
{
    char a[40], b[40];
    switch (f->kind) {
    case CG_STEP_NONE: snprintf(out, size, "-"); break;
    case CG_STEP_INTEGER: snprintf(out, size, "%lld", f->integer); break;
    case CG_STEP_REAL: put_real(out, size, f->real); break;
    case CG_STEP_TEXT: snprintf(out, size, "%s", f->text ? f->text : ""); break;
    case CG_STEP_PIXEL: snprintf(out, size, "(%d, %d)", f->pixel_x, f->pixel_y); break;
    case CG_STEP_POINT:
        put_real(a, sizeof a, f->point.x);
        put_real(b, sizeof b, f->point.y);
        snprintf(out, size, "(%s, %s)", a, b);
        break;
    case CG_STEP_REALS: {
        size_t used = (size_t)snprintf(out, size, "[");
        for (size_t i = 0; i < f->real_count && used + 1 < size; i++) {
            put_real(a, sizeof a, f->reals[i]);
            const char *gap = i == 0 ? "" : f->real_count == 16 && i % 4 == 0 ? "; " : " ";
            int n = snprintf(out + used, size - used, "%s%s", gap, a);
            if (n < 0)
                break;
            used += (size_t)n;
        }
        if (used + 1 < size)
            snprintf(out + used, size - used, "]");
        break;
    }
    case CG_STEP_POINTS: {
        size_t used = 0;
        out[0] = 0;
        if (f->point_count == 0)
            snprintf(out, size, "(none)");
        for (size_t i = 0; i < f->point_count && used + 1 < size; i++) {
            put_real(a, sizeof a, f->points[i].x);
            put_real(b, sizeof b, f->points[i].y);
            int n = snprintf(out + used, size - used, "%s(%s, %s)", i ? " " : "", a, b);
            if (n < 0)
                break;
            used += (size_t)n;
        }
        break;
    }
    }
}

/* A column is right-aligned when every value in it is a number (or none);
 * "no value" shows as "-" there and as nothing in a text column. */
static int numeric_column(const cg_step_log *log, size_t from, size_t to, int column)
{
    for (size_t i = from; i < to; i++) {
        cg_step_kind kind = cg_step_log_get(log, i)->fields[column].kind;
        if (kind != CG_STEP_INTEGER && kind != CG_STEP_REAL && kind != CG_STEP_NONE)
            return 0;
    }
    return 1;
}

static void cell_text(const cg_step_field *f, int numeric, char *out, size_t size)
{
    if (f->kind == CG_STEP_NONE && !numeric)
        out[0] = 0;
    else
        trace_field_text(f, out, size);
}

static int same_names(const cg_step *a, const cg_step *b)
{
    if (a->field_count != b->field_count)
        return 0;
    for (int i = 0; i < a->field_count; i++)
        if (strcmp(a->fields[i].name, b->fields[i].name) != 0)
            return 0;
    return 1;
}

static int same_phase(const cg_step *a, const cg_step *b)
{
    return (!a->phase && !b->phase) || (a->phase && b->phase && strcmp(a->phase, b->phase) == 0);
}

enum { CELL = 512, MAX_COLUMNS = 32 };

/* Prints steps [from, to) (one phase with the same fields) as a table with
 * column widths fitted to the values, numbering them from 0. */
static void print_block(const cg_step_log *log, size_t from, size_t to)
{
    const cg_step *first = cg_step_log_get(log, from);
    int columns = first->field_count;
    int width[MAX_COLUMNS], numeric[MAX_COLUMNS];
    char text[CELL];
    for (int c = 0; c < columns && c < MAX_COLUMNS; c++) {
        width[c] = (int)strlen(first->fields[c].name);
        numeric[c] = numeric_column(log, from, to, c);
        for (size_t i = from; i < to; i++) {
            cell_text(&cg_step_log_get(log, i)->fields[c], numeric[c], text, sizeof text);
            if ((int)strlen(text) > width[c])
                width[c] = (int)strlen(text);
        }
    }
    if (columns > MAX_COLUMNS)
        columns = MAX_COLUMNS;
    char line[MAX_COLUMNS * (CELL + 2) + 16];
    size_t used = (size_t)snprintf(line, sizeof line, " step");
    for (int c = 0; c < columns; c++)
        used += (size_t)snprintf(line + used, sizeof line - used, numeric[c] ? "  %*s" : "  %-*s",
                                 width[c], first->fields[c].name);
    while (used > 0 && line[used - 1] == ' ')
        line[--used] = 0;
    puts(line);
    for (size_t i = from; i < to; i++) {
        const cg_step *s = cg_step_log_get(log, i);
        used = (size_t)snprintf(line, sizeof line, "%5zu", i - from);
        for (int c = 0; c < columns; c++) {
            cell_text(&s->fields[c], numeric[c], text, sizeof text);
            used += (size_t)snprintf(line + used, sizeof line - used,
                                     numeric[c] ? "  %*s" : "  %-*s", width[c], text);
            if (used >= sizeof line)
                used = sizeof line - 1;
        }
        while (used > 0 && line[used - 1] == ' ')
            line[--used] = 0;
        puts(line);
    }
}

void trace_print_table(const trace_run *run)
{
    printf("%s\n", run->title);
    for (int i = 0; i < run->note_count; i++)
        printf("%s\n", run->notes[i]);
    size_t count = cg_step_log_count(run->log);
    for (size_t from = 0; from < count;) {
        const cg_step *first = cg_step_log_get(run->log, from);
        size_t to = from + 1;
        while (to < count && same_phase(first, cg_step_log_get(run->log, to))
               && same_names(first, cg_step_log_get(run->log, to)))
            to++;
        printf("\n%s:\n", first->phase ? first->phase : "steps");
        print_block(run->log, from, to);
        from = to;
    }
    if (run->summary)
        printf("%s\n", run->summary);
}

/* ---- JSON ------------------------------------------------------------------------ */

static void json_string(const char *s)
{
    putchar('"');
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            printf("\\%c", c);
        else if (c < 0x20)
            printf("\\u%04x", c);
        else
            putchar(c);
    }
    putchar('"');
}

static void json_real(double v)
{
    if (v != v || v - v != 0) /* NaN or infinite */
        printf("null");
    else
        printf("%.17g", v == 0 ? 0 : v);
}

static void json_point(cg_vec2 p)
{
    putchar('[');
    json_real(p.x);
    putchar(',');
    json_real(p.y);
    putchar(']');
}

static void json_points(const cg_vec2 *points, size_t count)
{
    putchar('[');
    for (size_t i = 0; i < count; i++) {
        if (i)
            putchar(',');
        json_point(points[i]);
    }
    putchar(']');
}

static void json_field(const cg_step_field *f)
{
    switch (f->kind) {
    case CG_STEP_NONE: printf("null"); break;
    case CG_STEP_INTEGER: printf("%lld", f->integer); break;
    case CG_STEP_REAL: json_real(f->real); break;
    case CG_STEP_TEXT: json_string(f->text); break;
    case CG_STEP_PIXEL: printf("[%d,%d]", f->pixel_x, f->pixel_y); break;
    case CG_STEP_POINT: json_point(f->point); break;
    case CG_STEP_POINTS: json_points(f->points, f->point_count); break;
    case CG_STEP_REALS:
        putchar('[');
        for (size_t i = 0; i < f->real_count; i++) {
            if (i)
                putchar(',');
            json_real(f->reals[i]);
        }
        putchar(']');
        break;
    }
}

static void json_step(const cg_step *s, size_t index, size_t in_phase)
{
    printf("  {\"index\":%zu,\"phase\":", index);
    if (s->phase)
        json_string(s->phase);
    else
        printf("null");
    printf(",\"step\":%zu,\"values\":{", in_phase);
    for (int i = 0; i < s->field_count; i++) {
        if (i)
            putchar(',');
        json_string(s->fields[i].name);
        putchar(':');
        json_field(&s->fields[i]);
    }
    printf("},\"pixels\":[");
    for (int i = 0; i < s->pixel_count; i++)
        printf("%s[%d,%d]", i ? "," : "", s->pixels[2 * i], s->pixels[2 * i + 1]);
    printf("]");
    if (s->intensity) {
        printf(",\"intensity\":[");
        for (int i = 0; i < s->pixel_count; i++) {
            if (i)
                putchar(',');
            json_real(s->intensity[i]);
        }
        printf("]");
    }
    printf(",\"geometry\":");
    json_points(s->geometry, (size_t)s->geometry_count);
    printf(",\"closed\":%s,\"kept\":", s->closed ? "true" : "false");
    json_points(s->kept, (size_t)s->kept_count);
    printf(",\"kept_closed\":%s}", s->kept_closed ? "true" : "false");
}

void trace_print_json(const trace_run *run)
{
    printf("{\"algorithm\":");
    json_string(run->algorithm);
    printf(",\"arguments\":[");
    for (int i = 0; i < run->argc; i++) {
        if (i)
            putchar(',');
        json_string(run->argv[i]);
    }
    printf("],\"title\":");
    json_string(run->title);
    printf(",\"notes\":[");
    for (int i = 0; i < run->note_count; i++) {
        if (i)
            putchar(',');
        json_string(run->notes[i]);
    }
    printf("],\"y_up\":%s,\"scene\":[", run->y_up ? "true" : "false");
    for (int i = 0; i < run->scene_count; i++) {
        printf("%s{\"points\":", i ? "," : "");
        json_points(run->scene[i].points, (size_t)run->scene[i].count);
        printf(",\"closed\":%s}", run->scene[i].closed ? "true" : "false");
    }
    printf("],\n\"steps\":[\n");
    size_t count = cg_step_log_count(run->log), in_phase = 0;
    for (size_t i = 0; i < count; i++) {
        const cg_step *s = cg_step_log_get(run->log, i);
        if (i > 0 && !same_phase(s, cg_step_log_get(run->log, i - 1)))
            in_phase = 0;
        json_step(s, i, in_phase++);
        printf(i + 1 < count ? ",\n" : "\n");
    }
    printf("],\"summary\":");
    if (run->summary)
        json_string(run->summary);
    else
        printf("null");
    printf("}\n");
}

static int write_outputs(const trace_run *run, cg_status status, const char *what,
                         const trace_outputs *out)
{
    if (status == CG_OK)
        status = cg_step_log_status(run->log);
    if (status == CG_EINVAL || status == CG_ERANGE)
        return cli_usage_error("trace", "%s: %s", run->algorithm, what);
    if (status != CG_OK)
        return cli_fail("trace: %s: %s", run->algorithm, cg_status_str(status));
    int frames = 0;
    if (out->frames_dir && trace_write_frames(run, out->frames_dir, &frames) != CLI_OK)
        return CLI_FAILED;
    if (out->html && trace_write_html(run, out->frames_dir, frames, out->html) != CLI_OK)
        return CLI_FAILED;
    if (out->json)
        trace_print_json(run);
    else
        trace_print_table(run);
    return fflush(stdout) == 0 ? CLI_OK : cli_fail("trace: cannot write the output");
}

int trace_finish(trace_run *run, cg_status status, const char *what, const trace_outputs *out)
{
    int code = write_outputs(run, status, what, out);
    trace_run_free(run);
    return code;
}
