/* Boolean operations on polygon sets by a sweep over scanbeams, in the manner
 * of Vatti (11.2.2).
 *
 * Every ring of both operands is a closed path on a 64-bit integer grid.  The
 * sweep visits the scanlines (the distinct y of the vertices) from bottom to
 * top; between two scanlines (a scanbeam) the active edges are ordered by x.
 *
 *  1. Intersections.  Two edges whose order at the top of a beam is the
 *     reverse of their order at the bottom cross inside the beam; an edge
 *     that passes through a scanline exactly where another edge or a
 *     horizontal edge is also needs a vertex there.  Such points are rounded
 *     to the grid and the edges split there (both pieces keep the path
 *     closed).  Rounding can move an edge by half a unit, so the sweep is
 *     repeated until a pass finds nothing to split (two passes in practice);
 *     from the second pass on, edges through the pixel of a rounded point are
 *     split there too (snap rounding), which settles nearly parallel fans.
 *  2. Classification.  In the final pass no two edges cross inside a beam,
 *     so walking a beam from left to right and summing the windings of the
 *     subject's and the clip's edges tells, for every gap between edges,
 *     whether it is in the result (fill rule per operand, then the
 *     operation).  An edge (or a group of coincident edges) with the result
 *     on one side only is a piece of the result's boundary, directed so the
 *     result is on its left; the pieces of one edge over consecutive beams
 *     join into a run.  On a scanline the result can only change from below
 *     to above under horizontal edges; there the horizontal boundary pieces
 *     come from comparing the two sides.
 *  3. Assembly.  The directed pieces meet only at grid points; they are
 *     linked into rings taking, at a vertex with several ways out, the
 *     sharpest left turn, which keeps rings that touch at a point apart.
 *     Counter-clockwise rings are outer contours, clockwise ones holes, each
 *     hole going to the smallest outer contour around it.
 *
 * All decisions are exact (128-bit integer arithmetic, with a double filter
 * for speed), so the result does not depend on rounding luck.
 *
 * This file loads the operands and runs the passes; the steps are in
 * boolean_pairs.c (the crossings of small inputs, pair by pair),
 * boolean_prepare.c (a pass's arrays and orders), boolean_sweep.c (the
 * full sweep), boolean_light.c (the light sweep), boolean_scanline.c (their
 * out-of-line steps on a scanline; boolean_scan.h holds what the two
 * share), boolean_checkpoint.c (where a pass after splits resumes),
 * boolean_split.c and boolean_snap.c (snap rounding and splitting),
 * boolean_assemble.c and boolean_pinch.c (rings and holes),
 * boolean_sort.c, and boolean_double.c (the double API);
 * boolean_engine.h holds what they share. */
#include "boolean_engine.h"
#include "../../core/sort.h"

int boolean_add_edge(engine *g, int64_t x0, int64_t y0, int64_t x1, int64_t y1, int op,
                     uint32_t orig)
{
    if (y0 == y1) {
        if (x0 == x1)
            return 1;
        if (!room_for_horizontal(g))
            return 0;
        g->horizontals[g->horizontal_count++] = (horizontal_edge){y0, x0 < x1 ? x0 : x1,
                                                                  x0 < x1 ? x1 : x0};
        return 1;
    }
    if (!room_for_edges(g, 1))
        return 0;
    edge *e = &g->edges[g->edge_count++];
    if (y0 < y1) {
        *e = (edge){x0, y0, x1, y1, 0, orig, -1, (uint8_t)op};
    } else {
        *e = (edge){x1, y1, x0, y0, 0, orig, 1, (uint8_t)op};
    }
    e->slope = (double)(e->x_top - e->x_bottom) / (double)(e->y_top - e->y_bottom);
    return 1;
}

#define MAX_PASSES 64
/* the light sweep's cost per edge, in active edges looked at by the full
 * sweep (the pass driver tries it first when the full sweep was dearer) */
#define LIGHT_COST 16
/* Complete snap rounding (Hobby): the pixels of the edges' ends, of the
 * rounded crossings and of the grid points where edges meet are all hot, and
 * every edge is snapped to each one it passes through; a verifying pass then
 * finds nothing to split.  On dense crossings the iterated rounding instead
 * makes new ones, pass after pass.  A pass snaps completely, once, when it
 * looked at DENSE_VISITS active edges per edge (long active lists: another
 * whole pass would be dear), or when the first pass's crossings are denser
 * than one in DENSE_AREA grid cells (a coarse grid). */
#ifndef DENSE_AREA
#define DENSE_AREA 64
#endif
#ifndef DENSE_VISITS
#define DENSE_VISITS 200
#endif

static int cmp_band(const void *a, const void *b)
{
    const int64_t *p = a, *q = b;
    return (p[0] > q[0]) - (p[0] < q[0]);
}

/* A block a call held (arr, room for cap) given back to a workspace slot
 * (slot, room for *slot_cap): the larger of the two stays, the other is
 * freed; the one kept is returned. */
static void *keep_larger(void *slot, size_t *slot_cap, void *arr, size_t cap)
{
    if (cap < *slot_cap) {
        free(arr);
        return slot;
    }
    free(slot);
    *slot_cap = cap;
    return arr;
}

/* Whether the first pass's split points are dense on the grid: more than
 * one in DENSE_AREA units of their bounds.  Rounding them then makes new
 * crossings pass after pass; complete snap rounding settles them at once. */
static int dense_crossings(const engine *g)
{
    if (g->split_count < 1024)
        return 0;
    int64_t x0 = g->splits[0].x, x1 = x0, y0 = g->splits[0].y, y1 = y0;
    for (size_t k = 1; k < g->split_count; k++) {
        x0 = g->splits[k].x < x0 ? g->splits[k].x : x0;
        x1 = g->splits[k].x > x1 ? g->splits[k].x : x1;
        y0 = g->splits[k].y < y0 ? g->splits[k].y : y0;
        y1 = g->splits[k].y > y1 ? g->splits[k].y : y1;
    }
    return ((double)(x1 - x0) + 1) * ((double)(y1 - y0) + 1) < DENSE_AREA * (double)g->split_count;
}

/* What the passes hand on to each other. */
typedef struct passes {
    engine *g;
    sweep s;            /* the sweep of the current pass */
    carry c;            /* the last pass's orders and where its edges went */
    ck_log logs[2];     /* this pass's checkpoints, the last pass's */
    int current_log;    /* this pass's, in logs[] */
    int can_resume;     /* the next pass may resume from logs[current_log] */
    int snapped;        /* a pass snapped completely (once is enough) */
    size_t visits;      /* active edges looked at by the last full sweep */
    size_t swept_edges; /* its edges */
    /* the y ranges of the edges split by the last pass (merged) */
    int64_t (*bands)[2];
    size_t band_count;
    /* the first pass's pieces (when it classified), and the ranges of them
     * the next pass takes */
    piece *saved;
    size_t saved_capacity;
    size_t (*ranges)[2];
    /* small inputs: the sweep's block (and the assembly's, the splits') on
     * the stack, and the orders kept between passes */
    max_align_t block_small[8192 / sizeof(max_align_t)];
    uint32_t carry_small[3 * 64];
} passes;

static void passes_init(passes *p, engine *g)
{
    memset(p, 0, offsetof(passes, block_small));
    p->g = g;
    p->s.engine = g;
    p->s.block = p->s.block_small = p->block_small;
    p->s.block_size = sizeof p->block_small;
    p->c.block_small = p->carry_small;
    p->c.by_bottom = p->carry_small;
    p->c.by_top = p->carry_small + 64;
    p->c.map = p->carry_small + 128;
    p->c.capacity = 64;
}

static void passes_free(passes *p)
{
    engine *g = p->g;
    sweep *s = &p->s;
    if (s->block != s->block_small) {
        if (g->workspace)
            g->workspace->block = keep_larger(g->workspace->block, &g->workspace->block_size,
                                              s->block, s->block_size);
        else
            free(s->block);
    }
    for (int k = 0; k < 2; k++) {
        free(p->logs[k].checkpoints);
        free(p->logs[k].edges);
    }
    free(p->saved);
    free(p->ranges);
    free(p->bands);
    if (p->c.by_bottom != p->c.block_small)
        free(p->c.by_bottom); /* (and by_top, map) */
    free(p->c.scanlines);
    free(p->c.split_ys);
}

/* What a step of a pass leads to. */
enum { PASS_FAILED, PASS_DONE, PASS_GO_ON };

/* The light sweep, and the assembly when it finds the pass final
 * (PASS_DONE, *st set); PASS_GO_ON when something needs a split (the full
 * sweep then runs), PASS_FAILED when out of memory. */
static int light_pass(passes *p, cg_polygon_set64 *result, cg_status *st)
{
    engine *g = p->g;
    sweep *s = &p->s;
    g->piece_count = 0;
    s->classify = 1;
    s->changed = 0;
    int r = boolean_light_sweep(s);
    if (!r)
        return PASS_FAILED;
    if (r == 1) {
        *st = boolean_assemble(g, result, &s->block, &s->block_size, s->block_small) ? CG_OK
                                                                                     : CG_ENOMEM;
        return PASS_DONE;
    }
    /* something to split: start over with the full sweep */
    size_t edge_room = g->edge_count ? g->edge_count : 1;
    memset(s->run_open, 0, 4 * edge_room); /* and run_up, run_break, run_break_next */
    g->split_count = 0;
    return PASS_GO_ON;
}

/* The full sweep set to start at the last pass's checkpoint below its
 * lowest split edge, with the pieces emitted below it (kept in the engine,
 * or, when the first pass's pieces are saved, taken as a range of them). */
static void resume_from_checkpoint(passes *p)
{
    engine *g = p->g;
    sweep *s = &p->s;
    const ck_log *last = &p->logs[p->current_log ^ 1];
    s->prev_map = p->c.map;
    s->prev_edge_count = p->c.edge_count;
    s->prev_checkpoint = boolean_ck_load(s, last, 0, p->bands[0][0]);
    size_t below = s->prev_checkpoint ? last->checkpoints[s->prev_checkpoint - 1].piece_count : 0;
    if (!p->saved) {
        g->piece_count = below;
        return;
    }
    /* its pieces stay where they are; this pass emits only those of the
     * bands, and notes the ranges it takes */
    s->prev_log = last;
    s->bands = (const int64_t(*)[2])p->bands;
    s->band_count = p->band_count;
    s->taken_ranges = p->ranges;
    if (below) {
        p->ranges[0][0] = 0;
        p->ranges[0][1] = below;
        s->taken_count = 1;
    }
}

/* The pieces of the saved ranges taken, then this pass's after them, as the
 * engine's pieces: 0 when out of memory. */
static int take_saved_pieces(passes *p)
{
    engine *g = p->g;
    const sweep *s = &p->s;
    piece *saved = p->saved;
    size_t w = 0;
    for (size_t k = 0; k < s->taken_count; k++) {
        memmove(saved + w, saved + p->ranges[k][0],
                (p->ranges[k][1] - p->ranges[k][0]) * sizeof *saved);
        w += p->ranges[k][1] - p->ranges[k][0];
    }
    if (!boolean_room((void **)&p->saved, &p->saved_capacity, w, g->piece_count, sizeof *p->saved,
                      NULL))
        return 0;
    saved = p->saved;
    if (g->piece_count)
        memcpy(saved + w, g->pieces, g->piece_count * sizeof *saved);
    if (g->pieces != g->pieces_small)
        free(g->pieces);
    g->pieces = saved;
    g->piece_capacity = p->saved_capacity;
    g->piece_count += w;
    p->saved = NULL;
    return 1;
}

/* The y ranges of the edges this pass split, merged into bands (one band
 * from the lowest bottom when the pass stopped classifying: only that is
 * of use then); after the first pass, its pieces saved for the next to
 * take the ranges between the bands.  0 when out of memory. */
static int note_split_bands(passes *p, int pass)
{
    engine *g = p->g;
    const sweep *s = &p->s;
    size_t nb = s->classify ? g->split_count : 1;
    int64_t(*bands)[2] = malloc(nb * sizeof *bands);
    if (!bands)
        return 0;
    p->bands = bands;
    bands[0][0] = INT64_MAX;
    bands[0][1] = INT64_MIN;
    for (size_t i = 0; i < g->split_count; i++) {
        const edge *e = &g->edges[g->splits[i].edge];
        size_t k = nb == 1 ? 0 : i;
        bands[k][0] = nb == 1 && bands[0][0] < e->y_bottom ? bands[0][0] : e->y_bottom;
        bands[k][1] = nb == 1 && bands[0][1] > e->y_top ? bands[0][1] : e->y_top;
    }
    core_sort(bands, nb, sizeof *bands, cmp_band);
    size_t band_count = 0;
    for (size_t i = 0; i < nb; i++) {
        if (band_count && bands[i][0] <= bands[band_count - 1][1]) {
            if (bands[i][1] > bands[band_count - 1][1])
                bands[band_count - 1][1] = bands[i][1];
        } else {
            bands[band_count][0] = bands[i][0];
            bands[band_count][1] = bands[i][1];
            band_count++;
        }
    }
    p->band_count = band_count;
    p->can_resume = 1;
    if (pass != 0 || !s->classify || !g->piece_count)
        return 1;
    p->ranges = malloc((band_count + 1) * sizeof *p->ranges);
    if (p->ranges && g->pieces == g->pieces_small) { /* (saved is freed) */
        piece *q = malloc(g->piece_capacity * sizeof *q);
        if (q)
            memcpy(q, g->pieces, g->piece_count * sizeof *q);
        else {
            free(p->ranges);
            p->ranges = NULL;
        }
        g->pieces = q ? q : g->pieces;
    }
    if (p->ranges) {
        p->saved = g->pieces; /* (the next pass starts a new array) */
        p->saved_capacity = g->piece_capacity;
        g->pieces = NULL;
        g->piece_capacity = 0;
        g->piece_count = 0;
    }
    return 1;
}

/* One full pass (after the light sweep, when that was tried): PASS_DONE
 * when it was final (the result assembled, *st set), PASS_GO_ON when it
 * split edges (the next pass verifies), PASS_FAILED when out of memory or
 * (with *st set) out of range. */
static int full_pass(passes *p, int pass, int light, cg_polygon_set64 *result, cg_status *st)
{
    engine *g = p->g;
    sweep *s = &p->s;
    g->piece_count = 0;
    s->classify = 1;
    s->changed = 0;
    /* later passes round on the pieces themselves, which settles whatever
     * the input-line rounding could not */
    s->use_input_lines = pass < 8;
    s->record_meets = pass == 0;
    if (p->can_resume && !light && p->band_count)
        resume_from_checkpoint(p);
    ck_log *log = &p->logs[p->current_log];
    log->checkpoint_count = log->edge_count = 0;
    log->budget = g->edge_count / 2 + 256; /* (a small block: no fresh pages) */
    /* (later passes are nearly always the last; small inputs gain less
     * than the checkpoints cost) */
    s->log = pass == 0 && g->edge_count >= 128 ? log : NULL;
    s->checkpoint_visits = 0;
    int r = boolean_run_sweep(s);
    if (r <= 0) {
        if (r < 0)
            *st = CG_ERANGE;
        return PASS_FAILED;
    }
    /* (a pass that started at a checkpoint looked at fewer edges than a
     * whole one would have: the last count stands unless larger) */
    if (!s->start_scanline || s->visits > p->visits)
        p->visits = s->visits;
    p->swept_edges = g->edge_count;
    if (p->saved && s->prev_log && s->taken_count && !take_saved_pieces(p))
        return PASS_FAILED;
    free(p->saved);
    p->saved = NULL;
    if (!s->changed) {
        *st = boolean_assemble(g, result, &s->block, &s->block_size, s->block_small) ? CG_OK
                                                                                     : CG_ENOMEM;
        return PASS_DONE;
    }
    int snap_now = !p->snapped
                   && (s->visits >= DENSE_VISITS * p->swept_edges
                       || (pass == 0 && dense_crossings(g)));
    if (pass >= 1 && !snap_now && !boolean_add_hot_pixel_splits(g, 0))
        return PASS_FAILED;
    free(p->bands);
    p->bands = NULL;
    p->band_count = 0;
    p->can_resume = 0;
    log->end_piece_count = g->piece_count;
    free(p->ranges);
    p->ranges = NULL;
    /* (else there is nothing to resume from; nor after complete snap
     * rounding, which splits nearly every edge) */
    if (log->checkpoint_count && !snap_now && !note_split_bands(p, pass))
        return PASS_FAILED;
    p->current_log ^= 1;
    carry *c = &p->c;
    if (!boolean_carry_keep(c, s)
        || !(snap_now ? boolean_snap_complete(g, c->map, &c->kept, s->block, s->block_size)
                      : boolean_apply_splits(g, c->map, &c->kept, s->block, s->block_size)))
        return PASS_FAILED;
    if (snap_now) {
        c->horizontals_sorted = 0; /* (its horizontal edges are put in order again) */
        p->snapped = 1;
    }
    c->valid = 1;
    if (g->edge_count > UINT32_MAX / 2) {
        *st = CG_ERANGE; /* too many pieces for 32-bit edge numbers */
        return PASS_FAILED;
    }
    return PASS_GO_ON;
}

static cg_status run_passes(engine *g, cg_polygon_set64 *result)
{
    passes state, *p = &state; /* (on the stack: small inputs need no allocation) */
    passes_init(p, g);
    cg_status st = CG_ENOMEM;
    sweep *s = &p->s;
    int paired = g->edge_count + g->horizontal_count <= PAIRS_MAX_EDGES;
    if (paired) {
        uint32_t map[PAIRS_MAX_EDGES];
        size_t kept;
        if (!boolean_add_pair_splits(g)
            || !boolean_apply_splits(g, map, &kept, s->block, s->block_size))
            return CG_ENOMEM;
    }
    if (g->workspace && g->workspace->block_size > s->block_size) {
        /* (the workspace's block, taken) */
        s->block = g->workspace->block;
        s->block_size = g->workspace->block_size;
        g->workspace->block = NULL;
        g->workspace->block_size = 0;
    }
    /* (the pairs' splits stand for the first pass) */
    for (int pass = paired;; pass++) {
        if (pass == MAX_PASSES) {
            st = CG_ERANGE;
            break;
        }
        /* After the first pass, most passes find nothing more to split.
         * The light sweep costs about LIGHT_COST active edges' worth of work
         * per edge; it is tried first when the full sweep was dearer. */
        int light = pass >= 1 && p->visits > LIGHT_COST * p->swept_edges;
        boolean_sweep_reset(s);
        if (!boolean_sweep_alloc(s, light) || !boolean_sweep_sort(s, &p->c))
            break;
        int next = light ? light_pass(p, result, &st) : PASS_GO_ON;
        if (next == PASS_GO_ON)
            next = full_pass(p, pass, light, result, &st);
        if (next != PASS_GO_ON)
            break;
    }
    passes_free(p);
    return st;
}

static cg_status load(engine *g, const cg_polygon_set64 *set, int op)
{
    if (!set)
        return CG_OK;
    if (set->ring_count && (!set->ring_start || (!set->points && set->point_count)))
        return CG_EINVAL; /* (rings with no points need no point array) */
    for (size_t r = 0; r < set->ring_count; r++) {
        size_t a = set->ring_start[r], b = set->ring_start[r + 1];
        if (b < a || b > set->point_count)
            return CG_EINVAL;
        for (size_t i = a; i < b; i++) {
            cg_point64 p = set->points[i];
            if (p.x > CG_CLIP_MAX_COORD || p.x < -CG_CLIP_MAX_COORD || p.y > CG_CLIP_MAX_COORD
                || p.y < -CG_CLIP_MAX_COORD)
                return CG_ERANGE;
        }
        if (b - a < 2)
            continue;
        /* room for the ring's edges at once, then each written in place
         * (horizontal ones go to g->horizontals) */
        if (!room_for_edges(g, b - a))
            return CG_ENOMEM;
        /* (held here: the byte stores below would make them be read
         * again) */
        const cg_point64 *pts = set->points;
        edge *edges = g->edges;
        size_t edge_count = g->edge_count;
        for (size_t i = a; i < b; i++) {
            cg_point64 p = pts[i], q = pts[i + 1 < b ? i + 1 : a];
            if (p.y == q.y) { /* (to g->horizontals) */
                if (!boolean_add_edge(g, p.x, p.y, q.x, q.y, op, NO_ORIG))
                    return CG_ENOMEM;
                continue;
            }
            edge *e = &edges[edge_count++];
            int up = p.y < q.y;
            cg_point64 lo = up ? p : q, hi = up ? q : p;
            e->x_bottom = lo.x;
            e->y_bottom = lo.y;
            e->x_top = hi.x;
            e->y_top = hi.y;
            e->input_edge = NO_ORIG;
            e->winding = (int8_t)(up ? -1 : 1);
            e->operand = (uint8_t)op;
            e->slope = (double)(hi.x - lo.x) / (double)(hi.y - lo.y);
        }
        g->edge_count = edge_count;
    }
    return CG_OK;
}

cg_clip_workspace *cg_clip_workspace_create(void)
{
    return calloc(1, sizeof(cg_clip_workspace));
}

void cg_clip_workspace_free(cg_clip_workspace *ws)
{
    if (!ws)
        return;
    free(ws->block);
    free(ws->edges);
    free(ws->pieces);
    free(ws);
}

cg_status cg_clip_boolean64(cg_clip_op op, const cg_polygon_set64 *subject,
                            cg_clip_fill subject_fill, const cg_polygon_set64 *clip,
                            cg_clip_fill clip_fill, cg_polygon_set64 *result)
{
    return cg_clip_boolean64_ws(NULL, op, subject, subject_fill, clip, clip_fill, result);
}

cg_status cg_clip_boolean64_ws(cg_clip_workspace *ws, cg_clip_op op,
                               const cg_polygon_set64 *subject, cg_clip_fill subject_fill,
                               const cg_polygon_set64 *clip, cg_clip_fill clip_fill,
                               cg_polygon_set64 *result)
{
    if (!result)
        return CG_EINVAL;
    if (result == subject || result == clip) {
        /* the result replaces an operand: computed beside it first */
        cg_polygon_set64 own = {0};
        cg_status st = cg_clip_boolean64_ws(ws, op, subject, subject_fill, clip, clip_fill, &own);
        cg_polygon_set64_clear(result);
        *result = own;
        return st;
    }
    /* emptied, its arrays kept: a result passed call after call is not
     * allocated again */
    result->point_count = result->ring_count = result->polygon_count = 0;
    if ((unsigned)op > CG_CLIP_XOR || (unsigned)subject_fill > CG_CLIP_NEGATIVE
        || (unsigned)clip_fill > CG_CLIP_NEGATIVE)
        return CG_EINVAL;
    engine g;
    memset(&g, 0, sizeof g);
    g.workspace = ws;
    g.operation = op;
    g.fill[0] = subject_fill;
    g.fill[1] = clip_fill;
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            g.in_result[a * 2 + b] = (unsigned char)(op == CG_CLIP_INTERSECTION ? a && b
                                                     : op == CG_CLIP_UNION      ? a || b
                                                     : op == CG_CLIP_DIFFERENCE ? a && !b
                                                                                : a != b);
    for (int a = 0; a < 5; a++)
        for (int b = 0; b < 5; b++)
            g.in_result_near[a][b] = (unsigned char)inside_rule(&g, a - 2, b - 2);
    /* room for the input's edges and some pieces: no regrowth; on small
     * inputs the edges, split points and pieces start on the stack (most
     * calls then need no allocation for them) */
    edge e_small[96];
    split_point s_small[32];
    piece p_small[64];
    size_t npts = (subject ? subject->point_count : 0) + (clip ? clip->point_count : 0);
    if (npts && npts < UINT32_MAX / 4) {
        g.edge_capacity = npts + npts / 4 + 64;
        if (g.edge_capacity <= sizeof e_small / sizeof e_small[0]) {
            g.edges = g.edges_small = e_small;
            g.edge_capacity = sizeof e_small / sizeof e_small[0];
            g.splits = g.splits_small = s_small;
            g.split_capacity = sizeof s_small / sizeof s_small[0];
            g.pieces = g.pieces_small = p_small;
            g.piece_capacity = sizeof p_small / sizeof p_small[0];
        } else if (ws && ws->edge_capacity >= g.edge_capacity) { /* (the workspace's, taken) */
            g.edges = ws->edges;
            g.edge_capacity = ws->edge_capacity;
            ws->edges = NULL;
            ws->edge_capacity = 0;
        } else {
            g.edges = malloc(g.edge_capacity * sizeof *g.edges);
            if (!g.edges)
                g.edge_capacity = 0;
        }
        if (ws && !g.pieces_small && ws->pieces) {
            g.pieces = ws->pieces;
            g.piece_capacity = ws->piece_capacity;
            ws->pieces = NULL;
            ws->piece_capacity = 0;
        }
    }
    cg_status st = load(&g, subject, 0);
    if (st == CG_OK)
        st = load(&g, clip, 1);
    if (st == CG_OK && g.edge_count > UINT32_MAX / 4)
        st = CG_ERANGE;
    if (st == CG_OK)
        st = run_passes(&g, result);
    if (st != CG_OK)
        cg_polygon_set64_clear(result);
    /* the edges and pieces back to the workspace, or freed */
    if (g.edges != g.edges_small) {
        if (ws)
            ws->edges = keep_larger(ws->edges, &ws->edge_capacity, g.edges, g.edge_capacity);
        else
            free(g.edges);
    }
    free(g.horizontals);
    free(g.meets);
    if (g.splits != g.splits_small)
        free(g.splits);
    if (g.pieces != g.pieces_small) {
        if (ws)
            ws->pieces = keep_larger(ws->pieces, &ws->piece_capacity, g.pieces, g.piece_capacity);
        else
            free(g.pieces);
    }
    if (g.input_edges != g.input_edges_small)
        free(g.input_edges);
    return st;
}
