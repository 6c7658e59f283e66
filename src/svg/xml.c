/* The element tree of an SVG file, read with expat.
 *
 * Names come from expat's namespace processing as "URI|local": elements of
 * the SVG namespace (or of none, as some files forget it) keep their local
 * name, elements of other namespaces (editor metadata) are dropped with
 * their contents, attributes keep their local name when unqualified and
 * become "xlink:NAME" in the XLink namespace; others are dropped.
 *
 * Refused: any entity declaration (internal ones allow exponential
 * expansion, external ones reading files), nesting deeper than
 * CG_SVG_MAX_DEPTH and more than CG_SVG_MAX_ELEMENTS elements. */
#include "internal.h"

#include <expat.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SVG_NAMESPACE "http://www.w3.org/2000/svg"
#define XLINK_NAMESPACE "http://www.w3.org/1999/xlink"

typedef struct xml_reader {
    cg_svg *svg;
    XML_Parser parser;
    svg_node *current; /* the open element, NULL before the root */
    int depth;         /* of open elements, the dropped ones included */
    int foreign_depth; /* > 0: inside an element of another namespace */
    long elements;
    cg_status failure; /* set when a handler stops the parser */
    char message[256];
} xml_reader;

static void stop(xml_reader *reader, cg_status status, const char *message)
{
    if (reader->failure == CG_OK) {
        reader->failure = status;
        snprintf(reader->message, sizeof reader->message, "%s", message);
    }
    XML_StopParser(reader->parser, XML_FALSE);
}

/* The local part of "URI|local" when URI is wanted (or there is none);
 * NULL for another namespace. */
static const char *local_name(const char *name, const char *wanted, int *no_namespace)
{
    const char *bar = strchr(name, '|');
    if (!bar) {
        if (no_namespace)
            *no_namespace = 1;
        return name;
    }
    size_t n = strlen(wanted);
    if ((size_t)(bar - name) == n && strncmp(name, wanted, n) == 0)
        return bar + 1;
    return NULL;
}

static char *copy_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *c = malloc(n);
    if (c)
        memcpy(c, s, n);
    return c;
}

static cg_status set_attributes(svg_node *node, const XML_Char **attributes)
{
    int count = 0;
    while (attributes[2 * count])
        count++;
    if (count == 0)
        return CG_OK;
    node->attributes = calloc((size_t)count, sizeof *node->attributes);
    if (!node->attributes)
        return CG_ENOMEM;
    for (int i = 0; i < count; i++) {
        const char *name = attributes[2 * i], *value = attributes[2 * i + 1];
        const char *local = local_name(name, "", NULL);
        char *kept = NULL;
        if (local && !strchr(name, '|')) {
            kept = copy_string(local);
        } else if ((local = local_name(name, XLINK_NAMESPACE, NULL)) != NULL) {
            kept = malloc(strlen(local) + 7);
            if (kept)
                sprintf(kept, "xlink:%s", local);
        } else {
            continue; /* another namespace: editor data */
        }
        char *v = copy_string(value);
        if (!kept || !v) {
            free(kept);
            free(v);
            return CG_ENOMEM;
        }
        node->attributes[node->attribute_count].name = kept;
        node->attributes[node->attribute_count].value = v;
        node->attribute_count++;
    }
    return CG_OK;
}

static void XMLCALL on_start(void *user, const XML_Char *name, const XML_Char **attributes)
{
    xml_reader *reader = user;
    if (++reader->depth > CG_SVG_MAX_DEPTH) {
        char m[96];
        snprintf(m, sizeof m, "elements nested deeper than %d", CG_SVG_MAX_DEPTH);
        stop(reader, CG_ERANGE, m);
        return;
    }
    if (++reader->elements > CG_SVG_MAX_ELEMENTS) {
        char m[96];
        snprintf(m, sizeof m, "more than %d elements", CG_SVG_MAX_ELEMENTS);
        stop(reader, CG_ERANGE, m);
        return;
    }
    if (reader->foreign_depth) {
        reader->foreign_depth++;
        return;
    }
    int no_namespace = 0;
    const char *local = local_name(name, SVG_NAMESPACE, &no_namespace);
    if (!local) {
        if (!reader->current) {
            stop(reader, CG_EFORMAT, "the root element is not an SVG <svg>");
            return;
        }
        reader->foreign_depth = 1;
        return;
    }
    if (!reader->current && (reader->svg->root || strcmp(local, "svg") != 0)) {
        char m[160];
        snprintf(m, sizeof m, "expected the root element <svg>, got <%.64s>", local);
        stop(reader, CG_EFORMAT, m);
        return;
    }
    svg_node *node = calloc(1, sizeof *node);
    if (!node || !(node->name = copy_string(local)) || set_attributes(node, attributes) != CG_OK) {
        svg_node_free(node);
        stop(reader, CG_ENOMEM, "out of memory");
        return;
    }
    node->line = (int)XML_GetCurrentLineNumber(reader->parser);
    node->parent = reader->current;
    if (reader->current) {
        if (reader->current->last_child)
            reader->current->last_child->next = node;
        else
            reader->current->first_child = node;
        reader->current->last_child = node;
    } else {
        reader->svg->root = node;
    }
    reader->current = node;
}

static void XMLCALL on_end(void *user, const XML_Char *name)
{
    (void)name;
    xml_reader *reader = user;
    reader->depth--;
    if (reader->foreign_depth) {
        reader->foreign_depth--;
        return;
    }
    if (reader->current)
        reader->current = reader->current->parent;
}

/* The "#text" child of a <text> or <tspan> that character data goes to:
 * its last child when that is one, else a new one (NULL when out of
 * memory, with the reader stopped). */
static svg_node *text_child(xml_reader *reader, svg_node *parent)
{
    if (parent->last_child && strcmp(parent->last_child->name, "#text") == 0)
        return parent->last_child;
    if (++reader->elements > CG_SVG_MAX_ELEMENTS) {
        char m[96];
        snprintf(m, sizeof m, "more than %d elements", CG_SVG_MAX_ELEMENTS);
        stop(reader, CG_ERANGE, m);
        return NULL;
    }
    svg_node *node = calloc(1, sizeof *node);
    if (!node || !(node->name = copy_string("#text"))) {
        svg_node_free(node);
        stop(reader, CG_ENOMEM, "out of memory");
        return NULL;
    }
    node->line = (int)XML_GetCurrentLineNumber(reader->parser);
    node->parent = parent;
    if (parent->last_child)
        parent->last_child->next = node;
    else
        parent->first_child = node;
    parent->last_child = node;
    return node;
}

/* Character data is kept for <style> (the sheets) and for <text> and
 * <tspan>, as "#text" children between their elements. */
static void XMLCALL on_text(void *user, const XML_Char *text, int length)
{
    xml_reader *reader = user;
    svg_node *node = reader->current;
    if (reader->foreign_depth || !node || length <= 0)
        return;
    if (strcmp(node->name, "text") == 0 || strcmp(node->name, "tspan") == 0)
        node = text_child(reader, node);
    else if (strcmp(node->name, "style") != 0)
        return;
    if (!node)
        return;
    char *grown = realloc(node->text, node->text_length + (size_t)length + 1);
    if (!grown) {
        stop(reader, CG_ENOMEM, "out of memory");
        return;
    }
    memcpy(grown + node->text_length, text, (size_t)length);
    node->text_length += (size_t)length;
    grown[node->text_length] = 0;
    node->text = grown;
}

static void XMLCALL on_entity(void *user, const XML_Char *name, int parameter,
                              const XML_Char *value, int value_length, const XML_Char *base,
                              const XML_Char *system_id, const XML_Char *public_id,
                              const XML_Char *notation)
{
    (void)parameter, (void)value, (void)value_length, (void)base, (void)public_id, (void)notation;
    char m[200];
    snprintf(m, sizeof m, "entity declaration '%.40s' refused: %s", name,
             system_id ? "external entities are never read"
                       : "entities could expand exponentially");
    stop(user, CG_EFORMAT, m);
}

cg_status svg_parse_xml(cg_svg *svg, const char *bytes, size_t size, cg_error *err)
{
    if (size > CG_SVG_MAX_BYTES)
        return cg_error_set(err, CG_ERANGE, "%s: %zu bytes is over the limit of %u", svg->name,
                            size, CG_SVG_MAX_BYTES);
    xml_reader reader;
    memset(&reader, 0, sizeof reader);
    reader.svg = svg;
    reader.parser = XML_ParserCreateNS(NULL, '|');
    if (!reader.parser)
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", svg->name);
    XML_SetUserData(reader.parser, &reader);
    XML_SetElementHandler(reader.parser, on_start, on_end);
    XML_SetCharacterDataHandler(reader.parser, on_text);
    XML_SetEntityDeclHandler(reader.parser, on_entity);
    XML_SetParamEntityParsing(reader.parser, XML_PARAM_ENTITY_PARSING_NEVER);
    enum XML_Status ok = XML_Parse(reader.parser, bytes, (int)size, XML_TRUE);
    cg_status status = CG_OK;
    long line = (long)XML_GetCurrentLineNumber(reader.parser);
    if (reader.failure != CG_OK)
        status = cg_error_set(err, reader.failure, "%s:%ld: %s", svg->name, line, reader.message);
    else if (ok != XML_STATUS_OK)
        status = cg_error_set(err, CG_EFORMAT, "%s:%ld: malformed XML: %s", svg->name, line,
                              XML_ErrorString(XML_GetErrorCode(reader.parser)));
    else if (!svg->root)
        status = cg_error_set(err, CG_EFORMAT, "%s: no <svg> element", svg->name);
    XML_ParserFree(reader.parser);
    return status;
}

void svg_node_free(svg_node *node)
{
    /* iteratively over siblings, recursively over children (depth is bounded) */
    while (node) {
        svg_node *next = node->next;
        svg_node_free(node->first_child);
        for (int i = 0; i < node->attribute_count; i++) {
            free(node->attributes[i].name);
            free(node->attributes[i].value);
        }
        free(node->attributes);
        free(node->name);
        free(node->text);
        free(node);
        node = next;
    }
}

const char *svg_attribute_value(const svg_node *node, const char *name)
{
    for (int i = 0; i < node->attribute_count; i++)
        if (strcmp(node->attributes[i].name, name) == 0)
            return node->attributes[i].value;
    return NULL;
}

const char *svg_href(const svg_node *node)
{
    const char *h = svg_attribute_value(node, "href");
    return h ? h : svg_attribute_value(node, "xlink:href");
}
