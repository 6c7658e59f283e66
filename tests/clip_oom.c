/* Boolean operations when memory runs out: every allocation libcg makes in a
 * call is made to fail in turn (the test is linked with the C library's
 * malloc, calloc and realloc wrapped, see clip.cmake).  Each call must give
 * CG_ENOMEM with an empty result, or, when the allocation that failed was
 * one it can do without, CG_OK with the result of the call that had all its
 * memory; never a crash, a leak or a wrong result (the sanitizer build runs
 * it too).  The inputs take each path of the engine: the pairs' splits of
 * small inputs, the iterated snap rounding of a fine grid, and complete snap
 * rounding on a coarse grid with its hot points in a bitmap, in a hash set
 * (a square far away) and in the hot-pixel grid (a square farther still). */
#include "cg/clip.h"
#include "check.h"

#include <string.h>

void *__real_malloc(size_t n);
void *__real_calloc(size_t n, size_t size);
void *__real_realloc(void *p, size_t n);

static long allocations, fail_at = -1; /* (-1: none fails) */

static int fails(void)
{
    allocations++;
    return allocations == fail_at;
}

void *__wrap_malloc(size_t n)
{
    return fails() ? NULL : __real_malloc(n);
}

void *__wrap_calloc(size_t n, size_t size)
{
    return fails() ? NULL : __real_calloc(n, size);
}

void *__wrap_realloc(void *p, size_t n)
{
    return fails() ? NULL : __real_realloc(p, n);
}

static void random_star(check_rng *rng, cg_polygon_set64 *set, int n, double cx, double cy,
                        double r0, double r1)
{
    cg_point64 *pts = __real_malloc((size_t)n * sizeof *pts);
    for (int i = 0; i < n; i++) {
        double t = 2 * M_PI * (i + 0.8 * check_rng_unit(rng)) / n;
        double r = r0 + (r1 - r0) * check_rng_unit(rng);
        pts[i] = (cg_point64){llround(cx + r * cos(t)), llround(cy + r * sin(t))};
    }
    fail_at = -1;
    cg_polygon_set64_add_ring(set, pts, (size_t)n, 1);
    free(pts);
}

static int same_result(const cg_polygon_set64 *a, const cg_polygon_set64 *b)
{
    return a->point_count == b->point_count && a->ring_count == b->ring_count
           && a->polygon_count == b->polygon_count
           && (!a->point_count
               || !memcmp(a->points, b->points, a->point_count * sizeof *a->points));
}

/* every allocation of op(a, b) failed in turn */
static void fail_each(const char *what, const cg_polygon_set64 *a, const cg_polygon_set64 *b)
{
    for (int op = 0; op < 4; op++) {
        cg_polygon_set64 full = {0}, r = {0};
        fail_at = -1;
        allocations = 0;
        CHECK(cg_clip_boolean64((cg_clip_op)op, a, CG_CLIP_NON_ZERO, b, CG_CLIP_NON_ZERO, &full)
              == CG_OK);
        long total = allocations, nomem = 0;
        for (long k = 1; k <= total; k++) {
            allocations = 0;
            fail_at = k;
            cg_status st = cg_clip_boolean64((cg_clip_op)op, a, CG_CLIP_NON_ZERO, b,
                                             CG_CLIP_NON_ZERO, &r);
            fail_at = -1;
            if (st == CG_ENOMEM) {
                nomem++;
                CHECK_MSG(!r.point_count && !r.ring_count && !r.polygon_count,
                          "%s op %d, allocation %ld failed: the result is not empty", what, op, k);
            } else {
                CHECK_MSG(st == CG_OK && same_result(&r, &full),
                          "%s op %d, allocation %ld failed: status %d, or another result", what, op,
                          k, (int)st);
            }
            cg_polygon_set64_clear(&r);
        }
        CHECK_MSG(nomem > 0, "%s op %d: no allocation's failure gave CG_ENOMEM", what, op);
        printf("%s, op %d: %ld allocations, %ld of them failed give CG_ENOMEM\n", what, op, total,
               nomem);
        cg_polygon_set64_clear(&full);
    }
}

int main(void)
{
    check_rng rng = {0x00a110c};
    struct {
        const char *what;
        int n;
        double radius;
        int far; /* a square 2^far units away, or 0 */
    } cases[] = {
        {"small stars (the pairs' splits)", 12, 1e6, 0},
        {"stars on a fine grid (iterated rounding)", 300, 1e6, 0},
        {"stars on a coarse grid (a bitmap)", 400, 128, 0},
        {"stars on a coarse grid, a square 2^20 away (a hash set)", 400, 128, 20},
        {"stars on a coarse grid, a square 2^35 away (the grid of cells)", 400, 128, 35},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        cg_polygon_set64 a = {0}, b = {0};
        double R = cases[c].radius;
        random_star(&rng, &a, cases[c].n, R, R, R / 12.8, R);
        random_star(&rng, &b, cases[c].n, 1.09 * R, 0.94 * R, R / 12.8, R);
        if (cases[c].far) {
            int64_t far = (int64_t)1 << cases[c].far;
            cg_point64 sq[4] = {{far, far}, {far + 3, far}, {far + 3, far + 3}, {far, far + 3}};
            cg_polygon_set64_add_ring(&b, sq, 4, 1);
        }
        fail_each(cases[c].what, &a, &b);
        cg_polygon_set64_clear(&a);
        cg_polygon_set64_clear(&b);
    }
    return check_finish();
}
