/* Generated meshes: sphere, torus, box. */
#include "internal.h"

static uint32_t grid_index(int i, int j, int columns)
{
    return (uint32_t)(i * columns + j);
}

cg_status cg_mesh_sphere(int slices, int stacks, double radius, cg_mesh **out)
{
    if (!out || slices < 3 || stacks < 2 || slices > 32768 || stacks > 32768 || !(radius > 0)
        || !isfinite(radius))
        return CG_EINVAL;
    size_t vertices = 2 + (size_t)slices * (size_t)(stacks - 1);
    size_t faces = (size_t)slices * (size_t)stacks;
    size_t corners = (size_t)slices * 3 * 2 + (size_t)slices * (size_t)(stacks - 2) * 4;
    cg_status status = cg_mesh_create(out, vertices, faces, corners, 0);
    if (status != CG_OK)
        return status;
    cg_mesh *m = *out;
    uint32_t top = (uint32_t)(vertices - 2), bottom = (uint32_t)(vertices - 1);
    for (int i = 1; i < stacks; i++) {
        double phi = CG_PI * i / stacks;
        for (int j = 0; j < slices; j++) {
            double theta = 2 * CG_PI * j / slices;
            m->positions[grid_index(i - 1, j, slices)] = cg_vec3_make(
                radius * sin(phi) * cos(theta), radius * cos(phi), -radius * sin(phi) * sin(theta));
        }
    }
    m->positions[top] = cg_vec3_make(0, radius, 0);
    m->positions[bottom] = cg_vec3_make(0, -radius, 0);
    size_t f = 0, k = 0;
    for (int i = 0; i < stacks; i++)
        for (int j = 0; j < slices; j++) {
            int j1 = (j + 1) % slices;
            m->face_offsets[f] = (uint32_t)k;
            if (i == 0) {
                m->face_indices[k++] = top;
                m->face_indices[k++] = grid_index(0, j, slices);
                m->face_indices[k++] = grid_index(0, j1, slices);
            } else if (i == stacks - 1) {
                m->face_indices[k++] = grid_index(i - 1, j, slices);
                m->face_indices[k++] = bottom;
                m->face_indices[k++] = grid_index(i - 1, j1, slices);
            } else {
                m->face_indices[k++] = grid_index(i - 1, j, slices);
                m->face_indices[k++] = grid_index(i, j, slices);
                m->face_indices[k++] = grid_index(i, j1, slices);
                m->face_indices[k++] = grid_index(i - 1, j1, slices);
            }
            f++;
        }
    m->face_offsets[f] = (uint32_t)k;
    return CG_OK;
}

cg_status cg_mesh_torus(int major_segments, int minor_segments, double major_radius,
                        double minor_radius, cg_mesh **out)
{
    if (!out || major_segments < 3 || minor_segments < 3 || major_segments > 32768
        || minor_segments > 32768 || !(major_radius > 0) || !(minor_radius > 0)
        || !isfinite(major_radius) || !isfinite(minor_radius))
        return CG_EINVAL;
    size_t count = (size_t)major_segments * (size_t)minor_segments;
    cg_status status = cg_mesh_create(out, count, count, count * 4, 0);
    if (status != CG_OK)
        return status;
    cg_mesh *m = *out;
    for (int i = 0; i < major_segments; i++) {
        double u = 2 * CG_PI * i / major_segments;
        for (int j = 0; j < minor_segments; j++) {
            double v = 2 * CG_PI * j / minor_segments;
            double ring = major_radius + minor_radius * cos(v);
            m->positions[grid_index(i, j, minor_segments)] = cg_vec3_make(
                ring * cos(u), minor_radius * sin(v), -ring * sin(u));
        }
    }
    size_t f = 0;
    for (int i = 0; i < major_segments; i++)
        for (int j = 0; j < minor_segments; j++) {
            int i1 = (i + 1) % major_segments, j1 = (j + 1) % minor_segments;
            m->face_offsets[f] = (uint32_t)(f * 4);
            uint32_t *q = &m->face_indices[f * 4];
            q[0] = grid_index(i, j, minor_segments);
            q[1] = grid_index(i1, j, minor_segments);
            q[2] = grid_index(i1, j1, minor_segments);
            q[3] = grid_index(i, j1, minor_segments);
            f++;
        }
    m->face_offsets[f] = (uint32_t)(f * 4);
    return CG_OK;
}

cg_status cg_mesh_box(cg_vec3 lo, cg_vec3 hi, cg_mesh **out)
{
    if (!out || !(lo.x < hi.x) || !(lo.y < hi.y) || !(lo.z < hi.z) || !isfinite(lo.x)
        || !isfinite(lo.y) || !isfinite(lo.z) || !isfinite(hi.x) || !isfinite(hi.y)
        || !isfinite(hi.z))
        return CG_EINVAL;
    cg_status status = cg_mesh_create(out, 8, 6, 24, 0);
    if (status != CG_OK)
        return status;
    cg_mesh *m = *out;
    for (int i = 0; i < 8; i++)
        m->positions[i] = cg_vec3_make(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y,
                                       i & 4 ? hi.z : lo.z);
    /* Counter-clockwise seen from outside. */
    static const uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (int f = 0; f < 6; f++) {
        m->face_offsets[f] = (uint32_t)(f * 4);
        for (int k = 0; k < 4; k++)
            m->face_indices[f * 4 + k] = quads[f][k];
    }
    m->face_offsets[6] = 24;
    return CG_OK;
}
