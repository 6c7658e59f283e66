/* Glyphs: a paragraph of text (DejaVu Serif, 16 px, 1024 x 768), shaped
 * once beforehand, rasterized by cg and by FreeType from the same outlines.
 *
 *   cg            the glyphs' cached outlines placed into one cg_path
 *                 (cg_font_glyph_path) and filled black onto an RGBA8
 *                 canvas, curves within 0.01 px (what `cg draw` uses)
 *   FreeType      each glyph's scaled outline (loaded once per glyph id,
 *                 unhinted), copied, moved to its pen position and
 *                 rasterized by FreeType's smooth rasterizer into one 8-bit
 *                 coverage bitmap (FT_Outline_Get_Bitmap): coverage only,
 *                 no compositing
 *   FT_Render_Glyph  what a FreeType program usually does: load, scale and
 *                 render each glyph into its own bitmap
 *
 * and the same paragraph through `cg draw --repeat` (bench_tool.h), which
 * also opens the font, shapes and lays out the text on every run.
 * Processor time, medians of several runs. */
#include "bench.h"
#include "bench_tool.h"
#include "cg/fill.h"
#include "cg/image.h"
#include "cg/text.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <math.h>
#include <string.h>

#define FONT "/usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf"
enum { WIDTH = 1024, HEIGHT = 768, SIZE = 16, LINES = 36, RUNS = 9 };

static const char *const words =
    "The quick brown fox jumps over the lazy dog while a wizard's job is to vex chumps "
    "quickly in fog; sphinx of black quartz, judge my vow, and pack my box with five "
    "dozen liquor jugs. Affine offices waft through fjords, AVATAR Wave Typography.";

typedef struct placed {
    unsigned glyph;
    double x, y; /* pen position in pixels, y down */
} placed;

typedef struct job {
    cg_font *font;
    FT_Library library;
    FT_Face face;
    placed *glyphs;
    size_t count;
    FT_Outline *outlines; /* per glyph id, scaled, NULL until loaded */
    unsigned char *loaded;
    cg_image *canvas;
    cg_path *path;
    cg_rasterizer *rasterizer;
    unsigned char *coverage; /* FreeType's target */
    double tolerance;
} job;

/* Shapes LINES lines of the text, each starting at a different word. */
static int layout(job *j)
{
    size_t cap = 0;
    double scale = (double)SIZE / cg_font_units_per_em(j->font);
    size_t n = strlen(words);
    for (int line = 0; line < LINES; line++) {
        char text[160];
        size_t start = (size_t)(line * 37) % n;
        while (start > 0 && words[start - 1] != ' ')
            start--;
        size_t k = 0;
        for (size_t i = 0; k < 120; i++)
            text[k++] = words[(start + i) % n];
        text[k] = '\0';
        cg_shaped_glyph *g;
        size_t count;
        if (cg_text_shape(j->font, text, (size_t)-1, &g, &count, NULL) != CG_OK)
            return 1;
        double pen = 8, base = 20 + line * 20.5;
        for (size_t i = 0; i < count; i++) {
            if (j->count == cap) {
                cap = cap ? 2 * cap : 1024;
                placed *grown = realloc(j->glyphs, cap * sizeof *grown);
                if (!grown)
                    return 1;
                j->glyphs = grown;
            }
            j->glyphs[j->count++] = (placed){g[i].glyph, pen + g[i].x_offset * scale,
                                             base - g[i].y_offset * scale};
            pen += g[i].x_advance * scale;
        }
        free(g);
    }
    return 0;
}

static void run_cg(void *context)
{
    job *j = context;
    cg_image_clear_rgba8(j->canvas, (cg_rgba8){255, 255, 255, 255});
    cg_path_reset(j->path);
    for (size_t i = 0; i < j->count; i++)
        cg_font_glyph_path(j->font, j->glyphs[i].glyph, SIZE, j->glyphs[i].x, j->glyphs[i].y,
                           j->path, NULL);
    cg_paint black = cg_paint_solid((cg_rgba8){0, 0, 0, 255});
    cg_rasterizer_set_tolerance(j->rasterizer, j->tolerance);
    cg_rasterizer_fill_path(j->rasterizer, j->canvas, j->path, CG_FILL_NONZERO, &black);
}

/* The same with one fill per glyph. */
static void run_cg_each(void *context)
{
    job *j = context;
    cg_image_clear_rgba8(j->canvas, (cg_rgba8){255, 255, 255, 255});
    cg_paint black = cg_paint_solid((cg_rgba8){0, 0, 0, 255});
    cg_rasterizer_set_tolerance(j->rasterizer, j->tolerance);
    for (size_t i = 0; i < j->count; i++) {
        cg_path_reset(j->path);
        cg_font_glyph_path(j->font, j->glyphs[i].glyph, SIZE, j->glyphs[i].x, j->glyphs[i].y,
                           j->path, NULL);
        cg_rasterizer_fill_path(j->rasterizer, j->canvas, j->path, CG_FILL_NONZERO, &black);
    }
}

static FT_Outline *ft_outline(job *j, unsigned glyph)
{
    if (!j->loaded[glyph]) {
        j->loaded[glyph] = 1;
        if (FT_Load_Glyph(j->face, glyph, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) == 0) {
            FT_Outline *o = &j->outlines[glyph];
            FT_Outline *src = &j->face->glyph->outline;
            if (FT_Outline_New(j->library, (FT_UInt)src->n_points, src->n_contours, o) == 0)
                FT_Outline_Copy(src, o);
        }
    }
    return j->outlines[glyph].n_points ? &j->outlines[glyph] : NULL;
}

static void run_freetype(void *context)
{
    job *j = context;
    memset(j->coverage, 0, (size_t)WIDTH * HEIGHT);
    FT_Bitmap bitmap = {0};
    bitmap.rows = HEIGHT;
    bitmap.width = WIDTH;
    bitmap.pitch = WIDTH;
    bitmap.buffer = j->coverage;
    bitmap.num_grays = 256;
    bitmap.pixel_mode = FT_PIXEL_MODE_GRAY;
    FT_Outline moved;
    FT_Outline_New(j->library, 4096, 512, &moved);
    for (size_t i = 0; i < j->count; i++) {
        FT_Outline *o = ft_outline(j, j->glyphs[i].glyph);
        if (!o || o->n_points > 4096 || o->n_contours > 512)
            continue;
        moved.n_points = o->n_points;
        moved.n_contours = o->n_contours;
        FT_Outline_Copy(o, &moved);
        /* FreeType's y is up, the bitmap's row 0 at the top */
        FT_Outline_Translate(&moved, (FT_Pos)lround(j->glyphs[i].x * 64),
                             (FT_Pos)lround((HEIGHT - j->glyphs[i].y) * 64));
        FT_Outline_Get_Bitmap(j->library, &moved, &bitmap);
    }
    moved.n_points = 4096;
    moved.n_contours = 512;
    FT_Outline_Done(j->library, &moved);
}

static void run_render_glyph(void *context)
{
    job *j = context;
    long sum = 0;
    for (size_t i = 0; i < j->count; i++)
        if (FT_Load_Glyph(j->face, j->glyphs[i].glyph, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) == 0
            && FT_Render_Glyph(j->face->glyph, FT_RENDER_MODE_NORMAL) == 0)
            sum += j->face->glyph->bitmap.rows;
    bench_sink = (double)sum;
}

/* The processor time of one run of the paragraph as a `cg draw` script
 * (bench_tool.h); -1 on failure. */
static double tool_seconds(void)
{
    char script[] = "/tmp/cg-bench-text-XXXXXX";
    int fd = mkstemp(script);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f)
        return -1;
    fprintf(f, "size %d %d\nfont %s %d\n", WIDTH, HEIGHT, FONT, SIZE);
    size_t n = strlen(words);
    for (int line = 0; line < LINES; line++) {
        size_t start = (size_t)(line * 37) % n;
        while (start > 0 && words[start - 1] != ' ')
            start--;
        fprintf(f, "text 8 %.17g \"", 20 + line * 20.5);
        for (size_t i = 0; i < 120; i++) {
            char c = words[(start + i) % n];
            if (c == '"' || c == '\\')
                fputc('\\', f);
            fputc(c, f);
        }
        fputs("\"\n", f);
    }
    fclose(f);
    double seconds = bench_tool_median(script, "/tmp/cg-bench-text.ppm", RUNS, 3);
    remove(script);
    remove("/tmp/cg-bench-text.ppm");
    return seconds;
}

int main(void)
{
    job j = {0};
    cg_error err;
    if (cg_font_load(FONT, 0, &j.font, &err) != CG_OK) {
        fprintf(stderr, "bench_text: %s (apt-get install fonts-dejavu-core)\n", err.message);
        return 0;
    }
    if (FT_Init_FreeType(&j.library) || FT_New_Face(j.library, FONT, 0, &j.face)
        || FT_Set_Pixel_Sizes(j.face, 0, SIZE) || layout(&j)
        || cg_image_create(&j.canvas, WIDTH, HEIGHT, CG_PIXEL_RGBA8) != CG_OK
        || cg_path_create(&j.path) != CG_OK || cg_rasterizer_create(&j.rasterizer) != CG_OK) {
        fprintf(stderr, "bench_text: set-up failed\n");
        return 1;
    }
    j.outlines = calloc((size_t)j.face->num_glyphs, sizeof *j.outlines);
    j.loaded = calloc((size_t)j.face->num_glyphs, 1);
    j.coverage = malloc((size_t)WIDTH * HEIGHT);
    if (!j.outlines || !j.loaded || !j.coverage)
        return 1;
    run_freetype(&j); /* outlines loaded once, as cg's cache has them */
    char name[160], note[160];
    snprintf(note, sizeof note, "%zu glyphs, %d lines, DejaVu Serif %d px, %d x %d", j.count, LINES,
             SIZE, WIDTH, HEIGHT);
    double ft = bench_median_clock(run_freetype, &j, RUNS, CLOCK_PROCESS_CPUTIME_ID);
    double render = bench_median_clock(run_render_glyph, &j, RUNS, CLOCK_PROCESS_CPUTIME_ID);
    const double tolerances[2] = {0.01, 0.1};
    for (int t = 0; t < 2; t++) {
        j.tolerance = tolerances[t];
        run_cg(&j);
        double cg = bench_median_clock(run_cg, &j, RUNS, CLOCK_PROCESS_CPUTIME_ID);
        snprintf(name, sizeof name, "glyphs: a paragraph, shaping excluded, cg tolerance %g",
                 tolerances[t]);
        bench_row(name, cg, "FreeType", ft, note);
        bench_row(name, cg, "FT_Render_Glyph", render, note);
        double each = bench_median_clock(run_cg_each, &j, RUNS, CLOCK_PROCESS_CPUTIME_ID);
        snprintf(name, sizeof name, "glyphs: a paragraph, one fill per glyph, cg tolerance %g",
                 tolerances[t]);
        bench_row(name, each, "FT_Render_Glyph", render, note);
    }
    double tool = tool_seconds();
    if (tool > 0)
        bench_row("glyphs: the paragraph by cg draw --repeat (opens, shapes, fills)", tool,
                  "FreeType", ft, note);
    else
        bench_row("glyphs: the paragraph by cg draw --repeat (opens, shapes, fills)", 0, "-", 0,
                  "cg draw failed");
    for (long g = 0; g < j.face->num_glyphs; g++)
        if (j.loaded[g] && j.outlines[g].n_points)
            FT_Outline_Done(j.library, &j.outlines[g]);
    free(j.outlines);
    free(j.loaded);
    free(j.coverage);
    free(j.glyphs);
    cg_rasterizer_free(j.rasterizer);
    cg_path_free(j.path);
    cg_image_free(j.canvas);
    FT_Done_Face(j.face);
    FT_Done_FreeType(j.library);
    cg_font_free(j.font);
    return 0;
}
