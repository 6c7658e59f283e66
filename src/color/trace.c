/* RGB to HSV and HSL per 7.3 of the notes, step by step
 * (cg/trace_steps.h), with the same arithmetic as models.c so that the last
 * step is cg_rgb_to_hsv's or cg_rgb_to_hsl's result exactly. */
#include "cg/color.h"
#include "../core/steps.h"

#include <math.h>

static int emit(const char *quantity, const char *formula, double value, cg_step_fn fn, void *user)
{
    core_step s;
    core_step_begin(&s, "formulas");
    core_step_text(&s, "quantity", quantity);
    core_step_text(&s, "formula", formula);
    core_step_real(&s, "value", value);
    return core_step_emit(&s, fn, user);
}

static double clamp_unit(double v)
{
    return cg_intensity_clamp(v);
}

/* The hue of 7.3.2: by which channel is largest. */
static int emit_hue(double r, double g, double b, double max, double delta, cg_step_fn fn,
                    void *user, double *hue)
{
    double h;
    const char *formula;
    if (max == r) {
        h = 60.0 * ((g - b) / delta);
        formula = "max is R: H = 60 (G - B) / delta";
    } else if (max == g) {
        h = 60.0 * ((b - r) / delta + 2.0);
        formula = "max is G: H = 60 ((B - R) / delta + 2)";
    } else {
        h = 60.0 * ((r - g) / delta + 4.0);
        formula = "max is B: H = 60 ((R - G) / delta + 4)";
    }
    if (emit("H", formula, h, fn, user))
        return 1;
    if (h < 0) {
        h += 360.0;
        if (h >= 360.0)
            h = 0;
        if (emit("H", "H < 0: H += 360", h, fn, user))
            return 1;
    }
    *hue = h;
    return 0;
}

cg_status cg_rgb_to_hsv_steps(cg_vec3 rgb, int lightness, cg_step_fn step, void *user)
{
    if (!step)
        return CG_EINVAL;
    double r = clamp_unit(rgb.x), g = clamp_unit(rgb.y), b = clamp_unit(rgb.z);
    if (emit("R", "the input clamped to [0, 1]", r, step, user)
        || emit("G", "the input clamped to [0, 1]", g, step, user)
        || emit("B", "the input clamped to [0, 1]", b, step, user))
        return CG_OK;
    double max = fmax(r, fmax(g, b)), min = fmin(r, fmin(g, b)), delta = max - min;
    if (emit("max", "max(R, G, B)", max, step, user) || emit("min", "min(R, G, B)", min, step, user)
        || emit("delta", "max - min", delta, step, user))
        return CG_OK;
    double first = lightness ? (max + min) / 2 : max;
    if (emit(lightness ? "L" : "V", lightness ? "(max + min) / 2" : "max", first, step, user))
        return CG_OK;
    double saturation = 0, hue = 0;
    if (delta <= 0) {
        if (emit("S", "delta = 0: a grey, S = 0 (and H = 0 by convention)", 0, step, user))
            return CG_OK;
    } else {
        if (!lightness) {
            saturation = delta / max;
            if (emit("S", "delta / max", saturation, step, user))
                return CG_OK;
        } else {
            double sum = max + min;
            saturation = first <= 0.5 ? delta / sum : delta / (2 - sum);
            if (saturation > 1)
                saturation = 1;
            if (emit("S",
                     first <= 0.5 ? "L <= 1/2: delta / (max + min)"
                                  : "L > 1/2: delta / (2 - max - min)",
                     saturation, step, user))
                return CG_OK;
        }
        if (emit_hue(r, g, b, max, delta, step, user, &hue))
            return CG_OK;
    }
    core_step s;
    double result[3] = {hue, saturation, first};
    core_step_begin(&s, "result");
    core_step_text(&s, "model", lightness ? "HSL" : "HSV");
    core_step_reals(&s, "value", result, 3);
    core_step_emit(&s, step, user);
    return CG_OK;
}
