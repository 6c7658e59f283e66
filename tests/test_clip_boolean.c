/* Boolean operations (cg_clip_boolean64 / cg_clip_boolean) against their
 * definition: a point is in the result exactly when the operation of the two
 * operands' fill rules says so; results are simple, oriented and nested;
 * areas obey the set identities; bad input gets a status. */
#include "cg/clip.h"
#include "check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

__extension__ typedef __int128 i128;

static int fill_rule(cg_clip_fill f, long w)
{
    switch (f) {
    case CG_CLIP_EVEN_ODD: return (int)(w & 1);
    case CG_CLIP_NON_ZERO: return w != 0;
    case CG_CLIP_POSITIVE: return w > 0;
    default: return w < 0;
    }
}

/* winding number of the paths of set around (px, py), a point on no edge */
static long winding(const cg_polygon_set64 *set, double px, double py)
{
    long w = 0;
    for (size_t r = 0; set && r < set->ring_count; r++) {
        size_t a = set->ring_start[r], b = set->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_point64 p = set->points[i], q = set->points[i + 1 < b ? i + 1 : a];
            if ((p.y <= py) != (q.y <= py)) {
                double x = p.x + (py - p.y) * (double)(q.x - p.x) / (double)(q.y - p.y);
                if (x < px)
                    w += q.y > p.y ? -1 : 1;
            }
        }
    }
    return w;
}

static double seg_dist(double px, double py, cg_point64 a, cg_point64 b)
{
    double dx = (double)(b.x - a.x), dy = (double)(b.y - a.y);
    double l = dx * dx + dy * dy, t = 0;
    if (l > 0)
        t = ((px - a.x) * dx + (py - a.y) * dy) / l;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double ex = a.x + t * dx - px, ey = a.y + t * dy - py;
    return sqrt(ex * ex + ey * ey);
}

static double dist_to_set(const cg_polygon_set64 *set, double px, double py)
{
    double d = INFINITY;
    for (size_t r = 0; set && r < set->ring_count; r++) {
        size_t a = set->ring_start[r], b = set->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            double e = seg_dist(px, py, set->points[i], set->points[i + 1 < b ? i + 1 : a]);
            if (e < d)
                d = e;
        }
    }
    return d;
}

static int inside_op(cg_clip_op op, int a, int b)
{
    switch (op) {
    case CG_CLIP_INTERSECTION: return a && b;
    case CG_CLIP_UNION: return a || b;
    case CG_CLIP_DIFFERENCE: return a && !b;
    default: return a != b;
    }
}

static int orient(cg_point64 a, cg_point64 b, cg_point64 c)
{
    i128 v = (i128)(b.x - a.x) * (c.y - a.y) - (i128)(b.y - a.y) * (c.x - a.x);
    return (v > 0) - (v < 0);
}

/* Do the segments a0-a1 and b0-b1 cross, or overlap along a length? */
static int segments_conflict(cg_point64 a0, cg_point64 a1, cg_point64 b0, cg_point64 b1)
{
    int o1 = orient(a0, a1, b0), o2 = orient(a0, a1, b1);
    int o3 = orient(b0, b1, a0), o4 = orient(b0, b1, a1);
    if (o1 * o2 < 0 && o3 * o4 < 0)
        return 1; /* proper crossing */
    if (o1 != 0 || o2 != 0)
        return 0;
    /* collinear: overlap of positive length? project on the dominant axis */
    int ax = llabs(a1.x - a0.x) >= llabs(a1.y - a0.y);
    int64_t p0 = ax ? a0.x : a0.y, p1 = ax ? a1.x : a1.y;
    int64_t q0 = ax ? b0.x : b0.y, q1 = ax ? b1.x : b1.y;
    int64_t lo = (p0 < p1 ? p0 : p1) > (q0 < q1 ? q0 : q1) ? (p0 < p1 ? p0 : p1)
                                                           : (q0 < q1 ? q0 : q1);
    int64_t hi = (p0 > p1 ? p0 : p1) < (q0 > q1 ? q0 : q1) ? (p0 > p1 ? p0 : p1)
                                                           : (q0 > q1 ? q0 : q1);
    return hi > lo;
}

/* the result's edges, as two arrays of ends; NULL-free even when empty */
static size_t result_edges(const cg_polygon_set64 *r, cg_point64 **A, cg_point64 **B)
{
    size_t n = r->point_count, m = 0;
    *A = malloc((n ? n : 1) * sizeof **A);
    *B = malloc((n ? n : 1) * sizeof **B);
    for (size_t k = 0; k < r->ring_count; k++) {
        size_t a = r->ring_start[k], b = r->ring_start[k + 1];
        for (size_t i = a; i < b; i++) {
            (*A)[m] = r->points[i];
            (*B)[m] = r->points[i + 1 < b ? i + 1 : a];
            m++;
        }
    }
    return m;
}

/* The result's edges: no two cross or overlap (they may meet at points). */
static int result_is_simple(const cg_polygon_set64 *r)
{
    cg_point64 *A, *B;
    size_t m = result_edges(r, &A, &B);
    int ok = 1;
    for (size_t i = 0; i < m && ok; i++) {
        if (A[i].x == B[i].x && A[i].y == B[i].y)
            ok = 0;
        for (size_t j = i + 1; j < m && ok; j++)
            ok = !segments_conflict(A[i], B[i], A[j], B[j]);
    }
    free(A);
    free(B);
    return ok;
}

/* result_is_simple for results of many edges: each edge is noted in the
 * cells of a grid that its bounding box covers, and the pairs sharing a
 * cell are checked */
typedef struct cell_edge {
    size_t cell, edge;
} cell_edge;

static int cmp_cell_edge(const void *a, const void *b)
{
    const cell_edge *p = a, *q = b;
    if (p->cell != q->cell)
        return p->cell < q->cell ? -1 : 1;
    return (p->edge > q->edge) - (p->edge < q->edge);
}

static int large_result_is_simple(const cg_polygon_set64 *r)
{
    cg_point64 *A, *B;
    size_t m = result_edges(r, &A, &B);
    int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
    for (size_t i = 0; i < m; i++) {
        x0 = A[i].x < x0 ? A[i].x : x0;
        y0 = A[i].y < y0 ? A[i].y : y0;
        x1 = A[i].x > x1 ? A[i].x : x1;
        y1 = A[i].y > y1 ? A[i].y : y1;
    }
    int64_t side = m ? (int64_t)sqrt((double)(x1 - x0 + 1) * (double)(y1 - y0 + 1) / (double)m) + 1
                     : 1;
    size_t cols = m ? (size_t)((x1 - x0) / side) + 1 : 1, n = 0, cap = 4 * m + 16;
    cell_edge *ce = malloc(cap * sizeof *ce);
    int ok = 1;
    for (size_t i = 0; i < m && ok; i++) {
        if (A[i].x == B[i].x && A[i].y == B[i].y)
            ok = 0;
        size_t c0 = (size_t)(((A[i].x < B[i].x ? A[i].x : B[i].x) - x0) / side);
        size_t c1 = (size_t)(((A[i].x < B[i].x ? B[i].x : A[i].x) - x0) / side);
        size_t r0 = (size_t)(((A[i].y < B[i].y ? A[i].y : B[i].y) - y0) / side);
        size_t r1 = (size_t)(((A[i].y < B[i].y ? B[i].y : A[i].y) - y0) / side);
        for (size_t rr = r0; rr <= r1; rr++)
            for (size_t cc = c0; cc <= c1; cc++) {
                if (n == cap)
                    ce = realloc(ce, (cap *= 2) * sizeof *ce);
                ce[n++] = (cell_edge){rr * cols + cc, i};
            }
    }
    qsort(ce, n, sizeof *ce, cmp_cell_edge);
    for (size_t i = 0; i < n && ok; i++)
        for (size_t j = i + 1; j < n && ce[j].cell == ce[i].cell && ok; j++)
            ok = !segments_conflict(A[ce[i].edge], B[ce[i].edge], A[ce[j].edge], B[ce[j].edge]);
    free(ce);
    free(A);
    free(B);
    return ok;
}

static i128 ring_area2(const cg_polygon_set64 *r, size_t k)
{
    i128 s = 0;
    size_t a = r->ring_start[k], b = r->ring_start[k + 1];
    for (size_t i = a; i < b; i++) {
        cg_point64 p = r->points[i], q = r->points[i + 1 < b ? i + 1 : a];
        s += (i128)p.x * q.y - (i128)q.x * p.y;
    }
    return s;
}

/* outer rings counter-clockwise, holes clockwise and inside their outer */
static int result_is_oriented(const cg_polygon_set64 *r)
{
    for (size_t p = 0; p < r->polygon_count; p++) {
        size_t r0 = r->polygon_start[p], r1 = r->polygon_start[p + 1];
        if (r1 <= r0 || ring_area2(r, r0) <= 0)
            return 0;
        for (size_t h = r0 + 1; h < r1; h++) {
            if (ring_area2(r, h) >= 0)
                return 0;
            /* a hole's edge midpoint is inside its outer ring */
            size_t a = r->ring_start[h];
            double mx = 0.5 * ((double)r->points[a].x + (double)r->points[a + 1].x);
            double my = 0.5 * ((double)r->points[a].y + (double)r->points[a + 1].y);
            cg_polygon_set64 outer = *r;
            outer.ring_count = 1;
            outer.ring_start = r->ring_start + r0;
            if (winding(&outer, mx, my + 1e-3) == 0 && winding(&outer, mx, my - 1e-3) == 0)
                return 0;
        }
    }
    return 1;
}

static void random_ring(check_rng *rng, cg_polygon_set64 *set, int n, int grid, int64_t scale)
{
    cg_point64 pts[64];
    n = n > 64 ? 64 : n;
    for (int i = 0; i < n; i++)
        pts[i] = (cg_point64){check_rng_int(rng, 0, grid) * scale,
                              check_rng_int(rng, 0, grid) * scale};
    cg_polygon_set64_add_ring(set, pts, (size_t)n, 1);
}

static void fixed_cases(void)
{
    cg_point64 A[] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}},
               B[] = {{5, 5}, {15, 5}, {15, 15}, {5, 15}};
    cg_point64 C[] = {{10, 10}, {20, 10}, {20, 20}, {10, 20}};
    cg_polygon_set64 a = {0}, b = {0}, c = {0}, r = {0};
    cg_polygon_set64_add_ring(&a, A, 4, 1);
    cg_polygon_set64_add_ring(&b, B, 4, 1);
    cg_polygon_set64_add_ring(&c, C, 4, 1);
    const double expect[4] = {25, 175, 75, 150};
    for (int op = 0; op < 4; op++) {
        CHECK(cg_clip_boolean64((cg_clip_op)op, &a, CG_CLIP_NON_ZERO, &b, CG_CLIP_NON_ZERO, &r)
              == CG_OK);
        CHECK_NEAR(cg_polygon_set64_area(&r), expect[op], 0);
    }
    /* xor of overlapping squares: two L shapes touching at two corners */
    CHECK_EQ_INT(r.polygon_count, 2);
    /* squares touching at a corner stay two polygons */
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &a, CG_CLIP_NON_ZERO, &c, CG_CLIP_NON_ZERO, &r)
          == CG_OK);
    CHECK_EQ_INT(r.polygon_count, 2);
    CHECK_NEAR(cg_polygon_set64_area(&r), 200, 0);
    /* a bow tie under even-odd: two triangles */
    cg_point64 T[] = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
    cg_polygon_set64 t = {0};
    cg_polygon_set64_add_ring(&t, T, 4, 1);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &t, CG_CLIP_EVEN_ODD, NULL, CG_CLIP_EVEN_ODD, &r)
          == CG_OK);
    CHECK_EQ_INT(r.polygon_count, 2);
    CHECK_NEAR(cg_polygon_set64_area(&r), 50, 0);
    /* two slivers under a unit wide that cross near (45, 13): rounding keeps
     * them (exact area 23.73; found by the fuzz target when all four edges
     * were snapped through that point and the result came out empty) */
    cg_point64 S[] = {{0, 35}, {51, 10}, {3, 38}, {50, 10}};
    cg_polygon_set64 sl = {0};
    cg_polygon_set64_add_ring(&sl, S, 4, 1);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &sl, CG_CLIP_NON_ZERO, NULL, CG_CLIP_EVEN_ODD, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set64_area(&r), 23.73, 2);
    cg_polygon_set64_clear(&sl);
    /* a clockwise bow tie half: positive keeps only the counter-clockwise lobe */
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &t, CG_CLIP_POSITIVE, NULL, CG_CLIP_EVEN_ODD, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set64_area(&r), 25, 0);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &t, CG_CLIP_NEGATIVE, NULL, CG_CLIP_EVEN_ODD, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set64_area(&r), 25, 0);
    /* a hole: outer counter-clockwise, inner clockwise */
    cg_point64 H[] = {{2, 2}, {2, 8}, {8, 8}, {8, 2}};
    cg_polygon_set64_add_ring(&a, H, 4, 0);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &a, CG_CLIP_NON_ZERO, NULL, CG_CLIP_NON_ZERO, &r)
          == CG_OK);
    CHECK_EQ_INT(r.polygon_count, 1);
    CHECK_EQ_INT(r.ring_count, 2);
    CHECK_NEAR(cg_polygon_set64_area(&r), 64, 0);
    CHECK(result_is_oriented(&r));
    /* the same square twice: non-zero sees winding 2, even-odd nothing */
    cg_polygon_set64 d = {0};
    cg_polygon_set64_add_ring(&d, A, 4, 1);
    cg_polygon_set64_add_ring(&d, A, 4, 1);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &d, CG_CLIP_EVEN_ODD, NULL, CG_CLIP_EVEN_ODD, &r)
          == CG_OK);
    CHECK_EQ_INT(r.ring_count, 0);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &d, CG_CLIP_NON_ZERO, NULL, CG_CLIP_EVEN_ODD, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set64_area(&r), 100, 0);
    /* empty, a point, collinear points: empty results, no error */
    cg_polygon_set64 e = {0};
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &e, CG_CLIP_NON_ZERO, &e, CG_CLIP_NON_ZERO, &r)
          == CG_OK);
    CHECK_EQ_INT(r.ring_count, 0);
    cg_point64 P[] = {{3, 3}}, L[] = {{0, 0}, {5, 5}, {10, 10}};
    cg_polygon_set64_add_ring(&e, P, 1, 1);
    cg_polygon_set64_add_ring(&e, L, 3, 1);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &e, CG_CLIP_NON_ZERO, &b, CG_CLIP_NON_ZERO, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set64_area(&r), 100, 0);
    /* only rings without points (so no point array): empty, no error (found
     * by fuzz_clip_boolean) */
    cg_polygon_set64 z = {0};
    cg_polygon_set64_add_ring(&z, NULL, 0, 1);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &z, CG_CLIP_NON_ZERO, &b, CG_CLIP_NON_ZERO, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set64_area(&r), 100, 0);
    CHECK(cg_clip_boolean64(CG_CLIP_INTERSECTION, &b, CG_CLIP_NON_ZERO, &z, CG_CLIP_EVEN_ODD, &r)
          == CG_OK);
    CHECK_EQ_INT(r.ring_count, 0);
    cg_polygon_set zd = {0}, rd = {0};
    cg_polygon_set_add_ring(&zd, NULL, 0, 1);
    CHECK(cg_clip_boolean(CG_CLIP_UNION, &zd, CG_CLIP_NON_ZERO, &zd, CG_CLIP_NON_ZERO, 0, &rd)
          == CG_OK);
    CHECK_EQ_INT(rd.ring_count, 0);
    cg_polygon_set64_clear(&z);
    cg_polygon_set_clear(&zd);
    cg_polygon_set_clear(&rd);
    /* out of range */
    cg_point64 Big[] = {{0, 0}, {CG_CLIP_MAX_COORD + 1, 0}, {0, 5}};
    cg_polygon_set64 big = {0};
    cg_polygon_set64_add_ring(&big, Big, 3, 1);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &big, CG_CLIP_NON_ZERO, NULL, CG_CLIP_NON_ZERO, &r)
          == CG_ERANGE);
    CHECK_EQ_INT(r.ring_count, 0);
    /* the extreme corners of the range are fine */
    cg_point64 Max[] = {{-CG_CLIP_MAX_COORD, -CG_CLIP_MAX_COORD},
                        {CG_CLIP_MAX_COORD, -CG_CLIP_MAX_COORD},
                        {-CG_CLIP_MAX_COORD, CG_CLIP_MAX_COORD},
                        {CG_CLIP_MAX_COORD, CG_CLIP_MAX_COORD}};
    cg_polygon_set64 mx = {0};
    cg_polygon_set64_add_ring(&mx, Max, 4, 1);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &mx, CG_CLIP_EVEN_ODD, NULL, CG_CLIP_NON_ZERO, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set64_area(&r),
               2.0 * (double)CG_CLIP_MAX_COORD * (double)CG_CLIP_MAX_COORD,
               1e-6 * (double)CG_CLIP_MAX_COORD * (double)CG_CLIP_MAX_COORD);
    CHECK(result_is_simple(&r));
    CHECK(cg_clip_boolean64((cg_clip_op)9, &a, CG_CLIP_NON_ZERO, NULL, CG_CLIP_NON_ZERO, &r)
          == CG_EINVAL);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &a, (cg_clip_fill)7, NULL, CG_CLIP_NON_ZERO, &r)
          == CG_EINVAL);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &a, CG_CLIP_NON_ZERO, NULL, CG_CLIP_NON_ZERO, NULL)
          == CG_EINVAL);
    cg_polygon_set64_clear(&a);
    cg_polygon_set64_clear(&b);
    cg_polygon_set64_clear(&c);
    cg_polygon_set64_clear(&d);
    cg_polygon_set64_clear(&e);
    cg_polygon_set64_clear(&t);
    cg_polygon_set64_clear(&r);
    cg_polygon_set64_clear(&big);
    cg_polygon_set64_clear(&mx);
}

static void double_api(void)
{
    cg_vec2 A[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
            B[] = {{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};
    cg_polygon_set a = {0}, b = {0}, r = {0};
    cg_polygon_set_add_ring(&a, A, 4, 1);
    cg_polygon_set_add_ring(&b, B, 4, 1);
    CHECK(cg_clip_boolean(CG_CLIP_INTERSECTION, &a, CG_CLIP_NON_ZERO, &b, CG_CLIP_NON_ZERO, 0, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set_area(&r), 0.25, 1e-12);
    CHECK(cg_clip_boolean(CG_CLIP_UNION, &a, CG_CLIP_NON_ZERO, &b, CG_CLIP_NON_ZERO, 1000, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set_area(&r), 1.75, 1e-12);
    /* tiny and huge coordinates with the automatic scale */
    for (int k = -200; k <= 200; k += 50) {
        double s = ldexp(1.0, k);
        cg_vec2 As[4], Bs[4];
        for (int i = 0; i < 4; i++) {
            As[i] = cg_vec2_scale(A[i], s);
            Bs[i] = cg_vec2_scale(B[i], s);
        }
        cg_polygon_set as = {0}, bs = {0};
        cg_polygon_set_add_ring(&as, As, 4, 1);
        cg_polygon_set_add_ring(&bs, Bs, 4, 1);
        CHECK(cg_clip_boolean(CG_CLIP_XOR, &as, CG_CLIP_NON_ZERO, &bs, CG_CLIP_NON_ZERO, 0, &r)
              == CG_OK);
        CHECK_NEAR(cg_polygon_set_area(&r) / (s * s), 1.5, 1e-9);
        cg_polygon_set_clear(&as);
        cg_polygon_set_clear(&bs);
    }
    /* the smallest normal numbers: a finite scale, no error */
    {
        cg_vec2 T[3] = {{0, 0}, {1e-300, 0}, {0, 1e-300}};
        cg_polygon_set t = {0};
        cg_polygon_set_add_ring(&t, T, 3, 1);
        CHECK(cg_clip_boolean(CG_CLIP_UNION, &t, CG_CLIP_NON_ZERO, NULL, CG_CLIP_NON_ZERO, 0, &r)
              == CG_OK);
        /* (the area itself underflows: check the vertices) */
        CHECK_EQ_INT(r.point_count, 3);
        double big = 0;
        for (size_t i = 0; i < r.point_count; i++)
            big = fmax(big, fmax(r.points[i].x, r.points[i].y));
        CHECK_NEAR(big / 1e-300, 1, 1e-10);
        cg_polygon_set_clear(&t);
    }
    /* NaN, infinity, out of range with an explicit scale */
    cg_vec2 N[] = {{0, 0}, {NAN, 0}, {1, 1}}, I[] = {{0, 0}, {INFINITY, 0}, {1, 1}},
            Bg[] = {{0, 0}, {1e300, 0}, {1, 1}};
    cg_polygon_set n = {0}, i = {0}, bg = {0};
    cg_polygon_set_add_ring(&n, N, 3, 1);
    cg_polygon_set_add_ring(&i, I, 3, 1);
    cg_polygon_set_add_ring(&bg, Bg, 3, 1);
    CHECK(cg_clip_boolean(CG_CLIP_UNION, &n, CG_CLIP_NON_ZERO, &a, CG_CLIP_NON_ZERO, 0, &r)
          == CG_EINVAL);
    CHECK(cg_clip_boolean(CG_CLIP_UNION, &a, CG_CLIP_NON_ZERO, &i, CG_CLIP_NON_ZERO, 0, &r)
          == CG_EINVAL);
    CHECK(cg_clip_boolean(CG_CLIP_UNION, &bg, CG_CLIP_NON_ZERO, &a, CG_CLIP_NON_ZERO, 1e6, &r)
          == CG_ERANGE);
    CHECK(cg_clip_boolean(CG_CLIP_UNION, &a, CG_CLIP_NON_ZERO, &b, CG_CLIP_NON_ZERO, NAN, &r)
          == CG_EINVAL);
    CHECK_EQ_INT(r.ring_count, 0);
    /* with the automatic scale a huge coordinate is fine */
    CHECK(cg_clip_boolean(CG_CLIP_UNION, &bg, CG_CLIP_NON_ZERO, NULL, CG_CLIP_NON_ZERO, 0, &r)
          == CG_OK);
    cg_polygon_set_clear(&a);
    cg_polygon_set_clear(&b);
    cg_polygon_set_clear(&n);
    cg_polygon_set_clear(&i);
    cg_polygon_set_clear(&bg);
    cg_polygon_set_clear(&r);
}

/* All four operations on a and b: status, simple, oriented and nested
 * results; with `samples`, that many random points away from the input
 * edges per operation are in the result exactly when the definition says
 * so; with tol > 0, the area identities within tol. */
static void check_round(const char *tag, int it, const cg_polygon_set64 *a, cg_clip_fill fa,
                        const cg_polygon_set64 *b, cg_clip_fill fb, check_rng *rng, int grid,
                        int64_t scale, int samples, double tol, long *membership_checks)
{
    cg_polygon_set64 r[4] = {{0}};
    for (int op = 0; op < 4; op++) {
        cg_status st = cg_clip_boolean64((cg_clip_op)op, a, fa, b, fb, &r[op]);
        CHECK_MSG(st == CG_OK, "%s %d op %d: status %d", tag, it, op, (int)st);
        CHECK_MSG(result_is_simple(&r[op]), "%s %d op %d: result edges cross", tag, it, op);
        CHECK_MSG(result_is_oriented(&r[op]), "%s %d op %d: orientation or nesting", tag, it, op);
        for (int s = 0; s < samples; s++) {
            double px = check_rng_range(rng, -0.5, grid + 0.5) * (double)scale;
            double py = check_rng_range(rng, -0.5, grid + 0.5) * (double)scale;
            if (dist_to_set(a, px, py) < 3 || dist_to_set(b, px, py) < 3)
                continue;
            int want = inside_op((cg_clip_op)op, fill_rule(fa, winding(a, px, py)),
                                 fill_rule(fb, winding(b, px, py)));
            int got = (int)(winding(&r[op], px, py) & 1);
            (*membership_checks)++;
            CHECK_MSG(want == got, "%s %d op %d: point (%.2f, %.2f) in result %d, expected %d", tag,
                      it, op, px, py, got, want);
        }
    }
    if (tol > 0) {
        double I = cg_polygon_set64_area(&r[0]), U = cg_polygon_set64_area(&r[1]);
        double D = cg_polygon_set64_area(&r[2]), X = cg_polygon_set64_area(&r[3]);
        cg_polygon_set64 ra = {0}, rb = {0};
        cg_clip_boolean64(CG_CLIP_UNION, a, fa, NULL, fa, &ra);
        cg_clip_boolean64(CG_CLIP_UNION, b, fb, NULL, fb, &rb);
        double A = cg_polygon_set64_area(&ra), B = cg_polygon_set64_area(&rb);
        CHECK_MSG(fabs(U - (A + B - I)) <= tol, "%s %d: |AuB| %.0f, |A|+|B|-|AnB| %.0f", tag, it, U,
                  A + B - I);
        CHECK_MSG(fabs(X - (U - I)) <= tol, "%s %d: xor %.0f, union-intersection %.0f", tag, it, X,
                  U - I);
        CHECK_MSG(fabs(D - (A - I)) <= tol, "%s %d: difference %.0f, |A|-|AnB| %.0f", tag, it, D,
                  A - I);
        cg_polygon_set64_clear(&ra);
        cg_polygon_set64_clear(&rb);
    }
    for (int op = 0; op < 4; op++)
        cg_polygon_set64_clear(&r[op]);
}

/* Random polygons on coarse grids (many shared vertices, coincident and
 * touching edges, self-intersections), all four operations, all fill rules. */
static void fuzz(void)
{
    check_rng rng = {0x5eed1234abcdULL};
    const int rounds = 1000;
    long membership_checks = 0;
    for (int it = 0; it < rounds; it++) {
        int grid = it % 3 == 0 ? 4 : it % 3 == 1 ? 8 : 50;
        int64_t scale = it % 2 ? 64 : 1024;
        cg_polygon_set64 a = {0}, b = {0};
        int na = (int)check_rng_int(&rng, 1, 2), nb = (int)check_rng_int(&rng, 1, 2);
        for (int k = 0; k < na; k++)
            random_ring(&rng, &a, (int)check_rng_int(&rng, 3, it % 5 ? 10 : 40), grid, scale);
        for (int k = 0; k < nb; k++)
            random_ring(&rng, &b, (int)check_rng_int(&rng, 3, 10), grid, scale);
        cg_clip_fill fa = (cg_clip_fill)check_rng_int(&rng, 0, 3),
                     fb = (cg_clip_fill)check_rng_int(&rng, 0, 3);
        /* rounding moves each crossing by under a unit: the identities
         * allow a little per edge */
        check_round("round", it, &a, fa, &b, fb, &rng, grid, scale, 12, 40.0 * (double)scale * grid,
                    &membership_checks);
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
    }
    printf("fuzz: %d rounds, %ld membership checks\n", rounds, membership_checks);
}

/* Many vertices, random everywhere: heavy self-intersection. */
static void stress(void)
{
    check_rng rng = {77};
    for (int it = 0; it < 6; it++) {
        cg_polygon_set64 a = {0}, b = {0}, r = {0};
        cg_point64 pts[64];
        for (int i = 0; i < 60; i++)
            pts[i] = (cg_point64){check_rng_int(&rng, -1000000, 1000000),
                                  check_rng_int(&rng, -1000000, 1000000)};
        cg_polygon_set64_add_ring(&a, pts, 60, 1);
        for (int i = 0; i < 60; i++)
            pts[i] = (cg_point64){check_rng_int(&rng, -1000000, 1000000),
                                  check_rng_int(&rng, -1000000, 1000000)};
        cg_polygon_set64_add_ring(&b, pts, 60, 1);
        for (int op = 0; op < 4; op++) {
            CHECK(cg_clip_boolean64((cg_clip_op)op, &a, CG_CLIP_EVEN_ODD, &b, CG_CLIP_NON_ZERO, &r)
                  == CG_OK);
            CHECK(result_is_simple(&r));
            CHECK(result_is_oriented(&r));
        }
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
        cg_polygon_set64_clear(&r);
    }
}

/* Crowded inputs: long random paths whose scanlines cross many edges (the
 * passes after the first then take the light sweep, which only looks at
 * the points where edges start and end), on coarse grids (shared vertices,
 * coincident edges, crossings exactly on vertices) and unscaled ones (every
 * crossing rounded). */
static void crowded(void)
{
    check_rng rng = {0xc0ffee};
    long membership_checks = 0;
    for (int it = 0; it < 80; it++) {
        int grid = it % 4 == 0 ? 12 : it % 4 == 1 ? 40 : 400;
        int64_t scale = it % 2 ? 1 : 16;
        cg_polygon_set64 a = {0}, b = {0};
        random_ring(&rng, &a, (int)check_rng_int(&rng, 30, 64), grid, scale);
        random_ring(&rng, &a, (int)check_rng_int(&rng, 3, 64), grid, scale);
        random_ring(&rng, &b, (int)check_rng_int(&rng, 30, 64), grid, scale);
        cg_clip_fill fa = (cg_clip_fill)check_rng_int(&rng, 0, 3),
                     fb = (cg_clip_fill)check_rng_int(&rng, 0, 3);
        double tol = 4.0 * (double)(a.point_count + b.point_count) * (double)scale * grid;
        check_round("crowded round", it, &a, fa, &b, fb, &rng, grid, scale, scale > 1 ? 30 : 0,
                    scale > 1 ? tol : 0, &membership_checks);
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
    }
    printf("crowded: 80 rounds, %ld membership checks\n", membership_checks);
}

/* Unscaled tiny grids: every crossing is rounded, edges collapse onto each
 * other; results must still be simple and well nested. */
static void snapping(void)
{
    check_rng rng = {4242};
    for (int it = 0; it < 1500; it++) {
        cg_polygon_set64 a = {0}, b = {0}, r = {0};
        int grid = (int)check_rng_int(&rng, 2, 7);
        random_ring(&rng, &a, (int)check_rng_int(&rng, 3, 30), grid, 1);
        random_ring(&rng, &b, (int)check_rng_int(&rng, 3, 30), grid, 1);
        if (it % 2)
            random_ring(&rng, &b, (int)check_rng_int(&rng, 3, 12), grid, 1);
        cg_clip_fill fa = (cg_clip_fill)check_rng_int(&rng, 0, 3),
                     fb = (cg_clip_fill)check_rng_int(&rng, 0, 3);
        for (int op = 0; op < 4; op++) {
            cg_status st = cg_clip_boolean64((cg_clip_op)op, &a, fa, &b, fb, &r);
            CHECK_MSG(st == CG_OK, "snap round %d op %d: status %d", it, op, (int)st);
            CHECK_MSG(result_is_simple(&r), "snap round %d op %d: result edges cross", it, op);
            CHECK_MSG(result_is_oriented(&r), "snap round %d op %d: orientation or nesting", it,
                      op);
        }
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
        cg_polygon_set64_clear(&r);
    }
}

/* Coordinates at the edge of the range (the 128-bit products at their
 * largest) and many copies of one ring (huge groups of coincident edges). */
static void extremes(void)
{
    check_rng rng = {31};
    const int64_t M = CG_CLIP_MAX_COORD;
    for (int it = 0; it < 300; it++) {
        cg_polygon_set64 a = {0}, b = {0}, r = {0};
        cg_point64 pts[12];
        int n = (int)check_rng_int(&rng, 3, 12);
        for (int i = 0; i < n; i++)
            pts[i] = (cg_point64){check_rng_int(&rng, 0, 1) ? M - check_rng_int(&rng, 0, 3)
                                                            : -M + check_rng_int(&rng, 0, 3),
                                  check_rng_int(&rng, -M, M)};
        cg_polygon_set64_add_ring(&a, pts, (size_t)n, 1);
        for (int i = 0; i < n; i++)
            pts[i] = (cg_point64){check_rng_int(&rng, -M, M), check_rng_int(&rng, -M, M)};
        cg_polygon_set64_add_ring(&b, pts, (size_t)n, 1);
        for (int op = 0; op < 4; op++) {
            cg_status st = cg_clip_boolean64((cg_clip_op)op, &a, CG_CLIP_EVEN_ODD, &b,
                                             CG_CLIP_NON_ZERO, &r);
            CHECK_MSG(st == CG_OK, "extreme round %d op %d: status %d", it, op, (int)st);
            CHECK(result_is_simple(&r));
            CHECK(result_is_oriented(&r));
            double A = cg_polygon_set64_area(&r);
            CHECK(A >= 0 && A <= 4.0 * (double)M * (double)M * (1 + 1e-12));
        }
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
        cg_polygon_set64_clear(&r);
    }
    /* fans of nearly vertical edges (x within 3 units, y over the whole
     * range): rounding a crossing moves such edges a lot along their length,
     * the case that needs snap rounding through hot pixels to settle */
    for (int it = 0; it < 100; it++) {
        cg_polygon_set64 a = {0}, b = {0}, r = {0};
        cg_point64 pts[30];
        for (int k = 0; k < 2; k++) {
            for (int i = 0; i < 30; i++)
                pts[i] = (cg_point64){check_rng_int(&rng, -3, 3), check_rng_int(&rng, -M, M)};
            cg_polygon_set64_add_ring(k ? &b : &a, pts, 30, 1);
        }
        for (int op = 0; op < 4; op++) {
            cg_status st = cg_clip_boolean64((cg_clip_op)op, &a, CG_CLIP_EVEN_ODD, &b,
                                             CG_CLIP_NON_ZERO, &r);
            CHECK_MSG(st == CG_OK, "fan round %d op %d: status %d", it, op, (int)st);
            CHECK(result_is_simple(&r));
            CHECK(result_is_oriented(&r));
        }
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
        cg_polygon_set64_clear(&r);
    }
    /* 2,000 copies of one square and one of a shifted square */
    cg_polygon_set64 a = {0}, b = {0}, r = {0};
    cg_point64 S[4] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}},
               T[4] = {{50, 50}, {150, 50}, {150, 150}, {50, 150}};
    for (int i = 0; i < 2000; i++)
        cg_polygon_set64_add_ring(&a, S, 4, 1);
    cg_polygon_set64_add_ring(&b, T, 4, 1);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &a, CG_CLIP_EVEN_ODD, &b, CG_CLIP_NON_ZERO, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set64_area(&r), 10000, 0); /* even count: a is empty */
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, &a, CG_CLIP_POSITIVE, &b, CG_CLIP_NON_ZERO, &r)
          == CG_OK);
    CHECK_NEAR(cg_polygon_set64_area(&r), 17500, 0);
    CHECK_EQ_INT(r.ring_count, 1);
    cg_polygon_set64_clear(&a);
    cg_polygon_set64_clear(&b);
    cg_polygon_set64_clear(&r);
}

/* A smooth ring: n vertices on an ellipse (centre, radii, turned by rot,
 * clockwise when cw), radius jitter up to `jitter`. */
static void smooth_ring(check_rng *rng, cg_polygon_set64 *set, int n, double cx, double cy,
                        double rx, double ry, double rot, int cw, double jitter)
{
    cg_point64 *pts = malloc((size_t)n * sizeof *pts);
    for (int i = 0; i < n; i++) {
        double t = 2 * M_PI * i / n * (cw ? -1 : 1), j = 1 - check_rng_range(rng, 0, jitter);
        double x = rx * j * cos(t), y = ry * j * sin(t);
        pts[i] = (cg_point64){(int64_t)llround(cx + x * cos(rot) - y * sin(rot)),
                              (int64_t)llround(cy + x * sin(rot) + y * cos(rot))};
    }
    cg_polygon_set64_add_ring(set, pts, (size_t)n, 1);
    free(pts);
}

/* Smooth shapes of over 1,024 edges that cross a few times, some with
 * holes: the first pass checkpoints its state and the second sweeps only
 * the y ranges of the split edges, taking the first pass's results
 * between them. */
static void smooth(void)
{
    check_rng rng = {0x5300};
    long membership_checks = 0;
    for (int it = 0; it < 16; it++) {
        cg_polygon_set64 a = {0}, b = {0};
        int n = (int)check_rng_int(&rng, 600, 1500);
        double jitter = it % 4 == 3 ? 0.02 : 0;
        smooth_ring(&rng, &a, n, 500000, 500000, 450000, check_rng_range(&rng, 150000, 450000),
                    check_rng_range(&rng, 0, 3), 0, jitter);
        if (it % 2) /* holes in a */
            for (int h = 0; h < 6; h++)
                smooth_ring(&rng, &a, 24, 250000 + 100000 * h, 500000, 30000, 30000, 0, 1, 0);
        smooth_ring(&rng, &b, n, check_rng_range(&rng, 400000, 600000),
                    check_rng_range(&rng, 400000, 600000), 450000,
                    check_rng_range(&rng, 150000, 450000), check_rng_range(&rng, 0, 3), 0, jitter);
        cg_clip_fill fa = (cg_clip_fill)check_rng_int(&rng, 0, 1),
                     fb = (cg_clip_fill)check_rng_int(&rng, 0, 1);
        check_round("smooth round", it, &a, fa, &b, fb, &rng, 1000, 1000, 40,
                    4.0 * (double)(a.point_count + b.point_count) * 1000, &membership_checks);
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
    }
    printf("smooth: 16 rounds, %ld membership checks\n", membership_checks);
}

/* A walk of 1,480 short steps (-3..3) on 0..4096, the generator of
 * fuzz_clip_boolean: a pass resumed at a checkpoint with no active edge
 * (no checkpoint edge logged) offset a null pointer (UBSan). */
static void checkpoint_without_edges(void)
{
    cg_point64 *pts = malloc(1480 * sizeof *pts);
    uint64_t s = 0xff;
    int64_t x = 2048, y = 2048;
    for (int i = 0; i < 1480; i++) {
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        x += (int64_t)(s % 7) - 3;
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        y += (int64_t)(s % 7) - 3;
        x = x < 0 ? 0 : x > 4096 ? 4096 : x;
        y = y < 0 ? 0 : y > 4096 ? 4096 : y;
        pts[i].x = x;
        pts[i].y = y;
    }
    cg_polygon_set64 a = {0}, e = {0};
    cg_polygon_set64_add_ring(&a, pts, 1480, 1);
    long checks = 0;
    check_rng rng = {11};
    check_round("walk", 0, &a, CG_CLIP_EVEN_ODD, &e, CG_CLIP_EVEN_ODD, &rng, 4096, 1, 64, 8 * 1480,
                &checks);
    cg_polygon_set64_clear(&a);
    free(pts);
}

static double perimeter(const cg_polygon_set64 *r)
{
    double sum = 0;
    for (size_t k = 0; k < r->ring_count; k++) {
        size_t a = r->ring_start[k], b = r->ring_start[k + 1];
        for (size_t i = a; i < b; i++) {
            cg_point64 p = r->points[i], q = r->points[i + 1 < b ? i + 1 : a];
            sum += hypot((double)(q.x - p.x), (double)(q.y - p.y));
        }
    }
    return sum;
}

/* The four operations on large inputs a and b within [0, extent]^2: results
 * simple by a grid of cells, rings oriented (outers counter-clockwise, holes
 * clockwise), membership at sample points, and the area identities. */
static void check_large_round(const char *tag, int it, const cg_polygon_set64 *a, cg_clip_fill fa,
                              const cg_polygon_set64 *b, cg_clip_fill fb, check_rng *rng,
                              double extent, long *membership_checks)
{
    cg_polygon_set64 r[4] = {{0}};
    for (int op = 0; op < 4; op++) {
        CHECK(cg_clip_boolean64((cg_clip_op)op, a, fa, b, fb, &r[op]) == CG_OK);
        CHECK_MSG(large_result_is_simple(&r[op]), "%s %d op %d: result edges cross", tag, it, op);
        int oriented = 1;
        for (size_t p = 0; p < r[op].polygon_count; p++)
            for (size_t k = r[op].polygon_start[p]; k < r[op].polygon_start[p + 1]; k++)
                oriented &= k == r[op].polygon_start[p] ? ring_area2(&r[op], k) > 0
                                                        : ring_area2(&r[op], k) < 0;
        CHECK_MSG(oriented, "%s %d op %d: ring orientation", tag, it, op);
        for (int q = 0; q < 25; q++) {
            double px = check_rng_range(rng, 0, extent), py = check_rng_range(rng, 0, extent);
            if (dist_to_set(a, px, py) < 3 || dist_to_set(b, px, py) < 3)
                continue;
            int want = inside_op((cg_clip_op)op, fill_rule(fa, winding(a, px, py)),
                                 fill_rule(fb, winding(b, px, py)));
            CHECK_MSG(want == (int)(winding(&r[op], px, py) & 1), "%s %d op %d: point (%.1f, %.1f)",
                      tag, it, op, px, py);
            (*membership_checks)++;
        }
    }
    /* rounding moves each edge by under a unit: the identities hold
     * within a unit-wide band along every result edge */
    cg_polygon_set64 ra = {0}, rb = {0};
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, a, fa, NULL, fa, &ra) == CG_OK);
    CHECK(cg_clip_boolean64(CG_CLIP_UNION, b, fb, NULL, fb, &rb) == CG_OK);
    double A = cg_polygon_set64_area(&ra), B = cg_polygon_set64_area(&rb);
    double I = cg_polygon_set64_area(&r[0]), U = cg_polygon_set64_area(&r[1]);
    double D = cg_polygon_set64_area(&r[2]), X = cg_polygon_set64_area(&r[3]);
    double tol = 0;
    const cg_polygon_set64 *all[6] = {&r[0], &r[1], &r[2], &r[3], &ra, &rb};
    for (int k = 0; k < 6; k++)
        tol += perimeter(all[k]);
    CHECK_NEAR(U, A + B - I, tol);
    CHECK_NEAR(X, U - I, tol);
    CHECK_NEAR(D, A - I, tol);
    cg_polygon_set64_clear(&ra);
    cg_polygon_set64_clear(&rb);
    for (int op = 0; op < 4; op++)
        cg_polygon_set64_clear(&r[op]);
}

/* Long random rings whose boundaries cross hundreds of thousands of times:
 * the first pass looks at hundreds of active edges per edge, so it snaps to
 * every hot pixel (the edges' ends too) before the verifying pass. */
static void dense(void)
{
    check_rng rng = {0xde45e};
    long membership_checks = 0;
    for (int it = 0; it < 2; it++) {
        cg_polygon_set64 a = {0}, b = {0};
        cg_point64 *pts = malloc(600 * sizeof *pts);
        int n = it ? 600 : 450;
        for (int k = 0; k < 2; k++) {
            for (int i = 0; i < n; i++)
                pts[i] = (cg_point64){check_rng_int(&rng, 0, 999999),
                                      check_rng_int(&rng, 0, 999999)};
            cg_polygon_set64_add_ring(k ? &b : &a, pts, (size_t)n, 1);
        }
        free(pts);
        cg_clip_fill fa = it ? CG_CLIP_EVEN_ODD : CG_CLIP_NON_ZERO, fb = CG_CLIP_NON_ZERO;
        check_large_round("dense", it, &a, fa, &b, fb, &rng, 1e6, &membership_checks);
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
    }
    printf("dense: 2 rounds, %ld membership checks\n", membership_checks);
}

/* A random star-shaped ring of n vertices around (cx, cy): vertex i at
 * angle 2 pi (i + jitter) / n, its radius uniform in [r0, r1]. */
static void random_star(check_rng *rng, cg_polygon_set64 *set, int n, double cx, double cy,
                        double r0, double r1)
{
    cg_point64 *pts = malloc((size_t)n * sizeof *pts);
    for (int i = 0; i < n; i++) {
        double t = 2 * M_PI * (i + 0.8 * check_rng_range(rng, 0, 1)) / n;
        double r = check_rng_range(rng, r0, r1);
        pts[i] = (cg_point64){llround(cx + r * cos(t)), llround(cy + r * sin(t))};
    }
    cg_polygon_set64_add_ring(set, pts, (size_t)n, 1);
    free(pts);
}

/* Spiky stars on coarse grids (radii from a twelfth of R to R, R = 32 to
 * 2,048 units): thousands of crossings among a few hundred scanlines, so
 * that many vertices coincide and snapped edges coincide, cross a third
 * edge exactly on a scanline, or pass through one point in groups (the
 * sweep holds such coincident groups back from rounding unless some other
 * edge meets them there). */
static void coarse_stars(void)
{
    check_rng rng = {0xc0a75e};
    long membership_checks = 0;
    const double radius[4] = {32, 128, 512, 2048};
    for (int it = 0; it < 8; it++) {
        double R = radius[it % 4];
        int n = it < 4 ? 300 : 800;
        cg_polygon_set64 a = {0}, b = {0};
        random_star(&rng, &a, n, R, R, R / 12, R);
        random_star(&rng, &b, n, 1.09 * R, 0.94 * R, R / 12, R);
        cg_clip_fill fa = it & 1 ? CG_CLIP_EVEN_ODD : CG_CLIP_NON_ZERO, fb = CG_CLIP_NON_ZERO;
        check_large_round("coarse stars", it, &a, fa, &b, fb, &rng, 2.2 * R, &membership_checks);
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
    }
    printf("coarse stars: 8 rounds, %ld membership checks\n", membership_checks);
}

/* Random self-intersecting polygons of 120-400 vertices on grids of 8 to
 * 256 units: their crossings are denser than the grid's cells, so the
 * operations snap every edge to every hot pixel it passes through at once
 * (complete snap rounding), where edges meet at pixel corners, run along
 * pixel sides and coincide by the hundred.  In a third of the rounds a small
 * square lies 2^20 units away (the hot pixels are then kept in a hash set,
 * not a bitmap of the bounds), in another third 2^35 (the bounds too wide
 * for either: the cells of the hot-pixel grid). */
static void dense_grids(void)
{
    check_rng rng = {0xd3e5e};
    long membership_checks = 0;
    for (int it = 0; it < 24; it++) {
        double extent = ldexp(8, it % 6);
        cg_polygon_set64 set[2] = {{0}};
        for (int k = 0; k < 2; k++) {
            int n = 120 + (int)check_rng_range(&rng, 0, 280);
            cg_point64 *pts = malloc((size_t)n * sizeof *pts);
            for (int i = 0; i < n; i++)
                pts[i] = (cg_point64){llround(check_rng_range(&rng, 0, extent)),
                                      llround(check_rng_range(&rng, 0, extent))};
            cg_polygon_set64_add_ring(&set[k], pts, (size_t)n, 1);
            free(pts);
        }
        if (it % 3) {
            int64_t far = (int64_t)1 << (it % 3 == 1 ? 20 : 35);
            cg_point64 sq[4] = {{far, far}, {far + 3, far}, {far + 3, far + 3}, {far, far + 3}};
            cg_polygon_set64_add_ring(&set[1], sq, 4, 1);
        }
        cg_clip_fill fa = (cg_clip_fill)(it % 4), fb = (cg_clip_fill)((it / 4) % 4);
        check_large_round("dense grids", it, &set[0], fa, &set[1], fb, &rng, extent,
                          &membership_checks);
        cg_polygon_set64_clear(&set[0]);
        cg_polygon_set64_clear(&set[1]);
    }
    printf("dense grids: 24 rounds, %ld membership checks\n", membership_checks);
}

/* same points, rings and polygons */
static int same_set64(const cg_polygon_set64 *a, const cg_polygon_set64 *b)
{
    if (a->point_count != b->point_count || a->ring_count != b->ring_count
        || a->polygon_count != b->polygon_count)
        return 0;
    if (a->point_count && memcmp(a->points, b->points, a->point_count * sizeof *a->points))
        return 0;
    if (a->ring_count
        && memcmp(a->ring_start, b->ring_start, (a->ring_count + 1) * sizeof *a->ring_start))
        return 0;
    return !a->polygon_count
           || !memcmp(a->polygon_start, b->polygon_start,
                      (a->polygon_count + 1) * sizeof *a->polygon_start);
}

/* A result passed again and again (its arrays reused, of a larger result
 * before) and a result that is one of the operands give what a fresh
 * result gets, for every operation; so does the double API with a result
 * that is an operand. */
static void result_reuse(void)
{
    check_rng rng = {0x2e05e};
    cg_polygon_set64 kept = {0};
    for (int it = 0; it < 300; it++) {
        cg_polygon_set64 a = {0}, b = {0};
        int grid = it % 2 ? 12 : 1000;
        random_ring(&rng, &a, (int)check_rng_int(&rng, 3, it % 7 ? 12 : 60), grid, 1);
        random_ring(&rng, &b, (int)check_rng_int(&rng, 3, 12), grid, 1);
        for (int op = 0; op < 4; op++) {
            cg_polygon_set64 fresh = {0}, as_a = {0}, as_b = {0};
            CHECK(cg_clip_boolean64((cg_clip_op)op, &a, CG_CLIP_EVEN_ODD, &b, CG_CLIP_NON_ZERO,
                                    &fresh)
                  == CG_OK);
            CHECK(
                cg_clip_boolean64((cg_clip_op)op, &a, CG_CLIP_EVEN_ODD, &b, CG_CLIP_NON_ZERO, &kept)
                == CG_OK);
            CHECK_MSG(same_set64(&kept, &fresh), "reuse %d op %d: reused result differs", it, op);
            cg_polygon_set64_add_ring(&as_a, a.points, a.point_count, 1);
            cg_polygon_set64_add_ring(&as_b, b.points, b.point_count, 1);
            CHECK(cg_clip_boolean64((cg_clip_op)op, &as_a, CG_CLIP_EVEN_ODD, &b, CG_CLIP_NON_ZERO,
                                    &as_a)
                  == CG_OK);
            CHECK(cg_clip_boolean64((cg_clip_op)op, &a, CG_CLIP_EVEN_ODD, &as_b, CG_CLIP_NON_ZERO,
                                    &as_b)
                  == CG_OK);
            CHECK_MSG(same_set64(&as_a, &fresh) && same_set64(&as_b, &fresh),
                      "reuse %d op %d: result as an operand differs", it, op);
            cg_polygon_set64_clear(&fresh);
            cg_polygon_set64_clear(&as_a);
            cg_polygon_set64_clear(&as_b);
        }
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
    }
    /* a refused call leaves the reused result empty */
    CHECK(cg_clip_boolean64((cg_clip_op)9, NULL, CG_CLIP_NON_ZERO, NULL, CG_CLIP_NON_ZERO, &kept)
          == CG_EINVAL);
    CHECK_EQ_INT(kept.point_count + kept.ring_count + kept.polygon_count, 0);
    cg_polygon_set64_clear(&kept);
    /* the double API */
    cg_vec2 sq[4] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}}, sh[4] = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    cg_polygon_set x = {0}, y = {0}, r = {0};
    cg_polygon_set_add_ring(&x, sq, 4, 1);
    cg_polygon_set_add_ring(&y, sh, 4, 1);
    CHECK(cg_clip_boolean(CG_CLIP_UNION, &x, CG_CLIP_NON_ZERO, &y, CG_CLIP_NON_ZERO, 0, &r)
          == CG_OK);
    CHECK(cg_clip_boolean(CG_CLIP_UNION, &x, CG_CLIP_NON_ZERO, &y, CG_CLIP_NON_ZERO, 0, &x)
          == CG_OK);
    CHECK_EQ_INT(x.point_count, r.point_count);
    CHECK(x.point_count == r.point_count
          && !memcmp(x.points, r.points, r.point_count * sizeof *r.points));
    CHECK_NEAR(cg_polygon_set_area(&x), 7, 1e-12);
    cg_polygon_set_clear(&x);
    cg_polygon_set_clear(&y);
    cg_polygon_set_clear(&r);
}

/* A workspace kept over calls of every size (small inputs on the stack,
 * large ones whose blocks it keeps, growing and shrinking in turn) gives
 * what calls without one give. */
static void workspace(void)
{
    check_rng rng = {0x3095ace};
    cg_clip_workspace *ws = cg_clip_workspace_create();
    CHECK(ws != NULL);
    cg_polygon_set64 r = {0}, plain = {0};
    for (int it = 0; it < 120; it++) {
        cg_polygon_set64 a = {0}, b = {0};
        int n = it % 3 == 0 ? 8 : it % 3 == 1 ? 200 : 1500;
        double grid = it % 4 < 2 ? 1000000 : 300;
        random_star(&rng, &a, n, grid / 2, grid / 2, 0.3 * grid, 0.5 * grid);
        random_star(&rng, &b, n, 0.6 * grid, grid / 2, 0.3 * grid, 0.5 * grid);
        cg_clip_op op = (cg_clip_op)(it % 4);
        CHECK(cg_clip_boolean64_ws(ws, op, &a, CG_CLIP_NON_ZERO, &b, CG_CLIP_EVEN_ODD, &r)
              == CG_OK);
        CHECK(cg_clip_boolean64(op, &a, CG_CLIP_NON_ZERO, &b, CG_CLIP_EVEN_ODD, &plain) == CG_OK);
        CHECK_MSG(same_set64(&r, &plain), "workspace %d: result differs", it);
        if (it % 10 == 0) { /* the result as an operand, with the workspace */
            CHECK(cg_clip_boolean64_ws(ws, op, &a, CG_CLIP_NON_ZERO, &b, CG_CLIP_EVEN_ODD, &a)
                  == CG_OK);
            CHECK_MSG(same_set64(&a, &plain), "workspace %d: result as subject differs", it);
        }
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
    }
    /* the double API through the same workspace */
    cg_vec2 sq[4] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}}, sh[4] = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    cg_polygon_set x = {0}, y = {0}, dr = {0}, dplain = {0};
    cg_polygon_set_add_ring(&x, sq, 4, 1);
    cg_polygon_set_add_ring(&y, sh, 4, 1);
    for (int op = 0; op < 4; op++) {
        CHECK(cg_clip_boolean_ws(ws, (cg_clip_op)op, &x, CG_CLIP_NON_ZERO, &y, CG_CLIP_NON_ZERO, 0,
                                 &dr)
              == CG_OK);
        CHECK(
            cg_clip_boolean((cg_clip_op)op, &x, CG_CLIP_NON_ZERO, &y, CG_CLIP_NON_ZERO, 0, &dplain)
            == CG_OK);
        CHECK(dr.point_count == dplain.point_count
              && !memcmp(dr.points, dplain.points, dr.point_count * sizeof *dr.points));
    }
    cg_polygon_set_clear(&x);
    cg_polygon_set_clear(&y);
    cg_polygon_set_clear(&dr);
    cg_polygon_set_clear(&dplain);
    cg_polygon_set64_clear(&r);
    cg_polygon_set64_clear(&plain);
    cg_clip_workspace_free(ws);
    cg_clip_workspace_free(NULL);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(extremes);
    CHECK_GROUP(snapping);
    CHECK_GROUP(fixed_cases);
    CHECK_GROUP(double_api);
    CHECK_GROUP(fuzz);
    CHECK_GROUP(stress);
    CHECK_GROUP(crowded);
    CHECK_GROUP(smooth);
    CHECK_GROUP(checkpoint_without_edges);
    CHECK_GROUP(dense);
    CHECK_GROUP(coarse_stars);
    CHECK_GROUP(dense_grids);
    CHECK_GROUP(result_reuse);
    CHECK_GROUP(workspace);
    return check_finish();
}
