/* cg/curve.h - parametric cubic curves and Bézier curves (section 2.3).
 *
 * A cubic segment is Q(t) = T M G for 0 <= t <= 1 with T = [t^3 t^2 t 1], a
 * 4x4 basis matrix M and a geometry vector G of four 2D or 3D entries:
 *  - Hermite:     G = [P1 P4 R1 R4]  (endpoints, then tangents at them)
 *  - Bézier:      G = [P1 P2 P3 P4]  (four control points)
 *  - B-spline:    G = [P0 P1 P2 P3]  (uniform non-rational; approximates)
 *  - Catmull-Rom: G = [P0 P1 P2 P3]  (interpolates P1 and P2)
 * Converting a segment from one basis to another keeps the same curve:
 * G_to = M_to^-1 M_from G_from.
 */
#ifndef CG_CURVE_H
#define CG_CURVE_H

#include "cg/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cg_curve_basis {
    CG_BASIS_HERMITE = 0,
    CG_BASIS_BEZIER = 1,
    CG_BASIS_BSPLINE = 2,
    CG_BASIS_CATMULL_ROM = 3
} cg_curve_basis;

/* The basis matrix M of a basis (row-major, rows for t^3, t^2, t, 1). */
cg_mat4 cg_curve_basis_matrix(cg_curve_basis basis);
/* Its inverse (every supported basis matrix is invertible). */
cg_mat4 cg_curve_basis_inverse(cg_curve_basis basis);
/* "hermite", "bezier", "bspline", "catmull-rom". */
const char *cg_curve_basis_name(cg_curve_basis basis);

/* A cubic segment in 2D or 3D. */
typedef struct cg_cubic2 {
    cg_curve_basis basis;
    cg_vec2 g[4];
} cg_cubic2;
typedef struct cg_cubic3 {
    cg_curve_basis basis;
    cg_vec3 g[4];
} cg_cubic3;

/* The coefficient rows C = M G: c[0] t^3 + c[1] t^2 + c[2] t + c[3]. */
void cg_cubic2_coefficients(const cg_cubic2 *curve, cg_vec2 c[4]);
void cg_cubic3_coefficients(const cg_cubic3 *curve, cg_vec3 c[4]);
/* Q(t) and the parametric tangent Q'(t) = [3t^2 2t 1 0] M G; any t. */
cg_vec2 cg_cubic2_point(const cg_cubic2 *curve, double t);
cg_vec2 cg_cubic2_tangent(const cg_cubic2 *curve, double t);
cg_vec3 cg_cubic3_point(const cg_cubic3 *curve, double t);
cg_vec3 cg_cubic3_tangent(const cg_cubic3 *curve, double t);
/* The same segment in another basis.  CG_EINVAL for an unknown basis. */
cg_status cg_cubic2_convert(const cg_cubic2 *curve, cg_curve_basis to, cg_cubic2 *out);
cg_status cg_cubic3_convert(const cg_cubic3 *curve, cg_curve_basis to, cg_cubic3 *out);

/* ---- Bézier curves of any degree --------------------------------------- */

/* Largest number of control points accepted (degree 1023). */
#define CG_BEZIER_MAX_POINTS 1024

/* The Bernstein polynomial B_{i,n}(t) = C(n,i) t^i (1-t)^(n-i); 0 outside
 * 0 <= i <= n. */
double cg_bernstein(int n, int i, double t);

/* Point and tangent at t of the Bézier curve with count = degree + 1 control
 * points, by de Casteljau's algorithm.  CG_EINVAL for count < 1 (tangent:
 * count < 2) or count > CG_BEZIER_MAX_POINTS, non-finite input. */
cg_status cg_bezier_point(const cg_vec2 *control, int count, double t, cg_vec2 *out);
cg_status cg_bezier_tangent(const cg_vec2 *control, int count, double t, cg_vec2 *out);
cg_status cg_bezier_point3(const cg_vec3 *control, int count, double t, cg_vec3 *out);
/* Subdivision at t (de Casteljau): left and right each receive count control
 * points, left covering [0, t] and right [t, 1] of the original; either may
 * be NULL, neither may overlap control. */
cg_status cg_bezier_split(const cg_vec2 *control, int count, double t, cg_vec2 *left,
                          cg_vec2 *right);

/* ---- flattening --------------------------------------------------------- */

/* Receives the points of a flattened curve one by one; a status other than
 * CG_OK stops the flattening, which returns it. */
typedef cg_status (*cg_point_sink)(void *user, cg_vec2 point);

/* Flattens the Bézier curve with count = degree + 1 control points (2 to
 * CG_BEZIER_MAX_POINTS) to a polyline by adaptive subdivision, emitting the
 * polyline's points after the first control point; the last point emitted is
 * exactly the last control point.  Every point of the polyline is within
 * tolerance of the curve and every point of the curve within tolerance of the
 * polyline.  CG_EINVAL for tolerance <= 0 or NaN, non-finite points, count
 * out of range; CG_ERANGE when the tolerance is too small for the curve's
 * size (more than 2^24 segments, or below the floating-point resolution of
 * its coordinates).  Nothing is emitted on error. */
cg_status cg_bezier_flatten(const cg_vec2 *control, int count, double tolerance, cg_point_sink sink,
                            void *user);
/* The same for a cubic segment in any basis (converted to Bézier form). */
cg_status cg_cubic2_flatten(const cg_cubic2 *curve, double tolerance, cg_point_sink sink,
                            void *user);

/* ---- piecewise curves: continuity at a joint --------------------------- */

typedef enum cg_continuity {
    CG_CONTINUITY_NONE = 0, /* the segments do not meet */
    CG_CONTINUITY_G0 = 1,   /* Q1(1) = Q2(0) */
    CG_CONTINUITY_G1 = 2,   /* and the tangents there have the same direction */
    CG_CONTINUITY_C1 = 3    /* and the tangent vectors are equal */
} cg_continuity;

/* "none", "G0", "G1", "C1". */
const char *cg_continuity_name(cg_continuity continuity);

/* The continuity where segment a (at t = 1) meets segment b (at t = 0).
 * Points and tangent vectors are compared within tolerance (absolute, in
 * the curves' units; directions within tolerance of each other as unit
 * vectors).  A zero tangent on either side has no direction: then G1 holds
 * only if both are zero (and that is also C1). */
cg_continuity cg_cubic2_continuity(const cg_cubic2 *a, const cg_cubic2 *b, double tolerance);
cg_continuity cg_cubic3_continuity(const cg_cubic3 *a, const cg_cubic3 *b, double tolerance);
/* The same from the end point and tangent of a and the start of b. */
cg_continuity cg_joint_continuity(cg_vec2 end_a, cg_vec2 tangent_a, cg_vec2 start_b,
                                  cg_vec2 tangent_b, double tolerance);

/* Changes b (keeping its basis) so that it starts where a ends with a's end
 * tangent vector (C1), or with a's end tangent direction and b's own tangent
 * length (G1; when b's start tangent is zero, a's length is used).  The
 * rest of b's Hermite form (its end point and end tangent) is kept.
 * CG_EINVAL when a's end tangent is zero (G1 has no direction to follow). */
cg_status cg_cubic2_join_c1(const cg_cubic2 *a, cg_cubic2 *b);
cg_status cg_cubic2_join_g1(const cg_cubic2 *a, cg_cubic2 *b);

#ifdef __cplusplus
}
#endif
#endif
