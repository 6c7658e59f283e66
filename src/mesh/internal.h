/* Private pieces shared by the mesh file readers and writers: a growable
 * mesh builder, number parsing and a cursor over text. */
#ifndef CG_MESH_INTERNAL_H
#define CG_MESH_INTERNAL_H

#include "cg/mesh.h"

#include <math.h>
#include <string.h>

/* ---- the builder -----------------------------------------------------------
 * Arrays grow geometrically with what is actually added; a reader may ask for
 * room in advance (builder_reserve_*) only for what the data left in the file
 * can hold, never for what a header claims. */
typedef struct mesh_builder {
    size_t vertex_count, vertex_capacity;
    cg_vec3 *positions;
    cg_vec3 *normals;   /* allocated when CG_MESH_NORMALS is in flags */
    cg_vec2 *texcoords; /* CG_MESH_TEXCOORDS */
    cg_rgbaf *colors;   /* CG_MESH_COLORS */
    size_t face_count, face_capacity;
    uint32_t *face_offsets; /* face_count + 1 entries once a face is added */
    cg_rgbaf *face_colors;  /* CG_MESH_FACE_COLORS */
    size_t index_count, index_capacity;
    uint32_t *face_indices;
    unsigned flags;
} mesh_builder;

/* Starts an empty builder (no allocation yet). */
void builder_init(mesh_builder *b);
void builder_free(mesh_builder *b);
/* Adds optional arrays (CG_MESH_* flags) to a builder that may already have
 * vertices or faces; existing entries are filled with fill (normals,
 * texcoords: zero; colours: the given colour). */
cg_status builder_add_arrays(mesh_builder *b, unsigned flags, cg_rgbaf fill);
/* Room for at least `more` further vertices / faces / corners. */
cg_status builder_reserve_vertices(mesh_builder *b, size_t more);
cg_status builder_reserve_faces(mesh_builder *b, size_t more);
cg_status builder_reserve_indices(mesh_builder *b, size_t more);

/* Appends a vertex (optional arrays zeroed / white) and returns its index. */
static inline cg_status builder_push_vertex(mesh_builder *b, cg_vec3 p, size_t *index)
{
    if (b->vertex_count == b->vertex_capacity) {
        cg_status s = builder_reserve_vertices(b, 1);
        if (s != CG_OK)
            return s;
    }
    size_t i = b->vertex_count++;
    b->positions[i] = p;
    if (b->normals)
        b->normals[i] = cg_vec3_make(0, 0, 0);
    if (b->texcoords)
        b->texcoords[i] = cg_vec2_make(0, 0);
    if (b->colors) {
        cg_rgbaf white = {1, 1, 1, 1};
        b->colors[i] = white;
    }
    if (index)
        *index = i;
    return CG_OK;
}

/* Appends one corner index to the face being built. */
static inline cg_status builder_push_index(mesh_builder *b, uint32_t v)
{
    if (b->index_count == b->index_capacity) {
        cg_status s = builder_reserve_indices(b, 1);
        if (s != CG_OK)
            return s;
    }
    b->face_indices[b->index_count++] = v;
    return CG_OK;
}

/* Closes the face made of the corners pushed since the previous face (its
 * colour, when the builder has face colours, is the reader's to set). */
cg_status builder_end_face(mesh_builder *b);

/* Corners pushed since the last builder_end_face. */
static inline size_t builder_open_corners(const mesh_builder *b)
{
    return b->index_count - (b->face_count ? b->face_offsets[b->face_count] : 0);
}

/* Moves the arrays into a new cg_mesh (the builder is left empty). */
cg_status builder_finish(mesh_builder *b, cg_mesh **out);

/* ---- numbers ---------------------------------------------------------------
 * Both parse a number starting exactly at *p (no leading blanks) and ending
 * at a blank, a line end, '/', '#' or end; on success they advance *p past
 * it and return 1, otherwise 0 with *p unchanged. */
int parse_double(const char **p, const char *end, double *out);
int parse_int64(const char **p, const char *end, int64_t *out);

static inline int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}
static inline int is_line_end(char c)
{
    return c == '\n' || c == '\r';
}
static inline int is_space(char c)
{
    return is_blank(c) || is_line_end(c);
}

/* ---- a cursor over text ------------------------------------------------ */
typedef struct text_cursor {
    const char *p, *end;
    const char *name;
    size_t line; /* 1-based line of p */
} text_cursor;

/* A cursor at the start of bytes[0..size), line 1 of the file name. */
static inline text_cursor text_cursor_start(const char *bytes, size_t size, const char *name)
{
    text_cursor t = {bytes, bytes + size, name, 1};
    return t;
}

static inline void text_skip_blanks(text_cursor *t)
{
    while (t->p < t->end && is_blank(*t->p))
        t->p++;
}

/* Moves past the current line's end ("\n", "\r\n" or "\r"). */
static inline void text_next_line(text_cursor *t)
{
    const char *nl = memchr(t->p, '\n', (size_t)(t->end - t->p));
    const char *cr = memchr(t->p, '\r', (size_t)((nl ? nl : t->end) - t->p));
    if (cr && (cr + 1 == t->end || cr[1] != '\n')) {
        t->p = cr + 1;
    } else if (nl) {
        t->p = nl + 1;
    } else {
        t->p = t->end;
        return;
    }
    t->line++;
}

/* True at a line end, '#' comment or end of text (after blanks). */
static inline int text_at_line_end(text_cursor *t)
{
    text_skip_blanks(t);
    return t->p >= t->end || is_line_end(*t->p) || *t->p == '#';
}

/* Skips blanks, line ends and '#' comments; counts lines. */
void text_skip_space_and_comments(text_cursor *t);

/* Describes the text at the cursor for a message: "'abc'" (at most 24
 * characters, non-printing ones as '?') or "the end of the line/file". */
const char *text_describe(const text_cursor *t, char buffer[40]);

/* Fails with CG_EFORMAT and "name:line: expected WHAT, got <text at the cursor>". */
cg_status text_expected(const text_cursor *t, const char *what, cg_error *err);

/* Reads a number (after blanks) or fails as text_expected does. */
cg_status text_double(text_cursor *t, double *out, const char *what, cg_error *err);

/* ---- helpers ----------------------------------------------------------- */

/* 0..255 (or 0..1 when is_float) encoded colour component to a linear one;
 * alpha components are linear already. */
float mesh_color_component(double value, int is_float, int is_alpha);

/* The first coordinate of p (0 x, 1 y, 2 z) that is NaN or infinite, or -1
 * when all three are finite. */
static inline int mesh_nonfinite_axis(cg_vec3 p)
{
    return !isfinite(p.x) ? 0 : !isfinite(p.y) ? 1 : !isfinite(p.z) ? 2 : -1;
}

/* Fails with CG_EFORMAT and "NAME:LINE: expected a finite vertex coordinate,
 * got y = nan" for p's first coordinate that is not finite; with line 0,
 * "NAME: byte BYTE: ..." and then " (ITEM)", e.g. "vertex 4", when item is
 * not NULL.  cg keeps finite positions only, so that bounds, framing,
 * rendering and the writers never meet NaN or infinity. */
cg_status mesh_nonfinite_error(cg_error *err, const char *name, size_t line, size_t byte,
                               const char *item, cg_vec3 p);

/* Checks a loaded mesh's face indices against its vertex count; "name: face F
 * refers to vertex I, but there are only N" otherwise. */
cg_status mesh_check_indices(const mesh_builder *b, const char *name, cg_error *err);

/* Appends one line (printf-style, a newline added) to *notes, a growing
 * string (NULL at first); CG_ENOMEM leaves *notes as it was. */
cg_status mesh_note(char **notes, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Reads the MTL library at path into materials[m] for each m whose name is
 * names[m] (the others are skipped); has_kd[m] is set where Kd is given.
 * *found is 0 when the file cannot be read (nothing else happens).  Maps
 * whose file is missing are noted in *notes.  CG_EFORMAT with
 * "path:line: ..." for a malformed statement. */
cg_status mtl_read_library(const char *path, char **names, size_t count,
                           cg_mesh_material *materials, unsigned char *has_kd, char **notes,
                           cg_error *err, int *found);

/* The readers.  bytes need not be NUL-terminated.  directory (may be NULL)
 * is where OBJ material libraries are looked for. */
cg_status obj_read(const char *bytes, size_t size, const char *name, const char *directory,
                   cg_mesh **out, cg_error *err);
cg_status ply_read(const unsigned char *bytes, size_t size, const char *name, cg_mesh **out,
                   cg_error *err);
cg_status off_read(const char *bytes, size_t size, const char *name, cg_mesh **out, cg_error *err);
cg_status stl_read(const unsigned char *bytes, size_t size, const char *name, cg_mesh **out,
                   cg_error *err);

/* Writers beside save.c's OBJ and PLY: OFF and binary STL (save_off_stl.c),
 * glTF binary (gltf_write.c).  The mesh is valid (cg_mesh_save checks). */
cg_status off_write(const cg_mesh *m, const char *path, cg_error *err);
cg_status stl_write(const cg_mesh *m, const char *path, cg_error *err);
cg_status gltf_write(const cg_mesh *m, const char *path, cg_error *err);
/* The mesh's faces as cg_mesh_triangle_count(m) triangles, for the writers
 * of triangle formats (STL, glTF): *out to free, or an error naming path. */
cg_status mesh_write_triangles(const cg_mesh *m, const char *path, cg_error *err,
                               uint32_t (**out)[3]);

/* glTF 2.0, .gltf or .glb (gltf.c); directory as for obj_read. */
cg_status gltf_read(const unsigned char *bytes, size_t size, const char *name,
                    const char *directory, cg_mesh **out, cg_error *err);
/* True when the bytes are JSON text with an "asset" member near the start. */
int mesh_looks_like_gltf_json(const unsigned char *bytes, size_t size);

/* A format cg does not read, recognised by its first bytes or by the name's
 * extension (".gz" looked through): "a glTF binary file (.glb)", or NULL. */
const char *mesh_foreign_by_content(const unsigned char *bytes, size_t size);
const char *mesh_foreign_by_name(const char *name);

/* A file read whole into memory (decompressed when gzip); free with free(). */
cg_status mesh_read_file(const char *path, unsigned char **bytes, size_t *size, cg_error *err);

#endif
