/* Line clipping (11.1): Cohen-Sutherland with the notes' TBRL region codes
 * and Liang-Barsky, in 2D against a window and in 3D against a box. */
#include "cg/clip.h"
#include "line_exact.h"

#include <math.h>
#include <string.h>

static int rect_valid(cg_rect w)
{
    return isfinite(w.xmin) && isfinite(w.ymin) && isfinite(w.xmax) && isfinite(w.ymax)
           && w.xmin <= w.xmax && w.ymin <= w.ymax;
}

static int box_valid(cg_box3 b)
{
    return isfinite(b.lo.x) && isfinite(b.lo.y) && isfinite(b.lo.z) && isfinite(b.hi.x)
           && isfinite(b.hi.y) && isfinite(b.hi.z) && b.lo.x <= b.hi.x && b.lo.y <= b.hi.y
           && b.lo.z <= b.hi.z;
}

static int vec2_finite(cg_vec2 p)
{
    return isfinite(p.x) && isfinite(p.y);
}
static int vec3_finite(cg_vec3 p)
{
    return isfinite(p.x) && isfinite(p.y) && isfinite(p.z);
}

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
    unsigned code = cg_clip_rcode((cg_rect){b.lo.x, b.lo.y, b.hi.x, b.hi.y},
                                  cg_vec2_make(p.x, p.y));
    if (p.z < b.lo.z)
        code |= CG_RCODE_NEAR;
    else if (p.z > b.hi.z)
        code |= CG_RCODE_FAR;
    return code;
}

/* The clippers below decide and compute exactly (line_exact.c): every
 * decision is the one of exact arithmetic and every new coordinate is the
 * exact one rounded to the nearest double, whatever the magnitudes (a
 * segment from -1.7e308 to 1.7e308 included, whose b - a overflows in
 * doubles).  An endpoint is moved to a window bound along the *original*
 * segment, so clipping again never adds to the error of the first clip. */

/* the bits of the rCode in the order Cohen-Sutherland tests them, with the
 * axis and the bound (1: the high one) of each */
static const unsigned cs_bits[6] = {CG_RCODE_TOP,  CG_RCODE_BOTTOM, CG_RCODE_RIGHT,
                                    CG_RCODE_LEFT, CG_RCODE_FAR,    CG_RCODE_NEAR};
static const int cs_axis[6] = {1, 1, 0, 0, 2, 2};
static const int cs_high[6] = {1, 0, 1, 0, 1, 0};

/* the rCode of the point at t, exactly */
static unsigned exact_code(const line_seg *s, const line_param *t, const double *lo,
                           const double *hi)
{
    unsigned code = 0;
    for (int k = 0; k < 2 * s->dim; k++) {
        int axis = cs_axis[k];
        int side = line_side(s, t, axis, cs_high[k] ? hi[axis] : lo[axis]);
        if (cs_high[k] ? side > 0 : side < 0)
            code |= cs_bits[k];
    }
    return code;
}

/* At most two clips per endpoint in 2D (three in 3D): the bound guards the
 * loop all the same. */
#define CS_MAX_STEPS 16

/* One step of Cohen-Sutherland told to trace (when given): the two
 * endpoints p with their region codes c, and what is done. */
static inline void cs_trace(cg_clip_trace_fn trace, void *user, double p[2][3], const unsigned c[2],
                            const char *what)
{
    if (trace)
        trace(user, cg_vec2_make(p[0][0], p[0][1]), c[0], cg_vec2_make(p[1][0], p[1][1]), c[1],
              what);
}

/* Cohen-Sutherland in dim 2 or 3 on a, b (in: the segment, out: its visible
 * part); trace only in 2D.  Returns whether a part is visible. */
static int cs_clip(int dim, double *a, double *b, const double *lo, const double *hi,
                   cg_clip_trace_fn trace, void *user)
{
    line_seg s;
    line_seg_init(&s, dim, a, b, lo, hi);
    line_param t[2];
    line_param_end(&t[0], 0);
    line_param_end(&t[1], 1);
    double p[2][3];
    memcpy(p[0], a, (size_t)dim * sizeof *a);
    memcpy(p[1], b, (size_t)dim * sizeof *b);
    unsigned c[2] = {exact_code(&s, &t[0], lo, hi), exact_code(&s, &t[1], lo, hi)};
    for (int step = 0; step < CS_MAX_STEPS; step++) {
        if (!(c[0] | c[1])) {
            cs_trace(trace, user, p, c, "trivial accept");
            memcpy(a, p[0], (size_t)dim * sizeof *a);
            memcpy(b, p[1], (size_t)dim * sizeof *b);
            return 1;
        }
        if (c[0] & c[1]) {
            cs_trace(trace, user, p, c, "trivial reject");
            return 0;
        }
        /* The outpoint: an endpoint with a non-zero rCode.  The bit tested
         * guarantees that b - a is not 0 on its axis: the other endpoint is
         * not on that side (or the AND above would be non-zero). */
        int e = c[0] ? 0 : 1, k = 0;
        while (!(c[e] & cs_bits[k]))
            k++;
        static const char *const what[6] = {"clip top",  "clip bottom", "clip right",
                                            "clip left", "clip far",    "clip near"};
        cs_trace(trace, user, p, c, what[k]);
        int axis = cs_axis[k];
        line_param_bound(&s, axis, cs_high[k] ? hi[axis] : lo[axis], &t[e]);
        for (int j = 0; j < dim; j++)
            p[e][j] = line_coord(&s, &t[e], j);
        c[e] = exact_code(&s, &t[e], lo, hi);
    }
    return 0;
}

/* Liang-Barsky in dim 2 or 3, as cs_clip: for each axis the parameters
 * where the segment enters and leaves the slab between the two bounds; the
 * visible part runs from the last entry (or 0) to the first exit (or 1). */
static int lb_clip(int dim, double *a, double *b, const double *lo, const double *hi)
{
    line_seg s;
    line_seg_init(&s, dim, a, b, lo, hi);
    line_param t0, t1, u;
    line_param_end(&t0, 0);
    line_param_end(&t1, 1);
    for (int j = 0; j < dim; j++) {
        int dir = (b[j] > a[j]) - (b[j] < a[j]);
        if (dir == 0) {
            if (a[j] < lo[j] || a[j] > hi[j])
                return 0; /* parallel, outside */
            continue;
        }
        line_param_bound(&s, j, dir > 0 ? lo[j] : hi[j], &u);
        if (line_param_cmp(&s, &u, &t0) > 0)
            line_param_copy(&t0, &u);
        line_param_bound(&s, j, dir > 0 ? hi[j] : lo[j], &u);
        if (line_param_cmp(&s, &u, &t1) < 0)
            line_param_copy(&t1, &u);
    }
    if (line_param_cmp(&s, &t0, &t1) > 0)
        return 0;
    for (int j = 0; j < dim; j++) {
        double x0 = line_coord(&s, &t0, j), x1 = line_coord(&s, &t1, j);
        a[j] = x0;
        b[j] = x1;
    }
    return 1;
}

/* Both ends inside: the segment itself (exact, and the common case). */
static int inside_all(int dim, const double *a, const double *b, const double *lo, const double *hi)
{
    for (int j = 0; j < dim; j++)
        if (a[j] < lo[j] || a[j] > hi[j] || b[j] < lo[j] || b[j] > hi[j])
            return 0;
    return 1;
}

/* The segment a-b clipped in dim dimensions by Liang-Barsky or by
 * Cohen-Sutherland (traced when trace is given; a traced segment goes through
 * the algorithm even when both ends are inside): 1 when a part remains, then
 * in a and b. */
static int clip_segment(int liang_barsky, int dim, double *a, double *b, const double *lo,
                        const double *hi, cg_clip_trace_fn trace, void *user)
{
    if (!trace && inside_all(dim, a, b, lo, hi))
        return 1;
    return liang_barsky ? lb_clip(dim, a, b, lo, hi) : cs_clip(dim, a, b, lo, hi, trace, user);
}

/* The four public entry points: their checks, then clip_segment. */
static cg_status clip_line2(int liang_barsky, cg_rect w, cg_vec2 *p0, cg_vec2 *p1, int *accepted,
                            cg_clip_trace_fn trace, void *user)
{
    if (!p0 || !p1 || !accepted)
        return CG_EINVAL;
    *accepted = 0;
    if (!rect_valid(w) || !vec2_finite(*p0) || !vec2_finite(*p1))
        return CG_EINVAL;
    double a[2] = {p0->x, p0->y}, b[2] = {p1->x, p1->y};
    double lo[2] = {w.xmin, w.ymin}, hi[2] = {w.xmax, w.ymax};
    if (clip_segment(liang_barsky, 2, a, b, lo, hi, trace, user)) {
        *p0 = cg_vec2_make(a[0], a[1]);
        *p1 = cg_vec2_make(b[0], b[1]);
        *accepted = 1;
    }
    return CG_OK;
}

static cg_status clip_line3(int liang_barsky, cg_box3 box, cg_vec3 *p0, cg_vec3 *p1, int *accepted)
{
    if (!p0 || !p1 || !accepted)
        return CG_EINVAL;
    *accepted = 0;
    if (!box_valid(box) || !vec3_finite(*p0) || !vec3_finite(*p1))
        return CG_EINVAL;
    double a[3] = {p0->x, p0->y, p0->z}, b[3] = {p1->x, p1->y, p1->z};
    double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
    if (clip_segment(liang_barsky, 3, a, b, lo, hi, NULL, NULL)) {
        *p0 = cg_vec3_make(a[0], a[1], a[2]);
        *p1 = cg_vec3_make(b[0], b[1], b[2]);
        *accepted = 1;
    }
    return CG_OK;
}

cg_status cg_clip_line_cohen_sutherland(cg_rect w, cg_vec2 *p0, cg_vec2 *p1, int *accepted,
                                        cg_clip_trace_fn trace, void *user)
{
    return clip_line2(0, w, p0, p1, accepted, trace, user);
}

cg_status cg_clip_line_liang_barsky(cg_rect w, cg_vec2 *p0, cg_vec2 *p1, int *accepted)
{
    return clip_line2(1, w, p0, p1, accepted, NULL, NULL);
}

cg_status cg_clip_line_cohen_sutherland3(cg_box3 box, cg_vec3 *p0, cg_vec3 *p1, int *accepted)
{
    return clip_line3(0, box, p0, p1, accepted);
}

cg_status cg_clip_line_liang_barsky3(cg_box3 box, cg_vec3 *p0, cg_vec3 *p1, int *accepted)
{
    return clip_line3(1, box, p0, p1, accepted);
}
