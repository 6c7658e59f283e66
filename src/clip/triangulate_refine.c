/* Refinement of the constrained Delaunay triangulation to a minimum angle
 * (Ruppert's algorithm, with Chew's and Shewchuk's concentric shells).
 *
 * The ring edges are kept as a list of subsegments.  Round after round the
 * constrained Delaunay triangulation of the rings and the points added so
 * far is built (triangulate.c), then:
 *
 * 1. every subsegment encroached (a vertex strictly inside its diametral
 *    circle, seen from the triangle on it) is split in two;
 * 2. when none is, each triangle whose smallest angle is below the bound
 *    gets its circumcenter added -- unless that point encroaches a
 *    subsegment, which is then split instead.  Centres are taken from
 *    triangles sharing no vertex, so two added in one round are never
 *    neighbours.
 *
 * It ends when no triangle is bad.  Split points lie exactly on their
 * subsegment: the grid point on it nearest the middle (a subsegment with
 * none inside is left whole).  A subsegment leaving a vertex where two ring
 * edges meet at less than 60 degrees is split at a power of two from that
 * vertex, so that the splits around it stay on concentric circles and do
 * not encroach each other without end; the triangles with their smallest
 * angle at such a vertex are left as they are (the input's angle bounds
 * them).  Circumcentres are rounded to the grid.  With the bound at most
 * 30 degrees this terminates in practice; two caps make it certain: on
 * the points added (64 per input vertex, plus 65,536) and on the work, the
 * points triangulated over all rounds (256 rounds of the input and 1,024
 * points), since near the grid's resolution a round may add a single point
 * (rounded circumcentres making new bad triangles) and every round
 * triangulates everything again.  At either cap the triangulation of the
 * last round is the result: valid, with some angles under the bound. */
#include "triangulate_internal.h"

#include "../core/array.h"
#include "../core/sort.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct subsegment {
    cg_point64 a, b;
    uint32_t ring;
    uint8_t split, whole; /* to split this round; has no grid point inside */
} subsegment;

typedef CORE_ARRAY(subsegment) subsegment_array;
typedef CORE_ARRAY(cg_point64) point_array;

/* The key of a subsegment: its ends in lexicographic order. */
typedef struct segment_key {
    cg_point64 lo, hi;
    uint32_t index;
} segment_key;

typedef CORE_ARRAY(segment_key) key_array;

typedef struct refinement {
    subsegment_array segments;
    key_array keys;
    point_array extra;  /* the points added inside */
    point_array apexes; /* vertices with an input angle below 60 degrees, sorted */
    point_array used;   /* vertices of this round's refined triangles (a hash set) */
    CORE_ARRAY(uint8_t) used_slot;
    cg_polygon_set64 rings, triangles;
    double cos_bound; /* a triangle is bad when an angle's cosine exceeds it */
} refinement;

static int point_less(cg_point64 p, cg_point64 q)
{
    return p.x < q.x || (p.x == q.x && p.y < q.y);
}

static int compare_point(const void *a, const void *b)
{
    const cg_point64 *p = a, *q = b;
    return point_less(*p, *q) ? -1 : point_less(*q, *p) ? 1 : 0;
}

static int compare_key(const void *a, const void *b)
{
    const segment_key *x = a, *y = b;
    int c = compare_point(&x->lo, &y->lo);
    return c ? c : compare_point(&x->hi, &y->hi);
}

static segment_key key_of(cg_point64 a, cg_point64 b)
{
    return point_less(a, b) ? (segment_key){a, b, 0} : (segment_key){b, a, 0};
}

static int contains_point(const point_array *sorted, cg_point64 p)
{
    return sorted->count > 0
           && bsearch(&p, sorted->data, sorted->count, sizeof p, compare_point) != NULL;
}

static polygon_i128 dot_at(cg_point64 v, cg_point64 a, cg_point64 b)
{
    return (polygon_i128)(a.x - v.x) * (b.x - v.x) + (polygon_i128)(a.y - v.y) * (b.y - v.y);
}

/* 1 when p lies strictly inside the diametral circle of a-b. */
static int encroaches(cg_point64 p, cg_point64 a, cg_point64 b)
{
    return dot_at(p, a, b) < 0;
}

/* The cosine of the angle at v of the triangle v, a, b. */
static double cosine_at(cg_point64 v, cg_point64 a, cg_point64 b)
{
    double ax = (double)(a.x - v.x), ay = (double)(a.y - v.y);
    double bx = (double)(b.x - v.x), by = (double)(b.y - v.y);
    return (ax * bx + ay * by) / (hypot(ax, ay) * hypot(bx, by));
}

/* The subsegments of the simple rings, and the vertices where two ring
 * edges meet at less than 60 degrees. */
static cg_status start(refinement *r, const cg_polygon_set64 *simple)
{
    cg_status st = CG_OK;
    for (size_t k = 0; k < simple->ring_count && st == CG_OK; k++) {
        size_t a = simple->ring_start[k], b = simple->ring_start[k + 1];
        for (size_t i = a; i < b && st == CG_OK; i++) {
            subsegment s = {simple->points[i], simple->points[i + 1 < b ? i + 1 : a], (uint32_t)k,
                            0, 0};
            st = core_array_push(&r->segments, s);
        }
    }
    /* every pair of edges at a vertex: the ends of the subsegments sorted by
     * vertex, then compared within each vertex's run */
    key_array ends = {0};
    for (size_t i = 0; i < r->segments.count && st == CG_OK; i++) {
        subsegment s = r->segments.data[i];
        st = core_array_push(&ends, ((segment_key){s.a, s.b, 0}));
        if (st == CG_OK)
            st = core_array_push(&ends, ((segment_key){s.b, s.a, 0}));
    }
    if (st == CG_OK && ends.count > 0)
        core_sort(ends.data, ends.count, sizeof *ends.data, compare_key);
    for (size_t i = 0; i < ends.count && st == CG_OK;) {
        size_t j = i + 1;
        while (j < ends.count && compare_point(&ends.data[j].lo, &ends.data[i].lo) == 0)
            j++;
        int sharp = 0;
        for (size_t p = i; p < j && !sharp; p++)
            for (size_t q = p + 1; q < j && !sharp; q++)
                sharp = cosine_at(ends.data[i].lo, ends.data[p].hi, ends.data[q].hi) > 0.5;
        if (sharp)
            st = core_array_push(&r->apexes, ends.data[i].lo); /* in sorted order */
        i = j;
    }
    core_array_free(&ends);
    return st;
}

/* The rings from the subsegments, and the keys that find them. */
static cg_status build_rings(refinement *r)
{
    cg_polygon_set64_clear(&r->rings);
    point_array ring = {0};
    cg_status st = CG_OK;
    r->keys.count = 0;
    for (size_t i = 0; i < r->segments.count && st == CG_OK; i++) {
        const subsegment *s = &r->segments.data[i];
        st = core_array_push(&ring, s->a);
        segment_key key = key_of(s->a, s->b);
        key.index = (uint32_t)i;
        if (st == CG_OK)
            st = core_array_push(&r->keys, key);
        int last = i + 1 == r->segments.count || r->segments.data[i + 1].ring != s->ring;
        if (st == CG_OK && last) {
            st = cg_polygon_set64_add_ring(&r->rings, ring.data, ring.count, 1);
            ring.count = 0;
        }
    }
    core_array_free(&ring);
    if (st == CG_OK && r->keys.count > 0)
        core_sort(r->keys.data, r->keys.count, sizeof *r->keys.data, compare_key);
    return st;
}

static subsegment *find_segment(refinement *r, cg_point64 a, cg_point64 b)
{
    segment_key key = key_of(a, b);
    const segment_key *k = r->keys.count
                               ? bsearch(&key, r->keys.data, r->keys.count, sizeof key, compare_key)
                               : NULL;
    return k ? &r->segments.data[k->index] : NULL;
}

static int64_t gcd64(int64_t a, int64_t b)
{
    a = a < 0 ? -a : a;
    b = b < 0 ? -b : b;
    while (b) {
        int64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* Where to split s: a grid point on it near the middle, or near a power of
 * two from an end at a sharp input angle.  0 when none lies inside. */
static int split_point(const refinement *r, const subsegment *s, cg_point64 *at)
{
    int64_t dx = s->b.x - s->a.x, dy = s->b.y - s->a.y, g = gcd64(dx, dy);
    if (g < 2)
        return 0;
    int sharp_a = contains_point(&r->apexes, s->a), sharp_b = contains_point(&r->apexes, s->b);
    double t = 0.5;
    if (sharp_a != sharp_b) {
        double length = hypot((double)dx, (double)dy);
        double shell = exp2(floor(log2(length / 2) + 0.5)); /* from the sharp end */
        t = shell / length;
        t = t < 0.25 ? 0.25 : t > 0.75 ? 0.75 : t;
        if (sharp_b)
            t = 1 - t;
    }
    int64_t k = (int64_t)llround(t * (double)g);
    k = k < 1 ? 1 : k > g - 1 ? g - 1 : k;
    *at = (cg_point64){s->a.x + k * (dx / g), s->a.y + k * (dy / g)};
    return 1;
}

/* Splits every subsegment marked; the count split. */
static cg_status split_marked(refinement *r, size_t *count)
{
    subsegment_array next = {0};
    cg_status st = core_array_reserve_for(&next, r->segments.count * 2);
    *count = 0;
    for (size_t i = 0; i < r->segments.count && st == CG_OK; i++) {
        subsegment s = r->segments.data[i];
        cg_point64 m;
        if (s.split && !s.whole && split_point(r, &s, &m)) {
            next.data[next.count++] = (subsegment){s.a, m, s.ring, 0, 0};
            next.data[next.count++] = (subsegment){m, s.b, s.ring, 0, 0};
            ++*count;
        } else {
            s.whole = s.whole || s.split; /* asked to split, but cannot be */
            s.split = 0;
            next.data[next.count++] = s;
        }
    }
    if (st == CG_OK) {
        core_array_free(&r->segments);
        r->segments = next;
    } else {
        core_array_free(&next);
    }
    return st;
}

/* Marks the subsegments encroached by a vertex of the triangles; how many. */
static size_t mark_encroached(refinement *r)
{
    size_t marked = 0;
    const cg_polygon_set64 *t = &r->triangles;
    for (size_t k = 0; k < t->ring_count; k++) {
        const cg_point64 *p = t->points + t->ring_start[k];
        for (int i = 0; i < 3; i++) {
            cg_point64 a = p[(i + 1) % 3], b = p[(i + 2) % 3];
            if (!encroaches(p[i], a, b))
                continue;
            subsegment *s = find_segment(r, a, b);
            if (s && !s->split && !s->whole) {
                s->split = 1;
                marked++;
            }
        }
    }
    return marked;
}

/* The circumcentre of a, b, c on the grid; 0 when it is off it. */
static int circumcentre(cg_point64 a, cg_point64 b, cg_point64 c, cg_point64 *out)
{
    double bx = (double)(b.x - a.x), by = (double)(b.y - a.y);
    double cx = (double)(c.x - a.x), cy = (double)(c.y - a.y);
    double d = 2 * (bx * cy - by * cx);
    double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    double x = (double)a.x + (cy * b2 - by * c2) / d, y = (double)a.y + (bx * c2 - cx * b2) / d;
    if (!(fabs(x) <= (double)CG_CLIP_MAX_COORD && fabs(y) <= (double)CG_CLIP_MAX_COORD))
        return 0;
    *out = (cg_point64){(int64_t)llround(x), (int64_t)llround(y)};
    return 1;
}

/* Whether the circumcentre c may be added: it encroaches no subsegment
 * (those it does are marked to split: 2; one that cannot be split rules c
 * out), lies strictly inside the rings and on no vertex or edge (1), or
 * not (0). */
static int try_centre(refinement *r, cg_point64 c)
{
    int encroached = 0, on_boundary = 0, near_whole = 0;
    for (size_t i = 0; i < r->segments.count; i++) {
        subsegment *s = &r->segments.data[i];
        int64_t xmin = s->a.x < s->b.x ? s->a.x : s->b.x, xmax = s->a.x ^ s->b.x ^ xmin;
        int64_t ymin = s->a.y < s->b.y ? s->a.y : s->b.y, ymax = s->a.y ^ s->b.y ^ ymin;
        if (c.x < xmin - (ymax - ymin) || c.x > xmax + (ymax - ymin) || c.y < ymin - (xmax - xmin)
            || c.y > ymax + (xmax - xmin))
            continue; /* outside a box around the diametral circle */
        if (dot_at(c, s->a, s->b) <= 0) {
            on_boundary |= polygon_orient(s->a, s->b, c) == 0;
            if (encroaches(c, s->a, s->b) && s->whole) {
                near_whole = 1; /* it would stay encroached: no point there */
            } else if (encroaches(c, s->a, s->b)) {
                s->split = 1;
                encroached = 1;
            }
        }
    }
    if (encroached)
        return 2;
    return !on_boundary && !near_whole && polygon_winding_number(&r->rings, c) != 0;
}

/* The set of used vertices: open addressing, room for twice `most`. */
static cg_status used_reset(refinement *r, size_t most)
{
    size_t size = 16;
    while (size < 2 * most)
        size *= 2;
    if (core_array_reserve_for(&r->used, size) != CG_OK
        || core_array_reserve_for(&r->used_slot, size) != CG_OK)
        return CG_ENOMEM;
    r->used.count = r->used_slot.count = size;
    memset(r->used_slot.data, 0, size);
    return CG_OK;
}

static size_t used_find(const refinement *r, cg_point64 p)
{
    uint64_t h = ((uint64_t)p.x * 0x9e3779b97f4a7c15ull) ^ ((uint64_t)p.y * 0xc2b2ae3d27d4eb4full);
    size_t mask = r->used.count - 1, i = (size_t)(h >> 17) & mask;
    while (r->used_slot.data[i] && (r->used.data[i].x != p.x || r->used.data[i].y != p.y))
        i = (i + 1) & mask;
    return i;
}

static int used_has(const refinement *r, cg_point64 p)
{
    return r->used_slot.data[used_find(r, p)];
}

static void used_add(refinement *r, cg_point64 p)
{
    size_t i = used_find(r, p);
    r->used.data[i] = p;
    r->used_slot.data[i] = 1;
}

/* Adds the circumcentres of the bad triangles (or splits what they
 * encroach); how many points that makes. */
static cg_status refine_triangles(refinement *r, size_t *added)
{
    const cg_polygon_set64 *t = &r->triangles;
    *added = 0;
    cg_status st = used_reset(r, 3 * t->ring_count);
    point_array fresh = {0};
    for (size_t k = 0; k < t->ring_count && st == CG_OK; k++) {
        const cg_point64 *p = t->points + t->ring_start[k];
        int worst = 0;
        double cosine[3];
        for (int i = 0; i < 3; i++) {
            cosine[i] = cosine_at(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
            worst = cosine[i] > cosine[worst] ? i : worst;
        }
        if (cosine[worst] <= r->cos_bound || contains_point(&r->apexes, p[worst]))
            continue;
        /* one triangle per vertex and round */
        int shares = used_has(r, p[0]) || used_has(r, p[1]) || used_has(r, p[2]);
        cg_point64 c;
        if (shares || !circumcentre(p[0], p[1], p[2], &c))
            continue;
        if ((c.x == p[0].x && c.y == p[0].y) || (c.x == p[1].x && c.y == p[1].y)
            || (c.x == p[2].x && c.y == p[2].y))
            continue; /* rounded onto a vertex: too small to refine on the grid */
        int verdict = try_centre(r, c);
        if (verdict == 1)
            st = core_array_push(&fresh, c);
        for (int i = 0; i < 3 && verdict; i++)
            used_add(r, p[i]);
        *added += verdict != 0;
    }
    for (size_t i = 0; i < fresh.count && st == CG_OK; i++)
        st = core_array_push(&r->extra, fresh.data[i]);
    core_array_free(&fresh);
    return st;
}

static void free_refinement(refinement *r)
{
    core_array_free(&r->segments);
    core_array_free(&r->keys);
    core_array_free(&r->extra);
    core_array_free(&r->apexes);
    core_array_free(&r->used);
    core_array_free(&r->used_slot);
    cg_polygon_set64_clear(&r->rings);
    cg_polygon_set64_clear(&r->triangles);
}

cg_status triangulate_refine(const cg_polygon_set64 *simple, double min_angle,
                             cg_polygon_set64 *result)
{
    refinement r = {0};
    r.cos_bound = cos(min_angle * M_PI / 180);
    cg_status st = start(&r, simple);
    size_t cap = 64 * simple->point_count + 65536;
    size_t work = 0, work_cap = 256 * (simple->point_count + 1024);
    for (int done = 0; st == CG_OK && !done;) {
        st = build_rings(&r);
        if (st == CG_OK)
            st = triangulate_cdt(&r.rings, r.extra.data, r.extra.count, &r.triangles);
        work += r.rings.point_count + r.extra.count;
        if (st != CG_OK || r.extra.count + r.segments.count > cap || work > work_cap)
            break;
        size_t split = 0, added = 0;
        if (mark_encroached(&r) == 0)
            st = refine_triangles(&r, &added);
        if (st == CG_OK)
            st = split_marked(&r, &split);
        done = split == 0 && added == 0;
    }
    if (st == CG_OK) {
        cg_polygon_set64_clear(result);
        *result = r.triangles;
        r.triangles = (cg_polygon_set64){0};
    }
    free_refinement(&r);
    return st;
}
