/* cg/clip.h - clipping (chapter 11 of the notes): lines against a window or a
 * box (Cohen-Sutherland with the notes' TBRL region codes, Liang-Barsky),
 * polygons against a convex window (Sutherland-Hodgman, 2D and against 3D
 * planes), against a concave window (Weiler-Atherton), boolean operations on
 * arbitrary polygon sets (a scanbeam sweep in the manner of Vatti), clipping a
 * triangle mesh against a box and frustum culling of bounding boxes.
 *
 * 2D coordinates here are y-up (mathematical): a counter-clockwise ring has
 * positive signed area.  See docs/clip.md for tie rules and limits. */
#ifndef CG_CLIP_H
#define CG_CLIP_H

#include "cg/core.h"
#include "cg/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- lines (11.1) ------------------------------------------------------ */

/* The notes' region codes, TBRL: bit 0 left, 1 right, 2 bottom, 3 top; in 3D
 * also bit 4 near (z < zmin) and bit 5 far (z > zmax). */
enum {
    CG_RCODE_INSIDE = 0,
    CG_RCODE_LEFT = 1,
    CG_RCODE_RIGHT = 2,
    CG_RCODE_BOTTOM = 4,
    CG_RCODE_TOP = 8,
    CG_RCODE_NEAR = 16,
    CG_RCODE_FAR = 32
};

typedef struct cg_rect {
    double xmin, ymin, xmax, ymax;
} cg_rect;
typedef struct cg_box3 {
    cg_vec3 lo, hi;
} cg_box3;

/* rCode of p against the window (points on the boundary are inside). */
unsigned cg_clip_rcode(cg_rect window, cg_vec2 p);
unsigned cg_clip_rcode3(cg_box3 box, cg_vec3 p);

/* Called by Cohen-Sutherland at each step when not NULL: the current
 * endpoints, their rCodes and what the step decided ("accept", "reject",
 * "clip top", ...). */
typedef void (*cg_clip_trace_fn)(void *user, cg_vec2 p0, unsigned code0, cg_vec2 p1, unsigned code1,
                                 const char *step);

/* Cohen-Sutherland clipping of the segment *p0-*p1 against window.  On return
 * *accepted is 1 and *p0, *p1 hold the visible part, or 0 (points untouched)
 * when nothing is visible.  The window must have xmin <= xmax, ymin <= ymax and
 * finite values; the points finite: CG_EINVAL otherwise.  A segment that only
 * touches the window's boundary is accepted (a point segment may result). */
cg_status cg_clip_line_cohen_sutherland(cg_rect window, cg_vec2 *p0, cg_vec2 *p1, int *accepted,
                                        cg_clip_trace_fn trace, void *user);
/* Liang-Barsky (parametric) clipping with the same contract. */
cg_status cg_clip_line_liang_barsky(cg_rect window, cg_vec2 *p0, cg_vec2 *p1, int *accepted);
/* The 3D forms against an axis-aligned box (6-bit codes). */
cg_status cg_clip_line_cohen_sutherland3(cg_box3 box, cg_vec3 *p0, cg_vec3 *p1, int *accepted);
cg_status cg_clip_line_liang_barsky3(cg_box3 box, cg_vec3 *p0, cg_vec3 *p1, int *accepted);

/* ---- Sutherland-Hodgman (11.2.1) --------------------------------------- */

/* Clips the polygon subject[0..n) against the convex window[0..m) (given
 * clockwise or counter-clockwise; at least 3 vertices and non-zero area,
 * otherwise CG_EINVAL; a window that is not convex gives CG_EINVAL too).
 * *out receives a new array (free it with free()) of *out_count points;
 * NULL and 0 when nothing is visible.  A point on the window's boundary is
 * inside.  As the notes say, a concave subject may give coincident
 * (degenerate) edges. */
cg_status cg_clip_sutherland_hodgman(const cg_vec2 *subject, size_t n, const cg_vec2 *window,
                                     size_t m, cg_vec2 **out, size_t *out_count);

/* A plane keeps the points p with dot(normal, p) + offset >= 0. */
typedef struct cg_plane {
    cg_vec3 normal;
    double offset;
} cg_plane;

/* Sutherland-Hodgman of a 3D polygon against plane_count planes; *out as
 * above (free()). */
cg_status cg_clip_polygon_planes(const cg_vec3 *polygon, size_t n, const cg_plane *planes,
                                 size_t plane_count, cg_vec3 **out, size_t *out_count);

/* ---- polygon sets and boolean operations (11.2.2) ----------------------- */

/* A set of rings.  Ring r is points[ring_start[r] .. ring_start[r + 1]).  In a
 * result, polygon p is the rings ring_start-indices polygon_start[p] ..
 * polygon_start[p + 1] - 1: the first is its outer contour (counter-clockwise),
 * the others its holes (clockwise).  As input every ring is a closed path
 * (the last point joins the first) and polygon_start is ignored. */
typedef struct cg_polygon_set {
    cg_vec2 *points;
    size_t point_count;
    size_t *ring_start; /* ring_count + 1 entries (NULL when empty) */
    size_t ring_count;
    size_t *polygon_start; /* polygon_count + 1 entries (NULL when empty) */
    size_t polygon_count;
    size_t point_capacity, ring_capacity, polygon_capacity;
} cg_polygon_set;

/* The same on the integer grid the boolean operations work on. */
typedef struct cg_point64 {
    int64_t x, y;
} cg_point64;
typedef struct cg_polygon_set64 {
    cg_point64 *points;
    size_t point_count;
    size_t *ring_start;
    size_t ring_count;
    size_t *polygon_start;
    size_t polygon_count;
    size_t point_capacity, ring_capacity, polygon_capacity;
} cg_polygon_set64;

/* An empty set is all zeros: `cg_polygon_set s = {0};`.  Frees the arrays
 * and leaves the set empty. */
void cg_polygon_set_clear(cg_polygon_set *set);
void cg_polygon_set64_clear(cg_polygon_set64 *set);
/* Appends a ring (as a path of the input, or as the next ring of the last
 * polygon when new_polygon is 0; new_polygon 1 starts a polygon). */
cg_status cg_polygon_set_add_ring(cg_polygon_set *set, const cg_vec2 *points, size_t n,
                                  int new_polygon);
cg_status cg_polygon_set64_add_ring(cg_polygon_set64 *set, const cg_point64 *points, size_t n,
                                    int new_polygon);
/* Signed area of ring r (positive counter-clockwise) and of the whole set
 * (the sum over its rings, so holes subtract). */
double cg_polygon_set_ring_area(const cg_polygon_set *set, size_t r);
double cg_polygon_set_area(const cg_polygon_set *set);
double cg_polygon_set64_area(const cg_polygon_set64 *set);

typedef enum cg_clip_op {
    CG_CLIP_INTERSECTION,
    CG_CLIP_UNION,
    CG_CLIP_DIFFERENCE, /* subject minus clip */
    CG_CLIP_XOR
} cg_clip_op;

/* Which points a set of paths covers, by the winding number w of the point
 * (the sum over the paths, each counting +1 per counter-clockwise turn). */
typedef enum cg_clip_fill {
    CG_CLIP_EVEN_ODD, /* w odd */
    CG_CLIP_NON_ZERO, /* w != 0 */
    CG_CLIP_POSITIVE, /* w > 0 */
    CG_CLIP_NEGATIVE  /* w < 0 */
} cg_clip_fill;

/* Integer coordinates must lie in [-CG_CLIP_MAX_COORD, CG_CLIP_MAX_COORD]. */
#define CG_CLIP_MAX_COORD ((int64_t)1 << 40)

/* Boolean operation on the integer grid.  Result (emptied first; its arrays
 * are reused, so a result passed call after call is not allocated again;
 * it may be subject or clip, which it then replaces) is a list of polygons
 * with holes: outer contours counter-clockwise, holes clockwise,
 * no two edges crossing, rings meeting at most at vertices, no collinear
 * consecutive vertices.  Intersection points are rounded to the grid (each
 * output vertex within one unit of the exact arrangement).  CG_ERANGE for
 * a coordinate out of range; CG_ENOMEM. */
cg_status cg_clip_boolean64(cg_clip_op op, const cg_polygon_set64 *subject,
                            cg_clip_fill subject_fill, const cg_polygon_set64 *clip,
                            cg_clip_fill clip_fill, cg_polygon_set64 *result);

/* The same on doubles (result cleared first; it may be subject or clip):
 * coordinates are multiplied by scale and rounded to integers, and the
 * result divided by scale.  scale <= 0 picks the largest
 * power of two that maps the largest |coordinate| of both inputs below 2^36
 * (so about 11 significant digits are kept, at any magnitude).  CG_EINVAL for a NaN or
 * infinite coordinate or scale, CG_ERANGE when a scaled coordinate exceeds
 * CG_CLIP_MAX_COORD. */
cg_status cg_clip_boolean(cg_clip_op op, const cg_polygon_set *subject, cg_clip_fill subject_fill,
                          const cg_polygon_set *clip, cg_clip_fill clip_fill, double scale,
                          cg_polygon_set *result);

/* Memory kept from one boolean operation to the next: a program that runs
 * many operations passes one workspace to cg_clip_boolean64_ws, which keeps
 * the engine's large blocks in it (the largest seen so far) instead of
 * taking them from the system and giving them back on every call.  One
 * thread at a time per workspace.  NULL when out of memory. */
typedef struct cg_clip_workspace cg_clip_workspace;
cg_clip_workspace *cg_clip_workspace_create(void);
void cg_clip_workspace_free(cg_clip_workspace *ws);
/* cg_clip_boolean64 and cg_clip_boolean with a workspace (or NULL: none). */
cg_status cg_clip_boolean64_ws(cg_clip_workspace *ws, cg_clip_op op,
                               const cg_polygon_set64 *subject, cg_clip_fill subject_fill,
                               const cg_polygon_set64 *clip, cg_clip_fill clip_fill,
                               cg_polygon_set64 *result);
cg_status cg_clip_boolean_ws(cg_clip_workspace *ws, cg_clip_op op, const cg_polygon_set *subject,
                             cg_clip_fill subject_fill, const cg_polygon_set *clip,
                             cg_clip_fill clip_fill, double scale, cg_polygon_set *result);

/* ---- Weiler-Atherton (11.2.2) ------------------------------------------ */

/* Clips the simple polygon subject[0..n) by the simple (possibly concave)
 * polygon window[0..m), either orientation, by walking the two boundaries:
 * along the subject from an entering intersection to the next (exiting)
 * one, then along the window to the next entering one, until the loop
 * closes.  Every loop is a separate polygon of result (cleared first):
 * counter-clockwise outer contours, and clockwise holes where the two
 * windows interlock around a hole.  Degenerate contacts (a vertex on the
 * other's edge, overlapping edges) are avoided by moving the window by 1e-9
 * of the drawing's extent, so results are exact to about that.
 * CG_EINVAL for fewer than 3 points or non-finite input; the polygons must
 * be simple (self-intersecting input gives a meaningless result, use
 * cg_clip_boolean for that). */
cg_status cg_clip_weiler_atherton(const cg_vec2 *subject, size_t n, const cg_vec2 *window, size_t m,
                                  cg_polygon_set *result);

/* ---- 3D (11.3) ----------------------------------------------------------- */

/* Clips every triangle of the mesh (faces are fan-triangulated) against the
 * box; triangles that cross a face of the box are cut there, the new
 * vertices get interpolated normals (renormalized), texture coordinates and
 * colours.  A vertex created on an edge shared by two triangles is computed
 * from the edge alone, so the cut stays closed (watertight).  *out is a new
 * triangle mesh (possibly with no faces). */
cg_status cg_clip_mesh_box(const cg_mesh *mesh, cg_box3 box, cg_mesh **out);

typedef enum cg_cull { CG_CULL_OUTSIDE = 0, CG_CULL_INTERSECTS = 1, CG_CULL_INSIDE = 2 } cg_cull;

/* The six planes (left, right, bottom, top, near, far; normals inward) of the
 * view volume of a projection * view matrix, in world coordinates. */
void cg_frustum_planes(cg_mat4 projection_view, cg_plane planes[6]);
/* Where the box lies with respect to the planes: conservative (a box that is
 * reported as intersecting may still be outside near a corner of the frustum,
 * never the other way round). */
cg_cull cg_frustum_cull_box(const cg_plane planes[6], cg_box3 box);

#ifdef __cplusplus
}
#endif
#endif
