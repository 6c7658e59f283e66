/* Circles, discs, ellipses, arcs and anti-aliased drawing against their
 * definitions (section 2.2 of the notes), plus bad input. */
#include "check.h"
#include "cg/draw.h"
#include "cg/color.h"
#include "cg/curve.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

static const cg_rgba8 white = {255, 255, 255, 255}, black = {0, 0, 0, 255};

static int is_set(const cg_image *image, int x, int y)
{
    return cg_image_contains(image, x, y) && cg_image_get_rgba8(image, x, y).r == 255;
}

/* ---- the first octant by Algorithm 2, as traced ------------------------ */

typedef struct octant {
    int *row;
    int last;
    int cap;
} octant;

static int record(void *user, const cg_circle_step *s)
{
    octant *o = user;
    if (s->x <= s->y && s->x < o->cap) {
        o->row[s->x] = s->y;
        o->last = s->x;
    }
    return 0;
}

/* Membership of offset (dx, dy) in the digital circle: mirror into the
 * first octant and compare with the traced row. */
static int member(const octant *o, long long dx, long long dy)
{
    long long x = llabs(dx), y = llabs(dy);
    if (x > y) {
        long long t = x;
        x = y;
        y = t;
    }
    return x <= o->last && o->row[x] == y;
}

/* The definition: y-distance of octant pixels to the real circle at most
 * 1/2, unit steps in x, E or SE moves, x <= y. */
static void octant_definition(void)
{
    long bad = 0;
    octant o = {malloc(20000 * sizeof(int)), -1, 20000};
    for (int r = 0; r <= 10000; r++) {
        o.last = -1;
        cg_circle_trace(r, record, &o);
        int ok = o.last >= 0 && o.row[0] == r;
        for (int x = 0; x <= o.last; x++) {
            double real = sqrt((double)r * r - (double)x * x);
            ok &= fabs(o.row[x] - real) <= 0.5 && o.row[x] >= x;
            if (x > 0)
                ok &= o.row[x] == o.row[x - 1] || o.row[x] == o.row[x - 1] - 1;
        }
        /* The octant reaches the diagonal: the next column would cross it. */
        ok &= o.last + 1 > o.row[o.last] - 1 || r == 0;
        if (!ok && bad++ < 5)
            fprintf(stderr, "octant of radius %d breaks the definition\n", r);
    }
    CHECK_EQ_INT(bad, 0);
    free(o.row);
}

/* The drawn circle: exactly the 8-symmetric set of the traced octant, every
 * pixel within 1/2 of the real circle in x or y, closed and 0-connected, and
 * each pixel drawn once (half-transparent drawing gives a single blend). */
static void whole_circles(void)
{
    octant o = {malloc(20000 * sizeof(int)), -1, 20000};
    long bad_set = 0, bad_dist = 0, bad_closed = 0, bad_once = 0;
    cg_rgba8 half = {255, 255, 255, 128};
    cg_image *one;
    cg_image_create(&one, 1, 1, CG_PIXEL_RGBA8);
    cg_image_clear_rgba8(one, black);
    cg_draw_circle(one, 0, 0, 0, half);
    uint8_t once = cg_image_get_rgba8(one, 0, 0).r;
    cg_image_free(one);
    for (int r = 0; r <= 260; r++) {
        int n = 2 * r + 5, c = r + 2;
        cg_image *image;
        cg_image_create(&image, n, n, CG_PIXEL_RGBA8);
        cg_image_clear_rgba8(image, black);
        o.last = -1;
        cg_circle_trace(r, record, &o);
        cg_draw_circle(image, c, c, r, r % 2 ? white : half);
        long count = 0, degree_bad = 0;
        for (int y = 0; y < n; y++)
            for (int x = 0; x < n; x++) {
                cg_rgba8 p = cg_image_get_rgba8(image, x, y);
                int set = p.r != 0;
                if (set != member(&o, x - c, y - c))
                    bad_set++;
                if (!set)
                    continue;
                count++;
                if (r % 2 == 0 && p.r != once)
                    bad_once++;
                double dx = fabs((double)(x - c)), dy = fabs((double)(y - c));
                double xd = dy <= r ? fabs(dx - sqrt((double)r * r - dy * dy)) : 1e9;
                double yd = dx <= r ? fabs(dy - sqrt((double)r * r - dx * dx)) : 1e9;
                if (fmin(xd, yd) > 0.5)
                    bad_dist++;
                /* closed curve: at least two 8-neighbours on the curve */
                int neighbours = 0;
                for (int j = -1; j <= 1; j++)
                    for (int i = -1; i <= 1; i++)
                        if ((i || j) && cg_image_contains(image, x + i, y + j)
                            && cg_image_get_rgba8(image, x + i, y + j).r != 0)
                            neighbours++;
                if (r > 0 && neighbours < 2)
                    degree_bad++;
            }
        if (degree_bad)
            bad_closed++;
        if (r == 0)
            CHECK_EQ_INT(count, 1);
        cg_image_free(image);
    }
    CHECK_EQ_INT(bad_set, 0);
    CHECK_EQ_INT(bad_dist, 0);
    CHECK_EQ_INT(bad_closed, 0);
    CHECK_EQ_INT(bad_once, 0);
    free(o.row);
}

/* Large radii (up to 10,000) and centres off the image: the clipped drawing
 * in a window equals the traced circle there. */
static void clipped_circles(void)
{
    enum { W = 61, H = 47 };
    octant o = {malloc(20000 * sizeof(int)), -1, 20000};
    cg_image *image;
    cg_image_create(&image, W, H, CG_PIXEL_RGBA8);
    check_rng rng = {31337};
    long bad = 0, seen = 0;
    for (int i = 0; i < 600; i++) {
        int r = i < 10 ? 10000 - i : (int)check_rng_int(&rng, 1, 10000);
        o.last = -1;
        cg_circle_trace(r, record, &o);
        /* A centre that puts the curve through the window: pick a window
         * point and an angle. */
        double a = check_rng_range(&rng, 0, 2 * CG_PI);
        int px = (int)check_rng_int(&rng, 0, W - 1), py = (int)check_rng_int(&rng, 0, H - 1);
        int cx = px - (int)lround(r * cos(a)), cy = py - (int)lround(r * sin(a));
        if (i % 7 == 0) { /* and some random ones, maybe missing the window */
            cx = (int)check_rng_int(&rng, -12000, 12000);
            cy = (int)check_rng_int(&rng, -12000, 12000);
        }
        cg_image_clear_rgba8(image, black);
        cg_draw_circle(image, cx, cy, r, white);
        int differ = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int want = member(&o, x - cx, y - cy);
                seen += want;
                differ |= want != is_set(image, x, y);
            }
        if (differ && bad++ < 5)
            fprintf(stderr, "clipped circle (%d, %d) r %d differs\n", cx, cy, r);
    }
    CHECK_EQ_INT(bad, 0);
    CHECK(seen > 10000);
    free(o.row);
    cg_image_free(image);
}

/* Radii near the int limit, centres far away: membership by the closed form
 * y (y - 1) < r^2 - x^2 <= y (y + 1) (checked against the trace above). */
__extension__ typedef __int128 wide;
static int member_closed(long long r, long long dx, long long dy)
{
    long long x = llabs(dx), y = llabs(dy);
    if (r == 0)
        return x == 0 && y == 0;
    if (x > y) {
        long long t = x;
        x = y;
        y = t;
    }
    wide n = (wide)r * r - (wide)x * x;
    return (wide)y * (y - 1) < n && n <= (wide)y * (y + 1) && x <= y;
}

static void huge_circles(void)
{
    enum { W = 40, H = 30 };
    cg_image *image;
    cg_image_create(&image, W, H, CG_PIXEL_RGBA8);
    check_rng rng = {2718};
    long bad = 0, seen = 0;
    for (int i = 0; i < 300; i++) {
        double a = check_rng_range(&rng, 0, 2 * CG_PI);
        long long r = check_rng_int(&rng, 100000, INT_MAX);
        long long px = check_rng_int(&rng, 0, W - 1), py = check_rng_int(&rng, 0, H - 1);
        long long cx = px - llround((double)r * cos(a)), cy = py - llround((double)r * sin(a));
        if (cx < INT_MIN || cx > INT_MAX || cy < INT_MIN || cy > INT_MAX)
            continue;
        cg_image_clear_rgba8(image, black);
        CHECK(cg_draw_circle(image, (int)cx, (int)cy, (int)r, white) == CG_OK);
        int differ = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int want = member_closed(r, x - cx, y - cy);
                seen += want;
                differ |= want != is_set(image, x, y);
            }
        if (differ && bad++ < 5)
            fprintf(stderr, "huge circle (%lld, %lld) r %lld differs\n", cx, cy, r);
    }
    CHECK_EQ_INT(bad, 0);
    CHECK(seen > 1000);
    cg_image_free(image);
}

/* Discs: each row filled from the leftmost to the rightmost circle pixel. */
static void discs(void)
{
    enum { W = 90, H = 70 };
    cg_image *circle, *disc;
    cg_image_create(&circle, W, H, CG_PIXEL_RGBA8);
    cg_image_create(&disc, W, H, CG_PIXEL_RGBA8);
    check_rng rng = {5};
    long bad = 0;
    for (int i = 0; i < 1500; i++) {
        int r = (int)check_rng_int(&rng, 0, i < 1000 ? 40 : 3000);
        int cx = (int)check_rng_int(&rng, -r - 5, W + r + 5),
            cy = (int)check_rng_int(&rng, -r - 5, H + r + 5);
        /* Reference rows come from a big-enough circle drawn around it. */
        cg_image_clear_rgba8(disc, black);
        cg_draw_disc(disc, cx, cy, r, white);
        for (int y = 0; y < H; y++) {
            long long d = llabs((long long)y - cy);
            if (d > r) {
                for (int x = 0; x < W; x++)
                    bad += is_set(disc, x, y);
                continue;
            }
            /* half-width: largest |dx| with (dx, d) on the circle */
            long long w = -1;
            for (long long dx = r; dx >= 0 && w < 0; dx--)
                if (member_closed(r, dx, d))
                    w = dx;
            for (int x = 0; x < W; x++) {
                int want = llabs((long long)x - cx) <= w;
                bad += want != is_set(disc, x, y);
            }
        }
    }
    CHECK_EQ_INT(bad, 0);
    cg_image_free(circle);
    cg_image_free(disc);
}

/* True when the set pixels form one 8-connected component. */
static int connected(const cg_image *image)
{
    int w = image->width, h = image->height, total = 0, reached = 0;
    int *stack = malloc((size_t)w * h * sizeof *stack);
    char *seen = calloc((size_t)w * h, 1);
    int top = 0;
    for (int i = 0; i < w * h; i++)
        if (is_set(image, i % w, i / w)) {
            total++;
            if (top == 0 && reached == 0) {
                stack[top++] = i;
                seen[i] = 1;
            }
        }
    while (top > 0) {
        int i = stack[--top], x = i % w, y = i / w;
        reached++;
        for (int j = -1; j <= 1; j++)
            for (int k = -1; k <= 1; k++) {
                int nx = x + k, ny = y + j;
                if (is_set(image, nx, ny) && !seen[ny * w + nx]) {
                    seen[ny * w + nx] = 1;
                    stack[top++] = ny * w + nx;
                }
            }
    }
    free(stack);
    free(seen);
    return reached == total;
}

/* Ellipses: 4-symmetric, each pixel within 1/2 of the real ellipse in x or
 * y, closed and 0-connected; equal radii give the midpoint circle. */
static void ellipses(void)
{
    check_rng rng = {11};
    long bad_sym = 0, bad_dist = 0, bad_closed = 0, bad_circle = 0;
    for (int i = 0; i < 1500; i++) {
        int rx = (int)check_rng_int(&rng, 0, 150), ry = (int)check_rng_int(&rng, 0, 150);
        if (i % 5 == 0)
            ry = (int)check_rng_int(&rng, 0, 4); /* flat ones */
        if (i % 9 == 0)
            ry = rx;
        int w = 2 * rx + 5, h = 2 * ry + 5, cx = rx + 2, cy = ry + 2;
        cg_image *image;
        cg_image_create(&image, w, h, CG_PIXEL_RGBA8);
        cg_image_clear_rgba8(image, black);
        cg_draw_ellipse(image, cx, cy, rx, ry, white);
        int sym = 1, dist = 1, closed = 1;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                if (!is_set(image, x, y))
                    continue;
                int mx = 2 * cx - x, my = 2 * cy - y;
                sym &= is_set(image, mx, y) && is_set(image, x, my);
                double dx = fabs((double)(x - cx)), dy = fabs((double)(y - cy));
                double xd = dy <= ry && ry > 0
                                ? fabs(dx - rx * sqrt(1 - dy * dy / ((double)ry * ry)))
                                : (dy == 0 ? fabs(dx - rx) : 1e9);
                double yd = dx <= rx && rx > 0
                                ? fabs(dy - ry * sqrt(1 - dx * dx / ((double)rx * rx)))
                                : (dx == 0 ? fabs(dy - ry) : 1e9);
                if (ry == 0 || rx == 0)
                    xd = yd = 0; /* degenerate: a segment */
                dist &= fmin(xd, yd) <= 0.5 + 1e-9;
                int neighbours = 0;
                for (int j = -1; j <= 1; j++)
                    for (int k = -1; k <= 1; k++)
                        neighbours += (j || k) && is_set(image, x + k, y + j);
                /* Thin ellipses may end in a one-pixel spur at a tip, so
                 * each pixel needs one neighbour here; connectivity of the
                 * whole curve is checked below. */
                if (rx > 0 && ry > 0)
                    closed &= neighbours >= 1;
            }
        closed &= connected(image);
        if (!dist && bad_dist < 5)
            fprintf(stderr, "ellipse %d x %d: a pixel farther than 1/2\n", rx, ry);
        bad_sym += !sym;
        bad_dist += !dist;
        bad_closed += !closed;
        if (rx == ry) {
            cg_image *c;
            cg_image_create(&c, w, h, CG_PIXEL_RGBA8);
            cg_image_clear_rgba8(c, black);
            cg_draw_circle(c, cx, cy, rx, white);
            bad_circle += memcmp(c->data, image->data, (size_t)h * image->stride) != 0;
            cg_image_free(c);
        }
        cg_image_free(image);
    }
    CHECK_EQ_INT(bad_sym, 0);
    CHECK_EQ_INT(bad_dist, 0);
    CHECK_EQ_INT(bad_closed, 0);
    CHECK_EQ_INT(bad_circle, 0);
    /* Clipped ellipses equal the window of the unclipped one. */
    cg_image *small, *big;
    cg_image_create(&small, 30, 20, CG_PIXEL_RGBA8);
    cg_image_create(&big, 400, 400, CG_PIXEL_RGBA8);
    long bad = 0;
    for (int i = 0; i < 300; i++) {
        int rx = (int)check_rng_int(&rng, 0, 150), ry = (int)check_rng_int(&rng, 0, 150);
        int cx = (int)check_rng_int(&rng, -rx - 2, 30 + rx + 2),
            cy = (int)check_rng_int(&rng, -ry - 2, 20 + ry + 2);
        cg_image_clear_rgba8(small, black);
        cg_image_clear_rgba8(big, black);
        cg_draw_ellipse(small, cx, cy, rx, ry, white);
        cg_draw_ellipse(big, cx + 180, cy + 180, rx, ry, white);
        for (int y = 0; y < 20; y++)
            for (int x = 0; x < 30; x++)
                bad += is_set(small, x, y) != is_set(big, x + 180, y + 180);
    }
    CHECK_EQ_INT(bad, 0);
    cg_image_free(small);
    cg_image_free(big);
}

/* Arcs: the pixels of the circle whose direction is on the arc. */
static void arcs(void)
{
    cg_image *full, *arc;
    cg_image_create(&full, 101, 101, CG_PIXEL_RGBA8);
    cg_image_create(&arc, 101, 101, CG_PIXEL_RGBA8);
    check_rng rng = {8};
    long bad = 0;
    for (int i = 0; i < 200; i++) {
        int r = (int)check_rng_int(&rng, 1, 48);
        double a0 = check_rng_range(&rng, -400, 400), a1 = a0 + check_rng_range(&rng, -50, 420);
        cg_image_clear_rgba8(full, black);
        cg_image_clear_rgba8(arc, black);
        int ellipse = i % 2;
        if (ellipse) {
            cg_draw_ellipse(full, 50, 50, r, r / 2, white);
            cg_draw_ellipse_arc(arc, 50, 50, r, r / 2, a0, a1, white);
        } else {
            cg_draw_circle(full, 50, 50, r, white);
            cg_draw_arc(arc, 50, 50, r, a0, a1, white);
        }
        double start = fmod(fmod(a0, 360) + 360, 360), sweep = fmod(fmod(a1 - a0, 360) + 360, 360);
        if (a1 - a0 >= 360)
            sweep = 360;
        for (int y = 0; y < 101; y++)
            for (int x = 0; x < 101; x++) {
                if (!is_set(full, x, y)) {
                    bad += is_set(arc, x, y);
                    continue;
                }
                double ang = atan2(50.0 - y, x - 50.0) * 180 / CG_PI;
                double rel = fmod(ang - start + 720, 360);
                int in = sweep >= 360 || rel <= sweep || rel >= 360 - 1e-9;
                /* directions within a hair of the boundary may go either way */
                double edge = fmin(fabs(rel - sweep), fmin(rel, 360 - rel));
                if (edge > 1e-6)
                    bad += in != is_set(arc, x, y);
            }
    }
    CHECK_EQ_INT(bad, 0);
    /* A quarter arc from 0 to 90 degrees is the upper-right quarter. */
    cg_image_clear_rgba8(arc, black);
    cg_draw_arc(arc, 50, 50, 20, 0, 90, white);
    CHECK(is_set(arc, 70, 50) && is_set(arc, 50, 30) && !is_set(arc, 30, 50)
          && !is_set(arc, 50, 70));
    cg_image_free(full);
    cg_image_free(arc);
}

/* Anti-aliased lines: coverage per unit length is 1 at every angle, so the
 * total linear-light intensity of a long line is its length. */
static double total_intensity(const cg_image *image)
{
    double sum = 0;
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++)
            sum += cg_image_get(image, x, y).r;
    return sum;
}

static void antialiased(void)
{
    cg_image *image;
    cg_image_create(&image, 200, 200, CG_PIXEL_RGBAF);
    cg_rgbaf clear = {0, 0, 0, 1};
    for (int k = 0; k < 24; k++) {
        double a = k * CG_PI / 12 + 0.05, len = 120;
        double x0 = 100 - 0.5 * len * cos(a), y0 = 100 - 0.5 * len * sin(a);
        cg_image_clear(image, clear);
        CHECK(cg_draw_line_aa(image, x0, y0, x0 + len * cos(a), y0 + len * sin(a), white) == CG_OK);
        CHECK_NEAR(total_intensity(image), len, len * 0.01);
    }
    /* A horizontal line through pixel centres covers exactly those pixels. */
    cg_image_clear(image, clear);
    cg_draw_line_aa(image, 10, 20.5, 30, 20.5, white);
    CHECK_NEAR(cg_image_get(image, 15, 20).r, 1, 1e-6);
    CHECK_NEAR(cg_image_get(image, 15, 19).r, 0, 1e-6);
    CHECK_NEAR(cg_image_get(image, 9, 20).r, 0, 1e-6);
    CHECK_NEAR(cg_image_get(image, 30, 20).r, 0, 1e-6);
    /* Circles: total intensity close to the circumference. */
    for (double r = 5; r < 90; r += 13.7) {
        cg_image_clear(image, clear);
        CHECK(cg_draw_circle_aa(image, 100.3, 99.6, r, white) == CG_OK);
        CHECK_NEAR(total_intensity(image), 2 * CG_PI * r, 2 * CG_PI * r * 0.03);
        cg_image_clear(image, clear);
        CHECK(cg_draw_ellipse_aa(image, 100.3, 99.6, r, r * 0.6, white) == CG_OK);
        /* Ramanujan's perimeter of the ellipse */
        double A = r, B = 0.6 * r, p = CG_PI * (3 * (A + B) - sqrt((3 * A + B) * (A + 3 * B)));
        CHECK_NEAR(total_intensity(image), p, p * 0.05);
    }
    /* Far away and huge: nothing visible, no hang. */
    CHECK(cg_draw_line_aa(image, -1e15, 3, 1e15, 5, white) == CG_OK);
    CHECK(cg_draw_line_aa(image, -1e300, -1e300, 1e300, 1e300, white) == CG_OK);
    CHECK(cg_draw_circle_aa(image, 1e12, 5, 3, white) == CG_OK);
    CHECK(cg_draw_circle_aa(image, 100, 100, 1e12, white) == CG_ERANGE);
    cg_image_free(image);
}

/* Curves drawn aliased: every drawn pixel's centre lies within tolerance +
 * sqrt(2)/2 + a Bresenham half-step of the curve, and every point of the
 * curve has a drawn pixel next to it. */
static void drawn_curves(void)
{
    check_rng rng = {77};
    cg_image *image;
    cg_image_create(&image, 200, 200, CG_PIXEL_RGBA8);
    enum { SAMPLES = 1000 };
    cg_vec2 dense[SAMPLES + 1];
    long far_pixels = 0, uncovered = 0;
    for (int i = 0; i < 60; i++) {
        cg_vec2 p[4];
        for (int k = 0; k < 4; k++)
            p[k] = cg_vec2_make(check_rng_range(&rng, 10, 190), check_rng_range(&rng, 10, 190));
        cg_cubic2 curve = {(cg_curve_basis)(i % 4), {p[0], p[1], p[2], p[3]}};
        double tol = 0.25;
        cg_image_clear_rgba8(image, black);
        cg_status status;
        switch (i % 4) {
        case CG_BASIS_HERMITE:
            status = cg_draw_hermite(image, p[0], p[1], p[2], p[3], tol, CG_DRAW_ALIASED, white);
            break;
        case CG_BASIS_BEZIER:
            status = cg_draw_bezier(image, p, 4, tol, CG_DRAW_ALIASED, white);
            break;
        case CG_BASIS_BSPLINE:
            status = cg_draw_bspline(image, p, 4, tol, CG_DRAW_ALIASED, white);
            break;
        default: status = cg_draw_catmull_rom(image, p, 4, tol, CG_DRAW_ALIASED, white); break;
        }
        if (status == CG_ERANGE || (i % 4 == CG_BASIS_HERMITE && status != CG_OK))
            continue; /* a Hermite with huge tangents may leave the image */
        CHECK(status == CG_OK);
        for (int k = 0; k <= SAMPLES; k++)
            dense[k] = cg_cubic2_point(&curve, (double)k / SAMPLES);
        for (int y = 0; y < 200; y++)
            for (int x = 0; x < 200; x++) {
                if (!is_set(image, x, y))
                    continue;
                double best = 1e9;
                for (int k = 0; k <= SAMPLES; k++)
                    best = fmin(best, hypot(x + 0.5 - dense[k].x, y + 0.5 - dense[k].y));
                far_pixels += best > tol + 1.25;
            }
        for (int k = 0; k <= SAMPLES; k += 7) {
            int px = (int)floor(dense[k].x), py = (int)floor(dense[k].y), near = 0;
            for (int j = -1; j <= 1; j++)
                for (int q = -1; q <= 1; q++)
                    near |= is_set(image, px + q, py + j);
            uncovered += cg_image_contains(image, px, py) && !near;
        }
    }
    CHECK_EQ_INT(far_pixels, 0);
    CHECK_EQ_INT(uncovered, 0);
    cg_image_free(image);
}

static void bad_input(void)
{
    cg_image *image;
    cg_image_create(&image, 10, 10, CG_PIXEL_RGBA8);
    cg_image_clear_rgba8(image, black);
    double nan = NAN, inf = INFINITY;
    CHECK(cg_draw_circle(image, 5, 5, -1, white) == CG_EINVAL);
    CHECK(cg_draw_disc(image, 5, 5, -3, white) == CG_EINVAL);
    CHECK(cg_draw_ellipse(image, 5, 5, -1, 2, white) == CG_EINVAL);
    CHECK(cg_draw_ellipse(image, 5, 5, (1 << 30) + 1, 2, white) == CG_ERANGE);
    CHECK(cg_draw_arc(image, 5, 5, 3, nan, 90, white) == CG_EINVAL);
    CHECK(cg_draw_ellipse_arc(image, 5, 5, 3, 2, 0, inf, white) == CG_EINVAL);
    CHECK(cg_draw_line_aa(image, nan, 0, 1, 1, white) == CG_EINVAL);
    CHECK(cg_draw_line_aa(image, 0, inf, 1, 1, white) == CG_EINVAL);
    CHECK(cg_draw_circle_aa(image, 5, 5, -1, white) == CG_EINVAL);
    CHECK(cg_draw_circle_aa(image, nan, 5, 1, white) == CG_EINVAL);
    CHECK(cg_draw_ellipse_aa(image, 5, 5, 1, nan, white) == CG_EINVAL);
    CHECK(cg_draw_circle(NULL, 5, 5, 1, white) == CG_EINVAL);
    cg_vec2 pts[3] = {{1, 1}, {nan, 2}, {3, 3}};
    CHECK(cg_draw_polyline_aa(image, pts, 3, white) == CG_EINVAL);
    CHECK(cg_draw_bezier(image, pts, 3, 0.5, CG_DRAW_ALIASED, white) == CG_EINVAL);
    pts[1] = cg_vec2_make(2, 2);
    CHECK(cg_draw_bezier(image, pts, 3, 0, CG_DRAW_ALIASED, white) == CG_EINVAL);
    CHECK(cg_draw_bezier(image, pts, 3, -1, CG_DRAW_ALIASED, white) == CG_EINVAL);
    CHECK(cg_draw_bezier(image, pts, 3, nan, CG_DRAW_ALIASED, white) == CG_EINVAL);
    CHECK(cg_draw_bezier(image, pts, 1, 0.5, CG_DRAW_ALIASED, white) == CG_EINVAL);
    cg_vec2 same[4] = {{4, 4}, {4, 4}, {4, 4}, {4, 4}};
    CHECK(cg_draw_bezier(image, same, 4, 0.5, CG_DRAW_ANTIALIASED, white) == CG_EEMPTY);
    CHECK(cg_draw_bspline(image, same, 4, 0.5, CG_DRAW_ALIASED, white) == CG_EEMPTY);
    CHECK(cg_draw_hermite(image, same[0], same[0], cg_vec2_make(0, 0), cg_vec2_make(0, 0), 0.5,
                          CG_DRAW_ALIASED, white)
          == CG_EEMPTY);
    CHECK(cg_draw_bspline(image, same, 3, 0.5, CG_DRAW_ALIASED, white) == CG_EINVAL);
    cg_vec2 far[2] = {{0, 0}, {1e12, 5}};
    CHECK(cg_draw_bezier(image, far, 2, 0.5, CG_DRAW_ALIASED, white) == CG_ERANGE);
    /* nothing was drawn by any of these */
    long drawn = 0;
    for (int y = 0; y < 10; y++)
        for (int x = 0; x < 10; x++)
            drawn += cg_image_get_rgba8(image, x, y).r != 0;
    CHECK_EQ_INT(drawn, 0);
    /* and the curve drawings do draw otherwise */
    cg_vec2 c[4] = {{0.5, 0.5}, {9, 0}, {0, 9}, {9.5, 9.5}};
    CHECK(cg_draw_bezier(image, c, 4, 0.25, CG_DRAW_ALIASED, white) == CG_OK);
    CHECK(is_set(image, 0, 0) && is_set(image, 9, 9));
    cg_image_free(image);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(octant_definition);
    CHECK_GROUP(whole_circles);
    CHECK_GROUP(clipped_circles);
    CHECK_GROUP(huge_circles);
    CHECK_GROUP(discs);
    CHECK_GROUP(ellipses);
    CHECK_GROUP(arcs);
    CHECK_GROUP(antialiased);
    CHECK_GROUP(drawn_curves);
    CHECK_GROUP(bad_input);
    return check_finish();
}
