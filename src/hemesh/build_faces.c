/* Step 1 of the half-edge build: which faces are usable (build.h). */
#include "build.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Step 1: which faces are usable. */

/* Whether face f is bad: fewer than 3 corners, a vertex out of range or a
 * vertex twice.  When it is and why is not NULL, why (160 bytes) receives
 * the reason.  *stamp is per-vertex scratch, allocated on first need for
 * faces too large to compare corner pairs. */
static cg_status face_is_bad(const cg_mesh *mesh, size_t f, uint32_t **stamp, char *why,
                             int *is_bad)
{
    uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
    const size_t why_size = 160;
    *is_bad = 1;
    if (end < begin || end - begin < 3) {
        if (why)
            snprintf(why, why_size, "has %ld corners, expected 3 or more", (long)end - (long)begin);
        return CG_OK;
    }
    for (uint32_t k = begin; k < end; k++)
        if (mesh->face_indices[k] >= mesh->vertex_count) {
            if (why)
                snprintf(why, why_size, "refers to vertex %u, but there are %zu",
                         mesh->face_indices[k], mesh->vertex_count);
            return CG_OK;
        }
    if (end - begin <= 8) {
        for (uint32_t i = begin; i < end; i++)
            for (uint32_t j = i + 1; j < end; j++)
                if (mesh->face_indices[i] == mesh->face_indices[j]) {
                    if (why)
                        snprintf(why, why_size, "repeats vertex %u", mesh->face_indices[i]);
                    return CG_OK;
                }
    } else {
        if (!*stamp && !(*stamp = calloc(mesh->vertex_count, sizeof **stamp)))
            return CG_ENOMEM;
        for (uint32_t k = begin; k < end; k++) {
            uint32_t v = mesh->face_indices[k];
            if ((*stamp)[v] == (uint32_t)f + 1) {
                if (why)
                    snprintf(why, why_size, "repeats vertex %u", v);
                return CG_OK;
            }
            (*stamp)[v] = (uint32_t)f + 1;
        }
    }
    *is_bad = 0;
    return CG_OK;
}

/* Lists the bad faces in increasing order into *list (*count of them in room
 * for *capacity), sums the corners of the others into *kept_corners, and
 * gives the first bad face's reason in why (160 bytes). */
static cg_status list_bad_faces(const cg_mesh *mesh, uint32_t **list, size_t *count,
                                size_t *capacity, size_t *kept_corners, char *why)
{
    uint32_t *stamp = NULL;
    int failed = 0;
    *kept_corners = 0;
    for (size_t f = 0; f < mesh->face_count && !failed; f++) {
        int is_bad;
        if (face_is_bad(mesh, f, &stamp, *count ? NULL : why, &is_bad) != CG_OK) {
            failed = 1;
        } else if (is_bad) {
            hm_list_push(list, count, capacity, (uint32_t)f, &failed);
        } else {
            *kept_corners += mesh->face_offsets[f + 1] - mesh->face_offsets[f];
        }
    }
    free(stamp);
    return failed ? CG_ENOMEM : CG_OK;
}

/* A private copy of the faces without the bad ones (bad_count of them,
 * listed in increasing order), and the map to the input faces. */
static cg_status copy_kept_faces(hm_builder *b, const uint32_t *bad, size_t bad_count)
{
    const cg_mesh *mesh = b->mesh;
    b->own_offsets = malloc((b->faces + 1) * sizeof *b->own_offsets);
    b->own_indices = malloc((b->corners ? b->corners : 1) * sizeof *b->own_indices);
    b->face_map = malloc(b->faces * sizeof *b->face_map);
    if (!b->own_offsets || !b->own_indices || !b->face_map)
        return cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    size_t nf = 0, k = 0, next_bad = 0;
    b->own_offsets[0] = 0;
    for (size_t f = 0; f < mesh->face_count; f++) {
        if (next_bad < bad_count && bad[next_bad] == f) {
            next_bad++;
            continue;
        }
        uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
        memcpy(b->own_indices + k, mesh->face_indices + begin,
               (end - begin) * sizeof *b->own_indices);
        k += end - begin;
        b->face_map[nf++] = (uint32_t)f;
        b->own_offsets[nf] = (uint32_t)k;
    }
    b->offsets = b->own_offsets;
    b->indices = b->own_indices;
    return CG_OK;
}

cg_status hm_build_check_faces(hm_builder *b)
{
    const cg_mesh *mesh = b->mesh;
    cg_hemesh_report *rep = b->report;
    /* The bad faces go into the report, or into a list of our own. */
    uint32_t *own_list = NULL;
    size_t own_count = 0, own_capacity = 0, kept_corners;
    uint32_t **list = rep ? &rep->bad_faces : &own_list;
    size_t *bad = rep ? &rep->bad_face_count : &own_count;
    size_t *capacity = rep ? &b->bad_face_capacity : &own_capacity;
    char why[160] = "";
    cg_status status = list_bad_faces(mesh, list, bad, capacity, &kept_corners, why);
    if (status != CG_OK)
        status = cg_error_set(b->err, CG_ENOMEM, "hemesh: out of memory");
    else if (*bad && !(b->flags & CG_HEMESH_DROP_BAD_FACES))
        status = cg_error_set(b->err, CG_EFORMAT,
                              "hemesh: face %u %s (%zu bad face%s in all; CG_HEMESH_DROP_BAD_FACES "
                              "leaves them out)",
                              (*list)[0], why, *bad, *bad == 1 ? "" : "s");
    else if (mesh->face_count == *bad)
        status = cg_error_set(b->err, CG_EEMPTY, "hemesh: the mesh has no usable faces (%zu given)",
                              mesh->face_count);
    else if (kept_corners > 0x7ffffffful)
        status = cg_error_set(b->err, CG_ERANGE, "hemesh: %zu face corners, at most 2^31 - 1",
                              kept_corners);
    if (status == CG_OK) {
        b->faces = mesh->face_count - *bad;
        b->corners = kept_corners;
        if (*bad) {
            status = copy_kept_faces(b, *list, *bad);
        } else {
            b->offsets = mesh->face_offsets;
            b->indices = mesh->face_indices;
        }
    }
    free(own_list);
    return status;
}
