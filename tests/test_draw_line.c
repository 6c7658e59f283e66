/* Bresenham lines against the definition of a digital line segment
 * (section 2.1 of the notes), in every octant, clipped and unclipped. */
#include "check.h"
#include "cg/draw.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

static const cg_rgba8 white = {255, 255, 255, 255}, black = {0, 0, 0, 255};

static int is_set(const cg_image *image, int x, int y)
{
    return cg_image_get_rgba8(image, x, y).r == 255;
}

/* Clears the rectangle [x0, x1] x [y0, y1] (clipped) to black. */
static void clear_box(cg_image *image, long long x0, long long y0, long long x1, long long y1)
{
    if (x1 < x0) {
        long long t = x0;
        x0 = x1;
        x1 = t;
    }
    if (y1 < y0) {
        long long t = y0;
        y0 = y1;
        y1 = t;
    }
    if (x0 < 0)
        x0 = 0;
    if (y0 < 0)
        y0 = 0;
    if (x1 >= image->width)
        x1 = image->width - 1;
    if (y1 >= image->height)
        y1 = image->height - 1;
    for (long long y = y0; y <= y1; y++)
        for (long long x = x0; x <= x1; x++)
            cg_image_set_rgba8(image, (int)x, (int)y, black);
}

typedef struct pixel {
    int x, y;
} pixel;

/* The pixels of the line in the box [x0, x1] x [y0, y1] of the image, listed
 * along the major axis (x for |dx| >= |dy|). */
static int collect(const cg_image *image, int ax, int ay, int bx, int by, pixel *out, int cap)
{
    int x0 = ax < bx ? ax : bx, x1 = ax < bx ? bx : ax, y0 = ay < by ? ay : by,
        y1 = ay < by ? by : ay;
    int x_major = abs(bx - ax) >= abs(by - ay), n = 0;
    if (x_major) {
        for (int x = x0; x <= x1; x++)
            for (int y = y0; y <= y1; y++)
                if (cg_image_contains(image, x, y) && is_set(image, x, y) && n < cap)
                    out[n++] = (pixel){x, y};
    } else {
        for (int y = y0; y <= y1; y++)
            for (int x = x0; x <= x1; x++)
                if (cg_image_contains(image, x, y) && is_set(image, x, y) && n < cap)
                    out[n++] = (pixel){x, y};
    }
    return n;
}

/* The definition: one pixel per major coordinate from one endpoint to the
 * other; each within 1/2 of the real line along the minor axis (so the
 * smaller of its x- and y-distance is at most 1/2); consecutive pixels
 * 0-connected; both endpoints present. */
static int satisfies_definition(const pixel *p, int n, int ax, int ay, int bx, int by)
{
    long long dx = (long long)bx - ax, dy = (long long)by - ay;
    int x_major = llabs(dx) >= llabs(dy);
    long long major = x_major ? llabs(dx) : llabs(dy);
    if (n != major + 1)
        return 0;
    int has_a = 0, has_b = 0;
    for (int i = 0; i < n; i++) {
        /* minor-axis distance: |cross| / |major extent| <= 1/2 */
        long long cross = dx * ((long long)p[i].y - ay) - dy * ((long long)p[i].x - ax);
        if (2 * llabs(cross) > major)
            return 0;
        if (i > 0) {
            long long du = x_major ? p[i].x - p[i - 1].x : p[i].y - p[i - 1].y;
            long long dv = x_major ? p[i].y - p[i - 1].y : p[i].x - p[i - 1].x;
            if (du != 1 || llabs(dv) > 1)
                return 0;
        }
        has_a |= p[i].x == ax && p[i].y == ay;
        has_b |= p[i].x == bx && p[i].y == by;
    }
    return has_a && has_b;
}

static void random_lines(void)
{
    /* Lines with both endpoints inside a 64 x 64 image, every octant. */
    cg_image *a, *b;
    cg_image_create(&a, 64, 64, CG_PIXEL_RGBA8);
    cg_image_create(&b, 64, 64, CG_PIXEL_RGBA8);
    check_rng rng = {12345};
    pixel pa[200], pb[200];
    long bad_definition = 0, bad_symmetry = 0, octants[8] = {0};
    for (int i = 0; i < 100000; i++) {
        int ax = (int)check_rng_int(&rng, 0, 63), ay = (int)check_rng_int(&rng, 0, 63);
        int bx = (int)check_rng_int(&rng, 0, 63), by = (int)check_rng_int(&rng, 0, 63);
        if (i % 4 == 0) { /* short lines too */
            bx = ax + (int)check_rng_int(&rng, -3, 3);
            by = ay + (int)check_rng_int(&rng, -3, 3);
            bx = bx < 0 ? 0 : bx > 63 ? 63 : bx;
            by = by < 0 ? 0 : by > 63 ? 63 : by;
        }
        int dx = bx - ax, dy = by - ay;
        octants[(dx < 0) * 4 + (dy < 0) * 2 + (abs(dx) < abs(dy))]++;
        clear_box(a, ax, ay, bx, by);
        clear_box(b, ax, ay, bx, by);
        cg_draw_line(a, ax, ay, bx, by, white);
        cg_draw_line(b, bx, by, ax, ay, white);
        int na = collect(a, ax, ay, bx, by, pa, 200), nb = collect(b, ax, ay, bx, by, pb, 200);
        if (!satisfies_definition(pa, na, ax, ay, bx, by)) {
            if (bad_definition++ < 5)
                fprintf(stderr, "line (%d,%d)-(%d,%d) breaks the definition\n", ax, ay, bx, by);
        }
        if (na != nb || memcmp(pa, pb, (size_t)na * sizeof *pa) != 0)
            bad_symmetry++;
    }
    CHECK_EQ_INT(bad_definition, 0);
    CHECK_EQ_INT(bad_symmetry, 0);
    for (int o = 0; o < 8; o++)
        CHECK_MSG(octants[o] > 5000, "octant %d had only %ld lines", o, octants[o]);
    cg_image_free(a);
    cg_image_free(b);
}

/* Clipped drawing on a small image equals the window of the same line drawn
 * unclipped on a large image. */
static void clipped_equals_unclipped(void)
{
    enum { W = 37, H = 29, OFF = 80, BIG = 200 };
    cg_image *small, *big;
    cg_image_create(&small, W, H, CG_PIXEL_RGBA8);
    cg_image_create(&big, BIG, BIG, CG_PIXEL_RGBA8);
    check_rng rng = {777};
    long bad = 0;
    for (int i = 0; i < 20000; i++) {
        int ax = (int)check_rng_int(&rng, -70, W + 70), ay = (int)check_rng_int(&rng, -70, H + 70);
        int bx = (int)check_rng_int(&rng, -70, W + 70), by = (int)check_rng_int(&rng, -70, H + 70);
        cg_image_clear_rgba8(small, black);
        clear_box(big, OFF - 1, OFF - 1, OFF + W, OFF + H);
        cg_draw_line(small, ax, ay, bx, by, white);
        cg_draw_line(big, ax + OFF, ay + OFF, bx + OFF, by + OFF, white);
        int differ = 0;
        for (int y = 0; y < H && !differ; y++)
            for (int x = 0; x < W; x++)
                if (is_set(small, x, y) != is_set(big, x + OFF, y + OFF)) {
                    differ = 1;
                    break;
                }
        if (differ && bad++ < 5)
            fprintf(stderr, "clipped line (%d,%d)-(%d,%d) differs\n", ax, ay, bx, by);
    }
    CHECK_EQ_INT(bad, 0);
    cg_image_free(small);
    cg_image_free(big);
}

/* The pixel the definition puts in major column u of the line, computed
 * independently in 128-bit arithmetic: the minor coordinate nearest to the
 * real line, ties going to the side of the start endpoint (the one with the
 * smaller major coordinate). */
__extension__ typedef __int128 wide;
static long long expected_minor(long long u0, long long v0, long long u1, long long v1, long long u)
{
    if (u1 < u0) {
        long long t = u0;
        u0 = u1;
        u1 = t;
        t = v0;
        v0 = v1;
        v1 = t;
    }
    wide du = u1 - u0, dv = v1 - v0, k = u - u0;
    /* v = v0 + dv k / du; nearest with ties toward v0: */
    wide num = 2 * dv * k, den = 2 * du; /* v - v0 = num / den */
    wide sign = num < 0 ? -1 : 1, mag = num < 0 ? -num : num;
    /* round |num/den| to nearest, ties down (toward 0, i.e. toward v0) */
    wide q = (mag + du - 1) / den;
    return (long long)(v0 + sign * q);
}

static void huge_lines(void)
{
    enum { W = 100, H = 80 };
    cg_image *image;
    cg_image_create(&image, W, H, CG_PIXEL_RGBA8);
    check_rng rng = {4242};
    long bad = 0, visible = 0;
    for (int i = 0; i < 3000; i++) {
        long long ax, ay, bx, by;
        /* Endpoints anywhere in int range, most through the image. */
        ax = check_rng_int(&rng, INT_MIN, INT_MAX);
        ay = check_rng_int(&rng, INT_MIN, INT_MAX);
        if (i % 3) {
            /* aim through a random image point: b = a + 2 (p - a), clamped */
            long long px = check_rng_int(&rng, 0, W - 1), py = check_rng_int(&rng, 0, H - 1);
            bx = px + (px - ax);
            by = py + (py - ay);
            if (bx > INT_MAX || bx < INT_MIN || by > INT_MAX || by < INT_MIN) {
                ax /= 2;
                ay /= 2;
                bx = px + (px - ax);
                by = py + (py - ay);
            }
        } else {
            bx = check_rng_int(&rng, INT_MIN, INT_MAX);
            by = check_rng_int(&rng, INT_MIN, INT_MAX);
        }
        if (i < 8) { /* the extreme corners */
            long long c[4] = {INT_MIN, INT_MAX, INT_MIN, INT_MAX};
            ax = c[i % 2];
            ay = c[(i / 2) % 2 + 2];
            bx = c[1 - i % 2];
            by = c[3 - (i / 2) % 2 - 0];
            if (i >= 4) {
                ax = INT_MIN;
                ay = INT_MIN + i;
                bx = INT_MAX;
                by = INT_MAX - i;
            }
        }
        cg_image_clear_rgba8(image, black);
        cg_draw_line(image, (int)ax, (int)ay, (int)bx, (int)by, white);
        int x_major = llabs(bx - ax) >= llabs(by - ay), differ = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                long long u = x_major ? x : y, v = x_major ? y : x;
                long long u0 = x_major ? ax : ay, u1 = x_major ? bx : by;
                long long v0 = x_major ? ay : ax, v1 = x_major ? by : bx;
                int inside = u >= (u0 < u1 ? u0 : u1) && u <= (u0 < u1 ? u1 : u0);
                int want = inside && (u0 == u1 ? v == v0 : expected_minor(u0, v0, u1, v1, u) == v);
                if (want != is_set(image, x, y))
                    differ = 1;
                visible += want;
            }
        if (differ && bad++ < 5)
            fprintf(stderr, "huge line (%lld,%lld)-(%lld,%lld) differs\n", ax, ay, bx, by);
    }
    CHECK_EQ_INT(bad, 0);
    CHECK(visible > 50000); /* the test really sees the lines */
    cg_image_free(image);
}

static void edge_cases(void)
{
    cg_image *image;
    cg_image_create(&image, 16, 12, CG_PIXEL_RGBA8);
    struct {
        int ax, ay, bx, by, count;
    } cases[] = {
        {3, 4, 3, 4, 1},    /* single pixel */
        {0, 5, 15, 5, 16},  /* horizontal, full width */
        {7, 0, 7, 11, 12},  /* vertical, full height */
        {0, 0, 11, 11, 12}, /* diagonal */
        {11, 0, 0, 11, 12}, /* anti-diagonal */
        {-100, 3, 100, 3, 16},
        {5, -100, 5, 100, 12},
        {INT_MIN, 2, INT_MAX, 2, 16},
        {9, INT_MAX, 9, INT_MIN, 12},
        {-5, -5, -1, -1, 0}, /* entirely outside */
        {16, 0, 30, 11, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        cg_image_clear_rgba8(image, black);
        CHECK(cg_draw_line(image, cases[i].ax, cases[i].ay, cases[i].bx, cases[i].by, white)
              == CG_OK);
        int n = 0;
        for (int y = 0; y < 12; y++)
            for (int x = 0; x < 16; x++)
                n += is_set(image, x, y);
        CHECK_MSG(n == cases[i].count, "case %zu: %d pixels, expected %d", i, n, cases[i].count);
    }
    CHECK(cg_draw_line(NULL, 0, 0, 1, 1, white) == CG_EINVAL);
    /* Float images get the same pixels. */
    cg_image *f;
    cg_image_create(&f, 16, 12, CG_PIXEL_RGBAF);
    cg_image_clear_rgba8(image, black);
    cg_draw_line(image, -3, 2, 19, 9, white);
    cg_draw_line(f, -3, 2, 19, 9, white);
    int same = 1;
    for (int y = 0; y < 12; y++)
        for (int x = 0; x < 16; x++)
            same &= is_set(image, x, y) == (cg_image_get(f, x, y).r > 0.5f);
    CHECK(same);
    cg_image_free(f);
    cg_image_free(image);
}

/* Half-transparent lines and polylines: every pixel blended exactly once. */
static void blending_once(void)
{
    cg_image *image;
    cg_image_create(&image, 50, 50, CG_PIXEL_RGBA8);
    cg_rgba8 half = {255, 0, 0, 128};
    cg_image_clear_rgba8(image, black);
    int xy[] = {5, 5, 40, 10, 20, 45, 5, 5, 45, 45};
    CHECK(cg_draw_polyline(image, xy, 5, half) == CG_OK);
    cg_draw_line(image, 0, 30, 49, 20, half);
    int once = 0, other = 0;
    cg_image *ref;
    cg_image_create(&ref, 1, 1, CG_PIXEL_RGBA8);
    cg_image_clear_rgba8(ref, black);
    cg_draw_line(ref, 0, 0, 0, 0, half);
    cg_rgba8 one = cg_image_get_rgba8(ref, 0, 0);
    cg_draw_line(ref, 0, 0, 0, 0, half);
    cg_rgba8 two = cg_image_get_rgba8(ref, 0, 0);
    for (int y = 0; y < 50; y++)
        for (int x = 0; x < 50; x++) {
            cg_rgba8 c = cg_image_get_rgba8(image, x, y);
            if (c.r == one.r)
                once++;
            else if (c.r != 0 && c.r != two.r)
                other++;
        }
    CHECK(once > 150);
    CHECK_EQ_INT(other, 0);
    /* Only genuine crossings of different segments may be blended twice. */
    int twice = 0;
    for (int y = 0; y < 50; y++)
        for (int x = 0; x < 50; x++)
            twice += cg_image_get_rgba8(image, x, y).r == two.r;
    CHECK(twice <= 12);
    cg_image_free(ref);
    cg_image_free(image);
}

/* cg_line_trace follows Algorithm 1 and agrees with the drawing. */
typedef struct trace_record {
    pixel p[256];
    int n;
} trace_record;
static int record(void *user, const cg_line_step *s)
{
    trace_record *r = user;
    if (r->n < 256)
        r->p[r->n++] = (pixel){s->x, s->y};
    return 0;
}

static void trace_matches(void)
{
    long long dx, dy, de, dne;
    trace_record r = {{{0, 0}}, 0};
    CHECK(cg_line_trace(0, 0, 8, 3, record, &r, &dx, &dy, &de, &dne) == CG_OK);
    CHECK_EQ_INT(dx, 8);
    CHECK_EQ_INT(dy, 3);
    CHECK_EQ_INT(de, 6);
    CHECK_EQ_INT(dne, -10);
    /* Worked by hand from Algorithm 1: f = -2, 4, -6, 0, 6, -4, 2, -8 */
    int ys[9] = {0, 0, 1, 1, 1, 2, 2, 3, 3};
    CHECK_EQ_INT(r.n, 9);
    for (int i = 0; i < 9 && i < r.n; i++) {
        CHECK_EQ_INT(r.p[i].x, i);
        CHECK_EQ_INT(r.p[i].y, ys[i]);
    }
    cg_image *image;
    cg_image_create(&image, 40, 40, CG_PIXEL_RGBA8);
    check_rng rng = {99};
    long bad = 0;
    for (int i = 0; i < 2000; i++) {
        int ax = (int)check_rng_int(&rng, 0, 39), ay = (int)check_rng_int(&rng, 0, 39);
        int bx = (int)check_rng_int(&rng, 0, 39), by = (int)check_rng_int(&rng, 0, 39);
        cg_image_clear_rgba8(image, black);
        cg_draw_line(image, ax, ay, bx, by, white);
        r.n = 0;
        cg_line_trace(ax, ay, bx, by, record, &r, NULL, NULL, NULL, NULL);
        int n = 0, all = 1;
        for (int y = 0; y < 40; y++)
            for (int x = 0; x < 40; x++)
                n += is_set(image, x, y);
        for (int k = 0; k < r.n; k++)
            all &= is_set(image, r.p[k].x, r.p[k].y);
        bad += !(all && n == r.n);
    }
    CHECK_EQ_INT(bad, 0);
    cg_image_free(image);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(random_lines);
    CHECK_GROUP(clipped_equals_unclipped);
    CHECK_GROUP(huge_lines);
    CHECK_GROUP(edge_cases);
    CHECK_GROUP(blending_once);
    CHECK_GROUP(trace_matches);
    return check_finish();
}
