/* libFuzzer target: the glTF 2.0 reader, .gltf JSON and .glb containers
 * alike (told apart by the "glTF" magic).  A mesh that loads must validate
 * and its material ids must lie in its material table; a failure must come
 * with a message.  Files outside the input (external buffers) are never
 * read: the input comes from memory.  A mesh that loads is written back as
 * .glb (cg's writer, with the textures the input embeds) and must read back
 * with its triangles and materials. */
#include "cg/mesh.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

/* The writer on a mesh that loaded: it succeeds (or says why), and what it
 * wrote reads back with one face per triangle and the same materials. */
static void write_back(const cg_mesh *mesh)
{
    char path[64];
    snprintf(path, sizeof path, "/tmp/cg_fuzz_gltf_%ld.glb", (long)getpid());
    cg_error err;
    cg_status status = cg_mesh_save(mesh, path, CG_MESH_FORMAT_GLTF, &err);
    if (status != CG_OK) {
        if (err.message[0] == '\0')
            abort();
        return;
    }
    cg_mesh *back = NULL;
    if (cg_mesh_load(path, &back, &err) != CG_OK || back->face_count != cg_mesh_triangle_count(mesh)
        || (back->face_count && back->material_count != mesh->material_count))
        abort();
    cg_mesh_free(back);
    remove(path);
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    cg_mesh *mesh = NULL;
    cg_error err;
    cg_status status = cg_mesh_load_memory(data, size, "fuzz.gltf", CG_MESH_FORMAT_GLTF, &mesh,
                                           &err);
    if (status == CG_OK) {
        cg_error check;
        if (!mesh || cg_mesh_validate(mesh, &check) != CG_OK)
            abort();
        for (size_t f = 0; mesh->face_materials && f < mesh->face_count; f++)
            if (mesh->face_materials[f] != CG_MESH_NO_MATERIAL
                && mesh->face_materials[f] >= mesh->material_count)
                abort();
        write_back(mesh);
    } else if (mesh || err.status != status || err.message[0] == '\0') {
        abort();
    }
    cg_mesh_free(mesh);
    return 0;
}
