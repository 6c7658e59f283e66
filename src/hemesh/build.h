/* The steps of the half-edge build (build.c) and the state they share.
 *
 *   build_faces.c     step 1: which faces are usable
 *   build.c           steps 2 and 3: matching the twins, orienting; the entry point
 *   build_assemble.c  step 4: the structure itself
 */
#ifndef CG_HEMESH_BUILD_H
#define CG_HEMESH_BUILD_H

#include "internal.h"
#include "../core/array.h"

#include <stddef.h>
#include <stdint.h>

/* The state of one build, shared by its steps. */
typedef struct hm_builder {
    const cg_mesh *mesh;
    unsigned flags;
    cg_hemesh_report *report;
    cg_error *err;
    /* the working faces: kept faces, possibly reversed */
    size_t faces, corners;
    const uint32_t *offsets, *indices;
    uint32_t *own_offsets, *own_indices, *face_map;
    /* matching */
    uint32_t *corner_halfedge; /* corners */
    uint32_t *edge_vertices;   /* 2 per edge: origin of 2e and of 2e + 1 */
    size_t edges;
    size_t nonmanifold, misoriented, cut;
    uint32_t *cut_edges; /* the cut edges opened, cut of them */
    uint32_t first_nonmanifold[2], first_misoriented[2];
    uint32_t *partner; /* corners, only when orienting */
    /* the room of the growing lists: cut_edges and the report's three */
    size_t cut_capacity, bad_face_capacity, nonmanifold_edge_capacity, nonmanifold_vertex_capacity;
} hm_builder;

/* Appends value to *list (count items in room for *capacity); sets *failed
 * when memory runs out. */
static inline void hm_list_push(uint32_t **list, size_t *count, size_t *capacity, uint32_t value,
                                int *failed)
{
    if (core_array_reserve((void **)list, capacity, *count + 1, sizeof **list) != CG_OK) {
        *failed = 1;
        return;
    }
    (*list)[(*count)++] = value;
}

/* Step 1: checks the faces, lists the bad ones in the report and, when
 * there are any (and CG_HEMESH_DROP_BAD_FACES allows it), makes the
 * builder's own copy of the others. */
cg_status hm_build_check_faces(hm_builder *b);
/* Step 4: links the matched edges into the structure, splitting the
 * vertices whose faces form several fans (or failing). */
cg_status hm_build_assemble(hm_builder *b, cg_hemesh **out);

#endif
