/* libFuzzer target: the glTF 2.0 reader, .gltf JSON and .glb containers
 * alike (told apart by the "glTF" magic).  A mesh that loads must validate
 * and its material ids must lie in its material table; a failure must come
 * with a message.  Files outside the input (external buffers) are never
 * read: the input comes from memory. */
#include "cg/mesh.h"

#include <stdlib.h>

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
    } else if (mesh || err.status != status || err.message[0] == '\0') {
        abort();
    }
    cg_mesh_free(mesh);
    return 0;
}
