/* The flood and boundary fill traces of cg/trace_steps.h: the notes'
 * scan-line seed fill with a stack of seed pixels.
 *
 *   pop a seed (x, y); if it is already filled, go on;
 *   extend it left and right to the whole run of region pixels [l, r]:
 *
 *        row y - 1   . . # # . . . . # .     each run of region pixels in
 *        row y       # [l . . . . . r] #     columns l .. r (l - 1 .. r + 1
 *        row y + 1   . . . # # . . # # #     for 8-connected regions) on
 *                                            the rows above and below
 *   fill it, and push one seed per run of region pixels next to it (its
 *   rightmost pixel).  The region is the 4- or 8-connected set of pixels
 *   like the seed (flood) or not of the boundary colour (boundary), as
 *   cg_flood_fill and cg_boundary_fill define it; the trace reads the image
 *   and marks what it has filled in a map of its own. */
#include "cg/fill.h"
#include "../core/array.h"
#include "../core/steps.h"

#include <stdlib.h>
#include <string.h>

enum { SHOWN_STACK = 64 };

typedef struct seed_fill {
    const cg_image *image;
    int eight, boundary, tolerance;
    cg_rgba8 reference;
    unsigned char *filled; /* one byte per pixel */
    CORE_ARRAY(cg_vec2) stack;
    cg_step_fn fn;
    void *user;
} seed_fill;

static int near_color(cg_rgba8 a, cg_rgba8 b, int tolerance)
{
    return abs(a.r - b.r) <= tolerance && abs(a.g - b.g) <= tolerance && abs(a.b - b.b) <= tolerance
           && abs(a.a - b.a) <= tolerance;
}

/* In the region and not yet filled. */
static int open_pixel(const seed_fill *f, int x, int y)
{
    if (!cg_image_contains(f->image, x, y) || f->filled[(size_t)y * f->image->width + x])
        return 0;
    int like = near_color(cg_image_get_rgba8(f->image, x, y), f->reference, f->tolerance);
    return f->boundary ? !like : like;
}

/* Pushes a seed for each run of open pixels of row y within [l, r]; the
 * seeds pushed are appended to pushed.  0, or -1 out of memory. */
static int push_runs(seed_fill *f, int l, int r, int y, cg_vec2 *pushed, int *pushed_count)
{
    if (y < 0 || y >= f->image->height)
        return 0;
    if (f->eight) {
        l--;
        r++;
    }
    for (int x = l; x <= r; x++) {
        if (!open_pixel(f, x, y))
            continue;
        while (x + 1 <= r && open_pixel(f, x + 1, y))
            x++;
        cg_vec2 seed = {x, y};
        if (core_array_push(&f->stack, seed) != CG_OK)
            return -1;
        if (*pushed_count < SHOWN_STACK)
            pushed[(*pushed_count)++] = seed;
    }
    return 0;
}

/* One popped seed: its span (if any), the seeds it pushes, the step.
 * 1 when stopped, -1 out of memory. */
static int fill_from(seed_fill *f, cg_vec2 seed, int *pixels, size_t pixel_room)
{
    int x = (int)seed.x, y = (int)seed.y;
    core_step s;
    cg_vec2 pushed[SHOWN_STACK];
    int pushed_count = 0;
    core_step_begin(&s, "stack");
    core_step_pixel(&s, "popped", x, y);
    if (!open_pixel(f, x, y)) {
        core_step_text(&s, "span", "already filled");
        core_step_none(&s, "left");
        core_step_none(&s, "right");
    } else {
        int l = x, r = x;
        while (open_pixel(f, l - 1, y))
            l--;
        while (open_pixel(f, r + 1, y))
            r++;
        memset(f->filled + (size_t)y * f->image->width + l, 1, (size_t)(r - l + 1));
        core_step_text(&s, "span", "filled");
        core_step_integer(&s, "left", l);
        core_step_integer(&s, "right", r);
        if (push_runs(f, l, r, y - 1, pushed, &pushed_count) < 0
            || push_runs(f, l, r, y + 1, pushed, &pushed_count) < 0)
            return -1;
        size_t n = (size_t)(r - l + 1);
        for (size_t i = 0; i < n && i < pixel_room; i++) {
            pixels[2 * i] = l + (int)i;
            pixels[2 * i + 1] = y;
        }
        s.step.pixels = pixels;
        s.step.pixel_count = (int)n;
    }
    core_step_points(&s, "pushed", pushed, (size_t)pushed_count);
    core_step_integer(&s, "stack_size", (long long)f->stack.count);
    size_t shown = f->stack.count < SHOWN_STACK ? f->stack.count : SHOWN_STACK;
    core_step_points(&s, "stack_top", f->stack.data + f->stack.count - shown, shown);
    return core_step_emit(&s, f->fn, f->user) ? 1 : 0;
}

static cg_status seed_fill_steps(const cg_image *image, int x, int y, int boundary,
                                 cg_rgba8 reference, cg_connectivity connectivity, int tolerance,
                                 cg_step_fn step, void *user)
{
    if (!image || !image->data || !step
        || (connectivity != CG_CONNECT_4 && connectivity != CG_CONNECT_8) || tolerance < 0
        || tolerance > 255)
        return CG_EINVAL;
    if (image->format != CG_PIXEL_RGBA8)
        return CG_EUNSUPPORTED;
    if (!cg_image_contains(image, x, y))
        return CG_ERANGE;
    seed_fill f = {
        image, connectivity == CG_CONNECT_8, boundary, tolerance, reference, NULL, {0}, step, user};
    if (!boundary)
        f.reference = cg_image_get_rgba8(image, x, y);
    f.filled = calloc((size_t)image->height, (size_t)image->width);
    int *pixels = malloc((size_t)image->width * 2 * sizeof *pixels);
    int outcome = f.filled && pixels ? 0 : -1;
    if (outcome == 0 && core_array_push(&f.stack, cg_vec2_make(x, y)) != CG_OK)
        outcome = -1;
    while (outcome == 0 && f.stack.count > 0) {
        cg_vec2 seed = f.stack.data[--f.stack.count];
        outcome = fill_from(&f, seed, pixels, (size_t)image->width);
    }
    free(f.filled);
    free(pixels);
    free(f.stack.data);
    return outcome < 0 ? CG_ENOMEM : CG_OK;
}

cg_status cg_flood_fill_steps(const cg_image *image, int x, int y, cg_connectivity connectivity,
                              int tolerance, cg_step_fn step, void *user)
{
    cg_rgba8 unused = {0, 0, 0, 0};
    return seed_fill_steps(image, x, y, 0, unused, connectivity, tolerance, step, user);
}

cg_status cg_boundary_fill_steps(const cg_image *image, int x, int y, cg_rgba8 boundary,
                                 cg_connectivity connectivity, int tolerance, cg_step_fn step,
                                 void *user)
{
    return seed_fill_steps(image, x, y, 1, boundary, connectivity, tolerance, step, user);
}
