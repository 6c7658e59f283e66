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

void render_bin_chunk(render_frame *f, render_chunk *c)
{
    if (c->failed)
        return;
    size_t tiles = (size_t)f->tile_count;
    if (core_array_reserve((void **)&c->bin_start, &c->bin_start_capacity, tiles + 1,
                           sizeof *c->bin_start) != CG_OK
        || core_array_reserve((void **)&c->bin_fill, &c->bin_fill_capacity, tiles,
                              sizeof *c->bin_fill) != CG_OK) {
        c->failed = 1;
        return;
    }
    uint32_t *start = c->bin_start, *fill = c->bin_fill;
    memset(start, 0, (tiles + 1) * sizeof *start);
    size_t total = 0;
    for (size_t i = 0; i < c->setup_count; i++) {
        const setup_triangle *t = (const setup_triangle *)(c->setups + i * f->stride);
        int tx0 = t->box[0] / RENDER_TILE, tx1 = (t->box[2] - 1) / RENDER_TILE;
        int ty0 = t->box[1] / RENDER_TILE, ty1 = (t->box[3] - 1) / RENDER_TILE;
        for (int ty = ty0; ty <= ty1; ty++)
            for (int tx = tx0; tx <= tx1; tx++)
                start[ty * f->tiles_x + tx + 1]++;
        total += (size_t)(tx1 - tx0 + 1) * (size_t)(ty1 - ty0 + 1);
    }
    if (total > UINT32_MAX) {
        c->failed = 1;
        return;
    }
    for (size_t t = 0; t < tiles; t++)
        start[t + 1] += start[t];
    if (core_array_reserve((void **)&c->bin_list, &c->bin_capacity, total ? total : 1,
                           sizeof *c->bin_list) != CG_OK) {
        c->failed = 1;
        return;
    }
    memcpy(fill, start, tiles * sizeof *fill);
    for (size_t i = 0; i < c->setup_count; i++) {
        const setup_triangle *t = (const setup_triangle *)(c->setups + i * f->stride);
        int tx0 = t->box[0] / RENDER_TILE, tx1 = (t->box[2] - 1) / RENDER_TILE;
        int ty0 = t->box[1] / RENDER_TILE, ty1 = (t->box[3] - 1) / RENDER_TILE;
        for (int ty = ty0; ty <= ty1; ty++)
            for (int tx = tx0; tx <= tx1; tx++)
                c->bin_list[fill[ty * f->tiles_x + tx]++] = (uint32_t)i;
    }
}
