/* `cg check line X1 Y1 X2 Y2`: the student's pixels against the definition
 * of a digital line segment (section 2.1) and against cg's Bresenham line.
 *
 * In the notes' first octant a DLS has exactly one pixel for each x from x1
 * to x2 (Observation 1), each within 1/2 of the real line along y; in
 * general the major axis (x when |dx| >= |dy|) takes x's part and the minor
 * axis y's.  A pixel exactly 1/2 away is a tie: either pixel of that column
 * is a DLS's, so a DLS that differs from cg's only there is right. */
#include "check.h"

#include "cli.h"
#include "cg/trace_steps.h"

#include <stdlib.h>
#include <string.h>

enum { MAX_STEPS = 1000000 };

/* The segment in major/minor terms. */
typedef struct dls {
    long long u1, v1, u2, v2; /* endpoints: major and minor coordinates */
    long long du, dv;
    int steep;                 /* the major axis is y */
    const char *major, *minor; /* "x", "y" */
} dls;

static long long major_of(const dls *l, long long x, long long y)
{
    return l->steep ? y : x;
}

static long long minor_of(const dls *l, long long x, long long y)
{
    return l->steep ? x : y;
}

/* The pixel (x, y) at major u and minor v. */
static void pixel_at(const dls *l, long long u, long long v, long long *x, long long *y)
{
    *x = l->steep ? v : u;
    *y = l->steep ? u : v;
}

/* Twice the minor-axis error of minor v at major u, times |du|:
 * 2 |v - v(u)| |du|; the pixel is a DLS's when it is <= |du|. */
static long long doubled_error(const dls *l, long long u, long long v)
{
    if (l->du == 0)
        return v == l->v1 ? 0 : 2;
    long long e = 2 * ((v - l->v1) * l->du - (u - l->u1) * l->dv);
    if (l->du < 0)
        e = -e;
    return e < 0 ? -e : e;
}

/* The one or two minor coordinates within 1/2 at major u: *count 1 or 2
 * (a tie), the lower first. */
static void candidates(const dls *l, long long u, long long v[2], int *count)
{
    long long ad = l->du < 0 ? -l->du : l->du;
    if (ad == 0) {
        v[0] = l->v1;
        *count = 1;
        return;
    }
    /* v(u) = v1 + (u - u1) dv / du; floor(v(u) + 1/2) first. */
    long long num = 2 * (u - l->u1) * l->dv * (l->du < 0 ? -1 : 1) + ad; /* 2 v(u)' + 1, x ad */
    long long den = 2 * ad;
    long long q = num / den - ((num % den != 0) && ((num < 0) != (den < 0)));
    v[0] = l->v1 + q;
    *count = 1;
    if (doubled_error(l, u, v[0] - 1) <= ad) {
        v[1] = v[0];
        v[0] = v[0] - 1;
        *count = 2;
    } else if (doubled_error(l, u, v[0] + 1) <= ad) {
        v[1] = v[0] + 1;
        *count = 2;
    }
}

typedef struct collected {
    CORE_ARRAY(int) xy;
} collected;

static int collect_pixels(void *user, const cg_step *step)
{
    collected *c = user;
    for (int i = 0; i < 2 * step->pixel_count; i++)
        if (core_array_push(&c->xy, step->pixels[i]) != CG_OK)
            return 1;
    return 0;
}

/* Each pixel on its own: within the major range and within 1/2.  1 after
 * a verdict, 0 when all are. */
static int check_each(const dls *l, const check_pixels *in, int *verdict)
{
    long long lo = l->u1 < l->u2 ? l->u1 : l->u2, hi = l->u1 < l->u2 ? l->u2 : l->u1;
    long long ad = l->du < 0 ? -l->du : l->du;
    for (size_t i = 0; i < in->count; i++) {
        const check_pixel *p = &in->data[i];
        long long u = major_of(l, p->x, p->y), v = minor_of(l, p->x, p->y);
        if (u < lo || u > hi) {
            *verdict = check_wrong("pixel (%lld, %lld) has %s = %lld outside [%lld, %lld]; every "
                                   "DLS pixel lies between the endpoints (%s1 <= %s <= %s2)",
                                   p->x, p->y, l->major, u, lo, hi, l->major, l->major, l->major);
            return 1;
        }
        long long e = doubled_error(l, u, v);
        if (e > (ad ? ad : 1)) {
            char distance[64];
            check_fraction(distance, sizeof distance, e, 2 * (ad ? ad : 1));
            *verdict = check_wrong("pixel (%lld, %lld) is %s from the line along %s; a DLS pixel "
                                   "is at most 1/2 away",
                                   p->x, p->y, distance, l->minor);
            if (u == l->u1 || u == l->u2) {
                long long x, y;
                pixel_at(l, u, u == l->u1 ? l->v1 : l->v2, &x, &y);
                check_note("the endpoint in that %s is (%lld, %lld)", l->steep ? "row" : "column",
                           x, y);
            }
            return 1;
        }
    }
    return 0;
}

/* Walks the major axis from the first endpoint: one pixel each.  The
 * pixels are known to be in range and within 1/2. */
static int check_columns(const dls *l, const check_pixel *sorted, size_t count, int *verdict)
{
    long long step = l->u2 >= l->u1 ? 1 : -1;
    for (long long u = l->u1;; u += step) {
        long long v[2];
        int n;
        candidates(l, u, v, &n);
        long found[2] = {-1, -1};
        for (int k = 0; k < n; k++) {
            long long x, y;
            pixel_at(l, u, v[k], &x, &y);
            found[k] = check_find(sorted, count, x, y);
        }
        long long x0, y0, x1, y1;
        pixel_at(l, u, v[0], &x0, &y0);
        pixel_at(l, u, v[n - 1], &x1, &y1);
        if (found[0] >= 0 && found[1] >= 0) {
            *verdict = check_wrong("pixels (%lld, %lld) and (%lld, %lld) both have %s = %lld; a "
                                   "DLS has exactly one pixel for each %s (Observation 1)",
                                   x0, y0, x1, y1, l->major, u, l->major);
            check_note("the line passes through the midpoint between them: either one is right");
            return 1;
        }
        if (found[0] < 0 && found[1] < 0) {
            if (u == l->u1 || u == l->u2)
                *verdict = check_wrong("the endpoint (%lld, %lld) is missing; a DLS connects "
                                       "both endpoints",
                                       x0, y0);
            else if (n == 2)
                *verdict = check_wrong("no pixel has %s = %lld; a DLS has one for each %s from "
                                       "%lld to %lld (Observation 1): (%lld, %lld) or (%lld, %lld) "
                                       "here (a tie)",
                                       l->major, u, l->major, l->u1, l->u2, x0, y0, x1, y1);
            else
                *verdict = check_wrong("no pixel has %s = %lld; a DLS has one for each %s from "
                                       "%lld to %lld (Observation 1): (%lld, %lld) here",
                                       l->major, u, l->major, l->u1, l->u2, x0, y0);
            return 1;
        }
        if (u == l->u2)
            break;
    }
    return 0;
}

/* The student's DLS against cg's Bresenham: the same pixels, or different
 * only where the line passes through a midpoint (both are DLSs then). */
static int compare_with_cg(const dls *l, const check_pixel *sorted, size_t count,
                           const collected *cg)
{
    size_t cg_count = cg->xy.count / 2, ties = 0;
    long long first_x = 0, first_y = 0, first_u = 0;
    for (size_t i = 0; i < cg_count; i++) {
        long long x = cg->xy.data[2 * i], y = cg->xy.data[2 * i + 1];
        if (check_find(sorted, count, x, y) >= 0)
            continue;
        long long u = major_of(l, x, y);
        if (ties++ == 0) {
            first_x = x;
            first_y = y;
            first_u = u;
        }
    }
    if (cg_count != count)
        return check_wrong("%zu pixels; cg's Bresenham line has %zu", count, cg_count);
    if (ties == 0)
        return check_right("a digital line segment from (%lld, %lld) to (%lld, %lld): %zu pixels, "
                           "one for each %s, each within 1/2 of the line, 0-connected, the same "
                           "as cg's Bresenham line",
                           l->steep ? l->v1 : l->u1, l->steep ? l->u1 : l->v1,
                           l->steep ? l->v2 : l->u2, l->steep ? l->u2 : l->v2, count, l->major);
    check_right("a digital line segment: %zu pixels, one for each %s, each within 1/2 of the line, "
                "0-connected",
                count, l->major);
    check_note("it differs from cg's Bresenham line only at %zu tie%s, where the line passes "
               "exactly through the midpoint between two pixels; the first at %s = %lld, where "
               "cg has (%lld, %lld) (f = 0 selects E, the pixel on the start's side)",
               ties, ties == 1 ? "" : "s", l->major, first_u, first_x, first_y);
    return CLI_OK;
}

static int run_line(int argc, char **argv, FILE *in, const check_options *options)
{
    (void)options;
    static const char *const names[4] = {"X1", "Y1", "X2", "Y2"};
    long v[4];
    if (argc != 5)
        return cli_usage_error("check", "line: expected 'line X1 Y1 X2 Y2'");
    for (int i = 0; i < 4; i++)
        if (cli_parse_long("check", names[i], argv[i + 1], -1073741824L, 1073741823L, &v[i]))
            return CLI_USAGE;
    long long dx = (long long)v[2] - v[0], dy = (long long)v[3] - v[1];
    dls l = {0};
    l.steep = (dy < 0 ? -dy : dy) > (dx < 0 ? -dx : dx);
    l.u1 = l.steep ? v[1] : v[0];
    l.v1 = l.steep ? v[0] : v[1];
    l.u2 = l.steep ? v[3] : v[2];
    l.v2 = l.steep ? v[2] : v[3];
    l.du = l.u2 - l.u1;
    l.dv = l.v2 - l.v1;
    l.major = l.steep ? "y" : "x";
    l.minor = l.steep ? "x" : "y";
    if ((l.du < 0 ? -l.du : l.du) > MAX_STEPS)
        return cli_usage_error("check", "line: at most %d steps along the major axis", MAX_STEPS);
    check_pixels pixels = {0};
    int code = check_read_pixels(in, &pixels);
    collected cg = {{0}};
    check_pixel *sorted = NULL;
    if (code == CLI_OK) {
        cg_status status = cg_line_steps((int)v[0], (int)v[1], (int)v[2], (int)v[3], collect_pixels,
                                         &cg);
        sorted = check_sorted(&pixels);
        if (status != CG_OK || (pixels.count && !sorted))
            code = cli_fail("check: line: %s", cg_status_str(status ? status : CG_ENOMEM));
    }
    if (code == CLI_OK) {
        long r = check_first_repeat(sorted, pixels.count);
        if (r >= 0)
            code = check_wrong_repeat(sorted, r, "a line");
        else if (!check_each(&l, &pixels, &code) && !check_columns(&l, sorted, pixels.count, &code))
            code = compare_with_cg(&l, sorted, pixels.count, &cg);
    }
    free(sorted);
    core_array_free(&pixels);
    core_array_free(&cg.xy);
    return code;
}

const check_algorithm check_line_algorithms[] = {
    {"line", "X1 Y1 X2 Y2", run_line},
    {NULL, NULL, NULL},
};
