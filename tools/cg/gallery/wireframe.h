/* Wireframe models and drawing, shared by the gallery sections on
 * projections and transformations. */
#ifndef CG_TOOL_WIREFRAME_H
#define CG_TOOL_WIREFRAME_H

#include "cg/core.h"
#include "cg/image.h"

typedef struct wire_model {
    const cg_vec3 *vertices;
    int vertex_count;
    const int (*edges)[2];
    int edge_count;
} wire_model;

/* A unit cube centred at the origin and a house (a box with a gable roof)
 * beside it: together they show every projection's behaviour. */
wire_model wire_cube(void);
wire_model wire_house(void);

/* Projects the models with transform (divided by w) and draws them scaled to
 * fit the image with a margin, edges coloured by direction: x red, y green,
 * z blue, others grey.  Returns CG_EINVAL when a vertex is behind the camera. */
cg_status wire_draw(cg_image *image, const wire_model *models, int model_count, cg_mat4 transform);

#endif

/* One gallery picture of the cube and house seen through a transform. */
typedef struct wire_view {
    const char *file, *caption;
    cg_mat4 transform;
} wire_view;

/* Writes each view as a draw script of its edges in a 360 x 270 picture
 * (FILE with .draw for .png) in the gallery folder and adds the picture it
 * draws, with the caption's command `cg draw`; returns 0 or non-zero. */
struct demo_context;
int wire_render_views(struct demo_context *context, const wire_view *views, int count);
