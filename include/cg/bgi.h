/* cg/bgi.h - the Borland/Turbo C BGI graphics calls that course labs use,
 * drawn with cg's own algorithms (libcg-bgi, a library of its own beside
 * libcg: build with `pkg-config --cflags --libs cg-bgi`).
 *
 * A lab program includes <graphics.h> (and <conio.h> for getch, <dos.h>
 * for delay), which map the classic names (initgraph, line, circle, ...) to
 * these cg_bgi_ functions; the two spellings are the same calls.
 *
 * The screen is 640 x 480 pixels of 16 colours (the EGA/VGA palette), origin
 * top-left, y down.  Lines, rectangles and polygons are Bresenham lines,
 * circles, arcs and ellipses the midpoint algorithms of cg/draw.h, bar and
 * fillpoly the scan-line fill of cg/fill.h (pixel centres inside, vertices
 * at pixel centres), floodfill cg's boundary fill (4-connected), text the
 * 5 x 7 bitmap font.  Everything outside the screen is clipped.
 *
 * With a display (DISPLAY or WAYLAND_DISPLAY set, SDL_VIDEODRIVER not
 * "dummy" or "offscreen") initgraph opens an SDL2 window, getch waits for a
 * key in it and delay sleeps.  Without one the picture stays in memory, the
 * program runs to its end without waiting (getch returns the next character
 * of $CG_BGI_KEYS, then Escape; kbhit is always true; delay returns at once)
 * and closegraph writes the picture to $CG_BGI_OUTPUT, or bgi.png in the
 * working directory; at exit too when closegraph was not called.  With a
 * window the picture is written only when $CG_BGI_OUTPUT is set.
 *
 * Like the BGI, the state (colours, current position, the picture) is one
 * per program: call it from one thread. */
#ifndef CG_BGI_H
#define CG_BGI_H

#ifdef __cplusplus
extern "C" {
#endif

/* The 16 colours. */
enum {
    CG_BGI_BLACK = 0,
    CG_BGI_BLUE,
    CG_BGI_GREEN,
    CG_BGI_CYAN,
    CG_BGI_RED,
    CG_BGI_MAGENTA,
    CG_BGI_BROWN,
    CG_BGI_LIGHTGRAY,
    CG_BGI_DARKGRAY,
    CG_BGI_LIGHTBLUE,
    CG_BGI_LIGHTGREEN,
    CG_BGI_LIGHTCYAN,
    CG_BGI_LIGHTRED,
    CG_BGI_LIGHTMAGENTA,
    CG_BGI_YELLOW,
    CG_BGI_WHITE
};

/* Fill styles: 8 x 8 patterns; set bits take the fill colour, clear bits
 * the background colour. */
enum {
    CG_BGI_EMPTY_FILL = 0, /* the background colour */
    CG_BGI_SOLID_FILL,     /* the fill colour */
    CG_BGI_LINE_FILL,      /* --- */
    CG_BGI_LTSLASH_FILL,   /* /// thin */
    CG_BGI_SLASH_FILL,     /* /// thick */
    CG_BGI_BKSLASH_FILL,   /* \\\ thick */
    CG_BGI_LTBKSLASH_FILL, /* \\\ thin */
    CG_BGI_HATCH_FILL,     /* light hatch */
    CG_BGI_XHATCH_FILL,    /* heavy cross-hatch */
    CG_BGI_INTERLEAVE_FILL,
    CG_BGI_WIDE_DOT_FILL,
    CG_BGI_CLOSE_DOT_FILL,
    CG_BGI_USER_FILL /* taken as SOLID_FILL */
};

/* Drivers and modes initgraph accepts (any driver is the VGA screen). */
enum { CG_BGI_DETECT = 0, CG_BGI_VGA = 9, CG_BGI_VGAHI = 2 };

/* graphresult() codes. */
enum {
    CG_BGI_OK = 0,
    CG_BGI_NO_INIT_GRAPH = -1, /* a drawing call before initgraph */
    CG_BGI_NOT_DETECTED = -2,
    CG_BGI_NO_MEMORY = -5,
    CG_BGI_ERROR = -11
};

/* Opens the screen (and the window, with a display), clears it to black and
 * sets colour WHITE, fill SOLID_FILL WHITE, position (0, 0).  *driver and
 * *mode (either may be NULL) receive VGA and VGAHI; path is ignored.  A
 * second call starts again. */
void cg_bgi_initgraph(int *driver, int *mode, const char *path);
/* Writes the picture (see above) and closes the screen. */
void cg_bgi_closegraph(void);
/* The status of the last call (CG_BGI_OK, ...), reset to OK by reading it. */
int cg_bgi_graphresult(void);
const char *cg_bgi_grapherrormsg(int code);

int cg_bgi_getmaxx(void); /* 639 */
int cg_bgi_getmaxy(void); /* 479 */

void cg_bgi_putpixel(int x, int y, int color);
/* The colour (0..15) of a pixel; 0 outside the screen. */
unsigned cg_bgi_getpixel(int x, int y);

/* Lines in the current colour; lineto and linerel move the position. */
void cg_bgi_line(int x1, int y1, int x2, int y2);
void cg_bgi_lineto(int x, int y);
void cg_bgi_linerel(int dx, int dy);
void cg_bgi_moveto(int x, int y);
void cg_bgi_moverel(int dx, int dy);
int cg_bgi_getx(void);
int cg_bgi_gety(void);

/* Circles, arcs and ellipses about (x, y); angles in degrees counter-
 * clockwise from 3 o'clock, an arc from start to end. */
void cg_bgi_circle(int x, int y, int radius);
void cg_bgi_arc(int x, int y, int start, int end, int radius);
void cg_bgi_ellipse(int x, int y, int start, int end, int xradius, int yradius);

/* The outline of the rectangle with corners (left, top) and (right,
 * bottom), and the filled rectangle (fill style, no outline), both corners'
 * pixels included. */
void cg_bgi_rectangle(int left, int top, int right, int bottom);
void cg_bgi_bar(int left, int top, int right, int bottom);

/* count points, points[2i], points[2i + 1]: drawpoly joins them (close it
 * by repeating the first point); fillpoly fills the closed polygon with the
 * fill style and outlines it in the current colour. */
void cg_bgi_drawpoly(int count, const int *points);
void cg_bgi_fillpoly(int count, const int *points);

/* Paints the fill style over the region around (x, y) bounded by pixels of
 * the colour border; nothing when (x, y) is of that colour. */
void cg_bgi_floodfill(int x, int y, int border);

void cg_bgi_setcolor(int color);
int cg_bgi_getcolor(void);
/* The background: cleardevice and EMPTY_FILL paint it. */
void cg_bgi_setbkcolor(int color);
int cg_bgi_getbkcolor(void);
void cg_bgi_setfillstyle(int pattern, int color);

/* Text in the current colour with its top-left corner at (x, y), 6 pixels a
 * character. */
void cg_bgi_outtextxy(int x, int y, const char *text);
/* Paints the whole screen the background colour; the position goes to
 * (0, 0). */
void cg_bgi_cleardevice(void);

/* Waits milliseconds (shows the picture first), without a display not at
 * all. */
void cg_bgi_delay(unsigned milliseconds);
/* The next key (its character), waiting for it; without a display, the next
 * character of $CG_BGI_KEYS, then 27 (Escape). */
int cg_bgi_getch(void);
/* Whether a key is waiting; without a display always 1. */
int cg_bgi_kbhit(void);

#ifdef __cplusplus
}
#endif
#endif
