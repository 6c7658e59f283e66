/* Gallery helpers of the chapter 2 sections: pictures made by `cg draw`
 * scripts, and magnified pixel grids for showing the algorithms at work. */
#ifndef CG_TOOL_DRAW_DEMO_H
#define CG_TOOL_DRAW_DEMO_H

#include "demo.h"
#include "cg/image.h"

/* Writes text as NAME.draw in the gallery folder, runs it and adds the
 * canvas as NAME.png with the command `cg draw NAME.draw -o NAME.png`. */
int draw_demo_script(demo_context *context, const char *name, const char *text,
                     const char *caption);

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
/* Maps a point of the grid's pixel plane to the magnified image plane. */
double zoom_x(const zoom *z, double x);

#endif
