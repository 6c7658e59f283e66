/* Flood fill of a 20,000 x 20,000 spiral: one corridor, one pixel wide,
 * about 200 million pixels long, which a recursive fill could never follow
 * (issue 4: "a 20,000 x 20,000 maze or spiral fills without stack
 * overflow").  The image takes 1.6 GB, so the test is skipped (exit code 77,
 * reported by ctest as skipped) in sanitizer builds, where it would take
 * minutes and several times the memory.
 *
 * The spiral, by definition: pixel (x, y) lies on ring d = its distance to
 * the nearest border, min(x, y, n-1-x, n-1-y).  Even rings are walls, odd
 * rings corridors.  Wall ring k > 0 has a door at (k, k+1) linking corridor
 * ring k-1 to corridor ring k+1; corridor ring j >= 3 entered by such a door
 * is blocked at (j, j+1), between the door and the next one, so the corridor
 * runs all the way round each ring before going in: one long path. */
#include "check.h"
#include "cg/fill.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SKIPPED 77

static int wall(int x, int y, int n)
{
    int d = x < y ? x : y;
    if (n - 1 - x < d)
        d = n - 1 - x;
    if (n - 1 - y < d)
        d = n - 1 - y;
    /* (d, d+1) lies on ring d exactly when 2d <= n - 2 */
    int special = x == d && y == d + 1 && 2 * d <= n - 2;
    if (d % 2 == 0)
        return !(special && d > 0);                   /* door */
    return special && d >= 3 && 2 * (d - 1) <= n - 2; /* blocker after a door */
}

/* The corridor's length, counted ring by ring from the definition. */
static size_t corridor_size(int n)
{
    size_t count = 0;
    for (int d = 0; 2 * d <= n - 1; d++) {
        int side = n - 2 * d;
        size_t ring = side == 1 ? 1 : 4 * (size_t)(side - 1);
        int special = 2 * d <= n - 2;
        if (d % 2) {
            count += ring;
            if (special && d >= 3 && 2 * (d - 1) <= n - 2)
                count--; /* blocker */
        } else if (d > 0 && special) {
            count++; /* door */
        }
    }
    return count;
}

/* Row y of the spiral, fast: ring d is x in the left band, n-1-x in the right
 * band and min(y, n-1-y) between them; only pixel (y-1, y) can be a door or
 * a blocker.  Checked against wall() pixel by pixel on small spirals. */
static void spiral_row(cg_rgba8 *row, int y, int n, cg_rgba8 wall_color, cg_rgba8 floor_color)
{
    int dy = y < n - 1 - y ? y : n - 1 - y;
    cg_rgba8 two[2] = {wall_color, floor_color}; /* by the ring's parity */
    for (int x = 0; x < dy; x++)
        row[x] = two[x & 1];
    for (int x = dy; x <= n - 1 - dy; x++)
        row[x] = two[dy & 1];
    for (int x = n - dy; x < n; x++)
        row[x] = two[(n - 1 - x) & 1];
    if (y >= 1 && y - 1 < n)
        row[y - 1] = wall(y - 1, y, n) ? wall_color : floor_color;
}

static cg_image *spiral(int n, cg_rgba8 wall_color, cg_rgba8 floor_color)
{
    cg_image *im;
    if (cg_image_create(&im, n, n, CG_PIXEL_RGBA8) != CG_OK)
        return NULL;
    for (int y = 0; y < n; y++)
        spiral_row(cg_image_row_rgba8(im, y), y, n, wall_color, floor_color);
    return im;
}

static int same(cg_rgba8 a, cg_rgba8 b)
{
    return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

/* Rows not as the definition says: walls wall_color, corridor corridor_color. */
static size_t mismatches(cg_image *im, cg_rgba8 wall_color, cg_rgba8 corridor_color)
{
    size_t bad = 0;
    int n = im->width;
    cg_rgba8 *expect = malloc(sizeof *expect * (size_t)n);
    if (!expect)
        return (size_t)n;
    for (int y = 0; y < n; y++) {
        spiral_row(expect, y, n, wall_color, corridor_color);
        bad += memcmp(expect, cg_image_row_rgba8(im, y), sizeof *expect * (size_t)n) != 0;
    }
    free(expect);
    return bad;
}

static const cg_rgba8 black = {0, 0, 0, 255}, white = {255, 255, 255, 255}, red = {255, 0, 0, 255};

/* Small spirals: the corridor is one 4-connected region whose size is the
 * count by construction, so the definition and the count can be trusted. */
static void small_spirals(void)
{
    for (int n = 3; n <= 80; n++) {
        cg_image *im = spiral(n, black, white);
        size_t direct = 0, wrong = 0;
        for (int y = 0; y < n; y++)
            for (int x = 0; x < n; x++) {
                direct += !wall(x, y, n);
                wrong += !same(cg_image_get_rgba8(im, x, y), wall(x, y, n) ? black : white);
            }
        CHECK_EQ_INT(wrong, 0);
        CHECK_EQ_INT(direct, corridor_size(n));
        size_t filled = 0;
        CHECK(cg_flood_fill(im, 1, 1, red, CG_CONNECT_4, 0, &filled) == CG_OK);
        CHECK_MSG(filled == corridor_size(n), "n %d: filled %zu of %zu", n, filled,
                  corridor_size(n));
        CHECK_EQ_INT(mismatches(im, black, red), 0);
        cg_image_free(im);
    }
}

int main(void)
{
    small_spirals();
#if defined(CG_TEST_SANITIZED) || defined(__SANITIZE_ADDRESS__)
    fprintf(stderr, "the 20,000 x 20,000 spiral is skipped: it needs 1.6 GB and minutes under "
                    "the sanitizers; the Release build runs it\n");
    return check_finish();
#else
    const int n = 20000;
    const cg_rgba8 green = {0, 160, 0, 255};
    cg_image *im = spiral(n, black, white);
    if (!im) {
        fprintf(stderr, "skipped: cannot allocate a %d x %d image (1.6 GB)\n", n, n);
        return SKIPPED;
    }
    size_t corridor = corridor_size(n), filled = 0;
    /* 4-connected from the outermost corridor... */
    CHECK(cg_flood_fill(im, 1, 1, red, CG_CONNECT_4, 0, &filled) == CG_OK);
    CHECK_EQ_INT(filled, corridor);
    CHECK_EQ_INT(mismatches(im, black, red), 0);
    /* ...then 8-connected from the innermost (the corner walls are solid, so
     * diagonal steps open no shortcut). */
    CHECK(!wall(n / 2 - 1, n / 2 - 1, n));
    CHECK(cg_flood_fill(im, n / 2 - 1, n / 2 - 1, green, CG_CONNECT_8, 0, &filled) == CG_OK);
    CHECK_EQ_INT(filled, corridor);
    cg_rgba8 spot[4] = {cg_image_get_rgba8(im, 1, 1), cg_image_get_rgba8(im, n - 2, n / 2),
                        cg_image_get_rgba8(im, 0, 0), cg_image_get_rgba8(im, 3, 4)};
    CHECK(same(spot[0], green) && same(spot[1], green));
    CHECK(same(spot[2], black) && same(spot[3], black)); /* border, first blocker */
    CHECK_EQ_INT(mismatches(im, black, green), 0);
    printf("spiral %d x %d: corridor of %zu pixels filled 4- and 8-connected\n", n, n, corridor);
    cg_image_free(im);
    return check_finish();
#endif
}
