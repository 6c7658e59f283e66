/* cg color FROM-TO V1 V2 V3 [V4]: converts one colour between models. */
#include "cli.h"
#include "command.h"
#include "cg/color.h"

#include <stdio.h>
#include <string.h>

/* Splits "FROM-TO" at the dash that leaves a model name on both sides
 * ("srgb-linear" is srgb to linear; "ycbcr601-lab" has one dash). */
static int parse_conversion(const char *text, cg_color_model *from, cg_color_model *to)
{
    for (const char *dash = strchr(text, '-'); dash; dash = strchr(dash + 1, '-')) {
        size_t left = (size_t)(dash - text);
        if (cg_color_model_parse(text, left, from, NULL) == CG_OK
            && cg_color_model_parse(dash + 1, strlen(dash + 1), to, NULL) == CG_OK)
            return 0;
    }
    return -1;
}

static void print_value(double v, int last)
{
    if (v == 0)
        v = 0; /* no "-0" */
    printf("%.17g%c", v, last ? '\n' : ' ');
}

/* FROM-TO and up to four values; more are counted, for the message. */
typedef struct color_arguments {
    const char *texts[5];
    int count;
} color_arguments;

static int color_argument(const char *command, int index, const char *text, void *arguments)
{
    (void)command;
    color_arguments *a = arguments;
    if (index < 5)
        a->texts[index] = text;
    a->count = index + 1;
    return 0;
}

static const cli_syntax color_syntax = {.command = "color", .positional = color_argument};

static int run(int argc, char **argv)
{
    color_arguments arguments = {{NULL}, 0};
    if (cli_parse(&color_syntax, argc, argv, &arguments, NULL, NULL) != CLI_OK)
        return CLI_USAGE;
    const char *const *texts = arguments.texts;
    if (arguments.count == 0)
        return cli_usage_error("color", "expected FROM-TO and the values of a colour");
    cg_color_model from, to;
    if (parse_conversion(texts[0], &from, &to) != 0)
        return cli_usage_error("color",
                               "'%s': expected FROM-TO with FROM and TO among rgb, srgb, linear, "
                               "hsv, hsl, cmy, cmyk, yiq, ycbcr601, ycbcr709, xyz, lab",
                               texts[0]);
    int need = cg_color_model_components(from);
    int given = arguments.count - 1;
    double in[4] = {0, 0, 0, 0}, out[4];
    if (from == CG_MODEL_RGB && given == 1) {
        /* rgb from "#rrggbb" or a colour name */
        cg_rgba8 c;
        cg_error err;
        if (cg_color_parse(texts[1], &c, &err) != CG_OK)
            return cli_usage_error("color", "%s", err.message);
        in[0] = c.r / 255.0;
        in[1] = c.g / 255.0;
        in[2] = c.b / 255.0;
    } else {
        if (given != need)
            return cli_usage_error("color", "%s takes %d values, got %d", cg_color_model_name(from),
                                   need, given);
        for (int i = 0; i < need; i++) {
            char what[32];
            snprintf(what, sizeof what, "value %d", i + 1);
            if (cli_parse_double("color", what, texts[1 + i], &in[i]) != 0)
                return CLI_USAGE;
        }
    }
    if (cg_color_convert(from, to, in, out) != CG_OK)
        return cli_fail("color: conversion %s failed", texts[0]);
    int n = cg_color_model_components(to);
    for (int i = 0; i < n; i++)
        print_value(out[i], i == n - 1);
    return CLI_OK;
}

const cg_command cg_command_color = {
    "color",
    "convert a colour between RGB, HSV, HSL, CMY(K), YIQ, YCbCr, XYZ, Lab",
    "usage: cg color FROM-TO V1 V2 V3 [V4]\n"
    "       cg color rgb-TO '#rrggbb' | NAME\n\n"
    "Converts one colour from model FROM to model TO and prints its components\n"
    "separated by spaces, in full precision (%.17g).  Models:\n"
    "  rgb (or srgb)  sRGB-encoded R G B in [0, 1]\n"
    "  linear         linear-light R G B in [0, 1] (srgb-linear decodes,\n"
    "                 linear-srgb encodes with the exact sRGB curves)\n"
    "  hsv, hsl       hue in degrees [0, 360), saturation and value/lightness in [0, 1]\n"
    "  cmy, cmyk      C M Y [K] in [0, 1] (cmyk takes four values)\n"
    "  yiq            NTSC Y I Q\n"
    "  ycbcr601, ycbcr709   Y in [0, 1], Cb and Cr in [-0.5, 0.5]\n"
    "  xyz            CIE XYZ (D65 white 0.9505 1 1.089), from linear RGB\n"
    "  lab            CIE L*a*b* relative to D65, L* in [0, 100]\n"
    "Values outside a model's range are clamped (hue is taken modulo 360);\n"
    "results in RGB are clamped to [0, 1] (out-of-gamut colours).\n\n"
    "Examples:\n"
    "  cg color rgb-hsv 1 0.5 0        -> 30 1 1\n"
    "  cg color srgb-linear 0.5 0.5 0.5\n"
    "  cg color rgb-lab cornflowerblue\n",
    run,
    NULL,
};
