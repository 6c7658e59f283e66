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
#undef VALUE
}
