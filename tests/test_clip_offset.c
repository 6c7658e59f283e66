/* Offsets of shapes whose offset area is known in closed form (squares and
 * segments, every join and end), on the integer grid exactly where the
 * shape stays on it; the double API against the integer one; bad input. */
#include "cg/polygon.h"
#include "check.h"

static cg_polygon_set64 square64(int64_t x0, int64_t y0, int64_t side)
{
    cg_polygon_set64 s = {0};
    cg_point64 p[4] = {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
    cg_polygon_set64_add_ring(&s, p, 4, 1);
    return s;
}

static double offset_area64(const cg_polygon_set64 *in, double delta, cg_offset_join join,
                            cg_offset_end end, double limit)
{
    cg_offset_options o = cg_offset_options_default();
    o.join = join;
    o.end = end;
    o.miter_limit = limit;
    cg_polygon_set64 out = {0};
    cg_status st = cg_offset64(in, delta, &o, &out);
    CHECK_MSG(st == CG_OK, "offset: %s", cg_status_str(st));
    double a = cg_polygon_set64_area(&out);
    cg_polygon_set64_clear(&out);
    return a;
}

/* A square of side s inflated and deflated by d with each join. */
static void squares(void)
{
    const double s = 1000, d = 100;
    cg_polygon_set64 sq = square64(-500, 300, 1000);
    CHECK_NEAR(offset_area64(&sq, d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_POLYGON, 2),
               (s + 2 * d) * (s + 2 * d), 0);
    CHECK_NEAR(offset_area64(&sq, d, CG_OFFSET_JOIN_BEVEL, CG_OFFSET_END_POLYGON, 2),
               (s + 2 * d) * (s + 2 * d) - 2 * d * d, 0);
    /* square joins cut the miter corner at d from the vertex (the cut's ends
     * rounded to the grid: half a unit along its 83 units, at 4 corners) */
    CHECK_NEAR(offset_area64(&sq, d, CG_OFFSET_JOIN_SQUARE, CG_OFFSET_END_POLYGON, 2),
               (s + 2 * d) * (s + 2 * d) - 4 * d * d * (3 - 2 * sqrt(2)), 4 * 83 * 0.5);
    /* a miter limit below sqrt(2) cuts the corners as square joins at limit * d */
    CHECK(offset_area64(&sq, d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_POLYGON, 1.2)
          < (s + 2 * d) * (s + 2 * d));
    double round = offset_area64(&sq, d, CG_OFFSET_JOIN_ROUND, CG_OFFSET_END_POLYGON, 2);
    double exact = s * s + 4 * s * d + M_PI * d * d, tolerance = d / 500;
    CHECK_MSG(round <= exact && round >= exact - 2 * M_PI * d * (tolerance + 0.5),
              "round: %.3f, exact %.3f", round, exact);
    for (int join = 0; join < 4; join++)
        CHECK_NEAR(offset_area64(&sq, -d, (cg_offset_join)join, CG_OFFSET_END_POLYGON, 2),
                   (s - 2 * d) * (s - 2 * d), 0);
    /* deflated past its half-width, nothing is left */
    CHECK_NEAR(offset_area64(&sq, -s / 2, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_POLYGON, 2), 0, 0);
    cg_polygon_set64_clear(&sq);
}

/* A hole shrinks when the polygon grows, and goes when the growth passes
 * its half-width; it grows when the polygon shrinks. */
static void holes(void)
{
    cg_polygon_set64 s = square64(0, 0, 1000);
    cg_point64 hole[4] = {{400, 400}, {400, 600}, {600, 600}, {600, 400}};
    cg_polygon_set64_add_ring(&s, hole, 4, 1);
    CHECK_NEAR(offset_area64(&s, 50, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_POLYGON, 2),
               1100.0 * 1100 - 100.0 * 100, 0);
    CHECK_NEAR(offset_area64(&s, -50, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_POLYGON, 2),
               900.0 * 900 - 300.0 * 300, 0);
    cg_offset_options o = cg_offset_options_default();
    cg_polygon_set64 out = {0};
    CHECK(cg_offset64(&s, 150, &o, &out) == CG_OK);
    CHECK_EQ_INT(out.ring_count, 1);
    CHECK_EQ_INT(out.polygon_count, 1);
    /* the result may be the input */
    CHECK(cg_offset64(&s, -50, &o, &s) == CG_OK);
    CHECK_NEAR(cg_polygon_set64_area(&s), 900.0 * 900 - 300.0 * 300, 0);
    cg_polygon_set64_clear(&s);
    cg_polygon_set64_clear(&out);
}

/* A segment of length L widened by d: butt, square, round ends; an L
 * path; a closed square loop joined. */
static void open_paths(void)
{
    const double L = 1000, d = 50;
    cg_polygon_set64 seg = {0};
    cg_point64 p[2] = {{0, 0}, {600, 800}};
    cg_polygon_set64_add_ring(&seg, p, 2, 1);
    CHECK_NEAR(offset_area64(&seg, d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_BUTT, 2), 2 * d * L, 2);
    CHECK_NEAR(offset_area64(&seg, d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_SQUARE, 2),
               2 * d * (L + 2 * d), 2);
    double round = offset_area64(&seg, d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_ROUND, 2);
    CHECK_MSG(round <= 2 * d * L + M_PI * d * d + 2
                  && round >= 2 * d * L + M_PI * d * d - 2 * M_PI * d,
              "round ends: %.2f", round);
    /* a negative width is its absolute value */
    CHECK_NEAR(offset_area64(&seg, -d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_BUTT, 2), 2 * d * L, 2);
    cg_polygon_set64_clear(&seg);

    cg_polygon_set64 ell = {0};
    cg_point64 q[3] = {{0, 0}, {1000, 0}, {1000, 1000}};
    cg_polygon_set64_add_ring(&ell, q, 3, 1);
    /* two 1000 x 100 bands meeting in a mitered corner: 2 * 2d * 1000 */
    CHECK_NEAR(offset_area64(&ell, d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_BUTT, 2), 4 * d * 1000,
               0);
    CHECK_NEAR(offset_area64(&ell, d, CG_OFFSET_JOIN_BEVEL, CG_OFFSET_END_BUTT, 2),
               4 * d * 1000 - d * d / 2, 0);
    cg_polygon_set64_clear(&ell);

    cg_polygon_set64 loop = square64(0, 0, 1000);
    CHECK_NEAR(offset_area64(&loop, d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_JOINED, 2),
               1100.0 * 1100 - 900.0 * 900, 0);
    cg_polygon_set64_clear(&loop);

    /* a lone point: a dot for round and square ends, nothing for butt */
    cg_polygon_set64 dot = {0};
    cg_point64 one = {5, 5};
    cg_polygon_set64_add_ring(&dot, &one, 1, 1);
    CHECK_NEAR(offset_area64(&dot, d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_SQUARE, 2), 4 * d * d, 0);
    CHECK_NEAR(offset_area64(&dot, d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_BUTT, 2), 0, 0);
    CHECK(offset_area64(&dot, d, CG_OFFSET_JOIN_MITER, CG_OFFSET_END_ROUND, 2) > 3.1 * d * d);
    cg_polygon_set64_clear(&dot);
}

/* The double API gives the integer API's result scaled back. */
static void double_api(void)
{
    cg_polygon_set sq = {0}, out = {0};
    cg_vec2 p[4] = {{0.25, 0.25}, {1.25, 0.25}, {1.25, 1.25}, {0.25, 1.25}};
    cg_polygon_set_add_ring(&sq, p, 4, 1);
    cg_offset_options o = cg_offset_options_default();
    CHECK(cg_offset(&sq, 0.1, &o, 0, &out) == CG_OK);
    CHECK_NEAR(cg_polygon_set_area(&out), 1.2 * 1.2, 1e-9);
    o.join = CG_OFFSET_JOIN_ROUND;
    o.arc_tolerance = 1e-4;
    CHECK(cg_offset(&sq, 0.1, &o, 0, &out) == CG_OK);
    double exact = 1 + 0.4 + M_PI * 0.01;
    CHECK_MSG(cg_polygon_set_area(&out) <= exact + 1e-9
                  && cg_polygon_set_area(&out) >= exact - (4 + 2 * M_PI * 0.1) * 1e-4,
              "area %.9f, exact %.9f", cg_polygon_set_area(&out), exact);
    /* an explicit scale, and a workspace reused */
    cg_clip_workspace *ws = cg_clip_workspace_create();
    for (int k = 0; k < 3; k++) {
        CHECK(cg_offset_ws(ws, &sq, -0.25, NULL, 1000, &out) == CG_OK);
        CHECK_NEAR(cg_polygon_set_area(&out), 0.25, 1e-12);
    }
    cg_clip_workspace_free(ws);
    CHECK(cg_offset(&sq, 0.1, NULL, 0, &sq) == CG_OK); /* in place */
    CHECK_NEAR(cg_polygon_set_area(&sq), 1.2 * 1.2, 1e-9);
    cg_polygon_set_clear(&sq);
    cg_polygon_set_clear(&out);
}

static void bad_input(void)
{
    cg_polygon_set64 sq = square64(0, 0, 10), out = {0};
    cg_offset_options o = cg_offset_options_default();
    CHECK(cg_offset64(&sq, NAN, &o, &out) == CG_EINVAL);
    CHECK(cg_offset64(&sq, INFINITY, &o, &out) == CG_EINVAL);
    CHECK(cg_offset64(NULL, 1, &o, &out) == CG_EINVAL);
    CHECK(cg_offset64(&sq, 1, &o, NULL) == CG_EINVAL);
    o.miter_limit = 0.5;
    CHECK(cg_offset64(&sq, 1, &o, &out) == CG_EINVAL);
    o = cg_offset_options_default();
    o.join = (cg_offset_join)7;
    CHECK(cg_offset64(&sq, 1, &o, &out) == CG_EINVAL);
    o = cg_offset_options_default();
    o.arc_tolerance = -1;
    CHECK(cg_offset64(&sq, 1, &o, &out) == CG_EINVAL);
    o = cg_offset_options_default();
    CHECK(cg_offset64(&sq, 1e15, &o, &out) == CG_ERANGE);
    cg_polygon_set64 far = square64(CG_CLIP_MAX_COORD - 5, 0, 5);
    CHECK(cg_offset64(&far, 10, &o, &out) == CG_ERANGE);
    cg_polygon_set64 empty = {0};
    CHECK(cg_offset64(&empty, 10, &o, &out) == CG_OK);
    CHECK_EQ_INT(out.ring_count, 0);
    cg_polygon_set d = {0}, dout = {0};
    cg_vec2 p[3] = {{0, 0}, {1, 0}, {NAN, 1}};
    cg_polygon_set_add_ring(&d, p, 3, 1);
    CHECK(cg_offset(&d, 1, NULL, 0, &dout) == CG_EINVAL);
    cg_polygon_set_clear(&d);
    cg_polygon_set64_clear(&sq);
    cg_polygon_set64_clear(&far);
    cg_polygon_set64_clear(&out);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(squares);
    CHECK_GROUP(holes);
    CHECK_GROUP(open_paths);
    CHECK_GROUP(double_api);
    CHECK_GROUP(bad_input);
    return check_finish();
}
