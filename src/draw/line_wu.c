/* Wu's anti-aliased line between pixel centres (section 2.1): along the
 * major axis, each column (row, for steep lines) gets the two pixels that
 * bracket the real line, with intensities that split 1 by the distance:
 *
 *     y = 4.3 at column x:    pixel (x, 4) gets 1 - 0.3 = 0.7
 *                             pixel (x, 5) gets 0.3
 *
 * The line runs between the centres of pixels (x0, y0) and (x1, y1): y is
 * the minor coordinate of the real line at the column's centre, in pixel
 * indices.  cg_draw_line_wu and its trace walk the same columns with the
 * same arithmetic (draw_wu_walk). */
#include "internal.h"
#include "../core/steps.h"

#include <math.h>
#include <stdlib.h>

enum { MAX_WU_TRACE = 1000000 };

/* One column: the major coordinate, the real minor coordinate, and the two
 * pixels with their intensities (lower first). */
typedef struct wu_column {
    long long k, major;
    double minor;
    long long pixel[2][2];
    double intensity[2];
} wu_column;

typedef int (*wu_visit)(void *user, const wu_column *c);

/* Walks the columns k = first .. last (0 .. n) of the line. */
static void draw_wu_walk(int x0, int y0, int x1, int y1, long long first, long long last,
                         wu_visit visit, void *user)
{
    long long dx = (long long)x1 - x0, dy = (long long)y1 - y0;
    int steep = llabs(dy) > llabs(dx);
    long long n = steep ? llabs(dy) : llabs(dx), major_step = (steep ? dy : dx) < 0 ? -1 : 1;
    double slope = n ? (double)(steep ? dx : dy) / (double)n : 0; /* minor change per step */
    long long major0 = steep ? y0 : x0, minor0 = steep ? x0 : y0;
    for (long long k = first; k <= last; k++) {
        wu_column c;
        c.k = k;
        c.major = major0 + major_step * k;
        c.minor = (double)minor0 + slope * (double)k;
        double base = floor(c.minor), fraction = c.minor - base;
        for (int i = 0; i < 2; i++) {
            long long minor = (long long)base + i;
            c.pixel[i][0] = steep ? minor : c.major;
            c.pixel[i][1] = steep ? c.major : minor;
        }
        c.intensity[0] = 1 - fraction;
        c.intensity[1] = fraction;
        if (visit(user, &c))
            return;
    }
}

static int paint_column(void *user, const wu_column *c)
{
    const cg_painter *painter = user;
    for (int i = 0; i < 2; i++)
        if (c->intensity[i] > 0 && cg_painter_visible(painter, c->pixel[i][0], c->pixel[i][1]))
            draw_painter_cover(painter, (int)c->pixel[i][0], (int)c->pixel[i][1],
                               (float)c->intensity[i]);
    return 0;
}

cg_status cg_draw_line_wu(cg_image *image, int x0, int y0, int x1, int y1, cg_rgba8 color)
{
    if (!image || !image->data)
        return CG_EINVAL;
    long long dx = (long long)x1 - x0, dy = (long long)y1 - y0;
    int steep = llabs(dy) > llabs(dx);
    long long n = steep ? llabs(dy) : llabs(dx), step = (steep ? dy : dx) < 0 ? -1 : 1;
    long long major0 = steep ? y0 : x0, size = steep ? image->height : image->width;
    /* Only the columns inside the image: major0 + step k in [0, size). */
    long long a = step > 0 ? -major0 : major0 - (size - 1);
    long long b = step > 0 ? size - 1 - major0 : major0;
    long long first = a > 0 ? a : 0, last = b < n ? b : n;
    if (first > last)
        return CG_OK;
    cg_painter painter;
    draw_painter_init(&painter, image, color);
    draw_wu_walk(x0, y0, x1, y1, first, last, paint_column, &painter);
    return CG_OK;
}

typedef struct wu_relay {
    cg_step_fn fn;
    void *user;
} wu_relay;

static int relay_column(void *user, const wu_column *c)
{
    wu_relay *r = user;
    core_step s;
    int xy[4] = {(int)c->pixel[0][0], (int)c->pixel[0][1], (int)c->pixel[1][0],
                 (int)c->pixel[1][1]};
    core_step_begin(&s, "columns");
    core_step_integer(&s, "k", c->k);
    core_step_integer(&s, "major", c->major);
    core_step_real(&s, "minor", c->minor);
    core_step_pixel(&s, "lower", c->pixel[0][0], c->pixel[0][1]);
    core_step_real(&s, "I_lower", c->intensity[0]);
    core_step_pixel(&s, "upper", c->pixel[1][0], c->pixel[1][1]);
    core_step_real(&s, "I_upper", c->intensity[1]);
    s.step.pixels = xy;
    s.step.intensity = c->intensity;
    s.step.pixel_count = 2;
    return core_step_emit(&s, r->fn, r->user);
}

cg_status cg_line_wu_steps(int x0, int y0, int x1, int y1, cg_step_fn step, void *user)
{
    if (!step)
        return CG_EINVAL;
    long long dx = llabs((long long)x1 - x0), dy = llabs((long long)y1 - y0);
    long long n = dx > dy ? dx : dy;
    if (n > MAX_WU_TRACE)
        return CG_ERANGE;
    wu_relay relay = {step, user};
    draw_wu_walk(x0, y0, x1, y1, 0, n, relay_column, &relay);
    return CG_OK;
}
