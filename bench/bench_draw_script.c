/* `cg draw` against the library calls it makes and against the peers, on the
 * same shapes: 20,000 Bresenham lines, 2,000 Bresenham circles (radius
 * 1-300) and 20,000 random star polygons (12-24 vertices, radius 10-200),
 * aliased and anti-aliased, each shape its own opaque colour, in a
 * 1024 x 1024 canvas with a white background.
 *
 * The script of each case is written to a temporary file and drawn by the
 * cg tool (CG_TOOL, the build's `cg`) with `--repeat`.  The time of one run
 * is the tool's processor time with --repeat R + 1 less its time with
 * --repeat 1, divided by R: reading the script, starting the program and
 * writing the image cancel out, and what is left is what --repeat times
 * (creating the canvas, converting every argument, drawing).  The library
 * calls and the peers are timed in this process the same way: processor
 * time of creating or clearing the canvas and drawing every shape.  Each
 * figure is the median of RUNS measurements.  The note says whether the
 * tool's image is the library calls' image, byte for byte.
 *
 * bench_draw_script [RUNS [ONLY]]: ONLY keeps the cases whose name contains
 * it ("polygons"). */
#include "bench.h"
#include "bench_tool.h"
#include "bench_draw_script_peers.h"
#include "cg/draw.h"
#include "cg/fill.h"
#include "cg/image.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <string.h>

#ifdef CG_BENCH_HAVE_CAIRO
#include <cairo.h>
#endif

enum { SIZE = 1024, LINES = 20000, CIRCLES = 2000, POLYGONS = 20000 };

typedef enum shape_kind { LINE, CIRCLE, POLYGON, AA_POLYGON } shape_kind;

/* The shapes of one case and the script that draws them. */
typedef struct shape_case {
    const char *name;
    shape_kind kind;
    int count, repeat; /* repeat: the R of `--repeat R + 1` */
    int *ints;         /* lines: x0 y0 x1 y1; circles: cx cy r */
    double *xy;        /* polygons: points, polygon i from xy + 2 * first[i] */
    int *first, *sizes;
    unsigned char *rgba; /* 4 bytes a shape */
    char *script;
    size_t length;
} shape_case;

static uint64_t rng = 88172645463325252ULL;
static uint64_t next_random(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}
static int uniform_int(int lo, int hi)
{
    return lo + (int)(next_random() % (uint64_t)(hi - lo + 1));
}
static double uniform(double lo, double hi)
{
    return lo + (hi - lo) * (double)(next_random() >> 11) * (1.0 / 9007199254740992.0);
}

/* Appends printf-formatted text to the case's script. */
static void append(shape_case *c, size_t *capacity, const char *format, ...)
    __attribute__((format(printf, 3, 4)));
static void append(shape_case *c, size_t *capacity, const char *format, ...)
{
    for (;;) {
        va_list args;
        va_start(args, format);
        int n = vsnprintf(c->script + c->length, *capacity - c->length, format, args);
        va_end(args);
        if (n >= 0 && c->length + (size_t)n < *capacity) {
            c->length += (size_t)n;
            return;
        }
        *capacity *= 2;
        c->script = realloc(c->script, *capacity);
        if (!c->script)
            abort();
    }
}

/* A coordinate written with two decimals, and the number a script reader
 * gets from that text: the library calls and the peers draw the same
 * points as the script. */
static double two_decimals(double v, char *text, size_t size)
{
    snprintf(text, size, "%.2f", v);
    return strtod(text, NULL);
}

static void build(shape_case *c)
{
    size_t capacity = 1 << 20;
    c->script = malloc(capacity);
    c->length = 0;
    c->rgba = malloc(4 * (size_t)c->count);
    append(c, &capacity, "size %d %d\n", SIZE, SIZE);
    if (c->kind == LINE || c->kind == CIRCLE)
        c->ints = malloc(4 * sizeof(int) * (size_t)c->count);
    else {
        c->xy = malloc(2 * 24 * sizeof(double) * (size_t)c->count);
        c->first = malloc(sizeof(int) * (size_t)c->count);
        c->sizes = malloc(sizeof(int) * (size_t)c->count);
    }
    int points = 0;
    for (int i = 0; i < c->count; i++) {
        unsigned char *rgba = c->rgba + 4 * i;
        for (int k = 0; k < 3; k++)
            rgba[k] = (unsigned char)uniform_int(0, 255);
        rgba[3] = 255;
        append(c, &capacity, "color #%02x%02x%02x\n", rgba[0], rgba[1], rgba[2]);
        if (c->kind == LINE) {
            int *l = c->ints + 4 * i;
            for (int k = 0; k < 4; k++)
                l[k] = uniform_int(0, SIZE - 1);
            append(c, &capacity, "line %d %d %d %d\n", l[0], l[1], l[2], l[3]);
        } else if (c->kind == CIRCLE) {
            int *circle = c->ints + 3 * i;
            circle[0] = uniform_int(0, SIZE - 1);
            circle[1] = uniform_int(0, SIZE - 1);
            circle[2] = uniform_int(1, 300);
            append(c, &capacity, "circle %d %d %d\n", circle[0], circle[1], circle[2]);
        } else {
            int n = 2 * uniform_int(6, 12); /* a star of n / 2 points */
            double r = uniform(10, 200), cx = uniform(0, SIZE), cy = uniform(0, SIZE);
            double turn = uniform(0, 2 * CG_PI);
            c->first[i] = points;
            c->sizes[i] = n;
            append(c, &capacity, "%s", c->kind == POLYGON ? "polygon" : "aapolygon");
            for (int k = 0; k < n; k++) {
                double radius = k % 2 ? 0.45 * r : r, angle = turn + 2 * CG_PI * k / n;
                char x[32], y[32];
                c->xy[2 * points] = two_decimals(cx + radius * cos(angle), x, sizeof x);
                c->xy[2 * points + 1] = two_decimals(cy + radius * sin(angle), y, sizeof y);
                points++;
                append(c, &capacity, " %s %s", x, y);
            }
            append(c, &capacity, "\n");
        }
    }
}

static void release(shape_case *c)
{
    free(c->ints);
    free(c->xy);
    free(c->first);
    free(c->sizes);
    free(c->rgba);
    free(c->script);
}

/* ---- the library calls ------------------------------------------------------- */

typedef struct library_job {
    const shape_case *c;
    cg_rasterizer *rasterizer;
    cg_image *image; /* the last run's canvas */
} library_job;

static cg_rgba8 colour_of(const shape_case *c, int i)
{
    const unsigned char *p = c->rgba + 4 * i;
    return (cg_rgba8){p[0], p[1], p[2], p[3]};
}

/* What `cg draw` does for the script: a new canvas cleared to white, then
 * one call a shape. */
static void run_library(void *context)
{
    library_job *j = context;
    const shape_case *c = j->c;
    cg_image_free(j->image);
    cg_image_create(&j->image, SIZE, SIZE, CG_PIXEL_RGBA8);
    cg_image_clear_rgba8(j->image, (cg_rgba8){255, 255, 255, 255});
    for (int i = 0; i < c->count; i++) {
        cg_rgba8 colour = colour_of(c, i);
        if (c->kind == LINE) {
            const int *l = c->ints + 4 * i;
            cg_draw_line(j->image, l[0], l[1], l[2], l[3], colour);
        } else if (c->kind == CIRCLE) {
            const int *circle = c->ints + 3 * i;
            cg_draw_circle(j->image, circle[0], circle[1], circle[2], colour);
        } else if (c->kind == POLYGON) {
            cg_rasterizer_fill_polygon(j->rasterizer, j->image,
                                       (const cg_vec2 *)(c->xy + 2 * c->first[i]), &c->sizes[i], 1,
                                       CG_FILL_NONZERO, colour);
        } else {
            cg_paint paint = cg_paint_solid(colour);
            cg_rasterizer_fill_polygon_aa(j->rasterizer, j->image,
                                          (const cg_vec2 *)(c->xy + 2 * c->first[i]), &c->sizes[i],
                                          1, CG_FILL_NONZERO, &paint);
        }
    }
}

/* ---- the cg tool --------------------------------------------------------------- */

/* The median over `runs` of the time of one run of the script by the tool. */
static double time_tool(const shape_case *c, const char *script, const char *out, int runs)
{
    return bench_tool_median(script, out, c->repeat, runs);
}

/* ---- the peers ------------------------------------------------------------------ */

typedef struct peer_job {
    const shape_case *c;
    unsigned char *pixels;
    int which; /* 0 OpenCV, 1 AGG, 2 Cairo */
} peer_job;

#ifdef CG_BENCH_HAVE_CAIRO
static void cairo_shapes(const shape_case *c, unsigned char *pixels)
{
    cairo_surface_t *surface = cairo_image_surface_create_for_data(pixels, CAIRO_FORMAT_ARGB32,
                                                                   SIZE, SIZE, SIZE * 4);
    cairo_t *cr = cairo_create(surface);
    cairo_set_antialias(cr, c->kind == AA_POLYGON ? CAIRO_ANTIALIAS_DEFAULT : CAIRO_ANTIALIAS_NONE);
    cairo_set_line_width(cr, 1.0);
    for (int i = 0; i < c->count; i++) {
        const unsigned char *p = c->rgba + 4 * i;
        cairo_set_source_rgb(cr, p[0] / 255.0, p[1] / 255.0, p[2] / 255.0);
        if (c->kind == LINE) {
            const int *l = c->ints + 4 * i;
            cairo_move_to(cr, l[0] + 0.5, l[1] + 0.5);
            cairo_line_to(cr, l[2] + 0.5, l[3] + 0.5);
            cairo_stroke(cr);
        } else if (c->kind == CIRCLE) {
            const int *circle = c->ints + 3 * i;
            cairo_arc(cr, circle[0] + 0.5, circle[1] + 0.5, circle[2], 0, 2 * CG_PI);
            cairo_stroke(cr);
        } else {
            const double *q = c->xy + 2 * c->first[i];
            cairo_move_to(cr, q[0], q[1]);
            for (int k = 1; k < c->sizes[i]; k++)
                cairo_line_to(cr, q[2 * k], q[2 * k + 1]);
            cairo_close_path(cr);
            cairo_fill(cr);
        }
    }
    cairo_destroy(cr);
    cairo_surface_flush(surface);
    cairo_surface_destroy(surface);
}
#endif

static void run_peer(void *context)
{
    peer_job *j = context;
    const shape_case *c = j->c;
    memset(j->pixels, 255, (size_t)SIZE * SIZE * 4);
    int aa = c->kind == AA_POLYGON;
    if (j->which == 0) {
        if (c->kind == LINE)
            peer_opencv_lines(j->pixels, SIZE, SIZE, c->ints, c->count, c->rgba);
        else if (c->kind == CIRCLE)
            peer_opencv_circles(j->pixels, SIZE, SIZE, c->ints, c->count, c->rgba);
        else
            peer_opencv_polygons(j->pixels, SIZE, SIZE, c->xy, c->first, c->sizes, c->count, aa,
                                 c->rgba);
    } else if (j->which == 1) {
        peer_agg_polygons(j->pixels, SIZE, SIZE, c->xy, c->first, c->sizes, c->count, aa, c->rgba);
    } else {
#ifdef CG_BENCH_HAVE_CAIRO
        cairo_shapes(c, j->pixels);
#endif
    }
}

/* ---- rows ------------------------------------------------------------------------ */

static const char *only;

static void peer_row(const shape_case *c, double t_tool, const char *peer, int which, int runs)
{
    static unsigned char *pixels;
    if (!pixels)
        pixels = malloc((size_t)SIZE * SIZE * 4);
    peer_job j = {c, pixels, which};
    double t = bench_median_clock(run_peer, &j, runs, CLOCK_PROCESS_CPUTIME_ID);
    char note[200];
    snprintf(note, sizeof note, "cg draw %.0f shapes/s, %s %.0f shapes/s", c->count / t_tool, peer,
             c->count / t);
    bench_row(c->name, t_tool, peer, t, note);
}

static void run_case(shape_case *c, int runs)
{
    build(c);
    char script[] = "/tmp/cg-bench-XXXXXX.draw", out[64];
    int fd = mkstemps(script, 5);
    if (fd < 0 || write(fd, c->script, c->length) != (ssize_t)c->length) {
        fprintf(stderr, "bench_draw_script: cannot write %s\n", script);
        exit(1);
    }
    close(fd);
    snprintf(out, sizeof out, "%.*s.png", (int)(strlen(script) - 5), script);

    library_job library = {c, NULL, NULL};
    cg_rasterizer_create(&library.rasterizer);
    double t_library = bench_median_clock(run_library, &library, runs, CLOCK_PROCESS_CPUTIME_ID);
    double t_tool = time_tool(c, script, out, runs);
    if (t_tool <= 0) {
        fprintf(stderr, "bench_draw_script: %s failed on %s\n", CG_TOOL, script);
        exit(1);
    }
    /* the tool's image (written by its last run) against the library's */
    cg_image *drawn = NULL;
    cg_error err;
    int same = cg_image_read(out, &drawn, &err) == CG_OK && drawn->width == SIZE
               && drawn->height == SIZE && drawn->format == CG_PIXEL_RGBA8;
    for (int y = 0; same && y < SIZE; y++)
        same = memcmp(drawn->data + (size_t)y * drawn->stride,
                      library.image->data + (size_t)y * library.image->stride, SIZE * 4)
               == 0;
    cg_image_free(drawn);
    char note[200];
    snprintf(note, sizeof note, "cg draw %.0f shapes/s, library %.0f shapes/s; %s",
             c->count / t_tool, c->count / t_library,
             same ? "the same pixels" : "THE PIXELS DIFFER");
    bench_row(c->name, t_tool, "cg library calls", t_library, note);

#ifdef CG_BENCH_HAVE_OPENCV
    peer_row(c, t_tool,
             c->kind == LINE      ? "OpenCV line LINE_8"
             : c->kind == CIRCLE  ? "OpenCV circle LINE_8"
             : c->kind == POLYGON ? "OpenCV fillPoly LINE_8"
                                  : "OpenCV fillPoly LINE_AA",
             0, runs);
#else
    bench_row(c->name, t_tool, "-", 0, "OpenCV not built in");
#endif
#ifdef CG_BENCH_HAVE_AGG
    if (c->kind == POLYGON || c->kind == AA_POLYGON)
        peer_row(c, t_tool, c->kind == POLYGON ? "AGG bin" : "AGG AA", 1, runs);
#endif
#ifdef CG_BENCH_HAVE_CAIRO
    peer_row(c, t_tool, c->kind == AA_POLYGON ? "Cairo AA" : "Cairo no-AA", 2, runs);
#else
    bench_row(c->name, t_tool, "-", 0, "Cairo not built in");
#endif
    cg_image_free(library.image);
    cg_rasterizer_free(library.rasterizer);
    unlink(script);
    unlink(out);
    release(c);
}

int main(int argc, char **argv)
{
    int runs = argc > 1 ? atoi(argv[1]) : 5;
    only = argc > 2 ? argv[2] : NULL;
    shape_case cases[] = {
        {.name = "cg draw --repeat: 20k Bresenham lines, one colour each",
         .kind = LINE,
         .count = LINES,
         .repeat = 20},
        {.name = "cg draw --repeat: 2k Bresenham circles r 1-300, one colour each",
         .kind = CIRCLE,
         .count = CIRCLES,
         .repeat = 60},
        {.name = "cg draw --repeat: 20k star polygons, one colour each",
         .kind = POLYGON,
         .count = POLYGONS,
         .repeat = 4},
        {.name = "cg draw --repeat: 20k anti-aliased star polygons, one colour each",
         .kind = AA_POLYGON,
         .count = POLYGONS,
         .repeat = 2},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        if (!only || strstr(cases[i].name, only))
            run_case(&cases[i], runs);
    return 0;
}
