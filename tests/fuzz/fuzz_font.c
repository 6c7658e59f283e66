/* libFuzzer target: fonts from bytes (FreeType through cg_font_load_memory),
 * then every reachable glyph outline and a shaped run turned into paths.
 * A font that loads must give paths or clear errors; a failure must come
 * with a message. */
#include "cg/text.h"

#include <stdlib.h>

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    cg_font *font = NULL;
    cg_error err;
    if (cg_font_load_memory(data, size, 0, &font, &err) != CG_OK) {
        if (font || err.message[0] == '\0')
            abort();
        return 0;
    }
    cg_path *path;
    if (cg_path_create(&path) == CG_OK) {
        int glyphs = cg_font_glyph_count(font);
        for (int g = 0; g < glyphs && g < 256; g++)
            cg_font_glyph_path(font, (unsigned)g, 24, 0, 30, path, NULL);
        cg_path_reset(path);
        cg_text_run_path(font, "Type AV fi", 16, 0, 20, CG_TEXT_MIDDLE, CG_BASELINE_TOP, path, NULL,
                         NULL);
        cg_path_free(path);
    }
    cg_font_free(font);
    return 0;
}
