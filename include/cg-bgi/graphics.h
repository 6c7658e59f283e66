/* graphics.h - the Turbo C BGI names for cg's BGI library (cg/bgi.h).
 * Build a lab program with: cc prog.c $(pkg-config --cflags --libs cg-bgi) */
#ifndef CG_BGI_GRAPHICS_H
#define CG_BGI_GRAPHICS_H

#include <cg/bgi.h>

enum {
    BLACK = CG_BGI_BLACK,
    BLUE = CG_BGI_BLUE,
    GREEN = CG_BGI_GREEN,
    CYAN = CG_BGI_CYAN,
    RED = CG_BGI_RED,
    MAGENTA = CG_BGI_MAGENTA,
    BROWN = CG_BGI_BROWN,
    LIGHTGRAY = CG_BGI_LIGHTGRAY,
    DARKGRAY = CG_BGI_DARKGRAY,
    LIGHTBLUE = CG_BGI_LIGHTBLUE,
    LIGHTGREEN = CG_BGI_LIGHTGREEN,
    LIGHTCYAN = CG_BGI_LIGHTCYAN,
    LIGHTRED = CG_BGI_LIGHTRED,
    LIGHTMAGENTA = CG_BGI_LIGHTMAGENTA,
    YELLOW = CG_BGI_YELLOW,
    WHITE = CG_BGI_WHITE
};

enum {
    EMPTY_FILL = CG_BGI_EMPTY_FILL,
    SOLID_FILL = CG_BGI_SOLID_FILL,
    LINE_FILL = CG_BGI_LINE_FILL,
    LTSLASH_FILL = CG_BGI_LTSLASH_FILL,
    SLASH_FILL = CG_BGI_SLASH_FILL,
    BKSLASH_FILL = CG_BGI_BKSLASH_FILL,
    LTBKSLASH_FILL = CG_BGI_LTBKSLASH_FILL,
    HATCH_FILL = CG_BGI_HATCH_FILL,
    XHATCH_FILL = CG_BGI_XHATCH_FILL,
    INTERLEAVE_FILL = CG_BGI_INTERLEAVE_FILL,
    WIDE_DOT_FILL = CG_BGI_WIDE_DOT_FILL,
    CLOSE_DOT_FILL = CG_BGI_CLOSE_DOT_FILL,
    USER_FILL = CG_BGI_USER_FILL
};

enum { DETECT = CG_BGI_DETECT, VGA = CG_BGI_VGA, VGAHI = CG_BGI_VGAHI };

enum {
    grOk = CG_BGI_OK,
    grNoInitGraph = CG_BGI_NO_INIT_GRAPH,
    grNotDetected = CG_BGI_NOT_DETECTED,
    grNoLoadMem = CG_BGI_NO_MEMORY,
    grError = CG_BGI_ERROR
};

/* Function-like macros: a variable called line or bar keeps its name. */
#define initgraph(driver, mode, path) cg_bgi_initgraph(driver, mode, path)
#define closegraph() cg_bgi_closegraph()
#define graphresult() cg_bgi_graphresult()
#define grapherrormsg(code) cg_bgi_grapherrormsg(code)
#define getmaxx() cg_bgi_getmaxx()
#define getmaxy() cg_bgi_getmaxy()
#define putpixel(x, y, color) cg_bgi_putpixel(x, y, color)
#define getpixel(x, y) cg_bgi_getpixel(x, y)
#define line(x1, y1, x2, y2) cg_bgi_line(x1, y1, x2, y2)
#define lineto(x, y) cg_bgi_lineto(x, y)
#define linerel(dx, dy) cg_bgi_linerel(dx, dy)
#define moveto(x, y) cg_bgi_moveto(x, y)
#define moverel(dx, dy) cg_bgi_moverel(dx, dy)
#define getx() cg_bgi_getx()
#define gety() cg_bgi_gety()
#define circle(x, y, radius) cg_bgi_circle(x, y, radius)
#define arc(x, y, start, end, radius) cg_bgi_arc(x, y, start, end, radius)
#define ellipse(x, y, start, end, xradius, yradius) \
    cg_bgi_ellipse(x, y, start, end, xradius, yradius)
#define rectangle(left, top, right, bottom) cg_bgi_rectangle(left, top, right, bottom)
#define bar(left, top, right, bottom) cg_bgi_bar(left, top, right, bottom)
#define drawpoly(count, points) cg_bgi_drawpoly(count, points)
#define fillpoly(count, points) cg_bgi_fillpoly(count, points)
#define floodfill(x, y, border) cg_bgi_floodfill(x, y, border)
#define setcolor(color) cg_bgi_setcolor(color)
#define getcolor() cg_bgi_getcolor()
#define setbkcolor(color) cg_bgi_setbkcolor(color)
#define getbkcolor() cg_bgi_getbkcolor()
#define setfillstyle(pattern, color) cg_bgi_setfillstyle(pattern, color)
#define outtextxy(x, y, text) cg_bgi_outtextxy(x, y, text)
#define cleardevice() cg_bgi_cleardevice()
#define delay(milliseconds) cg_bgi_delay(milliseconds)

#endif
