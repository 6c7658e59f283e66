/* The peers of bench_polygon.c (bench_polygon_peers.cpp): Clipper2 2.0 built
 * from ../shared/peers when it is there, and GEOS's C API when installed. */
#ifndef CG_BENCH_POLYGON_PEERS_H
#define CG_BENCH_POLYGON_PEERS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Rings one after another: ring r has ring_len[r] points (x, y pairs in xy). */
typedef struct polygon_peer_input {
    const int64_t *xy;
    const size_t *ring_len;
    size_t ring_count;
} polygon_peer_input;

/* Each prepares its input once (context), runs the operation and returns
 * the result's area (triangulations: the number of triangles). */
int peer_clipper2_available(void);
void *peer_clipper2_prepare(const polygon_peer_input *in);
/* join: 0 miter, 1 round; Clipper2's arc tolerance given in grid units */
double peer_clipper2_offset(void *ctx, double delta, int join, double arc_tolerance);
double peer_clipper2_rect(void *ctx, int64_t xmin, int64_t ymin, int64_t xmax, int64_t ymax);
double peer_clipper2_triangulate(void *ctx);
/* the rings as open polylines cut to the rectangle: the pieces' length */
double peer_clipper2_rect_lines(void *ctx, int64_t xmin, int64_t ymin, int64_t xmax, int64_t ymax);
/* MinkowskiSum of the first ring of pattern along the first ring of path
 * (closed: as a loop): the area */
double peer_clipper2_minkowski(void *pattern, void *path, int closed);
/* SimplifyPaths (rdp 0) or RamerDouglasPeucker (rdp 1): the points left */
double peer_clipper2_simplify(void *ctx, double epsilon, int rdp);
void peer_clipper2_free(void *ctx);

int peer_geos_available(void);
void *peer_geos_prepare(const polygon_peer_input *in);
/* the rings as a MULTILINESTRING of open polylines */
void *peer_geos_prepare_lines(const polygon_peer_input *in);
double peer_geos_buffer(void *ctx, double delta, int join, int quadrant_segments);
/* GEOSClipByRect: the area (lines: the length) */
double peer_geos_clip_rect(void *ctx, double xmin, double ymin, double xmax, double ymax);
/* GEOSTopologyPreserveSimplify: the points left (closing points counted once) */
double peer_geos_simplify(void *ctx, double tolerance);
/* GEOSConstrainedDelaunayTriangulation: the number of triangles */
double peer_geos_triangulate(void *ctx);
void peer_geos_free(void *ctx);

#ifdef __cplusplus
}
#endif
#endif
