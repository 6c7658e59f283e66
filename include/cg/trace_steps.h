/* cg/trace_steps.h - the course's algorithms step by step (`cg trace`).
 *
 * A trace calls a cg_step_fn once per step of an algorithm with a cg_step:
 * the algorithm's state at that step as named fields in the notes'
 * vocabulary (f, dE, dNE, p, q, t, ...), the pixels the step sets (they stay
 * in the picture) and the geometry it works on (a polyline shown with that
 * step only).  Every trace ends in the same result as the library call it
 * explains: the pixels a line trace lists are the pixels cg_draw_line sets,
 * the points a flattening trace emits are those of cg_bezier_flatten, the
 * list Sutherland-Hodgman's trace ends with is cg_clip_sutherland_hodgman's.
 * docs/teaching.md lists each trace's fields.
 *
 * A callback that returns non-zero stops the trace, which then returns
 * CG_OK.  Pointers in a cg_step are valid during the callback only;
 * cg_step_log keeps copies. */
#ifndef CG_TRACE_STEPS_H
#define CG_TRACE_STEPS_H

#include "cg/core.h"
#include "cg/clip.h"
#include "cg/curve.h"
#include "cg/fill.h"
#include "cg/image.h"
#include "cg/hemesh.h"
#include "cg/light.h"
#include "cg/mesh.h"
#include "cg/render.h"
#include "cg/trace.h"
#include "cg/xform.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cg_step_kind {
    CG_STEP_NONE = 0,    /* no value at this step (shown as "-", JSON null) */
    CG_STEP_INTEGER = 1, /* integer */
    CG_STEP_REAL = 2,    /* real */
    CG_STEP_TEXT = 3,    /* text: a move, a decision, a reason */
    CG_STEP_PIXEL = 4,   /* pixel (x, y) in integer */
    CG_STEP_POINT = 5,   /* point in point */
    CG_STEP_POINTS = 6,  /* list of point_count points in points */
    CG_STEP_REALS = 7    /* real_count reals in reals: a vector, or a 4 x 4
                            matrix row by row (16 reals) */
} cg_step_kind;

typedef struct cg_step_field {
    const char *name; /* a short identifier: "f", "dE", "t_enter", ... */
    cg_step_kind kind;
    long long integer;
    double real;
    int pixel_x, pixel_y;
    cg_vec2 point;
    const char *text;
    const cg_vec2 *points;
    size_t point_count;
    const double *reals;
    size_t real_count;
} cg_step_field;

typedef struct cg_step {
    const char *phase; /* "region 1", "clip edge 2", ... or NULL */
    const cg_step_field *fields;
    int field_count;
    /* The pixels this step sets, x y pairs, and their intensities in [0, 1]
     * (NULL: all 1). */
    const int *pixels;
    const double *intensity;
    int pixel_count;
    /* The geometry this step looks at: a polyline (closed when closed). */
    const cg_vec2 *geometry;
    int geometry_count;
    int closed;
    /* Geometry the step adds to the result for good (a polyline), as a
     * flattening step's chord. */
    const cg_vec2 *kept;
    int kept_count;
    int kept_closed; /* kept is a closed polygon that replaces earlier ones */
} cg_step;

typedef int (*cg_step_fn)(void *user, const cg_step *step);

/* The field called name in step, or NULL. */
const cg_step_field *cg_step_find(const cg_step *step, const char *name);

/* ---- a log: every step copied, for printing and pictures afterwards ---- */

typedef struct cg_step_log cg_step_log;

cg_status cg_step_log_create(cg_step_log **out);
void cg_step_log_free(cg_step_log *log);
/* A cg_step_fn (user: the log) that appends a copy of the step; it returns
 * non-zero (stopping the trace) when memory runs out, and
 * cg_step_log_status then gives CG_ENOMEM. */
int cg_step_log_record(void *log, const cg_step *step);
cg_status cg_step_log_status(const cg_step_log *log);
size_t cg_step_log_count(const cg_step_log *log);
/* Step i (i < count), owned by the log. */
const cg_step *cg_step_log_get(const cg_step_log *log, size_t i);

/* ---- chapter 2: lines, circles, ellipses ------------------------------ */

/* Bresenham's line (Algorithm 1) as cg_draw_line walks it: fields f, move
 * ("start", "E", "NE"), f_next and pixel, after a first step (phase
 * "octant") naming the octant and its mapping to the first one (fields
 * octant, swap, mirror, dx, dy, f0, dE, dNE).  Lines up to 10^6 steps
 * (CG_ERANGE beyond). */
cg_status cg_line_steps(int x0, int y0, int x1, int y1, cg_step_fn step, void *user);

/* The DDA line: the major coordinate steps by 1 and the minor one by the
 * slope m, rounded to the nearest pixel (halves round up).  Fields k, x, y
 * (real), pixel.  Its pixels lie within 1/2 of the line along the minor
 * axis; they differ from Bresenham's only where the line passes through a
 * midpoint, or by the rounding of the accumulated slope. */
cg_status cg_line_dda_steps(int x0, int y0, int x1, int y1, cg_step_fn step, void *user);

/* Wu's line as cg_draw_line_wu draws it: phase "columns", one step per
 * column along the major axis with k, major (the column), minor (the real
 * minor coordinate of the line there), the lower and upper pixels and
 * their intensities I_lower = 1 - frac(minor), I_upper = frac(minor); the
 * step's pixels carry those intensities. */
cg_status cg_line_wu_steps(int x0, int y0, int x1, int y1, cg_step_fn step, void *user);

/* Algorithm 2 (cg_circle_trace) with its 8 mirrors: fields f, dE, dSE, move,
 * f_next, dE_next, dSE_next, pixel (first octant); the step's pixels are
 * those cg_draw_circle sets for it, centred on (cx, cy).  r up to 10^6. */
cg_status cg_circle_steps(int cx, int cy, int r, cg_step_fn step, void *user);

/* The midpoint ellipse as cg_draw_ellipse draws it (rx != ry; equal radii
 * are the circle): region 1 column by column from (0, ry) (E or SE, the
 * decision d1 = 4 F(x, y - 1/2) at the midpoint below), the switch where the
 * slope reaches -1, region 2 row by row down to y = 0 (S or SE, d2 =
 * 4 F(x + 1/2, y)), and the bridge pixel when the regions leave a gap.
 * Fields x, y, d (the decision value), move, pixel; the step's pixels are the
 * four mirrors.  Radii up to 10^5. */
cg_status cg_ellipse_steps(int cx, int cy, int rx, int ry, cg_step_fn step, void *user);

/* ---- chapter 2: curves ------------------------------------------------- */

/* de Casteljau's algorithm at t for count control points (2 to 64): one
 * step per level r = 1 .. count-1 with the level's points P_i^r =
 * (1 - t) P_i^(r-1) + t P_(i+1)^(r-1) (field points); the last level is the
 * curve point (cg_bezier_point), and the two subdivisions' control points
 * (cg_bezier_split) end the trace. */
cg_status cg_casteljau_steps(const cg_vec2 *control, int count, double t, cg_step_fn step,
                             void *user);

/* Q(t) = T M G of a cubic segment at t = 0, 1/n, ..., 1 (n from 1 to 1000):
 * fields t, T (t^3 t^2 t 1), the blending weights T M (one per entry of G)
 * as b1..b4 and the point Q (cg_cubic2_point). */
cg_status cg_cubic_steps(const cg_cubic2 *curve, int n, cg_step_fn step, void *user);

/* Adaptive flattening of a Bézier curve as cg_bezier_flatten does it: each
 * piece tested (its parameter range, its flatness measure and the
 * tolerance), split or emitted, and why.  The points emitted, in order, are
 * exactly those cg_bezier_flatten gives the sink.  At most 100000 steps. */
cg_status cg_bezier_flatten_steps(const cg_vec2 *control, int count, double tolerance,
                                  cg_step_fn step, void *user);

/* ---- chapters 3-4: the viewing pipeline --------------------------------- */

/* One point through model, view, projection and the viewport of a width x
 * height image: phase "matrices" (M, V, P, P V M, W, W P V M as 16 reals
 * row by row), phase "point" (the point in object, world, eye and clip
 * coordinates as (x, y, z, w), after the divide by w in NDC, and in window
 * coordinates: pixel x, y and depth, as cg_project_point gives them; the
 * window step sets that pixel when the point is in the view volume).  A
 * point with w <= 0 stops at the divide. */
cg_status cg_pipeline_steps(cg_mat4 model, cg_mat4 view, cg_mat4 projection, int width, int height,
                            cg_vec3 point, cg_step_fn step, void *user);

/* The vanishing point of the lines of direction d under view and a
 * perspective projection: phase "point", the point at infinity (d, 0) in
 * direction, eye and clip coordinates, after the divide, and in window
 * pixels (the step sets that pixel when it lies in the frame); w <= 0 ends
 * the trace with the reason (parallel to the image plane, or receding
 * behind the camera).  CG_EINVAL for a zero or non-finite direction. */
cg_status cg_vanishing_point_steps(cg_mat4 view, cg_mat4 projection, int width, int height,
                                   cg_vec3 direction, cg_step_fn step, void *user);

/* Back-face culling (chapter 5) of a mesh placed by model and seen by
 * camera: phase "triangles", one step per triangle of the fan
 * triangulation (triangle, face, the world normal N = (v1 - v0) x (v2 - v0),
 * V from v0 toward the eye (parallel cameras: against the view direction),
 * N.V, the decision "back: culled" when N.V <= 0, culled_so_far).  The
 * geometry is the triangle in view-space x, y (kept when it is front
 * facing).  The count of culled triangles is the renderer's
 * (cg_render_stats.culled) for a mesh in front of the camera.  Errors as
 * cg_mesh_validate; CG_EINVAL for an unusable camera. */
cg_status cg_backface_steps(const cg_mesh *mesh, cg_mat4 model, const cg_camera *camera,
                            cg_step_fn step, void *user);

/* The z-buffer at pixel (x, y) of a width x height frame of the mesh
 * (placed by model, seen by camera, back faces culled when cull): phase
 * "fragments", one step per triangle whose screen bounding box holds the
 * pixel's centre (triangle, face, window_xyz: its three projected vertices
 * as x, y, depth; the centre's barycentric coordinates; the interpolated
 * depth; the buffer's depth before; the decision: not covered, culled,
 * accepted as nearer, rejected), then phase "result": the triangle that
 * won and its depth, or the background.  The depth is the renderer's
 * (cg_renderer_depth) up to its fixed-point snapping of the vertices; a
 * triangle with a vertex behind the camera is listed but left to the
 * clipper. */
cg_status cg_zbuffer_pixel_steps(const cg_mesh *mesh, cg_mat4 model, const cg_camera *camera,
                                 int width, int height, int x, int y, int cull, cg_step_fn step,
                                 void *user);

/* The painter's algorithm (5.2) as cg_renderer_draw runs it: draws one
 * frame into image with the renderer's options and CG_RENDER_PAINTER (the
 * same bytes as cg_renderer_draw with that algorithm) and reports the
 * renderer's own steps: phase "sorted", the polygons (triangles after
 * culling and clipping, in window x, y and depth) by farthest depth (k,
 * polygon, triangle, z_max, z_min, x_extent, y_extent); phase "tests", for
 * the list's head P each Q whose depth range reaches P's, Newell's tests in
 * order up to the first that passes (P, Q, z_extents, x_extents,
 * y_extents, P_behind_Q_plane, Q_front_of_P_plane, projections: "-" when
 * not reached; outcome: the test that passed, a swap that moves Q in front
 * of P, or a split into two new polygons); phase "paint", each polygon as
 * it is painted (order, polygon, triangle, vertices, z_max, fragments,
 * color).  Geometry: the outlines in window coordinates (y down).  Errors
 * as cg_renderer_draw. */
cg_status cg_painter_steps(cg_renderer *renderer, cg_image *image, cg_step_fn step, void *user);

/* A pixel's ray tree (5.4) as cg_trace_render traces it, in a width x
 * height image: the renderer's own rays, in the order they are started.
 * Phase "rays", one step per ray (sample, ray, parent, kind: primary,
 * reflected or refracted; depth; weight: its share of the pixel; hit: the
 * object, or a miss; t, point, normal (toward the ray's side), side
 * (outside or inside the object); local: the light at the hit through its
 * shadow rays; fresnel (Schlick, transparent materials), kr and kt: the
 * weights of the reflected and refracted rays; secondary: what follows;
 * color = local + kr color(reflected) + kt color(refracted)).  Phase
 * "shadow rays": for each ray's hit, each light (ray, light, kind, the
 * verdict).  Phase "pixel": the pixel's colour (RGBA, linear), exactly
 * cg_trace_render's.  Geometry: each ray from the side (-z, y).  Errors
 * as cg_trace_render. */
cg_status cg_trace_pixel_steps(cg_trace_scene *scene, const cg_camera *camera,
                               const cg_trace_options *options, int width, int height, int x, int y,
                               cg_step_fn step, void *user);

/* Flat, Gouraud and Phong shading at pixel (x, y) as the z-buffer
 * renderer does it: draws one frame into image with the renderer's options
 * (the same bytes as cg_renderer_draw; CG_EINVAL unless the algorithm is
 * CG_RENDER_ZBUFFER) and reports each triangle's fragment there in drawing
 * order: phase "fragments" (fragment, window_xyz: the snapped vertices,
 * barycentric: the screen weights from the rasterizer's edge functions,
 * perspective: the perspective-correct weights l_k (1/w_k) / sum, depth,
 * buffer: the depth before, decision: written or hidden, mode, then flat:
 * color; Gouraud: vertex_colors and the interpolated color; Phong:
 * vertex_normals, the renormalized N, position, base and the lighting terms
 * ambient, diffuse, specular and their sum color), then phase "pixel": the
 * frame's pixel (linear RGBA).  The values are recomputed in double from
 * the rasterizer's setup; the written colour agrees with the pixel to its
 * float rounding. */
cg_status cg_shading_pixel_steps(cg_renderer *renderer, cg_image *image, int x, int y,
                                 cg_step_fn step, void *user);

/* ---- chapters 6-7: illumination and colour -------------------------------- */

/* The illumination at a point by cg/light.h's model, light by light: phase
 * "lights", one step per light with its kind, intensity I_l and, for the
 * others than ambient ones, L (unit, toward the light), distance, f_att,
 * spot, N.L, R and R.V (Phong) or H and N.H (Blinn-Phong), spec, a note
 * (lit, behind the surface, outside the cone), and the light's own
 * ambient, diffuse and specular terms (cg_light_shade_terms of that light
 * alone); phase "total": the terms of all lights and their sum I.
 * CG_EINVAL for a material or light that cg_material_check or
 * cg_light_check refuses. */
cg_status cg_light_steps(cg_vec3 position, cg_vec3 normal, cg_vec3 view,
                         const cg_material *material, const cg_light *lights, size_t count,
                         cg_step_fn step, void *user);

/* RGB to HSV (lightness 0) or HSL (lightness 1) by the notes' formulas:
 * phase "formulas", one step per quantity (R, G, B clamped, max, min,
 * delta, V or L, S with the case that applies, H by which channel is the
 * largest, and H += 360 when negative) with its formula and value; phase
 * "result": (H, S, V) or (H, S, L), exactly cg_rgb_to_hsv's or
 * cg_rgb_to_hsl's. */
cg_status cg_rgb_to_hsv_steps(cg_vec3 rgb, int lightness, cg_step_fn step, void *user);

/* Intensity to pixel (6.1.5) as cg_dither_plane does it on a width x
 * height plane (rows width floats apart; at most 2^20 values), pixel by
 * pixel in its order (phase "pixels", the step setting that pixel with its
 * output level as intensity): CG_DITHER_NONE gives I (clamped), s = I (N -
 * 1), k, the error I - out and out; the Bayer methods I, s, floor_s, frac,
 * the matrix index b, threshold = (b + 1/2) / n^2, the decision and out;
 * Floyd-Steinberg I, v (I plus the errors it received), error = v - out,
 * the weights ("7/16 3/16 5/16 1/16", renormalized at the border; none at
 * the last pixel), the parts pushed right, below_left, below and
 * below_right, and out.  The outputs are cg_dither_plane's, bit for
 * bit.  Errors as cg_dither_plane. */
cg_status cg_dither_plane_steps(const float *in, int width, int height, int levels,
                                cg_dither method, cg_step_fn step, void *user);

/* Gamma correction (7.2.1) of intensities: phase "values", one step per
 * value with k, I (clamped), the corrected voltage V = I^(1/gamma)
 * (cg_gamma_encode), its 8-bit code round(255 V), what the CRT shows of it
 * V^gamma (cg_gamma_decode: I again), what it shows of the uncorrected
 * I^gamma, and the sRGB encoding of I (cg_linear_to_srgb) beside them.
 * CG_EINVAL unless gamma is finite and > 0. */
cg_status cg_gamma_steps(const double *intensities, size_t count, double gamma, cg_step_fn step,
                         void *user);

/* ---- chapter 9: half-edge meshes ------------------------------------------ */

/* The loop of face f by next (phase "face loop": k, h, origin, next, twin,
 * the face across, a note where the loop closes), in the order of
 * cg_hemesh_face_halfedges; and the one-ring of vertex v counter-clockwise
 * (phase "one-ring": k, the outgoing half-edge h, the neighbour at its end,
 * its face, prev(h) and twin(prev(h)), the next outgoing one), in the order
 * of cg_hemesh_vertex_outgoing(v, 1).  Geometry: x, y of the positions.
 * CG_EINVAL for a deleted or missing face or vertex. */
cg_status cg_hemesh_face_loop_steps(const cg_hemesh *m, uint32_t f, cg_step_fn step, void *user);
cg_status cg_hemesh_one_ring_steps(const cg_hemesh *m, uint32_t v, cg_step_fn step, void *user);

/* Subdivision stencils: the new position of old vertex v of a structure
 * without deleted elements, as cg_hemesh_subdivide_loop (triangles only,
 * else CG_EUNSUPPORTED) or cg_hemesh_subdivide_catmull_clark places it,
 * bit for bit.  Phase "stencil", one step per term (k, term: "P",
 * "neighbour", "face point", "edge midpoint", "boundary neighbour"; its
 * index; its weight; its position): Loop (1 - n beta) for P and beta for
 * each neighbour; Catmull-Clark (n - 3) / n for P, 1 / n^2 for each face
 * point and 2 / n^2 for each edge midpoint; on the boundary 3/4 and 1/8,
 * 1/8.  Phase "result": the rule, n, beta (Loop), the old and the new
 * position.  CG_EINVAL for a bad or deleted vertex or a structure with
 * deleted elements. */
cg_status cg_hemesh_loop_stencil_steps(const cg_hemesh *m, uint32_t v, cg_step_fn step, void *user);
cg_status cg_hemesh_catmull_clark_stencil_steps(const cg_hemesh *m, uint32_t v, cg_step_fn step,
                                                void *user);

typedef enum cg_edge_operation {
    CG_EDGE_FLIP = 0,    /* cg_hemesh_flip_edge(m, e) */
    CG_EDGE_SPLIT = 1,   /* cg_hemesh_split_edge at the edge's midpoint */
    CG_EDGE_COLLAPSE = 2 /* cg_hemesh_collapse_edge(m, 2e): origin(2e) removed */
} cg_edge_operation;

/* Applies the operation to edge e of m (the library's call, so m is
 * changed exactly as by it) and lists the half-edge records around it:
 * phase "before", each half-edge leaving the edge's ends and its opposite
 * corners (k, h, origin, dest, twin, next, prev, face), phase "operation"
 * (the edge, its ends a and b, what was done, "done" or "refused", the new
 * vertex of a split), then, when done, phase "after": the same for the
 * vertices still there and the new one.  A refused operation is not an
 * error (CG_OK, the structure unchanged); CG_EINVAL for a bad or deleted
 * edge or operation. */
cg_status cg_hemesh_edge_operation_steps(cg_hemesh *m, cg_edge_operation operation, uint32_t e,
                                         cg_step_fn step, void *user);

/* ---- chapter 10: filling -------------------------------------------------- */

/* Scan-line polygon fill as cg_fill_polygon does it (same arguments, image
 * coordinates, y down): phase "edge table", one step per non-horizontal
 * edge that crosses a pixel centre, sorted by first row (edge number, top,
 * bottom, first_row, last_row, x_first, dx_per_row, direction); phase
 * "scan-lines", one step per row with active edges (y, centre_y, the edges
 * added and removed, the active list sorted by crossing, the spans with the
 * pixel-centre rule at their ends), setting the spans' pixels: exactly
 * cg_fill_polygon's, unclipped.  Coordinates up to 4096 (CG_ERANGE
 * beyond). */
cg_status cg_scanline_fill_steps(const cg_vec2 *points, const int *contour_sizes, int contour_count,
                                 cg_fill_rule rule, cg_step_fn step, void *user);

/* Flood fill (the region of pixels like the seed's colour) and boundary
 * fill (the region of pixels not of the boundary colour) by the notes'
 * scan-line seed fill with a stack of seeds: one step per seed popped
 * (phase "stack": popped, span "filled" with its left and right ends or
 * "already filled", the seeds pushed, stack_size and stack_top, the last
 * 64 entries), setting the span's pixels.  The region, connectivity and
 * tolerance are those of cg_flood_fill and cg_boundary_fill, which fill
 * exactly these pixels; the image is only read.  Statuses as theirs. */
cg_status cg_flood_fill_steps(const cg_image *image, int x, int y, cg_connectivity connectivity,
                              int tolerance, cg_step_fn step, void *user);
cg_status cg_boundary_fill_steps(const cg_image *image, int x, int y, cg_rgba8 boundary,
                                 cg_connectivity connectivity, int tolerance, cg_step_fn step,
                                 void *user);

/* ---- chapter 11: clipping (y-up coordinates, as cg/clip.h) -------------- */

/* Cohen-Sutherland as cg_clip_line_cohen_sutherland walks it (its trace
 * callback): phase "steps", one step per decision with the endpoints p0,
 * p1, their TBRL region codes code0, code1 ("1001": top and left), their
 * AND, and the step ("trivial accept", "trivial reject", "clip top", ...);
 * phase "outcome": accept or reject and the visible part. */
cg_status cg_cohen_sutherland_steps(cg_rect window, cg_vec2 p0, cg_vec2 p1, cg_step_fn step,
                                    void *user);

/* Liang-Barsky: one step per boundary in the notes' order (left, right,
 * bottom, top) with p, q, t = q / p, whether the line enters or leaves
 * there (or runs parallel), and t_enter, t_exit so far; a last step gives
 * the outcome, with the visible part as cg_clip_line_liang_barsky computes
 * it (exactly; the trace's t values are doubles).  CG_EINVAL as
 * cg_clip_line_liang_barsky. */
cg_status cg_liang_barsky_steps(cg_rect window, cg_vec2 p0, cg_vec2 p1, cg_step_fn step,
                                void *user);

/* Sutherland-Hodgman as cg_clip_sutherland_hodgman: for each clip edge one
 * step per polygon edge s -> e (inside/outside of each end, the case and
 * the points it outputs), then a step with the edge's input and output
 * lists.  The last output list is cg_clip_sutherland_hodgman's result.
 * Errors as cg_clip_sutherland_hodgman. */
cg_status cg_sutherland_hodgman_steps(const cg_vec2 *subject, size_t n, const cg_vec2 *window,
                                      size_t m, cg_step_fn step, void *user);

/* Weiler-Atherton as cg_clip_weiler_atherton: phase "prepare" (both
 * boundaries counter-clockwise, the window moved by window_shift off
 * degenerate contacts), "crossings" (each crossing I0, I1, ... along the
 * subject: subject_edge, window_edge, t, u, point, entering or exiting),
 * "lists" (each boundary's nodes with the crossings inserted: S3, W1, I2(in)
 * ...), "traversal" (each leg of a loop: from a crossing along the subject
 * or the window to the next, the points emitted), "loops" (each loop
 * closed), and "result" (the library's rings: polygon, outer or hole, area,
 * ring).  With no crossing, phase "containment" says why the result is
 * what it is.  Errors as cg_clip_weiler_atherton. */
cg_status cg_weiler_atherton_steps(const cg_vec2 *subject, size_t n, const cg_vec2 *window,
                                   size_t m, cg_step_fn step, void *user);

/* Sutherland-Hodgman of a 3D polygon against planes, as
 * cg_clip_polygon_planes (11.3): for each plane k, phase "plane k" (with
 * plane_names[k] when given, as "near"), one step per polygon edge s -> e
 * with the signed distances d_s, d_e (N.p + offset; >= 0 is kept), the case
 * and the points it outputs (3 reals each), then a step with the plane's
 * input and output lists.  The last output list is the library's result,
 * bit for bit.  Errors as cg_clip_polygon_planes. */
cg_status cg_clip_planes_steps(const cg_vec3 *polygon, size_t n, const cg_plane *planes,
                               size_t plane_count, const char *const *plane_names, cg_step_fn step,
                               void *user);

#ifdef __cplusplus
}
#endif
#endif
