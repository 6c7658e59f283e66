/* libcg-bgi: the screen's life (initgraph, closegraph, the picture written at
 * the end), its state, and the keyboard and the clock. */
#include "internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

bgi_screen bgi_the_screen;

static int exit_hook_set;

cg_rgba8 bgi_palette(int color)
{
    static const unsigned char rgb[16][3] = {
        {0, 0, 0},     {0, 0, 170},    {0, 170, 0},    {0, 170, 170},
        {170, 0, 0},   {170, 0, 170},  {170, 85, 0},   {170, 170, 170},
        {85, 85, 85},  {85, 85, 255},  {85, 255, 85},  {85, 255, 255},
        {255, 85, 85}, {255, 85, 255}, {255, 255, 85}, {255, 255, 255},
    };
    const unsigned char *c = rgb[color & 15];
    return (cg_rgba8){c[0], c[1], c[2], 255};
}

bgi_screen *bgi_open_screen(void)
{
    bgi_screen *s = &bgi_the_screen;
    if (!s->image) {
        s->result = CG_BGI_NO_INIT_GRAPH;
        return NULL;
    }
    return s;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void bgi_show(bgi_screen *s, int force)
{
    if (!s->window)
        return;
    double t = now();
    if (force || t - s->last_shown > 0.03) {
        bgi_window_show(s->window, s->image);
        s->last_shown = t;
    }
}

/* Writes the picture where the program's user asked, or bgi.png without a
 * window; says so on stderr when it cannot. */
static void write_picture(bgi_screen *s)
{
    const char *path = getenv("CG_BGI_OUTPUT");
    if (!path || !path[0]) {
        if (s->window)
            return;
        path = "bgi.png";
    }
    cg_error err;
    if (cg_image_write(s->image, path, CG_FILE_UNKNOWN, &err) != CG_OK)
        fprintf(stderr, "cg-bgi: cannot write the picture: %s\n", err.message);
}

void cg_bgi_closegraph(void)
{
    bgi_screen *s = &bgi_the_screen;
    if (!s->image)
        return;
    write_picture(s);
    if (s->window)
        bgi_window_close(s->window);
    cg_image_free(s->image);
    s->image = NULL;
    s->window = NULL;
}

static void at_exit(void)
{
    cg_bgi_closegraph();
}

void cg_bgi_initgraph(int *driver, int *mode, const char *path)
{
    (void)path;
    bgi_screen *s = &bgi_the_screen;
    if (s->image) {
        if (s->window)
            bgi_window_close(s->window);
        cg_image_free(s->image);
    }
    memset(s, 0, sizeof *s);
    if (cg_image_create(&s->image, BGI_WIDTH, BGI_HEIGHT, CG_PIXEL_RGBA8) != CG_OK) {
        s->image = NULL;
        s->result = CG_BGI_NO_MEMORY;
        return;
    }
    cg_image_clear_rgba8(s->image, bgi_palette(CG_BGI_BLACK));
    s->color = CG_BGI_WHITE;
    s->fill_pattern = CG_BGI_SOLID_FILL;
    s->fill_color = CG_BGI_WHITE;
    s->keys = getenv("CG_BGI_KEYS");
    s->window = bgi_have_display() ? bgi_window_open(BGI_WIDTH, BGI_HEIGHT) : NULL;
    bgi_show(s, 1);
    if (driver)
        *driver = CG_BGI_VGA;
    if (mode)
        *mode = CG_BGI_VGAHI;
    if (!exit_hook_set && atexit(at_exit) == 0)
        exit_hook_set = 1;
    s->result = CG_BGI_OK;
}

int cg_bgi_graphresult(void)
{
    int result = bgi_the_screen.result;
    bgi_the_screen.result = CG_BGI_OK;
    return result;
}

const char *cg_bgi_grapherrormsg(int code)
{
    switch (code) {
    case CG_BGI_OK: return "No error";
    case CG_BGI_NO_INIT_GRAPH: return "(BGI) graphics not installed (use initgraph)";
    case CG_BGI_NOT_DETECTED: return "Graphics hardware not detected";
    case CG_BGI_NO_MEMORY: return "Not enough memory to load driver";
    default: return "Graphics error";
    }
}

int cg_bgi_getmaxx(void)
{
    return BGI_WIDTH - 1;
}

int cg_bgi_getmaxy(void)
{
    return BGI_HEIGHT - 1;
}

void cg_bgi_delay(unsigned milliseconds)
{
    bgi_screen *s = &bgi_the_screen;
    if (!s->image || !s->window)
        return;
    bgi_show(s, 1);
    bgi_window_sleep(s->window, milliseconds);
}

int cg_bgi_getch(void)
{
    bgi_screen *s = &bgi_the_screen;
    if (s->image && s->window) {
        bgi_show(s, 1);
        return bgi_window_key(s->window, 1);
    }
    if (s->keys && *s->keys)
        return (unsigned char)*s->keys++;
    return 27;
}

int cg_bgi_kbhit(void)
{
    bgi_screen *s = &bgi_the_screen;
    if (!s->image || !s->window)
        return 1;
    bgi_show(s, 1);
    return bgi_window_key(s->window, 0) >= 0;
}
