/* The peers of bench_clip.c, implemented in bench_clip_peers.cpp. */
#ifndef CG_BENCH_CLIP_PEERS_H
#define CG_BENCH_CLIP_PEERS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Rings one after another: ring r has ring_len[r] points (x, y pairs in xy). */
typedef struct peer_input {
    const int64_t *xy;
    const size_t *ring_len;
    size_t ring_count;
} peer_input;

/* op: 0 intersection, 1 union, 2 difference, 3 xor; both operands non-zero.
 * run returns the solution's area. */
int peer_clipper_available(void);
void *peer_clipper_prepare(const peer_input *a, const peer_input *b);
double peer_clipper_run(void *ctx, int op);
void peer_clipper_free(void *ctx);

int peer_geos_available(void);
void *peer_geos_prepare(const peer_input *a, const peer_input *b);
double peer_geos_run(void *ctx, int op);
void peer_geos_free(void *ctx);

#ifdef __cplusplus
}
#endif
#endif
