/* Gallery: polygon geometry beyond the booleans (chapter 11, cg/polygon.h) -
 * a letter outline offset with each join, inflated and deflated; a polyline
 * widened with each end; a Minkowski sum; polylines clipped by a polygon with holes; a
 * polygon with holes triangulated, and refined to a minimum angle; a
 * coastline simplified at several tolerances.  Every picture is made by the
 * very `cg clip ... -o NAME.png` command of its caption, run in-process on
 * the WKT files written into the gallery folder. */
#include "command.h"
#include "demo.h"

#include "cg/image.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

extern const cg_command cg_command_clip;

/* The letter A: an outline with acute and reflex corners, and a hole. */
static const char LETTER[] =
    "POLYGON ((0 0, 22 0, 31 28, 69 28, 78 0, 100 0, 62 120, 38 120, 0 0), "
    "(38 46, 50 86, 62 46, 38 46))";
/* A zigzag polyline for the ends. */
static const char ZIGZAG[] = "LINESTRING (0 0, 30 40, 60 0, 90 40)";
/* Polylines (one crossing itself) and a region with two holes. */
static const char PATHS[] =
    "MULTILINESTRING ((-10 50, 110 50), (-10 -10, 110 110, 110 -10, -10 110), "
    "(50 -10, 50 30, 20 80, 80 80, 50 30))";
static const char REGION[] =
    "POLYGON ((0 0, 100 0, 100 100, 0 100, 0 0), "
    "(15 60, 40 60, 40 85, 15 85, 15 60), (60 15, 85 15, 85 40, 60 40, 60 15))";
/* A small triangle and a spiral path for the Minkowski sum. */
static const char PEN[] = "POLYGON ((-4 -3, 4 -3, 0 5, -4 -3))";
static const char SPIRAL[] =
    "LINESTRING (0 0, 20 0, 20 20, -20 20, -20 -20, 40 -20, 40 40, -40 40)";
/* A house with a square window and a triangular one. */
static const char HOUSE[] = "POLYGON ((0 0, 100 0, 100 60, 50 100, 0 60, 0 0), "
                            "(20 20, 20 40, 40 40, 40 20, 20 20), (60 20, 70 50, 80 20, 60 20))";

static int write_text(demo_context *c, const char *name, const char *text)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", demo_directory(c), name);
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) == EOF || fputc('\n', f) == EOF) {
        if (f)
            fclose(f);
        fprintf(stderr, "cg: demo: cannot write %s\n", path);
        return 1;
    }
    return fclose(f) != 0;
}

/* Runs `command` (words separated by single spaces; .wkt and .png words are
 * files of the gallery folder) in-process, then adds the picture it wrote. */
static int shot(demo_context *c, const char *png, const char *caption, const char *command)
{
    char words[1024], paths[16][4096];
    char *argv[32];
    int argc = 0, files = 0;
    snprintf(words, sizeof words, "%s", command);
    for (char *w = strtok(words, " "); w && argc < 31; w = strtok(NULL, " ")) {
        size_t n = strlen(w);
        if (n > 4 && (strcmp(w + n - 4, ".wkt") == 0 || strcmp(w + n - 4, ".png") == 0)
            && files < 16) {
            snprintf(paths[files], sizeof paths[files], "%s/%s", demo_directory(c), w);
            argv[argc++] = paths[files++];
        } else {
            argv[argc++] = w;
        }
    }
    argv[argc] = NULL;
    /* argv: cg clip ACTION ...; the clip command takes argv from "clip" */
    if (argc < 3 || cg_command_clip.run(argc - 1, argv + 1) != 0)
        return 1;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", demo_directory(c), png);
    cg_image *image = NULL;
    cg_error err;
    if (cg_image_read(path, &image, &err) != CG_OK) {
        fprintf(stderr, "cg: demo: %s\n", err.message);
        return 1;
    }
    int status = demo_add(c, png, image, caption, command);
    cg_image_free(image);
    return status;
}

static int offsets(demo_context *c)
{
    static const char *joins[4] = {"miter", "round", "square", "bevel"};
    static const char *ends[4] = {"butt", "square", "round", "joined"};
    int r = write_text(c, "polygon-letter.wkt", LETTER)
            | write_text(c, "polygon-zigzag.wkt", ZIGZAG);
    for (int k = 0; k < 4 && r == 0; k++) {
        char png[64], command[256], caption[256];
        snprintf(png, sizeof png, "polygon-offset-%s.png", joins[k]);
        snprintf(command, sizeof command,
                 "cg clip offset 6 polygon-letter.wkt --join %s --miter-limit 3 -o %s", joins[k],
                 png);
        snprintf(caption, sizeof caption,
                 "The letter A inflated by 6 with %s joins (the union of the outline with the "
                 "band of its boundary; the hole shrinks)",
                 joins[k]);
        r |= shot(c, png, caption, command);
    }
    for (int k = 0; k < 2 && r == 0; k++) {
        char png[64], command[256], caption[256];
        snprintf(png, sizeof png, "polygon-deflate-%s.png", joins[k]);
        snprintf(command, sizeof command, "cg clip offset -5 polygon-letter.wkt --join %s -o %s",
                 joins[k], png);
        snprintf(caption, sizeof caption,
                 "The letter A deflated by 5 with %s joins: every point within 5 of its boundary "
                 "removed, the hole's corners %s",
                 joins[k], k == 0 ? "mitred" : "rounded");
        r |= shot(c, png, caption, command);
    }
    for (int k = 0; k < 4 && r == 0; k++) {
        char png[64], command[256], caption[256];
        snprintf(png, sizeof png, "polygon-end-%s.png", ends[k]);
        snprintf(command, sizeof command, "cg clip offset 6 polygon-zigzag.wkt --end %s -o %s",
                 ends[k], png);
        snprintf(caption, sizeof caption, "A polyline widened by 6 on each side with %s ends%s",
                 ends[k], k == 3 ? " (closed into a loop: the band of the loop)" : "");
        r |= shot(c, png, caption, command);
    }
    return r;
}

static int lines(demo_context *c)
{
    int r = write_text(c, "polygon-paths.wkt", PATHS) | write_text(c, "polygon-region.wkt", REGION);
    if (r == 0)
        r = shot(c, "polygon-lines-inside.png",
                 "Open paths clipped by a polygon with holes: the pieces inside (the boundary "
                 "included), in order along each path, exact on the grid",
                 "cg clip boolean intersection polygon-paths.wkt polygon-region.wkt -o "
                 "polygon-lines-inside.png");
    if (r == 0)
        r = shot(c, "polygon-lines-outside.png",
                 "The same paths' pieces outside the polygon (the difference), one crossing "
                 "itself",
                 "cg clip boolean difference polygon-paths.wkt polygon-region.wkt -o "
                 "polygon-lines-outside.png");
    return r;
}

static int minkowski(demo_context *c)
{
    int r = write_text(c, "polygon-pen.wkt", PEN) | write_text(c, "polygon-spiral.wkt", SPIRAL);
    if (r == 0)
        r = shot(c, "polygon-minkowski.png",
                 "The Minkowski sum of a triangle with a spiral path: the triangle at every "
                 "vertex united with the parallelogram each of its edges sweeps along each path "
                 "edge",
                 "cg clip minkowski sum polygon-pen.wkt polygon-spiral.wkt -o "
                 "polygon-minkowski.png");
    return r;
}

static int triangulations(demo_context *c)
{
    int r = write_text(c, "polygon-house.wkt", HOUSE);
    if (r == 0)
        r = shot(c, "polygon-triangulate.png",
                 "The constrained Delaunay triangulation of a polygon with two holes: no point "
                 "added, the triangles tile it exactly",
                 "cg clip triangulate polygon-house.wkt -o polygon-triangulate.png");
    if (r == 0)
        r = shot(c, "polygon-triangulate-30.png",
                 "The same refined to a minimum angle of 30 degrees (Ruppert's Steiner points: "
                 "encroached edges split, bad triangles' circumcentres added)",
                 "cg clip triangulate polygon-house.wkt --min-angle 30 -o "
                 "polygon-triangulate-30.png");
    return r;
}

/* A coastline: a ring of midpoint displacements around an island. */
static int coastline(demo_context *c)
{
    enum { COUNT = 1024 };
    static double radius[COUNT];
    uint64_t s = 0x5851f42d4c957f2dull;
    for (int i = 0; i < COUNT; i++)
        radius[i] = 0;
    radius[0] = 100;
    for (int step = COUNT / 2, level = 0; step >= 1; step /= 2, level++) {
        double amplitude = 70 * pow(0.6, level);
        for (int i = step; i < COUNT; i += 2 * step) {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            double u = (double)(s >> 11) / 9007199254740992.0 - 0.5;
            radius[i] = (radius[i - step] + radius[(i + step) % COUNT]) / 2 + amplitude * u;
        }
    }
    size_t size = 32 * COUNT + 64;
    char *text = malloc(size);
    if (!text)
        return 1;
    size_t used = (size_t)snprintf(text, size, "POLYGON ((");
    for (int i = 0; i <= COUNT; i++) {
        double a = 2 * M_PI * (i % COUNT) / COUNT, r = radius[i % COUNT];
        used += (size_t)snprintf(text + used, size - used, "%s%.2f %.2f", i ? ", " : "", r * cos(a),
                                 r * sin(a));
    }
    snprintf(text + used, size - used, "))");
    int r = write_text(c, "polygon-coast.wkt", text);
    free(text);
    static const char *tolerances[3] = {"0.5", "2", "8"};
    for (int k = 0; k < 3 && r == 0; k++) {
        char png[64], command[256], caption[256];
        snprintf(png, sizeof png, "polygon-simplify-%d.png", k + 1);
        snprintf(command, sizeof command, "cg clip simplify %s polygon-coast.wkt -o %s",
                 tolerances[k], png);
        snprintf(caption, sizeof caption,
                 "A coastline of 1,024 vertices simplified (Ramer-Douglas-Peucker) within %s, "
                 "its topology kept",
                 tolerances[k]);
        r |= shot(c, png, caption, command);
    }
    return r;
}

static int render(demo_context *context)
{
    int r = offsets(context);
    r |= minkowski(context);
    r |= lines(context);
    r |= triangulations(context);
    r |= coastline(context);
    return r;
}

const demo_section demo_section_polygon = {11, "Polygon geometry", render};
