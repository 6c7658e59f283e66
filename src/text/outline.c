/* Glyph outlines: FT_Outline_Decompose into a per-font cache in font units,
 * then into cg paths at a size and origin (cg/text.h). */
#include "internal.h"
#include "../core/array.h"

#include FT_OUTLINE_H

#include <stdlib.h>

static int outline_push(text_outline *o, unsigned char op, const FT_Vector *a, const FT_Vector *b,
                        const FT_Vector *c)
{
    const FT_Vector *p[3] = {a, b, c};
    int n = op == 'M' || op == 'L' ? 1 : op == 'Q' ? 2 : op == 'C' ? 3 : 0;
    if (core_array_reserve((void **)&o->ops, &o->op_cap, o->op_count + 1, sizeof *o->ops) != CG_OK
        || core_array_reserve((void **)&o->pts, &o->pt_cap, o->pt_count + 2 * (size_t)n,
                              sizeof *o->pts)
               != CG_OK)
        return -1;
    o->ops[o->op_count++] = op;
    for (int i = 0; i < n; i++) {
        o->pts[o->pt_count++] = (double)p[i]->x;
        o->pts[o->pt_count++] = (double)p[i]->y;
    }
    return 0;
}

/* A contour ends where the next begins and at the end: closing it there
 * keeps FreeType's implicit closure. */
static int on_move(const FT_Vector *to, void *user)
{
    text_outline *o = user;
    if (o->op_count && o->ops[o->op_count - 1] != 'Z' && outline_push(o, 'Z', NULL, NULL, NULL))
        return -1;
    return outline_push(o, 'M', to, NULL, NULL);
}

static int on_line(const FT_Vector *to, void *user)
{
    return outline_push(user, 'L', to, NULL, NULL);
}

static int on_conic(const FT_Vector *c, const FT_Vector *to, void *user)
{
    return outline_push(user, 'Q', c, to, NULL);
}

static int on_cubic(const FT_Vector *c1, const FT_Vector *c2, const FT_Vector *to, void *user)
{
    return outline_push(user, 'C', c1, c2, to);
}

static cg_status outline_load(cg_font *font, unsigned glyph, text_outline **out, cg_error *err)
{
    if (glyph >= (unsigned)font->face->num_glyphs)
        return cg_error_set(err, CG_ERANGE, "glyph %u is beyond the font's %ld glyphs", glyph,
                            (long)font->face->num_glyphs);
    text_outline *o = &font->outlines[glyph];
    if (!o->loaded) {
        if (FT_Load_Glyph(font->face, glyph,
                          FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP
                              | FT_LOAD_IGNORE_TRANSFORM))
            return cg_error_set(err, CG_EFORMAT, "glyph %u cannot be read from the font", glyph);
        FT_GlyphSlot slot = font->face->glyph;
        if (slot->format == FT_GLYPH_FORMAT_OUTLINE) {
            static const FT_Outline_Funcs funcs = {on_move, on_line, on_conic, on_cubic, 0, 0};
            o->op_count = o->pt_count = 0;
            if (FT_Outline_Decompose(&slot->outline, &funcs, o)
                || (o->op_count && o->ops[o->op_count - 1] != 'Z'
                    && outline_push(o, 'Z', NULL, NULL, NULL)))
                return cg_error_set(err, CG_EFORMAT, "glyph %u has a broken outline", glyph);
        } else if (slot->format != FT_GLYPH_FORMAT_COMPOSITE) {
            return cg_error_set(err, CG_EFORMAT, "glyph %u is not an outline", glyph);
        }
        o->loaded = 1;
        font->cached++;
    }
    *out = o;
    return CG_OK;
}

cg_status cg_font_glyph_path(cg_font *font, unsigned glyph, double size, double x, double y,
                             cg_path *out, cg_error *err)
{
    if (!font || !out || !(size > 0) || size > 1e6)
        return cg_error_set(err, CG_EINVAL, "glyph path: no font, no path or bad size");
    text_outline *o = NULL;
    cg_status status = outline_load(font, glyph, &o, err);
    if (status != CG_OK)
        return status;
    double s = size / font->face->units_per_EM;
    const double *p = o->pts;
    for (size_t i = 0; i < o->op_count && status == CG_OK; i++) {
        switch (o->ops[i]) {
        case 'M':
            status = cg_path_move_to(out, x + s * p[0], y - s * p[1]);
            p += 2;
            break;
        case 'L':
            status = cg_path_line_to(out, x + s * p[0], y - s * p[1]);
            p += 2;
            break;
        case 'Q':
            status = cg_path_quad_to(out, x + s * p[0], y - s * p[1], x + s * p[2], y - s * p[3]);
            p += 4;
            break;
        case 'C':
            status = cg_path_cubic_to(out, x + s * p[0], y - s * p[1], x + s * p[2], y - s * p[3],
                                      x + s * p[4], y - s * p[5]);
            p += 6;
            break;
        default: status = cg_path_close(out); break;
        }
    }
    if (status != CG_OK)
        return cg_error_set(err, status, "glyph %u: outline out of range at this size", glyph);
    return CG_OK;
}
