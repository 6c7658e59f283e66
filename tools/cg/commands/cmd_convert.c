/* cg convert IN OUT: between PNG, PPM, PGM and the float formats PFM,
 * Radiance HDR and OpenEXR, tone-mapping float images for 8-bit outputs. */
#include "cli.h"
#include "command.h"
#include "cg/image_float.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>

typedef struct convert_arguments {
    double exposure;
    int tonemap; /* index into tonemap_names */
    int exr_float;
} convert_arguments;

static const char *const tonemap_names[] = {"clamp", "none", "filmic", NULL};
static const cg_tonemap tonemaps[] = {CG_TONEMAP_CLAMP, CG_TONEMAP_CLAMP, CG_TONEMAP_FILMIC};

static const cli_option convert_options[] = {
    {.name = "--exposure",
     .kind = CLI_DOUBLE,
     .offset = offsetof(convert_arguments, exposure),
     .value_name = "STOPS",
     .low = -1000,
     .high = 1000,
     .range_text = "a number of stops in [-1000, 1000]",
     .help = "multiply the colours by 2^STOPS (default 0)"},
    {.name = "--tonemap",
     .kind = CLI_CHOICE,
     .offset = offsetof(convert_arguments, tonemap),
     .choices = tonemap_names,
     .help = "the curve from float to an 8-bit OUT: clamp (= none, the default)\n"
             "or filmic (ACES-like)"},
    {.name = "--exr-float",
     .kind = CLI_FLAG,
     .offset = offsetof(convert_arguments, exr_float),
     .flag_value = 1,
     .help = "write an .exr OUT with 32-bit float channels (default: half)"},
};
static const cli_option_group convert_groups[] = {CLI_GROUP(NULL, convert_options), {0}};
static const cli_syntax convert_syntax = {
    .command = "convert",
    .groups = convert_groups,
    .max_positionals = 2,
    .too_many = "expected two files, got '%s' as a third",
    .min_positionals = 2,
    .too_few = "expected IN and OUT files",
};
static const cli_syntax *const convert_syntaxes[] = {&convert_syntax, NULL};

/* The image to write: float for a float OUT, tone-mapped 8-bit otherwise. */
static cg_status prepare(cg_image **image, const convert_arguments *a, int float_out)
{
    cg_image *next = NULL;
    cg_status status = CG_OK;
    cg_tonemap curve = tonemaps[a->tonemap];
    if ((*image)->format == CG_PIXEL_RGBA8 && (float_out || a->exposure != 0 || a->tonemap == 2)) {
        if ((status = cg_image_decode_srgb(*image, &next)) != CG_OK)
            return status;
        cg_image_free(*image);
        *image = next;
    }
    if ((*image)->format != CG_PIXEL_RGBAF)
        return CG_OK;
    if (float_out) {
        float scale = (float)exp2(a->exposure);
        for (int y = 0; y < (*image)->height && a->exposure != 0; y++) {
            cg_rgbaf *row = cg_image_row_rgbaf(*image, y);
            for (int x = 0; x < (*image)->width; x++) {
                row[x].r *= scale;
                row[x].g *= scale;
                row[x].b *= scale;
            }
        }
        return CG_OK;
    }
    if ((status = cg_image_tonemap_curve(*image, a->exposure, curve, &next)) != CG_OK)
        return status;
    cg_image_free(*image);
    *image = next;
    return CG_OK;
}

static int run(int argc, char **argv)
{
    convert_arguments a = {0};
    const char *paths[2];
    if (cli_parse(&convert_syntax, argc, argv, &a, paths, NULL) != CLI_OK)
        return CLI_USAGE;
    cg_file_format format = cg_file_format_from_path(paths[1]);
    if (format == CG_FILE_UNKNOWN)
        return cli_usage_error("convert",
                               "%s: unknown output format (expected .png, .ppm, .pgm, .pfm, .hdr, "
                               ".exr)",
                               paths[1]);
    if (a.exr_float && format != CG_FILE_EXR)
        return cli_usage_error("convert", "--exr-float: %s is not an .exr file", paths[1]);
    cg_image *image;
    cg_error err;
    if (cg_image_load(paths[0], &image, &err) != CG_OK)
        return cli_fail("%s", err.message);
    int status = CLI_OK;
    if (prepare(&image, &a, cg_file_format_is_float(format)) != CG_OK)
        status = cli_fail("%s: out of memory converting the image", paths[0]);
    else if (format == CG_FILE_EXR) {
        cg_exr_options options = {a.exr_float};
        if (cg_image_write_exr(paths[1], image, NULL, 0, &options, &err) != CG_OK)
            status = cli_fail("%s", err.message);
    } else
        status = cli_write_image(image, paths[1]);
    cg_image_free(image);
    return status;
}

const cg_command cg_command_convert = {
    "convert",
    "convert an image between PNG, PPM, PGM, PFM, Radiance HDR and OpenEXR",
    "usage: cg convert IN OUT [--exposure STOPS] [--tonemap clamp|filmic] [--exr-float]\n\n"
    "Reads IN (PNG, PPM/PGM in P2, P3, P5 or P6, PFM, Radiance .hdr or OpenEXR;\n"
    "recognised by content) and writes OUT in the format of its extension: .png,\n"
    ".ppm (binary P6), .pgm (binary P5, luminance), .pfm (float RGB), .hdr\n"
    "(RGBE) or .exr (RGBA half, or float with --exr-float; ZIP).  An 8-bit image\n"
    "written to a float format is decoded from sRGB to linear light; a float\n"
    "image written to an 8-bit format is multiplied by 2^STOPS, passed through\n"
    "the tone curve and encoded to sRGB as cg encodes every PNG.  Between float\n"
    "formats the values are kept (PFM bit for bit), scaled by 2^STOPS when\n"
    "--exposure is given.  OUT is replaced only when writing succeeds.\n",
    run,
    convert_syntaxes,
};
