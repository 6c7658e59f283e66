/* core_sort: qsort, skipped below two elements (sort.h). */
#include "sort.h"

#include <stdlib.h>

void core_sort(void *base, size_t count, size_t size, int (*compare)(const void *, const void *))
{
    if (count < 2)
        return;
    qsort(base, count, size, compare);
}
