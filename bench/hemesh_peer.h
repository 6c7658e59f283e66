/* The peer (OpenMesh) side of bench_hemesh, callable from C.  Without
 * OpenMesh, hemesh_nopeer.c gives peer_available() == 0. */
#ifndef CG_BENCH_HEMESH_PEER_H
#define CG_BENCH_HEMESH_PEER_H

#include "cg/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

int peer_available(void);
/* Silences the peer's own error printing (complex edges of broken meshes). */
void peer_quiet(void);
void *peer_build(const cg_mesh *mesh);
void peer_free(void *mesh);
void *peer_copy(const void *mesh);
void peer_neighbor_average(const void *mesh, cg_vec3 *out);
void peer_loop(void *mesh);
size_t peer_counts(const void *mesh, size_t *vertices, size_t *edges);
const cg_vec3 *peer_point(const void *mesh, size_t v, cg_vec3 *out);

#ifdef __cplusplus
}
#endif
#endif
