/* cg svg IN.svg -o OUT.png [--width W | --height H | --zoom Z] [--background COLOR] */
#include "cli.h"
#include "command.h"
#include "cg/fill.h"
#include "cg/svg.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The output size: the document's, scaled by --zoom, or fitted to --width
 * or --height keeping the aspect, rounded to whole pixels (as resvg and
 * rsvg-convert round: 16 x 16.007 at 64 px wide is 64 x 64); at least one
 * pixel. */
static int output_size(double doc_w, double doc_h, double width, double height, double zoom,
                       int *w, int *h, double *scale_out)
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

static int run(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    double width = 0, height = 0, zoom = 0;
    int sized = 0, have_background = 0;
    cg_rgba8 background = {0, 0, 0, 0};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (cli_option_is(a, "-o") || cli_option_is(a, "--output")) {
            if (!(out = cli_option_value("svg", argc, argv, &i)))
                return CLI_USAGE;
        } else if (cli_option_is(a, "--width") || cli_option_is(a, "--height")
                   || cli_option_is(a, "--zoom")) {
            const char *name = cli_option_is(a, "--width") ? "--width"
                               : cli_option_is(a, "--height") ? "--height" : "--zoom";
            if (sized++)
                return cli_usage_error("svg", "give one of --width, --height and --zoom");
            const char *v = cli_option_value("svg", argc, argv, &i);
            double d;
            if (!v || cli_parse_double("svg", name, v, &d))
                return CLI_USAGE;
            if (!(d > 0) || d > (strcmp(name, "--zoom") == 0 ? 1e6 : CG_IMAGE_MAX_SIDE))
                return cli_usage_error("svg", "%s: expected a number > 0%s, got '%s'", name,
                                       strcmp(name, "--zoom") == 0 ? "" : " and at most 16777216",
                                       v);
            if (strcmp(name, "--width") == 0)
                width = d;
            else if (strcmp(name, "--height") == 0)
                height = d;
            else
                zoom = d;
        } else if (cli_option_is(a, "--background")) {
            const char *v = cli_option_value("svg", argc, argv, &i);
            if (!v || cli_parse_color("svg", "--background", v, &background))
                return CLI_USAGE;
            have_background = 1;
        } else if (cli_is_option(a)) {
            return cli_usage_error("svg", "unknown option '%s'", a);
        } else if (in) {
            return cli_usage_error("svg", "expected one input file, got '%s' as a second", a);
        } else {
            in = a;
        }
    }
    if (!in)
        return cli_usage_error("svg", "expected an input file IN.svg");
    if (!out)
        return cli_usage_error("svg", "expected -o OUT.png");
    if (cg_file_format_from_path(out) == CG_FILE_UNKNOWN)
        return cli_usage_error("svg", "%s: unknown output format (expected .png, .ppm, .pgm)",
                               out);
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
                        "and %lld pixels", in, doc_w * (zoom > 0 ? zoom : 1),
                        doc_h * (zoom > 0 ? zoom : 1), CG_IMAGE_MAX_SIDE,
                        (long long)CG_IMAGE_MAX_PIXELS);
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
    "opacity, embedded PNG images) into OUT (.png, .ppm or .pgm), compositing in\n"
    "sRGB as SVG specifies.  The picture has the document's size in px, or is\n"
    "scaled to W pixels wide or H high (the other side keeps the aspect), or by\n"
    "the factor Z.  It is transparent unless --background gives a colour\n"
    "(#rrggbb, #rrggbbaa or a name).  Unsupported content (filters, text,\n"
    "patterns, markers, animation, scripts, other files) is skipped with one\n"
    "warning for each kind on stderr; nothing is ever fetched.\n",
    run,
};
