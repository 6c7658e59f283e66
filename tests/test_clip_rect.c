/* Rectangle clipping against its definition: for random rings (crossing
 * themselves, under every fill rule) the result covers the same points as
 * the general boolean engine's intersection with the rectangle (the same
 * area within the rounding of the crossings, the same winding membership
 * at random points), is a valid boolean result, and lies in the rectangle;
 * polylines keep exactly the length inside, piece by piece in order. */
#include "cg/polygon.h"
#include "check.h"

static uint64_t state = 88172645463325252ull;
static int64_t uniform(int64_t lo, int64_t hi)
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return lo + (int64_t)(state % (uint64_t)(hi - lo + 1));
}

/* The winding number of p for the rings of s, and whether a point lies
 * within a unit of an edge (then membership is left unjudged). */
static int winding(const cg_polygon_set64 *s, double x, double y, int *near_edge)
{
    int w = 0;
    for (size_t r = 0; r < s->ring_count; r++) {
        size_t a = s->ring_start[r], b = s->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_point64 p = s->points[i], q = s->points[i + 1 < b ? i + 1 : a];
            double dx = (double)(q.x - p.x), dy = (double)(q.y - p.y);
            double c = dx * (y - (double)p.y) - (x - (double)p.x) * dy, l = hypot(dx, dy);
            double t = l > 0 ? ((x - (double)p.x) * dx + (y - (double)p.y) * dy) / (l * l) : 0;
            if (l > 0 && t > -0.01 && t < 1.01 && fabs(c) / l < 2)
                *near_edge = 1;
            if (p.y <= y && q.y > y && c > 0)
                w++;
            else if (p.y > y && q.y <= y && c < 0)
                w--;
        }
    }
    return w;
}

static int filled(int w, cg_clip_fill f)
{
    switch (f) {
    case CG_CLIP_EVEN_ODD: return w & 1;
    case CG_CLIP_NON_ZERO: return w != 0;
    case CG_CLIP_POSITIVE: return w > 0;
    default: return w < 0;
    }
}

static void random_rings(cg_polygon_set64 *s, int64_t extent)
{
    cg_polygon_set64_clear(s);
    int rings = 1 + (int)uniform(0, 3);
    for (int r = 0; r < rings; r++) {
        cg_point64 p[64];
        int n = 3 + (int)uniform(0, 40);
        for (int i = 0; i < n; i++)
            p[i] = (cg_point64){uniform(-extent, extent), uniform(-extent, extent)};
        cg_polygon_set64_add_ring(s, p, (size_t)n, 1);
    }
}

static void polygons_against_engine(void)
{
    cg_polygon_set64 in = {0}, fast = {0}, general = {0}, window = {0};
    for (int trial = 0; trial < 600; trial++) {
        int64_t extent = trial % 2 ? 1000 : 1000000;
        random_rings(&in, extent);
        cg_clip_fill fill = (cg_clip_fill)(trial % 4);
        int64_t x0 = uniform(-extent, extent), y0 = uniform(-extent, extent);
        cg_rect64 r = {x0, y0, x0 + uniform(0, extent), y0 + uniform(0, extent)};
        if (trial % 50 == 0)
            r = (cg_rect64){-2 * extent, -2 * extent, 2 * extent, 2 * extent}; /* all inside */
        CHECK(cg_rect_clip64(&in, fill, r, &fast) == CG_OK);
        cg_point64 w[4] = {{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}};
        cg_polygon_set64_clear(&window);
        cg_polygon_set64_add_ring(&window, w, 4, 1);
        CHECK(
            cg_clip_boolean64(CG_CLIP_INTERSECTION, &in, fill, &window, CG_CLIP_NON_ZERO, &general)
            == CG_OK);
        /* each crossing rounded moves the boundary by at most a unit over
         * an edge no longer than the rectangle's diagonal */
        double diagonal = hypot((double)(r.xmax - r.xmin), (double)(r.ymax - r.ymin));
        double bound = 2.0 * (double)(in.point_count + 4) * diagonal;
        CHECK_MSG(fabs(cg_polygon_set64_area(&fast) - cg_polygon_set64_area(&general)) <= bound,
                  "trial %d: area %.1f, engine %.1f", trial, cg_polygon_set64_area(&fast),
                  cg_polygon_set64_area(&general));
        int outside = 0;
        for (size_t i = 0; i < fast.point_count; i++)
            outside += fast.points[i].x < r.xmin || fast.points[i].x > r.xmax
                       || fast.points[i].y < r.ymin || fast.points[i].y > r.ymax;
        CHECK_MSG(outside == 0, "trial %d: %d points outside the rectangle", trial, outside);
        for (int k = 0; k < 40; k++) {
            double x = (double)uniform(r.xmin, r.xmax) + 0.5,
                   y = (double)uniform(r.ymin, r.ymax) + 0.25;
            int near = 0;
            int want = filled(winding(&in, x, y, &near), fill);
            int got = winding(&fast, x, y, &near) != 0;
            if (!near && x < (double)r.xmax && y < (double)r.ymax)
                CHECK_MSG(want == got, "trial %d: (%g, %g) %s", trial, x, y,
                          want ? "lost" : "added");
        }
        /* results are boolean results: counter-clockwise outer rings */
        for (size_t p = 0; p < fast.polygon_count; p++) {
            size_t r0 = fast.polygon_start[p];
            cg_polygon_set64 one = {0};
            cg_polygon_set64_add_ring(&one, fast.points + fast.ring_start[r0],
                                      fast.ring_start[r0 + 1] - fast.ring_start[r0], 1);
            CHECK(cg_polygon_set64_area(&one) > 0);
            cg_polygon_set64_clear(&one);
        }
    }
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&fast);
    cg_polygon_set64_clear(&general);
    cg_polygon_set64_clear(&window);
}

/* The length of a-b inside the rectangle, by Liang-Barsky in long double. */
static long double inside_length(cg_point64 a, cg_point64 b, cg_rect64 r)
{
    long double t0 = 0, t1 = 1, dx = (long double)(b.x - a.x), dy = (long double)(b.y - a.y);
    long double p[4] = {-dx, dx, -dy, dy};
    long double q[4] = {(long double)(a.x - r.xmin), (long double)(r.xmax - a.x),
                        (long double)(a.y - r.ymin), (long double)(r.ymax - a.y)};
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0) {
            if (q[k] < 0)
                return 0;
        } else if (p[k] < 0) {
            t0 = fmaxl(t0, q[k] / p[k]);
        } else {
            t1 = fminl(t1, q[k] / p[k]);
        }
    }
    return t1 > t0 ? (t1 - t0) * hypotl(dx, dy) : 0;
}

static void polylines(void)
{
    cg_polygon_set64 in = {0}, out = {0};
    for (int trial = 0; trial < 500; trial++) {
        random_rings(&in, 100000);
        cg_rect64 r = {uniform(-100000, 0), uniform(-100000, 0), uniform(0, 100000),
                       uniform(0, 100000)};
        CHECK(cg_rect_clip_lines64(&in, r, &out) == CG_OK);
        long double want = 0, got = 0;
        size_t crossings = 0;
        for (size_t k = 0; k < in.ring_count; k++)
            for (size_t i = in.ring_start[k]; i + 1 < in.ring_start[k + 1]; i++) {
                want += inside_length(in.points[i], in.points[i + 1], r);
                crossings += 2;
            }
        for (size_t k = 0; k < out.ring_count; k++)
            for (size_t i = out.ring_start[k]; i + 1 < out.ring_start[k + 1]; i++)
                got += hypotl((long double)(out.points[i + 1].x - out.points[i].x),
                              (long double)(out.points[i + 1].y - out.points[i].y));
        CHECK_MSG(fabsl(want - got) <= (long double)crossings,
                  "trial %d: length %.3Lf inside, pieces %.3Lf", trial, want, got);
        /* a piece ends inside only where its path ends */
        for (size_t k = 0; k < out.ring_count; k++) {
            size_t a = out.ring_start[k], b = out.ring_start[k + 1];
            CHECK(b > a);
            for (size_t i = a; i < b; i++)
                CHECK(out.points[i].x >= r.xmin && out.points[i].x <= r.xmax
                      && out.points[i].y >= r.ymin && out.points[i].y <= r.ymax);
        }
    }
    /* a segment along a side is kept; one touching a corner is a point */
    cg_point64 along[2] = {{0, 10}, {20, 10}}, corner[3] = {{-5, 5}, {0, 10}, {-5, 15}};
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_add_ring(&in, along, 2, 1);
    cg_polygon_set64_add_ring(&in, corner, 3, 1);
    CHECK(cg_rect_clip_lines64(&in, (cg_rect64){0, 0, 10, 10}, &out) == CG_OK);
    CHECK_EQ_INT(out.ring_count, 2);
    if (out.ring_count == 2) {
        CHECK_EQ_INT(out.ring_start[1], 2);
        CHECK(out.points[1].x == 10 && out.points[1].y == 10);
        CHECK_EQ_INT(out.ring_start[2] - out.ring_start[1], 1);
    }
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
}

static void double_api_and_bad_input(void)
{
    cg_polygon_set sq = {0}, out = {0};
    cg_vec2 p[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    cg_polygon_set_add_ring(&sq, p, 4, 1);
    CHECK(cg_rect_clip(&sq, CG_CLIP_EVEN_ODD, (cg_rect){0.5, -1, 2, 0.25}, 0, &out) == CG_OK);
    CHECK_NEAR(cg_polygon_set_area(&out), 0.125, 1e-12);
    CHECK(cg_rect_clip(&sq, CG_CLIP_EVEN_ODD, (cg_rect){2, 2, 3, 3}, 0, &out) == CG_OK);
    CHECK_EQ_INT(out.ring_count, 0);
    CHECK(cg_rect_clip(&sq, CG_CLIP_EVEN_ODD, (cg_rect){1, 0, 0, 1}, 0, &out) == CG_EINVAL);
    CHECK(cg_rect_clip(&sq, CG_CLIP_EVEN_ODD, (cg_rect){NAN, 0, 1, 1}, 0, &out) == CG_EINVAL);
    CHECK(cg_rect_clip_lines(&sq, (cg_rect){0.5, 0.5, 2, 2}, 0, &out) == CG_OK);
    CHECK_EQ_INT(out.ring_count, 1); /* (1, 0.5) up to (1, 1) and left to (0.5, 1) */
    cg_polygon_set64 big = {0}, r = {0};
    cg_point64 q[3] = {{0, 0}, {CG_CLIP_MAX_COORD + 1, 0}, {0, 5}};
    cg_polygon_set64_add_ring(&big, q, 3, 1);
    CHECK(cg_rect_clip64(&big, CG_CLIP_EVEN_ODD, (cg_rect64){0, 0, 1, 1}, &r) == CG_ERANGE);
    CHECK(cg_rect_clip_lines64(&big, (cg_rect64){0, 0, 1, 1}, &r) == CG_ERANGE);
    CHECK(cg_rect_clip64(&big, (cg_clip_fill)9, (cg_rect64){0, 0, 1, 1}, &r) != CG_OK);
    cg_polygon_set64_clear(&big);
    cg_polygon_set64_clear(&r);
    cg_polygon_set_clear(&sq);
    cg_polygon_set_clear(&out);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(polygons_against_engine);
    CHECK_GROUP(polylines);
    CHECK_GROUP(double_api_and_bad_input);
    return check_finish();
}
