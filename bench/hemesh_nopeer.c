/* Stand-in for the OpenMesh side of bench_hemesh when OpenMesh is absent. */
#include "hemesh_peer.h"

int peer_available(void)
{
    return 0;
}
void peer_quiet(void) {}
void *peer_build(const cg_mesh *mesh)
{
    (void)mesh;
    return 0;
}
void peer_free(void *mesh)
{
    (void)mesh;
}
void *peer_copy(const void *mesh)
{
    (void)mesh;
    return 0;
}
void peer_neighbor_average(const void *mesh, cg_vec3 *out)
{
    (void)mesh;
    (void)out;
}
void peer_loop(void *mesh)
{
    (void)mesh;
}
size_t peer_counts(const void *mesh, size_t *vertices, size_t *edges)
{
    (void)mesh;
    *vertices = *edges = 0;
    return 0;
}
const cg_vec3 *peer_point(const void *mesh, size_t v, cg_vec3 *out)
{
    (void)mesh;
    (void)v;
    return out;
}
