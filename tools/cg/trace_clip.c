/* `cg trace` for chapter 11: Liang-Barsky and Sutherland-Hodgman. */
#include "trace_algorithms.h"

const trace_algorithm trace_clip_algorithms[] = {
    {NULL, NULL, NULL},
};
