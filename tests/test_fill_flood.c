/* Flood fill and boundary fill against a breadth-first search over pixels. */
#include "check.h"
#include "cg/fill.h"
#include "maze.h"

#include <stdlib.h>
#include <string.h>

static int same(cg_rgba8 a, cg_rgba8 b)
{
    return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

static int near(cg_rgba8 a, cg_rgba8 b, int t)
{
    return abs(a.r - b.r) <= t && abs(a.g - b.g) <= t && abs(a.b - b.b) <= t && abs(a.a - b.a) <= t;
}

/* Reference: breadth-first search from the seed over pixels satisfying the
 * predicate (like the seed, or not like the boundary); paints the region
 * and returns its size. */
static size_t bfs_fill(cg_image *im, int sx, int sy, cg_rgba8 color, int boundary_mode,
                       cg_rgba8 boundary, int eight, int tolerance)
{
    int w = im->width, h = im->height;
    cg_rgba8 seed = cg_image_get_rgba8(im, sx, sy);
    unsigned char *in = calloc((size_t)w * h, 1);
    int *queue = malloc(sizeof(int) * (size_t)w * h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            cg_rgba8 p = cg_image_get_rgba8(im, x, y);
            in[(size_t)y * w + x] = boundary_mode ? !near(p, boundary, tolerance)
                                                  : near(p, seed, tolerance);
        }
    size_t count = 0, head = 0, tail = 0;
    if (in[(size_t)sy * w + sx]) {
        in[(size_t)sy * w + sx] = 2;
        queue[tail++] = sy * w + sx;
    }
    while (head < tail) {
        int v = queue[head++], x = v % w, y = v / w;
        count++;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                if ((dx == 0 && dy == 0) || (!eight && dx && dy))
                    continue;
                int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= w || ny >= h || in[(size_t)ny * w + nx] != 1)
                    continue;
                in[(size_t)ny * w + nx] = 2;
                queue[tail++] = ny * w + nx;
            }
    }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            if (in[(size_t)y * w + x] == 2)
                cg_image_set_rgba8(im, x, y, color);
    free(in);
    free(queue);
    return count;
}

static int images_equal(const cg_image *a, const cg_image *b)
{
    for (int y = 0; y < a->height; y++)
        if (memcmp(a->data + (size_t)y * a->stride, b->data + (size_t)y * b->stride,
                   (size_t)a->width * 4))
            return 0;
    return 1;
}

static cg_rgba8 palette(int k)
{
    static const cg_rgba8 colors[] = {{0, 0, 0, 255},     {255, 255, 255, 255}, {200, 30, 30, 255},
                                      {30, 200, 30, 255}, {3, 2, 1, 255},       {0, 0, 0, 0}};
    return colors[k % 6];
}

/* Random images of a few colours (noise, blobs, or near colours for the
 * tolerance), random seeds, both connectivities, both fills. */
static void random_images(void)
{
    check_rng rng = {0x1234567u};
    int mismatches = 0, runs = 0;
    for (int trial = 0; trial < 3000; trial++) {
        int w = (int)check_rng_int(&rng, 1, 40), h = (int)check_rng_int(&rng, 1, 40);
        cg_image *a, *b;
        cg_image_create(&a, w, h, CG_PIXEL_RGBA8);
        int colors = (int)check_rng_int(&rng, 2, 4), kind = trial % 3;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                cg_rgba8 c;
                if (kind == 0) {
                    c = palette((int)check_rng_int(&rng, 0, colors - 1));
                } else if (kind == 1) { /* noise around grey, for tolerance */
                    uint8_t v = (uint8_t)check_rng_int(&rng, 100, 140);
                    c.r = c.g = c.b = v;
                    c.a = 255;
                } else { /* mostly one colour with random walls */
                    c = palette(check_rng_unit(&rng) < 0.35 ? 1 : 0);
                }
                cg_image_set_rgba8(a, x, y, c);
            }
        cg_image_copy(a, &b);
        int sx = (int)check_rng_int(&rng, 0, w - 1), sy = (int)check_rng_int(&rng, 0, h - 1);
        int eight = check_rng_int(&rng, 0, 1) != 0;
        int tolerance = kind == 1 ? (int)check_rng_int(&rng, 0, 20)
                                  : (int)check_rng_int(&rng, 0, 1) * 3;
        int boundary_mode = check_rng_int(&rng, 0, 3) == 0;
        cg_rgba8 color = palette((int)check_rng_int(&rng, 0, 5));
        cg_rgba8 boundary = palette((int)check_rng_int(&rng, 0, colors - 1));
        size_t filled = 0, expect;
        cg_status st;
        if (boundary_mode)
            st = cg_boundary_fill(a, sx, sy, color, boundary, eight ? CG_CONNECT_8 : CG_CONNECT_4,
                                  tolerance, &filled);
        else
            st = cg_flood_fill(a, sx, sy, color, eight ? CG_CONNECT_8 : CG_CONNECT_4, tolerance,
                               &filled);
        expect = bfs_fill(b, sx, sy, color, boundary_mode, boundary, eight, tolerance);
        runs++;
        if (st != CG_OK || filled != expect || !images_equal(a, b)) {
            if (++mismatches <= 5)
                fprintf(stderr,
                        "trial %d: %dx%d seed %d,%d eight %d tol %d boundary %d: "
                        "filled %zu expected %zu status %d\n",
                        trial, w, h, sx, sy, eight, tolerance, boundary_mode, filled, expect, st);
        }
        cg_image_free(a);
        cg_image_free(b);
    }
    CHECK_MSG(mismatches == 0, "%d of %d random fills differ from the BFS reference", mismatches,
              runs);
}

/* A perfect maze on a grid of cells. */
static cg_image *maze(check_rng *rng, int cells_x, int cells_y)
{
    cg_image *im;
    cg_image_create(&im, 2 * cells_x + 1, 2 * cells_y + 1, CG_PIXEL_RGBA8);
    cg_rgba8 wall = {0, 0, 0, 255}, floor_ = {255, 255, 255, 255};
    maze_draw(im, cells_x, cells_y, check_rng_next(rng), 0, wall, floor_);
    return im;
}

/* A square spiral corridor one pixel wide between one-pixel walls. */
static cg_image *spiral(int size)
{
    cg_image *im;
    cg_image_create(&im, size, size, CG_PIXEL_RGBA8);
    cg_rgba8 wall = {0, 0, 0, 255}, floor_ = {255, 255, 255, 255};
    cg_image_clear_rgba8(im, floor_);
    /* walls: concentric squares at even offsets, each opened by a gap that
     * links it to the next ring, shifted so the corridor spirals. */
    for (int k = 0; 2 * k < size; k += 2) {
        int lo = k, hi = size - 1 - k;
        if (lo > hi)
            break;
        for (int i = lo; i <= hi; i++) {
            cg_image_set_rgba8(im, i, lo, wall);
            cg_image_set_rgba8(im, i, hi, wall);
            cg_image_set_rgba8(im, lo, i, wall);
            cg_image_set_rgba8(im, hi, i, wall);
        }
        if (k > 0 && lo + 1 <= hi)
            cg_image_set_rgba8(im, lo, lo + 1, floor_); /* door into the ring inside */
    }
    return im;
}

static void mazes_and_spirals(void)
{
    check_rng rng = {99};
    for (int t = 0; t < 40; t++) {
        cg_image *a = maze(&rng, (int)check_rng_int(&rng, 1, 60), (int)check_rng_int(&rng, 1, 60)),
                 *b;
        cg_image_copy(a, &b);
        cg_rgba8 red = {255, 0, 0, 255};
        size_t filled;
        int eight = t % 2;
        CHECK(cg_flood_fill(a, 1, 1, red, eight ? CG_CONNECT_8 : CG_CONNECT_4, 0, &filled)
              == CG_OK);
        size_t expect = bfs_fill(b, 1, 1, red, 0, red, eight, 0);
        CHECK_EQ_INT(filled, expect);
        CHECK(images_equal(a, b));
        cg_image_free(a);
        cg_image_free(b);
    }
    for (int size = 5; size < 200; size += 17) {
        cg_image *a = spiral(size), *b;
        cg_image_copy(a, &b);
        cg_rgba8 blue = {0, 0, 255, 255}, wall = {0, 0, 0, 255};
        size_t filled;
        int seed = size / 2;
        int sx = 1, sy = 1;
        (void)seed;
        CHECK(cg_boundary_fill(a, sx, sy, blue, wall, CG_CONNECT_4, 0, &filled) == CG_OK);
        size_t expect = bfs_fill(b, sx, sy, blue, 1, wall, 0, 0);
        CHECK_EQ_INT(filled, expect);
        CHECK(images_equal(a, b));
        cg_image_free(a);
        cg_image_free(b);
    }
}

/* A diagonal wall: 4-connectivity stops at it, 8-connectivity leaks through
 * its one-pixel diagonal gaps. */
static void diagonal_gaps(void)
{
    cg_image *im;
    cg_image_create(&im, 20, 20, CG_PIXEL_RGBA8);
    cg_rgba8 white = {255, 255, 255, 255}, black = {0, 0, 0, 255}, red = {255, 0, 0, 255};
    cg_image_clear_rgba8(im, white);
    for (int i = 0; i < 20; i++)
        cg_image_set_rgba8(im, i, 19 - i, black);
    size_t filled;
    CHECK(cg_flood_fill(im, 0, 0, red, CG_CONNECT_4, 0, &filled) == CG_OK);
    CHECK_EQ_INT(filled, 19 * 20 / 2);
    CHECK(same(cg_image_get_rgba8(im, 19, 19), white));
    CHECK(cg_flood_fill(im, 0, 0, white, CG_CONNECT_8, 0, &filled) == CG_OK);
    CHECK_EQ_INT(filled, 19 * 20 / 2);
    CHECK(cg_flood_fill(im, 0, 0, red, CG_CONNECT_8, 0, &filled) == CG_OK);
    CHECK_EQ_INT(filled, 400 - 20);
    CHECK(same(cg_image_get_rgba8(im, 19, 19), red));
    /* The black diagonal itself is 8-connected but not 4-connected. */
    CHECK(cg_flood_fill(im, 0, 19, white, CG_CONNECT_4, 0, &filled) == CG_OK);
    CHECK_EQ_INT(filled, 1);
    CHECK(cg_flood_fill(im, 1, 18, white, CG_CONNECT_8, 0, &filled) == CG_OK);
    CHECK_EQ_INT(filled, 19);
    cg_image_free(im);
}

static void edge_cases(void)
{
    cg_image *im, *copy;
    cg_image_create(&im, 8, 8, CG_PIXEL_RGBA8);
    cg_rgba8 white = {255, 255, 255, 255}, red = {255, 0, 0, 255};
    cg_image_clear_rgba8(im, white);
    cg_image_copy(im, &copy);
    size_t filled = 77;
    CHECK(cg_flood_fill(im, -1, 0, red, CG_CONNECT_4, 0, &filled) == CG_ERANGE);
    CHECK_EQ_INT(filled, 0);
    CHECK(cg_flood_fill(im, 0, 8, red, CG_CONNECT_4, 0, NULL) == CG_ERANGE);
    CHECK(cg_flood_fill(im, 2147483647, -2147483647 - 1, red, CG_CONNECT_8, 0, NULL) == CG_ERANGE);
    CHECK(cg_flood_fill(im, 0, 0, red, (cg_connectivity)6, 0, NULL) == CG_EINVAL);
    CHECK(cg_flood_fill(im, 0, 0, red, CG_CONNECT_4, -1, NULL) == CG_EINVAL);
    CHECK(cg_flood_fill(im, 0, 0, red, CG_CONNECT_4, 256, NULL) == CG_EINVAL);
    CHECK(cg_flood_fill(NULL, 0, 0, red, CG_CONNECT_4, 0, NULL) == CG_EINVAL);
    CHECK(images_equal(im, copy));
    /* Already the fill colour: the region is found, nothing changes. */
    CHECK(cg_flood_fill(im, 3, 3, white, CG_CONNECT_4, 0, &filled) == CG_OK);
    CHECK_EQ_INT(filled, 64);
    CHECK(images_equal(im, copy));
    /* Boundary fill seeded on the boundary fills nothing. */
    CHECK(cg_boundary_fill(im, 3, 3, red, white, CG_CONNECT_4, 0, &filled) == CG_OK);
    CHECK_EQ_INT(filled, 0);
    CHECK(images_equal(im, copy));
    /* A one-pixel image. */
    cg_image *one;
    cg_image_create(&one, 1, 1, CG_PIXEL_RGBA8);
    CHECK(cg_flood_fill(one, 0, 0, red, CG_CONNECT_8, 0, &filled) == CG_OK);
    CHECK_EQ_INT(filled, 1);
    CHECK(same(cg_image_get_rgba8(one, 0, 0), red));
    cg_image_free(one);
    /* Float images are refused. */
    cg_image *f;
    cg_image_create(&f, 4, 4, CG_PIXEL_RGBAF);
    CHECK(cg_flood_fill(f, 0, 0, red, CG_CONNECT_4, 0, NULL) == CG_EUNSUPPORTED);
    cg_image_free(f);
    cg_image_free(im);
    cg_image_free(copy);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(random_images);
    CHECK_GROUP(mazes_and_spirals);
    CHECK_GROUP(diagonal_gaps);
    CHECK_GROUP(edge_cases);
    return check_finish();
}
