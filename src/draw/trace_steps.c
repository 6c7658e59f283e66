/* The chapter-2 traces of cg/trace_steps.h: Bresenham's and the DDA line,
 * the midpoint circle with its mirrors and the midpoint ellipse, each as
 * cg_step records in the notes' vocabulary. */
#include "internal.h"
#include "../core/steps.h"

#include <math.h>
#include <stdlib.h>

enum { MAX_LINE_STEPS = 1000000, MAX_CIRCLE_RADIUS = 1000000, MAX_ELLIPSE_RADIUS = 20000 };

/* The octant of the direction (dx, dy), with y as the numbers give it (in
 * the image y grows downwards, so the count runs clockwise there): 1 to 8
 * counter-clockwise from +x, octant k covering the angles [45 (k - 1),
 * 45 k) degrees; 0 for a point.  Octant 1 is the notes' first octant,
 * 0 <= dy < dx.
 *
 *         y ^
 *       3   |   2
 *     4     |     1
 *   --------+--------> x
 *     5     |     8
 *       6   |   7          */
static int line_octant(long long x, long long y)
{
    if (x == 0 && y == 0)
        return 0;
    if (y >= 0 && x > 0)
        return y < x ? 1 : 2;
    if (x <= 0 && y > 0)
        return -x < y ? 3 : 4;
    if (y <= 0 && x < 0)
        return -y < -x ? 5 : 6;
    return x < -y ? 7 : 8;
}

typedef struct line_relay {
    cg_step_fn fn;
    void *user;
    int stopped;
} line_relay;

static int relay_line_step(void *user, const cg_line_step *s)
{
    line_relay *r = user;
    core_step step;
    int xy[2] = {s->x, s->y};
    core_step_begin(&step, "walk");
    int start = s->move[0] == 's';
    if (start)
        core_step_none(&step, "f");
    else
        core_step_integer(&step, "f", s->f);
    core_step_text(&step, "move", s->move);
    core_step_integer(&step, "f_next", s->f_next);
    core_step_pixel(&step, "pixel", s->x, s->y);
    step.step.pixels = xy;
    step.step.pixel_count = 1;
    r->stopped = core_step_emit(&step, r->fn, r->user);
    return r->stopped;
}

cg_status cg_line_steps(int x0, int y0, int x1, int y1, cg_step_fn step, void *user)
{
    if (!step)
        return CG_EINVAL;
    long long dx = (long long)x1 - x0, dy = (long long)y1 - y0;
    if (llabs(dx) > MAX_LINE_STEPS || llabs(dy) > MAX_LINE_STEPS)
        return CG_ERANGE;
    cg_line_frame frame;
    long long du, dv, de, dne;
    draw_line_frame_make(x0, y0, x1, y1, &frame);
    cg_line_trace(x0, y0, x1, y1, NULL, NULL, &du, &dv, &de, &dne);
    core_step s;
    cg_vec2 line[2] = {{x0 + 0.5, y0 + 0.5}, {x1 + 0.5, y1 + 0.5}};
    core_step_begin(&s, "octant");
    core_step_integer(&s, "octant", line_octant(dx, dy));
    core_step_text(&s, "swap", frame.swapped ? "walk from the second endpoint" : "no");
    core_step_text(&s, "exchange", frame.x_major ? "no" : "x and y exchanged (steep)");
    core_step_text(&s, "mirror", frame.sv < 0 ? "minor coordinate steps -1" : "no");
    core_step_integer(&s, "dx", du);
    core_step_integer(&s, "dy", dv);
    core_step_integer(&s, "f0", 2 * dv - du);
    core_step_integer(&s, "dE", de);
    core_step_integer(&s, "dNE", dne);
    s.step.geometry = line;
    s.step.geometry_count = 2;
    if (core_step_emit(&s, step, user))
        return CG_OK;
    line_relay relay = {step, user, 0};
    cg_line_trace(x0, y0, x1, y1, relay_line_step, &relay, NULL, NULL, NULL, NULL);
    return CG_OK;
}

/* floor(v + 1/2): the DDA's rounding (halves up). */
static long long round_half_up(double v)
{
    return (long long)floor(v + 0.5);
}

cg_status cg_line_dda_steps(int x0, int y0, int x1, int y1, cg_step_fn step, void *user)
{
    if (!step)
        return CG_EINVAL;
    long long dx = (long long)x1 - x0, dy = (long long)y1 - y0;
    long long n = llabs(dx) > llabs(dy) ? llabs(dx) : llabs(dy);
    if (n > MAX_LINE_STEPS)
        return CG_ERANGE;
    /* One of the increments is exactly +-1 (or both 0): only the minor
     * coordinate accumulates rounding, as in the notes. */
    double x_step = n ? (double)dx / (double)n : 0, y_step = n ? (double)dy / (double)n : 0;
    double x = x0, y = y0;
    for (long long k = 0; k <= n; k++) {
        core_step s;
        int xy[2] = {(int)round_half_up(x), (int)round_half_up(y)};
        core_step_begin(&s, "walk");
        core_step_integer(&s, "k", k);
        core_step_real(&s, "x", x);
        core_step_real(&s, "y", y);
        core_step_pixel(&s, "pixel", xy[0], xy[1]);
        s.step.pixels = xy;
        s.step.pixel_count = 1;
        if (core_step_emit(&s, step, user))
            break;
        x += x_step;
        y += y_step;
    }
    return CG_OK;
}

/* ---- circle -------------------------------------------------------------- */

typedef struct circle_relay {
    int cx, cy;
    cg_step_fn fn;
    void *user;
} circle_relay;

/* The distinct mirrors of first-octant pixel (x, y), 0 <= x <= y, around
 * the centre: 1, 4 or 8 pixels. */
static int circle_mirrors(int cx, int cy, long long x, long long y, int xy[16])
{
    long long offsets[8][2] = {{x, y},  {y, x},  {-x, y},  {-y, x},
                               {x, -y}, {y, -x}, {-x, -y}, {-y, -x}};
    int n = 0;
    for (int i = 0; i < 8; i++) {
        int seen = 0;
        for (int j = 0; j < n && !seen; j++)
            seen = xy[2 * j] == cx + offsets[i][0] && xy[2 * j + 1] == cy + offsets[i][1];
        if (!seen) {
            xy[2 * n] = (int)(cx + offsets[i][0]);
            xy[2 * n + 1] = (int)(cy + offsets[i][1]);
            n++;
        }
    }
    return n;
}

static int relay_circle_step(void *user, const cg_circle_step *c)
{
    circle_relay *r = user;
    core_step s;
    int xy[16];
    core_step_begin(&s, "octant 0 <= x <= y");
    int start = c->move[0] == 's';
    if (start) {
        core_step_none(&s, "f");
        core_step_none(&s, "dE");
        core_step_none(&s, "dSE");
    } else {
        core_step_integer(&s, "f", c->f);
        core_step_integer(&s, "dE", c->de);
        core_step_integer(&s, "dSE", c->dse);
    }
    core_step_text(&s, "move", c->move);
    core_step_integer(&s, "f_next", c->f_next);
    core_step_integer(&s, "dE_next", c->de_next);
    core_step_integer(&s, "dSE_next", c->dse_next);
    core_step_pixel(&s, "pixel", c->x, c->y);
    if (c->x > c->y) {
        core_step_text(&s, "note", "x > y: mirrors an earlier pixel, not drawn");
    } else {
        core_step_text(&s, "note", "");
        s.step.pixels = xy;
        s.step.pixel_count = circle_mirrors(r->cx, r->cy, c->x, c->y, xy);
    }
    return core_step_emit(&s, r->fn, r->user);
}

cg_status cg_circle_steps(int cx, int cy, int r, cg_step_fn step, void *user)
{
    if (!step || r < 0)
        return CG_EINVAL;
    if (r > MAX_CIRCLE_RADIUS)
        return CG_ERANGE;
    circle_relay relay = {cx, cy, step, user};
    return cg_circle_trace(r, relay_circle_step, &relay);
}

/* ---- ellipse ------------------------------------------------------------- */

/* F(x, y) = b^2 x^2 + a^2 y^2 - a^2 b^2 with a = rx, b = ry; the traces
 * test 4F at midpoints, so half-integers stay integers:
 * 4F(x, y + 1/2) = 4 b^2 x^2 + a^2 (2y + 1)^2 - 4 a^2 b^2. */
typedef struct ellipse_trace {
    long long cx, cy, rx, ry;
    cg_wide a2, b2;
    cg_step_fn fn;
    void *user;
} ellipse_trace;

static cg_wide four_f_row_midpoint(const ellipse_trace *e, long long x, long long y)
{
    return 4 * e->b2 * x * x + e->a2 * (2 * y + 1) * (2 * y + 1) - 4 * e->a2 * e->b2;
}

static cg_wide four_f_column_midpoint(const ellipse_trace *e, long long x, long long y)
{
    return e->b2 * (2 * x + 1) * (2 * x + 1) + 4 * e->a2 * y * y - 4 * e->a2 * e->b2;
}

/* Region 1's pixel in column x: the smallest y >= 0 with F(x, y + 1/2) >= 0,
 * searched down from y_above (a row at or above it). */
static long long ellipse_row(const ellipse_trace *e, long long x, long long y_above)
{
    long long y = y_above;
    while (y > 0 && four_f_row_midpoint(e, x, y - 1) >= 0)
        y--;
    return y;
}

/* Region 2's pixel in row y: the smallest x >= 0 with F(x + 1/2, y) >= 0,
 * searched right from x_left (a column at or left of it). */
static long long ellipse_column(const ellipse_trace *e, long long y, long long x_left)
{
    long long x = x_left;
    while (four_f_column_midpoint(e, x, y) < 0)
        x++;
    return x;
}

/* The largest x >= 0 with x^2 (a^2 + b^2) <= limit^2: the last column of
 * region 1 (limit a^2) or last row of region 2 (limit b^2). */
static long long region_end(cg_wide limit, cg_wide sum)
{
    long long x = (long long)((double)limit / sqrt((double)sum));
    while (x > 0 && (cg_wide)x * x * sum > limit * limit)
        x--;
    while ((cg_wide)(x + 1) * (x + 1) * sum <= limit * limit)
        x++;
    return x;
}

static int emit_ellipse(const ellipse_trace *e, const char *phase, long long x, long long y,
                        const char *move, int have_decision, cg_wide decision)
{
    core_step s;
    int xy[8], n = 0;
    long long offsets[4][2] = {{x, -y}, {-x, -y}, {x, y}, {-x, y}};
    int wanted[4] = {1, x > 0, y > 0, x > 0 && y > 0};
    for (int i = 0; i < 4; i++)
        if (wanted[i]) {
            xy[2 * n] = (int)(e->cx + offsets[i][0]);
            xy[2 * n + 1] = (int)(e->cy + offsets[i][1]);
            n++;
        }
    core_step_begin(&s, phase);
    core_step_integer(&s, "x", x);
    core_step_integer(&s, "y", y);
    if (have_decision)
        core_step_integer(&s, "d", (long long)decision);
    else
        core_step_none(&s, "d");
    core_step_text(&s, "move", move);
    core_step_pixel(&s, "pixel", xy[0], xy[1]);
    s.step.pixels = xy;
    s.step.pixel_count = n;
    return core_step_emit(&s, e->fn, e->user);
}

/* rx or ry is 0: the ellipse is a segment along an axis, or a point. */
static void ellipse_segment(const ellipse_trace *e)
{
    long long last = e->ry == 0 ? e->rx : e->ry;
    for (long long k = 0; k <= last; k++)
        if (emit_ellipse(e, "segment", e->ry == 0 ? k : 0, e->ry == 0 ? 0 : k,
                         k ? (e->ry == 0 ? "E" : "S") : "start", 0, 0))
            return;
}

/* Region 1: columns 0 .. xs from (0, ry), E or SE by d1 = 4F(x, y - 1/2). */
static int ellipse_region1(const ellipse_trace *e, long long xs, long long *last_y)
{
    long long y = e->ry;
    if (emit_ellipse(e, "region 1", 0, y, "start", 0, 0))
        return 1;
    for (long long x = 1; x <= xs; x++) {
        cg_wide d = y > 0 ? four_f_row_midpoint(e, x, y - 1) : -1;
        long long next = ellipse_row(e, x, y);
        const char *move = next == y ? "E" : next == y - 1 ? "SE" : "SE (several rows)";
        y = next;
        if (emit_ellipse(e, "region 1", x, y, move, 1, d))
            return 1;
    }
    *last_y = y;
    return 0;
}

cg_status cg_ellipse_steps(int cx, int cy, int rx, int ry, cg_step_fn step, void *user)
{
    if (!step || rx < 0 || ry < 0)
        return CG_EINVAL;
    if (rx > MAX_ELLIPSE_RADIUS || ry > MAX_ELLIPSE_RADIUS)
        return CG_ERANGE;
    ellipse_trace e = {cx, cy, rx, ry, (cg_wide)rx * rx, (cg_wide)ry * ry, step, user};
    if (rx == 0 || ry == 0) {
        ellipse_segment(&e);
        return CG_OK;
    }
    cg_wide sum = e.a2 + e.b2;
    long long xs = region_end(e.a2, sum), ys = region_end(e.b2, sum);
    long long ax = xs, ay = ry;
    if (ellipse_region1(&e, xs, &ay))
        return CG_OK;
    long long bx = ellipse_column(&e, ys, 0), by = ys;
    /* The switch: region 2 starts on row ys; a two-pixel gap between the
     * regions' last pixels is bridged by the pixel its row (or column)
     * would pick, kept adjacent to both. */
    if (ay - by == 2) {
        long long x = ellipse_column(&e, ay - 1, 0), low = ax > bx - 1 ? ax : bx - 1;
        long long high = ax + 1 < bx ? ax + 1 : bx;
        x = x < low ? low : x > high ? high : x;
        if (emit_ellipse(&e, "switch", x, ay - 1, "bridge", 1,
                         four_f_column_midpoint(&e, x, ay - 1)))
            return CG_OK;
    } else if (bx - ax == 2) {
        long long y = ellipse_row(&e, ax + 1, ay), low = by > ay - 1 ? by : ay - 1;
        long long high = by + 1 < ay ? by + 1 : ay;
        y = y < low ? low : y > high ? high : y;
        if (emit_ellipse(&e, "switch", ax + 1, y, "bridge", 1, four_f_row_midpoint(&e, ax + 1, y)))
            return CG_OK;
    }
    int same = ax == bx && ay == by;
    long long x = bx;
    for (long long y = ys; y >= 0; y--) {
        /* d2 = 4F(x + 1/2, y) at the previous column: >= 0 keeps it (S). */
        cg_wide d = four_f_column_midpoint(&e, x, y);
        long long next = ellipse_column(&e, y, x);
        const char *move = y == ys         ? (same ? "switch (region 1's last pixel)" : "switch")
                           : next == x     ? "S"
                           : next == x + 1 ? "SE"
                                           : "SE (several columns)";
        x = next;
        if (y == ys && same)
            continue;
        if (emit_ellipse(&e, "region 2", x, y, move, 1, d))
            return CG_OK;
    }
    return CG_OK;
}
