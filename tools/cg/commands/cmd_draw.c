/* cg draw FILE -o OUT: runs a drawing script (docs/draw-script.md). */
#include "cli.h"
#include "command.h"
#include "draw_script_run.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct draw_arguments {
    const char *output;
    int repeat;
} draw_arguments;

static const cli_option draw_options[] = {
    CLI_OPTION_OUTPUT(draw_arguments, output, "OUT", "the image to write (required)"),
    CLI_OPTION_REPEAT(draw_arguments, repeat, 1000000,
                      "draw N times, each on a fresh canvas, and print the median\n"
                      "drawing time on stderr as 'draw: 12.3 ms'"),
};
static const cli_option_group draw_groups[] = {CLI_GROUP(NULL, draw_options), {0}};
static const cli_syntax draw_syntax = {
    .command = "draw",
    .groups = draw_groups,
    .max_positionals = 1,
    .too_many = "expected one script, got '%s' as a second",
    .min_positionals = 1,
    .too_few = "expected a script FILE (or - for stdin)",
};
static const cli_syntax *const draw_syntaxes[] = {&draw_syntax, NULL};

static int run(int argc, char **argv)
{
    draw_arguments arguments = {NULL, 1};
    const char *input = NULL;
    if (cli_parse(&draw_syntax, argc, argv, &arguments, &input, NULL) != CLI_OK)
        return CLI_USAGE;
    const char *output = arguments.output;
    long repeat = arguments.repeat;
    if (!output)
        return cli_usage_error("draw", "expected -o OUT.png (or .ppm, .pgm)");
    if (cg_file_format_from_path(output) == CG_FILE_UNKNOWN)
        return cli_usage_error("draw", "%s: unknown output format (expected .png, .ppm, .pgm)",
                               output);
    draw_script script;
    if (draw_script_load(input, &script))
        return CLI_FAILED;
    double *times = malloc((size_t)repeat * sizeof *times);
    if (!times) {
        draw_script_free(&script);
        return cli_fail("draw: out of memory");
    }
    draw_state state;
    int status = CLI_OK;
    for (long i = 0; i < repeat; i++) {
        if (i > 0)
            draw_state_release(&state);
        double start = cli_now();
        int failed = draw_script_run(&script, &state);
        times[i] = cli_now() - start;
        if (failed) {
            status = CLI_FAILED;
            break;
        }
    }
    if (status == CLI_OK) {
        if (repeat > 1) {
            double ms = cli_median(times, (int)repeat) * 1e3;
            fprintf(stderr, ms >= 1 ? "draw: %.1f ms\n" : "draw: %.3f ms\n", ms);
        }
        status = cli_write_image(state.canvas, output);
    }
    draw_state_release(&state);
    free(times);
    draw_script_free(&script);
    return status;
}

const cg_command cg_command_draw = {
    "draw",
    "draw lines, circles, curves, polygons, paths and text from a script",
    "usage: cg draw FILE -o OUT [--repeat N]\n\n"
    "Runs the drawing script FILE (- for stdin) and writes the canvas to OUT in the\n"
    "format of its extension: .png, .ppm or .pgm.  One command a line, # starts a\n"
    "comment:\n"
    "  size W H            background COLOR      color COLOR\n"
    "  tolerance T         antialias on|off\n"
    "  line X0 Y0 X1 Y1    aaline X0 Y0 X1 Y1    polyline X0 Y0 X1 Y1 ...\n"
    "  circle CX CY R      disc CX CY R          aacircle CX CY R\n"
    "  ellipse CX CY RX RY aaellipse CX CY RX RY\n"
    "  arc CX CY R START_DEG END_DEG      ellipsearc CX CY RX RY START_DEG END_DEG\n"
    "  bezier X0 Y0 ... Xn Yn             hermite P1X P1Y P4X P4Y R1X R1Y R4X R4Y\n"
    "  bspline X0 Y0 ... (4+ points)      catmullrom X0 Y0 ... (4+ points)\n"
    "Filling:\n"
    "  polygon X0 Y0 X1 Y1 X2 Y2 ...      aapolygon X0 Y0 X1 Y1 X2 Y2 ...\n"
    "  contour X0 Y0 X1 Y1 X2 Y2 ...      (a hole or further contour of the polygon above)\n"
    "  fillrule evenodd|nonzero           path SVG_PATH_DATA (M L H V C S Q T A Z)\n"
    "  fill                stroke         width W             dash ON OFF ...\n"
    "  join miter|round|bevel             cap butt|round|square\n"
    "  compositing linear|srgb [OPERATOR [BLEND_MODE]]   (how later fills mix colours)\n"
    "  flood X Y           flood8 X Y     boundaryfill X Y BOUNDARY_COLOR\n"
    "Text (filled with the colour and compositing of fill):\n"
    "  font FAMILY-OR-FILE SIZE           (a fontconfig family such as DejaVu Sans,\n"
    "                                      sans-serif, or a .ttf/.otf/.ttc file; SIZE px;\n"
    "                                      DejaVu Sans:bold:italic, :weight=600 choose faces)\n"
    "  text X Y STRING                    (the words after Y; \"quoted\" keeps blanks,\n"
    "                                      #, and \\\" \\\\ \\n escapes)\n"
    "  align start|middle|end             baseline alphabetic|top|middle|bottom\n"
    "  wrap WIDTH (0 or off: no wrapping) linespacing FACTOR (default 1.2)\n"
    "Integer coordinates (pixel indices) for line, polyline, circle, disc, ellipse,\n"
    "arcs and the flood seeds; decimals for the others.  A bad line is reported as\n"
    "FILE:LINE: what was expected, and no output is written.  A UTF-8 byte-order\n"
    "mark before the first line is skipped.  See docs/draw-script.md.\n",
    run,
    draw_syntaxes,
};
