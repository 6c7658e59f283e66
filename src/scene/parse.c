/* Reading scene files: JSON (parsed by cJSON) checked key by key, with
 * errors that name the JSON path and what was expected. */
#include "internal.h"
#include "cg/color.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Everything a parsing function needs to report an error. */
typedef struct parser {
    const char *name;     /* file name for messages */
    cg_error *err;
    const char *base_dir; /* mesh paths are relative to it (NULL: current folder) */
    int load_meshes;      /* 0: check mesh entries but read no files */
} parser;

#define PATH_SIZE 256

static cg_status fail(const parser *p, const char *path, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static cg_status fail(const parser *p, const char *path, const char *format, ...)
{
    char message[400];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    return cg_error_set(p->err, CG_EFORMAT, "%s: %s: %s", p->name, path, message);
}

/* A short description of a JSON value for "got ..." in messages. */
static void describe(const cJSON *v, char *out, size_t size)
{
    if (!v)
        snprintf(out, size, "nothing");
    else if (cJSON_IsString(v))
        snprintf(out, size, "\"%.40s%s\"", v->valuestring, strlen(v->valuestring) > 40 ? "..." : "");
    else if (cJSON_IsNumber(v))
        snprintf(out, size, "%.17g", v->valuedouble);
    else if (cJSON_IsBool(v))
        snprintf(out, size, "%s", cJSON_IsTrue(v) ? "true" : "false");
    else if (cJSON_IsNull(v))
        snprintf(out, size, "null");
    else if (cJSON_IsArray(v))
        snprintf(out, size, "an array of %d", cJSON_GetArraySize(v));
    else
        snprintf(out, size, "an object");
}

static cg_status expected(const parser *p, const char *path, const char *what, const cJSON *v)
{
    char got[64];
    describe(v, got, sizeof got);
    return fail(p, path, "expected %s, got %s", what, got);
}

/* Writes a JSON path into out (PATH_SIZE bytes), cut short if too long. */
static void path_format(char *out, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void path_format(char *out, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(out, PATH_SIZE, format, args);
    va_end(args);
}

/* path.key, or key at the top level. */
static void join(char *out, const char *path, const char *key)
{
    path_format(out, "%s%s%s", path, path[0] ? "." : "", key);
}

/* obj[key], or NULL when absent; key_path receives path.key. */
static const cJSON *member(const cJSON *obj, const char *path, const char *key, char *key_path)
{
    join(key_path, path, key);
    return cJSON_GetObjectItemCaseSensitive(obj, key);
}

/* Every key of obj must be one of allowed (NULL-terminated). */
static cg_status check_keys(const parser *p, const char *path, const cJSON *obj,
                            const char *const *allowed)
{
    for (const cJSON *item = obj->child; item; item = item->next) {
        int known = 0;
        for (const char *const *a = allowed; *a; a++)
            if (strcmp(item->string, *a) == 0)
                known = 1;
        if (!known) {
            char list[200] = "", key_path[PATH_SIZE];
            for (const char *const *a = allowed; *a; a++) {
                size_t used = strlen(list);
                snprintf(list + used, sizeof list - used, "%s%s", used ? ", " : "", *a);
            }
            join(key_path, path, item->string);
            return fail(p, key_path, "unknown key (expected one of: %s)", list);
        }
    }
    return CG_OK;
}

static cg_status need_object(const parser *p, const char *path, const cJSON *v)
{
    return cJSON_IsObject(v) ? CG_OK : expected(p, path, "an object", v);
}

/* Optional number in [min, max]: *out untouched when absent. */
static cg_status get_number(const parser *p, const char *path, const cJSON *obj, const char *key,
                            double min, double max, double *out)
{
    char key_path[PATH_SIZE], what[96];
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    if (!cJSON_IsNumber(v) || !(v->valuedouble >= min) || !(v->valuedouble <= max)) {
        snprintf(what, sizeof what, "a number between %g and %g", min, max);
        return expected(p, key_path, what, v);
    }
    *out = v->valuedouble;
    return CG_OK;
}

static cg_status get_int(const parser *p, const char *path, const cJSON *obj, const char *key,
                         int min, int max, int *out)
{
    char key_path[PATH_SIZE], what[96];
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    if (!cJSON_IsNumber(v) || !(v->valuedouble >= min) || !(v->valuedouble <= max)
        || v->valuedouble != (double)(int)v->valuedouble) {
        snprintf(what, sizeof what, "a whole number between %d and %d", min, max);
        return expected(p, key_path, what, v);
    }
    *out = (int)v->valuedouble;
    return CG_OK;
}

static cg_status get_bool(const parser *p, const char *path, const cJSON *obj, const char *key,
                          int *out)
{
    char key_path[PATH_SIZE];
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    if (!cJSON_IsBool(v))
        return expected(p, key_path, "true or false", v);
    *out = cJSON_IsTrue(v);
    return CG_OK;
}

/* An array of n finite numbers at v. */
static cg_status read_numbers(const parser *p, const char *path, const cJSON *v, int n,
                              double *out)
{
    char what[64];
    snprintf(what, sizeof what, "an array of %d numbers", n);
    if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != n)
        return expected(p, path, what, v);
    int i = 0;
    for (const cJSON *item = v->child; item; item = item->next, i++) {
        if (!cJSON_IsNumber(item) || !isfinite(item->valuedouble)) {
            char item_path[PATH_SIZE];
            path_format(item_path, "%s[%d]", path, i);
            return expected(p, item_path, "a finite number", item);
        }
        out[i] = item->valuedouble;
    }
    return CG_OK;
}

static cg_status get_vec3(const parser *p, const char *path, const cJSON *obj, const char *key,
                          cg_vec3 *out)
{
    char key_path[PATH_SIZE];
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    double xyz[3];
    cg_status s = read_numbers(p, key_path, v, 3, xyz);
    if (s == CG_OK)
        *out = cg_vec3_make(xyz[0], xyz[1], xyz[2]);
    return s;
}

/* A colour: "#rrggbb" or a name (sRGB, decoded to linear light), or an
 * array [r, g, b] of linear values >= 0. */
static cg_status get_color(const parser *p, const char *path, const cJSON *obj, const char *key,
                           cg_vec3 *out)
{
    char key_path[PATH_SIZE];
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    if (cJSON_IsString(v)) {
        cg_rgba8 encoded;
        cg_error parse_error;
        if (cg_color_parse(v->valuestring, &encoded, &parse_error) != CG_OK)
            return fail(p, key_path, "%s", parse_error.message);
        cg_rgbaf linear = cg_rgba8_to_linear(encoded);
        *out = cg_vec3_make(linear.r, linear.g, linear.b);
        return CG_OK;
    }
    double rgb[3];
    if (!cJSON_IsArray(v))
        return expected(p, key_path, "a colour (\"#rrggbb\", a name, or [r, g, b] in linear light)", v);
    cg_status s = read_numbers(p, key_path, v, 3, rgb);
    if (s != CG_OK)
        return s;
    if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0)
        return expected(p, key_path, "colour components >= 0", v);
    *out = cg_vec3_make(rgb[0], rgb[1], rgb[2]);
    return CG_OK;
}

/* One of names (NULL-terminated); *out gets its index. */
static cg_status get_choice(const parser *p, const char *path, const cJSON *obj, const char *key,
                            const char *const *names, int *out)
{
    char key_path[PATH_SIZE], what[200] = "one of";
    const cJSON *v = member(obj, path, key, key_path);
    if (!v)
        return CG_OK;
    for (int i = 0; names[i]; i++) {
        if (cJSON_IsString(v) && strcmp(v->valuestring, names[i]) == 0) {
            *out = i;
            return CG_OK;
        }
        size_t used = strlen(what);
        snprintf(what + used, sizeof what - used, "%s \"%s\"", i ? "," : "", names[i]);
    }
    return expected(p, key_path, what, v);
}

static cg_status parse_image(const parser *p, const cJSON *v, cg_scene *s)
{
    static const char *const keys[] = {"width", "height", "background", NULL};
    cg_status st;
    if ((st = need_object(p, "image", v)) || (st = check_keys(p, "image", v, keys))
        || (st = get_int(p, "image", v, "width", 1, CG_SCENE_MAX_SIDE, &s->width))
        || (st = get_int(p, "image", v, "height", 1, CG_SCENE_MAX_SIDE, &s->height)))
        return st;
    cg_vec3 bg = {s->background.r, s->background.g, s->background.b};
    if ((st = get_color(p, "image", v, "background", &bg)))
        return st;
    s->background.r = (float)bg.x;
    s->background.g = (float)bg.y;
    s->background.b = (float)bg.z;
    return CG_OK;
}

static cg_status parse_camera(const parser *p, const cJSON *v, cg_scene *s)
{
    static const char *const keys[] = {"eye", "target", "up", "projection", "fov", "height",
                                       "near", "far", "frame", "angles", "ratio", "angle", NULL};
    static const char *const projections[] = {"perspective", "orthographic", "isometric",
                                              "dimetric", "trimetric", "cavalier", "cabinet",
                                              "oblique", NULL};
    cg_status st;
    if ((st = need_object(p, "camera", v)) || (st = check_keys(p, "camera", v, keys)))
        return st;
    cg_camera *c = &s->camera;
    int projection = (int)s->projection;
    double fov = cg_degrees(c->fovy), angle = cg_degrees(s->projection_angle);
    s->frame_camera = cJSON_GetObjectItemCaseSensitive(v, "eye") == NULL;
    if ((st = get_vec3(p, "camera", v, "eye", &c->eye)) || (st = get_vec3(p, "camera", v, "target", &c->target))
        || (st = get_vec3(p, "camera", v, "up", &c->up))
        || (st = get_choice(p, "camera", v, "projection", projections, &projection))
        || (st = get_number(p, "camera", v, "fov", 1, 179, &fov))
        || (st = get_number(p, "camera", v, "height", 1e-9, 1e12, &c->ortho_height))
        || (st = get_number(p, "camera", v, "near", 1e-9, 1e12, &c->near))
        || (st = get_number(p, "camera", v, "far", 1e-9, 1e15, &c->far))
        || (st = get_bool(p, "camera", v, "frame", &s->frame_camera))
        || (st = get_number(p, "camera", v, "ratio", 1e-3, 10, &s->projection_ratio))
        || (st = get_number(p, "camera", v, "angle", -360, 360, &angle)))
        return st;
    const cJSON *angles = cJSON_GetObjectItemCaseSensitive(v, "angles");
    if (angles) {
        double a[2];
        if ((st = read_numbers(p, "camera.angles", angles, 2, a)))
            return st;
        s->projection_angle = cg_radians(a[0]);
        s->projection_angle2 = cg_radians(a[1]);
    } else {
        s->projection_angle = cg_radians(angle);
    }
    if (projection == CG_SCENE_DIMETRIC && !(s->projection_ratio < 1))
        return fail(p, "camera.ratio", "expected a number between 0.001 and 1 (exclusive) for a dimetric view");
    s->near_given = cJSON_GetObjectItemCaseSensitive(v, "near") != NULL;
    s->far_given = cJSON_GetObjectItemCaseSensitive(v, "far") != NULL;
    if (s->near_given && s->far_given && !(c->far > c->near))
        return fail(p, "camera.far", "expected a distance greater than near (%g)", c->near);
    if (!(cg_vec3_length(cg_vec3_sub(c->target, c->eye)) > 0))
        return fail(p, "camera.target", "expected a point different from the eye");
    s->projection = (cg_scene_projection)projection;
    c->fovy = cg_radians(fov);
    c->orthographic = projection != CG_SCENE_PERSPECTIVE;
    return CG_OK;
}

static cg_status parse_render(const parser *p, const cJSON *v, cg_scene *s)
{
    static const char *const keys[] = {"algorithm", "shading", "cull", "edges", "threads",
                                       "samples", "depth", "shadows", NULL};
    static const char *const algorithms[] = {"zbuffer", "painter", "raytrace", NULL};
    static const char *const shadings[] = {"flat", "gouraud", "phong", NULL};
    static const char *const culls[] = {"none", "back", NULL};
    static const char *const edges[] = {"none", "wireframe", "hidden-line", "overlay", NULL};
    int algorithm = (int)s->algorithm, shading = (int)s->shading, cull = s->cull_back,
        edge = (int)s->edges;
    cg_status st;
    if ((st = need_object(p, "render", v)) || (st = check_keys(p, "render", v, keys))
        || (st = get_choice(p, "render", v, "algorithm", algorithms, &algorithm))
        || (st = get_choice(p, "render", v, "shading", shadings, &shading))
        || (st = get_choice(p, "render", v, "cull", culls, &cull))
        || (st = get_choice(p, "render", v, "edges", edges, &edge))
        || (st = get_int(p, "render", v, "threads", 1, 64, &s->threads))
        || (st = get_int(p, "render", v, "samples", 1, 1024, &s->samples))
        || (st = get_int(p, "render", v, "depth", 0, 32, &s->max_depth))
        || (st = get_bool(p, "render", v, "shadows", &s->shadows)))
        return st;
    s->algorithm = (cg_scene_algorithm)algorithm;
    s->shading = (cg_scene_shading)shading;
    s->cull_back = cull;
    s->edges = (cg_scene_edges)edge;
    return CG_OK;
}

/* Makes room for one more item in a growing array of count items; the
 * capacity doubles, so n appends cost O(n). */
static cg_status reserve(const parser *p, void **items, size_t count, size_t item_size)
{
    if (count & (count - 1)) /* not a power of two: there is room */
        return CG_OK;
    void *grown = realloc(*items, (count ? 2 * count : 1) * item_size);
    if (!grown)
        return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
    *items = grown;
    return CG_OK;
}

static cg_status parse_light(const parser *p, const char *path, const cJSON *v, cg_scene *s)
{
    static const char *const kinds[] = {"ambient", "point", "directional", "spot", "area", NULL};
    static const char *const keys[] = {"type", "color", "intensity", "position", "direction",
                                       "attenuation", "cutoff", "exponent", "corner", "edge_u",
                                       "edge_v", "samples", NULL};
    cg_status st;
    if ((st = need_object(p, path, v)) || (st = check_keys(p, path, v, keys)))
        return st;
    int kind = -1;
    if ((st = get_choice(p, path, v, "type", kinds, &kind)))
        return st;
    if (kind < 0) {
        char type_path[PATH_SIZE];
        join(type_path, path, "type");
        return expected(p, type_path, "one of \"ambient\", \"point\", \"directional\", \"spot\", \"area\"",
                        NULL);
    }
    cg_vec3 color = {1, 1, 1}, position = {0, 10, 0}, direction = {0, -1, 0};
    double intensity = 1, cutoff = 30, exponent = 0;
    if ((st = get_color(p, path, v, "color", &color)) || (st = get_number(p, path, v, "intensity", 0, 1e9, &intensity))
        || (st = get_vec3(p, path, v, "position", &position)) || (st = get_vec3(p, path, v, "direction", &direction))
        || (st = get_number(p, path, v, "cutoff", 1e-6, 180, &cutoff))
        || (st = get_number(p, path, v, "exponent", 0, 1e4, &exponent)))
        return st;
    color = cg_vec3_scale(color, intensity);
    if (kind == 4) { /* area */
        cg_scene_area_light a = {{0, 10, 0}, {1, 0, 0}, {0, 0, 1}, color, 4};
        if ((st = get_vec3(p, path, v, "corner", &a.corner)) || (st = get_vec3(p, path, v, "edge_u", &a.edge_u))
            || (st = get_vec3(p, path, v, "edge_v", &a.edge_v))
            || (st = get_int(p, path, v, "samples", 1, 64, &a.samples)))
            return st;
        if (!(cg_vec3_length(cg_vec3_cross(a.edge_u, a.edge_v)) > 0))
            return fail(p, path, "expected edge_u and edge_v spanning a rectangle");
        if ((st = reserve(p, (void **)&s->area_lights, s->area_light_count, sizeof a)))
            return st;
        s->area_lights[s->area_light_count++] = a;
        return CG_OK;
    }
    if ((kind == 2 || kind == 3) && !(cg_vec3_length(direction) > 0))
        return fail(p, path, "expected a non-zero direction");
    cg_light light;
    switch (kind) {
    case 0: light = cg_light_ambient(color); break;
    case 1: light = cg_light_point(position, color); break;
    case 2: light = cg_light_directional(direction, color); break;
    default: light = cg_light_spot(position, direction, cg_radians(cutoff), exponent, color); break;
    }
    const cJSON *att = cJSON_GetObjectItemCaseSensitive(v, "attenuation");
    if (att) {
        double c[3];
        char att_path[PATH_SIZE];
        join(att_path, path, "attenuation");
        if ((st = read_numbers(p, att_path, att, 3, c)))
            return st;
        cg_light_set_attenuation(&light, c[0], c[1], c[2]);
    }
    cg_error check;
    if (cg_light_check(&light, &check) != CG_OK)
        return fail(p, path, "%s", check.message);
    if ((st = reserve(p, (void **)&s->lights, s->light_count, sizeof light)))
        return st;
    s->lights[s->light_count++] = light;
    return CG_OK;
}

static cg_status parse_material(const parser *p, const char *path, const cJSON *v,
                                cg_scene_material *m)
{
    static const char *const keys[] = {"color", "specular_color", "ka", "kd", "ks", "shininess",
                                       "specular", "reflectance", "transmittance", "ior",
                                       "checker", NULL};
    static const char *const models[] = {"phong", "blinn", NULL};
    cg_material *s = &m->surface;
    int model = (int)s->specular;
    cg_status st;
    if ((st = need_object(p, path, v)) || (st = check_keys(p, path, v, keys))
        || (st = get_color(p, path, v, "color", &s->color))
        || (st = get_color(p, path, v, "specular_color", &s->specular_color))
        || (st = get_number(p, path, v, "ka", 0, 1e3, &s->ka)) || (st = get_number(p, path, v, "kd", 0, 1e3, &s->kd))
        || (st = get_number(p, path, v, "ks", 0, 1e3, &s->ks))
        || (st = get_number(p, path, v, "shininess", 0, 1e5, &s->shininess))
        || (st = get_choice(p, path, v, "specular", models, &model))
        || (st = get_number(p, path, v, "reflectance", 0, 1, &s->reflectance))
        || (st = get_number(p, path, v, "transmittance", 0, 1, &s->transmittance))
        || (st = get_number(p, path, v, "ior", 0.01, 100, &s->refractive_index)))
        return st;
    s->specular = (cg_specular_model)model;
    const cJSON *checker = cJSON_GetObjectItemCaseSensitive(v, "checker");
    if (checker) {
        static const char *const checker_keys[] = {"color", "size", NULL};
        char checker_path[PATH_SIZE];
        join(checker_path, path, "checker");
        m->checker_size = 1;
        m->checker_color = cg_vec3_make(0.1, 0.1, 0.1);
        if ((st = need_object(p, checker_path, checker)) || (st = check_keys(p, checker_path, checker, checker_keys))
            || (st = get_color(p, checker_path, checker, "color", &m->checker_color))
            || (st = get_number(p, checker_path, checker, "size", 1e-9, 1e12, &m->checker_size)))
            return st;
    }
    return CG_OK;
}

static cg_status parse_materials(const parser *p, const cJSON *v, cg_scene *s)
{
    cg_status st;
    if ((st = need_object(p, "materials", v)))
        return st;
    for (const cJSON *item = v->child; item; item = item->next) {
        char path[PATH_SIZE];
        join(path, "materials", item->string);
        for (size_t i = 0; i < s->material_count; i++)
            if (s->materials[i].name && strcmp(s->materials[i].name, item->string) == 0)
                return fail(p, path, "material defined twice");
        cg_scene_material m = scene_default_material();
        if ((st = parse_material(p, path, item, &m)))
            return st;
        cg_scene_material *grown = realloc(s->materials, (s->material_count + 1) * sizeof *grown);
        m.name = grown ? malloc(strlen(item->string) + 1) : NULL;
        if (!grown || !m.name) {
            if (grown)
                s->materials = grown;
            return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
        }
        strcpy(m.name, item->string);
        s->materials = grown;
        s->materials[s->material_count++] = m;
    }
    return CG_OK;
}

/* One step of a transform list: {"translate": [x, y, z]}, {"scale": s or
 * [sx, sy, sz], "center": [..]}, {"rotate": degrees, "axis": [..],
 * "point": [..]}, {"reflect": normal, "point": [..]}, {"shear": [xy, xz, yx,
 * yz, zx, zy]} or {"matrix": [16 numbers, row by row]}. */
static cg_status parse_step(const parser *p, const char *path, const cJSON *v, cg_mat4 *out)
{
    static const char *const translate_keys[] = {"translate", NULL};
    static const char *const scale_keys[] = {"scale", "center", NULL};
    static const char *const rotate_keys[] = {"rotate", "axis", "point", NULL};
    static const char *const reflect_keys[] = {"reflect", "point", NULL};
    static const char *const shear_keys[] = {"shear", NULL};
    static const char *const matrix_keys[] = {"matrix", NULL};
    cg_status st;
    if ((st = need_object(p, path, v)))
        return st;
    cg_vec3 center = {0, 0, 0};
    char key_path[PATH_SIZE];
    const cJSON *x;
    if ((x = cJSON_GetObjectItemCaseSensitive(v, "translate"))) {
        cg_vec3 t = {0, 0, 0};
        if ((st = check_keys(p, path, v, translate_keys)) || (st = get_vec3(p, path, v, "translate", &t)))
            return st;
        *out = cg_xform3_translate(t.x, t.y, t.z);
    } else if ((x = cJSON_GetObjectItemCaseSensitive(v, "scale"))) {
        cg_vec3 factors;
        if ((st = check_keys(p, path, v, scale_keys)) || (st = get_vec3(p, path, v, "center", &center)))
            return st;
        join(key_path, path, "scale");
        if (cJSON_IsNumber(x) && isfinite(x->valuedouble))
            factors = cg_vec3_make(x->valuedouble, x->valuedouble, x->valuedouble);
        else if ((st = get_vec3(p, path, v, "scale", &factors)))
            return st;
        if (factors.x == 0 || factors.y == 0 || factors.z == 0)
            return expected(p, key_path, "non-zero scale factors", x);
        *out = cg_xform3_scale(factors.x, factors.y, factors.z, center);
    } else if ((x = cJSON_GetObjectItemCaseSensitive(v, "rotate"))) {
        cg_vec3 axis = {0, 1, 0};
        double degrees = 0;
        if ((st = check_keys(p, path, v, rotate_keys)) || (st = get_number(p, path, v, "rotate", -1e6, 1e6, &degrees))
            || (st = get_vec3(p, path, v, "axis", &axis)) || (st = get_vec3(p, path, v, "point", &center)))
            return st;
        if (cg_xform3_rotate_axis(axis, cg_radians(degrees), center, out) != CG_OK)
            return fail(p, path, "expected a non-zero rotation axis");
    } else if ((x = cJSON_GetObjectItemCaseSensitive(v, "reflect"))) {
        cg_vec3 normal = {0, 1, 0};
        if ((st = check_keys(p, path, v, reflect_keys)) || (st = get_vec3(p, path, v, "reflect", &normal))
            || (st = get_vec3(p, path, v, "point", &center)))
            return st;
        if (cg_xform3_reflect(center, normal, out) != CG_OK)
            return fail(p, path, "expected a non-zero plane normal");
    } else if ((x = cJSON_GetObjectItemCaseSensitive(v, "shear"))) {
        double k[6];
        join(key_path, path, "shear");
        if ((st = check_keys(p, path, v, shear_keys)) || (st = read_numbers(p, key_path, x, 6, k)))
            return st;
        *out = cg_xform3_shear(k[0], k[1], k[2], k[3], k[4], k[5]);
    } else if ((x = cJSON_GetObjectItemCaseSensitive(v, "matrix"))) {
        double m[16];
        join(key_path, path, "matrix");
        if ((st = check_keys(p, path, v, matrix_keys)) || (st = read_numbers(p, key_path, x, 16, m)))
            return st;
        for (int i = 0; i < 16; i++)
            out->m[i / 4][i % 4] = m[i];
        cg_mat4 inverse;
        if (cg_mat4_inverse(*out, &inverse) != CG_OK)
            return fail(p, key_path, "expected an invertible matrix");
    } else {
        return expected(p, path, "a step with one of translate, scale, rotate, reflect, shear, matrix", v);
    }
    return CG_OK;
}

static cg_status parse_transform(const parser *p, const char *path, const cJSON *v, cg_mat4 *out)
{
    if (!cJSON_IsArray(v))
        return expected(p, path, "an array of transformation steps", v);
    int n = cJSON_GetArraySize(v);
    if (n > CG_SCENE_MAX_TRANSFORMS)
        return fail(p, path, "%d steps, more than the limit of %d", n, CG_SCENE_MAX_TRANSFORMS);
    *out = cg_mat4_identity();
    int i = 0;
    for (const cJSON *item = v->child; item; item = item->next, i++) {
        char step_path[PATH_SIZE];
        cg_mat4 step;
        path_format(step_path, "%s[%d]", path, i);
        cg_status st = parse_step(p, step_path, item, &step);
        if (st)
            return st;
        *out = cg_mat4_mul(step, *out); /* the steps happen in the order listed */
    }
    return CG_OK;
}

static char *resolve_path(const char *base_dir, const char *file)
{
    size_t base = (base_dir && base_dir[0] && file[0] != '/') ? strlen(base_dir) + 1 : 0;
    char *path = malloc(base + strlen(file) + 1);
    if (!path)
        return NULL;
    if (base)
        snprintf(path, base + strlen(file) + 1, "%s/%s", base_dir, file);
    else
        strcpy(path, file);
    return path;
}

static cg_status parse_object(const parser *p, const char *path, const cJSON *v, cg_scene *s)
{
    static const char *const kinds[] = {"mesh", "sphere", "plane", "box", NULL};
    static const char *const keys[] = {"type", "file", "center", "radius", "point", "normal",
                                       "lo", "hi", "material", "transform", NULL};
    cg_status st;
    if ((st = need_object(p, path, v)) || (st = check_keys(p, path, v, keys))
        || (st = reserve(p, (void **)&s->objects, s->object_count, sizeof *s->objects)))
        return st;
    /* Counted before it is read so that cg_scene_free releases a half-read
     * object too. */
    cg_scene_object *o = &s->objects[s->object_count++];
    memset(o, 0, sizeof *o);
    int kind = -1;
    if ((st = get_choice(p, path, v, "type", kinds, &kind)))
        return st;
    char key_path[PATH_SIZE];
    if (kind < 0) {
        join(key_path, path, "type");
        return expected(p, key_path, "one of \"mesh\", \"sphere\", \"plane\", \"box\"", NULL);
    }
    o->kind = (cg_scene_object_kind)kind;
    o->transform = cg_mat4_identity();
    o->radius = 1;
    o->normal = cg_vec3_make(0, 1, 0);
    o->lo = cg_vec3_make(-0.5, -0.5, -0.5);
    o->hi = cg_vec3_make(0.5, 0.5, 0.5);
    if ((st = get_vec3(p, path, v, "center", &o->center)) || (st = get_number(p, path, v, "radius", 0, 1e15, &o->radius))
        || (st = get_vec3(p, path, v, "point", &o->point)) || (st = get_vec3(p, path, v, "normal", &o->normal))
        || (st = get_vec3(p, path, v, "lo", &o->lo)) || (st = get_vec3(p, path, v, "hi", &o->hi)))
        return st;
    if (o->kind == CG_SCENE_PLANE && !(cg_vec3_length(o->normal) > 0)) {
        join(key_path, path, "normal");
        return fail(p, key_path, "expected a non-zero normal");
    }
    /* A box of zero size on an axis has no inside (and no mesh to rasterize). */
    if (o->kind == CG_SCENE_BOX && !(o->lo.x < o->hi.x && o->lo.y < o->hi.y && o->lo.z < o->hi.z)) {
        join(key_path, path, "hi");
        return fail(p, key_path, "expected every coordinate of hi to be greater than that of lo "
                                 "(a box of non-zero size on each axis)");
    }
    const cJSON *transform = cJSON_GetObjectItemCaseSensitive(v, "transform");
    if (transform) {
        join(key_path, path, "transform");
        if ((st = parse_transform(p, key_path, transform, &o->transform)))
            return st;
    }
    const cJSON *material = cJSON_GetObjectItemCaseSensitive(v, "material");
    if (material) {
        join(key_path, path, "material");
        if (!cJSON_IsString(material))
            return expected(p, key_path, "the name of a material", material);
        size_t i = 1;
        while (i < s->material_count && strcmp(s->materials[i].name, material->valuestring) != 0)
            i++;
        if (i == s->material_count)
            return expected(p, key_path, "the name of a material defined in \"materials\"", material);
        o->material = i;
    }
    const cJSON *file = cJSON_GetObjectItemCaseSensitive(v, "file");
    if (o->kind == CG_SCENE_MESH) {
        join(key_path, path, "file");
        if (!cJSON_IsString(file) || !file->valuestring[0])
            return expected(p, key_path, "the path of a mesh file", file);
        if (!(o->file = resolve_path(p->base_dir, file->valuestring)))
            return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
        if (p->load_meshes) {
            cg_error mesh_error;
            cg_status ms = cg_mesh_load(o->file, &o->mesh, &mesh_error);
            if (ms != CG_OK)
                return cg_error_set(p->err, ms, "%s: %s: %s", p->name, key_path, mesh_error.message);
        }
    } else if (file) {
        join(key_path, path, "file");
        return fail(p, key_path, "only mesh objects have a file");
    }
    return CG_OK;
}

static cg_status parse_overlay(const parser *p, const char *path, const cJSON *v, cg_scene *s)
{
    if (!cJSON_IsString(v) || strchr(v->valuestring, '\n'))
        return expected(p, path, "one line of a cg draw script", v);
    cg_status st = reserve(p, (void **)&s->overlays, s->overlay_count, sizeof *s->overlays);
    if (st)
        return st;
    size_t length = strlen(v->valuestring) + 1;
    if (!(s->overlays[s->overlay_count] = malloc(length)))
        return cg_error_set(p->err, CG_ENOMEM, "%s: out of memory", p->name);
    memcpy(s->overlays[s->overlay_count++], v->valuestring, length);
    return CG_OK;
}

typedef cg_status (*item_parser)(const parser *p, const char *path, const cJSON *v, cg_scene *s);

/* Reads the array root[key] (when present) of at most limit items, each with
 * parse_item, naming them key[0], key[1], ... in messages. */
static cg_status parse_array(const parser *p, const cJSON *root, const char *key, int limit,
                             item_parser parse_item, cg_scene *s)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(root, key);
    if (!v)
        return CG_OK;
    if (!cJSON_IsArray(v))
        return expected(p, key, "an array", v);
    if (cJSON_GetArraySize(v) > limit)
        return fail(p, key, "%d entries, more than the limit of %d", cJSON_GetArraySize(v), limit);
    int i = 0;
    for (const cJSON *item = v->child; item; item = item->next, i++) {
        char path[PATH_SIZE];
        path_format(path, "%s[%d]", key, i);
        cg_status st = parse_item(p, path, item, s);
        if (st)
            return st;
    }
    return CG_OK;
}

static cg_status parse_scene(const parser *p, const cJSON *root, cg_scene *s)
{
    static const char *const keys[] = {"comment", "image", "camera", "render", "lights",
                                       "materials", "objects", "overlays", NULL};
    cg_status st;
    if (!cJSON_IsObject(root))
        return cg_error_set(p->err, CG_EFORMAT, "%s: expected a JSON object at the top level", p->name);
    if ((st = check_keys(p, "", root, keys)))
        return st;
    const cJSON *v;
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "image")) && (st = parse_image(p, v, s)))
        return st;
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "camera")) && (st = parse_camera(p, v, s)))
        return st;
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "render")) && (st = parse_render(p, v, s)))
        return st;
    if ((v = cJSON_GetObjectItemCaseSensitive(root, "materials")) && (st = parse_materials(p, v, s)))
        return st;
    if ((st = parse_array(p, root, "lights", CG_SCENE_MAX_LIGHTS, parse_light, s))
        || (st = parse_array(p, root, "objects", CG_SCENE_MAX_OBJECTS, parse_object, s))
        || (st = parse_array(p, root, "overlays", CG_SCENE_MAX_OVERLAYS, parse_overlay, s)))
        return st;
    return CG_OK;
}

cg_status cg_scene_parse(const char *text, size_t size, const char *name, const char *base_dir,
                         int load_meshes, cg_scene **out, cg_error *err)
{
    if (!out)
        return cg_error_set(err, CG_EINVAL, "scene: no output given");
    *out = NULL;
    if (!name)
        name = "scene";
    if (!text || size == 0)
        return cg_error_set(err, CG_EFORMAT, "%s: empty scene file", name);
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithLengthOpts(text, size, &end, 0);
    if (!root) {
        /* cJSON reports where it stopped: turn that into a line and column. */
        size_t offset = end && end >= text && (size_t)(end - text) <= size ? (size_t)(end - text) : 0;
        int line = 1, column = 1;
        for (size_t i = 0; i < offset; i++) {
            if (text[i] == '\n') {
                line++;
                column = 1;
            } else {
                column++;
            }
        }
        return cg_error_set(err, CG_EFORMAT, "%s:%d:%d: malformed JSON", name, line, column);
    }
    cg_scene *scene;
    cg_status status = scene_create_empty(&scene);
    if (status != CG_OK) {
        cJSON_Delete(root);
        return cg_error_set(err, status, "%s: out of memory", name);
    }
    parser p = {name, err, base_dir, load_meshes};
    status = parse_scene(&p, root, scene);
    cJSON_Delete(root);
    if (status != CG_OK) {
        cg_scene_free(scene);
        return status;
    }
    *out = scene;
    return CG_OK;
}

cg_status cg_scene_load(const char *path, cg_scene **out, cg_error *err)
{
    if (!path || !out)
        return cg_error_set(err, CG_EINVAL, "scene: no path or output given");
    *out = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return cg_error_set(err, CG_EIO, "%s: cannot open: %s", path, strerror(errno));
    /* Scene files are small: anything over 64 MiB is refused before reading. */
    const long limit = 64L << 20;
    long size = -1;
    if (fseek(f, 0, SEEK_END) == 0)
        size = ftell(f);
    if (size < 0 || size > limit || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return cg_error_set(err, size > limit ? CG_ERANGE : CG_EIO,
                            size > limit ? "%s: larger than the 64 MiB limit for scene files"
                                         : "%s: cannot read", path);
    }
    char *text = malloc((size_t)size + 1);
    size_t got = text ? fread(text, 1, (size_t)size, f) : 0;
    int failed = ferror(f) || got != (size_t)size;
    fclose(f);
    if (!text)
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    if (failed) {
        free(text);
        return cg_error_set(err, CG_EIO, "%s: read error", path);
    }
    char *base_dir = malloc(strlen(path) + 1);
    if (!base_dir) {
        free(text);
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    }
    strcpy(base_dir, path);
    char *slash = strrchr(base_dir, '/');
    if (slash)
        *slash = '\0';
    else
        base_dir[0] = '\0';
    cg_status status = cg_scene_parse(text, (size_t)size, path, base_dir, 1, out, err);
    free(base_dir);
    free(text);
    return status;
}
