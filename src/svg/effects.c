/* Clip paths, masks, bounding boxes and embedded images.
 *
 * A clip path is drawn as coverage: each child shape filled in white over
 * a transparent image under its clip-rule, so the alpha holds the union of
 * their anti-aliased coverages.  A mask's children are drawn like any
 * content into a transparent layer, and each pixel's value is the
 * luminance of its sRGB colour times its alpha, inside the mask's
 * rectangle.  An element with both gets their product as one alpha image,
 * the mask of its layer (cg_rasterizer_composite_layer). */
#include "internal.h"
#include "../core/base64.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_EFFECT_DEPTH 8

static int displayed(const svg_node *node)
{
    const char *d = node->declared[SVG_DISPLAY].value;
    return !(d && strcmp(d, "none") == 0);
}

static cg_mat3 own_transform(const svg_node *node, cg_mat3 m)
{
    cg_mat3 t;
    const char *text = svg_attribute_value(node, "transform");
    if (text && svg_transform(text, &t) == 0)
        m = cg_mat3_mul(m, t);
    return m;
}

/* m moved by a <use>'s x and y. */
static cg_mat3 use_offset(const svg_node *use, cg_mat3 m, const svg_viewport *vp)
{
    double x = svg_length_attribute(use, "x", SVG_AXIS_X, vp, 0);
    double y = svg_length_attribute(use, "y", SVG_AXIS_Y, vp, 0);
    return cg_mat3_mul(m, svg_mat3_affine(1, 0, 0, 1, x, y));
}

static void grow_box(cg_vec2 *box, int *any, cg_vec2 lo, cg_vec2 hi)
{
    if (!*any) {
        box[0] = lo;
        box[1] = hi;
        *any = 1;
        return;
    }
    box[0].x = fmin(box[0].x, lo.x);
    box[0].y = fmin(box[0].y, lo.y);
    box[1].x = fmax(box[1].x, hi.x);
    box[1].y = fmax(box[1].y, hi.y);
}

/* Bounds of what node draws in the coordinates of m (its own transform
 * already in m). */
static int content_bounds(svg_render *r, const svg_node *node, cg_mat3 m, const svg_viewport *vp,
                          cg_vec2 *box, int depth)
{
    if (depth > SVG_MAX_USE_DEPTH || ++r->rendered > CG_SVG_MAX_RENDERED)
        return 0;
    int any = 0;
    if (svg_is_shape(node->name)) {
        cg_path *user = NULL, *mapped = NULL;
        cg_vec2 lo, hi;
        if (cg_path_create(&user) == CG_OK && cg_path_create(&mapped) == CG_OK
            && svg_shape_path(node, vp, user) && cg_path_transform(user, m, mapped) == CG_OK
            && cg_path_bounds(mapped, 0.001, &lo, &hi) == CG_OK)
            grow_box(box, &any, lo, hi);
        cg_path_free(user);
        cg_path_free(mapped);
        return any;
    }
    if (strcmp(node->name, "use") == 0) {
        const svg_node *t = svg_find_reference(r->svg, svg_href(node));
        if (!t || !displayed(t))
            return 0;
        cg_mat3 moved = use_offset(node, m, vp);
        if (strcmp(t->name, "symbol") == 0)
            return content_bounds(r, t, moved, vp, box, depth + 1);
        return content_bounds(r, t, own_transform(t, moved), vp, box, depth + 1);
    }
    if (strcmp(node->name, "g") == 0 || strcmp(node->name, "a") == 0
        || strcmp(node->name, "switch") == 0 || strcmp(node->name, "symbol") == 0
        || strcmp(node->name, "svg") == 0) {
        for (const svg_node *c = node->first_child; c; c = c->next) {
            cg_vec2 b[2];
            if (displayed(c) && content_bounds(r, c, own_transform(c, m), vp, b, depth + 1))
                grow_box(box, &any, b[0], b[1]);
        }
    }
    return any;
}

int svg_node_bounds(svg_render *r, const svg_node *node, cg_mat3 m, const svg_viewport *vp,
                    cg_vec2 *box)
{
    return content_bounds(r, node, m, vp, box, 0);
}

static cg_image *blank(svg_render *r)
{
    cg_image *image;
    if (cg_image_create(&image, r->width, r->height, CG_PIXEL_RGBA8) != CG_OK) {
        svg_fail(r, CG_ENOMEM, "out of memory for a clip or mask");
        return NULL;
    }
    return image;
}

/* Fills path (user space, mapped by m) in white onto coverage. */
static void cover_path(svg_render *r, const cg_path *user, cg_mat3 m, cg_fill_rule rule,
                       cg_image *coverage)
{
    cg_path *device;
    if (cg_path_create(&device) != CG_OK)
        return;
    cg_paint white = cg_paint_solid((cg_rgba8){255, 255, 255, 255});
    if (cg_path_transform(user, m, device) == CG_OK)
        cg_rasterizer_fill_path(r->coverage, coverage, device, rule, &white);
    cg_path_free(device);
}

/* A clip child: a shape, or a use of one. */
static void clip_child(svg_render *r, const svg_node *c, cg_mat3 m, const svg_viewport *vp,
                       const svg_style *parent, cg_image *coverage)
{
    if (!displayed(c))
        return;
    svg_style s;
    svg_compute_style(r, c, vp, parent, &s);
    m = own_transform(c, m);
    if (strcmp(c->name, "use") == 0) {
        const svg_node *t = svg_find_reference(r->svg, svg_href(c));
        if (t && svg_is_shape(t->name))
            clip_child(r, t, use_offset(c, m, vp), vp, &s, coverage);
        return;
    }
    if (!svg_is_shape(c->name) || !s.visible)
        return;
    cg_path *user;
    if (cg_path_create(&user) != CG_OK)
        return;
    if (svg_shape_path(c, vp, user))
        cover_path(r, user, m, s.clip_rule, coverage);
    cg_path_free(user);
}

/* Multiplies the alpha of a by that of b within box. */
static void multiply_alpha(cg_image *a, const cg_image *b, svg_box box)
{
    for (int y = (int)box.y0; y < (int)box.y1; y++) {
        cg_rgba8 *pa = cg_image_row_rgba8(a, y);
        const cg_rgba8 *pb = cg_image_row_rgba8((cg_image *)b, y);
        for (int x = (int)box.x0; x < (int)box.x1; x++)
            pa[x].a = (uint8_t)((pa[x].a * pb[x].a + 127) / 255);
    }
}

static cg_image *clip_image(svg_render *r, const svg_node *clip, const svg_node *node, cg_mat3 ctm,
                            const svg_viewport *vp, svg_box box);

/* The clip-path or mask property's own clip on the effect element. */
static int apply_nested_clip(svg_render *r, const svg_node *effect, cg_mat3 ctm,
                             const svg_viewport *vp, const svg_node *node, cg_image *image,
                             svg_box box)
{
    const char *v = effect->declared[SVG_CLIP_PATH].value;
    if (!v || strcmp(v, "none") == 0)
        return 1;
    const svg_node *nested = svg_find_reference(r->svg, v);
    if (!nested || strcmp(nested->name, "clipPath") != 0)
        return 0;
    cg_image *inner = clip_image(r, nested, node, ctm, vp, box);
    if (!inner)
        return 0;
    multiply_alpha(image, inner, box);
    cg_image_free(inner);
    return 1;
}

/* The bounding-box matrix of node (its fill bounds in user space), or 0. */
static int bbox_matrix(svg_render *r, const svg_node *node, const svg_viewport *vp, cg_vec2 *box,
                       cg_mat3 *out)
{
    if (!content_bounds(r, node, cg_mat3_identity(), vp, box, 0))
        return 0;
    double w = box[1].x - box[0].x, h = box[1].y - box[0].y;
    if (!(w > 0 && h > 0))
        return 0;
    *out = svg_mat3_affine(w, 0, 0, h, box[0].x, box[0].y);
    return 1;
}

static cg_image *clip_image(svg_render *r, const svg_node *clip, const svg_node *node, cg_mat3 ctm,
                            const svg_viewport *vp, svg_box box)
{
    if (r->effect_depth >= MAX_EFFECT_DEPTH) {
        svg_fail(r, CG_EFORMAT, "line %d: clip paths and masks nested deeper than %d (a cycle?)",
                 clip->line, MAX_EFFECT_DEPTH);
        return NULL;
    }
    const char *units = svg_attribute_value(clip, "clipPathUnits");
    cg_mat3 m = ctm;
    if (units && strcmp(units, "objectBoundingBox") == 0) {
        cg_vec2 box[2];
        cg_mat3 b;
        if (!bbox_matrix(r, node, vp, box, &b))
            return blank(r); /* no box: clipped away */
        m = cg_mat3_mul(m, b);
    }
    m = own_transform(clip, m);
    cg_image *coverage = blank(r);
    if (!coverage)
        return NULL;
    r->effect_depth++;
    svg_style initial, s;
    svg_initial_style(&initial);
    svg_compute_style(r, clip, vp, &initial, &s);
    for (const svg_node *c = clip->first_child; c; c = c->next)
        clip_child(r, c, m, vp, &s, coverage);
    if (!apply_nested_clip(r, clip, ctm, vp, node, coverage, box)) {
        cg_image_free(coverage);
        coverage = r->failure == CG_OK ? blank(r) : NULL;
    }
    r->effect_depth--;
    return coverage;
}

static double mask_length(const svg_node *mask, const char *name, int bbox_units, svg_axis axis,
                          const svg_viewport *vp, double fallback)
{
    const char *text = svg_attribute_value(mask, name);
    double v;
    if (!text)
        return fallback;
    if (bbox_units) {
        const char *end = svg_read_number(svg_skip(text, 0), &v);
        return end ? (*end == '%' ? v / 100 : v) : fallback;
    }
    return svg_length(text, axis, vp, &v) == 0 ? v : fallback;
}

static cg_image *mask_image(svg_render *r, const svg_node *mask, const svg_node *node, cg_mat3 ctm,
                            const svg_viewport *vp, svg_box box)
{
    if (r->effect_depth >= MAX_EFFECT_DEPTH) {
        svg_fail(r, CG_EFORMAT, "line %d: masks nested deeper than %d (a cycle?)", mask->line,
                 MAX_EFFECT_DEPTH);
        return NULL;
    }
    const char *units = svg_attribute_value(mask, "maskUnits");
    const char *content_units = svg_attribute_value(mask, "maskContentUnits");
    int bbox_units = !(units && strcmp(units, "userSpaceOnUse") == 0);
    int content_bbox = content_units && strcmp(content_units, "objectBoundingBox") == 0;
    cg_vec2 bounds[2];
    cg_mat3 b = cg_mat3_identity();
    int has_box = bbox_matrix(r, node, vp, bounds, &b);
    if ((bbox_units || content_bbox) && !has_box)
        return blank(r);
    /* the default rectangle: the box (or the viewport) grown by 10% */
    double unit_w = bbox_units ? 1 : vp->width, unit_h = bbox_units ? 1 : vp->height;
    double x = mask_length(mask, "x", bbox_units, SVG_AXIS_X, vp, -0.1 * unit_w);
    double y = mask_length(mask, "y", bbox_units, SVG_AXIS_Y, vp, -0.1 * unit_h);
    double w = mask_length(mask, "width", bbox_units, SVG_AXIS_X, vp, 1.2 * unit_w);
    double h = mask_length(mask, "height", bbox_units, SVG_AXIS_Y, vp, 1.2 * unit_h);
    if (!(w > 0 && h > 0))
        return blank(r);
    cg_mat3 rect_m = bbox_units ? cg_mat3_mul(ctm, b) : ctm;
    cg_image *rect = blank(r), *content = blank(r);
    cg_path *path = NULL;
    if (!rect || !content || cg_path_create(&path) != CG_OK) {
        cg_image_free(rect);
        cg_image_free(content);
        return NULL;
    }
    cg_path_move_to(path, x, y);
    cg_path_line_to(path, x + w, y);
    cg_path_line_to(path, x + w, y + h);
    cg_path_line_to(path, x, y + h);
    cg_path_close(path);
    cover_path(r, path, rect_m, CG_FILL_NONZERO, rect);
    cg_path_free(path);
    r->effect_depth++;
    svg_style initial, s;
    svg_initial_style(&initial);
    svg_compute_style(r, mask, vp, &initial, &s);
    cg_mat3 content_m = content_bbox ? cg_mat3_mul(ctm, b) : ctm;
    svg_box outer = r->dirty; /* the mask's drawing is not the element's */
    for (const svg_node *c = mask->first_child; c && r->failure == CG_OK; c = c->next)
        svg_render_node(r, c, content_m, vp, &s, content);
    r->dirty = outer;
    r->effect_depth--;
    /* luminance times alpha, within the rectangle, into rect's alpha (in
     * the element's box: the layer is transparent elsewhere) */
    for (int py = (int)box.y0; py < (int)box.y1; py++) {
        const cg_rgba8 *pc = cg_image_row_rgba8(content, py);
        cg_rgba8 *pr = cg_image_row_rgba8(rect, py);
        for (int px = (int)box.x0; px < (int)box.x1; px++) {
            double lum = (0.2125 * pc[px].r + 0.7154 * pc[px].g + 0.0721 * pc[px].b) / 255;
            double v = lum * pc[px].a / 255 * pr[px].a / 255;
            pr[px].a = (uint8_t)(v * 255 + 0.5);
        }
    }
    cg_image_free(content);
    if (!apply_nested_clip(r, mask, ctm, vp, node, rect, box)) {
        cg_image_free(rect);
        return r->failure == CG_OK ? blank(r) : NULL;
    }
    return rect;
}

cg_image *svg_clip_and_mask(svg_render *r, const svg_node *node, cg_mat3 ctm,
                            const svg_viewport *vp, svg_box box, int *none)
{
    *none = 0;
    cg_image *result = NULL;
    const char *clip = node->declared[SVG_CLIP_PATH].value;
    const char *mask = node->declared[SVG_MASK].value;
    if (clip && strcmp(clip, "none") != 0) {
        const svg_node *c = svg_find_reference(r->svg, clip);
        if (!c || strcmp(c->name, "clipPath") != 0) {
            *none = 1; /* a link to nothing: the element is not drawn (as resvg does) */
            return NULL;
        }
        result = clip_image(r, c, node, ctm, vp, box);
        if (!result) {
            *none = 1;
            return NULL;
        }
    }
    if (mask && strcmp(mask, "none") != 0) {
        const svg_node *m = svg_find_reference(r->svg, mask);
        if (!m || strcmp(m->name, "mask") != 0) {
            cg_image_free(result);
            *none = 1;
            return NULL;
        }
        cg_image *values = mask_image(r, m, node, ctm, vp, box);
        if (!values) {
            cg_image_free(result);
            *none = 1;
            return NULL;
        }
        if (result) {
            multiply_alpha(result, values, box);
            cg_image_free(values);
        } else {
            result = values;
        }
    }
    return result;
}

/* ---- images ------------------------------------------------------------------- */

/* The bytes of a base64 data URI's payload (malloc'ed), or NULL. */
static unsigned char *data_uri(const char *href, size_t *size)
{
    href = svg_skip(href, 0);
    if (strncmp(href, "data:", 5) != 0)
        return NULL;
    const char *comma = strchr(href, ',');
    if (!comma)
        return NULL;
    size_t header = (size_t)(comma - href);
    int base64 = 0;
    for (size_t i = 0; i + 7 <= header; i++)
        base64 |= strncmp(href + i, ";base64", 7) == 0;
    if (!base64)
        return NULL;
    unsigned char *out = NULL;
    if (core_base64_decode(comma + 1, strlen(comma + 1), 1, &out, size) != 1)
        return NULL;
    return out;
}

/* Bilinear sample of premultiplied sRGB at image point (u, v), edges
 * clamped. */
static cg_rgba8 sample(const cg_image *image, double u, double v)
{
    double fx = u - 0.5, fy = v - 0.5;
    int x0 = (int)floor(fx), y0 = (int)floor(fy);
    double tx = fx - x0, ty = fy - y0, acc[4] = {0, 0, 0, 0};
    for (int k = 0; k < 4; k++) {
        int x = x0 + (k & 1), y = y0 + (k >> 1);
        x = x < 0 ? 0 : (x >= image->width ? image->width - 1 : x);
        y = y < 0 ? 0 : (y >= image->height ? image->height - 1 : y);
        double w = ((k & 1) ? tx : 1 - tx) * ((k >> 1) ? ty : 1 - ty);
        cg_rgba8 p = cg_image_row_rgba8((cg_image *)image, y)[x];
        acc[0] += w * p.r * p.a;
        acc[1] += w * p.g * p.a;
        acc[2] += w * p.b * p.a;
        acc[3] += w * p.a;
    }
    cg_rgba8 out = {0, 0, 0, 0};
    if (acc[3] > 0) {
        out.r = (uint8_t)fmin(255, acc[0] / acc[3] + 0.5);
        out.g = (uint8_t)fmin(255, acc[1] / acc[3] + 0.5);
        out.b = (uint8_t)fmin(255, acc[2] / acc[3] + 0.5);
        out.a = (uint8_t)fmin(255, acc[3] + 0.5);
    }
    return out;
}

void svg_draw_image(svg_render *r, const svg_node *node, cg_mat3 ctm, const svg_viewport *vp,
                    const svg_style *style, cg_image *target)
{
    const char *href = svg_href(node);
    size_t size = 0;
    unsigned char *bytes = href && style->visible ? data_uri(href, &size) : NULL;
    if (!bytes)
        return;
    cg_image *picture = NULL;
    cg_status status = cg_image_read_memory(bytes, size, "embedded image", &picture, NULL);
    free(bytes);
    if (status != CG_OK)
        return;
    double iw = picture->width, ih = picture->height;
    double x = svg_length_attribute(node, "x", SVG_AXIS_X, vp, 0);
    double y = svg_length_attribute(node, "y", SVG_AXIS_Y, vp, 0);
    double w = svg_length_attribute(node, "width", SVG_AXIS_X, vp, iw);
    double h = svg_length_attribute(node, "height", SVG_AXIS_Y, vp, ih);
    cg_mat3 m, inverse;
    cg_image *layer = NULL;
    cg_path *rect = NULL, *device = NULL;
    if (!(w > 0 && h > 0))
        goto done;
    double box[4] = {0, 0, iw, ih};
    m = cg_mat3_mul(
        cg_mat3_mul(ctm, svg_mat3_affine(1, 0, 0, 1, x, y)),
        svg_view_box_matrix(box, w, h, svg_attribute_value(node, "preserveAspectRatio")));
    if (cg_mat3_inverse(m, &inverse) != CG_OK || cg_path_create(&rect) != CG_OK
        || cg_path_create(&device) != CG_OK
        || cg_image_create(&layer, target->width, target->height, CG_PIXEL_RGBA8) != CG_OK)
        goto done;
    cg_path_move_to(rect, 0, 0);
    cg_path_line_to(rect, iw, 0);
    cg_path_line_to(rect, iw, ih);
    cg_path_line_to(rect, 0, ih);
    cg_path_close(rect);
    cg_vec2 lo, hi;
    if (cg_path_transform(rect, m, device) != CG_OK
        || cg_path_bounds(device, 0.01, &lo, &hi) != CG_OK)
        goto done;
    int x0 = (int)fmax(0, floor(lo.x)), x1 = (int)fmin(target->width, ceil(hi.x));
    int y0 = (int)fmax(0, floor(lo.y)), y1 = (int)fmin(target->height, ceil(hi.y));
    if (x0 >= x1 || y0 >= y1 || !svg_spend(r, (double)(x1 - x0) * (y1 - y0)))
        goto done;
    svg_touch(r, (svg_box){x0, y0, x1, y1});
    for (int py = y0; py < y1; py++)
        for (int px = x0; px < x1; px++) {
            cg_vec2 p = cg_mat3_transform_point(inverse, cg_vec2_make(px + 0.5, py + 0.5));
            if (p.x >= 0 && p.y >= 0 && p.x <= iw && p.y <= ih)
                cg_image_row_rgba8(layer, py)[px] = sample(picture, p.x, p.y);
        }
    cg_layer_style ls = cg_layer_style_default();
    ls.clip = device;
    ls.has_box = 1;
    ls.box_x0 = x0;
    ls.box_y0 = y0;
    ls.box_x1 = x1;
    ls.box_y1 = y1;
    cg_rasterizer_composite_layer(r->raster, target, layer, &ls);
done:
    cg_image_free(picture);
    cg_image_free(layer);
    cg_path_free(rect);
    cg_path_free(device);
}
