/* Polygon fill (aliased and anti-aliased) and flood fill: cg against Cairo,
 * AGG and OpenCV on the same shapes in the same run.
 *
 * Shapes: random self-crossing polygons, ten-pointed stars and text-like
 * outlines (rings with holes and curved strokes, flattened to polygons so
 * every library fills the same edges), at sizes 32, 256 and 1024 pixels, in
 * a 1024 x 1024 RGBA image, opaque colour, even-odd rule.  Flood fill: a
 * maze and an open image, 2048 x 2048, 4- and 8-connected, against OpenCV's
 * floodFill (on a 3-channel copy: OpenCV does not flood 4-channel images).
 * The note of each row gives pixels per second (painted pixels / time).
 * Times are processor time (medians), as the machine may be shared. */
#include "bench.h"
#include "bench_fill_peers.h"
#include "cg/fill.h"
#include "../tests/maze.h"

#include <math.h>
#include <string.h>

#ifdef CG_BENCH_HAVE_CAIRO
#include <cairo.h>
#endif

#define SIZE 1024

/* Processor time: the machine is shared, and every measured call is
 * single-threaded. */
static double timed(void (*work)(void *), void *context, int runs)
{
    return bench_median_clock(work, context, runs, CLOCK_PROCESS_CPUTIME_ID);
}

typedef struct shape_set {
    double *xy;
    int *sizes;
    bench_shape *shapes;
    int count;
} shape_set;

static uint64_t rng_state = 88172645463325252ULL;
static double unit(void)
{
    return bench_random(&rng_state);
}

/* Builds count shapes by calling make(center, size, xy, sizes) which
 * returns the number of contours and writes points. */
typedef int (*shape_maker)(double cx, double cy, double size, double *xy, int *sizes);

static int make_random(double cx, double cy, double size, double *xy, int *sizes)
{
    sizes[0] = 12;
    for (int i = 0; i < 12; i++) {
        xy[2 * i] = cx + (unit() - 0.5) * size;
        xy[2 * i + 1] = cy + (unit() - 0.5) * size;
    }
    return 1;
}

static int make_star(double cx, double cy, double size, double *xy, int *sizes)
{
    sizes[0] = 20;
    double turn = unit() * 2 * CG_PI;
    for (int i = 0; i < 20; i++) {
        double r = (i % 2 ? 0.2 : 0.5) * size, a = turn + i * CG_PI / 10;
        xy[2 * i] = cx + r * cos(a);
        xy[2 * i + 1] = cy + r * sin(a);
    }
    return 1;
}

/* Points of an ellipse flattened within 0.1 pixel. */
static int ellipse(double cx, double cy, double rx, double ry, int reverse, double *xy)
{
    double r = rx > ry ? rx : ry;
    int n = (int)ceil(CG_PI / acos(1 - 0.1 / (r > 0.2 ? r : 0.2)));
    if (n < 8)
        n = 8;
    if (n > 400)
        n = 400;
    for (int i = 0; i < n; i++) {
        double a = (reverse ? -1 : 1) * 2 * CG_PI * i / n;
        xy[2 * i] = cx + rx * cos(a);
        xy[2 * i + 1] = cy + ry * sin(a);
    }
    return n;
}

/* Text-like: an "o" (ring with a hole) or a thick curved stroke like the
 * bowl of a "c", alternately. */
static int make_text(double cx, double cy, double size, double *xy, int *sizes)
{
    static int which;
    which++;
    if (which % 2) {
        sizes[0] = ellipse(cx, cy, size * 0.4, size * 0.5, 0, xy);
        sizes[1] = ellipse(cx, cy, size * 0.25, size * 0.37, 1, xy + 2 * sizes[0]);
        return 2;
    }
    int n = sizes[0] = ellipse(cx, cy, size * 0.45, size * 0.5, 0, xy) / 2 + 1;
    /* outer half arc forward, inner half arc back */
    int m = ellipse(cx, cy, size * 0.3, size * 0.35, 0, xy + 2 * n) / 2 + 1;
    for (int i = 0; i < m / 2; i++)
        for (int k = 0; k < 2; k++) {
            double t = xy[2 * (n + i) + k];
            xy[2 * (n + i) + k] = xy[2 * (n + m - 1 - i) + k];
            xy[2 * (n + m - 1 - i) + k] = t;
        }
    sizes[0] = n + m;
    return 1;
}

static void build(shape_set *set, shape_maker make, double size, int count)
{
    set->xy = malloc(sizeof(double) * 2 * 900 * (size_t)count);
    set->sizes = malloc(sizeof(int) * 2 * (size_t)count);
    set->shapes = malloc(sizeof(bench_shape) * (size_t)count);
    set->count = count;
    double *xy = set->xy;
    for (int i = 0; i < count; i++) {
        double cx = size / 2 + unit() * (SIZE - size), cy = size / 2 + unit() * (SIZE - size);
        if (size >= SIZE) {
            cx = cy = SIZE / 2.0;
            cx += (unit() - 0.5) * 8;
        }
        int *sizes = set->sizes + 2 * i;
        int contours = make(cx, cy, size, xy, sizes);
        set->shapes[i].xy = xy;
        set->shapes[i].sizes = sizes;
        set->shapes[i].contours = contours;
        int points = 0;
        for (int c = 0; c < contours; c++)
            points += sizes[c];
        xy += 2 * points;
    }
}

static void release(shape_set *set)
{
    free(set->xy);
    free(set->sizes);
    free(set->shapes);
}

typedef struct job {
    const shape_set *set;
    cg_image *image;
    cg_rasterizer *rasterizer;
    int antialias;
    int flood_x, flood_y, connectivity, toggle;
    unsigned char *peer_pixels;
#ifdef CG_BENCH_HAVE_CAIRO
    cairo_t *cairo;
#endif
} job;

static const cg_rgba8 ink = {30, 60, 200, 255};
static const unsigned char ink_rgba[4] = {30, 60, 200, 255};

/* Timed fill passes alternate between two inks, the same for every library,
 * so that no pass paints over the colour it is about to paint (which would
 * time a repaint of already-painted pixels, not a fill). */
static const unsigned char pass_inks[2][4] = {{30, 60, 200, 255}, {200, 90, 40, 255}};

static const unsigned char *next_ink(int *toggle)
{
    return pass_inks[(*toggle)++ % 2];
}

static cg_rgba8 as_rgba8(const unsigned char c[4])
{
    return (cg_rgba8){c[0], c[1], c[2], c[3]};
}

static void run_cg(void *context)
{
    job *j = context;
    cg_rgba8 color = as_rgba8(next_ink(&j->toggle));
    cg_paint paint = cg_paint_solid(color);
    for (int i = 0; i < j->set->count; i++) {
        const bench_shape *s = &j->set->shapes[i];
        if (j->antialias)
            cg_rasterizer_fill_polygon_aa(j->rasterizer, j->image, (const cg_vec2 *)s->xy, s->sizes,
                                          s->contours, CG_FILL_EVEN_ODD, &paint);
        else
            cg_rasterizer_fill_polygon(j->rasterizer, j->image, (const cg_vec2 *)s->xy, s->sizes,
                                       s->contours, CG_FILL_EVEN_ODD, color);
    }
}

#ifdef CG_BENCH_HAVE_CAIRO
static void run_cairo(void *context)
{
    job *j = context;
    cairo_t *cr = j->cairo;
    const unsigned char *c = next_ink(&j->toggle);
    cairo_set_source_rgb(cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
    for (int i = 0; i < j->set->count; i++) {
        const bench_shape *s = &j->set->shapes[i];
        const double *p = s->xy;
        for (int c = 0; c < s->contours; c++) {
            cairo_move_to(cr, p[0], p[1]);
            for (int k = 1; k < s->sizes[c]; k++)
                cairo_line_to(cr, p[2 * k], p[2 * k + 1]);
            cairo_close_path(cr);
            p += 2 * s->sizes[c];
        }
        cairo_fill(cr);
    }
}
#endif

#ifdef CG_BENCH_HAVE_AGG
static void run_agg(void *context)
{
    job *j = context;
    peer_agg_fill(j->peer_pixels, SIZE, SIZE, SIZE * 4, j->set->shapes, j->set->count, 1,
                  j->antialias, next_ink(&j->toggle));
}

#endif

#ifdef CG_BENCH_HAVE_OPENCV
static void run_opencv(void *context)
{
    job *j = context;
    peer_opencv_fill(j->peer_pixels, SIZE, SIZE, SIZE * 4, j->set->shapes, j->set->count,
                     j->antialias, next_ink(&j->toggle));
}
#endif

static size_t painted(const cg_image *im)
{
    size_t n = 0;
    for (int y = 0; y < im->height; y++) {
        const cg_rgba8 *row = (const cg_rgba8 *)(im->data + (size_t)y * im->stride);
        for (int x = 0; x < im->width; x++)
            n += row[x].a != 0;
    }
    return n;
}

static void row(const char *name, double cg_time, const char *peer, double peer_time, double pixels)
{
    char note[160];
    if (peer_time > 0)
        snprintf(note, sizeof note, "cg %.0f Mpx/s, %s %.0f Mpx/s", pixels / cg_time * 1e-6, peer,
                 pixels / peer_time * 1e-6);
    else
        snprintf(note, sizeof note, "cg %.0f Mpx/s; %s not built in", pixels / cg_time * 1e-6,
                 peer);
    bench_row(name, cg_time, peer_time > 0 ? peer : "-", peer_time, note);
}

/* Only cases whose name contains this text (argv[2]; all when NULL), and
 * whether to time the peers (argv[3] "cg" times cg alone, for profiling). */
static const char *only;
static int cg_alone;

static int wanted(const char *name)
{
    return !only || strstr(name, only);
}

static void polygon_cases(int runs)
{
    struct {
        const char *name;
        shape_maker make;
    } kinds[] = {{"random", make_random}, {"star", make_star}, {"text", make_text}};
    const double sizes[] = {32, 256, 1024};
    const int counts[] = {3000, 200, 12};
    cg_image *image;
    cg_image_create(&image, SIZE, SIZE, CG_PIXEL_RGBA8);
    cg_rasterizer *r;
    cg_rasterizer_create(&r);
    unsigned char *peer = calloc((size_t)SIZE * SIZE, 4);
#ifdef CG_BENCH_HAVE_CAIRO
    cairo_surface_t *surface = cairo_image_surface_create_for_data(peer, CAIRO_FORMAT_ARGB32, SIZE,
                                                                   SIZE, SIZE * 4);
    cairo_t *cr = cairo_create(surface);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    cairo_set_source_rgb(cr, 30 / 255.0, 60 / 255.0, 200 / 255.0);
#endif
    for (int aa = 0; aa < 2; aa++)
        for (int k = 0; k < 3; k++)
            for (int s = 0; s < 3; s++) {
                shape_set set;
                build(&set, kinds[k].make, sizes[s], counts[s]);
                job j;
                memset(&j, 0, sizeof j);
                j.set = &set;
                j.image = image;
                j.rasterizer = r;
                j.antialias = aa;
                j.peer_pixels = peer;
                char name[96];
                snprintf(name, sizeof name, "fill %s %s %gpx x%d", aa ? "aa" : "aliased",
                         kinds[k].name, sizes[s], counts[s]);
                if (!wanted(name)) {
                    release(&set);
                    continue;
                }
                /* pixels painted by one pass, counted on a clear image */
                memset(image->data, 0, (size_t)SIZE * SIZE * 4);
                run_cg(&j);
                double pixels = 0;
                {
                    /* each shape's own painted area, summed: redo per shape */
                    for (int i = 0; i < set.count; i++) {
                        shape_set one = {NULL, NULL, &set.shapes[i], 1};
                        job o = j;
                        o.set = &one;
                        memset(image->data, 0, (size_t)SIZE * SIZE * 4);
                        run_cg(&o);
                        pixels += (double)painted(image);
                        if (i == 40 && set.count > 200) { /* estimate from a sample */
                            pixels *= (double)set.count / 41;
                            break;
                        }
                    }
                }
                double t_cg = timed(run_cg, &j, runs);
                if (cg_alone) {
                    row(name, t_cg, "-", 0, pixels);
                    release(&set);
                    continue;
                }
#ifdef CG_BENCH_HAVE_CAIRO
                j.cairo = cr;
                cairo_set_antialias(cr, aa ? CAIRO_ANTIALIAS_DEFAULT : CAIRO_ANTIALIAS_NONE);
                row(name, t_cg, "cairo", timed(run_cairo, &j, runs), pixels);
#else
                row(name, t_cg, "cairo", 0, pixels);
#endif
#ifdef CG_BENCH_HAVE_AGG
                row(name, t_cg, "agg", timed(run_agg, &j, runs), pixels);
#else
                row(name, t_cg, "agg", 0, pixels);
#endif
#ifdef CG_BENCH_HAVE_OPENCV
                row(name, t_cg, "opencv", timed(run_opencv, &j, runs), pixels);
#else
                row(name, t_cg, "opencv", 0, pixels);
#endif
                release(&set);
            }
#ifdef CG_BENCH_HAVE_CAIRO
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
#endif
    cg_rasterizer_free(r);
    free(peer);
    cg_image_free(image);
}

/* ---- curved paths: each library flattens its own curves ------------------- */

/* Two glyph-like outlines in the unit square: an "o" (four cubics out, four
 * back in) and an "S" stroke outline of cubics. */
static const char glyph_o_verbs[] = "MCCCCZMCCCCZ";
static const char glyph_s_verbs[] = "MCCCLCCCZ";
static double glyph_o[2 * 26], glyph_s[2 * 20];

static void glyphs_init(void)
{
    const double k = 0.5522847498;
    double rings[2][2] = {{0.4, 0.5}, {0.25, 0.37}};
    double *p = glyph_o;
    for (int r = 0; r < 2; r++) {
        double rx = rings[r][0], ry = rings[r][1], s = r ? -1 : 1; /* inner ring reversed */
        double pts[13][2] = {{1, 0},      {1, k * s},  {k, s},       {0, s},   {-k, s},
                             {-1, k * s}, {-1, 0},     {-1, -k * s}, {-k, -s}, {0, -s},
                             {k, -s},     {1, -k * s}, {1, 0}};
        for (int i = 0; i < 13; i++) {
            *p++ = 0.5 + rx * pts[i][0];
            *p++ = 0.5 + ry * pts[i][1];
        }
    }
    static const double s[2 * 20] = {0.80, 0.20, 0.60, 0.00, 0.20, 0.05,  0.20, 0.30,  0.20, 0.55,
                                     0.80, 0.45, 0.80, 0.70, 0.80, 0.95,  0.40, 1.00,  0.15, 0.82,
                                     0.28, 0.72, 0.45, 0.86, 0.66, 0.84,  0.66, 0.70,  0.66, 0.55,
                                     0.05, 0.62, 0.05, 0.30, 0.05, -0.05, 0.60, -0.10, 0.90, 0.10};
    memcpy(glyph_s, s, sizeof s);
}

typedef struct curve_set {
    bench_curve_path *paths;
    double *xy;
    int count;
} curve_set;

static void build_glyphs(curve_set *set, double size, int count)
{
    set->paths = malloc(sizeof *set->paths * (size_t)count);
    set->xy = malloc(sizeof(double) * 2 * 26 * (size_t)count);
    set->count = count;
    for (int i = 0; i < count; i++) {
        int o = i % 2 == 0;
        const double *src = o ? glyph_o : glyph_s;
        int n = o ? 26 : 20;
        double x0 = unit() * (SIZE - size), y0 = unit() * (SIZE - size);
        double *dst = set->xy + 2 * 26 * (size_t)i;
        for (int k = 0; k < n; k++) {
            dst[2 * k] = x0 + src[2 * k] * size;
            dst[2 * k + 1] = y0 + src[2 * k + 1] * size;
        }
        set->paths[i].verbs = o ? glyph_o_verbs : glyph_s_verbs;
        set->paths[i].xy = dst;
    }
}

typedef struct curve_job {
    const curve_set *set;
    cg_image *image;
    cg_rasterizer *rasterizer;
    cg_path *path;
    unsigned char *peer_pixels;
    int toggle;
#ifdef CG_BENCH_HAVE_CAIRO
    cairo_t *cairo;
#endif
} curve_job;

static void run_curves_cg(void *context)
{
    curve_job *j = context;
    cg_paint paint = cg_paint_solid(as_rgba8(next_ink(&j->toggle)));
    for (int i = 0; i < j->set->count; i++) {
        const bench_curve_path *c = &j->set->paths[i];
        const double *p = c->xy;
        cg_path_reset(j->path);
        for (const char *v = c->verbs; *v; v++) {
            if (*v == 'M') {
                cg_path_move_to(j->path, p[0], p[1]);
                p += 2;
            } else if (*v == 'L') {
                cg_path_line_to(j->path, p[0], p[1]);
                p += 2;
            } else if (*v == 'C') {
                cg_path_cubic_to(j->path, p[0], p[1], p[2], p[3], p[4], p[5]);
                p += 6;
            } else {
                cg_path_close(j->path);
            }
        }
        cg_rasterizer_fill_path(j->rasterizer, j->image, j->path, CG_FILL_EVEN_ODD, &paint);
    }
}

#ifdef CG_BENCH_HAVE_CAIRO
static void run_curves_cairo(void *context)
{
    curve_job *j = context;
    cairo_t *cr = j->cairo;
    const unsigned char *ink_now = next_ink(&j->toggle);
    cairo_set_source_rgb(cr, ink_now[0] / 255.0, ink_now[1] / 255.0, ink_now[2] / 255.0);
    for (int i = 0; i < j->set->count; i++) {
        const bench_curve_path *c = &j->set->paths[i];
        const double *p = c->xy;
        for (const char *v = c->verbs; *v; v++) {
            if (*v == 'M') {
                cairo_move_to(cr, p[0], p[1]);
                p += 2;
            } else if (*v == 'L') {
                cairo_line_to(cr, p[0], p[1]);
                p += 2;
            } else if (*v == 'C') {
                cairo_curve_to(cr, p[0], p[1], p[2], p[3], p[4], p[5]);
                p += 6;
            } else {
                cairo_close_path(cr);
            }
        }
        cairo_fill(cr);
    }
}
#endif

#ifdef CG_BENCH_HAVE_AGG
static void run_curves_agg(void *context)
{
    curve_job *j = context;
    peer_agg_fill_curves(j->peer_pixels, SIZE, SIZE, SIZE * 4, j->set->paths, j->set->count,
                         next_ink(&j->toggle));
}
#endif

/* Glyph outlines of cubic Beziers, anti-aliased, even-odd; cg flattens
 * within 0.1 pixel, as Cairo does by default. */
static void curve_cases(int runs)
{
    const double sizes[] = {16, 64, 256};
    const int counts[] = {4000, 1000, 100};
    glyphs_init();
    cg_image *image;
    cg_image_create(&image, SIZE, SIZE, CG_PIXEL_RGBA8);
    unsigned char *peer = calloc((size_t)SIZE * SIZE, 4);
    curve_job j;
    memset(&j, 0, sizeof j);
    j.image = image;
    j.peer_pixels = peer;
    cg_rasterizer_create(&j.rasterizer);
    cg_path_create(&j.path);
#ifdef CG_BENCH_HAVE_CAIRO
    cairo_surface_t *surface = cairo_image_surface_create_for_data(peer, CAIRO_FORMAT_ARGB32, SIZE,
                                                                   SIZE, SIZE * 4);
    j.cairo = cairo_create(surface);
    cairo_set_fill_rule(j.cairo, CAIRO_FILL_RULE_EVEN_ODD);
    cairo_set_tolerance(j.cairo, 0.1);
    cairo_set_source_rgb(j.cairo, 30 / 255.0, 60 / 255.0, 200 / 255.0);
#endif
    for (int s = 0; s < 3; s++) {
        char name[96];
        snprintf(name, sizeof name, "fill aa glyph curves %gpx x%d", sizes[s], counts[s]);
        if (!wanted(name))
            continue;
        curve_set set;
        build_glyphs(&set, sizes[s], counts[s]);
        j.set = &set;
        double pixels = 0;
        for (int i = 0; i < set.count && i < 100; i++) {
            curve_set one = {set.paths + i, NULL, 1};
            curve_job o = j;
            o.set = &one;
            memset(image->data, 0, (size_t)SIZE * SIZE * 4);
            run_curves_cg(&o);
            pixels += (double)painted(image);
        }
        pixels *= (double)set.count / (set.count < 100 ? set.count : 100);
        double t_cg = timed(run_curves_cg, &j, runs);
        if (cg_alone) {
            row(name, t_cg, "-", 0, pixels);
        } else {
#ifdef CG_BENCH_HAVE_CAIRO
            row(name, t_cg, "cairo", timed(run_curves_cairo, &j, runs), pixels);
#else
            row(name, t_cg, "cairo", 0, pixels);
#endif
#ifdef CG_BENCH_HAVE_AGG
            row(name, t_cg, "agg", timed(run_curves_agg, &j, runs), pixels);
#else
            row(name, t_cg, "agg", 0, pixels);
#endif
        }
        free(set.paths);
        free(set.xy);
    }
#ifdef CG_BENCH_HAVE_CAIRO
    cairo_destroy(j.cairo);
    cairo_surface_destroy(surface);
#endif
    cg_path_free(j.path);
    cg_rasterizer_free(j.rasterizer);
    free(peer);
    cg_image_free(image);
}

/* ---- flood fill ---------------------------------------------------------- */

#define FLOOD 2048

static void maze(cg_image *im)
{
    /* a perfect maze of 1023 x 1023 cells */
    cg_rgba8 wall = {0, 0, 0, 255}, open = {255, 255, 255, 255};
    maze_draw(im, (FLOOD - 1) / 2, (FLOOD - 1) / 2, 88172645463325252ULL, 0, wall, open);
}

static void open_field(cg_image *im)
{
    cg_rgba8 wall = {0, 0, 0, 255}, open = {255, 255, 255, 255};
    cg_image_clear_rgba8(im, open);
    for (int i = 0; i < 3000; i++) { /* scattered short walls */
        int x = (int)(unit() * FLOOD), y = (int)(unit() * FLOOD), len = 5 + (int)(unit() * 40);
        int horizontal = unit() < 0.5;
        for (int k = 0; k < len; k++)
            cg_image_set_rgba8(im, horizontal ? x + k : x, horizontal ? y : y + k, wall);
    }
}

static void run_flood_cg(void *context)
{
    job *j = context;
    cg_rgba8 c = j->toggle++ % 2 ? (cg_rgba8){255, 255, 255, 255} : ink;
    cg_flood_fill(j->image, j->flood_x, j->flood_y, c, (cg_connectivity)j->connectivity, 0, NULL);
}

#ifdef CG_BENCH_HAVE_OPENCV
static void run_flood_opencv(void *context)
{
    job *j = context;
    unsigned char white[4] = {255, 255, 255, 255};
    peer_opencv_flood(j->peer_pixels, FLOOD, FLOOD, FLOOD * 3, j->flood_x, j->flood_y,
                      j->connectivity, j->toggle++ % 2 ? white : ink_rgba);
}
#endif

static void flood_cases(int runs)
{
    if (only && strncmp(only, "flood", 5) != 0)
        return;
    cg_image *im;
    cg_image_create(&im, FLOOD, FLOOD, CG_PIXEL_RGBA8);
    unsigned char *bgr = malloc((size_t)FLOOD * FLOOD * 3);
    for (int kind = 0; kind < 2; kind++) {
        if (kind == 0)
            maze(im);
        else
            open_field(im);
        for (int conn = 4; conn <= 8; conn += 4) {
            for (int y = 0; y < FLOOD; y++)
                for (int x = 0; x < FLOOD; x++) {
                    cg_rgba8 p = cg_image_get_rgba8(im, x, y);
                    unsigned char *q = bgr + ((size_t)y * FLOOD + x) * 3;
                    q[0] = p.r;
                    q[1] = p.g;
                    q[2] = p.b;
                }
            job j;
            memset(&j, 0, sizeof j);
            j.image = im;
            j.flood_x = j.flood_y = 1;
            j.connectivity = conn;
            j.peer_pixels = bgr;
            size_t filled = 0;
            cg_flood_fill(im, 1, 1, ink, (cg_connectivity)conn, 0, &filled);
            j.toggle = 1; /* the next run paints back to white */
            char name[96];
            snprintf(name, sizeof name, "flood %s %dx%d %d-connected", kind ? "open" : "maze",
                     FLOOD, FLOOD, conn);
            if (!wanted(name))
                continue;
            double t_cg = timed(run_flood_cg, &j, runs);
            j.toggle = 0;
#ifdef CG_BENCH_HAVE_OPENCV
            double t_cv = timed(run_flood_opencv, &j, runs);
#else
            double t_cv = 0;
#endif
            /* leave the region white again for the next connectivity */
            cg_flood_fill(im, 1, 1, (cg_rgba8){255, 255, 255, 255}, (cg_connectivity)conn, 0, NULL);
            row(name, t_cg, "opencv", t_cv, (double)filled);
        }
    }
    free(bgr);
    cg_image_free(im);
}

int main(int argc, char **argv)
{
    int runs = argc > 1 ? atoi(argv[1]) : 7;
    only = argc > 2 ? argv[2] : NULL;
    cg_alone = argc > 3 && strcmp(argv[3], "cg") == 0;
    (void)ink_rgba; /* unused when no peer is built in */
    polygon_cases(runs);
    curve_cases(runs);
    flood_cases(runs);
    return 0;
}
