// The peers of bench_polygon.c: Clipper2 (InflatePaths, RectClip,
// Triangulate) and GEOS (GEOSBufferWithStyle), each on the same integer
// input; a peer left out of the build says so through *_available().
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

void peer_clipper2_free(void *ctx) { delete static_cast<clipper2_context *>(ctx); }
#else
int peer_clipper2_available(void) { return 0; }
void *peer_clipper2_prepare(const polygon_peer_input *) { return nullptr; }
double peer_clipper2_offset(void *, double, int, double) { return 0; }
double peer_clipper2_rect(void *, int64_t, int64_t, int64_t, int64_t) { return 0; }
double peer_clipper2_triangulate(void *) { return 0; }
void peer_clipper2_free(void *) {}
#endif

#ifdef CG_HAVE_GEOS
#include <geos_c.h>
#include <cstdarg>

struct geos_context { GEOSContextHandle_t handle; GEOSGeometry *geometry; };

static void quiet(const char *, ...) {}

int peer_geos_available(void) { return 1; }

void *peer_geos_prepare(const polygon_peer_input *in)
{
    auto *c = new geos_context;
    c->handle = GEOS_init_r();
    GEOSContext_setErrorHandler_r(c->handle, quiet);
    GEOSContext_setNoticeHandler_r(c->handle, quiet);
    std::vector<GEOSGeometry *> rings;
    size_t k = 0;
    for (size_t r = 0; r < in->ring_count; r++) {
        unsigned n = (unsigned)in->ring_len[r];
        GEOSCoordSequence *s = GEOSCoordSeq_create_r(c->handle, n + 1, 2);
        for (unsigned i = 0; i <= n; i++) {
            size_t j = k + (i % n);
            GEOSCoordSeq_setX_r(c->handle, s, i, (double)in->xy[2 * j]);
            GEOSCoordSeq_setY_r(c->handle, s, i, (double)in->xy[2 * j + 1]);
        }
        k += n;
        rings.push_back(GEOSGeom_createLinearRing_r(c->handle, s));
    }
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
double peer_geos_buffer(void *, double, int, int) { return 0; }
void peer_geos_free(void *) {}
#endif
