/* Sorting for the boolean operations: stable radix and run-merging sorts of
 * edges and pieces by two integer keys, and qsort for a few records. */
#include "boolean_engine.h"
#include "../../core/sort.h"

/* The int64_t field of record i, the field of record 0 at `base` and the
 * records `stride` bytes apart (the sorts' keys k1 and k2). */
static inline int64_t key_at(const int64_t *base, size_t i, size_t stride)
{
    return *(const int64_t *)((const char *)base + i * stride);
}

/* whether record i's keys (k1, k2) come before (p1, p2) */
static inline int record_below(const int64_t *k1, const int64_t *k2, size_t stride, size_t i,
                               int64_t p1, int64_t p2)
{
    int64_t a1 = key_at(k1, i, stride);
    return a1 < p1 || (a1 == p1 && key_at(k2, i, stride) < p2);
}

/* the number of bits v needs (0 for 0) */
static inline int bit_length(uint64_t v)
{
    int n = 0;
    while (n < 64 && (v >> n))
        n++;
    return n;
}

/* a[i] and a[j] (i < j) in order, branch-free */
static inline void order_two(uint64_t *a, size_t i, size_t j)
{
    uint64_t p = a[i], q = a[j];
    a[i] = p < q ? p : q;
    a[j] = p < q ? q : p;
}

/* out[0..2m) = the sorted x[0..m) and y[0..m) merged, m steps from the
 * front taking the lesser key and m from the back taking the greater: two
 * equal runs need no bounds checks (after s steps from the front, s keys
 * are taken from the two), and the two ends are independent chains of work.
 * Each step is branch-free: on the few keys of small inputs which side a
 * key comes from is as good as random, and a branch would often be
 * mispredicted. */
static inline void merge_equal(const uint64_t *x, const uint64_t *y, size_t m, uint64_t *out)
{
    const uint64_t *xb = x + m - 1, *yb = y + m - 1;
    uint64_t *ob = out + 2 * m - 1;
    for (size_t s = 0; s < m; s++) {
        uint64_t p = *x, q = *y;
        size_t lesser = p <= q;
        *out++ = lesser ? p : q;
        x += lesser;
        y += 1 - lesser;
        uint64_t pb = *xb, qb = *yb;
        size_t greater = pb > qb;
        *ob-- = greater ? pb : qb;
        xb -= greater;
        yb -= 1 - greater;
    }
}

/* a[0..n) in ascending order, branch-free: n a power of two >= 4, tmp
 * holds n (shorter arrays are padded with UINT64_MAX) */
static void sort_pow2(uint64_t *a, size_t n, uint64_t *tmp)
{
    /* blocks of 4 by a sorting network, then merged bottom-up */
    for (size_t i = 0; i < n; i += 4) {
        order_two(a, i, i + 1);
        order_two(a, i + 2, i + 3);
        order_two(a, i, i + 2);
        order_two(a, i + 1, i + 3);
        order_two(a, i + 1, i + 2);
    }
    uint64_t *src = a, *dst = tmp;
    for (size_t w = 4; w < n; w *= 2) {
        for (size_t lo = 0; lo < n; lo += 2 * w)
            merge_equal(src + lo, src + lo + w, w, dst + lo);
        uint64_t *x = src;
        src = dst;
        dst = x;
    }
    if (src != a)
        memcpy(a, src, n * sizeof *a);
}

/* v put into a[0..i), in order by key, after the equal keys: a[0..i] in
 * order */
static inline void insert_key(keyval *a, size_t i, keyval v)
{
    for (; i > 0 && a[i - 1].key > v.key; i--)
        a[i] = a[i - 1];
    a[i] = v;
}

/* Stable sort of a[0..n) by key: straight insertion up to 48 keys, below
 * 2,048 one pass by the top bits then insertion (when the keys spread
 * evenly), else an LSD radix sort (6- or 11-bit digits, only as many passes
 * as the largest key needs); all is the OR of the keys, tmp holds n or is
 * NULL. */
static int radix_sort_all(keyval *a, size_t n, keyval *tmp, uint64_t all)
{
    if (n < 2)
        return 1;
    if (n <= 48) { /* few keys: straight insertion (stable) */
        for (size_t i = 1; i < n; i++)
            insert_key(a, i, a[i]);
        return 1;
    }
    keyval *t = tmp ? tmp : malloc(n * sizeof *t), *src = a, *dst = t;
    if (!t)
        return 0;
    if (n < 2048) {
        /* one pass by the top bits (about n buckets, stable), then straight
         * insertion, which moves keys within their bucket only: unless a
         * bucket holds many keys (uneven keys), then the digits below */
        int top = bit_length(all), b = 6;
        while (((size_t)1 << b) < n)
            b++;
        int shift = top > b ? top - b : 0;
        size_t count[2048], most = 0;
        memset(count, 0, ((size_t)1 << b) * sizeof count[0]);
        for (size_t i = 0; i < n; i++) {
            size_t c = ++count[a[i].key >> shift];
            most = c > most ? c : most;
        }
        if (most <= 16) {
            size_t sum = 0;
            for (size_t d = 0; d < ((size_t)1 << b); d++) {
                size_t c = count[d];
                count[d] = sum;
                sum += c;
            }
            for (size_t i = 0; i < n; i++)
                t[count[a[i].key >> shift]++] = a[i];
            for (size_t i = 0; i < n; i++)
                insert_key(a, i, t[i]);
            if (!tmp)
                free(t);
            return 1;
        }
    }
    /* small inputs: small digit tables */
    const int bits = n < 2048 ? 6 : 11;
    for (int shift = 0; shift < 64 && (all >> shift); shift += bits) {
        size_t count[1 << 11];
        memset(count, 0, ((size_t)1 << bits) * sizeof count[0]);
        for (size_t i = 0; i < n; i++)
            count[(src[i].key >> shift) & ((1u << bits) - 1)]++;
        if (count[(src[0].key >> shift) & ((1u << bits) - 1)] == n)
            continue; /* every key has this digit */
        size_t sum = 0;
        for (size_t d = 0; d < (1u << bits); d++) {
            size_t c = count[d];
            count[d] = sum;
            sum += c;
        }
        for (size_t i = 0; i < n; i++)
            dst[count[(src[i].key >> shift) & ((1u << bits) - 1)]++] = src[i];
        keyval *x = src;
        src = dst;
        dst = x;
    }
    if (src != a)
        memcpy(a, src, n * sizeof *a);
    if (!tmp)
        free(t);
    return 1;
}

static int radix_sort(keyval *a, size_t n, keyval *tmp)
{
    uint64_t all = 0;
    for (size_t i = 0; i < n; i++)
        all |= a[i].key;
    return radix_sort_all(a, n, tmp, all);
}

/* The natural runs of boolean_sort_two_keys' input, merged: idx[0..n) ordered by
 * (k1, k2, index) as the radix sort orders it, when the sequence is made
 * of at most MAX_RUNS ascending or strictly descending runs (the edges of
 * smooth rings come in a few monotone chains): 1, else 0 (nothing
 * written).  The runs are merged all at once, straight from the records
 * (each run's next key at hand, the least of them taken). */
#define MAX_RUNS 8
static int sort_runs(const int64_t *k1, const int64_t *k2, size_t stride, size_t n, uint32_t *idx)
{
    /* run r: positions at[r], at[r] + step[r], ... up to (excluding) end[r] */
    ptrdiff_t at[MAX_RUNS], end[MAX_RUNS], step[MAX_RUNS];
    int64_t h1[MAX_RUNS], h2[MAX_RUNS];
    size_t nr = 0;
    for (size_t i = 0; i < n;) {
        if (nr == MAX_RUNS)
            return 0;
        int64_t p1 = key_at(k1, i, stride), p2 = key_at(k2, i, stride);
        size_t j = i + 1;
        if (j < n && record_below(k1, k2, stride, j, p1, p2)) {
            /* strictly descending (no ties: backwards, it is in order) */
            do {
                p1 = key_at(k1, j, stride);
                p2 = key_at(k2, j, stride);
                j++;
            } while (j < n && record_below(k1, k2, stride, j, p1, p2));
            at[nr] = (ptrdiff_t)j - 1;
            end[nr] = (ptrdiff_t)i - 1;
            step[nr] = -1;
        } else {
            while (j < n && !record_below(k1, k2, stride, j, p1, p2)) {
                p1 = key_at(k1, j, stride);
                p2 = key_at(k2, j, stride);
                j++;
            }
            at[nr] = (ptrdiff_t)i;
            end[nr] = (ptrdiff_t)j;
            step[nr] = 1;
        }
        h1[nr] = key_at(k1, at[nr], stride);
        h2[nr] = key_at(k2, at[nr], stride);
        nr++;
        i = j;
    }
    for (size_t o = 0; o < n; o++) {
        size_t b = 0;
        for (size_t r = 1; r < nr; r++)
            if (h1[r] < h1[b]
                || (h1[r] == h1[b] && (h2[r] < h2[b] || (h2[r] == h2[b] && at[r] < at[b]))))
                b = r;
        idx[o] = (uint32_t)at[b];
        at[b] += step[b];
        if (at[b] == end[b]) { /* run b is used up: the last takes its place */
            nr--;
            at[b] = at[nr];
            end[b] = end[nr];
            step[b] = step[nr];
            h1[b] = h1[nr];
            h2[b] = h2[nr];
        } else {
            h1[b] = key_at(k1, at[b], stride);
            h2[b] = key_at(k2, at[b], stride);
        }
    }
    return 1;
}

#define RADIX_RUN 48

/* a[0..n) (records by index, in any order) in stable order by k2, a radix
 * sort from the least k2 */
static int radix_by_k2(const int64_t *k2, size_t stride, keyval *a, size_t n, keyval *tmp)
{
    int64_t lo2 = key_at(k2, a[0].val, stride);
    for (size_t q = 1; q < n; q++) {
        int64_t b = key_at(k2, a[q].val, stride);
        lo2 = b < lo2 ? b : lo2;
    }
    for (size_t q = 0; q < n; q++)
        a[q].key = (uint64_t)(key_at(k2, a[q].val, stride) - lo2);
    return radix_sort(a, n, tmp);
}

/* a[0..n) (records by index, in order but for k2) in stable order by k2,
 * by straight insertion, each k2 keyed as it is taken (the sign bit
 * flipped: unsigned order is k2's); 0 when that would move records more
 * than `budget` times (a[] then in no particular order) */
static ALWAYS_INLINE int insert_by_k2(const int64_t *k2, size_t stride, keyval *a, size_t n,
                                      size_t budget)
{
    const uint64_t flip = (uint64_t)1 << 63;
    size_t moves = 0;
    a[0].key = (uint64_t)key_at(k2, a[0].val, stride) ^ flip;
    for (size_t q = 1; q < n; q++) {
        keyval v = a[q];
        v.key = (uint64_t)key_at(k2, v.val, stride) ^ flip;
        size_t m = q;
        for (; m > 0 && a[m - 1].key > v.key; m--)
            a[m] = a[m - 1];
        a[m] = v;
        moves += q - m;
        if (moves > budget)
            return 0;
    }
    return 1;
}

/* boolean_sort_two_keys through one 63-bit key per record when n <= 64:
 * k1 and k2, each relative to record 0's, in 29 and 28 bits, then the index
 * in 6.  1 when the keys' spreads allow, else 0 (idx not written). */
static int sort_packed(const int64_t *k1, const int64_t *k2, size_t stride, size_t n, uint32_t *idx)
{
    uint64_t key[64], tmp[64];
    const char *r1 = (const char *)k1, *r2 = (const char *)k2;
    uint64_t base1 = (uint64_t)*k1 - ((uint64_t)1 << 28),
             base2 = (uint64_t)*k2 - ((uint64_t)1 << 27);
    uint64_t out = 0; /* bits beyond the fields */
    for (size_t i = 0; i < n; i++, r1 += stride, r2 += stride) {
        uint64_t d1 = (uint64_t) * (const int64_t *)r1 - base1,
                 d2 = (uint64_t) * (const int64_t *)r2 - base2;
        out |= d1 >> 29 | d2 >> 28;
        key[i] = d1 << 34 | d2 << 6 | i;
    }
    if (out)
        return 0;
    size_t m = 4;
    while (m < n)
        m *= 2;
    for (size_t i = n; i < m; i++)
        key[i] = UINT64_MAX; /* (after every key) */
    sort_pow2(key, m, tmp);
    for (size_t i = 0; i < n; i++)
        idx[i] = (uint32_t)(key[i] & 63);
    return 1;
}

/* sort_packed is used from PACKED_MIN records (below, straight insertion
 * costs less) to 64 */
#define PACKED_MIN 16

/* At most this many bits for k1 and k2 together: one radix sort on the two
 * (two passes of 11-bit digits), as on a coarse grid, where a few hundred
 * scanlines hold thousands of pieces each */
#define COMBINED_BITS 22

/* a[0..n) (k1 - its least, < 2^COMBINED_BITS, in a[].key; all is their OR)
 * in stable order by (k1, k2) through one key of both, when k2's spread
 * fits beside: 1; -1 when it does not (a[] unchanged); 0 when out of
 * memory. */
static int sort_combined(const int64_t *k2, size_t stride, size_t n, keyval *a, keyval *tmp,
                         uint64_t all)
{
    int bits1 = bit_length(all);
    int64_t lo2 = key_at(k2, a[0].val, stride), hi2 = lo2;
    for (size_t i = 1; i < n; i++) {
        int64_t b = key_at(k2, a[i].val, stride);
        lo2 = b < lo2 ? b : lo2;
        hi2 = b > hi2 ? b : hi2;
    }
    int bits2 = bit_length((uint64_t)hi2 - (uint64_t)lo2);
    if (bits1 + bits2 > COMBINED_BITS)
        return -1;
    uint64_t both = 0;
    for (size_t i = 0; i < n; i++) {
        a[i].key = a[i].key << bits2 | (uint64_t)(key_at(k2, a[i].val, stride) - lo2);
        both |= a[i].key;
    }
    return radix_sort_all(a, n, tmp, both);
}

/* idx[0..n) ordered by (k1[i], k2[i]) lexicographically (the keys are
 * int64 fields of records `stride` bytes apart); scratch of n, tmp of n or
 * NULL.  From PACKED_MIN to 64 records, one key each, sorted branch-free,
 * when the keys' spreads fit (sort_packed).  Else the natural runs merged
 * when they are few (sort_runs), else a radix sort by k1, then each run of
 * equal k1 by k2 (straight insertion; a run of more than RADIX_RUN records
 * radix sorted once insertion has moved records as many times as it has
 * records: on coarse grids hundreds of pieces start on one scanline in no
 * order, and insertion is quadratic). */
int boolean_sort_two_keys(const int64_t *k1, const int64_t *k2, size_t stride, size_t n,
                          uint32_t *idx, keyval *scratch, keyval *tmp)
{
    if (n == 0)
        return 1;
    if (n >= PACKED_MIN && n <= 64 && sort_packed(k1, k2, stride, n, idx))
        return 1;
    if (n <= 32) { /* few: straight insertion (stable: ties by index) */
        for (size_t i = 0; i < n; i++) {
            int64_t a1 = key_at(k1, i, stride), a2 = key_at(k2, i, stride);
            size_t j = i;
            for (; j > 0
                   && (key_at(k1, idx[j - 1], stride) > a1
                       || (key_at(k1, idx[j - 1], stride) == a1
                           && key_at(k2, idx[j - 1], stride) > a2));
                 j--)
                idx[j] = idx[j - 1];
            idx[j] = (uint32_t)i;
        }
        return 1;
    }
    if (n >= 64) {
        if (sort_runs(k1, k2, stride, n, idx))
            return 1;
    }
    /* the keys from the least (as few digits as they need) */
    int64_t lo1 = key_at(k1, 0, stride);
    for (size_t i = 0; i < n; i++) {
        int64_t a = key_at(k1, i, stride);
        lo1 = a < lo1 ? a : lo1;
        scratch[i] = (keyval){(uint64_t)a, (uint32_t)i};
    }
    uint64_t all = 0;
    for (size_t i = 0; i < n; i++) {
        scratch[i].key -= (uint64_t)lo1;
        all |= scratch[i].key;
    }
    /* (tried when k1 leaves k2 six bits or more: else the look at k2's
     * spread is mostly wasted) */
    int combined = all < ((uint64_t)1 << (COMBINED_BITS - 6))
                       ? sort_combined(k2, stride, n, scratch, tmp, all)
                       : -1;
    if (combined >= 0) {
        for (size_t i = 0; combined && i < n; i++)
            idx[i] = scratch[i].val;
        return combined;
    }
    if (!radix_sort_all(scratch, n, tmp, all))
        return 0;
    for (size_t i = 0; i < n;) {
        size_t j = i + 1;
        while (j < n && scratch[j].key == scratch[i].key)
            j++;
        /* a long run that needs many moves (on coarse grids, hundreds of
         * pieces in no order on one scanline) is radix sorted instead, while
         * one in order or nearly (a grid of squares) stays cheap */
        if (j - i > RADIX_RUN) {
            if (!insert_by_k2(k2, stride, scratch + i, j - i, j - i)
                && !radix_by_k2(k2, stride, scratch + i, j - i, tmp ? tmp + i : NULL))
                return 0;
        } else if (j - i > 1) {
            insert_by_k2(k2, stride, scratch + i, j - i, SIZE_MAX);
        }
        i = j;
    }
    for (size_t i = 0; i < n; i++)
        idx[i] = scratch[i].val;
    return 1;
}

/* qsort, by straight insertion when n is small (the assembly's rings and
 * holes, a hot-pixel cell's points, an edge's split points; cmp is a total
 * order, so the result is qsort's) */
void boolean_sort_few(void *base, size_t n, size_t size, int (*cmp)(const void *, const void *))
{
    unsigned char v[64], *a = base;
    if (n > 16 || size > sizeof v) {
        core_sort(base, n, size, cmp);
        return;
    }
    for (size_t i = 1; i < n; i++) {
        size_t j = i;
        memcpy(v, a + i * size, size);
        for (; j > 0 && cmp(a + (j - 1) * size, v) > 0; j--)
            memcpy(a + j * size, a + (j - 1) * size, size);
        if (j != i)
            memcpy(a + j * size, v, size);
    }
}
