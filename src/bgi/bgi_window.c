/* libcg-bgi's window: SDL2 shows the picture and reads the keys.  Built
 * without SDL2, there is never a window. */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

int bgi_have_display(void)
{
    const char *driver = getenv("SDL_VIDEODRIVER");
    if (driver && (strcmp(driver, "dummy") == 0 || strcmp(driver, "offscreen") == 0))
        return 0;
    const char *names[] = {"DISPLAY", "WAYLAND_DISPLAY"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        const char *value = getenv(names[i]);
        if (value && value[0])
            return 1;
    }
    return 0;
}

#ifdef CG_HAVE_SDL2
#include <SDL.h>

enum { KEY_QUEUE = 64 };

struct bgi_window {
    SDL_Window *window;
    SDL_Renderer *renderer;
    SDL_Texture *texture;
    int keys[KEY_QUEUE], key_count;
};

bgi_window *bgi_window_open(int width, int height)
{
    if (SDL_Init(SDL_INIT_VIDEO) != 0)
        return NULL;
    bgi_window *w = calloc(1, sizeof *w);
    if (w) {
        w->window = SDL_CreateWindow("cg BGI", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                     width, height, SDL_WINDOW_SHOWN);
        w->renderer = w->window ? SDL_CreateRenderer(w->window, -1, SDL_RENDERER_SOFTWARE) : NULL;
        w->texture = w->renderer ? SDL_CreateTexture(w->renderer, SDL_PIXELFORMAT_ABGR8888,
                                                     SDL_TEXTUREACCESS_STREAMING, width, height)
                                 : NULL;
    }
    if (!w || !w->texture) {
        bgi_window_close(w);
        SDL_Quit();
        return NULL;
    }
    SDL_StartTextInput();
    return w;
}

void bgi_window_close(bgi_window *w)
{
    if (!w)
        return;
    if (w->texture)
        SDL_DestroyTexture(w->texture);
    if (w->renderer)
        SDL_DestroyRenderer(w->renderer);
    if (w->window)
        SDL_DestroyWindow(w->window);
    free(w);
    SDL_Quit();
}

static void push_key(bgi_window *w, int key)
{
    if (w->key_count < KEY_QUEUE)
        w->keys[w->key_count++] = key;
}

/* Takes the waiting events: characters typed, Enter, Escape, Backspace and
 * Tab as keys; closing the window as Escape. */
static void pump(bgi_window *w)
{
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
        if (e.type == SDL_QUIT)
            push_key(w, 27);
        else if (e.type == SDL_TEXTINPUT && (unsigned char)e.text.text[0] < 128)
            push_key(w, (unsigned char)e.text.text[0]);
        else if (e.type == SDL_KEYDOWN) {
            SDL_Keycode k = e.key.keysym.sym;
            if (k == SDLK_RETURN || k == SDLK_KP_ENTER)
                push_key(w, 13);
            else if (k == SDLK_ESCAPE)
                push_key(w, 27);
            else if (k == SDLK_BACKSPACE)
                push_key(w, 8);
            else if (k == SDLK_TAB)
                push_key(w, 9);
        }
    }
}

void bgi_window_show(bgi_window *w, const cg_image *image)
{
    SDL_UpdateTexture(w->texture, NULL, image->data, (int)image->stride);
    SDL_RenderClear(w->renderer);
    SDL_RenderCopy(w->renderer, w->texture, NULL, NULL);
    SDL_RenderPresent(w->renderer);
    pump(w);
}

int bgi_window_key(bgi_window *w, int wait)
{
    pump(w);
    while (wait && w->key_count == 0) {
        SDL_WaitEventTimeout(NULL, 50);
        pump(w);
    }
    if (w->key_count == 0)
        return -1;
    int key = w->keys[0];
    if (wait) {
        memmove(w->keys, w->keys + 1, (size_t)(w->key_count - 1) * sizeof w->keys[0]);
        w->key_count--;
    }
    return key;
}

void bgi_window_sleep(bgi_window *w, unsigned milliseconds)
{
    Uint32 end = SDL_GetTicks() + milliseconds;
    for (;;) {
        pump(w);
        Uint32 t = SDL_GetTicks();
        if ((Sint32)(end - t) <= 0)
            break;
        SDL_Delay((Sint32)(end - t) > 10 ? 10 : end - t);
    }
}

#else

bgi_window *bgi_window_open(int width, int height)
{
    (void)width;
    (void)height;
    return NULL;
}

void bgi_window_close(bgi_window *w)
{
    (void)w;
}

void bgi_window_show(bgi_window *w, const cg_image *image)
{
    (void)w;
    (void)image;
}

int bgi_window_key(bgi_window *w, int wait)
{
    (void)w;
    (void)wait;
    return 27;
}

void bgi_window_sleep(bgi_window *w, unsigned milliseconds)
{
    (void)w;
    (void)milliseconds;
}

#endif
