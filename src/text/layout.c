/* Runs of text at a point and paragraphs wrapped to a width (cg/text.h). */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

static double baseline_shift(const cg_font *font, double size, cg_text_baseline baseline)
{
    double s = size / font->face->units_per_EM;
    double a = font->face->ascender * s, d = font->face->descender * s;
    switch (baseline) {
    case CG_BASELINE_TOP: return a;
    case CG_BASELINE_MIDDLE: return (a + d) / 2;
    case CG_BASELINE_BOTTOM: return d;
    default: return 0;
    }
}

/* Shapes len bytes and either measures them (out NULL) or appends their
 * outlines with the pen starting at (x, y). */
static cg_status run_bytes(cg_font *font, const char *text, size_t len, double size, double x,
                           double y, cg_path *out, double *width, cg_error *err)
{
    cg_shaped_glyph *g;
    size_t n;
    cg_status status = cg_text_shape(font, text, len, &g, &n, err);
    if (status != CG_OK)
        return status;
    double s = size / font->face->units_per_EM, pen_x = 0, pen_y = 0;
    for (size_t i = 0; i < n && status == CG_OK; i++) {
        if (out)
            status = cg_font_glyph_path(font, g[i].glyph, size, x + (pen_x + g[i].x_offset) * s,
                                        y - (pen_y + g[i].y_offset) * s, out, err);
        pen_x += g[i].x_advance;
        pen_y += g[i].y_advance;
    }
    free(g);
    if (width)
        *width = pen_x * s;
    return status;
}

static cg_status check_args(cg_font *font, const char *utf8, double size, cg_error *err)
{
    if (!font || !utf8)
        return cg_error_set(err, CG_EINVAL, "text: no font or no text");
    if (!(size > 0) || size > 1e6)
        return cg_error_set(err, CG_EINVAL, "text: size must be above 0 and at most 1e6");
    return CG_OK;
}

cg_status cg_text_measure(cg_font *font, const char *utf8, double size, double *width,
                          cg_error *err)
{
    cg_status status = check_args(font, utf8, size, err);
    if (status != CG_OK || !width)
        return status != CG_OK ? status : cg_error_set(err, CG_EINVAL, "text: no width output");
    return run_bytes(font, utf8, strlen(utf8), size, 0, 0, NULL, width, err);
}

static double align_x(double x, double w, cg_text_align align)
{
    return align == CG_TEXT_MIDDLE ? x - w / 2 : align == CG_TEXT_END ? x - w : x;
}

cg_status cg_text_run_path(cg_font *font, const char *utf8, double size, double x, double y,
                           cg_text_align align, cg_text_baseline baseline, cg_path *out,
                           double *width, cg_error *err)
{
    cg_status status = check_args(font, utf8, size, err);
    if (status != CG_OK)
        return status;
    if (!out)
        return cg_error_set(err, CG_EINVAL, "text: no path");
    size_t len = strlen(utf8);
    double w;
    status = run_bytes(font, utf8, len, size, 0, 0, NULL, &w, err);
    if (status == CG_OK)
        status = run_bytes(font, utf8, len, size, align_x(x, w, align),
                           y + baseline_shift(font, size, baseline), out, NULL, err);
    if (status == CG_OK && width)
        *width = w;
    return status;
}

/* The end of the next line of a paragraph starting at text[start]: the
 * most words whose shaped width stays within width. */
static cg_status next_line(cg_font *font, const char *text, size_t start, double size, double width,
                           size_t *end, double *line_width, cg_error *err)
{
    size_t best = start, i = start;
    double best_w = 0;
    if (!(width > 0)) { /* no wrapping: the line runs to the break, shaped once */
        while (text[i] && text[i] != '\n')
            i++;
        *end = i;
        return run_bytes(font, text + start, i - start, size, 0, 0, NULL, line_width, err);
    }
    for (;;) {
        while (text[i] && text[i] != ' ' && text[i] != '\n')
            i++;
        double w;
        cg_status status = run_bytes(font, text + start, i - start, size, 0, 0, NULL, &w, err);
        if (status != CG_OK)
            return status;
        if (best > start && width > 0 && w > width)
            break;
        best = i;
        best_w = w;
        if (!text[i] || text[i] == '\n')
            break;
        i++;
    }
    *end = best;
    *line_width = best_w;
    return CG_OK;
}

cg_status cg_text_paragraph_path(cg_font *font, const char *utf8, const cg_text_paragraph *style,
                                 double x, double y, cg_path *out, int *lines, cg_error *err)
{
    if (!style || !out)
        return cg_error_set(err, CG_EINVAL, "paragraph: no style or no path");
    cg_status status = check_args(font, utf8, style->size, err);
    if (status != CG_OK)
        return status;
    double spacing = (style->line_spacing > 0 ? style->line_spacing : 1.2) * style->size;
    double anchor = x;
    if (style->width > 0)
        anchor = style->align == CG_TEXT_MIDDLE ? x + style->width / 2
                 : style->align == CG_TEXT_END  ? x + style->width
                                                : x;
    double base = y + baseline_shift(font, style->size, style->baseline);
    int count = 0;
    size_t start = 0;
    for (;;) {
        size_t end;
        double w;
        status = next_line(font, utf8, start, style->size, style->width, &end, &w, err);
        if (status != CG_OK)
            return status;
        status = run_bytes(font, utf8 + start, end - start, style->size,
                           align_x(anchor, w, style->align), base + count * spacing, out, NULL,
                           err);
        if (status != CG_OK)
            return status;
        count++;
        if (!utf8[end])
            break;
        start = end + 1;
        while (utf8[start] == ' ')
            start++;
    }
    if (lines)
        *lines = count;
    return CG_OK;
}
