/* Reflection, refraction by Snell's law, and Schlick's Fresnel approximation. */
#include "cg/trace.h"

cg_vec3 cg_reflect(cg_vec3 incident, cg_vec3 n)
{
    return cg_vec3_sub(incident, cg_vec3_scale(n, 2 * cg_vec3_dot(incident, n)));
}

static int valid_index(double n)
{
    return isfinite(n) && n > 0;
}

int cg_refract(cg_vec3 incident, cg_vec3 n, double n1, double n2, cg_vec3 *out)
{
    if (!valid_index(n1) || !valid_index(n2))
        return 0;
    double eta = n1 / n2;
    double cos_i = -cg_vec3_dot(incident, n);
    if (cos_i > 1)
        cos_i = 1;
    double k = 1 - eta * eta * (1 - cos_i * cos_i);
    if (!(k >= 0))
        return 0; /* total internal reflection */
    cg_vec3 t = cg_vec3_add(cg_vec3_scale(incident, eta), cg_vec3_scale(n, eta * cos_i - sqrt(k)));
    if (out)
        *out = cg_vec3_normalize(t);
    return 1;
}

double cg_fresnel_schlick(double cos_incident, double n1, double n2)
{
    if (!valid_index(n1) || !valid_index(n2))
        return 1;
    if (n1 == n2)
        return 0; /* no interface: nothing is reflected */
    double c = fabs(cos_incident);
    if (c > 1)
        c = 1;
    double r0 = (n1 - n2) / (n1 + n2);
    r0 *= r0;
    if (n1 > n2) {
        /* Leaving the denser medium: Schlick's formula takes the angle on the
         * less dense side, which is the transmitted one. */
        double eta = n1 / n2;
        double sin2 = eta * eta * (1 - c * c);
        if (sin2 >= 1)
            return 1;
        c = sqrt(1 - sin2);
    }
    double m = 1 - c;
    return r0 + (1 - r0) * m * m * m * m * m;
}
