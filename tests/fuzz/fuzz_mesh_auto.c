/* libFuzzer target: the mesh format detection and gzip, then any reader (see fuzz_mesh.h). */
#define FUZZ_FORMAT CG_MESH_FORMAT_AUTO
#define FUZZ_NAME "fuzz.auto"
#include "fuzz_mesh.h"
