/* libcg-bgi: the filled shapes, bar, fillpoly and floodfill, painted with the
 * fill style: cg's scan-line fill gives the pixels of bars and polygons,
 * its boundary fill the region of floodfill. */
#include "internal.h"

#include "cg/draw.h"
#include "cg/fill.h"
#include "cg/trace_steps.h"

#include <stdlib.h>

/* Rows top to bottom, the leftmost pixel in bit 7. */
static const unsigned char patterns[12][8] = {
    {0, 0, 0, 0, 0, 0, 0, 0},                         /* empty */
    {0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff}, /* solid */
    {0xff, 0xff, 0, 0, 0xff, 0xff, 0, 0},             /* line */
    {0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x40, 0x80}, /* thin slash */
    {0x03, 0x07, 0x0e, 0x1c, 0x38, 0x70, 0xe0, 0xc1}, /* slash */
    {0xc0, 0xe0, 0x70, 0x38, 0x1c, 0x0e, 0x07, 0x83}, /* backslash */
    {0x80, 0x40, 0x20, 0x10, 0x08, 0x04, 0x02, 0x01}, /* thin backslash */
    {0xff, 0x88, 0x88, 0x88, 0xff, 0x88, 0x88, 0x88}, /* hatch */
    {0x81, 0x42, 0x24, 0x18, 0x18, 0x24, 0x42, 0x81}, /* cross-hatch */
    {0xcc, 0x33, 0xcc, 0x33, 0xcc, 0x33, 0xcc, 0x33}, /* interleave */
    {0x80, 0x00, 0x08, 0x00, 0x80, 0x00, 0x08, 0x00}, /* wide dots */
    {0x88, 0x00, 0x22, 0x00, 0x88, 0x00, 0x22, 0x00}, /* close dots */
};

void cg_bgi_setfillstyle(int pattern, int color)
{
    bgi_screen *s = &bgi_the_screen;
    if (pattern < CG_BGI_EMPTY_FILL || pattern > CG_BGI_USER_FILL) {
        s->result = CG_BGI_ERROR;
        return;
    }
    s->fill_pattern = pattern == CG_BGI_USER_FILL ? CG_BGI_SOLID_FILL : pattern;
    s->fill_color = color & 15;
}

void bgi_fill_pixel(bgi_screen *s, int x, int y)
{
    int set = (patterns[s->fill_pattern][y & 7] >> (7 - (x & 7))) & 1;
    cg_image_set_rgba8(s->image, x, y, bgi_palette(set ? s->fill_color : s->background));
}

/* A cg_step_fn painting the step's pixels that are on the screen. */
static int paint_step(void *user, const cg_step *step)
{
    bgi_screen *s = user;
    for (int i = 0; i < step->pixel_count; i++) {
        int x = step->pixels[2 * i], y = step->pixels[2 * i + 1];
        if (cg_image_contains(s->image, x, y))
            bgi_fill_pixel(s, x, y);
    }
    return 0;
}

/* Coordinates the scan-line fill takes (its traces stop at 4096). */
static int clamp(int v)
{
    return v < -4000 ? -4000 : v > 4000 ? 4000 : v;
}

void cg_bgi_bar(int left, int top, int right, int bottom)
{
    bgi_screen *s = bgi_open_screen();
    if (!s)
        return;
    int l = clamp(left < right ? left : right), r = clamp(left < right ? right : left);
    int t = clamp(top < bottom ? top : bottom), b = clamp(top < bottom ? bottom : top);
    /* The pixels l..r, t..b: their centres lie inside [l, r + 1] x [t, b + 1]. */
    cg_vec2 corners[4] = {{l, t}, {r + 1, t}, {r + 1, b + 1}, {l, b + 1}};
    int size = 4;
    cg_scanline_fill_steps(corners, &size, 1, CG_FILL_EVEN_ODD, paint_step, s);
    bgi_show(s, 0);
}

void cg_bgi_fillpoly(int count, const int *points)
{
    bgi_screen *s = bgi_open_screen();
    if (!s || count < 1 || !points)
        return;
    cg_vec2 *centres = malloc((size_t)count * sizeof *centres);
    int *outline = malloc(((size_t)count + 1) * 2 * sizeof *outline);
    if (!centres || !outline) {
        free(centres);
        free(outline);
        s->result = CG_BGI_NO_MEMORY;
        return;
    }
    /* Vertices at pixel centres: the pixels whose centres are inside. */
    for (int i = 0; i < count; i++)
        centres[i] = (cg_vec2){clamp(points[2 * i]) + 0.5, clamp(points[2 * i + 1]) + 0.5};
    for (int i = 0; i < 2 * count; i++)
        outline[i] = points[i];
    outline[2 * count] = points[0];
    outline[2 * count + 1] = points[1];
    if (count >= 3)
        cg_scanline_fill_steps(centres, &count, 1, CG_FILL_EVEN_ODD, paint_step, s);
    cg_draw_polyline(s->image, outline, count + 1, bgi_palette(s->color));
    free(centres);
    free(outline);
    bgi_show(s, 0);
}

void cg_bgi_floodfill(int x, int y, int border)
{
    bgi_screen *s = bgi_open_screen();
    if (!s || !cg_image_contains(s->image, x, y))
        return;
    /* The region: boundary fill of a copy with a colour no palette entry
     * has, then the fill style over the pixels it took. */
    cg_image *copy;
    if (cg_image_copy(s->image, &copy) != CG_OK) {
        s->result = CG_BGI_NO_MEMORY;
        return;
    }
    cg_rgba8 mark = {1, 2, 3, 255};
    if (cg_boundary_fill(copy, x, y, mark, bgi_palette(border), CG_CONNECT_4, 0, NULL) == CG_OK)
        for (int j = 0; j < copy->height; j++)
            for (int i = 0; i < copy->width; i++) {
                cg_rgba8 c = cg_image_get_rgba8(copy, i, j);
                if (c.r == mark.r && c.g == mark.g && c.b == mark.b)
                    bgi_fill_pixel(s, i, j);
            }
    else
        s->result = CG_BGI_ERROR;
    cg_image_free(copy);
    bgi_show(s, 0);
}
