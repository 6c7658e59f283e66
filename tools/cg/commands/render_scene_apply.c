/* The command line's options applied to a scene file (see render_scene.h):
 * each option keeps the meaning it has for a mesh, expressed in the scene's
 * terms, so that none is ignored in silence. */
#include "render_request.h"
#include "render_scene.h"

#include "cli.h"

#include <stdlib.h>

/* --light-dir: the given directional lights in place of the scene's own
 * (its ambient lights stay, as the mesh path keeps --ambient apart). */
static int replace_lights(const char *command, const cg_render_options *o, cg_scene *scene)
{
    size_t ambient = 0;
    for (size_t i = 0; i < scene->light_count; i++)
        ambient += scene->lights[i].kind == CG_LIGHT_AMBIENT;
    cg_light *lights = malloc((ambient + (size_t)o->light_count) * sizeof *lights);
    if (!lights)
        return cli_fail("%s: out of memory", command);
    size_t n = 0;
    for (size_t i = 0; i < scene->light_count; i++)
        if (scene->lights[i].kind == CG_LIGHT_AMBIENT)
            lights[n++] = scene->lights[i];
    for (int i = 0; i < o->light_count; i++) {
        double k = o->lights[i].intensity;
        lights[n++] = cg_light_directional(cg_vec3_scale(o->lights[i].direction, -1),
                                           cg_vec3_make(k, k, k));
    }
    free(scene->lights);
    scene->lights = lights;
    scene->light_count = n;
    scene->area_light_count = 0;
    return CLI_OK;
}

/* Camera options override the scene's camera as they place a mesh's: --eye
 * turns framing off, --view-from frames from its direction, --near and --far
 * set the depth range, --fov makes the
 * view perspective and --ortho parallel.  An axonometric projection fixes the
 * viewing direction itself, so a direction given by --eye or --view-from
 * turns it into a plain orthographic one. */
static void apply_camera(const render_request *r, cg_scene *scene)
{
    const render_cli_options *c = &r->trace.common;
    cg_camera *camera = &scene->camera;
    int turned = c->have_eye || r->trace.have_view_from;
    if (turned
        && (scene->projection == CG_SCENE_ISOMETRIC || scene->projection == CG_SCENE_DIMETRIC
            || scene->projection == CG_SCENE_TRIMETRIC))
        scene->projection = CG_SCENE_ORTHOGRAPHIC;
    if (c->have_target)
        camera->target = c->target;
    if (render_request_has(r, OPT_UP))
        camera->up = c->up;
    if (c->have_eye) {
        camera->eye = c->eye;
        scene->frame_camera = 0;
    }
    if (r->trace.have_view_from) {
        camera->eye = cg_vec3_add(camera->target, r->trace.view_from);
        scene->frame_camera = 1;
    }
    /* --near and --far replace the scene's (or its computed) depth range. */
    if (c->have_near) {
        camera->near = c->near;
        scene->near_given = 1;
    }
    if (c->have_far) {
        camera->far = c->far;
        scene->far_given = 1;
    }
    /* The later of --fov and --ortho wins, as for meshes. */
    if (c->ortho_height > 0) {
        if (scene->projection == CG_SCENE_PERSPECTIVE)
            scene->projection = CG_SCENE_ORTHOGRAPHIC;
        camera->orthographic = 1;
        camera->ortho_height = c->ortho_height;
    } else if (render_request_has(r, OPT_FOV)) {
        scene->projection = CG_SCENE_PERSPECTIVE;
        camera->orthographic = 0;
        camera->fovy = cg_radians(c->fov_degrees);
    }
}

/* --color, --ambient, --specular, --shininess: the surface where the file
 * names none, which in a scene is the default material (materials[0]). */
static void apply_default_material(const render_request *r, cg_scene *scene)
{
    const cg_render_options *o = &r->trace.common.render;
    cg_material *m = &scene->materials[0].surface;
    if (render_request_has(r, OPT_COLOR))
        m->color = cg_vec3_make(o->color.r, o->color.g, o->color.b);
    if (render_request_has(r, OPT_AMBIENT))
        m->ka = o->ambient;
    if (render_request_has(r, OPT_SPECULAR))
        m->ks = o->specular;
    if (render_request_has(r, OPT_SHININESS))
        m->shininess = o->shininess;
}

int render_scene_apply(const char *command, const render_request *r, cg_scene *scene)
{
    const render_cli_options *c = &r->trace.common;
    const cg_render_options *o = &c->render;
    if (render_request_has(r, OPT_ALGORITHM) || r->algorithm == RENDER_RAYTRACE) {
        if (r->algorithm == RENDER_DEPTH_SORT)
            return cli_usage_error(command, "--algorithm depth-sort: not available with a scene "
                                            "file (expected zbuffer, painter or raytrace)");
        scene->algorithm = r->algorithm == RENDER_RAYTRACE  ? CG_SCENE_RAYTRACE
                           : r->algorithm == RENDER_PAINTER ? CG_SCENE_PAINTER
                                                            : CG_SCENE_ZBUFFER;
    }
    if (c->have_size) {
        scene->width = c->size.width;
        scene->height = c->size.height;
    }
    if (c->have_shading)
        scene->shading = o->shading == CG_SHADING_FLAT      ? CG_SCENE_FLAT
                         : o->shading == CG_SHADING_GOURAUD ? CG_SCENE_GOURAUD
                                                            : CG_SCENE_PHONG;
    if (c->have_threads)
        scene->threads = o->threads;
    if (render_request_has(r, OPT_MSAA))
        scene->msaa = o->msaa;
    if (c->have_background)
        scene->background = o->background;
    if (render_request_has(r, OPT_CULL))
        scene->cull_back = o->cull == CG_CULL_BACK;
    if (render_request_has(r, OPT_WIREFRAME) || render_request_has(r, OPT_HIDDEN_LINE)
        || render_request_has(r, OPT_EDGES))
        scene->edges = (cg_scene_edges)o->edges;
    if (r->trace.have_samples)
        scene->samples = r->trace.extra.samples;
    if (r->trace.have_depth)
        scene->max_depth = r->trace.extra.depth;
    if (render_request_has(r, OPT_NO_SHADOWS))
        scene->shadows = 0;
    apply_camera(r, scene);
    apply_default_material(r, scene);
    if (render_request_has(r, OPT_LIGHT_DIR))
        return replace_lights(command, o, scene);
    return CLI_OK;
}
