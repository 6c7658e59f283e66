/* Path tracer benchmark: the Stanford bunny at 320 x 240, 64 samples a pixel,
 * depth 8, under a uniform sky.
 *   - the library call (cg_path_render_sums) on 1 and 2 threads;
 *   - the command line (`cg render --algorithm pathtrace`) beside it;
 *   - strong scaling under Open MPI (`mpirun -np N cg render ...`, rank 0
 *     scheduling and N - 1 ranks rendering) against the one-process command,
 *     when mpirun is present and cg was built with MPI;
 *   - the figures of the scaling model in docs/pathtrace.md: the time of one
 *     unit (32 x 32 pixels, 16 samples), mpirun's start-up, and rank 0's
 *     cost per unit, from a render of many small units.
 * Wall-clock medians (rows with ranks use the machine's cores at once). */
#include "bench.h"
#include "cg/mesh.h"
#include "cg/pathtrace.h"
#include "cg/trace.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define MESH CG_SOURCE_DIR "/data/meshes/bunny.obj"

typedef struct job {
    cg_trace_scene *scene;
    cg_camera camera;
    cg_path_options options;
    uint64_t *sums;
    int width, height;
} job;

static void render_once(void *context)
{
    job *j = context;
    memset(j->sums, 0, (size_t)j->width * (size_t)j->height * 3 * sizeof *j->sums);
    if (cg_path_render_sums(j->scene, &j->camera, j->width, j->height, &j->options, j->sums)
        != CG_OK)
        abort();
    bench_sink += (double)j->sums[0];
}

/* Runs argv (stderr and stdout to /dev/null) and returns its wall time, or
 * -1 when it failed. */
static double run_seconds(char *const argv[])
{
    double start = bench_now();
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        if (!freopen("/dev/null", "w", stderr) || !freopen("/dev/null", "w", stdout))
            _exit(127);
        execvp(argv[0], argv);
        _exit(127);
    }
    int status;
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    return bench_now() - start;
}

static double median_run(char *const argv[], int runs)
{
    double samples[16];
    for (int i = 0; i < runs; i++)
        if ((samples[i] = run_seconds(argv)) < 0)
            return -1;
    qsort(samples, (size_t)runs, sizeof *samples, bench_compare);
    return runs % 2 ? samples[runs / 2] : 0.5 * (samples[runs / 2 - 1] + samples[runs / 2]);
}

/* `cg render` of the bunny, under mpirun with np ranks when np > 0. */
static double time_command(int np, const char *size, const char *spp, const char *threads, int runs)
{
    char ranks[16];
    snprintf(ranks, sizeof ranks, "%d", np);
    char *with_mpi[] = {
        "mpirun",    "--oversubscribe", "--bind-to",  "none",  "-np",
        ranks,       CG_TOOL,           "render",     MESH,    "--algorithm",
        "pathtrace", "--size",          (char *)size, "--spp", (char *)spp,
        "--threads", (char *)threads,   "--quiet",    "-o",    "/tmp/bench_pathtrace.pfm",
        NULL};
    return median_run(np > 0 ? with_mpi : with_mpi + 6, runs);
}

static int mpi_works(void)
{
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
    return time_command(2, "32x32", "1", "1", 1) > 0;
}

int main(void)
{
    cg_mesh *mesh = NULL;
    cg_error err;
    job j = {.width = 320, .height = 240};
    if (cg_mesh_load(MESH, &mesh, &err) != CG_OK) {
        fprintf(stderr, "bench_pathtrace: %s\n", err.message);
        return 1;
    }
    cg_trace_material m = cg_trace_material_default();
    m.surface.color = cg_vec3_make(0.8, 0.8, 0.8);
    m.surface.kd = 1;
    cg_vec3 lo, hi;
    if (cg_trace_scene_create(&j.scene) != CG_OK
        || cg_trace_scene_add_mesh(j.scene, mesh, NULL, 0.6, &m) != CG_OK
        || cg_trace_scene_bounds(j.scene, &lo, &hi) != CG_OK)
        return 1;
    cg_mesh_free(mesh);
    j.camera = cg_camera_default();
    j.camera.target = cg_vec3_scale(cg_vec3_add(lo, hi), 0.5);
    j.camera.eye = cg_vec3_add(j.camera.target, cg_vec3_make(0, 0, 1));
    cg_camera_frame(&j.camera, lo, hi, (double)j.width / j.height);
    j.options = cg_path_options_default();
    j.options.spp = j.options.sample_end = 64;
    j.options.environment = cg_vec3_make(1, 1, 1);
    j.sums = malloc((size_t)j.width * (size_t)j.height * 3 * sizeof *j.sums);
    if (!j.sums)
        return 1;

    double library1 = bench_median(render_once, &j, 3);
    j.options.threads = 2;
    double library2 = bench_median(render_once, &j, 3);
    bench_row("pathtrace bunny 320x240 64spp, library, 2 threads", library2, "cg 1 thread",
              library1, "ratio: speed-up of 2 threads");
    double command1 = time_command(0, "320x240", "64", "1", 3);
    bench_row("pathtrace bunny 320x240 64spp, cg render (command line)", command1, "cg library",
              library1, "ratio: library time / command time");

    if (!mpi_works()) {
        bench_row("pathtrace under mpirun", 0, "-", 0,
                  "skipped: mpirun missing or cg built without Open MPI (libopenmpi-dev)");
        free(j.sums);
        cg_trace_scene_free(j.scene);
        return 0;
    }
    for (int np = 2; np <= 3; np++) {
        char name[96], note[96];
        double t = time_command(np, "320x240", "64", "1", 3);
        snprintf(name, sizeof name, "pathtrace bunny 320x240 64spp, mpirun -np %d", np);
        snprintf(note, sizeof note, "%d rendering rank(s); ratio: speed-up over one process",
                 np - 1);
        bench_row(name, t, "cg 1 process", command1, note);
    }

    /* The model's figures: one unit's time from the library; mpirun's
     * start-up from a one-unit render; rank 0's cost per unit from 1,200
     * units of 1 sample over one rendering rank, less their rendering. */
    j.options.threads = 1;
    j.options.x1 = j.options.y1 = 32;
    j.options.sample_end = 16;
    double unit = bench_median(render_once, &j, 5);
    double launch = time_command(2, "32x32", "16", "1", 3);
    free(j.sums);
    j.width = 1280, j.height = 960; /* the same 4:3 framing, 40 x 30 units */
    j.sums = malloc((size_t)j.width * (size_t)j.height * 3 * sizeof *j.sums);
    if (!j.sums)
        return 1;
    j.options.x1 = j.width, j.options.y1 = j.height, j.options.sample_end = 1;
    double small_render = bench_median(render_once, &j, 3);
    double small_units = time_command(2, "1280x960", "1", "1", 3) - launch;
    double per_unit = (small_units - small_render) / (40.0 * 30.0);
    char note[160];
    snprintf(
        note, sizeof note,
        "model: unit (32x32, 16 spp) %.1f ms, mpirun start-up %.0f ms, rank 0 per unit %.2f ms",
        unit * 1e3, launch * 1e3, per_unit * 1e3);
    bench_row("pathtrace scaling model figures", unit, "-", 0, note);
    free(j.sums);
    cg_trace_scene_free(j.scene);
    return 0;
}
