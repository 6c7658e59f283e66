/* Checkpoints of the boolean operations' sweep: the whole state at the
 * start of some scanlines, so that the pass after a split resumes where
 * nothing changed and takes the last pass's pieces there. */
#include "boolean_engine.h"

/* an active edge's run flags, as ck_edge.flags */
static inline unsigned ck_flags(const sweep *s, uint32_t e)
{
    return (unsigned)s->brk_next[e] | (unsigned)s->run_open[e] << 1 |
           (unsigned)(s->run_open[e] && s->run_up[e]) << 2;
}

/* Notes the state at the start of scanline y (before its events): 0 when
 * no more checkpoints are taken (budget spent or out of memory). */
int boolean_ck_record(sweep *s, int64_t y)
{
    ck_log *L = s->log;
    size_t n = s->nact;
    if (L->ned + n > L->budget)
        return 0;
    GROW(L->pt, L->npt, L->cappt, return 0);
    while (L->ned + n > L->caped) {
        size_t c = L->caped ? 2 * L->caped : 256;
        ck_edge *p = realloc(L->ed, c * sizeof *p);
        if (!p)
            return 0;
        L->ed = p;
        L->caped = c;
    }
    L->pt[L->npt++] = (ck_point){y, s->g->np, L->ned, n};
    for (size_t k = 0; k < n; k++) {
        uint32_t e = s->act[k];
        L->ed[L->ned++] = (ck_edge){e, ck_flags(s, e), s->wr0[e], s->wr1[e], s->xn[e],
                                    s->run_x[e], s->run_y[e]};
    }
    return 1;
}

/* Is this pass's state at the start of the scanline of checkpoint c of the
 * last pass the same as that pass's there?  Then, as no edge above was
 * split, the rest of this pass would be the rest of that one. */
int boolean_ck_same(const sweep *s, const ck_point *c)
{
    if (c->n != s->nact)
        return 0;
    const ck_edge *r = s->prev->ed + c->first;
    for (size_t k = 0; k < c->n; k++) {
        uint32_t e = s->act[k];
        if (r[k].e >= s->prev_ne || s->prev_map[r[k].e] != e || r[k].flags != ck_flags(s, e) ||
            r[k].x != s->xn[e] || r[k].wr0 != s->wr0[e] || r[k].wr1 != s->wr1[e] ||
            (s->run_open[e] && (r[k].run_x != s->run_x[e] || r[k].run_y != s->run_y[e])))
            return 0;
    }
    return 1;
}

/* first of a[0..n) (edge numbers sorted by a field) whose field is >= y */
static size_t first_edge_at(const bedge *E, const uint32_t *a, size_t n, int64_t y, int top)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if ((top ? E[a[mid]].yt : E[a[mid]].yb) < y)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Takes the state of the last checkpoint L->pt[j] (j >= j0) of the last
 * pass at or below y (every edge active there kept its number;
 * s->prev_map: the last pass's numbers to ours): its index + 1, or 0 when
 * there is none. */
size_t boolean_ck_load(sweep *s, const ck_log *L, size_t j0, int64_t y)
{
    size_t j = L->npt;
    while (j > j0 && L->pt[j - 1].y > y)
        j--;
    if (j == j0)
        return 0;
    const ck_point *c = &L->pt[j - 1];
    size_t lo = 0, hi = s->nys;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (s->ys[mid] < c->y)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo == s->nys || s->ys[lo] != c->y)
        return 0;
    /* (L->ed is NULL when no checkpoint logged an edge) */
    const ck_edge *r = c->n ? L->ed + c->first : NULL;
    for (size_t k = 0; k < c->n; k++)
        /* no active edge there was split */
        if (!CG_INVARIANT(r[k].e < s->prev_ne && s->prev_map[r[k].e] != UINT32_MAX))
            return 0;
    s->nbrkq = 0;
    s->brkq_full = 0;
    for (size_t k = 0; k < c->n; k++) {
        uint32_t e = s->prev_map[r[k].e];
        s->act[k] = e;
        s->xn[e] = r[k].x;
        s->brk_next[e] = (unsigned char)(r[k].flags & 1);
        s->run_open[e] = (unsigned char)(r[k].flags >> 1 & 1);
        s->run_up[e] = (unsigned char)(r[k].flags >> 2 & 1);
        s->wr0[e] = r[k].wr0;
        s->wr1[e] = r[k].wr1;
        s->run_x[e] = r[k].run_x;
        s->run_y[e] = r[k].run_y;
        if (r[k].flags & 1)
            s->brkq_next[s->nbrkq++] = e;
    }
    s->nact = c->n;
    s->start_iy = lo;
    s->start_ip = first_edge_at(s->g->E, s->by_bottom, s->g->ne, c->y, 0);
    s->start_it = first_edge_at(s->g->E, s->by_top, s->g->ne, c->y, 1);
    return j;
}
