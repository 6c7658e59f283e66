/* libFuzzer target: the OBJ mesh reader (see fuzz_mesh.h). */
#define FUZZ_FORMAT CG_MESH_FORMAT_OBJ
#define FUZZ_NAME "fuzz.obj"
#include "fuzz_mesh.h"
