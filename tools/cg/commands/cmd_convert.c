/* cg convert IN OUT: between PNG, PPM and PGM. */
#include "cli.h"
#include "command.h"

#include <stdio.h>

static const cli_syntax convert_syntax = {
    .command = "convert",
    .max_positionals = 2,
    .too_many = "expected two files, got '%s' as a third",
    .min_positionals = 2,
    .too_few = "expected IN and OUT files",
};

static int run(int argc, char **argv)
{
    const char *paths[2];
    if (cli_parse(&convert_syntax, argc, argv, NULL, paths, NULL) != CLI_OK)
        return CLI_USAGE;
    if (cg_file_format_from_path(paths[1]) == CG_FILE_UNKNOWN)
        return cli_usage_error("convert", "%s: unknown output format (expected .png, .ppm, .pgm)",
                               paths[1]);
    cg_image *image;
    cg_error err;
    if (cg_image_read(paths[0], &image, &err) != CG_OK)
        return cli_fail("%s", err.message);
    int status = cli_write_image(image, paths[1]);
    cg_image_free(image);
    return status;
}

const cg_command cg_command_convert = {
    "convert",
    "convert an image between PNG, PPM and PGM",
    "usage: cg convert IN OUT\n\n"
    "Reads IN (PNG, or PPM/PGM in P2, P3, P5 or P6; recognised by content) and\n"
    "writes OUT in the format of its extension: .png, .ppm (binary P6) or .pgm\n"
    "(binary P5, luminance).  OUT is replaced only when writing succeeds.\n",
    run,
    NULL,
};
