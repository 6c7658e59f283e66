/* The shared parts of src/core: the growable array's growth policy, its
 * refusal of sizes that overflow, and the typed array's macros; the worker
 * pool's blocks, each claimed exactly once, on any number of workers, with
 * threads that fail to start or wake late; the arena's measuring and
 * carving, its refusals, and its blocks. */
#include "../src/core/arena.h"
#include "../src/core/array.h"
#include "../src/core/base64.h"
#include "../src/core/worker_pool.h"
#include "check.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static void growth_policy(void)
{
    int *data = NULL;
    size_t capacity = 0;
    CHECK(core_array_reserve((void **)&data, &capacity, 0, sizeof *data) == CG_OK);
    CHECK(data == NULL && capacity == 0);
    CHECK(core_array_reserve((void **)&data, &capacity, 1, sizeof *data) == CG_OK);
    CHECK_EQ_INT(capacity, CORE_ARRAY_FIRST);
    CHECK(core_array_reserve((void **)&data, &capacity, CORE_ARRAY_FIRST + 1, sizeof *data)
          == CG_OK);
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

/* ---- the worker pool ------------------------------------------------------ */

#define POOL_BLOCKS_MAX 2000

/* Two phases of blocks: each block of the first counts its claims and notes
 * its worker; each block of the second checks that the first is complete. */
typedef struct pool_job {
    core_worker_pool *pool;
    core_worker_phase first, second;
    atomic_int claims[POOL_BLOCKS_MAX];
    int worker_of[POOL_BLOCKS_MAX];
    atomic_int second_claims[POOL_BLOCKS_MAX];
    atomic_int early;      /* second-phase blocks that saw the first unfinished */
    atomic_int bad_worker; /* worker indices out of range */
    atomic_int calls;      /* task calls */
} pool_job;

static void pool_task(void *context, int worker)
{
    pool_job *j = context;
    atomic_fetch_add(&j->calls, 1);
    if (worker < 0 || worker >= core_worker_pool_workers(j->pool))
        atomic_fetch_add(&j->bad_worker, 1);
    size_t block;
    while (core_worker_pool_claim(&j->first, &block)) {
        atomic_fetch_add(&j->claims[block], 1);
        j->worker_of[block] = worker;
        core_worker_pool_finish(j->pool, &j->first);
    }
    core_worker_pool_wait(j->pool, &j->first);
    while (core_worker_pool_claim(&j->second, &block)) {
        int complete = 1;
        for (size_t i = 0; i < j->first.blocks; i++)
            complete &= atomic_load(&j->claims[i]) == 1;
        if (!complete)
            atomic_fetch_add(&j->early, 1);
        atomic_fetch_add(&j->second_claims[block], 1);
        core_worker_pool_finish(j->pool, &j->second);
    }
}

/* Runs pool_task over `blocks` and `second` blocks; 1 when every block of
 * both phases was claimed exactly once, the second phase never started
 * early and no worker index was out of range.  Notes which workers took
 * part into *took_part (bit per worker). */
static int pool_round(core_worker_pool *pool, size_t blocks, size_t second,
                      unsigned long *took_part)
{
    static pool_job j;
    memset(&j, 0, sizeof j);
    j.pool = pool;
    core_worker_pool_phase_init(&j.first, blocks);
    core_worker_pool_phase_init(&j.second, second);
    for (size_t i = 0; i < POOL_BLOCKS_MAX; i++) {
        atomic_init(&j.claims[i], 0);
        atomic_init(&j.second_claims[i], 0);
    }
    atomic_init(&j.early, 0);
    atomic_init(&j.bad_worker, 0);
    atomic_init(&j.calls, 0);
    core_worker_pool_run(pool, pool_task, &j);
    int ok = atomic_load(&j.early) == 0 && atomic_load(&j.bad_worker) == 0
             && atomic_load(&j.calls) >= 1
             && atomic_load(&j.calls) <= core_worker_pool_workers(pool)
             && atomic_load(&j.first.done) == blocks && atomic_load(&j.second.done) == second;
    for (size_t i = 0; i < blocks; i++) {
        ok &= atomic_load(&j.claims[i]) == 1;
        if (j.worker_of[i] >= 0 && j.worker_of[i] < 64)
            *took_part |= 1ul << j.worker_of[i];
    }
    for (size_t i = 0; i < second; i++)
        ok &= atomic_load(&j.second_claims[i]) == 1;
    for (size_t i = blocks; i < POOL_BLOCKS_MAX; i++)
        ok &= atomic_load(&j.claims[i]) == 0;
    return ok;
}

static void worker_pool_claims(void)
{
    static const size_t sizes[] = {0, 1, 2, 3, 7, 64, 333, POOL_BLOCKS_MAX};
    for (int workers = 1; workers <= 6; workers++) {
        core_worker_pool *pool;
        CHECK(core_worker_pool_create(workers, &pool) == CG_OK);
        if (!pool)
            continue;
        CHECK_EQ_INT(core_worker_pool_workers(pool), workers);
        int rounds_ok = 0, rounds = 0;
        unsigned long took_part = 0;
        uint64_t seed = 12345u + (unsigned)workers;
        for (int round = 0; round < 300; round++) {
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            size_t blocks = round < 8 ? sizes[round] : (size_t)(seed >> 33) % POOL_BLOCKS_MAX;
            size_t second = (size_t)(seed >> 13) % 50;
            rounds_ok += pool_round(pool, blocks, second, &took_part);
            rounds++;
        }
        CHECK_MSG(rounds_ok == rounds, "%d workers: %d of %d rounds claimed every block once",
                  workers, rounds_ok, rounds);
        CHECK(took_part & 1); /* the caller always takes part */
        CHECK_MSG(took_part < (1ul << workers), "%d workers: worker bits %#lx", workers, took_part);
        core_worker_pool_free(pool);
    }
    /* No pool: the caller alone. */
    unsigned long took_part = 0;
    CHECK(pool_round(NULL, 100, 10, &took_part));
    CHECK_EQ_INT(took_part, 1);
    CHECK_EQ_INT(core_worker_pool_workers(NULL), 1);
}

/* A thread starter that starts only the first `start_budget` threads. */
static atomic_int start_budget;
static int start_some(pthread_t *thread, void *(*main)(void *), void *argument)
{
    if (atomic_fetch_sub(&start_budget, 1) <= 0)
        return 11; /* EAGAIN: as pthread_create when out of threads */
    return pthread_create(thread, NULL, main, argument);
}

static void worker_pool_failed_threads(void)
{
    for (int budget = 0; budget <= 3; budget++) {
        atomic_store(&start_budget, budget);
        core_worker_pool *pool;
        CHECK(core_worker_pool_create_with(5, start_some, &pool) == CG_OK);
        if (!pool)
            continue;
        CHECK_EQ_INT(core_worker_pool_workers(pool), 1 + budget);
        int rounds_ok = 0;
        unsigned long took_part = 0;
        for (int round = 0; round < 100; round++)
            rounds_ok += pool_round(pool, (size_t)(round * 37 % POOL_BLOCKS_MAX), 9, &took_part);
        CHECK_MSG(rounds_ok == 100, "%d threads started: %d of 100 rounds", budget, rounds_ok);
        CHECK_MSG(took_part < (1ul << (1 + budget)), "workers %#lx beyond the %d started",
                  took_part, budget);
        core_worker_pool_free(pool);
    }
    core_worker_pool *pool = (core_worker_pool *)&pool; /* any value: set to NULL */
    CHECK(core_worker_pool_create(0, &pool) == CG_EINVAL && pool == NULL);
    CHECK(core_worker_pool_create(-3, &pool) == CG_EINVAL);
    CHECK(core_worker_pool_create(CORE_WORKER_POOL_MAX + 1, &pool) == CG_EINVAL);
    CHECK(core_worker_pool_create(2, NULL) == CG_EINVAL);
    core_worker_pool_free(NULL);
}

/* Threads held at a gate before they first look at the pool: as threads
 * the scheduler has not run yet on a busy machine. */
static atomic_int gate_open;
typedef struct gated_start {
    void *(*main)(void *);
    void *argument;
} gated_start;
static gated_start gated[8];
static atomic_int gated_count;

static void *gated_main(void *argument)
{
    gated_start *g = argument;
    while (!atomic_load(&gate_open)) {
        struct timespec pause = {0, 1000000};
        nanosleep(&pause, NULL);
    }
    return g->main(g->argument);
}

static int start_gated(pthread_t *thread, void *(*main)(void *), void *argument)
{
    int i = atomic_fetch_add(&gated_count, 1);
    if (i >= 8)
        return 11;
    gated[i].main = main;
    gated[i].argument = argument;
    return pthread_create(thread, NULL, gated_main, &gated[i]);
}

static void worker_pool_late_threads(void)
{
    atomic_store(&gate_open, 0);
    atomic_store(&gated_count, 0);
    core_worker_pool *pool;
    CHECK(core_worker_pool_create_with(4, start_gated, &pool) == CG_OK);
    if (!pool)
        return;
    CHECK_EQ_INT(core_worker_pool_workers(pool), 4);
    /* Every thread asleep: each run is done by the caller alone, and
     * returns without waiting for anybody. */
    int rounds_ok = 0;
    unsigned long took_part = 0;
    for (int round = 0; round < 50; round++)
        rounds_ok += pool_round(pool, (size_t)(round * 41 % 500), 5, &took_part);
    CHECK_EQ_INT(rounds_ok, 50);
    CHECK_EQ_INT(took_part, 1);
    /* Awake: the threads skip the runs already closed and join the next
     * ones; every block is still claimed exactly once. */
    atomic_store(&gate_open, 1);
    rounds_ok = 0;
    for (int round = 0; round < 200; round++)
        rounds_ok += pool_round(pool, (size_t)(round * 53 % POOL_BLOCKS_MAX), 17, &took_part);
    CHECK_EQ_INT(rounds_ok, 200);
    core_worker_pool_free(pool);
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
            bytes += (count[k] * size[k] + CORE_ARENA_ALIGN - 1) / CORE_ARENA_ALIGN
                     * CORE_ARENA_ALIGN;
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
    CHECK(block == stack && size == sizeof stack);                /* room enough: kept */
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
    CHECK(core_array_reserve_from((void **)&data, &capacity, 9, 1000, sizeof *data, initial)
          == CG_OK);
    CHECK(capacity >= 1000 && data[8] == 80 && data[0] == 0);
    size_t before = capacity;
    int *kept = data;
    CHECK(core_array_reserve_from((void **)&data, &capacity, 9, SIZE_MAX / 2, sizeof *data, initial)
          == CG_ENOMEM);
    CHECK(data == kept && capacity == before); /* refused: unchanged */
    free(data);
    /* refused while still in the buffer: still there */
    data = initial;
    capacity = 8;
    CHECK(core_array_reserve_from((void **)&data, &capacity, 8, SIZE_MAX, 2, initial) == CG_ENOMEM);
    CHECK(data == initial && capacity == 8);
}

/* Decodes text; 1 when it gives exactly want (a C string), else 0 or -1. */
static int base64_gives(const char *text, int skip_whitespace, const char *want)
{
    unsigned char *out = NULL;
    size_t size = 0;
    int ok = core_base64_decode(text, strlen(text), skip_whitespace, &out, &size);
    if (ok != 1)
        return ok;
    ok = size == strlen(want) && memcmp(out, want, size) == 0;
    free(out);
    return ok;
}

/* RFC 4648's test vectors, with and without padding, the URL-safe
 * alphabet, wrapped text, and what is not base64. */
static void base64_decoding(void)
{
    const char *plain[] = {"", "f", "fo", "foo", "foob", "fooba", "foobar"};
    const char *padded[] = {"", "Zg==", "Zm8=", "Zm9v", "Zm9vYg==", "Zm9vYmE=", "Zm9vYmFy"};
    const char *bare[] = {"", "Zg", "Zm8", "Zm9v", "Zm9vYg", "Zm9vYmE", "Zm9vYmFy"};
    for (int i = 0; i < 7; i++) {
        CHECK_MSG(base64_gives(padded[i], 0, plain[i]) == 1, "padded '%s'", padded[i]);
        CHECK_MSG(base64_gives(bare[i], 0, plain[i]) == 1, "unpadded '%s'", bare[i]);
    }
    CHECK(base64_gives("-_8=", 0, "\xfb\xff") == 1);
    CHECK(base64_gives("+/8=", 0, "\xfb\xff") == 1);
    CHECK(base64_gives(" Zm9v\n YmFy\r\n", 1, "foobar") == 1);
    CHECK(base64_gives("Zm9v YmFy", 0, "foobar") == 0); /* spaces only when asked */
    CHECK(base64_gives("Zm9v*mFy", 1, "foobar") == 0);
    CHECK(base64_gives("Zm9vY", 0, "foo") == 0);   /* a lone trailing character */
    CHECK(base64_gives("Zg===", 0, "f") == 0);     /* three padding characters */
    CHECK(base64_gives("Zg==Zg==", 0, "ff") == 0); /* padding in the middle */
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(growth_policy);
    CHECK_GROUP(overflow_refused);
    CHECK_GROUP(typed_array);
    CHECK_GROUP(worker_pool_claims);
    CHECK_GROUP(worker_pool_failed_threads);
    CHECK_GROUP(worker_pool_late_threads);
    CHECK_GROUP(array_from_initial_buffer);
    CHECK_GROUP(arena_measure_then_carve);
    CHECK_GROUP(arena_refusals);
    CHECK_GROUP(arena_blocks);
    CHECK_GROUP(base64_decoding);
    return check_finish();
}
