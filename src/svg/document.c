/* SVG documents: loading (the XML, the style sheets, an index of ids, the
 * warnings about skipped content), the document's size, freeing. */
#include "internal.h"
#include "cg/fill.h"
#include "../core/sort.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void svg_warn(cg_svg *svg, const char *format, ...)
{
    char text[200];
    va_list args;
    va_start(args, format);
    vsnprintf(text, sizeof text, format, args);
    va_end(args);
    for (size_t i = 0; i < svg->warnings.count; i++)
        if (strcmp(svg->warnings.data[i], text) == 0)
            return;
    if (svg->warnings.count >= 100)
        return; /* enough to say what is missing */
    char *copy = malloc(strlen(text) + 1);
    if (!copy)
        return;
    strcpy(copy, text);
    if (core_array_push(&svg->warnings, copy) != CG_OK)
        free(copy);
}

int cg_svg_warning_count(const cg_svg *svg)
{
    return svg ? (int)svg->warnings.count : 0;
}

const char *cg_svg_warning(const cg_svg *svg, int index)
{
    if (!svg || index < 0 || (size_t)index >= svg->warnings.count)
        return NULL;
    return svg->warnings.data[index];
}

/* Elements drawn or used by reference; anything else is skipped. */
static const char *const known[] = {"svg",
                                    "g",
                                    "defs",
                                    "use",
                                    "symbol",
                                    "switch",
                                    "a",
                                    "path",
                                    "rect",
                                    "circle",
                                    "ellipse",
                                    "line",
                                    "polyline",
                                    "polygon",
                                    "linearGradient",
                                    "radialGradient",
                                    "stop",
                                    "clipPath",
                                    "mask",
                                    "image",
                                    "style",
                                    "title",
                                    "desc",
                                    "metadata",
                                    "text",
                                    "tspan",
                                    "#text"};

static const char *reason_for(const char *name)
{
    if (strcmp(name, "filter") == 0 || strncmp(name, "fe", 2) == 0)
        return "filter effects are not supported";
    if (strcmp(name, "textPath") == 0)
        return "text on a path is not supported";
    if (strncmp(name, "animate", 7) == 0 || strcmp(name, "set") == 0)
        return "animation is not supported (the static picture is drawn)";
    if (strcmp(name, "script") == 0)
        return "scripts are never run";
    if (strcmp(name, "foreignObject") == 0)
        return "foreign content is not drawn";
    if (strcmp(name, "pattern") == 0)
        return "pattern paint is not supported";
    if (strcmp(name, "marker") == 0)
        return "markers are not supported";
    return "unknown element";
}

static int compare_ids(const void *a, const void *b)
{
    const svg_node *x = *(const svg_node *const *)a, *y = *(const svg_node *const *)b;
    return strcmp(svg_attribute_value(x, "id"), svg_attribute_value(y, "id"));
}

/* Indexes ids and warns about unknown elements (each name once). */
static cg_status survey(cg_svg *svg, svg_node *node)
{
    for (; node; node = node->next) {
        int is_known = 0;
        for (size_t i = 0; i < sizeof known / sizeof *known; i++)
            is_known |= strcmp(node->name, known[i]) == 0;
        if (!is_known)
            svg_warn(svg, "skipped <%.40s>: %s", node->name, reason_for(node->name));
        if (svg_attribute_value(node, "id") && core_array_push(&svg->ids, node) != CG_OK)
            return CG_ENOMEM;
        cg_status status = survey(svg, node->first_child);
        if (status != CG_OK)
            return status;
    }
    return CG_OK;
}

/* Warnings about what the drawing will leave out or ignore, found once
 * here so that drawing never changes the document (two threads may draw
 * one document). */
static void review(cg_svg *svg, const svg_node *node)
{
    for (; node; node = node->next) {
        const svg_declared *d = node->declared;
        if (d[SVG_FILTER].value && strcmp(d[SVG_FILTER].value, "none") != 0)
            svg_warn(svg, "filter effects are not supported: drawn without them");
        for (int m = SVG_MARKER_START; m <= SVG_MARKER_END; m++)
            if (d[m].value && strcmp(d[m].value, "none") != 0)
                svg_warn(svg, "markers are not supported: drawn without them");
        const char *t = svg_attribute_value(node, "transform");
        cg_mat3 m;
        if (t && svg_transform(t, &m) != 0)
            svg_warn(svg, "line %d: malformed transform '%.40s' ignored", node->line, t);
        const char *href = svg_href(node);
        if (href && (strcmp(node->name, "use") == 0 || strcmp(node->name, "image") == 0)
            && *svg_skip(href, 0) != '#' && strncmp(svg_skip(href, 0), "data:", 5) != 0)
            svg_warn(svg, "skipped <%s> of '%.60s': other files are never read", node->name, href);
        if (strcmp(node->name, "path") == 0 && svg_attribute_value(node, "d")) {
            cg_path *path;
            cg_error err;
            if (cg_path_create(&path) == CG_OK) {
                if (cg_path_append_svg(path, svg_attribute_value(node, "d"), &err) != CG_OK)
                    svg_warn(svg, "line %d: %s (drawn up to the error)", node->line, err.message);
                cg_path_free(path);
            }
        }
        review(svg, node->first_child);
    }
}

const svg_node *svg_find_id(const cg_svg *svg, const char *id)
{
    size_t lo = 0, hi = svg->ids.count;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        int c = strcmp(svg_attribute_value(svg->ids.data[mid], "id"), id);
        if (c == 0) {
            /* the first of equal ids, as a browser takes it */
            while (mid > 0 && strcmp(svg_attribute_value(svg->ids.data[mid - 1], "id"), id) == 0)
                mid--;
            return svg->ids.data[mid];
        }
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return NULL;
}

const svg_node *svg_find_reference(const cg_svg *svg, const char *reference)
{
    if (!reference)
        return NULL;
    const char *s = svg_skip(reference, 0);
    char id[256];
    size_t n = 0;
    if (strncmp(s, "url(", 4) == 0) {
        s = svg_skip(s + 4, 0);
        char quote = (*s == '"' || *s == '\'') ? *s++ : 0;
        if (*s != '#')
            return NULL; /* another file: never fetched */
        s++;
        while (*s && *s != ')' && *s != quote && n + 1 < sizeof id)
            id[n++] = *s++;
        while (n > 0 && (id[n - 1] == ' ' || id[n - 1] == '\t'))
            n--;
    } else {
        if (*s != '#')
            return NULL;
        s++;
        while (*s && n + 1 < sizeof id)
            id[n++] = *s++;
    }
    id[n] = 0;
    return n ? svg_find_id(svg, id) : NULL;
}

/* The document's size: width and height (not percentages), else the
 * viewBox's, keeping its aspect when only one is given. */
static void document_size(cg_svg *svg)
{
    double box[4], w = -1, h = -1;
    int has_box = svg_view_box(svg_attribute_value(svg->root, "viewBox"), box) == 0;
    svg_viewport none = {100, 100};
    const char *ws = svg_attribute_value(svg->root, "width");
    const char *hs = svg_attribute_value(svg->root, "height");
    if (ws && !strchr(ws, '%'))
        w = svg_length_attribute(svg->root, "width", SVG_AXIS_X, &none, -1);
    if (hs && !strchr(hs, '%'))
        h = svg_length_attribute(svg->root, "height", SVG_AXIS_Y, &none, -1);
    if (!(w > 0) && !(h > 0)) {
        w = has_box ? box[2] : 100;
        h = has_box ? box[3] : 100;
    } else if (!(w > 0)) {
        w = has_box ? h * box[2] / box[3] : 100;
    } else if (!(h > 0)) {
        h = has_box ? w * box[3] / box[2] : 100;
    }
    svg->width = w;
    svg->height = h;
}

cg_status cg_svg_load_memory(const void *bytes, size_t size, const char *name, cg_svg **out,
                             cg_error *err)
{
    if (!out || (!bytes && size))
        return cg_error_set(err, CG_EINVAL, "cg_svg_load_memory: bad argument");
    *out = NULL;
    cg_svg *svg = calloc(1, sizeof *svg);
    if (!svg)
        return cg_error_set(err, CG_ENOMEM, "out of memory");
    snprintf(svg->name, sizeof svg->name, "%s", name ? name : "<memory>");
    cg_status status = svg_parse_xml(svg, bytes ? bytes : "", size, err);
    if (status == CG_OK && (status = survey(svg, svg->root)) == CG_OK) {
        core_sort(svg->ids.data, svg->ids.count, sizeof *svg->ids.data, compare_ids);
        status = svg_apply_styles(svg, err);
        if (status == CG_OK)
            review(svg, svg->root);
    }
    if (status != CG_OK) {
        if (err && err->status == CG_OK)
            cg_error_set(err, status, "%s: %s", svg->name, cg_status_str(status));
        cg_svg_free(svg);
        return status;
    }
    document_size(svg);
    *out = svg;
    return CG_OK;
}

cg_status cg_svg_load(const char *path, cg_svg **out, cg_error *err)
{
    if (!path || !out)
        return cg_error_set(err, CG_EINVAL, "cg_svg_load: bad argument");
    *out = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return cg_error_set(err, CG_EIO, "%s: cannot open: %s", path, strerror(errno));
    CORE_ARRAY(char) bytes = {0};
    char chunk[65536];
    size_t n;
    cg_status status = CG_OK;
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) {
        if (bytes.count + n > CG_SVG_MAX_BYTES) {
            status = cg_error_set(err, CG_ERANGE, "%s: larger than the limit of %u bytes", path,
                                  CG_SVG_MAX_BYTES);
            break;
        }
        if (core_array_reserve_for(&bytes, bytes.count + n) != CG_OK) {
            status = cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
            break;
        }
        memcpy(bytes.data + bytes.count, chunk, n);
        bytes.count += n;
    }
    if (status == CG_OK && ferror(f))
        status = cg_error_set(err, CG_EIO, "%s: read error", path);
    fclose(f);
    if (status == CG_OK)
        status = cg_svg_load_memory(bytes.data, bytes.count, path, out, err);
    free(bytes.data);
    return status;
}

void cg_svg_free(cg_svg *svg)
{
    if (!svg)
        return;
    svg_node_free(svg->root);
    free(svg->ids.data);
    for (size_t i = 0; i < svg->warnings.count; i++)
        free(svg->warnings.data[i]);
    free(svg->warnings.data);
    for (size_t i = 0; i < svg->strings.count; i++)
        free(svg->strings.data[i]);
    free(svg->strings.data);
    free(svg);
}

void cg_svg_size(const cg_svg *svg, double *width, double *height)
{
    if (width)
        *width = svg ? svg->width : 0;
    if (height)
        *height = svg ? svg->height : 0;
}
