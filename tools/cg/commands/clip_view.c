/* WKT polygons and drawing for `cg clip` and the clipping gallery. */
#include "clip_view.h"

#include "cg/fill.h"
#include "../../../src/core/array.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

typedef struct wkt {
    const char *s, *name;
    size_t pos;
    cg_error *err;
} wkt;

static void skip_space(wkt *w)
{
    while (isspace((unsigned char)w->s[w->pos]))
        w->pos++;
}

static cg_status fail(wkt *w, const char *what)
{
    return cg_error_set(w->err, CG_EFORMAT, "%s: offset %zu: expected %s", w->name, w->pos, what);
}

static int accept_char(wkt *w, char c)
{
    skip_space(w);
    if (w->s[w->pos] == c) {
        w->pos++;
        return 1;
    }
    return 0;
}

static int accept_word(wkt *w, const char *word)
{
    skip_space(w);
    size_t n = strlen(word);
    if (strncasecmp(w->s + w->pos, word, n) == 0 && !isalnum((unsigned char)w->s[w->pos + n])) {
        w->pos += n;
        return 1;
    }
    return 0;
}

static int number(wkt *w, double *out)
{
    skip_space(w);
    char *end;
    const char *start = w->s + w->pos;
    if (!(isdigit((unsigned char)*start) || *start == '-' || *start == '+' || *start == '.'))
        return 0;
    *out = strtod(start, &end);
    if (end == start)
        return 0;
    w->pos += (size_t)(end - start);
    return 1;
}

static cg_status ring(wkt *w, cg_polygon_set *set)
{
    if (!accept_char(w, '('))
        return fail(w, "'(' opening a ring");
    cg_vec2 *pts = NULL;
    size_t n = 0, cap = 0;
    cg_status st = CG_OK;
    do {
        double x, y;
        if (!number(w, &x) || !number(w, &y)) {
            st = fail(w, "a coordinate pair 'X Y'");
            goto done;
        }
        skip_space(w);
        if (isdigit((unsigned char)w->s[w->pos]) || w->s[w->pos] == '-') {
            st = fail(w, "',' or ')' (only 2D coordinates are read)");
            goto done;
        }
        if (!isfinite(x) || !isfinite(y)) {
            st = cg_error_set(w->err, CG_EINVAL, "%s: offset %zu: coordinate is not finite",
                              w->name, w->pos);
            goto done;
        }
        if (core_array_reserve((void **)&pts, &cap, n + 1, sizeof *pts) != CG_OK) {
            st = cg_error_set(w->err, CG_ENOMEM, "%s: out of memory", w->name);
            goto done;
        }
        pts[n++] = cg_vec2_make(x, y);
    } while (accept_char(w, ','));
    if (!accept_char(w, ')')) {
        st = fail(w, "',' or ')' closing a ring");
        goto done;
    }
    if (n > 1 && pts[0].x == pts[n - 1].x && pts[0].y == pts[n - 1].y)
        n--;
    st = cg_polygon_set_add_ring(set, pts, n, 1);
done:
    free(pts);
    return st;
}

static cg_status polygon_body(wkt *w, cg_polygon_set *set)
{
    if (accept_word(w, "EMPTY"))
        return CG_OK;
    if (!accept_char(w, '('))
        return fail(w, "'(' or EMPTY");
    do {
        cg_status st = ring(w, set);
        if (st != CG_OK)
            return st;
    } while (accept_char(w, ','));
    if (!accept_char(w, ')'))
        return fail(w, "',' or ')' closing a polygon");
    return CG_OK;
}

cg_status clip_wkt_parse(const char *text, const char *name, cg_polygon_set *set, cg_error *err)
{
    wkt w = {text, name, 0, err};
    cg_status st;
    if (accept_word(&w, "MULTIPOLYGON")) {
        if (accept_word(&w, "EMPTY"))
            st = CG_OK;
        else if (!accept_char(&w, '('))
            return fail(&w, "'(' or EMPTY after MULTIPOLYGON");
        else {
            do {
                st = polygon_body(&w, set);
                if (st != CG_OK)
                    return st;
            } while (accept_char(&w, ','));
            if (!accept_char(&w, ')'))
                return fail(&w, "',' or ')' closing the MULTIPOLYGON");
            st = CG_OK;
        }
    } else if (accept_word(&w, "POLYGON")) {
        st = polygon_body(&w, set);
    } else {
        return fail(&w, "POLYGON or MULTIPOLYGON");
    }
    if (st != CG_OK)
        return st;
    skip_space(&w);
    if (w.s[w.pos])
        return fail(&w, "the end of the text");
    return CG_OK;
}

cg_status clip_wkt_read(const char *path, cg_polygon_set *set, cg_error *err)
{
    FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    if (!f)
        return cg_error_set(err, CG_EIO, "%s: cannot open", path);
    size_t n = 0, cap = 0;
    char *buf = NULL;
    cg_status st = CG_OK;
    for (;;) {
        /* room for a read of 4096 bytes or more, and the final NUL */
        if (core_array_reserve((void **)&buf, &cap, n + 4096, 1) != CG_OK) {
            st = cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
            break;
        }
        size_t got = fread(buf + n, 1, cap - n - 1, f);
        n += got;
        if (n < cap - 1) {
            if (ferror(f))
                st = cg_error_set(err, CG_EIO, "%s: read error", path);
            break;
        }
    }
    if (f != stdin)
        fclose(f);
    if (st == CG_OK) {
        buf[n] = 0;
        if (strlen(buf) != n)
            st = cg_error_set(err, CG_EFORMAT, "%s: offset %zu: unexpected NUL byte", path,
                              strlen(buf));
        else
            st = clip_wkt_parse(buf, strcmp(path, "-") == 0 ? "stdin" : path, set, err);
    }
    free(buf);
    return st;
}

static void write_ring(FILE *out, const cg_polygon_set *set, size_t r)
{
    size_t a = set->ring_start[r], b = set->ring_start[r + 1];
    fputc('(', out);
    for (size_t i = a; i <= b && b > a; i++) {
        cg_vec2 p = set->points[i < b ? i : a];
        fprintf(out, "%s%.15g %.15g", i > a ? ", " : "", p.x, p.y);
    }
    fputc(')', out);
}

void clip_wkt_write(FILE *out, const cg_polygon_set *set)
{
    if (!set || set->polygon_count == 0) {
        fputs("MULTIPOLYGON EMPTY\n", out);
        return;
    }
    fputs("MULTIPOLYGON (", out);
    for (size_t p = 0; p < set->polygon_count; p++) {
        fputs(p ? ", (" : "(", out);
        for (size_t r = set->polygon_start[p]; r < set->polygon_start[p + 1]; r++) {
            if (r > set->polygon_start[p])
                fputs(", ", out);
            write_ring(out, set, r);
        }
        fputc(')', out);
    }
    fputs(")\n", out);
}

clip_view clip_view_fit(cg_vec2 lo, cg_vec2 hi, int width, int height, int margin)
{
    clip_view v;
    double w = hi.x - lo.x, h = hi.y - lo.y;
    if (!(w > 0))
        w = 1;
    if (!(h > 0))
        h = 1;
    double sx = (width - 2.0 * margin) / w, sy = (height - 2.0 * margin) / h;
    v.scale = sx < sy ? sx : sy;
    v.ox = 0.5 * width - v.scale * 0.5 * (lo.x + hi.x);
    v.oy = 0.5 * height + v.scale * 0.5 * (lo.y + hi.y);
    v.height = height;
    return v;
}

void clip_bounds_add(const cg_polygon_set *set, cg_vec2 *lo, cg_vec2 *hi)
{
    for (size_t i = 0; set && i < set->point_count; i++) {
        cg_vec2 p = set->points[i];
        lo->x = fmin(lo->x, p.x);
        lo->y = fmin(lo->y, p.y);
        hi->x = fmax(hi->x, p.x);
        hi->y = fmax(hi->y, p.y);
    }
}

cg_status clip_view_canvas(const cg_polygon_set *const *sets, size_t count, int size,
                           cg_image **image, clip_view *view)
{
    cg_vec2 lo = {INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < count; i++)
        clip_bounds_add(sets[i], &lo, &hi);
    if (!(lo.x <= hi.x)) {
        lo = cg_vec2_make(0, 0);
        hi = cg_vec2_make(1, 1);
    }
    *image = NULL;
    cg_status st = cg_image_create(image, size, size, CG_PIXEL_RGBA8);
    if (st != CG_OK)
        return st;
    cg_image_clear_rgba8(*image, (cg_rgba8){255, 255, 255, 255});
    *view = clip_view_fit(lo, hi, size, size, 24);
    return CG_OK;
}

cg_vec2 clip_view_map(const clip_view *v, cg_vec2 p)
{
    return cg_vec2_make(v->ox + v->scale * p.x, v->oy - v->scale * p.y);
}

cg_status clip_view_fill(cg_image *image, const clip_view *v, const cg_polygon_set *set,
                         cg_rgba8 color)
{
    if (!set || set->ring_count == 0)
        return CG_OK;
    cg_vec2 *pts = malloc(set->point_count * sizeof *pts);
    int *sizes = malloc(set->ring_count * sizeof *sizes);
    cg_status st = CG_ENOMEM;
    if (pts && sizes) {
        for (size_t i = 0; i < set->point_count; i++)
            pts[i] = clip_view_map(v, set->points[i]);
        for (size_t r = 0; r < set->ring_count; r++)
            sizes[r] = (int)(set->ring_start[r + 1] - set->ring_start[r]);
        cg_paint paint = cg_paint_solid(color);
        st = cg_fill_polygon_aa(image, pts, sizes, (int)set->ring_count, CG_FILL_NONZERO, &paint);
    }
    free(pts);
    free(sizes);
    return st;
}

cg_status clip_view_polyline(cg_image *image, const clip_view *v, const cg_vec2 *p, size_t n,
                             int closed, double width, cg_rgba8 color)
{
    if (n < 2)
        return CG_OK;
    cg_path *path = NULL;
    cg_status st = cg_path_create(&path);
    for (size_t i = 0; i < n && st == CG_OK; i++) {
        cg_vec2 q = clip_view_map(v, p[i]);
        st = i ? cg_path_line_to(path, q.x, q.y) : cg_path_move_to(path, q.x, q.y);
    }
    if (st == CG_OK && closed)
        st = cg_path_close(path);
    if (st == CG_OK) {
        cg_stroke_style style = cg_stroke_style_default();
        style.width = width;
        style.join = CG_JOIN_ROUND;
        style.cap = CG_CAP_ROUND;
        cg_paint paint = cg_paint_solid(color);
        st = cg_stroke_path(image, path, &style, &paint);
    }
    cg_path_free(path);
    return st;
}

cg_status clip_view_stroke(cg_image *image, const clip_view *v, const cg_polygon_set *set,
                           double width, cg_rgba8 color)
{
    for (size_t r = 0; set && r < set->ring_count; r++) {
        size_t a = set->ring_start[r], b = set->ring_start[r + 1];
        cg_status st = clip_view_polyline(image, v, set->points + a, b - a, 1, width, color);
        if (st != CG_OK)
            return st;
    }
    return CG_OK;
}
