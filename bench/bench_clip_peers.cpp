// Peers of bench_clip.c: Clipper 6.4 (libpolyclipping) and GEOS (C API),
// called on the same integer polygons.  Each prepares its own structures
// once; a run times what a user calls for one boolean operation.
#include "bench_clip_peers.h"

#include <vector>

#ifdef CG_HAVE_CLIPPER
#include <polyclipping/clipper.hpp>

struct clipper_ctx {
    ClipperLib::Paths a, b;
};

static ClipperLib::Paths to_paths(const peer_input *in)
{
    ClipperLib::Paths paths;
    size_t k = 0;
    for (size_t r = 0; r < in->ring_count; r++) {
        ClipperLib::Path p;
        for (size_t i = 0; i < in->ring_len[r]; i++, k++)
            p.push_back(ClipperLib::IntPoint(in->xy[2 * k], in->xy[2 * k + 1]));
        paths.push_back(p);
    }
    return paths;
}

extern "C" void *peer_clipper_prepare(const peer_input *a, const peer_input *b)
{
    clipper_ctx *c = new clipper_ctx;
    c->a = to_paths(a);
    c->b = to_paths(b);
    return c;
}

extern "C" double peer_clipper_run(void *ctx, int op)
{
    clipper_ctx *c = static_cast<clipper_ctx *>(ctx);
    static const ClipperLib::ClipType types[4] = {ClipperLib::ctIntersection, ClipperLib::ctUnion,
                                                  ClipperLib::ctDifference, ClipperLib::ctXor};
    ClipperLib::Clipper clipper;
    clipper.AddPaths(c->a, ClipperLib::ptSubject, true);
    clipper.AddPaths(c->b, ClipperLib::ptClip, true);
    ClipperLib::Paths solution;
    clipper.Execute(types[op], solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    double area = 0;
    for (const ClipperLib::Path &p : solution)
        area += ClipperLib::Area(p);
    return area;
}

extern "C" void peer_clipper_free(void *ctx) { delete static_cast<clipper_ctx *>(ctx); }
extern "C" int peer_clipper_available(void) { return 1; }
#else
extern "C" void *peer_clipper_prepare(const peer_input *, const peer_input *) { return nullptr; }
extern "C" double peer_clipper_run(void *, int) { return 0; }
extern "C" void peer_clipper_free(void *) {}
extern "C" int peer_clipper_available(void) { return 0; }
#endif

#ifdef CG_HAVE_GEOS
#include <geos_c.h>

struct geos_ctx {
    GEOSContextHandle_t h;
    GEOSGeometry *a, *b;
};

static void quiet(const char *, ...) {}

// Rings are taken as: first ring of each polygon counter-clockwise outer, the
// clockwise rings after it its holes (the inputs of the benchmark are valid).
static GEOSGeometry *to_geom(GEOSContextHandle_t h, const peer_input *in)
{
    std::vector<GEOSGeometry *> polys;
    std::vector<GEOSGeometry *> holes;
    GEOSGeometry *outer = nullptr;
    size_t k = 0;
    auto flush = [&]() {
        if (outer)
            polys.push_back(GEOSGeom_createPolygon_r(h, outer, holes.empty() ? nullptr : holes.data(),
                                                     (unsigned)holes.size()));
        outer = nullptr;
        holes.clear();
    };
    for (size_t r = 0; r < in->ring_count; r++) {
        size_t n = in->ring_len[r];
        GEOSCoordSequence *s = GEOSCoordSeq_create_r(h, (unsigned)n + 1, 2);
        double area = 0;
        for (size_t i = 0; i <= n; i++) {
            size_t j = k + (i % n), j2 = k + ((i + 1) % n);
            GEOSCoordSeq_setX_r(h, s, (unsigned)i, (double)in->xy[2 * j]);
            GEOSCoordSeq_setY_r(h, s, (unsigned)i, (double)in->xy[2 * j + 1]);
            if (i < n)
                area += (double)in->xy[2 * j] * (double)in->xy[2 * j2 + 1] -
                        (double)in->xy[2 * j2] * (double)in->xy[2 * j + 1];
        }
        k += n;
        GEOSGeometry *ring = GEOSGeom_createLinearRing_r(h, s);
        if (area > 0) {
            flush();
            outer = ring;
        } else {
            holes.push_back(ring);
        }
    }
    flush();
    return GEOSGeom_createCollection_r(h, GEOS_MULTIPOLYGON, polys.data(), (unsigned)polys.size());
}

extern "C" void *peer_geos_prepare(const peer_input *a, const peer_input *b)
{
    geos_ctx *c = new geos_ctx;
    c->h = GEOS_init_r();
    GEOSContext_setNoticeHandler_r(c->h, quiet);
    GEOSContext_setErrorHandler_r(c->h, quiet);
    c->a = to_geom(c->h, a);
    c->b = to_geom(c->h, b);
    return c;
}

extern "C" double peer_geos_run(void *ctx, int op)
{
    geos_ctx *c = static_cast<geos_ctx *>(ctx);
    GEOSGeometry *r = op == 0   ? GEOSIntersection_r(c->h, c->a, c->b)
                      : op == 1 ? GEOSUnion_r(c->h, c->a, c->b)
                      : op == 2 ? GEOSDifference_r(c->h, c->a, c->b)
                                : GEOSSymDifference_r(c->h, c->a, c->b);
    double area = -1;
    if (r) {
        GEOSArea_r(c->h, r, &area);
        GEOSGeom_destroy_r(c->h, r);
    }
    return area;
}

extern "C" void peer_geos_free(void *ctx)
{
    geos_ctx *c = static_cast<geos_ctx *>(ctx);
    GEOSGeom_destroy_r(c->h, c->a);
    GEOSGeom_destroy_r(c->h, c->b);
    GEOS_finish_r(c->h);
    delete c;
}
extern "C" int peer_geos_available(void) { return 1; }
#else
extern "C" void *peer_geos_prepare(const peer_input *, const peer_input *) { return nullptr; }
extern "C" double peer_geos_run(void *, int) { return 0; }
extern "C" void peer_geos_free(void *) {}
extern "C" int peer_geos_available(void) { return 0; }
#endif
