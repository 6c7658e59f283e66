/* Invariants: conditions of cg's own code that no input can break (a sorted
 * list still sorted, a piece taken once).  CG_INVARIANT(condition) gives the
 * condition's value, so that the code after it can still take an error path
 * in a release build:
 *
 *     if (!CG_INVARIANT(ended == expected))
 *         return -1;
 *
 * In the builds that look for bugs (the sanitizer and fuzz builds define
 * CG_CHECK_INVARIANTS) a broken invariant stops the program at once, naming
 * the condition and its place, so that a test or a fuzzer reports it instead
 * of seeing an error status that looks like bad input. */
#ifndef CG_CORE_INVARIANT_H
#define CG_CORE_INVARIANT_H

/* Prints "cg: invariant broken at FILE:LINE: CONDITION" and aborts. */
_Noreturn void core_invariant_failed(const char *condition, const char *file, int line);

#ifdef CG_CHECK_INVARIANTS
#define CG_INVARIANT(condition) \
    ((condition) ? 1 : (core_invariant_failed(#condition, __FILE__, __LINE__), 0))
#else
#define CG_INVARIANT(condition) ((condition) ? 1 : 0)
#endif
#define CG_ASSERT(condition) ((void)CG_INVARIANT(condition))

#endif
