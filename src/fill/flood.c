/* Seed fill and boundary fill (section 10.1) by the scan-line span method.
 *
 * A stack entry says: "row y, columns left..right, may hold pixels of the
 * region; the row y - dir next to it holds a painted span parent_left..
 * parent_right".  Popping it scans the columns, and for every run of region
 * pixels found there: extends the run to its full width, paints it, pushes
 * the row beyond it (same direction) and, where the run sticks out past its
 * parent, the parts of the row behind it that the parent did not cover.
 * Every pixel is painted once; the stack lives on the heap and grows. */
#include "cg/fill.h"
#include "../core/array.h"
#include "../core/simd4.h"

#include <stdlib.h>
#include <string.h>

typedef struct span_entry {
    int left, right, y, dir, parent_left, parent_right;
} span_entry;

enum { MODE_SEED_EXACT, MODE_SEED_TOLERANCE, MODE_BOUNDARY };

typedef struct flood {
    unsigned char *data;
    size_t stride;
    int width, height;
    int mode, tolerance;
    cg_rgba8 reference; /* the seed colour or the boundary colour */
    uint32_t reference_bits, color_bits;
    uint8_t *visited; /* one bit per pixel, or NULL when painting marks visits */
    size_t visited_stride;
    span_entry *stack;
    size_t count, capacity;
    size_t filled;
} flood;

static uint32_t pack(cg_rgba8 c)
{
    uint32_t v;
    memcpy(&v, &c, sizeof v);
    return v;
}

static int near_color(cg_rgba8 a, cg_rgba8 b, int tolerance)
{
    return abs(a.r - b.r) <= tolerance && abs(a.g - b.g) <= tolerance && abs(a.b - b.b) <= tolerance
           && abs(a.a - b.a) <= tolerance;
}

static inline uint32_t *row_of(const flood *f, int y)
{
    return (uint32_t *)(f->data + (size_t)y * f->stride);
}

/* Whether pixel x of row (row y) belongs to the region and is not yet painted. */
static inline int inside(const flood *f, const uint32_t *row, int x, int y)
{
    uint32_t p = row[x];
    if (f->mode == MODE_SEED_EXACT) {
        if (p != f->reference_bits)
            return 0;
    } else {
        cg_rgba8 c;
        memcpy(&c, &p, sizeof c);
        int like = f->tolerance == 0 ? p == f->reference_bits
                                     : near_color(c, f->reference, f->tolerance);
        if (like != (f->mode != MODE_BOUNDARY))
            return 0;
    }
    if (f->visited)
        return !((f->visited[(size_t)y * f->visited_stride + ((unsigned)x >> 3)] >> (x & 7)) & 1);
    return 1;
}

static void paint(flood *f, uint32_t *row, int y, int left, int right)
{
    for (int x = left; x <= right; x++)
        row[x] = f->color_bits;
    if (f->visited) {
        uint8_t *bits = f->visited + (size_t)y * f->visited_stride;
        for (int x = left; x <= right; x++)
            bits[(unsigned)x >> 3] |= (uint8_t)(1u << (x & 7));
    }
    f->filled += (size_t)(right - left + 1);
}

static int push(flood *f, int left, int right, int y, int dir, int parent_left, int parent_right)
{
    if (y < 0 || y >= f->height)
        return 1;
    if (left < 0)
        left = 0;
    if (right > f->width - 1)
        right = f->width - 1;
    if (left > right)
        return 1;
    if (core_array_reserve((void **)&f->stack, &f->capacity, f->count + 1, sizeof *f->stack)
        != CG_OK)
        return 0;
    span_entry e = {left, right, y, dir, parent_left, parent_right};
    f->stack[f->count++] = e;
    return 1;
}

#if defined(__GNUC__)
#define FLOOD_SPECIALIZE __attribute__((always_inline)) inline
#else
#define FLOOD_SPECIALIZE inline
#endif

/* The common case, an exact seed fill whose colour differs from the seed's:
 * a pixel is in the region exactly when it still has the seed's colour, and
 * painting marks it done.  Scanning and painting then go together, four
 * pixels at a time.  From pixel t (in the region, painted), paints and
 * returns the last region pixel at or before `last` going right... */
static inline int extend_right_exact(uint32_t *row, int t, int last, uint32_t reference,
                                     uint32_t color)
{
    i4 ref4 = i4_set((int)reference), color4 = i4_set((int)color);
    while (t + 4 <= last && i4_all_equal(i4_load(row + t + 1), ref4)) {
        i4_store(row + t + 1, color4);
        t += 4;
    }
    while (t < last && row[t + 1] == reference)
        row[++t] = color;
    return t;
}

/* ...and going left, down to column 0. */
static inline int extend_left_exact(uint32_t *row, int s, uint32_t reference, uint32_t color)
{
    i4 ref4 = i4_set((int)reference), color4 = i4_set((int)color);
    while (s >= 4 && i4_all_equal(i4_load(row + s - 4), ref4)) {
        i4_store(row + s - 4, color4);
        s -= 4;
    }
    while (s > 0 && row[s - 1] == reference)
        row[--s] = color;
    return s;
}

/* The span loop; `exact` (a constant in each specialization) selects the
 * fast case above. */
static FLOOD_SPECIALIZE cg_status run_spans(flood *f, int sx, int sy, int eight, int exact)
{
    int k = eight ? 1 : 0, w = f->width;
    uint32_t reference = f->reference_bits, color = f->color_bits;
    uint32_t *row = row_of(f, sy);
    if (exact ? row[sx] != reference : !inside(f, row, sx, sy))
        return CG_OK;
    int left = sx, right = sx;
    if (exact) {
        row[sx] = color;
        left = extend_left_exact(row, sx, reference, color);
        right = extend_right_exact(row, sx, w - 1, reference, color);
        f->filled += (size_t)(right - left + 1);
    } else {
        while (left > 0 && inside(f, row, left - 1, sy))
            left--;
        while (right < w - 1 && inside(f, row, right + 1, sy))
            right++;
        paint(f, row, sy, left, right);
    }
    if (!push(f, left - k, right + k, sy + 1, 1, left, right)
        || !push(f, left - k, right + k, sy - 1, -1, left, right))
        return CG_ENOMEM;
    while (f->count) {
        span_entry e = f->stack[--f->count];
        int y = e.y;
        row = row_of(f, y);
        for (int x = e.left; x <= e.right; x++) {
            int s, t;
            if (exact) {
                if (row[x] != reference)
                    continue;
                row[x] = color;
                s = extend_left_exact(row, x, reference, color);
                t = extend_right_exact(row, x, w - 1, reference, color);
                f->filled += (size_t)(t - s + 1);
            } else {
                if (!inside(f, row, x, y))
                    continue;
                s = x;
                t = x;
                while (s > 0 && inside(f, row, s - 1, y))
                    s--;
                while (t < w - 1 && inside(f, row, t + 1, y))
                    t++;
                paint(f, row, y, s, t);
            }
            if (!push(f, s - k, t + k, y + e.dir, e.dir, s, t))
                return CG_ENOMEM;
            /* Behind: the neighbours of s..t in the parent row that the
             * parent span did not cover. */
            if (s - k < e.parent_left
                && !push(f, s - k, e.parent_left - 1, y - e.dir, -e.dir, s, t))
                return CG_ENOMEM;
            if (t + k > e.parent_right
                && !push(f, e.parent_right + 1, t + k, y - e.dir, -e.dir, s, t))
                return CG_ENOMEM;
            x = t + 1; /* t + 1 is outside the region (or the image) */
        }
    }
    return CG_OK;
}

static cg_status run(flood *f, int sx, int sy, int eight)
{
    if (f->mode == MODE_SEED_EXACT && !f->visited)
        return eight ? run_spans(f, sx, sy, 1, 1) : run_spans(f, sx, sy, 0, 1);
    return run_spans(f, sx, sy, eight, 0);
}

static cg_status fill_common(cg_image *image, int x, int y, cg_rgba8 color, int mode,
                             cg_rgba8 boundary, cg_connectivity connectivity, int tolerance,
                             size_t *filled)
{
    if (filled)
        *filled = 0;
    if (!image || !image->data)
        return CG_EINVAL;
    if (connectivity != CG_CONNECT_4 && connectivity != CG_CONNECT_8)
        return CG_EINVAL;
    if (tolerance < 0 || tolerance > 255)
        return CG_EINVAL;
    if (image->format != CG_PIXEL_RGBA8)
        return CG_EUNSUPPORTED;
    if (!cg_image_contains(image, x, y))
        return CG_ERANGE;
    flood f;
    memset(&f, 0, sizeof f);
    f.data = image->data;
    f.stride = image->stride;
    f.width = image->width;
    f.height = image->height;
    f.tolerance = tolerance;
    f.color_bits = pack(color);
    if (mode == MODE_BOUNDARY) {
        f.mode = MODE_BOUNDARY;
        f.reference = boundary;
    } else {
        f.reference = cg_image_row_rgba8(image, y)[x];
        f.mode = tolerance == 0 ? MODE_SEED_EXACT : MODE_SEED_TOLERANCE;
    }
    f.reference_bits = pack(f.reference);
    /* When painted pixels would still look like region pixels, a bit per
     * pixel remembers which are done. */
    int like = near_color(color, f.reference, tolerance);
    if (like == (mode != MODE_BOUNDARY)) {
        f.visited_stride = ((size_t)f.width + 7) / 8;
        f.visited = calloc((size_t)f.height, f.visited_stride);
        if (!f.visited)
            return CG_ENOMEM;
    }
    cg_status status = run(&f, x, y, connectivity == CG_CONNECT_8);
    free(f.visited);
    free(f.stack);
    if (filled)
        *filled = f.filled;
    return status;
}

cg_status cg_flood_fill(cg_image *image, int x, int y, cg_rgba8 color, cg_connectivity connectivity,
                        int tolerance, size_t *filled)
{
    cg_rgba8 none = {0, 0, 0, 0};
    return fill_common(image, x, y, color, MODE_SEED_EXACT, none, connectivity, tolerance, filled);
}

cg_status cg_boundary_fill(cg_image *image, int x, int y, cg_rgba8 color, cg_rgba8 boundary,
                           cg_connectivity connectivity, int tolerance, size_t *filled)
{
    return fill_common(image, x, y, color, MODE_BOUNDARY, boundary, connectivity, tolerance,
                       filled);
}
