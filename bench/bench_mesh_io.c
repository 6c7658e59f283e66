/* Mesh file read speed in MB/s: cg_mesh_load against tinyobjloader (OBJ) and
 * OpenMesh (OBJ and PLY) on the same files: the real meshes in data/meshes
 * and a generated 1,000,000-triangle sphere written by cg_mesh_save as OBJ,
 * ASCII PLY and binary PLY into a temporary directory.  Every reader reads
 * the file from the page cache into its own structures; times are medians. */
#include "bench.h"
#include "cg.h"

#include <math.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

long peer_tinyobj_load(const char *path);
long peer_openmesh_load(const char *path);

typedef struct job {
    const char *path;
    long vertices;
} job;

static void cg_work(void *context)
{
    job *j = context;
    cg_mesh *m = NULL;
    if (cg_mesh_load(j->path, &m, NULL) == CG_OK)
        j->vertices = (long)m->vertex_count;
    else
        j->vertices = -1;
    cg_mesh_free(m);
}

static void tinyobj_work(void *context)
{
    job *j = context;
    j->vertices = peer_tinyobj_load(j->path);
}

static void openmesh_work(void *context)
{
    job *j = context;
    j->vertices = peer_openmesh_load(j->path);
}

static double file_mb(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (double)st.st_size / 1e6 : 0;
}

/* One row: cg against one peer on one file. */
static void compare(const char *label, const char *path, const char *peer_name,
                    void (*peer)(void *), int runs)
{
    double mb = file_mb(path);
    job a = {path, 0}, b = {path, 0};
    cg_work(&a); /* warm the page cache */
    double cg_time = bench_median(cg_work, &a, runs);
    char name[160], note[200];
    snprintf(name, sizeof name, "mesh read %s (%.1f MB) vs %s", label, mb, peer_name);
    peer(&b);
    if (b.vertices < 0) {
        snprintf(note, sizeof note, "cg %.0f MB/s; %s not built or failed", mb / cg_time,
                 peer_name);
        bench_row(name, cg_time, "-", 0, note);
        return;
    }
    double peer_time = bench_median(peer, &b, runs);
    snprintf(note, sizeof note, "cg %.0f MB/s, %s %.0f MB/s; %ld / %ld vertices", mb / cg_time,
             peer_name, mb / peer_time, a.vertices, b.vertices);
    bench_row(name, cg_time, peer_name, peer_time, note);
}

/* A UV sphere of 2 * slices * (stacks - 1) triangles. */
static cg_mesh *sphere(int stacks, int slices)
{
    size_t nv = (size_t)slices * (size_t)(stacks - 1) + 2;
    size_t nf = 2 * (size_t)slices * (size_t)(stacks - 1);
    cg_mesh *m;
    if (cg_mesh_create(&m, nv, nf, 3 * nf, 0) != CG_OK)
        return NULL;
    m->positions[0] = cg_vec3_make(0, 1, 0);
    for (int i = 1; i < stacks; i++)
        for (int j = 0; j < slices; j++) {
            double theta = CG_PI * i / stacks, phi = 2 * CG_PI * j / slices;
            m->positions[1 + (size_t)(i - 1) * slices + j] = cg_vec3_make(
                sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
        }
    m->positions[nv - 1] = cg_vec3_make(0, -1, 0);
    size_t f = 0, k = 0;
#define RING(i, j) (uint32_t)(1 + (size_t)((i)-1) * slices + (size_t)((j) % slices))
#define TRI(a, b, c)                                                                             \
    (m->face_offsets[f++] = (uint32_t)k, m->face_indices[k++] = (a), m->face_indices[k++] = (b), \
     m->face_indices[k++] = (c))
    for (int j = 0; j < slices; j++) {
        TRI(0, RING(1, j + 1), RING(1, j));
        TRI((uint32_t)(nv - 1), RING(stacks - 1, j), RING(stacks - 1, j + 1));
    }
    for (int i = 1; i < stacks - 1; i++)
        for (int j = 0; j < slices; j++) {
            TRI(RING(i, j), RING(i, j + 1), RING(i + 1, j));
            TRI(RING(i, j + 1), RING(i + 1, j + 1), RING(i + 1, j));
        }
    m->face_offsets[f] = (uint32_t)k;
    return m;
}

/* Decompresses a .gz file to path. */
static int gunzip_to(const char *gz, const char *path)
{
    gzFile in = gzopen(gz, "rb");
    FILE *out = fopen(path, "wb");
    char buffer[65536];
    int n, ok = in && out;
    while (ok && (n = gzread(in, buffer, sizeof buffer)) > 0)
        ok = fwrite(buffer, 1, (size_t)n, out) == (size_t)n;
    if (in)
        gzclose(in);
    if (out)
        fclose(out);
    return ok;
}

int main(int argc, char **argv)
{
    /* bench_mesh_io cg|tinyobjloader|openmesh FILE: one load, for instruction
     * counts under valgrind --tool=callgrind */
    if (argc == 3) {
        job j = {argv[2], 0};
        if (strcmp(argv[1], "cg") == 0)
            cg_work(&j);
        else if (strcmp(argv[1], "tinyobjloader") == 0)
            tinyobj_work(&j);
        else if (strcmp(argv[1], "openmesh") == 0)
            openmesh_work(&j);
        else
            j.vertices = -1;
        printf("%s: %ld vertices\n", argv[2], j.vertices);
        return j.vertices < 0;
    }
    char dir[] = "/tmp/cg-bench-mesh-XXXXXX";
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    char bunny[512], teapot[512], dragon[512], dragon_obj[512], sobj[512], sply[512], sbin[512];
    snprintf(bunny, sizeof bunny, "%s/data/meshes/bunny.obj", CG_SOURCE_DIR);
    snprintf(teapot, sizeof teapot, "%s/data/meshes/teapot.obj", CG_SOURCE_DIR);
    snprintf(dragon, sizeof dragon, "%s/dragon.ply", dir);
    snprintf(dragon_obj, sizeof dragon_obj, "%s/dragon.obj", dir);
    snprintf(sobj, sizeof sobj, "%s/sphere.obj", dir);
    snprintf(sply, sizeof sply, "%s/sphere-ascii.ply", dir);
    snprintf(sbin, sizeof sbin, "%s/sphere-binary.ply", dir);
    char gz[512];
    snprintf(gz, sizeof gz, "%s/data/meshes/dragon_vrip_res3.ply.gz", CG_SOURCE_DIR);
    cg_mesh *d = NULL;
    if (!gunzip_to(gz, dragon) || cg_mesh_load(dragon, &d, NULL) != CG_OK
        || cg_mesh_save(d, dragon_obj, CG_MESH_FORMAT_OBJ, NULL) != CG_OK) {
        fprintf(stderr, "bench_mesh_io: cannot prepare the dragon\n");
        return 1;
    }
    cg_mesh_free(d);
    cg_mesh *s = sphere(501, 1000);
    if (!s || cg_mesh_save(s, sobj, CG_MESH_FORMAT_OBJ, NULL) != CG_OK
        || cg_mesh_save(s, sply, CG_MESH_FORMAT_PLY_ASCII, NULL) != CG_OK
        || cg_mesh_save(s, sbin, CG_MESH_FORMAT_PLY_BINARY, NULL) != CG_OK) {
        fprintf(stderr, "bench_mesh_io: cannot write the sphere\n");
        return 1;
    }
    cg_mesh_free(s);

    compare("bunny.obj", bunny, "tinyobjloader", tinyobj_work, 21);
    compare("teapot.obj", teapot, "tinyobjloader", tinyobj_work, 31);
    compare("dragon res3 .obj", dragon_obj, "tinyobjloader", tinyobj_work, 11);
    compare("sphere 1M tris .obj", sobj, "tinyobjloader", tinyobj_work, 5);
    compare("sphere 1M tris .obj", sobj, "OpenMesh", openmesh_work, 3);
    compare("dragon res3 ASCII .ply", dragon, "OpenMesh", openmesh_work, 11);
    compare("sphere 1M tris ASCII .ply", sply, "OpenMesh", openmesh_work, 3);
    compare("sphere 1M tris binary .ply", sbin, "OpenMesh", openmesh_work, 3);

    const char *files[] = {dragon, dragon_obj, sobj, sply, sbin};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++)
        unlink(files[i]);
    rmdir(dir);
    return 0;
}
