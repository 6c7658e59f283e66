/* Internal parts of the text module (src/text/). */
#ifndef CG_TEXT_INTERNAL_H
#define CG_TEXT_INTERNAL_H

#include "cg/text.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include <hb.h>

/* One glyph outline in font units, y up: ops are 'M', 'L', 'Q', 'C', 'Z';
 * each takes 1, 1, 2, 3 and 0 points. */
typedef struct text_outline {
    int loaded;
    unsigned char *ops;
    double *pts; /* x, y pairs */
    size_t op_count, op_cap, pt_count, pt_cap;
} text_outline;

struct cg_font {
    FT_Library library;
    FT_Face face;
    unsigned char *data; /* the file's bytes: FreeType and HarfBuzz read them */
    size_t size;
    hb_blob_t *blob;
    hb_face_t *hb_face;
    hb_font_t *hb_font;
    text_outline *outlines; /* one per glyph id: the glyph-outline cache */
    size_t cached;
};

#endif
