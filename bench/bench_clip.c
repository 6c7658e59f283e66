/* Boolean operations: cg_clip_boolean64 against Clipper 6.4 and GEOS on the
 * same integer polygons (random star-shaped polygons of 10 to 100,000
 * vertices, spiky ones, smooth ellipses, many small squares against a circle, a plate
 * with holes), with the result areas side by side. */
#include "bench.h"
#include "bench_rings.h"
#include "bench_clip_peers.h"
#include "cg/clip.h"

#include <math.h>
#include <string.h>

typedef struct shape {
    cg_polygon_set64 set;
    int64_t *xy;
    size_t *len;
} shape;

static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;
static double rnd(void)
{
    return bench_random(&rng_state);
}

static void add_ring(shape *s, const cg_point64 *p, size_t n, int new_polygon)
{
    cg_polygon_set64_add_ring(&s->set, p, n, new_polygon);
}

static void finish(shape *s)
{
    bench_rings_flatten(&s->set, &s->xy, &s->len);
}

static void star(shape *s, size_t n, double cx, double cy, double r0, double r1)
{
    cg_point64 *p = malloc(n * sizeof *p);
    for (size_t i = 0; i < n; i++) {
        double a = 2 * M_PI * ((double)i + 0.8 * rnd()) / (double)n, r = r0 + (r1 - r0) * rnd();
        p[i] = (cg_point64){(int64_t)llround(cx + r * cos(a)), (int64_t)llround(cy + r * sin(a))};
    }
    add_ring(s, p, n, 1);
    free(p);
}

static void ellipse(shape *s, size_t n, double cx, double cy, double rx, double ry, double rot,
                    int cw)
{
    cg_point64 *p = malloc(n * sizeof *p);
    for (size_t i = 0; i < n; i++) {
        double a = 2 * M_PI * (double)(cw ? n - i : i) / (double)n;
        double x = rx * cos(a), y = ry * sin(a);
        p[i] = (cg_point64){(int64_t)llround(cx + x * cos(rot) - y * sin(rot)),
                            (int64_t)llround(cy + x * sin(rot) + y * cos(rot))};
    }
    add_ring(s, p, n, cw ? 0 : 1);
    free(p);
}

static void square(shape *s, int64_t x, int64_t y, int64_t side, int cw)
{
    cg_point64 p[4] = {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
    if (cw) {
        cg_point64 t = p[1];
        p[1] = p[3];
        p[3] = t;
    }
    add_ring(s, p, 4, !cw);
}

/* One timed unit: the operation on each of `pairs` pairs of shapes (a[k],
 * b[k]); small cases take many pairs, so that a sample is long against the
 * clock's own cost and one lucky or unlucky pair does not decide the row. */
typedef struct job {
    const shape *a, *b;
    size_t pairs;
    int op;
    cg_polygon_set64 result;
    void **peer;
    double area; /* the sum over the pairs */
} job;

static void run_cg(void *c)
{
    job *j = c;
    for (size_t k = 0; k < j->pairs; k++)
        cg_clip_boolean64((cg_clip_op)j->op, &j->a[k].set, CG_CLIP_NON_ZERO, &j->b[k].set,
                          CG_CLIP_NON_ZERO, &j->result);
}
static void run_clipper(void *c)
{
    job *j = c;
    j->area = 0;
    for (size_t k = 0; k < j->pairs; k++)
        j->area += peer_clipper_run(j->peer[k], j->op);
}
static void run_geos(void *c)
{
    job *j = c;
    j->area = 0;
    for (size_t k = 0; k < j->pairs; k++)
        j->area += peer_geos_run(j->peer[k], j->op);
}

static peer_input input_of(const shape *s)
{
    return (peer_input){s->xy, s->len, s->set.ring_count};
}

typedef struct peer {
    const char *name, *missing;
    int (*available)(void);
    void *(*prepare)(const peer_input *, const peer_input *);
    void (*run)(void *);
    void (*release)(void *);
    int runs;
} peer;

static const char *op_name[4] = {"intersection", "union", "difference", "xor"};

/* Profiling mode (for valgrind --tool=callgrind): --only cg|clipper|geos runs
 * one library alone, once per case, and --match TEXT keeps the cases whose
 * name contains TEXT. */
static const char *only, *match;
/* --cold: no untimed call before the timed ones (see compare) */
static int cold;

static void prepare_all(job *j, void *(*prepare)(const peer_input *, const peer_input *))
{
    j->peer = malloc(j->pairs * sizeof *j->peer);
    for (size_t k = 0; k < j->pairs; k++) {
        peer_input pa = input_of(&j->a[k]), pb = input_of(&j->b[k]);
        j->peer[k] = prepare(&pa, &pb);
    }
}

static void release_all(job *j, void (*release)(void *))
{
    for (size_t k = 0; k < j->pairs; k++)
        release(j->peer[k]);
    free(j->peer);
    j->peer = NULL;
}

/* cg's result over all pairs: the summed area and vertex count (untimed) */
static double cg_area(job *j, size_t *vertices)
{
    double area = 0;
    *vertices = 0;
    for (size_t k = 0; k < j->pairs; k++) {
        cg_clip_boolean64((cg_clip_op)j->op, &j->a[k].set, CG_CLIP_NON_ZERO, &j->b[k].set,
                          CG_CLIP_NON_ZERO, &j->result);
        area += cg_polygon_set64_area(&j->result);
        *vertices += j->result.point_count;
    }
    cg_polygon_set64_clear(&j->result);
    return area;
}

static void profile_one(const char *name, const shape *a, const shape *b, size_t pairs, int op)
{
    job j = {a, b, pairs, op, {0}, NULL, 0};
    double area = 0;
    if (!strcmp(only, "cg")) {
        run_cg(&j);
        cg_polygon_set64_clear(&j.result);
        size_t nv;
        area = cg_area(&j, &nv);
    } else if (!strcmp(only, "clipper") && peer_clipper_available()) {
        prepare_all(&j, peer_clipper_prepare);
        run_clipper(&j);
        release_all(&j, peer_clipper_free);
        area = j.area;
    } else if (!strcmp(only, "geos") && peer_geos_available()) {
        prepare_all(&j, peer_geos_prepare);
        run_geos(&j);
        release_all(&j, peer_geos_free);
        area = j.area;
    } else {
        fprintf(stderr, "bench_clip: --only %s: unknown or not installed\n", only);
        exit(2);
    }
    fprintf(stderr, "%-56s %s area %.6e\n", name, only, area);
}

/* Times are medians of processor time (steadier than wall time on a shared
 * machine; every library here is single-threaded), after one untimed call of
 * each library on the case (unless --cold): the first calls of a process on
 * a large case measure the C library's heap growing, not the operation.
 * glibc maps a large block afresh (page faults) until one such is freed, then
 * takes the next ones from its heap, which grows (page faults again) on the
 * second call; from the third call on the memory is reused.  Without the
 * warm-up, a median of 3 calls is one of the first two, and a peer timed
 * after cg finds the heap grown already. */
static void compare_pairs(const char *what, const shape *a, const shape *b, size_t pairs, int op,
                          int runs)
{
    char name[128], note[160];
    snprintf(name, sizeof name, "clip %s: %s", op_name[op], what);
    if (match && !strstr(name, match))
        return;
    if (only) {
        profile_one(name, a, b, pairs, op);
        return;
    }
    job j = {a, b, pairs, op, {0}, NULL, 0};
    /* (a case timed once takes seconds: its heap growth is noise) */
    int warm = !cold && runs > 1;
    if (warm)
        run_cg(&j);
    double t_cg = bench_median_clock(run_cg, &j, runs, CLOCK_PROCESS_CPUTIME_ID) / (double)pairs;
    cg_polygon_set64_clear(&j.result);
    size_t nv;
    double area_cg = cg_area(&j, &nv);
    const peer peers[2] = {
        {"Clipper 6.4", "Clipper (libpolyclipping-dev) not installed", peer_clipper_available,
         peer_clipper_prepare, run_clipper, peer_clipper_free, runs},
        {"GEOS", "GEOS (libgeos-dev) not installed", peer_geos_available, peer_geos_prepare,
         run_geos, peer_geos_free, runs > 3 ? 3 : runs},
    };
    for (int k = 0; k < 2; k++) {
        const peer *p = &peers[k];
        if (!p->available()) {
            bench_row(name, t_cg, "-", 0, p->missing);
            continue;
        }
        prepare_all(&j, p->prepare);
        if (warm)
            p->run(&j);
        double t = bench_median_clock(p->run, &j, p->runs, CLOCK_PROCESS_CPUTIME_ID)
                   / (double)pairs;
        snprintf(note, sizeof note, "area cg %.6e, %s %.6e (diff %.1e); %zu result vertices",
                 area_cg, p->name, j.area, fabs(area_cg - j.area) / fmax(1, fabs(j.area)), nv);
        bench_row(name, t_cg, p->name, t, note);
        release_all(&j, p->release);
    }
}

static void compare(const char *what, const shape *a, const shape *b, int op, int runs)
{
    compare_pairs(what, a, b, 1, op, runs);
}

static void free_shape(shape *s)
{
    cg_polygon_set64_clear(&s->set);
    free(s->xy);
    free(s->len);
}

/* All four operations on the shapes a and b (made ready here), which are
 * freed after. */
static void compare_four_and_free(const char *what, shape *a, shape *b)
{
    finish(a);
    finish(b);
    for (int op = 0; op < 4; op++)
        compare(what, a, b, op, 5);
    free_shape(a);
    free_shape(b);
}

/* Pairs of star-shaped polygons of n vertices, the second shifted; below
 * 1,000 vertices, 1,000 / n pairs of different polygons (the time is per
 * pair, the areas and result vertices are summed over the pairs). */
static void star_case(size_t n, double r0, const char *label, int ops, int runs)
{
    size_t pairs = n < 1000 ? 1000 / n : 1;
    shape *a = calloc(pairs, sizeof *a), *b = calloc(pairs, sizeof *b);
    for (size_t k = 0; k < pairs; k++) {
        star(&a[k], n, 0, 0, r0, 1e6);
        star(&b[k], n, 3e5, 2e5, r0, 1e6);
        finish(&a[k]);
        finish(&b[k]);
    }
    char what[96];
    if (pairs > 1)
        snprintf(what, sizeof what, "%s, %zu vertices each, %zu pairs", label, n, pairs);
    else
        snprintf(what, sizeof what, "%s, %zu vertices each", label, n);
    for (int op = 0; op < ops; op++)
        compare_pairs(what, a, b, pairs, op, runs);
    for (size_t k = 0; k < pairs; k++) {
        free_shape(&a[k]);
        free_shape(&b[k]);
    }
    free(a);
    free(b);
}

int main(int argc, char **argv)
{
    /* bench_clip [--cold] [--only cg|clipper|geos] [--match TEXT] [MAX_N [MIN_N]]:
     * sizes of the size sweeps */
    while (argc > 1 && !strcmp(argv[1], "--cold")) {
        cold = 1;
        argc--;
        argv++;
    }
    while (argc > 2 && (!strcmp(argv[1], "--only") || !strcmp(argv[1], "--match"))) {
        if (!strcmp(argv[1], "--only"))
            only = argv[2];
        else
            match = argv[2];
        argc -= 2;
        argv += 2;
    }
    size_t max_n = argc > 1 ? (size_t)atol(argv[1]) : 100000;
    size_t min_n = argc > 2 ? (size_t)atol(argv[2]) : 10;
    /* random star-shaped polygons: vertex k at angle 2 pi (k + jitter) / n,
     * radius uniform in [0.9, 1] x 10^6.  The boundaries cross about n^2 / 10^5
     * times (5,951 result rings at 20,000 vertices), so the output itself grows
     * quadratically: at 100,000 vertices a call takes seconds (Clipper about
     * 20 s), timed once, two operations. */
    for (size_t n = 10; n <= max_n && n <= 100000; n *= 10)
        if (n >= min_n)
            star_case(n, 9e5, "random polygons", n <= 1000 ? 4 : 2,
                      n <= 100     ? 15
                      : n <= 1000  ? 7
                      : n <= 10000 ? 3
                                   : 1);
    /* spiky: radius uniform in [0.5, 1]: a scanline meets a third of the edges */
    for (size_t n = 10; n <= max_n && n <= 1000; n *= 10)
        if (n >= min_n)
            star_case(n, 5e5, "spiky random polygons", 4, n <= 100 ? 15 : 5);
    for (size_t n = 100; n <= max_n; n *= 10) {
        if (n < min_n)
            continue;
        shape a = {0}, b = {0};
        ellipse(&a, n, 0, 0, 1e6, 6e5, 0, 0);
        ellipse(&b, n, 2e5, 1e5, 1e6, 5e5, 0.7, 0);
        finish(&a);
        finish(&b);
        char what[64];
        snprintf(what, sizeof what, "ellipses, %zu vertices each", n);
        compare(what, &a, &b, 0, n <= 10000 ? 5 : 3);
        compare(what, &a, &b, 1, n <= 10000 ? 5 : 3);
        free_shape(&a);
        free_shape(&b);
    }
    {
        /* a coarse grid: spiky stars of 2,000 vertices with radii 10 to 128
         * units, so that many vertices coincide and many edges overlap or
         * are collinear (the degenerate cases a sweep must sort out) */
        shape a = {0}, b = {0};
        star(&a, 2000, 128, 128, 10, 128);
        star(&b, 2000, 140, 120, 10, 128);
        compare_four_and_free("spiky stars on a 256-unit grid, 2,000 vertices each", &a, &b);
    }
    {
        /* a layout: 60 x 60 small squares against a disc of 2,000 vertices */
        shape a = {0}, b = {0};
        for (int i = 0; i < 60; i++)
            for (int k = 0; k < 60; k++)
                square(&a, i * 10000, k * 10000, 7000, 0);
        ellipse(&b, 2000, 300000, 300000, 280000, 280000, 0, 0);
        compare_four_and_free("3,600 squares and a disc", &a, &b);
    }
    {
        /* a plate with 400 round holes against a rotated plate */
        shape a = {0}, b = {0};
        cg_point64 plate[4] = {{0, 0}, {2000000, 0}, {2000000, 2000000}, {0, 2000000}};
        add_ring(&a, plate, 4, 1);
        for (int i = 0; i < 20; i++)
            for (int k = 0; k < 20; k++)
                ellipse(&a, 32, 50000 + i * 100000, 50000 + k * 100000, 30000, 30000, 0, 1);
        ellipse(&b, 4, 1000000, 1000000, 1200000, 1200000, 0.3, 0);
        compare_four_and_free("plate with 400 holes and a square", &a, &b);
    }
    return 0;
}
