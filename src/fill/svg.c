/* SVG path data (the "d" attribute): M L H V C S Q T A Z, absolute and
 * relative, implicit repetition of commands, numbers as in the SVG grammar
 * (sign, digits, fraction, exponent; no inf, nan or hex), flags as single
 * 0 or 1 characters. */
#include "internal.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

typedef struct parser {
    const char *text, *at;
    cg_error *err;
    int too_large; /* length of the number at `at` when it was beyond CG_FILL_MAX_COORD */
} parser;

static void skip_separators(parser *p)
{
    while (*p->at && (isspace((unsigned char)*p->at) || *p->at == ','))
        p->at++;
}

static cg_status fail(parser *p, const char *what, char command)
{
    if (p->too_large) /* still CG_EFORMAT, as cg/fill.h says of every data error */
        return cg_error_set(p->err, CG_EFORMAT,
                            "path data, offset %ld: %.*s after '%c' is out of range: coordinates "
                            "are at most 2^40 = 1099511627776 in magnitude",
                            (long)(p->at - p->text), p->too_large, p->at, command);
    const char *found = *p->at ? p->at : "end of data";
    int len = *p->at ? 1 : (int)strlen(found);
    return cg_error_set(p->err, CG_EFORMAT,
                        "path data, offset %ld: expected %s after '%c', got '%.*s'",
                        (long)(p->at - p->text), what, command, len, found);
}

/* Reads a number; 0 when none is there. */
static int read_number(parser *p, double *out)
{
    p->too_large = 0;
    skip_separators(p);
    const char *s = p->at, *q = s;
    if (*q == '+' || *q == '-')
        q++;
    int digits = 0;
    while (isdigit((unsigned char)*q)) {
        q++;
        digits++;
    }
    if (*q == '.') {
        q++;
        while (isdigit((unsigned char)*q)) {
            q++;
            digits++;
        }
    }
    if (!digits)
        return 0;
    if (*q == 'e' || *q == 'E') {
        const char *e = q + 1;
        if (*e == '+' || *e == '-')
            e++;
        if (isdigit((unsigned char)*e)) {
            while (isdigit((unsigned char)*e))
                e++;
            q = e;
        }
    }
    char buffer[64];
    size_t n = (size_t)(q - s);
    if (n >= sizeof buffer)
        return 0;
    memcpy(buffer, s, n);
    buffer[n] = 0;
    double v = strtod(buffer, NULL);
    if (!(fabs(v) <= CG_FILL_MAX_COORD)) {
        p->too_large = (int)n;
        return 0;
    }
    *out = v;
    p->at = q;
    return 1;
}

static int read_flag(parser *p, int *out)
{
    skip_separators(p);
    if (*p->at != '0' && *p->at != '1')
        return 0;
    *out = *p->at == '1';
    p->at++;
    return 1;
}

/* Whether another argument group follows (a number starts here). */
static int number_follows(parser *p)
{
    skip_separators(p);
    char c = *p->at;
    return isdigit((unsigned char)c) || c == '.' || c == '-' || c == '+';
}

static cg_status parse(parser *p, cg_path *path)
{
    skip_separators(p);
    if (!*p->at)
        return CG_OK;
    if (*p->at != 'M' && *p->at != 'm')
        return cg_error_set(p->err, CG_EFORMAT,
                            "path data, offset %ld: expected a moveto (M or m), got '%c'",
                            (long)(p->at - p->text), *p->at);
    char previous = 0;
    cg_vec2 control = {0, 0}; /* last control point of a C/S or Q/T */
    while (1) {
        skip_separators(p);
        if (!*p->at)
            return CG_OK;
        char command = *p->at;
        if (!strchr("MmLlHhVvCcSsQqTtAaZz", command))
            return cg_error_set(p->err, CG_EFORMAT,
                                "path data, offset %ld: expected a command letter, got '%c'",
                                (long)(p->at - p->text), command);
        p->at++;
        char upper = (char)toupper((unsigned char)command);
        int relative = command != upper;
        int first = 1;
        do {
            cg_vec2 cur = fill_path_current(path);
            double ox = relative ? cur.x : 0, oy = relative ? cur.y : 0;
            double a[7];
            int flags[2];
            cg_status status = CG_OK;
            switch (upper) {
            case 'Z': status = cg_path_close(path); break;
            case 'M':
            case 'L':
            case 'T':
                if (!read_number(p, &a[0]) || !read_number(p, &a[1]))
                    return fail(p, "a coordinate", command);
                if (upper == 'M' && first)
                    status = cg_path_move_to(path, a[0] + ox, a[1] + oy);
                else if (upper == 'T') {
                    cg_vec2 c = previous == 'Q' || previous == 'T'
                                    ? cg_vec2_make(2 * cur.x - control.x, 2 * cur.y - control.y)
                                    : cur;
                    control = c;
                    status = cg_path_quad_to(path, c.x, c.y, a[0] + ox, a[1] + oy);
                } else
                    status = cg_path_line_to(path, a[0] + ox, a[1] + oy);
                break;
            case 'H':
                if (!read_number(p, &a[0]))
                    return fail(p, "a coordinate", command);
                status = cg_path_line_to(path, a[0] + ox, cur.y);
                break;
            case 'V':
                if (!read_number(p, &a[0]))
                    return fail(p, "a coordinate", command);
                status = cg_path_line_to(path, cur.x, a[0] + oy);
                break;
            case 'C':
                for (int i = 0; i < 6; i++)
                    if (!read_number(p, &a[i]))
                        return fail(p, "a coordinate", command);
                control = cg_vec2_make(a[2] + ox, a[3] + oy);
                status = cg_path_cubic_to(path, a[0] + ox, a[1] + oy, a[2] + ox, a[3] + oy,
                                          a[4] + ox, a[5] + oy);
                break;
            case 'S': {
                for (int i = 0; i < 4; i++)
                    if (!read_number(p, &a[i]))
                        return fail(p, "a coordinate", command);
                cg_vec2 c1 = previous == 'C' || previous == 'S'
                                 ? cg_vec2_make(2 * cur.x - control.x, 2 * cur.y - control.y)
                                 : cur;
                control = cg_vec2_make(a[0] + ox, a[1] + oy);
                status = cg_path_cubic_to(path, c1.x, c1.y, a[0] + ox, a[1] + oy, a[2] + ox,
                                          a[3] + oy);
                break;
            }
            case 'Q':
                for (int i = 0; i < 4; i++)
                    if (!read_number(p, &a[i]))
                        return fail(p, "a coordinate", command);
                control = cg_vec2_make(a[0] + ox, a[1] + oy);
                status = cg_path_quad_to(path, a[0] + ox, a[1] + oy, a[2] + ox, a[3] + oy);
                break;
            case 'A':
                for (int i = 0; i < 3; i++)
                    if (!read_number(p, &a[i]))
                        return fail(p, "a number", command);
                if (!read_flag(p, &flags[0]) || !read_flag(p, &flags[1]))
                    return fail(p, "a flag (0 or 1)", command);
                if (!read_number(p, &a[3]) || !read_number(p, &a[4]))
                    return fail(p, "a coordinate", command);
                status = cg_path_svg_arc_to(path, a[0], a[1], a[2], flags[0], flags[1], a[3] + ox,
                                            a[4] + oy);
                break;
            }
            if (status != CG_OK)
                return cg_error_set(p->err, status, "path data, offset %ld: %s",
                                    (long)(p->at - p->text), cg_status_str(status));
            previous = upper == 'M' ? 'L' : upper;
            if (upper == 'M' && first)
                previous = 'M';
            first = 0;
        } while (upper != 'Z' && number_follows(p));
    }
}

cg_status cg_path_append_svg(cg_path *path, const char *data, cg_error *err)
{
    cg_error_clear(err);
    if (!path || !data)
        return cg_error_set(err, CG_EINVAL, "path data: no path or no text");
    fill_path_mark mark;
    fill_path_save(path, &mark);
    parser p = {data, data, err, 0};
    cg_status status = parse(&p, path);
    if (status != CG_OK)
        fill_path_restore(path, &mark);
    return status;
}
