/* Gallery helpers of the chapter 2 sections. */
#include "script_pictures.h"
#include "draw_script_run.h"
#include "../../../src/core/array.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

void script_add(script_text *script, const char *format, ...)
{
    size_t room = sizeof script->text - script->length;
    if (room <= 1)
        return;
    va_list args;
    va_start(args, format);
    int n = vsnprintf(script->text + script->length, room, format, args);
    va_end(args);
    if (n > 0)
        script->length += (size_t)n < room ? (size_t)n : room - 1;
}

void sketch_add(sketch *k, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    int n = vsnprintf(NULL, 0, format, args);
    va_end(args);
    if (k->failed || n < 0)
        return;
    if (core_array_reserve((void **)&k->text, &k->capacity, k->length + (size_t)n + 1, 1)
        != CG_OK) {
        k->failed = 1;
        return;
    }
    va_start(args, format);
    vsnprintf(k->text + k->length, k->capacity - k->length, format, args);
    va_end(args);
    k->length += (size_t)n;
}

int draw_demo_script(demo_context *context, const char *name, const char *text, const char *caption)
{
    char path[4096], file[256], command[512];
    snprintf(path, sizeof path, "%s/%s.draw", demo_directory(context), name);
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) < 0 || fclose(f) != 0) {
        fprintf(stderr, "cg: demo: cannot write %s\n", path);
        return 1;
    }
    snprintf(file, sizeof file, "%s.draw", name);
    draw_script script;
    draw_state state;
    if (draw_script_parse(file, text, &script))
        return 1;
    int status = draw_script_run(&script, &state);
    if (status == 0) {
        snprintf(file, sizeof file, "%s.png", name);
        snprintf(command, sizeof command, "cg draw %s.draw -o %s.png", name, name);
        status = demo_add(context, file, state.canvas, caption, command);
    }
    draw_state_release(&state);
    draw_script_free(&script);
    return status;
}

int zoom_create(zoom *z, int columns, int rows, int cell)
{
    z->cell = cell;
    if (cg_image_create(&z->image, columns * cell + 1, rows * cell + 1, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_rgba8 grid = {205, 205, 205, 255}, empty = {248, 248, 248, 255};
    cg_image_clear_rgba8(z->image, grid);
    for (int y = 0; y < rows; y++)
        for (int x = 0; x < columns; x++)
            zoom_fill(z, x, y, empty);
    return 0;
}

void zoom_fill(zoom *z, int x, int y, cg_rgba8 color)
{
    for (int j = 1; j < z->cell; j++)
        for (int i = 1; i < z->cell; i++)
            cg_image_set_rgba8(z->image, x * z->cell + i, y * z->cell + j, color);
}

double zoom_x(const zoom *z, double x)
{
    return x * z->cell + 0.5;
}

void zoom_fill_drawn(zoom *z, const cg_image *grid, cg_rgba8 color)
{
    for (int y = 0; y < grid->height; y++)
        for (int x = 0; x < grid->width; x++)
            if (cg_image_get_rgba8(grid, x, y).a)
                zoom_fill(z, x, y, color);
}

int zoom_add(demo_context *context, zoom *z, const char *file, const char *caption,
             const char *command)
{
    int status = demo_add(context, file, z->image, caption, command);
    cg_image_free(z->image);
    z->image = NULL;
    return status;
}

void zoom_to_script(zoom *z, sketch *k)
{
    cg_rgba8 grid = cg_image_get_rgba8(z->image, 0, 0);
    sketch_add(k, "size %d %d\nbackground #%02x%02x%02x\n", z->image->width, z->image->height,
               grid.r, grid.g, grid.b);
    int columns = (z->image->width - 1) / z->cell, rows = (z->image->height - 1) / z->cell;
    for (int y = 0; y < rows; y++)
        for (int x = 0; x < columns; x++) {
            /* pixels 1 to cell - 1 of the cell: their centres lie inside */
            cg_rgba8 c = cg_image_get_rgba8(z->image, x * z->cell + 1, y * z->cell + 1);
            int x0 = x * z->cell + 1, y0 = y * z->cell + 1, x1 = (x + 1) * z->cell,
                y1 = (y + 1) * z->cell;
            sketch_add(k, "color #%02x%02x%02x%02x\npolygon %d %d %d %d %d %d %d %d\n", c.r, c.g,
                       c.b, c.a, x0, y0, x1, y0, x1, y1, x0, y1);
        }
    cg_image_free(z->image);
    z->image = NULL;
}

int draw_demo_sketch(demo_context *context, sketch *k, const char *name, const char *caption)
{
    int status = k->failed ? 1 : draw_demo_script(context, name, k->text, caption);
    free(k->text);
    k->text = NULL;
    return status;
}
