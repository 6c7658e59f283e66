/* cg/draw.h - 2D scan conversion (chapter 2 of the notes).
 *
 * Colours are encoded sRGB (cg_rgba8); a colour with alpha < 255 is blended
 * source-over in linear light.  Every function draws into RGBA8 and RGBAF
 * images alike, accepts coordinates anywhere (far outside the image, near the
 * limits of int), draws only the visible part and never walks invisible
 * pixels of a line one by one.  Invalid arguments (NULL image, NaN or
 * infinite coordinates, negative radii, tolerance <= 0) give CG_EINVAL and
 * nothing is drawn.
 *
 * Two coordinate conventions, as in the rest of cg:
 *  - integer functions (Bresenham lines, circles, ellipses, arcs) take pixel
 *    indices: pixel (x, y) is the point (x, y) of the digital geometry of the
 *    notes, and its centre is the point (x + 0.5, y + 0.5) of the image plane;
 *  - anti-aliased functions take continuous image-plane coordinates, where
 *    pixel (x, y) covers [x, x+1) x [y, y+1): a line through the centres of
 *    pixels (0, 0) and (9, 0) goes from (0.5, 0.5) to (9.5, 0.5).
 */
#ifndef CG_DRAW_H
#define CG_DRAW_H

#include "cg/core.h"
#include "cg/image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- lines (section 2.1) ------------------------------------------------ */

/* Bresenham's line (Algorithm 1) from pixel (x0, y0) to pixel (x1, y1), both
 * endpoints drawn, generalised to all eight octants.  The line is clipped to
 * the image first: the pixels drawn are exactly those of the unclipped line
 * that lie inside the image, at a cost proportional to the visible part.
 *
 * Tie rule: the line is always walked from the endpoint with the smaller
 * major-axis coordinate (the left one when |dx| >= |dy|, the top one
 * otherwise), and when the real line passes exactly through a midpoint the
 * pixel on that start endpoint's side is kept (Algorithm 1's "f <= 0: E").
 * So drawing a to b and b to a gives the same pixels. */
cg_status cg_draw_line(cg_image *image, int x0, int y0, int x1, int y1, cg_rgba8 color);

/* An anti-aliased line one pixel wide between two image-plane points, with
 * butt ends exactly at the endpoints.  Each pixel gets the area of the
 * 1-pixel-thick band that falls in its column (row, for steep lines), so a
 * line's total coverage per unit length is 1 whatever its angle; colours are
 * blended in linear light.  A zero-length line draws nothing. */
cg_status cg_draw_line_aa(cg_image *image, double x0, double y0, double x1, double y1,
                          cg_rgba8 color);

/* Wu's anti-aliased line between the centres of pixels (x0, y0) and
 * (x1, y1): in each column along the major axis (row, for steep lines) the
 * two pixels around the real line, with intensities 1 - f and f, f the
 * fractional part of the line's minor coordinate there.  Blended in linear
 * light; the trace is cg_line_wu_steps (cg/trace_steps.h). */
cg_status cg_draw_line_wu(cg_image *image, int x0, int y0, int x1, int y1, cg_rgba8 color);

/* Connected Bresenham lines through count points (pixel indices); each
 * joint pixel is drawn once.  count >= 1. */
cg_status cg_draw_polyline(cg_image *image, const int *xy, int count, cg_rgba8 color);
/* Connected anti-aliased lines through count image-plane points. */
cg_status cg_draw_polyline_aa(cg_image *image, const cg_vec2 *points, int count, cg_rgba8 color);

/* ---- circles, ellipses, arcs (section 2.2) ------------------------------ */

/* Bresenham's midpoint circle (Algorithm 2: second-order differences and
 * 8-way symmetry) centred on pixel (cx, cy) with radius r >= 0 (r = 0 is one
 * pixel).  Every pixel is drawn exactly once, also where octants meet. */
cg_status cg_draw_circle(cg_image *image, int cx, int cy, int r, cg_rgba8 color);

/* The filled digital circle: on each row, every pixel from the leftmost to
 * the rightmost pixel of cg_draw_circle's circle on that row. */
cg_status cg_draw_disc(cg_image *image, int cx, int cy, int r, cg_rgba8 color);

/* The midpoint ellipse with axis-aligned radii rx, ry >= 0 (two regions cut
 * where the slope is -1, 4-way symmetry); each pixel drawn once.  Equal radii
 * give cg_draw_circle's circle.  Radii up to 2^30 (CG_ERANGE beyond). */
cg_status cg_draw_ellipse(cg_image *image, int cx, int cy, int rx, int ry, cg_rgba8 color);

/* The pixels of cg_draw_circle / cg_draw_ellipse whose direction from the
 * centre lies on the arc that runs counter-clockwise (as seen on screen:
 * 0 degrees points right, 90 up) from start_deg to end_deg.  end_deg is taken
 * modulo 360 after start_deg, except that end_deg - start_deg >= 360 gives
 * the whole curve.  A pixel's direction is the polar angle of its offset from
 * the centre (for ellipses too, not the parametric angle). */
cg_status cg_draw_arc(cg_image *image, int cx, int cy, int r, double start_deg, double end_deg,
                      cg_rgba8 color);
cg_status cg_draw_ellipse_arc(cg_image *image, int cx, int cy, int rx, int ry, double start_deg,
                              double end_deg, cg_rgba8 color);

/* Anti-aliased circle and ellipse one pixel wide, centred on an image-plane
 * point: each pixel gets coverage max(0, 1 - |d|) where d is the distance of
 * its centre from the real curve (for ellipses, the first-order estimate
 * F / |grad F|).  Blended in linear light.  Radii up to 1e9 (CG_ERANGE
 * beyond, unless the ring misses the image). */
cg_status cg_draw_circle_aa(cg_image *image, double cx, double cy, double r, cg_rgba8 color);
cg_status cg_draw_ellipse_aa(cg_image *image, double cx, double cy, double rx, double ry,
                             cg_rgba8 color);

/* ---- curves (section 2.3), flattened then drawn ------------------------- */

/* How cg_draw_bezier and friends draw the flattened polyline.  Control
 * points are image-plane coordinates in both modes. */
typedef enum cg_draw_mode {
    /* Bresenham lines between the pixels that contain the polyline's points
     * (coordinates up to 1e9 in magnitude: CG_ERANGE beyond) */
    CG_DRAW_ALIASED = 0,
    CG_DRAW_ANTIALIASED = 1 /* anti-aliased lines */
} cg_draw_mode;

/* A Bézier curve of any degree (count = degree + 1 control points, 2 to
 * CG_BEZIER_MAX_POINTS), flattened within tolerance pixels and drawn.
 * CG_EEMPTY (nothing drawn) when every control point is the same point. */
cg_status cg_draw_bezier(cg_image *image, const cg_vec2 *control, int count, double tolerance,
                         cg_draw_mode mode, cg_rgba8 color);
/* A Hermite segment: endpoints p1, p4 and tangents r1, r4 (section 2.3.2). */
cg_status cg_draw_hermite(cg_image *image, cg_vec2 p1, cg_vec2 p4, cg_vec2 r1, cg_vec2 r4,
                          double tolerance, cg_draw_mode mode, cg_rgba8 color);
/* A uniform cubic B-spline through count >= 4 control points (count - 3
 * segments), or a Catmull-Rom spline (interpolates points 1 .. count-2). */
cg_status cg_draw_bspline(cg_image *image, const cg_vec2 *control, int count, double tolerance,
                          cg_draw_mode mode, cg_rgba8 color);
cg_status cg_draw_catmull_rom(cg_image *image, const cg_vec2 *control, int count, double tolerance,
                              cg_draw_mode mode, cg_rgba8 color);

/* ---- stepping through the algorithms (for `cg trace`) ------------------- */

/* One step of Algorithm 1.  The line is first mapped to the first octant
 * (0 <= dy <= dx) by swapping the endpoints and mirroring, as for drawing;
 * f, dE and dNE are the notes' doubled decision variable and increments in
 * that octant, and (x, y) the pixel chosen in the real image. */
typedef struct cg_line_step {
    int x, y;         /* pixel selected at this step */
    const char *move; /* "start", "E" or "NE" (in first-octant terms) */
    long long f;      /* decision value tested to choose this move (start: the initial f) */
    long long f_next; /* f after the update, tested at the next step */
} cg_line_step;

/* Calls step(user, &s) for every pixel of the line, in drawing order, and
 * fills the octant description: *dx, *dy (first-octant values), *de, *dne.
 * Any out-pointer may be NULL, and step too (only the description is
 * filled then).  A non-zero callback result stops the walk. */
cg_status cg_line_trace(int x0, int y0, int x1, int y1,
                        int (*step)(void *user, const cg_line_step *s), void *user, long long *dx,
                        long long *dy, long long *de, long long *dne);

/* One step of Algorithm 2 for the first octant of a circle of radius r. */
typedef struct cg_circle_step {
    int x, y;          /* pixel of the first octant after this step */
    const char *move;  /* "start", "E" or "SE" */
    long long f;       /* decision value tested (start: the initial f = 1 - r) */
    long long de, dse; /* increments used with f at this step (start: initial values) */
    long long f_next, de_next, dse_next; /* values after the update */
} cg_circle_step;

/* Calls step(user, &s) for each step of Algorithm 2 (x = 0 .. while x < y),
 * r >= 0.  A final step may end with x > y: that pixel mirrors one already
 * selected and cg_draw_circle does not draw it again. */
cg_status cg_circle_trace(int r, int (*step)(void *user, const cg_circle_step *s), void *user);

#ifdef __cplusplus
}
#endif
#endif
