/* The `cg draw` script interpreter: reading, tokenising, command lookup and
 * the argument helpers of draw_script.h. */
#include "draw_script_run.h"
#include "cg/color.h"
#include "../../../src/core/array.h"

#include <errno.h>
#include <float.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Every command group, listed by the build from tools/cg/drawcmds_*.c. */
#define DRAW_COMMANDS(name) extern const draw_command_table draw_commands_##name;
#include "drawcmds.inc"
#undef DRAW_COMMANDS
#define DRAW_COMMANDS(name) &draw_commands_##name,
static const draw_command_table *const tables[] = {
#include "drawcmds.inc"
};
#undef DRAW_COMMANDS

enum { MAX_SCRIPT_BYTES = 256 << 20 };
/* The room a read asks for at least, in bytes. */
enum { READ_CHUNK = 4096 };

int draw_error(const draw_state *state, const char *format, ...)
{
    va_list args;
    if (state->json_array) /* line N is item N - 1 of the array */
        fprintf(stderr, "cg: %s: %s[%d]: ", state->file, state->json_array, state->line - 1);
    else
        fprintf(stderr, "%s:%d: ", state->file, state->line);
    va_start(args, format);
    vfprintf(stderr, format, args);
    va_end(args);
    fputc('\n', stderr);
    return 1;
}

int draw_arg_count(const draw_state *state, int argc, char **argv, int n, const char *usage)
{
    if (argc - 1 == n)
        return 0;
    return draw_error(state, "'%s' expects %d argument%s (%s), got %d", argv[0], n,
                      n == 1 ? "" : "s", usage, argc - 1);
}

/* A sign and at most 9 digits always fit in an int: read directly, the
 * value strtoll gives.  Returns 0 for any other text, which strtoll reads. */
static int read_simple_int(const char *text, int *out)
{
    const char *p = text;
    int negative = *p == '-';
    if (*p == '-' || *p == '+')
        p++;
    int v = 0, digits = 0;
    for (; *p >= '0' && *p <= '9'; p++) {
        if (++digits > 9)
            return 0;
        v = 10 * v + (*p - '0');
    }
    if (*p != '\0' || digits == 0)
        return 0;
    *out = negative ? -v : v;
    return 1;
}

int draw_arg_int(const draw_state *state, const char *text, const char *what, int *out)
{
    if (read_simple_int(text, out))
        return 0;
    char *end;
    errno = 0;
    long long v = strtoll(text, &end, 10);
    if (end == text || *end != '\0')
        return draw_error(state, "expected an integer for %s, got '%s'", what, text);
    if (errno == ERANGE || v < INT_MIN || v > INT_MAX)
        return draw_error(state, "%s = %s is outside the int range [%d, %d]", what, text, INT_MIN,
                          INT_MAX);
    *out = (int)v;
    return 0;
}

/* The decimal number of text when it is short and simple: a sign, up to 19
 * digits with at most 22 after the point, and no exponent, whose digits make
 * an integer m below 2^53.  Then m and 10^k are exact doubles and m / 10^k,
 * one correctly rounded division, is the value strtod gives (Clinger's fast
 * path), without strtod's general machinery.  Returns 0 for any other text,
 * which strtod then reads. */
static int read_simple_decimal(const char *text, double *out)
{
#if FLT_EVAL_METHOD == 0
    static const double powers_of_ten[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                             1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                             1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const char *p = text;
    int negative = *p == '-';
    if (*p == '-' || *p == '+')
        p++;
    unsigned long long m = 0;
    int digits = 0, fraction = -1; /* digits after the point, -1 before it */
    for (;; p++) {
        if (*p >= '0' && *p <= '9') {
            if (++digits > 19)
                return 0;
            m = 10 * m + (unsigned)(*p - '0');
            if (fraction >= 0)
                fraction++;
        } else if (*p == '.' && fraction < 0) {
            fraction = 0;
        } else {
            break;
        }
    }
    if (*p != '\0' || digits == 0 || fraction > 22 || m > (1ULL << 53))
        return 0;
    double v = (double)m;
    if (fraction > 0)
        v /= powers_of_ten[fraction];
    *out = negative ? -v : v;
    return 1;
#else
    (void)text;
    (void)out;
    return 0;
#endif
}

int draw_arg_double(const draw_state *state, const char *text, const char *what, double *out)
{
    if (read_simple_decimal(text, out))
        return 0;
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (end == text || *end != '\0')
        return draw_error(state, "expected a number for %s, got '%s'", what, text);
    if (!isfinite(v) || errno == ERANGE)
        return draw_error(state, "expected a finite number for %s, got '%s'", what, text);
    *out = v;
    return 0;
}

int draw_arg_nonnegative(const draw_state *state, const char *text, const char *what, double *out)
{
    if (draw_arg_double(state, text, what, out))
        return 1;
    if (*out < 0)
        return draw_error(state, "expected %s >= 0, got '%s'", what, text);
    return 0;
}

int draw_arg_color(const draw_state *state, const char *text, cg_rgba8 *out)
{
    cg_error err;
    if (cg_color_parse(text, out, &err) != CG_OK)
        return draw_error(state, "expected a colour (#rrggbb, #rrggbbaa or a name), got '%s'",
                          text);
    return 0;
}

int draw_arg_keyword(const draw_state *state, int argc, char **argv, const char *usage,
                     const char *const *words, int count, int *out)
{
    if (draw_arg_count(state, argc, argv, 1, usage))
        return 1;
    for (int i = 0; i < count; i++)
        if (strcmp(argv[1], words[i]) == 0) {
            *out = i;
            return 0;
        }
    return draw_error(state, "expected %s after '%s', got '%s'", usage + strlen(argv[0]) + 1,
                      argv[0], argv[1]);
}

int draw_arg_points(const draw_state *state, int argc, char **argv, int first, int min_points,
                    const char *usage, cg_vec2 **out, int *count)
{
    int numbers = argc - first;
    if (numbers < 2 * min_points || numbers % 2)
        return draw_error(state, "'%s' expects %s X Y pairs (%s), got %d number%s", argv[0],
                          min_points == 2   ? "two or more"
                          : min_points == 4 ? "four or more"
                                            : "more",
                          usage, numbers, numbers == 1 ? "" : "s");
    cg_vec2 *points = malloc((size_t)(numbers / 2) * sizeof *points);
    if (!points)
        return draw_error(state, "out of memory");
    if (draw_arg_point_pairs(state, argv + first, numbers / 2, points)) {
        free(points);
        return 1;
    }
    *out = points;
    *count = numbers / 2;
    return 0;
}

/* The name of the i-th number of a point list ("X3", "Y3") is made only for
 * a message: formatting it for every number would cost more than reading it. */
int draw_arg_point_pairs(const draw_state *state, char **words, int n, cg_vec2 *out)
{
    for (int i = 0; i < 2 * n; i++) {
        double *coordinate = i % 2 ? &out[i / 2].y : &out[i / 2].x;
        if (read_simple_decimal(words[i], coordinate))
            continue;
        char what[32];
        snprintf(what, sizeof what, "%c%d", i % 2 ? 'Y' : 'X', i / 2);
        if (draw_arg_double(state, words[i], what, coordinate))
            return 1;
    }
    return 0;
}

cg_image *draw_canvas(const draw_state *state)
{
    if (!state->canvas)
        draw_error(state, "expected 'size W H' before the first drawing command");
    return state->canvas;
}

int draw_check(const draw_state *state, cg_status status)
{
    if (status == CG_OK)
        return 0;
    return draw_error(state, "cannot draw: %s", cg_status_str(status));
}

/* ---- scripts ------------------------------------------------------------- */

static const draw_command *find_command(const char *name)
{
    for (size_t t = 0; t < sizeof tables / sizeof tables[0]; t++)
        for (int i = 0; i < tables[t]->count; i++)
            if (strcmp(tables[t]->commands[i].name, name) == 0)
                return &tables[t]->commands[i];
    return NULL;
}

static char *read_all(const char *path, size_t *size)
{
    FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 0, n = 0;
    char *text = NULL;
    if (core_array_reserve((void **)&text, &cap, READ_CHUNK, 1) != CG_OK)
        text = NULL;
    while (text) {
        if (n + 1 >= cap) {
            if (cap >= MAX_SCRIPT_BYTES) {
                free(text);
                text = NULL;
                errno = EFBIG;
                break;
            }
            if (core_array_reserve((void **)&text, &cap, n + READ_CHUNK, 1) != CG_OK) {
                free(text);
                text = NULL;
                break;
            }
        }
        size_t got = fread(text + n, 1, cap - n - 1, f);
        n += got;
        if (got == 0) {
            if (ferror(f)) {
                free(text);
                text = NULL;
            }
            break;
        }
    }
    if (f != stdin)
        fclose(f);
    if (text) {
        text[n] = '\0';
        *size = n;
    }
    return text;
}

/* A word of '#' and one or more hexadecimal digits is a colour (checked
 * later by the command); any other word starting with '#' starts a comment. */
static int is_hex_colour(const char *word, size_t length)
{
    if (length < 2)
        return 0;
    for (size_t i = 1; i < length; i++) {
        char c = word[i];
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')))
            return 0;
    }
    return 1;
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

void draw_script_free(draw_script *script)
{
    if (!script)
        return;
    for (int i = 0; i < script->count; i++)
        free(script->lines[i].argv);
    free(script->lines);
    free(script->text);
    memset(script, 0, sizeof *script);
}

static int parse(draw_script *script, size_t size);

/* A word starting with '"' at *q: its text up to the closing quote, with the
 * escapes \" \\ and \n, is moved to the start of the word (in place: it
 * only shrinks), the rest of the word's bytes become blanks, and *q points
 * after the closing quote.  Returns NULL, or what is wrong. */
static const char *unquote(char **q)
{
    char *read = *q + 1, *write = *q;
    for (;;) {
        char c = *read++;
        if (c == '\0')
            return "unterminated quoted string: expected a closing '\"' on the same line";
        if (c == '"')
            break;
        if (c == '\\') {
            c = *read++;
            if (c == 'n')
                c = '\n';
            else if (c != '"' && c != '\\')
                return "unknown escape in a quoted string (expected \\\", \\\\ or \\n)";
        }
        *write++ = c;
    }
    if (*read && !is_blank(*read))
        return "expected a blank after the closing '\"' of a quoted string";
    char *end = write;
    while (write < read)
        *write++ = ' ';
    *end = '\0';
    *q = read;
    return NULL;
}

int draw_script_load(const char *path, draw_script *script)
{
    memset(script, 0, sizeof *script);
    script->file = strcmp(path, "-") == 0 ? "<stdin>" : path;
    size_t size = 0;
    script->text = read_all(path, &size);
    if (!script->text) {
        fprintf(stderr, "cg: draw: %s: cannot read: %s\n", script->file, strerror(errno));
        return 1;
    }
    return parse(script, size);
}

int draw_script_parse(const char *name, const char *text, draw_script *script)
{
    return draw_script_parse_array(name, NULL, text, script);
}

int draw_script_parse_array(const char *name, const char *array, const char *text,
                            draw_script *script)
{
    memset(script, 0, sizeof *script);
    script->file = name;
    script->json_array = array;
    size_t size = strlen(text);
    script->text = malloc(size + 1);
    if (!script->text) {
        fprintf(stderr, "cg: draw: %s: out of memory\n", name);
        return 1;
    }
    memcpy(script->text, text, size + 1);
    return parse(script, size);
}

static int parse(draw_script *script, size_t size)
{
    if (memchr(script->text, '\0', size)) {
        fprintf(stderr, "cg: draw: %s: not a text file (contains a NUL byte)\n", script->file);
        draw_script_free(script);
        return 1;
    }
    size_t capacity = 0;
    int number = 0;
    char *p = script->text;
    /* A UTF-8 byte-order mark, as some editors write, is not part of line 1. */
    if (size >= 3 && memcmp(p, "\xef\xbb\xbf", 3) == 0)
        p += 3;
    draw_state where = {0};
    where.file = script->file;
    where.json_array = script->json_array;
    while (*p) {
        number++;
        char *end = strchr(p, '\n');
        char *next = end ? end + 1 : p + strlen(p);
        if (end)
            *end = '\0';
        /* Split into words, stopping at a comment. */
        int argc = 0;
        size_t cap = 0;
        char **argv = NULL;
        if (core_array_reserve((void **)&argv, &cap, 8, sizeof *argv) != CG_OK)
            goto out_of_memory;
        char *q = p;
        for (;;) {
            while (is_blank(*q))
                q++;
            if (!*q)
                break;
            char *word = q;
            int quoted = *q == '"';
            if (quoted) {
                const char *problem = unquote(&q);
                if (problem) {
                    where.line = number;
                    draw_error(&where, "%s", problem);
                    free(argv);
                    draw_script_free(script);
                    return 1;
                }
            }
            while (*q && !is_blank(*q))
                q++;
            size_t length = (size_t)(q - word);
            if (!quoted && word[0] == '#' && (argc == 0 || !is_hex_colour(word, length)))
                break;
            if (*q)
                *q++ = '\0';
            /* the word and the NULL that ends the list */
            if (core_array_reserve((void **)&argv, &cap, (size_t)argc + 2, sizeof *argv) != CG_OK) {
                free(argv);
                goto out_of_memory;
            }
            argv[argc++] = word;
        }
        p = next;
        if (argc == 0) {
            free(argv);
            continue;
        }
        argv[argc] = NULL;
        where.line = number;
        const draw_command *command = find_command(argv[0]);
        if (!command) {
            draw_error(&where,
                       "unknown command '%s' (expected a command such as size, color, "
                       "line, circle, bezier; see docs/draw-script.md)",
                       argv[0]);
            free(argv);
            draw_script_free(script);
            return 1;
        }
        if (core_array_reserve((void **)&script->lines, &capacity, (size_t)script->count + 1,
                               sizeof *script->lines)
            != CG_OK) {
            free(argv);
            goto out_of_memory;
        }
        draw_line *line = &script->lines[script->count++];
        line->number = number;
        line->argc = argc;
        line->argv = argv;
        line->command = command;
    }
    return 0;
out_of_memory:
    fprintf(stderr, "cg: draw: %s: out of memory\n", script->file);
    draw_script_free(script);
    return 1;
}

static void state_init(const draw_script *script, draw_state *state)
{
    memset(state, 0, sizeof *state);
    state->file = script->file;
    state->json_array = script->json_array;
    state->background = (cg_rgba8){255, 255, 255, 255};
    state->color = (cg_rgba8){0, 0, 0, 255};
    state->tolerance = 0.25;
    state->fill_rule = 1; /* CG_FILL_NONZERO, as in SVG */
    state->line_width = 1;
}

static int run_lines(const draw_script *script, draw_state *state)
{
    for (int i = 0; i < script->count; i++) {
        const draw_line *line = &script->lines[i];
        state->line = line->number;
        state->next_lines = line + 1;
        state->next_count = script->count - i - 1;
        state->consumed = 0;
        if (line->command->run(state, line->argc, line->argv))
            return 1;
        i += state->consumed;
    }
    return 0;
}

int draw_script_run(const draw_script *script, draw_state *state)
{
    state_init(script, state);
    if (run_lines(script, state))
        return 1;
    if (!state->canvas) {
        state->line = script->count ? script->lines[script->count - 1].number : 1;
        return draw_error(state, "expected a 'size W H' command: the script draws no canvas");
    }
    return 0;
}

int draw_script_run_on(const draw_script *script, cg_image *canvas)
{
    draw_state state;
    state_init(script, &state);
    state.canvas = canvas;
    int status = run_lines(script, &state);
    state.canvas = NULL; /* the caller's; `size` refuses to replace it */
    draw_state_release(&state);
    return status;
}

void draw_state_release(draw_state *state)
{
    draw_fill_release(state);
    draw_text_release(state);
    cg_image_free(state->canvas);
    state->canvas = NULL;
}
