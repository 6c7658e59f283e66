/* Ray tracing throughput and BVH build time: cg's BVH (binned SAH, 32-byte
 * nodes, watertight triangle test) against Embree 3's rtcIntersect1 and
 * rtcOccluded1 on the same rays, on 1 and 2 threads, and cg_bvh_build
 * against Embree's default scene build (rtcCommitScene), on real scanned
 * meshes (data/meshes) and generated ones. */
#include "bench.h"
#include "trace_meshes.h"
#include "cg/mesh.h"
#include "cg/trace.h"
#include "cg/xform.h"

#include <pthread.h>
#include <string.h>

#ifdef CG_HAVE_EMBREE
#include "trace_embree_scene.h"
#endif

enum { WIDTH = 640, HEIGHT = 480, RUNS = 5 };

/* The median CPU time of the calling thread over runs (at most 64): on a
 * shared, loaded machine it varies far less than the wall clock.  For the
 * single-thread rows, where all the work is on the calling thread. */
static double median_cpu(void (*fn)(void *), void *arg, int runs)
{
    return bench_median_clock(fn, arg, runs, CLOCK_THREAD_CPUTIME_ID);
}

typedef struct rays {
    size_t count;
    cg_vec3 *origin, *direction;
} rays;

typedef struct work {
    const cg_bvh *bvh;
#ifdef CG_HAVE_EMBREE
    RTCScene scene;
#endif
    const rays *r;
    int shadow, threads;
    size_t begin, end;
    long hits;
} work;

static void *trace_cg_range(void *arg)
{
    work *w = arg;
    long hits = 0;
    for (size_t i = w->begin; i < w->end; i++) {
        if (w->shadow)
            hits += cg_bvh_occluded(w->bvh, w->r->origin[i], w->r->direction[i], 0, INFINITY);
        else
            hits += cg_bvh_intersect(w->bvh, w->r->origin[i], w->r->direction[i], 0, INFINITY,
                                     NULL);
    }
    w->hits = hits;
    return NULL;
}

#ifdef CG_HAVE_EMBREE
static void *trace_embree_range(void *arg)
{
    work *w = arg;
    long hits = 0;
    for (size_t i = w->begin; i < w->end; i++) {
        if (w->shadow)
            hits += embree_occluded(w->scene, w->r->origin[i], w->r->direction[i], INFINITY);
        else
            hits += embree_intersect(w->scene, w->r->origin[i], w->r->direction[i], NULL) >= 0;
    }
    w->hits = hits;
    return NULL;
}
#endif

/* Runs fn over all rays on w->threads threads (interleaved halves). */
static long run_threads(work *w, void *(*fn)(void *))
{
    work parts[2];
    pthread_t id;
    int n = w->threads;
    for (int k = 0; k < n; k++) {
        parts[k] = *w;
        parts[k].begin = w->r->count * (size_t)k / (size_t)n;
        parts[k].end = w->r->count * (size_t)(k + 1) / (size_t)n;
    }
    if (n == 2)
        pthread_create(&id, NULL, fn, &parts[1]);
    fn(&parts[0]);
    if (n == 2)
        pthread_join(id, NULL);
    return parts[0].hits + (n == 2 ? parts[1].hits : 0);
}

static void run_cg(void *arg)
{
    work *w = arg;
    w->hits = run_threads(w, trace_cg_range);
}

#ifdef CG_HAVE_EMBREE
static void run_embree(void *arg)
{
    work *w = arg;
    w->hits = run_threads(w, trace_embree_range);
}
#endif

/* Primary rays of a WIDTH x HEIGHT view framing the mesh, and shadow rays
 * from their hits toward a directional light. */
static void make_rays(const cg_bvh *bvh, const soup *s, rays *primary, rays *shadow)
{
    cg_vec3 lo = s->p[0], hi = s->p[0];
    for (size_t i = 0; i < s->nv; i++) {
        cg_vec3 p = s->p[i];
        lo = cg_vec3_make(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
        hi = cg_vec3_make(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
    }
    cg_camera cam = cg_camera_default();
    cam.eye = cg_vec3_make(0.4, 0.5, 1);
    cg_camera_frame(&cam, lo, hi, (double)WIDTH / HEIGHT);
    size_t n = (size_t)WIDTH * HEIGHT;
    primary->count = n;
    primary->origin = malloc(n * sizeof(cg_vec3));
    primary->direction = malloc(n * sizeof(cg_vec3));
    shadow->count = 0;
    shadow->origin = malloc(n * sizeof(cg_vec3));
    shadow->direction = malloc(n * sizeof(cg_vec3));
    cg_vec3 light = cg_vec3_normalize(cg_vec3_make(-1, 2, 1.5));
    double scale = fmax(fmax(fabs(lo.x), fabs(hi.x)),
                        fmax(fmax(fabs(lo.y), fabs(hi.y)), fmax(fabs(lo.z), fabs(hi.z))));
    for (int y = 0; y < HEIGHT; y++)
        for (int x = 0; x < WIDTH; x++) {
            size_t i = (size_t)y * WIDTH + x;
            cg_camera_ray(&cam, WIDTH, HEIGHT, x + 0.5, y + 0.5, &primary->origin[i],
                          &primary->direction[i]);
            cg_bvh_hit h;
            if (cg_bvh_intersect(bvh, primary->origin[i], primary->direction[i], 0, INFINITY, &h)) {
                cg_vec3 p = cg_vec3_add(primary->origin[i],
                                        cg_vec3_scale(primary->direction[i], h.t));
                /* Backed off toward the eye, so the ray does not start
                 * inside the surface it leaves. */
                p = cg_vec3_sub(p, cg_vec3_scale(primary->direction[i], scale * 1e-4));
                shadow->origin[shadow->count] = p;
                shadow->direction[shadow->count] = light;
                shadow->count++;
            }
        }
}

static void free_rays(rays *r)
{
    free(r->origin);
    free(r->direction);
}

typedef struct build_job {
    const soup *s;
#ifdef CG_HAVE_EMBREE
    RTCDevice device;
#endif
} build_job;

static void build_cg(void *arg)
{
    build_job *b = arg;
    cg_bvh *bvh;
    cg_bvh_build(b->s->p, b->s->nv, b->s->idx, b->s->nt, &bvh);
    cg_bvh_free(bvh);
}

static void build_cg2(void *arg)
{
    build_job *b = arg;
    cg_bvh *bvh;
    cg_bvh_build_threads(b->s->p, b->s->nv, b->s->idx, b->s->nt, 2, &bvh);
    cg_bvh_free(bvh);
}

#ifdef CG_HAVE_EMBREE
static void build_embree(void *arg)
{
    build_job *b = arg;
    RTCScene scene = embree_scene(b->device, b->s->p, b->s->nv, b->s->idx, b->s->nt);
    rtcReleaseScene(scene);
}
#endif

static void bench_mesh(const char *name, const soup *s)
{
    char label[160], note[200];
    cg_bvh *bvh;
    if (cg_bvh_build(s->p, s->nv, s->idx, s->nt, &bvh) != CG_OK) {
        fprintf(stderr, "%s: build failed\n", name);
        return;
    }
    cg_bvh_stats st;
    cg_bvh_get_stats(bvh, &st);
    build_job bj = {s
#ifdef CG_HAVE_EMBREE
                    ,
                    NULL
#endif
    };
    int build_runs = s->nt > 500000 ? 3 : RUNS;
    double cg_build = median_cpu(build_cg, &bj, build_runs);
#ifdef CG_HAVE_EMBREE
    /* The single-thread device is timed before the default one exists:
     * while any device runs Embree's thread pool on all cores, a build on
     * the "threads=1" device uses them too (its calling thread's CPU time
     * then counts only part of the work, about half on 2 cores). */
    RTCDevice dev1 = rtcNewDevice("threads=1");
    bj.device = dev1;
    double e1 = median_cpu(build_embree, &bj, build_runs);
    RTCDevice dev2 = rtcNewDevice(NULL);
    bj.device = dev2;
    double e2 = bench_median(build_embree, &bj, build_runs);
    rtcReleaseDevice(dev2);
    snprintf(label, sizeof label, "trace build %s (%zu tris)", name, s->nt);
    snprintf(note, sizeof note, "both 1 thread, thread CPU time; cg SAH cost %.1f", st.sah_cost);
    bench_row(label, cg_build, "embree3", e1, note);
    snprintf(label, sizeof label, "trace build %s, 2 threads", name);
    bj.s = s;
    double cg2 = bench_median(build_cg2, &bj, build_runs);
    bench_row(label, cg2, "embree3", e2,
              "cg 2 threads, Embree default device (all cores); wall time");
    RTCScene scene = embree_scene(dev1, s->p, s->nv, s->idx, s->nt);
#else
    snprintf(label, sizeof label, "trace build %s (%zu tris)", name, s->nt);
    bench_row(label, cg_build, "-", 0, "Embree 3 not installed; thread CPU time");
    snprintf(label, sizeof label, "trace build %s, 2 threads", name);
    bench_row(label, bench_median(build_cg2, &bj, build_runs), "-", 0, "Embree 3 not installed");
#endif
    rays primary, shadow;
    make_rays(bvh, s, &primary, &shadow);
    for (int kind = 0; kind < 2; kind++)
        for (int threads = 1; threads <= 2; threads++) {
            rays *r = kind ? &shadow : &primary;
            work w;
            memset(&w, 0, sizeof w);
            w.bvh = bvh;
            w.r = r;
            w.shadow = kind;
            w.threads = threads;
            double (*timer)(void (*)(void *), void *, int) = threads == 1 ? median_cpu
                                                                          : bench_median;
            double tc = timer(run_cg, &w, RUNS);
            long cg_hits = w.hits;
            snprintf(label, sizeof label, "trace %s %s %dT (%zu rays)", kind ? "shadow" : "primary",
                     name, threads, r->count);
#ifdef CG_HAVE_EMBREE
            w.scene = scene;
            double te = timer(run_embree, &w, RUNS);
            snprintf(note, sizeof note, "cg %.2f Mrays/s, Embree %.2f Mrays/s; hits %ld vs %ld; %s",
                     r->count / tc * 1e-6, r->count / te * 1e-6, cg_hits, w.hits,
                     threads == 1 ? "thread CPU time" : "wall time");
            bench_row(label, tc, "embree3", te, note);
#else
            snprintf(note, sizeof note, "cg %.2f Mrays/s; Embree 3 not installed",
                     r->count / tc * 1e-6);
            bench_row(label, tc, "-", 0, note);
#endif
        }
    free_rays(&primary);
    free_rays(&shadow);
    cg_bvh_free(bvh);
#ifdef CG_HAVE_EMBREE
    rtcReleaseScene(scene);
    rtcReleaseDevice(dev1);
#endif
}

/* A mesh file as a triangle soup with shared vertices (faces fanned). */
static int load_soup(const char *path, soup *s)
{
    cg_mesh *mesh;
    cg_error err;
    if (cg_mesh_load(path, &mesh, &err) != CG_OK) {
        fprintf(stderr, "bench_trace: cannot read %s\n", path);
        return 0;
    }
    s->nv = mesh->vertex_count;
    s->nt = cg_mesh_triangle_count(mesh);
    s->p = malloc((s->nv ? s->nv : 1) * sizeof *s->p);
    s->idx = malloc((3 * s->nt + 1) * sizeof *s->idx);
    memcpy(s->p, mesh->positions, s->nv * sizeof *s->p);
    size_t t = 0;
    for (size_t f = 0; f < mesh->face_count; f++) {
        uint32_t b = mesh->face_offsets[f], e = mesh->face_offsets[f + 1];
        for (uint32_t k = b + 1; k + 1 < e; k++) {
            s->idx[3 * t] = mesh->face_indices[b];
            s->idx[3 * t + 1] = mesh->face_indices[k];
            s->idx[3 * t + 2] = mesh->face_indices[k + 1];
            t++;
        }
    }
    cg_mesh_free(mesh);
    return 1;
}

int main(void)
{
    check_rng rng = {7};
    const char *files[][2] = {{"bunny", CG_DATA_DIR "/meshes/bunny.obj"},
                              {"dragon", CG_DATA_DIR "/meshes/dragon_vrip_res3.ply.gz"}};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        soup s;
        if (!load_soup(files[i][1], &s))
            continue;
        bench_mesh(files[i][0], &s);
        soup_free(&s);
    }
    soup sphere = bumpy_sphere(&rng, 500, 1000, 0.01);
    bench_mesh("sphere-1M", &sphere);
    soup_free(&sphere);
    soup soup100k = random_soup(&rng, 100000);
    bench_mesh("soup-100k", &soup100k);
    soup_free(&soup100k);
    return 0;
}
