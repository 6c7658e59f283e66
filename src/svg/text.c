/* SVG text: a <text> element's character data and <tspan>s, laid out as
 * SVG 1.1 says (chapter 10) and drawn with cg's text module (cg/text.h).
 *
 * 1. The characters are collected in document order with the element that
 *    holds each (its computed style); white space is collapsed as with
 *    xml:space="default": every blank, tab and line break is a space, runs
 *    of spaces become one, and spaces at the start and end of the text go.
 * 2. The x, y, dx and dy lists of every element are given to its
 *    characters, the i-th value to the i-th character, an inner element's
 *    values over an outer one's.
 * 3. A span is a run of characters of one element with no position of its
 *    own after its first character; each is shaped with HarfBuzz in its
 *    font and placed at the current text position, which its advance then
 *    moves.  An absolute x or y starts a new text chunk; text-anchor (of
 *    the chunk's first character) shifts the chunk by half or all of its
 *    advance.
 * 4. Each span's glyph outlines are filled and stroked with its style, as
 *    a shape is. */
#include "internal.h"
#include "cg/text.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- fonts ------------------------------------------------------------------ */

typedef struct svg_font_entry {
    const char *family; /* the declared list (points into the document) */
    int weight, italic;
    cg_font *font; /* NULL: no font could be loaded */
} svg_font_entry;

struct svg_fonts {
    svg_font_entry *entries;
    size_t count, capacity;
};

void svg_fonts_free(svg_render *r)
{
    if (!r->fonts)
        return;
    for (size_t i = 0; i < r->fonts->count; i++)
        cg_font_free(r->fonts->entries[i].font);
    free(r->fonts->entries);
    free(r->fonts);
    r->fonts = NULL;
}

/* The next name of a font-family list from *p ("A, 'B C', serif"),
 * unquoted into name; 0 at the end. */
static int next_family(const char **p, char *name, size_t cap)
{
    const char *s = svg_skip(*p, 1);
    if (!*s)
        return 0;
    size_t n = 0;
    if (*s == '"' || *s == '\'') {
        char quote = *s++;
        while (*s && *s != quote) {
            if (n + 1 < cap)
                name[n++] = *s;
            s++;
        }
        if (*s)
            s++;
        while (*s && *s != ',')
            s++;
    } else {
        while (*s && *s != ',') {
            if (n + 1 < cap)
                name[n++] = *s;
            s++;
        }
        while (n > 0 && (name[n - 1] == ' ' || name[n - 1] == '\t' || name[n - 1] == '\n'))
            n--;
    }
    name[n] = '\0';
    *p = s;
    return 1;
}

/* The first family of the list that is installed (or generic), else what
 * fontconfig substitutes for the first one. */
static cg_font *open_family_list(const char *list, int weight, int italic)
{
    char name[256], first[256] = "serif";
    const char *p = list ? list : "serif";
    int index = 0;
    while (next_family(&p, name, sizeof name)) {
        if (!*name)
            continue;
        if (index++ == 0)
            memcpy(first, name, sizeof first);
        cg_font *font = NULL;
        if (cg_font_family_exists(name, NULL) == CG_OK
            && cg_font_open(name, weight, italic, &font, NULL) == CG_OK)
            return font;
    }
    cg_font *font = NULL;
    if (cg_font_open(first, weight, italic, &font, NULL) != CG_OK)
        font = NULL;
    return font;
}

static cg_font *font_for(svg_render *r, const svg_style *s)
{
    if (!r->fonts && !(r->fonts = calloc(1, sizeof *r->fonts))) {
        svg_fail(r, CG_ENOMEM, "out of memory");
        return NULL;
    }
    struct svg_fonts *f = r->fonts;
    for (size_t i = 0; i < f->count; i++) {
        svg_font_entry *e = &f->entries[i];
        if (e->weight == s->font_weight && e->italic == s->italic
            && (e->family == s->font_family
                || (e->family && s->font_family && strcmp(e->family, s->font_family) == 0)))
            return e->font;
    }
    if (core_array_reserve((void **)&f->entries, &f->capacity, f->count + 1, sizeof *f->entries)
        != CG_OK) {
        svg_fail(r, CG_ENOMEM, "out of memory");
        return NULL;
    }
    svg_font_entry *e = &f->entries[f->count++];
    e->family = s->font_family;
    e->weight = s->font_weight;
    e->italic = s->italic;
    e->font = open_family_list(s->font_family, s->font_weight, s->italic);
    return e->font;
}

/* ---- characters and their positions ---------------------------------------- */

enum { HAS_X = 1, HAS_Y = 2, HAS_DX = 4, HAS_DY = 8 };
/* Characters of one <text> element: a bound on a hostile file's memory
 * (about 50 bytes each) and time. */
#define SVG_MAX_TEXT_CHARS 1000000

typedef struct text_char {
    size_t byte;   /* offset of its UTF-8 bytes in the layout's text */
    int element;   /* index of the element holding it */
    int positions; /* HAS_X ... */
    double x, y, dx, dy;
} text_char;

typedef struct text_element {
    const svg_node *node;
    svg_style style;
    int start, end; /* its characters */
} text_element;

typedef struct text_layout {
    svg_render *r;
    const svg_viewport *vp;
    CORE_ARRAY(char) bytes;
    CORE_ARRAY(text_char) chars;
    CORE_ARRAY(text_element) elements;
    int failed;
} text_layout;

static void out_of_memory(text_layout *t)
{
    if (!t->failed)
        svg_fail(t->r, CG_ENOMEM, "out of memory");
    t->failed = 1;
}

/* Appends one character of n UTF-8 bytes held by element. */
static void add_char(text_layout *t, const char *bytes, size_t n, int element)
{
    text_char c = {t->bytes.count, element, 0, 0, 0, 0, 0};
    if (t->chars.count >= SVG_MAX_TEXT_CHARS) {
        if (!t->failed)
            svg_fail(t->r, CG_ERANGE, "a <text> element of more than %d characters",
                     SVG_MAX_TEXT_CHARS);
        t->failed = 1;
        return;
    }
    if (core_array_reserve((void **)&t->bytes.data, &t->bytes.capacity, t->bytes.count + n + 1, 1)
            != CG_OK
        || core_array_push(&t->chars, c) != CG_OK) {
        out_of_memory(t);
        return;
    }
    memcpy(t->bytes.data + t->bytes.count, bytes, n);
    t->bytes.count += n;
}

static int last_is_space(const text_layout *t)
{
    return t->chars.count > 0 && t->bytes.data[t->chars.data[t->chars.count - 1].byte] == ' ';
}

/* Character data, white space collapsed (expat gives valid UTF-8). */
static void add_text(text_layout *t, const char *s, size_t length, int element)
{
    for (size_t i = 0; i < length && !t->failed;) {
        unsigned char c = (unsigned char)s[i];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            if (t->chars.count > 0 && !last_is_space(t))
                add_char(t, " ", 1, element);
            i++;
            continue;
        }
        size_t n = c < 0x80 ? 1 : c < 0xe0 ? 2 : c < 0xf0 ? 3 : 4;
        if (i + n > length)
            n = length - i;
        add_char(t, s + i, n, element);
        i += n;
    }
}

static int displayed(const svg_node *node)
{
    const char *display = node->declared[SVG_DISPLAY].value;
    return !(display && strcmp(display, "none") == 0);
}

/* Collects the characters of node's children; element is node's index. */
static void collect(text_layout *t, const svg_node *node, int element)
{
    for (const svg_node *c = node->first_child; c && !t->failed; c = c->next) {
        if (strcmp(c->name, "#text") == 0) {
            add_text(t, c->text, c->text_length, element);
        } else if ((strcmp(c->name, "tspan") == 0 || strcmp(c->name, "a") == 0) && displayed(c)) {
            text_element e;
            memset(&e, 0, sizeof e);
            e.node = c;
            e.start = (int)t->chars.count;
            svg_compute_style(t->r, c, t->vp, &t->elements.data[element].style, &e.style);
            if (core_array_push(&t->elements, e) != CG_OK) {
                out_of_memory(t);
                return;
            }
            int index = (int)t->elements.count - 1;
            collect(t, c, index);
            t->elements.data[index].end = (int)t->chars.count;
        }
    }
}

/* Gives the values of node's attribute name (a list of lengths) to the
 * characters from start, at most up to end. */
static void give_positions(text_layout *t, const text_element *e, const char *name, int flag)
{
    const char *p = svg_attribute_value(e->node, name);
    svg_axis axis = name[strlen(name) - 1] == 'x' ? SVG_AXIS_X : SVG_AXIS_Y;
    for (int i = e->start; p && i < e->end; i++) {
        p = svg_skip(p, 1);
        const char *end = p;
        while (*end && *end != ',' && *end != ' ' && *end != '\t' && *end != '\n' && *end != '\r')
            end++;
        char word[64];
        size_t n = (size_t)(end - p);
        double v;
        if (n == 0 || n >= sizeof word)
            return;
        memcpy(word, p, n);
        word[n] = '\0';
        if (svg_length(word, axis, t->vp, &v) != 0)
            return; /* malformed: the rest of the list is ignored */
        text_char *c = &t->chars.data[i];
        c->positions |= flag;
        *(flag == HAS_X ? &c->x : flag == HAS_Y ? &c->y : flag == HAS_DX ? &c->dx : &c->dy) = v;
        p = end;
    }
}

/* ---- spans --------------------------------------------------------------------- */

typedef struct text_span {
    int first, last; /* characters [first, last) */
    int element;
    int chunk_start; /* it begins a text chunk */
    double x, y, advance;
    cg_font *font;
} text_span;

static int begins_span(const text_layout *t, int i)
{
    return i == 0 || t->chars.data[i].positions
           || t->chars.data[i].element != t->chars.data[i - 1].element;
}

/* The UTF-8 bytes of span, NUL-terminated in a scratch copy. */
static char *span_text(const text_layout *t, const text_span *s)
{
    size_t a = t->chars.data[s->first].byte;
    size_t b = s->last < (int)t->chars.count ? t->chars.data[s->last].byte : t->bytes.count;
    char *text = malloc(b - a + 1);
    if (text) {
        memcpy(text, t->bytes.data + a, b - a);
        text[b - a] = '\0';
    }
    return text;
}

/* Places every span: pen positions, advances, then each chunk's anchor. */
static void place_spans(text_layout *t, text_span *spans, int count)
{
    double pen_x = 0, pen_y = 0;
    for (int k = 0; k < count && !t->failed; k++) {
        text_span *s = &spans[k];
        const text_char *c = &t->chars.data[s->first];
        const svg_style *style = &t->elements.data[s->element].style;
        s->chunk_start = k == 0 || (c->positions & (HAS_X | HAS_Y));
        if (c->positions & HAS_X)
            pen_x = c->x;
        if (c->positions & HAS_Y)
            pen_y = c->y;
        if (c->positions & HAS_DX)
            pen_x += c->dx;
        if (c->positions & HAS_DY)
            pen_y += c->dy;
        s->x = pen_x;
        s->y = pen_y;
        s->advance = 0;
        s->font = style->font_size > 0 ? font_for(t->r, style) : NULL;
        char *text = s->font ? span_text(t, s) : NULL;
        if (s->font && !text)
            out_of_memory(t);
        if (text && cg_text_measure(s->font, text, style->font_size, &s->advance, NULL) != CG_OK)
            s->advance = 0;
        free(text);
        pen_x += s->advance;
    }
    for (int k = 0; k < count;) {
        int end = k + 1;
        while (end < count && !spans[end].chunk_start)
            end++;
        double width = spans[end - 1].x + spans[end - 1].advance - spans[k].x;
        int anchor = t->elements.data[spans[k].element].style.text_anchor;
        double shift = anchor == CG_TEXT_MIDDLE ? -width / 2 : anchor == CG_TEXT_END ? -width : 0;
        for (int i = k; i < end; i++)
            spans[i].x += shift;
        k = end;
    }
}

/* Appends span's outlines to path (user space): 1 when it has any. */
static int span_path(text_layout *t, const text_span *s, cg_path *path)
{
    const svg_style *style = &t->elements.data[s->element].style;
    char *text = s->font ? span_text(t, s) : NULL;
    if (s->font && !text)
        out_of_memory(t);
    int drawn = text
                && cg_text_run_path(s->font, text, style->font_size, s->x, s->y, CG_TEXT_START,
                                    CG_BASELINE_ALPHABETIC, path, NULL, NULL)
                       == CG_OK
                && !cg_path_is_empty(path);
    free(text);
    return drawn;
}

/* Draws the spans; gradients in objectBoundingBox units span the bounds
 * of the whole text (the union of its glyph outlines). */
static void draw_spans(text_layout *t, const text_span *spans, int count, cg_mat3 ctm,
                       double opacity, cg_image *target)
{
    cg_path *path = NULL;
    if (cg_path_create(&path) != CG_OK) {
        out_of_memory(t);
        return;
    }
    for (int k = 0; k < count && !t->failed; k++)
        span_path(t, &spans[k], path);
    cg_vec2 box[2];
    double tolerance = fmax(
        0.001, 0.01 / fmax(hypot(ctm.m[0][0], ctm.m[1][0]), hypot(ctm.m[0][1], ctm.m[1][1])));
    int has_box = !t->failed && cg_path_bounds(path, tolerance, &box[0], &box[1]) == CG_OK;
    for (int k = 0; has_box && k < count && !t->failed && t->r->failure == CG_OK; k++) {
        const svg_style *style = &t->elements.data[spans[k].element].style;
        if (!style->visible)
            continue;
        cg_path_reset(path);
        if (span_path(t, &spans[k], path))
            svg_paint_path(t->r, path, box, 0, ctm, t->vp, style, opacity, target);
    }
    cg_path_free(path);
}

void svg_draw_text(svg_render *r, const svg_node *node, cg_mat3 ctm, const svg_viewport *vp,
                   const svg_style *s, double opacity, cg_image *target)
{
    text_layout t;
    memset(&t, 0, sizeof t);
    t.r = r;
    t.vp = vp;
    text_element root = {node, *s, 0, 0};
    if (core_array_push(&t.elements, root) != CG_OK) {
        out_of_memory(&t);
        return;
    }
    collect(&t, node, 0);
    /* the text's trailing space goes; elements end at the last character */
    if (!t.failed && last_is_space(&t)) {
        t.chars.count--;
        t.bytes.count = t.chars.data[t.chars.count].byte;
    }
    t.elements.data[0].end = (int)t.chars.count;
    for (size_t i = 0; i < t.elements.count && !t.failed; i++) {
        text_element *e = &t.elements.data[i];
        if (e->end > (int)t.chars.count)
            e->end = (int)t.chars.count;
        give_positions(&t, e, "x", HAS_X);
        give_positions(&t, e, "y", HAS_Y);
        give_positions(&t, e, "dx", HAS_DX);
        give_positions(&t, e, "dy", HAS_DY);
    }
    int count = 0;
    for (size_t i = 0; i < t.chars.count; i++)
        count += begins_span(&t, (int)i);
    text_span *spans = !t.failed && count ? calloc((size_t)count, sizeof *spans) : NULL;
    if (count && !spans)
        out_of_memory(&t);
    if (spans) {
        int k = -1;
        for (int i = 0; i < (int)t.chars.count; i++) {
            if (begins_span(&t, i)) {
                spans[++k].first = i;
                spans[k].element = t.chars.data[i].element;
            }
            spans[k].last = i + 1;
        }
        place_spans(&t, spans, count);
        if (!t.failed)
            draw_spans(&t, spans, count, ctm, opacity, target);
    }
    free(spans);
    free(t.bytes.data);
    free(t.chars.data);
    free(t.elements.data);
}
