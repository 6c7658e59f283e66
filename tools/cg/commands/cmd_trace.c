/* cg trace ALGORITHM ARGS [--json] [--frames DIR] [--html OUT.html]: the
 * course's algorithms step by step.  The algorithms live in trace_*.c (one
 * table per chapter group, trace_algorithms.h); the outputs in
 * trace_output.c, trace_frames.c and trace_page.c. */
#include "cli.h"
#include "command.h"
#include "trace_algorithms.h"

#include <string.h>

static const trace_algorithm *const groups[] = {
    trace_chapter2_algorithms, trace_view_algorithms,     trace_surfaces_algorithms,
    trace_shading_algorithms,  trace_mesh_ops_algorithms, trace_fill_algorithms,
    trace_clip_algorithms,
};

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
    "Prints one of the notes' algorithms step by step in the notes' terms; each\n"
    "trace ends in the library call's own result.  docs/teaching.md gives every\n"
    "algorithm's fields.  Pixels are integer indices; points X,Y (X,Y,Z in 3D).\n\n"
    "Chapter 2:\n"
    "  line X1 Y1 X2 Y2           Bresenham (Algorithm 1): octant mapping, f, E/NE\n"
    "  dda X1 Y1 X2 Y2            the DDA line: x, y accumulated and rounded\n"
    "  wu X1 Y1 X2 Y2             Wu's line: two pixels and intensities per column\n"
    "  circle R                   midpoint circle (Algorithm 2): f, dE, dSE, E/SE\n"
    "  ellipse RX RY              midpoint ellipse: region 1, the switch, region 2\n"
    "  hermite P1 P4 R1 R4 [N]    Q(t) = T M G at N+1 values of t: T, weights T M, Q\n"
    "  bezier P1 P2 P3 P4 [N]     the same for a Bezier segment,\n"
    "  bspline P0 P1 P2 P3 [N]    a uniform B-spline segment\n"
    "  catmull-rom P0 P1 P2 P3 [N] and a Catmull-Rom segment\n"
    "  casteljau T P0 P1 [...]    de Casteljau: every level, the point, the halves\n"
    "  flatten TOL P0 P1 [...]    adaptive flattening: each piece, split or emitted\n"
    "Chapters 3-8:\n"
    "  pipeline X,Y,Z [EYE [TARGET [FOVY [WxH]]]]  one point through M, V, P, W\n"
    "  vanishing DX,DY,DZ [EYE [TARGET [FOVY [WxH]]]]  the vanishing point of d\n"
    "  backface MESH [ABOUT_Y [ABOUT_X]]  N, V and the sign of N.V per triangle\n"
    "  zbuffer MESH X Y [WxH]     every fragment at one pixel, accepted or not\n"
    "  painter MESH [ABOUT_Y [ABOUT_X]]  the depth-sorted list, Newell's tests per\n"
    "                             pair, each swap or split, the painting order\n"
    "  ray spheres|MESH X Y [WxH] a pixel's ray tree: hits, shadow rays,\n"
    "                             reflection, refraction, Fresnel, contributions\n"
    "  light POINT NORMAL EYE [LIGHT ...]  ambient, diffuse, specular per light\n"
    "                             (ambient:R,G,B point:X,Y,Z:R,G,B directional:...)\n"
    "  shading flat|gouraud|phong MESH X Y [WxH]  one pixel: barycentrics,\n"
    "                             interpolated colour or normal, lighting terms\n"
    "  hsv R G B                  RGB to HSV by the notes' formulas\n"
    "  hsl R G B                  RGB to HSL\n"
    "  quantize LEVELS I [I ...]  intensity to pixel: s = I (N-1), k, the error\n"
    "  dither METHOD LEVELS ramp:WxH|IMAGE  bayer2|bayer4|bayer8: threshold per\n"
    "                             pixel; floyd-steinberg: the error pushed on\n"
    "  gamma GAMMA I [I ...]      V = I^(1/gamma), its code, what the CRT shows\n"
    "Chapter 9:\n"
    "  face-loop MESH F           a face's half-edges by next: origin, next, twin\n"
    "  one-ring MESH V            a vertex's outgoing half-edges by twin(prev(h))\n"
    "  loop MESH V                Loop's stencil: weights, neighbours, new vertex\n"
    "  catmull-clark MESH V       Catmull-Clark's: face points, edge midpoints\n"
    "  edge-flip MESH E           half-edge records before and after a flip,\n"
    "  edge-split MESH E          a split at the midpoint,\n"
    "  edge-collapse MESH E       a collapse of half-edge 2E\n"
    "Chapter 10 (image coordinates, y down):\n"
    "  scanline 'POLYGON' [even-odd|nonzero]  edge table, active list, spans\n"
    "  flood IMAGE X Y [4|8] [TOL]  seed fill: each seed popped, span, pushes\n"
    "  boundary IMAGE X Y COLOR [4|8] [TOL]  the same inside a boundary colour\n"
    "Chapter 11 (y-up; polygons as 'X,Y X,Y X,Y ...'):\n"
    "  cohen-sutherland XMIN YMIN XMAX YMAX P0 P1  region codes and decisions\n"
    "  liang-barsky XMIN YMIN XMAX YMAX P0 P1  p, q, t per boundary\n"
    "  sutherland-hodgman 'WINDOW' 'SUBJECT'  input and output lists per edge\n"
    "  weiler-atherton 'WINDOW' 'SUBJECT'  crossings, lists, the traversal\n"
    "  frustum 'X,Y,Z ...' [EYE [TARGET [FOVY]]]  3D polygon against each plane\n\n"
    "By default a table per phase, with notes above it; the options go anywhere.\n"
    "Example: cg trace line 1 1 22 9;  cg trace circle 11 --html circle.html\n",
    run,
    trace_syntaxes,
};
