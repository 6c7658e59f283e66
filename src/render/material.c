/* The materials of a mesh as the rasterizer's textured shading uses them:
 * the base-colour texture of each material read once (from its file, or
 * from the bytes the model embeds), its wrap modes and its texture
 * transform (KHR_texture_transform) taken to cg's texture space.  A texture
 * that cannot be read is a warning and leaves the material its colour. */
#include "pipeline.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Appends one line to the renderer's warnings (dropped when out of memory:
 * the picture is still drawn). */
static void warn(cg_renderer *r, const char *format, ...)
{
    char line[640];
    va_list args;
    va_start(args, format);
    vsnprintf(line, sizeof line, format, args);
    va_end(args);
    size_t old = r->warnings ? strlen(r->warnings) : 0, add = strlen(line);
    char *grown = realloc(r->warnings, old + add + 2);
    if (!grown)
        return;
    memcpy(grown + old, line, add);
    grown[old + add] = '\n';
    grown[old + add + 1] = '\0';
    r->warnings = grown;
}

/* glTF's transform acts on (s, t) = (u, 1 - v):
 *   (s', t') = offset + R diag(scale) (s, t),  R = [c s; -s c]
 * with c, s the cosine and sine of the rotation (the direction the
 * TextureTransformTest sample model's markers confirm); written for (u, v)
 * and v' = 1 - t', an affine map of (u, v). */
static void texture_transform(const cg_mesh_texture_ref *ref, float m[2][3])
{
    double c = cos(ref->rotation), s = sin(ref->rotation);
    double sx = ref->scale[0], sy = ref->scale[1], ox = ref->offset[0], oy = ref->offset[1];
    if (!isfinite(c) || !isfinite(s) || !isfinite(sx) || !isfinite(sy) || !isfinite(ox)
        || !isfinite(oy)) {
        c = 1, s = 0, sx = sy = 1, ox = oy = 0;
    }
    /* s' = c sx s + s sy t + ox,  t' = -s sx s + c sy t + oy */
    m[0][0] = (float)(c * sx);
    m[0][1] = (float)(-s * sy);
    m[0][2] = (float)(ox + s * sy);
    m[1][0] = (float)(s * sx);
    m[1][1] = (float)(c * sy);
    m[1][2] = (float)(1 - c * sy - oy);
}

static void load_base_texture(cg_renderer *r, const cg_mesh_material *m, render_material *out)
{
    const cg_mesh_texture_ref *ref = &m->base_color_map;
    cg_error err = {0};
    cg_status status;
    const char *name = ref->image_path ? ref->image_path : "(embedded image)";
    if (ref->image_bytes && ref->image_byte_count > 0)
        status = cg_texture_load_memory(ref->image_bytes, ref->image_byte_count, name,
                                        CG_TEXTURE_SRGB, &out->base_texture, &err);
    else if (ref->image_path)
        status = cg_texture_load(ref->image_path, CG_TEXTURE_SRGB, &out->base_texture, &err);
    else
        return;
    if (status != CG_OK) {
        out->base_texture = NULL;
        warn(r, "texture of material '%s': %s; drawn with the material's colour",
             m->name ? m->name : "", err.message[0] ? err.message : cg_status_str(status));
    }
}

cg_status render_materials_load(cg_renderer *r, const cg_mesh *mesh)
{
    if (!mesh->face_materials || mesh->material_count == 0 || !mesh->materials)
        return CG_OK;
    r->materials = calloc(mesh->material_count, sizeof *r->materials);
    r->face_material = malloc((mesh->face_count ? mesh->face_count : 1) * sizeof(uint32_t));
    if (!r->materials || !r->face_material)
        return CG_ENOMEM;
    r->material_count = mesh->material_count;
    for (size_t f = 0; f < mesh->face_count; f++) {
        uint32_t k = mesh->face_materials[f];
        r->face_material[f] = k < mesh->material_count ? k : RENDER_NO_MATERIAL;
        if (k < mesh->material_count && mesh->materials[k].alpha_mode == CG_MESH_ALPHA_BLEND)
            r->blended = 1;
    }
    for (size_t k = 0; k < mesh->material_count; k++) {
        const cg_mesh_material *m = &mesh->materials[k];
        render_material *out = &r->materials[k];
        out->wrap_u = m->base_color_map.wrap_u;
        out->wrap_v = m->base_color_map.wrap_v;
        texture_transform(&m->base_color_map, out->transform);
        out->alpha = m->base_color.a;
        out->alpha_cutoff = m->alpha_mode == CG_MESH_ALPHA_MASK ? (float)m->alpha_cutoff : 0;
        out->blend = m->alpha_mode == CG_MESH_ALPHA_BLEND;
        if (mesh->texcoords)
            load_base_texture(r, m, out);
        if (out->base_texture)
            r->textured = 1;
    }
    return CG_OK;
}

void render_materials_free(cg_renderer *r)
{
    for (size_t k = 0; k < r->material_count; k++)
        cg_texture_free(r->materials[k].base_texture);
    free(r->materials);
    free(r->face_material);
    free(r->warnings);
    r->materials = NULL;
    r->face_material = NULL;
    r->warnings = NULL;
    r->material_count = 0;
}

const char *cg_renderer_warnings(const cg_renderer *renderer)
{
    return renderer ? renderer->warnings : NULL;
}
