/* 3x3 and 4x4 matrices: products, transpose, determinant, inverse. */
#include "cg/core.h"

#include <float.h>
#include <string.h>

/* A pivot smaller than this fraction of the largest entry marks the matrix as
 * singular: its inverse would be dominated by rounding error. */
#define SINGULAR_RELATIVE_PIVOT 1e-14

/* Gauss-Jordan elimination with partial pivoting on an n x n matrix stored
 * row-major in a (destroyed) into inverse.  Shared by the 3x3 and 4x4 forms. */
static cg_status invert_square(double *a, double *inverse, int n)
{
    double largest = 0;
    for (int i = 0; i < n * n; i++) {
        if (!isfinite(a[i]))
            return CG_ESINGULAR;
        if (fabs(a[i]) > largest)
            largest = fabs(a[i]);
    }
    if (largest == 0)
        return CG_ESINGULAR;
    for (int i = 0; i < n * n; i++)
        inverse[i] = (i / n == i % n) ? 1.0 : 0.0;

    for (int column = 0; column < n; column++) {
        int pivot = column;
        for (int row = column + 1; row < n; row++)
            if (fabs(a[row * n + column]) > fabs(a[pivot * n + column]))
                pivot = row;
        if (fabs(a[pivot * n + column]) <= SINGULAR_RELATIVE_PIVOT * largest)
            return CG_ESINGULAR;
        if (pivot != column) {
            for (int k = 0; k < n; k++) {
                double t = a[column * n + k];
                a[column * n + k] = a[pivot * n + k];
                a[pivot * n + k] = t;
                t = inverse[column * n + k];
                inverse[column * n + k] = inverse[pivot * n + k];
                inverse[pivot * n + k] = t;
            }
        }
        double scale = 1.0 / a[column * n + column];
        for (int k = 0; k < n; k++) {
            a[column * n + k] *= scale;
            inverse[column * n + k] *= scale;
        }
        for (int row = 0; row < n; row++) {
            if (row == column)
                continue;
            double factor = a[row * n + column];
            if (factor == 0)
                continue;
            for (int k = 0; k < n; k++) {
                a[row * n + k] -= factor * a[column * n + k];
                inverse[row * n + k] -= factor * inverse[column * n + k];
            }
        }
    }
    for (int i = 0; i < n * n; i++)
        if (!isfinite(inverse[i]))
            return CG_ESINGULAR;
    return CG_OK;
}

cg_mat3 cg_mat3_identity(void)
{
    cg_mat3 r = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    return r;
}

cg_mat3 cg_mat3_mul(cg_mat3 a, cg_mat3 b)
{
    cg_mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
}

cg_vec3 cg_mat3_mul_vec3(cg_mat3 a, cg_vec3 v)
{
    return cg_vec3_make(a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
                        a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
                        a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z);
}

cg_mat3 cg_mat3_transpose(cg_mat3 a)
{
    cg_mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.m[i][j] = a.m[j][i];
    return r;
}

double cg_mat3_determinant(cg_mat3 a)
{
    return a.m[0][0] * (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1])
           - a.m[0][1] * (a.m[1][0] * a.m[2][2] - a.m[1][2] * a.m[2][0])
           + a.m[0][2] * (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]);
}

cg_status cg_mat3_inverse(cg_mat3 a, cg_mat3 *out)
{
    cg_mat3 inverse;
    if (!out)
        return CG_EINVAL;
    cg_status status = invert_square(&a.m[0][0], &inverse.m[0][0], 3);
    if (status == CG_OK)
        *out = inverse;
    return status;
}

cg_vec2 cg_mat3_transform_point(cg_mat3 a, cg_vec2 p)
{
    cg_vec3 h = cg_mat3_mul_vec3(a, cg_vec3_make(p.x, p.y, 1.0));
    return cg_vec2_make(h.x / h.z, h.y / h.z);
}

cg_vec2 cg_mat3_transform_vector(cg_mat3 a, cg_vec2 v)
{
    return cg_vec2_make(a.m[0][0] * v.x + a.m[0][1] * v.y, a.m[1][0] * v.x + a.m[1][1] * v.y);
}

cg_mat4 cg_mat4_identity(void)
{
    cg_mat4 r = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    return r;
}

cg_mat4 cg_mat4_mul(cg_mat4 a, cg_mat4 b)
{
    cg_mat4 r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j]
                        + a.m[i][3] * b.m[3][j];
    return r;
}

cg_vec4 cg_mat4_mul_vec4(cg_mat4 a, cg_vec4 v)
{
    cg_vec4 r;
    r.x = a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z + a.m[0][3] * v.w;
    r.y = a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z + a.m[1][3] * v.w;
    r.z = a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z + a.m[2][3] * v.w;
    r.w = a.m[3][0] * v.x + a.m[3][1] * v.y + a.m[3][2] * v.z + a.m[3][3] * v.w;
    return r;
}

cg_mat4 cg_mat4_transpose(cg_mat4 a)
{
    cg_mat4 r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            r.m[i][j] = a.m[j][i];
    return r;
}

double cg_mat4_determinant(cg_mat4 a)
{
    /* Laplace expansion along the first row with 2x2 minors of the lower rows. */
    double s0 = a.m[2][0] * a.m[3][1] - a.m[2][1] * a.m[3][0];
    double s1 = a.m[2][0] * a.m[3][2] - a.m[2][2] * a.m[3][0];
    double s2 = a.m[2][0] * a.m[3][3] - a.m[2][3] * a.m[3][0];
    double s3 = a.m[2][1] * a.m[3][2] - a.m[2][2] * a.m[3][1];
    double s4 = a.m[2][1] * a.m[3][3] - a.m[2][3] * a.m[3][1];
    double s5 = a.m[2][2] * a.m[3][3] - a.m[2][3] * a.m[3][2];
    double c0 = a.m[1][1] * s5 - a.m[1][2] * s4 + a.m[1][3] * s3;
    double c1 = a.m[1][0] * s5 - a.m[1][2] * s2 + a.m[1][3] * s1;
    double c2 = a.m[1][0] * s4 - a.m[1][1] * s2 + a.m[1][3] * s0;
    double c3 = a.m[1][0] * s3 - a.m[1][1] * s1 + a.m[1][2] * s0;
    return a.m[0][0] * c0 - a.m[0][1] * c1 + a.m[0][2] * c2 - a.m[0][3] * c3;
}

cg_status cg_mat4_inverse(cg_mat4 a, cg_mat4 *out)
{
    cg_mat4 inverse;
    if (!out)
        return CG_EINVAL;
    cg_status status = invert_square(&a.m[0][0], &inverse.m[0][0], 4);
    if (status == CG_OK)
        *out = inverse;
    return status;
}

cg_vec3 cg_mat4_transform_point(cg_mat4 a, cg_vec3 p)
{
    cg_vec4 h = cg_mat4_mul_vec4(a, cg_vec4_from_point(p));
    return cg_vec3_make(h.x / h.w, h.y / h.w, h.z / h.w);
}

cg_vec3 cg_mat4_transform_vector(cg_mat4 a, cg_vec3 v)
{
    return cg_vec3_make(a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
                        a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
                        a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z);
}

void cg_mat4_transform_points(cg_mat4 a, const cg_vec3 *in, cg_vec3 *out, size_t n)
{
    /* Copy the entries into locals so the compiler keeps them in registers and
     * can vectorise: out may alias in, so it cannot assume that otherwise. */
    const double m00 = a.m[0][0], m01 = a.m[0][1], m02 = a.m[0][2], m03 = a.m[0][3];
    const double m10 = a.m[1][0], m11 = a.m[1][1], m12 = a.m[1][2], m13 = a.m[1][3];
    const double m20 = a.m[2][0], m21 = a.m[2][1], m22 = a.m[2][2], m23 = a.m[2][3];
    const double m30 = a.m[3][0], m31 = a.m[3][1], m32 = a.m[3][2], m33 = a.m[3][3];
    int affine = m30 == 0 && m31 == 0 && m32 == 0 && m33 == 1;
    if (affine) {
        for (size_t i = 0; i < n; i++) {
            double x = in[i].x, y = in[i].y, z = in[i].z;
            out[i].x = m00 * x + m01 * y + m02 * z + m03;
            out[i].y = m10 * x + m11 * y + m12 * z + m13;
            out[i].z = m20 * x + m21 * y + m22 * z + m23;
        }
        return;
    }
    for (size_t i = 0; i < n; i++) {
        double x = in[i].x, y = in[i].y, z = in[i].z;
        double w = 1.0 / (m30 * x + m31 * y + m32 * z + m33);
        out[i].x = (m00 * x + m01 * y + m02 * z + m03) * w;
        out[i].y = (m10 * x + m11 * y + m12 * z + m13) * w;
        out[i].z = (m20 * x + m21 * y + m22 * z + m23) * w;
    }
}

static int near_entries(const double *a, const double *b, int count, double tolerance)
{
    for (int i = 0; i < count; i++)
        if (!(fabs(a[i] - b[i]) <= tolerance))
            return 0;
    return 1;
}

int cg_mat4_near(cg_mat4 a, cg_mat4 b, double tolerance)
{
    return near_entries(&a.m[0][0], &b.m[0][0], 16, tolerance);
}

int cg_mat3_near(cg_mat3 a, cg_mat3 b, double tolerance)
{
    return near_entries(&a.m[0][0], &b.m[0][0], 9, tolerance);
}

cg_mat3 cg_mat3_compose(const cg_mat3 *steps, size_t n)
{
    cg_mat3 r = cg_mat3_identity();
    for (size_t i = 0; i < n; i++)
        r = cg_mat3_mul(steps[i], r);
    return r;
}

cg_mat4 cg_mat4_compose(const cg_mat4 *steps, size_t n)
{
    cg_mat4 r = cg_mat4_identity();
    for (size_t i = 0; i < n; i++)
        r = cg_mat4_mul(steps[i], r);
    return r;
}
