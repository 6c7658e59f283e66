/* cg trace ALGORITHM ARGS [--json] [--frames DIR] [--html OUT.html]: the
 * course's algorithms step by step.  The algorithms live in trace_*.c (one
 * table per chapter group, trace_algorithms.h); the outputs in
 * trace_output.c, trace_frames.c and trace_page.c. */
#include "cli.h"
#include "command.h"
#include "trace_algorithms.h"

#include <string.h>

static const trace_algorithm *const groups[] = {trace_chapter2_algorithms, trace_view_algorithms, trace_fill_algorithms,
                                                trace_clip_algorithms};

static const cli_syntax *const trace_syntaxes[] = {&trace_output_syntax, NULL};

static int run(int argc, char **argv)
{
    trace_outputs outputs;
    if (trace_outputs_parse(&argc, argv, &outputs) != 0)
        return CLI_USAGE;
    if (argc < 2)
        return cli_usage_error("trace", "expected an algorithm, as 'line X1 Y1 X2 Y2' or "
                                        "'circle R'");
    for (size_t g = 0; g < sizeof groups / sizeof groups[0]; g++)
        for (const trace_algorithm *a = groups[g]; a->name; a++)
            if (strcmp(argv[1], a->name) == 0)
                return a->run(argc - 1, argv + 1, &outputs);
    return cli_usage_error("trace", "unknown algorithm '%s' (run 'cg help trace' for the list)",
                           argv[1]);
}

const cg_command cg_command_trace = {
    "trace",
    "print the course's algorithms step by step (table, JSON, pictures, a page)",
    "usage: cg trace ALGORITHM ARGS [--json] [--frames DIR] [--html OUT.html]\n\n"
    "Prints each step of one of the notes' algorithms in the notes' terms: the\n"
    "decision variables, the move chosen, the pixels or points produced.  Each\n"
    "trace ends in the same result as the library call it explains.\n\n"
    "Chapter 2 (pixels are integer indices; points are X,Y image-plane coordinates):\n"
    "  line X1 Y1 X2 Y2           Bresenham's line (Algorithm 1), any octant: the octant\n"
    "                             mapping, then f, the move E/NE, f after the update\n"
    "  dda X1 Y1 X2 Y2            the DDA line: x, y accumulated, rounded to pixels\n"
    "  wu X1 Y1 X2 Y2             Wu's anti-aliased line: the two pixels and their\n"
    "                             intensities in each column\n"
    "  circle R                   the midpoint circle (Algorithm 2): f, dE, dSE, E/SE\n"
    "  ellipse RX RY              the midpoint ellipse: region 1 (E/SE), the switch,\n"
    "                             region 2 (S/SE), with the decision d at each step\n"
    "  hermite P1 P4 R1 R4 [N]    Q(t) = T M G at N+1 values of t (default 8): T, the\n"
    "  bezier P1 P2 P3 P4 [N]     blending weights T M and the point Q\n"
    "  bspline P0 P1 P2 P3 [N]\n"
    "  catmull-rom P0 P1 P2 P3 [N]\n"
    "  casteljau T P0 P1 [...]    de Casteljau at t: every level's points, the curve point\n"
    "                             and the two halves of the subdivision\n"
    "  flatten TOL P0 P1 [...]    adaptive flattening: each piece, its distance from\n"
    "                             the chord, split or emitted and why\n\n"
    "Chapters 3-7:\n"
    "  pipeline X,Y,Z [EYE [TARGET [FOVY [WxH]]]]\n"
    "                             one point through each matrix (model, view,\n"
    "                             projection, viewport): homogeneous coordinates before\n"
    "                             and after the divide, the pixel it lands on\n"
    "  vanishing DX,DY,DZ [EYE [TARGET [FOVY [WxH]]]]\n"
    "                             the vanishing point of a direction: (d, 0) through V, P,\n"
    "                             the divide and the viewport\n"
    "  backface MESH [ABOUT_Y [ABOUT_X]]\n"
    "                             back-face culling per triangle: N, V, the sign of N.V\n"
    "  zbuffer MESH X Y [WxH]     the z-buffer at one pixel: each triangle near it, its\n"
    "                             barycentric coordinates, depth, accepted or rejected\n"
    "  light POINT NORMAL EYE [LIGHT ...]\n"
    "                             ambient, diffuse, specular per light (LIGHT as\n"
    "                             ambient:R,G,B, point:X,Y,Z:R,G,B, directional:X,Y,Z:R,G,B)\n"
    "  hsv R G B                  RGB to HSV by the notes' formulas\n"
    "  hsl R G B                  RGB to HSL\n\n"
    "Chapter 10 (image coordinates, y down):\n"
    "  scanline 'POLYGON' [even-odd|nonzero]\n"
    "                             scan-line fill: the edge table, then per scan-line the\n"
    "                             active edge list and the spans with the pixel-centre\n"
    "                             rule; contours separated by ';'\n"
    "  flood IMAGE X Y [4|8] [TOL]\n"
    "                             seed fill of the region like the seed pixel, with\n"
    "                             the stack of seeds: each pop, span filled, pushes\n"
    "  boundary IMAGE X Y COLOR [4|8] [TOL]\n"
    "                             the same inside a boundary colour\n\n"
    "Chapter 11 (y-up coordinates; a window is XMIN YMIN XMAX YMAX):\n"
    "  cohen-sutherland XMIN YMIN XMAX YMAX P0 P1\n"
    "                             the TBRL region codes and each decision\n"
    "  liang-barsky XMIN YMIN XMAX YMAX P0 P1\n"
    "                             p, q and t for each boundary, entering or leaving\n"
    "  sutherland-hodgman 'WINDOW' 'SUBJECT'\n"
    "                             the input and output lists for each clip edge;\n"
    "                             polygons as 'X,Y X,Y X,Y ...'\n"
    "  weiler-atherton 'WINDOW' 'SUBJECT'\n"
    "                             any simple window: the crossings (entering or\n"
    "                             exiting), both lists, each leg of the traversal\n\n"
    "By default a table per phase of the algorithm, with notes above it; the\n"
    "options below go anywhere on the line.\n\n"
    "Example: cg trace line 1 1 22 9;  cg trace circle 11 --html circle.html\n",
    run,
    trace_syntaxes,
};
