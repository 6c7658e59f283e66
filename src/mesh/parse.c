/* Number parsing for the text mesh formats.
 *
 * parse_double reads decimal numbers by hand: the digits go into a 64-bit
 * integer m and the decimal exponent into e.  When m < 2^53 and |e| <= 22,
 * both m and 10^|e| are exact doubles, so one IEEE multiplication or
 * division gives the correctly rounded value (Clinger's fast path).  Any
 * other form (more than 19 significant digits, large exponents, inf, nan,
 * hexadecimal) goes through strtod, which rounds correctly too. */
#include "internal.h"

#include <stdio.h>
#include <stdlib.h>

static const double powers_of_ten[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                         1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                         1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

static inline int is_delimiter(const char *p, const char *end)
{
    return p >= end || is_space(*p) || *p == '/' || *p == '#';
}

/* The token at p (up to a delimiter) through strtod. */
static int parse_double_slow(const char **p, const char *end, double *out)
{
    const char *q = *p;
    while (!is_delimiter(q, end))
        q++;
    size_t length = (size_t)(q - *p);
    char buffer[512];
    if (length == 0 || length >= sizeof buffer)
        return 0;
    memcpy(buffer, *p, length);
    buffer[length] = '\0';
    char *stop;
    double value = strtod(buffer, &stop);
    if (stop != buffer + length)
        return 0;
    *out = value;
    *p = q;
    return 1;
}

int parse_double(const char **p, const char *end, double *out)
{
    const char *s = *p;
    int negative = 0;
    if (s < end && (*s == '-' || *s == '+')) {
        negative = *s == '-';
        s++;
    }
    uint64_t mantissa = 0;
    int digits = 0, exponent = 0, any = 0, inexact = 0;
    while (s < end && (unsigned)(*s - '0') < 10) {
        unsigned d = (unsigned)(*s - '0');
        any = 1;
        if (digits < 19) {
            mantissa = mantissa * 10 + d;
            digits += mantissa != 0;
        } else {
            exponent++;
            inexact |= d != 0;
        }
        s++;
    }
    if (s < end && *s == '.') {
        s++;
        while (s < end && (unsigned)(*s - '0') < 10) {
            unsigned d = (unsigned)(*s - '0');
            any = 1;
            if (digits < 19) {
                mantissa = mantissa * 10 + d;
                digits += mantissa != 0;
                exponent--;
            } else {
                inexact |= d != 0;
            }
            s++;
        }
    }
    if (!any)
        return parse_double_slow(p, end, out);
    if (s < end && (*s == 'e' || *s == 'E')) {
        s++;
        int exponent_negative = 0;
        if (s < end && (*s == '-' || *s == '+')) {
            exponent_negative = *s == '-';
            s++;
        }
        if (s >= end || (unsigned)(*s - '0') >= 10)
            return 0;
        int e = 0;
        while (s < end && (unsigned)(*s - '0') < 10) {
            if (e < 100000)
                e = e * 10 + (*s - '0');
            s++;
        }
        exponent += exponent_negative ? -e : e;
    }
    if (!is_delimiter(s, end))
        return 0;
    double value;
    if (mantissa == 0) {
        value = 0.0;
    } else if (!inexact && mantissa <= (UINT64_C(1) << 53) && exponent >= -22 && exponent <= 22) {
        value = (double)mantissa;
        value = exponent < 0 ? value / powers_of_ten[-exponent] : value * powers_of_ten[exponent];
    } else {
        return parse_double_slow(p, end, out);
    }
    *out = negative ? -value : value;
    *p = s;
    return 1;
}

int parse_int64(const char **p, const char *end, int64_t *out)
{
    const char *s = *p;
    int negative = 0;
    if (s < end && (*s == '-' || *s == '+')) {
        negative = *s == '-';
        s++;
    }
    if (s >= end || (unsigned)(*s - '0') >= 10)
        return 0;
    int64_t value = 0;
    while (s < end && (unsigned)(*s - '0') < 10) {
        if (value > (INT64_MAX - 9) / 10)
            return 0;
        value = value * 10 + (*s - '0');
        s++;
    }
    if (!is_delimiter(s, end))
        return 0;
    *out = negative ? -value : value;
    *p = s;
    return 1;
}

void text_skip_space_and_comments(text_cursor *t)
{
    while (t->p < t->end) {
        char c = *t->p;
        if (is_blank(c)) {
            t->p++;
        } else if (c == '#' || is_line_end(c)) {
            text_next_line(t);
        } else {
            break;
        }
    }
}

const char *text_describe(const text_cursor *t, char buffer[40])
{
    if (t->p >= t->end)
        return "the end of the file";
    if (is_line_end(*t->p))
        return "the end of the line";
    size_t n = 0;
    buffer[n++] = '\'';
    for (const char *q = t->p; q < t->end && !is_space(*q) && n < 25; q++)
        buffer[n++] = (*q >= 0x20 && *q < 0x7f) ? *q : '?';
    buffer[n++] = '\'';
    buffer[n] = '\0';
    return buffer;
}

cg_status text_double(text_cursor *t, double *out, const char *what, cg_error *err)
{
    text_skip_blanks(t);
    if (t->p < t->end && parse_double(&t->p, t->end, out))
        return CG_OK;
    char buffer[40];
    return cg_error_set(err, CG_EFORMAT, "%s:%zu: expected %s, got %s", t->name, t->line, what,
                        text_describe(t, buffer));
}
