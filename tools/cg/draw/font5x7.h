/* A 5 x 7 pixel bitmap font for status lines drawn into images (the viewer):
 * digits, letters (lower case drawn as upper case) and a few signs. */
#ifndef CG_TOOL_FONT5X7_H
#define CG_TOOL_FONT5X7_H

#include "cg/image.h"

/* Draws text with its top-left corner at (x, y), each font pixel a scale x
 * scale block; characters without a glyph are left blank.  Returns the width
 * drawn in pixels. */
int font_draw(cg_image *image, int x, int y, int scale, const char *text, cg_rgba8 color);

/* Width in pixels of text at the given scale. */
int font_width(const char *text, int scale);

#endif
