/* Computed style: each element's inherited properties from its parent's
 * and its own declarations (css.c cascaded them onto the element). */
#include "internal.h"

#include <math.h>
#include <string.h>

void svg_initial_style(svg_style *s)
{
    memset(s, 0, sizeof *s);
    s->fill.kind = SVG_PAINT_COLOR;
    s->fill.color = (cg_rgba8){0, 0, 0, 255};
    s->stroke.kind = SVG_PAINT_NONE;
    s->fill_opacity = s->stroke_opacity = 1;
    s->fill_rule = s->clip_rule = CG_FILL_NONZERO;
    s->stroke_width = 1;
    s->cap = CG_CAP_BUTT;
    s->join = CG_JOIN_MITER;
    s->miter_limit = 4;
    s->color = (cg_rgba8){0, 0, 0, 255};
    s->visible = 1;
    s->font_size = 16;
    s->font_weight = 400;
}

static int keyword(const char *value, const char *word)
{
    return value && strcmp(value, word) == 0;
}

/* fill or stroke: none, a colour, currentColor, url(#id) [fallback]; an
 * unknown value or a reference to nothing keeps the inherited paint (a
 * reference with a fallback takes the fallback). */
static void paint_value(const svg_render *r, const char *value, svg_paint_spec *paint)
{
    if (!value || keyword(value, "inherit"))
        return;
    if (keyword(value, "none")) {
        paint->kind = SVG_PAINT_NONE;
        return;
    }
    if (strncmp(value, "url(", 4) == 0) {
        const svg_node *server = svg_find_reference(r->svg, value);
        const char *close = strchr(value, ')');
        const char *fallback = close ? svg_skip(close + 1, 0) : "";
        if (server
            && (strcmp(server->name, "linearGradient") == 0
                || strcmp(server->name, "radialGradient") == 0)) {
            paint->kind = SVG_PAINT_SERVER;
            paint->server = server;
            return;
        }
        if (server && strcmp(server->name, "pattern") != 0)
            server = NULL; /* not a paint server */
        if (*fallback) {
            paint_value(r, fallback, paint);
            return;
        }
        /* a pattern (unsupported, warned) or a missing server: nothing */
        paint->kind = SVG_PAINT_NONE;
        return;
    }
    cg_rgba8 c;
    int k = svg_color(value, &c);
    if (k == 1) {
        paint->kind = SVG_PAINT_CURRENT_COLOR;
    } else if (k == 0) {
        paint->kind = SVG_PAINT_COLOR;
        paint->color = c;
    }
}

static void opacity_value(const char *value, double *out)
{
    double v;
    if (value && svg_unit_number(value, &v) == 0)
        *out = v;
}

static void dash_value(const char *value, const svg_viewport *vp, svg_style *s)
{
    if (!value || keyword(value, "inherit"))
        return;
    s->dash_count = 0;
    if (keyword(value, "none"))
        return;
    double sum = 0;
    const char *p = value;
    int count = 0;
    double dashes[SVG_MAX_DASHES];
    while (*(p = svg_skip(p, 1))) {
        const char *end = p;
        while (*end && *end != ',' && *end != ' ' && *end != '\t' && *end != '\n')
            end++;
        char word[64];
        size_t n = (size_t)(end - p) < sizeof word - 1 ? (size_t)(end - p) : sizeof word - 1;
        memcpy(word, p, n);
        word[n] = 0;
        double v;
        if (count == SVG_MAX_DASHES || svg_length(word, SVG_AXIS_DIAGONAL, vp, &v) != 0 || v < 0)
            return; /* malformed: solid */
        dashes[count++] = v;
        sum += v;
        p = end;
    }
    if (count == 0 || !(sum > 0))
        return;
    memcpy(s->dashes, dashes, (size_t)count * sizeof *dashes);
    s->dash_count = count;
}

/* font-size: a length, a percentage or em of the parent's size, or a
 * keyword of CSS's absolute and relative sizes. */
static void font_size_value(const char *value, const svg_viewport *vp, double *size)
{
    static const struct {
        const char *name;
        double px;
    } sizes[] = {{"xx-small", 9}, {"x-small", 10}, {"small", 13},    {"medium", 16},
                 {"large", 18},   {"x-large", 24}, {"xx-large", 32}, {"xxx-large", 48}};
    if (!value || keyword(value, "inherit"))
        return;
    for (size_t i = 0; i < sizeof sizes / sizeof *sizes; i++)
        if (keyword(value, sizes[i].name)) {
            *size = sizes[i].px;
            return;
        }
    if (keyword(value, "larger") || keyword(value, "smaller")) {
        *size = keyword(value, "larger") ? *size * 1.2 : *size / 1.2;
        return;
    }
    double v;
    const char *end = svg_read_number(svg_skip(value, 0), &v);
    if (!end)
        return;
    if (*end == '%' && !*svg_skip(end + 1, 0))
        v = *size * v / 100;
    else if (strncmp(end, "em", 2) == 0 && !*svg_skip(end + 2, 0))
        v = *size * v;
    else if (strncmp(end, "ex", 2) == 0 && !*svg_skip(end + 2, 0))
        v = *size * v / 2;
    else if (svg_length(value, SVG_AXIS_DIAGONAL, vp, &v) != 0)
        return;
    if (v >= 0 && v <= 1e6)
        *size = v;
}

/* font-weight: normal, bold, bolder, lighter (CSS's steps) or 1..1000. */
static void font_weight_value(const char *value, int *weight)
{
    if (!value || keyword(value, "inherit"))
        return;
    if (keyword(value, "normal")) {
        *weight = 400;
    } else if (keyword(value, "bold")) {
        *weight = 700;
    } else if (keyword(value, "bolder")) {
        *weight = *weight < 350 ? 400 : *weight < 550 ? 700 : 900;
    } else if (keyword(value, "lighter")) {
        *weight = *weight < 100 ? *weight : *weight < 550 ? 100 : *weight < 750 ? 400 : 700;
    } else {
        double v;
        const char *end = svg_read_number(svg_skip(value, 0), &v);
        if (end && !*svg_skip(end, 0) && v >= 1 && v <= 1000)
            *weight = (int)v;
    }
}

static void text_values(const svg_declared *d, const svg_viewport *vp, svg_style *s)
{
    const char *v;
    if ((v = d[SVG_FONT_FAMILY].value) != NULL && !keyword(v, "inherit") && *svg_skip(v, 0))
        s->font_family = v;
    font_size_value(d[SVG_FONT_SIZE].value, vp, &s->font_size);
    font_weight_value(d[SVG_FONT_WEIGHT].value, &s->font_weight);
    if ((v = d[SVG_FONT_STYLE].value) != NULL) {
        if (keyword(v, "italic") || keyword(v, "oblique"))
            s->italic = 1;
        else if (keyword(v, "normal"))
            s->italic = 0;
    }
    if ((v = d[SVG_TEXT_ANCHOR].value) != NULL) {
        if (keyword(v, "start"))
            s->text_anchor = 0;
        else if (keyword(v, "middle"))
            s->text_anchor = 1;
        else if (keyword(v, "end"))
            s->text_anchor = 2;
    }
}

void svg_compute_style(const svg_render *r, const svg_node *node, const svg_viewport *vp,
                       const svg_style *parent, svg_style *s)
{
    *s = *parent;
    const svg_declared *d = node->declared;
#define VALUE(p) (d[p].value)
    const char *v;
    if ((v = VALUE(SVG_COLOR)) != NULL) {
        cg_rgba8 c;
        if (svg_color(v, &c) == 0)
            s->color = c;
    }
    paint_value(r, VALUE(SVG_FILL), &s->fill);
    paint_value(r, VALUE(SVG_STROKE), &s->stroke);
    opacity_value(VALUE(SVG_FILL_OPACITY), &s->fill_opacity);
    opacity_value(VALUE(SVG_STROKE_OPACITY), &s->stroke_opacity);
    if ((v = VALUE(SVG_FILL_RULE)) != NULL) {
        if (keyword(v, "evenodd"))
            s->fill_rule = CG_FILL_EVEN_ODD;
        else if (keyword(v, "nonzero"))
            s->fill_rule = CG_FILL_NONZERO;
    }
    if ((v = VALUE(SVG_CLIP_RULE)) != NULL) {
        if (keyword(v, "evenodd"))
            s->clip_rule = CG_FILL_EVEN_ODD;
        else if (keyword(v, "nonzero"))
            s->clip_rule = CG_FILL_NONZERO;
    }
    double w;
    if ((v = VALUE(SVG_STROKE_WIDTH)) != NULL && svg_length(v, SVG_AXIS_DIAGONAL, vp, &w) == 0
        && w >= 0)
        s->stroke_width = w;
    if ((v = VALUE(SVG_STROKE_LINECAP)) != NULL) {
        if (keyword(v, "butt"))
            s->cap = CG_CAP_BUTT;
        else if (keyword(v, "round"))
            s->cap = CG_CAP_ROUND;
        else if (keyword(v, "square"))
            s->cap = CG_CAP_SQUARE;
    }
    if ((v = VALUE(SVG_STROKE_LINEJOIN)) != NULL) {
        if (keyword(v, "miter") || keyword(v, "miter-clip") || keyword(v, "arcs"))
            s->join = CG_JOIN_MITER;
        else if (keyword(v, "round"))
            s->join = CG_JOIN_ROUND;
        else if (keyword(v, "bevel"))
            s->join = CG_JOIN_BEVEL;
    }
    if ((v = VALUE(SVG_STROKE_MITERLIMIT)) != NULL) {
        double m;
        const char *end = svg_read_number(svg_skip(v, 0), &m);
        if (end && !*svg_skip(end, 0) && m >= 1)
            s->miter_limit = m;
    }
    dash_value(VALUE(SVG_STROKE_DASHARRAY), vp, s);
    if ((v = VALUE(SVG_STROKE_DASHOFFSET)) != NULL) {
        double o;
        if (svg_length(v, SVG_AXIS_DIAGONAL, vp, &o) == 0)
            s->dash_offset = o;
    }
    if ((v = VALUE(SVG_VISIBILITY)) != NULL) {
        if (keyword(v, "hidden") || keyword(v, "collapse"))
            s->visible = 0;
        else if (keyword(v, "visible"))
            s->visible = 1;
    }
    if ((v = VALUE(SVG_PAINT_ORDER)) != NULL && !keyword(v, "inherit")) {
        const char *fill = strstr(v, "fill"), *stroke = strstr(v, "stroke");
        s->stroke_first = stroke && (!fill || stroke < fill);
    }
    text_values(d, vp, s);
#undef VALUE
}
