/* Anti-aliased fill by exact area coverage (signed-area accumulation).
 *
 * Every line segment of the outline adds, to each pixel of each row it
 * crosses, the signed area of that pixel lying to the right of it within
 * the row, times the segment's direction.  Deposited as differences along
 * the row, a running sum over the row gives every pixel the integral of the
 * winding number over its square.  A cell holds two differences: one added
 * before its pixel's coverage is taken (the part of the area in its own
 * column) and one after (the rest, which every pixel further right
 * inherits), so that a line crossing a row within one column touches one
 * cell, not two.  The non-zero rule takes min(1, |sum|), even-odd folds the sum into
 * [0, 1].  Rows are processed in bands so memory stays bounded.
 *
 * Lines are clipped to the image first: parts above or below are dropped,
 * parts right of it are dropped (they only affect pixels further right),
 * and parts left of it are replaced by vertical lines on its left edge,
 * which cover the visible pixels the same way. */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

void fill_aa_begin(struct cg_rasterizer *r, const cg_image *image)
{
    r->line_count = 0;
    r->clip_width = image->width;
    r->clip_height = image->height;
    r->min_x = r->min_y = HUGE_VAL;
    r->max_x = r->max_y = -HUGE_VAL;
}

static cg_status push_line(struct cg_rasterizer *r, double x0, double y0, double x1, double y1)
{
    if (y0 == y1)
        return CG_OK;
    if (core_array_reserve((void **)&r->lines, &r->line_capacity, r->line_count + 1,
                           sizeof *r->lines)
        != CG_OK)
        return CG_ENOMEM;
    fill_line l = {x0, y0, x1, y1};
    r->lines[r->line_count++] = l;
    if (x0 < r->min_x)
        r->min_x = x0;
    if (x1 < r->min_x)
        r->min_x = x1;
    if (x0 > r->max_x)
        r->max_x = x0;
    if (x1 > r->max_x)
        r->max_x = x1;
    if (y0 < r->min_y)
        r->min_y = y0;
    if (y1 < r->min_y)
        r->min_y = y1;
    if (y0 > r->max_y)
        r->max_y = y0;
    if (y1 > r->max_y)
        r->max_y = y1;
    return CG_OK;
}

static double clamp_between(double v, double a, double b)
{
    double lo = a < b ? a : b, hi = a < b ? b : a;
    return v < lo ? lo : (v > hi ? hi : v);
}

cg_status fill_aa_add_line(struct cg_rasterizer *r, cg_vec2 a, cg_vec2 b)
{
    double x0 = a.x, y0 = a.y, x1 = b.x, y1 = b.y;
    double h = r->clip_height, w = r->clip_width;
    if (y0 == y1 || (y0 <= 0 && y1 <= 0) || (y0 >= h && y1 >= h))
        return CG_OK;
    /* Vertical clipping. */
    if (y0 < 0 || y0 > h) {
        double yc = y0 < 0 ? 0 : h;
        x0 = clamp_between(x0 + (yc - y0) * (x1 - x0) / (y1 - y0), x0, x1);
        y0 = yc;
    }
    if (y1 < 0 || y1 > h) {
        double yc = y1 < 0 ? 0 : h;
        x1 = clamp_between(x1 + (yc - y1) * (x0 - x1) / (y0 - y1), x0, x1);
        y1 = yc;
    }
    if (x0 >= w && x1 >= w) {
        /* Dropped, but the coverage of lines left of it now reaches the
         * right edge of the image. */
        if (w > r->max_x)
            r->max_x = w;
        return CG_OK;
    }
    if (x0 <= 0 && x1 <= 0)
        return push_line(r, 0, y0, 0, y1);
    if (x0 < 0 || x1 < 0) {
        double ym = clamp_between(y0 + (0 - x0) * (y1 - y0) / (x1 - x0), y0, y1);
        cg_status status;
        if (x0 < 0) {
            status = push_line(r, 0, y0, 0, ym);
            x0 = 0;
            y0 = ym;
        } else {
            status = push_line(r, 0, ym, 0, y1);
            x1 = 0;
            y1 = ym;
        }
        if (status != CG_OK)
            return status;
    }
    if (x0 > w || x1 > w) {
        double ym = clamp_between(y0 + (w - x0) * (y1 - y0) / (x1 - x0), y0, y1);
        if (x0 > w) {
            x0 = w;
            y0 = ym;
        } else {
            x1 = w;
            y1 = ym;
        }
    }
    return push_line(r, x0, y0, x1, y1);
}

cg_status fill_aa_add_polylines(struct cg_rasterizer *r, const fill_polylines *set)
{
    for (size_t i = 0; i < set->line_count; i++) {
        const fill_polyline *l = &set->lines[i];
        const cg_vec2 *p = set->points + l->start;
        for (size_t k = 0; k < l->count; k++) {
            cg_status status = fill_aa_add_line(r, p[k], p[(k + 1) % l->count]);
            if (status != CG_OK)
                return status;
        }
    }
    return CG_OK;
}

/* A bit per cell says which cells of a row were touched, so that a row is
 * swept in time proportional to its touched cells: the pixels between them
 * have constant coverage and are painted as spans. */
static inline void mark_cells(uint64_t *bits, int a, int b)
{
    int wa = a >> 6, wb = b >> 6;
    uint64_t ma = ~0ULL << (a & 63), mb = ~0ULL >> (63 - (b & 63));
    if (wa == wb) {
        bits[wa] |= ma & mb;
        return;
    }
    bits[wa] |= ma;
    for (int w = wa + 1; w < wb; w++)
        bits[w] = ~0ULL;
    bits[wb] |= mb;
}

static inline int lowest_bit(uint64_t m)
{
#if defined(__GNUC__)
    return __builtin_ctzll(m);
#else
    int n = 0;
    while (!(m & 1)) {
        m >>= 1;
        n++;
    }
    return n;
#endif
}

/* Marks cell c touched (the common case of a line crossing a row within
 * one column). */
static inline void mark_cell(uint64_t *bits, int c)
{
    bits[c >> 6] |= 1ULL << (c & 63);
}

/* Adds the part of a line within one row: x from xa to xb (relative to the
 * row's first cell, xa <= xb), signed height d; s = d / (xb - xa), the
 * area per unit of x, is the line's (given, as it is the same on every row).
 * Cell c's differences are row[2c] (added before pixel c's coverage is
 * taken) and row[2c + 1] (after).
 *
 * The part crossing cells c0 .. c1 (here c1 = c0 + 2).  A pixel's coverage
 * is the area right of the line in its own column (dotted), times d's sign:
 *
 *         c0   c0+1 c1   c1+1
 *        +----+----+----+----+   <- top of the part (ya)
 *     xa | \..|....|....|....|  ^
 *        |  \.|....|....|....|  |  d0 = s len0, len0 = c0 + 1 - xa
 *        |   \|....|....|....|  v
 *        |    \....|....|....|  ^
 *        |    |\...|....|....|  |
 *        |    | \..|....|....|  |  s: the height over one whole cell
 *        |    |  \.|....|....|  |
 *        |    |   \|....|....|  v
 *        |    |    \....|....|  ^  d1 = s len1, len1 = xb - c1
 *        |    |    |\...|....|  v
 *        +----+----+----+----+   <- bottom of the part
 *                   xb
 *
 *   pixel    coverage
 *   c0       d0 len0 / 2                         (a triangle)
 *   c0+1     d0 + s / 2                          (a rectangle and a triangle)
 *   ...      s more for each whole cell
 *   c1       d0 + s (c1 - c0 - 1) + d1 (1 - len1 / 2)
 *   beyond   d0 + s (c1 - c0 - 1) + d1 = d       (the whole height)
 *
 * The running sum along the row gives pixel c the before-differences of
 * cells 0 .. c and the after-differences of cells 0 .. c - 1, so a cell
 * holds what its pixel's coverage adds to the coverage of the pixel before:
 *
 *   cell     row[2c] (before)                    row[2c + 1] (after)
 *   c0       d0 len0 / 2                         0
 *   c0+1     d0 (1 - len0 / 2) + s / 2           0
 *   c0+2 ..  s                                   0
 *   c1       s / 2 + d1 (1 - len1 / 2)           d1 len1 / 2
 *
 * With no whole cell (c1 = c0 + 1) both s / 2 terms go.  A line that stays
 * in one cell (c0 = c1), at mean position fx = (xa + xb) / 2 - c0 in it:
 *
 *   c0       d (1 - fx)                          d fx */
static inline int deposit_row(float *row, uint64_t *touched, double xa, double xb, double d,
                              double s)
{
    if (xa < 0)
        xa = 0;
    int c0 = (int)xa, c1 = (int)xb;
    /* A span narrower than 1/1024 of a pixel that crosses a cell border
     * goes to the cell of its middle: s * (xb - xa) would not be d there,
     * as xb - xa is then a few units in the last place of x (a line 1e-14
     * off vertical across x = 56 deposited 25 times its area). */
    if (c0 != c1 && xb - xa < 1.0 / 1024)
        c0 = c1 = (int)(0.5 * (xa + xb));
    if (c0 == c1) {
        mark_cell(touched, c0);
        double fx = 0.5 * (xa + xb) - c0;
        row[2 * c0] += (float)(d * (1 - fx));
        row[2 * c0 + 1] += (float)(d * fx);
        return c0;
    }
    mark_cells(touched, c0, c1);
    double len0 = c0 + 1 - xa, d0 = s * len0;
    row[2 * c0] += (float)(d0 * len0 * 0.5);
    /* the first whole cell gets the rest of c0's area and half its own;
     * the next ones s each, and c1 the last whole cell's other half */
    double half = s * 0.5;
    row[2 * c0 + 2] += (float)(d0 * (1 - len0 * 0.5) + (c0 + 1 < c1 ? half : 0));
    float whole = (float)s;
    for (int c = c0 + 2; c < c1; c++)
        row[2 * c] += whole;
    double len1 = xb - c1, d1 = s * len1;
    row[2 * c1] += (float)((c0 + 1 < c1 ? half : 0) + d1 * (1 - len1 * 0.5));
    row[2 * c1 + 1] += (float)(d1 * len1 * 0.5);
    return c0;
}

/* floor and ceil of a clipped coordinate (0 <= v <= 2^24): inline, where
 * the library calls would cost more than the work around them. */
static inline int floor_clipped(double v)
{
    return (int)v;
}

static inline int ceil_clipped(double v)
{
    int i = (int)v;
    return i + (i < v);
}

/* Adds the part of a line within one row, from x = xa to xb (either way
 * round), and asks for the pixels under its first cell (blended when the
 * band is painted: asking now hides the wait for memory). */
static inline void deposit_step(float *cells, uint64_t *bits, double xa, double xb, double d,
                                double s, const cg_image *image, const unsigned char **pixel_row)
{
    int first = xa <= xb ? deposit_row(cells, bits, xa, xb, d, s)
                         : deposit_row(cells, bits, xb, xa, d, s);
    if (*pixel_row) {
#if defined(__GNUC__)
        __builtin_prefetch(*pixel_row + 4 * (size_t)first, 1, 3);
#else
        (void)first;
#endif
        *pixel_row += image->stride;
    }
}

/* Adds the part of line l within rows [band_top, band_bottom). */
static void deposit_line(float *accumulation, uint64_t *touched, size_t stride, size_t blocks,
                         int band_top, int band_bottom, double origin_x, const fill_line *l,
                         const cg_image *image)
{
    double x0 = l->x0 - origin_x, y0 = l->y0, x1 = l->x1 - origin_x, y1 = l->y1, sign = 1;
    if (y0 > y1) {
        double t = x0;
        x0 = x1;
        x1 = t;
        t = y0;
        y0 = y1;
        y1 = t;
        sign = -1;
    }
    double ys = y0 > band_top ? y0 : band_top, ye = y1 < band_bottom ? y1 : band_bottom;
    if (ys >= ye)
        return;
    double dxdy = (x1 - x0) / (y1 - y0);
    /* area per unit of x: d / |xb - xa| = sign / |dxdy| (unused when the
     * line stays in one column of a row, so dxdy = 0 gives no trouble) */
    double s = dxdy != 0 ? sign / fabs(dxdy) : 0;
    int row = floor_clipped(ys), row_end = ceil_clipped(ye);
    double xa = ys == y0 ? x0 : x0 + (ys - y0) * dxdy, ya = ys;
    float *cells = accumulation + (size_t)(row - band_top) * 2 * stride;
    uint64_t *bits = touched + (size_t)(row - band_top) * blocks;
    /* the pixels under the line (see deposit_step) */
    const unsigned char *pixel_row = image->format == CG_PIXEL_RGBA8
                                         ? image->data + (size_t)row * image->stride
                                               + (size_t)origin_x * 4
                                         : NULL;
    double next = row + 1; /* the next row's top */
    /* Every row but the last is left through its bottom (next < ye), where
     * x follows from the slope; after the first of them a row's height is
     * exactly 1, so its signed height is the sign.  The last row ends at ye
     * (at the line's own end point when ye is y1). */
    double d = sign * (next - ya);
    for (int last = row_end - 1; row < last;
         row++, next += 1, cells += 2 * stride, bits += blocks) {
        double xb = x0 + (next - y0) * dxdy;
        deposit_step(cells, bits, xa, xb, d, s, image, &pixel_row);
        xa = xb;
        ya = next;
        d = sign;
    }
    double xb = ye == y1 ? x1 : x0 + (ye - y0) * dxdy;
    deposit_step(cells, bits, xa, xb, sign * (ye - ya), s, image, &pixel_row);
}

/* min(a, b) as one instruction (a < b ? a : b): the comparisons it replaces
 * went either way at random on the pixels of an interior, where the sum is
 * 1 give or take its last bit, and mispredicted. */
static inline float min_float(float a, float b)
{
    return a < b ? a : b;
}

static inline int coverage_of(float acc, cg_fill_rule rule)
{
    float a = fabsf(acc);
    if (rule == CG_FILL_EVEN_ODD) {
        if (a < 2) {
            /* the usual case: 2 - a exactly where 1 < a < 2 (overlaps of
             * two), a where a <= 1 (then 2 - a >= 1 >= a) */
            a = min_float(a, 2 - a);
        } else {
            a -= 2.0f * (float)(int)(a * 0.5f); /* a >= 0: truncation is floor */
            if (a > 1)
                a = 2 - a;
        }
    } else {
        a = min_float(a, 1);
    }
    return (int)(a * 255.0f + 0.5f);
}

/* Sums cells 0..n-1 of row (two differences each) onto acc, clearing them,
 * and writes each pixel's coverage; returns the sum.  One loop per rule,
 * so neither tests it. */
static inline float sum_cells(float *row, int n, float acc, cg_fill_rule rule, uint8_t *cover)
{
    if (rule == CG_FILL_NONZERO) {
        for (int i = 0; i < n; i++) {
            acc += row[2 * i];
            cover[i] = (uint8_t)coverage_of(acc, CG_FILL_NONZERO);
            acc += row[2 * i + 1];
            row[2 * i] = row[2 * i + 1] = 0;
        }
    } else {
        for (int i = 0; i < n; i++) {
            acc += row[2 * i];
            cover[i] = (uint8_t)coverage_of(acc, CG_FILL_EVEN_ODD);
            acc += row[2 * i + 1];
            row[2 * i] = row[2 * i + 1] = 0;
        }
    }
    return acc;
}

/* Paints x0 .. x1 - 1 of row y with constant coverage c. */
static void constant_span(const fill_painter *painter, int y, int x0, int x1, int c, uint8_t *cover)
{
    if (x1 <= x0 || c == 0)
        return;
    if (c == 255) {
        fill_painter_span(painter, y, x0, x1 - x0, NULL);
        return;
    }
    memset(cover, c, (size_t)(x1 - x0));
    fill_painter_span(painter, y, x0, x1 - x0, cover);
}

/* Sums one row of the accumulation buffer into coverage and paints it with
 * a solid paint on RGBA8 (blend: its state), clearing the cells and bits
 * behind it.  The touched cells are visited one by one through the set bits,
 * each pixel blended as its cell is summed; the pixels between touched
 * cells (a gap) have the coverage of the sum after the cell before. */
static inline void render_row_solid(cg_image *image, const fill_blend_state *blend, float *row,
                                    uint64_t *touched, int width, size_t words, int y, int origin_x,
                                    cg_fill_rule rule)
{
    float acc = 0;
    int done = 0; /* pixels before done are painted */
    uint32_t *pixels = (uint32_t *)cg_image_row_rgba8(image, y) + origin_x;
    for (size_t w = 0; w < words; w++) {
        uint64_t m = touched[w];
        if (!m)
            continue;
        touched[w] = 0;
        do {
            int x = (int)(w << 6) + lowest_bit(m);
            m &= m - 1;
            if (x >= width) { /* deposits right of the last pixel: cleared, unused */
                row[2 * x] = row[2 * x + 1] = 0;
                continue;
            }
            if (x != done) {
                int c = coverage_of(acc, rule);
                if (c == 255 && blend->opaque)
                    fill_store32(pixels + done, x - done, blend->full);
                else if (c != 0)
                    for (int g = done; g < x; g++)
                        fill_solid_cached(blend, pixels + g, c);
            }
            acc += row[2 * x];
            fill_solid_cached(blend, pixels + x, coverage_of(acc, rule));
            acc += row[2 * x + 1];
            row[2 * x] = row[2 * x + 1] = 0;
            done = x + 1;
        } while (m);
    }
    int c = coverage_of(acc, rule);
    if (done < width && c != 0) {
        if (c == 255 && blend->opaque)
            fill_store32(pixels + done, width - done, blend->full);
        else
            for (int g = done; g < width; g++)
                fill_solid_cached(blend, pixels + g, c);
    }
}

/* The same for other paints: each run of touched cells (within one 64-bit
 * word of bits) is summed into cover[] and painted; the gaps between runs
 * are spans of the coverage left by the run before. */
static inline void render_row_paint(const fill_painter *painter, float *row, uint64_t *touched,
                                    int width, size_t words, int y, int origin_x, cg_fill_rule rule,
                                    uint8_t *cover)
{
    float acc = 0;
    int c = 0, done = 0; /* pixels before done are painted; c: the coverage there */
    for (size_t w = 0; w < words; w++) {
        uint64_t m = touched[w];
        if (!m)
            continue;
        touched[w] = 0;
        while (m) {
            int b = lowest_bit(m);
            uint64_t clear = ~m >> b; /* bit i: cell b + i untouched (0 beyond the word) */
            int len = clear ? lowest_bit(clear) : 64 - b;
            m = b + len >= 64 ? 0 : m & (~0ULL << (b + len));
            int start = (int)(w << 6) + b, end = start + len;
            int paint_end = end < width ? end : width;
            if (start < paint_end) {
                constant_span(painter, y, origin_x + done, origin_x + start, c, cover);
                acc = sum_cells(row + 2 * start, paint_end - start, acc, rule, cover);
                fill_painter_span(painter, y, origin_x + start, paint_end - start, cover);
                c = coverage_of(acc, rule); /* of the pixels after the run */
                done = paint_end;
            }
            /* deposits right of the last pixel: cleared, unused */
            for (int x = paint_end > start ? paint_end : start; x < end; x++)
                row[2 * x] = row[2 * x + 1] = 0;
        }
    }
    constant_span(painter, y, origin_x + done, origin_x + width, c, cover);
}

/* Rows y0 .. y1 - 1 of a band: row k's cells at cells + k * row_floats, its
 * bits at touched + k * words.  state: the blend state of a solid paint on
 * RGBA8, NULL for other paints. */
static void render_rows(const fill_painter *painter, const fill_blend_state *state, float *cells,
                        size_t row_floats, uint64_t *touched, size_t words, int width, int y0,
                        int y1, int origin_x, cg_fill_rule rule, uint8_t *cover)
{
    if (state) {
        /* a local copy, which the pixel stores cannot alias */
        fill_blend_state blend = *state;
        for (int y = y0; y < y1; y++, cells += row_floats, touched += words) {
            if (rule == CG_FILL_NONZERO)
                render_row_solid(painter->image, &blend, cells, touched, width, words, y, origin_x,
                                 CG_FILL_NONZERO);
            else
                render_row_solid(painter->image, &blend, cells, touched, width, words, y, origin_x,
                                 CG_FILL_EVEN_ODD);
        }
        return;
    }
    for (int y = y0; y < y1; y++, cells += row_floats, touched += words)
        render_row_paint(painter, cells, touched, width, words, y, origin_x, rule, cover);
}

cg_status fill_aa_render(struct cg_rasterizer *r, cg_image *image, cg_fill_rule rule,
                         const cg_paint *paint)
{
    if (rule != CG_FILL_EVEN_ODD && rule != CG_FILL_NONZERO)
        return CG_EINVAL;
    fill_painter painter;
    cg_status status = fill_painter_init(&painter, r, image, paint);
    if (status != CG_OK)
        return status;
    if (r->line_count == 0)
        return CG_OK;
    int origin_x = floor_clipped(r->min_x), end_x = ceil_clipped(r->max_x);
    int top = floor_clipped(r->min_y), bottom = ceil_clipped(r->max_y);
    if (end_x > image->width)
        end_x = image->width;
    if (bottom > image->height)
        bottom = image->height;
    if (origin_x < 0)
        origin_x = 0;
    if (top < 0)
        top = 0;
    int draw_width = end_x - origin_x;
    size_t stride = (size_t)(end_x - origin_x) + 3;
    int band = (int)(32768 / stride);
    if (band < 1)
        band = 1;
    if (band > 64)
        band = 64;
    int band_count = (bottom - top + band - 1) / band;
    if (draw_width <= 0 || band_count <= 0)
        return CG_OK;
    if (band > bottom - top)
        band = bottom - top;
    size_t blocks = (stride + 63) >> 6; /* 64-bit words of touched bits per row */
    /* The accumulation cells and block flags are all zero between calls:
     * rendering clears what it reads.  Only new memory needs clearing. */
    size_t cells_before = r->accumulation_capacity, flags_before = r->touched_capacity;
    if (core_array_reserve((void **)&r->accumulation, &r->accumulation_capacity,
                           2 * stride * (size_t)band, sizeof *r->accumulation)
            != CG_OK
        || core_array_reserve((void **)&r->touched, &r->touched_capacity, blocks * (size_t)band,
                              sizeof *r->touched)
               != CG_OK
        || core_array_reserve((void **)&r->cover, &r->cover_capacity, stride, 1) != CG_OK
        || core_array_reserve((void **)&r->order, &r->order_capacity,
                              r->line_count + (size_t)band_count + 1, sizeof *r->order)
               != CG_OK
        || core_array_reserve((void **)&r->active, &r->active_capacity, r->line_count,
                              sizeof *r->active)
               != CG_OK)
        return CG_ENOMEM;
    if (r->accumulation_capacity != cells_before)
        memset(r->accumulation, 0, r->accumulation_capacity * sizeof *r->accumulation);
    if (r->touched_capacity != flags_before)
        memset(r->touched, 0, r->touched_capacity * sizeof *r->touched);
    /* Counting sort of the lines by the band of their top. */
    size_t *first = r->order + r->line_count; /* band_count + 1 counters */
    memset(first, 0, ((size_t)band_count + 1) * sizeof *first);
    for (size_t i = 0; i < r->line_count; i++) {
        const fill_line *l = &r->lines[i];
        double ymin = l->y0 < l->y1 ? l->y0 : l->y1;
        int b = (floor_clipped(ymin) - top) / band;
        first[b < 0 ? 0 : b]++;
    }
    size_t sum = 0;
    for (int b = 0; b <= band_count; b++) {
        size_t c = first[b];
        first[b] = sum;
        sum += c;
    }
    /* first[b] is now where band b's lines start; fill and shift. */
    for (size_t i = 0; i < r->line_count; i++) {
        const fill_line *l = &r->lines[i];
        double ymin = l->y0 < l->y1 ? l->y0 : l->y1;
        int b = (floor_clipped(ymin) - top) / band;
        r->order[first[b < 0 ? 0 : b]++] = i;
    }
    int solid = painter.type == CG_PAINT_SOLID && image->format == CG_PIXEL_RGBA8
                && !painter.general;
    fill_blend_state blend = fill_blend_begin(&painter);
    size_t next = 0, active_count = 0;
    for (int b = 0; b < band_count; b++) {
        int band_top = top + b * band, band_bottom = band_top + band;
        if (band_bottom > bottom)
            band_bottom = bottom;
        while (next < first[b])
            r->active[active_count++] = r->order[next++];
        size_t kept = 0;
        for (size_t i = 0; i < active_count; i++) {
            const fill_line *l = &r->lines[r->active[i]];
            deposit_line(r->accumulation, r->touched, stride, blocks, band_top, band_bottom,
                         origin_x, l, image);
            double ymax = l->y0 > l->y1 ? l->y0 : l->y1;
            if (ymax > band_bottom)
                r->active[kept++] = r->active[i];
        }
        active_count = kept;
        render_rows(&painter, solid ? &blend : NULL, r->accumulation, 2 * stride, r->touched,
                    blocks, draw_width, band_top, band_bottom, origin_x, rule, r->cover);
    }
    return CG_OK;
}

static cg_status aa_polygon(cg_rasterizer *r, cg_image *image, const cg_vec2 *points,
                            const int *contour_sizes, int contour_count, cg_fill_rule rule,
                            const cg_paint *paint)
{
    size_t total;
    cg_status status = fill_check_polygon(points, contour_sizes, contour_count, &total);
    if (status != CG_OK)
        return status;
    fill_aa_begin(r, image);
    size_t start = 0;
    for (int c = 0; c < contour_count; c++) {
        size_t n = (size_t)contour_sizes[c];
        for (size_t i = 0; i < n; i++) {
            status = fill_aa_add_line(r, points[start + i], points[start + (i + 1) % n]);
            if (status != CG_OK)
                return status;
        }
        start += n;
    }
    return fill_aa_render(r, image, rule, paint);
}

cg_status cg_rasterizer_fill_polygon_aa(cg_rasterizer *r, cg_image *image, const cg_vec2 *points,
                                        const int *contour_sizes, int contour_count,
                                        cg_fill_rule rule, const cg_paint *paint)
{
    if (!r || !image || !image->data || !paint)
        return CG_EINVAL;
    return aa_polygon(r, image, points, contour_sizes, contour_count, rule, paint);
}

cg_status cg_fill_polygon_aa(cg_image *image, const cg_vec2 *points, const int *contour_sizes,
                             int contour_count, cg_fill_rule rule, const cg_paint *paint)
{
    cg_rasterizer *r;
    cg_status status = cg_rasterizer_create(&r);
    if (status != CG_OK)
        return status;
    status = cg_rasterizer_fill_polygon_aa(r, image, points, contour_sizes, contour_count, rule,
                                           paint);
    cg_rasterizer_free(r);
    return status;
}
