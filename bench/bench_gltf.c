/* glTF load time and peak memory: cg_mesh_load against assimp's reader
 * (aiImportFile, no post-processing) on the same files: the glTF 2.0 models
 * of Debian's assimp-testmodels that both read, and a generated .glb of a
 * 2,000,000-triangle sphere (positions, normals, texture coordinates,
 * 32-bit indices) written into a temporary directory.  cg's result is the
 * flattened world-space mesh (doubles); assimp's its scene of float meshes.
 * Times are medians; peak memory is measured in a child process per reader
 * (its peak resident size less that of a child that reads nothing).  A
 * second row per file times `cg mesh info FILE` as a user runs it (the
 * whole process: start, load, the half-edge summary it prints) against the
 * same assimp load, with the process's peak resident size. */
#include "bench.h"
#include "cg.h"

#include <stdint.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#ifdef CG_HAVE_ASSIMP
#include <assimp/cimport.h>
#include <assimp/scene.h>
#endif

typedef struct job {
    const char *path;
    long triangles;
} job;

static void cg_work(void *context)
{
    job *j = context;
    cg_mesh *m = NULL;
    j->triangles = cg_mesh_load(j->path, &m, NULL) == CG_OK ? (long)m->face_count : -1;
    cg_mesh_free(m);
}

static void assimp_work(void *context)
{
    job *j = context;
    j->triangles = -1;
#ifdef CG_HAVE_ASSIMP
    const struct aiScene *scene = aiImportFile(j->path, 0);
    if (!scene)
        return;
    long n = 0;
    for (unsigned i = 0; i < scene->mNumMeshes; i++)
        n += scene->mMeshes[i]->mNumFaces;
    j->triangles = n;
    aiReleaseImport(scene);
#endif
}

static void nothing(void *context)
{
    (void)context;
}

/* Peak resident memory (bytes) of a child that runs work once. */
static long peak_bytes(void (*work)(void *), void *context)
{
    pid_t pid = fork();
    if (pid == 0) {
        work(context);
        _exit(0);
    }
    int status;
    struct rusage usage;
    if (pid < 0 || wait4(pid, &status, 0, &usage) != pid)
        return -1;
    return usage.ru_maxrss * 1024L;
}

/* Processor time (user + system) of one run of `cg mesh info path`, and its
 * peak resident size in *peak; -1 when it failed. */
static double tool_seconds(const char *path, long *peak)
{
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr))
            _exit(127);
        execl(CG_TOOL, CG_TOOL, "mesh", "info", path, (char *)NULL);
        _exit(127);
    }
    int status;
    struct rusage usage;
    if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    *peak = usage.ru_maxrss * 1024L;
    return (double)usage.ru_utime.tv_sec + (double)usage.ru_utime.tv_usec * 1e-6
           + (double)usage.ru_stime.tv_sec + (double)usage.ru_stime.tv_usec * 1e-6;
}

/* The `cg mesh info FILE` row: the median over runs, against assimp's load. */
static void tool_row(const char *label, const char *path, int runs, double assimp_time)
{
    double samples[BENCH_MAX_RUNS];
    long peak = 0;
    runs = bench_runs(runs);
    for (int i = 0; i < runs; i++)
        if ((samples[i] = tool_seconds(path, &peak)) < 0) {
            fprintf(stderr, "bench_gltf: cg mesh info %s failed\n", path);
            return;
        }
    char name[160], note[160];
    snprintf(name, sizeof name, "cg mesh info %s", label);
    snprintf(note, sizeof note, "the whole process (start, load, summary); peak resident %.1f MB",
             peak / 1e6);
    bench_row(name, bench_median_of(samples, runs), assimp_time > 0 ? "assimp" : "-", assimp_time,
              note);
}

static void compare(const char *label, const char *path, int runs)
{
    job a = {path, 0}, b = {path, 0};
    cg_work(&a);
    if (a.triangles < 0) {
        cg_mesh *m = NULL;
        cg_error err;
        cg_mesh_load(path, &m, &err);
        fprintf(stderr, "bench_gltf: cg cannot read %s: %s\n", path, err.message);
        return;
    }
    double cg_time = bench_median_clock(cg_work, &a, runs, CLOCK_PROCESS_CPUTIME_ID);
    long base = peak_bytes(nothing, NULL);
    long cg_peak = peak_bytes(cg_work, &a) - base;
    char name[160], note[240];
    snprintf(name, sizeof name, "glTF load %s", label);
    assimp_work(&b);
    if (b.triangles < 0) {
        snprintf(note, sizeof note, "%ld triangles; peak +%.1f MB; assimp not built or failed",
                 a.triangles, cg_peak / 1e6);
        bench_row(name, cg_time, "-", 0, note);
        tool_row(label, path, runs, 0);
        return;
    }
    double assimp_time = bench_median_clock(assimp_work, &b, runs, CLOCK_PROCESS_CPUTIME_ID);
    long assimp_peak = peak_bytes(assimp_work, &b) - base;
    snprintf(note, sizeof note,
             "%ld / %ld triangles; peak memory cg +%.1f MB, assimp +%.1f MB (ratio %.2f)",
             a.triangles, b.triangles, cg_peak / 1e6, assimp_peak / 1e6,
             assimp_peak > 0 ? (double)cg_peak / (double)assimp_peak : 0);
    bench_row(name, cg_time, "assimp", assimp_time, note);
    tool_row(label, path, runs, assimp_time);
}

static void put_u32(FILE *f, uint32_t v)
{
    unsigned char b[4] = {(unsigned char)v, (unsigned char)(v >> 8), (unsigned char)(v >> 16),
                          (unsigned char)(v >> 24)};
    fwrite(b, 1, 4, f);
}

/* A .glb of a UV sphere: float positions, normals, texcoords; uint32 indices. */
static int write_sphere_glb(const char *path, int slices, int stacks)
{
    cg_mesh *m;
    if (cg_mesh_sphere(slices, stacks, 1.0, &m) != CG_OK)
        return 0;
    size_t nv = m->vertex_count, nt = cg_mesh_triangle_count(m);
    uint32_t(*tri)[3] = malloc(nt * sizeof *tri);
    float *data = malloc(nv * 8 * sizeof *data);
    if (!tri || !data || cg_mesh_triangulate(m, tri) != CG_OK)
        return 0;
    for (size_t t = 0; t < nt; t++) /* corners to vertices */
        for (int k = 0; k < 3; k++)
            tri[t][k] = m->face_indices[tri[t][k]];
    for (size_t i = 0; i < nv; i++) {
        cg_vec3 p = m->positions[i];
        float v[8] = {(float)p.x,
                      (float)p.y,
                      (float)p.z,
                      (float)p.x,
                      (float)p.y,
                      (float)p.z,
                      (float)(atan2(p.z, p.x) / 6.283185307 + 0.5),
                      (float)(p.y * 0.5 + 0.5)};
        memcpy(data + 8 * i, v, sizeof v);
    }
    size_t vertex_bytes = nv * 32, index_bytes = nt * 12;
    char json[2048];
    int n = snprintf(json, sizeof json,
                     "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":%zu}],"
                     "\"bufferViews\":[{\"buffer\":0,\"byteLength\":%zu,\"byteStride\":32},"
                     "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}],"
                     "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":%zu,"
                     "\"type\":\"VEC3\",\"min\":[-1,-1,-1],\"max\":[1,1,1]},"
                     "{\"bufferView\":0,\"byteOffset\":12,\"componentType\":5126,\"count\":%zu,"
                     "\"type\":\"VEC3\"},{\"bufferView\":0,\"byteOffset\":24,\"componentType\":"
                     "5126,\"count\":%zu,\"type\":\"VEC2\"},{\"bufferView\":1,\"componentType\":"
                     "5125,\"count\":%zu,\"type\":\"SCALAR\"}],\"meshes\":[{\"primitives\":"
                     "[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},"
                     "\"indices\":3}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],"
                     "\"scene\":0}",
                     vertex_bytes + index_bytes, vertex_bytes, vertex_bytes, index_bytes, nv, nv,
                     nv, nt * 3);
    while (n % 4)
        json[n++] = ' ';
    size_t binary = vertex_bytes + index_bytes;
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    fwrite("glTF", 1, 4, f);
    put_u32(f, 2);
    put_u32(f, (uint32_t)(12 + 8 + (size_t)n + 8 + binary));
    put_u32(f, (uint32_t)n);
    put_u32(f, 0x4E4F534Au);
    fwrite(json, 1, (size_t)n, f);
    put_u32(f, (uint32_t)binary);
    put_u32(f, 0x004E4942u);
    fwrite(data, sizeof *data, nv * 8, f);
    fwrite(tri, sizeof *tri, nt, f);
    fclose(f);
    free(tri);
    free(data);
    cg_mesh_free(m);
    return 1;
}

int main(void)
{
    static const struct {
        const char *label, *file;
    } models[] = {
        {"2CylinderEngine.glb (1.8 MB)", "2CylinderEngine-glTF-Binary/2CylinderEngine.glb"},
        {"ClearCoatTest.gltf (0.1 MB)", "ClearCoat-glTF/ClearCoatTest.gltf"},
        {"BoxTextured.gltf, embedded", "BoxTextured-glTF-Embedded/BoxTextured.gltf"},
    };
    const char *dir = "/usr/share/assimp/models/glTF2";
    for (size_t i = 0; i < sizeof models / sizeof models[0]; i++) {
        char path[512];
        snprintf(path, sizeof path, "%s/%s", dir, models[i].file);
        if (access(path, R_OK) == 0)
            compare(models[i].label, path, 15);
        else
            fprintf(stderr, "bench_gltf: %s missing (apt-get install assimp-testmodels)\n", path);
    }
    char tmp[] = "/tmp/cg_bench_gltf_XXXXXX";
    if (mkdtemp(tmp)) {
        char path[128];
        snprintf(path, sizeof path, "%s/sphere.glb", tmp);
        if (write_sphere_glb(path, 1000, 1001)) {
            struct stat st;
            stat(path, &st);
            char label[96];
            snprintf(label, sizeof label, "sphere.glb, 2M triangles (%.0f MB)", st.st_size / 1e6);
            compare(label, path, 5);
        }
        remove(path);
        rmdir(tmp);
    }
    return 0;
}
