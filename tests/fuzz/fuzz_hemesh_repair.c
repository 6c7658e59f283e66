/* libFuzzer target: the repairing half-edge build on any polygon soup.
 * Byte 0 gives the vertex count (1 to 32), placed on a 3 x 3 x 3 grid so
 * that positions coincide and faces line up with edges; then each face is
 * a size byte (1 to 8 corners) followed by its vertex bytes.  The input
 * counts must succeed, and when the repair builds: the structure validates,
 * its mesh builds strictly (manifold and oriented), and a second repair
 * gives the same mesh. */
#include "cg/hemesh.h"
#include "cg/mesh.h"

#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

static cg_mesh *soup(const unsigned char *data, size_t size)
{
    if (size < 2)
        return NULL;
    size_t V = (size_t)(data[0] % 32) + 1, F = 0, corners = 0;
    for (size_t i = 1; i < size;) {
        size_t n = (size_t)(data[i] % 8) + 1;
        if (i + 1 + n > size)
            break;
        F++;
        corners += n;
        i += 1 + n;
    }
    cg_mesh *m = NULL;
    if (!F || cg_mesh_create(&m, V, F, corners, 0) != CG_OK)
        return NULL;
    for (size_t v = 0; v < V; v++)
        m->positions[v] = cg_vec3_make((double)(v % 3), (double)(v / 3 % 3), (double)(v / 9 % 3));
    size_t f = 0, k = 0;
    for (size_t i = 1; f < F;) {
        size_t n = (size_t)(data[i] % 8) + 1;
        for (size_t j = 0; j < n; j++)
            m->face_indices[k++] = data[i + 1 + j] % (uint32_t)(V + 1); /* V is out of range */
        m->face_offsets[++f] = (uint32_t)k;
        i += 1 + n;
    }
    return m;
}

static cg_mesh *repaired(const cg_mesh *m)
{
    cg_hemesh *h = NULL;
    cg_error err;
    cg_status s = cg_hemesh_build(m, CG_HEMESH_REPAIR, &h, NULL, &err);
    if (s == CG_EEMPTY)
        return NULL;
    if (s != CG_OK || cg_hemesh_validate(h, &err) != CG_OK)
        abort();
    cg_mesh *out = NULL;
    if (cg_hemesh_to_mesh(h, &out) != CG_OK)
        abort();
    cg_hemesh_free(h);
    return out;
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    cg_mesh *m = soup(data, size);
    if (!m)
        return 0;
    cg_hemesh_input_counts counts;
    if (cg_hemesh_input_counts_compute(m, &counts) != CG_OK
        || counts.faces + counts.bad_faces != m->face_count)
        abort();
    cg_mesh *once = repaired(m);
    if (once) {
        cg_hemesh *strict = NULL;
        if (cg_hemesh_build(once, 0, &strict, NULL, NULL) != CG_OK)
            abort();
        cg_hemesh_free(strict);
        cg_mesh *twice = repaired(once);
        size_t corners = once->face_offsets[once->face_count];
        if (!twice || twice->vertex_count != once->vertex_count
            || twice->face_count != once->face_count
            || memcmp(twice->face_offsets, once->face_offsets,
                      (once->face_count + 1) * sizeof(uint32_t))
            || memcmp(twice->face_indices, once->face_indices, corners * sizeof(uint32_t)))
            abort();
        cg_mesh_free(twice);
        cg_mesh_free(once);
    }
    cg_mesh_free(m);
    return 0;
}
