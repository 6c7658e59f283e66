/* The growable array: cg's one way of making room for more elements.
 *
 * Two shapes share one growth policy (core_array_grow):
 *
 *   - raw: a pointer and a capacity kept wherever the caller likes,
 *
 *         if (core_array_reserve((void **)&set->points, &set->point_capacity,
 *                                need, sizeof *set->points) != CG_OK)
 *             return CG_ENOMEM;
 *
 *   - typed: a struct with data, count and capacity, declared with
 *     CORE_ARRAY(type), and the macros below:
 *
 *         CORE_ARRAY(cg_vec2) points = {0};
 *         if (core_array_push(&points, p) != CG_OK) ...
 *         free(points.data);
 *
 * The policy: the capacity doubles (starting from CORE_ARRAY_FIRST elements)
 * until it holds what is needed; a request whose size in bytes would not fit
 * in a size_t, or that realloc refuses, returns CG_ENOMEM and leaves the
 * array exactly as it was. */
#ifndef CG_CORE_ARRAY_H
#define CG_CORE_ARRAY_H

#include "cg/core.h"

#include <stddef.h>
#include <stdlib.h>

/* The capacity a first allocation gets (in elements), unless more is needed. */
#define CORE_ARRAY_FIRST 16

/* Grows *data (elements of element_size bytes, *capacity of them) so that it
 * holds at least `needed` elements: CG_OK, or CG_ENOMEM with *data and
 * *capacity unchanged.  Called by core_array_reserve when the room is short. */
cg_status core_array_grow(void **data, size_t *capacity, size_t needed, size_t element_size);

/* CG_OK when *data already holds `needed` elements, else core_array_grow. */
static inline cg_status core_array_reserve(void **data, size_t *capacity, size_t needed,
                                           size_t element_size)
{
    return needed <= *capacity ? CG_OK : core_array_grow(data, capacity, needed, element_size);
}

/* core_array_reserve for an array that may still be in the caller's buffer
 * `initial` (on the stack, say, for small inputs: realloc cannot take it):
 * when *data is `initial` and more room is needed, its first `count`
 * elements move to a new block on the heap, grown by the same policy;
 * `initial` itself is never freed.  CG_ENOMEM with the array unchanged. */
cg_status core_array_reserve_from(void **data, size_t *capacity, size_t count, size_t needed,
                                  size_t element_size, const void *initial);

/* A typed array: `data` holds `count` elements in room for `capacity`. */
#define CORE_ARRAY(type) \
    struct {             \
        type *data;      \
        size_t count;    \
        size_t capacity; \
    }

/* Room for `needed` elements in typed array a (a pointer to a CORE_ARRAY). */
#define core_array_reserve_for(a, needed) \
    core_array_reserve((void **)&(a)->data, &(a)->capacity, (needed), sizeof *(a)->data)

/* Appends value to typed array a: CG_OK, or CG_ENOMEM with a unchanged. */
#define core_array_push(a, value)                         \
    (core_array_reserve_for((a), (a)->count + 1) == CG_OK \
         ? ((a)->data[(a)->count++] = (value), CG_OK)     \
         : CG_ENOMEM)

/* Frees typed array a's storage and empties it. */
#define core_array_free(a)              \
    do {                                \
        free((a)->data);                \
        (a)->data = NULL;               \
        (a)->count = (a)->capacity = 0; \
    } while (0)

#endif
