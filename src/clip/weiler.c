/* Weiler-Atherton polygon clipping (11.2.2): both boundaries become lists of
 * vertices with the intersection points inserted; the clipped polygons are
 * traced by following the subject from each entering intersection and the
 * window from each exiting one. */
#include "cg/clip.h"
#include "internal.h"
#include "../core/array.h"
#include "../core/sort.h"

#include <stdlib.h>
#include <string.h>

typedef struct wnode {
    cg_vec2 p;
    size_t next;  /* next node on the same boundary */
    size_t twin;  /* the same intersection on the other boundary, or -1 */
    int entering; /* subject enters the window here */
    int visited;
} wnode;

typedef struct xing {
    size_t si, ci; /* subject and window edge */
    double t, u;   /* parameters along them */
    cg_vec2 p;
    int entering;
} xing;

double clip_twice_area(const cg_vec2 *p, size_t n)
{
    double s = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++)
        s += cg_vec2_cross(p[j], p[i]);
    return s;
}

static int point_in(const cg_vec2 *p, size_t n, cg_vec2 q)
{
    int in = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++)
        if ((p[i].y > q.y) != (p[j].y > q.y)
            && q.x < p[j].x + (q.y - p[j].y) * (p[i].x - p[j].x) / (p[i].y - p[j].y))
            in = !in;
    return in;
}

size_t clip_weiler_prepare(const cg_vec2 *in, size_t n, cg_vec2 d, cg_vec2 *out)
{
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        cg_vec2 p = cg_vec2_add(in[i], d);
        if (m && p.x == out[m - 1].x && p.y == out[m - 1].y)
            continue;
        out[m++] = p;
    }
    while (m > 1 && out[0].x == out[m - 1].x && out[0].y == out[m - 1].y)
        m--;
    if (m >= 3 && clip_twice_area(out, m) < 0)
        for (size_t i = 0; i < m / 2; i++) {
            cg_vec2 t = out[i];
            out[i] = out[m - 1 - i];
            out[m - 1 - i] = t;
        }
    return m;
}

static int cmp_s(const void *a, const void *b)
{
    const xing *x = a, *y = b;
    if (x->si != y->si)
        return x->si < y->si ? -1 : 1;
    return (x->t > y->t) - (x->t < y->t);
}

static int cmp_c(const void *a, const void *b)
{
    const xing *const *x = a, *const *y = b;
    if ((*x)->ci != (*y)->ci)
        return (*x)->ci < (*y)->ci ? -1 : 1;
    return ((*x)->u > (*y)->u) - ((*x)->u < (*y)->u);
}

/* Phase 1: every coordinate finite; the largest magnitude goes to *ext. */
static cg_status check_input(const cg_vec2 *subject, size_t n, const cg_vec2 *window, size_t m,
                             double *ext)
{
    *ext = 0;
    for (size_t i = 0; i < n + m; i++) {
        cg_vec2 p = i < n ? subject[i] : window[i - n];
        if (!isfinite(p.x) || !isfinite(p.y))
            return CG_EINVAL;
        *ext = fmax(*ext, fmax(fabs(p.x), fabs(p.y)));
    }
    return CG_OK;
}

int clip_weiler_crossing(cg_vec2 a, cg_vec2 d, cg_vec2 c, cg_vec2 e, double *t, double *u,
                         int *entering)
{
    double den = cg_vec2_cross(d, e);
    if (den == 0)
        return 0;
    cg_vec2 ac = cg_vec2_sub(c, a);
    *t = cg_vec2_cross(ac, e) / den;
    *u = cg_vec2_cross(ac, d) / den;
    *entering = den < 0;
    return *t >= 0 && *t < 1 && *u >= 0 && *u < 1;
}

/* Phase 2: every proper crossing of a subject edge with a window edge,
 * appended to *X in subject-edge order. */
static cg_status find_crossings(const cg_vec2 *S, size_t n, const cg_vec2 *C, size_t m, xing **X,
                                size_t *nx)
{
    size_t capx = 0;
    for (size_t i = 0; i < n; i++) {
        cg_vec2 a = S[i], b = S[(i + 1) % n], d = cg_vec2_sub(b, a);
        for (size_t j = 0; j < m; j++) {
            cg_vec2 c = C[j], e = cg_vec2_sub(C[(j + 1) % m], c);
            double t, u;
            int entering;
            if (!clip_weiler_crossing(a, d, c, e, &t, &u, &entering))
                continue;
            if (core_array_reserve((void **)X, &capx, *nx + 1, sizeof **X) != CG_OK)
                return CG_ENOMEM;
            (*X)[(*nx)++] = (xing){i, j, t, u, cg_vec2_add(a, cg_vec2_scale(d, t)), entering};
        }
    }
    return CG_OK;
}

/* Phase 3: the two boundary lists, vertices with the crossings inserted in
 * order along each edge, every crossing linked to its twin.  X (nx > 0) is
 * sorted here; sn holds n + nx nodes and cn m + nx. */
static cg_status build_lists(const cg_vec2 *S, size_t n, const cg_vec2 *C, size_t m, xing *X,
                             size_t nx, wnode *sn, wnode *cn)
{
    core_sort(X, nx, sizeof *X, cmp_s);
    xing **XC = malloc(nx * sizeof *XC);
    size_t *sidx = malloc(nx * sizeof *sidx);
    if (!XC || !sidx) {
        free(XC);
        free(sidx);
        return CG_ENOMEM;
    }
    size_t k = 0, ns = 0;
    for (size_t i = 0; i < n; i++) {
        sn[ns] = (wnode){S[i], 0, (size_t)-1, 0, 0};
        ns++;
        while (k < nx && X[k].si == i) {
            sn[ns] = (wnode){X[k].p, 0, (size_t)-1, X[k].entering, 0};
            sidx[k] = ns++;
            k++;
        }
    }
    for (size_t i = 0; i < ns; i++)
        sn[i].next = (i + 1) % ns;
    for (size_t i = 0; i < nx; i++)
        XC[i] = &X[i];
    core_sort(XC, nx, sizeof *XC, cmp_c);
    size_t nc = 0;
    k = 0;
    for (size_t j = 0; j < m; j++) {
        cn[nc] = (wnode){C[j], 0, (size_t)-1, 0, 0};
        nc++;
        while (k < nx && XC[k]->ci == j) {
            size_t s = sidx[XC[k] - X];
            cn[nc] = (wnode){XC[k]->p, 0, s, XC[k]->entering, 0};
            sn[s].twin = nc;
            nc++;
            k++;
        }
    }
    for (size_t i = 0; i < nc; i++)
        cn[i].next = (i + 1) % nc;
    free(sidx);
    free(XC);
    return CG_OK;
}

/* Phase 4: one loop from each unvisited entering crossing, following the
 * subject to the next crossing, then the window, and so on back to the
 * start.  ring has room for ns + nc points. */
static cg_status trace_loops(wnode *sn, size_t ns, wnode *cn, size_t nc, cg_vec2 *ring,
                             cg_polygon_set *result)
{
    cg_status st = CG_OK;
    for (size_t start = 0; start < ns && st == CG_OK; start++) {
        if (sn[start].twin == (size_t)-1 || !sn[start].entering || sn[start].visited)
            continue;
        size_t len = 0, cur = start, guard = 0, limit = ns + nc;
        wnode *list = sn;
        do {
            /* at a crossing: emit it, then follow this boundary to the next
             * crossing (crossings alternate entering / exiting along each
             * boundary) and continue on the other boundary from there */
            list[cur].visited = 1;
            (list == sn ? cn : sn)[list[cur].twin].visited = 1;
            if (len < limit)
                ring[len++] = list[cur].p;
            cur = list[cur].next;
            while (list[cur].twin == (size_t)-1 && guard++ < limit) {
                if (len < limit)
                    ring[len++] = list[cur].p;
                cur = list[cur].next;
            }
            cur = list[cur].twin;
            list = list == sn ? cn : sn;
        } while (!(list == sn && cur == start) && guard++ < limit);
        if (len >= 3)
            st = cg_polygon_set_add_ring(result, ring, len, 1);
    }
    return st;
}

/* The smallest counter-clockwise ring of rs that contains q, or -1. */
static size_t smallest_outer(const cg_polygon_set *rs, cg_vec2 q)
{
    size_t best = (size_t)-1;
    double best_area = INFINITY;
    for (size_t o = 0; o < rs->ring_count; o++) {
        double a = cg_polygon_set_ring_area(rs, o);
        if (a > 0 && a < best_area
            && point_in(rs->points + rs->ring_start[o], rs->ring_start[o + 1] - rs->ring_start[o],
                        q)) {
            best = o;
            best_area = a;
        }
    }
    return best;
}

/* Phase 5: loops turning clockwise are holes: move each after the smallest
 * counter-clockwise loop around it. */
static cg_status nest_holes(cg_polygon_set *result)
{
    cg_status st = CG_OK;
    cg_polygon_set sorted = {0};
    size_t nr = result->ring_count;
    for (size_t r = 0; r < nr && st == CG_OK; r++) {
        if (cg_polygon_set_ring_area(result, r) <= 0)
            continue;
        st = cg_polygon_set_add_ring(&sorted, result->points + result->ring_start[r],
                                     result->ring_start[r + 1] - result->ring_start[r], 1);
        for (size_t h = 0; h < nr && st == CG_OK; h++) {
            if (cg_polygon_set_ring_area(result, h) >= 0)
                continue;
            if (smallest_outer(result, result->points[result->ring_start[h]]) == r)
                st = cg_polygon_set_add_ring(&sorted, result->points + result->ring_start[h],
                                             result->ring_start[h + 1] - result->ring_start[h], 0);
        }
    }
    cg_polygon_set_clear(result);
    *result = sorted;
    return st;
}

cg_status cg_clip_weiler_atherton(const cg_vec2 *subject, size_t n, const cg_vec2 *window, size_t m,
                                  cg_polygon_set *result)
{
    if (!result)
        return CG_EINVAL;
    cg_polygon_set_clear(result);
    if (!subject || !window || n < 3 || m < 3 || n > ((size_t)1 << 24) || m > ((size_t)1 << 24))
        return CG_EINVAL;
    double ext;
    if (check_input(subject, n, window, m, &ext) != CG_OK)
        return CG_EINVAL;
    cg_status st = CG_ENOMEM;
    cg_vec2 *S = malloc(n * sizeof *S), *C = malloc(m * sizeof *C), *ring = NULL;
    xing *X = NULL;
    wnode *sn = NULL, *cn = NULL;
    size_t nx = 0;
    if (!S || !C)
        goto done;
    /* the window moved off every degenerate contact (an irrational-looking
     * direction, 1e-9 of the extent) */
    double delta = (ext > 0 ? ext : 1) * 1e-9;
    n = clip_weiler_prepare(subject, n, cg_vec2_make(0, 0), S);
    m = clip_weiler_prepare(window, m, cg_vec2_make(delta * 0.7548776662, delta * 0.5698402910), C);
    if (n < 3 || m < 3 || clip_twice_area(S, n) == 0 || clip_twice_area(C, m) == 0) {
        st = CG_OK; /* nothing with an area */
        goto done;
    }
    if (find_crossings(S, n, C, m, &X, &nx) != CG_OK)
        goto done;
    if (nx == 0 || nx % 2) {
        /* no crossing: one inside the other, or apart */
        st = CG_OK;
        if (point_in(C, m, S[0]))
            st = cg_polygon_set_add_ring(result, S, n, 1);
        else if (point_in(S, n, C[0]))
            st = cg_polygon_set_add_ring(result, C, m, 1);
        goto done;
    }
    sn = calloc(n + nx, sizeof *sn);
    cn = calloc(m + nx, sizeof *cn);
    ring = malloc((n + m + 2 * nx) * sizeof *ring);
    if (!sn || !cn || !ring || build_lists(S, n, C, m, X, nx, sn, cn) != CG_OK)
        goto done;
    st = trace_loops(sn, n + nx, cn, m + nx, ring, result);
    if (st == CG_OK && result->ring_count > 1)
        st = nest_holes(result);
done:
    if (st != CG_OK)
        cg_polygon_set_clear(result);
    free(S);
    free(C);
    free(X);
    free(sn);
    free(cn);
    free(ring);
    return st;
}
