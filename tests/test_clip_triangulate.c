/* Triangulations against their definition, exactly (coordinates below
 * 2^20, so the in-circle determinant fits in 128 bits here, computed apart
 * from cg's own predicate): every triangle counter-clockwise with positive
 * area; their areas sum exactly to the area of the simple rings the union
 * gives; every directed triangle edge is either a ring edge or met by its
 * reverse in exactly one other triangle, and every ring edge is a triangle
 * edge (so the triangles tile the region once); no vertex outside the
 * rings' vertices (no Steiner point); and every edge that is not a ring
 * edge is locally Delaunay.  The inputs: random self-crossing rings, rings
 * on a coarse grid (collinear runs, touching holes), combs, a square with
 * many touching square holes, and spirals. */
#include "polygon_shapes.h"
#include "check.h"

__extension__ typedef __int128 i128;

/* d strictly inside the circle through a, b, c (counter-clockwise). */
static int in_circle(cg_point64 a, cg_point64 b, cg_point64 c, cg_point64 d)
{
    i128 adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
    i128 cdx = c.x - d.x, cdy = c.y - d.y;
    i128 det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
               + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
               + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
    return det > 0;
}

/* A directed edge and where it came from. */
typedef struct edge {
    cg_point64 from, to;
    int triangle, ring;
} edge;

static int compare_edges(const void *a, const void *b)
{
    const edge *x = a, *y = b;
    int64_t k[4] = {x->from.x - y->from.x, x->from.y - y->from.y, x->to.x - y->to.x,
                    x->to.y - y->to.y};
    for (int i = 0; i < 4; i++)
        if (k[i])
            return k[i] < 0 ? -1 : 1;
    return (x->ring > y->ring) - (x->ring < y->ring);
}

static edge *find(edge *edges, size_t n, cg_point64 from, cg_point64 to, int ring)
{
    edge key = {from, to, 0, ring};
    return bsearch(&key, edges, n, sizeof key, compare_edges);
}

static int same(cg_point64 a, cg_point64 b)
{
    return a.x == b.x && a.y == b.y;
}

/* The ring edge a-b as the pieces between the rings' vertices lying on it
 * (a hole may touch the outer ring inside an edge): written to out, counted. */
static size_t ring_pieces(const cg_polygon_set64 *simple, cg_point64 a, cg_point64 b, edge *out)
{
    size_t n = 0;
    cg_point64 from = a;
    for (;;) {
        /* the nearest vertex strictly between from and b */
        i128 best = 0;
        cg_point64 next = b;
        i128 len = (i128)(b.x - from.x) * (b.x - from.x) + (i128)(b.y - from.y) * (b.y - from.y);
        for (size_t k = 0; k < simple->point_count; k++) {
            cg_point64 c = simple->points[k];
            i128 dot = (i128)(c.x - from.x) * (b.x - from.x)
                       + (i128)(c.y - from.y) * (b.y - from.y);
            if (shapes_cross64(from, b, c) == 0 && dot > 0 && dot < len
                && (best == 0 || dot < best)) {
                best = dot;
                next = c;
            }
        }
        out[n++] = (edge){from, next, -1, 1};
        if (same(next, b))
            return n;
        from = next;
    }
}

static void check_triangulation(const char *what, int trial, const cg_polygon_set64 *input,
                                cg_clip_fill fill)
{
    cg_polygon_set64 simple = {0}, none = {0}, tri = {0};
    cg_clip_boolean64(CG_CLIP_UNION, input, fill, &none, fill, &simple);
    cg_status st = cg_triangulate64(input, fill, &tri);
    CHECK_MSG(st == CG_OK, "%s %d: %s", what, trial, cg_status_str(st));
    size_t nt = tri.ring_count, nr = simple.point_count;
    edge *edges = malloc((3 * nt + nr * nr + nr + 1) * sizeof *edges);
    size_t ne = 0;
    i128 area = 0, want = 0;
    int bad = 0;
    for (size_t t = 0; t < nt; t++) {
        const cg_point64 *p = tri.points + tri.ring_start[t];
        bad += tri.ring_start[t + 1] - tri.ring_start[t] != 3;
        i128 a = shapes_cross64(p[0], p[1], p[2]);
        bad += a <= 0;
        area += a;
        for (int k = 0; k < 3; k++)
            edges[ne++] = (edge){p[k], p[(k + 1) % 3], (int)t, 0};
    }
    CHECK_MSG(bad == 0, "%s %d: %d triangles not counter-clockwise with area", what, trial, bad);
    for (size_t r = 0; r < simple.ring_count; r++) {
        size_t a = simple.ring_start[r], b = simple.ring_start[r + 1];
        for (size_t i = a; i + 2 < b; i++)
            want += shapes_cross64(simple.points[a], simple.points[i + 1], simple.points[i + 2]);
        for (size_t i = a; i < b; i++)
            ne += ring_pieces(&simple, simple.points[i], simple.points[i + 1 < b ? i + 1 : a],
                              edges + ne);
    }
    CHECK_MSG(area == want, "%s %d: twice the areas %.0f, of the region %.0f", what, trial,
              (double)area, (double)want);
    qsort(edges, ne, sizeof *edges, compare_edges);
    int unmatched = 0, duplicated = 0, not_delaunay = 0, steiner = 0, missing = 0;
    for (size_t i = 0; i < ne; i++) {
        edge *e = &edges[i];
        if (i + 1 < ne && compare_edges(e, &edges[i + 1]) == 0)
            duplicated++;
        if (e->ring) {
            missing += find(edges, ne, e->from, e->to, 0) == NULL;
            continue;
        }
        edge *twin = find(edges, ne, e->to, e->from, 0);
        if (find(edges, ne, e->from, e->to, 1))
            continue; /* a ring edge: nothing beyond it */
        if (!twin) {
            unmatched++;
            continue;
        }
        /* locally Delaunay: the far vertex of the twin outside the circle */
        const cg_point64 *p = tri.points + tri.ring_start[e->triangle];
        const cg_point64 *q = tri.points + tri.ring_start[twin->triangle];
        cg_point64 far = q[0];
        for (int k = 0; k < 3; k++)
            if (!same(q[k], e->from) && !same(q[k], e->to))
                far = q[k];
        not_delaunay += in_circle(p[0], p[1], p[2], far);
    }
    for (size_t i = 0; i < tri.point_count; i++) {
        int found = 0;
        for (size_t j = 0; j < nr && !found; j++)
            found = same(tri.points[i], simple.points[j]);
        steiner += !found;
    }
    CHECK_MSG(duplicated == 0, "%s %d: %d edges twice", what, trial, duplicated);
    CHECK_MSG(unmatched == 0, "%s %d: %d edges with no twin", what, trial, unmatched);
    CHECK_MSG(missing == 0, "%s %d: %d ring edges missing", what, trial, missing);
    CHECK_MSG(not_delaunay == 0, "%s %d: %d edges not Delaunay", what, trial, not_delaunay);
    CHECK_MSG(steiner == 0, "%s %d: %d points added", what, trial, steiner);
    free(edges);
    cg_polygon_set64_clear(&simple);
    cg_polygon_set64_clear(&tri);
}

static void random_rings(cg_polygon_set64 *s, int rings, int points, int64_t extent)
{
    cg_polygon_set64_clear(s);
    for (int r = 0; r < rings; r++) {
        cg_point64 p[200];
        int n = 3 + (int)shapes_int(0, points - 3);
        for (int i = 0; i < n; i++)
            p[i] = (cg_point64){shapes_int(-extent, extent), shapes_int(-extent, extent)};
        cg_polygon_set64_add_ring(s, p, (size_t)n, 1);
    }
}

static void random_polygons(void)
{
    cg_polygon_set64 s = {0};
    for (int trial = 0; trial < 300; trial++) {
        random_rings(&s, 1 + (int)shapes_int(0, 3), 60, 500000);
        check_triangulation("random", trial, &s, (cg_clip_fill)(trial % 4));
    }
    cg_polygon_set64_clear(&s);
}

/* Rings on a 6 x 6 grid: collinear runs, shared vertices, touching holes. */
static void coarse_grid(void)
{
    cg_polygon_set64 s = {0};
    for (int trial = 0; trial < 400; trial++) {
        random_rings(&s, 1 + (int)shapes_int(0, 4), 12, 3);
        for (size_t i = 0; i < s.point_count; i++) {
            s.points[i].x *= 1000;
            s.points[i].y *= 1000;
        }
        check_triangulation("grid", trial, &s, (cg_clip_fill)(trial % 4));
    }
    cg_polygon_set64_clear(&s);
}

/* A square with a chessboard of square holes touching at their corners, a
 * comb, a spiral: many collinear vertices and long thin triangles. */
static void structured(void)
{
    cg_polygon_set64 s = {0};
    cg_point64 outer[4] = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
    cg_polygon_set64_add_ring(&s, outer, 4, 1);
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 8; j++)
            if ((i + j) % 2 == 0) {
                int64_t x = 100 + 100 * i, y = 100 + 100 * j;
                cg_point64 h[4] = {{x, y}, {x, y + 100}, {x + 100, y + 100}, {x + 100, y}};
                cg_polygon_set64_add_ring(&s, h, 4, 1);
            }
    check_triangulation("chessboard", 0, &s, CG_CLIP_EVEN_ODD);
    cg_polygon_set64_clear(&s);
    cg_point64 comb[2 * 40 + 2];
    int n = 0;
    for (int k = 0; k < 20; k++) {
        comb[n++] = (cg_point64){10 * k, 0};
        comb[n++] = (cg_point64){10 * k + 5, 1000};
    }
    comb[n++] = (cg_point64){200, 0};
    comb[n++] = (cg_point64){200, -10};
    comb[n++] = (cg_point64){0, -10};
    cg_polygon_set64_add_ring(&s, comb, (size_t)n, 1);
    check_triangulation("comb", 0, &s, CG_CLIP_NON_ZERO);
    cg_polygon_set64_clear(&s);
    cg_point64 spiral[400];
    n = 0;
    for (int k = 0; k < 200; k++) {
        double a = 0.15 * k, r = 100 + 40 * a;
        spiral[n++] = (cg_point64){llround(r * cos(a)) * 10, llround(r * sin(a)) * 10};
    }
    for (int k = 199; k >= 0; k--) {
        double a = 0.15 * k, r = 130 + 40 * a;
        spiral[n++] = (cg_point64){llround(r * cos(a)) * 10, llround(r * sin(a)) * 10};
    }
    cg_polygon_set64_add_ring(&s, spiral, (size_t)n, 1);
    check_triangulation("spiral", 0, &s, CG_CLIP_NON_ZERO);
    /* points on one circle: every in-circle test is a tie */
    cg_polygon_set64_clear(&s);
    cg_point64 circle[8] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {0, -5}};
    cg_polygon_set64_add_ring(&s, circle, 8, 1);
    check_triangulation("cocircular", 0, &s, CG_CLIP_NON_ZERO);
    cg_polygon_set64_clear(&s);
}

static void double_api_and_bad_input(void)
{
    cg_polygon_set sq = {0}, out = {0};
    cg_vec2 p[4] = {{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
    cg_polygon_set_add_ring(&sq, p, 4, 1);
    CHECK(cg_triangulate(&sq, CG_CLIP_EVEN_ODD, 0, &out) == CG_OK);
    CHECK_EQ_INT(out.polygon_count, 2);
    CHECK_NEAR(cg_polygon_set_area(&out), 0.25, 1e-15);
    cg_polygon_set empty = {0};
    CHECK(cg_triangulate(&empty, CG_CLIP_EVEN_ODD, 0, &out) == CG_OK);
    CHECK_EQ_INT(out.polygon_count, 0);
    CHECK(cg_triangulate(&sq, (cg_clip_fill)5, 0, &out) == CG_EINVAL);
    CHECK(cg_triangulate(NULL, CG_CLIP_EVEN_ODD, 0, &out) == CG_EINVAL);
    cg_vec2 bad[3] = {{0, 0}, {1, 0}, {INFINITY, 1}};
    cg_polygon_set_add_ring(&empty, bad, 3, 1);
    CHECK(cg_triangulate(&empty, CG_CLIP_EVEN_ODD, 0, &out) == CG_EINVAL);
    cg_polygon_set_clear(&empty);
    cg_polygon_set_clear(&sq);
    cg_polygon_set_clear(&out);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(random_polygons);
    CHECK_GROUP(coarse_grid);
    CHECK_GROUP(structured);
    CHECK_GROUP(double_api_and_bad_input);
    return check_finish();
}
