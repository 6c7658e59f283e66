/* cg check ALGORITHM ARGS < OUTPUT: a student's result checked against the
 * algorithm's definition and against cg's own result, for autograders.  The
 * algorithms live in tools/cg/check/ (one table per group, check.h). */
#include "check.h"
#include "cli.h"
#include "command.h"

#include <stdlib.h>
#include <string.h>

static const check_algorithm *const groups[] = {check_line_algorithms, check_circle_algorithms,
                                                check_fill_algorithms, check_clip_algorithms};

extern const cg_command cg_command_check;

static int run(int argc, char **argv)
{
    if (argc >= 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        fputs(cg_command_check.usage, stdout);
        return CLI_OK;
    }
    check_options options = {0.01};
    /* --tolerance T anywhere: taken out before the algorithm's arguments. */
    int kept = 1;
    for (int i = 1; i < argc; i++) {
        if (cli_option_is(argv[i], "--tolerance")) {
            const char *value = cli_option_value("check", argc, argv, &i);
            if (!value || cli_parse_double("check", "--tolerance", value, &options.tolerance))
                return CLI_USAGE;
            if (!(options.tolerance >= 0))
                return cli_usage_error("check", "--tolerance: expected a number >= 0");
            continue;
        }
        argv[kept++] = argv[i];
    }
    argc = kept;
    if (argc < 2)
        return cli_usage_error("check", "expected an algorithm, as 'line X1 Y1 X2 Y2' or "
                                        "'circle R', and the pixels on standard input");
    for (size_t g = 0; g < sizeof groups / sizeof groups[0]; g++)
        for (const check_algorithm *a = groups[g]; a->name; a++)
            if (strcmp(argv[1], a->name) == 0)
                return a->run(argc - 1, argv + 1, stdin, &options);
    return cli_usage_error("check", "unknown algorithm '%s' (run 'cg help check' for the list)",
                           argv[1]);
}

const cg_command cg_command_check = {
    "check",
    "check a student's pixels or clipped points against the definitions and cg",
    "usage: cg check ALGORITHM ARGS < OUTPUT\n\n"
    "Reads a result of one of the notes' algorithms from standard input and checks\n"
    "it against the algorithm's definition and against cg's own result; the first\n"
    "difference is explained in the notes' terms.  Prints 'right: ...' and exits 0,\n"
    "or 'wrong: ...' naming the first wrong pixel or point and exits 1; 'note: ...'\n"
    "lines may follow.  Bad arguments or input exit 2 with one line on stderr.\n\n"
    "Input: one 'X Y' pair per line ('X,Y' and '(X, Y)' too); blank lines and\n"
    "'#' comments are ignored.  Pixels are whole numbers, in any order, each once.\n\n"
    "Pixels (image coordinates):\n"
    "  line X1 Y1 X2 Y2           a digital line segment: one pixel per step of the\n"
    "                             major axis, each within 1/2 of the line, both\n"
    "                             endpoints; at a tie either pixel is right\n"
    "  circle R [XC YC]           the digital circle (Algorithm 2), 8-symmetric\n"
    "  ellipse RX RY [XC YC]      the midpoint ellipse, 4-symmetric\n"
    "  polygon-fill 'POLYGON' [even-odd|nonzero]  the pixels whose centres\n"
    "                             (x + 0.5, y + 0.5) are inside, by the pixel-centre\n"
    "                             rule; POLYGON as 'X,Y X,Y X,Y ...' (';' between contours)\n"
    "  flood-fill IMAGE X Y [4|8] the region of the seed's colour connected to\n"
    "                             the seed (x, y) in the image file\n"
    "Points (real coordinates, y up, as cg clip):\n"
    "  cohen-sutherland XMIN YMIN XMAX YMAX X0,Y0 X1,Y1  the clipped segment's two\n"
    "                             endpoints, P0's side first, or no point when rejected\n"
    "  sutherland-hodgman 'WINDOW' 'SUBJECT'  the output list's vertices in order\n"
    "                             (any starting vertex), nothing when all is clipped\n"
    "  --tolerance T              how far a point may be from the right one (0.01)\n\n"
    "Example: ./my_line 1 1 22 9 | cg check line 1 1 22 9 && echo passed\n",
    run,
    NULL,
};
