/* cg/text.h - real text: fonts read with FreeType (TTF, OTF/CFF, TTC),
 * found by family, weight and style through fontconfig, shaped with
 * HarfBuzz, and turned into cg paths that cg's own exact-coverage
 * rasterizer fills (cg/fill.h).
 *
 * Coordinates follow cg's 2D convention: y grows downwards, so a glyph's
 * outline (y up in the font) is mirrored; a run starts at its origin on
 * the baseline.  Shaped positions are in font units (as `hb-shape` prints
 * them); sizes are in pixels per em.
 */
#ifndef CG_TEXT_H
#define CG_TEXT_H

#include "cg/core.h"
#include "cg/fill.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cg_font cg_font;

/* Loads face face_index (0 for TTF/OTF; the face within a TTC collection)
 * of a font file.  CG_EIO when the file cannot be read, CG_EFORMAT with a
 * one-line message when it is not a font FreeType reads or the face has no
 * scalable outlines, CG_ERANGE for a face index beyond the collection. */
cg_status cg_font_load(const char *path, int face_index, cg_font **out, cg_error *err);

/* As cg_font_load from bytes in memory (copied: data may be freed after). */
cg_status cg_font_load_memory(const void *data, size_t size, int face_index, cg_font **out,
                              cg_error *err);

/* Asks fontconfig for the best font of family with weight (CSS scale
 * 100..900, 400 normal, 700 bold) and italic (0 or 1); writes its file into
 * path (capacity cap) and its face index into *face_index.  CG_EEMPTY when
 * fontconfig has no font at all, CG_ERANGE when path is too small. */
cg_status cg_font_find(const char *family, int weight, int italic, char *path, size_t cap,
                       int *face_index, cg_error *err);

/* CG_OK when fontconfig has a scalable font whose family is exactly family
 * (compared as fontconfig does: case and blanks ignored), CG_EEMPTY with a
 * one-line message otherwise.  cg_font_find always returns a font, the
 * closest substitute when the family is missing; this says whether it would
 * substitute.  The generic names serif, sans-serif, monospace, cursive,
 * fantasy, system-ui, sans and mono (any case) are CG_OK: fontconfig's
 * configuration resolves them. */
cg_status cg_font_family_exists(const char *family, cg_error *err);

/* A font from a file name (when such a file exists) or else a family name
 * looked up with cg_font_find. */
cg_status cg_font_open(const char *family_or_file, int weight, int italic, cg_font **out,
                       cg_error *err);

void cg_font_free(cg_font *font);

/* Units per em of the font's design grid. */
int cg_font_units_per_em(const cg_font *font);
/* Number of glyphs of the face. */
int cg_font_glyph_count(const cg_font *font);
/* Ascender and descender (descender negative), in font units. */
void cg_font_metrics(const cg_font *font, int *ascender, int *descender, int *line_gap);

/* Appends the outline of glyph at size pixels per em with its origin at
 * (x, y) to out.  Outlines are read once (FT_Outline_Decompose, unhinted,
 * in font units) and kept in the font's glyph-outline cache.  CG_ERANGE for
 * a glyph id beyond the face, CG_EFORMAT for a broken glyph. */
cg_status cg_font_glyph_path(cg_font *font, unsigned glyph, double size, double x, double y,
                             cg_path *out, cg_error *err);

/* Number of glyph outlines in the cache (each read from the file once). */
size_t cg_font_cached_glyphs(const cg_font *font);

/* One shaped glyph, as HarfBuzz gives it: positions in font units, y up. */
typedef struct cg_shaped_glyph {
    unsigned glyph;   /* glyph id in the font */
    unsigned cluster; /* byte offset in the UTF-8 text of its cluster */
    int x_advance, y_advance, x_offset, y_offset;
} cg_shaped_glyph;

/* Shapes len bytes of UTF-8 text (len (size_t)-1: up to the NUL) with
 * HarfBuzz over the font's own bytes; direction, script and language are
 * guessed from the text (hb_buffer_guess_segment_properties), so Arabic runs
 * right to left and Devanagari gets its reordering.  *glyphs (malloc'ed,
 * free with free) receives *count glyphs in visual order.  CG_EFORMAT for
 * text that is not valid UTF-8. */
cg_status cg_text_shape(cg_font *font, const char *utf8, size_t len, cg_shaped_glyph **glyphs,
                        size_t *count, cg_error *err);

typedef enum cg_text_align {
    CG_TEXT_START = 0, /* the run begins at x */
    CG_TEXT_MIDDLE = 1,
    CG_TEXT_END = 2
} cg_text_align;

typedef enum cg_text_baseline {
    CG_BASELINE_ALPHABETIC = 0, /* y is the baseline */
    CG_BASELINE_TOP = 1,        /* y is the ascender line */
    CG_BASELINE_MIDDLE = 2,     /* y is half-way between ascender and descender */
    CG_BASELINE_BOTTOM = 3      /* y is the descender line */
} cg_text_baseline;

/* Width in pixels of the shaped text at size (the sum of its advances). */
cg_status cg_text_measure(cg_font *font, const char *utf8, double size, double *width,
                          cg_error *err);

/* Appends the outlines of one shaped line of text at (x, y) with align and
 * baseline.  *width (may be NULL) receives its advance width in pixels. */
cg_status cg_text_run_path(cg_font *font, const char *utf8, double size, double x, double y,
                           cg_text_align align, cg_text_baseline baseline, cg_path *out,
                           double *width, cg_error *err);

/* Paragraph layout: words (split at spaces; '\n' forces a break) are put on
 * a line while the line's shaped width stays within width (a word wider
 * than width gets a line of its own); width <= 0 never wraps.  Lines are
 * line_spacing * size apart (line_spacing <= 0 means 1.2), each aligned at
 * x within [x, x + width] for start (x, x + width / 2, x + width for middle
 * and end when width > 0; around x otherwise); the first baseline is at y
 * placed as baseline says.  *lines (may be NULL) gets the number of lines. */
typedef struct cg_text_paragraph {
    double size;
    double width;
    double line_spacing;
    cg_text_align align;
    cg_text_baseline baseline;
} cg_text_paragraph;

cg_status cg_text_paragraph_path(cg_font *font, const char *utf8, const cg_text_paragraph *style,
                                 double x, double y, cg_path *out, int *lines, cg_error *err);

#ifdef __cplusplus
}
#endif

#endif
