/* The team of threads that runs a frame of the z-buffer pipeline: three
 * phases -- vertex blocks, triangle chunks (triangle stage and binning),
 * tiles (clear and rasterize) -- each a set of blocks taken from a counter.
 * Every block writes its own part of the frame, so the picture does not
 * depend on which thread took which block, nor on the number of threads. */
#include "pipeline.h"

#include <pthread.h>
#include <string.h>

/* One frame's work: three phases (vertex blocks, triangle chunks, tiles),
 * each a set of blocks that threads take from a counter and count when done.
 * A thread moves to the next phase once every block of this one is done; it
 * never waits for a thread that has taken nothing, so a worker the
 * scheduler has not run yet (the machine busy with other work) holds up
 * nobody, and the caller may do the whole frame alone. */
typedef struct team {
    render_frame *frame;
    pthread_mutex_t *lock;      /* the pool's, NULL for the caller alone */
    pthread_cond_t *phase;      /* signalled when a phase completes */
    atomic_size_t next_vertex_block, vertex_blocks_done;
    atomic_size_t next_chunk, chunks_done;
    atomic_size_t next_tile, tiles_done;
    int painter;
    size_t fragments[64];
} team;

/* Counts one block of a phase of `total` done and returns the count; the
 * last one wakes the threads waiting for the phase. */
static size_t block_done(team *tm, atomic_size_t *done, size_t total)
{
    size_t count = atomic_fetch_add(done, 1) + 1;
    if (count == total && tm->lock) {
        pthread_mutex_lock(tm->lock);
        pthread_cond_broadcast(tm->phase);
        pthread_mutex_unlock(tm->lock);
    }
    return count;
}

/* Waits until every block of a phase is done: called once no block is left
 * to take, so only blocks other threads are working on can be missing. */
static void phase_wait(team *tm, atomic_size_t *done, size_t total)
{
    if (atomic_load(done) >= total || !tm->lock)
        return;
    pthread_mutex_lock(tm->lock);
    while (atomic_load(done) < total)
        pthread_cond_wait(tm->phase, tm->lock);
    pthread_mutex_unlock(tm->lock);
}

/* The renderer's worker threads, started at its first frame with more than
 * one thread and kept until the thread count changes or the renderer is
 * freed: starting threads for every frame costs, and a new thread often
 * waits for the scheduler to move it to an idle core, while a kept one
 * wakes on the core it last ran on.  The calling thread is worker 0. */
typedef struct render_pool {
    pthread_mutex_t lock;
    pthread_cond_t wake, idle, phase;
    int threads;                /* started besides the caller */
    int inside;                 /* threads working on the open frame */
    int quit;
    unsigned long generation;   /* frames handed out */
    team *team;                 /* the open frame's; NULL once it is closed */
    pthread_t ids[63];
    struct pool_worker {
        struct render_pool *pool;
        int index;
    } workers[64];
} render_pool;

static void work(team *tm, int index)
{
    render_frame *f = tm->frame;
    int chunks = f->chunk_count;
    /* Vertex stage and triangle stage in blocks taken from shared counters:
     * a thread slowed down (by other work on the machine) holds up the
     * others by one block at most.  The blocks depend on the mesh only,
     * and each lands in its own place, so the result does not depend on
     * which thread took which. */
    size_t vertices = f->r->vertex_count;
    size_t blocks = (vertices + VERTEX_BLOCK - 1) / VERTEX_BLOCK;
    for (;;) {
        size_t b = atomic_fetch_add(&tm->next_vertex_block, 1);
        if (b >= blocks)
            break;
        size_t end = (b + 1) * VERTEX_BLOCK;
        render_vertex_stage(f, b * VERTEX_BLOCK, end < vertices ? end : vertices);
        block_done(tm, &tm->vertex_blocks_done, blocks);
    }
    phase_wait(tm, &tm->vertex_blocks_done, blocks);
    for (;;) {
        size_t i = atomic_fetch_add(&tm->next_chunk, 1);
        if (i >= (size_t)chunks)
            break;
        /* Worked on in a local copy: the chunks other threads work on lie
         * next to it, and counting in place would bounce the shared cache
         * lines between the cores at every triangle. */
        render_chunk chunk = f->chunks[i];
        render_triangle_stage(f, &chunk, tm->painter);
        if (!tm->painter)
            render_bin_chunk(f, &chunk);
        f->chunks[i] = chunk;
        block_done(tm, &tm->chunks_done, (size_t)chunks);
    }
    phase_wait(tm, &tm->chunks_done, (size_t)chunks);
    if (tm->painter)
        return;
    int failed = 0;
    for (int i = 0; i < chunks; i++)
        failed |= f->chunks[i].failed;
    if (failed)
        return;
    size_t fragments = 0;
    for (;;) {
        size_t claimed = atomic_fetch_add(&tm->next_tile, 1);
        if (claimed >= (size_t)f->tile_count)
            break;
        int tile = (int)claimed;
        int x0 = tile % f->tiles_x * RENDER_TILE, y0 = tile / f->tiles_x * RENDER_TILE;
        int x1 = x0 + RENDER_TILE < f->width ? x0 + RENDER_TILE : f->width;
        int y1 = y0 + RENDER_TILE < f->height ? y0 + RENDER_TILE : f->height;
        int empty = 1;
        for (int i = 0; i < chunks && empty; i++)
            empty = f->chunks[i].bin_start[tile] == f->chunks[i].bin_start[tile + 1];
        /* The depth of a tile left empty since it was last cleared is
         * still infinite: only its colour (the caller's image) is written. */
        render_clear_tile(f, x0, y0, x1, y1, empty, !(empty && f->clean_tiles[tile]));
        f->clean_tiles[tile] = (unsigned char)empty;
        for (int i = 0; i < chunks; i++) {
            const render_chunk *c = &f->chunks[i];
            for (uint32_t k = c->bin_start[tile]; k < c->bin_start[tile + 1]; k++) {
                const setup_triangle *t =
                    (const setup_triangle *)(c->setups + (size_t)c->bin_list[k] * f->stride);
                fragments += render_raster(f, t, x0, y0, x1, y1, 1);
            }
        }
        size_t done = block_done(tm, &tm->tiles_done, (size_t)f->tile_count);
        if (index == 0 && f->o->progress)
            f->o->progress(f->o->progress_user, (double)done / f->tile_count);
    }
    tm->fragments[index] = fragments;
    if (index == 0)
        phase_wait(tm, &tm->tiles_done, (size_t)f->tile_count);
}

static void *pool_main(void *argument)
{
    struct pool_worker *w = argument;
    render_pool *p = w->pool;
    unsigned long seen = 0;
    pthread_mutex_lock(&p->lock);
    for (;;) {
        while (p->generation == seen && !p->quit)
            pthread_cond_wait(&p->wake, &p->lock);
        if (p->quit)
            break;
        seen = p->generation;
        team *tm = p->team;
        if (!tm)
            continue; /* woken too late: the caller finished the frame */
        p->inside++;
        pthread_mutex_unlock(&p->lock);
        work(tm, w->index);
        pthread_mutex_lock(&p->lock);
        if (--p->inside == 0)
            pthread_cond_signal(&p->idle);
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

static void pool_stop(render_pool *p)
{
    if (!p)
        return;
    pthread_mutex_lock(&p->lock);
    p->quit = 1;
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    for (int i = 0; i < p->threads; i++)
        pthread_join(p->ids[i], NULL);
    pthread_cond_destroy(&p->wake);
    pthread_cond_destroy(&p->idle);
    pthread_cond_destroy(&p->phase);
    pthread_mutex_destroy(&p->lock);
    free(p);
}

/* A pool for `threads` threads in all (the caller included); NULL when no
 * other thread can be started, and then the caller works alone.  Threads
 * that cannot be started leave their share to the others. */
static render_pool *pool_start(int threads)
{
    render_pool *p = calloc(1, sizeof *p);
    if (!p)
        return NULL;
    int made = 0; /* synchronization objects initialized */
    made += pthread_mutex_init(&p->lock, NULL) == 0;
    made += made == 1 && pthread_cond_init(&p->wake, NULL) == 0;
    made += made == 2 && pthread_cond_init(&p->idle, NULL) == 0;
    made += made == 3 && pthread_cond_init(&p->phase, NULL) == 0;
    if (made == 4)
        for (int i = 1; i < threads; i++) {
            p->workers[i].pool = p;
            p->workers[i].index = i;
            if (pthread_create(&p->ids[i - 1], NULL, pool_main, &p->workers[i]) != 0)
                break;
            p->threads++;
        }
    if (p->threads > 0)
        return p;
    if (made > 3)
        pthread_cond_destroy(&p->phase);
    if (made > 2)
        pthread_cond_destroy(&p->idle);
    if (made > 1)
        pthread_cond_destroy(&p->wake);
    if (made > 0)
        pthread_mutex_destroy(&p->lock);
    free(p);
    return NULL;
}

/* Runs this frame's work on the caller and the pool's threads. */
static void pool_run(render_pool *p, team *tm)
{
    if (!p) {
        work(tm, 0);
        return;
    }
    tm->lock = &p->lock;
    tm->phase = &p->phase;
    pthread_mutex_lock(&p->lock);
    p->team = tm;
    p->generation++;
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    work(tm, 0);
    /* Closed: threads that wake from now on leave it alone; the caller
     * waits only for those already working on it. */
    pthread_mutex_lock(&p->lock);
    p->team = NULL;
    while (p->inside > 0)
        pthread_cond_wait(&p->idle, &p->lock);
    pthread_mutex_unlock(&p->lock);
}

void render_team_stop(cg_renderer *r)
{
    pool_stop(r->pool);
    r->pool = NULL;
    r->pool_threads = 0;
}

void render_run_phases(render_frame *f, int painter, size_t *fragments)
{
    cg_renderer *r = f->r;
    team tm;
    memset(&tm, 0, sizeof tm);
    tm.frame = f;
    tm.painter = painter;
    atomic_init(&tm.next_vertex_block, 0);
    atomic_init(&tm.vertex_blocks_done, 0);
    atomic_init(&tm.next_chunk, 0);
    atomic_init(&tm.chunks_done, 0);
    atomic_init(&tm.next_tile, 0);
    atomic_init(&tm.tiles_done, 0);
    if (f->thread_count > 1 && r->pool_threads != f->thread_count) {
        pool_stop(r->pool);
        r->pool = pool_start(f->thread_count);
        r->pool_threads = f->thread_count;
    }
    pool_run(f->thread_count > 1 ? r->pool : NULL, &tm);
    *fragments = 0;
    for (int i = 0; i < f->thread_count; i++)
        *fragments += tm.fragments[i];
}
