/* The order in which the sides of a non-manifold edge are paired.
 *
 * Where three or more faces meet along an edge (two solids touching along
 * it, a fin, a face and its reversed copy), the build pairs its sides in
 * the order they are presented: the first two make one edge, the next two
 * another.  Presenting them in the order of their angle about the edge,
 * starting at a face whose back looks towards the next face, pairs each face
 * with its neighbour across the solid between them: two cubes sharing an
 * edge stay two closed cubes, touching only at the vertices the split then
 * separates, and a face with its reversed copy pairs with that copy.
 *
 * The angle of a side's face is that of its corner before the side (not on
 * the edge), seen along the edge from its smaller vertex to its larger.  A
 * face running along the edge from the smaller vertex has its front towards
 * increasing angle, one running the other way towards decreasing angle: the
 * solid lies ahead of the second kind.  So a group starts at a side running
 * from the larger vertex that is followed by one running from the smaller.
 */
#include "internal.h"
#include "../core/sort.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct radial_side {
    uint64_t entry; /* other vertex << 32 | corner << 1 | runs from the larger vertex */
    double angle;
} radial_side;

static int radial_compare(const void *pa, const void *pb)
{
    const radial_side *a = pa, *b = pb;
    uint32_t oa = (uint32_t)(a->entry >> 32), ob = (uint32_t)(b->entry >> 32);
    if (oa != ob)
        return oa < ob ? -1 : 1;
    if (a->angle != b->angle)
        return a->angle < b->angle ? -1 : 1;
    /* at equal angles (a face and its copy) the one running from the larger
     * vertex first, then the order of the corners */
    uint32_t da = (uint32_t)a->entry & 1u, db = (uint32_t)b->entry & 1u;
    if (da != db)
        return da > db ? -1 : 1;
    return a->entry < b->entry ? -1 : a->entry > b->entry;
}

/* The angle about the axis lo -> hi of point p. */
static double radial_angle(cg_vec3 lo, cg_vec3 hi, cg_vec3 p)
{
    double dx = hi.x - lo.x, dy = hi.y - lo.y, dz = hi.z - lo.z;
    double ux = p.x - lo.x, uy = p.y - lo.y, uz = p.z - lo.z;
    /* e1 perpendicular to d, across its smallest component; e2 = d x e1 */
    double ax = fabs(dx), ay = fabs(dy), az = fabs(dz);
    double e1x, e1y, e1z;
    if (ax <= ay && ax <= az) {
        e1x = 0, e1y = -dz, e1z = dy; /* d x (1, 0, 0) reversed */
    } else if (ay <= az) {
        e1x = dz, e1y = 0, e1z = -dx;
    } else {
        e1x = -dy, e1y = dx, e1z = 0;
    }
    double e2x = dy * e1z - dz * e1y, e2y = dz * e1x - dx * e1z, e2z = dx * e1y - dy * e1x;
    return atan2(ux * e2x + uy * e2y + uz * e2z, ux * e1x + uy * e1y + uz * e1z);
}

/* The corner before corner k in its face (for polygons a binary search for
 * the face: only the sides of non-manifold edges ask). */
static uint32_t radial_corner_before(const uint32_t *offsets, size_t faces, uint32_t k)
{
    if (offsets[faces] == 3 * faces) /* every face a triangle */
        return k % 3 ? k - 1 : k + 2;
    size_t lo = 0, hi = faces; /* the face f with offsets[f] <= k < offsets[f + 1] */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (offsets[mid] <= k)
            lo = mid;
        else
            hi = mid;
    }
    return k > offsets[lo] ? k - 1 : offsets[lo + 1] - 1;
}

cg_status hm_radial_sort_bucket(const cg_mesh *mesh, const uint32_t *offsets,
                                const uint32_t *indices, size_t faces, uint32_t lo,
                                uint64_t *entries, size_t n, const uint32_t *uses)
{
    radial_side *sides = malloc(n * sizeof *sides);
    if (!sides)
        return CG_ENOMEM;
    for (size_t i = 0; i < n; i++) {
        uint32_t other = (uint32_t)(entries[i] >> 32);
        uint32_t corner = (uint32_t)(entries[i] & 0xffffffffu) >> 1;
        sides[i].entry = entries[i];
        sides[i].angle =
            uses[other] < 3
                ? 0.0
                : radial_angle(
                    mesh->positions[lo], mesh->positions[other],
                    mesh->positions[indices[radial_corner_before(offsets, faces, corner)]]);
    }
    if (n <= 24) { /* buckets are about as long as a valence: insertion sort */
        for (size_t i = 1; i < n; i++) {
            radial_side x = sides[i];
            size_t j = i;
            for (; j > 0 && radial_compare(&sides[j - 1], &x) > 0; j--)
                sides[j] = sides[j - 1];
            sides[j] = x;
        }
    } else {
        core_sort(sides, n, sizeof *sides, radial_compare);
    }
    /* each group of three or more starts where the solid begins */
    for (size_t i = 0; i < n;) {
        uint32_t other = (uint32_t)(sides[i].entry >> 32);
        size_t m = uses[other], start = 0;
        for (size_t j = 0; j < m; j++)
            if ((sides[i + j].entry & 1u) && !(sides[i + (j + 1) % m].entry & 1u)) {
                start = j;
                break;
            }
        for (size_t j = 0; j < m; j++)
            entries[i + j] = sides[i + (start + j) % m].entry;
        i += m;
    }
    free(sides);
    return CG_OK;
}
