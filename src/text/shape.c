/* Shaping with HarfBuzz and laying out runs and paragraphs (cg/text.h). */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

/* Checks that s[0..len) is well-formed UTF-8 (no overlongs, surrogates or
 * code points beyond U+10FFFF). */
static int utf8_valid(const unsigned char *s, size_t len)
{
    size_t i = 0;
    while (i < len) {
        unsigned c = s[i];
        size_t n;
        if (c < 0x80)
            n = 0;
        else if ((c & 0xE0) == 0xC0)
            n = 1;
        else if ((c & 0xF0) == 0xE0)
            n = 2;
        else if ((c & 0xF8) == 0xF0)
            n = 3;
        else
            return 0;
        if (n > len - i - 1)
            return 0;
        unsigned cp = n == 0 ? c : c & (0x3F >> n);
        for (size_t k = 1; k <= n; k++) {
            if ((s[i + k] & 0xC0) != 0x80)
                return 0;
            cp = (cp << 6) | (s[i + k] & 0x3F);
        }
        if ((n == 1 && cp < 0x80) || (n == 2 && cp < 0x800) || (n == 3 && cp < 0x10000)
            || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
            return 0;
        i += n + 1;
    }
    return 1;
}

cg_status cg_text_shape(cg_font *font, const char *utf8, size_t len, cg_shaped_glyph **glyphs,
                        size_t *count, cg_error *err)
{
    if (!font || !utf8 || !glyphs || !count)
        return cg_error_set(err, CG_EINVAL, "shape: no font, text or output");
    *glyphs = NULL;
    *count = 0;
    if (len == (size_t)-1)
        len = strlen(utf8);
    if (len > (1u << 28))
        return cg_error_set(err, CG_ERANGE, "shape: text of %zu bytes is too long", len);
    if (!utf8_valid((const unsigned char *)utf8, len))
        return cg_error_set(err, CG_EFORMAT, "shape: the text is not valid UTF-8");
    if (len == 0)
        return CG_OK;
    hb_buffer_t *buffer = hb_buffer_create();
    hb_buffer_add_utf8(buffer, utf8, (int)len, 0, (int)len);
    hb_buffer_guess_segment_properties(buffer);
    hb_shape(font->hb_font, buffer, NULL, 0);
    if (!hb_buffer_allocation_successful(buffer)) {
        hb_buffer_destroy(buffer);
        return cg_error_set(err, CG_ENOMEM, "shape: out of memory");
    }
    unsigned n;
    hb_glyph_info_t *info = hb_buffer_get_glyph_infos(buffer, &n);
    hb_glyph_position_t *pos = hb_buffer_get_glyph_positions(buffer, NULL);
    cg_shaped_glyph *out = n ? malloc(n * sizeof *out) : NULL;
    if (n && !out) {
        hb_buffer_destroy(buffer);
        return cg_error_set(err, CG_ENOMEM, "shape: out of memory");
    }
    for (unsigned i = 0; i < n; i++) {
        out[i].glyph = info[i].codepoint;
        out[i].cluster = info[i].cluster;
        out[i].x_advance = pos[i].x_advance;
        out[i].y_advance = pos[i].y_advance;
        out[i].x_offset = pos[i].x_offset;
        out[i].y_offset = pos[i].y_offset;
    }
    hb_buffer_destroy(buffer);
    *glyphs = out;
    *count = n;
    return CG_OK;
}
