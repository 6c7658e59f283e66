/* cg draw FILE -o OUT: runs a drawing script (docs/draw-script.md). */
#include "cli.h"
#include "command.h"
#include "draw_script_run.h"

#include <stdio.h>
#include <stdlib.h>

static int run(int argc, char **argv)
{
    const char *input = NULL, *output = NULL;
    long repeat = 1;
    for (int i = 1; i < argc; i++) {
        if (cli_option_is(argv[i], "-o") || cli_option_is(argv[i], "--output")) {
            if (!(output = cli_option_value("draw", argc, argv, &i)))
                return CLI_USAGE;
        } else if (cli_option_is(argv[i], "--repeat")) {
            const char *value = cli_option_value("draw", argc, argv, &i);
            if (!value || cli_parse_long("draw", "--repeat", value, 1, 1000000, &repeat))
                return CLI_USAGE;
        } else if (cli_is_option(argv[i])) {
            return cli_usage_error("draw", "unknown option '%s'", argv[i]);
        } else if (input) {
            return cli_usage_error("draw", "expected one script, got '%s' as a second", argv[i]);
        } else {
            input = argv[i];
        }
    }
    if (!input)
        return cli_usage_error("draw", "expected a script FILE (or - for stdin)");
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
    "draw lines, circles, curves, polygons and paths from a script",
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
    "  flood X Y           flood8 X Y     boundaryfill X Y BOUNDARY_COLOR\n"
    "Integer coordinates (pixel indices) for line, polyline, circle, disc, ellipse,\n"
    "arcs and the flood seeds; decimals for the others.  A bad line is reported as\n"
    "FILE:LINE: what was expected, and no output is written.  A UTF-8 byte-order\n"
    "mark before the first line is skipped.  See docs/draw-script.md.\n\n"
    "  -o OUT       the image to write (required)\n"
    "  --repeat N   draw N times, each on a fresh canvas, and print the median\n"
    "               drawing time on stderr as 'draw: 12.3 ms'\n",
    run,
    NULL,
};
