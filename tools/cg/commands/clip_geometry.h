/* The polygon-geometry commands of `cg clip` (cg/polygon.h): offset, minkowski, rect,
 * triangulate, simplify.  cmd_clip.c hands them over through this. */
#ifndef CG_TOOL_CLIP_GEOMETRY_H
#define CG_TOOL_CLIP_GEOMETRY_H

#include "options.h"

/* Their command lines (for `cg help clip`'s options too). */
extern const cli_syntax clip_offset_syntax, clip_minkowski_syntax, clip_rect_syntax,
    clip_triangulate_syntax, clip_simplify_syntax;

/* True when name is one of these commands. */
int clip_geometry_handles(const char *name);
/* Runs one; argv[0] is its name.  Returns the exit status. */
int clip_geometry_run(int argc, char **argv);

/* Their lines of `cg help clip`. */
#define CLIP_GEOMETRY_USAGE_LINES                                                                \
    "       cg clip offset DELTA IN [--join miter|round|square|bevel] [--miter-limit M]\n"       \
    "                    [--end butt|square|round|joined] [--arc-tolerance T]\n"                 \
    "                    [--fill evenodd|nonzero|positive|negative] [-o OUT.png] [--repeat N]\n" \
    "       cg clip minkowski sum|difference PATTERN PATH\n"                                     \
    "                    [--fill evenodd|nonzero|positive|negative] [-o OUT.png] [--repeat N]\n" \
    "       cg clip rect XMIN YMIN XMAX YMAX IN [--fill evenodd|nonzero|positive|negative]\n"    \
    "                    [-o OUT.png] [--repeat N]\n"                                            \
    "       cg clip triangulate IN [--min-angle A] [--fill evenodd|nonzero|positive|negative]\n" \
    "                    [-o OUT.png] [--repeat N]\n"                                            \
    "       cg clip simplify TOLERANCE IN [--algorithm rdp|visvalingam]\n"                       \
    "                    [--fill evenodd|nonzero|positive|negative] [-o OUT.png] [--repeat N]\n"
#define CLIP_GEOMETRY_USAGE_TEXT                                                         \
    "offset: inflates (DELTA > 0) or deflates (DELTA < 0) the polygons of IN (WKT\n"     \
    "POLYGON or MULTIPOLYGON), or widens its line strings (LINESTRING or\n"              \
    "MULTILINESTRING) by |DELTA| on each side; prints a WKT MULTIPOLYGON.  --join\n"     \
    "shapes the corners (default miter, cut flat at --miter-limit times |DELTA|,\n"      \
    "default 2); --end the ends of line strings (default round; joined closes each\n"    \
    "into a loop and keeps its band); --arc-tolerance bounds the gap between a round\n"  \
    "join and its chords (default |DELTA|/500).\n\n"                                     \
    "minkowski: the Minkowski sum of the polygons of PATTERN with PATH (line strings:\n" \
    "the pattern swept along them; polygons: their region grown by it), or the\n"        \
    "difference (the pattern reflected through the origin), as a WKT MULTIPOLYGON.\n\n"  \
    "rect: the part of IN inside the rectangle: polygons (under --fill) as a WKT\n"      \
    "MULTIPOLYGON, line strings as a MULTILINESTRING of their pieces in order; a fast\n" \
    "path for small rectangles on large inputs (tiles of a map).\n\n"                    \
    "triangulate: the constrained Delaunay triangulation of the polygons of IN (made\n"  \
    "simple first), with no point added, as a MULTIPOLYGON of triangles.  --min-angle\n" \
    "A (degrees, at most 30) adds points (Ruppert's refinement) until no triangle has\n" \
    "an angle below A, except at input corners sharper than 60 degrees.\n\n"             \
    "simplify: removes vertices of IN's polygons (or line strings) while the shape\n"    \
    "stays within TOLERANCE (a distance for rdp, the default; a triangle's area for\n"   \
    "visvalingam), never making edges cross or touch and keeping every ring.\n"
#endif
