/* Private pieces of the glTF 2.0 reader (gltf*.c), shared between its files:
 *
 *   gltf.c           the entry point: .glb container or .gltf text, JSON,
 *                    the top-level checks, the mesh put together
 *   gltf_json.c      typed access to the JSON with messages naming the path
 *   gltf_buffer.c    buffers (GLB chunk, data: URIs, external files), views
 *   gltf_accessor.c  accessors: component types, strides, normalized, sparse
 *   gltf_scene.c     scenes, the node hierarchy and its world transforms
 *   gltf_primitive.c primitives to triangles in world space
 *   gltf_material.c  materials, textures, images, samplers
 *   gltf_camera.c    cameras and KHR_lights_punctual lights (checked)
 *   gltf_write.c     the .glb writer
 *
 * Every message starts with the file name and the JSON path of the value at
 * fault ("box.gltf: accessors[2].count: expected ..."). */
#ifndef CG_MESH_GLTF_INTERNAL_H
#define CG_MESH_GLTF_INTERNAL_H

#include "internal.h"
#include "../core/array.h"

#include <cjson/cJSON.h>

/* A JSON array as a table, so that index lookups are O(1) (cJSON keeps
 * arrays as linked lists). */
typedef struct gltf_list {
    cJSON **items;
    size_t count;
} gltf_list;

typedef struct gltf_buffer {
    const unsigned char *bytes; /* byte_length bytes */
    size_t byte_length;
    unsigned char *owned; /* what bytes points into when the reader allocated it */
} gltf_buffer;

/* What the reader met but the mesh does not carry: counted for the notes. */
typedef struct gltf_skipped {
    size_t point_primitives, line_primitives, no_position_primitives;
    size_t skins, animations, morph_targets;
    size_t cameras, lights, materials, textures;
} gltf_skipped;

typedef struct gltf_document {
    const char *name;      /* the file, for messages */
    const char *directory; /* where relative URIs are read, NULL when reading from memory */
    cg_error *err;
    cJSON *root;
    gltf_list accessors, buffer_views, buffers, meshes, nodes, scenes, materials, textures, images,
        cameras, skins, animations, samplers;
    gltf_list lights;                /* KHR_lights_punctual */
    gltf_buffer *loaded;             /* buffers.count entries */
    const unsigned char *glb_binary; /* the GLB BIN chunk, or NULL */
    size_t glb_binary_size;
    gltf_skipped skipped;
    int quantized;      /* KHR_mesh_quantization used: integer positions, normals, texcoords */
    size_t input_bytes; /* the file's size plus its external buffers' */
} gltf_document;

/* The most elements the reader makes for a file of doc->input_bytes bytes:
 * accessors without a buffer view (all zeros) and the default scene's
 * vertices and triangles (instancing repeats a mesh) stay within
 * GLTF_ELEMENTS_PER_BYTE per input byte plus GLTF_ELEMENTS_FREE, so that
 * memory follows the file's size however its JSON multiplies the data. */
#define GLTF_ELEMENTS_PER_BYTE 64
#define GLTF_ELEMENTS_FREE ((size_t)1 << 20)
static inline size_t gltf_element_budget(const gltf_document *doc)
{
    size_t budget = GLTF_ELEMENTS_FREE;
    if (doc->input_bytes > (SIZE_MAX - budget) / GLTF_ELEMENTS_PER_BYTE)
        return SIZE_MAX;
    return budget + GLTF_ELEMENTS_PER_BYTE * doc->input_bytes;
}

/* ---- JSON access (gltf_json.c) -------------------------------------------
 * Each getter reads member `key` of object `object`, whose JSON path is
 * `path`; when the member is absent it gives the default (optional) or fails
 * naming the path (required).  All fail with CG_EFORMAT. */
cg_status gltf_fail(gltf_document *doc, const char *path, const char *key, const char *expected,
                    const cJSON *got);
/* An integer in [minimum, maximum]. */
cg_status gltf_get_integer(gltf_document *doc, const cJSON *object, const char *path,
                           const char *key, int required, int64_t fallback, int64_t minimum,
                           int64_t maximum, int64_t *out);
/* An index into list (named list_name in messages). */
cg_status gltf_get_index(gltf_document *doc, const cJSON *object, const char *path, const char *key,
                         int required, const gltf_list *list, const char *list_name, size_t *out);
cg_status gltf_get_number(gltf_document *doc, const cJSON *object, const char *path,
                          const char *key, double fallback, double *out);
cg_status gltf_get_bool(gltf_document *doc, const cJSON *object, const char *path, const char *key,
                        int fallback, int *out);
/* A string member (NULL when absent and not required). */
cg_status gltf_get_string(gltf_document *doc, const cJSON *object, const char *path,
                          const char *key, int required, const char **out);
/* An object member (NULL when absent and not required). */
cg_status gltf_get_object(gltf_document *doc, const cJSON *object, const char *path,
                          const char *key, int required, const cJSON **out);
/* An array of exactly `count` numbers (any length >= 1 when count is 0),
 * or NULL when absent; the numbers go to values (at most `count`). */
cg_status gltf_get_numbers(gltf_document *doc, const cJSON *object, const char *path,
                           const char *key, size_t count, double *values, int *present);
/* An array member as a table; an empty table when absent.  minimum: the
 * fewest items allowed when present (glTF arrays are never empty). */
cg_status gltf_get_list(gltf_document *doc, const cJSON *object, const char *path, const char *key,
                        size_t minimum, gltf_list *out);
void gltf_list_free(gltf_list *list);
/* Checks that every item of list is a JSON object (path "name[i]"). */
cg_status gltf_check_objects(gltf_document *doc, const gltf_list *list, const char *name);
/* The same list checked to hold objects, as gltf_get_list then gltf_check_objects. */
cg_status gltf_get_object_list(gltf_document *doc, const cJSON *object, const char *path,
                               const char *key, gltf_list *out);
/* "a string", "the number 1.5", "an array"... for messages (buffer of 48). */
const char *gltf_describe(const cJSON *value, char buffer[48]);
cg_status gltf_out_of_memory(gltf_document *doc);

/* ---- buffers (gltf_buffer.c) ---------------------------------------------- */
/* Reads every buffer: the GLB BIN chunk, base64 data: URIs, external files
 * (relative to doc->directory). */
cg_status gltf_load_buffers(gltf_document *doc);
void gltf_free_buffers(gltf_document *doc);

/* A checked buffer view: its bytes and stride (0 when not given). */
typedef struct gltf_view {
    const unsigned char *bytes;
    size_t byte_length;
    size_t byte_stride;
    size_t buffer_offset; /* where bytes start in the buffer (for alignment rules) */
} gltf_view;
cg_status gltf_get_view(gltf_document *doc, size_t index, gltf_view *out);

/* ---- accessors (gltf_accessor.c) ------------------------------------------ */
enum {
    GLTF_BYTE = 5120,
    GLTF_UNSIGNED_BYTE = 5121,
    GLTF_SHORT = 5122,
    GLTF_UNSIGNED_SHORT = 5123,
    GLTF_UNSIGNED_INT = 5125,
    GLTF_FLOAT = 5126
};

/* An accessor's description, checked against its buffer view. */
typedef struct gltf_accessor {
    size_t index;
    size_t count;
    int component_type; /* GLTF_* */
    int components;     /* 1 SCALAR ... 16 MAT4 */
    int normalized;
    const char *type; /* "SCALAR", "VEC3", ... */
} gltf_accessor;

/* Reads accessor `index`'s description; checks the rules that need no data
 * (types, alignment, the view's bounds, sparse's structure). */
cg_status gltf_accessor_describe(gltf_document *doc, size_t index, gltf_accessor *out);
/* Every element as doubles (components per element), normalized integers
 * mapped to [0, 1] or [-1, 1], sparse substitution applied; values holds
 * count * components doubles. */
cg_status gltf_accessor_read_doubles(gltf_document *doc, const gltf_accessor *accessor,
                                     double *values);
/* An index accessor (SCALAR of unsigned byte, short or int, not normalized). */
cg_status gltf_accessor_read_indices(gltf_document *doc, const gltf_accessor *accessor,
                                     uint32_t *values);

/* ---- the scene (gltf_scene.c) -------------------------------------------- */
/* One use of a mesh by a node: the mesh and the node's world matrix. */
typedef struct gltf_instance {
    size_t mesh;
    size_t node;
    cg_mat4 world;
} gltf_instance;
typedef CORE_ARRAY(gltf_instance) gltf_instance_array;

/* Checks the node hierarchy (indices, one parent each, no cycle, TRS or
 * matrix) and lists the mesh instances of the default scene (scene, else
 * scenes[0], else every root node) in depth-first order. */
cg_status gltf_collect_instances(gltf_document *doc, gltf_instance_array *out);

/* ---- primitives (gltf_primitive.c) ---------------------------------------- */
/* Sizes of the mesh the instances make. */
typedef struct gltf_totals {
    size_t vertices, triangles;
    int all_normals, any_texcoords, any_colors;
} gltf_totals;

/* Checks every mesh's primitives (attributes, modes, accessors' types and
 * counts) and adds up what the instances need. */
cg_status gltf_count_primitives(gltf_document *doc, const gltf_instance_array *instances,
                                gltf_totals *totals);
/* Fills mesh (made with the totals) with the instances' triangles in world
 * space. */
cg_status gltf_fill_mesh(gltf_document *doc, const gltf_instance_array *instances, cg_mesh *mesh);

/* ---- cameras and lights (gltf_camera.c) ------------------------------------ */
/* Checks every camera and KHR_lights_punctual light. */
cg_status gltf_check_cameras_and_lights(gltf_document *doc);

/* ---- materials (gltf_material.c) ----------------------------------------- */
/* Checks materials, textures, images and samplers against the
 * specification and puts the materials into mesh's material table. */
cg_status gltf_read_materials(gltf_document *doc, cg_mesh *mesh);

#endif
