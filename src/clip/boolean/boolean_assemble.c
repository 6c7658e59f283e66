/* Assembly of the boolean operations' result: boundary pieces linked into
 * rings, holes placed in the smallest outer ring around them. */
#include "boolean_engine.h"
#include "../../core/arena.h"

/* Where direction o lies turning clockwise from direction r, as an order
 * key: 0 within a half turn, 1 at the half turn, 2 beyond it, 3 along r (a
 * full turn). */
static int half_cw(i128 rx, i128 ry, i128 ox, i128 oy)
{
    i128 c = rx * oy - ry * ox, d = rx * ox + ry * oy;
    if (c < 0)
        return 0;
    if (c == 0 && d < 0)
        return 1;
    if (c > 0)
        return 2;
    return 3;
}

/* whether piece a's direction comes before b's turning clockwise from r */
static int cw_before(i128 rx, i128 ry, const piece *a, const piece *b)
{
    i128 ax = a->x_end - a->x_start, ay = a->y_end - a->y_start, bx = b->x_end - b->x_start,
         by = b->y_end - b->y_start;
    int ha = half_cw(rx, ry, ax, ay), hb = half_cw(rx, ry, bx, by);
    if (ha != hb)
        return ha < hb;
    i128 c = ax * by - ay * bx;
    return c < 0; /* b is clockwise of a */
}

typedef struct ring_by_area {
    double area;
    size_t ring;
} ring_by_area;
static int cmp_area(const void *a, const void *b)
{
    const ring_by_area *x = a, *y = b;
    if (x->area != y->area)
        return x->area < y->area ? -1 : 1;
    return (x->ring > y->ring) - (x->ring < y->ring);
}

typedef struct hole_point {
    int64_t x, y;
    size_t ring, parent;
} hole_point;
static int cmp_hole_x(const void *a, const void *b)
{
    const hole_point *p = a, *q = b;
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    return (p->ring > q->ring) - (p->ring < q->ring);
}

static int cmp_hole_y(const void *a, const void *b)
{
    const hole_point *p = a, *q = b;
    if (p->y != q->y)
        return p->y < q->y ? -1 : 1;
    return (p->ring > q->ring) - (p->ring < q->ring);
}

/* first index of a (sorted by x, or by y) whose x (y) is >= v */
static size_t first_at_least(const hole_point *a, size_t n, int64_t v, int by_y)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if ((by_y ? a[mid].y : a[mid].x) < v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* a hash of a grid point in [0, 2^bits) */
static inline size_t point_hash(int64_t x, int64_t y, size_t bits)
{
    uint64_t h = (uint64_t)x * 0x9e3779b97f4a7c15u ^ (uint64_t)y * 0xc2b2ae3d27d4eb4fu;
    h ^= h >> 29;
    return (size_t)((h * 0xbf58476d1ce4e5b9u) >> (64 - bits));
}

/* whether piece p starts before the point (vx, vy), in the order of
 * the start points by y, then x */
static inline int starts_before(const piece *p, int64_t vx, int64_t vy)
{
    return p->y_start < vy || (p->y_start == vy && p->x_start < vx);
}

/* The first of the pieces pieces[0..piece_count) (sorted by start point, y then x)
 * starting at (vx, vy), piece_count when none: a search that gallops from pieces[from]
 * and then halves. */
static size_t first_leaving_search(const piece *pieces, size_t piece_count, size_t from, int64_t vx,
                                   int64_t vy)
{
    size_t lo, hi; /* the first not starting before v is in [lo, hi] (hi == np: none) */
    if (starts_before(&pieces[from], vx, vy)) {
        size_t step = 1;
        lo = from + 1;
        hi = lo;
        while (hi < piece_count && starts_before(&pieces[hi], vx, vy)) {
            lo = hi + 1;
            hi = step < piece_count - hi ? hi + step : piece_count;
            step *= 2;
        }
    } else {
        size_t step = 1;
        hi = from;
        lo = from;
        while (lo > 0 && !starts_before(&pieces[lo - 1], vx, vy)) {
            hi = lo - 1;
            lo = step < lo ? lo - step : 0;
            step *= 2;
        }
    }
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (starts_before(&pieces[mid], vx, vy))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < piece_count && pieces[lo].x_start == vx && pieces[lo].y_start == vy ? lo
                                                                                    : piece_count;
}

/* whether p is in the hash set h (2^bits entries: index + 1 into pts, 0
 * free) */
static int is_vertex(const uint32_t *h, size_t bits, const cg_point64 *pts, cg_point64 p)
{
    for (size_t i = point_hash(p.x, p.y, bits); h[i]; i = (i + 1) & (((size_t)1 << bits) - 1))
        if (pts[h[i] - 1].x == p.x && pts[h[i] - 1].y == p.y)
            return 1;
    return 0;
}

typedef struct ringbuf {
    cg_point64 *points;
    size_t count, capacity;
} ringbuf;

/* Whether a ring passes a point twice, from the indices of its points
 * with several ways out (count of them; the first ASM_BRANCHES noted):
 * compared pair by pair, or, with more, taken as yes (the cut then looks
 * at every point).  In an exclusive or, for one, every crossing of the
 * operands' edges is such a point, though the rings rarely pass one twice. */
#define ASM_BRANCHES PINCH_FEW
static int passes_twice(const cg_point64 *pts, const size_t *at, size_t count)
{
    if (count > ASM_BRANCHES)
        return 1;
    for (size_t i = 1; i < count; i++)
        for (size_t j = 0; j < i; j++)
            if (pts[at[i]].x == pts[at[j]].x && pts[at[i]].y == pts[at[j]].y)
                return 1;
    return 0;
}

/* Adds the ring of the n points at rings->points + rings->point_count to
 * rings, without its collinear vertices (none when fewer than 3 remain); 0
 * when there is no room for it (which the sizes of the assembly's arrays
 * rule out). */
static int assemble_add_ring(cg_polygon_set64 *rings, size_t n, size_t max_rings)
{
    cg_point64 *pts = rings->points + rings->point_count;
    int again = 1;
    while (again && n >= 3) {
        again = 0;
        size_t m = 0;
        for (size_t i = 0; i < n; i++) {
            cg_point64 a = m ? pts[m - 1] : pts[n - 1], b = pts[i], c = pts[i + 1 < n ? i + 1 : 0];
            i128 cr = (i128)(b.x - a.x) * (c.y - b.y) - (i128)(b.y - a.y) * (c.x - b.x);
            if (cr == 0) {
                again = 1;
                continue;
            }
            pts[m++] = b;
        }
        n = m;
    }
    if (n < 3)
        return 1;
    if (rings->ring_count == max_rings)
        return 0;
    rings->point_count += n;
    rings->ring_start[++rings->ring_count] = rings->point_count;
    return 1;
}

/* The assembly's arrays, every one carved from one block (sized from the
 * piece count: a ring takes each piece at most once and has 3 vertices or
 * more, so there are at most piece_count points in all and piece_count / 3
 * rings), and what its phases hand on. */
typedef struct assembly {
    size_t piece_count, max_rings;
    piece *pieces; /* the pieces sorted by start point (y, then x) */
    keyval *sort_scratch, *sort_tmp;
    uint32_t *sort_order;
    unsigned char *used; /* whether a ring took the piece */
    /* the first piece leaving a point, by a hash of the point (index + 1, 0
     * free; open addressing), when `hashed` */
    int hashed;
    size_t hash_bits;
    uint32_t *first_leaving;
    cg_polygon_set64 rings; /* the rings walked (their arrays in the block) */
    double *area;           /* twice each ring's signed area */
    int64_t (*boxes)[4];    /* each ring's bounds: x0, y0, x1, y1 */
    size_t *parent;         /* each hole's outer ring, or SIZE_MAX */
    size_t *outers;         /* the outer rings (counter-clockwise) */
    size_t outer_count;
    ring_by_area *outers_by_area;
    hole_point *hole_points;        /* a point of each hole, in quadrupled coordinates */
    hole_point *candidates;         /* the holes one outer ring may hold */
    unsigned char *inside;          /* of the candidates, those it holds */
    size_t *first_hole, *next_hole; /* each outer ring's holes, as lists */
} assembly;

/* The assembly's arrays taken from arena (measuring, then carving). */
static ALWAYS_INLINE void take_assembly_arrays(core_arena *arena, assembly *a)
{
    size_t n = a->piece_count, rings = a->max_rings;
    a->sort_scratch = core_arena_take(arena, n, sizeof *a->sort_scratch);
    a->sort_order = core_arena_take(arena, n, sizeof *a->sort_order);
    a->pieces = core_arena_take(arena, n, sizeof *a->pieces);
    a->used = core_arena_take(arena, n, 1);
    a->sort_tmp = core_arena_take(arena, n, sizeof *a->sort_tmp);
    a->rings.points = core_arena_take(arena, n, sizeof *a->rings.points);
    a->rings.ring_start = core_arena_take(arena, rings + 1, sizeof *a->rings.ring_start);
    a->area = core_arena_take(arena, rings, sizeof *a->area);
    a->boxes = core_arena_take(arena, rings, sizeof *a->boxes);
    a->parent = core_arena_take(arena, rings, sizeof *a->parent);
    a->outers = core_arena_take(arena, rings, sizeof *a->outers);
    a->outers_by_area = core_arena_take(arena, rings, sizeof *a->outers_by_area);
    a->hole_points = core_arena_take(arena, rings, sizeof *a->hole_points);
    a->candidates = core_arena_take(arena, rings, sizeof *a->candidates);
    a->first_hole = core_arena_take(arena, rings + 1, sizeof *a->first_hole);
    a->next_hole = core_arena_take(arena, rings + 1, sizeof *a->next_hole);
    a->first_leaving = core_arena_take(arena, a->hashed ? (size_t)1 << a->hash_bits : 0,
                                       sizeof *a->first_leaving);
    a->inside = core_arena_take(arena, rings, 1);
}

/* The pieces in order of their start points, and each point's first piece
 * leaving it in the hash: 0 when out of memory. */
static int sort_pieces(assembly *a, const piece *pieces)
{
    size_t n = a->piece_count, hash_bits = a->hash_bits;
    piece *sorted = a->pieces;
    const uint32_t *order = a->sort_order;
    uint32_t *first = a->first_leaving;
    if (!boolean_sort_two_keys(&pieces[0].y_start, &pieces[0].x_start, sizeof(piece), n,
                               a->sort_order, a->sort_scratch, a->sort_tmp))
        return 0;
    for (size_t i = 0; i < n; i++)
        sorted[i] = pieces[order[i]];
    if (!a->hashed)
        return 1;
    size_t hash_mask = ((size_t)1 << hash_bits) - 1;
    memset(first, 0, (hash_mask + 1) * sizeof *first);
    for (size_t i = 0; i < n; i++) {
        if (i && sorted[i].x_start == sorted[i - 1].x_start
            && sorted[i].y_start == sorted[i - 1].y_start)
            continue;
        size_t h = point_hash(sorted[i].x_start, sorted[i].y_start, hash_bits);
        while (first[h])
            h = (h + 1) & hash_mask;
        first[h] = (uint32_t)(i + 1);
    }
    return 1;
}

/* The first piece leaving (vx, vy), where piece `arriving` ends: by the
 * hash (first_leaving, hash_bits), or, when that is NULL, by a search from
 * the arriving piece (a ring's next piece is usually close by in the
 * order); piece_count when none. */
static inline size_t first_piece_at(const piece *pieces, size_t piece_count,
                                    const uint32_t *first_leaving, size_t hash_bits,
                                    size_t arriving, int64_t vx, int64_t vy)
{
    if (!first_leaving)
        return first_leaving_search(pieces, piece_count, arriving, vx, vy);
    size_t hash_mask = ((size_t)1 << hash_bits) - 1;
    for (size_t h = point_hash(vx, vy, hash_bits); first_leaving[h]; h = (h + 1) & hash_mask) {
        size_t f = first_leaving[h] - 1;
        if (pieces[f].x_start == vx && pieces[f].y_start == vy)
            return f;
    }
    return piece_count;
}

/* Walks the ring from piece `start` (unused), taking at each point the
 * sharpest left turn among the unused pieces leaving it, into walk; where
 * it passed a point with several ways out (the only points it can pass
 * twice), the first ASM_BRANCHES of them in branch_at[] (*branches of them
 * in all).  0 when a piece would be taken twice (cannot happen). */
static int walk_ring(const assembly *a, size_t start, ringbuf *walk, size_t *branch_at,
                     size_t *branches)
{
    /* (held here: the stores below would make them be read again) */
    const piece *pieces = a->pieces;
    unsigned char *used = a->used;
    const uint32_t *first_leaving = a->hashed ? a->first_leaving : NULL;
    size_t piece_count = a->piece_count, hash_bits = a->hash_bits, cur = start;
    cg_point64 *points = walk->points;
    size_t count = 0, capacity = walk->capacity, branch_count = 0;
    used[cur] = 1;
    for (;;) {
        if (!CG_INVARIANT(count < capacity)) /* each piece is taken once */
            return 0;
        points[count++] = (cg_point64){pieces[cur].x_start, pieces[cur].y_start};
        int64_t vx = pieces[cur].x_end, vy = pieces[cur].y_end;
        size_t lo = first_piece_at(pieces, piece_count, first_leaving, hash_bits, cur, vx, vy);
        size_t best = (size_t)-1;
        i128 rx = pieces[cur].x_start - pieces[cur].x_end,
             ry = pieces[cur].y_start - pieces[cur].y_end;
        size_t k = lo;
        for (; k < piece_count && pieces[k].y_start == vy && pieces[k].x_start == vx; k++) {
            if (used[k] && k != start)
                continue;
            if (best == (size_t)-1 || cw_before(rx, ry, &pieces[k], &pieces[best]))
                best = k;
        }
        if (k - lo > 1) {
            if (branch_count < ASM_BRANCHES)
                branch_at[branch_count] = best == start ? 0 : count;
            branch_count++;
        }
        if (best == (size_t)-1 || best == start)
            break;
        cur = best;
        used[cur] = 1;
    }
    walk->count = count;
    *branches = branch_count;
    return 1;
}

/* The ring walked added to the rings, cut first into rings of their own
 * at the points it passes twice: 0 when out of memory. */
static int add_walked_ring(assembly *a, const ringbuf *walk, const size_t *branch_at,
                           size_t branches)
{
    cg_polygon_set64 *rings = &a->rings;
    if (!passes_twice(walk->points, branch_at, branches))
        return assemble_add_ring(rings, walk->count, a->max_rings);
    size_t *ends, loops;
    if (!boolean_split_pinches(walk->points, walk->count, branch_at, branches, &ends, &loops))
        return 0;
    for (size_t k = 0, from = 0; k < loops; from = ends[k++]) {
        memmove(rings->points + rings->point_count, walk->points + from,
                (ends[k] - from) * sizeof *walk->points);
        if (!assemble_add_ring(rings, ends[k] - from, a->max_rings)) {
            free(ends);
            return 0;
        }
    }
    free(ends);
    return 1;
}

/* Every piece linked into rings (each walked in place, after the rings so
 * far): 0 when out of memory. */
static int walk_rings(assembly *a)
{
    memset(a->used, 0, a->piece_count);
    a->rings.ring_start[0] = 0;
    for (size_t start = 0; start < a->piece_count; start++) {
        if (a->used[start])
            continue;
        ringbuf walk = {a->rings.points + a->rings.point_count, 0,
                        a->piece_count - a->rings.point_count};
        size_t branch_at[ASM_BRANCHES], branches;
        if (!walk_ring(a, start, &walk, branch_at, &branches)
            || !add_walked_ring(a, &walk, branch_at, branches))
            return 0;
    }
    return 1;
}

/* Each ring's area and bounds: the counter-clockwise ones are the outer
 * rings, the others holes (no parent yet). */
static void measure_rings(assembly *a)
{
    /* (held here: the stores below would make them be read again) */
    const cg_point64 *points = a->rings.points;
    const size_t *ring_start = a->rings.ring_start;
    size_t ring_count = a->rings.ring_count, outer_count = 0;
    double *area = a->area;
    int64_t(*boxes)[4] = a->boxes;
    size_t *parent = a->parent, *outers = a->outers;
    for (size_t r = 0; r < ring_count; r++) {
        size_t first = ring_start[r], end = ring_start[r + 1];
        uint64_t area_mod64 = 0;
        int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
        for (size_t i = first; i < end; i++) {
            cg_point64 p = points[i], q = points[i + 1 < end ? i + 1 : first];
            area_mod64 += (uint64_t)p.x * (uint64_t)q.y - (uint64_t)q.x * (uint64_t)p.y;
            if (p.x < x0)
                x0 = p.x;
            if (p.x > x1)
                x1 = p.x;
            if (p.y < y0)
                y0 = p.y;
            if (p.y > y1)
                y1 = p.y;
        }
        /* twice the area, summed modulo 2^64 above: exact when it is known
         * to fit, that is when each of the n terms (taken from the box's
         * corner: the sum is the same) is within w h and n w h < 2^63 */
        uint64_t w = (uint64_t)x1 - (uint64_t)x0, hgt = (uint64_t)y1 - (uint64_t)y0;
        i128 twice = w < ((uint64_t)1 << 31) && hgt < ((uint64_t)1 << 31)
                             && w * hgt <= (uint64_t)INT64_MAX / (end - first)
                         ? (i128)(int64_t)area_mod64
                         : clip_ring_twice_area(points + first, end - first);
        area[r] = (double)twice;
        boxes[r][0] = x0;
        boxes[r][1] = y0;
        boxes[r][2] = x1;
        boxes[r][3] = y1;
        parent[r] = (size_t)-1;
        if (twice > 0)
            outers[outer_count++] = r;
    }
    a->outer_count = outer_count;
}

/* The point of each hole (in quadrupled coordinates), in a->hole_points
 * sorted by x: the midpoint of one of its edges, or else a quarter point,
 * that is not a vertex of another ring (rings may touch there, after the
 * collinear vertex of the hole went away), so that it is on no other ring.
 * 0 when out of memory. */
static int pick_hole_points(assembly *a, size_t hole_count)
{
    const cg_polygon_set64 *rings = &a->rings;
    uint32_t *verts = NULL; /* a hash set of the vertices, when first needed */
    size_t vbits = 4, vertex_count = rings->point_count, noted = 0;
    for (size_t r = 0; r < rings->ring_count; r++) {
        if (a->area[r] > 0)
            continue;
        size_t a0 = rings->ring_start[r], a1 = rings->ring_start[r + 1];
        cg_point64 u0 = rings->points[a0], v0 = rings->points[a0 + 1];
        int64_t px = 2 * (u0.x + v0.x), py = 2 * (u0.y + v0.y);
        int found = 0;
        for (int quarter = 0; quarter < 2 && !found; quarter++) {
            for (size_t i = a0; i < a1 && !found; i++) {
                cg_point64 u = rings->points[i], v = rings->points[i + 1 < a1 ? i + 1 : a0];
                int64_t qx = quarter ? 3 * u.x + v.x : 2 * (u.x + v.x);
                int64_t qy = quarter ? 3 * u.y + v.y : 2 * (u.y + v.y);
                cg_point64 m = {qx / 4, qy / 4};
                if (!(qx & 3) && !(qy & 3) && !verts) {
                    while (((size_t)1 << vbits) < 2 * vertex_count)
                        vbits++;
                    verts = calloc((size_t)1 << vbits, sizeof *verts);
                    if (!verts)
                        return 0;
                    for (size_t q = 0; q < vertex_count; q++) {
                        cg_point64 p = rings->points[q];
                        size_t h = point_hash(p.x, p.y, vbits);
                        while (verts[h])
                            h = (h + 1) & (((size_t)1 << vbits) - 1);
                        verts[h] = (uint32_t)(q + 1);
                    }
                }
                if ((qx & 3) || (qy & 3) || !is_vertex(verts, vbits, rings->points, m)) {
                    px = qx;
                    py = qy;
                    found = 1;
                }
            }
        }
        a->hole_points[noted++] = (hole_point){px, py, r, 0};
    }
    free(verts);
    boolean_sort_few(a->hole_points, hole_count, sizeof *a->hole_points, cmp_hole_x);
    return 1;
}

/* The holes among hole_points[] that outer ring `outer` holds and no
 * smaller one did: their parent set.  The holes within its box are tested
 * together, its edges matched with their points sorted by y (a crossing
 * count each).  How many were placed. */
static size_t place_holes_in(assembly *a, size_t outer, size_t hole_count)
{
    const cg_polygon_set64 *rings = &a->rings;
    hole_point *hole_points = a->hole_points, *candidates = a->candidates;
    int64_t bx0 = 4 * a->boxes[outer][0], by0 = 4 * a->boxes[outer][1],
            bx1 = 4 * a->boxes[outer][2], by1 = 4 * a->boxes[outer][3];
    /* candidates: holes with bx0 <= x <= bx1 (binary search), in y range */
    size_t lo = first_at_least(hole_points, hole_count, bx0, 0);
    size_t candidate_count = 0;
    for (size_t k = lo; k < hole_count && hole_points[k].x <= bx1; k++)
        if (hole_points[k].parent == 0 && hole_points[k].y >= by0 && hole_points[k].y <= by1) {
            candidates[candidate_count] = hole_points[k];
            candidates[candidate_count].parent = k; /* index back into hole_points */
            candidate_count++;
        }
    if (!candidate_count)
        return 0;
    boolean_sort_few(candidates, candidate_count, sizeof *candidates, cmp_hole_y);
    unsigned char *in = a->inside;
    memset(in, 0, candidate_count);
    size_t s0 = rings->ring_start[outer], s1 = rings->ring_start[outer + 1];
    for (size_t i = s0; i < s1; i++) {
        cg_point64 u = rings->points[i], v = rings->points[i + 1 < s1 ? i + 1 : s0];
        int64_t uy = 4 * u.y, vy = 4 * v.y;
        if (uy == vy)
            continue;
        int64_t ylo = uy < vy ? uy : vy, yhi = uy < vy ? vy : uy;
        /* candidates with ylo <= y < yhi */
        size_t l = first_at_least(candidates, candidate_count, ylo, 1);
        i128 ux = 4 * (i128)u.x, vx = 4 * (i128)v.x;
        for (size_t k = l; k < candidate_count && candidates[k].y < yhi; k++) {
            i128 mx = candidates[k].x, my = candidates[k].y;
            i128 lhs = (mx - ux) * (vy - uy), rhs = (vx - ux) * (my - uy);
            if (vy > uy ? lhs < rhs : lhs > rhs)
                in[k] = !in[k];
        }
    }
    size_t placed = 0;
    for (size_t k = 0; k < candidate_count; k++)
        if (in[k]) {
            hole_point *hole = &hole_points[candidates[k].parent];
            hole->parent = outer + 1;
            a->parent[hole->ring] = outer;
            placed++;
        }
    return placed;
}

/* Each hole given to the smallest outer ring containing its point: the
 * outer rings are taken by increasing area.  0 when out of memory. */
static int nest_holes(assembly *a)
{
    size_t outer_count = a->outer_count, hole_count = a->rings.ring_count - outer_count;
    for (size_t i = 0; i < outer_count; i++)
        a->outers_by_area[i] = (ring_by_area){a->area[a->outers[i]], a->outers[i]};
    boolean_sort_few(a->outers_by_area, outer_count, sizeof *a->outers_by_area, cmp_area);
    if (!pick_hole_points(a, hole_count))
        return 0;
    size_t unplaced = hole_count;
    for (size_t k = 0; k < outer_count && unplaced; k++)
        unplaced -= place_holes_in(a, a->outers_by_area[k].ring, hole_count);
    return 1;
}

/* The result: each outer ring followed by its holes (every hole has an
 * outer ring: one without would be dropped).  0 when out of memory. */
static int write_result(assembly *a, cg_polygon_set64 *result)
{
    const cg_polygon_set64 *rings = &a->rings;
    size_t ring_count = rings->ring_count;
    size_t *first_hole = a->first_hole, *next_hole = a->next_hole, *parent = a->parent;
    for (size_t r = 0; r < ring_count; r++)
        first_hole[r] = (size_t)-1;
    /* the result's arrays at their size at once (no regrowth) */
    size_t point_count = 0, kept_rings = 0;
    for (size_t r = ring_count; r-- > 0;) {
        if (parent[r] != (size_t)-1) {
            next_hole[r] = first_hole[parent[r]];
            first_hole[parent[r]] = r;
        }
        if (parent[r] != (size_t)-1 || a->area[r] > 0) {
            point_count += rings->ring_start[r + 1] - rings->ring_start[r];
            kept_rings++;
        }
    }
    if (a->outer_count
        && clip_polygon_set64_reserve(result, result->point_count + point_count,
                                      result->ring_count + kept_rings,
                                      result->polygon_count + a->outer_count)
               != CG_OK)
        return 0;
    for (size_t r = 0; r < ring_count; r++) {
        if (a->area[r] <= 0)
            continue;
        size_t first = rings->ring_start[r];
        if (cg_polygon_set64_add_ring(result, rings->points + first,
                                      rings->ring_start[r + 1] - first, 1)
            != CG_OK)
            return 0;
        for (size_t h = first_hole[r]; h != (size_t)-1; h = next_hole[h]) {
            size_t hole_first = rings->ring_start[h];
            if (cg_polygon_set64_add_ring(result, rings->points + hole_first,
                                          rings->ring_start[h + 1] - hole_first, 0)
                != CG_OK)
                return 0;
        }
    }
    return 1;
}

/* *buf (*cap bytes) is the sweep's block, no longer needed: the assembly's
 * arrays are carved from it, replaced by a larger one when they do not fit
 * (unless it is `fixed`, the caller's buffer on the stack); the caller
 * frees it.  (A block of its own, as large as the sweep's, would come fresh
 * from the system call after call; one allocation per call at most, which
 * is most of the fixed cost on small inputs.) */
int boolean_assemble(engine *g, cg_polygon_set64 *result, void **buf, size_t *cap,
                     const void *fixed)
{
    assembly a;
    memset(&a, 0, sizeof a);
    a.piece_count = g->piece_count;
    if (a.piece_count == 0)
        return 1;
    if (a.piece_count > ((size_t)-1) / 256 || a.piece_count >= UINT32_MAX)
        return 0;
    a.max_rings = a.piece_count / 3 + 1;
    /* the first piece leaving a point: by a hash of the point, or on many
     * pieces (where the lookups would miss the caches) by a search from the
     * piece that arrives there */
    a.hashed = a.piece_count < 32768;
    a.hash_bits = 4;
    while (a.hashed && ((size_t)1 << a.hash_bits) < 2 * a.piece_count)
        a.hash_bits++;
    core_arena measure = core_arena_measuring();
    take_assembly_arrays(&measure, &a);
    if (measure.failed || core_arena_block(buf, cap, measure.used, fixed) != CG_OK)
        return 0;
    core_arena carve = core_arena_on(*buf, *cap);
    take_assembly_arrays(&carve, &a);
    /* (g->pieces is not read after the assembly) */
    if (!sort_pieces(&a, g->pieces) || !walk_rings(&a))
        return 0;
    measure_rings(&a);
    return nest_holes(&a) && write_result(&a, result);
}
