/* Exact arithmetic for line clipping.
 *
 * Every finite double is an integer multiple of 2^-1074, so the coordinates
 * of one clip are integers once scaled by 2^-e, e the lowest set bit of any
 * of them: at most 2,098 bits, their differences 2,099, the products of two
 * differences 4,198.  A clipped endpoint lies on the segment a + t (b - a)
 * at a parameter t = (bound - a_k) / (b_k - a_k); each decision (which bound
 * is crossed first, on which side of a bound a point is) compares such
 * products exactly, and each coordinate a_j + t (b_j - a_j) is one quotient
 * of integers, rounded to the nearest double (ties to even) once.  So the
 * clip is the one of exact arithmetic, rounded only at its output. */
#include "line_exact.h"

#include <math.h>
#include <string.h>

__extension__ typedef unsigned __int128 line_u128;
__extension__ typedef __int128 line_i128;

static int mag_bits(const line_int *x)
{
    if (x->n == 0)
        return 0;
    return 64 * (x->n - 1) + 64 - __builtin_clzll(x->w[x->n - 1]);
}

static void mag_trim(line_int *x)
{
    while (x->n > 0 && x->w[x->n - 1] == 0)
        x->n--;
    if (x->n == 0)
        x->neg = 0;
}

/* *r = *x, copying only the limbs in use (a line_int is large) */
void line_int_copy(line_int *r, const line_int *x)
{
    r->neg = x->neg;
    r->n = x->n;
    memcpy(r->w, x->w, (size_t)x->n * sizeof x->w[0]);
}

static int mag_cmp(const line_int *a, const line_int *b)
{
    if (a->n != b->n)
        return a->n < b->n ? -1 : 1;
    for (int i = a->n - 1; i >= 0; i--)
        if (a->w[i] != b->w[i])
            return a->w[i] < b->w[i] ? -1 : 1;
    return 0;
}

/* r = |a| + |b| (r may be a or b) */
static void mag_add(line_int *r, const line_int *a, const line_int *b)
{
    int n = a->n > b->n ? a->n : b->n;
    uint64_t carry = 0;
    for (int i = 0; i < n; i++) {
        line_u128 s = (line_u128)(i < a->n ? a->w[i] : 0) + (i < b->n ? b->w[i] : 0) + carry;
        r->w[i] = (uint64_t)s;
        carry = (uint64_t)(s >> 64);
    }
    r->n = n;
    if (carry)
        r->w[r->n++] = carry;
}

/* r = |a| - |b| for |a| >= |b| (r may be a or b) */
static void mag_sub(line_int *r, const line_int *a, const line_int *b)
{
    uint64_t borrow = 0;
    for (int i = 0; i < a->n; i++) {
        uint64_t bi = i < b->n ? b->w[i] : 0;
        uint64_t d = a->w[i] - bi - borrow;
        borrow = a->w[i] < bi || (a->w[i] == bi && borrow);
        r->w[i] = d;
    }
    r->n = a->n;
    mag_trim(r);
}

void line_int_add(line_int *r, const line_int *a, const line_int *b, int negate_b)
{
    int bneg = b->neg ^ (negate_b && b->n);
    int aneg = a->neg;
    if (aneg == bneg) {
        mag_add(r, a, b);
        r->neg = aneg;
    } else if (mag_cmp(a, b) >= 0) {
        mag_sub(r, a, b);
        r->neg = r->n ? aneg : 0;
    } else {
        mag_sub(r, b, a);
        r->neg = r->n ? bneg : 0;
    }
}

void line_int_mul(line_int *r, const line_int *a, const line_int *b)
{
    line_int tmp, *t = r == a || r == b ? &tmp : r;
    t->n = a->n + b->n;
    memset(t->w, 0, (size_t)t->n * sizeof t->w[0]);
    for (int i = 0; i < a->n; i++) {
        uint64_t carry = 0;
        for (int j = 0; j < b->n; j++) {
            line_u128 p = (line_u128)a->w[i] * b->w[j] + t->w[i + j] + carry;
            t->w[i + j] = (uint64_t)p;
            carry = (uint64_t)(p >> 64);
        }
        t->w[i + b->n] = carry;
    }
    t->neg = a->neg ^ b->neg;
    mag_trim(t);
    if (t != r)
        line_int_copy(r, t);
}

int line_int_sign(const line_int *x)
{
    return x->n == 0 ? 0 : x->neg ? -1 : 1;
}

/* x <<= s (s >= 0) */
static void mag_shl(line_int *x, int s)
{
    if (x->n == 0 || s == 0)
        return;
    int limbs = s / 64, bits = s % 64, n = x->n;
    /* from the top down: each limb is read before anything is written over it */
    x->w[n + limbs] = 0;
    for (int i = n - 1; i >= 0; i--) {
        uint64_t v = x->w[i];
        if (bits)
            x->w[i + limbs + 1] |= v >> (64 - bits);
        x->w[i + limbs] = v << bits;
    }
    for (int i = 0; i < limbs; i++)
        x->w[i] = 0;
    x->n = n + limbs + 1;
    mag_trim(x);
}

/* v != 0 (finite) as m 2^e with m odd */
static uint64_t split_double(double v, int *e)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    int field = (int)((bits >> 52) & 0x7ff);
    uint64_t m = bits & (((uint64_t)1 << 52) - 1);
    if (field) /* normal: the hidden bit */
        m |= (uint64_t)1 << 52;
    *e = (field ? field : 1) - 1075;
    int tz = __builtin_ctzll(m);
    *e += tz;
    return m >> tz;
}

static int low_bit(double v)
{
    int e;
    split_double(v, &e);
    return e;
}

int line_scale(const double *v, int n)
{
    int e = 1024;
    for (int i = 0; i < n; i++)
        if (v[i] != 0) {
            int b = low_bit(v[i]);
            if (b < e)
                e = b;
        }
    return e;
}

void line_int_from(line_int *x, double v, int scale)
{
    x->n = 0;
    x->neg = 0;
    if (v == 0)
        return;
    int e;
    x->w[0] = split_double(v, &e);
    x->n = 1;
    x->neg = v < 0;
    mag_shl(x, e - scale);
}

void line_int_small(line_int *x, int v)
{
    x->neg = v < 0;
    x->n = v != 0;
    x->w[0] = (uint64_t)(v < 0 ? -(int64_t)v : v);
}

/* (q + f) 2^e, 2^54 <= q < 2^57, 0 <= f < 1 (f > 0 when sticky), negated
 * when neg, rounded to the nearest double (ties to even): 53 bits are kept
 * above the smallest subnormal's */
static double round_scaled(uint64_t q, int sticky, int e, int neg)
{
    int bq = 64 - __builtin_clzll(q);
    int lsb = bq - 1 + e - 52;
    if (lsb < -1074)
        lsb = -1074;
    int drop = lsb - e; /* >= 2 */
    if (drop >= 58)     /* q < 2^57: below half of the smallest step */
        return neg ? -0.0 : 0.0;
    uint64_t kept = q >> drop, rest = q & (((uint64_t)1 << drop) - 1);
    uint64_t half = (uint64_t)1 << (drop - 1);
    if (rest > half || (rest == half && (sticky || (kept & 1))))
        kept++;
    double v = ldexp((double)kept, lsb);
    return neg ? -v : v;
}

/* the leading 64 bits of x != 0 (the bits below dropped) */
static uint64_t top_bits(const line_int *x)
{
    int n = x->n, lead = __builtin_clzll(x->w[n - 1]);
    uint64_t top = x->w[n - 1] << lead;
    if (lead && n > 1)
        top |= x->w[n - 2] >> (64 - lead);
    return top;
}

double line_int_quotient(const line_int *num, const line_int *den, int scale)
{
    if (num->n == 0)
        return 0.0;
    /* Q = floor(|num| 2^s / den) with 2^55 <= Q < 2^57, R the remainder */
    int s = 56 - (mag_bits(num) - mag_bits(den));
    line_int r, t;
    line_int_copy(&r, num);
    line_int_copy(&t, den);
    r.neg = t.neg = 0;
    if (s >= 0)
        mag_shl(&r, s);
    else
        mag_shl(&t, -s);
    /* Q from the leading bits in long double (within a few units of Q
     * where long double has 64 bits, within some 2^5 where it has 53),
     * then corrected with the exact remainder */
    long double ratio = (long double)top_bits(&r) / (long double)top_bits(&t);
    uint64_t q = (uint64_t)ldexpl(ratio, mag_bits(&r) - mag_bits(&t));
    line_int qq, p;
    line_int_small(&qq, 1);
    qq.w[0] = q;
    line_int_mul(&p, &t, &qq);
    line_int_add(&r, &r, &p, 1); /* the remainder, perhaps out of [0, den) */
    while (r.neg) {
        line_int_add(&r, &r, &t, 0);
        q--;
    }
    while (mag_cmp(&r, &t) >= 0) {
        mag_sub(&r, &r, &t);
        q++;
    }
    return round_scaled(q, r.n != 0, scale - s, num->neg ^ den->neg);
}

/* The small form: when every scaled coordinate is below 2^62 (coordinates
 * within 2^62 of their common lowest bit, as integers and most coordinates
 * of graphics are), the differences fit in int64_t and the products and
 * their sums in __int128, and the same decisions and quotients come from
 * these in a few instructions. */
#define LINE_SMALL_BITS 62

/* the exponent of the highest set bit of v != 0 */
static int high_bit(double v)
{
    int e;
    uint64_t m = split_double(v, &e);
    return e + 63 - __builtin_clzll(m);
}

static int64_t small_from(double v, int scale)
{
    if (v == 0)
        return 0;
    int e;
    int64_t m = (int64_t)split_double(v, &e); /* (sets e: not in the same expression) */
    m <<= e - scale;
    return v < 0 ? -m : m;
}

void line_seg_init(line_seg *s, int dim, const double *a, const double *b, const double *lo,
                   const double *hi)
{
    double all[12] = {0};
    for (int j = 0; j < dim; j++) {
        all[4 * j] = a[j];
        all[4 * j + 1] = b[j];
        all[4 * j + 2] = lo[j];
        all[4 * j + 3] = hi[j];
    }
    s->dim = dim;
    s->scale = line_scale(all, 4 * dim);
    s->small = 1;
    for (int i = 0; i < 4 * dim; i++)
        if (all[i] != 0 && high_bit(all[i]) - s->scale >= LINE_SMALL_BITS)
            s->small = 0;
    for (int j = 0; j < dim; j++) {
        s->a[j] = a[j];
        s->b[j] = b[j];
        if (s->small) {
            s->sa[j] = small_from(a[j], s->scale);
            s->sd[j] = small_from(b[j], s->scale) - s->sa[j];
            continue;
        }
        line_int bj;
        line_int_from(&s->ai[j], a[j], s->scale);
        line_int_from(&bj, b[j], s->scale);
        line_int_add(&s->d[j], &bj, &s->ai[j], 1);
    }
}

void line_param_end(line_param *t, int at_b)
{
    t->num = at_b;
    t->den = 1;
    line_int_small(&t->bnum, at_b);
    line_int_small(&t->bden, 1);
}

void line_param_copy(line_param *r, const line_param *t)
{
    r->num = t->num;
    r->den = t->den;
    line_int_copy(&r->bnum, &t->bnum);
    line_int_copy(&r->bden, &t->bden);
}

void line_param_bound(const line_seg *s, int axis, double bound, line_param *t)
{
    if (s->small) {
        int64_t num = small_from(bound, s->scale) - s->sa[axis], den = s->sd[axis];
        t->num = den < 0 ? -num : num;
        t->den = den < 0 ? -den : den;
        t->bnum.n = t->bden.n = 0; /* (not used) */
        return;
    }
    line_int_from(&t->bnum, bound, s->scale);
    line_int_add(&t->bnum, &t->bnum, &s->ai[axis], 1);
    line_int_copy(&t->bden, &s->d[axis]);
    if (t->bden.neg) {
        t->bden.neg = 0;
        t->bnum.neg = t->bnum.n ? !t->bnum.neg : 0;
    }
}

static int sign128(line_i128 v)
{
    return (v > 0) - (v < 0);
}

int line_param_cmp(const line_seg *s, const line_param *t, const line_param *u)
{
    if (s->small)
        return sign128((line_i128)t->num * u->den - (line_i128)u->num * t->den);
    line_int l, r;
    line_int_mul(&l, &t->bnum, &u->bden);
    line_int_mul(&r, &u->bnum, &t->bden);
    line_int_add(&l, &l, &r, 1);
    return line_int_sign(&l);
}

/* whether t is 0 or 1: the point is a or b itself */
static int param_end(const line_seg *s, const line_param *t, int *at_b)
{
    if (s->small) {
        *at_b = t->num != 0;
        return t->num == 0 || t->num == t->den;
    }
    if (t->bnum.n == 0) {
        *at_b = 0;
        return 1;
    }
    *at_b = 1;
    return t->bnum.n == t->bden.n && !t->bnum.neg
           && !memcmp(t->bnum.w, t->bden.w, (size_t)t->bnum.n * sizeof t->bnum.w[0]);
}

int line_side(const line_seg *s, const line_param *t, int axis, double bound)
{
    int at_b;
    if (param_end(s, t, &at_b)) {
        double v = at_b ? s->b[axis] : s->a[axis];
        return (v > bound) - (v < bound);
    }
    /* sign(a + d num / den - bound) = sign((a - bound) den + d num), den > 0 */
    if (s->small)
        return sign128((line_i128)(s->sa[axis] - small_from(bound, s->scale)) * t->den
                       + (line_i128)s->sd[axis] * t->num);
    line_int x, y;
    line_int_from(&x, bound, s->scale);
    line_int_add(&x, &s->ai[axis], &x, 1);
    line_int_mul(&x, &x, &t->bden);
    line_int_mul(&y, &s->d[axis], &t->bnum);
    line_int_add(&x, &x, &y, 0);
    return line_int_sign(&x);
}

/* num / den 2^scale (den > 0) rounded to the nearest double */
static double small_quotient(line_i128 num, int64_t den, int scale)
{
    if (num == 0)
        return 0.0;
    int neg = num < 0;
    line_u128 n = neg ? -(line_u128)num : (line_u128)num, d = (line_u128)den;
    /* as in line_int_quotient: 2^55 <= q < 2^57 from n 2^k / d, where
     * n 2^k < 2^57 d < 2^120 fits; or n / d with its low bits dropped */
    int bn = n >> 64 ? 128 - __builtin_clzll((uint64_t)(n >> 64))
                     : 64 - __builtin_clzll((uint64_t)n);
    int bd = 64 - __builtin_clzll((uint64_t)d);
    int k = 56 - (bn - bd), e = scale, sticky;
    line_u128 q;
    if (k > 0) {
        n <<= k;
        e -= k;
        q = n / d;
        sticky = n % d != 0;
    } else {
        q = n / d;
        sticky = n % d != 0;
        int bq = q >> 64 ? 128 - __builtin_clzll((uint64_t)(q >> 64))
                         : 64 - __builtin_clzll((uint64_t)q);
        if (bq > 57) { /* the bits dropped join the sticky bit */
            int drop = bq - 57;
            sticky |= (q & (((line_u128)1 << drop) - 1)) != 0;
            q >>= drop;
            e += drop;
        }
    }
    return round_scaled((uint64_t)q, sticky, e, neg);
}

double line_coord(const line_seg *s, const line_param *t, int axis)
{
    int at_b;
    if (param_end(s, t, &at_b))
        return at_b ? s->b[axis] : s->a[axis];
    if (s->small)
        return small_quotient((line_i128)s->sa[axis] * t->den + (line_i128)s->sd[axis] * t->num,
                              t->den, s->scale);
    line_int x, y;
    line_int_mul(&x, &s->ai[axis], &t->bden);
    line_int_mul(&y, &s->d[axis], &t->bnum);
    line_int_add(&x, &x, &y, 0);
    return line_int_quotient(&x, &t->bden, s->scale);
}
