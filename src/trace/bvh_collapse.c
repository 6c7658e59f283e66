/* The 4-wide tree of a binary one: each 4-wide node takes a binary inner
 * node's two children and keeps opening the inner child of largest area in
 * their place until it has four (or only leaves).  Leaves' triangles go to
 * blocks of four, in leaf order. */
#include "bvh_internal.h"

#include <math.h>

/* A leaf's blocks: triangle indices, NaN in unused lanes, and for each
 * triangle its place (block * 4 + lane) in c->where; the corners are filled
 * afterwards, in triangle order (bvh_fill_corners). */
uint32_t bvh_emit_leaf(bvh_collapser *c, const bvh_node *leaf)
{
    uint32_t first = (uint32_t)c->block_count, count = leaf->count;
    for (uint32_t k = 0; k < count; k += 4) {
        size_t block = c->block_count++;
        bvh_tri4 *b = &c->blocks[block];
        for (uint32_t l = 0; l < 4; l++) {
            if (k + l >= count) {
                for (int j = 0; j < 3; j++)
                    for (int a = 0; a < 3; a++)
                        b->v[j][a][l] = NAN;
                b->id[l] = UINT32_MAX;
                continue;
            }
            uint32_t id = c->ids[leaf->offset + k + l];
            c->where[id] = (uint32_t)(4 * block + l);
            b->id[l] = id;
        }
    }
    return BVH_LEAF | first << 3 | (count - 1);
}

/* The corners of every stored triangle into its lane, reading the triangles
 * in order (the writes scatter, the reads do not wait on each other). */
void bvh_fill_corners(const bvh_collapser *c, size_t triangle_count)
{
    for (size_t i = 0; i < triangle_count; i++) {
        uint32_t w = c->where[i];
        if (w == UINT32_MAX)
            continue;
        bvh_tri4 *b = &c->blocks[w / 4];
        uint32_t l = w % 4;
        for (int j = 0; j < 3; j++) {
            cg_vec3 p = c->positions[c->indices ? c->indices[3 * i + j] : 3 * i + j];
            b->v[j][0][l] = (float)p.x;
            b->v[j][1][l] = (float)p.y;
            b->v[j][2][l] = (float)p.z;
        }
    }
}

/* One 4-wide node from a binary inner node P: its two children are the
 * first slots, and the inner slot of largest area is opened (replaced by its
 * own two children) until four slots are full or all are leaves.
 *
 *            P                     4-wide node
 *          /   \                 +----+----+----+----+
 *         A     B      open A   | A1 | B  | A2 |    |   (slot 3 unused:
 *        / \   / \     ---->    +----+----+----+----+    empty box)
 *      A1  A2 B1  B2   open B   | A1 | B1 | A2 | B2 |
 *                               +----+----+----+----+
 *
 * The slots' boxes are stored by coordinate, a row per plane and a lane
 * per slot, so one vector load gives one plane of all four boxes:
 *
 *            lane:  0     1     2     3
 *   box[0] lo x   [ A1  | B1  | A2  | B2  ]
 *   box[1] hi x   [ ... ]
 *   box[2] lo y, box[3] hi y, box[4] lo z, box[5] hi z
 *
 * An unused slot has lo +inf and hi -inf, a box no ray enters; its child
 * reference is BVH_NONE. */
uint32_t bvh_collapse(bvh_collapser *c, uint32_t index, int depth)
{
    const bvh_node *bin = c->bin;
    uint32_t kids[4] = {index + 1, bin[index].offset, 0, 0};
    int n = 2;
    while (n < 4) {
        int best = -1;
        float best_area = -1;
        for (int k = 0; k < n; k++) {
            float area = bin[kids[k]].count ? -1 : bvh_node_area(&bin[kids[k]]);
            if (area > best_area) {
                best = k;
                best_area = area;
            }
        }
        if (best < 0)
            break;
        uint32_t open = kids[best];
        kids[best] = open + 1;
        kids[n++] = bin[open].offset;
    }
    uint32_t me = (uint32_t)c->node_count++;
    if (depth > c->depth)
        c->depth = depth;
    bvh4_node *node = &c->nodes[me];
    memset(node, 0, sizeof *node);
    for (int k = 0; k < 4; k++)
        for (int a = 0; a < 3; a++) {
            node->box[2 * a][k] = k < n ? bin[kids[k]].lo[a] : INFINITY;
            node->box[2 * a + 1][k] = k < n ? bin[kids[k]].hi[a] : -INFINITY;
        }
    for (int k = 0; k < 4; k++) {
        uint32_t ref = BVH_NONE;
        if (k < n)
            ref = bin[kids[k]].count ? bvh_emit_leaf(c, &bin[kids[k]])
                                     : bvh_collapse(c, kids[k], depth + 1);
        c->nodes[me].child[k] = ref;
    }
    return me;
}
