/* Clipping open paths against polygons, against the definition: on hand-made
 * cases where every crossing is a grid point the pieces are exact (points on
 * the boundary, stretches along edges, vertices where rings touch, holes,
 * self-crossing paths); on random self-crossing rings under every fill rule
 * and random self-crossing paths, the pieces of the intersection and of the
 * difference together have the path's length (within the rounding of the
 * crossings), and the midpoint of every segment of a piece lies in the
 * region (intersection) or outside it (difference), judged by the winding
 * number of the input rings and an exact on-edge test on the doubled grid. */
#include "cg/polygon.h"
#include "check.h"

__extension__ typedef __int128 i128;

static uint64_t state = 0x2545f4914f6cdd1dull;
static int64_t uniform(int64_t lo, int64_t hi)
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return lo + (int64_t)(state % (uint64_t)(hi - lo + 1));
}

static cg_polygon_set64 set_of(const char *rings)
{
    /* "x y, x y; x y, ..." : rings separated by ';' */
    cg_polygon_set64 s = {0};
    cg_point64 p[64];
    size_t n = 0;
    const char *c = rings;
    while (*c) {
        char *end;
        long long x = strtoll(c, &end, 10);
        long long y = strtoll(end, &end, 10);
        p[n++] = (cg_point64){x, y};
        while (*end == ' ' || *end == ',')
            end++;
        if (*end == ';' || *end == 0) {
            cg_polygon_set64_add_ring(&s, p, n, 1);
            n = 0;
            if (*end == ';')
                end++;
        }
        c = end;
    }
    return s;
}

/* The pieces as text "x y, x y; x y, ..." for comparison. */
static void pieces_text(const cg_polygon_set64 *s, char *out, size_t size)
{
    size_t used = 0;
    out[0] = 0;
    for (size_t r = 0; r < s->ring_count; r++)
        for (size_t i = s->ring_start[r]; i < s->ring_start[r + 1]; i++)
            used += (size_t)snprintf(out + used, size - used, "%lld %lld%s",
                                     (long long)s->points[i].x, (long long)s->points[i].y,
                                     i + 1 < s->ring_start[r + 1] ? ", "
                                     : r + 1 < s->ring_count      ? "; "
                                                                  : "");
}

static void expect_pieces(cg_clip_op op, const char *path, const char *clip, cg_clip_fill fill,
                          const char *want)
{
    cg_polygon_set64 p = set_of(path), c = set_of(clip), r = {0};
    char got[2048];
    cg_status st = cg_clip_lines64(op, &p, &c, fill, &r);
    CHECK(st == CG_OK);
    pieces_text(&r, got, sizeof got);
    CHECK_MSG(strcmp(got, want) == 0, "%s of [%s] by [%s]: got [%s], want [%s]",
              op == CG_CLIP_INTERSECTION ? "intersection" : "difference", path, clip, got, want);
    cg_polygon_set64_clear(&p);
    cg_polygon_set64_clear(&c);
    cg_polygon_set64_clear(&r);
}

#define SQUARE_WITH_HOLE "0 0, 10 0, 10 10, 0 10; 3 3, 3 7, 7 7, 7 3"

static void exact_cases(void)
{
    const cg_clip_op I = CG_CLIP_INTERSECTION, D = CG_CLIP_DIFFERENCE;
    const cg_clip_fill E = CG_CLIP_EVEN_ODD;
    /* straight through a square with a hole */
    expect_pieces(I, "-5 5, 15 5", SQUARE_WITH_HOLE, E, "0 5, 3 5; 7 5, 10 5");
    expect_pieces(D, "-5 5, 15 5", SQUARE_WITH_HOLE, E, "-5 5, 0 5; 3 5, 7 5; 10 5, 15 5");
    /* backwards: the pieces follow the path */
    expect_pieces(I, "15 5, -5 5", SQUARE_WITH_HOLE, E, "10 5, 7 5; 3 5, 0 5");
    /* along an edge (boundary: inside for the intersection only) */
    expect_pieces(I, "-5 0, 15 0", SQUARE_WITH_HOLE, E, "0 0, 10 0");
    expect_pieces(D, "-5 0, 15 0", SQUARE_WITH_HOLE, E, "-5 0, 0 0; 10 0, 15 0");
    /* along a hole's edge, starting inside an edge */
    expect_pieces(I, "3 5, 3 8, 5 8", SQUARE_WITH_HOLE, E, "3 5, 3 8, 5 8");
    expect_pieces(D, "3 5, 3 8, 5 8", SQUARE_WITH_HOLE, E, "");
    /* touching a corner from outside: no piece inside, the outside cut */
    expect_pieces(I, "-5 5, 0 10, -5 15", SQUARE_WITH_HOLE, E, "");
    expect_pieces(D, "-5 5, 0 10, -5 15", SQUARE_WITH_HOLE, E, "-5 5, 0 10; 0 10, -5 15");
    /* through a corner diagonally, and through the hole's corners */
    expect_pieces(I, "-1 -1, 11 11", SQUARE_WITH_HOLE, E, "0 0, 3 3; 7 7, 10 10");
    expect_pieces(D, "-1 -1, 11 11", SQUARE_WITH_HOLE, E, "-1 -1, 0 0; 3 3, 7 7; 10 10, 11 11");
    /* touching the hole's corner from inside: stays one piece */
    expect_pieces(I, "1 5, 3 7, 1 9", SQUARE_WITH_HOLE, E, "1 5, 3 7, 1 9");
    expect_pieces(D, "1 5, 3 7, 1 9", SQUARE_WITH_HOLE, E, "");
    /* a self-crossing path, in and out twice */
    expect_pieces(I, "-2 1, 12 8, 12 1, -2 8", "0 0, 10 0, 10 10, 0 10", E, "0 2, 10 7; 10 2, 0 7");
    /* starting and ending on vertices and edges */
    expect_pieces(I, "0 0, 5 5, 10 5", "0 0, 10 0, 10 10, 0 10", E, "0 0, 5 5, 10 5");
    expect_pieces(D, "0 0, 5 5, 10 5", "0 0, 10 0, 10 10, 0 10", E, "");
    expect_pieces(D, "10 5, 20 5", "0 0, 10 0, 10 10, 0 10", E, "10 5, 20 5");
    /* two squares touching at a vertex: through the pinch */
    expect_pieces(I, "0 0, 20 20", "0 0, 10 0, 10 10, 0 10; 10 10, 20 10, 20 20, 10 20", E,
                  "0 0, 20 20");
    expect_pieces(I, "0 20, 20 0", "0 0, 10 0, 10 10, 0 10; 10 10, 20 10, 20 20, 10 20", E, "");
    expect_pieces(D, "0 20, 20 0", "0 0, 10 0, 10 10, 0 10; 10 10, 20 10, 20 20, 10 20", E,
                  "0 20, 10 10; 10 10, 20 0");
    /* a hole touching its outer ring inside an edge (an L-shaped notch) */
    expect_pieces(I, "5 -2, 5 12", "0 0, 10 0, 10 10, 0 10; 5 0, 4 2, 6 2", E, "5 2, 5 10");
    /* overlapping rings under the fill rules: even-odd leaves the overlap out */
    expect_pieces(I, "-1 1, 9 1", "0 0, 6 0, 6 2, 0 2; 3 0, 8 0, 8 2, 3 2", E,
                  "0 1, 3 1; 6 1, 8 1");
    expect_pieces(I, "-1 1, 9 1", "0 0, 6 0, 6 2, 0 2; 3 0, 8 0, 8 2, 3 2", CG_CLIP_NON_ZERO,
                  "0 1, 8 1");
    /* repeated points, a path of one point, an empty clip */
    expect_pieces(I, "1 1, 1 1, 2 2, 2 2", "0 0, 10 0, 10 10, 0 10", E, "1 1, 2 2");
    expect_pieces(I, "1 1", "0 0, 10 0, 10 10, 0 10", E, "");
    cg_polygon_set64 p = set_of("0 0, 5 5"), none = {0}, r = {0};
    CHECK(cg_clip_lines64(CG_CLIP_INTERSECTION, &p, &none, E, &r) == CG_OK && r.ring_count == 0);
    CHECK(cg_clip_lines64(CG_CLIP_DIFFERENCE, &p, &none, E, &r) == CG_OK && r.ring_count == 1);
    cg_polygon_set64_clear(&p);
    cg_polygon_set64_clear(&r);
}

/* Winding number of a point given on the doubled grid (x2, y2) for rings s. */
static int winding2(const cg_polygon_set64 *s, int64_t x2, int64_t y2)
{
    int w = 0;
    for (size_t r = 0; r < s->ring_count; r++) {
        size_t a = s->ring_start[r], b = s->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_point64 p = s->points[i], q = s->points[i + 1 < b ? i + 1 : a];
            int64_t px = 2 * p.x, py = 2 * p.y, qx = 2 * q.x, qy = 2 * q.y;
            i128 c = (i128)(qx - px) * (y2 - py) - (i128)(qy - py) * (x2 - px);
            if (py <= y2 && qy > y2 && c > 0)
                w++;
            else if (qy <= y2 && py > y2 && c < 0)
                w--;
        }
    }
    return w;
}

/* Whether the doubled point lies on an edge of s (exactly): 2 when that
 * edge is parallel to direction (dx, dy), 1 when it crosses it there; and
 * the distance to the nearest edge (in grid units). */
static int on_edge2(const cg_polygon_set64 *s, int64_t x2, int64_t y2, int64_t dx, int64_t dy,
                    double *distance)
{
    int on = 0;
    *distance = INFINITY;
    for (size_t r = 0; r < s->ring_count; r++) {
        size_t a = s->ring_start[r], b = s->ring_start[r + 1];
        for (size_t i = a; i < b; i++) {
            cg_point64 p = s->points[i], q = s->points[i + 1 < b ? i + 1 : a];
            int64_t px = 2 * p.x, py = 2 * p.y, qx = 2 * q.x, qy = 2 * q.y;
            i128 c = (i128)(qx - px) * (y2 - py) - (i128)(qy - py) * (x2 - px);
            i128 t = (i128)(qx - px) * (x2 - px) + (i128)(qy - py) * (y2 - py);
            i128 l = (i128)(qx - px) * (qx - px) + (i128)(qy - py) * (qy - py);
            if (c == 0 && t >= 0 && t <= l) {
                int parallel = (i128)(q.x - p.x) * dy == (i128)(q.y - p.y) * dx;
                on = parallel ? 2 : on > 1 ? on : 1;
            }
            double dx = (double)(qx - px), dy = (double)(qy - py), u = (double)t / (double)l;
            u = u < 0 ? 0 : u > 1 ? 1 : u;
            double ex = (double)px + u * dx - (double)x2, ey = (double)py + u * dy - (double)y2;
            double d = hypot(ex, ey) / 2;
            *distance = d < *distance ? d : *distance;
        }
    }
    return on;
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

static double length(const cg_polygon_set64 *s)
{
    double total = 0;
    for (size_t r = 0; r < s->ring_count; r++)
        for (size_t i = s->ring_start[r]; i + 1 < s->ring_start[r + 1]; i++)
            total += hypot((double)(s->points[i + 1].x - s->points[i].x),
                           (double)(s->points[i + 1].y - s->points[i].y));
    return total;
}

static void random_set(cg_polygon_set64 *s, int rings, int most, int64_t extent)
{
    cg_polygon_set64_clear(s);
    for (int r = 0; r < rings; r++) {
        cg_point64 p[64];
        int n = 3 + (int)uniform(0, most - 3);
        for (int i = 0; i < n; i++) {
            p[i] = (cg_point64){uniform(-extent, extent), uniform(-extent, extent)};
            if (i > 0 && uniform(0, 5) == 0) /* runs along axes meet edges collinearly */
                p[i].x = p[i - 1].x;
        }
        cg_polygon_set64_add_ring(s, p, (size_t)n, 1);
    }
}

static long judged, unjudged;

/* Whether a-b is a whole segment of a path of s (no rounded end). */
static int is_segment(const cg_polygon_set64 *s, cg_point64 a, cg_point64 b)
{
    for (size_t r = 0; r < s->ring_count; r++)
        for (size_t i = s->ring_start[r]; i + 1 < s->ring_start[r + 1]; i++)
            if (s->points[i].x == a.x && s->points[i].y == a.y && s->points[i + 1].x == b.x
                && s->points[i + 1].y == b.y)
                return 1;
    return 0;
}

/* Every segment's midpoint of the pieces lies where op says. */
static void check_sides(cg_clip_op op, const cg_polygon_set64 *pieces, const cg_polygon_set64 *path,
                        const cg_polygon_set64 *clip, cg_clip_fill fill,
                        const cg_polygon_set64 *region, int coarse, int trial)
{
    for (size_t r = 0; r < pieces->ring_count; r++)
        for (size_t i = pieces->ring_start[r]; i + 1 < pieces->ring_start[r + 1]; i++) {
            cg_point64 a = pieces->points[i], b = pieces->points[i + 1];
            int64_t x2 = a.x + b.x, y2 = a.y + b.y;
            double distance;
            int on = on_edge2(region, x2, y2, b.x - a.x, b.y - a.y, &distance);
            /* the region is the engine's union, its crossings rounded to
             * the grid: within a unit of the rings' exact region */
            int in = winding2(region, x2, y2) != 0;
            /* the rounding of a crossing may move a short stretch across an
             * edge, or put it where it crosses one */
            if ((distance < 2 && !is_segment(path, a, b)) || on == 1) {
                unjudged += !coarse;
                continue;
            }
            judged += !coarse;
            if (!on && !coarse)
                CHECK_MSG(in == filled(winding2(clip, x2, y2), fill),
                          "trial %d: the region differs from the rings' at a midpoint", trial);
            if (op == CG_CLIP_INTERSECTION)
                CHECK_MSG(on || in, "trial %d: piece %zu segment %zu outside", trial, r, i);
            else
                CHECK_MSG(!on && !in, "trial %d: piece %zu segment %zu inside", trial, r, i);
        }
}

static void random_paths(void)
{
    cg_polygon_set64 clip = {0}, path = {0}, in = {0}, out = {0}, region = {0}, none = {0};
    for (int trial = 0; trial < 1500; trial++) {
        int64_t extent = trial % 3 == 0 ? 12 : trial % 3 == 1 ? 1000 : 1000000000;
        cg_clip_fill fill = (cg_clip_fill)(trial % 4);
        random_set(&clip, 1 + (int)uniform(0, 2), 30, extent);
        random_set(&path, 1 + (int)uniform(0, 1), 40, extent + extent / 4);
        CHECK(cg_clip_lines64(CG_CLIP_INTERSECTION, &path, &clip, fill, &in) == CG_OK);
        CHECK(cg_clip_lines64(CG_CLIP_DIFFERENCE, &path, &clip, fill, &out) == CG_OK);
        CHECK(cg_clip_boolean64(CG_CLIP_UNION, &clip, fill, &none, fill, &region) == CG_OK);
        double total = length(&path), got = length(&in) + length(&out);
        double tolerance = 1.5 * (double)(in.ring_count + out.ring_count + 1);
        CHECK_MSG(fabs(total - got) <= tolerance, "trial %d: lengths %.17g + %.17g != %.17g", trial,
                  length(&in), length(&out), total);
        check_sides(CG_CLIP_INTERSECTION, &in, &path, &clip, fill, &region, extent < 100, trial);
        check_sides(CG_CLIP_DIFFERENCE, &out, &path, &clip, fill, &region, extent < 100, trial);
    }
    CHECK_MSG(unjudged * 20 < judged, "%ld segments unjudged of %ld", unjudged, judged);
    printf("   %ld segment midpoints judged exactly, %ld within 2 units of an edge (extents >= "
           "1000)\n",
           judged, unjudged);
    cg_polygon_set64_clear(&clip);
    cg_polygon_set64_clear(&path);
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
    cg_polygon_set64_clear(&region);
}

/* On a coarse grid every crossing of axis-parallel paths with axis-parallel
 * rings is a grid point: the pieces are exact, their lengths add up exactly. */
static void exact_lengths(void)
{
    cg_polygon_set64 clip = {0}, path = {0}, in = {0}, out = {0};
    for (int trial = 0; trial < 400; trial++) {
        cg_polygon_set64_clear(&clip);
        cg_polygon_set64_clear(&path);
        for (int r = 0; r < 3; r++) {
            int64_t x0 = uniform(-8, 6), y0 = uniform(-8, 6);
            int64_t x1 = x0 + uniform(1, 6), y1 = y0 + uniform(1, 6);
            cg_point64 box[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
            cg_polygon_set64_add_ring(&clip, box, 4, 1);
        }
        cg_point64 p[30];
        p[0] = (cg_point64){uniform(-10, 10), uniform(-10, 10)};
        for (int i = 1; i < 30; i++)
            p[i] = i % 2 ? (cg_point64){uniform(-10, 10), p[i - 1].y}
                         : (cg_point64){p[i - 1].x, uniform(-10, 10)};
        cg_polygon_set64_add_ring(&path, p, 30, 1);
        cg_clip_fill fill = (cg_clip_fill)(trial % 4);
        CHECK(cg_clip_lines64(CG_CLIP_INTERSECTION, &path, &clip, fill, &in) == CG_OK);
        CHECK(cg_clip_lines64(CG_CLIP_DIFFERENCE, &path, &clip, fill, &out) == CG_OK);
        CHECK_MSG(length(&in) + length(&out) == length(&path), "trial %d: %g + %g != %g", trial,
                  length(&in), length(&out), length(&path));
        /* every piece's vertices follow the path: consecutive pieces in order */
        for (size_t r = 0; r < in.ring_count; r++)
            CHECK(in.ring_start[r + 1] - in.ring_start[r] >= 2);
    }
    cg_polygon_set64_clear(&clip);
    cg_polygon_set64_clear(&path);
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
}

static void double_api_and_bad_input(void)
{
    cg_polygon_set path = {0}, clip = {0}, r = {0};
    cg_vec2 line[2] = {{-0.5, 0.25}, {1.5, 0.25}};
    cg_vec2 square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    cg_polygon_set_add_ring(&path, line, 2, 1);
    cg_polygon_set_add_ring(&clip, square, 4, 1);
    CHECK(cg_clip_lines(CG_CLIP_INTERSECTION, &path, &clip, CG_CLIP_EVEN_ODD, 0, &r) == CG_OK);
    CHECK(r.ring_count == 1 && r.point_count == 2);
    if (r.point_count == 2) {
        CHECK(r.points[0].x == 0 && r.points[0].y == 0.25);
        CHECK(r.points[1].x == 1 && r.points[1].y == 0.25);
    }
    cg_clip_workspace *ws = cg_clip_workspace_create();
    CHECK(cg_clip_lines_ws(ws, CG_CLIP_DIFFERENCE, &path, &clip, CG_CLIP_EVEN_ODD, 0, &r) == CG_OK);
    CHECK(r.ring_count == 2);
    cg_clip_workspace_free(ws);
    CHECK(cg_clip_lines(CG_CLIP_UNION, &path, &clip, CG_CLIP_EVEN_ODD, 0, &r) == CG_EINVAL);
    CHECK(cg_clip_lines(CG_CLIP_XOR, &path, &clip, CG_CLIP_EVEN_ODD, 0, &r) == CG_EINVAL);
    CHECK(cg_clip_lines(CG_CLIP_INTERSECTION, &path, &clip, (cg_clip_fill)9, 0, &r) == CG_EINVAL);
    CHECK(cg_clip_lines(CG_CLIP_INTERSECTION, NULL, &clip, CG_CLIP_EVEN_ODD, 0, &r) == CG_EINVAL);
    CHECK(cg_clip_lines(CG_CLIP_INTERSECTION, &path, &clip, CG_CLIP_EVEN_ODD, 0, NULL)
          == CG_EINVAL);
    path.points[1].x = NAN;
    CHECK(cg_clip_lines(CG_CLIP_INTERSECTION, &path, &clip, CG_CLIP_EVEN_ODD, 0, &r) == CG_EINVAL);
    path.points[1].x = 1e30;
    CHECK(cg_clip_lines(CG_CLIP_INTERSECTION, &path, &clip, CG_CLIP_EVEN_ODD, 1, &r) == CG_ERANGE);
    cg_polygon_set64 far = {0}, none = {0}, r64 = {0};
    cg_point64 big[2] = {{0, 0}, {CG_CLIP_MAX_COORD + 1, 0}};
    cg_polygon_set64_add_ring(&far, big, 2, 1);
    CHECK(cg_clip_lines64(CG_CLIP_INTERSECTION, &far, &none, CG_CLIP_EVEN_ODD, &r64) == CG_ERANGE);
    cg_polygon_set64_clear(&far);
    cg_polygon_set_clear(&path);
    cg_polygon_set_clear(&clip);
    cg_polygon_set_clear(&r);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(exact_cases);
    CHECK_GROUP(random_paths);
    CHECK_GROUP(exact_lengths);
    CHECK_GROUP(double_api_and_bad_input);
    return check_finish();
}
