/* Colour models in double precision (chapter 7): HSV, HSL, CMY, CMYK, YIQ,
 * YCbCr, CIE XYZ and L*a*b*, conversion by model name, tints, shades, tones,
 * luminance and the CRT power law. */
#include "cg/color.h"
#include "internal.h"

#include <string.h>
#include <strings.h>

/* [0, 1]; NaN -> 0, +inf -> 1. */
double cg_intensity_clamp(double v)
{
    if (!(v > 0))
        return 0;
    return v < 1 ? v : 1;
}

static double unit(double v)
{
    return cg_intensity_clamp(v);
}

/* Finite or 0. */
static double finite_or_zero(double v)
{
    return isfinite(v) ? v : 0;
}

static cg_vec3 unit3(cg_vec3 c)
{
    return cg_vec3_make(unit(c.x), unit(c.y), unit(c.z));
}

/* Hue reduced to [0, 360); non-finite -> 0. */
static double hue_reduce(double h)
{
    if (!isfinite(h))
        return 0;
    if (h >= 0 && h < 360)
        return h;
    h = fmod(h, 360.0);
    if (h < 0)
        h += 360.0;
    return h >= 360.0 ? 0 : h;
}

/* Hue in degrees of an RGB colour with max and delta = max - min > 0. */
static double hue_of(double r, double g, double b, double max, double delta)
{
    double h;
    if (max == r)
        h = 60.0 * ((g - b) / delta);
    else if (max == g)
        h = 60.0 * ((b - r) / delta + 2.0);
    else
        h = 60.0 * ((r - g) / delta + 4.0);
    if (h < 0) {
        h += 360.0;
        if (h >= 360.0)
            h = 0;
    }
    return h;
}

cg_vec3 cg_rgb_to_hsv(cg_vec3 rgb)
{
    cg_vec3 c = unit3(rgb);
    double max = fmax(c.x, fmax(c.y, c.z)), min = fmin(c.x, fmin(c.y, c.z));
    double delta = max - min;
    if (delta <= 0)
        return cg_vec3_make(0, 0, max);
    return cg_vec3_make(hue_of(c.x, c.y, c.z, max, delta), delta / max, max);
}

cg_vec3 cg_hsv_to_rgb(cg_vec3 hsv)
{
    double h = hue_reduce(hsv.x), s = unit(hsv.y), v = unit(hsv.z);
    if (s == 0)
        return cg_vec3_make(v, v, v);
    double hh = h / 60.0;
    int sector = (int)hh;
    if (sector > 5)
        sector = 5;
    double f = hh - sector;
    double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    switch (sector) {
    case 0: return cg_vec3_make(v, t, p);
    case 1: return cg_vec3_make(q, v, p);
    case 2: return cg_vec3_make(p, v, t);
    case 3: return cg_vec3_make(p, q, v);
    case 4: return cg_vec3_make(t, p, v);
    default: return cg_vec3_make(v, p, q);
    }
}

cg_vec3 cg_rgb_to_hsl(cg_vec3 rgb)
{
    cg_vec3 c = unit3(rgb);
    double max = fmax(c.x, fmax(c.y, c.z)), min = fmin(c.x, fmin(c.y, c.z));
    double delta = max - min, sum = max + min, l = sum / 2;
    if (delta <= 0)
        return cg_vec3_make(0, 0, l);
    double s = l <= 0.5 ? delta / sum : delta / (2 - sum);
    return cg_vec3_make(hue_of(c.x, c.y, c.z, max, delta), s > 1 ? 1 : s, l);
}

/* The helper of 7.3.4: one channel from m1, m2 and a hue offset. */
static double hsl_value(double m1, double m2, double hue)
{
    if (hue < 0)
        hue += 360;
    else if (hue >= 360)
        hue -= 360;
    if (hue < 60)
        return m1 + (m2 - m1) * hue / 60;
    if (hue < 180)
        return m2;
    if (hue < 240)
        return m1 + (m2 - m1) * (240 - hue) / 60;
    return m1;
}

cg_vec3 cg_hsl_to_rgb(cg_vec3 hsl)
{
    double h = hue_reduce(hsl.x), s = unit(hsl.y), l = unit(hsl.z);
    if (s == 0)
        return cg_vec3_make(l, l, l);
    double m2 = l <= 0.5 ? l * (1 + s) : l + s - l * s;
    double m1 = 2 * l - m2;
    return unit3(
        cg_vec3_make(hsl_value(m1, m2, h + 120), hsl_value(m1, m2, h), hsl_value(m1, m2, h - 120)));
}

cg_vec3 cg_rgb_to_cmy(cg_vec3 rgb)
{
    cg_vec3 c = unit3(rgb);
    return cg_vec3_make(1 - c.x, 1 - c.y, 1 - c.z);
}

cg_vec3 cg_cmy_to_rgb(cg_vec3 cmy)
{
    cg_vec3 c = unit3(cmy);
    return cg_vec3_make(1 - c.x, 1 - c.y, 1 - c.z);
}

cg_vec4 cg_rgb_to_cmyk(cg_vec3 rgb)
{
    cg_vec3 c = unit3(rgb);
    double max = fmax(c.x, fmax(c.y, c.z));
    if (max <= 0)
        return cg_vec4_make(0, 0, 0, 1);
    /* (1 - R - K) / (1 - K) with 1 - K = max */
    return cg_vec4_make((max - c.x) / max, (max - c.y) / max, (max - c.z) / max, 1 - max);
}

cg_vec3 cg_cmyk_to_rgb(cg_vec4 cmyk)
{
    double k = 1 - unit(cmyk.w);
    return cg_vec3_make((1 - unit(cmyk.x)) * k, (1 - unit(cmyk.y)) * k, (1 - unit(cmyk.z)) * k);
}

static cg_vec3 mul3(const double m[3][3], cg_vec3 v)
{
    return cg_vec3_make(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                        m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                        m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
}

static const double yiq_from_rgb[3][3] = {
    {0.299, 0.587, 0.114}, {0.596, -0.275, -0.321}, {0.212, -0.523, 0.311}};
/* The exact inverse (computed in rational arithmetic, rounded to double). */
static const double rgb_from_yiq[3][3] = {{1, 0.95568806036115672, 0.61985809445637075},
                                          {1, -0.2715817969440586, -0.64687381613840134},
                                          {1, -1.108177326682662, 1.7050645599191818}};

cg_vec3 cg_rgb_to_yiq(cg_vec3 rgb)
{
    return mul3(yiq_from_rgb, unit3(rgb));
}

cg_vec3 cg_yiq_to_rgb(cg_vec3 yiq)
{
    cg_vec3 v = cg_vec3_make(finite_or_zero(yiq.x), finite_or_zero(yiq.y), finite_or_zero(yiq.z));
    return unit3(mul3(rgb_from_yiq, v));
}

static void ycbcr_weights(cg_ycbcr_standard standard, double *kr, double *kb)
{
    if (standard == CG_YCBCR_BT709) {
        *kr = 0.2126;
        *kb = 0.0722;
    } else {
        *kr = 0.299;
        *kb = 0.114;
    }
}

cg_vec3 cg_rgb_to_ycbcr(cg_vec3 rgb, cg_ycbcr_standard standard)
{
    double kr, kb;
    ycbcr_weights(standard, &kr, &kb);
    cg_vec3 c = unit3(rgb);
    double y = kr * c.x + (1 - kr - kb) * c.y + kb * c.z;
    return cg_vec3_make(y, (c.z - y) / (2 * (1 - kb)), (c.x - y) / (2 * (1 - kr)));
}

static double clamp_range(double v, double lo, double hi)
{
    if (!(v > lo))
        return lo;
    return v < hi ? v : hi;
}

cg_vec3 cg_ycbcr_to_rgb(cg_vec3 ycbcr, cg_ycbcr_standard standard)
{
    double kr, kb;
    ycbcr_weights(standard, &kr, &kb);
    double y = unit(ycbcr.x), cb = clamp_range(ycbcr.y, -0.5, 0.5),
           cr = clamp_range(ycbcr.z, -0.5, 0.5);
    double r = y + 2 * (1 - kr) * cr, b = y + 2 * (1 - kb) * cb;
    double g = (y - kr * r - kb * b) / (1 - kr - kb);
    return unit3(cg_vec3_make(r, g, b));
}

static const double xyz_from_linear[3][3] = {
    {0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
static const double linear_from_xyz[3][3] = {
    {3.2406254773200533, -1.5372079722103187, -0.49862859869824788},
    {-0.96893071472931935, 1.875756060885241, 0.041517523842953943},
    {0.055710120445510609, -0.20402105059848669, 1.0569959422543882}};

cg_vec3 cg_d65_white(void)
{
    return cg_vec3_make(CG_COLOR_WHITE_X, 1.0, CG_COLOR_WHITE_Z);
}

cg_vec3 cg_linear_to_xyz(cg_vec3 linear_rgb)
{
    return mul3(xyz_from_linear, unit3(linear_rgb));
}

cg_vec3 cg_xyz_to_linear(cg_vec3 xyz)
{
    cg_vec3 v = cg_vec3_make(finite_or_zero(xyz.x), finite_or_zero(xyz.y), finite_or_zero(xyz.z));
    return unit3(mul3(linear_from_xyz, v));
}

/* The CIE function f(t) and its inverse; delta = 6/29. */
static double lab_f(double t)
{
    const double d = 6.0 / 29.0;
    return t > d * d * d ? cbrt(t) : t / (3 * d * d) + 4.0 / 29.0;
}

static double lab_f_inverse(double t)
{
    const double d = 6.0 / 29.0;
    return t > d ? t * t * t : 3 * d * d * (t - 4.0 / 29.0);
}

cg_vec3 cg_xyz_to_lab(cg_vec3 xyz)
{
    double fx = lab_f(finite_or_zero(xyz.x) / CG_COLOR_WHITE_X);
    double fy = lab_f(finite_or_zero(xyz.y));
    double fz = lab_f(finite_or_zero(xyz.z) / CG_COLOR_WHITE_Z);
    return cg_vec3_make(116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz));
}

cg_vec3 cg_lab_to_xyz(cg_vec3 lab)
{
    double fy = (finite_or_zero(lab.x) + 16) / 116;
    double fx = fy + finite_or_zero(lab.y) / 500;
    double fz = fy - finite_or_zero(lab.z) / 200;
    return cg_vec3_make(CG_COLOR_WHITE_X * lab_f_inverse(fx), lab_f_inverse(fy),
                        CG_COLOR_WHITE_Z * lab_f_inverse(fz));
}

static cg_vec3 srgb_decode3(cg_vec3 c)
{
    return cg_vec3_make(cg_srgb_to_linear(c.x), cg_srgb_to_linear(c.y), cg_srgb_to_linear(c.z));
}

static cg_vec3 srgb_encode3(cg_vec3 c)
{
    return cg_vec3_make(cg_linear_to_srgb(c.x), cg_linear_to_srgb(c.y), cg_linear_to_srgb(c.z));
}

cg_vec3 cg_rgb_to_lab(cg_vec3 rgb)
{
    return cg_xyz_to_lab(cg_linear_to_xyz(srgb_decode3(rgb)));
}

cg_vec3 cg_lab_to_rgb(cg_vec3 lab)
{
    return srgb_encode3(cg_xyz_to_linear(cg_lab_to_xyz(lab)));
}

/* ---- by name ------------------------------------------------------------- */

static const char *const model_names[CG_MODEL_COUNT] = {
    "rgb", "linear", "hsv", "hsl", "cmy", "cmyk", "yiq", "ycbcr601", "ycbcr709", "xyz", "lab"};

cg_status cg_color_model_parse(const char *name, size_t n, cg_color_model *out, cg_error *err)
{
    if (!name || !out)
        return cg_error_set(err, CG_EINVAL, "colour model: none given");
    if (n == 4 && strncasecmp(name, "srgb", 4) == 0) {
        *out = CG_MODEL_RGB;
        return CG_OK;
    }
    for (int i = 0; i < CG_MODEL_COUNT; i++)
        if (strlen(model_names[i]) == n && strncasecmp(name, model_names[i], n) == 0) {
            *out = (cg_color_model)i;
            return CG_OK;
        }
    return cg_error_set(err, CG_EFORMAT,
                        "unknown colour model '%.*s': expected rgb, srgb, linear, hsv, hsl, cmy, "
                        "cmyk, yiq, ycbcr601, ycbcr709, xyz or lab",
                        (int)(n > 64 ? 64 : n), name);
}

const char *cg_color_model_name(cg_color_model model)
{
    if ((int)model < 0 || model >= CG_MODEL_COUNT)
        return "unknown";
    return model_names[model];
}

int cg_color_model_components(cg_color_model model)
{
    return model == CG_MODEL_CMYK ? 4 : 3;
}

static int valid_model(cg_color_model m)
{
    return (int)m >= 0 && m < CG_MODEL_COUNT;
}

static int is_linear_family(cg_color_model m)
{
    return m == CG_MODEL_LINEAR || m == CG_MODEL_XYZ || m == CG_MODEL_LAB;
}

static cg_vec3 to_xyz(cg_color_model from, cg_vec3 v)
{
    if (from == CG_MODEL_LAB)
        return cg_lab_to_xyz(v);
    if (from == CG_MODEL_LINEAR)
        return cg_linear_to_xyz(v);
    return cg_vec3_make(finite_or_zero(v.x), finite_or_zero(v.y), finite_or_zero(v.z));
}

static cg_vec3 from_xyz(cg_color_model to, cg_vec3 xyz)
{
    if (to == CG_MODEL_LAB)
        return cg_xyz_to_lab(xyz);
    if (to == CG_MODEL_LINEAR)
        return cg_xyz_to_linear(xyz);
    return xyz;
}

static cg_vec3 to_rgb(cg_color_model from, const double *in)
{
    cg_vec3 v = cg_vec3_make(in[0], in[1], in[2]);
    switch (from) {
    case CG_MODEL_RGB: return unit3(v);
    case CG_MODEL_LINEAR: return srgb_encode3(v);
    case CG_MODEL_HSV: return cg_hsv_to_rgb(v);
    case CG_MODEL_HSL: return cg_hsl_to_rgb(v);
    case CG_MODEL_CMY: return cg_cmy_to_rgb(v);
    case CG_MODEL_CMYK: return cg_cmyk_to_rgb(cg_vec4_make(in[0], in[1], in[2], in[3]));
    case CG_MODEL_YIQ: return cg_yiq_to_rgb(v);
    case CG_MODEL_YCBCR601: return cg_ycbcr_to_rgb(v, CG_YCBCR_BT601);
    case CG_MODEL_YCBCR709: return cg_ycbcr_to_rgb(v, CG_YCBCR_BT709);
    case CG_MODEL_XYZ: return srgb_encode3(cg_xyz_to_linear(v));
    default: return cg_lab_to_rgb(v);
    }
}

static void put3(double *out, cg_vec3 v)
{
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

static void from_rgb(cg_color_model to, cg_vec3 rgb, double *out)
{
    switch (to) {
    case CG_MODEL_RGB: put3(out, rgb); break;
    case CG_MODEL_LINEAR: put3(out, srgb_decode3(rgb)); break;
    case CG_MODEL_HSV: put3(out, cg_rgb_to_hsv(rgb)); break;
    case CG_MODEL_HSL: put3(out, cg_rgb_to_hsl(rgb)); break;
    case CG_MODEL_CMY: put3(out, cg_rgb_to_cmy(rgb)); break;
    case CG_MODEL_CMYK: {
        cg_vec4 k = cg_rgb_to_cmyk(rgb);
        out[0] = k.x;
        out[1] = k.y;
        out[2] = k.z;
        out[3] = k.w;
        break;
    }
    case CG_MODEL_YIQ: put3(out, cg_rgb_to_yiq(rgb)); break;
    case CG_MODEL_YCBCR601: put3(out, cg_rgb_to_ycbcr(rgb, CG_YCBCR_BT601)); break;
    case CG_MODEL_YCBCR709: put3(out, cg_rgb_to_ycbcr(rgb, CG_YCBCR_BT709)); break;
    case CG_MODEL_XYZ: put3(out, cg_linear_to_xyz(srgb_decode3(rgb))); break;
    default: put3(out, cg_rgb_to_lab(rgb)); break;
    }
}

cg_status cg_color_convert(cg_color_model from, cg_color_model to, const double *in, double *out)
{
    if (!valid_model(from) || !valid_model(to) || !in || !out)
        return CG_EINVAL;
    if (is_linear_family(from) && is_linear_family(to)) {
        cg_vec3 v = cg_vec3_make(in[0], in[1], in[2]);
        if (from == to && from != CG_MODEL_LINEAR) {
            put3(out, cg_vec3_make(finite_or_zero(v.x), finite_or_zero(v.y), finite_or_zero(v.z)));
            return CG_OK;
        }
        put3(out, from_xyz(to, to_xyz(from, v)));
        return CG_OK;
    }
    from_rgb(to, to_rgb(from, in), out);
    return CG_OK;
}

/* ---- tints, shades, tones, luminance, gamma ------------------------------- */

static cg_vec3 mix(cg_vec3 base, cg_vec3 target, double amount)
{
    double t = unit(amount);
    return cg_vec3_add(base, cg_vec3_scale(cg_vec3_sub(target, base), t));
}

cg_vec3 cg_color_tint(cg_vec3 base, double amount)
{
    return mix(base, cg_vec3_make(1, 1, 1), amount);
}

cg_vec3 cg_color_shade(cg_vec3 base, double amount)
{
    return mix(base, cg_vec3_make(0, 0, 0), amount);
}

cg_vec3 cg_color_tone(cg_vec3 base, double amount, double grey)
{
    double g = unit(grey);
    return mix(base, cg_vec3_make(g, g, g), amount);
}

double cg_luminance(cg_vec3 c)
{
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

double cg_luma(cg_vec3 c)
{
    return 0.299 * c.x + 0.587 * c.y + 0.114 * c.z;
}

double cg_gamma_decode(double voltage, double gamma)
{
    if (!(gamma > 0) || !isfinite(gamma))
        return 0;
    return pow(unit(voltage), gamma);
}

double cg_gamma_encode(double intensity, double gamma)
{
    if (!(gamma > 0) || !isfinite(gamma))
        return 0;
    return pow(unit(intensity), 1.0 / gamma);
}
