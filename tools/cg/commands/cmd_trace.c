/* cg trace line X1 Y1 X2 Y2 | circle R: Algorithms 1 and 2 step by step
 * (a trace of the algorithm, not the ray tracer: that is cg trace-render,
 * cmd_trace_render.c and raytrace_run.c). */
#include "cli.h"
#include "command.h"
#include "cg/draw.h"

#include <limits.h>
#include <stdio.h>
#include <string.h>

enum { MAX_STEPS = 100000 };

static int line_step(void *user, const cg_line_step *s)
{
    long *step = user;
    if (strcmp(s->move, "start") == 0)
        printf("%5ld  %6s  %-5s  %7lld  (%d, %d)\n", *step, "-", s->move, s->f_next, s->x, s->y);
    else
        printf("%5ld  %6lld  %-5s  %7lld  (%d, %d)\n", *step, s->f, s->move, s->f_next, s->x, s->y);
    ++*step;
    return 0;
}

static const cli_syntax line_syntax = {
    .command = "trace", .max_positionals = 4, .too_many = "expected 'line X1 Y1 X2 Y2'",
};

static int trace_line(int argc, char **argv)
{
    const char *texts[4];
    int count = 0;
    if (cli_parse(&line_syntax, argc, argv, NULL, texts, &count) != CLI_OK)
        return CLI_USAGE;
    if (count != 4)
        return cli_usage_error("trace", "expected 'line X1 Y1 X2 Y2'");
    long v[4];
    const char *names[4] = {"X1", "Y1", "X2", "Y2"};
    for (int i = 0; i < 4; i++)
        if (cli_parse_long("trace", names[i], texts[i], INT_MIN, INT_MAX, &v[i]))
            return CLI_USAGE;
    long long dx = (long long)v[2] - v[0], dy = (long long)v[3] - v[1];
    long long adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    if ((adx > ady ? adx : ady) > MAX_STEPS)
        return cli_fail("trace: the line has more than %d steps; trace a shorter one", MAX_STEPS);
    int x_major = adx >= ady, swapped = x_major ? dx < 0 : dy < 0;
    long long minor = x_major ? (swapped ? -dy : dy) : (swapped ? -dx : dx);
    printf("Bresenham's line (Algorithm 1) from (%ld, %ld) to (%ld, %ld)\n", v[0], v[1], v[2], v[3]);
    if (swapped)
        printf("walked from (%ld, %ld), the end with the smaller %s\n", v[2], v[3],
               x_major ? "x" : "y");
    if (!x_major)
        printf("steep line: x and y exchanged, so E steps y and NE steps both\n");
    if (minor < 0)
        printf("the minor coordinate decreases: NE steps it by -1\n");
    long long fdx, fdy, de, dne;
    long step = 0;
    printf("first octant: dx = %lld, dy = %lld\n", adx > ady ? adx : ady, adx > ady ? ady : adx);
    /* the header values come from the trace itself */
    cg_line_trace((int)v[0], (int)v[1], (int)v[2], (int)v[3], NULL, NULL, &fdx, &fdy, &de, &dne);
    printf("f = 2dy - dx = %lld, dE = 2dy = %lld, dNE = 2(dy - dx) = %lld\n", 2 * fdy - fdx, de,
           dne);
    printf("f <= 0 selects E (f += dE), else NE (f += dNE); f' is f after the update\n\n");
    printf(" step       f  move        f'  pixel\n");
    cg_line_trace((int)v[0], (int)v[1], (int)v[2], (int)v[3], line_step, &step, NULL, NULL, NULL,
                  NULL);
    printf("%ld pixel%s\n", step, step == 1 ? "" : "s");
    return CLI_OK;
}

typedef struct circle_count { long step, pixels; } circle_count;

static int circle_step(void *user, const cg_circle_step *s)
{
    circle_count *c = user;
    const char *note = "";
    if (s->x > s->y)
        note = "  (x > y: mirrors an earlier pixel, not drawn)";
    else if (s->x == 0 && s->y == 0)
        c->pixels += 1;
    else if (s->x == 0 || s->x == s->y)
        c->pixels += 4;
    else
        c->pixels += 8;
    if (strcmp(s->move, "start") == 0)
        printf("%5ld  %6s  %6s  %6s  %-5s  %6lld  %6lld  %6lld  (%d, %d)%s\n", c->step, "-", "-",
               "-", s->move, s->f_next, s->de_next, s->dse_next, s->x, s->y, note);
    else
        printf("%5ld  %6lld  %6lld  %6lld  %-5s  %6lld  %6lld  %6lld  (%d, %d)%s\n", c->step, s->f,
               s->de, s->dse, s->move, s->f_next, s->de_next, s->dse_next, s->x, s->y, note);
    c->step++;
    return 0;
}

static const cli_syntax circle_syntax = {
    .command = "trace", .max_positionals = 1, .too_many = "expected 'circle R'",
};

static int trace_circle(int argc, char **argv)
{
    const char *radius = NULL;
    long r;
    if (cli_parse(&circle_syntax, argc, argv, NULL, &radius, NULL) != CLI_OK)
        return CLI_USAGE;
    if (!radius)
        return cli_usage_error("trace", "expected 'circle R'");
    if (cli_parse_long("trace", "R", radius, 0, MAX_STEPS, &r))
        return CLI_USAGE;
    printf("Bresenham's circle (Algorithm 2), radius %ld: first octant 0 <= x <= y from (0, %ld)\n",
           r, r);
    printf("f = 1 - r = %ld, dE = 3, dSE = -2r + 5 = %ld\n", 1 - r, 5 - 2 * r);
    printf("f < 0 selects E (x + 1, y): f += dE, dE += 2, dSE += 2\n");
    printf("else SE (x + 1, y - 1): f += dSE, dE += 2, dSE += 4\n");
    printf("f, dE, dSE: values tested; f', dE', dSE': after the update\n\n");
    printf(" step       f      dE     dSE  move        f'     dE'    dSE'  pixel\n");
    circle_count c = {0, 0};
    cg_circle_trace((int)r, circle_step, &c);
    printf("%ld step%s; with 8-way symmetry the circle has %ld pixel%s\n", c.step,
           c.step == 1 ? "" : "s", c.pixels, c.pixels == 1 ? "" : "s");
    return CLI_OK;
}

static int run(int argc, char **argv)
{
    if (argc < 2)
        return cli_usage_error("trace", "expected 'line X1 Y1 X2 Y2' or 'circle R'");
    if (strcmp(argv[1], "line") == 0)
        return trace_line(argc - 1, argv + 1);
    if (strcmp(argv[1], "circle") == 0)
        return trace_circle(argc - 1, argv + 1);
    return cli_usage_error("trace", "unknown figure '%s' (expected line or circle)", argv[1]);
}

const cg_command cg_command_trace = {
    "trace",
    "print Bresenham's line or circle algorithm step by step",
    "usage: cg trace line X1 Y1 X2 Y2\n"
    "       cg trace circle R\n\n"
    "Prints each step of Algorithm 1 (lines) or Algorithm 2 (circles) of the notes:\n"
    "the decision variable f tested, the move chosen (E/NE for lines, E/SE for\n"
    "circles), the values after the update (f, and dE, dSE for circles) and the\n"
    "pixel selected.  A line in another octant is first mapped to the first octant\n"
    "(0 <= dy <= dx) as the drawing code does; its pixels are shown in the real\n"
    "image.  The circle is centred on (0, 0); its first octant is traced.\n",
    run,
    NULL,
};
