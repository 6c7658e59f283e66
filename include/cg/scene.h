/* cg/scene.h - scene files: a JSON description of an image, a camera (any
 * projection of cg/xform.h), lights, materials and objects (mesh files,
 * spheres, planes, boxes, each with a list of transformations), the
 * visible-surface algorithm and shading, and 2D overlays in the `cg draw`
 * script language.  The format is documented in docs/scene-format.md.
 *
 * A scene renders with the z-buffer, the painter's algorithm or the ray
 * tracer; cg_scene_render picks the one the scene asks for (or another). */
#ifndef CG_SCENE_H
#define CG_SCENE_H

#include "cg/core.h"
#include "cg/image.h"
#include "cg/light.h"
#include "cg/mesh.h"
#include "cg/render.h"
#include "cg/trace.h"
#include "cg/xform.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Limits that keep a hostile file from asking for absurd work. */
#define CG_SCENE_MAX_SIDE 16384 /* image width and height */
#define CG_SCENE_MAX_OBJECTS 10000
#define CG_SCENE_MAX_LIGHTS 64
#define CG_SCENE_MAX_TRANSFORMS 256 /* steps in one object's transform list */
#define CG_SCENE_MAX_OVERLAYS 100000

typedef enum cg_scene_projection {
    CG_SCENE_PERSPECTIVE = 0,
    CG_SCENE_ORTHOGRAPHIC,
    CG_SCENE_ISOMETRIC,
    CG_SCENE_DIMETRIC,
    CG_SCENE_TRIMETRIC,
    CG_SCENE_CAVALIER,
    CG_SCENE_CABINET,
    CG_SCENE_OBLIQUE
} cg_scene_projection;

typedef enum cg_scene_algorithm {
    CG_SCENE_ZBUFFER = 0,
    CG_SCENE_PAINTER,
    CG_SCENE_RAYTRACE
} cg_scene_algorithm;

typedef enum cg_scene_shading {
    CG_SCENE_FLAT = 0,
    CG_SCENE_GOURAUD,
    CG_SCENE_PHONG
} cg_scene_shading;

typedef enum cg_scene_edges {
    CG_SCENE_EDGES_NONE = 0,
    CG_SCENE_EDGES_WIREFRAME,
    CG_SCENE_EDGES_HIDDEN_LINE,
    CG_SCENE_EDGES_OVERLAY
} cg_scene_edges;

typedef enum cg_scene_object_kind {
    CG_SCENE_MESH = 0,
    CG_SCENE_SPHERE,
    CG_SCENE_PLANE,
    CG_SCENE_BOX
} cg_scene_object_kind;

typedef struct cg_scene_material {
    char *name;
    cg_material surface;   /* colour, ka, kd, ks, shininess, reflectance, ... */
    cg_vec3 checker_color; /* second colour of a 3D checker (ray tracer) */
    double checker_size;   /* 0: plain */
    cg_vec3 emission;      /* emitted radiance (ray tracers), linear; 0: none */
} cg_scene_material;

typedef struct cg_scene_object {
    cg_scene_object_kind kind;
    char *file;        /* mesh: the path as resolved against the scene's folder */
    cg_mesh *mesh;     /* mesh: loaded by cg_scene_load */
    cg_vec3 center;    /* sphere */
    double radius;     /* sphere */
    cg_vec3 point;     /* plane */
    cg_vec3 normal;    /* plane */
    cg_vec3 lo, hi;    /* box */
    cg_mat4 transform; /* the composed transform list (identity when none) */
    size_t material;   /* index into materials */
} cg_scene_object;

/* A rectangular light for soft shadows (ray tracer). */
typedef struct cg_scene_area_light {
    cg_vec3 corner, edge_u, edge_v, color;
    int samples;
} cg_scene_area_light;

/* A scene's keyframes (the key "animation"), posed by cg_scene_set_frame. */
typedef struct cg_scene_animation cg_scene_animation;

typedef struct cg_scene {
    int width, height;
    cg_rgbaf background; /* linear light */

    cg_camera camera;          /* eye, target, up, fovy or ortho_height, near, far */
    int frame_camera;          /* move the eye so the whole scene fits (keeps direction) */
    int near_given, far_given; /* camera.near / far came from the file; otherwise they
                                     enclose the scene's depth range along the view */
    cg_scene_projection projection;
    double projection_angle;  /* trimetric: about y; oblique: direction of depth (radians) */
    double projection_angle2; /* trimetric: about x (radians) */
    double projection_ratio;  /* dimetric: z ratio; oblique: depth foreshortening */

    cg_scene_algorithm algorithm;
    cg_scene_shading shading;
    int cull_back; /* back-face culling (rasterizer) */
    cg_scene_edges edges;
    int threads;
    int samples;   /* ray tracer: samples per pixel */
    int max_depth; /* ray tracer: recursion limit */
    int shadows;   /* ray tracer: shadow rays */
    int msaa;      /* z-buffer: samples per pixel, 1, 2, 4, 8 or 16 */

    cg_light *lights;
    size_t light_count;
    cg_scene_area_light *area_lights;
    size_t area_light_count;
    cg_scene_material *materials; /* materials[0] is the default material */
    size_t material_count;
    cg_scene_object *objects;
    size_t object_count;
    char **overlays; /* `cg draw` script lines drawn over the picture */
    size_t overlay_count;

    /* The path tracer's sky, the key "environment": an equirectangular
     * file (resolved against the scene's folder, loaded as linear light
     * with the meshes: 8-bit files are decoded from sRGB) times intensity,
     * or a uniform colour.  Without the key (environment_given 0) the sky
     * is the background colour.  The other renderers ignore it. */
    int environment_given;
    char *environment_file;
    cg_image *environment_map;    /* NULL for a colour, or when files are not loaded */
    double environment_intensity; /* default 1 */
    cg_vec3 environment_color;    /* when there is no file */
    /* Keyframes: NULL and frame_count 0 for a still scene; else frames
     * 0 to frame_count - 1 (the key's "frames", or up to its last key). */
    cg_scene_animation *animation;
    int frame_count;
} cg_scene;

/* Reads a scene file and loads the mesh files it names (paths relative to
 * the scene file's folder).  Errors name the JSON path and what was expected,
 * e.g. "scene.json: camera.fov: expected a number between 1 and 179, got
 * \"wide\""; unknown keys are errors too; a mesh that fails to load gives the
 * mesh reader's message. */
cg_status cg_scene_load(const char *path, cg_scene **out, cg_error *err);
/* The same from text (size bytes, need not end in NUL); name is used in
 * messages and base_dir (may be NULL: the current folder) for mesh paths.
 * load_meshes 0 skips reading mesh files (for validation and fuzzing). */
cg_status cg_scene_parse(const char *text, size_t size, const char *name, const char *base_dir,
                         int load_meshes, cg_scene **out, cg_error *err);
void cg_scene_free(cg_scene *scene);

/* Poses an animated scene at frame (any finite number; frames between keys
 * are interpolated, linearly or by a Catmull-Rom spline through the keys,
 * and the first and last keys hold before and after them): each animated
 * value is written, the rest left as they are.  Camera values (eye, target,
 * up, fov) are written as the keys give them; an object's placement is
 * translate * rotate (about x, then y, then z, degrees) * scale applied
 * after the file's transform list; a light's colour is the file's times the
 * animated intensity (unless the lights have been replaced since).  Poses
 * do not accumulate.  CG_OK and nothing changed for a still scene;
 * CG_EINVAL for NULL or a non-finite frame. */
cg_status cg_scene_set_frame(cg_scene *scene, double frame);

/* Renders the scene into a new RGBA8 image of its size, with the scene's
 * algorithm.  Overlays are not drawn (the cg tool draws them with its script
 * interpreter).  CG_EUNSUPPORTED when the ray tracer is asked for an oblique
 * projection (its rays would not be perpendicular to the image plane); the
 * rasterizer draws every projection. */
cg_status cg_scene_render(const cg_scene *scene, cg_image **out, cg_error *err);
/* The same with another algorithm than the scene's. */
cg_status cg_scene_render_with(const cg_scene *scene, cg_scene_algorithm algorithm, cg_image **out,
                               cg_error *err);

/* The pieces the rasterizer gets, for programs that render a scene many
 * times (the viewer): every object as one world-space mesh with per-face
 * colours from the materials (spheres and boxes tessellated, planes as a
 * large square around the scene), and the renderer options for the scene's
 * camera, lights and settings with the given algorithm (zbuffer or painter). */
cg_status cg_scene_world_mesh(const cg_scene *scene, cg_mesh **out, cg_error *err);
/* The ray tracers' pieces: every object with its material and every light
 * in a new cg/trace.h scene, and the scene's camera (its near and far open
 * for planes, as the ray tracer draws them).  default_lights 1 adds the
 * rasterizer's key light and a white ambient light when the file gives no
 * light (what the Whitted ray tracer does); the path tracer passes 0, its
 * sky lighting such scenes.  CG_EUNSUPPORTED for oblique projections. */
cg_status cg_scene_trace_scene(const cg_scene *scene, int default_lights, cg_trace_scene **out,
                               cg_camera *camera, cg_error *err);
cg_status cg_scene_raster_options(const cg_scene *scene, cg_scene_algorithm algorithm,
                                  cg_render_options *options, cg_error *err);

#ifdef __cplusplus
}
#endif
#endif
