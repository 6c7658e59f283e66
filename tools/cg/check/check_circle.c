/* `cg check circle R [XC YC]` and `cg check ellipse RX RY [XC YC]`: the
 * student's pixels against the digital circle (section 2.2) and the
 * midpoint ellipse, and against cg's own.
 *
 * Circle: each pixel's offset (a, b) from the centre maps to the first
 * octant as x = min(|a|, |b|), y = max(|a|, |b|); there the pixel must lie
 * within 1/2 of the real circle along y, which leaves one pixel per column
 * (Observation 4), and all eight mirrors of each must be there
 * (Observation 2).  A missing pixel is explained by symmetry when a mirror
 * is present, else by Algorithm 2's midpoint decision.
 *
 * Ellipse: each pixel within 1/2 of the real ellipse by the same measure
 * (the smaller of the x- and y-distance), 4-symmetric, then cg's midpoint
 * ellipse (docs/draw.md): the pixel each column of region 1 and each row of
 * region 2 selects. */
#include "check.h"

#include "cli.h"
#include "cg/trace_steps.h"

#include <math.h>
#include <stdlib.h>

enum { MAX_RADIUS = 1000000, MAX_ELLIPSE_RADIUS = 100000 };

typedef struct pixel_list {
    CORE_ARRAY(long long) xy;
} pixel_list;

static int collect_pixels(void *user, const cg_step *step)
{
    pixel_list *c = user;
    for (int i = 0; i < 2 * step->pixel_count; i++)
        if (core_array_push(&c->xy, (long long)step->pixels[i]) != CG_OK)
            return 1;
    return 0;
}

/* The distance of the first-octant pixel (x, y), x <= y, from the circle
 * of radius r along y: |y - sqrt(r^2 - x^2)|, or the radial distance when
 * x > r. */
static double octant_distance(long long x, long long y, long long r)
{
    if (x > r)
        return sqrt((double)x * x + (double)y * y) - (double)r;
    return fabs((double)y - sqrt((double)(r * r - x * x)));
}

/* Whether the first-octant pixel (x, y) lies within 1/2 along y (exactly:
 * (2y - 1)^2 <= 4 (r^2 - x^2) <= (2y + 1)^2; never equal). */
static int within_half(long long x, long long y, long long r)
{
    if (x > r || y > r + 1)
        return 0; /* far, and no square below may overflow */
    long long s4 = 4 * (r * r - x * x);
    if (s4 < 0)
        return 0;
    return (y == 0 || (2 * y - 1) * (2 * y - 1) <= s4) && s4 <= (2 * y + 1) * (2 * y + 1);
}

/* The mirrors of (x, y) about the centre's axes and diagonals. */
static int mirrors(long long x, long long y, long long out[8][2])
{
    long long m[8][2] = {{x, y}, {-x, y}, {x, -y}, {-x, -y}, {y, x}, {-y, x}, {y, -x}, {-y, -x}};
    int n = 0;
    for (int i = 0; i < 8; i++) {
        int seen = 0;
        for (int k = 0; k < n; k++)
            seen |= out[k][0] == m[i][0] && out[k][1] == m[i][1];
        if (!seen) {
            out[n][0] = m[i][0];
            out[n][1] = m[i][1];
            n++;
        }
    }
    return n;
}

typedef struct circle_check {
    long long r, cx, cy;
    const check_pixel *sorted;
    size_t count;
} circle_check;

static int has(const circle_check *c, long long a, long long b)
{
    return check_find(c->sorted, c->count, c->cx + a, c->cy + b) >= 0;
}

/* Every pixel of the octant step (x, y) with its mirrors; 1 after a verdict
 * when one is missing.  (px, py) is the previous step and f4 four times
 * f(m) at the midpoint tested to reach this one. */
static int check_step(const circle_check *c, long long x, long long y, long long px, long long py,
                      long long f4, int *verdict)
{
    long long m[8][2];
    int n = mirrors(x, y, m);
    for (int i = 0; i < n; i++) {
        if (has(c, m[i][0], m[i][1]))
            continue;
        long long mx = c->cx + m[i][0], my = c->cy + m[i][1];
        for (int k = 0; k < n; k++)
            if (has(c, m[k][0], m[k][1])) {
                *verdict = check_wrong("pixel (%lld, %lld) is missing, but its mirror (%lld, "
                                       "%lld) is there; a digital circle is 8-symmetric "
                                       "(Observation 2)",
                                       mx, my, c->cx + m[k][0], c->cy + m[k][1]);
                return 1;
            }
        if (x == 0)
            *verdict = check_wrong("pixel (%lld, %lld) is missing; Algorithm 2 starts at (0, r) "
                                   "and selects its mirrors",
                                   mx, my);
        else
            *verdict = check_wrong("pixel (%lld, %lld) is missing: in the first octant, after "
                                   "(%lld, %lld) the midpoint m = (%lld, %lld.5) has f(m) = %.2f "
                                   "%s 0, so Algorithm 2 selects %s (%lld, %lld) and its mirrors",
                                   mx, my, px, py, x, py - 1, f4 / 4.0,
                                   f4 < 0 ? "<" : ">=", f4 < 0 ? "E" : "SE", x, y);
        return 1;
    }
    return 0;
}

/* Walks Algorithm 2 (with f(m) computed exactly, times 4) over the first
 * octant; 1 after a verdict. */
static int check_octant(const circle_check *c, int *verdict)
{
    long long x = 0, y = c->r;
    if (check_step(c, x, y, 0, 0, 0, verdict))
        return 1;
    while (x < y) {
        long long f4 = 4 * (x + 1) * (x + 1) + (2 * y - 1) * (2 * y - 1) - 4 * c->r * c->r;
        long long px = x, py = y;
        x++;
        if (f4 >= 0)
            y--;
        if (x <= y && check_step(c, x, y, px, py, f4, verdict))
            return 1;
    }
    return 0;
}

static int parse_centre(int argc, char **argv, int first, long *cx, long *cy)
{
    *cx = *cy = 0;
    if (argc == first)
        return 0;
    return cli_parse_long("check", "XC", argv[first], -1000000000L, 1000000000L, cx)
           || cli_parse_long("check", "YC", argv[first + 1], -1000000000L, 1000000000L, cy);
}

/* Every pixel within 1/2 of the circle; 1 after a verdict. */
static int check_distances(const circle_check *c, const check_pixels *in, int *verdict)
{
    for (size_t i = 0; i < in->count; i++) {
        const check_pixel *p = &in->data[i];
        long long a = llabs(p->x - c->cx), b = llabs(p->y - c->cy);
        long long x = a < b ? a : b, y = a < b ? b : a;
        if (within_half(x, y, c->r))
            continue;
        *verdict = check_wrong("pixel (%lld, %lld) is %.2f from the circle along %s; a pixel of "
                               "a digital circle is at most 1/2 away",
                               p->x, p->y, octant_distance(x, y, c->r), a <= b ? "y" : "x");
        check_note("its offset from the centre (%lld, %lld) is (%lld, %lld): in the first "
                   "octant that is (%lld, %lld), and the circle has y = %.2f there",
                   c->cx, c->cy, p->x - c->cx, p->y - c->cy, x, y,
                   x <= c->r ? sqrt((double)(c->r * c->r - x * x)) : 0.0);
        return 1;
    }
    return 0;
}

/* The student's pixels against cg's (each given set sorted): 0 when the
 * same, else the verdict. */
static int compare_sets(const check_pixel *sorted, size_t count, const pixel_list *cg,
                        const char *what)
{
    size_t cg_count = cg->xy.count / 2;
    for (size_t i = 0; i < cg_count; i++)
        if (check_find(sorted, count, cg->xy.data[2 * i], cg->xy.data[2 * i + 1]) < 0)
            return check_wrong("pixel (%lld, %lld) of cg's %s is missing", cg->xy.data[2 * i],
                               cg->xy.data[2 * i + 1], what);
    if (count != cg_count)
        return check_wrong("%zu pixels; cg's %s has %zu", count, what, cg_count);
    return CLI_OK;
}

static int run_circle(int argc, char **argv, FILE *in, const check_options *options)
{
    (void)options;
    long r, cx, cy;
    if (argc != 2 && argc != 4)
        return cli_usage_error("check", "circle: expected 'circle R [XC YC]'");
    if (cli_parse_long("check", "R", argv[1], 0, MAX_RADIUS, &r)
        || parse_centre(argc, argv, 2, &cx, &cy))
        return CLI_USAGE;
    check_pixels pixels = {0};
    pixel_list cg = {{0}};
    check_pixel *sorted = NULL;
    int code = check_read_pixels(in, &pixels);
    if (code == CLI_OK) {
        cg_status status = cg_circle_steps((int)cx, (int)cy, (int)r, collect_pixels, &cg);
        sorted = check_sorted(&pixels);
        if (status != CG_OK || (pixels.count && !sorted))
            code = cli_fail("check: circle: %s", cg_status_str(status ? status : CG_ENOMEM));
    }
    if (code == CLI_OK) {
        circle_check c = {r, cx, cy, sorted, pixels.count};
        long repeat = check_first_repeat(sorted, pixels.count);
        if (repeat >= 0) {
            code = check_wrong_repeat(sorted, repeat, "a digital circle");
            check_note("where octants meet (x = 0 or x = y) mirrors coincide: select each "
                       "pixel once");
        } else if (!check_distances(&c, &pixels, &code) && !check_octant(&c, &code)) {
            code = compare_sets(sorted, pixels.count, &cg, "circle");
            if (code == CLI_OK)
                check_right("the digital circle of radius %ld about (%ld, %ld): %zu pixels, "
                            "8-symmetric, each within 1/2 of the circle, as Algorithm 2 "
                            "selects them, the same as cg's",
                            r, cx, cy, pixels.count);
        }
    }
    free(sorted);
    core_array_free(&pixels);
    core_array_free(&cg.xy);
    return code;
}

/* The ellipse's distance from the pixel offset (a, b) >= 0, as the notes
 * measure a digital circle's: the smaller of the x-distance and the
 * y-distance to the real curve (the distance to the nearer tip beyond
 * both radii); *axis names which. */
static double ellipse_distance(long long a, long long b, long long rx, long long ry,
                               const char **axis)
{
    double x = (double)a, y = (double)b, A = (double)rx, B = (double)ry;
    /* A zero radius is a segment along the other axis. */
    double dy = x > A    ? INFINITY
                : A == 0 ? fmax(0, y - B)
                         : fabs(y - B * sqrt(1 - (x / A) * (x / A)));
    double dx = y > B    ? INFINITY
                : B == 0 ? fmax(0, x - A)
                         : fabs(x - A * sqrt(1 - (y / B) * (y / B)));
    if (isinf(dx) && isinf(dy)) {
        *axis = "the nearer tip";
        return fmin(hypot(x - A, y), hypot(x, y - B));
    }
    *axis = dy <= dx ? "y" : "x";
    return fmin(dx, dy);
}

/* The student's pixels by the definition (each within 1/2, 4-symmetric),
 * then each in cg's midpoint ellipse; 1 after a verdict. */
static int check_ellipse_pixels(const check_pixels *in, const check_pixel *sorted,
                                const check_pixel *cg_sorted, size_t cg_count, long rx, long ry,
                                long cx, long cy, int *verdict)
{
    for (size_t i = 0; i < in->count; i++) {
        const check_pixel *p = &in->data[i];
        const char *axis;
        double d = ellipse_distance(llabs(p->x - cx), llabs(p->y - cy), rx, ry, &axis);
        if (d > 0.5) {
            *verdict = check_wrong("pixel (%lld, %lld) is %.2f from the ellipse along %s; a "
                                   "pixel of a digital ellipse is at most 1/2 away (the smaller "
                                   "of its x- and y-distance)",
                                   p->x, p->y, d, axis);
            return 1;
        }
    }
    for (size_t i = 0; i < in->count; i++) {
        const check_pixel *p = &in->data[i];
        long long mx[3] = {2 * cx - p->x, p->x, 2 * cx - p->x};
        long long my[3] = {p->y, 2 * cy - p->y, 2 * cy - p->y};
        for (int k = 0; k < 3; k++)
            if (check_find(sorted, in->count, mx[k], my[k]) < 0) {
                *verdict = check_wrong("pixel (%lld, %lld) is missing, but its mirror (%lld, "
                                       "%lld) is there; the ellipse is 4-symmetric",
                                       mx[k], my[k], p->x, p->y);
                return 1;
            }
    }
    for (size_t i = 0; i < in->count; i++) {
        const check_pixel *p = &in->data[i];
        if (check_find(cg_sorted, cg_count, p->x, p->y) >= 0)
            continue;
        *verdict = check_wrong("pixel (%lld, %lld) is within 1/2 of the ellipse but not the "
                               "midpoint ellipse's: region 1 takes in each column the pixel "
                               "whose lower midpoint (x, y - 1/2) is inside, region 2 in each "
                               "row the pixel whose inner midpoint is inside",
                               p->x, p->y);
        return 1;
    }
    return 0;
}

/* cg's pixels the student lacks: by 4-symmetry when a mirror is there. */
static int check_ellipse_missing(const pixel_list *cg, const check_pixel *sorted, size_t count,
                                 long cx, long cy, int *verdict)
{
    for (size_t i = 0; i < cg->xy.count / 2; i++) {
        long long x = cg->xy.data[2 * i], y = cg->xy.data[2 * i + 1];
        if (check_find(sorted, count, x, y) >= 0)
            continue;
        long long mx[3] = {2 * cx - x, x, 2 * cx - x}, my[3] = {y, 2 * cy - y, 2 * cy - y};
        for (int k = 0; k < 3; k++)
            if (check_find(sorted, count, mx[k], my[k]) >= 0) {
                *verdict = check_wrong("pixel (%lld, %lld) is missing, but its mirror (%lld, "
                                       "%lld) is there; the ellipse is 4-symmetric",
                                       x, y, mx[k], my[k]);
                return 1;
            }
        *verdict = check_wrong("pixel (%lld, %lld) is missing; the midpoint ellipse takes one "
                               "pixel in each column of region 1 and each row of region 2",
                               x, y);
        return 1;
    }
    return 0;
}

static int run_ellipse(int argc, char **argv, FILE *in, const check_options *options)
{
    (void)options;
    long rx, ry, cx, cy;
    if (argc != 3 && argc != 5)
        return cli_usage_error("check", "ellipse: expected 'ellipse RX RY [XC YC]'");
    if (cli_parse_long("check", "RX", argv[1], 0, MAX_ELLIPSE_RADIUS, &rx)
        || cli_parse_long("check", "RY", argv[2], 0, MAX_ELLIPSE_RADIUS, &ry)
        || parse_centre(argc, argv, 3, &cx, &cy))
        return CLI_USAGE;
    check_pixels pixels = {0}, cg_pixels = {0};
    pixel_list cg = {{0}};
    check_pixel *sorted = NULL, *cg_sorted = NULL;
    int code = check_read_pixels(in, &pixels);
    if (code == CLI_OK) {
        cg_status status = rx == ry
                               ? cg_circle_steps((int)cx, (int)cy, (int)rx, collect_pixels, &cg)
                               : cg_ellipse_steps((int)cx, (int)cy, (int)rx, (int)ry,
                                                  collect_pixels, &cg);
        for (size_t i = 0; status == CG_OK && i < cg.xy.count / 2; i++)
            if (core_array_push(&cg_pixels,
                                ((check_pixel){cg.xy.data[2 * i], cg.xy.data[2 * i + 1], 0}))
                != CG_OK)
                status = CG_ENOMEM;
        sorted = check_sorted(&pixels);
        cg_sorted = check_sorted(&cg_pixels);
        if (status != CG_OK || (pixels.count && !sorted) || (cg_pixels.count && !cg_sorted))
            code = cli_fail("check: ellipse: %s", cg_status_str(status ? status : CG_ENOMEM));
    }
    if (code == CLI_OK) {
        long repeat = check_first_repeat(sorted, pixels.count);
        if (repeat >= 0)
            code = check_wrong_repeat(sorted, repeat, "the midpoint ellipse");
        else if (!check_ellipse_pixels(&pixels, sorted, cg_sorted, cg_pixels.count, rx, ry, cx, cy,
                                       &code)
                 && !check_ellipse_missing(&cg, sorted, pixels.count, cx, cy, &code))
            code = check_right("the midpoint ellipse with radii %ld and %ld about (%ld, %ld): "
                               "%zu pixels, 4-symmetric, the same as cg's",
                               rx, ry, cx, cy, pixels.count);
    }
    free(sorted);
    free(cg_sorted);
    core_array_free(&pixels);
    core_array_free(&cg_pixels);
    core_array_free(&cg.xy);
    return code;
}

const check_algorithm check_circle_algorithms[] = {
    {"circle", "R [XC YC]", run_circle},
    {"ellipse", "RX RY [XC YC]", run_ellipse},
    {NULL, NULL, NULL},
};
