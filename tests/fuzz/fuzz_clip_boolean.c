/* libFuzzer target: boolean operations on polygon sets (cg_clip_boolean64
 * and the double API cg_clip_boolean).  See README-clip_boolean.md for the
 * input layout.  Per input, for the subject A and the clip B (each of a few
 * rings, mostly on a 0..63 grid):
 *   - every call returns CG_OK, or CG_ERANGE exactly when a coordinate lies
 *     beyond CG_CLIP_MAX_COORD (never an abort, never ERANGE in range);
 *   - a result is well formed: ring and polygon starts in order, rings of at
 *     least 3 points, outer contours counter-clockwise and holes clockwise
 *     (exact integer areas), no repeated or collinear consecutive vertices,
 *     every vertex within one unit of the inputs' bounding box;
 *   - the areas obey the set identities, |A u B| + |A n B| = |A| + |B|,
 *     |A - B| = |A| - |A n B|, |A xor B| = |A u B| - |A n B|, where |A| is
 *     the area of A u {} under A's fill rule, within a rounding tolerance
 *     (each output vertex is within one unit of the exact arrangement);
 *   - on small inputs, sample points more than 2 units from every input and
 *     result edge are in the result exactly when the operation of the two
 *     fill rules says so;
 *   - the same call twice gives the same result, and so does the call
 *     through a workspace kept over all inputs (the engine's blocks left
 *     by earlier inputs of every size);
 *   - (small inputs) the double API with scale 1 gives the integer API's result; with an
 *     automatic scale the same areas; NaN or infinity gives CG_EINVAL. */
#include "cg/clip.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

__extension__ typedef __int128 i128;

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

/* A broken invariant: name the line, then abort (libFuzzer saves the input). */
#define FAIL() fail(__LINE__)
static void fail(int line)
{
    fprintf(stderr, "fuzz_clip_boolean.c:%d: invariant broken\n", line);
    abort();
}

#define MAX_RINGS 4
#define SMALL_MAX 25 /* points of a ring read byte by byte */
#define BIG_MIN 200  /* a generated ring: 200 .. 2000 points */
#define BIG_MAX 2000
#define TOTAL_MAX 2500 /* points of one operand */

typedef struct reader {
    const unsigned char *p;
    size_t n;
} reader;

static unsigned get(reader *r)
{
    if (!r->n)
        return 0;
    r->n--;
    return *r->p++;
}

static int64_t special(unsigned k)
{
    static const int64_t v[8] = {
        CG_CLIP_MAX_COORD, -CG_CLIP_MAX_COORD, CG_CLIP_MAX_COORD + 1,  -CG_CLIP_MAX_COORD - 1,
        INT64_MAX,         INT64_MIN,          ((int64_t)1 << 39) + 7, -3};
    return v[k & 7];
}

static uint64_t xorshift(uint64_t *s)
{
    uint64_t x = *s;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    return *s = x;
}

/* A generated ring of n points: a star (radius wandering around the centre,
 * simple before rounding) or a walk of short steps (self-crossing), on a
 * grid of 64 * k. */
static void big_ring(cg_point64 *pts, size_t n, unsigned kind, uint64_t seed)
{
    uint64_t s = seed | 1;
    int64_t g = (int64_t)64 << (2 * (kind & 3)); /* 64, 256, 1024, 4096 */
    if (kind & 4) {
        int64_t x = g / 2, y = g / 2;
        for (size_t i = 0; i < n; i++) {
            x += (int64_t)(xorshift(&s) % 7) - 3;
            y += (int64_t)(xorshift(&s) % 7) - 3;
            x = x < 0 ? 0 : x > g ? g : x;
            y = y < 0 ? 0 : y > g ? g : y;
            pts[i].x = x;
            pts[i].y = y;
        }
    } else {
        double c = (double)g / 2, turn = (kind & 8) ? -1 : 1, r = 0.6 * c;
        for (size_t i = 0; i < n; i++) {
            double a = turn * 6.283185307179586 * (double)i / (double)n;
            r += c * ((double)(xorshift(&s) % 9) - 4) / 64; /* (no spikes) */
            r = r < 0.2 * c ? 0.2 * c : r > c ? c : r;
            pts[i].x = llround(c + r * cos(a));
            pts[i].y = llround(c + r * sin(a));
        }
    }
}

/* Reads one operand; *out_of_range is set when a coordinate is beyond the
 * documented range. */
static void read_set(reader *r, unsigned rings, unsigned shift, int specials, cg_polygon_set64 *set,
                     int *out_of_range)
{
    cg_point64 pts[BIG_MAX];
    for (unsigned k = 0; k < rings; k++) {
        unsigned h = get(r);
        size_t n;
        if ((h & 0xe0) == 0xe0 && set->point_count + BIG_MIN <= TOTAL_MAX) {
            unsigned high = get(r); /* one call per operand: their order is unspecified */
            n = BIG_MIN + (high << 8 | get(r)) % (BIG_MAX - BIG_MIN + 1);
            if (set->point_count + n > TOTAL_MAX)
                n = TOTAL_MAX - set->point_count;
            uint64_t seed = 0;
            for (int i = 0; i < 4; i++)
                seed = seed << 8 | get(r);
            big_ring(pts, n, h, seed * 0x9e3779b97f4a7c15u + h);
        } else {
            n = h % (SMALL_MAX + 1); /* 0 .. 25, degenerate rings included */
            for (size_t i = 0; i < n; i++) {
                unsigned bx = get(r), by = get(r);
                pts[i].x = specials && bx >= 0xf8 ? special(bx) : (int64_t)(bx & 63) << shift;
                pts[i].y = specials && by >= 0xf8 ? special(by) : (int64_t)(by & 63) << shift;
            }
        }
        for (size_t i = 0; i < n; i++)
            if (pts[i].x > CG_CLIP_MAX_COORD || pts[i].x < -CG_CLIP_MAX_COORD
                || pts[i].y > CG_CLIP_MAX_COORD || pts[i].y < -CG_CLIP_MAX_COORD)
                *out_of_range = 1;
        if (cg_polygon_set64_add_ring(set, pts, n, 1) != CG_OK)
            FAIL();
    }
}

static i128 ring_area2(const cg_polygon_set64 *s, size_t r)
{
    size_t a = s->ring_start[r], b = s->ring_start[r + 1];
    i128 sum = 0;
    for (size_t i = a; i < b; i++) {
        cg_point64 p = s->points[i], q = s->points[i + 1 < b ? i + 1 : a];
        sum += (i128)p.x * q.y - (i128)q.x * p.y;
    }
    return sum;
}

static double set_area(const cg_polygon_set64 *s)
{
    i128 sum = 0;
    for (size_t r = 0; r < s->ring_count; r++)
        sum += ring_area2(s, r);
    return (double)sum / 2;
}

/* How far a result's area may be from the exact arrangement's: each vertex
 * is within one unit of an exact one (a rounded intersection, or an edge
 * bent through a nearby vertex), and moving vertex v by d moves the area by
 * |d x (next - prev)| / 2; plus 1 per vertex.  On an input, the same
 * bounds what vanishes when close edges merge. */
static double slack(const cg_polygon_set64 *s)
{
    double t = 0;
    for (size_t r = 0; r < s->ring_count; r++) {
        size_t a = s->ring_start[r], b = s->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_point64 p = s->points[i > a ? i - 1 : b - 1], q = s->points[i + 1 < b ? i + 1 : a];
            t += 0.5 * hypot((double)q.x - (double)p.x, (double)q.y - (double)p.y) + 1;
        }
    }
    return t;
}

typedef struct box {
    int64_t x0, y0, x1, y1;
} box;

static void grow(box *b, const cg_polygon_set64 *s)
{
    for (size_t i = 0; i < s->point_count; i++) {
        cg_point64 p = s->points[i];
        if (p.x < b->x0)
            b->x0 = p.x;
        if (p.y < b->y0)
            b->y0 = p.y;
        if (p.x > b->x1)
            b->x1 = p.x;
        if (p.y > b->y1)
            b->y1 = p.y;
    }
}

/* The result's structure (see the contract of cg_clip_boolean64). */
static void check_result(const cg_polygon_set64 *s, box bb)
{
    if (s->ring_count == 0) {
        if (s->point_count || s->polygon_count)
            FAIL();
        return;
    }
    if (!s->ring_start || !s->polygon_start || !s->points || s->ring_start[0] != 0
        || s->ring_start[s->ring_count] != s->point_count || s->polygon_start[0] != 0
        || s->polygon_start[s->polygon_count] != s->ring_count)
        FAIL();
    for (size_t p = 0; p < s->polygon_count; p++) {
        if (s->polygon_start[p + 1] <= s->polygon_start[p])
            FAIL();
        for (size_t r = s->polygon_start[p]; r < s->polygon_start[p + 1]; r++) {
            size_t a = s->ring_start[r], b = s->ring_start[r + 1];
            if (b < a + 3)
                FAIL(); /* a ring of fewer than 3 points */
            i128 area = ring_area2(s, r);
            if (r == s->polygon_start[p] ? area <= 0 : area >= 0)
                FAIL(); /* outer not counter-clockwise or hole not clockwise */
            for (size_t i = a; i < b; i++) {
                cg_point64 o = s->points[i > a ? i - 1 : b - 1], m = s->points[i],
                           q = s->points[i + 1 < b ? i + 1 : a];
                if (m.x < bb.x0 - 1 || m.x > bb.x1 + 1 || m.y < bb.y0 - 1 || m.y > bb.y1 + 1)
                    FAIL(); /* a vertex far outside the inputs */
                if ((i128)(m.x - o.x) * (q.y - m.y) - (i128)(m.y - o.y) * (q.x - m.x) == 0)
                    FAIL(); /* repeated or collinear consecutive vertices */
            }
        }
    }
}

static int same64(const cg_polygon_set64 *a, const cg_polygon_set64 *b)
{
    return a->point_count == b->point_count && a->ring_count == b->ring_count
           && a->polygon_count == b->polygon_count
           && (!a->point_count || !memcmp(a->points, b->points, a->point_count * sizeof *a->points))
           && (!a->ring_count
               || (!memcmp(a->ring_start, b->ring_start, (a->ring_count + 1) * sizeof(size_t))
                   && !memcmp(a->polygon_start, b->polygon_start,
                              (a->polygon_count + 1) * sizeof(size_t))));
}

static int rule(cg_clip_fill f, long w)
{
    switch (f) {
    case CG_CLIP_EVEN_ODD: return (int)(w & 1);
    case CG_CLIP_NON_ZERO: return w != 0;
    case CG_CLIP_POSITIVE: return w > 0;
    default: return w < 0;
    }
}

/* Winding number of s around (px, py) (counter-clockwise positive), and
 * whether the point is within 2 units of an edge (*near). */
static long winding(const cg_polygon_set64 *s, double px, double py, int *near)
{
    long w = 0;
    for (size_t r = 0; r < s->ring_count; r++) {
        size_t a = s->ring_start[r], b = s->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_point64 p = s->points[i], q = s->points[i + 1 < b ? i + 1 : a];
            double dx = (double)q.x - (double)p.x, dy = (double)q.y - (double)p.y;
            double ex = px - (double)p.x, ey = py - (double)p.y, l = dx * dx + dy * dy;
            double t = l > 0 ? (ex * dx + ey * dy) / l : 0;
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            double fx = ex - t * dx, fy = ey - t * dy;
            if (fx * fx + fy * fy < 4)
                *near = 1;
            if (((double)p.y <= py) != ((double)q.y <= py)) {
                double x = (double)p.x + (py - (double)p.y) * dx / dy;
                if (x > px)
                    w += q.y > p.y ? 1 : -1;
            }
        }
    }
    return w;
}

static int in_op(cg_clip_op op, int a, int b)
{
    return op == CG_CLIP_INTERSECTION ? a && b
           : op == CG_CLIP_UNION      ? a || b
           : op == CG_CLIP_DIFFERENCE ? a && !b
                                      : a != b;
}

static void check_points(cg_clip_op op, const cg_polygon_set64 *A, cg_clip_fill fa,
                         const cg_polygon_set64 *B, cg_clip_fill fb, const cg_polygon_set64 *R,
                         box bb, uint64_t seed)
{
    uint64_t s = seed | 1;
    double w = (double)(bb.x1 - bb.x0) + 4, h = (double)(bb.y1 - bb.y0) + 4;
    for (int k = 0; k < 16; k++) {
        double px = (double)bb.x0 - 2 + w * (double)(xorshift(&s) % 100003) / 100003.0;
        double py = (double)bb.y0 - 2 + h * (double)(xorshift(&s) % 100019) / 100019.0;
        int near = 0;
        long wa = winding(A, px, py, &near), wb = winding(B, px, py, &near);
        long wr = winding(R, px, py, &near);
        if (near)
            continue;
        /* a result is a set of simple rings, holes clockwise: winding 0 or 1 */
        if (wr != 0 && wr != 1)
            FAIL();
        if (wr != in_op(op, rule(fa, wa), rule(fb, wb)))
            FAIL();
    }
}

static void to_double(const cg_polygon_set64 *in, cg_polygon_set *out)
{
    cg_vec2 *v = malloc((in->point_count + 1) * sizeof *v);
    if (!v)
        FAIL();
    for (size_t r = 0; r < in->ring_count; r++) {
        size_t a = in->ring_start[r], b = in->ring_start[r + 1];
        for (size_t i = a; i < b; i++)
            v[i - a] = cg_vec2_make((double)in->points[i].x, (double)in->points[i].y);
        if (cg_polygon_set_add_ring(out, v, b - a, 1) != CG_OK)
            FAIL();
    }
    free(v);
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    reader rd = {data, size};
    unsigned h0 = get(&rd), h1 = get(&rd), h2 = get(&rd);
    cg_clip_op op = (cg_clip_op)(h0 & 3);
    cg_clip_fill fa = (cg_clip_fill)(h0 >> 2 & 3), fb = (cg_clip_fill)(h0 >> 4 & 3);
    int doubles = h0 >> 6 & 1, specials = h0 >> 7 & 1;
    unsigned na = 1 + (h1 & 3), nb = (h1 >> 2 & 7) % (MAX_RINGS + 1);
    unsigned shift = (h1 & 0x80) ? h2 % 38 : 0; /* up to 63 << 37 > CG_CLIP_MAX_COORD */
    cg_polygon_set64 A = {0}, B = {0}, E = {0}, R[4], R2 = {0}, UA = {0}, UB = {0};
    memset(R, 0, sizeof R);
    int bad = 0;
    read_set(&rd, na, shift, specials, &A, &bad);
    read_set(&rd, nb, shift, specials, &B, &bad);

    cg_status st[4];
    for (int o = 0; o < 4; o++) {
        st[o] = cg_clip_boolean64((cg_clip_op)o, &A, fa, &B, fb, &R[o]);
        if (st[o] != (bad ? CG_ERANGE : CG_OK))
            FAIL();
    }
    cg_status sa = cg_clip_boolean64(CG_CLIP_UNION, &A, fa, &E, fb, &UA);
    cg_status sb = cg_clip_boolean64(CG_CLIP_UNION, &B, fb, NULL, fa, &UB);
    cg_status s2 = cg_clip_boolean64(op, &A, fa, &B, fb, &R2);
    if (s2 != st[op] || !same64(&R2, &R[op]))
        FAIL();                   /* not deterministic */
    static cg_clip_workspace *ws; /* (kept over the inputs; freed at exit) */
    if (!ws)
        ws = cg_clip_workspace_create();
    if (!ws || cg_clip_boolean64_ws(ws, op, &A, fa, &B, fb, &R2) != st[op] || !same64(&R2, &R[op]))
        FAIL(); /* a workspace's blocks changed the result */
    if (!bad) {
        if (sa != CG_OK || sb != CG_OK)
            FAIL();
        box bb = {INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
        grow(&bb, &A);
        grow(&bb, &B);
        if (bb.x0 > bb.x1)
            bb.x0 = bb.y0 = bb.x1 = bb.y1 = 0;
        for (int o = 0; o < 4; o++)
            check_result(&R[o], bb);
        check_result(&UA, bb);
        check_result(&UB, bb);
        double a = set_area(&UA), b = set_area(&UB), u = set_area(&R[CG_CLIP_UNION]),
               i = set_area(&R[CG_CLIP_INTERSECTION]), d = set_area(&R[CG_CLIP_DIFFERENCE]),
               x = set_area(&R[CG_CLIP_XOR]);
        /* (the inputs' too: a sliver between close edges may vanish, with
         * all its vertices) */
        double tol = slack(&A) + slack(&B) + slack(&UA) + slack(&UB);
        for (int o = 0; o < 4; o++)
            tol += slack(&R[o]);
        if (a < 0 || b < 0 || u < 0 || i < 0 || d < 0 || x < 0)
            FAIL();
        if (fabs(u + i - a - b) > tol || fabs(d - (a - i)) > tol || fabs(x - (u - i)) > tol)
            FAIL();
        if (A.point_count + B.point_count <= 100 && shift == 0)
            check_points(op, &A, fa, &B, fb, &R[op], bb, (uint64_t)h0 << 16 | h1 << 8 | h2);

        if (doubles && A.point_count + B.point_count <= 100) {
            cg_polygon_set DA = {0}, DB = {0}, DR = {0}, DR2 = {0};
            to_double(&A, &DA);
            to_double(&B, &DB);
            /* scale 1: the integer result exactly */
            if (cg_clip_boolean(op, &DA, fa, &DB, fb, 1.0, &DR) != CG_OK
                || DR.point_count != R[op].point_count || DR.ring_count != R[op].ring_count
                || DR.polygon_count != R[op].polygon_count)
                FAIL();
            for (size_t k = 0; k < DR.point_count; k++)
                if (DR.points[k].x != (double)R[op].points[k].x
                    || DR.points[k].y != (double)R[op].points[k].y)
                    FAIL();
            /* automatic scale: a finer grid, the same area within the
             * tolerance */
            if (cg_clip_boolean(op, &DA, fa, &DB, fb, 0, &DR2) != CG_OK)
                FAIL();
            for (size_t k = 0; k < DR2.point_count; k++)
                if (!isfinite(DR2.points[k].x) || !isfinite(DR2.points[k].y))
                    FAIL();
            double want = set_area(&R[op]), got = cg_polygon_set_area(&DR2);
            double largest = (double)(bb.x1 > -bb.x0 ? bb.x1 : -bb.x0);
            if ((double)bb.y1 > largest)
                largest = (double)bb.y1;
            if (-(double)bb.y0 > largest)
                largest = -(double)bb.y0;
            int e = 0;
            frexp(largest, &e);
            double unit = e > 36 ? ldexp(1, e - 36) : 1; /* the automatic grid's step */
            if (fabs(got - want) > 2 * tol * unit * unit + 1e-9 * fabs(want))
                FAIL();
            /* NaN or infinity anywhere: CG_EINVAL and an empty result */
            if (DA.point_count) {
                DA.points[h2 % DA.point_count].y = (h2 & 1) ? NAN : -INFINITY;
                if (cg_clip_boolean(op, &DA, fa, &DB, fb, (h2 & 2) ? 1.0 : 0, &DR) != CG_EINVAL
                    || DR.point_count || DR.ring_count)
                    FAIL();
            }
            cg_polygon_set_clear(&DA);
            cg_polygon_set_clear(&DB);
            cg_polygon_set_clear(&DR);
            cg_polygon_set_clear(&DR2);
        }
    } else {
        /* an error leaves every result empty */
        for (int o = 0; o < 4; o++)
            if (R[o].point_count || R[o].ring_count || R[o].polygon_count)
                FAIL();
    }
    for (int o = 0; o < 4; o++)
        cg_polygon_set64_clear(&R[o]);
    cg_polygon_set64_clear(&R2);
    cg_polygon_set64_clear(&UA);
    cg_polygon_set64_clear(&UB);
    cg_polygon_set64_clear(&A);
    cg_polygon_set64_clear(&B);
    return 0;
}
