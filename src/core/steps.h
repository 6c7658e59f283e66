/* Private to libcg: building a cg_step field by field (cg/trace_steps.h). */
#ifndef CG_CORE_STEPS_H
#define CG_CORE_STEPS_H

#include "cg/trace_steps.h"

enum { CORE_STEP_MAX_FIELDS = 24 };

typedef struct core_step {
    cg_step step;
    cg_step_field fields[CORE_STEP_MAX_FIELDS];
} core_step;

/* Clears s and names its phase (NULL for none). */
void core_step_begin(core_step *s, const char *phase);
/* Append one field each (beyond CORE_STEP_MAX_FIELDS fields are dropped,
 * which a trace never needs). */
void core_step_none(core_step *s, const char *name);
void core_step_integer(core_step *s, const char *name, long long value);
void core_step_real(core_step *s, const char *name, double value);
void core_step_text(core_step *s, const char *name, const char *value);
void core_step_pixel(core_step *s, const char *name, long long x, long long y);
void core_step_point(core_step *s, const char *name, cg_vec2 value);
void core_step_points(core_step *s, const char *name, const cg_vec2 *points, size_t count);
void core_step_reals(core_step *s, const char *name, const double *reals, size_t count);
/* Appends printf text to the string in text[0..size), cut with "..." when
 * it does not fit (a step's label lists, bounded). */
void core_text_append(char *text, size_t size, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* Calls fn with the step built (fields set); its result. */
int core_step_emit(core_step *s, cg_step_fn fn, void *user);

#endif
