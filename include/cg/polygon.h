/* cg/polygon.h - polygon geometry beyond the boolean operations, on the same
 * exact integer grid (cg/clip.h): offsetting (inflating and deflating
 * polygons, widening polylines), Minkowski sums, clipping against an
 * axis-aligned rectangle, clipping open paths by polygons, triangulation
 * (refined to a minimum angle too) and simplification.
 *
 * Every function has an integer form (suffix 64, coordinates within
 * +-CG_CLIP_MAX_COORD) and a double form that scales to the grid as
 * cg_clip_boolean does (scale <= 0: the largest power of two that maps the
 * largest |coordinate| of the input and of the result below 2^36).  Results
 * are emptied first and their arrays reused; a polygon result has the
 * boolean engine's guarantee (outer rings counter-clockwise, holes
 * clockwise, simple rings meeting at most at vertices: OGC-valid). */
#ifndef CG_POLYGON_H
#define CG_POLYGON_H

#include "cg/clip.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- offsetting ------------------------------------------------------------ */

/* How the offset turns a corner on its outer side (where the two offset
 * edges leave a gap):
 *
 *        miter          square          bevel           round
 *          *          +-------+
 *         / \        /         \        +---+           .---.
 *     ---+   +---  -+           +-   -+     +-     -+'     '+-
 *        |   |      |           |     |     |       |       |
 *
 * miter extends both offset edges until they meet (cut flat, perpendicular
 * to the corner's bisector, at miter_limit * |delta| from the vertex when
 * they would meet farther); square cuts flat at |delta| from the vertex;
 * bevel joins the two offset edges' ends; round follows the circle of
 * radius |delta| within arc_tolerance. */
typedef enum cg_offset_join {
    CG_OFFSET_JOIN_MITER,
    CG_OFFSET_JOIN_ROUND,
    CG_OFFSET_JOIN_SQUARE,
    CG_OFFSET_JOIN_BEVEL
} cg_offset_join;

/* What the paths are: rings of polygons (filled by `fill`), or open
 * polylines widened by |delta| on both sides with their ends cut flat at
 * the end point (butt), extended by |delta| (square), rounded (round), or
 * joined into a loop whose band is the result (joined). */
typedef enum cg_offset_end {
    CG_OFFSET_END_POLYGON,
    CG_OFFSET_END_JOINED,
    CG_OFFSET_END_BUTT,
    CG_OFFSET_END_SQUARE,
    CG_OFFSET_END_ROUND
} cg_offset_end;

typedef struct cg_offset_options {
    cg_offset_join join;
    cg_offset_end end;
    double miter_limit;   /* >= 1; 0 picks 2 */
    double arc_tolerance; /* largest gap between an arc and its chords, in the
                             input's units; 0 picks |delta| / 500 (and at least
                             a quarter of a grid unit) */
    cg_clip_fill fill;    /* fill rule of closed input rings */
} cg_offset_options;

/* The default options: miter joins (limit 2), polygons, even-odd fill. */
cg_offset_options cg_offset_options_default(void);

/* Offsets the paths by delta: for polygons, delta > 0 adds every point
 * within delta of the polygons (inflates) and delta < 0 removes every point
 * within -delta of their boundary (deflates), with corners shaped by the
 * join; open paths are widened by |delta|.  The region is computed as the
 * input (made simple by a union first) united with, or less, the band
 * swept along its boundary, through the boolean engine: holes are kept and
 * parts that vanish are gone.  CG_EINVAL for a NaN or infinite delta or
 * option, an unknown join or end; CG_ERANGE when a coordinate of the input
 * or of the result leaves the grid; CG_ENOMEM. */
cg_status cg_offset64(const cg_polygon_set64 *paths, double delta, const cg_offset_options *options,
                      cg_polygon_set64 *result);
cg_status cg_offset64_ws(cg_clip_workspace *ws, const cg_polygon_set64 *paths, double delta,
                         const cg_offset_options *options, cg_polygon_set64 *result);
cg_status cg_offset(const cg_polygon_set *paths, double delta, const cg_offset_options *options,
                    double scale, cg_polygon_set *result);
cg_status cg_offset_ws(cg_clip_workspace *ws, const cg_polygon_set *paths, double delta,
                       const cg_offset_options *options, double scale, cg_polygon_set *result);

/* Variable offsets: deltas[i] is the distance at paths->points[i] (one per
 * point; all >= 0 or all <= 0), interpolated linearly along each edge.  The
 * band is what a disk sweeps whose centre runs along every edge of the
 * input paths (as given, not made simple first) while its radius goes from
 * |delta| at one end to |delta| at the other: the union over the edges of
 * the convex hull of their two end disks, its arcs drawn with chords
 * inside the circles within options->arc_tolerance.  Polygons
 * (options->end CG_OFFSET_END_POLYGON, filled by options->fill) are united
 * with the band (deltas >= 0) or lose it (deltas <= 0); for
 * CG_OFFSET_END_JOINED (closed loops) and CG_OFFSET_END_ROUND (open
 * polylines) the band is the result.  Joins are round (the disks at the
 * vertices); options->join and miter_limit are not used.  CG_EINVAL for a
 * NaN or infinite delta, deltas of both signs, another end type or a bad
 * option; CG_ERANGE when the result may leave the grid; CG_ENOMEM. */
cg_status cg_offset_variable64(const cg_polygon_set64 *paths, const double *deltas,
                               const cg_offset_options *options, cg_polygon_set64 *result);
cg_status cg_offset_variable64_ws(cg_clip_workspace *ws, const cg_polygon_set64 *paths,
                                  const double *deltas, const cg_offset_options *options,
                                  cg_polygon_set64 *result);
cg_status cg_offset_variable(const cg_polygon_set *paths, const double *deltas,
                             const cg_offset_options *options, double scale,
                             cg_polygon_set *result);

/* ---- Minkowski sums ---------------------------------------------------------- */

typedef enum cg_minkowski_op {
    CG_MINKOWSKI_SUM,       /* every pattern point plus every path point */
    CG_MINKOWSKI_DIFFERENCE /* every path point less every pattern point */
} cg_minkowski_op;

/* The Minkowski sum (or difference) of the region of pattern's rings
 * (under fill, made simple first) with path: its rings as open polylines
 * (path_open: the pattern swept along each), or as the region they cover
 * under fill (the region grown by the pattern).  Built as the union of the
 * pattern translated to every vertex of the path, the parallelogram each
 * pattern edge sweeps along each path edge, and (for a region) the region
 * moved to a point of each pattern polygon; a boolean result.  CG_EINVAL
 * for an unknown operation or fill; CG_ERANGE when a sum of coordinates
 * may leave the grid; CG_ENOMEM. */
cg_status cg_minkowski64(cg_minkowski_op op, const cg_polygon_set64 *pattern,
                         const cg_polygon_set64 *path, int path_open, cg_clip_fill fill,
                         cg_polygon_set64 *result);
cg_status cg_minkowski64_ws(cg_clip_workspace *ws, cg_minkowski_op op,
                            const cg_polygon_set64 *pattern, const cg_polygon_set64 *path,
                            int path_open, cg_clip_fill fill, cg_polygon_set64 *result);
cg_status cg_minkowski(cg_minkowski_op op, const cg_polygon_set *pattern,
                       const cg_polygon_set *path, int path_open, cg_clip_fill fill, double scale,
                       cg_polygon_set *result);
cg_status cg_minkowski_ws(cg_clip_workspace *ws, cg_minkowski_op op, const cg_polygon_set *pattern,
                          const cg_polygon_set *path, int path_open, cg_clip_fill fill,
                          double scale, cg_polygon_set *result);

/* ---- clipping against an axis-aligned rectangle ------------------------------ */

/* A rectangle on the integer grid (the boundary belongs to it). */
typedef struct cg_rect64 {
    int64_t xmin, ymin, xmax, ymax;
} cg_rect64;

/* The part inside the rectangle of the region the rings cover under the
 * fill rule, as polygons with holes (valid as a boolean result is).  Each
 * ring is first clipped against the rectangle's four sides in turn
 * (Sutherland-Hodgman, which keeps every winding number inside the
 * rectangle; a ring wholly inside is kept and one wholly outside dropped
 * at the cost of its bounds), and only what is left goes through the
 * boolean engine, which makes it simple: on a large input and a small
 * rectangle, the map-tile case, most of the work is skipped.  Intersections
 * with the sides are rounded to the grid.  CG_EINVAL for a rectangle with
 * xmin > xmax or ymin > ymax; CG_ERANGE for a coordinate off the grid. */
cg_status cg_rect_clip64(const cg_polygon_set64 *paths, cg_clip_fill fill, cg_rect64 rect,
                         cg_polygon_set64 *result);
cg_status cg_rect_clip64_ws(cg_clip_workspace *ws, const cg_polygon_set64 *paths, cg_clip_fill fill,
                            cg_rect64 rect, cg_polygon_set64 *result);
cg_status cg_rect_clip(const cg_polygon_set *paths, cg_clip_fill fill, cg_rect rect, double scale,
                       cg_polygon_set *result);
cg_status cg_rect_clip_ws(cg_clip_workspace *ws, const cg_polygon_set *paths, cg_clip_fill fill,
                          cg_rect rect, double scale, cg_polygon_set *result);

/* Every ring of paths taken as an open polyline, cut to the rectangle: each
 * piece inside it (boundary included) becomes a path of result (emptied
 * first; a piece that only touches the rectangle at a point is a path of
 * one point), in the order of the input.  Same errors. */
cg_status cg_rect_clip_lines64(const cg_polygon_set64 *paths, cg_rect64 rect,
                               cg_polygon_set64 *result);
cg_status cg_rect_clip_lines(const cg_polygon_set *paths, cg_rect rect, double scale,
                             cg_polygon_set *result);

/* ---- clipping open paths against polygons ----------------------------------- */

/* Every ring of paths taken as an open polyline (self-crossing allowed),
 * cut by the region the rings of clip cover under clip_fill:
 * CG_CLIP_INTERSECTION keeps the pieces inside the region, its boundary
 * included (a stretch running along an edge is inside), CG_CLIP_DIFFERENCE
 * the pieces outside it, boundary excluded (a path touching the boundary
 * from outside is cut there).  Each piece is a path of result (emptied
 * first; it may not be paths or clip), in order along each path and the
 * paths in the input's order; pieces of no length (a path touching the
 * region at a point) are left out.  Where a piece starts or ends is decided
 * exactly; a crossing inside an edge is rounded to the nearest grid point,
 * a vertex kept exactly, and the vertices of the path between are its own.
 * CG_EINVAL for another operation (a union or symmetric difference of a
 * line and a region is not a set of lines) or fill rule; CG_ERANGE for a
 * coordinate off the grid; CG_ENOMEM. */
cg_status cg_clip_lines64(cg_clip_op op, const cg_polygon_set64 *paths,
                          const cg_polygon_set64 *clip, cg_clip_fill clip_fill,
                          cg_polygon_set64 *result);
cg_status cg_clip_lines64_ws(cg_clip_workspace *ws, cg_clip_op op, const cg_polygon_set64 *paths,
                             const cg_polygon_set64 *clip, cg_clip_fill clip_fill,
                             cg_polygon_set64 *result);
cg_status cg_clip_lines(cg_clip_op op, const cg_polygon_set *paths, const cg_polygon_set *clip,
                        cg_clip_fill clip_fill, double scale, cg_polygon_set *result);
cg_status cg_clip_lines_ws(cg_clip_workspace *ws, cg_clip_op op, const cg_polygon_set *paths,
                           const cg_polygon_set *clip, cg_clip_fill clip_fill, double scale,
                           cg_polygon_set *result);

/* ---- triangulation ---------------------------------------------------------- */

/* The constrained Delaunay triangulation of the region the rings cover
 * under the fill rule, made simple by a union first (so self-crossing
 * rings gain their crossings as vertices): triangles whose vertices are
 * exactly the vertices of those simple rings (no point added), which tile
 * the region exactly (their areas sum to its area, none overlap), every
 * edge of the rings an edge of the triangles, and every other edge locally
 * Delaunay (no vertex of the triangle beyond it inside the circle through
 * the three of one side; decided exactly).  Holes, touching rings and
 * collinear vertices are allowed.  The result holds each triangle as a
 * polygon of one counter-clockwise ring of three points.  CG_ERANGE for a
 * coordinate off the grid; CG_ENOMEM; CG_EUNSUPPORTED beyond 2^30 points. */
cg_status cg_triangulate64(const cg_polygon_set64 *paths, cg_clip_fill fill,
                           cg_polygon_set64 *triangles);
cg_status cg_triangulate64_ws(cg_clip_workspace *ws, const cg_polygon_set64 *paths,
                              cg_clip_fill fill, cg_polygon_set64 *triangles);
cg_status cg_triangulate(const cg_polygon_set *paths, cg_clip_fill fill, double scale,
                         cg_polygon_set *triangles);
cg_status cg_triangulate_ws(cg_clip_workspace *ws, const cg_polygon_set *paths, cg_clip_fill fill,
                            double scale, cg_polygon_set *triangles);

/* The largest minimum angle (degrees) a refinement accepts. */
#define CG_TRIANGULATE_MAX_MIN_ANGLE 30.0

/* The constrained Delaunay triangulation refined with Steiner points until
 * no triangle has an angle below min_angle degrees (Ruppert's algorithm:
 * ring edges encroached upon are split, bad triangles get their
 * circumcentre), except the triangles whose smallest angle lies at a vertex
 * where the rings' edges meet at less than 60 degrees (the input's own
 * angle bounds those).  Points added on a ring edge lie exactly on it, at
 * a grid point (an edge with no grid point inside is not split, and the
 * triangles it keeps bad stay); points inside are rounded to the grid.  The
 * triangles tile the region exactly and the triangulation of all its
 * vertices is constrained Delaunay.  min_angle 0 is cg_triangulate64.
 * CG_EINVAL for min_angle NaN, negative or above
 * CG_TRIANGULATE_MAX_MIN_ANGLE (beyond it the refinement need not end);
 * otherwise as cg_triangulate64.  A cap on the points added (64 per input
 * vertex, plus 65,536) ends it in any case. */
cg_status cg_triangulate_refined64(const cg_polygon_set64 *paths, cg_clip_fill fill,
                                   double min_angle, cg_polygon_set64 *triangles);
cg_status cg_triangulate_refined64_ws(cg_clip_workspace *ws, const cg_polygon_set64 *paths,
                                      cg_clip_fill fill, double min_angle,
                                      cg_polygon_set64 *triangles);
cg_status cg_triangulate_refined(const cg_polygon_set *paths, cg_clip_fill fill, double min_angle,
                                 double scale, cg_polygon_set *triangles);
cg_status cg_triangulate_refined_ws(cg_clip_workspace *ws, const cg_polygon_set *paths,
                                    cg_clip_fill fill, double min_angle, double scale,
                                    cg_polygon_set *triangles);

/* ---- simplification --------------------------------------------------------- */

typedef enum cg_simplify_algorithm {
    CG_SIMPLIFY_RDP,        /* Ramer-Douglas-Peucker: tolerance is a distance */
    CG_SIMPLIFY_VISVALINGAM /* Visvalingam-Whyatt: tolerance is a triangle's area */
} cg_simplify_algorithm;

/* Simplifies the region the rings cover (made simple by a union first),
 * removing vertices while the shape stays within the tolerance: RDP keeps
 * the vertex farthest from each shortcut while it is farther than the
 * tolerance; Visvalingam-Whyatt removes, smallest first, the vertices
 * whose triangle with their two neighbours has an area below it.  Topology
 * is kept: a vertex goes only when no other vertex (of any ring) lies in
 * the region between the removed stretch and its shortcut, so no edge
 * crosses or touches another that did not before, and no ring falls below
 * three vertices.  The result is a boolean result (valid).  open: the rings
 * of paths are open polylines instead (their ends kept; result paths in the
 * input's order, not united).  CG_EINVAL for a negative or NaN tolerance. */
cg_status cg_simplify64(const cg_polygon_set64 *paths, int open, cg_clip_fill fill,
                        cg_simplify_algorithm algorithm, double tolerance,
                        cg_polygon_set64 *result);
cg_status cg_simplify(const cg_polygon_set *paths, int open, cg_clip_fill fill,
                      cg_simplify_algorithm algorithm, double tolerance, double scale,
                      cg_polygon_set *result);

#ifdef __cplusplus
}
#endif
#endif
