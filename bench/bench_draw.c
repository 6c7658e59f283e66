/* Scan conversion speed: cg against OpenCV (cv::line, cv::circle) and Cairo
 * (with and without anti-aliasing) on the same random primitives drawn into
 * the same 1024 x 1024 four-channel image, opaque colour.
 *
 * Each case draws a batch of primitives; the time is the median (process CPU
 * time) of several batches.  The note gives cg's pixel rate (pixels drawn per
 * second, counting one pixel per step of the major axis for lines and the
 * circles' pixels). */
#include "bench.h"
#include "cg/draw.h"

#include <stdint.h>
#include <string.h>

#ifdef HAVE_OPENCV
#include "draw_opencv.h"
#endif
#ifdef HAVE_CAIRO
#include <cairo.h>
#endif

enum { SIZE = 1024, LINES = 20000, CIRCLES = 2000, RUNS = 7 };

/* Every library here draws on the calling thread: process CPU time is the
 * steadier figure on a shared machine. */
static double cpu_median(void (*work)(void *), void *context, int runs)
{
    return bench_median_clock(work, context, runs, CLOCK_PROCESS_CPUTIME_ID);
}

static uint64_t state = 88172645463325252ULL;
static uint64_t next(void)
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
}
static int uniform(int lo, int hi)
{
    return lo + (int)(next() % (uint64_t)(hi - lo + 1));
}

static int lines[LINES * 4], small_lines[LINES * 4], far_lines[LINES * 4], fixed_lines[LINES * 4],
    circles[CIRCLES * 3];
static double aa_lines[LINES * 4];
static const cg_rgba8 color = {250, 180, 40, 255};

typedef struct job {
    cg_image *image;
    const int *ints;
    const double *doubles;
    int n, mode;
#ifdef HAVE_OPENCV
    void *ocv;
#endif
#ifdef HAVE_CAIRO
    cairo_t *cr;
    cairo_surface_t *surface;
#endif
} job;

static void cg_lines(void *p)
{
    job *j = p;
    for (int i = 0; i < j->n; i++)
        cg_draw_line(j->image, j->ints[4 * i], j->ints[4 * i + 1], j->ints[4 * i + 2],
                     j->ints[4 * i + 3], color);
}

static void cg_lines_aa(void *p)
{
    job *j = p;
    for (int i = 0; i < j->n; i++)
        cg_draw_line_aa(j->image, j->doubles[4 * i], j->doubles[4 * i + 1], j->doubles[4 * i + 2],
                        j->doubles[4 * i + 3], color);
}

static void cg_circles(void *p)
{
    job *j = p;
    for (int i = 0; i < j->n; i++) {
        const int *c = j->ints + 3 * i;
        if (j->mode == 0)
            cg_draw_circle(j->image, c[0], c[1], c[2], color);
        else if (j->mode == 1)
            cg_draw_circle_aa(j->image, c[0] + 0.5, c[1] + 0.5, c[2], color);
        else
            cg_draw_disc(j->image, c[0], c[1], c[2], color);
    }
}

#ifdef HAVE_OPENCV
static void ocv_lines_job(void *p)
{
    job *j = p;
    ocv_lines(j->ocv, j->ints, j->n);
}
static void ocv_lines_aa_job(void *p)
{
    job *j = p;
    ocv_lines_aa(j->ocv, j->ints, j->n);
}
static void ocv_circles_job(void *p)
{
    job *j = p;
    ocv_circles(j->ocv, j->ints, j->n, j->mode);
}
#endif

#ifdef HAVE_CAIRO
static void cairo_lines_job(void *p)
{
    job *j = p;
    for (int i = 0; i < j->n; i++) {
        if (j->ints) {
            const int *l = j->ints + 4 * i;
            cairo_move_to(j->cr, l[0] + 0.5, l[1] + 0.5);
            cairo_line_to(j->cr, l[2] + 0.5, l[3] + 0.5);
        } else {
            const double *l = j->doubles + 4 * i;
            cairo_move_to(j->cr, l[0], l[1]);
            cairo_line_to(j->cr, l[2], l[3]);
        }
        cairo_stroke(j->cr);
    }
    cairo_surface_flush(j->surface);
}
static void cairo_circles_job(void *p)
{
    job *j = p;
    for (int i = 0; i < j->n; i++) {
        const int *c = j->ints + 3 * i;
        cairo_arc(j->cr, c[0] + 0.5, c[1] + 0.5, c[2], 0, 2 * 3.14159265358979323846);
        if (j->mode == 2)
            cairo_fill(j->cr);
        else
            cairo_stroke(j->cr);
    }
    cairo_surface_flush(j->surface);
}
#endif

static double line_pixels(const int *l, int n)
{
    double total = 0;
    for (int i = 0; i < n; i++, l += 4) {
        int dx = abs(l[2] - l[0]), dy = abs(l[3] - l[1]);
        total += (dx > dy ? dx : dy) + 1;
    }
    return total;
}

static double circle_pixels(const int *c, int n, int filled)
{
    double total = 0;
    for (int i = 0; i < n; i++, c += 3)
        total += filled ? 3.14159265 * c[2] * c[2] : 4 * 1.41421356 * c[2];
    return total;
}

static void row(const char *name, double cg_time, const char *peer, double peer_time, double pixels)
{
    char note[160];
    snprintf(note, sizeof note, "%d x %d RGBA8; cg %.0f Mpx/s", SIZE, SIZE,
             pixels / cg_time * 1e-6);
    bench_row(name, cg_time, peer, peer_time, note);
}

/* `bench_draw ONLY` runs one job once, for instruction counts under
 * valgrind --tool=callgrind: ONLY is cg-lines, ocv-lines, cairo-lines,
 * cg-aalines, ocv-aalines, cairo-aalines, cg-circles, ocv-circles,
 * cairo-circles. */
static int only(const char *what, job *j);

int main(int argc, char **argv)
{
    for (int i = 0; i < LINES; i++) {
        for (int k = 0; k < 4; k++) {
            lines[4 * i + k] = uniform(0, SIZE - 1);
            far_lines[4 * i + k] = uniform(-3 * SIZE, 4 * SIZE);
            aa_lines[4 * i + k] = uniform(0, 16 * SIZE - 1) / 16.0;
            fixed_lines[4 * i + k] = (int)(aa_lines[4 * i + k] * 16) - 8; /* OpenCV: centre at +0 */
        }
    }
    for (int i = 0; i < LINES * 4; i++)
        small_lines[i] = lines[i] / 4; /* the same lines scaled into 256 x 256 */
    for (int i = 0; i < CIRCLES; i++) {
        circles[3 * i] = uniform(0, SIZE - 1);
        circles[3 * i + 1] = uniform(0, SIZE - 1);
        circles[3 * i + 2] = uniform(1, 300);
    }
    cg_image *image;
    cg_image_create(&image, SIZE, SIZE, CG_PIXEL_RGBA8);
    job j = {0};
    j.image = image;
#ifdef HAVE_OPENCV
    j.ocv = ocv_create(SIZE, SIZE);
#endif
#ifdef HAVE_CAIRO
    j.surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, SIZE, SIZE);
    j.cr = cairo_create(j.surface);
    cairo_set_source_rgb(j.cr, 0.98, 0.7, 0.16);
    cairo_set_line_width(j.cr, 1.0);
#endif
    if (argc == 2)
        return only(argv[1], &j);
    struct {
        const char *name;
        const int *ints;
        const double *doubles;
        int n, aa;
        double pixels;
    } line_cases[] = {
        {"draw: 20k Bresenham lines inside", lines, NULL, LINES, 0, line_pixels(lines, LINES)},
        {"draw: 20k Bresenham lines, clipped", far_lines, NULL, LINES, 0, 0},
        {"draw: 20k anti-aliased lines", fixed_lines, aa_lines, LINES, 1,
         line_pixels(lines, LINES)},
    };
    for (size_t c = 0; c < sizeof line_cases / sizeof line_cases[0]; c++) {
        j.ints = line_cases[c].ints;
        j.doubles = line_cases[c].doubles;
        j.n = line_cases[c].n;
        int aa = line_cases[c].aa;
        double pixels = line_cases[c].pixels;
        double t_cg = cpu_median(aa ? cg_lines_aa : cg_lines, &j, RUNS);
        if (pixels == 0) { /* count the visible pixels of the clipped case */
            cg_rgba8 black = {0, 0, 0, 255};
            cg_image_clear_rgba8(image, black);
            cg_lines(&j);
            for (int y = 0; y < SIZE; y++)
                for (int x = 0; x < SIZE; x++)
                    pixels += cg_image_get_rgba8(image, x, y).r != 0;
        }
        int printed = 0;
#ifdef HAVE_OPENCV
        row(line_cases[c].name, t_cg, aa ? "OpenCV LINE_AA" : "OpenCV LINE_8",
            cpu_median(aa ? ocv_lines_aa_job : ocv_lines_job, &j, RUNS), pixels);
        printed = 1;
#endif
#ifdef HAVE_CAIRO
        cairo_set_antialias(j.cr, aa ? CAIRO_ANTIALIAS_DEFAULT : CAIRO_ANTIALIAS_NONE);
        if (aa)
            j.ints = NULL;
        row(line_cases[c].name, t_cg, aa ? "Cairo AA" : "Cairo no-AA",
            cpu_median(cairo_lines_job, &j, RUNS), pixels);
        printed = 1;
#endif
        if (!printed)
            row(line_cases[c].name, t_cg, "-", 0, pixels);
    }
    /* The same lines scaled into a 256 x 256 image that stays in cache: the
     * drawing code itself rather than memory traffic. */
    {
        cg_image *small;
        cg_image_create(&small, SIZE / 4, SIZE / 4, CG_PIXEL_RGBA8);
        job s = j;
        s.image = small;
        s.ints = small_lines;
        s.n = LINES;
        double t_cg = cpu_median(cg_lines, &s, RUNS), pixels = line_pixels(small_lines, LINES);
        char note[160];
        snprintf(note, sizeof note, "256 x 256 RGBA8 (in cache); cg %.0f Mpx/s",
                 pixels / t_cg * 1e-6);
        int printed = 0;
#ifdef HAVE_OPENCV
        s.ocv = ocv_create(SIZE / 4, SIZE / 4);
        bench_row("draw: 20k Bresenham lines, small image", t_cg, "OpenCV LINE_8",
                  cpu_median(ocv_lines_job, &s, RUNS), note);
        ocv_free(s.ocv);
        printed = 1;
#endif
#ifdef HAVE_CAIRO
        s.surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, SIZE / 4, SIZE / 4);
        s.cr = cairo_create(s.surface);
        cairo_set_source_rgb(s.cr, 0.98, 0.7, 0.16);
        cairo_set_line_width(s.cr, 1.0);
        cairo_set_antialias(s.cr, CAIRO_ANTIALIAS_NONE);
        bench_row("draw: 20k Bresenham lines, small image", t_cg, "Cairo no-AA",
                  cpu_median(cairo_lines_job, &s, RUNS), note);
        cairo_destroy(s.cr);
        cairo_surface_destroy(s.surface);
        printed = 1;
#endif
        if (!printed)
            bench_row("draw: 20k Bresenham lines, small image", t_cg, "-", 0, note);
        cg_image_free(small);
    }
    const char *circle_names[3] = {"draw: 2k Bresenham circles r 1-300",
                                   "draw: 2k anti-aliased circles r 1-300",
                                   "draw: 2k filled discs r 1-300"};
    for (int mode = 0; mode < 3; mode++) {
        j.ints = circles;
        j.n = CIRCLES;
        j.mode = mode;
        double pixels = circle_pixels(circles, CIRCLES, mode == 2);
        double t_cg = cpu_median(cg_circles, &j, RUNS);
        int printed = 0;
#ifdef HAVE_OPENCV
        row(circle_names[mode], t_cg,
            mode == 1   ? "OpenCV LINE_AA"
            : mode == 2 ? "OpenCV FILLED"
                        : "OpenCV LINE_8",
            cpu_median(ocv_circles_job, &j, RUNS), pixels);
        printed = 1;
#endif
#ifdef HAVE_CAIRO
        cairo_set_antialias(j.cr, mode == 1 ? CAIRO_ANTIALIAS_DEFAULT : CAIRO_ANTIALIAS_NONE);
        row(circle_names[mode], t_cg, mode == 1 ? "Cairo AA" : "Cairo no-AA",
            cpu_median(cairo_circles_job, &j, RUNS), pixels);
        printed = 1;
#endif
        if (!printed)
            row(circle_names[mode], t_cg, "-", 0, pixels);
    }
#ifndef HAVE_OPENCV
    bench_row("draw: OpenCV", 0, "-", 0, "OpenCV not installed: skipped");
#else
    ocv_free(j.ocv);
#endif
#ifndef HAVE_CAIRO
    bench_row("draw: Cairo", 0, "-", 0, "Cairo not installed: skipped");
#else
    cairo_destroy(j.cr);
    cairo_surface_destroy(j.surface);
#endif
    cg_image_free(image);
    return 0;
}

static int only(const char *what, job *j)
{
    j->n = LINES;
    j->ints = lines;
    j->doubles = aa_lines;
    if (strcmp(what, "cg-lines") == 0)
        cg_lines(j);
    else if (strcmp(what, "cg-aalines") == 0)
        cg_lines_aa(j);
#ifdef HAVE_OPENCV
    else if (strcmp(what, "ocv-lines") == 0)
        ocv_lines_job(j);
    else if (strcmp(what, "ocv-aalines") == 0) {
        j->ints = fixed_lines;
        ocv_lines_aa_job(j);
    }
#endif
#ifdef HAVE_CAIRO
    else if (strcmp(what, "cairo-lines") == 0) {
        cairo_set_antialias(j->cr, CAIRO_ANTIALIAS_NONE);
        cairo_lines_job(j);
    } else if (strcmp(what, "cairo-aalines") == 0) {
        j->ints = NULL;
        cairo_lines_job(j);
    }
#endif
    else {
        j->ints = circles;
        j->n = CIRCLES;
        j->mode = 0;
        if (strcmp(what, "cg-circles") == 0)
            cg_circles(j);
#ifdef HAVE_OPENCV
        else if (strcmp(what, "ocv-circles") == 0)
            ocv_circles_job(j);
#endif
#ifdef HAVE_CAIRO
        else if (strcmp(what, "cairo-circles") == 0) {
            cairo_set_antialias(j->cr, CAIRO_ANTIALIAS_NONE);
            cairo_circles_job(j);
        }
#endif
        else {
            fprintf(stderr, "bench_draw: unknown job '%s'\n", what);
            return 2;
        }
    }
    return 0;
}
