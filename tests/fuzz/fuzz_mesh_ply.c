/* libFuzzer target: the PLY mesh reader (see fuzz_mesh.h). */
#define FUZZ_FORMAT CG_MESH_FORMAT_PLY
#define FUZZ_NAME "fuzz.ply"
#include "fuzz_mesh.h"
