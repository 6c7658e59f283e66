/* Triangle setup, between clipping and the rasterizer: the corners snapped
 * to the 1/256-pixel grid, ordered clockwise on the screen (back faces
 * culled by the sign of the area), the pixel box and 1 / area the
 * rasterizer's edge functions need; tiny triangles that cover no pixel
 * centre are dropped here.  Also cg_raster_triangle, one triangle through
 * the same edge functions and top-left rule for a caller's span function. */
#include "internal.h"

#include <string.h>

#define SUBPIXEL RENDER_SUBPIXEL
#define GUARD_BAND RENDER_GUARD_BAND
#define HALF (SUBPIXEL / 2)

/* floor(a / SUBPIXEL) for the snapped values (above -2^29): shifted to
 * non-negative first, so the division is a plain shift. */
static inline int64_t floor_subpixel(int64_t a)
{
    const int64_t offset = (int64_t)1 << 32;
    return (a + offset) / SUBPIXEL - offset / SUBPIXEL;
}

/* Triangles whose box holds at most this many pixels are tested pixel by
 * pixel at setup: the many that cover no pixel centre (in meshes whose
 * triangles are a pixel or less on the screen) then cost no binning and no
 * rasterizer setup. */
#define SMALL_BOX 4

static int covers_a_centre(const setup_triangle *t, int x0, int y0, int x1, int y1)
{
    raster_edges e;
    render_edges_at(t, x0, y0, &e);
    for (int y = y0; y < y1; y++) {
        int64_t a = e.w[0], b = e.w[1], c = e.w[2];
        for (int x = x0; x < x1; x++, a += e.step_x[0], b += e.step_x[1], c += e.step_x[2])
            if ((a | b | c) >= 0)
                return 1;
        for (int k = 0; k < 3; k++)
            e.w[k] += e.step_y[k];
    }
    return 0;
}

int render_setup_fixed(const render_corner *const v[3], int width, int height, int attribute_count,
                       int cull, setup_triangle *out)
{
    int32_t x[3] = {v[0]->x, v[1]->x, v[2]->x}, y[3] = {v[0]->y, v[1]->y, v[2]->y};
    int64_t area = (int64_t)(x[1] - x[0]) * (y[2] - y[0]) - (int64_t)(y[1] - y[0]) * (x[2] - x[0]);
    /* The camera sees front faces counter-clockwise; on the y-down screen
     * that makes this edge function negative.  The rasterizer wants it
     * positive: front faces are turned around, back faces culled or turned. */
    if (area == 0)
        return 0;
    if (area > 0 && (cull & RENDER_SETUP_CULL))
        return -1;
    int order[3] = {0, 2, 1};
    if (area > 0) {
        order[1] = 1;
        order[2] = 2;
    } else {
        area = -area;
    }
    int32_t min_x = x[0], max_x = x[0], min_y = y[0], max_y = y[0];
    for (int k = 1; k < 3; k++) {
        if (x[k] < min_x)
            min_x = x[k];
        if (x[k] > max_x)
            max_x = x[k];
        if (y[k] < min_y)
            min_y = y[k];
        if (y[k] > max_y)
            max_y = y[k];
    }
    /* Pixels whose centres p * 256 + 128 lie within the box; multisampled,
     * pixels whose square [p, p + 1) meets it (every standard sample
     * position lies in that square). */
    const int multisample = (cull & RENDER_SETUP_MULTISAMPLE) != 0;
    const int64_t half = multisample ? 0 : HALF;
    int64_t x0 = floor_subpixel((int64_t)min_x - half + (multisample ? 0 : SUBPIXEL - 1));
    int64_t x1 = floor_subpixel((int64_t)max_x - half) + 1;
    int64_t y0 = floor_subpixel((int64_t)min_y - half + (multisample ? 0 : SUBPIXEL - 1));
    int64_t y1 = floor_subpixel((int64_t)max_y - half) + 1;
    if (x0 < 0)
        x0 = 0;
    if (y0 < 0)
        y0 = 0;
    if (x1 > width)
        x1 = width;
    if (y1 > height)
        y1 = height;
    if (x0 >= x1 || y0 >= y1)
        return 0;
    for (int k = 0; k < 3; k++) {
        out->x[k] = v[order[k]]->x;
        out->y[k] = v[order[k]]->y;
    }
    if (!multisample && (x1 - x0) * (y1 - y0) <= SMALL_BOX
        && !covers_a_centre(out, (int)x0, (int)y0, (int)x1, (int)y1))
        return 0;
    for (int k = 0; k < 3; k++) {
        const render_corner *c = v[order[k]];
        out->z[k] = c->z;
        out->iw[k] = c->iw;
        for (int j = 0; j < attribute_count; j++)
            out->a[k * attribute_count + j] = c->a[j];
    }
    out->box[0] = (int32_t)x0;
    out->box[1] = (int32_t)y0;
    out->box[2] = (int32_t)x1;
    out->box[3] = (int32_t)y1;
    out->inverse_area = (float)(1.0 / (double)area);
    return 1;
}

void render_corner_from_screen(const screen_vertex *s, int width, int height, render_corner *out)
{
    out->x = render_snap(s->x, width);
    out->y = render_snap(s->y, height);
    out->z = (float)s->z;
    out->iw = (float)s->iw;
    out->a = s->a;
}

int render_setup(const screen_vertex *a, const screen_vertex *b, const screen_vertex *c, int width,
                 int height, int attribute_count, int cull, setup_triangle *out)
{
    render_corner corners[3];
    render_corner_from_screen(a, width, height, &corners[0]);
    render_corner_from_screen(b, width, height, &corners[1]);
    render_corner_from_screen(c, width, height, &corners[2]);
    const render_corner *v[3] = {&corners[0], &corners[1], &corners[2]};
    return render_setup_fixed(v, width, height, attribute_count, cull, out);
}

cg_status cg_raster_triangle(const cg_vec2 v[3], int width, int height, cg_span_fn span, void *user)
{
    if (!v || !span || width < 0 || height < 0)
        return CG_EINVAL;
    if (width > CG_RASTER_MAX_SIDE || height > CG_RASTER_MAX_SIDE)
        return CG_ERANGE;
    for (int k = 0; k < 3; k++)
        if (!isfinite(v[k].x) || !isfinite(v[k].y))
            return CG_EINVAL;
    if (width == 0 || height == 0)
        return CG_OK;
    /* Vertices beyond the guard band are first clipped to it (as points of
     * the plane w = 1); edges shared by two triangles are cut alike. */
    double hx = 0.5 * width + GUARD_BAND, hy = 0.5 * height + GUARD_BAND;
    clip_vertex in[3], polygon[RENDER_MAX_POLYGON];
    unsigned any = 0;
    for (int k = 0; k < 3; k++) {
        in[k].c[0] = (v[k].x - 0.5 * width) / hx;
        in[k].c[1] = (0.5 * height - v[k].y) / hy;
        in[k].c[2] = 0;
        in[k].c[3] = 1;
        any |= render_outcode(in[k].c);
    }
    int n = 3;
    if (any)
        n = render_clip_polygon(in, 3, 0x0f, 0, polygon);
    else
        memcpy(polygon, in, sizeof in);
    screen_vertex s[RENDER_MAX_POLYGON];
    for (int k = 0; k < n; k++) {
        if (any) {
            s[k].x = polygon[k].c[0] * hx + 0.5 * width;
            s[k].y = 0.5 * height - polygon[k].c[1] * hy;
        } else {
            s[k].x = v[k].x;
            s[k].y = v[k].y;
        }
        s[k].z = s[k].iw = 0;
    }
    for (int k = 1; k + 1 < n; k++) {
        setup_triangle t;
        if (render_setup(&s[0], &s[k], &s[k + 1], width, height, 0, 0, &t) != 1)
            continue;
        raster_edges e;
        render_edges_at(&t, t.box[0], t.box[1], &e);
        /* One covered run per row: the triangle is convex. */
        for (int y = t.box[1]; y < t.box[3]; y++) {
            int begin, end;
            render_row_span(e.w, e.step_x, t.box[2] - t.box[0], &begin, &end);
            if (begin < end)
                span(user, y, t.box[0] + begin, t.box[0] + end);
            for (int k2 = 0; k2 < 3; k2++)
                e.w[k2] += e.step_y[k2];
        }
    }
    return CG_OK;
}
