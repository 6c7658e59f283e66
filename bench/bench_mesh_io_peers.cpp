// Peers for bench_mesh_io: tinyobjloader (OBJ) and OpenMesh (OBJ and PLY),
// behind plain C functions.  Each returns the vertex count read, or -1.
#include <cstddef>

extern "C" long peer_tinyobj_load(const char *path);
extern "C" long peer_openmesh_load(const char *path);

#ifdef CG_HAVE_TINYOBJ
#include <tiny_obj_loader.h>
extern "C" long peer_tinyobj_load(const char *path)
{
    tinyobj::ObjReaderConfig config;
    config.triangulate = false; // cg keeps polygons too
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, config))
        return -1;
    return (long)(reader.GetAttrib().vertices.size() / 3);
}
#else
extern "C" long peer_tinyobj_load(const char *) { return -1; }
#endif

#ifdef CG_HAVE_OPENMESH
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
extern "C" long peer_openmesh_load(const char *path)
{
    omerr().disable(); // complex-edge warnings on the decimated dragon
    omlog().disable();
    OpenMesh::PolyMesh_ArrayKernelT<> mesh;
    if (!OpenMesh::IO::read_mesh(mesh, path))
        return -1;
    return (long)mesh.n_vertices();
}
#else
extern "C" long peer_openmesh_load(const char *) { return -1; }
#endif
