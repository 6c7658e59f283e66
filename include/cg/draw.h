/* cg/draw.h - 2D scan conversion (chapter 2 of the notes). */
#ifndef CG_DRAW_H
#define CG_DRAW_H

#include "cg/core.h"
#include "cg/image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Bresenham's line from pixel (x0, y0) to pixel (x1, y1), both endpoints
 * drawn, in an encoded colour (alpha < 255 blends in linear light).
 * Drawing a to b and b to a gives the same pixels: the line is always walked
 * from the endpoint with the smaller major-axis coordinate. */
cg_status cg_draw_line(cg_image *image, int x0, int y0, int x1, int y1, cg_rgba8 color);

#ifdef __cplusplus
}
#endif
#endif
