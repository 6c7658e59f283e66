/* `cg draw` commands for text: a font by family or file, runs of text at a
 * point with alignment and baseline, paragraphs wrapped to a width
 * (docs/draw-script.md, "Text").  The glyph outlines (cg/text.h) are filled
 * with the current colour by the rasterizer of the fill commands, so text
 * composites as `fill` does. */
#include "draw_script.h"
#include "cg/fill.h"
#include "cg/text.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* What the text commands keep between lines. */
typedef struct draw_text {
    cg_font *font; /* NULL until `font` */
    double size;
    cg_text_paragraph style; /* alignment, baseline, wrapping width, line spacing */
    cg_path *path;           /* scratch: the outlines of one `text` line */
} draw_text;

enum { MAX_FONT_NAME = 4096 };
/* The flattening tolerance of glyph outlines, in pixels. */
#define GLYPH_TOLERANCE 0.01

void draw_text_release(draw_state *state)
{
    draw_text *t = state->text;
    if (!t)
        return;
    cg_font_free(t->font);
    cg_path_free(t->path);
    free(t);
    state->text = NULL;
}

static draw_text *text_of(draw_state *s)
{
    if (!s->text) {
        s->text = calloc(1, sizeof *s->text);
        if (!s->text)
            return NULL;
        s->text->style.line_spacing = 1.2;
        if (cg_path_create(&s->text->path) != CG_OK) {
            draw_text_release(s);
            return NULL;
        }
    }
    return s->text;
}

static int out_of_memory(const draw_state *s)
{
    return draw_error(s, "out of memory");
}

/* The words argv[first .. last - 1] joined by single spaces, into a malloc'ed
 * string (NULL when out of memory). */
static char *join_words(char **argv, int first, int last)
{
    size_t length = 1;
    for (int i = first; i < last; i++)
        length += strlen(argv[i]) + 1;
    char *text = malloc(length);
    if (!text)
        return NULL;
    char *p = text;
    for (int i = first; i < last; i++) {
        size_t n = strlen(argv[i]);
        memcpy(p, argv[i], n);
        p += n;
        if (i + 1 < last)
            *p++ = ' ';
    }
    *p = '\0';
    return text;
}

/* A name naming a file, rather than a family: it has a '/' or a font
 * file's extension. */
static int looks_like_file(const char *name)
{
    static const char *const extensions[] = {".ttf", ".otf", ".ttc", ".otc", ".pfb", ".woff"};
    if (strchr(name, '/'))
        return 1;
    size_t n = strlen(name);
    for (size_t i = 0; i < sizeof extensions / sizeof *extensions; i++) {
        size_t e = strlen(extensions[i]);
        if (n > e && strcasecmp(name + n - e, extensions[i]) == 0)
            return 1;
    }
    return 0;
}

/* Cuts the style suffixes off a family name ("DejaVu Sans:bold:italic",
 * ":weight=600"), in place, into *weight and *italic: 0, or 1 after an
 * error naming the bad suffix. */
static int style_suffixes(draw_state *s, char *name, int *weight, int *italic)
{
    *weight = 400;
    *italic = 0;
    char *colon = strchr(name, ':');
    if (!colon)
        return 0;
    *colon = '\0';
    for (char *p = colon + 1; p;) {
        char *next = strchr(p, ':');
        if (next)
            *next++ = '\0';
        int w;
        char extra;
        if (strcmp(p, "bold") == 0)
            *weight = 700;
        else if (strcmp(p, "italic") == 0 || strcmp(p, "oblique") == 0)
            *italic = 1;
        else if (strcmp(p, "regular") == 0 || strcmp(p, "normal") == 0)
            *weight = 400;
        else if (sscanf(p, "weight=%d%c", &w, &extra) == 1 && w >= 1 && w <= 1000)
            *weight = w;
        else
            return draw_error(s,
                              "unknown font style ':%s' (expected :bold, :italic, :regular or "
                              ":weight=1..1000 after the family)",
                              p);
        p = next;
    }
    return 0;
}

static int open_font(draw_state *s, char *name, cg_font **font)
{
    cg_error err;
    struct stat st;
    int is_file = stat(name, &st) == 0 && S_ISREG(st.st_mode);
    if (!is_file && looks_like_file(name))
        return draw_error(s, "cannot open the font file '%s': no such file", name);
    int weight = 400, italic = 0;
    if (!is_file && style_suffixes(s, name, &weight, &italic))
        return 1;
    if (!is_file && cg_font_family_exists(name, &err) != CG_OK)
        return draw_error(s,
                          "no font family '%s' is installed (expected a family fontconfig "
                          "knows, such as 'DejaVu Sans', a generic sans-serif, serif or "
                          "monospace, or a font file)",
                          name);
    if (cg_font_open(name, weight, italic, font, &err) != CG_OK)
        return draw_error(s, "cannot load the font '%s': %s", name, err.message);
    return 0;
}

/* font FAMILY-OR-FILE SIZE: the words before SIZE are the name. */
static int run_font(draw_state *s, int argc, char **argv)
{
    static const char *const usage = "font FAMILY-OR-FILE SIZE";
    if (argc < 3)
        return draw_error(s, "'font' expects a family or file and a size (%s), got %d argument%s",
                          usage, argc - 1, argc == 2 ? "" : "s");
    double size;
    if (draw_arg_double(s, argv[argc - 1], "SIZE", &size))
        return 1;
    if (!(size > 0) || size > 1e6)
        return draw_error(s, "expected a font SIZE in pixels > 0 and at most 1000000, got '%s'",
                          argv[argc - 1]);
    draw_text *t = text_of(s);
    char *name = t ? join_words(argv, 1, argc - 1) : NULL;
    if (!name)
        return out_of_memory(s);
    if (strlen(name) >= MAX_FONT_NAME || !*name) {
        free(name);
        return draw_error(s, "expected a font family or file name of 1 to %d bytes",
                          MAX_FONT_NAME - 1);
    }
    cg_font *font = NULL;
    int failed = open_font(s, name, &font);
    free(name);
    if (failed)
        return 1;
    cg_font_free(t->font);
    t->font = font;
    t->size = size;
    return 0;
}

static int run_align(draw_state *s, int argc, char **argv)
{
    static const char *const words[] = {"start", "middle", "end"}; /* = cg_text_align */
    draw_text *t = text_of(s);
    int align = 0;
    if (!t)
        return out_of_memory(s);
    if (draw_arg_keyword(s, argc, argv, "align start|middle|end", words, 3, &align))
        return 1;
    t->style.align = (cg_text_align)align;
    return 0;
}

static int run_baseline(draw_state *s, int argc, char **argv)
{
    static const char *const words[] = {"alphabetic", "top", "middle",
                                        "bottom"}; /* = cg_text_baseline */
    draw_text *t = text_of(s);
    int baseline = 0;
    if (!t)
        return out_of_memory(s);
    if (draw_arg_keyword(s, argc, argv, "baseline alphabetic|top|middle|bottom", words, 4,
                         &baseline))
        return 1;
    t->style.baseline = (cg_text_baseline)baseline;
    return 0;
}

static int run_wrap(draw_state *s, int argc, char **argv)
{
    double width;
    draw_text *t = text_of(s);
    if (!t)
        return out_of_memory(s);
    if (draw_arg_count(s, argc, argv, 1, "wrap WIDTH"))
        return 1;
    if (strcmp(argv[1], "off") == 0)
        width = 0;
    else if (draw_arg_nonnegative(s, argv[1], "WIDTH", &width))
        return 1;
    if (width > CG_FILL_MAX_COORD)
        return draw_error(s, "expected a wrapping WIDTH of at most 2^40 = 1099511627776, got '%s'",
                          argv[1]);
    t->style.width = width;
    return 0;
}

static int run_linespacing(draw_state *s, int argc, char **argv)
{
    double spacing;
    draw_text *t = text_of(s);
    if (!t)
        return out_of_memory(s);
    if (draw_arg_count(s, argc, argv, 1, "linespacing FACTOR")
        || draw_arg_double(s, argv[1], "FACTOR", &spacing))
        return 1;
    if (!(spacing > 0) || spacing > 1000)
        return draw_error(s, "expected a line spacing FACTOR > 0 and at most 1000, got '%s'",
                          argv[1]);
    t->style.line_spacing = spacing;
    return 0;
}

/* text X Y STRING: the words after Y, joined by single spaces, are the text. */
static int run_text(draw_state *s, int argc, char **argv)
{
    double x, y;
    if (argc < 4)
        return draw_error(s,
                          "'text' expects X, Y and a string (text X Y STRING), got %d argument%s",
                          argc - 1, argc == 2 ? "" : "s");
    if (draw_arg_double(s, argv[1], "X", &x) || draw_arg_double(s, argv[2], "Y", &y))
        return 1;
    if (!(x >= -CG_FILL_MAX_COORD && x <= CG_FILL_MAX_COORD && y >= -CG_FILL_MAX_COORD
          && y <= CG_FILL_MAX_COORD))
        return draw_error(s,
                          "X, Y = %s, %s is out of range: coordinates are at most 2^40 = "
                          "1099511627776 in magnitude",
                          argv[1], argv[2]);
    cg_image *canvas = draw_canvas(s);
    if (!canvas)
        return 1;
    draw_text *t = s->text;
    if (!t || !t->font)
        return draw_error(s, "'text' needs a font: expected a 'font FAMILY-OR-FILE SIZE' line "
                             "before it");
    cg_rasterizer *rasterizer = draw_fill_rasterizer(s);
    char *string = rasterizer ? join_words(argv, 3, argc) : NULL;
    if (!string)
        return out_of_memory(s);
    cg_text_paragraph style = t->style;
    style.size = t->size;
    cg_error err;
    cg_path_reset(t->path);
    cg_status status = cg_text_paragraph_path(t->font, string, &style, x, y, t->path, NULL, &err);
    free(string);
    if (status != CG_OK)
        return draw_error(s, "cannot lay out the text: %s", err.message);
    /* glyphs within 0.01 px of their curves: coverage within 0.4/255 of
     * the exact area (docs/text.md), unless the script asks for finer */
    double tolerance = s->tolerance < 0.001 ? 0.001 : s->tolerance;
    cg_rasterizer_set_tolerance(rasterizer,
                                tolerance < GLYPH_TOLERANCE ? tolerance : GLYPH_TOLERANCE);
    cg_paint paint = cg_paint_solid(s->color);
    return draw_check(
        s, cg_rasterizer_fill_path(rasterizer, canvas, t->path, CG_FILL_NONZERO, &paint));
}

static const draw_command commands[] = {
    {"font", "font FAMILY-OR-FILE SIZE", run_font},
    {"text", "text X Y STRING", run_text},
    {"align", "align start|middle|end", run_align},
    {"baseline", "baseline alphabetic|top|middle|bottom", run_baseline},
    {"wrap", "wrap WIDTH", run_wrap},
    {"linespacing", "linespacing FACTOR", run_linespacing},
};

const draw_command_table draw_commands_text = {"text", commands,
                                               (int)(sizeof commands / sizeof commands[0])};
