/* Wavefront MTL material libraries into cg_mesh_material.
 *
 *   newmtl Hard Shiny Plastic        (names may hold spaces: the rest of the line)
 *   Kd 0.8 0.6 0.4                   base colour (one number: grey)
 *   Ks 0.9 0.9 0.9   Ns 40           specular colour and exponent
 *   Ke 1 0.5 0                       emissive colour
 *   d 0.5  or  Tr 0.5                opacity, or transparency = 1 - opacity
 *   illum 2                          illumination model
 *   map_Kd -s 2 2 -clamp on my wood.png    maps: options, then the file
 *   map_Ks, map_d, map_Ke, map_bump / bump (-bm amount), norm
 *
 * Colours are taken as linear (as OBJ exporters write them); files are
 * relative to the .mtl's directory ('\' read as '/').  A map whose file is
 * missing is a note naming it, and the material keeps its colour. */
#include "internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

typedef struct mtl_reader {
    text_cursor t;
    const char *directory; /* of the .mtl */
    cg_mesh_material *materials;
    unsigned char *has_kd;
    char **names;
    size_t count;
    char **notes;
    cg_error *err;
} mtl_reader;

/* The rest of the line, blanks trimmed, as [start, stop). */
static void line_rest(text_cursor *t, const char **start, const char **stop)
{
    text_skip_blanks(t);
    *start = t->p;
    const char *end = t->p;
    while (end < t->end && !is_line_end(*end))
        end++;
    while (end > *start && is_blank(end[-1]))
        end--;
    *stop = end;
    t->p = end;
}

static cg_status read_color(mtl_reader *r, const char *key, cg_rgbaf *out)
{
    text_skip_blanks(&r->t);
    if (r->t.p < r->t.end && (*r->t.p == 's' || *r->t.p == 'x')) /* spectral / CIE XYZ */
        return CG_OK;
    double c[3];
    char what[40];
    snprintf(what, sizeof what, "a red value after %s", key);
    cg_status s = text_double(&r->t, &c[0], what, r->err);
    if (s != CG_OK)
        return s;
    c[1] = c[2] = c[0];
    if (!text_at_line_end(&r->t)
        && ((s = text_double(&r->t, &c[1], "a green value", r->err)) != CG_OK
            || (s = text_double(&r->t, &c[2], "a blue value", r->err)) != CG_OK))
        return s;
    out->r = (float)c[0];
    out->g = (float)c[1];
    out->b = (float)c[2];
    return CG_OK;
}

/* Up to 3 numbers after an option (-o, -s, -t); fewer when the next word is
 * not a number. */
static int option_numbers(text_cursor *t, double *values)
{
    int n = 0;
    while (n < 3) {
        text_skip_blanks(t);
        if (!parse_double(&t->p, t->end, &values[n]))
            break;
        n++;
    }
    return n;
}

/* The map file, resolved against the .mtl's directory. */
static char *map_path(const mtl_reader *r, const char *start, const char *stop)
{
    size_t n = (size_t)(stop - start), dn = strlen(r->directory);
    int absolute = n && (*start == '/' || *start == '\\');
    char *path = malloc(dn + n + 2);
    if (!path)
        return NULL;
    size_t k = 0;
    if (!absolute) {
        memcpy(path, r->directory, dn);
        k = dn;
        path[k++] = '/';
    }
    for (size_t i = 0; i < n; i++)
        path[k++] = start[i] == '\\' ? '/' : start[i];
    path[k] = '\0';
    return path;
}

/* A map line: options, then the file name (the rest of the line). */
static cg_status read_map(mtl_reader *r, size_t m, const char *key, cg_mesh_texture_ref *map)
{
    for (;;) {
        text_skip_blanks(&r->t);
        if (r->t.p >= r->t.end || *r->t.p != '-')
            break;
        const char *word = r->t.p;
        while (r->t.p < r->t.end && !is_space(*r->t.p))
            r->t.p++;
        size_t length = (size_t)(r->t.p - word);
        double values[3] = {0, 0, 0};
#define OPTION(name) (length == sizeof name - 1 && memcmp(word, name, length) == 0)
        if (OPTION("-bm") || OPTION("-boost") || OPTION("-texres")) {
            cg_status s = text_double(&r->t, &values[0], "a number after the option", r->err);
            if (s != CG_OK)
                return s;
            if (OPTION("-bm"))
                map->amount = values[0];
        } else if (OPTION("-mm")) {
            option_numbers(&r->t, values);
        } else if (OPTION("-o") || OPTION("-s") || OPTION("-t")) {
            int n = option_numbers(&r->t, values);
            if (n == 0)
                return text_expected(&r->t, "1 to 3 numbers after the option", r->err);
            if (n == 1)
                values[1] = OPTION("-s") ? 1 : 0;
            /* OBJ's uv' = s uv + o (origin bottom-left) in cg_mesh_texture_ref's
             * glTF space (v_gltf = 1 - v): scale s, offset (o_u, 1 - s_v - o_v) */
            if (OPTION("-o")) {
                map->offset[0] = values[0];
                map->offset[1] = 1 - map->scale[1] - values[1];
            } else if (OPTION("-s")) {
                double old_offset_v = 1 - map->scale[1] - map->offset[1];
                map->scale[0] = values[0];
                map->scale[1] = values[1];
                map->offset[1] = 1 - values[1] - old_offset_v;
            }
        } else if (OPTION("-blendu") || OPTION("-blendv") || OPTION("-cc") || OPTION("-clamp")
                   || OPTION("-imfchan") || OPTION("-type")) {
            text_skip_blanks(&r->t);
            const char *value = r->t.p;
            while (r->t.p < r->t.end && !is_space(*r->t.p))
                r->t.p++;
            if (OPTION("-clamp") && r->t.p - value == 2 && memcmp(value, "on", 2) == 0)
                map->wrap_u = map->wrap_v = CG_TEXTURE_CLAMP;
        } else {
            r->t.p = word;
            break; /* not an option: a file name that starts with '-' */
        }
#undef OPTION
    }
    const char *start, *stop;
    line_rest(&r->t, &start, &stop);
    if (start == stop)
        return text_expected(&r->t, "a texture file name", r->err);
    char *path = map_path(r, start, stop);
    if (!path)
        return cg_error_set(r->err, CG_ENOMEM, "%s: out of memory", r->t.name);
    if (access(path, R_OK) != 0) {
        cg_status s = mesh_note(r->notes,
                                "%s:%zu: %s file %s not found; material '%s' keeps its "
                                "colour",
                                r->t.name, r->t.line, key, path, r->names[m]);
        free(path);
        return s == CG_OK ? CG_OK : cg_error_set(r->err, s, "%s: out of memory", r->t.name);
    }
    free(map->image_path);
    map->image_path = path;
    return CG_OK;
}

static int is_key(const char *word, size_t length, const char *key)
{
    return length == strlen(key) && memcmp(word, key, length) == 0;
}

/* One statement of the material m (SIZE_MAX: a material no face uses). */
static cg_status read_statement(mtl_reader *r, size_t m, const char *word, size_t length)
{
    if (m == SIZE_MAX)
        return CG_OK;
    cg_mesh_material *mat = &r->materials[m];
    double value;
    cg_status s = CG_OK;
    if (is_key(word, length, "Kd")) {
        s = read_color(r, "Kd", &mat->base_color);
        r->has_kd[m] = 1;
    } else if (is_key(word, length, "Ks")) {
        s = read_color(r, "Ks", &mat->specular);
    } else if (is_key(word, length, "Ke")) {
        s = read_color(r, "Ke", &mat->emissive);
    } else if (is_key(word, length, "Ns")) {
        s = text_double(&r->t, &mat->shininess, "a number after Ns", r->err);
    } else if (is_key(word, length, "d") || is_key(word, length, "Tr")) {
        text_skip_blanks(&r->t);
        if (r->t.end - r->t.p >= 5 && memcmp(r->t.p, "-halo", 5) == 0)
            r->t.p += 5;
        s = text_double(&r->t, &value, "an opacity in [0, 1]", r->err);
        if (s == CG_OK) {
            double opacity = word[0] == 'd' ? value : 1 - value;
            opacity = opacity < 0 ? 0 : opacity > 1 ? 1 : opacity;
            mat->base_color.a = (float)opacity;
            mat->alpha_mode = opacity < 1 ? CG_MESH_ALPHA_BLEND : CG_MESH_ALPHA_OPAQUE;
        }
    } else if (is_key(word, length, "illum")) {
        int64_t illum;
        text_skip_blanks(&r->t);
        if (!parse_int64(&r->t.p, r->t.end, &illum) || illum < 0 || illum > 10)
            return text_expected(&r->t, "an illumination model 0 to 10 after illum", r->err);
        mat->illum = (int)illum;
    } else if (is_key(word, length, "map_Kd")) {
        s = read_map(r, m, "map_Kd", &mat->base_color_map);
    } else if (is_key(word, length, "map_Ks")) {
        s = read_map(r, m, "map_Ks", &mat->specular_map);
    } else if (is_key(word, length, "map_Ke")) {
        s = read_map(r, m, "map_Ke", &mat->emissive_map);
    } else if (is_key(word, length, "map_d")) {
        s = read_map(r, m, "map_d", &mat->alpha_map);
    } else if (is_key(word, length, "map_bump") || is_key(word, length, "bump")
               || is_key(word, length, "map_Bump")) {
        s = read_map(r, m, "bump", &mat->bump_map);
    } else if (is_key(word, length, "norm") || is_key(word, length, "map_Kn")) {
        s = read_map(r, m, "norm", &mat->normal_map);
    }
    return s;
}

static cg_status parse(mtl_reader *r)
{
    size_t current = SIZE_MAX;
    while (r->t.p < r->t.end) {
        text_skip_blanks(&r->t);
        const char *word = r->t.p;
        while (r->t.p < r->t.end && !is_space(*r->t.p))
            r->t.p++;
        size_t length = (size_t)(r->t.p - word);
        cg_status s = CG_OK;
        if (is_key(word, length, "newmtl")) {
            const char *start, *stop;
            line_rest(&r->t, &start, &stop);
            current = SIZE_MAX;
            for (size_t m = 0; m < r->count; m++)
                if (strlen(r->names[m]) == (size_t)(stop - start)
                    && memcmp(r->names[m], start, (size_t)(stop - start)) == 0)
                    current = m;
        } else if (length && word[0] != '#') {
            s = read_statement(r, current, word, length);
        }
        if (s != CG_OK)
            return s;
        text_next_line(&r->t);
    }
    return CG_OK;
}

cg_status mtl_read_library(const char *path, char **names, size_t count,
                           cg_mesh_material *materials, unsigned char *has_kd, char **notes,
                           cg_error *err, int *found)
{
    unsigned char *bytes = NULL;
    size_t size = 0;
    *found = mesh_read_file(path, &bytes, &size, NULL) == CG_OK;
    if (!*found)
        return CG_OK;
    const char *slash = strrchr(path, '/');
    char *directory = slash ? malloc((size_t)(slash - path) + 2) : NULL;
    if (slash && !directory) {
        free(bytes);
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    }
    if (directory) {
        size_t n = slash == path ? 1 : (size_t)(slash - path);
        memcpy(directory, path, n);
        directory[n] = '\0';
    }
    mtl_reader r = {{(const char *)bytes, (const char *)bytes + size, path, 1},
                    directory ? directory : ".",
                    materials,
                    has_kd,
                    names,
                    count,
                    notes,
                    err};
    cg_status s = parse(&r);
    free(directory);
    free(bytes);
    return s;
}
