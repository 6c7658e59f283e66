/* libFuzzer target: the scene reader on arbitrary bytes (meshes not loaded). */
#include "cg.h"

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cg_scene *scene = NULL;
    cg_error err;
    if (cg_scene_parse((const char *)data, size, "fuzz.json", NULL, 0, &scene, &err) == CG_OK)
        cg_scene_free(scene);
    return 0;
}
