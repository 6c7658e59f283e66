/* Clipping in homogeneous coordinates against the six planes of the view
 * volume (section 11.3 of the notes), before the perspective divide: a point
 * is inside when -w <= x, y, z <= w.  Clipping before dividing keeps points
 * behind the camera (w <= 0) from wrapping around through infinity. */
#include "internal.h"

static double plane_distance(const double c[4], int plane)
{
    switch (plane) {
    case 0: return c[3] + c[0];
    case 1: return c[3] - c[0];
    case 2: return c[3] + c[1];
    case 3: return c[3] - c[1];
    case 4: return c[3] + c[2];
    default: return c[3] - c[2];
    }
}

/* The point a fraction t of the way from `inside` to `outside`. */
static void interpolate(const clip_vertex *inside, const clip_vertex *outside, double t,
                        int attribute_count, clip_vertex *out)
{
    for (int i = 0; i < 4; i++)
        out->c[i] = inside->c[i] + t * (outside->c[i] - inside->c[i]);
    for (int i = 0; i < attribute_count; i++)
        out->a[i] = (float)(inside->a[i] + t * ((double)outside->a[i] - inside->a[i]));
}

int render_clip_polygon(const clip_vertex *in, int n, unsigned mask, int attribute_count,
                        clip_vertex *out)
{
    clip_vertex buffer[2][RENDER_MAX_POLYGON + 1];
    const clip_vertex *source = in;
    int count = n;
    int which = 0;
    for (int plane = 0; plane < 6 && count > 0; plane++) {
        if (!(mask & (1u << plane)))
            continue;
        clip_vertex *target = buffer[which];
        int produced = 0;
        for (int i = 0; i < count; i++) {
            const clip_vertex *current = &source[i], *next = &source[(i + 1) % count];
            double dc = plane_distance(current->c, plane), dn = plane_distance(next->c, plane);
            int current_in = dc >= 0, next_in = dn >= 0;
            if (current_in && produced <= RENDER_MAX_POLYGON)
                target[produced++] = *current;
            if (current_in != next_in && produced <= RENDER_MAX_POLYGON) {
                /* Always from the inside end, so a shared edge is cut alike. */
                if (current_in)
                    interpolate(current, next, dc / (dc - dn), attribute_count,
                                &target[produced++]);
                else
                    interpolate(next, current, dn / (dn - dc), attribute_count,
                                &target[produced++]);
            }
        }
        source = target;
        count = produced < 3 ? 0 : produced;
        which ^= 1;
    }
    if (count > RENDER_MAX_POLYGON)
        count = RENDER_MAX_POLYGON;
    for (int i = 0; i < count; i++)
        out[i] = source[i];
    return count;
}

int render_clip_segment(clip_vertex *a, clip_vertex *b, int attribute_count)
{
    double t0 = 0, t1 = 1;
    for (int plane = 0; plane < 6; plane++) {
        double da = plane_distance(a->c, plane), db = plane_distance(b->c, plane);
        if (!(da >= 0) && !(db >= 0))
            return 0;
        if (da < 0) {
            double t = da / (da - db);
            if (t > t0)
                t0 = t;
        } else if (db < 0) {
            double t = da / (da - db);
            if (t < t1)
                t1 = t;
        }
    }
    if (!(t0 <= t1))
        return 0;
    clip_vertex start = *a, end = *b;
    if (t0 > 0)
        interpolate(a, b, t0, attribute_count, &start);
    if (t1 < 1)
        interpolate(a, b, t1, attribute_count, &end);
    *a = start;
    *b = end;
    return 1;
}
