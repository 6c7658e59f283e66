/* Queries on the 4-wide BVH: rays prepared once (slab data; the watertight
 * test's shear only for rays that reach the tree), ordered traversal testing
 * a node's four boxes or a block's four triangles in one vector pass, and the
 * nearest-hit and shadow queries. */
#include "bvh_internal.h"

#include <math.h>

/* The ray's checks and its data for the slab test (origin, inverse, flat
 * axes) and the watertight test's dominant axis kz; 0 when the ray is not
 * finite or has zero direction. */
static int ray_setup_slabs(bvh_ray *ray, cg_vec3 origin, cg_vec3 direction, double t_min)
{
    double o[3] = {origin.x, origin.y, origin.z}, d[3] = {direction.x, direction.y, direction.z};
    int kz = 0;
    for (int a = 0; a < 3; a++) {
        /* x - x is 0 exactly for finite x (and the origin must stay finite
         * in float). */
        float fo = (float)o[a];
        if (!(fo - fo == 0) || !(d[a] - d[a] == 0))
            return 0;
        if (fabs(d[a]) > fabs(d[kz]))
            kz = a;
    }
    if (d[kz] == 0 || !(t_min - t_min == 0))
        return 0;
    ray->flat_axes = 0;
    for (int a = 0; a < 3; a++) {
        ray->direction[a] = d[a];
        ray->origin[a] = (float)o[a];
        float f = (float)d[a];
        /* A zero (or float-underflowing) component is handled apart by the
         * slab test; its inverse only has to stay finite. */
        if (f == 0) {
            f = 1e-30f;
            ray->flat_axes |= 1 << a;
        }
        ray->inverse[a] = 1.0f / f;
    }
    ray->kz = kz;
    ray->t_min = (float)t_min;
    return 1;
}

/* The rest of the watertight test's data: the axis permutation and the
 * shear.  Apart, so that rays missing the BVH's root box (most primary
 * rays of a framed mesh) skip its three divisions. */
static void ray_setup_shear(bvh_ray *ray)
{
    const double *d = ray->direction;
    int kz = ray->kz, kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0) {
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    ray->kx = kx;
    ray->ky = ky;
    ray->shear_x = (float)(d[kx] / d[kz]);
    ray->shear_y = (float)(d[ky] / d[kz]);
    ray->shear_z = (float)(1.0 / d[kz]);
}

int bvh_ray_setup(bvh_ray *ray, cg_vec3 origin, cg_vec3 direction, double t_min)
{
    if (!ray_setup_slabs(ray, origin, direction, t_min))
        return 0;
    ray_setup_shear(ray);
    return 1;
}

/* The slab test for rays with a zero direction component: on such an axis
 * the slab holds the whole ray or none of it, boundaries included. */
static int hit_box_flat(const bvh_ray *ray, const bvh_node *node, float t_far_limit, float *t_near)
{
    float tn = ray->t_min, tf = FLT_MAX;
    for (int a = 0; a < 3; a++) {
        if (ray->flat_axes & (1 << a)) {
            if (ray->origin[a] < node->lo[a] || ray->origin[a] > node->hi[a]) {
                *t_near = FLT_MAX;
                return 0;
            }
            continue;
        }
        float t0 = (node->lo[a] - ray->origin[a]) * ray->inverse[a];
        float t1 = (node->hi[a] - ray->origin[a]) * ray->inverse[a];
        float n = t0 < t1 ? t0 : t1, f = t0 < t1 ? t1 : t0;
        tn = n > tn ? n : tn;
        tf = f < tf ? f : tf;
    }
    tf *= 1.0000003576f;
    tf = tf < t_far_limit ? tf : t_far_limit;
    *t_near = tn;
    return tn <= tf;
}

/* Slab test; far distances grown by 1 + 2 gamma(3) (Ize 2013) so rounding
 * never rejects a box that the exact ray touches.  origin and inverse hold
 * the ray's origin and 1 / direction in lanes 0..2. */
static inline int hit_box(const bvh_ray *ray, v4 origin, v4 inverse, const bvh_node *node,
                          float t_far_limit, float *t_near)
{
    if (ray->flat_axes)
        return hit_box_flat(ray, node, t_far_limit, t_near);
    v4 t0 = v4_mul(v4_sub(v4_load3(node->lo), origin), inverse);
    v4 t1 = v4_mul(v4_sub(v4_load3(node->hi), origin), inverse);
    float tn = v4_max3(v4_min(t0, t1), ray->t_min);
    float tf = v4_min3(v4_max(t0, t1), FLT_MAX) * 1.0000003576f;
    tf = tf < t_far_limit ? tf : t_far_limit;
    *t_near = tn;
    return tn <= tf;
}

/* The ray as the 4-wide tests read it: origin, inverse direction and the
 * watertight test's permuted origin and shear, each in all four lanes, and
 * the rows of a node's boxes that hold each axis' near and far planes. */
typedef struct ray4 {
    v4 ox, oy, oz, ix, iy, iz, t_min;
    v4 okx, oky, okz, sx, sy, sz;
    int near[3]; /* the far plane's row is near ^ 1 */
} ray4;

static void ray4_setup(ray4 *r, const bvh_ray *ray)
{
    r->ox = v4_set(ray->origin[0]);
    r->oy = v4_set(ray->origin[1]);
    r->oz = v4_set(ray->origin[2]);
    r->ix = v4_set(ray->inverse[0]);
    r->iy = v4_set(ray->inverse[1]);
    r->iz = v4_set(ray->inverse[2]);
    r->t_min = v4_set(ray->t_min);
    r->okx = v4_set(ray->origin[ray->kx]);
    r->oky = v4_set(ray->origin[ray->ky]);
    r->okz = v4_set(ray->origin[ray->kz]);
    r->sx = v4_set(ray->shear_x);
    r->sy = v4_set(ray->shear_y);
    r->sz = v4_set(ray->shear_z);
    /* With a positive inverse the lower plane is met first: then
     * (lo - o) / d <= (hi - o) / d, the min and max of the scalar test. */
    for (int a = 0; a < 3; a++) {
        r->near[a] = ray->inverse[a] >= 0 ? 2 * a : 2 * a + 1;
    }
}

/* A node's four boxes against the ray, one plane of all four per vector
 * (rows of bvh4_node.box, a lane per child).  On each axis the ray meets
 * the near plane first: the lo row when it runs toward +, the hi row when
 * toward -, so the near row is chosen once per ray (ray4.near) and the far
 * row is the other of the pair (near ^ 1):
 *
 *        lo x      hi x            rows 0, 1: x (2, 3: y; 4, 5: z)
 *    o --->|---------|---->        inverse x >= 0: near row 0, far row 1
 *          |   box   |
 *    <-----|---------|<--- o       inverse x < 0:  near row 1, far row 0
 *       far x     near x
 *
 *   t_near = max(near x, near y, near z, t_min)    entered when
 *   t_far  = min(far x, far y, far z)              t_near <= t_far
 *
 * Bit k of the result says child k is entered, t_near[k] where.  Lane by lane the very operations of hit_box, so
 * each decision is the one hit_box would make; an empty slot's box gives
 * t_near +inf and t_far -inf and is never entered. */
static inline int hit_node4(const bvh_ray *ray, const ray4 *r, const bvh4_node *node, v4 limit4,
                            float t_far_limit, float t_near[4])
{
    if (ray->flat_axes) {
        int mask = 0;
        for (int k = 0; k < 4; k++) {
            bvh_node box;
            for (int a = 0; a < 3; a++) {
                box.lo[a] = node->box[2 * a][k];
                box.hi[a] = node->box[2 * a + 1][k];
            }
            mask |= hit_box_flat(ray, &box, t_far_limit, &t_near[k]) << k;
        }
        return mask;
    }
    const int x = r->near[0], y = r->near[1], z = r->near[2];
    v4 nx = v4_mul(v4_sub(v4_load(node->box[x]), r->ox), r->ix);
    v4 ny = v4_mul(v4_sub(v4_load(node->box[y]), r->oy), r->iy);
    v4 nz = v4_mul(v4_sub(v4_load(node->box[z]), r->oz), r->iz);
    v4 fx = v4_mul(v4_sub(v4_load(node->box[x ^ 1]), r->ox), r->ix);
    v4 fy = v4_mul(v4_sub(v4_load(node->box[y ^ 1]), r->oy), r->iy);
    v4 fz = v4_mul(v4_sub(v4_load(node->box[z ^ 1]), r->oz), r->iz);
    v4 tn = v4_max(v4_max(nx, ny), v4_max(nz, r->t_min));
    /* As hit_box, without its clamp of t_far to FLT_MAX: the limit
     * clamps it anyway. */
    v4 tf = v4_min(v4_min(fx, fy), fz);
    tf = v4_min(v4_mul(tf, v4_set(1.0000003576f)), limit4);
    v4_store(t_near, tn);
    return v4_bits(v4_le(tn, tf));
}

/* The watertight test on a block of four triangles: bit k of the result
 * says triangle k is hit, with t[k], u[k], v[k].  Lane by lane the very
 * operations of the scalar test (hit_triangle in ray_triangle.c: the same
 * rounding, the same double-precision retry of edge functions that come out
 * zero), so its answers are hit_triangle's; NaN lanes are never hit. */
static inline int hit_tri4(const bvh_ray *ray, const ray4 *r, const bvh_tri4 *b, float t[4],
                           float u[4], float v[4])
{
    const int kx = ray->kx, ky = ray->ky, kz = ray->kz;
    const v4 ax = v4_sub(v4_load(b->v[0][kx]), r->okx), ay = v4_sub(v4_load(b->v[0][ky]), r->oky),
             az = v4_sub(v4_load(b->v[0][kz]), r->okz);
    const v4 bx = v4_sub(v4_load(b->v[1][kx]), r->okx), by = v4_sub(v4_load(b->v[1][ky]), r->oky),
             bz = v4_sub(v4_load(b->v[1][kz]), r->okz);
    const v4 cx = v4_sub(v4_load(b->v[2][kx]), r->okx), cy = v4_sub(v4_load(b->v[2][ky]), r->oky),
             cz = v4_sub(v4_load(b->v[2][kz]), r->okz);
    const v4 Ax = v4_sub(ax, v4_mul(r->sx, az)), Ay = v4_sub(ay, v4_mul(r->sy, az));
    const v4 Bx = v4_sub(bx, v4_mul(r->sx, bz)), By = v4_sub(by, v4_mul(r->sy, bz));
    const v4 Cx = v4_sub(cx, v4_mul(r->sx, cz)), Cy = v4_sub(cy, v4_mul(r->sy, cz));
    v4 U = v4_sub(v4_mul(Cx, By), v4_mul(Cy, Bx));
    v4 V = v4_sub(v4_mul(Ax, Cy), v4_mul(Ay, Cx));
    v4 W = v4_sub(v4_mul(Bx, Ay), v4_mul(By, Ax));
    const v4 zero = v4_set(0);
    int flat = v4_bits(v4_or(v4_or(v4_eq(U, zero), v4_eq(V, zero)), v4_eq(W, zero)));
    if (flat) {
        float fu[4], fv[4], fw[4], pax[4], pay[4], pbx[4], pby[4], pcx[4], pcy[4];
        v4_store(fu, U);
        v4_store(fv, V);
        v4_store(fw, W);
        v4_store(pax, Ax);
        v4_store(pay, Ay);
        v4_store(pbx, Bx);
        v4_store(pby, By);
        v4_store(pcx, Cx);
        v4_store(pcy, Cy);
        for (int k = 0; k < 4; k++)
            if (flat & (1 << k)) {
                fu[k] = (float)((double)pcx[k] * pby[k] - (double)pcy[k] * pbx[k]);
                fv[k] = (float)((double)pax[k] * pcy[k] - (double)pay[k] * pcx[k]);
                fw[k] = (float)((double)pbx[k] * pay[k] - (double)pby[k] * pax[k]);
            }
        U = v4_load(fu);
        V = v4_load(fv);
        W = v4_load(fw);
    }
    v4 neg = v4_or(v4_or(v4_lt(U, zero), v4_lt(V, zero)), v4_lt(W, zero));
    v4 pos = v4_or(v4_or(v4_gt(U, zero), v4_gt(V, zero)), v4_gt(W, zero));
    int mask = ~v4_bits(v4_and(neg, pos)) & 15;
    if (!mask)
        return 0;
    v4 det = v4_add(v4_add(U, V), W);
    v4 T = v4_add(v4_add(v4_mul(U, v4_mul(r->sz, az)), v4_mul(V, v4_mul(r->sz, bz))),
                  v4_mul(W, v4_mul(r->sz, cz)));
    v4 inv = v4_div(v4_set(1.0f), det);
    v4 tt = v4_mul(T, inv);
    mask &= v4_bits(v4_and(v4_neq(det, zero), v4_gt(tt, r->t_min)));
    if (mask) {
        v4_store(t, tt);
        v4_store(u, v4_mul(V, inv));
        v4_store(v, v4_mul(W, inv));
    }
    return mask;
}

/* How far beyond the best hit so far a box may begin and still be entered:
 * the box and triangle tests round differently, so a triangle touching its
 * box's boundary can report a t an ulp or so before the computed entry. */
static inline float cull_limit(float t)
{
    return t + fabsf(t) * (1.0f / 65536);
}

/* The lowest set bit of a 4-bit mask. */
static const signed char lowest_lane[16] = {-1, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};

/* Traversal of the 4-wide tree.  Nearest hit (any_hit 0): children entered
 * nearest first, and the best (t, index) with t in (t_min, t_max].  Shadow
 * query (any_hit 1): children in slot order, stopping at the first t in
 * (t_min, t_max).  The ray comes with its slab data (ray_setup_slabs). */
#if defined(__GNUC__)
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ALWAYS_INLINE inline
#endif

/* Inlined in each query, so each gets its own loop with any_hit constant. */
static ALWAYS_INLINE int traverse(const cg_bvh *bvh, bvh_ray *ray, float t_max, int any_hit,
                                  cg_bvh_hit *hit)
{
    float best_t = t_max, limit = cull_limit(best_t);
    {
        v4 o = v4_set3(ray->origin[0], ray->origin[1], ray->origin[2]);
        v4 i = v4_set3(ray->inverse[0], ray->inverse[1], ray->inverse[2]);
        float tn;
        if (!hit_box(ray, o, i, &bvh->bounds, limit, &tn))
            return 0;
    }
    ray_setup_shear(ray);
    ray4 r;
    ray4_setup(&r, ray);
    v4 limit4 = v4_set(limit);
    uint32_t best_id = UINT32_MAX;
    float best_u = 0, best_v = 0;
    int found = 0;
    uint32_t stack[STACK_SIZE];
    float stack_t[STACK_SIZE];
    int top = 0;
    uint32_t ref = bvh->root;
    for (;;) {
        if (!(ref & BVH_LEAF)) {
            const bvh4_node *node = &bvh->nodes[ref];
            float tn[4];
            int mask = hit_node4(ray, &r, node, limit4, limit, tn);
            if (mask) {
                int k = lowest_lane[mask];
                mask &= mask - 1;
                if (!mask) {
                    ref = node->child[k];
                    continue;
                }
                if (any_hit) {
                    /* A shadow ray's limit never shrinks, so what it
                     * pushes stays worth visiting: no order, no distance. */
                    do {
                        stack[top++] = node->child[lowest_lane[mask]];
                        mask &= mask - 1;
                    } while (mask);
                    ref = node->child[k];
                    continue;
                }
                /* Two to four children: sorted by entry distance (slot
                 * order on ties), the farthest pushed first. */
                uint32_t c[4];
                float d[4];
                int n = 1;
                c[0] = node->child[k];
                d[0] = tn[k];
                do {
                    int j = lowest_lane[mask];
                    mask &= mask - 1;
                    int i = n++;
                    while (i > 0 && d[i - 1] > tn[j]) {
                        c[i] = c[i - 1];
                        d[i] = d[i - 1];
                        i--;
                    }
                    c[i] = node->child[j];
                    d[i] = tn[j];
                } while (mask);
                for (int i = n - 1; i > 0; i--) {
                    stack[top] = c[i];
                    stack_t[top] = d[i];
                    top++;
                }
                ref = c[0];
                continue;
            }
        } else {
            const bvh_tri4 *b = bvh->blocks + ((ref & ~BVH_LEAF) >> 3);
            int count = (int)(ref & 7) + 1;
            for (int k = 0; k < count; k += 4, b++) {
                float t[4], u[4], v[4];
                int mask = hit_tri4(ray, &r, b, t, u, v);
                while (mask) {
                    int j = lowest_lane[mask];
                    mask &= mask - 1;
                    if (any_hit) {
                        if (t[j] < t_max)
                            return 1;
                    } else if (bvh_better(t[j], b->id[j], best_t, best_id)) {
                        best_t = t[j];
                        best_id = b->id[j];
                        best_u = u[j];
                        best_v = v[j];
                        found = 1;
                        limit = cull_limit(best_t);
                        limit4 = v4_set(limit);
                    }
                }
            }
        }
        /* Pop the next subtree that can still hold a nearer hit. */
        for (;;) {
            if (top == 0)
                goto done;
            top--;
            if (any_hit || stack_t[top] <= limit)
                break;
        }
        ref = stack[top];
    }
done:
    if (found && hit) {
        hit->triangle = best_id;
        hit->t = best_t;
        hit->u = best_u;
        hit->v = best_v;
    }
    return found;
}

int cg_bvh_intersect(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                     double t_max, cg_bvh_hit *hit)
{
    bvh_ray ray;
    if (!bvh || bvh->root == BVH_NONE || !ray_setup_slabs(&ray, origin, direction, t_min)
        || !(t_max > t_min))
        return 0;
    return traverse(bvh, &ray, bvh_clamp_far(t_max), 0, hit);
}

int cg_bvh_occluded(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                    double t_max)
{
    bvh_ray ray;
    if (!bvh || bvh->root == BVH_NONE || !ray_setup_slabs(&ray, origin, direction, t_min)
        || !(t_max > t_min))
        return 0;
    return traverse(bvh, &ray, bvh_clamp_far(t_max), 1, NULL);
}
