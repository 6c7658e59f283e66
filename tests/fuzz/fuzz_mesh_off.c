/* libFuzzer target: the OFF mesh reader (see fuzz_mesh.h). */
#define FUZZ_FORMAT CG_MESH_FORMAT_OFF
#define FUZZ_NAME "fuzz.off"
#include "fuzz_mesh.h"
