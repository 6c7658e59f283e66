/* cg view MESH_OR_SCENE: an interactive window on the rasterizer (SDL2).
 *
 * Mouse: left drag orbits around the target, right (or middle) drag pans,
 * the wheel zooms.  Keys: f / g / p flat, Gouraud, Phong shading; w
 * wireframe; e visible edges over the faces; h hidden lines; b back-face
 * culling on and off; z z-buffer / painter's; s saves a screenshot; arrows
 * orbit; + / - zoom; q or Escape quits.  A status line shows the mode and the
 * frame time. */
#include "cli.h"
#include "command.h"

#include <stddef.h>

typedef struct view_arguments {
    cli_size size;
    int threads;
    const char *screenshot_dir;
} view_arguments;

static const cli_option view_options[] = {
    CLI_OPTION_SIZE(view_arguments, size, 0, "window size (default 1280x720)"),
    CLI_OPTION_THREADS(view_arguments, threads, 0, "rendering threads (default: all cores)"),
    {.name = "--screenshot-dir",
     .kind = CLI_STRING,
     .offset = offsetof(view_arguments, screenshot_dir),
     .value_name = "DIR",
     .help = "where s saves cg-view-N.png (default .)"},
};
static const cli_option_group view_groups[] = {CLI_GROUP(NULL, view_options), {0}};
static const cli_syntax view_syntax = {
    .command = "view",
    .groups = view_groups,
    .max_positionals = 1,
    .too_many = "expected one MESH or SCENE file, got '%s' as well",
    .min_positionals = 1,
    .too_few = "expected a MESH or SCENE file",
};
static const cli_syntax *const view_syntaxes[] = {&view_syntax, NULL};

#ifdef CG_HAVE_SDL2

#include "font5x7.h"
#include "render_scene.h"
#include "cg/render.h"
#include "cg/scene.h"
#include "cg/color.h"

#include <SDL.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NAME "view"

typedef struct viewer {
    cg_renderer *renderer;
    cg_render_options options;
    cg_image *frame;
    /* orbit camera: target, distance, yaw (about y) and pitch */
    cg_vec3 target;
    double distance, yaw, pitch;
    cg_vec3 lo, hi; /* the model's box, which near and far enclose */
    double frame_ms;
    int screenshots;
    const char *screenshot_dir;
} viewer;

static void place_camera(viewer *v)
{
    cg_camera *c = &v->options.camera;
    cg_vec3 offset = cg_vec3_make(cos(v->pitch) * sin(v->yaw), sin(v->pitch),
                                  cos(v->pitch) * cos(v->yaw));
    c->target = v->target;
    c->eye = cg_vec3_add(v->target, cg_vec3_scale(offset, v->distance));
    c->up = cg_vec3_make(0, 1, 0);
    /* Near and far enclose the model's depth range wherever the orbit and
     * panning put the eye. */
    c->near = v->distance * 0.01;
    c->far = v->distance * 20;
    cg_camera_fit_depth(c, v->lo, v->hi);
    if (c->orthographic)
        c->ortho_height = v->distance * 2 * tan(c->fovy / 2);
}

static const char *shading_name(cg_shading s)
{
    return s == CG_SHADING_FLAT ? "flat" : s == CG_SHADING_PHONG ? "phong" : "gouraud";
}

static const char *edges_name(cg_edge_mode e)
{
    return e == CG_EDGES_WIREFRAME     ? "wireframe"
           : e == CG_EDGES_HIDDEN_LINE ? "hidden lines"
           : e == CG_EDGES_OVERLAY     ? "edges"
                                       : "faces";
}

static int draw_frame(viewer *v)
{
    place_camera(v);
    if (cg_renderer_set_options(v->renderer, &v->options) != CG_OK)
        return cli_fail("view: the camera or options were refused");
    double start = cli_now();
    cg_status s = cg_renderer_draw(v->renderer, v->frame);
    v->frame_ms = (cli_now() - start) * 1e3;
    if (s != CG_OK)
        return cli_fail("view: rendering failed: %s", cg_status_str(s));
    char status[160];
    snprintf(status, sizeof status, "%s | %s | %s | cull %s | %.1f ms",
             v->options.algorithm == CG_RENDER_PAINTER ? "painter" : "z-buffer",
             shading_name(v->options.shading), edges_name(v->options.edges),
             v->options.cull == CG_CULL_BACK ? "on" : "off", v->frame_ms);
    /* A dark band under the text keeps it readable on any picture. */
    cg_rgba8 band = {0, 0, 0, 160}, text = {255, 255, 255, 255};
    int height = 7 * 2 + 8;
    for (int y = v->frame->height - height; y < v->frame->height; y++)
        for (int x = 0; x < v->frame->width && x < font_width(status, 2) + 12; x++)
            cg_image_blend(v->frame, x, y, cg_rgba8_to_linear(band));
    font_draw(v->frame, 6, v->frame->height - height + 4, 2, status, text);
    return CLI_OK;
}

static int save_screenshot(viewer *v)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/cg-view-%d.png", v->screenshot_dir, ++v->screenshots);
    int status = cli_write_image(v->frame, path);
    if (status == CLI_OK)
        fprintf(stderr, "view: saved %s\n", path);
    return status;
}

/* Applies one key; returns 1 when the picture must be drawn again, -1 to quit. */
static int key(viewer *v, SDL_Keycode k)
{
    cg_render_options *o = &v->options;
    switch (k) {
    case SDLK_q:
    case SDLK_ESCAPE: return -1;
    case SDLK_f: o->shading = CG_SHADING_FLAT; return 1;
    case SDLK_g: o->shading = CG_SHADING_GOURAUD; return 1;
    case SDLK_p: o->shading = CG_SHADING_PHONG; return 1;
    case SDLK_w:
        o->edges = o->edges == CG_EDGES_WIREFRAME ? CG_EDGES_NONE : CG_EDGES_WIREFRAME;
        return 1;
    case SDLK_e:
        o->edges = o->edges == CG_EDGES_OVERLAY ? CG_EDGES_NONE : CG_EDGES_OVERLAY;
        return 1;
    case SDLK_h:
        o->edges = o->edges == CG_EDGES_HIDDEN_LINE ? CG_EDGES_NONE : CG_EDGES_HIDDEN_LINE;
        return 1;
    case SDLK_b: o->cull = o->cull == CG_CULL_BACK ? CG_CULL_NONE : CG_CULL_BACK; return 1;
    case SDLK_z:
        o->algorithm = o->algorithm == CG_RENDER_PAINTER ? CG_RENDER_ZBUFFER : CG_RENDER_PAINTER;
        return 1;
    case SDLK_LEFT: v->yaw -= 0.2; return 1;
    case SDLK_RIGHT: v->yaw += 0.2; return 1;
    case SDLK_UP: v->pitch = fmin(v->pitch + 0.2, 1.5); return 1;
    case SDLK_DOWN: v->pitch = fmax(v->pitch - 0.2, -1.5); return 1;
    case SDLK_PLUS:
    case SDLK_EQUALS:
    case SDLK_KP_PLUS: v->distance *= 0.8; return 1;
    case SDLK_MINUS:
    case SDLK_KP_MINUS: v->distance /= 0.8; return 1;
    case SDLK_s: save_screenshot(v); return 0;
    default: return 0;
    }
}

/* Moves the target in the image plane by a mouse motion of (dx, dy) pixels. */
static void pan(viewer *v, int dx, int dy)
{
    cg_camera *c = &v->options.camera;
    cg_vec3 forward = cg_vec3_normalize(cg_vec3_sub(c->target, c->eye));
    cg_vec3 side = cg_vec3_normalize(cg_vec3_cross(forward, c->up));
    cg_vec3 up = cg_vec3_cross(side, forward);
    double per_pixel = 2 * v->distance * tan(c->fovy / 2) / v->frame->height;
    v->target = cg_vec3_add(v->target, cg_vec3_add(cg_vec3_scale(side, -dx * per_pixel),
                                                   cg_vec3_scale(up, dy * per_pixel)));
}

/* Loads a mesh file, or a scene file as one world mesh with its options. */
static int load(const char *path, int threads, cg_mesh **mesh, cg_render_options *o)
{
    cg_error err;
    cg_render_options_default(o);
    if (render_scene_is_scene(path)) {
        cg_scene *scene;
        if (cg_scene_load(path, &scene, &err) != CG_OK)
            return cli_fail("%s", err.message);
        cg_status s = cg_scene_raster_options(
            scene, scene->algorithm == CG_SCENE_PAINTER ? CG_SCENE_PAINTER : CG_SCENE_ZBUFFER, o,
            &err);
        if (s == CG_OK)
            s = cg_scene_world_mesh(scene, mesh, &err);
        cg_scene_free(scene);
        if (s != CG_OK)
            return cli_fail("%s", err.message);
    } else if (cg_mesh_load(path, mesh, &err) != CG_OK) {
        return cli_fail("%s", err.message);
    }
    o->threads = threads;
    o->frame_camera = 0;
    return CLI_OK;
}

/* True when a window can be shown.  With no X11 or Wayland display SDL falls
 * back to its invisible offscreen driver and the viewer would wait forever for
 * events that never come; a driver the user names in SDL_VIDEODRIVER is
 * honoured as asked (the dummy and offscreen drivers included). */
static int have_display(void)
{
#if defined(__APPLE__) || defined(_WIN32)
    return 1;
#else
    const char *names[] = {"SDL_VIDEODRIVER", "DISPLAY", "WAYLAND_DISPLAY"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        const char *value = getenv(names[i]);
        if (value && value[0])
            return 1;
    }
    return 0;
#endif
}

/* Loads the model, frames the view of the whole of it (or takes the scene's
 * camera) and makes the renderer and the frame. */
static int viewer_open(viewer *v, const char *path, int threads, int width, int height)
{
    cg_mesh *mesh = NULL;
    int status = load(path, threads, &mesh, &v->options);
    if (status != CLI_OK)
        return status;
    cg_vec3 lo, hi;
    if (cg_mesh_bounds(mesh, &lo, &hi) != CG_OK) {
        lo = cg_vec3_make(-1, -1, -1);
        hi = cg_vec3_make(1, 1, 1);
    }
    cg_camera framed = v->options.camera;
    if (!render_scene_is_scene(path)) {
        framed.eye = cg_vec3_add(framed.target, cg_vec3_make(0, 0, 1));
        cg_camera_frame(&framed, lo, hi, (double)width / height);
    }
    v->options.camera = framed;
    v->lo = lo;
    v->hi = hi;
    v->target = framed.target;
    cg_vec3 offset = cg_vec3_sub(framed.eye, framed.target);
    v->distance = cg_vec3_length(offset);
    v->yaw = atan2(offset.x, offset.z);
    v->pitch = asin(offset.y / v->distance);
    cg_error err;
    if (cg_renderer_create(mesh, &v->options, &v->renderer, &err) != CG_OK) {
        cg_mesh_free(mesh);
        return cli_fail("%s: %s", path, err.message);
    }
    cg_mesh_free(mesh);
    if (cg_image_create(&v->frame, width, height, CG_PIXEL_RGBA8) != CG_OK) {
        cg_renderer_free(v->renderer);
        return cli_fail("view: cannot make a %dx%d frame", width, height);
    }
    return CLI_OK;
}

/* The window, its renderer and the texture the frame is copied to. */
typedef struct window {
    SDL_Window *window;
    SDL_Renderer *screen;
    SDL_Texture *texture;
} window;

static int window_open(window *w, const char *path, int width, int height)
{
    memset(w, 0, sizeof *w);
    if (SDL_Init(SDL_INIT_VIDEO) != 0)
        return cli_fail("view: cannot open a window: %s", SDL_GetError());
    char title[512];
    snprintf(title, sizeof title, "cg view - %s", path);
    w->window = SDL_CreateWindow(title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width,
                                 height, SDL_WINDOW_SHOWN);
    w->screen = w->window ? SDL_CreateRenderer(w->window, -1, 0) : NULL;
    if (!w->screen && w->window)
        w->screen = SDL_CreateRenderer(w->window, -1, SDL_RENDERER_SOFTWARE);
    /* ABGR8888 is R, G, B, A in memory order on little-endian machines, and
     * RGBA8888 on big-endian ones: cg's byte order either way. */
    w->texture = w->screen
                     ? SDL_CreateTexture(w->screen,
                                         SDL_BYTEORDER == SDL_LIL_ENDIAN ? SDL_PIXELFORMAT_ABGR8888
                                                                         : SDL_PIXELFORMAT_RGBA8888,
                                         SDL_TEXTUREACCESS_STREAMING, width, height)
                     : NULL;
    if (!w->texture)
        return cli_fail("view: cannot open a window: %s", SDL_GetError());
    return CLI_OK;
}

static void window_close(window *w)
{
    if (w->texture)
        SDL_DestroyTexture(w->texture);
    if (w->screen)
        SDL_DestroyRenderer(w->screen);
    if (w->window)
        SDL_DestroyWindow(w->window);
    SDL_Quit();
}

/* Applies one event; returns 1 when the picture must be drawn again, -1 to
 * quit.  *dragging is the mouse button held down, or 0. */
static int handle_event(viewer *v, const SDL_Event *e, int *dragging)
{
    switch (e->type) {
    case SDL_QUIT: return -1;
    case SDL_KEYDOWN: return key(v, e->key.keysym.sym);
    case SDL_MOUSEBUTTONDOWN: *dragging = e->button.button; return 0;
    case SDL_MOUSEBUTTONUP: *dragging = 0; return 0;
    case SDL_MOUSEMOTION:
        if (*dragging == SDL_BUTTON_LEFT) {
            v->yaw -= e->motion.xrel * 0.01;
            v->pitch = fmax(-1.5, fmin(1.5, v->pitch + e->motion.yrel * 0.01));
            return 1;
        }
        if (*dragging) {
            pan(v, e->motion.xrel, e->motion.yrel);
            return 1;
        }
        return 0;
    case SDL_MOUSEWHEEL: v->distance *= pow(0.9, e->wheel.y); return 1;
    case SDL_WINDOWEVENT: return e->window.event == SDL_WINDOWEVENT_EXPOSED;
    default: return 0;
    }
}

/* Draws and shows a frame whenever the events asked for one, until quit. */
static int event_loop(viewer *v, window *w)
{
    int dirty = 1, dragging = 0;
    for (;;) {
        if (dirty) {
            int status = draw_frame(v);
            if (status != CLI_OK)
                return status;
            SDL_UpdateTexture(w->texture, NULL, v->frame->data, (int)v->frame->stride);
            SDL_RenderClear(w->screen);
            SDL_RenderCopy(w->screen, w->texture, NULL, NULL);
            SDL_RenderPresent(w->screen);
            dirty = 0;
        }
        SDL_Event e;
        if (!SDL_WaitEvent(&e))
            return CLI_OK;
        do {
            int change = handle_event(v, &e, &dragging);
            if (change < 0)
                return CLI_OK;
            dirty |= change;
        } while (SDL_PollEvent(&e));
    }
}

static int run(int argc, char **argv)
{
    view_arguments arguments = {{1280, 720}, SDL_GetCPUCount(), "."};
    const char *path = NULL;
    if (cli_parse(&view_syntax, argc, argv, &arguments, &path, NULL) != CLI_OK)
        return CLI_USAGE;
    int width = arguments.size.width, height = arguments.size.height;
    int threads = arguments.threads < 1 ? 1 : arguments.threads > 64 ? 64 : arguments.threads;
    if (!have_display())
        return cli_fail("view: no display to open a window on (DISPLAY and WAYLAND_DISPLAY are "
                        "unset); run it in a desktop session, or set SDL_VIDEODRIVER to choose a "
                        "video driver");
    viewer v;
    memset(&v, 0, sizeof v);
    v.screenshot_dir = arguments.screenshot_dir;
    int status = viewer_open(&v, path, threads, width, height);
    if (status != CLI_OK)
        return status;
    window w;
    status = window_open(&w, path, width, height);
    if (status == CLI_OK)
        status = event_loop(&v, &w);
    window_close(&w);
    cg_renderer_free(v.renderer);
    cg_image_free(v.frame);
    return status;
}

#else

static int run(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return cli_fail("view: this cg was built without SDL2 (install libsdl2-dev and rebuild)");
}

#endif

const cg_command cg_command_view = {
    "view",
    "open a window on a mesh or scene: orbit, pan, zoom, switch modes",
    "usage: cg view MESH_OR_SCENE [--size WxH] [--threads N] [--screenshot-dir DIR]\n\n"
    "Shows a mesh file (OBJ, PLY, OFF, STL) or a scene file (.json) in a window,\n"
    "rendered by cg's rasterizer on N threads (default: all cores).\n\n"
    "  mouse      left drag: orbit   right or middle drag: pan   wheel: zoom\n"
    "  f g p      flat, Gouraud, Phong shading\n"
    "  w e h      wireframe, visible edges over faces, hidden lines (again: off)\n"
    "  b          back-face culling on / off\n"
    "  z          z-buffer / painter's algorithm\n"
    "  arrows     orbit        + -   zoom\n"
    "  s          save the window as DIR/cg-view-N.png (default DIR: .)\n"
    "  q, Esc     quit\n\n"
    "The line at the bottom shows the mode and the time of the last frame.\n"
    "The window needs a display (DISPLAY or WAYLAND_DISPLAY); without one cg view\n"
    "says so and exits with status 1, unless SDL_VIDEODRIVER names a driver.\n",
    run,
    view_syntaxes,
};
