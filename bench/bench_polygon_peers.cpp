// The peers of bench_polygon.c: Clipper2 (InflatePaths, RectClip,
// RectClipLines, MinkowskiSum, SimplifyPaths, RamerDouglasPeucker,
// Triangulate) and GEOS (GEOSBufferWithStyle, GEOSClipByRect,
// GEOSTopologyPreserveSimplify, GEOSConstrainedDelaunayTriangulation), each
// on the same integer input; a peer left out of the build says so through *_available().
#include "bench_polygon_peers.h"

#include <cmath>
#include <vector>

#ifdef CG_HAVE_CLIPPER2
#include "clipper2/clipper.h"
#include "clipper2/clipper.triangulation.h"

using namespace Clipper2Lib;

struct clipper2_context { Paths64 paths; };

int peer_clipper2_available(void) { return 1; }

void *peer_clipper2_prepare(const polygon_peer_input *in)
{
    auto *c = new clipper2_context;
    size_t k = 0;
    for (size_t r = 0; r < in->ring_count; r++) {
        Path64 p;
        for (size_t i = 0; i < in->ring_len[r]; i++, k++)
            p.push_back(Point64(in->xy[2 * k], in->xy[2 * k + 1]));
        c->paths.push_back(p);
    }
    return c;
}

double peer_clipper2_offset(void *ctx, double delta, int join, double arc_tolerance)
{
    auto *c = static_cast<clipper2_context *>(ctx);
    Paths64 out = InflatePaths(c->paths, delta, join ? JoinType::Round : JoinType::Miter,
                               EndType::Polygon, 2.0, arc_tolerance);
    return Area(out);
}

double peer_clipper2_rect(void *ctx, int64_t xmin, int64_t ymin, int64_t xmax, int64_t ymax)
{
    auto *c = static_cast<clipper2_context *>(ctx);
    Paths64 out = RectClip(Rect64(xmin, ymin, xmax, ymax), c->paths);
    return Area(out);
}

double peer_clipper2_triangulate(void *ctx)
{
    auto *c = static_cast<clipper2_context *>(ctx);
    Paths64 out;
    if (Triangulate(c->paths, out, true) != TriangulateResult::success)
        return -1;
    return (double)out.size();
}

static double length(const Paths64 &paths)
{
    double total = 0;
    for (const Path64 &p : paths)
        for (size_t i = 1; i < p.size(); i++)
            total += std::hypot((double)(p[i].x - p[i - 1].x), (double)(p[i].y - p[i - 1].y));
    return total;
}

double peer_clipper2_rect_lines(void *ctx, int64_t xmin, int64_t ymin, int64_t xmax, int64_t ymax)
{
    auto *c = static_cast<clipper2_context *>(ctx);
    return length(RectClipLines(Rect64(xmin, ymin, xmax, ymax), c->paths));
}

double peer_clipper2_minkowski(void *pattern, void *path, int closed)
{
    auto *a = static_cast<clipper2_context *>(pattern);
    auto *b = static_cast<clipper2_context *>(path);
    return Area(MinkowskiSum(a->paths[0], b->paths[0], closed != 0));
}

double peer_clipper2_simplify(void *ctx, double epsilon, int rdp)
{
    auto *c = static_cast<clipper2_context *>(ctx);
    Paths64 out = rdp ? RamerDouglasPeucker(c->paths, epsilon) : SimplifyPaths(c->paths, epsilon);
    double points = 0;
    for (const Path64 &p : out)
        points += (double)p.size();
    return points;
}

void peer_clipper2_free(void *ctx) { delete static_cast<clipper2_context *>(ctx); }
#else
int peer_clipper2_available(void) { return 0; }
void *peer_clipper2_prepare(const polygon_peer_input *) { return nullptr; }
double peer_clipper2_offset(void *, double, int, double) { return 0; }
double peer_clipper2_rect(void *, int64_t, int64_t, int64_t, int64_t) { return 0; }
double peer_clipper2_triangulate(void *) { return 0; }
double peer_clipper2_rect_lines(void *, int64_t, int64_t, int64_t, int64_t) { return 0; }
double peer_clipper2_minkowski(void *, void *, int) { return 0; }
double peer_clipper2_simplify(void *, double, int) { return 0; }
void peer_clipper2_free(void *) {}
#endif

#ifdef CG_HAVE_GEOS
#include <geos_c.h>
#include <cstdarg>

struct geos_context { GEOSContextHandle_t handle; GEOSGeometry *geometry; };

static void quiet(const char *, ...) {}

int peer_geos_available(void) { return 1; }

static geos_context *geos_open(void)
{
    auto *c = new geos_context;
    c->handle = GEOS_init_r();
    GEOSContext_setErrorHandler_r(c->handle, quiet);
    GEOSContext_setNoticeHandler_r(c->handle, quiet);
    return c;
}

// Each ring as a coordinate sequence (closed: its first point repeated).
static std::vector<GEOSCoordSequence *> geos_sequences(geos_context *c,
                                                       const polygon_peer_input *in, int closed)
{
    std::vector<GEOSCoordSequence *> out;
    size_t k = 0;
    for (size_t r = 0; r < in->ring_count; r++) {
        unsigned n = (unsigned)in->ring_len[r], m = closed ? n + 1 : n;
        GEOSCoordSequence *s = GEOSCoordSeq_create_r(c->handle, m, 2);
        for (unsigned i = 0; i < m; i++) {
            size_t j = k + (i % n);
            GEOSCoordSeq_setX_r(c->handle, s, i, (double)in->xy[2 * j]);
            GEOSCoordSeq_setY_r(c->handle, s, i, (double)in->xy[2 * j + 1]);
        }
        k += n;
        out.push_back(s);
    }
    return out;
}

void *peer_geos_prepare_lines(const polygon_peer_input *in)
{
    geos_context *c = geos_open();
    std::vector<GEOSGeometry *> lines;
    for (GEOSCoordSequence *s : geos_sequences(c, in, 0))
        lines.push_back(GEOSGeom_createLineString_r(c->handle, s));
    c->geometry = GEOSGeom_createCollection_r(c->handle, GEOS_MULTILINESTRING, lines.data(),
                                              (unsigned)lines.size());
    return c;
}

void *peer_geos_prepare(const polygon_peer_input *in)
{
    geos_context *c = geos_open();
    std::vector<GEOSGeometry *> rings;
    for (GEOSCoordSequence *s : geos_sequences(c, in, 1))
        rings.push_back(GEOSGeom_createLinearRing_r(c->handle, s));
    // the first ring the shell, the others its holes (the bench's shapes)
    c->geometry = GEOSGeom_createPolygon_r(c->handle, rings[0], rings.data() + 1,
                                           (unsigned)rings.size() - 1);
    return c;
}

double peer_geos_buffer(void *ctx, double delta, int join, int quadrant_segments)
{
    auto *c = static_cast<geos_context *>(ctx);
    GEOSGeometry *b = GEOSBufferWithStyle_r(c->handle, c->geometry, delta, quadrant_segments,
                                            GEOSBUF_CAP_ROUND,
                                            join ? GEOSBUF_JOIN_ROUND : GEOSBUF_JOIN_MITRE, 2.0);
    double area = 0;
    GEOSArea_r(c->handle, b, &area);
    GEOSGeom_destroy_r(c->handle, b);
    return area;
}

double peer_geos_clip_rect(void *ctx, double xmin, double ymin, double xmax, double ymax)
{
    auto *c = static_cast<geos_context *>(ctx);
    GEOSGeometry *g = GEOSClipByRect_r(c->handle, c->geometry, xmin, ymin, xmax, ymax);
    double measure = 0;
    if (GEOSGeomTypeId_r(c->handle, c->geometry) == GEOS_MULTILINESTRING)
        GEOSLength_r(c->handle, g, &measure);
    else
        GEOSArea_r(c->handle, g, &measure);
    GEOSGeom_destroy_r(c->handle, g);
    return measure;
}

double peer_geos_simplify(void *ctx, double tolerance)
{
    auto *c = static_cast<geos_context *>(ctx);
    GEOSGeometry *g = GEOSTopologyPreserveSimplify_r(c->handle, c->geometry, tolerance);
    int rings = 1 + GEOSGetNumInteriorRings_r(c->handle, g);
    double points = (double)GEOSGetNumCoordinates_r(c->handle, g) - rings;
    GEOSGeom_destroy_r(c->handle, g);
    return points;
}

double peer_geos_triangulate(void *ctx)
{
    auto *c = static_cast<geos_context *>(ctx);
    GEOSGeometry *g = GEOSConstrainedDelaunayTriangulation_r(c->handle, c->geometry);
    double triangles = g ? (double)GEOSGetNumGeometries_r(c->handle, g) : -1;
    if (g)
        GEOSGeom_destroy_r(c->handle, g);
    return triangles;
}

void peer_geos_free(void *ctx)
{
    auto *c = static_cast<geos_context *>(ctx);
    GEOSGeom_destroy_r(c->handle, c->geometry);
    GEOS_finish_r(c->handle);
    delete c;
}
#else
int peer_geos_available(void) { return 0; }
void *peer_geos_prepare(const polygon_peer_input *) { return nullptr; }
void *peer_geos_prepare_lines(const polygon_peer_input *) { return nullptr; }
double peer_geos_buffer(void *, double, int, int) { return 0; }
double peer_geos_clip_rect(void *, double, double, double, double) { return 0; }
double peer_geos_simplify(void *, double) { return 0; }
double peer_geos_triangulate(void *) { return 0; }
void peer_geos_free(void *) {}
#endif
