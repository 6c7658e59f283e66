/* The arena: cg's one way of carving many arrays out of one allocation.
 *
 * An engine that needs a dozen arrays whose sizes it knows up front takes
 * them from one block instead of a dozen mallocs: one allocation per call
 * (or none, when the block is kept from call to call), and all of it given
 * back at once.  The arena measures, then carves: the same sequence of
 * takes runs twice, first on a measuring arena, which has no memory and
 * only adds the sizes up, then on a block of the size measured.  So the
 * sizes are written once, beside the arrays they are for:
 *
 *     static void take_arrays(core_arena *arena, parts *p, size_t n)
 *     {
 *         p->order = core_arena_take(arena, n, sizeof *p->order);
 *         p->flags = core_arena_take(arena, n, 1);
 *     }
 *
 *     core_arena measure = core_arena_measuring();
 *     take_arrays(&measure, &p, n);
 *     if (measure.failed ||
 *         core_arena_block(&block, &block_size, measure.used, NULL) != CG_OK)
 *         return CG_ENOMEM;
 *     core_arena carve = core_arena_on(block, block_size);
 *     take_arrays(&carve, &p, n);        (carve.failed cannot be set now)
 *
 * Every block taken starts at a multiple of CORE_ARENA_ALIGN bytes from the
 * start of the allocation (which malloc aligns for any type), so it holds
 * any scalar type; blocks are not zeroed.
 *
 *     allocation:  [order .......|pad][flags ...|pad][ ... ]   unused
 *                  ^ base         ^ aligned        ^ used     ^ capacity
 */
#ifndef CG_CORE_ARENA_H
#define CG_CORE_ARENA_H

#include "cg/core.h"

#include <stddef.h>
#include <stdint.h>

/* The alignment of every block taken, in bytes. */
#define CORE_ARENA_ALIGN 16

typedef struct core_arena {
    char *base;      /* the allocation carved, or NULL while measuring */
    size_t capacity; /* its size in bytes */
    size_t used;     /* bytes taken so far, the padding included */
    int failed;      /* a take did not fit, or its size overflowed */
} core_arena;

/* An arena that only measures: its takes return NULL and add up `used`. */
static inline core_arena core_arena_measuring(void)
{
    core_arena arena = {NULL, SIZE_MAX, 0, 0};
    return arena;
}

/* An arena carving block[0..capacity) (the caller owns the block). */
static inline core_arena core_arena_on(void *block, size_t capacity)
{
    core_arena arena = {(char *)block, capacity, 0, 0};
    return arena;
}

/* Room for count elements of element_size bytes, aligned: NULL while
 * measuring, and NULL with `failed` set when the room is not there or the
 * size overflows a size_t.  A take of nothing takes nothing (it returns
 * the current position, or NULL while measuring). */
void *core_arena_take(core_arena *arena, size_t count, size_t element_size);

/* Makes *block hold at least `needed` bytes: CG_OK when it does already,
 * else the old block freed (unless it is `keep`, a caller's buffer such as
 * one on the stack, which is never freed) and a new one allocated, its
 * contents not kept.  CG_ENOMEM with *block NULL and *size 0 when that
 * fails. */
cg_status core_arena_block(void **block, size_t *size, size_t needed, const void *keep);

#endif
