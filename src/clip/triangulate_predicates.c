/* The exact in-circle test of the triangulation, on the int64 grid.
 *
 * With coordinates within 2^44 (the grid's 2^40 and the enclosing
 * triangle's corners), differences take 45 bits, the lifted terms
 * dx^2 + dy^2 91 and the determinant's products 181: a double filter
 * settles almost every call, and the rest is computed exactly in 256-bit
 * integers (four 64-bit limbs and a sign). */
#include "triangulate_internal.h"

#include <math.h>
#include <string.h>

/* A signed 256-bit integer: magnitude in limbs (least significant first). */
typedef struct wide {
    uint64_t limb[4];
    int negative;
} wide;

__extension__ typedef unsigned __int128 u128;

/* The product of two signed 128-bit values, exactly. */
static wide wide_mul(polygon_i128 a, polygon_i128 b)
{
    wide w = {{0, 0, 0, 0}, (a < 0) != (b < 0)};
    u128 x = a < 0 ? (u128)(-a) : (u128)a, y = b < 0 ? (u128)(-b) : (u128)b;
    uint64_t xs[2] = {(uint64_t)x, (uint64_t)(x >> 64)}, ys[2] = {(uint64_t)y, (uint64_t)(y >> 64)};
    for (int i = 0; i < 2; i++) {
        u128 carry = 0;
        for (int j = 0; j < 2; j++) {
            u128 t = (u128)xs[i] * ys[j] + w.limb[i + j] + carry;
            w.limb[i + j] = (uint64_t)t;
            carry = t >> 64;
        }
        for (int k = i + 2; k < 4 && carry; k++) {
            u128 t = (u128)w.limb[k] + carry;
            w.limb[k] = (uint64_t)t;
            carry = t >> 64;
        }
    }
    if ((w.limb[0] | w.limb[1] | w.limb[2] | w.limb[3]) == 0)
        w.negative = 0;
    return w;
}

/* Compares magnitudes: -1, 0, 1. */
static int magnitude_compare(const wide *a, const wide *b)
{
    for (int k = 3; k >= 0; k--)
        if (a->limb[k] != b->limb[k])
            return a->limb[k] < b->limb[k] ? -1 : 1;
    return 0;
}

static wide wide_add(wide a, wide b)
{
    wide r = {{0, 0, 0, 0}, 0};
    if (a.negative == b.negative) {
        u128 carry = 0;
        for (int k = 0; k < 4; k++) {
            u128 t = (u128)a.limb[k] + b.limb[k] + carry;
            r.limb[k] = (uint64_t)t;
            carry = t >> 64;
        }
        r.negative = a.negative;
    } else {
        /* the larger magnitude less the smaller, with the larger's sign */
        int c = magnitude_compare(&a, &b);
        if (c == 0)
            return r;
        const wide *big = c > 0 ? &a : &b, *small = c > 0 ? &b : &a;
        uint64_t borrow = 0;
        for (int k = 0; k < 4; k++) {
            uint64_t s = small->limb[k] + borrow;
            borrow = (s < borrow) || (big->limb[k] < s);
            r.limb[k] = big->limb[k] - s;
        }
        r.negative = big->negative;
    }
    return r;
}

static int wide_sign(wide w)
{
    if ((w.limb[0] | w.limb[1] | w.limb[2] | w.limb[3]) == 0)
        return 0;
    return w.negative ? -1 : 1;
}

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
    wide sum = wide_add(wide_add(wide_mul(Alift, AB), wide_mul(Blift, BC)), wide_mul(Clift, CA));
    return wide_sign(sum);
}
