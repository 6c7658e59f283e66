/* Bounding volume hierarchy over triangles: binned SAH build, 32-byte nodes,
 * ordered traversal, and the watertight ray-triangle test of Woop, Benthin and
 * Wald (JCGT 2013). */
#include "internal.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

enum {
    BINS = 32,        /* bins per axis for the SAH sweep */
    MAX_LEAF = 8,     /* a node with more triangles is always split */
    SAH_DEPTH = 48,   /* deeper than this, split at the object median */
    STACK_SIZE = 128  /* > SAH_DEPTH + 32: the deepest possible tree */
};

/* ---- building ------------------------------------------------------------ */

/* A triangle's bounds and index while building. */
typedef struct prim_ref {
    float lo[3];
    uint32_t id;
    float hi[3];
    uint32_t pad;
} prim_ref;

typedef struct box {
    float lo[3], hi[3];
} box;

static void box_empty(box *b)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = FLT_MAX;
        b->hi[a] = -FLT_MAX;
    }
}

static void box_grow(box *b, const float *lo, const float *hi)
{
    for (int a = 0; a < 3; a++) {
        if (lo[a] < b->lo[a])
            b->lo[a] = lo[a];
        if (hi[a] > b->hi[a])
            b->hi[a] = hi[a];
    }
}

/* Half the surface area (the factor cancels in the SAH). */
static float box_area(const box *b)
{
    float dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1], dz = b->hi[2] - b->lo[2];
    if (dx < 0 || dy < 0 || dz < 0)
        return 0;
    return dx * dy + dy * dz + dz * dx;
}

typedef struct builder {
    prim_ref *refs;
    bvh_node *nodes;
    size_t node_count;
    int depth;
} builder;

static uint32_t make_node(builder *b, const box *bounds)
{
    uint32_t index = (uint32_t)b->node_count++;
    bvh_node *node = &b->nodes[index];
    memcpy(node->lo, bounds->lo, sizeof node->lo);
    memcpy(node->hi, bounds->hi, sizeof node->hi);
    node->offset = 0;
    node->count = 0;
    return index;
}

static void build_node(builder *b, uint32_t index, size_t begin, size_t end, int depth)
{
    for (;;) {
        size_t count = end - begin;
        prim_ref *refs = b->refs;
        if (depth > b->depth)
            b->depth = depth;
        box centroids;
        box_empty(&centroids);
        for (size_t i = begin; i < end; i++) {
            float c[3];
            for (int a = 0; a < 3; a++)
                c[a] = refs[i].lo[a] + refs[i].hi[a];
            box_grow(&centroids, c, c);
        }
        bvh_node *node = &b->nodes[index];
        box parent;
        memcpy(parent.lo, node->lo, sizeof parent.lo);
        memcpy(parent.hi, node->hi, sizeof parent.hi);
        float parent_area = box_area(&parent);

        int best_axis = -1, best_bin = 0;
        float best_cost = FLT_MAX;
        float scale[3];
        if (count > 2 && depth < SAH_DEPTH) {
            box bins[3][BINS];
            uint32_t counts[3][BINS];
            for (int a = 0; a < 3; a++) {
                float extent = centroids.hi[a] - centroids.lo[a];
                scale[a] = extent > 0 ? (float)BINS * (1 - 1e-6f) / extent : 0;
                for (int k = 0; k < BINS; k++) {
                    box_empty(&bins[a][k]);
                    counts[a][k] = 0;
                }
            }
            for (size_t i = begin; i < end; i++) {
                for (int a = 0; a < 3; a++) {
                    float c = refs[i].lo[a] + refs[i].hi[a];
                    int k = (int)((c - centroids.lo[a]) * scale[a]);
                    k = k < 0 ? 0 : k >= BINS ? BINS - 1 : k;
                    box_grow(&bins[a][k], refs[i].lo, refs[i].hi);
                    counts[a][k]++;
                }
            }
            for (int a = 0; a < 3; a++) {
                if (scale[a] == 0)
                    continue;
                float right_area[BINS];
                uint32_t right_count[BINS];
                box acc;
                box_empty(&acc);
                uint32_t n = 0;
                for (int k = BINS - 1; k > 0; k--) {
                    box_grow(&acc, bins[a][k].lo, bins[a][k].hi);
                    n += counts[a][k];
                    right_area[k] = box_area(&acc);
                    right_count[k] = n;
                }
                box_empty(&acc);
                n = 0;
                for (int k = 0; k < BINS - 1; k++) {
                    box_grow(&acc, bins[a][k].lo, bins[a][k].hi);
                    n += counts[a][k];
                    if (n == 0 || right_count[k + 1] == 0)
                        continue;
                    float cost = box_area(&acc) * (float)n + right_area[k + 1] * (float)right_count[k + 1];
                    if (cost < best_cost) {
                        best_cost = cost;
                        best_axis = a;
                        best_bin = k;
                    }
                }
            }
        }

        size_t mid;
        if (best_axis >= 0) {
            /* Cost of splitting relative to intersecting everything here
             * (traversal cost 1, triangle cost 1). */
            float split_cost = parent_area > 0 ? 1 + best_cost / parent_area : FLT_MAX;
            if (count <= MAX_LEAF && split_cost >= (float)count)
                best_axis = -1;
        }
        if (best_axis >= 0) {
            size_t i = begin, j = end;
            int a = best_axis;
            while (i < j) {
                float c = refs[i].lo[a] + refs[i].hi[a];
                int k = (int)((c - centroids.lo[a]) * scale[a]);
                k = k < 0 ? 0 : k >= BINS ? BINS - 1 : k;
                if (k <= best_bin) {
                    i++;
                } else {
                    j--;
                    prim_ref t = refs[i];
                    refs[i] = refs[j];
                    refs[j] = t;
                }
            }
            mid = i;
        } else if (count <= MAX_LEAF) {
            node->offset = (uint32_t)begin;
            node->count = (uint32_t)count;
            return;
        } else {
            /* Many triangles with one centroid, or a tree deeper than
             * SAH_DEPTH (only for pathological inputs): split the range in
             * two halves, which bounds the depth by log2 of the count. */
            mid = begin + count / 2;
        }

        box left, right;
        box_empty(&left);
        box_empty(&right);
        for (size_t i = begin; i < mid; i++)
            box_grow(&left, refs[i].lo, refs[i].hi);
        for (size_t i = mid; i < end; i++)
            box_grow(&right, refs[i].lo, refs[i].hi);
        uint32_t left_index = make_node(b, &left);
        /* Recurse into the left child (it must directly follow this node),
         * loop on the right one; the recursion depth is the tree depth,
         * at most SAH_DEPTH + 32. */
        build_node(b, left_index, begin, mid, depth + 1);
        uint32_t right_index = make_node(b, &right);
        b->nodes[index].offset = right_index;
        index = right_index;
        begin = mid;
        depth++;
    }
}

static void sah_of(const cg_bvh *bvh, uint32_t index, double *cost)
{
    const bvh_node *n = &bvh->nodes[index];
    box b;
    memcpy(b.lo, n->lo, sizeof b.lo);
    memcpy(b.hi, n->hi, sizeof b.hi);
    double area = box_area(&b);
    if (n->count) {
        *cost += area * n->count;
        return;
    }
    *cost += area;
    sah_of(bvh, index + 1, cost);
    sah_of(bvh, n->offset, cost);
}

cg_status cg_bvh_build(const cg_vec3 *positions, size_t vertex_count, const uint32_t *indices,
                       size_t triangle_count, cg_bvh **out)
{
    if (!out)
        return CG_EINVAL;
    *out = NULL;
    if ((!positions && vertex_count) || (triangle_count && !positions))
        return CG_EINVAL;
    if (triangle_count > 0x7fffffffu)
        return CG_ERANGE;
    if (!indices && triangle_count > vertex_count / 3)
        return CG_EINVAL;
    if (indices)
        for (size_t i = 0; i < 3 * triangle_count; i++)
            if (indices[i] >= vertex_count)
                return CG_EINVAL;
    cg_bvh *bvh = calloc(1, sizeof *bvh);
    prim_ref *refs = malloc((triangle_count ? triangle_count : 1) * sizeof *refs);
    if (!bvh || !refs) {
        free(bvh);
        free(refs);
        return CG_ENOMEM;
    }
    /* Finite triangles only; coordinates rounded to float once, here. */
    size_t n = 0;
    box root;
    box_empty(&root);
    for (size_t i = 0; i < triangle_count; i++) {
        prim_ref r;
        int finite = 1;
        for (int a = 0; a < 3; a++) {
            r.lo[a] = FLT_MAX;
            r.hi[a] = -FLT_MAX;
        }
        for (int k = 0; k < 3 && finite; k++) {
            cg_vec3 p = positions[indices ? indices[3 * i + k] : 3 * i + k];
            float f[3] = {(float)p.x, (float)p.y, (float)p.z};
            for (int a = 0; a < 3; a++) {
                if (!isfinite(f[a])) {
                    finite = 0;
                    break;
                }
                if (f[a] < r.lo[a])
                    r.lo[a] = f[a];
                if (f[a] > r.hi[a])
                    r.hi[a] = f[a];
            }
        }
        if (!finite)
            continue;
        r.id = (uint32_t)i;
        r.pad = 0;
        box_grow(&root, r.lo, r.hi);
        refs[n++] = r;
    }
    bvh->triangle_count = n;
    bvh->nodes = malloc((2 * n + 1) * sizeof *bvh->nodes);
    bvh->triangles = malloc((n ? n : 1) * sizeof *bvh->triangles);
    if (!bvh->nodes || !bvh->triangles) {
        free(refs);
        cg_bvh_free(bvh);
        return CG_ENOMEM;
    }
    if (n) {
        builder b = {refs, bvh->nodes, 0, 0};
        uint32_t root_index = make_node(&b, &root);
        build_node(&b, root_index, 0, n, 1);
        bvh->node_count = b.node_count;
        bvh->depth = b.depth;
    }
    for (size_t i = 0; i < n; i++) {
        bvh_triangle *t = &bvh->triangles[i];
        uint32_t id = refs[i].id;
        float *corner[3] = {t->v0, t->v1, t->v2};
        for (int k = 0; k < 3; k++) {
            cg_vec3 p = positions[indices ? indices[3 * (size_t)id + k] : 3 * (size_t)id + k];
            corner[k][0] = (float)p.x;
            corner[k][1] = (float)p.y;
            corner[k][2] = (float)p.z;
        }
        t->id = id;
    }
    free(refs);
    *out = bvh;
    return CG_OK;
}

void cg_bvh_free(cg_bvh *bvh)
{
    if (!bvh)
        return;
    free(bvh->nodes);
    free(bvh->triangles);
    free(bvh);
}

void cg_bvh_get_stats(const cg_bvh *bvh, cg_bvh_stats *out)
{
    memset(out, 0, sizeof *out);
    if (!bvh)
        return;
    out->triangles = bvh->triangle_count;
    out->nodes = bvh->node_count;
    out->depth = bvh->depth;
    for (size_t i = 0; i < bvh->node_count; i++)
        out->leaves += bvh->nodes[i].count != 0;
    if (bvh->node_count) {
        double cost = 0;
        sah_of(bvh, 0, &cost);
        box b;
        memcpy(b.lo, bvh->nodes[0].lo, sizeof b.lo);
        memcpy(b.hi, bvh->nodes[0].hi, sizeof b.hi);
        double area = box_area(&b);
        out->sah_cost = area > 0 ? cost / area : 0;
    }
}

/* ---- rays and the triangle test ---------------------------------------- */

int bvh_ray_setup(bvh_ray *ray, cg_vec3 origin, cg_vec3 direction, double t_min)
{
    double o[3] = {origin.x, origin.y, origin.z}, d[3] = {direction.x, direction.y, direction.z};
    int kz = 0;
    for (int a = 0; a < 3; a++) {
        if (!isfinite(o[a]) || !isfinite(d[a]) || !isfinite((float)o[a]))
            return 0;
        if (fabs(d[a]) > fabs(d[kz]))
            kz = a;
    }
    if (d[kz] == 0 || !isfinite(t_min))
        return 0;
    ray->flat_axes = 0;
    for (int a = 0; a < 3; a++) {
        ray->dorigin[a] = o[a];
        ray->ddirection[a] = d[a];
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
    int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0) {
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    ray->kx = kx;
    ray->ky = ky;
    ray->kz = kz;
    ray->shear_x = (float)(d[kx] / d[kz]);
    ray->shear_y = (float)(d[ky] / d[kz]);
    ray->shear_z = (float)(1.0 / d[kz]);
    ray->t_min = (float)t_min;
    return 1;
}

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

/* Slab test; far distances grown by 1 + 2 gamma(3) (Ize 2013) so rounding
 * never rejects a box that the exact ray touches. */
static inline int hit_box(const bvh_ray *ray, const bvh_node *node, float t_far_limit,
                          float *t_near)
{
    float tn = ray->t_min, tf = FLT_MAX;
    for (int a = 0; a < 3; a++) {
        float t0 = (node->lo[a] - ray->origin[a]) * ray->inverse[a];
        float t1 = (node->hi[a] - ray->origin[a]) * ray->inverse[a];
        float n = t0 < t1 ? t0 : t1, f = t0 < t1 ? t1 : t0;
        tn = n > tn ? n : tn;
        tf = f < tf ? f : tf;
    }
    if (ray->flat_axes) {
        /* A direction component of zero: the slab holds the whole ray or
         * none of it, boundaries included (the axis's t values were made
         * harmless by a huge inverse and are overridden here). */
        for (int a = 0; a < 3; a++)
            if (ray->flat_axes & (1 << a)) {
                if (ray->origin[a] < node->lo[a] || ray->origin[a] > node->hi[a]) {
                    *t_near = FLT_MAX;
                    return 0;
                }
            }
        tn = ray->t_min;
        tf = FLT_MAX;
        for (int a = 0; a < 3; a++) {
            if (ray->flat_axes & (1 << a))
                continue;
            float t0 = (node->lo[a] - ray->origin[a]) * ray->inverse[a];
            float t1 = (node->hi[a] - ray->origin[a]) * ray->inverse[a];
            float n = t0 < t1 ? t0 : t1, f = t0 < t1 ? t1 : t0;
            tn = n > tn ? n : tn;
            tf = f < tf ? f : tf;
        }
    }
    tf *= 1.0000003576f;
    tf = tf < t_far_limit ? tf : t_far_limit;
    *t_near = tn;
    return tn <= tf;
}

/* How far beyond the best hit so far a box may begin and still be entered:
 * the box and triangle tests round differently, so a triangle touching its
 * box's boundary can report a t an ulp or so before the computed entry. */
static inline float cull_limit(float t)
{
    return t + fabsf(t) * (1.0f / 65536);
}

/* Is the candidate (t, id) better than the best so far? */
static inline int better(float t, uint32_t id, float best_t, uint32_t best_id)
{
    return t < best_t || (t == best_t && id < best_id);
}

static float clamp_far(double t_max)
{
    if (!(t_max < (double)FLT_MAX))
        return FLT_MAX;
    return (float)t_max;
}

int cg_bvh_intersect(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                     double t_max, cg_bvh_hit *hit)
{
    bvh_ray ray;
    if (!bvh || !bvh->node_count || !bvh_ray_setup(&ray, origin, direction, t_min)
        || !(t_max > t_min))
        return 0;
    float best_t = clamp_far(t_max), limit = cull_limit(best_t);
    uint32_t best_id = UINT32_MAX;
    float best_u = 0, best_v = 0;
    int found = 0;
    uint32_t stack[STACK_SIZE];
    float stack_t[STACK_SIZE];
    int top = 0;
    float tn;
    if (!hit_box(&ray, &bvh->nodes[0], limit, &tn))
        return 0;
    uint32_t index = 0;
    for (;;) {
        const bvh_node *node = &bvh->nodes[index];
        if (node->count) {
            const bvh_triangle *tri = bvh->triangles + node->offset;
            for (uint32_t k = 0; k < node->count; k++) {
                float t, u, v;
                if (hit_triangle(&ray, &tri[k], &t, &u, &v) && better(t, tri[k].id, best_t, best_id)) {
                    best_t = t;
                    best_id = tri[k].id;
                    best_u = u;
                    best_v = v;
                    found = 1;
                    limit = cull_limit(t);
                }
            }
        } else {
            uint32_t left = index + 1, right = node->offset;
            float tl, tr;
            int hl = hit_box(&ray, &bvh->nodes[left], limit, &tl);
            int hr = hit_box(&ray, &bvh->nodes[right], limit, &tr);
            if (hl && hr) {
                if (tr < tl) {
                    uint32_t s = left;
                    left = right;
                    right = s;
                    float st = tl;
                    tl = tr;
                    tr = st;
                }
                stack[top] = right;
                stack_t[top] = tr;
                top++;
                index = left;
                continue;
            }
            if (hl) {
                index = left;
                continue;
            }
            if (hr) {
                index = right;
                continue;
            }
        }
        /* Pop the next subtree that can still hold a nearer hit. */
        for (;;) {
            if (top == 0)
                goto done;
            top--;
            if (stack_t[top] <= limit)
                break;
        }
        index = stack[top];
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

int cg_bvh_occluded(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                    double t_max)
{
    bvh_ray ray;
    if (!bvh || !bvh->node_count || !bvh_ray_setup(&ray, origin, direction, t_min)
        || !(t_max > t_min))
        return 0;
    float far = clamp_far(t_max), limit = cull_limit(far);
    uint32_t stack[STACK_SIZE];
    int top = 0;
    float tn;
    if (!hit_box(&ray, &bvh->nodes[0], limit, &tn))
        return 0;
    uint32_t index = 0;
    for (;;) {
        const bvh_node *node = &bvh->nodes[index];
        if (node->count) {
            const bvh_triangle *tri = bvh->triangles + node->offset;
            for (uint32_t k = 0; k < node->count; k++) {
                float t, u, v;
                if (hit_triangle(&ray, &tri[k], &t, &u, &v) && t < far)
                    return 1;
            }
        } else {
            uint32_t left = index + 1, right = node->offset;
            float tl, tr;
            int hl = hit_box(&ray, &bvh->nodes[left], limit, &tl);
            int hr = hit_box(&ray, &bvh->nodes[right], limit, &tr);
            if (hl && hr) {
                if (tr < tl) {
                    uint32_t s = left;
                    left = right;
                    right = s;
                }
                stack[top++] = right;
                index = left;
                continue;
            }
            if (hl || hr) {
                index = hl ? left : right;
                continue;
            }
        }
        if (top == 0)
            return 0;
        index = stack[--top];
    }
}

int cg_bvh_intersect_brute(const cg_bvh *bvh, cg_vec3 origin, cg_vec3 direction, double t_min,
                           double t_max, cg_bvh_hit *hit)
{
    bvh_ray ray;
    if (!bvh || !bvh_ray_setup(&ray, origin, direction, t_min) || !(t_max > t_min))
        return 0;
    float best_t = clamp_far(t_max);
    uint32_t best_id = UINT32_MAX;
    int found = 0;
    for (size_t i = 0; i < bvh->triangle_count; i++) {
        float t, u, v;
        const bvh_triangle *tri = &bvh->triangles[i];
        if (hit_triangle(&ray, tri, &t, &u, &v) && better(t, tri->id, best_t, best_id)) {
            best_t = t;
            best_id = tri->id;
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
