/* Style: presentation attributes, <style> sheets and style attributes,
 * cascaded onto each element's declared properties.
 *
 * Sheets are CSS rules "selectors { declarations }".  A selector is a
 * chain of compounds (a type or *, then .class and #id parts) joined by
 * descendant (blank) or child (>) combinators; a rule with anything else
 * (attribute selectors, pseudo-classes, sibling combinators) is skipped, as
 * are at-rules (@import is never fetched).  Rank, lowest first:
 * presentation attribute, sheet rule (by specificity, then order), style
 * attribute, !important sheet rule. */
#include "internal.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

static const char *const property_names[SVG_PROPERTY_COUNT] = {"fill",
                                                               "fill-opacity",
                                                               "fill-rule",
                                                               "stroke",
                                                               "stroke-width",
                                                               "stroke-opacity",
                                                               "stroke-linecap",
                                                               "stroke-linejoin",
                                                               "stroke-miterlimit",
                                                               "stroke-dasharray",
                                                               "stroke-dashoffset",
                                                               "opacity",
                                                               "color",
                                                               "display",
                                                               "visibility",
                                                               "clip-path",
                                                               "clip-rule",
                                                               "mask",
                                                               "stop-color",
                                                               "stop-opacity",
                                                               "paint-order",
                                                               "mix-blend-mode",
                                                               "filter",
                                                               "marker-start",
                                                               "marker-mid",
                                                               "marker-end",
                                                               "font-family",
                                                               "font-size",
                                                               "font-weight",
                                                               "font-style",
                                                               "text-anchor"};

#define RANK_ATTRIBUTE 1ULL
#define RANK_SHEET (2ULL << 48)
#define RANK_STYLE (3ULL << 48)
#define RANK_IMPORTANT (4ULL << 48)

svg_property svg_property_of(const char *name, size_t length)
{
    for (int i = 0; i < SVG_PROPERTY_COUNT; i++)
        if (strlen(property_names[i]) == length && strncmp(name, property_names[i], length) == 0)
            return (svg_property)i;
    return SVG_PROPERTY_COUNT;
}

/* A copy the document owns, for declarations to point into. */
static char *owned_copy(cg_svg *svg, const char *text, size_t length)
{
    char *copy = malloc(length + 1);
    if (!copy)
        return NULL;
    memcpy(copy, text, length);
    copy[length] = 0;
    if (core_array_push(&svg->strings, copy) != CG_OK) {
        free(copy);
        return NULL;
    }
    return copy;
}

static void declare(svg_node *node, svg_property property, const char *value,
                    unsigned long long rank)
{
    if (property < SVG_PROPERTY_COUNT && rank >= node->declared[property].rank) {
        node->declared[property].value = value;
        node->declared[property].rank = rank;
    }
}

static char *trim(char *s, char *end)
{
    while (s < end && isspace((unsigned char)*s))
        s++;
    while (end > s && isspace((unsigned char)end[-1]))
        end--;
    *end = 0;
    return s;
}

/* One declaration of a rule, parsed once. */
typedef struct css_declaration {
    svg_property property;
    const char *value;
    int important;
} css_declaration;

typedef CORE_ARRAY(css_declaration) css_declarations;

static int is_font_size(const char *word)
{
    static const char *const keywords[] = {"xx-small", "x-small", "small",    "medium",
                                           "large",    "x-large", "xx-large", "xxx-large",
                                           "larger",   "smaller"};
    if (isdigit((unsigned char)word[0]) || word[0] == '.')
        return 1;
    for (size_t i = 0; i < sizeof keywords / sizeof *keywords; i++)
        if (strcmp(word, keywords[i]) == 0)
            return 1;
    return 0;
}

/* A weight number: 1 to 1000 in digits alone ("700"). */
static int is_font_weight_number(const char *word)
{
    size_t n = strspn(word, "0123456789");
    return n > 0 && n <= 4 && !word[n] && atoi(word) >= 1 && atoi(word) <= 1000;
}

/* The CSS font shorthand ("italic bold 20px/1.2 'DejaVu Serif', serif"),
 * cut in place into font-style, font-weight, font-size and font-family;
 * the style and weight it leaves out are reset to normal, and variant,
 * stretch and line height are not read.  Returns how many properties it
 * gives: 4, or 0 when it has no size or no family after it (a system font
 * keyword, a malformed value). */
static int expand_font(char *value, svg_property *properties, const char **values)
{
    const char *style = "normal", *weight = "normal";
    char *p = value;
    for (;;) {
        while (isspace((unsigned char)*p))
            p++;
        char *word = p;
        while (*p && !isspace((unsigned char)*p))
            p++;
        if (word == p)
            return 0;
        int at_end = !*p;
        *p = 0;
        char *slash = strchr(word, '/');
        if (slash)
            *slash = 0;
        if (is_font_weight_number(word) && !slash) {
            weight = word;
        } else if (strcmp(word, "italic") == 0 || strcmp(word, "oblique") == 0) {
            style = word;
        } else if (strcmp(word, "bold") == 0 || strcmp(word, "bolder") == 0
                   || strcmp(word, "lighter") == 0) {
            weight = word;
        } else if (is_font_size(word)) {
            char *family = at_end ? p : p + 1;
            while (isspace((unsigned char)*family))
                family++;
            if (!*family)
                return 0;
            properties[0] = SVG_FONT_STYLE, values[0] = style;
            properties[1] = SVG_FONT_WEIGHT, values[1] = weight;
            properties[2] = SVG_FONT_SIZE, values[2] = word;
            properties[3] = SVG_FONT_FAMILY, values[3] = family;
            return 4;
        }
        if (at_end)
            return 0;
        p++;
    }
}

/* Parses "name: value; ..." in place (text is owned and writable): onto
 * node when it is set, else into list. */
static cg_status declare_in_place(char *text, svg_node *node, unsigned long long rank,
                                  unsigned long long important_rank, css_declarations *list)
{
    char *s = text;
    while (*s) {
        char *end = strchr(s, ';');
        if (!end)
            end = s + strlen(s);
        int last = *end == 0;
        char *colon = memchr(s, ':', (size_t)(end - s));
        if (colon) {
            char *name = trim(s, colon);
            char *value = trim(colon + 1, end);
            unsigned long long r = rank;
            char *bang = strstr(value, "!important");
            if (bang) {
                *bang = 0;
                value = trim(value, bang);
                r = important_rank;
            }
            svg_property properties[4] = {svg_property_of(name, strlen(name))};
            const char *values[4] = {value};
            int count = 1;
            if (properties[0] == SVG_PROPERTY_COUNT && strcmp(name, "font") == 0)
                count = expand_font(value, properties, values);
            for (int i = 0; i < count; i++) {
                if (node) {
                    declare(node, properties[i], values[i], r);
                } else if (properties[i] < SVG_PROPERTY_COUNT) {
                    css_declaration d = {properties[i], values[i],
                                         r == important_rank && bang != NULL};
                    if (core_array_push(list, d) != CG_OK)
                        return CG_ENOMEM;
                }
            }
        }
        if (last)
            break;
        s = end + 1;
    }
    return CG_OK;
}

cg_status svg_declare_list(cg_svg *svg, svg_node *node, const char *text, size_t length,
                           unsigned long long rank, unsigned long long important_rank)
{
    char *copy = owned_copy(svg, text, length);
    if (!copy)
        return CG_ENOMEM;
    return declare_in_place(copy, node, rank, important_rank, NULL);
}

/* ---- sheets ---------------------------------------------------------------------- */

#define CSS_MAX_COMPOUNDS 8
#define CSS_MAX_CLASSES 4

typedef struct css_compound {
    const char *type; /* NULL: any */
    const char *id;
    const char *classes[CSS_MAX_CLASSES];
    int class_count;
    int child; /* joined to the compound before it by '>' (else a blank) */
} css_compound;

typedef struct css_selector {
    css_compound parts[CSS_MAX_COMPOUNDS];
    int count;
    unsigned specificity; /* ids << 16 | classes << 8 | types */
} css_selector;

typedef struct css_rule {
    css_selector selector;
    size_t first, count; /* its declarations in the sheet's list */
    unsigned order;
} css_rule;

/* The style sheets' rules and their declarations; steps bounds the work
 * of matching selectors (elements times rules times ancestors). */
typedef struct css_sheet {
    CORE_ARRAY(css_rule) rules;
    css_declarations declarations;
    double steps;
} css_sheet;

/* At most this many rules in all sheets, and this many selector steps:
 * a hostile sheet on a large file cannot take minutes. */
#define CSS_MAX_RULES 100000
#define CSS_MAX_STEPS 2e8

static int name_char(char c)
{
    return isalnum((unsigned char)c) || c == '-' || c == '_' || (unsigned char)c >= 0x80;
}

/* Parses one selector (text written in place: names are cut out with NULs
 * in a copy); 0 when it uses something unsupported. */
static int parse_selector(char *s, css_selector *out)
{
    memset(out, 0, sizeof *out);
    int child = 0;
    for (;;) {
        while (isspace((unsigned char)*s))
            s++;
        if (!*s)
            break;
        if (*s == '>') {
            child = 1;
            s++;
            continue;
        }
        if (out->count == CSS_MAX_COMPOUNDS)
            return 0;
        css_compound *c = &out->parts[out->count++];
        c->child = child && out->count > 1;
        child = 0;
        if (*s == '*') {
            s++;
        } else if (name_char(*s)) {
            c->type = s;
            while (name_char(*s))
                s++;
            out->specificity += 1;
        }
        while (*s == '.' || *s == '#') {
            char kind = *s;
            *s++ = 0; /* ends the name before it */
            char *name = s;
            while (name_char(*s))
                s++;
            if (s == name)
                return 0;
            if (kind == '#') {
                c->id = name;
                out->specificity += 1 << 16;
            } else {
                if (c->class_count == CSS_MAX_CLASSES)
                    return 0;
                c->classes[c->class_count++] = name;
                out->specificity += 1 << 8;
            }
        }
        if (*s && !isspace((unsigned char)*s) && *s != '>')
            return 0; /* [attr], :pseudo, + or ~ */
        if (*s == '>') {
            *s++ = 0;
            child = 1;
        } else if (*s) {
            *s++ = 0;
        }
    }
    return out->count > 0;
}

static int has_class(const svg_node *node, const char *name)
{
    const char *list = svg_attribute_value(node, "class");
    size_t n = strlen(name);
    while (list && *list) {
        while (isspace((unsigned char)*list))
            list++;
        const char *end = list;
        while (*end && !isspace((unsigned char)*end))
            end++;
        if ((size_t)(end - list) == n && strncmp(list, name, n) == 0)
            return 1;
        list = end;
    }
    return 0;
}

static int compound_matches(const css_compound *c, const svg_node *node)
{
    if (c->type && strcmp(c->type, node->name) != 0)
        return 0;
    if (c->id) {
        const char *id = svg_attribute_value(node, "id");
        if (!id || strcmp(id, c->id) != 0)
            return 0;
    }
    for (int i = 0; i < c->class_count; i++)
        if (!has_class(node, c->classes[i]))
            return 0;
    return 1;
}

/* Right to left: the last compound on the node, each one before on its
 * parent (child) or the nearest matching ancestor (descendant). */
static int selector_matches(const css_selector *s, const svg_node *node, double *steps)
{
    int i = s->count - 1;
    *steps += 1;
    if (!compound_matches(&s->parts[i], node))
        return 0;
    const svg_node *at = node;
    for (; i > 0; i--) {
        const css_compound *before = &s->parts[i - 1];
        if (s->parts[i].child) {
            at = at->parent;
            if (!at || !compound_matches(before, at))
                return 0;
        } else {
            do {
                at = at->parent;
                *steps += 1;
            } while (at && !compound_matches(before, at));
            if (!at)
                return 0;
        }
    }
    return 1;
}

/* Skips a comment or a block from s (at '{'), returning what follows. */
static char *skip_block(char *s)
{
    int depth = 0;
    for (; *s; s++) {
        if (*s == '{')
            depth++;
        else if (*s == '}' && --depth <= 0)
            return s + 1;
    }
    return s;
}

static void strip_comments(char *s)
{
    char *w = s;
    while (*s) {
        if (s[0] == '/' && s[1] == '*') {
            char *end = strstr(s + 2, "*/");
            s = end ? end + 2 : s + strlen(s);
            continue;
        }
        *w++ = *s++;
    }
    *w = 0;
}

static cg_status parse_sheet(cg_svg *svg, svg_node *style, css_sheet *sheet)
{
    const char *type = svg_attribute_value(style, "type");
    if (type && *type && strcmp(type, "text/css") != 0)
        return CG_OK;
    if (!style->text)
        return CG_OK;
    char *text = owned_copy(svg, style->text, style->text_length);
    if (!text)
        return CG_ENOMEM;
    strip_comments(text);
    char *s = text;
    for (;;) {
        while (isspace((unsigned char)*s) || *s == ';')
            s++;
        if (!*s)
            break;
        if (*s == '@') { /* @media, @import, @font-face...: skipped */
            char *brace = strchr(s, '{'), *semi = strchr(s, ';');
            if (semi && (!brace || semi < brace))
                s = semi + 1;
            else
                s = brace ? skip_block(brace) : s + strlen(s);
            continue;
        }
        char *open = strchr(s, '{');
        if (!open)
            break;
        char *close = strchr(open, '}');
        if (!close)
            close = open + strlen(open);
        char *after = *close ? close + 1 : close;
        *open = 0;
        *close = 0;
        size_t first = sheet->declarations.count;
        if (declare_in_place(open + 1, NULL, 0, 1, &sheet->declarations) != CG_OK)
            return CG_ENOMEM;
        /* each selector of the list is a rule of its own */
        char *selector = s;
        while (selector) {
            char *comma = strchr(selector, ',');
            if (comma)
                *comma = 0;
            css_rule rule;
            rule.first = first;
            rule.count = sheet->declarations.count - first;
            rule.order = (unsigned)sheet->rules.count;
            if (sheet->rules.count >= CSS_MAX_RULES)
                return CG_ERANGE;
            if (rule.count && parse_selector(selector, &rule.selector)
                && core_array_push(&sheet->rules, rule) != CG_OK)
                return CG_ENOMEM;
            selector = comma ? comma + 1 : NULL;
        }
        s = after;
    }
    return CG_OK;
}

static cg_status gather_sheets(cg_svg *svg, svg_node *node, css_sheet *sheet)
{
    for (; node; node = node->next) {
        cg_status status = strcmp(node->name, "style") == 0
                               ? parse_sheet(svg, node, sheet)
                               : gather_sheets(svg, node->first_child, sheet);
        if (status != CG_OK)
            return status;
    }
    return CG_OK;
}

static cg_status cascade(cg_svg *svg, svg_node *node, css_sheet *sheet)
{
    for (; node; node = node->next) {
        for (int i = 0; i < node->attribute_count; i++) {
            const svg_attribute *a = &node->attributes[i];
            svg_property p = svg_property_of(a->name, strlen(a->name));
            if (p < SVG_PROPERTY_COUNT)
                declare(node, p, a->value, RANK_ATTRIBUTE);
        }
        for (size_t i = 0; i < sheet->rules.count; i++) {
            const css_rule *rule = &sheet->rules.data[i];
            if (!selector_matches(&rule->selector, node, &sheet->steps))
                continue;
            unsigned long long rank = (unsigned long long)rule->selector.specificity << 24
                                      | rule->order;
            for (size_t k = 0; k < rule->count; k++) {
                const css_declaration *d = &sheet->declarations.data[rule->first + k];
                declare(node, d->property, d->value,
                        (d->important ? RANK_IMPORTANT : RANK_SHEET) + rank);
            }
        }
        if (sheet->steps > CSS_MAX_STEPS)
            return CG_ERANGE;
        const char *style = svg_attribute_value(node, "style");
        if (style) {
            cg_status status = svg_declare_list(svg, node, style, strlen(style), RANK_STYLE,
                                                RANK_STYLE);
            if (status != CG_OK)
                return status;
        }
        cg_status status = cascade(svg, node->first_child, sheet);
        if (status != CG_OK)
            return status;
    }
    return CG_OK;
}

cg_status svg_apply_styles(cg_svg *svg, cg_error *err)
{
    css_sheet sheet;
    memset(&sheet, 0, sizeof sheet);
    cg_status status = gather_sheets(svg, svg->root, &sheet);
    if (status == CG_ERANGE)
        cg_error_set(err, status, "%s: more than %d style sheet rules", svg->name, CSS_MAX_RULES);
    else if (status == CG_OK && (status = cascade(svg, svg->root, &sheet)) == CG_ERANGE)
        cg_error_set(err, status,
                     "%s: the style sheets take more than %.0f selector steps on "
                     "this document",
                     svg->name, CSS_MAX_STEPS);
    free(sheet.rules.data);
    free(sheet.declarations.data);
    return status;
}
