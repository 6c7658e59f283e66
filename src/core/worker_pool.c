/* The worker pool (worker_pool.h): threads kept between runs, woken for
 * each run, and the phases' counters.
 *
 * A run is "open" while the caller works on it: pool->task is set and
 * pool->generation counts it.  A thread that wakes sees a new generation;
 * if the run is still open it enters (pool->inside counts it), else it goes
 * back to sleep.  Closing a run clears pool->task and then waits only for
 * the threads inside, so a thread the scheduler runs late never delays the
 * caller and never touches a finished run. */
#include "worker_pool.h"

#include <stdlib.h>

typedef struct pool_thread {
    core_worker_pool *pool;
    int worker; /* its index in the tasks it runs */
} pool_thread;

struct core_worker_pool {
    pthread_mutex_t lock;
    pthread_cond_t wake;       /* a run opened, or the pool stops */
    pthread_cond_t idle;       /* the last thread inside a run left it */
    pthread_cond_t phase_done; /* a phase's last block was finished */
    int workers;               /* the caller and the threads started */
    int inside;                /* threads inside the open run's task */
    int quit;
    unsigned long generation; /* runs opened */
    core_worker_task task;    /* the open run's; NULL once it is closed */
    void *context;
    pthread_t *ids; /* workers - 1 of them */
    pool_thread *threads;
};

static void *thread_main(void *argument)
{
    const pool_thread *self = argument;
    core_worker_pool *pool = self->pool;
    unsigned long seen = 0;
    pthread_mutex_lock(&pool->lock);
    for (;;) {
        while (pool->generation == seen && !pool->quit)
            pthread_cond_wait(&pool->wake, &pool->lock);
        if (pool->quit)
            break;
        seen = pool->generation;
        core_worker_task task = pool->task;
        if (!task)
            continue; /* woken too late: the caller finished the run */
        void *context = pool->context;
        pool->inside++;
        pthread_mutex_unlock(&pool->lock);
        task(context, self->worker);
        pthread_mutex_lock(&pool->lock);
        if (--pool->inside == 0)
            pthread_cond_signal(&pool->idle);
    }
    pthread_mutex_unlock(&pool->lock);
    return NULL;
}

static int start_with_pthread(pthread_t *thread, void *(*main)(void *), void *argument)
{
    return pthread_create(thread, NULL, main, argument);
}

/* The lock and conditions: 1 when all four exist, else 0 with none left. */
static int init_sync(core_worker_pool *pool)
{
    int made = 0;
    made += pthread_mutex_init(&pool->lock, NULL) == 0;
    made += made == 1 && pthread_cond_init(&pool->wake, NULL) == 0;
    made += made == 2 && pthread_cond_init(&pool->idle, NULL) == 0;
    made += made == 3 && pthread_cond_init(&pool->phase_done, NULL) == 0;
    if (made == 4)
        return 1;
    if (made > 2)
        pthread_cond_destroy(&pool->idle);
    if (made > 1)
        pthread_cond_destroy(&pool->wake);
    if (made > 0)
        pthread_mutex_destroy(&pool->lock);
    return 0;
}

cg_status core_worker_pool_create_with(int workers, core_thread_start start, core_worker_pool **out)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if (workers < 1 || workers > CORE_WORKER_POOL_MAX || !start)
        return CG_EINVAL;
    core_worker_pool *pool = calloc(1, sizeof *pool);
    if (!pool)
        return CG_ENOMEM;
    size_t threads = (size_t)workers - 1;
    pool->ids = calloc(threads ? threads : 1, sizeof *pool->ids);
    pool->threads = calloc(threads ? threads : 1, sizeof *pool->threads);
    if (!pool->ids || !pool->threads || !init_sync(pool)) {
        free(pool->ids);
        free(pool->threads);
        free(pool);
        return CG_ENOMEM;
    }
    pool->workers = 1;
    for (size_t i = 0; i < threads; i++) {
        pool_thread *t = &pool->threads[pool->workers - 1];
        t->pool = pool;
        t->worker = pool->workers;
        /* A thread that does not start is left out; the ones started keep
         * consecutive worker indices. */
        if (start(&pool->ids[pool->workers - 1], thread_main, t) == 0)
            pool->workers++;
    }
    *out = pool;
    return CG_OK;
}

cg_status core_worker_pool_create(int workers, core_worker_pool **out)
{
    return core_worker_pool_create_with(workers, start_with_pthread, out);
}

void core_worker_pool_free(core_worker_pool *pool)
{
    if (!pool)
        return;
    pthread_mutex_lock(&pool->lock);
    pool->quit = 1;
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    for (int i = 0; i < pool->workers - 1; i++)
        pthread_join(pool->ids[i], NULL);
    pthread_cond_destroy(&pool->phase_done);
    pthread_cond_destroy(&pool->idle);
    pthread_cond_destroy(&pool->wake);
    pthread_mutex_destroy(&pool->lock);
    free(pool->ids);
    free(pool->threads);
    free(pool);
}

int core_worker_pool_workers(const core_worker_pool *pool)
{
    return pool ? pool->workers : 1;
}

void core_worker_pool_run(core_worker_pool *pool, core_worker_task task, void *context)
{
    if (!pool || pool->workers == 1) {
        task(context, 0);
        return;
    }
    pthread_mutex_lock(&pool->lock);
    pool->task = task;
    pool->context = context;
    pool->generation++;
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    task(context, 0);
    /* Closed: threads that wake from now on leave it alone; the caller
     * waits only for those already inside. */
    pthread_mutex_lock(&pool->lock);
    pool->task = NULL;
    pool->context = NULL;
    while (pool->inside > 0)
        pthread_cond_wait(&pool->idle, &pool->lock);
    pthread_mutex_unlock(&pool->lock);
}

void core_worker_pool_phase_init(core_worker_phase *phase, size_t blocks)
{
    atomic_init(&phase->next, 0);
    atomic_init(&phase->done, 0);
    phase->blocks = blocks;
}

size_t core_worker_pool_finish(core_worker_pool *pool, core_worker_phase *phase)
{
    size_t count = atomic_fetch_add(&phase->done, 1) + 1;
    if (count == phase->blocks && pool && pool->workers > 1) {
        pthread_mutex_lock(&pool->lock);
        pthread_cond_broadcast(&pool->phase_done);
        pthread_mutex_unlock(&pool->lock);
    }
    return count;
}

void core_worker_pool_wait(core_worker_pool *pool, core_worker_phase *phase)
{
    /* The caller alone has done every block by the time it gets here. */
    if (atomic_load(&phase->done) >= phase->blocks || !pool || pool->workers == 1)
        return;
    pthread_mutex_lock(&pool->lock);
    while (atomic_load(&phase->done) < phase->blocks)
        pthread_cond_wait(&pool->phase_done, &pool->lock);
    pthread_mutex_unlock(&pool->lock);
}
