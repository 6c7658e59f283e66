/* Simplification against its definition: the result's rings are simple
 * and meet no other edge they did not meet before (no two edges of the
 * result cross or touch, checked exactly over all pairs), no ring is lost
 * or falls below three vertices, every vertex of the input lies within the
 * tolerance of the result's boundary (RDP), the result's vertices are
 * input vertices, and the vertex count falls as the tolerance grows.  The
 * inputs: noisy star "coastlines" with noisy holes, two interleaved combs
 * a tolerance far above their gap (which must not make them touch), and
 * polylines. */
#include "cg/polygon.h"
#include "check.h"

__extension__ typedef __int128 i128;

static uint64_t state = 0x853c49e6748fea9bull;
static double uniform(double lo, double hi)
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return lo + (hi - lo) * (double)(state >> 11) / 9007199254740992.0;
}

static int orient(cg_point64 a, cg_point64 b, cg_point64 c)
{
    i128 d = (i128)(b.x - a.x) * (c.y - a.y) - (i128)(b.y - a.y) * (c.x - a.x);
    return (d > 0) - (d < 0);
}

static int on_segment(cg_point64 a, cg_point64 b, cg_point64 q)
{
    return orient(a, b, q) == 0 && (q.x - a.x) * (q.x - b.x) <= 0 && (q.y - a.y) * (q.y - b.y) <= 0;
}

/* Edges a-b and c-d meet somewhere other than at a shared end. */
static int edges_meet(cg_point64 a, cg_point64 b, cg_point64 c, cg_point64 d)
{
    int shared = (a.x == c.x && a.y == c.y) || (a.x == d.x && a.y == d.y)
                 || (b.x == c.x && b.y == c.y) || (b.x == d.x && b.y == d.y);
    int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0)
        return 1;
    if (shared)
        return (o1 == 0 && o2 == 0); /* overlapping from a shared end */
    return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

/* The number of pairs of edges of s that meet improperly (open: paths). */
static int bad_pairs(const cg_polygon_set64 *s, int open)
{
    int bad = 0;
    for (size_t r = 0; r < s->ring_count; r++)
        for (size_t i = s->ring_start[r]; i < s->ring_start[r + 1] - (open ? 1 : 0); i++) {
            size_t i2 = i + 1 < s->ring_start[r + 1] ? i + 1 : s->ring_start[r];
            for (size_t q = r; q < s->ring_count; q++)
                for (size_t j = q == r ? i + 1 : s->ring_start[q];
                     j < s->ring_start[q + 1] - (open ? 1 : 0); j++) {
                    size_t j2 = j + 1 < s->ring_start[q + 1] ? j + 1 : s->ring_start[q];
                    if (q == r && (j == i2 || j2 == i))
                        continue; /* neighbours on one ring share a vertex */
                    bad += edges_meet(s->points[i], s->points[i2], s->points[j], s->points[j2]);
                }
        }
    return bad;
}

static double distance_to_boundary(const cg_polygon_set64 *s, cg_point64 q, int open)
{
    double best = INFINITY;
    for (size_t r = 0; r < s->ring_count; r++)
        for (size_t i = s->ring_start[r]; i < s->ring_start[r + 1] - (open ? 1 : 0); i++) {
            size_t i2 = i + 1 < s->ring_start[r + 1] ? i + 1 : s->ring_start[r];
            double ax = (double)s->points[i].x, ay = (double)s->points[i].y;
            double dx = (double)s->points[i2].x - ax, dy = (double)s->points[i2].y - ay;
            double l2 = dx * dx + dy * dy,
                   t = l2 > 0 ? ((q.x - ax) * dx + (q.y - ay) * dy) / l2 : 0;
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            best = fmin(best, hypot(ax + t * dx - (double)q.x, ay + t * dy - (double)q.y));
        }
    return best;
}

static void coastline(cg_polygon_set64 *s, int n, double noise)
{
    cg_polygon_set64_clear(s);
    cg_point64 *p = malloc((size_t)n * sizeof *p);
    double phase = uniform(0, 6.28);
    for (int i = 0; i < n; i++) {
        double a = 2 * M_PI * i / n;
        double r = 100000 * (1 + 0.3 * sin(5 * a + phase)) + uniform(-noise, noise);
        p[i] = (cg_point64){llround(r * cos(a)), llround(r * sin(a))};
    }
    cg_polygon_set64_add_ring(s, p, (size_t)n, 1);
    for (int h = 0; h < 3; h++) { /* holes, clockwise, noisy too */
        double cx = uniform(-40000, 40000), cy = uniform(-40000, 40000);
        for (int i = 0; i < 60; i++) {
            double a = -2 * M_PI * i / 60, r = 8000 + uniform(-noise, noise);
            p[i] = (cg_point64){llround(cx + r * cos(a)), llround(cy + r * sin(a))};
        }
        cg_polygon_set64_add_ring(s, p, 60, 1);
    }
    free(p);
}

static void check_result(const char *what, int trial, const cg_polygon_set64 *in,
                         const cg_polygon_set64 *out, int open, double tolerance, int rdp)
{
    cg_polygon_set64 simple = {0}, none = {0};
    if (open)
        for (size_t r = 0; r < in->ring_count; r++)
            cg_polygon_set64_add_ring(&simple, in->points + in->ring_start[r],
                                      in->ring_start[r + 1] - in->ring_start[r], 1);
    else
        cg_clip_boolean64(CG_CLIP_UNION, in, CG_CLIP_EVEN_ODD, &none, CG_CLIP_EVEN_ODD, &simple);
    CHECK_MSG(out->ring_count == simple.ring_count, "%s %d: %zu rings from %zu", what, trial,
              out->ring_count, simple.ring_count);
    int small = 0, foreign = 0;
    for (size_t r = 0; r < out->ring_count; r++)
        small += out->ring_start[r + 1] - out->ring_start[r] < (open ? 2u : 3u);
    for (size_t i = 0; i < out->point_count; i++) {
        int found = 0;
        for (size_t j = 0; j < simple.point_count && !found; j++)
            found = simple.points[j].x == out->points[i].x
                    && simple.points[j].y == out->points[i].y;
        foreign += !found;
    }
    CHECK_MSG(small == 0, "%s %d: %d rings collapsed", what, trial, small);
    CHECK_MSG(foreign == 0, "%s %d: %d vertices not from the input", what, trial, foreign);
    int bad = bad_pairs(out, open);
    CHECK_MSG(bad == 0, "%s %d: %d pairs of edges meet", what, trial, bad);
    if (rdp) {
        double worst = 0;
        for (size_t i = 0; i < simple.point_count; i++)
            worst = fmax(worst, distance_to_boundary(out, simple.points[i], open));
        CHECK_MSG(worst <= tolerance + 1, "%s %d: a vertex %.2f from the result (tolerance %g)",
                  what, trial, worst, tolerance);
    }
    cg_polygon_set64_clear(&simple);
}

static void coastlines(void)
{
    cg_polygon_set64 in = {0}, out = {0};
    for (int trial = 0; trial < 24; trial++) {
        coastline(&in, 400 + 40 * trial, trial % 2 ? 3000 : 300);
        size_t last = (size_t)-1;
        for (int k = 0; k < 4; k++) {
            double tolerance = 100.0 * pow(4, k);
            int rdp = trial % 2 == 0;
            double t = rdp ? tolerance : tolerance * tolerance;
            cg_status st = cg_simplify64(&in, 0, CG_CLIP_EVEN_ODD,
                                         rdp ? CG_SIMPLIFY_RDP : CG_SIMPLIFY_VISVALINGAM, t, &out);
            CHECK(st == CG_OK);
            check_result(rdp ? "rdp" : "visvalingam", trial, &in, &out, 0, tolerance, rdp);
            CHECK(out.point_count <= last);
            last = out.point_count;
        }
    }
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
}

/* Two combs whose teeth interleave 5 units apart: a tolerance of 10,000
 * would flatten each into its spine, crossing the other's teeth. */
static void interleaved_combs(void)
{
    cg_polygon_set64 in = {0}, out = {0};
    cg_point64 a[64], b[64];
    int na = 0, nb = 0;
    a[na++] = (cg_point64){0, -50};
    a[na++] = (cg_point64){400, -50};
    a[na++] = (cg_point64){400, 0};
    for (int k = 9; k >= 0; k--) {
        a[na++] = (cg_point64){40 * k + 15, 0};
        a[na++] = (cg_point64){40 * k + 15, 1000};
        a[na++] = (cg_point64){40 * k + 5, 1000};
        a[na++] = (cg_point64){40 * k + 5, 0};
    }
    a[na++] = (cg_point64){0, 0};
    b[nb++] = (cg_point64){420, 1150};
    b[nb++] = (cg_point64){-20, 1150};
    b[nb++] = (cg_point64){-20, 1100};
    for (int k = 0; k < 10; k++) {
        b[nb++] = (cg_point64){40 * k + 20, 1100};
        b[nb++] = (cg_point64){40 * k + 20, 100};
        b[nb++] = (cg_point64){40 * k + 30, 100};
        b[nb++] = (cg_point64){40 * k + 30, 1100};
    }
    b[nb++] = (cg_point64){420, 1100};
    cg_polygon_set64_add_ring(&in, a, (size_t)na, 1);
    cg_polygon_set64_add_ring(&in, b, (size_t)nb, 1);
    for (int alg = 0; alg < 2; alg++) {
        CHECK(cg_simplify64(&in, 0, CG_CLIP_NON_ZERO, (cg_simplify_algorithm)alg,
                            alg ? 1e12 : 10000, &out)
              == CG_OK);
        check_result("combs", alg, &in, &out, 0, 10000, 0);
    }
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
}

static void polylines(void)
{
    cg_polygon_set64 in = {0}, out = {0};
    for (int trial = 0; trial < 40; trial++) {
        cg_polygon_set64_clear(&in);
        for (int r = 0; r < 3; r++) {
            cg_point64 p[300];
            double y = 3000.0 * r;
            for (int i = 0; i < 300; i++)
                p[i] = (cg_point64){100 * i,
                                    llround(y + 800 * sin(i * 0.05 + r) + uniform(-200, 200))};
            cg_polygon_set64_add_ring(&in, p, 300, 1);
        }
        int rdp = trial % 2 == 0;
        double tolerance = 50.0 * (1 + trial % 5);
        CHECK(cg_simplify64(&in, 1, CG_CLIP_EVEN_ODD,
                            rdp ? CG_SIMPLIFY_RDP : CG_SIMPLIFY_VISVALINGAM,
                            rdp ? tolerance : tolerance * tolerance, &out)
              == CG_OK);
        check_result("polyline", trial, &in, &out, 1, tolerance, rdp);
        for (size_t r = 0; r < out.ring_count; r++) { /* the ends stay */
            CHECK(out.points[out.ring_start[r]].x == 0);
            CHECK(out.points[out.ring_start[r + 1] - 1].x == 29900);
        }
    }
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
}

static void bad_input(void)
{
    cg_polygon_set64 in = {0}, out = {0};
    cg_point64 p[3] = {{0, 0}, {10, 0}, {0, 10}};
    cg_polygon_set64_add_ring(&in, p, 3, 1);
    CHECK(cg_simplify64(&in, 0, CG_CLIP_EVEN_ODD, CG_SIMPLIFY_RDP, -1, &out) == CG_EINVAL);
    CHECK(cg_simplify64(&in, 0, CG_CLIP_EVEN_ODD, CG_SIMPLIFY_RDP, NAN, &out) == CG_EINVAL);
    CHECK(cg_simplify64(&in, 0, CG_CLIP_EVEN_ODD, (cg_simplify_algorithm)4, 1, &out) == CG_EINVAL);
    CHECK(cg_simplify64(&in, 0, CG_CLIP_EVEN_ODD, CG_SIMPLIFY_RDP, 1e9, &out) == CG_OK);
    CHECK_EQ_INT(out.point_count, 3); /* a triangle keeps its three vertices */
    cg_polygon_set64 empty = {0};
    CHECK(cg_simplify64(&empty, 0, CG_CLIP_EVEN_ODD, CG_SIMPLIFY_RDP, 1, &out) == CG_OK);
    CHECK_EQ_INT(out.ring_count, 0);
    cg_polygon_set d = {0}, dout = {0};
    cg_vec2 q[4] = {{0, 0}, {1, 0.001}, {2, 0}, {1, 1}};
    cg_polygon_set_add_ring(&d, q, 4, 1);
    CHECK(cg_simplify(&d, 0, CG_CLIP_EVEN_ODD, CG_SIMPLIFY_RDP, 0.01, 0, &dout) == CG_OK);
    CHECK_EQ_INT(dout.point_count, 3);
    CHECK(cg_simplify(&d, 0, CG_CLIP_EVEN_ODD, CG_SIMPLIFY_VISVALINGAM, 0.01, 0, &dout) == CG_OK);
    CHECK_EQ_INT(dout.point_count, 3);
    cg_polygon_set_clear(&d);
    cg_polygon_set_clear(&dout);
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(coastlines);
    CHECK_GROUP(interleaved_combs);
    CHECK_GROUP(polylines);
    CHECK_GROUP(bad_input);
    return check_finish();
}
