/* Pieces shared inside src/draw: a painter that writes one colour into an
 * image (a fast path for opaque colours in RGBA8 images, blending in linear
 * light otherwise), and wide integers for exact clipping arithmetic. */
#ifndef CG_DRAW_INTERNAL_H
#define CG_DRAW_INTERNAL_H

#include "cg/draw.h"
#include "cg/color.h"

#include <string.h>

/* Products of two 33-bit values need more than 64 bits. */
__extension__ typedef __int128 cg_wide;

typedef struct cg_painter {
    cg_image *image;
    cg_rgba8 color;
    cg_rgbaf linear; /* the colour in linear light */
    uint32_t packed; /* the colour's four bytes as stored in RGBA8 */
    int opaque;      /* RGBA8 image and alpha 255: plain stores */
} cg_painter;

void draw_painter_init(cg_painter *painter, cg_image *image, cg_rgba8 color);

/* Pixel (x, y) must be inside the image. */
static inline void cg_painter_plot(const cg_painter *painter, int x, int y)
{
    cg_image *image = painter->image;
    if (painter->opaque)
        memcpy(image->data + (size_t)y * image->stride + (size_t)x * 4, &painter->packed, 4);
    else if (painter->color.a == 255)
        cg_image_set(image, x, y, painter->linear);
    else
        cg_image_blend(image, x, y, painter->linear);
}

static inline int cg_painter_visible(const cg_painter *painter, long long x, long long y)
{
    return x >= 0 && y >= 0 && x < painter->image->width && y < painter->image->height;
}

/* Pixel (x, y) clipped to the image. */
static inline void cg_painter_plot_clipped(const cg_painter *painter, long long x, long long y)
{
    if (cg_painter_visible(painter, x, y))
        cg_painter_plot(painter, (int)x, (int)y);
}

/* Pixels x0..x1 of row y, all inside the image. */
void draw_painter_span(const cg_painter *painter, int x0, int x1, int y);

/* Blends the colour with its alpha scaled by coverage in [0, 1] onto pixel
 * (x, y), which must be inside the image. */
void draw_painter_cover(const cg_painter *painter, int x, int y, float coverage);

/* Coverage blending in batches: the sRGB decoding and encoding of many
 * opaque RGBA8 pixels is done in one pass each.  Pixels must be inside the
 * image and distinct within a batch; others formats and translucent pixels
 * are blended at once. */
enum { CG_COVER_BATCH = 256 };
typedef struct cg_cover_batch {
    const cg_painter *painter;
    int count;
    uint8_t *pixel[CG_COVER_BATCH];
    float alpha[CG_COVER_BATCH];
} cg_cover_batch;

void draw_cover_flush(cg_cover_batch *batch);
static inline void cg_cover_add(cg_cover_batch *batch, int x, int y, float coverage)
{
    const cg_painter *painter = batch->painter;
    cg_image *image = painter->image;
    if (!(coverage > 0))
        return;
    if (image->format != CG_PIXEL_RGBA8) {
        draw_painter_cover(painter, x, y, coverage);
        return;
    }
    uint8_t *d = image->data + (size_t)y * image->stride + (size_t)x * 4;
    if (d[3] != 255) {
        draw_painter_cover(painter, x, y, coverage);
        return;
    }
    float a = painter->linear.a * (coverage < 1 ? coverage : 1);
    if (a >= 1) {
        memcpy(d, &painter->packed, 4);
        return;
    }
    batch->pixel[batch->count] = d;
    batch->alpha[batch->count] = a;
    if (++batch->count == CG_COVER_BATCH)
        draw_cover_flush(batch);
}

/* The Bresenham line with the options polylines need: skip_first leaves out
 * the pixel (x0, y0) (already drawn as the end of the previous segment). */
void draw_line_clipped(const cg_painter *painter, int x0, int y0, int x1, int y1, int skip_first);

/* The first-octant form of a line: the walk starts at (u0, v0) in (major,
 * minor) coordinates, du >= dv >= 0, the minor coordinate moving by sv. */
typedef struct cg_line_frame {
    int x_major; /* major axis is x */
    int swapped; /* endpoints were swapped to walk from the smaller major coordinate */
    long long u0, v0, du, dv;
    int sv;
} cg_line_frame;

void draw_line_frame_make(int x0, int y0, int x1, int y1, cg_line_frame *frame);

/* The integer square root floor(sqrt(n)) for 0 <= n < 2^63. */
long long draw_isqrt(long long n);

/* Arcs: normalises START_DEG/END_DEG to a start in [0, 360) and a sweep in
 * [0, 360] (0 when not finite); and tests whether the direction (dx, dy_up)
 * from the centre lies on the arc (a tiny slack keeps exact boundary
 * directions such as 90 degrees on it). */
int draw_arc_range(double start_deg, double end_deg, double *start, double *sweep);
int draw_arc_contains(double start, double sweep, double dx, double dy_up);

/* A pixel callback of the curve walks, and the arc filter: draw_arc_plot
 * draws pixel (x, y) when it is in the image and on the arc. */
typedef void (*cg_pixel_fn)(void *context, long long x, long long y);
typedef struct cg_arc_filter {
    const cg_painter *painter;
    long long cx, cy;
    double start, sweep; /* degrees, start in [0, 360), sweep in [0, 360] */
} cg_arc_filter;
void draw_arc_plot(void *context, long long x, long long y);

#endif
