/* Clearing a tile before it is drawn: its colour to the background and its
 * depth to +infinity, row by row, with 16-byte stores where SSE2 is there
 * (streamed past the caches for tiles no triangle touches). */
#include "pipeline.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <string.h>

#if defined(__SSE2__)
/* Fills `rows` rows of `bytes` bytes (a multiple of 4), `stride` bytes
 * apart, with a 16-byte pattern that repeats every 4 bytes (or fills whole
 * 16-byte units); with `stream`, past the caches when the rows are
 * aligned. */
static void fill_rows(unsigned char *p, size_t stride, int rows, size_t bytes, __m128i pattern,
                      int stream)
{
    size_t whole = bytes & ~(size_t)15;
    stream = stream && (uintptr_t)p % 16 == 0 && stride % 16 == 0;
    unsigned char tail[16];
    _mm_storeu_si128((__m128i *)tail, pattern);
    for (int y = 0; y < rows; y++, p += stride) {
        if (stream)
            for (size_t i = 0; i < whole; i += 16)
                _mm_stream_si128((__m128i *)(p + i), pattern);
        else
            for (size_t i = 0; i < whole; i += 16)
                _mm_storeu_si128((__m128i *)(p + i), pattern);
        if (whole < bytes)
            memcpy(p + whole, tail, bytes - whole);
    }
    if (stream)
        _mm_sfence();
}
#endif

void render_clear_tile(render_frame *f, int x0, int y0, int x1, int y1, int stream, int depth)
{
    size_t width = (size_t)(x1 - x0);
    size_t pixel = f->image->format == CG_PIXEL_RGBA8 ? sizeof(cg_rgba8) : sizeof(cg_rgbaf);
#if defined(__SSE2__)
    __m128i color;
    if (f->image->format == CG_PIXEL_RGBA8) {
        uint32_t code;
        memcpy(&code, &f->background8, sizeof code);
        color = _mm_set1_epi32((int)code);
    } else {
        color = _mm_castps_si128(_mm_loadu_ps(f->background));
    }
    if (depth)
        fill_rows((unsigned char *)(f->depth + (size_t)y0 * f->width + x0),
                  (size_t)f->width * sizeof(float), y1 - y0, width * sizeof(float),
                  _mm_castps_si128(_mm_set1_ps(INFINITY)), stream);
    fill_rows(f->image->data + (size_t)y0 * f->image->stride + (size_t)x0 * pixel, f->image->stride,
              y1 - y0, width * pixel, color, stream);
#else
    (void)stream;
    const cg_rgbaf background = {f->background[0], f->background[1], f->background[2],
                                 f->background[3]};
    /* The first row by hand, the others copied from it. */
    float *z0 = f->depth + (size_t)y0 * f->width + x0;
    if (depth)
        for (size_t x = 0; x < width; x++)
            z0[x] = INFINITY;
    if (f->image->format == CG_PIXEL_RGBA8) {
        cg_rgba8 *row = cg_image_row_rgba8(f->image, y0) + x0;
        for (size_t x = 0; x < width; x++)
            row[x] = f->background8;
    } else {
        cg_rgbaf *row = cg_image_row_rgbaf(f->image, y0) + x0;
        for (size_t x = 0; x < width; x++)
            row[x] = background;
    }
    const unsigned char *first = f->image->data + (size_t)y0 * f->image->stride
                                 + (size_t)x0 * pixel;
    for (int y = y0 + 1; y < y1; y++) {
        if (depth)
            memcpy(f->depth + (size_t)y * f->width + x0, z0, width * sizeof *z0);
        memcpy(f->image->data + (size_t)y * f->image->stride + (size_t)x0 * pixel, first,
               width * pixel);
    }
#endif
}
