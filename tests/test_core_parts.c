/* The shared parts of src/core: the growable array's growth policy, its
 * refusal of sizes that overflow, and the typed array's macros; the
 * arena's measuring and carving, its refusals, and its blocks. */
#include "../src/core/arena.h"
#include "../src/core/array.h"
#include "check.h"

#include <stdint.h>
#include <string.h>

static void growth_policy(void)
{
    int *data = NULL;
    size_t capacity = 0;
    CHECK(core_array_reserve((void **)&data, &capacity, 0, sizeof *data) == CG_OK);
    CHECK(data == NULL && capacity == 0);
    CHECK(core_array_reserve((void **)&data, &capacity, 1, sizeof *data) == CG_OK);
    CHECK_EQ_INT(capacity, CORE_ARRAY_FIRST);
    CHECK(core_array_reserve((void **)&data, &capacity, CORE_ARRAY_FIRST + 1, sizeof *data) == CG_OK);
    CHECK_EQ_INT(capacity, 2 * CORE_ARRAY_FIRST);
    CHECK(core_array_reserve((void **)&data, &capacity, 1000, sizeof *data) == CG_OK);
    CHECK_EQ_INT(capacity, 1024);
    for (int i = 0; i < 1000; i++)
        data[i] = i; /* the room is really there (the sanitizer build checks it) */
    size_t before = capacity;
    CHECK(core_array_reserve((void **)&data, &capacity, 10, sizeof *data) == CG_OK);
    CHECK_EQ_INT(capacity, before); /* never shrinks */
    free(data);
}

static void overflow_refused(void)
{
    char *data = NULL;
    size_t capacity = 0;
    CHECK(core_array_reserve((void **)&data, &capacity, 8, 1) == CG_OK);
    data[0] = 'x';
    size_t before = capacity;
    /* Bytes that do not fit in a size_t: refused, the array untouched. */
    CHECK(core_array_reserve((void **)&data, &capacity, SIZE_MAX / 2 + 1, 4) == CG_ENOMEM);
    CHECK(core_array_reserve((void **)&data, &capacity, SIZE_MAX, 2) == CG_ENOMEM);
    CHECK(core_array_reserve((void **)&data, &capacity, 100, 0) == CG_ENOMEM);
    CHECK_EQ_INT(capacity, before);
    CHECK(data[0] == 'x');
    free(data);
}

static void typed_array(void)
{
    CORE_ARRAY(double) values = {0};
    for (int i = 0; i < 100; i++)
        CHECK(core_array_push(&values, i * 0.5) == CG_OK);
    CHECK_EQ_INT(values.count, 100);
    CHECK(values.capacity >= 100);
    int same = 1;
    for (int i = 0; i < 100; i++)
        same &= values.data[i] == i * 0.5;
    CHECK(same);
    CHECK(core_array_reserve_for(&values, 500) == CG_OK);
    CHECK(values.capacity >= 500 && values.count == 100);
    core_array_free(&values);
    CHECK(values.data == NULL && values.count == 0 && values.capacity == 0);
}

/* A sequence of takes (sizes from a small generator, some empty, some of
 * odd sizes) measured, then carved from a block of exactly that size: every
 * block aligned, inside the allocation, after the one before without
 * overlap, and the carving uses what the measuring said. */
static uint64_t arena_rng = 0x243f6a8885a308d3u;
static size_t arena_random(size_t limit)
{
    arena_rng ^= arena_rng << 13;
    arena_rng ^= arena_rng >> 7;
    arena_rng ^= arena_rng << 17;
    return (size_t)(arena_rng % limit);
}

static void arena_measure_then_carve(void)
{
    for (int round = 0; round < 200; round++) {
        size_t takes = 1 + arena_random(24), count[24], size[24];
        for (size_t k = 0; k < takes; k++) {
            count[k] = arena_random(5) == 0 ? 0 : arena_random(1000);
            size[k] = 1 + arena_random(40);
        }
        core_arena measure = core_arena_measuring();
        size_t bytes = 0;
        for (size_t k = 0; k < takes; k++) {
            CHECK(core_arena_take(&measure, count[k], size[k]) == NULL);
            bytes += (count[k] * size[k] + CORE_ARENA_ALIGN - 1) / CORE_ARENA_ALIGN *
                     CORE_ARENA_ALIGN;
        }
        CHECK(!measure.failed);
        CHECK_EQ_INT(measure.used, bytes);
        void *block = NULL;
        size_t block_size = 0;
        CHECK(core_arena_block(&block, &block_size, measure.used, NULL) == CG_OK);
        CHECK(block_size >= measure.used);
        core_arena carve = core_arena_on(block, measure.used);
        char *end = block;
        int aligned = 1, ordered = 1, inside = 1;
        for (size_t k = 0; k < takes; k++) {
            char *p = core_arena_take(&carve, count[k], size[k]);
            aligned &= (uintptr_t)(p - (char *)block) % CORE_ARENA_ALIGN == 0;
            ordered &= p >= end;
            inside &= p + count[k] * size[k] <= (char *)block + measure.used;
            memset(p, (int)k, count[k] * size[k]); /* (the sanitizer build checks the room) */
            end = p + count[k] * size[k];
        }
        CHECK(aligned && ordered && inside);
        CHECK(!carve.failed);
        CHECK_EQ_INT(carve.used, measure.used);
        free(block);
    }
}

static void arena_refusals(void)
{
    char room[64] = {0};
    core_arena arena = core_arena_on(room, sizeof room);
    CHECK(core_arena_take(&arena, 3, 8) == room);
    CHECK_EQ_INT(arena.used, 32);
    CHECK(core_arena_take(&arena, 0, 8) == room + 32 && arena.used == 32);
    /* more than is left: refused, nothing taken */
    CHECK(core_arena_take(&arena, 33, 1) == NULL && arena.failed);
    CHECK_EQ_INT(arena.used, 32);
    arena.failed = 0;
    CHECK(core_arena_take(&arena, 32, 1) == room + 32 && !arena.failed);
    CHECK(core_arena_take(&arena, 1, 1) == NULL && arena.failed);
    /* sizes that overflow a size_t, measured or carved */
    core_arena measure = core_arena_measuring();
    CHECK(core_arena_take(&measure, SIZE_MAX / 2 + 1, 2) == NULL && measure.failed);
    measure = core_arena_measuring();
    CHECK(core_arena_take(&measure, SIZE_MAX - 3, 1) == NULL && measure.failed);
    measure = core_arena_measuring();
    core_arena_take(&measure, SIZE_MAX / 2, 1);
    CHECK(!measure.failed);
    core_arena_take(&measure, SIZE_MAX / 2, 1); /* (the total overflows) */
    CHECK(measure.failed);
}

static void arena_blocks(void)
{
    char stack[128] = {0};
    void *block = stack;
    size_t size = sizeof stack;
    CHECK(core_arena_block(&block, &size, 100, stack) == CG_OK);
    CHECK(block == stack && size == sizeof stack); /* room enough: kept */
    CHECK(core_arena_block(&block, &size, 1000, stack) == CG_OK); /* the stack is not freed */
    CHECK(block != stack && size == 1000);
    memset(block, 1, 1000);
    CHECK(core_arena_block(&block, &size, 4000, stack) == CG_OK);
    CHECK(size == 4000);
    memset(block, 2, 4000);
    CHECK(core_arena_block(&block, &size, SIZE_MAX, stack) == CG_ENOMEM);
    CHECK(block == NULL && size == 0);
    CHECK(core_arena_block(&block, &size, 0, stack) == CG_OK && block != NULL);
    free(block);
}

/* An array that starts in the caller's buffer: it stays there while the
 * room suffices, moves to the heap with its elements when it does not
 * (the buffer itself untouched and never freed), and grows there as any. */
static void array_from_initial_buffer(void)
{
    int initial[8] = {0};
    int *data = initial;
    size_t capacity = 8;
    for (int i = 0; i < 8; i++)
        data[i] = 10 * i;
    CHECK(core_array_reserve_from((void **)&data, &capacity, 8, 8, sizeof *data, initial) == CG_OK);
    CHECK(data == initial && capacity == 8);
    CHECK(core_array_reserve_from((void **)&data, &capacity, 8, 9, sizeof *data, initial) == CG_OK);
    CHECK(data != initial && capacity >= 9);
    int same = 1;
    for (int i = 0; i < 8; i++)
        same &= data[i] == 10 * i && initial[i] == 10 * i;
    CHECK(same);
    data[8] = 80;
    CHECK(core_array_reserve_from((void **)&data, &capacity, 9, 1000, sizeof *data, initial) ==
          CG_OK);
    CHECK(capacity >= 1000 && data[8] == 80 && data[0] == 0);
    size_t before = capacity;
    int *kept = data;
    CHECK(core_array_reserve_from((void **)&data, &capacity, 9, SIZE_MAX / 2, sizeof *data,
                                  initial) == CG_ENOMEM);
    CHECK(data == kept && capacity == before); /* refused: unchanged */
    free(data);
    /* refused while still in the buffer: still there */
    data = initial;
    capacity = 8;
    CHECK(core_array_reserve_from((void **)&data, &capacity, 8, SIZE_MAX, 2, initial) == CG_ENOMEM);
    CHECK(data == initial && capacity == 8);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(growth_policy);
    CHECK_GROUP(overflow_refused);
    CHECK_GROUP(typed_array);
    CHECK_GROUP(array_from_initial_buffer);
    CHECK_GROUP(arena_measure_then_carve);
    CHECK_GROUP(arena_refusals);
    CHECK_GROUP(arena_blocks);
    return check_finish();
}
