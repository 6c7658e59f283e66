/* Parametric cubic segments Q(t) = T M G (section 2.3.1) in four bases. */
#include "cg/curve.h"

static const double hermite[4][4] = {{2, -2, 1, 1}, {-3, 3, -2, -1}, {0, 0, 1, 0}, {1, 0, 0, 0}};
static const double bezier[4][4] = {{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}};
static const double bspline[4][4] = {{-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0},
                                     {3 / 6.0, -6 / 6.0, 3 / 6.0, 0},
                                     {-3 / 6.0, 0, 3 / 6.0, 0},
                                     {1 / 6.0, 4 / 6.0, 1 / 6.0, 0}};
static const double catmull_rom[4][4] = {
    {-0.5, 1.5, -1.5, 0.5}, {1, -2.5, 2, -0.5}, {-0.5, 0, 0.5, 0}, {0, 1, 0, 0}};

/* Inverses, worked exactly: the Hermite inverse is the constraint matrix of
 * section 2.3.2; the others follow from their geometric meaning. */
static const double hermite_inverse[4][4] = {
    {0, 0, 0, 1}, {1, 1, 1, 1}, {0, 0, 1, 0}, {3, 2, 1, 0}};
static const double bezier_inverse[4][4] = {
    {0, 0, 0, 1}, {0, 0, 1 / 3.0, 1}, {0, 1 / 3.0, 2 / 3.0, 1}, {1, 1, 1, 1}};
static const double bspline_inverse[4][4] = {
    {0, 2 / 3.0, -1, 1}, {0, -1 / 3.0, 0, 1}, {0, 2 / 3.0, 1, 1}, {6, 11 / 3.0, 2, 1}};
static const double catmull_rom_inverse[4][4] = {
    {1, 1, -1, 1}, {0, 0, 0, 1}, {1, 1, 1, 1}, {6, 4, 2, 1}};

static int valid_basis(cg_curve_basis basis)
{
    return basis >= CG_BASIS_HERMITE && basis <= CG_BASIS_CATMULL_ROM;
}

static cg_mat4 from_table(const double table[4][4])
{
    cg_mat4 m;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m.m[i][j] = table[i][j];
    return m;
}

cg_mat4 cg_curve_basis_matrix(cg_curve_basis basis)
{
    switch (basis) {
    case CG_BASIS_HERMITE: return from_table(hermite);
    case CG_BASIS_BEZIER: return from_table(bezier);
    case CG_BASIS_BSPLINE: return from_table(bspline);
    case CG_BASIS_CATMULL_ROM: return from_table(catmull_rom);
    }
    return cg_mat4_identity();
}

cg_mat4 cg_curve_basis_inverse(cg_curve_basis basis)
{
    switch (basis) {
    case CG_BASIS_HERMITE: return from_table(hermite_inverse);
    case CG_BASIS_BEZIER: return from_table(bezier_inverse);
    case CG_BASIS_BSPLINE: return from_table(bspline_inverse);
    case CG_BASIS_CATMULL_ROM: return from_table(catmull_rom_inverse);
    }
    return cg_mat4_identity();
}

const char *cg_curve_basis_name(cg_curve_basis basis)
{
    switch (basis) {
    case CG_BASIS_HERMITE: return "hermite";
    case CG_BASIS_BEZIER: return "bezier";
    case CG_BASIS_BSPLINE: return "bspline";
    case CG_BASIS_CATMULL_ROM: return "catmull-rom";
    }
    return "unknown";
}

/* Rows of M G for geometry stored as n doubles per entry. */
static void multiply(cg_mat4 m, const double *g, int n, double *out)
{
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < n; k++) {
            double s = 0;
            for (int j = 0; j < 4; j++)
                s += m.m[i][j] * g[j * n + k];
            out[i * n + k] = s;
        }
}

static void unpack2(const cg_vec2 *v, double *d)
{
    for (int i = 0; i < 4; i++) {
        d[2 * i] = v[i].x;
        d[2 * i + 1] = v[i].y;
    }
}

static void unpack3(const cg_vec3 *v, double *d)
{
    for (int i = 0; i < 4; i++) {
        d[3 * i] = v[i].x;
        d[3 * i + 1] = v[i].y;
        d[3 * i + 2] = v[i].z;
    }
}

void cg_cubic2_coefficients(const cg_cubic2 *curve, cg_vec2 c[4])
{
    double g[8], r[8];
    unpack2(curve->g, g);
    multiply(cg_curve_basis_matrix(curve->basis), g, 2, r);
    for (int i = 0; i < 4; i++)
        c[i] = cg_vec2_make(r[2 * i], r[2 * i + 1]);
}

void cg_cubic3_coefficients(const cg_cubic3 *curve, cg_vec3 c[4])
{
    double g[12], r[12];
    unpack3(curve->g, g);
    multiply(cg_curve_basis_matrix(curve->basis), g, 3, r);
    for (int i = 0; i < 4; i++)
        c[i] = cg_vec3_make(r[3 * i], r[3 * i + 1], r[3 * i + 2]);
}

cg_vec2 cg_cubic2_point(const cg_cubic2 *curve, double t)
{
    cg_vec2 c[4];
    cg_cubic2_coefficients(curve, c);
    return cg_vec2_make(((c[0].x * t + c[1].x) * t + c[2].x) * t + c[3].x,
                        ((c[0].y * t + c[1].y) * t + c[2].y) * t + c[3].y);
}

cg_vec2 cg_cubic2_tangent(const cg_cubic2 *curve, double t)
{
    cg_vec2 c[4];
    cg_cubic2_coefficients(curve, c);
    return cg_vec2_make((3 * c[0].x * t + 2 * c[1].x) * t + c[2].x,
                        (3 * c[0].y * t + 2 * c[1].y) * t + c[2].y);
}

cg_vec3 cg_cubic3_point(const cg_cubic3 *curve, double t)
{
    cg_vec3 c[4];
    cg_cubic3_coefficients(curve, c);
    return cg_vec3_make(((c[0].x * t + c[1].x) * t + c[2].x) * t + c[3].x,
                        ((c[0].y * t + c[1].y) * t + c[2].y) * t + c[3].y,
                        ((c[0].z * t + c[1].z) * t + c[2].z) * t + c[3].z);
}

cg_vec3 cg_cubic3_tangent(const cg_cubic3 *curve, double t)
{
    cg_vec3 c[4];
    cg_cubic3_coefficients(curve, c);
    return cg_vec3_make((3 * c[0].x * t + 2 * c[1].x) * t + c[2].x,
                        (3 * c[0].y * t + 2 * c[1].y) * t + c[2].y,
                        (3 * c[0].z * t + 2 * c[1].z) * t + c[2].z);
}

/* M_to^-1 M_from: the matrix taking a geometry vector between bases. */
static cg_mat4 conversion(cg_curve_basis from, cg_curve_basis to)
{
    return cg_mat4_mul(cg_curve_basis_inverse(to), cg_curve_basis_matrix(from));
}

cg_status cg_cubic2_convert(const cg_cubic2 *curve, cg_curve_basis to, cg_cubic2 *out)
{
    if (!curve || !out || !valid_basis(curve->basis) || !valid_basis(to))
        return CG_EINVAL;
    double g[8], r[8];
    unpack2(curve->g, g);
    multiply(conversion(curve->basis, to), g, 2, r);
    out->basis = to;
    for (int i = 0; i < 4; i++)
        out->g[i] = cg_vec2_make(r[2 * i], r[2 * i + 1]);
    return CG_OK;
}

cg_status cg_cubic3_convert(const cg_cubic3 *curve, cg_curve_basis to, cg_cubic3 *out)
{
    if (!curve || !out || !valid_basis(curve->basis) || !valid_basis(to))
        return CG_EINVAL;
    double g[12], r[12];
    unpack3(curve->g, g);
    multiply(conversion(curve->basis, to), g, 3, r);
    out->basis = to;
    for (int i = 0; i < 4; i++)
        out->g[i] = cg_vec3_make(r[3 * i], r[3 * i + 1], r[3 * i + 2]);
    return CG_OK;
}
