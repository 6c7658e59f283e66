/* Number parsing for the text mesh formats.
 *
 * parse_double reads decimal numbers by hand: the digits go into a 64-bit
 * integer m and the decimal exponent into e.  When m < 2^53 and |e| <= 22,
 * both m and 10^|e| are exact doubles, so one IEEE multiplication or
 * division gives the correctly rounded value (Clinger's fast path).
 *
 * Up to 19 digits (m < 2^64) with |e| <= 27 the same holds one size up
 * where long double has a 64-bit significand (x87): m and 10^|e| are exact
 * there, so r = m * 10^e or m / 10^-e is the exact value rounded once to 64
 * bits, within half a unit of its last bit.  Rounding r to double then gives
 * the correctly rounded double unless r lies on (or next to) a point halfway
 * between two doubles, which shows in r's 11 low significand bits; those
 * rare cases, and r with all 11 low bits zero (also what an emulator that
 * computes long double in double precision gives), go to strtod.
 *
 * Any other form (more than 19 significant digits, larger exponents, inf,
 * nan) goes through strtod, which rounds correctly too. */
#include "internal.h"

#include <float.h>
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

/* m * 10^e rounded correctly to double through long double, when that is
 * sure (see the top of the file); 0 when the caller must use strtod. */
static int wide_path(uint64_t m, int e, double *out)
{
#if LDBL_MANT_DIG == 64
    /* exact: 10^27 = 5^27 2^27 and 5^27 < 2^64 */
    static const long double powers[28] = {1e0L,  1e1L,  1e2L,  1e3L,  1e4L,  1e5L,  1e6L,
                                           1e7L,  1e8L,  1e9L,  1e10L, 1e11L, 1e12L, 1e13L,
                                           1e14L, 1e15L, 1e16L, 1e17L, 1e18L, 1e19L, 1e20L,
                                           1e21L, 1e22L, 1e23L, 1e24L, 1e25L, 1e26L, 1e27L};
    long double r = (long double)m; /* exact: m < 2^64 */
    r = e < 0 ? r / powers[-e] : r * powers[e];
    uint64_t significand;
    memcpy(&significand, &r, sizeof significand); /* x87: the 64 low bytes */
    unsigned low = (unsigned)(significand & 0x7ff);
    if (low == 0 || low == 0x3ff || low == 0x400 || low == 0x401)
        return 0;
    *out = (double)r;
    return 1;
#else
    (void)m;
    (void)e;
    (void)out;
    return 0;
#endif
}

int parse_double(const char **p, const char *end, double *out)
{
    const char *s = *p;
    int negative = 0;
    if (s < end && (*s == '-' || *s == '+')) {
        negative = *s == '-';
        s++;
    }
    /* the digits, all of them into m; more than 19 may wrap m, and then the
     * number goes to strtod */
    uint64_t mantissa = 0;
    const char *first = s;
    while (s < end && (unsigned)(*s - '0') < 10)
        mantissa = mantissa * 10 + (unsigned)(*s++ - '0');
    size_t digits = (size_t)(s - first), fraction = 0;
    if (s < end && *s == '.') {
        const char *point = ++s;
        while (s < end && (unsigned)(*s - '0') < 10)
            mantissa = mantissa * 10 + (unsigned)(*s++ - '0');
        fraction = (size_t)(s - point);
        digits += fraction;
    }
    if (digits == 0)
        return parse_double_slow(p, end, out); /* inf, nan, or not a number */
    int exponent = 0;
    if (s < end && (*s == 'e' || *s == 'E')) {
        s++;
        int exponent_negative = 0;
        if (s < end && (*s == '-' || *s == '+')) {
            exponent_negative = *s == '-';
            s++;
        }
        if (s >= end || (unsigned)(*s - '0') >= 10)
            return 0;
        while (s < end && (unsigned)(*s - '0') < 10) {
            if (exponent < 100000)
                exponent = exponent * 10 + (*s - '0');
            s++;
        }
        if (exponent_negative)
            exponent = -exponent;
    }
    if (!is_delimiter(s, end))
        return 0;
    if (digits > 19)
        return parse_double_slow(p, end, out);
    exponent -= (int)fraction;
    double value;
    if (mantissa == 0) {
        value = 0.0;
    } else if (mantissa <= (UINT64_C(1) << 53) && exponent >= -22 && exponent <= 22) {
        value = (double)mantissa;
        value = exponent < 0 ? value / powers_of_ten[-exponent] : value * powers_of_ten[exponent];
    } else if (exponent < -27 || exponent > 27 || !wide_path(mantissa, exponent, &value)) {
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
    const char *first = s;
    uint64_t value = 0; /* at most 18 digits: no overflow */
    while (s < end && (unsigned)(*s - '0') < 10)
        value = value * 10 + (unsigned)(*s++ - '0');
    if (s == first || s - first > 18 || !is_delimiter(s, end))
        return 0;
    *out = negative ? -(int64_t)value : (int64_t)value;
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

cg_status text_expected(const text_cursor *t, const char *what, cg_error *err)
{
    char buffer[40];
    return cg_error_set(err, CG_EFORMAT, "%s:%zu: expected %s, got %s", t->name, t->line, what,
                        text_describe(t, buffer));
}

cg_status text_double(text_cursor *t, double *out, const char *what, cg_error *err)
{
    text_skip_blanks(t);
    if (t->p < t->end && parse_double(&t->p, t->end, out))
        return CG_OK;
    return text_expected(t, what, err);
}
