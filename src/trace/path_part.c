/* Part files of the path tracer: the fixed-point sums of a tile and sample
 * range, and their merge into the whole image's sums. */
#include "path_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char magic[8] = {'C', 'G', 'P', 'A', 'R', 'T', '2', '\n'};

static void put(unsigned char *p, uint64_t v, int bytes)
{
    for (int i = 0; i < bytes; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

static uint64_t get(const unsigned char *p, int bytes)
{
    uint64_t v = 0;
    for (int i = 0; i < bytes; i++)
        v |= (uint64_t)p[i] << (8 * i);
    return v;
}

static int part_valid(const cg_path_part *p)
{
    return p->width > 0 && p->height > 0 && p->x0 < p->x1 && p->y0 < p->y1 && p->x1 <= p->width
           && p->y1 <= p->height && p->sample_begin < p->sample_end && p->sample_end <= p->spp
           && (uint64_t)p->width * p->height <= ((uint64_t)1 << 30);
}

static size_t part_values(const cg_path_part *p)
{
    return (size_t)(p->x1 - p->x0) * (size_t)(p->y1 - p->y0) * 3;
}

enum { HEADER = 8 + 10 * 4 + 8 + 8 };

cg_status cg_path_part_save(const cg_path_part *part, const char *path, cg_error *err)
{
    if (!part || !path || !part->sums || !part_valid(part))
        return cg_error_set(err, CG_EINVAL, "part: invalid part");
    size_t len = strlen(path);
    char *tmp = malloc(len + 8);
    if (!tmp)
        return cg_error_set(err, CG_ENOMEM, "part: out of memory");
    memcpy(tmp, path, len);
    memcpy(tmp + len, ".tmpXXX", 8);
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        free(tmp);
        return cg_error_set(err, CG_EIO, "%s: cannot write the part file", path);
    }
    unsigned char h[HEADER];
    memcpy(h, magic, 8);
    const uint32_t fields[10] = {part->width, part->height,   part->x0,           part->y0,
                                 part->x1,    part->y1,       part->sample_begin, part->sample_end,
                                 part->spp,   part->max_depth};
    for (int i = 0; i < 10; i++)
        put(h + 8 + 4 * i, fields[i], 4);
    put(h + 48, part->seed, 8);
    put(h + 56, part->render_key, 8);
    int ok = fwrite(h, 1, HEADER, f) == HEADER;
    size_t n = part_values(part);
    for (size_t i = 0; i < n && ok; i++) {
        unsigned char b[8];
        put(b, part->sums[i], 8);
        ok = fwrite(b, 1, 8, f) == 8;
    }
    ok = fclose(f) == 0 && ok;
    if (!ok || rename(tmp, path) != 0) {
        remove(tmp);
        free(tmp);
        return cg_error_set(err, CG_EIO, "%s: cannot write the part file", path);
    }
    free(tmp);
    return CG_OK;
}

cg_status cg_path_part_load(const char *path, cg_path_part *out, cg_error *err)
{
    if (!path || !out)
        return cg_error_set(err, CG_EINVAL, "part: no path");
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "rb");
    if (!f)
        return cg_error_set(err, CG_EIO, "%s: cannot open the part file", path);
    unsigned char h[HEADER];
    cg_path_part p;
    memset(&p, 0, sizeof p);
    if (fread(h, 1, HEADER, f) != HEADER || memcmp(h, magic, 8) != 0) {
        fclose(f);
        return cg_error_set(err, CG_EFORMAT, "%s: not a cg part file", path);
    }
    uint32_t v[10];
    for (int i = 0; i < 10; i++)
        v[i] = (uint32_t)get(h + 8 + 4 * i, 4);
    p.width = v[0], p.height = v[1], p.x0 = v[2], p.y0 = v[3], p.x1 = v[4], p.y1 = v[5];
    p.sample_begin = v[6], p.sample_end = v[7], p.spp = v[8], p.max_depth = v[9];
    p.seed = get(h + 48, 8);
    p.render_key = get(h + 56, 8);
    if (!part_valid(&p)) {
        fclose(f);
        return cg_error_set(err, CG_EFORMAT, "%s: the part's header is inconsistent", path);
    }
    size_t n = part_values(&p);
    p.sums = malloc(n * sizeof *p.sums);
    int ok = p.sums != NULL;
    for (size_t i = 0; i < n && ok; i++) {
        unsigned char b[8];
        ok = fread(b, 1, 8, f) == 8;
        if (ok)
            p.sums[i] = get(b, 8);
    }
    ok = ok && fgetc(f) == EOF;
    fclose(f);
    if (!ok) {
        free(p.sums);
        return cg_error_set(err, CG_EFORMAT, "%s: the part is truncated or too long", path);
    }
    *out = p;
    return CG_OK;
}

static int same_render(const cg_path_part *a, const cg_path_part *b)
{
    return a->width == b->width && a->height == b->height && a->spp == b->spp
           && a->max_depth == b->max_depth && a->seed == b->seed && a->render_key == b->render_key;
}

cg_status cg_path_part_merge(const cg_path_part *parts, size_t count, cg_path_part *out,
                             cg_error *err)
{
    if (!parts || !out || count == 0)
        return cg_error_set(err, CG_EINVAL, "merge: no parts");
    for (size_t i = 0; i < count; i++)
        if (!part_valid(&parts[i]) || !same_render(&parts[0], &parts[i]))
            return cg_error_set(err, CG_EINVAL,
                                "merge: part %zu is of another render (size, spp, depth, seed, "
                                "scene or sky)",
                                i + 1);
    cg_path_part m = parts[0];
    m.x0 = m.y0 = 0;
    m.x1 = m.width;
    m.y1 = m.height;
    m.sample_begin = 0;
    m.sample_end = m.spp;
    size_t pixels = (size_t)m.width * m.height;
    m.sums = calloc(pixels * 3, sizeof *m.sums);
    uint64_t *samples = calloc(pixels, sizeof *samples);
    if (!m.sums || !samples) {
        free(m.sums);
        free(samples);
        return cg_error_set(err, CG_ENOMEM, "merge: out of memory");
    }
    for (size_t i = 0; i < count; i++) {
        const cg_path_part *p = &parts[i];
        size_t w = p->x1 - p->x0;
        for (uint32_t y = p->y0; y < p->y1; y++)
            for (uint32_t x = p->x0; x < p->x1; x++) {
                size_t at = (size_t)y * m.width + x;
                const uint64_t *s = p->sums + ((size_t)(y - p->y0) * w + (x - p->x0)) * 3;
                for (int c = 0; c < 3; c++)
                    m.sums[at * 3 + (size_t)c] += s[c];
                samples[at] += p->sample_end - p->sample_begin;
            }
    }
    for (size_t i = 0; i < pixels; i++)
        if (samples[i] != m.spp) {
            cg_status s = cg_error_set(
                err, CG_EINVAL, "merge: pixel (%zu, %zu) has %llu of %u samples", i % m.width,
                i / m.width, (unsigned long long)samples[i], m.spp);
            free(m.sums);
            free(samples);
            return s;
        }
    free(samples);
    *out = m;
    return CG_OK;
}
