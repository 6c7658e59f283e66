/* Wireframe models and their fitted drawing. */
#include "wireframe.h"
#include "cg/draw.h"
#include "cg/xform.h"

#include <float.h>
#include <stdio.h>
#include <stdlib.h>

static const cg_vec3 cube_vertices[8] = {
    {-1.5, 0, -0.5}, {-0.5, 0, -0.5}, {-0.5, 1, -0.5}, {-1.5, 1, -0.5},
    {-1.5, 0, 0.5},  {-0.5, 0, 0.5},  {-0.5, 1, 0.5},  {-1.5, 1, 0.5},
};
static const int box_edges[12][2] = {
    {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7},
};
/* The house stands behind the cube (z from -2.25 to -0.75) so that no
 * principal view shows one on top of the other. */
static const cg_vec3 house_vertices[10] = {
    {0.5, 0, -2.25}, {1.5, 0, -2.25}, {1.5, 1, -2.25}, {0.5, 1, -2.25},   {0.5, 0, -0.75},
    {1.5, 0, -0.75}, {1.5, 1, -0.75}, {0.5, 1, -0.75}, {1.0, 1.6, -2.25}, {1.0, 1.6, -0.75},
};
static const int house_edges[17][2] = {
    {0, 1}, {1, 2}, {3, 0}, {4, 5}, {5, 6}, {7, 4}, {0, 4}, {1, 5}, {2, 6},
    {3, 7}, {3, 8}, {8, 2}, {7, 9}, {9, 6}, {8, 9}, {2, 3}, {6, 7},
};

wire_model wire_cube(void)
{
    wire_model m = {cube_vertices, 8, box_edges, 12};
    return m;
}

wire_model wire_house(void)
{
    wire_model m = {house_vertices, 10, house_edges, 17};
    return m;
}

static cg_rgba8 edge_color(cg_vec3 a, cg_vec3 b)
{
    cg_vec3 d = cg_vec3_sub(b, a);
    cg_rgba8 red = {200, 30, 30, 255}, green = {20, 150, 40, 255}, blue = {30, 60, 210, 255},
             grey = {90, 90, 90, 255};
    if (d.y == 0 && d.z == 0)
        return red;
    if (d.x == 0 && d.z == 0)
        return green;
    if (d.x == 0 && d.y == 0)
        return blue;
    return grey;
}

/* Calls emit for each edge of the models projected by transform and fitted
 * to a width x height picture, in pixels (y down), with its colour. */
typedef void wire_emit(void *user, int x0, int y0, int x1, int y1, cg_rgba8 color);
static cg_status wire_edges(int width, int height, const wire_model *models, int model_count,
                            cg_mat4 transform, wire_emit *emit, void *user)
{
    double min_x = DBL_MAX, min_y = DBL_MAX, max_x = -DBL_MAX, max_y = -DBL_MAX;
    for (int m = 0; m < model_count; m++) {
        for (int i = 0; i < models[m].vertex_count; i++) {
            int visible;
            cg_vec3 p = cg_project_point(transform, models[m].vertices[i], &visible);
            if (!visible)
                return CG_EINVAL;
            min_x = fmin(min_x, p.x);
            max_x = fmax(max_x, p.x);
            min_y = fmin(min_y, p.y);
            max_y = fmax(max_y, p.y);
        }
    }
    double margin = 0.08 * fmin(width, height);
    double sx = (width - 2 * margin) / fmax(max_x - min_x, 1e-9);
    double sy = (height - 2 * margin) / fmax(max_y - min_y, 1e-9);
    double s = fmin(sx, sy);
    double ox = (width - s * (max_x - min_x)) / 2, oy = (height - s * (max_y - min_y)) / 2;
    for (int m = 0; m < model_count; m++) {
        for (int e = 0; e < models[m].edge_count; e++) {
            cg_vec3 a = models[m].vertices[models[m].edges[e][0]];
            cg_vec3 b = models[m].vertices[models[m].edges[e][1]];
            cg_vec3 pa = cg_project_point(transform, a, NULL),
                    pb = cg_project_point(transform, b, NULL);
            /* Image y grows downward, projected y upward. */
            int x0 = (int)lround(ox + s * (pa.x - min_x)),
                y0 = (int)lround(oy + s * (max_y - pa.y));
            int x1 = (int)lround(ox + s * (pb.x - min_x)),
                y1 = (int)lround(oy + s * (max_y - pb.y));
            emit(user, x0, y0, x1, y1, edge_color(a, b));
        }
    }
    return CG_OK;
}

static void draw_edge(void *user, int x0, int y0, int x1, int y1, cg_rgba8 color)
{
    cg_draw_line(user, x0, y0, x1, y1, color);
}

cg_status wire_draw(cg_image *image, const wire_model *models, int model_count, cg_mat4 transform)
{
    return wire_edges(image->width, image->height, models, model_count, transform, draw_edge,
                      image);
}

#include "script_pictures.h"

#include <string.h>

static void script_edge(void *user, int x0, int y0, int x1, int y1, cg_rgba8 color)
{
    script_add(user, "color #%02x%02x%02x\nline %d %d %d %d\n", color.r, color.g, color.b, x0, y0,
               x1, y1);
}

/* The projection is computed in C; each picture is the draw script of its
 * projected edges, written next to it, so its caption is `cg draw`. */
int wire_render_views(struct demo_context *context, const wire_view *views, int count)
{
    wire_model models[2] = {wire_cube(), wire_house()};
    for (int i = 0; i < count; i++) {
        script_text script = {.length = 0};
        script_add(&script, "size 360 270\nbackground #ffffff\n");
        if (wire_edges(360, 270, models, 2, views[i].transform, script_edge, &script) != CG_OK)
            return 1;
        char name[256];
        snprintf(name, sizeof name, "%.*s", (int)(strlen(views[i].file) - strlen(".png")),
                 views[i].file);
        if (draw_demo_script(context, name, script.text, views[i].caption) != 0)
            return 1;
    }
    return 0;
}
