/* WKT line strings, and the choice between them and polygons. */
#include "clip_paths.h"
#include "clip_view.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

typedef struct line_reader {
    const char *text, *name;
    size_t pos;
    cg_error *err;
} line_reader;

static void skip_space(line_reader *r)
{
    while (isspace((unsigned char)r->text[r->pos]))
        r->pos++;
}

static cg_status expected(line_reader *r, const char *what)
{
    return cg_error_set(r->err, CG_EFORMAT, "%s: offset %zu: expected %s", r->name, r->pos, what);
}

static int accept_char(line_reader *r, char c)
{
    skip_space(r);
    if (r->text[r->pos] != c)
        return 0;
    r->pos++;
    return 1;
}

static int accept_word(line_reader *r, const char *word)
{
    skip_space(r);
    size_t n = strlen(word);
    if (strncasecmp(r->text + r->pos, word, n) != 0 || isalnum((unsigned char)r->text[r->pos + n]))
        return 0;
    r->pos += n;
    return 1;
}

static int number(line_reader *r, double *out)
{
    skip_space(r);
    const char *start = r->text + r->pos;
    char *end;
    if (!(isdigit((unsigned char)*start) || *start == '-' || *start == '+' || *start == '.'))
        return 0;
    *out = strtod(start, &end);
    if (end == start)
        return 0;
    r->pos += (size_t)(end - start);
    return 1;
}

/* The coordinate pairs of "(X Y, X Y, ...)": counted into *count, and
 * stored in points when it is not NULL. */
static cg_status line_points(line_reader *r, cg_vec2 *points, size_t *count)
{
    if (!accept_char(r, '('))
        return expected(r, "'(' opening a line string, or EMPTY");
    *count = 0;
    do {
        double x, y;
        if (!number(r, &x) || !number(r, &y))
            return expected(r, "a coordinate pair 'X Y'");
        skip_space(r);
        if (isdigit((unsigned char)r->text[r->pos]) || r->text[r->pos] == '-')
            return expected(r, "',' or ')' (only 2D coordinates are read)");
        if (!isfinite(x) || !isfinite(y))
            return cg_error_set(r->err, CG_EINVAL, "%s: offset %zu: coordinate is not finite",
                                r->name, r->pos);
        if (points)
            points[*count] = cg_vec2_make(x, y);
        ++*count;
    } while (accept_char(r, ','));
    if (!accept_char(r, ')'))
        return expected(r, "',' or ')' closing a line string");
    return CG_OK;
}

/* "(X Y, X Y, ...)" as one open path of set, or EMPTY (nothing added): read
 * once to count and check, then again into an array of that size. */
static cg_status line_body(line_reader *r, cg_polygon_set *set)
{
    if (accept_word(r, "EMPTY"))
        return CG_OK;
    size_t start = r->pos, count = 0;
    cg_status st = line_points(r, NULL, &count);
    if (st != CG_OK)
        return st;
    cg_vec2 *points = malloc(count * sizeof *points);
    if (!points)
        return cg_error_set(r->err, CG_ENOMEM, "%s: out of memory", r->name);
    r->pos = start;
    st = line_points(r, points, &count);
    if (st == CG_OK && cg_polygon_set_add_ring(set, points, count, 1) != CG_OK)
        st = cg_error_set(r->err, CG_ENOMEM, "%s: out of memory", r->name);
    free(points);
    return st;
}

static cg_status parse_lines(line_reader *r, cg_polygon_set *set)
{
    cg_status st = CG_OK;
    if (accept_word(r, "MULTILINESTRING")) {
        if (!accept_word(r, "EMPTY")) {
            if (!accept_char(r, '('))
                return expected(r, "'(' or EMPTY after MULTILINESTRING");
            do
                st = line_body(r, set);
            while (st == CG_OK && accept_char(r, ','));
            if (st == CG_OK && !accept_char(r, ')'))
                st = expected(r, "',' or ')' closing the MULTILINESTRING");
        }
    } else if (accept_word(r, "LINESTRING")) {
        st = line_body(r, set);
    }
    skip_space(r);
    if (st == CG_OK && r->text[r->pos])
        st = expected(r, "the end of the text");
    return st;
}

/* The whole file as a NUL-terminated text (free it), gathered by the C
 * library's memory stream. */
static cg_status read_text(const char *path, char **text, cg_error *err)
{
    FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    if (!f)
        return cg_error_set(err, CG_EIO, "%s: cannot open", path);
    size_t size = 0;
    *text = NULL;
    FILE *memory = open_memstream(text, &size);
    cg_status st = memory ? CG_OK : cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    char chunk[65536];
    size_t got;
    while (st == CG_OK && (got = fread(chunk, 1, sizeof chunk, f)) > 0)
        if (fwrite(chunk, 1, got, memory) != got)
            st = cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    if (st == CG_OK && ferror(f))
        st = cg_error_set(err, CG_EIO, "%s: read error", path);
    if (memory && fclose(memory) != 0 && st == CG_OK)
        st = cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    if (f != stdin)
        fclose(f);
    if (st == CG_OK && strlen(*text) != size)
        st = cg_error_set(err, CG_EFORMAT, "%s: offset %zu: unexpected NUL byte", path,
                          strlen(*text));
    if (st != CG_OK) {
        free(*text);
        *text = NULL;
    }
    return st;
}

cg_status clip_paths_read(const char *path, cg_polygon_set *set, int *open, cg_error *err)
{
    char *text = NULL;
    cg_status st = read_text(path, &text, err);
    if (st != CG_OK)
        return st;
    const char *name = strcmp(path, "-") == 0 ? "stdin" : path;
    line_reader r = {text, name, 0, err};
    *open = accept_word(&r, "LINESTRING") || accept_word(&r, "MULTILINESTRING");
    if (*open) {
        r.pos = 0;
        st = parse_lines(&r, set);
    } else {
        st = clip_wkt_parse(text, name, set, err);
        if (st == CG_EFORMAT && err && strstr(err->message, "POLYGON or MULTIPOLYGON"))
            st = cg_error_set(err, CG_EFORMAT,
                              "%s: offset 0: expected POLYGON, MULTIPOLYGON, "
                              "LINESTRING or MULTILINESTRING",
                              name);
    }
    free(text);
    return st;
}

void clip_paths_write_lines(FILE *out, const cg_polygon_set *set)
{
    if (!set || set->ring_count == 0) {
        fputs("MULTILINESTRING EMPTY\n", out);
        return;
    }
    fputs("MULTILINESTRING (", out);
    for (size_t r = 0; r < set->ring_count; r++) {
        fputs(r ? ", (" : "(", out);
        for (size_t i = set->ring_start[r]; i < set->ring_start[r + 1]; i++)
            fprintf(out, "%s%.15g %.15g", i > set->ring_start[r] ? ", " : "", set->points[i].x,
                    set->points[i].y);
        fputc(')', out);
    }
    fputs(")\n", out);
}
