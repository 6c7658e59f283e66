/* Splitting a ring of the boolean result where it touches itself.
 *
 * The assembly walks the boundary pieces and takes, at a point with several
 * ways out, the one that keeps the result on the left closest: two outer
 * rings that touch at a point come out separate, but a hole that touches its
 * outer ring at a point is walked into it, giving one ring through that point
 * twice (a "pinch"), which the OGC Simple Features do not allow.  Cutting a
 * ring at each point it passes twice gives closed loops, each passing every
 * point once: a pinch of an outer and a hole gives a counter-clockwise ring
 * and a clockwise one, two outers give two counter-clockwise rings.  The
 * areas add up to the ring's, so nothing of the result changes but its
 * rings. */
#include "boolean_engine.h"
#include "../../core/sort.h"

typedef struct pinch_point {
    int64_t x, y;
    size_t index; /* index in the ring */
} pinch_point;

static int cmp_pinch_point(const void *a, const void *b)
{
    const pinch_point *p = a, *q = b;
    if (p->y != q->y)
        return p->y < q->y ? -1 : 1;
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    return (p->index > q->index) - (p->index < q->index);
}

#define PINCH_NONE ((size_t)-1)

/* Cuts pts[0..n) (a closed ring) at the points it passes more than once:
 * the loops are written back over pts one after another, loop k ending at
 * (*ends)[k], *count of them (1 when the ring passes every point once).
 * Only points with several ways out can be passed twice: when there are
 * at most PINCH_FEW of them, at[0..branches) are their indices in the ring
 * and they alone are compared; otherwise every point is (sorted).  *ends is
 * allocated (free it); 0 when memory ran out. */
int boolean_split_pinches(cg_point64 *pts, size_t n, const size_t *at, size_t branches,
                          size_t **ends, size_t *count)
{
    *ends = NULL;
    *count = 0;
    if (n == 0)
        return 1;
    int few = branches <= PINCH_FEW;
    /* one block: the ring's copy, each point's group of equal points, each
     * group's place on the stack, the stack, the ends, and the points
     * sorted (unless few) */
    size_t bytes = n * (sizeof(cg_point64) + 4 * sizeof(size_t))
                   + (few ? 0 : n * sizeof(pinch_point));
    char *mem = malloc(bytes);
    if (!mem)
        return 0;
    cg_point64 *copy = (cg_point64 *)mem;
    size_t *group = (size_t *)(copy + n), *place = group + n, *stack = place + n, *end = stack + n;
    memcpy(copy, pts, n * sizeof *pts);
    if (few) {
        /* a group for each point with several ways out: the first of the
         * noted indices with that point */
        for (size_t i = 0; i < n; i++)
            group[i] = PINCH_NONE;
        for (size_t i = 0; i < branches; i++) {
            size_t g = i;
            for (size_t j = 0; j < i && g == i; j++)
                if (pts[at[j]].x == pts[at[i]].x && pts[at[j]].y == pts[at[i]].y)
                    g = group[at[j]];
            group[at[i]] = g;
            place[i] = PINCH_NONE;
        }
    } else {
        pinch_point *sorted = (pinch_point *)(end + n);
        for (size_t i = 0; i < n; i++)
            sorted[i] = (pinch_point){pts[i].x, pts[i].y, i};
        core_sort(sorted, n, sizeof *sorted, cmp_pinch_point);
        /* a group for each point the ring passes more than once */
        size_t groups = 0;
        for (size_t i = 0; i < n;) {
            size_t j = i + 1;
            while (j < n && sorted[j].x == sorted[i].x && sorted[j].y == sorted[i].y)
                j++;
            for (size_t k = i; k < j; k++)
                group[sorted[k].index] = j - i > 1 ? groups : PINCH_NONE;
            if (j - i > 1)
                place[groups++] = PINCH_NONE;
            i = j;
        }
    }
    /* Walk the ring keeping the points since the last cut on a stack; a
     * point already on it closes the loop from there, which is cut off
     * (the point stays, as the start of what follows). */
    size_t top = 0, written = 0, loops = 0;
    for (size_t i = 0; i < n; i++) {
        size_t g = group[i];
        if (g != PINCH_NONE && place[g] != PINCH_NONE) {
            size_t from = place[g];
            for (size_t k = from; k < top; k++)
                pts[written++] = copy[stack[k]];
            end[loops++] = written;
            for (size_t k = from + 1; k < top; k++)
                if (group[stack[k]] != PINCH_NONE)
                    place[group[stack[k]]] = PINCH_NONE;
            top = from + 1;
            continue;
        }
        if (g != PINCH_NONE)
            place[g] = top;
        stack[top++] = i;
    }
    for (size_t k = 0; k < top; k++)
        pts[written++] = copy[stack[k]];
    end[loops++] = written;
    /* the ends to the front of the block, which the caller frees */
    memmove(mem, end, loops * sizeof *end);
    *ends = (size_t *)mem;
    *count = loops;
    return 1;
}
