/* Step-by-step records of Algorithms 1 and 2, for learners (`cg trace`). */
#include "internal.h"

cg_status cg_line_trace(int x0, int y0, int x1, int y1,
                        int (*step)(void *user, const cg_line_step *s), void *user, long long *dx,
                        long long *dy, long long *de, long long *dne)
{
    cg_line_frame l;
    draw_line_frame_make(x0, y0, x1, y1, &l);
    long long e = 2 * l.dv, ne = 2 * (l.dv - l.du), f = 2 * l.dv - l.du;
    if (dx)
        *dx = l.du;
    if (dy)
        *dy = l.dv;
    if (de)
        *de = e;
    if (dne)
        *dne = ne;
    if (!step)
        return CG_OK;
    long long u = l.u0, v = l.v0;
    cg_line_step s = {0, 0, "start", f, f};
    for (long long k = 0; k <= l.du; k++) {
        if (k > 0) {
            s.f = f;
            if (f <= 0) {
                s.move = "E";
                f += e;
            } else {
                s.move = "NE";
                f += ne;
                v += l.sv;
            }
            u++;
            s.f_next = f;
        }
        s.x = (int)(l.x_major ? u : v);
        s.y = (int)(l.x_major ? v : u);
        if (step(user, &s))
            break;
    }
    return CG_OK;
}

cg_status cg_circle_trace(int r, int (*step)(void *user, const cg_circle_step *s), void *user)
{
    if (!step || r < 0)
        return CG_EINVAL;
    long long x = 0, y = r, f = 1 - (long long)r, de = 3, dse = 5 - 2 * (long long)r;
    cg_circle_step s = {0, r, "start", f, de, dse, f, de, dse};
    if (step(user, &s))
        return CG_OK;
    while (x < y) {
        s.f = f;
        s.de = de;
        s.dse = dse;
        if (f < 0) {
            s.move = "E";
            f += de;
            de += 2;
            dse += 2;
        } else {
            s.move = "SE";
            f += dse;
            de += 2;
            dse += 4;
            y--;
        }
        x++;
        s.x = (int)x;
        s.y = (int)y;
        s.f_next = f;
        s.de_next = de;
        s.dse_next = dse;
        if (step(user, &s))
            break;
    }
    return CG_OK;
}
