/* The stop of a broken invariant (see invariant.h): only the builds that
 * look for bugs call it. */
#include "invariant.h"

#include <stdio.h>
#include <stdlib.h>

void core_invariant_failed(const char *condition, const char *file, int line)
{
    fprintf(stderr, "cg: invariant broken at %s:%d: %s\n", file, line, condition);
    abort();
}
