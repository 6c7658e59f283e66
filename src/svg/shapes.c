/* The geometry of SVG's shapes in user space: path, rect (rounded), circle,
 * ellipse, line, polyline, polygon. */
#include "internal.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const shapes[] = {"path", "rect",     "circle", "ellipse",
                                     "line", "polyline", "polygon"};

int svg_is_shape(const char *name)
{
    for (size_t i = 0; i < sizeof shapes / sizeof *shapes; i++)
        if (strcmp(name, shapes[i]) == 0)
            return 1;
    return 0;
}

/* Path data with an error: SVG draws it up to the command in error.  The
 * reader's message gives the byte offset of the error; the data before
 * the last command letter at or before it is read again. */
static int path_data(const svg_node *node, cg_path *out)
{
    const char *d = svg_attribute_value(node, "d");
    if (!d)
        return 0;
    cg_error err;
    if (cg_path_append_svg(out, d, &err) == CG_OK)
        return !cg_path_is_empty(out);
    long offset = -1;
    const char *at = strstr(err.message, "offset ");
    if (at)
        offset = strtol(at + 7, NULL, 10);
    if (offset <= 0 || (size_t)offset > strlen(d))
        return !cg_path_is_empty(out);
    char *prefix = malloc((size_t)offset + 1);
    if (!prefix)
        return 0;
    /* the data before the error (an unknown command there), else before
     * the last command letter (a command short of its numbers) */
    memcpy(prefix, d, (size_t)offset);
    prefix[offset] = 0;
    if (cg_path_append_svg(out, prefix, NULL) != CG_OK) {
        long cut = offset - 1;
        while (cut > 0 && !(isalpha((unsigned char)d[cut]) && d[cut] != 'e' && d[cut] != 'E'))
            cut--;
        prefix[cut > 0 ? cut : 0] = 0;
        cg_path_append_svg(out, prefix, NULL);
    }
    free(prefix);
    return !cg_path_is_empty(out);
}

/* rx and ry of a rect: one given sets both; each at most half the side. */
static void corner_radii(const svg_node *node, const svg_viewport *vp, double w, double h,
                         double *rx, double *ry)
{
    double x = svg_length_attribute(node, "rx", SVG_AXIS_X, vp, -1);
    double y = svg_length_attribute(node, "ry", SVG_AXIS_Y, vp, -1);
    if (x < 0 && y < 0)
        x = y = 0;
    else if (x < 0)
        x = y;
    else if (y < 0)
        y = x;
    *rx = fmin(x, w / 2);
    *ry = fmin(y, h / 2);
}

static int rect_path(const svg_node *node, const svg_viewport *vp, cg_path *out)
{
    double x = svg_length_attribute(node, "x", SVG_AXIS_X, vp, 0);
    double y = svg_length_attribute(node, "y", SVG_AXIS_Y, vp, 0);
    double w = svg_length_attribute(node, "width", SVG_AXIS_X, vp, 0);
    double h = svg_length_attribute(node, "height", SVG_AXIS_Y, vp, 0);
    if (!(w > 0 && h > 0))
        return 0;
    double rx, ry;
    corner_radii(node, vp, w, h, &rx, &ry);
    cg_status s;
    if (rx > 0 && ry > 0) {
        s = cg_path_move_to(out, x + rx, y);
        if (s == CG_OK)
            s = cg_path_line_to(out, x + w - rx, y);
        if (s == CG_OK)
            s = cg_path_svg_arc_to(out, rx, ry, 0, 0, 1, x + w, y + ry);
        if (s == CG_OK)
            s = cg_path_line_to(out, x + w, y + h - ry);
        if (s == CG_OK)
            s = cg_path_svg_arc_to(out, rx, ry, 0, 0, 1, x + w - rx, y + h);
        if (s == CG_OK)
            s = cg_path_line_to(out, x + rx, y + h);
        if (s == CG_OK)
            s = cg_path_svg_arc_to(out, rx, ry, 0, 0, 1, x, y + h - ry);
        if (s == CG_OK)
            s = cg_path_line_to(out, x, y + ry);
        if (s == CG_OK)
            s = cg_path_svg_arc_to(out, rx, ry, 0, 0, 1, x + rx, y);
    } else {
        s = cg_path_move_to(out, x, y);
        if (s == CG_OK)
            s = cg_path_line_to(out, x + w, y);
        if (s == CG_OK)
            s = cg_path_line_to(out, x + w, y + h);
        if (s == CG_OK)
            s = cg_path_line_to(out, x, y + h);
    }
    if (s == CG_OK)
        s = cg_path_close(out);
    return s == CG_OK;
}

/* An ellipse as four arcs, starting at its rightmost point and going
 * clockwise on screen (as browsers start it, which dashes show). */
static int ellipse_path(double cx, double cy, double rx, double ry, cg_path *out)
{
    if (!(rx > 0 && ry > 0))
        return 0;
    cg_status s = cg_path_move_to(out, cx + rx, cy);
    if (s == CG_OK)
        s = cg_path_svg_arc_to(out, rx, ry, 0, 0, 1, cx, cy + ry);
    if (s == CG_OK)
        s = cg_path_svg_arc_to(out, rx, ry, 0, 0, 1, cx - rx, cy);
    if (s == CG_OK)
        s = cg_path_svg_arc_to(out, rx, ry, 0, 0, 1, cx, cy - ry);
    if (s == CG_OK)
        s = cg_path_svg_arc_to(out, rx, ry, 0, 0, 1, cx + rx, cy);
    if (s == CG_OK)
        s = cg_path_close(out);
    return s == CG_OK;
}

static int points_path(const svg_node *node, int close, cg_path *out)
{
    const char *s = svg_attribute_value(node, "points");
    if (!s)
        return 0;
    int count = 0;
    for (;;) {
        double x, y;
        s = svg_skip(s, 1);
        const char *after_x = svg_read_number(s, &x);
        if (!after_x)
            break;
        const char *after_y = svg_read_number(svg_skip(after_x, 1), &y);
        if (!after_y)
            break; /* an odd number of coordinates: the last is dropped */
        s = after_y;
        cg_status st = count ? cg_path_line_to(out, x, y) : cg_path_move_to(out, x, y);
        if (st != CG_OK)
            return 0;
        count++;
    }
    if (count < 2)
        return 0;
    if (close)
        cg_path_close(out);
    return 1;
}

int svg_shape_path(const svg_node *node, const svg_viewport *vp, cg_path *out)
{
    const char *name = node->name;
    if (strcmp(name, "path") == 0)
        return path_data(node, out);
    if (strcmp(name, "rect") == 0)
        return rect_path(node, vp, out);
    if (strcmp(name, "circle") == 0) {
        double r = svg_length_attribute(node, "r", SVG_AXIS_DIAGONAL, vp, 0);
        return ellipse_path(svg_length_attribute(node, "cx", SVG_AXIS_X, vp, 0),
                            svg_length_attribute(node, "cy", SVG_AXIS_Y, vp, 0), r, r, out);
    }
    if (strcmp(name, "ellipse") == 0) {
        double rx = svg_length_attribute(node, "rx", SVG_AXIS_X, vp, -1);
        double ry = svg_length_attribute(node, "ry", SVG_AXIS_Y, vp, -1);
        if (rx < 0)
            rx = ry; /* SVG 2: auto takes the other radius */
        if (ry < 0)
            ry = rx;
        return ellipse_path(svg_length_attribute(node, "cx", SVG_AXIS_X, vp, 0),
                            svg_length_attribute(node, "cy", SVG_AXIS_Y, vp, 0), rx, ry, out);
    }
    if (strcmp(name, "line") == 0) {
        double x1 = svg_length_attribute(node, "x1", SVG_AXIS_X, vp, 0);
        double y1 = svg_length_attribute(node, "y1", SVG_AXIS_Y, vp, 0);
        double x2 = svg_length_attribute(node, "x2", SVG_AXIS_X, vp, 0);
        double y2 = svg_length_attribute(node, "y2", SVG_AXIS_Y, vp, 0);
        return cg_path_move_to(out, x1, y1) == CG_OK && cg_path_line_to(out, x2, y2) == CG_OK;
    }
    if (strcmp(name, "polyline") == 0)
        return points_path(node, 0, out);
    if (strcmp(name, "polygon") == 0)
        return points_path(node, 1, out);
    return 0;
}
