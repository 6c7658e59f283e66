/* cg/mesh.h - the indexed polygon mesh that mesh files load into and that the
 * rasterizer, the ray tracer and the half-edge structure start from.
 *
 * Faces are polygons of any size; face f has the vertices
 * face_indices[face_offsets[f]] ... face_indices[face_offsets[f + 1] - 1],
 * counter-clockwise when seen from the front (outside).  Optional per-vertex
 * arrays are NULL when absent. */
#ifndef CG_MESH_H
#define CG_MESH_H

#include "cg/core.h"
#include "cg/image.h"
#include "cg/texture.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Vertex indices are 32-bit: at most CG_MESH_MAX_VERTICES vertices and
 * CG_MESH_MAX_INDICES face corners in one mesh. */
#define CG_MESH_MAX_VERTICES 0xfffffffeu
#define CG_MESH_MAX_INDICES 0xfffffffeu

/* ---- materials as the file gives them ------------------------------------
 * A mesh file's material table: what OBJ's .mtl and glTF's materials say,
 * in one shape, for the renderers to shade (OBJ with Phong / Blinn-Phong,
 * glTF with metallic-roughness).  Colours are linear light. */

/* A texture a material uses.  image_path names a file (resolved against the
 * model's or the .mtl's directory), or image_bytes holds an image embedded
 * in the model (glTF data: URI or GLB buffer view); both NULL: no texture. */
typedef struct cg_mesh_texture_ref {
    char *image_path;
    unsigned char *image_bytes;
    size_t image_byte_count;
    cg_texture_encoding encoding;   /* CG_TEXTURE_SRGB for colour (base colour,
                               emissive, specular), CG_TEXTURE_LINEAR for data
                               (normal, metallic-roughness, occlusion, alpha, bump) */
    int texcoord_set;               /* glTF texCoord (cg_mesh carries set 0) */
    cg_texture_wrap wrap_u, wrap_v; /* glTF sampler wrapS, wrapT; OBJ: -clamp on */
    int magnify_nearest;            /* glTF magFilter NEAREST (0: linear or unset) */
    /* KHR_texture_transform, in glTF's texture space (origin top-left):
     * uv' = translate(offset) rotate(rotation) scale(scale) uv */
    double offset[2], rotation, scale[2];
    double amount; /* normal map scale, occlusion strength, -bm bump
                               multiplier; 1 otherwise */
} cg_mesh_texture_ref;

enum { CG_MESH_MATERIAL_PHONG = 0, CG_MESH_MATERIAL_METALLIC_ROUGHNESS = 1 };
enum { CG_MESH_ALPHA_OPAQUE = 0, CG_MESH_ALPHA_MASK = 1, CG_MESH_ALPHA_BLEND = 2 };

typedef struct cg_mesh_material {
    char *name;                 /* "" when the file gives none */
    int model;                  /* CG_MESH_MATERIAL_PHONG (OBJ) or _METALLIC_ROUGHNESS (glTF) */
    cg_rgbaf base_color;        /* Kd with alpha d (1 - Tr); glTF baseColorFactor */
    cg_rgbaf specular;          /* Ks (Phong) */
    double shininess;           /* Ns (Phong) */
    int illum;                  /* OBJ illumination model (2 when not given) */
    double metallic, roughness; /* glTF factors */
    cg_rgbaf emissive;          /* Ke; glTF emissiveFactor times KHR_materials_emissive_strength */
    int alpha_mode;             /* CG_MESH_ALPHA_*: BLEND when d < 1 in OBJ */
    double alpha_cutoff;        /* MASK threshold (glTF alphaCutoff, 0.5 by default) */
    int double_sided;
    int unlit;                                  /* KHR_materials_unlit */
    cg_mesh_texture_ref base_color_map;         /* map_Kd; baseColorTexture (sRGB) */
    cg_mesh_texture_ref specular_map;           /* map_Ks (sRGB) */
    cg_mesh_texture_ref alpha_map;              /* map_d (linear) */
    cg_mesh_texture_ref bump_map;               /* map_bump / bump (linear heights) */
    cg_mesh_texture_ref normal_map;             /* norm; normalTexture (linear) */
    cg_mesh_texture_ref metallic_roughness_map; /* metallicRoughnessTexture (linear: G, B) */
    cg_mesh_texture_ref occlusion_map;          /* occlusionTexture (linear: R) */
    cg_mesh_texture_ref emissive_map;           /* emissiveTexture (sRGB) */
} cg_mesh_material;

/* A face without a material (face_materials entry). */
#define CG_MESH_NO_MATERIAL UINT32_MAX

typedef struct cg_mesh {
    size_t vertex_count;
    cg_vec3 *positions; /* vertex_count */
    cg_vec3 *normals;   /* vertex_count, or NULL */
    cg_vec2 *texcoords; /* vertex_count, or NULL */
    cg_rgbaf *colors;   /* vertex_count linear-light colours, or NULL */

    size_t face_count;
    uint32_t *face_offsets; /* face_count + 1; face_offsets[0] == 0 */
    uint32_t *face_indices; /* face_offsets[face_count] corners */
    cg_rgbaf *face_colors;  /* face_count diffuse colours (OBJ usemtl, PLY, OFF), or NULL;
                                alpha 0 marks a face the file gives no colour */

    /* Set by the file readers; NULL / 0 otherwise.  cg_mesh_free frees them. */
    size_t material_count;
    cg_mesh_material *materials; /* material_count */
    uint32_t *face_materials;    /* face_count indices into materials or
                                     CG_MESH_NO_MATERIAL; NULL when no face has one */
    char *notes;                 /* what the reader left out or could not find, one
                                     line each ("model.glb: 1 skin(s) (the rest pose
                                     is drawn)"), or NULL */
} cg_mesh;

/* Which optional arrays cg_mesh_create allocates. */
enum { CG_MESH_NORMALS = 1, CG_MESH_TEXCOORDS = 2, CG_MESH_COLORS = 4, CG_MESH_FACE_COLORS = 8 };

/* A mesh with room for vertex_count vertices, face_count faces and
 * index_count corners in all; arrays are zeroed (face_offsets too: the caller
 * fills them).  flags selects the optional arrays.  CG_ERANGE beyond the
 * limits above. */
cg_status cg_mesh_create(cg_mesh **out, size_t vertex_count, size_t face_count, size_t index_count,
                         unsigned flags);
void cg_mesh_free(cg_mesh *mesh);
/* Frees what a material owns (name, texture paths and bytes) and zeroes it. */
void cg_mesh_material_clear(cg_mesh_material *material);
/* A material with the defaults both formats start from: white, opaque,
 * Phong with Ks 0 and Ns 0, metallic 1 and roughness 1, alpha cutoff 0.5,
 * illum 2, texture references empty with scale 1 and amount 1. */
cg_mesh_material cg_mesh_material_default(void);

/* Number of corners of face f. */
static inline uint32_t cg_mesh_face_size(const cg_mesh *mesh, size_t f)
{
    return mesh->face_offsets[f + 1] - mesh->face_offsets[f];
}

/* Checks that every position is finite (no NaN or infinite coordinate),
 * offsets are non-decreasing, every face has at least 3 corners, and every
 * index is below vertex_count; CG_EFORMAT with the vertex or face number
 * otherwise. */
cg_status cg_mesh_validate(const cg_mesh *mesh, cg_error *err);
/* The same checks but the positions': for the consumers that leave out the
 * faces of non-finite vertices themselves (the rasterizer, the painter's
 * algorithm, the ray tracer, mesh clipping). */
cg_status cg_mesh_validate_topology(const cg_mesh *mesh, cg_error *err);

/* Axis-aligned bounding box of the finite positions; CG_EEMPTY when there
 * are none. */
cg_status cg_mesh_bounds(const cg_mesh *mesh, cg_vec3 *lo, cg_vec3 *hi);

/* Number of triangles cg_mesh_triangulate gives: n - 2 for a face of n
 * corners. */
size_t cg_mesh_triangle_count(const cg_mesh *mesh);

/* ---- triangulation ------------------------------------------------------
 * Splits face f into cg_mesh_face_size(mesh, f) - 2 triangles, written to
 * triangles[] as corner numbers (positions k in face_indices,
 * face_offsets[f] <= k < face_offsets[f + 1], so per-corner data such as
 * corner normals stays reachable), each counter-clockwise like the face.
 * The face is projected onto its best-fit plane (Newell's normal); the fan
 * from the first corner is kept when it covers the face exactly (every
 * convex face), and concave faces are cut by ear clipping, robust on
 * collinear and repeated corners, slightly non-planar and self-touching
 * faces (a hole joined to its outline by a bridge).  Triangles of no area
 * come out where corners are collinear.  See docs/mesh-io.md.
 * CG_EINVAL for a bad face number, a face of fewer than 3 corners or an
 * index out of range; CG_ENOMEM for a face of more than 32 corners when
 * memory runs out. */
cg_status cg_mesh_triangulate_face(const cg_mesh *mesh, size_t f, uint32_t (*triangles)[3]);

/* Every face in order: cg_mesh_triangle_count(mesh) triangles, face f's
 * n - 2 right after those of the faces before it.  Fails like
 * cg_mesh_validate_topology (a face with a non-finite corner gets its fan:
 * the renderers leave such faces out), or with CG_ENOMEM. */
cg_status cg_mesh_triangulate(const cg_mesh *mesh, uint32_t (*triangles)[3]);

/* ---- mesh files ---------------------------------------------------------
 * Readers for Wavefront OBJ (with MTL diffuse colours), OFF (and COFF, NOFF,
 * STOFF and their combinations), PLY (ASCII, binary little- and big-endian),
 * STL (ASCII and binary) and glTF 2.0 (.gltf with external or data: URI
 * buffers, .glb); writers for OBJ and PLY.  A glTF file gives the triangles
 * of its default scene in world space (node transforms applied), its
 * materials in the material table, and texture coordinates turned to cg's
 * convention (v' = 1 - v: origin bottom-left, as OBJ).  Any of them may be
 * gzip-compressed (detected by content).  See docs/mesh-io.md for the
 * accepted variants, limits and messages. */
typedef enum cg_mesh_format {
    CG_MESH_FORMAT_AUTO = 0, /* loading: by content, then by extension;
                                   saving: by extension (.obj, .ply = binary) */
    CG_MESH_FORMAT_OBJ,
    CG_MESH_FORMAT_OFF,
    CG_MESH_FORMAT_PLY,        /* loading: any PLY; saving: binary little-endian */
    CG_MESH_FORMAT_PLY_ASCII,  /* saving: ASCII PLY (loading: same as CG_MESH_FORMAT_PLY) */
    CG_MESH_FORMAT_PLY_BINARY, /* saving: binary little-endian PLY */
    CG_MESH_FORMAT_STL,        /* loading: ASCII or binary, by content; saving: binary */
    CG_MESH_FORMAT_GLTF        /* loading: .gltf (JSON) or .glb (binary), by content;
                                   saving: .glb */
} cg_mesh_format;

/* Largest file accepted, after gzip decompression: 4 GiB. */
#define CG_MESH_MAX_FILE_BYTES ((size_t)1 << 32)

/* The format a file name's extension names (a trailing .gz is looked
 * through); CG_MESH_FORMAT_AUTO when there is none. */
cg_mesh_format cg_mesh_format_from_path(const char *path);

/* Reads the mesh file at path.  OBJ material libraries (mtllib) are read
 * from the file's directory; a missing library means no face colours, not
 * an error.  On failure *out is NULL and err (may be NULL) says
 * "file:line: what was expected" (text) or "file: byte N: ..." (binary):
 * CG_EIO (cannot open or read), CG_EFORMAT (malformed), CG_ERANGE (more
 * vertices or corners than cg_mesh holds), CG_EUNSUPPORTED (a variant cg
 * does not read), CG_ENOMEM. */
cg_status cg_mesh_load(const char *path, cg_mesh **out, cg_error *err);

/* Reads a mesh file held in memory.  name is used in messages and, with
 * CG_MESH_FORMAT_AUTO, for its extension.  Reads no other file: OBJ
 * material libraries are ignored. */
cg_status cg_mesh_load_memory(const void *bytes, size_t size, const char *name,
                              cg_mesh_format format, cg_mesh **out, cg_error *err);

/* Writes the mesh to path through a temporary file renamed into place, so
 * an existing file is replaced only by a complete one.  Numbers are written
 * so that they read back exactly (positions as doubles in PLY), but in STL
 * and glTF, which hold floats.  OBJ face colours go to a material library
 * PATH-without-.obj.mtl beside it.  Each format keeps what it carries: OFF
 * positions, normals, colours, texture coordinates and face colours; STL
 * the triangles (faces triangulated); glTF (.glb) the triangles, normals,
 * texture coordinates, vertex colours and the material table's factors,
 * one primitive per material (texture maps are not written). */
cg_status cg_mesh_save(const cg_mesh *mesh, const char *path, cg_mesh_format format, cg_error *err);

/* Vertex normals of a mesh, computed as the renderer does when the mesh has
 * none: every corner gets the sum of the unit normals of the faces around its
 * vertex that differ from its own face's normal by at most crease_angle,
 * weighted by the faces' angles at that vertex, normalized.  corner_normals
 * receives face_offsets[face_count] normals (one per face corner, in
 * face_indices order); degenerate faces get a zero normal. */
cg_status cg_mesh_corner_normals(const cg_mesh *mesh, double crease_angle, cg_vec3 *corner_normals);

/* ---- generated meshes (tests, gallery, benchmarks) ----------------------- */

/* A UV sphere of the given radius at the origin: slices >= 3 around the y
 * axis, stacks >= 2 from pole to pole, triangles at the poles and quads
 * elsewhere, closed, counter-clockwise from outside, without normals.
 * 2 * slices * (stacks - 1) triangles.  CG_EINVAL for counts out of range
 * (at most 2^15 each). */
cg_status cg_mesh_sphere(int slices, int stacks, double radius, cg_mesh **out);
/* A torus around the y axis: major radius R, minor radius r, segments >= 3
 * around each circle; quads; 2 * major_segments * minor_segments triangles. */
cg_status cg_mesh_torus(int major_segments, int minor_segments, double major_radius,
                        double minor_radius, cg_mesh **out);
/* An axis-aligned box [lo, hi] of 6 quads. */
cg_status cg_mesh_box(cg_vec3 lo, cg_vec3 hi, cg_mesh **out);

#ifdef __cplusplus
}
#endif
#endif
