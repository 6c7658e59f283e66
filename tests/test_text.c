/* Text (cg/text.h): cg's fill of glyph outlines against FreeType's own
 * anti-aliased rendering, shaping properties (kerning, ligatures), layout
 * alignment and wrapping, the outline cache, and bad fonts refused. */
#include "cg/text.h"
#include "cg/fill.h"
#include "cg/image.h"
#include "check.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SANS "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#define SERIF "/usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf"

static cg_font *open_font(const char *path)
{
    cg_font *font = NULL;
    cg_error err;
    cg_status status = cg_font_load(path, 0, &font, &err);
    CHECK_MSG(status == CG_OK, "%s: %s", path, err.message);
    return font;
}

/* FreeType's own scaled outline (26.6 pixels, y up) as a cg path at (ox, oy). */
typedef struct ft_sink {
    cg_path *path;
    double ox, oy;
} ft_sink;
#define FX(v) (k->ox + (v)->x / 64.0)
#define FY(v) (k->oy - (v)->y / 64.0)
static int ft_move(const FT_Vector *to, void *u)
{
    ft_sink *k = u;
    return cg_path_move_to(k->path, FX(to), FY(to)) != CG_OK;
}
static int ft_line(const FT_Vector *to, void *u)
{
    ft_sink *k = u;
    return cg_path_line_to(k->path, FX(to), FY(to)) != CG_OK;
}
static int ft_conic(const FT_Vector *c, const FT_Vector *to, void *u)
{
    ft_sink *k = u;
    return cg_path_quad_to(k->path, FX(c), FY(c), FX(to), FY(to)) != CG_OK;
}
static int ft_cubic(const FT_Vector *a, const FT_Vector *b, const FT_Vector *to, void *u)
{
    ft_sink *k = u;
    return cg_path_cubic_to(k->path, FX(a), FY(a), FX(b), FY(b), FX(to), FY(to)) != CG_OK;
}

/* Differences of one glyph's coverage, in 1/255, summed over pixels. */
typedef struct coverage_sums {
    double cg_ft_box; /* |cg - FT_Render_Glyph| over the glyph's box */
    long box;         /* pixels of the box */
    double cg_exact;  /* |cg - exact| over the pixels touched (either above 0) */
    double ft_exact;  /* |FT_Render_Glyph - exact| over the same pixels */
    double own_exact; /* cg's own unrounded outline: |cg - exact| */
    long touched;
} coverage_sums;

enum { SUPER = 16 };         /* subpixels per pixel side of the exact coverage */
#define GLYPH_TOLERANCE 0.01 /* as cg draw flattens glyphs */

static cg_image *fill_glyph(cg_path *path, int w, int h)
{
    cg_image *image = NULL;
    cg_rasterizer *r = NULL;
    cg_paint white = cg_paint_solid((cg_rgba8){255, 255, 255, 255});
    if (cg_image_create(&image, w, h, CG_PIXEL_RGBA8) != CG_OK || cg_rasterizer_create(&r) != CG_OK
        || cg_rasterizer_set_tolerance(r, GLYPH_TOLERANCE) != CG_OK
        || cg_rasterizer_fill_path(r, image, path, CG_FILL_NONZERO, &white) != CG_OK) {
        cg_image_free(image);
        image = NULL;
    }
    cg_rasterizer_free(r);
    return image;
}

/* The exact coverage (0..255 as a real) of FreeType's scaled outline
 * placed at (ox, oy) in a w x h image: the outline 16 times larger, drawn
 * by FreeType's rasterizer and box-filtered over 16 x 16 subpixels (at that
 * scale its chords stay within 1/256 px of the curves).  NULL on failure. */
static double *exact_coverage(FT_Library lib, const FT_Outline *outline, double ox, double oy,
                              int w, int h)
{
    FT_Outline big;
    if (FT_Outline_New(lib, (FT_UInt)outline->n_points, outline->n_contours, &big))
        return NULL;
    FT_Outline_Copy(outline, &big);
    for (int i = 0; i < big.n_points; i++) { /* y up, row 0 of the bitmap at the top */
        big.points[i].x = (big.points[i].x + (FT_Pos)(ox * 64)) * SUPER;
        big.points[i].y = (big.points[i].y - (FT_Pos)(oy * 64) + h * 64) * SUPER;
    }
    unsigned char *fine = calloc((size_t)w * SUPER * h * SUPER, 1);
    double *exact = calloc((size_t)w * h, sizeof *exact);
    FT_Bitmap bitmap = {0};
    bitmap.rows = (unsigned)(h * SUPER);
    bitmap.width = (unsigned)(w * SUPER);
    bitmap.pitch = w * SUPER;
    bitmap.buffer = fine;
    bitmap.num_grays = 256;
    bitmap.pixel_mode = FT_PIXEL_MODE_GRAY;
    if (!fine || !exact || FT_Outline_Get_Bitmap(lib, &big, &bitmap)) {
        free(exact);
        exact = NULL;
    }
    for (int y = 0; exact && y < h; y++)
        for (int x = 0; x < w; x++) {
            double sum = 0;
            for (int j = 0; j < SUPER; j++)
                for (int i = 0; i < SUPER; i++)
                    sum += fine[(y * SUPER + j) * (w * SUPER) + x * SUPER + i];
            exact[y * w + x] = sum / (SUPER * SUPER);
        }
    free(fine);
    FT_Outline_Done(lib, &big);
    return exact;
}

/* Adds glyph's differences at size px to *sums: cg filling FreeType's own
 * scaled outline (points rounded to 1/64 px) and cg's unrounded
 * cg_font_glyph_path, FT_Render_Glyph (FT_RENDER_MODE_NORMAL, unhinted) and
 * the exact coverage of the rounded outline, over FreeType's bitmap with a
 * 2-pixel margin.  0, or -1 on failure. */
static int glyph_differences(FT_Library lib, FT_Face face, cg_font *font, unsigned glyph, int size,
                             coverage_sums *sums)
{
    FT_Set_Pixel_Sizes(face, 0, (FT_UInt)size);
    if (FT_Load_Glyph(face, glyph, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
        return -1;
    FT_Outline outline;
    FT_Outline_New(lib, (FT_UInt)face->glyph->outline.n_points, face->glyph->outline.n_contours,
                   &outline);
    FT_Outline_Copy(&face->glyph->outline, &outline);
    if (FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL)) {
        FT_Outline_Done(lib, &outline);
        return -1;
    }
    FT_Bitmap *bm = &face->glyph->bitmap;
    int pad = 2, w = (int)bm->width + 2 * pad, h = (int)bm->rows + 2 * pad;
    double ox = pad - face->glyph->bitmap_left, oy = pad + face->glyph->bitmap_top;
    cg_path *same = NULL, *own = NULL;
    cg_path_create(&same);
    cg_path_create(&own);
    static const FT_Outline_Funcs funcs = {ft_move, ft_line, ft_conic, ft_cubic, 0, 0};
    ft_sink sink = {same, ox, oy};
    int built = !FT_Outline_Decompose(&outline, &funcs, &sink)
                && cg_font_glyph_path(font, glyph, size, ox, oy, own, NULL) == CG_OK;
    double *exact = exact_coverage(lib, &outline, ox, oy, w, h);
    FT_Outline_Done(lib, &outline);
    cg_image *ours = built ? fill_glyph(same, w, h) : NULL;
    cg_image *unrounded = built ? fill_glyph(own, w, h) : NULL;
    int ok = ours && unrounded && exact;
    for (int y = 0; ok && y < h; y++)
        for (int x = 0; x < w; x++) {
            int ft = 0, bx = x - pad, by = y - pad;
            if (bx >= 0 && by >= 0 && bx < (int)bm->width && by < (int)bm->rows)
                ft = bm->buffer[by * bm->pitch + bx];
            int cg = cg_image_row_rgba8(ours, y)[x].a;
            int cg_own = cg_image_row_rgba8(unrounded, y)[x].a;
            double e = exact[y * w + x];
            sums->cg_ft_box += abs(ft - cg);
            sums->box++;
            if (ft || cg || e > 0) {
                sums->cg_exact += fabs(cg - e);
                sums->ft_exact += fabs(ft - e);
                sums->own_exact += fabs(cg_own - e);
                sums->touched++;
            }
        }
    free(exact);
    cg_image_free(ours);
    cg_image_free(unrounded);
    cg_path_free(same);
    cg_path_free(own);
    return ok ? 0 : -1;
}

/* cg's coverage of glyph outlines against the exact coverage (within
 * 1/255 on the touched pixels at 12-96 px) and against FreeType's own
 * anti-aliased rendering, which is further from the exact coverage than
 * cg is: its rasterizer draws conics as chords up to 1/16 px inside the
 * curve and gives ceil(256 c) - 1 for coverage c (docs/text.md). */
static void coverage_matches_freetype(void)
{
    const char *files[] = {SANS, SERIF};
    const char *chars = "AaBgQ@&%WfiMy8s";
    const int sizes[] = {12, 16, 24, 33, 48, 64, 96};
    FT_Library lib;
    FT_Init_FreeType(&lib);
    for (int f = 0; f < 2; f++) {
        FT_Face face;
        cg_font *font = open_font(files[f]);
        if (!font || FT_New_Face(lib, files[f], 0, &face)) {
            CHECK(0);
            cg_font_free(font);
            continue;
        }
        for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++) {
            coverage_sums sums = {0};
            for (const char *c = chars; *c; c++) {
                unsigned g = FT_Get_Char_Index(face, (FT_ULong)(unsigned char)*c);
                CHECK_MSG(glyph_differences(lib, face, font, g, sizes[s], &sums) == 0,
                          "glyph '%c' at %d px", *c, sizes[s]);
            }
            double n = sums.touched ? (double)sums.touched : 1;
            double cg = sums.cg_exact / n, ft = sums.ft_exact / n, own = sums.own_exact / n;
            double box = sums.cg_ft_box / (sums.box ? (double)sums.box : 1);
            printf("  %s %d px, touched pixels: |cg - exact| %.3f/255, |FT_Render_Glyph - "
                   "exact| %.3f, cg's unrounded outline %.3f; box: |cg - FT| %.3f\n",
                   strrchr(files[f], '/') + 1, sizes[s], cg, ft, own, box);
            CHECK_MSG(cg <= 1.0, "%s at %d px: %.3f/255 from the exact coverage", files[f],
                      sizes[s], cg);
            CHECK_MSG(cg < ft, "%s at %d px: cg %.3f/255 from exact, FreeType %.3f", files[f],
                      sizes[s], cg, ft);
            /* FreeType rounds the scaled points to 1/64 px, cg does not */
            CHECK_MSG(own <= 1.0, "%s at %d px: unrounded outline %.3f/255", files[f], sizes[s],
                      own);
            CHECK_MSG(box <= 1.25, "%s at %d px: %.3f/255 from FT_Render_Glyph", files[f], sizes[s],
                      box);
        }
        FT_Done_Face(face);
        cg_font_free(font);
    }
    FT_Done_FreeType(lib);
}

static void bad_fonts_refused(void)
{
    cg_font *font = (cg_font *)1;
    cg_error err;
    CHECK(cg_font_load("/nonexistent/font.ttf", 0, &font, &err) == CG_EIO);
    CHECK(font == NULL && strstr(err.message, "cannot open") != NULL);
    const char junk[] = "this is not a font at all, just some text bytes";
    CHECK(cg_font_load_memory(junk, sizeof junk, 0, &font, &err) == CG_EFORMAT);
    CHECK(font == NULL && strstr(err.message, "not a font") != NULL);
    CHECK(cg_font_load_memory(junk, 0, 0, &font, &err) == CG_EFORMAT);
    CHECK(cg_font_load(SANS, 7, &font, &err) == CG_ERANGE && font == NULL);
    CHECK(strstr(err.message, "face 7") != NULL);
    /* Truncated and corrupted copies of a real font: refused or read, never a crash. */
    FILE *file = fopen(SANS, "rb");
    unsigned char *bytes = malloc(1 << 20);
    size_t size = file && bytes ? fread(bytes, 1, 1 << 20, file) : 0;
    if (file)
        fclose(file);
    CHECK(size > 100000);
    const size_t cuts[] = {4, 12, 100, 1000, 20000};
    for (size_t i = 0; i < sizeof cuts / sizeof *cuts && size; i++) {
        cg_status status = cg_font_load_memory(bytes, cuts[i], 0, &font, &err);
        CHECK_MSG(status != CG_OK || font != NULL, "cut at %zu", cuts[i]);
        if (status == CG_OK) {
            cg_path *path;
            cg_path_create(&path);
            for (int g = 0; g < cg_font_glyph_count(font); g++)
                cg_font_glyph_path(font, (unsigned)g, 20, 0, 0, path, NULL);
            cg_path_free(path);
            cg_font_free(font);
        } else {
            CHECK(strlen(err.message) > 0 && strchr(err.message, '\n') == NULL);
        }
    }
    check_rng rng = {77};
    for (int round = 0; round < 20 && size; round++) {
        unsigned char *copy = malloc(size);
        memcpy(copy, bytes, size);
        for (int k = 0; k < 50; k++)
            copy[check_rng_int(&rng, 0, (long long)size - 1)] = (unsigned char)check_rng_int(
                &rng, 0, 255);
        if (cg_font_load_memory(copy, size, 0, &font, &err) == CG_OK) {
            cg_path *path;
            cg_path_create(&path);
            cg_text_run_path(font, "Hello, world", 24, 0, 30, CG_TEXT_START, CG_BASELINE_ALPHABETIC,
                             path, NULL, NULL);
            cg_path_free(path);
            cg_font_free(font);
        }
        free(copy);
    }
    free(bytes);
    font = open_font(SANS);
    if (font) {
        cg_path *path;
        cg_path_create(&path);
        CHECK(cg_font_glyph_path(font, 1u << 20, 12, 0, 0, path, &err) == CG_ERANGE);
        CHECK(cg_text_run_path(font, "bad \xC3\x28 utf8", 12, 0, 0, CG_TEXT_START,
                               CG_BASELINE_ALPHABETIC, path, NULL, &err)
              == CG_EFORMAT);
        CHECK(strstr(err.message, "UTF-8") != NULL);
        CHECK(cg_text_run_path(font, "x", -3, 0, 0, CG_TEXT_START, CG_BASELINE_ALPHABETIC, path,
                               NULL, &err)
              == CG_EINVAL);
        CHECK(cg_path_is_empty(path));
        cg_path_free(path);
        cg_font_free(font);
    }
}

static int advance_sum(cg_font *font, const char *text, size_t *count)
{
    cg_shaped_glyph *g;
    int sum = 0;
    if (cg_text_shape(font, text, (size_t)-1, &g, count, NULL) != CG_OK)
        return -1;
    for (size_t i = 0; i < *count; i++)
        sum += g[i].x_advance;
    free(g);
    return sum;
}

static void shaping_kerns_and_ligates(void)
{
    cg_font *font = open_font(SANS);
    if (!font)
        return;
    size_t n;
    int a = advance_sum(font, "A", &n), v = advance_sum(font, "V", &n);
    int av = advance_sum(font, "AV", &n);
    CHECK_MSG(n == 2 && av < a + v, "AV %d vs A+V %d: kerning applied", av, a + v);
    advance_sum(font, "fi", &n);
    CHECK_MSG(n == 1, "fi shapes to %zu glyphs (one ligature)", n);
    cg_shaped_glyph *g;
    CHECK(cg_text_shape(font, "", (size_t)-1, &g, &n, NULL) == CG_OK && n == 0 && g == NULL);
    /* Arabic runs right to left: clusters decrease along the visual order. */
    cg_font *arabic = NULL;
    if (cg_font_load("/usr/share/fonts/truetype/noto/NotoSansArabic-Regular.ttf", 0, &arabic, NULL)
        == CG_OK) {
        CHECK(cg_text_shape(arabic, "\xd8\xb3\xd9\x84\xd8\xa7\xd9\x85", (size_t)-1, &g, &n, NULL)
              == CG_OK);
        CHECK(n >= 2 && g[0].cluster > g[n - 1].cluster);
        free(g);
        cg_font_free(arabic);
    } else {
        printf("  (Arabic check skipped: apt-get install fonts-noto-core)\n");
    }
    cg_font_free(font);
}

static void bounds(const cg_path *path, cg_vec2 *lo, cg_vec2 *hi)
{
    if (cg_path_bounds(path, 0.01, lo, hi) != CG_OK)
        *lo = *hi = (cg_vec2){NAN, NAN};
}

static void layout_aligns_and_wraps(void)
{
    cg_font *font = open_font(SANS);
    if (!font)
        return;
    const char *text = "Sphinx of black quartz, judge my vow";
    double w = 0;
    CHECK(cg_text_measure(font, text, 20, &w, NULL) == CG_OK && w > 100);
    cg_vec2 lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        cg_path *path;
        cg_path_create(&path);
        double got;
        CHECK(cg_text_run_path(font, text, 20, 300, 50, (cg_text_align)a, CG_BASELINE_ALPHABETIC,
                               path, &got, NULL)
              == CG_OK);
        CHECK_NEAR(got, w, 1e-9);
        bounds(path, &lo[a], &hi[a]);
        cg_path_free(path);
    }
    CHECK_NEAR(lo[1].x, lo[0].x - w / 2, 1e-6);
    CHECK_NEAR(lo[2].x, lo[0].x - w, 1e-6);
    CHECK_NEAR(hi[2].y, hi[0].y, 1e-9);
    CHECK(lo[0].x >= 300 - 2 && hi[0].x <= 300 + w + 2 && hi[0].y > 50 && lo[0].y < 50 - 10);
    /* Baseline top: the ascender line at y, so every glyph is below. */
    cg_path *path;
    cg_path_create(&path);
    CHECK(
        cg_text_run_path(font, "Hxg", 40, 0, 100, CG_TEXT_START, CG_BASELINE_TOP, path, NULL, NULL)
        == CG_OK);
    cg_vec2 l, h;
    bounds(path, &l, &h);
    CHECK(l.y >= 100);
    /* Wrapping: every line within the width, lines spaced as asked. */
    check_rng rng = {5};
    for (int round = 0; round < 20; round++) {
        double width = check_rng_range(&rng, 60, 400), spacing = check_rng_range(&rng, 1, 2);
        cg_text_paragraph style = {16, width, spacing, (cg_text_align)(round % 3),
                                   CG_BASELINE_ALPHABETIC};
        cg_path_reset(path);
        int lines = 0;
        CHECK(cg_text_paragraph_path(font, text, &style, 10, 30, path, &lines, NULL) == CG_OK);
        bounds(path, &l, &h);
        CHECK_MSG(l.x >= 10 - 2 && h.x <= 10 + width + 2, "width %.1f: ink %.1f..%.1f", width, l.x,
                  h.x);
        CHECK(lines >= (int)ceil(w * 0.8 / width) && lines <= 7);
        /* the last baseline is (lines - 1) lines below the first */
        CHECK(h.y <= 30 + (lines - 1) * spacing * 16 + 16 && h.y > 30 + (lines - 1) * spacing * 16);
    }
    cg_text_paragraph one = {16, 0, 0, CG_TEXT_START, CG_BASELINE_ALPHABETIC};
    int lines = 0;
    CHECK(cg_text_paragraph_path(font, text, &one, 0, 20, path, &lines, NULL) == CG_OK
          && lines == 1);
    CHECK(cg_text_paragraph_path(font, "two\nlines", &one, 0, 20, path, &lines, NULL) == CG_OK
          && lines == 2);
    one.width = 1;
    CHECK(cg_text_paragraph_path(font, "a b c d", &one, 0, 20, path, &lines, NULL) == CG_OK
          && lines == 4);
    cg_path_free(path);
    cg_font_free(font);
}

static void cache_reads_each_glyph_once(void)
{
    cg_font *font = open_font(SANS);
    if (!font)
        return;
    cg_path *path;
    cg_path_create(&path);
    CHECK(cg_font_cached_glyphs(font) == 0);
    CHECK(cg_text_run_path(font, "aaaa", 12, 0, 0, CG_TEXT_START, CG_BASELINE_ALPHABETIC, path,
                           NULL, NULL)
          == CG_OK);
    CHECK(cg_font_cached_glyphs(font) == 1);
    CHECK(cg_text_run_path(font, "abab", 30, 0, 0, CG_TEXT_START, CG_BASELINE_ALPHABETIC, path,
                           NULL, NULL)
          == CG_OK);
    CHECK(cg_font_cached_glyphs(font) == 2);
    cg_path_free(path);
    cg_font_free(font);
}

static void fontconfig_finds_families(void)
{
    char path[4096];
    int index = -1;
    CHECK(cg_font_find("DejaVu Sans", 700, 0, path, sizeof path, &index, NULL) == CG_OK);
    CHECK_MSG(strstr(path, "DejaVuSans-Bold") != NULL, "bold found %s", path);
    CHECK(cg_font_find("DejaVu Serif", 400, 1, path, sizeof path, &index, NULL) == CG_OK);
    CHECK_MSG(strstr(path, "DejaVuSerif-Italic") != NULL, "italic found %s", path);
    cg_font *font = NULL;
    CHECK(cg_font_open("DejaVu Sans", 400, 0, &font, NULL) == CG_OK && font);
    cg_font_free(font);
    CHECK(cg_font_find("DejaVu Sans", 400, 0, path, 4, &index, NULL) == CG_ERANGE);
    /* whether a family is installed: fontconfig's comparison, generic names */
    cg_error err;
    CHECK(cg_font_family_exists("DejaVu Sans", &err) == CG_OK);
    CHECK(cg_font_family_exists("dejavu  SANS", &err) == CG_OK);
    CHECK(cg_font_family_exists("sans-serif", &err) == CG_OK);
    CHECK(cg_font_family_exists("Monospace", &err) == CG_OK);
    CHECK(cg_font_family_exists("No Such Family Cg", &err) == CG_EEMPTY);
    CHECK(strstr(err.message, "No Such Family Cg") != NULL);
    CHECK(cg_font_family_exists("DejaVu Sans Nonexistent", &err) == CG_EEMPTY);
    CHECK(cg_font_family_exists("", &err) == CG_EINVAL);
    CHECK(cg_font_family_exists(NULL, &err) == CG_EINVAL);
}

int main(int argc, char **argv)
{
    FILE *probe = fopen(SANS, "rb");
    if (!probe) {
        printf("test_text: %s not found: skipped (apt-get install fonts-dejavu-core)\n", SANS);
        return 77;
    }
    fclose(probe);
    check_start(argc, argv);
    CHECK_GROUP(coverage_matches_freetype);
    CHECK_GROUP(bad_fonts_refused);
    CHECK_GROUP(shaping_kerns_and_ligates);
    CHECK_GROUP(layout_aligns_and_wraps);
    CHECK_GROUP(cache_reads_each_glyph_once);
    CHECK_GROUP(fontconfig_finds_families);
    return check_finish();
}
