/* `cg trace` for chapters 3-9: the viewing pipeline of one point, vanishing
 * points, back-face culling, the z-buffer at a pixel, the illumination at a
 * point light by light, RGB to HSV and HSL, half-edge traversals. */
#include "trace_algorithms.h"

#include "cli.h"
#include "cg/color.h"
#include "cg/hemesh.h"
#include "cg/light.h"
#include "cg/mesh.h"
#include "cg/xform.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The camera arguments after the point, [EYE [TARGET [FOVY [WxH]]]], and
 * the view and projection they make: 0, or CLI_USAGE after a message. */
typedef struct camera_args {
    cg_vec3 eye, target;
    double fovy;
    int width, height;
    cg_mat4 view, projection;
} camera_args;

static int read_camera(const char *name, int argc, char **argv, camera_args *c)
{
    if ((argc > 2 && cli_parse_vec3("trace", "EYE", argv[2], &c->eye))
        || (argc > 3 && cli_parse_vec3("trace", "TARGET", argv[3], &c->target))
        || (argc > 4 && trace_parse_real("FOVY", argv[4], &c->fovy))
        || (argc > 5 && cli_parse_size("trace", "WxH", argv[5], &c->width, &c->height)))
        return CLI_USAGE;
    if (!(c->fovy > 0 && c->fovy < 180))
        return cli_usage_error("trace", "%s: FOVY is in degrees, between 0 and 180", name);
    if (cg_view_look_at(c->eye, c->target, cg_vec3_make(0, 1, 0), &c->view) != CG_OK
        && cg_view_look_at(c->eye, c->target, cg_vec3_make(0, 0, -1), &c->view) != CG_OK)
        return cli_usage_error("trace", "%s: EYE and TARGET must differ", name);
    if (cg_proj_perspective(c->fovy * M_PI / 180, (double)c->width / c->height, 0.1, 100,
                            &c->projection)
        != CG_OK)
        return cli_usage_error("trace", "%s: the projection cannot be made", name);
    return 0;
}

/* NAME X,Y,Z [EYE [TARGET [FOVY [WxH]]]]: the vector (called what) and the
 * camera, by default at (0, 0, 5) looking at the origin, 60 degrees,
 * 640x480.  0, or CLI_USAGE after a message (usage when the count is off). */
static int read_vector_camera(const char *usage, const char *what, int argc, char **argv,
                              cg_vec3 *vector, camera_args *c)
{
    *c = (camera_args){.eye = {0, 0, 5},
                       .target = {0, 0, 0},
                       .fovy = 60,
                       .width = 640,
                       .height = 480};
    if (argc < 2 || argc > 6)
        return cli_usage_error("trace", "%s", usage);
    if (cli_parse_vec3("trace", what, argv[1], vector) || read_camera(argv[0], argc, argv, c))
        return CLI_USAGE;
    return 0;
}

static int run_pipeline(int argc, char **argv, const trace_outputs *out)
{
    cg_vec3 point;
    camera_args c;
    if (read_vector_camera("pipeline: expected 'pipeline X,Y,Z [EYE [TARGET [FOVY [WxH]]]]' "
                           "(points as X,Y,Z)",
                           "point", argc, argv, &point, &c))
        return CLI_USAGE;
    trace_run *run = trace_run_create("pipeline", argc - 1, argv + 1,
                                      "The viewing pipeline of (%g, %g, %g): camera at (%g, %g, "
                                      "%g) looking at (%g, %g, %g), %g degrees, %dx%d",
                                      point.x, point.y, point.z, c.eye.x, c.eye.y, c.eye.z,
                                      c.target.x, c.target.y, c.target.z, c.fovy, c.width,
                                      c.height);
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run, "object --M--> world --V--> eye --P--> clip (x, y, z, w) --divide by w--> "
                    "NDC --W--> window");
    trace_note(run, "M is the identity here; V from look-at (up +y); P perspective, near 0.1, "
                    "far 100; matrices row by row, rows separated by ';'");
    cg_mat4 model = cg_xform3_translate(0, 0, 0);
    cg_status status = cg_pipeline_steps(model, c.view, c.projection, c.width, c.height, point,
                                         cg_step_log_record, run->log);
    return trace_finish(run, status, "the point must be finite", out);
}

static int run_vanishing(int argc, char **argv, const trace_outputs *out)
{
    cg_vec3 direction;
    camera_args c;
    if (read_vector_camera("vanishing: expected 'vanishing DX,DY,DZ [EYE [TARGET [FOVY [WxH]]]]'",
                           "direction", argc, argv, &direction, &c))
        return CLI_USAGE;
    if (!(cg_vec3_length(direction) > 0))
        return cli_usage_error("trace", "vanishing: the direction must not be zero");
    trace_run *run = trace_run_create("vanishing", argc - 1, argv + 1,
                                      "The vanishing point of direction (%g, %g, %g), camera at "
                                      "(%g, %g, %g) looking at (%g, %g, %g)",
                                      direction.x, direction.y, direction.z, c.eye.x, c.eye.y,
                                      c.eye.z, c.target.x, c.target.y, c.target.z);
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run, "parallel lines of direction d meet at the point at infinity (d, 0); its "
                    "image is where their images converge");
    cg_status status = cg_vanishing_point_steps(c.view, c.projection, c.width, c.height, direction,
                                                cg_step_log_record, run->log);
    return trace_finish(run, status, "the direction must not be zero", out);
}

static int run_color(int lightness, int argc, char **argv, const trace_outputs *out)
{
    double rgb[3];
    static const char *const names[3] = {"R", "G", "B"};
    if (argc != 4)
        return cli_usage_error("trace", "%s: expected '%s R G B' with components in [0, 1]",
                               argv[0], argv[0]);
    for (int i = 0; i < 3; i++)
        if (trace_parse_real(names[i], argv[i + 1], &rgb[i]))
            return CLI_USAGE;
    trace_run *run = trace_run_create(argv[0], argc - 1, argv + 1, "RGB (%g, %g, %g) to %s", rgb[0],
                                      rgb[1], rgb[2], lightness ? "HSL" : "HSV");
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run, "hue H in degrees [0, 360), saturation S and %s in [0, 1] (section 7.3)",
               lightness ? "lightness L" : "value V");
    cg_status status = cg_rgb_to_hsv_steps(cg_vec3_make(rgb[0], rgb[1], rgb[2]), lightness,
                                           cg_step_log_record, run->log);
    return trace_finish(run, status, "bad colour", out);
}

static int run_hsv(int argc, char **argv, const trace_outputs *out)
{
    return run_color(0, argc, argv, out);
}

static int run_hsl(int argc, char **argv, const trace_outputs *out)
{
    return run_color(1, argc, argv, out);
}

enum { MAX_LIGHTS = 8 };

/* "ambient:R,G,B", "point:X,Y,Z:R,G,B", "directional:X,Y,Z:R,G,B". */
static int parse_light(const char *text, cg_light *light)
{
    char kind[16], a[128], b[128];
    const char *colon = strchr(text, ':');
    size_t n = colon ? (size_t)(colon - text) : 0;
    if (!colon || n >= sizeof kind)
        return cli_usage_error("trace",
                               "light: '%s' is not ambient:R,G,B, point:X,Y,Z:R,G,B or "
                               "directional:X,Y,Z:R,G,B",
                               text);
    memcpy(kind, text, n);
    kind[n] = 0;
    const char *rest = colon + 1, *second = strchr(rest, ':');
    cg_vec3 where, color;
    if (strcmp(kind, "ambient") == 0 && !second) {
        if (cli_parse_vec3("trace", "light colour", rest, &color))
            return CLI_USAGE;
        *light = cg_light_ambient(color);
    } else if ((strcmp(kind, "point") == 0 || strcmp(kind, "directional") == 0) && second
               && (size_t)(second - rest) < sizeof a && strlen(second + 1) < sizeof b) {
        memcpy(a, rest, (size_t)(second - rest));
        a[second - rest] = 0;
        strcpy(b, second + 1);
        if (cli_parse_vec3("trace", "light position", a, &where)
            || cli_parse_vec3("trace", "light colour", b, &color))
            return CLI_USAGE;
        if (kind[0] == 'd' && !(cg_vec3_length(where) > 0))
            return cli_usage_error("trace", "light: a direction must not be zero");
        *light = kind[0] == 'p' ? cg_light_point(where, color) : cg_light_directional(where, color);
    } else {
        return cli_usage_error("trace",
                               "light: '%s' is not ambient:R,G,B, point:X,Y,Z:R,G,B or "
                               "directional:X,Y,Z:R,G,B",
                               text);
    }
    if (cg_light_check(light, NULL) != CG_OK)
        return cli_usage_error("trace", "light: '%s': colours must not be negative", text);
    return CLI_OK;
}

static int run_light(int argc, char **argv, const trace_outputs *out)
{
    cg_vec3 point, normal, eye;
    cg_light lights[MAX_LIGHTS];
    size_t count = 0;
    if (argc < 4 || argc > 4 + MAX_LIGHTS)
        return cli_usage_error("trace",
                               "light: expected 'light POINT NORMAL EYE [LIGHT ...]' "
                               "(at most %d lights)",
                               MAX_LIGHTS);
    if (cli_parse_vec3("trace", "POINT", argv[1], &point)
        || cli_parse_vec3("trace", "NORMAL", argv[2], &normal)
        || cli_parse_vec3("trace", "EYE", argv[3], &eye))
        return CLI_USAGE;
    if (!(cg_vec3_length(normal) > 0) || !(cg_vec3_length(cg_vec3_sub(eye, point)) > 0))
        return cli_usage_error("trace", "light: the normal must not be zero and the eye not at "
                                        "the point");
    for (int i = 4; i < argc; i++)
        if (parse_light(argv[i], &lights[count++]) != CLI_OK)
            return CLI_USAGE;
    if (count == 0) {
        lights[count++] = cg_light_ambient(cg_vec3_make(0.2, 0.2, 0.2));
        lights[count++] = cg_light_point(cg_vec3_make(5, 5, 5), cg_vec3_make(1, 1, 1));
    }
    cg_material material = cg_material_make(cg_vec3_make(0.8, 0.4, 0.2), 0.2, 0.7, 0.5, 20);
    normal = cg_vec3_normalize(normal);
    cg_vec3 view = cg_vec3_normalize(cg_vec3_sub(eye, point));
    trace_run *run = trace_run_create("light", argc - 1, argv + 1,
                                      "Illumination at (%g, %g, %g), normal (%g, %g, %g), seen "
                                      "from (%g, %g, %g)",
                                      point.x, point.y, point.z, normal.x, normal.y, normal.z,
                                      eye.x, eye.y, eye.z);
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run,
               "material: Od = (0.8, 0.4, 0.2), ka = 0.2, kd = 0.7, ks = 0.5, n = 20, "
               "Phong specular, Os white; V = (%g, %g, %g)",
               view.x, view.y, view.z);
    trace_note(run, "I = sum ka Od Ia + sum f_att spot Il (kd Od max(N.L, 0) + ks Os spec), "
                    "spec = max(R.V, 0)^n, R = 2 (N.L) N - L");
    trace_note(run, "f_att = min(1, 1 / (c0 + c1 d + c2 d^2)) (no attenuation here: c = 1, 0, "
                    "0); spec = 0 when N.L <= 0");
    cg_status status = cg_light_steps(point, normal, view, &material, lights, count,
                                      cg_step_log_record, run->log);
    return trace_finish(run, status, "bad material or light", out);
}

/* Loads the mesh, turns it about y then x (degrees) and frames it with the
 * default camera for the aspect, as cg render does; CLI_OK or CLI_FAILED
 * after a message. */
static int frame_mesh(const char *path, double about_y, double about_x, double aspect,
                      cg_mesh **mesh, cg_mat4 *model, cg_camera *camera)
{
    cg_error err;
    if (cg_mesh_load(path, mesh, &err) != CG_OK)
        return cli_fail("trace: %s", err.message);
    *model = cg_mat4_mul(cg_xform3_rotate_x(about_x * M_PI / 180),
                         cg_xform3_rotate_y(about_y * M_PI / 180));
    cg_vec3 lo, hi, corner[8];
    *camera = cg_camera_default();
    cg_status status = cg_mesh_bounds(*mesh, &lo, &hi);
    if (status == CG_OK) { /* frame the turned box */
        for (int i = 0; i < 8; i++)
            corner[i] = cg_mat4_transform_point(
                *model,
                cg_vec3_make(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z));
        lo = hi = corner[0];
        for (int i = 1; i < 8; i++) {
            lo = cg_vec3_make(fmin(lo.x, corner[i].x), fmin(lo.y, corner[i].y),
                              fmin(lo.z, corner[i].z));
            hi = cg_vec3_make(fmax(hi.x, corner[i].x), fmax(hi.y, corner[i].y),
                              fmax(hi.z, corner[i].z));
        }
        status = cg_camera_frame(camera, lo, hi, aspect);
    }
    if (status != CG_OK) {
        cg_mesh_free(*mesh);
        return cli_fail("trace: %s: the mesh has no extent to look at", path);
    }
    return CLI_OK;
}

/* backface MESH [ABOUT_Y [ABOUT_X]] */
static int run_backface(int argc, char **argv, const trace_outputs *out)
{
    double about_y = 30, about_x = 20;
    if (argc < 2 || argc > 4)
        return cli_usage_error("trace", "backface: expected 'backface MESH [ABOUT_Y [ABOUT_X]]' "
                                        "(degrees)");
    if ((argc > 2 && trace_parse_real("ABOUT_Y", argv[2], &about_y))
        || (argc > 3 && trace_parse_real("ABOUT_X", argv[3], &about_x)))
        return CLI_USAGE;
    cg_mesh *mesh;
    cg_mat4 model;
    cg_camera camera;
    if (frame_mesh(argv[1], about_y, about_x, 4.0 / 3.0, &mesh, &model, &camera) != CLI_OK)
        return CLI_FAILED;
    trace_run *run = trace_run_create("backface", argc - 1, argv + 1,
                                      "Back-face culling of %s turned %g degrees about y and %g "
                                      "about x, camera at (%g, %g, %g)",
                                      argv[1], about_y, about_x, camera.eye.x, camera.eye.y,
                                      camera.eye.z);
    if (!run) {
        cg_mesh_free(mesh);
        return cli_fail("trace: out of memory");
    }
    run->y_up = 1;
    trace_note(run, "N = (v1 - v0) x (v2 - v0) of each triangle in world space (faces are "
                    "counter-clockwise seen from outside), V = eye - v0");
    trace_note(run, "N.V > 0: the triangle faces the eye and is kept; N.V <= 0: a back face, "
                    "culled");
    trace_note(run, "the frames show the triangles in view space, x right and y up");
    cg_status status = cg_backface_steps(mesh, model, &camera, cg_step_log_record, run->log);
    cg_mesh_free(mesh);
    long culled = 0;
    for (size_t i = 0; i < cg_step_log_count(run->log); i++)
        culled += strcmp(cg_step_find(cg_step_log_get(run->log, i), "decision")->text,
                         "front: kept")
                  != 0;
    trace_summary(run, "%ld of %zu triangles culled", culled, cg_step_log_count(run->log));
    return trace_finish(run, status, "the mesh is not valid", out);
}

/* zbuffer MESH X Y [WxH]: the mesh turned 30 degrees about y and 20 about x,
 * framed, in a WxH frame (160x120). */
static int run_zbuffer(int argc, char **argv, const trace_outputs *out)
{
    long x, y;
    int width = 160, height = 120;
    if (argc < 4 || argc > 5)
        return cli_usage_error("trace", "zbuffer: expected 'zbuffer MESH X Y [WxH]'");
    if ((argc > 4 && cli_parse_size("trace", "WxH", argv[4], &width, &height))
        || trace_parse_int("X", argv[2], 0, width - 1, &x)
        || trace_parse_int("Y", argv[3], 0, height - 1, &y))
        return CLI_USAGE;
    cg_mesh *mesh;
    cg_mat4 model;
    cg_camera camera;
    if (frame_mesh(argv[1], 30, 20, (double)width / height, &mesh, &model, &camera) != CLI_OK)
        return CLI_FAILED;
    trace_run *run = trace_run_create("zbuffer", argc - 1, argv + 1,
                                      "The z-buffer at pixel (%ld, %ld) of a %dx%d frame of %s", x,
                                      y, width, height, argv[1]);
    if (!run) {
        cg_mesh_free(mesh);
        return cli_fail("trace: out of memory");
    }
    trace_note(run, "the mesh turned 30 degrees about y and 20 about x, framed as cg render "
                    "frames it; back faces culled");
    trace_note(run,
               "each triangle whose screen box holds the centre (%ld.5, %ld.5): its "
               "window x, y, depth, the centre's barycentric coordinates",
               x, y);
    trace_note(run, "a fragment when all three are >= 0; depth = the weighted vertex depths; "
                    "accepted when nearer than the buffer (initially the background)");
    cg_status status = cg_zbuffer_pixel_steps(mesh, model, &camera, width, height, (int)x, (int)y,
                                              1, cg_step_log_record, run->log);
    cg_mesh_free(mesh);
    return trace_finish(run, status, "the mesh is not valid", out);
}

/* face-loop MESH F and one-ring MESH V on the half-edge structure built
 * from the file (strict: a defect is an error, named). */
static int run_hemesh(int ring, int argc, char **argv, const trace_outputs *out)
{
    long index;
    if (argc != 3)
        return cli_usage_error("trace", "%s: expected '%s MESH %s'", argv[0], argv[0],
                               ring ? "V" : "F");
    if (trace_parse_int(ring ? "V" : "F", argv[2], 0, 4294967293L, &index))
        return CLI_USAGE;
    cg_mesh *mesh;
    cg_hemesh *hemesh;
    cg_error err;
    if (cg_mesh_load(argv[1], &mesh, &err) != CG_OK)
        return cli_fail("trace: %s", err.message);
    cg_status status = cg_hemesh_build(mesh, 0, &hemesh, NULL, &err);
    cg_mesh_free(mesh);
    if (status != CG_OK)
        return cli_fail("trace: %s: %s", argv[1], err.message);
    trace_run *run = trace_run_create(argv[0], argc - 1, argv + 1, "The %s of %s %ld in %s",
                                      ring ? "one-ring" : "loop", ring ? "vertex" : "face", index,
                                      argv[1]);
    if (!run) {
        cg_hemesh_free(hemesh);
        return cli_fail("trace: out of memory");
    }
    run->y_up = 1;
    trace_note(run, "half-edges come in twins: twin(h) = h xor 1; each knows its origin, next, "
                    "prev and face");
    if (ring)
        trace_note(run,
                   "around vertex %ld counter-clockwise: from an outgoing h, the next one "
                   "is twin(prev(h))",
                   index);
    else
        trace_note(run, "around face %ld: from its half-edge, follow next until it comes back",
                   index);
    trace_note(run, "the frames show x and y of the positions");
    status = ring
                 ? cg_hemesh_one_ring_steps(hemesh, (uint32_t)index, cg_step_log_record, run->log)
                 : cg_hemesh_face_loop_steps(hemesh, (uint32_t)index, cg_step_log_record, run->log);
    cg_hemesh_free(hemesh);
    return trace_finish(run, status, ring ? "no such vertex" : "no such face", out);
}

static int run_face_loop(int argc, char **argv, const trace_outputs *out)
{
    return run_hemesh(0, argc, argv, out);
}

static int run_one_ring(int argc, char **argv, const trace_outputs *out)
{
    return run_hemesh(1, argc, argv, out);
}

const trace_algorithm trace_view_algorithms[] = {
    {"pipeline", "X,Y,Z [EYE [TARGET [FOVY [WxH]]]]", run_pipeline},
    {"vanishing", "DX,DY,DZ [EYE [TARGET [FOVY [WxH]]]]", run_vanishing},
    {"backface", "MESH [ABOUT_Y [ABOUT_X]]", run_backface},
    {"zbuffer", "MESH X Y [WxH]", run_zbuffer},
    {"light", "POINT NORMAL EYE [LIGHT ...]", run_light},
    {"hsv", "R G B", run_hsv},
    {"hsl", "R G B", run_hsl},
    {"face-loop", "MESH F", run_face_loop},
    {"one-ring", "MESH V", run_one_ring},
    {NULL, NULL, NULL},
};
