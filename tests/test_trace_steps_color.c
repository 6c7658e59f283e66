/* The intensity-to-pixel and gamma traces of cg/trace_steps.h against the
 * library and the definitions: every pixel reported once in the method's
 * order, its output the one cg_dither_plane gives (bit for bit), and each
 * step's values what the method's formula makes of the ones before them. */
#include "check.h"
#include "cg/color.h"
#include "cg/image.h"
#include "cg/trace_steps.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { SIDE = 24 };

typedef struct seen {
    float out[SIDE * SIDE];
    int count[SIDE * SIDE];
    int width, levels, n, next, order_wrong, formula_wrong;
    const float *in;
    double pushed_to_next; /* Floyd-Steinberg: the error the right neighbour gets */
} seen;

static double real_of(const cg_step *s, const char *name)
{
    const cg_step_field *f = cg_step_find(s, name);
    return f && f->kind == CG_STEP_REAL ? f->real : NAN;
}

static double clamp01(double v)
{
    return v > 0 ? (v < 1 ? v : 1) : 0;
}

/* The Bayer matrix by its definition: B(2n) = [4B, 4B+2; 4B+3, 4B+1]. */
static int bayer(int n, int x, int y)
{
    if (n == 1)
        return 0;
    int half = n / 2, b = 4 * bayer(half, x % half, y % half);
    static const int add[2][2] = {{0, 2}, {3, 1}};
    return b + add[y / half][x / half];
}

static int record(void *user, const cg_step *s)
{
    seen *m = user;
    const cg_step_field *pixel = cg_step_find(s, "pixel");
    int i = pixel->pixel_y * m->width + pixel->pixel_x;
    m->order_wrong += i != m->next++;
    m->count[i]++;
    double out = real_of(s, "out"), in = clamp01(m->in[i]), top = m->levels - 1;
    m->out[i] = (float)out;
    m->formula_wrong += s->pixel_count != 1 || s->intensity[0] != out;
    if (m->n > 0) { /* ordered: up a level when frac(s) > (b + 1/2) / n^2 */
        double scaled = real_of(s, "s"), frac = real_of(s, "frac");
        int b = (int)cg_step_find(s, "b")->integer;
        m->formula_wrong += b != bayer(m->n, pixel->pixel_x % m->n, pixel->pixel_y % m->n);
        m->formula_wrong += fabs(scaled - (float)in * top) > 1e-6;
        double k = floor(scaled) + (frac > (b + 0.5) / (m->n * m->n));
        m->formula_wrong += fabs(out - fmin(k, top) / top) > 1e-6;
    } else if (m->n < 0) { /* Floyd-Steinberg: out nearest v, the error pushed on */
        double v = real_of(s, "v"), e = real_of(s, "error");
        m->formula_wrong += fabs(v - out - e) > 1e-6 || fabs(clamp01(v) - out) > 0.5 / top + 1e-6;
        if (pixel->pixel_x > 0 && pixel->pixel_x < m->width && pixel->pixel_y == 0)
            m->formula_wrong += fabs(v - in - m->pushed_to_next) > 1e-6; /* first row */
        m->pushed_to_next = real_of(s, "right");
        double parts = real_of(s, "right") + real_of(s, "below_left") + real_of(s, "below")
                       + real_of(s, "below_right");
        const char *w = cg_step_find(s, "weights")->text;
        m->formula_wrong += strncmp(w, "none", 4) != 0 && fabs(parts - e) > 1e-9;
    } else { /* the nearest level */
        m->formula_wrong += fabs(out - floor(in * top + 0.5) / top) > 1e-6;
    }
    return 0;
}

static void dither_agrees(void)
{
    check_rng rng = {0xd17e4};
    static const cg_dither methods[5] = {CG_DITHER_NONE, CG_DITHER_BAYER2, CG_DITHER_BAYER4,
                                         CG_DITHER_BAYER8, CG_DITHER_FLOYD_STEINBERG};
    static const int sides[5] = {0, 2, 4, 8, -1};
    long planes = 0, pixels = 0;
    for (int trial = 0; trial < 1000; trial++) {
        int w = (int)check_rng_int(&rng, 1, SIDE), h = (int)check_rng_int(&rng, 1, SIDE);
        int levels = trial % 7 == 0 ? 256 : (int)check_rng_int(&rng, 2, 9), m = trial % 5;
        float in[SIDE * SIDE], out[SIDE * SIDE];
        for (int i = 0; i < w * h; i++)
            in[i] = trial % 11 == 0 && i % 9 == 0 ? (i % 2 ? NAN : 1.5f)
                                                  : (float)check_rng_range(&rng, -0.1, 1.1);
        seen *s = calloc(1, sizeof *s);
        s->width = w;
        s->levels = levels;
        s->n = sides[m];
        s->in = in;
        CHECK(cg_dither_plane_steps(in, w, h, levels, methods[m], record, s) == CG_OK);
        CHECK(cg_dither_plane(in, out, w, h, (size_t)w, levels, methods[m]) == CG_OK);
        int same = 1;
        for (int i = 0; i < w * h; i++)
            same &= s->count[i] == 1 && memcmp(&s->out[i], &out[i], sizeof(float)) == 0;
        CHECK_MSG(same,
                  "trial %d (method %d, %dx%d, %d levels): the trace's levels are not "
                  "cg_dither_plane's",
                  trial, m, w, h, levels);
        CHECK_MSG(s->order_wrong == 0, "trial %d: pixels out of row order", trial);
        CHECK_MSG(s->formula_wrong == 0, "trial %d (method %d): %d steps break the formula", trial,
                  m, s->formula_wrong);
        planes++;
        pixels += w * h;
        free(s);
    }
    CHECK(planes == 1000 && pixels > 100000);
    float one = 0.5f;
    CHECK(cg_dither_plane_steps(&one, 1, 1, 1, CG_DITHER_NONE, record, NULL) == CG_EINVAL);
    CHECK(cg_dither_plane_steps(&one, 0, 1, 2, CG_DITHER_NONE, record, NULL) == CG_EINVAL);
    CHECK(cg_dither_plane_steps(NULL, 1, 1, 2, CG_DITHER_NONE, record, NULL) == CG_EINVAL);
}

typedef struct gamma_seen {
    const double *in;
    double gamma;
    int wrong;
    size_t count;
} gamma_seen;

static int gamma_record(void *user, const cg_step *s)
{
    gamma_seen *g = user;
    double i = clamp01(g->in[g->count++]), v = real_of(s, "V");
    g->wrong += v != cg_gamma_encode(i, g->gamma) || fabs(v - pow(i, 1 / g->gamma)) > 1e-12;
    g->wrong += fabs(real_of(s, "shown") - i) > 1e-12;
    g->wrong += cg_step_find(s, "code")->integer != lround(255 * v);
    g->wrong += real_of(s, "sRGB") != cg_linear_to_srgb(i);
    return 0;
}

static void gamma_agrees(void)
{
    check_rng rng = {0x6a33a};
    for (int trial = 0; trial < 300; trial++) {
        double in[16], gamma = check_rng_range(&rng, 0.3, 3.5);
        for (int i = 0; i < 16; i++)
            in[i] = check_rng_range(&rng, -0.2, 1.2);
        gamma_seen g = {in, gamma, 0, 0};
        CHECK(cg_gamma_steps(in, 16, gamma, gamma_record, &g) == CG_OK);
        CHECK(g.count == 16 && g.wrong == 0);
    }
    double v = 0.5;
    CHECK(cg_gamma_steps(&v, 1, 0, gamma_record, NULL) == CG_EINVAL);
    CHECK(cg_gamma_steps(&v, 1, INFINITY, gamma_record, NULL) == CG_EINVAL);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(dither_agrees);
    CHECK_GROUP(gamma_agrees);
    return check_finish();
}
