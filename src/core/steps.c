/* Building steps for the traces, and the step log that copies them. */
#include "steps.h"

#include "array.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void core_step_begin(core_step *s, const char *phase)
{
    memset(&s->step, 0, sizeof s->step);
    s->step.phase = phase;
}

static cg_step_field *next_field(core_step *s, const char *name, cg_step_kind kind)
{
    if (s->step.field_count >= CORE_STEP_MAX_FIELDS)
        return NULL;
    cg_step_field *f = &s->fields[s->step.field_count++];
    memset(f, 0, sizeof *f);
    f->name = name;
    f->kind = kind;
    return f;
}

void core_step_none(core_step *s, const char *name)
{
    next_field(s, name, CG_STEP_NONE);
}

void core_step_integer(core_step *s, const char *name, long long value)
{
    cg_step_field *f = next_field(s, name, CG_STEP_INTEGER);
    if (f)
        f->integer = value;
}

void core_step_real(core_step *s, const char *name, double value)
{
    cg_step_field *f = next_field(s, name, CG_STEP_REAL);
    if (f)
        f->real = value;
}

void core_step_text(core_step *s, const char *name, const char *value)
{
    cg_step_field *f = next_field(s, name, CG_STEP_TEXT);
    if (f)
        f->text = value;
}

void core_step_pixel(core_step *s, const char *name, long long x, long long y)
{
    cg_step_field *f = next_field(s, name, CG_STEP_PIXEL);
    if (f) {
        f->pixel_x = (int)x;
        f->pixel_y = (int)y;
    }
}

void core_step_point(core_step *s, const char *name, cg_vec2 value)
{
    cg_step_field *f = next_field(s, name, CG_STEP_POINT);
    if (f)
        f->point = value;
}

void core_step_points(core_step *s, const char *name, const cg_vec2 *points, size_t count)
{
    cg_step_field *f = next_field(s, name, CG_STEP_POINTS);
    if (f) {
        f->points = points;
        f->point_count = count;
    }
}

void core_step_reals(core_step *s, const char *name, const double *reals, size_t count)
{
    cg_step_field *f = next_field(s, name, CG_STEP_REALS);
    if (f) {
        f->reals = reals;
        f->real_count = count;
    }
}

int core_step_emit(core_step *s, cg_step_fn fn, void *user)
{
    s->step.fields = s->fields;
    return fn(user, &s->step);
}

const cg_step_field *cg_step_find(const cg_step *step, const char *name)
{
    if (!step || !name)
        return NULL;
    for (int i = 0; i < step->field_count; i++)
        if (strcmp(step->fields[i].name, name) == 0)
            return &step->fields[i];
    return NULL;
}

/* ---- the log ------------------------------------------------------------ */

/* A logged step owns one block holding its fields, names, texts, points and
 * pixels; the cg_step inside points into it. */
typedef struct logged_step {
    cg_step step;
    void *block;
} logged_step;

struct cg_step_log {
    CORE_ARRAY(logged_step) steps;
    cg_status status;
};

cg_status cg_step_log_create(cg_step_log **out)
{
    if (!out)
        return CG_EINVAL;
    *out = calloc(1, sizeof **out);
    return *out ? CG_OK : CG_ENOMEM;
}

void cg_step_log_free(cg_step_log *log)
{
    if (!log)
        return;
    for (size_t i = 0; i < log->steps.count; i++)
        free(log->steps.data[i].block);
    free(log->steps.data);
    free(log);
}

/* Bytes a copy of the text needs (0 for NULL). */
static size_t text_size(const char *text)
{
    return text ? strlen(text) + 1 : 0;
}

static size_t step_size(const cg_step *s)
{
    size_t size = (size_t)s->field_count * sizeof(cg_step_field);
    size += (size_t)(s->geometry_count + s->kept_count) * sizeof(cg_vec2);
    size += (size_t)s->pixel_count * (2 * sizeof(int) + (s->intensity ? sizeof(double) : 0));
    for (int i = 0; i < s->field_count; i++)
        size += s->fields[i].point_count * sizeof(cg_vec2)
                + s->fields[i].real_count * sizeof(double);
    size += text_size(s->phase);
    for (int i = 0; i < s->field_count; i++)
        size += text_size(s->fields[i].name) + text_size(s->fields[i].text);
    return size;
}

typedef struct copier {
    char *at;
} copier;

/* Copies n bytes to the copier's next place (doubles and pointers first, so
 * every piece stays aligned; texts last). */
static void *copy_bytes(copier *c, const void *from, size_t n)
{
    if (!from || !n)
        return NULL;
    void *to = c->at;
    memcpy(to, from, n);
    c->at += n;
    return to;
}

int cg_step_log_record(void *user, const cg_step *s)
{
    cg_step_log *log = user;
    if (!log || !s || log->status != CG_OK)
        return 1;
    if (core_array_reserve_for(&log->steps, log->steps.count + 1) != CG_OK) {
        log->status = CG_ENOMEM;
        return 1;
    }
    void *block = malloc(step_size(s) + 1);
    if (!block) {
        log->status = CG_ENOMEM;
        return 1;
    }
    copier c = {block};
    logged_step *l = &log->steps.data[log->steps.count++];
    l->block = block;
    l->step = *s;
    cg_step_field *fields = copy_bytes(&c, s->fields, (size_t)s->field_count * sizeof *fields);
    l->step.fields = fields;
    l->step.geometry = copy_bytes(&c, s->geometry, (size_t)s->geometry_count * sizeof(cg_vec2));
    l->step.kept = copy_bytes(&c, s->kept, (size_t)s->kept_count * sizeof(cg_vec2));
    l->step.intensity = copy_bytes(&c, s->intensity,
                                   s->intensity ? (size_t)s->pixel_count * sizeof(double) : 0);
    for (int i = 0; i < s->field_count; i++) {
        fields[i].points = copy_bytes(&c, s->fields[i].points,
                                      s->fields[i].point_count * sizeof(cg_vec2));
        fields[i].reals = copy_bytes(&c, s->fields[i].reals,
                                     s->fields[i].real_count * sizeof(double));
    }
    l->step.pixels = copy_bytes(&c, s->pixels, (size_t)s->pixel_count * 2 * sizeof(int));
    l->step.phase = copy_bytes(&c, s->phase, text_size(s->phase));
    for (int i = 0; i < s->field_count; i++) {
        fields[i].name = copy_bytes(&c, s->fields[i].name, text_size(s->fields[i].name));
        fields[i].text = copy_bytes(&c, s->fields[i].text, text_size(s->fields[i].text));
    }
    return 0;
}

cg_status cg_step_log_status(const cg_step_log *log)
{
    return log ? log->status : CG_EINVAL;
}

size_t cg_step_log_count(const cg_step_log *log)
{
    return log ? log->steps.count : 0;
}

const cg_step *cg_step_log_get(const cg_step_log *log, size_t i)
{
    return log && i < log->steps.count ? &log->steps.data[i].step : NULL;
}

void core_text_append(char *text, size_t size, const char *format, ...)
{
    size_t used = strlen(text);
    if (used + 4 >= size)
        return;
    va_list args;
    va_start(args, format);
    int n = vsnprintf(text + used, size - used, format, args);
    va_end(args);
    if (n < 0 || used + (size_t)n >= size)
        strcpy(text + size - 4, "...");
}
