/* Preparing a mesh for rendering: the shared triangulation of its faces
 * (cg_mesh_triangulate), angle-weighted vertex normals with a crease angle,
 * vertices split where normals or colours differ between the faces around
 * them. */
#include "pipeline.h"
#include "cg/color.h"

#include <stdlib.h>
#include <string.h>

/* Newell's normal of face f (robust for non-planar polygons), unit or zero. */
static cg_vec3 face_normal(const cg_mesh *mesh, size_t f)
{
    uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
    cg_vec3 n = {0, 0, 0};
    for (uint32_t k = begin; k < end; k++) {
        cg_vec3 a = mesh->positions[mesh->face_indices[k]];
        cg_vec3 b = mesh->positions[mesh->face_indices[k + 1 < end ? k + 1 : begin]];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    double length = cg_vec3_length(n);
    if (!(length > 0) || !isfinite(length))
        return cg_vec3_make(0, 0, 0);
    return cg_vec3_scale(n, 1 / length);
}

/* Interior angle of face f at corner k. */
static double corner_angle(const cg_mesh *mesh, size_t f, uint32_t k)
{
    uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
    cg_vec3 p = mesh->positions[mesh->face_indices[k]];
    cg_vec3 prev = mesh->positions[mesh->face_indices[k > begin ? k - 1 : end - 1]];
    cg_vec3 next = mesh->positions[mesh->face_indices[k + 1 < end ? k + 1 : begin]];
    cg_vec3 u = cg_vec3_sub(prev, p), v = cg_vec3_sub(next, p);
    double angle = atan2(cg_vec3_length(cg_vec3_cross(u, v)), cg_vec3_dot(u, v));
    return isfinite(angle) ? angle : 0;
}

/* Corner-to-face map and vertex-to-corner lists (CSR). */
typedef struct incidence {
    uint32_t *corner_face;   /* corners */
    uint32_t *vertex_start;  /* vertex_count + 1 */
    uint32_t *vertex_corner; /* corners */
} incidence;

static void incidence_free(incidence *in)
{
    free(in->corner_face);
    free(in->vertex_start);
    free(in->vertex_corner);
}

static cg_status incidence_build(const cg_mesh *mesh, incidence *in)
{
    size_t corners = mesh->face_offsets[mesh->face_count];
    in->corner_face = malloc((corners ? corners : 1) * sizeof *in->corner_face);
    in->vertex_start = calloc(mesh->vertex_count + 1, sizeof *in->vertex_start);
    in->vertex_corner = malloc((corners ? corners : 1) * sizeof *in->vertex_corner);
    if (!in->corner_face || !in->vertex_start || !in->vertex_corner) {
        incidence_free(in);
        return CG_ENOMEM;
    }
    for (size_t f = 0; f < mesh->face_count; f++)
        for (uint32_t k = mesh->face_offsets[f]; k < mesh->face_offsets[f + 1]; k++)
            in->corner_face[k] = (uint32_t)f;
    for (size_t k = 0; k < corners; k++)
        in->vertex_start[mesh->face_indices[k] + 1]++;
    for (size_t v = 0; v < mesh->vertex_count; v++)
        in->vertex_start[v + 1] += in->vertex_start[v];
    uint32_t *fill = malloc((mesh->vertex_count ? mesh->vertex_count : 1) * sizeof *fill);
    if (!fill) {
        incidence_free(in);
        return CG_ENOMEM;
    }
    memcpy(fill, in->vertex_start, mesh->vertex_count * sizeof *fill);
    for (size_t k = 0; k < corners; k++)
        in->vertex_corner[fill[mesh->face_indices[k]]++] = (uint32_t)k;
    free(fill);
    return CG_OK;
}

/* Normals of every corner into out, given the face normals and angles. */
static void corner_normals(const cg_mesh *mesh, const incidence *in, const cg_vec3 *faces,
                           const double *angles, double cos_crease, cg_vec3 *out)
{
    for (size_t v = 0; v < mesh->vertex_count; v++) {
        for (uint32_t i = in->vertex_start[v]; i < in->vertex_start[v + 1]; i++) {
            uint32_t corner = in->vertex_corner[i];
            cg_vec3 own = faces[in->corner_face[corner]], sum = {0, 0, 0};
            if (own.x != 0 || own.y != 0 || own.z != 0) {
                /* Summed in the same order for every corner of the vertex, so
                 * corners in one smooth region get identical normals. */
                for (uint32_t j = in->vertex_start[v]; j < in->vertex_start[v + 1]; j++) {
                    uint32_t other = in->vertex_corner[j];
                    cg_vec3 n = faces[in->corner_face[other]];
                    if (cg_vec3_dot(n, own) >= cos_crease)
                        sum = cg_vec3_add(sum, cg_vec3_scale(n, angles[other]));
                }
            }
            out[corner] = cg_vec3_normalize(sum);
        }
    }
}

static cg_status compute_corner_normals(const cg_mesh *mesh, double crease_angle, cg_vec3 *out)
{
    size_t corners = mesh->face_offsets[mesh->face_count];
    incidence in;
    cg_status status = incidence_build(mesh, &in);
    if (status != CG_OK)
        return status;
    cg_vec3 *faces = malloc((mesh->face_count ? mesh->face_count : 1) * sizeof *faces);
    double *angles = malloc((corners ? corners : 1) * sizeof *angles);
    if (!faces || !angles) {
        free(faces);
        free(angles);
        incidence_free(&in);
        return CG_ENOMEM;
    }
    for (size_t f = 0; f < mesh->face_count; f++) {
        faces[f] = face_normal(mesh, f);
        for (uint32_t k = mesh->face_offsets[f]; k < mesh->face_offsets[f + 1]; k++)
            angles[k] = corner_angle(mesh, f, k);
    }
    /* A tiny tolerance so that a crease angle of exactly the angle between
     * two faces keeps them together. */
    double cos_crease = cos(crease_angle) - 1e-12;
    corner_normals(mesh, &in, faces, angles, cos_crease, out);
    free(faces);
    free(angles);
    incidence_free(&in);
    return CG_OK;
}

cg_status cg_mesh_corner_normals(const cg_mesh *mesh, double crease_angle,
                                 cg_vec3 *corner_normals_out)
{
    if (!mesh || !corner_normals_out || !(crease_angle >= 0))
        return CG_EINVAL;
    cg_status status = cg_mesh_validate_topology(mesh, NULL);
    if (status != CG_OK)
        return status;
    return compute_corner_normals(mesh, crease_angle, corner_normals_out);
}

/* Twice the area of a triangle of corner numbers (0 when not finite). */
static double corner_triangle_area(const cg_mesh *mesh, const uint32_t corners[3])
{
    cg_vec3 a = mesh->positions[mesh->face_indices[corners[0]]];
    cg_vec3 b = mesh->positions[mesh->face_indices[corners[1]]];
    cg_vec3 c = mesh->positions[mesh->face_indices[corners[2]]];
    double area = cg_vec3_length(cg_vec3_cross(cg_vec3_sub(b, a), cg_vec3_sub(c, a)));
    return isfinite(area) ? area : 0;
}

static void to_float3(cg_vec3 v, float out[3])
{
    out[0] = (float)v.x;
    out[1] = (float)v.y;
    out[2] = (float)v.z;
}

/* The base colour of corner k of face f. */
static void corner_color(const cg_mesh *mesh, const cg_render_options *options, size_t f,
                         uint32_t k, float out[3])
{
    cg_rgbaf c = options->color;
    uint32_t material = mesh->face_materials ? mesh->face_materials[f] : CG_MESH_NO_MATERIAL;
    if (mesh->face_colors && mesh->face_colors[f].a > 0) {
        c = mesh->face_colors[f]; /* alpha 0: the file gives this face no colour */
    } else if (material < mesh->material_count && mesh->materials) {
        c = mesh->materials[material].base_color;
        if (mesh->colors) {
            cg_rgbaf v = mesh->colors[mesh->face_indices[k]];
            c.r *= v.r, c.g *= v.g, c.b *= v.b;
        }
    }
    if (mesh->colors && !(material < mesh->material_count && mesh->materials))
        c = mesh->colors[mesh->face_indices[k]];
    out[0] = c.r;
    out[1] = c.g;
    out[2] = c.b;
}

static int same_vertex(const prepared_vertex *a, const float normal[3], const float color[3])
{
    return memcmp(a->normal, normal, sizeof a->normal) == 0
           && memcmp(a->color, color, sizeof a->color) == 0;
}

static cg_status check_options(const cg_render_options *o)
{
    if (!o || o->threads < 1 || o->threads > 64 || o->light_count < 0
        || o->light_count > CG_RENDER_MAX_LIGHTS || !(o->crease_angle >= 0) || !isfinite(o->ambient)
        || !isfinite(o->specular) || !isfinite(o->shininess)
        || (unsigned)o->algorithm > CG_RENDER_DEPTH_SORT || (unsigned)o->shading > CG_SHADING_UNLIT
        || (unsigned)o->texture_filter > CG_TEXTURE_TRILINEAR || (unsigned)o->cull > CG_CULL_BACK
        || (unsigned)o->edges > CG_EDGES_OVERLAY)
        return CG_EINVAL;
    if (o->msaa != 0 && o->msaa != 1 && o->msaa != 2 && o->msaa != 4 && o->msaa != 8
        && o->msaa != 16)
        return CG_EINVAL;
    if (o->msaa > 1 && o->algorithm != CG_RENDER_ZBUFFER)
        return CG_EINVAL;
    if (o->shadows != 0 && o->shadows != 1)
        return CG_EINVAL;
    for (int i = 0; i < o->light_count; i++)
        if (!(cg_vec3_length(o->lights[i].direction) > 0)
            || !isfinite(cg_vec3_length(o->lights[i].direction)) || !(o->lights[i].intensity >= 0)
            || !isfinite(o->lights[i].intensity))
            return CG_EINVAL;
    return CG_OK;
}

void cg_render_options_default(cg_render_options *o)
{
    if (!o)
        return;
    memset(o, 0, sizeof *o);
    o->camera = cg_camera_default();
    o->frame_camera = 1;
    o->model = cg_mat4_identity();
    o->algorithm = CG_RENDER_ZBUFFER;
    o->shading = CG_SHADING_GOURAUD;
    o->cull = CG_CULL_BACK;
    o->edges = CG_EDGES_NONE;
    o->threads = 1;
    o->background = (cg_rgbaf){0.012f, 0.014f, 0.02f, 1};
    o->color = (cg_rgbaf){0.55f, 0.55f, 0.55f, 1};
    o->edge_color = (cg_rgbaf){0.9f, 0.9f, 0.9f, 1};
    o->ambient = 0.15;
    o->specular = 0.25;
    o->shininess = 32;
    o->light_count = 0;
    o->crease_angle = cg_radians(60);
    o->texture_filter = CG_TEXTURE_TRILINEAR;
    o->msaa = 1;
}

cg_status cg_renderer_set_options(cg_renderer *renderer, const cg_render_options *options)
{
    if (!renderer)
        return CG_EINVAL;
    cg_status status = check_options(options);
    if (status != CG_OK)
        return status;
    renderer->options = *options;
    return CG_OK;
}

void cg_renderer_free(cg_renderer *r)
{
    if (!r)
        return;
    free(r->vertices);
    free(r->triangles);
    free(r->triangle_face);
    free(r->face_triangle);
    free(r->edges);
    free(r->depth);
    render_materials_free(r);
    render_buffers_free(r);
    free(r);
}

/* Split vertices: corners of one vertex share a prepared vertex when their
 * normal and colour agree exactly.  The prepared vertex of each corner goes
 * to corner_vertex. */
static void split_vertices(const cg_mesh *mesh, const cg_render_options *options,
                           const incidence *in, const cg_vec3 *normals, cg_renderer *r,
                           uint32_t *corner_vertex)
{
    size_t count = 0;
    float first_color[3] = {0, 0, 0};
    for (size_t v = 0; v < mesh->vertex_count; v++) {
        size_t first = count;
        float position[3];
        to_float3(mesh->positions[v], position);
        for (uint32_t i = in->vertex_start[v]; i < in->vertex_start[v + 1]; i++) {
            uint32_t k = in->vertex_corner[i];
            float normal[3], color[3];
            to_float3(normals[k], normal);
            corner_color(mesh, options, in->corner_face[k], k, color);
            if (count == 0)
                memcpy(first_color, color, sizeof color);
            else if (memcmp(first_color, color, sizeof color) != 0)
                r->varying_color = 1;
            size_t found = count;
            for (size_t j = first; j < count; j++)
                if (same_vertex(&r->vertices[j], normal, color)) {
                    found = j;
                    break;
                }
            if (found == count) {
                r->vertices[count].uv[0] = mesh->texcoords ? (float)mesh->texcoords[v].x : 0;
                r->vertices[count].uv[1] = mesh->texcoords ? (float)mesh->texcoords[v].y : 0;
                memcpy(r->vertices[count].position, position, sizeof position);
                memcpy(r->vertices[count].normal, normal, sizeof normal);
                memcpy(r->vertices[count].color, color, sizeof color);
                count++;
            }
            corner_vertex[k] = (uint32_t)found;
        }
    }
    r->vertex_count = count;
}

/* The triangles (of corner numbers until now) and the edges of each face
 * in prepared vertices, the face of each triangle, and each face's
 * triangle of largest area. */
static void index_faces(const cg_mesh *mesh, const uint32_t *corner_vertex, cg_renderer *r)
{
    size_t t = 0, e = 0;
    for (size_t f = 0; f < mesh->face_count; f++) {
        uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
        double largest = -1;
        for (uint32_t k = begin + 2; k < end; k++, t++) {
            double area = corner_triangle_area(mesh, r->triangles[t]);
            if (area > largest) {
                largest = area;
                r->face_triangle[f] = (uint32_t)t;
            }
            for (int j = 0; j < 3; j++)
                r->triangles[t][j] = corner_vertex[r->triangles[t][j]];
            r->triangle_face[t] = (uint32_t)f;
        }
        for (uint32_t k = begin; k < end; k++) {
            r->edges[e][0] = corner_vertex[k];
            r->edges[e][1] = corner_vertex[k + 1 < end ? k + 1 : begin];
            r->edges[e++][2] = (uint32_t)f;
        }
    }
    r->edge_count = e;
}

cg_status cg_renderer_create(const cg_mesh *mesh, const cg_render_options *options,
                             cg_renderer **out, cg_error *err)
{
    if (!out)
        return cg_error_set(err, CG_EINVAL, "render: no place for the renderer");
    *out = NULL;
    if (!mesh)
        return cg_error_set(err, CG_EINVAL, "render: no mesh given");
    if (check_options(options) != CG_OK)
        return cg_error_set(err, CG_EINVAL, "render: invalid options");
    cg_status status = cg_mesh_validate_topology(mesh, err);
    if (status != CG_OK)
        return status;
    cg_renderer *r = calloc(1, sizeof *r);
    if (!r)
        return cg_error_set(err, CG_ENOMEM, "render: out of memory");
    r->options = *options;
    r->camera = options->camera;
    r->face_count = mesh->face_count;
    r->has_bounds = cg_mesh_bounds(mesh, &r->lo, &r->hi) == CG_OK;
    size_t corners = mesh->face_offsets[mesh->face_count];
    r->triangle_count = cg_mesh_triangle_count(mesh);
    cg_vec3 *normals = malloc((corners ? corners : 1) * sizeof *normals);
    uint32_t *corner_vertex = malloc((corners ? corners : 1) * sizeof *corner_vertex);
    r->vertices = malloc((corners ? corners : 1) * sizeof *r->vertices);
    r->triangles = malloc((r->triangle_count ? r->triangle_count : 1) * sizeof *r->triangles);
    r->triangle_face = malloc((r->triangle_count ? r->triangle_count : 1) * sizeof(uint32_t));
    r->face_triangle = malloc((mesh->face_count ? mesh->face_count : 1) * sizeof(uint32_t));
    r->edges = malloc((corners ? corners : 1) * sizeof *r->edges);
    incidence in = {0};
    if (!normals || !corner_vertex || !r->vertices || !r->triangles || !r->triangle_face
        || !r->face_triangle || !r->edges || incidence_build(mesh, &in) != CG_OK) {
        free(normals);
        free(corner_vertex);
        cg_renderer_free(r);
        return cg_error_set(err, CG_ENOMEM, "render: out of memory preparing %zu faces",
                            mesh->face_count);
    }
    /* Triangles of corner numbers, turned into prepared vertices below. */
    if (cg_mesh_triangulate(mesh, r->triangles) != CG_OK) {
        free(normals);
        free(corner_vertex);
        incidence_free(&in);
        cg_renderer_free(r);
        return cg_error_set(err, CG_ENOMEM, "render: out of memory triangulating %zu faces",
                            mesh->face_count);
    }
    if (mesh->normals) {
        for (size_t k = 0; k < corners; k++)
            normals[k] = cg_vec3_normalize(mesh->normals[mesh->face_indices[k]]);
    } else if ((status = compute_corner_normals(mesh, options->crease_angle, normals)) != CG_OK) {
        free(normals);
        free(corner_vertex);
        incidence_free(&in);
        cg_renderer_free(r);
        return cg_error_set(err, status, "render: out of memory computing normals");
    }
    split_vertices(mesh, options, &in, normals, r, corner_vertex);
    index_faces(mesh, corner_vertex, r);
    free(normals);
    free(corner_vertex);
    incidence_free(&in);
    if (render_materials_load(r, mesh) != CG_OK) {
        cg_renderer_free(r);
        return cg_error_set(err, CG_ENOMEM, "render: out of memory reading the materials");
    }
    *out = r;
    return CG_OK;
}

const float *cg_renderer_depth(const cg_renderer *renderer)
{
    return renderer && renderer->depth_valid ? renderer->depth : NULL;
}

cg_status cg_renderer_depth_image(const cg_renderer *r, cg_image *image)
{
    if (!r || !r->depth_valid || !image || !image->data || image->width != r->depth_width
        || image->height != r->depth_height)
        return CG_EINVAL;
    size_t pixels = (size_t)image->width * (size_t)image->height;
    float lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < pixels; i++)
        if (isfinite(r->depth[i])) {
            lo = r->depth[i] < lo ? r->depth[i] : lo;
            hi = r->depth[i] > hi ? r->depth[i] : hi;
        }
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++) {
            float d = r->depth[(size_t)y * image->width + x];
            uint8_t v = 0;
            if (isfinite(d))
                v = (uint8_t)(235 - (hi > lo ? 200 * (d - lo) / (hi - lo) : 0));
            cg_rgba8 grey = {v, v, v, 255};
            if (image->format == CG_PIXEL_RGBA8)
                cg_image_set_rgba8(image, x, y, grey);
            else
                cg_image_set(image, x, y, cg_rgba8_to_linear(grey));
        }
    return CG_OK;
}

cg_render_stats cg_renderer_stats(const cg_renderer *renderer)
{
    cg_render_stats none = {0};
    return renderer ? renderer->stats : none;
}

cg_camera cg_renderer_camera(const cg_renderer *renderer)
{
    return renderer ? renderer->camera : cg_camera_default();
}

cg_status cg_render(const cg_mesh *mesh, const cg_render_options *options, cg_image *image,
                    cg_error *err)
{
    cg_renderer *r;
    cg_status status = cg_renderer_create(mesh, options, &r, err);
    if (status != CG_OK)
        return status;
    status = cg_renderer_draw(r, image);
    if (status != CG_OK)
        cg_error_set(err, status, "render: %s", cg_status_str(status));
    cg_renderer_free(r);
    return status;
}
