/* Shared pieces of libcg-bgi (cg/bgi.h): the one screen of the program, and
 * the window that shows it when there is a display. */
#ifndef CG_BGI_INTERNAL_H
#define CG_BGI_INTERNAL_H

#include "cg/bgi.h"
#include "cg/image.h"

enum { BGI_WIDTH = 640, BGI_HEIGHT = 480 };

typedef struct bgi_window bgi_window;

typedef struct bgi_screen {
    cg_image *image;    /* the picture, RGBA8 with palette colours only; NULL when closed */
    bgi_window *window; /* NULL without a display */
    int color, background, fill_pattern, fill_color;
    int x, y;          /* the current position */
    int result;        /* for graphresult */
    const char *keys;  /* what getch returns without a display */
    double last_shown; /* when the window last showed the picture (seconds) */
} bgi_screen;

/* The program's screen. */
extern bgi_screen bgi_the_screen;

/* The palette colour of index & 15. */
cg_rgba8 bgi_palette(int color);
/* The screen when open; else NULL, with graphresult set to grNoInitGraph. */
bgi_screen *bgi_open_screen(void);
/* Shows the picture in the window when it was last shown long enough ago
 * (or at once with force); nothing without a window. */
void bgi_show(bgi_screen *s, int force);
/* Paints pixel (x, y), known to be on the screen, with the fill style. */
void bgi_fill_pixel(bgi_screen *s, int x, int y);

/* The window (bgi_window.c): NULL when there is no display or SDL2 fails. */
bgi_window *bgi_window_open(int width, int height);
void bgi_window_close(bgi_window *w);
void bgi_window_show(bgi_window *w, const cg_image *image);
/* With wait, the next key's character, waiting for it; without, the
 * waiting key's character, left waiting (-1 when none waits). */
int bgi_window_key(bgi_window *w, int wait);
void bgi_window_sleep(bgi_window *w, unsigned milliseconds);
/* Whether a display can show a window. */
int bgi_have_display(void);

#endif
