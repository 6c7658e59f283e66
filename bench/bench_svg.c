/* bench_svg: SVG icons drawn in one process, cg against librsvg (called
 * as a library through its C API and Cairo) and resvg (through node and
 * @resvg/resvg-js, one process timing its own loop: bench/bench_svg_resvg.js).
 *
 * The sample is tests/test_svg_peers.sh's: every k-th of the sorted
 * distinct SVG files of Papirus's 64x64 folder (200 icons), each read into
 * memory first, then parsed and drawn 256 px wide onto a transparent
 * image; the processor time of the whole sample is the median of 3 runs
 * (node reports its own, process.cpuUsage).  Each row
 * gives icons per second in its note.
 * usage: bench_svg [COUNT [SIZE]] */
#include "bench.h"
#include "cg/svg.h"

#include <dirent.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#ifdef CG_BENCH_HAVE_RSVG
#include <cairo.h>
#include <librsvg/rsvg.h>
#endif

#define PAPIRUS "/usr/share/icons/Papirus/64x64"

typedef struct icon {
    char path[PATH_MAX];
    char *bytes;
    size_t size;
} icon;

typedef struct sample {
    icon *icons;
    int count;
    int side;
} sample;

static int compare_strings(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Every distinct .svg under root (symbolic links resolved), sorted. */
static void gather(const char *root, char ***names, int *count, int *capacity)
{
    DIR *dir = opendir(root);
    if (!dir)
        return;
    struct dirent *e;
    while ((e = readdir(dir)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        char path[PATH_MAX];
        snprintf(path, sizeof path, "%s/%s", root, e->d_name);
        struct stat st;
        if (stat(path, &st) != 0)
            continue;
        if (S_ISDIR(st.st_mode)) {
            gather(path, names, count, capacity);
            continue;
        }
        size_t n = strlen(e->d_name);
        char real[PATH_MAX];
        if (n < 4 || strcmp(e->d_name + n - 4, ".svg") != 0 || !realpath(path, real))
            continue;
        if (*count == *capacity) {
            *capacity = *capacity ? *capacity * 2 : 1024;
            *names = realloc(*names, (size_t)*capacity * sizeof **names);
        }
        (*names)[(*count)++] = strdup(real);
    }
    closedir(dir);
}

static int load_sample(sample *s, int wanted)
{
    char **names = NULL;
    int count = 0, capacity = 0;
    gather(PAPIRUS, &names, &count, &capacity);
    if (count == 0)
        return 0;
    qsort(names, (size_t)count, sizeof *names, compare_strings);
    int distinct = 0;
    for (int i = 0; i < count; i++)
        if (distinct == 0 || strcmp(names[i], names[distinct - 1]) != 0)
            names[distinct++] = names[i];
        else
            free(names[i]);
    int step = distinct / wanted > 0 ? distinct / wanted : 1;
    s->icons = calloc((size_t)wanted, sizeof *s->icons);
    s->count = 0;
    for (int i = 0; i < distinct && s->count < wanted; i += step) {
        FILE *f = fopen(names[i], "rb");
        if (!f)
            continue;
        icon *ic = &s->icons[s->count];
        fseek(f, 0, SEEK_END);
        ic->size = (size_t)ftell(f);
        fseek(f, 0, SEEK_SET);
        ic->bytes = malloc(ic->size + 1);
        if (fread(ic->bytes, 1, ic->size, f) == ic->size) {
            snprintf(ic->path, sizeof ic->path, "%s", names[i]);
            s->count++;
        } else {
            free(ic->bytes);
        }
        fclose(f);
    }
    for (int i = 0; i < distinct; i++)
        free(names[i]);
    free(names);
    return s->count;
}

static void run_cg(void *context)
{
    sample *s = context;
    cg_image *image;
    if (cg_image_create(&image, s->side, s->side, CG_PIXEL_RGBA8) != CG_OK)
        return;
    for (int i = 0; i < s->count; i++) {
        memset(image->data, 0, (size_t)image->stride * (size_t)image->height);
        cg_svg *svg;
        if (cg_svg_load_memory(s->icons[i].bytes, s->icons[i].size, "icon", &svg, NULL) != CG_OK)
            continue;
        double w, h;
        cg_svg_size(svg, &w, &h);
        cg_mat3 m = cg_mat3_identity();
        m.m[0][0] = m.m[1][1] = s->side / w;
        cg_svg_render(svg, image, m, NULL);
        bench_sink += cg_image_row_rgba8(image, s->side / 2)[s->side / 2].a;
        cg_svg_free(svg);
    }
    cg_image_free(image);
}

#ifdef CG_BENCH_HAVE_RSVG
static void run_rsvg(void *context)
{
    sample *s = context;
    cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, s->side, s->side);
    for (int i = 0; i < s->count; i++) {
        cairo_t *cr = cairo_create(surface);
        cairo_set_operator(cr, CAIRO_OPERATOR_CLEAR);
        cairo_paint(cr);
        cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
        RsvgHandle *handle = rsvg_handle_new_from_data((const guint8 *)s->icons[i].bytes,
                                                       s->icons[i].size, NULL);
        if (handle) {
            RsvgRectangle viewport = {0, 0, s->side, s->side};
            rsvg_handle_render_document(handle, cr, &viewport, NULL);
            g_object_unref(handle);
        }
        cairo_destroy(cr);
    }
    cairo_surface_flush(surface);
    bench_sink += cairo_image_surface_get_data(surface)[0];
    cairo_surface_destroy(surface);
}
#endif

/* resvg's time for the sample, from node timing its own loop; 0 when node
 * or the package is missing. */
static double resvg_seconds(const sample *s)
{
    char list[] = "/tmp/bench_svg_XXXXXX";
    int fd = mkstemp(list);
    if (fd < 0)
        return 0;
    FILE *f = fdopen(fd, "w");
    for (int i = 0; i < s->count; i++)
        fprintf(f, "%s\n", s->icons[i].path);
    fclose(f);
    char command[8192];
    /* the package from tests/svg (npm install there) or a global install */
    snprintf(command, sizeof command,
             "m='%s/tests/svg/node_modules/@resvg/resvg-js'; [ -d \"$m\" ] || "
             "m=\"$(npm root -g 2>/dev/null)/@resvg/resvg-js\"; CG_RESVG_MODULE=\"$m\" "
             "node '%s/bench/bench_svg_resvg.js' '%s' %d 3 2>/dev/null",
             CG_SOURCE_DIR, CG_SOURCE_DIR, list, s->side);
    FILE *p = popen(command, "r");
    double seconds = 0;
    if (p) {
        if (fscanf(p, "%lf", &seconds) != 1)
            seconds = 0;
        pclose(p);
    }
    remove(list);
    return seconds;
}

int main(int argc, char **argv)
{
    int wanted = argc > 1 ? atoi(argv[1]) : 200;
    sample s = {NULL, 0, argc > 2 ? atoi(argv[2]) : 256};
    if (wanted < 1 || s.side < 1 || load_sample(&s, wanted) == 0) {
        bench_row("svg papirus", 0, "-", 0, "Papirus icons not found (papirus-icon-theme)");
        return 0;
    }
    char name[96], note[160];
    snprintf(name, sizeof name, "svg papirus %d icons at %d px", s.count, s.side);
    /* processor time: steadier than wall time on a shared machine */
    double cg = bench_median_clock(run_cg, &s, 3, CLOCK_PROCESS_CPUTIME_ID);
#ifdef CG_BENCH_HAVE_RSVG
    double rsvg = bench_median_clock(run_rsvg, &s, 3, CLOCK_PROCESS_CPUTIME_ID);
    snprintf(note, sizeof note, "icons/s: cg %.0f, librsvg %.0f", s.count / cg, s.count / rsvg);
    bench_row(name, cg, "librsvg", rsvg, note);
#else
    bench_row(name, cg, "-", 0, "librsvg not found (librsvg2-dev)");
#endif
    double resvg = resvg_seconds(&s);
    if (resvg > 0) {
        snprintf(note, sizeof note, "icons/s: cg %.0f, resvg %.0f", s.count / cg, s.count / resvg);
        bench_row(name, cg, "resvg", resvg, note);
    } else {
        bench_row(name, cg, "-", 0, "resvg not found (cd tests/svg && npm install)");
    }
    for (int i = 0; i < s.count; i++)
        free(s.icons[i].bytes);
    free(s.icons);
    return 0;
}
