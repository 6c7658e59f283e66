/* Private to libcg: the one call of the C library's qsort.  qsort wants a
 * non-null array even for zero elements (the sanitizer build stops on
 * qsort(NULL, 0, ...)), and an empty or one-element array is sorted
 * already, so core_sort does nothing below two elements: callers need no
 * guard of their own. */
#ifndef CG_CORE_SORT_H
#define CG_CORE_SORT_H

#include <stddef.h>

/* Sorts base[0..count) (elements of size bytes) by compare, as qsort. */
void core_sort(void *base, size_t count, size_t size, int (*compare)(const void *, const void *));

#endif
