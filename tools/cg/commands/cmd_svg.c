/* cg svg IN.svg -o OUT.png [--width W | --height H | --zoom Z] [--background COLOR] */
#include "cli.h"
#include "command.h"

#include <stddef.h>
#include "cg/fill.h"
#include "cg/svg.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The output size: the document's, scaled by --zoom, or fitted to --width
 * or --height keeping the aspect, rounded to whole pixels (as resvg and
 * rsvg-convert round: 16 x 16.007 at 64 px wide is 64 x 64); at least one
 * pixel. */
static int output_size(double doc_w, double doc_h, double width, double height, double zoom, int *w,
                       int *h, double *scale_out)
{
    double scale = zoom;
    if (width > 0)
        scale = width / doc_w;
    else if (height > 0)
        scale = height / doc_h;
    double fw = width > 0 ? width : floor(doc_w * scale + 0.5);
    double fh = height > 0 ? height : floor(doc_h * scale + 0.5);
    if (!(fw >= 1))
        fw = 1;
    if (!(fh >= 1))
        fh = 1;
    if (fw > CG_IMAGE_MAX_SIDE || fh > CG_IMAGE_MAX_SIDE || fw * fh > CG_IMAGE_MAX_PIXELS)
        return -1;
    *w = (int)fw;
    *h = (int)fh;
    *scale_out = scale;
    return 0;
}

typedef struct svg_arguments {
    const char *output;
    double width, height, zoom;
    cg_rgba8 background;
    int width_given, height_given, zoom_given, background_given;
} svg_arguments;

static const cli_option svg_options[] = {
    CLI_OPTION_OUTPUT(svg_arguments, output, "OUT",
                      "the image to write (required): .png, .ppm or .pgm"),
    {.name = "--width",
     .kind = CLI_DOUBLE,
     .offset = offsetof(svg_arguments, width),
     .value_name = "W",
     .given = CLI_GIVEN(svg_arguments, width_given),
     .low = 0,
     .high = CG_IMAGE_MAX_SIDE,
     .open = CLI_OPEN_LOW,
     .range_text = "a number > 0 and at most 16777216",
     .help = "W pixels wide, the height keeping the aspect"},
    {.name = "--height",
     .kind = CLI_DOUBLE,
     .offset = offsetof(svg_arguments, height),
     .value_name = "H",
     .given = CLI_GIVEN(svg_arguments, height_given),
     .low = 0,
     .high = CG_IMAGE_MAX_SIDE,
     .open = CLI_OPEN_LOW,
     .range_text = "a number > 0 and at most 16777216",
     .help = "H pixels high, the width keeping the aspect"},
    {.name = "--zoom",
     .kind = CLI_DOUBLE,
     .offset = offsetof(svg_arguments, zoom),
     .value_name = "Z",
     .given = CLI_GIVEN(svg_arguments, zoom_given),
     .low = 0,
     .high = 1e6,
     .open = CLI_OPEN_LOW,
     .range_text = "a number > 0",
     .help = "Z times the document's size (default 1)"},
    {.name = "--background",
     .kind = CLI_COLOR,
     .offset = offsetof(svg_arguments, background),
     .value_name = "COLOR",
     .given = CLI_GIVEN(svg_arguments, background_given),
     .help = "the colour under the picture (default transparent)"},
};
static const cli_option_group svg_groups[] = {CLI_GROUP(NULL, svg_options), {0}};
static const cli_syntax svg_syntax = {
    .command = "svg",
    .groups = svg_groups,
    .max_positionals = 1,
    .too_many = "expected one input file, got '%s' as a second",
};
static const cli_syntax *const svg_syntaxes[] = {&svg_syntax, NULL};

static int run(int argc, char **argv)
{
    svg_arguments a = {NULL, 0, 0, 0, {0, 0, 0, 0}, 0, 0, 0, 0};
    const char *in = NULL;
    if (cli_parse(&svg_syntax, argc, argv, &a, &in, NULL) != CLI_OK)
        return CLI_USAGE;
    const char *out = a.output;
    if (a.width_given + a.height_given + a.zoom_given > 1)
        return cli_usage_error("svg", "give one of --width, --height and --zoom");
    double width = a.width_given ? a.width : 0, height = a.height_given ? a.height : 0;
    double zoom = a.zoom_given ? a.zoom : 0;
    int have_background = a.background_given > 0;
    cg_rgba8 background = a.background;
    if (!in)
        return cli_usage_error("svg", "expected an input file IN.svg");
    if (!out)
        return cli_usage_error("svg", "expected -o OUT.png");
    if (cg_file_format_from_path(out) == CG_FILE_UNKNOWN)
        return cli_usage_error("svg", "%s: unknown output format (expected .png, .ppm, .pgm)", out);
    cg_svg *svg;
    cg_error err;
    if (cg_svg_load(in, &svg, &err) != CG_OK)
        return cli_fail("%s", err.message);
    for (int i = 0; i < cg_svg_warning_count(svg); i++)
        fprintf(stderr, "cg: %s: warning: %s\n", in, cg_svg_warning(svg, i));
    double doc_w, doc_h;
    cg_svg_size(svg, &doc_w, &doc_h);
    int w, h;
    double scale;
    if (output_size(doc_w, doc_h, width, height, zoom > 0 ? zoom : 1, &w, &h, &scale) != 0) {
        cg_svg_free(svg);
        return cli_fail("%s: the picture would be %.0f x %.0f px, over the limit of %d px a side "
                        "and %lld pixels",
                        in, doc_w * (zoom > 0 ? zoom : 1), doc_h * (zoom > 0 ? zoom : 1),
                        CG_IMAGE_MAX_SIDE, (long long)CG_IMAGE_MAX_PIXELS);
    }
    cg_image *image;
    cg_status status = cg_image_create(&image, w, h, CG_PIXEL_RGBA8);
    if (status != CG_OK) {
        cg_svg_free(svg);
        return cli_fail("%s: cannot make a %d x %d image: %s", in, w, h, cg_status_str(status));
    }
    if (have_background)
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                cg_image_row_rgba8(image, y)[x] = background;
    cg_mat3 m = cg_mat3_identity();
    m.m[0][0] = scale; /* one scale: the rounded side is cut or padded, not stretched */
    m.m[1][1] = scale;
    status = cg_svg_render(svg, image, m, &err);
    cg_svg_free(svg);
    int result = status == CG_OK ? cli_write_image(image, out) : cli_fail("%s", err.message);
    cg_image_free(image);
    return result;
}

const cg_command cg_command_svg = {
    "svg",
    "render an SVG file to PNG",
    "usage: cg svg IN.svg -o OUT.png [--width W | --height H | --zoom Z] [--background COLOR]\n\n"
    "Draws the SVG document IN.svg (the static subset icon themes use: shapes,\n"
    "paths, groups, use and symbol, style sheets, gradients, clip paths, masks,\n"
    "opacity, embedded PNG images, text and tspan) into OUT (.png, .ppm or\n"
    ".pgm), compositing in sRGB as SVG specifies.  The picture has the document's size in px, or "
    "is\n"
    "scaled to W pixels wide or H high (the other side keeps the aspect), or by\n"
    "the factor Z.  It is transparent unless --background gives a colour\n"
    "(#rrggbb, #rrggbbaa or a name).  Unsupported content (filters, textPath,\n"
    "patterns, markers, animation, scripts, other files) is skipped with one\n"
    "warning for each kind on stderr; nothing is ever fetched.  See docs/svg.md.\n",
    run,
    svg_syntaxes,
};
