/* Offsetting polygons and polylines on the int64 grid.
 *
 * The offset region is built from pieces the boolean engine unites, so that
 * it is exact to the pieces and valid whatever the input:
 *
 *   - the band: for every edge a-b of the (simple) boundary, the rectangle
 *     of width d = |delta| beside it on the side that counts, and at every
 *     vertex whose turn leaves a gap between two consecutive rectangles on
 *     that side, the join that fills it;
 *
 *              gap (join)
 *             +--+                           a +nr*d          b +nr*d
 *            /    \                           +----------------+
 *     ------+  p   +                          |a      edge     |b
 *     edge 1 \    / edge 2                    +----------------+
 *                                             a -nr*d          b -nr*d
 *
 *   - inflating (delta > 0) is the polygons united with the band on their
 *     outer side (the right of every ring: outer rings run counter-clockwise,
 *     holes clockwise): every point outside within d of the polygons lies in
 *     the rectangle of its nearest edge or, when the nearest point is a
 *     vertex, in that vertex's join (the normal cone there is exactly the
 *     gap);
 *   - deflating (delta < 0) is the polygons less the band on their inner
 *     side (the same argument from inside);
 *   - an open path is its band on both sides alone, with a cap at each end.
 *
 * The rectangles and joins of a run of edges are given to the engine united
 * already, as one polygon (see "chains" below).  A join is only built on
 * the side that counts: a miter reaches up to
 * miter_limit * d from its vertex, farther than the offset, and one built
 * on the other side (say inside a hole's sharp corner) could cross the
 * polygon and come out beyond it. */
#include "internal.h"
#include "polygon_internal.h"

#include "../core/array.h"

#include <math.h>

typedef struct direction {
    double x, y;
} direction;

/* What one offset builds its band with. */
enum { BAND_RIGHT = 1, BAND_LEFT = 2 };

typedef struct offset_band {
    double width; /* d = |delta| on the grid */
    int sides;    /* the sides of the paths that count: BAND_RIGHT, BAND_LEFT */
    cg_offset_join join;
    double miter_limit; /* >= 1 */
    double arc_step;    /* angle of one chord of a round join */
    cg_polygon_set64 *rings;
    CORE_ARRAY(cg_point64) piece; /* the ring being built */
} offset_band;

static cg_point64 moved(cg_point64 p, direction v, double distance)
{
    return (cg_point64){(int64_t)llround((double)p.x + v.x * distance),
                        (int64_t)llround((double)p.y + v.y * distance)};
}

static direction unit(cg_point64 a, cg_point64 b)
{
    double x = (double)(b.x - a.x), y = (double)(b.y - a.y), length = hypot(x, y);
    return (direction){x / length, y / length};
}

static double distance(cg_point64 a, cg_point64 b)
{
    return hypot((double)(b.x - a.x), (double)(b.y - a.y));
}

static direction right_normal(direction t)
{
    return (direction){t.y, -t.x};
}

static cg_status piece_push(offset_band *band, cg_point64 p)
{
    return core_array_push(&band->piece, p);
}

/* Adds the piece as a counter-clockwise ring (reversed when clockwise;
 * dropped when rounding left it without area). */
static cg_status piece_close(offset_band *band)
{
    cg_point64 *p = band->piece.data;
    size_t n = band->piece.count;
    band->piece.count = 0;
    polygon_i128 area = polygon_ring_twice_area(p, n);
    if (area == 0)
        return CG_OK;
    if (area < 0)
        for (size_t i = 0, j = n - 1; i < j; i++, j--) {
            cg_point64 t = p[i];
            p[i] = p[j];
            p[j] = t;
        }
    return cg_polygon_set64_add_ring(band->rings, p, n, 1);
}

/* The corner points of a join cut flat, perpendicular to the bisector b, at
 * `reach` from the vertex p: on each offset edge (p + m*d, along the edge
 * towards b) the point whose distance along b is reach.  phi is the angle
 * between m1 and b. */
static cg_status add_flat_cut(offset_band *band, cg_point64 p, direction m1, direction m2,
                              direction b, double phi, double reach)
{
    /* At phi = 0 (a turn too small for the doubles) the cut passes through
     * p + m*d itself: along is 0 there, and u1, u2 have no direction. */
    double d = band->width, sin_phi = sin(phi);
    double along = sin_phi > 1e-12 ? (reach - d * cos(phi)) / sin_phi : 0;
    direction u1 = {b.x - m1.x * cos(phi), b.y - m1.y * cos(phi)};
    direction u2 = {b.x - m2.x * cos(phi), b.y - m2.y * cos(phi)};
    double l1 = hypot(u1.x, u1.y), l2 = hypot(u2.x, u2.y);
    double k1 = l1 > 0 ? along / l1 : 0, k2 = l2 > 0 ? along / l2 : 0;
    cg_point64 q1 = {(int64_t)llround((double)p.x + m1.x * d + u1.x * k1),
                     (int64_t)llround((double)p.y + m1.y * d + u1.y * k1)};
    cg_point64 q2 = {(int64_t)llround((double)p.x + m2.x * d + u2.x * k2),
                     (int64_t)llround((double)p.y + m2.y * d + u2.y * k2)};
    cg_status st = piece_push(band, q1);
    return st == CG_OK ? piece_push(band, q2) : st;
}

/* The outline of a join on the gap's side at p: p + m1*d, the join's own
 * points, p + m2*d (m1, m2 the normals there, b their bisector, phi the
 * angle between m1 and b; side +1 when m1 turns counter-clockwise to m2). */
static cg_status push_join_points(offset_band *band, cg_point64 p, direction m1, direction m2,
                                  direction b, double phi, double side)
{
    double d = band->width, cos_phi = cos(phi);
    cg_status st = piece_push(band, moved(p, m1, d));
    if (st != CG_OK)
        return st;
    switch (band->join) {
    case CG_OFFSET_JOIN_BEVEL: break;
    case CG_OFFSET_JOIN_SQUARE: st = add_flat_cut(band, p, m1, m2, b, phi, d); break;
    case CG_OFFSET_JOIN_MITER:
        if (cos_phi * band->miter_limit >= 1)
            st = piece_push(band, moved(p, b, d / cos_phi));
        else
            st = add_flat_cut(band, p, m1, m2, b, phi, d * band->miter_limit);
        break;
    case CG_OFFSET_JOIN_ROUND: {
        int steps = (int)ceil(2 * phi / band->arc_step);
        for (int k = 1; k < steps && st == CG_OK; k++) {
            double angle = side * 2 * phi * k / steps, c = cos(angle), s = sin(angle);
            direction v = {m1.x * c - m1.y * s, m1.x * s + m1.y * c};
            st = piece_push(band, moved(p, v, d));
        }
        break;
    }
    }
    return st == CG_OK ? piece_push(band, moved(p, m2, d)) : st;
}

/* The join at vertex p between an edge arriving along t1 and one leaving
 * along t2 (turn: the exact sign of the turn, 0 when straight on or back):
 * the ring p, p + m1*d, (the join's own points), p + m2*d, where m1 and m2
 * are the normals on the gap's side, when that side counts; and when the
 * other side counts, the triangle p, p - m1*d, p - m2*d there, which the
 * two rectangles overlap exactly (when the edges are long enough) but which
 * rounding their corners could leave uncovered by a sliver. */
static cg_status add_join(offset_band *band, cg_point64 p, direction t1, direction t2, int turn,
                          double shorter_edge)
{
    double cross = t1.x * t2.y - t1.y * t2.x, dot = t1.x * t2.x + t1.y * t2.y;
    double d = band->width;
    if (turn == 0 && dot > 0)
        return CG_OK; /* straight on: the two rectangles share their ends */
    /* a left turn leaves its gap on the right; a full reversal on both
     * sides, filled as one join around the front (bisector t1) */
    int reversal = turn == 0 || fabs(cross) < 1e-12;
    double side = reversal || cross > 0 ? 1 : -1;
    direction n1 = right_normal(t1), n2 = right_normal(t2);
    direction m1 = {side * n1.x, side * n1.y}, m2 = {side * n2.x, side * n2.y};
    direction b = {m1.x + m2.x, m1.y + m2.y};
    double bl = hypot(b.x, b.y);
    if (reversal || bl < 1e-12)
        b = t1;
    else
        b = (direction){b.x / bl, b.y / bl};
    double phi = acos(fmin(1, fmax(-1, m1.x * b.x + m1.y * b.y)));
    int gap_counts = band->sides & (side > 0 ? BAND_RIGHT : BAND_LEFT);
    int overlap_counts = band->sides & (side > 0 ? BAND_LEFT : BAND_RIGHT);
    cg_status st = CG_OK;
    /* the triangle lies within both rectangles when it reaches no farther
     * along either edge than the shorter edge's length (sin of the turn * d) */
    if (overlap_counts && !reversal && fabs(cross) * d <= shorter_edge) {
        cg_point64 inner[3] = {p, moved(p, m1, -d), moved(p, m2, -d)};
        for (int i = 0; i < 3 && st == CG_OK; i++)
            st = piece_push(band, inner[i]);
        if (st == CG_OK)
            st = piece_close(band);
    }
    if (!gap_counts || st != CG_OK)
        return st;
    st = piece_push(band, p);
    if (st == CG_OK)
        st = push_join_points(band, p, m1, m2, b, phi, side);
    return st == CG_OK ? piece_close(band) : st;
}

/* ---- chains: the band of a run of edges as one polygon ---------------------- *
 *
 * The rectangles and joins of consecutive edges, on one side, unite into
 * the polygon between the run of edges and its offset: where the run turns
 * towards that side (a gap) the offset follows the join, where it turns
 * away the two offset edges meet at their crossing (the rectangles
 * overlap).  The engine then has one ring per run instead of two per
 * edge, with few crossings.  A run ends where this polygon might stop
 * being simple: after a quarter turn in all, at a reversal, or where the
 * crossing of two offset edges would lie beyond an edge's end (a turn
 * sharp for the edges' lengths); there it ends square, and the vertex
 * gets its join as a piece of its own.
 *
 *      offset:  q0 --------- x ---------- q2        (x: the crossing)
 *               |                          |
 *      run:     p0 -------- p1 ----------- p2       (p1 turns away)
 */

typedef struct chain {
    CORE_ARRAY(cg_point64) offset; /* the offset side, in the run's direction */
    size_t first;                  /* the run's first vertex */
    double turned;                 /* the turning so far */
    double used;                   /* length of the current edge taken by a crossing at its start */
} chain;

/* The run from vertex c->first to `last` (indices modulo n) closed by its
 * offset, as a ring of the band; a new run starts at `last`. */
static cg_status chain_close(offset_band *band, chain *c, const cg_point64 *p, size_t n,
                             size_t last, direction end_normal)
{
    cg_status st = core_array_push(&c->offset, moved(p[last % n], end_normal, band->width));
    for (size_t i = 0; i < c->offset.count && st == CG_OK; i++)
        st = piece_push(band, c->offset.data[i]);
    for (size_t k = last + 1; k-- > c->first && st == CG_OK;)
        st = piece_push(band, p[k % n]);
    if (st == CG_OK)
        st = piece_close(band);
    c->offset.count = 0;
    c->first = last;
    c->turned = 0;
    c->used = 0;
    return st;
}

/* The right side's band of the path p[0..n) (distinct consecutive points;
 * closed: the ring, which starts and ends its runs at vertex 0). */
static cg_status add_right_side(offset_band *band, const cg_point64 *p, size_t n, int closed)
{
    size_t edges = closed ? n : n - 1;
    chain c = {{0}, 0, 0, 0};
    direction t = unit(p[0], p[1 % n]);
    cg_status st = core_array_push(&c.offset, moved(p[0], right_normal(t), band->width));
    for (size_t k = 1; k <= edges && st == CG_OK; k++) {
        /* vertex k (p[k % n]) between edge k-1 (direction t) and edge k */
        direction n1 = right_normal(t);
        if (k == edges) {
            st = chain_close(band, &c, p, n, k, n1);
            if (st == CG_OK && closed)
                st = add_join(band, p[0], t, unit(p[0], p[1]), polygon_orient(p[n - 1], p[0], p[1]),
                              fmin(distance(p[n - 1], p[0]), distance(p[0], p[1])));
            break;
        }
        cg_point64 a = p[k - 1], v = p[k % n], b = p[(k + 1) % n];
        direction t2 = unit(v, b), n2 = right_normal(t2);
        int turn = polygon_orient(a, v, b);
        double cross = t.x * t2.y - t.y * t2.x, dot = t.x * t2.x + t.y * t2.y;
        double angle = fabs(atan2(cross, dot)), d = band->width;
        double before = distance(a, v) - c.used, after = distance(v, b);
        /* the crossing of the offset edges lies d tan(angle / 2) back along each */
        double reach = d * tan(angle / 2);
        int keep = c.turned + angle <= M_PI / 4 && !(turn == 0 && dot < 0);
        if (turn == 0 && dot > 0) {
            c.used = 0; /* straight on */
        } else if (turn > 0 && keep) {
            /* towards the right side's gap: the join's outline */
            direction b2 = {n1.x + n2.x, n1.y + n2.y};
            double bl = hypot(b2.x, b2.y);
            b2 = (direction){b2.x / bl, b2.y / bl};
            band->piece.count = 0;
            st = push_join_points(band, v, n1, n2, b2, angle / 2, 1);
            for (size_t i = 0; i < band->piece.count && st == CG_OK; i++)
                st = core_array_push(&c.offset, band->piece.data[i]);
            band->piece.count = 0;
            c.turned += angle;
            c.used = 0;
        } else if (turn < 0 && keep && reach <= before && reach <= after) {
            double scale = d / (1 + n1.x * n2.x + n1.y * n2.y);
            direction m = {n1.x + n2.x, n1.y + n2.y};
            st = core_array_push(&c.offset, moved(v, m, scale));
            c.turned += angle;
            c.used = reach;
        } else {
            st = chain_close(band, &c, p, n, k, n1);
            if (st == CG_OK)
                st = add_join(band, v, t, t2, turn, fmin(distance(a, v), after));
            if (st == CG_OK)
                st = core_array_push(&c.offset, moved(v, n2, d));
        }
        t = t2;
    }
    core_array_free(&c.offset);
    return st;
}

/* The band of path p[0..n) on the sides that count: the right side as it
 * is, the left side as the right side of the path reversed. */
static cg_status add_sides(offset_band *band, cg_point64 *p, size_t n, int closed)
{
    int sides = band->sides;
    cg_status st = CG_OK;
    band->sides = BAND_RIGHT;
    if (sides & BAND_RIGHT)
        st = add_right_side(band, p, n, closed);
    if (st == CG_OK && (sides & BAND_LEFT)) {
        for (size_t i = 0, j = n - 1; i < j; i++, j--) {
            cg_point64 swap = p[i];
            p[i] = p[j];
            p[j] = swap;
        }
        st = add_right_side(band, p, n, closed);
        for (size_t i = 0, j = n - 1; i < j; i++, j--) {
            cg_point64 swap = p[i];
            p[i] = p[j];
            p[j] = swap;
        }
    }
    band->sides = sides;
    return st;
}

/* The cap of an open path at its end p, reached along t. */
static cg_status add_cap(offset_band *band, cg_point64 p, direction t, cg_offset_end end)
{
    if (end == CG_OFFSET_END_BUTT)
        return CG_OK;
    cg_offset_join join = band->join;
    band->join = end == CG_OFFSET_END_ROUND ? CG_OFFSET_JOIN_ROUND : CG_OFFSET_JOIN_SQUARE;
    cg_status st = add_join(band, p, t, (direction){-t.x, -t.y}, 0, 0);
    band->join = join;
    return st;
}

/* The band of the open path p[0..n) (distinct consecutive points). */
static cg_status add_open(offset_band *band, cg_point64 *p, size_t n, cg_offset_end end)
{
    if (n == 1) {
        /* a lone point: two caps back to back (nothing for butt ends) */
        cg_status st = add_cap(band, p[0], (direction){1, 0}, end);
        return st == CG_OK ? add_cap(band, p[0], (direction){-1, 0}, end) : st;
    }
    cg_status st = add_sides(band, p, n, 0);
    direction first = unit(p[0], p[1]), last = unit(p[n - 2], p[n - 1]);
    if (st == CG_OK)
        st = add_cap(band, p[n - 1], last, end);
    if (st == CG_OK)
        st = add_cap(band, p[0], (direction){-first.x, -first.y}, end);
    return st;
}

/* The band of every ring of paths, with consecutive duplicates dropped. */
static cg_status build_band(offset_band *band, const cg_polygon_set64 *paths, cg_offset_end end)
{
    CORE_ARRAY(cg_point64) clean = {0};
    cg_status st = CG_OK;
    for (size_t r = 0; r < paths->ring_count && st == CG_OK; r++) {
        const cg_point64 *p = clip_ring_points(paths, r);
        size_t n = paths->ring_start[r + 1] - paths->ring_start[r];
        clean.count = 0;
        st = core_array_reserve_for(&clean, n);
        for (size_t i = 0; i < n && st == CG_OK; i++)
            if (clean.count == 0 || clean.data[clean.count - 1].x != p[i].x
                || clean.data[clean.count - 1].y != p[i].y)
                clean.data[clean.count++] = p[i];
        int closed = end == CG_OFFSET_END_POLYGON || end == CG_OFFSET_END_JOINED;
        while (closed && clean.count > 1 && clean.data[0].x == clean.data[clean.count - 1].x
               && clean.data[0].y == clean.data[clean.count - 1].y)
            clean.count--;
        if (st != CG_OK || clean.count == 0)
            continue;
        if (closed && clean.count >= 2)
            st = add_sides(band, clean.data, clean.count, 1);
        else if (closed) /* a joined lone point: a round or square dot */
            st = add_open(band, clean.data, 1,
                          band->join == CG_OFFSET_JOIN_ROUND ? CG_OFFSET_END_ROUND
                                                             : CG_OFFSET_END_SQUARE);
        else
            st = add_open(band, clean.data, clean.count, end);
    }
    core_array_free(&clean);
    return st;
}

cg_offset_options cg_offset_options_default(void)
{
    cg_offset_options o = {CG_OFFSET_JOIN_MITER, CG_OFFSET_END_POLYGON, 2, 0, CG_CLIP_EVEN_ODD};
    return o;
}

/* Checks the options and fills in their defaults for a width d on the grid. */
static cg_status check_options(const cg_offset_options *options, double d, offset_band *band)
{
    if ((unsigned)options->join > CG_OFFSET_JOIN_BEVEL
        || (unsigned)options->end > CG_OFFSET_END_ROUND
        || (unsigned)options->fill > CG_CLIP_NEGATIVE || !isfinite(options->miter_limit)
        || !isfinite(options->arc_tolerance) || options->arc_tolerance < 0
        || (options->miter_limit != 0 && options->miter_limit < 1))
        return CG_EINVAL;
    band->width = d;
    band->join = options->join;
    band->miter_limit = options->miter_limit == 0 ? 2 : options->miter_limit;
    double tolerance = options->arc_tolerance > 0 ? options->arc_tolerance : d / 500;
    /* a quarter of a grid unit at least, and at most some 700 chords a turn */
    tolerance = fmax(tolerance, fmax(0.25, d * 1e-5));
    band->arc_step = tolerance >= d ? M_PI / 2 : 2 * acos(1 - tolerance / d);
    if (band->arc_step > M_PI / 2)
        band->arc_step = M_PI / 2;
    return CG_OK;
}

cg_status cg_offset64_ws(cg_clip_workspace *ws, const cg_polygon_set64 *paths, double delta,
                         const cg_offset_options *options, cg_polygon_set64 *result)
{
    cg_offset_options defaults = cg_offset_options_default();
    if (!options)
        options = &defaults;
    if (!paths || !result || !isfinite(delta))
        return CG_EINVAL;
    int64_t largest;
    double d = fabs(delta);
    offset_band band = {0};
    cg_status st = check_options(options, d, &band);
    if (st == CG_OK)
        st = polygon_set64_max_abs(paths, &largest);
    if (st != CG_OK)
        return st;
    /* every point of the band lies within miter_limit * d (or d) of the input */
    double reach = d * fmax(band.miter_limit, 1.5);
    if ((double)largest + reach + 2 > (double)CG_CLIP_MAX_COORD)
        return CG_ERANGE;
    cg_polygon_set64 simple = {0}, rings = {0};
    band.rings = &rings;
    int polygons = options->end == CG_OFFSET_END_POLYGON;
    if (polygons) {
        /* the boundary of the region the fill rule gives, as simple rings */
        cg_polygon_set64 none = {0};
        st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, paths, options->fill, &none, options->fill,
                                  &simple);
    }
    band.sides = !polygons ? BAND_RIGHT | BAND_LEFT : delta > 0 ? BAND_RIGHT : BAND_LEFT;
    if (st == CG_OK && (d > 0 || !polygons))
        st = build_band(&band, polygons ? &simple : paths, options->end);
    core_array_free(&band.piece);
    if (st == CG_OK) {
        if (!polygons)
            st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, &rings, CG_CLIP_NON_ZERO, &simple,
                                      CG_CLIP_NON_ZERO, result);
        else if (delta > 0)
            st = cg_clip_boolean64_ws(ws, CG_CLIP_UNION, &simple, CG_CLIP_NON_ZERO, &rings,
                                      CG_CLIP_NON_ZERO, result);
        else
            st = cg_clip_boolean64_ws(ws, CG_CLIP_DIFFERENCE, &simple, CG_CLIP_NON_ZERO, &rings,
                                      CG_CLIP_NON_ZERO, result);
    }
    if (st == CG_OK)
        polygon_drop_slivers(result);
    cg_polygon_set64_clear(&simple);
    cg_polygon_set64_clear(&rings);
    return st;
}

cg_status cg_offset64(const cg_polygon_set64 *paths, double delta, const cg_offset_options *options,
                      cg_polygon_set64 *result)
{
    return cg_offset64_ws(NULL, paths, delta, options, result);
}

cg_status cg_offset_ws(cg_clip_workspace *ws, const cg_polygon_set *paths, double delta,
                       const cg_offset_options *options, double scale, cg_polygon_set *result)
{
    cg_offset_options grid_options = options ? *options : cg_offset_options_default();
    if (!paths || !result || !isfinite(delta) || !isfinite(grid_options.arc_tolerance))
        return CG_EINVAL;
    double largest = polygon_max_abs(paths);
    double limit = grid_options.miter_limit > 1 ? grid_options.miter_limit : 2;
    polygon_grid grid;
    cg_status st = polygon_grid_pick(scale, largest + fabs(delta) * limit, &grid);
    if (st != CG_OK)
        return st;
    grid_options.arc_tolerance = polygon_grid_to(grid, grid_options.arc_tolerance);
    cg_polygon_set64 in = {0}, out = {0};
    st = polygon_set_to_grid(paths, grid, &in);
    if (st == CG_OK)
        st = cg_offset64_ws(ws, &in, polygon_grid_to(grid, delta), &grid_options, &out);
    if (st == CG_OK)
        st = polygon_set_from_grid(&out, grid, result);
    cg_polygon_set64_clear(&in);
    cg_polygon_set64_clear(&out);
    return st;
}

cg_status cg_offset(const cg_polygon_set *paths, double delta, const cg_offset_options *options,
                    double scale, cg_polygon_set *result)
{
    return cg_offset_ws(NULL, paths, delta, options, scale, result);
}
