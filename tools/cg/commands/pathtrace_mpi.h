/* `mpirun -np N cg render ... --algorithm pathtrace`: the render spread over
 * Open MPI ranks.  Rank 0 hands out the units (pathtrace_units.h) one at a
 * time to whichever rank asks, adds the sums that come back, keeps them in
 * the checkpoint, and writes the output; ranks 1..N-1 render.  The fixed-
 * point sums make the result byte-identical to a one-process render. */
#ifndef CG_TOOL_PATHTRACE_MPI_H
#define CG_TOOL_PATHTRACE_MPI_H

#include "pathtrace_units.h"

/* The number of ranks the process was started among, from the launcher's
 * environment (Open MPI's OMPI_COMM_WORLD_SIZE, or PMI_SIZE); 1 outside a
 * launcher. */
int pathtrace_mpi_ranks(void);

/* True when cg was built with Open MPI. */
int pathtrace_mpi_available(void);

/* Renders the job's region over the ranks.  On rank 0 *writer is set to 1
 * and the region's sums are complete when CLI_OK returns; other ranks
 * return with *writer 0.  Returns an exit status. */
int pathtrace_mpi_render(const char *command, const pathtrace_job *job, int *writer);

/* Ends MPI (after rank 0 has written its output). */
void pathtrace_mpi_finish(void);

#endif
