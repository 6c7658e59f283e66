/* The half-edge structure against OpenMesh (TriMesh, array kernel, double
 * points): building from an indexed triangle mesh, a one-ring traversal of
 * every vertex (the average of its neighbours), and one Loop subdivision
 * step, on generated meshes from 10 thousand to 2 million triangles (and
 * the real meshes of data/meshes when given as arguments).  Memory per face
 * is the heap growth (mallinfo2) of one built structure, both libraries
 * measured the same way.  Times are process CPU time (both libraries run
 * single-threaded), which a loaded machine disturbs less than wall time;
 * each is the median of several runs. */
#include "bench.h"
#include "cg.h"
#include "hemesh_peer.h"
#include "hemesh_shapes.h"

#include <malloc.h>
#include <stdio.h>
#include <string.h>

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static size_t heap_bytes(void)
{
    struct mallinfo2 info = mallinfo2();
    return info.uordblks + info.hblkhd;
}

static double median(double *t, int n)
{
    qsort(t, (size_t)n, sizeof *t, bench_compare);
    return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

static void run_case(const char *name, cg_mesh *mesh, unsigned flags)
{
    size_t F = mesh->face_count;
    int runs = F > 500000 ? 5 : F > 50000 ? 9 : 15;
    int peer = peer_available();
    char label[160], note[200];
    double t_cg[16], t_peer[16];

    /* build */
    for (int i = 0; i < runs; i++) {
        cg_hemesh *h = NULL;
        double t0 = cpu_now();
        cg_status s = cg_hemesh_build(mesh, flags, &h, NULL, NULL);
        t_cg[i] = cpu_now() - t0;
        if (s != CG_OK) {
            fprintf(stderr, "bench_hemesh: %s: build failed\n", name);
            return;
        }
        cg_hemesh_free(h);
        if (peer) {
            t0 = cpu_now();
            void *om = peer_build(mesh);
            t_peer[i] = cpu_now() - t0;
            peer_free(om);
        }
    }
    size_t before = heap_bytes();
    cg_hemesh *h = NULL;
    cg_hemesh_build(mesh, flags, &h, NULL, NULL);
    size_t cg_bytes = heap_bytes() - before;
    before = heap_bytes();
    void *om = peer ? peer_build(mesh) : NULL;
    size_t peer_bytes = heap_bytes() - before;
    snprintf(label, sizeof label, "hemesh build, %s (%zu tris)", name, F);
    if (peer)
        snprintf(note, sizeof note, "memory per face: cg %.1f B, OpenMesh %.1f B",
                 (double)cg_bytes / (double)F, (double)peer_bytes / (double)F);
    else
        snprintf(note, sizeof note, "OpenMesh not installed; cg %.1f B per face",
                 (double)cg_bytes / (double)F);
    bench_row(label, median(t_cg, runs), peer ? "OpenMesh" : "-", peer ? median(t_peer, runs) : 0,
              note);

    /* one-ring of every vertex */
    size_t V = mesh->vertex_count, room = h->vertex_count > V ? h->vertex_count : V;
    cg_vec3 *a = malloc(room * sizeof *a), *b = malloc(room * sizeof *b);
    for (int i = 0; i < runs; i++) {
        double t0 = cpu_now();
        cg_hemesh_neighbor_average(h, a);
        t_cg[i] = cpu_now() - t0;
        if (peer) {
            t0 = cpu_now();
            peer_neighbor_average(om, b);
            t_peer[i] = cpu_now() - t0;
        }
    }
    double diff = 0;
    for (size_t v = 0; peer && v < V; v++)
        diff = fmax(diff, cg_vec3_length(cg_vec3_sub(a[v], b[v])));
    snprintf(label, sizeof label, "hemesh one-ring of every vertex, %s", name);
    snprintf(note, sizeof note, "average of neighbours; largest difference %.1e", diff);
    bench_row(label, median(t_cg, runs), peer ? "OpenMesh" : "-", peer ? median(t_peer, runs) : 0,
              peer ? note : "OpenMesh not installed");
    free(a);
    free(b);

    /* one Loop step (OpenMesh subdivides a fresh copy in place) */
    int loop_runs = runs > 9 ? 9 : runs;
    size_t cg_faces = 0, peer_faces = 0;
    double old_diff = 0;
    for (int i = 0; i < loop_runs; i++) {
        cg_hemesh *r = NULL;
        double t0 = cpu_now();
        cg_hemesh_subdivide_loop(h, &r);
        t_cg[i] = cpu_now() - t0;
        if (peer) {
            void *copy = peer_copy(om);
            t0 = cpu_now();
            peer_loop(copy);
            t_peer[i] = cpu_now() - t0;
            size_t pv, pe;
            peer_faces = peer_counts(copy, &pv, &pe);
            for (size_t v = 0; v < V && r && pv == r->vertex_count; v++) {
                cg_vec3 p;
                peer_point(copy, v, &p);
                old_diff = fmax(old_diff, cg_vec3_length(cg_vec3_sub(p, r->positions[v])));
            }
            peer_free(copy);
        }
        cg_faces = r ? r->live_faces : 0;
        cg_hemesh_free(r);
    }
    snprintf(label, sizeof label, "hemesh Loop subdivision step, %s", name);
    snprintf(note, sizeof note, "%zu faces out (OpenMesh %zu); old vertices differ by %.1e",
             cg_faces, peer_faces, old_diff);
    bench_row(label, median(t_cg, loop_runs), peer ? "OpenMesh" : "-",
              peer ? median(t_peer, loop_runs) : 0, peer ? note : "OpenMesh not installed");
    peer_free(om);
    cg_hemesh_free(h);
}

int main(int argc, char **argv)
{
    struct {
        const char *name;
        cg_mesh *(*make)(int);
        int arg;
    } cases[] = {
        {"grid 71x71", NULL, 71},
        {"icosphere level 6", shape_icosphere, 6},
        {"icosphere level 8", shape_icosphere, 8},
        {"grid 1024x1024", NULL, 1024},
    };
    /* --quick: the two small cases; any other argument: only the cases whose
     * name contains it */
    int only = argc > 1 && strcmp(argv[1], "--quick") == 0;
    const char *filter = argc > 1 && !only ? argv[1] : NULL;
    peer_quiet();
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        if ((only && i >= 2) || (filter && !strstr(cases[i].name, filter)))
            continue;
        cg_mesh *mesh = cases[i].make ? cases[i].make(cases[i].arg)
                                      : shape_grid(cases[i].arg, cases[i].arg, 1);
        if (!mesh) {
            fprintf(stderr, "bench_hemesh: cannot make %s\n", cases[i].name);
            return 1;
        }
        run_case(cases[i].name, mesh, 0);
        cg_mesh_free(mesh);
    }
    /* the real meshes: the dragon has non-manifold edges and vertices, which
     * cg repairs (CG_HEMESH_REPAIR) and OpenMesh's add_face skips */
    static const char *real[] = {"bunny.obj", "dragon_vrip_res3.ply.gz"};
    for (size_t i = 0; !only && i < sizeof real / sizeof real[0]; i++) {
        if (filter && !strstr(real[i], filter))
            continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/data/meshes/%s", CG_SOURCE_DIR, real[i]);
        cg_mesh *mesh = NULL;
        cg_error err;
        if (cg_mesh_load(path, &mesh, &err) != CG_OK) {
            fprintf(stderr, "bench_hemesh: %s\n", err.message);
            continue;
        }
        run_case(real[i], mesh, CG_HEMESH_REPAIR);
        cg_mesh_free(mesh);
    }
    return 0;
}
