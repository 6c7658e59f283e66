/* cg's glTF reader against assimp's (Debian's libassimp-dev) on every glTF
 * 2.0 model of Debian's assimp-testmodels.
 *
 * A valid model must load in both, and then give the same triangles: the
 * mesh instances of the default scene in depth-first node order, each
 * triangle primitive's vertices (count, world positions, world normals,
 * texture coordinates) and triangles (corners equal up to rotation, so the
 * same winding), within float rounding, and the same world-space bounds.
 * assimp flips v as cg does (v' = 1 - v).
 *
 * The deliberately broken models (and those needing an extension cg does
 * not read) must be refused with one message naming the file and what was
 * expected; none may crash.  Exit 77 when the models are absent. */
#include "cg.h"
#include "check.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char *models;

/* The broken models and a piece of the message cg must give for each. */
static const struct {
    const char *file;
    const char *says;
} refused[] = {
    {"BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", "KHR_technique_webgl"},
    {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "expected a finite POSITION"},
    {"IncorrectVertexArrays/Cube.gltf", "bufferViews[2]: expected to lie inside buffers[0]"},
    {"IndexOutOfRange/AllIndicesOutOfRange.gltf", "expected indices below 24"},
    {"IndexOutOfRange/IndexOutOfRange.gltf", "expected indices below 24"},
    {"MissingBin/BoxTextured.gltf", "buffers[0].uri"},
    {"RecursiveNodes/RecursiveNodes.gltf", "node cycle"},
    {"SchemaFailures/sceneWrongType.gltf", "scene: expected an index into scenes"},
    {"TestNoRootNode/NoScene.gltf", "scene: expected an index into scenes"},
    {"draco/2CylinderEngine.gltf", "KHR_draco_mesh_compression"},
    {"issue_3269/texcoord_crash.gltf", "got TEXCOORD_1 without TEXCOORD_0"},
    {"wrongTypes/badArray.gltf", "meshes[0].primitives: expected an array"},
    {"wrongTypes/badExtension.gltf", "KHR_texture_transform: expected an object"},
    {"wrongTypes/badNumber.gltf", "materials[0].normalTexture"},
    {"wrongTypes/badObject.gltf", "pbrMetallicRoughness: expected an object"},
    {"wrongTypes/badString.gltf", "scenes[0].name: expected a string"},
    {"wrongTypes/badUint.gltf", "baseColorTexture.index: expected an index"},
};

static const char *must_refuse(const char *relative)
{
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++)
        if (strcmp(relative, refused[i].file) == 0)
            return refused[i].says;
    return NULL;
}

/* ---- walking assimp's scene the way cg flattens it ----------------------- */
typedef struct walk {
    const struct aiScene *scene;
    const cg_mesh *mesh;
    const char *name;
    size_t vertex, face; /* where the next primitive starts in cg's mesh */
    cg_vec3 lo, hi;
    int bounded;
    int mismatch;
} walk;

static cg_vec3 transform_point(const struct aiMatrix4x4 *m, struct aiVector3D v)
{
    return cg_vec3_make(m->a1 * (double)v.x + m->a2 * (double)v.y + m->a3 * (double)v.z + m->a4,
                        m->b1 * (double)v.x + m->b2 * (double)v.y + m->b3 * (double)v.z + m->b4,
                        m->c1 * (double)v.x + m->c2 * (double)v.y + m->c3 * (double)v.z + m->c4);
}

static double length3(cg_vec3 v)
{
    return sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

static int near3(cg_vec3 a, cg_vec3 b, double tolerance)
{
    return fabs(a.x - b.x) <= tolerance && fabs(a.y - b.y) <= tolerance
           && fabs(a.z - b.z) <= tolerance;
}

/* The normal matrix (inverse transpose of the upper 3x3) of m, as a cg_mat4. */
static cg_mat4 normal_matrix(const struct aiMatrix4x4 *m)
{
    cg_mat4 a = {{{m->a1, m->a2, m->a3, 0},
                  {m->b1, m->b2, m->b3, 0},
                  {m->c1, m->c2, m->c3, 0},
                  {0, 0, 0, 1}}};
    cg_mat4 inverse;
    if (cg_mat4_inverse(a, &inverse) != CG_OK)
        return a;
    return cg_mat4_transpose(inverse);
}

static void compare_mesh(walk *w, const struct aiMesh *am, const struct aiMatrix4x4 *world)
{
    const cg_mesh *m = w->mesh;
    CHECK_MSG(
        w->vertex + am->mNumVertices <= m->vertex_count && w->face + am->mNumFaces <= m->face_count,
        "%s: assimp has more vertices or faces than cg (%zu + %u of %zu, %zu + %u of %zu)", w->name,
        w->vertex, am->mNumVertices, m->vertex_count, w->face, am->mNumFaces, m->face_count);
    if (w->vertex + am->mNumVertices > m->vertex_count || w->face + am->mNumFaces > m->face_count) {
        w->mismatch = 1;
        return;
    }
    cg_mat4 nm = normal_matrix(world);
    long bad_positions = 0, bad_normals = 0, bad_texcoords = 0, bad_faces = 0;
    for (unsigned i = 0; i < am->mNumVertices; i++) {
        cg_vec3 p = transform_point(world, am->mVertices[i]);
        cg_vec3 q = m->positions[w->vertex + i];
        double scale = fmax(1.0, fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))));
        bad_positions += !near3(p, q, 1e-5 * scale);
        if (!w->bounded) {
            w->lo = w->hi = p;
            w->bounded = 1;
        }
        w->lo = cg_vec3_make(fmin(w->lo.x, p.x), fmin(w->lo.y, p.y), fmin(w->lo.z, p.z));
        w->hi = cg_vec3_make(fmax(w->hi.x, p.x), fmax(w->hi.y, p.y), fmax(w->hi.z, p.z));
        if (am->mNormals && m->normals) {
            struct aiVector3D an = am->mNormals[i];
            cg_vec3 n = cg_mat4_transform_vector(nm, cg_vec3_make(an.x, an.y, an.z));
            double length = length3(n);
            if (length > 0)
                n = cg_vec3_make(n.x / length, n.y / length, n.z / length);
            else
                n = cg_vec3_make(0, 0, 0);
            bad_normals += !near3(n, m->normals[w->vertex + i], 1e-5);
        }
        if (am->mTextureCoords[0]) {
            bad_texcoords += !m->texcoords;
            if (m->texcoords) {
                struct aiVector3D t = am->mTextureCoords[0][i];
                cg_vec2 c = m->texcoords[w->vertex + i];
                bad_texcoords += fabs(t.x - c.x) > 1e-6 || fabs(t.y - c.y) > 1e-6;
            }
        }
    }
    for (unsigned f = 0; f < am->mNumFaces; f++) {
        const struct aiFace *face = &am->mFaces[f];
        size_t cf = w->face + f;
        if (face->mNumIndices != 3 || cg_mesh_face_size(m, cf) != 3) {
            bad_faces++;
            continue;
        }
        const uint32_t *corners = m->face_indices + m->face_offsets[cf];
        int same = 0;
        for (int r = 0; r < 3 && !same; r++)
            same = corners[0] == w->vertex + face->mIndices[r]
                   && corners[1] == w->vertex + face->mIndices[(r + 1) % 3]
                   && corners[2] == w->vertex + face->mIndices[(r + 2) % 3];
        bad_faces += !same;
    }
    CHECK_MSG(bad_positions == 0, "%s: %ld of %u positions differ from assimp's", w->name,
              bad_positions, am->mNumVertices);
    CHECK_MSG(bad_normals == 0, "%s: %ld of %u normals differ from assimp's", w->name, bad_normals,
              am->mNumVertices);
    CHECK_MSG(bad_texcoords == 0, "%s: %ld of %u texture coordinates differ from assimp's", w->name,
              bad_texcoords, am->mNumVertices);
    CHECK_MSG(bad_faces == 0, "%s: %ld of %u triangles differ from assimp's", w->name, bad_faces,
              am->mNumFaces);
    CHECK_MSG(!am->mNormals == !m->normals || !am->mNormals,
              "%s: assimp has no normals but cg does", w->name);
    w->vertex += am->mNumVertices;
    w->face += am->mNumFaces;
}

static void walk_node(walk *w, const struct aiNode *node, struct aiMatrix4x4 parent)
{
    struct aiMatrix4x4 world = parent;
    aiMultiplyMatrix4(&world, &node->mTransformation);
    for (unsigned i = 0; i < node->mNumMeshes && !w->mismatch; i++) {
        const struct aiMesh *am = w->scene->mMeshes[node->mMeshes[i]];
        if (am->mPrimitiveTypes != aiPrimitiveType_TRIANGLE)
            continue; /* points and lines: cg leaves them out */
        compare_mesh(w, am, &world);
    }
    for (unsigned c = 0; c < node->mNumChildren && !w->mismatch; c++)
        walk_node(w, node->mChildren[c], world);
}

static void compare_with_assimp(const char *path, const char *relative, const cg_mesh *mesh)
{
    const struct aiScene *scene = aiImportFile(path, aiProcess_ValidateDataStructure);
    CHECK_MSG(scene != NULL, "%s: cg loads it but assimp does not: %s", relative,
              aiGetErrorString());
    if (!scene)
        return;
    walk w = {scene, mesh, relative, 0, 0, {0, 0, 0}, {0, 0, 0}, 0, 0};
    struct aiMatrix4x4 identity;
    aiIdentityMatrix4(&identity);
    if (scene->mRootNode)
        walk_node(&w, scene->mRootNode, identity);
    CHECK_MSG(w.vertex == mesh->vertex_count && w.face == mesh->face_count,
              "%s: assimp's triangle meshes have %zu vertices and %zu triangles, cg's %zu and %zu",
              relative, w.vertex, w.face, mesh->vertex_count, mesh->face_count);
    cg_vec3 lo, hi;
    if (w.bounded && cg_mesh_bounds(mesh, &lo, &hi) == CG_OK) {
        double scale = fmax(1.0, fmax(length3(w.lo), length3(w.hi)));
        CHECK_MSG(near3(lo, w.lo, 1e-5 * scale) && near3(hi, w.hi, 1e-5 * scale),
                  "%s: world bounds (%g %g %g)-(%g %g %g), assimp's (%g %g %g)-(%g %g %g)",
                  relative, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, w.lo.x, w.lo.y, w.lo.z, w.hi.x,
                  w.hi.y, w.hi.z);
    }
    printf("ok    %s: %zu vertices, %zu triangles, as assimp\n", relative, mesh->vertex_count,
           mesh->face_count);
    aiReleaseImport(scene);
}

static void try_model(const char *path)
{
    const char *relative = path + strlen(models) + 1;
    const char *says = must_refuse(relative);
    cg_mesh *mesh = NULL;
    cg_error err;
    cg_error_clear(&err);
    cg_status s = cg_mesh_load(path, &mesh, &err);
    if (says) {
        CHECK_MSG(s != CG_OK && !mesh, "%s: a broken model loaded", relative);
        CHECK_MSG(s != CG_OK && strncmp(err.message, path, strlen(path)) == 0
                      && strstr(err.message, says) && !strchr(err.message, '\n'),
                  "%s: the message '%s' should name the file and say '%s'", relative, err.message,
                  says);
        printf("error %s\n", err.message);
    } else {
        CHECK_MSG(s == CG_OK, "%s: a valid model is refused: %s", relative, err.message);
        if (s == CG_OK) {
            cg_error check;
            CHECK_MSG(cg_mesh_validate(mesh, &check) == CG_OK, "%s: %s", relative, check.message);
            compare_with_assimp(path, relative, mesh);
        }
    }
    cg_mesh_free(mesh);
}

static int has_gltf_suffix(const char *name)
{
    size_t n = strlen(name);
    return (n > 5 && strcmp(name + n - 5, ".gltf") == 0)
           || (n > 4 && strcmp(name + n - 4, ".glb") == 0);
}

static int compare_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Every .gltf and .glb under dir, in name order. */
static void walk_directory(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    char **names = NULL;
    size_t count = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        char **grown = realloc(names, (count + 1) * sizeof *names);
        if (!grown)
            break;
        names = grown;
        size_t n = strlen(dir) + strlen(e->d_name) + 2;
        names[count] = malloc(n);
        snprintf(names[count], n, "%s/%s", dir, e->d_name);
        count++;
    }
    closedir(d);
    qsort(names, count, sizeof *names, compare_names);
    for (size_t i = 0; i < count; i++) {
        struct stat st;
        if (stat(names[i], &st) == 0 && S_ISDIR(st.st_mode))
            walk_directory(names[i]);
        else if (has_gltf_suffix(names[i]))
            try_model(names[i]);
        free(names[i]);
    }
    free(names);
}

static void assimp_models(void)
{
    walk_directory(models);
    /* every listed broken model exists, so the list cannot go stale quietly */
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        char path[512];
        snprintf(path, sizeof path, "%s/%s", models, refused[i].file);
        struct stat st;
        CHECK_MSG(stat(path, &st) == 0, "%s: listed as broken but not found", path);
    }
}

int main(int argc, char **argv)
{
    static const char *const places[] = {"/usr/share/assimp/models/glTF2",
                                         "/usr/share/assimp-testmodels/glTF2",
                                         "/usr/share/assimp-testmodels/models/glTF2"};
    for (size_t i = 0; i < sizeof places / sizeof places[0] && !models; i++) {
        struct stat st;
        if (stat(places[i], &st) == 0)
            models = places[i];
    }
    if (!models) {
        printf("test_mesh_gltf_assimp: the glTF2 models of assimp-testmodels are not installed: "
               "skipped (apt-get install assimp-testmodels)\n");
        return 77;
    }
    check_start(argc, argv);
    CHECK_GROUP(assimp_models);
    return check_finish();
}
