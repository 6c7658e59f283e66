/* The path tracer's deterministic sample numbers. */
#include "path_internal.h"

#include <math.h>

static uint64_t mix(uint64_t z)
{
    z ^= z >> 30;
    z *= 0xbf58476d1ce4e5b9ULL;
    z ^= z >> 27;
    z *= 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return z;
}

static double hash_unit(uint64_t a, uint64_t b, uint64_t c, uint64_t d)
{
    uint64_t z = mix(a + 0x9e3779b97f4a7c15ULL);
    z = mix(z ^ (b + 0x632be59bd9b4e019ULL));
    z = mix(z ^ (c + 0xd6e8feb86659fd7dULL));
    z = mix(z ^ (d + 0x94d049bb133111ebULL));
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

void path_pixel_offset(const path_sampler *s, double *dx, double *dy)
{
    /* R2: the plastic number's reciprocals (Roberts 2018). */
    const double a1 = 0.7548776662466927, a2 = 0.5698402909980532;
    double shift_x = hash_unit(s->seed, s->pixel, UINT64_MAX, 0);
    double shift_y = hash_unit(s->seed, s->pixel, UINT64_MAX, 1);
    double k = (double)s->sample;
    double x = shift_x + fmod(a1 * k, 1.0), y = shift_y + fmod(a2 * k, 1.0);
    *dx = x - floor(x);
    *dy = y - floor(y);
}

double path_next(path_sampler *s)
{
    return hash_unit(s->seed, s->pixel, s->sample, s->dimension++);
}
