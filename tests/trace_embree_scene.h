/* An Embree 3 scene of one triangle mesh, for comparing cg's ray tracer with
 * Embree in the test and the benchmark. */
#ifndef CG_TEST_TRACE_EMBREE_SCENE_H
#define CG_TEST_TRACE_EMBREE_SCENE_H

#include <embree3/rtcore.h>
#include <math.h>
#include <stdint.h>

#include "cg/core.h"

/* Commits a scene of triangles (corners positions[indices[3 i + k]], or
 * 3 i + k without indices) with Embree's default build settings. */
static inline RTCScene embree_scene(RTCDevice device, const cg_vec3 *positions, size_t vertex_count,
                                    const uint32_t *indices, size_t triangle_count)
{
    RTCScene scene = rtcNewScene(device);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *v = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       3 * sizeof(float), vertex_count);
    unsigned *t = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                          3 * sizeof(unsigned), triangle_count);
    for (size_t i = 0; i < vertex_count; i++) {
        v[3 * i] = (float)positions[i].x;
        v[3 * i + 1] = (float)positions[i].y;
        v[3 * i + 2] = (float)positions[i].z;
    }
    for (size_t i = 0; i < 3 * triangle_count; i++)
        t[i] = indices ? indices[i] : (unsigned)i;
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene);
    return scene;
}

static inline void embree_ray(struct RTCRay *ray, cg_vec3 o, cg_vec3 d, float t_far)
{
    ray->org_x = (float)o.x;
    ray->org_y = (float)o.y;
    ray->org_z = (float)o.z;
    ray->dir_x = (float)d.x;
    ray->dir_y = (float)d.y;
    ray->dir_z = (float)d.z;
    ray->tnear = 0;
    ray->tfar = t_far;
    ray->time = 0;
    ray->mask = 0xffffffffu;
    ray->id = 0;
    ray->flags = 0;
}

/* Nearest hit: the triangle index, or -1 for none. */
static inline long embree_intersect(RTCScene scene, cg_vec3 o, cg_vec3 d, float *t)
{
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    struct RTCRayHit rh;
    embree_ray(&rh.ray, o, d, INFINITY);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return -1;
    if (t)
        *t = rh.ray.tfar;
    return (long)rh.hit.primID;
}

static inline int embree_occluded(RTCScene scene, cg_vec3 o, cg_vec3 d, float t_far)
{
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    struct RTCRay ray;
    embree_ray(&ray, o, d, t_far);
    rtcOccluded1(scene, &context, &ray);
    return ray.tfar == -INFINITY;
}

#endif
