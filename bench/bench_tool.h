/* Timing `cg draw --repeat` (bench_draw_script, bench_text): the processor
 * time of one run of a script by the cg tool (CG_TOOL, the build's `cg`),
 * as the tool's time with --repeat R + 1 less its time with --repeat 1,
 * divided by R, so that reading the script, starting the program and
 * writing the image cancel out.  Needs _POSIX_C_SOURCE=200809L and
 * _DEFAULT_SOURCE (fork, wait4). */
#ifndef CG_BENCH_TOOL_H
#define CG_BENCH_TOOL_H

#include "bench.h"

#include <stdio.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

/* Runs `cg draw SCRIPT -o OUT --repeat R` and returns its processor time
 * (user + system) in seconds, or -1 when it failed. */
static inline double bench_tool_seconds(const char *script, const char *out, int repeat)
{
    char times[16];
    snprintf(times, sizeof times, "%d", repeat);
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        if (!freopen("/dev/null", "w", stderr))
            _exit(127);
        execl(CG_TOOL, CG_TOOL, "draw", script, "-o", out, "--repeat", times, (char *)NULL);
        _exit(127);
    }
    int status;
    struct rusage usage;
    if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    return (double)usage.ru_utime.tv_sec + (double)usage.ru_utime.tv_usec * 1e-6
           + (double)usage.ru_stime.tv_sec + (double)usage.ru_stime.tv_usec * 1e-6;
}

/* The median over `runs` (at most 64) of the processor time of one run of
 * the script, from runs with --repeat 1 and --repeat repeat + 1; -1 when
 * the tool failed. */
static inline double bench_tool_median(const char *script, const char *out, int repeat, int runs)
{
    double samples[BENCH_MAX_RUNS];
    runs = bench_runs(runs);
    for (int i = 0; i < runs; i++) {
        double once = bench_tool_seconds(script, out, 1);
        double more = bench_tool_seconds(script, out, repeat + 1);
        if (once < 0 || more < 0)
            return -1;
        samples[i] = (more - once) / repeat;
    }
    return bench_median_of(samples, runs);
}

#endif
