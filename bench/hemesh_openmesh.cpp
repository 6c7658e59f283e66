// The OpenMesh side of bench_hemesh: the same work through OpenMesh's
// TriMesh (array kernel, double-precision points so both hold the same
// data), called from C.
#include "hemesh_peer.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <vector>

namespace {
struct Traits : public OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3d Point;
    typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::TriMesh_ArrayKernelT<Traits> Mesh;
} // namespace

extern "C" {

int peer_available(void) { return 1; }

void peer_quiet(void) { omerr().disable(); }

void *peer_build(const cg_mesh *m)
{
    Mesh *mesh = new Mesh;
    size_t corners = m->face_offsets[m->face_count];
    /* edges: half the corners plus room for boundary edges, so that no
     * array has to grow (and double its capacity) while building */
    mesh->reserve(m->vertex_count, corners / 2 + corners / 64 + 64, m->face_count);
    std::vector<Mesh::VertexHandle> vh(m->vertex_count);
    for (size_t v = 0; v < m->vertex_count; v++) {
        const cg_vec3 &p = m->positions[v];
        vh[v] = mesh->add_vertex(Mesh::Point(p.x, p.y, p.z));
    }
    std::vector<Mesh::VertexHandle> face;
    for (size_t f = 0; f < m->face_count; f++) {
        face.clear();
        for (uint32_t k = m->face_offsets[f]; k < m->face_offsets[f + 1]; k++)
            face.push_back(vh[m->face_indices[k]]);
        mesh->add_face(face);
    }
    return mesh;
}

void peer_free(void *mesh) { delete static_cast<Mesh *>(mesh); }

void *peer_copy(const void *mesh) { return new Mesh(*static_cast<const Mesh *>(mesh)); }

void peer_neighbor_average(const void *handle, cg_vec3 *out)
{
    const Mesh &mesh = *static_cast<const Mesh *>(handle);
    for (auto v : mesh.vertices()) {
        OpenMesh::Vec3d sum(0, 0, 0);
        int n = 0;
        for (auto w : mesh.vv_range(v)) {
            sum += mesh.point(w);
            n++;
        }
        if (n)
            sum /= n;
        else
            sum = mesh.point(v);
        out[v.idx()] = cg_vec3_make(sum[0], sum[1], sum[2]);
    }
}

void peer_loop(void *handle)
{
    Mesh &mesh = *static_cast<Mesh *>(handle);
    OpenMesh::Subdivider::Uniform::LoopT<Mesh, double> loop;
    loop.attach(mesh);
    loop(1);
    loop.detach();
}

size_t peer_counts(const void *handle, size_t *vertices, size_t *edges)
{
    const Mesh &mesh = *static_cast<const Mesh *>(handle);
    *vertices = mesh.n_vertices();
    *edges = mesh.n_edges();
    return mesh.n_faces();
}

const cg_vec3 *peer_point(const void *handle, size_t v, cg_vec3 *out)
{
    const Mesh &mesh = *static_cast<const Mesh *>(handle);
    OpenMesh::Vec3d p = mesh.point(Mesh::VertexHandle((int)v));
    *out = cg_vec3_make(p[0], p[1], p[2]);
    return out;
}
}
