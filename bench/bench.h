/* Benchmark harness: time a piece of work as the median of several runs and
 * print result rows that bench/run.sh gathers into bench/RESULTS.md.
 *
 * A row compares cg with one peer on one case:
 *   BENCH<TAB>case<TAB>cg seconds<TAB>peer name<TAB>peer seconds<TAB>note
 * The ratio printed is peer time / cg time: above 1 means cg is faster.
 * Use peer "-" and seconds 0 for a row with no peer (a peer not installed). */
#ifndef CG_BENCH_H
#define CG_BENCH_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static inline double bench_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static inline int bench_compare(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

enum { BENCH_MAX_RUNS = 64 };

/* runs clamped to 1 .. BENCH_MAX_RUNS. */
static inline int bench_runs(int runs)
{
    return runs > BENCH_MAX_RUNS ? BENCH_MAX_RUNS : runs < 1 ? 1 : runs;
}

/* The median of samples[0 .. runs - 1] (sorted in place). */
static inline double bench_median_of(double *samples, int runs)
{
    qsort(samples, (size_t)runs, sizeof samples[0], bench_compare);
    return runs % 2 ? samples[runs / 2] : 0.5 * (samples[runs / 2 - 1] + samples[runs / 2]);
}

/* A uniform number in [0, 1) from the xorshift64 generator at *state (the
 * benchmarks' inputs are the same on every run and machine). */
static inline double bench_random(uint64_t *state)
{
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    return (double)(*state >> 11) * (1.0 / 9007199254740992.0);
}

/* Runs work(context) `runs` times (at most 64) and returns the median time
 * in seconds measured on the given clock: CLOCK_MONOTONIC for wall time,
 * CLOCK_PROCESS_CPUTIME_ID for the processor time of single-threaded work
 * (steadier when the machine is shared with other jobs). */
static inline double bench_median_clock(void (*work)(void *), void *context, int runs,
                                        clockid_t clock)
{
    double samples[BENCH_MAX_RUNS];
    runs = bench_runs(runs);
    for (int i = 0; i < runs; i++) {
        struct timespec a, b;
        clock_gettime(clock, &a);
        work(context);
        clock_gettime(clock, &b);
        samples[i] = (double)(b.tv_sec - a.tv_sec) + (double)(b.tv_nsec - a.tv_nsec) * 1e-9;
    }
    return bench_median_of(samples, runs);
}

/* Runs work(context) `runs` times (at most 64) and returns the median wall
 * time in seconds. */
static inline double bench_median(void (*work)(void *), void *context, int runs)
{
    return bench_median_clock(work, context, runs, CLOCK_MONOTONIC);
}

/* Prints one machine-readable row and a human-readable line on stderr. */
static inline void bench_row(const char *name, double cg_seconds, const char *peer,
                             double peer_seconds, const char *note)
{
    printf("BENCH\t%s\t%.6g\t%s\t%.6g\t%s\n", name, cg_seconds, peer, peer_seconds,
           note ? note : "");
    if (peer_seconds > 0)
        fprintf(stderr, "%-44s cg %10.3f ms   %-14s %10.3f ms   ratio %.2fx\n", name,
                cg_seconds * 1e3, peer, peer_seconds * 1e3, peer_seconds / cg_seconds);
    else
        fprintf(stderr, "%-44s cg %10.3f ms   (%s)\n", name, cg_seconds * 1e3,
                note ? note : "no peer");
    fflush(stdout);
}

/* Keeps the compiler from discarding a result. */
static volatile double bench_sink;

#endif
