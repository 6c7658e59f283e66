/* Binning, between the triangle stage and the rasterizer: the set-up
 * triangles of one chunk sorted by the screen tiles (RENDER_TILE pixels
 * square) their boxes touch, a counting sort that keeps mesh order within
 * each tile.  A tile is then drawn from the lists of every chunk in chunk
 * order, which is mesh order, whichever thread draws it.
 *
 *   bin_start[t] .. bin_start[t + 1]   the entries of tile t in bin_list
 *   bin_list[k]                        a triangle's index in the chunk's list */
#include "pipeline.h"

#include <string.h>

/* The tiles a set-up triangle's pixel box touches, inclusive. */
typedef struct tile_range {
    int x0, y0, x1, y1;
} tile_range;

static inline tile_range tiles_under(const render_frame *f, const render_chunk *c, size_t i)
{
    const setup_triangle *t = (const setup_triangle *)(c->setups + i * f->stride);
    tile_range r = {t->box[0] / RENDER_TILE, t->box[1] / RENDER_TILE, (t->box[2] - 1) / RENDER_TILE,
                    (t->box[3] - 1) / RENDER_TILE};
    return r;
}

void render_bin_chunk(render_frame *f, render_chunk *c)
{
    if (c->failed)
        return;
    size_t tiles = (size_t)f->tile_count;
    if (core_array_reserve((void **)&c->bin_start, &c->bin_start_capacity, tiles + 1,
                           sizeof *c->bin_start)
            != CG_OK
        || core_array_reserve((void **)&c->bin_fill, &c->bin_fill_capacity, tiles,
                              sizeof *c->bin_fill)
               != CG_OK) {
        c->failed = 1;
        return;
    }
    uint32_t *start = c->bin_start, *fill = c->bin_fill;
    memset(start, 0, (tiles + 1) * sizeof *start);
    size_t total = 0;
    for (size_t i = 0; i < c->setup_count; i++) {
        tile_range tiles_of = tiles_under(f, c, i);
        for (int ty = tiles_of.y0; ty <= tiles_of.y1; ty++)
            for (int tx = tiles_of.x0; tx <= tiles_of.x1; tx++)
                start[ty * f->tiles_x + tx + 1]++;
        total += (size_t)(tiles_of.x1 - tiles_of.x0 + 1) * (size_t)(tiles_of.y1 - tiles_of.y0 + 1);
    }
    if (total > UINT32_MAX) {
        c->failed = 1;
        return;
    }
    for (size_t t = 0; t < tiles; t++)
        start[t + 1] += start[t];
    if (core_array_reserve((void **)&c->bin_list, &c->bin_capacity, total ? total : 1,
                           sizeof *c->bin_list)
        != CG_OK) {
        c->failed = 1;
        return;
    }
    memcpy(fill, start, tiles * sizeof *fill);
    for (size_t i = 0; i < c->setup_count; i++) {
        tile_range tiles_of = tiles_under(f, c, i);
        for (int ty = tiles_of.y0; ty <= tiles_of.y1; ty++)
            for (int tx = tiles_of.x0; tx <= tiles_of.x1; tx++)
                c->bin_list[fill[ty * f->tiles_x + tx]++] = (uint32_t)i;
    }
}
