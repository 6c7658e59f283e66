/* libFuzzer target: the STL mesh reader (see fuzz_mesh.h). */
#define FUZZ_FORMAT CG_MESH_FORMAT_STL
#define FUZZ_NAME "fuzz.stl"
#include "fuzz_mesh.h"
