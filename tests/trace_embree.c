/* cg's BVH against Embree 3 on the same meshes and rays: the nearest-hit
 * triangle must agree on at least 99.9% of random rays (the two differ only
 * where a ray grazes a shared edge or vertex, where either neighbour is
 * right), and so must the shadow-ray answer. */
#include "check.h"
#include "trace_embree_scene.h"
#include "trace_meshes.h"
#include "cg/trace.h"

#if defined(__SANITIZE_ADDRESS__)
#define RAY_COUNT 50000
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RAY_COUNT 50000
#endif
#endif
#ifndef RAY_COUNT
#define RAY_COUNT 400000
#endif

static void compare(RTCDevice device, const char *name, const soup *s, check_rng *rng)
{
    cg_bvh *bvh;
    CHECK(cg_bvh_build(s->p, s->nv, s->idx, s->nt, &bvh) == CG_OK);
    RTCScene scene = embree_scene(device, s->p, s->nv, s->idx, s->nt);
    long agree = 0, hits = 0, shadow_agree = 0, t_close = 0, both = 0;
    for (long i = 0; i < RAY_COUNT; i++) {
        cg_vec3 o = cg_vec3_make(check_rng_range(rng, -2.5, 2.5), check_rng_range(rng, -2.5, 2.5),
                                 check_rng_range(rng, -2.5, 2.5));
        /* Toward a random point of the central region, so most rays hit. */
        cg_vec3 target = cg_vec3_make(check_rng_range(rng, -1, 1), check_rng_range(rng, -1, 1),
                                      check_rng_range(rng, -1, 1));
        cg_vec3 d = cg_vec3_normalize(cg_vec3_sub(target, o));
        cg_bvh_hit h;
        int hit = cg_bvh_intersect(bvh, o, d, 0, INFINITY, &h);
        float te = 0;
        long e = embree_intersect(scene, o, d, &te);
        hits += hit;
        if ((hit ? (long)h.triangle : -1) == e)
            agree++;
        if (hit && e >= 0) {
            both++;
            t_close += fabsf(h.t - te) <= 1e-5f * fmaxf(1, te);
        }
        float far = (float)check_rng_range(rng, 0.5, 5);
        shadow_agree += cg_bvh_occluded(bvh, o, d, 0, far) == embree_occluded(scene, o, d, far);
    }
    double rate = (double)agree / RAY_COUNT;
    printf("%s: %zu triangles, %ld rays, %ld hits, nearest triangle agrees on %.4f%%, "
           "shadow rays on %.4f%%\n",
           name, s->nt, (long)RAY_COUNT, hits, 100 * rate, 100.0 * shadow_agree / RAY_COUNT);
    CHECK_MSG(rate >= 0.999, "%s: nearest hits agree on only %.4f%%", name, 100 * rate);
    CHECK_MSG(shadow_agree >= 0.999 * RAY_COUNT, "%s: shadow rays agree on only %ld of %ld", name,
              shadow_agree, (long)RAY_COUNT);
    CHECK_MSG(t_close >= 0.999 * both, "%s: distances agree on only %ld of %ld", name, t_close,
              both);
    CHECK(hits > RAY_COUNT / 4);
    rtcReleaseScene(scene);
    cg_bvh_free(bvh);
}

int main(void)
{
    RTCDevice device = rtcNewDevice("threads=1");
    if (!device) {
        printf("Embree device could not be created: skipped\n");
        return 0;
    }
    check_rng rng = {2024};
    soup sphere = bumpy_sphere(&rng, 100, 160, 0.03);
    soup ring = torus(200, 60);
    soup rand = random_soup(&rng, 20000);
    compare(device, "bumpy sphere", &sphere, &rng);
    compare(device, "torus", &ring, &rng);
    compare(device, "random soup", &rand, &rng);
    soup_free(&sphere);
    soup_free(&ring);
    soup_free(&rand);
    rtcReleaseDevice(device);
    return check_finish();
}
