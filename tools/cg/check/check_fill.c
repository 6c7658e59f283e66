/* `cg check polygon-fill 'POLYGON' [even-odd|nonzero]` and `cg check
 * flood-fill IMAGE X Y [4|8]` (chapter 10): the student's pixels against the
 * definitions, computed here directly, and against cg's fills.
 *
 * Polygon fill: pixel (x, y) is filled when its centre (x + 0.5, y + 0.5) is
 * inside, by the pixel-centre rule: on the scan-line through the centre an
 * edge counts when top <= y < bottom (a vertex on the line counts once,
 * horizontal edges never), and a span [xl, xr) between crossings takes the
 * centres with xl <= x < xr.  Flood fill: the pixels of the seed's colour
 * connected to the seed through 4 (or 8) neighbours of that colour. */
#include "check.h"

#include "cli.h"
#include "trace_algorithms.h"
#include "cg/fill.h"
#include "cg/image.h"
#include "cg/trace_steps.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_POINTS = 256, MAX_CONTOURS = 16, MAX_SHOWN = 6 };

typedef struct polygon {
    cg_vec2 points[MAX_POINTS];
    int sizes[MAX_CONTOURS], contours;
    cg_fill_rule rule;
} polygon;

typedef struct crossing {
    double x;
    int dir;
} crossing;

static int compare_crossings(const void *a, const void *b)
{
    double x = ((const crossing *)a)->x, y = ((const crossing *)b)->x;
    return (x > y) - (x < y);
}

/* The crossings of the scan-line at centre height yc, sorted; their count. */
static int row_crossings(const polygon *poly, double yc, crossing *out)
{
    int n = 0, start = 0;
    for (int c = 0; c < poly->contours; c++) {
        for (int i = 0; i < poly->sizes[c]; i++) {
            cg_vec2 a = poly->points[start + i], b = poly->points[start + (i + 1) % poly->sizes[c]];
            if (a.y == b.y)
                continue;
            cg_vec2 top = a.y < b.y ? a : b, bottom = a.y < b.y ? b : a;
            if (!(top.y <= yc && yc < bottom.y))
                continue;
            double slope = (bottom.x - top.x) / (bottom.y - top.y);
            out[n++] = (crossing){top.x + (yc - top.y) * slope, b.y > a.y ? 1 : -1};
        }
        start += poly->sizes[c];
    }
    core_sort(out, (size_t)n, sizeof *out, compare_crossings);
    return n;
}

/* Whether the centre (xc, yc) is inside: the crossings at or left of it. */
static int centre_inside(const polygon *poly, const crossing *c, int n, double xc)
{
    int count = 0, winding = 0;
    for (int i = 0; i < n && c[i].x <= xc; i++) {
        count++;
        winding += c[i].dir;
    }
    return poly->rule == CG_FILL_NONZERO ? winding != 0 : (count & 1);
}

/* "[1.25, 6.75) [8, 9.5)": the spans of a row. */
static void describe_spans(const polygon *poly, const crossing *c, int n, char *text, size_t size)
{
    size_t used = 0;
    int shown = 0, count = 0, winding = 0;
    text[0] = 0;
    for (int i = 0; i + 1 < n && shown < MAX_SHOWN; i++) {
        count++;
        winding += c[i].dir;
        int inside = poly->rule == CG_FILL_NONZERO ? winding != 0 : (count & 1);
        if (!inside || c[i + 1].x <= c[i].x)
            continue;
        int w = snprintf(text + used, size - used, "%s[%g, %g)", shown ? " " : "", c[i].x,
                         c[i + 1].x);
        if (w < 0 || (size_t)w >= size - used)
            break;
        used += (size_t)w;
        shown++;
    }
    if (!shown)
        snprintf(text, size, "none");
}

/* The explanation of pixel (x, y) by its scan-line: filled says whether the
 * student filled it. */
static int explain_pixel(const void *context, long long x, long long y, int filled)
{
    const polygon *poly = context;
    static crossing c[MAX_POINTS];
    double xc = (double)x + 0.5, yc = (double)y + 0.5;
    int n = row_crossings(poly, yc, c);
    char spans[512];
    describe_spans(poly, c, n, spans, sizeof spans);
    if (filled)
        check_wrong("pixel (%lld, %lld) is filled, but its centre (%g, %g) is outside the polygon: "
                    "the spans on scan-line y = %g are %s",
                    x, y, xc, yc, yc, spans);
    else
        check_wrong("pixel (%lld, %lld) is not filled, but its centre (%g, %g) is inside the "
                    "polygon: the spans on scan-line y = %g are %s",
                    x, y, xc, yc, yc, spans);
    check_note("a span [xl, xr) takes the pixels whose centre x is in [xl, xr): ceil(xl - 0.5) "
               ".. ceil(xr - 0.5) - 1");
    for (int i = 0; i < n; i++)
        if (c[i].x == xc) {
            check_note("the centre lies exactly on an edge: by the pixel-centre rule it belongs "
                       "to the region on its right");
            return CLI_FAILED;
        }
    int start = 0;
    for (int k = 0; k < poly->contours; k++) {
        for (int i = 0; i < poly->sizes[k]; i++) {
            cg_vec2 a = poly->points[start + i], b = poly->points[start + (i + 1) % poly->sizes[k]];
            if (a.y == yc || b.y == yc) {
                check_note("the scan-line y = %g passes through a vertex: an edge counts on the "
                           "rows with top <= y < bottom, so a horizontal edge belongs to the "
                           "region below it",
                           yc);
                return CLI_FAILED;
            }
        }
        start += poly->sizes[k];
    }
    return CLI_FAILED;
}

/* The filled pixels by the definition, sorted by (y, x). */
static int definition_fill(const polygon *poly, check_pixels *out)
{
    static crossing c[MAX_POINTS];
    double ymin = INFINITY, ymax = -INFINITY;
    int total = 0;
    for (int k = 0; k < poly->contours; k++)
        total += poly->sizes[k];
    for (int i = 0; i < total; i++) {
        ymin = fmin(ymin, poly->points[i].y);
        ymax = fmax(ymax, poly->points[i].y);
    }
    for (long long y = (long long)floor(ymin) - 1; y <= (long long)ceil(ymax); y++) {
        int n = row_crossings(poly, (double)y + 0.5, c);
        if (n == 0)
            continue;
        long long x0 = (long long)floor(c[0].x) - 1, x1 = (long long)ceil(c[n - 1].x) + 1;
        for (long long x = x0; x <= x1; x++)
            if (centre_inside(poly, c, n, (double)x + 0.5)
                && core_array_push(out, ((check_pixel){x, y, 0})) != CG_OK)
                return -1;
    }
    return 0;
}

static int collect_pixels(void *user, const cg_step *step)
{
    check_pixels *out = user;
    for (int i = 0; i < step->pixel_count; i++)
        if (core_array_push(out, ((check_pixel){step->pixels[2 * i], step->pixels[2 * i + 1], 0}))
            != CG_OK)
            return 1;
    return 0;
}

static int same_pixel(const check_pixel *a, const check_pixel *b)
{
    return a->x == b->x && a->y == b->y;
}

/* The first pixel, in scan order, in one of the sorted sets and not the
 * other: 1 with *in_student set when it is the student's, 0 when none. */
static int first_difference(const check_pixel *s, size_t ns, const check_pixel *d, size_t nd,
                            check_pixel *out, int *in_student)
{
    size_t i = 0, j = 0;
    while (i < ns || j < nd) {
        if (i < ns && j < nd && same_pixel(&s[i], &d[j])) {
            i++;
            j++;
            continue;
        }
        int take_s = j >= nd
                     || (i < ns && (s[i].y < d[j].y || (s[i].y == d[j].y && s[i].x < d[j].x)));
        *out = take_s ? s[i] : d[j];
        *in_student = take_s;
        return 1;
    }
    return 0;
}

/* Explains the first pixel in which the student's fill differs from the
 * definition's: in_student says which of the two has it. */
typedef int (*explain_fn)(const void *context, long long x, long long y, int in_student);

/* The student's sorted pixels against the definition's, then against cg's
 * (both in scan order): CLI_OK when the same as both, else the verdict. */
static int compare_fill(const check_pixel *sorted, size_t count, const check_pixels *definition,
                        const check_pixel *cg, size_t cg_count, explain_fn explain,
                        const void *context, const char *cg_name)
{
    check_pixel at;
    int in_student;
    if (first_difference(sorted, count, definition->data, definition->count, &at, &in_student))
        return explain(context, at.x, at.y, in_student);
    if (first_difference(sorted, count, cg, cg_count, &at, &in_student))
        return check_wrong("pixel (%lld, %lld) is %s, but %s %s it", at.x, at.y,
                           in_student ? "filled" : "not filled", cg_name,
                           in_student ? "leaves" : "fills");
    return CLI_OK;
}

static int check_polygon(const polygon *poly, const check_pixel *sorted, size_t count)
{
    check_pixels definition = {0}, cg = {0};
    int code = CLI_OK;
    cg_status status = cg_scanline_fill_steps(poly->points, poly->sizes, poly->contours, poly->rule,
                                              collect_pixels, &cg);
    check_pixel *cg_sorted = check_sorted(&cg);
    if (definition_fill(poly, &definition) != 0 || status != CG_OK || (cg.count && !cg_sorted))
        code = cli_fail("check: polygon-fill: %s", cg_status_str(status ? status : CG_ENOMEM));
    if (code == CLI_OK)
        code = compare_fill(sorted, count, &definition, cg_sorted, cg.count, explain_pixel, poly,
                            "cg's scan-line fill (a rounding of a crossing)");
    if (code == CLI_OK)
        code = check_right("%zu pixels, those whose centres are inside by the pixel-centre rule "
                           "(%s), the same as cg's scan-line fill",
                           count, poly->rule == CG_FILL_NONZERO ? "non-zero" : "even-odd");
    free(cg_sorted);
    core_array_free(&definition);
    core_array_free(&cg);
    return code;
}

static int run_polygon_fill(int argc, char **argv, FILE *in, const check_options *options)
{
    (void)options;
    static polygon poly;
    if (argc != 2 && argc != 3)
        return cli_usage_error("check", "polygon-fill: expected 'polygon-fill \"X,Y X,Y X,Y ...\" "
                                        "[even-odd|nonzero]'");
    poly.rule = CG_FILL_EVEN_ODD;
    if (argc == 3) {
        if (strcmp(argv[2], "nonzero") == 0)
            poly.rule = CG_FILL_NONZERO;
        else if (strcmp(argv[2], "even-odd") != 0)
            return cli_usage_error("check",
                                   "polygon-fill: unknown rule '%s' (even-odd or "
                                   "nonzero)",
                                   argv[2]);
    }
    if (trace_parse_contours("check", "polygon-fill", argv[1], poly.points, MAX_POINTS, poly.sizes,
                             MAX_CONTOURS, &poly.contours)
        != CLI_OK)
        return CLI_USAGE;
    int total = 0;
    for (int k = 0; k < poly.contours; k++)
        total += poly.sizes[k];
    for (int i = 0; i < total; i++)
        if (!(fabs(poly.points[i].x) <= 4096 && fabs(poly.points[i].y) <= 4096))
            return cli_usage_error("check", "polygon-fill: coordinates must lie within 4096");
    check_pixel *sorted;
    size_t count;
    int code = check_read_set(in, "a scan-line fill", &sorted, &count);
    if (code == CLI_OK)
        code = check_polygon(&poly, sorted, count);
    free(sorted);
    return code;
}

/* ---- flood fill ----------------------------------------------------------- */

static int same_colour(cg_rgba8 a, cg_rgba8 b)
{
    return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

/* The region by breadth-first search: region[i] is 0 outside, else 1 + the
 * direction (0..7) of the neighbour it was reached from (8 for the seed). */
static int definition_region(const cg_image *image, int sx, int sy, int connectivity,
                             unsigned char *region)
{
    static const int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1}, dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    size_t w = (size_t)image->width, n = w * (size_t)image->height;
    size_t *queue = malloc(n * sizeof *queue);
    if (!queue)
        return -1;
    cg_rgba8 seed = cg_image_get_rgba8(image, sx, sy);
    size_t head = 0, tail = 0;
    queue[tail++] = (size_t)sy * w + (size_t)sx;
    region[queue[0]] = 9;
    while (head < tail) {
        size_t at = queue[head++];
        int x = (int)(at % w), y = (int)(at / w);
        for (int d = 0; d < connectivity; d++) {
            int nx = x + dx[d], ny = y + dy[d];
            if (!cg_image_contains(image, nx, ny))
                continue;
            size_t k = (size_t)ny * w + (size_t)nx;
            if (region[k] || !same_colour(cg_image_get_rgba8(image, nx, ny), seed))
                continue;
            region[k] = (unsigned char)(1 + d);
            queue[tail++] = k;
        }
    }
    free(queue);
    return 0;
}

static const char *hex(cg_rgba8 c, char text[16])
{
    if (c.a == 255)
        snprintf(text, 16, "#%02x%02x%02x", c.r, c.g, c.b);
    else
        snprintf(text, 16, "#%02x%02x%02x%02x", c.r, c.g, c.b, c.a);
    return text;
}

typedef struct flood_check {
    const cg_image *image;
    const unsigned char *region;
    int sx, sy, connectivity;
} flood_check;

static int explain_flood(const void *context, long long x, long long y, int in_student)
{
    const flood_check *f = context;
    static const int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1}, dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    char a[16], b[16];
    cg_rgba8 seed = cg_image_get_rgba8(f->image, f->sx, f->sy);
    if (!in_student) {
        int d = f->region[(size_t)y * (size_t)f->image->width + (size_t)x] - 1;
        if (d == 8)
            return check_wrong("the seed pixel (%d, %d) is not filled", f->sx, f->sy);
        return check_wrong("pixel (%lld, %lld) is not filled, but it has the seed's colour %s "
                           "and its %sneighbour (%lld, %lld) is in the region: a %d-connected "
                           "flood fill reaches it",
                           x, y, hex(seed, a), d >= 4 ? "diagonal " : "", x - dx[d], y - dy[d],
                           f->connectivity);
    }
    if (x < 0 || y < 0 || x >= f->image->width || y >= f->image->height)
        return check_wrong("pixel (%lld, %lld) is outside the %d x %d image", x, y, f->image->width,
                           f->image->height);
    cg_rgba8 c = cg_image_get_rgba8(f->image, (int)x, (int)y);
    if (!same_colour(c, seed))
        return check_wrong("pixel (%lld, %lld) is filled, but its colour %s is not the seed's %s: "
                           "a flood fill replaces only the seed's colour",
                           x, y, hex(c, a), hex(seed, b));
    return check_wrong("pixel (%lld, %lld) is filled and has the seed's colour %s, but no "
                       "%d-connected path of that colour leads to it from the seed (%d, %d)",
                       x, y, hex(seed, a), f->connectivity, f->sx, f->sy);
}

/* The region's pixels in scan order, and cg's (pixels changed by
 * cg_flood_fill). */
static int regions(const cg_image *image, const unsigned char *region, int sx, int sy,
                   int connectivity, check_pixels *definition, check_pixels *cg)
{
    cg_image *copy;
    if (cg_image_copy(image, &copy) != CG_OK)
        return -1;
    cg_rgba8 seed = cg_image_get_rgba8(image, sx, sy), paint = seed;
    paint.r ^= 0x80;
    cg_status status = cg_flood_fill(copy, sx, sy, paint,
                                     connectivity == 8 ? CG_CONNECT_8 : CG_CONNECT_4, 0, NULL);
    for (int y = 0; status == CG_OK && y < image->height; y++)
        for (int x = 0; status == CG_OK && x < image->width; x++) {
            if (region[(size_t)y * (size_t)image->width + (size_t)x]
                && core_array_push(definition, ((check_pixel){x, y, 0})) != CG_OK)
                status = CG_ENOMEM;
            if (!same_colour(cg_image_get_rgba8(copy, x, y), cg_image_get_rgba8(image, x, y))
                && core_array_push(cg, ((check_pixel){x, y, 0})) != CG_OK)
                status = CG_ENOMEM;
        }
    cg_image_free(copy);
    return status == CG_OK ? 0 : -1;
}

static int check_flood(const cg_image *image, long sx, long sy, long connectivity,
                       const check_pixel *sorted, size_t count)
{
    size_t n = (size_t)image->width * (size_t)image->height;
    unsigned char *region = calloc(n, 1);
    check_pixels definition = {0}, cg = {0};
    int code = CLI_OK;
    if (!region || definition_region(image, (int)sx, (int)sy, (int)connectivity, region) != 0
        || regions(image, region, (int)sx, (int)sy, (int)connectivity, &definition, &cg) != 0)
        code = cli_fail("check: flood-fill: out of memory");
    flood_check f = {image, region, (int)sx, (int)sy, (int)connectivity};
    if (code == CLI_OK)
        code = compare_fill(sorted, count, &definition, cg.data, cg.count, explain_flood, &f,
                            "cg's flood fill");
    if (code == CLI_OK)
        code = check_right("%zu pixels, the %ld-connected region of the seed's colour around "
                           "(%ld, %ld), the same as cg's flood fill",
                           count, connectivity, sx, sy);
    free(region);
    core_array_free(&definition);
    core_array_free(&cg);
    return code;
}

static int run_flood_fill(int argc, char **argv, FILE *in, const check_options *options)
{
    (void)options;
    long x, y, connectivity = 4;
    if (argc != 4 && argc != 5)
        return cli_usage_error("check", "flood-fill: expected 'flood-fill IMAGE X Y [4|8]'");
    if (cli_parse_long("check", "X", argv[2], -2147483647L, 2147483647L, &x)
        || cli_parse_long("check", "Y", argv[3], -2147483647L, 2147483647L, &y)
        || (argc == 5 && cli_parse_long("check", "connectivity", argv[4], 4, 8, &connectivity)))
        return CLI_USAGE;
    if (connectivity != 4 && connectivity != 8)
        return cli_usage_error("check", "flood-fill: connectivity is 4 or 8, not %ld",
                               connectivity);
    cg_image *read, *image;
    cg_error err;
    if (cg_image_read(argv[1], &read, &err) != CG_OK)
        return cli_usage_error("check", "%s", err.message);
    cg_status status = cg_image_convert(read, CG_PIXEL_RGBA8, &image);
    cg_image_free(read);
    if (status != CG_OK)
        return cli_fail("check: %s: %s", argv[1], cg_status_str(status));
    if (!cg_image_contains(image, (int)x, (int)y)) {
        int width = image->width, height = image->height;
        cg_image_free(image);
        return cli_usage_error("check",
                               "flood-fill: the seed (%ld, %ld) is outside the image "
                               "(%d x %d)",
                               x, y, width, height);
    }
    check_pixel *sorted;
    size_t count;
    int code = check_read_set(in, "a flood fill", &sorted, &count);
    if (code == CLI_OK)
        code = check_flood(image, x, y, connectivity, sorted, count);
    free(sorted);
    cg_image_free(image);
    return code;
}

const check_algorithm check_fill_algorithms[] = {
    {"polygon-fill", "'POLYGON' [even-odd|nonzero]", run_polygon_fill},
    {"flood-fill", "IMAGE X Y [4|8]", run_flood_fill},
    {NULL, NULL, NULL},
};
