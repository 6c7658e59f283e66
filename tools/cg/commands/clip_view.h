/* Polygon sets as text (WKT) and as pictures, shared by `cg clip` and the
 * clipping gallery. */
#ifndef CG_TOOL_CLIP_VIEW_H
#define CG_TOOL_CLIP_VIEW_H

#include "cg/clip.h"
#include "cg/image.h"

#include <stdio.h>

/* Parses WKT POLYGON or MULTIPOLYGON (EMPTY allowed) into set (appended;
 * every ring becomes a path, the closing point of each ring dropped).
 * CG_EFORMAT with "NAME: offset N: expected ..." in err. */
cg_status clip_wkt_parse(const char *text, const char *name, cg_polygon_set *set, cg_error *err);
/* Reads a whole file ("-" for stdin) and parses it. */
cg_status clip_wkt_read(const char *path, cg_polygon_set *set, cg_error *err);
/* Writes set as WKT MULTIPOLYGON (a result: polygons with their holes; rings
 * closed), or "MULTIPOLYGON EMPTY", and a newline. */
void clip_wkt_write(FILE *out, const cg_polygon_set *set);

/* World (y up) to pixels (y down), fitting a box with a margin. */
typedef struct clip_view {
    double scale, ox, oy;
    int height;
} clip_view;

clip_view clip_view_fit(cg_vec2 lo, cg_vec2 hi, int width, int height, int margin);
/* Grows [lo, hi] to hold the set's points. */
void clip_bounds_add(const cg_polygon_set *set, cg_vec2 *lo, cg_vec2 *hi);
cg_vec2 clip_view_map(const clip_view *v, cg_vec2 p);
/* The blank picture of a clip: a white square image of size pixels and the
 * view fitting the points of sets[0..count) (NULL entries skipped; the unit
 * box when there are none) with a 24-pixel margin.  CG_ENOMEM leaves
 * *image NULL. */
cg_status clip_view_canvas(const cg_polygon_set *const *sets, size_t count, int size,
                           cg_image **image, clip_view *view);
/* Fills the set (non-zero rule, so a result with holes), anti-aliased. */
cg_status clip_view_fill(cg_image *image, const clip_view *v, const cg_polygon_set *set,
                         cg_rgba8 color);
/* Strokes every ring of the set (width in pixels), closed. */
cg_status clip_view_stroke(cg_image *image, const clip_view *v, const cg_polygon_set *set,
                           double width, cg_rgba8 color);
/* Strokes one polyline (closed or not). */
cg_status clip_view_polyline(cg_image *image, const clip_view *v, const cg_vec2 *p, size_t n,
                             int closed, double width, cg_rgba8 color);

#endif
