/* The painter's algorithm (section 5.2) in Newell, Newell and Sancha's form:
 * polygons sorted by their farthest depth, then, before the farthest polygon
 * P is painted, every polygon Q whose depth range overlaps P's is checked:
 *   1. their x extents do not overlap, or
 *   2. their y extents do not overlap, or
 *   3. P lies entirely on the far side of Q's plane, or
 *   4. Q lies entirely on the near side of P's plane, or
 *   5. their projections do not overlap (separating axis test).
 * When all five fail, Q is moved in front of P if the reversed tests 3 and 4
 * allow it; a Q that was already moved once closes a cycle, and the cycle is
 * broken by splitting P (or Q) along the other's plane.  The tests run in
 * screen space (pixels, window depth), where the projection is parallel. */
#include "internal.h"
#include "../core/array.h"
#include "../core/sort.h"

#include <stdlib.h>
#include <string.h>

typedef struct node {
    double xmin, xmax, ymin, ymax, zmin, zmax;
    double plane[4]; /* unit normal (toward the viewer) and offset, depth scaled */
    int prev, next;
    unsigned char moved, floating;
} node;

typedef struct painter {
    const render_frame *f;
    painter_polygon *polygons;
    node *nodes;
    size_t count, polygon_capacity, node_capacity, limit;
    double depth_scale;
} painter;

static double vx(const screen_vertex *v)
{
    return v->x;
}
static double vy(const screen_vertex *v)
{
    return v->y;
}

static void describe(painter *pt, int i)
{
    const painter_polygon *p = &pt->polygons[i];
    node *n = &pt->nodes[i];
    double s = pt->depth_scale;
    n->xmin = n->ymin = n->zmin = INFINITY;
    n->xmax = n->ymax = n->zmax = -INFINITY;
    double normal[3] = {0, 0, 0}, centre[3] = {0, 0, 0};
    for (int k = 0; k < p->n; k++) {
        const screen_vertex *a = &p->v[k], *b = &p->v[(k + 1) % p->n];
        n->xmin = fmin(n->xmin, a->x);
        n->xmax = fmax(n->xmax, a->x);
        n->ymin = fmin(n->ymin, a->y);
        n->ymax = fmax(n->ymax, a->y);
        n->zmin = fmin(n->zmin, a->z);
        n->zmax = fmax(n->zmax, a->z);
        double az = a->z * s, bz = b->z * s;
        normal[0] += (a->y - b->y) * (az + bz);
        normal[1] += (az - bz) * (a->x + b->x);
        normal[2] += (a->x - b->x) * (a->y + b->y);
        centre[0] += a->x;
        centre[1] += a->y;
        centre[2] += az;
    }
    double length = sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    if (!(length > 0))
        length = 1;
    /* Toward the viewer is toward smaller depth. */
    if (normal[2] > 0)
        length = -length;
    for (int k = 0; k < 3; k++) {
        n->plane[k] = normal[k] / length;
        centre[k] /= p->n;
    }
    n->plane[3] = -(n->plane[0] * centre[0] + n->plane[1] * centre[1] + n->plane[2] * centre[2]);
}

#define SIDE_EPSILON 1e-6
#define OVERLAP_EPSILON 1e-7

static double distance(const painter *pt, int plane_of, const screen_vertex *v)
{
    const double *q = pt->nodes[plane_of].plane;
    return q[0] * v->x + q[1] * v->y + q[2] * v->z * pt->depth_scale + q[3];
}

/* Every vertex of a on the far side (sign -1) or near side (+1) of b's plane. */
static int all_on_side(const painter *pt, int a, int b, int sign)
{
    const painter_polygon *p = &pt->polygons[a];
    for (int k = 0; k < p->n; k++)
        if (sign * distance(pt, b, &p->v[k]) < -SIDE_EPSILON)
            return 0;
    return 1;
}

/* Whether the two convex projections are separated by an edge direction of
 * a (touching counts as separated). */
static int separated_by_edges(const painter_polygon *a, const painter_polygon *b)
{
    for (int k = 0; k < a->n; k++) {
        const screen_vertex *p = &a->v[k], *q = &a->v[(k + 1) % a->n];
        double axis_x = -(vy(q) - vy(p)), axis_y = vx(q) - vx(p);
        double amin = INFINITY, amax = -INFINITY, bmin = INFINITY, bmax = -INFINITY;
        for (int i = 0; i < a->n; i++) {
            double d = axis_x * a->v[i].x + axis_y * a->v[i].y;
            amin = fmin(amin, d);
            amax = fmax(amax, d);
        }
        for (int i = 0; i < b->n; i++) {
            double d = axis_x * b->v[i].x + axis_y * b->v[i].y;
            bmin = fmin(bmin, d);
            bmax = fmax(bmax, d);
        }
        double tolerance = OVERLAP_EPSILON * (fabs(amax) + fabs(bmax) + 1);
        if (amax <= bmin + tolerance || bmax <= amin + tolerance)
            return 1;
    }
    return 0;
}

/* True when P can be painted before Q: tests 1 to 5. */
static int may_precede(const painter *pt, int p, int q)
{
    const node *a = &pt->nodes[p], *b = &pt->nodes[q];
    if (a->xmax <= b->xmin || b->xmax <= a->xmin)
        return 1;
    if (a->ymax <= b->ymin || b->ymax <= a->ymin)
        return 1;
    if (all_on_side(pt, p, q, -1))
        return 1;
    if (all_on_side(pt, q, p, +1))
        return 1;
    const painter_polygon *pp = &pt->polygons[p], *qq = &pt->polygons[q];
    return separated_by_edges(pp, qq) || separated_by_edges(qq, pp);
}

static int add_polygon(painter *pt, const painter_polygon *p)
{
    if (core_array_reserve((void **)&pt->polygons, &pt->polygon_capacity, pt->count + 1,
                           sizeof *pt->polygons)
            != CG_OK
        || core_array_reserve((void **)&pt->nodes, &pt->node_capacity, pt->count + 1,
                              sizeof *pt->nodes)
               != CG_OK)
        return -1;
    pt->polygons[pt->count] = *p;
    memset(&pt->nodes[pt->count], 0, sizeof(node));
    describe(pt, (int)pt->count);
    return (int)pt->count++;
}

/* The point a fraction t from a to b, attributes interpolated linearly in
 * screen space after division by w (perspective-correct). */
static void split_point(const screen_vertex *a, const screen_vertex *b, double t, int attributes,
                        screen_vertex *out)
{
    out->x = a->x + t * (b->x - a->x);
    out->y = a->y + t * (b->y - a->y);
    out->z = a->z + t * (b->z - a->z);
    out->iw = a->iw + t * (b->iw - a->iw);
    for (int j = 0; j < attributes; j++)
        out->a[j] = (float)((a->a[j] * a->iw + t * (b->a[j] * b->iw - a->a[j] * a->iw)) / out->iw);
}

/* Splits polygon `which` by the plane of polygon `by`: returns 0 when the
 * plane does not cut it, else the indices of the far and near pieces. */
static int split(painter *pt, int which, int by, int *far_piece, int *near_piece)
{
    if (pt->count + 2 > pt->limit)
        return 0;
    painter_polygon p = pt->polygons[which];
    double d[RENDER_MAX_POLYGON];
    int positive = 0, negative = 0;
    for (int k = 0; k < p.n; k++) {
        d[k] = distance(pt, by, &p.v[k]);
        positive |= d[k] > SIDE_EPSILON;
        negative |= d[k] < -SIDE_EPSILON;
    }
    if (!positive || !negative)
        return 0;
    painter_polygon pieces[2]; /* 0: far (d <= 0), 1: near (d >= 0) */
    pieces[0] = p;
    pieces[1] = p;
    pieces[0].n = pieces[1].n = 0;
    for (int k = 0; k < p.n; k++) {
        int next = (k + 1) % p.n;
        if (d[k] <= 0 && pieces[0].n < RENDER_MAX_POLYGON)
            pieces[0].v[pieces[0].n++] = p.v[k];
        if (d[k] >= 0 && pieces[1].n < RENDER_MAX_POLYGON)
            pieces[1].v[pieces[1].n++] = p.v[k];
        if ((d[k] < 0 && d[next] > 0) || (d[k] > 0 && d[next] < 0)) {
            screen_vertex cut;
            split_point(&p.v[k], &p.v[next], d[k] / (d[k] - d[next]), pt->f->attribute_count, &cut);
            if (pieces[0].n < RENDER_MAX_POLYGON)
                pieces[0].v[pieces[0].n++] = cut;
            if (pieces[1].n < RENDER_MAX_POLYGON)
                pieces[1].v[pieces[1].n++] = cut;
        }
    }
    if (pieces[0].n < 3 || pieces[1].n < 3)
        return 0;
    int a = add_polygon(pt, &pieces[0]);
    if (a < 0)
        return -1;
    int b = add_polygon(pt, &pieces[1]);
    if (b < 0)
        return -1;
    *far_piece = a;
    *near_piece = b;
    return 1;
}

static void unlink_node(painter *pt, int *list_head, int i)
{
    node *n = &pt->nodes[i];
    if (n->prev >= 0)
        pt->nodes[n->prev].next = n->next;
    else
        *list_head = n->next;
    if (n->next >= 0)
        pt->nodes[n->next].prev = n->prev;
}

static void push_front(painter *pt, int *list_head, int i)
{
    pt->nodes[i].prev = -1;
    pt->nodes[i].next = *list_head;
    if (*list_head >= 0)
        pt->nodes[*list_head].prev = i;
    *list_head = i;
}

typedef struct sort_key {
    double zmax;
    int index;
} sort_key;

/* Farthest first; ties in mesh order. */
static int by_far_depth(const void *a, const void *b)
{
    const sort_key *x = a, *y = b;
    if (x->zmax != y->zmax)
        return x->zmax < y->zmax ? 1 : -1;
    return (x->index > y->index) - (x->index < y->index);
}

static void paint(painter *pt, int i)
{
    const render_frame *f = pt->f;
    const painter_polygon *p = &pt->polygons[i];
    for (int k = 1; k + 1 < p->n; k++) {
        setup_triangle t;
        if (render_setup(&p->v[0], &p->v[k], &p->v[k + 1], f->width, f->height, f->attribute_count,
                         0, &t)
            != 1)
            continue;
        render_finish_setup(f, &t, p->color);
        f->r->stats.rasterized++;
        f->r->stats.fragments += render_raster(f, &t, 0, 0, f->width, f->height, 0);
    }
}

/* The image cleared to the background, the depth to +infinity. */
static void clear_frame(render_frame *f)
{
    for (int y = 0; y < f->height; y++) {
        float *z = f->depth + (size_t)y * f->width;
        unsigned char *row = f->image->data + (size_t)y * f->image->stride;
        for (int x = 0; x < f->width; x++) {
            z[x] = INFINITY;
            if (f->image->format == CG_PIXEL_RGBA8)
                ((cg_rgba8 *)row)[x] = f->background8;
            else
                ((cg_rgbaf *)row)[x] = (cg_rgbaf){f->background[0], f->background[1],
                                                  f->background[2], f->background[3]};
        }
    }
}

/* The polygons of every chunk, in mesh order, into pt, and the list of
 * them sorted by farthest depth into *list (farthest first). */
static cg_status gather_sorted(painter *pt, int *list)
{
    const render_frame *f = pt->f;
    size_t total = 0;
    for (int c = 0; c < f->chunk_count; c++)
        total += f->chunks[c].polygon_count;
    /* Splitting is bounded: past four times the input (plus a margin) the
     * remaining conflicts are painted in sorted order. */
    pt->limit = total * 4 + 1024;
    if (total > (size_t)1 << 28)
        return CG_ENOMEM;
    for (int c = 0; c < f->chunk_count; c++)
        for (size_t i = 0; i < f->chunks[c].polygon_count; i++)
            if (add_polygon(pt, &f->chunks[c].polygons[i]) < 0)
                return CG_ENOMEM;
    sort_key *keys = malloc((pt->count ? pt->count : 1) * sizeof *keys);
    if (!keys)
        return CG_ENOMEM;
    for (size_t i = 0; i < pt->count; i++) {
        keys[i].zmax = pt->nodes[i].zmax;
        keys[i].index = (int)i;
    }
    core_sort(keys, pt->count, sizeof *keys, by_far_depth);
    *list = -1;
    for (size_t i = pt->count; i-- > 0;)
        push_front(pt, list, keys[i].index);
    free(keys);
    return CG_OK;
}

/* The pieces a (far) and b (near) of polygon `which` take its place in
 * the list. */
static void replace_by_pieces(painter *pt, int *list, int which, int a, int b)
{
    int before = pt->nodes[which].prev;
    unlink_node(pt, list, which);
    if (before < 0) {
        push_front(pt, list, b);
        push_front(pt, list, a);
    } else {
        int after = pt->nodes[before].next;
        pt->nodes[a].prev = before;
        pt->nodes[a].next = b;
        pt->nodes[b].prev = a;
        pt->nodes[b].next = after;
        pt->nodes[before].next = a;
        if (after >= 0)
            pt->nodes[after].prev = b;
    }
    pt->nodes[a].floating = pt->nodes[b].floating = 1;
}

/* Newell's tests of the list's head P against every Q that overlaps it in
 * depth: 0 when P may be painted now, 1 when the list changed (a Q moved in
 * front of P, or a polygon was split: start again from the head), -1 when
 * memory runs out. */
static int settle_head(painter *pt, int *list, size_t *splits)
{
    int p = *list;
    for (int q = pt->nodes[p].next; q >= 0; q = pt->nodes[q].next) {
        if (pt->nodes[q].zmax <= pt->nodes[p].zmin) {
            if (!pt->nodes[q].floating)
                break; /* the sorted rest cannot overlap P in depth */
            continue;
        }
        if (may_precede(pt, p, q))
            continue;
        /* P may hide part of Q: can Q go first instead? */
        if (!pt->nodes[q].moved && (all_on_side(pt, q, p, -1) || all_on_side(pt, p, q, +1))) {
            unlink_node(pt, list, q);
            push_front(pt, list, q);
            pt->nodes[q].moved = pt->nodes[q].floating = 1;
            return 1;
        }
        /* A cycle or interpenetration: split one by the other's plane. */
        int a, b, which = p, result = split(pt, p, q, &a, &b);
        if (result == 0) {
            which = q;
            result = split(pt, q, p, &a, &b);
        }
        if (result < 0)
            return -1;
        if (result == 0)
            continue; /* cannot be resolved: keep the sorted order */
        ++*splits;
        replace_by_pieces(pt, list, which, a, b);
        return 1;
    }
    return 0;
}

cg_status render_painter(render_frame *f)
{
    clear_frame(f);
    painter pt;
    memset(&pt, 0, sizeof pt);
    pt.f = f;
    pt.depth_scale = f->width > f->height ? f->width : f->height;
    int list = -1;
    cg_status status = gather_sorted(&pt, &list);
    size_t splits = 0, painted = 0;
    int naive = f->o->algorithm == CG_RENDER_DEPTH_SORT;
    while (status == CG_OK && list >= 0) {
        int p = list;
        if (!naive) {
            int settled = settle_head(&pt, &list, &splits);
            if (settled < 0)
                status = CG_ENOMEM;
            if (settled != 0)
                continue;
        }
        unlink_node(&pt, &list, p);
        paint(&pt, p);
        if (!naive && ++painted % 4096 == 0 && f->o->progress)
            f->o->progress(f->o->progress_user, (double)painted / (double)pt.count);
    }
    f->splits = splits;
    free(pt.polygons);
    free(pt.nodes);
    return status;
}
