/* PLY reader: ASCII, binary little-endian and binary big-endian; properties
 * in any order and of any type; list properties with any count and index
 * types; elements and properties cg does not use are read past.
 *
 * The header is parsed into a small table of elements and properties; each
 * property of the vertex and face elements gets a destination (x, y, z,
 * normal, texture coordinate, colour, corner list) or none.  The body is then
 * read element by element in one pass, each value checked against the bytes
 * that remain, so that a header count never causes an allocation larger than
 * what the file holds. */
#include "internal.h"

#include <stdio.h>
#include <stdlib.h>

enum ply_type {
    PLY_NONE,
    PLY_INT8,
    PLY_UINT8,
    PLY_INT16,
    PLY_UINT16,
    PLY_INT32,
    PLY_UINT32,
    PLY_FLOAT32,
    PLY_FLOAT64
};
static const unsigned char type_size[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};

enum ply_target {
    T_SKIP,
    T_X,
    T_Y,
    T_Z,
    T_NX,
    T_NY,
    T_NZ,
    T_U,
    T_V,
    T_R,
    T_G,
    T_B,
    T_A,
    T_CORNERS
};

typedef struct ply_property {
    enum ply_type type;       /* value type, or the list's index type */
    enum ply_type count_type; /* PLY_NONE unless a list */
    enum ply_target target;
} ply_property;

enum ply_kind { E_OTHER, E_VERTEX, E_FACE };

#define PLY_MAX_PROPERTIES 256
#define PLY_MAX_ELEMENTS 256

typedef struct ply_element {
    enum ply_kind kind;
    uint64_t count;
    size_t first_property, property_count;
    size_t header_line;
    char name[32]; /* for messages; longer names are cut */
} ply_element;

enum ply_format { PLY_ASCII, PLY_LITTLE, PLY_BIG };

typedef struct ply_reader {
    const char *name;
    cg_error *err;
    enum ply_format format;
    ply_element elements[PLY_MAX_ELEMENTS];
    size_t element_count;
    ply_property properties[PLY_MAX_PROPERTIES];
    size_t property_count;
    mesh_builder b;
    int vertices_read; /* the vertex element came before: indices checkable at once */
} ply_reader;

static enum ply_type parse_type(const char *word, size_t length)
{
    static const struct {
        const char *name;
        enum ply_type type;
    } names[] = {{"char", PLY_INT8},      {"int8", PLY_INT8},       {"uchar", PLY_UINT8},
                 {"uint8", PLY_UINT8},    {"short", PLY_INT16},     {"int16", PLY_INT16},
                 {"ushort", PLY_UINT16},  {"uint16", PLY_UINT16},   {"int", PLY_INT32},
                 {"int32", PLY_INT32},    {"uint", PLY_UINT32},     {"uint32", PLY_UINT32},
                 {"float", PLY_FLOAT32},  {"float32", PLY_FLOAT32}, {"double", PLY_FLOAT64},
                 {"float64", PLY_FLOAT64}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strlen(names[i].name) == length && memcmp(names[i].name, word, length) == 0)
            return names[i].type;
    return PLY_NONE;
}

static enum ply_target vertex_target(const char *word, size_t length)
{
    static const struct {
        const char *name;
        enum ply_target target;
    } names[] = {{"x", T_X},
                 {"y", T_Y},
                 {"z", T_Z},
                 {"nx", T_NX},
                 {"ny", T_NY},
                 {"nz", T_NZ},
                 {"u", T_U},
                 {"v", T_V},
                 {"s", T_U},
                 {"t", T_V},
                 {"texture_u", T_U},
                 {"texture_v", T_V},
                 {"texture_s", T_U},
                 {"texture_t", T_V},
                 {"red", T_R},
                 {"green", T_G},
                 {"blue", T_B},
                 {"alpha", T_A},
                 {"diffuse_red", T_R},
                 {"diffuse_green", T_G},
                 {"diffuse_blue", T_B},
                 {"r", T_R},
                 {"g", T_G},
                 {"b", T_B}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strlen(names[i].name) == length && memcmp(names[i].name, word, length) == 0)
            return names[i].target;
    return T_SKIP;
}

static int word_is(const char *word, size_t length, const char *keyword)
{
    return strlen(keyword) == length && memcmp(word, keyword, length) == 0;
}

/* Moves t to the next word on the line; returns its length (0 at line end). */
static size_t next_word(text_cursor *t, const char **word)
{
    text_skip_blanks(t);
    *word = t->p;
    while (t->p < t->end && !is_space(*t->p))
        t->p++;
    return (size_t)(t->p - *word);
}

static cg_status header_fail(ply_reader *r, text_cursor *t, const char *what)
{
    return text_expected(t, what, r->err);
}

/* Parses the header; *body is where the data starts. */
/* The header's 'format' line, after the keyword. */
static cg_status read_format_line(ply_reader *r, text_cursor *t)
{
    const char *word;
    size_t length = next_word(t, &word);
    if (word_is(word, length, "ascii"))
        r->format = PLY_ASCII;
    else if (word_is(word, length, "binary_little_endian"))
        r->format = PLY_LITTLE;
    else if (word_is(word, length, "binary_big_endian"))
        r->format = PLY_BIG;
    else {
        t->p = word;
        return header_fail(r, t, "ascii, binary_little_endian or binary_big_endian");
    }
    length = next_word(t, &word);
    if (!word_is(word, length, "1.0")) {
        t->p = word;
        return header_fail(r, t, "version 1.0");
    }
    return CG_OK;
}

/* An 'element' line, after the keyword: name and count. */
static cg_status read_element_line(ply_reader *r, text_cursor *t)
{
    if (r->element_count == PLY_MAX_ELEMENTS)
        return cg_error_set(r->err, CG_EFORMAT, "%s:%zu: more than %d elements", r->name, t->line,
                            PLY_MAX_ELEMENTS);
    ply_element *e = &r->elements[r->element_count];
    const char *word;
    size_t length = next_word(t, &word);
    if (length == 0)
        return header_fail(r, t, "an element name");
    size_t kept = length < sizeof e->name - 1 ? length : sizeof e->name - 1;
    for (size_t i = 0; i < kept; i++)
        e->name[i] = word[i] >= 0x20 && word[i] < 0x7f ? word[i] : '?';
    e->name[kept] = '\0';
    e->kind = word_is(word, length, "vertex") ? E_VERTEX
              : word_is(word, length, "face") ? E_FACE
                                              : E_OTHER;
    for (size_t i = 0; i < r->element_count; i++)
        if (e->kind != E_OTHER && r->elements[i].kind == e->kind)
            return cg_error_set(r->err, CG_EFORMAT, "%s:%zu: a second '%s' element", r->name,
                                t->line, e->kind == E_VERTEX ? "vertex" : "face");
    text_skip_blanks(t);
    int64_t count;
    if (!parse_int64(&t->p, t->end, &count) || count < 0)
        return header_fail(r, t, "an element count (a whole number, 0 or more)");
    e->count = (uint64_t)count;
    e->first_property = r->property_count;
    e->property_count = 0;
    e->header_line = t->line;
    r->element_count++;
    return CG_OK;
}

/* What a property named word feeds, in an element of the given kind. */
static enum ply_target property_target(enum ply_kind kind, const ply_property *p, const char *word,
                                       size_t length)
{
    if (kind == E_VERTEX && !p->count_type)
        return vertex_target(word, length);
    if (kind == E_FACE && p->count_type
        && (word_is(word, length, "vertex_indices") || word_is(word, length, "vertex_index")))
        return p->type >= PLY_FLOAT32 ? T_SKIP : T_CORNERS;
    if (kind == E_FACE && !p->count_type)
        return vertex_target(word, length) >= T_R ? vertex_target(word, length) : T_SKIP;
    return T_SKIP;
}

/* A 'property' line, after the keyword: [list count-type] type name. */
static cg_status read_property_line(ply_reader *r, text_cursor *t)
{
    if (r->element_count == 0)
        return cg_error_set(r->err, CG_EFORMAT, "%s:%zu: expected 'element' before 'property'",
                            r->name, t->line);
    if (r->property_count == PLY_MAX_PROPERTIES)
        return cg_error_set(r->err, CG_EFORMAT, "%s:%zu: more than %d properties", r->name, t->line,
                            PLY_MAX_PROPERTIES);
    ply_element *e = &r->elements[r->element_count - 1];
    ply_property *p = &r->properties[r->property_count];
    memset(p, 0, sizeof *p);
    const char *word;
    size_t length = next_word(t, &word);
    if (word_is(word, length, "list")) {
        length = next_word(t, &word);
        p->count_type = parse_type(word, length);
        if (p->count_type == PLY_NONE || p->count_type >= PLY_FLOAT32) {
            t->p = word;
            return header_fail(r, t, "an integer type for the list count");
        }
        length = next_word(t, &word);
    }
    p->type = parse_type(word, length);
    if (p->type == PLY_NONE) {
        t->p = word;
        return header_fail(r, t,
                           "a property type (char, uchar, short, ushort, int, "
                           "uint, float, double or int8 ... float64)");
    }
    length = next_word(t, &word);
    if (length == 0)
        return header_fail(r, t, "a property name");
    p->target = property_target(e->kind, p, word, length);
    for (size_t i = e->first_property; i < r->property_count; i++)
        if (p->target != T_SKIP && r->properties[i].target == p->target)
            p->target = T_SKIP; /* a repeated name: the first one counts */
    r->property_count++;
    e->property_count++;
    return CG_OK;
}

/* After the header: some 'vertex' element has x, y and z. */
static cg_status check_vertex_xyz(ply_reader *r)
{
    int has_xyz[3] = {0, 0, 0};
    for (size_t i = 0; i < r->element_count; i++) {
        if (r->elements[i].kind != E_VERTEX)
            continue;
        for (size_t k = 0; k < r->elements[i].property_count; k++) {
            enum ply_target tg = r->properties[r->elements[i].first_property + k].target;
            if (tg >= T_X && tg <= T_Z)
                has_xyz[tg - T_X] = 1;
        }
    }
    if (!has_xyz[0] || !has_xyz[1] || !has_xyz[2])
        return cg_error_set(r->err, CG_EFORMAT,
                            "%s: expected a 'vertex' element with properties x, y and z", r->name);
    return CG_OK;
}

static cg_status read_header(ply_reader *r, const unsigned char *bytes, size_t size, size_t *body,
                             size_t *body_line)
{
    text_cursor t = {(const char *)bytes, (const char *)bytes + size, r->name, 1};
    const char *word;
    size_t length = next_word(&t, &word);
    if (!word_is(word, length, "ply"))
        return cg_error_set(r->err, CG_EFORMAT, "%s:1: expected 'ply' as the first line", r->name);
    int have_format = 0;
    cg_status s = CG_OK;
    for (;;) {
        if (!text_at_line_end(&t))
            return header_fail(r, &t, "the end of the line");
        if (t.p >= t.end)
            return cg_error_set(r->err, CG_EFORMAT,
                                "%s:%zu: expected 'end_header', the file ends first", r->name,
                                t.line);
        text_next_line(&t);
        length = next_word(&t, &word);
        if (length == 0)
            continue; /* blank line, or the end of the file */
        if (word_is(word, length, "comment") || word_is(word, length, "obj_info")) {
            while (t.p < t.end && !is_line_end(*t.p))
                t.p++;
        } else if (word_is(word, length, "format")) {
            s = read_format_line(r, &t);
            have_format = 1;
        } else if (word_is(word, length, "element")) {
            s = read_element_line(r, &t);
        } else if (word_is(word, length, "property")) {
            s = read_property_line(r, &t);
        } else if (word_is(word, length, "end_header")) {
            if (!text_at_line_end(&t) || (t.p < t.end && *t.p == '#'))
                return header_fail(r, &t, "the end of the line after 'end_header'");
            /* the body starts after exactly one line end */
            if (t.p < t.end && *t.p == '\r')
                t.p++;
            if (t.p < t.end && *t.p == '\n')
                t.p++;
            *body = (size_t)(t.p - (const char *)bytes);
            *body_line = t.line + 1;
            break;
        } else {
            t.p = word;
            return header_fail(r, &t,
                               "a header keyword (format, element, property, comment, "
                               "end_header)");
        }
        if (s != CG_OK)
            return s;
    }
    if (!have_format)
        return cg_error_set(r->err, CG_EFORMAT, "%s: expected a 'format' line in the header",
                            r->name);
    return check_vertex_xyz(r);
}

/* ---- destinations -------------------------------------------------------- */

/* Which optional arrays the vertex and face properties fill. */
static unsigned wanted_arrays(const ply_reader *r)
{
    unsigned flags = 0;
    for (size_t i = 0; i < r->element_count; i++) {
        const ply_element *e = &r->elements[i];
        for (size_t k = 0; k < e->property_count; k++) {
            enum ply_target tg = r->properties[e->first_property + k].target;
            if (e->kind == E_VERTEX && tg >= T_NX && tg <= T_NZ)
                flags |= CG_MESH_NORMALS;
            if (e->kind == E_VERTEX && (tg == T_U || tg == T_V))
                flags |= CG_MESH_TEXCOORDS;
            if (e->kind == E_VERTEX && tg >= T_R && tg <= T_B)
                flags |= CG_MESH_COLORS;
            if (e->kind == E_FACE && tg >= T_R && tg <= T_B)
                flags |= CG_MESH_FACE_COLORS;
        }
    }
    return flags;
}

/* Stores one scalar value of a vertex (or face colour) property. */
static void store(ply_reader *r, enum ply_target target, enum ply_type type, double value, size_t i,
                  int face)
{
    mesh_builder *b = &r->b;
    int is_float = type >= PLY_FLOAT32;
    if (face) {
        if (!b->face_colors) /* no colour, or alpha alone */
            return;
        cg_rgbaf *c = &b->face_colors[i];
        switch (target) {
        case T_R: c->r = mesh_color_component(value, is_float, 0); break;
        case T_G: c->g = mesh_color_component(value, is_float, 0); break;
        case T_B: c->b = mesh_color_component(value, is_float, 0); break;
        case T_A: c->a = mesh_color_component(value, is_float, 1); break;
        default: break;
        }
        return;
    }
    switch (target) {
    case T_X: b->positions[i].x = value; break;
    case T_Y: b->positions[i].y = value; break;
    case T_Z: b->positions[i].z = value; break;
    case T_NX: b->normals[i].x = value; break;
    case T_NY: b->normals[i].y = value; break;
    case T_NZ: b->normals[i].z = value; break;
    case T_U: b->texcoords[i].x = value; break;
    case T_V: b->texcoords[i].y = value; break;
    case T_R:
        if (b->colors)
            b->colors[i].r = mesh_color_component(value, is_float, 0);
        break;
    case T_G:
        if (b->colors)
            b->colors[i].g = mesh_color_component(value, is_float, 0);
        break;
    case T_B:
        if (b->colors)
            b->colors[i].b = mesh_color_component(value, is_float, 0);
        break;
    case T_A:
        if (b->colors)
            b->colors[i].a = mesh_color_component(value, is_float, 1);
        break;
    default: break;
    }
}

/* Starts vertex / face i of an element (defaults for what it may not set). */
static cg_status begin_item(ply_reader *r, enum ply_kind kind)
{
    mesh_builder *b = &r->b;
    if (kind == E_VERTEX)
        return builder_push_vertex(b, cg_vec3_make(0, 0, 0), NULL);
    cg_status s = builder_reserve_faces(b, 1);
    if (s == CG_OK && b->face_colors) {
        cg_rgbaf white = {1, 1, 1, 1};
        b->face_colors[b->face_count] = white;
    }
    return s;
}

/* Closes the face whose corners were just read. */
static cg_status finish_face(ply_reader *r)
{
    if (builder_open_corners(&r->b) == 0)
        return cg_error_set(r->err, CG_EFORMAT, "%s: the face element has no vertex_indices list",
                            r->name);
    if (builder_end_face(&r->b) != CG_OK)
        return cg_error_set(r->err, CG_ENOMEM, "%s: out of memory", r->name);
    return CG_OK;
}

static int valid_integer(enum ply_type type, double value)
{
    return type < PLY_FLOAT32 && value == floor(value);
}

/* Range of an integer type. */
static void type_range(enum ply_type type, double *lo, double *hi)
{
    static const double los[] = {0, -128, 0, -32768, 0, -2147483648.0, 0, 0, 0};
    static const double his[] = {0, 127, 255, 32767, 65535, 2147483647.0, 4294967295.0, 0, 0};
    *lo = los[type];
    *hi = his[type];
}

/* Fails when the vertex just read has a coordinate that is not finite; line
 * (ASCII) or byte (binary, line 0) says where the vertex is. */
static cg_status check_vertex(ply_reader *r, size_t line, size_t byte)
{
    cg_vec3 p = r->b.positions[r->b.vertex_count - 1];
    if (mesh_nonfinite_axis(p) < 0)
        return CG_OK;
    char item[40];
    snprintf(item, sizeof item, "vertex %zu", r->b.vertex_count - 1);
    return mesh_nonfinite_error(r->err, r->name, line, byte, line ? NULL : item, p);
}

/* ---- ASCII body ------------------------------------------------------------ */

static cg_status ascii_fail(ply_reader *r, text_cursor *t, const char *what, uint64_t item,
                            const char *element)
{
    char buffer[40];
    return cg_error_set(r->err, CG_EFORMAT, "%s:%zu: expected %s of %s %llu, got %s", r->name,
                        t->line, what, element, (unsigned long long)item, text_describe(t, buffer));
}

/* Reads one number of the given type, skipping blanks and line ends. */
static int ascii_value(text_cursor *t, enum ply_type type, double *value)
{
    const char *p = t->p, *end = t->end;
    while (p < end && is_space(*p)) {
        if (*p == '\n' || (*p == '\r' && (p + 1 == end || p[1] != '\n')))
            t->line++;
        p++;
    }
    t->p = p;
    if (p >= end)
        return 0;
    double lo, hi;
    if (type < PLY_FLOAT32) {
        type_range(type, &lo, &hi);
        int64_t i;
        if (parse_int64(&t->p, end, &i)) {
            *value = (double)i;
            if (*value >= lo && *value <= hi)
                return 1;
            t->p = p;
            return 0;
        }
    }
    if (!parse_double(&t->p, end, value))
        return 0;
    /* an integer property written as "3.0" is still a whole number */
    if (type >= PLY_FLOAT32 || (valid_integer(type, *value) && *value >= lo && *value <= hi))
        return 1;
    t->p = p; /* the message shows the number */
    return 0;
}

static const char *kind_name(const ply_element *e)
{
    return e->name;
}

static cg_status read_ascii(ply_reader *r, const unsigned char *bytes, size_t size, size_t body,
                            size_t line)
{
    text_cursor t = {(const char *)bytes + body, (const char *)bytes + size, r->name, line};
    static const char *const type_word[] = {"",           "an integer", "an integer",
                                            "an integer", "an integer", "an integer",
                                            "an integer", "a number",   "a number"};
    for (size_t ei = 0; ei < r->element_count; ei++) {
        ply_element *e = &r->elements[ei];
        const ply_property *props = &r->properties[e->first_property];
        if (e->property_count == 0) {
            if (e->kind == E_FACE && e->count)
                return cg_error_set(r->err, CG_EFORMAT,
                                    "%s: the face element has no vertex_indices list", r->name);
            continue; /* items without properties take no text */
        }
        /* each item takes at least 2 bytes a value ("0 "), a face's corner list
         * at least 4 values: reserve no more than the text left can hold */
        size_t least = 2 * e->property_count;
        for (size_t k = 0; k < e->property_count; k++)
            least += props[k].target == T_CORNERS ? 6 : 0;
        size_t room = (size_t)(t.end - t.p) / least;
        size_t guess = e->count < room ? (size_t)e->count : room;
        if (e->kind == E_VERTEX && builder_reserve_vertices(&r->b, guess) != CG_OK)
            return cg_error_set(r->err, CG_ENOMEM, "%s: out of memory", r->name);
        if (e->kind == E_FACE
            && (builder_reserve_faces(&r->b, guess) != CG_OK
                || builder_reserve_indices(&r->b, guess * 3) != CG_OK))
            return cg_error_set(r->err, CG_ENOMEM, "%s: out of memory", r->name);
        for (uint64_t item = 0; item < e->count; item++) {
            if (e->kind != E_OTHER && begin_item(r, e->kind) != CG_OK)
                return cg_error_set(r->err, CG_ERANGE, "%s:%zu: too many items for cg_mesh",
                                    r->name, t.line);
            for (size_t k = 0; k < e->property_count; k++) {
                const ply_property *p = &props[k];
                double value;
                if (!p->count_type) {
                    if (!ascii_value(&t, p->type, &value))
                        return ascii_fail(r, &t, type_word[p->type], item, kind_name(e));
                    if (e->kind != E_OTHER)
                        store(r, p->target, p->type, value,
                              e->kind == E_FACE ? r->b.face_count : r->b.vertex_count - 1,
                              e->kind == E_FACE);
                    continue;
                }
                if (!ascii_value(&t, p->count_type, &value))
                    return ascii_fail(r, &t, "a list length (a whole number, 0 or more)", item,
                                      kind_name(e));
                if (value < 0) /* a signed count type: converting it would be undefined */
                    return cg_error_set(r->err, CG_EFORMAT,
                                        "%s:%zu: expected a list length of 0 or more in %s "
                                        "%llu, got %.0f",
                                        r->name, t.line, kind_name(e), (unsigned long long)item,
                                        value);
                uint64_t n = (uint64_t)value;
                if (p->target == T_CORNERS && n < 3)
                    return cg_error_set(r->err, CG_EFORMAT,
                                        "%s:%zu: expected a face of at least 3 vertices, face "
                                        "%llu has %llu",
                                        r->name, t.line, (unsigned long long)item,
                                        (unsigned long long)n);
                for (uint64_t j = 0; j < n; j++) {
                    if (!ascii_value(&t, p->type, &value))
                        return ascii_fail(
                            r, &t, p->target == T_CORNERS ? "a vertex index" : type_word[p->type],
                            item, kind_name(e));
                    if (p->target != T_CORNERS)
                        continue;
                    if (value < 0 || (r->vertices_read && value >= (double)r->b.vertex_count))
                        return cg_error_set(r->err, CG_EFORMAT,
                                            "%s:%zu: face %llu refers to vertex %.0f, but there "
                                            "are %zu vertices",
                                            r->name, t.line, (unsigned long long)item, value,
                                            r->b.vertex_count);
                    if (value > CG_MESH_MAX_VERTICES
                        || builder_push_index(&r->b, (uint32_t)value) != CG_OK)
                        return cg_error_set(r->err, CG_ERANGE,
                                            "%s:%zu: too many face corners for cg_mesh", r->name,
                                            t.line);
                }
            }
            if (e->kind == E_FACE) {
                cg_status status = finish_face(r);
                if (status != CG_OK)
                    return status;
            }
            if (e->kind == E_VERTEX && check_vertex(r, t.line, 0) != CG_OK)
                return r->err ? r->err->status : CG_EFORMAT;
        }
        if (e->kind == E_VERTEX)
            r->vertices_read = 1;
    }
    text_skip_space_and_comments(&t);
    if (t.p < t.end)
        return text_expected(&t, "the end of the file after the last element", r->err);
    return CG_OK;
}

/* ---- binary body ----------------------------------------------------------- */

static inline uint64_t load_bits(const unsigned char *p, size_t n, int big)
{
    uint64_t v = 0;
    if (big)
        for (size_t i = 0; i < n; i++)
            v = v << 8 | p[i];
    else
        for (size_t i = n; i-- > 0;)
            v = v << 8 | p[i];
    return v;
}

static inline double binary_value(const unsigned char *p, enum ply_type type, int big)
{
    uint64_t bits = load_bits(p, type_size[type], big);
    switch (type) {
    case PLY_INT8: return (double)(int8_t)bits;
    case PLY_UINT8: return (double)(uint8_t)bits;
    case PLY_INT16: return (double)(int16_t)bits;
    case PLY_UINT16: return (double)(uint16_t)bits;
    case PLY_INT32: return (double)(int32_t)bits;
    case PLY_UINT32: return (double)(uint32_t)bits;
    case PLY_FLOAT32: {
        uint32_t b32 = (uint32_t)bits;
        float f;
        memcpy(&f, &b32, 4);
        return f;
    }
    case PLY_FLOAT64: {
        double d;
        memcpy(&d, &bits, 8);
        return d;
    }
    default: return 0;
    }
}

static cg_status binary_truncated(ply_reader *r, size_t offset, const ply_element *e, uint64_t item)
{
    return cg_error_set(r->err, CG_EFORMAT,
                        "%s: byte %zu: the file ends inside %s %llu of %llu (header line %zu)",
                        r->name, offset, kind_name(e), (unsigned long long)item,
                        (unsigned long long)e->count, e->header_line);
}

static cg_status read_binary(ply_reader *r, const unsigned char *bytes, size_t size, size_t body)
{
    int big = r->format == PLY_BIG;
    size_t at = body;
    for (size_t ei = 0; ei < r->element_count; ei++) {
        ply_element *e = &r->elements[ei];
        const ply_property *props = &r->properties[e->first_property];
        size_t fixed = 0; /* bytes of an item without lists (lists: their count) */
        int has_list = 0;
        for (size_t k = 0; k < e->property_count; k++) {
            fixed += type_size[props[k].count_type ? props[k].count_type : props[k].type];
            has_list |= props[k].count_type != PLY_NONE;
        }
        size_t left = size - at;
        if (fixed && e->count > left / fixed) {
            uint64_t fits = left / fixed;
            return cg_error_set(r->err, CG_EFORMAT,
                                "%s: byte %zu: the header says %llu items of element '%s' (line "
                                "%zu) but only %zu bytes remain, room for at most %llu",
                                r->name, at, (unsigned long long)e->count, e->name, e->header_line,
                                left, (unsigned long long)fits);
        }
        if (e->kind == E_OTHER && !has_list) {
            at += (size_t)e->count * fixed;
            continue;
        }
        /* room for what the bytes left can hold: a face's list has 3 or more indices */
        size_t least = fixed;
        for (size_t k = 0; k < e->property_count; k++)
            least += props[k].target == T_CORNERS ? 3 * type_size[props[k].type] : 0;
        size_t guess = least && e->count < (size - at) / least ? (size_t)e->count
                       : least                                 ? (size - at) / least
                                                               : 0;
        if (e->kind == E_VERTEX && builder_reserve_vertices(&r->b, guess) != CG_OK)
            return cg_error_set(r->err, CG_ENOMEM, "%s: out of memory", r->name);
        if (e->kind == E_FACE && builder_reserve_faces(&r->b, guess) != CG_OK)
            return cg_error_set(r->err, CG_ENOMEM, "%s: out of memory", r->name);
        for (uint64_t item = 0; item < e->count; item++) {
            if (e->kind != E_OTHER && begin_item(r, e->kind) != CG_OK)
                return cg_error_set(r->err, CG_ERANGE, "%s: byte %zu: too many items for cg_mesh",
                                    r->name, at);
            size_t index = e->kind == E_FACE ? r->b.face_count : r->b.vertex_count - 1;
            size_t item_at = at;
            for (size_t k = 0; k < e->property_count; k++) {
                const ply_property *p = &props[k];
                if (!p->count_type) {
                    size_t n = type_size[p->type];
                    if (size - at < n)
                        return binary_truncated(r, at, e, item);
                    if (p->target != T_SKIP)
                        store(r, p->target, p->type, binary_value(bytes + at, p->type, big), index,
                              e->kind == E_FACE);
                    at += n;
                    continue;
                }
                size_t cn = type_size[p->count_type];
                if (size - at < cn)
                    return binary_truncated(r, at, e, item);
                double count = binary_value(bytes + at, p->count_type, big);
                if (count < 0)
                    return cg_error_set(r->err, CG_EFORMAT,
                                        "%s: byte %zu: expected a list length of 0 or more in %s "
                                        "%llu, got %.0f",
                                        r->name, at, kind_name(e), (unsigned long long)item, count);
                at += cn;
                uint64_t n = (uint64_t)count;
                size_t vn = type_size[p->type];
                if (n > (size - at) / vn)
                    return binary_truncated(r, at, e, item);
                if (p->target != T_CORNERS) {
                    at += (size_t)n * vn;
                    continue;
                }
                if (n < 3)
                    return cg_error_set(r->err, CG_EFORMAT,
                                        "%s: byte %zu: expected a face of at least 3 vertices, "
                                        "face %llu has %llu",
                                        r->name, at - cn, (unsigned long long)item,
                                        (unsigned long long)n);
                if (builder_reserve_indices(&r->b, (size_t)n) != CG_OK)
                    return cg_error_set(r->err, CG_ERANGE,
                                        "%s: byte %zu: too many face corners for cg_mesh", r->name,
                                        at);
                for (uint64_t j = 0; j < n; j++, at += vn) {
                    double v = binary_value(bytes + at, p->type, big);
                    if (v < 0 || (r->vertices_read && v >= (double)r->b.vertex_count))
                        return cg_error_set(r->err, CG_EFORMAT,
                                            "%s: byte %zu: face %llu refers to vertex %.0f, but "
                                            "there are %zu vertices",
                                            r->name, at, (unsigned long long)item, v,
                                            r->b.vertex_count);
                    r->b.face_indices[r->b.index_count++] = (uint32_t)v;
                }
            }
            if (e->kind == E_FACE) {
                cg_status status = finish_face(r);
                if (status != CG_OK)
                    return status;
            }
            if (e->kind == E_VERTEX && check_vertex(r, 0, item_at) != CG_OK)
                return r->err ? r->err->status : CG_EFORMAT;
        }
        if (e->kind == E_VERTEX)
            r->vertices_read = 1;
    }
    if (at != size)
        return cg_error_set(r->err, CG_EFORMAT,
                            "%s: byte %zu: expected the end of the file after the last element, "
                            "%zu more bytes follow",
                            r->name, at, size - at);
    return CG_OK;
}

cg_status ply_read(const unsigned char *bytes, size_t size, const char *name, cg_mesh **out,
                   cg_error *err)
{
    ply_reader *r = calloc(1, sizeof *r);
    if (!r)
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", name);
    r->name = name;
    r->err = err;
    builder_init(&r->b);
    size_t body = 0, line = 1;
    cg_status s = read_header(r, bytes, size, &body, &line);
    if (s == CG_OK) {
        cg_rgbaf white = {1, 1, 1, 1};
        if (builder_add_arrays(&r->b, wanted_arrays(r), white) != CG_OK)
            s = cg_error_set(err, CG_ENOMEM, "%s: out of memory", name);
    }
    if (s == CG_OK)
        s = r->format == PLY_ASCII ? read_ascii(r, bytes, size, body, line)
                                   : read_binary(r, bytes, size, body);
    if (s == CG_OK)
        s = mesh_check_indices(&r->b, name, err);
    if (s == CG_OK && (s = builder_finish(&r->b, out)) != CG_OK)
        s = cg_error_set(err, s, "%s: out of memory", name);
    builder_free(&r->b);
    free(r);
    return s;
}
