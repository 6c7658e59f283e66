/* Private pieces shared by the SVG module's files: the element tree read
 * from the XML (xml.c), style sheets (css.c), property values (values.c),
 * geometry (shapes.c), paint servers (paint.c), clip paths and masks
 * (effects.c) and the drawing walk (render.c). */
#ifndef CG_SVG_INTERNAL_H
#define CG_SVG_INTERNAL_H

#include "cg/svg.h"
#include "cg/fill.h"
#include "../core/array.h"

#include <stddef.h>

/* ---- the element tree ------------------------------------------------------ */

/* The properties cg reads, from presentation attributes, style sheets and
 * style attributes alike. */
typedef enum svg_property {
    SVG_FILL,
    SVG_FILL_OPACITY,
    SVG_FILL_RULE,
    SVG_STROKE,
    SVG_STROKE_WIDTH,
    SVG_STROKE_OPACITY,
    SVG_STROKE_LINECAP,
    SVG_STROKE_LINEJOIN,
    SVG_STROKE_MITERLIMIT,
    SVG_STROKE_DASHARRAY,
    SVG_STROKE_DASHOFFSET,
    SVG_OPACITY,
    SVG_COLOR,
    SVG_DISPLAY,
    SVG_VISIBILITY,
    SVG_CLIP_PATH,
    SVG_CLIP_RULE,
    SVG_MASK,
    SVG_STOP_COLOR,
    SVG_STOP_OPACITY,
    SVG_PAINT_ORDER,
    SVG_MIX_BLEND_MODE,
    SVG_FILTER,
    SVG_MARKER_START,
    SVG_MARKER_MID,
    SVG_MARKER_END,
    SVG_FONT_FAMILY,
    SVG_FONT_SIZE,
    SVG_FONT_WEIGHT,
    SVG_FONT_STYLE,
    SVG_TEXT_ANCHOR,
    SVG_PROPERTY_COUNT
} svg_property;

/* A property's value as declared on an element, with the rank of its
 * origin: presentation attribute < style sheet (by specificity, then
 * order) < style attribute < !important in a sheet. */
typedef struct svg_declared {
    const char *value; /* NULL: not declared */
    unsigned long long rank;
} svg_declared;

typedef struct svg_attribute {
    char *name; /* local name; "xlink:href" for XLink's href */
    char *value;
} svg_attribute;

typedef struct svg_node {
    char *name; /* the element's local name ("rect") */
    svg_attribute *attributes;
    int attribute_count;
    struct svg_node *parent, *first_child, *last_child, *next;
    char *text; /* character data (of <style>, and of "#text" nodes), may be NULL */
    size_t text_length;
    int line; /* in the file, for messages */
    svg_declared declared[SVG_PROPERTY_COUNT];
} svg_node;

/* The value of an attribute, or NULL. */
const char *svg_attribute_value(const svg_node *node, const char *name);
/* href or xlink:href. */
const char *svg_href(const svg_node *node);

struct cg_svg {
    char name[128];             /* for messages */
    svg_node *root;             /* the <svg> element */
    CORE_ARRAY(svg_node *) ids; /* elements with an id, sorted by id after loading */
    CORE_ARRAY(char *) warnings;
    CORE_ARRAY(char *) strings; /* style sheet text the declarations point into */
    double width, height;       /* the document's size in px */
};

/* The element with this id ("#id" references drop the '#'), or NULL. */
const svg_node *svg_find_id(const cg_svg *svg, const char *id);
/* The element a "url(#id)" or "#id" names, or NULL. */
const svg_node *svg_find_reference(const cg_svg *svg, const char *reference);
/* Adds "text" to the warnings unless already there. */
void svg_warn(cg_svg *svg, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Parses the XML into svg->root (xml.c). */
cg_status svg_parse_xml(cg_svg *svg, const char *bytes, size_t size, cg_error *err);
void svg_node_free(svg_node *node);

/* Applies the <style> sheets and style attributes to every element's
 * declared properties (css.c). */
cg_status svg_apply_styles(cg_svg *svg, cg_error *err);
/* The property of a name ("stroke-width"), or SVG_PROPERTY_COUNT. */
svg_property svg_property_of(const char *name, size_t length);
/* Parses "a: b; c: d" declarations onto node at rank. */
cg_status svg_declare_list(cg_svg *svg, svg_node *node, const char *text, size_t length,
                           unsigned long long rank, unsigned long long important_rank);

/* ---- values (values.c) ------------------------------------------------------- */

/* What a length's percentage refers to. */
typedef enum svg_axis { SVG_AXIS_X, SVG_AXIS_Y, SVG_AXIS_DIAGONAL } svg_axis;

typedef struct svg_viewport {
    double width, height;
} svg_viewport;

/* Skips blanks (and commas when comma is set). */
const char *svg_skip(const char *s, int comma);
/* Reads a number; NULL when there is none. */
const char *svg_read_number(const char *s, double *out);
/* A length with optional unit or %, in px: 0 on success. */
int svg_length(const char *text, svg_axis axis, const svg_viewport *viewport, double *out);
/* The attribute as a length, or fallback when absent or malformed. */
double svg_length_attribute(const svg_node *node, const char *name, svg_axis axis,
                            const svg_viewport *viewport, double fallback);
/* A number or percentage in [0, 1] (opacity, offsets): 0 on success. */
int svg_unit_number(const char *text, double *out);
/* A colour: #hex, rgb()/rgba(), a CSS name, transparent: 0 on success;
 * currentColor gives 1 (the caller uses the color property). */
int svg_color(const char *text, cg_rgba8 *out);
/* Parses a transform list into *out (0 on success, -1 malformed). */
int svg_transform(const char *text, cg_mat3 *out);
/* viewBox "x y w h" (w, h > 0): 0 on success. */
int svg_view_box(const char *text, double *box);
/* The matrix mapping a viewBox into a viewport width x height under a
 * preserveAspectRatio value (NULL: xMidYMid meet). */
cg_mat3 svg_view_box_matrix(const double *box, double width, double height, const char *aspect);
cg_mat3 svg_mat3_affine(double a, double b, double c, double d, double e, double f);

/* ---- geometry (shapes.c) ----------------------------------------------------- */

/* The path of a basic shape or path element in user space, appended to
 * out: 1 when the element has geometry, 0 when not (or it is malformed). */
int svg_shape_path(const svg_node *node, const svg_viewport *viewport, cg_path *out);
/* Whether an element name is a shape (path, rect, circle ...). */
int svg_is_shape(const char *name);

/* ---- drawing (render.c, paint.c, effects.c) ---------------------------------- */

typedef enum svg_paint_kind {
    SVG_PAINT_NONE,
    SVG_PAINT_COLOR,
    SVG_PAINT_CURRENT_COLOR,
    SVG_PAINT_SERVER
} svg_paint_kind;

typedef struct svg_paint_spec {
    svg_paint_kind kind;
    cg_rgba8 color;         /* SVG_PAINT_COLOR */
    const svg_node *server; /* SVG_PAINT_SERVER: a gradient */
} svg_paint_spec;

#define SVG_MAX_DASHES 64

/* The inherited properties at an element, computed. */
typedef struct svg_style {
    svg_paint_spec fill, stroke;
    double fill_opacity, stroke_opacity;
    cg_fill_rule fill_rule, clip_rule;
    double stroke_width; /* user units */
    cg_line_cap cap;
    cg_line_join join;
    double miter_limit;
    double dashes[SVG_MAX_DASHES];
    int dash_count;
    double dash_offset;
    cg_rgba8 color;
    int visible;
    int stroke_first; /* paint-order: stroke before fill */
    /* text */
    const char *font_family; /* the declared list, NULL: the initial (serif) */
    double font_size;        /* user units, initially 16 */
    int font_weight;         /* CSS 1..1000, initially 400 */
    int italic;              /* font-style italic or oblique */
    int text_anchor;         /* cg_text_align: start, middle, end */
} svg_style;

/* A box of pixels x0 <= x < x1, y0 <= y < y1 (empty when x0 >= x1). */
typedef struct svg_box {
    double x0, y0, x1, y1;
} svg_box;

#define SVG_MAX_USE_DEPTH 64
/* Pixels composited through layers, clips and masks in one drawing: a
 * bound on the time of a hostile file (2^31: seconds). */
#define SVG_MAX_WORK 2147483648.0
/* Flattening tolerance of curves in pixels. */
#define SVG_TOLERANCE 0.02

typedef struct svg_render {
    const cg_svg *svg;
    cg_rasterizer *raster;   /* compositing in sRGB */
    cg_rasterizer *coverage; /* default compositing: clip coverage */
    cg_error *err;
    long rendered; /* elements drawn so far (the budget) */
    const svg_node *use_stack[SVG_MAX_USE_DEPTH];
    int use_depth;
    int effect_depth; /* clip paths and masks being built */
    cg_status failure;
    int width, height;       /* of the target image */
    svg_box dirty;           /* where drawing calls drew since it was reset */
    double work;             /* pixels composited so far */
    struct svg_fonts *fonts; /* the fonts text asked for (text.c), NULL until then */
} svg_render;

/* Grows r->dirty by box (clamped to the image). */
void svg_touch(svg_render *r, svg_box box);
/* Adds pixels to the work; 0 (after failing) beyond SVG_MAX_WORK. */
int svg_spend(svg_render *r, double pixels);

/* Computes node's inherited properties from its parent's. */
void svg_compute_style(const svg_render *r, const svg_node *node, const svg_viewport *vp,
                       const svg_style *parent, svg_style *out);
void svg_initial_style(svg_style *out);

/* A paint for a gradient server: 1 with *paint (stops in stops[0..255]),
 * 0 when it paints nothing.  bbox: the element's fill bounds in user space
 * (min, max), ctm: user space to pixels; opacity multiplies the stops. */
int svg_gradient_paint(const svg_render *r, const svg_node *server, const cg_vec2 *bbox,
                       int has_bbox, cg_mat3 ctm, const svg_viewport *vp, double opacity,
                       cg_rgba8 current_color, cg_paint *paint, cg_gradient_stop *stops);

/* Draws node (any element) with its parent's style onto target. */
void svg_render_node(svg_render *r, const svg_node *node, cg_mat3 ctm, const svg_viewport *vp,
                     const svg_style *parent, cg_image *target);
/* The fill bounds of node's geometry in the coordinates of m: 1 when it
 * has any. */
int svg_node_bounds(svg_render *r, const svg_node *node, cg_mat3 m, const svg_viewport *vp,
                    cg_vec2 *box);

/* An alpha image (the size of the target) combining node's clip-path and
 * mask; NULL with *none set when the element shows nowhere, NULL alone
 * when it has neither or they failed. */
cg_image *svg_clip_and_mask(svg_render *r, const svg_node *node, cg_mat3 ctm,
                            const svg_viewport *vp, svg_box box, int *none);
/* Fills and strokes path (user space) with style s, as a shape is drawn;
 * paint_box (min, max in user space; NULL: the path's bounds) is the
 * objectBoundingBox of gradients; is_line: the element is a <line>, which
 * has no fill. */
void svg_paint_path(svg_render *r, const cg_path *user, const cg_vec2 *paint_box, int is_line,
                    cg_mat3 ctm, const svg_viewport *vp, const svg_style *s, double opacity,
                    cg_image *target);
/* Draws a <text> element: its character data and tspans, shaped and laid
 * out (text.c). */
void svg_draw_text(svg_render *r, const svg_node *node, cg_mat3 ctm, const svg_viewport *vp,
                   const svg_style *s, double opacity, cg_image *target);
/* Frees r->fonts. */
void svg_fonts_free(svg_render *r);
/* Draws an <image> with an embedded PNG. */
void svg_draw_image(svg_render *r, const svg_node *node, cg_mat3 ctm, const svg_viewport *vp,
                    const svg_style *style, cg_image *target);
/* Stops the drawing with an error message (the first one is kept). */
void svg_fail(svg_render *r, cg_status status, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#endif
