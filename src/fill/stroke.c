/* Strokes turned into polygons.
 *
 * An open polyline becomes one closed contour: the offset of its left side
 * walking forward, the end cap, the left side of the reversed polyline (the
 * right side walking back) and the start cap.  A closed polyline becomes two
 * contours, one per side.  At a vertex the outer side gets the join (miter,
 * round or bevel); the inner side goes through the vertex itself, which
 * makes small loops that the non-zero rule fills as part of the stroke.
 * Dashes cut the polylines by arc length first. */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

typedef struct stroker {
    const cg_stroke_style *style;
    double half, tolerance;
    fill_polylines *out;
} stroker;

/* The direction from a to b.  Tiny differences are scaled up by a power of
 * two first (exactly), so that the length of a difference of a subnormal
 * size is computed to full precision.  (This guarded against NaN directions
 * before cg_vec2_normalize handled such lengths itself; it stays because
 * removing it would move some of these directions by their last bit.) */
static cg_vec2 unit(cg_vec2 a, cg_vec2 b)
{
    cg_vec2 d = cg_vec2_sub(b, a);
    if (fabs(d.x) < 0x1p-500 && fabs(d.y) < 0x1p-500)
        d = cg_vec2_scale(d, 0x1p600);
    return cg_vec2_normalize(d);
}

/* Left normal of direction u scaled to half the width. */
static cg_vec2 normal(const stroker *s, cg_vec2 u)
{
    return cg_vec2_make(-u.y * s->half, u.x * s->half);
}

static cg_status add(stroker *s, cg_vec2 p)
{
    return fill_polylines_add(s->out, p);
}

/* Points of a half-turn from v + n around v through v + u * half to v - n
 * (interior points only). */
static cg_status half_turn(stroker *s, cg_vec2 v, cg_vec2 n)
{
    double a0 = atan2(n.y, n.x);
    return fill_arc_points(s->out, v, s->half, a0, a0 - CG_PI, s->tolerance);
}

/* The left side at vertex v, arriving along u0 from a segment of length
 * len0 and leaving along u1 on one of length len1. */
static cg_status join(stroker *s, cg_vec2 v, cg_vec2 u0, cg_vec2 u1, double len0, double len1)
{
    cg_vec2 n0 = normal(s, u0), n1 = normal(s, u1);
    double cross = cg_vec2_cross(u0, u1), dot = cg_vec2_dot(u0, u1);
    if (cross > 0) { /* turning left: the left side is inside */
        /* Where the two offset lines cross, h tan(turn / 2) back from v
         * along both segments: the exact inner corner when both segments
         * are that long; otherwise go round through v itself. */
        double back = s->half * cross / (1 + dot);
        if (back <= len0 && back <= len1)
            return add(s, cg_vec2_add(v, cg_vec2_scale(cg_vec2_add(n0, n1), 1 / (1 + dot))));
        cg_status status = add(s, cg_vec2_add(v, n0));
        if (status == CG_OK)
            status = add(s, v);
        return status != CG_OK ? status : add(s, cg_vec2_add(v, n1));
    }
    cg_status status = add(s, cg_vec2_add(v, n0));
    if (status != CG_OK)
        return status;
    if (cross == 0 && dot > 0)
        return CG_OK; /* straight on */
    switch (s->style->join) {
    case CG_JOIN_MITER:
        /* miter length / width = 1 / cos(turn / 2) */
        if (dot > -1 && 1 / sqrt((1 + dot) / 2) <= s->style->miter_limit) {
            cg_vec2 m = cg_vec2_add(v, cg_vec2_scale(cg_vec2_add(n0, n1), 1 / (1 + dot)));
            status = add(s, m);
        }
        break;
    case CG_JOIN_ROUND: {
        double a0 = atan2(n0.y, n0.x), turn = acos(dot < -1 ? -1 : (dot > 1 ? 1 : dot));
        status = fill_arc_points(s->out, v, s->half, a0, a0 - turn, s->tolerance);
        break;
    }
    default: break;
    }
    return status != CG_OK ? status : add(s, cg_vec2_add(v, n1));
}

/* Cap at p reached along u: from p + n to p - n. */
static cg_status cap(stroker *s, cg_vec2 p, cg_vec2 u)
{
    cg_vec2 n = normal(s, u), forward = cg_vec2_scale(u, s->half);
    switch (s->style->cap) {
    case CG_CAP_SQUARE: {
        cg_status status = add(s, cg_vec2_add(cg_vec2_add(p, n), forward));
        return status != CG_OK ? status : add(s, cg_vec2_add(cg_vec2_sub(p, n), forward));
    }
    case CG_CAP_ROUND: return half_turn(s, p, n);
    default: return CG_OK;
    }
}

/* One side of an open polyline of m >= 2 distinct consecutive points, walked
 * forward (step 1) or backward (step -1). */
static cg_status side(stroker *s, const cg_vec2 *p, size_t m, int backward)
{
#define AT(i) (backward ? p[m - 1 - (i)] : p[(i)])
    cg_status status = add(s, cg_vec2_add(AT(0), normal(s, unit(AT(0), AT(1)))));
    for (size_t i = 1; status == CG_OK && i + 1 < m; i++)
        status = join(s, AT(i), unit(AT(i - 1), AT(i)), unit(AT(i), AT(i + 1)),
                      cg_vec2_length(cg_vec2_sub(AT(i), AT(i - 1))),
                      cg_vec2_length(cg_vec2_sub(AT(i + 1), AT(i))));
    if (status == CG_OK)
        status = add(s, cg_vec2_add(AT(m - 1), normal(s, unit(AT(m - 2), AT(m - 1)))));
    if (status == CG_OK)
        status = cap(s, AT(m - 1), unit(AT(m - 2), AT(m - 1)));
    return status;
#undef AT
}

static cg_status stroke_dot(stroker *s, cg_vec2 p)
{
    cg_status status = CG_OK;
    if (s->style->cap == CG_CAP_BUTT)
        return CG_OK;
    status = fill_polylines_begin(s->out);
    if (status != CG_OK)
        return status;
    if (s->style->cap == CG_CAP_ROUND) {
        status = add(s, cg_vec2_make(p.x + s->half, p.y));
        if (status == CG_OK)
            status = fill_arc_points(s->out, p, s->half, 0, 2 * CG_PI, s->tolerance);
    } else {
        double h = s->half;
        cg_vec2 corners[4] = {{p.x - h, p.y - h},
                              {p.x + h, p.y - h},
                              {p.x + h, p.y + h},
                              {p.x - h, p.y + h}};
        for (int i = 0; status == CG_OK && i < 4; i++)
            status = add(s, corners[i]);
    }
    fill_polylines_close(s->out);
    return status;
}

static cg_status stroke_open(stroker *s, const cg_vec2 *p, size_t m)
{
    if (m == 1)
        return stroke_dot(s, p[0]);
    cg_status status = fill_polylines_begin(s->out);
    if (status == CG_OK)
        status = side(s, p, m, 0);
    if (status == CG_OK)
        status = side(s, p, m, 1);
    fill_polylines_close(s->out);
    return status;
}

static cg_status stroke_closed(stroker *s, const cg_vec2 *p, size_t m)
{
    for (int backward = 0; backward < 2; backward++) {
        cg_status status = fill_polylines_begin(s->out);
        for (size_t k = 0; status == CG_OK && k < m; k++) {
            size_t i = backward ? m - 1 - k : k;
            size_t prev = backward ? (i + 1) % m : (i + m - 1) % m;
            size_t next = backward ? (i + m - 1) % m : (i + 1) % m;
            status = join(s, p[i], unit(p[prev], p[i]), unit(p[i], p[next]),
                          cg_vec2_length(cg_vec2_sub(p[i], p[prev])),
                          cg_vec2_length(cg_vec2_sub(p[next], p[i])));
        }
        fill_polylines_close(s->out);
        if (status != CG_OK)
            return status;
    }
    return CG_OK;
}

/* Cuts the polyline p[0..m) (closed: with the segment back to p[0]) into
 * dashes, appended to dashes as open polylines. */
static cg_status cut_dashes(const cg_stroke_style *style, const cg_vec2 *p, size_t m, int closed,
                            double cap_points, fill_polylines *dashes)
{
    double pattern[64];
    int count = style->dash_count;
    double period = 0;
    for (int i = 0; i < count; i++)
        period += style->dashes[i];
    for (int i = 0; i < 2 * count && i < 64; i++)
        pattern[i] = style->dashes[i % count];
    if (count % 2)
        count *= 2;
    if (count > 64)
        count = 64;
    period = 0;
    for (int i = 0; i < count; i++)
        period += pattern[i];
    /* Bounded work and memory: refuse patterns so fine for the path's length
     * that it would need over 400,000 dashes, or whose dashes' round caps
     * (cap_points points each dash) would need over 4,000,000 points. */
    double length = 0;
    size_t segments = closed ? m : m - 1;
    for (size_t i = 0; i < segments; i++)
        length += cg_vec2_length(cg_vec2_sub(p[(i + 1) % m], p[i]));
    double needed = length / period * (count / 2);
    if (needed > 4e5 || needed * cap_points > 4e6)
        return CG_ERANGE;
    double phase = fmod(style->dash_offset, period);
    if (phase < 0)
        phase += period;
    int index = 0;
    while (phase >= pattern[index]) {
        phase -= pattern[index];
        index = (index + 1) % count;
    }
    double left = pattern[index] - phase; /* of the current pattern entry */
    int on = index % 2 == 0;
    size_t first_dash = dashes->line_count;
    int starts_on = on;
    cg_status status = CG_OK;
    if (on) {
        status = fill_polylines_begin(dashes);
        if (status == CG_OK)
            status = fill_polylines_add(dashes, p[0]);
    }
    for (size_t i = 0; status == CG_OK && i < segments; i++) {
        cg_vec2 a = p[i], b = p[(i + 1) % m];
        double len = cg_vec2_length(cg_vec2_sub(b, a)), done = 0;
        while (status == CG_OK && len - done > left) {
            done += left;
            cg_vec2 q = cg_vec2_add(a, cg_vec2_scale(cg_vec2_sub(b, a), done / len));
            if (on)
                status = fill_polylines_add(dashes, q);
            else if ((status = fill_polylines_begin(dashes)) == CG_OK)
                status = fill_polylines_add(dashes, q);
            on = !on;
            index = (index + 1) % count;
            left = pattern[index];
        }
        left -= len - done;
        if (on && status == CG_OK)
            status = fill_polylines_add(dashes, b);
    }
    if (status != CG_OK)
        return status;
    /* A closed path that is dashed on at both its start and its end: the
     * last dash continues into the first. */
    if (closed && on && starts_on && dashes->line_count - first_dash >= 2) {
        const fill_polyline *head = &dashes->lines[first_dash];
        for (size_t k = 1; status == CG_OK && k < head->count; k++)
            status = fill_polylines_add(dashes, dashes->points[head->start + k]);
        dashes->lines[first_dash].count = 0; /* merged into the last */
    }
    return status;
}

/* Copies polyline l without consecutive duplicates (and without a closing
 * duplicate of the first point) into buffer; returns the count. */
static cg_status distinct_points(const fill_polylines *in, const fill_polyline *l,
                                 fill_polylines *buffer, size_t *m)
{
    fill_polylines_reset(buffer);
    cg_status status = fill_polylines_begin(buffer);
    const cg_vec2 *p = in->points + l->start;
    for (size_t i = 0; status == CG_OK && i < l->count; i++) {
        size_t n = buffer->point_count;
        if (n && buffer->points[n - 1].x == p[i].x && buffer->points[n - 1].y == p[i].y)
            continue;
        status = fill_polylines_add(buffer, p[i]);
    }
    size_t n = buffer->point_count;
    if (l->closed && n > 1 && buffer->points[0].x == buffer->points[n - 1].x
        && buffer->points[0].y == buffer->points[n - 1].y)
        n--;
    *m = n;
    return status;
}

static cg_status check_style(const cg_stroke_style *style)
{
    if (!(style->width > 0) || !(style->width <= CG_FILL_MAX_COORD))
        return CG_EINVAL;
    if (style->join < CG_JOIN_MITER || style->join > CG_JOIN_BEVEL || style->cap < CG_CAP_BUTT
        || style->cap > CG_CAP_SQUARE)
        return CG_EINVAL;
    if (!(style->miter_limit >= 1) || !isfinite(style->miter_limit))
        return CG_EINVAL;
    if (style->dash_count < 0 || style->dash_count > 32 || (style->dash_count && !style->dashes)
        || !isfinite(style->dash_offset))
        return CG_EINVAL;
    for (int i = 0; i < style->dash_count; i++)
        if (!(style->dashes[i] >= 0) || !isfinite(style->dashes[i]))
            return CG_EINVAL;
    return CG_OK;
}

cg_stroke_style cg_stroke_style_default(void)
{
    cg_stroke_style s;
    memset(&s, 0, sizeof s);
    s.width = 1;
    s.join = CG_JOIN_MITER;
    s.cap = CG_CAP_BUTT;
    s.miter_limit = 4;
    return s;
}

cg_status fill_stroke_polylines(const fill_polylines *in, const cg_stroke_style *style,
                                double tolerance, fill_polylines *out)
{
    fill_polylines_reset(out);
    cg_status status = check_style(style);
    if (status != CG_OK)
        return status;
    double period = 0;
    for (int i = 0; i < style->dash_count; i++)
        period += style->dashes[i];
    int dashed = style->dash_count > 0 && period > 0;
    stroker s = {style, style->width / 2, tolerance, out};
    /* the points of a dash's two round caps */
    double cap_points = style->cap == CG_CAP_ROUND
                            ? 2.0 * (double)fill_arc_steps(s.half, CG_PI, tolerance)
                            : 0;
    fill_polylines buffer = {0}, dashes = {0};
    for (size_t i = 0; status == CG_OK && i < in->line_count; i++) {
        const fill_polyline *l = &in->lines[i];
        if (l->count < 2)
            continue; /* a bare move draws nothing */
        size_t m;
        status = distinct_points(in, l, &buffer, &m);
        if (status != CG_OK)
            break;
        const cg_vec2 *p = buffer.points;
        if (m == 1) {
            status = stroke_dot(&s, p[0]);
        } else if (dashed) {
            fill_polylines_reset(&dashes);
            status = cut_dashes(style, p, m, l->closed, cap_points, &dashes);
            for (size_t d = 0; status == CG_OK && d < dashes.line_count; d++) {
                if (dashes.lines[d].count == 0)
                    continue;
                size_t dm;
                fill_polylines one = {0};
                status = distinct_points(&dashes, &dashes.lines[d], &one, &dm);
                if (status == CG_OK && dm > 0)
                    status = stroke_open(&s, one.points, dm);
                fill_polylines_free(&one);
            }
        } else if (l->closed) {
            status = stroke_closed(&s, p, m);
        } else {
            status = stroke_open(&s, p, m);
        }
    }
    fill_polylines_free(&buffer);
    fill_polylines_free(&dashes);
    return status;
}
