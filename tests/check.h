/* A small test harness: CHECK macros count passes and failures, print each
 * failure with its location, and check_finish() prints the closing line
 * "N passed, N failed" and gives the exit status.
 *
 * A test program is a list of groups of checks, each a function:
 *
 *     int main(int argc, char **argv)
 *     {
 *         check_start(argc, argv);
 *         CHECK_GROUP(octants);
 *         CHECK_GROUP(bad_input);
 *         return check_finish();
 *     }
 *
 * prints "== octants: 120 passed, 0 failed" after each group, and
 * `test_x octants` (or several names) runs only the groups named;
 * `test_x --list` lists them. */
#ifndef CG_TEST_CHECK_H
#define CG_TEST_CHECK_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static long check_passed, check_failed;
/* The groups named on the command line (none: all), and whether each ran. */
static char **check_only;
static int check_only_count, check_listing;
static unsigned long long check_only_ran; /* bit i: check_only[i] matched */

#define CHECK_REPORT(ok, ...)                                                 \
    do {                                                                      \
        if (ok) {                                                             \
            check_passed++;                                                   \
        } else {                                                              \
            check_failed++;                                                   \
            if (check_failed <= 50) {                                         \
                fprintf(stderr, "%s:%d: check failed: ", __FILE__, __LINE__); \
                fprintf(stderr, __VA_ARGS__);                                 \
                fputc('\n', stderr);                                          \
            }                                                                 \
        }                                                                     \
    } while (0)

#define CHECK(cond) CHECK_REPORT((cond), "%s", #cond)
#define CHECK_MSG(cond, ...) CHECK_REPORT((cond), __VA_ARGS__)
#define CHECK_NEAR(a, b, tol)                                                                     \
    do {                                                                                          \
        double check_a_ = (a), check_b_ = (b);                                                    \
        CHECK_REPORT(fabs(check_a_ - check_b_) <= (tol), "%s = %.17g, %s = %.17g (tolerance %g)", \
                     #a, check_a_, #b, check_b_, (double)(tol));                                  \
    } while (0)
#define CHECK_EQ_INT(a, b)                                                                      \
    do {                                                                                        \
        long long check_a_ = (long long)(a), check_b_ = (long long)(b);                         \
        CHECK_REPORT(check_a_ == check_b_, "%s = %lld, %s = %lld", #a, check_a_, #b, check_b_); \
    } while (0)

/* Reads the groups to run from the command line: names, or --list. */
static inline void check_start(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--list") == 0)
            check_listing = 1;
    }
    check_only = argv + 1;
    check_only_count = argc - 1 - check_listing;
    if (check_only_count > 64)
        check_only_count = 64;
}

/* Runs one group when it was asked for, and prints its name and counts. */
static inline void check_group(const char *name, void (*run)(void))
{
    if (check_listing) {
        printf("%s\n", name);
        return;
    }
    if (check_only_count > 0) {
        int wanted = 0;
        for (int i = 0; i < check_only_count; i++) {
            if (strcmp(check_only[i], name) == 0) {
                wanted = 1;
                check_only_ran |= 1ULL << i;
            }
        }
        if (!wanted)
            return;
    }
    long passed = check_passed, failed = check_failed;
    run();
    printf("== %s: %ld passed, %ld failed\n", name, check_passed - passed, check_failed - failed);
    fflush(stdout);
}
#define CHECK_GROUP(function) check_group(#function, function)

/* Prints the closing line; use as `return check_finish();` at the end of main.
 * A group named on the command line that does not exist is a failure. */
static inline int check_finish(void)
{
    if (check_listing)
        return 0;
    for (int i = 0; i < check_only_count; i++) {
        if (!(check_only_ran >> i & 1)) {
            fprintf(stderr, "no group of checks named '%s' (--list lists them)\n", check_only[i]);
            check_failed++;
        }
    }
    printf("%ld passed, %ld failed\n", check_passed, check_failed);
    return check_failed ? 1 : 0;
}

/* A deterministic random generator (xorshift64*) so failures reproduce. */
typedef struct check_rng {
    uint64_t state;
} check_rng;
static inline uint64_t check_rng_next(check_rng *r)
{
    r->state ^= r->state >> 12;
    r->state ^= r->state << 25;
    r->state ^= r->state >> 27;
    return r->state * 2685821657736338717ULL;
}
/* Uniform in [0, 1). */
static inline double check_rng_unit(check_rng *r)
{
    return (double)(check_rng_next(r) >> 11) * (1.0 / 9007199254740992.0);
}
static inline double check_rng_range(check_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * check_rng_unit(r);
}
/* Uniform integer in [lo, hi]. */
static inline long long check_rng_int(check_rng *r, long long lo, long long hi)
{
    return lo + (long long)(check_rng_next(r) % (uint64_t)(hi - lo + 1));
}

#endif
