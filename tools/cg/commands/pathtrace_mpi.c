/* The path tracer over Open MPI ranks (see pathtrace_mpi.h).
 *
 *   rank 0                         rank k (1..N-1)
 *     <- READY ------------------------ asks for work
 *     -- WORK (unit a) --------------->
 *     -- WORK (unit b) --------------->  renders a
 *     <- RESULT (a, sums) ------------  renders b
 *     -- WORK (unit c) --------------->  ...
 *     -- WORK (-1: no more) ---------->  stops, once it has nothing left
 *
 * Each rendering rank holds up to AHEAD units, so that the next one is
 * already there when it finishes one, whatever rank 0's latency.  Units go
 * out in plan order to whichever rank returns one first, so fast ranks take
 * more.  A rank that dies ends the job (Open MPI's default error handling):
 * mpirun exits non-zero and no output is written, as rank 0 writes only
 * after every unit is in. */
#include "pathtrace_mpi.h"

#include "cli.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int pathtrace_mpi_ranks(void)
{
    static const char *const names[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"};
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        const char *v = getenv(names[i]);
        if (v && atoi(v) > 0)
            return atoi(v);
    }
    return 1;
}

#ifndef CG_HAVE_MPI

int pathtrace_mpi_available(void)
{
    return 0;
}

int pathtrace_mpi_render(const char *command, const pathtrace_job *job, int *writer)
{
    (void)job;
    *writer = 0;
    return cli_fail("%s: this cg was built without Open MPI (install libopenmpi-dev and "
                    "rebuild), so it cannot render over %d ranks; render parts with --tile or "
                    "--sample-range and add them with cg merge instead",
                    command, pathtrace_mpi_ranks());
}

void pathtrace_mpi_finish(void) {}

#else

#include <mpi.h>
#include <time.h>

enum { TAG_WORK = 1, TAG_RESULT = 2, AHEAD = 2 };

int pathtrace_mpi_available(void)
{
    return 1;
}

/* Waits for a message without spinning: Open MPI's blocking receive polls
 * at full speed, which would take a core from the rendering ranks. */
static void wait_for_message(int tag, MPI_Status *status)
{
    int ready = 0;
    struct timespec pause = {0, 500000};
    for (;;) {
        MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &ready, status);
        if (ready)
            return;
        nanosleep(&pause, NULL);
    }
}

static size_t largest_unit(const pathtrace_unit *units, size_t count)
{
    size_t largest = 0;
    for (size_t k = 0; k < count; k++)
        if (pathtrace_unit_values(units[k]) > largest)
            largest = pathtrace_unit_values(units[k]);
    return largest;
}

static void *allocate_or_abort(const char *command, size_t bytes)
{
    void *p = calloc(bytes ? bytes : 1, 1);
    if (!p) {
        fprintf(stderr, "%s: out of memory\n", command);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    return p;
}

/* Tops the rank up to AHEAD units, or stops it when nothing is left for it
 * and it holds none; returns 1 when it was stopped. */
static int hand_out(const char *finished, size_t count, size_t *next, int rank, int *holding)
{
    do {
        while (*next < count && finished[*next])
            (*next)++;
        long work = *next < count ? (long)(*next)++ : -1;
        if (work < 0 && *holding > 0)
            return 0;
        MPI_Send(&work, 1, MPI_LONG, rank, TAG_WORK, MPI_COMM_WORLD);
        if (work < 0)
            return 1;
        (*holding)++;
    } while (*holding < AHEAD);
    return 0;
}

/* Rank 0: takes finished units from the checkpoint, hands out the others,
 * adds the results into the region and keeps them in the checkpoint. */
static int scheduler(const char *command, const pathtrace_job *job, const pathtrace_unit *units,
                     size_t count, int ranks)
{
    size_t reused = 0, done = 0, next = 0;
    uint64_t *message = allocate_or_abort(command, (largest_unit(units, count) + 1) * 8);
    char *finished = allocate_or_abort(command, count);
    int *holding = allocate_or_abort(command, (size_t)ranks * sizeof(int));
    for (size_t k = 0; job->checkpoint && k < count; k++)
        if (pathtrace_checkpoint_load(job, units[k], message + 1)) {
            pathtrace_unit_add(job->region, units[k], message + 1);
            finished[k] = 1;
            reused++;
            done++;
        }
    double start = cli_now();
    for (int stopped = 0; stopped < ranks - 1;) {
        MPI_Status st;
        wait_for_message(TAG_RESULT, &st);
        int n;
        MPI_Get_count(&st, MPI_UINT64_T, &n);
        MPI_Recv(message, n, MPI_UINT64_T, st.MPI_SOURCE, TAG_RESULT, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        if (message[0] != UINT64_MAX) {
            pathtrace_unit u = units[message[0]];
            pathtrace_unit_add(job->region, u, message + 1);
            holding[st.MPI_SOURCE]--;
            cg_error err;
            if (job->checkpoint && pathtrace_checkpoint_save(job, u, message + 1, &err) != CG_OK) {
                fprintf(stderr, "%s: %s\n", command, err.message);
                MPI_Abort(MPI_COMM_WORLD, 1);
            }
            done++;
            if (!job->quiet && (done == count || done % 64 == 0))
                fprintf(stderr, "%s: pathtrace: %zu/%zu units over %d ranks, %.2f s\n", command,
                        done, count, ranks, cli_now() - start);
        }
        stopped += hand_out(finished, count, &next, st.MPI_SOURCE, &holding[st.MPI_SOURCE]);
    }
    if (job->checkpoint && !job->quiet)
        fprintf(stderr, "%s: pathtrace: %zu of %zu units from the checkpoint\n", command, reused,
                count);
    free(holding);
    free(finished);
    free(message);
    return CLI_OK;
}

/* A rendering rank.  Results go out with MPI_Isend from two buffers in
 * turn, so that a large result (sent by rendezvous, when rank 0 gets to it)
 * never keeps the rank from rendering the next unit. */
static void worker(const char *command, const pathtrace_job *job, const pathtrace_unit *units,
                   size_t count)
{
    size_t largest = largest_unit(units, count);
    uint64_t *buffers[2] = {allocate_or_abort(command, (largest + 1) * 8),
                            allocate_or_abort(command, (largest + 1) * 8)};
    MPI_Request sent[2] = {MPI_REQUEST_NULL, MPI_REQUEST_NULL};
    uint64_t ready = UINT64_MAX; /* asks for work, no result yet */
    MPI_Send(&ready, 1, MPI_UINT64_T, 0, TAG_RESULT, MPI_COMM_WORLD);
    for (int turn = 0;; turn ^= 1) {
        long work;
        MPI_Recv(&work, 1, MPI_LONG, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (work < 0 || (size_t)work >= count)
            break;
        uint64_t *message = buffers[turn];
        MPI_Wait(&sent[turn], MPI_STATUS_IGNORE);
        if (pathtrace_unit_render(job, units[work], message + 1) != CG_OK) {
            fprintf(stderr, "%s: path tracing failed\n", command);
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
        message[0] = (uint64_t)work;
        int length = 1 + (int)pathtrace_unit_values(units[work]);
        MPI_Isend(message, length, MPI_UINT64_T, 0, TAG_RESULT, MPI_COMM_WORLD, &sent[turn]);
    }
    MPI_Waitall(2, sent, MPI_STATUSES_IGNORE);
    free(buffers[0]);
    free(buffers[1]);
}

int pathtrace_mpi_render(const char *command, const pathtrace_job *job, int *writer)
{
    int ranks, rank;
    MPI_Init(NULL, NULL);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    *writer = rank == 0;
    size_t count = 0;
    pathtrace_unit *units = pathtrace_units_plan(job->region, &count);
    if (!units) {
        fprintf(stderr, "%s: out of memory\n", command);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    int status = CLI_OK;
    if (ranks == 1) /* a singleton: this rank does it all */
        status = pathtrace_units_run(command, job);
    else if (rank == 0)
        status = scheduler(command, job, units, count, ranks);
    else
        worker(command, job, units, count);
    free(units);
    return status;
}

void pathtrace_mpi_finish(void)
{
    int started = 0;
    MPI_Initialized(&started);
    if (started)
        MPI_Finalize();
}

#endif
