/* The exact in-circle test of the triangulation, on the int64 grid.
 *
 * With coordinates within 2^44 (the grid's 2^40 and the enclosing
 * triangle's corners), differences take 45 bits, the lifted terms
 * dx^2 + dy^2 91 and the determinant's products 181: a double filter
 * settles almost every call, and the rest is computed exactly in 256-bit
 * integers (four 64-bit limbs and a sign). */
#include "triangulate_internal.h"

#include <math.h>

int triangulate_incircle(cg_point64 a, cg_point64 b, cg_point64 c, cg_point64 d)
{
    double adx = (double)(a.x - d.x), ady = (double)(a.y - d.y);
    double bdx = (double)(b.x - d.x), bdy = (double)(b.y - d.y);
    double cdx = (double)(c.x - d.x), cdy = (double)(c.y - d.y);
    double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy;
    double clift = cdx * cdx + cdy * cdy;
    double ab = bdx * cdy - cdx * bdy, bc = cdx * ady - adx * cdy, ca = adx * bdy - bdx * ady;
    double det = alift * ab + blift * bc + clift * ca;
    double permanent = alift * (fabs(bdx * cdy) + fabs(cdx * bdy))
                       + blift * (fabs(cdx * ady) + fabs(adx * cdy))
                       + clift * (fabs(adx * bdy) + fabs(bdx * ady));
    /* the differences are exact in doubles (below 2^53); the bound covers
     * the rounding of the products and sums that follow */
    double bound = 1e-14 * permanent;
    if (det > bound)
        return 1;
    if (det < -bound)
        return -1;
    polygon_i128 Adx = a.x - d.x, Ady = a.y - d.y, Bdx = b.x - d.x, Bdy = b.y - d.y;
    polygon_i128 Cdx = c.x - d.x, Cdy = c.y - d.y;
    polygon_i128 Alift = Adx * Adx + Ady * Ady, Blift = Bdx * Bdx + Bdy * Bdy;
    polygon_i128 Clift = Cdx * Cdx + Cdy * Cdy;
    polygon_i128 AB = Bdx * Cdy - Cdx * Bdy, BC = Cdx * Ady - Adx * Cdy, CA = Adx * Bdy - Bdx * Ady;
    polygon_wide sum = polygon_wide_add(
        polygon_wide_add(polygon_wide_mul(Alift, AB), polygon_wide_mul(Blift, BC)),
        polygon_wide_mul(Clift, CA));
    return polygon_wide_sign(sum);
}
