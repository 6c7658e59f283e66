/* The body of the mesh-reader fuzz targets: each fuzz_mesh_<format>.c sets
 * FUZZ_FORMAT to a cg_mesh_format (CG_MESH_FORMAT_AUTO also tries gzip and
 * the format detection) and includes this.  A mesh that loads must
 * validate; a failure must come with a message. */
#include "cg/mesh.h"

#include <stdlib.h>

#ifndef FUZZ_FORMAT
#define FUZZ_FORMAT CG_MESH_FORMAT_AUTO
#endif
#ifndef FUZZ_NAME
#define FUZZ_NAME "fuzz"
#endif

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    cg_mesh *mesh = NULL;
    cg_error err;
    cg_status status = cg_mesh_load_memory(data, size, FUZZ_NAME, FUZZ_FORMAT, &mesh, &err);
    if (status == CG_OK) {
        cg_error check;
        if (!mesh || cg_mesh_validate(mesh, &check) != CG_OK)
            abort();
    } else if (mesh || err.status != status || err.message[0] == '\0') {
        abort();
    }
    cg_mesh_free(mesh);
    return 0;
}
