/* libFuzzer target: the scene reader on arbitrary bytes (meshes not loaded),
 * and an animated scene posed before, at, between and after its frames. */
#include "cg.h"

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cg_scene *scene = NULL;
    cg_error err;
    if (cg_scene_parse((const char *)data, size, "fuzz.json", NULL, 0, &scene, &err) == CG_OK) {
        static const double frames[] = {-1, 0, 0.5, 1, 2.25, 7, 1e6};
        for (size_t i = 0; i < sizeof frames / sizeof *frames; i++)
            if (cg_scene_set_frame(scene, frames[i] * (scene->frame_count + 1)) != CG_OK)
                __builtin_trap();
        cg_scene_free(scene);
    }
    return 0;
}
