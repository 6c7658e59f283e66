/* Exact arithmetic beyond 128 bits for the polygon-geometry files: signed
 * 256-bit integers (products of two 128-bit values and their sums), and
 * division rounded to the grid. */
#include "polygon_internal.h"


__extension__ typedef unsigned __int128 u128;

polygon_wide polygon_wide_mul(polygon_i128 a, polygon_i128 b)
{
    polygon_wide w = {{0, 0, 0, 0}, (a < 0) != (b < 0)};
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
static int magnitude_compare(const polygon_wide *a, const polygon_wide *b)
{
    for (int k = 3; k >= 0; k--)
        if (a->limb[k] != b->limb[k])
            return a->limb[k] < b->limb[k] ? -1 : 1;
    return 0;
}

polygon_wide polygon_wide_add(polygon_wide a, polygon_wide b)
{
    polygon_wide r = {{0, 0, 0, 0}, 0};
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
        const polygon_wide *big = c > 0 ? &a : &b, *small = c > 0 ? &b : &a;
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

int polygon_wide_sign(polygon_wide w)
{
    if ((w.limb[0] | w.limb[1] | w.limb[2] | w.limb[3]) == 0)
        return 0;
    return w.negative ? -1 : 1;
}

int polygon_compare_products(polygon_i128 a, polygon_i128 b, polygon_i128 c, polygon_i128 d)
{
    polygon_wide ab = polygon_wide_mul(a, b), cd = polygon_wide_mul(c, d);
    cd.negative = !cd.negative;
    return polygon_wide_sign(polygon_wide_add(ab, cd));
}

int64_t polygon_divide_rounded(polygon_i128 numerator, polygon_i128 denominator)
{
    if (denominator < 0) {
        numerator = -numerator;
        denominator = -denominator;
    }
    polygon_i128 half = denominator / 2;
    return (int64_t)(numerator >= 0 ? (numerator + half) / denominator
                                    : -((-numerator + half) / denominator));
}
