/* cg/fill.h - filling (chapter 10 of the notes): flood and boundary fill,
 * scan-line polygon fill, anti-aliased paths and strokes.
 *
 * Coordinates of polygons and paths are continuous, as in SVG and Cairo:
 * pixel (x, y) covers [x, x+1) x [y, y+1) and its centre is (x+0.5, y+0.5);
 * integer vertices lie on pixel corners.
 *
 *  - Aliased fill (cg_fill_polygon): a pixel is painted when its centre is
 *    inside.  A centre exactly on an edge belongs to the region on its right
 *    (greater x); a centre exactly on a horizontal edge belongs to the region
 *    below it (greater y).  So polygons that share edges never paint a pixel
 *    twice and never leave a gap between them.
 *  - Anti-aliased fill (cg_fill_polygon_aa, cg_fill_path, cg_stroke_path):
 *    each pixel gets the exact area of its square covered by the shape
 *    (signed-area accumulation), composited source-over in linear light.
 *    With the non-zero rule the coverage is min(1, |winding-weighted area|);
 *    with even-odd the area folded into [0, 1].  Both are exact wherever the
 *    winding number inside a pixel takes only the values 0 and +-1.
 *
 * Colours are cg_rgba8 (sRGB-encoded, straight alpha).  Images may be RGBA8
 * or RGBAF; blending always happens in linear light.
 *
 * Bad input (NaN or infinite coordinates, coordinates beyond +-CG_FILL_MAX_COORD,
 * negative or NaN widths, malformed path data) returns a status and draws
 * nothing.  Empty and zero-area shapes draw nothing and return CG_OK.
 */
#ifndef CG_FILL_H
#define CG_FILL_H

#include "cg/core.h"
#include "cg/image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest accepted |coordinate| of a polygon or path point (2^40). */
#define CG_FILL_MAX_COORD 1099511627776.0

typedef enum cg_fill_rule {
    CG_FILL_EVEN_ODD = 0, /* inside where a ray crosses the outline an odd number of times */
    CG_FILL_NONZERO = 1   /* inside where the winding number is not zero */
} cg_fill_rule;

/* ---- flood fill (10.1) --------------------------------------------------- */

typedef enum cg_connectivity {
    CG_CONNECT_4 = 4, /* left, right, up, down */
    CG_CONNECT_8 = 8  /* and the four diagonals */
} cg_connectivity;

/* Seed fill: replaces the connected region of pixels "like" the seed pixel
 * (x, y) with color.  A pixel is like the seed when every channel (r, g, b, a
 * of the encoded colour) differs from the seed's by at most tolerance
 * (0..255; 0 = exactly the same colour).  The region is 4- or 8-connected.
 * A scan-line span algorithm with an explicit, growing stack: no recursion,
 * every pixel is read a bounded number of times.  *filled (may be NULL)
 * receives the number of pixels of the region.
 * RGBA8 images only (CG_EUNSUPPORTED otherwise); CG_ERANGE when the seed is
 * outside the image; CG_EINVAL for a bad connectivity or tolerance;
 * CG_ENOMEM when the stack cannot grow (the image is then partly filled). */
cg_status cg_flood_fill(cg_image *image, int x, int y, cg_rgba8 color, cg_connectivity connectivity,
                        int tolerance, size_t *filled);

/* Boundary fill: paints color over the connected region around (x, y) of
 * pixels that are not of the boundary colour (within tolerance, as above).
 * Pixels inside that already have the fill colour are painted through, not
 * treated as walls.  A seed on the boundary fills nothing.  Same statuses. */
cg_status cg_boundary_fill(cg_image *image, int x, int y, cg_rgba8 color, cg_rgba8 boundary,
                           cg_connectivity connectivity, int tolerance, size_t *filled);

/* ---- paints ---------------------------------------------------------------- */

typedef enum cg_paint_type {
    CG_PAINT_SOLID = 0,
    CG_PAINT_LINEAR = 1, /* colour varies along p0 -> p1 */
    CG_PAINT_RADIAL = 2  /* colour varies with distance from p0, reaching the end at radius */
} cg_paint_type;

/* What a gradient does beyond its ends (t outside [0, 1]), as SVG's
 * spreadMethod: pad holds the end colours, reflect mirrors the ramp back
 * and forth, repeat starts it again. */
typedef enum cg_gradient_spread {
    CG_SPREAD_PAD = 0,
    CG_SPREAD_REFLECT = 1,
    CG_SPREAD_REPEAT = 2
} cg_gradient_spread;

typedef struct cg_gradient_stop {
    double offset; /* 0..1, non-decreasing along the array */
    cg_rgba8 color;
} cg_gradient_stop;

/* How a shape is coloured.  Gradients interpolate their stops in the
 * rasterizer's compositing space: in linear light premultiplied by alpha
 * (the default), or, in the sRGB space, on the encoded values with straight
 * alpha (as SVG renderers do).  The stops array is read during the drawing
 * call only.  Fields added after the first ones are zero in a paint made by
 * the constructors below, and zero means "not used". */
typedef struct cg_paint {
    cg_paint_type type;
    cg_rgba8 color; /* CG_PAINT_SOLID */
    cg_vec2 p0, p1; /* linear: t = 0 at p0, 1 at p1; radial: centre p0 */
    double radius;  /* radial: t = 1 at this distance from p0 */
    const cg_gradient_stop *stops;
    int stop_count;            /* at least 1 for gradients */
    cg_gradient_spread spread; /* beyond the ends; default pad */
    /* radial with has_focal: t = 0 at focal (SVG's fx, fy) and 1 on the
     * circle, along each ray from focal; a focal point outside the circle
     * is moved just inside it, as SVG 1.1 says */
    int has_focal;
    cg_vec2 focal;
    /* has_transform: p0, p1, radius and focal are in a space mapped to
     * pixels by transform (SVG's gradientTransform and objectBoundingBox
     * units); it must be invertible */
    int has_transform;
    cg_mat3 transform;
} cg_paint;

cg_paint cg_paint_solid(cg_rgba8 color);
cg_paint cg_paint_linear(cg_vec2 p0, cg_vec2 p1, const cg_gradient_stop *stops, int stop_count);
cg_paint cg_paint_radial(cg_vec2 center, double radius, const cg_gradient_stop *stops,
                         int stop_count);

/* ---- compositing ------------------------------------------------------------- */

/* The space in which a drawing mixes colours: linear light (physical mixing,
 * cg's default, SVG's color-interpolation: linearRGB) or the sRGB-encoded
 * values themselves (what SVG, CSS and browsers do by default).  Images keep
 * their own format: RGBA8 is always sRGB-encoded and RGBAF linear. */
typedef enum cg_compositing_space {
    CG_COMPOSITE_LINEAR = 0,
    CG_COMPOSITE_SRGB = 1
} cg_compositing_space;

/* Porter-Duff operators.  With source colour cs and alpha as, backdrop cb
 * and ab (premultiplied), the result is co = cs * Fa + cb * Fb and
 * ao = as * Fa + ab * Fb with the factors
 *     clear 0, 0          source 1, 0           destination 0, 1
 *     over 1, 1-as        destination_over 1-ab, 1
 *     in ab, 0            destination_in 0, as
 *     out 1-ab, 0         destination_out 0, 1-as
 *     atop ab, 1-as       destination_atop 1-ab, as
 *     xor 1-ab, 1-as      plus 1, 1 (clamped to 1)
 * A drawing applies its operator within the shape only: a pixel of coverage
 * k gets k * operator(source, backdrop) + (1 - k) * backdrop, and pixels
 * outside the shape keep their colour. */
typedef enum cg_composite_operator {
    CG_OPERATOR_OVER = 0,
    CG_OPERATOR_CLEAR,
    CG_OPERATOR_SOURCE,
    CG_OPERATOR_DESTINATION,
    CG_OPERATOR_DESTINATION_OVER,
    CG_OPERATOR_IN,
    CG_OPERATOR_DESTINATION_IN,
    CG_OPERATOR_OUT,
    CG_OPERATOR_DESTINATION_OUT,
    CG_OPERATOR_ATOP,
    CG_OPERATOR_DESTINATION_ATOP,
    CG_OPERATOR_XOR,
    CG_OPERATOR_PLUS,
    CG_OPERATOR_COUNT
} cg_composite_operator;

/* The blend modes of the W3C Compositing and Blending spec: B(cb, cs) on
 * straight colours replaces the source colour by
 * (1 - ab) * cs + ab * B(cb, cs) before the operator is applied. */
typedef enum cg_blend_mode {
    CG_BLEND_NORMAL = 0,
    CG_BLEND_MULTIPLY,
    CG_BLEND_SCREEN,
    CG_BLEND_OVERLAY,
    CG_BLEND_DARKEN,
    CG_BLEND_LIGHTEN,
    CG_BLEND_COLOR_DODGE,
    CG_BLEND_COLOR_BURN,
    CG_BLEND_HARD_LIGHT,
    CG_BLEND_SOFT_LIGHT,
    CG_BLEND_DIFFERENCE,
    CG_BLEND_EXCLUSION,
    CG_BLEND_HUE,
    CG_BLEND_SATURATION,
    CG_BLEND_COLOR,
    CG_BLEND_LUMINOSITY,
    CG_BLEND_COUNT
} cg_blend_mode;

/* One pixel: source over backdrop, both premultiplied with components in
 * [0, 1] (any space), through blend mode then operator; premultiplied. */
cg_rgbaf cg_composite(cg_rgbaf source, cg_rgbaf backdrop, cg_composite_operator op,
                      cg_blend_mode mode);

/* Names as CSS and SVG spell them ("source-over" is "over", "copy" is
 * "source", "destination-in", "lighter" is "plus"; "multiply",
 * "color-dodge", ...): NULL for a value out of range; the parsers accept
 * the name and CSS's alternative spellings and return CG_EINVAL otherwise. */
const char *cg_composite_operator_name(cg_composite_operator op);
const char *cg_blend_mode_name(cg_blend_mode mode);
cg_status cg_composite_operator_parse(const char *name, cg_composite_operator *out);
cg_status cg_blend_mode_parse(const char *name, cg_blend_mode *out);

/* ---- polygons (10.2) ------------------------------------------------------- */

/* A polygon of contour_count contours: contour i has contour_sizes[i] points,
 * taken in order from points (all contours concatenated); each contour is
 * closed implicitly.  Contours may cross each other and themselves; holes
 * are contours (any orientation under even-odd, opposite orientation under
 * non-zero). */

/* Aliased scan-line fill with an edge table and an active edge list; the
 * pixel-centre rule above.  color's alpha < 255 blends in linear light. */
cg_status cg_fill_polygon(cg_image *image, const cg_vec2 *points, const int *contour_sizes,
                          int contour_count, cg_fill_rule rule, cg_rgba8 color);

/* Anti-aliased fill by exact area coverage. */
cg_status cg_fill_polygon_aa(cg_image *image, const cg_vec2 *points, const int *contour_sizes,
                             int contour_count, cg_fill_rule rule, const cg_paint *paint);

/* ---- paths ----------------------------------------------------------------- */

typedef struct cg_path cg_path;

cg_status cg_path_create(cg_path **out);
void cg_path_free(cg_path *path);
/* Removes every segment (keeps the memory). */
void cg_path_reset(cg_path *path);
/* True when the path has no drawing segment. */
int cg_path_is_empty(const cg_path *path);

/* Each returns CG_EINVAL (and leaves the path unchanged) for a NaN, infinite
 * or out-of-range coordinate.  A segment without a current point starts at
 * (0, 0), as in SVG. */
cg_status cg_path_move_to(cg_path *path, double x, double y);
cg_status cg_path_line_to(cg_path *path, double x, double y);
/* Quadratic Bezier with control point (x1, y1) ending at (x, y). */
cg_status cg_path_quad_to(cg_path *path, double x1, double y1, double x, double y);
/* Cubic Bezier with control points (x1, y1), (x2, y2) ending at (x, y). */
cg_status cg_path_cubic_to(cg_path *path, double x1, double y1, double x2, double y2, double x,
                           double y);
/* Circular arc around (cx, cy) of radius r from angle a0 to angle a1 (radians,
 * measured from +x towards +y, so clockwise on screen when a1 > a0 and
 * counter-clockwise when a1 < a0).  A line joins the current point to the
 * arc's start (a move when there is no current point). */
cg_status cg_path_arc(cg_path *path, double cx, double cy, double r, double a0, double a1);
/* SVG elliptical arc from the current point to (x, y): radii rx, ry, x-axis
 * rotation in degrees, large-arc and sweep flags; radii too small are scaled
 * up and a zero radius gives a straight line, as SVG specifies. */
cg_status cg_path_svg_arc_to(cg_path *path, double rx, double ry, double rotation_degrees,
                             int large_arc, int sweep, double x, double y);
/* Closes the current subpath with a straight line to its start. */
cg_status cg_path_close(cg_path *path);

/* Appends SVG path data ("M 10 10 L 20 10 Q 30 20 10 30 Z", all of
 * M L H V C S Q T A Z in both absolute and relative forms).  CG_EFORMAT with
 * a message giving the byte offset and what was expected; the path is then
 * left as it was before the call. */
cg_status cg_path_append_svg(cg_path *path, const char *data, cg_error *err);

/* Appends path to out with every point mapped by the affine matrix (its
 * last row must be 0 0 1; CG_EINVAL otherwise or for a non-finite or
 * out-of-range result).  Lines and Beziers map exactly; arcs become cubic
 * Beziers of at most 45 degrees each (within 4e-6 of the radius).  out may
 * not be path. */
cg_status cg_path_transform(const cg_path *path, cg_mat3 matrix, cg_path *out);

/* The smallest box holding the path's curves (flattened within tolerance,
 * at least 0.001): CG_EINVAL for an empty path. */
cg_status cg_path_bounds(const cg_path *path, double tolerance, cg_vec2 *min, cg_vec2 *max);

/* ---- strokes ---------------------------------------------------------------- */

typedef enum cg_line_join { CG_JOIN_MITER = 0, CG_JOIN_ROUND = 1, CG_JOIN_BEVEL = 2 } cg_line_join;
typedef enum cg_line_cap { CG_CAP_BUTT = 0, CG_CAP_ROUND = 1, CG_CAP_SQUARE = 2 } cg_line_cap;

typedef struct cg_stroke_style {
    double width; /* > 0 */
    cg_line_join join;
    cg_line_cap cap;
    double miter_limit;   /* >= 1: longest miter / width; longer ones become bevels */
    const double *dashes; /* NULL or dash_count lengths: on, off, on, ... */
    int dash_count;       /* an odd count is repeated twice, as in SVG */
    double dash_offset;   /* distance into the pattern at the start of each subpath */
} cg_stroke_style;

/* Width 1, miter joins with limit 4, butt caps, no dashes (SVG's defaults). */
cg_stroke_style cg_stroke_style_default(void);

/* The outline of the stroke as a path of closed polygons to be filled with
 * the non-zero rule (curves flattened within tolerance pixels).  The outline
 * is appended to out. */
cg_status cg_stroke_to_path(const cg_path *path, const cg_stroke_style *style, double tolerance,
                            cg_path *out);

/* Anti-aliased fill of the path (each subpath closed implicitly); curves are
 * flattened within 0.1 pixel. */
cg_status cg_fill_path(cg_image *image, const cg_path *path, cg_fill_rule rule,
                       const cg_paint *paint);
/* Anti-aliased stroke: the outline of cg_stroke_to_path filled non-zero. */
cg_status cg_stroke_path(cg_image *image, const cg_path *path, const cg_stroke_style *style,
                         const cg_paint *paint);

/* ---- a reusable rasterizer ------------------------------------------------- */

/* Holds the scratch memory and tables of the drawing calls above, so that a
 * program drawing many shapes allocates once.  One rasterizer per thread. */
typedef struct cg_rasterizer cg_rasterizer;

cg_status cg_rasterizer_create(cg_rasterizer **out);
void cg_rasterizer_free(cg_rasterizer *rasterizer);
/* Flattening tolerance in pixels for curves, arcs and round joins
 * (default 0.1; CG_EINVAL unless in [0.001, 100]). */
cg_status cg_rasterizer_set_tolerance(cg_rasterizer *rasterizer, double tolerance);
/* How the drawing calls below mix colours: the compositing space (default
 * linear), the operator (default over) and the blend mode (default normal);
 * CG_EINVAL for a value out of range. */
cg_status cg_rasterizer_set_compositing(cg_rasterizer *rasterizer, cg_compositing_space space,
                                        cg_composite_operator op, cg_blend_mode mode);

cg_status cg_rasterizer_fill_polygon(cg_rasterizer *rasterizer, cg_image *image,
                                     const cg_vec2 *points, const int *contour_sizes,
                                     int contour_count, cg_fill_rule rule, cg_rgba8 color);
cg_status cg_rasterizer_fill_polygon_aa(cg_rasterizer *rasterizer, cg_image *image,
                                        const cg_vec2 *points, const int *contour_sizes,
                                        int contour_count, cg_fill_rule rule,
                                        const cg_paint *paint);
cg_status cg_rasterizer_fill_path(cg_rasterizer *rasterizer, cg_image *image, const cg_path *path,
                                  cg_fill_rule rule, const cg_paint *paint);
cg_status cg_rasterizer_stroke_path(cg_rasterizer *rasterizer, cg_image *image, const cg_path *path,
                                    const cg_stroke_style *style, const cg_paint *paint);

/* ---- layers ------------------------------------------------------------------ */

/* A layer is a transparent image of the drawing's size (cg_image_create
 * makes one): draw into it with any calls, then composite it onto the
 * drawing as one piece, as SVG does for a group with opacity, a blend mode,
 * a clip path or a mask. */

typedef enum cg_mask_type {
    CG_MASK_ALPHA = 0,    /* the mask image's alpha */
    CG_MASK_LUMINANCE = 1 /* its luminance times its alpha (SVG's mask) */
} cg_mask_type;

typedef struct cg_layer_style {
    double opacity;           /* 0..1: scales the layer's alpha */
    cg_composite_operator op; /* how the layer meets the drawing */
    cg_blend_mode mode;
    /* NULL, or a path in pixel coordinates: the layer shows only inside it
     * (anti-aliased: a pixel half inside gets half the layer's effect),
     * under clip_rule */
    const cg_path *clip;
    cg_fill_rule clip_rule;
    /* NULL, or an image of the layer's size whose value (below) scales the
     * layer's alpha pixel by pixel */
    const cg_image *mask;
    cg_mask_type mask_type;
    /* has_box: only pixels x0 <= x < x1, y0 <= y < y1 are composited (a
     * clip rectangle; a caller that knows where the layer has content
     * saves the work of the rest) */
    int has_box;
    int box_x0, box_y0, box_x1, box_y1;
} cg_layer_style;

/* Opacity 1, over, normal, no clip (non-zero rule), no mask, no box. */
cg_layer_style cg_layer_style_default(void);

/* Composites layer onto image (both the same size, RGBA8 or RGBAF) in the
 * rasterizer's compositing space: each pixel of the layer, its alpha scaled
 * by opacity and the mask, goes through the blend mode and operator, within
 * the clip as a drawing within its shape.  CG_EINVAL for a size mismatch, an
 * opacity outside [0, 1] or a bad enum; the rasterizer's own operator and
 * blend mode are not used. */
cg_status cg_rasterizer_composite_layer(cg_rasterizer *rasterizer, cg_image *image,
                                        const cg_image *layer, const cg_layer_style *style);

#ifdef __cplusplus
}
#endif
#endif
