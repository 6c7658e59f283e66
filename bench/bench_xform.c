/* Transforming 10 million points with a composed 4x4 matrix: cg's batch
 * transform against the same computation written naively in plain C (a loop
 * calling a matrix-vector product per point).  The harness's smoke test. */
#include "bench.h"
#include "cg.h"

#define COUNT 10000000

typedef struct job {
    cg_mat4 m;
    cg_vec3 *in, *out;
} job;

static void run_cg(void *context)
{
    job *j = context;
    cg_mat4_transform_points(j->m, j->in, j->out, COUNT);
    bench_sink = j->out[COUNT / 2].x;
}

/* What a user would write without cg: homogeneous product, then divide. */
static void run_naive(void *context)
{
    job *j = context;
    for (size_t i = 0; i < COUNT; i++) {
        double p[4] = {j->in[i].x, j->in[i].y, j->in[i].z, 1}, r[4];
        for (int row = 0; row < 4; row++) {
            r[row] = 0;
            for (int k = 0; k < 4; k++)
                r[row] += j->m.m[row][k] * p[k];
        }
        j->out[i].x = r[0] / r[3];
        j->out[i].y = r[1] / r[3];
        j->out[i].z = r[2] / r[3];
    }
    bench_sink = j->out[COUNT / 2].x;
}

int main(void)
{
    job j;
    j.in = malloc(sizeof(cg_vec3) * COUNT);
    j.out = malloc(sizeof(cg_vec3) * COUNT);
    if (!j.in || !j.out)
        return 1;
    for (size_t i = 0; i < COUNT; i++)
        j.in[i] = cg_vec3_make((double)(i % 1000), (double)(i % 777), (double)(i % 555));
    cg_mat4 rotate;
    cg_xform3_rotate_axis(cg_vec3_make(1, 2, 3), 0.7, cg_vec3_make(1, 1, 1), &rotate);
    cg_mat4 steps[3] = {cg_xform3_scale(2, 3, 4, cg_vec3_make(0, 0, 0)), rotate,
                        cg_xform3_translate(5, -2, 1)};
    j.m = cg_mat4_compose(steps, 3);
    bench_row("transform 10M points, affine 4x4", bench_median(run_cg, &j, 7), "naive C",
              bench_median(run_naive, &j, 7), NULL);
    cg_mat4 projection;
    cg_proj_perspective(1.0, 1.5, 0.1, 100, &projection);
    j.m = cg_mat4_mul(projection, j.m);
    bench_row("transform 10M points, projective 4x4", bench_median(run_cg, &j, 7), "naive C",
              bench_median(run_naive, &j, 7), NULL);
    free(j.in);
    free(j.out);
    return 0;
}
