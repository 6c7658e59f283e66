/* The growth policy of the growable array (array.h). */
#include "array.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

cg_status core_array_grow(void **data, size_t *capacity, size_t needed, size_t element_size)
{
    if (needed <= *capacity)
        return CG_OK;
    if (element_size == 0 || needed > SIZE_MAX / element_size)
        return CG_ENOMEM;
    size_t grown = *capacity ? *capacity : CORE_ARRAY_FIRST;
    while (grown < needed)
        grown = grown > SIZE_MAX / 2 ? needed : grown * 2;
    if (grown > SIZE_MAX / element_size)
        grown = needed; /* doubling would overflow: exactly what is needed */
    void *larger = realloc(*data, grown * element_size);
    if (!larger)
        return CG_ENOMEM;
    *data = larger;
    *capacity = grown;
    return CG_OK;
}

cg_status core_array_reserve_from(void **data, size_t *capacity, size_t count, size_t needed,
                                  size_t element_size, const void *initial)
{
    if (needed <= *capacity)
        return CG_OK;
    if (!initial || *data != initial)
        return core_array_grow(data, capacity, needed, element_size);
    void *heap = NULL;
    size_t heap_capacity = 0;
    if (core_array_grow(&heap, &heap_capacity, needed, element_size) != CG_OK)
        return CG_ENOMEM;
    if (count)
        memcpy(heap, *data, count * element_size);
    *data = heap;
    *capacity = heap_capacity;
    return CG_OK;
}
