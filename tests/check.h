/* A small test harness: CHECK macros count passes and failures, print each
 * failure with its location, and check_finish() prints the closing line
 * "N passed, N failed" and gives the exit status. */
#ifndef CG_TEST_CHECK_H
#define CG_TEST_CHECK_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static long check_passed, check_failed;

#define CHECK_REPORT(ok, ...)                                                  \
    do {                                                                       \
        if (ok) {                                                              \
            check_passed++;                                                    \
        } else {                                                               \
            check_failed++;                                                    \
            if (check_failed <= 50) {                                          \
                fprintf(stderr, "%s:%d: check failed: ", __FILE__, __LINE__); \
                fprintf(stderr, __VA_ARGS__);                                  \
                fputc('\n', stderr);                                           \
            }                                                                  \
        }                                                                      \
    } while (0)

#define CHECK(cond) CHECK_REPORT((cond), "%s", #cond)
#define CHECK_MSG(cond, ...) CHECK_REPORT((cond), __VA_ARGS__)
#define CHECK_NEAR(a, b, tol)                                                        \
    do {                                                                             \
        double check_a_ = (a), check_b_ = (b);                                       \
        CHECK_REPORT(fabs(check_a_ - check_b_) <= (tol), "%s = %.17g, %s = %.17g (tolerance %g)", \
                     #a, check_a_, #b, check_b_, (double)(tol));                     \
    } while (0)
#define CHECK_EQ_INT(a, b)                                                               \
    do {                                                                                 \
        long long check_a_ = (long long)(a), check_b_ = (long long)(b);                  \
        CHECK_REPORT(check_a_ == check_b_, "%s = %lld, %s = %lld", #a, check_a_, #b, check_b_); \
    } while (0)

/* Prints the closing line; use as `return check_finish();` at the end of main. */
static inline int check_finish(void)
{
    printf("%ld passed, %ld failed\n", check_passed, check_failed);
    return check_failed ? 1 : 0;
}

/* A deterministic random generator (xorshift64*) so failures reproduce. */
typedef struct check_rng { uint64_t state; } check_rng;
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
