/* A random perfect maze (randomised depth-first search), shared by the fill
 * test, the fill benchmark and the gallery.  Header-only; include with a
 * relative path. */
#ifndef CG_TESTS_MAZE_H
#define CG_TESTS_MAZE_H

#include "cg/image.h"

#include <stdint.h>
#include <stdlib.h>

/* Draws on im (at least 2 cells_x + 1 by 2 cells_y + 1 pixels) a maze of
 * cells_x x cells_y cells: walls in wall colour, cells and passages in open
 * colour, cell (i, j) at pixel (2i + 1, 2j + 1).  With wall_every > 0 every
 * wall_every-th passage stays walled, so the maze falls into regions.
 * Returns 0, or -1 when memory runs out. */
static inline int maze_draw(cg_image *im, int cells_x, int cells_y, uint64_t seed, int wall_every,
                            cg_rgba8 wall, cg_rgba8 open)
{
    static const int d[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    int n = cells_x * cells_y, top = 0, carved = 0;
    unsigned char *seen = (unsigned char *)calloc((size_t)n, 1);
    int *stack = (int *)malloc(sizeof(int) * (size_t)n);
    if (!seen || !stack) {
        free(seen);
        free(stack);
        return -1;
    }
    cg_image_clear_rgba8(im, wall);
    stack[top++] = 0;
    seen[0] = 1;
    cg_image_set_rgba8(im, 1, 1, open);
    uint64_t state = seed | 1;
    while (top) {
        int c = stack[top - 1], cx = c % cells_x, cy = c / cells_x, options[4], k = 0;
        for (int i = 0; i < 4; i++) {
            int nx = cx + d[i][0], ny = cy + d[i][1];
            if (nx >= 0 && ny >= 0 && nx < cells_x && ny < cells_y && !seen[ny * cells_x + nx])
                options[k++] = i;
        }
        if (!k) {
            top--;
            continue;
        }
        state ^= state << 13; /* xorshift64 */
        state ^= state >> 7;
        state ^= state << 17;
        int i = options[state % (uint64_t)k];
        int nx = cx + d[i][0], ny = cy + d[i][1];
        seen[ny * cells_x + nx] = 1;
        if (wall_every <= 0 || ++carved % wall_every != 0)
            cg_image_set_rgba8(im, 2 * cx + 1 + d[i][0], 2 * cy + 1 + d[i][1], open);
        cg_image_set_rgba8(im, 2 * nx + 1, 2 * ny + 1, open);
        stack[top++] = ny * cells_x + nx;
    }
    free(seen);
    free(stack);
    return 0;
}

#endif
