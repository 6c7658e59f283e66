/* The team of threads that runs a frame of the z-buffer pipeline on the
 * renderer's worker pool (src/core/worker_pool.h): three phases -- vertex
 * blocks, triangle chunks (triangle stage and binning), tiles (clear and
 * rasterize) -- each a set of blocks claimed from a counter.  A worker moves
 * to the next phase once every block of this one is done; it never waits
 * for a worker that has taken nothing, so a thread the scheduler has not
 * run yet (the machine busy with other work) holds up nobody, and the
 * caller may do the whole frame alone.  Every block writes its own part of
 * the frame, so the picture depends neither on which worker took which
 * block nor on the number of threads.
 *
 * The renderer keeps its pool from frame to frame (started at its first
 * frame with more than one thread, restarted when the thread count
 * changes, stopped by cg_renderer_free). */
#include "pipeline.h"
#include "../core/worker_pool.h"

#include <stdlib.h>
#include <string.h>

/* One frame's phases and the fragment count of each worker. */
typedef struct team {
    render_frame *frame;
    core_worker_pool *pool;
    core_worker_phase vertex_blocks, chunks, tiles;
    int painter;
    size_t fragments[64];
} team;

/* Vertex stage in blocks of VERTEX_BLOCK vertices: a thread slowed down
 * holds up the others by one block at most. */
static void vertex_phase(team *tm)
{
    render_frame *f = tm->frame;
    size_t vertices = f->r->vertex_count, block;
    while (core_worker_pool_claim(&tm->vertex_blocks, &block)) {
        size_t end = (block + 1) * VERTEX_BLOCK;
        render_vertex_stage(f, block * VERTEX_BLOCK, end < vertices ? end : vertices);
        core_worker_pool_finish(tm->pool, &tm->vertex_blocks);
    }
    core_worker_pool_wait(tm->pool, &tm->vertex_blocks);
}

/* Triangle stage and binning, a chunk (a range of the mesh) at a time. */
static void triangle_phase(team *tm)
{
    render_frame *f = tm->frame;
    size_t i;
    while (core_worker_pool_claim(&tm->chunks, &i)) {
        /* Worked on in a local copy: the chunks other threads work on lie
         * next to it, and counting in place would bounce the shared cache
         * lines between the cores at every triangle. */
        render_chunk chunk = f->chunks[i];
        render_triangle_stage(f, &chunk, tm->painter);
        if (!tm->painter)
            render_bin_chunk(f, &chunk);
        f->chunks[i] = chunk;
        core_worker_pool_finish(tm->pool, &tm->chunks);
    }
    core_worker_pool_wait(tm->pool, &tm->chunks);
}

/* A blended triangle of a tile, in the order it is drawn: farthest first
 * (the sum of its corners' window depths, which orders as their centroid),
 * then in mesh order. */
typedef struct blended {
    float depth;
    uint32_t order; /* position among the tile's triangles, in mesh order */
    const setup_triangle *t;
} blended;

static int back_to_front(const void *a, const void *b)
{
    const blended *p = a, *q = b;
    if (p->depth != q->depth)
        return p->depth < q->depth ? 1 : -1;
    return p->order < q->order ? -1 : p->order > q->order;
}

static int is_blended(const render_frame *f, const setup_triangle *t)
{
    return f->shading == MODE_TEXTURED && t->material != RENDER_NO_MATERIAL
           && f->r->materials[t->material].blend;
}

/* Draws a non-empty tile through the samples (multisample.c) of worker:
 * the opaque triangles in mesh order, then the blended ones back to front
 * (in mesh order when there is no memory to sort them); returns the
 * covered sample count. */
static size_t draw_tile_samples(render_frame *f, int worker, int x0, int y0, int x1, int y1,
                                int tile)
{
    render_samples *s = &f->sample_buffers[worker];
    render_samples_begin(f, s, x0, y0, x1, y1);
    size_t fragments = 0, blend_count = 0;
    for (int i = 0; i < f->chunk_count; i++) {
        const render_chunk *c = &f->chunks[i];
        for (uint32_t k = c->bin_start[tile]; k < c->bin_start[tile + 1]; k++) {
            const setup_triangle *t =
                (const setup_triangle *)(c->setups + (size_t)c->bin_list[k] * f->stride);
            if (is_blended(f, t))
                blend_count++;
            else
                fragments += render_raster_samples(f, s, t, x0, y0, x1, y1);
        }
    }
    if (blend_count) {
        blended *list = malloc(blend_count * sizeof *list);
        size_t n = 0;
        uint32_t order = 0;
        for (int i = 0; i < f->chunk_count; i++) {
            const render_chunk *c = &f->chunks[i];
            for (uint32_t k = c->bin_start[tile]; k < c->bin_start[tile + 1]; k++, order++) {
                const setup_triangle *t =
                    (const setup_triangle *)(c->setups + (size_t)c->bin_list[k] * f->stride);
                if (!is_blended(f, t))
                    continue;
                if (!list) {
                    fragments += render_raster_samples(f, s, t, x0, y0, x1, y1);
                    continue;
                }
                list[n].depth = t->z[0] + t->z[1] + t->z[2];
                list[n].order = order;
                list[n++].t = t;
            }
        }
        if (list) {
            qsort(list, n, sizeof *list, back_to_front);
            for (size_t k = 0; k < n; k++)
                fragments += render_raster_samples(f, s, list[k].t, x0, y0, x1, y1);
            free(list);
        }
    }
    render_samples_resolve(f, s, x0, y0, x1, y1);
    return fragments;
}

/* Clears tile `tile` and draws every triangle binned on it, chunk by chunk
 * (mesh order); returns the covered pixel (or sample) count. */
static size_t draw_tile(render_frame *f, int worker, int tile)
{
    int chunks = f->chunk_count;
    int x0 = tile % f->tiles_x * RENDER_TILE, y0 = tile / f->tiles_x * RENDER_TILE;
    int x1 = x0 + RENDER_TILE < f->width ? x0 + RENDER_TILE : f->width;
    int y1 = y0 + RENDER_TILE < f->height ? y0 + RENDER_TILE : f->height;
    int empty = 1;
    for (int i = 0; i < chunks && empty; i++)
        empty = f->chunks[i].bin_start[tile] == f->chunks[i].bin_start[tile + 1];
    if (f->use_samples && !empty) {
        f->clean_tiles[tile] = 0;
        return draw_tile_samples(f, worker, x0, y0, x1, y1, tile);
    }
    /* The depth of a tile left empty since it was last cleared is still
     * infinite: only its colour (the caller's image) is written. */
    render_clear_tile(f, x0, y0, x1, y1, empty, !(empty && f->clean_tiles[tile]));
    f->clean_tiles[tile] = (unsigned char)empty;
    size_t fragments = 0;
    for (int i = 0; i < chunks; i++) {
        const render_chunk *c = &f->chunks[i];
        for (uint32_t k = c->bin_start[tile]; k < c->bin_start[tile + 1]; k++) {
            const setup_triangle *t =
                (const setup_triangle *)(c->setups + (size_t)c->bin_list[k] * f->stride);
            fragments += render_raster(f, t, x0, y0, x1, y1, 1);
        }
    }
    return fragments;
}

/* The tiles, each cleared and drawn by one worker; the caller reports the
 * progress. */
static void tile_phase(team *tm, int worker)
{
    render_frame *f = tm->frame;
    size_t fragments = 0, tile;
    while (core_worker_pool_claim(&tm->tiles, &tile)) {
        fragments += draw_tile(f, worker, (int)tile);
        size_t done = core_worker_pool_finish(tm->pool, &tm->tiles);
        if (worker == 0 && f->o->progress)
            f->o->progress(f->o->progress_user, (double)done / f->tile_count);
    }
    tm->fragments[worker] = fragments;
    if (worker == 0)
        core_worker_pool_wait(tm->pool, &tm->tiles);
}

static void work(void *context, int worker)
{
    team *tm = context;
    render_frame *f = tm->frame;
    vertex_phase(tm);
    triangle_phase(tm);
    if (tm->painter)
        return;
    int failed = 0;
    for (int i = 0; i < f->chunk_count; i++)
        failed |= f->chunks[i].failed;
    if (failed)
        return;
    tile_phase(tm, worker);
}

void render_team_stop(cg_renderer *r)
{
    core_worker_pool_free(r->pool);
    r->pool = NULL;
    r->pool_threads = 0;
}

void render_run_phases(render_frame *f, int painter, size_t *fragments)
{
    cg_renderer *r = f->r;
    if (f->thread_count > 1 && r->pool_threads != f->thread_count) {
        /* Without a pool (out of memory) the caller works alone. */
        render_team_stop(r);
        if (core_worker_pool_create(f->thread_count, &r->pool) != CG_OK)
            r->pool = NULL;
        r->pool_threads = f->thread_count;
    }
    team tm;
    memset(&tm, 0, sizeof tm);
    tm.frame = f;
    tm.pool = f->thread_count > 1 ? r->pool : NULL;
    tm.painter = painter;
    size_t vertices = r->vertex_count;
    core_worker_pool_phase_init(&tm.vertex_blocks, (vertices + VERTEX_BLOCK - 1) / VERTEX_BLOCK);
    core_worker_pool_phase_init(&tm.chunks, (size_t)f->chunk_count);
    core_worker_pool_phase_init(&tm.tiles, (size_t)f->tile_count);
    core_worker_pool_run(tm.pool, work, &tm);
    *fragments = 0;
    for (int i = 0; i < core_worker_pool_workers(tm.pool); i++)
        *fragments += tm.fragments[i];
}
