/* Clearing a tile before it is drawn: its colour to the background and its
 * depth to +infinity, row by row, with 16-byte stores where SSE2 is there
 * (streamed past the caches for tiles no triangle touches). */
#include "pipeline.h"
#include "../core/simd4.h"

#include <string.h>

/* Fills `rows` rows of `bytes` bytes (a multiple of 4), `stride` bytes
 * apart, with a 16-byte pattern that repeats every 4 bytes (or fills whole
 * 16-byte units); with `stream`, past the caches when the rows are
 * aligned. */
static void fill_rows(unsigned char *p, size_t stride, int rows, size_t bytes, i4 pattern,
                      int stream)
{
    size_t whole = bytes & ~(size_t)15;
    stream = stream && (uintptr_t)p % 16 == 0 && stride % 16 == 0;
    unsigned char tail[16];
    i4_store(tail, pattern);
    for (int y = 0; y < rows; y++, p += stride) {
        if (stream)
            for (size_t i = 0; i < whole; i += 16)
                i4_stream(p + i, pattern);
        else
            for (size_t i = 0; i < whole; i += 16)
                i4_store(p + i, pattern);
        if (whole < bytes)
            memcpy(p + whole, tail, bytes - whole);
    }
    if (stream)
        v4_stream_fence();
}

void render_clear_tile(render_frame *f, int x0, int y0, int x1, int y1, int stream, int depth)
{
    size_t width = (size_t)(x1 - x0);
    size_t pixel = f->image->format == CG_PIXEL_RGBA8 ? sizeof(cg_rgba8) : sizeof(cg_rgbaf);
    i4 color;
    if (f->image->format == CG_PIXEL_RGBA8) {
        uint32_t code;
        memcpy(&code, &f->background8, sizeof code);
        color = i4_set((int)code);
    } else {
        color = i4_from_v4_bits(v4_load(f->background));
    }
    if (depth)
        fill_rows((unsigned char *)(f->depth + (size_t)y0 * f->width + x0),
                  (size_t)f->width * sizeof(float), y1 - y0, width * sizeof(float),
                  i4_from_v4_bits(v4_set(INFINITY)), stream);
    fill_rows(f->image->data + (size_t)y0 * f->image->stride + (size_t)x0 * pixel, f->image->stride,
              y1 - y0, width * pixel, color, stream);
}
