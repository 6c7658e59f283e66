/* Paths: move, line, quadratic and cubic Bezier, arcs, close; flattening to
 * polylines.  Beziers are flattened by the curve module; arcs (circular and
 * SVG elliptical) are flattened here by stepping the angle so that the
 * chord of each step stays within the tolerance of the ellipse. */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

#include "cg/curve.h"

enum { VERB_MOVE, VERB_LINE, VERB_QUAD, VERB_CUBIC, VERB_ARC, VERB_CLOSE };

/* Doubles stored per verb after the verb itself. */
static const int verb_coords[] = {2, 2, 4, 6, 9, 0};

struct cg_path {
    unsigned char *verbs;
    size_t verb_count, verb_capacity;
    double *coords;
    size_t coord_count, coord_capacity;
    cg_vec2 current, start;
    int has_current; /* a current point exists (after any segment or move) */
    int after_close; /* the next segment must start a new subpath at start */
    size_t drawing;  /* verbs other than moves */
};

/* ---- polyline sets ---------------------------------------------------------- */

void fill_polylines_reset(fill_polylines *set)
{
    set->point_count = 0;
    set->line_count = 0;
}

void fill_polylines_free(fill_polylines *set)
{
    free(set->points);
    free(set->lines);
    memset(set, 0, sizeof *set);
}

cg_status fill_polylines_begin(fill_polylines *set)
{
    if (core_array_reserve((void **)&set->lines, &set->line_capacity, set->line_count + 1,
                           sizeof *set->lines)
        != CG_OK)
        return CG_ENOMEM;
    fill_polyline l = {set->point_count, 0, 0};
    set->lines[set->line_count++] = l;
    return CG_OK;
}

cg_status fill_polylines_add(fill_polylines *set, cg_vec2 p)
{
    if (core_array_reserve((void **)&set->points, &set->point_capacity, set->point_count + 1,
                           sizeof *set->points)
        != CG_OK)
        return CG_ENOMEM;
    set->points[set->point_count++] = p;
    set->lines[set->line_count - 1].count++;
    return CG_OK;
}

void fill_polylines_close(fill_polylines *set)
{
    if (set->line_count)
        set->lines[set->line_count - 1].closed = 1;
}

/* ---- building paths ------------------------------------------------------------ */

cg_status cg_path_create(cg_path **out)
{
    if (!out)
        return CG_EINVAL;
    *out = calloc(1, sizeof **out);
    return *out ? CG_OK : CG_ENOMEM;
}

void cg_path_free(cg_path *path)
{
    if (!path)
        return;
    free(path->verbs);
    free(path->coords);
    free(path);
}

void cg_path_reset(cg_path *path)
{
    if (!path)
        return;
    path->verb_count = path->coord_count = 0;
    path->has_current = path->after_close = 0;
    path->drawing = 0;
    path->current = path->start = cg_vec2_make(0, 0);
}

int cg_path_is_empty(const cg_path *path)
{
    return !path || path->drawing == 0;
}

static int valid_coord(double v)
{
    return fabs(v) <= CG_FILL_MAX_COORD; /* false for NaN */
}

static cg_status append(cg_path *path, int verb, const double *coords)
{
    int n = verb_coords[verb];
    if (core_array_reserve((void **)&path->verbs, &path->verb_capacity, path->verb_count + 1, 1)
            != CG_OK
        || core_array_reserve((void **)&path->coords, &path->coord_capacity,
                              path->coord_count + (size_t)n, sizeof *path->coords)
               != CG_OK)
        return CG_ENOMEM;
    path->verbs[path->verb_count++] = (unsigned char)verb;
    if (n)
        memcpy(path->coords + path->coord_count, coords, (size_t)n * sizeof *coords);
    path->coord_count += (size_t)n;
    if (verb != VERB_MOVE)
        path->drawing++;
    return CG_OK;
}

cg_status cg_path_move_to(cg_path *path, double x, double y)
{
    if (!path || !valid_coord(x) || !valid_coord(y))
        return CG_EINVAL;
    double c[2] = {x, y};
    cg_status status = append(path, VERB_MOVE, c);
    if (status != CG_OK)
        return status;
    path->current = path->start = cg_vec2_make(x, y);
    path->has_current = 1;
    path->after_close = 0;
    return CG_OK;
}

/* Before a drawing segment: a move to the current point (or the origin) when
 * no subpath is open. */
static cg_status ensure_subpath(cg_path *path)
{
    if (path->has_current && !path->after_close)
        return CG_OK;
    cg_vec2 p = path->has_current ? path->start : cg_vec2_make(0, 0);
    return cg_path_move_to(path, p.x, p.y);
}

static cg_status segment(cg_path *path, int verb, const double *coords)
{
    for (int i = 0; i < verb_coords[verb]; i++)
        if (!valid_coord(coords[i]))
            return CG_EINVAL;
    cg_status status = ensure_subpath(path);
    if (status != CG_OK)
        return status;
    status = append(path, verb, coords);
    if (status != CG_OK)
        return status;
    int n = verb_coords[verb];
    path->current = cg_vec2_make(coords[n - 2], coords[n - 1]);
    return CG_OK;
}

cg_status cg_path_line_to(cg_path *path, double x, double y)
{
    if (!path)
        return CG_EINVAL;
    double c[2] = {x, y};
    return segment(path, VERB_LINE, c);
}

cg_status cg_path_quad_to(cg_path *path, double x1, double y1, double x, double y)
{
    if (!path)
        return CG_EINVAL;
    double c[4] = {x1, y1, x, y};
    return segment(path, VERB_QUAD, c);
}

cg_status cg_path_cubic_to(cg_path *path, double x1, double y1, double x2, double y2, double x,
                           double y)
{
    if (!path)
        return CG_EINVAL;
    double c[6] = {x1, y1, x2, y2, x, y};
    return segment(path, VERB_CUBIC, c);
}

cg_status cg_path_close(cg_path *path)
{
    if (!path)
        return CG_EINVAL;
    if (!path->has_current || path->after_close)
        return CG_OK;
    cg_status status = append(path, VERB_CLOSE, NULL);
    if (status != CG_OK)
        return status;
    path->current = path->start;
    path->after_close = 1;
    return CG_OK;
}

/* An arc of the ellipse centred at (cx, cy) with radii rx, ry rotated by phi,
 * from parameter angle theta0 through dtheta, ending exactly at end. */
static cg_status add_arc(cg_path *path, double cx, double cy, double rx, double ry, double phi,
                         double theta0, double dtheta, cg_vec2 end)
{
    double c[9] = {cx, cy, rx, ry, phi, theta0, dtheta, end.x, end.y};
    for (int i = 0; i < 9; i++)
        if (!isfinite(c[i]))
            return CG_EINVAL;
    return segment(path, VERB_ARC, c);
}

cg_status cg_path_arc(cg_path *path, double cx, double cy, double r, double a0, double a1)
{
    if (!path || !valid_coord(cx) || !valid_coord(cy) || !(r >= 0) || !valid_coord(r)
        || !isfinite(a0) || !isfinite(a1))
        return CG_EINVAL;
    double sweep = a1 - a0;
    if (sweep > 2 * CG_PI)
        sweep = 2 * CG_PI;
    if (sweep < -2 * CG_PI)
        sweep = -2 * CG_PI;
    cg_vec2 from = cg_vec2_make(cx + r * cos(a0), cy + r * sin(a0));
    cg_vec2 to = cg_vec2_make(cx + r * cos(a0 + sweep), cy + r * sin(a0 + sweep));
    if (!valid_coord(from.x) || !valid_coord(from.y) || !valid_coord(to.x) || !valid_coord(to.y))
        return CG_EINVAL;
    cg_status status = path->has_current && !path->after_close
                           ? cg_path_line_to(path, from.x, from.y)
                           : cg_path_move_to(path, from.x, from.y);
    if (status != CG_OK || r == 0 || sweep == 0)
        return status;
    return add_arc(path, cx, cy, r, r, 0, a0, sweep, to);
}

static double vector_angle(double ux, double uy, double vx, double vy)
{
    return atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

cg_status cg_path_svg_arc_to(cg_path *path, double rx, double ry, double rotation_degrees,
                             int large_arc, int sweep, double x, double y)
{
    if (!path || !isfinite(rx) || !isfinite(ry) || !isfinite(rotation_degrees) || !valid_coord(x)
        || !valid_coord(y))
        return CG_EINVAL;
    cg_vec2 p1 = path->has_current ? path->current : cg_vec2_make(0, 0);
    if (p1.x == x && p1.y == y)
        return CG_OK; /* SVG: the arc is omitted */
    rx = fabs(rx);
    ry = fabs(ry);
    if (rx == 0 || ry == 0)
        return cg_path_line_to(path, x, y);
    /* SVG implementation notes, F.6.5: endpoint to centre parameterization. */
    double phi = cg_radians(fmod(rotation_degrees, 360.0)), cp = cos(phi), sp = sin(phi);
    double hx = (p1.x - x) / 2, hy = (p1.y - y) / 2;
    double x1 = cp * hx + sp * hy, y1 = -sp * hx + cp * hy;
    double lambda = (x1 * x1) / (rx * rx) + (y1 * y1) / (ry * ry);
    if (lambda > 1) {
        double s = sqrt(lambda);
        rx *= s;
        ry *= s;
    }
    double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
    double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    double coef = den > 0 && num > 0 ? sqrt(num / den) : 0;
    if ((large_arc != 0) == (sweep != 0))
        coef = -coef;
    double ccx = coef * rx * y1 / ry, ccy = -coef * ry * x1 / rx;
    double cx = cp * ccx - sp * ccy + (p1.x + x) / 2, cy = sp * ccx + cp * ccy + (p1.y + y) / 2;
    double ux = (x1 - ccx) / rx, uy = (y1 - ccy) / ry, vx = (-x1 - ccx) / rx, vy = (-y1 - ccy) / ry;
    double theta0 = vector_angle(1, 0, ux, uy), dtheta = vector_angle(ux, uy, vx, vy);
    if (!sweep && dtheta > 0)
        dtheta -= 2 * CG_PI;
    else if (sweep && dtheta < 0)
        dtheta += 2 * CG_PI;
    if (!valid_coord(cx) || !valid_coord(cy) || !valid_coord(rx) || !valid_coord(ry))
        return CG_EINVAL;
    return add_arc(path, cx, cy, rx, ry, phi, theta0, dtheta, cg_vec2_make(x, y));
}

/* ---- flattening ------------------------------------------------------------------ */

/* Number of chords for an arc of radius r through |sweep| radians so that
 * each chord's sagitta r (1 - cos(step / 2)) stays within tolerance. */
long fill_arc_steps(double r, double sweep, double tolerance)
{
    double step = tolerance < r ? 2 * acos(1 - tolerance / r) : CG_PI / 2;
    if (step > CG_PI / 2)
        step = CG_PI / 2;
    double n = ceil(fabs(sweep) / step);
    if (!(n >= 1))
        n = 1;
    if (n > 100000)
        n = 100000;
    return (long)n;
}

/* ---- culling what cannot be seen ----------------------------------------------- */

/* Whether every point lies beyond one side of the box. */
static int outside(const cg_vec2 *p, int n, const fill_clip *box)
{
    int left = 1, right = 1, above = 1, below = 1;
    for (int i = 0; i < n; i++) {
        left &= p[i].x < box->x0;
        right &= p[i].x > box->x1;
        above &= p[i].y < box->y0;
        below &= p[i].y > box->y1;
    }
    return left || right || above || below;
}

static double extent(const cg_vec2 *p, int n)
{
    double x0 = p[0].x, x1 = p[0].x, y0 = p[0].y, y1 = p[0].y;
    for (int i = 1; i < n; i++) {
        x0 = fmin(x0, p[i].x);
        x1 = fmax(x1, p[i].x);
        y0 = fmin(y0, p[i].y);
        y1 = fmax(y1, p[i].y);
    }
    return fmax(x1 - x0, y1 - y0);
}

static cg_vec2 ellipse_at(const double *a, double t)
{
    double ex = a[2] * cos(t), ey = a[3] * sin(t), cp = cos(a[4]), sp = sin(a[4]);
    return cg_vec2_make(a[0] + cp * ex - sp * ey, a[1] + sp * ex + cp * ey);
}

/* Points of the ellipse arc a (centre, radii, rotation) from parameter t0
 * through dt, ending with end.  Pieces entirely outside the box (the chord's
 * bounds grown by the sagitta) become their end point: the loop between
 * piece and chord lies outside the box, so no visible pixel's winding
 * changes.  Pieces much larger than the box are halved first. */
static cg_status ellipse_piece(fill_polylines *set, const double *a, double t0, double dt,
                               cg_vec2 end, double tolerance, const fill_clip *box, int depth)
{
    double r = fmax(a[2], a[3]);
    if (box) {
        cg_vec2 ends[2] = {ellipse_at(a, t0), end};
        double h = fabs(dt) < CG_PI ? r * (1 - cos(dt / 2)) + 1e-9 * r : 2 * r;
        fill_clip grown = {box->x0 - h, box->y0 - h, box->x1 + h, box->y1 + h};
        if (outside(ends, 2, &grown))
            return fill_polylines_add(set, end);
        double size = fmax(box->x1 - box->x0, box->y1 - box->y0);
        if (depth < 64 && r * fabs(dt) > 4 * size + 64) {
            double half = dt / 2;
            cg_status status = ellipse_piece(set, a, t0, half, ellipse_at(a, t0 + half), tolerance,
                                             box, depth + 1);
            return status != CG_OK ? status
                                   : ellipse_piece(set, a, t0 + half, dt - half, end, tolerance,
                                                   box, depth + 1);
        }
    }
    long n = fill_arc_steps(r, dt, tolerance);
    for (long i = 1; i < n; i++) {
        cg_status status = fill_polylines_add(set, ellipse_at(a, t0 + dt * (double)i / (double)n));
        if (status != CG_OK)
            return status;
    }
    return fill_polylines_add(set, end);
}

static cg_status sink_point(void *user, cg_vec2 point)
{
    return fill_polylines_add(user, point);
}

/* Uniform flattening with the segment count known in advance: the piece of
 * a degree-n curve over a parameter step 1/m has second differences at most
 * M / m^2 (M: the largest second difference of the control points), so its
 * control polygon, and the curve, lie within n^2 M / (8 m^2) of its chord
 * (the bound cg_bezier_flatten also uses).  m = ceil(n sqrt(M / (8 tol)))
 * keeps every chord within the tolerance; the points are evaluated in the
 * power basis.  Cheaper per point than adaptive subdivision, and for the
 * small curves of text about as many points.  Returns 0 (nothing added)
 * when m would exceed max_segments: the caller then flattens adaptively. */
static int uniform_bezier(fill_polylines *set, const cg_vec2 *c, int count, double tolerance,
                          long max_segments, cg_status *status)
{
    double second = 0;
    for (int i = 0; i + 2 < count; i++) {
        double dx = c[i + 2].x - 2 * c[i + 1].x + c[i].x, dy = c[i + 2].y - 2 * c[i + 1].y + c[i].y;
        second = fmax(second, sqrt(dx * dx + dy * dy));
    }
    double degree = count - 1, steps = ceil(degree * sqrt(second / (8 * tolerance)));
    if (!(steps <= (double)max_segments))
        return 0;
    long m = steps < 1 ? 1 : (long)steps;
    /* P(t) = ((a t + b) t + d) t + c[0] (a = 0 for quadratics) */
    cg_vec2 a = {0, 0}, b, d;
    if (count == 4) {
        a.x = c[3].x - 3 * c[2].x + 3 * c[1].x - c[0].x;
        a.y = c[3].y - 3 * c[2].y + 3 * c[1].y - c[0].y;
        b.x = 3 * (c[2].x - 2 * c[1].x + c[0].x);
        b.y = 3 * (c[2].y - 2 * c[1].y + c[0].y);
        d.x = 3 * (c[1].x - c[0].x);
        d.y = 3 * (c[1].y - c[0].y);
    } else {
        b.x = c[2].x - 2 * c[1].x + c[0].x;
        b.y = c[2].y - 2 * c[1].y + c[0].y;
        d.x = 2 * (c[1].x - c[0].x);
        d.y = 2 * (c[1].y - c[0].y);
    }
    *status = CG_OK;
    for (long i = 1; i < m && *status == CG_OK; i++) {
        double t = (double)i / (double)m;
        cg_vec2 p = {((a.x * t + b.x) * t + d.x) * t + c[0].x,
                     ((a.y * t + b.y) * t + d.y) * t + c[0].y};
        *status = fill_polylines_add(set, p);
    }
    if (*status == CG_OK)
        *status = fill_polylines_add(set, c[count - 1]); /* the end point exactly */
    return 1;
}

/* The same for Bezier curves: pieces whose control points all lie beyond
 * one side of the box become their end point (the curve and its chord lie
 * in the control points' hull); pieces much larger than the box are split
 * in two (de Casteljau) before being flattened by the curve module. */
static cg_status bezier_piece(fill_polylines *set, const cg_vec2 *c, int n, double tolerance,
                              const fill_clip *box, int depth)
{
    if (box) {
        if (outside(c, n, box))
            return fill_polylines_add(set, c[n - 1]);
        double size = fmax(box->x1 - box->x0, box->y1 - box->y0);
        if (depth < 64 && extent(c, n) > 4 * size + 64) {
            cg_vec2 left[4], right[4];
            cg_status status = cg_bezier_split(c, n, 0.5, left, right);
            if (status == CG_OK)
                status = bezier_piece(set, left, n, tolerance, box, depth + 1);
            return status != CG_OK ? status
                                   : bezier_piece(set, right, n, tolerance, box, depth + 1);
        }
    }
    cg_status status;
    if ((n == 3 || n == 4) && uniform_bezier(set, c, n, tolerance, 4096, &status))
        return status;
    return cg_bezier_flatten(c, n, tolerance, sink_point, set);
}

cg_status fill_arc_points(fill_polylines *set, cg_vec2 c, double r, double a0, double a1,
                          double tolerance)
{
    long n = fill_arc_steps(r, a1 - a0, tolerance);
    for (long i = 1; i < n; i++) {
        double t = a0 + (a1 - a0) * (double)i / (double)n;
        cg_status status = fill_polylines_add(set,
                                              cg_vec2_make(c.x + r * cos(t), c.y + r * sin(t)));
        if (status != CG_OK)
            return status;
    }
    return CG_OK;
}

cg_status fill_path_flatten(const cg_path *path, double tolerance, const fill_clip *box,
                            fill_polylines *out)
{
    fill_polylines_reset(out);
    const double *c = path->coords;
    cg_vec2 current = cg_vec2_make(0, 0);
    for (size_t i = 0; i < path->verb_count; i++) {
        int verb = path->verbs[i];
        cg_status status = CG_OK;
        switch (verb) {
        case VERB_MOVE:
            status = fill_polylines_begin(out);
            if (status == CG_OK)
                status = fill_polylines_add(out, cg_vec2_make(c[0], c[1]));
            break;
        case VERB_LINE: status = fill_polylines_add(out, cg_vec2_make(c[0], c[1])); break;
        case VERB_QUAD:
        case VERB_CUBIC: {
            /* a quad has four coordinates: read c[4], c[5] for cubics only */
            cg_vec2 control[4] = {current, {c[0], c[1]}, {c[2], c[3]}, {0, 0}};
            if (verb == VERB_CUBIC)
                control[3] = cg_vec2_make(c[4], c[5]);
            status = bezier_piece(out, control, verb == VERB_QUAD ? 3 : 4, tolerance, box, 0);
            break;
        }
        case VERB_ARC:
            status = ellipse_piece(out, c, c[5], c[6], cg_vec2_make(c[7], c[8]), tolerance, box, 0);
            break;
        case VERB_CLOSE: {
            fill_polyline *l = &out->lines[out->line_count - 1];
            if (l->count == 1) /* "M x y Z": a zero-length subpath */
                status = fill_polylines_add(out, out->points[l->start]);
            fill_polylines_close(out);
            break;
        }
        }
        if (status != CG_OK)
            return status;
        int n = verb_coords[verb];
        if (n)
            current = cg_vec2_make(c[n - 2], c[n - 1]);
        c += n;
    }
    return CG_OK;
}

/* ---- drawing paths --------------------------------------------------------------- */

cg_status cg_rasterizer_fill_path(cg_rasterizer *r, cg_image *image, const cg_path *path,
                                  cg_fill_rule rule, const cg_paint *paint)
{
    if (!r || !image || !image->data || !path || !paint)
        return CG_EINVAL;
    /* curves wholly outside the image (and a pixel around it) are culled */
    fill_clip box = {-1, -1, image->width + 1.0, image->height + 1.0};
    cg_status status = fill_path_flatten(path, r->tolerance, &box, &r->flat);
    if (status != CG_OK)
        return status;
    fill_aa_begin(r, image);
    status = fill_aa_add_polylines(r, &r->flat);
    if (status != CG_OK)
        return status;
    return fill_aa_render(r, image, rule, paint);
}

cg_status cg_rasterizer_stroke_path(cg_rasterizer *r, cg_image *image, const cg_path *path,
                                    const cg_stroke_style *style, const cg_paint *paint)
{
    if (!r || !image || !image->data || !path || !paint || !style)
        return CG_EINVAL;
    /* Curves farther from the image than the stroke reaches are culled;
     * not under dashes, whose phase follows the true length. */
    double reach = fabs(style->width) / 2 * fmax(style->miter_limit, 1.5) + 1;
    fill_clip box = {-reach, -reach, image->width + reach, image->height + reach};
    int culled = style->dash_count == 0 && isfinite(reach);
    cg_status status = fill_path_flatten(path, r->tolerance, culled ? &box : NULL, &r->flat);
    if (status == CG_OK)
        status = fill_stroke_polylines(&r->flat, style, r->tolerance, &r->outline);
    if (status != CG_OK)
        return status;
    fill_aa_begin(r, image);
    status = fill_aa_add_polylines(r, &r->outline);
    if (status != CG_OK)
        return status;
    return fill_aa_render(r, image, CG_FILL_NONZERO, paint);
}

cg_status cg_fill_path(cg_image *image, const cg_path *path, cg_fill_rule rule,
                       const cg_paint *paint)
{
    cg_rasterizer *r;
    cg_status status = cg_rasterizer_create(&r);
    if (status != CG_OK)
        return status;
    status = cg_rasterizer_fill_path(r, image, path, rule, paint);
    cg_rasterizer_free(r);
    return status;
}

cg_status cg_stroke_path(cg_image *image, const cg_path *path, const cg_stroke_style *style,
                         const cg_paint *paint)
{
    cg_rasterizer *r;
    cg_status status = cg_rasterizer_create(&r);
    if (status != CG_OK)
        return status;
    status = cg_rasterizer_stroke_path(r, image, path, style, paint);
    cg_rasterizer_free(r);
    return status;
}

cg_status cg_stroke_to_path(const cg_path *path, const cg_stroke_style *style, double tolerance,
                            cg_path *out)
{
    if (!path || !style || !out || !(tolerance >= 0.001 && tolerance <= 100))
        return CG_EINVAL;
    fill_polylines flat = {0}, outline = {0};
    cg_status status = fill_path_flatten(path, tolerance, NULL, &flat);
    if (status == CG_OK)
        status = fill_stroke_polylines(&flat, style, tolerance, &outline);
    for (size_t i = 0; status == CG_OK && i < outline.line_count; i++) {
        const fill_polyline *l = &outline.lines[i];
        for (size_t k = 0; status == CG_OK && k < l->count; k++) {
            cg_vec2 p = outline.points[l->start + k];
            status = k ? cg_path_line_to(out, p.x, p.y) : cg_path_move_to(out, p.x, p.y);
        }
        if (status == CG_OK)
            status = cg_path_close(out);
    }
    fill_polylines_free(&flat);
    fill_polylines_free(&outline);
    return status;
}

/* ---- transforming and measuring -------------------------------------------------- */

static cg_vec2 affine_point(const cg_mat3 *m, double x, double y)
{
    return cg_vec2_make(m->m[0][0] * x + m->m[0][1] * y + m->m[0][2],
                        m->m[1][0] * x + m->m[1][1] * y + m->m[1][2]);
}

/* The arc a (centre, radii, rotation, start, sweep, end) as cubic pieces of
 * at most 45 degrees: each piece from E(t0) to E(t1) with control points
 * along the tangents at k = 4/3 tan((t1 - t0) / 4) of the derivative. */
static cg_status arc_as_cubics(const double *a, const cg_mat3 *m, cg_path *out)
{
    double sweep = a[6];
    int pieces = (int)ceil(fabs(sweep) / (CG_PI / 4));
    if (pieces < 1)
        pieces = 1;
    double step = sweep / pieces, k = 4.0 / 3.0 * tan(step / 4);
    double cp = cos(a[4]), sp = sin(a[4]);
    for (int i = 0; i < pieces; i++) {
        double t0 = a[5] + step * i, t1 = t0 + step;
        double e0x = a[2] * cos(t0), e0y = a[3] * sin(t0), e1x = a[2] * cos(t1),
               e1y = a[3] * sin(t1);
        double d0x = -a[2] * sin(t0), d0y = a[3] * cos(t0), d1x = -a[2] * sin(t1),
               d1y = a[3] * cos(t1);
        double p1x = e0x + k * d0x, p1y = e0y + k * d0y, p2x = e1x - k * d1x, p2y = e1y - k * d1y;
        cg_vec2 c1 = affine_point(m, a[0] + cp * p1x - sp * p1y, a[1] + sp * p1x + cp * p1y);
        cg_vec2 c2 = affine_point(m, a[0] + cp * p2x - sp * p2y, a[1] + sp * p2x + cp * p2y);
        cg_vec2 end = i == pieces - 1
                          ? affine_point(m, a[7], a[8])
                          : affine_point(m, a[0] + cp * e1x - sp * e1y, a[1] + sp * e1x + cp * e1y);
        cg_status status = cg_path_cubic_to(out, c1.x, c1.y, c2.x, c2.y, end.x, end.y);
        if (status != CG_OK)
            return status;
    }
    return CG_OK;
}

cg_status cg_path_transform(const cg_path *path, cg_mat3 matrix, cg_path *out)
{
    if (!path || !out || path == out || matrix.m[2][0] != 0 || matrix.m[2][1] != 0
        || matrix.m[2][2] != 1)
        return CG_EINVAL;
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(matrix.m[i][k]))
                return CG_EINVAL;
    fill_path_mark mark;
    fill_path_save(out, &mark);
    const double *c = path->coords;
    cg_status status = CG_OK;
    for (size_t i = 0; i < path->verb_count && status == CG_OK; i++) {
        int verb = path->verbs[i];
        cg_vec2 p[3];
        for (int k = 0; k < 3 && verb != VERB_ARC && 2 * k < verb_coords[verb]; k++)
            p[k] = affine_point(&matrix, c[2 * k], c[2 * k + 1]);
        switch (verb) {
        case VERB_MOVE: status = cg_path_move_to(out, p[0].x, p[0].y); break;
        case VERB_LINE: status = cg_path_line_to(out, p[0].x, p[0].y); break;
        case VERB_QUAD: status = cg_path_quad_to(out, p[0].x, p[0].y, p[1].x, p[1].y); break;
        case VERB_CUBIC:
            status = cg_path_cubic_to(out, p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y);
            break;
        case VERB_ARC: status = arc_as_cubics(c, &matrix, out); break;
        default: status = cg_path_close(out); break;
        }
        c += verb_coords[verb];
    }
    if (status != CG_OK)
        fill_path_restore(out, &mark);
    return status;
}

cg_status cg_path_bounds(const cg_path *path, double tolerance, cg_vec2 *min, cg_vec2 *max)
{
    if (!path || !min || !max || !(tolerance >= 0.001) || path->verb_count == 0)
        return CG_EINVAL;
    fill_polylines flat = {0};
    cg_status status = fill_path_flatten(path, tolerance, NULL, &flat);
    if (status == CG_OK && flat.point_count == 0)
        status = CG_EINVAL;
    if (status == CG_OK) {
        *min = *max = flat.points[0];
        for (size_t i = 1; i < flat.point_count; i++) {
            cg_vec2 p = flat.points[i];
            min->x = fmin(min->x, p.x);
            min->y = fmin(min->y, p.y);
            max->x = fmax(max->x, p.x);
            max->y = fmax(max->y, p.y);
        }
    }
    fill_polylines_free(&flat);
    return status;
}

/* ---- for the SVG parser: saving and restoring a path's state ------------------ */

void fill_path_save(const cg_path *path, fill_path_mark *m)
{
    m->verb_count = path->verb_count;
    m->coord_count = path->coord_count;
    m->drawing = path->drawing;
    m->current = path->current;
    m->start = path->start;
    m->has_current = path->has_current;
    m->after_close = path->after_close;
}

void fill_path_restore(cg_path *path, const fill_path_mark *m)
{
    path->verb_count = m->verb_count;
    path->coord_count = m->coord_count;
    path->drawing = m->drawing;
    path->current = m->current;
    path->start = m->start;
    path->has_current = m->has_current;
    path->after_close = m->after_close;
}

cg_vec2 fill_path_current(const cg_path *path)
{
    return path->has_current ? path->current : cg_vec2_make(0, 0);
}

cg_vec2 fill_path_start(const cg_path *path)
{
    return path->has_current ? path->start : cg_vec2_make(0, 0);
}
