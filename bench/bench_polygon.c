/* Polygon geometry beyond booleans (cg/polygon.h) against Clipper2 2.0 and
 * GEOS on the same integer inputs: offsets of 5-lobed star polygons (a
 * random jitter of half a chord) by 1% of their radius with round and
 * miter joins (against Clipper2's InflatePaths and GEOS's buffer),
 * rectangle clips of a small tile and of most of the star, as a polygon
 * (against cg's own boolean intersection, Clipper2's RectClip and GEOS's
 * GEOSClipByRect) and as a polyline (RectClipLines, GEOSClipByRect),
 * Minkowski sums of a 32-gon along the star as an open path (Clipper2's
 * MinkowskiSum), RDP simplifications (GEOS's TopologyPreserveSimplify,
 * Clipper2's SimplifyPaths and RamerDouglasPeucker), triangulations of a
 * star with a star hole (Clipper2's Triangulate, GEOS's constrained
 * Delaunay triangulation), and the cg command's own time beside the
 * library's.  Areas (lengths, point or triangle counts) are printed side
 * by side in the notes.  `bench_polygon [offset|rect|lines|minkowski|
 * simplify|triangulate|command]` runs one group. */
#include "bench.h"
#include "bench_rings.h"
#include "bench_polygon_peers.h"
#include "cg/polygon.h"

#include <math.h>
#include <string.h>

#define RADIUS 1e6

static uint64_t rng_state = 0x9e3779b97f4a7c15ull;
static double rnd(void)
{
    return bench_random(&rng_state);
}

typedef struct shape {
    cg_polygon_set64 set;
    int64_t *xy;
    size_t *len;
    polygon_peer_input peer;
} shape;

/* A 5-lobed star ring of n vertices (clockwise when reversed). */
static void star(shape *s, size_t n, double radius, int reversed)
{
    cg_point64 *p = malloc(n * sizeof *p);
    for (size_t i = 0; i < n; i++) {
        double a = 2 * M_PI * ((double)i + 0.5 * rnd()) / (double)n;
        double r = radius * (1 + 0.3 * sin(5 * a));
        p[reversed ? n - 1 - i : i] = (cg_point64){llround(r * cos(a)), llround(r * sin(a))};
    }
    cg_polygon_set64_add_ring(&s->set, p, n, 1);
    free(p);
}

static void finish(shape *s)
{
    bench_rings_flatten(&s->set, &s->xy, &s->len);
    s->peer = (polygon_peer_input){s->xy, s->len, s->set.ring_count};
}

static void shape_free(shape *s)
{
    cg_polygon_set64_clear(&s->set);
    free(s->xy);
    free(s->len);
}

typedef struct job {
    shape *input;
    cg_polygon_set64 result;
    cg_clip_workspace *ws;
    double delta, area, tolerance;
    int join;
    cg_rect64 rect;
    void *peer;
} job;

static void cg_offset_job(void *v)
{
    job *j = v;
    cg_offset_options o = cg_offset_options_default();
    o.join = j->join ? CG_OFFSET_JOIN_ROUND : CG_OFFSET_JOIN_MITER;
    o.arc_tolerance = j->tolerance;
    cg_offset64_ws(j->ws, &j->input->set, j->delta, &o, &j->result);
    j->area = cg_polygon_set64_area(&j->result);
}
static void clipper2_offset_job(void *v)
{
    job *j = v;
    j->area = peer_clipper2_offset(j->peer, j->delta, j->join, j->tolerance);
}
static void geos_offset_job(void *v)
{
    job *j = v;
    /* the chord error d (1 - cos(pi / 4q)) matched to the arc tolerance */
    int q = (int)ceil(M_PI / 4 / acos(1 - j->tolerance / j->delta));
    j->area = peer_geos_buffer(j->peer, j->delta, j->join, q);
}
static void cg_rect_job(void *v)
{
    job *j = v;
    cg_rect_clip64_ws(j->ws, &j->input->set, CG_CLIP_NON_ZERO, j->rect, &j->result);
    j->area = cg_polygon_set64_area(&j->result);
}
static void cg_boolean_rect_job(void *v)
{
    job *j = v;
    cg_polygon_set64 window = {0};
    cg_point64 w[4] = {{j->rect.xmin, j->rect.ymin},
                       {j->rect.xmax, j->rect.ymin},
                       {j->rect.xmax, j->rect.ymax},
                       {j->rect.xmin, j->rect.ymax}};
    cg_polygon_set64_add_ring(&window, w, 4, 1);
    cg_clip_boolean64_ws(j->ws, CG_CLIP_INTERSECTION, &j->input->set, CG_CLIP_NON_ZERO, &window,
                         CG_CLIP_NON_ZERO, &j->result);
    j->area = cg_polygon_set64_area(&j->result);
    cg_polygon_set64_clear(&window);
}
static void clipper2_rect_job(void *v)
{
    job *j = v;
    j->area = peer_clipper2_rect(j->peer, j->rect.xmin, j->rect.ymin, j->rect.xmax, j->rect.ymax);
}
static void cg_triangulate_job(void *v)
{
    job *j = v;
    cg_triangulate64_ws(j->ws, &j->input->set, CG_CLIP_NON_ZERO, &j->result);
    j->area = (double)j->result.ring_count;
}
static void clipper2_triangulate_job(void *v)
{
    job *j = v;
    j->area = peer_clipper2_triangulate(j->peer);
}

static void cg_rect_lines_job(void *v)
{
    job *j = v;
    cg_rect_clip_lines64(&j->input->set, j->rect, &j->result);
    double total = 0;
    for (size_t r = 0; r < j->result.ring_count; r++)
        for (size_t i = j->result.ring_start[r] + 1; i < j->result.ring_start[r + 1]; i++)
            total += hypot((double)(j->result.points[i].x - j->result.points[i - 1].x),
                           (double)(j->result.points[i].y - j->result.points[i - 1].y));
    j->area = total;
}
static void clipper2_rect_lines_job(void *v)
{
    job *j = v;
    j->area = peer_clipper2_rect_lines(j->peer, j->rect.xmin, j->rect.ymin, j->rect.xmax,
                                       j->rect.ymax);
}
static void geos_rect_job(void *v)
{
    job *j = v;
    j->area = peer_geos_clip_rect(j->peer, (double)j->rect.xmin, (double)j->rect.ymin,
                                  (double)j->rect.xmax, (double)j->rect.ymax);
}
static void cg_simplify_job(void *v)
{
    job *j = v;
    cg_simplify64(&j->input->set, 0, CG_CLIP_NON_ZERO, CG_SIMPLIFY_RDP, j->tolerance, &j->result);
    j->area = (double)j->result.point_count;
}
static void clipper2_simplify_job(void *v)
{
    job *j = v;
    j->area = peer_clipper2_simplify(j->peer, j->tolerance, j->join);
}
static void geos_simplify_job(void *v)
{
    job *j = v;
    j->area = peer_geos_simplify(j->peer, j->tolerance);
}
static void geos_triangulate_job(void *v)
{
    job *j = v;
    j->area = peer_geos_triangulate(j->peer);
}

/* The pattern of the Minkowski rows, its input beside it. */
static shape *minkowski_pattern;
static void *minkowski_pattern_peer;
static void cg_minkowski_job(void *v)
{
    job *j = v;
    cg_minkowski64_ws(j->ws, CG_MINKOWSKI_SUM, &minkowski_pattern->set, &j->input->set, 1,
                      CG_CLIP_NON_ZERO, &j->result);
    j->area = cg_polygon_set64_area(&j->result);
}
static void clipper2_minkowski_job(void *v)
{
    job *j = v;
    j->area = peer_clipper2_minkowski(minkowski_pattern_peer, j->peer, 0);
}

static int runs_for(size_t n)
{
    return n >= 100000 ? 3 : n >= 10000 ? 5 : 15;
}

/* Times run on the Clipper2 copy of j's input and prints its row beside
 * cg's time t_cg; the note compares cg's value v_cg with the peer's (areas,
 * or triangle counts when counts).  Without Clipper2 a row says so when
 * say_missing. */
static void clipper2_row(const char *name, double t_cg, double v_cg, int counts,
                         void (*run)(void *), job *j, int runs, int say_missing)
{
    char note[160];
    if (!peer_clipper2_available()) {
        if (say_missing)
            bench_row(name, t_cg, "-", 0, "Clipper2 not found (../shared/peers/clipper2)");
        return;
    }
    j->peer = peer_clipper2_prepare(&j->input->peer);
    double t = bench_median(run, j, runs);
    if (counts)
        snprintf(note, sizeof note, "triangles cg %.0f, Clipper2 %.0f", v_cg, j->area);
    else
        snprintf(note, sizeof note, "areas cg %.6g, Clipper2 %.6g", v_cg, j->area);
    bench_row(name, t_cg, "Clipper2", t, note);
    peer_clipper2_free(j->peer);
}

/* The same for GEOS (lines: its input as polylines); what names v_cg. */
static void geos_row(const char *name, double t_cg, double v_cg, const char *what,
                     void (*run)(void *), job *j, int runs, int lines)
{
    char note[160];
    if (!peer_geos_available())
        return;
    j->peer = lines ? peer_geos_prepare_lines(&j->input->peer) : peer_geos_prepare(&j->input->peer);
    double t = bench_median(run, j, runs);
    snprintf(note, sizeof note, "%s cg %.6g, GEOS %.6g", what, v_cg, j->area);
    bench_row(name, t_cg, "GEOS", t, note);
    peer_geos_free(j->peer);
}

static void offsets(void)
{
    static const size_t sizes[] = {1000, 10000, 100000};
    for (int k = 0; k < 3; k++) {
        shape s = {0};
        star(&s, sizes[k], RADIUS, 0);
        finish(&s);
        for (int join = 1; join >= 0; join--) {
            job j = {&s,
                     {0},
                     cg_clip_workspace_create(),
                     RADIUS / 100,
                     0,
                     RADIUS / 100 / 500,
                     join,
                     {0, 0, 0, 0},
                     NULL};
            int runs = runs_for(sizes[k]);
            double t_cg = bench_median(cg_offset_job, &j, runs), a_cg = j.area;
            char name[64], note[160];
            snprintf(name, sizeof name, "offset %s star %zu", join ? "round" : "miter", sizes[k]);
            clipper2_row(name, t_cg, a_cg, 0, clipper2_offset_job, &j, runs, 1);
            if (peer_geos_available()) {
                j.peer = peer_geos_prepare(&s.peer);
                double t = bench_median(geos_offset_job, &j, runs < 5 ? runs : 5);
                snprintf(note, sizeof note, "areas cg %.6g, GEOS %.6g", a_cg, j.area);
                bench_row(name, t_cg, "GEOS", t, note);
                peer_geos_free(j.peer);
            }
            cg_polygon_set64_clear(&j.result);
            cg_clip_workspace_free(j.ws);
        }
        shape_free(&s);
    }
}

static void rectangles(void)
{
    static const size_t sizes[] = {10000, 100000, 1000000};
    for (int k = 0; k < 3; k++) {
        shape s = {0};
        star(&s, sizes[k], RADIUS, 0);
        finish(&s);
        for (int large = 0; large < 2; large++) {
            /* a tile across the boundary, or most of the star */
            int64_t h = large ? (int64_t)(0.8 * RADIUS) : (int64_t)(0.05 * RADIUS);
            int64_t cx = large ? 0 : (int64_t)RADIUS; /* the star crosses x = RADIUS on the axis */
            job j = {&s, {0}, cg_clip_workspace_create(), 0,   0,
                     0,  0,   {cx - h, -h, cx + h, h},    NULL};
            int runs = runs_for(sizes[k]);
            double t_cg = bench_median(cg_rect_job, &j, runs), a_cg = j.area;
            char name[64], note[160];
            snprintf(name, sizeof name, "rect %s star %zu", large ? "large" : "tile", sizes[k]);
            double t_bool = bench_median(cg_boolean_rect_job, &j, runs);
            snprintf(note, sizeof note, "areas rect %.6g, boolean %.6g", a_cg, j.area);
            bench_row(name, t_cg, "cg boolean", t_bool, note);
            clipper2_row(name, t_cg, a_cg, 0, clipper2_rect_job, &j, runs, 0);
            geos_row(name, t_cg, a_cg, "areas", geos_rect_job, &j, runs, 0);
            cg_polygon_set64_clear(&j.result);
            cg_clip_workspace_free(j.ws);
        }
        shape_free(&s);
    }
}

static void triangulations(void)
{
    static const size_t sizes[] = {1000, 10000, 100000};
    for (int k = 0; k < 3; k++) {
        shape s = {0};
        star(&s, sizes[k], RADIUS, 0);
        star(&s, sizes[k] / 10, RADIUS / 3, 1);
        finish(&s);
        job j = {&s, {0}, cg_clip_workspace_create(), 0, 0, 0, 0, {0, 0, 0, 0}, NULL};
        int runs = runs_for(sizes[k]);
        double t_cg = bench_median(cg_triangulate_job, &j, runs), n_cg = j.area;
        char name[64];
        snprintf(name, sizeof name, "triangulate star+hole %zu", sizes[k] + sizes[k] / 10);
        clipper2_row(name, t_cg, n_cg, 1, clipper2_triangulate_job, &j, runs, 1);
        geos_row(name, t_cg, n_cg, "triangles", geos_triangulate_job, &j, runs < 3 ? runs : 3, 0);
        cg_polygon_set64_clear(&j.result);
        cg_clip_workspace_free(j.ws);
        shape_free(&s);
    }
}

/* The star's ring as an open polyline cut to a tile and to most of it. */
static void rectangle_lines(void)
{
    static const size_t sizes[] = {1000, 100000, 1000000};
    for (int k = 0; k < 3; k++) {
        shape s = {0};
        star(&s, sizes[k], RADIUS, 0);
        finish(&s);
        for (int large = 0; large < 2; large++) {
            int64_t h = large ? (int64_t)(0.8 * RADIUS) : (int64_t)(0.05 * RADIUS);
            int64_t cx = large ? 0 : (int64_t)RADIUS;
            job j = {&s, {0}, cg_clip_workspace_create(), 0,   0,
                     0,  0,   {cx - h, -h, cx + h, h},    NULL};
            int runs = runs_for(sizes[k]);
            double t_cg = bench_median(cg_rect_lines_job, &j, runs), l_cg = j.area;
            char name[64], note[160];
            snprintf(name, sizeof name, "rect lines %s star %zu", large ? "large" : "tile",
                     sizes[k]);
            if (peer_clipper2_available()) {
                j.peer = peer_clipper2_prepare(&s.peer);
                double t = bench_median(clipper2_rect_lines_job, &j, runs);
                snprintf(note, sizeof note, "lengths cg %.6g, Clipper2 %.6g", l_cg, j.area);
                bench_row(name, t_cg, "Clipper2", t, note);
                peer_clipper2_free(j.peer);
            }
            geos_row(name, t_cg, l_cg, "lengths", geos_rect_job, &j, runs, 1);
            cg_polygon_set64_clear(&j.result);
            cg_clip_workspace_free(j.ws);
        }
        shape_free(&s);
    }
}

/* A 32-gon of 1% of the radius swept along the star's ring as an open
 * path. */
static void minkowski(void)
{
    static const size_t sizes[] = {1000, 10000, 100000};
    shape pattern = {0};
    cg_point64 p[32];
    for (int i = 0; i < 32; i++)
        p[i] = (cg_point64){llround(RADIUS / 100 * cos(2 * M_PI * i / 32)),
                            llround(RADIUS / 100 * sin(2 * M_PI * i / 32))};
    cg_polygon_set64_add_ring(&pattern.set, p, 32, 1);
    finish(&pattern);
    minkowski_pattern = &pattern;
    minkowski_pattern_peer = peer_clipper2_available() ? peer_clipper2_prepare(&pattern.peer)
                                                       : NULL;
    for (int k = 0; k < 3; k++) {
        shape s = {0};
        star(&s, sizes[k], RADIUS, 0);
        finish(&s);
        job j = {&s, {0}, cg_clip_workspace_create(), 0, 0, 0, 0, {0, 0, 0, 0}, NULL};
        int runs = runs_for(sizes[k]);
        double t_cg = bench_median(cg_minkowski_job, &j, runs), a_cg = j.area;
        char name[64];
        snprintf(name, sizeof name, "minkowski 32-gon along star path %zu", sizes[k]);
        if (sizes[k] <= 10000)
            clipper2_row(name, t_cg, a_cg, 0, clipper2_minkowski_job, &j, runs < 3 ? runs : 3, 1);
        else /* Clipper2 takes seconds at 10,000 already, growing faster than n */
            bench_row(name, t_cg, "-", 0, "Clipper2 not run at this size (7.8 s at 10,000)");
        cg_polygon_set64_clear(&j.result);
        cg_clip_workspace_free(j.ws);
        shape_free(&s);
    }
    if (minkowski_pattern_peer)
        peer_clipper2_free(minkowski_pattern_peer);
    shape_free(&pattern);
}

/* RDP at 0.1% of the radius (cg keeps topology, as GEOS's does; Clipper2's
 * SimplifyPaths and RamerDouglasPeucker do not). */
static void simplifications(void)
{
    static const size_t sizes[] = {1000, 100000};
    for (int k = 0; k < 2; k++) {
        shape s = {0};
        star(&s, sizes[k], RADIUS, 0);
        finish(&s);
        job j = {&s, {0}, NULL, 0, 0, RADIUS / 1000, 0, {0, 0, 0, 0}, NULL};
        int runs = runs_for(sizes[k]);
        double t_cg = bench_median(cg_simplify_job, &j, runs), n_cg = j.area;
        char name[64], note[160];
        snprintf(name, sizeof name, "simplify rdp star %zu", sizes[k]);
        geos_row(name, t_cg, n_cg, "points", geos_simplify_job, &j, runs, 0);
        if (peer_clipper2_available()) {
            j.peer = peer_clipper2_prepare(&s.peer);
            for (j.join = 0; j.join < 2; j.join++) {
                double t = bench_median(clipper2_simplify_job, &j, runs);
                snprintf(note, sizeof note, "points cg %.0f, Clipper2 %s %.0f", n_cg,
                         j.join ? "RamerDouglasPeucker" : "SimplifyPaths", j.area);
                bench_row(name, t_cg, j.join ? "Clipper2 RDP" : "Clipper2", t, note);
            }
            peer_clipper2_free(j.peer);
        }
        cg_polygon_set64_clear(&j.result);
        shape_free(&s);
    }
}

/* The cg command on a WKT file of the 10,000-vertex star: its own median
 * time (what it prints for --repeat) beside the library call on the same
 * input and arguments (the command converts to and from its grid). */
static void command_rows(void)
{
    shape s = {0};
    star(&s, 10000, RADIUS, 0);
    char path[] = "/tmp/cg_bench_polygon_XXXXXX";
    int fd = mkstemp(path);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) {
        bench_row("cg clip offset (command)", 0, "-", 0, "no temporary file");
        return;
    }
    fputs("POLYGON ((", f);
    for (size_t i = 0; i < s.set.point_count; i++)
        fprintf(f, "%s%lld %lld", i ? ", " : "", (long long)s.set.points[i].x,
                (long long)s.set.points[i].y);
    fputs("))\n", f);
    fclose(f);
    enum { COMMANDS = 4 };
    static const char *commands[COMMANDS] = {
        "offset 10000 %s --join round --repeat 5", "triangulate %s --repeat 5",
        "rect 950000 -50000 1050000 50000 %s --repeat 5", "simplify 1000 %s --repeat 5"};
    static const char *names[COMMANDS] = {
        "cg clip offset round star 10000 (command)", "cg clip triangulate star 10000 (command)",
        "cg clip rect tile star 10000 (command)", "cg clip simplify rdp star 10000 (command)"};
    for (int c = 0; c < COMMANDS; c++) {
        char args[256], line[4096];
        snprintf(args, sizeof args, commands[c], path);
        snprintf(line, sizeof line, "'%s' clip %s 2>&1 >/dev/null", CG_TOOL, args);
        FILE *p = popen(line, "r");
        double ms = -1;
        char text[256];
        while (p && fgets(text, sizeof text, p)) {
            char *colon = strchr(text, ':');
            if (colon && strstr(text, " ms"))
                ms = atof(colon + 1);
        }
        if (p)
            pclose(p);
        /* the library on the same input and arguments */
        static void (*const library[COMMANDS])(void *) = {cg_offset_job, cg_triangulate_job,
                                                          cg_rect_job, cg_simplify_job};
        job j = {&s,
                 {0},
                 cg_clip_workspace_create(),
                 RADIUS / 100,
                 0,
                 c == 3 ? RADIUS / 1000 : 0, /* 0: the default arc tolerance */
                 1,
                 {950000, -50000, 1050000, 50000},
                 NULL};
        double t_lib = bench_median(library[c], &j, 5);
        cg_polygon_set64_clear(&j.result);
        cg_clip_workspace_free(j.ws);
        char note[160];
        snprintf(note, sizeof note,
                 "the median the command prints for --repeat 5; the library call %.3f ms",
                 t_lib * 1e3);
        bench_row(names[c], ms / 1e3, "-", 0, note);
    }
    remove(path);
    shape_free(&s);
}

int main(int argc, char **argv)
{
    const char *only = argc > 1 ? argv[1] : NULL;
    if (!only || strcmp(only, "offset") == 0)
        offsets();
    if (!only || strcmp(only, "rect") == 0)
        rectangles();
    if (!only || strcmp(only, "lines") == 0)
        rectangle_lines();
    if (!only || strcmp(only, "minkowski") == 0)
        minkowski();
    if (!only || strcmp(only, "simplify") == 0)
        simplifications();
    if (!only || strcmp(only, "triangulate") == 0)
        triangulations();
    if (!only || strcmp(only, "command") == 0)
        command_rows();
    return 0;
}
