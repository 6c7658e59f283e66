/* glTF scenes and the node hierarchy.
 *
 *   scene.nodes: [0, 3]        node 0 (matrix)      node 3 (T R S)
 *                                |                     |
 *                              node 1 (mesh 0)       node 4 (mesh 0)
 *
 * Each node has at most one parent and the hierarchy has no cycle; a
 * node's world matrix is its parent's times its own (a matrix, or T * R * S
 * from translation, rotation quaternion and scale).  The default scene is
 * `scene`, else scenes[0], else the root nodes in file order. */
#include "gltf_internal.h"

#include <stdio.h>
#include <stdlib.h>

/* A node's local matrix from its matrix (column-major) or TRS. */
static cg_status local_matrix(gltf_document *doc, const cJSON *node, const char *path, cg_mat4 *out)
{
    double matrix[16], translation[3] = {0, 0, 0}, rotation[4] = {0, 0, 0, 1}, scale[3] = {1, 1, 1};
    int has_matrix, has_t, has_r, has_s;
    cg_status s = gltf_get_numbers(doc, node, path, "matrix", 16, matrix, &has_matrix);
    if (s == CG_OK)
        s = gltf_get_numbers(doc, node, path, "translation", 3, translation, &has_t);
    if (s == CG_OK)
        s = gltf_get_numbers(doc, node, path, "rotation", 4, rotation, &has_r);
    if (s == CG_OK)
        s = gltf_get_numbers(doc, node, path, "scale", 3, scale, &has_s);
    if (s != CG_OK)
        return s;
    if (has_matrix && (has_t || has_r || has_s))
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s: expected either matrix or translation/rotation/scale, got "
                            "both",
                            doc->name, path);
    if (has_matrix) {
        /* decomposable into TRS, so affine: the last row is 0 0 0 1 */
        if (matrix[3] != 0 || matrix[7] != 0 || matrix[11] != 0 || matrix[15] != 1)
            return cg_error_set(doc->err, CG_EFORMAT,
                                "%s: %s.matrix: expected an affine matrix (a last row of 0 0 0 1, "
                                "elements 3, 7, 11, 15), got %g %g %g %g",
                                doc->name, path, matrix[3], matrix[7], matrix[11], matrix[15]);
        for (int column = 0; column < 4; column++)
            for (int row = 0; row < 4; row++)
                out->m[row][column] = matrix[column * 4 + row];
        return CG_OK;
    }
    double x = rotation[0], y = rotation[1], z = rotation[2], w = rotation[3];
    double length = sqrt(x * x + y * y + z * z + w * w);
    if (!(length > 1e-12))
        return cg_error_set(doc->err, CG_EFORMAT,
                            "%s: %s.rotation: expected a unit quaternion (x, y, z, w), got one of "
                            "length 0",
                            doc->name, path);
    x /= length, y /= length, z /= length, w /= length;
    double r[3][3] = {
        {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
        {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
        {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)},
    };
    *out = cg_mat4_identity();
    for (int row = 0; row < 3; row++) {
        for (int column = 0; column < 3; column++)
            out->m[row][column] = r[row][column] * scale[column];
        out->m[row][3] = translation[row];
    }
    return CG_OK;
}

/* Reads every node's children and checks: indices in range, one parent per
 * node, no cycle.  parent[i] is node i's parent or SIZE_MAX. */
static cg_status check_hierarchy(gltf_document *doc, size_t *parent)
{
    size_t n = doc->nodes.count;
    for (size_t i = 0; i < n; i++)
        parent[i] = SIZE_MAX;
    for (size_t i = 0; i < n; i++) {
        char path[48];
        snprintf(path, sizeof path, "nodes[%zu]", i);
        gltf_list children;
        cg_status s = gltf_get_list(doc, doc->nodes.items[i], path, "children", 1, &children);
        for (size_t c = 0; s == CG_OK && c < children.count; c++) {
            const cJSON *item = children.items[c];
            double d = cJSON_IsNumber(item) ? item->valuedouble : -1;
            char child_path[80];
            snprintf(child_path, sizeof child_path, "%s.children[%zu]", path, c);
            if (d != floor(d) || d < 0 || d >= (double)n) {
                char expected[64];
                snprintf(expected, sizeof expected, "an index into nodes (0 to %zu)", n - 1);
                s = gltf_fail(doc, child_path, NULL, expected, item);
            } else if ((size_t)d == i) {
                s = cg_error_set(doc->err, CG_EFORMAT,
                                 "%s: %s: node %zu is its own child (a node cycle)", doc->name,
                                 child_path, i);
            } else if (parent[(size_t)d] != SIZE_MAX) {
                s = cg_error_set(doc->err, CG_EFORMAT,
                                 "%s: %s: expected a node without a parent, but node %zu is "
                                 "already a child of node %zu",
                                 doc->name, child_path, (size_t)d, parent[(size_t)d]);
            } else {
                parent[(size_t)d] = i;
            }
        }
        gltf_list_free(&children);
        if (s != CG_OK)
            return s;
    }
    /* with one parent each, a cycle is a chain of parents that comes back:
     * walk up from each node, marking the walk (1) and what is known to
     * reach a root (2) */
    unsigned char *state = calloc(n ? n : 1, 1);
    if (!state)
        return gltf_out_of_memory(doc);
    cg_status s = CG_OK;
    for (size_t i = 0; i < n && s == CG_OK; i++) {
        size_t k = i;
        while (k != SIZE_MAX && state[k] == 0) {
            state[k] = 1;
            k = parent[k];
        }
        if (k != SIZE_MAX && state[k] == 1)
            s = cg_error_set(doc->err, CG_EFORMAT,
                             "%s: nodes[%zu].children: expected a tree, but node %zu is its own "
                             "ancestor (a node cycle)",
                             doc->name, parent[k], k);
        for (k = i; k != SIZE_MAX && state[k] == 1; k = parent[k])
            state[k] = 2;
    }
    free(state);
    return s;
}

/* Which nodes the default scene starts from: a list of root node indices. */
static cg_status scene_roots(gltf_document *doc, const size_t *parent, size_t **roots,
                             size_t *root_count)
{
    size_t scene;
    *roots = NULL;
    *root_count = 0;
    cg_status s = gltf_get_index(doc, doc->root, "", "scene", 0, &doc->scenes, "scenes", &scene);
    if (s != CG_OK)
        return s;
    if (scene == SIZE_MAX && doc->scenes.count)
        scene = 0;
    size_t n = doc->nodes.count;
    if (scene == SIZE_MAX) { /* no scene: every root node */
        if (!(*roots = malloc((n ? n : 1) * sizeof **roots)))
            return gltf_out_of_memory(doc);
        for (size_t i = 0; i < n; i++)
            if (parent[i] == SIZE_MAX)
                (*roots)[(*root_count)++] = i;
        return CG_OK;
    }
    char path[48];
    snprintf(path, sizeof path, "scenes[%zu]", scene);
    gltf_list nodes;
    if ((s = gltf_get_list(doc, doc->scenes.items[scene], path, "nodes", 1, &nodes)) != CG_OK)
        return s;
    if (nodes.count && !(*roots = malloc(nodes.count * sizeof **roots)))
        s = gltf_out_of_memory(doc);
    for (size_t i = 0; s == CG_OK && i < nodes.count; i++) {
        const cJSON *item = nodes.items[i];
        double d = cJSON_IsNumber(item) ? item->valuedouble : -1;
        char item_path[80];
        snprintf(item_path, sizeof item_path, "%s.nodes[%zu]", path, i);
        if (d != floor(d) || d < 0 || d >= (double)n) {
            char expected[64];
            snprintf(expected, sizeof expected,
                     n ? "an index into nodes (0 to %zu)"
                       : "an index into nodes, but the file has none",
                     n ? n - 1 : 0);
            s = gltf_fail(doc, item_path, NULL, expected, item);
        } else if (parent[(size_t)d] != SIZE_MAX) {
            s = cg_error_set(doc->err, CG_EFORMAT,
                             "%s: %s: expected a root node, but node %zu is a child of node %zu",
                             doc->name, item_path, (size_t)d, parent[(size_t)d]);
        } else {
            for (size_t j = 0; j < *root_count; j++)
                if ((*roots)[j] == (size_t)d)
                    s = cg_error_set(doc->err, CG_EFORMAT,
                                     "%s: %s: expected each node once, but node %zu is listed "
                                     "twice",
                                     doc->name, item_path, (size_t)d);
            (*roots)[(*root_count)++] = (size_t)d;
        }
    }
    gltf_list_free(&nodes);
    if (s != CG_OK) {
        free(*roots);
        *roots = NULL;
    }
    return s;
}

/* Checks one node's own members and counts what it carries beyond a mesh. */
static cg_status check_node(gltf_document *doc, size_t i, size_t *mesh)
{
    const cJSON *node = doc->nodes.items[i];
    char path[48];
    snprintf(path, sizeof path, "nodes[%zu]", i);
    size_t camera, skin;
    cg_status s = gltf_get_index(doc, node, path, "mesh", 0, &doc->meshes, "meshes", mesh);
    if (s == CG_OK)
        s = gltf_get_index(doc, node, path, "camera", 0, &doc->cameras, "cameras", &camera);
    if (s == CG_OK)
        s = gltf_get_index(doc, node, path, "skin", 0, &doc->skins, "skins", &skin);
    if (s != CG_OK)
        return s;
    if (skin != SIZE_MAX && *mesh == SIZE_MAX)
        return cg_error_set(doc->err, CG_EFORMAT, "%s: %s.skin: expected a node with a mesh",
                            doc->name, path);
    const cJSON *extensions, *lights;
    if ((s = gltf_get_object(doc, node, path, "extensions", 0, &extensions)) != CG_OK)
        return s;
    char light_path[80];
    snprintf(light_path, sizeof light_path, "%s.extensions", path);
    if ((s = gltf_get_object(doc, extensions, light_path, "KHR_lights_punctual", 0, &lights))
        != CG_OK)
        return s;
    if (lights) {
        size_t light;
        snprintf(light_path, sizeof light_path, "%s.extensions.KHR_lights_punctual", path);
        if ((s = gltf_get_index(doc, lights, light_path, "light", 1, &doc->lights,
                                "KHR_lights_punctual.lights", &light))
            != CG_OK)
            return s;
    }
    return CG_OK;
}

typedef struct walk_entry {
    size_t node;
    cg_mat4 parent_world;
} walk_entry;

cg_status gltf_collect_instances(gltf_document *doc, gltf_instance_array *out)
{
    size_t n = doc->nodes.count;
    size_t *parent = malloc((n ? n : 1) * sizeof *parent);
    size_t *meshes = malloc((n ? n : 1) * sizeof *meshes);
    cg_mat4 *locals = malloc((n ? n : 1) * sizeof *locals);
    size_t *roots = NULL, root_count = 0;
    CORE_ARRAY(walk_entry) stack = {0};
    cg_status s = parent && meshes && locals ? CG_OK : gltf_out_of_memory(doc);
    if (s == CG_OK)
        s = check_hierarchy(doc, parent);
    for (size_t i = 0; s == CG_OK && i < n; i++) {
        char path[48];
        snprintf(path, sizeof path, "nodes[%zu]", i);
        s = check_node(doc, i, &meshes[i]);
        if (s == CG_OK)
            s = local_matrix(doc, doc->nodes.items[i], path, &locals[i]);
    }
    if (s == CG_OK)
        s = scene_roots(doc, parent, &roots, &root_count);
    /* depth first, roots and children in order: each root's tree is walked
     * with a stack onto which children go in reverse */
    for (size_t r = 0; s == CG_OK && r < root_count; r++) {
        walk_entry root = {roots[r], cg_mat4_identity()};
        if (core_array_push(&stack, root) != CG_OK)
            s = gltf_out_of_memory(doc);
        while (s == CG_OK && stack.count) {
            walk_entry e = stack.data[--stack.count];
            cg_mat4 world = cg_mat4_mul(e.parent_world, locals[e.node]);
            if (meshes[e.node] != SIZE_MAX) {
                gltf_instance instance = {meshes[e.node], e.node, world};
                if (core_array_push(out, instance) != CG_OK) {
                    s = gltf_out_of_memory(doc);
                    break;
                }
            }
            const cJSON *children = cJSON_GetObjectItemCaseSensitive(doc->nodes.items[e.node],
                                                                     "children");
            size_t count = (size_t)cJSON_GetArraySize(children);
            if (core_array_reserve_for(&stack, stack.count + count) != CG_OK) {
                s = gltf_out_of_memory(doc);
                break;
            }
            size_t k = stack.count + count;
            for (const cJSON *c = children ? children->child : NULL; c; c = c->next) {
                walk_entry child = {(size_t)c->valuedouble, world};
                stack.data[--k] = child;
            }
            stack.count += count;
        }
    }
    core_array_free(&stack);
    free(roots);
    free(parent);
    free(meshes);
    free(locals);
    return s;
}
