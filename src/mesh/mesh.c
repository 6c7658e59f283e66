/* The indexed mesh: allocation, validation, bounds. */
#include "cg/mesh.h"

#include <stdlib.h>
#include <string.h>

static void *zeroed(size_t count, size_t size)
{
    return calloc(count ? count : 1, size);
}

cg_status cg_mesh_create(cg_mesh **out, size_t vertex_count, size_t face_count, size_t index_count,
                         unsigned flags)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if (vertex_count > CG_MESH_MAX_VERTICES || index_count > CG_MESH_MAX_INDICES
        || face_count > CG_MESH_MAX_INDICES)
        return CG_ERANGE;
    cg_mesh *m = calloc(1, sizeof *m);
    if (!m)
        return CG_ENOMEM;
    m->vertex_count = vertex_count;
    m->face_count = face_count;
    m->positions = zeroed(vertex_count, sizeof *m->positions);
    m->face_offsets = zeroed(face_count + 1, sizeof *m->face_offsets);
    m->face_indices = zeroed(index_count, sizeof *m->face_indices);
    int failed = !m->positions || !m->face_offsets || !m->face_indices;
    if (flags & CG_MESH_NORMALS)
        failed |= !(m->normals = zeroed(vertex_count, sizeof *m->normals));
    if (flags & CG_MESH_TEXCOORDS)
        failed |= !(m->texcoords = zeroed(vertex_count, sizeof *m->texcoords));
    if (flags & CG_MESH_COLORS)
        failed |= !(m->colors = zeroed(vertex_count, sizeof *m->colors));
    if (flags & CG_MESH_FACE_COLORS)
        failed |= !(m->face_colors = zeroed(face_count, sizeof *m->face_colors));
    if (failed) {
        cg_mesh_free(m);
        return CG_ENOMEM;
    }
    *out = m;
    return CG_OK;
}

void cg_mesh_free(cg_mesh *mesh)
{
    if (!mesh)
        return;
    free(mesh->positions);
    free(mesh->normals);
    free(mesh->texcoords);
    free(mesh->colors);
    free(mesh->face_offsets);
    free(mesh->face_indices);
    free(mesh->face_colors);
    for (size_t i = 0; i < mesh->material_count; i++)
        cg_mesh_material_clear(&mesh->materials[i]);
    free(mesh->materials);
    free(mesh->face_materials);
    free(mesh->notes);
    free(mesh);
}

static void texture_ref_clear(cg_mesh_texture_ref *t)
{
    free(t->image_path);
    free(t->image_bytes);
    t->image_path = NULL;
    t->image_bytes = NULL;
    t->image_byte_count = 0;
}

void cg_mesh_material_clear(cg_mesh_material *material)
{
    if (!material)
        return;
    free(material->name);
    cg_mesh_texture_ref *maps[] = {&material->base_color_map, &material->specular_map,
                                   &material->alpha_map,      &material->bump_map,
                                   &material->normal_map,     &material->metallic_roughness_map,
                                   &material->occlusion_map,  &material->emissive_map};
    for (size_t i = 0; i < sizeof maps / sizeof maps[0]; i++)
        texture_ref_clear(maps[i]);
    memset(material, 0, sizeof *material);
}

cg_mesh_material cg_mesh_material_default(void)
{
    cg_mesh_material m;
    memset(&m, 0, sizeof m);
    cg_rgbaf white = {1, 1, 1, 1}, black = {0, 0, 0, 1};
    m.base_color = white;
    m.specular = black;
    m.emissive = black;
    m.illum = 2;
    m.metallic = 1;
    m.roughness = 1;
    m.alpha_cutoff = 0.5;
    cg_mesh_texture_ref empty;
    memset(&empty, 0, sizeof empty);
    empty.scale[0] = empty.scale[1] = 1;
    empty.amount = 1;
    empty.encoding = CG_TEXTURE_SRGB;
    empty.wrap_u = empty.wrap_v = CG_TEXTURE_REPEAT;
    m.base_color_map = m.specular_map = m.emissive_map = empty;
    empty.encoding = CG_TEXTURE_LINEAR;
    m.alpha_map = m.bump_map = m.normal_map = m.metallic_roughness_map = m.occlusion_map = empty;
    return m;
}

cg_status cg_mesh_validate(const cg_mesh *mesh, cg_error *err)
{
    if (!mesh)
        return cg_error_set(err, CG_EINVAL, "mesh: none given");
    for (size_t v = 0; v < mesh->vertex_count; v++) {
        cg_vec3 p = mesh->positions[v];
        int axis = !isfinite(p.x) ? 0 : !isfinite(p.y) ? 1 : !isfinite(p.z) ? 2 : -1;
        if (axis >= 0)
            return cg_error_set(err, CG_EFORMAT,
                                "mesh: vertex %zu: expected finite coordinates, got %c = %g", v,
                                "xyz"[axis],
                                axis == 0   ? p.x
                                : axis == 1 ? p.y
                                            : p.z);
    }
    return cg_mesh_validate_topology(mesh, err);
}

cg_status cg_mesh_validate_topology(const cg_mesh *mesh, cg_error *err)
{
    if (!mesh)
        return cg_error_set(err, CG_EINVAL, "mesh: none given");
    if (mesh->face_offsets[0] != 0)
        return cg_error_set(err, CG_EFORMAT, "mesh: face offsets must start at 0");
    for (size_t f = 0; f < mesh->face_count; f++) {
        uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
        if (end < begin || end - begin < 3)
            return cg_error_set(err, CG_EFORMAT,
                                "mesh: face %zu has %ld corners, expected 3 or more", f,
                                (long)end - (long)begin);
        for (uint32_t k = begin; k < end; k++)
            if (mesh->face_indices[k] >= mesh->vertex_count)
                return cg_error_set(err, CG_EFORMAT,
                                    "mesh: face %zu refers to vertex %u, but there are %zu", f,
                                    mesh->face_indices[k], mesh->vertex_count);
    }
    return CG_OK;
}

cg_status cg_mesh_bounds(const cg_mesh *mesh, cg_vec3 *lo, cg_vec3 *hi)
{
    int any = 0;
    cg_vec3 a = {0, 0, 0}, b = {0, 0, 0};
    for (size_t i = 0; mesh && i < mesh->vertex_count; i++) {
        cg_vec3 p = mesh->positions[i];
        if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(p.z))
            continue;
        if (!any) {
            a = b = p;
            any = 1;
            continue;
        }
        a = cg_vec3_make(fmin(a.x, p.x), fmin(a.y, p.y), fmin(a.z, p.z));
        b = cg_vec3_make(fmax(b.x, p.x), fmax(b.y, p.y), fmax(b.z, p.z));
    }
    if (!any)
        return CG_EEMPTY;
    *lo = a;
    *hi = b;
    return CG_OK;
}

size_t cg_mesh_triangle_count(const cg_mesh *mesh)
{
    size_t n = 0;
    for (size_t f = 0; f < mesh->face_count; f++) {
        uint32_t size = cg_mesh_face_size(mesh, f);
        if (size >= 3)
            n += size - 2;
    }
    return n;
}
