/* The work units of a path-traced render, for renders spread over MPI ranks
 * and for checkpoints: the region (a tile and sample range of the picture,
 * the whole of both by default) cut into tiles of UNIT_SIDE pixels and
 * sample ranges of UNIT_SAMPLES samples.  The cut depends on the region
 * alone, never on the number of ranks, so a checkpoint written by one run
 * serves a rerun on any number of ranks.  The sums are fixed point
 * (cg/pathtrace.h), so the units add up to exactly the region's sums. */
#ifndef CG_TOOL_PATHTRACE_UNITS_H
#define CG_TOOL_PATHTRACE_UNITS_H

#include "cg/pathtrace.h"

#include <stddef.h>

/* One unit: pixels [x0, x1) x [y0, y1), samples [sample_begin, sample_end). */
typedef struct pathtrace_unit {
    int x0, y0, x1, y1, sample_begin, sample_end;
} pathtrace_unit;

/* What every unit of one render shares. */
typedef struct pathtrace_job {
    cg_trace_scene *scene;
    const cg_camera *camera;
    cg_path_options options; /* tile and sample range set per unit */
    cg_path_part *region;    /* the region's sums, added to as units finish */
    const char *checkpoint;  /* a directory keeping finished units, or NULL */
    int quiet;
} pathtrace_job;

/* The units of the region (malloc'ed; *count set); NULL when out of memory. */
pathtrace_unit *pathtrace_units_plan(const cg_path_part *region, size_t *count);

/* Three uint64 sums per pixel of the unit. */
size_t pathtrace_unit_values(pathtrace_unit unit);

/* Renders the unit into sums (pathtrace_unit_values of them, zeroed here). */
cg_status pathtrace_unit_render(const pathtrace_job *job, pathtrace_unit unit, uint64_t *sums);

/* Adds a unit's sums into the region's. */
void pathtrace_unit_add(cg_path_part *region, pathtrace_unit unit, const uint64_t *sums);

/* The unit from the checkpoint into sums: 1 when a part file of this render
 * and unit is there, 0 when not (or when the file is not such a part: a
 * warning, and the unit is rendered again). */
int pathtrace_checkpoint_load(const pathtrace_job *job, pathtrace_unit unit, uint64_t *sums);

/* Keeps a finished unit in the checkpoint directory (atomically). */
cg_status pathtrace_checkpoint_save(const pathtrace_job *job, pathtrace_unit unit,
                                    const uint64_t *sums, cg_error *err);

/* Renders every unit in this process, in order, taking finished ones from
 * the checkpoint and keeping new ones there; progress on stderr.  Returns an
 * exit status. */
int pathtrace_units_run(const char *command, const pathtrace_job *job);

#endif
