/* Paint servers: linearGradient and radialGradient, their attributes and
 * stops inherited through href, in objectBoundingBox or userSpaceOnUse
 * units, made into a cg_paint with a transform (gradient space to pixels). */
#include "internal.h"

#include <math.h>
#include <string.h>

#define HREF_CHAIN 16

/* The gradient chain: the server, then what its href names, and so on
 * (stopping at a repeat or a non-gradient). */
static int chain_of(const svg_render *r, const svg_node *server, const svg_node **chain)
{
    int n = 0;
    while (server && n < HREF_CHAIN) {
        for (int i = 0; i < n; i++)
            if (chain[i] == server)
                return n;
        if (strcmp(server->name, "linearGradient") != 0
            && strcmp(server->name, "radialGradient") != 0)
            break;
        chain[n++] = server;
        server = svg_find_reference(r->svg, svg_href(server));
    }
    return n;
}

static const char *inherited(const svg_node *const *chain, int n, const char *name)
{
    for (int i = 0; i < n; i++) {
        const char *v = svg_attribute_value(chain[i], name);
        if (v)
            return v;
    }
    return NULL;
}

/* A coordinate: in bounding-box units a number or a fraction ("50%" is
 * 0.5), in user space a length of the viewport. */
static double coordinate(const char *text, int bbox_units, svg_axis axis, const svg_viewport *vp,
                         double fallback)
{
    if (!text)
        return fallback;
    double v;
    if (bbox_units) {
        const char *end = svg_read_number(svg_skip(text, 0), &v);
        if (!end)
            return fallback;
        if (*end == '%')
            v /= 100;
        return v;
    }
    return svg_length(text, axis, vp, &v) == 0 ? v : fallback;
}

static int stop_list(const svg_node *const *chain, int n, double opacity, cg_rgba8 current,
                     cg_gradient_stop *stops)
{
    const svg_node *holder = NULL;
    for (int i = 0; i < n && !holder; i++)
        for (const svg_node *c = chain[i]->first_child; c; c = c->next)
            if (strcmp(c->name, "stop") == 0) {
                holder = chain[i];
                break;
            }
    if (!holder)
        return 0;
    int count = 0;
    double last = 0;
    for (const svg_node *c = holder->first_child; c && count < 256; c = c->next) {
        if (strcmp(c->name, "stop") != 0)
            continue;
        double offset = 0, stop_opacity = 1;
        svg_unit_number(svg_attribute_value(c, "offset"), &offset);
        if (offset < last)
            offset = last; /* offsets never go back */
        last = offset;
        cg_rgba8 color = {0, 0, 0, 255}, own_color = current;
        const char *cv = c->declared[SVG_COLOR].value;
        if (cv)
            svg_color(cv, &own_color);
        const char *sc = c->declared[SVG_STOP_COLOR].value;
        if (sc && svg_color(sc, &color) == 1)
            color = own_color;
        const char *so = c->declared[SVG_STOP_OPACITY].value;
        if (so)
            svg_unit_number(so, &stop_opacity);
        color.a = (uint8_t)(color.a * stop_opacity * opacity + 0.5);
        stops[count].offset = offset;
        stops[count].color = color;
        count++;
    }
    return count;
}

int svg_gradient_paint(const svg_render *r, const svg_node *server, const cg_vec2 *bbox,
                       int has_bbox, cg_mat3 ctm, const svg_viewport *vp, double opacity,
                       cg_rgba8 current_color, cg_paint *paint, cg_gradient_stop *stops)
{
    const svg_node *chain[HREF_CHAIN];
    int n = chain_of(r, server, chain);
    if (n == 0)
        return 0;
    int count = stop_list(chain, n, opacity, current_color, stops);
    if (count == 0)
        return 0;
    if (count == 1) {
        if (stops[0].color.a == 0)
            return 0;
        *paint = cg_paint_solid(stops[0].color);
        return 1;
    }
    const char *units = inherited(chain, n, "gradientUnits");
    int bbox_units = !(units && strcmp(units, "userSpaceOnUse") == 0);
    cg_mat3 m = ctm;
    if (bbox_units) {
        if (!has_bbox)
            return 0;
        double w = bbox[1].x - bbox[0].x, h = bbox[1].y - bbox[0].y;
        if (!(w > 0 && h > 0))
            return 0; /* SVG: a bounding box of no area takes no gradient */
        m = cg_mat3_mul(m, svg_mat3_affine(w, 0, 0, h, bbox[0].x, bbox[0].y));
    }
    cg_mat3 t;
    const char *transform = inherited(chain, n, "gradientTransform");
    if (transform && svg_transform(transform, &t) == 0)
        m = cg_mat3_mul(m, t);
    if (!(fabs(cg_mat3_determinant(m)) > 1e-300))
        return 0;
    int radial = strcmp(server->name, "radialGradient") == 0;
    if (radial) {
        double cx = coordinate(inherited(chain, n, "cx"), bbox_units, SVG_AXIS_X, vp,
                               bbox_units ? 0.5 : vp->width / 2);
        double cy = coordinate(inherited(chain, n, "cy"), bbox_units, SVG_AXIS_Y, vp,
                               bbox_units ? 0.5 : vp->height / 2);
        double radius = coordinate(
            inherited(chain, n, "r"), bbox_units, SVG_AXIS_DIAGONAL, vp,
            bbox_units ? 0.5 : 0.5 * sqrt((vp->width * vp->width + vp->height * vp->height) / 2));
        double fx = coordinate(inherited(chain, n, "fx"), bbox_units, SVG_AXIS_X, vp, cx);
        double fy = coordinate(inherited(chain, n, "fy"), bbox_units, SVG_AXIS_Y, vp, cy);
        if (!(radius > 0)) { /* the last stop's colour */
            if (stops[count - 1].color.a == 0)
                return 0;
            *paint = cg_paint_solid(stops[count - 1].color);
            return 1;
        }
        *paint = cg_paint_radial(cg_vec2_make(cx, cy), radius, stops, count);
        if (fx != cx || fy != cy) {
            paint->has_focal = 1;
            paint->focal = cg_vec2_make(fx, fy);
        }
    } else {
        double x1 = coordinate(inherited(chain, n, "x1"), bbox_units, SVG_AXIS_X, vp, 0);
        double y1 = coordinate(inherited(chain, n, "y1"), bbox_units, SVG_AXIS_Y, vp, 0);
        double x2 = coordinate(inherited(chain, n, "x2"), bbox_units, SVG_AXIS_X, vp,
                               bbox_units ? 1 : vp->width);
        double y2 = coordinate(inherited(chain, n, "y2"), bbox_units, SVG_AXIS_Y, vp, 0);
        if (x1 == x2 && y1 == y2) { /* SVG: the last stop's colour */
            if (stops[count - 1].color.a == 0)
                return 0;
            *paint = cg_paint_solid(stops[count - 1].color);
            return 1;
        }
        *paint = cg_paint_linear(cg_vec2_make(x1, y1), cg_vec2_make(x2, y2), stops, count);
    }
    const char *spread = inherited(chain, n, "spreadMethod");
    if (spread && strcmp(spread, "reflect") == 0)
        paint->spread = CG_SPREAD_REFLECT;
    else if (spread && strcmp(spread, "repeat") == 0)
        paint->spread = CG_SPREAD_REPEAT;
    paint->has_transform = 1;
    paint->transform = m;
    return 1;
}
