/* Assembly of the boolean operations' result: boundary pieces linked into
 * rings, holes placed in the smallest outer ring around them. */
#include "boolean_engine.h"

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

typedef struct ring_by_area { double area; size_t ring; } ring_by_area;
static int cmp_area(const void *a, const void *b)
{
    const ring_by_area *x = a, *y = b;
    if (x->area != y->area)
        return x->area < y->area ? -1 : 1;
    return (x->ring > y->ring) - (x->ring < y->ring);
}

typedef struct hole_point { int64_t x, y; size_t ring, parent; } hole_point;
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
static size_t first_leaving(const piece *pieces, size_t piece_count, size_t from, int64_t vx,
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

/* *buf (*cap bytes) is the sweep's block, no longer needed: the assembly's
 * arrays are carved from it, replaced by a larger one when they do not fit
 * (unless it is `fixed`, the caller's buffer on the stack); the caller
 * frees it.  (A block of its own, as large as the sweep's, would come fresh
 * from the system call after call.) */
int boolean_assemble(engine *g, cg_polygon_set64 *result, void **buf, size_t *cap,
                     const void *fixed)
{
    size_t piece_count = g->piece_count;
    piece *pieces = g->pieces;
    if (piece_count == 0)
        return 1;
    /* Every array of the assembly from one block sized from the piece
     * count (a ring takes each piece at most once and has 3 vertices or
     * more, so at most np points in all and np / 3 rings): one allocation
     * per call, which is most of the fixed cost on small inputs. */
    if (piece_count > ((size_t)-1) / 256 || piece_count >= UINT32_MAX)
        return 0;
    size_t max_rings = piece_count / 3 + 1; /* rings at most */
    size_t bytes = 0, off[16], npart = 0;
#define ASM_PART(n, size) (off[npart++] = bytes, bytes += ((n) * (size) + 15) & ~(size_t)15)
    ASM_PART(piece_count, sizeof(keyval)); /* 0: sort scratch */
    ASM_PART(piece_count, sizeof(uint32_t)); /* 1: sort order */
    ASM_PART(piece_count, sizeof(piece)); /* 2: sorted pieces */
    ASM_PART(piece_count, 1); /* 3: used */
    ASM_PART(piece_count, sizeof(keyval)); /* 4: sort temporary */
    ASM_PART(piece_count, sizeof(cg_point64)); /* 5: ring points */
    ASM_PART(max_rings + 1, sizeof(size_t)); /* 6: ring starts */
    ASM_PART(max_rings, sizeof(double)); /* 7: area */
    ASM_PART(max_rings, 4 * sizeof(int64_t)); /* 8: bounding boxes */
    ASM_PART(max_rings, sizeof(size_t)); /* 9: parent */
    ASM_PART(max_rings, sizeof(size_t)); /* 10: outer rings */
    ASM_PART(max_rings, sizeof(ring_by_area)); /* 11: outers by area */
    ASM_PART(max_rings, sizeof(hole_point)); /* 12: hole points */
    ASM_PART(max_rings, sizeof(hole_point)); /* 13: candidates */
    ASM_PART(2 * (max_rings + 1), sizeof(size_t)); /* 14: first and next hole */
    /* the first piece leaving a point: by a hash of the point, or on many
     * pieces (where the lookups would miss the caches) by a search from the
     * piece that arrives there (a ring's next piece is usually close by in
     * the order) */
    int hashed = piece_count < 32768;
    size_t hash_bits = 4;
    while (hashed && ((size_t)1 << hash_bits) < 2 * piece_count)
        hash_bits++;
    ASM_PART(hashed ? (size_t)1 << hash_bits : 0, sizeof(uint32_t)); /* 15: point -> piece */
#undef ASM_PART
    if (bytes > *cap) {
        if (*buf != fixed)
            free(*buf);
        *cap = 0;
        *buf = malloc(bytes);
        if (!*buf)
            return 0;
        *cap = bytes;
    }
    char *mem = *buf;
    {
        keyval *scratch = (keyval *)(mem + off[0]);
        uint32_t *order = (uint32_t *)(mem + off[1]);
        piece *sorted = (piece *)(mem + off[2]);
        if (!boolean_sort_two_keys(&pieces[0].y_start, &pieces[0].x_start, sizeof(piece),
                                   piece_count, order, scratch, (keyval *)(mem + off[4])))
            return 0;
        for (size_t i = 0; i < piece_count; i++)
            sorted[i] = pieces[order[i]];
        pieces = sorted; /* (g->pieces is not read after the assembly) */
    }
    /* the first of the (sorted) pieces leaving each point, by a hash of the
     * point (open addressing; index + 1, 0 is free) */
    uint32_t *first = (uint32_t *)(mem + off[15]);
    size_t hash_mask = ((size_t)1 << hash_bits) - 1;
    if (hashed)
        memset(first, 0, (hash_mask + 1) * sizeof *first);
    for (size_t i = 0; i < piece_count && hashed; i++) {
        if (i && pieces[i].x_start == pieces[i - 1].x_start &&
            pieces[i].y_start == pieces[i - 1].y_start)
            continue;
        size_t h = point_hash(pieces[i].x_start, pieces[i].y_start, hash_bits);
        while (first[h])
            h = (h + 1) & hash_mask;
        first[h] = (uint32_t)(i + 1);
    }
    unsigned char *used = (unsigned char *)(mem + off[3]);
    memset(used, 0, piece_count);
    /* rings collected first: points and ring boundaries (in the block:
     * never grown, never freed on their own) */
    cg_polygon_set64 rings = {0};
    rings.points = (cg_point64 *)(mem + off[5]);
    rings.ring_start = (size_t *)(mem + off[6]);
    rings.ring_start[0] = 0;
    ringbuf walk = {NULL, 0, 0};
    int ok = 0;
    for (size_t start = 0; start < piece_count; start++) {
        if (used[start])
            continue;
        /* walked in place, after the rings so far */
        walk.points = rings.points + rings.point_count;
        walk.capacity = piece_count - rings.point_count;
        walk.count = 0;
        size_t cur = start;
        used[cur] = 1;
        /* where the ring passed a point with several ways out (the only
         * points it can pass twice): the first ASM_BRANCHES of them */
        size_t branch_at[ASM_BRANCHES], branches = 0;
        for (;;) {
            if (!CG_INVARIANT(walk.count < walk.capacity)) /* each piece is taken once */
                goto fail;
            walk.points[walk.count++] = (cg_point64){pieces[cur].x_start, pieces[cur].y_start};
            int64_t vx = pieces[cur].x_end, vy = pieces[cur].y_end;
            /* outgoing pieces at v: the first of them */
            size_t lo = hashed ? piece_count : first_leaving(pieces, piece_count, cur, vx, vy);
            for (size_t h = point_hash(vx, vy, hash_bits); hashed && first[h];
                 h = (h + 1) & hash_mask) {
                size_t f = first[h] - 1;
                if (pieces[f].x_start == vx && pieces[f].y_start == vy) {
                    lo = f;
                    break;
                }
            }
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
                if (branches < ASM_BRANCHES)
                    branch_at[branches] = best == start ? 0 : walk.count;
                branches++;
            }
            if (best == (size_t)-1 || best == start)
                break;
            cur = best;
            used[cur] = 1;
        }
        if (!passes_twice(walk.points, branch_at, branches)) {
            if (!assemble_add_ring(&rings, walk.count, max_rings))
                goto fail;
            continue;
        }
        /* a ring through a point twice is cut there into rings of their own */
        size_t *ends, loops;
        if (!boolean_split_pinches(walk.points, walk.count, branch_at, branches, &ends, &loops))
            goto fail;
        for (size_t k = 0, from = 0; k < loops; from = ends[k++]) {
            memmove(rings.points + rings.point_count, walk.points + from,
                    (ends[k] - from) * sizeof *walk.points);
            if (!assemble_add_ring(&rings, ends[k] - from, max_rings)) {
                free(ends);
                goto fail;
            }
        }
        free(ends);
    }
    /* classify and nest */
    {
        size_t ring_count = rings.ring_count;
        double *area = (double *)(mem + off[7]);
        int64_t(*boxes)[4] = (int64_t(*)[4])(mem + off[8]);
        size_t *parent = (size_t *)(mem + off[9]);
        size_t *order = (size_t *)(mem + off[10]);
        size_t outer_count = 0;
        for (size_t r = 0; r < ring_count; r++) {
            size_t a = rings.ring_start[r], b = rings.ring_start[r + 1];
            uint64_t area_mod64 = 0;
            int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
            for (size_t i = a; i < b; i++) {
                cg_point64 p = rings.points[i], q = rings.points[i + 1 < b ? i + 1 : a];
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
            /* twice the area, summed modulo 2^64 above: exact when it
             * is known to fit, that is when each of the n terms (taken
             * from the box's corner: the sum is the same) is within
             * w h and n w h < 2^63 */
            uint64_t w = (uint64_t)x1 - (uint64_t)x0, hgt = (uint64_t)y1 - (uint64_t)y0;
            i128 s = w < ((uint64_t)1 << 31) && hgt < ((uint64_t)1 << 31) &&
                             w * hgt <= (uint64_t)INT64_MAX / (b - a)
                         ? (i128)(int64_t)area_mod64
                         : clip_ring_twice_area(rings.points + a, b - a);
            area[r] = (double)s;
            boxes[r][0] = x0;
            boxes[r][1] = y0;
            boxes[r][2] = x1;
            boxes[r][3] = y1;
            parent[r] = (size_t)-1;
            if (s > 0)
                order[outer_count++] = r;
        }
        /* Each hole goes to the smallest outer containing a point of one
         * of its edges that is on no other ring (below).  The outers are
         * taken by increasing area; for each, the still unplaced holes
         * within its box are tested together: the outer's edges are
         * matched with the hole points sorted by y. */
        int fail_nest = 0;
        ring_by_area *outers_by_area = (ring_by_area *)(mem + off[11]);
        size_t hole_count = ring_count - outer_count;
        hole_point *hole_points = (hole_point *)(mem + off[12]);
        hole_point *candidates = (hole_point *)(mem + off[13]);
        {
            for (size_t i = 0; i < outer_count; i++)
                outers_by_area[i] = (ring_by_area){area[order[i]], order[i]};
            boolean_sort_few(outers_by_area, outer_count, sizeof *outers_by_area, cmp_area);
            /* The point of a hole (in quadrupled coordinates): the midpoint
             * of one of its edges, or else a quarter point, that is not a
             * vertex of another ring (rings may touch there, after the
             * collinear vertex of the hole went away), so that it is on no
             * other ring. */
            uint32_t *verts = NULL; /* a hash set of the vertices, when first needed */
            size_t vbits = 4;
            size_t nv = rings.point_count;
            size_t noted_holes = 0; /* holes noted in hp */
            for (size_t r = 0; r < ring_count && !fail_nest; r++) {
                if (area[r] > 0)
                    continue;
                size_t a0 = rings.ring_start[r], a1 = rings.ring_start[r + 1];
                cg_point64 u0 = rings.points[a0], v0 = rings.points[a0 + 1];
                int64_t px = 2 * (u0.x + v0.x), py = 2 * (u0.y + v0.y);
                int found = 0;
                for (int quarter = 0; quarter < 2 && !found; quarter++) {
                    for (size_t i = a0; i < a1 && !found; i++) {
                        cg_point64 u = rings.points[i], v = rings.points[i + 1 < a1 ? i + 1 : a0];
                        int64_t qx = quarter ? 3 * u.x + v.x : 2 * (u.x + v.x);
                        int64_t qy = quarter ? 3 * u.y + v.y : 2 * (u.y + v.y);
                        cg_point64 m = {qx / 4, qy / 4};
                        if (!(qx & 3) && !(qy & 3) && !verts) {
                            while (((size_t)1 << vbits) < 2 * nv)
                                vbits++;
                            verts = calloc((size_t)1 << vbits, sizeof *verts);
                            if (!verts) {
                                fail_nest = 1;
                                break;
                            }
                            for (size_t q = 0; q < nv; q++) {
                                cg_point64 p = rings.points[q];
                                size_t h = point_hash(p.x, p.y, vbits);
                                while (verts[h])
                                    h = (h + 1) & (((size_t)1 << vbits) - 1);
                                verts[h] = (uint32_t)(q + 1);
                            }
                        }
                        if ((qx & 3) || (qy & 3) ||
                            !is_vertex(verts, vbits, rings.points, m)) {
                            px = qx;
                            py = qy;
                            found = 1;
                        }
                    }
                }
                hole_points[noted_holes++] = (hole_point){px, py, r, 0};
            }
            free(verts);
            if (fail_nest)
                hole_count = 0;
            boolean_sort_few(hole_points, hole_count, sizeof *hole_points, cmp_hole_x);
            size_t unplaced = hole_count;
            for (size_t oi = 0; oi < outer_count && unplaced; oi++) {
                size_t o = outers_by_area[oi].ring;
                int64_t bx0 = 4 * boxes[o][0], by0 = 4 * boxes[o][1], bx1 = 4 * boxes[o][2],
                        by1 = 4 * boxes[o][3];
                /* candidates: holes with bx0 <= x <= bx1 (binary search), in y range */
                size_t lo = first_at_least(hole_points, hole_count, bx0, 0);
                size_t candidate_count = 0;
                for (size_t k = lo; k < hole_count && hole_points[k].x <= bx1; k++)
                    if (hole_points[k].parent == 0 && hole_points[k].y >= by0 &&
                        hole_points[k].y <= by1) {
                        candidates[candidate_count] = hole_points[k];
                        candidates[candidate_count].parent = k; /* index back into hp */
                        candidate_count++;
                    }
                if (!candidate_count)
                    continue;
                boolean_sort_few(candidates, candidate_count, sizeof *candidates, cmp_hole_y);
                unsigned char *in = calloc(candidate_count, 1);
                if (!in) {
                    fail_nest = 1;
                    break;
                }
                size_t s0 = rings.ring_start[o], s1 = rings.ring_start[o + 1];
                for (size_t i = s0; i < s1; i++) {
                    cg_point64 u = rings.points[i], v = rings.points[i + 1 < s1 ? i + 1 : s0];
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
                for (size_t k = 0; k < candidate_count; k++)
                    if (in[k]) {
                        hole_point *hpk = &hole_points[candidates[k].parent];
                        hpk->parent = o + 1;
                        parent[hpk->ring] = o;
                        unplaced--;
                    }
                free(in);
            }
        }
        if (fail_nest)
            goto fail;
        /* output: each outer followed by its holes (every hole has an outer:
         * one without would be dropped) */
        size_t *first_hole = (size_t *)(mem + off[14]);
        size_t *next_hole = first_hole + (ring_count + 1);
        int fail = 0;
        {
            for (size_t r = 0; r < ring_count; r++)
                first_hole[r] = (size_t)-1;
            /* the result's arrays at their size at once (no regrowth) */
            size_t npts = 0, nrings = 0;
            for (size_t r = ring_count; r-- > 0;) {
                if (parent[r] != (size_t)-1) {
                    next_hole[r] = first_hole[parent[r]];
                    first_hole[parent[r]] = r;
                }
                if (parent[r] != (size_t)-1 || area[r] > 0) {
                    npts += rings.ring_start[r + 1] - rings.ring_start[r];
                    nrings++;
                }
            }
            if (outer_count && clip_polygon_set64_reserve(
                                   result, result->point_count + npts, result->ring_count + nrings,
                                   result->polygon_count + outer_count) != CG_OK)
                fail = 1;
            for (size_t r = 0; r < ring_count && !fail; r++) {
                if (area[r] <= 0)
                    continue;
                size_t a = rings.ring_start[r];
                if (cg_polygon_set64_add_ring(result, rings.points + a,
                                              rings.ring_start[r + 1] - a, 1) != CG_OK) {
                    fail = 1;
                    break;
                }
                for (size_t h = first_hole[r]; h != (size_t)-1; h = next_hole[h]) {
                    size_t ha = rings.ring_start[h];
                    if (cg_polygon_set64_add_ring(result, rings.points + ha,
                                                  rings.ring_start[h + 1] - ha, 0) != CG_OK) {
                        fail = 1;
                        break;
                    }
                }
            }
        }
        if (fail)
            goto fail;
    }
    ok = 1;
fail:
    return ok;
}
