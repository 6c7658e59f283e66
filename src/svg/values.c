/* Property and attribute values: numbers, lengths with units, colours,
 * transform lists, viewBox and preserveAspectRatio. */
#include "internal.h"
#include "cg/color.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *svg_skip(const char *s, int comma)
{
    while (*s && (isspace((unsigned char)*s) || (comma && *s == ',')))
        s++;
    return s;
}

/* The SVG number grammar: sign, digits, fraction, exponent (no inf, nan,
 * hex, which strtod would take). */
const char *svg_read_number(const char *s, double *out)
{
    const char *p = s;
    if (*p == '+' || *p == '-')
        p++;
    int digits = 0;
    while (isdigit((unsigned char)*p))
        p++, digits++;
    if (*p == '.') {
        p++;
        while (isdigit((unsigned char)*p))
            p++, digits++;
    }
    if (!digits)
        return NULL;
    if (*p == 'e' || *p == 'E') {
        const char *e = p + 1;
        if (*e == '+' || *e == '-')
            e++;
        if (isdigit((unsigned char)*e)) {
            while (isdigit((unsigned char)*e))
                e++;
            p = e;
        }
    }
    char buffer[64];
    size_t n = (size_t)(p - s);
    if (n >= sizeof buffer)
        n = sizeof buffer - 1; /* a number that long is not a useful coordinate */
    memcpy(buffer, s, n);
    buffer[n] = 0;
    double v = strtod(buffer, NULL);
    if (!isfinite(v))
        return NULL;
    *out = v;
    return p;
}

int svg_length(const char *text, svg_axis axis, const svg_viewport *viewport, double *out)
{
    if (!text)
        return -1;
    double v;
    const char *s = svg_read_number(svg_skip(text, 0), &v);
    if (!s)
        return -1;
    static const struct {
        const char *unit;
        double px;
    } units[] = {{"px", 1},         {"pt", 4.0 / 3.0}, {"pc", 16}, {"mm", 96 / 25.4},
                 {"cm", 96 / 2.54}, {"in", 96},        {"em", 16}, {"ex", 8}};
    if (*s == '%') {
        double base = axis == SVG_AXIS_X   ? viewport->width
                      : axis == SVG_AXIS_Y ? viewport->height
                                           : sqrt((viewport->width * viewport->width
                                                   + viewport->height * viewport->height)
                                                  / 2);
        v = v / 100 * base;
        s++;
    } else {
        for (size_t i = 0; i < sizeof units / sizeof *units; i++)
            if (strncmp(s, units[i].unit, 2) == 0) {
                v *= units[i].px;
                s += 2;
                break;
            }
    }
    if (*svg_skip(s, 0))
        return -1;
    *out = v;
    return 0;
}

double svg_length_attribute(const svg_node *node, const char *name, svg_axis axis,
                            const svg_viewport *viewport, double fallback)
{
    double v;
    return svg_length(svg_attribute_value(node, name), axis, viewport, &v) == 0 ? v : fallback;
}

int svg_unit_number(const char *text, double *out)
{
    if (!text)
        return -1;
    double v;
    const char *s = svg_read_number(svg_skip(text, 0), &v);
    if (!s)
        return -1;
    if (*s == '%') {
        v /= 100;
        s++;
    }
    if (*svg_skip(s, 0))
        return -1;
    *out = v < 0 ? 0 : (v > 1 ? 1 : v);
    return 0;
}

static int color_function(const char *s, cg_rgba8 *out)
{
    int alpha = strncmp(s, "rgba(", 5) == 0;
    s = svg_skip(s + (alpha ? 5 : 4), 0);
    double c[4] = {0, 0, 0, 1};
    for (int i = 0; i < 4; i++) {
        double v;
        const char *e = svg_read_number(s, &v);
        if (!e) {
            if (i == 3)
                break;
            return -1;
        }
        if (*e == '%') {
            v = i == 3 ? v / 100 : v * 2.55;
            e++;
        } else if (i == 3 && v > 1) {
            v = 1;
        }
        c[i] = v;
        s = svg_skip(e, 0);
        if (*s == ',' || *s == '/')
            s = svg_skip(s + 1, 0);
        if (*s == ')')
            break;
    }
    if (*s != ')')
        return -1;
    for (int i = 0; i < 3; i++)
        c[i] = c[i] < 0 ? 0 : (c[i] > 255 ? 255 : c[i]);
    out->r = (uint8_t)(c[0] + 0.5);
    out->g = (uint8_t)(c[1] + 0.5);
    out->b = (uint8_t)(c[2] + 0.5);
    double a = c[3] < 0 ? 0 : (c[3] > 1 ? 1 : c[3]);
    out->a = (uint8_t)(a * 255 + 0.5);
    return 0;
}

int svg_color(const char *text, cg_rgba8 *out)
{
    if (!text)
        return -1;
    text = svg_skip(text, 0);
    char word[64];
    size_t n = 0;
    while (text[n] && !isspace((unsigned char)text[n]) && n + 1 < sizeof word) {
        word[n] = text[n];
        n++;
    }
    word[n] = 0;
    if (strncmp(text, "rgb(", 4) == 0 || strncmp(text, "rgba(", 5) == 0)
        return color_function(text, out);
    for (size_t i = 0; i < n; i++)
        word[i] = (char)tolower((unsigned char)word[i]);
    if (strcmp(word, "currentcolor") == 0)
        return 1;
    if (*svg_skip(text + n, 0) && strncmp(svg_skip(text + n, 0), "!important", 10) != 0)
        return -1; /* a colour followed by more (an ICC colour) */
    return cg_color_parse(word, out, NULL) == CG_OK ? 0 : -1;
}

cg_mat3 svg_mat3_affine(double a, double b, double c, double d, double e, double f)
{
    cg_mat3 m = cg_mat3_identity();
    m.m[0][0] = a;
    m.m[1][0] = b;
    m.m[0][1] = c;
    m.m[1][1] = d;
    m.m[0][2] = e;
    m.m[1][2] = f;
    return m;
}

int svg_transform(const char *text, cg_mat3 *out)
{
    cg_mat3 m = cg_mat3_identity();
    const char *s = svg_skip(text ? text : "", 1);
    while (*s) {
        static const char *const names[] = {"matrix", "translate", "scale",
                                            "rotate", "skewX",     "skewY"};
        int which = -1;
        size_t len = 0;
        for (int i = 0; i < 6; i++) {
            len = strlen(names[i]);
            if (strncmp(s, names[i], len) == 0) {
                which = i;
                break;
            }
        }
        if (which < 0)
            return -1;
        s = svg_skip(s + len, 0);
        if (*s != '(')
            return -1;
        s++;
        double v[6];
        int count = 0;
        for (;;) {
            s = svg_skip(s, 1);
            if (*s == ')')
                break;
            if (count == 6 || !(s = svg_read_number(s, &v[count])))
                return -1;
            count++;
        }
        s++;
        static const int ok_counts[6][3] = {{6, 6, 6}, {1, 2, 2}, {1, 2, 2},
                                            {1, 3, 3}, {1, 1, 1}, {1, 1, 1}};
        if (count != ok_counts[which][0] && count != ok_counts[which][1]
            && count != ok_counts[which][2])
            return -1;
        cg_mat3 t;
        switch (which) {
        case 0: t = svg_mat3_affine(v[0], v[1], v[2], v[3], v[4], v[5]); break;
        case 1: t = svg_mat3_affine(1, 0, 0, 1, v[0], count > 1 ? v[1] : 0); break;
        case 2: t = svg_mat3_affine(v[0], 0, 0, count > 1 ? v[1] : v[0], 0, 0); break;
        case 3: {
            double a = v[0] * CG_PI / 180, c = cos(a), sn = sin(a);
            double cx = count == 3 ? v[1] : 0, cy = count == 3 ? v[2] : 0;
            /* translate(cx, cy) rotate(a) translate(-cx, -cy) */
            t = svg_mat3_affine(c, sn, -sn, c, cx - c * cx + sn * cy, cy - sn * cx - c * cy);
            break;
        }
        case 4: t = svg_mat3_affine(1, 0, tan(v[0] * CG_PI / 180), 1, 0, 0); break;
        default: t = svg_mat3_affine(1, tan(v[0] * CG_PI / 180), 0, 1, 0, 0); break;
        }
        m = cg_mat3_mul(m, t);
        s = svg_skip(s, 1);
    }
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(m.m[i][k]))
                return -1;
    *out = m;
    return 0;
}

int svg_view_box(const char *text, double *box)
{
    if (!text)
        return -1;
    const char *s = text;
    for (int i = 0; i < 4; i++) {
        s = svg_skip(s, 1);
        if (!(s = svg_read_number(s, &box[i])))
            return -1;
    }
    return box[2] > 0 && box[3] > 0 ? 0 : -1;
}

cg_mat3 svg_view_box_matrix(const double *box, double width, double height, const char *aspect)
{
    double sx = width / box[2], sy = height / box[3];
    const char *s = svg_skip(aspect ? aspect : "", 0);
    if (strncmp(s, "defer", 5) == 0)
        s = svg_skip(s + 5, 0);
    if (strncmp(s, "none", 4) == 0)
        return svg_mat3_affine(sx, 0, 0, sy, -box[0] * sx, -box[1] * sy);
    double ax = 0.5, ay = 0.5; /* xMidYMid */
    if (strlen(s) >= 8 && s[0] == 'x' && s[4] == 'Y') {
        ax = strncmp(s + 1, "Min", 3) == 0 ? 0 : strncmp(s + 1, "Max", 3) == 0 ? 1 : 0.5;
        ay = strncmp(s + 5, "Min", 3) == 0 ? 0 : strncmp(s + 5, "Max", 3) == 0 ? 1 : 0.5;
        s = svg_skip(s + 8, 0);
    }
    int slice = strncmp(s, "slice", 5) == 0;
    double scale = slice ? fmax(sx, sy) : fmin(sx, sy);
    double tx = (width - box[2] * scale) * ax - box[0] * scale;
    double ty = (height - box[3] * scale) * ay - box[1] * scale;
    return svg_mat3_affine(scale, 0, 0, scale, tx, ty);
}
