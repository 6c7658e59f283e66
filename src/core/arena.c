/* The arena's takes and blocks (arena.h). */
#include "arena.h"

#include <stdint.h>
#include <stdlib.h>

void *core_arena_take(core_arena *arena, size_t count, size_t element_size)
{
    if (element_size && count > SIZE_MAX / element_size) {
        arena->failed = 1;
        return NULL;
    }
    size_t bytes = count * element_size;
    size_t padded = (bytes + (CORE_ARENA_ALIGN - 1)) & ~(size_t)(CORE_ARENA_ALIGN - 1);
    if (padded < bytes || padded > arena->capacity - arena->used) {
        arena->failed = 1;
        return NULL;
    }
    void *start = arena->base ? arena->base + arena->used : NULL;
    arena->used += padded;
    return start;
}

cg_status core_arena_block(void **block, size_t *size, size_t needed, const void *keep)
{
    if (needed <= *size && *block)
        return CG_OK;
    if (*block != keep)
        free(*block);
    *size = 0;
    /* (no object may be larger than PTRDIFF_MAX bytes) */
    *block = needed <= PTRDIFF_MAX ? malloc(needed ? needed : 1) : NULL;
    if (!*block)
        return CG_ENOMEM;
    *size = needed;
    return CG_OK;
}
