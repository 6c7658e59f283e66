/* Shadow maps for the directional lights (cg_render_options.shadows).
 * Before a frame, each directional light gets a square depth map seen
 * along its direction: an orthographic view whose square encloses the
 * model's world bounding box, every triangle of the mesh rasterized into
 * it keeping the nearest depth (distance along the light's direction) at
 * each texel centre.  While shading, a point is looked up in each light's
 * map with a slope-scaled bias, bias = texel (1.5 + 2 tan(theta)) with
 * theta the angle between the normal and the light (at most 8 texels), and
 * percentage-closer filtering: the fraction of the 3 x 3 texels around it
 * whose depth is not nearer than the point's less the bias.  That fraction
 * scales the light's diffuse and specular terms (render_shade). */
#include "pipeline.h"

#include <stdlib.h>
#include <string.h>

#define SHADOW_SIZE 2048

void render_shadows_free(cg_renderer *r)
{
    for (int i = 0; i < CG_RENDER_MAX_LIGHTS; i++) {
        free(r->shadow_maps[i].depth);
        r->shadow_maps[i].depth = NULL;
    }
}

static void normalize3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++)
        v[k] /= l;
}

/* The map's frame for travel direction d (unit): rows of m map a world
 * point to texel u, v and depth along d. */
static void light_frame(const double d[3], const cg_vec3 lo, const cg_vec3 hi, int size,
                        render_shadow_map *map)
{
    double up[3] = {0, 1, 0};
    if (fabs(d[1]) > 0.9) {
        up[0] = 1;
        up[1] = 0;
    }
    double right[3] = {d[1] * up[2] - d[2] * up[1], d[2] * up[0] - d[0] * up[2],
                       d[0] * up[1] - d[1] * up[0]};
    normalize3(right);
    double top[3] = {right[1] * d[2] - right[2] * d[1], right[2] * d[0] - right[0] * d[2],
                     right[0] * d[1] - right[1] * d[0]};
    const double *axes[3] = {right, top, d};
    double low[3] = {INFINITY, INFINITY, INFINITY}, high[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < 8; i++) {
        double p[3] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
        for (int a = 0; a < 3; a++) {
            double t = p[0] * axes[a][0] + p[1] * axes[a][1] + p[2] * axes[a][2];
            low[a] = fmin(low[a], t);
            high[a] = fmax(high[a], t);
        }
    }
    double extent = fmax(high[0] - low[0], high[1] - low[1]);
    extent = extent > 0 ? extent * 1.02 : 1;
    double scale = size / extent;
    double centre[2] = {0.5 * (low[0] + high[0]), 0.5 * (low[1] + high[1])};
    for (int a = 0; a < 2; a++) {
        for (int k = 0; k < 3; k++)
            map->m[a][k] = (float)(axes[a][k] * scale);
        map->m[a][3] = (float)(0.5 * size - centre[a] * scale);
    }
    for (int k = 0; k < 3; k++)
        map->m[2][k] = (float)d[k];
    map->m[2][3] = 0;
    map->texel = (float)(extent / size);
    map->size = size;
}

static void map_point(const render_shadow_map *map, const float p[3], float out[3])
{
    for (int a = 0; a < 3; a++)
        out[a] = map->m[a][0] * p[0] + map->m[a][1] * p[1] + map->m[a][2] * p[2] + map->m[a][3];
}

/* The nearest depth of triangle a, b, c (map coordinates) at the texel
 * centres it covers. */
static void draw_triangle(render_shadow_map *map, const float *a, const float *b, const float *c)
{
    double area = (double)(b[0] - a[0]) * (c[1] - a[1]) - (double)(b[1] - a[1]) * (c[0] - a[0]);
    if (!(fabs(area) > 0) || !isfinite(area) || !isfinite(a[2] + b[2] + c[2]))
        return;
    double x0 = fmin(a[0], fmin(b[0], c[0])), x1 = fmax(a[0], fmax(b[0], c[0]));
    double y0 = fmin(a[1], fmin(b[1], c[1])), y1 = fmax(a[1], fmax(b[1], c[1]));
    /* Clamped to the map before the conversions. */
    double last = map->size - 1;
    int ix0 = (int)fmin(fmax(0, ceil(x0 - 0.5)), last + 1);
    int ix1 = (int)fmax(fmin(last, floor(x1 - 0.5)), -1);
    int iy0 = (int)fmin(fmax(0, ceil(y0 - 0.5)), last + 1);
    int iy1 = (int)fmax(fmin(last, floor(y1 - 0.5)), -1);
    for (int y = iy0; y <= iy1; y++)
        for (int x = ix0; x <= ix1; x++) {
            double px = x + 0.5, py = y + 0.5;
            double w0 = ((double)(b[0] - px) * (c[1] - py) - (double)(b[1] - py) * (c[0] - px))
                        / area;
            double w1 = ((double)(c[0] - px) * (a[1] - py) - (double)(c[1] - py) * (a[0] - px))
                        / area;
            double w2 = 1 - w0 - w1;
            if (w0 < 0 || w1 < 0 || w2 < 0)
                continue;
            float z = (float)(w0 * a[2] + w1 * b[2] + w2 * c[2]);
            float *d = &map->depth[(size_t)y * map->size + x];
            if (z < *d)
                *d = z;
        }
}

cg_status render_shadows_build(render_frame *f)
{
    cg_renderer *r = f->r;
    render_lighting *l = &f->lighting;
    for (int i = 0; i < CG_RENDER_MAX_LIGHTS; i++)
        l->shadow[i] = NULL;
    if (!f->o->shadows || !r->has_bounds)
        return CG_OK;
    /* World bounds of the model box. */
    cg_vec3 lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < 8; i++) {
        cg_vec3 p = {(i & 1) ? r->hi.x : r->lo.x, (i & 2) ? r->hi.y : r->lo.y,
                     (i & 4) ? r->hi.z : r->lo.z};
        p = cg_mat4_transform_point(f->model, p);
        lo = cg_vec3_make(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
        hi = cg_vec3_make(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
    }
    size_t texels = (size_t)SHADOW_SIZE * SHADOW_SIZE;
    float *world = malloc((r->vertex_count ? r->vertex_count : 1) * 3 * sizeof *world);
    if (!world)
        return CG_ENOMEM;
    for (int k = 0; k < l->directional; k++) {
        render_shadow_map *map = &r->shadow_maps[k];
        if (!map->depth && !(map->depth = malloc(texels * sizeof *map->depth))) {
            free(world);
            return CG_ENOMEM;
        }
        double d[3] = {-l->to_light[k][0], -l->to_light[k][1], -l->to_light[k][2]};
        normalize3(d);
        light_frame(d, lo, hi, SHADOW_SIZE, map);
        for (size_t t = 0; t < texels; t++)
            map->depth[t] = INFINITY;
        for (size_t v = 0; v < r->vertex_count; v++) {
            float p[3];
            world_of(f, r->vertices[v].position, p);
            map_point(map, p, world + 3 * v);
        }
        for (size_t t = 0; t < r->triangle_count; t++) {
            const uint32_t *tri = r->triangles[t];
            draw_triangle(map, world + 3 * (size_t)tri[0], world + 3 * (size_t)tri[1],
                          world + 3 * (size_t)tri[2]);
        }
        l->shadow[k] = map;
    }
    free(world);
    return CG_OK;
}

float render_shadow_visibility(const render_shadow_map *map, const float position[3], float nl)
{
    float q[3];
    map_point(map, position, q);
    float tangent = nl > 0 ? sqrtf(fmaxf(0, 1 - nl * nl)) / nl : 4;
    float bias = map->texel * fminf(1.5f + 2 * tangent, 8);
    if (!(q[0] >= 0 && q[1] >= 0 && q[0] < (float)map->size && q[1] < (float)map->size))
        return 1; /* outside the map (or not finite): lit */
    int x = (int)q[0], y = (int)q[1];
    if (x >= map->size || y >= map->size)
        return 1;
    int lit = 0, count = 0;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= map->size || v >= map->size)
                continue;
            count++;
            lit += !(map->depth[(size_t)v * map->size + u] < q[2] - bias);
        }
    return count ? (float)lit / (float)count : 1;
}
