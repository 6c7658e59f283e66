/* Intensity to pixel (6.1.5) and gamma correction (7.2.1) step by step
 * (cg/trace_steps.h).  The dithering steps come from intensity.c's own
 * loops (color_dither_plane), so the levels a trace ends with are
 * cg_dither_plane's:
 *
 *   quantize:         s = I (N - 1), k = floor(s + 1/2), out = k / (N - 1)
 *   ordered (Bayer):  k = floor(s) + (frac(s) > (b + 1/2) / n^2)
 *   Floyd-Steinberg:  v = I + the errors pushed to the pixel, out = the
 *                     level nearest v, e = v - out pushed on as
 *                     7/16 right, 3/16 below left, 5/16 below, 1/16 below
 *                     right (border weights renormalized) */
#include "cg/color.h"
#include "internal.h"
#include "../core/steps.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static float unit(float v)
{
    return v > 0 ? (v < 1 ? v : 1) : 0;
}

static void finish(color_dither_report *r, core_step *s, int x, int y, float out, int *xy,
                   double *intensity)
{
    core_step_real(s, "out", out);
    xy[0] = x;
    xy[1] = y;
    *intensity = out;
    s->step.pixels = xy;
    s->step.intensity = intensity;
    s->step.pixel_count = 1;
    if (core_step_emit(s, r->fn, r->user))
        r->stopped = 1;
}

void color_report_quantize(color_dither_report *r, int x, int y, float input, double top, float out)
{
    if (r->stopped)
        return;
    int xy[2];
    double intensity;
    double scaled = unit(input) * top;
    core_step s;
    core_step_begin(&s, "pixels");
    core_step_pixel(&s, "pixel", x, y);
    core_step_real(&s, "I", unit(input));
    core_step_real(&s, "s", scaled);
    core_step_integer(&s, "k", (long long)lround(out * top));
    core_step_real(&s, "error", unit(input) - out);
    finish(r, &s, x, y, out, xy, &intensity);
}

void color_report_ordered(color_dither_report *r, int x, int y, float input, double scaled, int b,
                          int n, float out)
{
    if (r->stopped)
        return;
    int xy[2];
    double intensity, base = floor(scaled), threshold = (b + 0.5) / (n * n);
    core_step s;
    core_step_begin(&s, "pixels");
    core_step_pixel(&s, "pixel", x, y);
    core_step_real(&s, "I", unit(input));
    core_step_real(&s, "s", scaled);
    core_step_integer(&s, "floor_s", (long long)base);
    core_step_real(&s, "frac", scaled - base);
    core_step_integer(&s, "b", b);
    core_step_real(&s, "threshold", threshold);
    core_step_text(&s, "decision", scaled - base > threshold ? "frac > threshold: up" : "keep");
    finish(r, &s, x, y, out, xy, &intensity);
}

void color_report_diffusion(color_dither_report *r, int x, int y, float input, double v, float out,
                            double error, const double weights[4])
{
    if (r->stopped)
        return;
    static const char *const names[4] = {"right", "below_left", "below", "below_right"};
    int xy[2];
    double intensity, total = weights[0] + weights[1] + weights[2] + weights[3];
    char text[32];
    snprintf(text, sizeof text, total > 0 ? "%g/%g %g/%g %g/%g %g/%g" : "none: the last pixel",
             weights[0], total, weights[1], total, weights[2], total, weights[3], total);
    core_step s;
    core_step_begin(&s, "pixels");
    core_step_pixel(&s, "pixel", x, y);
    core_step_real(&s, "I", unit(input));
    core_step_real(&s, "v", v);
    core_step_real(&s, "error", error);
    core_step_text(&s, "weights", text);
    for (int k = 0; k < 4; k++)
        core_step_real(&s, names[k], total > 0 ? error * weights[k] / total : 0);
    finish(r, &s, x, y, out, xy, &intensity);
}

cg_status cg_dither_plane_steps(const float *in, int width, int height, int levels,
                                cg_dither method, cg_step_fn step, void *user)
{
    if (!in || !step || width <= 0 || height <= 0 || (size_t)width * (size_t)height > 1u << 20)
        return CG_EINVAL;
    float *out = malloc((size_t)width * (size_t)height * sizeof *out);
    if (!out)
        return CG_ENOMEM;
    color_dither_report report = {step, user, 0};
    cg_status status = color_dither_plane(in, out, width, height, (size_t)width, levels, method,
                                          &report);
    free(out);
    return status;
}

cg_status cg_gamma_steps(const double *intensities, size_t count, double gamma, cg_step_fn step,
                         void *user)
{
    if ((!intensities && count > 0) || !step || !(gamma > 0) || !isfinite(gamma))
        return CG_EINVAL;
    for (size_t i = 0; i < count; i++) {
        double in = intensities[i], v = cg_gamma_encode(in, gamma);
        core_step s;
        core_step_begin(&s, "values");
        core_step_integer(&s, "k", (long long)i);
        core_step_real(&s, "I", cg_intensity_clamp(in));
        core_step_real(&s, "V", v);
        core_step_integer(&s, "code", lround(255 * v));
        core_step_real(&s, "shown", cg_gamma_decode(v, gamma));
        core_step_real(&s, "uncorrected", cg_gamma_decode(cg_intensity_clamp(in), gamma));
        core_step_real(&s, "sRGB", cg_linear_to_srgb(in));
        if (core_step_emit(&s, step, user))
            break;
    }
    return CG_OK;
}
