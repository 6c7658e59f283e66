/* libcg-bgi: pixels, lines, circles, arcs, ellipses, outlines and text, drawn
 * by cg's scan conversion (cg/draw.h) in the current colour. */
#include "internal.h"

#include "cg/draw.h"
#include "font5x7.h"

#include <stdlib.h>

void cg_bgi_putpixel(int x, int y, int color)
{
    bgi_screen *s = bgi_open_screen();
    if (!s || !cg_image_contains(s->image, x, y))
        return;
    cg_image_set_rgba8(s->image, x, y, bgi_palette(color));
    bgi_show(s, 0);
}

unsigned cg_bgi_getpixel(int x, int y)
{
    bgi_screen *s = bgi_open_screen();
    if (!s || !cg_image_contains(s->image, x, y))
        return 0;
    cg_rgba8 c = cg_image_get_rgba8(s->image, x, y);
    for (int i = 0; i < 16; i++) {
        cg_rgba8 p = bgi_palette(i);
        if (p.r == c.r && p.g == c.g && p.b == c.b)
            return (unsigned)i;
    }
    return 0;
}

void cg_bgi_line(int x1, int y1, int x2, int y2)
{
    bgi_screen *s = bgi_open_screen();
    if (!s)
        return;
    cg_draw_line(s->image, x1, y1, x2, y2, bgi_palette(s->color));
    bgi_show(s, 0);
}

void cg_bgi_moveto(int x, int y)
{
    bgi_screen *s = bgi_open_screen();
    if (!s)
        return;
    s->x = x;
    s->y = y;
}

void cg_bgi_moverel(int dx, int dy)
{
    bgi_screen *s = bgi_open_screen();
    if (s)
        cg_bgi_moveto(s->x + dx, s->y + dy);
}

void cg_bgi_lineto(int x, int y)
{
    bgi_screen *s = bgi_open_screen();
    if (!s)
        return;
    cg_bgi_line(s->x, s->y, x, y);
    cg_bgi_moveto(x, y);
}

void cg_bgi_linerel(int dx, int dy)
{
    bgi_screen *s = bgi_open_screen();
    if (s)
        cg_bgi_lineto(s->x + dx, s->y + dy);
}

int cg_bgi_getx(void)
{
    return bgi_the_screen.x;
}

int cg_bgi_gety(void)
{
    return bgi_the_screen.y;
}

void cg_bgi_circle(int x, int y, int radius)
{
    bgi_screen *s = bgi_open_screen();
    if (!s)
        return;
    cg_draw_circle(s->image, x, y, radius < 0 ? -radius : radius, bgi_palette(s->color));
    bgi_show(s, 0);
}

void cg_bgi_arc(int x, int y, int start, int end, int radius)
{
    bgi_screen *s = bgi_open_screen();
    if (!s)
        return;
    if (end < start)
        end += 360 * ((start - end) / 360 + 1);
    cg_draw_arc(s->image, x, y, radius < 0 ? -radius : radius, start, end, bgi_palette(s->color));
    bgi_show(s, 0);
}

void cg_bgi_ellipse(int x, int y, int start, int end, int xradius, int yradius)
{
    bgi_screen *s = bgi_open_screen();
    if (!s)
        return;
    int rx = xradius < 0 ? -xradius : xradius, ry = yradius < 0 ? -yradius : yradius;
    if (end < start)
        end += 360 * ((start - end) / 360 + 1);
    if (end - start >= 360)
        cg_draw_ellipse(s->image, x, y, rx, ry, bgi_palette(s->color));
    else
        cg_draw_ellipse_arc(s->image, x, y, rx, ry, start, end, bgi_palette(s->color));
    bgi_show(s, 0);
}

void cg_bgi_rectangle(int left, int top, int right, int bottom)
{
    bgi_screen *s = bgi_open_screen();
    if (!s)
        return;
    int xy[10] = {left, top, right, top, right, bottom, left, bottom, left, top};
    cg_draw_polyline(s->image, xy, 5, bgi_palette(s->color));
    bgi_show(s, 0);
}

void cg_bgi_drawpoly(int count, const int *points)
{
    bgi_screen *s = bgi_open_screen();
    if (!s || count < 1 || !points)
        return;
    cg_draw_polyline(s->image, points, count, bgi_palette(s->color));
    bgi_show(s, 0);
}

void cg_bgi_setcolor(int color)
{
    bgi_the_screen.color = color & 15;
}

int cg_bgi_getcolor(void)
{
    return bgi_the_screen.color;
}

void cg_bgi_setbkcolor(int color)
{
    bgi_the_screen.background = color & 15;
}

int cg_bgi_getbkcolor(void)
{
    return bgi_the_screen.background;
}

void cg_bgi_outtextxy(int x, int y, const char *text)
{
    bgi_screen *s = bgi_open_screen();
    if (!s || !text)
        return;
    font_draw(s->image, x, y, 1, text, bgi_palette(s->color));
    bgi_show(s, 0);
}

void cg_bgi_cleardevice(void)
{
    bgi_screen *s = bgi_open_screen();
    if (!s)
        return;
    cg_image_clear_rgba8(s->image, bgi_palette(s->background));
    s->x = s->y = 0;
    bgi_show(s, 1);
}
