/* cg/core.h - status codes, error details, vectors and matrices.
 *
 * Conventions used by every cg module:
 *  - Functions that can fail return cg_status (CG_OK is 0) and give their
 *    results through out-parameters.  Those that read files or parse text also
 *    take an optional cg_error* (may be NULL) that receives a one-line message
 *    naming the file, the line or byte offset and what was expected.
 *  - Vectors are column vectors.  A matrix M maps a point p to M p, so in the
 *    product A B the transformation B is applied first and A second.
 *  - Matrices are stored row-major: m[row][column].
 */
#ifndef CG_CORE_H
#define CG_CORE_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CG_VERSION_MAJOR 0
#define CG_VERSION_MINOR 1
#define CG_VERSION_PATCH 0
#define CG_VERSION_STRING "0.1.0"

typedef enum cg_status {
    CG_OK = 0,
    CG_EINVAL,       /* an argument is invalid: NaN, negative size, NULL ... */
    CG_ENOMEM,       /* memory could not be allocated */
    CG_EIO,          /* a file could not be opened, read or written */
    CG_EFORMAT,      /* a file or text is malformed */
    CG_ERANGE,       /* a value is outside the documented range */
    CG_ESINGULAR,    /* a matrix has no inverse */
    CG_EUNSUPPORTED, /* valid input that this build cannot handle */
    CG_EEMPTY        /* the input has nothing to work on */
} cg_status;

/* A short English sentence describing a status. Never NULL. */
const char *cg_status_str(cg_status status);

/* Details of a failure: the status and a message such as
 * "mesh.obj:12: expected a vertex index, got 'x'". */
typedef struct cg_error {
    cg_status status;
    char message[512];
} cg_error;

/* Fills err (when not NULL) and returns status, so that a function can
 * `return cg_error_set(err, CG_EFORMAT, "%s:%d: ...", ...)`. */
cg_status cg_error_set(cg_error *err, cg_status status, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Clears err to CG_OK with an empty message (err may be NULL). */
void cg_error_clear(cg_error *err);

/* ---- vectors ---------------------------------------------------------- */

typedef struct cg_vec2 {
    double x, y;
} cg_vec2;
typedef struct cg_vec3 {
    double x, y, z;
} cg_vec3;
typedef struct cg_vec4 {
    double x, y, z, w;
} cg_vec4;

static inline cg_vec2 cg_vec2_make(double x, double y)
{
    cg_vec2 v = {x, y};
    return v;
}
static inline cg_vec2 cg_vec2_add(cg_vec2 a, cg_vec2 b)
{
    return cg_vec2_make(a.x + b.x, a.y + b.y);
}
static inline cg_vec2 cg_vec2_sub(cg_vec2 a, cg_vec2 b)
{
    return cg_vec2_make(a.x - b.x, a.y - b.y);
}
static inline cg_vec2 cg_vec2_scale(cg_vec2 a, double s)
{
    return cg_vec2_make(a.x * s, a.y * s);
}
static inline double cg_vec2_dot(cg_vec2 a, cg_vec2 b)
{
    return a.x * b.x + a.y * b.y;
}
/* z component of the 3D cross product: positive when b is counter-clockwise from a
 * in a y-up frame. */
static inline double cg_vec2_cross(cg_vec2 a, cg_vec2 b)
{
    return a.x * b.y - a.y * b.x;
}
static inline double cg_vec2_length(cg_vec2 a)
{
    return hypot(a.x, a.y);
}
/* Unit vector in the direction of a, for any finite length however tiny or
 * huge; zero, NaN and infinite vectors are returned as they are. */
cg_vec2 cg_vec2_normalize(cg_vec2 a);

static inline cg_vec3 cg_vec3_make(double x, double y, double z)
{
    cg_vec3 v = {x, y, z};
    return v;
}
static inline cg_vec3 cg_vec3_add(cg_vec3 a, cg_vec3 b)
{
    return cg_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline cg_vec3 cg_vec3_sub(cg_vec3 a, cg_vec3 b)
{
    return cg_vec3_make(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline cg_vec3 cg_vec3_scale(cg_vec3 a, double s)
{
    return cg_vec3_make(a.x * s, a.y * s, a.z * s);
}
static inline cg_vec3 cg_vec3_mul(cg_vec3 a, cg_vec3 b)
{
    return cg_vec3_make(a.x * b.x, a.y * b.y, a.z * b.z);
}
static inline double cg_vec3_dot(cg_vec3 a, cg_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline cg_vec3 cg_vec3_cross(cg_vec3 a, cg_vec3 b)
{
    return cg_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double cg_vec3_length(cg_vec3 a)
{
    return sqrt(cg_vec3_dot(a, a));
}
/* Unit vector in the direction of a, for any finite length however tiny or
 * huge; zero, NaN and infinite vectors are returned as they are. */
cg_vec3 cg_vec3_normalize(cg_vec3 a);

static inline cg_vec4 cg_vec4_make(double x, double y, double z, double w)
{
    cg_vec4 v = {x, y, z, w};
    return v;
}
static inline cg_vec4 cg_vec4_add(cg_vec4 a, cg_vec4 b)
{
    return cg_vec4_make(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w);
}
static inline cg_vec4 cg_vec4_sub(cg_vec4 a, cg_vec4 b)
{
    return cg_vec4_make(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w);
}
static inline cg_vec4 cg_vec4_scale(cg_vec4 a, double s)
{
    return cg_vec4_make(a.x * s, a.y * s, a.z * s, a.w * s);
}
static inline double cg_vec4_dot(cg_vec4 a, cg_vec4 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}
static inline cg_vec4 cg_vec4_from_point(cg_vec3 p)
{
    return cg_vec4_make(p.x, p.y, p.z, 1.0);
}

/* ---- matrices --------------------------------------------------------- */

typedef struct cg_mat3 {
    double m[3][3];
} cg_mat3;
typedef struct cg_mat4 {
    double m[4][4];
} cg_mat4;

cg_mat3 cg_mat3_identity(void);
/* a b: b is applied first. */
cg_mat3 cg_mat3_mul(cg_mat3 a, cg_mat3 b);
cg_vec3 cg_mat3_mul_vec3(cg_mat3 a, cg_vec3 v);
cg_mat3 cg_mat3_transpose(cg_mat3 a);
double cg_mat3_determinant(cg_mat3 a);
/* CG_ESINGULAR (out untouched) when |det| is zero or negligible relative to
 * the size of the entries, or when an entry is not finite. */
cg_status cg_mat3_inverse(cg_mat3 a, cg_mat3 *out);
/* Applies the homogeneous 2D transform to point p: (x, y, 1) -> divide by w. */
cg_vec2 cg_mat3_transform_point(cg_mat3 a, cg_vec2 p);
/* Applies the linear part only (translation ignored): for direction vectors. */
cg_vec2 cg_mat3_transform_vector(cg_mat3 a, cg_vec2 v);

cg_mat4 cg_mat4_identity(void);
/* a b: b is applied first. */
cg_mat4 cg_mat4_mul(cg_mat4 a, cg_mat4 b);
cg_vec4 cg_mat4_mul_vec4(cg_mat4 a, cg_vec4 v);
cg_mat4 cg_mat4_transpose(cg_mat4 a);
double cg_mat4_determinant(cg_mat4 a);
/* CG_ESINGULAR (out untouched) when the matrix has no usable inverse. */
cg_status cg_mat4_inverse(cg_mat4 a, cg_mat4 *out);
/* Applies the transform to point p with w = 1 and divides by the resulting w. */
cg_vec3 cg_mat4_transform_point(cg_mat4 a, cg_vec3 p);
/* Applies the upper-left 3x3 only: for direction vectors. */
cg_vec3 cg_mat4_transform_vector(cg_mat4 a, cg_vec3 v);
/* Transforms n points (w = 1, divided by w) from in to out; in and out may be
 * the same array. */
void cg_mat4_transform_points(cg_mat4 a, const cg_vec3 *in, cg_vec3 *out, size_t n);
/* True when every entry differs by at most tolerance. */
int cg_mat4_near(cg_mat4 a, cg_mat4 b, double tolerance);
int cg_mat3_near(cg_mat3 a, cg_mat3 b, double tolerance);

/* ---- composition ------------------------------------------------------- */

/* The single matrix that applies steps[0] first, then steps[1], ... that is
 * steps[n-1] ... steps[1] steps[0].  n == 0 gives the identity. */
cg_mat3 cg_mat3_compose(const cg_mat3 *steps, size_t n);
cg_mat4 cg_mat4_compose(const cg_mat4 *steps, size_t n);

#define CG_PI 3.14159265358979323846

static inline double cg_radians(double degrees)
{
    return degrees * (CG_PI / 180.0);
}
static inline double cg_degrees(double radians)
{
    return radians * (180.0 / CG_PI);
}

#ifdef __cplusplus
}
#endif
#endif
