/* WKT for the polygon-geometry commands of `cg clip` (offset, rect,
 * triangulate, simplify): polygons as clip_view.h reads them, and open
 * polylines (LINESTRING, MULTILINESTRING). */
#ifndef CG_TOOL_CLIP_PATHS_H
#define CG_TOOL_CLIP_PATHS_H

#include "cg/clip.h"

#include <stdio.h>

/* Reads a whole file ("-" for stdin) as WKT POLYGON or MULTIPOLYGON (*open
 * set to 0: every ring a closed path) or LINESTRING or MULTILINESTRING
 * (*open set to 1: every line string an open path, all its points kept).
 * EMPTY is allowed.  CG_EFORMAT with "NAME: offset N: expected ..." in err. */
cg_status clip_paths_read(const char *path, cg_polygon_set *set, int *open, cg_error *err);
/* Writes every ring of set as an open path: MULTILINESTRING, or
 * "MULTILINESTRING EMPTY", and a newline. */
void clip_paths_write_lines(FILE *out, const cg_polygon_set *set);

#endif
