/* cg/svg.h - SVG documents: the static subset icon themes and illustrators
 * use, read with expat and drawn with cg's anti-aliased fill (cg/fill.h).
 *
 * Read: svg (width, height, viewBox, preserveAspectRatio; nested), g, defs,
 * use, symbol, switch, a; path, rect (rx, ry), circle, ellipse, line,
 * polyline, polygon; transform lists; presentation attributes, the style
 * attribute and <style> sheets (type, class, id, universal and descendant
 * or child selectors); fill and stroke with all their properties, opacity,
 * color and currentColor, display, visibility, paint-order, mix-blend-mode;
 * linear and radial gradients (gradientUnits, gradientTransform,
 * spreadMethod, fx/fy, href inheritance); clipPath, mask; image with an
 * embedded PNG (data: URI); text and tspan (x, y, dx, dy, font-family,
 * font-size, font-weight, font-style, text-anchor), shaped and drawn with
 * cg/text.h.  Compositing is in sRGB, SVG's default.
 *
 * Anything else (filters, patterns, markers, textPath, animation, scripts,
 * foreignObject, references to other files) is skipped with one warning
 * naming it; nothing is ever fetched.
 *
 * Hostile files are refused with a message in bounded time and memory:
 * entity declarations (entity expansion, external entities), nesting deeper
 * than CG_SVG_MAX_DEPTH, more than CG_SVG_MAX_ELEMENTS elements, files over
 * CG_SVG_MAX_BYTES, <use> cycles and <use> trees expanding to more than
 * CG_SVG_MAX_RENDERED elements. */
#ifndef CG_SVG_H
#define CG_SVG_H

#include "cg/core.h"
#include "cg/image.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CG_SVG_MAX_BYTES (64u << 20) /* 64 MiB of XML */
#define CG_SVG_MAX_DEPTH 256         /* nesting of elements */
#define CG_SVG_MAX_ELEMENTS 1000000  /* elements in the file */
#define CG_SVG_MAX_RENDERED 2000000  /* elements drawn, <use> expanded */

typedef struct cg_svg cg_svg;

/* Reads an SVG file (or bytes in memory; name is used in messages).
 * CG_EIO when the file cannot be read, CG_EFORMAT with "name:line: ..." for
 * malformed or refused XML, CG_ERANGE beyond the limits above. */
cg_status cg_svg_load(const char *path, cg_svg **out, cg_error *err);
cg_status cg_svg_load_memory(const void *bytes, size_t size, const char *name, cg_svg **out,
                             cg_error *err);
void cg_svg_free(cg_svg *svg);

/* The document's size in pixels (CSS px, 96 per inch): the root's width and
 * height, else its viewBox's, else 100 x 100. */
void cg_svg_size(const cg_svg *svg, double *width, double *height);

/* Warnings of the reader: one per kind of skipped content, such as
 * "skipped <filter>: filter effects are not supported". */
int cg_svg_warning_count(const cg_svg *svg);
const char *cg_svg_warning(const cg_svg *svg, int index);

/* Draws the document onto image (RGBA8 or RGBAF, composited over what it
 * holds) with the document's px coordinates mapped by transform (an affine
 * cg_mat3; the identity draws it at its own size).  CG_EFORMAT with a
 * message for a <use> cycle or too large an expansion; CG_EINVAL for a bad
 * argument. */
cg_status cg_svg_render(const cg_svg *svg, cg_image *image, cg_mat3 transform, cg_error *err);

#ifdef __cplusplus
}
#endif
#endif
