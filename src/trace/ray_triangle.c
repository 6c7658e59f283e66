/* The watertight ray-triangle test of Woop, Benthin and Wald (JCGT 2013),
 * one triangle at a time: cg_ray_triangle, and the BVH's brute-force
 * reference query that passes every stored triangle through it.  The
 * traversal's four-lane version (bvh_traverse.c) performs the same
 * operations lane by lane. */
#include "bvh_internal.h"

#include <math.h>

/* The watertight test against t in (ray->t_min, t_max] (t_max included when
 * inclusive, excluded otherwise).  Edge functions exactly zero are recomputed
 * in double, as the paper prescribes, so the sign decision is consistent
 * between neighbouring triangles. */
static inline int hit_triangle(const bvh_ray *ray, const bvh_triangle *tri, float *t_out,
                               float *u_out, float *v_out)
{
    const int kx = ray->kx, ky = ray->ky, kz = ray->kz;
    const float ax = tri->v0[kx] - ray->origin[kx], ay = tri->v0[ky] - ray->origin[ky],
                az = tri->v0[kz] - ray->origin[kz];
    const float bx = tri->v1[kx] - ray->origin[kx], by = tri->v1[ky] - ray->origin[ky],
                bz = tri->v1[kz] - ray->origin[kz];
    const float cx = tri->v2[kx] - ray->origin[kx], cy = tri->v2[ky] - ray->origin[ky],
                cz = tri->v2[kz] - ray->origin[kz];
    const float Ax = ax - ray->shear_x * az, Ay = ay - ray->shear_y * az;
    const float Bx = bx - ray->shear_x * bz, By = by - ray->shear_y * bz;
    const float Cx = cx - ray->shear_x * cz, Cy = cy - ray->shear_y * cz;
    float U = Cx * By - Cy * Bx;
    float V = Ax * Cy - Ay * Cx;
    float W = Bx * Ay - By * Ax;
    if (U == 0 || V == 0 || W == 0) {
        U = (float)((double)Cx * By - (double)Cy * Bx);
        V = (float)((double)Ax * Cy - (double)Ay * Cx);
        W = (float)((double)Bx * Ay - (double)By * Ax);
    }
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0))
        return 0;
    float det = U + V + W;
    if (det == 0)
        return 0;
    float T = U * (ray->shear_z * az) + V * (ray->shear_z * bz) + W * (ray->shear_z * cz);
    float inv = 1.0f / det;
    float t = T * inv;
    if (!(t > ray->t_min))
        return 0;
    *t_out = t;
    *u_out = V * inv;
    *v_out = W * inv;
    return 1;
}

/* Lane k of a block as a triangle for the scalar test. */
static void block_triangle(const bvh_tri4 *b, int k, bvh_triangle *tri)
{
    for (int a = 0; a < 3; a++) {
        tri->v0[a] = b->v[0][a][k];
        tri->v1[a] = b->v[1][a][k];
        tri->v2[a] = b->v[2][a][k];
    }
    tri->id = b->id[k];
}

int cg_bvh_intersect_brute(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                           double t_max, cg_bvh_hit *hit)
{
    bvh_ray ray;
    if (!bvh || !bvh_ray_setup(&ray, origin, direction, t_min) || !(t_max > t_min))
        return 0;
    float best_t = bvh_clamp_far(t_max);
    uint32_t best_id = UINT32_MAX;
    int found = 0;
    /* Every stored triangle through the scalar test, one at a time. */
    for (size_t i = 0; i < 4 * bvh->block_count; i++) {
        const bvh_tri4 *b = &bvh->blocks[i / 4];
        size_t k = i % 4;
        if (b->id[k] == UINT32_MAX)
            continue;
        bvh_triangle tri;
        block_triangle(b, (int)k, &tri);
        float t, u, v;
        if (hit_triangle(&ray, &tri, &t, &u, &v) && bvh_better(t, tri.id, best_t, best_id)) {
            best_t = t;
            best_id = tri.id;
            found = 1;
            if (hit) {
                hit->u = u;
                hit->v = v;
            }
        }
    }
    if (found && hit) {
        hit->triangle = best_id;
        hit->t = best_t;
    }
    return found;
}

int cg_ray_triangle(cg_vec3 origin, cg_vec3 direction, cg_vec3 a, cg_vec3 b, cg_vec3 c,
                    double t_min, double t_max, double *t, double *u, double *v)
{
    bvh_ray ray;
    if (!bvh_ray_setup(&ray, origin, direction, t_min))
        return 0;
    bvh_triangle tri;
    const cg_vec3 corner[3] = {a, b, c};
    float *dst[3] = {tri.v0, tri.v1, tri.v2};
    for (int k = 0; k < 3; k++) {
        dst[k][0] = (float)corner[k].x;
        dst[k][1] = (float)corner[k].y;
        dst[k][2] = (float)corner[k].z;
        if (!isfinite(dst[k][0]) || !isfinite(dst[k][1]) || !isfinite(dst[k][2]))
            return 0;
    }
    tri.id = 0;
    float ft, fu, fv;
    if (!hit_triangle(&ray, &tri, &ft, &fu, &fv) || !(ft <= t_max))
        return 0;
    if (t)
        *t = ft;
    if (u)
        *u = fu;
    if (v)
        *v = fv;
    return 1;
}
