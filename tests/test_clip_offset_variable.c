/* Variable offsets against their definition: a point belongs to the band
 * when some point c(t) = p + t (q - p) of an edge p-q lies within
 * r(t) = r_p + t (r_q - r_p) of it (the function |x - c(t)| - r(t) is
 * convex in t, minimised here by ternary search); the result is the region
 * united with the band (inflating), less it (deflating), or the band (open
 * paths).  Random star polygons with holes and random polylines, random
 * distances per vertex: membership at random points agrees, except within
 * the arc tolerance and a grid unit of the band's boundary; equal distances
 * give cg_offset64's round offset (the symmetric difference thin); bad
 * input. */
#include "polygon_shapes.h"
#include "check.h"

/* min over t of |x - c(t)| - r(t) for the edge p-q. */
static double edge_gap(double x, double y, cg_point64 p, cg_point64 q, double rp, double rq)
{
    double lo = 0, hi = 1;
    for (int k = 0; k < 100; k++) {
        double t1 = lo + (hi - lo) / 3, t2 = hi - (hi - lo) / 3;
        double f1 = hypot(x - ((double)p.x + t1 * (double)(q.x - p.x)),
                          y - ((double)p.y + t1 * (double)(q.y - p.y)))
                    - (rp + t1 * (rq - rp));
        double f2 = hypot(x - ((double)p.x + t2 * (double)(q.x - p.x)),
                          y - ((double)p.y + t2 * (double)(q.y - p.y)))
                    - (rp + t2 * (rq - rp));
        if (f1 < f2)
            hi = t2;
        else
            lo = t1;
    }
    double t = (lo + hi) / 2;
    return hypot(x - ((double)p.x + t * (double)(q.x - p.x)),
                 y - ((double)p.y + t * (double)(q.y - p.y)))
           - (rp + t * (rq - rp));
}

/* The smallest gap over the edges of s (closed rings or open paths). */
static double band_gap(const cg_polygon_set64 *s, const double *r, int closed, double x, double y)
{
    double best = INFINITY;
    for (size_t k = 0; k < s->ring_count; k++) {
        size_t a = s->ring_start[k], b = s->ring_start[k + 1];
        if (b - a == 1) /* a lone point: its disk */
            best = fmin(best, edge_gap(x, y, s->points[a], s->points[a], fabs(r[a]), fabs(r[a])));
        for (size_t i = a; i + (closed ? 0 : 1) < b && b - a > 1; i++) {
            size_t j = i + 1 < b ? i + 1 : a;
            best = fmin(best, edge_gap(x, y, s->points[i], s->points[j], fabs(r[i]), fabs(r[j])));
        }
    }
    return best;
}

static void star(cg_polygon_set64 *s, int n, double cx, double cy, double lo, double hi,
                 int reversed)
{
    cg_point64 p[64];
    for (int i = 0; i < n; i++) {
        double t = 2 * M_PI * (i + shapes_between(0, 0.6)) / n, r = shapes_between(lo, hi);
        p[reversed ? n - 1 - i : i] = (cg_point64){(int64_t)llround(cx + r * cos(t)),
                                                   (int64_t)llround(cy + r * sin(t))};
    }
    cg_polygon_set64_add_ring(s, p, (size_t)n, 1);
}

static long judged, unjudged;

/* Membership at random points against the definition. */
static void check_points(const cg_polygon_set64 *in, const double *deltas, cg_offset_end end,
                         const cg_polygon_set64 *result, double slack, int trial)
{
    int closed = end != CG_OFFSET_END_ROUND, polygons = end == CG_OFFSET_END_POLYGON;
    int deflate = polygons && deltas[0] < 0;
    for (int k = 0; k < 400; k++) {
        double x = shapes_between(-3000, 3000), y = shapes_between(-3000, 3000);
        double gap = band_gap(in, deltas, closed, x, y);
        int region = polygons && shapes_winding64(in, x, y) != 0; /* fill: nonzero */
        if (fabs(gap) < slack) {
            unjudged++;
            continue;
        }
        int want = polygons ? (deflate ? region && gap > 0 : region || gap < 0) : gap < 0;
        int got = shapes_winding64(result, x, y) != 0;
        judged++;
        CHECK_MSG(got == want, "trial %d: (%.1f, %.1f) gap %.2f: got %d, want %d", trial, x, y, gap,
                  got, want);
    }
}

static void against_definition(void)
{
    cg_polygon_set64 in = {0}, out = {0};
    cg_offset_options o = cg_offset_options_default();
    o.fill = CG_CLIP_NON_ZERO;
    o.arc_tolerance = 1;
    for (int trial = 0; trial < 120; trial++) {
        cg_polygon_set64_clear(&in);
        cg_offset_end end = trial % 3 == 0   ? CG_OFFSET_END_POLYGON
                            : trial % 3 == 1 ? CG_OFFSET_END_ROUND
                                             : CG_OFFSET_END_JOINED;
        if (end == CG_OFFSET_END_POLYGON) {
            star(&in, 5 + (int)shapes_between(0, 30), 0, 0, 800, 2000, 0);
            star(&in, 3 + (int)shapes_between(0, 8), shapes_between(-200, 200),
                 shapes_between(-200, 200), 100, 400, 1);
        } else {
            cg_point64 p[20];
            int n = 1 + (int)shapes_between(0, 12);
            for (int i = 0; i < n; i++)
                p[i] = (cg_point64){(int64_t)shapes_between(-2000, 2000),
                                    (int64_t)shapes_between(-2000, 2000)};
            cg_polygon_set64_add_ring(&in, p, (size_t)n, 1);
        }
        double deltas[64], sign = end == CG_OFFSET_END_POLYGON && trial % 2 ? -1 : 1;
        for (size_t i = 0; i < in.point_count; i++)
            deltas[i] = sign * (trial % 5 == 0 ? 0 : shapes_between(0, 400));
        o.end = end;
        CHECK(cg_offset_variable64(&in, deltas, &o, &out) == CG_OK);
        check_points(&in, deltas, end, &out, o.arc_tolerance + 2, trial);
    }
    printf("   %ld points judged, %ld within the tolerance of the band's boundary\n", judged,
           unjudged);
    CHECK(judged > 20 * unjudged);
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
}

/* Equal distances: the round offset of cg_offset64, within the chords. */
static void constant_is_round_offset(void)
{
    cg_polygon_set64 in = {0}, a = {0}, b = {0}, x = {0};
    cg_offset_options o = cg_offset_options_default();
    o.join = CG_OFFSET_JOIN_ROUND;
    o.arc_tolerance = 2;
    for (int trial = 0; trial < 40; trial++) {
        cg_polygon_set64_clear(&in);
        star(&in, 5 + (int)shapes_between(0, 30), 0, 0, 800, 2000, 0);
        double d = trial % 2 ? 150 : -150, deltas[64];
        for (size_t i = 0; i < in.point_count; i++)
            deltas[i] = d;
        CHECK(cg_offset_variable64(&in, deltas, &o, &a) == CG_OK);
        CHECK(cg_offset64(&in, d, &o, &b) == CG_OK);
        CHECK(cg_clip_boolean64(CG_CLIP_XOR, &a, CG_CLIP_NON_ZERO, &b, CG_CLIP_NON_ZERO, &x)
              == CG_OK);
        double perimeter = 0;
        for (size_t i = 0; i < in.point_count; i++) {
            cg_point64 p = in.points[i], q = in.points[(i + 1) % in.point_count];
            perimeter += hypot((double)(q.x - p.x), (double)(q.y - p.y));
        }
        /* both within the tolerance (plus rounding) of the exact offset,
         * whose boundary is at most the perimeter plus a circle long */
        double bound = (2 * o.arc_tolerance + 2) * (perimeter + 2 * M_PI * 150);
        CHECK_MSG(fabs(cg_polygon_set64_area(&x)) <= bound, "trial %d: xor area %g > %g", trial,
                  fabs(cg_polygon_set64_area(&x)), bound);
    }
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&a);
    cg_polygon_set64_clear(&b);
    cg_polygon_set64_clear(&x);
}

static void double_api_and_bad_input(void)
{
    cg_polygon_set s = {0}, r = {0};
    cg_vec2 line[2] = {{0, 0}, {10, 0}};
    cg_polygon_set_add_ring(&s, line, 2, 1);
    double d[2] = {1, 3};
    cg_offset_options o = cg_offset_options_default();
    o.end = CG_OFFSET_END_ROUND;
    CHECK(cg_offset_variable(&s, d, &o, 0, &r) == CG_OK);
    /* the hull of the disks of radius 1 and 3 ten apart: the sectors
     * beyond the tangents and two right trapezoids between them */
    double beta = acos((1.0 - 3.0) / 10), h = sqrt(100 - 4);
    double area = 1 * (M_PI - beta) + 9 * beta + (1 + 3) * h, perimeter = 2 * h + 2 * M_PI * 3;
    double got = cg_polygon_set_area(&r);
    CHECK_MSG(got <= area + 1e-9 && got >= area - 3.0 / 500 * perimeter, "area %.9g, hull %.9g",
              got, area);
    double mixed[2] = {1, -1}, nan_delta[2] = {1, NAN};
    CHECK(cg_offset_variable(&s, mixed, &o, 0, &r) == CG_EINVAL);
    CHECK(cg_offset_variable(&s, nan_delta, &o, 0, &r) == CG_EINVAL);
    CHECK(cg_offset_variable(&s, NULL, &o, 0, &r) == CG_EINVAL);
    o.end = CG_OFFSET_END_BUTT;
    CHECK(cg_offset_variable(&s, d, &o, 0, &r) == CG_EINVAL);
    o.end = CG_OFFSET_END_ROUND;
    o.arc_tolerance = -1;
    CHECK(cg_offset_variable(&s, d, &o, 0, &r) == CG_EINVAL);
    cg_polygon_set64 far = {0}, r64 = {0};
    cg_point64 big[1] = {{CG_CLIP_MAX_COORD - 5, 0}};
    cg_polygon_set64_add_ring(&far, big, 1, 1);
    double ten[1] = {10};
    o.arc_tolerance = 0;
    CHECK(cg_offset_variable64(&far, ten, &o, &r64) == CG_ERANGE);
    cg_polygon_set64 none = {0};
    CHECK(cg_offset_variable64(&none, NULL, NULL, &r64) == CG_OK && r64.ring_count == 0);
    cg_polygon_set64_clear(&far);
    cg_polygon_set_clear(&s);
    cg_polygon_set_clear(&r);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(against_definition);
    CHECK_GROUP(constant_is_round_offset);
    CHECK_GROUP(double_api_and_bad_input);
    return check_finish();
}
