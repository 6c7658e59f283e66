/* Drawing an SVG document: a walk of the element tree with the current
 * transformation matrix (user space to pixels), the viewport for
 * percentages and the inherited style.  A group with opacity, a blend mode,
 * a clip path or a mask is drawn into a transparent layer first and
 * composited as one piece (cg_rasterizer_composite_layer). */
#include "internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void svg_fail(svg_render *r, cg_status status, const char *format, ...)
{
    if (r->failure != CG_OK)
        return;
    r->failure = status;
    if (r->err) {
        char text[400];
        va_list args;
        va_start(args, format);
        vsnprintf(text, sizeof text, format, args);
        va_end(args);
        cg_error_set(r->err, status, "%s: %s", r->svg->name, text);
    }
}

void svg_touch(svg_render *r, svg_box b)
{
    b.x0 = fmax(0, floor(b.x0));
    b.y0 = fmax(0, floor(b.y0));
    b.x1 = fmin(r->width, ceil(b.x1));
    b.y1 = fmin(r->height, ceil(b.y1));
    if (!(b.x0 < b.x1 && b.y0 < b.y1))
        return;
    if (!(r->dirty.x0 < r->dirty.x1)) {
        r->dirty = b;
        return;
    }
    r->dirty.x0 = fmin(r->dirty.x0, b.x0);
    r->dirty.y0 = fmin(r->dirty.y0, b.y0);
    r->dirty.x1 = fmax(r->dirty.x1, b.x1);
    r->dirty.y1 = fmax(r->dirty.y1, b.y1);
}

int svg_spend(svg_render *r, double pixels)
{
    r->work += pixels;
    if (r->work <= SVG_MAX_WORK)
        return 1;
    svg_fail(r, CG_EFORMAT, "more than %.0f pixels to composite through groups, clips and masks",
             SVG_MAX_WORK);
    return 0;
}

/* The pixels a shape can touch: its user-space bounds through ctm, grown
 * by how far its stroke reaches and a pixel of anti-aliasing. */
static svg_box device_box(const cg_vec2 *bbox, cg_mat3 ctm, double reach)
{
    svg_box b = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int i = 0; i < 4; i++) {
        cg_vec2 p = cg_mat3_transform_point(ctm, cg_vec2_make(bbox[i & 1].x, bbox[i >> 1].y));
        b.x0 = fmin(b.x0, p.x);
        b.y0 = fmin(b.y0, p.y);
        b.x1 = fmax(b.x1, p.x);
        b.y1 = fmax(b.y1, p.y);
    }
    b.x0 -= reach + 1;
    b.y0 -= reach + 1;
    b.x1 += reach + 1;
    b.y1 += reach + 1;
    return b;
}

/* The scale of a similarity (rotation, uniform scale, reflection) or 0. */
static double similarity_scale(cg_mat3 m)
{
    double a = m.m[0][0], b = m.m[1][0], c = m.m[0][1], d = m.m[1][1];
    double sx = hypot(a, b), sy = hypot(c, d);
    if (!(sx > 0) || fabs(sx - sy) > 1e-9 * sx || fabs(a * c + b * d) > 1e-9 * sx * sx)
        return 0;
    return sx;
}

static double largest_scale(cg_mat3 m)
{
    double a = m.m[0][0], b = m.m[1][0], c = m.m[0][1], d = m.m[1][1];
    return fmax(hypot(a, b), hypot(c, d));
}

/* The paint of a fill or stroke; 0 when it paints nothing. */
static int resolve_paint(svg_render *r, const svg_paint_spec *spec, double opacity,
                         const svg_style *style, const cg_vec2 *bbox, int has_bbox, cg_mat3 ctm,
                         const svg_viewport *vp, cg_paint *paint, cg_gradient_stop *stops)
{
    if (spec->kind == SVG_PAINT_NONE || !(opacity > 0))
        return 0;
    if (spec->kind == SVG_PAINT_SERVER)
        return svg_gradient_paint(r, spec->server, bbox, has_bbox, ctm, vp, opacity, style->color,
                                  paint, stops);
    cg_rgba8 c = spec->kind == SVG_PAINT_COLOR ? spec->color : style->color;
    c.a = (uint8_t)(c.a * opacity + 0.5);
    if (c.a == 0)
        return 0;
    *paint = cg_paint_solid(c);
    return 1;
}

static void check(svg_render *r, cg_status status)
{
    if (status != CG_OK && status != CG_EINVAL)
        svg_fail(r, status, "drawing failed: %s", cg_status_str(status));
}

static void fill_shape(svg_render *r, const cg_path *device, const cg_paint *paint,
                       cg_fill_rule rule, cg_image *target)
{
    check(r, cg_rasterizer_fill_path(r->raster, target, device, rule, paint));
}

/* A stroke: in pixels when the transform is a similarity (width and
 * dashes scaled), else in user space and its outline transformed, so a
 * non-uniform scale makes the pen elliptical as SVG says. */
static void stroke_shape(svg_render *r, const cg_path *user, const cg_path *device,
                         const svg_style *s, cg_mat3 ctm, const cg_paint *paint, cg_image *target)
{
    cg_stroke_style style = cg_stroke_style_default();
    style.join = s->join;
    style.cap = s->cap;
    style.miter_limit = s->miter_limit;
    double scale = similarity_scale(ctm), dashes[SVG_MAX_DASHES];
    double unit = scale > 0 ? scale : 1;
    style.width = s->stroke_width * unit;
    for (int i = 0; i < s->dash_count; i++)
        dashes[i] = s->dashes[i] * unit;
    style.dashes = s->dash_count ? dashes : NULL;
    style.dash_count = s->dash_count;
    style.dash_offset = s->dash_offset * unit;
    if (scale > 0) {
        check(r, cg_rasterizer_stroke_path(r->raster, target, device, &style, paint));
        return;
    }
    double tolerance = SVG_TOLERANCE / largest_scale(ctm);
    tolerance = tolerance < 0.001 ? 0.001 : (tolerance > 100 ? 100 : tolerance);
    cg_path *outline = NULL, *mapped = NULL;
    if (cg_path_create(&outline) != CG_OK || cg_path_create(&mapped) != CG_OK) {
        svg_fail(r, CG_ENOMEM, "out of memory");
    } else if (cg_stroke_to_path(user, &style, tolerance, outline) == CG_OK
               && cg_path_transform(outline, ctm, mapped) == CG_OK) {
        fill_shape(r, mapped, paint, CG_FILL_NONZERO, target);
    }
    cg_path_free(outline);
    cg_path_free(mapped);
}

/* A shape's fill and stroke; opacity (the element's, when it needs no
 * layer) multiplies both. */
static void draw_shape(svg_render *r, const svg_node *node, cg_mat3 ctm, const svg_viewport *vp,
                       const svg_style *s, double opacity, cg_image *target)
{
    if (!s->visible)
        return;
    cg_path *user = NULL;
    if (cg_path_create(&user) != CG_OK)
        svg_fail(r, CG_ENOMEM, "out of memory");
    else if (svg_shape_path(node, vp, user))
        svg_paint_path(r, user, NULL, strcmp(node->name, "line") == 0, ctm, vp, s, opacity, target);
    cg_path_free(user);
}

void svg_paint_path(svg_render *r, const cg_path *user, const cg_vec2 *paint_box, int is_line,
                    cg_mat3 ctm, const svg_viewport *vp, const svg_style *s, double opacity,
                    cg_image *target)
{
    cg_path *device = NULL;
    if (cg_path_create(&device) != CG_OK) {
        svg_fail(r, CG_ENOMEM, "out of memory");
        return;
    }
    if (cg_path_transform(user, ctm, device) != CG_OK)
        goto done;
    cg_vec2 bbox[2];
    /* within 0.01 px of the true bounds (a gradient's box, the drawn box) */
    double bounds_tolerance = fmax(0.001, 0.01 / largest_scale(ctm));
    int has_bbox = cg_path_bounds(user, bounds_tolerance, &bbox[0], &bbox[1]) == CG_OK;
    if (!has_bbox)
        goto done;
    int stroked = s->stroke.kind != SVG_PAINT_NONE && s->stroke_width > 0;
    double reach = stroked ? s->stroke_width / 2 * largest_scale(ctm)
                                 * fmax(s->join == CG_JOIN_MITER ? s->miter_limit : 1, 1.5)
                           : 0;
    svg_touch(r, device_box(bbox, ctm, reach));
    if (paint_box) { /* the gradients' objectBoundingBox: the element's */
        bbox[0] = paint_box[0];
        bbox[1] = paint_box[1];
    }
    cg_gradient_stop stops[256];
    for (int pass = 0; pass < 2; pass++) {
        int stroke = pass == (s->stroke_first ? 0 : 1);
        cg_paint paint;
        if (stroke) {
            if (s->stroke_width > 0
                && resolve_paint(r, &s->stroke, s->stroke_opacity * opacity, s, bbox, has_bbox, ctm,
                                 vp, &paint, stops))
                stroke_shape(r, user, device, s, ctm, &paint, target);
        } else if (!is_line
                   && resolve_paint(r, &s->fill, s->fill_opacity * opacity, s, bbox, has_bbox, ctm,
                                    vp, &paint, stops)) {
            fill_shape(r, device, &paint, s->fill_rule, target);
        }
    }
done:
    cg_path_free(device);
}

static void render_children(svg_render *r, const svg_node *node, cg_mat3 ctm,
                            const svg_viewport *vp, const svg_style *s, cg_image *target)
{
    for (const svg_node *c = node->first_child; c && r->failure == CG_OK; c = c->next)
        svg_render_node(r, c, ctm, vp, s, target);
}

/* A new viewport (nested svg, a symbol through use): x, y, width, height
 * and the viewBox mapped into it. */
static void viewport_transform(const svg_node *node, const svg_viewport *vp, double w, double h,
                               double x, double y, cg_mat3 *ctm, svg_viewport *inner)
{
    *ctm = cg_mat3_mul(*ctm, svg_mat3_affine(1, 0, 0, 1, x, y));
    inner->width = w;
    inner->height = h;
    double box[4];
    if (svg_view_box(svg_attribute_value(node, "viewBox"), box) == 0) {
        *ctm = cg_mat3_mul(
            *ctm, svg_view_box_matrix(box, w, h, svg_attribute_value(node, "preserveAspectRatio")));
        inner->width = box[2];
        inner->height = box[3];
    }
    (void)vp;
}

static void render_use(svg_render *r, const svg_node *node, cg_mat3 ctm, const svg_viewport *vp,
                       const svg_style *s, cg_image *target)
{
    const svg_node *target_node = svg_find_reference(r->svg, svg_href(node));
    if (!target_node)
        return; /* other files are never read (the reader warned) */
    for (int i = 0; i < r->use_depth; i++)
        if (r->use_stack[i] == node) {
            svg_fail(r, CG_EFORMAT, "line %d: <use> refers to itself through '%.60s' (a cycle)",
                     node->line, svg_href(node));
            return;
        }
    if (r->use_depth == SVG_MAX_USE_DEPTH) {
        svg_fail(r, CG_EFORMAT, "line %d: <use> nested deeper than %d", node->line,
                 SVG_MAX_USE_DEPTH);
        return;
    }
    double x = svg_length_attribute(node, "x", SVG_AXIS_X, vp, 0);
    double y = svg_length_attribute(node, "y", SVG_AXIS_Y, vp, 0);
    r->use_stack[r->use_depth++] = node;
    if (strcmp(target_node->name, "symbol") == 0 || strcmp(target_node->name, "svg") == 0) {
        double w = svg_length_attribute(node, "width", SVG_AXIS_X, vp, -1);
        double h = svg_length_attribute(node, "height", SVG_AXIS_Y, vp, -1);
        if (w < 0)
            w = svg_length_attribute(target_node, "width", SVG_AXIS_X, vp, vp->width);
        if (h < 0)
            h = svg_length_attribute(target_node, "height", SVG_AXIS_Y, vp, vp->height);
        if (w > 0 && h > 0) {
            cg_mat3 inner_ctm = ctm;
            svg_viewport inner;
            viewport_transform(target_node, vp, w, h, x, y, &inner_ctm, &inner);
            svg_style ts;
            svg_compute_style(r, target_node, vp, s, &ts);
            if (target_node->declared[SVG_DISPLAY].value
                && strcmp(target_node->declared[SVG_DISPLAY].value, "none") == 0
                && strcmp(target_node->name, "symbol") != 0) {
                /* display: none on the referenced svg */
            } else {
                render_children(r, target_node, inner_ctm, &inner, &ts, target);
            }
        }
    } else {
        svg_render_node(r, target_node, cg_mat3_mul(ctm, svg_mat3_affine(1, 0, 0, 1, x, y)), vp, s,
                        target);
    }
    r->use_depth--;
}

/* What an element draws, once its group effects are taken care of. */
static void render_content(svg_render *r, const svg_node *node, cg_mat3 ctm, const svg_viewport *vp,
                           const svg_style *s, double opacity, cg_image *target)
{
    const char *name = node->name;
    if (svg_is_shape(name)) {
        draw_shape(r, node, ctm, vp, s, opacity, target);
    } else if (strcmp(name, "g") == 0 || strcmp(name, "a") == 0) {
        render_children(r, node, ctm, vp, s, target);
    } else if (strcmp(name, "switch") == 0) {
        /* no conditions are tested: the first child that draws */
        for (const svg_node *c = node->first_child; c; c = c->next)
            if (strcmp(c->name, "title") != 0 && strcmp(c->name, "desc") != 0) {
                svg_render_node(r, c, ctm, vp, s, target);
                break;
            }
    } else if (strcmp(name, "svg") == 0) {
        double w = svg_length_attribute(node, "width", SVG_AXIS_X, vp, vp->width);
        double h = svg_length_attribute(node, "height", SVG_AXIS_Y, vp, vp->height);
        if (w > 0 && h > 0) {
            svg_viewport inner;
            viewport_transform(node, vp, w, h, svg_length_attribute(node, "x", SVG_AXIS_X, vp, 0),
                               svg_length_attribute(node, "y", SVG_AXIS_Y, vp, 0), &ctm, &inner);
            render_children(r, node, ctm, &inner, s, target);
        }
    } else if (strcmp(name, "use") == 0) {
        render_use(r, node, ctm, vp, s, target);
    } else if (strcmp(name, "image") == 0) {
        svg_draw_image(r, node, ctm, vp, s, target);
    } else if (strcmp(name, "text") == 0) {
        svg_draw_text(r, node, ctm, vp, s, opacity, target);
    }
    /* defs, symbol, gradients, clipPath, mask, style, metadata and the
     * skipped elements draw nothing here */
}

/* Shapes whose opacity can go into the paint: one fill or one stroke. */
static int single_paint(const svg_node *node, const svg_style *s)
{
    if (!svg_is_shape(node->name))
        return 0;
    int fill = s->fill.kind != SVG_PAINT_NONE && strcmp(node->name, "line") != 0;
    int stroke = s->stroke.kind != SVG_PAINT_NONE && s->stroke_width > 0;
    return !(fill && stroke);
}

void svg_render_node(svg_render *r, const svg_node *node, cg_mat3 ctm, const svg_viewport *vp,
                     const svg_style *parent, cg_image *target)
{
    if (r->failure != CG_OK || node->name[0] == '#') /* "#text": drawn by its <text> */
        return;
    if (++r->rendered > CG_SVG_MAX_RENDERED) {
        svg_fail(r, CG_EFORMAT, "more than %d elements to draw (an exponential <use> tree?)",
                 CG_SVG_MAX_RENDERED);
        return;
    }
    const char *display = node->declared[SVG_DISPLAY].value;
    if (display && strcmp(display, "none") == 0)
        return;
    const char *transform = svg_attribute_value(node, "transform");
    if (transform && strcmp(node->name, "svg") != 0) {
        cg_mat3 t;
        if (svg_transform(transform, &t) == 0) { /* malformed: ignored (the reader warned) */
            if (cg_mat3_determinant(t) == 0)
                return; /* a zero scale: nothing shows */
            ctm = cg_mat3_mul(ctm, t);
        }
    }
    svg_style s;
    svg_compute_style(r, node, vp, parent, &s);
    double opacity = 1;
    const char *o = node->declared[SVG_OPACITY].value;
    if (o)
        svg_unit_number(o, &opacity);
    if (!(opacity > 0))
        return;
    cg_blend_mode mode = CG_BLEND_NORMAL;
    const char *blend = node->declared[SVG_MIX_BLEND_MODE].value;
    if (blend && cg_blend_mode_parse(blend, &mode) != CG_OK)
        mode = CG_BLEND_NORMAL;
    int has_effects = (node->declared[SVG_CLIP_PATH].value
                       && strcmp(node->declared[SVG_CLIP_PATH].value, "none") != 0)
                      || (node->declared[SVG_MASK].value
                          && strcmp(node->declared[SVG_MASK].value, "none") != 0);
    if (!has_effects && mode == CG_BLEND_NORMAL && (opacity >= 1 || single_paint(node, &s))) {
        render_content(r, node, ctm, vp, &s, opacity, target);
        return;
    }
    /* the content into a layer, noting where it drew; then the clip and
     * mask over that box only, and the layer composited there */
    cg_image *layer = NULL, *mask = NULL;
    if (cg_image_create(&layer, target->width, target->height, CG_PIXEL_RGBA8) != CG_OK) {
        svg_fail(r, CG_ENOMEM, "out of memory for a layer");
        return;
    }
    svg_box outer = r->dirty, empty = {0, 0, 0, 0};
    r->dirty = empty;
    render_content(r, node, ctm, vp, &s, 1, layer);
    svg_box box = r->dirty;
    int none = !(box.x0 < box.x1) || r->failure != CG_OK
               || !svg_spend(r, (box.x1 - box.x0) * (box.y1 - box.y0));
    if (!none && has_effects)
        mask = svg_clip_and_mask(r, node, ctm, vp, box, &none);
    if (!none && r->failure == CG_OK) {
        cg_layer_style style = cg_layer_style_default();
        style.opacity = opacity;
        style.mode = mode;
        style.mask = mask;
        style.mask_type = CG_MASK_ALPHA;
        style.has_box = 1;
        style.box_x0 = (int)box.x0;
        style.box_y0 = (int)box.y0;
        style.box_x1 = (int)box.x1;
        style.box_y1 = (int)box.y1;
        check(r, cg_rasterizer_composite_layer(r->raster, target, layer, &style));
    }
    r->dirty = outer;
    if (!none)
        svg_touch(r, box);
    cg_image_free(layer);
    cg_image_free(mask);
}

cg_status cg_svg_render(const cg_svg *svg, cg_image *image, cg_mat3 transform, cg_error *err)
{
    if (!svg || !image || !image->data
        || (image->format != CG_PIXEL_RGBA8 && image->format != CG_PIXEL_RGBAF))
        return cg_error_set(err, CG_EINVAL, "cg_svg_render: bad argument");
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(transform.m[i][k]))
                return cg_error_set(err, CG_EINVAL, "cg_svg_render: non-finite transform");
    if (transform.m[2][0] != 0 || transform.m[2][1] != 0 || transform.m[2][2] != 1)
        return cg_error_set(err, CG_EINVAL, "cg_svg_render: the transform is not affine");
    svg_render r;
    memset(&r, 0, sizeof r);
    r.svg = svg;
    r.err = err;
    r.width = image->width;
    r.height = image->height;
    if (cg_rasterizer_create(&r.raster) != CG_OK || cg_rasterizer_create(&r.coverage) != CG_OK) {
        cg_rasterizer_free(r.raster);
        return cg_error_set(err, CG_ENOMEM, "out of memory");
    }
    cg_rasterizer_set_compositing(r.raster, CG_COMPOSITE_SRGB, CG_OPERATOR_OVER, CG_BLEND_NORMAL);
    /* curves within 0.02 px: areas within 0.1% of a 10 px circle's */
    cg_rasterizer_set_tolerance(r.raster, SVG_TOLERANCE);
    cg_rasterizer_set_tolerance(r.coverage, SVG_TOLERANCE);
    /* the root's viewBox into the document's size */
    cg_mat3 ctm = transform;
    svg_viewport vp = {svg->width, svg->height};
    double box[4];
    if (svg_view_box(svg_attribute_value(svg->root, "viewBox"), box) == 0) {
        ctm = cg_mat3_mul(
            ctm, svg_view_box_matrix(box, svg->width, svg->height,
                                     svg_attribute_value(svg->root, "preserveAspectRatio")));
        vp.width = box[2];
        vp.height = box[3];
    }
    svg_style initial;
    svg_initial_style(&initial);
    /* the root as a group: its own opacity, clip and mask apply */
    svg_node *root = svg->root;
    svg_style s;
    svg_compute_style(&r, root, &vp, &initial, &s);
    const char *display = root->declared[SVG_DISPLAY].value;
    if (!(display && strcmp(display, "none") == 0)) {
        double opacity = 1;
        if (root->declared[SVG_OPACITY].value)
            svg_unit_number(root->declared[SVG_OPACITY].value, &opacity);
        if (opacity >= 1) {
            render_children(&r, root, ctm, &vp, &s, image);
        } else if (opacity > 0) {
            cg_image *layer;
            if (cg_image_create(&layer, image->width, image->height, CG_PIXEL_RGBA8) == CG_OK) {
                render_children(&r, root, ctm, &vp, &s, layer);
                cg_layer_style style = cg_layer_style_default();
                style.opacity = opacity;
                check(&r, cg_rasterizer_composite_layer(r.raster, image, layer, &style));
                cg_image_free(layer);
            } else {
                svg_fail(&r, CG_ENOMEM, "out of memory for a layer");
            }
        }
    }
    cg_rasterizer_free(r.raster);
    cg_rasterizer_free(r.coverage);
    svg_fonts_free(&r);
    if (r.failure != CG_OK && err && err->status == CG_OK)
        cg_error_set(err, r.failure, "%s: %s", svg->name, cg_status_str(r.failure));
    return r.failure;
}
