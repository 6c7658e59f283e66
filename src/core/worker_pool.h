/* The worker pool: cg's one way of running work on several threads.
 *
 * A pool of N workers is the calling thread (worker 0) and N - 1 threads,
 * started once and kept until the pool is freed: starting threads for every
 * frame costs, and a new thread often waits for the scheduler to move it to
 * an idle core, while a kept one wakes on the core it last ran on.
 *
 * core_worker_pool_run(pool, task, context) calls task(context, worker) on
 * the caller and on every thread that wakes while the run is open.  The
 * task divides its work into blocks claimed from atomic counters, a phase
 * at a time:
 *
 *     static void task(void *context, int worker)
 *     {
 *         job *j = context;
 *         size_t block;
 *         while (core_worker_pool_claim(&j->rows, &block)) {
 *             draw_rows(j, block);
 *             core_worker_pool_finish(j->pool, &j->rows);
 *         }
 *         core_worker_pool_wait(j->pool, &j->rows);   (then the next phase)
 *     }
 *
 * A phase waits for its blocks, never for threads: a thread that has not
 * been scheduled yet (the machine busy with other work) holds up nobody,
 * the caller may do every block alone, and a thread that wakes after the
 * caller has finished the run skips it.  Each block writes its own part of
 * the result, so the result depends on the blocks only -- never on the
 * number of threads or on which worker took which block.
 *
 * Threads that cannot be started leave their share to the others: the pool
 * then has fewer workers (core_worker_pool_workers), down to the caller
 * alone.  A NULL pool is the caller alone, too. */
#ifndef CG_CORE_WORKER_POOL_H
#define CG_CORE_WORKER_POOL_H

#include "cg/core.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stddef.h>

/* Most workers a pool may have (the caller included). */
#define CORE_WORKER_POOL_MAX 1024

typedef struct core_worker_pool core_worker_pool;

/* The work of one run, called once on each worker taking part (worker 0
 * is the caller; the others are 1 .. core_worker_pool_workers - 1). */
typedef void (*core_worker_task)(void *context, int worker);

/* How the pool starts a thread: pthread_create's contract (0 when started).
 * Tests pass one that fails. */
typedef int (*core_thread_start)(pthread_t *thread, void *(*main)(void *), void *argument);

/* A pool of `workers` workers, 1 .. CORE_WORKER_POOL_MAX (the caller and
 * workers - 1 threads): CG_OK, CG_EINVAL for a count out of range, or
 * CG_ENOMEM.  Threads that fail to start are left out. */
cg_status core_worker_pool_create(int workers, core_worker_pool **out);
/* The same, starting the threads with start. */
cg_status core_worker_pool_create_with(int workers, core_thread_start start,
                                       core_worker_pool **out);
/* Stops and joins the threads; NULL is allowed. */
void core_worker_pool_free(core_worker_pool *pool);
/* The workers the pool has: 1 (the caller) plus the threads started; 1
 * for NULL. */
int core_worker_pool_workers(const core_worker_pool *pool);

/* Runs task on the caller (worker 0) and on the pool's threads that wake in
 * time, and returns once the caller's call has returned and every thread
 * that took part has left the task: every block claimed during the run is
 * then done.  One run at a time per pool. */
void core_worker_pool_run(core_worker_pool *pool, core_worker_task task, void *context);

/* ---- phases: blocks claimed from a counter, counted when done ------------ */

typedef struct core_worker_phase {
    atomic_size_t next; /* the next block to claim */
    atomic_size_t done; /* blocks finished */
    size_t blocks;      /* blocks in the phase */
} core_worker_phase;

/* A phase of `blocks` blocks, none claimed (before the run starts). */
void core_worker_pool_phase_init(core_worker_phase *phase, size_t blocks);

/* Claims the next block of the phase: 1 with *block set (each block is
 * claimed exactly once over all workers), 0 when none is left. */
static inline int core_worker_pool_claim(core_worker_phase *phase, size_t *block)
{
    size_t claimed = atomic_fetch_add(&phase->next, 1);
    if (claimed >= phase->blocks)
        return 0;
    *block = claimed;
    return 1;
}

/* Counts one claimed block done and returns how many are done; the last one
 * wakes the workers waiting for the phase. */
size_t core_worker_pool_finish(core_worker_pool *pool, core_worker_phase *phase);

/* Waits until every block of the phase is done: called once claiming has
 * failed, so only blocks other workers are working on can be missing. */
void core_worker_pool_wait(core_worker_pool *pool, core_worker_phase *phase);

#endif
