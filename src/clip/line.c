/* Line clipping (11.1): Cohen-Sutherland with the notes' TBRL region codes
 * and Liang-Barsky, in 2D against a window and in 3D against a box. */
#include "cg/clip.h"

#include <math.h>

static int rect_valid(cg_rect w)
{
    return isfinite(w.xmin) && isfinite(w.ymin) && isfinite(w.xmax) && isfinite(w.ymax) &&
           w.xmin <= w.xmax && w.ymin <= w.ymax;
}

static int box_valid(cg_box3 b)
{
    return isfinite(b.lo.x) && isfinite(b.lo.y) && isfinite(b.lo.z) && isfinite(b.hi.x) &&
           isfinite(b.hi.y) && isfinite(b.hi.z) && b.lo.x <= b.hi.x && b.lo.y <= b.hi.y &&
           b.lo.z <= b.hi.z;
}

static int vec2_finite(cg_vec2 p) { return isfinite(p.x) && isfinite(p.y); }
static int vec3_finite(cg_vec3 p) { return isfinite(p.x) && isfinite(p.y) && isfinite(p.z); }

/* Note: Fig. 11.3 of the notes sets RIGHT whenever x >= xmin and TOP whenever
 * y >= ymin (a missing "else if (x > xmax)"); the codes of Fig. 11.1 need the
 * comparison with xmax and ymax, which is what is done here. */
unsigned cg_clip_rcode(cg_rect w, cg_vec2 p)
{
    unsigned code = CG_RCODE_INSIDE;
    if (p.x < w.xmin)
        code |= CG_RCODE_LEFT;
    else if (p.x > w.xmax)
        code |= CG_RCODE_RIGHT;
    if (p.y < w.ymin)
        code |= CG_RCODE_BOTTOM;
    else if (p.y > w.ymax)
        code |= CG_RCODE_TOP;
    return code;
}

unsigned cg_clip_rcode3(cg_box3 b, cg_vec3 p)
{
    unsigned code = cg_clip_rcode((cg_rect){b.lo.x, b.lo.y, b.hi.x, b.hi.y}, cg_vec2_make(p.x, p.y));
    if (p.z < b.lo.z)
        code |= CG_RCODE_NEAR;
    else if (p.z > b.hi.z)
        code |= CG_RCODE_FAR;
    return code;
}

/* At most two clips per endpoint are needed in exact arithmetic; the bound
 * only guards against rounding ping-pong at a corner. */
#define CS_MAX_STEPS 16

cg_status cg_clip_line_cohen_sutherland(cg_rect w, cg_vec2 *p0, cg_vec2 *p1, int *accepted,
                                        cg_clip_trace_fn trace, void *user)
{
    if (!p0 || !p1 || !accepted)
        return CG_EINVAL;
    *accepted = 0;
    if (!rect_valid(w) || !vec2_finite(*p0) || !vec2_finite(*p1))
        return CG_EINVAL;
    cg_vec2 a = *p0, b = *p1;
    unsigned c0 = cg_clip_rcode(w, a), c1 = cg_clip_rcode(w, b);
    for (int step = 0; step < CS_MAX_STEPS; step++) {
        if (!(c0 | c1)) {
            if (trace)
                trace(user, a, c0, b, c1, "trivial accept");
            *p0 = a;
            *p1 = b;
            *accepted = 1;
            return CG_OK;
        }
        if (c0 & c1) {
            if (trace)
                trace(user, a, c0, b, c1, "trivial reject");
            return CG_OK;
        }
        /* The outpoint: an endpoint with a non-zero rCode.  The bit tested
         * guarantees the denominator is non-zero: the other endpoint is not on
         * that side (or the AND above would be non-zero). */
        unsigned out = c0 ? c0 : c1;
        double x, y;
        const char *what;
        if (out & CG_RCODE_TOP) {
            x = a.x + (b.x - a.x) * (w.ymax - a.y) / (b.y - a.y);
            y = w.ymax;
            what = "clip top";
        } else if (out & CG_RCODE_BOTTOM) {
            x = a.x + (b.x - a.x) * (w.ymin - a.y) / (b.y - a.y);
            y = w.ymin;
            what = "clip bottom";
        } else if (out & CG_RCODE_RIGHT) {
            y = a.y + (b.y - a.y) * (w.xmax - a.x) / (b.x - a.x);
            x = w.xmax;
            what = "clip right";
        } else {
            y = a.y + (b.y - a.y) * (w.xmin - a.x) / (b.x - a.x);
            x = w.xmin;
            what = "clip left";
        }
        if (trace)
            trace(user, a, c0, b, c1, what);
        if (out == c0) {
            a = cg_vec2_make(x, y);
            c0 = cg_clip_rcode(w, a);
        } else {
            b = cg_vec2_make(x, y);
            c1 = cg_clip_rcode(w, b);
        }
    }
    /* Rounding kept an endpoint a hair outside a corner: the segment only
     * grazes the corner; report it as not visible. */
    if (trace)
        trace(user, a, c0, b, c1, "reject (rounding at a corner)");
    return CG_OK;
}

/* One Liang-Barsky boundary test: p t <= q for the visible part. */
static int lb_edge(double p, double q, double *t0, double *t1)
{
    if (p == 0)
        return q >= 0; /* parallel: visible iff on the inner side */
    double r = q / p;
    if (p < 0) {
        if (r > *t1)
            return 0;
        if (r > *t0)
            *t0 = r;
    } else {
        if (r < *t0)
            return 0;
        if (r < *t1)
            *t1 = r;
    }
    return 1;
}

cg_status cg_clip_line_liang_barsky(cg_rect w, cg_vec2 *p0, cg_vec2 *p1, int *accepted)
{
    if (!p0 || !p1 || !accepted)
        return CG_EINVAL;
    *accepted = 0;
    if (!rect_valid(w) || !vec2_finite(*p0) || !vec2_finite(*p1))
        return CG_EINVAL;
    cg_vec2 a = *p0, b = *p1;
    double dx = b.x - a.x, dy = b.y - a.y, t0 = 0, t1 = 1;
    if (!lb_edge(-dx, a.x - w.xmin, &t0, &t1) || !lb_edge(dx, w.xmax - a.x, &t0, &t1) ||
        !lb_edge(-dy, a.y - w.ymin, &t0, &t1) || !lb_edge(dy, w.ymax - a.y, &t0, &t1))
        return CG_OK;
    if (t1 < 1)
        *p1 = cg_vec2_make(a.x + t1 * dx, a.y + t1 * dy);
    if (t0 > 0)
        *p0 = cg_vec2_make(a.x + t0 * dx, a.y + t0 * dy);
    /* The parametric points can round a hair outside the window. */
    p0->x = fmin(fmax(p0->x, w.xmin), w.xmax);
    p0->y = fmin(fmax(p0->y, w.ymin), w.ymax);
    p1->x = fmin(fmax(p1->x, w.xmin), w.xmax);
    p1->y = fmin(fmax(p1->y, w.ymin), w.ymax);
    *accepted = 1;
    return CG_OK;
}

static double vget(cg_vec3 v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }

cg_status cg_clip_line_cohen_sutherland3(cg_box3 box, cg_vec3 *p0, cg_vec3 *p1, int *accepted)
{
    if (!p0 || !p1 || !accepted)
        return CG_EINVAL;
    *accepted = 0;
    if (!box_valid(box) || !vec3_finite(*p0) || !vec3_finite(*p1))
        return CG_EINVAL;
    cg_vec3 a = *p0, b = *p1;
    unsigned c0 = cg_clip_rcode3(box, a), c1 = cg_clip_rcode3(box, b);
    /* bit order tested: top, bottom, right, left, far, near */
    static const unsigned bits[6] = {CG_RCODE_TOP, CG_RCODE_BOTTOM, CG_RCODE_RIGHT,
                                     CG_RCODE_LEFT, CG_RCODE_FAR,   CG_RCODE_NEAR};
    static const int axes[6] = {1, 1, 0, 0, 2, 2};
    static const int high[6] = {1, 0, 1, 0, 1, 0};
    for (int step = 0; step < CS_MAX_STEPS; step++) {
        if (!(c0 | c1)) {
            *p0 = a;
            *p1 = b;
            *accepted = 1;
            return CG_OK;
        }
        if (c0 & c1)
            return CG_OK;
        unsigned out = c0 ? c0 : c1;
        int k = 0;
        while (!(out & bits[k]))
            k++;
        int axis = axes[k];
        double plane = vget(high[k] ? box.hi : box.lo, axis);
        double t = (plane - vget(a, axis)) / (vget(b, axis) - vget(a, axis));
        cg_vec3 p = cg_vec3_add(a, cg_vec3_scale(cg_vec3_sub(b, a), t));
        if (axis == 0)
            p.x = plane;
        else if (axis == 1)
            p.y = plane;
        else
            p.z = plane;
        if (out == c0) {
            a = p;
            c0 = cg_clip_rcode3(box, a);
        } else {
            b = p;
            c1 = cg_clip_rcode3(box, b);
        }
    }
    return CG_OK;
}

cg_status cg_clip_line_liang_barsky3(cg_box3 box, cg_vec3 *p0, cg_vec3 *p1, int *accepted)
{
    if (!p0 || !p1 || !accepted)
        return CG_EINVAL;
    *accepted = 0;
    if (!box_valid(box) || !vec3_finite(*p0) || !vec3_finite(*p1))
        return CG_EINVAL;
    cg_vec3 a = *p0, b = *p1, d = cg_vec3_sub(b, a);
    double t0 = 0, t1 = 1;
    if (!lb_edge(-d.x, a.x - box.lo.x, &t0, &t1) || !lb_edge(d.x, box.hi.x - a.x, &t0, &t1) ||
        !lb_edge(-d.y, a.y - box.lo.y, &t0, &t1) || !lb_edge(d.y, box.hi.y - a.y, &t0, &t1) ||
        !lb_edge(-d.z, a.z - box.lo.z, &t0, &t1) || !lb_edge(d.z, box.hi.z - a.z, &t0, &t1))
        return CG_OK;
    if (t1 < 1)
        *p1 = cg_vec3_add(a, cg_vec3_scale(d, t1));
    if (t0 > 0)
        *p0 = cg_vec3_add(a, cg_vec3_scale(d, t0));
    cg_vec3 *ps[2] = {p0, p1};
    for (int i = 0; i < 2; i++) {
        ps[i]->x = fmin(fmax(ps[i]->x, box.lo.x), box.hi.x);
        ps[i]->y = fmin(fmax(ps[i]->y, box.lo.y), box.hi.y);
        ps[i]->z = fmin(fmax(ps[i]->z, box.lo.z), box.hi.z);
    }
    *accepted = 1;
    return CG_OK;
}
