/* Triangulation of polygonal faces (cg_mesh_triangulate_face,
 * cg_mesh_triangulate) against its definition: n - 2 triangles of the
 * face's own corners, none clockwise, none overlapping another, none
 * crossing the outline, each inside the face, their areas adding up to the
 * face's area; the fan wherever the fan is exact.  Checked in exact integer
 * arithmetic over thousands of random simple polygons (star-shaped and
 * not, orthogonal combs and spirals, faces with a hole joined by a bridge)
 * with collinear and repeated corners inserted and the first corner
 * rotated, then the same faces turned into random planes of 3D space, made
 * slightly non-planar, and given bad input. */
#include "cg.h"
#include "check.h"

#include <string.h>

#define MAX_CORNERS 4096

typedef struct polygon {
    int n;
    long long x[MAX_CORNERS], y[MAX_CORNERS];
} polygon;

static long long orient(long long ax, long long ay, long long bx, long long by, long long cx,
                        long long cy)
{
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

static int sign(long long v)
{
    return (v > 0) - (v < 0);
}

/* Twice the signed area. */
static long long twice_area(const polygon *p)
{
    long long s = 0;
    for (int i = 0; i < p->n; i++) {
        int j = (i + 1) % p->n;
        s += p->x[i] * p->y[j] - p->x[j] * p->y[i];
    }
    return s;
}

static int on_segment(long long ax, long long ay, long long bx, long long by, long long px,
                      long long py)
{
    return orient(ax, ay, bx, by, px, py) == 0 && px >= (ax < bx ? ax : bx)
           && px <= (ax > bx ? ax : bx) && py >= (ay < by ? ay : by) && py <= (ay > by ? ay : by);
}

/* Closed segments a-b and c-d share a point. */
static int segments_touch(long long ax, long long ay, long long bx, long long by, long long cx,
                          long long cy, long long dx, long long dy)
{
    int o1 = sign(orient(ax, ay, bx, by, cx, cy)), o2 = sign(orient(ax, ay, bx, by, dx, dy));
    int o3 = sign(orient(cx, cy, dx, dy, ax, ay)), o4 = sign(orient(cx, cy, dx, dy, bx, by));
    if (o1 * o2 < 0 && o3 * o4 < 0)
        return 1;
    return on_segment(ax, ay, bx, by, cx, cy) || on_segment(ax, ay, bx, by, dx, dy)
           || on_segment(cx, cy, dx, dy, ax, ay) || on_segment(cx, cy, dx, dy, bx, by);
}

/* Open segments a-b and c-d cross at a single interior point of both. */
static int segments_cross(long long ax, long long ay, long long bx, long long by, long long cx,
                          long long cy, long long dx, long long dy)
{
    int o1 = sign(orient(ax, ay, bx, by, cx, cy)), o2 = sign(orient(ax, ay, bx, by, dx, dy));
    int o3 = sign(orient(cx, cy, dx, dy, ax, ay)), o4 = sign(orient(cx, cy, dx, dy, bx, by));
    return o1 * o2 < 0 && o3 * o4 < 0;
}

/* No two edges meet except consecutive ones at their shared corner. */
static int is_simple(const polygon *p)
{
    int n = p->n;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            int i2 = (i + 1) % n, j2 = (j + 1) % n;
            if (j == i2 || i == j2) {
                /* neighbours: only the shared corner, no folding back */
                int k = j == i2 ? i : j, m = j == i2 ? i2 : i, l = j == i2 ? j2 : i2;
                if (orient(p->x[k], p->y[k], p->x[m], p->y[m], p->x[l], p->y[l]) == 0)
                    return 0;
                continue;
            }
            if (segments_touch(p->x[i], p->y[i], p->x[i2], p->y[i2], p->x[j], p->y[j], p->x[j2],
                               p->y[j2]))
                return 0;
        }
    return 1;
}

/* Winding number of the polygon around (px, py), the polygon scaled by s. */
static int winding(const polygon *p, long long s, long long px, long long py)
{
    int w = 0;
    for (int i = 0; i < p->n; i++) {
        int j = (i + 1) % p->n;
        long long ax = s * p->x[i], ay = s * p->y[i], bx = s * p->x[j], by = s * p->y[j];
        if (ay <= py) {
            if (by > py && orient(ax, ay, bx, by, px, py) > 0)
                w++;
        } else if (by <= py && orient(ax, ay, bx, by, px, py) < 0) {
            w--;
        }
    }
    return w;
}

static cg_mesh *mesh_of(const polygon *p)
{
    cg_mesh *m;
    if (cg_mesh_create(&m, (size_t)p->n, 1, (size_t)p->n, 0) != CG_OK)
        return NULL;
    for (int i = 0; i < p->n; i++) {
        m->positions[i] = cg_vec3_make((double)p->x[i], (double)p->y[i], 0);
        m->face_indices[i] = (uint32_t)i;
    }
    m->face_offsets[1] = (uint32_t)p->n;
    return m;
}

/* The triangles of the corners of p's face, checked exactly against the
 * definition; returns 1 when every check holds. */
static int check_exact(const polygon *p, uint32_t (*t)[3], const char *what)
{
    int n = p->n, ok = 1;
    long long sum = 0;
    for (int a = 0; a < n - 2 && ok; a++) {
        int i = (int)t[a][0], j = (int)t[a][1], k = (int)t[a][2];
        if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n || i == j || j == k || i == k) {
            CHECK_MSG(0, "%s: triangle %d has corners %d %d %d of %d", what, a, i, j, k, n);
            return 0;
        }
        long long area = orient(p->x[i], p->y[i], p->x[j], p->y[j], p->x[k], p->y[k]);
        if (area < 0) {
            CHECK_MSG(0, "%s: triangle %d (%d %d %d) is clockwise", what, a, i, j, k);
            return 0;
        }
        sum += area;
        if (area == 0)
            continue;
        /* inside: its centroid is inside the face, no edge crosses the outline */
        long long cx = p->x[i] + p->x[j] + p->x[k], cy = p->y[i] + p->y[j] + p->y[k];
        if (winding(p, 3, cx, cy) != 1) {
            CHECK_MSG(0, "%s: triangle %d (%d %d %d) lies outside the face", what, a, i, j, k);
            return 0;
        }
        const int c[3] = {i, j, k};
        for (int e = 0; e < 3 && ok; e++)
            for (int q = 0; q < n && ok; q++) {
                int q2 = (q + 1) % n, u = c[e], v = c[(e + 1) % 3];
                if (segments_cross(p->x[u], p->y[u], p->x[v], p->y[v], p->x[q], p->y[q], p->x[q2],
                                   p->y[q2])) {
                    CHECK_MSG(0, "%s: triangle %d crosses edge %d", what, a, q);
                    ok = 0;
                }
            }
    }
    if (!ok)
        return 0;
    if (sum != twice_area(p)) {
        CHECK_MSG(0, "%s: triangles' area %lld, face's %lld", what, sum, twice_area(p));
        return 0;
    }
    /* no overlap: two triangles of positive area are separated by a line
     * through an edge of one of them */
    for (int a = 0; a < n - 2; a++) {
        const uint32_t *A = t[a];
        if (orient(p->x[A[0]], p->y[A[0]], p->x[A[1]], p->y[A[1]], p->x[A[2]], p->y[A[2]]) == 0)
            continue;
        for (int b = a + 1; b < n - 2; b++) {
            const uint32_t *B = t[b];
            if (orient(p->x[B[0]], p->y[B[0]], p->x[B[1]], p->y[B[1]], p->x[B[2]], p->y[B[2]]) == 0)
                continue;
            int separated = 0;
            for (int side = 0; side < 2 && !separated; side++) {
                const uint32_t *P = side ? B : A, *Q = side ? A : B;
                for (int e = 0; e < 3 && !separated; e++) {
                    uint32_t u = P[e], v = P[(e + 1) % 3];
                    int all_out = 1;
                    for (int m = 0; m < 3; m++)
                        all_out &= orient(p->x[u], p->y[u], p->x[v], p->y[v], p->x[Q[m]],
                                          p->y[Q[m]])
                                   <= 0;
                    separated = all_out;
                }
            }
            if (!separated) {
                CHECK_MSG(0, "%s: triangles %d and %d overlap", what, a, b);
                return 0;
            }
        }
    }
    return 1;
}

static int is_fan(uint32_t (*t)[3], int n)
{
    for (int k = 0; k < n - 2; k++)
        if (t[k][0] != 0 || t[k][1] != (uint32_t)k + 1 || t[k][2] != (uint32_t)k + 2)
            return 0;
    return 1;
}

static uint32_t (*triangles_of(const polygon *p))[3]
{
    cg_mesh *m = mesh_of(p);
    uint32_t(*t)[3] = malloc((size_t)p->n * sizeof *t);
    CHECK(m && t);
    if (!m || !t) {
        cg_mesh_free(m);
        free(t);
        return NULL;
    }
    cg_status s = cg_mesh_triangulate_face(m, 0, t);
    CHECK_EQ_INT(s, CG_OK);
    cg_mesh_free(m);
    return t;
}

/* Triangulates p and checks it; returns 1 when it held. */
static int check_polygon(const polygon *p, const char *what)
{
    uint32_t(*t)[3] = triangles_of(p);
    if (!t)
        return 0;
    int ok = check_exact(p, t, what);
    CHECK(ok);
    free(t);
    return ok;
}

static long long rng_int(check_rng *r, long long lo, long long hi)
{
    return lo + (long long)(check_rng_next(r) % (uint64_t)(hi - lo + 1));
}

/* Random star-shaped polygon around the origin (k corners, radius r); 0
 * when rounding made it non-simple. */
static int random_star(check_rng *rng, polygon *p, int k, double radius)
{
    double angle[MAX_CORNERS];
    for (int i = 0; i < k; i++)
        angle[i] = 2 * CG_PI * check_rng_unit(rng);
    for (int i = 1; i < k; i++)
        for (int j = i; j > 0 && angle[j - 1] > angle[j]; j--) {
            double s = angle[j];
            angle[j] = angle[j - 1];
            angle[j - 1] = s;
        }
    p->n = k;
    for (int i = 0; i < k; i++) {
        double r = radius * (0.15 + 0.85 * check_rng_unit(rng));
        p->x[i] = llround(r * cos(angle[i]));
        p->y[i] = llround(r * sin(angle[i]));
    }
    return is_simple(p) && twice_area(p) > 0;
}

/* Random simple polygon through k random points: 2-opt moves undo every
 * crossing (each shortens the tour, so it ends); 0 when the points are not
 * in general position. */
static int random_two_opt(check_rng *rng, polygon *p, int k, long long range)
{
    p->n = k;
    for (int i = 0; i < k; i++) {
        p->x[i] = rng_int(rng, -range, range);
        p->y[i] = rng_int(rng, -range, range);
    }
    for (int i = 0; i < k; i++)
        for (int j = i + 1; j < k; j++)
            for (int l = j + 1; l < k; l++)
                if (orient(p->x[i], p->y[i], p->x[j], p->y[j], p->x[l], p->y[l]) == 0)
                    return 0;
    for (int round = 0; round < 10000; round++) {
        int changed = 0;
        for (int i = 0; i < k && !changed; i++)
            for (int j = i + 2; j < k && !changed; j++) {
                int i2 = i + 1, j2 = (j + 1) % k;
                if (j2 == i)
                    continue;
                if (segments_cross(p->x[i], p->y[i], p->x[i2], p->y[i2], p->x[j], p->y[j], p->x[j2],
                                   p->y[j2])) {
                    for (int a = i2, b = j; a < b; a++, b--) {
                        long long sx = p->x[a], sy = p->y[a];
                        p->x[a] = p->x[b];
                        p->y[a] = p->y[b];
                        p->x[b] = sx;
                        p->y[b] = sy;
                    }
                    changed = 1;
                }
            }
        if (!changed)
            break;
    }
    if (!is_simple(p))
        return 0;
    if (twice_area(p) < 0)
        for (int a = 0, b = k - 1; a < b; a++, b--) {
            long long sx = p->x[a], sy = p->y[a];
            p->x[a] = p->x[b];
            p->y[a] = p->y[b];
            p->x[b] = sx;
            p->y[b] = sy;
        }
    return 1;
}

/* An orthogonal comb: a base bar and `teeth` teeth of random heights. */
static void comb(check_rng *rng, polygon *p, int teeth)
{
    int n = 0;
    long long w = 2 * teeth + 1;
    p->x[n] = 0, p->y[n++] = 0;
    p->x[n] = w, p->y[n++] = 0;
    for (int i = teeth - 1; i >= 0; i--) {
        long long h = rng_int(rng, 2, 9);
        long long right = 2 * i + 2, left = 2 * i + 1;
        if (i == teeth - 1) {
            p->x[n] = w, p->y[n++] = h;
        } else {
            p->x[n] = right, p->y[n++] = 1;
            p->x[n] = right, p->y[n++] = h;
        }
        p->x[n] = left, p->y[n++] = h;
        p->x[n] = left, p->y[n++] = 1;
    }
    p->x[n] = 0, p->y[n++] = 1;
    p->n = n;
}

/* A square spiral of `turns` quarter turns: a corridor 2 wide around a
 * centre line whose arms grow by 4, walls offset 1 to either side. */
static void spiral(polygon *p, int turns)
{
    static const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
    long long cx[256], cy[256];
    int m = turns + 1;
    cx[0] = 0, cy[0] = 0;
    for (int t = 0; t < turns; t++) {
        long long len = 4 * (t / 2 + 1);
        cx[t + 1] = cx[t] + dx[t % 4] * len;
        cy[t + 1] = cy[t] + dy[t % 4] * len;
    }
    int n = 0;
    for (int side = 0; side < 2; side++)
        for (int i = 0; i < m; i++) {
            int t = side ? i : m - 1 - i; /* right wall forward, left wall back */
            int in = t > 0 ? (t - 1) % 4 : 0, out = t < turns ? t % 4 : (turns - 1) % 4;
            long long ox = -dy[in] - (t > 0 && t < turns ? dy[out] : 0);
            long long oy = dx[in] + (t > 0 && t < turns ? dx[out] : 0);
            if (t == 0)
                ox = -dy[out], oy = dx[out];
            long long s = side ? -1 : 1;
            p->x[n] = cx[t] + s * ox;
            p->y[n++] = cy[t] + s * oy;
        }
    p->n = n;
    if (twice_area(p) < 0)
        for (int a = 0, b = n - 1; a < b; a++, b--) {
            long long sx = p->x[a], sy = p->y[a];
            p->x[a] = p->x[b];
            p->y[a] = p->y[b];
            p->x[b] = sx;
            p->y[b] = sy;
        }
}

/* A regular-ish outline with a hole joined to it by a bridge (a face that
 * touches itself along the bridge, its two ends repeated). */
static void keyhole(check_rng *rng, polygon *p, int outer, int inner)
{
    int n = 0;
    long long R = rng_int(rng, 400, 1000), r = rng_int(rng, 50, 300);
    for (int i = 0; i <= outer; i++) {
        double a = 2 * CG_PI * (i % outer) / outer;
        p->x[n] = llround(R * cos(a)), p->y[n++] = llround(R * sin(a));
    }
    for (int i = 0; i <= inner; i++) {
        double a = -2 * CG_PI * (i % inner) / inner;
        p->x[n] = llround(r * cos(a)), p->y[n++] = llround(r * sin(a));
    }
    p->n = n;
}

/* Doubles coordinates and inserts the midpoint of `count` random edges
 * (collinear corners) and repeats `repeats` random corners. */
static void add_degeneracies(check_rng *rng, polygon *p, int count, int repeats)
{
    for (int i = 0; i < p->n; i++) {
        p->x[i] *= 2;
        p->y[i] *= 2;
    }
    for (int c = 0; c < count + repeats && p->n < MAX_CORNERS; c++) {
        int i = (int)rng_int(rng, 0, p->n - 1), j = (i + 1) % p->n;
        long long mx = c < count ? (p->x[i] + p->x[j]) / 2 : p->x[i];
        long long my = c < count ? (p->y[i] + p->y[j]) / 2 : p->y[i];
        if (c < count && ((p->x[i] + p->x[j]) % 2 || (p->y[i] + p->y[j]) % 2))
            continue;
        memmove(p->x + i + 2, p->x + i + 1, (size_t)(p->n - i - 1) * sizeof *p->x);
        memmove(p->y + i + 2, p->y + i + 1, (size_t)(p->n - i - 1) * sizeof *p->y);
        p->x[i + 1] = mx;
        p->y[i + 1] = my;
        p->n++;
    }
}

static void rotate_start(polygon *p, int by)
{
    polygon q = *p;
    for (int i = 0; i < p->n; i++) {
        p->x[i] = q.x[(i + by) % p->n];
        p->y[i] = q.y[(i + by) % p->n];
    }
}

static void test_random_simple(void)
{
    check_rng rng = {20261202};
    static polygon p;
    int stars = 0, others = 0;
    for (int c = 0; c < 3000; c++) {
        int k = (int)rng_int(&rng, 3, c % 10 < 2 ? (c % 2 ? 300 : 100) : 14);
        int made = c % 2 ? random_star(&rng, &p, k, (double)rng_int(&rng, 20, 100000))
                         : random_two_opt(&rng, &p, k, rng_int(&rng, 10, 100000));
        if (!made)
            continue;
        if (c % 2)
            stars++;
        else
            others++;
        check_polygon(&p, c % 2 ? "star" : "2-opt");
        add_degeneracies(&rng, &p, (int)rng_int(&rng, 0, 4), (int)rng_int(&rng, 0, 3));
        rotate_start(&p, (int)rng_int(&rng, 0, p.n - 1));
        check_polygon(&p, c % 2 ? "star, collinear and repeated" : "2-opt, collinear and repeated");
    }
    CHECK_MSG(stars > 1000 && others > 1000, "%d star-shaped and %d other polygons", stars, others);
}

static void test_orthogonal_and_holes(void)
{
    check_rng rng = {7};
    static polygon p;
    for (int c = 0; c < 300; c++) {
        comb(&rng, &p, (int)rng_int(&rng, 1, 20));
        CHECK(is_simple(&p));
        rotate_start(&p, (int)rng_int(&rng, 0, p.n - 1));
        check_polygon(&p, "comb");
        add_degeneracies(&rng, &p, 3, 2);
        check_polygon(&p, "comb, collinear and repeated");
    }
    for (int turns = 1; turns <= 40; turns++) {
        spiral(&p, turns);
        CHECK_MSG(is_simple(&p), "spiral of %d turns is simple", turns);
        for (int r = 0; r < p.n; r += 3) {
            polygon q = p;
            rotate_start(&q, r);
            check_polygon(&q, "spiral");
        }
    }
    for (int c = 0; c < 300; c++) {
        keyhole(&rng, &p, (int)rng_int(&rng, 3, 40), (int)rng_int(&rng, 3, 40));
        rotate_start(&p, (int)rng_int(&rng, 0, p.n - 1));
        check_polygon(&p, "ring with a bridge");
    }
}

/* The L-shaped hexagon whose fan from its first corner covers the notch. */
static void test_l_hexagon(void)
{
    polygon p = {6, {2, 1, 1, 0, 0, 2}, {1, 1, 2, 2, 0, 0}};
    uint32_t(*t)[3] = triangles_of(&p);
    if (!t)
        return;
    CHECK(check_exact(&p, t, "L hexagon"));
    CHECK(!is_fan(t, p.n));
    free(t);
}

/* Convex faces (and any face whose fan is exact) keep the fan. */
static void test_fan_kept(void)
{
    check_rng rng = {99};
    static polygon p;
    for (int c = 0; c < 2000; c++) {
        int k = (int)rng_int(&rng, 3, 40);
        long long r = rng_int(&rng, 50, 1000000);
        /* corners of a circle, in order: convex; with repeats and midpoints */
        double start = 2 * CG_PI * check_rng_unit(&rng);
        p.n = k;
        for (int i = 0; i < k; i++) {
            double a = start + 2 * CG_PI * i / k;
            p.x[i] = llround(r * cos(a));
            p.y[i] = llround(r * sin(a));
        }
        if (!is_simple(&p))
            continue;
        if (c % 2)
            add_degeneracies(&rng, &p, 2, 1);
        uint32_t(*t)[3] = triangles_of(&p);
        if (!t)
            return;
        CHECK_MSG(is_fan(t, p.n), "convex face of %d corners keeps the fan", p.n);
        check_exact(&p, t, "convex");
        free(t);
    }
    /* star-shaped from the first corner though concave elsewhere */
    polygon l = {6, {0, 2, 2, 1, 1, 0}, {0, 0, 1, 1, 2, 2}};
    uint32_t(*t)[3] = triangles_of(&l);
    if (t) {
        CHECK(is_fan(t, l.n));
        free(t);
    }
}

/* The same faces in random planes of space, exactly planar up to rounding
 * and then bent slightly out of their plane: the triangles, measured in
 * the face's own plane coordinates, still tile the face. */
static void test_in_space(void)
{
    check_rng rng = {1234};
    static polygon p;
    for (int c = 0; c < 1500; c++) {
        int k = (int)rng_int(&rng, 4, 30);
        if (!(c % 3 ? random_two_opt(&rng, &p, k, 1000) : random_star(&rng, &p, k, 1000)))
            continue;
        cg_mat4 m = cg_mat4_mul(cg_xform3_translate(check_rng_unit(&rng) * 100, 5, -7),
                                cg_mat4_mul(cg_xform3_rotate_x(2 * CG_PI * check_rng_unit(&rng)),
                                            cg_xform3_rotate_y(2 * CG_PI * check_rng_unit(&rng))));
        cg_mesh *mesh = mesh_of(&p);
        uint32_t(*t)[3] = malloc((size_t)p.n * sizeof *t);
        if (!mesh || !t) {
            CHECK(0);
            cg_mesh_free(mesh);
            free(t);
            return;
        }
        cg_vec3 normal = cg_mat4_transform_vector(m, cg_vec3_make(0, 0, 1));
        double bend = c % 2 ? 1e-6 : 0;
        for (int i = 0; i < p.n; i++) {
            cg_vec3 q = cg_mat4_transform_point(m, mesh->positions[i]);
            mesh->positions[i] = cg_vec3_add(
                q, cg_vec3_scale(normal, bend * (check_rng_unit(&rng) - 0.5)));
        }
        CHECK_EQ_INT(cg_mesh_triangulate_face(mesh, 0, t), CG_OK);
        check_exact(&p, t, bend > 0 ? "in space, slightly bent" : "in space");
        free(t);
        cg_mesh_free(mesh);
    }
}

/* Whole meshes: cg_mesh_triangulate is every face's triangulation in turn. */
static void test_whole_mesh(void)
{
    check_rng rng = {5};
    static polygon p[20];
    size_t vertices = 0, corners = 0;
    int faces = 0;
    for (int c = 0; faces < 20; c++)
        if (random_two_opt(&rng, &p[faces], (int)rng_int(&rng, 3, 25), 500)) {
            vertices += (size_t)p[faces].n;
            corners += (size_t)p[faces].n;
            faces++;
        }
    cg_mesh *m;
    CHECK_EQ_INT(cg_mesh_create(&m, vertices, 20, corners, 0), CG_OK);
    size_t v = 0;
    for (int f = 0; f < faces; f++) {
        for (int i = 0; i < p[f].n; i++, v++) {
            m->positions[v] = cg_vec3_make((double)p[f].x[i], (double)p[f].y[i], 0);
            m->face_indices[v] = (uint32_t)v;
        }
        m->face_offsets[f + 1] = (uint32_t)v;
    }
    size_t count = cg_mesh_triangle_count(m);
    CHECK_EQ_INT(count, corners - 2 * 20);
    uint32_t(*all)[3] = malloc(count * sizeof *all), (*one)[3] = malloc(64 * sizeof *one);
    CHECK_EQ_INT(cg_mesh_triangulate(m, all), CG_OK);
    size_t t = 0;
    for (int f = 0; f < faces; f++) {
        CHECK_EQ_INT(cg_mesh_triangulate_face(m, (size_t)f, one), CG_OK);
        CHECK(memcmp(one, all + t, (size_t)(p[f].n - 2) * sizeof *one) == 0);
        /* corner numbers are the mesh's: shift back to the face's own */
        for (int k = 0; k < p[f].n - 2; k++)
            for (int j = 0; j < 3; j++)
                one[k][j] -= m->face_offsets[f];
        check_exact(&p[f], one, "face of a mesh");
        t += (size_t)p[f].n - 2;
    }
    free(all);
    free(one);
    cg_mesh_free(m);
}

/* Degenerate and hostile faces: n - 2 triangles of the face's corners, no
 * hang, clear errors for bad arguments. */
static void test_degenerate(void)
{
    check_rng rng = {77};
    static polygon p;
    for (int c = 0; c < 500; c++) {
        /* random corners in any order: self-intersecting faces */
        int k = (int)rng_int(&rng, 3, 50);
        p.n = k;
        for (int i = 0; i < k; i++) {
            p.x[i] = rng_int(&rng, -5, 5);
            p.y[i] = c % 5 == 0 ? 2 * p.x[i] : rng_int(&rng, -5, 5); /* every 5th on a line */
        }
        uint32_t(*t)[3] = triangles_of(&p);
        if (!t)
            return;
        int ok = 1;
        for (int a = 0; a < k - 2; a++)
            for (int j = 0; j < 3; j++)
                ok &= t[a][j] < (uint32_t)k && t[a][j] != t[a][(j + 1) % 3];
        CHECK_MSG(ok, "self-intersecting face of %d corners gives valid triangles", k);
        free(t);
    }
    /* a large spiky star: quadratic work at most */
    p.n = MAX_CORNERS;
    for (int i = 0; i < p.n; i++) {
        double a = 2 * CG_PI * i / p.n, r = i % 2 ? 1000000 : 300000 + 1000 * (i % 7);
        p.x[i] = llround(r * cos(a));
        p.y[i] = llround(r * sin(a));
    }
    uint32_t(*t)[3] = triangles_of(&p);
    if (t) {
        long long sum = 0;
        int clockwise = 0;
        for (int a = 0; a < p.n - 2; a++) {
            long long o = orient(p.x[t[a][0]], p.y[t[a][0]], p.x[t[a][1]], p.y[t[a][1]],
                                 p.x[t[a][2]], p.y[t[a][2]]);
            sum += o;
            clockwise += o < 0;
        }
        CHECK_EQ_INT(sum, twice_area(&p));
        CHECK_EQ_INT(clockwise, 0);
        free(t);
    }
    /* a face of 50,000 random corners crossing itself everywhere: bounded
     * work, still n - 2 triangles of its corners */
    {
        uint32_t big = 50000;
        cg_mesh *r;
        CHECK_EQ_INT(cg_mesh_create(&r, big, 1, big, 0), CG_OK);
        for (uint32_t i = 0; i < big; i++) {
            r->positions[i] = cg_vec3_make((double)rng_int(&rng, 0, 999),
                                           (double)rng_int(&rng, 0, 999), 0);
            r->face_indices[i] = i;
        }
        r->face_offsets[1] = big;
        uint32_t(*rt)[3] = malloc(big * sizeof *rt);
        CHECK_EQ_INT(cg_mesh_triangulate(r, rt), CG_OK);
        int ok = 1;
        for (uint32_t a = 0; a + 2 < big; a++)
            ok &= rt[a][0] < big && rt[a][1] < big && rt[a][2] < big && rt[a][0] != rt[a][1]
                  && rt[a][1] != rt[a][2] && rt[a][0] != rt[a][2];
        CHECK(ok);
        free(rt);
        cg_mesh_free(r);
    }
    /* NaN and infinite corners: the fan, no crash */
    cg_mesh *m;
    CHECK_EQ_INT(cg_mesh_create(&m, 5, 1, 5, 0), CG_OK);
    for (int i = 0; i < 5; i++) {
        m->positions[i] = cg_vec3_make(i % 2, i, 0);
        m->face_indices[i] = (uint32_t)i;
    }
    m->face_offsets[1] = 5;
    m->positions[2].x = NAN;
    uint32_t tri[3][3];
    CHECK_EQ_INT(cg_mesh_triangulate_face(m, 0, tri), CG_OK);
    CHECK(tri[0][0] == 0 && tri[2][2] == 4);
    m->positions[2].x = INFINITY;
    CHECK_EQ_INT(cg_mesh_triangulate_face(m, 0, tri), CG_OK);
    CHECK_EQ_INT(cg_mesh_triangulate_face(m, 1, tri), CG_EINVAL);
    CHECK_EQ_INT(cg_mesh_triangulate_face(NULL, 0, tri), CG_EINVAL);
    CHECK_EQ_INT(cg_mesh_triangulate_face(m, 0, NULL), CG_EINVAL);
    CHECK_EQ_INT(cg_mesh_triangulate(m, NULL), CG_EINVAL);
    m->face_indices[3] = 9;
    CHECK_EQ_INT(cg_mesh_triangulate_face(m, 0, tri), CG_EINVAL);
    CHECK(cg_mesh_triangulate(m, tri) != CG_OK);
    cg_mesh_free(m);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_l_hexagon);
    CHECK_GROUP(test_fan_kept);
    CHECK_GROUP(test_random_simple);
    CHECK_GROUP(test_orthogonal_and_holes);
    CHECK_GROUP(test_in_space);
    CHECK_GROUP(test_whole_mesh);
    CHECK_GROUP(test_degenerate);
    return check_finish();
}
