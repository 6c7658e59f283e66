/* Checkpoints of the boolean operations' sweep: the whole state at the
 * start of some scanlines, so that the pass after a split resumes where
 * nothing changed and takes the last pass's pieces there. */
#include "boolean_engine.h"

/* an active edge's run flags, as ck_edge.flags */
static inline unsigned ck_flags(const sweep *s, uint32_t e)
{
    return (unsigned)s->run_break_next[e] | (unsigned)s->run_open[e] << 1
           | (unsigned)(s->run_open[e] && s->run_up[e]) << 2;
}

/* Notes the state at the start of scanline y (before its events): 0 when
 * no more checkpoints are taken (budget spent or out of memory). */
int boolean_ck_record(sweep *s, int64_t y)
{
    ck_log *log = s->log;
    size_t n = s->active_count;
    if (log->edge_count + n > log->budget)
        return 0;
    if (!boolean_room((void **)&log->checkpoints, &log->checkpoint_capacity, log->checkpoint_count,
                      1, sizeof *log->checkpoints, NULL)
        || !boolean_room((void **)&log->edges, &log->edge_capacity, log->edge_count, n,
                         sizeof *log->edges, NULL))
        return 0;
    log->checkpoints[log->checkpoint_count++] = (ck_point){y, s->engine->piece_count,
                                                           log->edge_count, n};
    for (size_t k = 0; k < n; k++) {
        uint32_t e = s->active[k];
        log->edges[log->edge_count++] = (ck_edge){
            e,           ck_flags(s, e), s->winding_subject[e], s->winding_clip[e], s->x_next[e],
            s->run_x[e], s->run_y[e]};
    }
    return 1;
}

/* Is this pass's state at the start of the scanline of checkpoint c of the
 * last pass the same as that pass's there?  Then, as no edge above was
 * split, the rest of this pass would be the rest of that one. */
int boolean_ck_same(const sweep *s, const ck_point *c)
{
    if (c->edge_count != s->active_count)
        return 0;
    const ck_edge *records = s->prev_log->edges + c->first_edge;
    for (size_t k = 0; k < c->edge_count; k++) {
        uint32_t e = s->active[k];
        if (records[k].edge >= s->prev_edge_count || s->prev_map[records[k].edge] != e
            || records[k].flags != ck_flags(s, e) || records[k].x_at_scanline != s->x_next[e]
            || records[k].winding_subject != s->winding_subject[e]
            || records[k].winding_clip != s->winding_clip[e]
            || (s->run_open[e]
                && (records[k].run_x != s->run_x[e] || records[k].run_y != s->run_y[e])))
            return 0;
    }
    return 1;
}

/* first of a[0..n) (edge numbers sorted by a field) whose field is >= y */
static size_t first_edge_at(const edge *E, const uint32_t *a, size_t n, int64_t y, int top)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if ((top ? E[a[mid]].y_top : E[a[mid]].y_bottom) < y)
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
size_t boolean_ck_load(sweep *s, const ck_log *log, size_t j0, int64_t y)
{
    size_t j = log->checkpoint_count;
    while (j > j0 && log->checkpoints[j - 1].scanline_y > y)
        j--;
    if (j == j0)
        return 0;
    const ck_point *c = &log->checkpoints[j - 1];
    size_t lo = 0, hi = s->scanline_count;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (s->scanlines[mid] < c->scanline_y)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo == s->scanline_count || s->scanlines[lo] != c->scanline_y)
        return 0;
    /* (L->ed is NULL when no checkpoint logged an edge) */
    const ck_edge *records = c->edge_count ? log->edges + c->first_edge : NULL;
    for (size_t k = 0; k < c->edge_count; k++)
        /* no active edge there was split */
        if (!CG_INVARIANT(records[k].edge < s->prev_edge_count
                          && s->prev_map[records[k].edge] != UINT32_MAX))
            return 0;
    s->break_queue_count = 0;
    s->break_queue_full = 0;
    for (size_t k = 0; k < c->edge_count; k++) {
        uint32_t e = s->prev_map[records[k].edge];
        s->active[k] = e;
        s->x_next[e] = records[k].x_at_scanline;
        s->run_break_next[e] = (unsigned char)(records[k].flags & 1);
        s->run_open[e] = (unsigned char)(records[k].flags >> 1 & 1);
        s->run_up[e] = (unsigned char)(records[k].flags >> 2 & 1);
        s->winding_subject[e] = records[k].winding_subject;
        s->winding_clip[e] = records[k].winding_clip;
        s->run_x[e] = records[k].run_x;
        s->run_y[e] = records[k].run_y;
        if (records[k].flags & 1)
            s->break_queue_next[s->break_queue_count++] = e;
    }
    s->active_count = c->edge_count;
    s->start_scanline = lo;
    s->start_bottom = first_edge_at(s->engine->edges, s->by_bottom, s->engine->edge_count,
                                    c->scanline_y, 0);
    s->start_top = first_edge_at(s->engine->edges, s->by_top, s->engine->edge_count, c->scanline_y,
                                 1);
    return j;
}
