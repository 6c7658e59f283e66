/* `cg check cohen-sutherland XMIN YMIN XMAX YMAX X0,Y0 X1,Y1` and `cg check
 * sutherland-hodgman 'WINDOW' 'SUBJECT'` (chapter 11): the student's
 * coordinates against the definition (the part of the segment or polygon
 * inside the window) and cg's clippers, within --tolerance.  y points up,
 * as in cg clip and cg trace. */
#include "check.h"

#include "cli.h"
#include "trace_algorithms.h"
#include "cg/clip.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_POLYGON = 256 };

static int near(cg_vec2 a, cg_vec2 b, double tolerance)
{
    return fabs(a.x - b.x) <= tolerance && fabs(a.y - b.y) <= tolerance;
}

/* "1001 (T: y > ymax, L: x < xmin)" */
static void describe_code(unsigned code, char *text, size_t size)
{
    static const char *const parts[4] = {"L: x < xmin", "R: x > xmax", "B: y < ymin",
                                         "T: y > ymax"};
    size_t used = (size_t)snprintf(text, size, "%u%u%u%u", (code >> 3) & 1, (code >> 2) & 1,
                                   (code >> 1) & 1, code & 1);
    int first = 1;
    for (int bit = 3; bit >= 0 && used < size; bit--)
        if (code & (1u << bit)) {
            used += (size_t)snprintf(text + used, size - used, "%s%s", first ? " (" : ", ",
                                     parts[bit]);
            first = 0;
        }
    if (!first && used < size)
        snprintf(text + used, size - used, ")");
}

/* The visible part of p0-p1 by its definition, P(t) for t in [t0, t1]
 * where every boundary holds: 1 when there is one. */
static int visible_part(cg_rect w, cg_vec2 p0, cg_vec2 p1, cg_vec2 *a, cg_vec2 *b)
{
    double d[2] = {p1.x - p0.x, p1.y - p0.y}, t0 = 0, t1 = 1;
    double p[4] = {-d[0], d[0], -d[1], d[1]};
    double q[4] = {p0.x - w.xmin, w.xmax - p0.x, p0.y - w.ymin, w.ymax - p0.y};
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0) {
            if (q[k] < 0)
                return 0;
            continue;
        }
        double t = q[k] / p[k];
        if (p[k] < 0 && t > t0)
            t0 = t;
        if (p[k] > 0 && t < t1)
            t1 = t;
    }
    if (t0 > t1)
        return 0;
    *a = t0 == 0 ? p0 : (cg_vec2){p0.x + t0 * d[0], p0.y + t0 * d[1]};
    *b = t1 == 1 ? p1 : (cg_vec2){p0.x + t1 * d[0], p0.y + t1 * d[1]};
    return 1;
}

/* Distance of q from the segment a-b. */
static double segment_distance(cg_vec2 a, cg_vec2 b, cg_vec2 q)
{
    double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((q.x - a.x) * dx + (q.y - a.y) * dy) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(q.x - (a.x + t * dx), q.y - (a.y + t * dy));
}

/* Which boundary a visible end lies on, for the note. */
static const char *boundary_of(cg_rect w, cg_vec2 p, double tolerance)
{
    if (fabs(p.x - w.xmin) <= tolerance)
        return "the left boundary x = xmin";
    if (fabs(p.x - w.xmax) <= tolerance)
        return "the right boundary x = xmax";
    if (fabs(p.y - w.ymin) <= tolerance)
        return "the bottom boundary y = ymin";
    return "the top boundary y = ymax";
}

/* Each point in the window and on the segment: 1 after a verdict. */
static int check_cs_points(cg_rect w, cg_vec2 p0, cg_vec2 p1, const check_points *in,
                           double tolerance, int *verdict)
{
    cg_rect grown = {w.xmin - tolerance, w.ymin - tolerance, w.xmax + tolerance,
                     w.ymax + tolerance};
    for (size_t i = 0; i < in->count; i++) {
        cg_vec2 q = in->data[i].p;
        unsigned code = cg_clip_rcode(grown, q);
        char text[96];
        if (code) {
            describe_code(code, text, sizeof text);
            *verdict = check_wrong("point (%g, %g) is outside the window: its region code is %s; "
                                   "a clipped endpoint lies in the window (code 0000)",
                                   q.x, q.y, text);
            return 1;
        }
        double d = segment_distance(p0, p1, q);
        if (d > tolerance) {
            *verdict = check_wrong("point (%g, %g) is %.3g from the segment (%g, %g)-(%g, %g); a "
                                   "clipped endpoint lies on the segment",
                                   q.x, q.y, d, p0.x, p0.y, p1.x, p1.y);
            return 1;
        }
    }
    return 0;
}

static int cs_verdict(cg_rect w, cg_vec2 p0, cg_vec2 p1, const check_points *in, double tolerance)
{
    cg_vec2 a, b;
    int visible = visible_part(w, p0, p1, &a, &b);
    unsigned c0 = cg_clip_rcode(w, p0), c1 = cg_clip_rcode(w, p1);
    char t0[96], t1[96];
    describe_code(c0, t0, sizeof t0);
    describe_code(c1, t1, sizeof t1);
    int code;
    if (check_cs_points(w, p0, p1, in, tolerance, &code))
        return code;
    if (!visible && in->count == 0)
        return check_right("rejected: no part of the segment lies in the window (codes %s and "
                           "%s%s)",
                           t0, t1, (c0 & c1) ? ", a trivial reject: their AND is not 0000" : "");
    if (!visible) {
        check_wrong("point (%g, %g): the segment misses the window, so Cohen-Sutherland rejects "
                    "it and outputs no point",
                    in->data[0].p.x, in->data[0].p.y);
        check_note("P0 has region code %s, P1 %s", t0, t1);
        return CLI_FAILED;
    }
    if (in->count == 0) {
        check_wrong("rejected, but the part from (%g, %g) to (%g, %g) lies in the window", a.x, a.y,
                    b.x, b.y);
        check_note("P0 has region code %s, P1 %s: their AND is %s", t0, t1,
                   (c0 & c1) ? "not 0000" : "0000, so it is no trivial reject");
        return CLI_FAILED;
    }
    cg_vec2 s0 = in->data[0].p, s1 = in->data[1].p;
    if (near(s0, a, tolerance) && near(s1, b, tolerance))
        return check_right("the visible part from (%g, %g) to (%g, %g), as Cohen-Sutherland "
                           "clips it",
                           a.x, a.y, b.x, b.y);
    if (near(s0, b, tolerance) && near(s1, a, tolerance)) {
        check_right("the visible part from (%g, %g) to (%g, %g)", a.x, a.y, b.x, b.y);
        check_note("listed from P1's side: cg keeps the direction P0 -> P1");
        return CLI_OK;
    }
    int first_wrong = !(near(s0, a, tolerance) || near(s0, b, tolerance));
    cg_vec2 bad = first_wrong ? s0 : s1, good = first_wrong ? (near(s1, b, tolerance) ? a : b)
                                                            : (near(s0, a, tolerance) ? b : a);
    check_wrong("point (%g, %g) should be (%g, %g): the visible part runs from (%g, %g) to (%g, "
                "%g)",
                bad.x, bad.y, good.x, good.y, a.x, a.y, b.x, b.y);
    if (!near(good, p0, tolerance) && !near(good, p1, tolerance))
        check_note("(%g, %g) is where the segment crosses %s", good.x, good.y,
                   boundary_of(w, good, tolerance));
    return CLI_FAILED;
}

static int run_cohen_sutherland(int argc, char **argv, FILE *in, const check_options *options)
{
    cg_rect w;
    cg_vec2 p0, p1;
    if (trace_parse_window_segment("check", "cohen-sutherland", argc, argv, &w, &p0, &p1))
        return CLI_USAGE;
    check_points points = {0};
    int code = check_read_points(in, &points);
    if (code == CLI_OK && points.count != 0 && points.count != 2)
        code = cli_usage_error("check",
                               "cohen-sutherland: expected the clipped segment's two "
                               "endpoints, or no point when it is rejected; got %zu",
                               points.count);
    if (code == CLI_OK) {
        /* cg's clipper must agree with the definition (a check of cg). */
        cg_vec2 q0 = p0, q1 = p1, a, b;
        int accepted = 0;
        cg_status status = cg_clip_line_cohen_sutherland(w, &q0, &q1, &accepted, NULL, NULL);
        int visible = visible_part(w, p0, p1, &a, &b);
        if (status != CG_OK)
            code = cli_fail("check: cohen-sutherland: %s", cg_status_str(status));
        else if (accepted != visible
                 || (visible
                     && !(near(q0, a, 1e-9 * (1 + fabs(a.x) + fabs(a.y)))
                          && near(q1, b, 1e-9 * (1 + fabs(b.x) + fabs(b.y))))))
            code = cli_fail("check: cohen-sutherland: cg's clipper and the definition disagree");
        else
            code = cs_verdict(w, p0, p1, &points, options->tolerance);
    }
    core_array_free(&points);
    return code;
}

/* ---- Sutherland-Hodgman --------------------------------------------------- */

/* Drops each point equal (within tolerance) to the one before it, also
 * around the end: the new count. */
static size_t drop_repeats(cg_vec2 *p, size_t n, double tolerance)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        if (k == 0 || !near(p[i], p[k - 1], tolerance))
            p[k++] = p[i];
    while (k > 1 && near(p[k - 1], p[0], tolerance))
        k--;
    return k;
}

/* The clip edge (0-based) the point is outside of, or -1. */
static int outside_edge(const cg_vec2 *w, size_t m, cg_vec2 q, double tolerance)
{
    double area = 0;
    for (size_t i = 0; i < m; i++)
        area += w[i].x * w[(i + 1) % m].y - w[(i + 1) % m].x * w[i].y;
    for (size_t i = 0; i < m; i++) {
        cg_vec2 a = w[i], b = w[(i + 1) % m];
        double len = hypot(b.x - a.x, b.y - a.y);
        if (len == 0)
            continue;
        double side = ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / len;
        if ((area > 0 ? side : -side) < -tolerance)
            return (int)i;
    }
    return -1;
}

/* Whether s matches e (n points each) from e's vertex r on, forwards or
 * (backwards) backwards; the first mismatch in *at. */
static int matches(const cg_vec2 *s, const cg_vec2 *e, size_t n, size_t r, int backwards,
                   double tolerance, size_t *at)
{
    for (size_t i = 0; i < n; i++) {
        size_t k = backwards ? (r + n - i) % n : (r + i) % n;
        if (!near(s[i], e[k], tolerance)) {
            *at = i;
            return 0;
        }
    }
    return 1;
}

static int sh_compare(cg_vec2 *s, size_t n, cg_vec2 *e, size_t m, double tolerance)
{
    if (n != m) {
        for (size_t k = 0; k < m; k++) {
            size_t i = 0;
            while (i < n && !near(s[i], e[k], tolerance))
                i++;
            if (i == n)
                return check_wrong("%zu vertices; Sutherland-Hodgman's output list has %zu, "
                                   "and (%g, %g), its vertex %zu, is missing",
                                   n, m, e[k].x, e[k].y, k + 1);
        }
        for (size_t i = 0; i < n; i++) {
            size_t k = 0;
            while (k < m && !near(s[i], e[k], tolerance))
                k++;
            if (k == m)
                return check_wrong("vertex %zu (%g, %g) is not in Sutherland-Hodgman's output "
                                   "list (%zu vertices)",
                                   i + 1, s[i].x, s[i].y, m);
        }
        return check_wrong("%zu vertices; Sutherland-Hodgman's output list has %zu (a vertex "
                           "repeated?)",
                           n, m);
    }
    size_t r = 0, at = 0, best = 0;
    while (r < m && !near(s[0], e[r], tolerance))
        r++;
    if (r == m)
        return check_wrong("vertex 1 (%g, %g) is not in Sutherland-Hodgman's output list", s[0].x,
                           s[0].y);
    if (matches(s, e, n, r, 0, tolerance, &at)) {
        check_right("the clipped polygon, %zu vertices, as Sutherland-Hodgman's output list", n);
        if (r)
            check_note("your list starts at the output list's vertex %zu", r + 1);
        return CLI_OK;
    }
    best = at;
    if (matches(s, e, n, r, 1, tolerance, &at)) {
        check_right("the clipped polygon, %zu vertices, in the opposite order", n);
        check_note("Sutherland-Hodgman keeps the subject's orientation");
        return CLI_OK;
    }
    size_t k = (r + best) % m;
    return check_wrong("vertex %zu is (%g, %g); Sutherland-Hodgman's output list has (%g, %g) "
                       "there",
                       best + 1, s[best].x, s[best].y, e[k].x, e[k].y);
}

static int sh_verdict(const cg_vec2 *window, size_t m, check_points *in, cg_vec2 *expected,
                      size_t count, double tolerance)
{
    for (size_t i = 0; i < in->count; i++) {
        int edge = outside_edge(window, m, in->data[i].p, tolerance);
        if (edge >= 0) {
            cg_vec2 a = window[edge], b = window[((size_t)edge + 1) % m];
            return check_wrong("vertex %zu (%g, %g) is outside clip edge %d from (%g, %g) to "
                               "(%g, %g); the clipped polygon lies inside every clip edge",
                               i + 1, in->data[i].p.x, in->data[i].p.y, edge + 1, a.x, a.y, b.x,
                               b.y);
        }
    }
    cg_vec2 *s = malloc((in->count ? in->count : 1) * sizeof *s);
    if (!s)
        return cli_fail("check: out of memory");
    for (size_t i = 0; i < in->count; i++)
        s[i] = in->data[i].p;
    size_t n = drop_repeats(s, in->count, tolerance);
    size_t m2 = drop_repeats(expected, count, tolerance);
    int code;
    if (n == 0 && m2 == 0)
        code = check_right("nothing: the subject lies outside the window");
    else if (n == 0)
        code = check_wrong("no vertex, but the subject reaches into the window: the output list "
                           "starts (%g, %g)",
                           expected[0].x, expected[0].y);
    else if (m2 == 0)
        code = check_wrong("vertex 1 (%g, %g): the subject lies outside the window, so the "
                           "output list is empty",
                           s[0].x, s[0].y);
    else
        code = sh_compare(s, n, expected, m2, tolerance);
    if (n != in->count || m2 != count)
        check_note("points repeated one after the other were compared once (a vertex on a clip "
                   "line may be output twice)");
    free(s);
    return code;
}

static int run_sutherland_hodgman(int argc, char **argv, FILE *in, const check_options *options)
{
    static cg_vec2 window[MAX_POLYGON], subject[MAX_POLYGON];
    if (argc != 3)
        return cli_usage_error("check", "sutherland-hodgman: expected 'sutherland-hodgman "
                                        "\"WINDOW\" \"SUBJECT\"', each as 'X,Y X,Y X,Y ...'");
    int m = trace_parse_polygon_for("check", "WINDOW", argv[1], window, MAX_POLYGON);
    int n = m < 0 ? -1 : trace_parse_polygon_for("check", "SUBJECT", argv[2], subject, MAX_POLYGON);
    if (m < 0 || n < 0)
        return CLI_USAGE;
    if (m < 3 || n < 3)
        return cli_usage_error("check", "sutherland-hodgman: each polygon needs at least 3 "
                                        "points");
    cg_vec2 *expected = NULL;
    size_t count = 0;
    cg_status status = cg_clip_sutherland_hodgman(subject, (size_t)n, window, (size_t)m, &expected,
                                                  &count);
    if (status != CG_OK)
        return cli_usage_error("check",
                               "sutherland-hodgman: %s (the window must be convex with "
                               "non-zero area)",
                               cg_status_str(status));
    check_points points = {0};
    int code = check_read_points(in, &points);
    if (code == CLI_OK)
        code = sh_verdict(window, (size_t)m, &points, expected, count, options->tolerance);
    free(expected);
    core_array_free(&points);
    return code;
}

const check_algorithm check_clip_algorithms[] = {
    {"cohen-sutherland", "XMIN YMIN XMAX YMAX X0,Y0 X1,Y1", run_cohen_sutherland},
    {"sutherland-hodgman", "'WINDOW' 'SUBJECT'", run_sutherland_hodgman},
    {NULL, NULL, NULL},
};
