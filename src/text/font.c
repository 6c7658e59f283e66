/* Fonts: FreeType faces over the file's bytes, fontconfig look-up, and the
 * glyph-outline cache (cg/text.h). */
#include "internal.h"
#include "../core/array.h"

#include FT_OUTLINE_H
#include <fontconfig/fontconfig.h>
#include <pthread.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* The largest font file accepted (fonts of CJK scripts reach ~30 MB). */
#define TEXT_MAX_FONT_BYTES ((size_t)256 << 20)

static cg_status font_from_bytes(unsigned char *data, size_t size, int face_index, const char *name,
                                 cg_font **out, cg_error *err)
{
    cg_font *font = calloc(1, sizeof *font);
    if (!font) {
        free(data);
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", name);
    }
    font->data = data;
    font->size = size;
    if (FT_Init_FreeType(&font->library)) {
        cg_font_free(font);
        return cg_error_set(err, CG_ENOMEM, "%s: FreeType could not start", name);
    }
    FT_Face probe;
    if (FT_New_Memory_Face(font->library, data, (FT_Long)size, -1, &probe)) {
        cg_font_free(font);
        return cg_error_set(err, CG_EFORMAT, "%s: not a font file (TTF, OTF or TTC)", name);
    }
    long faces = probe->num_faces;
    FT_Done_Face(probe);
    if (face_index < 0 || face_index >= faces) {
        cg_font_free(font);
        return cg_error_set(err, CG_ERANGE, "%s: face %d does not exist (the file has %ld)", name,
                            face_index, faces);
    }
    if (FT_New_Memory_Face(font->library, data, (FT_Long)size, face_index, &font->face)) {
        cg_font_free(font);
        return cg_error_set(err, CG_EFORMAT, "%s: face %d cannot be read", name, face_index);
    }
    if (!FT_IS_SCALABLE(font->face) || font->face->units_per_EM == 0
        || font->face->num_glyphs <= 0) {
        cg_font_free(font);
        return cg_error_set(err, CG_EFORMAT, "%s: the font has no scalable outlines", name);
    }
    font->outlines = calloc((size_t)font->face->num_glyphs, sizeof *font->outlines);
    font->blob = hb_blob_create((const char *)data, (unsigned)size, HB_MEMORY_MODE_READONLY, NULL,
                                NULL);
    font->hb_face = hb_face_create(font->blob, (unsigned)face_index);
    font->hb_font = hb_font_create(font->hb_face);
    if (!font->outlines || !font->hb_font || hb_font_get_empty() == font->hb_font) {
        cg_font_free(font);
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", name);
    }
    *out = font;
    return CG_OK;
}

cg_status cg_font_load_memory(const void *data, size_t size, int face_index, cg_font **out,
                              cg_error *err)
{
    if (!out || (!data && size))
        return cg_error_set(err, CG_EINVAL, "font: no data");
    *out = NULL;
    if (size == 0)
        return cg_error_set(err, CG_EFORMAT, "font: empty data is not a font");
    if (size > TEXT_MAX_FONT_BYTES)
        return cg_error_set(err, CG_ERANGE, "font: %zu bytes is larger than any font", size);
    unsigned char *copy = malloc(size);
    if (!copy)
        return cg_error_set(err, CG_ENOMEM, "font: out of memory");
    memcpy(copy, data, size);
    return font_from_bytes(copy, size, face_index, "font", out, err);
}

cg_status cg_font_load(const char *path, int face_index, cg_font **out, cg_error *err)
{
    if (!path || !out)
        return cg_error_set(err, CG_EINVAL, "font: no file name");
    *out = NULL;
    FILE *file = fopen(path, "rb");
    if (!file)
        return cg_error_set(err, CG_EIO, "%s: cannot open the font file", path);
    unsigned char *data = NULL;
    size_t size = 0, cap = 0;
    for (;;) {
        if (size == cap) {
            cg_status grown = size < TEXT_MAX_FONT_BYTES
                                  ? core_array_reserve((void **)&data, &cap, size + 65536, 1)
                                  : CG_ERANGE;
            if (grown != CG_OK) {
                free(data);
                fclose(file);
                return cg_error_set(err, grown, "%s: font file too large", path);
            }
            if (cap > TEXT_MAX_FONT_BYTES)
                cap = TEXT_MAX_FONT_BYTES; /* read no more than the limit */
        }
        size_t got = fread(data + size, 1, cap - size, file);
        size += got;
        if (got == 0)
            break;
    }
    int failed = ferror(file);
    fclose(file);
    if (failed || size == 0) {
        free(data);
        return cg_error_set(
            err, failed ? CG_EIO : CG_EFORMAT,
            failed ? "%s: cannot read the font file" : "%s: empty file is not a font", path);
    }
    return font_from_bytes(data, size, face_index, path, out, err);
}

void cg_font_free(cg_font *font)
{
    if (!font)
        return;
    if (font->outlines) {
        for (long g = 0; g < font->face->num_glyphs; g++) {
            free(font->outlines[g].ops);
            free(font->outlines[g].pts);
        }
        free(font->outlines);
    }
    if (font->hb_font)
        hb_font_destroy(font->hb_font);
    if (font->hb_face)
        hb_face_destroy(font->hb_face);
    if (font->blob)
        hb_blob_destroy(font->blob);
    if (font->face)
        FT_Done_Face(font->face);
    if (font->library)
        FT_Done_FreeType(font->library);
    free(font->data);
    free(font);
}

int cg_font_units_per_em(const cg_font *font)
{
    return font ? font->face->units_per_EM : 0;
}

int cg_font_glyph_count(const cg_font *font)
{
    return font ? (int)font->face->num_glyphs : 0;
}

void cg_font_metrics(const cg_font *font, int *ascender, int *descender, int *line_gap)
{
    int a = font ? font->face->ascender : 0, d = font ? font->face->descender : 0;
    int h = font ? font->face->height : 0;
    if (ascender)
        *ascender = a;
    if (descender)
        *descender = d;
    if (line_gap)
        *line_gap = h - (a - d) > 0 ? h - (a - d) : 0;
}

size_t cg_font_cached_glyphs(const cg_font *font)
{
    return font ? font->cached : 0;
}

/* ---- font look-up ----------------------------------------------------------- */

/* fontconfig's configuration, loaded once per process: reading the
 * configuration files and scanning the font cache took a few milliseconds
 * on every lookup.  cg keeps its own (not fontconfig's current one, which
 * the program may set or free), destroyed at exit (or when libcg is
 * unloaded): fontconfig keeps pointers to some of its blocks in its mapped
 * cache files only, where a leak checker would not see them.  NULL when
 * fontconfig cannot start. */
static FcConfig *loaded_config;
static pthread_once_t config_once = PTHREAD_ONCE_INIT;

static void free_config(void)
{
    FcConfigDestroy(loaded_config);
    loaded_config = NULL;
}

static void load_config(void)
{
    loaded_config = FcInitLoadConfigAndFonts();
    if (loaded_config)
        atexit(free_config);
}

static FcConfig *font_config(void)
{
    pthread_once(&config_once, load_config);
    return loaded_config;
}

static int fc_weight(int css)
{
    return (int)FcWeightFromOpenTypeDouble(css < 1 ? 400 : css > 1000 ? 1000 : css);
}

cg_status cg_font_find(const char *family, int weight, int italic, char *path, size_t cap,
                       int *face_index, cg_error *err)
{
    if (!family || !path || !cap || !face_index)
        return cg_error_set(err, CG_EINVAL, "font: no family name");
    FcConfig *config = font_config();
    FcPattern *pattern = config ? FcPatternCreate() : NULL;
    if (!pattern)
        return cg_error_set(err, CG_ENOMEM, "font %s: fontconfig could not start", family);
    FcPatternAddString(pattern, FC_FAMILY, (const FcChar8 *)family);
    FcPatternAddInteger(pattern, FC_WEIGHT, fc_weight(weight));
    FcPatternAddInteger(pattern, FC_SLANT, italic ? FC_SLANT_ITALIC : FC_SLANT_ROMAN);
    FcPatternAddBool(pattern, FC_SCALABLE, FcTrue);
    FcConfigSubstitute(config, pattern, FcMatchPattern);
    FcDefaultSubstitute(pattern);
    FcResult result;
    FcPattern *match = FcFontMatch(config, pattern, &result);
    FcChar8 *file = NULL;
    int index = 0;
    cg_status status = CG_OK;
    if (!match || FcPatternGetString(match, FC_FILE, 0, &file) != FcResultMatch)
        status = cg_error_set(err, CG_EEMPTY, "font %s: fontconfig knows no font", family);
    else if (strlen((const char *)file) >= cap)
        status = cg_error_set(err, CG_ERANGE, "font %s: file name too long", family);
    else {
        if (FcPatternGetInteger(match, FC_INDEX, 0, &index) != FcResultMatch)
            index = 0;
        memcpy(path, file, strlen((const char *)file) + 1);
        *face_index = index;
    }
    if (match)
        FcPatternDestroy(match);
    FcPatternDestroy(pattern);
    return status;
}

/* The generic families fontconfig resolves through its configuration. */
static int is_generic_family(const char *name)
{
    static const char *const generic[] = {"serif",   "sans-serif", "monospace", "cursive",
                                          "fantasy", "system-ui",  "sans",      "mono"};
    for (size_t i = 0; i < sizeof generic / sizeof *generic; i++)
        if (strcasecmp(name, generic[i]) == 0)
            return 1;
    return 0;
}

cg_status cg_font_family_exists(const char *family, cg_error *err)
{
    if (!family || !*family)
        return cg_error_set(err, CG_EINVAL, "font: no family name");
    if (is_generic_family(family))
        return CG_OK;
    FcConfig *config = font_config();
    FcPattern *pattern = config ? FcPatternCreate() : NULL;
    FcObjectSet *objects = pattern ? FcObjectSetBuild(FC_FILE, (char *)NULL) : NULL;
    FcFontSet *set = NULL;
    if (objects) {
        FcPatternAddString(pattern, FC_FAMILY, (const FcChar8 *)family);
        FcPatternAddBool(pattern, FC_SCALABLE, FcTrue);
        set = FcFontList(config, pattern, objects);
    }
    cg_status status = CG_OK;
    if (!set)
        status = cg_error_set(err, CG_ENOMEM, "font %s: fontconfig could not start", family);
    else if (set->nfont == 0)
        status = cg_error_set(err, CG_EEMPTY, "no font of the family '%s' is installed", family);
    if (set)
        FcFontSetDestroy(set);
    if (objects)
        FcObjectSetDestroy(objects);
    if (pattern)
        FcPatternDestroy(pattern);
    return status;
}

cg_status cg_font_open(const char *family_or_file, int weight, int italic, cg_font **out,
                       cg_error *err)
{
    if (!family_or_file || !out)
        return cg_error_set(err, CG_EINVAL, "font: no name");
    struct stat st;
    if (stat(family_or_file, &st) == 0 && S_ISREG(st.st_mode))
        return cg_font_load(family_or_file, 0, out, err);
    char path[4096];
    int index;
    cg_status status = cg_font_find(family_or_file, weight, italic, path, sizeof path, &index, err);
    if (status != CG_OK)
        return status;
    return cg_font_load(path, index, out, err);
}
