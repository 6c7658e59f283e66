/* Gallery helpers of the chapter 2 sections: pictures made by `cg draw`
 * scripts, and magnified pixel grids for showing the algorithms at work. */
#ifndef CG_TOOL_SCRIPT_PICTURES_H
#define CG_TOOL_SCRIPT_PICTURES_H

#include "demo.h"
#include "cg/image.h"

/* Writes text as NAME.draw in the gallery folder, runs it and adds the
 * canvas as NAME.png with the command `cg draw NAME.draw -o NAME.png`. */
int draw_demo_script(demo_context *context, const char *name, const char *text,
                     const char *caption);

/* A script built line by line (text truncated beyond its size). */
typedef struct script_text {
    char text[16384];
    size_t length;
} script_text;
void script_add(script_text *script, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* A script of any length, growing as it is written; failed is set when
 * memory ran out (the text then stops short). */
typedef struct sketch {
    char *text;
    size_t length, capacity;
    int failed;
} sketch;
void sketch_add(sketch *k, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Writes the sketch as NAME.draw, adds its picture as NAME.png (as
 * draw_demo_script does) and frees the sketch's text. */
int draw_demo_sketch(demo_context *context, sketch *k, const char *name, const char *caption);

/* A magnified view: each pixel of a small grid becomes a cell of `cell`
 * image pixels with a thin grid between cells. */
typedef struct zoom {
    cg_image *image;
    int cell;
} zoom;

/* A zoom of a columns x rows grid; cells start light grey. */
int zoom_create(zoom *z, int columns, int rows, int cell);
/* Fills grid pixel (x, y). */
void zoom_fill(zoom *z, int x, int y, cg_rgba8 color);
/* Fills the cells of the pixels drawn (alpha > 0) in grid, an image of the
 * zoom's columns x rows. */
void zoom_fill_drawn(zoom *z, const cg_image *grid, cg_rgba8 color);
/* Adds the magnified image to the gallery and frees it. */
int zoom_add(demo_context *context, zoom *z, const char *file, const char *caption,
             const char *command);
/* Starts a script that draws the zoom's grid and cells as they are now
 * (one aliased polygon per cell), so that overlays can follow as commands;
 * frees the zoom's image. */
void zoom_to_script(zoom *z, sketch *k);
/* Maps a point of the grid's pixel plane to the magnified image plane. */
double zoom_x(const zoom *z, double x);

#endif
