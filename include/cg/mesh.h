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

#ifdef __cplusplus
extern "C" {
#endif

/* Vertex indices are 32-bit: at most CG_MESH_MAX_VERTICES vertices and
 * CG_MESH_MAX_INDICES face corners in one mesh. */
#define CG_MESH_MAX_VERTICES 0xfffffffeu
#define CG_MESH_MAX_INDICES 0xfffffffeu

typedef struct cg_mesh {
    size_t vertex_count;
    cg_vec3 *positions;  /* vertex_count */
    cg_vec3 *normals;    /* vertex_count, or NULL */
    cg_vec2 *texcoords;  /* vertex_count, or NULL */
    cg_rgbaf *colors;    /* vertex_count linear-light colours, or NULL */

    size_t face_count;
    uint32_t *face_offsets;  /* face_count + 1; face_offsets[0] == 0 */
    uint32_t *face_indices;  /* face_offsets[face_count] corners */
    cg_rgbaf *face_colors;   /* face_count diffuse colours (OBJ usemtl), or NULL */
} cg_mesh;

/* Which optional arrays cg_mesh_create allocates. */
enum {
    CG_MESH_NORMALS = 1,
    CG_MESH_TEXCOORDS = 2,
    CG_MESH_COLORS = 4,
    CG_MESH_FACE_COLORS = 8
};

/* A mesh with room for vertex_count vertices, face_count faces and
 * index_count corners in all; arrays are zeroed (face_offsets too: the caller
 * fills them).  flags selects the optional arrays.  CG_ERANGE beyond the
 * limits above. */
cg_status cg_mesh_create(cg_mesh **out, size_t vertex_count, size_t face_count,
                         size_t index_count, unsigned flags);
void cg_mesh_free(cg_mesh *mesh);

/* Number of corners of face f. */
static inline uint32_t cg_mesh_face_size(const cg_mesh *mesh, size_t f)
{
    return mesh->face_offsets[f + 1] - mesh->face_offsets[f];
}

/* Checks that offsets are non-decreasing, every face has at least 3
 * corners, and every index is below vertex_count; CG_EFORMAT with the face
 * number otherwise. */
cg_status cg_mesh_validate(const cg_mesh *mesh, cg_error *err);

/* Axis-aligned bounding box of the finite positions; CG_EEMPTY when there
 * are none. */
cg_status cg_mesh_bounds(const cg_mesh *mesh, cg_vec3 *lo, cg_vec3 *hi);

/* Number of triangles a fan triangulation of every face gives. */
size_t cg_mesh_triangle_count(const cg_mesh *mesh);

#ifdef __cplusplus
}
#endif
#endif
