/* Private to painter.c and painter_steps.c: the painter's list of polygons
 * and the reports cg_painter_steps gives of it. */
#ifndef CG_RENDER_PAINTER_H
#define CG_RENDER_PAINTER_H

#include "internal.h"

typedef struct painter_node {
    double xmin, xmax, ymin, ymax, zmin, zmax;
    double plane[4]; /* unit normal (toward the viewer) and offset, depth scaled */
    int prev, next;
    unsigned char moved, floating;
} painter_node;

typedef struct painter {
    const render_frame *f;
    painter_polygon *polygons;
    painter_node *nodes;
    size_t count, polygon_capacity, node_capacity, limit;
    double depth_scale;
    cg_step_fn step; /* cg_painter_steps' callback, or NULL */
    void *user;
    int stopped; /* the callback asked to stop reporting */
    size_t painted;
} painter;

/* Newell's tests of P against Q in order, up to the first that passes:
 * tests[k] is 1 when test k passed (P cannot hide Q that way), 0 when it
 * failed, -1 when it was not reached (k = 0: x extents, 1: y extents, 2: P
 * behind Q's plane, 3: Q in front of P's plane, 4: the projections). */
enum { PAINTER_TESTS = 5 };

/* How a pair P, Q was settled, for the report. */
typedef enum painter_outcome {
    PAINTER_DEPTH_APART, /* Q's depth range is nearer than P's: the list stops */
    PAINTER_DEPTH_SKIP,  /* the same, but Q was moved or split: look on */
    PAINTER_PASSED,      /* one of the five tests passed */
    PAINTER_MOVED,       /* Q moved to the front (reversed test 3 or 4) */
    PAINTER_SPLIT_P,     /* P split by Q's plane */
    PAINTER_SPLIT_Q,     /* Q split by P's plane */
    PAINTER_UNRESOLVED   /* neither can be split: the sorted order is kept */
} painter_outcome;

void painter_report_sorted(painter *pt, int list);
void painter_report_pair(painter *pt, int p, int q, const int *tests, painter_outcome outcome,
                         int far_piece, int near_piece);
void painter_report_paint(painter *pt, int p, size_t fragments);

#endif
